#pragma once
#include <petscsys.h>

/* A bounding-volume tree over axis-aligned boxes (bvh.c): the faces of a
   contact surface, each by its box (Face3dBox), queried by a box. */

typedef struct _n_Bvh *Bvh;

PetscErrorCode BvhCreate(PetscInt, const PetscReal[], Bvh *);
PetscErrorCode BvhQuery(Bvh, const PetscReal[6], PetscInt *, const PetscInt **);
PetscErrorCode BvhDestroy(Bvh *);
