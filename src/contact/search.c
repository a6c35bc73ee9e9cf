/* Closest-point search over a master surface.

   Every slave point finds the closest point of the whole master surface,
   however far it lies: a point that an iterate has pushed deep into the other
   body still has a master edge and a (negative) gap, so the energy is
   continuous along every line search whatever the step. A search with a
   bounded reach cannot promise that: a point beyond it loses its master, its
   energy drops to zero and the line search meets a jump, whose effect then
   depends on where the search happens to sample (on one machine's rounding).

   Bounding-volume hierarchy. Each master edge is bounded by the box of its
   Bezier control polygon (the quadratic through its three nodes has control
   points a, b and 2m - (a + b)/2), grown by the blend's largest excursion
   (max |psi| = 4 W / 27 times the end corrections). The edges are split
   recursively at the median of their box centres along the wider spread, down
   to leaves of at most SEARCH_LEAF edges; each node's box bounds its edges'.
   The tree is rebuilt from the current coordinates at every evaluation
   (n_m log^2 n_m: a few microseconds per hundred edges).

   Query. Branch and bound: a node is skipped when its box lies farther from
   the point than the best squared distance found; of two children the nearer
   box is visited first. The edges of a leaf are projected (edge.c:
   MasterProject) in turn; of edges at the same distance (a point whose
   closest point is the node two edges share) the lower-numbered is kept, so
   the answer, ties included, depends on the coordinates alone, not on the
   order of the visit. A point near the
   surface visits O(log n_m) nodes; a point far from it, a few more. */
#include "search.h"
#include "edge.h"

#define SEARCH_LEAF 4

typedef struct {
  PetscReal bb[4]; /* xmin, ymin, xmax, ymax */
  PetscInt  lo, hi; /* edges perm[lo..hi) */
  PetscInt  child;  /* first of the two children (the second follows it); -1: a leaf */
} SearchNode;

struct _n_ContactSearch {
  const ContactSurface *S;
  PetscReal (*bb)[4];      /* [ne] bounding box of each edge */
  PetscReal  *key;         /* [ne] box centres along the split axis (scratch) */
  PetscInt   *perm;        /* [ne] edges in the tree's order */
  SearchNode *node;        /* [2 ne] the tree; node 0 the root */
  PetscInt    nnode;
};

PetscErrorCode ContactSearchCreate(const ContactSurface *S, ContactSearch *search)
{
  ContactSearch M;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&M));
  M->S = S;
  PetscCall(PetscMalloc4(S->ne, &M->bb, S->ne, &M->key, S->ne, &M->perm, 2 * S->ne + 1, &M->node));
  *search = M;
  PetscFunctionReturn(0);
}

PetscErrorCode ContactSearchDestroy(ContactSearch *search)
{
  ContactSearch M = *search;

  PetscFunctionBeginUser;
  if (!M) PetscFunctionReturn(0);
  PetscCall(PetscFree4(M->bb, M->key, M->perm, M->node));
  PetscCall(PetscFree(M));
  *search = NULL;
  PetscFunctionReturn(0);
}

/* The box of edge e in the current configuration: its control polygon's,
   grown by the blend's excursion. */
static void SearchEdgeBox(const ContactSurface *S, PetscInt e, PetscReal bb[4])
{
  const PetscInt *en = &S->enodes[3 * e], *mn = &S->mnodes[7 * e];

  for (PetscInt d = 0; d < 2; ++d) {
    const PetscReal a = S->x[2 * en[0] + d], b = S->x[2 * en[1] + d], c = 2.0 * S->x[2 * en[2] + d] - 0.5 * (a + b);
    PetscReal       ca = 0.0, cb = 0.0, grow;
    for (PetscInt j = 0; j < 7; ++j) {
      ca += S->mcorr[14 * e + j] * S->x[2 * mn[j] + d];
      cb += S->mcorr[14 * e + 7 + j] * S->x[2 * mn[j] + d];
    }
    grow      = 4.0 * S->blend / 27.0 * (PetscAbsReal(ca) + PetscAbsReal(cb));
    bb[d]     = PetscMin(a, PetscMin(b, c)) - grow;
    bb[2 + d] = PetscMax(a, PetscMax(b, c)) + grow;
  }
}

