/* A contact surface: a physical curve's edges as the body gives them
   (BodyGetGroupEdges: an elastic body's from its DMPlex, a rigid body's from
   its lines), replication on every rank, node numbering, the walk that gives
   the arc position, and the exchange of the surface's coordinates and
   gradient with the body (BodyGetNodeDisplacements, BodyAddNodeForces).

   Parallel. Surfaces are curves, small beside the bodies: every rank holds
   the whole surface (nodes, edges, current coordinates gathered at each
   evaluation); the rank that owns an edge integrates it as slave, and the
   gradient on the surface nodes is summed over ranks and added by the rank
   that owns each node. Since every rank holds every edge, a formulation may
   instead share the edges out by ContactSurfaceSplitEdges: runs of the walk
   of nearly equal weight, whatever the mesh partition (the cells along a
   surface seldom split evenly: 40 and 100 of the reference disc's 140 edges
   at h = 0.015 on 2 ranks). */
#include "surface.h"
#include "edge.h"

static PetscBool NodeBefore(const ContactSurface *S, PetscInt a, PetscInt b)
{
  const PetscReal tol = 1e-9 * (PetscAbsReal(S->X[2 * a]) + PetscAbsReal(S->X[2 * b]) + 1.0);

  if (PetscAbsReal(S->X[2 * a] - S->X[2 * b]) > tol) return S->X[2 * a] < S->X[2 * b] ? PETSC_TRUE : PETSC_FALSE;
  return S->X[2 * a + 1] < S->X[2 * b + 1] ? PETSC_TRUE : PETSC_FALSE;
}

/* Every rank's edges (BodyGetGroupEdges) gathered on every rank (in rank order): the
   surface's nodes (sorted unique global numbers), their reference
   coordinates, each edge's nodes and sign, and which edges are this rank's. */
static PetscErrorCode ContactSurfaceGatherEdges(ContactSurface *S, Body b, const char pair[], PetscInt n, const PetscInt eid[], const PetscReal erl[])
{
  PetscMPIInt  size, rank, *cnt, *disp, cntl = (PetscMPIInt)n, *c3, *d3, *c7, *d7;
  PetscInt    *alle, nall, *ids;
  PetscReal   *allr;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(BodyGetComm(b), &size));
  PetscCallMPI(MPI_Comm_rank(BodyGetComm(b), &rank));
  PetscCall(PetscMalloc2(size, &cnt, size + 1, &disp));
  PetscCallMPI(MPI_Allgather(&cntl, 1, MPI_INT, cnt, 1, MPI_INT, BodyGetComm(b)));
  disp[0] = 0;
  for (PetscMPIInt r = 0; r < size; ++r) disp[r + 1] = disp[r] + cnt[r];
  S->ne = disp[size];
  PetscCheck(S->ne > 0, BodyGetComm(b), PETSC_ERR_FILE_UNEXPECTED, "contact pair %s: surface '%s' of body %s has no edges", pair, S->group, BodyGetName(b));
  PetscCall(PetscMalloc4(size, &c3, size, &d3, size, &c7, size, &d7));
  for (PetscMPIInt r = 0; r < size; ++r) {
    c3[r] = 3 * cnt[r];
    d3[r] = 3 * disp[r];
    c7[r] = 7 * cnt[r];
    d7[r] = 7 * disp[r];
  }
  PetscCall(PetscMalloc2(3 * S->ne, &alle, 7 * S->ne, &allr));
  PetscCallMPI(MPI_Allgatherv(eid, 3 * cntl, MPIU_INT, alle, c3, d3, MPIU_INT, BodyGetComm(b)));
  PetscCallMPI(MPI_Allgatherv(erl, 7 * cntl, MPIU_REAL, allr, c7, d7, MPIU_REAL, BodyGetComm(b)));
  PetscCall(PetscFree4(c3, d3, c7, d7));
  /* surface nodes: sorted unique global numbers */
  nall = 3 * S->ne;
  PetscCall(PetscMalloc1(nall, &ids));
  PetscCall(PetscArraycpy(ids, alle, nall));
  PetscCall(PetscSortRemoveDupsInt(&nall, ids));
  S->nn     = nall;
  S->nodeId = ids;
  PetscCall(PetscMalloc3(3 * S->ne, &S->enodes, S->ne, &S->esign, S->ne, &S->s0));
  PetscCall(PetscMalloc2(S->ne, &S->edir, S->ne, &S->elen));
  PetscCall(PetscMalloc4(2 * S->nn, &S->X, 2 * S->nn, &S->x, 2 * S->nn, &S->g, 2 * S->nn, &S->big));
  PetscCall(PetscCalloc1(S->nn, &S->endNode));
  for (PetscInt e = 0; e < S->ne; ++e) {
    for (PetscInt j = 0; j < 3; ++j) {
      PetscInt loc;
      PetscCall(PetscFindInt(alle[3 * e + j], S->nn, S->nodeId, &loc));
      S->enodes[3 * e + j] = loc;
      S->X[2 * loc]        = allr[7 * e + 2 * j];
      S->X[2 * loc + 1]    = allr[7 * e + 2 * j + 1];
    }
    S->esign[e] = allr[7 * e + 6];
  }
  PetscCall(PetscMalloc1(n + 1, &S->ownEdges));
  S->nown = n;
  for (PetscInt k = 0; k < n; ++k) S->ownEdges[k] = disp[rank] + k;
  PetscCall(PetscInfo(NULL, "contact pair %s, surface '%s' of body %s: %" PetscInt_FMT " edges, %" PetscInt_FMT " in this rank's cells\n", pair, S->group, BodyGetName(b), S->ne, n));
  PetscCall(PetscFree2(alle, allr));
  PetscCall(PetscFree2(cnt, disp));
  PetscCall(PetscArraycpy(S->x, S->X, 2 * S->nn));
  PetscFunctionReturn(0);
}

