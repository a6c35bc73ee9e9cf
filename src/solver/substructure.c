/* Newton steps through the Schur complement on the contact surfaces, on any
   number of ranks, by substructuring.

   The cells of each rank form its subdomain r, with dofs D_r (the
   unconstrained dofs of its cells, numbered as in the joined vector). A dof of
   several subdomains is an interface dof; the interface dofs that are not on a
   contact surface, G, and the contact-surface dofs c form the boundary
   B = G + c, and D_r = I_r + B_r with interior dofs I_r that belong to r
   alone (and are owned by r's rank: no other rank has them). The elastic
   stiffness is the sum of the subdomain stiffnesses K^r, each assembled from
   r's cells only,

       K = sum_r R_r^T K^r R_r,     K^r = [ K^r_II  K^r_IB ]
                                          [ K^r_BI  K^r_BB ],

   and eliminating every I_r leaves the boundary Schur complement

       S_B = sum_r R_Br^T S^r R_Br,     S^r = K^r_BB - K^r_BI (K^r_II)^-1 K^r_IB,

   each S^r computed on its own rank by MUMPS, sequentially: K^r factored with
   B_r as its Schur block (ICNTL(19)). Eliminating G from S_B (S_GG = L_G L_G^T)
   leaves the Schur complement of K on the contact surfaces

       S_K = S_cc - S_cG S_GG^-1 S_Gc = S_cc - W^T W,     W = L_G^-1 S_Gc,

   the matrix schur.c takes from one factorisation of K on one rank. All of
   this is done once per solve (K does not depend on u), and S_K is inverted
   once. The Hessian is H = K + C with C in the cc block only, so a Newton
   step H z = r is

     1. condensation, each rank: g^r = -K^r_BI (K^r_II)^-1 r_I (MUMPS, ICNTL(26) = 1),
        then g_B = r_B + sum_r R_Br^T g^r (one sum over ranks of |B| numbers);
     2. every rank, dense: y = L_G^-1 g_G,  (S_K + C_cc) z_c = g_c - W^T y,
        L_G^T z_G = y - W z_c;
     3. expansion, each rank: z_I = (K^r_II)^-1 (r_I - K^r_IB z_B) (ICNTL(26) = 2).

   r_I is read and z_I written where they are owned, with no communication.
   The bodies are coupled only by contact, so S_B, S_K and G = S_K^-1 are
   block diagonal by body: each body's block is summed onto one rank (body
   b on rank b mod size), eliminated and inverted there, and broadcast; with
   two bodies on two ranks the dense set-up work is split, not repeated, and
   a quarter of what one block of both surfaces would cost. Per step, with
   A the surface dofs the contact Hessian couples (the contact zone, a
   fraction of c), the surface system (S_K + C_cc) z_c = g_c is solved by
   the capacitance matrix: z_c = G (g_c - E_A C_AA z_A) with
   (I + G_AA C_AA) z_A = (G g_c)_A, an LU factorisation of order |A| on
   every rank (valid for the exact, indefinite contact Hessian too). The
   sparse work of a step is one forward and one backward substitution per
   subdomain, in parallel. MUMPS is called directly (dmumps_c): PETSc 3.18
   does not expose its condensation and expansion phases, and through
   MatSolve a step would cost two whole subdomain solves.

   The border of coupled force control (forceborder.c: H bordered by m
   constant columns B_k, B = K_fc 1) needs B^T H^-1 B at every Hessian and
   B^T H^-1 r_u and H^-1 (r_u - B dU) at every step. Eliminating I, then G,
   from a symmetric H gives for any a, b

       a^T H^-1 b = a_I^T K_II^-1 b_I + y(a)^T y(b) + t(a)^T (S_K + C_cc)^-1 t(b),

   with y = L_G^-1 g_G and t = g_c - W^T y the right side condensed onto
   the surfaces (step 2). Of B_k's, only the last term depends on C: so
   once (SubBorderSetColumns, m condensations and expansions with z_B = 0)
   y_k, t_k, v_k = S_K^-1 t_k, X_k = K_II^-1 B_k,I (zero on B) and
   Q_lk = B_l^T X_k + y_l^T y_k are kept, and per Hessian
   (SubBorderGetCoupling) Zc_k = (S_K + C_cc)^-1 t_k is v_k corrected by the
   capacitance solve (nA^2 + nA nc each) and B_l^T H^-1 B_k = Q_lk +
   t_l^T Zc_k: no sparse work at all. Per step (SubBorderCondense) r_u is
   condensed and its surface solve w_c made, which gives B_k^T H^-1 r_u =
   X_k^T r_u + y_k^T y(r_u) + t_k^T w_c; and once dU is known
   (SubBorderExpand), by linearity the boundary of H^-1 (r_u - B dU) solves
   with y(r_u) - sum dU_k y_k and z_c = w_c - sum dU_k Zc_k, and its interior
   is K_II^-1 (r_I - K_IB z_B) - sum dU_k X_k: r_u's own expansion less the
   kept X_k. One condensation and one expansion a step, what one solve of H
   costs, where eliminating by m solves cost m + 1. On several ranks X_k^T
   r_u is one more sum over ranks of m numbers. */
#include "substructure.h"
#include "denselu.h"
#include <petscblaslapack.h>
#include <dmumps_c.h>
#include <petsc/private/petscimpl.h> /* PetscUseMethod */

#define ICNTL(i) icntl[(i) - 1]
#define INFOG(i) infog[(i) - 1]

/* One body's part of the boundary: its interface dofs G_b and surface dofs
   c_b (positions in B), the factor L_G of its S_GG, W = L_G^-1 S_Gc and
   Ginv = S_K^-1 (full), all on every rank. */
typedef struct {
  PetscInt     nG, nc;
  PetscInt    *G, *c;
  PetscScalar *LG, *W, *Ginv;
  PetscScalar *y; /* [nG] work */
} SubBody;

/* The border of coupled force control's step (SubBorder* below): its m
   constant columns B_k condensed once, and their surface solves of the
   current step. */
typedef struct {
  PetscInt     m;         /* columns; 0: none set */
  PetscScalar *red;       /* [m nB] y_k = L_G^-1 g_G(B_k) on G, t_k = g_c - W^T y_k on c */
  PetscScalar *v;         /* [m nc] S_K^-1 t_k */
  PetscScalar *X;         /* [m nI] (K^r_II)^-1 B_k,I on this rank's interior dofs */
  PetscScalar *Q;         /* [m m] B_l,I^T K_II^-1 B_k,I + y_l^T y_k, on every rank */
  PetscScalar *Zc;        /* [m nc] (S_K + C_cc)^-1 t_k, this step's */
  PetscScalar *xr;        /* [m] work */
  PetscBool    condensed; /* gB, zc and MUMPS hold a right side's first half (SubBorderCondense) */
} SubBorder;

typedef struct {
  MPI_Comm comm, self; /* self: MUMPS's communicator, a duplicate of MPI_COMM_SELF */
  PetscInt rstart;     /* first row of this rank in the joined vector */
  /* the subdomain */
  PetscInt       nD, nI, nBr;
  PetscInt      *D;          /* [nD] joined-vector index of each subdomain dof, sorted */
  PetscInt      *Iloc;       /* [nI] interior dofs: positions in D */
  PetscInt      *Bloc, *Bpos; /* [nBr] boundary dofs: positions in D and in B */
  PetscScalar   *rhs, *red;  /* [nD] right-hand side, then solution; [nBr] reduced right-hand side */
  DMUMPS_STRUC_C mumps;
  PetscBool      hasMumps;
  /* the boundary B = G + c, on every rank; the bodies are coupled only by
     contact, so S_B, S_K and everything dense is block diagonal by body */
  PetscInt      nG, nc, nB;
  PetscInt      nOwned;              /* boundary dofs owned by this rank */
  PetscInt     *ownedPos, *ownedRow; /* their positions in B and rows in this rank's part of X */
  PetscInt     *bBody, *bLocal;      /* [nB] body of each boundary dof, its position in the body's [G_b; c_b] */
  PetscInt      nbodies;
  SubBody       body[CONTACT_MAX_BODIES];
  PetscScalar  *gB, *zc, *tmp;       /* [nB] g_B, then z_B; [nc] z_c; [2 nc] work */
  IS            isc;
  const PetscInt *surf; /* the contact-surface dofs (isc's indices, sorted) */
  Mat           K;      /* the stiffness: C = H - K on the surface rows */
  /* the contact Hessian of the current step: its entries, its support A */
  PetscInt      nC, nA, capC, capA;
  PetscInt     *Ci, *Cj;  /* [nC] positions in A */
  PetscScalar  *Cv;       /* [nC] */
  PetscInt     *A, *inA;  /* [nA] positions in c; [nc] position in A or -1 */
  PetscScalar  *MA, *GAA, *tA; /* [nA x nA] LU of I + G_AA C_AA; G_AA; [nA] work */
  PetscBLASInt *ipiv;
  PetscInt      splitLU;  /* on several ranks, from this |A| on (-newton_schur_split_lu), */
  DenseLU       lu;       /* I + G_AA C_AA factored in parts (denselu.c) */
  SubBorder     border;
} SubCtx;


static PetscLogEvent SubFactor = 0, SubInterface, SubStep, SubSolve, SubBorderCols, SubBorderStep, SubBorderSolve;
/* the phases of SubstrInterface (S_B's blocks summed, eliminated, broadcast) and of SubstrStep (C gathered, the capacitance matrix formed, factored) */
static PetscLogEvent SubIfSum, SubIfDense, SubIfBcast, SubCapGather, SubCapForm, SubCapFactor;

