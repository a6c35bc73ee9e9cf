/* Coulomb friction on the slave surface of a 3D mortar pair
   (-contact_friction, -contact_<pair>_friction): friction.c's tangential
   penalty and return map, the slip a vector in the plane of each slave
   node.

   Slip. On slave node j, with the dual weights W_j of the slave's faces,
   C_j = int_S' W_j dS and the points of the pair's segments (mortar3d.c,
   segment3d.c: the same pieces, the same points, the same closest points
   eta* on the master), the weighted gap vector and its offset at the last
   accepted state are

     d_j(x)  = (1/C_j) int_S' W_j (x_s - x_m(eta*)) dS = sum_k c_k x_k,
     d_j(xa) = the same coefficients on the accepted coordinates xa,

   x_s = sum_i N_i x_i on the slave face, x_m = sum_k M_k(eta*) x_k on the
   master face of the point's closest point, the coefficients c_k of the
   slave nodes (W_j N_i dS / C_j) and of the master's (-W_j M_k dS / C_j)
   gathered in node j's row. d_j(x) is about g_j nu_j where the surfaces
   touch; d_j(x) - d_j(xa) is the motion of the slave's points against the
   master's material points they meet now: the slip of the increment,
   plus the closing of a gap. The current part is read in the plane normal
   to nu_j, the master's outward normal at node j's points (sum W_j n_m dS,
   normalised), with the orthonormal basis T_j = [t1 t2] (t1 the axis least
   along nu_j, its part normal to nu_j; t2 = nu_j x t1); the accepted part in
   the master's plane at the accepted state, R_j = T_j turned by the
   rotation that takes nu_j to the master's normal there (its nodal normals
   at the accepted coordinates, weighted as the row's master entries):

     e_j = T_j^T d_j(x) - R_j^T (d_j(xa) - s_j)     (2 components)

   with s_j the elastic slip of the accepted state (a vector of its plane).
   This is 2D's reading (friction.c): where the master is flat at rest the
   gap a ball closes from rest on a flat closes along the flat's normal, so
   the accepted offset is read in the master's plane as it was (a normal
   turned with the indented surface, r/2R on similar bodies, would read the
   closing r^2/2R as a slip of r^3/4R^2: 2.5e-4 at r = a = 0.1 R, 8 times
   the stick range mu p / k_t of a first try, whose normal stage slipped
   at 7 of 65 nodes, its radial shear 68 % of the shear in L2); where the
   master is curved, in the plane normal to the direction the gaps close in,
   the two surfaces' normals weighted by their curvatures at rest
   (Friction3dClosingNormal, 2D's weighting of the tangents). A node in contact at the
   accepted state has no gap to misread: its offset is its elastic slip, the
   same in either plane to the square of their angle. Within one
   fixed-point iterate the points, eta*, C_j, T_j and R_j are those of the
   lag's state: e_j = T_j^T sum_k c_k x_k + o_j, o_j = R_j^T (s_j -
   d_j(xa)), affine in the nodes' coordinates (small sliding per increment,
   as 2D).

   Return map as a potential. With the bound b_j = mu p_j (p_j = k_p
   <-g_j>_+, lagged) and the tangential penalty k_t,

     psi(e) = k_t/2 |e|^2                  k_t |e| <= b
            = b |e| - b^2/(2 k_t)          k_t |e| >  b,
     Psi = sum_j A_j psi(e_j),

   convex and C1; q_j = psi'(e_j) = k_t e_j (stick) or b_j e_j/|e_j| (slip)
   is the return map onto Coulomb's disc |q| <= b, and
     psi'' = k_t I (stick),   (b/|e|) (I - e e^T/|e|^2) (slip),
   the second the derivative of b e/|e| (the slip direction turning; 2D has
   no such term). Gradient sum_j A_j c_k T_j q_j at node k, Hessian
   A_j c_k c_l T_j psi'' T_j^T between nodes k and l: exact within the
   iterate. The shear traction the master puts on the slave at node j is
   -T_j q_j, per unit of the slave's reference measure as p_j is.

   Fixed point, state and lifecycle: friction.c's. The lag (mortar3d.c,
   once the increment's solve has converged) takes p_j and the rows at the
   solution, until mu p changes by less than -contact_friction_lag_rtol of
   mu p_max; Accept records the converged state (s_j = q_j / k_t as a 3D
   vector T_j q_j / k_t, the accumulated slip += T_j (e_j - q_j / k_t) where
   b_j > 0, stick k_t |e_j| < b_j, the coordinates of both surfaces), Begin
   makes it the accepted one, Restore goes back to the accepted bound (the
   rows rebuilt by the caller), Reset to rest. At rest the bound is 0 (2D's
   is infinite, tying what rows there are; in 3D the segments pair the
   surfaces before they touch, so an infinite bound would tie nodes apart):
   the first solve from rest is frictionless, and its lag gives every node
   in contact mu p_j; tied instead where a body is held along the contact
   by friction alone and given a force along it (Friction3dChooseStart).

   Parallel: each rank lags its own slave faces (mortar3d.c) and the rows'
   entries are gathered on every rank (Friction3dLagExchange), so that
   every rank holds every row; energy, gradient and Hessian are each
   rank's nodes j = rank mod size, summed by the caller. */
#include "friction3d.h"

struct _n_Friction3d {
  MPI_Comm    comm;
  PetscMPIInt rank, size;
  PetscReal   mu, ktScale;
  PetscInt    s, nn, nmn;      /* the slave side, its nodes, the master's nodes */
  const ContactSurface3d *S;  /* the pair's two surfaces */
  PetscReal  *A;               /* [nn] A_j */
  PetscReal  *T;               /* [nn][6] t1, t2 at the lag */
  PetscReal  *R;               /* [nn][6] T's axes turned into the master's plane at the accepted state (Friction3dOffsets) */
  PetscReal  *mnrm;            /* [master nn][3] the master's nodal normals at the accepted state */
  PetscReal  *snrm;            /* [nn][3] the slave's nodal normals at the accepted state (Friction3dClosingNormals) */
  PetscReal  *kap[2];          /* [n] each surface's nodal mean curvature at rest, |H| */
  PetscReal  *nu;              /* [nn][3] the master's normal at node j's points, at the lag */
  PetscReal  *off;             /* [nn][2] o_j */
  PetscReal  *bound, *bnew;    /* [nn] mu p_j at the lag; the next */
  PetscInt   *rowStart;        /* [nn + 1] */
  PetscInt   *eside, *enode;   /* [nent] */
  PetscReal  *ecoef;           /* [nent] */
  PetscInt    nent, nentMax;
  PetscInt   *rkey;            /* [nraw] raw entries of the lag: key (j, side, node) */
  PetscReal  *rval;            /* [nraw] their coefficients (times C_j) */
  PetscInt    nraw, nrawMax;
  PetscReal  *xacc[2], *xaccN[2]; /* [n][3] both surfaces' coordinates: accepted, recorded */
  PetscReal  *sel, *slip, *selN, *slipN; /* [nn][3] elastic slip, accumulated slip: accepted, recorded */
  PetscReal  *boundAcc, *boundN;
  PetscBool   pending;
  PetscReal  *shear, *stick;   /* [nn][3], [nn] the last converged increment's */
  PetscReal  *stageR;          /* [nstageMax] the stick radius at each stage's end */
  PetscReal  *stageSet;        /* [nstageMax][7 nn]: shear, slip, stick */
  PetscInt    nstage, nstageMax;
  Friction3dBlockFn rigidBlock; /* the pair's hook for a rigid body's part of each block (Friction3dSetRigidBlock), or NULL */
  void             *rigidCtx;
  PetscBool         tie;         /* an increment from rest starts tied (Friction3dChooseStart) */
  PetscBool         rowsPending; /* tied at rest, its rows not built yet (Friction3dRowsPending) */
};