/* Each edge's reference length (8-point Gauss), each node's degree (an end
   node has one edge) and the edges at each node (adj[adjStart[v] ..
   adjStart[v + 1]]; PetscFree the three). */
static PetscErrorCode ContactSurfaceAdjacency(ContactSurface *S, PetscInt **degree, PetscInt **adjacent, PetscInt **adjacentStart)
{
  PetscInt *deg, *adj, *adjStart;
  PetscReal gx[8], gw[8];

  PetscFunctionBeginUser;
  PetscCall(PetscDTGaussQuadrature(8, -1.0, 1.0, gx, gw));
  PetscCall(PetscCalloc2(S->nn, &deg, S->nn + 1, &adjStart));
  for (PetscInt e = 0; e < S->ne; ++e) {
    deg[S->enodes[3 * e]]++;
    deg[S->enodes[3 * e + 1]]++;
    S->elen[e] = 0.0;
    for (PetscInt q = 0; q < 8; ++q) {
      PetscReal pq[2], t[2];
      EdgeEval(S->X, &S->enodes[3 * e], gx[q], pq, t);
      S->elen[e] += gw[q] * PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
    }
  }
  for (PetscInt v = 0; v < S->nn; ++v) {
    adjStart[v + 1] = adjStart[v] + deg[v];
    S->endNode[v]   = deg[v] == 1 ? PETSC_TRUE : PETSC_FALSE;
    deg[v]          = 0;
  }
  PetscCall(PetscMalloc1(adjStart[S->nn] + 1, &adj));
  for (PetscInt e = 0; e < S->ne; ++e)
    for (PetscInt j = 0; j < 2; ++j) {
      const PetscInt v = S->enodes[3 * e + j];
      adj[adjStart[v] + deg[v]++] = e;
    }
  *degree        = deg;
  *adjacent      = adj;
  *adjacentStart = adjStart;
  PetscFunctionReturn(0);
}

/* The walk over the surface's chains that gives each edge its direction
   (edir) and the arc position where the walk enters it (s0). */
