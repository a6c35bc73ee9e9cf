#pragma once
#include "surface.h"
#include "shape1d.h"

/* The quadratic edge of a contact surface (edge.c): shape functions, the
   master edge with its C1 blend into the neighbouring edges, and the
   closest-point projection onto it. The evaluations are inline: they sit in
   the innermost loops of every formulation. */

/* Point and tangent at e of the quadratic edge through nodes en of x[][2]. */
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
   x_m(eta) = sum_j M_j(eta) x_j (nodes M->mnodes[7 e + j]). */
static inline void MasterShape(const ContactSurface *M, PetscInt e, PetscReal eta, PetscReal N[7], PetscReal dN[7], PetscReal d2N[7])
{
  const PetscReal W = M->blend, *A = &M->mcorr[14 * e], *B = A + 7;
  const PetscReal sa = eta + 1.0, sb = 1.0 - eta;

  EdgeShape(eta, N, dN);
  d2N[0] = d2N[1] = 1.0;
  d2N[2]          = -2.0;
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
   functions at some eta, in the current coordinates. */
static inline void MasterCombine(const ContactSurface *M, PetscInt e, const PetscReal N[7], const PetscReal dN[7], const PetscReal d2N[7], PetscReal p[2], PetscReal t[2], PetscReal tpp[2])
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
static inline void MasterEval(const ContactSurface *M, PetscInt e, PetscReal eta, PetscReal p[2], PetscReal t[2], PetscReal tpp[2])
{
  PetscReal N[7], dN[7], d2N[7];

  MasterShape(M, e, eta, N, dN, d2N);
  MasterCombine(M, e, N, dN, d2N, p, t, tpp);
}

/* Closest point of master edge e to p: eta in [-1, 1] and the squared distance. */
void MasterProject(const ContactSurface *M, PetscInt e, const PetscReal p[2], PetscReal *eta, PetscReal *dist2);

/* Sets up the blend of every edge (M->mnodes, M->mcorr) from the surface's
   node degrees and node-to-edge adjacency (adj[adjStart[v] .. adjStart[v+1]]). */
PetscErrorCode ContactSurfaceSetUpBlend(ContactSurface *M, const PetscInt deg[], const PetscInt adj[], const PetscInt adjStart[]);