static PetscLogEvent FRICTION3D_EnergyGrad, FRICTION3D_Hessian, FRICTION3D_Lag;

PetscErrorCode Friction3dCreate(MPI_Comm comm, PetscReal mu, PetscReal ktScale, Friction3d *fr)
{
  Friction3d f;

  PetscFunctionBeginUser;
  if (!FRICTION3D_EnergyGrad) {
    PetscClassId id;
    PetscCall(PetscClassIdRegister("ContactFriction3d", &id));
    PetscCall(PetscLogEventRegister("Friction3dEnergyGrad", id, &FRICTION3D_EnergyGrad));
    PetscCall(PetscLogEventRegister("Friction3dHessian", id, &FRICTION3D_Hessian));
    PetscCall(PetscLogEventRegister("Friction3dLag", id, &FRICTION3D_Lag));
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

PetscErrorCode Friction3dDestroy(Friction3d *fr)
{
  Friction3d f = *fr;

  PetscFunctionBeginUser;
  if (!f) PetscFunctionReturn(0);
  PetscCall(PetscFree6(f->A, f->T, f->nu, f->off, f->bound, f->bnew));
  PetscCall(PetscFree(f->rowStart));
  PetscCall(PetscFree3(f->eside, f->enode, f->ecoef));
  PetscCall(PetscFree2(f->rkey, f->rval));
  PetscCall(PetscFree4(f->xacc[0], f->xacc[1], f->xaccN[0], f->xaccN[1]));
  PetscCall(PetscFree4(f->sel, f->slip, f->selN, f->slipN));
  PetscCall(PetscFree4(f->boundAcc, f->boundN, f->shear, f->stick));
  PetscCall(PetscFree(f->stageR));
  PetscCall(PetscFree(f->stageSet));
  PetscCall(PetscFree2(f->R, f->mnrm));
  PetscCall(PetscFree3(f->snrm, f->kap[0], f->kap[1]));
  PetscCall(PetscFree(*fr));
  PetscFunctionReturn(0);
}

/* Each node's unit normal of the surface S at the coordinates x: the mean
   of its faces' normals there, normalised. */
static void Friction3dNodalNormals(const ContactSurface3d *S, const PetscReal x[], PetscReal nrm[])
{
  for (PetscInt v = 0; v < 3 * S->nn; ++v) nrm[v] = 0.0;
  for (PetscInt face = 0; face < S->nf; ++face) {
    PetscReal xf[27];
    ContactSurface3dFaceCoords(S, face, x, xf);
    for (PetscInt i = 0; i < S->nb; ++i) {
      PetscReal xi[2], X[3], T[6], n[3];
      Face3dNodeXi(S->type, i, xi);
      Face3dEval(S->type, xf, xi, X, T, NULL);
      Face3dNormal(T, n);
      for (PetscInt c = 0; c < 3; ++c) nrm[3 * S->fnodes[S->nb * face + i] + c] += n[c];
    }
  }
  for (PetscInt v = 0; v < S->nn; ++v) {
    PetscReal *n = &nrm[3 * v], l = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (l > 0) n[0] /= l, n[1] /= l, n[2] /= l;
  }
}

/* Each node's mean curvature |H| of the surface S at the coordinates x,
   averaged over its faces. On a face, with the tangents x_1, x_2, the second
   derivatives x_ab and the unit normal n at the node, E = x_1.x_1, F =
   x_1.x_2, G = x_2.x_2, e = n.x_11, f = n.x_12, g = n.x_22 and
   H = (e G - 2 f F + g E) / (2 (E G - F^2)), the mean of the principal
   curvatures: 1/R on a sphere of radius R, 0 on a plane whose mid-edge nodes
   are the edges' midpoints (a face's |H| below 1e-10 of 1/hmax, the round-off
   of a plane's coordinates, counted 0: a flat master reads as before, to the
   bit). */
static PetscErrorCode Friction3dCurvatures(const ContactSurface3d *S, const PetscReal x[], PetscReal kap[])
{
  PetscInt *cnt;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(S->nn, &cnt));
  for (PetscInt v = 0; v < S->nn; ++v) kap[v] = 0.0;
  for (PetscInt face = 0; face < S->nf; ++face) {
    PetscReal xf[27];
    ContactSurface3dFaceCoords(S, face, x, xf);
    for (PetscInt i = 0; i < S->nb; ++i) {
      const PetscInt v = S->fnodes[S->nb * face + i];
      PetscReal      xi[2], X[3], T[6], H[9], n[3], E, F, G, det;
      Face3dNodeXi(S->type, i, xi);
      Face3dEval(S->type, xf, xi, X, T, H);
      Face3dNormal(T, n);
      E   = T[0] * T[0] + T[1] * T[1] + T[2] * T[2];
      F   = T[0] * T[3] + T[1] * T[4] + T[2] * T[5];
      G   = T[3] * T[3] + T[4] * T[4] + T[5] * T[5];
      det = E * G - F * F;
      if (det > 0) {
        const PetscReal e = n[0] * H[0] + n[1] * H[1] + n[2] * H[2], fm = n[0] * H[3] + n[1] * H[4] + n[2] * H[5];
        const PetscReal g = n[0] * H[6] + n[1] * H[7] + n[2] * H[8];
        const PetscReal H2 = PetscAbsReal((e * G - 2.0 * fm * F + g * E) / (2.0 * det));
        kap[v] += H2 * S->hmax > 1e-10 ? H2 : 0.0;
        cnt[v]++;
      }
    }
  }
  for (PetscInt v = 0; v < S->nn; ++v)
    if (cnt[v]) kap[v] /= cnt[v];
  PetscCall(PetscFree(cnt));
  PetscFunctionReturn(0);
}

PetscErrorCode Friction3dSetUp(Friction3d f, const ContactSurface3d S[2], PetscInt s)
{
  PetscFunctionBeginUser;
  f->S   = S;
  f->s   = s;
  f->nn  = S[s].nn;
  f->nmn = S[1 - s].nn;
  PetscCheck((PetscReal)f->nn * 2 * (PetscReal)PetscMax(f->nn, f->nmn) < (PetscReal)PETSC_MAX_INT, f->comm, PETSC_ERR_SUP, "friction: %" PetscInt_FMT " slave nodes against %" PetscInt_FMT " master nodes overflow the rows' sort keys (PetscInt of %d bytes)", f->nn, f->nmn, (int)sizeof(PetscInt));
  PetscCall(PetscCalloc6(f->nn, &f->A, 6 * f->nn, &f->T, 3 * f->nn, &f->nu, 2 * f->nn, &f->off, f->nn, &f->bound, f->nn, &f->bnew));
  PetscCall(PetscCalloc1(f->nn + 1, &f->rowStart));
  PetscCall(PetscCalloc2(6 * f->nn, &f->R, 3 * f->nmn, &f->mnrm));
  PetscCall(PetscCalloc3(3 * f->nn, &f->snrm, S[0].nn, &f->kap[0], S[1].nn, &f->kap[1]));
  for (PetscInt k = 0; k < 2; ++k) PetscCall(Friction3dCurvatures(&S[k], S[k].X, f->kap[k]));
  PetscCall(PetscMalloc4(3 * S[0].nn, &f->xacc[0], 3 * S[1].nn, &f->xacc[1], 3 * S[0].nn, &f->xaccN[0], 3 * S[1].nn, &f->xaccN[1]));
  PetscCall(PetscCalloc4(3 * f->nn, &f->sel, 3 * f->nn, &f->slip, 3 * f->nn, &f->selN, 3 * f->nn, &f->slipN));
  PetscCall(PetscCalloc4(f->nn, &f->boundAcc, f->nn, &f->boundN, 3 * f->nn, &f->shear, f->nn, &f->stick));
  PetscCall(Friction3dReset(f, S));
  PetscFunctionReturn(0);
}

/* The tied start of an increment from rest (Friction3dChooseStart): the
   accepted bound infinite at every node, so that the first solve holds each
   node whose points meet the master by the tangential penalty alone,
   psi = k_t/2 |e|^2 with e its tangential motion against the master since
   rest, and the rows built at the first state the pair evaluates
   (Friction3dRowsPending) or where a cut-back restores rest. */
static void Friction3dTieAtRest(Friction3d f)
{
  for (PetscInt j = 0; j < f->nn; ++j) f->bound[j] = f->boundAcc[j] = PETSC_INFINITY;
  f->rowsPending = PETSC_TRUE;
}

PetscErrorCode Friction3dReset(Friction3d f, const ContactSurface3d S[2])
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < 2; ++k) PetscCall(PetscArraycpy(f->xacc[k], S[k].X, 3 * S[k].nn));
  PetscCall(PetscArrayzero(f->sel, 3 * f->nn));
  PetscCall(PetscArrayzero(f->slip, 3 * f->nn));
  PetscCall(PetscArrayzero(f->shear, 3 * f->nn));
  PetscCall(PetscArrayzero(f->stick, f->nn));
  PetscCall(PetscArrayzero(f->bound, f->nn));
  PetscCall(PetscArrayzero(f->boundAcc, f->nn));
  PetscCall(PetscArrayzero(f->rowStart, f->nn + 1));
  PetscCall(PetscArrayzero(f->off, 2 * f->nn));
  f->nent    = 0;
  f->nstage  = 0;
  f->pending = PETSC_FALSE;
  if (f->tie) Friction3dTieAtRest(f);
  PetscFunctionReturn(0);
}

