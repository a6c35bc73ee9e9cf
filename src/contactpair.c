/* Two-way penalty contact between curved quadratic surfaces.

   A pair names a surface S_A on body A and S_B on body B. With S_A as slave,

     E_AB(u) = 1/2 k_p int_{S_A} <-g(X)>_+^2 dS,   <z>_+ = max(z, 0),

   where X runs over the slave surface in the reference configuration (dS is its
   reference length: Gauss points on each curved quadratic edge, weights times
   |dX/dxi|) and g is the signed normal gap in the current configuration: the
   slave point x_s = X + u is projected onto the closest point x_m(eta*) of the
   master surface, each master edge being the quadratic curve through its three
   current nodes (not a chord), and g = (x_s - x_m(eta*)) . n(eta*) with n the
   master body's outward unit normal. The pair's energy is (E_AB + E_BA) / 2 and
   the contact pressure at a slave point is p = k_p <-g>_+.

   Master corners. Adjacent quadratic edges meet at a node with a small corner
   (the kink of the finite element displacement: a few 1e-3 rad at h = 0.06).
   A penetrating slave point that crosses the bisector of a corner switches
   normals, so g is only C0 there and its gradient jumps by about force times
   corner angle: Newton then stalls (gradient 1e-7 of its start near 1e6 dofs,
   with hundreds of line-search evaluations). So over a zone of each master
   edge's ends (-contact_blend, a fraction of the edge, default 0.05) the
   edge's end tangent is blended into the mean of its own and its neighbour's
   (MasterShape): the master surface is C1 and g is C1 where it is negative.
   x_m stays linear in the nodal coordinates (seven nodes: the edge's and its
   neighbours' others), so the formulas below hold with M_j over seven nodes.
   The blend moves the surface by at most 4/27 of the zone times the tangent
   jump; a wider blend departs from the quadratic surface the slave points lie
   on (relative L2 error of the hertz profile at h = 0.06: 10.68 % without,
   10.70 % at 0.05, 12.4 % at 0.25, 31 % at 0.5).

   Gradient. At an orthogonal projection x_s - x_m = g n and x_m' . n = 0, so
   the variations of eta* and of n drop out:
     dg = n . (sum_i N_i(xi) du_i - sum_j M_j(eta*) du_j)
   (N slave, M master edge shape functions): this is the exact derivative of g,
   including its dependence on the closest point and the normal. It is
   approximate only where the projection falls on a corner the blend leaves
   (a real corner of the surface, over 30 degrees, or -contact_blend 0).
   dE_AB = -k_p int <-g>_+ dg dS.

   Hessian. d2E_AB = k_p int H(-g) (dg dg + g d2g) dS. The Gauss-Newton part
   alone (-contact_hessian gauss_newton) is symmetric positive semi-definite;
   the term it drops is of the order of the penetration over the edge length,
   but it holds the tangential modes, so that Newton with it converges only
   linearly. -contact_hessian exact adds it; auto (the default, problem.c)
   adds it once the gradient is small. With t = x_m'(eta*), tau = t/|t|, kappa = n . x_m'', D = |t|^2 - g kappa,
   varying the projection condition (x_s - x_m) . t = 0 gives
     d eta = (|t| a . du + g b . du) / D,   a = tau . (du_s - du_m), b = n . du_m'
   (du_m' = sum_j M_j'(eta*) du_j), and with dn = -(n . dt / |t|) tau,
     d2g = -(kappa a a + g b b + |t| (a b + b a)) / D,
   symmetric; it is exact away from edge ends (eta* = +-1, where the
   Gauss-Newton part alone is used).

   Search. Master edges are hashed into square cells by the bounding box of their
   Bezier control polygon, inflated by the cell size; the (cell, edge) keys are
   sorted (n_m log n_m) and each slave point finds its candidates by binary
   search (log n_m), rebuilt at every evaluation from the current coordinates.

   Parallel. Surfaces are curves, small beside the bodies: every rank holds the
   whole surface (nodes, edges, current coordinates gathered each evaluation),
   integrates the slave edges it owns, and the gradient on surface nodes is
   summed over ranks and added by the rank that owns each node. */
#include <petscviewerhdf5.h>
#include "contactpair.h"

#define CP_MAX_PAIRS 4

typedef struct {
  PetscInt   body, tag;
  char       group[CONTACT_NAME_LEN];
  PetscInt   nn, ne;      /* surface nodes and edges (whole surface, every rank) */
  PetscInt  *enodes;      /* [ne][3]: nodes at eta = -1, +1, 0 */
  PetscReal *esign;       /* [ne] +-1 so that (t_y, -t_x) * esign is outward */
  PetscReal *s0, *edir, *elen; /* arc position of the walk entering the edge, direction, length */
  PetscInt  *nodeId;      /* [nn] global node number, sorted */
  PetscReal *X, *x, *g;   /* [nn][2] reference, current coordinates, gradient */
  PetscInt  *big;         /* [nn][2] index in the joined vector, -1 if constrained */
  PetscBool *endNode;     /* [nn] node on a single edge: an end of the surface */
  PetscInt  *mnodes;      /* [ne][7] as master: own nodes (eta = -1, +1, 0), the other nodes of the neighbour at eta = -1, at +1 */
  PetscReal *mcorr;       /* [ne][2][7] end-tangent corrections at eta = -1, +1 over those nodes */
  PetscReal  blend;       /* W: width in eta of the blend zone at each end (0: none) */
  PetscInt   nloc, *locNode, *locOff; /* owned node points: surface node, local offset */
  PetscInt   nown, *ownEdges;          /* edges this rank integrates as slave */
  /* search structure over this surface as master */
  PetscInt   nkeys, *keys, *kedge, nx, ny;
  PetscReal  lo[2], cell, reach;
  PetscReal (*bb)[4];     /* [ne] bounding box of each edge: xmin, ymin, xmax, ymax */
  PetscInt  *stamp, query; /* [ne] last query that projected on the edge */
  /* results of the last evaluation with this surface as slave (owned points) */
  PetscInt   nq;
  PetscReal *qdata;       /* [nq][8]: s, X, Y, x, y, gap, pressure, weight */
  PetscReal  force[2];    /* contact force on this surface's body */
  /* report (rank 0 after ContactPairsReport) */
  PetscInt   nprof;
  PetscReal *prof;        /* [nprof][8] sorted by s */
  PetscReal  pmax, a, am, l2err, sc, ptotal; /* am: half-width from the second moment */
} Surface;

typedef struct {
  char      name[CONTACT_NAME_LEN];
  Surface   S[2];
  PetscReal kp, kpScene; /* penalty in use (continuation), the scene's */
  PetscInt  nqp;          /* Gauss points per slave edge */
  PetscReal xi[8], wxi[8];
  PetscBool hertz, mirror; /* mirror: the scene is the half y >= mirrorY of a symmetric model */
  PetscBool exactHessian; /* add the g d2g term to the Gauss-Newton Hessian */
  PetscReal radii[2], Estar, Rstar, mirrorY;
  PetscReal maxPen, P, hertzA, hertzPmax, femPmax, femA, femAm, l2err;
  PetscReal force[2];
  PetscBool reported;
} ContactPair;

static PetscLogEvent CP_EnergyGrad, CP_Search, CP_Hessian;

static inline void EdgeShape(PetscReal e, PetscReal N[3], PetscReal dN[3])
{
  N[0]  = 0.5 * e * (e - 1.0);
  N[1]  = 0.5 * e * (e + 1.0);
  N[2]  = 1.0 - e * e;
  dN[0] = e - 0.5;
  dN[1] = e + 0.5;
  dN[2] = -2.0 * e;
}

static inline void EdgeEval(const PetscReal *x, const PetscInt *en, PetscReal e, PetscReal p[2], PetscReal t[2])
{
  PetscReal N[3], dN[3];

  EdgeShape(e, N, dN);
  p[0] = p[1] = t[0] = t[1] = 0.0;
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt d = 0; d < 2; ++d) {
      p[d] += N[i] * x[2 * en[i] + d];
      t[d] += dN[i] * x[2 * en[i] + d];
    }
}

/* Master edge e: the quadratic edge plus, in a zone of width W (in eta) at
   each end joined to a neighbour, a cubic blend psi(s) = s (1 - s/W)^2 (s the
   distance in eta from the end) times the correction that turns the edge's
   end tangent into the mean of its own and the neighbour's; psi(0) = 0,
   psi'(0) = 1, psi(W) = psi'(W) = 0. Linear in the seven nodes' coordinates:
   x_m(eta) = sum_j M_j(eta) x_j. */
static inline void MasterShape(const Surface *M, PetscInt e, PetscReal eta, PetscReal N[7], PetscReal dN[7], PetscReal d2N[7])
{
  const PetscReal  W = M->blend, *A = &M->mcorr[14 * e], *B = A + 7;
  const PetscReal  sa = eta + 1.0, sb = 1.0 - eta;

  EdgeShape(eta, N, dN);
  d2N[0] = d2N[1] = 1.0;
  d2N[2] = -2.0;
  for (PetscInt j = 3; j < 7; ++j) N[j] = dN[j] = d2N[j] = 0.0;
  if (W > 0 && sa < W) {
    const PetscReal r = 1.0 - sa / W, psi = sa * r * r, dpsi = r * (1.0 - 3.0 * sa / W), d2psi = (6.0 * sa / W - 4.0) / W;
    for (PetscInt j = 0; j < 7; ++j) {
      N[j] += psi * A[j];
      dN[j] += dpsi * A[j];
      d2N[j] += d2psi * A[j];
    }
  }
  if (W > 0 && sb < W) { /* psi_b(eta) = -psi(1 - eta) */
    const PetscReal r = 1.0 - sb / W, psi = sb * r * r, dpsi = r * (1.0 - 3.0 * sb / W), d2psi = (6.0 * sb / W - 4.0) / W;
    for (PetscInt j = 0; j < 7; ++j) {
      N[j] -= psi * B[j];
      dN[j] += dpsi * B[j];
      d2N[j] -= d2psi * B[j];
    }
  }
}

