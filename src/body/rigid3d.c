/* A rigid 3D body (rigidbody.h): its surfaces read from the Gmsh file, its
   motion by a translation and a rotation vector, and the motion's exact
   first and second derivatives, which map the contact's gradient and
   Hessian at its surface nodes to its six unknowns.

   The body. Its mesh is 3D when it has a Physical Volume (Rigid3dIs): the
   body keeps the second-order faces of its physical surfaces (MSH 2.2
   types 9, Tri6, and 10, Quad9; one type a body), and the volume's
   elements only for a point inside it: each face is turned so that its
   corners' right hand points away from the centroid of the volume's
   nodes (the faces' outward normal where the body is star-shaped about that
   point, as a punch, a ball or a plate is). Rank 0 reads the file and
   broadcasts the faces, as 2D's curves (rigidbody.c).

   The motion. A point X of the body is at

       x(q) = c + t + R(theta) v,   v = X - c,

   c the reference point, t the translation and R(theta) = exp([theta]x)
   the rotation by |theta| about the axis theta / |theta| (Rodrigues):
   exact for finite rotations. With a = |theta|,

       R v = A v + B (theta x v) + C (theta . v) theta,
       A = cos a,  B = sin a / a,  C = (1 - cos a) / a^2.

   Derivatives. For a function F(a), dF/dtheta_j = F1 theta_j and
   d2F/dtheta_j dtheta_k = F1 delta_jk + F2 theta_j theta_k, F1 = F'/a,
   F2 = F1'/a. With w = theta x v, s = theta . v, ds/dtheta_j = v_j,
   dw/dtheta_j = e_j x v:

       d(Rv)/dtheta_j = A1 theta_j v + B1 theta_j w + B e_j x v
                        + C1 theta_j s theta + C v_j theta + C s e_j,

       d2(Rv)/dtheta_j dtheta_k = (A1 d_jk + A2 th_j th_k) v
         + (B1 d_jk + B2 th_j th_k) w + B1 (th_j e_k x v + th_k e_j x v)
         + (C1 d_jk + C2 th_j th_k) s theta
         + C1 (th_j v_k + th_k v_j) theta + C1 s (th_j e_k + th_k e_j)
         + C (v_j e_k + v_k e_j),

   d_jk Kronecker's delta. At theta = 0 these are e_j x v and
   -d_jk v + (v_j e_k + v_k e_j) / 2, the second derivatives of
   v + theta x v + theta x (theta x v) / 2. The scalar functions, each a
   series in a^2 (F = sum c_n a^2n: F1 = sum 2n c_n a^(2n-2),
   F2 = sum 2n (2n-2) c_n a^(2n-4); c_n = (-1)^n / (2n)!, / (2n+1)!,
   / (2n+2)! for A, B, C), by their series below a = 1 (14 terms: below
   1e-20 of the first) and their closed forms above, where the
   cancellation in C2 = (a^2 cos a - 5 a sin a + 8 - 8 cos a) / a^6 costs
   no more than round-off times 1e3.

   The unknowns q = (t, L theta), L the surfaces' size, so that each is a
   length (as 2D's arc L theta). The contact energy Pi_c(x(q)) has the
   gradient J^T g (g the gradient at the surface nodes): the force
   F = sum g and dPi/dtheta_j = sum g . d(Rv)/dtheta_j; its Hessian is
   J^T H_c J + sum g . d2x/dq2, the second part in the rotation's block
   alone (t enters linearly): curl3 = sum g . d2(Rv)/dtheta_j dtheta_k,
   gathered with the gradient (Rigid3dAddForce) as 2D's curl. The moment
   reported is M = sum (x - c - t) x g about c + t; dPi/dtheta = T^T M with
   T = d(omega)/d(theta) invertible for |theta| < 2 pi, so M = 0 where the
   rotation's gradient is.

   A moment control (-<body>_rigid_moment, rigidbody.c) adds the potential
   -M_a . theta on the free components: at equilibrium T^T M = M_a there,
   so the moment the contact balances is T^-T M_a, M_a itself only where
   T^T M_a = M_a (theta along M_a: a rotation about a fixed axis along the
   moment); to first order T = I + [theta]x / 2 and T^-T M_a = M_a +
   theta x M_a / 2. No exact potential gives a fixed spatial moment on a
   finite rotation vector (its work depends on the path). */
