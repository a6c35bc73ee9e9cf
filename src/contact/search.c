/* Closest-point search over a master surface.

   Master edges are hashed into square cells by the bounding box of their
   Bezier control polygon (grown by the blend's largest excursion), inflated
   by the cell size; the (cell, edge) keys are sorted (n_m log n_m) and each
   slave point finds its candidates by binary search (log n_m). The grid is
   rebuilt at every evaluation from the current coordinates. A point looks in
   its cell, then in rings of cells around it until it finds edges (up to a
   tenth of the master surface's extent), so deeply penetrated iterates keep a
   gap and the energy stays continuous. */
#include "search.h"
#include "edge.h"

struct _n_ContactSearch {
  const ContactSurface *S;
  PetscInt   nkeys, *keys, *kedge, nx, ny;
  PetscReal  lo[2], cell, reach;
  PetscReal (*bb)[4];      /* [ne] bounding box of each edge: xmin, ymin, xmax, ymax */
  PetscInt  *stamp, query; /* [ne] last query that projected on the edge */
};

PetscErrorCode ContactSearchCreate(const ContactSurface *S, ContactSearch *search)
{
  ContactSearch M;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&M));
  M->S = S;
  PetscCall(PetscCalloc2(S->ne, &M->bb, S->ne, &M->stamp));
  *search = M;
  PetscFunctionReturn(0);
}

PetscErrorCode ContactSearchDestroy(ContactSearch *search)
{
  ContactSearch M = *search;

  PetscFunctionBeginUser;
  if (!M) PetscFunctionReturn(0);
  PetscCall(PetscFree2(M->keys, M->kedge));
  PetscCall(PetscFree2(M->bb, M->stamp));
  PetscCall(PetscFree(M));
  *search = NULL;
  PetscFunctionReturn(0);
}

PetscErrorCode ContactSearchBuild(ContactSearch M)
{
  const ContactSurface *S = M->S;
  PetscReal hi[2], ext = 0.0;
  PetscReal (*bb)[4];
  PetscInt  n = 0;

  PetscFunctionBeginUser;
  bb       = M->bb;
  M->lo[0] = M->lo[1] = PETSC_MAX_REAL;
  hi[0] = hi[1] = -PETSC_MAX_REAL;
  for (PetscInt e = 0; e < S->ne; ++e) {
    const PetscInt *en = &S->enodes[3 * e], *mn = &S->mnodes[7 * e];
    for (PetscInt d = 0; d < 2; ++d) {
      const PetscReal a = S->x[2 * en[0] + d], b = S->x[2 * en[1] + d], c = 2.0 * S->x[2 * en[2] + d] - 0.5 * (a + b);
      PetscReal       ca = 0.0, cb = 0.0, grow;
      for (PetscInt j = 0; j < 7; ++j) {
        ca += S->mcorr[14 * e + j] * S->x[2 * mn[j] + d];
        cb += S->mcorr[14 * e + 7 + j] * S->x[2 * mn[j] + d];
      }
      grow         = 4.0 * S->blend / 27.0 * (PetscAbsReal(ca) + PetscAbsReal(cb)); /* max |psi| = 4 W / 27 */
      bb[e][d]     = PetscMin(a, PetscMin(b, c)) - grow;
      bb[e][2 + d] = PetscMax(a, PetscMax(b, c)) + grow;
      ext          = PetscMax(ext, bb[e][2 + d] - bb[e][d]);
      M->lo[d]     = PetscMin(M->lo[d], bb[e][d]);
      hi[d]        = PetscMax(hi[d], bb[e][2 + d]);
    }
  }
  /* cells no smaller than the largest edge, and at most 4096 per direction */
  M->cell = PetscMax(ext, PetscMax(hi[0] - M->lo[0], hi[1] - M->lo[1]) / 4096.0);
  if (M->cell <= 0) M->cell = 1.0;
  /* how far from the surface a slave point is still matched: a tenth of the
     surface's extent, enough for any penetration a solver iterate makes */
  M->reach = PetscMax(M->cell, 0.1 * PetscMax(hi[0] - M->lo[0], hi[1] - M->lo[1]));
  M->lo[0] -= M->cell;
  M->lo[1] -= M->cell;
  M->nx = (PetscInt)((hi[0] - M->lo[0]) / M->cell) + 2;
  M->ny = (PetscInt)((hi[1] - M->lo[1]) / M->cell) + 2;
  for (PetscInt pass = 0; pass < 2; ++pass) {
    n = 0;
    for (PetscInt e = 0; e < S->ne; ++e) {
      const PetscInt i0 = (PetscInt)((bb[e][0] - M->cell - M->lo[0]) / M->cell), i1 = (PetscInt)((bb[e][2] + M->cell - M->lo[0]) / M->cell);
      const PetscInt j0 = (PetscInt)((bb[e][1] - M->cell - M->lo[1]) / M->cell), j1 = (PetscInt)((bb[e][3] + M->cell - M->lo[1]) / M->cell);
      for (PetscInt i = PetscMax(i0, 0); i <= PetscMin(i1, M->nx - 1); ++i)
        for (PetscInt j = PetscMax(j0, 0); j <= PetscMin(j1, M->ny - 1); ++j) {
          if (pass) {
            M->keys[n]  = i * M->ny + j;
            M->kedge[n] = e;
          }
          n++;
        }
    }
    if (!pass) {
      if (n > M->nkeys) {
        PetscCall(PetscFree2(M->keys, M->kedge));
        PetscCall(PetscMalloc2(n, &M->keys, n, &M->kedge));
      }
      M->nkeys = n;
    }
  }
  M->nkeys = n;
  PetscCall(PetscSortIntWithArray(n, M->keys, M->kedge));
  PetscFunctionReturn(0);
}

