/* Exact displacement fields with their body forces, chosen by name
   (-<body>_exact NAME, -<body>_exact_params p0,p1,...).

   affine: u = (p0 + p1 x + p2 y, p3 + p4 x + p5 y). Constant strain, so
           f = -div sigma = 0 and the strain energy is W(eps) times the area:
           the patch test. grad u = [[p1, p2], [p4, p5]]. With 12
           parameters, the 3D map u_i = p[4i] + p[4i+1] x + p[4i+2] y +
           p[4i+3] z (a 3D body's: grad u[i*3+j] = p[4i+1+j]), f = 0 again.
   trig:   u = A (sin(k x) cos(k y), cos(k x) sin(k y)), params {A, k}.
           div u = 2 A k cos(k x) cos(k y), Laplacian u = -2 k^2 u and
           grad div u = -2 k^2 u, so
           f = -(mu Lap u + (lambda + mu) grad div u) = 2 k^2 (lambda + 2 mu) u:
           a manufactured solution for convergence studies. Its gradient,
           du_i/dx_j at [i*2+j] as in elasticity.c:
             grad u = A k [[ cos kx cos ky, -sin kx sin ky],
                           [-sin kx sin ky,  cos kx cos ky]],
           so eps = grad u (symmetric) and the exact stress is
           sigma(grad u) (the energy-norm and stress errors of body.c).
           Its second derivatives (d2u) give any material's body force
           f_i = -A_iJkL d2u_k/dx_J dx_L (body.c; A the material's tangent
           at grad u): a manufactured solution at finite strain too.
           On a 3D body, u_i = A sin(k x_i) prod_(j != i) cos(k x_j), the
           same {A, k}, f = -((lambda + mu) grad div u + mu Lap u) from
           its second derivatives.
   lame:   in axisymmetry (x = r, y = z), u = (A r + B / r, C z), params
           {A, B, C}: Lame's thick-walled tube (C = 0: no axial strain) and,
           with B = 0, a cylinder under uniform axial strain C with
           A = -nu C (a uniaxial stress). eps_rr = A - B/r^2,
           eps_thth = A + B/r^2, eps_zz = C, so tr eps = 2A + C is uniform and
           sigma_rr - sigma_thth = -4 mu B / r^2: the radial equilibrium
           d sigma_rr/dr + (sigma_rr - sigma_thth)/r = 4 mu B/r^3 - 4 mu B/r^3 = 0,
           and the axial one holds with sigma_zz uniform, so f = 0. A
           solution in r-z only (-axisymmetric); affine and trig are
           plane-strain ones.
   sphere: on a 3D body, u = (A + B / r^3) x, params {A, B}: Lame's thick
           hollow sphere, u_r = A r + B / r^2; with inner radius a, outer
           b and internal pressure p, A = p a^3 (1 - 2 nu) / (E (b^3 - a^3)),
           B = p a^3 b^3 (1 + nu) / (2 E (b^3 - a^3)). grad u = (A + B/r^3) I
           - 3 B x x^T / r^5; div u = 3 A is uniform and u is a gradient
           (curl u = 0), so mu Lap u + (lambda + mu) grad div u = 0: f = 0. */
#include "exact.h"

PetscFunctionList ExactSolutionList = NULL;

static void AffineU(const PetscReal p[], const PetscReal x[], PetscReal u[])
{
  u[0] = p[0] + p[1] * x[0] + p[2] * x[1];
  u[1] = p[3] + p[4] * x[0] + p[5] * x[1];
}

static void AffineDU(const PetscReal p[], const PetscReal x[], PetscReal du[])
{
  (void)x;
  du[0] = p[1];
  du[1] = p[2];
  du[2] = p[4];
  du[3] = p[5];
}

static void AffineU3(const PetscReal p[], const PetscReal x[], PetscReal u[])
{
  for (PetscInt i = 0; i < 3; ++i) u[i] = p[4 * i] + p[4 * i + 1] * x[0] + p[4 * i + 2] * x[1] + p[4 * i + 3] * x[2];
}

static void AffineDU3(const PetscReal p[], const PetscReal x[], PetscReal du[])
{
  (void)x;
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) du[i * 3 + j] = p[4 * i + 1 + j];
}

static void ZeroF3(const PetscReal p[], PetscReal lambda, PetscReal mu, const PetscReal x[], PetscReal f[])
{
  (void)p; (void)lambda; (void)mu; (void)x;
  f[0] = f[1] = f[2] = 0.0;
}

static void ZeroD2U3(const PetscReal p[], const PetscReal x[], PetscReal d2u[])
{
  (void)p; (void)x;
  for (PetscInt k = 0; k < 27; ++k) d2u[k] = 0.0;
}

static void ZeroF(const PetscReal p[], PetscReal lambda, PetscReal mu, const PetscReal x[], PetscReal f[])
{
  (void)p; (void)lambda; (void)mu; (void)x;
  f[0] = f[1] = 0.0;
}