/* Node j's weighted vector sum_k c_k x_k with the coordinates x[2] of both surfaces. */
static void Friction3dRowVector(Friction3d f, PetscInt j, PetscReal *const x[2], PetscReal d[3])
{
  d[0] = d[1] = d[2] = 0.0;
  for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k) {
    const PetscReal *xk = &x[f->eside[k]][3 * f->enode[k]];
    for (PetscInt c = 0; c < 3; ++c) d[c] += f->ecoef[k] * xk[c];
  }
}

/* x turned by the rotation that takes the unit vector b to the unit vector
   a about their common normal (Rodrigues: v = b x a, c = b . a); x itself
   where they are opposite. */
static void Friction3dTurn(const PetscReal b[3], const PetscReal a[3], const PetscReal x[3], PetscReal y[3])
{
  const PetscReal v[3] = {b[1] * a[2] - b[2] * a[1], b[2] * a[0] - b[0] * a[2], b[0] * a[1] - b[1] * a[0]};
  const PetscReal c = b[0] * a[0] + b[1] * a[1] + b[2] * a[2], vx = v[0] * x[0] + v[1] * x[1] + v[2] * x[2];

  if (!(c > -0.5)) {
    y[0] = x[0], y[1] = x[1], y[2] = x[2];
    return;
  }
  y[0] = c * x[0] + v[1] * x[2] - v[2] * x[1] + v[0] * vx / (1.0 + c);
  y[1] = c * x[1] + v[2] * x[0] - v[0] * x[2] + v[1] * vx / (1.0 + c);
  y[2] = c * x[2] + v[0] * x[1] - v[1] * x[0] + v[2] * vx / (1.0 + c);
}

/* The normal of the plane node j's accepted offset is read in (see the
   derivation): the master's normal n_m where node j's points meet it at the
   accepted state (its nodal normals weighted as the row's master entries
   are), turned towards the direction the gaps close in where the master is
   curved. Two bodies pressed together close their gaps along their common
   normal (Hertz's, Mindlin's); at r from the first contact the slave's
   outward normal n_s is turned by r kappa_s from it and the master's n_m by
   -r kappa_m, so that
     w_j = (kappa_s n_m - kappa_m n_s) / |kappa_s n_m - kappa_m n_s|
   turns by r (kappa_s kappa_m - kappa_m kappa_s) / (kappa_s + kappa_m) = 0
   (2D's FrictionOffsets in 3D: kappa the surfaces' mean curvatures |H| at
   rest, Friction3dCurvatures, the master's weighted as its row entries; n_s
   the slave's nodal normal at the accepted state). n_m itself where the
   master is flat (kappa_m = 0: a ball on a plane), the slave's -n_s where
   the slave is, the bisector between equal balls, where n_m would read the
   closing of the gap r^2/R from rest as a slip of r^3/R^2 (1e-3 at r = a =
   0.1 R: the normal stage of tests/test_mindlin3d.py's two balls locked in a
   radial shear 1.8 times Mindlin's at Q/(mu P) = 0.1). */
