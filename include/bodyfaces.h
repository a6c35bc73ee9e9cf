#pragma once
#include "body.h"

/* A 3D elastic body's boundary faces as a 3D contact surface sees them
   (src/body/faces.c; the 2D analogue is BodyGetGroupEdges and BodyMapNodes,
   boundary.c). */

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
/* The 3D BodyMapNodes: the surface nodes (global numbers ids, nn of them,
   sorted) among this rank's owned points, map->node their index among the
   nn and map->off their local offsets; joined[3 nn], on every rank, each
   node's components' indices in the joined vector (-1: constrained). */
PetscErrorCode BodyMapFaceNodes(Body, PetscInt nn, const PetscInt ids[], BodyNodeMap *map, PetscInt joined[]);
/* Collective: the displacements u[3 nn] of the nodes from the body's local
   vector, each from the rank that owns it (the same bits on every rank). */
PetscErrorCode BodyGetFaceNodeDisplacements(Body, PetscInt nn, const BodyNodeMap *, PetscReal u[]);
/* Adds g[3 nn] (the same on every rank) at this rank's owned nodes into the
   body's local gradient. */
PetscErrorCode BodyAddFaceNodeForces(Body, const BodyNodeMap *, const PetscReal g[]);
