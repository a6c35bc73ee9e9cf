/* Small-strain J2 (von Mises) plasticity with linear isotropic hardening
   (-<body>_material plastic, -<body>_E, _nu, _yield, _hardening), written
   as an incremental potential of the displacement gradient (material.h):
   one source for plane strain, r-z and 3D, as linear elasticity's
   (elasticity.c), whose sums it uses for the elastic part.

   Fields: eps = (H + H^T)/2; the state of the last accepted increment at a
   quadrature point, state = {eps_p (xx, yy, zz, xy, xz, yz: the plastic
   strain, a deviatoric tensor's components), alpha_n (the equivalent
   plastic strain)}, zero at rest (nstate = 7). params = {lambda, mu,
   sigma_y, Hh}: Lame's constants, the initial yield stress and the
   hardening modulus (sigma_y + Hh alpha the yield stress in von Mises'
   q = sqrt(3/2) |dev sigma|).

   Incremental potential (Ortiz and Stainier 1999, variational constitutive
   updates): over the plastic strain increment d, deviatoric, and the
   equivalent one da >= sqrt(2/3) |d|,
     W(eps) = min  psi_e(eps - eps_p - d) + Hh/2 (alpha_n + da)^2 + sigma_y (alpha_n + da),
     psi_e(ee) = lambda/2 (tr ee)^2 + mu ee:ee,
   the stored energy of the elastic strain and of the hardening, plus the
   dissipation sigma_y alpha, all of it from rest: W is the work done on the
   point from rest (the increment's dissipation sigma_y da beyond
   psi + Hh/2 alpha^2; the constant sigma_y alpha_n leaves the minimiser
   alone and keeps W continuous when the state is accepted). The minimiser
   is the radial return: the trial stress sigma_tr = C:(eps - eps_p), its
   deviator s_tr, q_tr = sqrt(3/2) |s_tr|, f = q_tr - (sigma_y + Hh alpha_n);
     f <= 0:  da = 0 (elastic: with a zero state, linear elasticity's W,
              sigma and C to the bit),
     f > 0:   da = f / (3 mu + Hh), n = s_tr / |s_tr|,
              d = sqrt(3/2) da n,  sigma = sigma_tr - 2 mu d.
   By the envelope theorem P = dW/dH = sigma (symmetric: W depends on
   eps alone), and the tangent is the consistent (algorithmic) one
   (de Souza Neto, Peric and Owen, Box 7.4),
     A = C - 6 mu^2 da/q_tr I_dev + 6 mu^2 (da/q_tr - 1/(3 mu + Hh)) n (x) n,
   I_dev_ijkl = (d_ik d_jl + d_il d_jk)/2 - d_ij d_kl / 3, continuous with
   C - 6 mu^2/(3 mu + Hh) n (x) n at the yield surface. W is convex in eps
   and C^1; A jumps across the yield surface, where Newton's tangent
   changes branch. update gives eps_p + d and alpha_n + da at the
   converged eps. In uniaxial stress past yield the slope of sigma against
   eps is E Hh / (E + Hh) (sigma = sigma_y + Hh alpha, eps = sigma/E + alpha).

   Axisymmetry: the hoop strain H_22 = u_r / r is eps_thth, one more
   component of the same 3 x 3 strain, and plastic flow in it is as in any
   other: supported. Plane strain: eps_zz = 0 while eps_p,zz is not (the
   state keeps all six components). The Cauchy stress is sigma (small
   strain, as linear elasticity's). */
#include "contact.h"
#include "material.h"
#include "options.h"

#define PLASTIC_NSTATE 7

/* A point's return: the elastic strain ee and stress sigma after it, the
   equivalent plastic strain alpha, and in the plastic branch (da > 0) the
   flow direction n[9] (unit, deviatoric) and q_tr. */
typedef struct {
  PetscReal ee[6], sigma[9], alpha, da, n[9], qtr;
} PlasticReturn;

static void PlasticReturnMap(const PetscReal param[], const PetscReal state[], const PetscReal H[], PlasticReturn *r)
{
  const PetscReal mu = param[1], sy = param[2], Hh = param[3], c = PetscSqrtReal(1.5);
  const PetscReal zero[PLASTIC_NSTATE] = {0, 0, 0, 0, 0, 0, 0}, *s = state ? state : zero;
  PetscReal       e[6], W, p, dev[9], norm;

  (void)ElasticityStrain(H, e);
  for (PetscInt k = 0; k < 6; ++k) r->ee[k] = e[k] - s[k];
  ElasticityStrainEnergyStress(param, r->ee, &W, r->sigma);
  r->alpha = s[6];
  r->da    = 0.0;
  p        = (r->sigma[0] + r->sigma[4] + r->sigma[8]) / 3.0;
  for (PetscInt k = 0; k < 9; ++k) dev[k] = r->sigma[k] - (k % 4 == 0 ? p : 0.0);
  norm   = PetscSqrtReal(dev[0] * dev[0] + dev[4] * dev[4] + dev[8] * dev[8] + 2.0 * (dev[1] * dev[1] + dev[2] * dev[2] + dev[5] * dev[5]));
  r->qtr = c * norm;
  if (!(r->qtr - (sy + Hh * r->alpha) > 0.0)) return; /* elastic */
  r->da = (r->qtr - (sy + Hh * r->alpha)) / (3.0 * mu + Hh);
  r->alpha += r->da;
  for (PetscInt k = 0; k < 9; ++k) {
    r->n[k] = dev[k] / norm;
    r->sigma[k] -= 2.0 * mu * c * r->da * r->n[k];
  }
  r->ee[0] -= c * r->da * r->n[0];
  r->ee[1] -= c * r->da * r->n[4];
  r->ee[2] -= c * r->da * r->n[8];
  r->ee[3] -= c * r->da * r->n[1];
  r->ee[4] -= c * r->da * r->n[2];
  r->ee[5] -= c * r->da * r->n[5];
}

