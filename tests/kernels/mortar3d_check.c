/* A check of the 3D mortar kernels (face3d.c, clip.c, segment3d.c, bvh.c), no
   mesh file needed: bin/mortar3d-check, driven by tests/test_mortar3d_kernels.py,
   which asserts the figures it prints, one "case figure value" a line.

   basis   (Tri6 and Quad9, flat and curved faces) the partition of unity of
           N, Nt and W at random xi; int W_i Nt_k dS - delta_ik int Nt_k dS
           with the face rule; A_j = int W_j dS of every node over the face's
           area; the plain P2 corner's int N_c dS.
   patch   a flat slave of Tri6 faces (interior corners moved at random)
           under a flat master of Quad9 faces, non-matching, at the gap g0:
           g_j = Q_j / A_j against g0 (nodes with |A_j| >= 0.05 max A: a
           node whose support the master covers partly can have A_j near 0),
           |Q_j - g0 A_j| / (g0 max A) at every node, and sum A_j against the
           overlap's area; and a Quad9 slave under a Tri6 master, tilted;
           level, tilted (a rotation and a shift of both), and with the
           master ending inside the slave (partial).
   sphere  a slave sphere of radius 1 (an octahedron's faces divided n x n,
           curved Tri6, nodes on the sphere) inside a master sphere of radius
           1 + g0 (a cube's faces divided m x m, curved Quad9, normals
           inward): max |g_j - g0| for n = 2, 4, 8, 16 (m = 3n/2).
   deriv   dQ_j against central differences (h = 1e-6) of Q_j at the frozen
           points, and d eta* against differences of the closest point, on
           curved faces moved at random; and dQ against differences of the
           whole computation (the segments made again) on the tilted patch.
   bvh     the tree's answers against every box tested, on random boxes. */
#include "face3d.h"
#include "segment3d.h"
#include "clip.h"
#include "bvh.h"

#include "checkutil.h"

#define PI 3.14159265358979323846

/* A surface mesh: nf faces of one type, conn[nn f + i] into nodes x[3 v]. */
typedef struct {
  Face3dType type;
  PetscInt   nf, nv, *conn;
  PetscReal *x;
} Mesh;

static PetscErrorCode MeshDestroy(Mesh *m)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(m->conn));
  PetscCall(PetscFree(m->x));
  PetscFunctionReturn(0);
}

static PetscErrorCode MeshAlloc(Face3dType t, PetscInt nf, PetscInt nv, Mesh *m)
{
  PetscFunctionBeginUser;
  m->type = t;
  m->nf   = nf;
  m->nv   = nv;
  PetscCall(PetscMalloc1(Face3dNodes(t) * nf, &m->conn));
  PetscCall(PetscMalloc1(3 * nv, &m->x));
  PetscFunctionReturn(0);
}

static void FaceCoords(const Mesh *m, PetscInt f, PetscReal *xf)
{
  const PetscInt n = Face3dNodes(m->type);
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt d = 0; d < 3; ++d) xf[3 * i + d] = m->x[3 * m->conn[n * f + i] + d];
}

/* Flat Tri6 slave on [0,1]^2 (z = 0, normal +z), nx x nx squares in two
   triangles, interior corners moved by up to 0.2 h, straight edges. */
static PetscErrorCode MeshFlatTri6(PetscInt nx, Mesh *m)
{
  const PetscInt G = 2 * nx + 1;
  const PetscReal h = 1.0 / nx;

  PetscFunctionBeginUser;
  PetscCall(MeshAlloc(FACE3D_TRI6, 2 * nx * nx, G * G, m));
  for (PetscInt j = 0; j < G; j += 2)
    for (PetscInt i = 0; i < G; i += 2) {
      const PetscBool in = (PetscBool)(i > 0 && j > 0 && i < G - 1 && j < G - 1);
      PetscReal      *p  = &m->x[3 * (j * G + i)];
      p[0]               = 0.5 * i * h + (in ? Uniform(-0.2, 0.2) * h : 0.0);
      p[1]               = 0.5 * j * h + (in ? Uniform(-0.2, 0.2) * h : 0.0);
      p[2]               = 0.0;
    }
  for (PetscInt j = 0; j < G; ++j) /* mid-edge and diagonal nodes at the middle of their corners */
    for (PetscInt i = 0; i < G; ++i) {
      PetscInt a, b;
      if (i % 2 == 0 && j % 2 == 0) continue;
      if (i % 2 && j % 2) {
        a = (j - 1) * G + i - 1;
        b = (j + 1) * G + i + 1;
      } else if (i % 2) {
        a = j * G + i - 1;
        b = j * G + i + 1;
      } else {
        a = (j - 1) * G + i;
        b = (j + 1) * G + i;
      }
      for (PetscInt d = 0; d < 3; ++d) m->x[3 * (j * G + i) + d] = 0.5 * (m->x[3 * a + d] + m->x[3 * b + d]);
    }
  for (PetscInt j = 0, f = 0; j < nx; ++j)
    for (PetscInt i = 0; i < nx; ++i) {
      const PetscInt I0 = 2 * i, J0 = 2 * j;
#define V(a, b) ((J0 + (b)) * G + I0 + (a))
      const PetscInt t1[6] = {V(0, 0), V(2, 0), V(2, 2), V(1, 0), V(2, 1), V(1, 1)};
      const PetscInt t2[6] = {V(0, 0), V(2, 2), V(0, 2), V(1, 1), V(1, 2), V(0, 1)};
#undef V
      for (PetscInt k = 0; k < 6; ++k) {
        m->conn[6 * f + k]     = t1[k];
        m->conn[6 * f + 6 + k] = t2[k];
      }
      f += 2;
    }
  PetscFunctionReturn(0);
}

/* Flat Quad9 master on [x0,x1] x [y0,y1] at z = g0, normal -z (xi along y,
   eta along x), mx x my faces, interior corners moved by up to 0.15 h. */
