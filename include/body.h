#pragma once
#include "contact.h"
#include "exact.h"

/* A Dirichlet condition: a named physical group, constrained components and
   values. A force-controlled component (-<body>_bc_<group>_control force)
   moves the group rigidly by values[c], which the solve finds so that the
   reaction equals force[c] (forcecontrol.c). */
typedef struct {
  char      group[CONTACT_NAME_LEN];
  PetscInt  ncomp, comps[2];
  PetscReal values[2];
  PetscBool control[2]; /* component c (of comps) is force-controlled */
  PetscBool anchor;     /* an anchor of a body held by contact (anchors.c): force 0 */
  PetscReal force[2];   /* its force: the reaction it must have */
  PetscBool exact;   /* values from the body's exact solution */
  PetscInt  tag;     /* Gmsh physical tag */
  DMLabel   label;   /* faces of the group and their closure */
  PetscReal reaction[2];
} BodyBC;

/* A dead load on a named physical group (loads.c): a traction per unit
   reference length, or a pressure along the inward reference normal. */
typedef struct {
  char      group[CONTACT_NAME_LEN];
  PetscBool isPressure;
  PetscReal traction[2], pressure;
  PetscReal force[2]; /* its resultant at the full load, summed over ranks (BodyLoadsSetUp) */
} BodyLoad;

/* One elastic body: its own DMPlex (P2 on Tri6, Q2 on Quad9), material, Dirichlet
   conditions and the per-cell geometry cache used by the element loops. */
typedef struct _n_Body *Body;
struct _n_Body {
  char      name[CONTACT_NAME_LEN];
  MPI_Comm  comm;
  char      geo[PETSC_MAX_PATH_LEN], msh[PETSC_MAX_PATH_LEN];
  PetscReal h;
  PetscInt  ngeoparams;
  char     *geoparams[16];
  char      bgm[PETSC_MAX_PATH_LEN]; /* size field for Gmsh (-accuracy's refinement, BodySetSizeField), or empty */
  PetscReal E, nu, param[2]; /* param = {lambda, mu} */
  PetscInt  nbc, qdeg;
  void     *bcctx[CONTACT_MAX_BC][2];
  BodyBC    bc[CONTACT_MAX_BC];
  PetscInt  nload;
  BodyLoad  load[CONTACT_MAX_BC];
  Vec       Fl;         /* the loads' consistent nodal forces at the full load (local vector; this rank's edges), or NULL */
  PetscReal loadFactor; /* load stepping: the fraction of the Dirichlet values and loads applied */
  ExactSolution exact;
  PetscBool hasExact;

  PetscInt  nphys;
  char    **physNames;
  PetscInt *physDims, *physTags;

  DM        dm;
  PetscFE   fe, feScalar;
  PetscBool simplex;
  PetscInt  dim, ncells, nb, nq, ncellsGlobal;
  PetscInt *cpts;  /* [ncells][nb]: node points of each cell, in basis order */
  PetscInt *cdof;  /* [ncells][nb]: local offset of the first component of each node */
  PetscReal *dNdx; /* [ncells][nq][nb][2] */
  PetscReal *wdetJ;/* [ncells][nq] */
  PetscReal *xq;   /* [ncells][nq][2] */
  PetscReal *xnode;/* [ncells][nb][2] node coordinates */
  const PetscReal *B; /* [nq][nb] reference basis at quadrature points */
  Vec       Xg, Gg, Xl, Gl, bcl, bclFull; /* bcl: Dirichlet values of the load step, bclFull: the scene's */
  PetscInt  nlocal, nglobal; /* sizes of the body's global (unconstrained) vector */
  PetscInt *l2b;   /* local dof -> index in the joined vector, or -1 if constrained */
  PetscInt  pStart, pEnd;   /* chart */
  PetscReal *xpoint;        /* [chart][2] reference coordinates of node points */
  PetscBool *owned;         /* [chart] point owned by this rank */
  PetscSection nodeGS;      /* global numbering of the node points */
  PetscLogDouble tmesh; /* wall time of meshing and mesh reading */
  PetscBool generate;   /* the mesh is generated from -geo by Gmsh */
  PetscBool mayAnchor;  /* set before BodySetUp: the body is in a contact and loaded, so a free rigid motion is anchored (anchors.c) */  PetscReal axisTol;    /* axisymmetry: a node within this of x = 0 is on the axis */
  PetscBool axisym;     /* set before BodySetUp (-axisymmetric): x is the radius r >= 0, y the axis; every volume and surface measure carries 2 pi r (axis.c) */
};

