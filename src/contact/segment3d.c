/* Segment-based integration of the nodal weighted gaps of a curved slave
   face (Puso-Laursen style) and their first derivatives.

   For a slave face S with weights W_j (face3d.c), its reference
   configuration X_S (the measure dS and the weights' coefficients: they do
   not move with u, as in 2D) and current coordinates x_S, and the master
   faces M_m that face it, the contributions
     A_j = int_S' W_j dS,   Q_j = int_S' W_j g dS,
     g = (x_s(xi) - x_m(eta*)) . n(eta*),
   x_m(eta*) the closest point of the curved master face to x_s(xi), n the
   master's outward unit normal there (as gap.c in 2D: g > 0 apart), S' the
   part of S whose closest point lies on a master face. The weighted gap
   is g_j = Q_j / A_j summed over the slave's faces.

   Segments (Segment3dPoints). S is split into flat sub-triangles through
   its nodes (Tri6 4, Quad9 8; Face3dSubTriangles) and so is every master
   face. Each slave sub-triangle T defines a plane (origin at its first
   vertex, normal (v1 - v0) x (v2 - v0), axes e1 along v1 - v0 and
   e2 = n x e1); each master sub-triangle whose normal opposes T's is
   projected on it and clipped by T (clip.c), and the clipped polygon is
   cut into triangles. Its vertices, master nodes, are projected node by
   node (so the projected sub-triangles still tile): a node inside the
   master surface along the mean of its faces' normals there, to the point
   of T's plane whose barycentric coordinates in T are the slave's
   parameters where that line meets the curved slave face
   (Segment3dNodeDirections, Segment3dSlaveHit): an edge between two master
   faces then falls, at its nodes, where a slave point's closest point
   passes from one face to the other, and the kink of the gap there on a
   piece's border, not inside a piece (along T's normal it fell inside by
   the gap times the two normals' angle, plus the slave's bulge off T: the
   Hertz balls' Taylor level 4.9e-9 and 8.0e-9 of |H v|, now 1.6e-9 and
   2.4e-9: docs/formulations.md). The hit is weighed out (to the line onto
   T's plane) more than half a face outside the slave face, and where the
   node's faces are larger than the slave face (to SEGMENT3D_HIT_COARSE
   times it): a coarse master's edge from a node on its hit to one far off
   on the plane would cross T askew. A node on the master's border goes
   along n (the ends' term below and the strip take it so). Between the
   nodes the projected edge is straight where the closest point's passage
   from one face to the next is a curve: with nedge > 0
   (-contact_mortar_edge_points) nedge points of each edge that two faces
   given share go as the nodes do (along the two faces' mean unit normal
   there, onto the curved slave: Segment3dEdgeLines) and bend the
   sub-triangle's side, cut into a fan (Segment3dBentPieces); and where S'
   has no end inside the slave face (Segment3dHasEnd: the master's border,
   if any, runs along the slave's) the border nodes go along their lines
   too. The gap's gradient, which jumps across that curve, is then
   integrated on either side of it, and the line's motion is the Hessian's
   (Segment3dKinkHessian, the kink lines Segment3dKink); between a piece's
   straight border and that curve the pieces integrate the other face's
   gap, so Q_j moves with the layout, and dQ_j takes that motion too
   (Segment3dKinkEvaluate): the Hessian's Taylor remainder falls at order 2
   to about 1e-8 of |H v| where the master is as soft as the slave, to
   round-off where it is stiff (docs/formulations.md).
   A point p of T's plane has barycentric
   coordinates (l1, l2) in T, the same in the slave's parameters since T's
   vertices are nodes and the map of T is affine in xi: xi = xi_0 + l1
   (xi_1 - xi_0) + l2 (xi_2 - xi_0). A piece's Gauss points (the rule
   given, degree 5 or more) so become slave parameters, with the weight
   w = w_q (area of the piece) (area of T in xi)/(area of T in the plane);
   the integrand is then f(xi) J(xi), J the curved slave's area element,
   so the pieces tile the slave's parameter plane where the master's
   projection covers it, and on flat faces (T = S's piece, exact planes)
   the integrals are exact for polynomial integrands of the rule's degree.
   The same barycentric coordinates in the projected master sub-triangle
   give a first guess of eta; Newton (Face3dClosestPoint) finds the closest
   point of x_s(xi) on the curved master face. In/out: the point belongs to
   the master face whose closest point lies in its reference domain (within
   SEGMENT3D_IN_TOL): that of the piece, else another of the faces given
   (on a curved master the flat sub-triangles' footprint and the closest
   point's differ near a face's edge), else the face whose closest point
   on its boundary is nearest, if another face shares that point (behind a
   convex edge between two faces, the fan of normals where, as at a 2D
   corner, g is the signed distance to the edge's point and n the unit
   vector from it: g stays continuous), else none: the point lies beyond
   the master surface's end and is dropped (S' ends there). Where the
   master's border runs along the slave's own (both surfaces cut by a
   symmetry plane: Segment3dAlongSlaveBorder), the master's sub-triangle is
   followed by a strip beyond that border edge, a quarter of T's size wide,
   clipped by T: its points (ext) have their closest point on the master
   face's polynomial extension (Newton, unclamped), so that the pieces reach
   the slave's border. Without it the border, projected on T along T's own
   normal, fell inside T by a sliver of S' left uncovered (up to 7 % of T
   where the surfaces lie apart), whose width moved with both surfaces and
   whose end had no term: the quarter Hertz ball's Hessian remainder stood
   at 2.9e-6 of |H v| (8.0e-9 with the strip, the whole ball's 4.9e-9), and
   the sliver's end term, where taken, made the energy's derivative jump
   where a sliver opened.

   First derivatives (Segment3dEvaluate), the points fixed in the slave's
   xi (the segments are not differentiated: the exact integral of an
   integrand continuous across the master's face edges has no term there;
   where the master ends inside S, the end moves and its term, W_j g on the
   end times its motion, is Segment3dEndEvaluate's, below). At the
   closest point x_s - x_m = g n, t_a . n = 0 and dn . n = 0, so the
   motions of eta* and of n drop out:
     dg = n . (sum_i N_i(xi) dx_i - sum_k M_k(eta*) dx_k),
     dQ_j = sum_points W_j J w dg,   dA_j = 0 (reference measure).
   The motion of eta* itself (for the Hessian: d2g needs it, as in 2D) is
   Segment3dProjectionDerivative's: with d = x_m - x_s, the conditions
   r_a = d . t_a = 0 vary as K deta + dr/dx dx = 0,
     K_ab = t_a . t_b + d . x_ab,
     dr_a/dx_i = -N_i t_a (slave node i),
     dr_a/dx_k = M_k t_a + d M_k,a (master node k),
   deta = -K^-1 dr/dx dx. Behind an edge (the fan) x_m moves along the
   edge, orthogonal to x_s - x_m = g n, so dg has the same form with that
   n; Segment3dProjectionDerivative is the interior's. */
#include "segment3d.h"
#include <petscdt.h>
#include "clip.h"

static PetscReal Segment3dSlaveHit(const Face3d *, const PetscReal[3], const PetscReal[3], PetscReal[2]);
static PetscReal Segment3dHitWeight(const Face3d *, const PetscReal[3], const PetscReal[3], PetscReal, PetscReal, PetscReal[2]);

