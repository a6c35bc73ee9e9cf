/* The watch for a frictional contact that slides without end.

   A tangential force above what friction holds, mu P, has no equilibrium:
   every node of the contact slips, and each Newton step carries the body
   further along, the energy falling by (Q - mu P) times the slip with no
   bound. Where the scene's given forces say so before solving (a body held
   by one frictional pair with forces alone, givenforces.c; a force no
   contact can react, support.c) the run is refused then; where they do not
   (the normal force comes from a displacement, or from several pairs) the
   solve used to go on to a line search that failed, four cutbacks, and
   each cut load failing again (57 to 103 s), or to More-Thuente's own
   error "dx * (stp-stx) >= 0.0".

   Watched at each iteration of every solve, from the terms' state at the
   iterate (EnergyTermGetSlipState): while some frictional pair has nodes
   in contact and none of them sticks, the largest trial slip s_k of the
   increment is recorded. A converging Newton's slip settles: its changes
   contract (quadratically near the answer, as every increment of the
   friction tests' gross sliding under a displacement does). A slide
   without end does not: s_k grows and its change does not contract,
       s_k > s_{k-1} > s_{k-2}  and  s_k - s_{k-1} >= s_{k-1} - s_{k-2} / 2,
   and s_k is beyond what the displacements given could make it: 2 D, D
   the largest displacement a Dirichlet component imposes (a part slid 0.3
   along a ledge by its displacement slips up to 0.3, its first Newton
   iterates growing as a slide would; the cattaneo disc below, pushed 0.003,
   slipped 0.88 then 4.07 in its iterates).
   After SLIDE_GROWING such iterates in a row the solve stops at once,
   DIVERGED_USER, with the pair's diagnosis (mortar.c: "pair X slides: none
   of its n nodes in contact sticks ..."), and no cutback: a smaller load
   increment of the same force would slide as well. A solve that stops
   otherwise (its line search failing on the slide) after such iterates,
   SLIDE_GROWING - 1 in a row, with no node sticking at its last, is taken
   as the same slide: no cutback (ProblemSlideWatchSlid; the cattaneo disc
   above: 3.0 s with four cutbacks before, each failing again). */
#include "slidewatch.h"
#include "problem.h"
#include "energyterm.h"

#define SLIDE_GROWING 3

/* D, the largest displacement any Dirichlet component imposes at the end of
   any stage (force-controlled components and anchors left out; a body's
   exact solution counts as unbounded): a slide between bodies held by
   displacements is bounded by about D. */
static PetscReal ProblemImposedDisplacement(Problem p)
{
  PetscReal D = 0.0;

  for (PetscInt i = 0; i < p->nbodies; ++i) {
    const Body b = p->bodies[i];
    for (PetscInt g = 0; g < BodyGetNumConditions(b); ++g) {
      const BodyBC *bc = BodyGetCondition(b, g);
      if (bc->anchor) continue;
      if (bc->exact) return PETSC_INFINITY;
      for (PetscInt c = 0; c < bc->ncomp; ++c) {
        if (bc->control[c]) continue;
        D = PetscMax(D, PetscAbsReal(bc->values[c]));
        for (PetscInt k = 0; k < PetscMin(BodyGetNumStages(b), CONTACT_MAX_STAGES); ++k) D = PetscMax(D, PetscAbsReal(bc->stage[k][c]));
      }
    }
  }
  return D;
}

PetscErrorCode ProblemSlideWatchBegin(Problem p)
{
  PetscFunctionBeginUser;
  p->slide.bound   = 2.0 * ProblemImposedDisplacement(p);
  p->slide.n       = 0;
  p->slide.growing = 0;
  p->slide.peak    = 0;
  p->slide.term    = -1;
  p->slide.sliding = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSlideWatchSlid(Problem p, PetscBool *slid)
{
  SlideWatch *w = &p->slide;

  PetscFunctionBeginUser;
  *slid = (PetscBool)(w->term >= 0 && w->peak >= SLIDE_GROWING - 1 && w->sliding);
  if (*slid && !p->res.why[0]) PetscCall(EnergyTermDiagnose(p->terms[w->term], sizeof(p->res.why), p->res.why));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSlideWatchTest(Problem p, Tao tao)
{
  SlideWatch        *w = &p->slide;
  TaoConvergedReason reason;
  PetscInt           it, sliding = -1;
  PetscReal          slip = 0.0;

  PetscFunctionBeginUser;
  PetscCall(TaoGetConvergedReason(tao, &reason));
  if (reason != TAO_CONTINUE_ITERATING) PetscFunctionReturn(0);
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscInt  stuck, loaded;
    PetscReal s;
    PetscCall(EnergyTermGetSlipState(p->terms[t], &stuck, &loaded, &s));
    if (loaded > 0 && stuck == 0 && s >= slip) {
      sliding = t;
      slip    = s;
    }
  }
  w->sliding = (PetscBool)(sliding >= 0);
  if (sliding < 0) { /* some node sticks, or no friction: nothing slides without end */
    w->n       = 0;
    w->growing = 0;
    PetscFunctionReturn(0);
  }
  if (w->n == 3) {
    w->slip[0] = w->slip[1];
    w->slip[1] = w->slip[2];
    w->n       = 2;
  }
  w->slip[w->n++] = slip;
  if (w->n < 3) PetscFunctionReturn(0);
  if (w->slip[2] > w->slip[1] && w->slip[1] > w->slip[0] && w->slip[2] - w->slip[1] >= 0.5 * (w->slip[1] - w->slip[0]) && w->slip[2] > w->bound) w->growing++;
  else w->growing = 0;
  w->peak = PetscMax(w->peak, w->growing);
  w->term = sliding;
  PetscCall(TaoGetIterationNumber(tao, &it));
  PetscCall(PetscInfo(tao, "iteration %" PetscInt_FMT ": no node of pair %s sticks; its largest slip %g (%" PetscInt_FMT " growing)\n", it, p->terms[sliding]->name, (double)slip, w->growing));
  if (w->growing < SLIDE_GROWING) PetscFunctionReturn(0);
  PetscCall(EnergyTermDiagnose(p->terms[sliding], sizeof(p->res.why), p->res.why));
  if (!p->res.why[0]) PetscCall(PetscSNPrintf(p->res.why, sizeof(p->res.why), "pair %s slides: none of its nodes in contact sticks and its slip keeps growing", p->terms[sliding]->name));
  PetscCall(PetscInfo(tao, "the slip of pair %s has grown without contracting for %d iterations: stopped\n", p->terms[sliding]->name, SLIDE_GROWING));
  PetscCall(TaoSetConvergedReason(tao, TAO_DIVERGED_USER));
  w->stops++;
  PetscFunctionReturn(0);
}
