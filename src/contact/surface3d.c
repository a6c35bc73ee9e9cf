/* A 3D contact surface: a physical surface's faces as the body gives them
   (BodyGetGroupFaces, src/body/faces.c), replicated on every rank, its
   nodes numbered (sorted unique global numbers), and the exchange of its
   coordinates and gradient with the body (BodyMapNodes,
   BodyGetNodeDisplacements, BodyAddNodeForces: three components a node).

   Parallel, as in 2D (surface.c): every rank holds the whole surface (its
   nodes, faces, current coordinates gathered at each evaluation, the same
   bits on every rank); the rank that gave a face integrates it as slave,
   and the gradient on the surface nodes is summed over ranks and added by
   the rank that owns each node. A surface is a part of its body's boundary,
   so this stays small beside the body (a quarter of the dofs of a cube of
   n^3 cells is on one face at n = 4, a 20th at n = 20); a surface whose
   size would matter is for a later, distributed one. */
#include "surface3d.h"

PetscErrorCode ContactSurface3dSetUp(ContactSurface3d *S, Body b, const char pair[])
{
  BodyFaces    F;
  char         what[2 * CONTACT_NAME_LEN];
  PetscMPIInt  size, rank, cntl, *cnt, *disp, *ci, *di, *cx, *dx;
  PetscInt    *allid, nall, *ids;
  PetscReal   *allx;
  MPI_Comm     comm = BodyGetComm(b);

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(what, sizeof(what), "contact pair %s", pair));
  PetscCall(BodyGetGroupFaces(b, S->group, what, &S->tag, &F));
  S->nb   = F.nb;
  S->type = F.nb == 6 ? FACE3D_TRI6 : FACE3D_QUAD9;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  cntl = (PetscMPIInt)F.n;
  PetscCall(PetscMalloc2(size, &cnt, size + 1, &disp));
  PetscCallMPI(MPI_Allgather(&cntl, 1, MPI_INT, cnt, 1, MPI_INT, comm));
  disp[0] = 0;
  for (PetscMPIInt r = 0; r < size; ++r) disp[r + 1] = disp[r] + cnt[r];
  S->nf = disp[size];
  PetscCheck(S->nf > 0, comm, PETSC_ERR_FILE_UNEXPECTED, "contact pair %s: surface '%s' of body %s has no faces", pair, S->group, BodyGetName(b));
  PetscCall(PetscMalloc4(size, &ci, size, &di, size, &cx, size, &dx));
  for (PetscMPIInt r = 0; r < size; ++r) {
    ci[r] = (PetscMPIInt)(S->nb * cnt[r]);
    di[r] = (PetscMPIInt)(S->nb * disp[r]);
    cx[r] = 3 * ci[r];
    dx[r] = 3 * di[r];
  }
  PetscCall(PetscMalloc2(S->nb * S->nf, &allid, 3 * S->nb * S->nf, &allx));
  PetscCallMPI(MPI_Allgatherv(F.id, (PetscMPIInt)(S->nb * F.n), MPIU_INT, allid, ci, di, MPIU_INT, comm));
  PetscCallMPI(MPI_Allgatherv(F.X, (PetscMPIInt)(3 * S->nb * F.n), MPIU_REAL, allx, cx, dx, MPIU_REAL, comm));
  PetscCall(PetscFree4(ci, di, cx, dx));
  PetscCall(BodyFacesDestroy(&F));
  nall = S->nb * S->nf;
  PetscCall(PetscMalloc1(nall, &ids));
  PetscCall(PetscArraycpy(ids, allid, nall));
  PetscCall(PetscSortRemoveDupsInt(&nall, ids));
  S->nn     = nall;
  S->nodeId = ids;
  PetscCall(PetscMalloc1(S->nb * S->nf, &S->fnodes));
  PetscCall(PetscMalloc5(3 * S->nn, &S->X, 3 * S->nn, &S->x, 3 * S->nn, &S->g, 3 * S->nn, &S->gsum, 3 * S->nn, &S->big));
  for (PetscInt k = 0; k < S->nb * S->nf; ++k) {
    PetscInt loc;
    PetscCall(PetscFindInt(allid[k], S->nn, S->nodeId, &loc));
    S->fnodes[k] = loc;
    for (PetscInt d = 0; d < 3; ++d) S->X[3 * loc + d] = allx[3 * k + d];
  }
  PetscCall(PetscFree2(allid, allx));
  S->nown = cnt[rank];
  PetscCall(PetscMalloc1(S->nown + 1, &S->ownFaces));
  for (PetscInt k = 0; k < S->nown; ++k) S->ownFaces[k] = disp[rank] + k;
  PetscCall(PetscFree2(cnt, disp));
  S->hmin = PETSC_MAX_REAL;
  S->hmax = 0.0;
  for (PetscInt f = 0; f < S->nf; ++f) {
    const PetscInt nc = S->nb == 6 ? 3 : 4;
    for (PetscInt j = 0; j < nc; ++j) {
      const PetscInt a = S->fnodes[S->nb * f + j], c = S->fnodes[S->nb * f + (j + 1) % nc];
      PetscReal      l = 0.0;
      for (PetscInt d = 0; d < 3; ++d) l += PetscSqr(S->X[3 * a + d] - S->X[3 * c + d]);
      l       = PetscSqrtReal(l);
      S->hmin = PetscMin(S->hmin, l);
      S->hmax = PetscMax(S->hmax, l);
    }
  }
  PetscCall(PetscArraycpy(S->x, S->X, 3 * S->nn));
  PetscCall(PetscArrayzero(S->g, 3 * S->nn));
  PetscCall(PetscArrayzero(S->gsum, 3 * S->nn));
  PetscCall(BodyMapNodes(b, S->nn, S->nodeId, &S->map, S->big));
  PetscCall(PetscInfo(NULL, "contact pair %s, surface '%s' of body %s: %" PetscInt_FMT " %s faces, %" PetscInt_FMT " nodes, %" PetscInt_FMT " faces on this rank\n", pair, S->group, BodyGetName(b), S->nf, S->nb == 6 ? "Tri6" : "Quad9", S->nn, S->nown));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactSurface3dDestroy(ContactSurface3d *S)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(S->fnodes));
  PetscCall(PetscFree(S->nodeId));
  PetscCall(PetscFree5(S->X, S->x, S->g, S->gsum, S->big));
  PetscCall(PetscFree(S->ownFaces));
  PetscCall(BodyNodeMapDestroy(&S->map));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactSurface3dUpdateCoordinates(ContactSurface3d *S, Body b, PetscBool *changed)
{
  PetscFunctionBeginUser;
  PetscCall(BodyUpdateNodeCoordinates(b, S->nn, S->X, &S->map, S->x, changed));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactSurface3dAddGradient(ContactSurface3d *S, Body b)
{
  PetscFunctionBeginUser;
  PetscCall(MPIU_Allreduce(S->g, S->gsum, 3 * S->nn, MPIU_REAL, MPIU_SUM, BodyGetComm(b)));
  PetscCall(BodyAddNodeForces(b, S->nn, S->X, &S->map, S->gsum));
  PetscFunctionReturn(0);
}

/* The nodes on the surface's border (bnd[nn]): those of the edges that
   one face alone has (an edge's mid node is on that edge alone, so it is
   on the border exactly when its edge is; a corner is where one of its
   edges is). */
PetscErrorCode ContactSurface3dBorderNodes(const ContactSurface3d *S, PetscBool **bnd)
{
  const PetscInt nc = S->nb == 6 ? 3 : 4;
  PetscInt      *cnt;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(S->nn, bnd));
  PetscCall(PetscCalloc1(S->nn, &cnt));
  for (PetscInt f = 0; f < S->nf; ++f)
    for (PetscInt e = 0; e < nc; ++e) cnt[S->fnodes[S->nb * f + nc + e]]++;
  for (PetscInt f = 0; f < S->nf; ++f)
    for (PetscInt e = 0; e < nc; ++e) {
      const PetscInt *fn = &S->fnodes[S->nb * f];
      if (cnt[fn[nc + e]] != 1) continue;
      (*bnd)[fn[nc + e]] = (*bnd)[fn[e]] = (*bnd)[fn[(e + 1) % nc]] = PETSC_TRUE;
    }
  PetscCall(PetscFree(cnt));
  PetscFunctionReturn(0);
}

