/* The Newton step's linear solve (nls, ntr): the KSP and preconditioner of
   the Hessian, chosen by the options: the Schur complement on the contact
   surfaces (substructure.c on any number of ranks, schur.c on one), a
   direct Cholesky factorisation, or CG with GAMG (iterative.c); with
   coupled force control, the bordered Hessian's solve around it
   (forceborder.c). The orchestrator (solve.c) sets it up; L-BFGS's H0
   (lmvm.c) shares its Cholesky. */
#include "newtonstep.h"
#include "problem.h"
#include "schur.h"
#include "substructure.h"
#include "iterative.h"
#include "forceborder.h"
#include "tangentswitch.h"

const char *const SchurTypes[]   = {"substructure", "mumps", "SchurType", "SCHUR_", NULL};

/* MUMPS's factorisation works in an array sized at the analysis, from the
   pattern alone, plus ICNTL(14) per cent (20 by default). An indefinite
   Hessian (a neohookean body's tangent with the exact contact Hessian)
   delays pivots up the elimination tree, and on several ranks the
   factorisation can outgrow that margin: MUMPS stops with INFOG(1) = -9,
   PETSc marks the factor failed (FACTOR_OUTMEMORY) and Newton's step is
   lost. TAO then takes gradient steps, which zigzag and stop: a rigid
   cylinder on a neohookean pad at -tangent_at_rest 0, h = 0.06, diverged on
   2 ranks with -partitioner simple (at the first exact-Hessian step of its
   last stage) where 1 rank, metis and ptscotch converged
   (tests/test_ranks_neohookean.py). 100 % leaves room enough (30 % already
   passed there);
   -<prefix>mat_mumps_icntl_14 sets another. Set as the option's default
   (MUMPS reads its controls from the options when it creates the factor)
   and marked read, so that a run that never factors does not report it
   unused. */
#define CHOLESKY_MUMPS_WORKSPACE "100"

static PetscErrorCode ContactPCSetMumpsWorkspace(PC pc)
{
  const char *prefix;
  char        name[256];
  PetscBool   given;

  PetscFunctionBeginUser;
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCall(PetscSNPrintf(name, sizeof(name), "-%smat_mumps_icntl_14", prefix ? prefix : ""));
  PetscCall(PetscOptionsHasName(NULL, NULL, name, &given));
  if (!given) {
    PetscCall(PetscOptionsSetValue(NULL, name, CHOLESKY_MUMPS_WORKSPACE));
    PetscCall(PetscOptionsHasName(NULL, NULL, name, &given)); /* marks it read */
  }
  PetscFunctionReturn(0);
}

/* A direct solve by Cholesky: CHOLMOD on one rank, MUMPS on several, and
   MUMPS's LDL^T for a matrix that may be indefinite. */
PetscErrorCode ContactPCSetCholesky(PC pc, MPI_Comm comm, PetscBool indefinite)
{
  PetscMPIInt size;
  PetscBool   mumps;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  mumps = (PetscBool)(size > 1 || indefinite);
  PetscCall(PCSetType(pc, PCCHOLESKY));
  PetscCall(PCFactorSetMatSolverType(pc, mumps ? MATSOLVERMUMPS : MATSOLVERCHOLMOD));
  if (mumps) PetscCall(ContactPCSetMumpsWorkspace(pc));
  PetscFunctionReturn(0);
}

/* The Schur complement on the contact surfaces of K (set up): MUMPS's on one
   rank with -newton_schur_type mumps, else by substructuring. */
PetscErrorCode ProblemSchurPCSetUp(Problem p, PC pc)
{
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  if (p->cfg->newton.schurType == SCHUR_MUMPS && size == 1) PetscCall(ContactSchurPCSetUp(pc, p->K, p->surfaceDofs, &p->exactHessian));
  else PetscCall(ContactSubstructurePCSetUp(pc, p->K, p->surfaceDofs, p->nbodies, p->offset, p->cfg->newton.splitLU, &p->sub));
  PetscFunctionReturn(0);
}

