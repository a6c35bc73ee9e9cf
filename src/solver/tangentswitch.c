/* The Newton step's choice between two Hessians (problem.c decides at each
   Hessian, ProblemAssembleHessian): where -tangent_at_rest is not given, a
   neohookean body's Hessian is the stiffness at rest K for the first
   -tangent_at_rest_its iterations of each solve (10), its tangent after.
   With K in the tangent's place Newton's step is modified Newton's (the
   gradient is still the material's, so the answer is the same): the linear
   bodies' Schur step, K condensed once, one surface solve a step, where the
   tangent costs a factorisation of the whole Hessian a step. At small and
   moderate strain the modified steps converge in about the iterations
   Newton's take, at a third of their cost; at large strain (the rubber
   squeeze's 52 %) they converge slowly, and the tangent takes over.
   Measured on the reference scene with both bodies neohookean, pushed by
   0.01, 0.05, 0.15, 0.3 (largest strain 1.4 to 25 %), and on the squeeze:
   docs/solver.md. The two preconditioners share the Hessian matrix, which
   holds whichever the problem assembled; the step applies the matching one,
   set up (factored, or its surface block condensed) only when it is
   applied, so a solve that ends within the first iterations never factors
   the whole Hessian. */
#include "tangentswitch.h"

typedef struct {
  PC               rest, full;
  const PetscBool *useFull;
} SwitchCtx;

static PetscErrorCode SwitchApply(PC pc, Vec x, Vec y)
{
  SwitchCtx *c;
  PC         a;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &c));
  a = *c->useFull ? c->full : c->rest;
  PetscCall(PCSetUp(a)); /* nothing where the Hessian has not changed since */
  PetscCall(PCApply(a, x, y));
  PetscFunctionReturn(0);
}

static PetscErrorCode SwitchDestroy(PC pc)
{
  SwitchCtx *c;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &c));
  PetscCall(PCDestroy(&c->rest));
  PetscCall(PCDestroy(&c->full));
  PetscCall(PetscFree(c));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactTangentSwitchPCSetUp(PC pc, PC rest, PC full, const PetscBool *full_in_use)
{
  SwitchCtx *c;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&c));
  PetscCall(PetscObjectReference((PetscObject)rest));
  PetscCall(PetscObjectReference((PetscObject)full));
  c->rest    = rest;
  c->full    = full;
  c->useFull = full_in_use;
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, c));
  PetscCall(PCShellSetApply(pc, SwitchApply));
  PetscCall(PCShellSetDestroy(pc, SwitchDestroy));
  PetscCall(PCShellSetName(pc, "Newton's step: the stiffness at rest's Schur step or the tangent's factorisation, chosen at each Hessian"));
  PetscFunctionReturn(0);
}
