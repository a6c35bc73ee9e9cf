#pragma once
/* A body, elastic or rigid (body.c): its life (create, options, mesh,
   set-up, destroy), its energy and stiffness, and the post-processing of a
   solution. body.c orchestrates the body's files below, whose headers this
   one gathers for the callers of the body; a caller never asks which kind a
   body is (the body dispatches, bodyimpl.h), only what it has (BodyHasCells,
   BodyGetRigidMotion). */
#include "bodycore.h"
#include "conditions.h"
#include "controls.h"
#include "history.h"
#include "loads.h"
#include "rigid.h"
#include "rigidbody.h"

PetscErrorCode BodyCreate(MPI_Comm, const char name[], Body *);
PetscErrorCode BodySetFromOptions(Body, PetscReal meshSizeOverride);
/* The Gmsh size field (a .pos file) the body's next mesh follows; "" or NULL: none. */
PetscErrorCode BodySetSizeField(Body, const char path[]);
/* Meshes the body's .geo with Gmsh (cached in meshDir), unless the mesh would
   exceed *maxDofs (> 0), which its estimate is taken off (limit describes
   where the limit comes from); estimateOnly: the check alone, no meshing. */
PetscErrorCode BodyGenerateMesh(Body, const char meshDir[], PetscReal *maxDofs, const char limit[], PetscBool estimateOnly);
PetscErrorCode BodySetUp(Body, PetscInt partitioner, PetscBool partitionView);
PetscErrorCode BodyDestroy(Body *);
PetscReal      BodyElementGradients(PetscInt nb, const PetscReal x[][2], const PetscReal D[], PetscReal dNdx[]);
/* The same in dimension dim (2 or 3): x[nb][dim], D[nb][dim], dNdx[nb][dim]; det J. */
PetscReal      BodyElementGradientsDim(PetscInt dim, PetscInt nb, const PetscReal x[], const PetscReal D[], PetscReal dNdx[]);
/* Global node number of a node point (owned or ghost). */
PetscErrorCode BodyGetNodeNumber(Body, PetscInt point, PetscInt *node);
PetscErrorCode BodyGlobalToLocal(Body, Vec Xg, Vec Xl);
PetscErrorCode BodyComputeEnergyGradient(Body, Vec Xl, PetscReal *energy, Vec Gl);
/* Collective: how many energy evaluations found the body inverted (J <= 0
   at a quadrature point: +inf), and where one did (reference x, y). */
PetscErrorCode BodyGetInversions(Body, PetscInt *n, PetscReal xy[2]);
PetscErrorCode BodyAssembleHessian(Body, Mat H);
PetscErrorCode BodyAssembleHessianMapped(Body, const PetscInt map[], Mat H);
/* The tangent stiffness at the body's local vector Xl, added into H (l2b
   indices): the stiffness at rest for a material of constant tangent. */
PetscErrorCode BodyAssembleTangent(Body, Vec Xl, Mat H);
/* Yl = K(Xl) El, local vectors, K the tangent at Xl (NULL: at rest), this rank's cells' part. */
PetscErrorCode BodyApplyTangentLocal(Body, Vec Xl, Vec El, Vec Yl);
PetscErrorCode BodyComputeReactions(Body, Vec Gl);
/* A body's errors against its exact solution, if any (zero without one), with
   the exact solution's norms: L2 of u, energy norm, L2 of the stress. */
typedef struct {
  PetscReal l2, l2norm, energy, energynorm, stress, stressnorm;
} BodyErrors;
PetscErrorCode BodyComputeErrors(Body, Vec Xl, BodyErrors *);
/* Nodal fields for output (fields.c), from the body's local vector Xl:
   coords and disp of dim components, stress of BodyStressComponents(dim)
   (xx, yy, zz, xy; in 3D then yz, xz). */
