/* The Newton system of coupled force control (forcecontrol.c), the bodies'
   Hessian bordered by the controlled displacements, and its solve by
   eliminating them. The unknowns are the bodies' dofs u (Xb's layout) and
   the m controlled displacements U (the last entries of rank 0's part of
   X), and the Hessian of the energy Pi(u, U) - F U is H bordered by the
   controls,

       [ H    B ] [ du ]   [ r_u ]
       [ B^T  D ] [ dU ] = [ r_U ],     B = K_fc 1,  D = 1^T K_cc 1,

   H the Hessian of the bodies' dofs (K + the contact's), column k of B the
   force on the free dofs when group k moves by 1, D the groups' own
   stiffness (forcecontrol.c computes both once, or for an anchor of a
   neohookean body with each Hessian from its tangent: the assumption, named
   there, is that no controlled group is on a contact surface). Eliminating u with
   the solve of H the step already has (schur.c, substructure.c, Cholesky,
   or CG):

       Z = H^-1 B (m solves, once per Hessian),  S = D - B^T Z (m x m),
       w = H^-1 r_u,  S dU = r_U - B^T w,  du = w - Z dU,

   one solve of H per step. That is how any solve of H does it (schur.c,
   Cholesky, CG): m + 1 solves of H per Hessian.
   Where kin's PC eliminates the border itself (ContactBorderPCSetColumns:
   the substructuring, substructure.c's header has the derivation), B^T
   H^-1 B comes from the contact surfaces alone, B^T w from the first half
   of w's solve, and du = H^-1 (r_u - B dU) from its second half: one solve
   of H per step and nothing more per Hessian than a surface solve of order
   |A| per control. Measured on the roller by force (m = 4, 26 Newton
   iterations either way; docs/solver.md): ForceBorderSetUp 2.87 -> 0.40 s
   (0.30 s of it SubstrStep, the PC's own set-up, which the m solves
   included too), TaoSolve 4.89 -> 2.50 s. -force_control_border_solves
   keeps the m solves (tests/test_force_control.py compares the two).

   S is the stiffness the controls feel through the whole scene: the
   reaction's derivative dR/dU. Where a controlled body
   touches nothing yet in the controlled direction, S is zero to round-off
   (the body moves freely with U) and the step in U has no length of its
   own; and where the contact has just closed at a few points, S may ask for
   a step that throws the body far past its partner. So dU solves the
   regularised (S + mu diag(D)) dU = r_U, mu >= 0 the least (from 0, 1e-12,
   then times 4) for which the matrix is positive definite (scaled pivots
   above 1e-9) and every |dU_k| is at most its cap, -force_control_step
   times the size of control k's body (in 3D at most the contact's reach
   along it, forcereach.c; 0.3 by default: measured with
   scripts/force_control_table.py on 1 rank, Newton iterations at 0.003,
   0.01, 0.1, 0.3, 1: hertz 19, 15, 11, 11, 12; sphere 9, 11, 11, 10, 10;
   sphere pushed by 0.05 16, 12, 14, 13, 13; softdisc at hc = 0.0007 8, 10,
   10, 10, 10; pinch 10, 9, 9, 9, 9: a small cap holds back a large push,
   a large one throws a small one far past its partner, which the line
   search takes back). The regularised system is the
   Hessian with D + mu diag(D) in its corner: symmetric positive definite, so
   the step is a descent direction, and the line search finds the length
   along it (the energy falls like -F U until the contact takes the force).
   With mu = 0, the step is Newton's. */
#include "forceborder.h"
#include "substructure.h"
#include "forcereach.h"
#include <petscblaslapack.h>
#include <petsc/private/petscimpl.h> /* PetscObjectStateGet */

typedef struct {
  MPI_Comm         comm;
  PetscMPIInt      rank;
  PetscInt         m, nloc; /* controls; this rank's dofs of Xb */
  Vec              B[CONTACT_MAX_CONTROLS], Z[CONTACT_MAX_CONTROLS];
  const PetscReal *D;                        /* the problem's p->fc.D: a rigid body's part changes with each Hessian */
  PetscReal        S[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS];
  PetscReal        floor[CONTACT_MAX_CONTROLS]; /* the least own stiffness a control's step is scaled and regularised by (a rigid body's unknown out of contact has none) */
  PetscReal        cap[CONTACT_MAX_CONTROLS];
  Mat              Hin;
  KSP              kin;
  PetscObjectState state; /* Hin's when Z and S were made */
  PetscBool        haveZ;
  PetscBool        solves; /* -force_control_border_solves: the m solves even where kin's PC can do without */
  PetscBool        asked;  /* whether kin's PC has been given the columns */
  PetscBool        varies; /* the columns change with each Hessian (a rigid body's unknowns): given to kin's PC at each */
  PC               fast;   /* kin's PC, where it eliminates the border itself (substructure.c); else NULL */
  Vec              wx, wy; /* views of Xb's layout on X's arrays */
  Unheld          *unheld; /* the problem's: the anchors' frozen directions (unheld.c) */
} BorderCtx;