static PetscErrorCode MeshFlatQuad9(PetscInt mx, PetscInt my, PetscReal x0, PetscReal x1, PetscReal y0, PetscReal y1, PetscReal g0, Mesh *m)
{
  const PetscInt  Gx = 2 * mx + 1, Gy = 2 * my + 1;
  const PetscReal hx = (x1 - x0) / mx, hy = (y1 - y0) / my;

  PetscFunctionBeginUser;
  PetscCall(MeshAlloc(FACE3D_QUAD9, mx * my, Gx * Gy, m));
  for (PetscInt j = 0; j < Gy; j += 2)
    for (PetscInt i = 0; i < Gx; i += 2) {
      const PetscBool in = (PetscBool)(i > 0 && j > 0 && i < Gx - 1 && j < Gy - 1);
      PetscReal      *p  = &m->x[3 * (j * Gx + i)];
      p[0]               = x0 + 0.5 * i * hx + (in ? Uniform(-0.15, 0.15) * hx : 0.0);
      p[1]               = y0 + 0.5 * j * hy + (in ? Uniform(-0.15, 0.15) * hy : 0.0);
      p[2]               = g0;
    }
  for (PetscInt j = 0; j < Gy; ++j)
    for (PetscInt i = 0; i < Gx; ++i) {
      PetscReal *p = &m->x[3 * (j * Gx + i)];
      if (i % 2 == 0 && j % 2 == 0) continue;
      for (PetscInt d = 0; d < 3; ++d) {
        if (i % 2 && j % 2) p[d] = 0.25 * (m->x[3 * ((j - 1) * Gx + i - 1) + d] + m->x[3 * ((j - 1) * Gx + i + 1) + d] + m->x[3 * ((j + 1) * Gx + i - 1) + d] + m->x[3 * ((j + 1) * Gx + i + 1) + d]);
        else if (i % 2) p[d] = 0.5 * (m->x[3 * (j * Gx + i - 1) + d] + m->x[3 * (j * Gx + i + 1) + d]);
        else p[d] = 0.5 * (m->x[3 * ((j - 1) * Gx + i) + d] + m->x[3 * ((j + 1) * Gx + i) + d]);
      }
    }
  for (PetscInt j = 0, f = 0; j < my; ++j)
    for (PetscInt i = 0; i < mx; ++i, ++f) {
      const PetscInt I0 = 2 * i, J0 = 2 * j;
      /* xi along +y, eta along +x: t_xi x t_eta = y x x = -z */
#define V(a, b) ((J0 + (b)) * Gx + I0 + (a))
      const PetscInt q[9] = {V(0, 0), V(0, 2), V(2, 2), V(2, 0), V(0, 1), V(1, 2), V(2, 1), V(1, 0), V(1, 1)};
#undef V
      for (PetscInt k = 0; k < 9; ++k) m->conn[9 * f + k] = q[k];
    }
  PetscFunctionReturn(0);
}

/* x <- R x + c for every node (R the rotation by angle about axis). */
static void MeshMove(Mesh *m, const PetscReal axis[3], PetscReal angle, const PetscReal c[3])
{
  const PetscReal l = PetscSqrtReal(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const PetscReal u[3] = {axis[0] / l, axis[1] / l, axis[2] / l}, cs = PetscCosReal(angle), sn = PetscSinReal(angle);
  PetscReal       R[9];
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) R[3 * i + j] = (i == j ? cs : 0.0) + (1 - cs) * u[i] * u[j];
  R[1] -= sn * u[2];
  R[2] += sn * u[1];
  R[3] += sn * u[2];
  R[5] -= sn * u[0];
  R[6] -= sn * u[1];
  R[7] += sn * u[0];
  for (PetscInt v = 0; v < m->nv; ++v) {
    PetscReal *p = &m->x[3 * v], q[3];
    for (PetscInt i = 0; i < 3; ++i) q[i] = R[3 * i] * p[0] + R[3 * i + 1] * p[1] + R[3 * i + 2] * p[2] + c[i];
    for (PetscInt i = 0; i < 3; ++i) p[i] = q[i];
  }
}

/* Merges nodes that coincide (to 1e-10): the sphere's faces are made one by
   one. Sorted by x, then each compared with those of nearly the same x. */
static PetscReal *sortx;
static int        CompareX(const void *a, const void *b)
{
  const PetscReal u = sortx[3 * *(const PetscInt *)a], v = sortx[3 * *(const PetscInt *)b];
  return u < v ? -1 : u > v ? 1 : 0;
}

static PetscErrorCode MeshMerge(Mesh *m)
{
  PetscInt *order, *id, nv = 0;
  PetscReal *x;
  const PetscInt n = Face3dNodes(m->type);

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc3(m->nv, &order, m->nv, &id, 3 * m->nv, &x));
  for (PetscInt v = 0; v < m->nv; ++v) {
    order[v] = v;
    id[v]    = -1;
  }
  sortx = m->x;
  qsort(order, (size_t)m->nv, sizeof(PetscInt), CompareX);
  for (PetscInt a = 0; a < m->nv; ++a) {
    const PetscInt u = order[a];
    if (id[u] >= 0) continue;
    id[u] = nv;
    for (PetscInt d = 0; d < 3; ++d) x[3 * nv + d] = m->x[3 * u + d];
    for (PetscInt b = a + 1; b < m->nv && m->x[3 * order[b]] - m->x[3 * u] < 1e-10; ++b) {
      const PetscInt w = order[b];
      if (id[w] < 0 && PetscAbsReal(m->x[3 * w + 1] - m->x[3 * u + 1]) < 1e-10 && PetscAbsReal(m->x[3 * w + 2] - m->x[3 * u + 2]) < 1e-10) id[w] = nv;
    }
    ++nv;
  }
  for (PetscInt k = 0; k < n * m->nf; ++k) m->conn[k] = id[m->conn[k]];
  PetscCall(PetscFree(m->x));
  PetscCall(PetscMalloc1(3 * nv, &m->x));
  PetscCall(PetscArraycpy(m->x, x, 3 * nv));
  m->nv = nv;
  PetscCall(PetscFree3(order, id, x));
  PetscFunctionReturn(0);
}

/* Reverses a face's orientation where its normal at the centre does not
   point along sgn times the radius (sphere meshes). */
