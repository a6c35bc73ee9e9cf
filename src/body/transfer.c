/* A body's displacement carried from one of its meshes to another (the
   same body meshed anew): -accuracy's first iterate of each step from the
   last step's answer, and any later transfer of a state between meshes.

   Every rank gets every cell of the old mesh (its vertices and its nodal
   displacements) and locates each new node it owns in them through a
   bucket grid: the old cell whose straight-sided shape through its
   vertices (affine triangle, bilinear quadrilateral) holds the node, its
   reference coordinates found there; a node outside every cell (on a
   curved boundary, between the two meshes' polygons) takes the cell it
   lies least far outside of, at its closest point. The old P2/Q2
   displacement is evaluated there, by the element's basis at those
   reference coordinates. */
#include "transfer.h"
#include "gather.h"
#include "bodyimpl.h"

/* The old mesh's cells on every rank: a record of R = 8 + 2 nb reals per
   cell (4 vertices, the last repeated in a triangle, then the nb nodal
   displacements of U, from's local vector); the vertices' reference
   coordinates Rc[nv] and their number nv. */
static PetscErrorCode GatherCells(Body from, Vec U, PetscInt *ncell, PetscReal **all, PetscReal Rc[4][2], PetscInt *nv)
{
  const PetscInt     nb = from->nb, R = 8 + 2 * nb;
  PetscReal          ref[2 * 64], *rec;
  PetscInt           corner[4];
  const PetscScalar *ua;

  PetscFunctionBeginUser;
  PetscCall(BodyGetCellCorners(from, ref, corner, nv));
  for (PetscInt k = 0; k < *nv; ++k)
    for (PetscInt d = 0; d < 2; ++d) Rc[k][d] = ref[2 * corner[k] + d];
  PetscCall(VecGetArrayRead(U, &ua));
  PetscCall(PetscMalloc1(R * from->ncells + 1, &rec));
  for (PetscInt c = 0; c < from->ncells; ++c) {
    PetscReal *r = &rec[R * c];
    for (PetscInt k = 0; k < 4; ++k) {
      const PetscInt a = corner[PetscMin(k, *nv - 1)];
      r[2 * k]         = from->xnode[2 * (nb * c + a)];
      r[2 * k + 1]     = from->xnode[2 * (nb * c + a) + 1];
    }
    for (PetscInt a = 0; a < nb; ++a) {
      r[8 + 2 * a]     = PetscRealPart(ua[from->cdof[nb * c + a]]);
      r[8 + 2 * a + 1] = PetscRealPart(ua[from->cdof[nb * c + a] + 1]);
    }
  }
  PetscCall(VecRestoreArrayRead(U, &ua));
  PetscCall(ContactGatherReals(from->comm, PETSC_TRUE, R * from->ncells, rec, ncell, all));
  *ncell /= R;
  PetscCall(PetscFree(rec));
  PetscFunctionReturn(0);
}

/* A bucket grid over the old cells' boxes, buckets bw wide (about two
   cells) from lo: bucket (bx, by) holds the cells bcell[bstart[k] ..
   bstart[k + 1]), k = bx nby + by. */
typedef struct {
  PetscReal lo[2], bw;
  PetscInt  nbx, nby, *bstart, *bfill, *bcell;
} CellBuckets;

/* The smallest box holding the first nv vertices of record r. */
static void CellBox(PetscInt nv, const PetscReal r[], PetscReal cl[2], PetscReal ch[2])
{
  cl[0] = cl[1] = PETSC_MAX_REAL;
  ch[0] = ch[1] = PETSC_MIN_REAL;
  for (PetscInt k = 0; k < nv; ++k)
    for (PetscInt d = 0; d < 2; ++d) {
      cl[d] = PetscMin(cl[d], r[2 * k + d]);
      ch[d] = PetscMax(ch[d], r[2 * k + d]);
    }
}

