#pragma once
#include "problemtypes.h"

/* The watch for a frictional contact that slides without end (slidewatch.c). */
/* At the start of each TAO solve: no iterate recorded. */
PetscErrorCode ProblemSlideWatchBegin(Problem);
/* Part of TAO's convergence test (solve.c): DIVERGED_USER, with the pair's
   diagnosis in the problem's why, once the slip of a pair none of whose
   nodes sticks has grown without contracting for a few iterations. */
PetscErrorCode ProblemSlideWatchTest(Problem, Tao);
/* Whether the last TAO solve stopped while a frictional contact slid without
   end (its slip grew without contracting, no node sticking at its last
   iterate): the problem's why then names the pair. */
PetscErrorCode ProblemSlideWatchSlid(Problem, PetscBool *slid);
