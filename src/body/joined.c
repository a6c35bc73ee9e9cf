/* The body's part of the joined vector X (problem.c): on each rank the
   bodies' owned unconstrained dofs in turn, so that a body's part of X and
   of the gradient G start at an offset of the rank's arrays. The body maps
   its local dofs to their indices in X (l2b: -1 for a constrained dof),
   scatters its part of X to its local vector (the Dirichlet values
   inserted) and adds its local gradient into its part of G. A rigid body has
   no dofs (its unknowns are force control's, forcecontrol.c): its table
   leaves these out. */
#include "body.h"
#include "bodyimpl.h"

PetscErrorCode BodySetJoinedNumbering(Body b, PetscInt first)
{
  PetscFunctionBeginUser;
  if (b->ops.setjoinednumbering) PetscCall(b->ops.setjoinednumbering(b, first));
  PetscFunctionReturn(0);
}

/* The global indices first + k written into the body's global vector are
   scattered to its local one, which leaves the constrained dofs (-1) alone. */
PetscErrorCode BodySetJoinedNumbering_Elastic(Body b, PetscInt first)
{
  PetscScalar       *a;
  const PetscScalar *l;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetArray(b->Xg, &a));
  for (PetscInt k = 0; k < b->nlocal; ++k) a[k] = (PetscScalar)(first + k);
  PetscCall(VecRestoreArray(b->Xg, &a));
  PetscCall(VecSet(b->Xl, -1.0));
  PetscCall(DMGlobalToLocalBegin(b->dm, b->Xg, INSERT_VALUES, b->Xl));
  PetscCall(DMGlobalToLocalEnd(b->dm, b->Xg, INSERT_VALUES, b->Xl));
  PetscCall(VecGetLocalSize(b->Xl, &n));
  PetscCall(PetscMalloc1(n, &b->l2b));
  PetscCall(VecGetArrayRead(b->Xl, &l));
  for (PetscInt k = 0; k < n; ++k) b->l2b[k] = (PetscInt)PetscFloorReal(PetscRealPart(l[k]) + 0.5);
  PetscCall(VecRestoreArrayRead(b->Xl, &l));
  PetscCall(VecZeroEntries(b->Xg));
  PetscFunctionReturn(0);
}

PetscErrorCode BodySetJoinedSolution(Body b, const PetscScalar x[])
{
  PetscFunctionBeginUser;
  PetscCall(VecPlaceArray(b->Xg, x));
  PetscCall(BodyGlobalToLocal(b, b->Xg, b->Xl));
  PetscCall(VecResetArray(b->Xg));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyAddJoinedGradient(Body b, PetscScalar g[])
{
  PetscFunctionBeginUser;
  if (b->ops.addjoinedgradient) PetscCall(b->ops.addjoinedgradient(b, b->Gl, g));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyAddLocalToJoined(Body b, Vec Yl, PetscScalar g[])
{
  PetscFunctionBeginUser;
  if (b->ops.addjoinedgradient) PetscCall(b->ops.addjoinedgradient(b, Yl, g));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyAddJoinedGradient_Elastic(Body b, Vec Yl, PetscScalar g[])
{
  PetscFunctionBeginUser;
  PetscCall(VecPlaceArray(b->Gg, g));
  PetscCall(DMLocalToGlobalBegin(b->dm, Yl, ADD_VALUES, b->Gg));
  PetscCall(DMLocalToGlobalEnd(b->dm, Yl, ADD_VALUES, b->Gg));
  PetscCall(VecResetArray(b->Gg));
  PetscFunctionReturn(0);
}