#include "rigidbody.h"
#include "mshcheck.h"
#include "meshgen.h"
#include "stagedvalues.h"
#include "bodyimpl.h"

/* F[k] = {F, F1, F2} for k = A, B, C at a = |theta|. */
static void Rigid3dScalars(PetscReal a, PetscReal F[3][3])
{
  if (a < 1.0) {
    PetscReal pw[14];
    pw[0] = 1.0;
    for (PetscInt n = 1; n < 14; ++n) pw[n] = pw[n - 1] * a * a;
    for (PetscInt k = 0; k < 3; ++k) {
      PetscReal fact = 1.0; /* (2n + k)! */
      for (PetscInt j = 1; j <= k; ++j) fact *= (PetscReal)j;
      F[k][0] = F[k][1] = F[k][2] = 0.0;
      for (PetscInt n = 0; n < 14; ++n) {
        const PetscReal c = (n % 2 ? -1.0 : 1.0) / fact;
        F[k][0] += c * pw[n];
        if (n >= 1) F[k][1] += 2.0 * n * c * pw[n - 1];
        if (n >= 2) F[k][2] += 2.0 * n * (2.0 * n - 2.0) * c * pw[n - 2];
        fact *= (PetscReal)(2 * n + k + 1) * (PetscReal)(2 * n + k + 2);
      }
    }
    return;
  }
  {
    const PetscReal c = PetscCosReal(a), sn = PetscSinReal(a), a2 = a * a, a3 = a2 * a;
    F[0][0] = c;
    F[0][1] = -sn / a;
    F[0][2] = (sn - a * c) / a3;
    F[1][0] = sn / a;
    F[1][1] = (a * c - sn) / a3;
    F[1][2] = (3.0 * sn - 3.0 * a * c - a2 * sn) / (a3 * a2);
    F[2][0] = (1.0 - c) / a2;
    F[2][1] = (a * sn - 2.0 + 2.0 * c) / (a2 * a2);
    F[2][2] = (a2 * c - 5.0 * a * sn + 8.0 - 8.0 * c) / (a3 * a3);
  }
}