static void OrientFace(Face3dType t, PetscInt *conn, const PetscReal *x, PetscReal sgn)
{
  static const PetscInt tri[6] = {0, 2, 1, 5, 4, 3}, quad[9] = {0, 3, 2, 1, 7, 6, 5, 4, 8};
  const PetscInt        n = Face3dNodes(t);
  PetscReal             xf[27], c[2], X[3], T[6], nr[3];
  PetscInt              tmp[9];
  c[0] = c[1] = t == FACE3D_TRI6 ? 1.0 / 3.0 : 0.0;
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt d = 0; d < 3; ++d) xf[3 * i + d] = x[3 * conn[i] + d];
  Face3dEval(t, xf, c, X, T, NULL);
  Face3dNormal(T, nr);
  if (sgn * (nr[0] * X[0] + nr[1] * X[1] + nr[2] * X[2]) > 0) return;
  for (PetscInt i = 0; i < n; ++i) tmp[i] = conn[t == FACE3D_TRI6 ? tri[i] : quad[i]];
  for (PetscInt i = 0; i < n; ++i) conn[i] = tmp[i];
}

/* The octahedron's 8 faces divided n x n, Tri6 nodes projected on the
   sphere of radius R, normals outward. */
static PetscErrorCode MeshSphereTri6(PetscInt n, PetscReal R, Mesh *m)
{
  PetscInt nv = 0;

  PetscFunctionBeginUser;
  PetscCall(MeshAlloc(FACE3D_TRI6, 8 * n * n, 48 * n * n, m));
  for (PetscInt o = 0, f = 0; o < 8; ++o) {
    const PetscReal A[3] = {o & 1 ? -1.0 : 1.0, 0, 0}, B[3] = {0, o & 2 ? -1.0 : 1.0, 0}, C[3] = {0, 0, o & 4 ? -1.0 : 1.0};
    for (PetscInt j = 0; j < n; ++j)
      for (PetscInt i = 0; i + j < n; ++i)
        for (PetscInt up = 0; up < 2; ++up) {
          static const PetscReal corner[2][3][2] = {{{0, 0}, {1, 0}, {0, 1}}, {{1, 0}, {1, 1}, {0, 1}}}; /* the triangles below and above the diagonal */
          PetscReal              b[6][2];
          if (up && i + j + 1 >= n) continue;
          for (PetscInt k = 0; k < 3; ++k) {
            b[k][0] = i + corner[up][k][0];
            b[k][1] = j + corner[up][k][1];
          }
          for (PetscInt d = 0; d < 2; ++d) {
            b[3][d] = 0.5 * (b[0][d] + b[1][d]);
            b[4][d] = 0.5 * (b[1][d] + b[2][d]);
            b[5][d] = 0.5 * (b[2][d] + b[0][d]);
          }
          for (PetscInt k = 0; k < 6; ++k) {
            const PetscReal u = b[k][0] / n, v = b[k][1] / n, w = 1.0 - u - v;
            PetscReal       p[3], l;
            for (PetscInt d = 0; d < 3; ++d) p[d] = w * A[d] + u * B[d] + v * C[d];
            l = PetscSqrtReal(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            for (PetscInt d = 0; d < 3; ++d) m->x[3 * nv + d] = R * p[d] / l;
            m->conn[6 * f + k] = nv++;
          }
          OrientFace(FACE3D_TRI6, &m->conn[6 * f], m->x, 1.0);
          ++f;
        }
  }
  PetscCall(MeshMerge(m));
  PetscFunctionReturn(0);
}

/* The cube's 6 faces divided n x n (equiangular), Quad9 nodes projected on
   the sphere of radius R, normals inward (the inner face of a shell). */
static PetscErrorCode MeshSphereQuad9(PetscInt n, PetscReal R, Mesh *m)
{
  PetscInt nv = 0;

  PetscFunctionBeginUser;
  PetscCall(MeshAlloc(FACE3D_QUAD9, 6 * n * n, 54 * n * n, m));
  for (PetscInt c = 0, f = 0; c < 6; ++c)
    for (PetscInt j = 0; j < n; ++j)
      for (PetscInt i = 0; i < n; ++i, ++f) {
        for (PetscInt k = 0; k < 9; ++k) {
          PetscReal xi[2], a, b, p[3], l;
          const PetscInt ax = c / 2;
          Face3dNodeXi(FACE3D_QUAD9, k, xi);
          a          = PetscTanReal(0.25 * PI * (-1.0 + (2.0 * i + 1.0 + xi[0]) / n));
          b          = PetscTanReal(0.25 * PI * (-1.0 + (2.0 * j + 1.0 + xi[1]) / n));
          p[ax]      = c % 2 ? -1.0 : 1.0;
          p[(ax + 1) % 3] = a;
          p[(ax + 2) % 3] = b;
          l          = PetscSqrtReal(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
          for (PetscInt d = 0; d < 3; ++d) m->x[3 * nv + d] = R * p[d] / l;
          m->conn[9 * f + k] = nv++;
        }
        OrientFace(FACE3D_QUAD9, &m->conn[9 * f], m->x, -1.0);
      }
  PetscCall(MeshMerge(m));
  PetscFunctionReturn(0);
}

/* A_j and Q_j at the slave's nodes (arrays of S->nv, zeroed here): every
   slave face against the master faces whose boxes meet its box widened by
   margin (the tree), reference = current configuration. */
static PetscErrorCode Integrate(const Mesh *S, const Mesh *M, PetscReal margin, const Face3dRule *rule, const Face3dRule *frule, PetscReal A[], PetscReal Q[])
{
  const PetscInt ns = Face3dNodes(S->type), nm = Face3dNodes(M->type);
  PetscReal     *boxes, xs[27], Ad[81], *xm;
  Face3d        *mf;
  Bvh            tree;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc3(6 * M->nf, &boxes, 27 * 64, &xm, 64, &mf));
  for (PetscInt f = 0; f < M->nf; ++f) {
    PetscReal xf[27];
    FaceCoords(M, f, xf);
    Face3dBox(M->type, xf, &boxes[6 * f]);
  }
  PetscCall(BvhCreate(M->nf, boxes, &tree));
  for (PetscInt v = 0; v < S->nv; ++v) A[v] = Q[v] = 0.0;
  for (PetscInt f = 0; f < S->nf; ++f) {
    PetscReal       box[6], a[9] = {0}, q[9] = {0};
    const PetscInt *found;
    PetscInt        nfound, np;
    Segment3dPoint *pts;
    Face3d          sf;
    FaceCoords(S, f, xs);
    sf.type = S->type;
    sf.x    = xs;
    Face3dBox(S->type, xs, box);
    for (PetscInt d = 0; d < 3; ++d) {
      box[d] -= margin;
      box[3 + d] += margin;
    }
    PetscCall(BvhQuery(tree, box, &nfound, &found));
    PetscCheck(nfound <= 64, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%" PetscInt_FMT " master faces near slave face %" PetscInt_FMT, nfound, f);
    for (PetscInt k = 0; k < nfound; ++k) {
      FaceCoords(M, found[k], &xm[27 * k]);
      mf[k].type = M->type;
      mf[k].x    = &xm[27 * k];
    }
    (void)nm;
    PetscCall(Face3dDualCoefficients(S->type, xs, frule, Ad));
    PetscCall(Segment3dPoints(&sf, nfound, mf, rule, 0, &np, &pts, 0, NULL, NULL, NULL, NULL));
    PetscCall(Segment3dEvaluate(&sf, xs, Ad, nfound, mf, np, pts, a, q, NULL));
    for (PetscInt i = 0; i < ns; ++i) {
      A[S->conn[ns * f + i]] += a[i];
      Q[S->conn[ns * f + i]] += q[i];
    }
    PetscCall(PetscFree(pts));
  }
  PetscCall(BvhDestroy(&tree));
  PetscCall(PetscFree3(boxes, xm, mf));
  PetscFunctionReturn(0);
}

/* (1) The bases on one face through xf. */
static PetscErrorCode CheckBasis(const char *name, Face3dType t, const PetscReal xf[], const Face3dRule *frule)
{
  const PetscInt n = Face3dNodes(t);
  PetscReal      Ad[81], B[81] = {0}, D[9] = {0}, Aj[9] = {0}, P2[9] = {0}, pu = 0.0, bio = 0.0, area = 0.0, amin = PETSC_MAX_REAL, amax = 0.0, p2c = 0.0;

  PetscFunctionBeginUser;
  PetscCall(Face3dDualCoefficients(t, xf, frule, Ad));
  for (PetscInt s = 0; s < 100; ++s) {
    PetscReal xi[2], N[9], Nt[9], W[9], sn = 0, st = 0, sw = 0;
    xi[0] = Uniform(t == FACE3D_TRI6 ? 0.0 : -1.0, 1.0);
    xi[1] = Uniform(t == FACE3D_TRI6 ? 0.0 : -1.0, 1.0);
    if (t == FACE3D_TRI6 && xi[0] + xi[1] > 1) {
      xi[0] = 1 - xi[0];
      xi[1] = 1 - xi[1];
    }
    Face3dShape(t, xi, N, NULL, NULL);
    Face3dWeightBasis(t, xi, Nt);
    Face3dWeights(t, Ad, xi, W);
    for (PetscInt i = 0; i < n; ++i) {
      sn += N[i];
      st += Nt[i];
      sw += W[i];
    }
    pu = PetscMax(pu, PetscMax(PetscAbsReal(sn - 1), PetscMax(PetscAbsReal(st - 1), PetscAbsReal(sw - 1))));
  }
  for (PetscInt q = 0; q < frule->nq; ++q) {
    PetscReal X[3], T[6], nr[3], N[9], Nt[9], W[9], dS;
    Face3dEval(t, xf, &frule->xi[2 * q], X, T, NULL);
    dS = Face3dNormal(T, nr) * frule->w[q];
    Face3dShape(t, &frule->xi[2 * q], N, NULL, NULL);
    Face3dWeightBasis(t, &frule->xi[2 * q], Nt);
    Face3dWeights(t, Ad, &frule->xi[2 * q], W);
    area += dS;
    for (PetscInt i = 0; i < n; ++i) {
      D[i] += Nt[i] * dS;
      Aj[i] += W[i] * dS;
      P2[i] += N[i] * dS;
      for (PetscInt k = 0; k < n; ++k) B[i * n + k] += W[i] * Nt[k] * dS;
    }
  }
  for (PetscInt i = 0; i < n; ++i) {
    for (PetscInt k = 0; k < n; ++k) bio = PetscMax(bio, PetscAbsReal(B[i * n + k] - (i == k ? D[k] : 0.0)));
    amin = PetscMin(amin, Aj[i] / area);
    amax = PetscMax(amax, Aj[i] / area);
  }
  for (PetscInt i = 0; i < (t == FACE3D_TRI6 ? 3 : 4); ++i) p2c = PetscMax(p2c, PetscAbsReal(P2[i] / area));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "basis_%s partition_of_unity %.3e\n", name, (double)pu));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "basis_%s biorthogonality %.3e\n", name, (double)(bio / MaxAbs(n, D))));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "basis_%s A_min_rel %.15e\n", name, (double)amin));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "basis_%s A_max_rel %.15e\n", name, (double)amax));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "basis_%s P2_corner_rel %.6e\n", name, (double)p2c));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckBases(const Face3dRule *trule, const Face3dRule *qrule)
{
  PetscReal xf[27];

  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < 2; ++t) { /* flat: affine images of the reference faces (a Quad9's a parallelogram) */
    const Face3dType ty = t ? FACE3D_QUAD9 : FACE3D_TRI6;
    for (PetscInt i = 0; i < Face3dNodes(ty); ++i) {
      PetscReal xi[2];
      Face3dNodeXi(ty, i, xi);
      xf[3 * i]     = 0.3 + 1.1 * xi[0] + 0.4 * xi[1];
      xf[3 * i + 1] = -0.2 + 0.2 * xi[0] + 0.9 * xi[1];
      xf[3 * i + 2] = 0.5 + 0.3 * xi[0] - 0.6 * xi[1];
    }
    PetscCall(CheckBasis(t ? "quad9_flat" : "tri6_flat", ty, xf, t ? qrule : trule));
  }
  /* curved: a Tri6 over an octant of the unit sphere, a Quad9 over a cube's face of it (one sixth) */
  for (PetscInt i = 0; i < 6; ++i) {
    PetscReal xi[2], p[3], l;
    Face3dNodeXi(FACE3D_TRI6, i, xi);
    p[0] = 1 - xi[0] - xi[1];
    p[1] = xi[0];
    p[2] = xi[1];
    l    = PetscSqrtReal(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (PetscInt d = 0; d < 3; ++d) xf[3 * i + d] = p[d] / l;
  }
  PetscCall(CheckBasis("tri6_octant", FACE3D_TRI6, xf, trule));
  for (PetscInt i = 0; i < 9; ++i) {
    PetscReal xi[2], p[3], l;
    Face3dNodeXi(FACE3D_QUAD9, i, xi);
    p[0] = 1.0;
    p[1] = xi[0];
    p[2] = xi[1];
    l    = PetscSqrtReal(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (PetscInt d = 0; d < 3; ++d) xf[3 * i + d] = p[d] / l;
  }
  PetscCall(CheckBasis("quad9_cubeface", FACE3D_QUAD9, xf, qrule));
  PetscFunctionReturn(0);
}

/* (2) The flat patch: level, tilted, partial. */
static PetscErrorCode CheckPatch(const char *name, PetscBool quadSlave, PetscBool tilt, PetscReal xend, const Face3dRule *rule, const Face3dRule *frule)
{
  const PetscReal g0 = 0.05, axis[3] = {1.0, -2.0, 0.7}, shift[3] = {0.3, -0.1, 0.2};
  Mesh            S, M;
  PetscReal      *A, *Q, sumA = 0.0, area, gerr = 0.0, qerr = 0.0, amax = 0.0, amin = PETSC_MAX_REAL;
  PetscInt        nneg = 0;

  PetscFunctionBeginUser;
  if (quadSlave) { /* the roles swapped: 5 x 4 Quad9 on [0.1, 0.9]^2 turned over (normal +z) under 72 Tri6 on the unit square (normal -z) */
    const PetscReal xaxis[3] = {1.0, 0.0, 0.0}, up[3] = {0.0, 1.0, 0.0}, over[3] = {0.0, 1.0, g0};
    PetscCall(MeshFlatQuad9(5, 4, 0.1, 0.9, 0.1, 0.9, 0.0, &S));
    PetscCall(MeshFlatTri6(6, &M));
    MeshMove(&S, xaxis, PI, up);
    MeshMove(&M, xaxis, PI, over);
  } else {
    PetscCall(MeshFlatTri6(7, &S));
    PetscCall(MeshFlatQuad9(5, 6, -0.13, xend, -0.11, 1.17, g0, &M));
  }
  if (tilt) {
    MeshMove(&S, axis, 0.7, shift);
    MeshMove(&M, axis, 0.7, shift);
  }
  PetscCall(PetscMalloc2(S.nv, &A, S.nv, &Q));
  PetscCall(Integrate(&S, &M, 2 * g0, rule, frule, A, Q));
  area = quadSlave ? 0.64 : PetscMin(xend, 1.0);
  for (PetscInt v = 0; v < S.nv; ++v) {
    sumA += A[v];
    amax = PetscMax(amax, A[v]);
  }
  for (PetscInt v = 0; v < S.nv; ++v) {
    qerr = PetscMax(qerr, PetscAbsReal(Q[v] - g0 * A[v]) / (g0 * amax));
    if (PetscAbsReal(A[v]) >= 0.05 * amax) gerr = PetscMax(gerr, PetscAbsReal(Q[v] / A[v] - g0) / g0);
    if (A[v] != 0.0) amin = PetscMin(amin, A[v] / amax);
    if (A[v] < 0.0) ++nneg;
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "patch_%s g_rel %.3e\n", name, (double)gerr));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "patch_%s Q_rel %.3e\n", name, (double)qerr));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "patch_%s area_rel %.3e\n", name, (double)(PetscAbsReal(sumA - area) / area)));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "patch_%s A_min_rel %.6e\n", name, (double)amin));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "patch_%s negative_nodes %" PetscInt_FMT "\n", name, nneg));
  PetscCall(PetscFree2(A, Q));
  PetscCall(MeshDestroy(&S));
  PetscCall(MeshDestroy(&M));
  PetscFunctionReturn(0);
}