/* Point, tangent and second derivative of master edge e from its shape
   functions at some eta. */
static inline void MasterCombine(const Surface *M, PetscInt e, const PetscReal N[7], const PetscReal dN[7], const PetscReal d2N[7], PetscReal p[2], PetscReal t[2], PetscReal tpp[2])
{
  const PetscInt *mn = &M->mnodes[7 * e];

  p[0] = p[1] = t[0] = t[1] = tpp[0] = tpp[1] = 0.0;
  for (PetscInt j = 0; j < 7; ++j)
    for (PetscInt d = 0; d < 2; ++d) {
      p[d] += N[j] * M->x[2 * mn[j] + d];
      t[d] += dN[j] * M->x[2 * mn[j] + d];
      tpp[d] += d2N[j] * M->x[2 * mn[j] + d];
    }
}

/* Point, tangent and second derivative of master edge e at eta. */
static inline void MasterEval(const Surface *M, PetscInt e, PetscReal eta, PetscReal p[2], PetscReal t[2], PetscReal tpp[2])
{
  PetscReal N[7], dN[7], d2N[7];

  MasterShape(M, e, eta, N, dN, d2N);
  MasterCombine(M, e, N, dN, d2N, p, t, tpp);
}

/* Closest point on master edge e: Newton on f(eta) = |x(eta) - p|^2 / 2 from
   the best of five samples, eta kept in [-1, 1]. Returns eta and the squared
   distance. */
static void MasterProject(const Surface *M, PetscInt ed, const PetscReal p[2], PetscReal *eta, PetscReal *dist2)
{
  PetscReal best = PETSC_MAX_REAL, e = 0.0, q[2], t[2], xpp[2];

  for (PetscInt k = 0; k < 5; ++k) {
    const PetscReal ek = -1.0 + 0.5 * k;
    MasterEval(M, ed, ek, q, t, xpp);
    const PetscReal d2 = PetscSqr(q[0] - p[0]) + PetscSqr(q[1] - p[1]);
    if (d2 < best) {
      best = d2;
      e    = ek;
    }
  }
  for (PetscInt it = 0; it < 30; ++it) {
    PetscReal fp, fpp, de;
    MasterEval(M, ed, e, q, t, xpp);
    fp     = (q[0] - p[0]) * t[0] + (q[1] - p[1]) * t[1];
    fpp    = t[0] * t[0] + t[1] * t[1] + (q[0] - p[0]) * xpp[0] + (q[1] - p[1]) * xpp[1];
    if (fpp <= 0) fpp = t[0] * t[0] + t[1] * t[1];
    de = -fp / fpp;
    e  = PetscMax(-1.0, PetscMin(1.0, e + de));
    if (PetscAbsReal(de) < 1e-15) break;
  }
  MasterEval(M, ed, e, q, t, xpp);
  *eta   = e;
  *dist2 = PetscSqr(q[0] - p[0]) + PetscSqr(q[1] - p[1]);
}

static PetscErrorCode SurfaceBuildSearch(Surface *M)
{
  PetscReal hi[2], ext = 0.0;
  PetscReal (*bb)[4];
  PetscInt  n = 0;

  PetscFunctionBeginUser;
  if (!M->bb) PetscCall(PetscCalloc2(M->ne, &M->bb, M->ne, &M->stamp));
  bb       = M->bb;
  M->lo[0] = M->lo[1] = PETSC_MAX_REAL;
  hi[0] = hi[1] = -PETSC_MAX_REAL;
  for (PetscInt e = 0; e < M->ne; ++e) {
    const PetscInt *en = &M->enodes[3 * e], *mn = &M->mnodes[7 * e];
    for (PetscInt d = 0; d < 2; ++d) {
      const PetscReal a = M->x[2 * en[0] + d], b = M->x[2 * en[1] + d], c = 2.0 * M->x[2 * en[2] + d] - 0.5 * (a + b);
      PetscReal       ca = 0.0, cb = 0.0, grow;
      for (PetscInt j = 0; j < 7; ++j) {
        ca += M->mcorr[14 * e + j] * M->x[2 * mn[j] + d];
        cb += M->mcorr[14 * e + 7 + j] * M->x[2 * mn[j] + d];
      }
      grow         = 4.0 * M->blend / 27.0 * (PetscAbsReal(ca) + PetscAbsReal(cb)); /* max |psi| = 4 W / 27 */
      bb[e][d]     = PetscMin(a, PetscMin(b, c)) - grow;
      bb[e][2 + d] = PetscMax(a, PetscMax(b, c)) + grow;
      ext          = PetscMax(ext, bb[e][2 + d] - bb[e][d]);
      M->lo[d]     = PetscMin(M->lo[d], bb[e][d]);
      hi[d]        = PetscMax(hi[d], bb[e][2 + d]);
    }
  }
  /* cells no smaller than the largest edge, and at most 4096 per direction */
  M->cell = PetscMax(ext, PetscMax(hi[0] - M->lo[0], hi[1] - M->lo[1]) / 4096.0);
  if (M->cell <= 0) M->cell = 1.0;
  /* how far from the surface a slave point is still matched: a tenth of the
     surface's extent, enough for any penetration a solver iterate makes */
  M->reach = PetscMax(M->cell, 0.1 * PetscMax(hi[0] - M->lo[0], hi[1] - M->lo[1]));
  M->lo[0] -= M->cell;
  M->lo[1] -= M->cell;
  M->nx = (PetscInt)((hi[0] - M->lo[0]) / M->cell) + 2;
  M->ny = (PetscInt)((hi[1] - M->lo[1]) / M->cell) + 2;
  for (PetscInt pass = 0; pass < 2; ++pass) {
    n = 0;
    for (PetscInt e = 0; e < M->ne; ++e) {
      const PetscInt i0 = (PetscInt)((bb[e][0] - M->cell - M->lo[0]) / M->cell), i1 = (PetscInt)((bb[e][2] + M->cell - M->lo[0]) / M->cell);
      const PetscInt j0 = (PetscInt)((bb[e][1] - M->cell - M->lo[1]) / M->cell), j1 = (PetscInt)((bb[e][3] + M->cell - M->lo[1]) / M->cell);
      for (PetscInt i = PetscMax(i0, 0); i <= PetscMin(i1, M->nx - 1); ++i)
        for (PetscInt j = PetscMax(j0, 0); j <= PetscMin(j1, M->ny - 1); ++j) {
          if (pass) {
            M->keys[n]  = i * M->ny + j;
            M->kedge[n] = e;
          }
          n++;
        }
    }
    if (!pass) {
      if (n > M->nkeys) {
        PetscCall(PetscFree2(M->keys, M->kedge));
        PetscCall(PetscMalloc2(n, &M->keys, n, &M->kedge));
      }
      M->nkeys = n;
    }
  }
  M->nkeys = n;
  PetscCall(PetscSortIntWithArray(n, M->keys, M->kedge));
  PetscFunctionReturn(0);
}

/* Candidates of one cell: the closest one updates (best, edge, eta). An edge is
   projected once per query, and not at all when its bounding box is already
   farther than the best distance found. */
static void SurfaceSearchCell(Surface *M, PetscInt i, PetscInt j, const PetscReal p[2], PetscReal *best, PetscInt *edge, PetscReal *eta)
{
  PetscInt key, lo = 0, hi = M->nkeys;

  if (i < 0 || j < 0 || i >= M->nx || j >= M->ny) return;
  key = i * M->ny + j;
  while (lo < hi) {
    const PetscInt mid = (lo + hi) / 2;
    if (M->keys[mid] < key) lo = mid + 1;
    else hi = mid;
  }
  for (PetscInt k = lo; k < M->nkeys && M->keys[k] == key; ++k) {
    const PetscInt   ke = M->kedge[k];
    const PetscReal *b  = M->bb[ke];
    const PetscReal  dx = PetscMax(0.0, PetscMax(b[0] - p[0], p[0] - b[2])), dy = PetscMax(0.0, PetscMax(b[1] - p[1], p[1] - b[3]));
    PetscReal        e, d2;
    if (M->stamp[ke] == M->query || dx * dx + dy * dy > *best) continue;
    M->stamp[ke] = M->query;
    MasterProject(M, ke, p, &e, &d2);
    if (d2 < *best) {
      *best = d2;
      *edge = M->kedge[k];
      *eta  = e;
    }
  }
}

/* Closest master edge to p: the candidates of p's cell, then of rings of cells
   around it until some are found (plus one more ring, which may hold a closer
   edge), up to M->reach; *edge = -1 if none. Deeply penetrated points thus keep
   a gap, and the energy stays continuous. */
