/* Bodies held by contact: the outer iteration on the anchors (anchors.c)
   and, in the same scene, the force controls (forcecontrol.c's problem).

   A body held by contact gets at most three Dirichlet components at two of
   its vertices, the anchors, each with force zero: the solve finds their
   displacements U such that every anchor's reaction R(U) = d Pi*(U) / dU
   vanishes (Pi*(U) the energy minimised over u with the anchors at U), and
   the answer is then the free body's. Force-controlled components join the
   same iteration with R(U) = F. Unlike force control's Broyden iteration,
   this one allows for motions that the contact does not hold. A roller
   between two flat races slides along them without changing the energy:
   the reaction of those anchors is the discretisation's (an unsymmetric
   mesh's tangential force: 7e-7 of the load on the roller scene at
   h = 0.02, 1.9e-5 at h = 0.03) and hardly changes with U. A Broyden step
   divides that force by a stiffness of about zero and throws the roller
   away, and probes of 1e-2 of the body's size turn a disc so far that its
   linearised rotation inflates it, so that they measure the inflation and
   not the stiffness (measured: 40 solves, DIVERGED_MAXITS).

   The iteration here, from U = 0 (the first solve from rest, with the
   scene's stages; each later one from the last converged state, one stage):

   1. The test. Component k has converged when |R_k - F_k| <= rtol s_k, with
      rtol = -force_control_rtol. For a force control s_k is |F_k| plus its
      body's loads (force control's own scale). For an anchor, s_k scales
      with the forces that pass through its body: the largest force of the
      scene, over every load's resultant, every force control's force and
      every other Dirichlet group's reaction (a roller carries the load its
      races pass on; its own load is zero). Along the directions the
      contact does not hold (step 2) an anchor's residual is allowed
      HELD_NEUTRAL of that scale (50 times the roller's at h = 0.03).
   2. The Jacobian J = dR/dU, column by column, by probes of HELD_PROBE times
      the body's size from the current state, and the eigenvectors of its
      symmetric part, the directions. A direction whose stiffness is below
      HELD_STIFF times its bodies' E (times their size in r-z, where forces
      are over the whole circle) is not held by the contact: its body is not
      yet in contact in that direction, or the contact cannot hold that
      motion.
   3. The step. Along the held directions, Newton's s = -J^-1 r; along an
      unheld one, where a force control's residual is above its tolerance or
      an anchor's above HELD_PUSH of the scene's largest force (a body not
      yet in contact), half the step limit towards the forces; else no step
      (a roller's sliding, whose reaction falls as the held directions
      converge). The step is limited to c times each body's size, c = 1e-2
      at first and then 4 times the last step (the stiffness of a contact
      that has just closed grows with the load); a solve that fails is
      retried with half the step, up to HELD_HALVINGS times. Where the step
      was Newton's alone and divided the misfit (the largest residual over
      its tolerance) by 1 / HELD_KEEP, J gets Broyden's update instead of
      new probes.

   The reactions are only as exact as the solves: a point anchor's reaction
   moves by about the solve's gradient norm from one solve to the next, and
   a soft direction (a roller's rotation, 1e2 times softer than its
   squeeze) shows it most (measured 1e-4 on the roller pressed by 1000 with
   -tao_gttol 1e-8). So the tolerance is at least HELD_FLOOR times the last
   solve's gradient norm (on the roller at h = 0.03, residuals stalled at
   1.7 times it), and where a Newton step without a push fails to halve the
   misfit while every anchor's residual is within the allowance
   HELD_NEUTRAL and every force control's within HELD_STALL times its
   tolerance, the iteration ends there: the stiff directions, which carry
   the load, have converged by then (the roller's contacts balance to 3e-9
   of the load at h = 0.02, 3e-8 at 0.03). It stops unconverged after
   -force_control_max_it solves (probes included). */
#include "problem.h"
#include <petscblaslapack.h>

