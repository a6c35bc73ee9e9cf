/* L-BFGS (TAO's lmvm and blmvm): the initial Hessian H0 and the screening of
   the correction pairs.

   L-BFGS applies to the gradient g the inverse of B, the BFGS update of H0 by
   its correction pairs (s, y) = (x_k - x_{k-1}, g_k - g_{k-1}):
       B^-1 = V^T H0^-1 V + s s^T / (y^T s),   V = I - y s^T / (y^T s)
   (one pair; TAO's two-loop recursion nests more).

   -lmvm_h0 contact (the default): H0 = K + C(x), K the elastic stiffness, C
   the contact's Gauss-Newton Hessian at the current iterate (positive
   semi-definite, so H0 stays SPD whatever -contact_hessian says). H0^-1 is
   the Newton step's Schur-complement solve (schur.c, substructure.c): K is
   condensed once, each set-up of H0 redoes only the dense contact block;
   where the Newton step would not take it (-newton_schur 0, or a 3D scene
   with more contact-surface dofs than -newton_schur_surface_dofs, whose
   dense blocks would not fit: ProblemSchurStepFits), H0 is factored whole
   by Cholesky at each set-up.
   H0 is set up at the first iterate of every TAO solve and then every
   -lmvm_h0_refresh iterations (the JSON's h0_refreshes counts them). What
   H0 leaves out is the second-order term of the gap (the tangential,
   sliding modes) and, between set-ups, the change of C; one pair, the
   default history, is what learns it (at h = 0.03: 27 iterations with 1,
   42 with 2, 58 with TAO's 5).
   -lmvm_h0 elastic: H0 = K, factorised once (-h0_pc_type to change).

   Screening. Along s the energy's mean curvature is y^T s / s^T s; H0's is
   s^T H0 s / s^T s. Where the active set is the same at both ends of s the
   two differ by the second-order term and the change of C, and their ratio
       r = y^T s / s^T H0 s
   is near 1. Where contact points opened or closed along s, y holds the
   penalty stiffness k_p of points that H0 (built at x_k) has not, or lacks
   that of points it has: at k_p / E = 1e7 r reaches 1e4 or 1e-4, and the
   update then bends B^-1 along s by that factor, a step 1e4 times too long
   or short, which the line search cannot repair in its 30 evaluations. So
   a pair with r outside [1/R, R] (R = -lmvm_pair_ratio) is dropped (the
   LMVM matrix's history reset: the step is then H0's, the Gauss-Newton step
   at x_k), and the next pair, on one side of the kinks, starts it anew.
   TAO's own test (y^T s > eps s^T s) only rejects pairs of negative
   curvature. Measured on the half scene at k_p = 1e10, push 0.3 (gpts and
   mortar, h = 0.25 and 0.1, no continuation): 67, 56, 127 and 80 iterations
   with R = 10 (the default), 135, 58, 236 and 215 keeping every pair, 89 to
   198 with R = 100; at the reference scene (h = 0.03) it drops one pair and
   costs 4 iterations of 27.

   The line search. Where a step closes contact at a stiff penalty the energy
   along it rises by the penalty's factor past the kink (f(1) = 1e8 f(0) on the
   first step from rest at k_p = 1e10); More-Thuente's cubic steps then creep
   up on the kink from both sides and use TAO's 30 evaluations before they
   reach it. 100 evaluations (-tao_ls_max_funcs, the default here) let it
   converge on every case of the robustness sweep where 30 stopped 3 of the 4
   at k_p = 1e10.

   Restarts. When its line search fails, TAO 3.18's lmvm means to retry along
   the H0 step with an empty history but passes the wrong vectors to its solve
   (the iterate as right-hand side, into the gradient), so every failure ends
   the solve; blmvm's retry is right. A solve that stopped so after lowering
   the energy is restarted from where it stopped (an empty history, H0 at that
   iterate, the same stopping test) at most -lmvm_restarts times.

   Continuation. The active set moves the most in the first iterations, where
   every pair straddles kinks; at a soft penalty those kinks are mild. Where
   neither the user nor the scene chose a continuation, lmvm and blmvm solve
   in penalty stages a factor of at most 32 apart (LMVM_STAGE_FACTOR, as the
   automatic penalty's 2 stages from 0.03), from 1e-3 k_p or, if that is
   softer, from where the stiffest pair's k_p h / E* is 1
   (LMVM_START_STIFFNESS): 3 stages up to k_p h / E* = 1000, the automatic
   penalty's (at h = 0.03 and k_p = 2e6 12 iterations against 31 in one
   stage); 4 on the reference scene at h = 0.03 and k_p = 1e8 (k_p h / E* =
   5.4e3: 14 iterations, 16 with 3 stages from 1e-3 k_p, 96 in one); 5 to 6
   at the robustness sweep's k_p = 1e10 (9.1e4 to 3.8e6). Why the first
   stage's own stiffness: from 1e-3 k_p alone, k_p = 1e10's first stage is
   at k_p h / E* = 91 to 3.8e3, and from rest each step of H0 = K + C(x)
   closes contact that C(x) does not hold; the energy at the full step rises
   100 to 10,000 times, the line search stops at the first kink (steps of
   1e-2 to 1e-4), and that stage alone takes 30 to 130 such steps, down which
   round-off sends 1 and 2 ranks different ways (iterations more than 10 %
   apart in 7 of the sweep's 30 pairs, a cutback in 6 of its 120 runs, the
   later stages alike). Measured on the half scene at k_p = 1e10, push p
   (bin/contact -options_file meshes/hertz-half/hertz-half.opts -mesh_size h
   -contact_penalty 1e10 -block_bc_push_values -p,0 -contact_formulation F
   -output none -tao_type lmvm [-penalty_stages n -penalty_start s]; k_p h /
   E* = 1.7e6 at h = 0.1, 5.4e5 at 0.03), iterations on 1 / 2 ranks:
       F, h, p            3 from 1e-3  4 from 1e-5  5 from 1e-6  6 from 1e-7  default
       gpts 0.1 0.3          53/59        32/32        31/31        30/30      30/30
       mortar 0.1 0.15       39/46        17/17        16/16        19/19      18/18
       mortar 0.1 0.3        71/128 (a)   22/22        22/22        22/22      21/21
       mortar 0.03 0.15      65/69        19/19        16/16        18/18      17/17
       gpts 0.03 0.3         64/59        39/41        37/37        35/35      36/36
       mortar 0.03 0.3       86/93        30/30        19/19        23/23      25/25
     (a) after a cutback on 2 ranks; the default is 6 stages at h = 0.1, 5
     at 0.03. The whole k_p = 1e10 part of the sweep (h = 0.25 to 0.005,
     both formulations, pushes 0.01 to 0.3; scripts/stress_sweep.py --kp 1e10
     --tao-type lmvm, and blmvm): 11 to 36 iterations (were 7 to 268, growing
     with 1/h), 1 and 2 ranks within 5 % in every pair and P within 1.9e-9,
     no cutback; the slowest run 46 s (was 158).

   The stopping test, where the penalty is not stiff (see the decrement
   test): -tao_gttol 1e-10 (Newton's is 1e-8). L-BFGS converges
   linearly, so it stops just below its tolerance, where Newton's last,
   quadratic, step lands far below it: at 1e-8 the contact force P was 2e-7
   to 2e-6 from Newton's (to 1e-12) at h = 0.03; at 1e-10 6e-11 there, for 2
   more iterations, and 2.1e-8 at h = 0.015 (1e-11: 8.5e-10, 2 iterations
   more; but at k_p = 1e10 1e-11 is below the gradient's round-off, where
   the mortar half scene at h = 0.25 stops and h = 0.1 takes 380 iterations
   instead of 70).

   The decrement test (-lmvm_decrement_rtol rtol). At
   k_p = 1e10 the gradient test leaves P 4.7e-8 apart between 1 and 2 ranks
   at h = 0.01, and its tighter value is below the gradient's round-off on
   coarse meshes. The Newton decrement in H0's norm,
       lambda^2 = g^T H0^-1 g,
   weighs each direction by its inverse stiffness: the soft modes (sliding,
   bending), whose displacement error g_s / mu_min the contact force follows,
   count fully; the contact's stiff directions, where the gradient's
   round-off lives (eps k_p |u|), are damped by 1/k_p. With rtol > 0 the last
   stage stops (TAO_CONVERGED_USER) when lambda <= rtol lambda_0, its
   gradient tolerances off (TAO's test still ends it for every other reason).
   lambda_0 is the decrement at the first iterate of the staged solve, at rest
   for a solve from rest: the contact is open there, so g is the full
   problem's whatever the stage's penalty, and H0 ~ K, so lambda_0^2 ~
   g0^T K^-1 g0, twice the energy the load would store without contact, a
   scale independent of k_p and of the staging, as the gradient test's g0
   (with -load_steps n it is the first load's, 1/n of that: a tighter test).
   lambda is computed with H0 as last set up (at the previous iterate), one
   more solve of the H0 KSP per iteration of the last stage (the JSON's
   lmvm_decrement_solves; the set-up, not the solve, is H0's cost). The price
   of the damping: the stiff directions' own error, which is P's directly
   (g_c = dP), counts only as g_c / sqrt(k_p) in lambda, so rtol must sit
   well below -tao_gttol (1e-12 against 1e-10 here). Measured (bin/contact
   -options_file meshes/hertz-half/hertz-half.opts -mesh_size h
   -contact_penalty 1e10 -block_bc_push_values -push,0 -contact_formulation F
   -output none -tao_type lmvm [-lmvm_decrement_rtol r | -tao_gttol 1e-11]):
     push 0.3, 1 rank: iterations (default: gttol 1e-10)
       F, h         default  gttol 1e-11  r 1e-11  r 1e-12  r 1e-13
       gpts 0.25       47       62           45       46       48
       mortar 0.25     36       stops (LS)   32       37       38
       gpts 0.1        52       53           51       52       53
       mortar 0.1      70       380          71       73       74
     (the decrement's floor: 5e-14 lambda_0 on mortar h = 0.25, where
     r 1e-14 stops by line search failures as gttol 1e-11 does)
     push 0.15, h = 0.01: |P1 - P2| / P1 (1 and 2 ranks), iterations 1 / 2
       F         default         r 1e-11         r 1e-12         r 1e-13
       gpts      4.7e-8  61/62   8.9e-9  61/63   8.4e-11 62/64   4.3e-12 63/65
       mortar    3.4e-8  73/68   3.4e-8  73/68   5.2e-9  74/68   1.9e-11 75/70
     (solve times 27-32 s each, the same with and without the test)
     k_p = 2e6 (-options_file meshes/hertz/hertz.opts -mesh_size 0.03
     -tao_type lmvm): iterations and |P - P_Newton| / P (Newton at
     -tao_gttol 1e-12): default 14, 6.1e-11; r 1e-10 15, 3.4e-10; r 1e-11
     17, 4.4e-12; r 1e-12 19, 3.0e-13. The same at k_p = 1e8: default 16,
     6.7e-9; r 1e-12 20, 2.0e-11. At k_p = 1e10: 85 both, the same P.
     2 ranks, mortar, h = 0.1, push 0.3: 70 default, 71 with r 1e-12.
   So the test is the default where the penalty is stiff: where a pair's
   k_p h / E* exceeds LMVM_STIFF_PENALTY = 1e4 (ten times the automatic
   penalty's 1000; the sweep's k_p = 1e10 is 9.1e4 at h = 0.005 to 3.8e6 at
   h = 0.25, its 1e6 at most 380, the reference scene 347 at h = 0.1) and
   no -tao_gatol, -tao_grtol or -tao_gttol is given, with r = 1e-13;
   elsewhere the gradient test, which at
   the normal penalty stops 5 iterations sooner (14 against 19 at r = 1e-12
   on the reference scene) with P within 6e-11 of Newton's. r = 1e-13, not
   1e-12: at 1e-12 one pair of the k_p = 1e10 sweep's 24 (h = 0.25 to 0.01)
   stayed 1.3e-8 apart. Its margin to the decrement's round-off floor is
   smaller: run with r = 1e-16, the half scene at h = 0.25 and 0.1 (gpts and
   mortar, push 0.15 and 0.3) reaches 7e-15 to 2.5e-14 of lambda_0 before
   its line search fails. So a last stage whose line search fails within
   -lmvm_decrement_floor = 10 of the tolerance (lambda <= 1e-12 lambda_0)
   ends converged at that floor, as TAO_CONVERGED_USER, not restarted or cut
   back (JSON lmvm_decrement_floor_stops); a larger factor with a tolerance
   below the floor makes the floor the stop (tests/test_lmvm.py forces it
   so: r = 1e-15, factor 1000). Measured with the default (the
   k_p = 1e10 part of the robustness sweep, h = 0.25 to 0.005, both
   formulations, pushes 0.01 to 0.3, 1 and 2 ranks: scripts/stress_sweep.py
   --kp 1e10 --tao-type lmvm, and blmvm; bench/stress-lmvm, stress-blmvm):
   all 60 converge for each type, P of 1 and 2 ranks within 4.9e-9 in every
   pair (5.4e-8 with the gradient test), with the continuation then the
   default, 3 stages from 1e-3 k_p; with the one above, 1.9e-9. */