static void Friction3dClosingNormal(Friction3d f, PetscInt j, PetscReal na[3])
{
  const PetscInt m = 1 - f->s;
  PetscReal      km = 0.0, wm = 0.0, l;

  na[0] = na[1] = na[2] = 0.0;
  for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k)
    if (f->eside[k] == m) {
      for (PetscInt c = 0; c < 3; ++c) na[c] -= f->ecoef[k] * f->mnrm[3 * f->enode[k] + c];
      km += PetscAbsReal(f->ecoef[k]) * f->kap[m][f->enode[k]], wm += PetscAbsReal(f->ecoef[k]);
    }
  l = PetscSqrtReal(na[0] * na[0] + na[1] * na[1] + na[2] * na[2]);
  if (!(l > 0)) return;
  for (PetscInt c = 0; c < 3; ++c) na[c] /= l;
  km = wm > 0 ? km / wm : 0.0;
  if (km > 0) {
    const PetscReal ks = f->kap[f->s][j], *ns = &f->snrm[3 * j];
    PetscReal       w[3];
    for (PetscInt c = 0; c < 3; ++c) w[c] = ks * na[c] - km * ns[c];
    l = PetscSqrtReal(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    if (l > 0)
      for (PetscInt c = 0; c < 3; ++c) na[c] = w[c] / l;
  }
}

/* The offsets o_j = R_j^T (s_j - d_j(xa)) at the lag, R_j = T_j turned from
   nu_j to the normal node j's accepted offset is read along
   (Friction3dClosingNormal). */
static void Friction3dOffsets(Friction3d f)
{
  Friction3dNodalNormals(&f->S[1 - f->s], f->xacc[1 - f->s], f->mnrm);
  Friction3dNodalNormals(&f->S[f->s], f->xacc[f->s], f->snrm);
  for (PetscInt j = 0; j < f->nn; ++j) {
    const PetscReal *T = &f->T[6 * j], *nu = &f->nu[3 * j];
    PetscReal       *R = &f->R[6 * j], d[3], v[3], na[3];
    Friction3dClosingNormal(f, j, na);
    if (na[0] != 0.0 || na[1] != 0.0 || na[2] != 0.0) {
      Friction3dTurn(nu, na, T, R);
      Friction3dTurn(nu, na, T + 3, R + 3);
    } else
      for (PetscInt c = 0; c < 6; ++c) R[c] = T[c];
    Friction3dRowVector(f, j, f->xacc, d);
    for (PetscInt c = 0; c < 3; ++c) v[c] = f->sel[3 * j + c] - d[c];
    f->off[2 * j]     = R[0] * v[0] + R[1] * v[1] + R[2] * v[2];
    f->off[2 * j + 1] = R[3] * v[0] + R[4] * v[1] + R[5] * v[2];
  }
}

PetscErrorCode Friction3dBegin(Friction3d f)
{
  PetscFunctionBeginUser;
  if (!f->pending) PetscFunctionReturn(0);
  for (PetscInt k = 0; k < 2; ++k) PetscCall(PetscArraycpy(f->xacc[k], f->xaccN[k], 3 * f->S[k].nn));
  PetscCall(PetscArraycpy(f->sel, f->selN, 3 * f->nn));
  PetscCall(PetscArraycpy(f->slip, f->slipN, 3 * f->nn));
  PetscCall(PetscArraycpy(f->boundAcc, f->boundN, f->nn));
  f->pending = PETSC_FALSE;
  Friction3dOffsets(f); /* the rows of the last lag, measured from the new accepted state */
  PetscFunctionReturn(0);
}

/* A tied pair's increment after the first (staging.c, growth the given
   forces' over the increment): its first solve's bound is the accepted one
   times growth, as friction.c's FrictionScaleBound and for its reason:
   with the last increment's bound mu p_j the force given in proportion
   outgrows what the contact held (the flat patch given P and Q = 0.5 mu P
   in one stage of 4 increments: the second's first solve at Q_2/(mu P_1)
   = 1, "none of its 101 nodes in contact sticks", DIVERGED_USER). */
PetscErrorCode Friction3dScaleBound(Friction3d f, PetscReal growth)
{
  PetscFunctionBeginUser;
  if (!f->tie) PetscFunctionReturn(0);
  for (PetscInt j = 0; j < f->nn; ++j) f->bound[j] = growth * f->boundAcc[j];
  PetscFunctionReturn(0);
}

PetscErrorCode Friction3dRestore(Friction3d f)
{
  PetscFunctionBeginUser;
  PetscCall(PetscArraycpy(f->bound, f->boundAcc, f->nn));
  PetscFunctionReturn(0);
}

