#pragma once
#include "body.h"

/* A contact surface: a Gmsh physical curve of one body, held whole on every
   rank (surfaces are curves, small beside the bodies). It owns the quadratic
   edges and their nodes, the reference and current coordinates of the nodes,
   a gradient array over them, the arc position along the surface, and, as a
   master surface, each edge's C1 blend into its neighbours (set up by
   ContactSurfaceSetUpBlend in edge.c). Formulations read these arrays; only
   surface.c and edge.c write them. */
typedef struct {
  PetscInt   body, tag;
  char       group[CONTACT_NAME_LEN];
  PetscInt   nn, ne;      /* surface nodes and edges (whole surface, every rank) */
  PetscInt  *enodes;      /* [ne][3]: nodes at eta = -1, +1, 0 */
  PetscReal *esign;       /* [ne] +-1 so that (t_y, -t_x) * esign is outward */
  PetscReal *s0, *edir, *elen; /* arc position of the walk entering the edge, direction, length */
  PetscInt  *walk;        /* [ne] the edges in the order of the walk */
  PetscInt  *nodeId;      /* [nn] global node number, sorted */
  PetscReal *X, *x, *g;   /* [nn][2] reference, current coordinates, gradient */
  PetscInt  *big;         /* [nn][2] index in the joined vector, -1 if constrained */
  PetscBool *endNode;     /* [nn] node on a single edge: an end of the surface */
  PetscReal *endTurn;     /* [nn] at an end: the angle (radians, in (-pi, pi]) from the surface's tangent leaving the end to the body's boundary that continues it there, positive towards the body (a convex corner: pi/2 at a square one; 0 where the boundary goes on smoothly); else 0 (reference configuration) */
  PetscBool  mirror;      /* the surface is half of one symmetric about y = mirrorY (its mirror image continues it) */
  PetscReal  mirrorY, mirrorReach; /* the line; how far the current surface reaches past it (>= 0) */
  PetscReal *cutNode;     /* [nn] at an end of the surface on the mirror line, where its image joins it: the sign (+-1) of the x component of the outward normal there (reference configuration); else 0 */
  PetscInt  *mnodes;      /* [ne][7] as master: own nodes (eta = -1, +1, 0), the other nodes of the neighbour at eta = -1, at +1 */
  PetscReal *mcorr;       /* [ne][2][7] end-tangent corrections at eta = -1, +1 over those nodes */
  PetscReal  blend;       /* W: width in eta of the blend zone at each end (0: none) */
  BodyNodeMap map;        /* the surface nodes among the body's owned points, and their local offsets (BodyMapNodes) */
  PetscInt   nown, *ownEdges;          /* edges this rank integrates as slave */
  PetscBool  axisym;      /* the body is axisymmetric: every dS is 2 pi r dS (ContactSurfaceMeasure) */
} ContactSurface;

/* The surface's measure per unit of the edge parameter at a point of
   reference position X and reference tangent T = dX/dxi: |T| (the
   reference length), times 2 pi X_r in axisymmetry (the area the point's
   ring sweeps). Every weight of the contact terms is this. */
static inline PetscReal ContactSurfaceMeasure(const ContactSurface *S, const PetscReal X[2], const PetscReal T[2])
{
  const PetscReal J = PetscSqrtReal(T[0] * T[0] + T[1] * T[1]);

  return S->axisym ? 2.0 * PETSC_PI * X[0] * J : J;
}

/* Collective on the body: extracts the group's edges, replicates them, numbers
   the nodes, walks the arc and sets up the master blend of width blend (in eta). */
PetscErrorCode ContactSurfaceSetUp(ContactSurface *, Body, const char pair[], PetscReal blend);
PetscErrorCode ContactSurfaceDestroy(ContactSurface *);
/* A rigid body's surface (after ContactSurfaceSetUp): each chain turned to
   face the partner surface M, and the body's continuation at its ends. */
PetscErrorCode ContactSurfaceOrientRigid(ContactSurface *, Body, const ContactSurface *M, const char pair[]);
/* The surface is the half y >= y of one symmetric about that line: marks its
   ends on the line, where the mirror image continues it. */
PetscErrorCode ContactSurfaceSetMirror(ContactSurface *, PetscReal y);
/* The mirror image of height y (a half model's line, ContactSurfaceSetMirror). */
static inline PetscReal ContactSurfaceMirrorY(const ContactSurface *S, PetscReal y)
{
  return 2.0 * S->mirrorY - y;
}
/* At an end of the surface on the mirror line: the sign (+-1) of the x
   component of the outward normal there; 0 elsewhere or without a mirror. */
static inline PetscReal ContactSurfaceCutSide(const ContactSurface *S, PetscInt v)
{
  return S->cutNode ? S->cutNode[v] : 0.0;
}
/* Collective: x = X + u of every node, from the body's local vector Xl;
   changed: whether x differs from the last (the same answer on every rank). */
PetscErrorCode ContactSurfaceUpdateCoordinates(ContactSurface *, Body, PetscBool *changed);
/* The rank owner[e] of each edge when they are shared out among size ranks in
   runs of the walk of nearly equal weight (weight NULL: one each). */
void           ContactSurfaceSplitEdges(const ContactSurface *, PetscMPIInt size, const PetscReal weight[], PetscMPIInt owner[]);
/* Collective: sums g over ranks and adds it to the body's local gradient Gl. */
PetscErrorCode ContactSurfaceAddGradient(ContactSurface *, Body);
/* Arc position (reference length) of edge e at parameter xi. */
PetscErrorCode ContactSurfaceArc(const ContactSurface *, PetscInt e, PetscReal xi, PetscReal *s);
/* Outward unit normal n[nn][2] at each node, current configuration (edge normals averaged at a shared node). */
void ContactSurfaceNodalNormals(const ContactSurface *, PetscReal n[]);
/* Unit tangent t[nn][2] at each node along the arc (increasing arc position), current configuration (averaged alike). */
void ContactSurfaceNodalTangents(const ContactSurface *, PetscReal t[]);
/* Arc position s[nn] (reference length) of each node. */
PetscErrorCode ContactSurfaceNodeArcs(const ContactSurface *, PetscReal s[]);
/* Length of the whole surface (the end of the arc). */
PetscReal ContactSurfaceLength(const ContactSurface *);
