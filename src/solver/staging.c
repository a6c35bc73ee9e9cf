/* The staged solve: the load history's stages (-load_stages, history.c),
   load steps within each (outer), penalty continuation (inner) and
   automatic cutback, each stage a TAO solve from the last converged state,
   and the stopping test of each stage (the last relative to the gradient
   of the full problem at rest, so that the result does not depend on the
   staging). The load parameter lambda walks from 0 to S = -load_stages;
   one stage is today's load factor. Below the orchestrator (solve.c) and force control's solves
   (forcesolve.c, forceouter.c); above the assembled system (problem.c) and
   L-BFGS's TAO solve (lmvm.c). */
#include "staging.h"
#include "forcestop.h"
#include "slidewatch.h"
#include "problem.h"
#include "forcecontrol.h"
#include "lmvm.h"
#include "newtonstep.h"

static PetscErrorCode ProblemSetStage(Problem p, PetscReal load, PetscReal penalty)
{
  PetscFunctionBeginUser;
  PetscCall(ProblemSetLoad(p, load));
  for (PetscInt t = 0; t < p->nterms; ++t)
    PetscCall(EnergyTermSetPenaltyFactor(p->terms[t], penalty));
  PetscFunctionReturn(0);
}

/* The gradient norm g0 of the full problem (the scene's penalty) at rest,
   where a solve from rest starts and the last stage stops relative to; the
   energy evaluations are not counted. The full problem is the load at each
   stage's end, the largest of their norms (one stage: load 1; a stage that
   unloads to rest then stops as the loading did). Where the full load put
   on at rest inverts an element (a neohookean body), the gradient there has
   no value: g0 is then the gradient at load 1e-6 divided by 1e-6, its limit
   at small load, which is the linear body's g0. */
static PetscErrorCode ProblemGradientAtRest(Problem p, PetscReal *g0)
{
  const PetscReal small = 1e-6;
  const PetscInt  S     = p->cfg->load.stages;
  PetscReal       f, g;
  Vec             X;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(p->X, &X));
  *g0 = 0.0;
  for (PetscInt k = 1; k <= S; ++k) {
    PetscCall(ProblemSetStage(p, (PetscReal)k, 1.0));
    PetscCall(ProblemComputeObjectiveGradient(p->tao, X, &f, p->G, p));
    p->res.nEnergyEvals--;
    PetscCall(VecNorm(p->G, NORM_2, &g));
    if (PetscIsInfReal(f) && k > 1) g = 0.0; /* a later stage's: the first's limit stands */
    else if (PetscIsInfReal(f)) {
      PetscCall(ProblemSetStage(p, small, 1.0));
      PetscCall(ProblemComputeObjectiveGradient(p->tao, X, &f, p->G, p));
      p->res.nEnergyEvals--;
      PetscCall(VecNorm(p->G, NORM_2, &g));
      g /= small;
    }
    *g0 = PetscMax(*g0, g);
  }
  PetscCall(ProblemSetStage(p, (PetscReal)S, 1.0));
  PetscCall(VecDestroy(&X));
  PetscFunctionReturn(0);
}

/* -load_stages: keeps X at the end of stage k (the converged state at load k). */
static PetscErrorCode ProblemStageEndRecord(Problem p, PetscInt k)
{
  StageEnds *e = &p->res.ends;

  PetscFunctionBeginUser;
  if (!e->X[k - 1]) PetscCall(VecDuplicate(p->X, &e->X[k - 1]));
  PetscCall(VecCopy(p->X, e->X[k - 1]));
  e->n = PetscMax(e->n, k);
  PetscFunctionReturn(0);
}

/* The tangent predictor of a stage from load l0 to l1 (at the penalty
   factor of the stage): X += dX with
     H(X; l0) dX = -(g(X; l0) + (g(X; l0 + t (l1 - l0)) - g(X; l0)) / t),
   the gradient's change with the load taken by a secant at t = 1e-3 (a
   step of the Dirichlet values that inverts nothing) and H the Hessian at
   the last converged state: the equilibrium path extrapolated linearly, a
   linear solve from rest for the first load. The inside of the body moves
   with its Dirichlet values instead of waiting for them. Nothing is done
   where H cannot be factored (a body held by contact alone at rest) or
   the controls are coupled to X. */
