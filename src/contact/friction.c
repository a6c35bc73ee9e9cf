/* Coulomb friction on the slave surface of a mortar pair (-contact_friction,
   -contact_<pair>_friction): a tangential penalty k_t with a return map, as
   an incremental potential that TAO minimises with the rest of the energy.

   Slip. On slave node j, with the weights W_j, the weight C_j = int_S' W_j dS
   and the quadrature points of the pair's normal gaps (mortar.c: the same
   segments, the same points, the same closest points of the master), the
   weighted tangential slip over the load increment is

     ds_j = (1/C_j) int_S' W_j [tau_j . (x_s - x_m(eta*))
                                - t_j . (xa_s - xa_m(eta*))] dS,

   x_s = sum_i N_i x_i on the slave edge, x_m = sum_k M_k(eta*) x_k at the
   point's closest point eta* on the master, xa the same at the last
   accepted state, tau_j the unit tangent of the slave surface at node j
   along its arc, and t_j the master's unit tangent at the accepted state
   where node j's points meet it (sum_k dM_k/deta(eta*) xa_k weighted as the
   points are, oriented along tau_j). The first term is the tangential part
   of the current gap vector, about 0 where the surfaces touch; the second
   is the accepted offset between the slave's point and the master's
   material point it meets now, read along the master as it was: the slip.
   Projecting both on tau_j instead, ds_j = tau_j . (du_s - du_m(eta*)),
   counts the closing of a gap as slip where the surface turns during the
   increment: a ball pressed from rest turns its surface by about x/R, which
   reads the gap x^2/2R it closes as a slip of about (x/R)(x^2/2R) (on the
   sphere scene 7.7e-5 at r = 0.06, 8 times the stick range mu p_j / k_t,
   so that the first re-solve of the fixed point met 40 of 41 nodes
   slipping, then took 9 Newton iterations to stick 37 of them again).
   Which tangent reads the accepted offset matters where node j was open:
   the offset then holds the gap the increment closes, and only a tangent
   normal to the direction the gap closes in reads none of it as slip. Two
   bodies pressed together close their gaps along their common normal
   (Hertz's, Mindlin's linearised pairing); at a point y from the first
   contact the slave's surface is turned by y kappa_s from the common
   tangent and the master's by -y kappa_m, so the offset is read along
     r_j = (kappa_m tau_j^a + kappa_s t_j) / |kappa_m tau_j^a + kappa_s t_j|
   (tau_j^a the slave's tangent at node j and t_j the master's at the
   accepted state, kappa their curvatures at rest, the shapes whose gap
   closes, not the indented ones: FrictionOffsets), which turns by
   y (kappa_m kappa_s - kappa_s kappa_m) / (kappa_s + kappa_m) = 0: the
   master's tangent where the master is flat (a ball on a plane, the
   reading above), the slave's where the slave is (a flat slab as the slave
   of a disc: read along the disc's tangent, the gap x^2/2R from rest counted
   y^3/2R^2 of slip, 5e-4 at y = a = 0.1 R, and the shear profile was 25.8 %
   from Mindlin's in one increment a stage where the disc as slave gave
   5.45 %; now 5.45 % both ways), the bisector between equal discs (both
   flat: the master's). A node in contact at the accepted state has no gap
   to misread: its offset is its elastic slip, the same in either tangent to
   the square of their angle.
   Within one fixed-point iterate (below) the points, eta*, C_j, tau_j and
   t_j are those of the lag's state: ds_j = B_j . x - o_j is affine in the
   nodes' coordinates, with B_j the sparse row of coefficients (FrictionLag;
   every rank holds every node's row), the offset o_j = r_j . (xa_s -
   xa_m(eta*)) weighted as the points are. This is small sliding per increment:
   the pairing follows the contact from lag to lag, and a point slides a
   fraction of an edge in an increment.

   Return map as a potential. The trial elastic slip e_j = s_el,j + ds_j
   (s_el,j: the elastic slip of the accepted state), the bound b_j = mu p_j
   (p_j = k_p <-g_j>_+ the node's pressure, lagged), and

     psi(e) = k_t/2 e^2                    k_t |e| <= b
            = b |e| - b^2/(2 k_t)          k_t |e| >  b,
     Psi = sum_j A_j psi(e_j),   A_j = int_S W_j dS

   (psi = 0 where b = 0: an open node carries no shear). psi is convex and
   C1: its derivative, the shear traction q_j = psi'(e_j) = clip(k_t e_j,
   -b_j, b_j), is the return map of a tangential penalty onto Coulomb's
   cone, and psi'' = k_t where the node sticks and 0 where it slips:
     dPsi = sum_j A_j q_j B_j,   d2Psi = sum_{j stuck} A_j k_t B_j B_j^T,
   both exact (B_j and b_j do not depend on u within the iterate). The nodal
   shear q_j is per unit of the slave's reference measure, as p_j is.

   Fixed point. p_j depends on u, and Coulomb's cone is a bound that moves
   with it; the potential above holds p lagged. Within each load increment
   the solve is repeated with p_j (and the points, C_j, tau_j) taken from
   the last solution until the largest change of mu p_j is below
   -contact_friction_lag_rtol times mu max p_j (FrictionLag's change). At
   the fixed point q_j = clip(k_t e_j, -mu p_j, mu p_j) with the converged
   p_j: |q_j| <= mu p_j, |q_j| = mu p_j where the node slips, against its
   slip (q has the sign of e, the slip increment e - q/k_t too). The
   remaining error is the tangential penalty's elastic slip q/k_t in the
   stick zone, as the normal penalty's penetration is p/k_p.

   The tangential penalty. k_t = -contact_friction_penalty times the
   pair's k_p, 0.01 by default (with -contact_penalty auto, k_t = 10 E* / h),
   the scene's k_p: a penalty continuation does not soften it (that is for
   the normal contact's closing; softened with it, the cattaneo scene at
   a/R = 0.1, hc = 0.0075 took 102 Newton iterations, at the full k_t from the start
   60). On the cattaneo scene at a/R = 0.1, hc = 0.01 the
   stick zone's half-width is the same to 4 digits with 0.1 and 0.01 (241
   and 81 Newton iterations, then softened) and 3 % wider with 0.001; with
   k_t = k_p the first solve at the full penalty had not converged after
   500 iterations, Newton's steps overshooting where a stiff stuck node
   turns to slip; on the disc on a slab of tests/meshes/friction-similar.opts
   (a/R = 0.1, the slab the slave) k_t = k_p converges in 120 Newton
   iterations in one increment a stage and 355 in 8 (407 in one with the
   offset read along the master's tangent alone), c/a 0.16 % from 0.01's.

   State. Accepting a converged increment keeps, per node, the elastic slip
   q_j / k_t, the accumulated slip (+= e_j - q_j/k_t where b_j > 0: an open
   node does not slip), stick (k_t |e_j| < b_j
   with b_j > 0), the pressure and the shear, and the coordinates x_acc of
   both surfaces. It becomes the state the energy is measured from when the
   next increment begins (FrictionBegin), not before: until then the energy
   at any state is the last increment's (at its solution, each stage end
   re-evaluated for its figures, and the Taylor test, whose slipping nodes
   are then inside the slip branch, not on the kink |k_t e| = b where a
   just accepted slip would put them and psi'' jumps). A cut-back restores
   the lagged bound of the accepted state and rebuilds the rows there.
   A solve from rest starts from no slip and x_acc = X. At rest no point
   pairs the surfaces (mortar pairs them where they overlap), so the first
   solve from rest has no rows: it is frictionless, and the first lag puts
   the bound of each node at mu p_j, open nodes at 0 (the bound at reset,
   b = infinity, ties whatever rows exist, none). Where the penalty is
   continued (the automatic penalty's stages), the increment from rest lags
   once more before its last stage (staging.c), at the softer stage's
   answer: its last stage's first iterate has rows and the bound mu p_j
   there, so that a body whose tangential load is a force (Cattaneo-
   Mindlin's disc) is held by friction from that iterate on (the cattaneo
   scene at a/R = 0.05: 402 Newton iterations in that stage without this
   lag, its disc's y held by nothing but its force control, 10 with it; the
   sphere's 13 and 5). */
