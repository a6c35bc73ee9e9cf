/* The final stop measured against the forces the contacts carry
   (-stop_force_rtol).

   The final tolerance is relative to the gradient at rest (staging.c):
   ||g|| <= gttol ||g_0||. At rest the free dofs are 0 and a displaced
   group's displacement sits on its nodes alone, so that g_0 holds the
   stiffness of that group's first layer of elements times the displacement,
   whatever the contact will carry. Where the body so driven is far stiffer
   than its partner the two part: a punch of E = 1e7 pushed 0.01 into a
   layer of E = 1 (the layer 0.3 thick, 3 wide, h = 0.0125 at the contact)
   has ||g_0|| = 1.2e6 and carries P = 0.042, so that the stop at 1e-8 of
   ||g_0|| met Newton after 2 iterations with ||g|| = 5.9e-3, P 19 % above
   its converged value (0.0500 against 0.0421), and reported CONVERGED.

   What the stop should bound is the error of the forces the user reads.
   At an iterate u the gradient g = f_int(u) - f_c(u) - f_ext is the force
   out of balance at the free dofs; f_c, the contacts' nodal forces (the
   terms' gradient alone), is what it unbalances. A contact force read off
   the solution is in error by about ||g|| / ||f_c|| relative where g is
   spread as f_c is (a uniform residual over the n contact nodes moves P by
   sqrt(n) ||g||, and ||f_c|| is P / sqrt(n) for a uniform pressure). So a
   last stage whose gradient has met TAO's test (GATOL, GRTOL, GTTOL) goes
   on while
       ||g|| > rtol ||f_c||,   rtol = -stop_force_rtol (1e-6),
   ||f_c|| computed at that iterate; the test only tightens TAO's, never
   loosens it, and is off where no contact carries a force (f_c = 0) and
   where the user gave a TAO gradient tolerance and not this option (a
   stop chosen: -tao_gatol 1000 to look at an iterate far from the
   answer, -tao_gttol 1e-12 to pin one).
   Past TAO's test the gradient may reach its round-off floor above the
   forces' test (asked 1e-10 on that punch, it stalls at 2.5e-8), or crawl
   (the shipped punch with the block as mortar slave: about 1e-2 of the
   forces, iteration after iteration of 1 s each, up to TAO's 500): where
   it has not halved in FORCESTOP_STALL iterations the solve ends there,
   converged with TAO's reason (JSON `force_stop.floors`), and a converged
   solve whose gradient is above the forces' test says so in a warning
   (ProblemPostProcess): the forces are as far from converged as that.
   If the solve, gone on, ends otherwise than converged (a line search
   that fails at round-off, the iteration budget: the coarse rubber squeeze
   at 1.4e-5 of its forces), or stalls, it ends at the iterate of least
   gradient past TAO's test, with TAO's reason there, no worse than without
   this test (JSON `force_stop`: the solves continued, those ended at their
   floor and those ended so).
   The JSON's `force_residual` is ||g|| / ||f_c|| at the solution. */
#include "forcestop.h"
#include "problem.h"
#include "body.h"
#include "energyterm.h"

#define FORCESTOP_STALL 10

/* ||f_c||: the terms' gradient alone at X, summed into the bodies' dofs
   (a rigid body's unknowns, which have none, left out). */
PetscErrorCode ProblemContactForceNorm(Problem p, Vec X, PetscReal *fc)
{
  Vec       W;
  PetscReal et;

  PetscFunctionBeginUser;
  *fc = 0.0;
  if (!p->nterms) PetscFunctionReturn(0);
  PetscCall(ProblemScatterToBodies(p, X));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(VecZeroEntries(BodyGetLocalGradient(p->bodies[i])));
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermComputeEnergyGradient(p->terms[t], p->bodies, &et));
  PetscCall(VecDuplicate(X, &W));
  PetscCall(ProblemGatherGradient(p, W));
  PetscCall(VecNorm(W, NORM_2, fc));
  PetscCall(VecDestroy(&W));
  PetscFunctionReturn(0);
}

