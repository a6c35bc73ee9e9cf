/* A 3D elastic body's boundary faces of a physical surface, as a 3D contact
   surface sees them (surface3d.c); the surface's nodes are then mapped, and
   their displacements and forces exchanged, by boundary.c's functions of
   any dimension (BodyMapNodes, BodyGetNodeDisplacements, BodyAddNodeForces).

   A face point of the DMPlex (depth 2) has edges for its cone and vertices
   below them. Its corners are put in a cycle by walking its edges (each
   shares a vertex with the next), without reading the cone's orientations;
   the mid-edge node of corners k, k+1 is the edge between them, and a
   Quad9's centre is the face point itself (Tet10: P2, the nodes are the
   vertices and edges; Hex27: Q2, the faces and cells carry a node too).
   The cycle is turned so that the corners' right hand points away from the
   cell on the face (the centroid of the cell's nodes): the outward normal
   of face3d.h. The node points' reference coordinates are the body's
   (xpoint), the same bits on every rank. Each face is given by the rank
   that owns its face point, so that the ranks' faces together are the
   group's, each once. */
#include "bodyfaces.h"
#include "bodyimpl.h"

/* The corners v[nc] and mid-edge points e[nc] (e[k] between v[k] and
   v[k + 1]) of face f in a cycle. */
static PetscErrorCode FaceCycle(Body b, PetscInt f, PetscInt *nc, PetscInt v[4], PetscInt e[4])
{
  const PetscInt *cone;
  PetscInt        n, used[4] = {0, 0, 0, 0};

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetConeSize(b->dm, f, &n));
  PetscCheck(n == 3 || n == 4, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: a face with %" PetscInt_FMT " edges (3D contact needs Tet10 or Hex27 cells)", b->name, n);
  PetscCall(DMPlexGetCone(b->dm, f, &cone));
  {
    const PetscInt *ev;
    PetscCall(DMPlexGetCone(b->dm, cone[0], &ev));
    v[0]    = ev[0];
    v[1]    = ev[1];
    e[0]    = cone[0];
    used[0] = 1;
  }
  for (PetscInt k = 1; k < n; ++k) { /* the unused edge through v[k] */
    PetscBool found = PETSC_FALSE;
    for (PetscInt j = 0; j < n && !found; ++j) {
      const PetscInt *ev;
      if (used[j]) continue;
      PetscCall(DMPlexGetCone(b->dm, cone[j], &ev));
      if (ev[0] != v[k] && ev[1] != v[k]) continue;
      e[k]    = cone[j];
      used[j] = 1;
      if (k + 1 < n) v[k + 1] = ev[0] == v[k] ? ev[1] : ev[0];
      found = PETSC_TRUE;
    }
    PetscCheck(found, PETSC_COMM_SELF, PETSC_ERR_PLIB, "body %s: the edges of face %" PetscInt_FMT " do not close", b->name, f);
  }
  *nc = n;
  PetscFunctionReturn(0);
}