/* Newton types (nls, ntr): the Hessian changes only in the contact-surface
   block, so the step goes through the Schur complement on that block, K
   condensed once: by substructuring on any number of ranks
   (substructure.c), or on one rank by MUMPS's Schur complement of K
   (schur.c, -newton_schur_type mumps). Without contact, with
   -newton_schur 0, or where a body's tangent depends on u (a neohookean
   body, unless -tangent_at_rest puts the stiffness at rest in its place:
   the whole Hessian changes, and may be indefinite; where -tangent_at_rest
   is not given, either at each Hessian, tangentswitch.c), a Cholesky
   factorisation per step (CHOLMOD on one rank, MUMPS on several; MUMPS's
   LDL^T where the Hessian may be indefinite); -newton_iterative: CG with
   GAMG (iterative.c). nls takes
   the factored step directly (preonly); at most 500 iterations (TAO's 50 are
   too few for k_p / E above 1e7). Set before TaoSetFromOptions(), so that
   -tao_max_it, -newton_schur 0, -tao_nls_ksp_type, -tao_nls_pc_type, ...
   override them and -help shows them. Without a set-up problem (-help) the
   Schur preconditioner is only named. */
static PetscErrorCode ProblemSetUpStepKSP(Problem p, KSP ksp, PetscBool nls)
{
  PC          pc;
  PetscMPIInt size;
  PetscBool   varies = ProblemTangentReassembled(p); /* a body's tangent depends on u (neohookean): K is no longer condensed once */
  PetscBool   choose = ProblemTangentChosen(p);      /* or chosen at each Hessian (tangentswitch.c) */

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  if (nls) PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  p->tangentAuto = PETSC_FALSE;
  if (p->cfg->newton.iterative) {
    if (p->K) PetscCall(ContactIterativeKSPSetUp(ksp, p->H, p->nbodies, p->bodies, (PetscBool)(p->nterms == 0 && !varies && !choose), &p->cfg->newton));
  } else if (p->cfg->newton.schur && p->nterms > 0 && choose && p->K) {
    PC rest, full;
    PetscCheck(p->cfg->newton.schurType != SCHUR_MUMPS || size == 1, p->comm, PETSC_ERR_USER_INPUT, "option -newton_schur_type mumps: one rank only (MUMPS Schur complements are sequential in PETSc 3.18); use substructure on %d ranks", (int)size);
    PetscCall(PCCreate(p->comm, &rest));
    PetscCall(PCSetOperators(rest, p->H, p->H));
    PetscCall(ProblemSchurPCSetUp(p, rest));
    PetscCall(PCCreate(p->comm, &full));
    PetscCall(PCSetOperators(full, p->H, p->H));
    PetscCall(ContactPCSetCholesky(full, p->comm, PETSC_TRUE));
    PetscCall(ContactTangentSwitchPCSetUp(pc, rest, full, &p->tangentFull));
    PetscCall(PCDestroy(&rest));
    PetscCall(PCDestroy(&full));
    p->tangentAuto = PETSC_TRUE;
  } else if (p->cfg->newton.schur && p->nterms > 0 && !varies) {
    PetscCheck(p->cfg->newton.schurType != SCHUR_MUMPS || size == 1, p->comm, PETSC_ERR_USER_INPUT, "option -newton_schur_type mumps: one rank only (MUMPS Schur complements are sequential in PETSc 3.18); use substructure on %d ranks", (int)size);
    if (!p->K) PetscCall(PCSetType(pc, PCSHELL));
    else PetscCall(ProblemSchurPCSetUp(p, pc));
  } else PetscCall(ContactPCSetCholesky(pc, p->comm, (PetscBool)(varies || p->cfg->hessian.type != HESSIAN_GAUSS_NEWTON)));
  PetscFunctionReturn(0);
}

/* 3D scenes with contact pairs: the contact surfaces' dofs nc, and whether
   the Schur step's dense surface blocks fit (nc at most
   -newton_schur_surface_dofs, or -newton_schur given); other scenes: 0, yes. */