/* The measure a point at radius x sweeps per unit area or length: 2 pi x in
   axisymmetry, 1 in plane strain. */
static inline PetscReal BodyRadialWeight(Body b, PetscReal x)
{
  return b->axisym ? 2.0 * PETSC_PI * x : 1.0;
}

PetscErrorCode BodyCreate(MPI_Comm, const char name[], Body *);
PetscErrorCode BodySetFromOptions(Body, PetscReal meshSizeOverride);
/* Refuses a group named twice in the list of option opt (-<body>_bc, -<body>_load). */
PetscErrorCode BodyCheckGroupsUnique(Body, const char opt[], PetscInt n, char *const names[]);
/* The Gmsh size field (a .pos file) the body's next mesh follows; "" or NULL: none. */
PetscErrorCode BodySetSizeField(Body, const char path[]);
/* Meshes the body's .geo with Gmsh (cached in meshDir), unless the mesh would
   exceed *maxDofs (> 0), which its estimate is taken off (limit describes
   where the limit comes from); estimateOnly: the check alone, no meshing. */
PetscErrorCode BodyGenerateMesh(Body, const char meshDir[], PetscReal *maxDofs, const char limit[], PetscBool estimateOnly);
PetscErrorCode BodySetUp(Body, PetscInt partitioner, PetscBool partitionView);
PetscErrorCode BodyDestroy(Body *);
PetscErrorCode BodyGetReferenceNodes(Body, PetscReal ref[]);
/* This rank's vertices' coordinates, [v - vStart][2] (PetscFree); before the section exists too. */
PetscErrorCode BodyVertexCoordinates(Body, PetscReal **xy);
/* Collective: the bounding box lo, hi of every rank's points xy[n][2]. */
PetscErrorCode BodyPointsBox(Body, PetscInt n, const PetscReal xy[], PetscReal lo[2], PetscReal hi[2]);
/* The index k of component c among bc's components if bc holds c at point p, else -1. */
PetscErrorCode BodyBCHolds(const BodyBC *bc, PetscInt p, PetscInt c, PetscInt *k);
/* The first Dirichlet condition whose label holds component c at point p:
   its index i and the index k of c among its components (-1, -1: none). */
PetscErrorCode BodyBCHolding(Body, PetscInt p, PetscInt c, PetscInt *i, PetscInt *k);
PetscReal      BodyElementGradients(PetscInt nb, const PetscReal x[][2], const PetscReal D[], PetscReal dNdx[]);
PetscErrorCode BodyGetNodeNumber(Body, PetscInt point, PetscInt *node);
PetscErrorCode BodyGetPhysicalTag(Body, const char group[], PetscInt dim, PetscInt *tag);
PetscErrorCode BodyGlobalToLocal(Body, Vec Xg, Vec Xl);
PetscErrorCode BodySetLoadFactor(Body, PetscReal);
/* Moves Dirichlet condition i's component c (an index into its comps) to
   the value U (a force-controlled component's displacement). */
PetscErrorCode BodySetBCValue(Body, PetscInt i, PetscInt c, PetscReal U);
/* Whether the reference edge e (a point of b's DMPlex, on the boundary) has
   outward normal +(t_y, -t_x) or -(t_y, -t_x), t the chord from its first to
   its second node: away from the centroid of the cell on it. x: its nodes'
   coordinates (corner, corner, mid); what: who asks, for the error of an
   edge that is not on the boundary. */