#define HELD_PROBE     1e-4 /* a probe: this times the body's size */
#define HELD_STIFF     1e-4 /* held: |dR/dU| at least this times E (E L in r-z) */
#define HELD_NEUTRAL   1e-3 /* an unheld anchor's reaction allowed, relative to the scene's largest force */
#define HELD_PUSH      1e-2 /* an unheld anchor is pushed towards contact above this times the scene's largest force */
#define HELD_FIRST     1e-2 /* the first step's limit, relative to the body's size */
#define HELD_HALVINGS  4
#define HELD_KEEP       0.25 /* J is kept while a step divides the misfit by 4 */
#define HELD_STALL      1e3  /* where Newton stalls, a force control's residual up to this times its tolerance ends the iteration */
#define HELD_STALL_RATE 0.5
#define HELD_FLOOR      10 /* a reaction is resolved to this times the solve's gradient norm */

typedef struct {
  PetscInt  m;
  PetscReal U[CONTACT_MAX_CONTROLS], R[CONTACT_MAX_CONTROLS];
  PetscReal L[CONTACT_MAX_CONTROLS];    /* the size of each component's body */
  PetscReal kref[CONTACT_MAX_CONTROLS]; /* the stiffness below which a component's motion is not held */
  PetscBool anchor[CONTACT_MAX_CONTROLS];
  PetscReal S;     /* the scene's largest force at the last solve */
  PetscReal floor; /* what the last solve resolves in a reaction: HELD_FLOOR times its gradient norm */
  PetscBool haveJ;                                          /* J and the directions below are known */
  PetscReal J[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS]; /* dR/dU (column-major) */
  PetscReal w[CONTACT_MAX_CONTROLS];                        /* the stiffness of each direction */
  PetscReal V[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS]; /* the directions (columns, orthonormal) */
  PetscBool held[CONTACT_MAX_CONTROLS];                     /* direction i is held by the contact */
  PetscBool stalled; /* a Newton step no longer halved the misfit, every residual acceptable */
} HeldState;

/* The diagonal of body b's reference bounding box (over every rank). */
static PetscErrorCode HeldBodySize(Body b, PetscReal *L)
{
  PetscReal m[4] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}; /* least x, y, -x, -y */

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < b->ncells * b->nb; ++k)
    for (PetscInt d = 0; d < 2; ++d) {
      m[d]     = PetscMin(m[d], b->xnode[2 * k + d]);
      m[2 + d] = PetscMin(m[2 + d], -b->xnode[2 * k + d]);
    }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, m, 4, MPIU_REAL, MPIU_MIN, b->comm));
  *L = PetscSqrtReal(PetscSqr(m[0] + m[2]) + PetscSqr(m[1] + m[3]));
  if (!(*L > 0)) *L = 1.0;
  PetscFunctionReturn(0);
}

/* The largest force of the scene: every load's resultant, every force
   control's force, every Dirichlet group's reaction but the anchors'. */
static PetscReal HeldSceneForce(Problem p)
{
  PetscReal S = 0;

  for (PetscInt i = 0; i < p->nbodies; ++i) {
    const Body b = p->bodies[i];
    for (PetscInt l = 0; l < b->nload; ++l) S = PetscMax(S, PetscSqrtReal(PetscSqr(b->load[l].force[0]) + PetscSqr(b->load[l].force[1])));
    for (PetscInt j = 0; j < b->nbc; ++j) {
      if (b->bc[j].anchor) continue;
      S = PetscMax(S, PetscSqrtReal(PetscSqr(b->bc[j].reaction[0]) + PetscSqr(b->bc[j].reaction[1])));
      for (PetscInt c = 0; c < b->bc[j].ncomp; ++c)
        if (b->bc[j].control[c]) S = PetscMax(S, PetscAbsReal(b->bc[j].force[c]));
    }
  }
  return S;
}

/* Sets the displacements U and solves, from X0 (one stage) or from rest
   (X0 NULL, the scene's stages); then the reactions R and the scene's force. */
static PetscErrorCode HeldSolve(Problem p, HeldState *st, const PetscReal U[], Vec X0, PetscReal R[], PetscInt *its, TaoConvergedReason *reason)
{
  PetscFunctionBeginUser;
  PetscCall(ProblemSolveAtControls(p, U, X0, R, its, reason));
  if (*reason <= 0) PetscFunctionReturn(0);
  st->S = HeldSceneForce(p);
  PetscCall(TaoGetSolutionStatus(p->tao, NULL, NULL, &st->floor, NULL, NULL, NULL));
  st->floor *= HELD_FLOOR;
  PetscFunctionReturn(0);
}

