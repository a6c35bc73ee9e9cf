#pragma once
#include "problemtypes.h"

/* The final stop measured against the forces the contacts carry
   (-stop_force_rtol, forcestop.c). */
/* Part of TAO's convergence test (solve.c), after TAO's own: a last stage's
   convergence by the gradient tolerances undone while the gradient is above
   -stop_force_rtol times the contacts' nodal forces. */
PetscErrorCode ProblemForceStopTest(Problem, Tao);
/* Whether the coming TAO solves stop at the final tolerance (the test applies to them alone). */
PetscErrorCode ProblemForceStopSetActive(Problem, PetscBool active);
/* Around each TaoSolve: forget the last solve's iterate; a solve that went on
   past the gradient tolerance and then stopped unconverged ends at the iterate
   that met it, with its reason. */
PetscErrorCode ProblemForceStopBegin(Problem);
PetscErrorCode ProblemForceStopEnd(Problem, TaoConvergedReason *reason);
/* -stage_rtol and -stop_force_rtol ("Stopping options"), with their defaults and checks. */
PetscErrorCode StopOptionsSetFromOptions(MPI_Comm, StopOptions *);
