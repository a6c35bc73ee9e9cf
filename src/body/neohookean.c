/* Pointwise kernels of the compressible neo-Hookean material
   (-<body>_material neohookean), total Lagrangian, in plane strain and in
   axisymmetry (material.h gives the arguments).

   Field: displacement u(X) of the reference point X; the deformation gradient
   is F = I + grad u with the in-plane block F_iJ = d_iJ + gu[i*2+J] and one
   out-of-plane stretch F33 = 1 + e3: 1 in plane strain (e3 = 0), 1 + u_r/r
   in axisymmetry (x = r, y = z: the hoop stretch r/R; on the axis, where
   u_r = 0, its limit 1 + du_r/dr, as elasticity.c's hoop strain). F is block
   diagonal, so J = det F = (F00 F11 - F01 F10) F33 and F^-1 is block
   diagonal with (F^-1)33 = 1/F33. params = {lambda, mu}, Lame's constants
   from E and nu.

   Energy per unit reference volume, I1 = tr(F^T F) = sum F_iJ^2 + F33^2:
       W(F) = mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2,
   so that Pi(u) = int W dV over the reference body (dV = dA in plane
   strain, 2 pi R dA in axisymmetry). At F = I + H, with H small,
   W = lambda/2 (tr H)^2 + mu |sym H|^2 + O(|H|^3): linear elasticity's.
   W grows without bound as J -> 0+; for J <= 0 (an inverted material
   point) W is +inf, so that a line search backs off a step that inverts
   an element, and the gradient there is left zero.

   First Piola-Kirchhoff stress, P = dW/dF (with dJ/dF = J F^-T, dI1/dF = 2F):
       P_iJ = mu (F_iJ - F^-1_Ji) + lambda ln J F^-1_Ji,
       P33  = mu (F33 - 1/F33) + lambda ln J / F33.
   Gradient: dPi/du_(a i) = int (P_iJ dN_a/dX_J + d_i0 P33 N_a / r) dV, since
   dF_iJ/du_(a i) = dN_a/dX_J and, in axisymmetry, dF33/du_(a r) = N_a / r.

   Tangent, A_iJkL = dP_iJ/dF_kL (with dF^-1_Ji/dF_kL = -F^-1_Jk F^-1_Li):
       A_iJkL   = mu d_ik d_JL + (mu - lambda ln J) F^-1_Jk F^-1_Li + lambda F^-1_Ji F^-1_Lk,
       A_iJ33   = lambda F^-1_Ji / F33           (in-plane i, J: F^-1_J3 = 0),
       A_3333   = mu + (mu - lambda ln J + lambda) / F33^2.
   Hessian (exact, symmetric; indefinite where the material is compressed
   far enough):
       d2Pi/du_(a i) du_(b j) = int [ A_iJjL dN_a/dX_J dN_b/dX_L
            + d_i0 (N_a/r) A_jL33 dN_b/dX_L + d_j0 (N_b/r) A_iJ33 dN_a/dX_J
            + d_i0 d_j0 A_3333 N_a N_b / r^2 ] dV,
   the last three terms in axisymmetry only. At F = I, A is linear
   elasticity's C (A_iJ33 = lambda d_iJ, A_3333 = lambda + 2 mu), so the
   stiffness at rest is the linear body's.

   Cauchy stress, sigma = P F^T / J = mu/J (F F^T - I) + lambda ln J / J I:
   in-plane sigma_ij = mu/J (b_ij - d_ij) + lambda ln J / J d_ij with
   b = F F^T, and sigma33 = mu/J (F33^2 - 1) + lambda ln J / J, the stress of
   the deformed configuration, written at the material point's reference
   position (fields.c).

   Round-off: I1 - 3 and ln J are formed from the displacement gradient
   (I1 - 3 = 2 tr H + |H|^2, ln J = log1p(J - 1)), not from F, so that W at
   small strain is not the difference of numbers of order one. */
#include "contact.h"
#include "material.h"

/* F^-1 of the in-plane block (Fi[J*2+i] = F^-1_Ji), J and ln J; false if J <= 0. */
static PetscBool NeoHookeanKinematics(const PetscReal gu[], PetscReal e3, PetscReal F[4], PetscReal Fi[4], PetscReal *J, PetscReal *lnJ)
{
  const PetscReal d2m1 = gu[0] + gu[3] + gu[0] * gu[3] - gu[1] * gu[2]; /* det of the in-plane block, minus 1 */
  const PetscReal Jm1  = d2m1 + e3 + d2m1 * e3;
  const PetscReal d2   = 1.0 + d2m1;

  F[0] = 1.0 + gu[0];
  F[1] = gu[1];
  F[2] = gu[2];
  F[3] = 1.0 + gu[3];
  *J   = 1.0 + Jm1;
  if (!(*J > 0.0) || !(1.0 + e3 > 0.0)) return PETSC_FALSE;
  *lnJ  = log1p(Jm1);
  Fi[0] = F[3] / d2;
  Fi[1] = -F[1] / d2;
  Fi[2] = -F[2] / d2;
  Fi[3] = F[0] / d2;
  return PETSC_TRUE;
}

