/* Pointwise kernels of plane-strain linear elasticity.

   Field: displacement u(x) in R^2; gradu[i*2+j] = du_i/dx_j.
   Strain eps = (gradu + gradu^T)/2; params = {lambda, mu} (Lame constants).
   Stress (plane strain):  sigma = lambda tr(eps) I + 2 mu eps,
                           sigma_zz = lambda tr(eps).
   Energy density:         W = lambda/2 tr(eps)^2 + mu eps:eps,
   so that Pi(u) = int W dA, dPi/du_a = int sigma : grad N_a dA (gradient) and
   d2Pi/du_a du_b = int grad N_a : C : grad N_b dA (Hessian) with the tangent
   C_ijkl = lambda d_ij d_kl + mu (d_ik d_jl + d_il d_jk). */
#include "contact.h"

void ElasticityEnergyDensity(const PetscReal params[], const PetscReal gradu[], PetscReal *W)
{
  const PetscReal lambda = params[0], mu = params[1];
  const PetscReal exx = gradu[0], eyy = gradu[3], exy = 0.5 * (gradu[1] + gradu[2]);
  const PetscReal tr = exx + eyy;

  *W = 0.5 * lambda * tr * tr + mu * (exx * exx + eyy * eyy + 2.0 * exy * exy);
}

void ElasticityStress(const PetscReal params[], const PetscReal gradu[], PetscReal sigma[])
{
  const PetscReal lambda = params[0], mu = params[1];
  const PetscReal exx = gradu[0], eyy = gradu[3], exy = 0.5 * (gradu[1] + gradu[2]);
  const PetscReal tr = exx + eyy;

  sigma[0] = lambda * tr + 2.0 * mu * exx;
  sigma[1] = 2.0 * mu * exy;
  sigma[2] = 2.0 * mu * exy;
  sigma[3] = lambda * tr + 2.0 * mu * eyy;
}

PetscReal ElasticityStressZZ(const PetscReal params[], const PetscReal gradu[])
{
  return params[0] * (gradu[0] + gradu[3]);
}

void ElasticityTangent(const PetscReal params[], PetscReal C[])
{
  const PetscReal lambda = params[0], mu = params[1];

  for (PetscInt i = 0; i < 2; ++i)
    for (PetscInt j = 0; j < 2; ++j)
      for (PetscInt k = 0; k < 2; ++k)
        for (PetscInt l = 0; l < 2; ++l) C[((i * 2 + j) * 2 + k) * 2 + l] = lambda * (i == j) * (k == l) + mu * ((i == k) * (j == l) + (i == l) * (j == k));
}

/* von Mises equivalent stress of the full (3D) plane-strain stress state. */
PetscReal ElasticityVonMises(PetscReal sxx, PetscReal syy, PetscReal szz, PetscReal sxy)
{
  const PetscReal d = (sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx);

  return PetscSqrtReal(0.5 * d + 3.0 * sxy * sxy);
}