static void SurfaceFindClosest(Surface *M, const PetscReal p[2], PetscInt *edge, PetscReal *eta)
{
  const PetscInt i = (PetscInt)PetscFloorReal((p[0] - M->lo[0]) / M->cell), j = (PetscInt)PetscFloorReal((p[1] - M->lo[1]) / M->cell);
  const PetscInt rmax = (PetscInt)(M->reach / M->cell) + 1;
  PetscReal      best = PETSC_MAX_REAL;
  PetscInt       found = -1;

  *edge = -1;
  M->query++;
  if (i < -rmax || j < -rmax || i >= M->nx + rmax || j >= M->ny + rmax) return;
  for (PetscInt r = 0; r <= rmax && (found < 0 || r <= found + 1); ++r) {
    for (PetscInt a = -r; a <= r; ++a) {
      SurfaceSearchCell(M, i + a, j - r, p, &best, edge, eta);
      if (r) SurfaceSearchCell(M, i + a, j + r, p, &best, edge, eta);
    }
    for (PetscInt b = -r + 1; b <= r - 1; ++b) {
      SurfaceSearchCell(M, i - r, j + b, p, &best, edge, eta);
      SurfaceSearchCell(M, i + r, j + b, p, &best, edge, eta);
    }
    if (found < 0 && *edge >= 0) found = r;
  }
}

/* Gathers the current coordinates x = X + u of the surface nodes on every rank. */
static PetscErrorCode SurfaceUpdateCoordinates(Surface *S, Body b)
{
  const PetscScalar *u;
  PetscReal         *du;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(2 * S->nn, &du));
  PetscCall(VecGetArrayRead(b->Xl, &u));
  for (PetscInt k = 0; k < S->nloc; ++k) {
    du[2 * S->locNode[k]]     = PetscRealPart(u[S->locOff[k]]);
    du[2 * S->locNode[k] + 1] = PetscRealPart(u[S->locOff[k] + 1]);
  }
  PetscCall(VecRestoreArrayRead(b->Xl, &u));
  PetscCall(MPIU_Allreduce(du, S->x, 2 * S->nn, MPIU_REAL, MPIU_SUM, b->comm));
  for (PetscInt k = 0; k < 2 * S->nn; ++k) S->x[k] += S->X[k];
  PetscCall(PetscFree(du));
  PetscFunctionReturn(0);
}

/* Sums the surface gradient over ranks and adds it where the node is owned. */
static PetscErrorCode SurfaceAddGradient(Surface *S, Body b)
{
  PetscScalar *g;
  PetscReal   *sum;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(2 * S->nn, &sum));
  PetscCall(MPIU_Allreduce(S->g, sum, 2 * S->nn, MPIU_REAL, MPIU_SUM, b->comm));
  PetscCall(VecGetArray(b->Gl, &g));
  for (PetscInt k = 0; k < S->nloc; ++k) {
    g[S->locOff[k]] += sum[2 * S->locNode[k]];
    g[S->locOff[k] + 1] += sum[2 * S->locNode[k] + 1];
  }
  PetscCall(VecRestoreArray(b->Gl, &g));
  PetscCall(PetscFree(sum));
  PetscFunctionReturn(0);
}

/* Arc position (reference length) at parameter xi of edge e, along the walk. */
static PetscReal EdgeArc(const Surface *S, PetscInt e, PetscReal xi, const PetscReal gx[], const PetscReal gw[], PetscInt ng)
{
  PetscReal part = 0.0;

  for (PetscInt q = 0; q < ng; ++q) {
    const PetscReal h = 0.5 * (xi + 1.0), eta = -1.0 + h * (gx[q] + 1.0);
    PetscReal       p[2], t[2];
    EdgeEval(S->X, &S->enodes[3 * e], eta, p, t);
    part += gw[q] * h * PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
  }
  return S->edir[e] > 0 ? S->s0[e] + part : S->s0[e] + S->elen[e] - part;
}

/* One-sided term: slave S against master M, weight c (1/2 for two-way), adds
   to the slave and master gradient arrays; records the slave points. */
static PetscErrorCode PairSlaveEnergyGradient(ContactPair *cp, Surface *S, Surface *M, PetscReal c, PetscReal *energy, Mat H)
{
  PetscReal e = 0.0;

  PetscFunctionBeginUser;
  S->nq = 0;
  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt  se = S->ownEdges[k];
    const PetscInt *sn = &S->enodes[3 * se];
    for (PetscInt q = 0; q < cp->nqp; ++q) {
      PetscReal N[3], dN[3], xs[2], ts[2], w, eta = 0.0, xm[2], tm[2], xpp[2], M7[7], dM7[7], d2M7[7], n[2], tn, gap, pen;
      PetscInt  me;
      PetscReal *rec = &S->qdata[8 * S->nq++]; /* s, X, Y and weight set in SurfaceSetUpSlavePoints */

      EdgeShape(cp->xi[q], N, dN);
      EdgeEval(S->x, sn, cp->xi[q], xs, ts);
      w      = rec[7];
      rec[3] = xs[0];
      rec[4] = xs[1];
      rec[5] = PETSC_INFINITY;
      rec[6] = 0.0;
      SurfaceFindClosest(M, xs, &me, &eta);
      if (me < 0) continue;
      {
        const PetscInt *mn = &M->mnodes[7 * me];
        /* beyond an end of the master surface: no contact */
        if ((eta <= -1.0 && M->endNode[mn[0]]) || (eta >= 1.0 && M->endNode[mn[1]])) continue;
        MasterShape(M, me, eta, M7, dM7, d2M7); /* once: the point, normal and derivatives below */
        MasterCombine(M, me, M7, dM7, d2M7, xm, tm, xpp);
        tn   = PetscSqrtReal(tm[0] * tm[0] + tm[1] * tm[1]);
        n[0] = M->esign[me] * tm[1] / tn;
        n[1] = -M->esign[me] * tm[0] / tn;
        gap  = (xs[0] - xm[0]) * n[0] + (xs[1] - xm[1]) * n[1];
        rec[5] = gap;
        if (gap >= 0.0) continue;
        pen    = -gap;
        rec[6] = cp->kp * pen;
        e += c * 0.5 * cp->kp * w * pen * pen;
        cp->maxPen = PetscMax(cp->maxPen, pen);
        {
          const PetscReal f = c * cp->kp * w * pen;
          if (!H) {
            for (PetscInt i = 0; i < 3; ++i)
              for (PetscInt d = 0; d < 2; ++d) S->g[2 * sn[i] + d] -= f * N[i] * n[d];
            for (PetscInt j = 0; j < 7; ++j)
              for (PetscInt d = 0; d < 2; ++d) M->g[2 * mn[j] + d] += f * M7[j] * n[d];
            S->force[0] += f * n[0];
            S->force[1] += f * n[1];
            M->force[0] -= f * n[0];
            M->force[1] -= f * n[1];
          } else {
            PetscInt    idx[20];
            PetscReal   dg[20];
            PetscScalar K[400];
            const PetscReal kw = c * cp->kp * w;
            for (PetscInt d = 0; d < 2; ++d) {
              for (PetscInt i = 0; i < 3; ++i) {
                idx[2 * i + d] = S->big[2 * sn[i] + d];
                dg[2 * i + d]  = N[i] * n[d];
              }
              for (PetscInt j = 0; j < 7; ++j) {
                idx[6 + 2 * j + d] = M->big[2 * mn[j] + d];
                dg[6 + 2 * j + d]  = -M7[j] * n[d];
              }
            }
            for (PetscInt i = 0; i < 20; ++i)
              for (PetscInt j = 0; j < 20; ++j) K[i * 20 + j] = kw * dg[i] * dg[j];
            if (cp->exactHessian && PetscAbsReal(eta) < 1.0) {
              const PetscReal tau[2] = {tm[0] / tn, tm[1] / tn};
              const PetscReal kappa = n[0] * xpp[0] + n[1] * xpp[1], D = tn * tn - gap * kappa;
              PetscReal       a[20], b[20];
              for (PetscInt d = 0; d < 2; ++d) {
                for (PetscInt i = 0; i < 3; ++i) {
                  a[2 * i + d] = N[i] * tau[d];
                  b[2 * i + d] = 0.0;
                }
                for (PetscInt j = 0; j < 7; ++j) {
                  a[6 + 2 * j + d] = -M7[j] * tau[d];
                  b[6 + 2 * j + d] = dM7[j] * n[d];
                }
              }
              for (PetscInt i = 0; i < 20; ++i)
                for (PetscInt j = 0; j < 20; ++j) K[i * 20 + j] -= kw * gap * (kappa * a[i] * a[j] + gap * b[i] * b[j] + tn * (a[i] * b[j] + b[i] * a[j])) / D;
            }
            PetscCall(MatSetValues(H, 20, idx, 20, idx, K, ADD_VALUES));
          }
        }
      }
    }
  }
  *energy += e;
  PetscFunctionReturn(0);
}

