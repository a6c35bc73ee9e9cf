#pragma once
#include "problem.h"

/* -accuracy TOL (accuracy.c): the scene solved on a sequence of meshes, each
   refined around the contact zones of the last, until the estimated relative
   error of the contact pressure profiles and forces is below TOL. */
typedef struct _n_Accuracy *Accuracy;

PetscErrorCode AccuracyCreate(MPI_Comm, Accuracy *);
/* Reads -accuracy and its options (listed by -help). */
PetscErrorCode AccuracySetFromOptions(Accuracy);
/* Whether -accuracy was given. */
PetscBool      AccuracyIsSet(Accuracy);
/* Collective: the refinement loop, the report and the output of the last
   step; *status 0 when the target is reached, 2 when a limit stops the loop
   first (the best answer is written) or a solve does not converge. t0: the
   start of the run. */
PetscErrorCode AccuracySolve(Accuracy, PetscLogDouble t0, int *status);
PetscErrorCode AccuracyDestroy(Accuracy *);
