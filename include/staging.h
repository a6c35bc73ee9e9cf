#pragma once
#include "problemtypes.h"

/* The solve's stages (staging.c): load steps, penalty continuation and
   cutbacks as p->sched says, from p->X0 or rest; the TAO iterations of all
   and the reason of the last. TAO's tolerances are restored after them, so
   that another solve of the same problem stops by the same test. */
PetscErrorCode ProblemSolveStaged(Problem, PetscInt *its, TaoConvergedReason *reason);