static inline void Cross3(const PetscReal a[3], const PetscReal b[3], PetscReal c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/* f = R(th) v, and where asked df[j][3] = d f/d th_j, d2f[j][k][3]. */
static void Rigid3dRotate(const PetscReal th[3], const PetscReal v[3], PetscReal f[3], PetscReal df[3][3], PetscReal d2f[3][3][3])
{
  const PetscReal a = PetscSqrtReal(th[0] * th[0] + th[1] * th[1] + th[2] * th[2]), s = th[0] * v[0] + th[1] * v[1] + th[2] * v[2];
  PetscReal       F[3][3], w[3], ev[3][3];

  Rigid3dScalars(a, F);
  Cross3(th, v, w);
  for (PetscInt i = 0; i < 3; ++i) f[i] = F[0][0] * v[i] + F[1][0] * w[i] + F[2][0] * s * th[i];
  if (!df) return;
  for (PetscInt j = 0; j < 3; ++j) {
    const PetscReal e[3] = {j == 0 ? 1.0 : 0.0, j == 1 ? 1.0 : 0.0, j == 2 ? 1.0 : 0.0};
    Cross3(e, v, ev[j]);
  }
  for (PetscInt j = 0; j < 3; ++j)
    for (PetscInt i = 0; i < 3; ++i) df[j][i] = F[0][1] * th[j] * v[i] + F[1][1] * th[j] * w[i] + F[1][0] * ev[j][i] + F[2][1] * th[j] * s * th[i] + F[2][0] * v[j] * th[i] + (i == j ? F[2][0] * s : 0.0);
  if (!d2f) return;
  for (PetscInt j = 0; j < 3; ++j)
    for (PetscInt k = 0; k < 3; ++k) {
      const PetscReal djk = j == k ? 1.0 : 0.0, tt = th[j] * th[k];
      for (PetscInt i = 0; i < 3; ++i) {
        const PetscReal eki = i == k ? 1.0 : 0.0, eji = i == j ? 1.0 : 0.0;
        d2f[j][k][i] = (F[0][1] * djk + F[0][2] * tt) * v[i] + (F[1][1] * djk + F[1][2] * tt) * w[i] + F[1][1] * (th[j] * ev[k][i] + th[k] * ev[j][i]) + (F[2][1] * djk + F[2][2] * tt) * s * th[i] + F[2][1] * (th[j] * v[k] + th[k] * v[j]) * th[i] +
                       F[2][1] * s * (th[j] * eki + th[k] * eji) + F[2][0] * (v[j] * eki + v[k] * eji);
      }
    }
}

void Rigid3dDisplacement(const BodyRigid *r, const PetscReal X[3], PetscReal u[3])
{
  const PetscReal v[3] = {X[0] - r->centre[0], X[1] - r->centre[1], X[2] - r->centre[2]};
  PetscReal       f[3];

  Rigid3dRotate(r->rot, v, f, NULL, NULL);
  for (PetscInt d = 0; d < 3; ++d) u[d] = r->t[d] + f[d] - v[d];
}

void Rigid3dAddForce(BodyRigid *r, PetscInt n, const PetscReal X[], const PetscReal g[])
{
  for (PetscInt i = 0; i < n; ++i) {
    const PetscReal *gi = &g[3 * i], v[3] = {X[3 * i] - r->centre[0], X[3 * i + 1] - r->centre[1], X[3 * i + 2] - r->centre[2]};
    PetscReal        f[3], df[3][3], d2f[3][3][3], m[3];

    if (gi[0] == 0.0 && gi[1] == 0.0 && gi[2] == 0.0) continue;
    Rigid3dRotate(r->rot, v, f, df, d2f);
    Cross3(f, gi, m);
    for (PetscInt d = 0; d < 3; ++d) {
      r->force[d] += gi[d];
      r->mom[d] += m[d];
    }
    for (PetscInt j = 0; j < 3; ++j) {
      r->grot[j] += df[j][0] * gi[0] + df[j][1] * gi[1] + df[j][2] * gi[2];
      for (PetscInt k = 0; k < 3; ++k) r->curl3[3 * j + k] += d2f[j][k][0] * gi[0] + d2f[j][k][1] * gi[1] + d2f[j][k][2] * gi[2];
    }
  }
}

/* The rows J[q][d] = dx_d/dq of a surface node at x: its reference offset
   v = R^T (x - c - t), R^T = R(-theta). */
static void Rigid3dJacobian(const BodyRigid *r, const PetscReal x[3], PetscReal J[6][3])
{
  const PetscReal y[3] = {x[0] - r->centre[0] - r->t[0], x[1] - r->centre[1] - r->t[1], x[2] - r->centre[2] - r->t[2]}, mth[3] = {-r->rot[0], -r->rot[1], -r->rot[2]};
  PetscReal       v[3], f[3], df[3][3];

  Rigid3dRotate(mth, y, v, NULL, NULL);
  Rigid3dRotate(r->rot, v, f, df, NULL);
  for (PetscInt q = 0; q < 3; ++q)
    for (PetscInt d = 0; d < 3; ++d) {
      J[q][d]     = q == d ? 1.0 : 0.0;
      J[3 + q][d] = df[q][d] / r->L;
    }
}

/* As BodyRigidAddHessian in 2D: K's coupling of the body's surface
   components (indices below -1, ContactRigidDofDecode3) to the joined
   dofs into the border's columns B[q], among themselves J^T K J into D. */
PetscErrorCode Rigid3dAddHessian(Body b, const PetscReal x[], PetscInt n, const PetscInt idx[], const PetscScalar K[])
{
  BodyRigid *r = b->rg;
  PetscInt  *pos, nr = 0;
  PetscReal *Jr;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(n + 1, &pos, 6 * n + 1, &Jr));
  for (PetscInt a = 0; a < n; ++a) {
    PetscInt  j, d;
    PetscReal J[6][3];
    if (!ContactRigidDofDecode3(idx[a], &j, &d)) continue;
    Rigid3dJacobian(r, &x[3 * j], J);
    for (PetscInt q = 0; q < 6; ++q) Jr[6 * nr + q] = J[q][d];
    pos[nr++] = a;
  }
  for (PetscInt q = 0; q < 6 && nr; ++q) {
    if (!r->unknown[q] || !r->B[q]) continue;
    for (PetscInt e = 0; e < n; ++e) { /* K symmetric: row e's coupling to the body's dofs */
      PetscScalar v = 0;
      if (idx[e] < 0) continue;
      for (PetscInt k = 0; k < nr; ++k) v += K[e * n + pos[k]] * Jr[6 * k + q];
      if (v != 0.0) PetscCall(VecSetValue(r->B[q], idx[e], v, ADD_VALUES));
    }
    for (PetscInt q2 = 0; q2 < 6; ++q2) {
      PetscReal s = 0.0;
      if (!r->unknown[q2]) continue;
      for (PetscInt k = 0; k < nr; ++k) {
        PetscReal row = 0.0;
        for (PetscInt l = 0; l < nr; ++l) row += PetscRealPart(K[pos[k] * n + pos[l]]) * Jr[6 * l + q2];
        s += Jr[6 * k + q] * row;
      }
      r->D[6 * q + q2] += s;
    }
  }
  PetscCall(PetscFree2(pos, Jr));
  PetscFunctionReturn(0);
}

