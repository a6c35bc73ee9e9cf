#pragma once
#include "body.h"

/* Newton steps by CG preconditioned by GAMG whose near-nullspace is the
   bodies' rigid motions (iterative.c): the step where a direct factorisation
   no longer fits. H: the Hessian, whose rows on each rank are the bodies'
   dofs in their order. */
PetscErrorCode ContactIterativeKSPSetUp(KSP, Mat H, PetscInt nbodies, Body bodies[]);
