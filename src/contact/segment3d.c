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
   projected on it along n and clipped by T (clip.c), and the clipped
   polygon is cut into triangles. A point p of T's plane has barycentric
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
   the master surface's end and is dropped (S' ends there).

   First derivatives (Segment3dEvaluate), the points fixed in the slave's
   xi (the segments are not differentiated: the exact integral of an
   integrand continuous across the master's face edges has no term there;
   where the master ends inside S, the end moves and its term, W_j g on the
   end times its motion, is left out as 2D leaves its end cuts). At the
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
#include "clip.h"

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

typedef struct {
  PetscInt        n, cap;
  Segment3dPoint *p;
} PointList;

static PetscErrorCode PointListPush(PointList *L, const Segment3dPoint *q)
{
  PetscFunctionBeginUser;
  if (L->n == L->cap) {
    Segment3dPoint *p;
    L->cap = L->cap ? 2 * L->cap : 64;
    PetscCall(PetscMalloc1(L->cap, &p));
    if (L->n) PetscCall(PetscArraycpy(p, L->p, L->n));
    PetscCall(PetscFree(L->p));
    L->p = p;
  }
  L->p[L->n++] = *q;
  PetscFunctionReturn(0);
}

/* The points of one clipped triangle piece tri[6] of the slave plane P,
   master sub-triangle mt2d (its vertices' master parameters meta). */
static PetscErrorCode Segment3dPiecePoints(const Face3d *slave, const SubPlane *P, PetscInt nm, const Face3d master[], const PetscReal boxes[], PetscInt m, const PetscReal tri[6], const PetscReal mt2d[6], const PetscReal meta[6], const Face3dRule *rule, PointList *L)
{
  const PetscReal area = ClipSignedArea(3, tri), scale = P->xiArea / ClipSignedArea(3, P->v2d);

  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < rule->nq; ++q) {
    const PetscReal r = rule->xi[2 * q], s = rule->xi[2 * q + 1];
    const PetscReal p[2] = {tri[0] + r * (tri[2] - tri[0]) + s * (tri[4] - tri[0]), tri[1] + r * (tri[3] - tri[1]) + s * (tri[5] - tri[1])};
    PetscReal       l[2], lm[2], xs[3];
    Segment3dPoint  pt;
    Barycentric(P->v2d, p, l);
    Barycentric(mt2d, p, lm);
    for (PetscInt a = 0; a < 2; ++a) {
      pt.xi[a]  = P->xi[a] + l[0] * (P->xi[2 + a] - P->xi[a]) + l[1] * (P->xi[4 + a] - P->xi[a]);
      pt.eta[a] = meta[a] + lm[0] * (meta[2 + a] - meta[a]) + lm[1] * (meta[4 + a] - meta[a]);
    }
    pt.w = 2.0 * rule->w[q] * area * scale;
    Face3dEval(slave->type, slave->x, pt.xi, xs, NULL, NULL);
    pt.m = Segment3dOwner(nm, master, boxes, m, xs, pt.eta);
    if (pt.m >= 0) PetscCall(PointListPush(L, &pt));
  }
  PetscFunctionReturn(0);
}

/* The integration points of the slave face against the nm master faces
   (current coordinates), the rule on the unit triangle (weights summing
   to 1/2) for each clipped piece; *pts allocated (PetscFree). */
