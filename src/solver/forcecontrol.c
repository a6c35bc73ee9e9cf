/* Force control: -<body>_bc_<group>_control force turns a component of a
   Dirichlet condition into a force F. The group moves rigidly in that
   component by an unknown U, and the energy gains -F U:

     minimise over (u, U)   Pi(u; U) - F . U,

   Pi(u; U) the energy with the controlled groups displaced by U. Its
   derivative in U_k is the reaction of group k, R_k = dPi/dU_k (the sum of
   dPi/du over the group's dofs in that component, what BodyComputeReactions
   computes), so at the minimum R = F: the group's reaction is the force.

   Two types, by name (-force_control_type, ForceControlList):
   - coupled (the default): the U are unknowns of the one minimisation, the
     last m entries of rank 0's part of X; the gradient in U_k is R_k - F_k,
     the energy has -F . U, and the Hessian is bordered by
       K_fU = K_fc 1 (column k: the force on the free dofs when group k moves
       by 1, ctrlB[k]) and K_UU = 1^T K_cc 1 (ctrlD),
     which the Newton step eliminates (forceborder.c) with the solve it
     already has. One solve, as a displacement run's; measured in
     results/force_control.json. Assumption: the border is the elastic
     stiffness's alone, so a controlled group on a contact surface (whose
     nodes the contact would couple to U) gets a Newton step without that
     coupling: still a descent direction, no longer Newton's.
     With load stepping (load factor lambda) the group moves by U, and the
     force is lambda F: the group's Dirichlet value is set to U / lambda,
     which the body scales by lambda.
     It ends where the solve's gradient test ends it (its last stage
     relative to the gradient at rest of the displacement run of the U
     found, problem.c); where -force_control_rtol is given and a reaction is
     then further from its force than it, the solve goes on from there with
     the gradient tolerance -force_control_rtol times the least |F| (one
     more solve, counted in force_control_solves).
   - outer: an outer iteration on U around displacement-controlled solves
     (forceouter.c). A scene with a body held by contact (anchors.c) is
     always coupled: its anchors are controls of force zero, and the motions
     the contact does not hold are frozen where the anchors' residual is
     small (unheld.c). */
#include "problem.h"

PetscFunctionList ForceControlList = NULL;

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

/* The size of body b: its reference bounding box's diagonal. */
static PetscErrorCode ControlBodySize(Problem p, PetscInt body, PetscReal *L)
{
  Body      b = p->bodies[body];
  PetscReal lo[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[2] = {PETSC_MIN_REAL, PETSC_MIN_REAL};

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < b->ncells * b->nb; ++k) /* every node of this rank's cells */
    for (PetscInt d = 0; d < 2; ++d) {
      lo[d] = PetscMin(lo[d], b->xnode[2 * k + d]);
      hi[d] = PetscMax(hi[d], b->xnode[2 * k + d]);
    }
  lo[0] = -lo[0];
  lo[1] = -lo[1];
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, lo, 2, MPIU_REAL, MPIU_MAX, p->comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, hi, 2, MPIU_REAL, MPIU_MAX, p->comm));
  *L = PetscSqrtReal(PetscSqr(hi[0] + lo[0]) + PetscSqr(hi[1] + lo[1]));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemCollectControls(Problem p)
{
  PetscBool anchor[CONTACT_MAX_CONTROLS];
  PetscInt  body[CONTACT_MAX_CONTROLS];
  PetscReal kref[CONTACT_MAX_CONTROLS];

  PetscFunctionBeginUser;
  p->ncontrols = 0;
  for (PetscInt i = 0; i < p->nbodies; ++i)
    for (PetscInt j = 0; j < p->bodies[i]->nbc; ++j)
      for (PetscInt c = 0; c < p->bodies[i]->bc[j].ncomp; ++c) {
        const Body    b = p->bodies[i];
        ForceControl *fc;
        if (!b->bc[j].control[c]) continue;
        PetscCheck(p->ncontrols < CONTACT_MAX_CONTROLS, p->comm, PETSC_ERR_USER_INPUT, "more than %d force-controlled components", CONTACT_MAX_CONTROLS);
        fc         = &p->controls[p->ncontrols++];
        fc->body   = i;
        fc->bc     = j;
        fc->c      = c;
        fc->force  = b->bc[j].force[c];
        fc->U      = 0.0;
        fc->anchor = b->bc[j].anchor;
        fc->scale  = PetscAbsReal(fc->force);
        for (PetscInt l = 0; l < b->nload; ++l) fc->scale += PetscSqrtReal(PetscSqr(b->load[l].force[0]) + PetscSqr(b->load[l].force[1]));
        if (!(fc->scale > 0)) fc->scale = 1.0;
        PetscCall(ControlBodySize(p, i, &fc->L));
        fc->kref = b->E * (b->axisym ? fc->L : 1.0); /* a stiffness (force per length per unit thickness; r-z: over the whole circle) */
      }
  for (PetscInt k = 0; k < p->ncontrols; ++k) {
    anchor[k] = p->controls[k].anchor;
    body[k]   = p->controls[k].body;
    kref[k]   = p->controls[k].kref;
  }
  PetscCall(UnheldSetUp(&p->unheld, p->ncontrols, anchor, body, kref));
  PetscCall(PetscStrcmp(p->opt.controlType, "coupled", &p->coupled));
  if (p->ncontrols && !p->coupled && UnheldAny(&p->unheld)) PetscCall(PetscInfo(NULL, "force control: a body held by contact: coupled, whatever -force_control_type\n"));
  p->coupled = (PetscBool)(p->ncontrols > 0 && (p->coupled || UnheldAny(&p->unheld)));
  PetscFunctionReturn(0);
}