/* (3) Concentric spheres. */
static PetscErrorCode CheckSphere(const Face3dRule *rule, const Face3dRule *frule)
{
  const PetscReal g0 = 0.01;
  PetscReal       prev = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt n = 2; n <= 16; n *= 2) {
    Mesh      S, M;
    PetscReal *A, *Q, err = 0.0, sumA = 0.0, amin = PETSC_MAX_REAL;
    PetscCall(MeshSphereTri6(n, 1.0, &S));
    PetscCall(MeshSphereQuad9(3 * n / 2, 1.0 + g0, &M));
    PetscCall(PetscMalloc2(S.nv, &A, S.nv, &Q));
    PetscCall(Integrate(&S, &M, 2 * g0, rule, frule, A, Q));
    for (PetscInt v = 0; v < S.nv; ++v) {
      sumA += A[v];
      err  = PetscMax(err, PetscAbsReal(Q[v] / A[v] - g0));
      amin = PetscMin(amin, A[v]);
    }
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "sphere_n%" PetscInt_FMT " g_err_rel %.6e\n", n, (double)(err / g0)));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "sphere_n%" PetscInt_FMT " area_rel %.6e\n", n, (double)(PetscAbsReal(sumA - 4 * PI) / (4 * PI))));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "sphere_n%" PetscInt_FMT " A_min_rel %.6e\n", n, (double)(amin * S.nv / sumA)));
    if (n > 2) PetscCall(PetscPrintf(PETSC_COMM_SELF, "sphere_n%" PetscInt_FMT " g_order %.4f\n", n, (double)(PetscLog2Real(prev / err))));
    prev = err;
    PetscCall(PetscFree2(A, Q));
    PetscCall(MeshDestroy(&S));
    PetscCall(MeshDestroy(&M));
  }
  PetscFunctionReturn(0);
}