#include <petsc/private/taoimpl.h>
#include "lmvm.h"
#include "forcestop.h"
#include "slidewatch.h"
#include "options.h"
#include "problem.h"
#include "newtonstep.h"
#include "forceborder.h"
#include "schedule.h"

const char *const H0Types[]      = {"none", "elastic", "contact", "H0Type", "H0_", NULL};

#define LMVM_STIFF_PENALTY   1e4   /* k_p h / E* above which the last stage stops by the decrement (10 times the automatic penalty's) */
#define LMVM_DECREMENT_RTOL  1e-13 /* -lmvm_decrement_rtol there */
#define LMVM_START_STIFFNESS 1.0   /* the continuation's first stage no stiffer than this k_p h / E* */
#define LMVM_STAGE_FACTOR    32.0  /* nor its stages further apart than this factor */

/* L-BFGS's state for one TAO solver: composed with it (LMVM_CONTEXT), made
   where H0 is set up and freed with the solver. */
#define LMVM_CONTEXT "contact_lmvm"
typedef struct {
  Problem   p;
  Mat       H0;      /* H0 as TAO sees it: H or K, or either bordered by the controls (forceborder.c) */
  KSP       kin;     /* coupled force control: the solve of H0 inside the bordered one */
  Vec       X, G, W; /* -lmvm_h0 contact: the last iterate and its gradient, work (else NULL) */
  PetscBool have;    /* X, G hold an iterate of the current TAO solve */
  PetscReal F0, G0;  /* the energy and gradient norm at the first iterate of the last TAO solve */
  PetscReal lambda0; /* -lmvm_decrement_rtol: the decrement at the first iterate of the staged solve (-1: not yet) */
  PetscReal lambda;  /* -lmvm_decrement_rtol: the decrement at the current TAO solve's last iterate (-1: none yet) */
  PetscBool last;    /* the current TAO solve is the last stage (the decrement test applies) */
} LMVMCtx;

