/* A curved quadratic face of a 3D contact surface: the map, the weights of
   the nodal weighted gaps, the closest point, a box.

   Map. x(xi) = sum_i N_i(xi) x_i with the quadratic Lagrange basis: Tri6 on
   the unit triangle with barycentric l0 = 1 - r - s, l1 = r, l2 = s,
     N_c = l_c (2 l_c - 1) at the corners, N_e = 4 l_a l_b at the mid-edge
     node e of the edge a-b;
   Quad9 on [-1,1]^2 the tensor product of L_-(x) = x (x - 1)/2,
   L_+(x) = x (x + 1)/2 and L_0(x) = 1 - x^2. The tangents t_a = dx/dxi_a,
   the normal n = t_1 x t_2 / J and the area element J = |t_1 x t_2|, so that
   int_face f dS = int f(xi) J(xi) dxi; the second derivatives x_ab serve the
   closest point's Newton steps and its derivative.

   Weights. The weighted gap of slave node j is g_j = int W_j g dS / A_j with
   A_j = int W_j dS; a uniform gap gives g_j = g if sum_j W_j = 1, and every
   node needs A_j > 0. The P2 corner functions of a Tri6 integrate to zero
   (int N_c dS = 0 on a flat face, int N_e dS = A/3), so neither they nor
   their duals give the corners any weight. Popp and Wohlmuth's
   transformation moves a share alpha of each mid-edge function to the two
   corners of its edge:
     Nt_c = N_c + alpha (N_e + N_e') (e, e' the mid-edge nodes beside c),
     Nt_e = (1 - 2 alpha) N_e,
   still a partition of unity (each N_e gives alpha to two corners and keeps
   1 - 2 alpha); on a flat face of area A, int Nt_c dS = 2 alpha A/3 and
   int Nt_e dS = (1 - 2 alpha) A/3: positive for 0 < alpha < 1/2. alpha =
   1/5 (FACE3D_TRI6_ALPHA) gives the corners 2A/15 and the mid-edge nodes
   A/5. A Quad9's corner functions integrate positive (A/36 on a
   parallelogram, mid-edge A/9, centre 4A/9): Nt = N.
   The weights are the dual basis of Nt, biorthogonal over the face:
     W_i = sum_k A_ik Nt_k,  A = D M^-1,  M_jk = int Nt_j Nt_k dS,
     D = diag(int Nt_j dS),   so  int W_i Nt_k dS = delta_ik int Nt_k dS,
   and sum_i W_i = sum_k (sum_i A_ik) Nt_k = 1 (since sum_i D_i (M^-1)_ik
   = 1 for all k: the vector of ones solves M^T y = D 1 because
   M 1 = (int Nt_j sum_k Nt_k) = D 1 and M is symmetric). Then
     A_j = int W_j dS = sum_k int W_j Nt_k dS = int Nt_j dS > 0
   on any face whose area element keeps int Nt_j dS positive (a flat face,
   or a curved one whose J varies less than the margin: the check program
   measures both). M and D are the face rule's sums, so biorthogonality
   holds for that rule to round-off.

   Closest point. eta* minimises f = 1/2 |x(eta) - p|^2 over the face's
   polynomial surface (extended past its edges): r_a = (x - p) . t_a = 0,
   Newton with K_ab = t_a . t_b + (x - p) . x_ab (Gauss-Newton's t_a . t_b
   where K is not positive definite), steps capped at 1/2 in xi. The point
   is on the face where eta* lies in the reference domain (Face3dContains,
   a tolerance in xi): the in/out test. Else the closest point of the face
   is on its boundary (Face3dClosestPointOnFace: each edge's quadratic curve
   by Newton, clamped at the corners): behind a convex edge between two
   faces (a fan of normals, as at a corner node in 2D), or past the end of
   the master surface; segment3d.c tells the two apart.

   Box. The convex hull of a quadratic Bezier patch's control points holds
   the patch (its Bernstein basis is positive and sums to 1). A Lagrange
   mid-edge node x_e on the edge a-b is the Bezier control point
   b_e = 2 x_e - (x_a + x_b)/2; a Quad9 converts row by row, then column by
   column. So the box of the control points holds the curved face, which
   the box of its nodes does not (a bulging face rises above its nodes). */
#include "face3d.h"
#include "shape1d.h"
#include <petscdt.h>

