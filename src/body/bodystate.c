/* The quadrature-point state of a body whose material has history
   (material.h: nstate > 0, the plastic material), and its lifecycle, the
   one the energy terms' state has (energyterm.h):

     state[c][q][k]  the accepted state at quadrature point q of local cell
                     c, k < nstate, the one the element loop (element.c)
                     gives the material's kernels; zero at rest
                     (BodyStateSetUp, BodyResetState);
     accept          after an increment converged at the displacement the
                     body's local vector holds: at each point the material's
                     update(state, H) is recorded (stateNew);
     begin           the next increment begins: the recorded state becomes
                     the accepted one;
     restore         a cut-back goes back to the accepted state, which the
                     state still is (only begin writes it, after a
                     converged increment): nothing to undo;
     reset           back to rest (a solve from rest).

   Within an increment, and after the last one, the state is fixed: the
   material's energy is then an incremental potential of the displacement
   alone, minimised as any other, and the converged solution stays its
   minimiser (its stress, energy and tangent those of the increment: a
   Taylor test at the solution sees the increment's potential, smooth where
   a point flows, not the kink of the yield surface the new state puts the
   solution on). What the state has become is the recorded one
   (BodyGetStateRange). Each point's update reads only that point, so that
   the state is computed where its cell is, on every rank alike. A body
   without history (and a rigid body) has no state: each function is then
   a no-op. */
#include "element.h"
#include "bodyimpl.h"

PetscErrorCode BodyStateSetUp(Body b)
{
  const PetscInt ns = b->mat ? b->mat->nstate : 0;

  PetscFunctionBeginUser;
  PetscCall(PetscFree(b->state));
  PetscCall(PetscFree(b->stateNew));
  b->statePending = PETSC_FALSE;
  if (!ns || !b->ncells) PetscFunctionReturn(0);
  PetscCheck(ns <= MATERIAL_MAX_STATE, b->comm, PETSC_ERR_PLIB, "body %s: material %s keeps %" PetscInt_FMT " state values a point, more than %d", b->name, b->mat->name, ns, MATERIAL_MAX_STATE);
  PetscCall(PetscCalloc1(b->ncells * b->nq * ns, &b->state)); /* two arrays, not one block: BodyBeginState swaps them */
  PetscCall(PetscCalloc1(b->ncells * b->nq * ns, &b->stateNew));
  PetscFunctionReturn(0);
}

PetscBool BodyHasState(Body b)
{
  return (PetscBool)(!b->rigid && b->mat && b->mat->nstate > 0);
}

PetscErrorCode BodyAcceptState(Body b)
{
  const PetscInt     nq = b->nq, ns = b->mat ? b->mat->nstate : 0;
  const PetscScalar *x;

  PetscFunctionBeginUser;
  if (!b->state) PetscFunctionReturn(0);
  PetscCall(VecGetArrayRead(b->Xl, &x));
  for (PetscInt c = 0; c < b->ncells; ++c) {
    PetscReal u[ELEMENT_MAX_DOFS];

    ElementGather(b, c, x, u);
    for (PetscInt iq = 0; iq < nq; ++iq) {
      const PetscInt p = (c * nq + iq) * ns;
      PetscReal      H[9];

      ElementPointGradient(b, c, iq, u, NULL, H);
      b->mat->update(b->param, &b->state[p], H, &b->stateNew[p]);
    }
  }
  PetscCall(VecRestoreArrayRead(b->Xl, &x));
  b->statePending = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode BodyBeginState(Body b)
{
  PetscReal *t = b->state;

  PetscFunctionBeginUser;
  if (!b->statePending) PetscFunctionReturn(0);
  b->state        = b->stateNew;
  b->stateNew     = t;
  b->statePending = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode BodyRestoreState(Body b)
{
  PetscFunctionBeginUser;
  b->statePending = PETSC_FALSE; /* the state is still the accepted one: only BodyBeginState writes it */
  PetscFunctionReturn(0);
}

PetscErrorCode BodyResetState(Body b)
{
  PetscFunctionBeginUser;
  b->statePending = PETSC_FALSE;
  if (b->state) PetscCall(PetscArrayzero(b->state, b->ncells * b->nq * b->mat->nstate));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGetStateRange(Body b, PetscInt k, PetscReal *vmin, PetscReal *vmax)
{
  const PetscInt   ns = b->state ? b->mat->nstate : 0;
  const PetscReal *s  = b->statePending ? b->stateNew : b->state; /* the latest: recorded, or accepted */
  PetscReal        lo[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, gl[2];

  PetscFunctionBeginUser;
  for (PetscInt p = 0; ns && k < ns && p < b->ncells * b->nq; ++p) {
    lo[0] = PetscMin(lo[0], s[p * ns + k]);
    lo[1] = PetscMin(lo[1], -s[p * ns + k]);
  }
  PetscCall(MPIU_Allreduce(lo, gl, 2, MPIU_REAL, MPIU_MIN, b->comm));
  *vmin = gl[0];
  *vmax = -gl[1];
  PetscFunctionReturn(0);
}