#include <petscviewerhdf5.h>
#include "friction.h"
#include "edge.h"
#include "outputwrite.h"

struct _n_Friction {
  MPI_Comm    comm;
  PetscMPIInt rank, size;
  PetscReal   mu, ktScale;
  PetscInt    slave, nn, nm;      /* the slave side, its nodes, the master's */
  PetscReal  *s;                  /* [nn] arc position of each slave node (reference) */
  PetscInt   *order;              /* [nn] the slave's nodes sorted by arc position */
  PetscReal   sAxis;              /* axisymmetric: the arc position of the node on the axis, where the stick zone's radius starts (else -1) */
  PetscReal  *A;                  /* [nn] int_S W_j dS */
  PetscReal  *tau;                /* [nn][2] unit tangent along the arc at the lag */
  PetscReal  *off;                /* [nn] the offset o_j the trial slip is measured from, at the lag */
  const ContactSurface *surf[2];  /* the pair's surfaces */
  PetscReal  *gtan[2], *gkap[2], *gcnt[2]; /* [nn][2], [nn], [nn] of each surface: its tangents at the accepted state, its curvatures at rest */
  PetscReal  *bound;              /* [nn] mu p_j at the lag */
  PetscInt   *rowStart;           /* [nn + 1] b_j: entries rowStart[j] .. rowStart[j + 1] */
  PetscInt   *eside, *enode;      /* [nent] the entry's surface and node */
  PetscReal  *ecoef;              /* [nent] its coefficient */
  PetscReal  *edcoef;             /* [nent] a master entry's coefficient of the tangent (dM/deta at the closest points), else 0 */
  PetscInt    nent, nentMax;
  PetscReal  *xacc[2];            /* [nn][2] each surface's coordinates at the accepted state */
  PetscReal  *sel, *slip;         /* [nn] accepted: elastic slip, accumulated slip */
  PetscReal  *boundAcc;           /* [nn] the bound at the accepted state, where a restored increment starts */
  PetscBool   pending;            /* an increment has converged, its state not yet the one the next starts from */
  PetscReal  *xaccN[2], *selN, *slipN, *boundN; /* that state (FrictionBegin makes it the accepted one) */
  PetscReal  *stick, *q, *p;      /* [nn] the last converged increment's stick, shear and pressure */
  PetscReal  *stageC;             /* [nstageMax] stick half-width at each stage's end */
  PetscReal  *stageSet;           /* [nstageMax][3][nn] shear, accumulated slip and stick at each stage's end */
  PetscInt    nstage, nstageMax;
  PetscBool   tie;                /* an increment from rest builds its rows at its first state (FrictionSetTieAtRest) */
  PetscBool   rowsPending;        /* at rest, tied, its rows not built yet (FrictionRowsPending) */
};

static PetscLogEvent FRICTION_EnergyGrad, FRICTION_Hessian, FRICTION_Lag;