static PetscErrorCode LMVMCtxDestroy(void *ctx)
{
  LMVMCtx *l = (LMVMCtx *)ctx;

  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&l->H0));
  PetscCall(KSPDestroy(&l->kin));
  PetscCall(VecDestroy(&l->X));
  PetscCall(VecDestroy(&l->G));
  PetscCall(VecDestroy(&l->W));
  PetscCall(PetscFree(l));
  PetscFunctionReturn(0);
}

/* The context composed with the problem's solver, or NULL where L-BFGS has no H0 of the program's. */
static PetscErrorCode ProblemGetLMVM(Problem p, LMVMCtx **l)
{
  PetscObject c = NULL;

  PetscFunctionBeginUser;
  *l = NULL;
  if (p->tao) PetscCall(PetscObjectQuery((PetscObject)p->tao, LMVM_CONTEXT, &c));
  if (c) PetscCall(PetscContainerGetPointer((PetscContainer)c, (void **)l));
  PetscFunctionReturn(0);
}

static PetscErrorCode ProblemCreateLMVM(Problem p, LMVMCtx **l)
{
  PetscContainer c;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(l));
  (*l)->p = p;
  PetscCall(PetscContainerCreate(p->comm, &c));
  PetscCall(PetscContainerSetPointer(c, *l));
  PetscCall(PetscContainerSetUserDestroy(c, LMVMCtxDestroy));
  PetscCall(PetscObjectCompose((PetscObject)p->tao, LMVM_CONTEXT, (PetscObject)c));
  PetscCall(PetscContainerDestroy(&c));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemLMVMBeginStaged(Problem p)
{
  LMVMCtx *l;

  PetscFunctionBeginUser;
  PetscCall(ProblemGetLMVM(p, &l));
  if (!l) PetscFunctionReturn(0);
  l->lambda0 = -1.0; /* set at the first iterate */
  l->last    = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemLMVMSetLastStage(Problem p, PetscBool last)
{
  LMVMCtx *l;

  PetscFunctionBeginUser;
  PetscCall(ProblemGetLMVM(p, &l));
  if (l) l->last = last;
  PetscFunctionReturn(0);
}

/* H0 = K + C(X) into p->H, whose factorisation the H0 KSP's preconditioner
   redoes when the matrix changes. */
static PetscErrorCode ProblemComputeH0(Problem p, Vec X)
{
  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermSetHessianExact(p->terms[t], PETSC_FALSE));
  PetscCall(ProblemAssembleHessian(p, X, p->H));
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermSetHessianExact(p->terms[t], p->exactHessian));
  p->res.h0Refreshes++;
  PetscFunctionReturn(0);
}

