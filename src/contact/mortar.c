/* Contact formulation "mortar": penalty on nodal weighted gaps, integrated
   segment by segment, one surface as slave: one that ends on the other, else
   the softer body's, else the pair's first (or the first, the second, or
   both averaged as in gpts: -contact_mortar_slave; MortarChooseSlaves).

   With S the slave surface, N_j its quadratic (P2) basis at node j and dS
   the reference length,

     A_j = int_S N_j dS,   g_j = (1/C_j) int_S' N_j g dS,   C_j = int_S' N_j dS,
     E_S = 1/2 k_p sum_j A_j <-g_j>_+^2,    p_j = k_p <-g_j>_+,

   where g is the normal gap of gap.c (closest point on the master surface,
   continuous across the master's nodes, and past the master surface's ends
   that of the body's boundary beyond them, or in a half model the gap to
   its mirror image) and S' the part of the slave surface
   that faces a master edge: all of it, but for an empty master, so C_j = A_j.
   (A quadratic N_j is negative on part of its support; a node whose support
   faced the master over less than half of A_j would be left out.) The pair's energy
   is (E_A + E_B)/2, each surface taking its turn as slave. A uniform gap gives
   g_j = g at every node and the consistent nodal forces of a uniform
   pressure: the formulation passes the contact patch test, where collocation
   at Gauss points (gpts) does not.

   Segments. g is smooth along a slave edge except where the feature of the
   master closest to its points changes (its normal turns, the master shape
   functions change): the inside of an edge, a corner node, or the extension
   past an end. Each slave edge is cut there (MortarSplit). Where the closest
   point passes smoothly through a master node v the cut solves
   (x_s(xi) - x_v) . t = 0, a quadratic in xi: t the common tangent at a
   blended node, the edge's own where it gives way to its end's fan or
   extension. Without the blend (mortar's default) every master node is a
   corner: outside a convex one the closest point stays at the node over a
   fan between the two edges' normal lines, where g is the distance to the
   node (gap.c), and those two lines are cut. Inside a concave corner, or
   behind a master surface that curves more tightly than the point's depth (a
   deeply penetrated iterate), the closest point jumps from one feature to
   another where their distances tie: the piece is cut at that tie, found by
   bisection on the difference of the squared distances. Every piece is
   checked at its Gauss points, and halved where it is not uniform (to 2^-12
   of the edge at most), so that each segment's integrand is smooth. An end
   of a piece where a master feature and its mirror image tie to round-off
   (a slave node on a half model's mirror line, as close to the master's end
   edge as to its image) belongs to either and is not cut there: else
   round-off, choosing one or the other, changes the segments and with them
   the quadrature error from one state to the next, a jump in the energy
   (MortarEndTies). Each
   segment takes a Gauss rule of
   -contact_quadrature_points points (4 by default: degree 7).

   Gradient. Since dg is exact (gap.c) and the integrand is continuous across
   the moving split points,
     dE_S = k_p sum_j A_j <g_j>_- dg_j = int_S' Lambda dg dS,
     Lambda(xi) = k_p sum_j (A_j / C_j) min(g_j, 0) W_j(xi),
   a pointwise term like gpts' with the smooth nodal field Lambda in place of
   k_p g, were the integrals exact. Two passes: the weighted gaps (summed
   over the ranks that share a node), then the gradient.

   The Gauss points move. The integrals are the Gauss rules of the segments,
   Q_j = sum_seg sum_q h w_q F_j(xi_q), xi_q = (l + r)/2 + h x_q, h = (r -
   l)/2 on a segment [l, r], with F_j = W_j g J for int W_j g dS and W_j J
   for C_j (J = dS/dxi; C_j is a Gauss rule too, so it moves with the cuts
   where J is not a polynomial, on a curved slave surface). A cut c at a
   crossing (below) moves with u, and the Gauss points of its two segments
   with it. Of the exact integral, d/dc = W_j J (g_a - g_b) = 0 at c; of the
   rule,
     d/dr sum_q h w_q F(xi_q) = sum_q w_q (F/2 + h gamma_q F'),   gamma_q = (1 + x_q)/2,
   and d/dl alike with -F/2 and gamma_q = (1 - x_q)/2: F(r) to the rule's
   error, which is not zero. At a deep iterate of the reference scene
   (penetration 2.8e-3) it left the gradient 6.8e-5 of its largest entry
   from the energy's and the Hessian's Taylor remainder at 8.5e-5 of |H v|
   (order 1); the sublinear weights, whose cut at mid-edge halves the
   segments, were already exact to order 2. So, with g_j = Q_j / C_j,
     dg_j = G_j / C_j,   G_j = int_S' W_j dg dS + sum_c q_jc dc,
     dE_S = int_S' Lambda dg dS + sum_c s_c dc,   s_c = sum_j Lambda_j q_jc,
   (Lambda_j = k_p A_j min(g_j, 0) / C_j), q_jc = d(Q_j - g_j C_j)/dc by the
   rule above with F = W_j (g - g_j) J (g_j held), and dc = -(dg_a - dg_b)
   / phi' at a crossing (phi = g_a - g_b; ' = d/dxi). The derivatives along
   the slave edge at a point: g' = n_s . x_s' (n_s = dg/dx_s), J' and J''
   of the reference edge, and, for the Hessian, dg' = N_i' n_s on the slave
   rows plus d2g w, g'' = w . d2g w + n_s . x_s'' (w moves every slave node
   of the edge by x_s', which moves the point by x_s'). Other cuts that move
   with u (the normal lines bounding a corner's fan, an end's normal line,
   the line where the ramp past an end ends: MortarSplitRamp) are not
   differentiated so: the gap is C1 across them, so the exact integral has
   no term there, and their rule's error is left out (at the
   solution of the reference scene with the block as slave, whose disc
   master has fans, a finite-difference Hessian of the gradient differs by
   4.6e-9 of its norm, the round-off of the check 1.6e-10).

   Hessian.
     d2E_S = k_p sum_{j: g_j < 0} (A_j / C_j^2) (G_j G_j^T - g_j (G_j K_j^T + K_j G_j^T))
             + int_S' Lambda d2g dS
             + sum_c (V_c dc^T + dc V_c^T + S_c dc dc^T + s_c d2c)
             + sum_(c1, c2) T (dc_1 dc_2^T + dc_2 dc_1^T),
   K_j = dC_j = sum_c k_jc dc (k_jc by the rule with F = W_j J). The third
   sum runs over the crossings c where the closest point passes from master
   edge a to edge b across a node where their normals differ (no blend; a
   tie's cut alike): V_c = sum_j Lambda_j d(q_jc)/du, by the rule with dF =
   Lambda J dg and dF' = (Lambda J)' dg + Lambda J dg'; S_c = ds_c/dc, by
   d2/dr2 = sum_q w_q (gamma_q F' + h gamma_q^2 F'') (d2/dl2 with -gamma_q
   F'); and d2c = -(phi_uu + phi_u' dc^T + dc phi_u'^T + phi'' dc dc^T) /
   phi', phi_uu = d2g_a - d2g_b at c. The last sum runs over the segments
   bounded by two crossings c1 < c2, T = d2E/dc1 dc2 by d2/dl dr = sum_q w_q
   ((gamma_l - gamma_r) F'/2 + h gamma_l gamma_r F''). Were the integrals
   exact, q = k = s = T = 0, V_c = Lambda J (dg_a - dg_b) (the jump of the
   gradient's integrand) and S_c = Lambda J phi', and the crossing's terms
   would be -Lambda J (dg_a - dg_b)(dg_a - dg_b)^T / phi'. The pointwise
   part and the crossings' second-order terms are added with
   -contact_hessian exact or auto; the first couples every dof under the
   support of W_j, so it is assembled node by node, over the node's slave
   edges, by the rank that owns the node (the rank of its first edge along
   the walk). Parallel: the surfaces are whole on every rank, so the slave
   edges are shared out among the ranks in runs of the walk of nearly equal
   cost, an active node costing more (MortarShareEdges), not by the cells'
   partition; a rank builds the blocks of its nodes from the points of the
   last update (of the state where the Hessian is asked: an update at
   unchanged coordinates does nothing), those of another rank's edge
   computed again.

   Nodal forces and the master's pressure. The pair's contact force on node j
   of either surface is F_j = -dE/du_j, the gradient above: on a slave node
   -int_S' Lambda N_j n dS, on a master node +int_S' Lambda M_j(eta*) n dS
   (M_j the master's shape functions at the closest point, n the master's
   outward normal there; Lambda <= 0). At every point the two parts are
   -Lambda n dS (sum_i N_i - sum_j M_j) = 0 (both sets of shape functions
   sum to 1; the blend's corrections to 0), and a crossing's s_c dc sums to
   0 alike (dc is made of dg_a and dg_b), so the forces on the two surfaces
   balance to round-off, one-sided or averaged: E depends only on the
   relative positions x_s - x_m and on the master's tangent, and is unchanged
   by a rigid translation of both. A surface that is not a slave shows the
   slave's pressure transferred to it. Its nodal forces are the consistent
   transfer: a traction -p n_M on the master has the nodal forces F_j =
   -int_M N_j p n_M dS, lumped F_j = -p_j A_j n_j (A_j = int_M N_j dS), but
   p_j = -F_j . n_j / A_j turns the negative parts of N_j near the zone's ends
   into negative pressures and an oscillation the slave's profile does not
   have. So the master's nodal pressure is the slave's, interpolated linearly
   between the slave's nodes at the master node's closest point of the slave,
   per unit of the master's own reference length (the two surfaces' stretches
   at the two points: MortarSlavePressureAt): exact on the patch test, never
   negative; its integral is the normal force to the interpolation's error,
   and the forces themselves are written beside it. Where both surfaces are slaves, each
   shows its own pressure k_p <-g_j>_+, and F_j is the whole pair's force on
   the node (its slave half and its master half, each weighted 1/2). */
#include <petscviewerhdf5.h>
#include "contactterm.h"
#include "friction.h"
#include "edge.h"
#include "gap.h"
#include "options.h"
#include "outputwrite.h"

#define MORTAR_MAX_SEG   64
#define MORTAR_MAX_DEPTH 12
#define MORTAR_TIE_RTOL  1e-12 /* a feature's and its image's squared distances from a point that tie to round-off */

/* A quadrature point of a segment: slave edge, shape functions, weight (with
   the reference length), gap. */
typedef struct {
  PetscInt   se;
  PetscReal  xi, N[3], W[3], wt; /* parameter on the edge, displacement shape functions, weight functions */
  ContactGap G;
} MortarPoint;

/* The weight functions W_j of the nodal gaps on a slave edge: the quadratic
   basis itself, linear hats on the corners (mid-edge nodes unweighted), or
   linear hats on the two halves of the edge (every node, all positive). */
/* Which surfaces act as slave: the softer of the two (the first where
   their moduli tie), the pair's first, its second, or both. */
typedef enum { MORTAR_SLAVE_AUTO, MORTAR_SLAVE_FIRST, MORTAR_SLAVE_SECOND, MORTAR_SLAVE_BOTH } MortarSlave;
static const char *const MortarSlaves[] = {"auto", "first", "second", "both", "MortarSlave", "MORTAR_SLAVE_", NULL};

typedef enum { MORTAR_BASIS_QUADRATIC, MORTAR_BASIS_LINEAR, MORTAR_BASIS_SUBLINEAR, MORTAR_BASIS_DUAL } MortarBasis;
static const char *const MortarBases[] = {"quadratic", "linear", "sublinear", "dual", "MortarBasis", "MORTAR_BASIS_", NULL};

/* dual: psi_i = sum_k A_ik N_k on each edge, A = D M^-1 with M_jk = int N_j N_k dS,
   D = diag(int N_j dS) (biorthogonal: int psi_i N_k dS = delta_ik int N_k dS) */
static inline void MortarWeights(MortarBasis basis, const PetscReal *dual, PetscReal xi, PetscReal W[3])
{
  PetscReal dN[3], N[3];

  switch (basis) {
  case MORTAR_BASIS_DUAL:
    EdgeShape(xi, N, dN);
    for (PetscInt i = 0; i < 3; ++i) W[i] = dual[3 * i] * N[0] + dual[3 * i + 1] * N[1] + dual[3 * i + 2] * N[2];
    break;
  case MORTAR_BASIS_QUADRATIC:
    EdgeShape(xi, W, dN);
    break;
  case MORTAR_BASIS_LINEAR:
    W[0] = 0.5 * (1.0 - xi);
    W[1] = 0.5 * (1.0 + xi);
    W[2] = 0.0;
    break;
  case MORTAR_BASIS_SUBLINEAR:
    W[0] = xi < 0 ? -xi : 0.0;
    W[1] = xi > 0 ? xi : 0.0;
    W[2] = 1.0 - PetscAbsReal(xi);
    break;
  }
}

/* A cut of a slave edge at xi; where the closest point passes there from
   master edge ea to eb across their common node, ea and eb (else -1), and
   whether each is the edge's mirror image (a half model). For a crossing:
   the first points of the pieces left and right of it (pl, pr: indices in
   the array of points, -1 for an empty piece) and their other ends xl, xr. */
typedef struct {
  PetscInt  se, ea, eb;
  PetscReal xi;
  PetscBool ma, mb;
  PetscInt  pl, pr;
  PetscReal xl, xr;
} MortarCut;

typedef struct {
  PetscInt   n, nmax;
  MortarCut *c;
} MortarCutList;

typedef struct {
  PetscReal *A, *cover;    /* [nn] int W_j dS over the surface; int W_j over the part facing a master (summed over ranks) */
  PetscReal *AN;           /* [nn] int N_j dS: the node's weight as a master */
  PetscReal *gw, *gj;      /* [nn] int N_j g dS (summed over ranks), g_j */
  PetscReal *s;            /* [nn] arc position of the node */
  PetscBool *mine;         /* [nn] node owned by this rank: its energy, Hessian block and report row */
  PetscInt  *first;        /* [nn] the node's first edge along the walk: the node goes with it */
  PetscMPIInt *owner;      /* [ne] the rank that integrates the edge as slave */
  PetscReal *weight;       /* [ne] its expected cost, to share the edges out */
  PetscInt  *pbeg, *pend;  /* [ne] the points of an edge of this rank: pts[pbeg, pend) (pbeg -1: another rank's) */
  PetscInt  *nodeEdgeStart, *nodeEdge; /* edges on each node */
  PetscReal *dual;         /* [ne][3][3] coefficients of the dual weights on each edge */
  PetscInt   np, npmax;    /* points of this rank's edges at the current state */
  MortarPoint *pts;
  MortarCutList cross;    /* the node crossings on this rank's edges */
  PetscInt  *cbeg, *cend;  /* [ne] those of an edge of this rank: cross.c[cbeg, cend) */
} MortarSide;

typedef struct {
  ContactTerm b;           /* first: the surfaces, searches, penalty, results */
  MortarSide  side[2];     /* S[s] as slave */
  PetscReal   xq[8], wq[8];
  PetscInt    nq;
  MortarBasis basis;
  PetscInt    slaveChoice; /* -contact_mortar_slave: MORTAR_SLAVE_* */
  PetscBool   slave[2];    /* the surfaces that act as slave */
  PetscReal   c;           /* weight of each one-sided energy: 1 / the number of slaves */
  PetscMPIInt rank, size;
  Friction    fr;          /* Coulomb friction on the slave surface (friction.c), or NULL */
  FrictionPoint *fpts;     /* the slave's points as friction reads them */
  PetscInt    nfmax;
} Mortar;

