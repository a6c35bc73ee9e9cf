/* A body's load history: -load_stages S, and every Dirichlet value (a
   displacement, or the force of a force-controlled component), every
   traction and every pressure gives S end values per component, stage
   after stage. The loading is a function of the load parameter lambda in
   [0, S]: in stage k (k - 1 <= lambda <= k, t = lambda - (k - 1))

     v(lambda) = (1 - t) v_{k-1} + t v_k,     v_0 = 0 (rest),

   linear from the last stage's end to this one's. The staged solve
   (staging.c) walks lambda from 0 to S, -load_steps increments a stage; a
   single stage is today's load factor lambda times the scene's values.

   Everything here is linear in the values: the Dirichlet vector of the
   conditions (DMPlexInsertBoundaryValues of the values), the loads'
   consistent nodal forces and a control's force. So the body holds the
   active stage's start and end (bclFrom and bclFull, FlFrom and Fl, each
   load's resultants forceFrom and force), rebuilt when lambda enters
   another stage, and the value at lambda is their weighted sum with the
   weights w = (1 - t, t) (w = (0, t) in the first stage, whose start is
   rest: bit for bit today's lambda times the end). What every stage
   shares, a force control's displacement U (the unknown, the same in the
   start and the end vector) and a body's exact solution, is scaled by the
   load factor w_0 + w_1: lambda in the first stage, 1 after. A rigid body
   has no vectors: its prescribed translation and rotation take the same
   weights on their stage ends (rigidbody.c), and its force controls' forces
   the same interpolation as an elastic body's. */
#include "history.h"
#include "loads.h"
#include "rigidbody.h"
#include "bodyimpl.h"

/* The conditions' displacement values (not the force-controlled
   components, whose value is the control's displacement) and the loads at
   the end of stage s (0: rest). */
static void BodyTakeStageValues(Body b, PetscInt s)
{
  for (PetscInt i = 0; i < b->nbc; ++i) {
    BodyBC *bc = &b->bc[i];
    for (PetscInt c = 0; c < bc->ncomp; ++c) {
      const PetscReal v = s > 0 ? bc->stage[s - 1][c] : 0.0;
      if (bc->control[c]) bc->force[c] = v;
      else bc->values[c] = v;
    }
  }
  for (PetscInt l = 0; l < b->nload; ++l) {
    BodyLoad *L = &b->load[l];
    for (PetscInt c = 0; c < 3; ++c) L->traction[c] = s > 0 ? L->stageTraction[s - 1][c] : 0.0;
    L->pressure    = s > 0 ? L->stagePressure[s - 1] : 0.0;
  }
}

/* The Dirichlet vector of the conditions' values as they are. */
static PetscErrorCode BodyInsertValues(Body b, Vec v)
{
  PetscFunctionBeginUser;
  PetscCall(VecSet(v, 0.0));
  PetscCall(DMPlexInsertBoundaryValues(b->dm, PETSC_TRUE, v, 0.0, NULL, NULL, NULL));
  PetscFunctionReturn(0);
}

/* The active stage's Dirichlet vectors, start and end, from the values of
   its conditions (a force control's as it is), and the conditions' values
   and forces at its end. */
static PetscErrorCode BodyStageDirichlet(Body b)
{
  PetscFunctionBeginUser;
  if (b->stage > 1) {
    BodyTakeStageValues(b, b->stage - 1);
    if (!b->bclFrom) PetscCall(VecDuplicate(b->bclFull, &b->bclFrom));
    PetscCall(BodyInsertValues(b, b->bclFrom));
  } else PetscCall(VecDestroy(&b->bclFrom));
  BodyTakeStageValues(b, b->stage);
  PetscCall(BodyInsertValues(b, b->bclFull));
  PetscFunctionReturn(0);
}

/* The active stage's loads, start and end: their nodal forces and resultants. */
static PetscErrorCode BodyStageLoads(Body b)
{
  PetscFunctionBeginUser;
  if (!b->nload) PetscFunctionReturn(0);
  if (b->stage > 1) {
    BodyTakeStageValues(b, b->stage - 1);
    if (!b->FlFrom) PetscCall(VecDuplicate(b->Fl, &b->FlFrom));
    PetscCall(BodyLoadsAssemble(b, b->FlFrom, PETSC_TRUE));
  } else PetscCall(VecDestroy(&b->FlFrom));
  BodyTakeStageValues(b, b->stage);
  PetscCall(BodyLoadsAssemble(b, b->Fl, PETSC_FALSE));
  PetscFunctionReturn(0);
}

