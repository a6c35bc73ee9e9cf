#pragma once
/* Axisymmetry (axis.c): u_r = 0 held on the points on the axis, a Dirichlet
   condition of its own (in BodySetUp, before the section is made), and
   the check that no node lies at x < 0 (once the cell cache is built). */
#include "bodycore.h"

PetscErrorCode BodyAddAxis(Body);
PetscErrorCode BodyCheckAxis(Body);