static PetscErrorCode ContactSurfaceWalk(ContactSurface *S, const PetscInt adj[], const PetscInt adjStart[])
{
  PetscBool *done;
  PetscReal  s0    = 0.0;
  PetscInt   nwalk = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(S->ne, &done));
  PetscCall(PetscMalloc1(S->ne, &S->walk));
  for (;;) {
    PetscInt start = -1, v, e = -1;
    /* start a chain at the unwalked end node of smallest (x, then y)
       reference coordinate, so that the walk does not depend on the
       partition; else at any unwalked edge */
    for (PetscInt k = 0; k < S->ne; ++k) {
      if (done[k]) continue;
      for (PetscInt j = 0; j < 2; ++j) {
        const PetscInt w = S->enodes[3 * k + j];
        if (S->endNode[w] && (start < 0 || NodeBefore(S, w, start))) {
          start = w;
          e     = k;
        }
      }
    }
    for (PetscInt k = 0; k < S->ne && start < 0; ++k)
      if (!done[k]) {
        start = S->enodes[3 * k] < S->enodes[3 * k + 1] ? S->enodes[3 * k] : S->enodes[3 * k + 1];
        e     = k;
      }
    if (start < 0) break;
    v = start;
    while (e >= 0) {
      PetscInt next = -1;
      done[e]          = PETSC_TRUE;
      S->walk[nwalk++] = e;
      S->edir[e]       = S->enodes[3 * e] == v ? 1.0 : -1.0;
      /* the arc position where the walk enters the edge: at eta = -1 if
         dir > 0, at eta = +1 if dir < 0 (see ContactSurfaceArc) */
      S->s0[e] = s0;
      s0 += S->elen[e];
      v = S->edir[e] > 0 ? S->enodes[3 * e + 1] : S->enodes[3 * e];
      for (PetscInt j = adjStart[v]; j < adjStart[v + 1]; ++j)
        if (!done[adj[j]]) next = adj[j];
      e = next;
    }
  }
  PetscCall(PetscFree(done));
  PetscFunctionReturn(0);
}

/* The turn at end node v of the surface (end j of its edge e) to the body's
   boundary edge that continues it, whose nodes (eta = -1, +1, 0) are at xf
   with v at eta = -1 (first) or +1: the angle from the surface's unit
   tangent leaving the end, t_out, to the continuation's, t_2, positive
   towards the body (along -n, n the surface's outward normal). */
static PetscReal ContactSurfaceEndTurn(const ContactSurface *S, PetscInt e, PetscInt j, const PetscReal xf[6], PetscBool first)
{
  PetscReal p[2], t[2], N[3], dN[3], t2[2] = {0, 0}, tout[2], nin[2], l;

  EdgeEval(S->X, &S->enodes[3 * e], j ? 1.0 : -1.0, p, t);
  l       = PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
  tout[0] = (j ? 1.0 : -1.0) * t[0] / l;
  tout[1] = (j ? 1.0 : -1.0) * t[1] / l;
  nin[0]  = -S->esign[e] * t[1] / l; /* -n, n = esign (t_y, -t_x) / |t| */
  nin[1]  = S->esign[e] * t[0] / l;
  EdgeShape(first ? -1.0 : 1.0, N, dN);
  for (PetscInt k = 0; k < 3; ++k)
    for (PetscInt d = 0; d < 2; ++d) t2[d] += (first ? 1.0 : -1.0) * dN[k] * xf[2 * k + d];
  return PetscAtan2Real(t2[0] * nin[0] + t2[1] * nin[1], t2[0] * tout[0] + t2[1] * tout[1]);
}

/* BodyBoundaryEdgesAt's callback: the turn at end node v to the body's edge
   xf through it, into turn[v]. */
typedef struct {
  const ContactSurface *S;
  PetscReal            *turn;
} EndTurnCtx;

static void ContactSurfaceEndTurnAt(void *ctx, PetscInt v, const PetscReal xf[6], PetscBool first)
{
  const EndTurnCtx *c = (const EndTurnCtx *)ctx;

  for (PetscInt e = 0; e < c->S->ne; ++e)
    for (PetscInt j = 0; j < 2; ++j)
      if (c->S->enodes[3 * e + j] == v) c->turn[v] = ContactSurfaceEndTurn(c->S, e, j, xf, first);
}

/* Where the surface ends, how the body goes on (endTurn): at each end node,
   the boundary edge of the body through it that is not in the surface's
   group (BodyBoundaryEdgesAt: the body's boundary, not the partition's),
   found by the rank whose cells hold it. A slave point past the end is then
   judged against that continuation (gap.c), not against the surface's own
   tangent line, which runs on into the open beside a corner. */
