#pragma once
/* The Body's data, private to the body's files (src/body/): everyone else
   holds a Body as an opaque handle and asks it through the functions of
   include/body.h and the headers it gathers, as PETSc's objects keep their
   structs in include/petsc/private/ *impl.h. The operations that differ
   between an elastic and a rigid body are a table (ops), below. */
#include "body.h"
#include "bodyfaces.h"

/* What differs between an elastic body (body.c, boundary.c) and a rigid one
   (rigidbody.c, rigidsurface.c): the body's functions of include/body.h
   call through this table, so that no caller asks which kind a body is.
   BodyCreate fills the elastic table, BodySetFromOptions the rigid one where
   -<body>_rigid says so. A rigid body leaves NULL what it has nothing for
   (its cells' Hessian, tangent and errors, its dofs' numbering and scatter),
   and the body's function is then a no-op. */
typedef struct {
  PetscErrorCode (*setup)(Body, PetscInt partitioner, PetscBool partitionView);
  PetscErrorCode (*globaltolocal)(Body, Vec Xg, Vec Xl);
  PetscErrorCode (*energygradient)(Body, Vec Xl, PetscReal *energy, Vec Gl);
  PetscErrorCode (*hessian)(Body, Mat H);
  PetscErrorCode (*tangent)(Body, Vec Xl, Mat H);
  PetscErrorCode (*applytangent)(Body, Vec Xl, Vec El, Vec Yl);
  PetscErrorCode (*reactions)(Body, Vec Gl);
  PetscErrorCode (*errors)(Body, Vec Xl, BodyErrors *);
  PetscErrorCode (*setjoinednumbering)(Body, PetscInt first);
  PetscErrorCode (*addjoinedgradient)(Body, Vec Yl, PetscScalar g[]);
  PetscErrorCode (*checkheld)(Body, PetscBool contact);
  PetscErrorCode (*viewsolution)(Body, PetscBool axisymmetric);
  PetscErrorCode (*groupedges)(Body, const char group[], const char what[], PetscInt *tag, PetscInt *n, PetscInt **eid, PetscReal **erl);
  PetscErrorCode (*boundaryedgesat)(Body, PetscInt tag, PetscInt nn, const PetscInt ids[], const PetscBool end[], BodyEdgeFn fn, void *ctx);
  PetscErrorCode (*mapnodes)(Body, PetscInt nn, const PetscInt ids[], BodyNodeMap *map, PetscInt joined[]);
  PetscErrorCode (*nodedisplacements)(Body, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, PetscReal u[]);
  PetscErrorCode (*addnodeforces)(Body, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, const PetscReal g[]);
  PetscErrorCode (*addsurfacehessian)(Body, const PetscReal x[], PetscInt n, const PetscInt idx[], const PetscScalar K[]);
  PetscErrorCode (*getcontrols)(Body, PetscInt *n, BodyControl ctl[]);
  PetscErrorCode (*setcontrol)(Body, PetscInt bc, PetscInt c, PetscReal U);
  PetscReal (*controlforce)(Body, PetscInt bc, PetscInt c);
  PetscReal (*controlreaction)(Body, PetscInt bc, PetscInt c);
  const char *(*controlcomponent)(Body, PetscInt bc, PetscInt c);
  /* the body at the load's weights (loadWeight, stage) where they are not
     its conditions' and loads' staged values (a rigid body's motion; NULL:
     those, history.c) */
  PetscErrorCode (*setload)(Body);
  PetscErrorCode (*destroy)(Body);
} BodyOps;

/* One elastic body: its own DMPlex (P2 on Tri6 and Tet10, Q2 on Quad9 and Hex27), material, Dirichlet
   conditions and the per-cell geometry cache used by the element loops; or a rigid body (rg). */
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
  PetscReal *state;/* [ncells][nq][mat->nstate]: a material with history's accepted state at each point (bodystate.c), or NULL */
  PetscReal *stateNew; PetscBool statePending; /* the state a converged increment recorded, and whether it waits for the next increment's begin */
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
  BodyOps   ops;
};

/* A rigid body's curves (2D) or surfaces (3D) and motion (rigidbody.h
   describes the motion). Its unknowns q: 2D's t_x, t_y and the arc
   L theta; 3D's t_x, t_y, t_z and L theta_x, L theta_y, L theta_z
   (theta the rotation vector, rigid3d.c). */
