#pragma once
#include "body.h"

/* A 3D elastic body's boundary faces as a 3D contact surface sees them
   (src/body/bodyfaces.c; the 2D analogue is BodyGetGroupEdges, boundary.c; the
   nodes' map, displacements and forces are body.h's BodyMapNodes,
   BodyGetNodeDisplacements and BodyAddNodeForces in either dimension). */

/* The faces of a physical surface held by this rank's owned face points,
   each a Tri6 (a Tet10's face, nb = 6) or a Quad9 (a Hex27's, nb = 9) with
   its nodes in Gmsh's order (corners anticlockwise seen from outside, then
   the mid-edge nodes, then a Quad9's centre), so that the corners' right
   hand gives the body's outward normal. Per face and node: its point, its
   global node number, the local offset of its first component, its
   components' joined indices (-1: constrained) and its reference
   coordinates. */
typedef struct {
  PetscInt   n, nb;
  PetscInt  *point;  /* [n][nb] */
  PetscInt  *id;     /* [n][nb] */
  PetscInt  *off;    /* [n][nb] */
  PetscInt  *joined; /* [n][nb][3] */
  PetscReal *X;      /* [n][nb][3] */
} BodyFaces;

/* Collective: the faces of group (a Gmsh physical surface) on this rank;
   tag: its physical tag; what: who asks, for the errors. */
PetscErrorCode BodyGetGroupFaces(Body, const char group[], const char what[], PetscInt *tag, BodyFaces *);
PetscErrorCode BodyFacesDestroy(BodyFaces *);