static PetscErrorCode ContactSurfaceSetUpEnds(ContactSurface *S, Body b, const char pair[])
{
  const PetscReal none = -10.0; /* below any angle */
  PetscReal      *turn;
  EndTurnCtx      ctx;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(S->nn, &S->endTurn));
  PetscCall(PetscMalloc1(S->nn, &turn));
  for (PetscInt v = 0; v < S->nn; ++v) turn[v] = none;
  ctx.S    = S;
  ctx.turn = turn;
  PetscCall(BodyBoundaryEdgesAt(b, S->tag, S->nn, S->nodeId, S->endNode, ContactSurfaceEndTurnAt, &ctx));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, turn, S->nn, MPIU_REAL, MPI_MAX, BodyGetComm(b)));
  for (PetscInt v = 0; v < S->nn; ++v) {
    if (!S->endNode[v]) continue;
    if (turn[v] > none) S->endTurn[v] = turn[v];
    PetscCall(PetscInfo(NULL, "contact pair %s, surface '%s' of body %s: an end at (%g, %g), the boundary turns there by %g degrees%s\n", pair, S->group, BodyGetName(b), (double)S->X[2 * v], (double)S->X[2 * v + 1], (double)(S->endTurn[v] * 180.0 / PETSC_PI), turn[v] > none ? "" : " (no boundary edge continues it: taken as straight on)"));
  }
  PetscCall(PetscFree(turn));
  PetscFunctionReturn(0);
}

/* Builds the whole surface on every rank: the owned edges of the physical
   group with their nodes' global numbers, reference coordinates and outward
   normal sign, gathered from all ranks; the map to the body's and the joined
   vectors; the blend at the nodes; the walk that gives the arc position. */
PetscErrorCode ContactSurfaceSetUp(ContactSurface *S, Body b, const char pair[], PetscReal blend)
{
  PetscInt  n = 0, *eid = NULL, *deg = NULL, *adj = NULL, *adjStart = NULL;
  PetscReal *erl = NULL;
  char       what[2 * CONTACT_NAME_LEN];

  PetscFunctionBeginUser;
  S->blend  = blend;
  S->axisym = BodyIsAxisymmetric(b);
  PetscCall(PetscSNPrintf(what, sizeof(what), "contact pair %s", pair));
  PetscCall(BodyGetGroupEdges(b, S->group, what, &S->tag, &n, &eid, &erl)); /* this rank's */
  PetscCall(ContactSurfaceGatherEdges(S, b, pair, n, eid, erl));
  PetscCall(PetscFree2(eid, erl));
  PetscCall(BodyMapNodes(b, S->nn, S->nodeId, &S->map, S->big));
  PetscCall(ContactSurfaceAdjacency(S, &deg, &adj, &adjStart));
  PetscCall(ContactSurfaceSetUpBlend(S, deg, adj, adjStart));
  PetscCall(ContactSurfaceWalk(S, adj, adjStart));
  if (BodyHasCells(b)) PetscCall(ContactSurfaceSetUpEnds(S, b, pair)); /* its cells tell its outward side */
  else PetscCall(PetscCalloc1(S->nn, &S->endTurn)); /* lines alone: once oriented against the partner (ContactSurfaceOrientRigid) */
  PetscCall(PetscFree2(deg, adjStart));
  PetscCall(PetscFree(adj));
  PetscFunctionReturn(0);
}

/* A rigid surface's outward side, and how the body goes on at its ends.
   Its lines carry no cell to tell the body's side, so each chain of the
   surface (edges joined end to end) is oriented along its walk, and then
   turned outwards: where the body's lines close on themselves (its
   outline: every corner on two lines), away from the region they enclose
   (a point a millionth of an edge off each edge's middle, by the even-odd
   rule); where they do not (a rigid plane given as one line), towards the
   partner surface, the side on which most of the partner's nodes lie, each
   judged at the chain's point nearest it (a partner node on the chain's
   own line, as a flat block's top beside a flat punch's face, has no
   vote). At an end, the body continues along its other lines through
   that node (its other curves), as an elastic body's boundary does. */
