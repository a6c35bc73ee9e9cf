/* A rigid body's boundary as a contact surface sees it (surface.c), the
   rigid side of boundary.c: its lines of a group, given once by rank 0
   (every rank holds the body's curves) with the sign +1, the surface
   choosing the outward side against its partner (ContactSurfaceOrientRigid);
   its other lines through the surface's ends; no dofs, so that the nodes'
   components stand in the joined indices for the body's motion
   (ContactRigidDof), their displacements are the motion's and the
   contact's gradient at them is the force and moment on the body; and the
   contact's Hessian at them goes to the border of its unknowns
   (BodyRigidAddHessian). */
#include "rigidbody.h"
#include "bodyimpl.h"

PetscErrorCode BodyRigidGroupEdgesAsSurface(Body b, const char group[], const char what[], PetscInt *tag, PetscInt *n, PetscInt **eid, PetscReal **erl)
{
  const BodyRigid *r = b->rg;
  PetscMPIInt      rank;
  PetscInt         ne, *edges;

  PetscFunctionBeginUser;
  (void)what;
  PetscCallMPI(MPI_Comm_rank(b->comm, &rank));
  PetscCall(BodyGetPhysicalTag(b, group, 1, tag));
  PetscCall(BodyRigidGroupEdges(b, *tag, &ne, &edges));
  if (rank) ne = 0;
  PetscCall(PetscMalloc2(3 * ne + 1, eid, 7 * ne + 1, erl));
  for (PetscInt k = 0; k < ne; ++k) {
    const PetscInt *en = &r->enodes[3 * edges[k]];
    for (PetscInt j = 0; j < 3; ++j) {
      (*eid)[3 * k + j]         = r->ids[en[j]];
      (*erl)[7 * k + 2 * j]     = r->X[2 * en[j]];
      (*erl)[7 * k + 2 * j + 1] = r->X[2 * en[j] + 1];
    }
    (*erl)[7 * k + 6] = 1.0;
  }
  *n = ne;
  PetscCall(PetscFree(edges));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyRigidBoundaryEdgesAt(Body b, PetscInt tag, PetscInt nn, const PetscInt ids[], const PetscBool end[], BodyEdgeFn fn, void *ctx)
{
  const BodyRigid *r = b->rg;

  PetscFunctionBeginUser;
  for (PetscInt v = 0; v < nn; ++v) {
    if (!end[v]) continue;
    for (PetscInt f = 0; f < r->ne; ++f) {
      const PetscInt *fn_ = &r->enodes[3 * f];
      PetscReal       xf[6];
      if (r->etag[f] == tag) continue;
      if (r->ids[fn_[0]] != ids[v] && r->ids[fn_[1]] != ids[v]) continue;
      for (PetscInt k = 0; k < 3; ++k) {
        xf[2 * k]     = r->X[2 * fn_[k]];
        xf[2 * k + 1] = r->X[2 * fn_[k] + 1];
      }
      fn(ctx, v, xf, r->ids[fn_[0]] == ids[v] ? PETSC_TRUE : PETSC_FALSE);
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BodyRigidMapNodes(Body b, PetscInt nn, const PetscInt ids[], BodyNodeMap *map, PetscInt joined[])
{
  PetscFunctionBeginUser;
  (void)ids;
  PetscCall(PetscMalloc2(1, &map->node, 1, &map->off));
  map->n = 0;
  if (b->rg->dim == 3) {
    for (PetscInt j = 0; j < nn; ++j)
      for (PetscInt d = 0; d < 3; ++d) joined[3 * j + d] = ContactRigidDof3(j, d);
    PetscFunctionReturn(0);
  }
  for (PetscInt j = 0; j < nn; ++j)
    for (PetscInt d = 0; d < 2; ++d) joined[2 * j + d] = ContactRigidDof(j, d); /* through the body's motion (rigidbody.h) */
  PetscFunctionReturn(0);
}

PetscErrorCode BodyRigidNodeDisplacements(Body b, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, PetscReal u[])
{
  PetscFunctionBeginUser;
  (void)map;
  if (b->rg->dim == 3) {
    for (PetscInt v = 0; v < nn; ++v) Rigid3dDisplacement(b->rg, &X[3 * v], &u[3 * v]);
    PetscFunctionReturn(0);
  }
  for (PetscInt v = 0; v < nn; ++v) BodyRigidDisplacement(b, &X[2 * v], &u[2 * v]);
  PetscFunctionReturn(0);
}

PetscErrorCode BodyRigidAddNodeForces(Body b, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, const PetscReal g[])
{
  PetscFunctionBeginUser;
  (void)map;
  BodyRigidAddForce(b, nn, X, g);
  PetscFunctionReturn(0);
}

PetscErrorCode BodyRigidGetOutline(Body b, PetscInt *nn, PetscReal **x, PetscInt *ne, const PetscInt **enodes)
{
  const BodyRigid *r = b->rg;

  PetscFunctionBeginUser;
  *nn     = r->nn;
  *ne     = r->ne;
  *enodes = r->enodes;
  PetscCall(PetscMalloc1(2 * r->nn + 1, x));
  for (PetscInt i = 0; i < r->nn; ++i) {
    PetscReal u[2];
    BodyRigidDisplacement(b, &r->X[2 * i], u);
    (*x)[2 * i]     = r->X[2 * i] + u[0];
    (*x)[2 * i + 1] = r->X[2 * i + 1] + u[1];
  }
  PetscFunctionReturn(0);
}
