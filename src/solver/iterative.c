/* Newton steps by an iterative solver, for problems whose factorisation no
   longer fits in memory: conjugate gradients on the Hessian H = K + C,
   preconditioned by aggregation algebraic multigrid (PCGAMG).
   Elasticity needs the multigrid's coarse spaces to represent the rigid
   motions, which the stiffness of a body free of its Dirichlet conditions
   annihilates: they are given as H's near-nullspace, three per 2D body
   (translations in x and y, rotation; six per 3D body: three translations,
   three rotations), each supported on its own body's
   dofs, orthonormalised. The contact Hessian couples the bodies only through
   their surfaces, a low-rank change GAMG sees in its matrix. Each Newton step
   is solved to -tao_nls_ksp_rtol (1e-6 by default, relative to the gradient):
   Newton's convergence is then quadratic down to that level and linear with
   factor 1e-6 below it, so -tao_gttol 1e-8 is met in a step or two more than
   with the exact step. GAMG is set up again at every step, its
   interpolation too (PCGAMG's default reuses the first step's, built without
   contact, and the preconditioner turns indefinite once the penalty acts),
   except where H does not change (no contact term, the bodies' stiffness
   at rest): then its first set-up serves every step and stage (on the Hex27
   block of 89k dofs, under load, GAMG's set-up took 9 s a step, its 13 CG
   iterations 2.4 s).
   In 3D the aggregation is unsmoothed (-pc_gamg_agg_nsmooths 0): a
   quadratic 3D cell couples each node to up to 125 others, so that the
   smoothed prolongator's Galerkin product A P is most of the set-up; without
   it the set-up is several times cheaper for some 40 % more CG
   iterations (on the Hex27 block of 108k dofs, one rank: 6.8 s against
   10.2 s for the solve, 28 against 18 iterations; bench/solid3d/RESULTS.md).
   Where H is constant the problem is linear and Newton's first step is its
   answer: solved to 1e-9 in place of 1e-6, it meets -tao_gttol 1e-8 in one
   step, with no second solve to restart CG from (Lame's octant, 79k dofs:
   53 CG iterations in one step against 73 in two, solve 4.2 s against 5.0 s).
   That stop is on the true residual (CG's unpreconditioned norm), which is
   the gradient the step leaves, g0 + H d: the preconditioned norm's 1e-9
   left it at 4.9e-9 of g0 with GAMG on the free dofs and at 9.5e-9 by nodes,
   a hair below 1e-8, where a second Newton step doubles the cost; the true
   norm's 1e-9 costs 5 iterations more (46 against 41 on Lame's octant).
   The Gauss-Newton contact Hessian is symmetric positive semi-definite, so
   CG applies; the exact one, which auto adds only once the gradient is
   small, leaves H positive definite there. */
#include "iterative.h"
#include "rigid.h"

