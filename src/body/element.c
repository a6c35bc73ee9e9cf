/* The element loop, written once for any dimension: per cell the nodal
   displacements, the displacement gradient H at each quadrature point, the
   material's pointwise kernels of H (material.h), and their contraction with
   the basis into the cell's energy, gradient and tangent.

   It reads the cell cache (bodyimpl.h) with stride dim (2 or 3): the basis
   gradients dNdx[c][q][a][J] = dN_a/dX_J, the weights wdetJ[c][q] (dV: dA,
   2 pi r dA in axisymmetry, the volume in 3D) and the quadrature points
   xq[c][q][dim], for any element of up to ELEMENT_MAX_NODES nodes, and a
   material with history's state[c][q][nstate] (bodystate.c), each point's
   given to the kernels (the tangent at rest: the virgin state's, NULL).

   At a quadrature point, H_iJ = sum_a u_(a i) dN_a/dX_J for i, J < dim,
   and in axisymmetry (x = r) H_22 = u_r / r = sum_a u_(a 0) N_a / r, so
   dH_iJ/du_(a i) = dN_a/dX_J and dH_22/du_(a 0) = N_a / r. With
   P = dW/dF and A = d2W/dF dF from the material,
     energy:   Pi_c = sum_q w W,
     gradient: dPi_c/du_(a i) = sum_q w (P_iJ dN_a/dX_J + d_i0 P_22 N_a / r),
     tangent:  K_(a i)(b j) = sum_q w [ A_iJjL dN_a/dX_J dN_b/dX_L
                 + d_i0 (N_a/r) A_22jL dN_b/dX_L + d_j0 (N_b/r) A_iJ22 dN_a/dX_J
                 + d_i0 d_j0 A_2222 N_a N_b / r^2 ],
   the terms in N/r in axisymmetry only (neohookean.c derives them). The
   in-plane part is contracted in two steps, G_(a i) jL = w dN_a/dX_J
   A_iJjL, then K += G dN_b, over the blocks b >= a (K is symmetric; the
   lower blocks are mirrored); the (0, 0) hoop terms use A's symmetry
   A_220J = A_0J22. Sums run over J < dim in order from zero, so that a 2D
   body's numbers are those of the 2D loops they replace (a zero entry of
   A adds an exact zero: linear elasticity's r-z terms are its old ones). */
#include "element.h"
#include "bodyimpl.h"

/* Each loop is written once with dim an argument, inlined where dim is the
   constant 2 or 3 (the public functions below choose), so that the
   compiler unrolls the loops over components as a 2D-only loop was. */
#if defined(__GNUC__)
  #define ELEMENT_INLINE static inline __attribute__((always_inline))
#else
  #define ELEMENT_INLINE static inline
#endif
/* before a loop over components (at most 3): unrolled (-O2 does not) */
#if defined(__GNUC__) && !defined(__clang__)
  #define ELEMENT_UNROLL _Pragma("GCC unroll 3")
#else
  #define ELEMENT_UNROLL
#endif

ELEMENT_INLINE void GatherDim(Body b, PetscInt c, const PetscScalar x[], PetscReal u[], const PetscInt dim)
{
  const PetscInt nb = b->nb, *dof = &b->cdof[c * nb];

  for (PetscInt a = 0; a < nb; ++a)
    ELEMENT_UNROLL
    for (PetscInt i = 0; i < dim; ++i) u[a * dim + i] = x ? PetscRealPart(x[dof[a] + i]) : 0.0;
}

/* (summed in h, which nothing can alias, so that it stays in registers) */
ELEMENT_INLINE void FormGradientDim(PetscInt nb, const PetscReal u[], const PetscReal dN[], PetscReal H[9], const PetscInt dim)
{
  PetscReal h[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};

  for (PetscInt a = 0; a < nb; ++a)
    ELEMENT_UNROLL
    for (PetscInt i = 0; i < dim; ++i)
      ELEMENT_UNROLL
      for (PetscInt J = 0; J < dim; ++J) h[i][J] += u[a * dim + i] * dN[a * dim + J];
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt J = 0; J < 3; ++J) H[i * 3 + J] = h[i][J];
}