static const PetscReal Tri6Xi[6][2]  = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
static const PetscInt  Quad9Ij[9][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {1, 2}, {2, 1}, {0, 2}, {2, 2}}; /* 1D functions L_-, L_+, L_0 in xi and eta */
static const PetscInt  Tri6Sub[4][3]  = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
static const PetscInt  Quad9Sub[8][3] = {{0, 4, 8}, {0, 8, 7}, {4, 1, 5}, {4, 5, 8}, {8, 5, 2}, {8, 2, 6}, {7, 8, 6}, {7, 6, 3}};

void Face3dNodeXi(Face3dType t, PetscInt i, PetscReal xi[2])
{
  static const PetscReal c[3] = {-1.0, 1.0, 0.0};
  if (t == FACE3D_TRI6) {
    xi[0] = Tri6Xi[i][0];
    xi[1] = Tri6Xi[i][1];
  } else {
    xi[0] = c[Quad9Ij[i][0]];
    xi[1] = c[Quad9Ij[i][1]];
  }
}

/* The flat sub-triangles through a face's nodes (Tri6: 4, Quad9: 8),
   anticlockwise in xi: the pieces the segment integration clips. */
void Face3dSubTriangles(Face3dType t, PetscInt *nsub, const PetscInt (**sub)[3])
{
  *nsub = t == FACE3D_TRI6 ? 4 : 8;
  *sub  = t == FACE3D_TRI6 ? Tri6Sub : Quad9Sub;
}

static inline void Lagrange1d(PetscReal x, PetscReal L[3], PetscReal dL[3], PetscReal d2L[3])
{
  EdgeShape(x, L, dL);
  d2L[0] = 1.0;
  d2L[1] = 1.0;
  d2L[2] = -2.0;
}

/* N[i], dN[2 i + a] = dN_i/dxi_a, d2N[3 i + (0, 1, 2)] = (rr, rs, ss); dN and
   d2N may be NULL. */
void Face3dShape(Face3dType t, const PetscReal xi[2], PetscReal N[], PetscReal dN[], PetscReal d2N[])
{
  if (t == FACE3D_TRI6) {
    const PetscReal r = xi[0], s = xi[1], l0 = 1.0 - r - s;
    const PetscReal n[6]     = {l0 * (2 * l0 - 1), r * (2 * r - 1), s * (2 * s - 1), 4 * l0 * r, 4 * r * s, 4 * s * l0};
    const PetscReal d[12]    = {1 - 4 * l0, 1 - 4 * l0, 4 * r - 1, 0, 0, 4 * s - 1, 4 * (l0 - r), -4 * r, 4 * s, 4 * r, -4 * s, 4 * (l0 - s)};
    const PetscReal dd[18]   = {4, 4, 4, 4, 0, 0, 0, 0, 4, -8, -4, 0, 0, 4, 0, 0, -4, -8};
    for (PetscInt i = 0; i < 6; ++i) N[i] = n[i];
    if (dN) for (PetscInt i = 0; i < 12; ++i) dN[i] = d[i];
    if (d2N) for (PetscInt i = 0; i < 18; ++i) d2N[i] = dd[i];
  } else {
    PetscReal L[3], dL[3], d2L[3], M[3], dM[3], d2M[3];
    Lagrange1d(xi[0], L, dL, d2L);
    Lagrange1d(xi[1], M, dM, d2M);
    for (PetscInt i = 0; i < 9; ++i) {
      const PetscInt a = Quad9Ij[i][0], b = Quad9Ij[i][1];
      N[i] = L[a] * M[b];
      if (dN) {
        dN[2 * i]     = dL[a] * M[b];
        dN[2 * i + 1] = L[a] * dM[b];
      }
      if (d2N) {
        d2N[3 * i]     = d2L[a] * M[b];
        d2N[3 * i + 1] = dL[a] * dM[b];
        d2N[3 * i + 2] = L[a] * d2M[b];
      }
    }
  }
}

/* The point X, tangents T = (t_1, t_2) and second derivatives H = (x_rr,
   x_rs, x_ss) at xi of the face through x[3 i + d]; T and H may be NULL. */
