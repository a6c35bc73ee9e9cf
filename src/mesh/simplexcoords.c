/* A Tet10 mesh's second-order coordinates put in each cell's own vertex
   order, before the mesh is distributed.

   PETSc 3.18's Gmsh reader stores a simplicial mesh's second-order
   coordinates cellwise (a discontinuous P2 field): each cell's values
   describe x(xi) over the reference tetrahedron with the cell's Gmsh vertices
   at the reference vertices in Gmsh's order. The cell's topology is another
   order: its cone is reordered (DMPlexReorderCell) and interpolated, and
   the closure's vertices, which the displacement element's nodes follow
   (body.c), come out in that order. For a triangle the two agree; for a
   tetrahedron they need not, and a node's position read from one cell's
   coordinates is then another vertex's: the mesh is not conforming
   (measured: nodes 0.6 apart between cells sharing them on a unit box,
   the affine patch test off by 4 %).

   So each cell's coordinates are rewritten in its closure's vertex order.
   The cell's vertex positions G_j (its field at the reference vertices R_j)
   are right as a set; which closure vertex sits at which is found by
   agreement: a vertex's position is the one that every cell around it has
   among its G_j (two cells share at most three vertices, and the cells
   round a vertex have it alone in common), and where its cells leave more
   than one (a vertex of one cell, at a corner of the mesh), by elimination
   of the positions its cell's other vertices have. With sigma(i) the
   reference vertex at which closure vertex i sits, the new field takes at
   each of its nodes (barycentric lambda in the closure's frame) the old
   field's value at sum_i lambda_i R_sigma(i): the same map x(xi), in the
   cell's own frame, the curved faces and edges kept. */
#include "simplexcoords.h"

#define SC_MAXNODES 64

typedef struct {
  PetscBool seen;
  PetscInt  ncand;
  PetscReal cand[4][3];
} VertexCandidates;

static PetscBool SamePoint(const PetscReal a[3], const PetscReal b[3], PetscReal tol)
{
  return (PetscBool)(PetscAbsReal(a[0] - b[0]) <= tol && PetscAbsReal(a[1] - b[1]) <= tol && PetscAbsReal(a[2] - b[2]) <= tol);
}

/* The closure's vertices of cell c, in order. */
static PetscErrorCode CellVertices(DM dm, PetscInt c, PetscInt vs, PetscInt ve, PetscInt v[4])
{
  PetscInt *cl = NULL, ncl, k = 0;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &ncl, &cl));
  for (PetscInt i = 0; i < ncl; ++i)
    if (cl[2 * i] >= vs && cl[2 * i] < ve && k < 4) v[k++] = cl[2 * i];
  PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &ncl, &cl));
  PetscCheck(k == 4, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell %" PetscInt_FMT ": %" PetscInt_FMT " vertices", c, k);
  PetscFunctionReturn(0);
}

/* The reference tetrahedron's vertices R[4][3] in its closure's order. */
static PetscErrorCode ReferenceVertices(PetscReal R[4][3])
{
  DM                 rdm;
  Vec                rc;
  PetscInt           rvs, rve, v[4];
  const PetscScalar *ra;

  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateReferenceCell(PETSC_COMM_SELF, DM_POLYTOPE_TETRAHEDRON, &rdm));
  PetscCall(DMPlexGetDepthStratum(rdm, 0, &rvs, &rve));
  PetscCall(CellVertices(rdm, 0, rvs, rve, v));
  PetscCall(DMGetCoordinatesLocal(rdm, &rc));
  PetscCall(VecGetArrayRead(rc, &ra));
  for (PetscInt i = 0; i < 4; ++i)
    for (PetscInt d = 0; d < 3; ++d) R[i][d] = PetscRealPart(ra[3 * (v[i] - rvs) + d]);
  PetscCall(VecRestoreArrayRead(rc, &ra));
  PetscCall(DMDestroy(&rdm));
  PetscCheck(R[0][0] == -1 && R[0][1] == -1 && R[0][2] == -1, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the reference tetrahedron's first vertex is not (-1, -1, -1)");
  PetscFunctionReturn(0);
}

/* Each vertex's candidates (vc): the positions every cell round it has
   among its G_j; then, where several are left, less those its cells' other
   vertices have. */