ELEMENT_INLINE void PointGradientDim(Body b, PetscInt c, PetscInt iq, const PetscReal u[], PetscReal uq[], PetscReal H[9], const PetscInt dim)
{
  const PetscInt   nb = b->nb, nq = b->nq;
  const PetscReal *dN = &b->dNdx[(c * nq + iq) * nb * dim], *B = &b->B[iq * nb];

  FormGradientDim(nb, u, dN, H, dim);
  if (uq) {
    ELEMENT_UNROLL
    for (PetscInt i = 0; i < dim; ++i) uq[i] = 0.0;
    for (PetscInt a = 0; a < nb; ++a)
      ELEMENT_UNROLL
      for (PetscInt i = 0; i < dim; ++i) uq[i] += B[a] * u[a * dim + i];
  }
  if (b->axisym) { /* the hoop strain u_r / r, at a quadrature point (r > 0) */
    PetscReal ur = 0.0;
    for (PetscInt a = 0; a < nb; ++a) ur += B[a] * u[a * dim];
    H[8] = ElasticityHoopStrain(ur, H[0], b->xq[(c * nq + iq) * dim]);
  }
}

/* The exact solution's body force f[dim] at x, times the load factor (a
   load, as the Dirichlet values it goes with). f = -div P(F(u)): its own
   (linear elasticity's) for a material of constant tangent, else from the
   material's tangent at grad u and the solution's second derivatives,
   f_i = -A_iJkL d2u_k/dX_J dX_L (du[i*dim+J], d2u[(k*dim+J)*dim+L]: exact.h). */