static PetscErrorCode ProblemPredict(Problem p, PetscReal l0, PetscReal l1, PetscReal penalty)
{
  const PetscReal    t = 1e-3;
  PetscReal          f0, f1;
  Vec                g0, g1;
  KSP                ksp;
  PC                 pc;
  KSPConvergedReason kr = KSP_CONVERGED_ITERATING;

  PetscFunctionBeginUser;
  if (p->X != p->Xb || !(l1 > l0)) PetscFunctionReturn(0);
  PetscCall(VecDuplicate(p->X, &g0));
  PetscCall(VecDuplicate(p->X, &g1));
  PetscCall(ProblemSetStage(p, l0, penalty));
  PetscCall(ProblemEvaluate(p, p->X, &f0, g0, NULL));
  PetscCall(ProblemAssembleHessian(p, p->X, p->H));
  PetscCall(ProblemSetStage(p, l0 + t * (l1 - l0), penalty));
  PetscCall(ProblemEvaluate(p, p->X, &f1, g1, NULL));
  if (!PetscIsInfReal(f0) && !PetscIsInfReal(f1)) {
    PetscCall(VecAXPBY(g1, 1.0 - 1.0 / t, 1.0 / t, g0)); /* g0 + (g1 - g0) / t */
    PetscCall(KSPCreate(p->comm, &ksp));
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(KSPSetOperators(ksp, p->H, p->H));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(ContactPCSetCholesky(pc, p->comm, PETSC_TRUE));
    PetscCall(KSPSolve(ksp, g1, g0));
    PetscCall(KSPGetConvergedReason(ksp, &kr));
    PetscCall(KSPDestroy(&ksp));
    if (kr >= 0) PetscCall(VecAXPY(p->X, -1.0, g0));
  }
  PetscCall(PetscInfo(p->tao, "tangent predictor from load %g to %g: %s\n", (double)l0, (double)l1, kr >= 0 && kr != KSP_CONVERGED_ITERATING ? "applied" : "not applied"));
  PetscCall(ProblemSetStage(p, l1, penalty));
  PetscCall(VecDestroy(&g0));
  PetscCall(VecDestroy(&g1));
  PetscFunctionReturn(0);
}