static inline PetscReal Dot3(const PetscReal a[3], const PetscReal b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void Cross3(const PetscReal a[3], const PetscReal b[3], PetscReal c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/* 0 below 0, 1 above 1, the cubic 3 s^2 - 2 s^3 between. */
static inline PetscReal SmoothStep(PetscReal s)
{
  if (s <= 0) return 0.0;
  if (s >= 1) return 1.0;
  return s * s * (3.0 - 2.0 * s);
}

/* Barycentric (l1, l2) of p in the triangle t[6] of the plane. */
static inline void Barycentric(const PetscReal t[6], const PetscReal p[2], PetscReal l[2])
{
  const PetscReal ax = t[2] - t[0], ay = t[3] - t[1], bx = t[4] - t[0], by = t[5] - t[1];
  const PetscReal det = ax * by - ay * bx, px = p[0] - t[0], py = p[1] - t[1];
  l[0] = (px * by - py * bx) / det;
  l[1] = (ax * py - ay * px) / det;
}

/* The plane of a slave sub-triangle: origin o, axes e[0..2], e[3..5],
   normal e[6..8]; its vertices in the plane. */
typedef struct {
  PetscReal o[3], e[9], v2d[6], xi[6], xiArea;
} SubPlane;

static void SubPlaneSetUp(const Face3d *f, const PetscInt v[3], SubPlane *P)
{
  PetscReal a[3], b[3], len;

  for (PetscInt d = 0; d < 3; ++d) {
    P->o[d] = f->x[3 * v[0] + d];
    a[d]    = f->x[3 * v[1] + d] - P->o[d];
    b[d]    = f->x[3 * v[2] + d] - P->o[d];
  }
  Cross3(a, b, &P->e[6]);
  len = PetscSqrtReal(Dot3(&P->e[6], &P->e[6]));
  for (PetscInt d = 0; d < 3; ++d) P->e[6 + d] /= len;
  len = PetscSqrtReal(Dot3(a, a));
  for (PetscInt d = 0; d < 3; ++d) P->e[d] = a[d] / len;
  Cross3(&P->e[6], &P->e[0], &P->e[3]);
  for (PetscInt k = 0; k < 3; ++k) {
    PetscReal r[3];
    for (PetscInt d = 0; d < 3; ++d) r[d] = f->x[3 * v[k] + d] - P->o[d];
    P->v2d[2 * k]     = Dot3(r, &P->e[0]);
    P->v2d[2 * k + 1] = Dot3(r, &P->e[3]);
    Face3dNodeXi(f->type, v[k], &P->xi[2 * k]);
  }
  P->xiArea = ClipSignedArea(3, P->xi);
}

/* The longest edge of a sub-plane's triangle, in the plane. */
static PetscReal SubPlaneLongestEdge(const SubPlane *P)
{
  PetscReal len2 = 0.0;

  for (PetscInt i = 0; i < 3; ++i) len2 = PetscMax(len2, PetscSqr(P->v2d[2 * ((i + 1) % 3)] - P->v2d[2 * i]) + PetscSqr(P->v2d[2 * ((i + 1) % 3) + 1] - P->v2d[2 * i + 1]));
  return PetscSqrtReal(len2);
}

/* The squared distance from p to the box b (lo[3], hi[3]): 0 inside, and no
   more than the distance to anything in it. */
static inline PetscReal BoxDistance2(const PetscReal b[6], const PetscReal p[3])
{
  PetscReal d2 = 0.0;

  for (PetscInt d = 0; d < 3; ++d) {
    const PetscReal o = p[d] < b[d] ? b[d] - p[d] : (p[d] > b[3 + d] ? p[d] - b[3 + d] : 0.0);
    d2 += o * o;
  }
  return d2;
}

/* The master face that owns the point p: face m0 (from eta) where p's
   closest point lies inside it (inside a concave edge between two faces,
   where a point has a closest point in each, the piece's face is kept, not
   the nearer: not measured yet; 2D cuts at the tie); else the face whose own closest point
   (Face3dClosestPointOnFace) is the nearest, if that point is inside it or
   on an edge another face shares (the same point of another face: a fan
   behind a convex edge); -1 where it is on an edge no other face reaches
   (past the master surface's end). eta is updated. A face whose box
   (Face3dBox: it holds the curved face) is no nearer than the best so far
   is not tried: the same owner as trying every face, at a cost that no
   longer grows with the faces given where few are near. */
/* Squared distance from p to face m's point at e. */
static inline PetscReal FaceDistance2(const Face3d *f, const PetscReal e[2], const PetscReal p[3], PetscReal X[3])
{
  Face3dEval(f->type, f->x, e, X, NULL, NULL);
  return (X[0] - p[0]) * (X[0] - p[0]) + (X[1] - p[1]) * (X[1] - p[1]) + (X[2] - p[2]) * (X[2] - p[2]);
}

static PetscInt Segment3dOwner(PetscInt nm, const Face3d master[], const PetscReal boxes[], PetscInt m0, const PetscReal p[3], PetscReal eta[2])
{
  PetscReal e[2] = {eta[0], eta[1]}, best, X[3], Xb[3], be[2], size, bd[SEGMENT3D_MAX_MASTER];
  PetscBool clamped, bclamped = PETSC_TRUE, deferred[SEGMENT3D_MAX_MASTER];
  PetscInt  owner = m0, order[SEGMENT3D_MAX_MASTER], n = 0;

  Face3dClosestPointOnFace(master[m0].type, master[m0].x, p, SEGMENT3D_IN_TOL, e, &clamped);
  if (!clamped) {
    eta[0] = e[0];
    eta[1] = e[1];
    return m0;
  }
  /* The owner is the face of least distance to its own closest point
     (Face3dClosestPointOnFace), the first by index among equals. Found in
     two passes that give the same face: first the faces' interior closest
     points (Newton alone), nearest box first, then the boundary points of
     the faces whose interior one lies outside them, each face skipped
     where its box is farther than the best so far (no point in it is
     nearer). m0's is its boundary point, found above. */
  best  = FaceDistance2(&master[m0], e, p, Xb);
  be[0] = e[0];
  be[1] = e[1];
  for (PetscInt m = 0; m < nm; ++m) {
    deferred[m] = PETSC_FALSE;
    if (m == m0) continue;
    bd[m] = BoxDistance2(&boxes[6 * m], p);
    if (bd[m] > best) continue;
    order[n++] = m;
  }
  for (PetscInt i = 1; i < n; ++i) { /* by box distance, then index */
    const PetscInt m = order[i];
    PetscInt       k = i;
    for (; k > 0 && (bd[order[k - 1]] > bd[m] || (bd[order[k - 1]] == bd[m] && order[k - 1] > m)); --k) order[k] = order[k - 1];
    order[k] = m;
  }
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt m = order[i];
    PetscReal      d2;
    if (bd[m] > best) break;
    e[0] = e[1] = master[m].type == FACE3D_TRI6 ? 1.0 / 3.0 : 0.0;
    if (!(Face3dClosestPoint(master[m].type, master[m].x, p, e, NULL) && Face3dContains(master[m].type, e, SEGMENT3D_IN_TOL))) {
      deferred[m] = PETSC_TRUE;
      continue;
    }
    d2 = FaceDistance2(&master[m], e, p, X);
    if (d2 < best || (d2 == best && m < owner)) {
      best     = d2;
      owner    = m;
      bclamped = PETSC_FALSE;
      be[0]    = e[0];
      be[1]    = e[1];
      for (PetscInt d = 0; d < 3; ++d) Xb[d] = X[d];
    }
  }
  for (PetscInt m = 0; m < nm; ++m) {
    PetscReal d2;
    if (!deferred[m] || bd[m] > best) continue;
    Face3dClosestBoundaryPoint(master[m].type, master[m].x, p, e);
    d2 = FaceDistance2(&master[m], e, p, X);
    if (d2 < best || (d2 == best && m < owner)) {
      best     = d2;
      owner    = m;
      bclamped = PETSC_TRUE;
      be[0]    = e[0];
      be[1]    = e[1];
      for (PetscInt d = 0; d < 3; ++d) Xb[d] = X[d];
    }
  }
  eta[0] = be[0];
  eta[1] = be[1];
  if (!bclamped) return owner;
  size = 0.0; /* the owner's first edge's length: the scale of "the same point" */
  for (PetscInt d = 0; d < 3; ++d) size += PetscSqr(master[owner].x[3 + d] - master[owner].x[d]);
  size = PetscSqrtReal(size);
  for (PetscInt m = 0; m < nm; ++m) {
    if (m == owner || BoxDistance2(&boxes[6 * m], Xb) > PetscSqr(1e-8 * size)) continue;
    e[0] = e[1] = master[m].type == FACE3D_TRI6 ? 1.0 / 3.0 : 0.0;
    Face3dClosestPointOnFace(master[m].type, master[m].x, Xb, SEGMENT3D_IN_TOL, e, &clamped);
    if (PetscSqrtReal(FaceDistance2(&master[m], e, Xb, X)) <= 1e-8 * size) return owner;
  }
  return -1;
}

/* Room in a growing list (*p, *cap items of size bytes, n in use) for one
   more item: its room doubled (first items at the start) when full. */
static PetscErrorCode ListGrow(PetscInt n, PetscInt *cap, PetscInt first, size_t size, void **p)
{
  void *q;

  PetscFunctionBeginUser;
  if (n < *cap) PetscFunctionReturn(0);
  *cap = *cap ? 2 * *cap : first;
  PetscCall(PetscMalloc((size_t)*cap * size, &q));
  if (n) PetscCall(PetscMemcpy(q, *p, (size_t)n * size));
  PetscCall(PetscFree(*p));
  *p = q;
  PetscFunctionReturn(0);
}

typedef struct {
  PetscInt        n, cap;
  Segment3dPoint *p;
} PointList;

static PetscErrorCode PointListPush(PointList *L, const Segment3dPoint *q)
{
  PetscFunctionBeginUser;
  PetscCall(ListGrow(L->n, &L->cap, 64, sizeof(*L->p), (void **)&L->p));
  L->p[L->n++] = *q;
  PetscFunctionReturn(0);
}

/* The closest point eta (updated) on master face M of the slave point x
   of pt: on the face's polynomial extension where pt lies beyond the
   master's border along the slave's own (ext: Newton, unclamped), else on
   the face (*clamped: on its boundary, Face3dClosestPointOnFace). */
void Segment3dPointClosest(const Segment3dPoint *pt, const Face3d *M, const PetscReal x[3], PetscReal eta[2], PetscBool *clamped)
{
  if (pt->ext) {
    *clamped = PETSC_FALSE;
    (void)Face3dClosestPoint(M->type, M->x, x, eta, NULL);
  } else Face3dClosestPointOnFace(M->type, M->x, x, SEGMENT3D_IN_TOL, eta, clamped);
}

/* The slave parameters xi of the point x of T's plane P (its barycentric
   coordinates in T, the same in xi). */
static void SubPlaneXi(const SubPlane *P, const PetscReal x[2], PetscReal xi[2])
{
  PetscReal l[2];

  Barycentric(P->v2d, x, l);
  for (PetscInt a = 0; a < 2; ++a) xi[a] = P->xi[a] + l[0] * (P->xi[2 + a] - P->xi[a]) + l[1] * (P->xi[4 + a] - P->xi[a]);
}

/* The points of one clipped triangle piece tri[6] of the slave plane P,
   master sub-triangle mt2d (its vertices' master parameters meta). */
static PetscErrorCode Segment3dPiecePoints(const Face3d *slave, const SubPlane *P, PetscInt nm, const Face3d master[], const PetscReal boxes[], PetscInt m, const PetscReal tri[6], const PetscReal mt2d[6], const PetscReal meta[6], const Face3dRule *rule, PetscBool ext, PointList *L)
{
  const PetscReal area = ClipSignedArea(3, tri), scale = P->xiArea / ClipSignedArea(3, P->v2d);

  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < rule->nq; ++q) {
    const PetscReal r = rule->xi[2 * q], s = rule->xi[2 * q + 1];
    const PetscReal p[2] = {tri[0] + r * (tri[2] - tri[0]) + s * (tri[4] - tri[0]), tri[1] + r * (tri[3] - tri[1]) + s * (tri[5] - tri[1])};
    PetscReal       lm[2], xs[3];
    Segment3dPoint  pt;
    SubPlaneXi(P, p, pt.xi);
    Barycentric(mt2d, p, lm);
    for (PetscInt a = 0; a < 2; ++a) pt.eta[a] = meta[a] + lm[0] * (meta[2 + a] - meta[a]) + lm[1] * (meta[4 + a] - meta[a]);
    pt.w = 2.0 * rule->w[q] * area * scale;
    Face3dEval(slave->type, slave->x, pt.xi, xs, NULL, NULL);
    pt.ext = ext ? 1 : 0;
    if (ext) pt.m = Face3dClosestPoint(master[m].type, master[m].x, xs, pt.eta, NULL) ? m : -1;
    else pt.m = Segment3dOwner(nm, master, boxes, m, xs, pt.eta);
    if (pt.m >= 0) PetscCall(PointListPush(L, &pt));
  }
  PetscFunctionReturn(0);
}

typedef struct {
  PetscInt      n, cap;
  Segment3dEnd *e;
} EndList;

static PetscErrorCode EndListPush(EndList *L, const Segment3dEnd *q)
{
  PetscFunctionBeginUser;
  PetscCall(ListGrow(L->n, &L->cap, 8, sizeof(*L->e), (void **)&L->e));
  L->e[L->n++] = *q;
  PetscFunctionReturn(0);
}

typedef struct {
  PetscInt       n, cap;
  Segment3dKink *k;
} KinkList;

static PetscErrorCode KinkListPush(KinkList *L, const Segment3dKink *q)
{
  PetscFunctionBeginUser;
  PetscCall(ListGrow(L->n, &L->cap, 16, sizeof(*L->k), (void **)&L->k));
  L->k[L->n++] = *q;
  PetscFunctionReturn(0);
}

/* Whether node a of a face lies on its side k (from corner k to corner
   k + 1). */
static PetscBool Segment3dOnSide(Face3dType type, PetscInt a, PetscInt k)
{
  PetscReal x[2];

  Face3dNodeXi(type, a, x);
  if (type == FACE3D_TRI6) return (PetscBool)(k == 0 ? x[1] == 0 : (k == 1 ? x[0] + x[1] == 1 : x[0] == 0));
  return (PetscBool)(k == 0 ? x[1] == -1 : (k == 1 ? x[0] == 1 : (k == 2 ? x[1] == 1 : x[0] == -1)));
}

