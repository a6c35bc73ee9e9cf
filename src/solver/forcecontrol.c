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
       by 1, fc.B[k]) and K_UU = 1^T K_cc 1 (fc.D),
     which the Newton step eliminates (forceborder.c) with the solve it
     already has. One solve, as a displacement run's; measured in
     results/force_control.json. Assumption: the border is the elastic
     stiffness's alone, so a controlled group on a contact surface (whose
     nodes the contact would couple to U) gets a Newton step without that
     coupling: still a descent direction, no longer Newton's.
     A body whose tangent varies (neohookean) has no constant K: its
     controls are only anchors (a force control of its own is refused,
     body.c), whose columns K(u) e_k are made again at each Hessian from
     the stiffness that Hessian has, the tangent at u or the stiffness at
     rest (ProblemUpdateControlBorder): the bordered matrix is then the
     Hessian of Pi(u; U) in (u, U) (but for the assumption above), and the
     step Newton's. Only the cells
     around each anchor's vertex are visited; measured on a whole rubber
     disc squeezed by 30 % (3,247 dofs, 270 Newton iterations) 0.27 ms a
     Hessian, 0.35 % of the solve (tests/test_neo_held.py). With the
     columns at rest instead, the same scene did not converge in 1,873
     iterations (the tangent's border differs from the rest's by the
     strain, 50 %).
     With load stepping (load factor lambda) the group moves by U, and the
     force is lambda F: the group's Dirichlet value is set to U / lambda,
     which the body scales by lambda.
     It ends where the solve's gradient test ends it (its last stage
     relative to the gradient at rest of the displacement run of the U
     found, staging.c); where -force_control_rtol is given and a reaction is
     then further from its force than it, the solve goes on from there with
     the gradient tolerance -force_control_rtol times the least |F| (one
     more solve, counted in force_control_solves; forcesolve.c).
   - outer: an outer iteration on U around displacement-controlled solves
     (forceouter.c). A scene with a body held by contact (anchors.c) is
     always coupled: its anchors are controls of force zero, and the motions
     the contact does not hold are frozen where the anchors' residual is
     small (unheld.c).

   This file is force control's part of the assembled system: the controls
   found, the border, the controls' displacements and work in an evaluation
   of X. problem.c calls it; the solves by type are forcesolve.c's and
   forceouter.c's, above it. */
#include "forcecontrol.h"
#include "options.h"

/* Adds body i's controls (controls.h) to the problem's, those of kind
   motion (a rigid body's unknowns) or not; a motion's kref is the least E
   of the elastic bodies (Emin) times its own factor (the body's size in r-z). */
