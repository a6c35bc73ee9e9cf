/* Pointwise kernels of linear elasticity, of the full 3 x 3 displacement
   gradient: one source for plane strain, axisymmetry and 3D (material.h).

   Field: displacement u(x); H[i*3+j] = du_i/dx_j, with row and column 2
   zero in plane strain (eps_zz = 0) and, in axisymmetry (x = r, y = z),
   zero but for H[8] = u_r / r, the hoop strain eps_thth (on the axis, where
   u_r = 0, its limit du_r/dr: ElasticityHoopStrain). params = {lambda, mu}
   (Lame constants). Strain eps = (H + H^T)/2, tr = eps_kk.
   Stress:                  sigma = lambda tr I + 2 mu eps,
   Energy density:          W = lambda/2 tr^2 + mu eps : eps
                              = lambda/2 tr^2 + mu (exx^2 + eyy^2 + ezz^2 + 2 exy^2 + 2 exz^2 + 2 eyz^2),
   so that Pi(u) = int W dV, dPi/du_a = int sigma : dH/du_a dV (gradient:
   in axisymmetry dH_22/du_(a r) = N_a / r) and d2Pi/du_a du_b = int
   dH/du_a : C : dH/du_b dV (Hessian) with the tangent
   C_ijkl = lambda d_ij d_kl + mu (d_ik d_jl + d_il d_jk); dV is dA in plane
   strain, 2 pi r dA in axisymmetry, the volume in 3D. These are the
   material "linear" (material.h): its stress is sigma and its tangent C,
   whatever the displacement. The sums are written so that, where the
   entries of row and column 2 are zero, they add exact zeros to the 2D
   sums in the 2D order: plane strain's numbers are the 2D kernels' to the
   bit. */
#include "contact.h"
#include "material.h"

/* The strain's six components e = {xx, yy, zz, xy, xz, yz} and tr. */
static inline PetscReal Strain(const PetscReal H[], PetscReal e[6])
{
  e[0] = H[0];
  e[1] = H[4];
  e[2] = H[8];
  e[3] = 0.5 * (H[1] + H[3]);
  e[4] = 0.5 * (H[2] + H[6]);
  e[5] = 0.5 * (H[5] + H[7]);
  return e[0] + e[1] + e[2];
}

static inline PetscReal Energy(PetscReal lambda, PetscReal mu, const PetscReal e[6], PetscReal tr)
{
  return 0.5 * lambda * tr * tr + mu * (e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + 2.0 * e[3] * e[3] + 2.0 * e[4] * e[4] + 2.0 * e[5] * e[5]);
}

static inline void Stress(PetscReal lambda, PetscReal mu, const PetscReal e[6], PetscReal tr, PetscReal sigma[])
{
  const PetscReal lt = lambda * tr;

  sigma[0] = lt + 2.0 * mu * e[0];
  sigma[4] = lt + 2.0 * mu * e[1];
  sigma[8] = lt + 2.0 * mu * e[2];
  sigma[1] = sigma[3] = 2.0 * mu * e[3];
  sigma[2] = sigma[6] = 2.0 * mu * e[4];
  sigma[5] = sigma[7] = 2.0 * mu * e[5];
}

void ElasticityEnergyDensity(const PetscReal params[], const PetscReal H[], PetscReal *W)
{
  PetscReal e[6], tr = Strain(H, e);

  *W = Energy(params[0], params[1], e, tr);
}

void ElasticityStress(const PetscReal params[], const PetscReal H[], PetscReal sigma[])
{
  PetscReal e[6], tr = Strain(H, e);

  Stress(params[0], params[1], e, tr, sigma);
}

PetscReal ElasticityStrain(const PetscReal H[], PetscReal e[6])
{
  return Strain(H, e);
}

void ElasticityStrainEnergyStress(const PetscReal params[], const PetscReal e[6], PetscReal *W, PetscReal sigma[])
{
  const PetscReal tr = e[0] + e[1] + e[2];

  *W = Energy(params[0], params[1], e, tr);
  Stress(params[0], params[1], e, tr, sigma);
}

PetscReal ElasticityHoopStrain(PetscReal ur, PetscReal durdr, PetscReal r)
{
  return r > 0 ? ur / r : durdr;
}

void ElasticityTangent(const PetscReal params[], PetscReal C[])
{
  const PetscReal lambda = params[0], mu = params[1];

  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j)
      for (PetscInt k = 0; k < 3; ++k)
        for (PetscInt l = 0; l < 3; ++l) C[((i * 3 + j) * 3 + k) * 3 + l] = lambda * (i == j) * (k == l) + mu * ((i == k) * (j == l) + (i == l) * (j == k));
}

/* von Mises equivalent stress of a symmetric 3 x 3 stress sigma[i*3+j]. */
PetscReal ElasticityVonMises(const PetscReal s[])
{
  const PetscReal d = (s[0] - s[4]) * (s[0] - s[4]) + (s[4] - s[8]) * (s[4] - s[8]) + (s[8] - s[0]) * (s[8] - s[0]);

  return PetscSqrtReal(0.5 * d + 3.0 * s[1] * s[1] + 3.0 * s[2] * s[2] + 3.0 * s[5] * s[5]);
}

static PetscBool LinearEnergy(const PetscReal param[], const PetscReal state[], const PetscReal H[], PetscReal *W, PetscReal P[])
{
  PetscReal e[6], tr = Strain(H, e);

  (void)state; /* no history (nstate = 0) */
  *W = Energy(param[0], param[1], e, tr);
  Stress(param[0], param[1], e, tr, P);
  return PETSC_TRUE;
}

static void LinearModuli(const PetscReal param[], const PetscReal state[], const PetscReal H[], PetscReal A[])
{
  (void)state; /* no history (nstate = 0) */
  (void)H;
  ElasticityTangent(param, A);
}

static void LinearCauchy(const PetscReal param[], const PetscReal state[], const PetscReal H[], PetscReal sigma[])
{
  (void)state; /* no history (nstate = 0) */
  ElasticityStress(param, H, sigma);
}

const Material MaterialLinear = {"linear", MaterialElasticConstantsSetFromOptions, PETSC_TRUE, LinearEnergy, LinearModuli, LinearCauchy, 0, NULL};
