/* Contact formulation "mortar" between 3D bodies: the weighted-gap penalty
   on curved quadratic faces (Tri6, Quad9), integrated segment by segment
   (face3d.c, clip.c, segment3d.c, bvh.c), one surface as slave.

   With S the slave surface, W_j the dual weights of its faces (face3d.c)
   and dS its reference measure (the slave's reference configuration: A_j
   and the weights do not move with u),
     A_j = int_S W_j dS              (the whole surface's: constant),
     Q_j = int_S' W_j g dS,  g_j = Q_j / A_j,
     E   = 1/2 k_p sum_j A_j <-g_j>_+^2,   p_j = k_p <-g_j>_+,
   g = (x_s - x_m) . n the gap to the closest point of the curved master
   (n its outward normal, g > 0 apart; behind a convex edge between two
   master faces the signed distance to the edge's point, segment3d.c), S'
   the part of S whose closest point lies on the master. A node whose
   covered part C_j = int_S' W_j dS carries less than half of A_j is left
   out (its g_j would be a part's, as 2D leaves out the nodes that face the
   master over less than half: surfaces that end); where S' is all of S,
   C_j = A_j and a uniform gap gives g_j = g at every node and the
   consistent nodal forces of a uniform pressure: the contact patch test.

   Gradient: dE = sum_j k_p A_j g_j dg_j over the nodes in contact (g_j < 0)
   with dg_j = G_j / A_j, G_j = dQ_j (Segment3dEvaluate: the points fixed in
   the slave's parameters, the motion of the closest point and of n drop
   out at the closest point), so dE = -sum_j p_j G_j. Hessian:
     H = k_p sum_{j: g_j < 0} (G_j G_j^T / A_j + g_j d2Q_j),
   the first part Gauss-Newton's (SPD), the second, with the exact Hessian
   (-contact_hessian exact, or auto near the solution), a sum over the
   points of lambda d2g, lambda = k_p sum_j g_j W_j dS (Mortar3dGapHessian:
   the master normal's turning and the closest point's motion; a point
   behind a master edge, in the fan, keeps the Gauss-Newton part). The
   segments are found again at every evaluation (current coordinates);
   their motion is not differentiated (segment3d.c: no term where the
   integrand is continuous across the master's face edges; where the
   master's border lies inside the slave, the end's term is in G_j and its
   leading second-order part in the exact Hessian, Mortar3dHessianEnds), which on
   curved faces leaves the Gauss rule's motion out: the Hessian's Taylor
   remainder is second order on the flat patch test and levels at 2.4e-9
   of |H v| on the curved Hertz cap (the quarter ball; the whole one
   1.6e-9: tests/test_seghess3d.py).

   Slave: -contact_mortar_slave first|second, or auto (the default): as in
   2D, a surface that ends on the other (ContactSurface3dEndsOn), else the
   softer body's surface (E/(1 - nu^2)), else the first named
   (Mortar3dChooseSlave). The automatic penalty k_p = 1000 E* / h, h the shortest chord
   between corners of the slave's faces.

   Parallel: every rank holds both surfaces whole (surface3d.c). For the
   energy and gradient each rank integrates the slave faces it gave (its
   owned face points), the A_j, C_j, Q_j are summed over ranks, and each
   rank adds the gradient of its own faces, summed over ranks and added at
   the owned nodes. The Hessian: each G_j needs all the faces around j, so
   node j is assembled by the lowest rank that gave a face around it, which
   integrates its own faces and the others' around its nodes (a layer one
   face wide along the borders between the ranks' parts of the surface:
   Mortar3dSetUpHessianFaces); C_j, Q_j are summed over ranks from the
   faces' owners as for the gradient. The search's queries are made from
   the faces that share a node with those integrated, and each rank's tree
   holds only the master faces that can meet them: the ranks exchange the
   boxes of the slave faces they search from and each master face is sent
   by the rank that gave it to the ranks whose box it meets
   (Mortar3dBuildTree, at each update, following the current
   coordinates). Friction's rows: each rank lags its own faces, the rows'
   entries gathered on every rank (Mortar3dFrictionLag). What stays whole
   on every rank, O(surface) a rank: the surfaces' coordinates (gathered
   at each evaluation), the sums of C_j, Q_j and the gradient over ranks,
   friction's rows (gathered) and the Hessian's pattern's search
   (Mortar3dGetPattern, once, on the reference coordinates).

   Master faces near a slave face: a bounding-volume tree over the master
   faces' boxes (current coordinates), queried with the slave face's box
   widened by the face's size (its longest corner chord): a slave point
   whose gap is less than that finds the face of its closest point, and a
   point farther from the master is apart (a node's support, of the face's
   size, is not both in contact and that far but where the surfaces meet
   at more than 45 degrees). Where a master much finer than the slave gives
   a face more than MORTAR3D_MAX_MASTER faces, the nearest are kept.

   Friction (-contact_<pair>_friction): friction3d.c, through a few hooks:
   its energy and gradient in Mortar3dEvaluate, its Hessian in
   Mortar3dHessian, its lag, state lifecycle and results in the
   Mortar3dFriction* functions, its sets in the output. */
#include <petscviewerhdf5.h>
#include <petsc/private/hashsetij.h>
#include "mortar3d.h"
#include "bvh.h"
#include "outputwrite.h"
#include "report3d.h"
#include "xdmf.h"
#include "segment3d.h"
#include "surface3d.h"
#include "friction3d.h"

#define MORTAR3D_MAX_MASTER 64 /* master faces near one slave face (Segment3dEvaluate's limit) */

/* One slave face's integrals at the current coordinates: a[j] = C_j's and
   q[j] = Q_j's parts, the master faces mf[nm] it met, and dQ[j ndof + c]
   over its dofs (slave nodes, then each master face's nodes, 3 each). */
typedef struct {
  PetscInt        nm, ndof, mf[MORTAR3D_MAX_MASTER];
  PetscReal       a[FACE3D_MAX_NODES], q[FACE3D_MAX_NODES];
  PetscReal      *dQ;
  PetscInt        np;  /* its points, kept where keep (the exact Hessian's second-order term) */
  Segment3dPoint *pts;
  PetscInt        nend; /* the ends of S' inside it (segment3d.c), kept where keep */
  Segment3dEnd   *ends;
  PetscInt        nkink; /* its kink lines (with edge points), kept where keep */
  Segment3dKink  *kinks;
} Mortar3dFace;

typedef struct {
  ContactPairSpec  spec;
  ContactSurface3d S[2];
  Body             body[2];
  PetscInt         s;            /* the slave surface (0 or 1) */
  PetscReal        kp;           /* the penalty in use (continuation) */
  PetscBool        exactHessian; /* asked for: the Hessian stays Gauss-Newton (above) */
  PetscReal        patternMargin; /* -contact_mortar_pattern_margin (Mortar3dGetPattern) */
  PetscInt         edgePoints;    /* -contact_mortar_edge_points (segment3d.c) */
  Face3dRule       rule, frule;  /* the clipped pieces' rule; the slave faces' own (dual coefficients, A_j) */
  PetscReal       *Adual;        /* [slave nf][81] the dual weights' coefficients */
  PetscReal       *A, *C, *Q, *gj; /* [slave nn] */
  PetscBool       *active;       /* [slave nn] C_j >= A_j / 2 */
  PetscBool       *nearNode, *integrate; /* [slave nn], [slave nf]: Mortar3dUpdate */
  PetscInt        *nodeFaceStart, *nodeFace; /* the slave faces at each slave node */
  Bvh              tree;         /* over the master faces this rank's search needs (Mortar3dBuildTree) */
  PetscInt         nmaster, nmasterMax, nmasterCap; /* their number: now, the most so far; room */
  PetscInt        *mlocal, *mfound; /* [nmaster] their numbers (the tree's items), a query's answers */
  PetscReal       *boxes;        /* [master nf][6] (those of the mlocal faces current) */
  PetscReal       *xm;           /* [MORTAR3D_MAX_MASTER][27] work */
  Mortar3dFace    *own;          /* [slave nown] the last evaluation of this rank's faces */
  PetscBool        ownFresh, ownDeriv, ownPts; /* own[] is at the current coordinates; with dQ; with its points */
  PetscInt         nhess, *hessFaces; /* the slave faces this rank integrates for the Hessian (Mortar3dSetUpHessianFaces) */
  PetscInt        *hessSlot;     /* [slave nf] a face's place in hessFaces, -1 if not there */
  PetscInt        *nodeRank;     /* [slave nn] the rank that assembles node j's G_j G_j^T */
  PetscInt        *faceRank;     /* [slave nf] the rank that gave face f (integrates it as slave) */
  PetscInt         nquery, *queryFaces; /* the slave faces whose search decides integrate[] of the hessFaces (Mortar3dUpdate) */
  PetscBool        counting;     /* Mortar3dGrowPattern: the Hessian added to a MATPREALLOCATOR (no rigid border) */
  PetscHSetIJ      covered;      /* (slave face, master face) pairs the Hessian's pattern holds (Mortar3dGetPattern, Mortar3dGrowPattern) */
  /* the results (post-processing) */
  PetscBool done;
  PetscReal force[2][3], pmax, pmin, maxPen, area;
  PetscInt  ncontact, nactive;
  Friction3d fr;                 /* Coulomb friction on the slave (friction3d.c), or NULL */
  PetscReal  shearForce[3], normalLoad, tangentialLoad, stickArea, stickRadius; /* its results (Mortar3dFrictionResults) */
  ContactReport3d report; /* the whole model's figures and Hertz's (report3d.c) */
} Mortar3d;

static PetscLogEvent MORTAR3D_EnergyGrad, MORTAR3D_Hessian, MORTAR3D_FrictionLag, MORTAR3D_Grow;
static PetscErrorCode Mortar3dFrictionResults(Mortar3d *);
static PetscErrorCode Mortar3dFrictionCreate(Mortar3d *, EnergyTerm);
static PetscErrorCode Mortar3dWriteFrictionHDF5(const Mortar3d *, Body[], PetscViewer, MPI_Comm, PetscInt);

/* Face f's coordinates xs from c and its box widened on every side by
   factor times the face's size. */
static void Mortar3dWideBox(const ContactSurface3d *S, PetscInt f, const PetscReal c[], PetscReal factor, PetscReal xs[], PetscReal box[6])
{
  PetscReal margin;

  ContactSurface3dFaceCoords(S, f, c, xs);
  Face3dBox(S->type, xs, box);
  margin = factor * Face3dSize(S->type, xs);
  for (PetscInt d = 0; d < 3; ++d) {
    box[d] -= margin;
    box[3 + d] += margin;
  }
}

/* The box of the slave faces this rank searches from (faces[nq]), each
   widened by its size (the widest of the searches' margins,
   Mortar3dFaceEvaluate's; Mortar3dUpdate's is
   MORTAR3D_NEAR): a master face whose box misses it meets none of their
   queries. Empty (low ends above high ends) where nq is 0. */
static void Mortar3dRankBox(const Mortar3d *m, PetscInt nq, const PetscInt faces[], PetscReal rbox[6])
{
  const ContactSurface3d *S = &m->S[m->s];

  for (PetscInt d = 0; d < 3; ++d) {
    rbox[d]     = PETSC_MAX_REAL;
    rbox[3 + d] = -PETSC_MAX_REAL;
  }
  for (PetscInt q = 0; q < nq; ++q) {
    PetscReal xs[27], box[6];
    Mortar3dWideBox(S, faces[q], S->x, 1.0, xs, box);
    for (PetscInt d = 0; d < 3; ++d) {
      rbox[d]     = PetscMin(rbox[d], box[d]);
      rbox[3 + d] = PetscMax(rbox[3 + d], box[3 + d]);
    }
  }
}

/* Collective. The master faces this rank's search needs and their tree,
   at the current coordinates: the ranks' boxes (Mortar3dRankBox over the
   slave faces each searches from) are exchanged, each rank computes the
   boxes of the master faces it gave (M->ownFaces) and sends to every rank
   those that meet its box (their numbers and boxes), and the tree is built
   over the faces received (m->mlocal, in increasing number; their boxes
   also at m->boxes[6 face] for Mortar3dKeepNearest). The search costs a
   rank O(k log k) for the k faces near its part of the slave, not
   O(master): the faces a rank holds follow the slave's motion, as the
   exchange is made at each update. */
static PetscErrorCode Mortar3dBuildTree(Mortar3d *m, PetscInt nq, const PetscInt faces[])
{
  const ContactSurface3d *M    = &m->S[1 - m->s];
  MPI_Comm                comm = BodyGetComm(m->body[0]);
  PetscMPIInt             size, rank, *scnt, *sdsp, *rcnt, *rdsp, *scnt6, *sdsp6, *rcnt6, *rdsp6;
  PetscReal               rbox[6], *all, *obox, *sbox, *rboxes, *lboxes;
  PetscInt               *sid, *rid, *perm, nsend = 0, nrecv;

  PetscFunctionBeginUser;
  PetscCall(BvhDestroy(&m->tree));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  Mortar3dRankBox(m, nq, faces, rbox);
  PetscCall(PetscMalloc1(6 * size, &all));
  PetscCallMPI(MPI_Allgather(rbox, 6, MPIU_REAL, all, 6, MPIU_REAL, comm));
  PetscCall(PetscMalloc1(6 * M->nown + 1, &obox));
  for (PetscInt k = 0; k < M->nown; ++k) {
    PetscReal xf[27];
    ContactSurface3dFaceCoords(M, M->ownFaces[k], M->x, xf);
    Face3dBox(M->type, xf, &obox[6 * k]);
  }
  PetscCall(PetscMalloc4(size, &scnt, size + 1, &sdsp, size, &rcnt, size + 1, &rdsp));
  PetscCall(PetscMalloc4(size, &scnt6, size, &sdsp6, size, &rcnt6, size, &rdsp6));
  for (PetscMPIInt r = 0; r < size; ++r) {
    scnt[r] = 0;
    for (PetscInt k = 0; k < M->nown; ++k) scnt[r] += BvhBoxesMeet(&obox[6 * k], &all[6 * r]) ? 1 : 0;
    nsend += scnt[r];
  }
  PetscCall(PetscMalloc2(nsend + 1, &sid, 6 * nsend + 1, &sbox));
  sdsp[0] = 0;
  for (PetscMPIInt r = 0; r < size; ++r) {
    PetscInt n = sdsp[r];
    for (PetscInt k = 0; k < M->nown; ++k)
      if (BvhBoxesMeet(&obox[6 * k], &all[6 * r])) {
        sid[n] = M->ownFaces[k];
        PetscCall(PetscArraycpy(&sbox[6 * n], &obox[6 * k], 6));
        n++;
      }
    sdsp[r + 1] = (PetscMPIInt)n;
  }
  PetscCallMPI(MPI_Alltoall(scnt, 1, MPI_INT, rcnt, 1, MPI_INT, comm));
  rdsp[0] = 0;
  for (PetscMPIInt r = 0; r < size; ++r) {
    rdsp[r + 1] = rdsp[r] + rcnt[r];
    scnt6[r]    = 6 * scnt[r];
    sdsp6[r]    = 6 * sdsp[r];
    rcnt6[r]    = 6 * rcnt[r];
    rdsp6[r]    = 6 * rdsp[r];
  }
  nrecv = rdsp[size];
  PetscCall(PetscMalloc4(nrecv + 1, &rid, 6 * nrecv + 1, &rboxes, nrecv + 1, &perm, 6 * nrecv + 1, &lboxes));
  PetscCallMPI(MPI_Alltoallv(sid, scnt, sdsp, MPIU_INT, rid, rcnt, rdsp, MPIU_INT, comm));
  PetscCallMPI(MPI_Alltoallv(sbox, scnt6, sdsp6, MPIU_REAL, rboxes, rcnt6, rdsp6, MPIU_REAL, comm));
  for (PetscInt k = 0; k < nrecv; ++k) perm[k] = k;
  PetscCall(PetscSortIntWithPermutation(nrecv, rid, perm));
  if (nrecv > m->nmasterCap) {
    PetscCall(PetscFree2(m->mlocal, m->mfound));
    m->nmasterCap = nrecv;
    PetscCall(PetscMalloc2(nrecv, &m->mlocal, nrecv, &m->mfound));
  }
  for (PetscInt k = 0; k < nrecv; ++k) {
    m->mlocal[k] = rid[perm[k]];
    PetscCall(PetscArraycpy(&lboxes[6 * k], &rboxes[6 * perm[k]], 6));
    PetscCall(PetscArraycpy(&m->boxes[6 * m->mlocal[k]], &rboxes[6 * perm[k]], 6));
  }
  m->nmaster    = nrecv;
  m->nmasterMax = PetscMax(m->nmasterMax, nrecv);
  PetscCall(BvhCreate(nrecv, lboxes, &m->tree));
  PetscCall(PetscFree4(rid, rboxes, perm, lboxes));
  PetscCall(PetscFree2(sid, sbox));
  PetscCall(PetscFree4(scnt, sdsp, rcnt, rdsp));
  PetscCall(PetscFree4(scnt6, sdsp6, rcnt6, rdsp6));
  PetscCall(PetscFree(obox));
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

/* The master faces (their numbers, increasing: the order whatever the
   tree's shape, the same on any number of ranks) whose boxes meet box, in
   m->mfound until the next query. */
static PetscErrorCode Mortar3dQuery(Mortar3d *m, const PetscReal box[6], PetscInt *nfound, const PetscInt **found)
{
  const PetscInt *loc;

  PetscFunctionBeginUser;
  PetscCall(BvhQuery(m->tree, box, nfound, &loc));
  for (PetscInt k = 0; k < *nfound; ++k) m->mfound[k] = m->mlocal[loc[k]];
  PetscCall(PetscSortInt(*nfound, m->mfound));
  *found = m->mfound;
  PetscFunctionReturn(0);
}

/* Of the n master faces found (more than MORTAR3D_MAX_MASTER, where the
   master is much finer than the slave), the MORTAR3D_MAX_MASTER whose boxes'
   centres are nearest the slave face's corners' centroid, in keep:
   the faraway ones hold no closest point of the slave face's points. */
static PetscErrorCode Mortar3dKeepNearest(Mortar3d *m, const PetscReal xs[], PetscInt n, const PetscInt found[], PetscInt keep[])
{
  PetscReal *d2, c[3];
  PetscInt  *perm;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(n, &d2, n, &perm));
  for (PetscInt d = 0; d < 3; ++d) {
    const PetscInt nc = m->S[m->s].type == FACE3D_TRI6 ? 3 : 4;
    c[d]              = 0.0;
    for (PetscInt j = 0; j < nc; ++j) c[d] += xs[3 * j + d] / nc;
  }
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal *b = &m->boxes[6 * found[k]];
    d2[k]              = 0.0;
    for (PetscInt d = 0; d < 3; ++d) d2[k] += PetscSqr(0.5 * (b[d] + b[3 + d]) - c[d]);
    perm[k] = k;
  }
  PetscCall(PetscSortRealWithPermutation(n, d2, perm));
  for (PetscInt k = 0; k < MORTAR3D_MAX_MASTER; ++k) keep[k] = found[perm[k]];
  PetscCall(PetscSortInt(MORTAR3D_MAX_MASTER, keep)); /* the faces' order as the tree gives it, whatever the distances' ties */
  PetscCall(PetscInfo(NULL, "pair %s: a slave face meets %" PetscInt_FMT " master faces; the %d nearest kept\n", m->spec.name, n, MORTAR3D_MAX_MASTER));
  PetscCall(PetscFree2(d2, perm));
  PetscFunctionReturn(0);
}