/* The largest force of the scene at the evaluation whose local gradients
   the bodies hold: every load's resultant, every force control's force,
   every Dirichlet group's reaction (anchors' included). */
PetscErrorCode ProblemControlSceneForce(Problem p, PetscReal *S)
{
  PetscFunctionBeginUser;
  *S = 0;
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    const Body b = p->bodies[i];
    PetscCall(BodyComputeReactions(b, b->Gl));
    for (PetscInt l = 0; l < b->nload; ++l) *S = PetscMax(*S, PetscSqrtReal(PetscSqr(b->load[l].force[0]) + PetscSqr(b->load[l].force[1])));
    for (PetscInt j = 0; j < b->nbc; ++j) {
      *S = PetscMax(*S, PetscSqrtReal(PetscSqr(b->bc[j].reaction[0]) + PetscSqr(b->bc[j].reaction[1])));
      for (PetscInt c = 0; c < b->bc[j].ncomp; ++c)
        if (b->bc[j].control[c]) *S = PetscMax(*S, PetscAbsReal(b->loadFactor * b->bc[j].force[c]));
    }
  }
  PetscFunctionReturn(0);
}

/* Column k of the border and the controls' own stiffness: the gradient of
   the elastic energy at the local vector e_k (1 on group k's nodes in its
   component, 0 elsewhere) minus the gradient at 0, K e_k (the energy is
   quadratic), summed to the free dofs (B_k) and over each control's group
   (D_lk, as a reaction). */