void Face3dEval(Face3dType t, const PetscReal x[], const PetscReal xi[2], PetscReal X[3], PetscReal T[6], PetscReal H[9])
{
  PetscReal      N[FACE3D_MAX_NODES], dN[2 * FACE3D_MAX_NODES], d2N[3 * FACE3D_MAX_NODES];
  const PetscInt n = Face3dNodes(t);

  Face3dShape(t, xi, N, dN, d2N);
  for (PetscInt d = 0; d < 3; ++d) {
    X[d] = 0.0;
    if (T) T[d] = T[3 + d] = 0.0;
    if (H) H[d] = H[3 + d] = H[6 + d] = 0.0;
    for (PetscInt i = 0; i < n; ++i) {
      X[d] += N[i] * x[3 * i + d];
      if (T) {
        T[d] += dN[2 * i] * x[3 * i + d];
        T[3 + d] += dN[2 * i + 1] * x[3 * i + d];
      }
      if (H)
        for (PetscInt k = 0; k < 3; ++k) H[3 * k + d] += d2N[3 * i + k] * x[3 * i + d];
    }
  }
}

/* The unit normal (t_1 x t_2)/J; returns the area element J. */
PetscReal Face3dNormal(const PetscReal T[6], PetscReal n[3])
{
  PetscReal J;

  n[0] = T[1] * T[5] - T[2] * T[4];
  n[1] = T[2] * T[3] - T[0] * T[5];
  n[2] = T[0] * T[4] - T[1] * T[3];
  J    = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (J > 0) for (PetscInt d = 0; d < 3; ++d) n[d] /= J;
  return J;
}

/* Whether xi lies in the reference domain, within tol. */
PetscBool Face3dContains(Face3dType t, const PetscReal xi[2], PetscReal tol)
{
  if (t == FACE3D_TRI6) return (PetscBool)(xi[0] >= -tol && xi[1] >= -tol && xi[0] + xi[1] <= 1.0 + tol);
  return (PetscBool)(PetscAbsReal(xi[0]) <= 1.0 + tol && PetscAbsReal(xi[1]) <= 1.0 + tol);
}

/* The basis the weights are dual to: Tri6 transformed (alpha), Quad9 N. */
void Face3dWeightBasis(Face3dType t, const PetscReal xi[2], PetscReal Nt[])
{
  if (t == FACE3D_TRI6) {
    const PetscReal a = FACE3D_TRI6_ALPHA;
    PetscReal       N[6];
    Face3dShape(t, xi, N, NULL, NULL);
    Nt[0] = N[0] + a * (N[3] + N[5]);
    Nt[1] = N[1] + a * (N[3] + N[4]);
    Nt[2] = N[2] + a * (N[4] + N[5]);
    for (PetscInt e = 3; e < 6; ++e) Nt[e] = (1.0 - 2.0 * a) * N[e];
  } else Face3dShape(t, xi, Nt, NULL, NULL);
}

/* W_i(xi) = sum_k A_ik Nt_k(xi) (A from Face3dDualCoefficients; A = NULL:
   the weights are Nt itself). */
void Face3dWeights(Face3dType t, const PetscReal A[], const PetscReal xi[2], PetscReal W[])
{
  PetscReal      Nt[FACE3D_MAX_NODES];
  const PetscInt n = Face3dNodes(t);

  Face3dWeightBasis(t, xi, Nt);
  for (PetscInt i = 0; i < n; ++i) {
    W[i] = A ? 0.0 : Nt[i];
    if (A) for (PetscInt k = 0; k < n; ++k) W[i] += A[i * n + k] * Nt[k];
  }
}

/* Newton on r_a = (x(eta) - p) . t_a = 0 from eta (updated); returns whether
   it converged (a step below 1e-12 in xi, taken, within 50 steps: Newton
   then leaves an error of the order of its square, round-off). */
