#pragma once
#include "surface.h"

/* Closest-point search over a master surface's edges in the current
   configuration (search.c): a bounding-volume hierarchy rebuilt from the
   current coordinates by ContactSearchBuild, queried point by point. */
typedef struct _n_ContactSearch *ContactSearch;

PetscErrorCode ContactSearchCreate(const ContactSurface *master, ContactSearch *);
/* Rebuilds the tree from the master's current coordinates (master->x). */
PetscErrorCode ContactSearchBuild(ContactSearch);
/* Closest master edge to p and the parameter eta of the closest point on it;
   every point has one, however far (*edge = -1 only for an empty surface). */
void           ContactSearchFindClosest(ContactSearch, const PetscReal p[2], PetscInt *edge, PetscReal *eta);
PetscErrorCode ContactSearchDestroy(ContactSearch *);
