/* A bounding-volume tree of axis-aligned boxes: build and query.

   Build, top down: a node holds a range of the items (boxes, lo[3] then
   hi[3]) and the box of their boxes; a range of more than BVH_LEAF items is
   split at the median of the boxes' centres along the longest side of the
   centres' box, found by quickselect (expected linear time), so that the
   tree is balanced whatever the items' order: depth log2(n / BVH_LEAF),
   each level linear, O(n log n) in all, 2 n / BVH_LEAF nodes at most.
   Query: the items whose box meets the given box (closed boxes: touching
   counts), by a walk that descends only into nodes whose box meets it:
   O(log n + k) for k answers where boxes overlap little. The answers are
   kept in the tree's buffer until the next query. */
#include "bvh.h"

#define BVH_LEAF 4

typedef struct {
  PetscReal box[6];
  PetscInt  start, count, left, right; /* the items' range; children (-1 at a leaf) */
} BvhNode;

struct _n_Bvh {
  PetscInt   n, nnodes, cap;
  PetscReal *boxes;
  PetscInt  *items, *found, nfound;
  BvhNode   *nodes;
};

static inline PetscReal Centre(const PetscReal *b, PetscInt d)
{
  return 0.5 * (b[d] + b[3 + d]);
}

/* Puts the k-th smallest centre (along d) of items[lo, hi) at lo + k, the
   smaller before it and the larger after (Hoare's selection). */
static void Select(const PetscReal *boxes, PetscInt *items, PetscInt lo, PetscInt hi, PetscInt k, PetscInt d)
{
  PetscInt l = lo, r = hi - 1, target = lo + k;
  while (l < r) {
    const PetscReal pivot = Centre(&boxes[6 * items[(l + r) / 2]], d);
    PetscInt        i = l, j = r;
    while (i <= j) {
      while (Centre(&boxes[6 * items[i]], d) < pivot) ++i;
      while (Centre(&boxes[6 * items[j]], d) > pivot) --j;
      if (i <= j) {
        const PetscInt t = items[i];
        items[i++]       = items[j];
        items[j--]       = t;
      }
    }
    if (target <= j) r = j;
    else if (target >= i) l = i;
    else break;
  }
}

static PetscInt BvhBuild(Bvh t, PetscInt start, PetscInt count)
{
  const PetscInt id = t->nnodes++;
  BvhNode       *nd = &t->nodes[id];
  PetscReal      cb[6];

  nd->start = start;
  nd->count = count;
  nd->left = nd->right = -1;
  for (PetscInt d = 0; d < 3; ++d) {
    nd->box[d] = cb[d] = PETSC_MAX_REAL;
    nd->box[3 + d] = cb[3 + d] = -PETSC_MAX_REAL;
  }
  for (PetscInt i = start; i < start + count; ++i) {
    const PetscReal *b = &t->boxes[6 * t->items[i]];
    for (PetscInt d = 0; d < 3; ++d) {
      nd->box[d]     = PetscMin(nd->box[d], b[d]);
      nd->box[3 + d] = PetscMax(nd->box[3 + d], b[3 + d]);
      cb[d]          = PetscMin(cb[d], Centre(b, d));
      cb[3 + d]      = PetscMax(cb[3 + d], Centre(b, d));
    }
  }
  if (count > BVH_LEAF) {
    PetscInt axis = 0, l, r;
    for (PetscInt d = 1; d < 3; ++d)
      if (cb[3 + d] - cb[d] > cb[3 + axis] - cb[axis]) axis = d;
    Select(t->boxes, t->items, start, start + count, count / 2, axis);
    l                  = BvhBuild(t, start, count / 2);
    r                  = BvhBuild(t, start + count / 2, count - count / 2);
    t->nodes[id].left  = l;
    t->nodes[id].right = r;
  }
  return id;
}

/* The tree of the n boxes boxes[6 i + (lo 0-2, hi 3-5)] (copied). */
PetscErrorCode BvhCreate(PetscInt n, const PetscReal boxes[], Bvh *tree)
{
  Bvh t;

  PetscFunctionBeginUser;
  PetscCheck(n >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "tree of %" PetscInt_FMT " boxes", n);
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt d = 0; d < 3; ++d) PetscCheck(boxes[6 * i + d] <= boxes[6 * i + 3 + d], PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "box %" PetscInt_FMT ": its low end %g above its high end %g along axis %" PetscInt_FMT, i, (double)boxes[6 * i + d], (double)boxes[6 * i + 3 + d], d);
  PetscCall(PetscNew(&t));
  t->n = n;
  PetscCall(PetscMalloc4(6 * n, &t->boxes, n, &t->items, PetscMax(n, 1), &t->found, PetscMax(2 * n, 1), &t->nodes));
  PetscCall(PetscArraycpy(t->boxes, boxes, 6 * n));
  for (PetscInt i = 0; i < n; ++i) t->items[i] = i;
  if (n) BvhBuild(t, 0, n);
  *tree = t;
  PetscFunctionReturn(0);
}

/* The items whose boxes meet box: *nfound of them in (*found)[], valid until
   the next query. */
PetscErrorCode BvhQuery(Bvh t, const PetscReal box[6], PetscInt *nfound, const PetscInt **found)
{
  PetscInt stack[128], top = 0;

  PetscFunctionBeginUser;
  t->nfound = 0;
  if (t->n) stack[top++] = 0;
  while (top) {
    const BvhNode *nd = &t->nodes[stack[--top]];
    if (!BvhBoxesMeet(nd->box, box)) continue;
    if (nd->left < 0) {
      for (PetscInt i = nd->start; i < nd->start + nd->count; ++i)
        if (BvhBoxesMeet(&t->boxes[6 * t->items[i]], box)) t->found[t->nfound++] = t->items[i];
    } else {
      PetscCheck(top + 2 <= 128, PETSC_COMM_SELF, PETSC_ERR_PLIB, "tree deeper than 64 levels");
      stack[top++] = nd->right;
      stack[top++] = nd->left;
    }
  }
  *nfound = t->nfound;
  *found  = t->found;
  PetscFunctionReturn(0);
}

PetscErrorCode BvhDestroy(Bvh *tree)
{
  PetscFunctionBeginUser;
  if (!*tree) PetscFunctionReturn(0);
  PetscCall(PetscFree4((*tree)->boxes, (*tree)->items, (*tree)->found, (*tree)->nodes));
  PetscCall(PetscFree(*tree));
  PetscFunctionReturn(0);
}