/* Whether side k of slave face g (from corner k to corner k + 1, its
   mid-side node nc + k) lies on the slave surface's border: no other slave
   face holds both its corners. */
static PetscBool Mortar3dSideOnBorder(const Mortar3d *m, PetscInt g, PetscInt k)
{
  const ContactSurface3d *S  = &m->S[m->s];
  const PetscInt          nc = S->type == FACE3D_TRI6 ? 3 : 4;
  const PetscInt          a = S->fnodes[S->nb * g + k], b = S->fnodes[S->nb * g + (k + 1) % nc];

  for (PetscInt r = m->nodeFaceStart[a]; r < m->nodeFaceStart[a + 1]; ++r) {
    const PetscInt h = m->nodeFace[r];
    if (h == g) continue;
    for (PetscInt i = 0; i < S->nb; ++i)
      if (S->fnodes[S->nb * h + i] == b) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

/* The nodes of slave face f on the slave surface's border, a bit each (node
   i of the face: bit i): those on a side of a slave face around them that
   lies on the border (Mortar3dSideOnBorder). */
static PetscInt Mortar3dSlaveBorder(const Mortar3d *m, PetscInt f)
{
  const ContactSurface3d *S  = &m->S[m->s];
  const PetscInt          nc = S->type == FACE3D_TRI6 ? 3 : 4;
  PetscInt                border = 0;

  for (PetscInt i = 0; i < S->nb; ++i) {
    const PetscInt j = S->fnodes[S->nb * f + i];
    for (PetscInt r = m->nodeFaceStart[j]; r < m->nodeFaceStart[j + 1] && !(border & (1 << i)); ++r) {
      const PetscInt g = m->nodeFace[r];
      for (PetscInt k = 0; k < nc; ++k) {
        const PetscInt *side = &S->fnodes[S->nb * g];
        if ((side[k] == j || side[(k + 1) % nc] == j || side[nc + k] == j) && Mortar3dSideOnBorder(m, g, k)) {
          border |= 1 << i;
          break;
        }
      }
    }
  }
  return border;
}

/* Slave face f against the master faces near it (deriv: with dQ; keep:
   its points kept in E, PetscFree(E->pts)). */
static PetscErrorCode Mortar3dFaceEvaluate(Mortar3d *m, PetscInt f, PetscBool deriv, PetscBool keep, Mortar3dFace *E)
{
  const ContactSurface3d *S = &m->S[m->s], *M = &m->S[1 - m->s];
  PetscReal               xs[27], Xs[27], box[6];
  Face3d                  sf, ref, mf[MORTAR3D_MAX_MASTER];
  const PetscInt         *found;
  PetscInt                nfound, np, nend = 0, nkink = 0;
  Segment3dPoint         *pts;
  Segment3dEnd           *ends  = NULL;
  Segment3dKink          *kinks = NULL;

  PetscFunctionBeginUser;
  E->np   = 0;
  E->nend  = 0;
  E->nkink = 0;
  PetscCall(PetscFree(E->pts));
  PetscCall(PetscFree(E->ends));
  PetscCall(PetscFree(E->kinks));
  if (!m->integrate[f]) { /* far from the master */
    E->nm   = 0;
    E->ndof = 3 * S->nb;
    PetscCall(PetscArrayzero(E->a, FACE3D_MAX_NODES));
    PetscCall(PetscArrayzero(E->q, FACE3D_MAX_NODES));
    PetscCall(PetscFree(E->dQ));
    if (deriv) PetscCall(PetscCalloc1(S->nb * E->ndof, &E->dQ));
    PetscFunctionReturn(0);
  }
  Mortar3dWideBox(S, f, S->x, 1.0, xs, box);
  ContactSurface3dFaceCoords(S, f, S->X, Xs);
  PetscCall(Mortar3dQuery(m, box, &nfound, &found));
  if (nfound > MORTAR3D_MAX_MASTER) PetscCall(Mortar3dKeepNearest(m, xs, nfound, found, E->mf));
  else PetscCall(PetscArraycpy(E->mf, found, nfound));
  nfound  = PetscMin(nfound, MORTAR3D_MAX_MASTER);
  E->nm   = nfound;
  E->ndof = 3 * (S->nb + nfound * M->nb);
  for (PetscInt k = 0; k < nfound; ++k) {
    ContactSurface3dFaceCoords(M, E->mf[k], M->x, &m->xm[27 * k]);
    mf[k].type = M->type;
    mf[k].x    = &m->xm[27 * k];
  }
  sf.type  = S->type;
  sf.x     = xs;
  ref.type = S->type;
  ref.x    = Xs;
  PetscCall(PetscArrayzero(E->a, FACE3D_MAX_NODES));
  PetscCall(PetscArrayzero(E->q, FACE3D_MAX_NODES));
  PetscCall(PetscFree(E->dQ));
  if (deriv) PetscCall(PetscCalloc1(S->nb * E->ndof + 1, &E->dQ));
  if (!nfound) PetscFunctionReturn(0);
  PetscCall(Segment3dPoints(&sf, nfound, mf, &m->rule, m->edgePoints, &np, &pts, Mortar3dSlaveBorder(m, f), &nend, &ends, &nkink, deriv ? &kinks : NULL)); /* the kink lines: dQ's term and, kept, the Hessian's (which reuses only an evaluation with dQ) */
  PetscCall(Segment3dEvaluate(&ref, xs, &m->Adual[81 * f], nfound, mf, np, pts, E->a, E->q, E->dQ));
  if (deriv) PetscCall(Segment3dEndEvaluate(&ref, xs, &m->Adual[81 * f], nfound, mf, nend, ends, E->dQ));
  if (deriv) PetscCall(Segment3dKinkEvaluate(&ref, xs, &m->Adual[81 * f], nfound, mf, nkink, kinks, E->dQ));
  if (keep) {
    E->np   = np;
    E->pts  = pts;
    E->nend  = nend;
    E->ends  = ends;
    E->nkink = nkink;
    E->kinks = kinks;
  } else {
    PetscCall(PetscFree(pts));
    PetscCall(PetscFree(ends));
    PetscCall(PetscFree(kinks));
  }
  PetscFunctionReturn(0);
}

/* Column c of face f's dQ: the surface (0 slave, 1 master) and the index of
   the node's component in its arrays (3 node + d). */
static inline void Mortar3dColumn(const Mortar3d *m, PetscInt f, const Mortar3dFace *E, PetscInt c, PetscInt *side, PetscInt *k)
{
  const ContactSurface3d *S = &m->S[m->s], *M = &m->S[1 - m->s];

  if (c < 3 * S->nb) {
    *side = 0;
    *k    = 3 * S->fnodes[S->nb * f + c / 3] + c % 3;
  } else {
    const PetscInt r = c - 3 * S->nb, face = E->mf[r / (3 * M->nb)], i = (r % (3 * M->nb)) / 3;
    *side = 1;
    *k    = 3 * M->fnodes[M->nb * face + i] + r % 3;
  }
}

/* Both surfaces' current coordinates, the master's tree, and the slave
   faces to integrate: those with a node near the master (on a face whose
   box, widened by MORTAR3D_NEAR of its size, meets a master face's box),
   so that a node near the master has every face around it integrated
   (its C_j and Q_j whole) and a node far from it none (C_j = 0: not
   counted, as its gap is positive wherever its faces are); the slave
   faces searched are those this rank's evaluations need (m->queryFaces). */
#define MORTAR3D_NEAR 0.25
static PetscErrorCode Mortar3dUpdate(Mortar3d *m)
{
  const ContactSurface3d *S = &m->S[m->s];
  const PetscInt          nq = m->nquery;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < 2; ++k) {
    PetscBool changed;
    PetscCall(ContactSurface3dUpdateCoordinates(&m->S[k], m->body[k], &changed));
    if (changed) m->ownFresh = PETSC_FALSE;
  }
  PetscCall(Mortar3dBuildTree(m, nq, m->queryFaces));
  PetscCall(PetscArrayzero(m->nearNode, S->nn));
  for (PetscInt q = 0; q < nq; ++q) {
    const PetscInt  f = m->queryFaces[q];
    PetscReal       xs[27], box[6];
    const PetscInt *found;
    PetscInt        nfound;
    Mortar3dWideBox(S, f, S->x, MORTAR3D_NEAR, xs, box);
    PetscCall(Mortar3dQuery(m, box, &nfound, &found));
    if (nfound)
      for (PetscInt i = 0; i < S->nb; ++i) m->nearNode[S->fnodes[S->nb * f + i]] = PETSC_TRUE;
  }
  for (PetscInt f = 0; f < S->nf; ++f) {
    m->integrate[f] = PETSC_FALSE;
    for (PetscInt i = 0; i < S->nb; ++i)
      if (m->nearNode[S->fnodes[S->nb * f + i]]) m->integrate[f] = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

/* g_j and the nodes counted from C_j and Q_j (summed over the faces). */
static void Mortar3dNodalGaps(Mortar3d *m)
{
  const ContactSurface3d *S = &m->S[m->s];

  for (PetscInt j = 0; j < S->nn; ++j) {
    m->active[j] = (PetscBool)(m->A[j] > 0 && m->C[j] >= 0.5 * m->A[j]);
    m->gj[j]     = m->active[j] ? m->Q[j] / m->A[j] : PETSC_INFINITY;
  }
}

/* The energy (rank 0's: the whole), and with gradient the gradient on both
   surfaces summed over ranks (S->gsum), added to the bodies' local
   gradients where add. */
static PetscErrorCode Mortar3dEvaluate(Mortar3d *m, PetscBool gradient, PetscBool add, PetscReal *energy)
{
  ContactSurface3d *S = &m->S[m->s], *M = &m->S[1 - m->s];
  PetscMPIInt       rank;
  PetscReal        *buf;
  PetscBool         reuse;

  PetscFunctionBeginUser;
  PetscCall(Mortar3dUpdate(m));
  reuse = (PetscBool)(m->ownFresh && (m->ownDeriv || !gradient)); /* the same coordinates as the last evaluation */
  PetscCall(PetscCalloc1(2 * S->nn, &buf));
  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt f  = S->ownFaces[k];
    Mortar3dFace  *E  = &m->own[k];
    if (!reuse) PetscCall(Mortar3dFaceEvaluate(m, f, gradient, m->exactHessian, E));
    for (PetscInt i = 0; i < S->nb; ++i) {
      buf[S->fnodes[S->nb * f + i]] += E->a[i];
      buf[S->nn + S->fnodes[S->nb * f + i]] += E->q[i];
    }
  }
  PetscCall(MPIU_Allreduce(buf, m->C, S->nn, MPIU_REAL, MPIU_SUM, BodyGetComm(m->body[0])));
  PetscCall(MPIU_Allreduce(buf + S->nn, m->Q, S->nn, MPIU_REAL, MPIU_SUM, BodyGetComm(m->body[0])));
  PetscCall(PetscFree(buf));
  if (!reuse) {
    m->ownFresh = PETSC_TRUE;
    m->ownDeriv = gradient;
    m->ownPts   = m->exactHessian;
  }
  Mortar3dNodalGaps(m);
  PetscCallMPI(MPI_Comm_rank(BodyGetComm(m->body[0]), &rank));
  *energy = 0.0;
  if (!rank)
    for (PetscInt j = 0; j < S->nn; ++j)
      if (m->active[j] && m->gj[j] < 0) *energy += 0.5 * m->kp * m->A[j] * m->gj[j] * m->gj[j];
  if (!gradient) {
    if (m->fr) PetscCall(Friction3dAddEnergyGradient(m->fr, m->S, m->spec.kp, energy)); /* its gradient into S->g, unused here */
    PetscFunctionReturn(0);
  }
  PetscCall(PetscArrayzero(S->g, 3 * S->nn));
  PetscCall(PetscArrayzero(M->g, 3 * M->nn));
  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt      f = S->ownFaces[k];
    const Mortar3dFace *E = &m->own[k];
    if (!E->nm) continue;
    for (PetscInt i = 0; i < S->nb; ++i) {
      const PetscInt  j = S->fnodes[S->nb * f + i];
      const PetscReal lam = m->kp * m->gj[j]; /* -p_j */
      if (!m->active[j] || !(m->gj[j] < 0)) continue;
      for (PetscInt c = 0; c < E->ndof; ++c) {
        PetscInt side, idx;
        Mortar3dColumn(m, f, E, c, &side, &idx);
        (side ? M : S)->g[idx] += lam * E->dQ[i * E->ndof + c];
      }
    }
  }
  if (m->fr) PetscCall(Friction3dAddEnergyGradient(m->fr, m->S, m->spec.kp, energy)); /* the scene's k_p: k_t is not continued (friction.c) */
  for (PetscInt k = 0; k < 2; ++k) {
    ContactSurface3d *T = k ? M : S;
    if (add) PetscCall(ContactSurface3dAddGradient(T, m->body[k ? 1 - m->s : m->s]));
    else PetscCall(MPIU_Allreduce(T->g, T->gsum, 3 * T->nn, MPIU_REAL, MPIU_SUM, BodyGetComm(m->body[0])));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dFrictionLag(EnergyTerm, Body[], PetscReal *);

static PetscErrorCode Mortar3dEnergyGradient(EnergyTerm t, Body bodies[], PetscReal *energy)
{
  Mortar3d *m = (Mortar3d *)t->data;

  PetscFunctionBeginUser;
  if (m->fr && Friction3dRowsPending(m->fr)) PetscCall(Mortar3dFrictionLag(t, bodies, NULL)); /* a tied start's rows (friction3d.c) */
  PetscCall(PetscLogEventBegin(MORTAR3D_EnergyGrad, 0, 0, 0, 0));
  PetscCall(Mortar3dEvaluate(m, PETSC_TRUE, PETSC_TRUE, energy));
  PetscCall(PetscLogEventEnd(MORTAR3D_EnergyGrad, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The second derivative of the gap g at one point (slave face xs at xi,
   master face xm at its closest point eta, inside the face) over the two
   faces' dofs (slave first, n = 3 (ns + nm)), K[n][n]. With D = x_s - x_m =
   g n at the closest point, dg = n . (sum N_i dx_i - sum M_k dx_k) (the
   motions of eta and n drop out), so
     d2g(u, v) = dn(v) . (D_u) - sum_k (M_k,a deta_a(v)) n . u_k,
   D_u = sum N_i u_i - sum M_k u_k, deta from the closest point's
   conditions (Segment3dProjectionDerivative), and the unit normal's
   derivative dn = (I - n n^T) dc / |c|, c = t_1 x t_2,
   dt_a = sum M_k,a dx_k + x_,ab deta_b. Symmetrised (it is symmetric where
   eta is the closest point). PETSC_FALSE (K untouched) where the closest
   point's Hessian is not positive definite (a point deeper than the
   master's radius of curvature): the Gauss-Newton part alone there. */
static PetscErrorCode Mortar3dGapHessian(const Face3d *sf, const PetscReal xi[2], const Face3d *mf, const PetscReal eta[2], PetscReal K[], PetscBool *ok)
{
  const PetscInt ns = Face3dNodes(sf->type), nm = Face3dNodes(mf->type), n = 3 * (ns + nm);
  PetscReal      c[3], nrm[3], len, deta[2 * 3 * 2 * FACE3D_MAX_NODES], dn[3 * 3 * 2 * FACE3D_MAX_NODES];
  Segment3dClosest cp;
  const PetscReal *N = cp.N, *M = cp.M, *dM = cp.dM, *T = cp.T, *H = cp.H;

  PetscFunctionBeginUser;
  *ok = PETSC_FALSE;
  if (!Segment3dClosestPointAt(sf, xi, mf, eta, &cp)) PetscFunctionReturn(0);
  Segment3dProjectionDerivative(&cp, ns, nm, deta);
  c[0] = T[1] * T[5] - T[2] * T[4];
  c[1] = T[2] * T[3] - T[0] * T[5];
  c[2] = T[0] * T[4] - T[1] * T[3];
  len  = PetscSqrtReal(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  for (PetscInt k = 0; k < 3; ++k) nrm[k] = c[k] / len;
  for (PetscInt col = 0; col < n; ++col) { /* dn along dof col */
    PetscReal dt[6], dc[3], nd;
    const PetscInt node = col / 3, dd = col % 3;
    for (PetscInt a = 0; a < 2; ++a)
      for (PetscInt k = 0; k < 3; ++k) dt[3 * a + k] = H[3 * a + k] * deta[col] + H[3 * (a + 1) + k] * deta[n + col];
    if (node >= ns)
      for (PetscInt a = 0; a < 2; ++a) dt[3 * a + dd] += dM[2 * (node - ns) + a];
    dc[0] = dt[1] * T[5] - dt[2] * T[4] + T[1] * dt[5] - T[2] * dt[4];
    dc[1] = dt[2] * T[3] - dt[0] * T[5] + T[2] * dt[3] - T[0] * dt[5];
    dc[2] = dt[0] * T[4] - dt[1] * T[3] + T[0] * dt[4] - T[1] * dt[3];
    nd    = nrm[0] * dc[0] + nrm[1] * dc[1] + nrm[2] * dc[2];
    for (PetscInt k = 0; k < 3; ++k) dn[3 * col + k] = (dc[k] - nd * nrm[k]) / len;
  }
  for (PetscInt r = 0; r < n; ++r)
    for (PetscInt col = 0; col < n; ++col) {
      const PetscInt node = col / 3, dd = col % 3;
      PetscReal      v;
      if (node < ns) v = dn[3 * r + dd] * N[node];
      else {
        const PetscInt k = node - ns;
        v = -dn[3 * r + dd] * M[k] - (dM[2 * k] * deta[r] + dM[2 * k + 1] * deta[n + r]) * nrm[dd];
      }
      K[r * n + col] = v;
    }
  for (PetscInt r = 0; r < n; ++r)
    for (PetscInt col = 0; col < r; ++col) K[r * n + col] = K[col * n + r] = 0.5 * (K[r * n + col] + K[col * n + r]);
  *ok = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* A block K over the joined indices idx into H (negative indices left
   out) and, where a rigid body's surface components stand among them
   (indices below -1, ContactRigidDof3), into its unknowns' border
   (BodyAddSurfaceHessian, at the surface's current coordinates). */
static PetscErrorCode Mortar3dAddRigidBlock(Mortar3d *m, PetscInt n, const PetscInt idx[], const PetscScalar K[])
{
  PetscFunctionBeginUser;
  if (m->counting) PetscFunctionReturn(0);
  for (PetscInt k = 0; k < 2; ++k)
    if (!BodyHasCells(m->body[k])) PetscCall(BodyAddSurfaceHessian(m->body[k], m->S[k].x, n, idx, K));
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dAddHessianBlock(Mortar3d *m, Mat H, PetscInt n, const PetscInt idx[], const PetscScalar K[])
{
  PetscFunctionBeginUser;
  PetscCall(MatSetValues(H, n, idx, n, idx, K, ADD_VALUES));
  PetscCall(Mortar3dAddRigidBlock(m, n, idx, K));
  PetscFunctionReturn(0);
}

/* The joined indices of a block over slave face f's dofs, then master face face's. */
static void Mortar3dBlockIndices(const Mortar3d *m, PetscInt f, PetscInt face, PetscInt idx[])
{
  const ContactSurface3d *S = &m->S[m->s], *M = &m->S[1 - m->s];

  for (PetscInt i = 0; i < S->nb; ++i)
    for (PetscInt d = 0; d < 3; ++d) idx[3 * i + d] = S->big[3 * S->fnodes[S->nb * f + i] + d];
  for (PetscInt i = 0; i < M->nb; ++i)
    for (PetscInt d = 0; d < 3; ++d) idx[3 * (S->nb + i) + d] = M->big[3 * M->fnodes[M->nb * face + i] + d];
}

/* The exact Hessian's second-order part, k_p sum_j g_j d2Q_j = sum over the
   points of this rank's slave faces of lambda d2g, lambda = k_p sum_j g_j
   W_j dS over the face's nodes in contact (Mortar3dGapHessian; a point
   behind a master edge, in the fan, keeps the Gauss-Newton part alone);
   all[] holds the faces of m->hessFaces, this rank's among them. */
static PetscErrorCode Mortar3dHessianSecondOrder(Mortar3d *m, const Mortar3dFace all[], Mat H)
{
  const ContactSurface3d *S = &m->S[m->s], *M = &m->S[1 - m->s];
  const PetscInt          n = 3 * (S->nb + M->nb);
  PetscReal               xs[27], Xs[27], xm[27], K[54 * 54], Ksum[54 * 54], W[FACE3D_MAX_NODES];
  PetscInt                idx[54];

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt      f = S->ownFaces[k];
    const Mortar3dFace *E = &all[m->hessSlot[f]];
    Face3d              sf;
    sf.type = S->type;
    sf.x    = xs;
    ContactSurface3dFaceCoords(S, f, S->x, xs);
    ContactSurface3dFaceCoords(S, f, S->X, Xs);
    for (PetscInt mm = 0; mm < E->nm; ++mm) { /* the points of each master face summed, added once */
      const PetscInt face = E->mf[mm];
      PetscBool      any  = PETSC_FALSE;
      Face3d         mf;
      ContactSurface3dFaceCoords(M, face, M->x, xm);
      mf.type = M->type;
      mf.x    = xm;
      for (PetscInt q = 0; q < E->np; ++q) {
        const Segment3dPoint *pt = &E->pts[q];
        PetscReal             X[3], T[6], nrm[3], x[3], e2[2] = {pt->eta[0], pt->eta[1]}, dS, lam = 0.0;
        PetscBool             clamped, ok;
        if (pt->m != mm) continue;
        Face3dEval(S->type, Xs, pt->xi, X, T, NULL);
        dS = Face3dNormal(T, nrm) * pt->w;
        Face3dWeights(S->type, &m->Adual[81 * f], pt->xi, W);
        for (PetscInt i = 0; i < S->nb; ++i) {
          const PetscInt j = S->fnodes[S->nb * f + i];
          if (m->active[j] && m->gj[j] < 0) lam += m->kp * m->gj[j] * W[i] * dS;
        }
        if (lam == 0.0) continue;
        Face3dEval(S->type, xs, pt->xi, x, NULL, NULL);
        Segment3dPointClosest(pt, &mf, x, e2, &clamped);
        if (clamped) continue;
        PetscCall(Mortar3dGapHessian(&sf, pt->xi, &mf, e2, K, &ok));
        if (!ok) continue;
        if (!any) PetscCall(PetscArrayzero(Ksum, n * n));
        any = PETSC_TRUE;
        for (PetscInt r = 0; r < n * n; ++r) Ksum[r] += lam * K[r];
      }
      if (!any) continue;
      Mortar3dBlockIndices(m, f, face, idx);
      PetscCall(Mortar3dAddHessianBlock(m, H, n, idx, Ksum));
    }
  }
  PetscFunctionReturn(0);
}

/* The exact Hessian's end part: where the master's border lies inside a
   slave face of this rank's, the leading part of k_p sum_j g_j d2Q_j's
   end term, sum_j k_p g_j int_end W_j (dg v^T + v dg^T) (segment3d.c,
   Segment3dEndHessian), one block per end over the slave face's and its
   master face's dofs; and with edge points (-contact_mortar_edge_points),
   where a slave point's closest point passes from one master face to the
   next, the term of that kink line's motion (Segment3dKinkHessian), one
   block per kink over the slave face's and the line's first face's dofs;
   all[] as Mortar3dHessianSecondOrder's. */
static PetscErrorCode Mortar3dHessianEnds(Mortar3d *m, const Mortar3dFace all[], Mat H)
{
  const ContactSurface3d *S = &m->S[m->s], *M = &m->S[1 - m->s];
  const PetscInt          n = 3 * (S->nb + M->nb);
  PetscReal               xs[27], Xs[27], xm[27], xm2[27], K[54 * 54], lam[FACE3D_MAX_NODES];
  PetscInt                idx[54];

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt      f = S->ownFaces[k];
    const Mortar3dFace *E = &all[m->hessSlot[f]];
    Face3d              ref, mf, mf2;
    PetscBool           any = PETSC_FALSE;
    if (!E->nend && !E->nkink) continue;
    for (PetscInt i = 0; i < S->nb; ++i) {
      const PetscInt j = S->fnodes[S->nb * f + i];
      lam[i]           = m->active[j] && m->gj[j] < 0 ? m->kp * m->gj[j] : 0.0;
      if (lam[i] != 0.0) any = PETSC_TRUE;
    }
    if (!any) continue;
    ContactSurface3dFaceCoords(S, f, S->x, xs);
    ContactSurface3dFaceCoords(S, f, S->X, Xs);
    ref.type = S->type;
    ref.x    = Xs;
    mf.type  = M->type;
    mf.x     = xm;
    mf2.type = M->type;
    mf2.x    = xm2;
    for (PetscInt e = 0; e < E->nend; ++e) {
      const PetscInt face = E->mf[E->ends[e].m];
      ContactSurface3dFaceCoords(M, face, M->x, xm);
      PetscCall(PetscArrayzero(K, n * n));
      any = PETSC_FALSE;
      PetscCall(Segment3dEndHessian(&ref, xs, &m->Adual[81 * f], lam, &mf, &E->ends[e], K, &any));
      if (!any) continue;
      Mortar3dBlockIndices(m, f, face, idx);
      PetscCall(Mortar3dAddHessianBlock(m, H, n, idx, K));
    }
    for (PetscInt e = 0; e < E->nkink; ++e) { /* the kink lines (edge points): the gradient's jump moving */
      const PetscInt face = E->mf[E->kinks[e].m];
      ContactSurface3dFaceCoords(M, face, M->x, xm);
      ContactSurface3dFaceCoords(M, E->mf[E->kinks[e].m2], M->x, xm2);
      PetscCall(PetscArrayzero(K, n * n));
      any = PETSC_FALSE;
      PetscCall(Segment3dKinkHessian(&ref, xs, &m->Adual[81 * f], lam, &mf, &mf2, &E->kinks[e], K, &any));
      if (!any) continue;
      Mortar3dBlockIndices(m, f, face, idx);
      PetscCall(Mortar3dAddHessianBlock(m, H, n, idx, K));
    }
  }
  PetscFunctionReturn(0);
}

/* The Gauss-Newton part k_p sum_j G_j G_j^T / A_j over the nodes j in
   contact this rank assembles (m->nodeRank), G_j's entries by joined index
   summed over the faces around j (all[] by m->hessSlot). The blocks of neighbouring nodes overlap
   (a master node faces many slave nodes), so they are summed first, row by
   row from the nodes whose G_j holds the row's dof (the work the nonzeros',
   sum_j n_j^2, not the square of the number of dofs touched, as a dense
   buffer over them would cost), and each row of the sum is added
   once, its columns in order: one MatSetValues entry per nonzero of the sum,
   not one per node and pair of its dofs. */
static PetscErrorCode Mortar3dAddGaussNewton(Mortar3d *m, const Mortar3dFace all[], PetscMPIInt rank, Mat H)
{
  const ContactSurface3d *S = &m->S[m->s], *M = &m->S[1 - m->s];
  PetscInt                nj = 0, total = 0, nU = 0, *start, *idx, *loc, *U;
  PetscReal              *val, *w, *Kr;
  const PetscBool         rigid = (PetscBool)(!BodyHasCells(m->body[0]) || !BodyHasCells(m->body[1]));

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < S->nn; ++j) {
    if (m->nodeRank[j] != rank || !m->active[j] || !(m->gj[j] < 0)) continue;
    ++nj;
    for (PetscInt r = m->nodeFaceStart[j]; r < m->nodeFaceStart[j + 1]; ++r) total += all[m->hessSlot[m->nodeFace[r]]].ndof;
  }
  PetscCall(PetscMalloc5(nj + 1, &start, total + 1, &idx, total + 1, &val, total + 1, &loc, nj + 1, &w));
  start[0] = 0;
  nj       = 0;
  for (PetscInt j = 0; j < S->nn; ++j) { /* G_j: its distinct joined indices, sorted, and values */
    PetscInt *id = &idx[start[nj]], n = 0;
    PetscReal *v = &val[start[nj]];
    if (m->nodeRank[j] != rank || !m->active[j] || !(m->gj[j] < 0)) continue;
    for (PetscInt r = m->nodeFaceStart[j]; r < m->nodeFaceStart[j + 1]; ++r) {
      const PetscInt      f = m->nodeFace[r];
      const Mortar3dFace *E = &all[m->hessSlot[f]];
      PetscInt            i;
      for (i = 0; i < S->nb && S->fnodes[S->nb * f + i] != j; ++i) {}
      for (PetscInt c = 0; c < E->ndof; ++c) {
        PetscInt side, k, big, at = -1;
        Mortar3dColumn(m, f, E, c, &side, &k);
        big = (side ? M : S)->big[k];
        if (big == -1) continue; /* constrained; a rigid body's (below -1) go to its border (Mortar3dAddHessianBlock) */
        for (PetscInt l = 0; l < n && at < 0; ++l)
          if (id[l] == big) at = l;
        if (at < 0) {
          at     = n++;
          id[at] = big;
          v[at]  = 0.0;
        }
        v[at] += E->dQ[i * E->ndof + c];
      }
    }
    PetscCall(PetscSortIntWithScalarArray(n, id, v));
    if (rigid) { /* a rigid body's part of the block, to its unknowns' border */
        PetscCall(PetscMalloc1(n * n, &Kr));
      for (PetscInt a = 0; a < n; ++a)
        for (PetscInt b = 0; b < n; ++b) Kr[a * n + b] = m->kp * v[a] * v[b] / m->A[j];
      PetscCall(Mortar3dAddRigidBlock(m, n, id, Kr));
      PetscCall(PetscFree(Kr));
    }
    w[nj]         = m->kp / m->A[j];
    start[nj + 1] = start[nj] + n;
    ++nj;
  }
  total = start[nj];
  PetscCall(PetscMalloc1(total + 1, &U));
  PetscCall(PetscArraycpy(U, idx, total));
  nU = total;
  PetscCall(PetscSortRemoveDupsInt(&nU, U));
  for (PetscInt l = 0; l < total; ++l) PetscCall(PetscFindInt(idx[l], nU, U, &loc[l]));
  { /* each row r of the sum from the nodes whose G_j holds U[r] (rq, ra by row, nodes ascending), its columns marked in acc */
    PetscInt  *rs, *cur, *rq, *ra, *mark, *touched, *cols;
    PetscReal *acc, *rowv;
    PetscCall(PetscCalloc2(nU + 1, &rs, nU + 1, &cur));
    PetscCall(PetscMalloc2(total + 1, &rq, total + 1, &ra));
    PetscCall(PetscMalloc5(nU + 1, &mark, nU + 1, &touched, nU + 1, &cols, nU + 1, &acc, nU + 1, &rowv));
    for (PetscInt a = 0; a < total; ++a) ++rs[loc[a] + 1];
    for (PetscInt r = 0; r < nU; ++r) {
      rs[r + 1] += rs[r];
      cur[r] = rs[r];
      mark[r] = -1;
    }
    for (PetscInt q = 0; q < nj; ++q)
      for (PetscInt a = start[q]; a < start[q + 1]; ++a) {
        rq[cur[loc[a]]]   = q;
        ra[cur[loc[a]]++] = a;
      }
    for (PetscInt r = 0; r < nU; ++r) {
      PetscInt nt = 0;
      for (PetscInt e = rs[r]; e < rs[r + 1]; ++e) {
        const PetscInt  q  = rq[e];
        const PetscReal wa = w[q] * val[ra[e]];
        for (PetscInt b = start[q]; b < start[q + 1]; ++b) {
          const PetscInt c = loc[b];
          if (mark[c] != r) {
            mark[c]       = r;
            acc[c]        = 0.0;
            touched[nt++] = c;
          }
          acc[c] += wa * val[b];
        }
      }
      PetscCall(PetscSortInt(nt, touched));
      for (PetscInt i = 0; i < nt; ++i) {
        cols[i] = U[touched[i]];
        rowv[i] = acc[touched[i]];
      }
      if (nt) PetscCall(MatSetValues(H, 1, &U[r], nt, cols, rowv, ADD_VALUES));
    }
    PetscCall(PetscFree5(mark, touched, cols, acc, rowv));
    PetscCall(PetscFree2(rq, ra));
    PetscCall(PetscFree2(rs, cur));
  }
  PetscCall(PetscFree(U));
  PetscCall(PetscFree5(start, idx, val, loc, w));
  PetscFunctionReturn(0);
}

/* This rank's entries of the Hessian into H (all[]: the faces of
   m->hessFaces, C_j, Q_j and g_j current): the Gauss-Newton blocks of the
   nodes in contact it assembles and the second-order part of its faces. */
static PetscErrorCode Mortar3dHessianAdd(Mortar3d *m, const Mortar3dFace all[], PetscMPIInt rank, Mat H)
{
  PetscFunctionBeginUser;
  PetscCall(Mortar3dAddGaussNewton(m, all, rank, H));
  if (m->exactHessian) PetscCall(Mortar3dHessianSecondOrder(m, all, H));
  if (m->exactHessian) PetscCall(Mortar3dHessianEnds(m, all, H));
  if (m->fr) PetscCall(Friction3dAddHessian(m->fr, m->S, m->spec.kp, H));
  PetscFunctionReturn(0);
}

/* Collective: whether every master face that a face of m->hessFaces meets
   now is one its pattern holds (m->covered), on every rank. */
static PetscErrorCode Mortar3dPatternCovers(Mortar3d *m, const Mortar3dFace all[], MPI_Comm comm, PetscBool *covers)
{
  PetscBool mine = PETSC_TRUE;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < m->nhess && mine; ++k)
    for (PetscInt i = 0; i < all[k].nm && mine; ++i) {
      PetscHashIJKey key;
      PetscBool      has;
      key.i = m->hessFaces[k];
      key.j = all[k].mf[i];
      PetscCall(PetscHSetIJHas(m->covered, key, &has));
      if (!has) mine = PETSC_FALSE;
    }
  PetscCall(MPIU_Allreduce(&mine, covers, 1, MPIU_BOOL, MPI_LAND, comm));
  PetscFunctionReturn(0);
}

/* Collective. The pair has slid past the pattern reserved for its Hessian
   (Mortar3dGetPattern's margin): H's preallocation is made again, once, as
   the union of its pattern and the entries this Hessian adds, its values
   so far kept, in place of PETSc's growth entry by entry, which copies the
   whole matrix at each row that overflows (minutes for one Hessian at 2e4
   dofs once a ball has slid by its contact width). The entries added are
   counted by a MATPREALLOCATOR over this pair's Hessian alone and laid out
   in an AIJ matrix (C); H's rows are then merged with C's row by row into
   one CSR (H's values, zeros at the new entries) that becomes H's
   preallocation and values at once. A MATPREALLOCATOR over the whole of H
   (every entry hashed) cost some 3 s a growth at 1e5 dofs, ten Hessians'
   worth. The master faces met join m->covered. */
static PetscErrorCode Mortar3dGrowPattern(Mortar3d *m, const Mortar3dFace all[], PetscMPIInt rank, Mat H)
{
  Mat          pre, C;
  MPI_Comm     comm;
  PetscInt     rstart, rend, mloc, nloc, M, N, rbs, cbs, *ia, *ja;
  PetscScalar *va;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(MORTAR3D_Grow, 0, 0, 0, 0));
  PetscCall(PetscObjectGetComm((PetscObject)H, &comm));
  PetscCall(MatAssemblyBegin(H, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(H, MAT_FINAL_ASSEMBLY));
  PetscCall(MatGetLocalSize(H, &mloc, &nloc));
  PetscCall(MatGetSize(H, &M, &N));
  PetscCall(MatGetBlockSizes(H, &rbs, &cbs));
  PetscCall(MatCreate(comm, &pre));
  PetscCall(MatSetSizes(pre, mloc, nloc, M, N));
  PetscCall(MatSetBlockSizes(pre, rbs, cbs));
  PetscCall(MatSetType(pre, MATPREALLOCATOR));
  PetscCall(MatSetUp(pre));
  m->counting = PETSC_TRUE;
  PetscCall(Mortar3dHessianAdd(m, all, rank, pre));
  m->counting = PETSC_FALSE;
  PetscCall(MatAssemblyBegin(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreate(comm, &C));
  PetscCall(MatSetSizes(C, mloc, nloc, M, N));
  PetscCall(MatSetBlockSizes(C, rbs, cbs));
  PetscCall(MatSetType(C, MATAIJ));
  PetscCall(MatPreallocatorPreallocate(pre, PETSC_TRUE, C));
  PetscCall(MatDestroy(&pre));
  PetscCall(MatAssemblyBegin(C, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(C, MAT_FINAL_ASSEMBLY));
  /* the union row by row: counted, then filled (both rows' columns sorted) */
  PetscCall(MatGetOwnershipRange(H, &rstart, &rend));
  PetscCall(PetscMalloc1(rend - rstart + 1, &ia));
  ia[0] = 0;
  for (PetscInt pass = 0; pass < 2; ++pass) {
    if (pass) PetscCall(PetscMalloc2(ia[rend - rstart] + 1, &ja, ia[rend - rstart] + 1, &va));
    for (PetscInt r = rstart; r < rend; ++r) {
      const PetscInt    *hc, *cc;
      const PetscScalar *hv;
      PetscInt           nh, nc, i = 0, j = 0, n = pass ? ia[r - rstart] : 0;
      PetscCall(MatGetRow(H, r, &nh, &hc, pass ? &hv : NULL));
      PetscCall(MatGetRow(C, r, &nc, &cc, NULL));
      while (i < nh || j < nc) {
        const PetscBool fromH = (PetscBool)(j == nc || (i < nh && hc[i] <= cc[j]));
        if (pass) {
          ja[n] = fromH ? hc[i] : cc[j];
          va[n] = fromH ? hv[i] : 0.0;
        }
        ++n;
        if (fromH && j < nc && hc[i] == cc[j]) ++j;
        if (fromH) ++i;
        else ++j;
      }
      if (!pass) ia[r - rstart + 1] = ia[r - rstart] + n;
      PetscCall(MatRestoreRow(C, r, &nc, &cc, NULL));
      PetscCall(MatRestoreRow(H, r, &nh, &hc, pass ? &hv : NULL));
    }
  }
  PetscCall(MatDestroy(&C));
  PetscCall(MatSeqAIJSetPreallocationCSR(H, ia, ja, va));
  PetscCall(MatMPIAIJSetPreallocationCSR(H, ia, ja, va));
  PetscCall(MatSetOption(H, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(PetscFree2(ja, va));
  PetscCall(PetscFree(ia));
  for (PetscInt k = 0; k < m->nhess; ++k)
    for (PetscInt i = 0; i < all[k].nm; ++i) {
      PetscHashIJKey key;
      key.i = m->hessFaces[k];
      key.j = all[k].mf[i];
      PetscCall(PetscHSetIJAdd(m->covered, key));
    }
  PetscCall(PetscInfo(NULL, "pair %s: slid past the Hessian's pattern (-contact_mortar_pattern_margin %g): its preallocation widened\n", m->spec.name, (double)m->patternMargin));
  PetscCall(PetscLogEventEnd(MORTAR3D_Grow, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The Hessian, its work shared by the ranks: each rank integrates its own
   slave faces and the other ranks' faces around the nodes it assembles
   (m->hessFaces: a layer one face wide along the borders between the
   ranks' parts of the surface), C_j and Q_j are its own faces' summed
   over ranks (as the gradient's), and it adds the Gauss-Newton block
   k_p G_j G_j^T / A_j of the nodes in contact that are its (m->nodeRank),
   each G_j whole from the faces around j; with the exact Hessian the
   second-order part of its own faces (Mortar3dHessianSecondOrder). */
static PetscErrorCode Mortar3dHessian(EnergyTerm t, Body bodies[], Mat H)
{
  Mortar3d         *m = (Mortar3d *)t->data;
  ContactSurface3d *S = &m->S[m->s];
  Mortar3dFace     *all;
  PetscMPIInt       size, rank;
  PetscReal        *buf;
  PetscBool         reuse;

  PetscFunctionBeginUser;
  (void)bodies;
  PetscCall(PetscLogEventBegin(MORTAR3D_Hessian, 0, 0, 0, 0));
  PetscCallMPI(MPI_Comm_rank(t->comm, &rank));
  PetscCall(Mortar3dUpdate(m));
  PetscCallMPI(MPI_Comm_size(t->comm, &size));
  PetscCall(PetscCalloc1(m->nhess + 1, &all));
  PetscCall(PetscCalloc1(2 * S->nn, &buf));
  /* on one rank, where the last energy and gradient were evaluated at these coordinates, its faces (hessFaces = ownFaces = all) */
  reuse = (PetscBool)(size == 1 && m->nhess == S->nf && S->nown == S->nf && m->ownFresh && m->ownDeriv && (m->ownPts || !m->exactHessian));
  if (reuse)
    for (PetscInt k = 0; k < S->nown; ++k) all[k] = m->own[k];
  for (PetscInt k = 0; k < m->nhess; ++k) {
    const PetscInt  f   = m->hessFaces[k];
    const PetscBool own = (PetscBool)(m->faceRank[f] == rank);
    if (!reuse) PetscCall(Mortar3dFaceEvaluate(m, f, PETSC_TRUE, (PetscBool)(own && m->exactHessian), &all[k]));
    if (!own) continue;
    for (PetscInt i = 0; i < S->nb; ++i) {
      buf[S->fnodes[S->nb * f + i]] += all[k].a[i];
      buf[S->nn + S->fnodes[S->nb * f + i]] += all[k].q[i];
    }
  }
  PetscCall(MPIU_Allreduce(buf, m->C, S->nn, MPIU_REAL, MPIU_SUM, t->comm));
  PetscCall(MPIU_Allreduce(buf + S->nn, m->Q, S->nn, MPIU_REAL, MPIU_SUM, t->comm));
  PetscCall(PetscFree(buf));
  Mortar3dNodalGaps(m);
  if (m->covered) {
    PetscBool covers;
    PetscCall(Mortar3dPatternCovers(m, all, t->comm, &covers));
    if (!covers) PetscCall(Mortar3dGrowPattern(m, all, rank, H));
  }
  PetscCall(Mortar3dHessianAdd(m, all, rank, H));
  if (!reuse)
    for (PetscInt k = 0; k < m->nhess; ++k) {
      PetscCall(PetscFree(all[k].dQ));
      PetscCall(PetscFree(all[k].pts));
      PetscCall(PetscFree(all[k].ends));
      PetscCall(PetscFree(all[k].kinks));
    }
  PetscCall(PetscFree(all));
  PetscCall(PetscLogEventEnd(MORTAR3D_Hessian, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Which rank does what for the Hessian (Mortar3dHessian), from the faces
   each rank gave (gathered once): node j is assembled by the lowest rank
   that gave a face around it (m->nodeRank), which then integrates every
   face around it (m->hessFaces: its own and, where j's faces lie on more
   than one rank, the others' next to the border); the search decides
   which of those to integrate from the faces that share a node with them
   (m->queryFaces, Mortar3dUpdate). One rank: every face, every node. */
static PetscErrorCode Mortar3dSetUpHessianFaces(Mortar3d *m, MPI_Comm comm)
{
  const ContactSurface3d *S = &m->S[m->s];
  PetscMPIInt             size, rank, nown = (PetscMPIInt)S->nown, *cnt, *disp;
  PetscInt               *allOwn, *mark, nshared = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMalloc2(size, &cnt, size + 1, &disp));
  PetscCallMPI(MPI_Allgather(&nown, 1, MPI_INT, cnt, 1, MPI_INT, comm));
  disp[0] = 0;
  for (PetscMPIInt r = 0; r < size; ++r) disp[r + 1] = disp[r] + cnt[r];
  PetscCheck(disp[size] == S->nf, comm, PETSC_ERR_PLIB, "contact pair %s: the ranks gave %d slave faces of %" PetscInt_FMT, m->spec.name, disp[size], S->nf);
  PetscCall(PetscMalloc1(S->nf + 1, &allOwn));
  PetscCallMPI(MPI_Allgatherv(S->ownFaces, nown, MPIU_INT, allOwn, cnt, disp, MPIU_INT, comm));
  PetscCall(PetscMalloc3(S->nf, &m->faceRank, S->nf, &m->hessSlot, S->nn, &m->nodeRank));
  PetscCall(PetscMalloc1(S->nf, &mark));
  for (PetscMPIInt r = 0; r < size; ++r)
    for (PetscInt k = disp[r]; k < disp[r + 1]; ++k) m->faceRank[allOwn[k]] = r;
  PetscCall(PetscFree(allOwn));
  PetscCall(PetscFree2(cnt, disp));
  for (PetscInt j = 0; j < S->nn; ++j) {
    PetscInt lo = size, hi = -1;
    for (PetscInt r = m->nodeFaceStart[j]; r < m->nodeFaceStart[j + 1]; ++r) {
      lo = PetscMin(lo, m->faceRank[m->nodeFace[r]]);
      hi = PetscMax(hi, m->faceRank[m->nodeFace[r]]);
    }
    m->nodeRank[j] = lo;
    if (hi > lo) nshared++;
  }
  for (PetscInt f = 0; f < S->nf; ++f) mark[f] = m->faceRank[f] == rank;
  for (PetscInt j = 0; j < S->nn; ++j)
    if (m->nodeRank[j] == rank)
      for (PetscInt r = m->nodeFaceStart[j]; r < m->nodeFaceStart[j + 1]; ++r) mark[m->nodeFace[r]] = 1;
  m->nhess = 0;
  for (PetscInt f = 0; f < S->nf; ++f) m->nhess += mark[f] ? 1 : 0;
  PetscCall(PetscMalloc1(m->nhess + 1, &m->hessFaces));
  m->nhess = 0;
  for (PetscInt f = 0; f < S->nf; ++f) {
    m->hessSlot[f] = mark[f] ? m->nhess : -1;
    if (mark[f]) m->hessFaces[m->nhess++] = f;
  }
  for (PetscInt k = 0; k < m->nhess; ++k) /* the faces sharing a node with a face integrated */
    for (PetscInt i = 0; i < S->nb; ++i) {
      const PetscInt j = S->fnodes[S->nb * m->hessFaces[k] + i];
      for (PetscInt r = m->nodeFaceStart[j]; r < m->nodeFaceStart[j + 1]; ++r) mark[m->nodeFace[r]] = 1;
    }
  m->nquery = 0;
  for (PetscInt f = 0; f < S->nf; ++f) m->nquery += mark[f] ? 1 : 0;
  PetscCall(PetscMalloc1(m->nquery + 1, &m->queryFaces));
  m->nquery = 0;
  for (PetscInt f = 0; f < S->nf; ++f)
    if (mark[f]) m->queryFaces[m->nquery++] = f;
  PetscCall(PetscFree(mark));
  PetscCall(PetscInfo(NULL, "pair %s: %" PetscInt_FMT " slave nodes with faces on more than one rank; this rank integrates %" PetscInt_FMT " faces for the Hessian (%" PetscInt_FMT " its own), searches from %" PetscInt_FMT " of %" PetscInt_FMT "\n", m->spec.name, nshared, m->nhess, S->nown, m->nquery, S->nf));
  PetscFunctionReturn(0);
}

/* The slave's constants: the dual coefficients of each face and A_j =
   int W_j dS over the whole surface (reference), the slave faces at each
   node, the penalty. */
static PetscErrorCode Mortar3dSetUpSlave(Mortar3d *m)
{
  const ContactSurface3d *S = &m->S[m->s];
  PetscInt               *cnt;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(81 * S->nf, &m->Adual));
  PetscCall(PetscCalloc5(S->nn, &m->A, S->nn, &m->C, S->nn, &m->Q, S->nn, &m->gj, S->nn, &m->active));
  for (PetscInt f = 0; f < S->nf; ++f) {
    PetscReal X[27], W[FACE3D_MAX_NODES];
    ContactSurface3dFaceCoords(S, f, S->X, X);
    PetscCall(Face3dDualCoefficients(S->type, X, &m->frule, &m->Adual[81 * f]));
    for (PetscInt q = 0; q < m->frule.nq; ++q) {
      PetscReal x[3], T[6], nrm[3], dS;
      Face3dEval(S->type, X, &m->frule.xi[2 * q], x, T, NULL);
      dS = Face3dNormal(T, nrm) * m->frule.w[q];
      Face3dWeights(S->type, &m->Adual[81 * f], &m->frule.xi[2 * q], W);
      for (PetscInt i = 0; i < S->nb; ++i) m->A[S->fnodes[S->nb * f + i]] += W[i] * dS;
    }
  }
  PetscCall(PetscCalloc2(S->nn + 1, &m->nodeFaceStart, S->nb * S->nf, &m->nodeFace));
  PetscCall(PetscCalloc1(S->nn, &cnt));
  for (PetscInt k = 0; k < S->nb * S->nf; ++k) m->nodeFaceStart[S->fnodes[k] + 1]++;
  for (PetscInt j = 0; j < S->nn; ++j) m->nodeFaceStart[j + 1] += m->nodeFaceStart[j];
  for (PetscInt f = 0; f < S->nf; ++f)
    for (PetscInt i = 0; i < S->nb; ++i) {
      const PetscInt j = S->fnodes[S->nb * f + i];
      m->nodeFace[m->nodeFaceStart[j] + cnt[j]++] = f;
    }
  PetscCall(PetscFree(cnt));
  PetscCall(PetscCalloc1(S->nown + 1, &m->own));
  PetscCall(PetscCalloc2(S->nn, &m->nearNode, S->nf, &m->integrate));
  m->spec.kpH = S->hmin;
  if (m->spec.kpAuto) m->spec.kp = CONTACT_PENALTY_AUTO * m->spec.Estar / S->hmin;
  m->kp = m->spec.kp;
  PetscCall(PetscInfo(NULL, "pair %s (3D): slave surface '%s', k_p = %g (h = %g, E* = %g)\n", m->spec.name, S->group, (double)m->kp, (double)S->hmin, (double)m->spec.Estar));
  PetscFunctionReturn(0);
}

/* The 3D pairs' own options (listed by -help whether or not a pair is 3D). */
PetscErrorCode ContactMortar3dOptionsRead(MPI_Comm comm, PetscReal *margin, PetscInt *edgePoints)
{
  PetscFunctionBeginUser;
  *margin     = 2.0;
  *edgePoints = 0;
  PetscOptionsBegin(comm, NULL, "3D mortar contact options", NULL);
  PetscCall(PetscOptionsReal("-contact_mortar_pattern_margin", "3D pairs: the Hessian's preallocated pattern couples a slave face with the master faces within this many face sizes of it (the smaller of the two faces'), at rest (the solve's sliding; beyond it the Hessian's preallocation is widened; negative: the faces' own boxes shrunk)", NULL, *margin, margin, NULL));
  PetscCall(PetscOptionsInt("-contact_mortar_edge_points", "3D pairs: points along each master edge between two faces, projected onto the slave as its nodes are, so that the pieces' borders follow the edge's curved image, where the gap's gradient jumps (the Hessian's Taylor test then of order 2 to round-off on a stiff master, to about 1e-8 on one as soft as the slave; at 3 the mortar's energy and gradient take about 2.6 times as long, the quarter Hertz ball's run 1.5 times); 0: straight between the nodes", NULL, *edgePoints, edgePoints, NULL));
  PetscOptionsEnd();
  PetscCheck(!PetscIsInfOrNanReal(*margin), comm, PETSC_ERR_ARG_OUTOFRANGE, "option -contact_mortar_pattern_margin: must be a finite number, got %g", (double)*margin);
  PetscCheck(*edgePoints >= 0 && *edgePoints <= SEGMENT3D_MAX_EDGE_POINTS, comm, PETSC_ERR_USER_INPUT, "option -contact_mortar_edge_points: must be in [0, %d], got %" PetscInt_FMT, SEGMENT3D_MAX_EDGE_POINTS, *edgePoints);
  PetscFunctionReturn(0);
}

/* -contact_mortar_slave: first, second or auto (both is 2D's alone). auto,
   as in 2D (mortar.c, MortarChooseSlaves): a surface that ends on the
   other (a punch's face on a block: its border is where the pressure is
   singular, and as slave its border nodes carry it), else the softer
   body's by E/(1 - nu^2), else the first named. Between a rigid and an
   elastic body the elastic body's surface is the slave: a rigid flat
   punch's face as slave gave P/delta 3.5 % and 2.2 % from Boussinesq at
   h = a/6 and a/10, as master 0.64 % and 0.34 % (tests/test_rigid3d.py). */
static PetscErrorCode Mortar3dChooseSlave(Mortar3d *m)
{
  char      value[64] = "auto";
  PetscBool set, first, second, autoc;
  PetscReal E[2], nu[2];

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-contact_mortar_slave", value, sizeof(value), &set));
  PetscCall(PetscStrcmp(value, "first", &first));
  PetscCall(PetscStrcmp(value, "second", &second));
  PetscCall(PetscStrcmp(value, "auto", &autoc));
  PetscCheck(first || second || autoc, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "option -contact_mortar_slave %s: contact pair %s is 3D, where the slave is first, second or auto", value, m->spec.name);
  for (PetscInt k = 0; k < 2; ++k) BodyGetElasticConstants(m->body[k], &E[k], &nu[k]);
  if (first) m->s = 0;
  else if (second) m->s = 1;
  else {
    PetscBool *bnd[2], on[2];
    for (PetscInt k = 0; k < 2; ++k) PetscCall(ContactSurface3dBorderNodes(&m->S[k], &bnd[k]));
    for (PetscInt k = 0; k < 2; ++k) PetscCall(ContactSurface3dEndsOn(&m->S[k], bnd[k], &m->S[1 - k], bnd[1 - k], 0.05 * m->S[k].hmin, &on[k]));
    for (PetscInt k = 0; k < 2; ++k) PetscCall(PetscFree(bnd[k]));
    for (PetscInt k = 0; k < 2; ++k) on[k] = (PetscBool)(on[k] && BodyHasCells(m->body[0]) && BodyHasCells(m->body[1])); /* a rigid face is the master */
    if (on[0] != on[1]) m->s = on[0] ? 0 : 1;
    else m->s = E[1] / (1 - nu[1] * nu[1]) < E[0] / (1 - nu[0] * nu[0]) ? 1 : 0;
    PetscCall(PetscInfo(NULL, "pair %s: slave %s (%s)\n", m->spec.name, m->spec.group[m->s], on[0] != on[1] ? "it ends on the other surface" : on[0] ? "both end on the other; the softer body, else the first named" : "neither ends on the other; the softer body, else the first named"));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dSetUp(EnergyTerm t, Body bodies[])
{
  Mortar3d *m = (Mortar3d *)t->data;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < 2; ++k) {
    m->body[k]    = bodies[m->spec.body[k]];
    m->S[k].body  = m->spec.body[k];
    PetscCall(PetscStrncpy(m->S[k].group, m->spec.group[k], sizeof(m->S[k].group)));
    PetscCheck(BodyGetDimension(m->body[k]) == 3, t->comm, PETSC_ERR_USER_INPUT, "contact pair %s: body %s is not a 3D body (a 3D pair joins two)", m->spec.name, BodyGetName(m->body[k]));
  }
  PetscCheck(BodyHasCells(m->body[0]) || BodyHasCells(m->body[1]), t->comm, PETSC_ERR_USER_INPUT, "contact pair %s: bodies %s and %s are both rigid: a contact between them has no elastic side", m->spec.name, BodyGetName(m->body[0]), BodyGetName(m->body[1]));
  for (PetscInt k = 0; k < 2; ++k) PetscCall(ContactSurface3dSetUp(&m->S[k], m->body[k], m->spec.name));
  PetscCall(Mortar3dChooseSlave(m));
  PetscCall(ContactMortar3dOptionsRead(t->comm, &m->patternMargin, &m->edgePoints));
  PetscCall(Face3dRuleCreate(FACE3D_TRI6, 2 * m->spec.nqp - 1 > 6 ? 2 * m->spec.nqp - 1 : 6, &m->rule)); /* the pieces': degree 7 at the default 4 points */
  PetscCall(Face3dRuleCreate(m->S[m->s].type, 10, &m->frule));
  PetscCall(PetscMalloc2(6 * m->S[1 - m->s].nf, &m->boxes, 27 * MORTAR3D_MAX_MASTER, &m->xm));
  PetscCall(Mortar3dSetUpSlave(m));
  PetscCall(Mortar3dSetUpHessianFaces(m, t->comm));
  if (m->fr) PetscCall(Friction3dSetUp(m->fr, m->S, m->s));
  if (m->fr) PetscCall(Friction3dCheckGivenForces(m->fr, m->spec.name, m->body));
  if (m->fr) PetscCall(Friction3dChooseStart(m->fr, m->body));
  PetscFunctionReturn(0);
}

/* The report's figures (report3d.c) from the slave's nodal pressures, on
   every rank (each holds the slave's sums whole). */
static PetscErrorCode Mortar3dReport(Mortar3d *m)
{
  const ContactSurface3d *S = &m->S[m->s];
  PetscReal              *p;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(S->nn + 1, &p));
  for (PetscInt j = 0; j < S->nn; ++j) p[j] = m->active[j] && m->gj[j] < 0 ? -m->kp * m->gj[j] : 0.0;
  ContactReport3dCompute(&m->spec, S->nn, S->X, p, m->A, m->force[0], m->fr ? m->shearForce : NULL, &m->report);
  {
    const ContactSurface3d *M = &m->S[1 - m->s];
    PetscBool              *bnd[2];
    PetscReal              *Xb;
    PetscInt                nb = 0;
    for (PetscInt k = 0; k < 2; ++k) PetscCall(ContactSurface3dBorderNodes(&m->S[k], &bnd[k]));
    PetscCall(PetscMalloc1(3 * M->nn + 1, &Xb));
    for (PetscInt j = 0; j < M->nn; ++j)
      if (bnd[1 - m->s][j]) {
        for (PetscInt d = 0; d < 3; ++d) Xb[3 * nb + d] = M->X[3 * j + d];
        nb++;
      }
    ContactReport3dCuts(&m->spec, S->nn, S->X, p, bnd[m->s], nb, Xb, &m->report);
    PetscCall(PetscFree(Xb));
    for (PetscInt k = 0; k < 2; ++k) PetscCall(PetscFree(bnd[k]));
  }
  PetscCall(PetscFree(p));
  PetscFunctionReturn(0);
}

/* The results at the state in the bodies' local vectors: the pair's force
   on each surface's body (minus the gradient on its nodes), the nodal
   pressures p_j = k_p <-g_j>_+ of the nodes counted, the deepest weighted
   penetration, and the contact area sum A_j over the nodes in contact. */
static PetscErrorCode Mortar3dPostProcess(EnergyTerm t, Body bodies[])
{
  Mortar3d               *m = (Mortar3d *)t->data;
  const ContactSurface3d *S = &m->S[m->s];
  PetscReal               e;

  PetscFunctionBeginUser;
  (void)bodies;
  PetscCall(Mortar3dEvaluate(m, PETSC_TRUE, PETSC_FALSE, &e));
  for (PetscInt k = 0; k < 2; ++k) {
    const ContactSurface3d *T = &m->S[k];
    for (PetscInt d = 0; d < 3; ++d) m->force[k][d] = 0.0;
    for (PetscInt v = 0; v < T->nn; ++v)
      for (PetscInt d = 0; d < 3; ++d) m->force[k][d] -= T->gsum[3 * v + d];
  }
  m->pmax = m->maxPen = m->area = 0.0;
  m->pmin = PETSC_MAX_REAL;
  m->ncontact = m->nactive = 0;
  for (PetscInt j = 0; j < S->nn; ++j) {
    if (!m->active[j]) continue;
    m->nactive++;
    if (!(m->gj[j] < 0)) continue;
    m->ncontact++;
    m->pmax   = PetscMax(m->pmax, -m->kp * m->gj[j]);
    m->pmin   = PetscMin(m->pmin, -m->kp * m->gj[j]);
    m->maxPen = PetscMax(m->maxPen, -m->gj[j]);
    m->area += m->A[j];
  }
  if (!m->ncontact) m->pmin = 0.0;
  if (m->fr) PetscCall(Mortar3dFrictionResults(m));
  PetscCall(PetscInfo(NULL, "pair %s: this rank's search held up to %" PetscInt_FMT " of the %" PetscInt_FMT " master faces (%" PetscInt_FMT " now)\n", m->spec.name, m->nmasterMax, m->S[1 - m->s].nf, m->nmaster));
  PetscCall(Mortar3dReport(m));
  if (m->fr) ContactReport3dFriction(Friction3dGetCoefficient(m->fr), m->stickArea, &m->report);
  m->done = PETSC_TRUE;
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dView(EnergyTerm t, Body bodies[])
{
  const Mortar3d *m = (const Mortar3d *)t->data;
  const PetscReal *F = m->force[0];

  PetscFunctionBeginUser;
  if (!m->done) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(t->comm, "Contact pair %s (mortar, 3D; slave %s:%s, %" PetscInt_FMT " %s faces; master %s:%s, %" PetscInt_FMT " faces), k_p %.6g:\n", m->spec.name, BodyGetName(bodies[m->spec.body[m->s]]), m->spec.group[m->s], m->S[m->s].nf, m->S[m->s].nb == 6 ? "Tri6" : "Quad9",
                        BodyGetName(bodies[m->spec.body[1 - m->s]]), m->spec.group[1 - m->s], m->S[1 - m->s].nf, (double)m->kp));
  PetscCall(PetscPrintf(t->comm, "  force on %s: (%.6g, %.6g, %.6g), |F| %.6g; nodal pressure %.6g to %.6g at %" PetscInt_FMT " of %" PetscInt_FMT " slave nodes, contact area %.6g, deepest weighted penetration %.3g\n", BodyGetName(bodies[m->spec.body[0]]), (double)F[0], (double)F[1], (double)F[2],
                        (double)PetscSqrtReal(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]), (double)m->pmin, (double)m->pmax, m->ncontact, m->S[m->s].nn, (double)m->area, (double)m->maxPen));
  if (m->fr) {
    const PetscReal mu = Friction3dGetCoefficient(m->fr);
    PetscCall(PetscPrintf(t->comm, "  friction mu %g: shear force (%.6g, %.6g, %.6g), Q/(mu P) = %.6g (P %.6g, Q %.6g); stick zone area %.6g, the radius of a disc of it %.6g (of the contact's area %.6g: %.6g)\n", (double)mu, (double)m->shearForce[0], (double)m->shearForce[1], (double)m->shearForce[2],
                          (double)(m->normalLoad > 0 ? m->tangentialLoad / (mu * m->normalLoad) : 0.0), (double)m->normalLoad, (double)m->tangentialLoad, (double)m->stickArea, (double)m->stickRadius, (double)m->area, (double)PetscSqrtReal(m->area / PETSC_PI)));
  }
  PetscCall(ContactReport3dView(&m->report, &m->spec, t->comm));
  PetscFunctionReturn(0);
}

/* Rank 0. summary: the top-level figures; else the pair's object. */
static PetscErrorCode Mortar3dWriteJSON(EnergyTerm t, Body bodies[], FILE *fp, PetscBool summary)
{
  const Mortar3d  *m = (const Mortar3d *)t->data;
  const PetscReal *F = m->force[0];

  PetscFunctionBeginUser;
  if (summary) {
    ContactReport3dWriteJSON(&m->report, &m->spec, fp, ",\n  ", "contact_force");
    ContactJSONKeyReal(fp, ",\n  ", "max_penetration", m->maxPen);
    PetscFunctionReturn(0);
  }
  fprintf(fp, "{\"formulation\": \"%s\", \"dimension\": 3", m->spec.formulation);
  ContactJSONKeyReal(fp, ", ", "penalty", m->kp);
  fprintf(fp, ", \"penalty_auto\": %s", m->spec.kpAuto ? "true" : "false");
  ContactJSONKeyReal(fp, ", ", "penalty_h", m->spec.kpH);
  ContactJSONKeyReal(fp, ", ", "penalty_stiffness", ContactPairPenaltyStiffness(&m->spec));
  ContactJSONKeyVector(fp, ", ", "force", 3, F);
  ContactReport3dWriteJSON(&m->report, &m->spec, fp, ", ", "P");
  ContactJSONKeyReal(fp, ", ", "pmax", m->pmax);
  ContactJSONKeyReal(fp, ", ", "pmin", m->pmin);
  fprintf(fp, ", \"nodes_in_contact\": %d, \"nodes_counted\": %d", (int)m->ncontact, (int)m->nactive);
  ContactJSONKeyReal(fp, ", ", "max_penetration", m->maxPen);
  fprintf(fp, ", \"hessian\": \"%s\"", m->exactHessian ? "exact" : "gauss-newton"); /* at the solve's end */
  ContactJSONKeyReal(fp, ", ", "friction", m->fr ? Friction3dGetCoefficient(m->fr) : 0.0);
  if (m->fr) {
    ContactJSONKeyVector(fp, ", ", "shear_force", 3, m->shearForce);
    ContactJSONKeyReal(fp, ", ", "normal_load", m->normalLoad);
    ContactJSONKeyReal(fp, ", ", "tangential_load", m->tangentialLoad);
    ContactJSONKeyReal(fp, ", ", "stick_area", m->stickArea);
    ContactJSONKeyReal(fp, ", ", "stick_radius", m->stickRadius);
    ContactReport3dWriteFrictionJSON(&m->report, fp, ", ");
  }
  { /* the slave nodes in contact: reference position, pressure, weight A_j */
    const ContactSurface3d *S = &m->S[m->s];
    PetscInt                n = 0;
    fprintf(fp, ", \"contact_nodes\": {\"columns\": [\"X\", \"Y\", \"Z\", \"p\", \"A\"], \"rows\": [");
    for (PetscInt j = 0; j < S->nn; ++j) {
      const PetscReal row[5] = {S->X[3 * j], S->X[3 * j + 1], S->X[3 * j + 2], -m->kp * m->gj[j], m->A[j]};
      if (!m->active[j] || !(m->gj[j] < 0)) continue;
      fprintf(fp, "%s[", n++ ? ", " : "");
      for (PetscInt k = 0; k < 5; ++k) {
        if (k) fprintf(fp, ", ");
        ContactJSONReal(fp, row[k]);
      }
      fprintf(fp, "]");
    }
    fprintf(fp, "]}");
  }
  fprintf(fp, ", \"surfaces\": [");
  for (PetscInt k = 0; k < 2; ++k) {
    const ContactSurface3d *T = &m->S[k];
    fprintf(fp, "%s{\"body\": \"%s\", \"group\": \"%s\", \"faces\": %d, \"face_type\": \"%s\", \"nodes\": %d, \"slave\": %s", k ? ", " : "", BodyGetName(bodies[m->spec.body[k]]), m->spec.group[k], (int)T->nf, T->nb == 6 ? "Tri6" : "Quad9", (int)T->nn, k == m->s ? "true" : "false");
    ContactJSONKeyVector(fp, ", ", "force", 3, m->force[k]);
    fprintf(fp, "}");
  }
  fprintf(fp, "]}");
  PetscFunctionReturn(0);
}

/* The report's figures as attributes of the pair's group (report3d.c):
   model_share, contact_area and P the whole model's, fem_a (from the area),
   fem_a_moment, and with Hertz radii E_star, R_star, hertz_a, hertz_pmax,
   pressure_l2_error. */
static PetscErrorCode Mortar3dWriteHDF5Report(const Mortar3d *m, PetscViewer v, const char group[])
{
  const ContactReport3d *R = &m->report;
  const char            *names[] = {"model_share", "contact_area", "fem_a", "fem_a_moment", "E_star", "R_star", "hertz_a", "hertz_pmax", "pressure_l2_error"};
  const PetscReal        vals[]  = {R->share, R->area, R->aArea, R->aMoment, m->spec.Estar, m->spec.Rstar, R->hertzA, R->hertzP0, R->l2err};
  const char            *more[CONTACT_REPORT3D_ATTRS];
  PetscReal              mval[CONTACT_REPORT3D_ATTRS];
  const PetscInt         nmore = ContactReport3dAttributes(R, more, mval);

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < (m->spec.hertz ? 9 : 4); ++k) ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, names[k], PETSC_REAL, &vals[k]));
  for (PetscInt k = 0; k < nmore; ++k) ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, more[k], PETSC_REAL, &mval[k]));
  PetscFunctionReturn(0);
}

/* Collective: rank 0's n tuples of bs values as dataset name in v's current
   group (an n x bs dataset where bs > 1), the other ranks none. */
static PetscErrorCode Mortar3dWriteArray(PetscViewer v, MPI_Comm comm, const char name[], PetscInt n, PetscInt bs, const PetscReal val[])
{
  Vec          vec;
  PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(VecCreate(comm, &vec));
  PetscCall(VecSetSizes(vec, n * bs, PETSC_DETERMINE));
  PetscCall(VecSetBlockSize(vec, bs));
  PetscCall(VecSetType(vec, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)vec, name));
  PetscCall(VecGetArray(vec, &a));
  for (PetscInt i = 0; i < n * bs; ++i) a[i] = val[i];
  PetscCall(VecRestoreArray(vec, &a));
  ContactOutputCall(v, VecView(vec, v));
  PetscCall(VecDestroy(&vec));
  PetscFunctionReturn(0);
}

/* The slave's friction sets into the viewer's current group (rank 0's n
   nodes, the others none): node_shear (3 components: the shear traction the
   master puts on the slave, per unit of the slave's reference measure as
   node_pressure), node_slip (3: the accumulated slip of the slave against
   the master) and node_stick (1 stuck, 0 slipping or apart); the same at
   each earlier stage's end (-load_stages) under /stages/<k>/contact/... */
static PetscErrorCode Mortar3dWriteFrictionHDF5(const Mortar3d *m, Body bodies[], PetscViewer v, MPI_Comm comm, PetscInt n)
{
  const PetscReal *shear, *slip, *stick;
  PetscInt         nstage;
  char             group[4 * CONTACT_NAME_LEN + 32];

  PetscFunctionBeginUser;
  PetscCall(Friction3dGetNodal(m->fr, 0, &shear, &slip, &stick, &nstage));
  PetscCall(Mortar3dWriteArray(v, comm, "node_shear", n, 3, shear));
  PetscCall(Mortar3dWriteArray(v, comm, "node_slip", n, 3, slip));
  PetscCall(Mortar3dWriteArray(v, comm, "node_stick", n, 1, stick));
  for (PetscInt k = 1; k < nstage; ++k) { /* the last stage's are the sets above */
    PetscCall(Friction3dGetNodal(m->fr, k, &shear, &slip, &stick, &nstage));
    PetscCall(PetscSNPrintf(group, sizeof(group), "/stages/%d/contact/%s/%s_%s", (int)k, m->spec.name, BodyGetName(bodies[m->spec.body[m->s]]), m->spec.group[m->s]));
    PetscCall(PetscViewerHDF5PushGroup(v, group));
    PetscCall(Mortar3dWriteArray(v, comm, "node_shear", n, 3, shear));
    PetscCall(Mortar3dWriteArray(v, comm, "node_slip", n, 3, slip));
    PetscCall(Mortar3dWriteArray(v, comm, "node_stick", n, 1, stick));
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  PetscFunctionReturn(0);
}

/* The slave surface, /contact/<pair>/<body>_<group>/, from rank 0 (every
   rank holds it whole; the others write nothing): its nodes' reference and
   current coordinates node_X, node_x, their displacement
   node_displacement (x - X), the nodal pressure node_pressure (p_j =
   k_p <-g_j>_+, 0 where apart or not counted), the weighted gap node_gap
   (g_j; NaN where the node is not counted, C_j < A_j / 2), the weight
   node_weight (A_j), the pair's force on each node node_force (3
   components, minus the gradient there: sum p_j A_j over the surface's z
   is the pair's force), its faces node_cells (Tri6 or Quad9, Gmsh's node
   order, which is XDMF's), xdmf_nan (the bodies' stresses there, xdmf.h);
   as attributes its body, group, face_type ("Triangle_6" or
   "Quadrilateral_9"), slave (1) and surface_index. The pair's figures as
   attributes of /contact/<pair>: formulation, dimension (3), penalty, P,
   force (3), fem_pmax, contact_area, max_penetration, as the JSON has them
   (every rank holds them: collective). */
static PetscErrorCode Mortar3dWriteHDF5(EnergyTerm t, Body bodies[], PetscViewer v)
{
  const Mortar3d         *m = (const Mortar3d *)t->data;
  const ContactSurface3d *S = &m->S[m->s];
  const PetscReal        *F = m->force[0];
  const PetscInt          dim = 3;
  MPI_Comm                comm;
  PetscMPIInt             rank;
  PetscInt                n, nf;
  PetscReal              *u, *p, *g, *f, *nan;
  char                    group[4 * CONTACT_NAME_LEN];

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)v, &comm));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  n  = rank ? 0 : S->nn;
  nf = rank ? 0 : S->nf;
  PetscCall(PetscMalloc5(3 * n + 1, &u, n + 1, &p, n + 1, &g, 3 * n + 1, &f, n + 1, &nan));
  for (PetscInt j = 0; j < n; ++j) {
    const PetscBool in = (PetscBool)(m->active[j] && m->gj[j] < 0);
    p[j]               = in ? -m->kp * m->gj[j] : 0.0;
    g[j]               = m->active[j] ? m->gj[j] : (PetscReal)NAN;
    nan[j]             = (PetscReal)NAN;
    for (PetscInt d = 0; d < 3; ++d) {
      u[3 * j + d] = S->x[3 * j + d] - S->X[3 * j + d];
      f[3 * j + d] = -S->gsum[3 * j + d];
    }
  }
  PetscCall(PetscSNPrintf(group, sizeof(group), "/contact/%s/%s_%s", m->spec.name, BodyGetName(bodies[m->spec.body[m->s]]), m->spec.group[m->s]));
  PetscCall(PetscViewerHDF5PushGroup(v, group));
  PetscCall(Mortar3dWriteArray(v, comm, "node_X", n, 3, S->X));
  PetscCall(Mortar3dWriteArray(v, comm, "node_x", n, 3, S->x));
  PetscCall(Mortar3dWriteArray(v, comm, "node_displacement", n, 3, u));
  PetscCall(Mortar3dWriteArray(v, comm, "node_pressure", n, 1, p));
  PetscCall(Mortar3dWriteArray(v, comm, "node_gap", n, 1, g));
  PetscCall(Mortar3dWriteArray(v, comm, "node_weight", n, 1, m->A));
  PetscCall(Mortar3dWriteArray(v, comm, "node_force", n, 3, f));
  PetscCall(Mortar3dWriteArray(v, comm, "xdmf_nan", n, 1, nan));
  {
    PetscReal *nan3;
    PetscCall(PetscMalloc1(3 * n + 1, &nan3));
    for (PetscInt j = 0; j < 3 * n; ++j) nan3[j] = (PetscReal)NAN;
    PetscCall(Mortar3dWriteArray(v, comm, "xdmf_nan_xyz", n, 3, nan3));
    PetscCall(PetscFree(nan3));
  }
  if (m->fr) PetscCall(Mortar3dWriteFrictionHDF5(m, bodies, v, comm, n));
  {
    IS is;
    PetscCall(ISCreateGeneral(comm, nf * S->nb, S->fnodes, PETSC_USE_POINTER, &is));
    PetscCall(ISSetBlockSize(is, S->nb));
    PetscCall(PetscObjectSetName((PetscObject)is, "node_cells"));
    ContactOutputCall(v, ISView(is, v));
    PetscCall(ISDestroy(&is));
  }
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "body", PETSC_STRING, BodyGetName(bodies[m->spec.body[m->s]])));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "group", PETSC_STRING, m->spec.group[m->s]));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "face_type", PETSC_STRING, S->type == FACE3D_TRI6 ? "Triangle_6" : "Quadrilateral_9"));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "slave", PETSC_INT, &(PetscInt){1}));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "surface_index", PETSC_INT, &m->s));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(PetscFree5(u, p, g, f, nan));
  PetscCall(PetscSNPrintf(group, sizeof(group), "/contact/%s", m->spec.name));
  PetscCall(PetscViewerHDF5PushGroup(v, group));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "formulation", PETSC_STRING, m->spec.formulation));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "dimension", PETSC_INT, &dim));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "penalty", PETSC_REAL, &m->kp));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "P", PETSC_REAL, &m->report.P));
  for (PetscInt d = 0; d < 3; ++d) {
    const char *names[3] = {"force_x", "force_y", "force_z"};
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, names[d], PETSC_REAL, &F[d]));
  }
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "fem_pmax", PETSC_REAL, &m->pmax));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "max_penetration", PETSC_REAL, &m->maxPen));
  if (m->fr) {
    const PetscReal mu = Friction3dGetCoefficient(m->fr);
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "friction", PETSC_REAL, &mu));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "normal_load", PETSC_REAL, &m->normalLoad));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "tangential_load", PETSC_REAL, &m->tangentialLoad));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "stick_area", PETSC_REAL, &m->stickArea));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "stick_radius", PETSC_REAL, &m->stickRadius));
  }
  PetscCall(Mortar3dWriteHDF5Report(m, v, group));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscFunctionReturn(0);
}