/* Node k over edges perm[lo..hi): its box, then its children over the two
   halves of the edges sorted by box centre along the wider spread. */
static PetscErrorCode SearchBuildNode(ContactSearch M, PetscInt k, PetscInt lo, PetscInt hi)
{
  SearchNode *N = &M->node[k];
  PetscReal   cmin[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, cmax[2] = {-PETSC_MAX_REAL, -PETSC_MAX_REAL};
  PetscInt    axis, mid;

  PetscFunctionBeginUser;
  N->lo    = lo;
  N->hi    = hi;
  N->child = -1;
  N->bb[0] = N->bb[1] = PETSC_MAX_REAL;
  N->bb[2] = N->bb[3] = -PETSC_MAX_REAL;
  for (PetscInt i = lo; i < hi; ++i) {
    const PetscReal *b = M->bb[M->perm[i]];
    for (PetscInt d = 0; d < 2; ++d) {
      const PetscReal c = 0.5 * (b[d] + b[2 + d]);
      N->bb[d]          = PetscMin(N->bb[d], b[d]);
      N->bb[2 + d]      = PetscMax(N->bb[2 + d], b[2 + d]);
      cmin[d]           = PetscMin(cmin[d], c);
      cmax[d]           = PetscMax(cmax[d], c);
    }
  }
  if (hi - lo <= SEARCH_LEAF) PetscFunctionReturn(0);
  axis = cmax[0] - cmin[0] >= cmax[1] - cmin[1] ? 0 : 1;
  for (PetscInt i = lo; i < hi; ++i) M->key[i] = 0.5 * (M->bb[M->perm[i]][axis] + M->bb[M->perm[i]][2 + axis]);
  PetscCall(PetscSortRealWithArrayInt(hi - lo, &M->key[lo], &M->perm[lo]));
  mid      = lo + (hi - lo) / 2;
  N->child = M->nnode;
  M->nnode += 2;
  PetscCall(SearchBuildNode(M, N->child, lo, mid));
  PetscCall(SearchBuildNode(M, N->child + 1, mid, hi));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactSearchBuild(ContactSearch M)
{
  const ContactSurface *S = M->S;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < S->ne; ++e) {
    SearchEdgeBox(S, e, M->bb[e]);
    M->perm[e] = e;
  }
  M->nnode = 1;
  if (S->ne) PetscCall(SearchBuildNode(M, 0, 0, S->ne));
  PetscFunctionReturn(0);
}

/* Squared distance from p to box b (0 inside). */
static inline PetscReal SearchBoxDistance2(const PetscReal b[4], const PetscReal p[2])
{
  const PetscReal dx = PetscMax(0.0, PetscMax(b[0] - p[0], p[0] - b[2])), dy = PetscMax(0.0, PetscMax(b[1] - p[1], p[1] - b[3]));

  return dx * dx + dy * dy;
}

void ContactSearchFindClosest(ContactSearch M, const PetscReal p[2], PetscInt *edge, PetscReal *eta)
{
  PetscInt  stack[128], top = 0; /* a median split: depth <= log2(ne); at most depth + 1 entries wait */
  PetscReal best = PETSC_MAX_REAL;

  *edge = -1;
  if (!M->S->ne) return;
  stack[top++] = 0;
  while (top) {
    const SearchNode *N = &M->node[stack[--top]];
    if (SearchBoxDistance2(N->bb, p) > best) continue;
    if (N->child < 0) {
      for (PetscInt i = N->lo; i < N->hi; ++i) {
        const PetscInt e = M->perm[i];
        PetscReal      e_eta, d2;
        if (SearchBoxDistance2(M->bb[e], p) > best) continue;
        MasterProject(M->S, e, p, &e_eta, &d2);
        if (d2 < best || (d2 == best && e < *edge)) {
          best  = d2;
          *edge = e;
          *eta  = e_eta;
        }
      }
    } else {
      const PetscInt  a = N->child, b = N->child + 1;
      const PetscReal da = SearchBoxDistance2(M->node[a].bb, p), db = SearchBoxDistance2(M->node[b].bb, p);
      /* the farther child waits below the nearer */
      stack[top++] = da <= db ? b : a;
      stack[top++] = da <= db ? a : b;
    }
  }
}