static PetscErrorCode SubMumps(SubCtx *ctx, MUMPS_INT job)
{
  PetscFunctionBeginUser;
  ctx->mumps.job = job;
  dmumps_c(&ctx->mumps);
  PetscCheck(ctx->mumps.INFOG(1) >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "MUMPS on a subdomain (job %d): INFOG(1) = %d, INFOG(2) = %d", (int)job, (int)ctx->mumps.INFOG(1), (int)ctx->mumps.INFOG(2));
  PetscFunctionReturn(0);
}

/* The body of each boundary dof (G[] then the surface dofs, joined-vector
   indices): the body whose block of its owner's rows holds it (every rank
   knows every rank's row range and body offsets); each body's lists G_b,
   c_b of positions in B, and each boundary dof's position in its body's
   [G_b; c_b]. */
static PetscErrorCode SubSetUpBodies(SubCtx *ctx, PetscInt nb, const PetscInt offset[], const PetscInt G[], const PetscInt surf[])
{
  const PetscInt *ranges;
  PetscInt       *offs;
  PetscMPIInt     size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCall(MatGetOwnershipRanges(ctx->K, &ranges));
  PetscCall(PetscMalloc1(size * nb, &offs));
  PetscCallMPI(MPI_Allgather(offset, (PetscMPIInt)nb, MPIU_INT, offs, (PetscMPIInt)nb, MPIU_INT, ctx->comm));
  ctx->nbodies = nb;
  PetscCall(PetscMalloc2(ctx->nB, &ctx->bBody, ctx->nB, &ctx->bLocal));
  for (PetscInt k = 0; k < ctx->nB; ++k) {
    const PetscInt g = k < ctx->nG ? G[k] : surf[k - ctx->nG];
    PetscMPIInt    q = 0;
    PetscInt       b = 0;

    while (g >= ranges[q + 1]) ++q;
    while (b + 1 < nb && g - ranges[q] >= offs[q * nb + b + 1]) ++b;
    ctx->bBody[k] = b;
    if (k < ctx->nG) ctx->body[b].nG++;
    else ctx->body[b].nc++;
  }
  PetscCall(PetscFree(offs));
  for (PetscInt b = 0; b < nb; ++b) {
    SubBody *B = &ctx->body[b];
    PetscCall(PetscMalloc3(B->nG + 1, &B->G, B->nc + 1, &B->c, B->nG + 1, &B->y));
    B->nG = B->nc = 0;
  }
  for (PetscInt k = 0; k < ctx->nB; ++k) {
    SubBody *B = &ctx->body[ctx->bBody[k]];
    if (k < ctx->nG) {
      ctx->bLocal[k]  = B->nG;
      B->G[B->nG++] = k;
    } else B->c[B->nc++] = k;
  }
  for (PetscInt k = ctx->nG; k < ctx->nB; ++k) { /* c_b after G_b in the body's ordering */
    SubBody *B = &ctx->body[ctx->bBody[k]];
    PetscInt j;
    PetscCall(PetscFindInt(k, B->nc, B->c, &j));
    ctx->bLocal[k] = B->nG + j;
  }
  PetscFunctionReturn(0);
}

/* D_r, its interior and boundary parts, the interface G (gathered on every
   rank, sorted) and the positions of the boundary dofs in B. A dof is on the
   interface if another subdomain has it: it is a ghost here, or the sum over
   ranks of the subdomains holding it exceeds one. */
static PetscErrorCode SubSetUpDofs(SubCtx *ctx, Subdomain sub, PetscInt nbodies, const PetscInt offset[])
{
  PetscInt           n = 0, rend, nsurf, ngown = 0, nI = 0, nBr = 0, nOwned = 0;
  const PetscInt    *surf;
  PetscInt          *gown, *onB;
  PetscScalar       *ones;
  const PetscScalar *cnt;
  Vec                count;
  PetscMPIInt        size, ngownm, *counts, *displs;

  PetscFunctionBeginUser;
  if (sub) { /* several ranks: the subdomain's dofs */
    n = sub->n;
    PetscCall(PetscMalloc1(n + 1, &ctx->D));
    PetscCall(PetscArraycpy(ctx->D, sub->dofs, n));
  } else { /* one rank: the whole joined vector */
    PetscCall(MatGetSize(ctx->K, &n, NULL));
    PetscCall(PetscMalloc1(n + 1, &ctx->D));
    for (PetscInt k = 0; k < n; ++k) ctx->D[k] = k;
  }
  ctx->nD = n;

  PetscCall(MatCreateVecs(ctx->K, &count, NULL));
  PetscCall(VecZeroEntries(count));
  PetscCall(PetscMalloc1(n + 1, &ones));
  for (PetscInt k = 0; k < n; ++k) ones[k] = 1.0;
  PetscCall(VecSetValues(count, n, ctx->D, ones, ADD_VALUES));
  PetscCall(PetscFree(ones));
  PetscCall(VecAssemblyBegin(count));
  PetscCall(VecAssemblyEnd(count));
  PetscCall(MatGetOwnershipRange(ctx->K, &ctx->rstart, &rend));
  PetscCall(ISGetLocalSize(ctx->isc, &nsurf));
  surf = ctx->surf;
  PetscCall(PetscMalloc2(n + 1, &onB, n + 1, &gown));
  PetscCall(VecGetArrayRead(count, &cnt));
  for (PetscInt k = 0; k < n; ++k) {
    const PetscInt  g     = ctx->D[k];
    const PetscBool owned = (PetscBool)(g >= ctx->rstart && g < rend);
    const PetscBool shared = (PetscBool)(!owned || PetscRealPart(cnt[g - ctx->rstart]) > 1.5);
    PetscInt        loc;

    PetscCall(PetscFindInt(g, nsurf, surf, &loc));
    onB[k] = shared || loc >= 0;
    if (owned && shared && loc < 0) gown[ngown++] = g;
    nBr += onB[k];
    nOwned += onB[k] && owned;
  }
  PetscCall(VecRestoreArrayRead(count, &cnt));
  PetscCall(VecDestroy(&count));

  /* G on every rank: each interface dof is owned by one rank, and the ranks'
     rows ascend, so the concatenation is sorted */
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCall(PetscMalloc2(size, &counts, size + 1, &displs));
  PetscCall(PetscMPIIntCast(ngown, &ngownm));
  PetscCallMPI(MPI_Allgather(&ngownm, 1, MPI_INT, counts, 1, MPI_INT, ctx->comm));
  displs[0] = 0;
  for (PetscMPIInt q = 0; q < size; ++q) displs[q + 1] = displs[q] + counts[q];
  ctx->nG = displs[size];
  ctx->nc = nsurf;
  ctx->nB = ctx->nG + ctx->nc;
  {
    PetscInt *G;
    PetscCall(PetscMalloc1(ctx->nG + 1, &G));
    PetscCallMPI(MPI_Allgatherv(gown, ngownm, MPIU_INT, G, counts, displs, MPIU_INT, ctx->comm));

    nI = n - nBr;
    ctx->nI = nI;
    ctx->nBr = nBr;
    ctx->nOwned = nOwned;
    PetscCall(PetscMalloc3(nI + 1, &ctx->Iloc, nBr + 1, &ctx->Bloc, nBr + 1, &ctx->Bpos));
    PetscCall(PetscMalloc2(nOwned + 1, &ctx->ownedPos, nOwned + 1, &ctx->ownedRow));
    nI = nBr = nOwned = 0;
    for (PetscInt k = 0; k < n; ++k) {
      const PetscInt g = ctx->D[k];
      PetscInt       pos;

      if (!onB[k]) {
        ctx->Iloc[nI++] = k;
        continue;
      }
      PetscCall(PetscFindInt(g, ctx->nG, G, &pos));
      if (pos < 0) {
        PetscCall(PetscFindInt(g, nsurf, surf, &pos));
        pos += ctx->nG;
      }
      ctx->Bloc[nBr]   = k;
      ctx->Bpos[nBr++] = pos;
      if (g >= ctx->rstart && g < rend) {
        ctx->ownedPos[nOwned]   = pos;
        ctx->ownedRow[nOwned++] = g - ctx->rstart;
      }
    }
    PetscCall(SubSetUpBodies(ctx, nbodies, offset, G, surf));
    PetscCall(PetscFree(G));
  }
  PetscCall(PetscFree2(counts, displs));
  PetscCall(PetscFree2(onB, gown));
  PetscCall(PetscMalloc2(ctx->nD + 1, &ctx->rhs, ctx->nBr + 1, &ctx->red));
  PetscFunctionReturn(0);
}

/* S^r (nBr x nBr, column-major; its lower triangle is set). MUMPS factors K^r
   (its upper triangle less explicit zeros; SPD: the interior block of a
   subdomain is held by the boundary or by Dirichlet conditions) with B_r as
   the Schur block. Without interior dofs S^r is K^r itself. */