/* The tolerance of component k (step 1). */
static PetscReal HeldTolerance(Problem p, const HeldState *st, PetscInt k)
{
  const ForceControl *fc = &p->controls[k];

  return PetscMax(p->opt.controlRtol * (st->anchor[k] ? PetscMax(st->S, fc->scale) : fc->scale), st->floor);
}

/* The residual r = R - F split into its parts along the held directions
   (rh) and the others (rn = r - rh). */
static void HeldSplit(Problem p, const HeldState *st, PetscReal r[], PetscReal rh[], PetscReal rn[])
{
  const PetscInt m = st->m;

  for (PetscInt k = 0; k < m; ++k) {
    r[k]  = st->R[k] - p->controls[k].force;
    rh[k] = 0;
  }
  for (PetscInt i = 0; i < m && st->haveJ; ++i) {
    PetscReal d = 0;
    if (!st->held[i]) continue;
    for (PetscInt k = 0; k < m; ++k) d += st->V[i * m + k] * r[k];
    for (PetscInt k = 0; k < m; ++k) rh[k] += d * st->V[i * m + k];
  }
  for (PetscInt k = 0; k < m; ++k) rn[k] = st->haveJ ? r[k] - rh[k] : 0.0;
  if (!st->haveJ)
    for (PetscInt k = 0; k < m; ++k) rh[k] = r[k];
}

/* What a component's residual may be in directions the contact does not
   hold: an anchor's the neutral allowance, a force control's its tolerance. */
static PetscReal HeldAllowance(Problem p, const HeldState *st, PetscInt k)
{
  return st->anchor[k] ? PetscMax(HELD_NEUTRAL * st->S, HeldTolerance(p, st, k)) : HeldTolerance(p, st, k);
}

/* Step 1: every component within its tolerance along the held directions
   and within its allowance along the others. */
