/* Contact formulation "gpts": two-way Gauss-point-to-segment penalty between
   curved quadratic surfaces.

   A pair names a surface S_A on body A and S_B on body B. With S_A as slave,

     E_AB(u) = 1/2 k_p int_{S_A} <-g(X)>_+^2 dS,   <z>_+ = max(z, 0),

   where X runs over the slave surface in the reference configuration (dS is its
   reference length: Gauss points on each curved quadratic edge, weights times
   |dX/dxi|; in axisymmetry times 2 pi X_r, surface.h) and g is the signed normal gap in the current configuration: the
   slave point x_s = X + u is projected onto the closest point x_m(eta*) of the
   master surface (edge.h: each master edge the quadratic curve through its
   current nodes, blended C1 into its neighbours), and g = (x_s - x_m(eta*)) .
   n(eta*) with n the master body's outward unit normal. The pair's energy is
   (E_AB + E_BA) / 2 and the contact pressure at a slave point is p = k_p <-g>_+.

   Gradient and Hessian. dg is exact (gap.c), so
     dE_AB = -k_p int <-g>_+ dg dS,
     d2E_AB = k_p int H(-g) (dg dg + g d2g) dS.
   The Gauss-Newton part alone (-contact_hessian gauss_newton) is symmetric
   positive semi-definite; the term it drops is of the order of the
   penetration over the edge length, but it holds the tangential modes, so
   that Newton with it converges only linearly. -contact_hessian exact adds it
   (d2g from gap.c); auto (the default, problem.c) adds it once the gradient
   is small.

   The energy-gradient, Hessian and profile kernels share the point geometry
   (GPTSPointProject) and differ in what they accumulate. */
#include "contactterm.h"
#include "edge.h"
#include "gap.h"

typedef struct {
  ContactTerm b;           /* first: the surfaces, searches, penalty, results */
  PetscReal   xi[8], wxi[8];
  PetscInt    npts[2];     /* slave points this rank integrates on S[s] */
  PetscReal  *spt[2];      /* [npts][4]: s, X, Y, weight of each slave point */
} GPTS;

static PetscLogEvent GPTS_EnergyGrad, GPTS_Search, GPTS_Hessian, GPTS_Report;

/* Slave point q of slave edge se: its shape functions and current position,
   and its gap against the master surface. */
typedef struct {
  PetscReal  N[3], dN[3], xs[2];
  ContactGap G;
} GPTSPoint;

static inline void GPTSPointProject(const GPTS *cp, const ContactSurface *S, const ContactSurface *M, ContactSearch search, PetscInt se, PetscInt q, GPTSPoint *P)
{
  PetscReal ts[2];

  EdgeShape(cp->xi[q], P->N, P->dN);
  EdgeEval(S->x, &S->enodes[3 * se], cp->xi[q], P->xs, ts);
  ContactGapProject(M, search, P->xs, &P->G);
}

/* One-sided energy and gradient: slave s against master 1 - s, weight c (1/2
   for two-way); adds to both surfaces' gradient arrays. */
static void GPTSSlaveEnergyGradient(GPTS *cp, PetscInt s, PetscReal c, PetscReal *energy)
{
  ContactSurface *S = &cp->b.S[s], *M = &cp->b.S[1 - s];
  PetscReal       e = 0.0;

  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt  se = S->ownEdges[k];
    const PetscInt *sn = &S->enodes[3 * se];
    for (PetscInt q = 0; q < cp->b.spec.nqp; ++q) {
      const PetscReal w = cp->spt[s][4 * (k * cp->b.spec.nqp + q) + 3];
      GPTSPoint       P;
      PetscReal       pen, f;

      GPTSPointProject(cp, S, M, cp->b.search[1 - s], se, q, &P);
      if (P.G.me < 0 || P.G.gap >= 0.0) continue;
      pen = -P.G.gap;
      e += c * 0.5 * cp->b.kp * w * pen * pen;
      f = c * cp->b.kp * w * pen;
      for (PetscInt i = 0; i < 3; ++i)
        for (PetscInt d = 0; d < 2; ++d) S->g[2 * sn[i] + d] -= f * P.N[i] * P.G.ns[d];
      for (PetscInt j = 0; j < 7; ++j) {
        PetscReal w[2];
        ContactGapMasterWeight(&P.G, j, w);
        for (PetscInt d = 0; d < 2; ++d) M->g[2 * M->mnodes[7 * P.G.me + j] + d] += f * w[d];
      }
    }
  }
  *energy += e;
}

