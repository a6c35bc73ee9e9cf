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
   plane strain and 2 pi r dA in axisymmetry. These are the material
   "linear" (material.h): its stress is sigma and its tangent C, whatever
   the displacement. */
#include "contact.h"
#include "material.h"

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

/* K_(a i)(b j) += w dN_a/dx_k C_ikjl dN_b/dx_l for the blocks bb >= a, with
   the in-plane tangent C[((i*2+k)*2+j)*2+l] of any material (K: 2 nb x 2 nb). */
void ElasticityAddTangent(const PetscReal C[], PetscInt nb, PetscReal w, const PetscReal dN[], PetscScalar K[])
{
  const PetscInt n = 2 * nb;
  PetscReal      G[9][2][2][2]; /* w dN_a/dx_k C_ikjl, summed over k */

  for (PetscInt a = 0; a < nb; ++a)
    for (PetscInt i = 0; i < 2; ++i)
      for (PetscInt j = 0; j < 2; ++j)
        for (PetscInt l = 0; l < 2; ++l) G[a][i][j][l] = w * (dN[2 * a] * C[((i * 2) * 2 + j) * 2 + l] + dN[2 * a + 1] * C[((i * 2 + 1) * 2 + j) * 2 + l]);
  for (PetscInt a = 0; a < nb; ++a) /* the upper blocks (bb >= a); K is symmetric */
    for (PetscInt i = 0; i < 2; ++i)
      for (PetscInt bb = a; bb < nb; ++bb)
        for (PetscInt j = 0; j < 2; ++j) K[(2 * a + i) * n + 2 * bb + j] += G[a][i][j][0] * dN[2 * bb] + G[a][i][j][1] * dN[2 * bb + 1];
}

static PetscBool LinearEnergy(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscReal *W, PetscReal P[], PetscReal *P33)
{
  ElasticityEnergyDensity(param, gu, e3, W);
  ElasticityStress(param, gu, e3, P);
  *P33 = ElasticityStress33(param, gu, e3);
  return PETSC_TRUE;
}

static void LinearCauchy(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscReal sigma[], PetscReal *s33)
{
  ElasticityStress(param, gu, e3, sigma);
  *s33 = ElasticityStress33(param, gu, e3);
}

/* The in-plane terms with C, and in axisymmetry the hoop strain's terms:
   e3 = N_a / r on u_a,r. */
static void LinearTangent(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscInt nb, PetscReal w, const PetscReal dN[], const PetscReal B[], PetscReal r, PetscScalar K[])
{
  const PetscInt n = 2 * nb;
  PetscReal      C[16];

  (void)gu;
  (void)e3;
  ElasticityTangent(param, C);
  ElasticityAddTangent(C, nb, w, dN, K);
  if (r > 0) {
    const PetscReal lambda = param[0], mu = param[1];
    for (PetscInt a = 0; a < nb; ++a)
      for (PetscInt bb = a; bb < nb; ++bb) {
        const PetscReal na = B[a] / r, nbb = B[bb] / r;
        K[(2 * a) * n + 2 * bb] += w * (lambda * (dN[2 * a] * nbb + na * dN[2 * bb]) + (lambda + 2.0 * mu) * na * nbb);
        K[(2 * a) * n + 2 * bb + 1] += w * lambda * na * dN[2 * bb + 1];
        K[(2 * a + 1) * n + 2 * bb] += w * lambda * dN[2 * a + 1] * nbb;
      }
  }
}

static void LinearModuli(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscReal A[], PetscReal a3[], PetscReal *a33)
{
  (void)gu;
  (void)e3;
  ElasticityTangent(param, A);
  for (PetscInt j = 0; j < 4; ++j) a3[j] = (j == 0 || j == 3) ? param[0] : 0.0;
  *a33 = param[0] + 2.0 * param[1];
}

const Material MaterialLinear = {"linear", PETSC_TRUE, LinearEnergy, LinearCauchy, LinearModuli, LinearTangent};