PetscBool Face3dClosestPoint(Face3dType t, const PetscReal x[], const PetscReal p[3], PetscReal eta[2], PetscInt *its)
{
  for (PetscInt it = 0; it < 50; ++it) {
    PetscReal X[3], T[6], H[9], d[3], r[2], K[3], det, s[2], len;
    Face3dEval(t, x, eta, X, T, H);
    for (PetscInt k = 0; k < 3; ++k) d[k] = X[k] - p[k];
    r[0] = d[0] * T[0] + d[1] * T[1] + d[2] * T[2];
    r[1] = d[0] * T[3] + d[1] * T[4] + d[2] * T[5];
    K[0] = T[0] * T[0] + T[1] * T[1] + T[2] * T[2];
    K[1] = T[0] * T[3] + T[1] * T[4] + T[2] * T[5];
    K[2] = T[3] * T[3] + T[4] * T[4] + T[5] * T[5];
    {
      const PetscReal F0 = K[0] + d[0] * H[0] + d[1] * H[1] + d[2] * H[2];
      const PetscReal F1 = K[1] + d[0] * H[3] + d[1] * H[4] + d[2] * H[5];
      const PetscReal F2 = K[2] + d[0] * H[6] + d[1] * H[7] + d[2] * H[8];
      if (F0 > 0 && F0 * F2 - F1 * F1 > 0) { /* full Newton where K is positive definite */
        K[0] = F0;
        K[1] = F1;
        K[2] = F2;
      }
    }
    det = K[0] * K[2] - K[1] * K[1];
    if (!(det > 0)) break;
    s[0] = -(K[2] * r[0] - K[1] * r[1]) / det;
    s[1] = -(K[0] * r[1] - K[1] * r[0]) / det;
    len  = PetscSqrtReal(s[0] * s[0] + s[1] * s[1]);
    if (len > 0.5) {
      s[0] *= 0.5 / len;
      s[1] *= 0.5 / len;
    }
    eta[0] += s[0];
    eta[1] += s[1];
    if (its) *its = it + 1;
    if (len < 1e-12) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

/* The closest point on the face's boundary: each edge a quadratic curve
   x(s) = L_-(s) x_a + L_0(s) x_e + L_+(s) x_b, s in [-1, 1], by Newton on
   (x(s) - p) . x'(s) = 0 (Gauss-Newton where x' . x' + (x - p) . x'' is not
   positive), clamped to the ends (the corners); the nearest of the edges.
   eta is the point's face parameters (the edges are straight in xi). */
void Face3dClosestBoundaryPoint(Face3dType t, const PetscReal x[], const PetscReal p[3], PetscReal eta[2])
{
  static const PetscInt tri[3][3] = {{0, 3, 1}, {1, 4, 2}, {2, 5, 0}}, quad[4][3] = {{0, 4, 1}, {1, 5, 2}, {2, 6, 3}, {3, 7, 0}};
  const PetscInt        ne = t == FACE3D_TRI6 ? 3 : 4;
  PetscReal             best = PETSC_MAX_REAL;

  for (PetscInt e = 0; e < ne; ++e) {
    const PetscInt *v = t == FACE3D_TRI6 ? tri[e] : quad[e];
    PetscReal       s = 0.0, X[3], d2 = 0.0, xa[2], xb[2];
    for (PetscInt it = 0; it < 50; ++it) {
      const PetscReal L[3] = {0.5 * s * (s - 1), 1 - s * s, 0.5 * s * (s + 1)}, dL[3] = {s - 0.5, -2 * s, s + 0.5}, d2L[3] = {1, -2, 1};
      PetscReal       r = 0, K = 0, F = 0, step;
      for (PetscInt d = 0; d < 3; ++d) {
        const PetscReal xd  = L[0] * x[3 * v[0] + d] + L[1] * x[3 * v[1] + d] + L[2] * x[3 * v[2] + d];
        const PetscReal td  = dL[0] * x[3 * v[0] + d] + dL[1] * x[3 * v[1] + d] + dL[2] * x[3 * v[2] + d];
        const PetscReal t2d = d2L[0] * x[3 * v[0] + d] + d2L[1] * x[3 * v[1] + d] + d2L[2] * x[3 * v[2] + d];
        r += (xd - p[d]) * td;
        K += td * td;
        F += (xd - p[d]) * t2d;
      }
      if (K + F > 0) K += F;
      if (!(K > 0)) break;
      step = -r / K;
      step = PetscMax(-0.5, PetscMin(0.5, step));
      s    = PetscMax(-1.0, PetscMin(1.0, s + step));
      if (PetscAbsReal(step) < 1e-12) break;
    }
    {
      const PetscReal L[3] = {0.5 * s * (s - 1), 1 - s * s, 0.5 * s * (s + 1)};
      for (PetscInt d = 0; d < 3; ++d) {
        X[d] = L[0] * x[3 * v[0] + d] + L[1] * x[3 * v[1] + d] + L[2] * x[3 * v[2] + d];
        d2 += (X[d] - p[d]) * (X[d] - p[d]);
      }
    }
    if (d2 < best) {
      best = d2;
      Face3dNodeXi(t, v[0], xa);
      Face3dNodeXi(t, v[2], xb);
      eta[0] = 0.5 * (1 - s) * xa[0] + 0.5 * (1 + s) * xb[0];
      eta[1] = 0.5 * (1 - s) * xa[1] + 0.5 * (1 + s) * xb[1];
    }
  }
}

/* The closest point of the face itself (its reference domain) to p: that of
   the polynomial surface where it lies in the domain (within tol), else the
   nearest point of its boundary (*clamped). */
void Face3dClosestPointOnFace(Face3dType t, const PetscReal x[], const PetscReal p[3], PetscReal tol, PetscReal eta[2], PetscBool *clamped)
{
  PetscReal e[2] = {eta[0], eta[1]};

  if (Face3dClosestPoint(t, x, p, e, NULL) && Face3dContains(t, e, tol)) {
    eta[0]   = e[0];
    eta[1]   = e[1];
    *clamped = PETSC_FALSE;
    return;
  }
  Face3dClosestBoundaryPoint(t, x, p, eta);
  *clamped = PETSC_TRUE;
}

PetscReal Face3dSize(Face3dType t, const PetscReal x[])
{
  const PetscInt nc = t == FACE3D_TRI6 ? 3 : 4;
  PetscReal      h  = 0.0;

  for (PetscInt j = 0; j < nc; ++j) {
    PetscReal l = 0.0;
    for (PetscInt d = 0; d < 3; ++d) l += PetscSqr(x[3 * j + d] - x[3 * ((j + 1) % nc) + d]);
    h = PetscMax(h, l);
  }
  return PetscSqrtReal(h);
}

/* The box (lo[3], hi[3]) of the face's Bezier control points. */
void Face3dBox(Face3dType t, const PetscReal x[], PetscReal box[6])
{
  PetscReal      b[3 * FACE3D_MAX_NODES];
  const PetscInt n = Face3dNodes(t);

  for (PetscInt k = 0; k < 3 * n; ++k) b[k] = x[k];
  for (PetscInt d = 0; d < 3; ++d) {
    if (t == FACE3D_TRI6) {
      b[9 + d]  = 2 * x[9 + d] - 0.5 * (x[d] + x[3 + d]);
      b[12 + d] = 2 * x[12 + d] - 0.5 * (x[3 + d] + x[6 + d]);
      b[15 + d] = 2 * x[15 + d] - 0.5 * (x[6 + d] + x[d]);
    } else {
      const PetscReal c4 = 2 * x[12 + d] - 0.5 * (x[d] + x[3 + d]);  /* rows in xi */
      const PetscReal c6 = 2 * x[18 + d] - 0.5 * (x[9 + d] + x[6 + d]);
      const PetscReal c8 = 2 * x[24 + d] - 0.5 * (x[21 + d] + x[15 + d]);
      b[12 + d] = c4;
      b[18 + d] = c6;
      b[15 + d] = 2 * x[15 + d] - 0.5 * (x[3 + d] + x[6 + d]); /* then columns in eta */
      b[21 + d] = 2 * x[21 + d] - 0.5 * (x[d] + x[9 + d]);
      b[24 + d] = 2 * c8 - 0.5 * (c4 + c6);
    }
    box[d] = box[3 + d] = b[d];
    for (PetscInt i = 1; i < n; ++i) {
      box[d]     = PetscMin(box[d], b[3 * i + d]);
      box[3 + d] = PetscMax(box[3 + d], b[3 * i + d]);
    }
  }
}

/* A Gauss rule of the given degree on the face's reference domain: PETSc's
   simplex rule mapped from (-1,-1), (1,-1), (-1,1) to the unit triangle
   (weights sum to 1/2), or the tensor Gauss rule on [-1,1]^2. */
PetscErrorCode Face3dRuleCreate(Face3dType t, PetscInt degree, Face3dRule *rule)
{
  PetscQuadrature  q;
  const PetscReal *p, *w;
  PetscInt         nq;

  PetscFunctionBeginUser;
  PetscCheck(degree >= 1 && degree <= 30, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "face rule of degree %" PetscInt_FMT ": 1 to 30", degree);
  if (t == FACE3D_TRI6) PetscCall(PetscDTSimplexQuadrature(2, degree, PETSCDTSIMPLEXQUAD_DEFAULT, &q));
  else PetscCall(PetscDTGaussTensorQuadrature(2, 1, (degree + 2) / 2, -1.0, 1.0, &q));
  PetscCall(PetscQuadratureGetData(q, NULL, NULL, &nq, &p, &w));
  rule->nq = nq;
  PetscCall(PetscMalloc2(2 * nq, &rule->xi, nq, &rule->w));
  for (PetscInt k = 0; k < nq; ++k) {
    const PetscBool tri = (PetscBool)(t == FACE3D_TRI6);
    rule->xi[2 * k]     = tri ? 0.5 * (p[2 * k] + 1.0) : p[2 * k];
    rule->xi[2 * k + 1] = tri ? 0.5 * (p[2 * k + 1] + 1.0) : p[2 * k + 1];
    rule->w[k]          = tri ? 0.25 * w[k] : w[k];
  }
  PetscCall(PetscQuadratureDestroy(&q));
  PetscFunctionReturn(0);
}

PetscErrorCode Face3dRuleDestroy(Face3dRule *rule)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(rule->xi, rule->w));
  rule->nq = 0;
  PetscFunctionReturn(0);
}