/* The side of a face that holds its nodes a and b, or -1. */
static PetscInt Segment3dFaceSide(Face3dType type, PetscInt a, PetscInt b)
{
  for (PetscInt k = 0; k < (type == FACE3D_TRI6 ? 3 : 4); ++k)
    if (Segment3dOnSide(type, a, k) && Segment3dOnSide(type, b, k)) return k;
  return -1;
}

/* The other face given that holds master face m's nodes a and b (the same
   coordinates): *k, and the two nodes' numbers *ia, *ib there; false if
   none (the edge lies on the master surface's border). */
static PetscBool Segment3dNeighbour(PetscInt nm, const Face3d master[], PetscInt m, PetscInt a, PetscInt b, PetscInt *k, PetscInt *ia, PetscInt *ib)
{
  const PetscReal *ya = &master[m].x[3 * a], *yb = &master[m].x[3 * b];

  for (PetscInt f = 0; f < nm; ++f) {
    PetscInt fa = -1, fb = -1;
    if (f == m) continue;
    for (PetscInt i = 0; i < Face3dNodes(master[f].type); ++i) {
      const PetscReal *z = &master[f].x[3 * i];
      if (z[0] == ya[0] && z[1] == ya[1] && z[2] == ya[2]) fa = i;
      if (z[0] == yb[0] && z[1] == yb[1] && z[2] == yb[2]) fb = i;
    }
    if (fa >= 0 && fb >= 0) {
      *k  = f;
      *ia = fa;
      *ib = fb;
      return PETSC_TRUE;
    }
  }
  return PETSC_FALSE;
}

/* Whether the edge between nodes a and b of master face m (a sub-triangle's
   edge) lies on the master surface's border: on the face's own boundary
   and no other face given has both points (Segment3dNeighbour). */
static PetscBool Segment3dBorderEdge(PetscInt nm, const Face3d master[], PetscInt m, PetscInt a, PetscInt b)
{
  PetscInt k, ia, ib;

  return (PetscBool)(Segment3dFaceSide(master[m].type, a, b) >= 0 && !Segment3dNeighbour(nm, master, m, a, b, &k, &ia, &ib));
}

/* The part [*s0, *s1] of the segment p + s (q - p), s in [0, 1], inside the
   anticlockwise triangle t[6] (Cyrus-Beck; *s1 <= *s0 where none). */
static void Segment3dSegmentInTriangle(const PetscReal t[6], const PetscReal p[2], const PetscReal q[2], PetscReal *s0, PetscReal *s1)
{
  *s0 = 0.0;
  *s1 = 1.0;
  for (PetscInt k = 0; k < 3; ++k) {
    const PetscReal *a = &t[2 * k], *b = &t[2 * ((k + 1) % 3)];
    const PetscReal  ex = b[0] - a[0], ey = b[1] - a[1];
    const PetscReal  sp = ex * (p[1] - a[1]) - ey * (p[0] - a[0]), sq = ex * (q[1] - a[1]) - ey * (q[0] - a[0]);
    if (sp == sq) {
      if (sp < 0) *s1 = -1.0;
    } else if (sq > sp) *s0 = PetscMax(*s0, sp / (sp - sq));
    else *s1 = PetscMin(*s1, sp / (sp - sq));
  }
}

/* Whether a point x of the plane P lies on the slave surface's border, to
   tol: near a vertex of P's sub-triangle on the border (slaveBorder: a bit
   per node of the slave face), or near an edge between two such vertices
   on one side of the face. */