static PetscErrorCode ProblemControlColumn(Problem p, PetscInt k)
{
  const ForceControl *fc = &p->controls[k];
  Body                b  = p->bodies[fc->body];
  const PetscReal     v0 = b->bc[fc->bc].values[fc->c];
  Vec                 e, z, g0;
  PetscScalar        *a;
  PetscReal           en;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(b->Xl, &e));
  PetscCall(VecDuplicate(b->Xl, &z));
  PetscCall(VecDuplicate(b->Xl, &g0));
  PetscCall(BodySetBCValue(b, fc->bc, fc->c, 1.0));
  PetscCall(VecCopy(b->bclFull, e));
  PetscCall(BodySetBCValue(b, fc->bc, fc->c, 0.0));
  PetscCall(VecAXPY(e, -1.0, b->bclFull));
  PetscCall(BodySetBCValue(b, fc->bc, fc->c, v0));
  PetscCall(VecZeroEntries(z));
  PetscCall(VecZeroEntries(g0));
  PetscCall(BodyComputeEnergyGradient(b, z, &en, g0));
  PetscCall(VecZeroEntries(b->Gl));
  PetscCall(BodyComputeEnergyGradient(b, e, &en, b->Gl));
  PetscCall(VecAXPY(b->Gl, -1.0, g0));
  PetscCall(BodyComputeReactions(b, b->Gl));
  for (PetscInt l = 0; l < p->ncontrols; ++l) {
    const ForceControl *fl = &p->controls[l];
    const BodyBC       *bc = &p->bodies[fl->body]->bc[fl->bc];
    p->ctrlD[l * p->ncontrols + k] = fl->body == fc->body ? bc->reaction[bc->comps[fl->c]] : 0.0;
  }
  PetscCall(VecDuplicate(p->Xb, &p->ctrlB[k]));
  PetscCall(VecZeroEntries(p->ctrlB[k]));
  PetscCall(VecGetArray(p->ctrlB[k], &a));
  PetscCall(VecPlaceArray(b->Gg, a + p->offset[fc->body]));
  PetscCall(DMLocalToGlobalBegin(b->dm, b->Gl, ADD_VALUES, b->Gg));
  PetscCall(DMLocalToGlobalEnd(b->dm, b->Gl, ADD_VALUES, b->Gg));
  PetscCall(VecResetArray(b->Gg));
  PetscCall(VecRestoreArray(p->ctrlB[k], &a));
  PetscCall(VecDestroy(&e));
  PetscCall(VecDestroy(&z));
  PetscCall(VecDestroy(&g0));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetUpControlBorder(Problem p)
{
  const PetscInt m = p->ncontrols;

  PetscFunctionBeginUser;
  if (!p->coupled) PetscFunctionReturn(0);
  for (PetscInt k = 0; k < m; ++k) PetscCall(ProblemControlColumn(p, k));
  for (PetscInt k = 0; k < m; ++k) {
    PetscCheck(p->ctrlD[k * m + k] > 0, p->comm, PETSC_ERR_USER_INPUT, "body %s: force-controlled group %s has no stiffness of its own (no cell touches it on any rank)", p->bodies[p->controls[k].body]->name, p->bodies[p->controls[k].body]->bc[p->controls[k].bc].group);
    for (PetscInt l = 0; l < k; ++l) p->ctrlD[k * m + l] = p->ctrlD[l * m + k] = 0.5 * (p->ctrlD[k * m + l] + p->ctrlD[l * m + k]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetControlDisplacements(Problem p, Vec X)
{
  PetscReal          U[CONTACT_MAX_CONTROLS];
  PetscInt           n, nb;
  PetscMPIInt        rank, m;
  const PetscScalar *x;

  PetscFunctionBeginUser;
  if (!p->coupled) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  PetscCall(VecGetLocalSize(X, &n));
  PetscCall(VecGetLocalSize(p->Xb, &nb));
  if (!rank) {
    PetscCheck(n == nb + p->ncontrols, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "force control: a vector without the controlled displacements");
    PetscCall(VecGetArrayRead(X, &x));
    for (PetscInt k = 0; k < p->ncontrols; ++k) U[k] = PetscRealPart(x[nb + k]);
    PetscCall(VecRestoreArrayRead(X, &x));
  }
  PetscCall(PetscMPIIntCast(p->ncontrols, &m));
  PetscCallMPI(MPI_Bcast(U, m, MPIU_REAL, 0, p->comm));
  for (PetscInt k = 0; k < p->ncontrols; ++k) {
    ForceControl   *fc = &p->controls[k];
    Body            b  = p->bodies[fc->body];
    const PetscReal v  = b->loadFactor > 0 ? U[k] / b->loadFactor : 0.0;
    fc->U              = U[k];
    if (b->bc[fc->bc].values[fc->c] != v) PetscCall(BodySetBCValue(b, fc->bc, fc->c, v));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemAddControlWork(Problem p, PetscReal *f, Vec G)
{
  PetscBool   done[CONTACT_MAX_BODIES] = {PETSC_FALSE};
  PetscMPIInt rank;
  PetscInt    nb;
  PetscReal   gU[CONTACT_MAX_CONTROLS], S = 0;

  PetscFunctionBeginUser;
  if (!p->coupled) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  PetscCall(VecGetLocalSize(p->Xb, &nb));
  if (UnheldAny(&p->unheld)) PetscCall(ProblemControlSceneForce(p, &S)); /* every body's reactions */
  for (PetscInt k = 0; k < p->ncontrols; ++k) {
    ForceControl *fc = &p->controls[k];
    Body          b  = p->bodies[fc->body];
    const BodyBC *bc = &b->bc[fc->bc];
    if (!done[fc->body] && !UnheldAny(&p->unheld)) PetscCall(BodyComputeReactions(b, b->Gl)); /* Gl: the evaluation's, before its sum over ranks */
    done[fc->body] = PETSC_TRUE;
    fc->R          = bc->reaction[bc->comps[fc->c]];
    gU[k]          = fc->R - b->loadFactor * fc->force;
    *f -= b->loadFactor * fc->force * fc->U;
  }
  PetscCall(PetscInfo(NULL, "force control: U_0 = %.10g, reaction %.10g, energy %.10g\n", (double)p->controls[0].U, (double)p->controls[0].R, (double)*f));
  if (UnheldAny(&p->unheld)) PetscCall(UnheldSetGradient(&p->unheld, S, gU)); /* the directions the contact does not hold, projected out */
  if (!rank) {
    PetscScalar *g;
    PetscCall(VecGetArray(G, &g));
    for (PetscInt k = 0; k < p->ncontrols; ++k) g[nb + k] = gU[k];
    PetscCall(VecRestoreArray(G, &g));
  }
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
  if (!p->coupled || p->opt.penaltyStagesSet || p->opt.penaltyStartSet) PetscFunctionReturn(0);
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
  for (PetscInt k = 0; k < p->ncontrols; ++k)
    if (PetscAbsReal(p->controls[k].R - p->controls[k].force) > p->opt.controlRtol * p->controls[k].scale) return PETSC_FALSE;
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
  for (PetscInt k = 0; k < p->ncontrols; ++k) smin = PetscMin(smin, p->controls[k].scale);
  while (*reason > 0) {
    const PetscInt loadSteps = p->sched.loadSteps, stages = p->sched.penaltyStages;
    PetscReal      tol[3];
    PetscInt       n;
    Vec            X0;

    PetscCall(ProblemComputeReactions(p, p->X)); /* the controls' U (ProblemScatterToBodies) and R at X */
    for (PetscInt k = 0; k < p->ncontrols; ++k) {
      ForceControl *fc = &p->controls[k];
      const BodyBC *bc = &p->bodies[fc->body]->bc[fc->bc];
      fc->R            = bc->reaction[bc->comps[fc->c]];
    }
    if (!p->opt.controlRtolSet || ControlsConverged(p)) break;
    if (p->res.controlSolves >= p->opt.controlMaxIt) {
      *reason = TAO_DIVERGED_MAXITS;
      PetscCall(PetscSNPrintf(p->res.why, sizeof(p->res.why), "force control: the reactions are not the forces after -force_control_max_it %" PetscInt_FMT " solves (%s: reaction %g, force %g)", p->opt.controlMaxIt, p->bodies[p->controls[0].body]->bc[p->controls[0].bc].group, (double)p->controls[0].R, (double)p->controls[0].force));
      break;
    }
    PetscCall(PetscInfo(p->tao, "force control: reaction %g, force %g: the solve goes on to the gradient %g\n", (double)p->controls[0].R, (double)p->controls[0].force, (double)(p->opt.controlRtol * smin)));
    PetscCall(VecDuplicate(p->X, &X0));
    PetscCall(VecCopy(p->X, X0));
    PetscCall(ProblemSetInitialGuess(p, X0));
    PetscCall(VecDestroy(&X0));
    PetscCall(TaoGetTolerances(p->tao, &tol[0], &tol[1], &tol[2]));
    PetscCall(TaoSetTolerances(p->tao, p->opt.controlRtol * smin, tol[1], 0.0));
    p->sched.loadSteps     = 1;
    p->sched.penaltyStages = 1;
    PetscCall(ProblemSolveStaged(p, &n, reason));
    p->sched.loadSteps     = loadSteps;
    p->sched.penaltyStages = stages;
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
  PetscCall(PetscFunctionListFind(ForceControlList, p->coupled ? "coupled" : "outer", &solve));
  PetscCheck(solve, p->comm, PETSC_ERR_PLIB, "force control: type not registered");
  PetscCall((*solve)(p, its, reason));
  PetscFunctionReturn(0);
}