static PetscLogEvent BorderSetUp = 0, BorderSolve = 0;

/* The controls' entries of a vector of X's layout (array a), on every rank. */
static PetscErrorCode BorderGetU(BorderCtx *c, const PetscScalar *a, PetscReal U[])
{
  PetscMPIInt m;

  PetscFunctionBeginUser;
  if (!c->rank)
    for (PetscInt k = 0; k < c->m; ++k) U[k] = PetscRealPart(a[c->nloc + k]);
  PetscCall(PetscMPIIntCast(c->m, &m));
  PetscCallMPI(MPI_Bcast(U, m, MPIU_REAL, 0, c->comm));
  PetscFunctionReturn(0);
}

static PetscErrorCode BorderMatMult(Mat M, Vec x, Vec y)
{
  BorderCtx         *c;
  const PetscScalar *xa;
  PetscScalar       *ya, bt[CONTACT_MAX_CONTROLS], Us[CONTACT_MAX_CONTROLS];
  PetscReal          U[CONTACT_MAX_CONTROLS];

  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(M, &c));
  PetscCall(VecGetArrayRead(x, &xa));
  PetscCall(VecGetArray(y, &ya));
  PetscCall(BorderGetU(c, xa, U));
  PetscCall(VecPlaceArray(c->wx, xa));
  PetscCall(VecPlaceArray(c->wy, ya));
  PetscCall(MatMult(c->Hin, c->wx, c->wy));
  for (PetscInt k = 0; k < c->m; ++k) Us[k] = U[k];
  PetscCall(VecMAXPY(c->wy, c->m, Us, c->B));
  PetscCall(VecMDot(c->wx, c->m, c->B, bt));
  PetscCall(VecResetArray(c->wx));
  PetscCall(VecResetArray(c->wy));
  if (!c->rank)
    for (PetscInt k = 0; k < c->m; ++k) {
      PetscReal s = PetscRealPart(bt[k]);
      for (PetscInt l = 0; l < c->m; ++l) s += c->D[k * c->m + l] * U[l];
      ya[c->nloc + k] = s;
    }
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCall(VecRestoreArray(y, &ya));
  PetscFunctionReturn(0);
}

/* The controls' stiffness through the scene and their own, every entry of S
   and the diagonal of D to round-off (-info; the tests compare the two ways
   of eliminating the border with it). */
static PetscErrorCode BorderInfoS(BorderCtx *c)
{
  char      buf[CONTACT_MAX_CONTROLS * (CONTACT_MAX_CONTROLS + 1) * 26 + 16];
  size_t    len = 0;
  PetscBool on;

  PetscFunctionBeginUser;
  PetscCall(PetscInfoEnabled(PETSC_SMALLEST_CLASSID, &on)); /* PetscInfo(NULL, ...): the class "sys" */
  if (!on) PetscFunctionReturn(0);
  buf[0] = 0;
  for (PetscInt k = 0; k < c->m * c->m; ++k) {
    PetscCall(PetscSNPrintf(buf + len, sizeof(buf) - len, "%s%.17g", k ? (k % c->m ? " " : "; ") : "", (double)c->S[k]));
    PetscCall(PetscStrlen(buf, &len));
  }
  PetscCall(PetscSNPrintf(buf + len, sizeof(buf) - len, "], own D_kk = ["));
  for (PetscInt k = 0; k < c->m; ++k) {
    PetscCall(PetscStrlen(buf, &len));
    PetscCall(PetscSNPrintf(buf + len, sizeof(buf) - len, "%s%.17g", k ? " " : "", (double)c->D[k * c->m + k]));
  }
  PetscCall(PetscInfo(NULL, "force control: the controls' stiffness through the scene S = [%s]\n", buf));
  PetscFunctionReturn(0);
}

/* The first set-up asks kin's PC whether it eliminates the border itself
   (ContactBorderPCSetColumns: the substructuring's does, condensing the
   columns once; a rigid body's, which change with the Hessian and live on
   the contact surfaces alone, at each Hessian, with no interior solve);
   unless -force_control_border_solves, the fast path then takes it. */
