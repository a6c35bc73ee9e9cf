/* A check of the element loop (element.c) in 3D, no 3D mesh needed:
   bin/element-check, driven by tests/test_material_kernels.py, which asserts
   the figures it prints, one "cell material figure value" a line.

   One cell, Hex27 (Q2, 27 Gauss points) or Tet10 (P2, degree-4 simplex
   quadrature), from PETSc's Lagrange element on the reference cell mapped by
   an affine x = M X (M a fixed matrix, det M = 1.9): the cell cache
   (dNdx = dN/dX M^-1, wdetJ = w det M) of a body with dim = 3, filled here,
   and the loop asked for its energy, gradient and tangent:
     taylor_g_order_min/max  the order of |Pi(u + tv) - Pi(u) - t g.v| between t and t/2 (2 if g = dPi/du);
     taylor_K_order_min/max  the same of |g(u + tv) - g(u) - t K v| (neo-Hookean; 2 if K = dg/du);
     K_sym_rel               max |K - K^T| / max |K|;
     patch_W_rel             |Pi - W(H0) vol| / |W(H0) vol| for u = H0 x (affine: H0 at every point);
     patch_g_sum_rel         |sum_a g_a| / max |g_a| for that u (sum_a N_a = 1: the forces balance);
     rest_null_rel           max |K r| / (max |K| max |r|) over the six rigid modes r at rest;
     rotation_W, rotation_g  Pi / (mu vol) and max |g| / (mu vol) at u = (Q - I) x, Q a rotation (neo-Hookean).
   u and v are random of size 0.05 (finite strain, J > 0). */
#include <petscfe.h>
#include <petscdt.h>
#include "element.h"
#include "bodyimpl.h" /* the test fills in a body of one cell itself */

#include "checkutil.h"

/* Pi and g of the one cell at u (as a local array: cdof[a] = 3a). */
static PetscReal EnergyGradient(Body b, const PetscReal u[], PetscReal g[])
{
  PetscReal e = 0.0;
  PetscInt  iq;
  for (PetscInt k = 0; k < b->nb * b->dim; ++k) g[k] = 0.0;
  if (!ElementAddEnergyGradient(b, 0, u, &e, g, &iq)) return (PetscReal)INFINITY;
  return e;
}