PetscErrorCode ContactSurfaceOrientRigid(ContactSurface *S, Body b, const ContactSurface *M, const char pair[])
{
  const PetscBool  closed = BodyRigidClosed(b);
  EndTurnCtx       ctx;
  PetscInt        *chain, nchain = 0;

  PetscFunctionBeginUser;
  /* chains: consecutive edges of the walk that share a node */
  PetscCall(PetscMalloc1(S->ne, &chain));
  for (PetscInt k = 0; k < S->ne; ++k) {
    const PetscInt e = S->walk[k];
    PetscBool      joined = PETSC_FALSE;
    if (k) {
      const PetscInt f = S->walk[k - 1];
      for (PetscInt i = 0; i < 2; ++i)
        for (PetscInt j = 0; j < 2; ++j) joined = (PetscBool)(joined || S->enodes[3 * e + i] == S->enodes[3 * f + j]);
    }
    if (!joined && k) nchain++;
    chain[e]    = nchain;
    S->esign[e] = S->edir[e];
  }
  nchain++;
  for (PetscInt c = 0; c < nchain; ++c) {
    PetscInt votes = 0;
    if (closed) /* a closed body: the normal at each edge's middle points out of the region */
      for (PetscInt e = 0; e < S->ne; ++e) {
        PetscReal p[2], t[2], q[2], l;
        if (chain[e] != c) continue;
        EdgeEval(S->X, &S->enodes[3 * e], 0.0, p, t);
        l    = PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
        q[0] = p[0] + 1e-6 * S->esign[e] * t[1] / l * S->elen[e];
        q[1] = p[1] - 1e-6 * S->esign[e] * t[0] / l * S->elen[e];
        votes += BodyRigidInside(b, q) ? -1 : 1;
      }
    else
      for (PetscInt w = 0; w < M->nn; ++w) { /* open lines: each partner node's side of the chain, at the chain's point nearest it */
        PetscReal best = PETSC_MAX_REAL, side = 0.0;
        for (PetscInt e = 0; e < S->ne; ++e) {
          if (chain[e] != c) continue;
          for (PetscInt q = 0; q < 9; ++q) {
            PetscReal p[2], t[2], d;
            EdgeEval(S->X, &S->enodes[3 * e], -1.0 + 0.25 * q, p, t);
            d = PetscSqr(p[0] - M->X[2 * w]) + PetscSqr(p[1] - M->X[2 * w + 1]);
            if (d < best) {
              best = d;
              side = S->esign[e] * (t[1] * (M->X[2 * w] - p[0]) - t[0] * (M->X[2 * w + 1] - p[1])); /* n . (x_w - p), n = esign (t_y, -t_x) */
            }
          }
        }
        votes += side > 1e-12 * best ? 1 : (side < -1e-12 * best ? -1 : 0);
      }
    PetscCheck(votes != 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "contact pair %s: surface '%s' of rigid body %s: its lines do not close on themselves and the partner surface lies as much on one side of it as on the other, so its outward side is not known (close the body's outline in its .geo)", pair, S->group, BodyGetName(b));
    if (votes < 0)
      for (PetscInt e = 0; e < S->ne; ++e)
        if (chain[e] == c) S->esign[e] = -S->esign[e];
  }
  PetscCall(PetscFree(chain));
  /* the ends: the body's other lines through them */
  ctx.S    = S;
  ctx.turn = S->endTurn;
  PetscCall(BodyBoundaryEdgesAt(b, S->tag, S->nn, S->nodeId, S->endNode, ContactSurfaceEndTurnAt, &ctx));
  for (PetscInt v = 0; v < S->nn; ++v)
    if (S->endNode[v]) PetscCall(PetscInfo(NULL, "contact pair %s, surface '%s' of rigid body %s: an end at (%g, %g), the boundary turns there by %g degrees\n", pair, S->group, BodyGetName(b), (double)S->X[2 * v], (double)S->X[2 * v + 1], (double)(S->endTurn[v] * 180.0 / PETSC_PI)));
  PetscFunctionReturn(0);
}

/* How far below the mirror line the current surface reaches: each quadratic
   edge lies in the triangle of its end nodes and its control point
   2 x_mid - (x_a + x_b)/2, so the lowest of these bounds it. A point at
   y - mirrorY >= mirrorReach + d is at least d from the mirror image. */
static void ContactSurfaceMirrorReach(ContactSurface *S)
{
  PetscReal lo = 0.0;

  for (PetscInt e = 0; e < S->ne; ++e) {
    const PetscInt *n  = &S->enodes[3 * e];
    const PetscReal ya = S->x[2 * n[0] + 1], yb = S->x[2 * n[1] + 1], yc = 2.0 * S->x[2 * n[2] + 1] - 0.5 * (ya + yb);
    lo = PetscMin(lo, PetscMin(ya, PetscMin(yb, yc)) - S->mirrorY);
  }
  S->mirrorReach = -lo;
}