#define RIGID_MAX_UNKNOWNS 6
struct _n_BodyRigid {
  PetscInt   dim;       /* 2: curves, 3: surfaces (a Physical Volume in its mesh: rigid3d.c) */
  PetscInt   nq;        /* the motion's components: 3 (2D) or 6 (3D) */
  PetscInt   nn;        /* nodes of the curves or surfaces */
  PetscInt  *ids;       /* [nn] Gmsh node numbers, sorted */
  PetscReal *X;         /* [nn][dim] reference coordinates */
  PetscInt   ne;        /* second-order line elements (2D) */
  PetscInt  *enodes;    /* [ne][3] node indices: the ends, then the middle */
  PetscInt  *etag;      /* [ne] physical tag */
  PetscInt   nf, nbf;   /* 3D: second-order faces (Tri6 or Quad9), nodes per face (6 or 9) */
  PetscInt  *fnodes;    /* [nf][nbf] node indices in Gmsh's order, turned so that the corners' right hand points outward */
  PetscInt  *ftag;      /* [nf] physical tag */
  PetscReal  centre[3]; /* reference point c */
  PetscReal  rotation[CONTACT_MAX_STAGES]; /* the rotation at each stage's end (radians) */
  PetscReal  rotEnd[CONTACT_MAX_STAGES][3]; /* 3D: the rotation vector at each stage's end (0 for an unknown) */
  PetscReal  tEnd[CONTACT_MAX_STAGES][3];  /* the translation at each stage's end (the conditions' values; 0 for an unknown) */
  PetscReal  momEnd[CONTACT_MAX_STAGES][3]; /* -rigid_moment: the moment on the free rotation at each stage's end (2D: [s][0]) */
  PetscReal  t[3], theta; /* the motion at the current load parameter */
  PetscReal  rot[3];      /* 3D: the rotation vector theta at the current load parameter */
  PetscReal  force[3], moment; /* the contact's force on the body and its moment about c + t, at the last evaluation */
  PetscReal  mom[3];      /* 3D: the moment sum (x - c - t) x g about c + t */
  PetscReal  grot[3];     /* 3D: dPi/dtheta = sum g . dx/dtheta */
  PetscReal  curl;      /* -sum g.(x - c - t) at the last evaluation: d2Pi/dtheta2 beyond the contact's Hessian */
  PetscReal  curl3[9];  /* 3D: sum g . d2x/dtheta_j dtheta_k at the last evaluation */
  PetscReal  L;         /* the curves' size (their bounding box's diagonal): the rotation's unknown is L theta */
  PetscBool  unknown[RIGID_MAX_UNKNOWNS];  /* component q is an unknown */
  PetscBool  control[RIGID_MAX_UNKNOWNS];  /* a force control (a condition's _control force); else held by the contact alone */
  PetscReal  qforce[RIGID_MAX_UNKNOWNS];   /* an unknown's force at the full load (a control's; 0: held by the contact) */
  PetscInt   qbc[RIGID_MAX_UNKNOWNS];      /* the condition that controls component q, or -1 */
  Vec        B[RIGID_MAX_UNKNOWNS];        /* during a Hessian's assembly (borrowed): column q of the border, the contact's coupling of unknown q to the joined vector's dofs */
  PetscReal  D[RIGID_MAX_UNKNOWNS * RIGID_MAX_UNKNOWNS]; /* and this rank's part of the contact's coupling between the unknowns, [nq][nq] */
  char       prefix[CONTACT_NAME_LEN + 2]; /* the options' prefix, and the motion's options as given: read at the set-up, once the mesh says the dimension */
  char       rotOpt[64 * CONTACT_MAX_STAGES];
  PetscBool  setRot, setCentre, setMom;
  PetscReal  centreOpt[3];
  PetscInt   ncentre;
  PetscReal  momOpt[3 * CONTACT_MAX_STAGES + 1];
  PetscInt   nmom;
};

/* rigidbody.c's, for the body's files (rigidbody.h describes the motion). */
/* The rigid options (-<body>_rigid_centre, -<body>_rigid_rotation), in the body's options block's place. */
PetscErrorCode BodyRigidSetFromOptions(Body, const char prefix[]);
/* Collective: reads the curves of b->msh (rank 0, broadcast), the reference
   point, the conditions' translation; b->nlocal = 0. */
PetscErrorCode BodyRigidSetUp(Body);
/* The prescribed motion at the load parameter b->stage and b->loadWeight say (history.c). */
/* Sets unknown q of the motion (x, y translation, or the arc L theta). */
void           BodyRigidSetUnknown(Body, PetscInt q, PetscReal value);
/* Unknown q's value, and its gradient dPi/dq at the last evaluation (the force, or the moment over L). */
PetscReal      BodyRigidGetUnknown(const Body, PetscInt q);
PetscReal      BodyRigidUnknownGradient(const Body, PetscInt q);
/* The contact's force and moment on the body: minus its unknowns' gradient
   (a support's reaction is the gradient: the two balance at equilibrium). */
void           BodyRigidContactForce(const Body, PetscReal f[2], PetscReal *moment);
/* The derivative of the current position x of a point with respect to
   unknown q: J[q] = (1, 0), (0, 1), or perp(x - c - t) / L. */
void           BodyRigidJacobian(const Body, const PetscReal x[2], PetscReal J[3][2]);
/* Adds to the border a Hessian block K (n x n, row-major, symmetric) over
   the joined vector's indices idx, where the negative ones below -1 are
   this body's surface nodes' components (ContactRigidDofDecode), at their
   current positions x: K's coupling of them to the other indices into
   r->B, among themselves into r->D. */