static PetscErrorCode SubFactorSubdomain(SubCtx *ctx, Mat Kr, PetscScalar Sr[])
{
  const PetscInt    *ia, *ja;
  const PetscScalar *v;
  PetscInt           n;
  PetscBool          done;

  PetscFunctionBeginUser;
  PetscCall(MatGetRowIJ(Kr, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_LIB, "MatGetRowIJ failed on the subdomain stiffness");
  PetscCall(MatSeqAIJGetArrayRead(Kr, &v));
  if (!ctx->nI) {
    for (PetscInt i = 0; i < n; ++i)
      for (PetscInt k = ia[i]; k < ia[i + 1]; ++k) Sr[i * n + ja[k]] = v[k];
  } else {
    MUMPS_INT   *irn, *jcn;
    PetscScalar *a;
    PetscInt     nz = 0;

    for (PetscInt i = 0; i < n; ++i)
      for (PetscInt k = ia[i]; k < ia[i + 1]; ++k) nz += ja[k] == i || (ja[k] > i && v[k] != 0.0);
    PetscCall(PetscMalloc3(nz, &irn, nz, &jcn, nz, &a));
    nz = 0;
    for (PetscInt i = 0; i < n; ++i)
      for (PetscInt k = ia[i]; k < ia[i + 1]; ++k)
        if (ja[k] == i || (ja[k] > i && v[k] != 0.0)) {
          irn[nz]  = (MUMPS_INT)(i + 1);
          jcn[nz]  = (MUMPS_INT)(ja[k] + 1);
          a[nz++] = v[k];
        }
    PetscCallMPI(MPI_Comm_dup(PETSC_COMM_SELF, &ctx->self));
    ctx->mumps.comm_fortran = (MUMPS_INT)MPI_Comm_c2f(ctx->self);
    ctx->mumps.par          = 1;
    ctx->mumps.sym          = 1;
    PetscCall(SubMumps(ctx, -1));
    ctx->hasMumps         = PETSC_TRUE;
    ctx->mumps.ICNTL(1)   = -1; /* errors are read from INFOG and reported by PETSc */
    ctx->mumps.ICNTL(2)   = -1;
    ctx->mumps.ICNTL(3)   = -1;
    ctx->mumps.ICNTL(4)   = 0;
    ctx->mumps.n          = (MUMPS_INT)n;
    ctx->mumps.nnz        = (MUMPS_INT8)nz;
    ctx->mumps.irn        = irn;
    ctx->mumps.jcn        = jcn;
    ctx->mumps.a          = a;
    if (ctx->nBr) {
      PetscCall(PetscMalloc1(ctx->nBr, &ctx->mumps.listvar_schur));
      for (PetscInt k = 0; k < ctx->nBr; ++k) ctx->mumps.listvar_schur[k] = (MUMPS_INT)(ctx->Bloc[k] + 1);
      ctx->mumps.ICNTL(19)  = 2; /* the lower triangle, by columns */
      ctx->mumps.size_schur = (MUMPS_INT)ctx->nBr;
      ctx->mumps.schur_lld  = (MUMPS_INT)ctx->nBr;
      ctx->mumps.schur      = Sr;
    }
    /* analysis, then factorisation; MUMPS's workspace estimate can fall short
       (INFOG(1) = -8, -9: small subdomains whose boundary is most of them),
       so the relaxation ICNTL(14) is doubled and the factorisation redone. A
       rank's failure is reported on every rank (ContactSubstructurePCSetUp). */
    ctx->mumps.job = 1;
    dmumps_c(&ctx->mumps);
    for (PetscInt attempt = 0; ctx->mumps.INFOG(1) >= 0 && attempt < 8; ++attempt) {
      ctx->mumps.job = 2;
      dmumps_c(&ctx->mumps);
      if (ctx->mumps.INFOG(1) != -8 && ctx->mumps.INFOG(1) != -9) break;
      PetscCall(PetscInfo(NULL, "MUMPS workspace too small (INFOG(1) = %d): ICNTL(14) %d -> %d\n", (int)ctx->mumps.INFOG(1), (int)ctx->mumps.ICNTL(14), (int)(2 * ctx->mumps.ICNTL(14))));
      ctx->mumps.INFOG(1) = 0;
      ctx->mumps.ICNTL(14) *= 2;
    }
    PetscCall(PetscFree3(irn, jcn, a));
    ctx->mumps.irn = ctx->mumps.jcn = NULL;
    ctx->mumps.a   = NULL;
    ctx->mumps.schur = NULL;
    PetscCall(PetscLogFlops(ctx->mumps.rinfog[2]));
    PetscCall(PetscInfo(NULL, "subdomain factor: %lld entries, %g flops (ordering %d)\n", (long long)ctx->mumps.INFOG(29), (double)ctx->mumps.rinfog[2], (int)ctx->mumps.INFOG(7)));
  }
  PetscCall(MatSeqAIJRestoreArrayRead(Kr, &v));
  PetscCall(MatRestoreRowIJ(Kr, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscFunctionReturn(0);
}

/* Where entry (r, t) of body b's block of S_B (positions in its [G_b; c_b],
   r >= t or r < nG <= t) is kept in the block's packed array: only what the
   root reads, column by column: in a column t of G_b its rows t..nG-1 (L_G's
   lower triangle), in a column t of c_b its rows in G_b (S_Gc) and t..nb-1
   (S_cc's lower triangle); about half of the nb^2 numbers. off[t]: column
   t's start. */
static inline PetscInt SubPacked(const PetscInt off[], PetscInt nG, PetscInt r, PetscInt t)
{
  return off[t] + (t < nG ? r - t : (r < nG ? r : nG + r - t));
}

/* Each body's block of S_B, summed over ranks onto the rank that owns the
   body's dense work (body b on rank b mod size), where its interface is
   eliminated (L_G, W, S_K) and S_K inverted (potrf, potri); the results are
   then broadcast to every rank. The blocks are independent: no redundant
   dense work while there are at least as many bodies as ranks. Each entry
   of S^r (its lower triangle) is added once, where the root reads it
   (SubPacked): the interface-surface pairs as S_Gc (row in G, column in
   c), the others in the lower triangle; the sums are those of the whole
   block's, in half its memory and messages. S^r is freed once summed. */
static PetscErrorCode SubCondenseInterface(SubCtx *ctx, PetscScalar **Srp)
{
  const PetscScalar *Sr = *Srp;
  const PetscInt    nBr = ctx->nBr;
  PetscScalar      *SB[CONTACT_MAX_BODIES];
  PetscInt         *off[CONTACT_MAX_BODIES];
  PetscMPIInt       rank, size;
  const PetscScalar one = 1.0, mone = -1.0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCall(PetscLogEventBegin(SubIfSum, 0, 0, 0, 0));
  for (PetscInt b = 0; b < ctx->nbodies; ++b) {
    const PetscInt nG = ctx->body[b].nG, nb = nG + ctx->body[b].nc;
    PetscCall(PetscMalloc1(nb + 1, &off[b]));
    off[b][0] = 0;
    for (PetscInt t = 0; t < nb; ++t) off[b][t + 1] = off[b][t] + (t < nG ? nG - t : nG + nb - t);
    PetscCall(PetscCalloc1(off[b][nb] + 1, &SB[b]));
  }
  for (PetscInt j = 0; j < nBr; ++j)
    for (PetscInt i = j; i < nBr; ++i) {
      const PetscScalar s  = Sr[j * nBr + i];
      const PetscInt    bi = ctx->Bpos[i], bj = ctx->Bpos[j], b = ctx->bBody[bi];
      const PetscInt    nG = ctx->body[b].nG, li = ctx->bLocal[bi], lj = ctx->bLocal[bj];
      const PetscInt    lo = PetscMin(li, lj), hi = PetscMax(li, lj);

      if (ctx->bBody[bj] != b) continue; /* the bodies' stiffnesses do not couple */
      if (lo < nG && hi >= nG) SB[b][SubPacked(off[b], nG, lo, hi)] += s;
      else SB[b][SubPacked(off[b], nG, hi, lo)] += s;
    }
  PetscCall(PetscFree(*Srp));
  for (PetscInt b = 0; b < ctx->nbodies; ++b) { /* every body's block onto its root first, */
    const PetscInt    len0 = off[b][ctx->body[b].nG + ctx->body[b].nc];
    const PetscMPIInt root = (PetscMPIInt)(b % size);
    for (PetscInt o = 0; o < len0; o += PETSC_MPI_INT_MAX / 2) {
      PetscMPIInt len;
      PetscCall(PetscMPIIntCast(PetscMin(len0 - o, PETSC_MPI_INT_MAX / 2), &len));
      PetscCallMPI(MPI_Reduce(rank == root ? MPI_IN_PLACE : SB[b] + o, SB[b] + o, len, MPIU_SCALAR, MPIU_SUM, root, ctx->comm));
    }
    if (rank != root) PetscCall(PetscFree(SB[b])); /* sent: the memory's peak is the roots' */
  }
  PetscCall(PetscLogEventEnd(SubIfSum, 0, 0, 0, 0));
  PetscCall(PetscLogEventBegin(SubIfDense, 0, 0, 0, 0));
  for (PetscInt b = 0; b < ctx->nbodies; ++b) { /* then the roots work at once, */
    SubBody       *B  = &ctx->body[b];
    const PetscInt nG = B->nG, nc = B->nc;
    PetscBLASInt   bG, bc, info;

    PetscCall(PetscInfo(NULL, "body %" PetscInt_FMT ": %" PetscInt_FMT " interface and %" PetscInt_FMT " surface dofs, dense work on rank %d\n", b, nG, nc, (int)(b % size)));

    PetscCall(PetscMalloc3(nG * nG + 1, &B->LG, nG * nc + 1, &B->W, nc * nc + 1, &B->Ginv));
    if (rank == (PetscMPIInt)(b % size)) {
      PetscCall(PetscBLASIntCast(nG, &bG));
      PetscCall(PetscBLASIntCast(nc, &bc));
      PetscCall(PetscArrayzero(B->LG, nG * nG)); /* its upper triangle unread */
      for (PetscInt j = 0; j < nG; ++j) PetscCall(PetscArraycpy(B->LG + j * nG + j, SB[b] + off[b][j], nG - j));
      for (PetscInt j = 0; j < nc; ++j) {
        PetscCall(PetscArraycpy(B->W + j * nG, SB[b] + off[b][nG + j], nG));
        PetscCall(PetscArraycpy(B->Ginv + j * nc + j, SB[b] + off[b][nG + j] + nG, nc - j)); /* its upper triangle set after potri */
      }
      PetscCall(PetscFree(SB[b]));
      if (nG) {
        PetscCallBLAS("LAPACKpotrf", LAPACKpotrf_("L", &bG, B->LG, &bG, &info));
        PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "interface Schur complement not positive definite (potrf info %d)", (int)info);
        if (nc) {
          PetscCallBLAS("BLAStrsm", BLAStrsm_("L", "L", "N", "N", &bG, &bc, &one, B->LG, &bG, B->W, &bG));
          PetscCallBLAS("BLASsyrk", BLASsyrk_("L", "T", &bc, &bG, &mone, B->W, &bG, &one, B->Ginv, &bc));
        }
        PetscCall(PetscLogFlops((double)nG * nG * nG / 3.0 + (double)nG * nG * nc + (double)nc * nc * nG));
      }
      if (nc) {
        PetscCallBLAS("LAPACKpotrf", LAPACKpotrf_("L", &bc, B->Ginv, &bc, &info));
        PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "Schur complement of the stiffness on the contact surfaces not positive definite (potrf info %d)", (int)info);
        PetscCallBLAS("LAPACKpotri", LAPACKpotri_("L", &bc, B->Ginv, &bc, &info));
        PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "potri info %d", (int)info);
        for (PetscInt j = 0; j < nc; ++j)
          for (PetscInt i = j + 1; i < nc; ++i) B->Ginv[i * nc + j] = B->Ginv[j * nc + i];
        PetscCall(PetscLogFlops((double)nc * nc * nc));
      }
    }
  }
  PetscCall(PetscLogEventEnd(SubIfDense, 0, 0, 0, 0));
  PetscCall(PetscLogEventBegin(SubIfBcast, 0, 0, 0, 0));
  for (PetscInt b = 0; b < ctx->nbodies; ++b) { /* and every rank receives every body's */
    SubBody          *B    = &ctx->body[b];
    const PetscMPIInt root = (PetscMPIInt)(b % size);
    PetscMPIInt       n[3];
    PetscCall(PetscMPIIntCast(B->nG * B->nG, &n[0]));
    PetscCall(PetscMPIIntCast(B->nG * B->nc, &n[1]));
    PetscCall(PetscMPIIntCast(B->nc * B->nc, &n[2]));
    PetscCallMPI(MPI_Bcast(B->LG, n[0], MPIU_SCALAR, root, ctx->comm));
    PetscCallMPI(MPI_Bcast(B->W, n[1], MPIU_SCALAR, root, ctx->comm));
    PetscCallMPI(MPI_Bcast(B->Ginv, n[2], MPIU_SCALAR, root, ctx->comm));
  }
  for (PetscInt b = 0; b < ctx->nbodies; ++b) PetscCall(PetscFree(off[b]));
  PetscCall(PetscLogEventEnd(SubIfBcast, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The entries of the contact Hessian, C = H - K on the surface block (H's
   pattern K's, or more where a term left its own: matched by column), from the rows this rank owns, gathered on
   every rank in rank order; A, the surface dofs they couple. */
static PetscErrorCode SubGatherContactHessian(SubCtx *ctx, Mat H)
{
  PetscInt     rstart, rend, n = 0, cap = 16, nall;
  PetscInt    *ij, *kc = NULL;
  PetscScalar *v, *kv = NULL;
  PetscInt     kcap = 0;
  PetscMPIInt  size, nm, *counts, *displs;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(H, &rstart, &rend));
  PetscCall(PetscMalloc2(2 * cap, &ij, cap, &v));
  for (PetscInt r = 0; r < ctx->nc; ++r) {
    const PetscInt     g = ctx->surf[r];
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscInt           nk, nh, nkept, at = 0;

    if (g < rstart || g >= rend) continue;
    PetscCall(MatGetRow(ctx->K, g, &nk, &cols, &vals));
    if (nk > kcap) {
      PetscCall(PetscFree2(kc, kv));
      kcap = nk;
      PetscCall(PetscMalloc2(kcap, &kc, kcap, &kv));
    }
    PetscCall(PetscArraycpy(kc, cols, nk));
    PetscCall(PetscArraycpy(kv, vals, nk));
    nkept = nk;
    PetscCall(MatRestoreRow(ctx->K, g, &nk, &cols, &vals)); /* zeroes nk */
    nk = nkept;
    PetscCall(MatGetRow(H, g, &nh, &cols, &vals));
    for (PetscInt k = 0; k < nh; ++k) { /* both rows sorted; H's a superset where a term left its pattern (problem.c) */
      PetscScalar c;
      PetscInt    pos;
      while (at < nk && kc[at] < cols[k]) ++at;
      c = vals[k] - (at < nk && kc[at] == cols[k] ? kv[at] : 0.0);

      if (c == 0.0) continue;
      PetscCall(PetscFindInt(cols[k], ctx->nc, ctx->surf, &pos));
      PetscCheck(pos >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the contact Hessian couples dof %" PetscInt_FMT " with %" PetscInt_FMT ", outside the contact surfaces", g, cols[k]);
      if (n == cap) {
        PetscInt    *ij2;
        PetscScalar *v2;
        PetscCall(PetscMalloc2(4 * cap, &ij2, 2 * cap, &v2));
        PetscCall(PetscArraycpy(ij2, ij, 2 * n));
        PetscCall(PetscArraycpy(v2, v, n));
        PetscCall(PetscFree2(ij, v));
        ij = ij2;
        v  = v2;
        cap *= 2;
      }
      ij[2 * n]     = r;
      ij[2 * n + 1] = pos;
      v[n++]        = c;
    }
    PetscCall(MatRestoreRow(H, g, &nh, &cols, &vals));
  }
  PetscCall(PetscFree2(kc, kv));

  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCall(PetscMalloc2(size, &counts, size + 1, &displs));
  PetscCall(PetscMPIIntCast(n, &nm));
  PetscCallMPI(MPI_Allgather(&nm, 1, MPI_INT, counts, 1, MPI_INT, ctx->comm));
  displs[0] = 0;
  for (PetscMPIInt q = 0; q < size; ++q) displs[q + 1] = displs[q] + counts[q];
  nall = displs[size];
  if (nall > ctx->capC) {
    PetscCall(PetscFree3(ctx->Ci, ctx->Cj, ctx->Cv));
    ctx->capC = nall;
    PetscCall(PetscMalloc3(nall, &ctx->Ci, nall, &ctx->Cj, nall, &ctx->Cv));
  }
  ctx->nC = nall;
  PetscCallMPI(MPI_Allgatherv(v, nm, MPIU_SCALAR, ctx->Cv, counts, displs, MPIU_SCALAR, ctx->comm));
  for (PetscMPIInt q = 0; q <= size; ++q) {
    if (q < size) counts[q] *= 2;
    displs[q] *= 2;
  }
  {
    PetscInt *all;
    PetscCall(PetscMalloc1(2 * nall + 1, &all));
    PetscCallMPI(MPI_Allgatherv(ij, 2 * nm, MPIU_INT, all, counts, displs, MPIU_INT, ctx->comm));
    for (PetscInt k = 0; k < ctx->nc; ++k) ctx->inA[k] = -1;
    ctx->nA = 0;
    for (PetscInt k = 0; k < 2 * nall; ++k) ctx->inA[all[k]] = 0;
    for (PetscInt k = 0; k < ctx->nc; ++k)
      if (!ctx->inA[k]) {
        ctx->inA[k]        = ctx->nA;
        ctx->A[ctx->nA++] = k;
      }
    for (PetscInt k = 0; k < nall; ++k) {
      ctx->Ci[k] = ctx->inA[all[2 * k]];
      ctx->Cj[k] = ctx->inA[all[2 * k + 1]];
    }
    PetscCall(PetscFree(all));
  }
  PetscCall(PetscFree2(counts, displs));
  PetscCall(PetscFree2(ij, v));
  PetscFunctionReturn(0);
}

/* Columns cols[0..ncols-1] of I + G_AA C_AA into M (nA x ncols, by columns):
   column j is e_j plus C_kj times column k of G_AA over the entries of C
   in column j, added in the order they were gathered. G_AA (nA^2 numbers,
   90 MB at |A| = 3,300) is far larger than the caches and C has some 300
   entries a column, so entry by entry every column of G_AA came from
   memory again (1e6 entries: 25 GB read a step, 85 % of the step on one
   rank). Here the rows go by blocks of SUB_FORM_ROWS: a block of G_AA
   (|A| SUB_FORM_ROWS numbers, 3 MB) stays in cache while every entry
   reads its piece of it, the entries copied first in column order so that
   each pass reads them in sequence. The same sums in the same order: the
   same matrix. loc: [nA] work. */
#define SUB_FORM_ROWS 128
#if defined(__GNUC__) && !defined(__clang__)
__attribute__((optimize("tree-vectorize"))) /* the axpy below in vectors (-O2 leaves it scalar); a multiply then an add, as scalar: the same bits */
#endif
static PetscErrorCode SubCapacitanceColumns(SubCtx *ctx, PetscInt ncols, const PetscInt cols[], PetscInt loc[], PetscScalar M[])
{
  const PetscInt nA = ctx->nA;
  PetscInt      *start, *ci, n = 0;
  PetscScalar   *cv;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < nA; ++j) loc[j] = -1;
  for (PetscInt l = 0; l < ncols; ++l) loc[cols[l]] = l;
  for (PetscInt k = 0; k < ctx->nC; ++k) n += loc[ctx->Cj[k]] >= 0;
  PetscCall(PetscMalloc3(ncols + 1, &start, n + 1, &ci, n + 1, &cv));
  PetscCall(PetscArrayzero(start, ncols + 1));
  for (PetscInt k = 0; k < ctx->nC; ++k)
    if (loc[ctx->Cj[k]] >= 0) start[loc[ctx->Cj[k]] + 1]++;
  for (PetscInt l = 0; l < ncols; ++l) start[l + 1] += start[l];
  for (PetscInt k = 0; k < ctx->nC; ++k) /* by column, each column's entries in their order, read in sequence below */
    if (loc[ctx->Cj[k]] >= 0) {
      const PetscInt q = start[loc[ctx->Cj[k]]]++;
      ci[q]            = ctx->Ci[k];
      cv[q]            = ctx->Cv[k];
    }
  for (PetscInt l = ncols; l > 0; --l) start[l] = start[l - 1];
  start[0] = 0;
  PetscCall(PetscArrayzero(M, nA * ncols));
  for (PetscInt l = 0; l < ncols; ++l) M[l * nA + cols[l]] = 1.0;
  for (PetscInt r0 = 0; r0 < nA; r0 += SUB_FORM_ROWS) {
    const PetscInt r1 = PetscMin(nA, r0 + SUB_FORM_ROWS);
    for (PetscInt l = 0; l < ncols; ++l) {
      PetscScalar *PETSC_RESTRICT col = M + l * nA;
      for (PetscInt q = start[l]; q < start[l + 1]; ++q) {
        const PetscScalar *PETSC_RESTRICT ga = ctx->GAA + ci[q] * nA;
        const PetscScalar                 c  = cv[q];
        for (PetscInt a = r0; a < r1; ++a) col[a] += ga[a] * c;
      }
    }
  }
  PetscCall(PetscFree3(start, ci, cv));
  PetscFunctionReturn(0);
}

/* Per Newton step, on every rank: the contact Hessian's entries and support
   A, and the LU factors of the capacitance matrix I + G_AA C_AA (|A| is the
   part of the surfaces in contact, a fraction of |c|). With z_c = G (g_c -
   E_A C_AA z_A) (E_A: A into c), the surface system (S_K + C_cc) z_c = g_c
   becomes (I + G_AA C_AA) z_A = (G g_c)_A. LU with partial pivoting holds
   for the Gauss-Newton and the (indefinite) exact contact Hessian alike. */
static PetscErrorCode SubPCSetUp(PC pc)
{
  SubCtx      *ctx;
  Mat          H;
  PetscBLASInt bA, info;
  PetscInt     nA;
  PetscMPIInt  size;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &ctx));
  PetscCall(PCGetOperators(pc, NULL, &H));
  PetscCallMPI(MPI_Comm_size(ctx->comm, &size));
  PetscCall(PetscLogEventBegin(SubStep, 0, 0, 0, 0));
  ctx->border.condensed = PETSC_FALSE;
  PetscCall(PetscLogEventBegin(SubCapGather, 0, 0, 0, 0));
  PetscCall(SubGatherContactHessian(ctx, H));
  PetscCall(PetscLogEventEnd(SubCapGather, 0, 0, 0, 0));
  PetscCall(PetscLogEventBegin(SubCapForm, 0, 0, 0, 0));
  nA = ctx->nA;
  if (nA > ctx->capA) {
    PetscCall(PetscFree4(ctx->MA, ctx->GAA, ctx->tA, ctx->ipiv));
    ctx->capA = nA;
    PetscCall(PetscMalloc4(nA * nA, &ctx->MA, nA * nA, &ctx->GAA, nA, &ctx->tA, nA, &ctx->ipiv));
  }
  /* G_AA (block diagonal by body, zero between bodies), then column j of
     I + G_AA C_AA gets C_kj times column k of G_AA */
  for (PetscInt k = 0; k < nA; ++k) {
    const PetscInt     ck = ctx->nG + ctx->A[k], b = ctx->bBody[ck];
    const SubBody     *B  = &ctx->body[b];
    const PetscScalar *Gk = B->Ginv + (ctx->bLocal[ck] - B->nG) * B->nc;
    PetscScalar       *ga = ctx->GAA + k * nA;
    for (PetscInt a = 0; a < nA; ++a) {
      const PetscInt ca = ctx->nG + ctx->A[a];
      ga[a] = ctx->bBody[ca] == b ? Gk[ctx->bLocal[ca] - B->nG] : 0.0;
    }
  }
  if (size > 1 && nA >= ctx->splitLU) { /* this rank's columns only, the factorisation shared */
    PetscInt        nloc;
    const PetscInt *cols;
    PetscScalar    *a;
    PetscInt       *loc = ctx->inA; /* reused: column j's place among this rank's, or -1 */

    if (!ctx->lu) PetscCall(DenseLUCreate(ctx->comm, &ctx->lu));
    PetscCall(DenseLUGetLocalColumns(ctx->lu, nA, &nloc, &cols, &a));
    PetscCall(SubCapacitanceColumns(ctx, nloc, cols, loc, a));
    PetscCall(PetscLogEventEnd(SubCapForm, 0, 0, 0, 0));
    PetscCall(PetscLogEventBegin(SubCapFactor, 0, 0, 0, 0));
    PetscCall(DenseLUFactor(ctx->lu, ctx->MA, ctx->ipiv));
    for (PetscInt k = 0; k < ctx->nc; ++k) ctx->inA[k] = -1; /* inA back */
    for (PetscInt k = 0; k < nA; ++k) ctx->inA[ctx->A[k]] = k;
    PetscCall(PetscLogEventEnd(SubCapFactor, 0, 0, 0, 0));
  } else { /* on several ranks each forms a block of columns, gathered; every rank factors it whole */
    PetscInt    *all, j0 = 0, j1 = nA;
    PetscMPIInt *counts = NULL, *displs = NULL, rank;

    if (size > 1) { /* 2 |C| |A| flops split; |A|^2 numbers gathered; the same matrix, to the last bit */
      PetscCallMPI(MPI_Comm_rank(ctx->comm, &rank));
      j0 = (nA * rank) / size;
      j1 = (nA * (rank + 1)) / size;
    }
    PetscCall(PetscMalloc1(nA + 1, &all));
    for (PetscInt j = j0; j < j1; ++j) all[j - j0] = j;
    PetscCall(SubCapacitanceColumns(ctx, j1 - j0, all, ctx->inA, ctx->MA + j0 * nA));
    PetscCall(PetscFree(all));
    if (j1 - j0 < nA) {
      PetscCall(PetscMalloc2(size, &counts, size, &displs));
      for (PetscMPIInt q = 0; q < size; ++q) {
        PetscCall(PetscMPIIntCast(((nA * (q + 1)) / size - (nA * q) / size) * nA, &counts[q]));
        PetscCall(PetscMPIIntCast(((nA * q) / size) * nA, &displs[q]));
      }
      PetscCallMPI(MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, ctx->MA, counts, displs, MPIU_SCALAR, ctx->comm));
      PetscCall(PetscFree2(counts, displs));
    }
    for (PetscInt k = 0; k < ctx->nc; ++k) ctx->inA[k] = -1; /* inA back */
    for (PetscInt k = 0; k < nA; ++k) ctx->inA[ctx->A[k]] = k;
    PetscCall(PetscLogEventEnd(SubCapForm, 0, 0, 0, 0));
    PetscCall(PetscLogEventBegin(SubCapFactor, 0, 0, 0, 0));
    PetscCall(PetscBLASIntCast(nA, &bA));
    if (nA) {
      PetscCallBLAS("LAPACKgetrf", LAPACKgetrf_(&bA, &bA, ctx->MA, &bA, ctx->ipiv, &info));
      PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "the surface block of the Hessian is singular (getrf info %d)", (int)info);
    }
    PetscCall(PetscLogFlops(2.0 / 3.0 * nA * nA * nA));
    PetscCall(PetscLogEventEnd(SubCapFactor, 0, 0, 0, 0));
  }
  PetscCall(PetscInfo(pc, "contact Hessian: %" PetscInt_FMT " entries coupling %" PetscInt_FMT " of %" PetscInt_FMT " surface dofs; capacitance matrix factored by %s\n", ctx->nC, nA, ctx->nc, ctx->lu && size > 1 && nA >= ctx->splitLU ? "the ranks together" : "each rank"));
  PetscCall(PetscLogFlops(2.0 * ctx->nC * nA));
  PetscCall(PetscLogEventEnd(SubStep, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Step 1, condensation: g_B = r_B + sum_r R_Br^T g^r for the nrhs right
   sides in ra (each of nD entries on this rank's subdomain: the interior
   ones are read from the columns' local arrays ra[j]), g^r = -K^r_BI
   (K^r_II)^-1 r_I by MUMPS (ICNTL(26) = 1, which keeps the forward
   substitution for the expansion that follows it); gB[j nB ...], summed
   over ranks. */
static PetscErrorCode SubCondense(SubCtx *ctx, PetscInt nrhs, const PetscScalar *const ra[], PetscScalar rhs[], PetscScalar red[], PetscScalar gB[])
{
  PetscMPIInt nBm;

  PetscFunctionBeginUser;
  PetscCall(PetscArrayzero(rhs, nrhs * ctx->nD));
  for (PetscInt j = 0; j < nrhs; ++j)
    for (PetscInt k = 0; k < ctx->nI; ++k) rhs[j * ctx->nD + ctx->Iloc[k]] = ra[j][ctx->D[ctx->Iloc[k]] - ctx->rstart];
  PetscCall(PetscArrayzero(gB, nrhs * ctx->nB));
  if (ctx->nI && ctx->nBr) {
    ctx->mumps.nrhs      = (MUMPS_INT)nrhs;
    ctx->mumps.lrhs      = (MUMPS_INT)ctx->nD;
    ctx->mumps.rhs       = rhs;
    ctx->mumps.redrhs    = red;
    ctx->mumps.lredrhs   = (MUMPS_INT)ctx->nBr;
    ctx->mumps.ICNTL(26) = 1;
    PetscCall(SubMumps(ctx, 3));
    for (PetscInt j = 0; j < nrhs; ++j)
      for (PetscInt k = 0; k < ctx->nBr; ++k) gB[j * ctx->nB + ctx->Bpos[k]] += red[j * ctx->nBr + k];
  }
  for (PetscInt j = 0; j < nrhs; ++j)
    for (PetscInt k = 0; k < ctx->nOwned; ++k) gB[j * ctx->nB + ctx->ownedPos[k]] += ra[j][ctx->ownedRow[k]];
  PetscCall(PetscMPIIntCast(nrhs * ctx->nB, &nBm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, gB, nBm, MPIU_SCALAR, MPIU_SUM, ctx->comm));
  PetscFunctionReturn(0);
}

/* Step 2a, in place on g_B, per body: y = L_G^-1 g_G on G, t = g_c - W^T y
   on c, the right side condensed onto the contact surfaces. */
static PetscErrorCode SubReduce(SubCtx *ctx, PetscScalar gB[])
{
  PetscBLASInt      one_i = 1;
  const PetscScalar one = 1.0, mone = -1.0;

  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < ctx->nbodies; ++b) {
    SubBody     *B = &ctx->body[b];
    PetscBLASInt bG, bc;
    PetscScalar *t = ctx->tmp;

    if (!B->nG) continue;
    PetscCall(PetscBLASIntCast(B->nG, &bG));
    PetscCall(PetscBLASIntCast(B->nc, &bc));
    for (PetscInt j = 0; j < B->nc; ++j) t[j] = gB[B->c[j]];
    for (PetscInt i = 0; i < B->nG; ++i) B->y[i] = gB[B->G[i]];
    PetscCallBLAS("BLAStrsm", BLAStrsm_("L", "L", "N", "N", &bG, &one_i, &one, B->LG, &bG, B->y, &bG));
    if (B->nc) PetscCallBLAS("BLASgemv", BLASgemv_("T", &bG, &bc, &mone, B->W, &bG, B->y, &one_i, &one, t, &one_i));
    for (PetscInt i = 0; i < B->nG; ++i) gB[B->G[i]] = B->y[i];
    for (PetscInt j = 0; j < B->nc; ++j) gB[B->c[j]] = t[j];
  }
  PetscFunctionReturn(0);
}

/* zc = S_K^-1 t, per body (t on gB's surface positions). */
static PetscErrorCode SubSurfaceInverse(SubCtx *ctx, const PetscScalar gB[], PetscScalar zc[])
{
  PetscBLASInt      one_i = 1;
  const PetscScalar one = 1.0, zero = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < ctx->nbodies; ++b) {
    SubBody     *B = &ctx->body[b];
    PetscBLASInt bc;
    PetscScalar *t = ctx->tmp, *zcb = ctx->tmp + B->nc;

    if (!B->nc) continue;
    PetscCall(PetscBLASIntCast(B->nc, &bc));
    for (PetscInt j = 0; j < B->nc; ++j) t[j] = gB[B->c[j]];
    PetscCallBLAS("BLASgemv", BLASgemv_("N", &bc, &bc, &one, B->Ginv, &bc, t, &one_i, &zero, zcb, &one_i));
    for (PetscInt j = 0; j < B->nc; ++j) zc[B->c[j] - ctx->nG] = zcb[j];
  }
  PetscFunctionReturn(0);
}

/* From zc = S_K^-1 t to (S_K + C_cc)^-1 t, in place: z_c -= G E_A C_AA z_A,
   (I + G_AA C_AA) z_A = (G t)_A (the LU of SubPCSetUp). */
static PetscErrorCode SubSurfaceCorrect(SubCtx *ctx, PetscScalar zc[])
{
  PetscScalar *w = ctx->tmp;
  PetscBLASInt bA, one_i = 1, info;

  PetscFunctionBeginUser;
  if (!ctx->nA) PetscFunctionReturn(0);
  PetscCall(PetscBLASIntCast(ctx->nA, &bA));
  for (PetscInt a = 0; a < ctx->nA; ++a) ctx->tA[a] = zc[ctx->A[a]];
  PetscCallBLAS("LAPACKgetrs", LAPACKgetrs_("N", &bA, &one_i, ctx->MA, &bA, ctx->ipiv, ctx->tA, &bA, &info));
  PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "getrs info %d", (int)info);
  PetscCall(PetscArrayzero(w, ctx->nA));
  for (PetscInt k = 0; k < ctx->nC; ++k) w[ctx->Ci[k]] += ctx->Cv[k] * ctx->tA[ctx->Cj[k]];
  for (PetscInt a = 0; a < ctx->nA; ++a) {
    const PetscInt     ca = ctx->nG + ctx->A[a];
    const SubBody     *B  = &ctx->body[ctx->bBody[ca]];
    const PetscScalar *Ga = B->Ginv + (ctx->bLocal[ca] - B->nG) * B->nc;
    if (w[a] != 0.0)
      for (PetscInt j = 0; j < B->nc; ++j) zc[B->c[j] - ctx->nG] -= w[a] * Ga[j];
  }
  PetscFunctionReturn(0);
}