static PetscErrorCode PairEnergyGradient(EnergyTerm t, Body bodies[], PetscReal *energy)
{
  ContactPair *cp = (ContactPair *)t->ctx;
  PetscReal    e  = 0.0;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CP_EnergyGrad, 0, 0, 0, 0));
  cp->maxPen = 0.0;
  for (PetscInt s = 0; s < 2; ++s) {
    Surface *S = &cp->S[s];
    PetscCall(SurfaceUpdateCoordinates(S, bodies[S->body]));
    PetscCall(PetscArrayzero(S->g, 2 * S->nn));
    S->force[0] = S->force[1] = 0.0;
  }
  PetscCall(PetscLogEventBegin(CP_Search, 0, 0, 0, 0));
  for (PetscInt s = 0; s < 2; ++s) PetscCall(SurfaceBuildSearch(&cp->S[s]));
  PetscCall(PetscLogEventEnd(CP_Search, 0, 0, 0, 0));
  PetscCall(PairSlaveEnergyGradient(cp, &cp->S[0], &cp->S[1], 0.5, &e, NULL));
  PetscCall(PairSlaveEnergyGradient(cp, &cp->S[1], &cp->S[0], 0.5, &e, NULL));
  for (PetscInt s = 0; s < 2; ++s) PetscCall(SurfaceAddGradient(&cp->S[s], bodies[cp->S[s].body]));
  *energy = e;
  PetscCall(PetscLogEventEnd(CP_EnergyGrad, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode PairHessian(EnergyTerm t, Body bodies[], Mat H)
{
  ContactPair *cp = (ContactPair *)t->ctx;
  PetscReal    e  = 0.0;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CP_Hessian, 0, 0, 0, 0));
  for (PetscInt s = 0; s < 2; ++s) PetscCall(SurfaceUpdateCoordinates(&cp->S[s], bodies[cp->S[s].body]));
  for (PetscInt s = 0; s < 2; ++s) PetscCall(SurfaceBuildSearch(&cp->S[s]));
  PetscCall(PairSlaveEnergyGradient(cp, &cp->S[0], &cp->S[1], 0.5, &e, H));
  PetscCall(PairSlaveEnergyGradient(cp, &cp->S[1], &cp->S[0], 0.5, &e, H));
  PetscCall(PetscLogEventEnd(CP_Hessian, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode SurfaceDestroy(Surface *S)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree3(S->enodes, S->esign, S->s0));
  PetscCall(PetscFree2(S->edir, S->elen));
  PetscCall(PetscFree(S->nodeId));
  PetscCall(PetscFree4(S->X, S->x, S->g, S->big));
  PetscCall(PetscFree(S->endNode));
  PetscCall(PetscFree2(S->mnodes, S->mcorr));
  PetscCall(PetscFree2(S->locNode, S->locOff));
  PetscCall(PetscFree(S->ownEdges));
  PetscCall(PetscFree2(S->keys, S->kedge));
  PetscCall(PetscFree2(S->bb, S->stamp));
  PetscCall(PetscFree(S->qdata));
  PetscCall(PetscFree(S->prof));
  PetscFunctionReturn(0);
}

static PetscErrorCode PairDestroy(EnergyTerm t)
{
  ContactPair *cp = (ContactPair *)t->ctx;

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) PetscCall(SurfaceDestroy(&cp->S[s]));
  PetscCall(PetscFree(cp));
  PetscFunctionReturn(0);
}

static PetscErrorCode PairSetPenaltyFactor(EnergyTerm t, PetscReal f)
{
  ContactPair *cp = (ContactPair *)t->ctx;

  PetscFunctionBeginUser;
  cp->kp = f * cp->kpScene;
  PetscFunctionReturn(0);
}

static PetscErrorCode PairSetHessianExact(EnergyTerm t, PetscBool exact)
{
  ContactPair *cp = (ContactPair *)t->ctx;

  PetscFunctionBeginUser;
  cp->exactHessian = exact;
  PetscFunctionReturn(0);
}

/* The unconstrained dofs of every contact surface (indices in the joined
   vector, sorted, each once): the only rows and columns the contact Hessian
   touches. Surfaces are replicated, so every rank gets the whole set. */
PetscErrorCode ContactPairsGetSurfaceDofs(Problem p, IS *is)
{
  PetscInt  n = 0, *idx;

  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < p->nterms; ++t) {
    ContactPair *cp = (ContactPair *)p->terms[t]->ctx;
    for (PetscInt s = 0; s < 2; ++s) n += 2 * cp->S[s].nn;
  }
  PetscCall(PetscMalloc1(n + 1, &idx));
  n = 0;
  for (PetscInt t = 0; t < p->nterms; ++t) {
    ContactPair *cp = (ContactPair *)p->terms[t]->ctx;
    for (PetscInt s = 0; s < 2; ++s)
      for (PetscInt k = 0; k < 2 * cp->S[s].nn; ++k)
        if (cp->S[s].big[k] >= 0) idx[n++] = cp->S[s].big[k];
  }
  PetscCall(PetscSortRemoveDupsInt(&n, idx));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, idx, PETSC_OWN_POINTER, is));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactPairsCreateFromOptions(Problem p)
{
  char     *names[CP_MAX_PAIRS];
  PetscInt  np = CP_MAX_PAIRS, nq = 4;
  PetscReal kp = -1.0, blend = 0.05;
  PetscBool setkp, disable = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (!CP_EnergyGrad) {
    PetscClassId id;
    PetscCall(PetscClassIdRegister("ContactPair", &id));
    PetscCall(PetscLogEventRegister("ContactEnergyGrad", id, &CP_EnergyGrad));
    PetscCall(PetscLogEventRegister("ContactSearch", id, &CP_Search));
    PetscCall(PetscLogEventRegister("ContactHessian", id, &CP_Hessian));
  }
  PetscOptionsBegin(p->comm, NULL, "Contact options", NULL);
  PetscCall(PetscOptionsStringArray("-contact_pairs", "Contact pair names (see -contact_<pair>_surfaces)", NULL, names, &np, NULL));
  PetscCall(PetscOptionsReal("-contact_penalty", "Penalty k_p of every pair (required with pairs)", NULL, kp, &kp, &setkp));
  PetscCall(PetscOptionsInt("-contact_quadrature_points", "Gauss points per slave edge", NULL, nq, &nq, NULL));
  PetscCall(PetscOptionsReal("-contact_blend", "Fraction of a master edge, at each end, over which its tangent is blended into its neighbour's (0: quadratic edges meeting at corners)", NULL, blend, &blend, NULL));
  PetscCall(PetscOptionsBool("-contact_disable", "Ignore the scene's contact pairs", NULL, disable, &disable, NULL));
  PetscOptionsEnd();
  PetscCheck(blend >= 0 && blend <= 0.5, p->comm, PETSC_ERR_USER_INPUT, "option -contact_blend: must be in [0, 0.5], got %g", (double)blend);
  PetscCheck(nq >= 1 && nq <= 8, p->comm, PETSC_ERR_USER_INPUT, "option -contact_quadrature_points: must be in [1, 8], got %" PetscInt_FMT, nq);
  for (PetscInt i = 0; i < np; ++i) {
    ContactPair *cp;
    EnergyTerm   t;
    char         prefix[2 * CONTACT_NAME_LEN], *surf[2] = {NULL, NULL};
    PetscInt     ns = 2, nr = 2;
    PetscBool    setPair;

    PetscCall(PetscNew(&cp));
    PetscCall(PetscStrncpy(cp->name, names[i], sizeof(cp->name)));
    PetscCall(PetscFree(names[i]));
    cp->kp           = kp;
    cp->nqp          = nq;
    cp->S[0].blend = cp->S[1].blend = 2.0 * blend; /* in eta */
    cp->exactHessian = p->exactHessian;
    PetscCall(PetscDTGaussQuadrature(nq, -1.0, 1.0, cp->xi, cp->wxi));
    PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "contact_%s_", cp->name));
    PetscOptionsBegin(p->comm, prefix, "Contact pair options", NULL);
    PetscCall(PetscOptionsStringArray("-surfaces", "The two surfaces, body:group,body:group", NULL, surf, &ns, &setPair));
    PetscCall(PetscOptionsReal("-penalty", "Penalty k_p of this pair (default -contact_penalty)", NULL, cp->kp, &cp->kp, NULL));
    PetscCall(PetscOptionsRealArray("-hertz_radii", "Radii of the two surfaces for the Hertz comparison (0: flat)", NULL, cp->radii, &nr, &cp->hertz));
    PetscCall(PetscOptionsReal("-mirror_y", "Half model mirrored about the line y = value: the report doubles the force across it and mirrors the profiles", NULL, cp->mirrorY, &cp->mirrorY, &cp->mirror));
    PetscOptionsEnd();
    PetscCheck(setPair && ns == 2, p->comm, PETSC_ERR_USER_INPUT, "option -%ssurfaces: give two surfaces body:group,body:group", prefix);
    PetscCheck(!cp->hertz || nr == 2, p->comm, PETSC_ERR_USER_INPUT, "option -%shertz_radii: give two radii (0 for a flat surface)", prefix);
    PetscCheck(!PetscIsInfOrNanReal(cp->kp) && cp->kp > 0, p->comm, PETSC_ERR_USER_INPUT, "option -%spenalty (or -contact_penalty): must be a finite number > 0, got %g", prefix, (double)cp->kp);
    cp->kpScene = cp->kp;
    for (PetscInt s = 0; s < 2; ++s) {
      char *colon = strchr(surf[s], ':');
      PetscCheck(colon, p->comm, PETSC_ERR_USER_INPUT, "option -%ssurfaces: '%s' is not body:group", prefix, surf[s]);
      *colon            = 0;
      cp->S[s].body     = -1;
      for (PetscInt b = 0; b < p->nbodies; ++b) {
        PetscBool same;
        PetscCall(PetscStrcmp(p->bodies[b]->name, surf[s], &same));
        if (same) cp->S[s].body = b;
      }
      PetscCheck(cp->S[s].body >= 0, p->comm, PETSC_ERR_USER_INPUT, "option -%ssurfaces: no body named '%s'", prefix, surf[s]);
      PetscCall(PetscStrncpy(cp->S[s].group, colon + 1, sizeof(cp->S[s].group)));
      PetscCall(PetscFree(surf[s]));
    }
    for (PetscInt s = 0; s < 2; ++s) PetscCheck(!cp->hertz || (cp->radii[s] >= 0 && !PetscIsInfOrNanReal(cp->radii[s])), p->comm, PETSC_ERR_USER_INPUT, "option -%shertz_radii: radius %g must be >= 0", prefix, (double)cp->radii[s]);
    PetscCheck(!cp->hertz || cp->radii[0] > 0 || cp->radii[1] > 0, p->comm, PETSC_ERR_USER_INPUT, "option -%shertz_radii: at least one surface must be curved", prefix);
    if (disable) { /* read and checked like the others, then dropped */
      PetscCall(PetscFree(cp));
      continue;
    }
    PetscCall(PetscNew(&t));
    PetscCall(PetscStrncpy(t->name, cp->name, sizeof(t->name)));
    t->ctx                  = cp;
    t->couples[cp->S[0].body] = PETSC_TRUE;
    t->couples[cp->S[1].body] = PETSC_TRUE;
    t->energygrad = PairEnergyGradient;
    t->hessian    = PairHessian;
    t->destroy    = PairDestroy;
    t->setpenaltyfactor = PairSetPenaltyFactor;
    t->sethessianexact  = PairSetHessianExact;
    PetscCheck(p->nterms < CONTACT_MAX_BODIES, p->comm, PETSC_ERR_USER_INPUT, "too many contact pairs");
    p->terms[p->nterms++] = t;
  }
  PetscFunctionReturn(0);
}