PetscErrorCode BodyRigidAddHessian(Body, const PetscReal x[], PetscInt n, const PetscInt idx[], const PetscScalar K[]);
/* The displacement of the reference point X under the current motion. */
void           BodyRigidDisplacement(const Body, const PetscReal X[2], PetscReal u[2]);
/* Zeroes the force and moment (before an evaluation). */
void           BodyRigidZeroForce(Body);
/* Adds the gradient g[n][2] at the nodes of reference coordinates X[n][2]
   (summed over ranks) to the body's force and moment. */
void           BodyRigidAddForce(Body, PetscInt n, const PetscReal X[], const PetscReal g[]);
/* The conditions' reactions: each group's held components' share of the force (the whole force). */
PetscErrorCode BodyRigidComputeReactions(Body);
PetscErrorCode BodyRigidDestroy(Body);
/* The line elements of physical tag: their count, and (PetscFree) their indices. */
PetscErrorCode BodyRigidGroupEdges(Body, PetscInt tag, PetscInt *n, PetscInt **edges);

/* rigid3d.c's: a rigid 3D body. Rigid3dIs: whether the body's mesh has a
   Physical Volume (rank 0 reads, every rank answers). ReadSurfaces: its
   faces (rank 0 reads, broadcast), oriented, its size L and default
   centre. The motion's options, conditions and functions in 3D, which
   rigidbody.c's call where r->dim == 3. */
PetscErrorCode Rigid3dIs(Body, PetscBool *);
PetscErrorCode Rigid3dSetUpSurfaces(Body, BodyRigid *);
PetscErrorCode Rigid3dParseRotation(Body, BodyRigid *);
void           Rigid3dDisplacement(const BodyRigid *, const PetscReal X[3], PetscReal u[3]);
void           Rigid3dAddForce(BodyRigid *, PetscInt n, const PetscReal X[], const PetscReal g[]);
PetscErrorCode Rigid3dAddHessian(Body, const PetscReal x[], PetscInt n, const PetscInt idx[], const PetscScalar K[]);
PetscErrorCode Rigid3dGroupFaces(Body, const char group[], PetscInt *tag, BodyFaces *);
PetscErrorCode Rigid3dViewSolution(Body);

/* Collective: the quadrature points' state of a material with history, at
   rest (bodystate.c), once the cell cache is built. */
PetscErrorCode BodyStateSetUp(Body);

/* The elastic body's operations (body.c, boundary.c) and the rigid body's (rigidbody.c, rigidsurface.c). */
void BodyElasticSetOps(Body);
void BodyRigidSetOps(Body);
/* The elastic implementations of other files than body.c, for its table. */
PetscErrorCode BodySetJoinedNumbering_Elastic(Body, PetscInt first);
PetscErrorCode BodyAddJoinedGradient_Elastic(Body, Vec Yl, PetscScalar g[]);
PetscErrorCode BodyGetControls_Elastic(Body, PetscInt *n, BodyControl ctl[]);
PetscErrorCode BodySetControlValue_Elastic(Body, PetscInt bc, PetscInt c, PetscReal U);
PetscReal      BodyGetControlForce_Elastic(Body, PetscInt bc, PetscInt c);
PetscReal      BodyGetControlReaction_Elastic(Body, PetscInt bc, PetscInt c);
const char    *BodyGetControlComponent_Elastic(Body, PetscInt bc, PetscInt c);
PetscErrorCode BodyCheckHeld_Elastic(Body, PetscBool contact);
PetscErrorCode BodyGetGroupEdges_Elastic(Body, const char group[], const char what[], PetscInt *tag, PetscInt *n, PetscInt **eid, PetscReal **erl);
PetscErrorCode BodyBoundaryEdgesAt_Elastic(Body, PetscInt tag, PetscInt nn, const PetscInt ids[], const PetscBool end[], BodyEdgeFn fn, void *ctx);
PetscErrorCode BodyMapNodes_Elastic(Body, PetscInt nn, const PetscInt ids[], BodyNodeMap *map, PetscInt joined[]);
PetscErrorCode BodyGetNodeDisplacements_Elastic(Body, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, PetscReal u[]);
PetscErrorCode BodyAddNodeForces_Elastic(Body, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, const PetscReal g[]);
/* rigidsurface.c's, for the rigid table (rigidbody.c) */
PetscErrorCode BodyRigidGroupEdgesAsSurface(Body, const char group[], const char what[], PetscInt *tag, PetscInt *n, PetscInt **eid, PetscReal **erl);
PetscErrorCode BodyRigidBoundaryEdgesAt(Body, PetscInt tag, PetscInt nn, const PetscInt ids[], const PetscBool end[], BodyEdgeFn fn, void *ctx);
PetscErrorCode BodyRigidMapNodes(Body, PetscInt nn, const PetscInt ids[], BodyNodeMap *map, PetscInt joined[]);
PetscErrorCode BodyRigidNodeDisplacements(Body, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, PetscReal u[]);
PetscErrorCode BodyRigidAddNodeForces(Body, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, const PetscReal g[]);

/* The measure a point at radius x sweeps per unit area or length: 2 pi x in
   axisymmetry, 1 in plane strain. */
static inline PetscReal BodyRadialWeight(Body b, PetscReal x)
{
  return b->axisym ? 2.0 * PETSC_PI * x : 1.0;
}
