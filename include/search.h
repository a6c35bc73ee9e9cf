#pragma once
#include "surface.h"

/* Closest-point search over a master surface's edges in the current
   configuration (search.c): a bucket grid rebuilt from the current
   coordinates by ContactSearchBuild, queried point by point. */
typedef struct _n_ContactSearch *ContactSearch;

PetscErrorCode ContactSearchCreate(const ContactSurface *master, ContactSearch *);
/* Rebuilds the grid from the master's current coordinates (master->x). */
PetscErrorCode ContactSearchBuild(ContactSearch);
/* Closest master edge to p and the parameter eta of the closest point on it;
   *edge = -1 if no edge lies within reach (a tenth of the surface's extent). */
void           ContactSearchFindClosest(ContactSearch, const PetscReal p[2], PetscInt *edge, PetscReal *eta);
PetscErrorCode ContactSearchDestroy(ContactSearch *);
