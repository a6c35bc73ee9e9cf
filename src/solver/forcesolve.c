/* Force control's solves (forcecontrol.c derives the formulation): the
   types by name (-force_control_type, ForceControlList: coupled, outer),
   the coupled type's solve, on from its staged solve while a reaction is
   further from its force than -force_control_rtol, and the coupled type's
   penalty continuation where the user chose none. The outer type is
   forceouter.c's. */
#include "forcesolve.h"
#include "forceouter.h"
#include "staging.h"
#include "schedule.h"
#include "problem.h"
#include "forcecontrol.h"

static PetscErrorCode ProblemSolveControlledCoupled(Problem, PetscInt *, TaoConvergedReason *);

static PetscErrorCode ForceControlFinalize(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&ForceControlList));
  PetscFunctionReturn(0);
}


PetscErrorCode ForceControlRegisterAll(void)
{
  PetscFunctionBeginUser;
  if (ForceControlList) PetscFunctionReturn(0);
  PetscCall(PetscFunctionListAdd(&ForceControlList, "coupled", ProblemSolveControlledCoupled));
  PetscCall(PetscFunctionListAdd(&ForceControlList, "outer", ProblemSolveControlledOuter));
  PetscCall(PetscRegisterFinalize(ForceControlFinalize));
  PetscFunctionReturn(0);
}


/* Coupled force control's penalty continuation, where the user chose none:
   from where the stiffest pair's k_p h / E* is CONTROL_START_STIFFNESS, in
   stages at most CONTROL_STAGE_FACTOR apart, unless the schedule already
   chosen starts as soft (L-BFGS's, lmvm.c). From rest nothing holds a force-controlled body but the contact,
   whose Hessian holds only the points already in contact: a Newton step
   towards the force closes points beyond them, and at a stiff penalty the
   line search cuts the step to the first of them, so that the contact zone
   grows by a few points a step. At k_p h / E* about 1 the contact is as
   soft as the bodies and full steps hold; the stiffer stage starts from the
   softer one's wider zone, which it only shrinks, as a displacement run's
   steps do. Measured (scripts/force_control_table.py, 1 rank; in brackets
   the displacement run's): the hertz scene at k_p = 2e6 (k_p h / E* = 364)
   20 iterations in one stage, 12 in 2 from 1e-2, 13 in 3 from 2.7e-3 or in
   2 from 1e-3 (8); softdisc at hc = 0.0007 19 in the automatic penalty's 2
   stages from 0.03, 13 in 2 from 1e-2, 10 in 2 from 1e-3, 11 in 3 from
   1e-3 (7); sphere 12 in 3 stages from 1e-3, 11 in 2 (6); all at
   -force_control_step 0.1. So one jump, of
   at most 1000. */
#define CONTROL_START_STIFFNESS 1.0
#define CONTROL_STAGE_FACTOR    1000.0

PetscErrorCode ProblemSetControlContinuation(Problem p)
{
  PetscReal stiff = 0.0, s, start;
  PetscInt  stages;

  PetscFunctionBeginUser;
  if (!p->fc.coupled || p->cfg->penalty.stagesSet || p->cfg->penalty.startSet) PetscFunctionReturn(0);
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscCall(EnergyTermGetPenaltyStiffness(p->terms[t], &s));
    stiff = PetscMax(stiff, s);
  }
  if (!(stiff > CONTROL_START_STIFFNESS)) PetscFunctionReturn(0);
  start = CONTROL_START_STIFFNESS / stiff;
  if (p->sched.penaltyStages > 1 && p->sched.penaltyStart <= start) PetscFunctionReturn(0); /* a schedule as soft already (L-BFGS's) */
  stages = 1 + (PetscInt)PetscCeilReal(PetscLogReal(1.0 / start) / PetscLogReal(CONTROL_STAGE_FACTOR) - 1e-6);
  PetscCall(ProblemSetPenaltyContinuation(p, stages, start));
  PetscCall(PetscInfo(NULL, "force control: k_p h / E* = %g: %" PetscInt_FMT " penalty stages from %g k_p\n", (double)stiff, stages, (double)start));
  PetscFunctionReturn(0);
}