/* The LMVM matrix of TAO's lmvm or blmvm. PETSc 3.18 has no getter for it
   (TaoGetLMVMMatrix serves the bqnk types only); both TAO_LMVM and TAO_BLMVM
   hold it as their first member. */
static PetscErrorCode TaoLMVMGetMatrix(Tao tao, Mat *M)
{
  PetscBool lmvm;

  PetscFunctionBeginUser;
  *M = *(Mat *)tao->data;
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)*M, MATLMVM, &lmvm));
  PetscCheck(lmvm, PetscObjectComm((PetscObject)tao), PETSC_ERR_LIB, "TAO %s: its first member is not the LMVM matrix in this PETSc version", ((PetscObject)tao)->type_name);
  PetscFunctionReturn(0);
}

/* The pair (s, y) from the last iterate to X, G: dropped (the history reset)
   if r = y^T s / s^T H0 s is outside [1/R, R]. */
static PetscErrorCode ProblemScreenPair(LMVMCtx *l, Tao tao, Vec X, Vec G)
{
  Problem     p = l->p;
  PetscScalar ys, sHs;
  PetscReal   r;
  Mat         M;

  PetscFunctionBeginUser;
  PetscCall(VecAYPX(l->X, -1.0, X)); /* s */
  PetscCall(VecAYPX(l->G, -1.0, G)); /* y */
  PetscCall(MatMult(l->H0, l->X, l->W));
  PetscCall(VecDotBegin(l->G, l->X, &ys));
  PetscCall(VecDotBegin(l->W, l->X, &sHs));
  PetscCall(VecDotEnd(l->G, l->X, &ys));
  PetscCall(VecDotEnd(l->W, l->X, &sHs));
  r = PetscRealPart(sHs) > 0 ? PetscRealPart(ys) / PetscRealPart(sHs) : 1.0;
  PetscCall(PetscInfo(tao, "L-BFGS pair: y^T s / s^T H0 s = %g\n", (double)r));
  if (r * p->cfg->lmvm.pairRatio >= 1.0 && r <= p->cfg->lmvm.pairRatio) PetscFunctionReturn(0);
  PetscCall(TaoLMVMGetMatrix(tao, &M));
  PetscCall(MatLMVMReset(M, PETSC_FALSE));
  p->res.pairsDropped++;
  PetscFunctionReturn(0);
}

/* The Newton decrement in H0's norm, lambda = sqrt(g^T H0^-1 g), through
   the H0 KSP (the solve TAO's L-BFGS applies), with H0 as last set up. */
