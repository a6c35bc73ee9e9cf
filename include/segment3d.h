#pragma once
#include "face3d.h"

/* Segment-based integration of the nodal weighted gaps of one slave face
   against curved master faces (segment3d.c). */

/* A face: its type and node coordinates x[3 i + d]. */
typedef struct {
  Face3dType       type;
  const PetscReal *x;
} Face3d;

/* An integration point: the slave parameters xi and weight w (in the slave's
   parameter plane: int f dS = sum w f J), the master face m (an index into
   the caller's list) and the parameters eta of the closest point there. */
typedef struct {
  PetscInt  m, ext; /* ext: beyond the master's border along the slave's own (a symmetry plane), eta on the face's extension */
  PetscReal xi[2], eta[2], w;
} Segment3dPoint;

#define SEGMENT3D_MAX_MASTER 64 /* master faces against one slave face, at most */
#define SEGMENT3D_MAX_EDGE_POINTS 8 /* points along a master edge bending the pieces' borders (-contact_mortar_edge_points), at most */
#define SEGMENT3D_IN_TOL 1e-10 /* the in/out test's tolerance in the master's parameters */
#define SEGMENT3D_DIR_COS 0.5 /* a master node's own direction where it meets the slave's sub-triangle within 60 degrees, else the sub-triangle's normal */
#define SEGMENT3D_HIT_ITS 30   /* Newton's iterations for a master node's line on the slave face, at most */
#define SEGMENT3D_HIT_TOL 1e-12 /* ... and its step in the slave's parameters when converged */
#define SEGMENT3D_HIT_COARSE 2.0 /* a master node's line's hit is weighed out (1 to 0) as its faces' size goes from the slave face's to this many times it */
#define SEGMENT3D_END_TOL 1e-12    /* an end shorter than this (a fraction of the master edge) is dropped */
#define SEGMENT3D_END_POINTS 5     /* Gauss points along an end (degree 9) */
#define SEGMENT3D_ALONG 0.1        /* an end this near (of the edge's length) a slave border edge runs along it: no end term */
#define SEGMENT3D_EDGE_MARGIN 0.0   /* a closest point this far inside the piece's master face is its (no other face tried) */

/* An end of S' inside the slave face: the part s in [s0, s1] of the edge
   P -> Q of a master face's sub-triangle that lies on the master surface's
   border (no other master face given shares it), projected on the plane of
   the slave's sub-triangle of vertices t[] (slave node numbers) and inside
   it; P -> Q anticlockwise about the master's piece in that plane (the
   covered part on its left). m: the master face (index into the caller's
   list); e[]: P's and Q's node numbers in it. */
typedef struct {
  PetscInt  m, t[3], e[2];
  PetscReal s0, s1;
} Segment3dEnd;

/* A kink line of S' inside the slave face (with edge points, -contact_mortar_edge_points):
   where a slave point's closest point passes from master face m to m2 across
   their shared edge the gap's gradient jumps (the master's normal turns). A
   straight part of the bent side P -> Q of m's sub-triangle (e[]: P's and
   Q's nodes in m, e2[] in m2), between its edge parameters s0 and s1 (0 at
   P, 1 at Q), at the slave parameters xi0 and xi1, inside the slave's
   sub-triangle. */
typedef struct {
  PetscInt  m, m2, e[2], e2[2];
  PetscReal s0, s1, xi0[2], xi1[2];
} Segment3dKink;

PetscErrorCode Segment3dPoints(const Face3d *, PetscInt, const Face3d[], const Face3dRule *, PetscInt, PetscInt *, Segment3dPoint **, PetscInt, PetscInt *, Segment3dEnd **, PetscInt *, Segment3dKink **);
PetscErrorCode Segment3dKinkEvaluate(const Face3d *, const PetscReal[], const PetscReal[], PetscInt, const Face3d[], PetscInt, const Segment3dKink[], PetscReal[]);
PetscErrorCode Segment3dKinkHessian(const Face3d *, const PetscReal[], const PetscReal[], const PetscReal[], const Face3d *, const Face3d *, const Segment3dKink *, PetscReal[], PetscBool *);
PetscErrorCode Segment3dEvaluate(const Face3d *, const PetscReal[], const PetscReal[], PetscInt, const Face3d[], PetscInt, Segment3dPoint[], PetscReal[], PetscReal[], PetscReal[]);
void           Segment3dPointClosest(const Segment3dPoint *, const Face3d *, const PetscReal[3], PetscReal[2], PetscBool *);
PetscErrorCode Segment3dEndEvaluate(const Face3d *, const PetscReal[], const PetscReal[], PetscInt, const Face3d[], PetscInt, const Segment3dEnd[], PetscReal[]);
PetscErrorCode Segment3dEndHessian(const Face3d *, const PetscReal[], const PetscReal[], const PetscReal[], const Face3d *, const Segment3dEnd *, PetscReal[], PetscBool *);
/* A slave point's closest point on a master face (Segment3dClosestPointAt). */
typedef struct {
  PetscReal N[FACE3D_MAX_NODES], M[FACE3D_MAX_NODES], dM[2 * FACE3D_MAX_NODES]; /* slave, master shapes; master's derivatives */
  PetscReal xs[3], xm[3], T[6], H[9], d[3], K[3];                              /* points, master's x_,a and x_,ab, d = xm - xs, K */
} Segment3dClosest;

PetscBool Segment3dClosestPointAt(const Face3d *, const PetscReal[2], const Face3d *, const PetscReal[2], Segment3dClosest *);
void      Segment3dProjectionDerivative(const Segment3dClosest *, PetscInt, PetscInt, PetscReal[]);