/* Whether every reaction is its force to -force_control_rtol. */
static PetscBool ControlsConverged(Problem p)
{
  for (PetscInt k = 0; k < p->fc.n; ++k)
    if (PetscAbsReal(p->fc.c[k].R - p->fc.c[k].force) > p->cfg->control.rtol * p->fc.c[k].scale) return PETSC_FALSE;
  return PETSC_TRUE;
}


/* The coupled type: the staged solve of (u, U), then, while a reaction is
   further from its force than -force_control_rtol, the solve on from there
   with the gradient tolerance -force_control_rtol times the least scale. */
static PetscErrorCode ProblemSolveControlledCoupled(Problem p, PetscInt *its, TaoConvergedReason *reason)
{
  PetscReal smin = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  p->res.why[0]        = 0;
  p->res.controlSolves = 1;
  PetscCall(ProblemSolveStaged(p, its, reason));
  for (PetscInt k = 0; k < p->fc.n; ++k) smin = PetscMin(smin, p->fc.c[k].scale);
  while (*reason > 0) {
    ProblemSchedule saved;
    PetscReal       tol[3];
    PetscInt        n;
    Vec             X0;

    PetscCall(ProblemComputeReactions(p, p->X)); /* the controls' U (ProblemScatterToBodies) and R at X */
    for (PetscInt k = 0; k < p->fc.n; ++k) p->fc.c[k].R = ProblemControlReaction(p, k);
    if (!p->cfg->control.rtolSet || ControlsConverged(p)) break;
    if (p->res.controlSolves >= p->cfg->control.maxIt) {
      *reason = TAO_DIVERGED_MAXITS;
      PetscCall(PetscSNPrintf(p->res.why, sizeof(p->res.why), "force control: the reactions are not the forces after -force_control_max_it %" PetscInt_FMT " solves (%s: reaction %g, force %g)", p->cfg->control.maxIt, ProblemControlGroup(p, 0), (double)p->fc.c[0].R, (double)p->fc.c[0].force));
      break;
    }
    PetscCall(PetscInfo(p->tao, "force control: reaction %g, force %g: the solve goes on to the gradient %g\n", (double)p->fc.c[0].R, (double)p->fc.c[0].force, (double)(p->cfg->control.rtol * smin)));
    PetscCall(VecDuplicate(p->X, &X0));
    PetscCall(VecCopy(p->X, X0));
    PetscCall(ProblemSetInitialGuess(p, X0));
    PetscCall(VecDestroy(&X0));
    PetscCall(TaoGetTolerances(p->tao, &tol[0], &tol[1], &tol[2]));
    PetscCall(TaoSetTolerances(p->tao, p->cfg->control.rtol * smin, tol[1], 0.0));
    PetscCall(ProblemScheduleOneStage(p, &saved));
    PetscCall(ProblemSolveStaged(p, &n, reason));
    PetscCall(ProblemScheduleRestore(p, &saved));
    PetscCall(TaoSetTolerances(p->tao, tol[0], tol[1], tol[2]));
    PetscCall(VecDestroy(&p->X0));
    p->res.controlSolves++;
    *its += n;
  }
  PetscFunctionReturn(0);
}


PetscErrorCode ProblemSolveControlled(Problem p, PetscInt *its, TaoConvergedReason *reason)
{
  PetscErrorCode (*solve)(Problem, PetscInt *, TaoConvergedReason *) = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListFind(ForceControlList, p->fc.coupled ? "coupled" : "outer", &solve));
  PetscCheck(solve, p->comm, PETSC_ERR_PLIB, "force control: type not registered");
  PetscCall((*solve)(p, its, reason));
  PetscFunctionReturn(0);
}