static PetscErrorCode ProblemDecrement(LMVMCtx *l, Tao tao, Vec G, PetscReal *lambda)
{
  KSP         ksp;
  PetscScalar gHg;

  PetscFunctionBeginUser;
  PetscCall(TaoLMVMGetH0KSP(tao, &ksp));
  PetscCall(KSPSolve(ksp, G, l->W));
  PetscCall(VecDot(G, l->W, &gHg));
  *lambda = PetscSqrtReal(PetscMax(PetscRealPart(gHg), 0.0));
  l->p->res.decrementSolves++;
  PetscFunctionReturn(0);
}

/* -lmvm_decrement_rtol: in the last stage, converged (TAO_CONVERGED_USER)
   when lambda <= rtol lambda_0; TAO's own test for every other reason
   (iterations, evaluations, NaN, the step), with its gradient tolerances
   off. Not at a solve's first iterate, where H0 is still
   the last solve's. */
static PetscErrorCode ProblemLMVMConverged(Tao tao, void *ctx)
{
  LMVMCtx           *l = (LMVMCtx *)ctx;
  Problem            p = l->p;
  PetscReal          gatol, grtol, gttol, lambda;
  PetscInt           it;
  TaoConvergedReason reason;
  Vec                G;

  PetscFunctionBeginUser;
  if (!(l->last && p->sched.decrementRtol > 0 && l->lambda0 > 0)) {
    PetscCall(TaoDefaultConvergenceTest(tao, NULL));
    PetscFunctionReturn(0);
  }
  PetscCall(TaoGetTolerances(tao, &gatol, &grtol, &gttol));
  PetscCall(TaoSetTolerances(tao, 0.0, 0.0, 0.0));
  PetscCall(TaoDefaultConvergenceTest(tao, NULL));
  PetscCall(TaoSetTolerances(tao, gatol, grtol, gttol));
  PetscCall(TaoGetConvergedReason(tao, &reason));
  PetscCall(TaoGetIterationNumber(tao, &it));
  if (reason != TAO_CONTINUE_ITERATING || it == 0) PetscFunctionReturn(0);
  PetscCall(TaoGetGradient(tao, &G, NULL, NULL));
  PetscCall(ProblemDecrement(l, tao, G, &lambda));
  PetscCall(PetscInfo(tao, "L-BFGS: decrement %g, %g of the first iterate's\n", (double)lambda, (double)(lambda / l->lambda0)));
  l->lambda = lambda;
  if (lambda <= p->sched.decrementRtol * l->lambda0) PetscCall(TaoSetConvergedReason(tao, TAO_CONVERGED_USER));
  PetscFunctionReturn(0);
}

/* Whether a last stage whose line search failed is at the decrement's
   round-off floor: its last decrement within -lmvm_decrement_floor of the
   tolerance. */
static PetscBool ProblemLMVMAtFloor(const LMVMCtx *l)
{
  const PetscReal rtol = l->p->sched.decrementRtol;

  return (PetscBool)(l->last && rtol > 0 && l->lambda0 > 0 && l->lambda >= 0 && l->lambda <= l->p->cfg->lmvm.decrementFloor * rtol * l->lambda0);
}

/* TAO's update at the start of each iteration, before the LMVM matrix takes
   its pair: H0 at the current iterate (at the first iterate of a solve, then
   every -lmvm_h0_refresh iterations), then the pair screened against it. */