PetscErrorCode ProblemSchurStepFits(Problem p, PetscInt *nc, PetscBool *fits)
{
  PetscFunctionBeginUser;
  *nc   = 0;
  *fits = PETSC_TRUE;
  if (!p->Xb || ProblemGetDimension(p) != 3 || p->nterms == 0) PetscFunctionReturn(0);
  if (p->surfaceDofs) PetscCall(ISGetSize(p->surfaceDofs, nc));
  *fits = (PetscBool)(p->cfg->newton.schurSet || *nc <= p->cfg->newton.schurSurfaceDofs);
  PetscFunctionReturn(0);
}

/* The direct step or CG + GAMG where the user chose neither
   (-newton_iterative): 2D and r-z scenes keep the direct step (their
   results do not move); a 3D scene takes CG + GAMG above
   -newton_iterative_dofs, where a factorisation's fill, growing as N^(4/3)
   in 3D against the multigrid's N, costs more time and memory
   (bench/solid3d/RESULTS.md: the crossing on elastic blocks). A 3D scene
   with contact pairs keeps the direct step at any size: on the quarter
   Hertz ball the direct step took a third of CG + GAMG's CPU time at 22k
   and 66k dofs (2.7 s against 9.5 s, 19 s against 54 s, one rank:
   docs/solver.md), by the Schur step up to -newton_schur_surface_dofs
   contact-surface dofs and by the whole Hessian's factorisation above,
   where the Schur step's dense blocks (8 nc^2 bytes and more) would not
   fit (docs/solver.md, "3D contact: the Schur step or the whole
   Hessian"). Said in one line.
   With contact, CG + GAMG (forced) aggregates the nodes on one level, not
   on the cells' vertices first (-newton_iterative_two_levels), unless that
   is given: the vertices' linear displacements cannot meet the mortar's
   penalty on the quadratic faces, and the two-level preconditioned Hessian
   of the ball at h = 0.04 spreads its spectrum over 0.038 to 520 (without
   contact 0.26 to 1.0): CG stalled at 1e-3 for thousands of iterations,
   where GAMG on the nodes takes 24 to 75. */
static PetscErrorCode ProblemChooseNewtonStep(Problem p)
{
  PetscInt N;

  PetscFunctionBeginUser;
  if (!p->Xb || ProblemGetDimension(p) != 3) PetscFunctionReturn(0);
  if (p->nterms > 0 && !p->cfg->newton.iterativeTwoLevelsSet) p->cfg->newton.iterativeTwoLevels = PETSC_FALSE;
  if (p->cfg->newton.iterativeSet) PetscFunctionReturn(0);
  PetscCall(VecGetSize(p->Xb, &N));
  if (p->nterms > 0) {
    PetscInt  nc;
    PetscBool fits;
    p->cfg->newton.iterative = PETSC_FALSE;
    PetscCall(ProblemSchurStepFits(p, &nc, &fits));
    if (p->cfg->newton.schur && !fits) {
      p->cfg->newton.schur = PETSC_FALSE;
      PetscCall(PetscPrintf(p->comm, "Newton step: direct factorisation of the whole Hessian (3D, %" PetscInt_FMT " dofs, with contact pairs on %" PetscInt_FMT " surface dofs, above -newton_schur_surface_dofs %" PetscInt_FMT ": the Schur step's dense surface blocks would take some %.0f MB; -newton_schur 1 forces it, -newton_iterative 1 CG + GAMG)\n", N, nc,
                            p->cfg->newton.schurSurfaceDofs, 8.0 * (double)nc * (double)nc / 1048576.0));
      PetscFunctionReturn(0);
    }
    PetscCall(PetscPrintf(p->comm, "Newton step: direct factorisation (3D, %" PetscInt_FMT " dofs, with contact pairs; -newton_iterative 1 forces CG + GAMG)\n", N));
    PetscFunctionReturn(0);
  }
  p->cfg->newton.iterative = (PetscBool)(N > p->cfg->newton.iterativeDofs);
  PetscCall(PetscPrintf(p->comm, "Newton step: %s (3D, %" PetscInt_FMT " dofs, %s -newton_iterative_dofs %" PetscInt_FMT "; -newton_iterative 0 or 1 forces either)\n",
                        p->cfg->newton.iterative ? "CG + GAMG" : "direct factorisation", N, p->cfg->newton.iterative ? "above" : "at most", p->cfg->newton.iterativeDofs));
  PetscFunctionReturn(0);
}

