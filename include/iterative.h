#pragma once
#include "problem.h"

/* Newton steps by CG preconditioned by GAMG whose near-nullspace is the
   bodies' rigid motions (iterative.c): the step where a direct factorisation
   no longer fits. */
PetscErrorCode ContactIterativeKSPSetUp(Problem, KSP);