/* Rank 0. The slave surface as a grid of its faces (Triangle_6 or
   Quadrilateral_9) named <pair>:<body>:<group>, on its nodes' reference
   coordinates with their displacement, as the bodies' grids are (so Warp
   By Vector moves it with them), with the 3D contact fields (xdmf.h):
   pressure, gap, weight and force; NaN for the bodies' stresses. */
static PetscErrorCode Mortar3dWriteXDMF(EnergyTerm t, Body bodies[], FILE *fp, const char h5[], PetscBool friction)
{
  const Mortar3d         *m = (const Mortar3d *)t->data;
  const ContactSurface3d *S = &m->S[m->s];
  const char             *body = BodyGetName(bodies[m->spec.body[m->s]]), *grp = m->spec.group[m->s];
  const char             *names[XDMF_CONTACT_SCALARS_3D] = {"node_pressure", "node_gap", "node_weight"};
  const int               nn = (int)S->nn;
  char                    g[4 * CONTACT_NAME_LEN + PETSC_MAX_PATH_LEN], path[sizeof(g) + 32];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(g, sizeof(g), "%s:/contact/%s/%s_%s/", h5, m->spec.name, body, grp));
  fprintf(fp, "   <Grid Name=\"%s:%s:%s\" GridType=\"Uniform\">\n", m->spec.name, body, grp);
  fprintf(fp, "    <Topology TopologyType=\"%s\" NumberOfElements=\"%d\">\n", S->type == FACE3D_TRI6 ? "Triangle_6" : "Quadrilateral_9", (int)S->nf);
  fprintf(fp, "     <DataItem Dimensions=\"%d %d\" NumberType=\"Int\" Precision=\"%d\" Format=\"HDF\">%snode_cells</DataItem>\n    </Topology>\n", (int)S->nf, (int)S->nb, (int)sizeof(PetscInt), g);
  fprintf(fp, "    <Geometry GeometryType=\"XYZ\">\n     <DataItem Dimensions=\"%d 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%snode_X</DataItem>\n    </Geometry>\n", nn, g);
  PetscCall(PetscSNPrintf(path, sizeof(path), "%snode_displacement", g));
  XdmfWriteAttribute(fp, "displacement", nn, 3, path);
  for (PetscInt k = 0; k < XDMF_CONTACT_SCALARS_3D; ++k) {
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s%s", g, names[k]));
    XdmfWriteAttribute(fp, XdmfContactScalars3D[k], nn, 1, path);
  }
  PetscCall(PetscSNPrintf(path, sizeof(path), "%snode_force", g));
  XdmfWriteAttribute(fp, XDMF_CONTACT_VECTOR_3D, nn, 3, path);
  PetscCall(PetscSNPrintf(path, sizeof(path), "%sxdmf_nan", g));
  for (PetscInt k = 0; k < XDMF_BODY_SCALARS_3D; ++k) XdmfWriteAttribute(fp, XdmfBodyScalars3D[k], nn, 1, path);
  for (PetscInt k = 0; k < XDMF_FRICTION_FIELDS_3D && friction; ++k) { /* this pair's, else NaN (xdmf.h) */
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s%s", g, m->fr ? XdmfFrictionSets3D[k] : (XdmfFrictionComponents3D[k] == 3 ? "xdmf_nan_xyz" : "xdmf_nan")));
    XdmfWriteAttribute(fp, XdmfFrictionFields3D[k], nn, XdmfFrictionComponents3D[k], path);
  }
  fprintf(fp, "   </Grid>\n");
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dGetDofs(EnergyTerm t, PetscInt *n, PetscInt **idx)
{
  const Mortar3d *m = (const Mortar3d *)t->data;
  PetscInt        c = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(3 * (m->S[0].nn + m->S[1].nn) + 1, idx));
  for (PetscInt k = 0; k < 2; ++k)
    for (PetscInt v = 0; v < 3 * m->S[k].nn; ++v)
      if (m->S[k].big[v] >= 0) (*idx)[c++] = m->S[k].big[v];
  PetscCall(PetscSortRemoveDupsInt(&c, *idx));
  *n = c;
  PetscFunctionReturn(0);
}