/* A = D M^-1 on the face through x (its area element; the reference
   configuration, so that the weights do not move with u), M and D the
   rule's sums; M^-1 by Gauss-Jordan with partial pivoting. */
PetscErrorCode Face3dDualCoefficients(Face3dType t, const PetscReal x[], const Face3dRule *rule, PetscReal A[])
{
  const PetscInt n = Face3dNodes(t);
  PetscReal      M[FACE3D_MAX_NODES * FACE3D_MAX_NODES] = {0}, Mi[FACE3D_MAX_NODES * FACE3D_MAX_NODES] = {0}, D[FACE3D_MAX_NODES] = {0}, big = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < rule->nq; ++q) {
    PetscReal X[3], T[6], nrm[3], Nt[FACE3D_MAX_NODES], dS;
    Face3dEval(t, x, &rule->xi[2 * q], X, T, NULL);
    dS = Face3dNormal(T, nrm) * rule->w[q];
    Face3dWeightBasis(t, &rule->xi[2 * q], Nt);
    for (PetscInt j = 0; j < n; ++j) {
      D[j] += Nt[j] * dS;
      for (PetscInt k = 0; k < n; ++k) M[j * n + k] += Nt[j] * Nt[k] * dS;
    }
  }
  for (PetscInt k = 0; k < n * n; ++k) big = PetscMax(big, PetscAbsReal(M[k]));
  for (PetscInt i = 0; i < n; ++i) Mi[i * n + i] = 1.0;
  for (PetscInt c = 0; c < n; ++c) {
    PetscInt  p = c;
    PetscReal piv;
    for (PetscInt r = c + 1; r < n; ++r)
      if (PetscAbsReal(M[r * n + c]) > PetscAbsReal(M[p * n + c])) p = r;
    PetscCheck(PetscAbsReal(M[p * n + c]) > 1e-14 * big, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "degenerate face: its mass matrix is singular at column %" PetscInt_FMT " (pivot %g of %g)", c, (double)M[p * n + c], (double)big);
    for (PetscInt k = 0; k < n; ++k) {
      PetscReal tmp = M[c * n + k];
      M[c * n + k]  = M[p * n + k];
      M[p * n + k]  = tmp;
      tmp           = Mi[c * n + k];
      Mi[c * n + k] = Mi[p * n + k];
      Mi[p * n + k] = tmp;
    }
    piv = M[c * n + c];
    for (PetscInt k = 0; k < n; ++k) {
      M[c * n + k] /= piv;
      Mi[c * n + k] /= piv;
    }
    for (PetscInt r = 0; r < n; ++r) {
      const PetscReal f = M[r * n + c];
      if (r == c || f == 0.0) continue;
      for (PetscInt k = 0; k < n; ++k) {
        M[r * n + k] -= f * M[c * n + k];
        Mi[r * n + k] -= f * Mi[c * n + k];
      }
    }
  }
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt k = 0; k < n; ++k) A[i * n + k] = D[i] * Mi[i * n + k];
  PetscFunctionReturn(0);
}

void Face3dPlaneBasis(const PetscReal n[3], PetscReal T[6])
{
  PetscInt  a = 0;
  PetscReal l;

  for (PetscInt c = 1; c < 3; ++c)
    if (PetscAbsReal(n[c]) < PetscAbsReal(n[a])) a = c;
  for (PetscInt c = 0; c < 3; ++c) T[c] = (c == a ? 1.0 : 0.0) - n[a] * n[c];
  l = PetscSqrtReal(T[0] * T[0] + T[1] * T[1] + T[2] * T[2]);
  for (PetscInt c = 0; c < 3; ++c) T[c] /= l;
  T[3] = n[1] * T[2] - n[2] * T[1];
  T[4] = n[2] * T[0] - n[0] * T[2];
  T[5] = n[0] * T[1] - n[1] * T[0];
}