static PetscErrorCode BorderChoosePath(BorderCtx *c)
{
  PC        pc;
  PetscBool has = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (c->asked) {
    if (c->fast && c->varies) PetscCall(ContactBorderPCSetColumns(c->fast, c->m, c->B, &has));
    PetscFunctionReturn(0);
  }
  c->asked = PETSC_TRUE;
  if (c->solves) PetscFunctionReturn(0);
  PetscCall(KSPGetPC(c->kin, &pc));
  PetscCall(ContactBorderPCSetColumns(pc, c->m, c->B, &has));
  if (has) c->fast = pc;
  PetscCall(PetscInfo(NULL, "force control: the border eliminated %s\n", has ? "by the PC of the bodies' step from the surfaces (one solve a step)" : "by m solves of the bodies' step a Hessian"));
  PetscFunctionReturn(0);
}

/* B^T H^-1 B: by m solves Z_k = Hin^-1 B_k, or from kin's PC. */
static PetscErrorCode BorderCoupling(BorderCtx *c, PetscReal BHB[])
{
  PetscScalar bz[CONTACT_MAX_CONTROLS];

  PetscFunctionBeginUser;
  if (c->fast) {
    PetscCall(PCSetUp(c->fast)); /* for Hin as it is now */
    PetscCall(ContactBorderPCGetCoupling(c->fast, BHB));
    PetscFunctionReturn(0);
  }
  for (PetscInt k = 0; k < c->m; ++k) {
    if (!c->Z[k]) PetscCall(VecDuplicate(c->B[k], &c->Z[k]));
    PetscCall(KSPSolve(c->kin, c->B[k], c->Z[k]));
    PetscCall(VecMDot(c->Z[k], c->m, c->B, bz));
    for (PetscInt l = 0; l < c->m; ++l) BHB[k * c->m + l] = PetscRealPart(bz[l]);
  }
  PetscFunctionReturn(0);
}