static PetscLogEvent MORTAR_EnergyGrad, MORTAR_Search, MORTAR_Segments, MORTAR_Hessian, MORTAR_Report;

/* Slave point of edge se at xi: position and reference length element. */
static inline void MortarSlaveEval(const ContactSurface *S, PetscInt se, PetscReal xi, PetscReal xs[2], PetscReal *dS)
{
  PetscReal t[2], X[2], T[2];

  EdgeEval(S->x, &S->enodes[3 * se], xi, xs, t);
  EdgeEval(S->X, &S->enodes[3 * se], xi, X, T);
  *dS = ContactSurfaceMeasure(S, X, T);
}

/* The feature of the master surface closest to a slave point: the inside of
   an edge (its orthogonal projection, or an end clamped at a blended node),
   a corner node (the fan of directions outside a convex corner), or the
   extension past an end of the surface (its lift's quadratic start, the
   ramp, apart: gap.c's g'' jumps where the ramp begins and ends, so each
   is a cut); none where the master is empty. edge: the master edge of the point's gap (for a node, the edge the
   search reports), end: the node's or the extension's end of that edge;
   mirror: the feature is on the master's mirror image (a half model; never
   for a node on the line, its own image). */
typedef enum { REGION_NONE, REGION_EDGE, REGION_NODE, REGION_EXT, REGION_RAMP } MortarRegionKind;
typedef struct {
  MortarRegionKind kind;
  PetscInt         id, edge, end; /* id: the edge (inside, extension) or the node (corner) */
  PetscBool        mirror;
} MortarRegion;

static inline PetscBool MortarRegionSame(MortarRegion a, MortarRegion b)
{
  return (PetscBool)(a.kind == b.kind && a.id == b.id && a.mirror == b.mirror);
}

/* The gaps that MortarPieceUniform computes at a piece's Gauss points, which
   are the points of the piece if it is kept (the same arithmetic from the
   same ends): MortarEdgePoints takes them from here instead of projecting
   the points again. */
#define MORTAR_CACHE 64
typedef struct {
  PetscInt   n;
  PetscReal  xi[MORTAR_CACHE];
  ContactGap G[MORTAR_CACHE];
} MortarGapCache;

/* The gap of point xi of slave edge se, from the cache if it is there. */
static void MortarGapAt(const Mortar *m, PetscInt s, PetscInt se, PetscReal xi, const MortarGapCache *cache, ContactGap *G)
{
  PetscReal xs[2], dS;

  for (PetscInt k = 0; cache && k < cache->n; ++k)
    if (cache->xi[k] == xi) {
      *G = cache->G[k];
      return;
    }
  MortarSlaveEval(&m->b.S[s], se, xi, xs, &dS);
  ContactGapProject(&m->b.S[1 - s], m->b.search[1 - s], xs, G);
}

/* The region of point xi of slave edge se; its gap is kept in cache (if not NULL and not full). */
static MortarRegion MortarRegionAt(const Mortar *m, PetscInt s, PetscInt se, PetscReal xi, MortarGapCache *cache)
{
  const ContactSurface *M = &m->b.S[1 - s];
  ContactGap            G;
  MortarRegion          R = {REGION_NONE, -1, -1, 0, PETSC_FALSE};

  MortarGapAt(m, s, se, xi, cache, &G);
  if (cache && cache->n < MORTAR_CACHE) {
    cache->xi[cache->n]  = xi;
    cache->G[cache->n++] = G;
  }
  if (G.me < 0) return R;
  R.edge   = G.me;
  R.mirror = G.mirror;
  R.end  = G.eta > 0 ? 1 : 0;
  if (G.ext) {
    R.kind = G.ramp ? REGION_RAMP : REGION_EXT;
    R.id   = G.me;
  } else if (G.fan) {
    R.kind = REGION_NODE;
    R.id   = M->enodes[3 * G.me + R.end];
  } else {
    R.kind = REGION_EDGE;
    R.id   = G.me;
  }
  return R;
}

/* Squared distance from point xi of slave edge se to the feature of region R. */
static PetscReal MortarRegionDistance2(const Mortar *m, PetscInt s, PetscInt se, MortarRegion R, PetscReal xi)
{
  const ContactSurface *M = &m->b.S[1 - s];
  PetscReal             xs[2], dS, eta, d2, xv[2], t[2], xpp[2];

  MortarSlaveEval(&m->b.S[s], se, xi, xs, &dS);
  if (R.mirror) xs[1] = ContactSurfaceMirrorY(M, xs[1]); /* the image's distance is the reflected point's */
  switch (R.kind) {
  case REGION_EDGE:
    MasterProject(M, R.id, xs, &eta, &d2);
    return d2;
  case REGION_NODE:
    return PetscSqr(xs[0] - M->x[2 * R.id]) + PetscSqr(xs[1] - M->x[2 * R.id + 1]);
  case REGION_EXT: /* past the end: to the end node, as the search measures it */
  case REGION_RAMP:
    MasterEval(M, R.id, R.end ? 1.0 : -1.0, xv, t, xpp);
    return PetscSqr(xs[0] - xv[0]) + PetscSqr(xs[1] - xv[1]);
  default:
    return PETSC_MAX_REAL;
  }
}

/* The parameter in (a, b) where slave edge se crosses the line through master
   node v (end i of master edge ea, end j of eb) where the closest point
   passes from ea to eb: normal to the mean of the two edges' unit tangents at
   v (the bisector of their normals; the common normal where the blend makes
   them meet smoothly); a - 1 if none. The crossing solves
   (x_s(xi) - x_v) . tau = off, a quadratic in xi, with tau the unit tangents
   of ea and eb at v weighted wa and wb (1, 1: the bisector; 1, 0 or 0, 1: the
   normal line of one edge, a side of the corner's fan, or with off = +-h0 the
   line parallel to it where the ramp past an end of the surface ends).
   mirror: the edges are the master's mirror image, whose line the reflected
   slave edge crosses. */
static PetscReal MortarNodeCrossing(const ContactSurface *S, PetscInt se, const ContactSurface *M, PetscInt ea, PetscInt i, PetscInt eb, PetscInt j, PetscReal a, PetscReal b, PetscReal wa, PetscReal wb, PetscReal off, PetscBool mirror)
{
  const PetscInt *sn = &S->enodes[3 * se];
  const PetscReal sg = i != j ? 1.0 : -1.0; /* tangents oriented the same way along the surface */
  PetscReal       xv[2], ta[2], tb[2], xpp[2], tv[2], na, nb, c0 = 0, c1 = 0, c2 = 0, r[2];
  PetscInt        nr = 0;

  MasterEval(M, ea, i ? 1.0 : -1.0, xv, ta, xpp);
  MasterEval(M, eb, j ? 1.0 : -1.0, xv, tb, xpp);
  na = PetscSqrtReal(ta[0] * ta[0] + ta[1] * ta[1]);
  nb = PetscSqrtReal(tb[0] * tb[0] + tb[1] * tb[1]);
  for (PetscInt d = 0; d < 2; ++d) tv[d] = wa * ta[d] / na + wb * sg * tb[d] / nb;
  c0 = -off;
  for (PetscInt d = 0; d < 2; ++d) { /* x_s(xi) = x_m + xi (x_b - x_a)/2 + xi^2 ((x_a + x_b)/2 - x_m) */
    PetscReal xa = S->x[2 * sn[0] + d], xb = S->x[2 * sn[1] + d], xm = S->x[2 * sn[2] + d];
    if (mirror && d == 1) {
      xa = ContactSurfaceMirrorY(M, xa);
      xb = ContactSurfaceMirrorY(M, xb);
      xm = ContactSurfaceMirrorY(M, xm);
    }
    c0 += (xm - xv[d]) * tv[d];
    c1 += 0.5 * (xb - xa) * tv[d];
    c2 += (0.5 * (xa + xb) - xm) * tv[d];
  }
  if (PetscAbsReal(c2) <= 1e-14 * PetscAbsReal(c1)) {
    if (c1 != 0) r[nr++] = -c0 / c1;
  } else {
    const PetscReal disc = c1 * c1 - 4 * c2 * c0;
    if (disc >= 0) {
      const PetscReal q = -0.5 * (c1 + (c1 >= 0 ? 1 : -1) * PetscSqrtReal(disc));
      r[nr++]           = q / c2;
      if (q != 0) r[nr++] = c0 / q;
    }
  }
  for (PetscInt k = 0; k < nr; ++k)
    if (r[k] > a && r[k] < b) return r[k];
  return a - 1.0;
}