/* GAMG by nodes. The Hessian's rows are the free dofs only: a node on a
   roller (a symmetry plane) keeps two of its three components, so H has
   no block size and GAMG aggregates single components, not nodes, its
   strength graph as large as H. Here H is copied into Hn, in which every node of a 3D
   body has its three components as consecutive rows, a constrained one an
   identity row and column (decoupled, its right-hand side zero): Hn has
   block size 3 and GAMG aggregates nodes. The preconditioner of H is
   R GAMG(Hn) R^T, R the injection of H's rows into Hn's: symmetric
   positive definite as GAMG(Hn) is, so CG applies. Hn's rows on a rank are
   its nodes' in the order of their first free row, so that each row's
   columns keep H's order. The near-nullspace is the bodies' rigid motions
   as on H, injected (zero on the constrained components). Measured on
   Lame's octant at h = 0.1 (79,245 dofs, rollers on three planes; one
   rank, load 1.5): by nodes the V-cycle takes as many CG iterations as on
   the free dofs (54 against 53 to the preconditioned 1e-9; the aggregates
   are as coarse, some 40 nodes each), but its graph is a ninth of H's
   (peak 455 MB against 525) and the coarse levels are cheap enough for a
   W-cycle (-newton_iterative_cycle, w by default): 41 iterations, the
   solve's CG 2.1 s against 2.7 s. Neither -pc_gamg_threshold 0.01 or 0.02,
   nor 1 or 3 Chebyshev steps a level, nor SOR on the finest, did better;
   smoothed aggregation without the aggressive first coarsening takes 18
   iterations but its first coarse level has 1277 entries a row (set-up 30
   times longer).
   Two levels (one rank, the default there): what limits GAMG on quadratic
   cells is its first coarse space, aggregates of some 40 nodes with the
   rigid modes alone. A quadratic mesh holds a better one, its linear
   (P1, Q1) displacements on the same cells: P interpolates each node from
   the vertices of its point's closure (an edge's midpoint the mean of its
   two, a Hex27 face's of four, a cell's of eight), and the coarse operator
   is P^T Hn P, some 7 times smaller on Tet10, as sparse as a linear mesh's.
   The nodes are smoothed by Chebyshev (2 steps, Jacobi) and the vertices
   solved by one GAMG V-cycle, with smoothed aggregation there (its Galerkin
   products on rows of 40 entries cost little). Lame's octant: 20 CG
   iterations against 46 by nodes (both to the true 1e-9), the CG 0.95 s
   against 2.3 s, the set-up 0.58 s against 0.8; tet10-1e5 16 against 34,
   hex27-1e5 13 against 26. On several ranks a closure's vertices may be
   another rank's, which P does not gather: GAMG by nodes there. */
typedef struct {
  PC            gamg;   /* on Hn */
  Mat           Hn;     /* H in the nodes' numbering, block size 3 */
  PetscObjectState Hstate; /* H's nonzero pattern's state when Hn was made (NodalPCBuildMatrix) */
  Vec           xn, yn; /* Hn's vectors (xn zero on the constrained rows) */
  VecScatter    inject; /* R^T: H's vectors into Hn's */
  MatNullSpace  nsp;    /* on Hn */
  PetscInt      nrows;  /* Hn's rows on this rank */
  PetscInt     *slot;   /* Hn's row rstart_n + k: H's row, or -1 (a constrained component) */
  PetscInt     *row;    /* H's row rstart + i: Hn's row */
  PCMGCycleType cycle;  /* -newton_iterative_cycle */
  Vec           rowOf;  /* row as a vector of H's layout, for columns on other ranks */
  Mat           P;      /* two levels (one rank): the cells' vertices' displacements interpolated to every node */
  PC            mg;     /* two levels: the nodes, then the vertices by GAMG */
  Mat           Ac;     /* P^T Hn P */
} NodalPC;

/* Hn's node of a point's joined rows (its last free component's row in Hn
   / 3), -1 for a point with no free component. */
static PetscInt NodalPCRowsNode(NodalPC *np, const PetscInt rows[3], PetscInt rstart)
{
  PetscInt node = -1;

  for (PetscInt d = 2; d >= 0; --d)
    if (rows[d] >= 0) node = np->row[rows[d] - rstart] / 3;
  return node;
}

/* P: each node's displacement the mean of its cell's vertices' around it,
   the vertices of its point's closure (an edge's two, a face's, a cell's:
   the linear (P1, Q1) interpolation at a quadratic node, exact for
   Tet10's and Hex27's), component by component; a vertex is a coarse node,
   in Hn's order. One rank (the vertices of a closure are then all here;
   BodyGetNodeVertexRows gives them). */
