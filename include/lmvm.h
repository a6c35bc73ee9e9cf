#pragma once
#include "problem.h"

/* L-BFGS (TAO's lmvm and blmvm): its initial Hessian H0 and the screening of
   its correction pairs (lmvm.c). */
/* After TaoSetFromOptions(): H0 for lmvm/blmvm (-lmvm_h0), nothing for other types. */
PetscErrorCode ProblemSetLMVMInitialHessian(Problem);
/* Before TaoSetFromOptions(): the defaults TAO reads for type (history size). */
PetscErrorCode ProblemSetLMVMDefaults(Problem, const char type[]);
PetscErrorCode ProblemLMVMDestroy(Problem);
/* TaoSolve, and for lmvm/blmvm with -lmvm_h0 contact its restarts where the
   line search failed after progress: the iterations of all and the reason of the last. */
PetscErrorCode ProblemTaoSolve(Problem, PetscInt *its, TaoConvergedReason *reason);