/* Whether master edges ea and eb share a node: end i of ea and end j of eb. */
static PetscBool MortarSharedEnd(const ContactSurface *M, PetscInt ea, PetscInt eb, PetscInt *i, PetscInt *j)
{
  for (*i = 0; *i < 2; ++*i)
    for (*j = 0; *j < 2; ++*j)
      if (M->enodes[3 * ea + *i] == M->enodes[3 * eb + *j]) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* The tie in (a, b) where the features of regions Ra (closest at a) and Rb
   (closest at b) are at the same distance from the slave point, by bisection
   on the difference of the squared distances (which changes sign there,
   transversally); a - 1 if a and b do not bracket one. */
static PetscReal MortarTie(const Mortar *m, PetscInt s, PetscInt se, PetscReal a, MortarRegion Ra, PetscReal b, MortarRegion Rb)
{
  PetscReal lo = a, hi = b;

  if (MortarRegionDistance2(m, s, se, Ra, a) - MortarRegionDistance2(m, s, se, Rb, a) > 0) return a - 1.0;
  if (MortarRegionDistance2(m, s, se, Ra, b) - MortarRegionDistance2(m, s, se, Rb, b) < 0) return a - 1.0;
  for (PetscInt it = 0; it < 64 && hi - lo > 1e-14; ++it) {
    const PetscReal c = 0.5 * (lo + hi);
    if (MortarRegionDistance2(m, s, se, Ra, c) - MortarRegionDistance2(m, s, se, Rb, c) <= 0) lo = c;
    else hi = c;
  }
  return 0.5 * (lo + hi);
}

/* Where in (a, b) the closest point passes from region Ra to Rb (a - 1 if
   not found), and the master edges of the cut (*ea, *eb; -1 where the gap's
   derivative does not jump there). Smoothly, on a line through a master
   node: from the inside of an edge to the fan of its end node or to the
   extension past its end (the edge's normal line there), from one edge to
   the next across a blended node (the common normal). Otherwise the closest
   point jumps from one feature to the other where their distances tie:
   inside a concave corner, between two corners, or behind a master surface
   that curves more tightly than the point's depth (a deeply penetrated
   iterate). The gap is continuous at a tie and its derivative jumps: the cut
   carries the two edges for the Hessian's crossing term (none next to an
   extension, whose gap ContactGapOnEdge does not give). */
static PetscReal MortarTransition(const Mortar *m, PetscInt s, PetscInt se, PetscReal a, MortarRegion Ra, PetscReal b, MortarRegion Rb, PetscInt *ea, PetscInt *eb, PetscBool *ma, PetscBool *mb)
{
  const ContactSurface *M = &m->b.S[1 - s], *S = &m->b.S[s];
  PetscInt              i, j;

  *ea = *eb = -1;
  *ma = *mb = PETSC_FALSE;
  for (PetscInt k = 0; k < 2; ++k) { /* an edge and its own end's fan or extension, either way round (an end on the mirror line is the image's end too) */
    const MortarRegion E = k ? Rb : Ra, O = k ? Ra : Rb;
    if (E.kind != REGION_EDGE) continue;
    for (PetscInt e = 0; e < 2; ++e) {
      const PetscInt v = M->enodes[3 * E.id + e];
      if ((O.kind == REGION_NODE && O.id == v && (O.mirror == E.mirror || ContactSurfaceCutSide(M, v) != 0)) || ((O.kind == REGION_EXT || O.kind == REGION_RAMP) && O.id == E.id && O.end == e && O.mirror == E.mirror)) return MortarNodeCrossing(S, se, M, E.id, e, E.id, e, a, b, 1.0, 0.0, 0.0, E.mirror);
    }
  }
  if (((Ra.kind == REGION_RAMP && Rb.kind == REGION_EXT) || (Ra.kind == REGION_EXT && Rb.kind == REGION_RAMP)) && Ra.id == Rb.id && Ra.end == Rb.end && Ra.mirror == Rb.mirror) /* the ramp's far end */
    return MortarNodeCrossing(S, se, M, Ra.id, Ra.end, Ra.id, Ra.end, a, b, 1.0, 0.0, (Ra.end ? 1.0 : -1.0) * ContactGapRampLength(M, Ra.id, Ra.end), Ra.mirror);
  if (Ra.kind == REGION_EDGE && Rb.kind == REGION_EDGE && Ra.mirror == Rb.mirror && MortarSharedEnd(M, Ra.id, Rb.id, &i, &j) && ContactGapEndBlended(M, Ra.id, i)) { /* across a blended node */
    *ea = Ra.id;
    *eb = Rb.id;
    *ma = *mb = Ra.mirror;
    return MortarNodeCrossing(S, se, M, Ra.id, i, Rb.id, j, a, b, 1.0, 1.0, 0.0, Ra.mirror);
  }
  if (Ra.kind != REGION_EXT && Rb.kind != REGION_EXT && Ra.kind != REGION_RAMP && Rb.kind != REGION_RAMP) {
    *ea = Ra.edge;
    *eb = Rb.edge;
    *ma = Ra.mirror;
    *mb = Rb.mirror;
  }
  return MortarTie(m, s, se, a, Ra, b, Rb);
}

/* Whether the closest point of slave edge se stays in region R over [a, b],
   checked at the piece's Gauss points (where its integrand is evaluated) and
   its midpoint. */
static PetscBool MortarPieceUniform(const Mortar *m, PetscInt s, PetscInt se, PetscReal a, PetscReal b, MortarRegion R, MortarGapCache *cache)
{
  const PetscReal h = 0.5 * (b - a), c = 0.5 * (a + b);

  if (!MortarRegionSame(MortarRegionAt(m, s, se, c, NULL), R)) return PETSC_FALSE;
  for (PetscInt q = 0; q < m->nq; ++q)
    if (!MortarRegionSame(MortarRegionAt(m, s, se, c + h * m->xq[q], cache), R)) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* Whether regions R and O are a master feature and its mirror image at the
   same distance from point xi of slave edge se, to round-off. A slave node
   on a half model's mirror line is as close to the master's end edge as to
   its image, and round-off picks either: taken as a region of its own, the
   image made MortarSplit halve the edge towards the node to its depth
   limit, so that the edge's weighted gaps came from 20 pieces at one state
   and from one at the next, a jump of their quadrature error (a jump of
   4.5e-9 in g_j and of 1.4e-9 in the energy at k_p = 1e10, h = 0.25, push
   0.01, the line search's failure there). The crossing between the two is pinned to
   the node, which the symmetry holds on the line. Ties between different
   features (a slave node facing a master node) keep their cut: the
   crossing there moves with u and carries the Hessian's crossing term
   (taylor_contact_mortar's remainder levels off at 1.2e-6 without it). */
static PetscBool MortarEndTies(const Mortar *m, PetscInt s, PetscInt se, PetscReal xi, MortarRegion R, MortarRegion O)
{
  PetscReal dR, dO;

  if (!(R.kind == O.kind && R.id == O.id && R.mirror != O.mirror)) return PETSC_FALSE; /* a feature and its image alone */
  dR = MortarRegionDistance2(m, s, se, R, xi);
  dO = MortarRegionDistance2(m, s, se, O, xi);
  return (PetscBool)(PetscAbsReal(dR - dO) <= MORTAR_TIE_RTOL * (dR + dO + PetscSqr(m->b.S[s].elen[se])));
}

/* Where [a, b] of slave edge se passes from the inside of a master edge to
   its extension past an end of the surface (or back) and the lift turns
   there: through the ramp, between the end's normal line and the line h0
   past it (gap.c, ContactGapBeyondEnd), whose g'' jumps at both lines (by
   kappa / h0): a cut at each, so that no Gauss rule straddles either. As
   the cuts move with u their rules' error is left out (g is C1 across
   both), as at a fan's sides; a rule over the ramp and the straight lift
   together, whose integrand is not smooth, missed by about k_p g_j h0 / 2
   per unit of the cut's motion the term of the gradient a moving cut
   carries (6.6e-3 of a corner force of 1.2 on a block slid past its
   partner's end, which stalled Newton there). False where it does not
   apply or the pieces are not uniform. */
static PetscBool MortarSplitRamp(const Mortar *m, PetscInt s, PetscInt se, PetscReal a, MortarRegion Ra, PetscReal b, MortarRegion Rb, PetscInt *ncut, MortarCut cut[], MortarGapCache *cache)
{
  const ContactSurface *M = &m->b.S[1 - s], *S = &m->b.S[s];
  const PetscBool       fromEdge = (PetscBool)(Ra.kind == REGION_EDGE);
  const MortarRegion    E = fromEdge ? Ra : Rb, X = fromEdge ? Rb : Ra;
  MortarRegion          R = X;
  PetscReal             h0, c0, c1, lo, hi;

  if (!((Ra.kind == REGION_EDGE && Rb.kind == REGION_EXT) || (Ra.kind == REGION_EXT && Rb.kind == REGION_EDGE)) || X.id != E.id || X.mirror != E.mirror) return PETSC_FALSE;
  h0 = ContactGapRampLength(M, X.id, X.end);
  if (h0 <= 0) return PETSC_FALSE;
  c0 = MortarNodeCrossing(S, se, M, X.id, X.end, X.id, X.end, a, b, 1.0, 0.0, 0.0, X.mirror);
  c1 = MortarNodeCrossing(S, se, M, X.id, X.end, X.id, X.end, a, b, 1.0, 0.0, (X.end ? 1.0 : -1.0) * h0, X.mirror);
  lo = fromEdge ? c0 : c1;
  hi = fromEdge ? c1 : c0;
  if (!(a < lo && lo < hi && hi < b)) return PETSC_FALSE;
  R.kind = REGION_RAMP;
  if (!MortarPieceUniform(m, s, se, a, lo, Ra, cache) || !MortarPieceUniform(m, s, se, lo, hi, R, cache) || !MortarPieceUniform(m, s, se, hi, b, Rb, cache)) return PETSC_FALSE;
  cut[(*ncut)++] = (MortarCut){se, -1, -1, lo, PETSC_FALSE, PETSC_FALSE, -1, -1, 0.0, 0.0};
  cut[(*ncut)++] = (MortarCut){se, -1, -1, hi, PETSC_FALSE, PETSC_FALSE, -1, -1, 0.0, 0.0};
  return PETSC_TRUE;
}

/* Splits [a, b] of slave edge se, whose ends lie in regions Ra and Rb,
   until the closest point stays in one region over each piece (checked at
   the pieces' Gauss points and midpoints), so that every piece's integrand
   is smooth;
   appends the cuts to cut[]. A transition that is not found, or whose
   pieces are not uniform, is halved (to 2^-12 of the edge at most). */
static void MortarSplit(const Mortar *m, PetscInt s, PetscInt se, PetscReal a, MortarRegion Ra, PetscReal b, MortarRegion Rb, PetscInt depth, PetscInt *ncut, MortarCut cut[], MortarGapCache *cache)
{
  PetscReal    c;
  MortarRegion Rc;

  if (depth >= MORTAR_MAX_DEPTH || *ncut >= MORTAR_MAX_SEG - 2) return;
  if (MortarRegionSame(Ra, Rb)) {
    if (MortarPieceUniform(m, s, se, a, b, Ra, cache)) return;
  } else if (Ra.kind != REGION_NONE && Rb.kind != REGION_NONE) {
    const ContactSurface *M = &m->b.S[1 - s];
    PetscInt              ea, eb, i, j;
    PetscBool             ma, mb;
    /* an end where the two features tie belongs to either: no cut where the piece is the other end's region throughout */
    if (MortarEndTies(m, s, se, a, Ra, Rb) && MortarPieceUniform(m, s, se, a, b, Rb, cache)) return;
    if (MortarEndTies(m, s, se, b, Rb, Ra) && MortarPieceUniform(m, s, se, a, b, Ra, cache)) return;
    if (Ra.kind == REGION_EDGE && Rb.kind == REGION_EDGE && Ra.mirror == Rb.mirror && MortarSharedEnd(M, Ra.id, Rb.id, &i, &j) && !ContactGapEndBlended(M, Ra.id, i)) {
      /* two edges at a corner: its fan, if the bisector lies in it */
      c = MortarNodeCrossing(&m->b.S[s], se, M, Ra.id, i, Rb.id, j, a, b, 1.0, 1.0, 0.0, Ra.mirror);
      if (c > a && c < b) {
        Rc = MortarRegionAt(m, s, se, c, NULL);
        if (Rc.kind == REGION_NODE && Rc.id == M->enodes[3 * Ra.id + i]) {
          MortarSplit(m, s, se, a, Ra, c, Rc, depth + 1, ncut, cut, cache);
          cut[(*ncut)++] = (MortarCut){se, -1, -1, c, PETSC_FALSE, PETSC_FALSE, -1, -1, 0.0, 0.0};
          MortarSplit(m, s, se, c, Rc, b, Rb, depth + 1, ncut, cut, cache);
          return;
        }
      }
    }
    if (MortarSplitRamp(m, s, se, a, Ra, b, Rb, ncut, cut, cache)) return;
    c = MortarTransition(m, s, se, a, Ra, b, Rb, &ea, &eb, &ma, &mb);
    if (c > a && c < b && MortarPieceUniform(m, s, se, a, c, Ra, cache) && MortarPieceUniform(m, s, se, c, b, Rb, cache)) {
      cut[(*ncut)++] = (MortarCut){se, ea, eb, c, ma, mb, -1, -1, 0.0, 0.0};
      return;
    }
  }
  c  = 0.5 * (a + b);
  Rc = MortarRegionAt(m, s, se, c, NULL);
  MortarSplit(m, s, se, a, Ra, c, Rc, depth + 1, ncut, cut, cache);
  cut[(*ncut)++] = (MortarCut){se, -1, -1, c, PETSC_FALSE, PETSC_FALSE, -1, -1, 0.0, 0.0};
  MortarSplit(m, s, se, c, Rc, b, Rb, depth + 1, ncut, cut, cache);
}

/* Appends the quadrature points of slave edge se, segment by segment, and
   (if L) its node crossings to L, with the pieces on either side. */
static PetscErrorCode MortarEdgePoints(Mortar *m, PetscInt s, PetscInt se, PetscInt *np, PetscInt *npmax, MortarPoint **pts, MortarCutList *L)
{
  const ContactSurface *S = &m->b.S[s];
  MortarCut             cut[MORTAR_MAX_SEG + MORTAR_MAX_DEPTH + 4]; /* MortarSplit stops adding at MORTAR_MAX_SEG, then closes its open levels */
  PetscInt              ncut = 0, first[MORTAR_MAX_SEG + MORTAR_MAX_DEPTH + 4];
  MortarGapCache        cache;

  PetscFunctionBeginUser;
  cache.n     = 0;
  cut[ncut++] = (MortarCut){se, -1, -1, -1.0, PETSC_FALSE, PETSC_FALSE, -1, -1, 0.0, 0.0};
  if (m->basis == MORTAR_BASIS_SUBLINEAR) { /* the weights' kink at the mid-edge node */
    const MortarRegion R0 = MortarRegionAt(m, s, se, 0.0, NULL);
    MortarSplit(m, s, se, -1.0, MortarRegionAt(m, s, se, -1.0, NULL), 0.0, R0, 0, &ncut, cut, &cache);
    cut[ncut++] = (MortarCut){se, -1, -1, 0.0, PETSC_FALSE, PETSC_FALSE, -1, -1, 0.0, 0.0};
    MortarSplit(m, s, se, 0.0, R0, 1.0, MortarRegionAt(m, s, se, 1.0, NULL), 0, &ncut, cut, &cache);
  } else MortarSplit(m, s, se, -1.0, MortarRegionAt(m, s, se, -1.0, NULL), 1.0, MortarRegionAt(m, s, se, 1.0, NULL), 0, &ncut, cut, &cache);
  cut[ncut++] = (MortarCut){se, -1, -1, 1.0, PETSC_FALSE, PETSC_FALSE, -1, -1, 0.0, 0.0};
  if (*np + (ncut - 1) * m->nq > *npmax) {
    MortarPoint *grown;
    *npmax = 2 * (*np + (ncut - 1) * m->nq);
    PetscCall(PetscMalloc1(*npmax, &grown));
    PetscCall(PetscArraycpy(grown, *pts, *np));
    PetscCall(PetscFree(*pts));
    *pts = grown;
  }
  for (PetscInt k = 0; k + 1 < ncut; ++k) {
    const PetscReal h = 0.5 * (cut[k + 1].xi - cut[k].xi), c = 0.5 * (cut[k + 1].xi + cut[k].xi);
    first[k] = -1;
    if (h <= 0) continue;
    first[k] = *np;
    for (PetscInt q = 0; q < m->nq; ++q) {
      MortarPoint *P  = &(*pts)[(*np)++];
      PetscReal    xi = c + h * m->xq[q], xs[2], dS, dN[3];
      P->se           = se;
      P->xi           = xi;
      EdgeShape(xi, P->N, dN);
      MortarWeights(m->basis, &m->side[s].dual[9 * se], xi, P->W);
      MortarSlaveEval(S, se, xi, xs, &dS);
      P->wt = h * m->wq[q] * dS;
      MortarGapAt(m, s, se, xi, &cache, &P->G);
    }
  }
  for (PetscInt k = 1; L && k + 1 < ncut; ++k) {
    if (cut[k].ea < 0) continue;
    if (L->n == L->nmax) {
      MortarCut *grown;
      L->nmax = 2 * L->nmax + 16;
      PetscCall(PetscMalloc1(L->nmax, &grown));
      PetscCall(PetscArraycpy(grown, L->c, L->n));
      PetscCall(PetscFree(L->c));
      L->c = grown;
    }
    cut[k].pl       = first[k - 1];
    cut[k].pr       = first[k];
    cut[k].xl       = cut[k - 1].xi;
    cut[k].xr       = cut[k + 1].xi;
    L->c[L->n++]    = cut[k];
  }
  PetscFunctionReturn(0);
}

/* Which rank integrates each edge of side s, and so owns each node (the
   rank of its first edge along the walk): runs of the walk of nearly equal
   cost (surface.c), whatever the mesh partition. An edge costs one (its
   segments, at every evaluation) and MORTAR_NODE_COST for each active node
   that goes with it (its block of the Hessian, the heaviest part of a Newton
   step's contact work), the active set that of the last update. Every rank
   shares out alike (g_j is the same on every rank), and only the sums' order
   depends on it. */
#define MORTAR_NODE_COST 2.0
static void MortarShareEdges(Mortar *m, PetscInt s)
{
  const ContactSurface *S = &m->b.S[s];
  MortarSide           *D = &m->side[s];

  for (PetscInt e = 0; e < S->ne; ++e) D->weight[e] = 1.0;
  for (PetscInt j = 0; j < S->nn && m->slave[s]; ++j)
    if (D->gj[j] < 0) D->weight[D->first[j]] += MORTAR_NODE_COST;
  ContactSurfaceSplitEdges(S, m->size, D->weight, D->owner);
  for (PetscInt j = 0; j < S->nn; ++j) D->mine[j] = (PetscBool)(D->owner[D->first[j]] == m->rank);
}

/* The current coordinates of both surfaces, their search grids, and for each
   side the points of this rank's slave edges and the weighted gaps g_j;
   nothing but the coordinates where they have not changed since the last
   update (a Hessian at the point of the last energy evaluation). */
static PetscErrorCode MortarUpdatePoints(Mortar *m, MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(MORTAR_Segments, 0, 0, 0, 0));
  for (PetscInt s = 0; s < 2; ++s) {
    ContactSurface *S = &m->b.S[s];
    MortarSide     *D = &m->side[s];
    D->np             = 0;
    D->cross.n        = 0;
    MortarShareEdges(m, s);
    if (!m->slave[s]) continue;
    for (PetscInt k = 0; k < S->ne; ++k) {
      const PetscInt e = S->walk[k];
      D->pbeg[e]       = -1;
      D->cbeg[e] = D->cend[e] = 0;
      if (D->owner[e] != m->rank) continue;
      D->pbeg[e] = D->np;
      D->cbeg[e] = D->cross.n;
      PetscCall(MortarEdgePoints(m, s, e, &D->np, &D->npmax, &D->pts, &D->cross));
      D->pend[e] = D->np;
      D->cend[e] = D->cross.n;
    }
    PetscCall(PetscArrayzero(D->gw, 2 * S->nn)); /* gw and cover, adjacent: one reduction */
    for (PetscInt k = 0; k < D->np; ++k) {
      const MortarPoint *P  = &D->pts[k];
      const PetscInt    *sn = &S->enodes[3 * P->se];
      if (P->G.me < 0) continue;
      for (PetscInt i = 0; i < 3; ++i) {
        D->gw[sn[i]] += P->wt * P->W[i] * P->G.gap;
        D->cover[sn[i]] += P->wt * P->W[i];
      }
    }
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, D->gw, 2 * S->nn, MPIU_REAL, MPIU_SUM, comm));
    for (PetscInt j = 0; j < S->nn; ++j) D->gj[j] = D->A[j] > 0 && D->cover[j] > 0.5 * D->A[j] ? D->gw[j] / D->cover[j] : PETSC_INFINITY;
  }
  PetscCall(PetscLogEventEnd(MORTAR_Segments, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarUpdate(Mortar *m, Body bodies[], MPI_Comm comm)
{
  PetscBool changed;

  PetscFunctionBeginUser;
  PetscCall(ContactTermUpdate(&m->b, bodies, MORTAR_Search, &changed));
  if (changed) PetscCall(MortarUpdatePoints(m, comm)); /* else the points and weighted gaps are those of these coordinates (the first update always changes) */
  PetscFunctionReturn(0);
}

/* Lambda at a point of slave edge se: c k_p sum_i (A_i / C_i) min(g_i, 0) W_i. */
static inline PetscReal MortarLambda(const Mortar *m, const MortarSide *D, const PetscInt sn[3], const PetscReal W[3], PetscReal c)
{
  PetscReal L = 0.0;

  for (PetscInt i = 0; i < 3; ++i)
    if (D->gj[sn[i]] < 0) L += D->A[sn[i]] / D->cover[sn[i]] * D->gj[sn[i]] * W[i];
  return c * m->b.kp * L;
}

/* The nodal factors of Lambda on slave edge sn: Lambda_i = c k_p (A_i / C_i)
   min(g_i, 0), and g_i where it is finite (else 0). */
static inline void MortarEdgeLambda(const Mortar *m, const MortarSide *D, const PetscInt sn[3], PetscReal Lam[3], PetscReal g[3])
{
  for (PetscInt i = 0; i < 3; ++i) {
    const PetscReal gj = D->gj[sn[i]];
    Lam[i]             = gj < 0 ? m->c * m->b.kp * D->A[sn[i]] / D->cover[sn[i]] * gj : 0.0;
    g[i]               = PetscIsInfOrNanReal(gj) ? 0.0 : gj;
  }
}

/* The weights' first and second derivatives in xi (MortarWeights). */
static void MortarWeightDerivatives(MortarBasis basis, const PetscReal *dual, PetscReal xi, PetscReal W1[3], PetscReal W2[3])
{
  const PetscReal d2N[3] = {1.0, 1.0, -2.0};
  PetscReal       N[3], dN[3];

  EdgeShape(xi, N, dN);
  for (PetscInt i = 0; i < 3; ++i) W1[i] = W2[i] = 0.0;
  switch (basis) {
  case MORTAR_BASIS_DUAL:
    for (PetscInt i = 0; i < 3; ++i)
      for (PetscInt k = 0; k < 3; ++k) {
        W1[i] += dual[3 * i + k] * dN[k];
        W2[i] += dual[3 * i + k] * d2N[k];
      }
    break;
  case MORTAR_BASIS_QUADRATIC:
    for (PetscInt i = 0; i < 3; ++i) {
      W1[i] = dN[i];
      W2[i] = d2N[i];
    }
    break;
  case MORTAR_BASIS_LINEAR:
    W1[0] = -0.5;
    W1[1] = 0.5;
    break;
  case MORTAR_BASIS_SUBLINEAR: /* its kink at xi = 0 is a fixed cut */
    W1[0] = xi < 0 ? -1.0 : 0.0;
    W1[1] = xi > 0 ? 1.0 : 0.0;
    W1[2] = xi < 0 ? 1.0 : -1.0;
    break;
  }
}

/* What varies along slave edge se at xi: shape functions N and N', weights
   W, W', W'', the current point's x_s' and x_s'', and the reference measure
   J (ContactSurfaceMeasure), J' and J'' (d/dxi). */
typedef struct {
  PetscReal N[3], N1[3], W[3], W1[3], W2[3], x1[2], x2[2], J[3];
} MortarAlong;

static void MortarAlongEval(const Mortar *m, PetscInt s, PetscInt se, PetscReal xi, MortarAlong *A)
{
  const ContactSurface *S      = &m->b.S[s];
  const PetscInt       *sn     = &S->enodes[3 * se];
  const PetscReal       d2N[3] = {1.0, 1.0, -2.0};
  PetscReal             X[2] = {0, 0}, T[2] = {0, 0}, T2[2] = {0, 0}, L, L1, L2;

  EdgeShape(xi, A->N, A->N1);
  MortarWeights(m->basis, &m->side[s].dual[9 * se], xi, A->W);
  MortarWeightDerivatives(m->basis, &m->side[s].dual[9 * se], xi, A->W1, A->W2);
  A->x1[0] = A->x1[1] = A->x2[0] = A->x2[1] = 0.0;
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt d = 0; d < 2; ++d) {
      A->x1[d] += A->N1[i] * S->x[2 * sn[i] + d];
      A->x2[d] += d2N[i] * S->x[2 * sn[i] + d];
      X[d] += A->N[i] * S->X[2 * sn[i] + d];
      T[d] += A->N1[i] * S->X[2 * sn[i] + d];
      T2[d] += d2N[i] * S->X[2 * sn[i] + d];
    }
  L  = PetscSqrtReal(T[0] * T[0] + T[1] * T[1]);
  L1 = (T[0] * T2[0] + T[1] * T2[1]) / L;
  L2 = (T2[0] * T2[0] + T2[1] * T2[1]) / L - L1 * L1 / L;
  if (S->axisym) {
    A->J[0] = 2.0 * PETSC_PI * X[0] * L;
    A->J[1] = 2.0 * PETSC_PI * (T[0] * L + X[0] * L1);
    A->J[2] = 2.0 * PETSC_PI * (T2[0] * L + 2.0 * T[0] * L1 + X[0] * L2);
  } else {
    A->J[0] = L;
    A->J[1] = L1;
    A->J[2] = L2;
  }
}

/* The gap of G along the slave edge (A at its point): g' = n_s . x_s' and,
   if K, d2g (K, over the 20 dofs of ContactGapIndices), g'' = x_s'^T
   (d2g/dx_s^2) x_s' + n_s . x_s'' and dg' = d/dxi of dg: the slave rows
   N_i' n_s plus d2g w, w moving every slave node by x_s' (which moves the
   point by x_s', the shape functions summing to 1). */
static void MortarGapAlong(const ContactGap *G, const MortarAlong *A, PetscReal dg[20], PetscReal *g1, PetscScalar *K, PetscReal *g2, PetscReal dg1[20])
{
  PetscReal w[20];

  ContactGapFirst(G, A->N, dg);
  *g1 = G->ns[0] * A->x1[0] + G->ns[1] * A->x1[1];
  if (!K) return;
  for (PetscInt a = 0; a < 400; ++a) K[a] = 0.0;
  ContactGapAddSecond(G, A->N, 1.0, K);
  for (PetscInt a = 0; a < 20; ++a) w[a] = a < 6 ? A->x1[a % 2] : 0.0;
  *g2 = G->ns[0] * A->x2[0] + G->ns[1] * A->x2[1];
  for (PetscInt a = 0; a < 20; ++a) {
    dg1[a] = a < 6 ? A->N1[a / 2] * G->ns[a % 2] : 0.0;
    for (PetscInt b = 0; b < 20; ++b) dg1[a] += K[a * 20 + b] * w[b];
    *g2 += w[a] * (dg1[a] - (a < 6 ? A->N1[a / 2] * G->ns[a % 2] : 0.0));
  }
}

/* A crossing c of slave edge se and the quadrature's dependence on it, to
   first order (MortarCrossFirst): the gaps on either side (edges a and b)
   at c, their gradients, d(g_a - g_b)/dxi (den, so that dc/du = -(dg_a -
   dg_b) / den), and for each node i of the edge q_i = dQ_i/dc and k_i =
   dC_i/dc (Q_i = int W_i (g - g_i) dS by the Gauss rule of the two pieces,
   g_i held, C_i = int W_i dS) and s = sum_i Lambda_i q_i = dE/dc. False
   where none of the edge's nodes is active (nothing depends on c then) or
   where the two gaps' slopes meet (a blended node: no crossing term). */
typedef struct {
  ContactGap  Ga, Gb;
  MortarAlong A;
  PetscReal   dga[20], dgb[20], ga1, gb1, den, q[3], k[3], s, Lam[3], g[3];
  PetscInt    ia[20], ib[20];
} MortarCross;

/* The Gauss rule of a piece [l, r] with h = (r - l)/2 and nodes xi_q = (l +
   r)/2 + h x_q: d/dr sum_q h w_q F(xi_q) = sum_q w_q (F/2 + h gamma_q F'),
   gamma_q = (1 + x_q)/2, and d/dl alike with -F/2 and gamma_q = (1 - x_q)/2
   (sigma = +1 at r, -1 at l); d2/dr2 = sum_q w_q (gamma_q F' + h gamma_q^2
   F''), d2/dl2 = sum_q w_q (-gamma_q F' + h gamma_q^2 F''), d2/dl dr =
   sum_q w_q ((gamma_l - gamma_r) F'/2 + h gamma_l gamma_r F''). The piece
   left of crossing X (side 0) ends at c (sigma = +1), the right one (side 1)
   begins there (sigma = -1). */
static inline void MortarPieceOf(const MortarCut *X, PetscInt side, PetscInt *p0, PetscReal *h, PetscReal *sigma)
{
  *p0    = side ? X->pr : X->pl;
  *h     = side ? 0.5 * (X->xr - X->xi) : 0.5 * (X->xi - X->xl);
  *sigma = side ? -1.0 : 1.0;
}

static PetscBool MortarCrossFirst(const Mortar *m, PetscInt s, const MortarCut *X, const MortarPoint *pts, MortarCross *C)
{
  const ContactSurface *S  = &m->b.S[s], *M = &m->b.S[1 - s];
  const PetscInt       *sn = &S->enodes[3 * X->se];
  PetscReal             xs[2], dS;

  MortarEdgeLambda(m, &m->side[s], sn, C->Lam, C->g);
  if (C->Lam[0] == 0 && C->Lam[1] == 0 && C->Lam[2] == 0) return PETSC_FALSE; /* no active node on the edge: nothing moves the energy here */
  MortarAlongEval(m, s, X->se, X->xi, &C->A);
  MortarSlaveEval(S, X->se, X->xi, xs, &dS);
  ContactGapOnEdge(M, X->ea, X->ma, xs, &C->Ga);
  ContactGapOnEdge(M, X->eb, X->mb, xs, &C->Gb);
  MortarGapAlong(&C->Ga, &C->A, C->dga, &C->ga1, NULL, NULL, NULL);
  MortarGapAlong(&C->Gb, &C->A, C->dgb, &C->gb1, NULL, NULL, NULL);
  C->den = C->ga1 - C->gb1;
  if (PetscAbsReal(C->den) <= 1e-12 * PetscSqrtReal(C->A.x1[0] * C->A.x1[0] + C->A.x1[1] * C->A.x1[1])) return PETSC_FALSE;
  ContactGapIndices(S, sn, M, &C->Ga, C->ia);
  ContactGapIndices(S, sn, M, &C->Gb, C->ib);
  for (PetscInt i = 0; i < 3; ++i) C->q[i] = C->k[i] = 0.0;
  for (PetscInt side = 0; side < 2; ++side) {
    PetscInt  p0;
    PetscReal h, sg;
    MortarPieceOf(X, side, &p0, &h, &sg);
    for (PetscInt q = 0; p0 >= 0 && q < m->nq; ++q) {
      const MortarPoint *P  = &pts[p0 + q];
      const PetscReal    ga = 0.5 * (1.0 + sg * m->xq[q]);
      MortarAlong        B;
      PetscReal          g1;
      if (P->G.me < 0) continue;
      MortarAlongEval(m, s, X->se, P->xi, &B);
      g1 = P->G.ns[0] * B.x1[0] + P->G.ns[1] * B.x1[1];
      for (PetscInt i = 0; i < 3; ++i) {
        const PetscReal WJ = B.W[i] * B.J[0], WJ1 = B.W1[i] * B.J[0] + B.W[i] * B.J[1];
        const PetscReal F = WJ * (P->G.gap - C->g[i]), F1 = WJ1 * (P->G.gap - C->g[i]) + WJ * g1;
        C->q[i] += m->wq[q] * (0.5 * sg * F + h * ga * F1);
        C->k[i] += m->wq[q] * (0.5 * sg * WJ + h * ga * WJ1);
      }
    }
  }
  C->s = 0.0;
  for (PetscInt i = 0; i < 3; ++i) C->s += C->Lam[i] * C->q[i];
  return PETSC_TRUE;
}

/* The slot of index i in a sparse vector's index set (idx, n), appended with
   its nv value arrays zeroed if new; -1 for i = -1 (a constrained dof; a
   rigid body's surface dofs, below -1, have their slots: rigidbody.h). */
static PetscErrorCode SparseSlot(PetscInt i, PetscInt *n, PetscInt nmax, PetscInt idx[], PetscInt nv, PetscReal *val[], PetscInt *slot)
{
  PetscFunctionBeginUser;
  *slot = -1;
  if (i == -1) PetscFunctionReturn(0);
  for (PetscInt k = 0; k < *n; ++k)
    if (idx[k] == i) {
      *slot = k;
      PetscFunctionReturn(0);
    }
  PetscCheck(*n < nmax, PETSC_COMM_SELF, PETSC_ERR_PLIB, "mortar: crossing support larger than %" PetscInt_FMT " dofs", nmax);
  idx[*n] = i;
  for (PetscInt v = 0; v < nv; ++v) val[v][*n] = 0.0;
  *slot = (*n)++;
  PetscFunctionReturn(0);
}

/* Adds a dc/du of crossing C, times a, into the sparse vectors val[] of
   (idx, n) at value array v (the other nv - 1 arrays zeroed where new);
   sa, sb (if not NULL) get the slots of C's dofs on either side. */
static PetscErrorCode MortarCrossAddDc(const MortarCross *C, PetscReal a, PetscInt *n, PetscInt nmax, PetscInt idx[], PetscInt nv, PetscReal *val[], PetscInt v, PetscInt sa[20], PetscInt sb[20])
{
  PetscInt k;

  PetscFunctionBeginUser;
  for (PetscInt l = 0; l < 20; ++l) {
    PetscCall(SparseSlot(C->ia[l], n, nmax, idx, nv, val, &k));
    if (k >= 0) val[v][k] -= a * C->dga[l] / C->den;
    if (sa) sa[l] = k;
    PetscCall(SparseSlot(C->ib[l], n, nmax, idx, nv, val, &k));
    if (k >= 0) val[v][k] += a * C->dgb[l] / C->den;
    if (sb) sb[l] = k;
  }
  PetscFunctionReturn(0);
}

/* The terms of the Hessian that crossing X adds (see the header): V dc^T +
   dc V^T + S dc dc^T + s d2c, from the points of its two pieces. */
static PetscErrorCode MortarCrossHessian(const Mortar *m, PetscInt s, const MortarCut *X, const MortarPoint *pts, PetscInt nmax, PetscInt idx[], PetscReal *val[3], PetscScalar K[], Mat H)
{
  const ContactSurface *S  = &m->b.S[s], *M = &m->b.S[1 - s];
  const PetscInt       *sn = &S->enodes[3 * X->se];
  PetscReal            *dc = val[0], *V = val[1], *phi = val[2], dg1a[20], dg1b[20], ga2, gb2, Sc = 0.0, f;
  PetscScalar           Ka[400], Kb[400], KP[400];
  PetscInt              n = 0, sa[20], sb[20], k;
  MortarCross           C;

  PetscFunctionBeginUser;
  if (!MortarCrossFirst(m, s, X, pts, &C)) PetscFunctionReturn(0);
  MortarGapAlong(&C.Ga, &C.A, C.dga, &C.ga1, Ka, &ga2, dg1a);
  MortarGapAlong(&C.Gb, &C.A, C.dgb, &C.gb1, Kb, &gb2, dg1b);
  PetscCall(MortarCrossAddDc(&C, 1.0, &n, nmax, idx, 3, val, 0, sa, sb));
  for (PetscInt l = 0; l < 20; ++l) {
    if (sa[l] >= 0) phi[sa[l]] += dg1a[l];
    if (sb[l] >= 0) phi[sb[l]] -= dg1b[l];
  }
  for (PetscInt side = 0; side < 2; ++side) {
    PetscInt  p0;
    PetscReal h, sg;
    MortarPieceOf(X, side, &p0, &h, &sg);
    for (PetscInt q = 0; p0 >= 0 && q < m->nq; ++q) {
      const MortarPoint *P  = &pts[p0 + q];
      const PetscReal    ga = 0.5 * (1.0 + sg * m->xq[q]);
      MortarAlong        B;
      PetscReal          dg[20], dg1[20], g1, g2, LJ = 0, LJ1 = 0, F1 = 0, F2 = 0;
      PetscInt           ip[20];
      if (P->G.me < 0) continue;
      MortarAlongEval(m, s, X->se, P->xi, &B);
      MortarGapAlong(&P->G, &B, dg, &g1, KP, &g2, dg1);
      for (PetscInt i = 0; i < 3; ++i) {
        const PetscReal WJ = B.W[i] * B.J[0], WJ1 = B.W1[i] * B.J[0] + B.W[i] * B.J[1], WJ2 = B.W2[i] * B.J[0] + 2.0 * B.W1[i] * B.J[1] + B.W[i] * B.J[2];
        const PetscReal d = P->G.gap - C.g[i];
        LJ += C.Lam[i] * WJ;
        LJ1 += C.Lam[i] * WJ1;
        F1 += C.Lam[i] * (WJ1 * d + WJ * g1);
        F2 += C.Lam[i] * (WJ2 * d + 2.0 * WJ1 * g1 + WJ * g2);
      }
      Sc += m->wq[q] * (sg * ga * F1 + h * ga * ga * F2);
      ContactGapIndices(S, sn, M, &P->G, ip);
      for (PetscInt l = 0; l < 20; ++l) {
        PetscCall(SparseSlot(ip[l], &n, nmax, idx, 3, val, &k));
        if (k >= 0) V[k] += m->wq[q] * (0.5 * sg * LJ * dg[l] + h * ga * (LJ1 * dg[l] + LJ * dg1[l]));
      }
    }
  }
  f = -C.s / C.den; /* s d2c = f (phi_uu + phi_uxi dc^T + dc phi_uxi^T + phi_xixi dc dc^T), phi = g_a - g_b */
  for (PetscInt a = 0; a < n; ++a)
    for (PetscInt b = 0; b < n; ++b) K[a * n + b] = V[a] * dc[b] + dc[a] * V[b] + Sc * dc[a] * dc[b] + f * (phi[a] * dc[b] + dc[a] * phi[b] + (ga2 - gb2) * dc[a] * dc[b]);
  for (PetscInt l = 0; l < 20; ++l)
    for (PetscInt l2 = 0; l2 < 20; ++l2) {
      if (sa[l] >= 0 && sa[l2] >= 0) K[sa[l] * n + sa[l2]] += f * Ka[l * 20 + l2];
      if (sb[l] >= 0 && sb[l2] >= 0) K[sb[l] * n + sb[l2]] -= f * Kb[l * 20 + l2];
    }
  PetscCall(ContactTermAddHessian(&m->b, H, n, idx, K));
  PetscFunctionReturn(0);
}

/* Two crossings X1 < X2 of one slave edge that bound one piece (X1's right,
   X2's left): T (dc_1 dc_2^T + dc_2 dc_1^T), T = d2E/dc_1 dc_2 by the
   piece's Gauss rule. */
static PetscErrorCode MortarCrossPair(const Mortar *m, PetscInt s, const MortarCut *X1, const MortarCut *X2, const MortarPoint *pts, PetscInt nmax, PetscInt idx[], PetscReal *val[2], PetscScalar K[], Mat H)
{
  const PetscReal h = 0.5 * (X2->xi - X1->xi);
  MortarCross     C1, C2;
  PetscReal       T = 0.0;
  PetscInt        n = 0;

  PetscFunctionBeginUser;
  if (X1->pr < 0 || X1->pr != X2->pl) PetscFunctionReturn(0);
  if (!MortarCrossFirst(m, s, X1, pts, &C1) || !MortarCrossFirst(m, s, X2, pts, &C2)) PetscFunctionReturn(0);
  for (PetscInt q = 0; q < m->nq; ++q) {
    const MortarPoint *P  = &pts[X1->pr + q];
    const PetscReal    gl = 0.5 * (1.0 - m->xq[q]), gr = 0.5 * (1.0 + m->xq[q]);
    MortarAlong        B;
    PetscReal          dg[20], dg1[20], g1, g2, F1 = 0, F2 = 0;
    PetscScalar        KP[400];
    if (P->G.me < 0) continue;
    MortarAlongEval(m, s, X1->se, P->xi, &B);
    MortarGapAlong(&P->G, &B, dg, &g1, KP, &g2, dg1);
    for (PetscInt i = 0; i < 3; ++i) {
      const PetscReal WJ = B.W[i] * B.J[0], WJ1 = B.W1[i] * B.J[0] + B.W[i] * B.J[1], WJ2 = B.W2[i] * B.J[0] + 2.0 * B.W1[i] * B.J[1] + B.W[i] * B.J[2];
      const PetscReal d = P->G.gap - C1.g[i];
      F1 += C1.Lam[i] * (WJ1 * d + WJ * g1);
      F2 += C1.Lam[i] * (WJ2 * d + 2.0 * WJ1 * g1 + WJ * g2);
    }
    T += m->wq[q] * (0.5 * (gl - gr) * F1 + h * gl * gr * F2);
  }
  if (T == 0) PetscFunctionReturn(0);
  PetscCall(MortarCrossAddDc(&C1, 1.0, &n, nmax, idx, 2, val, 0, NULL, NULL));
  PetscCall(MortarCrossAddDc(&C2, 1.0, &n, nmax, idx, 2, val, 1, NULL, NULL));
  for (PetscInt a = 0; a < n; ++a)
    for (PetscInt b = 0; b < n; ++b) K[a * n + b] = T * (val[0][a] * val[1][b] + val[1][a] * val[0][b]);
  PetscCall(ContactTermAddHessian(&m->b, H, n, idx, K));
  PetscFunctionReturn(0);
}

/* This rank's part of the pair's energy and of its gradient on both
   surfaces' nodes (in S->g, not yet summed over ranks), at the state of the
   last MortarUpdate. */
static PetscErrorCode MortarAccumulateGradient(Mortar *m, PetscReal *energy)
{
  PetscReal e = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) PetscCall(PetscArrayzero(m->b.S[s].g, 2 * m->b.S[s].nn));
  for (PetscInt s = 0; s < 2; ++s) {
    ContactSurface   *S = &m->b.S[s], *M = &m->b.S[1 - s];
    const MortarSide *D = &m->side[s];
    if (!m->slave[s]) continue;
    for (PetscInt j = 0; j < S->nn; ++j)
      if (D->mine[j] && D->gj[j] < 0) e += 0.5 * m->c * m->b.kp * D->A[j] * D->gj[j] * D->gj[j];
    for (PetscInt k = 0; k < D->np; ++k) {
      const MortarPoint *P  = &D->pts[k];
      const PetscInt    *sn = &S->enodes[3 * P->se], *mn;
      PetscReal          f;
      if (P->G.me < 0) continue;
      f = P->wt * MortarLambda(m, D, sn, P->W, m->c);
      if (f == 0) continue;
      mn = &M->mnodes[7 * P->G.me];
      for (PetscInt i = 0; i < 3; ++i)
        for (PetscInt d = 0; d < 2; ++d) S->g[2 * sn[i] + d] += f * P->N[i] * P->G.ns[d];
      for (PetscInt j = 0; j < 7; ++j) {
        PetscReal w[2];
        ContactGapMasterWeight(&P->G, j, w);
        for (PetscInt d = 0; d < 2; ++d) M->g[2 * mn[j] + d] -= f * w[d];
      }
    }
    /* the Gauss points move with the crossings: (dE/dc) dc/du */
    for (PetscInt k = 0; k < D->cross.n; ++k) {
      const MortarCut *X  = &D->cross.c[k];
      const PetscInt  *sn = &S->enodes[3 * X->se], *ma, *mb;
      MortarCross      C;
      PetscReal        f;
      if (!MortarCrossFirst(m, s, X, D->pts, &C) || C.s == 0) continue;
      f  = -C.s / C.den;
      ma = &M->mnodes[7 * C.Ga.me];
      mb = &M->mnodes[7 * C.Gb.me];
      for (PetscInt d = 0; d < 2; ++d) {
        for (PetscInt i = 0; i < 3; ++i) S->g[2 * sn[i] + d] += f * (C.dga[2 * i + d] - C.dgb[2 * i + d]);
        for (PetscInt j = 0; j < 7; ++j) {
          M->g[2 * ma[j] + d] += f * C.dga[6 + 2 * j + d];
          M->g[2 * mb[j] + d] -= f * C.dgb[6 + 2 * j + d];
        }
      }
    }
  }
  *energy = e;
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarFrictionLag(EnergyTerm, Body[], PetscReal *);

static PetscErrorCode MortarEnergyGradient(EnergyTerm t, Body bodies[], PetscReal *energy)
{
  Mortar *m = (Mortar *)t->data;

  PetscFunctionBeginUser;
  if (m->fr && FrictionRowsPending(m->fr)) PetscCall(MortarFrictionLag(t, bodies, NULL)); /* a tied start's rows (friction.c) */
  PetscCall(PetscLogEventBegin(MORTAR_EnergyGrad, 0, 0, 0, 0));
  PetscCall(MortarUpdate(m, bodies, t->comm));
  PetscCall(MortarAccumulateGradient(m, energy));
  if (m->fr) PetscCall(FrictionAddEnergyGradient(m->fr, m->b.S, m->b.spec.kp, energy)); /* the scene's k_p: k_t is not continued (friction.c) */
  for (PetscInt s = 0; s < 2; ++s) PetscCall(ContactSurfaceAddGradient(&m->b.S[s], bodies[m->b.S[s].body]));
  PetscCall(PetscLogEventEnd(MORTAR_EnergyGrad, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* G_j = dQ_j/du of node j of slave side s (Q_j = int_S' W_j g dS by the
   Gauss rule of the segments), and K_j = dC_j/du (C_j = int_S' W_j dS by
   that rule), sparse vectors on one index set (n, idx; val[0], val[1]):
   the points' int W_j dg dS, and the crossings' q_j dc/du and k_j dc/du,
   the points moving with them (MortarCrossFirst); from the points of the
   last update on this rank's edges; those of an edge of another rank (at an
   end of this rank's run) are computed again, in the work array *pts. */
static PetscErrorCode MortarNodeGradient(Mortar *m, PetscInt s, PetscInt j, PetscInt nmax, PetscInt *n, PetscInt idx[], PetscReal *val[2], PetscInt *npmax, MortarPoint **pts, MortarCutList *L)
{
  const ContactSurface *S = &m->b.S[s], *M = &m->b.S[1 - s];
  const MortarSide     *D = &m->side[s];

  PetscFunctionBeginUser;
  for (PetscInt k = D->nodeEdgeStart[j]; k < D->nodeEdgeStart[j + 1]; ++k) {
    const PetscInt     e  = D->nodeEdge[k];
    const MortarPoint *P0 = D->pbeg[e] >= 0 ? &D->pts[D->pbeg[e]] : NULL;
    const MortarCut   *X0 = D->pbeg[e] >= 0 && D->cend[e] > D->cbeg[e] ? &D->cross.c[D->cbeg[e]] : NULL;
    PetscInt           n0 = D->pbeg[e] >= 0 ? D->pend[e] - D->pbeg[e] : 0, nx = D->pbeg[e] >= 0 ? D->cend[e] - D->cbeg[e] : 0, i0 = -1, slot;
    const PetscInt    *sn = &S->enodes[3 * e];
    for (PetscInt i = 0; i < 3; ++i)
      if (sn[i] == j) i0 = i;
    if (!P0) {
      L->n = 0;
      PetscCall(MortarEdgePoints(m, s, e, &n0, npmax, pts, L));
      P0 = *pts;
      X0 = L->c;
      nx = L->n;
    }
    for (PetscInt q = 0; q < n0; ++q) {
      const MortarPoint *P = &P0[q];
      PetscInt           gi[20];
      PetscReal          dg[20];
      if (P->G.me < 0) continue;
      ContactGapIndices(S, sn, M, &P->G, gi);
      ContactGapFirst(&P->G, P->N, dg);
      for (PetscInt l = 0; l < 20; ++l) {
        PetscCall(SparseSlot(gi[l], n, nmax, idx, 2, val, &slot));
        if (slot >= 0) val[0][slot] += P->wt * P->W[i0] * dg[l];
      }
    }
    for (PetscInt x = 0; x < nx; ++x) {
      const MortarPoint *base = D->pbeg[e] >= 0 ? D->pts : *pts;
      MortarCross        C;
      if (!MortarCrossFirst(m, s, &X0[x], base, &C)) continue;
      PetscCall(MortarCrossAddDc(&C, C.q[i0], n, nmax, idx, 2, val, 0, NULL, NULL));
      PetscCall(MortarCrossAddDc(&C, C.k[i0], n, nmax, idx, 2, val, 1, NULL, NULL));
    }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarAssembleHessian(Mortar *m, Mat H)
{
  const PetscInt nmax = 512;
  PetscInt      *gidx, npmax = 0;
  PetscReal     *gval[3];
  PetscScalar   *K;
  MortarPoint   *pts = NULL;
  MortarCutList  L   = {0, 0, NULL};

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc5(nmax, &gidx, nmax, &gval[0], nmax, &gval[1], nmax, &gval[2], nmax * nmax, &K));
  for (PetscInt s = 0; s < 2; ++s) {
    ContactSurface   *S = &m->b.S[s], *M = &m->b.S[1 - s];
    const MortarSide *D = &m->side[s];
    if (!m->slave[s]) continue;
    /* int Lambda d2g dS, pointwise over this rank's edges */
    for (PetscInt k = 0; k < D->np && m->b.exactHessian; ++k) {
      const MortarPoint *P  = &D->pts[k];
      const PetscInt    *sn = &S->enodes[3 * P->se];
      PetscInt           idx[20];
      PetscReal          L;
      if (P->G.me < 0) continue;
      L = MortarLambda(m, D, sn, P->W, m->c);
      if (L == 0) continue;
      PetscCall(PetscArrayzero(K, 400));
      ContactGapAddSecond(&P->G, P->N, P->wt * L, K);
      ContactGapIndices(S, sn, M, &P->G, idx);
      PetscCall(ContactTermAddHessian(&m->b, H, 20, idx, K));
    }
    /* the crossings: the closest point's passage from one master edge to
       the next, and the Gauss points that move with it */
    for (PetscInt k = 0; k < D->cross.n && m->b.exactHessian; ++k) {
      PetscCall(MortarCrossHessian(m, s, &D->cross.c[k], D->pts, nmax, gidx, gval, K, H));
      if (k + 1 < D->cross.n && D->cross.c[k + 1].se == D->cross.c[k].se) PetscCall(MortarCrossPair(m, s, &D->cross.c[k], &D->cross.c[k + 1], D->pts, nmax, gidx, gval, K, H));
    }
    /* (c k_p A_j / C_j^2) (G_j G_j^T - g_j (G_j K_j^T + K_j G_j^T)) for the active nodes this rank owns */
    for (PetscInt j = 0; j < S->nn; ++j) {
      PetscInt  n = 0;
      PetscReal c, g;
      if (!D->mine[j] || D->gj[j] >= 0) continue;
      PetscCall(MortarNodeGradient(m, s, j, nmax, &n, gidx, gval, &npmax, &pts, &L));
      c = m->c * m->b.kp * D->A[j] / (D->cover[j] * D->cover[j]);
      g = m->b.exactHessian ? D->gj[j] : 0.0;
      for (PetscInt a = 0; a < n; ++a)
        for (PetscInt b = 0; b < n; ++b) K[a * n + b] = c * (gval[0][a] * gval[0][b] - g * (gval[0][a] * gval[1][b] + gval[1][a] * gval[0][b]));
      PetscCall(ContactTermAddHessian(&m->b, H, n, gidx, K));
    }
  }
  PetscCall(PetscFree(pts));
  PetscCall(PetscFree(L.c));
  PetscCall(PetscFree5(gidx, gval[0], gval[1], gval[2], K));
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarHessian(EnergyTerm t, Body bodies[], Mat H)
{
  Mortar *m = (Mortar *)t->data;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(MORTAR_Hessian, 0, 0, 0, 0));
  PetscCall(MortarUpdate(m, bodies, t->comm));
  PetscCall(MortarAssembleHessian(m, H));
  if (m->fr) PetscCall(FrictionAddHessian(m->fr, &m->b, m->b.spec.kp, H)); /* the scene's k_p: k_t is not continued (friction.c) */
  PetscCall(PetscLogEventEnd(MORTAR_Hessian, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The columns of node j's row that every surface fills alike: arc position,
   reference and current position, the pair's force F on it. */
static void MortarNodeRow(const ContactSurface *S, const MortarSide *D, PetscInt j, const PetscReal F[], PetscReal r[])
{
  r[CONTACT_ROW_S]  = D->s[j];
  r[CONTACT_ROW_X]  = S->X[2 * j];
  r[CONTACT_ROW_Y]  = S->X[2 * j + 1];
  r[CONTACT_ROW_XC] = S->x[2 * j];
  r[CONTACT_ROW_YC] = S->x[2 * j + 1];
  r[CONTACT_ROW_FX] = F[2 * j];
  r[CONTACT_ROW_FY] = F[2 * j + 1];
}

/* Slave surface s: a row per node this rank owns (weighted gap, Inf where the
   master faces less than half the node's support; pressure k_p <-g_j>_+;
   A_j), and the largest weighted penetration. */
static void MortarSlaveRows(const Mortar *m, PetscInt s, const PetscReal F[], PetscReal rows[], PetscInt *nrow, PetscReal *maxPen)
{
  const ContactSurface *S = &m->b.S[s];
  const MortarSide     *D = &m->side[s];

  *nrow = 0;
  for (PetscInt j = 0; j < S->nn; ++j) {
    PetscReal *r = &rows[CONTACT_ROW_COLS * *nrow];
    if (!D->mine[j] || D->A[j] <= 0) continue; /* linear weights: mid-edge nodes carry none */
    (*nrow)++;
    MortarNodeRow(S, D, j, F, r);
    r[CONTACT_ROW_GAP] = D->gj[j] < PETSC_INFINITY ? D->gj[j] : CONTACT_GAP_NONE; /* gj: PETSC_INFINITY where uncovered */
    r[CONTACT_ROW_P]   = D->gj[j] < 0 ? -m->b.kp * D->gj[j] : 0.0;
    r[CONTACT_ROW_W]   = D->A[j];
    if (D->gj[j] < 0) *maxPen = PetscMax(*maxPen, -D->gj[j]);
  }
}

/* The stretch of surface S at parameter xi of its edge e: the current
   measure over the reference one, |dx/dxi| / |dX/dxi|, times r / R in
   axisymmetry (where the measure is 2 pi r dS; 1 for that factor on the
   axis). */
static PetscReal MortarStretch(const ContactSurface *S, PetscInt e, PetscReal xi)
{
  PetscReal x[2], t[2], X[2], T[2], l;

  EdgeEval(S->x, &S->enodes[3 * e], xi, x, t);
  EdgeEval(S->X, &S->enodes[3 * e], xi, X, T);
  l = PetscSqrtReal((t[0] * t[0] + t[1] * t[1]) / (T[0] * T[0] + T[1] * T[1]));
  return S->axisym && X[0] > 0 ? l * x[0] / X[0] : l;
}

/* Whether x, whose closest point of surface S is (e, eta), lies past an end
   of S (not a half model's cut, which its image continues) by more than a
   millionth of the end edge. */
static PetscBool MortarPastEnd(const ContactSurface *S, PetscInt e, PetscReal eta, const PetscReal x[2])
{
  const PetscInt *en = &S->enodes[3 * e];
  const PetscInt  v  = en[eta > 0 ? 1 : 0];
  PetscReal       xe[2], t[2];

  if (PetscAbsReal(eta) < 1.0 || !S->endNode[v] || ContactSurfaceCutSide(S, v) != 0) return PETSC_FALSE;
  EdgeEval(S->x, en, eta > 0 ? 1.0 : -1.0, xe, t);
  return (PetscBool)((eta > 0 ? 1.0 : -1.0) * ((x[0] - xe[0]) * t[0] + (x[1] - xe[1]) * t[1]) > 1e-6 * S->elen[e] * PetscSqrtReal(t[0] * t[0] + t[1] * t[1]));
}

/* The slave's pressure (surface s as slave) at point x of the other
   surface, per unit current measure: the slave's nodal pressures k_p
   <-g_j>_+ (per unit of its own reference measure) interpolated linearly,
   node to node along the slave's edge (corner, mid-edge, corner), at x's
   closest point of the slave, over the slave's stretch there; 0 past an end
   of the slave surface (not a half model's cut, which its image continues)
   by more than a millionth of the end edge. Linear between nodes, so never
   below the smaller of two nodal pressures: no negative values and no
   oscillation the slave's own profile does not have. A node without a
   weight (linear weights' mid-edge nodes) takes its edge's corners' mean.
   In axisymmetry a corner on the axis has no weight either (set-up: int
   N_j 2 pi r dS vanishes there) and so no pressure of its own, but the
   pressure there is not 0: it is its neighbours' limit, by the symmetry an
   even function of r, p = a + b r^2 near the axis. Through the edge's other
   two nodes (reference radii r_m, r_c, pressures p_m, p_c)
   a = (p_m r_c^2 - p_c r_m^2) / (r_c^2 - r_m^2), (4 p_m - p_c) / 3 on a
   straight edge, kept >= 0; p_c alone where the mid-edge node has no
   weight either. A uniform pressure stays uniform: taking 0 there (before)
   made the nodes of the other surface facing the first half of the slave's
   edge from the axis read the pressure fallen linearly to 0 at the axis
   (the patch test's 0.4 p a quarter of the slave's edge from the axis). */
static PetscReal MortarSlavePressureAt(const Mortar *m, PetscInt s, const PetscReal x[2])
{
  const ContactSurface *S = &m->b.S[s];
  const MortarSide     *D = &m->side[s];
  const PetscInt       *en;
  PetscReal             eta, p[3];
  PetscInt              e;

  ContactSearchFindClosest(m->b.search[s], x, &e, &eta);
  if (e < 0 || MortarPastEnd(S, e, eta, x)) return 0.0;
  en = &S->enodes[3 * e];
  for (PetscInt i = 0; i < 3; ++i) {
    const PetscReal g = D->gj[en[i]];
    p[i]              = D->A[en[i]] > 0 && !PetscIsInfOrNanReal(g) ? (g < 0 ? -m->b.kp * g : 0.0) : -1.0;
  }
  for (PetscInt i = 0; i < 2; ++i)
    if (p[i] < 0 && S->axisym && D->AN[en[i]] <= 0 && p[1 - i] >= 0) { /* a corner on the axis */
      const PetscReal rc2 = PetscSqr(S->X[2 * en[1 - i]]), rm2 = PetscSqr(S->X[2 * en[2]]);
      p[i] = p[2] >= 0 && rc2 > rm2 ? PetscMax(0.0, (p[2] * rc2 - p[1 - i] * rm2) / (rc2 - rm2)) : p[1 - i];
    }
  if (p[2] < 0) p[2] = 0.5 * (PetscMax(p[0], 0.0) + PetscMax(p[1], 0.0));
  for (PetscInt i = 0; i < 2; ++i)
    if (p[i] < 0) p[i] = 0.0;
  eta = PetscMax(-1.0, PetscMin(1.0, eta));
  return (eta < 0 ? -eta * p[0] + (1.0 + eta) * p[2] : (1.0 - eta) * p[2] + eta * p[1]) / MortarStretch(S, e, eta);
}

/* The stretch of surface s at its node j: the mean over the node's edges. */
static PetscReal MortarNodeStretch(const Mortar *m, PetscInt s, PetscInt j)
{
  const ContactSurface *S = &m->b.S[s];
  const MortarSide     *D = &m->side[s];
  const PetscReal       xi[3] = {-1.0, 1.0, 0.0};
  PetscReal             l = 0.0;
  PetscInt              n = 0;

  for (PetscInt k = D->nodeEdgeStart[j]; k < D->nodeEdgeStart[j + 1]; ++k) {
    const PetscInt e = D->nodeEdge[k];
    for (PetscInt i = 0; i < 3; ++i)
      if (S->enodes[3 * e + i] == j) {
        l += MortarStretch(S, e, xi[i]);
        n++;
      }
  }
  return n ? l / n : 1.0;
}

/* Master surface s (not a slave): a row per node this rank owns with the
   slave's pressure at the node's closest point of the slave
   (MortarSlavePressureAt) per unit of the master's own reference measure
   (times its stretch at the node, as the slave's is per unit of its own: on
   the reference scene the block's edge is shortened 1.5 % at the centre, the
   disc's arc 3.7 %, and the block's peak is 2.4 % above the disc's), its
   nodal force (the slave's transferred:
   sum_j F_j is the pair's force), and the gap weighted as the slave's but
   with the master's shape functions at the closest points, over the slave's
   points: int_S' M_j g dS / int_S' M_j dS (none, CONTACT_GAP_NONE, where
   that covers less than half of A_j). The force over A_j, -F_j . n_j / A_j, is the consistent
   transfer, but its lumping turns the negative parts of N_j near the zone's
   ends into negative pressures (-2.4 beside a peak of 104 on the reference
   scene, an oscillation index of 0.022 where the slave's is 0.005 on a
   graded one). */
static PetscErrorCode MortarMasterRows(const Mortar *m, PetscInt s, const PetscReal F[], PetscReal rows[], PetscInt *nrow, MPI_Comm comm)
{
  const ContactSurface *S = &m->b.S[s];
  const MortarSide     *D = &m->side[s], *Ds = &m->side[1 - s];
  PetscReal            *gw;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(2 * S->nn, &gw)); /* int_S' M_j g dS, then int_S' M_j dS */
  for (PetscInt k = 0; k < Ds->np; ++k) {
    const MortarPoint *P = &Ds->pts[k];
    if (P->G.me < 0) continue;
    for (PetscInt i = 0; i < 7; ++i) {
      gw[S->mnodes[7 * P->G.me + i]] += P->wt * P->G.M7[i] * P->G.gap;
      gw[S->nn + S->mnodes[7 * P->G.me + i]] += P->wt * P->G.M7[i];
    }
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, gw, 2 * S->nn, MPIU_REAL, MPIU_SUM, comm));
  *nrow = 0;
  for (PetscInt j = 0; j < S->nn; ++j) {
    PetscReal *r = &rows[CONTACT_ROW_COLS * *nrow];
    if (!D->mine[j] || D->AN[j] <= 0) continue;
    (*nrow)++;
    MortarNodeRow(S, D, j, F, r);
    r[CONTACT_ROW_GAP] = gw[S->nn + j] > 0.5 * D->AN[j] ? gw[j] / gw[S->nn + j] : CONTACT_GAP_NONE;
    r[CONTACT_ROW_P]   = MortarSlavePressureAt(m, 1 - s, &S->x[2 * j]) * MortarNodeStretch(m, s, j); /* per unit of the master's reference measure */
    r[CONTACT_ROW_W]   = D->AN[j];
  }
  PetscCall(PetscFree(gw));
  PetscFunctionReturn(0);
}

/* Rank 0, with friction: the pair's whole force (its normal part and the
   shear) along the contact zone's normal and across it, Cattaneo-Mindlin's
   P and Q. The zone's normal is that of the chord between its end nodes
   on the slave surface (current positions): on a curved slave the shear
   has a share along the normal part's direction, and under a tangential
   load that direction leans more than the zone (1.4e-3 on the cattaneo
   scene at a/R = 0.1, P = 4.3, against the zone's 1.0e-3, whose slab tilts under the shear: Q
   0.6512 and 0.6506 against the load 0.645 across the undeformed slab).
   Elsewhere (and without contact) the normal part's direction. */
static PetscErrorCode MortarContactLoads(ContactReport *R, PetscInt s)
{
  const ContactSide *S  = &R->side[s];
  const PetscReal    Fn = PetscSqrtReal(PetscSqr(R->force[0]) + PetscSqr(R->force[1])), F[2] = {R->force[0] + R->shearForce[0], R->force[1] + R->shearForce[1]};
  PetscReal          n[2] = {Fn > 0 ? R->force[0] / Fn : 0.0, Fn > 0 ? R->force[1] / Fn : 0.0}, Fp;
  PetscInt           lo = -1, hi = -1;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < S->n; ++i)
    if (S->rows[CONTACT_ROW_COLS * i + CONTACT_ROW_P] > 0) {
      if (lo < 0) lo = i;
      hi = i;
    }
  if (lo >= 0 && hi > lo) {
    const PetscReal *a = &S->rows[CONTACT_ROW_COLS * lo], *b = &S->rows[CONTACT_ROW_COLS * hi];
    const PetscReal  t[2] = {b[CONTACT_ROW_XC] - a[CONTACT_ROW_XC], b[CONTACT_ROW_YC] - a[CONTACT_ROW_YC]}, l = PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
    if (l > 0) n[0] = t[1] / l, n[1] = -t[0] / l;
  }
  Fp                = F[0] * n[0] + F[1] * n[1];
  R->normalLoad     = PetscAbsReal(Fp);
  R->tangentialLoad = PetscSqrtReal(PetscSqr(F[0] - Fp * n[0]) + PetscSqr(F[1] - Fp * n[1]));
  PetscFunctionReturn(0);
}

/* The nodal profile of each surface (its own for a slave, transferred for a
   master), the pair's force on each surface as the sum of its nodal forces,
   and the largest weighted penetration. */
static PetscErrorCode MortarPostProcess(EnergyTerm t, Body bodies[])
{
  Mortar    *m = (Mortar *)t->data;
  PetscReal *rows[2], *F[2], force[2][2] = {{0, 0}, {0, 0}}, maxPen = 0.0, L[2], e;
  PetscInt   nrow[2];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(MORTAR_Report, 0, 0, 0, 0));
  PetscCall(MortarUpdate(m, bodies, t->comm));
  PetscCall(MortarAccumulateGradient(m, &e));
  for (PetscInt s = 0; s < 2; ++s) {
    const ContactSurface *S = &m->b.S[s];
    L[s]                    = ContactSurfaceLength(S);
    PetscCall(PetscMalloc2(CONTACT_ROW_COLS * S->nn + 1, &rows[s], 2 * S->nn, &F[s]));
    PetscCall(MPIU_Allreduce(S->g, F[s], 2 * S->nn, MPIU_REAL, MPIU_SUM, t->comm));
    for (PetscInt j = 0; j < S->nn; ++j)
      for (PetscInt d = 0; d < 2; ++d) {
        F[s][2 * j + d] = -F[s][2 * j + d];
        if (m->side[s].mine[j]) force[s][d] += F[s][2 * j + d];
      }
  }
  for (PetscInt s = 0; s < 2; ++s) {
    if (m->slave[s]) MortarSlaveRows(m, s, F[s], rows[s], &nrow[s], &maxPen);
    else PetscCall(MortarMasterRows(m, s, F[s], rows[s], &nrow[s], t->comm));
  }
  PetscCall(ContactTermReportBegin(&m->b, m->slave));
  m->b.report.nodal = PETSC_TRUE;
  if (m->fr) {
    m->b.report.friction = PETSC_TRUE;
    PetscCall(FrictionStickHalfWidth(m->fr, &m->b.report.stickHalfWidth));
  }
  PetscCall(ContactReportFinish(&m->b.report, &m->b.spec, t->comm, nrow, rows, (const PetscReal(*)[2])force, maxPen, L));
  if (m->fr) {
    ContactReport  *R  = &m->b.report;
    const PetscReal mu = FrictionGetCoefficient(m->fr);
    PetscReal       Q;
    PetscCall(FrictionShearForce(m->fr, R->shearForce));
    if (!m->slave[0]) R->shearForce[0] = -R->shearForce[0], R->shearForce[1] = -R->shearForce[1]; /* on the first surface's body, as the pair's force */
    if (m->b.spec.axisym) R->shearForce[0] = 0.0; /* the rings' radial shear has no resultant (as the pair's force) */
    PetscCall(MortarContactLoads(R, m->slave[0] ? 0 : 1));
    Q           = R->tangentialLoad;
    R->mindlinC = m->b.spec.hertz && !m->b.spec.axisym && Q < mu * R->normalLoad ? R->hertzA * PetscSqrtReal(1.0 - Q / (mu * R->normalLoad)) : 0.0; /* plane strain's Cattaneo-Mindlin */
  }
  for (PetscInt s = 0; s < 2; ++s) PetscCall(PetscFree2(rows[s], F[s]));
  PetscCall(PetscLogEventEnd(MORTAR_Report, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Both surfaces and their searches; per side the nodal integrals A_j and
   int N_j dS (8-point Gauss on every edge, every rank), the arc position of each node, the edges
   on each node and the nodes this rank owns. */
/* Whether surface A ends on surface B: an end of A (not a half model's cut,
   nor on the axis of an axisymmetric body, where the surface goes on by
   symmetry) whose closest point of B is inside B (not at or past B's end:
   two surfaces that end flush do not) and within 5 % of A's length of it,
   in the configuration at set-up (a punch's face on the block's top, even a
   little above it). */
static PetscBool MortarEndsOn(const ContactSurface *A, const ContactSurface *B)
{
  const PetscReal tol = 0.05 * ContactSurfaceLength(A);

  for (PetscInt v = 0; v < A->nn; ++v) {
    PetscReal best = PETSC_MAX_REAL, etab = 0.0;
    PetscInt  eb   = -1;
    if (!A->endNode[v] || ContactSurfaceCutSide(A, v) != 0 || (A->axisym && PetscAbsReal(A->X[2 * v]) <= 1e-9 * tol)) continue;
    for (PetscInt e = 0; e < B->ne; ++e) {
      PetscReal eta, d2;
      MasterProject(B, e, &A->x[2 * v], &eta, &d2);
      if (d2 < best) {
        best = d2;
        eb   = e;
        etab = eta;
      }
    }
    if (eb < 0 || PetscSqrtReal(best) > tol) continue;
    if (PetscAbsReal(etab) >= 1.0 - 1e-6 && B->endNode[B->enodes[3 * eb + (etab > 0 ? 1 : 0)]]) continue; /* at or past B's end */
    return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

/* The slave surfaces. auto: a surface that ends on the other (a punch's face
   on a block), else the softer body's by its plane-strain modulus
   E/(1 - nu^2) (the first where the two agree to 1e-12). The mortar
   constraint lives on the slave's weights. Where the slave is the stiffer
   body the softer master's surface can take shapes that those weights do
   not see, and the pressure zigzags from node to node (a disc 250 times
   stiffer than the slab, as slave: profile 24 % from Hertz, as master 6.8 %
   at a/h of about 6); the softer body's surface follows the contact, and its
   weights with it. But where a surface ends inside the contact, its end is
   where the pressure is singular (a flat punch's corners): as slave its end
   nodes carry that, as master its corners fall inside the other's slave
   edges, whose weights smear it (the punch scene, block as slave: P 0.4 to
   3 % low depending on k_p and the meshes; punch as slave: P the same to
   1e-4 over k_p from 9e6 to 1e9 and three meshes). So the pressure a user
   reads does not depend on the order of the pair's surfaces. */
static void MortarChooseSlaves(Mortar *m, Body bodies[])
{
  const char *why = NULL;
  PetscReal   Es[2];
  PetscBool   on[2];

  for (PetscInt s = 0; s < 2; ++s) {
    PetscReal E, nu;
    BodyGetElasticConstants(bodies[m->b.S[s].body], &E, &nu);
    Es[s] = E / (1.0 - nu * nu);
    on[s] = MortarEndsOn(&m->b.S[s], &m->b.S[1 - s]);
  }
  switch ((MortarSlave)m->slaveChoice) {
  case MORTAR_SLAVE_AUTO:
    if (on[0] != on[1]) {
      m->slave[0] = on[0];
      why         = "it ends on the other surface";
    } else {
      m->slave[0] = (PetscBool)(Es[0] <= Es[1] * (1.0 + 1e-12));
      why         = Es[0] <= Es[1] * (1.0 + 1e-12) && Es[1] <= Es[0] * (1.0 + 1e-12) ? "the first named, the bodies' moduli equal" : "the softer body";
    }
    m->slave[1] = (PetscBool)!m->slave[0];
    break;
  case MORTAR_SLAVE_FIRST:
    m->slave[0] = PETSC_TRUE;
    m->slave[1] = PETSC_FALSE;
    break;
  case MORTAR_SLAVE_SECOND:
    m->slave[0] = PETSC_FALSE;
    m->slave[1] = PETSC_TRUE;
    break;
  case MORTAR_SLAVE_BOTH:
    m->slave[0] = m->slave[1] = PETSC_TRUE;
    break;
  }
  m->c = 1.0 / (m->slave[0] + m->slave[1]);
  if (why) (void)PetscInfo(NULL, "pair %s: slave surface %s:%s (-contact_mortar_slave auto: %s)\n", m->b.spec.name, BodyGetName(bodies[m->b.S[m->slave[0] ? 0 : 1].body]), m->b.S[m->slave[0] ? 0 : 1].group, why);
}

static PetscErrorCode MortarSetUp(EnergyTerm t, Body bodies[])
{
  Mortar   *m = (Mortar *)t->data;
  PetscReal gx[8], gw[8];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(t->comm, &m->rank));
  PetscCallMPI(MPI_Comm_size(t->comm, &m->size));
  PetscCall(PetscDTGaussQuadrature(8, -1.0, 1.0, gx, gw));
  PetscCall(ContactTermSetUpSurfaces(&m->b, bodies, 0.0)); /* no blend by default: see above */
  MortarChooseSlaves(m, bodies);
  for (PetscInt s = 0; s < 2; ++s) {
    ContactSurface *S = &m->b.S[s];
    MortarSide     *D = &m->side[s];
    PetscInt       *wpos, *cnt;
    PetscCall(PetscCalloc5(2 * S->nn, &D->A, 2 * S->nn, &D->gw, S->nn, &D->gj, S->nn, &D->s, S->nn, &D->mine));
    PetscCall(PetscMalloc5(S->nn, &D->first, S->ne, &D->owner, S->ne, &D->weight, S->ne, &D->pbeg, S->ne, &D->pend));
    PetscCall(PetscCalloc2(S->ne, &D->cbeg, S->ne, &D->cend));
    D->AN    = D->A + S->nn;
    D->cover = D->gw + S->nn;
    PetscCall(PetscMalloc2(S->ne, &wpos, S->nn + 1, &cnt));
    PetscCall(PetscCalloc1(S->nn + 1, &D->nodeEdgeStart));
    for (PetscInt k = 0; k < S->ne; ++k) wpos[S->walk[k]] = k;
    for (PetscInt j = 0; j < S->nn; ++j) D->first[j] = -1;
    PetscCall(PetscCalloc1(9 * S->ne, &D->dual));
    for (PetscInt e = 0; e < S->ne; ++e) { /* A = D M^-1 on each edge (dual weights) */
      PetscReal M[9] = {0}, d[3] = {0}, Mi[9], det;
      for (PetscInt q = 0; q < 8; ++q) {
        PetscReal N[3], dN[3], X[2], T[2], J;
        EdgeShape(gx[q], N, dN);
        EdgeEval(S->X, &S->enodes[3 * e], gx[q], X, T);
        J = gw[q] * ContactSurfaceMeasure(S, X, T);
        for (PetscInt i = 0; i < 3; ++i) {
          d[i] += J * N[i];
          for (PetscInt k = 0; k < 3; ++k) M[3 * i + k] += J * N[i] * N[k];
        }
      }
      det   = M[0] * (M[4] * M[8] - M[5] * M[7]) - M[1] * (M[3] * M[8] - M[5] * M[6]) + M[2] * (M[3] * M[7] - M[4] * M[6]);
      Mi[0] = (M[4] * M[8] - M[5] * M[7]) / det;
      Mi[1] = (M[2] * M[7] - M[1] * M[8]) / det;
      Mi[2] = (M[1] * M[5] - M[2] * M[4]) / det;
      Mi[3] = (M[5] * M[6] - M[3] * M[8]) / det;
      Mi[4] = (M[0] * M[8] - M[2] * M[6]) / det;
      Mi[5] = (M[2] * M[3] - M[0] * M[5]) / det;
      Mi[6] = (M[3] * M[7] - M[4] * M[6]) / det;
      Mi[7] = (M[1] * M[6] - M[0] * M[7]) / det;
      Mi[8] = (M[0] * M[4] - M[1] * M[3]) / det;
      for (PetscInt i = 0; i < 3; ++i)
        for (PetscInt k = 0; k < 3; ++k) D->dual[9 * e + 3 * i + k] = d[i] * Mi[3 * i + k];
    }
    for (PetscInt e = 0; e < S->ne; ++e) {
      const PetscInt *en = &S->enodes[3 * e];
      for (PetscInt h = 0; h < 2; ++h) /* each half of the edge: the sublinear weights have a kink at 0 */
        for (PetscInt q = 0; q < 8; ++q) {
          const PetscReal xi = 0.5 * (gx[q] + 2.0 * h - 1.0);
          PetscReal       W[3], N[3], dN[3], X[2], T[2], J;
          MortarWeights(m->basis, &D->dual[9 * e], xi, W);
          EdgeShape(xi, N, dN);
          EdgeEval(S->X, en, xi, X, T);
          J = ContactSurfaceMeasure(S, X, T);
          for (PetscInt i = 0; i < 3; ++i) {
            D->A[en[i]] += 0.5 * gw[q] * W[i] * J;
            D->AN[en[i]] += 0.5 * gw[q] * N[i] * J;
          }
        }
      for (PetscInt i = 0; i < 3; ++i) {
        if (D->first[en[i]] < 0 || wpos[e] < wpos[D->first[en[i]]]) D->first[en[i]] = e;
        D->nodeEdgeStart[en[i] + 1]++;
      }
    }
    PetscCall(ContactSurfaceNodeArcs(S, D->s));
    if (S->axisym) { /* a corner on the axis carries no gap: its weight
                        int N_j 2 pi r dS is 0 on a straight edge from r = 0
                        (N_j r has zero mean there) and a sliver of its
                        neighbours' on a curved one, so its weighted gap
                        would be a ratio of two vanishing integrals */
      const PetscReal tol = 1e-8 * ContactSurfaceLength(S);
      for (PetscInt j = 0; j < S->nn; ++j)
        if (PetscAbsReal(S->X[2 * j]) <= tol) D->A[j] = D->AN[j] = 0.0;
    }
    for (PetscInt j = 0; j < S->nn; ++j) {
      D->nodeEdgeStart[j + 1] += D->nodeEdgeStart[j];
      cnt[j]                    = D->nodeEdgeStart[j];
    }
    PetscCall(PetscMalloc1(D->nodeEdgeStart[S->nn] + 1, &D->nodeEdge));
    for (PetscInt e = 0; e < S->ne; ++e)
      for (PetscInt i = 0; i < 3; ++i) D->nodeEdge[cnt[S->enodes[3 * e + i]]++] = e;
    PetscCall(PetscFree2(wpos, cnt));
    MortarShareEdges(m, s);
  }
  if (m->fr) {
    PetscCheck(m->slave[0] + m->slave[1] == 1, t->comm, PETSC_ERR_USER_INPUT, "option -contact_%s_friction %g: friction needs one slave surface, not -contact_mortar_slave both", m->b.spec.name, (double)m->b.spec.friction);
    PetscCheck(!m->b.spec.mirror, t->comm, PETSC_ERR_USER_INPUT, "option -contact_%s_friction %g: friction in a mirrored half model is not implemented (a tangential load breaks the symmetry)", m->b.spec.name, (double)m->b.spec.friction);
    PetscCall(FrictionSetUp(m->fr, m->b.S, m->slave[0] ? 0 : 1));
    if (ContactTermTiesAtRest(&m->b, bodies)) PetscCall(FrictionSetTieAtRest(m->fr, m->b.S));
  }
  PetscFunctionReturn(0);
}

/* Friction's fixed-point lag at the bodies' state: the slave's points of
   this rank's edges, its weights and its nodal pressures p_j = k_p <-g_j>_+
   (NULL change: the rows alone, the bound kept). */
static PetscErrorCode MortarFrictionLag(EnergyTerm t, Body bodies[], PetscReal *change)
{
  Mortar           *m = (Mortar *)t->data;
  const PetscInt    s = m->slave[0] ? 0 : 1;
  const MortarSide *D = &m->side[s];
  PetscReal        *p, dummy;

  PetscFunctionBeginUser;
  PetscCall(MortarUpdate(m, bodies, t->comm));
  if (FrictionRowsPending(m->fr)) PetscCall(MortarUpdatePoints(m, t->comm)); /* at rest MortarUpdate kept no points (the cattaneo disc: 0, then 1900 built here); why it kept none is not found */
  if (D->np > m->nfmax) {
    PetscCall(PetscFree(m->fpts));
    m->nfmax = 2 * D->np;
    PetscCall(PetscMalloc1(m->nfmax, &m->fpts));
  }
  for (PetscInt k = 0; k < D->np; ++k) {
    const MortarPoint *P = &D->pts[k];
    FrictionPoint     *F = &m->fpts[k];
    F->se                = P->se;
    F->me                = P->G.me >= 0 && !P->G.ext && !P->G.mirror ? P->G.me : -1; /* the master surface itself */
    F->wt                = P->wt;
    for (PetscInt i = 0; i < 3; ++i) F->N[i] = P->N[i], F->W[i] = P->W[i];
    for (PetscInt i = 0; i < 7; ++i) F->M7[i] = P->G.M7[i], F->dM7[i] = P->G.dM7[i];
  }
  PetscCall(PetscMalloc1(m->b.S[s].nn, &p));
  for (PetscInt j = 0; j < m->b.S[s].nn; ++j) p[j] = D->gj[j] < 0 ? -m->b.kp * D->gj[j] : 0.0;
  PetscCall(FrictionLag(m->fr, m->b.S, D->np, m->fpts, D->A, D->cover, change ? p : NULL, change ? change : &dummy));
  PetscCall(PetscFree(p));
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarFrictionAccept(EnergyTerm t, Body bodies[], PetscReal load)
{
  Mortar *m = (Mortar *)t->data;

  PetscFunctionBeginUser;
  PetscCall(MortarUpdate(m, bodies, t->comm));
  PetscCall(FrictionAccept(m->fr, m->b.S, m->b.spec.kp, load));
  PetscFunctionReturn(0);
}

/* Back to the accepted state, the bodies holding it again: its bound, and
   the rows rebuilt there. */
static PetscErrorCode MortarFrictionRestore(EnergyTerm t, Body bodies[])
{
  Mortar *m = (Mortar *)t->data;

  PetscFunctionBeginUser;
  PetscCall(FrictionRestore(m->fr));
  PetscCall(MortarFrictionLag(t, bodies, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarFrictionBegin(EnergyTerm t)
{
  Mortar *m = (Mortar *)t->data;

  PetscFunctionBeginUser;
  PetscCall(FrictionBegin(m->fr));
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarFrictionScaleBound(EnergyTerm t, PetscReal growth)
{
  PetscFunctionBeginUser;
  PetscCall(FrictionScaleBound(((Mortar *)t->data)->fr, growth));
  PetscFunctionReturn(0);
}

/* The slave's shear (surface s as slave) at point x of the other surface,
   as the traction it puts there per unit current measure, -q tau_s (the
   slave's is -q tau_s on itself, the master's the opposite), into t[2]: q
   interpolated linearly node to node along the slave's edge at x's closest
   point, as the pressure (MortarSlavePressureAt), with tau_s the slave's
   unit tangent along its arc there; 0 where x's closest point is none or
   lies past an end of the slave surface (as the pressure's). */
static void MortarSlaveShearAt(const Mortar *m, PetscInt s, const PetscReal q[], const PetscReal x[2], PetscReal t[2])
{
  const ContactSurface *S = &m->b.S[s];
  const PetscInt       *en;
  PetscReal             eta, qe, xe[2], te[2], l;
  PetscInt              e;

  t[0] = t[1] = 0.0;
  ContactSearchFindClosest(m->b.search[s], x, &e, &eta);
  if (e < 0 || MortarPastEnd(S, e, eta, x)) return;
  en = &S->enodes[3 * e];
  eta = PetscMax(-1.0, PetscMin(1.0, eta));
  qe  = eta < 0 ? -eta * q[en[0]] + (1.0 + eta) * q[en[2]] : (1.0 - eta) * q[en[2]] + eta * q[en[1]];
  EdgeEval(S->x, en, eta, xe, te);
  l = PetscSqrtReal(te[0] * te[0] + te[1] * te[1]);
  if (!(l > 0)) return;
  qe /= MortarStretch(S, e, eta);
  t[0] = -qe * S->edir[e] * te[0] / l;
  t[1] = -qe * S->edir[e] * te[1] / l;
}

/* Rank 0, with friction: the master surface's node_shear, the slave's shear
   transferred as its pressure is (MortarMasterRows): at each master node
   with a weight, in the report's order (by arc position), the slave's
   traction at the node's closest point of the slave (MortarSlaveShearAt),
   opposite on the master, per unit of the master's reference measure, and
   signed as the slave's: the master's traction is -q_m tau_m, tau_m its
   unit tangent along its own arc at the node (the mean over its edges). */
static PetscErrorCode MortarWriteMasterShear(const Mortar *m, PetscInt ms, PetscViewer v, MPI_Comm comm)
{
  const ContactSurface *S = &m->b.S[ms];
  const MortarSide     *D = &m->side[ms];
  const PetscReal      *q = FrictionGetShear(m->fr);
  PetscMPIInt           rank;
  PetscReal            *key, *val, *tau;
  PetscInt             *order, n = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMalloc4(S->nn + 1, &key, S->nn + 1, &val, S->nn + 1, &order, 2 * S->nn + 1, &tau));
  if (!rank) ContactSurfaceNodalTangents(S, tau);
  for (PetscInt j = 0; j < S->nn && !rank; ++j) {
    PetscReal t[2];
    if (D->AN[j] <= 0) continue;
    MortarSlaveShearAt(m, 1 - ms, q, &S->x[2 * j], t);
    key[n]   = D->s[j];
    order[n] = n;
    val[n]   = (t[0] * tau[2 * j] + t[1] * tau[2 * j + 1]) * MortarNodeStretch(m, ms, j); /* -(-t) . tau_m */
    n++;
  }
  PetscCall(PetscSortRealWithArrayInt(n, key, order));
  PetscCall(ContactOutputWriteValues(v, comm, "node_shear", n, val, order));
  PetscCall(PetscFree4(key, val, order, tau));
  PetscFunctionReturn(0);
}

/* The report's sets, and the slave surface's friction: node_shear, node_slip, node_stick, and the
   master's node_shear transferred; with -load_stages, the slave's friction sets at each earlier
   stage's end under /stages/<k>/contact/<pair>/<surface>. */
static PetscErrorCode MortarWriteHDF5(EnergyTerm t, Body bodies[], PetscViewer v)
{
  Mortar        *m = (Mortar *)t->data;
  const PetscInt s = m->slave[0] ? 0 : 1;
  char           group[4 * CONTACT_NAME_LEN];

  PetscFunctionBeginUser;
  PetscCall(ContactReportWriteHDF5(&m->b.report, &m->b.spec, bodies, v));
  PetscCall(PetscSNPrintf(group, sizeof(group), "/contact/%s/%s_%s", m->b.spec.name, BodyGetName(bodies[m->b.S[s].body]), m->b.S[s].group));
  PetscCall(PetscViewerHDF5PushGroup(v, group));
  PetscCall(FrictionWriteHDF5(m->fr, m->side[s].A, v));
  PetscCall(PetscViewerHDF5PopGroup(v));
  if (m->fr) {
    PetscInt         n;
    const PetscReal *c;
    PetscCall(PetscSNPrintf(group, sizeof(group), "/contact/%s/%s_%s", m->b.spec.name, BodyGetName(bodies[m->b.S[1 - s].body]), m->b.S[1 - s].group));
    PetscCall(PetscViewerHDF5PushGroup(v, group));
    PetscCall(MortarWriteMasterShear(m, 1 - s, v, t->comm));
    PetscCall(PetscViewerHDF5PopGroup(v));
    PetscCall(FrictionGetStages(m->fr, &n, &c));
    for (PetscInt k = 1; k < n; ++k) { /* -load_stages: each earlier stage's end (the last is the sets above) */
      PetscCall(PetscSNPrintf(group, sizeof(group), "/stages/%d/contact/%s/%s_%s", (int)k, m->b.spec.name, BodyGetName(bodies[m->b.S[s].body]), m->b.S[s].group));
      PetscCall(PetscViewerHDF5PushGroup(v, group));
      PetscCall(FrictionWriteStageHDF5(m->fr, k, m->side[s].A, v));
      PetscCall(PetscViewerHDF5PopGroup(v));
    }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarStickHalfWidth(EnergyTerm t, PetscInt k, PetscReal *c, PetscBool *has)
{
  Mortar          *m = (Mortar *)t->data;
  PetscInt         n;
  const PetscReal *cs;

  PetscFunctionBeginUser;
  PetscCall(FrictionGetStages(m->fr, &n, &cs));
  *has = (PetscBool)(k >= 1 && k <= n);
  *c   = *has ? cs[k - 1] : 0.0;
  PetscFunctionReturn(0);
}

/* Why the solve may have stopped: the report's reason, else, with friction,
   a contact of which no node sticks at the last iterate: the pair slides
   (a tangential force above what friction holds has no equilibrium). */
static PetscErrorCode MortarDiagnose(EnergyTerm t, size_t n, char why[])
{
  Mortar  *m = (Mortar *)t->data;
  PetscInt stuck, loaded;

  PetscFunctionBeginUser;
  PetscCall(ContactReportDiagnose(&m->b.report, &m->b.spec, n, why));
  if (why[0]) PetscFunctionReturn(0);
  PetscCall(FrictionCountStuck(m->fr, m->b.S, m->b.spec.kp, &stuck, &loaded));
  if (loaded > 0 && stuck == 0) PetscCall(PetscSNPrintf(why, n, "pair %s slides: none of its %" PetscInt_FMT " nodes in contact sticks under its friction mu = %g (the tangential load exceeds what friction holds, mu P; -contact_%s_friction)", t->name, loaded, (double)FrictionGetCoefficient(m->fr), t->name));
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarSlipState(EnergyTerm t, PetscInt *stuck, PetscInt *loaded, PetscReal *slip)
{
  Mortar *m = (Mortar *)t->data;

  PetscFunctionBeginUser;
  PetscCall(FrictionSlipState(m->fr, m->b.S, m->b.spec.kp, stuck, loaded, slip));
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarFrictionReset(EnergyTerm t, Body bodies[])
{
  Mortar *m = (Mortar *)t->data;

  PetscFunctionBeginUser;
  (void)bodies;
  PetscCall(FrictionReset(m->fr, m->b.S));
  PetscFunctionReturn(0);
}

static PetscErrorCode MortarDestroy(EnergyTerm t)
{
  Mortar *m = (Mortar *)t->data;

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) {
    MortarSide *D = &m->side[s];
    PetscCall(PetscFree5(D->A, D->gw, D->gj, D->s, D->mine));
    PetscCall(PetscFree5(D->first, D->owner, D->weight, D->pbeg, D->pend));
    PetscCall(PetscFree(D->nodeEdgeStart));
    PetscCall(PetscFree(D->nodeEdge));
    PetscCall(PetscFree(D->dual));
    PetscCall(PetscFree(D->pts));
    PetscCall(PetscFree(D->cross.c));
    PetscCall(PetscFree2(D->cbeg, D->cend));
  }
  PetscCall(FrictionDestroy(&m->fr));
  PetscCall(PetscFree(m->fpts));
  PetscCall(ContactTermDestroy(&m->b));
  PetscCall(PetscFree(m));
  PetscFunctionReturn(0);
}

/* Mortar's own options, shared by every mortar pair: the slave surface and
   the weight functions of the nodal gaps. */
static PetscErrorCode MortarOptionsRead(MPI_Comm comm, MortarSlave *slave, MortarBasis *basis)
{
  PetscEnum which = (PetscEnum)*slave, w = (PetscEnum)*basis;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Mortar contact options", NULL);
  PetscCall(PetscOptionsEnum("-contact_mortar_slave", "Slave surface: auto (one that ends on the other, else the softer body's, else the first), the pair's first, its second, or both (each one-sided energy weighted 1/2)", NULL, MortarSlaves, which, &which, NULL));
  PetscCall(PetscOptionsEnum("-contact_mortar_basis", "Weight functions of the nodal gaps: dual (biorthogonal to the quadratic basis), quadratic, linear (corner hats), sublinear (hats on the edge halves)", NULL, MortarBases, w, &w, NULL));
  PetscOptionsEnd();
  *slave = (MortarSlave)which;
  *basis = (MortarBasis)w;
  PetscFunctionReturn(0);
}

PetscErrorCode ContactMortarOptionsHelp(MPI_Comm comm)
{
  MortarSlave slave = MORTAR_SLAVE_AUTO;
  MortarBasis basis = MORTAR_BASIS_DUAL;

  PetscFunctionBeginUser;
  PetscCall(MortarOptionsRead(comm, &slave, &basis));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactTermCreate_Mortar(const ContactPairSpec *spec, EnergyTerm t)
{
  Mortar *m;

  PetscFunctionBeginUser;
  if (!MORTAR_EnergyGrad) {
    PetscClassId id;
    PetscCall(PetscClassIdRegister("ContactMortar", &id));
    PetscCall(PetscLogEventRegister("MortarEnergyGrad", id, &MORTAR_EnergyGrad));
    PetscCall(PetscLogEventRegister("MortarSearch", id, &MORTAR_Search));
    PetscCall(PetscLogEventRegister("MortarSegments", id, &MORTAR_Segments));
    PetscCall(PetscLogEventRegister("MortarHessian", id, &MORTAR_Hessian));
    PetscCall(PetscLogEventRegister("MortarReport", id, &MORTAR_Report));
  }
  PetscCheck(spec->nqp >= 3, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "option -contact_quadrature_points: mortar needs at least 3 Gauss points per segment (degree 5), got %" PetscInt_FMT, spec->nqp);
  PetscCall(PetscNew(&m));
  m->basis = MORTAR_BASIS_DUAL;
  {
    MortarSlave slave = MORTAR_SLAVE_AUTO;
    PetscCall(MortarOptionsRead(PETSC_COMM_WORLD, &slave, &m->basis));
    m->slaveChoice = (PetscInt)slave;
  }
  m->nq = spec->nqp;
  PetscCall(PetscDTGaussQuadrature(m->nq, -1.0, 1.0, m->xq, m->wq));
  t->data = m;
  PetscCall(ContactTermInitialize(&m->b, spec, t));
  t->ops.setup            = MortarSetUp;
  t->ops.energygradient   = MortarEnergyGradient;
  t->ops.hessian          = MortarHessian;
  t->ops.postprocess      = MortarPostProcess;
  t->ops.destroy          = MortarDestroy;
  if (spec->friction > 0) {
    PetscCall(FrictionCreate(t->comm, spec->friction, spec->frictionPenalty, &m->fr));
    t->ops.lag     = MortarFrictionLag;
    t->ops.accept  = MortarFrictionAccept;
    t->ops.begin   = MortarFrictionBegin;
    t->ops.scalebound = MortarFrictionScaleBound;
    t->ops.restore = MortarFrictionRestore;
    t->ops.reset   = MortarFrictionReset;
    t->ops.writehdf5 = MortarWriteHDF5;
    t->ops.stickhalfwidth = MortarStickHalfWidth;
    t->ops.diagnose       = MortarDiagnose;
    t->ops.slipstate      = MortarSlipState;
  }
  PetscFunctionReturn(0);
}