/* Whether a term holds state across load increments (friction). */
static PetscBool ProblemHasState(Problem p)
{
  for (PetscInt t = 0; t < p->nterms; ++t)
    if (EnergyTermHasState(p->terms[t])) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* A body whose material has history (plastic: bodystate.c): its state
   follows the terms' lifecycle (accept, begin, restore, reset), without a
   lag. */
static PetscBool ProblemBodiesHaveState(Problem p)
{
  for (PetscInt i = 0; i < p->nbodies; ++i)
    if (BodyHasState(p->bodies[i])) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* A term with state holds a quantity lagged within the increment (the
   friction's normal pressure): after a converged solve the lag is updated
   from the solution, and the increment solved again from there, until the
   largest relative change is below -contact_friction_lag_rtol (a fixed
   point), at most -contact_friction_lag_max_it solves in all. An
   intermediate stage (a penalty continuation's, stopped at -stage_rtol)
   leaves the lag as it is: its solution is only the next stage's start,
   and a pressure lagged from a soft penalty's wider zone made the first
   solve at the full one take 24 Newton iterations on the cattaneo scene
   at a/R = 0.1 (P = 4.3; the normal stage 41 in all; lagged from the full penalty alone, 32). The re-solves start close to their answer, so a stop relative to
   their own first gradient (gttol) is one relative to the first solve's,
   gstart. */
/* The terms' lag at the bodies' state p->X (evaluated there first, so that
   the bodies hold it and not a line search's last trial); change: the
   largest relative change of what they lag. */
static PetscErrorCode ProblemStateLag(Problem p, PetscReal *change)
{
  PetscReal f;

  PetscFunctionBeginUser;
  *change = 0.0;
  PetscCall(ProblemEvaluate(p, p->X, &f, p->G, NULL));
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscReal c;
    PetscCall(EnergyTermLag(p->terms[t], p->bodies, &c));
    *change = PetscMax(*change, c);
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode ProblemStageSolveLagged(Problem p, PetscBool converge, PetscReal gstart, PetscInt *its, TaoConvergedReason *reason)
{
  PetscInt  k = 1;
  PetscReal tol[3];

  PetscFunctionBeginUser;
  if (!ProblemHasState(p) || !converge) PetscFunctionReturn(0);
  PetscCall(TaoGetTolerances(p->tao, &tol[0], &tol[1], &tol[2]));
  PetscCall(TaoSetTolerances(p->tao, PetscMax(tol[0], tol[2] * gstart), tol[1], 0.0)); /* a re-solve stops where the first did, not relative to its own start */
  while (*reason > 0) {
    PetscReal change;
    PetscInt  n;
    PetscCall(ProblemStateLag(p, &change));
    PetscCall(PetscInfo(p->tao, "fixed point %" PetscInt_FMT ": the lagged pressure changed by %g (%" PetscInt_FMT " iterations so far)\n", k, (double)change, *its));
    p->res.lagSolves++;
    if (change <= p->cfg->lag.rtol) break;
    if (k >= p->cfg->lag.maxIt) {
      *reason = TAO_DIVERGED_MAXITS;
      PetscCall(PetscSNPrintf(p->res.why, sizeof(p->res.why), "friction: the normal pressure still changes by %g of its largest after -contact_friction_lag_max_it %" PetscInt_FMT " solves of the increment", (double)change, p->cfg->lag.maxIt));
      break;
    }
    PetscCall(ProblemTaoSolve(p, &n, reason));
    *its += n;
    k++;
  }
  PetscCall(TaoSetTolerances(p->tao, tol[0], tol[1], tol[2]));
  PetscFunctionReturn(0);
}

/* From rest, before the last penalty stage: the terms' lag at the softer
   stage's answer (friction.c: the last stage's first iterate then has rows
   and a bound), softer the factor of that stage's penalty over the last's.
   In 3D the pressure lagged is the softer stage's own, its k_p times its
   gaps. Read with the last stage's k_p, as 2D reads it, it was 1/softer
   times the answer's (1000 with -contact_penalty auto's continuation): a
   bound that tied every node where the frictionless soft stage had left
   it. The rigid cube of tests/test_rigidm3d.py, pressed off its centre and
   tilted there, was held so (its energy 5.5 against the answer's -1.1e-3,
   its rotations' stiffness through the force control's border -229: the
   contact's 1000-fold force on the lever below its reference point), and
   the fixed point's next solve, with the true bound, slid from there:
   DIVERGED_USER (Prescott, Nehalem, Sandybridge) or DIVERGED_LS_FAILURE
   (Haswell), 99 Newton iterations where it converged (SkylakeX). At the
   softer stage's k_p it converges under all five kernels (51 or 52
   iterations with the box held at its bottom, 37 or 38 held whole). 2D
   keeps the last stage's k_p (the cattaneo disc's figures, friction.c). */
static PetscErrorCode ProblemStateLagSofter(Problem p, PetscReal load, PetscReal softer, PetscReal penalty)
{
  const PetscBool three = (PetscBool)(ProblemGetDimension(p) == 3);
  PetscReal       change;

  PetscFunctionBeginUser;
  if (three) PetscCall(ProblemSetStage(p, load, penalty * softer));
  PetscCall(ProblemStateLag(p, &change));
  if (three) PetscCall(ProblemSetStage(p, load, penalty));
  PetscFunctionReturn(0);
}

/* The terms' state and the bodies' (a material's history): the bodies'
   displacement (p->X, converged at load) accepted. */
static PetscErrorCode ProblemStateAccept(Problem p, PetscReal load)
{
  PetscReal f;

  PetscFunctionBeginUser;
  if (!ProblemHasState(p) && !ProblemBodiesHaveState(p)) PetscFunctionReturn(0);
  PetscCall(ProblemEvaluate(p, p->X, &f, p->G, NULL));
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermAccept(p->terms[t], p->bodies, load));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyAcceptState(p->bodies[i]));
  PetscFunctionReturn(0);
}

/* An increment begins: the last converged one's state is the accepted one. */
static PetscErrorCode ProblemStateBegin(Problem p)
{
  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermBegin(p->terms[t]));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyBeginState(p->bodies[i]));
  PetscFunctionReturn(0);
}

/* Back to the accepted state, which p->X holds again (a cut-back). */
static PetscErrorCode ProblemStateRestore(Problem p)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyRestoreState(p->bodies[i]));
  if (!ProblemHasState(p)) PetscFunctionReturn(0);
  PetscCall(ProblemScatterToBodies(p, p->X));
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermRestore(p->terms[t], p->bodies));
  PetscFunctionReturn(0);
}