/* S = D - B^T Hin^-1 B, where Hin has changed since it was made. */
static PetscErrorCode BorderSetUpSchur(BorderCtx *c)
{
  PetscObjectState st;
  PetscReal        BHB[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS];

  PetscFunctionBeginUser;
  PetscCall(PetscObjectStateGet((PetscObject)c->Hin, &st));
  if (c->haveZ && st == c->state) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(BorderSetUp, 0, 0, 0, 0));
  PetscCall(BorderChoosePath(c));
  PetscCall(BorderCoupling(c, BHB));
  for (PetscInt k = 0; k < c->m; ++k)
    for (PetscInt l = 0; l < c->m; ++l) c->S[k * c->m + l] = c->D[k * c->m + l] - BHB[k * c->m + l];
  for (PetscInt k = 0; k < c->m; ++k) /* symmetric in exact arithmetic */
    for (PetscInt l = 0; l < k; ++l) c->S[k * c->m + l] = c->S[l * c->m + k] = 0.5 * (c->S[k * c->m + l] + c->S[l * c->m + k]);
  c->state = st;
  c->haveZ = PETSC_TRUE;
  if (UnheldAny(c->unheld)) PetscCall(UnheldUpdate(c->unheld, c->S));
  PetscCall(BorderInfoS(c));
  PetscCall(PetscLogEventEnd(BorderSetUp, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* (S + mu diag(D)) dU = r, mu the least of 0, 1e-12, 4e-12, ... that keeps
   the matrix positive definite and every |dU_k| within cap_k; with no part
   along an anchor's frozen direction (unheld.c). */
static PetscErrorCode BorderSolveControls(BorderCtx *c, const PetscReal r[], PetscReal dU[])
{
  const PetscInt m = c->m;
  PetscScalar    A[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS], y[CONTACT_MAX_CONTROLS];
  PetscReal      Au[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS], ru[CONTACT_MAX_CONTROLS], s[CONTACT_MAX_CONTROLS], mu = 0.0;
  PetscBLASInt   bm, one = 1, info;

  PetscFunctionBeginUser;
  PetscCall(PetscBLASIntCast(m, &bm));
  for (PetscInt k = 0; k < m; ++k) s[k] = PetscSqrtReal(PetscMax(c->D[k * m + k], c->floor[k]));
  for (PetscInt it = 0; it < 200; ++it, mu = mu > 0 ? 4 * mu : 1e-12) {
    PetscBool ok = PETSC_TRUE;
    for (PetscInt k = 0; k < m; ++k) {
      ru[k] = r[k];
      for (PetscInt l = 0; l < m; ++l) Au[k * m + l] = c->S[k * m + l] + (k == l ? mu * s[k] * s[k] : 0.0);
    }
    UnheldConstrain(c->unheld, Au, ru);
    for (PetscInt k = 0; k < m; ++k)
      for (PetscInt l = 0; l < m; ++l) A[k * m + l] = Au[k * m + l] / (s[k] * s[l]);
    PetscCallBLAS("LAPACKpotrf", LAPACKpotrf_("L", &bm, A, &bm, &info));
    if (info) continue;
    for (PetscInt k = 0; k < m; ++k) ok = (PetscBool)(ok && PetscSqr(PetscRealPart(A[k * m + k])) > 1e-9);
    if (!ok) continue;
    for (PetscInt k = 0; k < m; ++k) y[k] = ru[k] / s[k];
    PetscCallBLAS("LAPACKpotrs", LAPACKpotrs_("L", &bm, &one, A, &bm, y, &bm, &info));
    PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "force control: potrs info %d", (int)info);
    for (PetscInt k = 0; k < m; ++k) {
      dU[k] = PetscRealPart(y[k]) / s[k];
      ok    = (PetscBool)(ok && PetscAbsReal(dU[k]) <= c->cap[k]);
    }
    if (!ok) continue;
    if (mu > 0) PetscCall(PetscInfo(NULL, "force control: the step in the controls regularised by mu = %g (dU_0 = %g, cap %g)\n", (double)mu, (double)dU[0], (double)c->cap[0]));
    PetscFunctionReturn(0);
  }
  SETERRQ(c->comm, PETSC_ERR_LIB, "force control: no step of the controlled displacements within -force_control_step (the controls' stiffness S_00 = %g)", (double)c->S[0]);
}

/* w = Hin^-1 r_u and B^T w (bw), in y: by a solve, or the first half of
   one through kin's PC. */
static PetscErrorCode BorderSolveFirst(BorderCtx *c, PetscReal bw[])
{
  PetscScalar bws[CONTACT_MAX_CONTROLS];

  PetscFunctionBeginUser;
  if (c->fast) {
    PetscCall(ContactBorderPCCondense(c->fast, c->wx, bw));
    PetscFunctionReturn(0);
  }
  PetscCall(KSPSolve(c->kin, c->wx, c->wy));
  PetscCall(VecMDot(c->wy, c->m, c->B, bws));
  for (PetscInt k = 0; k < c->m; ++k) bw[k] = PetscRealPart(bws[k]);
  PetscFunctionReturn(0);
}

/* du = w - Z dU = Hin^-1 (r_u - B dU), in y. */
static PetscErrorCode BorderSolveSecond(BorderCtx *c, const PetscReal dU[])
{
  PetscScalar mdU[CONTACT_MAX_CONTROLS];

  PetscFunctionBeginUser;
  if (c->fast) {
    PetscCall(ContactBorderPCExpand(c->fast, dU, c->wy));
    PetscFunctionReturn(0);
  }
  for (PetscInt k = 0; k < c->m; ++k) mdU[k] = -dU[k];
  PetscCall(VecMAXPY(c->wy, c->m, mdU, c->Z));
  PetscFunctionReturn(0);
}

static PetscErrorCode BorderPCApply(PC pc, Vec r, Vec z)
{
  BorderCtx         *c;
  Mat                M;
  const PetscScalar *ra;
  PetscScalar       *za;
  PetscReal          rU[CONTACT_MAX_CONTROLS], rhs[CONTACT_MAX_CONTROLS], dU[CONTACT_MAX_CONTROLS], bw[CONTACT_MAX_CONTROLS];

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &M));
  PetscCall(MatShellGetContext(M, &c));
  PetscCall(BorderSetUpSchur(c));
  PetscCall(PetscLogEventBegin(BorderSolve, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(r, &ra));
  PetscCall(VecGetArray(z, &za));
  PetscCall(BorderGetU(c, ra, rU));
  PetscCall(VecPlaceArray(c->wx, ra));
  PetscCall(VecPlaceArray(c->wy, za));
  PetscCall(BorderSolveFirst(c, bw));
  for (PetscInt k = 0; k < c->m; ++k) rhs[k] = rU[k] - bw[k];
  PetscCall(BorderSolveControls(c, rhs, dU));
  PetscCall(BorderSolveSecond(c, dU));
  PetscCall(VecResetArray(c->wx));
  PetscCall(VecResetArray(c->wy));
  if (!c->rank)
    for (PetscInt k = 0; k < c->m; ++k) za[c->nloc + k] = dU[k];
  PetscCall(VecRestoreArrayRead(r, &ra));
  PetscCall(VecRestoreArray(z, &za));
  PetscCall(PetscLogEventEnd(BorderSolve, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode BorderMatDestroy(Mat M)
{
  BorderCtx *c;

  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(M, &c));
  for (PetscInt k = 0; k < c->m; ++k) {
    PetscCall(VecDestroy(&c->B[k]));
    PetscCall(VecDestroy(&c->Z[k]));
  }
  PetscCall(VecDestroy(&c->wx));
  PetscCall(VecDestroy(&c->wy));
  PetscCall(MatDestroy(&c->Hin));
  PetscCall(KSPDestroy(&c->kin));
  PetscCall(PetscFree(c));
  PetscFunctionReturn(0);
}

PetscErrorCode ForceBorderMatCreate(Problem p, Mat Hin, KSP kin, Mat *M)
{
  BorderCtx *c;
  PetscInt   n, N;

  PetscFunctionBeginUser;
  if (!BorderSetUp) {
    PetscClassId id;
    PetscCall(PetscClassIdRegister("ContactForceBorder", &id));
    PetscCall(PetscLogEventRegister("ForceBorderSetUp", id, &BorderSetUp));
    PetscCall(PetscLogEventRegister("ForceBorderSolve", id, &BorderSolve));
  }
  PetscCall(PetscNew(&c));
  c->comm = p->comm;
  PetscCallMPI(MPI_Comm_rank(p->comm, &c->rank));
  c->m = p->fc.n;
  PetscCall(VecGetLocalSize(p->Xb, &c->nloc));
  for (PetscInt k = 0; k < c->m; ++k) {
    PetscCall(PetscObjectReference((PetscObject)p->fc.B[k]));
    c->B[k]   = p->fc.B[k];
    c->cap[k] = p->cfg->control.step * p->fc.c[k].L;
  }
  for (PetscInt k = 0; k < c->m; ++k) { /* 3D: within the contact's reach (forcereach.c) */
    PetscReal reach;
    PetscCall(ForceControlContactReach(p, k, &reach));
    if (reach > 0.0 && reach < c->cap[k]) {
      PetscCall(PetscInfo(NULL, "force control: control %" PetscInt_FMT "'s step held to the contact's reach %g (not %g)\n", k, (double)reach, (double)c->cap[k]));
      c->cap[k] = reach;
    }
  }
  c->solves = p->cfg->control.borderSolves;
  c->D = p->fc.D;
  for (PetscInt k = 0; k < c->m; ++k) c->floor[k] = p->fc.c[k].motion ? p->fc.c[k].kref : 0.0;
  c->varies = p->fc.rigid; /* a rigid body's columns change with the Hessian: condensed anew at each */
  c->unheld = &p->fc.unheld;
  PetscCall(PetscObjectReference((PetscObject)Hin));
  c->Hin = Hin;
  if (kin) PetscCall(PetscObjectReference((PetscObject)kin));
  c->kin = kin;
  PetscCall(VecCreateMPIWithArray(p->comm, 1, c->nloc, PETSC_DECIDE, NULL, &c->wx));
  PetscCall(VecCreateMPIWithArray(p->comm, 1, c->nloc, PETSC_DECIDE, NULL, &c->wy));
  PetscCall(VecGetLocalSize(p->X, &n));
  PetscCall(VecGetSize(p->X, &N));
  PetscCall(MatCreateShell(p->comm, n, n, N, N, c, M));
  PetscCall(MatShellSetOperation(*M, MATOP_MULT, (void (*)(void))BorderMatMult));
  PetscCall(MatShellSetOperation(*M, MATOP_DESTROY, (void (*)(void))BorderMatDestroy));
  PetscCall(MatSetOption(*M, MAT_SYMMETRIC, PETSC_TRUE));
  PetscFunctionReturn(0);
}

PetscErrorCode ForceBorderPCSetUp(Mat M, PC pc)
{
  BorderCtx *c;

  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(M, &c));
  PetscCheck(c->kin, c->comm, PETSC_ERR_ARG_WRONGSTATE, "force control: the bordered Hessian has no solve of its bodies' part");
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, M)); /* not referenced: the matrix is the PC's operator, and outlives it in the problem */
  PetscCall(PCShellSetApply(pc, BorderPCApply));
  PetscCall(PCShellSetName(pc, "force control: the bodies' step bordered by the controlled displacements (eliminated around the bodies' solve)"));
  PetscFunctionReturn(0);
}
