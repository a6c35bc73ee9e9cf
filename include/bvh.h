#pragma once
#include <petscsys.h>

/* A bounding-volume tree over axis-aligned boxes (bvh.c): the faces of a
   contact surface, each by its box (Face3dBox), queried by a box. */

typedef struct _n_Bvh *Bvh;

PetscErrorCode BvhCreate(PetscInt, const PetscReal[], Bvh *);
PetscErrorCode BvhQuery(Bvh, const PetscReal[6], PetscInt *, const PetscInt **);
PetscErrorCode BvhDestroy(Bvh *);
/* Whether two closed boxes (lo[3] then hi[3]) meet (touching counts). */
static inline PetscBool BvhBoxesMeet(const PetscReal a[6], const PetscReal b[6])
{
  for (PetscInt d = 0; d < 3; ++d)
    if (a[3 + d] < b[d] || b[3 + d] < a[d]) return PETSC_FALSE;
  return PETSC_TRUE;
}