static PetscErrorCode ProblemAddBodyControls(Problem p, PetscInt i, PetscInt n, const BodyControl ctl[], PetscBool motion, PetscReal Emin)
{
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < n; ++j) {
    ForceControl *fc;
    if (ctl[j].motion != motion) continue;
    PetscCheck(p->fc.n < CONTACT_MAX_CONTROLS, p->comm, PETSC_ERR_USER_INPUT, motion ? "more than %d force-controlled components and rigid bodies' unknowns" : "more than %d force-controlled components", CONTACT_MAX_CONTROLS);
    fc         = &p->fc.c[p->fc.n++];
    fc->body   = i;
    fc->bc     = ctl[j].bc;
    fc->c      = ctl[j].c;
    fc->motion = ctl[j].motion;
    fc->force  = ctl[j].force;
    fc->U      = 0.0;
    fc->anchor = ctl[j].anchor;
    fc->scale  = ctl[j].scale;
    fc->L      = ctl[j].L;
    fc->kref   = motion ? Emin * ctl[j].kref : ctl[j].kref;
    if (motion) p->fc.rigid = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemCollectControls(Problem p)
{
  PetscBool    anchor[CONTACT_MAX_CONTROLS];
  PetscReal    kref[CONTACT_MAX_CONTROLS], Emin = PETSC_MAX_REAL;
  PetscInt     n[CONTACT_MAX_BODIES];
  BodyControl *ctl;

  PetscFunctionBeginUser;
  p->fc.n     = 0;
  p->fc.rigid = PETSC_FALSE;
  PetscCall(PetscMalloc1(p->nbodies * (3 * CONTACT_MAX_BC + 3), &ctl));
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    PetscReal E, nu;
    PetscCall(BodyGetControls(p->bodies[i], &n[i], &ctl[i * (3 * CONTACT_MAX_BC + 3)]));
    BodyGetElasticConstants(p->bodies[i], &E, &nu);
    if (BodyHasCells(p->bodies[i])) Emin = PetscMin(Emin, E);
  }
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(ProblemAddBodyControls(p, i, n[i], &ctl[i * (3 * CONTACT_MAX_BC + 3)], PETSC_FALSE, Emin)); /* the conditions' first, then the rigid bodies' unknowns */
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(ProblemAddBodyControls(p, i, n[i], &ctl[i * (3 * CONTACT_MAX_BC + 3)], PETSC_TRUE, Emin));
  PetscCall(PetscFree(ctl));
  for (PetscInt k = 0; k < p->fc.n; ++k) {
    anchor[k] = p->fc.c[k].anchor;
    kref[k]   = p->fc.c[k].kref;
  }
  PetscCall(UnheldSetUp(&p->fc.unheld, p->fc.n, anchor, kref));
  PetscCall(PetscStrcmp(p->cfg->control.type, "coupled", &p->fc.coupled));
  if (p->fc.n && !p->fc.coupled && UnheldAny(&p->fc.unheld)) PetscCall(PetscInfo(NULL, "force control: a body held by contact: coupled, whatever -force_control_type\n"));
  PetscCheck(!p->fc.rigid || p->fc.coupled, p->comm, PETSC_ERR_USER_INPUT, "option -force_control_type %s: a rigid body's free motion is solved coupled only", p->cfg->control.type);
  p->fc.coupled = (PetscBool)(p->fc.n > 0 && (p->fc.coupled || UnheldAny(&p->fc.unheld)));
  PetscCheck(!p->fc.n || p->fc.coupled || p->cfg->load.stages == 1, p->comm, PETSC_ERR_USER_INPUT, "option -force_control_type outer: its iteration finds the controls' displacements at one load, not along -load_stages %" PetscInt_FMT "; use -force_control_type coupled", p->cfg->load.stages);
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCheck(!p->fc.n || p->fc.coupled || !EnergyTermHasState(p->terms[t]), p->comm, PETSC_ERR_USER_INPUT, "option -force_control_type outer: each trial goes on from the last, whose slip pair %s's friction would keep; use -force_control_type coupled", p->terms[t]->name);
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
    PetscCall(BodyComputeReactions(b, BodyGetLocalGradient(b)));
    for (PetscInt l = 0; l < BodyGetNumLoads(b); ++l) *S = PetscMax(*S, PetscSqrtReal(PetscSqr(BodyGetLoad(b, l)->force[0]) + PetscSqr(BodyGetLoad(b, l)->force[1])));
    for (PetscInt j = 0; j < BodyGetNumConditions(b); ++j) {
      const BodyBC *bc = BodyGetCondition(b, j);
      *S               = PetscMax(*S, PetscSqrtReal(PetscSqr(bc->reaction[0]) + PetscSqr(bc->reaction[1])));
      for (PetscInt c = 0; c < bc->ncomp; ++c)
        if (bc->control[c]) *S = PetscMax(*S, PetscAbsReal(BodyControlForce(b, j, c)));
    }
  }
  PetscFunctionReturn(0);
}

/* Column k of the border and the controls' own stiffness: K e_k, e_k the
   local vector with 1 on group k's nodes in its component and 0 elsewhere,
   summed to the free dofs (B_k) and over each control's group (D_lk, as a
   reaction). K is the body's stiffness: for a constant one the gradient of
   the elastic energy at e_k minus that at 0 (the energy is quadratic); for
   a body whose tangent varies (neohookean: only an anchor, anchors.c) the
   tangent at its local vector Xl (NULL: at rest) applied to e_k over the
   few cells around the group (BodyApplyTangentLocal), made anew with each
   Hessian (ProblemUpdateControlBorder). The body's reactions and
   gradient are left as the last evaluation made them. */