static PetscBool Segment3dNearSlaveBorder(Face3dType stype, PetscInt slaveBorder, const PetscInt tsub[3], const SubPlane *P, const PetscReal x[2], PetscReal tol)
{
  for (PetscInt i = 0; i < 3; ++i) {
    const PetscInt   i1 = (i + 1) % 3;
    const PetscReal *a = &P->v2d[2 * i], *b = &P->v2d[2 * i1];
    const PetscReal  ex = b[0] - a[0], ey = b[1] - a[1];
    if (!(slaveBorder & (1 << tsub[i]))) continue;
    if (PetscSqr(x[0] - a[0]) + PetscSqr(x[1] - a[1]) <= tol * tol) return PETSC_TRUE;
    if ((slaveBorder & (1 << tsub[i1])) && Segment3dFaceSide(stype, tsub[i], tsub[i1]) >= 0 && PetscAbsReal(ex * (x[1] - a[1]) - ey * (x[0] - a[0])) <= tol * PetscSqrtReal(ex * ex + ey * ey)) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

/* Whether the part [s0, s1] of the segment p -> q of the plane P lies on
   the slave surface's border (both its ends within SEGMENT3D_ALONG of P's
   longest edge of it, Segment3dNearSlaveBorder): both surfaces end there
   (a symmetry plane that cuts both), S' ends with the slave, and no end of
   it moves; the master's border, projected on the slave's sub-triangles
   each along its own normal, only grazes their edges and corners there. */
static PetscBool Segment3dAlongSlaveBorder(Face3dType stype, PetscInt slaveBorder, const PetscInt tsub[3], const SubPlane *P, const PetscReal p[2], const PetscReal q[2], PetscReal s0, PetscReal s1)
{
  PetscReal tol;

  if (!slaveBorder) return PETSC_FALSE;
  tol = SEGMENT3D_ALONG * SubPlaneLongestEdge(P);
  for (PetscInt k = 0; k < 2; ++k) {
    const PetscReal s = k ? s1 : s0, x[2] = {p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])};
    if (!Segment3dNearSlaveBorder(stype, slaveBorder, tsub, P, x, tol)) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

/* The point of T's plane P a master vertex y goes to: along its direction
   dv where that meets the plane within 60 degrees of its normal, else (and
   on the master's border: along) along the normal; then blended, by the
   hit's weight w, with the point of P whose barycentric coordinates in T
   are the slave parameters hxi where the line y + t dv meets the curved
   slave face. */
static void Segment3dProjectVertex(const SubPlane *P, const PetscReal y[3], const PetscReal dv[3], PetscBool border, PetscReal w, const PetscReal hxi[2], PetscReal out[2])
{
  const PetscReal dn = Dot3(dv, &P->e[6]);
  PetscReal       r[3], l[2];

  for (PetscInt d = 0; d < 3; ++d) r[d] = y[d] - P->o[d];
  if (!border && dn < -SEGMENT3D_DIR_COS) {
    const PetscReal t = Dot3(r, &P->e[6]) / dn;
    for (PetscInt d = 0; d < 3; ++d) r[d] -= t * dv[d];
  }
  out[0] = Dot3(r, &P->e[0]);
  out[1] = Dot3(r, &P->e[3]);
  if (w > 0) {
    Barycentric(P->xi, hxi, l);
    for (PetscInt c = 0; c < 2; ++c) out[c] = w * (P->v2d[c] + l[0] * (P->v2d[2 + c] - P->v2d[c]) + l[1] * (P->v2d[4 + c] - P->v2d[c])) + (1.0 - w) * out[c];
  }
}

/* The lines of the edge between master faces m and k (nodes a -> b of m,
   ia -> ib of k, a sub-triangle's side) at s = j/(nedge + 1), j = 1..nedge:
   line[9 (j - 1) + ...] its point (3), direction (3, the mean of the two
   faces' unit normals there), where it meets the curved slave (2) and that
   hit's weight (1), as the nodes' (Segment3dNodeDirections). */
static void Segment3dEdgeLines(const Face3d *slave, PetscReal ssize, const Face3d master[], PetscInt m, PetscInt a, PetscInt b, PetscInt k, PetscInt ia, PetscInt ib, PetscInt nedge, PetscReal line[])
{
  const PetscReal sz = PetscMax(Face3dSize(master[m].type, master[m].x), Face3dSize(master[k].type, master[k].x));
  PetscReal       ea[2], eb[2], fa[2], fb[2];

  Face3dNodeXi(master[m].type, a, ea);
  Face3dNodeXi(master[m].type, b, eb);
  Face3dNodeXi(master[k].type, ia, fa);
  Face3dNodeXi(master[k].type, ib, fb);
  for (PetscInt j = 1; j <= nedge; ++j) {
    const PetscReal s = j / (PetscReal)(nedge + 1);
    PetscReal      *X = &line[9 * (j - 1)], *d = X + 3, *hx = X + 6;
    PetscReal       eta[2], eta2[2], Y[3], T[6], n1[3], n2[3], len;
    for (PetscInt c = 0; c < 2; ++c) {
      eta[c]  = ea[c] + s * (eb[c] - ea[c]); /* a side is straight in a face's parameters, the same curve in both faces' */
      eta2[c] = fa[c] + s * (fb[c] - fa[c]);
    }
    Face3dEval(master[k].type, master[k].x, eta2, Y, T, NULL);
    (void)Face3dNormal(T, n2);
    Face3dEval(master[m].type, master[m].x, eta, X, T, NULL);
    (void)Face3dNormal(T, n1);
    for (PetscInt c = 0; c < 3; ++c) d[c] = n1[c] + n2[c];
    len = PetscSqrtReal(Dot3(d, d));
    for (PetscInt c = 0; c < 3; ++c) d[c] = len > 0 ? d[c] / len : 0.0;
    X[8] = len > 0 ? Segment3dHitWeight(slave, X, d, sz, ssize, hx) : 0.0;
  }
}

/* Whether S' ends inside the slave face: a side of a master face's
   sub-triangle on the master surface's border, its nodes projected along
   the slave sub-triangles' normals, crosses a sub-triangle and does not run
   along the slave's border (as Segment3dSubEnds finds the ends). */
static PetscErrorCode Segment3dHasEnd(const Face3d *slave, PetscInt slaveBorder, PetscInt nm, const Face3d master[], const PetscBool border[], PetscBool *hasEnd)
{
  PetscInt ns, nsm;
  const PetscInt(*sub)[3], (*msub)[3];
  const PetscReal zero[3] = {0, 0, 0}, nohit[2] = {0, 0};

  PetscFunctionBeginUser;
  *hasEnd = PETSC_FALSE;
  Face3dSubTriangles(slave->type, &ns, &sub);
  for (PetscInt t = 0; t < ns && !*hasEnd; ++t) {
    SubPlane P;
    SubPlaneSetUp(slave, sub[t], &P);
    for (PetscInt m = 0; m < nm && !*hasEnd; ++m) {
      Face3dSubTriangles(master[m].type, &nsm, &msub);
      for (PetscInt u = 0; u < nsm && !*hasEnd; ++u)
        for (PetscInt k = 0; k < 3 && !*hasEnd; ++k) {
          const PetscInt a = msub[u][k], b = msub[u][(k + 1) % 3];
          PetscReal      pa[2], pb[2], s0, s1;
          if (!border[9 * m + a] || !border[9 * m + b] || !Segment3dBorderEdge(nm, master, m, a, b)) continue;
          Segment3dProjectVertex(&P, &master[m].x[3 * a], zero, PETSC_TRUE, 0.0, nohit, pa);
          Segment3dProjectVertex(&P, &master[m].x[3 * b], zero, PETSC_TRUE, 0.0, nohit, pb);
          Segment3dSegmentInTriangle(P.v2d, pa, pb, &s0, &s1);
          if (s1 - s0 > SEGMENT3D_END_TOL && !Segment3dAlongSlaveBorder(slave->type, slaveBorder, sub[t], &P, pa, pb, s0, s1)) *hasEnd = PETSC_TRUE;
        }
    }
  }
  PetscFunctionReturn(0);
}

/* The ends of S' on the slave plane P from master face m's sub-triangle u
   (mt2d its vertices in the plane, as given: either orientation). */
static PetscErrorCode Segment3dSubEnds(Face3dType stype, PetscInt slaveBorder, PetscInt nm, const Face3d master[], PetscInt m, const PetscInt msub[3], const PetscInt tsub[3], const SubPlane *P, const PetscReal mt2d[6], EndList *L)
{
  const PetscBool ccw = (PetscBool)(ClipSignedArea(3, mt2d) > 0);

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < 3; ++k) {
    const PetscInt a = ccw ? k : (k + 1) % 3, b = ccw ? (k + 1) % 3 : k; /* the piece on the left of a -> b */
    Segment3dEnd   E;
    if (!Segment3dBorderEdge(nm, master, m, msub[a], msub[b])) continue;
    Segment3dSegmentInTriangle(P->v2d, &mt2d[2 * a], &mt2d[2 * b], &E.s0, &E.s1);
    if (!(E.s1 - E.s0 > SEGMENT3D_END_TOL)) continue;
    if (Segment3dAlongSlaveBorder(stype, slaveBorder, tsub, P, &mt2d[2 * a], &mt2d[2 * b], E.s0, E.s1)) continue;
    E.m    = m;
    E.e[0] = msub[a];
    E.e[1] = msub[b];
    for (PetscInt i = 0; i < 3; ++i) E.t[i] = tsub[i];
    PetscCall(EndListPush(L, &E));
  }
  PetscFunctionReturn(0);
}

/* The directions the master faces' nodes inside the master surface are
   projected along (dir[27 m + 3 a], node a of face m): the mean of
   the unit normals there of the faces given that hold the node (the same
   coordinates: the same node), so that an edge between two faces projects
   where the closest point passes from one to the other (the bisector of a
   concave edge, the middle of a convex edge's fan) and the gap's kink
   there falls on the pieces' border, not inside a piece. border[9 m + a]:
   the node lies on the master surface's border (on a side of a face that
   no other face given shares: Segment3dBorderEdge), projected along the
   sub-triangle's normal as the ends' term and the strip beyond the border
   take it (on the line's hit a point near the border, whose closest point
   falls just beyond it, would drop out: a sliver again); size[9 m + a]: the
   longest side of the faces that hold the node; side[] is scratch. A
   node's direction is the same for every face that holds it, so the
   projected sub-triangles still tile. */
static void Segment3dNodeDirections(PetscInt nm, const Face3d master[], PetscBool side[], PetscBool border[], PetscReal dir[], PetscReal size[])
{
  PetscReal nrm[27 * SEGMENT3D_MAX_MASTER], fsize[SEGMENT3D_MAX_MASTER];

  for (PetscInt m = 0; m < nm; ++m) { /* each face's size, its unit normal at its nodes, and its nodes on a side of it on the border */
    const Face3d  *F  = &master[m];
    const PetscInt nn = Face3dNodes(F->type), nc = F->type == FACE3D_TRI6 ? 3 : 4;
    fsize[m] = Face3dSize(F->type, F->x);
    for (PetscInt a = 0; a < nn; ++a) {
      PetscReal xi[2], X[3], T[6];
      Face3dNodeXi(F->type, a, xi);
      Face3dEval(F->type, F->x, xi, X, T, NULL);
      (void)Face3dNormal(T, &nrm[27 * m + 3 * a]);
      side[9 * m + a] = PETSC_FALSE;
    }
    for (PetscInt k = 0; k < nc; ++k) {
      if (!Segment3dBorderEdge(nm, master, m, k, (k + 1) % nc)) continue;
      for (PetscInt a = 0; a < nn; ++a)
        if (Segment3dOnSide(F->type, a, k)) side[9 * m + a] = PETSC_TRUE;
    }
  }
  for (PetscInt m = 0; m < nm; ++m)
    for (PetscInt a = 0; a < Face3dNodes(master[m].type); ++a) {
      const PetscReal *y = &master[m].x[3 * a];
      PetscReal       *d = &dir[27 * m + 3 * a], len;
      d[0] = d[1] = d[2] = 0.0;
      border[9 * m + a] = PETSC_FALSE;
      size[9 * m + a]   = 0.0;
      for (PetscInt k = 0; k < nm; ++k)
        for (PetscInt i = 0; i < Face3dNodes(master[k].type); ++i) {
          const PetscReal *z = &master[k].x[3 * i];
          if (z[0] != y[0] || z[1] != y[1] || z[2] != y[2]) continue;
          if (side[9 * k + i]) border[9 * m + a] = PETSC_TRUE;
          size[9 * m + a] = PetscMax(size[9 * m + a], fsize[k]);
          for (PetscInt c = 0; c < 3; ++c) d[c] += nrm[27 * k + 3 * i + c];
        }
      len = PetscSqrtReal(Dot3(d, d));
      for (PetscInt c = 0; c < 3; ++c) d[c] = len > 0 ? d[c] / len : 0.0;
    }
}

/* Where the line y + t d meets the curved slave face S (its polynomial,
   extended): the slave parameters xi, by Newton on x_S(xi) - y - t d = 0
   from S's centre, and the weight (returned) the hit is taken with against
   the projection on a sub-triangle's plane: 1 within half the face's size
   of its domain, 0 beyond the whole size or where Newton does not converge,
   a smooth step between (far out the extended polynomial is not the
   surface, and may fold). */
static PetscReal Segment3dSlaveHit(const Face3d *S, const PetscReal y[3], const PetscReal d[3], PetscReal xi[2])
{
  const PetscBool tri = (PetscBool)(S->type == FACE3D_TRI6);
  PetscReal       t = 0.0, out;

  xi[0] = xi[1] = tri ? 1.0 / 3.0 : 0.0;
  for (PetscInt it = 0;; ++it) {
    PetscReal X[3], T[6], F[3], c[3], det, dx[3];
    if (it == SEGMENT3D_HIT_ITS) return 0.0;
    Face3dEval(S->type, S->x, xi, X, T, NULL);
    for (PetscInt k = 0; k < 3; ++k) F[k] = X[k] - y[k] - t * d[k];
    Cross3(&T[3], d, c); /* [t1 t2 -d] (dxi, dt) = -F by Cramer's rule, det = -t1 . (t2 x d) */
    det = -Dot3(T, c);
    if (!(PetscAbsReal(det) > 0)) return 0.0;
    dx[0] = Dot3(F, c) / det;
    Cross3(d, T, c);
    dx[1] = Dot3(F, c) / det;
    Cross3(T, &T[3], c);
    dx[2] = -Dot3(F, c) / det;
    xi[0] += dx[0];
    xi[1] += dx[1];
    t += dx[2];
    if (!(PetscAbsReal(xi[0]) < 1e3 && PetscAbsReal(xi[1]) < 1e3)) return 0.0;
    if (PetscAbsReal(dx[0]) + PetscAbsReal(dx[1]) < SEGMENT3D_HIT_TOL) break;
  }
  /* how far outside the domain, in its sides' lengths (Tri6 1, Quad9 2) */
  out = tri ? PetscMax(PetscMax(-xi[0], -xi[1]), xi[0] + xi[1] - 1.0) : 0.5 * (PetscMax(PetscAbsReal(xi[0]), PetscAbsReal(xi[1])) - 1.0);
  return SmoothStep(2.0 * (1.0 - out));
}

/* The weight a master vertex y (its faces' size fsize) is taken with on
   its line y + t d's hit on the slave S (hxi, Segment3dSlaveHit), against
   the projection on a sub-triangle's plane: the hit's own weight, times 1
   to 0 as fsize goes from S's size ssize to SEGMENT3D_HIT_COARSE times it. */
static PetscReal Segment3dHitWeight(const Face3d *S, const PetscReal y[3], const PetscReal d[3], PetscReal fsize, PetscReal ssize, PetscReal hxi[2])
{
  return Segment3dSlaveHit(S, y, d, hxi) * SmoothStep((SEGMENT3D_HIT_COARSE - fsize / ssize) / (SEGMENT3D_HIT_COARSE - 1.0));
}

/* The lines of the master sub-triangles' sides that bend (Segment3dEdgeLines),
   made at a side's first use and kept for the slave face's other
   sub-triangles: state[3 (8 m + u) + k] 0 not yet, 1 straight, 2 bent,
   line[] nedge lines of 9 per side. */
typedef struct {
  PetscInt   nedge;
  char      *state;
  PetscReal *line;
  PetscInt  *nb; /* [3 (8 m + u) + k][3]: the other face, and the side's two nodes there */
} EdgeCache;

/* With nedge points along each master edge: master face m's sub-triangle u
   (msub its nodes, mt2d their points on P, meta their parameters) with its
   sides that lie on an edge to another face given bent through those
   edges' points projected as the nodes are, cut into a fan (from the
   vertex across where one side bends, else from the centroid), each
   triangle clipped by T and its points added; *bent: whether a side bent
   (else the caller clips the straight sub-triangle). With KL, the kink
   lines of the bent sides (Segment3dKink) inside T, each edge's from the
   face of the lower index. */
static PetscErrorCode Segment3dBentPieces(const Face3d *slave, const SubPlane *P, PetscReal ssize, PetscInt nm, const Face3d master[], const PetscReal boxes[], PetscInt m, PetscInt u, const PetscInt msub[3], const PetscReal mt2d[6], const PetscReal meta[6], const Face3dRule *rule, EdgeCache *C, PetscBool *bent, PointList *L, KinkList *KL)
{
  const PetscInt nedge = C->nedge;
  PetscReal      poly[2 * 3 * (SEGMENT3D_MAX_EDGE_POINTS + 1)], apex[2];
  PetscInt       n = 0, nbent = 0, first = -1, sideStart[3];

  PetscFunctionBeginUser;
  *bent = PETSC_FALSE;
  for (PetscInt k = 0; k < 3; ++k) {
    const PetscInt k1 = (k + 1) % 3, c = 3 * (8 * m + u) + k;
    PetscReal     *line = &C->line[9 * nedge * c];
    sideStart[k]    = n;
    poly[2 * n]     = mt2d[2 * k];
    poly[2 * n + 1] = mt2d[2 * k + 1];
    ++n;
    if (!C->state[c]) {
      PetscInt *nb = &C->nb[3 * c];
      C->state[c] = 1;
      if (Segment3dFaceSide(master[m].type, msub[k], msub[k1]) >= 0 && Segment3dNeighbour(nm, master, m, msub[k], msub[k1], &nb[0], &nb[1], &nb[2])) {
        Segment3dEdgeLines(slave, ssize, master, m, msub[k], msub[k1], nb[0], nb[1], nb[2], nedge, line);
        C->state[c] = 2;
      }
    }
    if (C->state[c] != 2) continue;
    for (PetscInt j = 0; j < nedge; ++j, ++n) Segment3dProjectVertex(P, &line[9 * j], &line[9 * j + 3], PETSC_FALSE, line[9 * j + 8], &line[9 * j + 6], &poly[2 * n]);
    if (KL && m < C->nb[3 * c]) { /* the kink line, once per edge: the bent side's straight parts inside T */
      for (PetscInt i = 0; i <= nedge; ++i) {
        const PetscReal *q0 = &poly[2 * (sideStart[k] + i)], *q1 = i < nedge ? &poly[2 * (sideStart[k] + i + 1)] : &mt2d[2 * k1];
        PetscReal        t0, t1, x[2];
        Segment3dKink    K;
        Segment3dSegmentInTriangle(P->v2d, q0, q1, &t0, &t1);
        if (!(t1 - t0 > SEGMENT3D_END_TOL)) continue;
        K.m     = m;
        K.m2    = C->nb[3 * c];
        K.e[0]  = msub[k];
        K.e[1]  = msub[k1];
        K.e2[0] = C->nb[3 * c + 1];
        K.e2[1] = C->nb[3 * c + 2];
        K.s0    = (i + t0) / (nedge + 1);
        K.s1    = (i + t1) / (nedge + 1);
        for (PetscInt e = 0; e < 2; ++e) {
          const PetscReal t = e ? t1 : t0;
          for (PetscInt d = 0; d < 2; ++d) x[d] = q0[d] + t * (q1[d] - q0[d]);
          SubPlaneXi(P, x, e ? K.xi1 : K.xi0);
        }
        PetscCall(KinkListPush(KL, &K));
      }
    }
    if (first < 0) first = k;
    ++nbent;
  }
  if (!nbent) PetscFunctionReturn(0);
  *bent = PETSC_TRUE;
  if (nbent == 1) { /* from the vertex across the bent side: its nedge + 1 triangles */
    const PetscInt k2 = (first + 2) % 3;
    apex[0] = mt2d[2 * k2];
    apex[1] = mt2d[2 * k2 + 1];
  } else {
    apex[0] = (mt2d[0] + mt2d[2] + mt2d[4]) / 3.0;
    apex[1] = (mt2d[1] + mt2d[3] + mt2d[5]) / 3.0;
  }
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt  i1     = (i + 1) % n;
    const PetscReal fan[6] = {apex[0], apex[1], poly[2 * i], poly[2 * i + 1], poly[2 * i1], poly[2 * i1 + 1]};
    PetscReal       fpoly[2 * CLIP_MAX_VERTICES], ftri[6 * CLIP_MAX_VERTICES];
    PetscInt        nfp, nft;
    if (nbent == 1 && (i == sideStart[(first + 2) % 3] || i1 == sideStart[(first + 2) % 3])) continue; /* the sides at the apex */
    PetscCall(ClipConvex(3, fan, 3, P->v2d, &nfp, fpoly));
    if (nfp < 3) continue;
    nft = ClipTriangulate(nfp, fpoly, 1e-14 * ClipSignedArea(3, P->v2d), ftri);
    for (PetscInt q = 0; q < nft; ++q) PetscCall(Segment3dPiecePoints(slave, P, nm, master, boxes, m, &ftri[6 * q], mt2d, meta, rule, PETSC_FALSE, L));
  }
  PetscFunctionReturn(0);
}