static PetscErrorCode NodalPCBuildInterpolation(NodalPC *np, Mat H, PetscInt nbodies, Body bodies[])
{
  PetscInt rstart, rend, nn = np->nrows / 3, *cidx, nc = 0;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(H, &rstart, &rend));
  PetscCall(PetscMalloc1(nn + 1, &cidx));
  for (PetscInt k = 0; k < nn; ++k) cidx[k] = -1;
  for (PetscInt pass = 0; pass < 2; ++pass) { /* the vertices numbered, then the interpolation */
    if (pass == 1) {
      for (PetscInt k = 0; k < nn; ++k)
        if (cidx[k] > 0) cidx[k] = nc++;
      PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, 3 * nn, 3 * nc, 8, NULL, &np->P));
    }
    for (PetscInt i = 0; i < nbodies; ++i) {
      PetscInt n, *rows, *nv, *vrows;

      PetscCall(BodyGetNodeVertexRows(bodies[i], &n, &rows, &nv, &vrows));
      for (PetscInt k = 0; k < n; ++k) {
        const PetscInt node = NodalPCRowsNode(np, &rows[3 * k], rstart);
        if (node < 0) continue;
        for (PetscInt j = 0; j < nv[k]; ++j) { /* a vertex with every component held: no coarse node, no term */
          const PetscInt v = NodalPCRowsNode(np, &vrows[(8 * k + j) * 3], rstart);
          if (v < 0) continue;
          if (pass == 0) cidx[v] = 1;
          else
            for (PetscInt d = 0; d < 3; ++d) PetscCall(MatSetValue(np->P, 3 * node + d, 3 * cidx[v] + d, 1.0 / nv[k], INSERT_VALUES));
        }
      }
      PetscCall(PetscFree3(rows, nv, vrows));
    }
  }
  PetscCall(MatAssemblyBegin(np->P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(np->P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetBlockSizes(np->P, 3, 3));
  PetscCall(PetscInfo(H, "two levels: %" PetscInt_FMT " nodes, %" PetscInt_FMT " vertices\n", nn, nc));
  PetscCall(PetscFree(cidx));
  PetscFunctionReturn(0);
}

/* H's row (n columns cols) in Hn's columns j. */
static PetscErrorCode NodalPCMapRow(const NodalPC *np, PetscInt rstart, PetscInt rend, PetscInt noff, const PetscInt garray[], const PetscScalar offRow[], PetscInt n, const PetscInt cols[], PetscInt j[])
{
  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < n; ++e) {
    if (cols[e] >= rstart && cols[e] < rend) j[e] = np->row[cols[e] - rstart];
    else {
      PetscInt loc;
      PetscCall(PetscFindInt(cols[e], noff, garray, &loc));
      PetscCheck(loc >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "column %" PetscInt_FMT " of the Hessian not among its off-rank columns", cols[e]);
      j[e] = (PetscInt)PetscRealPart(offRow[loc]);
    }
  }
  PetscFunctionReturn(0);
}

/* Hn from H's values: each free row's entries at Hn's columns, a constrained
   row's diagonal 1, inserted row by row straight from H's rows. Where H's
   nonzero pattern is the one Hn was made from (every step but the first,
   unless the Hessian grew), Hn's values are replaced in place; else Hn is
   made anew, preallocated by a first pass counting its rows' columns. No
   copy of H's entries is gathered and the old Hn is not kept beside the
   new: the set-up's peak memory holds K, H and Hn (three matrices of H's
   pattern) where it held five (the gathered entries, as large as a matrix,
   and the last step's Hn besides; the Hertz ball at h 0.02 by CG + GAMG,
   bench/contact3d/NOTES.md). The same entries are inserted in the same
   order either way, so Hn is the same matrix. */