/* The Hessian's pattern (ops.getpattern). With N_j the nodes of G_j (the
   slave nodes of the faces around slave node j and the nodes of the master
   faces those faces can meet), the Gauss-Newton part couples N_j x N_j,
   and the second-order part a slave face's nodes with those of the master
   faces it meets, inside it. Node a's columns: the union of the N_j that
   hold a. The master faces a slave face can meet: those of
   Mortar3dFaceEvaluate's search, on the reference coordinates, its margin
   widened from one face size to -contact_mortar_pattern_margin of them
   (2), to cover the solve's motion along the surfaces, the size the
   smaller of the two faces' (Mortar3dPatternNear). A pair that slides
   farther puts a few entries outside the pattern: the Hessian grows there
   (problem.c). Nodes: the slave's 0 .. nS - 1, the master's nS + i. */
/* Whether Mortar3dGetPattern reserves the pair of a slave face (box sb,
   size hs) and a master face (box mb, size hm): their boxes apart by at
   most margin times the smaller size on every axis (a negative margin:
   overlapping by at least that much). By the slave face's size alone, a
   coarse slave face reserved every master face within twice its own size,
   however fine: on a graded mesh (the Hertz ball's cap coarsening beyond
   its fine zone, above the block's fine top) the rows of the master nodes
   there held a region fixed in size, its faces growing in number as the
   mesh was refined; the widest row had 1,271, 3,156, 5,382 and 9,689
   columns at h 0.04, 0.02, 0.0125 and 0.008, the Hessian 320 nonzeros a
   row at h 0.008. By the smaller size the region follows the finer mesh:
   1,265, 2,812, 4,052 and 4,409 columns (the margin's stencil of some
   1,400 nodes once the fine zone holds it), 167 a row at h 0.008. On
   faces of one size the test is the same as before. */