static PetscErrorCode ProblemControlColumn(Problem p, PetscInt k, Vec Xl)
{
  const ForceControl *fc = &p->fc.c[k];
  Body                b  = p->bodies[fc->body];
  Vec                 y;
  PetscScalar        *a;
  PetscReal           R[CONTACT_MAX_BC][3];

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(BodyGetLocalSolution(b), &y));
  PetscCall(BodyControlColumn(b, fc->bc, fc->c, Xl, &p->fc.E[k], y, R));
  for (PetscInt l = 0; l < p->fc.n; ++l) {
    const ForceControl *fl = &p->fc.c[l];
    p->fc.D[l * p->fc.n + k] = !fl->motion && fl->body == fc->body ? R[fl->bc][BodyGetCondition(b, fl->bc)->comps[fl->c]] : 0.0;
  }
  if (!p->fc.B[k]) PetscCall(VecDuplicate(p->Xb, &p->fc.B[k]));
  PetscCall(VecZeroEntries(p->fc.B[k]));
  PetscCall(VecGetArray(p->fc.B[k], &a));
  PetscCall(BodyAddLocalToJoined(b, y, a + p->offset[fc->body]));
  PetscCall(VecRestoreArray(p->fc.B[k], &a));
  PetscCall(VecDestroy(&y));
  PetscFunctionReturn(0);
}

/* D's entries between controls of one body, symmetric in exact arithmetic:
   their mean. */
static void ProblemControlSymmetrise(Problem p)
{
  const PetscInt m = p->fc.n;

  for (PetscInt k = 0; k < m; ++k)
    for (PetscInt l = 0; l < k; ++l)
      if (!p->fc.c[k].motion && !p->fc.c[l].motion) p->fc.D[k * m + l] = p->fc.D[l * m + k] = 0.5 * (p->fc.D[k * m + l] + p->fc.D[l * m + k]);
}

PetscErrorCode ProblemSetUpControlBorder(Problem p)
{
  const PetscInt m = p->fc.n;

  PetscFunctionBeginUser;
  if (!p->fc.coupled) PetscFunctionReturn(0);
  for (PetscInt k = 0; k < m; ++k) {
    if (!p->fc.c[k].motion) PetscCall(ProblemControlColumn(p, k, NULL));
    else { /* the contact's, at each Hessian (ProblemRigidBorderEnd) */
      PetscCall(VecDuplicate(p->Xb, &p->fc.B[k]));
      PetscCall(VecZeroEntries(p->fc.B[k]));
      for (PetscInt l = 0; l < m; ++l) p->fc.D[l * m + k] = p->fc.D[k * m + l] = 0.0;
    }
  }
  for (PetscInt k = 0; k < m; ++k) {
    if (p->fc.c[k].motion) continue;
    PetscCheck(p->fc.D[k * m + k] > 0, p->comm, PETSC_ERR_USER_INPUT, "body %s: force-controlled group %s has no stiffness of its own (no cell touches it on any rank)", BodyGetName(p->bodies[p->fc.c[k].body]), BodyGetCondition(p->bodies[p->fc.c[k].body], p->fc.c[k].bc)->group);
  }
  ProblemControlSymmetrise(p);
  PetscFunctionReturn(0);
}

static PetscLogEvent ControlColumns = 0;

