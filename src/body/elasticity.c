/* Pointwise kernels of linear elasticity in plane strain and in axisymmetry.

   Field: displacement u(x) in R^2; gradu[i*2+j] = du_i/dx_j. The strain has
   the in-plane part (gradu + gradu^T)/2 and one out-of-plane normal
   component e3: 0 in plane strain (eps_zz), the hoop strain u_r / r in
   axisymmetry (x = r, y = z: eps_thth; on the axis, where u_r = 0, its limit
   du_r/dr). params = {lambda, mu} (Lame constants), tr = exx + eyy + e3.
   Stress:                  sigma = lambda tr I + 2 mu eps   (2 x 2 part),
                            sigma_33 = lambda tr + 2 mu e3   (sigma_zz, sigma_thth).
   Energy density:          W = lambda/2 tr^2 + mu (exx^2 + eyy^2 + e3^2 + 2 exy^2),
   so that Pi(u) = int W dV, dPi/du_a = int (sigma : grad N_a + sigma_33 de3/du_a) dV
   (gradient) and d2Pi/du_a du_b = int eps_a : C : eps_b dV (Hessian) with the
   tangent C_ijkl = lambda d_ij d_kl + mu (d_ik d_jl + d_il d_jk); dV is dA in
   plane strain and 2 pi r dA in axisymmetry. */
#include "contact.h"

void ElasticityEnergyDensity(const PetscReal params[], const PetscReal gradu[], PetscReal e3, PetscReal *W)
{
  const PetscReal lambda = params[0], mu = params[1];
  const PetscReal exx = gradu[0], eyy = gradu[3], exy = 0.5 * (gradu[1] + gradu[2]);
  const PetscReal tr = exx + eyy + e3;

  *W = 0.5 * lambda * tr * tr + mu * (exx * exx + eyy * eyy + e3 * e3 + 2.0 * exy * exy);
}

void ElasticityStress(const PetscReal params[], const PetscReal gradu[], PetscReal e3, PetscReal sigma[])
{
  const PetscReal lambda = params[0], mu = params[1];
  const PetscReal exx = gradu[0], eyy = gradu[3], exy = 0.5 * (gradu[1] + gradu[2]);
  const PetscReal tr = exx + eyy + e3;

  sigma[0] = lambda * tr + 2.0 * mu * exx;
  sigma[1] = 2.0 * mu * exy;
  sigma[2] = 2.0 * mu * exy;
  sigma[3] = lambda * tr + 2.0 * mu * eyy;
}

PetscReal ElasticityStress33(const PetscReal params[], const PetscReal gradu[], PetscReal e3)
{
  return params[0] * (gradu[0] + gradu[3] + e3) + 2.0 * params[1] * e3;
}

PetscReal ElasticityHoopStrain(PetscReal ur, PetscReal durdr, PetscReal r)
{
  return r > 0 ? ur / r : durdr;
}

void ElasticityTangent(const PetscReal params[], PetscReal C[])
{
  const PetscReal lambda = params[0], mu = params[1];

  for (PetscInt i = 0; i < 2; ++i)
    for (PetscInt j = 0; j < 2; ++j)
      for (PetscInt k = 0; k < 2; ++k)
        for (PetscInt l = 0; l < 2; ++l) C[((i * 2 + j) * 2 + k) * 2 + l] = lambda * (i == j) * (k == l) + mu * ((i == k) * (j == l) + (i == l) * (j == k));
}

/* von Mises equivalent stress of the full (3D) stress state: in-plane
   xx, yy, xy and the out-of-plane normal stress s33. */
PetscReal ElasticityVonMises(PetscReal sxx, PetscReal syy, PetscReal szz, PetscReal sxy)
{
  const PetscReal d = (sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx);

  return PetscSqrtReal(0.5 * d + 3.0 * sxy * sxy);
}