/* Rank 0: whether the file's physical groups have a volume. */
PetscErrorCode Rigid3dIs(Body b, PetscBool *is3)
{
  PetscMPIInt rank;
  int         found = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(b->comm, &rank));
  if (!rank) {
    FILE *fp = fopen(b->msh, "r");
    char  line[4096];
    while (fp && fgets(line, sizeof(line), fp)) {
      long n = 0;
      if (!strncmp(line, "$Nodes", 6)) break;
      if (strncmp(line, "$PhysicalNames", 14)) continue;
      if (!fgets(line, sizeof(line), fp) || sscanf(line, "%ld", &n) != 1) break;
      for (long i = 0; i < n && fgets(line, sizeof(line), fp); ++i) {
        int dim;
        if (sscanf(line, "%d", &dim) == 1 && dim == 3) found = 1;
      }
      break;
    }
    if (fp) fclose(fp);
  }
  PetscCallMPI(MPI_Bcast(&found, 1, MPI_INT, 0, b->comm));
  *is3 = found ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* -rigid_rotation in 3D: free (all three), or three entries a stage
   (stage-major), each a number (radians) or free; a component free in one
   stage is free in all. -rigid_centre: three numbers. */
PetscErrorCode Rigid3dParseRotation(Body b, BodyRigid *r)
{
  const char *prefix = r->prefix;
  char        rot[64 * CONTACT_MAX_STAGES], *tok, *save = NULL;
  PetscReal   v[3 * CONTACT_MAX_STAGES];
  PetscBool   all, isfree[3 * CONTACT_MAX_STAGES];
  PetscInt    nv = 0, S = b->nstages;

  PetscFunctionBeginUser;
  PetscCheck(!r->setCentre || r->ncentre == 3, b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_centre: body %s is 3D: give three numbers x,y,z", prefix, b->name);
  PetscCall(PetscStrcmp(r->rotOpt, "free", &all));
  if (all) {
    r->unknown[3] = r->unknown[4] = r->unknown[5] = PETSC_TRUE;
    PetscFunctionReturn(0);
  }
  if (!r->setRot) PetscFunctionReturn(0); /* held at 0 */
  PetscCall(PetscStrncpy(rot, r->rotOpt, sizeof(rot)));
  for (tok = strtok_r(rot, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
    char *end;
    PetscCheck(nv < 3 * S, b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_rotation: body %s is 3D: give a rotation vector ax,ay,az (radians: the axis and the angle) per stage, %" PetscInt_FMT " values for -load_stages %" PetscInt_FMT ", or free; got more", prefix, b->name, 3 * S, S);
    PetscCall(PetscStrcmp(tok, "free", &isfree[nv]));
    v[nv] = isfree[nv] ? 0.0 : strtod(tok, &end);
    PetscCheck(isfree[nv] || (end != tok && !*end), b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_rotation: each component must be a number (radians) or free, got '%s'", prefix, tok);
    PetscCheck(!PetscIsInfOrNanReal(v[nv]), b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_rotation: must be finite, got %g", prefix, (double)v[nv]);
    nv++;
  }
  PetscCheck(nv == 3 * S, b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_rotation: body %s is 3D: give a rotation vector ax,ay,az (radians: the axis and the angle) per stage, %" PetscInt_FMT " values for -load_stages %" PetscInt_FMT ", or free; got %" PetscInt_FMT, prefix, b->name, 3 * S, S, nv);
  for (PetscInt c = 0; c < 3; ++c) {
    r->unknown[3 + c] = isfree[c];
    for (PetscInt s = 0; s < S; ++s) {
      PetscCheck(isfree[3 * s + c] == isfree[c], b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_rotation: component %" PetscInt_FMT " is free in one stage and not in another; a free component is free in every stage", prefix, c);
      r->rotEnd[s][c] = v[3 * s + c];
    }
  }
  PetscFunctionReturn(0);
}

typedef struct {
  PetscInt   nnodes, *ids, *perm, nf, nbf, *fn, *ftag;
  PetscReal *X, inside[3];
} Rigid3dFile;

/* Rank 0: the nodes, the faces of types 9 and 10, and the volume's node centroid. */
static PetscErrorCode Rigid3dReadFile(Body b, Rigid3dFile *F)
{
  FILE     *fp;
  char      line[4096];
  PetscInt  nel = 0, cap = 0;
  PetscReal nvol = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(F, sizeof(*F)));
  fp = fopen(b->msh, "r");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "body %s: cannot open mesh %s", b->name, b->msh);
  while (fgets(line, sizeof(line), fp)) {
    if (!strncmp(line, "$Nodes", 6)) {
      PetscCheck(fgets(line, sizeof(line), fp) && sscanf(line, "%" PetscInt_FMT, &F->nnodes) == 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: bad $Nodes", b->name, b->msh);
      PetscCall(PetscMalloc3(F->nnodes, &F->ids, F->nnodes, &F->perm, 3 * F->nnodes, &F->X));
      for (PetscInt i = 0; i < F->nnodes; ++i) {
        double x, y, z;
        PetscCheck(fgets(line, sizeof(line), fp) && sscanf(line, "%" PetscInt_FMT " %lf %lf %lf", &F->ids[i], &x, &y, &z) == 4, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: bad node line", b->name, b->msh);
        F->X[3 * i]     = x;
        F->X[3 * i + 1] = y;
        F->X[3 * i + 2] = z;
        F->perm[i]      = i;
      }
      PetscCall(PetscSortIntWithArray(F->nnodes, F->ids, F->perm));
    } else if (!strncmp(line, "$Elements", 9)) {
      PetscCheck(F->ids && fgets(line, sizeof(line), fp) && sscanf(line, "%" PetscInt_FMT, &nel) == 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: bad $Elements", b->name, b->msh);
      for (PetscInt i = 0; i < nel; ++i) {
        long  v[48];
        int   nv = 0, nb;
        char *s  = line, *end;
        PetscCheck(fgets(line, sizeof(line), fp), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: short $Elements", b->name, b->msh);
        for (long x = strtol(s, &end, 10); end != s && nv < 48; x = strtol(s, &end, 10)) {
          v[nv++] = x;
          s       = end;
        }
        if (nv < 3) continue;
        if (v[1] == 11 || v[1] == 12 || v[1] == 4 || v[1] == 5) { /* a volume element: its corners for the inside point */
          const int nc = v[1] == 11 || v[1] == 4 ? 4 : 8;
          for (int k = 0; k < nc && 3 + v[2] + k < nv; ++k) {
            PetscInt loc;
            PetscCall(PetscFindInt((PetscInt)v[3 + v[2] + k], F->nnodes, F->ids, &loc));
            if (loc < 0) continue;
            for (PetscInt d = 0; d < 3; ++d) F->inside[d] += F->X[3 * F->perm[loc] + d];
            nvol += 1;
          }
          continue;
        }
        if (v[1] != 9 && v[1] != 10) continue;
        nb = v[1] == 9 ? 6 : 9;
        PetscCheck(nv == 3 + v[2] + nb && v[2] >= 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: bad face element %ld", b->name, b->msh, v[0]);
        PetscCheck(!F->nbf || F->nbf == nb, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s mixes Tri6 and Quad9 faces; a rigid 3D body's surfaces are of one type", b->name, b->msh);
        F->nbf = nb;
        if (F->nf == cap) {
          cap = 2 * cap + 64;
          PetscCall(PetscRealloc(sizeof(PetscInt) * cap * 9, &F->fn));
          PetscCall(PetscRealloc(sizeof(PetscInt) * cap, &F->ftag));
        }
        F->ftag[F->nf] = (PetscInt)v[3];
        for (PetscInt j = 0; j < nb; ++j) F->fn[nb * F->nf + j] = (PetscInt)v[3 + v[2] + j];
        F->nf++;
      }
    }
  }
  fclose(fp);
  PetscCheck(F->nf > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s has no second-order faces: a rigid 3D body is given by its physical surfaces (Mesh.ElementOrder = 2)", b->name, b->msh);
  PetscCheck(nvol > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s has a Physical Volume but no volume elements", b->name, b->msh);
  for (PetscInt d = 0; d < 3; ++d) F->inside[d] /= nvol;
  PetscFunctionReturn(0);
}

/* Rank 0: the faces' nodes as sorted indices, each face turned outward
   (away from the inside point, as bodyfaces.c turns an elastic body's). */
static PetscErrorCode Rigid3dKeepFaces(Body b, BodyRigid *r, Rigid3dFile *F)
{
  const PetscInt nb = F->nbf, nc = nb == 6 ? 3 : 4;
  PetscInt       n = nb * F->nf, *used;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n, &used));
  PetscCall(PetscArraycpy(used, F->fn, n));
  PetscCall(PetscSortRemoveDupsInt(&n, used));
  r->nn = n;
  PetscCall(PetscMalloc2(n, &r->ids, 3 * n, &r->X));
  for (PetscInt i = 0; i < n; ++i) {
    PetscInt loc;
    PetscCall(PetscFindInt(used[i], F->nnodes, F->ids, &loc));
    PetscCheck(loc >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: a face's node %" PetscInt_FMT " is not among its nodes", b->name, b->msh, used[i]);
    r->ids[i] = used[i];
    for (PetscInt d = 0; d < 3; ++d) r->X[3 * i + d] = F->X[3 * F->perm[loc] + d];
  }
  r->nf  = F->nf;
  r->nbf = nb;
  PetscCall(PetscMalloc2(nb * F->nf, &r->fnodes, F->nf, &r->ftag));
  for (PetscInt f = 0; f < F->nf; ++f) {
    PetscInt *P = &r->fnodes[nb * f];
    PetscReal a[3], c[3], nrm[3], xf[3] = {0, 0, 0};
    r->ftag[f] = F->ftag[f];
    for (PetscInt j = 0; j < nb; ++j) PetscCall(PetscFindInt(F->fn[nb * f + j], n, r->ids, &P[j]));
    for (PetscInt d = 0; d < 3; ++d) {
      const PetscReal *x0 = &r->X[3 * P[0]], *x1 = &r->X[3 * P[1]], *x2 = &r->X[3 * P[2]];
      a[d] = nc == 3 ? x1[d] - x0[d] : x2[d] - x0[d];
      c[d] = nc == 3 ? x2[d] - x0[d] : r->X[3 * P[3] + d] - x1[d];
      for (PetscInt j = 0; j < nc; ++j) xf[d] += r->X[3 * P[j] + d] / nc;
    }
    Cross3(a, c, nrm);
    if (nrm[0] * (xf[0] - F->inside[0]) + nrm[1] * (xf[1] - F->inside[1]) + nrm[2] * (xf[2] - F->inside[2]) < 0) { /* v0, v_{n-1}, ..., v1 and the edges alike */
      PetscInt vr[4], er[4];
      for (PetscInt j = 0; j < nc; ++j) {
        vr[j] = P[(nc - j) % nc];
        er[j] = P[nc + nc - 1 - j];
      }
      for (PetscInt j = 0; j < nc; ++j) {
        P[j]      = vr[j];
        P[nc + j] = er[j];
      }
    }
  }
  PetscCall(PetscFree(used));
  PetscFunctionReturn(0);
}

/* The centroid of the surfaces, weighted by area: each face split into flat
   triangles on its nodes (a Tri6 in 4, a Quad9 in 8), exact for flat faces. */
static void Rigid3dSurfaceCentroid(BodyRigid *r)
{
  static const PetscInt tri6[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}}, quad9[8][3] = {{0, 4, 8}, {0, 8, 7}, {4, 1, 5}, {4, 5, 8}, {8, 5, 2}, {8, 2, 6}, {7, 8, 6}, {7, 6, 3}};
  PetscReal             area = 0.0, c[3] = {0, 0, 0};

  for (PetscInt f = 0; f < r->nf; ++f) {
    const PetscInt *P = &r->fnodes[r->nbf * f], nt = r->nbf == 6 ? 4 : 8;
    for (PetscInt k = 0; k < nt; ++k) {
      const PetscInt  *t  = r->nbf == 6 ? tri6[k] : quad9[k];
      const PetscReal *x0 = &r->X[3 * P[t[0]]], *x1 = &r->X[3 * P[t[1]]], *x2 = &r->X[3 * P[t[2]]];
      const PetscReal  a[3] = {x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]}, e[3] = {x2[0] - x0[0], x2[1] - x0[1], x2[2] - x0[2]};
      PetscReal        n[3], A;
      Cross3(a, e, n);
      A = 0.5 * PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      area += A;
      for (PetscInt d = 0; d < 3; ++d) c[d] += A * (x0[d] + x1[d] + x2[d]) / 3.0;
    }
  }
  for (PetscInt d = 0; d < 3; ++d) r->centre[d] = c[d] / area;
}

PetscErrorCode Rigid3dSetUpSurfaces(Body b, BodyRigid *r)
{
  PetscMPIInt rank;
  PetscInt    n[3];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(b->comm, &rank));
  PetscCall(MeshCheckFile(b->comm, b->name, b->msh));
  PetscCall(MeshReadPhysicalNames(b->comm, b->msh, &b->nphys, &b->physNames, &b->physDims, &b->physTags));
  if (!rank) {
    Rigid3dFile F;
    PetscCall(Rigid3dReadFile(b, &F));
    PetscCall(Rigid3dKeepFaces(b, r, &F));
    PetscCall(PetscFree3(F.ids, F.perm, F.X));
    PetscCall(PetscFree(F.fn));
    PetscCall(PetscFree(F.ftag));
  }
  n[0] = r->nn;
  n[1] = r->nf;
  n[2] = r->nbf;
  PetscCallMPI(MPI_Bcast(n, 3, MPIU_INT, 0, b->comm));
  if (rank) {
    r->nn  = n[0];
    r->nf  = n[1];
    r->nbf = n[2];
    PetscCall(PetscMalloc2(r->nn, &r->ids, 3 * r->nn, &r->X));
    PetscCall(PetscMalloc2(r->nbf * r->nf, &r->fnodes, r->nf, &r->ftag));
  }
  PetscCallMPI(MPI_Bcast(r->ids, (PetscMPIInt)r->nn, MPIU_INT, 0, b->comm));
  PetscCallMPI(MPI_Bcast(r->X, (PetscMPIInt)(3 * r->nn), MPIU_REAL, 0, b->comm));
  PetscCallMPI(MPI_Bcast(r->fnodes, (PetscMPIInt)(r->nbf * r->nf), MPIU_INT, 0, b->comm));
  PetscCallMPI(MPI_Bcast(r->ftag, (PetscMPIInt)r->nf, MPIU_INT, 0, b->comm));
  if (r->centre[0] == PETSC_MAX_REAL) Rigid3dSurfaceCentroid(r);
  {
    PetscReal lo[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[3] = {PETSC_MIN_REAL, PETSC_MIN_REAL, PETSC_MIN_REAL};
    for (PetscInt i = 0; i < r->nn; ++i)
      for (PetscInt d = 0; d < 3; ++d) {
        lo[d] = PetscMin(lo[d], r->X[3 * i + d]);
        hi[d] = PetscMax(hi[d], r->X[3 * i + d]);
      }
    r->L = PetscSqrtReal(PetscSqr(hi[0] - lo[0]) + PetscSqr(hi[1] - lo[1]) + PetscSqr(hi[2] - lo[2]));
  }
  PetscFunctionReturn(0);
}

/* A physical surface's faces as a 3D contact surface takes them
   (bodyfaces.h): given by rank 0 alone, so that the ranks' faces together
   are the group's, each once. */
PetscErrorCode Rigid3dGroupFaces(Body b, const char group[], PetscInt *tag, BodyFaces *F)
{
  const BodyRigid *r  = b->rg;
  const PetscInt   nb = r->nbf;
  PetscMPIInt      rank;
  PetscInt         k  = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(F, sizeof(*F)));
  PetscCallMPI(MPI_Comm_rank(b->comm, &rank));
  PetscCall(BodyGetPhysicalTag(b, group, 2, tag));
  PetscCall(PetscMalloc5(nb * r->nf + 1, &F->point, nb * r->nf + 1, &F->id, nb * r->nf + 1, &F->off, 3 * nb * r->nf + 1, &F->joined, 3 * nb * r->nf + 1, &F->X));
  for (PetscInt f = 0; f < r->nf && !rank; ++f) {
    if (r->ftag[f] != *tag) continue;
    for (PetscInt j = 0; j < nb; ++j) {
      const PetscInt i = r->fnodes[nb * f + j];
      F->point[nb * k + j] = -1;
      F->off[nb * k + j]   = -1;
      F->id[nb * k + j]    = r->ids[i];
      for (PetscInt d = 0; d < 3; ++d) {
        F->joined[3 * (nb * k + j) + d] = -1;
        F->X[3 * (nb * k + j) + d]      = r->X[3 * i + d];
      }
    }
    k++;
  }
  F->n  = k;
  F->nb = nb;
  PetscFunctionReturn(0);
}

PetscErrorCode Rigid3dViewSolution(Body b)
{
  const BodyRigid *r = b->rg;
  const PetscReal  a = PetscSqrtReal(PetscSqr(r->rot[0]) + PetscSqr(r->rot[1]) + PetscSqr(r->rot[2]));

  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(b->comm, "  rigid body %s: moved (%g, %g, %g), turned by the rotation vector (%g, %g, %g) (%g degrees) about (%g, %g, %g); the contact's force on it (%.6e, %.6e, %.6e), moment (%.6e, %.6e, %.6e)\n", b->name, (double)r->t[0], (double)r->t[1], (double)r->t[2], (double)r->rot[0], (double)r->rot[1], (double)r->rot[2], (double)(a * 180.0 / PETSC_PI),
                        (double)r->centre[0], (double)r->centre[1], (double)r->centre[2], (double)-r->force[0], (double)-r->force[1], (double)-r->force[2], (double)-r->mom[0], (double)-r->mom[1], (double)-r->mom[2]));
  PetscFunctionReturn(0);
}