/* The ends of the surface on the line (to a millionth of the surface's
   length, in the reference configuration), and the side the surface faces
   there: its outward normal and its image's have the mean (n_x, 0), and the
   sign of n_x is fixed by the reference configuration (an iterate may bend
   the end edge until its own tangent there is parallel to the line). */
PetscErrorCode ContactSurfaceSetMirror(ContactSurface *S, PetscReal y)
{
  const PetscReal tol = 1e-6 * ContactSurfaceLength(S);

  PetscFunctionBeginUser;
  S->mirror  = PETSC_TRUE;
  S->mirrorY = y;
  PetscCall(PetscCalloc1(S->nn, &S->cutNode));
  for (PetscInt e = 0; e < S->ne; ++e)
    for (PetscInt j = 0; j < 2; ++j) {
      const PetscInt v = S->enodes[3 * e + j];
      PetscReal      p[2], t[2];
      if (!S->endNode[v] || PetscAbsReal(S->X[2 * v + 1] - y) > tol) continue;
      EdgeEval(S->X, &S->enodes[3 * e], j ? 1.0 : -1.0, p, t);
      PetscCheck(PetscAbsReal(t[1]) > 1e-3 * PetscAbsReal(t[0]), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "surface '%s' ends on the mirror line y = %g at (%g, %g) running along it: a mirrored surface must cross the line", S->group, (double)y, (double)p[0], (double)p[1]);
      S->cutNode[v] = S->esign[e] * t[1] > 0 ? 1.0 : -1.0; /* n = esign (t_y, -t_x) */
    }
  ContactSurfaceMirrorReach(S);
  PetscFunctionReturn(0);
}

/* Gathers the current coordinates x = X + u of the surface nodes on every
   rank (each node's u from the one rank that owns it, so x is the same to the
   bit on every rank); changed: whether any differs from the last x. */
PetscErrorCode ContactSurfaceUpdateCoordinates(ContactSurface *S, Body b, PetscBool *changed)
{
  PetscFunctionBeginUser;
  PetscCall(BodyUpdateNodeCoordinates(b, S->nn, S->X, &S->map, S->x, changed));
  if (S->mirror) ContactSurfaceMirrorReach(S);
  PetscFunctionReturn(0);
}

/* Shares the edges out among size ranks in runs of the walk: with W the sum
   of the weights and w_k the sum before the k-th edge of the walk, that edge
   goes to rank floor(size (w_k + weight/2) / W) (the rank whose share holds
   the middle of its weight), so each rank's run weighs W / size to within
   one edge. Weights NULL: one each. The same on every rank given the same
   weights. */
void ContactSurfaceSplitEdges(const ContactSurface *S, PetscMPIInt size, const PetscReal weight[], PetscMPIInt owner[])
{
  PetscReal W = 0.0, w = 0.0;

  for (PetscInt e = 0; e < S->ne; ++e) W += weight ? weight[e] : 1.0;
  for (PetscInt k = 0; k < S->ne; ++k) {
    const PetscInt  e  = S->walk[k];
    const PetscReal we = weight ? weight[e] : 1.0;
    owner[e]           = (PetscMPIInt)PetscMin(size - 1, (PetscInt)(size * (w + 0.5 * we) / W));
    w += we;
  }
}

/* Sums the surface gradient over ranks and adds it where the node is owned. */
PetscErrorCode ContactSurfaceAddGradient(ContactSurface *S, Body b)
{
  PetscReal *sum;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(2 * S->nn, &sum));
  PetscCall(MPIU_Allreduce(S->g, sum, 2 * S->nn, MPIU_REAL, MPIU_SUM, BodyGetComm(b)));
  PetscCall(BodyAddNodeForces(b, S->nn, S->X, &S->map, sum)); /* a rigid body: the force and moment on it */
  PetscCall(PetscFree(sum));
  PetscFunctionReturn(0);
}

/* Arc position (reference length) at parameter xi of edge e, along the walk:
   8-point Gauss on the part of the edge from its entry end. */
