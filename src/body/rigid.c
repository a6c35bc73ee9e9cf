/* A body's rigid motions r(x) = (t_x - w y, t_y + w x): the three modes
   (translations in x and y, the rotation w) as vectors, and the algebra that
   counts how many of them its Dirichlet conditions leave free. A
   constrained component c at node x removes the row e_c . dr/d(t_x, t_y, w);
   the constraint Gram matrix M, the sum of the rows' outer products (3 x 3,
   coordinates centred and scaled for conditioning), has the free motions
   as its null space, so 3 - rank M of them are free. anchors.c adds rows to
   it until none is. A 3D body has six, r(x) = t + w x x (three
   translations, three rotations), counted alike from a 6 x 6 Gram matrix
   (BodyCountFreeRigidModes). */
#include "rigid.h"
#include "bodyimpl.h"

/* The rank of the n x n symmetric matrix M (Gaussian elimination with full
   pivoting, pivots below 1e-10 of its trace taken as zero). */
static PetscInt RigidRankN(PetscInt n, const PetscReal M[])
{
  PetscReal A[36], tol = 0;
  PetscInt  rank = 0;
  PetscBool used[6] = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE};

  for (PetscInt k = 0; k < n * n; ++k) A[k] = M[k];
  for (PetscInt k = 0; k < n; ++k) tol += M[k * n + k];
  tol *= 1e-10;
  for (PetscInt step = 0; step < n; ++step) {
    PetscInt  pr = -1, pc = -1;
    PetscReal best = tol;
    for (PetscInt a = 0; a < n; ++a)
      for (PetscInt e = 0; e < n; ++e)
        if (!used[a] && PetscAbsReal(A[n * a + e]) > best) {
          best = PetscAbsReal(A[n * a + e]);
          pr   = a;
          pc   = e;
        }
    if (pr < 0) break;
    used[pr] = PETSC_TRUE;
    ++rank;
    for (PetscInt a = 0; a < n; ++a) {
      PetscReal f;
      if (used[a]) continue;
      f = A[n * a + pc] / A[n * pr + pc];
      for (PetscInt e = 0; e < n; ++e) A[n * a + e] -= f * A[n * pr + e];
    }
  }
  return rank;
}

/* A 3D body's constrained component c at x (centred, scaled) removes the row
   e_c . d(t + w x x)/d(t, w) of its six rigid motions. */
static void RigidGramAddRow3D(PetscReal M[36], PetscInt c, const PetscReal x[3])
{
  PetscReal r[6] = {0, 0, 0, 0, 0, 0};

  r[c] = 1.0;
  if (c == 0) { r[4] = x[2]; r[5] = -x[1]; }
  if (c == 1) { r[3] = -x[2]; r[5] = x[0]; }
  if (c == 2) { r[3] = x[1]; r[4] = -x[0]; }
  for (PetscInt a = 0; a < 6; ++a)
    for (PetscInt e = 0; e < 6; ++e) M[6 * a + e] += r[a] * r[e];
}