/* A solve from rest: the terms' state at rest. */
static PetscErrorCode ProblemStateReset(Problem p)
{
  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermReset(p->terms[t], p->bodies));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyResetState(p->bodies[i]));
  PetscFunctionReturn(0);
}

/* A stage's TAO solve from load l0 (the last converged) at load l1. Where
   its first iterate inverts an element (a neohookean body given the load's
   Dirichlet values at once, its inside still where the last load left it),
   the tangent predictor moves the inside along; if the iterate still
   inverts, the stage stops as at a NaN (TAO refuses an infinite energy at
   its start), and the load is cut back. A term with state (friction) then
   iterates its lag to a fixed point (converged where last: the load's last
   penalty stage). */
static PetscErrorCode ProblemStageSolve(Problem p, PetscReal l0, PetscReal l1, PetscReal penalty, PetscBool last, PetscInt *its, TaoConvergedReason *reason)
{
  PetscReal f, gstart = 0.0;

  PetscFunctionBeginUser;
  if (ProblemTangentVaries(p)) { /* a material that can invert (neohookean) */
    PetscCall(ProblemEvaluate(p, p->X, &f, p->G, NULL));
    if (PetscIsInfReal(f)) {
      PetscCall(ProblemPredict(p, l0, l1, penalty));
      PetscCall(ProblemEvaluate(p, p->X, &f, p->G, NULL));
    }
    if (PetscIsInfReal(f)) {
      PetscCall(PetscInfo(p->tao, "the stage's first iterate inverts an element: stopped as at a NaN\n"));
      *its    = 0;
      *reason = TAO_DIVERGED_NAN;
      PetscFunctionReturn(0);
    }
  }
  if (last && ProblemHasState(p)) { /* the first gradient, for the lag's re-solves */
    PetscCall(ProblemEvaluate(p, p->X, &f, p->G, NULL));
    PetscCall(VecNorm(p->G, NORM_2, &gstart));
  }
  PetscCall(ProblemTaoSolve(p, its, reason));
  PetscCall(ProblemStageSolveLagged(p, last, gstart, its, reason));
  PetscFunctionReturn(0);
}

/* Whether a stopped solve is retried with a smaller load increment: its line
   search failed (or met a NaN), which is what an iterate thrown far from the
   solution by a large step of the load meets (the contact's kinks, a
   non-convex energy at deep overlap); not a limit the user set. TAO's own
   budget of energy evaluations runs out the same way, where line searches
   keep failing and L-BFGS restarts after each (lmvm.c: measured on the half
   scene at h = 0.01, k_p = 1e10, push 0.3, mortar, where the load's half
   then converges); -tao_max_funcs given is the user's limit. Not where the
   solve stopped while a frictional contact slid without end (slidewatch.c). */
