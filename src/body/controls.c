/* A body's force controls (controls.h): the dispatchers of the table, and
   the elastic body's side of each (rigidbody.c has the rigid body's). An
   elastic body's control is a force-controlled component c of Dirichlet
   condition bc: the group moves rigidly in it by a displacement U, set as
   the condition's value U / lambda (the body scales its values by the load
   factor lambda, history.c), and its reaction is the condition's reaction
   in that component. Its column of the border (forcecontrol.c) is K e, e the
   unit motion of the group in the component: for a constant tangent the
   gradient of the (quadratic) elastic energy at e minus that at 0, else the
   tangent at the body's state applied to e over the cells around the group
   (BodyApplyTangentLocal). */
#include "controls.h"
#include "body.h"
#include "bodyimpl.h"

PetscErrorCode BodyGetControls(Body b, PetscInt *n, BodyControl ctl[])
{
  PetscFunctionBeginUser;
  *n = 0;
  if (b->ops.getcontrols) PetscCall(b->ops.getcontrols(b, n, ctl));
  PetscFunctionReturn(0);
}

PetscErrorCode BodySetControlValue(Body b, PetscInt bc, PetscInt c, PetscReal U)
{
  PetscFunctionBeginUser;
  PetscCall(b->ops.setcontrol(b, bc, c, U));
  PetscFunctionReturn(0);
}

PetscReal BodyGetControlForce(Body b, PetscInt bc, PetscInt c)
{
  return b->ops.controlforce(b, bc, c);
}

PetscReal BodyGetControlReaction(Body b, PetscInt bc, PetscInt c)
{
  return b->ops.controlreaction(b, bc, c);
}

const char *BodyGetControlComponent(Body b, PetscInt bc, PetscInt c)
{
  return b->ops.controlcomponent(b, bc, c);
}

/* The size of the body: its reference bounding box's diagonal. */
static PetscErrorCode BodyControlSize(Body b, PetscReal *L)
{
  PetscReal lo[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[3] = {PETSC_MIN_REAL, PETSC_MIN_REAL, PETSC_MIN_REAL};
  PetscInt  dim = b->dim;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < b->ncells * b->nb; ++k) /* every node of this rank's cells */
    for (PetscInt d = 0; d < dim; ++d) {
      lo[d] = PetscMin(lo[d], b->xnode[dim * k + d]);
      hi[d] = PetscMax(hi[d], b->xnode[dim * k + d]);
    }
  for (PetscInt d = 0; d < dim; ++d) lo[d] = -lo[d];
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, lo, dim, MPIU_REAL, MPIU_MAX, b->comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, hi, dim, MPIU_REAL, MPIU_MAX, b->comm));
  if (dim == 3) *L = PetscSqrtReal(PetscSqr(hi[0] + lo[0]) + PetscSqr(hi[1] + lo[1]) + PetscSqr(hi[2] + lo[2]));
  else *L = PetscSqrtReal(PetscSqr(hi[0] + lo[0]) + PetscSqr(hi[1] + lo[1]));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGetControls_Elastic(Body b, PetscInt *n, BodyControl ctl[])
{
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < b->nbc; ++j)
    for (PetscInt c = 0; c < b->bc[j].ncomp; ++c) {
      BodyControl *k;
      if (!b->bc[j].control[c]) continue;
      k         = &ctl[(*n)++];
      k->bc     = j;
      k->c      = c;
      k->force  = b->bc[j].force[c];
      k->anchor = b->bc[j].anchor;
      k->motion = PETSC_FALSE;
      k->scale  = PetscAbsReal(k->force);
      for (PetscInt l = 0; l < b->nload; ++l) k->scale += PetscSqrtReal(PetscSqr(b->load[l].force[0]) + PetscSqr(b->load[l].force[1]));
      if (!(k->scale > 0)) k->scale = 1.0;
      PetscCall(BodyControlSize(b, &k->L));
      k->kref = b->E * (b->axisym ? k->L : 1.0); /* a stiffness (force per length per unit thickness; r-z: over the whole circle) */
    }
  PetscFunctionReturn(0);
}

/* U / lambda: the group moves by U whatever the load factor. */
PetscErrorCode BodySetControlValue_Elastic(Body b, PetscInt bc, PetscInt c, PetscReal U)
{
  const PetscReal v = b->loadFactor > 0 ? U / b->loadFactor : 0.0;

  PetscFunctionBeginUser;
  if (b->bc[bc].values[c] != v) PetscCall(BodySetBCValue(b, bc, c, v));
  PetscFunctionReturn(0);
}

PetscReal BodyGetControlForce_Elastic(Body b, PetscInt bc, PetscInt c)
{
  return BodyControlForce(b, bc, c);
}

PetscReal BodyGetControlReaction_Elastic(Body b, PetscInt bc, PetscInt c)
{
  return b->bc[bc].reaction[b->bc[bc].comps[c]];
}

const char *BodyGetControlComponent_Elastic(Body b, PetscInt bc, PetscInt c)
{
  static const char *const axis[3] = {"x", "y", "z"}; /* the condition's component c is axis comps[c] (3D: z too) */
  return axis[b->bc[bc].comps[c]];
}

PetscErrorCode BodyControlColumn(Body b, PetscInt bc, PetscInt c, Vec Xl, Vec *E, Vec y, PetscReal R[][3])
{
  const PetscReal v0 = b->bc[bc].values[c];
  Vec             e;
  PetscReal       en, saved[CONTACT_MAX_BC][3];

  PetscFunctionBeginUser;
  if (*E) e = *E;
  else {
    PetscCall(VecDuplicate(b->Xl, &e));
    PetscCall(BodySetBCValue(b, bc, c, 1.0));
    PetscCall(VecCopy(b->bclFull, e));
    PetscCall(BodySetBCValue(b, bc, c, 0.0));
    PetscCall(VecAXPY(e, -1.0, b->bclFull));
    PetscCall(BodySetBCValue(b, bc, c, v0));
    if (!b->mat->constantTangent) *E = e; /* kept: the column is made again at each Hessian */
  }
  if (b->mat->constantTangent) {
    Vec z, g0;
    PetscCall(VecDuplicate(b->Xl, &z));
    PetscCall(VecDuplicate(b->Xl, &g0));
    PetscCall(VecZeroEntries(z));
    PetscCall(VecZeroEntries(g0));
    PetscCall(BodyComputeEnergyGradient(b, z, &en, g0));
    PetscCall(VecZeroEntries(y));
    PetscCall(BodyComputeEnergyGradient(b, e, &en, y));
    PetscCall(VecAXPY(y, -1.0, g0));
    PetscCall(VecDestroy(&z));
    PetscCall(VecDestroy(&g0));
  } else PetscCall(BodyApplyTangentLocal(b, Xl, e, y));
  for (PetscInt j = 0; j < b->nbc; ++j) {
    for (PetscInt d = 0; d < 3; ++d) saved[j][d] = b->bc[j].reaction[d];
  }
  PetscCall(BodyComputeReactions(b, y));
  for (PetscInt j = 0; j < b->nbc; ++j) {
    for (PetscInt d = 0; d < 3; ++d) R[j][d] = b->bc[j].reaction[d];
    for (PetscInt d = 0; d < 3; ++d) b->bc[j].reaction[d] = saved[j][d]; /* as the column found them */
  }
  if (e != *E) PetscCall(VecDestroy(&e));
  PetscFunctionReturn(0);
}
