#pragma once
#include "problemtypes.h"

/* Collective: the most a Newton step may move coupled force control k's
   group in 3D before its body's contact surfaces pass through their
   partners (forcereach.c); 0 where no such bound applies (2D, a rigid
   body's unknown, an anchor, a body in no contact pair, flat faces across
   the control). */
PetscErrorCode ForceControlContactReach(Problem, PetscInt k, PetscReal *reach);