/* The centroid of the nodes of the cell on face f. */
static PetscErrorCode FaceCellCentroid(Body b, PetscSection s, PetscInt f, const char what[], const char group[], PetscReal xc[3])
{
  const PetscInt *supp;
  PetscInt        nsupp, *cl = NULL, ncl;
  PetscReal       cnt = 0;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetSupportSize(b->dm, f, &nsupp));
  PetscCall(DMPlexGetSupport(b->dm, f, &supp));
  PetscCheck(nsupp == 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: a face of group '%s' of body %s is not on the boundary", what, group, b->name);
  xc[0] = xc[1] = xc[2] = 0.0;
  PetscCall(DMPlexGetTransitiveClosure(b->dm, supp[0], PETSC_TRUE, &ncl, &cl));
  for (PetscInt j = 0; j < ncl; ++j) {
    PetscInt dof;
    PetscCall(PetscSectionGetDof(s, cl[2 * j], &dof));
    if (!dof) continue;
    for (PetscInt d = 0; d < 3; ++d) xc[d] += b->xpoint[3 * (cl[2 * j] - b->pStart) + d];
    cnt += 1;
  }
  PetscCall(DMPlexRestoreTransitiveClosure(b->dm, supp[0], PETSC_TRUE, &ncl, &cl));
  for (PetscInt d = 0; d < 3; ++d) xc[d] /= cnt;
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGetGroupFaces(Body b, const char group[], const char what[], PetscInt *tag, BodyFaces *F)
{
  DMLabel         labels;
  IS              is = NULL;
  PetscSection    s;
  PetscInt        np = 0, k = 0, nb = 0, gnb;
  const PetscInt *pts = NULL;

  PetscFunctionBeginUser;
  if (b->rigid && b->dim == 3) { /* a rigid 3D body's faces (rigid3d.c) */
    PetscCall(Rigid3dGroupFaces(b, group, tag, F));
    PetscFunctionReturn(0);
  }
  PetscCheck(BodyHasCells(b) && b->dim == 3, b->comm, PETSC_ERR_USER_INPUT, "%s: body %s is not a 3D body: its surface '%s' has no faces", what, b->name, group);
  PetscCall(PetscMemzero(F, sizeof(*F)));
  PetscCall(BodyGetPhysicalTag(b, group, 2, tag));
  PetscCall(DMGetLocalSection(b->dm, &s));
  PetscCall(DMGetLabel(b->dm, "Face Sets", &labels));
  if (labels) PetscCall(DMLabelGetStratumIS(labels, *tag, &is));
  if (is) {
    PetscCall(ISGetLocalSize(is, &np));
    PetscCall(ISGetIndices(is, &pts));
  }
  nb = b->simplex ? 6 : 9;
  PetscCall(MPIU_Allreduce(&nb, &gnb, 1, MPIU_INT, MPI_MAX, b->comm));
  PetscCall(PetscMalloc5(nb * np + 1, &F->point, nb * np + 1, &F->id, nb * np + 1, &F->off, 3 * nb * np + 1, &F->joined, 3 * nb * np + 1, &F->X));
  for (PetscInt i = 0; i < np; ++i) {
    const PetscInt f = pts[i];
    PetscInt       nc = 0, v[4] = {0, 0, 0, 0}, e[4] = {0, 0, 0, 0}, *P = &F->point[nb * k];
    PetscReal      xc[3], a[3], c[3], nrm[3], xf[3] = {0, 0, 0};

    if (!b->owned[f - b->pStart]) continue;
    PetscCall(FaceCycle(b, f, &nc, v, e));
    PetscCheck(nc == (nb == 6 ? 3 : 4), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: face %" PetscInt_FMT " of group '%s' of body %s has %" PetscInt_FMT " corners, its cells' faces %d", what, f, group, b->name, nc, nb == 6 ? 3 : 4);
    PetscCall(FaceCellCentroid(b, s, f, what, group, xc));
    for (PetscInt d = 0; d < 3; ++d) { /* the corners' right hand: (v1 - v0) x (v2 - v0) a triangle's, (v2 - v0) x (v3 - v1) a quadrilateral's */
      const PetscReal *x0 = &b->xpoint[3 * (v[0] - b->pStart)], *x1 = &b->xpoint[3 * (v[1] - b->pStart)], *x2 = &b->xpoint[3 * (v[2] - b->pStart)];
      a[d] = nc == 3 ? x1[d] - x0[d] : x2[d] - x0[d];
      c[d] = nc == 3 ? x2[d] - x0[d] : b->xpoint[3 * (v[3] - b->pStart) + d] - x1[d];
      for (PetscInt j = 0; j < nc; ++j) xf[d] += b->xpoint[3 * (v[j] - b->pStart) + d] / nc;
    }
    nrm[0] = a[1] * c[2] - a[2] * c[1];
    nrm[1] = a[2] * c[0] - a[0] * c[2];
    nrm[2] = a[0] * c[1] - a[1] * c[0];
    if (nrm[0] * (xf[0] - xc[0]) + nrm[1] * (xf[1] - xc[1]) + nrm[2] * (xf[2] - xc[2]) < 0) { /* turn the cycle: v0, v_{n-1}, ..., v1 */
      PetscInt vr[4], er[4];
      for (PetscInt j = 0; j < nc; ++j) {
        vr[j] = v[(nc - j) % nc];
        er[j] = e[nc - 1 - j];
      }
      for (PetscInt j = 0; j < nc; ++j) {
        v[j] = vr[j];
        e[j] = er[j];
      }
    }
    for (PetscInt j = 0; j < nc; ++j) {
      P[j]      = v[j];
      P[nc + j] = e[j];
    }
    if (nb == 9) P[8] = f;
    for (PetscInt j = 0; j < nb; ++j) {
      PetscInt dof, off;
      PetscCall(PetscSectionGetDof(s, P[j], &dof));
      PetscCheck(dof == 3, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: a node of face %" PetscInt_FMT " of group '%s' of body %s has %" PetscInt_FMT " dofs, not 3", what, f, group, b->name, dof);
      PetscCall(PetscSectionGetOffset(s, P[j], &off));
      PetscCall(BodyGetNodeNumber(b, P[j], &F->id[nb * k + j]));
      F->off[nb * k + j] = off;
      for (PetscInt d = 0; d < 3; ++d) {
        F->joined[3 * (nb * k + j) + d] = b->l2b[off + d];
        F->X[3 * (nb * k + j) + d]      = b->xpoint[3 * (P[j] - b->pStart) + d];
      }
    }
    k++;
  }
  F->n  = k;
  F->nb = nb;
  if (is) {
    PetscCall(ISRestoreIndices(is, &pts));
    PetscCall(ISDestroy(&is));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BodyFacesDestroy(BodyFaces *F)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree5(F->point, F->id, F->off, F->joined, F->X));
  F->n = 0;
  PetscFunctionReturn(0);
}