static void TrigU(const PetscReal p[], const PetscReal x[], PetscReal u[])
{
  const PetscReal A = p[0], k = p[1];

  u[0] = A * PetscSinReal(k * x[0]) * PetscCosReal(k * x[1]);
  u[1] = A * PetscCosReal(k * x[0]) * PetscSinReal(k * x[1]);
}

static void TrigDU(const PetscReal p[], const PetscReal x[], PetscReal du[])
{
  const PetscReal A = p[0], k = p[1];
  const PetscReal cc = PetscCosReal(k * x[0]) * PetscCosReal(k * x[1]), ss = PetscSinReal(k * x[0]) * PetscSinReal(k * x[1]);

  du[0] = A * k * cc;
  du[1] = -A * k * ss;
  du[2] = -A * k * ss;
  du[3] = A * k * cc;
}

/* d2u[(k*2+J)*2+L] = d2u_k/dx_J dx_L: d2u_0/dx^2 = d2u_0/dy^2 = -k^2 u_0,
   d2u_0/dxdy = -k^2 u_1, and the same with 0 and 1 swapped. */
static void TrigD2U(const PetscReal p[], const PetscReal x[], PetscReal d2u[])
{
  const PetscReal k2 = p[1] * p[1];
  PetscReal       u[2];

  TrigU(p, x, u);
  for (PetscInt c = 0; c < 2; ++c) {
    d2u[c * 4 + 0] = d2u[c * 4 + 3] = -k2 * u[c];
    d2u[c * 4 + 1] = d2u[c * 4 + 2] = -k2 * u[1 - c];
  }
}

static void ZeroD2U(const PetscReal p[], const PetscReal x[], PetscReal d2u[])
{
  (void)p;
  (void)x;
  for (PetscInt j = 0; j < 8; ++j) d2u[j] = 0.0;
}

static void TrigF(const PetscReal p[], PetscReal lambda, PetscReal mu, const PetscReal x[], PetscReal f[])
{
  const PetscReal k = p[1];
  PetscReal       u[2];

  TrigU(p, x, u);
  f[0] = 2.0 * k * k * (lambda + 2.0 * mu) * u[0];
  f[1] = 2.0 * k * k * (lambda + 2.0 * mu) * u[1];
}

/* The 3D trig solution's factor j of u_i, sin(k x_i) (j = i) or cos(k x_j),
   differentiated n times. */
static PetscReal Trig3Factor(PetscReal k, PetscInt i, PetscInt j, const PetscReal x[], PetscInt n)
{
  const PetscReal s = PetscSinReal(k * x[j]), c = PetscCosReal(k * x[j]);

  if (i == j) return n == 0 ? s : n == 1 ? k * c : -k * k * s;
  return n == 0 ? c : n == 1 ? -k * s : -k * k * c;
}

static void Trig3U(const PetscReal p[], const PetscReal x[], PetscReal u[])
{
  for (PetscInt i = 0; i < 3; ++i) u[i] = p[0] * Trig3Factor(p[1], i, 0, x, 0) * Trig3Factor(p[1], i, 1, x, 0) * Trig3Factor(p[1], i, 2, x, 0);
}

static void Trig3DU(const PetscReal p[], const PetscReal x[], PetscReal du[])
{
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt J = 0; J < 3; ++J) {
      du[i * 3 + J] = p[0];
      for (PetscInt j = 0; j < 3; ++j) du[i * 3 + J] *= Trig3Factor(p[1], i, j, x, j == J);
    }
}

static void Trig3D2U(const PetscReal p[], const PetscReal x[], PetscReal d2u[])
{
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt J = 0; J < 3; ++J)
      for (PetscInt L = 0; L < 3; ++L) {
        PetscReal v = p[0];
        for (PetscInt j = 0; j < 3; ++j) v *= Trig3Factor(p[1], i, j, x, (j == J) + (j == L));
        d2u[(i * 3 + J) * 3 + L] = v;
      }
}

static void Trig3F(const PetscReal p[], PetscReal lambda, PetscReal mu, const PetscReal x[], PetscReal f[])
{
  PetscReal d2u[27];

  Trig3D2U(p, x, d2u);
  for (PetscInt i = 0; i < 3; ++i) {
    PetscReal graddiv = 0, lap = 0;
    for (PetscInt k = 0; k < 3; ++k) graddiv += d2u[(k * 3 + k) * 3 + i];
    for (PetscInt J = 0; J < 3; ++J) lap += d2u[(i * 3 + J) * 3 + J];
    f[i] = -((lambda + mu) * graddiv + mu * lap);
  }
}

static void SphereU(const PetscReal p[], const PetscReal x[], PetscReal u[])
{
  const PetscReal r = PetscSqrtReal(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);

  for (PetscInt i = 0; i < 3; ++i) u[i] = (p[0] + p[1] / (r * r * r)) * x[i];
}

static void SphereDU(const PetscReal p[], const PetscReal x[], PetscReal du[])
{
  const PetscReal r2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2], r = PetscSqrtReal(r2);

  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) du[i * 3 + j] = (i == j) * (p[0] + p[1] / (r * r2)) - 3.0 * p[1] * x[i] * x[j] / (r2 * r2 * r);
}