#define BodyStressComponents(dim) ((dim) == 3 ? 6 : 4)
typedef struct {
  Vec       coords, disp, stress, vm;
  IS        topo;
  PetscInt  nnodes, ncells;
  PetscReal umax, unorm2;
  BodyErrors err; /* against the body's exact solution, if any */
  PetscReal maxStrain; /* the largest principal Green-Lagrange strain (BodyComputeMaxStrain) */
  PetscInt  nstate;    /* a material with history: its state values' smallest and largest over the quadrature points (BodyGetStateRange) */
  PetscReal stateMin[MATERIAL_MAX_STATE], stateMax[MATERIAL_MAX_STATE];
} BodyNodalFields;
PetscErrorCode BodyComputeNodalFields(Body, Vec Xl, BodyNodalFields *);
/* Cell c's nb global node numbers in the order of its XDMF / VTK cell type
   (cellorder.c): Triangle_6, Quadrilateral_9, Tetrahedron_10, Hexahedron_27. */
PetscErrorCode BodyCellOutputNodes(Body, PetscInt c, PetscInt topo[]);
PetscErrorCode BodyNodalFieldsDestroy(BodyNodalFields *);
/* Collective: the largest principal Green-Lagrange strain, in magnitude,
   over the body's quadrature points (fields.c). */
PetscErrorCode BodyComputeMaxStrain(Body, Vec Xl, PetscReal *emax);
/* Collective: the largest strain (as above), where it is (a quadrature
   point's reference position x), its cell's size h, and the largest strain
   between BODY_STRAIN_RING / 2 and BODY_STRAIN_RING h from x (ring); below
   BODY_STRAIN_POINT times the peak, the peak is a singular point's
   (fields.c derives both). */
#define BODY_STRAIN_RING  4.0
#define BODY_STRAIN_POINT 0.8
typedef struct {
  PetscReal emax, x[3], h, ring;
} BodyStrainPeak;
PetscErrorCode BodyComputeStrainPeak(Body, Vec Xl, BodyStrainPeak *);
/* Zienkiewicz-Zhu error indicator of each local cell (fields.c): the L2 norm
   of the recovered (nodal-average) stress minus the cell's stress. */
PetscErrorCode BodyComputeStressIndicator(Body, Vec Xl, PetscReal eta[]);

/* The state of a material with history at the body's quadrature points
   (bodystate.c; material.h): the lifecycle the energy terms' state has
   (energyterm.h). BodyAcceptState: an increment converged at the body's
   local solution, whose state is recorded; BodyBeginState: the next
   increment begins, the recorded state becomes the accepted one (until
   then the body's energy is still the converged increment's);
   BodyRestoreState: back to the accepted state (a cut-back);
   BodyResetState: back to rest. Collective in spirit, local in fact (each
   point's own); a no-op for a body without history. BodyGetStateRange:
   collective, the smallest and largest value k of the latest state
   (recorded, else accepted) over every rank's points (BodyHasState: the
   material's nstate > 0). */
PetscBool       BodyHasState(Body);
PetscErrorCode  BodyAcceptState(Body);
PetscErrorCode  BodyBeginState(Body);
PetscErrorCode  BodyRestoreState(Body);
PetscErrorCode  BodyResetState(Body);
PetscErrorCode  BodyGetStateRange(Body, PetscInt k, PetscReal *vmin, PetscReal *vmax);

/* What the rest of the program may read of a body (bodyquery.c). */
const char     *BodyGetName(Body);
MPI_Comm        BodyGetComm(Body);
/* 2 or 3, the components of its displacement; a rigid body's curves: 2. */
PetscInt        BodyGetDimension(Body);
PetscBool       BodyIsAxisymmetric(Body);
/* Whether it has cells (and dofs, stress, strain, fields to write): an
   elastic body; a rigid one has curves and a motion alone. */
PetscBool       BodyHasCells(Body);
/* Its Young's modulus and Poisson's ratio at rest (a rigid body: E = inf, nu = 0). */
void            BodyGetElasticConstants(Body, PetscReal *E, PetscReal *nu);
const Material *BodyGetMaterial(Body);
/* Whether its tangent stiffness is the same at every state (a rigid body's: none, constant). */
PetscBool       BodyHasConstantTangent(Body);
/* A rigid body's motion and the contact's force and moment on it (about its
   current reference point), and its curves' node count: PETSC_TRUE for a
   body given by its motion (a rigid one), PETSC_FALSE (m untouched) else. */
