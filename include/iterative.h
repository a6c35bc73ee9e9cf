#pragma once
#include "body.h"
#include "configtypes.h"

/* Newton steps by CG preconditioned by GAMG whose near-nullspace is the
   bodies' rigid motions (iterative.c): the step where a direct factorisation
   no longer fits. H: the Hessian, whose rows on each rank are the bodies'
   dofs in their order; constant: H is the same matrix at every step (no
   contact, no tangent that depends on u), so that GAMG is set up once;
   o: -newton_iterative_nodal, _two_levels, _cycle (newtonstep.c reads them). */
PetscErrorCode ContactIterativeKSPSetUp(KSP, Mat H, PetscInt nbodies, Body bodies[], PetscBool constant, const NewtonOptions *o);