PetscErrorCode FrictionCreate(MPI_Comm comm, PetscReal mu, PetscReal ktScale, Friction *fr)
{
  Friction f;

  PetscFunctionBeginUser;
  if (!FRICTION_EnergyGrad) {
    PetscClassId id;
    PetscCall(PetscClassIdRegister("ContactFriction", &id));
    PetscCall(PetscLogEventRegister("FrictionEnergyGrad", id, &FRICTION_EnergyGrad));
    PetscCall(PetscLogEventRegister("FrictionHessian", id, &FRICTION_Hessian));
    PetscCall(PetscLogEventRegister("FrictionLag", id, &FRICTION_Lag));
  }
  PetscCall(PetscNew(&f));
  f->comm    = comm;
  f->mu      = mu;
  f->ktScale = ktScale;
  PetscCallMPI(MPI_Comm_rank(comm, &f->rank));
  PetscCallMPI(MPI_Comm_size(comm, &f->size));
  *fr = f;
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionDestroy(Friction *fr)
{
  Friction f = *fr;

  PetscFunctionBeginUser;
  if (!f) PetscFunctionReturn(0);
  PetscCall(PetscFree5(f->s, f->A, f->tau, f->bound, f->rowStart));
  PetscCall(PetscFree(f->order));
  PetscCall(PetscFree(f->off));
  for (PetscInt k = 0; k < 2; ++k) PetscCall(PetscFree3(f->gtan[k], f->gkap[k], f->gcnt[k]));
  PetscCall(PetscFree(f->stageC));
  PetscCall(PetscFree(f->stageSet));
  PetscCall(PetscFree4(f->eside, f->enode, f->ecoef, f->edcoef));
  PetscCall(PetscFree4(f->xacc[0], f->xacc[1], f->xaccN[0], f->xaccN[1]));
  PetscCall(PetscFree6(f->sel, f->slip, f->stick, f->q, f->p, f->boundAcc));
  PetscCall(PetscFree3(f->selN, f->slipN, f->boundN));
  PetscCall(PetscFree(*fr));
  PetscFunctionReturn(0);
}

static void FrictionSurfaceShape(const ContactSurface *, const PetscReal[], PetscReal[], PetscReal[], PetscReal[]);
static void FrictionOffsets(Friction);

PetscErrorCode FrictionSetUp(Friction f, const ContactSurface S[2], PetscInt slave)
{
  const ContactSurface *Ss = &S[slave];

  PetscFunctionBeginUser;
  f->slave = slave;
  f->nn    = Ss->nn;
  f->sAxis = -1.0;
  f->nm    = S[1 - slave].nn;
  PetscCall(PetscCalloc5(f->nn, &f->s, f->nn, &f->A, 2 * f->nn, &f->tau, f->nn, &f->bound, f->nn + 1, &f->rowStart));
  PetscCall(PetscMalloc1(f->nn, &f->order));
  PetscCall(PetscCalloc1(f->nn, &f->off));
  for (PetscInt k = 0; k < 2; ++k) {
    f->surf[k] = &S[k];
    PetscCall(PetscMalloc3(2 * S[k].nn, &f->gtan[k], S[k].nn, &f->gkap[k], S[k].nn, &f->gcnt[k]));
    FrictionSurfaceShape(&S[k], S[k].X, NULL, f->gkap[k], f->gcnt[k]);
  }
  PetscCall(PetscMalloc4(2 * S[0].nn, &f->xacc[0], 2 * S[1].nn, &f->xacc[1], 2 * S[0].nn, &f->xaccN[0], 2 * S[1].nn, &f->xaccN[1]));
  PetscCall(PetscCalloc6(f->nn, &f->sel, f->nn, &f->slip, f->nn, &f->stick, f->nn, &f->q, f->nn, &f->p, f->nn, &f->boundAcc));
  PetscCall(PetscCalloc3(f->nn, &f->selN, f->nn, &f->slipN, f->nn, &f->boundN));
  PetscCall(ContactSurfaceNodeArcs(Ss, f->s));
  for (PetscInt j = 0; j < f->nn && Ss->axisym; ++j)
    if (PetscAbsReal(Ss->X[2 * j]) <= 1e-8 * ContactSurfaceLength(Ss)) f->sAxis = f->s[j];
  {
    PetscReal *key;
    PetscCall(PetscMalloc1(f->nn, &key));
    PetscCall(PetscArraycpy(key, f->s, f->nn));
    for (PetscInt j = 0; j < f->nn; ++j) f->order[j] = j;
    PetscCall(PetscSortRealWithArrayInt(f->nn, key, f->order));
    PetscCall(PetscFree(key));
  }
  PetscCall(FrictionReset(f, S));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionReset(Friction f, const ContactSurface S[2])
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < 2; ++k) PetscCall(PetscArraycpy(f->xacc[k], S[k].X, 2 * S[k].nn));
  PetscCall(PetscArrayzero(f->sel, f->nn));
  PetscCall(PetscArrayzero(f->slip, f->nn));
  PetscCall(PetscArrayzero(f->stick, f->nn));
  PetscCall(PetscArrayzero(f->q, f->nn));
  PetscCall(PetscArrayzero(f->p, f->nn));
  for (PetscInt j = 0; j < f->nn; ++j) f->bound[j] = f->boundAcc[j] = PETSC_INFINITY; /* whatever rows there are tied: see above */
  PetscCall(PetscArrayzero(f->rowStart, f->nn + 1));
  PetscCall(PetscArrayzero(f->off, f->nn));
  f->nent        = 0;
  f->nstage      = 0;
  f->pending     = PETSC_FALSE;
  f->rowsPending = f->tie;
  PetscFunctionReturn(0);
}