static PetscErrorCode ProblemCutbackApplies(Problem p, TaoConvergedReason r, PetscBool *applies)
{
  PetscBool userLimit = PETSC_FALSE, slid;

  PetscFunctionBeginUser;
  *applies = PETSC_FALSE;
  if (r > 0) PetscFunctionReturn(0);
  PetscCall(ProblemSlideWatchSlid(p, &slid));
  if (slid) PetscFunctionReturn(0); /* a contact sliding without end: a smaller step of the same force slides too (slidewatch.c) */
  if (r == TAO_DIVERGED_MAXFCN) PetscCall(PetscOptionsHasName(NULL, NULL, "-tao_max_funcs", &userLimit));
  *applies = (PetscBool)(r == TAO_DIVERGED_LS_FAILURE || r == TAO_DIVERGED_NAN || r == TAO_DIVERGED_TR_REDUCTION || (r == TAO_DIVERGED_MAXFCN && !userLimit));
  PetscFunctionReturn(0);
}

/* Coupled force control: the gradient norm at rest of the displacement run
   that imposes the controls' displacements as X now holds them (the bodies'
   dofs at 0; the controls' own entries left out, as that run has none),
   counted as no energy evaluation. A displacement run's last stage stops
   relative to its gradient at rest, K_fc 1 U and the loads; a force
   control's at rest is F alone, far smaller where the group's own stiffness
   is large (the reference scene pushed by 0.01: 2.25 against 577), so that
   its solve would be held to a tighter stop than the displacement run's.
   A body held by contact keeps its anchors at 0 there: one vertex moved
   alone would give a gradient of its own stiffness times U. And in a scene
   with a body held by contact the scale is at most the scene's largest
   force (at the state the last stage starts from): a displacement pushed
   into a penalty contact from rest gives a gradient far above the forces
   it makes, and a body held by contact balances its contacts only to the
   stop (measured on the roller pushed by 1000: a scale of 116079 stopped
   at a gradient norm of 8.3e-5 with the contacts 4e-7 of the load apart).
   Once an earlier stage has found U, its last stage stops relative to the
   larger of the two. */
static PetscErrorCode ProblemControlGradientScale(Problem p, PetscReal g0, PetscReal *g)
{
  PetscReal f, S = 0;
  Vec       Y;

  PetscFunctionBeginUser;
  if (UnheldAny(&p->fc.unheld)) { /* the scene's largest force, at the state the last stage starts from */
    PetscCall(ProblemEvaluate(p, p->X, &f, p->G, NULL));
    PetscCall(ProblemControlSceneForce(p, &S));
  }
  PetscCall(VecDuplicate(p->X, &Y));
  PetscCall(ProblemControlRest(p, p->X, Y));
  PetscCall(ProblemEvaluate(p, Y, &f, p->G, NULL)); /* G: the bodies' part alone */
  PetscCall(VecNorm(p->G, NORM_2, g));
  PetscCall(VecDestroy(&Y));
  *g = PetscMax(g0, *g);
  if (S > 0) *g = PetscMin(*g, S);
  PetscFunctionReturn(0);
}

/* Room in the load path's record for one more state of ngroups groups. */
static PetscErrorCode LoadPathReserve(LoadPath *lp, PetscInt ngroups)
{
  const PetscInt cap = 2 * lp->cap + 8;
  PetscReal     *l, *e, *r;

  PetscFunctionBeginUser;
  if (lp->n < lp->cap) PetscFunctionReturn(0);
  PetscCall(PetscMalloc3(cap, &l, cap, &e, 3 * cap * ngroups, &r));
  PetscCall(PetscArraycpy(l, lp->load, lp->n));
  PetscCall(PetscArraycpy(e, lp->energy, lp->n));
  PetscCall(PetscArraycpy(r, lp->reaction, 3 * lp->n * ngroups));
  PetscCall(PetscFree3(lp->load, lp->energy, lp->reaction));
  lp->load = l, lp->energy = e, lp->reaction = r, lp->cap = cap, lp->ngroups = ngroups;
  PetscFunctionReturn(0);
}

