/* The normal gap of a slave point and its derivatives.

   The slave point x_s = sum_i N_i(xi) x_i is projected onto the closest point
   x_m(eta*) of the master surface (edge.h: each master edge the quadratic
   curve through its current nodes, blended C1 into its neighbours, linear in
   its seven nodes: x_m = sum_j M_j(eta) x_j), and g = (x_s - x_m(eta*)) .
   n(eta*) with n the master body's outward unit normal.

   First derivative. At an orthogonal projection x_s - x_m = g n and
   x_m' . n = 0, so the variations of eta* and of n drop out:
     dg = n . (sum_i N_i du_i - sum_j M_j(eta*) du_j),
   exact, including the dependence on the closest point and the normal. It is
   approximate only where the projection falls on a corner the blend leaves (a
   real corner of the surface, over 30 degrees, or -contact_blend 0).

   Second derivative. With t = x_m'(eta*), tau = t/|t|, kappa = n . x_m'',
   D = |t|^2 - g kappa, varying the projection condition (x_s - x_m) . t = 0
   gives
     d eta = (|t| a . du + g b . du) / D,   a = tau . (du_s - du_m), b = n . du_m'
   (du_m' = sum_j M_j'(eta*) du_j), and with dn = -(n . dt / |t|) tau,
     d2g = -(kappa a a + g b b + |t| (a b + b a)) / D,
   symmetric; exact away from the master edge's ends (eta* = +-1).

   Corners. Where the master's edges meet at a corner (-contact_blend 0, or a
   real corner of the surface; not at a blended node, where the surface is
   smooth and a projection clamped at the node is a tie between the two
   edges) a point outside a convex corner, or inside a
   concave one, has the corner node as its closest point over a fan of
   directions; there g is the signed distance to the node and n the unit
   vector from the node to the point, so that g is continuous, with
   dg = n . (du_s - du_v) and d2g = a a / g, a = tau . (du_s - du_v), tau
   normal to n (the curvature of the distance to a point).

   Ends. Past an end of the master surface the closest point is the end node;
   there the gap is the end's tangent-line gap lifted by the overhang past
   the end, as steeply as the master body's boundary turns there (surface.c's
   endTurn; ContactGapBeyondEnd): a point is in contact where it lies inside
   the master body, or past a square corner within its own penetration of
   it, never for lying below the surface's tangent line beside a corner.

   Mirror. In a half model (the pair's -mirror_y y0) the master surface is
   continued across the line by its mirror image R(M), R(x, y) = (x, 2 y0 - y),
   not by its tangent: the closest point of M u R(M) to x_s is that of M, or
   the image of the closest point of M to R x_s, whichever is nearer (the
   image only where it can be: x_s lies below y0 + the surface's reach past
   the line + the gap to M). On R(M) the gap is g = (R x_s - x_m) . n, so dg
   and d2g are those of R x_s with their slave rows reflected (n_s = R n). An
   end on the line joins its image at a corner: its fan's side is that of the
   two edges' mean normal, which lies along the line. A tangent extension at
   the cut would tilt with the end edge, and a point that an iterate pushes
   deep across it would find a positive gap: the bodies would pass each other
   through the cut. */
#include "gap.h"
#include "edge.h"

/* Whether end j (0: eta = -1, 1: eta = +1) of master edge e is blended into its
   neighbour (a smooth node: no corner, no fan of normals). */