static PetscBool HeldConverged(Problem p, const HeldState *st)
{
  PetscReal r[CONTACT_MAX_CONTROLS], rh[CONTACT_MAX_CONTROLS], rn[CONTACT_MAX_CONTROLS];

  HeldSplit(p, st, r, rh, rn);
  for (PetscInt k = 0; k < st->m; ++k)
    if (PetscAbsReal(rh[k]) > HeldTolerance(p, st, k) || PetscAbsReal(rn[k]) > HeldAllowance(p, st, k)) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* Where Newton stalls: whether every anchor's residual is within the
   allowance of the directions the contact does not hold, and every force
   control's within HELD_STALL times its tolerance. */
static PetscBool HeldAcceptable(Problem p, const HeldState *st)
{
  for (PetscInt k = 0; k < st->m; ++k) {
    const PetscReal r = PetscAbsReal(st->R[k] - p->controls[k].force);
    if (r > (st->anchor[k] ? PetscMax(HELD_NEUTRAL * st->S, HeldTolerance(p, st, k)) : HELD_STALL * HeldTolerance(p, st, k))) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

/* How far from converged: the largest of each component's residual over its
   tolerance (held directions) or its allowance (the others); 1 converged. */
static PetscReal HeldMisfit(Problem p, const HeldState *st)
{
  PetscReal r[CONTACT_MAX_CONTROLS], rh[CONTACT_MAX_CONTROLS], rn[CONTACT_MAX_CONTROLS], e = 0;

  HeldSplit(p, st, r, rh, rn);
  for (PetscInt k = 0; k < st->m; ++k) e = PetscMax(e, PetscMax(PetscAbsReal(rh[k]) / HeldTolerance(p, st, k), PetscAbsReal(rn[k]) / HeldAllowance(p, st, k)));
  return e;
}

/* Step 2: J by probes from Xs; its symmetric part's eigenvectors are the
   directions, held where the stiffness is at least the components' kref
   (weighted by the direction). */
static PetscErrorCode HeldDirections(Problem p, HeldState *st)
{
  const PetscInt m = st->m;
  PetscScalar    A[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS], work[16 * CONTACT_MAX_CONTROLS];
  PetscBLASInt   n, lwork = 16 * CONTACT_MAX_CONTROLS, info = 0;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < m; ++k)
    for (PetscInt i = 0; i < m; ++i) A[k * m + i] = 0.5 * (st->J[k * m + i] + st->J[i * m + k]);
  PetscCall(PetscBLASIntCast(m, &n));
  PetscCallBLAS("LAPACKsyev", LAPACKsyev_("V", "U", &n, A, &n, st->w, work, &lwork, &info));
  PetscCheck(info == 0, p->comm, PETSC_ERR_LIB, "held by contact: LAPACK syev failed with info %d", (int)info);
  for (PetscInt i = 0; i < m; ++i) {
    PetscReal kref = 0;
    for (PetscInt k = 0; k < m; ++k) {
      st->V[i * m + k] = PetscRealPart(A[i * m + k]);
      kref += PetscSqr(st->V[i * m + k]) * st->kref[k];
    }
    st->held[i] = (PetscBool)(st->w[i] >= kref);
    PetscCall(PetscInfo(p->tao, "held by contact: direction %" PetscInt_FMT ": stiffness %g (held from %g): %s\n", i, (double)st->w[i], (double)kref, st->held[i] ? "held" : "not held"));
  }
  st->haveJ = PETSC_TRUE;
  PetscFunctionReturn(0);
}

static PetscErrorCode HeldJacobian(Problem p, HeldState *st, Vec Xs, PetscInt *its, TaoConvergedReason *reason)
{
  const PetscInt m = st->m;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < m; ++k) {
    PetscReal U1[CONTACT_MAX_CONTROLS], R1[CONTACT_MAX_CONTROLS], rho = HELD_PROBE * st->L[k];
    if (st->R[k] > p->controls[k].force) rho = -rho; /* towards the force */
    PetscCall(PetscArraycpy(U1, st->U, m));
    U1[k] += rho;
    PetscCall(HeldSolve(p, st, U1, Xs, R1, its, reason));
    if (*reason <= 0) PetscFunctionReturn(0);
    for (PetscInt i = 0; i < m; ++i) st->J[k * m + i] = (R1[i] - st->R[i]) / rho;
  }
  PetscCall(HeldDirections(p, st));
  PetscFunctionReturn(0);
}

/* Broyden's update of J after the step s changed R by dR, and the directions again. */
static PetscErrorCode HeldBroyden(Problem p, HeldState *st, const PetscReal s[], const PetscReal dR[])
{
  const PetscInt m = st->m;
  PetscReal      ss = 0, Js[CONTACT_MAX_CONTROLS];

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < m; ++k) ss += s[k] * s[k];
  if (!(ss > 0)) PetscFunctionReturn(0);
  for (PetscInt i = 0; i < m; ++i) {
    Js[i] = 0;
    for (PetscInt k = 0; k < m; ++k) Js[i] += st->J[k * m + i] * s[k];
  }
  for (PetscInt i = 0; i < m; ++i)
    for (PetscInt k = 0; k < m; ++k) st->J[k * m + i] += (dR[i] - Js[i]) * s[k] / ss;
  PetscCall(HeldDirections(p, st));
  PetscFunctionReturn(0);
}

/* Step 3: Newton's step along the held directions; along another, where a
   component's residual is above its allowance (a body not yet in contact),
   half the step limit towards the forces; limited to c times each body's size. */
static void HeldStep(Problem p, const HeldState *st, PetscReal c, PetscReal s[], PetscBool *pushed)
{
  const PetscInt m = st->m;
  PetscReal      r[CONTACT_MAX_CONTROLS], rh[CONTACT_MAX_CONTROLS], rn[CONTACT_MAX_CONTROLS], big = 0;

  HeldSplit(p, st, r, rh, rn);
  *pushed = PETSC_FALSE;
  for (PetscInt k = 0; k < m; ++k) s[k] = 0;
  for (PetscInt i = 0; i < m; ++i) {
    PetscReal d = 0, len = 0;
    PetscBool far = PETSC_FALSE;
    for (PetscInt k = 0; k < m; ++k) d += st->V[i * m + k] * r[k];
    if (st->held[i]) {
      for (PetscInt k = 0; k < m; ++k) s[k] -= d / st->w[i] * st->V[i * m + k];
      continue;
    }
    for (PetscInt k = 0; k < m; ++k) {
      far = (PetscBool)(far || PetscAbsReal(d * st->V[i * m + k]) > (st->anchor[k] ? PetscMax(HELD_PUSH * st->S, HeldAllowance(p, st, k)) : HeldAllowance(p, st, k)));
      len += PetscAbsReal(st->V[i * m + k]) * st->L[k];
    }
    if (!far) continue;
    *pushed = PETSC_TRUE;
    for (PetscInt k = 0; k < m; ++k) s[k] += (d > 0 ? -0.5 : 0.5) * c * len * st->V[i * m + k];
  }
  for (PetscInt k = 0; k < m; ++k) big = PetscMax(big, PetscAbsReal(s[k]) / st->L[k]);
  if (big > c)
    for (PetscInt k = 0; k < m; ++k) s[k] *= c / big;
}