PetscErrorCode Friction3dLagBegin(Friction3d f, const PetscReal p[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(FRICTION3D_Lag, 0, 0, 0, 0));
  for (PetscInt j = 0; j < f->nn; ++j) f->bnew[j] = p ? f->mu * p[j] : f->bound[j];
  PetscCall(PetscArrayzero(f->nu, 3 * f->nn));
  f->nraw = 0;
  PetscCall(PetscLogEventEnd(FRICTION3D_Lag, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Room for n more raw entries. */
static PetscErrorCode Friction3dRawReserve(Friction3d f, PetscInt n)
{
  PetscFunctionBeginUser;
  if (f->nraw + n <= f->nrawMax) PetscFunctionReturn(0);
  f->nrawMax = PetscMax(2 * f->nrawMax, f->nraw + n + 1024);
  PetscCall(PetscRealloc(sizeof(PetscInt) * (size_t)f->nrawMax, &f->rkey));
  PetscCall(PetscRealloc(sizeof(PetscReal) * (size_t)f->nrawMax, &f->rval));
  PetscFunctionReturn(0);
}

/* Slave face f's part of the rows of its nodes that carry a bound: the
   coefficients int W_j N_i dS and -int W_j M_k dS over its points (face by
   face, then merged by Friction3dLagEnd), and int W_j n_m dS. */
PetscErrorCode Friction3dLagFace(Friction3d f, const ContactSurface3d S[2], PetscInt face, const PetscReal Adual[], PetscInt nm, const PetscInt mf[], PetscInt np, const Segment3dPoint pts[])
{
  const ContactSurface3d *Ss = &S[f->s], *M = &S[1 - f->s];
  const PetscInt          nb = Ss->nb, mb = M->nb, ncol = nb + nm * mb;
  const PetscInt          stride = 2 * PetscMax(f->nn, f->nmn);
  PetscReal               Xs[27], xm[27], coef[FACE3D_MAX_NODES * (FACE3D_MAX_NODES + 64 * FACE3D_MAX_NODES)];
  PetscBool               any = PETSC_FALSE;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < nb; ++i)
    if (f->bnew[Ss->fnodes[nb * face + i]] > 0) any = PETSC_TRUE;
  if (!any || !np) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(FRICTION3D_Lag, 0, 0, 0, 0));
  PetscCall(PetscArrayzero(coef, nb * ncol));
  ContactSurface3dFaceCoords(Ss, face, Ss->X, Xs);
  for (PetscInt q = 0; q < np; ++q) {
    const Segment3dPoint *pt = &pts[q];
    PetscReal             X[3], T[6], n[3], N[FACE3D_MAX_NODES], Nm[FACE3D_MAX_NODES], W[FACE3D_MAX_NODES], xp[3], dS;
    Face3dEval(Ss->type, Xs, pt->xi, X, T, NULL);
    dS = Face3dNormal(T, n) * pt->w;
    Face3dShape(Ss->type, pt->xi, N, NULL, NULL);
    Face3dWeights(Ss->type, Adual, pt->xi, W);
    ContactSurface3dFaceCoords(M, mf[pt->m], M->x, xm);
    Face3dEval(M->type, xm, pt->eta, xp, T, NULL);
    Face3dNormal(T, n);
    Face3dShape(M->type, pt->eta, Nm, NULL, NULL);
    for (PetscInt i = 0; i < nb; ++i) {
      const PetscInt  j = Ss->fnodes[nb * face + i];
      const PetscReal w = W[i] * dS;
      if (!(f->bnew[j] > 0)) continue;
      for (PetscInt l = 0; l < nb; ++l) coef[i * ncol + l] += w * N[l];
      for (PetscInt k = 0; k < mb; ++k) coef[i * ncol + nb + pt->m * mb + k] -= w * Nm[k];
      for (PetscInt c = 0; c < 3; ++c) f->nu[3 * j + c] += w * n[c];
    }
  }
  PetscCall(Friction3dRawReserve(f, nb * ncol));
  for (PetscInt i = 0; i < nb; ++i) {
    const PetscInt j = Ss->fnodes[nb * face + i];
    if (!(f->bnew[j] > 0)) continue;
    for (PetscInt c = 0; c < ncol; ++c) {
      const PetscInt side = c < nb ? f->s : 1 - f->s, node = c < nb ? Ss->fnodes[nb * face + c] : M->fnodes[mb * mf[(c - nb) / mb] + (c - nb) % mb];
      if (coef[i * ncol + c] == 0) continue;
      f->rkey[f->nraw]   = j * stride + (side == f->s ? 0 : stride / 2) + node;
      f->rval[f->nraw++] = coef[i * ncol + c];
    }
  }
  PetscCall(PetscLogEventEnd(FRICTION3D_Lag, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Collective: every rank's raw entries (those of the faces it lagged, its
   own: Friction3dLagFace) gathered on every rank, in rank order (the
   ranks' own faces are consecutive runs of the surface's, so the entries
   come in the order one rank gives them), and the sums int W_j n_m dS
   summed over ranks: each rank integrates its own faces, O(surface /
   ranks), and receives the rows' entries, so that every rank holds every
   row (Friction3dAccept, Friction3dSlipState, Friction3dShearForce read
   them all). One rank: nothing to do. */
PetscErrorCode Friction3dLagExchange(Friction3d f)
{
  PetscMPIInt n = (PetscMPIInt)f->nraw, *cnt, *disp;
  PetscInt   *key;
  PetscReal  *val, *nu;

  PetscFunctionBeginUser;
  if (f->size == 1) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(FRICTION3D_Lag, 0, 0, 0, 0));
  PetscCall(PetscMalloc2(f->size, &cnt, f->size + 1, &disp));
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, cnt, 1, MPI_INT, f->comm));
  disp[0] = 0;
  for (PetscMPIInt r = 0; r < f->size; ++r) disp[r + 1] = disp[r] + cnt[r];
  PetscCall(PetscMalloc3(disp[f->size] + 1, &key, disp[f->size] + 1, &val, 3 * f->nn + 1, &nu));
  PetscCallMPI(MPI_Allgatherv(f->rkey, n, MPIU_INT, key, cnt, disp, MPIU_INT, f->comm));
  PetscCallMPI(MPI_Allgatherv(f->rval, n, MPIU_REAL, val, cnt, disp, MPIU_REAL, f->comm));
  PetscCall(MPIU_Allreduce(f->nu, nu, 3 * f->nn, MPIU_REAL, MPIU_SUM, f->comm));
  f->nraw = 0;
  PetscCall(Friction3dRawReserve(f, disp[f->size]));
  PetscCall(PetscArraycpy(f->rkey, key, disp[f->size]));
  PetscCall(PetscArraycpy(f->rval, val, disp[f->size]));
  PetscCall(PetscArraycpy(f->nu, nu, 3 * f->nn));
  f->nraw = disp[f->size];
  PetscCall(PetscFree3(key, val, nu));
  PetscCall(PetscFree2(cnt, disp));
  PetscCall(PetscLogEventEnd(FRICTION3D_Lag, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode Friction3dLagEnd(Friction3d f, const PetscReal A[], const PetscReal C[], PetscReal *change)
{
  const PetscInt stride = 2 * PetscMax(f->nn, f->nmn);
  PetscInt      *perm;
  PetscReal      dmax = 0.0, bmax = 0.0;
  PetscBool      tied = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(FRICTION3D_Lag, 0, 0, 0, 0));
  PetscCall(PetscMalloc1(f->nraw + 1, &perm));
  for (PetscInt k = 0; k < f->nraw; ++k) perm[k] = k;
  PetscCall(PetscSortIntWithArray(f->nraw, f->rkey, perm));
  if (f->nraw > f->nentMax) {
    PetscCall(PetscFree3(f->eside, f->enode, f->ecoef));
    f->nentMax = f->nraw;
    PetscCall(PetscMalloc3(f->nentMax, &f->eside, f->nentMax, &f->enode, f->nentMax, &f->ecoef));
  }
  PetscCall(PetscArrayzero(f->rowStart, f->nn + 1));
  f->nent = 0;
  for (PetscInt k = 0; k < f->nraw; ++k) {
    const PetscInt j = f->rkey[k] / stride, r = f->rkey[k] % stride;
    if (k && f->rkey[k] == f->rkey[k - 1]) {
      f->ecoef[f->nent - 1] += f->rval[perm[k]];
      continue;
    }
    f->eside[f->nent] = r < stride / 2 ? f->s : 1 - f->s;
    f->enode[f->nent] = r < stride / 2 ? r : r - stride / 2;
    f->ecoef[f->nent] = f->rval[perm[k]];
    f->nent++;
    f->rowStart[j + 1]++;
  }
  PetscCall(PetscFree(perm));
  for (PetscInt j = 0; j < f->nn; ++j) f->rowStart[j + 1] += f->rowStart[j];
  for (PetscInt j = 0; j < f->nn; ++j) {
    const PetscReal *n = &f->nu[3 * j];
    const PetscReal  l = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    PetscReal        nj[3] = {0.0, 0.0, 1.0};
    for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1] && C[j] > 0; ++k) f->ecoef[k] /= C[j];
    if (l > 0)
      for (PetscInt c = 0; c < 3; ++c) nj[c] = n[c] / l;
    Face3dPlaneBasis(nj, &f->T[6 * j]);
    for (PetscInt c = 0; c < 3; ++c) f->nu[3 * j + c] = nj[c];
    if (PetscIsInfReal(f->bound[j])) tied = PETSC_TRUE;
    else dmax = PetscMax(dmax, PetscAbsReal(f->bnew[j] - f->bound[j]));
    bmax       = PetscMax(bmax, f->bnew[j]);
    f->bound[j] = (C[j] > 0 && l > 0) ? f->bnew[j] : 0.0;
    f->A[j]     = A[j];
  }
  Friction3dOffsets(f);
  f->rowsPending = PETSC_FALSE;
  *change = tied ? 1.0 : bmax > 0 ? dmax / bmax : 0.0; /* from a tied solve: all of the bound changed (it held a node apart too) */
  PetscCall(PetscLogEventEnd(FRICTION3D_Lag, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The trial elastic slip e_j at the surfaces' current coordinates. */
static void Friction3dTrial(Friction3d f, const ContactSurface3d S[2], PetscInt j, PetscReal e[2])
{
  const PetscReal *T = &f->T[6 * j];
  PetscReal        d[3] = {0.0, 0.0, 0.0};

  for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k) {
    const PetscReal *x = &S[f->eside[k]].x[3 * f->enode[k]];
    for (PetscInt c = 0; c < 3; ++c) d[c] += f->ecoef[k] * x[c];
  }
  e[0] = T[0] * d[0] + T[1] * d[1] + T[2] * d[2] + f->off[2 * j];
  e[1] = T[3] * d[0] + T[4] * d[1] + T[5] * d[2] + f->off[2 * j + 1];
}

/* psi(e), q = psi'(e) and H = psi''(e) (2 x 2, row-major) for the bound b and the tangential penalty kt. */
static inline void Friction3dPotential(const PetscReal e[2], PetscReal b, PetscReal kt, PetscReal *psi, PetscReal q[2], PetscReal H[4])
{
  const PetscReal r = PetscSqrtReal(e[0] * e[0] + e[1] * e[1]);

  if (b <= 0) {
    *psi = q[0] = q[1] = H[0] = H[1] = H[2] = H[3] = 0.0;
  } else if (kt * r <= b) {
    *psi = 0.5 * kt * r * r;
    q[0] = kt * e[0], q[1] = kt * e[1];
    H[0] = H[3] = kt, H[1] = H[2] = 0.0;
  } else {
    const PetscReal u[2] = {e[0] / r, e[1] / r}, c = b / r;
    *psi = b * r - 0.5 * b * b / kt;
    q[0] = b * u[0], q[1] = b * u[1];
    H[0] = c * (1.0 - u[0] * u[0]), H[3] = c * (1.0 - u[1] * u[1]);
    H[1] = H[2] = -c * u[0] * u[1];
  }
}

static inline PetscBool Friction3dMine(Friction3d f, PetscInt j)
{
  return (PetscBool)(j % f->size == f->rank);
}

PetscErrorCode Friction3dAddEnergyGradient(Friction3d f, ContactSurface3d S[2], PetscReal kp, PetscReal *energy)
{
  const PetscReal kt = f->ktScale * kp;
  PetscReal       E  = 0.0;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(FRICTION3D_EnergyGrad, 0, 0, 0, 0));
  for (PetscInt j = 0; j < f->nn; ++j) {
    const PetscReal *T = &f->T[6 * j];
    PetscReal        e[2], q[2], H[4], psi, v[3];
    if (!Friction3dMine(f, j) || !(f->bound[j] > 0)) continue;
    Friction3dTrial(f, S, j, e);
    Friction3dPotential(e, f->bound[j], kt, &psi, q, H);
    E += f->A[j] * psi;
    for (PetscInt c = 0; c < 3; ++c) v[c] = f->A[j] * (T[c] * q[0] + T[3 + c] * q[1]);
    for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k) {
      PetscReal *g = &S[f->eside[k]].g[3 * f->enode[k]];
      for (PetscInt c = 0; c < 3; ++c) g[c] += f->ecoef[k] * v[c];
    }
  }
  *energy += E;
  PetscCall(PetscLogEventEnd(FRICTION3D_EnergyGrad, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode Friction3dAddHessian(Friction3d f, const ContactSurface3d S[2], PetscReal kp, Mat H)
{
  const PetscReal kt   = f->ktScale * kp;
  PetscInt        nmax = 0, *idx;
  PetscReal      *cf;
  PetscScalar    *K;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(FRICTION3D_Hessian, 0, 0, 0, 0));
  for (PetscInt j = 0; j < f->nn; ++j) nmax = PetscMax(nmax, f->rowStart[j + 1] - f->rowStart[j]);
  PetscCall(PetscMalloc3(3 * nmax + 1, &idx, nmax + 1, &cf, (size_t)9 * nmax * nmax + 1, &K));
  for (PetscInt j = 0; j < f->nn; ++j) {
    const PetscReal *T = &f->T[6 * j];
    PetscReal        e[2], q[2], h[4], psi, B[9];
    PetscInt         n = 0;
    if (!Friction3dMine(f, j) || !(f->bound[j] > 0)) continue;
    Friction3dTrial(f, S, j, e);
    Friction3dPotential(e, f->bound[j], kt, &psi, q, h);
    if (h[0] == 0 && h[3] == 0) continue;
    for (PetscInt a = 0; a < 3; ++a) /* B = A_j T h T^T */
      for (PetscInt b = 0; b < 3; ++b) B[3 * a + b] = f->A[j] * (T[a] * (h[0] * T[b] + h[1] * T[3 + b]) + T[3 + a] * (h[2] * T[b] + h[3] * T[3 + b]));
    for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k) {
      cf[n] = f->ecoef[k];
      for (PetscInt c = 0; c < 3; ++c) idx[3 * n + c] = S[f->eside[k]].big[3 * f->enode[k] + c];
      n++;
    }
    for (PetscInt a = 0; a < 3 * n; ++a)
      for (PetscInt b = 0; b < 3 * n; ++b) K[a * 3 * n + b] = cf[a / 3] * cf[b / 3] * B[3 * (a % 3) + b % 3];
    if (f->rigidBlock) PetscCall(f->rigidBlock(f->rigidCtx, 3 * n, idx, K)); /* a rigid body's components (codes below -1): its unknowns' border */
    for (PetscInt a = 0; a < 3 * n; ++a)
      if (idx[a] < 0) idx[a] = -1; /* a constrained dof or a rigid body's: MatSetValues skips it */
    PetscCall(MatSetValues(H, 3 * n, idx, 3 * n, idx, K, ADD_VALUES));
  }
  PetscCall(PetscFree3(idx, cf, K));
  PetscCall(PetscLogEventEnd(FRICTION3D_Hessian, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* A rigid body's part of the Hessian: each node's block K over its joined
   indices, a rigid body's surface components among them as codes below -1
   (rigiddof.h), goes to fn as well as into H, so that the body maps it to
   its unknowns, J^T K J and the coupling K J (the chain rule through
   x(q), as the normal part's blocks: mortar3d.c). The rest of the second
   derivative, the friction's gradient times d2x/dq2, the body takes with
   the contact's whole gradient at its surface nodes (rigid3d.c). */
PetscErrorCode Friction3dSetRigidBlock(Friction3d f, Friction3dBlockFn fn, void *ctx)
{
  PetscFunctionBeginUser;
  f->rigidBlock = fn;
  f->rigidCtx   = ctx;
  PetscFunctionReturn(0);
}

PetscErrorCode Friction3dAccept(Friction3d f, const ContactSurface3d S[2], PetscReal kp, PetscReal load)
{
  const PetscReal kt = f->ktScale * kp;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < f->nn; ++j) {
    const PetscReal *T = &f->T[6 * j];
    PetscReal        e[2], q[2], H[4], psi;
    Friction3dTrial(f, S, j, e);
    Friction3dPotential(e, f->bound[j], kt, &psi, q, H);
    for (PetscInt c = 0; c < 3; ++c) {
      const PetscReal qc = T[c] * q[0] + T[3 + c] * q[1], ec = T[c] * e[0] + T[3 + c] * e[1];
      f->shear[3 * j + c] = -qc; /* the traction on the slave */
      f->selN[3 * j + c]  = qc / kt;
      f->slipN[3 * j + c] = f->slip[3 * j + c] + (f->bound[j] > 0 ? ec - qc / kt : 0.0);
    }
    f->stick[j] = f->bound[j] > 0 && kt * PetscSqrtReal(e[0] * e[0] + e[1] * e[1]) < f->bound[j] ? 1.0 : 0.0;
  }
  PetscCall(PetscArraycpy(f->boundN, f->bound, f->nn));
  for (PetscInt k = 0; k < 2; ++k) PetscCall(PetscArraycpy(f->xaccN[k], S[k].x, 3 * S[k].nn));
  f->pending = PETSC_TRUE;
  if (load > 0.5 && PetscAbsReal(load - PetscFloorReal(load + 0.5)) < 1e-12) {
    const PetscInt k = (PetscInt)PetscFloorReal(load + 0.5);
    PetscReal     *set, area;
    if (k > f->nstageMax) {
      const PetscInt n = PetscMax(2 * k, 8);
      PetscCall(PetscRealloc(sizeof(PetscReal) * (size_t)n, &f->stageR));
      PetscCall(PetscRealloc(sizeof(PetscReal) * (size_t)n * 7 * (size_t)f->nn + 1, &f->stageSet));
      f->nstageMax = n;
    }
    set = &f->stageSet[(k - 1) * 7 * f->nn];
    PetscCall(PetscArraycpy(set, f->shear, 3 * f->nn));
    PetscCall(PetscArraycpy(set + 3 * f->nn, f->slipN, 3 * f->nn));
    PetscCall(PetscArraycpy(set + 6 * f->nn, f->stick, f->nn));
    PetscCall(Friction3dStickZone(f, &area, &f->stageR[k - 1]));
    f->nstage = PetscMax(f->nstage, k);
  }
  PetscFunctionReturn(0);
}

PetscReal Friction3dGetCoefficient(Friction3d f)
{
  return f->mu;
}

/* The stuck nodes' area sum A_j and the radius sqrt(area / pi) of a disc of it. */
PetscErrorCode Friction3dStickZone(Friction3d f, PetscReal *area, PetscReal *radius)
{
  PetscFunctionBeginUser;
  *area = 0.0;
  for (PetscInt j = 0; j < f->nn; ++j)
    if (f->stick[j] > 0) *area += f->A[j];
  *radius = PetscSqrtReal(*area / PETSC_PI);
  PetscFunctionReturn(0);
}

PetscErrorCode Friction3dGetStage(Friction3d f, PetscInt k, PetscReal *radius, PetscBool *has)
{
  PetscFunctionBeginUser;
  *has    = (PetscBool)(k >= 1 && k <= f->nstage);
  *radius = *has ? f->stageR[k - 1] : 0.0;
  PetscFunctionReturn(0);
}

PetscErrorCode Friction3dGetNodal(Friction3d f, PetscInt k, const PetscReal **shear, const PetscReal **slip, const PetscReal **stick, PetscInt *nstage)
{
  PetscFunctionBeginUser;
  *nstage = f->nstage;
  if (k < 1) {
    *shear = f->shear;
    *slip  = f->pending ? f->slipN : f->slip;
    *stick = f->stick;
  } else if (k <= f->nstage) {
    const PetscReal *set = &f->stageSet[(k - 1) * 7 * f->nn];
    *shear = set;
    *slip  = set + 3 * f->nn;
    *stick = set + 6 * f->nn;
  } else *shear = *slip = *stick = NULL;
  PetscFunctionReturn(0);
}

/* -sum_j A_j f_j T_j q_j = sum_j A_j f_j t_j, t_j the slave's traction and f_j the sum of the slave entries of row j (1 where all of node j's points meet the master). */
PetscErrorCode Friction3dShearForce(Friction3d f, PetscReal F[3])
{
  PetscFunctionBeginUser;
  F[0] = F[1] = F[2] = 0.0;
  for (PetscInt j = 0; j < f->nn; ++j) {
    PetscReal fj = 0.0;
    for (PetscInt k = f->rowStart[j]; k < f->rowStart[j + 1]; ++k)
      if (f->eside[k] == f->s) fj += f->ecoef[k];
    for (PetscInt c = 0; c < 3; ++c) F[c] += f->A[j] * fj * f->shear[3 * j + c];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Friction3dSlipState(Friction3d f, const ContactSurface3d S[2], PetscReal kp, PetscInt *stuck, PetscInt *loaded, PetscReal *slip)
{
  const PetscReal kt = f->ktScale * kp;

  PetscFunctionBeginUser;
  *stuck = *loaded = 0;
  *slip            = 0.0;
  for (PetscInt j = 0; j < f->nn; ++j) {
    PetscReal e[2], r;
    if (!(f->bound[j] > 0)) continue;
    Friction3dTrial(f, S, j, e);
    r = PetscSqrtReal(e[0] * e[0] + e[1] * e[1]);
    (*loaded)++;
    if (kt * r < f->bound[j]) (*stuck)++;
    *slip = PetscMax(*slip, r);
  }
  PetscFunctionReturn(0);
}

/* Whether the surface is flat in the reference configuration: its unit
   normals at every face's nodes parallel to 1e-9 (n, the first face's). */
static PetscBool Friction3dFlatNormal(const ContactSurface3d *M, PetscReal n[3])
{
  for (PetscInt face = 0; face < M->nf; ++face) {
    PetscReal xf[27];
    ContactSurface3dFaceCoords(M, face, M->X, xf);
    for (PetscInt i = 0; i < M->nb; ++i) {
      PetscReal xi[2], X[3], T[6], m[3], c[3];
      Face3dNodeXi(M->type, i, xi);
      Face3dEval(M->type, xf, xi, X, T, NULL);
      if (!(Face3dNormal(T, m) > 0)) return PETSC_FALSE;
      if (!face && !i) {
        n[0] = m[0], n[1] = m[1], n[2] = m[2];
        continue;
      }
      c[0] = n[1] * m[2] - n[2] * m[1], c[1] = n[2] * m[0] - n[0] * m[2], c[2] = n[0] * m[1] - n[1] * m[0];
      if (PetscSqrtReal(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) > 1e-9) return PETSC_FALSE;
    }
  }
  return M->nf > 0 ? PETSC_TRUE : PETSC_FALSE;
}

/* The forces a scene gives against what friction can hold, before solving:
   givenforces.c's check of a 2D pair, for a 3D one. A body held along a
   partner flat in the reference configuration (outward normal n) by this
   pair alone, with no pressure or traction, whose Dirichlet components are
   each force-controlled (their sum F at each stage's end) or held by a
   displacement along an axis e normal to n (a symmetry plane's roller: its
   reaction R along e is any), is in equilibrium only if the contact's
   force -(F + R) has a tangential part within mu times its normal part
   |F.n| (Q <= mu P). The least tangential part over R is F's with its
   held axes' components taken out, the rest of it along the plane:
   Ft = |F' - (F'.n) n|, F' = F less its held components (held axes normal
   to n: F'.n = F.n). A held axis not normal to n may take the normal force
   itself: no check. Where Ft > mu |F.n| at some stage no state holds it
   (the body slides without end; the solve learns it after its cutbacks):
   one line naming the pair, the body, the stage and both forces. */
PetscErrorCode Friction3dCheckGivenForces(Friction3d f, const char pair[], const Body body[2])
{
  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) {
    const Body B = body[s];
    PetscReal  F[CONTACT_MAX_STAGES][3], n[3];
    PetscBool  held[3], normal = PETSC_TRUE;

    if (BodyGetNumContactPairs(B) != 1 || !BodyGivenForcesAlone(B, F, held) || !Friction3dFlatNormal(&f->S[1 - s], n)) continue;
    for (PetscInt c = 0; c < 3; ++c)
      if (held[c] && PetscAbsReal(n[c]) > 1e-9) normal = PETSC_FALSE;
    if (!normal) continue;
    for (PetscInt k = 0; k < BodyGetNumStages(B); ++k) {
      PetscReal Fp[3], Fn, Ft = 0.0;
      for (PetscInt c = 0; c < 3; ++c) Fp[c] = held[c] ? 0.0 : F[k][c];
      Fn = Fp[0] * n[0] + Fp[1] * n[1] + Fp[2] * n[2];
      for (PetscInt c = 0; c < 3; ++c) Ft += PetscSqr(Fp[c] - Fn * n[c]);
      Ft = PetscSqrtReal(Ft);
      PetscCheck(Ft <= f->mu * PetscAbsReal(Fn) * (1.0 + 1e-12), f->comm, PETSC_ERR_USER_INPUT,
                 "pair %s: the forces given on body %s at stage %" PetscInt_FMT " are %g along %s:%s and %g across it, more than friction holds (mu = %g times %g = %g; Q/(mu P) = %.6g): it would slide without end; lower the tangential force or raise -contact_%s_friction",
                 pair, BodyGetName(B), k + 1, (double)Ft, BodyGetName(body[1 - s]), f->S[1 - s].group, (double)PetscAbsReal(Fn), (double)f->mu, (double)PetscAbsReal(Fn), (double)(f->mu * PetscAbsReal(Fn)), (double)(PetscAbsReal(Fn) > 0 ? Ft / (f->mu * PetscAbsReal(Fn)) : PETSC_INFINITY), pair);
    }
  }
  PetscFunctionReturn(0);
}

/* Where an increment from rest starts. Its first solve has no lagged
   pressure yet: with the bound 0 of rest it is frictionless, and a body
   that friction alone holds along the contact (given forces alone, held by
   this pair alone: Friction3dCheckGivenForces' bodies; an axis neither
   held nor along a flat partner's normal, whatever its force) is free
   along it there: with a force along it no equilibrium, its Newton steps
   carry it off until the line search fails (the flat patch pushed by
   Q = 0.5 mu P with P from rest: DIVERGED_LS_FAILURE, four cutbacks,
   status 2), with none a singular Hessian. For such a pair, the
   first solve from rest is tied instead (Friction3dTieAtRest): every node
   whose points meet the master is held along it by k_t, a stick
   everywhere, which has an equilibrium whatever the tangential force; its
   lag then gives each node its bound mu p_j (0 where open: a node the tie
   held apart lets go) and the fixed point goes on as from a frictionless
   first solve (its change from the tied bound counted whole, so that it
   is solved again at least once). Against a curved partner every free
   axis counts. */
PetscErrorCode Friction3dChooseStart(Friction3d f, const Body body[2])
{
  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2 && !f->tie; ++s) {
    const Body B = body[s];
    PetscReal  F[CONTACT_MAX_STAGES][3], n[3] = {0.0, 0.0, 0.0};
    PetscBool  held[3];

    if (BodyGetNumContactPairs(B) != 1 || !BodyGivenForcesAlone(B, F, held)) continue;
    if (!Friction3dFlatNormal(&f->S[1 - s], n)) n[0] = n[1] = n[2] = 0.0;
    for (PetscInt c = 0; c < 3; ++c)
      if (!held[c] && PetscAbsReal(n[c]) < 1.0 - 1e-12) f->tie = PETSC_TRUE; /* an axis free of the partner's normal: the body slides along it */
  }
  if (f->tie) Friction3dTieAtRest(f);
  PetscFunctionReturn(0);
}

PetscBool Friction3dRowsPending(Friction3d f)
{
  return f->rowsPending;
}