PetscErrorCode Segment3dPoints(const Face3d *slave, PetscInt nm, const Face3d master[], const Face3dRule *rule, PetscInt *np, Segment3dPoint **pts)
{
  PointList       L = {0, 0, NULL};
  PetscInt        ns, nsm;
  const PetscInt(*sub)[3], (*msub)[3];
  PetscReal      *boxes;

  PetscFunctionBeginUser;
  PetscCheck(nm <= SEGMENT3D_MAX_MASTER, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%" PetscInt_FMT " master faces for one slave face: %d at most", nm, SEGMENT3D_MAX_MASTER);
  PetscCall(PetscMalloc1(6 * nm + 1, &boxes));
  for (PetscInt m = 0; m < nm; ++m) Face3dBox(master[m].type, master[m].x, &boxes[6 * m]);
  Face3dSubTriangles(slave->type, &ns, &sub);
  for (PetscInt t = 0; t < ns; ++t) {
    SubPlane P;
    SubPlaneSetUp(slave, sub[t], &P);
    for (PetscInt m = 0; m < nm; ++m) {
      Face3dSubTriangles(master[m].type, &nsm, &msub);
      for (PetscInt u = 0; u < nsm; ++u) {
        PetscReal a[3], b[3], nu[3], mt2d[6], meta[6], poly[2 * CLIP_MAX_VERTICES], tri[6 * CLIP_MAX_VERTICES];
        PetscInt  npoly, ntri;
        for (PetscInt d = 0; d < 3; ++d) {
          a[d] = master[m].x[3 * msub[u][1] + d] - master[m].x[3 * msub[u][0] + d];
          b[d] = master[m].x[3 * msub[u][2] + d] - master[m].x[3 * msub[u][0] + d];
        }
        Cross3(a, b, nu);
        if (Dot3(nu, &P.e[6]) >= 0) continue; /* not facing the slave */
        for (PetscInt k = 0; k < 3; ++k) {
          PetscReal r[3];
          for (PetscInt d = 0; d < 3; ++d) r[d] = master[m].x[3 * msub[u][k] + d] - P.o[d];
          mt2d[2 * k]     = Dot3(r, &P.e[0]);
          mt2d[2 * k + 1] = Dot3(r, &P.e[3]);
          Face3dNodeXi(master[m].type, msub[u][k], &meta[2 * k]);
        }
        PetscCall(ClipConvex(3, mt2d, 3, P.v2d, &npoly, poly));
        if (npoly < 3) continue;
        if (ClipSignedArea(3, mt2d) < 0) { /* the master's parameters follow its vertices in the plane: keep them anticlockwise too */
          PetscReal t2[6], te[6];
          for (PetscInt k = 0; k < 3; ++k)
            for (PetscInt c = 0; c < 2; ++c) {
              t2[2 * k + c] = mt2d[2 * (2 - k) + c];
              te[2 * k + c] = meta[2 * (2 - k) + c];
            }
          PetscCall(PetscArraycpy(mt2d, t2, 6));
          PetscCall(PetscArraycpy(meta, te, 6));
        }
        ntri = ClipTriangulate(npoly, poly, 1e-14 * ClipSignedArea(3, P.v2d), tri);
        for (PetscInt k = 0; k < ntri; ++k) PetscCall(Segment3dPiecePoints(slave, &P, nm, master, boxes, m, &tri[6 * k], mt2d, meta, rule, &L));
      }
    }
  }
  PetscCall(PetscFree(boxes));
  *np  = L.n;
  *pts = L.p;
  PetscFunctionReturn(0);
}

/* A_j and Q_j (added into A[], Q[]) over the points, their eta updated by
   Newton at the current coordinates (xs the slave's, master[] the
   masters'); Xref the slave's reference face (dS), Adual its weights'
   coefficients. dQ (or NULL): dQ[j ndof + c], ndof = 3 (slave nodes + the
   master faces' nodes in order), slave's dofs first. */
PetscErrorCode Segment3dEvaluate(const Face3d *Xref, const PetscReal xs[], const PetscReal Adual[], PetscInt nm, const Face3d master[], PetscInt np, Segment3dPoint pts[], PetscReal A[], PetscReal Q[], PetscReal dQ[])
{
  const PetscInt ns = Face3dNodes(Xref->type);
  PetscInt       ndof = 3 * ns, off[64];

  PetscFunctionBeginUser;
  PetscCheck(nm <= 64, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%" PetscInt_FMT " master faces for one slave face: 64 at most", nm);
  for (PetscInt m = 0; m < nm; ++m) {
    off[m] = ndof;
    ndof += 3 * Face3dNodes(master[m].type);
  }
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
    Face3dClosestPointOnFace(M->type, M->x, x, SEGMENT3D_IN_TOL, pt->eta, &clamped);
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