/* The tied start of an increment from rest: the bound at rest is already
   infinite (FrictionReset), and the rows are built at the first state the
   pair evaluates (FrictionRowsPending; the caller lags with no pressures)
   instead of at the first lag, so that every node whose points meet the
   master is held along it by k_t from the first solve: a stick everywhere,
   with an equilibrium whatever the tangential force given (a node the tie
   held apart lets go at the next lag, its bound mu p_j = 0). For pairs where
   a body given forces alone would otherwise be free along the contact in
   its first solve (ContactTermTiesAtRest). The increments after it start
   from the bound scaled by the load (FrictionScaleBound). */
PetscErrorCode FrictionSetTieAtRest(Friction f, const ContactSurface S[2])
{
  PetscFunctionBeginUser;
  f->tie = PETSC_TRUE;
  PetscCall(FrictionReset(f, S));
  PetscFunctionReturn(0);
}

PetscBool FrictionRowsPending(Friction f)
{
  return f->rowsPending;
}

/* A tied pair's increment after the first (staging.c; growth the given
   forces' over the increment: load / accepted load within the first stage,
   1 after it): its first solve's bound is the accepted one times growth,
   mu p_j as the pressure would be where the contact is loaded in
   proportion, and the fixed point goes on from there (its answer does not
   depend on that start: the disc of tests/test_oblique2d.py in 8
   increments gave the same c/a and shear to the digits printed either
   way). Every increment used to start tied, the bound infinite, as the one
   from rest: with the force control's penalty continuation each
   increment's softer stage then moved the tied nodes 1000 times as far
   along, the full penalty's stage began with their shear k_t e that many
   times the bound (energy 5.3e4 against 660) and its line search failed
   (the cattaneo scene given P and Q = 0.5 mu P in one stage, in 4, 12, 16
   or 32 increments: DIVERGED_LS_FAILURE or DIVERGED_MAXITS after 70-420
   s). Tied at the full penalty alone it converged, but its first solve put
   pressures 5 times the answer's where the tie held open nodes, and the
   fixed point took 7 lags an increment (4 increments: 232 Newton
   iterations, 14 s; scaled, the softer stage kept: 137, 9 s). */
