/* The compressible Mooney-Rivlin material (-<body>_material mooneyrivlin,
   -<body>_C10, -<body>_C01, -<body>_D1), total Lagrangian, of the full 3 x 3
   displacement gradient (material.h): one source for plane strain, r-z and
   3D. It shows a material as one file: its options and its kernels.

   With C = F^T F, I1 = tr C, I2 = (I1^2 - tr C^2) / 2, J = det F and the
   isochoric invariants I1b = J^(-2/3) I1, I2b = J^(-4/3) I2:

       W = C10 (I1b - 3) + C01 (I2b - 3) + (J - 1)^2 / D1,

   params = {C10, C01, D1}. At rest its shear modulus is mu = 2 (C10 + C01)
   and its bulk modulus K = 2 / D1, so E = 9 K mu / (3 K + mu) and nu = (3 K
   - 2 mu) / (2 (3 K + mu)), the small-strain constants the contact's E* and
   the reports use; C01 = 0 is a neo-Hookean of another volumetric term.

   W is a function of (I1, I2, J), whose derivatives in F are
       dI1/dF = 2 F,  dI2/dF = 2 (I1 F - F C),  dJ/dF = cof F = J F^-T,
   so P = W_1 2F + W_2 2(I1 F - F C) + W_J cof F, and, with g^a those three
   gradients and W_ab the second partials,
       A_iJkL = sum_ab W_ab g^a_iJ g^b_kL + 2 W_1 d_ik d_JL
              + 2 W_2 (2 F_iJ F_kL + I1 d_ik d_JL - d_ik C_LJ - F_iL F_kJ - b_ik d_JL)
              + W_J (cof_iJ cof_kL - cof_iL cof_kJ) / J,
   b = F F^T (the last from d cof_iJ/dF_kL = (cof_iJ cof_kL - cof_iL cof_kJ)/J).
   For this W:
       W_1 = C10 J^(-2/3), W_2 = C01 J^(-4/3),
       W_J = -2/3 C10 J^(-5/3) I1 - 4/3 C01 J^(-7/3) I2 + 2 (J - 1)/D1,
       W_1J = -2/3 C10 J^(-5/3), W_2J = -4/3 C01 J^(-7/3),
       W_JJ = 10/9 C10 J^(-8/3) I1 + 28/9 C01 J^(-10/3) I2 + 2/D1,
   the others zero. The Cauchy stress is P F^T / J.

   Round-off: I1 - 3 = 2 tr H + |H|^2, I2 - 3 = 2 tr D + ((tr D)^2 - D:D)/2
   with D = C - I = H + H^T + H^T H, J - 1 = tr H + ((tr H)^2 - tr H^2)/2 +
   det H, and J^(-2/3) - 1 = expm1(-2/3 log1p(J - 1)): I1b - 3 = J^(-2/3)
   (I1 - 3) + 3 (J^(-2/3) - 1) is not the difference of numbers of order one
   at small strain. J <= 0: W = +inf. */
#include "material.h"
#include "options.h"

typedef struct {
  PetscReal F[9], C[9], b[9], cof[9];
  PetscReal I1, I2, J, I1m3, I2m3, Jm1;
} MRState;

/* F, C, b, cof F and the invariants of H, from H; false where J <= 0. */
static PetscBool MRKinematics(const PetscReal H[9], MRState *s)
{
  PetscReal D[9], trD = 0, DD = 0, trH = H[0] + H[4] + H[8], trHH = 0, detH;

  for (PetscInt k = 0; k < 9; ++k) s->F[k] = (k % 4 == 0 ? 1.0 : 0.0) + H[k];
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) {
      PetscReal c = 0, bb = 0, hth = 0;
      for (PetscInt k = 0; k < 3; ++k) {
        c += s->F[k * 3 + i] * s->F[k * 3 + j];
        bb += s->F[i * 3 + k] * s->F[j * 3 + k];
        hth += H[k * 3 + i] * H[k * 3 + j];
      }
      s->C[i * 3 + j] = c;
      s->b[i * 3 + j] = bb;
      D[i * 3 + j]    = H[i * 3 + j] + H[j * 3 + i] + hth;
      trHH += H[i * 3 + j] * H[j * 3 + i];
    }
  for (PetscInt i = 0; i < 3; ++i) trD += D[i * 4];
  for (PetscInt k = 0; k < 9; ++k) DD += D[k] * D[k];
  detH    = H[0] * (H[4] * H[8] - H[5] * H[7]) - H[1] * (H[3] * H[8] - H[5] * H[6]) + H[2] * (H[3] * H[7] - H[4] * H[6]);
  s->Jm1  = trH + 0.5 * (trH * trH - trHH) + detH;
  s->J    = 1.0 + s->Jm1;
  s->I1m3 = trD;
  s->I2m3 = 2.0 * trD + 0.5 * (trD * trD - DD);
  s->I1   = 3.0 + s->I1m3;
  s->I2   = 3.0 + s->I2m3;
  if (!(s->J > 0.0)) return PETSC_FALSE;
  s->cof[0] = s->F[4] * s->F[8] - s->F[5] * s->F[7];
  s->cof[1] = s->F[5] * s->F[6] - s->F[3] * s->F[8];
  s->cof[2] = s->F[3] * s->F[7] - s->F[4] * s->F[6];
  s->cof[3] = s->F[2] * s->F[7] - s->F[1] * s->F[8];
  s->cof[4] = s->F[0] * s->F[8] - s->F[2] * s->F[6];
  s->cof[5] = s->F[1] * s->F[6] - s->F[0] * s->F[7];
  s->cof[6] = s->F[1] * s->F[5] - s->F[2] * s->F[4];
  s->cof[7] = s->F[2] * s->F[3] - s->F[0] * s->F[5];
  s->cof[8] = s->F[0] * s->F[4] - s->F[1] * s->F[3];
  return PETSC_TRUE;
}

