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
  PetscReal *u;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(3 * S->nn, &u));
  PetscCall(BodyGetNodeDisplacements(b, S->nn, S->X, &S->map, u));
  *changed = PETSC_FALSE;
  for (PetscInt k = 0; k < 3 * S->nn; ++k) {
    const PetscReal x = S->X[k] + u[k];
    if (x != S->x[k]) *changed = PETSC_TRUE;
    S->x[k] = x;
  }
  PetscCall(PetscFree(u));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactSurface3dAddGradient(ContactSurface3d *S, Body b)
{
  PetscFunctionBeginUser;
  PetscCall(MPIU_Allreduce(S->g, S->gsum, 3 * S->nn, MPIU_REAL, MPIU_SUM, BodyGetComm(b)));
  PetscCall(BodyAddNodeForces(b, S->nn, S->X, &S->map, S->gsum));
  PetscFunctionReturn(0);
}