/* As master, edge e's end tangent at a node it shares with one other edge is
   blended into the mean of the two (see MasterShape), unless the edges meet
   at a real corner (more than 30 degrees in the reference configuration). */
static PetscErrorCode SurfaceSetUpBlend(Surface *S, const PetscInt deg[], const PetscInt adj[], const PetscInt adjStart[])
{
  const PetscReal dNend[2][3] = {{-1.5, -0.5, 2.0}, {0.5, 1.5, -2.0}}; /* dN_{a,b,m} at eta = -1, +1 */

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(7 * S->ne, &S->mnodes, 14 * S->ne, &S->mcorr));
  for (PetscInt e = 0; e < S->ne; ++e) {
    const PetscInt *en = &S->enodes[3 * e];
    PetscInt       *mn = &S->mnodes[7 * e];
    for (PetscInt j = 0; j < 7; ++j) mn[j] = j < 3 ? en[j] : en[0]; /* placeholders: zero weights */
    for (PetscInt j = 0; j < 14; ++j) S->mcorr[14 * e + j] = 0.0;
    for (PetscInt j = 0; j < 2; ++j) {
      const PetscInt v = en[j];
      PetscInt       nb = -1, jn, slot = 3;
      PetscReal      s, te[2] = {0, 0}, tnb[2] = {0, 0}, *C = &S->mcorr[14 * e + 7 * j];
      if (deg[v] != 2) continue;
      for (PetscInt k = adjStart[v]; k < adjStart[v + 1]; ++k)
        if (adj[k] != e) nb = adj[k];
      if (nb < 0) continue;
      jn = S->enodes[3 * nb] == v ? 0 : 1;
      /* both tangents pointing the same way along the surface */
      s = (j == 0) == (jn == 1) ? 1.0 : -1.0;
      for (PetscInt i = 0; i < 3; ++i)
        for (PetscInt d = 0; d < 2; ++d) {
          te[d] += dNend[j][i] * S->X[2 * en[i] + d];
          tnb[d] += s * dNend[jn][i] * S->X[2 * S->enodes[3 * nb + i] + d];
        }
      if (te[0] * tnb[0] + te[1] * tnb[1] < PetscCosReal(PETSC_PI / 6) * PetscSqrtReal((te[0] * te[0] + te[1] * te[1]) * (tnb[0] * tnb[0] + tnb[1] * tnb[1]))) continue;
      /* correction = (s x_nb'(end) - x_e'(end)) / 2 */
      for (PetscInt i = 0; i < 3; ++i) C[i] -= 0.5 * dNend[j][i];
      for (PetscInt i = 0; i < 3; ++i) {
        const PetscInt w = S->enodes[3 * nb + i];
        if (w == v) C[j] += 0.5 * s * dNend[jn][i];
        else {
          mn[3 + 2 * j + (slot - 3)] = w;
          C[3 + 2 * j + (slot - 3)] += 0.5 * s * dNend[jn][i];
          slot++;
        }
      }
    }
  }
  PetscFunctionReturn(0);
}

/* Builds the whole surface on every rank: the owned edges of the physical
   group with their nodes' global numbers, reference coordinates and outward
   normal sign, gathered from all ranks. */
static PetscBool NodeBefore(const Surface *S, PetscInt a, PetscInt b)
{
  const PetscReal tol = 1e-9 * (PetscAbsReal(S->X[2 * a]) + PetscAbsReal(S->X[2 * b]) + 1.0);

  if (PetscAbsReal(S->X[2 * a] - S->X[2 * b]) > tol) return S->X[2 * a] < S->X[2 * b] ? PETSC_TRUE : PETSC_FALSE;
  return S->X[2 * a + 1] < S->X[2 * b + 1] ? PETSC_TRUE : PETSC_FALSE;
}