/* The closest point y of surface B to p (reference coordinates), over the
   faces whose box (box[6 f]) is nearer than the best so far; its distance. */
static PetscReal Surface3dClosest(const ContactSurface3d *B, const PetscReal box[], const PetscReal p[3], PetscReal y[3])
{
  PetscReal best = PETSC_MAX_REAL, xf[3 * FACE3D_MAX_NODES];

  for (PetscInt f = 0; f < B->nf; ++f) {
    const PetscReal *b = &box[6 * f];
    PetscReal        eta[2] = {B->type == FACE3D_TRI6 ? 1.0 / 3.0 : 0.0, B->type == FACE3D_TRI6 ? 1.0 / 3.0 : 0.0}, z[3], d2 = 0.0;
    PetscBool        clamped;
    for (PetscInt d = 0; d < 3; ++d) d2 += PetscSqr(PetscMax(0.0, PetscMax(b[d] - p[d], p[d] - b[3 + d])));
    if (d2 >= best) continue;
    d2 = 0.0;
    ContactSurface3dFaceCoords(B, f, B->X, xf);
    Face3dClosestPointOnFace(B->type, xf, p, 0.0, eta, &clamped);
    Face3dEval(B->type, xf, eta, z, NULL, NULL);
    for (PetscInt d = 0; d < 3; ++d) d2 += PetscSqr(z[d] - p[d]);
    if (d2 < best) {
      best = d2;
      for (PetscInt d = 0; d < 3; ++d) y[d] = z[d];
    }
  }
  return PetscSqrtReal(best);
}

