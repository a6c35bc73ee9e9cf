/* Newton steps through the Schur complement on the contact surfaces.

   Order the unknowns as interior dofs i and contact-surface dofs c. The
   Gauss-Newton Hessian is H = K + C where K, the elastic stiffness, does not
   depend on u, and the contact Hessian C has nonzeros only in the c block:

       H = [ K_ii  K_ic        ]      S(u) = K_cc + C_cc - K_ci K_ii^-1 K_ic
           [ K_ci  K_cc + C_cc ]           = S_K + C_cc

   with S_K the Schur complement of K. So K is factored once, by MUMPS with c as
   its Schur block (ICNTL(19)), which also yields S_K; each Newton step then
   replaces the factor's Schur block by S_K + C_cc = T0 + H_cc, with
   T0 = S_K - K_cc formed once, and MUMPS solves H z = r exactly through it
   (condensation on c, a dense factorisation of the n_c x n_c block,
   expansion). The sparse factorisation is done once per solve instead of once
   per step; a step costs a dense factorisation of the surface block and two
   triangular solves.
   The PC is exact for the assembled H (so preonly is a true Newton step). */
#include "schur.h"

typedef struct {
  IS  isc;    /* contact-surface dofs */
  Mat F;      /* MUMPS Cholesky of K with Schur block on isc */
  Mat T0;     /* S_K - K_cc, dense */
  Mat Hcc;    /* c block of the current Hessian */
  const PetscBool *exact; /* the Hessian has its second-order term: may be indefinite (sytrf; else potrf) */
} SchurCtx;

static PetscLogEvent SchurFactorK = 0, SchurStep;

static PetscErrorCode SchurPCSetUp(PC pc)
{
  SchurCtx *ctx;
  Mat       H, Sf;
  MatFactorSchurStatus status;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &ctx));
  PetscCall(PCGetOperators(pc, NULL, &H));
  PetscCall(PetscLogEventBegin(SchurStep, 0, 0, 0, 0));
  PetscCall(MatDestroy(&ctx->Hcc)); /* the contact Hessian's pattern changes with the active set */
  PetscCall(MatCreateSubMatrix(H, ctx->isc, ctx->isc, MAT_INITIAL_MATRIX, &ctx->Hcc));
  PetscCall(MatFactorGetSchurComplement(ctx->F, &Sf, &status));
  PetscCall(MatSetUnfactored(Sf)); /* factored in place by the previous step */
  PetscCall(MatCopy(ctx->T0, Sf, SAME_NONZERO_PATTERN));
  PetscCall(MatAXPY(Sf, 1.0, ctx->Hcc, DIFFERENT_NONZERO_PATTERN));
  PetscCall(MatSetOption(Sf, MAT_SPD, (PetscBool)!*ctx->exact)); /* Gauss-Newton: LAPACK potrf, not sytrf */
  PetscCall(MatFactorRestoreSchurComplement(ctx->F, &Sf, MAT_FACTOR_SCHUR_UNFACTORED));
  PetscCall(PetscLogEventEnd(SchurStep, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode SchurPCApply(PC pc, Vec r, Vec z)
{
  SchurCtx *ctx;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &ctx));
  PetscCall(MatSolve(ctx->F, r, z));
  PetscFunctionReturn(0);
}

static PetscErrorCode SchurPCDestroy(PC pc)
{
  SchurCtx *ctx;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &ctx));
  PetscCall(ISDestroy(&ctx->isc));
  PetscCall(MatDestroy(&ctx->F));
  PetscCall(MatDestroy(&ctx->T0));
  PetscCall(MatDestroy(&ctx->Hcc));
  PetscCall(PetscFree(ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactSchurPCSetUp(PC pc, Mat K, IS surface, const PetscBool *exact)
{
  SchurCtx     *ctx;
  MatFactorInfo info;
  Mat           Kcc, S;
  MatFactorSchurStatus status;

  PetscFunctionBeginUser;
  if (!SchurFactorK) {
    PetscClassId id;
    PetscCall(PetscClassIdRegister("ContactSchur", &id));
    PetscCall(PetscLogEventRegister("SchurFactorK", id, &SchurFactorK));
    PetscCall(PetscLogEventRegister("SchurStep", id, &SchurStep));
  }
  PetscCall(PetscNew(&ctx));
  ctx->exact = exact;
  PetscCall(PetscObjectReference((PetscObject)surface));
  ctx->isc = surface;
  {
    PetscInt nc;
    PetscCall(ISGetSize(ctx->isc, &nc));
    PetscCall(PetscInfo(pc, "Schur block: %" PetscInt_FMT " contact-surface dofs\n", nc));
  }
  PetscCall(PetscLogEventBegin(SchurFactorK, 0, 0, 0, 0));
  PetscCall(MatGetFactor(K, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &ctx->F));
  PetscCall(MatFactorSetSchurIS(ctx->F, ctx->isc));
  PetscCall(MatFactorInfoInitialize(&info));
  PetscCall(MatCholeskyFactorSymbolic(ctx->F, K, NULL, &info));
  PetscCall(MatCholeskyFactorNumeric(ctx->F, K, &info));
  PetscCall(MatFactorCreateSchurComplement(ctx->F, &S, &status));
  PetscCall(MatCreateSubMatrix(K, ctx->isc, ctx->isc, MAT_INITIAL_MATRIX, &Kcc));
  PetscCall(MatAXPY(S, -1.0, Kcc, DIFFERENT_NONZERO_PATTERN));
  ctx->T0 = S;
  PetscCall(MatDestroy(&Kcc));
  PetscCall(PetscLogEventEnd(SchurFactorK, 0, 0, 0, 0));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, ctx));
  PetscCall(PCShellSetSetUp(pc, SchurPCSetUp));
  PetscCall(PCShellSetApply(pc, SchurPCApply));
  PetscCall(PCShellSetDestroy(pc, SchurPCDestroy));
  PetscCall(PCShellSetName(pc, "contact Schur: K factored once (MUMPS), dense surface block per step"));
  PetscFunctionReturn(0);
}