/* The Newton KSP as above; with coupled force control the Hessian TAO sees
   is H bordered by the controls, and its step eliminates them around a KSP
   of H set up as above (forceborder.c). */
PetscErrorCode ProblemSetNewtonDefaults(Problem p)
{
  PetscBool nls;
  KSP       ksp;

  PetscFunctionBeginUser;
  PetscCall(ProblemChooseNewtonStep(p));
  PetscCall(PetscObjectTypeCompare((PetscObject)p->tao, TAONLS, &nls));
  PetscCall(TaoSetMaximumIterations(p->tao, 500));
  PetscCall(TaoGetKSP(p->tao, &ksp));
  if (p->fc.coupled && p->K) {
    PC pc;
    PetscCall(KSPCreate(p->comm, &p->fc.ksp));
    PetscCall(KSPSetOperators(p->fc.ksp, p->H, p->H));
    PetscCall(ProblemSetUpStepKSP(p, p->fc.ksp, PETSC_TRUE));
    PetscCall(MatDestroy(&p->Htao));
    PetscCall(ForceBorderMatCreate(p, p->H, p->fc.ksp, &p->Htao));
    if (nls) PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(ForceBorderPCSetUp(p->Htao, pc));
  } else PetscCall(ProblemSetUpStepKSP(p, ksp, nls));
  PetscFunctionReturn(0);
}