/* Step 2b, in place on g_B holding y on G and z_c on c, per body:
   z_G = L_G^-T (y - W z_c). */
static PetscErrorCode SubInterfaceBack(SubCtx *ctx, PetscScalar gB[])
{
  PetscBLASInt      one_i = 1;
  const PetscScalar one = 1.0, mone = -1.0;

  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < ctx->nbodies; ++b) {
    SubBody     *B = &ctx->body[b];
    PetscBLASInt bG, bc;
    PetscScalar *t = ctx->tmp;

    if (!B->nG) continue;
    PetscCall(PetscBLASIntCast(B->nG, &bG));
    PetscCall(PetscBLASIntCast(B->nc, &bc));
    for (PetscInt j = 0; j < B->nc; ++j) t[j] = gB[B->c[j]];
    for (PetscInt i = 0; i < B->nG; ++i) B->y[i] = gB[B->G[i]];
    if (B->nc) PetscCallBLAS("BLASgemv", BLASgemv_("N", &bG, &bc, &mone, B->W, &bG, t, &one_i, &one, B->y, &one_i));
    PetscCallBLAS("BLAStrsm", BLAStrsm_("L", "L", "T", "N", &bG, &one_i, &one, B->LG, &bG, B->y, &bG));
    for (PetscInt i = 0; i < B->nG; ++i) gB[B->G[i]] = B->y[i];
  }
  PetscFunctionReturn(0);
}