/* Whether surface A ends on surface B, as 2D's rule has it (mortar.c,
   MortarEndsOn), in the reference configuration: a node of A's border
   (bndA, ContactSurface3dBorderNodes) as near B as A comes anywhere
   (within tol of the least distance of A's nodes to B: a punch's face,
   flat on the block, all of it), its closest point inside B, farther than
   half B's longest face chord from every node of B's border (bndB). Two
   surfaces that end flush, or that the same symmetry plane cuts, do not end
   on each other (a curved face's closest point to a point on the cut may
   lie a little inside it), nor does a block's surface whose border lies
   under a ball's cap that touches it at one point. */
PetscErrorCode ContactSurface3dEndsOn(const ContactSurface3d *A, const PetscBool bndA[], const ContactSurface3d *B, const PetscBool bndB[], PetscReal tol, PetscBool *ends)
{
  PetscReal *box, *dist, *yb, gmin = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  *ends = PETSC_FALSE;
  PetscCall(PetscMalloc3(6 * B->nf, &box, A->nn, &dist, 3 * A->nn, &yb));
  for (PetscInt f = 0; f < B->nf; ++f) {
    PetscReal xf[3 * FACE3D_MAX_NODES];
    ContactSurface3dFaceCoords(B, f, B->X, xf);
    Face3dBox(B->type, xf, &box[6 * f]);
  }
  for (PetscInt v = 0; v < A->nn; ++v) {
    dist[v] = Surface3dClosest(B, box, &A->X[3 * v], &yb[3 * v]);
    gmin    = PetscMin(gmin, dist[v]);
  }
  for (PetscInt v = 0; v < A->nn && !*ends; ++v) {
    PetscReal near = PETSC_MAX_REAL;
    if (!bndA[v] || dist[v] > gmin + tol) continue;
    for (PetscInt w = 0; w < B->nn; ++w) {
      PetscReal d2 = 0.0;
      if (!bndB[w]) continue;
      for (PetscInt d = 0; d < 3; ++d) d2 += PetscSqr(B->X[3 * w + d] - yb[3 * v + d]);
      near = PetscMin(near, d2);
    }
    if (PetscSqrtReal(near) <= 0.5 * B->hmax) continue; /* at or past B's border */
    *ends = PETSC_TRUE;
  }
  PetscCall(PetscFree3(box, dist, yb));
  PetscFunctionReturn(0);
}