static PetscBool PlasticEnergy(const PetscReal param[], const PetscReal state[], const PetscReal H[], PetscReal *W, PetscReal P[])
{
  PlasticReturn r;
  PetscReal     sig[9];

  PlasticReturnMap(param, state, H, &r);
  ElasticityStrainEnergyStress(param, r.ee, W, sig); /* psi_e of the elastic strain after the return */
  if (r.alpha != 0.0) *W += r.alpha * (param[2] + 0.5 * param[3] * r.alpha);
  for (PetscInt k = 0; k < 9; ++k) P[k] = r.sigma[k];
  return PETSC_TRUE;
}

static void PlasticModuli(const PetscReal param[], const PetscReal state[], const PetscReal H[], PetscReal A[])
{
  const PetscReal mu = param[1], Hh = param[3];
  PlasticReturn   r;
  PetscReal       a, b;

  ElasticityTangent(param, A);
  PlasticReturnMap(param, state, H, &r);
  if (!(r.da > 0.0)) return;
  a = 6.0 * mu * mu * r.da / r.qtr;
  b = 6.0 * mu * mu * (r.da / r.qtr - 1.0 / (3.0 * mu + Hh));
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j)
      for (PetscInt k = 0; k < 3; ++k)
        for (PetscInt l = 0; l < 3; ++l) {
          const PetscReal Idev = 0.5 * ((i == k) * (j == l) + (i == l) * (j == k)) - (i == j) * (k == l) / 3.0;
          A[(i * 3 + j) * 9 + k * 3 + l] += -a * Idev + b * r.n[i * 3 + j] * r.n[k * 3 + l];
        }
}

static void PlasticCauchy(const PetscReal param[], const PetscReal state[], const PetscReal H[], PetscReal sigma[])
{
  PlasticReturn r;

  PlasticReturnMap(param, state, H, &r);
  for (PetscInt k = 0; k < 9; ++k) sigma[k] = r.sigma[k];
}

static void PlasticUpdate(const PetscReal param[], const PetscReal state[], const PetscReal H[], PetscReal stateNew[])
{
  const PetscReal c = PetscSqrtReal(1.5);
  PlasticReturn   r;

  PlasticReturnMap(param, state, H, &r);
  for (PetscInt k = 0; k < PLASTIC_NSTATE; ++k) stateNew[k] = state ? state[k] : 0.0;
  if (!(r.da > 0.0)) return;
  stateNew[0] += c * r.da * r.n[0];
  stateNew[1] += c * r.da * r.n[4];
  stateNew[2] += c * r.da * r.n[8];
  stateNew[3] += c * r.da * r.n[1];
  stateNew[4] += c * r.da * r.n[2];
  stateNew[5] += c * r.da * r.n[5];
  stateNew[6] = r.alpha;
}

/* -E, -nu (MaterialElasticConstantsSetFromOptions), -yield (required,
   finite, > 0) and -hardening (0, finite, >= 0): param = {lambda, mu,
   sigma_y, Hh}. -help: the last two alone (linear's reader lists E, nu). */
static PetscErrorCode PlasticSetFromOptions(MPI_Comm comm, const char prefix[], PetscBool help, PetscReal param[], PetscReal *E, PetscReal *nu)
{
  PetscReal sy = 0, Hh = 0;
  PetscBool setY;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix, "J2 plasticity (-<body>_material plastic, with -<body>_E and -<body>_nu)", NULL);
  PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-yield", "Initial yield stress sigma_y in von Mises' equivalent stress (required with -<body>_material plastic)", "required", PETSC_FALSE, &sy, &setY));
  PetscCall(PetscOptionsReal("-hardening", "Linear isotropic hardening modulus H: the yield stress is sigma_y + H times the equivalent plastic strain (0: perfectly plastic)", NULL, Hh, &Hh, NULL));
  PetscOptionsEnd();
  if (help) PetscFunctionReturn(0);
  PetscCall(MaterialElasticConstantsSetFromOptions(comm, prefix, PETSC_FALSE, param, E, nu));
  PetscCheck(setY, comm, PETSC_ERR_USER_INPUT, "option -%syield is required with -%smaterial plastic", prefix, prefix);
  PetscCheck(!PetscIsInfOrNanReal(sy) && sy > 0, comm, PETSC_ERR_USER_INPUT, "option -%syield: the yield stress must be a finite number > 0, got %g", prefix, (double)sy);
  PetscCheck(!PetscIsInfOrNanReal(Hh) && Hh >= 0, comm, PETSC_ERR_USER_INPUT, "option -%shardening: the hardening modulus must be a finite number >= 0, got %g", prefix, (double)Hh);
  param[2] = sy;
  param[3] = Hh;
  PetscFunctionReturn(0);
}

const Material MaterialPlastic = {"plastic", PlasticSetFromOptions, PETSC_FALSE, PlasticEnergy, PlasticModuli, PlasticCauchy, PLASTIC_NSTATE, PlasticUpdate};
