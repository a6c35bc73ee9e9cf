#pragma once
#include "run.h"

/* -accuracy TOL (accuracy.c): the pipeline of run.h in a loop, on a sequence
   of meshes, each refined around the contact zones of the last, until the
   estimated relative error of the contact pressure profiles, the contact
   forces computed (not given by force controls) and the displacements of
   the force-controlled groups is below TOL. */
typedef struct _n_Accuracy *Accuracy;

PetscErrorCode AccuracyCreate(MPI_Comm, Accuracy *);
/* Reads -accuracy and its options (listed by -help). */
PetscErrorCode AccuracySetFromOptions(Accuracy);
/* Whether -accuracy was given. */
PetscBool      AccuracyIsSet(Accuracy);
/* Collective: the refinement loop from the problem given (created, not yet
   meshed; taken and destroyed), the report and the output of the last
   converged step (RunFinish); rec->status 0 when the target is reached, 2
   when a limit stops the loop first (the best answer is written) or no step
   converges (none is). */
PetscErrorCode AccuracySolve(Accuracy, Problem *, RunRecord *);
PetscErrorCode AccuracyDestroy(Accuracy *);