/* Candidates of one cell: the closest one updates (best, edge, eta). An edge is
   projected once per query, and not at all when its bounding box is already
   farther than the best distance found. */
static void SearchCell(ContactSearch M, PetscInt i, PetscInt j, const PetscReal p[2], PetscReal *best, PetscInt *edge, PetscReal *eta)
{
  PetscInt key, lo = 0, hi = M->nkeys;

  if (i < 0 || j < 0 || i >= M->nx || j >= M->ny) return;
  key = i * M->ny + j;
  while (lo < hi) {
    const PetscInt mid = (lo + hi) / 2;
    if (M->keys[mid] < key) lo = mid + 1;
    else hi = mid;
  }
  for (PetscInt k = lo; k < M->nkeys && M->keys[k] == key; ++k) {
    const PetscInt   ke = M->kedge[k];
    const PetscReal *b  = M->bb[ke];
    const PetscReal  dx = PetscMax(0.0, PetscMax(b[0] - p[0], p[0] - b[2])), dy = PetscMax(0.0, PetscMax(b[1] - p[1], p[1] - b[3]));
    PetscReal        e, d2;
    if (M->stamp[ke] == M->query || dx * dx + dy * dy > *best) continue;
    M->stamp[ke] = M->query;
    MasterProject(M->S, ke, p, &e, &d2);
    if (d2 < *best) {
      *best = d2;
      *edge = M->kedge[k];
      *eta  = e;
    }
  }
}

/* Closest master edge to p: the candidates of p's cell, then of rings of cells
   around it until some are found (plus one more ring, which may hold a closer
   edge), up to M->reach; *edge = -1 if none. Deeply penetrated points thus keep
   a gap, and the energy stays continuous. */
void ContactSearchFindClosest(ContactSearch M, const PetscReal p[2], PetscInt *edge, PetscReal *eta)
{
  const PetscInt i = (PetscInt)PetscFloorReal((p[0] - M->lo[0]) / M->cell), j = (PetscInt)PetscFloorReal((p[1] - M->lo[1]) / M->cell);
  const PetscInt rmax = (PetscInt)(M->reach / M->cell) + 1;
  PetscReal      best = PETSC_MAX_REAL;
  PetscInt       found = -1;

  *edge = -1;
  M->query++;
  if (i < -rmax || j < -rmax || i >= M->nx + rmax || j >= M->ny + rmax) return;
  for (PetscInt r = 0; r <= rmax && (found < 0 || r <= found + 1); ++r) {
    for (PetscInt a = -r; a <= r; ++a) {
      SearchCell(M, i + a, j - r, p, &best, edge, eta);
      if (r) SearchCell(M, i + a, j + r, p, &best, edge, eta);
    }
    for (PetscInt b = -r + 1; b <= r - 1; ++b) {
      SearchCell(M, i - r, j + b, p, &best, edge, eta);
      SearchCell(M, i + r, j + b, p, &best, edge, eta);
    }
    if (found < 0 && *edge >= 0) found = r;
  }
}