static PetscErrorCode ProblemLMVMUpdate(Tao tao, PetscInt it, void *ctx)
{
  LMVMCtx *l = (LMVMCtx *)ctx;
  Problem  p = l->p;
  Vec      X, G;

  PetscFunctionBeginUser;
  PetscCall(TaoGetSolution(tao, &X));
  PetscCall(TaoGetGradient(tao, &G, NULL, NULL));
  if (it % p->cfg->lmvm.h0Refresh == 0) PetscCall(ProblemComputeH0(p, X));
  if (it == 0) { /* TAO starts the solve with an empty history */
    l->have   = PETSC_FALSE;
    l->lambda = -1.0;
    PetscCall(TaoGetSolutionStatus(tao, NULL, &l->F0, &l->G0, NULL, NULL, NULL));
  }
  if (it == 0 && p->sched.decrementRtol > 0 && l->lambda0 <= 0) PetscCall(ProblemDecrement(l, tao, G, &l->lambda0));
  if (l->have) PetscCall(ProblemScreenPair(l, tao, X, G));
  PetscCall(VecCopy(X, l->X));
  PetscCall(VecCopy(G, l->G));
  l->have = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemLMVMConvergenceTest(Problem p, Tao tao)
{
  LMVMCtx *l;

  PetscFunctionBeginUser;
  PetscCall(ProblemGetLMVM(p, &l));
  if (l && l->X && p->sched.decrementRtol > 0) PetscCall(ProblemLMVMConverged(tao, l));
  else PetscCall(TaoDefaultConvergenceTest(tao, NULL));
  PetscFunctionReturn(0);
}

/* TaoSolve, with the breakdown of TAO 3.18's More-Thuente line search
   taken as the line search's failure: its step routine raises an error
   (PETSC_ERR_ARG_OUTOFRANGE, "dx * (stp-stx) >= 0.0", "bad stp in bracket")
   where the energy along the step is not what its bracket assumes, which a
   contact sliding without end met (the cattaneo disc pressed by a
   displacement and pulled beyond mu P: its fourth iterate had slid 4 times
   the disc's radius), and which the program then reported as bad input.
   Any other error stands, with its message. */
static PetscErrorCode ProblemTaoSolveOnce(Problem p)
{
  PetscErrorCode ierr;
  const char    *text;
  char          *specific = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = TaoSolve(p->tao);
  PetscCall(PetscPopErrorHandler());
  if (!ierr) PetscFunctionReturn(0);
  PetscCall(PetscErrorMessage(ierr, &text, &specific));
  if (ierr == PETSC_ERR_ARG_OUTOFRANGE && specific && (strstr(specific, "stp-stx") || strstr(specific, "stp in bracket"))) {
    PetscCall(PetscInfo(p->tao, "the line search broke down (%s): a failed line search\n", specific));
    PetscCall(TaoSetConvergedReason(p->tao, TAO_DIVERGED_LS_FAILURE));
    PetscFunctionReturn(0);
  }
  SETERRQ(p->comm, ierr, "%s", specific ? specific : (text ? text : "TAO's solve failed"));
}

PetscErrorCode ProblemTaoSolve(Problem p, PetscInt *its, TaoConvergedReason *reason)
{
  PetscReal gatol, grtol, gttol, g0 = -1.0, f;
  PetscInt  maxit, n;
  LMVMCtx  *l;

  PetscFunctionBeginUser;
  PetscCall(ProblemGetLMVM(p, &l));
  PetscCall(TaoGetTolerances(p->tao, &gatol, &grtol, &gttol));
  PetscCall(TaoGetMaximumIterations(p->tao, &maxit));
  *its = 0;
  for (PetscInt r = 0;; ++r) {
    PetscReal f0;
    PetscCall(ProblemForceStopBegin(p));
    PetscCall(ProblemSlideWatchBegin(p));
    PetscCall(ProblemTaoSolveOnce(p));
    PetscCall(TaoGetSolutionStatus(p->tao, &n, &f, NULL, NULL, NULL, reason));
    PetscCall(ProblemForceStopEnd(p, reason));
    *its += n;
    if (!l || !l->X) break; /* no restart without the iterates of the program's H0 */
    if (g0 < 0) g0 = l->G0;
    f0 = l->F0;
    if (*reason == TAO_DIVERGED_LS_FAILURE && ProblemLMVMAtFloor(l)) {
      PetscCall(PetscInfo(p->tao, "L-BFGS: the line search failed at decrement %g of the first iterate's, within %g of the tolerance: converged at its round-off floor\n", (double)(l->lambda / l->lambda0), (double)p->cfg->lmvm.decrementFloor));
      *reason = TAO_CONVERGED_USER;
      p->res.decrementFloor++;
      break;
    }
    if (*reason != TAO_DIVERGED_LS_FAILURE || r >= p->cfg->lmvm.restarts || !(f < f0) || *its >= maxit) break;
    /* the restart stops where the first solve would have: its gradient tolerances relative to the first iterate's */
    PetscCall(TaoSetTolerances(p->tao, PetscMax(gatol, gttol * g0), grtol, 0.0));
    PetscCall(TaoSetMaximumIterations(p->tao, maxit - *its));
    PetscCall(PetscInfo(p->tao, "L-BFGS: the line search failed after %" PetscInt_FMT " iterations (energy %g, was %g): restarted with an empty history\n", n, (double)f, (double)f0));
    p->res.lmvmRestarts++;
  }
  PetscCall(TaoSetTolerances(p->tao, gatol, grtol, gttol));
  PetscCall(TaoSetMaximumIterations(p->tao, maxit));
  PetscFunctionReturn(0);
}

/* -lmvm_decrement_rtol not given: LMVM_DECREMENT_RTOL where a pair's k_p h / E*
   exceeds LMVM_STIFF_PENALTY, unless the user gave a gradient tolerance; else
   off. After the terms' set-up (without it, -help, off). */
static PetscErrorCode ProblemChooseDecrementTest(Problem p, PetscReal stiff)
{
  PetscBool given;

  PetscFunctionBeginUser;
  PetscCall(ContactGradientToleranceGiven(&given));
  PetscCall(ProblemSetDecrementTest(p, !given && stiff > LMVM_STIFF_PENALTY ? LMVM_DECREMENT_RTOL : 0.0));
  PetscCall(PetscInfo(p->tao, "L-BFGS: k_p h / E* = %g: the last stage stops by %s\n", (double)stiff, p->sched.decrementRtol > 0 ? "the decrement" : "the gradient tolerances"));
  PetscFunctionReturn(0);
}

/* Penalty continuation where the user and the scene chose none: stages a
   factor of at most LMVM_STAGE_FACTOR apart from 1e-3 k_p, or from where
   k_p h / E* is LMVM_START_STIFFNESS if that is softer (see the derivation). */
static PetscErrorCode ProblemChooseContinuation(Problem p, PetscReal stiff)
{
  PetscReal start = 1e-3;
  PetscInt  stages;

  PetscFunctionBeginUser;
  if (stiff * start > LMVM_START_STIFFNESS) start = LMVM_START_STIFFNESS / stiff;
  stages = 1 + (PetscInt)PetscCeilReal(PetscLogReal(1.0 / start) / PetscLogReal(LMVM_STAGE_FACTOR) - 1e-6);
  PetscCall(ProblemSetPenaltyContinuation(p, stages, start));
  PetscCall(PetscInfo(p->tao, "L-BFGS: k_p h / E* = %g: %" PetscInt_FMT " penalty stages from %g k_p\n", (double)stiff, stages, (double)start));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetLMVMDefaults(Problem p, const char type[])
{
  char      name[64];
  PetscBool given;
  PetscReal stiff;

  PetscFunctionBeginUser;
  if (!((!strcmp(type, TAOLMVM) || !strcmp(type, TAOBLMVM)) && p->cfg->lmvm.h0 == H0_CONTACT && p->nterms)) PetscFunctionReturn(0);
  PetscCall(ProblemGetPenaltyStiffness(p, &stiff));
  /* -lmvm_h0 contact: one correction pair (see the derivation). The default
     of -tao_lmvm_mat_lmvm_hist_size, which TAO reads (its LMVM matrix has no
     setter through Tao in 3.18); the user's value wins. */
  PetscCall(PetscSNPrintf(name, sizeof(name), "-tao_%s_mat_lmvm_hist_size", type));
  PetscCall(PetscOptionsHasName(NULL, NULL, name, &given));
  if (!given) PetscCall(PetscOptionsSetValue(NULL, name, "1"));
  /* a tighter stop than Newton's 1e-8: L-BFGS converges linearly, so it stops
     near its tolerance, where Newton's last step lands far below it */
  PetscCall(TaoSetTolerances(p->tao, 0.0, 0.0, 1e-10));
  /* the decrement test where the penalty is stiff and the user chose no test */
  if (p->sched.decrementRtol < 0) PetscCall(ProblemChooseDecrementTest(p, stiff));
  if (!p->cfg->penalty.stagesSet && !p->cfg->penalty.startSet) PetscCall(ProblemChooseContinuation(p, stiff));
  /* the line search's evaluations: 100, not TAO's 30 (see the derivation) */
  PetscCall(PetscOptionsHasName(NULL, NULL, "-tao_ls_max_funcs", &given));
  if (!given) PetscCall(PetscOptionsSetValue(NULL, "-tao_ls_max_funcs", "100"));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetLMVMInitialHessian(Problem p)
{
  PetscBool lmvm, blmvm, contact;
  KSP       ksp, kin;
  PC        pc;
  Mat       H0;
  LMVMCtx  *l;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)p->tao, TAOLMVM, &lmvm));
  PetscCall(PetscObjectTypeCompare((PetscObject)p->tao, TAOBLMVM, &blmvm));
  if (!(lmvm || blmvm) || p->cfg->lmvm.h0 == H0_NONE) PetscFunctionReturn(0);
  if (!p->cfg->newton.tangentAtRestSet) p->cfg->newton.tangentAtRest = PETSC_TRUE; /* H0 is the stiffness at rest with the contact's Hessian, whatever the material (a neohookean body's tangent would be factored anew at each refresh) */
  contact = (PetscBool)(p->cfg->lmvm.h0 == H0_CONTACT && p->nterms && !ProblemTangentReassembled(p)); /* a varying tangent: the stiffness at rest (elastic) */
  PetscCall(ProblemCreateLMVM(p, &l));
  if (contact) PetscCall(ProblemAssembleHessian(p, p->X, p->H)); /* a matrix for the set-up; each solve sets H0 up at its first iterate */
  H0 = contact ? p->H : p->K;
  if (p->fc.coupled) { /* H0 bordered by the controls (forceborder.c), around a KSP of H0 set up as below */
    PetscCall(KSPCreate(p->comm, &l->kin));
    PetscCall(KSPSetOperators(l->kin, H0, H0));
    kin = l->kin;
  } else {
    PetscCall(PetscObjectReference((PetscObject)H0));
    l->H0 = H0;
    PetscCall(TaoLMVMSetH0(p->tao, H0));
    PetscCall(TaoLMVMGetH0KSP(p->tao, &kin));
  }
  ksp = kin;
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  if (contact) {
    PetscInt  nc;
    PetscBool fits;
    PetscCall(ProblemSchurStepFits(p, &nc, &fits));
    if (p->cfg->newton.schur && fits) PetscCall(ProblemSchurPCSetUp(p, pc));
    else PetscCall(ContactPCSetCholesky(pc, p->comm, PETSC_FALSE)); /* H0 = K + C is SPD: refactored at each refresh */
    if (!fits)
      PetscCall(PetscPrintf(p->comm, "L-BFGS H0: direct factorisation of the whole H0 at each refresh (3D, with contact pairs on %" PetscInt_FMT " surface dofs, above -newton_schur_surface_dofs %" PetscInt_FMT ": the Schur step's dense surface blocks would take some %.0f MB; -newton_schur 1 forces it)\n", nc,
                            p->cfg->newton.schurSurfaceDofs, 8.0 * (double)nc * (double)nc / 1048576.0));
  } else PetscCall(ContactPCSetCholesky(pc, p->comm, PETSC_FALSE));
  if (p->fc.coupled) {
    PetscCall(ForceBorderMatCreate(p, H0, kin, &l->H0));
    PetscCall(TaoLMVMSetH0(p->tao, l->H0));
    PetscCall(TaoLMVMGetH0KSP(p->tao, &ksp));
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(ForceBorderPCSetUp(l->H0, pc));
  }
  PetscCall(KSPSetOptionsPrefix(ksp, "h0_"));
  PetscCall(KSPSetFromOptions(ksp));
  if (contact) {
    PetscCall(VecDuplicate(p->X, &l->X));
    PetscCall(VecDuplicate(p->X, &l->G));
    PetscCall(VecDuplicate(p->X, &l->W));
    PetscCall(TaoSetUpdate(p->tao, ProblemLMVMUpdate, l));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LMVMOptionsSetFromOptions(MPI_Comm comm, LMVMOptions *o)
{
  PetscBool setDecrement;

  PetscFunctionBeginUser;
  o->h0             = H0_CONTACT;
  o->h0Refresh      = 1;
  o->restarts       = 50;
  o->decrementRtol  = -1.0; /* chosen with the solver (ProblemChooseDecrementTest) */
  o->decrementFloor = 10.0;
  o->pairRatio      = 10.0;
  PetscOptionsBegin(comm, NULL, "L-BFGS options", NULL);
  PetscCall(PetscOptionsEnum("-lmvm_h0", "Initial Hessian of lmvm/blmvm: contact (the stiffness and the contact's Gauss-Newton Hessian, through the Newton step's Schur complement or, where that would not be taken, factored whole, refreshed every -lmvm_h0_refresh iterations; with one correction pair), elastic (the stiffness of the bodies, factorised once) or none", NULL, H0Types, (PetscEnum)o->h0, (PetscEnum *)&o->h0, NULL));
  PetscCall(PetscOptionsInt("-lmvm_h0_refresh", "-lmvm_h0 contact: recompute the contact part of H0 every this many iterations", NULL, o->h0Refresh, &o->h0Refresh, NULL));
  PetscCall(PetscOptionsInt("-lmvm_restarts", "-lmvm_h0 contact: restart an L-BFGS solve whose line search failed after it lowered the energy, with an empty history, at most this many times", NULL, o->restarts, &o->restarts, NULL));
  PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-lmvm_decrement_rtol", "-lmvm_h0 contact: the last stage stops when the Newton decrement in H0's norm, sqrt(g'H0^-1 g), has fallen by this factor from the first iterate's, instead of by the gradient tolerances (0: off)", "1e-13 where a pair's k_p h / E* exceeds 1e4 and no -tao_gatol, -tao_grtol or -tao_gttol is given, else 0", PETSC_FALSE, &o->decrementRtol, &setDecrement));
  PetscCall(PetscOptionsReal("-lmvm_decrement_floor", "-lmvm_decrement_rtol: a last stage whose line search fails with the decrement within this factor of the tolerance has reached the decrement's round-off floor and ends converged (JSON lmvm_decrement_floor_stops)", NULL, o->decrementFloor, &o->decrementFloor, NULL));
  PetscCall(PetscOptionsReal("-lmvm_pair_ratio", "-lmvm_h0 contact: drop an L-BFGS correction pair whose curvature y's/s'H0s is not within this factor of H0's (where contact opened or closed along the step; 1e300: keep every pair)", NULL, o->pairRatio, &o->pairRatio, NULL));
  PetscOptionsEnd();
  PetscCheck(o->h0Refresh >= 1, comm, PETSC_ERR_USER_INPUT, "option -lmvm_h0_refresh: must be >= 1, got %" PetscInt_FMT, o->h0Refresh);
  PetscCheck(o->restarts >= 0, comm, PETSC_ERR_USER_INPUT, "option -lmvm_restarts: must be >= 0, got %" PetscInt_FMT, o->restarts);
  PetscCheck(!setDecrement || (o->decrementRtol >= 0 && o->decrementRtol < 1), comm, PETSC_ERR_USER_INPUT, "option -lmvm_decrement_rtol: must be in [0, 1), got %g", (double)o->decrementRtol);
  PetscCheck(o->decrementFloor >= 1 && !PetscIsInfOrNanReal(o->decrementFloor), comm, PETSC_ERR_USER_INPUT, "option -lmvm_decrement_floor: must be a finite number >= 1, got %g", (double)o->decrementFloor);
  PetscCheck(o->pairRatio >= 1 && !PetscIsInfOrNanReal(o->pairRatio), comm, PETSC_ERR_USER_INPUT, "option -lmvm_pair_ratio: must be a finite number >= 1, got %g", (double)o->pairRatio);
  PetscFunctionReturn(0);
}