/* Step 3, expansion of the nrhs right sides last condensed (SubCondense, with
   the same rhs and red): z_I = (K^r_II)^-1 (r_I - K^r_IB z_B) in rhs, z_B
   read from gB[j nB ...] (with no boundary, the subdomain's own solve). */
static PetscErrorCode SubExpand(SubCtx *ctx, PetscInt nrhs, const PetscScalar gB[], PetscScalar rhs[], PetscScalar red[])
{
  PetscFunctionBeginUser;
  if (!ctx->nI) PetscFunctionReturn(0);
  for (PetscInt j = 0; j < nrhs; ++j)
    for (PetscInt k = 0; k < ctx->nBr; ++k) red[j * ctx->nBr + k] = gB[j * ctx->nB + ctx->Bpos[k]];
  ctx->mumps.nrhs      = (MUMPS_INT)nrhs;
  ctx->mumps.lrhs      = (MUMPS_INT)ctx->nD;
  ctx->mumps.rhs       = rhs;
  ctx->mumps.redrhs    = red;
  ctx->mumps.lredrhs   = (MUMPS_INT)ctx->nBr;
  ctx->mumps.ICNTL(26) = ctx->nBr ? 2 : 0;
  PetscCall(SubMumps(ctx, 3));
  PetscFunctionReturn(0);
}

