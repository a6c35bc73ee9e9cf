/* The quadratic edge as master: closest-point projection and the set-up of the
   C1 blend of each edge into its neighbours (the evaluations are inline in
   edge.h).

   Master corners. Adjacent quadratic edges meet at a node with a small corner
   (the kink of the finite element displacement: a few 1e-3 rad at h = 0.06).
   A penetrating slave point that crosses the bisector of a corner switches
   normals, so the gap is only C0 there and its gradient jumps by about force
   times corner angle: Newton then stalls (gradient 1e-7 of its start near 1e6
   dofs, with hundreds of line-search evaluations). So over a zone of each
   master edge's ends (-contact_blend, a fraction of the edge, default 0.05)
   the edge's end tangent is blended into the mean of its own and its
   neighbour's (MasterShape): the master surface is C1. x_m stays linear in the
   nodal coordinates (seven nodes: the edge's and its neighbours' others). The
   blend moves the surface by at most 4/27 of the zone times the tangent jump;
   a wider blend departs from the quadratic surface the slave points lie on
   (relative L2 error of the hertz profile at h = 0.06: 10.68 % without,
   10.70 % at 0.05, 12.4 % at 0.25, 31 % at 0.5). */
#include "edge.h"

/* Closest point on master edge e: Newton on f(eta) = |x(eta) - p|^2 / 2 from
   the best of five samples, eta kept in [-1, 1]. Returns eta and the squared
   distance. */
void MasterProject(const ContactSurface *M, PetscInt ed, const PetscReal p[2], PetscReal *eta, PetscReal *dist2)
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

/* As master, edge e's end tangent at a node it shares with one other edge is
   blended into the mean of the two (see MasterShape), unless the edges meet
   at a real corner (more than 30 degrees in the reference configuration). */
PetscErrorCode ContactSurfaceSetUpBlend(ContactSurface *S, const PetscInt deg[], const PetscInt adj[], const PetscInt adjStart[])
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