PetscErrorCode ContactSurfaceArc(const ContactSurface *S, PetscInt e, PetscReal xi, PetscReal *s)
{
  PetscReal gx[8], gw[8], part = 0.0;

  PetscFunctionBeginUser;
  PetscCall(PetscDTGaussQuadrature(8, -1.0, 1.0, gx, gw));
  for (PetscInt q = 0; q < 8; ++q) {
    const PetscReal h = 0.5 * (xi + 1.0), eta = -1.0 + h * (gx[q] + 1.0);
    PetscReal       p[2], t[2];
    EdgeEval(S->X, &S->enodes[3 * e], eta, p, t);
    part += gw[q] * h * PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
  }
  *s = S->edir[e] > 0 ? S->s0[e] + part : S->s0[e] + S->elen[e] - part;
  PetscFunctionReturn(0);
}

/* Unit vectors u[nn][2] at the nodes, current configuration: each edge's
   unit tangent times sign[e], turned a quarter (normal) or not, summed at
   a shared node and normalised. */
static void SurfaceNodalUnitVectors(const ContactSurface *S, const PetscReal sign[], PetscBool normal, PetscReal u[])
{
  const PetscReal xi[3] = {-1.0, 1.0, 0.0};

  for (PetscInt k = 0; k < 2 * S->nn; ++k) u[k] = 0.0;
  for (PetscInt e = 0; e < S->ne; ++e)
    for (PetscInt i = 0; i < 3; ++i) {
      const PetscInt j = S->enodes[3 * e + i];
      PetscReal      p[2], t[2], l;
      EdgeEval(S->x, &S->enodes[3 * e], xi[i], p, t);
      l = sign[e] / PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
      u[2 * j] += (normal ? t[1] : t[0]) * l;
      u[2 * j + 1] += (normal ? -t[0] : t[1]) * l;
    }
  for (PetscInt j = 0; j < S->nn; ++j) {
    const PetscReal l = PetscSqrtReal(u[2 * j] * u[2 * j] + u[2 * j + 1] * u[2 * j + 1]);
    if (l > 0) {
      u[2 * j] /= l;
      u[2 * j + 1] /= l;
    }
  }
}

/* The outward unit normal at each node in the current configuration: on a
   mid-edge node its edge's, on a node shared by two edges the mean of their
   two normals there (the bisector: the edges of a finite element surface
   meet at a small corner), normalised. */
void ContactSurfaceNodalNormals(const ContactSurface *S, PetscReal n[])
{
  SurfaceNodalUnitVectors(S, S->esign, PETSC_TRUE, n);
}

void ContactSurfaceNodalTangents(const ContactSurface *S, PetscReal t[])
{
  SurfaceNodalUnitVectors(S, S->edir, PETSC_FALSE, t);
}

PetscErrorCode ContactSurfaceNodeArcs(const ContactSurface *S, PetscReal s[])
{
  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < S->ne; ++e) {
    const PetscInt *en = &S->enodes[3 * e];
    s[en[0]]           = S->edir[e] > 0 ? S->s0[e] : S->s0[e] + S->elen[e];
    s[en[1]]           = S->edir[e] > 0 ? S->s0[e] + S->elen[e] : S->s0[e];
    PetscCall(ContactSurfaceArc(S, e, 0.0, &s[en[2]]));
  }
  PetscFunctionReturn(0);
}

PetscReal ContactSurfaceLength(const ContactSurface *S)
{
  PetscReal L = 0.0;

  for (PetscInt e = 0; e < S->ne; ++e) L = PetscMax(L, S->s0[e] + S->elen[e]);
  return L;
}

PetscErrorCode ContactSurfaceDestroy(ContactSurface *S)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree3(S->enodes, S->esign, S->s0));
  PetscCall(PetscFree2(S->edir, S->elen));
  PetscCall(PetscFree(S->nodeId));
  PetscCall(PetscFree4(S->X, S->x, S->g, S->big));
  PetscCall(PetscFree(S->endNode));
  PetscCall(PetscFree(S->endTurn));
  PetscCall(PetscFree(S->cutNode));
  PetscCall(PetscFree2(S->mnodes, S->mcorr));
  PetscCall(BodyNodeMapDestroy(&S->map));
  PetscCall(PetscFree(S->ownEdges));
  PetscCall(PetscFree(S->walk));
  PetscFunctionReturn(0);
}