typedef struct {
  PetscInt  dim;  /* 2, or 3: t, centre, force and the rotation vector rot and moment mom have three components */
  PetscReal t[3], theta, centre[3], force[3], moment, rot[3], mom[3];
  PetscInt  nodes;
} BodyRigidMotion;
PetscBool       BodyGetRigidMotion(Body, BodyRigidMotion *m);
/* Its nodes per cell (6, 9, 10, 27), this rank's cells, and their nodes'
   reference coordinates, xnode[ncells][nb][dim] (the body's cache). */
PetscInt        BodyGetNodesPerCell(Body);
PetscInt        BodyGetNumLocalCells(Body);
const PetscReal *BodyGetCellNodeCoordinates(Body);
/* Its node points (the chart pStart..pEnd of its DMPlex), whether this rank
   owns each (owned[p - pStart]) and their reference coordinates
   (xpoint[(p - pStart) dim + d]). */
void            BodyGetNodePoints(Body, PetscInt *pStart, PetscInt *pEnd, const PetscBool **owned, const PetscReal **xpoint);
/* Its mesh file (.msh, read or generated) and mesh size; its global counts of dofs and cells. */
const char     *BodyGetMeshFile(Body);
PetscReal       BodyGetMeshSize(Body);
PetscBool       BodyIsSimplex(Body);
void            BodyGetGlobalSizes(Body, PetscInt *ndofs, PetscInt *ncells);
/* Wall time spent meshing and reading its mesh. */
PetscLogDouble  BodyGetMeshTime(Body);
/* The exact solution it is compared with, or NULL. */
const ExactSolution *BodyGetExactSolution(Body);
/* Its local vectors: the displacement of the last scatter (Dirichlet values
   included) and the gradient of the last evaluation (this rank's cells' part). */
Vec             BodyGetLocalSolution(Body);
Vec             BodyGetLocalGradient(Body);
/* Its DMPlex (NULL for a rigid body). */
DM              BodyGetDM(Body);
/* The size of its part of the joined vector on this rank (0 for a rigid
   body), and each local dof's index in the joined vector (-1: constrained). */
PetscInt        BodyGetLocalSize(Body);
const PetscInt *BodyGetJoinedMap(Body);
/* Its Dirichlet conditions and loads (conditions.h, loads.h) by index. */
PetscInt        BodyGetNumConditions(Body);
const BodyBC   *BodyGetCondition(Body, PetscInt j);
PetscInt        BodyGetNumLoads(Body);
const BodyLoad *BodyGetLoad(Body, PetscInt l);
/* -load_stages and -axisymmetric, set by the problem before BodySetFromOptions. */
PetscInt        BodyGetNumStages(Body);
void            BodySetNumStages(Body, PetscInt);
void            BodySetAxisymmetric(Body, PetscBool);
/* The contact pairs it takes part in: one more, and how many. */
void            BodyAddContactPair(Body);
PetscInt        BodyGetNumContactPairs(Body);
/* Before BodySetUp: the body is in a contact and loaded, so that its free
   rigid motions are anchored (anchors.c); a rigid body has none to anchor. */
void            BodySetMayAnchor(Body, PetscBool);
/* The factor on what every stage shares at the load parameter (history.c). */
PetscReal       BodyGetLoadFactor(Body);

/* The joined vector (problem.c): each rank's part is its bodies' owned
   unconstrained dofs in turn. Collective: the body's dofs number from first
   on this rank; X's and G's parts of this body start at x and g. */
PetscErrorCode  BodySetJoinedNumbering(Body, PetscInt first);
PetscErrorCode  BodySetJoinedSolution(Body, const PetscScalar x[]);
PetscErrorCode  BodyAddJoinedGradient(Body, PetscScalar g[]);
/* Every point carrying a node: its dim joined rows (nodeRows[n][dim]), and
   the rows of the nv[k] <= 8 vertices of its closure (vertexRows[n][8][dim]),
   -1 for a constrained component (PetscFree3 the three; none without cells). */