static PetscBool Mortar3dPatternNear(const PetscReal sb[6], PetscReal hs, const PetscReal mb[6], PetscReal hm, PetscReal margin)
{
  const PetscReal reach = margin * PetscMin(hs, hm);

  for (PetscInt d = 0; d < 3; ++d)
    if (PetscMax(sb[d], mb[d]) - PetscMin(sb[3 + d], mb[3 + d]) > reach) return PETSC_FALSE;
  return PETSC_TRUE;
}

static PetscErrorCode Mortar3dGetPattern(EnergyTerm t, PetscInt *nrows, PetscInt **rows, PetscInt **start, PetscInt **cols)
{
  const Mortar3d         *m = (const Mortar3d *)t->data;
  const ContactSurface3d *S = &m->S[m->s], *M = &m->S[1 - m->s];
  const PetscInt          nS = S->nn, nn = S->nn + M->nn;
  PetscInt               *nearStart, *near, cap, *mfStart, *mfFace, *mark, *list, *markJ, *markF, *faces, nr = 0, nc = 0, ccap;
  PetscReal              *boxes, *msize;
  Bvh                     tree;
  PetscHSetIJ             covered;

  PetscFunctionBeginUser;
  if (!m->covered) PetscCall(PetscHSetIJCreate(&((Mortar3d *)t->data)->covered)); /* the pairs reserved, for Mortar3dHessian */
  covered = m->covered;
  /* the master faces each slave face can meet, and their inverse */
  PetscCall(PetscMalloc2(6 * M->nf + 1, &boxes, M->nf + 1, &msize));
  for (PetscInt f = 0; f < M->nf; ++f) {
    PetscReal xf[27];
    ContactSurface3dFaceCoords(M, f, M->X, xf);
    Face3dBox(M->type, xf, &boxes[6 * f]);
    msize[f] = Face3dSize(M->type, xf);
  }
  PetscCall(BvhCreate(M->nf, boxes, &tree));
  cap = 16 * S->nf + 1;
  PetscCall(PetscMalloc1(S->nf + 1, &nearStart));
  PetscCall(PetscMalloc1(cap, &near)); /* reallocated: apart */
  nearStart[0] = 0;
  for (PetscInt f = 0; f < S->nf; ++f) {
    PetscReal       xs[27], box[6], sbox[6], hs;
    const PetscInt *found;
    PetscInt        nfound, nkept = 0;
    Mortar3dWideBox(S, f, S->X, m->patternMargin, xs, box);
    Face3dBox(S->type, xs, sbox);
    hs = Face3dSize(S->type, xs);
    PetscCall(BvhQuery(tree, box, &nfound, &found));
    if (nearStart[f] + nfound > cap) {
      cap = 2 * (nearStart[f] + nfound);
      PetscCall(PetscRealloc(sizeof(PetscInt) * cap, &near));
    }
    for (PetscInt k = 0; k < nfound; ++k) {
      PetscHashIJKey key;
      if (!Mortar3dPatternNear(sbox, hs, &boxes[6 * found[k]], msize[found[k]], m->patternMargin)) continue;
      near[nearStart[f] + nkept++] = found[k];
      key.i = f;
      key.j = found[k];
      PetscCall(PetscHSetIJAdd(covered, key));
    }
    nearStart[f + 1] = nearStart[f] + nkept;
  }
  PetscCall(BvhDestroy(&tree));
  PetscCall(PetscFree2(boxes, msize));
  PetscCall(PetscCalloc2(M->nf + 1, &mfStart, nearStart[S->nf] + 1, &mfFace));
  for (PetscInt k = 0; k < nearStart[S->nf]; ++k) mfStart[near[k] + 1]++;
  for (PetscInt f = 0; f < M->nf; ++f) mfStart[f + 1] += mfStart[f];
  {
    PetscInt *cnt;
    PetscCall(PetscCalloc1(M->nf + 1, &cnt));
    for (PetscInt f = 0; f < S->nf; ++f)
      for (PetscInt k = nearStart[f]; k < nearStart[f + 1]; ++k) mfFace[mfStart[near[k]] + cnt[near[k]]++] = f;
    PetscCall(PetscFree(cnt));
  }
  /* node a's columns: the N_j of the slave nodes j of the slave faces at a
     (a slave) or of the slave faces that can meet a master face at a */
  PetscCall(PetscMalloc5(nn, &mark, nn, &list, nS + 1, &markJ, S->nf + 1, &markF, S->nf + 1, &faces));
  for (PetscInt a = 0; a < nn; ++a) mark[a] = -1;
  for (PetscInt j = 0; j < nS; ++j) markJ[j] = -1;
  for (PetscInt f = 0; f < S->nf; ++f) markF[f] = -1;
  ccap = 64 * nn + 1;
  PetscCall(PetscMalloc1(ccap, cols));
  PetscCall(PetscMalloc1(3 * nn + 1, rows));
  PetscCall(PetscMalloc1(3 * nn + 1, start));
  (*start)[0] = 0;
  {
    PetscInt *mnodeFaceStart, *mnodeFace, *cnt;
    PetscCall(PetscCalloc3(M->nn + 1, &mnodeFaceStart, M->nb * M->nf + 1, &mnodeFace, M->nn + 1, &cnt));
    for (PetscInt k = 0; k < M->nb * M->nf; ++k) mnodeFaceStart[M->fnodes[k] + 1]++;
    for (PetscInt i = 0; i < M->nn; ++i) mnodeFaceStart[i + 1] += mnodeFaceStart[i];
    for (PetscInt f = 0; f < M->nf; ++f)
      for (PetscInt i = 0; i < M->nb; ++i) mnodeFace[mnodeFaceStart[M->fnodes[M->nb * f + i]] + cnt[M->fnodes[M->nb * f + i]]++] = f;
    for (PetscInt a = 0; a < nn; ++a) {
      const ContactSurface3d *A  = a < nS ? S : M;
      const PetscInt          ia = a < nS ? a : a - nS;
      PetscInt                nl = 0;
      PetscInt                nf = 0;
      /* the slave faces f around the slave nodes j that have a in N_j (those
         of the slave faces at a, or that can meet a master face at a), each once */
      PetscInt fs = a < nS ? m->nodeFaceStart[a] : mnodeFaceStart[ia], fe = a < nS ? m->nodeFaceStart[a + 1] : mnodeFaceStart[ia + 1];
      for (PetscInt r = fs; r < fe; ++r) {
        const PetscInt g = a < nS ? m->nodeFace[r] : mnodeFace[r]; /* a slave face at a, or a master face at a */
        const PetscInt ks = a < nS ? 0 : mfStart[g], ke = a < nS ? 1 : mfStart[g + 1];
        for (PetscInt k = ks; k < ke; ++k) {
          const PetscInt f0 = a < nS ? g : mfFace[k];
          for (PetscInt i = 0; i < S->nb; ++i) {
            const PetscInt j = S->fnodes[S->nb * f0 + i];
            if (markJ[j] == a) continue;
            markJ[j] = a;
            for (PetscInt q = m->nodeFaceStart[j]; q < m->nodeFaceStart[j + 1]; ++q)
              if (markF[m->nodeFace[q]] != a) {
                markF[m->nodeFace[q]] = a;
                faces[nf++]           = m->nodeFace[q];
              }
          }
        }
      }
      for (PetscInt q = 0; q < nf; ++q) { /* their nodes and those of the master faces they can meet: the union of the N_j */
        const PetscInt f = faces[q];
        for (PetscInt l = 0; l < S->nb; ++l) {
          const PetscInt b = S->fnodes[S->nb * f + l];
          if (mark[b] != a) {
            mark[b]    = a;
            list[nl++] = b;
          }
        }
        for (PetscInt e = nearStart[f]; e < nearStart[f + 1]; ++e)
          for (PetscInt l = 0; l < M->nb; ++l) {
            const PetscInt b = nS + M->fnodes[M->nb * near[e] + l];
            if (mark[b] != a) {
              mark[b]    = a;
              list[nl++] = b;
            }
          }
      }
      for (PetscInt d = 0; d < 3; ++d) {
        if (A->big[3 * ia + d] < 0) continue;
        if (nc + 3 * nl > ccap) {
          ccap = 2 * (nc + 3 * nl);
          PetscCall(PetscRealloc(sizeof(PetscInt) * ccap, cols));
        }
        for (PetscInt l = 0; l < nl; ++l) {
          const ContactSurface3d *B  = list[l] < nS ? S : M;
          const PetscInt          ib = list[l] < nS ? list[l] : list[l] - nS;
          for (PetscInt e = 0; e < 3; ++e)
            if (B->big[3 * ib + e] >= 0) (*cols)[nc++] = B->big[3 * ib + e];
        }
        (*rows)[nr++]   = A->big[3 * ia + d];
        (*start)[nr]    = nc;
      }
    }
    PetscCall(PetscFree3(mnodeFaceStart, mnodeFace, cnt));
  }
  PetscCall(PetscFree5(mark, list, markJ, markF, faces));
  PetscCall(PetscFree2(mfStart, mfFace));
  PetscCall(PetscFree(nearStart));
  PetscCall(PetscFree(near));
  *nrows = nr;
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dSetPenaltyFactor(EnergyTerm t, PetscReal f)
{
  Mortar3d *m = (Mortar3d *)t->data;

  PetscFunctionBeginUser;
  m->kp = f * m->spec.kp;
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dGetPenaltyStiffness(EnergyTerm t, PetscReal *stiffness)
{
  const Mortar3d *m = (const Mortar3d *)t->data;

  PetscFunctionBeginUser;
  *stiffness = ContactPairPenaltyStiffness(&m->spec);
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dSetHessianExact(EnergyTerm t, PetscBool exact)
{
  Mortar3d *m = (Mortar3d *)t->data;

  PetscFunctionBeginUser;
  m->exactHessian = exact;
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dDestroy(EnergyTerm t)
{
  Mortar3d *m = (Mortar3d *)t->data;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < 2; ++k)
    if (m->S[k].nodeId) PetscCall(ContactSurface3dDestroy(&m->S[k]));
  if (m->own)
    for (PetscInt k = 0; k < m->S[m->s].nown; ++k) {
      PetscCall(PetscFree(m->own[k].dQ));
      PetscCall(PetscFree(m->own[k].pts));
      PetscCall(PetscFree(m->own[k].ends));
      PetscCall(PetscFree(m->own[k].kinks));
    }
  PetscCall(PetscFree(m->own));
  PetscCall(BvhDestroy(&m->tree));
  PetscCall(PetscFree2(m->mlocal, m->mfound));
  PetscCall(PetscFree2(m->boxes, m->xm));
  PetscCall(PetscFree(m->Adual));
  PetscCall(PetscFree5(m->A, m->C, m->Q, m->gj, m->active));
  PetscCall(PetscFree2(m->nodeFaceStart, m->nodeFace));
  PetscCall(PetscFree2(m->nearNode, m->integrate));
  PetscCall(PetscFree3(m->faceRank, m->hessSlot, m->nodeRank));
  PetscCall(PetscFree(m->hessFaces));
  PetscCall(PetscFree(m->queryFaces));
  if (m->covered) PetscCall(PetscHSetIJDestroy(&m->covered));
  PetscCall(Friction3dDestroy(&m->fr));
  if (m->rule.nq) PetscCall(Face3dRuleDestroy(&m->rule));
  if (m->frule.nq) PetscCall(Face3dRuleDestroy(&m->frule));
  PetscCall(PetscFree(m));
  PetscFunctionReturn(0);
}

/* Friction's fixed-point lag at the bodies' state (friction3d.c): this
   rank's slave faces integrated with their points kept (the search of
   Mortar3dUpdate, which decides them), C_j and Q_j summed over ranks as
   for the energy, the nodal pressures p_j = k_p <-g_j>_+ (NULL change:
   the rows alone, the bound kept); the faces' rows' entries gathered on
   every rank (Friction3dLagExchange), each rank integrating its own faces
   alone, as the gradient does. */
static PetscErrorCode Mortar3dFrictionLag(EnergyTerm t, Body bodies[], PetscReal *change)
{
  Mortar3d         *m = (Mortar3d *)t->data;
  ContactSurface3d *S = &m->S[m->s];
  Mortar3dFace     *all;
  PetscReal        *p, *buf, dummy;

  PetscFunctionBeginUser;
  (void)bodies;
  PetscCall(PetscLogEventBegin(MORTAR3D_FrictionLag, 0, 0, 0, 0));
  PetscCall(Mortar3dUpdate(m));
  PetscCall(PetscCalloc1(S->nown + 1, &all));
  PetscCall(PetscCalloc1(2 * S->nn, &buf));
  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt f = S->ownFaces[k];
    PetscCall(Mortar3dFaceEvaluate(m, f, PETSC_FALSE, PETSC_TRUE, &all[k]));
    for (PetscInt i = 0; i < S->nb; ++i) {
      buf[S->fnodes[S->nb * f + i]] += all[k].a[i];
      buf[S->nn + S->fnodes[S->nb * f + i]] += all[k].q[i];
    }
  }
  PetscCall(MPIU_Allreduce(buf, m->C, S->nn, MPIU_REAL, MPIU_SUM, t->comm));
  PetscCall(MPIU_Allreduce(buf + S->nn, m->Q, S->nn, MPIU_REAL, MPIU_SUM, t->comm));
  PetscCall(PetscFree(buf));
  Mortar3dNodalGaps(m);
  PetscCall(PetscMalloc1(S->nn, &p));
  for (PetscInt j = 0; j < S->nn; ++j) p[j] = m->active[j] && m->gj[j] < 0 ? -m->kp * m->gj[j] : 0.0;
  PetscCall(Friction3dLagBegin(m->fr, change ? p : NULL));
  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt f = S->ownFaces[k];
    PetscCall(Friction3dLagFace(m->fr, m->S, f, &m->Adual[81 * f], all[k].nm, all[k].mf, all[k].np, all[k].pts));
    PetscCall(PetscFree(all[k].pts));
    PetscCall(PetscFree(all[k].ends));
    PetscCall(PetscFree(all[k].kinks));
    PetscCall(PetscFree(all[k].dQ));
  }
  PetscCall(Friction3dLagExchange(m->fr));
  PetscCall(Friction3dLagEnd(m->fr, m->A, m->C, change ? change : &dummy));
  PetscCall(PetscFree(p));
  PetscCall(PetscFree(all));
  PetscCall(PetscLogEventEnd(MORTAR3D_FrictionLag, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dFrictionAccept(EnergyTerm t, Body bodies[], PetscReal load)
{
  Mortar3d *m = (Mortar3d *)t->data;

  PetscFunctionBeginUser;
  (void)bodies;
  PetscCall(Mortar3dUpdate(m));
  PetscCall(Friction3dAccept(m->fr, m->S, m->spec.kp, load));
  PetscFunctionReturn(0);
}

/* Back to the accepted state, the bodies holding it again: its bound, and the rows rebuilt there. */
static PetscErrorCode Mortar3dFrictionRestore(EnergyTerm t, Body bodies[])
{
  Mortar3d *m = (Mortar3d *)t->data;

  PetscFunctionBeginUser;
  PetscCall(Friction3dRestore(m->fr));
  PetscCall(Mortar3dFrictionLag(t, bodies, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dFrictionBegin(EnergyTerm t)
{
  PetscFunctionBeginUser;
  PetscCall(Friction3dBegin(((Mortar3d *)t->data)->fr));
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dFrictionScaleBound(EnergyTerm t, PetscReal growth)
{
  PetscFunctionBeginUser;
  PetscCall(Friction3dScaleBound(((Mortar3d *)t->data)->fr, growth));
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dFrictionReset(EnergyTerm t, Body bodies[])
{
  Mortar3d *m = (Mortar3d *)t->data;

  PetscFunctionBeginUser;
  (void)bodies;
  PetscCall(Friction3dReset(m->fr, m->S));
  PetscFunctionReturn(0);
}

/* The stick radius (Friction3dStickZone's) at the end of stage k, in the JSON's load_stages. */
static PetscErrorCode Mortar3dStickRadius(EnergyTerm t, PetscInt k, PetscReal *c, PetscBool *has)
{
  PetscFunctionBeginUser;
  PetscCall(Friction3dGetStage(((Mortar3d *)t->data)->fr, k, c, has));
  PetscFunctionReturn(0);
}

static PetscErrorCode Mortar3dSlipState(EnergyTerm t, PetscInt *stuck, PetscInt *loaded, PetscReal *slip)
{
  Mortar3d *m = (Mortar3d *)t->data;

  PetscFunctionBeginUser;
  PetscCall(Friction3dSlipState(m->fr, m->S, m->spec.kp, stuck, loaded, slip));
  PetscFunctionReturn(0);
}

/* Why the solve may have stopped: a contact of which no node sticks at the
   last iterate slides (a tangential force above what friction holds has no
   equilibrium), as 2D's. */
static PetscErrorCode Mortar3dDiagnose(EnergyTerm t, size_t n, char why[])
{
  Mortar3d *m = (Mortar3d *)t->data;
  PetscInt  stuck, loaded;
  PetscReal slip;

  PetscFunctionBeginUser;
  why[0] = 0;
  PetscCall(Friction3dSlipState(m->fr, m->S, m->spec.kp, &stuck, &loaded, &slip));
  if (loaded > 0 && stuck == 0) PetscCall(PetscSNPrintf(why, n, "pair %s slides: none of its %" PetscInt_FMT " nodes in contact sticks under its friction mu = %g (the tangential load exceeds what friction holds, mu P; -contact_%s_friction)", t->name, loaded, (double)Friction3dGetCoefficient(m->fr), t->name));
  PetscFunctionReturn(0);
}

/* The friction's results after the post-processing: its force on the first
   surface's body (Friction3dShearForce's, on the slave's), the normal load
   P (the rest of the pair's force) and the tangential one Q, the stick zone. */
static PetscErrorCode Mortar3dFrictionResults(Mortar3d *m)
{
  PetscReal Fs[3], n2 = 0.0, t2 = 0.0;

  PetscFunctionBeginUser;
  PetscCall(Friction3dShearForce(m->fr, Fs));
  for (PetscInt d = 0; d < 3; ++d) {
    m->shearForce[d] = m->s == 0 ? Fs[d] : -Fs[d];
    n2 += PetscSqr(m->force[0][d] - m->shearForce[d]);
    t2 += PetscSqr(m->shearForce[d]);
  }
  m->normalLoad     = PetscSqrtReal(n2);
  m->tangentialLoad = PetscSqrtReal(t2);
  PetscCall(Friction3dStickZone(m->fr, &m->stickArea, &m->stickRadius));
  PetscFunctionReturn(0);
}

/* Friction3d's blocks' rigid part into the rigid body's border, as the normal part's (Mortar3dAddRigidBlock). */
static PetscErrorCode Mortar3dFrictionRigidBlock(void *ctx, PetscInt n, const PetscInt idx[], const PetscScalar K[])
{
  PetscFunctionBeginUser;
  PetscCall(Mortar3dAddRigidBlock((Mortar3d *)ctx, n, idx, K));
  PetscFunctionReturn(0);
}

/* A frictional pair's ops (the lifecycle of its state: energyterm.h). */
static PetscErrorCode Mortar3dFrictionCreate(Mortar3d *m, EnergyTerm t)
{
  PetscFunctionBeginUser;
  PetscCall(Friction3dCreate(t->comm, m->spec.friction, m->spec.frictionPenalty, &m->fr));
  PetscCall(Friction3dSetRigidBlock(m->fr, Mortar3dFrictionRigidBlock, m));
  t->ops.lag            = Mortar3dFrictionLag;
  t->ops.accept         = Mortar3dFrictionAccept;
  t->ops.begin          = Mortar3dFrictionBegin;
  t->ops.scalebound     = Mortar3dFrictionScaleBound;
  t->ops.restore        = Mortar3dFrictionRestore;
  t->ops.reset          = Mortar3dFrictionReset;
  t->ops.stickhalfwidth = Mortar3dStickRadius;
  t->ops.diagnose       = Mortar3dDiagnose;
  t->ops.slipstate      = Mortar3dSlipState;
  PetscFunctionReturn(0);
}

PetscErrorCode ContactTermCreate_Mortar3d(const ContactPairSpec *spec, EnergyTerm t)
{
  Mortar3d *m;

  PetscFunctionBeginUser;
  if (!MORTAR3D_EnergyGrad) {
    PetscClassId id;
    PetscCall(PetscClassIdRegister("ContactMortar3d", &id));
    PetscCall(PetscLogEventRegister("Mortar3dEnergyGrad", id, &MORTAR3D_EnergyGrad));
    PetscCall(PetscLogEventRegister("Mortar3dHessian", id, &MORTAR3D_Hessian));
    PetscCall(PetscLogEventRegister("Mortar3dFrictionLag", id, &MORTAR3D_FrictionLag));
    PetscCall(PetscLogEventRegister("Mortar3dGrow", id, &MORTAR3D_Grow));
  }
  PetscCheck(!spec->mirror, t->comm, PETSC_ERR_USER_INPUT, "option -contact_%s_mirror_y: a 2D half model's mirror; contact pair %s is 3D (hold symmetry planes on rollers instead)", spec->name, spec->name);
  PetscCall(PetscNew(&m));
  m->spec                    = *spec;
  t->data                    = m;
  t->ops.setup               = Mortar3dSetUp;
  t->ops.energygradient      = Mortar3dEnergyGradient;
  t->ops.hessian             = Mortar3dHessian;
  t->ops.getdofs             = Mortar3dGetDofs;
  t->ops.getpattern          = Mortar3dGetPattern;
  t->ops.setpenaltyfactor    = Mortar3dSetPenaltyFactor;
  t->ops.getpenaltystiffness = Mortar3dGetPenaltyStiffness;
  t->ops.sethessianexact     = Mortar3dSetHessianExact;
  t->ops.postprocess         = Mortar3dPostProcess;
  t->ops.view                = Mortar3dView;
  t->ops.writejson           = Mortar3dWriteJSON;
  t->ops.writehdf5           = Mortar3dWriteHDF5;
  t->ops.writexdmf           = Mortar3dWriteXDMF;
  t->ops.destroy             = Mortar3dDestroy;
  if (spec->friction > 0) PetscCall(Mortar3dFrictionCreate(m, t));
  PetscFunctionReturn(0);
}

/* "mortar" in either dimension: the 2D term (mortar.c) until the set-up,
   where the bodies' meshes give the dimension; a pair of 3D bodies then
   becomes the 3D term (the 2D one, not yet set up, destroyed), its spec
   and Hessian switch carried over. Every 2D term's set-up is mortar.c's
   one function, kept here to be called. */
static PetscErrorCode (*Mortar2dSetUp)(EnergyTerm, Body[]) = NULL;

static PetscErrorCode MortarSetUpByDimension(EnergyTerm t, Body bodies[])
{
  const ContactTerm *b    = (const ContactTerm *)t->data; /* mortar.c's context starts with it */
  ContactPairSpec    spec = b->spec;
  const PetscBool    exact = b->exactHessian;

  PetscFunctionBeginUser;
  if (BodyGetDimension(bodies[spec.body[0]]) == 3 || BodyGetDimension(bodies[spec.body[1]]) == 3) {
    PetscCall(t->ops.destroy(t));
    PetscCall(PetscMemzero(&t->ops, sizeof(t->ops)));
    t->data = NULL;
    PetscCall(ContactTermCreate_Mortar3d(&spec, t));
    PetscCall(Mortar3dSetHessianExact(t, exact));
  } else {
    PetscCheck(!spec.nsym, t->comm, PETSC_ERR_USER_INPUT, "option -contact_%s_symmetry: a 3D pair's symmetry planes; contact pair %s is 2D, where a half model gives -contact_%s_mirror_y", spec.name, spec.name, spec.name);
    t->ops.setup = Mortar2dSetUp;
  }
  PetscCall(t->ops.setup(t, bodies));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactTermCreate_MortarAnyDim(const ContactPairSpec *spec, EnergyTerm t)
{
  PetscFunctionBeginUser;
  PetscCall(ContactTermCreate_Mortar(spec, t));
  Mortar2dSetUp = t->ops.setup;
  t->ops.setup  = MortarSetUpByDimension;
  PetscFunctionReturn(0);
}
