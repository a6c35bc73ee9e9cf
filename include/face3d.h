#pragma once
#include <petscsys.h>

/* A curved quadratic face of a 3D contact surface (face3d.c): Tri6 (the
   face of a Tet10) and Quad9 (of a Hex27), nodes in Gmsh's order. The map
   x(xi) = sum_i N_i(xi) x_i, its tangents, normal and area element; the
   weights W_j of the nodal weighted gaps (dual to a basis whose every
   function integrates positive); the closest point of a face to a point;
   a box that holds the curved face; Gauss rules on the reference face. */

typedef enum { FACE3D_TRI6, FACE3D_QUAD9 } Face3dType;

#define FACE3D_MAX_NODES 9

/* Parameters: Tri6 on the unit triangle (0,0), (1,0), (0,1) (corners 0-2,
   mid-edge 3: 0-1, 4: 1-2, 5: 2-0); Quad9 on [-1,1]^2 (corners 0-3
   anticlockwise from (-1,-1), mid-edge 4: 0-1, 5: 1-2, 6: 2-3, 7: 3-0,
   centre 8). The orientation (t_1 x t_2) is the body's outward normal. */
static inline PetscInt Face3dNodes(Face3dType t)
{
  return t == FACE3D_TRI6 ? 6 : 9;
}

/* A Gauss rule on a reference domain: points xi[2 q], weights w[q]. */
typedef struct {
  PetscInt   nq;
  PetscReal *xi, *w;
} Face3dRule;

void      Face3dNodeXi(Face3dType, PetscInt, PetscReal[2]);
void      Face3dShape(Face3dType, const PetscReal[2], PetscReal[], PetscReal[], PetscReal[]);
void      Face3dEval(Face3dType, const PetscReal[], const PetscReal[2], PetscReal[3], PetscReal[6], PetscReal[9]);
PetscReal Face3dNormal(const PetscReal[6], PetscReal[3]);
/* An orthonormal basis t1 = T[0..2], t2 = T[3..5] of the plane normal to the unit vector n:
   t1 from the axis least along n (the first of the least), t2 = n x t1. */
void      Face3dPlaneBasis(const PetscReal[3], PetscReal[6]);
PetscBool Face3dContains(Face3dType, const PetscReal[2], PetscReal);
void      Face3dWeightBasis(Face3dType, const PetscReal[2], PetscReal[]);
void      Face3dWeights(Face3dType, const PetscReal[], const PetscReal[2], PetscReal[]);
PetscBool Face3dClosestPoint(Face3dType, const PetscReal[], const PetscReal[3], PetscReal[2], PetscInt *);
void      Face3dClosestBoundaryPoint(Face3dType, const PetscReal[], const PetscReal[3], PetscReal[2]);
void      Face3dClosestPointOnFace(Face3dType, const PetscReal[], const PetscReal[3], PetscReal, PetscReal[2], PetscBool *);
void      Face3dBox(Face3dType, const PetscReal[], PetscReal[6]);
/* The face's size: its longest side, corner to corner. */
PetscReal Face3dSize(Face3dType, const PetscReal[]);
void      Face3dSubTriangles(Face3dType, PetscInt *, const PetscInt (**)[3]);

PetscErrorCode Face3dRuleCreate(Face3dType, PetscInt, Face3dRule *);
PetscErrorCode Face3dRuleDestroy(Face3dRule *);
PetscErrorCode Face3dDualCoefficients(Face3dType, const PetscReal[], const Face3dRule *, PetscReal[]);

/* The transformation of the Tri6 weight basis (Popp-Wohlmuth; face3d.c). */
#define FACE3D_TRI6_ALPHA 0.2