/* (4) Derivatives: a curved slave face of type st (on the unit sphere, its
   nodes moved by 0.02) against 4 curved master faces of type mt (a shell of
   radius 1.03 around it, moved alike); points frozen. */
static PetscErrorCode CheckDerivatives(const char *name, Face3dType st, Face3dType mt, const Face3dRule *rule, const Face3dRule *frule)
{
  const PetscInt  ns = Face3dNodes(st), nm = Face3dNodes(mt), nmf = 4, ndof = 3 * (ns + nmf * nm);
  const PetscReal h = 1e-6;
  PetscReal       xs[27], X0[27], xm[4 * 27], Ad[81], a[9], q[9], *dQ, *fd, err = 0.0, deta[2 * 54], etaerr = 0.0, etamax = 0.0, dqmax;
  Face3d          sf = {st, xs}, ref = {st, X0}, mf[4];
  Segment3dPoint *pts, *p0;
  PetscInt        np;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ns; ++i) { /* a patch near (1, 0.1, 0.05) of size 0.3 */
    PetscReal xi[2], p[3], l;
    Face3dNodeXi(st, i, xi);
    if (st == FACE3D_QUAD9) {
      xi[0] = 0.5 * (xi[0] + 1);
      xi[1] = 0.5 * (xi[1] + 1);
    }
    p[0] = 1.0; /* normal +x (outward) */
    p[1] = 0.3 * xi[0];
    p[2] = 0.3 * xi[1];
    l    = PetscSqrtReal(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (PetscInt d = 0; d < 3; ++d) xs[3 * i + d] = p[d] / l + Uniform(-0.005, 0.005);
  }
  for (PetscInt f = 0; f < nmf; ++f) { /* Quad9: 2 x 2 faces over (-0.1, 0.4)^2 of the plane x = 1; Tri6: one over (-0.1, 0.8) */
    PetscInt conn[9];
    for (PetscInt k = 0; k < nm; ++k) {
      PetscReal xi[2], p[3], l;
      Face3dNodeXi(mt, k, xi);
      p[0] = 1.0;
      if (mt == FACE3D_QUAD9) {
        p[1] = -0.1 + 0.25 * ((f % 2) + 0.5 * (xi[0] + 1));
        p[2] = -0.1 + 0.25 * ((f / 2) + 0.5 * (xi[1] + 1));
      } else {
        p[1] = -0.1 + 0.9 * xi[0];
        p[2] = -0.1 + 0.9 * xi[1];
      }
      l = PetscSqrtReal(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      for (PetscInt d = 0; d < 3; ++d) xm[27 * f + 3 * k + d] = 1.03 * p[d] / l + 0.005 * PetscSinReal(37.0 * p[1] + 11.0 * p[2] + 5.0 * d); /* a function of the place: shared nodes move alike */
      conn[k] = k;
    }
    OrientFace(mt, conn, &xm[27 * f], -1.0); /* the shell's inner face: normal inward */
    {
      PetscReal tmp[27];
      for (PetscInt k = 0; k < nm; ++k)
        for (PetscInt d = 0; d < 3; ++d) tmp[3 * k + d] = xm[27 * f + 3 * conn[k] + d];
      PetscCall(PetscArraycpy(&xm[27 * f], tmp, 3 * nm));
    }
    mf[f].type = mt;
    mf[f].x    = &xm[27 * f];
  }
  PetscCall(PetscArraycpy(X0, xs, 3 * ns)); /* the reference configuration: dS and the weights held */
  PetscCall(PetscCalloc2(ns * ndof, &dQ, ns * ndof, &fd));
  PetscCall(Face3dDualCoefficients(st, xs, frule, Ad));
  PetscCall(Segment3dPoints(&sf, mt == FACE3D_TRI6 ? 1 : nmf, mf, rule, 0, &np, &pts, 0, NULL, NULL, NULL, NULL));
  PetscCheck(np > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "no points");
  PetscCall(PetscMalloc1(np, &p0));
  PetscCall(PetscArraycpy(p0, pts, np));
  PetscCall(PetscArrayzero(a, 9));
  PetscCall(PetscArrayzero(q, 9));
  PetscCall(Segment3dEvaluate(&ref, xs, Ad, mt == FACE3D_TRI6 ? 1 : nmf, mf, np, pts, a, q, dQ));
  {
    const PetscInt nmu = mt == FACE3D_TRI6 ? 1 : nmf, nd = 3 * (ns + nmu * nm);
    for (PetscInt c = 0; c < nd; ++c) {
      PetscReal *x = c < 3 * ns ? &xs[c] : &xm[27 * ((c - 3 * ns) / (3 * nm)) + (c - 3 * ns) % (3 * nm)], x0 = *x, qp[9] = {0}, qm[9] = {0}, ap[9] = {0};
      *x = x0 + h;
      PetscCall(PetscArraycpy(pts, p0, np));
      PetscCall(Segment3dEvaluate(&ref, xs, Ad, nmu, mf, np, pts, ap, qp, NULL));
      *x = x0 - h;
      PetscCall(PetscArraycpy(pts, p0, np));
      PetscCall(Segment3dEvaluate(&ref, xs, Ad, nmu, mf, np, pts, ap, qm, NULL));
      *x = x0;
      for (PetscInt j = 0; j < ns; ++j) fd[j * nd + c] = (qp[j] - qm[j]) / (2 * h);
    }
    (void)ndof;
    dqmax = 0.0;
    for (PetscInt k = 0; k < ns * nd; ++k) {
      dqmax = PetscMax(dqmax, PetscAbsReal(dQ[k]));
      err   = PetscMax(err, PetscAbsReal(dQ[k] - fd[k]));
    }
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "deriv_%s dQ_fd_rel %.3e\n", name, (double)(err / dqmax)));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "deriv_%s points %" PetscInt_FMT "\n", name, np));
    /* the closest point's motion at the first point */
    {
      const Face3d *M = &mf[p0[0].m];
      const PetscInt n2 = 3 * (ns + nm);
      {
        PetscReal xp[3];
        Face3dEval(st, xs, p0[0].xi, xp, NULL, NULL);
        pts[0].eta[0] = p0[0].eta[0];
        pts[0].eta[1] = p0[0].eta[1];
        PetscCheck(Face3dClosestPoint(M->type, M->x, xp, pts[0].eta, NULL), PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "closest point");
      }
      {
        Segment3dClosest cp;
        PetscCheck(Segment3dClosestPointAt(&sf, p0[0].xi, M, pts[0].eta, &cp), PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "closest point not a strict minimum");
        Segment3dProjectionDerivative(&cp, ns, nm, deta);
      }
      for (PetscInt c = 0; c < n2; ++c) {
        PetscReal *x = c < 3 * ns ? &xs[c] : (PetscReal *)&M->x[c - 3 * ns], x0 = *x, ep[2], em[2], p[3];
        ep[0] = em[0] = pts[0].eta[0];
        ep[1] = em[1] = pts[0].eta[1];
        *x = x0 + h;
        Face3dEval(st, xs, p0[0].xi, p, NULL, NULL);
        PetscCheck(Face3dClosestPoint(M->type, M->x, p, ep, NULL), PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "closest point");
        *x = x0 - h;
        Face3dEval(st, xs, p0[0].xi, p, NULL, NULL);
        PetscCheck(Face3dClosestPoint(M->type, M->x, p, em, NULL), PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "closest point");
        *x = x0;
        for (PetscInt aa = 0; aa < 2; ++aa) {
          etaerr = PetscMax(etaerr, PetscAbsReal((ep[aa] - em[aa]) / (2 * h) - deta[aa * n2 + c]));
          etamax = PetscMax(etamax, PetscAbsReal(deta[aa * n2 + c]));
        }
      }
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "deriv_%s deta_fd_rel %.3e\n", name, (double)(etaerr / etamax)));
    }
  }
  PetscCall(PetscFree(pts));
  PetscCall(PetscFree(p0));
  PetscCall(PetscFree2(dQ, fd));
  PetscFunctionReturn(0);
}