static PetscErrorCode NodalPCBuildMatrix(NodalPC *np, Mat H)
{
  PetscInt         rstart, rend, nstart, noff = 0, *garray = NULL, *dnz, *onz, w = 1, *j;
  PetscScalar     *offRow = NULL, one = 1.0;
  PetscMPIInt      size;
  MPI_Comm         comm = PetscObjectComm((PetscObject)H);
  Vec              offVec = NULL;
  VecScatter       offScatter = NULL;
  PetscObjectState state;
  PetscBool        fresh;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(MatGetOwnershipRange(H, &rstart, &rend));
  PetscCall(MatGetNonzeroState(H, &state));
  fresh = (PetscBool)(!np->Hn || state != np->Hstate);
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &fresh, 1, MPIU_BOOL, MPI_LOR, comm));
  PetscCallMPI(MPI_Scan(&np->nrows, &nstart, 1, MPIU_INT, MPI_SUM, comm));
  nstart -= np->nrows;
  if (size > 1) { /* Hn's rows of H's columns on other ranks */
    Mat Ad, Ao;
    IS  is;
    PetscCall(MatMPIAIJGetSeqAIJ(H, &Ad, &Ao, (const PetscInt **)&garray));
    PetscCall(MatGetSize(Ao, NULL, &noff));
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, noff, garray, PETSC_USE_POINTER, &is));
    PetscCall(VecCreateSeq(PETSC_COMM_SELF, noff, &offVec));
    PetscCall(VecScatterCreate(np->rowOf, is, offVec, NULL, &offScatter));
    PetscCall(VecScatterBegin(offScatter, np->rowOf, offVec, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(offScatter, np->rowOf, offVec, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(ISDestroy(&is));
    PetscCall(VecGetArray(offVec, &offRow));
  }
  for (PetscInt k = 0; k < np->nrows; ++k) { /* the widest row */
    PetscInt n, m;
    if (np->slot[k] < 0) continue;
    PetscCall(MatGetRow(H, np->slot[k], &n, NULL, NULL));
    m = n; /* MatRestoreRow() zeroes it */
    PetscCall(MatRestoreRow(H, np->slot[k], &m, NULL, NULL));
    w = PetscMax(w, n);
  }
  PetscCall(PetscMalloc1(w, &j));
  if (fresh) {
    PetscCall(MatDestroy(&np->Hn));
    PetscCall(PetscCalloc2(np->nrows, &dnz, np->nrows, &onz));
    for (PetscInt k = 0; k < np->nrows; ++k) {
      const PetscInt *cols;
      PetscInt        n;
      if (np->slot[k] < 0) {
        dnz[k] = 1;
        continue;
      }
      PetscCall(MatGetRow(H, np->slot[k], &n, &cols, NULL));
      PetscCall(NodalPCMapRow(np, rstart, rend, noff, garray, offRow, n, cols, j));
      for (PetscInt e = 0; e < n; ++e) {
        if (j[e] >= nstart && j[e] < nstart + np->nrows) ++dnz[k];
        else ++onz[k];
      }
      PetscCall(MatRestoreRow(H, np->slot[k], &n, &cols, NULL));
    }
    PetscCall(MatCreate(comm, &np->Hn));
    PetscCall(MatSetSizes(np->Hn, np->nrows, np->nrows, PETSC_DETERMINE, PETSC_DETERMINE));
    PetscCall(MatSetType(np->Hn, MATAIJ));
    PetscCall(MatSetBlockSize(np->Hn, 3));
    PetscCall(MatSeqAIJSetPreallocation(np->Hn, 0, dnz));
    PetscCall(MatMPIAIJSetPreallocation(np->Hn, 0, dnz, 0, onz));
    PetscCall(PetscFree2(dnz, onz));
  }
  for (PetscInt k = 0; k < np->nrows; ++k) {
    const PetscInt     r = nstart + k;
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscInt           n;
    if (np->slot[k] < 0) {
      PetscCall(MatSetValues(np->Hn, 1, &r, 1, &r, &one, INSERT_VALUES));
      continue;
    }
    PetscCall(MatGetRow(H, np->slot[k], &n, &cols, &vals));
    PetscCall(NodalPCMapRow(np, rstart, rend, noff, garray, offRow, n, cols, j));
    PetscCall(MatSetValues(np->Hn, 1, &r, n, j, vals, INSERT_VALUES));
    PetscCall(MatRestoreRow(H, np->slot[k], &n, &cols, &vals));
  }
  PetscCall(PetscFree(j));
  if (offVec) {
    PetscCall(VecRestoreArray(offVec, &offRow));
    PetscCall(VecDestroy(&offVec));
    PetscCall(VecScatterDestroy(&offScatter));
  }
  PetscCall(MatAssemblyBegin(np->Hn, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(np->Hn, MAT_FINAL_ASSEMBLY));
  if (fresh) {
    PetscCall(MatSetOption(np->Hn, MAT_SYMMETRIC, PETSC_TRUE));
    PetscCall(MatSetNearNullSpace(np->Hn, np->nsp));
  }
  np->Hstate = state;
  PetscFunctionReturn(0);
}

static PetscErrorCode NodalPCSetUp(PC pc)
{
  NodalPC *np;
  Mat      H;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &np));
  PetscCall(PCGetOperators(pc, NULL, &H));
  PetscCall(NodalPCBuildMatrix(np, H));
  if (np->P) { /* two levels: Chebyshev on Hn, GAMG on P^T Hn P */
    KSP          smooth, coarse;
    PC           spc, cpc;
    MatNullSpace cn;
    Vec          cm[6 * CONTACT_MAX_BODIES];
    const Vec   *fm;
    PetscInt     nf, m;

    PetscCall(MatDestroy(&np->Ac));
    PetscCall(MatPtAP(np->Hn, np->P, MAT_INITIAL_MATRIX, 2.0, &np->Ac));
    PetscCall(MatSetBlockSize(np->Ac, 3));
    /* the coarse near-nullspace: the fine one at the vertices (P's rows there are the identity) */
    PetscCall(MatNullSpaceGetVecs(np->nsp, NULL, &nf, &fm));
    PetscCall(MatGetSize(np->P, &m, NULL));
    for (PetscInt k = 0; k < nf; ++k) {
      const PetscScalar *f;
      PetscScalar       *c;
      PetscCall(MatCreateVecs(np->Ac, &cm[k], NULL));
      PetscCall(VecZeroEntries(cm[k]));
      PetscCall(VecGetArrayRead(fm[k], &f));
      PetscCall(VecGetArray(cm[k], &c));
      for (PetscInt r = 0; r < m; ++r) {
        PetscInt           ncols;
        const PetscInt    *cols;
        const PetscScalar *vals;
        PetscCall(MatGetRow(np->P, r, &ncols, &cols, &vals));
        if (ncols == 1 && vals[0] == 1.0) c[cols[0]] = f[r];
        PetscCall(MatRestoreRow(np->P, r, &ncols, &cols, &vals));
      }
      PetscCall(VecRestoreArrayRead(fm[k], &f));
      PetscCall(VecRestoreArray(cm[k], &c));
    }
    PetscCall(MatNullSpaceCreate(PETSC_COMM_SELF, PETSC_FALSE, nf, cm, &cn));
    PetscCall(MatSetNearNullSpace(np->Ac, cn));
    PetscCall(MatNullSpaceDestroy(&cn));
    for (PetscInt k = 0; k < nf; ++k) PetscCall(VecDestroy(&cm[k]));
    if (!np->mg) {
      PetscCall(PCCreate(PETSC_COMM_SELF, &np->mg));
      PetscCall(PCSetType(np->mg, PCMG));
      PetscCall(PCMGSetLevels(np->mg, 2, NULL));
      PetscCall(PCMGSetInterpolation(np->mg, 1, np->P));
      PetscCall(PCMGSetGalerkin(np->mg, PC_MG_GALERKIN_NONE));
      PetscCall(PCMGGetSmoother(np->mg, 1, &smooth));
      PetscCall(KSPSetType(smooth, KSPCHEBYSHEV));
      PetscCall(KSPGetPC(smooth, &spc));
      PetscCall(PCSetType(spc, PCJACOBI));
      PetscCall(KSPChebyshevEstEigSet(smooth, 0, 0.1, 0, 1.1));
      PetscCall(KSPSetTolerances(smooth, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 2));
      PetscCall(PCMGGetCoarseSolve(np->mg, &coarse));
      PetscCall(KSPSetType(coarse, KSPPREONLY));
      PetscCall(KSPGetPC(coarse, &cpc));
      PetscCall(PCSetType(cpc, PCGAMG));
      PetscCall(PCGAMGSetNSmooths(cpc, 1));
    }
    PetscCall(PCMGGetSmoother(np->mg, 1, &smooth));
    PetscCall(KSPSetOperators(smooth, np->Hn, np->Hn));
    PetscCall(PCMGGetCoarseSolve(np->mg, &coarse));
    PetscCall(KSPSetOperators(coarse, np->Ac, np->Ac));
    PetscCall(PCSetOperators(np->mg, np->Hn, np->Hn));
    PetscCall(PCSetUp(np->mg));
    PetscFunctionReturn(0);
  }
  PetscCall(PCSetOperators(np->gamg, np->Hn, np->Hn));
  PetscCall(PCSetUp(np->gamg));
  PetscCall(PCMGSetCycleType(np->gamg, np->cycle)); /* PCMG's levels exist once it is set up */
  PetscFunctionReturn(0);
}

