/* A body held by contact: one whose Dirichlet conditions leave a rigid motion
   free, in a contact pair of a scene that something loads (its own traction
   or pressure, or another body's load, displacement or force passed on
   through a contact: a roller between two races). Its energy has no minimum
   without the contact, and the contact holds it only once the bodies touch:
   from rest the stiffness is singular, and the Newton step's factorisations
   (of K alone, in the Schur step) need it regular.

   So the free rigid motions are anchored: at most two vertices, A and B, get
   Dirichlet components (the fewest of A_x, A_y, B_x, B_y that leave no rigid
   motion free), each force-controlled with force zero: their displacements
   are unknowns of coupled force control's one minimisation
   (forcecontrol.c). Every Newton step is then regular (the anchors hold
   the body where the contact does not yet), and at its end each anchor's
   reaction is zero (within what unheld.c allows where the contact cannot
   hold the motion, a roller's sliding): the anchors carry nothing, the body is
   held by the contact alone, and the answer is the free body's. A is the
   loaded vertex nearest the loaded vertices' centroid (the anchor carries the
   load until the contact takes it, so it sits where the load is), or for a
   body with no load of its own (a roller between two races, loaded through
   them) the vertex nearest the centre of its bounding box; B the vertex
   farthest from A (a lever arm against rotation); a component a Dirichlet
   condition holds at a vertex is not anchored there. A neohookean body is
   anchored alike: the anchors' border is its tangent's, made again with
   each Hessian (forcecontrol.c, ProblemUpdateControlBorder). */
#include "anchors.h"
#include "conditions.h"
#include "rigid.h"
#include "bodyimpl.h"

/* Whether vertex v is on an edge of a loaded group (faces: the mesh's
   "Face Sets", tags: the loaded groups' physical tags). */