/* -load_path: appends the state at load factor load to the record (X, or
   rest where atRest: X = 0 at load 0, the record restarted), its energy and
   every Dirichlet group's reaction; the record then reads as the load path
   of the converged states from rest, whose energy is the work of the
   reactions along it (where the groups' values are the only loading). */
static PetscErrorCode ProblemLoadPathAppend(Problem p, PetscReal load, PetscBool atRest)
{
  LoadPath *lp = &p->res.path;
  PetscReal f, *R, stage = p->res.load;
  PetscInt  ngroups = 0;
  Vec       X = p->X;

  PetscFunctionBeginUser;
  if (!p->cfg->load.path) PetscFunctionReturn(0);
  for (PetscInt i = 0; i < p->nbodies; ++i) ngroups += BodyGetNumConditions(p->bodies[i]);
  if (atRest) lp->n = 0;
  PetscCall(LoadPathReserve(lp, ngroups));
  if (atRest) {
    PetscCall(VecDuplicate(p->X, &X));
    PetscCall(ProblemSetStage(p, 0.0, 1.0));
  }
  PetscCall(ProblemEvaluate(p, X, &f, p->G, NULL));
  R = lp->reaction + 3 * lp->n * ngroups;
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    PetscCall(BodyComputeReactions(p->bodies[i], BodyGetLocalGradient(p->bodies[i])));
    for (PetscInt j = 0; j < BodyGetNumConditions(p->bodies[i]); ++j, R += 3) PetscCall(PetscArraycpy(R, BodyGetCondition(p->bodies[i], j)->reaction, 3));
  }
  lp->load[lp->n]   = load;
  lp->energy[lp->n] = f;
  lp->n++;
  if (atRest) {
    PetscCall(VecDestroy(&X));
    PetscCall(ProblemSetStage(p, stage, 1.0)); /* the load the solve starts at, as it was */
  }
  PetscFunctionReturn(0);
}

/* The penalty stages at load factor load, each a TAO solve from the last;
   the last stage of the last load (of every load with -load_path or with a
   term that keeps state from load to load, friction, whose history an
   increment stopped at -stage_rtol would carry on: 1 and 2 ranks then
   differed by 5e-5 in the cattaneo scene's shear; of each load stage's end)
   stops at
   the final tolerance, gttol times the gradient norm g0 of the full problem
   at rest, the others when their gradient norm has fallen by -stage_rtol. */
