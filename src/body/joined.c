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

/* For the iterative step's coarse level (iterative.c): every point of the
   chart that carries a node (dim components), its joined rows, and the
   joined rows of the vertices of its closure (an edge's two, a face's, a
   cell's; at most 8), -1 for a constrained component. A body without cells
   has none. */
PetscErrorCode BodyGetNodeVertexRows(Body b, PetscInt *n, PetscInt **nodeRows, PetscInt **nv, PetscInt **vertexRows)
{
  const PetscInt dim = b->dim;
  PetscSection   sec;
  PetscInt       vs, ve, k = 0;

  PetscFunctionBeginUser;
  *n = 0;
  *nodeRows = *nv = *vertexRows = NULL;
  if (!b->dm || !b->l2b) PetscFunctionReturn(0);
  PetscCall(DMGetLocalSection(b->dm, &sec));
  PetscCall(DMPlexGetDepthStratum(b->dm, 0, &vs, &ve));
  PetscCall(PetscMalloc3(dim * (b->pEnd - b->pStart) + 1, nodeRows, b->pEnd - b->pStart + 1, nv, 8 * dim * (b->pEnd - b->pStart) + 1, vertexRows));
  for (PetscInt p = b->pStart; p < b->pEnd; ++p) {
    PetscInt dof, off, ncl, *cl = NULL, m = 0;

    PetscCall(PetscSectionGetDof(sec, p, &dof));
    if (dof < dim) continue;
    PetscCall(PetscSectionGetOffset(sec, p, &off));
    for (PetscInt d = 0; d < dim; ++d) (*nodeRows)[dim * k + d] = b->l2b[off + d];
    PetscCall(DMPlexGetTransitiveClosure(b->dm, p, PETSC_TRUE, &ncl, &cl));
    for (PetscInt j = 0; j < ncl && m < 8; ++j) {
      const PetscInt q = cl[2 * j];
      PetscInt       voff;
      if (q < vs || q >= ve) continue;
      PetscCall(PetscSectionGetOffset(sec, q, &voff));
      for (PetscInt d = 0; d < dim; ++d) (*vertexRows)[(8 * k + m) * dim + d] = b->l2b[voff + d];
      ++m;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(b->dm, p, PETSC_TRUE, &ncl, &cl));
    (*nv)[k++] = m;
  }
  *n = k;
  PetscFunctionReturn(0);
}
