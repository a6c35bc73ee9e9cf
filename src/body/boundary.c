/* An elastic body's boundary as a contact surface sees it (surface.c): a
   group's boundary edges held by this rank's owned points, with their
   nodes' global numbers, reference coordinates and outward side (away from
   the cell on them); the boundary edges that continue the surface past its
   ends (DMPlexMarkBoundaryFaces: the body's boundary, not the partition's);
   the surface nodes among the owned points with their offsets in the local
   vector and indices in the joined one; their displacements gathered from
   the local vector, and the contact's gradient added into the local
   gradient (dim components a node: a 3D body's surfaces too, bodyfaces.c). The dispatchers of the table (bodyimpl.h) are here too:
   rigidsurface.c is the rigid body's side of each. */
#include "body.h"
#include "bodyimpl.h"

PetscErrorCode BodyGetGroupEdges(Body b, const char group[], const char what[], PetscInt *tag, PetscInt *n, PetscInt **eid, PetscReal **erl)
{
  PetscFunctionBeginUser;
  PetscCall(b->ops.groupedges(b, group, what, tag, n, eid, erl));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyBoundaryEdgesAt(Body b, PetscInt tag, PetscInt nn, const PetscInt ids[], const PetscBool end[], BodyEdgeFn fn, void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(b->ops.boundaryedgesat(b, tag, nn, ids, end, fn, ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyMapNodes(Body b, PetscInt nn, const PetscInt ids[], BodyNodeMap *map, PetscInt joined[])
{
  PetscFunctionBeginUser;
  PetscCall(b->ops.mapnodes(b, nn, ids, map, joined));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyNodeMapDestroy(BodyNodeMap *map)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(map->node, map->off));
  map->n = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGetNodeDisplacements(Body b, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, PetscReal u[])
{
  PetscFunctionBeginUser;
  PetscCall(b->ops.nodedisplacements(b, nn, X, map, u));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyUpdateNodeCoordinates(Body b, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, PetscReal x[], PetscBool *changed)
{
  const PetscInt n = b->dim * nn;
  PetscReal     *u;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n, &u));
  PetscCall(BodyGetNodeDisplacements(b, nn, X, map, u));
  *changed = PETSC_FALSE;
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal xk = X[k] + u[k];
    if (xk != x[k]) *changed = PETSC_TRUE;
    x[k] = xk;
  }
  PetscCall(PetscFree(u));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyAddNodeForces(Body b, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, const PetscReal g[])
{
  PetscFunctionBeginUser;
  PetscCall(b->ops.addnodeforces(b, nn, X, map, g));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyAddSurfaceHessian(Body b, const PetscReal x[], PetscInt n, const PetscInt idx[], const PetscScalar K[])
{
  PetscFunctionBeginUser;
  if (b->ops.addsurfacehessian) PetscCall(b->ops.addsurfacehessian(b, x, n, idx, K));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGetGroupEdges_Elastic(Body b, const char group[], const char what[], PetscInt *tag, PetscInt *n, PetscInt **eid, PetscReal **erl)
{
  DMLabel         faces;
  IS              is = NULL;
  PetscInt        np = 0, k = 0;
  const PetscInt *pts = NULL;

  PetscFunctionBeginUser;
  PetscCall(BodyGetPhysicalTag(b, group, 1, tag));
  PetscCall(DMGetLabel(b->dm, "Face Sets", &faces));
  if (faces) PetscCall(DMLabelGetStratumIS(faces, *tag, &is));
  if (is) {
    PetscCall(ISGetLocalSize(is, &np));
    PetscCall(ISGetIndices(is, &pts));
  }
  PetscCall(PetscMalloc2(3 * np + 1, eid, 7 * np + 1, erl));
  for (PetscInt i = 0; i < np; ++i) {
    const PetscInt e = pts[i];
    PetscInt       nodes[3];
    PetscReal     *x = &(*erl)[7 * k];

    if (!b->owned[e - b->pStart]) continue;
    PetscCall(BodyEdgeNodes(b, e, nodes, x));
    for (PetscInt j = 0; j < 3; ++j) PetscCall(BodyGetNodeNumber(b, nodes[j], &(*eid)[3 * k + j]));
    PetscCall(BodyEdgeOutwardSign(b, e, x, what, group, &x[6]));
    k++;
  }
  *n = k;
  if (is) {
    PetscCall(ISRestoreIndices(is, &pts));
    PetscCall(ISDestroy(&is));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BodyBoundaryEdgesAt_Elastic(Body b, PetscInt tag, PetscInt nn, const PetscInt ids[], const PetscBool end[], BodyEdgeFn fn, void *ctx)
{
  DMLabel  bnd, faces;
  PetscInt vStart, vEnd;

  PetscFunctionBeginUser;
  PetscCall(DMLabelCreate(PETSC_COMM_SELF, "boundary", &bnd));
  PetscCall(DMPlexMarkBoundaryFaces(b->dm, 1, bnd));
  PetscCall(DMGetLabel(b->dm, "Face Sets", &faces));
  PetscCall(DMPlexGetDepthStratum(b->dm, 0, &vStart, &vEnd));
  for (PetscInt pt = vStart; pt < vEnd; ++pt) {
    const PetscInt *supp;
    PetscInt        id, v, ns;
    PetscCall(BodyGetNodeNumber(b, pt, &id));
    PetscCall(PetscFindInt(id, nn, ids, &v));
    if (v < 0 || !end[v]) continue;
    PetscCall(DMPlexGetSupportSize(b->dm, pt, &ns));
    PetscCall(DMPlexGetSupport(b->dm, pt, &supp));
    for (PetscInt k = 0; k < ns; ++k) {
      PetscInt  val, nodes[3];
      PetscBool in = PETSC_FALSE;
      PetscReal xf[6];
      PetscCall(DMLabelGetValue(bnd, supp[k], &val));
      if (val != 1) continue;
      if (faces) PetscCall(DMLabelStratumHasPoint(faces, tag, supp[k], &in));
      if (in) continue;
      PetscCall(BodyEdgeNodes(b, supp[k], nodes, xf));
      fn(ctx, v, xf, nodes[0] == pt ? PETSC_TRUE : PETSC_FALSE);
    }
  }
  PetscCall(DMLabelDestroy(&bnd));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyMapNodes_Elastic(Body b, PetscInt nn, const PetscInt ids[], BodyNodeMap *map, PetscInt joined[])
{
  PetscSection s;
  PetscInt    *bigl, k = 0;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(b->dm, &s));
  PetscCall(PetscMalloc2(b->pEnd - b->pStart, &map->node, b->pEnd - b->pStart, &map->off));
  PetscCall(PetscMalloc1(b->dim * nn + 1, &bigl));
  for (PetscInt i = 0; i < b->dim * nn; ++i) bigl[i] = -2;
  for (PetscInt pt = b->pStart; pt < b->pEnd; ++pt) {
    PetscInt dof, id, loc, off;
    if (!b->owned[pt - b->pStart]) continue;
    PetscCall(PetscSectionGetDof(s, pt, &dof));
    if (!dof) continue;
    PetscCall(BodyGetNodeNumber(b, pt, &id));
    PetscCall(PetscFindInt(id, nn, ids, &loc));
    if (loc < 0) continue;
    PetscCall(PetscSectionGetOffset(s, pt, &off));
    map->node[k] = loc;
    map->off[k]  = off;
    for (PetscInt d = 0; d < b->dim; ++d) bigl[b->dim * loc + d] = b->l2b[off + d];
    k++;
  }
  map->n = k;
  PetscCall(MPIU_Allreduce(bigl, joined, b->dim * nn, MPIU_INT, MPI_MAX, b->comm));
  PetscCall(PetscFree(bigl));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGetNodeDisplacements_Elastic(Body b, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, PetscReal u[])
{
  const PetscScalar *xl;
  PetscReal         *du;

  PetscFunctionBeginUser;
  (void)X;
  PetscCall(PetscCalloc1(b->dim * nn + 1, &du));
  PetscCall(VecGetArrayRead(b->Xl, &xl));
  for (PetscInt k = 0; k < map->n; ++k)
    for (PetscInt d = 0; d < b->dim; ++d) du[b->dim * map->node[k] + d] = PetscRealPart(xl[map->off[k] + d]);
  PetscCall(VecRestoreArrayRead(b->Xl, &xl));
  PetscCall(MPIU_Allreduce(du, u, b->dim * nn, MPIU_REAL, MPIU_SUM, b->comm));
  PetscCall(PetscFree(du));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyAddNodeForces_Elastic(Body b, PetscInt nn, const PetscReal X[], const BodyNodeMap *map, const PetscReal g[])
{
  PetscScalar *gl;

  PetscFunctionBeginUser;
  (void)nn;
  (void)X;
  PetscCall(VecGetArray(b->Gl, &gl));
  for (PetscInt k = 0; k < map->n; ++k)
    for (PetscInt d = 0; d < b->dim; ++d) gl[map->off[k] + d] += g[b->dim * map->node[k] + d];
  PetscCall(VecRestoreArray(b->Gl, &gl));
  PetscFunctionReturn(0);
}
