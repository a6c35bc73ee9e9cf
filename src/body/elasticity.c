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

void ElasticityEnergyDensity(const PetscReal params[], const PetscReal H[], PetscReal *W)
{
  const PetscReal lambda = params[0], mu = params[1];
  const PetscReal exx = H[0], eyy = H[4], ezz = H[8];
  const PetscReal exy = 0.5 * (H[1] + H[3]), exz = 0.5 * (H[2] + H[6]), eyz = 0.5 * (H[5] + H[7]);
  const PetscReal tr = exx + eyy + ezz;

  *W = 0.5 * lambda * tr * tr + mu * (exx * exx + eyy * eyy + ezz * ezz + 2.0 * exy * exy + 2.0 * exz * exz + 2.0 * eyz * eyz);
}

void ElasticityStress(const PetscReal params[], const PetscReal H[], PetscReal sigma[])
{
  const PetscReal lambda = params[0], mu = params[1];
  const PetscReal tr = H[0] + H[4] + H[8];

  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) {
      const PetscReal e = 0.5 * (H[i * 3 + j] + H[j * 3 + i]);
      sigma[i * 3 + j]  = i == j ? lambda * tr + 2.0 * mu * e : 2.0 * mu * e;
    }
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

static PetscBool LinearEnergy(const PetscReal param[], const PetscReal H[], PetscReal *W, PetscReal P[])
{
  ElasticityEnergyDensity(param, H, W);
  ElasticityStress(param, H, P);
  return PETSC_TRUE;
}

static void LinearModuli(const PetscReal param[], const PetscReal H[], PetscReal A[])
{
  (void)H;
  ElasticityTangent(param, A);
}

const Material MaterialLinear = {"linear", PETSC_TRUE, LinearEnergy, LinearModuli, ElasticityStress};
