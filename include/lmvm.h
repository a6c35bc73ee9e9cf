#pragma once
#include "problemtypes.h"

/* L-BFGS (TAO's lmvm and blmvm): its initial Hessian H0 and the screening of
   its correction pairs (lmvm.c). Its state lives with the TAO solver. */
/* After TaoSetFromOptions(): H0 for lmvm/blmvm (-lmvm_h0), nothing for other types. */
PetscErrorCode ProblemSetLMVMInitialHessian(Problem);
/* Before TaoSetFromOptions(): the defaults TAO reads for type (history size). */
PetscErrorCode ProblemSetLMVMDefaults(Problem, const char type[]);
/* The staged solve (staging.c) begins: the decrement's reference is taken
   anew at its first iterate, and a single solve is its last stage. */
PetscErrorCode ProblemLMVMBeginStaged(Problem);
/* Whether the coming TAO solve is the last stage (the decrement test applies to it alone). */
PetscErrorCode ProblemLMVMSetLastStage(Problem, PetscBool last);
/* TAO's convergence test, or with -lmvm_decrement_rtol in force the
   decrement's (the test forcestop.c's wraps). */
PetscErrorCode ProblemLMVMConvergenceTest(Problem, Tao);
/* TaoSolve, and for lmvm/blmvm with -lmvm_h0 contact its restarts where the
   line search failed after progress: the iterations of all and the reason of the last. */
PetscErrorCode ProblemTaoSolve(Problem, PetscInt *its, TaoConvergedReason *reason);
/* -lmvm_* ("L-BFGS options"), with their defaults and checks. */
PetscErrorCode LMVMOptionsSetFromOptions(MPI_Comm, LMVMOptions *);
