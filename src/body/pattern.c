/* The elastic stiffness's nonzero pattern, counted exactly for its
   preallocation (problem.c, subdomain.c). A node's rows couple to every dof
   of every cell around it; counting, as a bound, dim nb columns per cell
   around the node counts a column once per cell that shares it: a Hex27
   vertex, in 8 cells, 8 x 81 = 648 against its 375 distinct columns, a
   Tet10 vertex in about 24 cells some 720 against about 200. MatAssembly
   squeezes the excess out of the rows but keeps the arrays it was given, so
   that K holds the bound's memory to the end, and on several ranks so does
   each subdomain's copy. Here the cells around each node are listed (a
   node-to-cell table, CSR), their mapped columns gathered, sorted and
   deduplicated: the exact count, at a sort of at most 8 x 81 entries a
   node. */
#include "pattern.h"
#include "bodyimpl.h"

PetscErrorCode BodyNodeColumns(Body b, const PetscInt map[], PatternNodeFn fn, void *ctx)
{
  const PetscInt nk = b->ncells * b->nb;
  PetscInt       nl, *start, *cells, *buf, maxn = 0;

  PetscFunctionBeginUser;
  if (nk == 0) PetscFunctionReturn(0);
  PetscCall(VecGetLocalSize(b->Xl, &nl));
  PetscCall(PetscCalloc1(nl + 2, &start));
  for (PetscInt k = 0; k < nk; ++k) start[b->cdof[k] + 2]++;
  for (PetscInt i = 0; i < nl; ++i) {
    maxn = PetscMax(maxn, start[i + 2]);
    start[i + 2] += start[i + 1];
  }
  PetscCall(PetscMalloc2(nk, &cells, maxn * b->nb * b->dim + 1, &buf));
  for (PetscInt k = 0; k < nk; ++k) cells[start[b->cdof[k] + 1]++] = k / b->nb; /* start[i + 1]: the end of node i's list */
  for (PetscInt i = 0; i < nl; ++i) {
    PetscInt n = 0;
    if (start[i + 1] == start[i]) continue; /* not a node's first component */
    for (PetscInt j = start[i]; j < start[i + 1]; ++j)
      for (PetscInt a = 0; a < b->nb; ++a)
        for (PetscInt d = 0; d < b->dim; ++d) {
          const PetscInt col = map[b->cdof[cells[j] * b->nb + a] + d];
          if (col >= 0) buf[n++] = col;
        }
    PetscCall(PetscSortRemoveDupsInt(&n, buf));
    PetscCall(fn(ctx, i, n, buf));
  }
  PetscCall(PetscFree2(cells, buf));
  PetscCall(PetscFree(start));
  PetscFunctionReturn(0);
}
