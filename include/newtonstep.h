#pragma once
#include "problemtypes.h"

/* The Newton step's linear solve (newtonstep.c). */
/* A 3D scene without -newton_iterative takes CG + GAMG above this many dofs
   and the direct factorisation at or below (-newton_iterative_dofs): where
   the two cross on 3D elastic blocks, bench/solid3d/RESULTS.md. */
#define NEWTON_ITERATIVE_DOFS 50000
/* A direct solve by Cholesky: CHOLMOD on one rank, MUMPS on several or for a matrix that may be indefinite. */
PetscErrorCode ContactPCSetCholesky(PC, MPI_Comm, PetscBool indefinite);
/* The Schur complement on the contact surfaces of the set-up K (schur.c on
   one rank with -newton_schur_type mumps, else substructure.c): the Newton
   step's, and L-BFGS's H0 = K + C (lmvm.c). */
PetscErrorCode ProblemSchurPCSetUp(Problem, PC);
/* Newton types (nls, ntr), before TaoSetFromOptions(): TAO's KSP with the
   step's preconditioner; with coupled force control the Hessian TAO sees
   (p->Htao) bordered by the controls, around a KSP of H (p->fc.ksp). */
PetscErrorCode ProblemSetNewtonDefaults(Problem);
/* -newton_* and -tangent_at_rest* ("Newton step options"), with their defaults and checks. */
PetscErrorCode NewtonOptionsSetFromOptions(MPI_Comm, NewtonOptions *);