PetscErrorCode NewtonOptionsSetFromOptions(MPI_Comm comm, NewtonOptions *o)
{
  PetscFunctionBeginUser;
  o->iterative        = PETSC_FALSE;
  o->iterativeSet     = PETSC_FALSE;
  o->iterativeDofs    = NEWTON_ITERATIVE_DOFS;
  o->schur            = PETSC_TRUE;
  o->schurSet         = PETSC_FALSE;
  o->schurSurfaceDofs = NEWTON_SCHUR_SURFACE_DOFS;
  o->schurType        = SCHUR_SUBSTRUCTURE;
  o->tangentAtRest    = PETSC_FALSE;
  o->tangentAtRestSet = PETSC_FALSE;
  o->tangentIts       = 10;
  o->iterativeNodal     = PETSC_TRUE;
  o->iterativeTwoLevels = PETSC_TRUE;
  o->iterativeTwoLevelsSet = PETSC_FALSE;
  o->iterativeCycle     = PC_MG_CYCLE_W;
  o->splitLU            = NEWTON_SCHUR_SPLIT_LU;
  PetscOptionsBegin(comm, NULL, "Newton step options", NULL);
  PetscCall(PetscOptionsBool("-newton_iterative", "Newton steps by CG preconditioned by GAMG with the bodies' rigid motions as near-nullspace (no factorisation; for problems a direct solver cannot hold); 0 forces the direct step. Default: 2D and r-z scenes and 3D scenes with contact direct; other 3D scenes CG + GAMG above -newton_iterative_dofs, direct at or below", NULL, o->iterative, &o->iterative, &o->iterativeSet));
  PetscCall(PetscOptionsInt("-newton_iterative_dofs", "3D scenes without -newton_iterative: Newton steps by CG + GAMG above this many dofs, by the direct factorisation at or below (bench/solid3d/RESULTS.md)", NULL, o->iterativeDofs, &o->iterativeDofs, NULL));
  PetscCall(PetscOptionsBool("-newton_iterative_nodal", "3D bodies, CG + GAMG: GAMG aggregates nodes, on the Hessian with each node's 3 components (a constrained one an identity row); 0: on the Hessian's free dofs alone", NULL, o->iterativeNodal, &o->iterativeNodal, NULL));
  PetscCall(PetscOptionsBool("-newton_iterative_two_levels", "3D bodies on one rank, GAMG by nodes: first a level of the cells' vertices (linear interpolation to the quadratic nodes, Chebyshev on the nodes), GAMG (smoothed aggregation) on it; 0: GAMG on the nodes. Default: true without contact, false with contact pairs (the vertices cannot meet the penalty)", NULL, o->iterativeTwoLevels, &o->iterativeTwoLevels, &o->iterativeTwoLevelsSet));
  PetscCall(PetscOptionsEnum("-newton_iterative_cycle", "3D bodies, GAMG by nodes: its multigrid cycle (v or w)", NULL, PCMGCycleTypes, (PetscEnum)o->iterativeCycle, (PetscEnum *)&o->iterativeCycle, NULL));
  PetscCall(PetscOptionsBool("-newton_schur", "Newton steps through the Schur complement on the contact surfaces (K condensed once, a dense surface block per step); 0: the whole Hessian factored at each step. Default: true, except a 3D scene with more than -newton_schur_surface_dofs contact-surface dofs", NULL, o->schur, &o->schur, &o->schurSet));
  PetscCall(PetscOptionsInt("-newton_schur_surface_dofs", "3D scenes with contact pairs, without -newton_schur or -newton_iterative: the Schur step up to this many contact-surface dofs (its dense blocks take 8 bytes times their square and more), the whole Hessian factored at each step above", NULL, o->schurSurfaceDofs, &o->schurSurfaceDofs, NULL));
  PetscCall(PetscOptionsInt("-newton_schur_split_lu", "Substructured Newton step on several ranks: the ranks share the factorisation of the contact zone's capacitance matrix (ScaLAPACK) when its order is at least this, each repeats it whole (LAPACK) below", NULL, o->splitLU, &o->splitLU, NULL));
  PetscCall(PetscOptionsEnum("-newton_schur_type", "Schur complement of the Newton step: substructure (each rank condenses its subdomain; any number of ranks) or mumps (K factored by MUMPS with the surfaces as Schur block; one rank)", NULL, SchurTypes, (PetscEnum)o->schurType, (PetscEnum *)&o->schurType, NULL));
  PetscCall(PetscOptionsBool("-tangent_at_rest", "Newton's step and L-BFGS's H0 take the bodies' stiffness at rest in place of a neohookean body's tangent (modified Newton: the linear bodies' Schur step, K condensed once, the gradient still the material's; for small strain); false: the tangent at every step. Default: with Newton the stiffness at rest for -tangent_at_rest_its iterations, then the tangent; true with lmvm/blmvm (H0 then has the contact's Hessian)", NULL, o->tangentAtRest, &o->tangentAtRest, &o->tangentAtRestSet));
  PetscCall(PetscOptionsInt("-tangent_at_rest_its", "Newton without -tangent_at_rest: the stiffness at rest for at most this many iterations of each solve, and only while two steps divide the gradient by more than 2, then a neohookean body's tangent (modified Newton while it converges fast, Newton's quadratic convergence where it would be slow)", NULL, o->tangentIts, &o->tangentIts, NULL));
  PetscOptionsEnd();
  PetscCheck(o->iterativeDofs >= 0, comm, PETSC_ERR_USER_INPUT, "option -newton_iterative_dofs: must be at least 0, got %" PetscInt_FMT, o->iterativeDofs);
  PetscCheck(o->schurSurfaceDofs >= 0, comm, PETSC_ERR_USER_INPUT, "option -newton_schur_surface_dofs: must be at least 0, got %" PetscInt_FMT, o->schurSurfaceDofs);
  PetscCheck(o->splitLU >= 1, comm, PETSC_ERR_USER_INPUT, "option -newton_schur_split_lu: must be at least 1, got %" PetscInt_FMT, o->splitLU);
  PetscCheck(o->tangentIts >= 0, comm, PETSC_ERR_USER_INPUT, "option -tangent_at_rest_its: must be at least 0, got %" PetscInt_FMT, o->tangentIts);
  PetscFunctionReturn(0);
}