PetscErrorCode  BodyGetNodeVertexRows(Body, PetscInt *n, PetscInt **nodeRows, PetscInt **nv, PetscInt **vertexRows);
/* Collective: refuses a body whose conditions (and contacts: contact, it is
   in one) leave a motion free, so that the problem is singular. */
PetscErrorCode  BodyCheckHeld(Body, PetscBool contact);
/* Collective: prints what the solve found of the body beyond its fields (a
   rigid body's motion and the contact's force on it). */
PetscErrorCode  BodyViewSolution(Body, PetscBool axisymmetric);

/* The body's boundary as a contact surface sees it (boundary.c for an
   elastic body, rigidsurface.c for a rigid one). */
/* A group's boundary edges this rank gives (an elastic body: those its owned
   points hold; a rigid body: rank 0 all of them), with their nodes' global
   numbers (eid, 3 an edge: the ends, then the middle) and, in erl (7 an
   edge), their reference coordinates and the outward normal's sign (a rigid
   body: +1, its side chosen by the surface); tag: the group's physical tag;
   what: who asks, for the errors. PetscFree2(eid, erl). */
PetscErrorCode  BodyGetGroupEdges(Body, const char group[], const char what[], PetscInt *tag, PetscInt *n, PetscInt **eid, PetscReal **erl);
/* For each node of global number ids[v] with end[v] (of nn, sorted), the
   body's boundary edges through it outside the group tag: fn(ctx, v, xf,
   first), xf the edge's nodes' reference coordinates (ends, middle), first:
   the node is its first end. An elastic body calls fn on the rank whose
   cells hold the edge, a rigid body on every rank. */
typedef void (*BodyEdgeFn)(void *ctx, PetscInt v, const PetscReal xf[6], PetscBool first);
PetscErrorCode  BodyBoundaryEdgesAt(Body, PetscInt tag, PetscInt nn, const PetscInt ids[], const PetscBool end[], BodyEdgeFn fn, void *ctx);
/* The surface nodes (global numbers ids, nn of them, sorted) among this
   rank's owned points: map->n of them, node (their index among the nn) and
   off (their offset in the body's local vector); joined[dim nn] (dim the
   body's dimension), on every rank: each node's components' indices in the
   joined vector (-1: constrained; a rigid body: ContactRigidDof, through its
   motion). */
typedef struct {
  PetscInt  n;
  PetscInt *node, *off;
} BodyNodeMap;
PetscErrorCode  BodyMapNodes(Body, PetscInt nn, const PetscInt ids[], BodyNodeMap *map, PetscInt joined[]);
PetscErrorCode  BodyNodeMapDestroy(BodyNodeMap *);
/* Collective: the displacement u[dim nn] of the nodes of reference
   coordinates X[dim nn] (the same to the bit on every rank: each node's from
   the one rank that owns it). */
PetscErrorCode  BodyGetNodeDisplacements(Body, PetscInt nn, const PetscReal X[], const BodyNodeMap *, PetscReal u[]);
/* Collective: the current coordinates x = X + u[dim nn] of the nodes (as
   BodyGetNodeDisplacements); changed: whether any differs from x's last. */
PetscErrorCode  BodyUpdateNodeCoordinates(Body, PetscInt nn, const PetscReal X[], const BodyNodeMap *, PetscReal x[], PetscBool *changed);
/* Adds the gradient g[dim nn] (summed over ranks, the same on every rank) at
   the nodes to the body's: an elastic body's local gradient at its owned
   nodes, a rigid body's force and moment. */
PetscErrorCode  BodyAddNodeForces(Body, PetscInt nn, const PetscReal X[], const BodyNodeMap *, const PetscReal g[]);
/* A contact's Hessian block K over the joined indices idx at the surface's
   current coordinates x: what the joined matrix cannot hold of it (a rigid
   body's: its unknowns' border, rigidbody.h); nothing for an elastic body. */
PetscErrorCode  BodyAddSurfaceHessian(Body, const PetscReal x[], PetscInt n, const PetscInt idx[], const PetscScalar K[]);
