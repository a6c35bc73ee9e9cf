#pragma once
#include <petscsys.h>

/* Convex polygons in a plane (clip.c): the intersection of two by
   Sutherland-Hodgman, its area, and its triangles. Points are (x, y) pairs. */

#define CLIP_MAX_VERTICES 16

PetscReal      ClipSignedArea(PetscInt, const PetscReal[]);
PetscErrorCode ClipConvex(PetscInt, const PetscReal[], PetscInt, const PetscReal[], PetscInt *, PetscReal[]);
PetscInt       ClipTriangulate(PetscInt, const PetscReal[], PetscReal, PetscReal[]);