/* The integration points of the slave face against the nm master faces
   (current coordinates), the rule on the unit triangle (weights summing
   to 1/2) for each clipped piece; *pts allocated (PetscFree). With ends
   (or NULL), the ends of S' inside the face (Segment3dEnd), *ends
   allocated (PetscFree); slaveBorder: a bit per node of the slave face on
   the slave surface's border (bit i: node i). With kinks (or NULL) and
   nedge > 0, the kink lines (Segment3dKink), *kinks allocated (PetscFree). */
PetscErrorCode Segment3dPoints(const Face3d *slave, PetscInt nm, const Face3d master[], const Face3dRule *rule, PetscInt nedge, PetscInt *np, Segment3dPoint **pts, PetscInt slaveBorder, PetscInt *nend, Segment3dEnd **ends, PetscInt *nkink, Segment3dKink **kinks)
{
  PointList       L  = {0, 0, NULL};
  EndList         EL = {0, 0, NULL};
  KinkList        KL = {0, 0, NULL};
  PetscInt        ns, nsm;
  const PetscInt(*sub)[3], (*msub)[3];
  PetscReal      *boxes, *dir, *hxi, *hw, *size, ssize;
  PetscBool      *border;
  EdgeCache       EC;

  PetscFunctionBeginUser;
  PetscCheck(nm <= SEGMENT3D_MAX_MASTER, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%" PetscInt_FMT " master faces for one slave face: %d at most", nm, SEGMENT3D_MAX_MASTER);
  PetscCheck(nedge >= 0 && nedge <= SEGMENT3D_MAX_EDGE_POINTS, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%" PetscInt_FMT " points along a master edge: 0 to %d", nedge, SEGMENT3D_MAX_EDGE_POINTS);
  PetscCall(PetscMalloc6(6 * nm + 1, &boxes, 27 * nm + 1, &dir, 18 * nm + 1, &hxi, 9 * nm + 1, &hw, 18 * nm + 1, &border, 9 * nm + 1, &size));
  EC.nedge = nedge;
  PetscCall(PetscCalloc3(nedge ? 24 * nm : 0, &EC.state, nedge ? 216 * nm * nedge : 0, &EC.line, nedge ? 72 * nm : 0, &EC.nb));
  for (PetscInt m = 0; m < nm; ++m) Face3dBox(master[m].type, master[m].x, &boxes[6 * m]);
  ssize = Face3dSize(slave->type, slave->x);
  Segment3dNodeDirections(nm, master, &border[9 * nm], border, dir, size);
  for (PetscInt m = 0; m < nm; ++m)
    for (PetscInt a = 0; a < Face3dNodes(master[m].type); ++a) {
      const PetscReal *d = &dir[27 * m + 3 * a];
      hw[9 * m + a]      = (border[9 * m + a] && !nedge) || (d[0] == 0 && d[1] == 0 && d[2] == 0) ? 0.0 : Segment3dHitWeight(slave, &master[m].x[3 * a], d, size[9 * m + a], ssize, &hxi[18 * m + 2 * a]);
    }
  if (nedge) { /* with edge points, the border nodes too go along their lines where S' has no end inside the slave face (the master's border, if any, runs along the slave's: a symmetry plane) */
    PetscBool hasEnd;
    PetscCall(Segment3dHasEnd(slave, slaveBorder, nm, master, border, &hasEnd));
    for (PetscInt m = 0; m < nm; ++m)
      for (PetscInt a = 0; a < Face3dNodes(master[m].type); ++a)
        if (border[9 * m + a]) {
          if (hasEnd) hw[9 * m + a] = 0.0;
          else border[9 * m + a] = PETSC_FALSE;
        }
  }
  Face3dSubTriangles(slave->type, &ns, &sub);
  for (PetscInt t = 0; t < ns; ++t) {
    SubPlane P;
    SubPlaneSetUp(slave, sub[t], &P);
    for (PetscInt m = 0; m < nm; ++m) {
      Face3dSubTriangles(master[m].type, &nsm, &msub);
      for (PetscInt u = 0; u < nsm; ++u) {
        PetscReal a[3], b[3], nu[3], mt2d[6], meta[6], poly[2 * CLIP_MAX_VERTICES], tri[6 * CLIP_MAX_VERTICES];
        PetscInt  npoly, ntri, mnode[3] = {msub[u][0], msub[u][1], msub[u][2]}; /* mt2d's vertices' master nodes */
        PetscBool bent = PETSC_FALSE;
        for (PetscInt d = 0; d < 3; ++d) {
          a[d] = master[m].x[3 * msub[u][1] + d] - master[m].x[3 * msub[u][0] + d];
          b[d] = master[m].x[3 * msub[u][2] + d] - master[m].x[3 * msub[u][0] + d];
        }
        Cross3(a, b, nu);
        if (Dot3(nu, &P.e[6]) >= 0) continue; /* not facing the slave */
        for (PetscInt k = 0; k < 3; ++k) { /* where the node's line meets the slave, or along the line (Segment3dNodeDirections), or T's normal */
          const PetscInt a = msub[u][k];
          Segment3dProjectVertex(&P, &master[m].x[3 * a], &dir[27 * m + 3 * a], border[9 * m + a], hw[9 * m + a], &hxi[18 * m + 2 * a], &mt2d[2 * k]);
          Face3dNodeXi(master[m].type, a, &meta[2 * k]);
        }
        PetscCall(ClipConvex(3, mt2d, 3, P.v2d, &npoly, poly));
        if (npoly < 3) continue;
        if (nedge) PetscCall(Segment3dBentPieces(slave, &P, ssize, nm, master, boxes, m, u, msub[u], mt2d, meta, rule, &EC, &bent, &L, kinks ? &KL : NULL));
        if (ends) PetscCall(Segment3dSubEnds(slave->type, slaveBorder, nm, master, m, msub[u], sub[t], &P, mt2d, &EL));
        if (ClipSignedArea(3, mt2d) < 0) { /* the master's parameters follow its vertices in the plane: keep them anticlockwise too */
          PetscReal t2[6], te[6];
          for (PetscInt k = 0; k < 3; ++k)
            for (PetscInt c = 0; c < 2; ++c) {
              t2[2 * k + c] = mt2d[2 * (2 - k) + c];
              te[2 * k + c] = meta[2 * (2 - k) + c];
            }
          PetscCall(PetscArraycpy(mt2d, t2, 6));
          PetscCall(PetscArraycpy(meta, te, 6));
          mnode[0] = msub[u][2];
          mnode[2] = msub[u][0];
        }
        ntri = bent ? 0 : ClipTriangulate(npoly, poly, 1e-14 * ClipSignedArea(3, P.v2d), tri);
        for (PetscInt k = 0; k < ntri; ++k) PetscCall(Segment3dPiecePoints(slave, &P, nm, master, boxes, m, &tri[6 * k], mt2d, meta, rule, PETSC_FALSE, &L));
        if (slaveBorder) { /* the master's border along the slave's own: a strip beyond it, to T's edge */
          const PetscReal width = 0.25 * SubPlaneLongestEdge(&P);
          for (PetscInt k = 0; k < 3; ++k) {
            const PetscInt   k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            const PetscReal *pa = &mt2d[2 * k], *pb = &mt2d[2 * k1], *pc = &mt2d[2 * k2];
            PetscReal        s0, s1, nx, ny, nn, strip[8], spoly[2 * CLIP_MAX_VERTICES], stri[6 * CLIP_MAX_VERTICES];
            PetscInt         ns2, nst;
            if (Segment3dFaceSide(master[m].type, mnode[k], mnode[k1]) < 0 || !Segment3dBorderEdge(nm, master, m, mnode[k], mnode[k1])) continue;
            Segment3dSegmentInTriangle(P.v2d, pa, pb, &s0, &s1);
            if (!(s1 - s0 > SEGMENT3D_END_TOL) || !Segment3dAlongSlaveBorder(slave->type, slaveBorder, sub[t], &P, pa, pb, s0, s1)) continue;
            nx = pb[1] - pa[1];
            ny = -(pb[0] - pa[0]);
            if (nx * (pc[0] - pa[0]) + ny * (pc[1] - pa[1]) > 0) {
              nx = -nx;
              ny = -ny;
            }
            nn = PetscSqrtReal(nx * nx + ny * ny);
            nx *= width / nn;
            ny *= width / nn;
            strip[0] = pa[0];
            strip[1] = pa[1];
            strip[2] = pa[0] + nx;
            strip[3] = pa[1] + ny;
            strip[4] = pb[0] + nx;
            strip[5] = pb[1] + ny;
            strip[6] = pb[0];
            strip[7] = pb[1];
            if (ClipSignedArea(4, strip) < 0) {
              PetscReal tmp[8] = {strip[6], strip[7], strip[4], strip[5], strip[2], strip[3], strip[0], strip[1]};
              PetscCall(PetscArraycpy(strip, tmp, 8));
            }
            PetscCall(ClipConvex(4, strip, 3, P.v2d, &ns2, spoly));
            if (ns2 < 3) continue;
            nst = ClipTriangulate(ns2, spoly, 1e-14 * ClipSignedArea(3, P.v2d), stri);
            for (PetscInt q = 0; q < nst; ++q) PetscCall(Segment3dPiecePoints(slave, &P, nm, master, boxes, m, &stri[6 * q], mt2d, meta, rule, PETSC_TRUE, &L));
          }
        }
      }
    }
  }
  PetscCall(PetscFree6(boxes, dir, hxi, hw, border, size));
  PetscCall(PetscFree3(EC.state, EC.line, EC.nb));
  *np  = L.n;
  *pts = L.p;
  if (ends) {
    *nend = EL.n;
    *ends = EL.e;
  }
  if (kinks) {
    *nkink = KL.n;
    *kinks = KL.k;
  }
  PetscFunctionReturn(0);
}

/* The columns of dQ (Segment3dEvaluate's layout): the slave's 3 ns dofs,
   then the nm master faces', face m's from off[m]; returns their number. */
static PetscInt Segment3dColumns(PetscInt ns, PetscInt nm, const Face3d master[], PetscInt off[])
{
  PetscInt ndof = 3 * ns;

  for (PetscInt m = 0; m < nm; ++m) {
    off[m] = ndof;
    ndof += 3 * Face3dNodes(master[m].type);
  }
  return ndof;
}

/* A_j and Q_j (added into A[], Q[]) over the points, their eta updated by
   Newton at the current coordinates (xs the slave's, master[] the
   masters'); Xref the slave's reference face (dS), Adual its weights'
   coefficients. dQ (or NULL): dQ[j ndof + c], ndof = 3 (slave nodes + the
   master faces' nodes in order), slave's dofs first. */
PetscErrorCode Segment3dEvaluate(const Face3d *Xref, const PetscReal xs[], const PetscReal Adual[], PetscInt nm, const Face3d master[], PetscInt np, Segment3dPoint pts[], PetscReal A[], PetscReal Q[], PetscReal dQ[])
{
  const PetscInt ns = Face3dNodes(Xref->type);
  PetscInt       ndof, off[64];

  PetscFunctionBeginUser;
  PetscCheck(nm <= 64, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%" PetscInt_FMT " master faces for one slave face: 64 at most", nm);
  ndof = Segment3dColumns(ns, nm, master, off);
  for (PetscInt q = 0; q < np; ++q) {
    Segment3dPoint *pt = &pts[q];
    const Face3d   *M  = &master[pt->m];
    PetscReal       N[FACE3D_MAX_NODES], Nm[FACE3D_MAX_NODES], W[FACE3D_MAX_NODES], X[3], T[6], n[3], x[3], xm[3], dS, g;
    PetscBool       clamped;
    Face3dEval(Xref->type, Xref->x, pt->xi, X, T, NULL);
    dS = Face3dNormal(T, n) * pt->w;
    Face3dShape(Xref->type, pt->xi, N, NULL, NULL);
    Face3dWeights(Xref->type, Adual, pt->xi, W);
    Face3dEval(Xref->type, xs, pt->xi, x, NULL, NULL);
    Segment3dPointClosest(pt, M, x, pt->eta, &clamped);
    Face3dEval(M->type, M->x, pt->eta, xm, T, NULL);
    Face3dNormal(T, n);
    Face3dShape(M->type, pt->eta, Nm, NULL, NULL);
    g = (x[0] - xm[0]) * n[0] + (x[1] - xm[1]) * n[1] + (x[2] - xm[2]) * n[2];
    if (clamped) { /* behind an edge: g the signed distance to the edge's point, n along it */
      const PetscReal dist = PetscSqrtReal(PetscSqr(x[0] - xm[0]) + PetscSqr(x[1] - xm[1]) + PetscSqr(x[2] - xm[2]));
      PetscCheck(dist > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "slave point (%g, %g, %g) on the edge of master face %" PetscInt_FMT ": no normal", (double)x[0], (double)x[1], (double)x[2], pt->m);
      g = g < 0 ? -dist : dist;
      for (PetscInt d = 0; d < 3; ++d) n[d] = (x[d] - xm[d]) / g;
    }
    for (PetscInt j = 0; j < ns; ++j) {
      const PetscReal wj = W[j] * dS;
      A[j] += wj;
      Q[j] += wj * g;
      if (!dQ) continue;
      for (PetscInt i = 0; i < ns; ++i)
        for (PetscInt d = 0; d < 3; ++d) dQ[j * ndof + 3 * i + d] += wj * N[i] * n[d];
      for (PetscInt k = 0; k < Face3dNodes(M->type); ++k)
        for (PetscInt d = 0; d < 3; ++d) dQ[j * ndof + off[pt->m] + 3 * k + d] -= wj * Nm[k] * n[d];
    }
  }
  PetscFunctionReturn(0);
}

/* The closest point eta on the master of the slave point at xi: the shape
   values, points, the master's tangents T and second derivatives H there,
   d = x_m - x_s, and the closest-point conditions' Jacobian
   K_ab = t_a . t_b + d . x_,ab (symmetric: K[0] = K_11, K[1] = K_12,
   K[2] = K_22). PETSC_TRUE where K is positive definite (eta a strict
   minimum: the point nearer than the master's radius of curvature). */
PetscBool Segment3dClosestPointAt(const Face3d *slave, const PetscReal xi[2], const Face3d *master, const PetscReal eta[2], Segment3dClosest *c)
{
  Face3dShape(slave->type, xi, c->N, NULL, NULL);
  Face3dShape(master->type, eta, c->M, c->dM, NULL);
  Face3dEval(slave->type, slave->x, xi, c->xs, NULL, NULL);
  Face3dEval(master->type, master->x, eta, c->xm, c->T, c->H);
  for (PetscInt k = 0; k < 3; ++k) c->d[k] = c->xm[k] - c->xs[k];
  c->K[0] = Dot3(&c->T[0], &c->T[0]) + Dot3(c->d, &c->H[0]);
  c->K[1] = Dot3(&c->T[0], &c->T[3]) + Dot3(c->d, &c->H[3]);
  c->K[2] = Dot3(&c->T[3], &c->T[3]) + Dot3(c->d, &c->H[6]);
  return (PetscBool)(c->K[0] * c->K[2] - c->K[1] * c->K[1] > 0);
}

/* deta[a n + c] = d eta*_a / d(dof c) of the closest point c (of a slave
   face of ns nodes on a master face of nm, Segment3dClosestPointAt, K
   positive definite), n = 3 (ns + nm), the slave's dofs first. */
void Segment3dProjectionDerivative(const Segment3dClosest *c, PetscInt ns, PetscInt nm, PetscReal deta[])
{
  const PetscInt  n   = 3 * (ns + nm);
  const PetscReal det = c->K[0] * c->K[2] - c->K[1] * c->K[1];
  const PetscReal Ki[3] = {c->K[2] / det, -c->K[1] / det, c->K[0] / det};

  for (PetscInt col = 0; col < n; ++col) {
    PetscReal      r[2];
    const PetscInt node = col / 3, dd = col % 3;
    if (node < ns) {
      r[0] = -c->N[node] * c->T[dd];
      r[1] = -c->N[node] * c->T[3 + dd];
    } else {
      const PetscInt k = node - ns;
      r[0]             = c->M[k] * c->T[dd] + c->d[dd] * c->dM[2 * k];
      r[1]             = c->M[k] * c->T[3 + dd] + c->d[dd] * c->dM[2 * k + 1];
    }
    deta[col]     = -(Ki[0] * r[0] + Ki[1] * r[1]);
    deta[n + col] = -(Ki[1] * r[0] + Ki[2] * r[1]);
  }
}

/* The end term (Segment3dEnd). Q_j = int_R W_j g J dxi over the part R of
   the slave's parameter plane that the pieces tile; on one slave
   sub-triangle T (vertices x0, x1, x2, a = x1 - x0, b = x2 - x0, c = a x b,
   n = c / |c|) a point's slave parameters are affine in its barycentric
   coordinates l = (l1, l2) in T, dxi = D dl, D = 2 (T's area in xi), and a
   master point y projects on T's plane at
     y - x0 = l1 a + l2 b + t n,  l1 = (y - x0) . beta1, l2 = (y - x0) . beta2,
     beta1 = (b x n) / |c|,  beta2 = (n x a) / |c|.
   Where R ends on a master border edge P -> Q (its projection inside T,
   y(s) = x_P + s (x_Q - x_P), the covered part on its left), the edge moves
   in l with the nodes, and the derivative of the integral over a moving
   domain adds the flux through it (outward normal motion times the
   integrand; in l the outward normal motion times the length is the 2D
   cross product dl x l', l' = dl/ds = l(Q) - l(P)):
     dQ_j += int_s0^s1 W_j g J D (dl(s) x l') ds.
   dl from varying y - x0 = l1 a + l2 b + t n and dotting with beta1 and
   beta2 (a . beta1 = b . beta2 = 1, b . beta1 = a . beta2 = n . beta = 0):
     dl_k = beta_k . (dy - (1 - l1 - l2) dx0 - l1 dx1 - l2 dx2 - t dn),
   dn = (I - n n^T) (da x b + a x db) / |c|, so that
     t dn . beta1 = t (-|b|^2 n . da + (a . b) n . db) / |c|^2,
     t dn . beta2 = t ((a . b) n . da - |a|^2 n . db) / |c|^2,
   da = dx1 - dx0, db = dx2 - dx0, dy = (1 - s) dx_P + s dx_Q. The other
   edges of R (T's edges, fixed in l; the master's edges shared by two
   faces or inside a face, across which the integrand is continuous, the
   two sides' fluxes cancelling) have no term. The flux integrand is O(g)
   (the gradient's term is O(p g)); its derivative's leading part, with
   the points' dg as inside,
     d2Q_j += int_end W_j J D (dg v^T + v dg^T) ds,  v = dl x l',
   the rest O(g) (left out: O(p g) in the Hessian). */
typedef struct {
  PetscReal xi[2], w, g, n[3], N[FACE3D_MAX_NODES], Nm[FACE3D_MAX_NODES], W[FACE3D_MAX_NODES], v[15];
} Segment3dEndPt;

/* The end E at s (master face M, current slave coordinates xs, reference
   face Xref, dual coefficients Adual): the point's slave parameters, the
   weight J D ds (ds the Gauss weight wq times the end's length in s), W_j,
   g and n at its closest point on M, the shapes, and v[5][3] (over T's
   vertices, then P, Q). */
static void Segment3dEndPointAt(const Face3d *Xref, const PetscReal xs[], const PetscReal Adual[], const Face3d *M, const Segment3dEnd *E, PetscReal s, PetscReal wq, Segment3dEndPt *q)
{
  PetscReal x[3][3], xP[3], xQ[3], a[3], b[3], c[3], n[3], b1[3], b2[3], y[3], r[3], dy[3], txi[6], lp[2], l1, l2, t, cc, ab, aa, bb, D, X[3], T[6], nr[3], xsp[3], xm[3], eta[2], eP[2], eQ[2];
  PetscBool clamped;

  for (PetscInt k = 0; k < 3; ++k) {
    for (PetscInt d = 0; d < 3; ++d) x[k][d] = xs[3 * E->t[k] + d];
    Face3dNodeXi(Xref->type, E->t[k], &txi[2 * k]);
  }
  for (PetscInt d = 0; d < 3; ++d) {
    xP[d] = M->x[3 * E->e[0] + d];
    xQ[d] = M->x[3 * E->e[1] + d];
    a[d]  = x[1][d] - x[0][d];
    b[d]  = x[2][d] - x[0][d];
    y[d]  = xP[d] + s * (xQ[d] - xP[d]);
    r[d]  = y[d] - x[0][d];
    dy[d] = xQ[d] - xP[d];
  }
  Cross3(a, b, c);
  cc = Dot3(c, c);
  for (PetscInt d = 0; d < 3; ++d) n[d] = c[d] / PetscSqrtReal(cc);
  Cross3(b, n, b1);
  Cross3(n, a, b2);
  for (PetscInt d = 0; d < 3; ++d) {
    b1[d] /= PetscSqrtReal(cc);
    b2[d] /= PetscSqrtReal(cc);
  }
  l1    = Dot3(r, b1);
  l2    = Dot3(r, b2);
  t     = Dot3(r, n);
  lp[0] = Dot3(dy, b1);
  lp[1] = Dot3(dy, b2);
  ab    = Dot3(a, b);
  aa    = Dot3(a, a);
  bb    = Dot3(b, b);
  D     = PetscAbsReal((txi[2] - txi[0]) * (txi[5] - txi[1]) - (txi[3] - txi[1]) * (txi[4] - txi[0]));
  for (PetscInt k = 0; k < 2; ++k) q->xi[k] = txi[k] + l1 * (txi[2 + k] - txi[k]) + l2 * (txi[4 + k] - txi[k]);
  for (PetscInt d = 0; d < 3; ++d) { /* v = dl1 l'_2 - dl2 l'_1 over x0, x1, x2, x_P, x_Q */
    const PetscReal beta = b1[d] * lp[1] - b2[d] * lp[0];
    const PetscReal t1   = t * (bb * lp[1] + ab * lp[0]) / cc; /* -t dn . (beta1 l'_2 - beta2 l'_1) on n . dx1 */
    const PetscReal t2   = -t * (ab * lp[1] + aa * lp[0]) / cc; /* on n . dx2 */
    q->v[3 * 0 + d] = -(1 - l1 - l2) * beta - (t1 + t2) * n[d];
    q->v[3 * 1 + d] = -l1 * beta + t1 * n[d];
    q->v[3 * 2 + d] = -l2 * beta + t2 * n[d];
    q->v[3 * 3 + d] = (1 - s) * beta;
    q->v[3 * 4 + d] = s * beta;
  }
  Face3dEval(Xref->type, Xref->x, q->xi, X, T, NULL);
  q->w = Face3dNormal(T, nr) * D * wq * (E->s1 - E->s0);
  Face3dWeights(Xref->type, Adual, q->xi, q->W);
  Face3dShape(Xref->type, q->xi, q->N, NULL, NULL);
  Face3dEval(Xref->type, xs, q->xi, xsp, NULL, NULL);
  Face3dNodeXi(M->type, E->e[0], eP);
  Face3dNodeXi(M->type, E->e[1], eQ);
  for (PetscInt k = 0; k < 2; ++k) eta[k] = eP[k] + s * (eQ[k] - eP[k]);
  Face3dClosestPointOnFace(M->type, M->x, xsp, SEGMENT3D_IN_TOL, eta, &clamped);
  Face3dEval(M->type, M->x, eta, xm, T, NULL);
  Face3dNormal(T, q->n);
  Face3dShape(M->type, eta, q->Nm, NULL, NULL);
  q->g = (xsp[0] - xm[0]) * q->n[0] + (xsp[1] - xm[1]) * q->n[1] + (xsp[2] - xm[2]) * q->n[2];
}

/* The Gauss-Legendre rule of SEGMENT3D_END_POINTS points on [0, 1]. */
static PetscErrorCode Segment3dEndRule(PetscReal s[], PetscReal w[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscDTGaussQuadrature(SEGMENT3D_END_POINTS, 0.0, 1.0, s, w));
  PetscFunctionReturn(0);
}

/* The ends' term of dQ (Segment3dEvaluate's layout: dQ[j ndof + c], the
   slave's dofs, then the nm master faces'), added. */
PetscErrorCode Segment3dEndEvaluate(const Face3d *Xref, const PetscReal xs[], const PetscReal Adual[], PetscInt nm, const Face3d master[], PetscInt nend, const Segment3dEnd ends[], PetscReal dQ[])
{
  const PetscInt ns = Face3dNodes(Xref->type);
  PetscInt       ndof, off[SEGMENT3D_MAX_MASTER];
  PetscReal      sq[SEGMENT3D_END_POINTS], wq[SEGMENT3D_END_POINTS];

  PetscFunctionBeginUser;
  if (!nend) PetscFunctionReturn(0);
  ndof = Segment3dColumns(ns, nm, master, off);
  PetscCall(Segment3dEndRule(sq, wq));
  for (PetscInt e = 0; e < nend; ++e) {
    const Segment3dEnd *E = &ends[e];
    for (PetscInt q = 0; q < SEGMENT3D_END_POINTS; ++q) {
      Segment3dEndPt pt;
      PetscInt       col[5];
      Segment3dEndPointAt(Xref, xs, Adual, &master[E->m], E, E->s0 + sq[q] * (E->s1 - E->s0), wq[q], &pt);
      for (PetscInt k = 0; k < 3; ++k) col[k] = 3 * E->t[k];
      col[3] = off[E->m] + 3 * E->e[0];
      col[4] = off[E->m] + 3 * E->e[1];
      for (PetscInt j = 0; j < ns; ++j) {
        const PetscReal f = pt.W[j] * pt.w * pt.g;
        for (PetscInt k = 0; k < 5; ++k)
          for (PetscInt d = 0; d < 3; ++d) dQ[j * ndof + col[k] + d] += f * pt.v[3 * k + d];
      }
    }
  }
  PetscFunctionReturn(0);
}

/* The end E's leading Hessian part, sum_j lam_j d2Q_j's O(1) end term,
   lam[j] per slave node (k_p g_j where in contact, else 0), added into
   K[n][n] over the slave face's and the master face M's dofs (n = 3 (ns +
   nm), the slave's first); *any: whether it added. */
PetscErrorCode Segment3dEndHessian(const Face3d *Xref, const PetscReal xs[], const PetscReal Adual[], const PetscReal lam[], const Face3d *M, const Segment3dEnd *E, PetscReal K[], PetscBool *any)
{
  const PetscInt ns = Face3dNodes(Xref->type), n = 3 * (ns + Face3dNodes(M->type));
  PetscReal      sq[SEGMENT3D_END_POINTS], wq[SEGMENT3D_END_POINTS];
  PetscInt       col[5];

  PetscFunctionBeginUser;
  PetscCall(Segment3dEndRule(sq, wq));
  for (PetscInt k = 0; k < 3; ++k) col[k] = 3 * E->t[k];
  col[3] = 3 * (ns + E->e[0]);
  col[4] = 3 * (ns + E->e[1]);
  for (PetscInt q = 0; q < SEGMENT3D_END_POINTS; ++q) {
    Segment3dEndPt pt;
    PetscReal      L = 0.0, dg[3 * 2 * FACE3D_MAX_NODES];
    Segment3dEndPointAt(Xref, xs, Adual, M, E, E->s0 + sq[q] * (E->s1 - E->s0), wq[q], &pt);
    for (PetscInt j = 0; j < ns; ++j) L += lam[j] * pt.W[j] * pt.w;
    if (L == 0.0) continue;
    *any = PETSC_TRUE;
    for (PetscInt i = 0; i < ns; ++i)
      for (PetscInt d = 0; d < 3; ++d) dg[3 * i + d] = pt.N[i] * pt.n[d];
    for (PetscInt i = 0; i < Face3dNodes(M->type); ++i)
      for (PetscInt d = 0; d < 3; ++d) dg[3 * (ns + i) + d] = -pt.Nm[i] * pt.n[d];
    for (PetscInt k = 0; k < 5; ++k)
      for (PetscInt d = 0; d < 3; ++d) {
        const PetscReal vk = L * pt.v[3 * k + d];
        for (PetscInt c = 0; c < n; ++c) {
          K[(col[k] + d) * n + c] += vk * dg[c];
          K[c * n + col[k] + d] += vk * dg[c];
        }
      }
  }
  PetscFunctionReturn(0);
}

/* A point of the kink line Kk (faces M, M2) at sq of it, the line rule's
   weight wq: its slave parameters xi, its edge point's parameters in M
   (eta) and in M2 (eta2), the unit vector b normal to the edge and to the
   faces' mean normal there (towards M2: from the edge's point to M2's
   centroid), beta = (n1 - n2) . b, and meas = wq |det(xi', grad phi)| /
   |grad phi|^2, grad phi = (b . t_1, b . t_2) the slave's tangents xs at
   xi (xi' = dxi/ds along the line): the line's motion in xi per unit of
   -b . (sum N_i du_i - sum M_k du_k). PETSC_FALSE where it has none (b or
   grad phi zero). */
typedef struct {
  PetscReal xi[2], eta[2], eta2[2], b[3], beta, meas;
} Segment3dKinkPt;

static PetscBool Segment3dKinkPointAt(const Face3d *S, const Face3d *M, const Face3d *M2, const Segment3dKink *Kk, PetscReal sq, PetscReal wq, Segment3dKinkPt *p)
{
  const PetscReal se = Kk->s0 + sq * (Kk->s1 - Kk->s0);
  PetscReal       e0[2], e1[2], f0[2], f1[2], c2[3] = {0, 0, 0}, dxi[2], X[3], xe[3], T[6], n1[3], n2[3], nb[3], te[3], r[3], gp[2], len, sg;

  Face3dNodeXi(M->type, Kk->e[0], e0);
  Face3dNodeXi(M->type, Kk->e[1], e1);
  Face3dNodeXi(M2->type, Kk->e2[0], f0);
  Face3dNodeXi(M2->type, Kk->e2[1], f1);
  for (PetscInt i = 0; i < Face3dNodes(M2->type); ++i)
    for (PetscInt d = 0; d < 3; ++d) c2[d] += M2->x[3 * i + d] / Face3dNodes(M2->type);
  for (PetscInt a = 0; a < 2; ++a) {
    p->xi[a]   = Kk->xi0[a] + sq * (Kk->xi1[a] - Kk->xi0[a]);
    dxi[a]     = Kk->xi1[a] - Kk->xi0[a];
    p->eta[a]  = e0[a] + se * (e1[a] - e0[a]);
    p->eta2[a] = f0[a] + se * (f1[a] - f0[a]);
  }
  Face3dEval(M2->type, M2->x, p->eta2, X, T, NULL);
  (void)Face3dNormal(T, n2);
  Face3dEval(M->type, M->x, p->eta, xe, T, NULL);
  (void)Face3dNormal(T, n1);
  for (PetscInt d = 0; d < 3; ++d) {
    nb[d] = n1[d] + n2[d];
    te[d] = T[d] * (e1[0] - e0[0]) + T[3 + d] * (e1[1] - e0[1]);
    r[d]  = c2[d] - xe[d];
  }
  Cross3(te, nb, p->b);
  len = PetscSqrtReal(Dot3(p->b, p->b));
  if (!(len > 0)) return PETSC_FALSE;
  sg = Dot3(p->b, r) < 0 ? -1.0 : 1.0; /* the orientation once, for all three components */
  for (PetscInt d = 0; d < 3; ++d) {
    p->b[d] *= sg / len;
    r[d] = n1[d] - n2[d];
  }
  p->beta = Dot3(r, p->b);
  Face3dEval(S->type, S->x, p->xi, X, T, NULL);
  gp[0] = Dot3(p->b, T);
  gp[1] = Dot3(p->b, &T[3]);
  if (!(gp[0] * gp[0] + gp[1] * gp[1] > 0)) return PETSC_FALSE;
  p->meas = PetscAbsReal(dxi[0] * gp[1] - dxi[1] * gp[0]) / (gp[0] * gp[0] + gp[1] * gp[1]) * wq;
  return PETSC_TRUE;
}

/* The kink lines' term of dQ (Segment3dEvaluate's layout), added: a piece's
   border is a straight part of the bent side, the line where the closest
   point passes from M to M2 a curve beside it, so between them a piece
   integrates the other face's gap and Q_j moves with the pieces' layout
   (by the sagitta's order: its exact value does not). As the border moves
   with the line, dQ_j takes
     int W_j J (g_1 - g_2) V ds along each kink line,
   g_1 and g_2 the gaps to M's and M2's polynomial extensions there (their
   closest points by Newton, unclamped) and V ds = -(c . du) meas
   (Segment3dKinkPointAt, c as Segment3dKinkHessian's): the Gauss-Newton
   part k_p dQ_j dQ_j^T then holds that motion too. */
PetscErrorCode Segment3dKinkEvaluate(const Face3d *Xref, const PetscReal xs[], const PetscReal Adual[], PetscInt nm, const Face3d master[], PetscInt nkink, const Segment3dKink kinks[], PetscReal dQ[])
{
  const PetscInt ns = Face3dNodes(Xref->type);
  const Face3d   S  = {Xref->type, xs};
  PetscInt       ndof, off[SEGMENT3D_MAX_MASTER];
  PetscReal      sq[SEGMENT3D_END_POINTS], wq[SEGMENT3D_END_POINTS];

  PetscFunctionBeginUser;
  if (!nkink) PetscFunctionReturn(0);
  ndof = Segment3dColumns(ns, nm, master, off);
  PetscCall(Segment3dEndRule(sq, wq));
  for (PetscInt e = 0; e < nkink; ++e) {
    const Segment3dKink *Kk = &kinks[e];
    const Face3d        *M = &master[Kk->m], *M2 = &master[Kk->m2];
    for (PetscInt q = 0; q < SEGMENT3D_END_POINTS; ++q) {
      Segment3dKinkPt pt;
      PetscReal       x[3], X[3], T[6], nr[3], g[2], J, W[FACE3D_MAX_NODES], N[FACE3D_MAX_NODES], Mk[FACE3D_MAX_NODES];
      PetscBool       ok = PETSC_TRUE;
      if (!Segment3dKinkPointAt(&S, M, M2, Kk, sq[q], wq[q], &pt)) continue;
      Face3dEval(S.type, xs, pt.xi, x, NULL, NULL);
      for (PetscInt k = 0; k < 2; ++k) { /* the gap to each face's extension */
        const Face3d *F = k ? M2 : M;
        PetscReal     eta[2] = {k ? pt.eta2[0] : pt.eta[0], k ? pt.eta2[1] : pt.eta[1]}, xm[3];
        if (!Face3dClosestPoint(F->type, F->x, x, eta, NULL)) ok = PETSC_FALSE;
        Face3dEval(F->type, F->x, eta, xm, T, NULL);
        (void)Face3dNormal(T, nr);
        g[k] = (x[0] - xm[0]) * nr[0] + (x[1] - xm[1]) * nr[1] + (x[2] - xm[2]) * nr[2];
      }
      if (!ok) continue;
      Face3dEval(Xref->type, Xref->x, pt.xi, X, T, NULL);
      J = Face3dNormal(T, nr);
      Face3dWeights(Xref->type, Adual, pt.xi, W);
      Face3dShape(Xref->type, pt.xi, N, NULL, NULL);
      Face3dShape(M->type, pt.eta, Mk, NULL, NULL);
      for (PetscInt j = 0; j < ns; ++j) {
        const PetscReal f = -W[j] * J * (g[0] - g[1]) * pt.meas;
        for (PetscInt i = 0; i < ns; ++i)
          for (PetscInt d = 0; d < 3; ++d) dQ[j * ndof + 3 * i + d] += f * N[i] * pt.b[d];
        for (PetscInt i = 0; i < Face3dNodes(M->type); ++i)
          for (PetscInt d = 0; d < 3; ++d) dQ[j * ndof + off[Kk->m] + 3 * i + d] -= f * Mk[i] * pt.b[d];
      }
    }
  }
  PetscFunctionReturn(0);
}

/* A kink line's Hessian term, added into K[n][n] over the slave face's and
   master face M's dofs (n = 3 (ns + nm), the slave's first; M the line's
   face m, M2 its m2): where a slave point passes from M to M2 the gap's
   gradient W_j J n . du jumps by W_j J (n1 - n2) . du, and the line moves
   as phi = b . (x_s(xi) - x_e) = 0 does (x_e the edge's point, b the unit
   vector normal to the edge and to the faces' mean normal, towards M2), at
   -dphi/|grad phi| in xi; with n1 - n2 = beta b (both normals are normal to
   the edge and n1 + n2 to b), the leading part of sum_j lam_j d2Q_j is
     -sum_j lam_j int W_j J beta (c . du)(c . dv) |det(xi', grad phi)| / |grad phi|^2 ds,
   c = b over the slave's N_i and -b over M's shapes, xi' = dxi/ds along
   the line (grad phi the slave tangents dotted with b: Segment3dKinkPointAt);
   *any: whether it added. (Where the edge is convex to the slave the
   gradient turns across the fan behind it, the same term in the limit of a
   thin fan.) */
PetscErrorCode Segment3dKinkHessian(const Face3d *Xref, const PetscReal xs[], const PetscReal Adual[], const PetscReal lam[], const Face3d *M, const Face3d *M2, const Segment3dKink *Kk, PetscReal K[], PetscBool *any)
{
  const PetscInt ns = Face3dNodes(Xref->type), nmn = Face3dNodes(M->type), n = 3 * (ns + nmn);
  const Face3d   S  = {Xref->type, xs};
  PetscReal      sq[SEGMENT3D_END_POINTS], wq[SEGMENT3D_END_POINTS];

  PetscFunctionBeginUser;
  PetscCall(Segment3dEndRule(sq, wq));
  for (PetscInt q = 0; q < SEGMENT3D_END_POINTS; ++q) {
    Segment3dKinkPt pt;
    PetscReal       X[3], T[6], r[3], L = 0.0, J;
    PetscReal       W[FACE3D_MAX_NODES], N[FACE3D_MAX_NODES], Mk[FACE3D_MAX_NODES], c[3 * 2 * FACE3D_MAX_NODES];
    const PetscReal xi[2] = {Kk->xi0[0] + sq[q] * (Kk->xi1[0] - Kk->xi0[0]), Kk->xi0[1] + sq[q] * (Kk->xi1[1] - Kk->xi0[1])};
    Face3dWeights(Xref->type, Adual, xi, W);
    for (PetscInt j = 0; j < ns; ++j) L += lam[j] * W[j];
    if (L == 0.0) continue;
    if (!Segment3dKinkPointAt(&S, M, M2, Kk, sq[q], wq[q], &pt)) continue;
    Face3dEval(Xref->type, Xref->x, pt.xi, X, T, NULL);
    J = Face3dNormal(T, r);
    Face3dShape(Xref->type, pt.xi, N, NULL, NULL);
    Face3dShape(M->type, pt.eta, Mk, NULL, NULL);
    for (PetscInt i = 0; i < ns; ++i)
      for (PetscInt d = 0; d < 3; ++d) c[3 * i + d] = N[i] * pt.b[d];
    for (PetscInt i = 0; i < nmn; ++i)
      for (PetscInt d = 0; d < 3; ++d) c[3 * (ns + i) + d] = -Mk[i] * pt.b[d];
    L *= -J * pt.meas * pt.beta;
    *any = PETSC_TRUE;
    for (PetscInt r0 = 0; r0 < n; ++r0)
      for (PetscInt c0 = 0; c0 < n; ++c0) K[r0 * n + c0] += L * c[r0] * c[c0];
  }
  PetscFunctionReturn(0);
}