static PetscErrorCode SurfaceSetUp(Surface *S, Body b, const char pair[])
{
  DMLabel         faces;
  IS              is = NULL;
  PetscSection    s;
  PetscInt        n = 0, *eid, nall, *ids;
  PetscReal      *erl;
  PetscMPIInt     size, *cnt, *disp, cntl;
  const PetscInt *pts = NULL;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(b->comm, &size));
  PetscCall(DMGetLocalSection(b->dm, &s));
  PetscCall(BodyGetPhysicalTag(b, S->group, 1, &S->tag));
  PetscCall(DMGetLabel(b->dm, "Face Sets", &faces));
  if (faces) PetscCall(DMLabelGetStratumIS(faces, S->tag, &is));
  if (is) {
    PetscCall(ISGetLocalSize(is, &n));
    PetscCall(ISGetIndices(is, &pts));
  }
  PetscCall(PetscMalloc2(3 * n + 1, &eid, 7 * n + 1, &erl));
  {
    PetscInt k = 0;
    for (PetscInt i = 0; i < n; ++i) {
      const PetscInt  e = pts[i];
      const PetscInt *cone, *supp;
      PetscInt        nsupp, *cl = NULL, ncl, nodes[3];
      PetscReal       xc[2] = {0, 0}, t[2], nrm[2], cnt2 = 0;

      if (!b->owned[e - b->pStart]) continue;
      PetscCall(DMPlexGetCone(b->dm, e, &cone));
      nodes[0] = cone[0];
      nodes[1] = cone[1];
      nodes[2] = e;
      for (PetscInt j = 0; j < 3; ++j) {
        PetscCall(BodyGetNodeNumber(b, nodes[j], &eid[3 * k + j]));
        erl[7 * k + 2 * j]     = b->xpoint[2 * (nodes[j] - b->pStart)];
        erl[7 * k + 2 * j + 1] = b->xpoint[2 * (nodes[j] - b->pStart) + 1];
      }
      /* outward: away from the centroid of the cell on the edge */
      PetscCall(DMPlexGetSupportSize(b->dm, e, &nsupp));
      PetscCall(DMPlexGetSupport(b->dm, e, &supp));
      PetscCheck(nsupp == 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "contact pair %s: an edge of group '%s' of body %s is not on the boundary", pair, S->group, b->name);
      PetscCall(DMPlexGetTransitiveClosure(b->dm, supp[0], PETSC_TRUE, &ncl, &cl));
      for (PetscInt j = 0; j < ncl; ++j) {
        PetscInt dof;
        PetscCall(PetscSectionGetDof(s, cl[2 * j], &dof));
        if (!dof) continue;
        xc[0] += b->xpoint[2 * (cl[2 * j] - b->pStart)];
        xc[1] += b->xpoint[2 * (cl[2 * j] - b->pStart) + 1];
        cnt2 += 1;
      }
      PetscCall(DMPlexRestoreTransitiveClosure(b->dm, supp[0], PETSC_TRUE, &ncl, &cl));
      t[0]   = erl[7 * k + 2] - erl[7 * k];
      t[1]   = erl[7 * k + 3] - erl[7 * k + 1];
      nrm[0] = t[1];
      nrm[1] = -t[0];
      erl[7 * k + 6] = (nrm[0] * (erl[7 * k + 4] - xc[0] / cnt2) + nrm[1] * (erl[7 * k + 5] - xc[1] / cnt2)) > 0 ? 1.0 : -1.0;
      k++;
    }
    n = k;
  }
  if (is) {
    PetscCall(ISRestoreIndices(is, &pts));
    PetscCall(ISDestroy(&is));
  }
  PetscCall(PetscMalloc2(size, &cnt, size + 1, &disp));
  cntl = (PetscMPIInt)n;
  PetscCallMPI(MPI_Allgather(&cntl, 1, MPI_INT, cnt, 1, MPI_INT, b->comm));
  disp[0] = 0;
  for (PetscMPIInt r = 0; r < size; ++r) disp[r + 1] = disp[r] + cnt[r];
  S->ne = disp[size];
  PetscCheck(S->ne > 0, b->comm, PETSC_ERR_FILE_UNEXPECTED, "contact pair %s: surface '%s' of body %s has no edges", pair, S->group, b->name);
  {
    PetscMPIInt rank;
    PetscInt   *alle;
    PetscReal  *allr;
    PetscMPIInt *c3, *d3, *c7, *d7;
    PetscCallMPI(MPI_Comm_rank(b->comm, &rank));
    PetscCall(PetscMalloc4(size, &c3, size, &d3, size, &c7, size, &d7));
    for (PetscMPIInt r = 0; r < size; ++r) {
      c3[r] = 3 * cnt[r];
      d3[r] = 3 * disp[r];
      c7[r] = 7 * cnt[r];
      d7[r] = 7 * disp[r];
    }
    PetscCall(PetscMalloc2(3 * S->ne, &alle, 7 * S->ne, &allr));
    PetscCallMPI(MPI_Allgatherv(eid, 3 * cntl, MPIU_INT, alle, c3, d3, MPIU_INT, b->comm));
    PetscCallMPI(MPI_Allgatherv(erl, 7 * cntl, MPIU_REAL, allr, c7, d7, MPIU_REAL, b->comm));
    PetscCall(PetscFree4(c3, d3, c7, d7));
    /* surface nodes: sorted unique global numbers */
    nall = 3 * S->ne;
    PetscCall(PetscMalloc1(nall, &ids));
    PetscCall(PetscArraycpy(ids, alle, nall));
    PetscCall(PetscSortRemoveDupsInt(&nall, ids));
    S->nn = nall;
    S->nodeId = ids;
    PetscCall(PetscMalloc3(3 * S->ne, &S->enodes, S->ne, &S->esign, S->ne, &S->s0));
    PetscCall(PetscMalloc2(S->ne, &S->edir, S->ne, &S->elen));
    PetscCall(PetscMalloc4(2 * S->nn, &S->X, 2 * S->nn, &S->x, 2 * S->nn, &S->g, 2 * S->nn, &S->big));
    PetscCall(PetscCalloc1(S->nn, &S->endNode));
    for (PetscInt e = 0; e < S->ne; ++e) {
      for (PetscInt j = 0; j < 3; ++j) {
        PetscInt loc;
        PetscCall(PetscFindInt(alle[3 * e + j], S->nn, S->nodeId, &loc));
        S->enodes[3 * e + j]  = loc;
        S->X[2 * loc]         = allr[7 * e + 2 * j];
        S->X[2 * loc + 1]     = allr[7 * e + 2 * j + 1];
      }
      S->esign[e] = allr[7 * e + 6];
    }
    PetscCall(PetscMalloc1(n + 1, &S->ownEdges));
    S->nown = n;
    for (PetscInt k = 0; k < n; ++k) S->ownEdges[k] = disp[rank] + k;
    PetscCall(PetscFree2(alle, allr));
  }
  PetscCall(PetscFree2(cnt, disp));
  PetscCall(PetscFree2(eid, erl));
  PetscCall(PetscArraycpy(S->x, S->X, 2 * S->nn));
  /* owned local node points on the surface; their indices in the joined vector */
  {
    PetscInt *bigl, k = 0;
    PetscCall(PetscMalloc2(b->pEnd - b->pStart, &S->locNode, b->pEnd - b->pStart, &S->locOff));
    PetscCall(PetscMalloc1(2 * S->nn, &bigl));
    for (PetscInt i = 0; i < 2 * S->nn; ++i) bigl[i] = -2;
    for (PetscInt pt = b->pStart; pt < b->pEnd; ++pt) {
      PetscInt dof, id, loc, off;
      if (!b->owned[pt - b->pStart]) continue;
      PetscCall(PetscSectionGetDof(s, pt, &dof));
      if (!dof) continue;
      PetscCall(BodyGetNodeNumber(b, pt, &id));
      PetscCall(PetscFindInt(id, S->nn, S->nodeId, &loc));
      if (loc < 0) continue;
      PetscCall(PetscSectionGetOffset(s, pt, &off));
      S->locNode[k] = loc;
      S->locOff[k]  = off;
      bigl[2 * loc]     = b->l2b[off];
      bigl[2 * loc + 1] = b->l2b[off + 1];
      k++;
    }
    S->nloc = k;
    PetscCall(MPIU_Allreduce(bigl, S->big, 2 * S->nn, MPIU_INT, MPI_MAX, b->comm));
    PetscCall(PetscFree(bigl));
  }
  /* ends of the surface, and the arc position along a walk over its chains */
  {
    PetscInt *deg, *adj, *adjStart;
    PetscBool *done;
    PetscReal gx[8], gw[8], s0 = 0.0;
    PetscCall(PetscDTGaussQuadrature(8, -1.0, 1.0, gx, gw));
    PetscCall(PetscCalloc3(S->nn, &deg, S->nn + 1, &adjStart, S->ne, &done));
    for (PetscInt e = 0; e < S->ne; ++e) {
      deg[S->enodes[3 * e]]++;
      deg[S->enodes[3 * e + 1]]++;
      S->elen[e] = 0.0;
      for (PetscInt q = 0; q < 8; ++q) {
        PetscReal pq[2], t[2];
        EdgeEval(S->X, &S->enodes[3 * e], gx[q], pq, t);
        S->elen[e] += gw[q] * PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
      }
    }
    for (PetscInt v = 0; v < S->nn; ++v) {
      adjStart[v + 1] = adjStart[v] + deg[v];
      S->endNode[v]   = deg[v] == 1 ? PETSC_TRUE : PETSC_FALSE;
      deg[v]          = 0;
    }
    PetscCall(PetscMalloc1(adjStart[S->nn] + 1, &adj));
    for (PetscInt e = 0; e < S->ne; ++e)
      for (PetscInt j = 0; j < 2; ++j) {
        const PetscInt v = S->enodes[3 * e + j];
        adj[adjStart[v] + deg[v]++] = e;
      }
    PetscCall(SurfaceSetUpBlend(S, deg, adj, adjStart));
    for (;;) {
      PetscInt start = -1, v, e = -1;
      /* start a chain at the unwalked end node of smallest (x, then y)
         reference coordinate, so that the walk does not depend on the
         partition; else at any unwalked edge */
      for (PetscInt k = 0; k < S->ne; ++k) {
        if (done[k]) continue;
        for (PetscInt j = 0; j < 2; ++j) {
          const PetscInt w = S->enodes[3 * k + j];
          if (S->endNode[w] && (start < 0 || NodeBefore(S, w, start))) {
            start = w;
            e     = k;
          }
        }
      }
      for (PetscInt k = 0; k < S->ne && start < 0; ++k)
        if (!done[k]) {
          start = S->enodes[3 * k] < S->enodes[3 * k + 1] ? S->enodes[3 * k] : S->enodes[3 * k + 1];
          e     = k;
        }
      if (start < 0) break;
      v = start;
      while (e >= 0) {
        done[e]    = PETSC_TRUE;
        S->edir[e] = S->enodes[3 * e] == v ? 1.0 : -1.0;
        /* the arc position where the walk enters the edge: at eta = -1 if
           dir > 0, at eta = +1 if dir < 0 (see EdgeArc) */
        S->s0[e]   = s0;
        s0 += S->elen[e];
        v = S->edir[e] > 0 ? S->enodes[3 * e + 1] : S->enodes[3 * e];
        {
          PetscInt next = -1;
          for (PetscInt j = adjStart[v]; j < adjStart[v + 1]; ++j)
            if (!done[adj[j]]) next = adj[j];
          e = next;
        }
      }
    }
    PetscCall(PetscFree3(deg, adjStart, done));
    PetscCall(PetscFree(adj));
  }
  PetscFunctionReturn(0);
}

/* The slave points of the owned edges depend only on the reference geometry:
   their arc position, reference coordinates and weight are set once. */
