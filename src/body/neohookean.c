/* Pointwise kernels of the compressible neo-Hookean material
   (-<body>_material neohookean), total Lagrangian, of the full 3 x 3
   displacement gradient: one source for plane strain, axisymmetry and 3D
   (material.h gives the arguments).

   Field: displacement u(X) of the reference point X; the deformation gradient
   is F = I + H, H[i*3+J] = du_i/dX_J: full in 3D; in plane strain row and
   column 2 zero (F22 = 1); in axisymmetry (x = r, y = z) zero but for
   H[8] = u_r / r (F22 = r/R, the hoop stretch; on the axis, where u_r = 0,
   its limit 1 + du_r/dr, as elasticity.c's hoop strain). J = det F, F^-1 =
   adj(F) / J. params = {lambda, mu}, Lame's constants from E and nu.

   Energy per unit reference volume, I1 = tr(F^T F) = sum F_iJ^2:
       W(F) = mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2,
   so that Pi(u) = int W dV over the reference body (dV = dA in plane
   strain, 2 pi R dA in axisymmetry, the volume in 3D). At F = I + H, with H
   small, W = lambda/2 (tr H)^2 + mu |sym H|^2 + O(|H|^3): linear
   elasticity's. W grows without bound as J -> 0+; for J <= 0 (an inverted
   material point) W is +inf, so that a line search backs off a step that
   inverts an element, and the stress there is left zero. W depends on F
   through I1 and J alone: W(Q F) = W(F) for a rotation Q.

   First Piola-Kirchhoff stress, P = dW/dF (with dJ/dF = J F^-T, dI1/dF = 2F):
       P_iJ = mu (F_iJ - F^-1_Ji) + lambda ln J F^-1_Ji.
   Gradient (element.c): dPi/du_(a i) = int P_iJ dF_iJ/du_(a i) dV, with
   dF_iJ/du_(a i) = dN_a/dX_J and, in axisymmetry, dF_22/du_(a r) = N_a / r.

   Tangent, A_iJkL = dP_iJ/dF_kL (with dF^-1_Ji/dF_kL = -F^-1_Jk F^-1_Li):
       A_iJkL = mu d_ik d_JL + (mu - lambda ln J) F^-1_Jk F^-1_Li + lambda F^-1_Ji F^-1_Lk,
   symmetric (A_iJkL = A_kLiJ). Hessian (exact, symmetric; indefinite where
   the material is compressed far enough; element.c contracts it):
       d2Pi/du_(a i) du_(b j) = int [ A_iJjL dN_a/dX_J dN_b/dX_L
            + d_i0 (N_a/r) A_22jL dN_b/dX_L + d_j0 (N_b/r) A_iJ22 dN_a/dX_J
            + d_i0 d_j0 A_2222 N_a N_b / r^2 ] dV,
   the last three terms in axisymmetry only (in r-z, F^-1_J2 = 0 for J < 2,
   so A_iJ22 = lambda F^-1_Ji / F22 and A_2222 = mu + (mu - lambda ln J +
   lambda) / F22^2). At F = I, A is linear elasticity's C, so the stiffness
   at rest is the linear body's.

   Cauchy stress, sigma = P F^T / J = mu/J (F F^T - I) + lambda ln J / J I:
   sigma_ij = mu/J (b_ij - d_ij) + lambda ln J / J d_ij with b = F F^T, the
   stress of the deformed configuration, written at the material point's
   reference position (fields.c).

   Round-off: I1 - 3, J - 1 and b - I are formed from the displacement
   gradient (I1 - 3 = 2 tr H + |H|^2, J - 1 = the in-plane block's
   determinant minus 1, times F22, plus the terms of row and column 2,
   ln J = log1p(J - 1)), not from F, so that W at small strain is not the
   difference of numbers of order one. Where row and column 2 are zero
   the sums add exact zeros to the 2D kernels' in their order: plane
   strain's numbers are the 2D kernels' to the bit. */
#include "contact.h"
#include "material.h"

/* Whether row and column 2 of H are zero off the diagonal (plane strain,
   r-z): F and F^-1 are then block diagonal, and F^-1's zero entries are
   set, not computed: the same numbers, fewer operations (5 divisions
   instead of 9). */
static inline PetscBool NeoHookeanBlock(const PetscReal H[])
{
  return (PetscBool)(H[2] == 0.0 && H[5] == 0.0 && H[6] == 0.0 && H[7] == 0.0);
}