static void ElementExactForce(Body b, const PetscReal x[], PetscReal f[])
{
  const PetscInt dim = b->dim;

  if (b->mat->constantTangent) b->exact.f(b->exact.params, b->param[0], b->param[1], x, f);
  else {
    PetscReal du[9], d2u[27], H[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, A[81];
    b->exact.du(b->exact.params, x, du);
    b->exact.d2u(b->exact.params, x, d2u);
    ELEMENT_UNROLL
    for (PetscInt i = 0; i < dim; ++i)
      ELEMENT_UNROLL
      for (PetscInt J = 0; J < dim; ++J) H[i * 3 + J] = du[i * dim + J];
    b->mat->moduli(b->param, NULL, H, A); /* a material without history (BodySetFromOptions) */
    ELEMENT_UNROLL
    for (PetscInt i = 0; i < dim; ++i) {
      f[i] = 0.0;
      ELEMENT_UNROLL
      for (PetscInt J = 0; J < dim; ++J)
        ELEMENT_UNROLL
        for (PetscInt k = 0; k < dim; ++k)
          ELEMENT_UNROLL
          for (PetscInt L = 0; L < dim; ++L) f[i] -= A[((i * 3 + J) * 3 + k) * 3 + L] * d2u[(k * dim + J) * dim + L];
    }
  }
  ELEMENT_UNROLL
  for (PetscInt i = 0; i < dim; ++i) f[i] *= b->loadFactor;
}

/* The sums run in locals (el, g), which nothing else can alias, and are
   written out at the end: a stride-dim loop as fast as the 2D one was. */
ELEMENT_INLINE PetscBool EnergyGradientDim(Body b, PetscInt c, const PetscScalar x[], PetscReal *e, PetscScalar ge[], PetscInt *iqBad, const PetscInt dim)
{
  const PetscInt   nb = b->nb, nq = b->nq, *dof = &b->cdof[c * nb], ns = b->mat->nstate;
  const PetscBool  axisym = b->axisym, hasExact = b->hasExact, canInvert = (PetscBool)!b->mat->constantTangent;
  const PetscReal *xq = &b->xq[c * nq * dim], *wdetJ = &b->wdetJ[c * nq], *param = b->param, *state = ns ? &b->state[c * nq * ns] : NULL;
  PetscBool (*energy)(const PetscReal[], const PetscReal[], const PetscReal[], PetscReal *, PetscReal[]) = b->mat->energy;
  PetscReal u[ELEMENT_MAX_DOFS], g[ELEMENT_MAX_DOFS], el = *e;
  PetscBool ok = PETSC_TRUE;

  GatherDim(b, c, x, u, dim);
  for (PetscInt k = 0; k < nb * dim; ++k) g[k] = 0.0;
  for (PetscInt iq = 0; iq < nq; ++iq) {
    const PetscReal *dN = &b->dNdx[(c * nq + iq) * nb * dim], *B = &b->B[iq * nb];
    const PetscReal  w  = wdetJ[iq];
    PetscReal        H[9], W, P[9], s3r = 0.0;

    PointGradientDim(b, c, iq, u, NULL, H, dim);
    /* in r-z a hoop stretch 1 + u_r/r <= 0 is a point through the axis,
       inverted whatever J = det F says (the linear material is defined for
       every H) */
    if (!energy(param, state ? &state[iq * ns] : NULL, H, &W, P) || (axisym && canInvert && !(1.0 + H[8] > 0.0))) {
      *iqBad = iq;
      ok     = PETSC_FALSE;
      break;
    }
    if (axisym) s3r = P[8] / xq[iq * dim];
    el += w * W;
    for (PetscInt a = 0; a < nb; ++a)
      ELEMENT_UNROLL
      for (PetscInt i = 0; i < dim; ++i) {
        PetscReal t = 0.0;
        ELEMENT_UNROLL
        for (PetscInt J = 0; J < dim; ++J) t += P[i * 3 + J] * dN[a * dim + J];
        if (i == 0) t += s3r * B[a];
        g[a * dim + i] += w * t;
      }
    if (hasExact) {
      PetscReal f[3], uq[3], fu = 0.0;
      ElementExactForce(b, &xq[iq * dim], f);
      ELEMENT_UNROLL
      for (PetscInt i = 0; i < dim; ++i) uq[i] = 0.0;
      for (PetscInt a = 0; a < nb; ++a)
        ELEMENT_UNROLL
        for (PetscInt i = 0; i < dim; ++i) uq[i] += B[a] * u[a * dim + i];
      ELEMENT_UNROLL
      for (PetscInt i = 0; i < dim; ++i) fu += f[i] * uq[i];
      el -= w * fu;
      for (PetscInt a = 0; a < nb; ++a)
        ELEMENT_UNROLL
        for (PetscInt i = 0; i < dim; ++i) g[a * dim + i] -= w * f[i] * B[a];
    }
  }
  *e = el;
  for (PetscInt a = 0; a < nb; ++a)
    ELEMENT_UNROLL
    for (PetscInt i = 0; i < dim; ++i) ge[dof[a] + i] += g[a * dim + i];
  return ok;
}

ELEMENT_INLINE void TangentDim(Body b, PetscInt c, const PetscReal u[], PetscScalar K[], const PetscInt dim)
{
  const PetscInt   nb = b->nb, nq = b->nq, n = dim * nb, ns = b->mat->nstate;
  const PetscReal *state = ns && u ? &b->state[c * nq * ns] : NULL; /* at rest (u NULL): the virgin state's */
  PetscReal        G[ELEMENT_MAX_NODES][3][3][3]; /* w dN_a/dX_J A_iJjL, summed over J: 5.8 KB */

  const PetscBool constant = (PetscBool)(!u || b->mat->constantTangent); /* A the same at every point: asked once */
  PetscReal       A[81];

  for (PetscInt k = 0; k < n * n; ++k) K[k] = 0.0;
  if (constant) {
    const PetscReal H[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    b->mat->moduli(b->param, NULL, H, A);
  }
  for (PetscInt iq = 0; iq < nq; ++iq) {
    const PetscReal *dN = &b->dNdx[(c * nq + iq) * nb * dim], *B = &b->B[iq * nb];
    const PetscReal  w  = b->wdetJ[c * nq + iq], r = b->axisym ? b->xq[(c * nq + iq) * dim] : 0.0;

    if (!constant) {
      PetscReal H[9];
      PointGradientDim(b, c, iq, u, NULL, H, dim);
      b->mat->moduli(b->param, state ? &state[iq * ns] : NULL, H, A);
    }
    for (PetscInt a = 0; a < nb; ++a)
      ELEMENT_UNROLL
      for (PetscInt i = 0; i < dim; ++i)
        ELEMENT_UNROLL
        for (PetscInt j = 0; j < dim; ++j)
          ELEMENT_UNROLL
          for (PetscInt L = 0; L < dim; ++L) {
            PetscReal s = 0.0;
            ELEMENT_UNROLL
            for (PetscInt J = 0; J < dim; ++J) s += dN[a * dim + J] * A[((i * 3 + J) * 3 + j) * 3 + L];
            G[a][i][j][L] = w * s;
          }
    for (PetscInt a = 0; a < nb; ++a) /* the upper blocks (bb >= a) */
      ELEMENT_UNROLL
      for (PetscInt i = 0; i < dim; ++i)
        for (PetscInt bb = a; bb < nb; ++bb)
          ELEMENT_UNROLL
          for (PetscInt j = 0; j < dim; ++j) {
            PetscReal s = 0.0;
            ELEMENT_UNROLL
            for (PetscInt L = 0; L < dim; ++L) s += G[a][i][j][L] * dN[bb * dim + L];
            K[(dim * a + i) * n + dim * bb + j] += s;
          }
    if (r > 0) /* axisymmetry: the hoop strain's terms, dH_22/du_(a 0) = N_a / r */
      for (PetscInt a = 0; a < nb; ++a)
        for (PetscInt bb = a; bb < nb; ++bb) {
          const PetscReal na = B[a] / r, nbb = B[bb] / r;
          PetscReal       k = 0.0;
          /* (0, 0): sum_J A_0J22 (dN_a/dX_J N_b + N_a dN_b/dX_J) / r + A_2222 N_a N_b / r^2 (A_220J = A_0J22) */
          ELEMENT_UNROLL
          for (PetscInt J = 0; J < dim; ++J) k += A[(0 * 3 + J) * 9 + 8] * (dN[a * dim + J] * nbb + na * dN[bb * dim + J]);
          k += A[80] * na * nbb;
          K[(dim * a) * n + dim * bb] += w * k;
          ELEMENT_UNROLL
          for (PetscInt j = 1; j < dim; ++j) /* (0, j): N_a / r A_22jL dN_b/dX_L */
            ELEMENT_UNROLL
            for (PetscInt L = 0; L < dim; ++L) K[(dim * a) * n + dim * bb + j] += w * A[8 * 9 + j * 3 + L] * na * dN[bb * dim + L];
          ELEMENT_UNROLL
          for (PetscInt i = 1; i < dim; ++i) /* (i, 0): N_b / r A_iJ22 dN_a/dX_J */
            ELEMENT_UNROLL
            for (PetscInt J = 0; J < dim; ++J) K[(dim * a + i) * n + dim * bb] += w * A[(i * 3 + J) * 9 + 8] * dN[a * dim + J] * nbb;
        }
  }
  for (PetscInt a = 0; a < nb; ++a)
    ELEMENT_UNROLL
    for (PetscInt i = 0; i < dim; ++i)
      for (PetscInt bb = a + 1; bb < nb; ++bb)
        ELEMENT_UNROLL
        for (PetscInt j = 0; j < dim; ++j) K[(dim * bb + j) * n + dim * a + i] = K[(dim * a + i) * n + dim * bb + j];
}

void ElementGather(Body b, PetscInt c, const PetscScalar x[], PetscReal u[])
{
  if (b->dim == 2) GatherDim(b, c, x, u, 2);
  else GatherDim(b, c, x, u, 3);
}

void ElementFormGradient(PetscInt dim, PetscInt nb, const PetscReal u[], const PetscReal dN[], PetscReal H[9])
{
  if (dim == 2) FormGradientDim(nb, u, dN, H, 2);
  else FormGradientDim(nb, u, dN, H, 3);
}

void ElementPointGradient(Body b, PetscInt c, PetscInt iq, const PetscReal u[], PetscReal uq[], PetscReal H[9])
{
  if (b->dim == 2) PointGradientDim(b, c, iq, u, uq, H, 2);
  else PointGradientDim(b, c, iq, u, uq, H, 3);
}

PetscBool ElementAddEnergyGradient(Body b, PetscInt c, const PetscScalar x[], PetscReal *e, PetscScalar g[], PetscInt *iqBad)
{
  return b->dim == 2 ? EnergyGradientDim(b, c, x, e, g, iqBad, 2) : EnergyGradientDim(b, c, x, e, g, iqBad, 3);
}

void ElementTangent(Body b, PetscInt c, const PetscReal u[], PetscScalar K[])
{
  if (b->dim == 2) TangentDim(b, c, u, K, 2);
  else TangentDim(b, c, u, K, 3);
}