PetscErrorCode ProblemUpdateControlBorder(Problem p, PetscBool tangent)
{
  PetscBool any = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (!p->fc.coupled) PetscFunctionReturn(0);
  if (!ControlColumns) {
    PetscClassId id;
    PetscCall(PetscClassIdRegister("ContactForceControl", &id));
    PetscCall(PetscLogEventRegister("ForceBorderColumns", id, &ControlColumns));
  }
  PetscCall(PetscLogEventBegin(ControlColumns, 0, 0, 0, 0));
  for (PetscInt k = 0; k < p->fc.n; ++k) {
    const Body b = p->bodies[p->fc.c[k].body];
    if (p->fc.c[k].motion || BodyHasConstantTangent(b)) continue;
    PetscCall(ProblemControlColumn(p, k, tangent ? BodyGetLocalSolution(b) : NULL));
    any = PETSC_TRUE;
  }
  if (any) ProblemControlSymmetrise(p);
  PetscCall(PetscLogEventEnd(ControlColumns, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetControlDisplacements(Problem p, Vec X)
{
  PetscReal          U[CONTACT_MAX_CONTROLS];
  PetscInt           n, nb;
  PetscMPIInt        rank, m;
  const PetscScalar *x;

  PetscFunctionBeginUser;
  if (!p->fc.coupled) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  PetscCall(VecGetLocalSize(X, &n));
  PetscCall(VecGetLocalSize(p->Xb, &nb));
  if (!rank) {
    PetscCheck(n == nb + p->fc.n, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "force control: a vector without the controlled displacements");
    PetscCall(VecGetArrayRead(X, &x));
    for (PetscInt k = 0; k < p->fc.n; ++k) U[k] = PetscRealPart(x[nb + k]);
    PetscCall(VecRestoreArrayRead(X, &x));
  }
  PetscCall(PetscMPIIntCast(p->fc.n, &m));
  PetscCallMPI(MPI_Bcast(U, m, MPIU_REAL, 0, p->comm));
  for (PetscInt k = 0; k < p->fc.n; ++k) {
    ForceControl *fc = &p->fc.c[k];
    fc->U            = U[k];
    PetscCall(BodySetControlValue(p->bodies[fc->body], fc->bc, fc->c, U[k]));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemAddControlWork(Problem p, PetscReal *f, Vec G)
{
  const PetscBool held = UnheldAny(&p->fc.unheld);
  PetscBool       done[CONTACT_MAX_BODIES];
  PetscMPIInt     rank;
  PetscInt        nb;
  PetscReal       gU[CONTACT_MAX_CONTROLS], S = 0;

  PetscFunctionBeginUser;
  if (!p->fc.coupled) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  PetscCall(VecGetLocalSize(p->Xb, &nb));
  if (held) PetscCall(ProblemControlSceneForce(p, &S)); /* it computes every body's reactions */
  for (PetscInt i = 0; i < p->nbodies; ++i) done[i] = held;
  for (PetscInt k = 0; k < p->fc.n; ++k) {
    ForceControl *fc = &p->fc.c[k];
    Body          b  = p->bodies[fc->body];
    PetscReal     F;
    if (!done[fc->body]) PetscCall(BodyComputeReactions(b, BodyGetLocalGradient(b))); /* Gl: the evaluation's, before its sum over ranks */
    done[fc->body] = PETSC_TRUE;
    fc->R          = ProblemControlReaction(p, k); /* a rigid body's dPi/dq: the contact's force, or moment over L */
    F              = BodyGetControlForce(b, fc->bc, fc->c); /* at the load parameter (history.c) */
    gU[k]          = fc->R - F;
    *f -= F * fc->U;
  }
  PetscCall(PetscInfo(NULL, "force control: U_0 = %.10g, reaction %.10g, energy %.10g\n", (double)p->fc.c[0].U, (double)p->fc.c[0].R, (double)*f));
  if (held) PetscCall(UnheldSetGradient(&p->fc.unheld, S, gU)); /* the directions the contact does not hold, projected out */
  if (!rank) {
    PetscScalar *g;
    PetscCall(VecGetArray(G, &g));
    for (PetscInt k = 0; k < p->fc.n; ++k) g[nb + k] = gU[k];
    PetscCall(VecRestoreArray(G, &g));
  }
  PetscFunctionReturn(0);
}

PetscReal ProblemControlReaction(Problem p, PetscInt k)
{
  const ForceControl *fc = &p->fc.c[k];

  return BodyGetControlReaction(p->bodies[fc->body], fc->bc, fc->c);
}

const char *ProblemControlGroup(Problem p, PetscInt k)
{
  const ForceControl *fc = &p->fc.c[k];

  return fc->bc < 0 ? "" : BodyGetCondition(p->bodies[fc->body], fc->bc)->group;
}

const char *ProblemControlComponent(Problem p, PetscInt k)
{
  const ForceControl *fc = &p->fc.c[k];

  return BodyGetControlComponent(p->bodies[fc->body], fc->bc, fc->c);
}

PetscErrorCode ProblemRigidBorderBegin(Problem p)
{
  PetscFunctionBeginUser;
  if (!p->fc.rigid) PetscFunctionReturn(0);
  for (PetscInt k = 0; k < p->fc.n; ++k) {
    const ForceControl *fc = &p->fc.c[k];
    if (!fc->motion) continue;
    PetscCall(VecZeroEntries(p->fc.B[k]));
    BodyRigidBorderBegin(p->bodies[fc->body], fc->c, p->fc.B[k]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemRigidBorderEnd(Problem p)
{
  const PetscInt m = p->fc.n;

  PetscFunctionBeginUser;
  if (!p->fc.rigid) PetscFunctionReturn(0);
  for (PetscInt k = 0; k < m; ++k) /* each body's coupling among its unknowns, summed over ranks once */
    if (p->fc.c[k].motion && (k == 0 || p->fc.c[k - 1].body != p->fc.c[k].body || !p->fc.c[k - 1].motion)) PetscCall(BodyRigidBorderSum(p->bodies[p->fc.c[k].body]));
  for (PetscInt k = 0; k < m; ++k) {
    const ForceControl *fc = &p->fc.c[k];
    if (!fc->motion) continue;
    PetscCall(VecAssemblyBegin(p->fc.B[k]));
    PetscCall(VecAssemblyEnd(p->fc.B[k]));
    BodyRigidBorderEnd(p->bodies[fc->body], fc->c);
    for (PetscInt l = 0; l < m; ++l) {
      const ForceControl *fl = &p->fc.c[l];
      if (!fl->motion || fl->body != fc->body) continue;
      p->fc.D[k * m + l] = BodyRigidBorderCoupling(p->bodies[fc->body], fc->c, fl->c);
    }
  }
  PetscFunctionReturn(0);
}

/* Y: the rest of the displacement run that imposes the controls'
   displacements as X holds them: the bodies' dofs at 0, each control's U
   (an anchor's at 0: its vertex moved alone is no displacement run's rest). */
PetscErrorCode ProblemControlRest(Problem p, Vec X, Vec Y)
{
  const PetscScalar *x;
  PetscScalar       *y;
  PetscInt           nb, n;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(Y));
  PetscCall(VecGetLocalSize(p->Xb, &nb));
  PetscCall(VecGetLocalSize(X, &n));
  PetscCall(VecGetArrayRead(X, &x));
  PetscCall(VecGetArray(Y, &y));
  for (PetscInt k = nb; k < n; ++k) y[k] = p->fc.c[k - nb].anchor ? 0.0 : x[k];
  PetscCall(VecRestoreArray(Y, &y));
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode ForceControlsDestroy(ForceControls *fc)
{
  PetscFunctionBeginUser;
  PetscCall(KSPDestroy(&fc->ksp));
  for (PetscInt k = 0; k < fc->n; ++k) {
    PetscCall(VecDestroy(&fc->B[k]));
    PetscCall(VecDestroy(&fc->E[k]));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ForceControlOptionsSetFromOptions(MPI_Comm comm, ForceControlOptions *o)
{
  PetscErrorCode (*solve)(void) = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(o->type, "coupled", sizeof(o->type)));
  o->maxIt        = 40;
  o->rtol         = 1e-9;
  o->rtolSet      = PETSC_FALSE;
  o->step         = 0.3;
  o->borderSolves = PETSC_FALSE;
  PetscOptionsBegin(comm, NULL, "Force control options", NULL);
  PetscCall(ContactOptionsFList(PetscOptionsObject, "-force_control_type", "Force control: coupled (each controlled displacement an unknown of the one minimisation) or outer (an outer iteration of solves on them; not with a body held by contact, always coupled)", NULL, ForceControlList, o->type, o->type, sizeof(o->type), NULL));
  PetscCall(PetscOptionsInt("-force_control_max_it", "Force control: the most solves (outer: of its iteration on the controlled displacements; coupled: the solve and its continuations to -force_control_rtol)", NULL, o->maxIt, &o->maxIt, NULL));
  PetscCall(PetscOptionsReal("-force_control_rtol", "Force control: every controlled group's reaction is its force to this relative tolerance at the end (coupled: where given; else the solve's gradient test)", NULL, o->rtol, &o->rtol, &o->rtolSet));
  PetscCall(PetscOptionsReal("-force_control_step", "Coupled force control: the most a Newton step moves a controlled group, relative to its body's size", NULL, o->step, &o->step, NULL));
  PetscCall(PetscOptionsBool("-force_control_border_solves", "Coupled force control: eliminate the controls by m solves of the bodies' Hessian per Hessian, even where the step's preconditioner (the substructuring) does it from the contact surfaces with one solve a step", NULL, o->borderSolves, &o->borderSolves, NULL));
  PetscOptionsEnd();
  PetscCheck(o->maxIt >= 1, comm, PETSC_ERR_USER_INPUT, "option -force_control_max_it: must be >= 1, got %" PetscInt_FMT, o->maxIt);
  PetscCheck(o->rtol > 0 && o->rtol < 1, comm, PETSC_ERR_USER_INPUT, "option -force_control_rtol: must be in (0, 1), got %g", (double)o->rtol);
  PetscCheck(o->step > 0 && !PetscIsInfOrNanReal(o->step), comm, PETSC_ERR_USER_INPUT, "option -force_control_step: must be a finite number > 0, got %g", (double)o->step);
  PetscCall(PetscFunctionListFind(ForceControlList, o->type, &solve));
  PetscCheck(solve, comm, PETSC_ERR_USER_INPUT, "option -force_control_type: unknown type '%s' (known: coupled, outer)", o->type);
  PetscFunctionReturn(0);
}