static PetscErrorCode ProblemSolveLoad(Problem p, PetscReal load, PetscBool lastLoad, PetscBool stageEnd, const PetscReal tol[3], PetscReal g0, PetscInt *its, TaoConvergedReason *reason)
{
  const ProblemSchedule *sc = &p->sched;

  PetscFunctionBeginUser;
  PetscCall(ProblemStateBegin(p));
  if (p->res.loadDone > 0) /* a tied start's next increments (friction.c): the given forces grow as the load within the first stage */
    for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermScaleBound(p->terms[t], load <= 1.0 ? load / p->res.loadDone : 1.0));
  for (PetscInt s = 1; s <= sc->penaltyStages; ++s) {
    const PetscBool last    = (PetscBool)(lastLoad && s == sc->penaltyStages);
    const PetscBool tight   = (PetscBool)((lastLoad || stageEnd || p->cfg->load.path || ProblemHasState(p) || ProblemBodiesHaveState(p)) && s == sc->penaltyStages); /* stops at the final tolerance (every load where a term or a body keeps its state from it) */
    const PetscReal penalty = sc->penaltyStages > 1 ? PetscPowReal(sc->penaltyStart, (PetscReal)(sc->penaltyStages - s) / (sc->penaltyStages - 1)) : 1.0;
    PetscInt        n;

    PetscCall(ProblemSetStage(p, load, penalty));
    PetscCall(ProblemLMVMSetLastStage(p, last));
    if (last && p->fc.coupled && p->res.stagesDone > 0) { /* force control: as the displacement run of the U found */
      PetscReal gd;
      PetscCall(ProblemControlGradientScale(p, g0, &gd));
      PetscCall(PetscInfo(p->tao, "force control: the last stage stops relative to %g (at rest: %g)\n", (double)gd, (double)g0));
      g0 = gd;
    }
    if (tight) PetscCall(TaoSetTolerances(p->tao, PetscMax(tol[0], tol[2] * g0), tol[1], 0.0));
    else PetscCall(TaoSetTolerances(p->tao, tol[0], tol[1], p->cfg->stop.stageRtol));
    PetscCall(ProblemForceStopSetActive(p, tight));
    if (s > 1 && s == sc->penaltyStages && p->res.loadDone == 0.0 && !p->X0 && ProblemHasState(p)) /* from rest: the lag at the softer stage's answer (friction.c) */
      PetscCall(ProblemStateLagSofter(p, load, PetscPowReal(sc->penaltyStart, 1.0 / (sc->penaltyStages - 1)), penalty));
    PetscCall(ProblemStageSolve(p, p->res.loadDone, load, penalty, (PetscBool)(s == sc->penaltyStages), &n, reason));
    PetscCall(PetscInfo(p->tao, "stage %" PetscInt_FMT ": load %g, penalty factor %g: %s after %" PetscInt_FMT " iterations\n", p->res.stagesDone + 1, (double)load, (double)penalty, TaoConvergedReasons[*reason], n));
    *its += n;
    p->res.stagesDone++;
    if (*reason <= 0) PetscFunctionReturn(0);
  }
  PetscFunctionReturn(0);
}

/* Load stepping (outer), penalty continuation (inner) and automatic cutback.
   The load parameter walks from 0 to S = -load_stages, through each stage
   in steps of 1/-load_steps (a step never crosses a stage's end); each load
   is solved from the last converged state. Where a load's solve stops with
   a failed line search the state goes back to the last converged one and
   the step is halved (at most -load_cutbacks times in all): a smaller step
   of the load starts Newton closer to the solution it tracks, as an
   implicit analysis cuts back its increment. A single solve from rest (the
   default, one stage) that fails starts this walk with a step of 1/2; a
   given start (p->X0) is solved at the last stage's end at once. The last
   stage stops where a single solve from rest would, at -tao_gttol times the
   gradient norm of the full problem at rest, which makes the result
   independent of the staging; so does each stage's end, which is recorded
   (with -load_path every load's last stage stops there, and each converged
   load is recorded). */