static PetscErrorCode ExactSetSphere(ExactSolution *e)
{
  PetscFunctionBeginUser;
  PetscCheck(e->nparams == 2, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "exact solution sphere needs 2 parameters (A, B: u = (A + B/r^3) x), got %" PetscInt_FMT, e->nparams);
  e->u   = SphereU;
  e->du  = SphereDU;
  e->f   = ZeroF3;
  e->d2u = NULL;
  e->dim = 3;
  PetscFunctionReturn(0);
}

PetscErrorCode ExactSolutionSetDimension(ExactSolution *e, PetscInt dim, const char body[])
{
  PetscBool trig, lame;

  PetscFunctionBeginUser;
  PetscCall(PetscStrcmp(e->name, "trig", &trig));
  PetscCall(PetscStrcmp(e->name, "lame", &lame));
  PetscCheck(dim == 2 || !lame, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "option -%s_exact: lame is a solution in r-z, and body %s is 3D", body, body);
  if (trig && dim == 3) {
    e->u   = Trig3U;
    e->du  = Trig3DU;
    e->d2u = Trig3D2U;
    e->f   = Trig3F;
    e->dim = 3;
  }
  PetscCheck((e->dim == 3) == (dim == 3), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "option -%s_exact_params: %" PetscInt_FMT " parameters, a %s solution, for a %" PetscInt_FMT "D body", body, e->nparams, e->dim == 3 ? "3D" : "2D", dim);
  PetscFunctionReturn(0);
}

static void LameU(const PetscReal p[], const PetscReal x[], PetscReal u[])
{
  u[0] = p[0] * x[0] + p[1] / x[0];
  u[1] = p[2] * x[1];
}

static void LameDU(const PetscReal p[], const PetscReal x[], PetscReal du[])
{
  du[0] = p[0] - p[1] / (x[0] * x[0]);
  du[1] = 0.0;
  du[2] = 0.0;
  du[3] = p[2];
}

static PetscErrorCode ExactSetLame(ExactSolution *e)
{
  PetscFunctionBeginUser;
  PetscCheck(e->nparams == 3, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "exact solution lame needs 3 parameters (A, B, C: u = (A r + B/r, C z)), got %" PetscInt_FMT, e->nparams);
  e->u            = LameU;
  e->du           = LameDU;
  e->f            = ZeroF;
  e->axisymmetric = PETSC_TRUE;
  PetscFunctionReturn(0);
}

static PetscErrorCode ExactSetAffine(ExactSolution *e)
{
  PetscFunctionBeginUser;
  PetscCheck(e->nparams == 6 || e->nparams == 12, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "exact solution affine needs 6 parameters (u0, dux/dx, dux/dy, v0, duy/dx, duy/dy) in 2D or 12 in 3D (u0, dux/dx, dux/dy, dux/dz, v0, ..., w0, ...), got %" PetscInt_FMT, e->nparams);
  if (e->nparams == 12) {
    e->u   = AffineU3;
    e->du  = AffineDU3;
    e->d2u = ZeroD2U3;
    e->f   = ZeroF3;
    e->dim = 3;
    PetscFunctionReturn(0);
  }
  e->u   = AffineU;
  e->du  = AffineDU;
  e->d2u = ZeroD2U;
  e->f   = ZeroF;
  PetscFunctionReturn(0);
}

static PetscErrorCode ExactSetTrig(ExactSolution *e)
{
  PetscFunctionBeginUser;
  PetscCheck(e->nparams == 2, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "exact solution trig needs 2 parameters (A, k), got %" PetscInt_FMT, e->nparams);
  e->u   = TrigU;
  e->du  = TrigDU;
  e->d2u = TrigD2U;
  e->f   = TrigF;
  PetscFunctionReturn(0);
}

PetscErrorCode ExactSolutionRegisterAll(void)
{
  PetscFunctionBeginUser;
  if (ExactSolutionList) PetscFunctionReturn(0);
  PetscCall(PetscFunctionListAdd(&ExactSolutionList, "affine", ExactSetAffine));
  PetscCall(PetscFunctionListAdd(&ExactSolutionList, "trig", ExactSetTrig));
  PetscCall(PetscFunctionListAdd(&ExactSolutionList, "lame", ExactSetLame));
  PetscCall(PetscFunctionListAdd(&ExactSolutionList, "sphere", ExactSetSphere));
  PetscFunctionReturn(0);
}

PetscErrorCode ExactSolutionSetType(ExactSolution *e, const char name[])
{
  PetscErrorCode (*set)(ExactSolution *) = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListFind(ExactSolutionList, name, &set));
  PetscCheck(set, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "unknown exact solution '%s' (known: affine, trig, lame, sphere)", name);
  PetscCall(PetscStrncpy(e->name, name, sizeof(e->name)));
  PetscCall((*set)(e));
  PetscFunctionReturn(0);
}

PetscErrorCode ExactSolutionFinalize(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&ExactSolutionList));
  PetscFunctionReturn(0);
}