/* One-sided Hessian (see the derivation above), added into H. */
static PetscErrorCode GPTSSlaveHessian(GPTS *cp, PetscInt s, PetscReal c, Mat H)
{
  ContactSurface *S = &cp->b.S[s], *M = &cp->b.S[1 - s];

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt  se = S->ownEdges[k];
    const PetscInt *sn = &S->enodes[3 * se];
    for (PetscInt q = 0; q < cp->b.spec.nqp; ++q) {
      const PetscReal w = cp->spt[s][4 * (k * cp->b.spec.nqp + q) + 3], kw = c * cp->b.kp * w;
      GPTSPoint       P;
      PetscInt        idx[20];
      PetscReal       dg[20];
      PetscScalar     K[400];

      GPTSPointProject(cp, S, M, cp->b.search[1 - s], se, q, &P);
      if (P.G.me < 0 || P.G.gap >= 0.0) continue;
      ContactGapIndices(S, sn, M, &P.G, idx);
      ContactGapFirst(&P.G, P.N, dg);
      for (PetscInt i = 0; i < 20; ++i)
        for (PetscInt j = 0; j < 20; ++j) K[i * 20 + j] = kw * dg[i] * dg[j];
      if (cp->b.exactHessian) ContactGapAddSecond(&P.G, P.N, kw * P.G.gap, K);
      PetscCall(ContactTermAddHessian(&cp->b, H, 20, idx, K));
    }
  }
  PetscFunctionReturn(0);
}

/* One-sided profile at the current state: a row per slave point this rank
   owns (s, X, Y, x, y, gap, pressure, weight; gap Inf where no master edge
   faces the point), the forces on both bodies with weight c, the largest
   penetration. */
static void GPTSSlaveProfile(GPTS *cp, PetscInt s, PetscReal c, PetscReal rows[], PetscReal force[2][2], PetscReal *maxPen)
{
  ContactSurface *S = &cp->b.S[s], *M = &cp->b.S[1 - s];

  for (PetscInt k = 0; k < S->nown; ++k) {
    const PetscInt se = S->ownEdges[k];
    for (PetscInt q = 0; q < cp->b.spec.nqp; ++q) {
      const PetscInt   i = k * cp->b.spec.nqp + q;
      const PetscReal *sp = &cp->spt[s][4 * i];
      PetscReal       *r = &rows[CONTACT_ROW_COLS * i], pen, f;
      GPTSPoint        P;

      GPTSPointProject(cp, S, M, cp->b.search[1 - s], se, q, &P);
      r[CONTACT_ROW_S]   = sp[0];
      r[CONTACT_ROW_X]   = sp[1];
      r[CONTACT_ROW_Y]   = sp[2];
      r[CONTACT_ROW_XC]  = P.xs[0];
      r[CONTACT_ROW_YC]  = P.xs[1];
      r[CONTACT_ROW_GAP] = P.G.me < 0 ? CONTACT_GAP_NONE : P.G.gap;
      r[CONTACT_ROW_P]   = 0.0;
      r[CONTACT_ROW_W]   = sp[3];
      r[CONTACT_ROW_FX]  = 0.0; /* nodal forces: not at Gauss points */
      r[CONTACT_ROW_FY]  = 0.0;
      if (P.G.me < 0 || P.G.gap >= 0.0) continue;
      pen              = -P.G.gap;
      r[CONTACT_ROW_P] = cp->b.kp * pen;
      *maxPen          = PetscMax(*maxPen, pen);
      f                = c * cp->b.kp * sp[3] * pen;
      force[s][0] += f * P.G.ns[0];
      force[s][1] += f * P.G.ns[1];
      force[1 - s][0] -= f * P.G.n[0];
      force[1 - s][1] -= f * P.G.n[1];
    }
  }
}