/* (4b) The whole computation (segments made again) differenced on slave
   face sface of S against the master faces of M near it: a master node
   shared by several faces moves in each (the sum of its copies'
   derivatives). */
static PetscErrorCode CheckDerivativeWhole(const char *name, Mesh *S, Mesh *M, PetscInt sface, PetscReal margin, const Face3dRule *rule, const Face3dRule *frule)
{
  const PetscReal h = 1e-6;
  PetscReal       xs[18], X0[18], xm[27 * 16], Ad[36], a[6], q[6], *dQ, err = 0.0, dqmax = 0.0, box[6];
  Face3d          sf = {FACE3D_TRI6, xs}, ref = {FACE3D_TRI6, X0}, mf[16];
  PetscInt        nmf = 0, np, ndof, fid[16];
  Segment3dPoint *pts;

  PetscFunctionBeginUser;
  FaceCoords(S, sface, xs);
  Face3dBox(FACE3D_TRI6, xs, box);
  for (PetscInt f = 0; f < M->nf && nmf < 16; ++f) {
    PetscReal b[6];
    FaceCoords(M, f, &xm[27 * nmf]);
    Face3dBox(FACE3D_QUAD9, &xm[27 * nmf], b);
    if (b[0] > box[3] + margin || b[3] < box[0] - margin || b[1] > box[4] + margin || b[4] < box[1] - margin || b[2] > box[5] + margin || b[5] < box[2] - margin) continue;
    mf[nmf].type = FACE3D_QUAD9;
    mf[nmf].x    = &xm[27 * nmf];
    fid[nmf++]   = f;
  }
  ndof = 18 + 27 * nmf;
  PetscCall(PetscArraycpy(X0, xs, 18));
  PetscCall(PetscCalloc1(6 * ndof, &dQ));
  PetscCall(Face3dDualCoefficients(FACE3D_TRI6, xs, frule, Ad));
  PetscCall(PetscArrayzero(a, 6));
  PetscCall(PetscArrayzero(q, 6));
  PetscCall(Segment3dPoints(&sf, nmf, mf, rule, 0, &np, &pts, 0, NULL, NULL, NULL, NULL));
  PetscCall(Segment3dEvaluate(&ref, xs, Ad, nmf, mf, np, pts, a, q, dQ));
  PetscCall(PetscFree(pts));
  for (PetscInt v = -6; v < M->nv; ++v) /* the slave's 6 nodes (v < 0), then the masters' */
    for (PetscInt d = 0; d < 3; ++d) {
      PetscReal *x, x0, qp[6] = {0}, qm[6] = {0}, ap[6] = {0}, an[6] = {0};
      PetscBool  used = (PetscBool)(v < 0);
      for (PetscInt f = 0; f < nmf; ++f)
        for (PetscInt k = 0; k < 9; ++k)
          if (M->conn[9 * fid[f] + k] == v) {
            used = PETSC_TRUE;
            for (PetscInt j = 0; j < 6; ++j) an[j] += dQ[j * ndof + 18 + 27 * f + 3 * k + d];
          }
      if (!used) continue;
      if (v < 0)
        for (PetscInt j = 0; j < 6; ++j) an[j] = dQ[j * ndof + 3 * (v + 6) + d];
      x  = v < 0 ? &xs[3 * (v + 6) + d] : &M->x[3 * v + d];
      x0 = *x;
      for (PetscInt s = 0; s < 2; ++s) {
        *x = x0 + (s ? -h : h);
        for (PetscInt f = 0; f < nmf; ++f) FaceCoords(M, fid[f], &xm[27 * f]);
        PetscCall(Segment3dPoints(&sf, nmf, mf, rule, 0, &np, &pts, 0, NULL, NULL, NULL, NULL));
        PetscCall(Segment3dEvaluate(&ref, xs, Ad, nmf, mf, np, pts, ap, s ? qm : qp, NULL));
        PetscCall(PetscFree(pts));
      }
      *x = x0;
      for (PetscInt f = 0; f < nmf; ++f) FaceCoords(M, fid[f], &xm[27 * f]);
      for (PetscInt j = 0; j < 6; ++j) {
        err   = PetscMax(err, PetscAbsReal((qp[j] - qm[j]) / (2 * h) - an[j]));
        dqmax = PetscMax(dqmax, PetscAbsReal(an[j]));
      }
    }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "deriv_whole_%s dQ_fd_rel %.3e\n", name, (double)(err / dqmax)));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "deriv_whole_%s master_faces %" PetscInt_FMT "\n", name, nmf));
  PetscCall(PetscFree(dQ));
  PetscFunctionReturn(0);
}