/* F, F^-1 (Fi[J*3+i] = F^-1_Ji), J and ln J; false if J <= 0. */
static PetscBool NeoHookeanKinematics(const PetscReal H[], PetscBool block, PetscReal F[9], PetscReal Fi[9], PetscReal *J, PetscReal *lnJ)
{
  const PetscReal d2m1 = H[0] + H[4] + H[0] * H[4] - H[1] * H[3]; /* det of the (0, 1) block, minus 1 */
  PetscReal       Jm1;

  F[0] = 1.0 + H[0];
  F[1] = H[1];
  F[2] = H[2];
  F[3] = H[3];
  F[4] = 1.0 + H[4];
  F[5] = H[5];
  F[6] = H[6];
  F[7] = H[7];
  F[8] = 1.0 + H[8];
  /* det F = F22 det2 - F12 (F00 F21 - F01 F20) + F02 (F10 F21 - F11 F20) */
  Jm1 = d2m1 + H[8] + d2m1 * H[8];
  if (!block) Jm1 += -F[5] * (F[0] * F[7] - F[1] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
  *J = 1.0 + Jm1;
  if (!(*J > 0.0)) return PETSC_FALSE;
  *lnJ = log1p(Jm1);
  if (block) {
    Fi[0] = F[4] * F[8] / *J;
    Fi[1] = -(F[1] * F[8]) / *J;
    Fi[3] = -(F[3] * F[8]) / *J;
    Fi[4] = F[0] * F[8] / *J;
    Fi[8] = (F[0] * F[4] - F[1] * F[3]) / *J;
    Fi[2] = Fi[5] = Fi[6] = Fi[7] = 0.0;
  } else {
    Fi[0] = (F[4] * F[8] - F[5] * F[7]) / *J;
    Fi[1] = (F[2] * F[7] - F[1] * F[8]) / *J;
    Fi[2] = (F[1] * F[5] - F[2] * F[4]) / *J;
    Fi[3] = (F[5] * F[6] - F[3] * F[8]) / *J;
    Fi[4] = (F[0] * F[8] - F[2] * F[6]) / *J;
    Fi[5] = (F[2] * F[3] - F[0] * F[5]) / *J;
    Fi[6] = (F[3] * F[7] - F[4] * F[6]) / *J;
    Fi[7] = (F[1] * F[6] - F[0] * F[7]) / *J;
    Fi[8] = (F[0] * F[4] - F[1] * F[3]) / *J;
  }
  return PETSC_TRUE;
}

static PetscBool NeoHookeanEnergy(const PetscReal param[], const PetscReal state[], const PetscReal H[], PetscReal *W, PetscReal P[])
{
  const PetscReal lambda = param[0], mu = param[1];
  PetscReal       F[9], Fi[9], J, lnJ, I1m3, ll;

  (void)state; /* no history (nstate = 0) */
  if (!NeoHookeanKinematics(H, NeoHookeanBlock(H), F, Fi, &J, &lnJ)) {
    *W = (PetscReal)INFINITY;
    for (PetscInt k = 0; k < 9; ++k) P[k] = 0.0;
    return PETSC_FALSE;
  }
  I1m3 = 2.0 * (H[0] + H[4] + H[8]) + H[0] * H[0] + H[1] * H[1] + H[2] * H[2] + H[3] * H[3] + H[4] * H[4] + H[5] * H[5] + H[6] * H[6] + H[7] * H[7] + H[8] * H[8];
  *W   = 0.5 * mu * (I1m3 - 2.0 * lnJ) + 0.5 * lambda * lnJ * lnJ;
  ll   = lambda * lnJ;
#define NEO_P(i, Jx) P[i * 3 + Jx] = mu * (F[i * 3 + Jx] - Fi[Jx * 3 + i]) + ll * Fi[Jx * 3 + i]
  NEO_P(0, 0);
  NEO_P(0, 1);
  NEO_P(0, 2);
  NEO_P(1, 0);
  NEO_P(1, 1);
  NEO_P(1, 2);
  NEO_P(2, 0);
  NEO_P(2, 1);
  NEO_P(2, 2);
#undef NEO_P
  return PETSC_TRUE;
}

static void NeoHookeanCauchy(const PetscReal param[], const PetscReal state[], const PetscReal H[], PetscReal sigma[])
{
  const PetscReal lambda = param[0], mu = param[1];
  PetscReal       F[9], Fi[9], J, lnJ;

  (void)state; /* no history (nstate = 0) */
  if (!NeoHookeanKinematics(H, NeoHookeanBlock(H), F, Fi, &J, &lnJ)) {
    for (PetscInt k = 0; k < 9; ++k) sigma[k] = (PetscReal)NAN;
    return;
  }
  /* b - I, from H: b_ij - d_ij = H_ij + H_ji + H_iK H_jK */
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) {
      const PetscReal bm = H[i * 3 + j] + H[j * 3 + i] + H[i * 3] * H[j * 3] + H[i * 3 + 1] * H[j * 3 + 1] + H[i * 3 + 2] * H[j * 3 + 2];
      sigma[i * 3 + j]   = i == j ? (mu * bm + lambda * lnJ) / J : mu * bm / J;
    }
}