/* The gradients g^1 = 2F, g^2 = 2 (I1 F - F C), g^J = cof F. */
static void MRGradients(const MRState *s, PetscReal g1[9], PetscReal g2[9], PetscReal gJ[9])
{
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) {
      PetscReal fc = 0;
      for (PetscInt k = 0; k < 3; ++k) fc += s->F[i * 3 + k] * s->C[k * 3 + j];
      g1[i * 3 + j] = 2.0 * s->F[i * 3 + j];
      g2[i * 3 + j] = 2.0 * (s->I1 * s->F[i * 3 + j] - fc);
      gJ[i * 3 + j] = s->cof[i * 3 + j];
    }
}

static PetscBool MooneyRivlinEnergy(const PetscReal param[], const PetscReal state[], const PetscReal H[9], PetscReal *W, PetscReal P[9])
{
  const PetscReal C10 = param[0], C01 = param[1], D1 = param[2];
  MRState         s;
  PetscReal       lnJ, j23, j43, W1, W2, WJ, g1[9], g2[9], gJ[9];

  (void)state; /* no history (nstate = 0) */
  if (!MRKinematics(H, &s)) {
    *W = (PetscReal)INFINITY;
    for (PetscInt k = 0; k < 9; ++k) P[k] = 0.0;
    return PETSC_FALSE;
  }
  lnJ = log1p(s.Jm1);
  j23 = expm1(-2.0 / 3.0 * lnJ); /* J^(-2/3) - 1 */
  j43 = expm1(-4.0 / 3.0 * lnJ);
  *W  = C10 * ((1.0 + j23) * s.I1m3 + 3.0 * j23) + C01 * ((1.0 + j43) * s.I2m3 + 3.0 * j43) + s.Jm1 * s.Jm1 / D1;
  W1  = C10 * (1.0 + j23);
  W2  = C01 * (1.0 + j43);
  WJ  = -2.0 / 3.0 * C10 * (1.0 + j23) * s.I1 / s.J - 4.0 / 3.0 * C01 * (1.0 + j43) * s.I2 / s.J + 2.0 * s.Jm1 / D1;
  MRGradients(&s, g1, g2, gJ);
  for (PetscInt k = 0; k < 9; ++k) P[k] = W1 * g1[k] + W2 * g2[k] + WJ * gJ[k];
  return PETSC_TRUE;
}

static void MooneyRivlinModuli(const PetscReal param[], const PetscReal state[], const PetscReal H[9], PetscReal A[81])
{
  const PetscReal C10 = param[0], C01 = param[1], D1 = param[2];
  MRState         s;
  PetscReal       J, a23, a43, W1, W2, WJ, W1J, W2J, WJJ, g1[9], g2[9], gJ[9];

  (void)state; /* no history (nstate = 0) */
  for (PetscInt k = 0; k < 81; ++k) A[k] = 0.0;
  if (!MRKinematics(H, &s)) return; /* never asked: an inverted state is never accepted */
  J   = s.J;
  a23 = PetscPowReal(J, -2.0 / 3.0);
  a43 = PetscPowReal(J, -4.0 / 3.0);
  W1  = C10 * a23;
  W2  = C01 * a43;
  WJ  = -2.0 / 3.0 * C10 * a23 * s.I1 / J - 4.0 / 3.0 * C01 * a43 * s.I2 / J + 2.0 * s.Jm1 / D1;
  W1J = -2.0 / 3.0 * C10 * a23 / J;
  W2J = -4.0 / 3.0 * C01 * a43 / J;
  WJJ = 10.0 / 9.0 * C10 * a23 * s.I1 / (J * J) + 28.0 / 9.0 * C01 * a43 * s.I2 / (J * J) + 2.0 / D1;
  MRGradients(&s, g1, g2, gJ);
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt Jx = 0; Jx < 3; ++Jx)
      for (PetscInt k = 0; k < 3; ++k)
        for (PetscInt L = 0; L < 3; ++L) {
          const PetscInt  a = i * 3 + Jx, b = k * 3 + L;
          const PetscReal dik = i == k, dJL = Jx == L;
          PetscReal       v;
          v = W1J * (g1[a] * gJ[b] + gJ[a] * g1[b]) + W2J * (g2[a] * gJ[b] + gJ[a] * g2[b]) + WJJ * gJ[a] * gJ[b];
          v += 2.0 * W1 * dik * dJL;
          v += 2.0 * W2 * (2.0 * s.F[a] * s.F[b] + s.I1 * dik * dJL - dik * s.C[L * 3 + Jx] - s.F[i * 3 + L] * s.F[k * 3 + Jx] - s.b[i * 3 + k] * dJL);
          v += WJ * (s.cof[a] * s.cof[b] - s.cof[i * 3 + L] * s.cof[k * 3 + Jx]) / J;
          A[a * 9 + b] = v;
        }
}