/* The Dirichlet values at the load parameter last set: bcl = w_0 bclFrom + w_1 bclFull. */
static PetscErrorCode BodyCombineDirichlet(Body b)
{
  PetscFunctionBeginUser;
  if (b->bclFrom) PetscCall(VecAXPBYPCZ(b->bcl, b->loadWeight[0], b->loadWeight[1], 0.0, b->bclFrom, b->bclFull));
  else PetscCall(VecAXPBY(b->bcl, b->loadWeight[1], 0.0, b->bclFull));
  PetscFunctionReturn(0);
}

PetscErrorCode BodySetLoad(Body b, PetscReal lambda)
{
  PetscInt  k;
  PetscReal t;

  PetscFunctionBeginUser;
  LoadHistoryLocate(b->nstages, lambda, &k, &t);
  b->loadWeight[0] = k > 1 ? 1.0 - t : 0.0;
  b->loadWeight[1] = t;
  b->loadFactor    = k > 1 ? 1.0 : t;
  if (b->ops.setload) { /* a rigid body's motion: the same weights on its translation's and rotation's stage ends */
    b->stage = k;
    PetscCall(b->ops.setload(b));
    PetscFunctionReturn(0);
  }
  if (k != b->stage) {
    b->stage = k;
    PetscCall(BodyStageDirichlet(b));
    PetscCall(BodyStageLoads(b));
  }
  PetscCall(BodyCombineDirichlet(b));
  PetscFunctionReturn(0);
}

PetscErrorCode BodySetBCValue(Body b, PetscInt i, PetscInt c, PetscReal U)
{
  PetscFunctionBeginUser;
  b->bc[i].values[c] = U;
  PetscCall(BodyStageDirichlet(b));
  PetscCall(BodyCombineDirichlet(b));
  PetscFunctionReturn(0);
}

PetscReal BodyControlForce(Body b, PetscInt i, PetscInt c)
{
  const BodyBC *bc = &b->bc[i];

  if (bc->anchor) return 0.0;
  return (b->stage > 1 ? b->loadWeight[0] * bc->stage[b->stage - 2][c] : 0.0) + b->loadWeight[1] * bc->stage[b->stage - 1][c];
}

PetscReal BodyRigidControlForce(Body b, PetscInt q)
{
  const BodyRigid *r = b->rg;

  if (!r->control[q]) return 0.0; /* held by the contact alone: force 0 */
  if (q >= r->dim) { /* the rotation's: the moment over L (-rigid_moment: rigidbody.c) */
    const PetscInt c = q - r->dim;
    return ((b->stage > 1 ? b->loadWeight[0] * r->momEnd[b->stage - 2][c] : 0.0) + b->loadWeight[1] * r->momEnd[b->stage - 1][c]) / r->L;
  }
  for (PetscInt k = 0; k < b->bc[r->qbc[q]].ncomp; ++k)
    if (b->bc[r->qbc[q]].comps[k] == q) return BodyControlForce(b, r->qbc[q], k);
  return 0.0;
}

void BodyLoadResultant(Body b, PetscInt l, PetscReal f[3])
{
  const BodyLoad *L = &b->load[l];

  for (PetscInt d = 0; d < b->dim; ++d) f[d] = b->loadWeight[1] * L->force[d] + (b->stage > 1 ? b->loadWeight[0] * L->forceFrom[d] : 0.0);
}

/* Any stage's load, Dirichlet value or exact solution imposed that is not
   zero. */
PetscBool BodyIsLoaded(Body b)
{
  for (PetscInt l = 0; l < b->nload; ++l)
    for (PetscInt st = 0; st < b->nstages; ++st)
      if (b->load[l].isPressure ? b->load[l].stagePressure[st] != 0 : b->load[l].stageTraction[st][0] != 0 || b->load[l].stageTraction[st][1] != 0 || b->load[l].stageTraction[st][2] != 0) return PETSC_TRUE;
  for (PetscInt j = 0; j < b->nbc; ++j) {
    if (b->bc[j].exact) return PETSC_TRUE;
    for (PetscInt c = 0; c < b->bc[j].ncomp; ++c)
      for (PetscInt st = 0; st < b->nstages; ++st)
        if (b->bc[j].stage[st][c] != 0) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}