/* A_iJkL from mFi = m F^-1 and lFi = lambda F^-1, formed once (the same
   products, in the same order, as mu d_ik d_JL + m F^-1_Jk F^-1_Li +
   lambda F^-1_Ji F^-1_Lk). */
static inline void ModuliEntry(PetscReal mu, const PetscReal mFi[], const PetscReal lFi[], const PetscReal Fi[], PetscInt i, PetscInt Jx, PetscInt k, PetscInt L, PetscReal A[])
{
  A[((i * 3 + Jx) * 3 + k) * 3 + L] = (i == k && Jx == L ? mu : 0.0) + mFi[Jx * 3 + k] * Fi[L * 3 + i] + lFi[Jx * 3 + i] * Fi[L * 3 + k];
}

/* The tangent at H: A[(i*3+J)*9+k*3+L] = A_iJkL. Where F is block diagonal
   the entries with an odd number of indices 2 are zero (each term pairs its
   indices): the 41 others alone are formed. */
static void NeoHookeanModuli(const PetscReal param[], const PetscReal state[], const PetscReal H[], PetscReal A[])
{
  const PetscReal lambda = param[0], mu = param[1];
  const PetscBool block = NeoHookeanBlock(H);
  PetscReal       F[9], Fi[9], J, lnJ, m, mFi[9], lFi[9];

  (void)state; /* no history (nstate = 0) */
  if (!NeoHookeanKinematics(H, block, F, Fi, &J, &lnJ)) { /* never asked: an inverted state is never accepted */
    for (PetscInt k = 0; k < 81; ++k) A[k] = 0.0;
    return;
  }
  m = mu - lambda * lnJ;
  for (PetscInt k = 0; k < 9; ++k) {
    mFi[k] = m * Fi[k];
    lFi[k] = lambda * Fi[k];
  }
  if (!block) {
    for (PetscInt i = 0; i < 3; ++i)
      for (PetscInt Jx = 0; Jx < 3; ++Jx)
        for (PetscInt k = 0; k < 3; ++k)
          for (PetscInt L = 0; L < 3; ++L) ModuliEntry(mu, mFi, lFi, Fi, i, Jx, k, L, A);
    return;
  }
  for (PetscInt k = 0; k < 81; ++k) A[k] = 0.0;
  for (PetscInt p = 0; p < 2; ++p)
    for (PetscInt q = 0; q < 2; ++q) {
      for (PetscInt k = 0; k < 2; ++k)
        for (PetscInt L = 0; L < 2; ++L) ModuliEntry(mu, mFi, lFi, Fi, p, q, k, L, A);
      ModuliEntry(mu, mFi, lFi, Fi, 2, 2, p, q, A);
      ModuliEntry(mu, mFi, lFi, Fi, p, q, 2, 2, A);
      ModuliEntry(mu, mFi, lFi, Fi, 2, p, 2, q, A);
      ModuliEntry(mu, mFi, lFi, Fi, p, 2, q, 2, A);
      ModuliEntry(mu, mFi, lFi, Fi, 2, p, q, 2, A);
      ModuliEntry(mu, mFi, lFi, Fi, p, 2, 2, q, A);
    }
  ModuliEntry(mu, mFi, lFi, Fi, 2, 2, 2, 2, A);
}

const Material MaterialNeoHookean = {"neohookean", MaterialElasticConstantsSetFromOptions, PETSC_FALSE, NeoHookeanEnergy, NeoHookeanModuli, NeoHookeanCauchy, 0, NULL};