static PetscErrorCode NodalPCApply(PC pc, Vec x, Vec y)
{
  NodalPC *np;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &np));
  PetscCall(VecScatterBegin(np->inject, x, np->xn, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(np->inject, x, np->xn, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(PCApply(np->mg ? np->mg : np->gamg, np->xn, np->yn));
  PetscCall(VecScatterBegin(np->inject, np->yn, y, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(np->inject, np->yn, y, INSERT_VALUES, SCATTER_REVERSE));
  PetscFunctionReturn(0);
}

static PetscErrorCode NodalPCView(PC pc, PetscViewer viewer)
{
  NodalPC *np;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &np));
  PetscCall(PetscViewerASCIIPrintf(viewer, "GAMG by nodes: the Hessian with every node's 3 components (constrained ones identity), block size 3:\n"));
  PetscCall(PetscViewerASCIIPushTab(viewer));
  if (np->mg) PetscCall(PetscViewerASCIIPrintf(viewer, "two levels: the nodes (Chebyshev), the cells' vertices (GAMG)\n"));
  PetscCall(PCView(np->mg ? np->mg : np->gamg, viewer));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(0);
}

static PetscErrorCode NodalPCDestroy(PC pc)
{
  NodalPC *np;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &np));
  PetscCall(PCDestroy(&np->gamg));
  PetscCall(PCDestroy(&np->mg));
  PetscCall(MatDestroy(&np->P));
  PetscCall(MatDestroy(&np->Ac));
  PetscCall(MatDestroy(&np->Hn));
  PetscCall(VecDestroy(&np->xn));
  PetscCall(VecDestroy(&np->yn));
  PetscCall(VecDestroy(&np->rowOf));
  PetscCall(VecScatterDestroy(&np->inject));
  PetscCall(MatNullSpaceDestroy(&np->nsp));
  PetscCall(PetscFree2(np->slot, np->row));
  PetscCall(PetscFree(np));
  PetscFunctionReturn(0);
}