PetscErrorCode BodyAddRigidModes(Body b, PetscInt rstart, PetscInt rend, PetscScalar *modes[])
{
  PetscSection s;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(b->dm, &s));
  if (b->dim == 3) {
    for (PetscInt p = b->pStart; p < b->pEnd; ++p) {
      PetscInt         dof, off;
      const PetscReal *x = &b->xpoint[3 * (p - b->pStart)];

      PetscCall(PetscSectionGetDof(s, p, &dof));
      PetscCall(PetscSectionGetOffset(s, p, &off));
      for (PetscInt d = 0; d < PetscMin(dof, 3); ++d) {
        const PetscInt g = b->l2b[off + d];
        if (g < rstart || g >= rend) continue;
        modes[d][g - rstart] += 1.0;
        /* (e_k x x)_d for k = 0, 1, 2 */
        modes[3][g - rstart] += d == 1 ? -x[2] : d == 2 ? x[1] : 0.0;
        modes[4][g - rstart] += d == 0 ? x[2] : d == 2 ? -x[0] : 0.0;
        modes[5][g - rstart] += d == 0 ? -x[1] : d == 1 ? x[0] : 0.0;
      }
    }
    PetscFunctionReturn(0);
  }
  for (PetscInt p = b->pStart; p < b->pEnd; ++p) {
    PetscInt        dof, off;
    const PetscReal x = b->xpoint[2 * (p - b->pStart)], y = b->xpoint[2 * (p - b->pStart) + 1];

    PetscCall(PetscSectionGetDof(s, p, &dof));
    PetscCall(PetscSectionGetOffset(s, p, &off));
    for (PetscInt d = 0; d < PetscMin(dof, 2); ++d) {
      const PetscInt g = b->l2b[off + d];
      if (g < rstart || g >= rend) continue;
      if (b->axisym && d == 0) continue; /* in r-z the translation along the axis alone */
      modes[d][g - rstart] += 1.0;
      if (!b->axisym) modes[2][g - rstart] += d == 0 ? -y : x;
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGetOwnedNodeRows(Body b, PetscInt rstart, PetscInt rend, PetscInt *n, PetscInt idx[])
{
  const PetscInt dim = b->dim;
  PetscSection   s;

  PetscFunctionBeginUser;
  *n = 0;
  if (b->rigid) PetscFunctionReturn(0);
  PetscCall(DMGetLocalSection(b->dm, &s));
  for (PetscInt p = b->pStart; p < b->pEnd; ++p) {
    PetscInt dof, off;

    PetscCall(PetscSectionGetDof(s, p, &dof));
    PetscCall(PetscSectionGetOffset(s, p, &off));
    for (PetscInt k = off; k + dim <= off + dof; k += dim) { /* a point's nodes, dim components each */
      PetscBool owned = PETSC_FALSE;
      for (PetscInt d = 0; d < dim; ++d) owned = (PetscBool)(owned || (b->l2b[k + d] >= rstart && b->l2b[k + d] < rend));
      if (!owned) continue;
      if (idx)
        for (PetscInt d = 0; d < dim; ++d) idx[*n * dim + d] = b->l2b[k + d] >= 0 ? b->l2b[k + d] : -1;
      ++*n;
    }
  }
  PetscFunctionReturn(0);
}

/* Number of rigid motions (x and y translation, rotation; a 3D body's six)
   that the Dirichlet conditions leave free. A constrained component c at
   node x removes the part of the rigid motion in that component, a row of
   the motion's derivative in its parameters (BodyRigidGramAddRow,
   RigidGramAddRow3D); the free motions are the null space of the sum of the
   rows' outer products (coordinates centred and scaled for conditioning). */
PetscErrorCode BodyCountFreeRigidModes(Body b, PetscInt *nfree)
{
  const PetscInt dim = b->dim, nm = dim == 3 ? 6 : 3;
  PetscReal      lo[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[3] = {PETSC_MIN_REAL, PETSC_MIN_REAL, PETSC_MIN_REAL}, glo[3], ghi[3], c[3], L = 0;
  PetscReal      M[36] = {0}, Mg[36];
  PetscSection   s;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(b->dm, &s));
  for (PetscInt p = 0; p < b->pEnd - b->pStart; ++p) {
    PetscInt dof;
    PetscCall(PetscSectionGetDof(s, p + b->pStart, &dof));
    if (!dof) continue;
    for (PetscInt d = 0; d < dim; ++d) {
      lo[d] = PetscMin(lo[d], b->xpoint[dim * p + d]);
      hi[d] = PetscMax(hi[d], b->xpoint[dim * p + d]);
    }
  }
  PetscCall(MPIU_Allreduce(lo, glo, dim, MPIU_REAL, MPIU_MIN, b->comm));
  PetscCall(MPIU_Allreduce(hi, ghi, dim, MPIU_REAL, MPIU_MAX, b->comm));
  for (PetscInt d = 0; d < dim; ++d) {
    c[d] = 0.5 * (glo[d] + ghi[d]);
    L    = PetscMax(L, ghi[d] - glo[d]);
  }
  if (!(L > 0)) L = 1.0;
  for (PetscInt i = 0; i < b->nbc; ++i) {
    BodyBC         *bc = &b->bc[i];
    IS              is;
    const PetscInt *pts;
    PetscInt        n;

    PetscCall(DMLabelGetStratumIS(bc->label, 1, &is));
    if (!is) continue;
    PetscCall(ISGetLocalSize(is, &n));
    PetscCall(ISGetIndices(is, &pts));
    for (PetscInt j = 0; j < n; ++j) {
      PetscInt  dof, q = pts[j] - b->pStart;
      PetscReal x[3] = {0, 0, 0};
      PetscCall(PetscSectionGetDof(s, pts[j], &dof));
      if (!dof) continue;
      for (PetscInt d = 0; d < dim; ++d) x[d] = (b->xpoint[dim * q + d] - c[d]) / L;
      for (PetscInt k = 0; k < bc->ncomp; ++k) {
        if (dim == 3) RigidGramAddRow3D(M, bc->comps[k], x);
        else BodyRigidGramAddRow(M, bc->comps[k], x[0], x[1]);
      }
    }
    PetscCall(ISRestoreIndices(is, &pts));
    PetscCall(ISDestroy(&is));
  }
  PetscCall(MPIU_Allreduce(M, Mg, nm * nm, MPIU_REAL, MPIU_SUM, b->comm));
  if (dim == 2) BodyRigidGramAxisymmetric(b, Mg);
  *nfree = nm - RigidRankN(nm, Mg);
  PetscFunctionReturn(0);
}

/* In r-z a body's only rigid motion is the translation along the axis: a
   radial translation or a rotation strains the hoop. Those two are held, as
   if by a constraint row each. */
void BodyRigidGramAxisymmetric(Body b, PetscReal M[9])
{
  if (!b->axisym) return;
  M[0] += 1.0;
  M[8] += 1.0;
}

void BodyRigidGramAddRow(PetscReal M[9], PetscInt c, PetscReal x, PetscReal y)
{
  const PetscReal r[3] = {c == 0 ? 1.0 : 0.0, c == 1 ? 1.0 : 0.0, c == 0 ? -y : x};

  for (PetscInt a = 0; a < 3; ++a)
    for (PetscInt e = 0; e < 3; ++e) M[3 * a + e] += r[a] * r[e];
}

PetscInt BodyRigidRank(const PetscReal M[9])
{
  return RigidRankN(3, M);
}

PetscInt BodyGetNumRigidModes(Body b)
{
  if (b->rigid) return 0;
  return b->dim == 3 ? 6 : 3;
}

PetscErrorCode BodyCheckHeld(Body b, PetscBool contact)
{
  PetscFunctionBeginUser;
  if (b->ops.checkheld) PetscCall(b->ops.checkheld(b, contact));
  PetscFunctionReturn(0);
}

/* An elastic body whose conditions leave a rigid motion free: frictionless
   contact pushes it but does not hold it. */
PetscErrorCode BodyCheckHeld_Elastic(Body b, PetscBool contact)
{
  PetscInt nfree;

  PetscFunctionBeginUser;
  PetscCall(BodyCountFreeRigidModes(b, &nfree));
  if (!nfree) PetscFunctionReturn(0);
  SETERRQ(b->comm, PETSC_ERR_USER_INPUT, "body %s: %s leave %" PetscInt_FMT " rigid motion(s) free%s, so the problem is singular; constrain it with -%s_bc", b->name, b->nbc ? "its Dirichlet conditions" : "no Dirichlet conditions", nfree,
          contact ? " (frictionless contact pushes but does not hold it; a load pressing it on, -<body>_load, would)" : " and it is in no contact pair", b->name);
}