PetscErrorCode BodyEdgeOutwardSign(Body, PetscInt e, const PetscReal x[6], const char what[], const char group[], PetscReal *sign);
/* The nodes of boundary edge e: their points (corner, corner, mid) and coordinates. */
PetscErrorCode BodyEdgeNodes(Body, PetscInt e, PetscInt pts[3], PetscReal x[6]);
/* Loads (loads.c): -<body>_load and each group's _traction or _pressure. */
PetscErrorCode BodyLoadsSetFromOptions(Body, const char prefix[], PetscBool help);
/* This rank's edges of load L's group (all, owned or not): their number and points (is NULL if none; ISDestroy). */
PetscErrorCode BodyLoadGetEdges(Body, const BodyLoad *L, PetscInt *n, IS *is);
/* Load L's consistent nodal forces fe[3][2] on boundary edge e, at its nodes pts (corner, corner, mid). */
PetscErrorCode BodyLoadEdgeForces(Body, const BodyLoad *L, PetscInt e, PetscInt pts[3], PetscReal fe[3][2]);
/* Collective: the consistent nodal forces of the loads, once the mesh is read. */
PetscErrorCode BodyLoadsSetUp(Body);
/* Adds -f . u (times the load factor) to *energy and -f to g (local arrays). */
PetscErrorCode BodyLoadsAddEnergyGradient(Body, const PetscScalar x[], PetscReal *energy, PetscScalar g[]);
PetscErrorCode BodyComputeEnergyGradient(Body, Vec Xl, PetscReal *energy, Vec Gl);
PetscErrorCode BodyAssembleHessian(Body, Mat H);
PetscErrorCode BodyAssembleHessianMapped(Body, const PetscInt map[], Mat H);
PetscErrorCode BodyAddRigidModes(Body, PetscInt rstart, PetscInt rend, PetscScalar *modes[3]);
PetscErrorCode BodyComputeReactions(Body, Vec Gl);
PetscErrorCode BodyCountFreeRigidModes(Body, PetscInt *nfree);
/* Adds to the rigid-motion constraint Gram matrix M the row of component c
   fixed at (x, y) (coordinates centred and scaled): (e_c, r_c), r = (-y, x). */
void           BodyRigidGramAddRow(PetscReal M[9], PetscInt c, PetscReal x, PetscReal y);
/* The rank of a rigid-motion constraint Gram matrix (3 x 3: x and y
   translation, rotation), by elimination with full pivoting. */
PetscInt       BodyRigidRank(const PetscReal M[9]);
/* Axisymmetry: the radial translation and the rotation marked held in M (body.c). */
void           BodyRigidGramAxisymmetric(Body, PetscReal M[9]);
/* Axisymmetry (axis.c): u_r = 0 held on the points on the axis, a Dirichlet
   condition of its own (in BodySetUp, before the section is made), and
   the check that no node lies at x < 0 (once the cell cache is built). */
PetscErrorCode BodyAddAxis(Body);
PetscErrorCode BodyCheckAxis(Body);
/* Collective, at the end of BodySetUp (conditions.c): refuses a force-controlled
   group's node that another condition holds in the controlled component, and a
   load acting at a node in a component that a force control holds; warns of a
   load whose part in a component acts only at nodes held in it. */
PetscErrorCode BodyCheckConditions(Body);
/* Anchors the rigid motions its Dirichlet conditions leave free (anchors.c;
   in BodySetUp, before the section is made). */
PetscErrorCode BodyAddAnchors(Body);
/* Collective: refuses a first-order mesh (affine coordinates) in one line. */
PetscErrorCode BodyCheckSecondOrder(Body);
/* A body's errors against its exact solution, if any (zero without one), with
   the exact solution's norms: L2 of u, energy norm, L2 of the stress. */
typedef struct {
  PetscReal l2, l2norm, energy, energynorm, stress, stressnorm;
} BodyErrors;
PetscErrorCode BodyComputeErrors(Body, Vec Xl, BodyErrors *);
/* Nodal fields for output (fields.c), from the body's local vector Xl. */
typedef struct {
  Vec       coords, disp, stress, vm;
  IS        topo;
  PetscInt  nnodes, ncells;
  PetscReal umax, unorm2;
  BodyErrors err; /* against the body's exact solution, if any */
} BodyNodalFields;
PetscErrorCode BodyComputeNodalFields(Body, Vec Xl, BodyNodalFields *);
PetscErrorCode BodyNodalFieldsDestroy(BodyNodalFields *);
/* Zienkiewicz-Zhu error indicator of each local cell (fields.c): the L2 norm
   of the recovered (nodal-average) stress minus the cell's stress. */
PetscErrorCode BodyComputeStressIndicator(Body, Vec Xl, PetscReal eta[]);