/* z's entries on this rank: the interior from the expansion, the owned
   boundary dofs from z_B. */
static PetscErrorCode SubScatterSolution(SubCtx *ctx, const PetscScalar gB[], Vec z)
{
  PetscScalar *za;

  PetscFunctionBeginUser;
  PetscCall(VecGetArray(z, &za));
  for (PetscInt k = 0; k < ctx->nI; ++k) za[ctx->D[ctx->Iloc[k]] - ctx->rstart] = ctx->rhs[ctx->Iloc[k]];
  for (PetscInt k = 0; k < ctx->nOwned; ++k) za[ctx->ownedRow[k]] = gB[ctx->ownedPos[k]];
  PetscCall(VecRestoreArray(z, &za));
  PetscFunctionReturn(0);
}

static PetscErrorCode SubLogSolveFlops(SubCtx *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogFlops(2.0 * ctx->nc * ctx->nc + 2.0 * ctx->nc * ctx->nA + 2.0 * ctx->nG * ctx->nG + 4.0 * ctx->nG * ctx->nc));
  PetscFunctionReturn(0);
}

/* H z = r: steps 1 to 3 above. */
static PetscErrorCode SubPCApply(PC pc, Vec r, Vec z)
{
  SubCtx            *ctx;
  const PetscScalar *ra;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &ctx));
  PetscCall(PetscLogEventBegin(SubSolve, 0, 0, 0, 0));
  ctx->border.condensed = PETSC_FALSE; /* MUMPS's forward substitution is this right side's now */
  PetscCall(VecGetArrayRead(r, &ra));
  PetscCall(SubCondense(ctx, 1, &ra, ctx->rhs, ctx->red, ctx->gB));
  PetscCall(VecRestoreArrayRead(r, &ra));
  PetscCall(SubReduce(ctx, ctx->gB));
  PetscCall(SubSurfaceInverse(ctx, ctx->gB, ctx->zc));
  PetscCall(SubSurfaceCorrect(ctx, ctx->zc));
  PetscCall(PetscArraycpy(ctx->gB + ctx->nG, ctx->zc, ctx->nc));
  PetscCall(SubInterfaceBack(ctx, ctx->gB));
  PetscCall(SubExpand(ctx, 1, ctx->gB, ctx->rhs, ctx->red));
  PetscCall(SubScatterSolution(ctx, ctx->gB, z));
  PetscCall(SubLogSolveFlops(ctx));
  PetscCall(PetscLogEventEnd(SubSolve, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The bordered step of coupled force control (forceborder.c) through the
   substructuring: see the file's header. Once, for the constant columns B_k:
   y_k and t_k (condensation, step 2a), v_k = S_K^-1 t_k, X_k = (K_II)^-1
   B_k,I (condensation and an expansion with z_B = 0), and Q_lk = B_l,I^T X_k
   + y_l^T y_k. */
static PetscErrorCode SubBorderSetColumns(PC pc, PetscInt m, const Vec B[])
{
  SubCtx             *ctx;
  SubBorder          *bd;
  const PetscScalar **ba;
  PetscScalar        *rhs, *red, *gB;
  PetscMPIInt         mm;
  PetscBool           inner = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &ctx));
  bd = &ctx->border;
  PetscCheck(m >= 1, ctx->comm, PETSC_ERR_ARG_OUTOFRANGE, "the border needs at least one column, got %" PetscInt_FMT, m);
  PetscCall(PetscLogEventBegin(SubBorderCols, 0, 0, 0, 0));
  PetscCall(PetscFree6(bd->red, bd->v, bd->X, bd->Q, bd->Zc, bd->xr));
  bd->m         = m;
  bd->condensed = PETSC_FALSE;
  PetscCall(PetscMalloc6(m * ctx->nB + 1, &bd->red, m * ctx->nc + 1, &bd->v, m * ctx->nI + 1, &bd->X, m * m, &bd->Q, m * ctx->nc + 1, &bd->Zc, m, &bd->xr));
  PetscCall(PetscMalloc4(m * ctx->nD + 1, &rhs, m * ctx->nBr + 1, &red, m * ctx->nB + 1, &gB, m, &ba));
  for (PetscInt k = 0; k < m; ++k) PetscCall(VecGetArrayRead(B[k], &ba[k]));
  for (PetscInt k = 0; k < m && !inner; ++k) /* columns on the boundary alone (a rigid body's: the contact's coupling) need no interior solve */
    for (PetscInt i = 0; i < ctx->nI && !inner; ++i) inner = (PetscBool)(ba[k][ctx->D[ctx->Iloc[i]] - ctx->rstart] != 0.0);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &inner, 1, MPIU_BOOL, MPI_LOR, ctx->comm));
  if (inner) {
    PetscCall(SubCondense(ctx, m, ba, rhs, red, gB));
    PetscCall(PetscArraycpy(bd->red, gB, m * ctx->nB));
    PetscCall(PetscArrayzero(gB, m * ctx->nB));
    PetscCall(SubExpand(ctx, m, gB, rhs, red)); /* z_B = 0: the interior's own solve */
  } else { /* g_B = r_B, X_k = 0 */
    PetscCall(PetscArrayzero(bd->red, m * ctx->nB));
    for (PetscInt k = 0; k < m; ++k)
      for (PetscInt j = 0; j < ctx->nOwned; ++j) bd->red[k * ctx->nB + ctx->ownedPos[j]] = ba[k][ctx->ownedRow[j]];
    PetscCall(PetscMPIIntCast(m * ctx->nB, &mm));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, bd->red, mm, MPIU_SCALAR, MPIU_SUM, ctx->comm));
    PetscCall(PetscArrayzero(rhs, m * ctx->nD));
  }
  for (PetscInt k = 0; k < m; ++k) {
    for (PetscInt i = 0; i < ctx->nI; ++i) bd->X[k * ctx->nI + i] = rhs[k * ctx->nD + ctx->Iloc[i]];
    PetscCall(SubReduce(ctx, bd->red + k * ctx->nB));
    PetscCall(SubSurfaceInverse(ctx, bd->red + k * ctx->nB, bd->v + k * ctx->nc));
  }
  for (PetscInt l = 0; l < m; ++l)
    for (PetscInt k = 0; k < m; ++k) {
      PetscScalar s = 0.0;
      for (PetscInt i = 0; i < ctx->nI; ++i) s += ba[l][ctx->D[ctx->Iloc[i]] - ctx->rstart] * bd->X[k * ctx->nI + i];
      bd->Q[l * m + k] = s;
    }
  for (PetscInt k = 0; k < m; ++k) PetscCall(VecRestoreArrayRead(B[k], &ba[k]));
  PetscCall(PetscMPIIntCast(m * m, &mm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, bd->Q, mm, MPIU_SCALAR, MPIU_SUM, ctx->comm));
  for (PetscInt l = 0; l < m; ++l)
    for (PetscInt k = 0; k < m; ++k)
      for (PetscInt i = 0; i < ctx->nG; ++i) bd->Q[l * m + k] += bd->red[l * ctx->nB + i] * bd->red[k * ctx->nB + i];
  PetscCall(PetscFree4(rhs, red, gB, ba));
  PetscCall(PetscLogFlops(2.0 * m * ctx->nc * ctx->nc + 2.0 * m * m * (ctx->nI + ctx->nG)));
  PetscCall(PetscLogEventEnd(SubBorderCols, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Per Hessian (after SubPCSetUp): Zc_k = (S_K + C_cc)^-1 t_k from v_k by the
   capacitance correction, and B_l^T H^-1 B_k = Q_lk + t_l^T Zc_k. */
static PetscErrorCode SubBorderGetCoupling(PC pc, PetscReal BHB[])
{
  SubCtx    *ctx;
  SubBorder *bd;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &ctx));
  bd = &ctx->border;
  PetscCheck(bd->m, ctx->comm, PETSC_ERR_ORDER, "the border's columns are not set (ContactBorderPCSetColumns)");
  PetscCall(PetscLogEventBegin(SubBorderStep, 0, 0, 0, 0));
  bd->condensed = PETSC_FALSE; /* the contact block may have changed since */
  for (PetscInt k = 0; k < bd->m; ++k) {
    PetscScalar *Zk = bd->Zc + k * ctx->nc;
    PetscCall(PetscArraycpy(Zk, bd->v + k * ctx->nc, ctx->nc));
    PetscCall(SubSurfaceCorrect(ctx, Zk));
  }
  for (PetscInt l = 0; l < bd->m; ++l)
    for (PetscInt k = 0; k < bd->m; ++k) {
      const PetscScalar *tl = bd->red + l * ctx->nB + ctx->nG, *Zk = bd->Zc + k * ctx->nc;
      PetscScalar        s  = bd->Q[l * bd->m + k];
      for (PetscInt j = 0; j < ctx->nc; ++j) s += tl[j] * Zk[j];
      BHB[l * bd->m + k] = PetscRealPart(s);
    }
  PetscCall(PetscLogFlops(bd->m * (2.0 * ctx->nC + 2.0 * ctx->nA * ctx->nA + 2.0 * ctx->nA * ctx->nc) + 2.0 * bd->m * bd->m * ctx->nc));
  PetscCall(PetscLogEventEnd(SubBorderStep, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The first half of H^-1 r: condensation, y(r), t(r) in gB and w_c =
   (S_K + C_cc)^-1 t(r) in zc (MUMPS keeps r's forward substitution), and
   B_k^T H^-1 r = X_k^T r_I + y_k^T y(r) + t_k^T w_c. */
static PetscErrorCode SubBorderCondense(PC pc, Vec r, PetscReal BHr[])
{
  SubCtx            *ctx;
  SubBorder         *bd;
  const PetscScalar *ra;
  PetscScalar       *xr;
  PetscMPIInt        mm;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &ctx));
  bd = &ctx->border;
  PetscCheck(bd->m, ctx->comm, PETSC_ERR_ORDER, "the border's columns are not set (ContactBorderPCSetColumns)");
  xr = bd->xr;
  PetscCall(PetscLogEventBegin(SubBorderSolve, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(r, &ra));
  PetscCall(SubCondense(ctx, 1, &ra, ctx->rhs, ctx->red, ctx->gB));
  for (PetscInt k = 0; k < bd->m; ++k) {
    xr[k] = 0.0;
    for (PetscInt i = 0; i < ctx->nI; ++i) xr[k] += bd->X[k * ctx->nI + i] * ra[ctx->D[ctx->Iloc[i]] - ctx->rstart];
  }
  PetscCall(VecRestoreArrayRead(r, &ra));
  PetscCall(PetscMPIIntCast(bd->m, &mm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, xr, mm, MPIU_SCALAR, MPIU_SUM, ctx->comm));
  PetscCall(SubReduce(ctx, ctx->gB));
  PetscCall(SubSurfaceInverse(ctx, ctx->gB, ctx->zc));
  PetscCall(SubSurfaceCorrect(ctx, ctx->zc));
  for (PetscInt k = 0; k < bd->m; ++k) {
    const PetscScalar *yk = bd->red + k * ctx->nB, *tk = yk + ctx->nG;
    PetscScalar        s  = xr[k];
    for (PetscInt i = 0; i < ctx->nG; ++i) s += yk[i] * ctx->gB[i];
    for (PetscInt j = 0; j < ctx->nc; ++j) s += tk[j] * ctx->zc[j];
    BHr[k] = PetscRealPart(s);
  }
  bd->condensed = PETSC_TRUE;
  PetscCall(SubLogSolveFlops(ctx));
  PetscCall(PetscLogEventEnd(SubBorderSolve, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The second half: z = H^-1 (r - B dU), r the right side last condensed. By
   linearity its y and z_c are y(r) - sum_k dU_k y_k and w_c - sum_k dU_k
   Zc_k; then z_G (step 2b), the expansion of r with that z_B, and the
   interior less sum_k dU_k X_k. */
static PetscErrorCode SubBorderExpand(PC pc, const PetscReal dU[], Vec z)
{
  SubCtx    *ctx;
  SubBorder *bd;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &ctx));
  bd = &ctx->border;
  PetscCheck(bd->condensed, ctx->comm, PETSC_ERR_ORDER, "the border's expansion without a condensation before it (ContactBorderPCCondense)");
  PetscCall(PetscLogEventBegin(SubBorderSolve, 0, 0, 0, 0));
  for (PetscInt k = 0; k < bd->m; ++k) {
    const PetscScalar *yk = bd->red + k * ctx->nB, *Zk = bd->Zc + k * ctx->nc;
    for (PetscInt i = 0; i < ctx->nG; ++i) ctx->gB[i] -= dU[k] * yk[i];
    for (PetscInt j = 0; j < ctx->nc; ++j) ctx->zc[j] -= dU[k] * Zk[j];
  }
  PetscCall(PetscArraycpy(ctx->gB + ctx->nG, ctx->zc, ctx->nc));
  PetscCall(SubInterfaceBack(ctx, ctx->gB));
  PetscCall(SubExpand(ctx, 1, ctx->gB, ctx->rhs, ctx->red));
  for (PetscInt k = 0; k < bd->m; ++k)
    for (PetscInt i = 0; i < ctx->nI; ++i) ctx->rhs[ctx->Iloc[i]] -= dU[k] * bd->X[k * ctx->nI + i];
  PetscCall(SubScatterSolution(ctx, ctx->gB, z));
  bd->condensed = PETSC_FALSE;
  PetscCall(PetscLogFlops(2.0 * bd->m * (ctx->nG + ctx->nc + ctx->nI)));
  PetscCall(PetscLogEventEnd(SubBorderSolve, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode SubPCDestroy(PC pc)
{
  SubCtx *ctx;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &ctx));
  if (ctx->hasMumps) {
    PetscCall(SubMumps(ctx, -2));
    PetscCall(PetscFree(ctx->mumps.listvar_schur));
    PetscCallMPI(MPI_Comm_free(&ctx->self));
  }
  PetscCall(ISRestoreIndices(ctx->isc, &ctx->surf));
  PetscCall(ISDestroy(&ctx->isc));
  PetscCall(PetscFree(ctx->D));
  PetscCall(PetscFree3(ctx->Iloc, ctx->Bloc, ctx->Bpos));
  PetscCall(PetscFree2(ctx->ownedPos, ctx->ownedRow));
  PetscCall(PetscFree2(ctx->rhs, ctx->red));
  for (PetscInt b = 0; b < ctx->nbodies; ++b) {
    PetscCall(PetscFree3(ctx->body[b].G, ctx->body[b].c, ctx->body[b].y));
    PetscCall(PetscFree3(ctx->body[b].LG, ctx->body[b].W, ctx->body[b].Ginv));
  }
  PetscCall(PetscFree2(ctx->bBody, ctx->bLocal));
  PetscCall(PetscFree3(ctx->gB, ctx->zc, ctx->tmp));
  PetscCall(PetscFree3(ctx->Ci, ctx->Cj, ctx->Cv));
  PetscCall(PetscFree2(ctx->A, ctx->inA));
  PetscCall(PetscFree4(ctx->MA, ctx->GAA, ctx->tA, ctx->ipiv));
  PetscCall(DenseLUDestroy(&ctx->lu));
  PetscCall(PetscFree6(ctx->border.red, ctx->border.v, ctx->border.X, ctx->border.Q, ctx->border.Zc, ctx->border.xr));
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "ContactBorderPCSetColumns_C", NULL));
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "ContactBorderPCGetCoupling_C", NULL));
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "ContactBorderPCCondense_C", NULL));
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "ContactBorderPCExpand_C", NULL));
  PetscCall(MatDestroy(&ctx->K));
  PetscCall(PetscFree(ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactSubstructurePCSetUp(PC pc, Mat K, IS surface, PetscInt nbodies, const PetscInt offset[], PetscInt splitLU, Subdomain *sub)
{
  SubCtx      *ctx;
  PetscScalar *Sr;

  PetscFunctionBeginUser;
  if (!SubFactor) {
    PetscClassId id;
    PetscCall(PetscClassIdRegister("ContactSubstructure", &id));
    PetscCall(PetscLogEventRegister("SubstrFactor", id, &SubFactor));
    PetscCall(PetscLogEventRegister("SubstrInterface", id, &SubInterface));
    PetscCall(PetscLogEventRegister("SubstrStep", id, &SubStep));
    PetscCall(PetscLogEventRegister("SubstrSolve", id, &SubSolve));
    PetscCall(PetscLogEventRegister("SubstrBordCols", id, &SubBorderCols));
    PetscCall(PetscLogEventRegister("SubstrBordStep", id, &SubBorderStep));
    PetscCall(PetscLogEventRegister("SubstrBordSolve", id, &SubBorderSolve));
    PetscCall(PetscLogEventRegister("SubstrIfSum", id, &SubIfSum));
    PetscCall(PetscLogEventRegister("SubstrIfDense", id, &SubIfDense));
    PetscCall(PetscLogEventRegister("SubstrIfBcast", id, &SubIfBcast));
    PetscCall(PetscLogEventRegister("SubstrCapGather", id, &SubCapGather));
    PetscCall(PetscLogEventRegister("SubstrCapForm", id, &SubCapForm));
    PetscCall(PetscLogEventRegister("SubstrCapFactor", id, &SubCapFactor));
  }
  PetscCall(PetscNew(&ctx));
  ctx->comm    = PetscObjectComm((PetscObject)K);
  ctx->splitLU = splitLU;
  PetscCall(PetscObjectReference((PetscObject)surface));
  ctx->isc = surface;
  PetscCall(ISGetIndices(ctx->isc, &ctx->surf));
  PetscCall(PetscObjectReference((PetscObject)K));
  ctx->K = K;
  PetscCall(PetscLogEventBegin(SubFactor, 0, 0, 0, 0));
  PetscCall(SubSetUpDofs(ctx, *sub, nbodies, offset));
  PetscCall(PetscInfo(NULL, "subdomain: %" PetscInt_FMT " dofs, %" PetscInt_FMT " interior, %" PetscInt_FMT " boundary; interface %" PetscInt_FMT ", contact surfaces %" PetscInt_FMT " dofs\n", ctx->nD, ctx->nI, ctx->nBr, ctx->nG, ctx->nc));
  PetscCall(PetscCalloc1(ctx->nBr * ctx->nBr + 1, &Sr));
  /* K^r: the subdomain's stiffness (subdomain.c), consumed here; on one rank K
     itself, with the surface block's explicit zeros, which
     SubFactorSubdomain drops */
  PetscCall(SubFactorSubdomain(ctx, *sub ? (*sub)->K : K, Sr));
  PetscCall(SubdomainDestroy(sub));
  {
    PetscMPIInt info[2] = {ctx->hasMumps ? (PetscMPIInt)ctx->mumps.INFOG(1) : 0, 0}, worst[2];
    PetscCallMPI(MPI_Comm_rank(ctx->comm, &info[1]));
    PetscCallMPI(MPI_Allreduce(info, worst, 1, MPI_2INT, MPI_MINLOC, ctx->comm));
    PetscCheck(worst[0] >= 0, ctx->comm, PETSC_ERR_LIB, "MUMPS failed on the subdomain of rank %d: INFOG(1) = %d", worst[1], worst[0]);
  }
  PetscCall(PetscLogEventEnd(SubFactor, 0, 0, 0, 0));
  PetscCall(PetscLogEventBegin(SubInterface, 0, 0, 0, 0));
  PetscCall(SubCondenseInterface(ctx, &Sr)); /* frees Sr once summed */
  PetscCall(PetscMalloc3(ctx->nB + 1, &ctx->gB, ctx->nc + 1, &ctx->zc, 2 * ctx->nc + 1, &ctx->tmp));
  PetscCall(PetscMalloc2(ctx->nc, &ctx->A, ctx->nc, &ctx->inA));
  PetscCall(PetscLogEventEnd(SubInterface, 0, 0, 0, 0));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, ctx));
  PetscCall(PCShellSetSetUp(pc, SubPCSetUp));
  PetscCall(PCShellSetApply(pc, SubPCApply));
  PetscCall(PCShellSetDestroy(pc, SubPCDestroy));
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "ContactBorderPCSetColumns_C", SubBorderSetColumns));
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "ContactBorderPCGetCoupling_C", SubBorderGetCoupling));
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "ContactBorderPCCondense_C", SubBorderCondense));
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "ContactBorderPCExpand_C", SubBorderExpand));
  PetscCall(PCShellSetName(pc, "contact Schur by substructuring: subdomains condensed once (MUMPS), dense surface block per step"));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactBorderPCSetColumns(PC pc, PetscInt m, const Vec B[], PetscBool *has)
{
  PetscErrorCode (*f)(PC, PetscInt, const Vec[]);

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQueryFunction((PetscObject)pc, "ContactBorderPCSetColumns_C", &f));
  *has = f ? PETSC_TRUE : PETSC_FALSE;
  if (f) PetscCall((*f)(pc, m, B));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactBorderPCGetCoupling(PC pc, PetscReal BHB[])
{
  PetscFunctionBeginUser;
  PetscUseMethod(pc, "ContactBorderPCGetCoupling_C", (PC, PetscReal[]), (pc, BHB));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactBorderPCCondense(PC pc, Vec r, PetscReal BHr[])
{
  PetscFunctionBeginUser;
  PetscUseMethod(pc, "ContactBorderPCCondense_C", (PC, Vec, PetscReal[]), (pc, r, BHr));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactBorderPCExpand(PC pc, const PetscReal dU[], Vec z)
{
  PetscFunctionBeginUser;
  PetscUseMethod(pc, "ContactBorderPCExpand_C", (PC, const PetscReal[], Vec), (pc, dU, z));
  PetscFunctionReturn(0);
}
