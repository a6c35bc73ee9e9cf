#pragma once
/* A body's handle (its struct is private to src/body/, in bodyimpl.h), its
   Dirichlet conditions and loads as data, and the queries of its mesh that the body's files share
   (body.c, conditions.c, loads.c, axis.c, anchors.c, rigid.c, transfer.c).
   It calls none of them. */
#include "contact.h"
#include "exact.h"
#include "material.h"

/* A Dirichlet condition: a named physical group (or the program's own
   points: the axis's, an anchor's), constrained components and values. A force-controlled component (-<body>_bc_<group>_control force)
   moves the group rigidly by values[c], which the solve finds so that the
   reaction equals force[c] (forcecontrol.c). */
typedef struct {
  char      group[CONTACT_NAME_LEN];
  PetscInt  ncomp, comps[3]; /* at most the body's dimension */
  PetscReal values[3];
  PetscBool control[3]; /* component c (of comps) is force-controlled */
  PetscBool anchor;     /* an anchor of a body held by contact (anchors.c): force 0 */
  PetscBool allComps;   /* no -components: every component of the body (its dimension, once the mesh is read) */
  PetscReal force[3];   /* its force: the reaction it must have */
  PetscReal stage[CONTACT_MAX_STAGES][3]; /* -load_stages: each stage's end value of each component (a displacement, or a force where controlled); values and force hold the active stage's (history.c) */
  PetscBool exact;   /* values from the body's exact solution */
  PetscInt  tag;     /* Gmsh physical tag */
  DMLabel   label;   /* faces of the group and their closure */
  PetscReal reaction[3];
} BodyBC;

/* A dead load on a named physical group (loads.c): a traction per unit
   reference length, or a pressure along the inward reference normal. */
typedef struct {
  char      group[CONTACT_NAME_LEN];
  PetscBool isPressure;
  PetscInt  ncomp; /* the traction's components a stage: 2 or 3, the body's dimension (checked once the mesh gives it) */
  PetscReal traction[3], pressure;
  PetscReal force[3]; /* its resultant at the active stage's end, summed over ranks (BodyLoadsSetUp) */
  PetscReal forceFrom[3]; /* its resultant at the active stage's start */
  PetscReal stageTraction[CONTACT_MAX_STAGES][3], stagePressure[CONTACT_MAX_STAGES]; /* -load_stages: each stage's end value; traction and pressure hold the active stage's */
} BodyLoad;

/* A body, elastic or rigid: an opaque handle (src/body/bodyimpl.h holds its
   data); everyone outside src/body/ asks it through the functions declared in
   include/body.h and the headers it gathers. */
typedef struct _n_Body *Body;
typedef struct _n_BodyRigid BodyRigid; /* a rigid body's curves and motion (src/body/bodyimpl.h) */


/* Refuses a group named twice in the list of option opt (-<body>_bc, -<body>_load). */
PetscErrorCode BodyCheckGroupsUnique(Body, const char opt[], PetscInt n, char *const names[]);
PetscErrorCode BodyGetPhysicalTag(Body, const char group[], PetscInt dim, PetscInt *tag);
/* Reference coordinates of the nodes of the scalar element, in basis order. */
PetscErrorCode BodyGetReferenceNodes(Body, PetscReal ref[]);
/* The cell vertices among the element's nb nodes (basis order), in cyclic
   order (quadrilaterals: reference (-1,-1), (1,-1), (1,1), (-1,1)), their
   number nv, and the reference coordinates of every node, ref[2 nb] (nb <= 64). */
PetscErrorCode BodyGetCellCorners(Body, PetscReal ref[], PetscInt corner[4], PetscInt *nv);
/* Collective: refuses a first-order mesh (affine coordinates) in one line. */
PetscErrorCode BodyCheckSecondOrder(Body);
/* This rank's vertices' coordinates, [v - vStart][2] (PetscFree); before the section exists too. */
PetscErrorCode BodyVertexCoordinates(Body, PetscReal **xy);
/* Collective: the bounding box lo, hi of every rank's points xy[n][2]. */
PetscErrorCode BodyPointsBox(Body, PetscInt n, const PetscReal xy[], PetscReal lo[2], PetscReal hi[2]);
/* The nodes of boundary edge e: their points (corner, corner, mid) and coordinates. */
PetscErrorCode BodyEdgeNodes(Body, PetscInt e, PetscInt pts[3], PetscReal x[6]);
/* Whether the reference edge e (a point of b's DMPlex, on the boundary) has
   outward normal +(t_y, -t_x) or -(t_y, -t_x), t the chord from its first to
   its second node: away from the centroid of the cell on it. x: its nodes'
   coordinates (corner, corner, mid); what: who asks, for the error of an
   edge that is not on the boundary. */
PetscErrorCode BodyEdgeOutwardSign(Body, PetscInt e, const PetscReal x[6], const char what[], const char group[], PetscReal *sign);