static PetscErrorCode CellBucketsCreate(PetscInt ncell, PetscInt R, PetscInt nv, const PetscReal all[], CellBuckets *g)
{
  PetscReal hi[2] = {PETSC_MIN_REAL, PETSC_MIN_REAL}, hsum = 0;

  PetscFunctionBeginUser;
  g->lo[0] = g->lo[1] = PETSC_MAX_REAL;
  for (PetscInt c = 0; c < ncell; ++c)
    for (PetscInt k = 0; k < nv; ++k)
      for (PetscInt d = 0; d < 2; ++d) {
        g->lo[d] = PetscMin(g->lo[d], all[R * c + 2 * k + d]);
        hi[d]    = PetscMax(hi[d], all[R * c + 2 * k + d]);
      }
  for (PetscInt c = 0; c < ncell; ++c) hsum += PetscAbsReal(all[R * c] - all[R * c + 2]) + PetscAbsReal(all[R * c + 1] - all[R * c + 3]);
  g->bw  = PetscMax(2.0 * hsum / PetscMax(ncell, 1), 1e-12);
  g->nbx = PetscMin(2048, (PetscInt)((hi[0] - g->lo[0]) / g->bw) + 1);
  g->nby = PetscMin(2048, (PetscInt)((hi[1] - g->lo[1]) / g->bw) + 1);
  PetscCall(PetscCalloc2(g->nbx * g->nby + 1, &g->bstart, g->nbx * g->nby + 1, &g->bfill));
  for (PetscInt pass = 0; pass < 2; ++pass) { /* count, then fill */
    if (pass) {
      for (PetscInt k = 0; k < g->nbx * g->nby; ++k) g->bstart[k + 1] += g->bstart[k];
      PetscCall(PetscMalloc1(g->bstart[g->nbx * g->nby] + 1, &g->bcell));
    }
    for (PetscInt c = 0; c < ncell; ++c) {
      PetscReal cl[2], ch[2];
      CellBox(nv, &all[R * c], cl, ch);
      for (PetscInt bx = (PetscInt)((cl[0] - g->lo[0]) / g->bw); bx <= PetscMin(g->nbx - 1, (PetscInt)((ch[0] - g->lo[0]) / g->bw)); ++bx)
        for (PetscInt by = (PetscInt)((cl[1] - g->lo[1]) / g->bw); by <= PetscMin(g->nby - 1, (PetscInt)((ch[1] - g->lo[1]) / g->bw)); ++by) {
          const PetscInt k = bx * g->nby + by;
          if (!pass) g->bstart[k + 1]++;
          else g->bcell[g->bstart[k] + g->bfill[k]++] = c;
        }
    }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode CellBucketsDestroy(CellBuckets *g)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(g->bstart, g->bfill));
  PetscCall(PetscFree(g->bcell));
  PetscFunctionReturn(0);
}

/* Reference coordinates in an old cell of the point X, from the cell's
   straight-sided shape through its vertices v (affine triangle, bilinear
   quadrilateral); returns how far outside the cell the point lies (0 inside),
   the coordinates clamped into the cell. */
static PetscReal CellLocate(PetscBool simplex, const PetscReal v[][2], const PetscReal R[][2], const PetscReal X[2], PetscReal xi[2])
{
  if (simplex) {
    const PetscReal a = v[1][0] - v[0][0], b = v[2][0] - v[0][0], c = v[1][1] - v[0][1], d = v[2][1] - v[0][1], det = a * d - b * c;
    const PetscReal rx = X[0] - v[0][0], ry = X[1] - v[0][1];
    PetscReal       l1 = (d * rx - b * ry) / det, l2 = (-c * rx + a * ry) / det, out, sum;
    out = PetscMax(PetscMax(-l1, -l2), l1 + l2 - 1.0);
    l1  = PetscMax(l1, 0.0);
    l2  = PetscMax(l2, 0.0);
    sum = l1 + l2;
    if (sum > 1.0) {
      l1 /= sum;
      l2 /= sum;
    }
    for (PetscInt k = 0; k < 2; ++k) xi[k] = R[0][k] + l1 * (R[1][k] - R[0][k]) + l2 * (R[2][k] - R[0][k]);
    return PetscMax(out, 0.0);
  } else {
    PetscReal s = 0.0, t = 0.0, out;
    for (PetscInt it = 0; it < 20; ++it) { /* Newton on x(s, t) = X */
      const PetscReal N[4] = {(1 - s) * (1 - t) / 4, (1 + s) * (1 - t) / 4, (1 + s) * (1 + t) / 4, (1 - s) * (1 + t) / 4};
      const PetscReal Ns[4] = {-(1 - t) / 4, (1 - t) / 4, (1 + t) / 4, -(1 + t) / 4}, Nt[4] = {-(1 - s) / 4, -(1 + s) / 4, (1 + s) / 4, (1 - s) / 4};
      PetscReal       r[2] = {-X[0], -X[1]}, J[4] = {0, 0, 0, 0}, det, ds, dt;
      for (PetscInt k = 0; k < 4; ++k) {
        r[0] += N[k] * v[k][0];
        r[1] += N[k] * v[k][1];
        J[0] += Ns[k] * v[k][0];
        J[1] += Nt[k] * v[k][0];
        J[2] += Ns[k] * v[k][1];
        J[3] += Nt[k] * v[k][1];
      }
      det = J[0] * J[3] - J[1] * J[2];
      if (det == 0) break;
      ds = (J[3] * r[0] - J[1] * r[1]) / det;
      dt = (-J[2] * r[0] + J[0] * r[1]) / det;
      s -= ds;
      t -= dt;
      if (PetscAbsReal(ds) + PetscAbsReal(dt) < 1e-13) break;
    }
    out   = PetscMax(PetscAbsReal(s), PetscAbsReal(t)) - 1.0;
    xi[0] = PetscMax(-1.0, PetscMin(1.0, s));
    xi[1] = PetscMax(-1.0, PetscMin(1.0, t));
    return PetscMax(out, 0.0);
  }
}