static PetscErrorCode ProblemSolveStages(Problem p, PetscInt *its, TaoConvergedReason *reason)
{
  const PetscReal S = (PetscReal)p->cfg->load.stages;
  PetscReal       tol[3], g0 = -1.0, step = 1.0 / p->sched.loadSteps;
  PetscBool       cut;
  Vec             Xs;

  PetscFunctionBeginUser;
  *its = 0;
  p->res.stagesDone = 0;
  p->res.cutbacks   = 0;
  p->res.loadDone   = 0.0;
  PetscCall(ProblemSetHessianSwitchReference(p, -1.0)); /* -contact_hessian auto: the first Hessian's */
  PetscCall(ProblemLMVMBeginStaged(p)); /* a single solve is the last stage */
  PetscCall(TaoGetTolerances(p->tao, &tol[0], &tol[1], &tol[2]));
  if (!p->X0) PetscCall(ProblemStateReset(p)); /* a given start goes on from the accepted state */
  PetscCall(ProblemLoadPathAppend(p, 0.0, PETSC_TRUE));
  if (p->sched.loadSteps * p->sched.penaltyStages == 1 && (S == 1 || p->X0)) { /* one solve, from rest or from the given start */
    if (p->X0 || ProblemTangentVaries(p)) { /* a given start, or the tangent predictor's: the stop is relative to the gradient at rest */
      PetscCall(ProblemGradientAtRest(p, &g0));
      if (p->X0) PetscCall(VecCopy(p->X0, p->X));
      PetscCall(TaoSetTolerances(p->tao, PetscMax(tol[0], tol[2] * g0), tol[1], 0.0));
    }
    PetscCall(ProblemSetStage(p, S, 1.0));
    PetscCall(ProblemStateBegin(p));
    PetscCall(ProblemForceStopSetActive(p, PETSC_TRUE));
    PetscCall(ProblemStageSolve(p, p->X0 ? S : 0.0, S, 1.0, PETSC_TRUE, its, reason));
    p->res.stagesDone = 1;
    PetscCall(ProblemCutbackApplies(p, *reason, &cut));
    cut = (PetscBool)(cut && p->cfg->load.cutbacks > 0);
    if (!cut) {
      if (*reason > 0) PetscCall(ProblemStateAccept(p, S));
      if (*reason > 0) p->res.loadDone = S;
      if (*reason > 0) PetscCall(ProblemLoadPathAppend(p, S, PETSC_FALSE));
      if (*reason > 0) PetscCall(ProblemStageEndRecord(p, (PetscInt)S));
      PetscFunctionReturn(0);
    }
    PetscCall(PetscInfo(p->tao, "the solve from rest stopped (%s): load steps of 1/2 from rest\n", TaoConvergedReasons[*reason]));
    p->res.cutbacks = 1;
    step        = 0.5;
    PetscCall(ProblemStateReset(p));
  }
  if (g0 < 0) PetscCall(ProblemGradientAtRest(p, &g0));
  PetscCall(ProblemSetHessianSwitchReference(p, g0)); /* every stage switches where a single solve would */
  PetscCall(VecZeroEntries(p->X));
  PetscCall(VecDuplicate(p->X, &Xs));
  PetscCall(VecCopy(p->X, Xs));
  while (p->res.loadDone < S) {
    const PetscReal end = PetscFloorReal(p->res.loadDone + 1e-12) + 1.0; /* the end of the stage the load is in */
    const PetscReal next = p->res.loadDone + step, load = next > end - 1e-12 ? end : next; /* a step on from the last converged load */
    PetscCall(ProblemSolveLoad(p, load, (PetscBool)(load == S), (PetscBool)(load == end), tol, g0, its, reason));
    if (*reason > 0) {
      PetscCall(ProblemStateAccept(p, load));
      p->res.loadDone = load;
      PetscCall(ProblemLoadPathAppend(p, load, PETSC_FALSE));
      if (load == end) PetscCall(ProblemStageEndRecord(p, (PetscInt)end));
      PetscCall(VecCopy(p->X, Xs));
      continue;
    }
    PetscCall(ProblemCutbackApplies(p, *reason, &cut));
    if (!cut || p->res.cutbacks >= p->cfg->load.cutbacks) break;
    PetscCall(PetscInfo(p->tao, "load %g stopped (%s): back to load %g, step %g\n", (double)load, TaoConvergedReasons[*reason], (double)p->res.loadDone, (double)(0.5 * step)));
    p->res.cutbacks++;
    step *= 0.5;
    PetscCall(VecCopy(Xs, p->X));
    PetscCall(ProblemStateRestore(p));
  }
  PetscCall(VecDestroy(&Xs));
  PetscFunctionReturn(0);
}

/* The stages, and TAO's tolerances restored after them (they set each
   stage's own), so that another solve of the same problem (force control's
   next trial) stops by the same test. */
PetscErrorCode ProblemSolveStaged(Problem p, PetscInt *its, TaoConvergedReason *reason)
{
  PetscReal tol[3];

  PetscFunctionBeginUser;
  PetscCall(TaoGetTolerances(p->tao, &tol[0], &tol[1], &tol[2]));
  PetscCall(ProblemSolveStages(p, its, reason));
  PetscCall(TaoSetTolerances(p->tao, tol[0], tol[1], tol[2]));
  PetscCall(ProblemForceStopSetActive(p, PETSC_FALSE));
  PetscFunctionReturn(0);
}
