#pragma once
/* A body's data (bodycore.c): the Body struct, its Dirichlet conditions and
   loads as data, and the queries of its mesh that the body's files share
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

/* One elastic body: its own DMPlex (P2 on Tri6 and Tet10, Q2 on Quad9 and Hex27), material, Dirichlet
   conditions and the per-cell geometry cache used by the element loops. */
typedef struct _n_Body *Body;
typedef struct _n_BodyRigid BodyRigid; /* a rigid body's curves and motion (rigidbody.h) */
struct _n_Body {
  char      name[CONTACT_NAME_LEN];
  MPI_Comm  comm;
  char      geo[PETSC_MAX_PATH_LEN], msh[PETSC_MAX_PATH_LEN];
  PetscReal h;
  PetscInt  ngeoparams;
  char     *geoparams[16];
  char      bgm[PETSC_MAX_PATH_LEN]; /* size field for Gmsh (-accuracy's refinement, BodySetSizeField), or empty */
  PetscReal E, nu, param[MATERIAL_MAX_PARAMS]; /* E, nu: small-strain at rest (the material's); param: the material's own (material.h) */
  const Material *mat;       /* -<body>_material: its kernels (material.h) */
  PetscInt  inverted; PetscReal invertedAt[2]; /* energy evaluations that found J <= 0, and where the last one did (reference x, y) */
  PetscInt  nbc, qdeg;
  void     *bcctx[CONTACT_MAX_BC][2];
  BodyBC    bc[CONTACT_MAX_BC];
  PetscInt  nload;
  BodyLoad  load[CONTACT_MAX_BC];
  Vec       Fl;         /* the loads' consistent nodal forces at the active stage's end (local vector; this rank's edges), or NULL */
  Vec       FlFrom;     /* the same at the active stage's start (NULL in the first stage: rest) */
  PetscInt  nstages, stage; /* -load_stages (set before BodySetFromOptions), and the active stage, 1..nstages (history.c) */
  PetscReal loadWeight[2]; /* the weights of the active stage's start and end values at the load parameter (history.c) */
  PetscReal loadFactor; /* the factor on what every stage shares (a force control's displacement, the exact solution): the load parameter in the first stage, then 1 */
  ExactSolution exact;
  PetscBool hasExact;

  PetscInt  nphys;
  char    **physNames;
  PetscInt *physDims, *physTags;

  DM        dm;
  PetscFE   fe, feScalar;
  PetscBool simplex;
  PetscInt  dim, ncells, nb, nq, ncellsGlobal; /* dim: 2 (plane strain, r-z) or 3, the components of u too */
  PetscInt *cpts;  /* [ncells][nb]: node points of each cell, in basis order */
  PetscInt *cdof;  /* [ncells][nb]: local offset of the first component of each node */
  PetscReal *dNdx; /* [ncells][nq][nb][dim] */
  PetscReal *wdetJ;/* [ncells][nq] */
  PetscReal *xq;   /* [ncells][nq][dim] */
  PetscReal *xnode;/* [ncells][nb][dim] node coordinates */
  const PetscReal *B; /* [nq][nb] reference basis at quadrature points */
  Vec       Xg, Gg, Xl, Gl, bcl, bclFull, bclFrom; /* bcl: Dirichlet values of the load step, bclFull: the active stage's end, bclFrom: its start (NULL in the first stage) */
  PetscInt  nlocal, nglobal; /* sizes of the body's global (unconstrained) vector */
  PetscInt *l2b;   /* local dof -> index in the joined vector, or -1 if constrained */
  PetscInt  pStart, pEnd;   /* chart */
  PetscReal *xpoint;        /* [chart][dim] reference coordinates of node points */
  PetscBool *owned;         /* [chart] point owned by this rank */
  PetscSection nodeGS;      /* global numbering of the node points */
  PetscLogDouble tmesh; /* wall time of meshing and mesh reading */
  PetscBool generate;   /* the mesh is generated from -geo by Gmsh */
  PetscBool mayAnchor;  /* set before BodySetUp: the body is in a contact and loaded, so a free rigid motion is anchored (anchors.c) */
  PetscInt  npairs;     /* the contact pairs it takes part in (ProblemAddTerm) */
  PetscInt  nsupport;   /* the inward unit normals of its contact surfaces ([nsupport][2], reference configuration) and the largest friction of their pairs (support.c) */
  PetscReal *support, supportMu;
  PetscReal axisTol;    /* axisymmetry: a node within this of x = 0 is on the axis */
  PetscBool rigid;      /* -<body>_rigid: a rigid body (rigidbody.c): no cells, no dofs; rg its curves and motion */
  BodyRigid *rg;
  PetscBool axisym;     /* set before BodySetUp (-axisymmetric): x is the radius r >= 0, y the axis; every volume and surface measure carries 2 pi r (axis.c) */
};

/* The measure a point at radius x sweeps per unit area or length: 2 pi x in
   axisymmetry, 1 in plane strain. */
static inline PetscReal BodyRadialWeight(Body b, PetscReal x)
{
  return b->axisym ? 2.0 * PETSC_PI * x : 1.0;
}

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
