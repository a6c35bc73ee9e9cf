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
  PetscInt  m;
  PetscReal xi[2], eta[2], w;
} Segment3dPoint;

#define SEGMENT3D_MAX_MASTER 64 /* master faces against one slave face, at most */
#define SEGMENT3D_IN_TOL 1e-10 /* the in/out test's tolerance in the master's parameters */
#define SEGMENT3D_EDGE_MARGIN 0.0   /* a closest point this far inside the piece's master face is its (no other face tried) */

PetscErrorCode Segment3dPoints(const Face3d *, PetscInt, const Face3d[], const Face3dRule *, PetscInt *, Segment3dPoint **);
PetscErrorCode Segment3dEvaluate(const Face3d *, const PetscReal[], const PetscReal[], PetscInt, const Face3d[], PetscInt, Segment3dPoint[], PetscReal[], PetscReal[], PetscReal[]);
/* A slave point's closest point on a master face (Segment3dClosestPointAt). */
typedef struct {
  PetscReal N[FACE3D_MAX_NODES], M[FACE3D_MAX_NODES], dM[2 * FACE3D_MAX_NODES]; /* slave, master shapes; master's derivatives */
  PetscReal xs[3], xm[3], T[6], H[9], d[3], K[3];                              /* points, master's x_,a and x_,ab, d = xm - xs, K */
} Segment3dClosest;

PetscBool Segment3dClosestPointAt(const Face3d *, const PetscReal[2], const Face3d *, const PetscReal[2], Segment3dClosest *);
void      Segment3dProjectionDerivative(const Segment3dClosest *, PetscInt, PetscInt, PetscReal[]);