PetscErrorCode FrictionScaleBound(Friction f, PetscReal growth)
{
  PetscFunctionBeginUser;
  if (!f->tie) PetscFunctionReturn(0);
  for (PetscInt j = 0; j < f->nn; ++j) f->bound[j] = growth * f->boundAcc[j];
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionBegin(Friction f)
{
  PetscFunctionBeginUser;
  if (!f->pending) PetscFunctionReturn(0);
  for (PetscInt k = 0; k < 2; ++k) PetscCall(PetscArraycpy(f->xacc[k], f->xaccN[k], 2 * (k == f->slave ? f->nn : f->nm)));
  PetscCall(PetscArraycpy(f->sel, f->selN, f->nn));
  PetscCall(PetscArraycpy(f->slip, f->slipN, f->nn));
  PetscCall(PetscArraycpy(f->boundAcc, f->boundN, f->nn));
  f->pending = PETSC_FALSE;
  FrictionOffsets(f); /* the rows of the last lag, measured from the new accepted state */
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionRestore(Friction f)
{
  PetscFunctionBeginUser;
  PetscCall(PetscArraycpy(f->bound, f->boundAcc, f->nn));
  PetscFunctionReturn(0);
}

/* The rows b_j from this rank's points, gathered on every rank, sorted by
   node and merged: entry (j, surface, node, coefficient). */
static PetscErrorCode FrictionBuildRows(Friction f, const ContactSurface S[2], PetscInt np, const FrictionPoint pts[], const PetscReal cover[])
{
  const ContactSurface *Ss = &S[f->slave], *M = &S[1 - f->slave];
  const PetscInt        stride = 2 * PetscMax(f->nn, f->nm) + 2;
  PetscReal            *loc, *all;
  PetscInt              nloc = 0, nall = 0, *key, *perm;
  PetscMPIInt          *counts, *displs, n4;

  PetscFunctionBeginUser;
  PetscCheck((PetscReal)f->nn * stride < (PetscReal)PETSC_MAX_INT, f->comm, PETSC_ERR_SUP, "friction: %" PetscInt_FMT " slave nodes against %" PetscInt_FMT " master nodes overflow the rows' sort keys (PetscInt of %d bytes)", f->nn, f->nm, (int)sizeof(PetscInt));
  PetscCall(PetscMalloc1(5 * 30 * (size_t)np + 1, &loc));
  for (PetscInt k = 0; k < np; ++k) {
    const FrictionPoint *P  = &pts[k];
    const PetscInt      *sn = &Ss->enodes[3 * P->se], *mn;
    if (P->me < 0) continue;
    mn = &M->mnodes[7 * P->me];
    for (PetscInt i = 0; i < 3; ++i) {
      const PetscInt  j = sn[i];
      const PetscReal w = cover[j] > 0 ? P->wt * P->W[i] / cover[j] : 0.0;
      if (w == 0) continue;
      for (PetscInt l = 0; l < 3; ++l) {
        PetscReal *r = &loc[5 * nloc++];
        r[0] = j, r[1] = f->slave, r[2] = sn[l], r[3] = w * P->N[l], r[4] = 0.0;
      }
      for (PetscInt l = 0; l < 7; ++l) {
        PetscReal *r;
        if (P->M7[l] == 0 && P->dM7[l] == 0) continue;
        r    = &loc[5 * nloc++];
        r[0] = j, r[1] = 1 - f->slave, r[2] = mn[l], r[3] = -w * P->M7[l], r[4] = w * P->dM7[l];
      }
    }
  }
  PetscCall(PetscMalloc2(f->size, &counts, f->size + 1, &displs));
  PetscCall(PetscMPIIntCast(5 * nloc, &n4));
  PetscCallMPI(MPI_Allgather(&n4, 1, MPI_INT, counts, 1, MPI_INT, f->comm));
  displs[0] = 0;
  for (PetscMPIInt r = 0; r < f->size; ++r) displs[r + 1] = displs[r] + counts[r];
  nall = displs[f->size] / 5;
  PetscCall(PetscMalloc3(5 * nall + 1, &all, nall + 1, &key, nall + 1, &perm));
  PetscCallMPI(MPI_Allgatherv(loc, n4, MPIU_REAL, all, counts, displs, MPIU_REAL, f->comm));
  for (PetscInt k = 0; k < nall; ++k) {
    key[k]  = (PetscInt)all[5 * k] * stride + (PetscInt)all[5 * k + 1] * (stride / 2) + (PetscInt)all[5 * k + 2];
    perm[k] = k;
  }
  PetscCall(PetscSortIntWithArray(nall, key, perm));
  if (nall > f->nentMax) {
    PetscCall(PetscFree4(f->eside, f->enode, f->ecoef, f->edcoef));
    f->nentMax = nall;
    PetscCall(PetscMalloc4(nall, &f->eside, nall, &f->enode, nall, &f->ecoef, nall, &f->edcoef));
  }
  PetscCall(PetscArrayzero(f->rowStart, f->nn + 1));
  f->nent = 0;
  for (PetscInt k = 0; k < nall; ++k) {
    const PetscReal *r = &all[5 * perm[k]];
    if (f->nent && k && key[k] == key[k - 1]) {
      f->ecoef[f->nent - 1] += r[3];
      f->edcoef[f->nent - 1] += r[4];
      continue;
    }
    f->eside[f->nent] = (PetscInt)r[1];
    f->enode[f->nent] = (PetscInt)r[2];
    f->ecoef[f->nent]  = r[3];
    f->edcoef[f->nent] = r[4];
    f->nent++;
    f->rowStart[(PetscInt)r[0] + 1]++;
  }
  for (PetscInt j = 0; j < f->nn; ++j) f->rowStart[j + 1] += f->rowStart[j];
  PetscCall(PetscFree3(all, key, perm));
  PetscCall(PetscFree2(counts, displs));
  PetscCall(PetscFree(loc));
  PetscFunctionReturn(0);
}

/* Node j's weighted gap vector sum_k c_k x_k with the coordinates x[2] of
   both surfaces (d), and the master's unit tangent there (t, oriented along
   tau_j; tau_j where the row has no master tangent). */
static void FrictionRowVector(Friction f, PetscInt j, PetscReal *const x[2], PetscReal d[2], PetscReal t[2])
{
  PetscReal tn;

  d[0] = d[1] = t[0] = t[1] = 0.0;
  for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k) {
    const PetscInt   v  = f->enode[k];
    const PetscReal *xs = x[f->eside[k]];
    d[0] += f->ecoef[k] * xs[2 * v];
    d[1] += f->ecoef[k] * xs[2 * v + 1];
    t[0] += f->edcoef[k] * xs[2 * v];
    t[1] += f->edcoef[k] * xs[2 * v + 1];
  }
  tn = PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
  if (tn > 0) {
    if (t[0] * f->tau[2 * j] + t[1] * f->tau[2 * j + 1] < 0) tn = -tn;
    t[0] /= tn, t[1] /= tn;
  } else t[0] = f->tau[2 * j], t[1] = f->tau[2 * j + 1];
}

/* Each node's unit tangent along the arc (tan, summed over its edges and
   normalised) or curvature (kap, the magnitude averaged over its edges;
   NULL: not computed) of the surface S at the coordinates x: on a quadratic edge x(xi), xi = -1, 1
   at its ends and 0 at its middle node, x' = (x1 - x0)/2 + xi (x0 + x1 -
   2 xm), x'' = x0 + x1 - 2 xm and kappa = |x' x x''| / |x'|^3. */
static void FrictionSurfaceShape(const ContactSurface *S, const PetscReal x[], PetscReal tan[], PetscReal kap[], PetscReal cnt[])
{
  for (PetscInt v = 0; v < S->nn; ++v) {
    if (tan) tan[2 * v] = tan[2 * v + 1] = 0.0;
    if (kap) kap[v] = 0.0;
    cnt[v] = 0.0;
  }
  for (PetscInt e = 0; e < S->ne; ++e) {
    const PetscInt *en = &S->enodes[3 * e];
    const PetscReal xi[3] = {-1.0, 1.0, 0.0};
    PetscReal       c[2], dd[2];
    for (PetscInt d = 0; d < 2; ++d) {
      c[d]  = 0.5 * (x[2 * en[1] + d] - x[2 * en[0] + d]);
      dd[d] = x[2 * en[0] + d] + x[2 * en[1] + d] - 2.0 * x[2 * en[2] + d];
    }
    for (PetscInt i = 0; i < 3; ++i) {
      const PetscReal dx = c[0] + xi[i] * dd[0], dy = c[1] + xi[i] * dd[1], n = PetscSqrtReal(dx * dx + dy * dy);
      if (!(n > 0)) continue;
      if (tan) tan[2 * en[i]] += S->edir[e] * dx / n, tan[2 * en[i] + 1] += S->edir[e] * dy / n;
      if (kap) kap[en[i]] += PetscAbsReal(dx * dd[1] - dy * dd[0]) / (n * n * n);
      cnt[en[i]] += 1.0;
    }
  }
  for (PetscInt v = 0; v < S->nn; ++v) {
    const PetscReal n = tan ? PetscSqrtReal(tan[2 * v] * tan[2 * v] + tan[2 * v + 1] * tan[2 * v + 1]) : 0.0;
    if (n > 0) tan[2 * v] /= n, tan[2 * v + 1] /= n;
    if (kap && cnt[v] > 0) kap[v] /= cnt[v];
  }
}

/* The offsets o_j at the lag: see the derivation. */
static void FrictionOffsets(Friction f)
{
  const PetscInt m = 1 - f->slave;

  for (PetscInt k = 0; k < 2; ++k) FrictionSurfaceShape(f->surf[k], f->xacc[k], f->gtan[k], NULL, f->gcnt[k]);
  for (PetscInt j = 0; j < f->nn; ++j) {
    PetscReal d[2], t[2], r[2], ts[2], km = 0.0, wm = 0.0, ks = f->gkap[f->slave][j], rn;
    FrictionRowVector(f, j, f->xacc, d, t);
    ts[0] = f->gtan[f->slave][2 * j], ts[1] = f->gtan[f->slave][2 * j + 1];
    if (ts[0] * f->tau[2 * j] + ts[1] * f->tau[2 * j + 1] < 0) ts[0] = -ts[0], ts[1] = -ts[1];
    for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k)
      if (f->eside[k] == m) km += PetscAbsReal(f->ecoef[k]) * f->gkap[m][f->enode[k]], wm += PetscAbsReal(f->ecoef[k]);
    km = wm > 0 ? km / wm : 0.0;
    r[0] = km * ts[0] + ks * t[0], r[1] = km * ts[1] + ks * t[1];
    rn   = PetscSqrtReal(r[0] * r[0] + r[1] * r[1]);
    if (!(rn > 0)) r[0] = t[0], r[1] = t[1];
    else r[0] /= rn, r[1] /= rn;
    f->off[j] = r[0] * d[0] + r[1] * d[1];
  }
}

