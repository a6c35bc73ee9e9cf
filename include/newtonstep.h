#pragma once
#include "problemtypes.h"

/* The Newton step's linear solve (newtonstep.c). */
/* A 3D scene without -newton_iterative takes CG + GAMG above this many dofs
   and the direct factorisation at or below (-newton_iterative_dofs): where
   the two cross on 3D elastic blocks, bench/solid3d/RESULTS.md. */
#define NEWTON_ITERATIVE_DOFS 50000
/* On several ranks the substructured step's capacitance matrix (order |A|,
   the surface dofs in contact) is factored by the ranks together from this
   order on (-newton_schur_split_lu; denselu.c: ScaLAPACK), by each whole
   below. Off by default: on this shared machine under load (8 to 12 on 2
   cores) pdgetrf on 2 ranks took 48.9 s for the quarter Hertz ball's 9
   factorisations of order 3,050 where one rank's getrf took 10.1 s: its
   many messages each wait for a rank the system has descheduled. What the
   ranks do split is the matrix's formation (substructure.c). */
#define NEWTON_SCHUR_SPLIT_LU 1000000000
/* A 3D scene with contact pairs and without -newton_schur or
   -newton_iterative takes the Schur step (its dense surface blocks of
   order the contact surfaces' dofs nc: MUMPS's Schur complement of both
   bodies, 8 nc^2 bytes, then each body's) at most this many surface dofs,
   the whole Hessian's factorisation above (-newton_schur_surface_dofs;
   newtonstep.c, ProblemChooseNewtonStep). */
#define NEWTON_SCHUR_SURFACE_DOFS 12000
/* A direct solve by Cholesky: CHOLMOD on one rank, MUMPS on several or for a matrix that may be indefinite. */
PetscErrorCode ContactPCSetCholesky(PC, MPI_Comm, PetscBool indefinite);
/* The Schur complement on the contact surfaces of the set-up K (schur.c on
   one rank with -newton_schur_type mumps, else substructure.c): the Newton
   step's, and L-BFGS's H0 = K + C (lmvm.c). */
PetscErrorCode ProblemSchurPCSetUp(Problem, PC);
/* 3D scenes with contact pairs: the contact surfaces' dofs, and whether
   the Schur step fits (at most -newton_schur_surface_dofs of them, or
   -newton_schur given); the Newton step's choice and L-BFGS's H0's. */
PetscErrorCode ProblemSchurStepFits(Problem, PetscInt *nc, PetscBool *fits);
/* Newton types (nls, ntr), before TaoSetFromOptions(): TAO's KSP with the
   step's preconditioner; with coupled force control the Hessian TAO sees
   (p->Htao) bordered by the controls, around a KSP of H (p->fc.ksp). */
PetscErrorCode ProblemSetNewtonDefaults(Problem);
/* -newton_* and -tangent_at_rest* ("Newton step options"), with their defaults and checks. */
PetscErrorCode NewtonOptionsSetFromOptions(MPI_Comm, NewtonOptions *);