/* (5) The tree against brute force. */
static PetscErrorCode CheckBvh(void)
{
  const PetscInt n = 5000, nq = 500;
  PetscReal     *boxes;
  PetscInt      *mark, mismatch = 0, total = 0;
  Bvh            tree;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(6 * n, &boxes, n, &mark));
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt d = 0; d < 3; ++d) {
      const PetscReal c = Uniform(0, 1), w = Uniform(0, 0.04);
      boxes[6 * i + d]     = c - w;
      boxes[6 * i + 3 + d] = c + w;
    }
  for (PetscInt i = 0; i < 50; ++i) /* some identical boxes, some flat ones */
    for (PetscInt d = 0; d < 6; ++d) boxes[6 * (n - 1 - i) + d] = boxes[d];
  PetscCall(BvhCreate(n, boxes, &tree));
  for (PetscInt k = 0; k < nq; ++k) {
    PetscReal       b[6];
    PetscInt        nf, brute = 0;
    const PetscInt *found;
    for (PetscInt d = 0; d < 3; ++d) {
      const PetscReal c = Uniform(-0.1, 1.1), w = Uniform(0, 0.1);
      b[d]     = c - w;
      b[3 + d] = c + w;
    }
    if (k == 0)
      for (PetscInt d = 0; d < 6; ++d) b[d] = boxes[d];
    PetscCall(BvhQuery(tree, b, &nf, &found));
    for (PetscInt i = 0; i < n; ++i) mark[i] = 0;
    for (PetscInt i = 0; i < nf; ++i) mark[found[i]]++;
    for (PetscInt i = 0; i < n; ++i) {
      PetscBool meet = PETSC_TRUE;
      for (PetscInt d = 0; d < 3; ++d)
        if (boxes[6 * i + 3 + d] < b[d] || b[3 + d] < boxes[6 * i + d]) meet = PETSC_FALSE;
      brute += meet;
      if (mark[i] != (meet ? 1 : 0)) ++mismatch;
    }
    total += brute;
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "bvh mismatches %" PetscInt_FMT "\n", mismatch));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "bvh answers %" PetscInt_FMT "\n", total));
  PetscCall(BvhDestroy(&tree));
  PetscCall(PetscFree2(boxes, mark));
  PetscFunctionReturn(0);
}

