/* Force control by an outer iteration (-force_control_type outer; not for
   a scene with a body held by contact, whose anchors are always coupled):
   each controlled displacement U is found by an
   iteration around the usual solve of u, which keeps every inner problem
   displacement-controlled, so that a body whose only support in that
   direction is the contact stays supported by the imposed U. Minimising
   Pi(u; U) - F . U over u first leaves Pi*(U) = min_u Pi(u; U), whose
   derivative is the reaction R(U) (the envelope theorem), so the iteration
   solves R(U) = F.

   It is Broyden's method on r(U) = R(U) - F: a first solve
   at U = 0, then a probe of each component by delta = rho sign(F - R) (rho =
   1e-2 of the body's size) that gives the initial Jacobian's columns, then
   quasi-Newton steps U <- U - J^-1 r with Broyden's update. A step is capped
   at 4 times the last (the reaction of a contact that has just closed is
   flat, so a first secant can overshoot), and where the secant says the
   reaction does not grow with U (a body not yet in contact) the step goes on
   in the force's direction, doubled. Each trial is solved from the last
   converged state (one stage: the load and penalty stages, if any, are for
   the first solve from rest). It stops when |R - F| <= -force_control_rtol
   (1e-9) times |F| in every component, or after -force_control_max_it solves.
   Each solve costs Newton's iterations anew: 16 against the displacement
   run's 5 on a soft disc pressed on a stiff slab; forcecontrol.c's coupled
   type solves once. */
#include "forceouter.h"
#include "staging.h"
#include "schedule.h"
#include "problem.h"
#include <petscblaslapack.h>

/* Sets the controls' displacements U and solves, from X0 (or rest, with the
   scene's stages, when X0 is NULL); R: the controlled groups' reactions. */
static PetscErrorCode ProblemSolveAtControls(Problem p, const PetscReal U[], Vec X0, PetscReal R[], PetscInt *its, TaoConvergedReason *reason)
{
  ProblemSchedule saved = p->sched;
  PetscInt        n;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < p->fc.n; ++k) {
    ForceControl *fc = &p->fc.c[k];
    fc->U            = U[k];
    PetscCall(BodySetBCValue(p->bodies[fc->body], fc->bc, fc->c, U[k]));
  }
  PetscCall(VecDestroy(&p->X0));
  if (X0) { /* from the last converged state: one stage */
    PetscCall(ProblemSetInitialGuess(p, X0));
    PetscCall(ProblemScheduleOneStage(p, &saved));
  }
  PetscCall(ProblemSolveStaged(p, &n, reason));
  PetscCall(ProblemScheduleRestore(p, &saved));
  p->res.controlSolves++;
  *its += n;
  if (*reason <= 0) PetscFunctionReturn(0);
  PetscCall(ProblemComputeReactions(p, p->X));
  for (PetscInt k = 0; k < p->fc.n; ++k) {
    ForceControl *fc = &p->fc.c[k];
    const BodyBC *bc = BodyGetCondition(p->bodies[fc->body], fc->bc);
    fc->R            = bc->reaction[bc->comps[fc->c]];
    R[k]             = fc->R;
  }
  PetscFunctionReturn(0);
}