/* The nodes of every body on this rank (all 3D), ordered by their first free
   row: np->slot, np->row, np->nrows; *ok false on every rank where a rank's
   rows are not all its nodes' (a 2D body, a node split between ranks,
   rows of no node). */
static PetscErrorCode NodalPCNumber(NodalPC *np, Mat H, PetscInt nbodies, Body bodies[], PetscBool *ok)
{
  PetscInt  rstart, rend, nn = 0, nstart, covered = 0, *idx, *key, *perm;
  PetscBool mine = PETSC_TRUE;
  MPI_Comm  comm = PetscObjectComm((PetscObject)H);

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(H, &rstart, &rend));
  for (PetscInt i = 0; i < nbodies; ++i) {
    PetscInt n;
    if (!BodyHasCells(bodies[i])) continue;
    if (BodyGetDimension(bodies[i]) != 3) mine = PETSC_FALSE;
    PetscCall(BodyGetOwnedNodeRows(bodies[i], rstart, rend, &n, NULL));
    nn += n;
  }
  PetscCall(PetscMalloc3(3 * nn + 1, &idx, nn + 1, &key, nn + 1, &perm));
  nn = 0;
  for (PetscInt i = 0; i < nbodies && mine; ++i) {
    PetscInt n;
    if (!BodyHasCells(bodies[i])) continue;
    PetscCall(BodyGetOwnedNodeRows(bodies[i], rstart, rend, &n, &idx[3 * nn]));
    nn += n;
  }
  for (PetscInt k = 0; k < nn && mine; ++k) {
    key[k]  = PETSC_MAX_INT;
    perm[k] = k;
    for (PetscInt d = 0; d < 3; ++d) {
      const PetscInt g = idx[3 * k + d];
      if (g < 0) continue;
      if (g < rstart || g >= rend) mine = PETSC_FALSE; /* a node split between ranks */
      key[k] = PetscMin(key[k], g);
      ++covered;
    }
  }
  if (covered != rend - rstart) mine = PETSC_FALSE;
  PetscCall(MPIU_Allreduce(&mine, ok, 1, MPIU_BOOL, MPI_LAND, comm));
  if (*ok) {
    PetscCall(PetscSortIntWithArray(nn, key, perm));
    np->nrows = 3 * nn;
    PetscCallMPI(MPI_Scan(&np->nrows, &nstart, 1, MPIU_INT, MPI_SUM, comm));
    nstart -= np->nrows;
    PetscCall(PetscMalloc2(np->nrows, &np->slot, rend - rstart, &np->row));
    for (PetscInt k = 0; k < nn; ++k)
      for (PetscInt d = 0; d < 3; ++d) {
        const PetscInt g = idx[3 * perm[k] + d];
        np->slot[3 * k + d] = g;
        if (g >= 0) np->row[g - rstart] = nstart + 3 * k + d;
      }
  }
  PetscCall(PetscFree3(idx, key, perm));
  PetscFunctionReturn(0);
}