static PetscErrorCode SurfaceSetUpSlavePoints(Surface *S, const ContactPair *cp)
{
  PetscReal gx[8], gw[8];

  PetscFunctionBeginUser;
  PetscCall(PetscDTGaussQuadrature(8, -1.0, 1.0, gx, gw));
  PetscCall(PetscCalloc1(8 * S->nown * cp->nqp + 8, &S->qdata));
  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt se = S->ownEdges[k];
    for (PetscInt q = 0; q < cp->nqp; ++q) {
      PetscReal *rec = &S->qdata[8 * (k * cp->nqp + q)], X[2], T[2];
      EdgeEval(S->X, &S->enodes[3 * se], cp->xi[q], X, T);
      rec[0] = EdgeArc(S, se, cp->xi[q], gx, gw, 8);
      rec[1] = X[0];
      rec[2] = X[1];
      rec[7] = cp->wxi[q] * PetscSqrtReal(T[0] * T[0] + T[1] * T[1]);
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ContactPairsSetUp(Problem p)
{
  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < p->nterms; ++t) {
    ContactPair *cp = (ContactPair *)p->terms[t]->ctx;
    for (PetscInt s = 0; s < 2; ++s) {
      PetscCall(SurfaceSetUp(&cp->S[s], p->bodies[cp->S[s].body], cp->name));
      PetscCall(SurfaceSetUpSlavePoints(&cp->S[s], cp));
    }
    if (cp->hertz) {
      Body      b0 = p->bodies[cp->S[0].body], b1 = p->bodies[cp->S[1].body];
      PetscReal iR = 0.0;
      cp->Estar = 1.0 / ((1.0 - b0->nu * b0->nu) / b0->E + (1.0 - b1->nu * b1->nu) / b1->E);
      for (PetscInt s = 0; s < 2; ++s)
        if (cp->radii[s] > 0) iR += 1.0 / cp->radii[s];
      cp->Rstar = 1.0 / iR;
    }
  }
  PetscFunctionReturn(0);
}

/* Gathers one slave surface's points on rank 0, sorted by arc position, and
   compares the profile with Hertz: p(s) = pmax sqrt(1 - ((s - sc)/a)^2), with
   sc the pressure centroid. The computed half-width is half the length of the
   zone p > 0, resolved to half the spacing of the slave points. */
static PetscErrorCode SurfaceReport(ContactPair *cp, Surface *S, MPI_Comm comm)
{
  PetscMPIInt rank, size, *cnt, *disp, n8 = (PetscMPIInt)(8 * S->nq);
  PetscReal  *all = NULL;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMalloc2(size, &cnt, size + 1, &disp));
  PetscCallMPI(MPI_Gather(&n8, 1, MPI_INT, cnt, 1, MPI_INT, 0, comm));
  if (!rank) {
    disp[0] = 0;
    for (PetscMPIInt r = 0; r < size; ++r) disp[r + 1] = disp[r] + cnt[r];
    PetscCall(PetscMalloc1(2 * disp[size] + 1, &all));
  }
  PetscCallMPI(MPI_Gatherv(S->qdata, n8, MPIU_REAL, all, cnt, disp, MPIU_REAL, 0, comm));
  if (!rank && cp->mirror && disp[size] > 0) {
    /* the mirror image of every point, about the end of the arc that lies on
       the symmetry line (s = 0 or the surface's length) */
    const PetscInt m = disp[size] / 8;
    PetscInt       lo = 0, hi = 0;
    PetscReal      L = 0.0, scut;
    for (PetscInt e = 0; e < S->ne; ++e) L = PetscMax(L, S->s0[e] + S->elen[e]);
    for (PetscInt i = 1; i < m; ++i) {
      if (all[8 * i] < all[8 * lo]) lo = i;
      if (all[8 * i] > all[8 * hi]) hi = i;
    }
    scut = PetscAbsReal(all[8 * lo + 2] - cp->mirrorY) <= PetscAbsReal(all[8 * hi + 2] - cp->mirrorY) ? 0.0 : L;
    for (PetscInt i = 0; i < m; ++i) {
      PetscReal *r = &all[8 * (m + i)];
      PetscCall(PetscArraycpy(r, &all[8 * i], 8));
      r[0] = 2.0 * scut - r[0];
      r[2] = 2.0 * cp->mirrorY - r[2];
      r[4] = 2.0 * cp->mirrorY - r[4];
    }
    disp[size] *= 2;
  }
  if (!rank) {
    PetscInt   n = disp[size] / 8, *perm, i0 = -1, i1 = -1;
    PetscReal *sv, num = 0, den = 0, err = 0, nrm = 0;
    PetscCall(PetscMalloc2(n + 1, &perm, n + 1, &sv));
    for (PetscInt i = 0; i < n; ++i) {
      perm[i] = i;
      sv[i]   = all[8 * i];
    }
    PetscCall(PetscSortRealWithPermutation(n, sv, perm));
    PetscCall(PetscFree(S->prof));
    PetscCall(PetscMalloc1(8 * n + 8, &S->prof));
    for (PetscInt i = 0; i < n; ++i) PetscCall(PetscArraycpy(&S->prof[8 * i], &all[8 * perm[i]], 8));
    S->nprof  = n;
    S->pmax   = 0.0;
    S->ptotal = 0.0;
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal *r = &S->prof[8 * i];
      S->pmax = PetscMax(S->pmax, r[6]);
      S->ptotal += r[6] * r[7];
      num += r[0] * r[6] * r[7];
      den += r[6] * r[7];
      if (r[6] > 0) {
        if (i0 < 0) i0 = i;
        i1 = i;
      }
    }
    S->sc = den > 0 ? num / den : 0.0;
    /* Hertz's p ~ sqrt(1 - (s/a)^2) has int p s^2 / int p = a^2/4: a half-width
       from the whole profile, not from where its last loaded point happens to be */
    {
      PetscReal m2 = 0.0;
      for (PetscInt i = 0; i < n; ++i) m2 += S->prof[8 * i + 6] * S->prof[8 * i + 7] * PetscSqr(S->prof[8 * i] - S->sc);
      S->am = den > 0 ? 2.0 * PetscSqrtReal(m2 / den) : 0.0;
    }
    /* the zone ends half-way between the outermost loaded point and the next one */
    S->a = 0.0;
    if (i0 >= 0) {
      const PetscReal lo = i0 > 0 ? 0.5 * (S->prof[8 * i0] + S->prof[8 * (i0 - 1)]) : S->prof[8 * i0];
      const PetscReal hi = i1 < n - 1 ? 0.5 * (S->prof[8 * i1] + S->prof[8 * (i1 + 1)]) : S->prof[8 * i1];
      S->a               = 0.5 * (hi - lo);
    }
    if (cp->hertz && cp->hertzA > 0) {
      for (PetscInt i = 0; i < n; ++i) {
        const PetscReal *r = &S->prof[8 * i];
        const PetscReal  z = (r[0] - S->sc) / cp->hertzA;
        const PetscReal  ph = PetscAbsReal(z) < 1 ? cp->hertzPmax * PetscSqrtReal(1 - z * z) : 0.0;
        err += r[7] * PetscSqr(r[6] - ph);
        nrm += r[7] * ph * ph;
      }
      S->l2err = nrm > 0 ? PetscSqrtReal(err / nrm) : PETSC_INFINITY;
    }
    PetscCall(PetscFree2(perm, sv));
    PetscCall(PetscFree(all));
  }
  PetscCall(PetscFree2(cnt, disp));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactPairsReport(Problem p)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  for (PetscInt t = 0; t < p->nterms; ++t) {
    ContactPair *cp = (ContactPair *)p->terms[t]->ctx;
    PetscReal    f[4], pen;

    f[0] = cp->S[0].force[0];
    f[1] = cp->S[0].force[1];
    f[2] = cp->S[1].force[0];
    f[3] = cp->S[1].force[1];
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, f, 4, MPIU_REAL, MPIU_SUM, p->comm));
    PetscCall(MPIU_Allreduce(&cp->maxPen, &pen, 1, MPIU_REAL, MPIU_MAX, p->comm));
    cp->maxPen   = pen;
    cp->force[0] = f[0];
    cp->force[1] = f[1];
    if (cp->mirror) { /* the mirror half doubles the force across the line and cancels along it */
      for (PetscInt k = 0; k < 4; k += 2) {
        f[k] *= 2.0;
        f[k + 1] = 0.0;
      }
    }
    cp->P        = PetscSqrtReal(f[0] * f[0] + f[1] * f[1]);
    if (cp->hertz) {
      cp->hertzA    = PetscSqrtReal(4.0 * cp->P * cp->Rstar / (PETSC_PI * cp->Estar));
      cp->hertzPmax = cp->hertzA > 0 ? 2.0 * cp->P / (PETSC_PI * cp->hertzA) : 0.0;
    }
    for (PetscInt s = 0; s < 2; ++s) PetscCall(SurfaceReport(cp, &cp->S[s], p->comm));
    cp->femPmax  = 0.5 * (cp->S[0].pmax + cp->S[1].pmax);
    cp->femA     = 0.5 * (cp->S[0].a + cp->S[1].a);
    cp->femAm    = 0.5 * (cp->S[0].am + cp->S[1].am);
    cp->l2err    = 0.5 * (cp->S[0].l2err + cp->S[1].l2err);
    cp->reported = PETSC_TRUE;
    PetscCall(PetscPrintf(p->comm, "Contact pair %s (k_p = %g): %s:%s against %s:%s\n", cp->name, (double)cp->kp, p->bodies[cp->S[0].body]->name, cp->S[0].group, p->bodies[cp->S[1].body]->name, cp->S[1].group));
    PetscCall(PetscPrintf(p->comm, "  contact force on %s%s: (%.6e, %.6e), P = %.6e\n", p->bodies[cp->S[0].body]->name, cp->mirror ? " (with its mirror image)" : "", (double)f[0], (double)f[1], (double)cp->P));
    PetscCall(PetscPrintf(p->comm, "  largest penetration %.6e (p_max/k_p = %.6e)\n", (double)cp->maxPen, (double)(cp->femPmax / cp->kp)));
    if (!rank) {
      for (PetscInt s = 0; s < 2; ++s) {
        Surface  *S = &cp->S[s];
        PetscInt  first = -1, last = -1, step;
        for (PetscInt i = 0; i < S->nprof; ++i)
          if (S->prof[8 * i + 6] > 0) {
            if (first < 0) first = i;
            last = i;
          }
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "  pressure on %s:%s (centre s = %.6g):\n", p->bodies[S->body]->name, S->group, (double)S->sc));
        if (first < 0) {
          PetscCall(PetscPrintf(PETSC_COMM_SELF, "    no contact\n"));
          continue;
        }
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "    %12s %12s %12s %12s\n", "s - s_c", "p", cp->hertz ? "p Hertz" : "", "gap"));
        first = PetscMax(0, first - 1);
        last  = PetscMin(S->nprof - 1, last + 1);
        step  = PetscMax(1, (last - first + 1) / 21);
        for (PetscInt i = first; i <= last; i += step) {
          const PetscReal *r = &S->prof[8 * i];
          PetscReal        ph = 0.0;
          if (cp->hertz && cp->hertzA > 0) {
            const PetscReal z = (r[0] - S->sc) / cp->hertzA;
            ph                = PetscAbsReal(z) < 1 ? cp->hertzPmax * PetscSqrtReal(1 - z * z) : 0.0;
          }
          if (cp->hertz) PetscCall(PetscPrintf(PETSC_COMM_SELF, "    %12.5g %12.6g %12.6g %12.4e\n", (double)(r[0] - S->sc), (double)r[6], (double)ph, (double)r[5]));
          else PetscCall(PetscPrintf(PETSC_COMM_SELF, "    %12.5g %12.6g %12s %12.4e\n", (double)(r[0] - S->sc), (double)r[6], "", (double)r[5]));
        }
      }
    }
    if (cp->hertz && !(cp->P > 0)) PetscCall(PetscPrintf(p->comm, "  no contact force: nothing to compare with Hertz\n"));
    else if (cp->hertz) {
      PetscCall(PetscPrintf(p->comm, "  Hertz (E* = %g, R* = %g): a = %.6g, p_max = %.6g\n", (double)cp->Estar, (double)cp->Rstar, (double)cp->hertzA, (double)cp->hertzPmax));
      PetscCall(PetscPrintf(p->comm, "  computed:              a = %.6g (%+.2f %%), p_max = %.6g (%+.2f %%)\n", (double)cp->femA, (double)(100 * (cp->femA / cp->hertzA - 1)), (double)cp->femPmax, (double)(100 * (cp->femPmax / cp->hertzPmax - 1))));
      PetscCall(PetscPrintf(p->comm, "  half-width from the profile's second moment: a = %.6g (%+.2f %%)\n", (double)cp->femAm, (double)(100 * (cp->femAm / cp->hertzA - 1))));
      if (PetscIsInfOrNanReal(cp->l2err)) PetscCall(PetscPrintf(p->comm, "  relative L2 error of the pressure profile: n/a (a surface has no point inside Hertz's zone)\n"));
      else PetscCall(PetscPrintf(p->comm, "  relative L2 error of the pressure profile: %.2f %% (surfaces: %.2f %%, %.2f %%)\n", (double)(100 * cp->l2err), (double)(100 * cp->S[0].l2err), (double)(100 * cp->S[1].l2err)));
    }
  }
  PetscFunctionReturn(0);
}