/* Whether every reaction is its force to the tolerance. */
static PetscBool ControlConverged(Problem p, const PetscReal R[])
{
  for (PetscInt k = 0; k < p->fc.n; ++k)
    if (PetscAbsReal(R[k] - p->fc.c[k].force) > p->cfg->control.rtol * p->fc.c[k].scale) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* s = -J^-1 r (m small; LAPACK's LU on a copy); *ok false where J is singular. */
static PetscErrorCode ControlNewtonStep(PetscInt m, const PetscReal J[], const PetscReal r[], PetscReal s[], PetscBool *ok)
{
  PetscScalar  A[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS], b[CONTACT_MAX_CONTROLS];
  PetscBLASInt n, one = 1, ipiv[CONTACT_MAX_CONTROLS], info;

  PetscFunctionBeginUser;
  PetscCall(PetscBLASIntCast(m, &n));
  for (PetscInt i = 0; i < m * m; ++i) A[i] = J[i]; /* column-major */
  for (PetscInt i = 0; i < m; ++i) b[i] = -r[i];
  PetscCallBLAS("LAPACKgesv", LAPACKgesv_(&n, &one, A, &n, ipiv, b, &n, &info));
  *ok = (PetscBool)(info == 0);
  for (PetscInt i = 0; i < m; ++i) s[i] = PetscRealPart(b[i]);
  for (PetscInt i = 0; i < m && *ok; ++i)
    if (PetscIsInfOrNanReal(s[i])) *ok = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* The step from U: Broyden's, capped at 4 times the last step (cap); where
   J says the reaction does not grow towards the force (a flat or falling
   reaction: no contact yet), the last step doubled, towards the force. */
static PetscErrorCode ControlStep(Problem p, const PetscReal J[], const PetscReal r[], PetscReal cap, PetscReal s[])
{
  const PetscInt m = p->fc.n;
  PetscBool      ok;
  PetscReal      big = 0;

  PetscFunctionBeginUser;
  PetscCall(ControlNewtonStep(m, J, r, s, &ok));
  for (PetscInt k = 0; k < m && ok; ++k)
    if (J[k * m + k] <= 0) ok = PETSC_FALSE;
  if (!ok) {
    for (PetscInt k = 0; k < m; ++k) s[k] = r[k] < 0 ? cap / 2 : r[k] > 0 ? -cap / 2 : 0.0; /* cap is 4 times the last step */
    PetscFunctionReturn(0);
  }
  for (PetscInt k = 0; k < m; ++k) big = PetscMax(big, PetscAbsReal(s[k]));
  if (big > cap)
    for (PetscInt k = 0; k < m; ++k) s[k] *= cap / big;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSolveControlledOuter(Problem p, PetscInt *its, TaoConvergedReason *reason)
{
  const PetscInt m = p->fc.n;
  PetscReal      U[CONTACT_MAX_CONTROLS] = {0}, R[CONTACT_MAX_CONTROLS], r[CONTACT_MAX_CONTROLS], s[CONTACT_MAX_CONTROLS];
  PetscReal      J[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS] = {0}, last = 0;
  Vec            Xs;

  PetscFunctionBeginUser;
  *its                   = 0;
  p->res.controlSolves   = 0;
  p->res.why[0]          = 0;
  PetscCall(ProblemSolveAtControls(p, U, NULL, R, its, reason)); /* from rest */
  if (*reason <= 0) PetscFunctionReturn(0);
  PetscCall(VecDuplicate(p->X, &Xs));
  PetscCall(VecCopy(p->X, Xs));
  for (PetscInt k = 0; k < m && !ControlConverged(p, R); ++k) { /* the initial Jacobian, column by column */
    PetscReal rho = 1e-2 * p->fc.c[k].L, R1[CONTACT_MAX_CONTROLS];
    if (R[k] > p->fc.c[k].force) rho = -rho;
    U[k] += rho;
    PetscCall(ProblemSolveAtControls(p, U, Xs, R1, its, reason));
    if (*reason <= 0) break;
    for (PetscInt i = 0; i < m; ++i) {
      J[k * m + i] = (R1[i] - R[i]) / rho;
      R[i]         = R1[i];
    }
    last = PetscMax(last, PetscAbsReal(rho));
    PetscCall(VecCopy(p->X, Xs));
  }
  while (*reason > 0 && !ControlConverged(p, R)) {
    PetscReal R1[CONTACT_MAX_CONTROLS], ss = 0, Js[CONTACT_MAX_CONTROLS];
    if (p->res.controlSolves >= p->cfg->control.maxIt) {
      *reason = TAO_DIVERGED_MAXITS;
      PetscCall(PetscSNPrintf(p->res.why, sizeof(p->res.why), "force control: the reactions are not the forces after -force_control_max_it %" PetscInt_FMT " solves (%s: reaction %g, force %g)", p->cfg->control.maxIt, BodyGetCondition(p->bodies[p->fc.c[0].body], p->fc.c[0].bc)->group, (double)R[0], (double)p->fc.c[0].force));
      break;
    }
    for (PetscInt k = 0; k < m; ++k) r[k] = R[k] - p->fc.c[k].force;
    PetscCall(ControlStep(p, J, r, 4 * last, s));
    for (PetscInt k = 0; k < m; ++k) U[k] += s[k];
    PetscCall(ProblemSolveAtControls(p, U, Xs, R1, its, reason));
    if (*reason <= 0) break;
    /* Broyden: J += (dR - J s) s^T / (s^T s) */
    for (PetscInt k = 0; k < m; ++k) ss += s[k] * s[k];
    for (PetscInt i = 0; i < m; ++i) {
      Js[i] = 0;
      for (PetscInt k = 0; k < m; ++k) Js[i] += J[k * m + i] * s[k];
    }
    for (PetscInt i = 0; i < m; ++i)
      for (PetscInt k = 0; k < m; ++k) J[k * m + i] += (R1[i] - R[i] - Js[i]) * s[k] / ss;
    last = 0;
    for (PetscInt k = 0; k < m; ++k) {
      R[k] = R1[k];
      last = PetscMax(last, PetscAbsReal(s[k]));
    }
    PetscCall(VecCopy(p->X, Xs));
    PetscCall(PetscInfo(p->tao, "force control: solve %" PetscInt_FMT ", U[0] = %g, reaction %g, force %g\n", p->res.controlSolves, (double)U[0], (double)R[0], (double)p->fc.c[0].force));
  }
  PetscCall(VecDestroy(&Xs));
  PetscFunctionReturn(0);
}
