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
   there the master is continued by its tangent line (ContactGapExtend), so a
   deeply penetrated iterate's gap is continuous wherever the point goes.

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

/* Beyond end je (+-1) of master edge P->me, which ends the master surface:
   the gap to the edge's tangent line there, x_m(eta) = x_m(je) + (eta - je)
   x_m'(je), a straight extension whose shape functions M_j(je) + (eta - je)
   M_j'(je) are linear in eta. The projection onto it is orthogonal, so dg and
   d2g keep their form (with x_m'' = 0), and g is C1 across the normal line
   at the end: a point that an iterate pushes past the end of the master
   surface keeps its gap, and the energy stays continuous. */
static void ContactGapExtend(const ContactSurface *M, const PetscReal xs[2], PetscReal je, ContactGap *P)
{
  PetscReal delta;

  MasterShape(M, P->me, je, P->M7, P->dM7, P->d2M7);
  MasterCombine(M, P->me, P->M7, P->dM7, P->d2M7, P->xm, P->tm, P->xpp);
  delta = ((xs[0] - P->xm[0]) * P->tm[0] + (xs[1] - P->xm[1]) * P->tm[1]) / (P->tm[0] * P->tm[0] + P->tm[1] * P->tm[1]);
  if (delta * je < 0) delta = 0.0; /* the clamped projection is at the end itself */
  for (PetscInt j = 0; j < 7; ++j) {
    P->M7[j] += delta * P->dM7[j];
    P->d2M7[j] = 0.0;
  }
  for (PetscInt d = 0; d < 2; ++d) {
    P->xm[d] += delta * P->tm[d];
    P->xpp[d] = 0.0;
  }
  P->eta = je + delta;
  P->ext = PETSC_TRUE;
  P->fan = PETSC_FALSE;
  ContactGapNormal(M, xs, P);
}

/* The closest point of the master half itself. */
static void ContactGapProjectHalf(const ContactSurface *M, ContactSearch search, const PetscReal xs[2], ContactGap *P)
{
  const PetscInt *mn;

  P->eta = 0.0;
  P->ext = PETSC_FALSE;
  ContactSearchFindClosest(search, xs, &P->me, &P->eta);
  if (P->me < 0) return;
  mn = &M->mnodes[7 * P->me];
  /* beyond an end of the master surface: its straight extension. A positive
     gap there is no contact; a negative one is a point pushed past the end,
     whose energy must not vanish as it crosses the end's normal line. Not at
     the cut of a half model, which the mirror image continues (a corner) */
  if (P->eta <= -1.0 && M->endNode[mn[0]] && ContactSurfaceCutSide(M, mn[0]) == 0) ContactGapExtend(M, xs, -1.0, P);
  else if (P->eta >= 1.0 && M->endNode[mn[1]] && ContactSurfaceCutSide(M, mn[1]) == 0) ContactGapExtend(M, xs, 1.0, P);
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

  P->me  = e;
  P->ext = PETSC_FALSE;
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
    for (PetscInt j = 0; j < 7; ++j) dg[6 + 2 * j + d] = -P->M7[j] * P->n[d];
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
  if (PetscAbsReal(P->eta) >= 1.0 && !P->ext) return;
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