static PetscErrorCode VertexPositions(PetscInt cS, PetscInt cE, const PetscInt cv[], PetscInt vs, const PetscReal G[], PetscReal tol, VertexCandidates vc[])
{
  PetscFunctionBeginUser;
  for (PetscInt c = cS; c < cE; ++c) {
    const PetscInt *v = &cv[4 * (c - cS)];
    for (PetscInt i = 0; i < 4; ++i) {
      VertexCandidates *w = &vc[v[i] - vs];
      const PetscReal  *g = &G[12 * (c - cS)];
      if (!w->seen) { /* first cell: its four */
        w->seen = PETSC_TRUE;
        for (PetscInt j = 0; j < 4; ++j)
          for (PetscInt d = 0; d < 3; ++d) w->cand[j][d] = g[3 * j + d];
        w->ncand = 4;
        continue;
      }
      for (PetscInt k = 0; k < w->ncand;) {
        PetscBool found = PETSC_FALSE;
        for (PetscInt j = 0; j < 4 && !found; ++j) found = SamePoint(w->cand[k], &g[3 * j], tol);
        if (found) ++k;
        else {
          for (PetscInt d = 0; d < 3; ++d) w->cand[k][d] = w->cand[w->ncand - 1][d];
          w->ncand--;
        }
      }
    }
  }
  for (PetscBool progress = PETSC_TRUE; progress;) {
    progress = PETSC_FALSE;
    for (PetscInt c = cS; c < cE; ++c) {
      const PetscInt *v = &cv[4 * (c - cS)];
      for (PetscInt i = 0; i < 4; ++i) {
        VertexCandidates *w = &vc[v[i] - vs];
        if (w->ncand <= 1) continue;
        for (PetscInt o = 0; o < 4; ++o) {
          const VertexCandidates *u = &vc[v[o] - vs];
          if (o == i || u->ncand != 1) continue;
          for (PetscInt k = 0; k < w->ncand; ++k)
            if (SamePoint(w->cand[k], u->cand[0], tol)) {
              for (PetscInt d = 0; d < 3; ++d) w->cand[k][d] = w->cand[w->ncand - 1][d];
              w->ncand--;
              progress = PETSC_TRUE;
              break;
            }
        }
      }
    }
  }
  PetscFunctionReturn(0);
}

/* The old field's basis at the points where a cell whose closure vertex i
   sits at R_sigma(i) has its nodes: each node (reference ref[k],
   barycentric lambda in the closure's frame) at sum_i lambda_i R_sigma(i). */
static PetscErrorCode PermutedTabulation(PetscFE cfe, PetscInt nb, const PetscReal ref[], PetscReal R[4][3], const PetscInt sigma[4], PetscTabulation *T)
{
  PetscReal pts[SC_MAXNODES * 3];

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < nb; ++k) {
    const PetscReal *x = &ref[3 * k];
    PetscReal        l[4];
    for (PetscInt i = 1; i < 4; ++i) { /* R_0 = (-1,-1,-1), R_i one coordinate at +1 */
      PetscInt axis = 0;
      for (PetscInt d = 0; d < 3; ++d)
        if (R[i][d] > 0) axis = d;
      l[i] = 0.5 * (x[axis] + 1.0);
    }
    l[0] = 1.0 - l[1] - l[2] - l[3];
    for (PetscInt d = 0; d < 3; ++d) {
      pts[3 * k + d] = 0;
      for (PetscInt i = 0; i < 4; ++i) pts[3 * k + d] += l[i] * R[sigma[i]][d];
    }
  }
  PetscCall(PetscFECreateTabulation(cfe, 1, nb, pts, 0, T));
  PetscFunctionReturn(0);
}

/* Cell c's field a[nb * nc] rewritten in its closure's frame, T the old
   field's basis at its nodes (PermutedTabulation). */
static void CellRewrite(PetscInt nb, PetscInt nc, PetscTabulation T, PetscScalar a[])
{
  PetscReal old[SC_MAXNODES * 3];

  for (PetscInt f = 0; f < nb * nc; ++f) old[f] = PetscRealPart(a[f]);
  for (PetscInt k = 0; k < nb; ++k)
    for (PetscInt d = 0; d < nc; ++d) {
      PetscReal x = 0;
      for (PetscInt f = 0; f < nb * nc; ++f) x += old[f] * T->T[0][(k * nb * nc + f) * nc + d];
      a[k * nc + d] = x;
    }
}