/* After TAO's test (or L-BFGS's decrement test), in a last stage: the forces'. */
PetscErrorCode ProblemForceStopTest(Problem p, Tao tao)
{
  ForceStop         *s = &p->fstop;
  TaoConvergedReason reason;
  PetscReal          gnorm, fc;
  Vec                X;

  PetscFunctionBeginUser;
  if (!s->active || p->opt.forceRtol <= 0) PetscFunctionReturn(0);
  PetscCall(TaoGetConvergedReason(tao, &reason));
  if (reason != TAO_CONVERGED_GATOL && reason != TAO_CONVERGED_GRTOL && reason != TAO_CONVERGED_GTTOL) PetscFunctionReturn(0);
  PetscCall(TaoGetSolutionStatus(tao, NULL, NULL, &gnorm, NULL, NULL, NULL));
  PetscCall(TaoGetSolution(tao, &X));
  PetscCall(ProblemContactForceNorm(p, X, &fc));
  if (fc <= 0.0) PetscFunctionReturn(0);
  s->ratio = gnorm / fc;
  if (gnorm <= p->opt.forceRtol * fc) PetscFunctionReturn(0);
  if (!s->met) { /* the first iterate that met TAO's test: kept, to end at if the solve goes no further */
    if (!s->Xmet) PetscCall(VecDuplicate(X, &s->Xmet));
    PetscCall(VecCopy(X, s->Xmet));
    s->met       = PETSC_TRUE;
    s->metReason = reason;
    s->best = s->ref = gnorm;
    s->stalled       = 0;
    s->continued++;
  } else {
    if (gnorm < s->best) { /* the least gradient past TAO's test: the iterate to end at */
      s->best = gnorm;
      PetscCall(VecCopy(X, s->Xmet));
    }
    if (gnorm < 0.5 * s->ref) {
      s->ref     = gnorm;
      s->stalled = 0;
    } else if (++s->stalled >= FORCESTOP_STALL) { /* the gradient's round-off floor, or a crawl: as far as the solve goes */
      PetscCall(PetscInfo(tao, "the gradient norm %g (%g of the contacts' nodal forces) has not halved in %d iterations: as far as it goes, converged (%s) at the least, %g\n", (double)gnorm, (double)s->ratio, FORCESTOP_STALL, TaoConvergedReasons[reason], (double)s->best));
      s->floors++;
      PetscFunctionReturn(0); /* ProblemForceStopEnd moves it to Xmet */
    }
  }
  PetscCall(PetscInfo(tao, "the gradient norm %g met %s but is %g of the contacts' nodal forces (%g), above -stop_force_rtol %g: going on\n", (double)gnorm, TaoConvergedReasons[reason], (double)s->ratio, (double)fc, (double)p->opt.forceRtol));
  PetscCall(TaoSetConvergedReason(tao, TAO_CONTINUE_ITERATING));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemForceStopSetActive(Problem p, PetscBool active)
{
  PetscFunctionBeginUser;
  p->fstop.active = active;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemForceStopBegin(Problem p)
{
  PetscFunctionBeginUser;
  p->fstop.met = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemForceStopEnd(Problem p, TaoConvergedReason *reason)
{
  ForceStop *s = &p->fstop;
  PetscReal  f;

  PetscFunctionBeginUser;
  if (!s->met) PetscFunctionReturn(0);
  s->met = PETSC_FALSE;
  if (*reason > 0 && s->stalled < FORCESTOP_STALL) PetscFunctionReturn(0); /* converged by the forces' test */
  PetscCall(PetscInfo(p->tao, "the solve, gone on past the gradient tolerance for the forces' test, stopped with %s: it ends at its least gradient past it, %g (%s)\n", TaoConvergedReasons[*reason], (double)s->best, TaoConvergedReasons[s->metReason]));
  if (*reason <= 0) s->fallbacks++;
  PetscCall(VecCopy(s->Xmet, p->X));
  PetscCall(ProblemEvaluate(p, p->X, &f, p->G, NULL)); /* the bodies and terms at the state kept */
  *reason = s->metReason;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemForceStopDestroy(Problem p)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&p->fstop.Xmet));
  PetscFunctionReturn(0);
}