PetscBool ContactGapEndBlended(const ContactSurface *M, PetscInt e, PetscInt j)
{
  const PetscReal *C = &M->mcorr[14 * e + 7 * j];

  if (M->blend <= 0) return PETSC_FALSE; /* no blend zone (mortar's default): every node is a corner */
  for (PetscInt k = 0; k < 7; ++k)
    if (C[k] != 0.0) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* The master's outward unit normal from its tangent P->tm, and the gap of xs
   from the master point P->xm along it. */
static void ContactGapNormal(const ContactSurface *M, const PetscReal xs[2], ContactGap *P)
{
  P->tn   = PetscSqrtReal(P->tm[0] * P->tm[0] + P->tm[1] * P->tm[1]);
  P->n[0] = M->esign[P->me] * P->tm[1] / P->tn;
  P->n[1] = -M->esign[P->me] * P->tm[0] / P->tn;
  P->gap  = (xs[0] - P->xm[0]) * P->n[0] + (xs[1] - P->xm[1]) * P->n[1];
}

/* The side (+1 outside, -1 inside the master body) of a point at d from the
   node at end j of master edge e, for a point whose closest master point is
   that node: the sign of d along the node's normal, the mean of the two
   edges' (the edge's end tangent corrected by mcorr into the mean of its own
   and its neighbour's, as the blend does). Near the node, in its fan, every
   normal between the two edges' gives the same sign; a point deeper than the
   surface's scallops (an iterate with a large overlap) may lie beyond the
   tangent line of one edge, tilted at a corner, and not of the mean, which
   keeps the sign of the gap continuous across the fan. */
static PetscReal ContactGapNodeSide(const ContactSurface *M, PetscInt e, PetscInt j, const PetscReal d[2])
{
  const PetscReal *C  = &M->mcorr[14 * e + 7 * j];
  const PetscInt  *mn = &M->mnodes[7 * e];
  PetscReal        N[3], dN[3], t[2] = {0, 0}, n[2];

  if (ContactSurfaceCutSide(M, mn[j]) != 0) return d[0] * ContactSurfaceCutSide(M, mn[j]) >= 0 ? 1.0 : -1.0; /* on the mirror line: the mean of its image's normal and its own is along the line */
  EdgeShape(j ? 1.0 : -1.0, N, dN); /* the edge's own end tangent, then the correction */
  for (PetscInt k = 0; k < 7; ++k)
    for (PetscInt c = 0; c < 2; ++c) t[c] += ((k < 3 ? dN[k] : 0.0) + C[k]) * M->x[2 * mn[k] + c];
  n[0] = M->esign[e] * t[1];
  n[1] = -M->esign[e] * t[0];
  return d[0] * n[0] + d[1] * n[1] >= 0 ? 1.0 : -1.0;
}

/* The gap at the closest point P->eta of master edge P->me. */
static void ContactGapEvaluate(const ContactSurface *M, const PetscReal xs[2], ContactGap *P)
{
  MasterShape(M, P->me, P->eta, P->M7, P->dM7, P->d2M7); /* once: the point, normal and derivatives below */
  MasterCombine(M, P->me, P->M7, P->dM7, P->d2M7, P->xm, P->tm, P->xpp);
  ContactGapNormal(M, xs, P);
  P->fan = PETSC_FALSE;
  if (PetscAbsReal(P->eta) >= 1.0 && !ContactGapEndBlended(M, P->me, P->eta > 0 ? 1 : 0)) {
    /* the closest point is a node where the edges meet at a corner (no blend):
       in the fan of normals there g is the signed distance to the node, along
       the direction to the point, so that g stays continuous (C1 outside a
       convex corner) */
    const PetscReal d[2] = {xs[0] - P->xm[0], xs[1] - P->xm[1]}, dist = PetscSqrtReal(d[0] * d[0] + d[1] * d[1]);
    if (dist > 0) {
      const PetscReal sg = ContactGapNodeSide(M, P->me, P->eta > 0 ? 1 : 0, d);
      P->gap             = sg * dist;
      P->n[0]            = sg * d[0] / dist;
      P->n[1]            = sg * d[1] / dist;
      P->fan             = PETSC_TRUE;
    }
  }
}

/* Beyond end je (+-1) of master edge P->me, which ends the master surface
   at its node v = x_m(je): the gap
     g = d . n1 + kappa s(eps),   d = x_s - v,   eps = d . t_out,
   with t = x_m'(je), tau = t/|t|, t_out = je tau (leaving the surface), n1
   = esign (tau_y, -tau_x) the outward normal at the end, kappa = tan(phi)
   for the turn phi of the body's boundary at v (surface.c's endTurn)
   clipped to [-45, 45] degrees, and s the overhang past the end smoothed
   over a length h0 (1 % of the end edge): s = 0 for eps <= 0, eps^2 / (2 h0)
   up to h0, eps - h0/2 beyond. d . n1 is the gap to the end's tangent line;
   kappa s lifts it along the overhang:
   - where the boundary goes on smoothly (phi = 0), g is the gap to the
     tangent line (kappa = 0), as it was;
   - where it turns by up to 45 degrees (a chamfer), g = 0 along the line on
     which the body goes on (past h0), so that a point is in contact where it
     lies inside the master body;
   - at a sharper corner (a square punch's), a point past the end is in
     contact only under the corner's 45 degree cone, where its overhang is
     less than its penetration d . (-n1) (plus h0/2): the penalty's own
     regularisation, as deep as the penetration p/k_p, never a point below
     the tangent line farther out (the block's top beside a punch, which
     followed that line and carried a pressure everywhere). A sharper
     concave end alike.
   g is continuous and C1 across the end's normal line (s = s' = 0 there),
   whatever the turn, so the energy stays smooth wherever the point goes, and
   a slave surface that ends flush with the master (eps of round-off) keeps
   its gap to round-off.
   Derivatives. With theta the angle of t (dtheta = tau_p . dt / |t|,
   tau_p = (-tau_y, tau_x), dt = sum_j M_j'(je) du_j, d2theta = -2 (tau .
   dt)(tau_p . dt) / |t|^2), dn1/dtheta = esign tau, dt_out/dtheta = je
   tau_p, and Delta = du_s - sum_j M_j(je) du_j:
     dg  = m . Delta + q dtheta,   m = n1 + kappa s' t_out,   q = d . v,
           v = esign tau + kappa s' je tau_p,
     d2g = 2 (v . Delta) dtheta - (d . m) dtheta^2 + q d2theta
           + kappa s'' deps^2,   deps = t_out . Delta + je (d . tau_p) dtheta. */
static PetscReal ContactGapLift(const ContactSurface *M, PetscInt e, PetscInt j)
{
  return PetscTanReal(PetscMax(-0.25 * PETSC_PI, PetscMin(0.25 * PETSC_PI, M->endTurn[M->mnodes[7 * e + j]])));
}

PetscReal ContactGapRampLength(const ContactSurface *M, PetscInt e, PetscInt j)
{
  return ContactGapLift(M, e, j) != 0.0 ? 0.01 * M->elen[e] : 0.0;
}

static void ContactGapBeyondEnd(const ContactSurface *M, const PetscReal xs[2], PetscReal je, ContactGap *P)
{
  const PetscReal es = M->esign[P->me], kappa = ContactGapLift(M, P->me, je > 0 ? 1 : 0), h0 = 0.01 * M->elen[P->me];
  PetscReal       d[2], tp[2], eps, sv, s1, s2, dn1;

  MasterShape(M, P->me, je, P->M7, P->dM7, P->d2M7);
  MasterCombine(M, P->me, P->M7, P->dM7, P->d2M7, P->xm, P->tm, P->xpp);
  ContactGapNormal(M, xs, P); /* n1, |t|, d . n1 */
  dn1      = P->gap;
  d[0]     = xs[0] - P->xm[0];
  d[1]     = xs[1] - P->xm[1];
  P->et[0] = P->tm[0] / P->tn;
  P->et[1] = P->tm[1] / P->tn;
  P->en[0] = P->n[0];
  P->en[1] = P->n[1];
  tp[0]    = -P->et[1];
  tp[1]    = P->et[0];
  eps      = je * (d[0] * P->et[0] + d[1] * P->et[1]);
  P->ramp  = (PetscBool)(kappa != 0.0 && eps > 0 && eps < h0);
  if (eps <= 0) sv = s1 = s2 = 0.0;
  else if (eps < h0) {
    sv = 0.5 * eps * eps / h0;
    s1 = eps / h0;
    s2 = 1.0 / h0;
  } else {
    sv = eps - 0.5 * h0;
    s1 = 1.0;
    s2 = 0.0;
  }
  for (PetscInt c = 0; c < 2; ++c) {
    P->n[c]   = P->en[c] + kappa * s1 * je * P->et[c];
    P->ev[c]  = es * P->et[c] + kappa * s1 * je * tp[c];
    P->xpp[c] = 0.0;
  }
  P->gap   = dn1 + kappa * sv;
  P->eq    = d[0] * P->ev[0] + d[1] * P->ev[1];
  P->egt   = dn1 + kappa * s1 * eps;
  P->es2   = kappa * s2;
  P->edp   = d[0] * tp[0] + d[1] * tp[1];
  P->je    = je;
  P->delta = -es * P->eq / P->tn; /* q dtheta = delta sum_j M_j' (n1 . du_j), n1 = -esign tau_p */
  for (PetscInt j = 0; j < 7; ++j) P->d2M7[j] = 0.0;
  P->eta = je;
  P->ext = PETSC_TRUE;
  P->fan = PETSC_FALSE;
}

void ContactGapMasterWeight(const ContactGap *P, PetscInt j, PetscReal w[2])
{
  for (PetscInt c = 0; c < 2; ++c) w[c] = P->M7[j] * P->n[c] - (P->ext ? P->delta * P->dM7[j] * P->en[c] : 0.0);
}

/* The closest point of the master half itself. */
static void ContactGapProjectHalf(const ContactSurface *M, ContactSearch search, const PetscReal xs[2], ContactGap *P)
{
  const PetscInt *mn;

  P->eta  = 0.0;
  P->ext  = PETSC_FALSE;
  P->ramp = PETSC_FALSE;
  ContactSearchFindClosest(search, xs, &P->me, &P->eta);
  if (P->me < 0) return;
  mn = &M->mnodes[7 * P->me];
  /* beyond an end of the master surface: its straight extension. A positive
     gap there is no contact; a negative one is a point pushed past the end,
     whose energy must not vanish as it crosses the end's normal line. Not at
     the cut of a half model, which the mirror image continues (a corner) */
  if (P->eta <= -1.0 && M->endNode[mn[0]] && ContactSurfaceCutSide(M, mn[0]) == 0) ContactGapBeyondEnd(M, xs, -1.0, P);
  else if (P->eta >= 1.0 && M->endNode[mn[1]] && ContactSurfaceCutSide(M, mn[1]) == 0) ContactGapBeyondEnd(M, xs, 1.0, P);
  else ContactGapEvaluate(M, xs, P);
}

/* The slave's normal: n, or its reflection where the closest point is on the mirror image. */
static void ContactGapSetMirror(ContactGap *P, PetscBool mirror)
{
  P->mirror = mirror;
  P->ns[0]  = P->n[0];
  P->ns[1]  = mirror ? -P->n[1] : P->n[1];
}

void ContactGapProject(const ContactSurface *M, ContactSearch search, const PetscReal xs[2], ContactGap *P)
{
  ContactGapProjectHalf(M, search, xs, P);
  ContactGapSetMirror(P, PETSC_FALSE);
  if (M->mirror && P->me >= 0 && xs[1] - M->mirrorY < M->mirrorReach + PetscAbsReal(P->gap)) {
    const PetscReal xr[2] = {xs[0], ContactSurfaceMirrorY(M, xs[1])};
    ContactGap      R;
    ContactGapProjectHalf(M, search, xr, &R);
    if (R.me >= 0 && PetscAbsReal(R.gap) < PetscAbsReal(P->gap)) { /* a tie (a point on the line) keeps the half's own */
      *P = R;
      ContactGapSetMirror(P, PETSC_TRUE);
    }
  }
}

void ContactGapOnEdge(const ContactSurface *M, PetscInt e, PetscBool mirror, const PetscReal xs[2], ContactGap *P)
{
  const PetscReal xr[2] = {xs[0], mirror ? ContactSurfaceMirrorY(M, xs[1]) : xs[1]};
  PetscReal       d2;

  P->me   = e;
  P->ext  = PETSC_FALSE;
  P->ramp = PETSC_FALSE;
  MasterProject(M, e, xr, &P->eta, &d2);
  ContactGapEvaluate(M, xr, P);
  ContactGapSetMirror(P, mirror);
}

void ContactGapIndices(const ContactSurface *S, const PetscInt sn[3], const ContactSurface *M, const ContactGap *P, PetscInt idx[20])
{
  const PetscInt *mn = &M->mnodes[7 * P->me];

  for (PetscInt d = 0; d < 2; ++d) {
    for (PetscInt i = 0; i < 3; ++i) idx[2 * i + d] = S->big[2 * sn[i] + d];
    for (PetscInt j = 0; j < 7; ++j) idx[6 + 2 * j + d] = M->big[2 * mn[j] + d];
  }
}

void ContactGapFirst(const ContactGap *P, const PetscReal N[3], PetscReal dg[20])
{
  for (PetscInt d = 0; d < 2; ++d) {
    for (PetscInt i = 0; i < 3; ++i) dg[2 * i + d] = N[i] * P->ns[d];
  }
  for (PetscInt j = 0; j < 7; ++j) {
    PetscReal w[2];
    ContactGapMasterWeight(P, j, w);
    for (PetscInt d = 0; d < 2; ++d) dg[6 + 2 * j + d] = -w[d];
  }
}

void ContactGapAddSecond(const ContactGap *P, const PetscReal N[3], PetscReal c, PetscScalar K[400])
{
  const PetscReal tau[2] = {P->tm[0] / P->tn, P->tm[1] / P->tn};
  const PetscReal kappa = P->n[0] * P->xpp[0] + P->n[1] * P->xpp[1], D = P->tn * P->tn - P->gap * kappa;
  const PetscReal r[2]  = {1.0, P->mirror ? -1.0 : 1.0}; /* the slave rows of a reflected point */
  PetscReal       a[20], b[20];

  if (P->fan) {
    const PetscReal t[2] = {-P->n[1], P->n[0]};
    for (PetscInt d = 0; d < 2; ++d) {
      for (PetscInt i = 0; i < 3; ++i) a[2 * i + d] = N[i] * r[d] * t[d];
      for (PetscInt j = 0; j < 7; ++j) a[6 + 2 * j + d] = -P->M7[j] * t[d];
    }
    for (PetscInt i = 0; i < 20; ++i)
      for (PetscInt j = 0; j < 20; ++j) K[i * 20 + j] += c * a[i] * a[j] / P->gap;
    return;
  }
  if (P->ext) { /* past an end: ContactGapBeyondEnd */
    const PetscReal tp[2] = {-P->et[1], P->et[0]};
    PetscReal       B[20], C[20], E[20];
    for (PetscInt d = 0; d < 2; ++d) {
      for (PetscInt i = 0; i < 3; ++i) {
        a[2 * i + d] = N[i] * r[d] * P->ev[d];
        E[2 * i + d] = N[i] * r[d] * P->je * P->et[d];
        B[2 * i + d] = C[2 * i + d] = 0.0;
      }
      for (PetscInt j = 0; j < 7; ++j) {
        a[6 + 2 * j + d] = -P->M7[j] * P->ev[d];
        B[6 + 2 * j + d] = P->dM7[j] * tp[d] / P->tn;
        C[6 + 2 * j + d] = P->dM7[j] * P->et[d] / P->tn;
        E[6 + 2 * j + d] = -P->M7[j] * P->je * P->et[d] + P->je * P->edp * B[6 + 2 * j + d];
      }
    }
    for (PetscInt i = 0; i < 20; ++i)
      for (PetscInt j = 0; j < 20; ++j) K[i * 20 + j] += c * (a[i] * B[j] + B[i] * a[j] - P->egt * B[i] * B[j] - P->eq * (C[i] * B[j] + B[i] * C[j]) + P->es2 * E[i] * E[j]);
    return;
  }
  if (PetscAbsReal(P->eta) >= 1.0) return;
  for (PetscInt d = 0; d < 2; ++d) {
    for (PetscInt i = 0; i < 3; ++i) {
      a[2 * i + d] = N[i] * r[d] * tau[d];
      b[2 * i + d] = 0.0;
    }
    for (PetscInt j = 0; j < 7; ++j) {
      a[6 + 2 * j + d] = -P->M7[j] * tau[d];
      b[6 + 2 * j + d] = P->dM7[j] * P->n[d];
    }
  }
  for (PetscInt i = 0; i < 20; ++i)
    for (PetscInt j = 0; j < 20; ++j) K[i * 20 + j] -= c * (kappa * a[i] * a[j] + P->gap * b[i] * b[j] + P->tn * (a[i] * b[j] + b[i] * a[j])) / D;
}