/* The old cell *cell that holds X, or that X lies least far outside of, and
   X's reference coordinates xi in it: the cells of X's bucket first, every
   cell if none is there. */
static void NodeLocate(const CellBuckets *g, PetscBool simplex, PetscInt ncell, PetscInt R, PetscInt nv, const PetscReal all[], const PetscReal Rc[][2], const PetscReal X[2], PetscInt *cell, PetscReal xi[2])
{
  const PetscInt bx = PetscMax(0, PetscMin(g->nbx - 1, (PetscInt)((X[0] - g->lo[0]) / g->bw)));
  const PetscInt by = PetscMax(0, PetscMin(g->nby - 1, (PetscInt)((X[1] - g->lo[1]) / g->bw)));
  PetscReal      bestOut = PETSC_MAX_REAL, v[4][2];

  *cell = -1;
  xi[0] = xi[1] = 0.0;
  for (PetscInt sweep = 0; sweep < 2 && *cell < 0; ++sweep) { /* the node's bucket, else every cell */
    const PetscInt k0 = sweep ? 0 : g->bstart[bx * g->nby + by], k1 = sweep ? ncell : g->bstart[bx * g->nby + by + 1];
    for (PetscInt k = k0; k < k1 && bestOut > 0; ++k) {
      const PetscInt c = sweep ? k : g->bcell[k];
      PetscReal      x2[2], o;
      for (PetscInt j = 0; j < nv; ++j) {
        v[j][0] = all[R * c + 2 * j];
        v[j][1] = all[R * c + 2 * j + 1];
      }
      o = CellLocate(simplex, (const PetscReal(*)[2])v, Rc, X, x2);
      if (o < bestOut) {
        bestOut = o;
        *cell   = c;
        xi[0]   = x2[0];
        xi[1]   = x2[1];
      }
    }
  }
}

PetscErrorCode BodyTransferDisplacement(Body from, Vec U, Body to, Vec X)
{
  const PetscInt  nb = from->nb, R = 8 + 2 * nb, np = to->pEnd - to->pStart;
  PetscReal      *all = NULL, Rc[4][2], *pref, *pu;
  PetscInt        nv, ncell, npt = 0, *pcell, *idx;
  CellBuckets     g;
  PetscSection    sec;
  PetscTabulation T;

  PetscFunctionBeginUser;
  PetscCall(GatherCells(from, U, &ncell, &all, Rc, &nv));
  PetscCall(CellBucketsCreate(ncell, R, nv, all, &g));
  /* the new nodes this rank owns and solves for */
  PetscCall(DMGetLocalSection(to->dm, &sec));
  PetscCall(PetscMalloc4(2 * np + 1, &pref, np + 1, &pcell, 2 * np + 1, &pu, 2 * np + 1, &idx));
  for (PetscInt p = to->pStart; p < to->pEnd; ++p) {
    PetscInt dof, off;
    PetscCall(PetscSectionGetDof(sec, p, &dof));
    if (dof != 2 || !to->owned[p - to->pStart]) continue;
    PetscCall(PetscSectionGetOffset(sec, p, &off));
    if (to->l2b[off] < 0 && to->l2b[off + 1] < 0) continue;
    NodeLocate(&g, from->simplex, ncell, R, nv, all, (const PetscReal(*)[2])Rc, &to->xpoint[2 * (p - to->pStart)], &pcell[npt], &pref[2 * npt]);
    idx[2 * npt]     = to->l2b[off];
    idx[2 * npt + 1] = to->l2b[off + 1];
    ++npt;
  }
  PetscCall(PetscFECreateTabulation(from->feScalar, 1, npt ? npt : 1, pref, 0, &T));
  for (PetscInt k = 0; k < npt; ++k) {
    const PetscReal *r = &all[R * pcell[k]];
    pu[2 * k] = pu[2 * k + 1] = 0.0;
    for (PetscInt a = 0; a < nb; ++a) {
      pu[2 * k] += T->T[0][k * nb + a] * r[8 + 2 * a];
      pu[2 * k + 1] += T->T[0][k * nb + a] * r[8 + 2 * a + 1];
    }
  }
  PetscCall(PetscTabulationDestroy(&T));
  PetscCall(VecSetOption(X, VEC_IGNORE_NEGATIVE_INDICES, PETSC_TRUE));
  PetscCall(VecSetValues(X, 2 * npt, idx, pu, INSERT_VALUES)); /* negative indices (constrained) are skipped */
  PetscCall(PetscFree4(pref, pcell, pu, idx));
  PetscCall(CellBucketsDestroy(&g));
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}