PetscErrorCode MeshSimplexCoordinatesInCellOrder(DM dm, const char name[], const char file[])
{
  DM                cdm;
  Vec               coords;
  PetscSection      cs;
  PetscFE           cfe;
  PetscDualSpace    sp;
  PetscTabulation   Tv, Tp[256] = {NULL}; /* the permuted tabulations met, by sigma's code (4 digits base 4) */
  PetscInt          dim, cS, cE, vs, ve, nb, nc, dof, changed = 0;
  PetscReal         R[4][3], ref[SC_MAXNODES * 3], lo[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[3] = {PETSC_MIN_REAL, PETSC_MIN_REAL, PETSC_MIN_REAL}, tol = 0;
  PetscReal        *G;
  PetscInt         *cv;
  VertexCandidates *vc;
  PetscScalar      *a;
  PetscObject       obj;

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cS, &cE));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vs, &ve));
  if (dim != 3 || cE == cS) PetscFunctionReturn(0);
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetField(cdm, 0, NULL, &obj));
  if (!obj) PetscFunctionReturn(0);
  cfe = (PetscFE)obj;
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(PetscSectionGetDof(cs, cS, &dof));
  if (!dof) PetscFunctionReturn(0); /* a continuous field: ordered by the points themselves */
  PetscCall(PetscFEGetDimension(cfe, &nb));
  PetscCall(PetscFEGetNumComponents(cfe, &nc));
  nb /= nc;
  PetscCheck(nc == 3 && nb <= SC_MAXNODES, PETSC_COMM_SELF, PETSC_ERR_SUP, "body %s: mesh %s: a coordinate field of %" PetscInt_FMT " components and %" PetscInt_FMT " nodes", name, file, nc, nb);
  PetscCall(ReferenceVertices(R));
  PetscCall(PetscFEGetDualSpace(cfe, &sp));
  for (PetscInt k = 0; k < nb; ++k) { /* the nodes of the field's first component (its functionals come component by component at each node) */
    PetscQuadrature  fq;
    const PetscReal *pts;
    PetscCall(PetscDualSpaceGetFunctional(sp, k * nc, &fq));
    PetscCall(PetscQuadratureGetData(fq, NULL, NULL, NULL, &pts, NULL));
    for (PetscInt d = 0; d < 3; ++d) ref[3 * k + d] = pts[d];
  }
  PetscCall(PetscFECreateTabulation(cfe, 1, 4, &R[0][0], 0, &Tv));
  PetscCall(PetscMalloc2(12 * (cE - cS), &G, 4 * (cE - cS), &cv));
  PetscCall(PetscCalloc1(ve - vs, &vc));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(VecGetArray(coords, &a));
  for (PetscInt c = cS; c < cE; ++c) { /* each cell's vertex positions G_j, its field at R_j */
    PetscInt off;
    PetscCall(PetscSectionGetOffset(cs, c, &off));
    for (PetscInt j = 0; j < 4; ++j)
      for (PetscInt d = 0; d < 3; ++d) {
        PetscReal x = 0;
        for (PetscInt f = 0; f < nb * nc; ++f) x += PetscRealPart(a[off + f]) * Tv->T[0][(j * nb * nc + f) * nc + d];
        G[12 * (c - cS) + 3 * j + d] = x;
        lo[d] = PetscMin(lo[d], x);
        hi[d] = PetscMax(hi[d], x);
      }
  }
  for (PetscInt d = 0; d < 3; ++d) tol = PetscMax(tol, hi[d] - lo[d]);
  tol *= 1e-9;
  for (PetscInt c = cS; c < cE; ++c) PetscCall(CellVertices(dm, c, vs, ve, &cv[4 * (c - cS)])); /* each cell's closure vertices, once */
  PetscCall(VertexPositions(cS, cE, cv, vs, G, tol, vc));
  for (PetscInt c = cS; c < cE; ++c) { /* sigma per cell, and its field rewritten in its closure's frame */
    const PetscInt *v = &cv[4 * (c - cS)];
    PetscInt        sigma[4], off;
    PetscBool       identity = PETSC_TRUE;
    for (PetscInt i = 0; i < 4; ++i) {
      const VertexCandidates *w = &vc[v[i] - vs];
      PetscInt                j = -1;
      PetscCheck(w->ncand == 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: the position of a vertex of cell %" PetscInt_FMT " is not determined by its cells (%" PetscInt_FMT " candidates)", name, file, c, w->ncand);
      for (PetscInt k = 0; k < 4 && j < 0; ++k)
        if (SamePoint(w->cand[0], &G[12 * (c - cS) + 3 * k], tol)) j = k;
      PetscCheck(j >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: cell %" PetscInt_FMT " has no vertex at its vertex's position", name, file, c);
      sigma[i] = j;
      identity = (PetscBool)(identity && j == i);
    }
    if (identity) continue;
    changed++;
    {
      const PetscInt code = ((sigma[0] * 4 + sigma[1]) * 4 + sigma[2]) * 4 + sigma[3];
      if (!Tp[code]) PetscCall(PermutedTabulation(cfe, nb, ref, R, sigma, &Tp[code]));
      PetscCall(PetscSectionGetOffset(cs, c, &off));
      CellRewrite(nb, nc, Tp[code], &a[off]);
    }
  }
  PetscCall(VecRestoreArray(coords, &a));
  PetscCall(DMSetCoordinatesLocal(dm, coords));
  PetscCall(PetscTabulationDestroy(&Tv));
  for (PetscInt k = 0; k < 256; ++k)
    if (Tp[k]) PetscCall(PetscTabulationDestroy(&Tp[k]));
  PetscCall(PetscFree2(G, cv));
  PetscCall(PetscFree(vc));
  PetscCall(PetscInfo(NULL, "body %s: %" PetscInt_FMT " of %" PetscInt_FMT " cells' second-order coordinates put in their closure's vertex order\n", name, changed, cE - cS));
  PetscFunctionReturn(0);
}