PetscErrorCode FrictionLag(Friction f, const ContactSurface S[2], PetscInt np, const FrictionPoint pts[], const PetscReal A[], const PetscReal cover[], const PetscReal p[], PetscReal *change)
{
  PetscReal dmax = 0.0, bmax = 0.0;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(FRICTION_Lag, 0, 0, 0, 0));
  ContactSurfaceNodalTangents(&S[f->slave], f->tau);
  PetscCall(FrictionBuildRows(f, S, np, pts, cover));
  f->rowsPending = PETSC_FALSE;
  for (PetscInt j = 0; j < f->nn; ++j) {
    const PetscReal b = p ? f->mu * p[j] : f->bound[j];
    dmax              = PetscIsInfReal(f->bound[j]) ? PETSC_INFINITY : PetscMax(dmax, PetscAbsReal(b - f->bound[j]));
    bmax              = PetscMax(bmax, b);
    f->bound[j]       = b;
    f->A[j]           = A[j];
  }
  FrictionOffsets(f);
  *change = bmax > 0 ? dmax / bmax : 0.0;
  PetscCall(PetscLogEventEnd(FRICTION_Lag, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The trial elastic slip e_j at the surfaces' current coordinates. */
static PetscReal FrictionTrial(Friction f, const ContactSurface S[2], PetscInt j)
{
  PetscReal d[2] = {0.0, 0.0};

  for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k) {
    const PetscInt   v = f->enode[k];
    const PetscReal *x = S[f->eside[k]].x;
    d[0] += f->ecoef[k] * x[2 * v];
    d[1] += f->ecoef[k] * x[2 * v + 1];
  }
  return f->sel[j] + f->tau[2 * j] * d[0] + f->tau[2 * j + 1] * d[1] - f->off[j];
}

/* psi(e), q = psi'(e), psi''(e) for the bound b and the tangential penalty kt. */
static inline void FrictionPotential(PetscReal e, PetscReal b, PetscReal kt, PetscReal *psi, PetscReal *q, PetscReal *h)
{
  if (b <= 0) {
    *psi = *q = *h = 0.0;
  } else if (kt * PetscAbsReal(e) <= b) {
    *psi = 0.5 * kt * e * e;
    *q   = kt * e;
    *h   = kt;
  } else {
    *psi = b * PetscAbsReal(e) - 0.5 * b * b / kt;
    *q   = e > 0 ? b : -b;
    *h   = 0.0;
  }
}

static inline PetscBool FrictionMine(Friction f, PetscInt j)
{
  return (PetscBool)(j % f->size == f->rank);
}

PetscErrorCode FrictionAddEnergyGradient(Friction f, ContactSurface S[2], PetscReal kp, PetscReal *energy)
{
  const PetscReal kt = f->ktScale * kp;
  PetscReal       E  = 0.0;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(FRICTION_EnergyGrad, 0, 0, 0, 0));
  for (PetscInt j = 0; j < f->nn; ++j) {
    PetscReal psi, q, h;
    if (!FrictionMine(f, j) || f->bound[j] <= 0) continue;
    FrictionPotential(FrictionTrial(f, S, j), f->bound[j], kt, &psi, &q, &h);
    E += f->A[j] * psi;
    if (q == 0) continue;
    for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k) {
      const PetscReal c = f->A[j] * q * f->ecoef[k];
      PetscReal      *g = S[f->eside[k]].g;
      g[2 * f->enode[k]] += c * f->tau[2 * j];
      g[2 * f->enode[k] + 1] += c * f->tau[2 * j + 1];
    }
  }
  *energy += E;
  PetscCall(PetscLogEventEnd(FRICTION_EnergyGrad, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionAddHessian(Friction f, const ContactTerm *b, PetscReal kp, Mat H)
{
  const PetscReal kt = f->ktScale * kp;
  PetscInt        nmax = 0, *idx;
  PetscReal      *val;
  PetscScalar    *K;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(FRICTION_Hessian, 0, 0, 0, 0));
  for (PetscInt j = 0; j < f->nn; ++j) nmax = PetscMax(nmax, 2 * (f->rowStart[j + 1] - f->rowStart[j]));
  PetscCall(PetscMalloc3(nmax + 1, &idx, nmax + 1, &val, (size_t)nmax * nmax + 1, &K));
  for (PetscInt j = 0; j < f->nn; ++j) {
    PetscReal psi, q, h;
    PetscInt  n = 0;
    if (!FrictionMine(f, j) || f->bound[j] <= 0) continue;
    FrictionPotential(FrictionTrial(f, b->S, j), f->bound[j], kt, &psi, &q, &h);
    if (h == 0) continue;
    for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k)
      for (PetscInt d = 0; d < 2; ++d) {
        const PetscInt i = b->S[f->eside[k]].big[2 * f->enode[k] + d];
        if (i == -1) continue; /* a constrained dof; a rigid body's surface dofs (below -1) go to the body's through ContactTermAddHessian */
        idx[n]   = i;
        val[n++] = f->ecoef[k] * f->tau[2 * j + d];
      }
    for (PetscInt a = 0; a < n; ++a)
      for (PetscInt c = 0; c < n; ++c) K[a * n + c] = f->A[j] * h * val[a] * val[c];
    PetscCall(ContactTermAddHessian(b, H, n, idx, K));
  }
  PetscCall(PetscFree3(idx, val, K));
  PetscCall(PetscLogEventEnd(FRICTION_Hessian, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionAccept(Friction f, const ContactSurface S[2], PetscReal kp, PetscReal load)
{
  const PetscReal kt = f->ktScale * kp;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < f->nn; ++j) {
    const PetscReal e = FrictionTrial(f, S, j);
    PetscReal       psi, q, h;
    FrictionPotential(e, f->bound[j], kt, &psi, &q, &h);
    f->q[j]     = q;
    f->selN[j]  = q / kt;
    f->slipN[j] = f->slip[j] + (f->bound[j] > 0 ? e - q / kt : 0.0); /* slip where the node touches */
    f->stick[j] = f->bound[j] > 0 && kt * PetscAbsReal(e) < f->bound[j] ? 1.0 : 0.0;
    f->p[j]     = f->bound[j] / f->mu;
  }
  PetscCall(PetscArraycpy(f->boundN, f->bound, f->nn));
  for (PetscInt k = 0; k < 2; ++k) PetscCall(PetscArraycpy(f->xaccN[k], S[k].x, 2 * S[k].nn));
  f->pending = PETSC_TRUE;
  if (load > 0.5 && PetscAbsReal(load - PetscFloorReal(load + 0.5)) < 1e-12) {
    const PetscInt k = (PetscInt)PetscFloorReal(load + 0.5);
    PetscReal     *set;
    if (k > f->nstageMax) {
      const PetscInt n = PetscMax(2 * k, 8);
      PetscCall(PetscRealloc(sizeof(PetscReal) * (size_t)n, &f->stageC));
      PetscCall(PetscRealloc(sizeof(PetscReal) * (size_t)n * 3 * (size_t)f->nn + 1, &f->stageSet));
      f->nstageMax = n;
    }
    set = &f->stageSet[(k - 1) * 3 * f->nn];
    PetscCall(PetscArraycpy(set, f->q, f->nn));
    PetscCall(PetscArraycpy(set + f->nn, f->slipN, f->nn));
    PetscCall(PetscArraycpy(set + 2 * f->nn, f->stick, f->nn));
    PetscCall(FrictionStickHalfWidth(f, &f->stageC[k - 1]));
    f->nstage = PetscMax(f->nstage, k);
  }
  PetscFunctionReturn(0);
}

/* The end of the stick zone beyond its outermost stuck node i (next inward
   j, next outward o, in arc order; -1 where none): with r = |q| / (mu p),
   1 - r vanishes like the square root of the distance to the zone's end
   (the shear deficit of a stick zone's edge, as at a crack's tip: Mindlin's
   q gives 1 - r ~ (c/a) sqrt(2 (c - x)/c) / sqrt(1 - c^2/a^2)), so (1 - r)^2
   is extrapolated linearly from j and i to its zero, kept between i and o;
   half-way to o where j is missing or the extrapolation does not apply. */
static PetscReal FrictionStickEnd(Friction f, PetscInt i, PetscInt j, PetscInt o)
{
  const PetscReal so = o >= 0 ? f->s[o] : f->s[i];

  if (j >= 0 && f->p[i] > 0 && f->p[j] > 0) {
    const PetscReal yi = PetscSqr(1.0 - PetscAbsReal(f->q[i]) / (f->mu * f->p[i])), yj = PetscSqr(1.0 - PetscAbsReal(f->q[j]) / (f->mu * f->p[j]));
    if (yj > yi) {
      const PetscReal e = f->s[i] + (f->s[i] - f->s[j]) * yi / (yj - yi);
      return f->s[i] < so ? PetscMin(e, so) : PetscMax(e, so);
    }
  }
  return 0.5 * (f->s[i] + so);
}

/* Half the arc length of the stick zone: from the first to the last stuck
   node along the arc, each end carried past its node to where the shear
   reaches Coulomb's bound (FrictionStickEnd); in r-z, where the surface
   starts on the axis, the zone's radius, its far end's arc distance from
   the axis; 0 where no node sticks. */
PetscErrorCode FrictionStickHalfWidth(Friction f, PetscReal *c)
{
  PetscInt lo = -1, hi = -1;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < f->nn; ++k)
    if (f->stick[f->order[k]] > 0) {
      if (lo < 0) lo = k;
      hi = k;
    }
  *c = 0.0;
  if (lo < 0) PetscFunctionReturn(0);
  {
    const PetscReal L = FrictionStickEnd(f, f->order[lo], lo < hi ? f->order[lo + 1] : -1, lo > 0 ? f->order[lo - 1] : -1);
    const PetscReal R = FrictionStickEnd(f, f->order[hi], hi > lo ? f->order[hi - 1] : -1, hi + 1 < f->nn ? f->order[hi + 1] : -1);
    *c                = f->sAxis >= 0 ? PetscMax(PetscAbsReal(R - f->sAxis), PetscAbsReal(L - f->sAxis)) : 0.5 * (R - L); /* r-z: the zone's radius from the axis */
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionGetStages(Friction f, PetscInt *n, const PetscReal **c)
{
  PetscFunctionBeginUser;
  *n = f->nstage;
  *c = f->stageC;
  PetscFunctionReturn(0);
}

PetscReal FrictionGetCoefficient(Friction f)
{
  return f->mu;
}

const PetscReal *FrictionGetShear(Friction f)
{
  return f->q;
}

/* Rank 0: the nodes with a weight (A[j] > 0, as the report's rows) sorted
   by arc position, as the report writes its nodal sets. */
static PetscErrorCode FrictionSortedNodes(Friction f, const PetscReal A[], PetscInt *n, PetscInt **order)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(f->nn + 1, order));
  *n = 0;
  for (PetscInt k = 0; k < f->nn && !f->rank; ++k)
    if (A[f->order[k]] > 0) (*order)[(*n)++] = f->order[k]; /* f->order: by arc position */
  PetscFunctionReturn(0);
}

/* node_shear, node_slip and node_stick of the values val[3] (per slave node) into the viewer's current group. */
static PetscErrorCode FrictionWriteSets(Friction f, const PetscReal A[], const PetscReal *val[3], PetscViewer v)
{
  const char *names[3] = {"node_shear", "node_slip", "node_stick"};
  PetscInt    n = 0, *order;

  PetscFunctionBeginUser;
  PetscCall(FrictionSortedNodes(f, A, &n, &order));
  for (PetscInt k = 0; k < 3; ++k) PetscCall(ContactOutputWriteValues(v, f->comm, names[k], n, val[k], order));
  PetscCall(PetscFree(order));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionWriteHDF5(Friction f, const PetscReal A[], PetscViewer v)
{
  const PetscReal *val[3] = {f->q, f->pending ? f->slipN : f->slip, f->stick};

  PetscFunctionBeginUser;
  PetscCall(FrictionWriteSets(f, A, val, v));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionWriteStageHDF5(Friction f, PetscInt k, const PetscReal A[], PetscViewer v)
{
  const PetscReal *set    = &f->stageSet[(k - 1) * 3 * f->nn];
  const PetscReal *val[3] = {set, set + f->nn, set + 2 * f->nn};

  PetscFunctionBeginUser;
  PetscCheck(k >= 1 && k <= f->nstage, f->comm, PETSC_ERR_PLIB, "friction: stage %" PetscInt_FMT " of %" PetscInt_FMT " recorded", k, f->nstage);
  PetscCall(FrictionWriteSets(f, A, val, v));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionShearForce(Friction f, PetscReal F[2])
{
  PetscFunctionBeginUser;
  F[0] = F[1] = 0.0;
  for (PetscInt j = 0; j < f->nn; ++j) {
    PetscReal fj = 0.0;
    for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k)
      if (f->eside[k] == f->slave) fj += f->ecoef[k];
    F[0] -= f->A[j] * f->q[j] * fj * f->tau[2 * j];
    F[1] -= f->A[j] * f->q[j] * fj * f->tau[2 * j + 1];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionCountStuck(Friction f, const ContactSurface S[2], PetscReal kp, PetscInt *stuck, PetscInt *loaded)
{
  PetscReal slip;

  PetscFunctionBeginUser;
  PetscCall(FrictionSlipState(f, S, kp, stuck, loaded, &slip));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionSlipState(Friction f, const ContactSurface S[2], PetscReal kp, PetscInt *stuck, PetscInt *loaded, PetscReal *slip)
{
  const PetscReal kt = f->ktScale * kp;

  PetscFunctionBeginUser;
  *stuck = *loaded = 0;
  *slip            = 0.0;
  for (PetscInt j = 0; j < f->nn; ++j) {
    PetscReal e;
    if (!(f->bound[j] > 0) || PetscIsInfReal(f->bound[j])) continue;
    e = PetscAbsReal(FrictionTrial(f, S, j));
    (*loaded)++;
    if (kt * e < f->bound[j]) (*stuck)++;
    *slip = PetscMax(*slip, e);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionLagOptionsSetFromOptions(MPI_Comm comm, FrictionLagOptions *o)
{
  PetscFunctionBeginUser;
  o->rtol  = 1e-8;
  o->maxIt = 30;
  PetscOptionsBegin(comm, NULL, "Friction lag options", NULL);
  PetscCall(PetscOptionsReal("-contact_friction_lag_rtol", "Friction: each load increment is solved again with the normal pressure of the last solution until mu p changes by less than this times mu p_max at every node", NULL, o->rtol, &o->rtol, NULL));
  PetscCall(PetscOptionsInt("-contact_friction_lag_max_it", "Friction: the most solves of one load increment's fixed point on the pressure", NULL, o->maxIt, &o->maxIt, NULL));
  PetscOptionsEnd();
  PetscCheck(o->rtol > 0 && o->rtol < 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "option -contact_friction_lag_rtol: must be in (0, 1), got %g", (double)o->rtol);
  PetscCheck(o->maxIt >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "option -contact_friction_lag_max_it: must be >= 1, got %" PetscInt_FMT, o->maxIt);
  PetscFunctionReturn(0);
}