static PetscBool NeoHookeanEnergy(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscReal *W, PetscReal P[], PetscReal *P33)
{
  const PetscReal lambda = param[0], mu = param[1], F33 = 1.0 + e3;
  PetscReal       F[4], Fi[4], J, lnJ, I1m3;

  if (!NeoHookeanKinematics(gu, e3, F, Fi, &J, &lnJ)) {
    *W   = (PetscReal)INFINITY;
    P[0] = P[1] = P[2] = P[3] = 0.0;
    *P33 = 0.0;
    return PETSC_FALSE;
  }
  I1m3 = 2.0 * (gu[0] + gu[3] + e3) + gu[0] * gu[0] + gu[1] * gu[1] + gu[2] * gu[2] + gu[3] * gu[3] + e3 * e3;
  *W   = 0.5 * mu * (I1m3 - 2.0 * lnJ) + 0.5 * lambda * lnJ * lnJ;
  for (PetscInt i = 0; i < 2; ++i)
    for (PetscInt Jx = 0; Jx < 2; ++Jx) P[i * 2 + Jx] = mu * (F[i * 2 + Jx] - Fi[Jx * 2 + i]) + lambda * lnJ * Fi[Jx * 2 + i];
  *P33 = mu * (F33 - 1.0 / F33) + lambda * lnJ / F33;
  return PETSC_TRUE;
}

static void NeoHookeanCauchy(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscReal sigma[], PetscReal *s33)
{
  const PetscReal lambda = param[0], mu = param[1], F33 = 1.0 + e3;
  PetscReal       F[4], Fi[4], J, lnJ, bm[4];

  if (!NeoHookeanKinematics(gu, e3, F, Fi, &J, &lnJ)) {
    sigma[0] = sigma[1] = sigma[2] = sigma[3] = *s33 = (PetscReal)NAN;
    return;
  }
  /* b - I, from gu: b_ij - d_ij = gu_ij + gu_ji + gu_iK gu_jK */
  for (PetscInt i = 0; i < 2; ++i)
    for (PetscInt j = 0; j < 2; ++j) bm[i * 2 + j] = gu[i * 2 + j] + gu[j * 2 + i] + gu[i * 2] * gu[j * 2] + gu[i * 2 + 1] * gu[j * 2 + 1];
  sigma[0] = (mu * bm[0] + lambda * lnJ) / J;
  sigma[1] = mu * bm[1] / J;
  sigma[2] = mu * bm[2] / J;
  sigma[3] = (mu * bm[3] + lambda * lnJ) / J;
  *s33     = (mu * e3 * (2.0 + e3) + lambda * lnJ) / J;
  (void)F33;
}

/* The tangent at (gu, e3): A[((i*2+J)*2+k)*2+L] in-plane, a3[i*2+J] = A_iJ33, a33 = A_3333. */
static void NeoHookeanModuli(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscReal A[], PetscReal a3[], PetscReal *a33)
{
  const PetscReal lambda = param[0], mu = param[1], F33 = 1.0 + e3;
  PetscReal       F[4], Fi[4], J, lnJ, m;

  if (!NeoHookeanKinematics(gu, e3, F, Fi, &J, &lnJ)) { /* never asked: an inverted state is never accepted */
    PetscArrayzero(A, 16);
    PetscArrayzero(a3, 4);
    *a33 = 0.0;
    return;
  }
  m = mu - lambda * lnJ;
  for (PetscInt i = 0; i < 2; ++i)
    for (PetscInt Jx = 0; Jx < 2; ++Jx) {
      for (PetscInt k = 0; k < 2; ++k)
        for (PetscInt L = 0; L < 2; ++L) A[((i * 2 + Jx) * 2 + k) * 2 + L] = mu * (i == k) * (Jx == L) + m * Fi[Jx * 2 + k] * Fi[L * 2 + i] + lambda * Fi[Jx * 2 + i] * Fi[L * 2 + k];
      a3[i * 2 + Jx] = lambda * Fi[Jx * 2 + i] / F33;
    }
  *a33 = mu + (m + lambda) / (F33 * F33);
}

static void NeoHookeanTangent(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscInt nb, PetscReal w, const PetscReal dN[], const PetscReal B[], PetscReal r, PetscScalar K[])
{
  const PetscInt n = 2 * nb;
  PetscReal      A[16], a3[4], a33;

  NeoHookeanModuli(param, gu, e3, A, a3, &a33);
  ElasticityAddTangent(A, nb, w, dN, K);
  if (r > 0)
    for (PetscInt a = 0; a < nb; ++a)
      for (PetscInt bb = a; bb < nb; ++bb) {
        const PetscReal na = B[a] / r, nbb = B[bb] / r;
        for (PetscInt i = 0; i < 2; ++i)
          for (PetscInt j = 0; j < 2; ++j) {
            PetscReal k = 0.0;
            if (i == 0) k += na * (a3[j * 2] * dN[2 * bb] + a3[j * 2 + 1] * dN[2 * bb + 1]);
            if (j == 0) k += nbb * (a3[i * 2] * dN[2 * a] + a3[i * 2 + 1] * dN[2 * a + 1]);
            if (i == 0 && j == 0) k += a33 * na * nbb;
            K[(2 * a + i) * n + 2 * bb + j] += w * k;
          }
      }
}

const Material MaterialNeoHookean = {"neohookean", PETSC_FALSE, NeoHookeanEnergy, NeoHookeanCauchy, NeoHookeanModuli, NeoHookeanTangent};