static PetscErrorCode Check(const char cell[], PetscBool simplex, const Material *m, const PetscReal param[])
{
  const PetscInt  dim = 3;
  const PetscReal M[9] = {1.2, 0.1, -0.2, 0.3, 0.9, 0.1, 0.0, -0.25, 1.1};
  PetscFE         fe;
  PetscQuadrature q;
  PetscTabulation T;
  PetscDualSpace  sp;
  const PetscReal *qw;
  PetscInt        nb, nq, n;
  PetscReal      *dNdx, *wdetJ, *xq, *xn, Mi[9], detM, vol = 0.0;
  PetscInt       *cdof;
  struct _n_Body  body;
  Body            b = &body;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&body, sizeof(body)));
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, dim, 1, simplex, 2, PETSC_DETERMINE, &fe));
  if (simplex) PetscCall(PetscDTSimplexQuadrature(dim, 4, PETSCDTSIMPLEXQUAD_DEFAULT, &q));
  else PetscCall(PetscDTGaussTensorQuadrature(dim, 1, 3, -1.0, 1.0, &q));
  PetscCall(PetscFESetQuadrature(fe, q));
  PetscCall(PetscFEGetDimension(fe, &nb));
  PetscCall(PetscQuadratureGetData(q, NULL, NULL, &nq, NULL, &qw));
  PetscCall(PetscFEGetCellTabulation(fe, 1, &T));
  PetscCall(PetscFEGetDualSpace(fe, &sp));
  n    = dim * nb;
  detM = M[0] * (M[4] * M[8] - M[5] * M[7]) - M[1] * (M[3] * M[8] - M[5] * M[6]) + M[2] * (M[3] * M[7] - M[4] * M[6]);
  Mi[0] = (M[4] * M[8] - M[5] * M[7]) / detM;
  Mi[1] = (M[2] * M[7] - M[1] * M[8]) / detM;
  Mi[2] = (M[1] * M[5] - M[2] * M[4]) / detM;
  Mi[3] = (M[5] * M[6] - M[3] * M[8]) / detM;
  Mi[4] = (M[0] * M[8] - M[2] * M[6]) / detM;
  Mi[5] = (M[2] * M[3] - M[0] * M[5]) / detM;
  Mi[6] = (M[3] * M[7] - M[4] * M[6]) / detM;
  Mi[7] = (M[1] * M[6] - M[0] * M[7]) / detM;
  Mi[8] = (M[0] * M[4] - M[1] * M[3]) / detM;
  PetscCall(PetscMalloc5(nq * nb * dim, &dNdx, nq, &wdetJ, nq * dim, &xq, nb * dim, &xn, nb, &cdof));
  for (PetscInt a = 0; a < nb; ++a) { /* the nodes: the point of each Lagrange functional, mapped */
    PetscQuadrature  f;
    const PetscReal *pt;
    cdof[a] = dim * a;
    PetscCall(PetscDualSpaceGetFunctional(sp, a, &f));
    PetscCall(PetscQuadratureGetData(f, NULL, NULL, NULL, &pt, NULL));
    for (PetscInt i = 0; i < dim; ++i) xn[a * dim + i] = M[i * 3] * pt[0] + M[i * 3 + 1] * pt[1] + M[i * 3 + 2] * pt[2];
  }
  for (PetscInt iq = 0; iq < nq; ++iq) {
    for (PetscInt a = 0; a < nb; ++a) /* dN/dx_J = dN/dX_K (M^-1)_KJ */
      for (PetscInt J = 0; J < dim; ++J) {
        dNdx[(iq * nb + a) * dim + J] = 0.0;
        for (PetscInt K = 0; K < dim; ++K) dNdx[(iq * nb + a) * dim + J] += T->T[1][(iq * nb + a) * dim + K] * Mi[K * 3 + J];
      }
    wdetJ[iq] = qw[iq] * PetscAbsReal(detM);
    vol += wdetJ[iq];
    for (PetscInt i = 0; i < dim; ++i) {
      xq[iq * dim + i] = 0.0;
      for (PetscInt a = 0; a < nb; ++a) xq[iq * dim + i] += T->T[0][iq * nb + a] * xn[a * dim + i];
    }
  }
  b->dim    = dim;
  b->nb     = nb;
  b->nq     = nq;
  b->ncells = 1;
  b->cdof   = cdof;
  b->dNdx   = dNdx;
  b->wdetJ  = wdetJ;
  b->xq     = xq;
  b->B      = T->T[0];
  b->mat    = m;
  b->param[0] = param[0];
  b->param[1] = param[1];
  {
    const PetscBool neo = (PetscBool)!m->constantTangent;
    PetscReal      *u, *v, *ut, *g, *gt, *K, *Kv, rP[4], rg[4], omin = 1e30, omax = -1e30, kmin = 1e30, kmax = -1e30, ksym = 0.0, gv = 0.0, e;
    PetscCall(PetscMalloc7(n, &u, n, &v, n, &ut, n, &g, n, &gt, n * n, &K, n, &Kv));
    for (PetscInt k = 0; k < n; ++k) {
      u[k] = Uniform(-0.05, 0.05);
      v[k] = Uniform(-0.05, 0.05);
    }
    e = EnergyGradient(b, u, g);
    ElementTangent(b, 0, u, K);
    for (PetscInt k = 0; k < n; ++k) gv += g[k] * v[k];
    for (PetscInt i = 0; i < n; ++i) {
      Kv[i] = 0.0;
      for (PetscInt j = 0; j < n; ++j) Kv[i] += K[i * n + j] * v[j];
    }
    for (PetscInt l = 0; l < 4; ++l) {
      const PetscReal t = 0.5 / (PetscReal)(1 << l);
      PetscReal       et, d2 = 0.0;
      for (PetscInt k = 0; k < n; ++k) ut[k] = u[k] + t * v[k];
      et    = EnergyGradient(b, ut, gt);
      rP[l] = PetscAbsReal(et - e - t * gv);
      for (PetscInt k = 0; k < n; ++k) d2 += PetscSqr(gt[k] - g[k] - t * Kv[k]);
      rg[l] = PetscSqrtReal(d2);
    }
    for (PetscInt l = 0; l < 3; ++l) {
      omin = PetscMin(omin, PetscLog2Real(rP[l] / rP[l + 1]));
      omax = PetscMax(omax, PetscLog2Real(rP[l] / rP[l + 1]));
      kmin = PetscMin(kmin, PetscLog2Real(rg[l] / rg[l + 1]));
      kmax = PetscMax(kmax, PetscLog2Real(rg[l] / rg[l + 1]));
    }
    for (PetscInt i = 0; i < n; ++i)
      for (PetscInt j = 0; j < n; ++j) ksym = PetscMax(ksym, PetscAbsReal(K[i * n + j] - K[j * n + i]));
    printf("%s %s taylor_g_order_min %.6e\n%s %s taylor_g_order_max %.6e\n", cell, m->name, (double)omin, cell, m->name, (double)omax);
    if (neo) printf("%s %s taylor_K_order_min %.6e\n%s %s taylor_K_order_max %.6e\n", cell, m->name, (double)kmin, cell, m->name, (double)kmax);
    printf("%s %s K_sym_rel %.6e\n", cell, m->name, (double)(ksym / MaxAbs(n * n, K)));
    { /* affine patch u = H0 x */
      const PetscReal H0[9] = {0.05, -0.03, 0.02, 0.04, -0.06, 0.01, -0.02, 0.03, 0.07};
      PetscReal       W, P[9], s[3] = {0, 0, 0};
      for (PetscInt a = 0; a < nb; ++a)
        for (PetscInt i = 0; i < dim; ++i) u[a * dim + i] = H0[i * 3] * xn[a * dim] + H0[i * 3 + 1] * xn[a * dim + 1] + H0[i * 3 + 2] * xn[a * dim + 2];
      e = EnergyGradient(b, u, g);
      (void)m->energy(param, NULL, H0, &W, P);
      for (PetscInt a = 0; a < nb; ++a)
        for (PetscInt i = 0; i < dim; ++i) s[i] += g[a * dim + i];
      printf("%s %s patch_W_rel %.6e\n%s %s patch_g_sum_rel %.6e\n", cell, m->name, (double)(PetscAbsReal(e - W * vol) / PetscAbsReal(W * vol)), cell, m->name, (double)(MaxAbs(3, s) / MaxAbs(n, g)));
    }
    { /* the six rigid modes at rest: K r = 0 */
      PetscReal worst = 0.0;
      ElementTangent(b, 0, NULL, K);
      for (PetscInt r = 0; r < 6; ++r) {
        for (PetscInt a = 0; a < nb; ++a) {
          const PetscReal *x = &xn[a * dim];
          PetscReal       *ur = &u[a * dim];
          ur[0] = ur[1] = ur[2] = 0.0;
          if (r < 3) ur[r] = 1.0;
          else if (r == 3) { ur[1] = -x[2]; ur[2] = x[1]; }
          else if (r == 4) { ur[0] = x[2]; ur[2] = -x[0]; }
          else { ur[0] = -x[1]; ur[1] = x[0]; }
        }
        for (PetscInt i = 0; i < n; ++i) {
          PetscReal s = 0.0;
          for (PetscInt j = 0; j < n; ++j) s += K[i * n + j] * u[j];
          worst = PetscMax(worst, PetscAbsReal(s) / (MaxAbs(n * n, K) * MaxAbs(n, u)));
        }
      }
      printf("%s %s rest_null_rel %.6e\n", cell, m->name, (double)worst);
    }
    if (neo) { /* a rigid rotation by 60 degrees about (1, 2, 3)/sqrt(14): no energy, no force */
      const PetscReal c = 0.5, s = PetscSqrtReal(3.0) / 2.0, nx = 1.0 / PetscSqrtReal(14.0), ny = 2.0 * nx, nz = 3.0 * nx;
      const PetscReal Q[9] = {c + (1 - c) * nx * nx, (1 - c) * nx * ny - s * nz, (1 - c) * nx * nz + s * ny, (1 - c) * ny * nx + s * nz, c + (1 - c) * ny * ny, (1 - c) * ny * nz - s * nx, (1 - c) * nz * nx - s * ny, (1 - c) * nz * ny + s * nx, c + (1 - c) * nz * nz};
      for (PetscInt a = 0; a < nb; ++a)
        for (PetscInt i = 0; i < dim; ++i) u[a * dim + i] = (Q[i * 3] - (i == 0)) * xn[a * dim] + (Q[i * 3 + 1] - (i == 1)) * xn[a * dim + 1] + (Q[i * 3 + 2] - (i == 2)) * xn[a * dim + 2];
      e = EnergyGradient(b, u, g);
      printf("%s %s rotation_W %.6e\n%s %s rotation_g %.6e\n", cell, m->name, (double)(e / (param[1] * vol)), cell, m->name, (double)(MaxAbs(n, g) / (param[1] * vol)));
    }
    PetscCall(PetscFree7(u, v, ut, g, gt, K, Kv));
  }
  PetscCall(PetscFree5(dNdx, wdetJ, xq, xn, cdof));
  PetscCall(PetscQuadratureDestroy(&q));
  PetscCall(PetscFEDestroy(&fe));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  const char     *names[] = {"linear", "neohookean"};
  const PetscReal p[2]    = {0.3 / (1.3 * 0.4), 1.0 / 2.6}; /* E = 1, nu = 0.3 */

  PetscCall(PetscInitialize(&argc, &argv, NULL, "Checks the element loop in 3D (tests/test_material_kernels.py)"));
  PetscCall(MaterialRegisterAll());
  for (PetscInt k = 0; k < 2; ++k) {
    const Material *m;
    PetscCall(MaterialFind(names[k], &m));
    PetscCheck(m, PETSC_COMM_SELF, PETSC_ERR_PLIB, "material %s is not registered", names[k]);
    PetscCall(Check("hex27", PETSC_FALSE, m, p));
    PetscCall(Check("tet10", PETSC_TRUE, m, p));
  }
  PetscCall(MaterialFinalize());
  PetscCall(PetscFinalize());
  return 0;
}