/* (2') Face3dBox holds the curved face: random points of bulging faces. */
static PetscErrorCode CheckBox(void)
{
  PetscReal out = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < 2; ++t) {
    const Face3dType ty = t ? FACE3D_QUAD9 : FACE3D_TRI6;
    for (PetscInt s = 0; s < 50; ++s) {
      PetscReal xf[27], box[6];
      for (PetscInt k = 0; k < 3 * Face3dNodes(ty); ++k) xf[k] = Uniform(-1, 1);
      Face3dBox(ty, xf, box);
      for (PetscInt r = 0; r < 200; ++r) {
        PetscReal xi[2], X[3];
        xi[0] = Uniform(ty == FACE3D_TRI6 ? 0.0 : -1.0, 1.0);
        xi[1] = Uniform(ty == FACE3D_TRI6 ? 0.0 : -1.0, 1.0);
        if (ty == FACE3D_TRI6 && xi[0] + xi[1] > 1) {
          xi[0] = 1 - xi[0];
          xi[1] = 1 - xi[1];
        }
        Face3dEval(ty, xf, xi, X, NULL, NULL);
        for (PetscInt d = 0; d < 3; ++d) out = PetscMax(out, PetscMax(box[d] - X[d], X[d] - box[3 + d]));
      }
    }
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "bvh box_outside %.3e\n", (double)out));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  Face3dRule rule, trule, qrule;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(Face3dRuleCreate(FACE3D_TRI6, 6, &rule)); /* the clipped pieces' rule: degree 6 */
  PetscCall(Face3dRuleCreate(FACE3D_TRI6, 10, &trule)); /* the faces' own rules (dual coefficients) */
  PetscCall(Face3dRuleCreate(FACE3D_QUAD9, 10, &qrule));
  PetscCall(CheckBases(&trule, &qrule));
  PetscCall(CheckPatch("level", PETSC_FALSE, PETSC_FALSE, 1.1, &rule, &trule));
  PetscCall(CheckPatch("tilted", PETSC_FALSE, PETSC_TRUE, 1.1, &rule, &trule));
  PetscCall(CheckPatch("partial", PETSC_FALSE, PETSC_TRUE, 0.63, &rule, &trule));
  PetscCall(CheckPatch("quad9slave", PETSC_TRUE, PETSC_TRUE, 0.0, &rule, &qrule));
  PetscCall(CheckSphere(&rule, &trule));
  PetscCall(CheckDerivatives("tri6_quad9", FACE3D_TRI6, FACE3D_QUAD9, &rule, &trule));
  PetscCall(CheckDerivatives("quad9_tri6", FACE3D_QUAD9, FACE3D_TRI6, &rule, &qrule));
  {
    const PetscReal axis[3] = {1.0, -2.0, 0.7}, shift[3] = {0.3, -0.1, 0.2};
    Mesh            S, M;
    PetscCall(MeshFlatTri6(3, &S));
    PetscCall(MeshFlatQuad9(4, 4, -0.13, 1.1, -0.11, 1.17, 0.05, &M));
    MeshMove(&S, axis, 0.7, shift);
    MeshMove(&M, axis, 0.7, shift);
    PetscCall(CheckDerivativeWhole("tilted", &S, &M, 7, 0.1, &rule, &trule));
    PetscCall(MeshDestroy(&S));
    PetscCall(MeshDestroy(&M));
    PetscCall(MeshSphereTri6(4, 1.0, &S));
    PetscCall(MeshSphereQuad9(6, 1.01, &M));
    PetscCall(CheckDerivativeWhole("sphere", &S, &M, 5, 0.02, &rule, &trule));
    PetscCall(MeshDestroy(&S));
    PetscCall(MeshDestroy(&M));
  }
  PetscCall(CheckBvh());
  PetscCall(CheckBox());
  PetscCall(Face3dRuleDestroy(&rule));
  PetscCall(Face3dRuleDestroy(&trule));
  PetscCall(Face3dRuleDestroy(&qrule));
  PetscCall(PetscFinalize());
  return 0;
}