/* The state st at Xs (its reactions), after probes moved away from it. */
static PetscErrorCode HeldRestore(Problem p, HeldState *st, Vec Xs)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < st->m; ++k) {
    ForceControl *fc = &p->controls[k];
    fc->U            = st->U[k];
    fc->R            = st->R[k];
    PetscCall(BodySetBCValue(p->bodies[fc->body], fc->bc, fc->c, st->U[k]));
  }
  PetscCall(VecCopy(Xs, p->X));
  PetscCall(ProblemComputeReactions(p, p->X));
  st->S = HeldSceneForce(p);
  PetscFunctionReturn(0);
}

PetscBool ProblemHasAnchors(Problem p)
{
  for (PetscInt k = 0; k < p->ncontrols; ++k)
    if (p->bodies[p->controls[k].body]->bc[p->controls[k].bc].anchor) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* Every later solve stops where the first (from rest, U = 0) did: at
   -tao_gttol times the gradient norm at rest with U = 0, given as an absolute
   tolerance. Left to itself, a solve from X0 measures "rest" with the anchors
   and controls at their trial U, whose energy at u = 0 (a vertex moved alone)
   is far from the problem's: measured on the roller with a pressure, its
   solves stopped at a gradient norm of 7.6e-5 and the contacts 1.9e-8 of
   the load from balance. The scene's largest force S at that solve caps it
   (a displacement pushed into a penalty contact from rest gives a gradient
   far above the forces it makes: measured, the roller pushed by 0.0444
   balanced to 1.1e-7 of its load, with the cap 1e-8); where nothing is
   loaded at U = 0 (every load a force control), the largest force stands
   for it. */
static PetscErrorCode HeldFixTolerance(Problem p, PetscReal S, PetscReal tol[3])
{
  PetscReal f, g0;
  Vec       X;

  PetscFunctionBeginUser;
  PetscCall(TaoGetTolerances(p->tao, &tol[0], &tol[1], &tol[2]));
  PetscCall(VecDuplicate(p->X, &X));
  PetscCall(ProblemComputeObjectiveGradient(p->tao, X, &f, p->G, p)); /* the last stage's load and penalty: the whole problem */
  p->res.nEnergyEvals--;
  PetscCall(VecNorm(p->G, NORM_2, &g0));
  PetscCall(VecDestroy(&X));
  if (S > 0) g0 = g0 > 0 ? PetscMin(g0, S) : S;
  for (PetscInt k = 0; k < p->ncontrols && !(g0 > 0); ++k) g0 = PetscMax(g0, PetscAbsReal(p->controls[k].force)); /* nothing loaded at U = 0 (every load a force control): the largest force */
  if (g0 > 0) PetscCall(TaoSetTolerances(p->tao, PetscMax(tol[0], tol[2] * g0), tol[1], 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSolveHeld(Problem p, PetscInt *its, TaoConvergedReason *reason)
{
  HeldState st;
  PetscReal c = HELD_FIRST, tol[3];
  PetscBool keep = PETSC_FALSE, pushed;
  Vec       Xs;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&st, sizeof(st)));
  st.m                 = p->ncontrols;
  *its                 = 0;
  p->res.controlSolves = 0;
  p->res.why[0]        = 0;
  for (PetscInt k = 0; k < st.m; ++k) {
    const Body b = p->bodies[p->controls[k].body];
    PetscCall(HeldBodySize(b, &st.L[k]));
    st.anchor[k] = b->bc[p->controls[k].bc].anchor;
    st.kref[k]   = HELD_STIFF * b->E * (b->axisym ? st.L[k] : 1.0);
  }
  PetscCall(HeldSolve(p, &st, st.U, NULL, st.R, its, reason)); /* from rest */
  if (*reason <= 0) PetscFunctionReturn(0);
  PetscCall(HeldFixTolerance(p, st.S, tol));
  PetscCall(VecDuplicate(p->X, &Xs));
  PetscCall(VecCopy(p->X, Xs));
  while (!st.stalled && !HeldConverged(p, &st)) {
    PetscReal s[CONTACT_MAX_CONTROLS], U1[CONTACT_MAX_CONTROLS], R1[CONTACT_MAX_CONTROLS], dR[CONTACT_MAX_CONTROLS], big = 0, e0;
    if (p->res.controlSolves + (keep ? 1 : st.m + 1) > p->opt.controlMaxIt) {
      *reason = TAO_DIVERGED_MAXITS;
      PetscCall(PetscSNPrintf(p->res.why, sizeof(p->res.why), "held by contact: the reactions are not the forces after -force_control_max_it %" PetscInt_FMT " solves (%s: reaction %g, force %g)", p->opt.controlMaxIt, p->bodies[p->controls[0].body]->bc[p->controls[0].bc].group, (double)st.R[0], (double)p->controls[0].force));
      break;
    }
    if (!keep) {
      PetscCall(HeldJacobian(p, &st, Xs, its, reason));
      if (*reason <= 0) break;
      PetscCall(HeldRestore(p, &st, Xs));
      if (HeldConverged(p, &st)) break; /* within the allowance where the contact does not hold */
    }
    e0 = HeldMisfit(p, &st);
    HeldStep(p, &st, c, s, &pushed);
    for (PetscInt h = 0; h <= HELD_HALVINGS; ++h) {
      for (PetscInt k = 0; k < st.m; ++k) U1[k] = st.U[k] + s[k];
      PetscCall(HeldSolve(p, &st, U1, Xs, R1, its, reason));
      if (*reason > 0 || h == HELD_HALVINGS) break;
      PetscCall(PetscInfo(p->tao, "held by contact: a step's solve stopped (%s): half the step\n", TaoConvergedReasons[*reason]));
      for (PetscInt k = 0; k < st.m; ++k) s[k] *= 0.5;
    }
    if (*reason <= 0) break;
    for (PetscInt k = 0; k < st.m; ++k) dR[k] = R1[k] - st.R[k];
    for (PetscInt k = 0; k < st.m; ++k) {
      const BodyBC *bc = &p->bodies[p->controls[k].body]->bc[p->controls[k].bc];
      st.U[k]          = U1[k];
      st.R[k]          = R1[k];
      big              = PetscMax(big, PetscAbsReal(s[k]) / st.L[k]);
      PetscCall(PetscInfo(p->tao, "held by contact: solve %" PetscInt_FMT ", %s %s: U = %g, reaction %g, force %g\n", p->res.controlSolves, bc->group, bc->comps[p->controls[k].c] ? "y" : "x", (double)st.U[k], (double)st.R[k], (double)p->controls[k].force));
    }
    c    = PetscMax(4 * big, HELD_PROBE);
    {
      const PetscReal e1 = HeldMisfit(p, &st);
      PetscCall(PetscInfo(p->tao, "held by contact: misfit %g, was %g%s\n", (double)e1, (double)e0, pushed ? ", pushed" : ""));
      keep = (PetscBool)(!pushed && e1 <= HELD_KEEP * e0); /* Newton's step, and J still good: Broyden's update, no probes next time */
      if (keep) PetscCall(HeldBroyden(p, &st, s, dR));
      if (!pushed && e1 > HELD_STALL_RATE * e0 && HeldAcceptable(p, &st)) { /* Newton no longer gains: the reactions' resolution */
        PetscCall(PetscInfo(p->tao, "held by contact: converged to the solves' resolution (misfit %g, was %g)\n", (double)e1, (double)e0));
        st.stalled = PETSC_TRUE;
      }
    }
    PetscCall(VecCopy(p->X, Xs));
  }
  PetscCall(VecDestroy(&Xs));
  PetscCall(TaoSetTolerances(p->tao, tol[0], tol[1], tol[2]));
  PetscFunctionReturn(0);
}