/* The preconditioner of H as GAMG by nodes (above), near-nullspace the
   rigid modes on H's rows, modes[n]; *ok false (pc untouched) where a rank's
   rows are not whole 3D nodes. */
static PetscErrorCode NodalPCCreate(PC pc, Mat H, PetscInt nbodies, Body bodies[], PetscInt n, Vec modes[], PCMGCycleType cycle, PetscBool twolevel, PetscBool *ok)
{
  NodalPC    *np;
  MPI_Comm    comm = PetscObjectComm((PetscObject)H);
  Vec         x, nmodes[6 * CONTACT_MAX_BODIES];
  IS          is;
  PetscInt    rstart, rend;
  const char *prefix;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&np));
  PetscCall(NodalPCNumber(np, H, nbodies, bodies, ok));
  if (!*ok) {
    PetscCall(PetscFree(np));
    PetscFunctionReturn(0);
  }
  np->cycle = cycle;
  PetscCall(MatGetOwnershipRange(H, &rstart, &rend));
  PetscCall(VecCreateMPI(comm, np->nrows, PETSC_DETERMINE, &np->xn));
  PetscCall(VecSetBlockSize(np->xn, 3));
  PetscCall(VecZeroEntries(np->xn));
  PetscCall(VecDuplicate(np->xn, &np->yn));
  PetscCall(MatCreateVecs(H, &x, NULL));
  PetscCall(VecDuplicate(x, &np->rowOf));
  for (PetscInt i = rstart; i < rend; ++i) PetscCall(VecSetValue(np->rowOf, i, (PetscScalar)np->row[i - rstart], INSERT_VALUES));
  PetscCall(VecAssemblyBegin(np->rowOf));
  PetscCall(VecAssemblyEnd(np->rowOf));
  PetscCall(ISCreateGeneral(comm, rend - rstart, np->row, PETSC_USE_POINTER, &is));
  PetscCall(VecScatterCreate(x, NULL, np->xn, is, &np->inject));
  PetscCall(ISDestroy(&is));
  PetscCall(VecDestroy(&x));
  for (PetscInt k = 0; k < n; ++k) {
    PetscCall(VecDuplicate(np->xn, &nmodes[k]));
    PetscCall(VecZeroEntries(nmodes[k]));
    PetscCall(VecScatterBegin(np->inject, modes[k], nmodes[k], INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(np->inject, modes[k], nmodes[k], INSERT_VALUES, SCATTER_FORWARD));
  }
  PetscCall(MatNullSpaceCreate(comm, PETSC_FALSE, n, nmodes, &np->nsp));
  for (PetscInt k = 0; k < n; ++k) PetscCall(VecDestroy(&nmodes[k]));
  if (twolevel) { /* one rank only: the closures' vertices are all this rank's */
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(comm, &size));
    if (size == 1) PetscCall(NodalPCBuildInterpolation(np, H, nbodies, bodies));
  }
  PetscCall(PCCreate(comm, &np->gamg));
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCall(PCSetOptionsPrefix(np->gamg, prefix));
  PetscCall(PCSetType(np->gamg, PCGAMG));
  PetscCall(PCGAMGSetReuseInterpolation(np->gamg, PETSC_FALSE));
  PetscCall(PCGAMGSetNSmooths(np->gamg, 0));
  PetscCall(PCSetFromOptions(np->gamg));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, np));
  PetscCall(PCShellSetName(pc, "GAMG by nodes"));
  PetscCall(PCShellSetSetUp(pc, NodalPCSetUp));
  PetscCall(PCShellSetApply(pc, NodalPCApply));
  PetscCall(PCShellSetView(pc, NodalPCView));
  PetscCall(PCShellSetDestroy(pc, NodalPCDestroy));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactIterativeKSPSetUp(KSP ksp, Mat H, PetscInt nbodies, Body bodies[], PetscBool constant, const NewtonOptions *o)
{
  Vec           modes[6 * CONTACT_MAX_BODIES];
  PetscInt      n = 0, rstart, rend, dim = 2;
  MatNullSpace  nsp;
  PC            pc;
  PetscBool     nodal = o->iterativeNodal;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(H, &rstart, &rend));
  for (PetscInt i = 0; i < nbodies; ++i) {
    Vec          v[6];
    PetscScalar *a[6];
    PetscInt     first = n, nm;

    nm = BodyGetNumRigidModes(bodies[i]);
    if (!nm) continue; /* no dofs (a rigid body): its motion is the border's (forceborder.c) */
    dim = BodyGetDimension(bodies[i]);
    for (PetscInt k = 0; k < nm; ++k) {
      PetscCall(MatCreateVecs(H, &v[k], NULL));
      PetscCall(VecZeroEntries(v[k]));
      PetscCall(VecGetArray(v[k], &a[k]));
    }
    PetscCall(BodyAddRigidModes(bodies[i], rstart, rend, a));
    for (PetscInt k = 0; k < nm; ++k) PetscCall(VecRestoreArray(v[k], &a[k]));
    for (PetscInt k = 0; k < nm; ++k) { /* Gram-Schmidt within the body (bodies' modes are disjoint) */
      PetscReal norm;
      for (PetscInt j = first; j < n; ++j) {
        PetscScalar d;
        PetscCall(VecDot(v[k], modes[j], &d));
        PetscCall(VecAXPY(v[k], -d, modes[j]));
      }
      PetscCall(VecNorm(v[k], NORM_2, &norm));
      if (norm == 0.0) { /* a body without free dofs on the whole problem */
        PetscCall(VecDestroy(&v[k]));
        continue;
      }
      PetscCall(VecScale(v[k], 1.0 / norm));
      modes[n++] = v[k];
    }
  }
  PetscCall(MatNullSpaceCreate(PetscObjectComm((PetscObject)H), PETSC_FALSE, n, modes, &nsp));
  PetscCall(MatSetNearNullSpace(H, nsp));
  PetscCall(MatNullSpaceDestroy(&nsp));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetTolerances(ksp, constant ? 1e-9 : 1e-6, PETSC_DEFAULT, PETSC_DEFAULT, 10000));
  if (constant) PetscCall(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED)); /* the gradient Newton's step leaves: below 1e-9 of g0 */
  PetscCall(KSPGetPC(ksp, &pc));
  if (dim == 3 && nodal) PetscCall(NodalPCCreate(pc, H, nbodies, bodies, n, modes, o->iterativeCycle, o->iterativeTwoLevels, &nodal));
  else nodal = PETSC_FALSE;
  for (PetscInt k = 0; k < n; ++k) PetscCall(VecDestroy(&modes[k]));
  if (!nodal) {
    PetscCall(PCSetType(pc, PCGAMG));
    PetscCall(PCGAMGSetReuseInterpolation(pc, PETSC_FALSE));
    if (dim == 3) PetscCall(PCGAMGSetNSmooths(pc, 0));
  }
  PetscCall(KSPSetReusePreconditioner(ksp, constant));
  PetscFunctionReturn(0);
}