static PetscErrorCode GPTSEnergyGradient(EnergyTerm t, Body bodies[], PetscReal *energy)
{
  GPTS     *cp = (GPTS *)t->data;
  PetscReal e  = 0.0;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(GPTS_EnergyGrad, 0, 0, 0, 0));
  for (PetscInt s = 0; s < 2; ++s) PetscCall(PetscArrayzero(cp->b.S[s].g, 2 * cp->b.S[s].nn));
  PetscCall(ContactTermUpdate(&cp->b, bodies, GPTS_Search, NULL));
  GPTSSlaveEnergyGradient(cp, 0, 0.5, &e);
  GPTSSlaveEnergyGradient(cp, 1, 0.5, &e);
  for (PetscInt s = 0; s < 2; ++s) PetscCall(ContactSurfaceAddGradient(&cp->b.S[s], bodies[cp->b.S[s].body]));
  *energy = e;
  PetscCall(PetscLogEventEnd(GPTS_EnergyGrad, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode GPTSHessian(EnergyTerm t, Body bodies[], Mat H)
{
  GPTS *cp = (GPTS *)t->data;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(GPTS_Hessian, 0, 0, 0, 0));
  PetscCall(ContactTermUpdate(&cp->b, bodies, GPTS_Search, NULL));
  PetscCall(GPTSSlaveHessian(cp, 0, 0.5, H));
  PetscCall(GPTSSlaveHessian(cp, 1, 0.5, H));
  PetscCall(PetscLogEventEnd(GPTS_Hessian, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The pair's results at the state in the bodies' local vectors. */
static PetscErrorCode GPTSPostProcess(EnergyTerm t, Body bodies[])
{
  GPTS     *cp = (GPTS *)t->data;
  PetscReal *rows[2], force[2][2] = {{0, 0}, {0, 0}}, maxPen = 0.0, L[2];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(GPTS_Report, 0, 0, 0, 0));
  PetscCall(ContactTermUpdate(&cp->b, bodies, GPTS_Search, NULL));
  for (PetscInt s = 0; s < 2; ++s) {
    PetscCall(PetscMalloc1(CONTACT_ROW_COLS * cp->npts[s] + 1, &rows[s]));
    L[s] = ContactSurfaceLength(&cp->b.S[s]);
  }
  GPTSSlaveProfile(cp, 0, 0.5, rows[0], force, &maxPen);
  GPTSSlaveProfile(cp, 1, 0.5, rows[1], force, &maxPen);
  PetscCall(ContactTermReportBegin(&cp->b, (const PetscBool[2]){PETSC_TRUE, PETSC_TRUE}));
  PetscCall(ContactReportFinish(&cp->b.report, &cp->b.spec, t->comm, cp->npts, rows, (const PetscReal(*)[2])force, maxPen, L));
  for (PetscInt s = 0; s < 2; ++s) PetscCall(PetscFree(rows[s]));
  PetscCall(PetscLogEventEnd(GPTS_Report, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Both surfaces, their searches, and the slave points of the owned edges,
   which depend only on the reference geometry: arc position, reference
   coordinates and weight, set once. */
static PetscErrorCode GPTSSetUp(EnergyTerm t, Body bodies[])
{
  GPTS *cp = (GPTS *)t->data;

  PetscFunctionBeginUser;
  PetscCall(ContactTermSetUpSurfaces(&cp->b, bodies, 0.05));
  for (PetscInt s = 0; s < 2; ++s) {
    ContactSurface *S = &cp->b.S[s];
    cp->npts[s]       = S->nown * cp->b.spec.nqp;
    PetscCall(PetscCalloc1(4 * cp->npts[s] + 4, &cp->spt[s]));
    for (PetscInt k = 0; k < S->nown; ++k) {
      const PetscInt se = S->ownEdges[k];
      for (PetscInt q = 0; q < cp->b.spec.nqp; ++q) {
        PetscReal *sp = &cp->spt[s][4 * (k * cp->b.spec.nqp + q)], X[2], T[2];
        EdgeEval(S->X, &S->enodes[3 * se], cp->xi[q], X, T);
        PetscCall(ContactSurfaceArc(S, se, cp->xi[q], &sp[0]));
        sp[1] = X[0];
        sp[2] = X[1];
        sp[3] = cp->wxi[q] * ContactSurfaceMeasure(S, X, T);
      }
    }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode GPTSDestroy(EnergyTerm t)
{
  GPTS *cp = (GPTS *)t->data;

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) PetscCall(PetscFree(cp->spt[s]));
  PetscCall(ContactTermDestroy(&cp->b));
  PetscCall(PetscFree(cp));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactTermCreate_GPTS(const ContactPairSpec *spec, EnergyTerm t)
{
  GPTS *cp;

  PetscFunctionBeginUser;
  if (!GPTS_EnergyGrad) {
    PetscClassId id;
    PetscCall(PetscClassIdRegister("ContactGPTS", &id));
    PetscCall(PetscLogEventRegister("ContactEnergyGrad", id, &GPTS_EnergyGrad));
    PetscCall(PetscLogEventRegister("ContactSearch", id, &GPTS_Search));
    PetscCall(PetscLogEventRegister("ContactHessian", id, &GPTS_Hessian));
    PetscCall(PetscLogEventRegister("ContactReport", id, &GPTS_Report));
  }
  PetscCheck(spec->friction == 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "option -contact_%s_friction (or -contact_friction) %g: formulation gpts has no friction (mortar has)", spec->name, (double)spec->friction);
  PetscCheck(!spec->nsym, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "option -contact_%s_symmetry: a 3D pair's symmetry planes; formulation gpts is 2D, where a half model gives -contact_%s_mirror_y", spec->name, spec->name);
  PetscCall(PetscNew(&cp));
  PetscCall(PetscDTGaussQuadrature(spec->nqp, -1.0, 1.0, cp->xi, cp->wxi));
  t->data = cp;
  PetscCall(ContactTermInitialize(&cp->b, spec, t));
  t->ops.setup            = GPTSSetUp;
  t->ops.energygradient   = GPTSEnergyGradient;
  t->ops.hessian          = GPTSHessian;
  t->ops.postprocess      = GPTSPostProcess;
  t->ops.destroy          = GPTSDestroy;
  PetscFunctionReturn(0);
}