static void MooneyRivlinCauchy(const PetscReal param[], const PetscReal state[], const PetscReal H[9], PetscReal sigma[9])
{
  PetscReal W, P[9], F[9], J;

  (void)state; /* no history (nstate = 0) */
  if (!MooneyRivlinEnergy(param, NULL, H, &W, P)) {
    for (PetscInt k = 0; k < 9; ++k) sigma[k] = (PetscReal)NAN;
    return;
  }
  for (PetscInt k = 0; k < 9; ++k) F[k] = (k % 4 == 0 ? 1.0 : 0.0) + H[k];
  J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) {
      PetscReal s = 0;
      for (PetscInt k = 0; k < 3; ++k) s += P[i * 3 + k] * F[j * 3 + k];
      sigma[i * 3 + j] = s / J;
    }
}

/* -C10 (required, > 0), -C01 (0, >= 0), -D1 (required, > 0): param =
   {C10, C01, D1}, and E, nu at rest. */
static PetscErrorCode MooneyRivlinSetFromOptions(MPI_Comm comm, const char prefix[], PetscBool help, PetscReal param[], PetscReal *E, PetscReal *nu)
{
  PetscReal C10 = 0, C01 = 0, D1 = 0, mu, K;
  PetscBool set10, set1;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix, "Mooney-Rivlin constants (-<body>_material mooneyrivlin)", NULL);
  PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-C10", "Mooney-Rivlin C10, of the isochoric I1 (required with -<body>_material mooneyrivlin)", "required", PETSC_FALSE, &C10, &set10));
  PetscCall(PetscOptionsReal("-C01", "Mooney-Rivlin C01, of the isochoric I2", NULL, C01, &C01, NULL));
  PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-D1", "Mooney-Rivlin D1, of the volumetric (J - 1)^2 / D1: 2 / bulk modulus (required with -<body>_material mooneyrivlin)", "required", PETSC_FALSE, &D1, &set1));
  PetscOptionsEnd();
  if (help) PetscFunctionReturn(0);
  PetscCheck(set10, comm, PETSC_ERR_USER_INPUT, "option -%sC10 is required with -%smaterial mooneyrivlin", prefix, prefix);
  PetscCheck(set1, comm, PETSC_ERR_USER_INPUT, "option -%sD1 is required with -%smaterial mooneyrivlin", prefix, prefix);
  PetscCheck(!PetscIsInfOrNanReal(C10) && C10 > 0, comm, PETSC_ERR_USER_INPUT, "option -%sC10: must be a finite number > 0, got %g", prefix, (double)C10);
  PetscCheck(!PetscIsInfOrNanReal(C01) && C01 >= 0, comm, PETSC_ERR_USER_INPUT, "option -%sC01: must be a finite number >= 0, got %g", prefix, (double)C01);
  PetscCheck(!PetscIsInfOrNanReal(D1) && D1 > 0, comm, PETSC_ERR_USER_INPUT, "option -%sD1: must be a finite number > 0, got %g", prefix, (double)D1);
  param[0] = C10;
  param[1] = C01;
  param[2] = D1;
  mu       = 2.0 * (C10 + C01);
  K        = 2.0 / D1;
  *E       = 9.0 * K * mu / (3.0 * K + mu);
  *nu      = (3.0 * K - 2.0 * mu) / (2.0 * (3.0 * K + mu));
  PetscFunctionReturn(0);
}

const Material MaterialMooneyRivlin = {"mooneyrivlin", MooneyRivlinSetFromOptions, PETSC_FALSE, MooneyRivlinEnergy, MooneyRivlinModuli, MooneyRivlinCauchy, 0, NULL};