static PetscErrorCode Loaded(Body b, DMLabel faces, const PetscInt tags[], PetscInt v, PetscBool *on)
{
  const PetscInt *supp;
  PetscInt        ns;

  PetscFunctionBeginUser;
  *on = PETSC_FALSE;
  PetscCall(DMPlexGetSupportSize(b->dm, v, &ns));
  PetscCall(DMPlexGetSupport(b->dm, v, &supp));
  for (PetscInt k = 0; k < ns && !*on; ++k) {
    PetscInt val;
    PetscCall(DMLabelGetValue(faces, supp[k], &val));
    for (PetscInt l = 0; l < b->nload && val >= 0; ++l)
      if (val == tags[l]) *on = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

/* The constraint Gram matrix of the body's Dirichlet conditions (over every
   rank) at this rank's vertices vs, vs + 1, ... at xy[n][2], in coordinates
   centred at c and scaled by L. */
static PetscErrorCode DirichletGram(Body b, PetscInt n, PetscInt vs, const PetscReal xy[], const PetscReal c[2], PetscReal L, PetscReal M[9])
{
  PetscReal Ml[9] = {0};

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < n; ++k)
    for (PetscInt i = 0; i < b->nbc; ++i) {
      PetscInt val;
      PetscCall(DMLabelGetValue(b->bc[i].label, vs + k, &val));
      if (val != 1) continue;
      for (PetscInt j = 0; j < b->bc[i].ncomp; ++j) BodyRigidGramAddRow(Ml, b->bc[i].comps[j], (xy[2 * k] - c[0]) / L, (xy[2 * k + 1] - c[1]) / L);
    }
  PetscCall(MPIU_Allreduce(Ml, M, 9, MPIU_REAL, MPIU_SUM, b->comm));
  BodyRigidGramAxisymmetric(b, M);
  PetscFunctionReturn(0);
}

/* A Dirichlet condition on the one vertex at (x, y) (on every rank that has
   it), components comps, force-controlled with force zero. */
static PetscErrorCode AddAnchor(Body b, const char name[], PetscInt n, PetscInt vs, const PetscReal xy[], const PetscReal at[2], PetscInt ncomp, const PetscInt comps[])
{
  BodyBC bc = {.ncomp = ncomp, .anchor = PETSC_TRUE};

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(bc.group, name, sizeof(bc.group)));
  for (PetscInt j = 0; j < ncomp; ++j) {
    bc.comps[j]   = comps[j];
    bc.control[j] = PETSC_TRUE; /* force 0 */
  }
  PetscCall(DMCreateLabel(b->dm, name));
  PetscCall(DMGetLabel(b->dm, name, &bc.label));
  for (PetscInt k = 0; k < n; ++k)
    if (xy[2 * k] == at[0] && xy[2 * k + 1] == at[1]) PetscCall(DMLabelSetValue(bc.label, vs + k, 1));
  PetscCall(BodyAddDirichlet(b, &bc));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyAddAnchors(Body b)
{
  PetscInt   n, vs, ve, rank0, nA = 0, nB = 0, cA[2], cB[2];
  PetscReal *xy = NULL, lo[2], hi[2], c[2], L;
  PetscReal  M[9], A[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, B[3] = {-1.0, 0.0, 0.0};

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(b->dm, 0, &vs, &ve));
  n = ve - vs;
  PetscCall(BodyCheckSecondOrder(b));
  PetscCall(BodyVertexCoordinates(b, &xy));
  PetscCall(BodyPointsBox(b, n, xy, lo, hi));
  c[0] = 0.5 * (lo[0] + hi[0]);
  c[1] = 0.5 * (lo[1] + hi[1]);
  L    = PetscMax(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(L > 0)) L = 1.0;
  PetscCall(DirichletGram(b, n, vs, xy, c, L, M));
  rank0 = BodyRigidRank(M);
  if (rank0 == 3) {
    PetscCall(PetscFree(xy));
    PetscFunctionReturn(0);
  }
  { /* A: the loaded vertex nearest the loaded vertices' centroid (least (x, y) on a tie) */
    PetscReal m[3] = {0, 0, 0}, dbest = PETSC_MAX_REAL, dmin;
    PetscBool *on;
    PetscInt   tags[CONTACT_MAX_BC];
    DMLabel    faces;
    PetscCall(DMGetLabel(b->dm, "Face Sets", &faces));
    for (PetscInt l = 0; l < b->nload; ++l) PetscCall(BodyGetPhysicalTag(b, b->load[l].group, 1, &tags[l]));
    PetscCall(PetscCalloc1(n + 1, &on));
    for (PetscInt k = 0; k < n && faces; ++k) {
      PetscCall(Loaded(b, faces, tags, vs + k, &on[k]));
      if (!on[k]) continue;
      m[0] += xy[2 * k];
      m[1] += xy[2 * k + 1];
      m[2] += 1;
    }
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, m, 3, MPIU_REAL, MPIU_SUM, b->comm)); /* a vertex shared by ranks counts twice: the centroid moves, not the choice's rule */
    if (!(m[2] > 0)) { /* no load of its own: the vertex nearest its box's centre (the same on every partition) */
      m[0] = c[0];
      m[1] = c[1];
      m[2] = 1;
      for (PetscInt k = 0; k < n; ++k) on[k] = PETSC_TRUE;
    }
    for (PetscInt k = 0; k < n; ++k) {
      const PetscReal d = PetscSqr(xy[2 * k] - m[0] / m[2]) + PetscSqr(xy[2 * k + 1] - m[1] / m[2]);
      if (!on[k]) continue;
      if (d < dbest || (d == dbest && (xy[2 * k] < A[0] || (xy[2 * k] == A[0] && xy[2 * k + 1] < A[1])))) {
        dbest = d;
        A[0]  = xy[2 * k];
        A[1]  = xy[2 * k + 1];
      }
    }
    PetscCall(PetscFree(on));
    PetscCall(MPIU_Allreduce(&dbest, &dmin, 1, MPIU_REAL, MPIU_MIN, b->comm));
    if (dbest > dmin) A[0] = A[1] = PETSC_MAX_REAL;
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, A, 2, MPIU_REAL, MPIU_MIN, b->comm)); /* every rank: the nearest, wherever it lies */
  }
  PetscCheck(A[0] < PETSC_MAX_REAL, b->comm, PETSC_ERR_USER_INPUT, "body %s: every vertex is in a Dirichlet group, yet a rigid motion is free", b->name);
  for (PetscInt k = 0; k < n; ++k) { /* B: the vertex farthest from A */
    const PetscReal d = PetscSqr(xy[2 * k] - A[0]) + PetscSqr(xy[2 * k + 1] - A[1]);
    if (d > B[0] || (d == B[0] && (xy[2 * k] < B[1] || (xy[2 * k] == B[1] && xy[2 * k + 1] < B[2])))) {
      B[0] = d;
      B[1] = xy[2 * k];
      B[2] = xy[2 * k + 1];
    }
  }
  {
    PetscReal dmax;
    PetscCall(MPIU_Allreduce(&B[0], &dmax, 1, MPIU_REAL, MPIU_MAX, b->comm));
    if (B[0] < dmax) B[1] = B[2] = PETSC_MAX_REAL;
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &B[1], 2, MPIU_REAL, MPIU_MIN, b->comm));
  }
  /* the fewest components, A's first, that fix every rigid motion */
  for (PetscInt j = 0; j < 4 && BodyRigidRank(M) < 3; ++j) {
    const PetscReal *at = j < 2 ? A : &B[1];
    PetscReal        T[9], held = 0;
    for (PetscInt k = 0; k < n; ++k) /* a component a Dirichlet condition holds there is not an anchor's */
      if (xy[2 * k] == at[0] && xy[2 * k + 1] == at[1]) {
        PetscInt i, l;
        PetscCall(BodyBCHolding(b, vs + k, j % 2, &i, &l));
        if (i >= 0) held = 1;
      }
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &held, 1, MPIU_REAL, MPIU_MAX, b->comm));
    if (held > 0) continue;
    PetscCall(PetscArraycpy(T, M, 9));
    BodyRigidGramAddRow(T, j % 2, (at[0] - c[0]) / L, (at[1] - c[1]) / L);
    if (BodyRigidRank(T) == BodyRigidRank(M)) continue;
    PetscCall(PetscArraycpy(M, T, 9));
    if (j < 2) cA[nA++] = j % 2;
    else cB[nB++] = j % 2;
  }
  if (nA) PetscCall(AddAnchor(b, "anchor_a", n, vs, xy, A, nA, cA));
  if (nB) PetscCall(AddAnchor(b, "anchor_b", n, vs, xy, &B[1], nB, cB));
  PetscCall(PetscInfo(NULL, "body %s: held by contact: %" PetscInt_FMT " rigid motion(s) anchored at (%g, %g)%s\n", b->name, 3 - rank0, (double)A[0], (double)A[1], nB ? " and its farthest vertex" : ""));
  PetscCall(PetscFree(xy));
  PetscFunctionReturn(0);
}