static void JKV(FILE *fp, const char sep[], const char key[], PetscReal v)
{
  fprintf(fp, "%s\"%s\": ", sep, key);
  ContactJSONReal(fp, v);
}

/* The figures of a pair, each preceded by sep. */
static void PairFiguresJSON(FILE *fp, const ContactPair *cp, const char sep[], const char forceKey[])
{
  JKV(fp, sep, forceKey, cp->P);
  JKV(fp, sep, "max_penetration", cp->maxPen);
  JKV(fp, sep, "fem_pmax", cp->femPmax);
  JKV(fp, sep, "fem_a", cp->femA);
  JKV(fp, sep, "fem_a_moment", cp->femAm);
  if (!cp->hertz) return;
  JKV(fp, sep, "E_star", cp->Estar);
  JKV(fp, sep, "R_star", cp->Rstar);
  JKV(fp, sep, "hertz_a", cp->hertzA);
  JKV(fp, sep, "hertz_pmax", cp->hertzPmax);
  JKV(fp, sep, "pressure_l2_error", cp->l2err);
}

/* Called on rank 0 only: the first pair's figures at top level, then every pair. */
PetscErrorCode ContactPairsWriteJSON(Problem p, FILE *fp)
{
  PetscFunctionBeginUser;
  if (!p->nterms || !((ContactPair *)p->terms[0]->ctx)->reported) PetscFunctionReturn(0);
  PairFiguresJSON(fp, (ContactPair *)p->terms[0]->ctx, ",\n  ", "contact_force");
  fprintf(fp, ",\n  \"contact\": {");
  for (PetscInt t = 0; t < p->nterms; ++t) {
    ContactPair *cp = (ContactPair *)p->terms[t]->ctx;
    fprintf(fp, "%s\n    \"%s\": {\"penalty\": ", t ? "," : "", cp->name);
    ContactJSONReal(fp, cp->kp);
    fprintf(fp, ", \"force\": [");
    ContactJSONReal(fp, cp->force[0]);
    fprintf(fp, ", ");
    ContactJSONReal(fp, cp->force[1]);
    fprintf(fp, "]");
    PairFiguresJSON(fp, cp, ", ", "P");
    fprintf(fp, ", \"surfaces\": [");
    for (PetscInt s = 0; s < 2; ++s) {
      const Surface *S = &cp->S[s];
      fprintf(fp, "%s{\"body\": \"%s\", \"group\": \"%s\", \"edges\": %d", s ? ", " : "", p->bodies[S->body]->name, S->group, (int)S->ne);
      JKV(fp, ", ", "pmax", S->pmax);
      JKV(fp, ", ", "a", S->a);
      JKV(fp, ", ", "a_moment", S->am);
      JKV(fp, ", ", "centre", S->sc);
      JKV(fp, ", ", "pressure_integral", S->ptotal);
      fprintf(fp, ", \"force\": [");
      ContactJSONReal(fp, S->force[0]);
      fprintf(fp, ", ");
      ContactJSONReal(fp, S->force[1]);
      fprintf(fp, "]");
      if (cp->hertz) JKV(fp, ", ", "pressure_l2_error", S->l2err);
      fprintf(fp, "}");
    }
    fprintf(fp, "]}");
  }
  fprintf(fp, "\n  }");
  PetscFunctionReturn(0);
}

/* Per slave surface, /contact/<pair>/<body>_<group>/: s, X (reference), x
   (current), gap, pressure, weight, all from rank 0 (collective). */
PetscErrorCode ContactPairsWriteHDF5(Problem p, PetscViewer v)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  for (PetscInt t = 0; t < p->nterms; ++t) {
    ContactPair *cp = (ContactPair *)p->terms[t]->ctx;
    if (!cp->reported) continue;
    for (PetscInt s = 0; s < 2; ++s) {
      Surface    *S = &cp->S[s];
      char        group[4 * CONTACT_NAME_LEN];
      const char *names[6] = {"s", "X", "x", "gap", "pressure", "weight"};
      const PetscInt cols[6] = {0, 1, 3, 5, 6, 7}, bs[6] = {1, 2, 2, 1, 1, 1};
      PetscInt    n = rank ? 0 : S->nprof;

      PetscCall(PetscSNPrintf(group, sizeof(group), "/contact/%s/%s_%s", cp->name, p->bodies[S->body]->name, S->group));
      PetscCall(PetscViewerHDF5PushGroup(v, group));
      for (PetscInt k = 0; k < 6; ++k) {
        Vec          vec;
        PetscScalar *a;
        PetscCall(VecCreate(p->comm, &vec));
        PetscCall(VecSetSizes(vec, n * bs[k], PETSC_DETERMINE));
        PetscCall(VecSetBlockSize(vec, bs[k]));
        PetscCall(VecSetType(vec, VECSTANDARD));
        PetscCall(PetscObjectSetName((PetscObject)vec, names[k]));
        PetscCall(VecGetArray(vec, &a));
        for (PetscInt i = 0; i < n; ++i)
          for (PetscInt j = 0; j < bs[k]; ++j) a[i * bs[k] + j] = S->prof[8 * i + cols[k] + j];
        PetscCall(VecRestoreArray(vec, &a));
        PetscCall(VecView(vec, v));
        PetscCall(VecDestroy(&vec));
      }
      PetscCall(PetscViewerHDF5WriteAttribute(v, group, "body", PETSC_STRING, p->bodies[S->body]->name));
      PetscCall(PetscViewerHDF5WriteAttribute(v, group, "group", PETSC_STRING, S->group));
      PetscCall(PetscViewerHDF5WriteAttribute(v, group, "centre", PETSC_REAL, &S->sc));
      PetscCall(PetscViewerHDF5PopGroup(v));
    }
    {
      char group[2 * CONTACT_NAME_LEN];
      PetscCall(PetscSNPrintf(group, sizeof(group), "/contact/%s", cp->name));
      PetscCall(PetscViewerHDF5PushGroup(v, group));
      PetscCall(PetscViewerHDF5WriteAttribute(v, group, "penalty", PETSC_REAL, &cp->kp));
      PetscCall(PetscViewerHDF5WriteAttribute(v, group, "P", PETSC_REAL, &cp->P));
      PetscCall(PetscViewerHDF5WriteAttribute(v, group, "max_penetration", PETSC_REAL, &cp->maxPen));
      PetscCall(PetscViewerHDF5WriteAttribute(v, group, "fem_pmax", PETSC_REAL, &cp->femPmax));
      PetscCall(PetscViewerHDF5WriteAttribute(v, group, "fem_a", PETSC_REAL, &cp->femA));
      PetscCall(PetscViewerHDF5WriteAttribute(v, group, "fem_a_moment", PETSC_REAL, &cp->femAm));
      if (cp->hertz) {
        PetscCall(PetscViewerHDF5WriteAttribute(v, group, "E_star", PETSC_REAL, &cp->Estar));
        PetscCall(PetscViewerHDF5WriteAttribute(v, group, "R_star", PETSC_REAL, &cp->Rstar));
        PetscCall(PetscViewerHDF5WriteAttribute(v, group, "hertz_a", PETSC_REAL, &cp->hertzA));
        PetscCall(PetscViewerHDF5WriteAttribute(v, group, "hertz_pmax", PETSC_REAL, &cp->hertzPmax));
        PetscCall(PetscViewerHDF5WriteAttribute(v, group, "pressure_l2_error", PETSC_REAL, &cp->l2err));
      }
      PetscCall(PetscViewerHDF5PopGroup(v));
    }
  }
  PetscFunctionReturn(0);
}
