/* Dead loads on a body's boundary groups, given per unit reference length:

     -<body>_load top,inner
     -<body>_load_top_traction tx,ty     a traction t, fixed in direction and size
     -<body>_load_inner_pressure p       a pressure along the inward reference normal

   The load's potential is linear in u, so the body's energy gains

     -int_Gamma t . u dS            (traction)
     -int_Gamma (-p n) . u dS       (pressure, n the outward reference normal)

   over the reference boundary. On a quadratic edge with nodes X_a (corner,
   corner, mid at xi = -1, 1, 0; N_0 = xi (xi - 1)/2, N_1 = xi (xi + 1)/2,
   N_2 = 1 - xi^2), u = sum_a N_a u_a and dS = |dX/dxi| dxi, so the energy is
   -f . u with the consistent nodal forces

     f_a = int_{-1}^{1} N_a t |dX/dxi| dxi                          (traction)
     f_a = -p s int_{-1}^{1} N_a (dY/dxi, -dX/dxi) dxi               (pressure)

   where n |dX/dxi| = s (dY/dxi, -dX/dxi), s = +-1 the edge's outward sign.
   The pressure's integrand is a polynomial of degree 3, integrated exactly
   by 3 Gauss points, and its resultant sum_a f_a = -p s (dY, -dX) over the
   edge is p times the chord turned inward: over a group, p times the chord
   between its ends, exactly, on straight and curved edges alike. The
   traction's |dX/dxi| is not polynomial on a curved edge: 6 points. f is
   assembled once, at the full load, into a local vector from this rank's
   owned edges (each edge counted once over the ranks, as the cells are);
   its gradient is -f, its Hessian zero; load stepping scales it with the
   Dirichlet values.

   In axisymmetry (axis.c) every dS is 2 pi r dS, r = X(xi): a traction or
   a pressure per unit area of the surface of revolution, and the forces are
   the whole ring's. The pressure's integrand gains a degree (to 5), still
   exact with 3 points; its axial resultant is p times the area the group's
   ends sweep, pi (r_1^2 - r_0^2).

   A 3D body's loads act on the faces of its physical surfaces, per unit
   reference area (-traction tx,ty,tz): on a second-order face (Tri6 or
   Quad9: its nodes X_a the points of its closure, in the order of the face
   element's basis N_a), with the tangents T1 = dX/dxi, T2 = dX/deta,
   n dS = (T1 x T2) dxi deta (up to the face's outward sign s), so

     f_a = int N_a t |T1 x T2| dxi deta                   (traction)
     f_a = -p s int N_a (T1 x T2) dxi deta                 (pressure).

   The pressure's integrand is a polynomial (degree 4 on a Tri6, 5 in each
   direction on a Quad9): exact by the rules used (degree 6; 3 Gauss
   points a direction), so its resultant over a face is -p s times its
   vector area, 1/2 the integral of X x dX round its edges. The traction's
   |T1 x T2| is not polynomial on a curved face: degree 10, 6 points. */
#include "loads.h"
#include "stagedvalues.h"
#include "options.h"
#include "bodyimpl.h"

static PetscErrorCode BodyLoadSetFromOptions(Body b, const char prefix[], PetscBool help, BodyLoad *L)
{
  char      lprefix[4 * CONTACT_NAME_LEN], opt[5 * CONTACT_NAME_LEN];
  PetscReal vt[3 * CONTACT_MAX_STAGES + 1] = {0}, vp[CONTACT_MAX_STAGES + 1] = {0};
  PetscInt  nt = help ? 2 * b->nstages : 3 * CONTACT_MAX_STAGES + 1, np = help ? b->nstages : CONTACT_MAX_STAGES + 1; /* -help: as many as a run reads */
  PetscBool setT, setP;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(lprefix, sizeof(lprefix), "%sload_%s_", prefix, L->group));
  PetscOptionsBegin(b->comm, lprefix, "Load on a boundary group", NULL);
  PetscCall(PetscOptionsRealArray("-traction", "Traction tx,ty per unit reference length (a dead load; tx,ty,tz per unit area on a 3D body); with -load_stages S, S of them, stage-major (tx1,ty1,tx2,ty2,...)", NULL, vt, &nt, &setT));
  if (b->nstages == 1) { /* one value, shown with its default */
    PetscCall(PetscOptionsReal("-pressure", "Pressure along the inward reference normal (a dead load; instead of -traction); with -load_stages S, S values", NULL, vp[0], &vp[0], &setP));
    np = 1;
  } else PetscCall(PetscOptionsRealArray("-pressure", "Pressure along the inward reference normal (a dead load; instead of -traction); with -load_stages S, S values", NULL, vp, &np, &setP));
  PetscOptionsEnd();
  if (help) PetscFunctionReturn(0); /* listed, not required */
  PetscCheck(setT || setP, b->comm, PETSC_ERR_USER_INPUT, "option -%sload: group %s needs -%straction tx,ty or -%spressure p", prefix, L->group, lprefix, lprefix);
  PetscCheck(!(setT && setP), b->comm, PETSC_ERR_USER_INPUT, "option -%spressure: group %s has -%straction too; give one of them", lprefix, L->group, lprefix);
  L->ncomp = setT && nt % b->nstages == 0 ? nt / b->nstages : 0;
  PetscCheck(!setT || L->ncomp == 2 || L->ncomp == 3, b->comm, PETSC_ERR_USER_INPUT, "option -%straction: give two components tx,ty (three, tx,ty,tz, on a 3D body) a stage, got %" PetscInt_FMT, lprefix, nt);
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s%s", lprefix, setT ? "traction" : "pressure"));
  if (setT) PetscCall(BodyStagedValues(b, opt, nt, L->ncomp, vt, 3, &L->stageTraction[0][0]));
  else PetscCall(BodyStagedValues(b, opt, np, 1, vp, 1, L->stagePressure));
  for (PetscInt c = 0; c < 3; ++c) L->traction[c] = L->stageTraction[b->nstages - 1][c]; /* the last stage's, until the solve sets another */
  L->pressure    = L->stagePressure[b->nstages - 1];
  L->isPressure  = setP;
  PetscFunctionReturn(0);
}

PetscErrorCode BodyLoadsSetFromOptions(Body b, const char prefix[], PetscBool help)
{
  char     *names[CONTACT_MAX_BC], opt[4 * CONTACT_NAME_LEN];
  PetscInt  n = CONTACT_MAX_BC;

  PetscFunctionBeginUser;
  PetscOptionsBegin(b->comm, prefix, "Body loads", NULL);
  PetscCall(ContactOptionsStringArray(PetscOptionsObject, "-load", "Loaded physical groups (see -<body>_load_<group>_traction, _pressure)", NULL, names, &n, NULL));
  PetscOptionsEnd();
  if (help && !n) { /* a load's options under a placeholder group */
    PetscCall(PetscStrallocpy("<group>", &names[0]));
    n = 1;
  }
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sload", prefix));
  PetscCall(BodyCheckGroupsUnique(b, opt, n, names));
  b->nload = n;
  for (PetscInt i = 0; i < n; ++i) {
    PetscCall(PetscStrncpy(b->load[i].group, names[i], sizeof(b->load[i].group)));
    PetscCall(PetscFree(names[i]));
    PetscCall(BodyLoadSetFromOptions(b, prefix, help, &b->load[i]));
  }
  PetscFunctionReturn(0);
}

/* The consistent nodal forces of load L on edge e with nodes x (corner,
   corner, mid), into fe[3][2], by the nq-point Gauss rule gx, gw. */
static PetscErrorCode EdgeLoadForces(Body b, const BodyLoad *L, PetscInt e, const PetscReal x[6], PetscInt nq, const PetscReal gx[], const PetscReal gw[], PetscReal fe[3][2])
{
  PetscReal sign = 1.0;

  PetscFunctionBeginUser;
  if (L->isPressure) {
    char what[2 * CONTACT_NAME_LEN];
    PetscCall(PetscSNPrintf(what, sizeof(what), "body %s, load", b->name));
    PetscCall(BodyEdgeOutwardSign(b, e, x, what, L->group, &sign));
  }
  for (PetscInt a = 0; a < 3; ++a) fe[a][0] = fe[a][1] = 0.0;
  for (PetscInt q = 0; q < nq; ++q) {
    const PetscReal xi = gx[q], N[3] = {0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi};
    const PetscReal dN[3] = {xi - 0.5, xi + 0.5, -2.0 * xi};
    PetscReal       dX = 0, dY = 0, X = 0, t[2], rw;

    for (PetscInt a = 0; a < 3; ++a) {
      dX += dN[a] * x[2 * a];
      dY += dN[a] * x[2 * a + 1];
      X += N[a] * x[2 * a];
    }
    rw = BodyRadialWeight(b, X);
    if (L->isPressure) { /* -p n |dX/dxi| */
      t[0] = -L->pressure * sign * dY;
      t[1] = L->pressure * sign * dX;
    } else {
      const PetscReal J = PetscSqrtReal(dX * dX + dY * dY);
      t[0] = L->traction[0] * J;
      t[1] = L->traction[1] * J;
    }
    for (PetscInt a = 0; a < 3; ++a) {
      fe[a][0] += gw[q] * rw * N[a] * t[0];
      fe[a][1] += gw[q] * rw * N[a] * t[1];
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BodyLoadGetEdges(Body b, const BodyLoad *L, PetscInt *n, IS *is)
{
  DMLabel  faces;
  PetscInt tag;

  PetscFunctionBeginUser;
  *n  = 0;
  *is = NULL;
  PetscCall(BodyGetPhysicalTag(b, L->group, b->dim - 1, &tag));
  PetscCall(DMGetLabel(b->dm, "Face Sets", &faces));
  if (faces) PetscCall(DMLabelGetStratumIS(faces, tag, is));
  if (*is) PetscCall(ISGetLocalSize(*is, n));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyLoadEdgeForces(Body b, const BodyLoad *L, PetscInt e, PetscInt pts[3], PetscReal fe[3][2])
{
  const PetscInt nq = L->isPressure ? 3 : 6;
  PetscReal      x[6], gx[6], gw[6];

  PetscFunctionBeginUser;
  PetscCall(PetscDTGaussQuadrature(nq, -1.0, 1.0, gx, gw));
  PetscCall(BodyEdgeNodes(b, e, pts, x));
  PetscCall(EdgeLoadForces(b, L, e, x, nq, gx, gw, fe));
  PetscFunctionReturn(0);
}

/* A face element's reference rule and basis: Lagrange P2 (Tri6) or Q2
   (Quad9) in 2D, at the rule of the load (above). */
typedef struct {
  PetscFE          fe;
  PetscTabulation  T;
  PetscInt         nq, nb;
  const PetscReal *w;
} FaceRule;

static PetscErrorCode FaceRuleCreate(PetscBool simplex, PetscBool pressure, FaceRule *r)
{
  PetscQuadrature q;

  PetscFunctionBeginUser;
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 2, 1, simplex, 2, PETSC_DETERMINE, &r->fe));
  if (simplex) PetscCall(PetscDTSimplexQuadrature(2, pressure ? 6 : 10, PETSCDTSIMPLEXQUAD_DEFAULT, &q));
  else PetscCall(PetscDTGaussTensorQuadrature(2, 1, pressure ? 3 : 6, -1.0, 1.0, &q));
  PetscCall(PetscFESetQuadrature(r->fe, q));
  PetscCall(PetscQuadratureDestroy(&q));
  PetscCall(PetscFEGetDimension(r->fe, &r->nb));
  PetscCall(PetscFEGetCellTabulation(r->fe, 1, &r->T));
  PetscCall(PetscFEGetQuadrature(r->fe, &q));
  PetscCall(PetscQuadratureGetData(q, NULL, NULL, &r->nq, NULL, &r->w));
  PetscFunctionReturn(0);
}

/* The consistent nodal forces of load L on face f of a 3D body (above):
   its nodes' points pts[nb] and forces fe[nb][3]. */
static PetscErrorCode FaceLoadForces(Body b, const BodyLoad *L, PetscInt f, const FaceRule *r, PetscInt pts[], PetscReal fe[][3])
{
  PetscSection    s;
  PetscInt       *cl = NULL, ncl, k = 0;
  const PetscInt *supp;
  PetscReal       x[9][3], xf[3] = {0, 0, 0}, xc[3] = {0, 0, 0}, sign = 1.0, area[3] = {0, 0, 0}, cnt = 0;
  PetscInt        nsupp;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(b->dm, &s));
  PetscCall(DMPlexGetTransitiveClosure(b->dm, f, PETSC_TRUE, &ncl, &cl));
  for (PetscInt i = 0; i < ncl; ++i) {
    PetscInt dof;
    PetscCall(PetscSectionGetDof(s, cl[2 * i], &dof));
    if (!dof) continue;
    PetscCheck(k < r->nb, PETSC_COMM_SELF, PETSC_ERR_PLIB, "face %" PetscInt_FMT ": more nodes than its element's %" PetscInt_FMT, f, r->nb);
    pts[k] = cl[2 * i];
    for (PetscInt d = 0; d < 3; ++d) x[k][d] = b->xpoint[3 * (cl[2 * i] - b->pStart) + d];
    k++;
  }
  PetscCall(DMPlexRestoreTransitiveClosure(b->dm, f, PETSC_TRUE, &ncl, &cl));
  PetscCheck(k == r->nb, PETSC_COMM_SELF, PETSC_ERR_PLIB, "face %" PetscInt_FMT ": %" PetscInt_FMT " nodes, its element has %" PetscInt_FMT, f, k, r->nb);
  for (PetscInt a = 0; a < r->nb; ++a)
    for (PetscInt c = 0; c < 3; ++c) fe[a][c] = 0.0;
  for (PetscInt q = 0; q < r->nq; ++q) {
    const PetscReal *N = &r->T->T[0][q * r->nb], *D = &r->T->T[1][q * r->nb * 2];
    PetscReal        T1[3] = {0, 0, 0}, T2[3] = {0, 0, 0}, nA[3], t[3];

    for (PetscInt a = 0; a < r->nb; ++a)
      for (PetscInt d = 0; d < 3; ++d) {
        T1[d] += D[2 * a] * x[a][d];
        T2[d] += D[2 * a + 1] * x[a][d];
        xf[d] += q == 0 ? x[a][d] / r->nb : 0.0;
      }
    nA[0] = T1[1] * T2[2] - T1[2] * T2[1];
    nA[1] = T1[2] * T2[0] - T1[0] * T2[2];
    nA[2] = T1[0] * T2[1] - T1[1] * T2[0];
    for (PetscInt d = 0; d < 3; ++d) area[d] += r->w[q] * nA[d];
    if (L->isPressure)
      for (PetscInt d = 0; d < 3; ++d) t[d] = -L->pressure * nA[d];
    else {
      const PetscReal J = PetscSqrtReal(nA[0] * nA[0] + nA[1] * nA[1] + nA[2] * nA[2]);
      for (PetscInt d = 0; d < 3; ++d) t[d] = L->traction[d] * J;
    }
    for (PetscInt a = 0; a < r->nb; ++a)
      for (PetscInt d = 0; d < 3; ++d) fe[a][d] += r->w[q] * N[a] * t[d];
  }
  if (L->isPressure) { /* outward: away from the centre of the cell on the face */
    PetscCall(DMPlexGetSupportSize(b->dm, f, &nsupp));
    PetscCall(DMPlexGetSupport(b->dm, f, &supp));
    PetscCheck(nsupp == 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s, load: a face of group '%s' is not on the boundary", b->name, L->group);
    PetscCall(DMPlexGetTransitiveClosure(b->dm, supp[0], PETSC_TRUE, &ncl, &cl));
    for (PetscInt i = 0; i < ncl; ++i) {
      PetscInt dof;
      PetscCall(PetscSectionGetDof(s, cl[2 * i], &dof));
      if (!dof) continue;
      for (PetscInt d = 0; d < 3; ++d) xc[d] += b->xpoint[3 * (cl[2 * i] - b->pStart) + d];
      cnt += 1;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(b->dm, supp[0], PETSC_TRUE, &ncl, &cl));
    sign = area[0] * (xf[0] - xc[0] / cnt) + area[1] * (xf[1] - xc[1] / cnt) + area[2] * (xf[2] - xc[2] / cnt) > 0 ? 1.0 : -1.0;
    for (PetscInt a = 0; a < r->nb; ++a)
      for (PetscInt d = 0; d < 3; ++d) fe[a][d] *= sign;
  }
  PetscFunctionReturn(0);
}

/* Load L's nodal forces on this rank's owned faces of its group (a 3D
   body's) into the local array f, and its resultant (this rank's) into r. */
static PetscErrorCode BodyLoadAssembleFaces(Body b, PetscSection s, const BodyLoad *L, PetscScalar f[], PetscReal r[3])
{
  IS              is;
  PetscInt        n, gn;
  const PetscInt *pts = NULL;
  FaceRule        rule;

  PetscFunctionBeginUser;
  PetscCheck(L->isPressure || L->ncomp == 3, b->comm, PETSC_ERR_USER_INPUT, "option -%s_load_%s_traction: %" PetscInt_FMT " components a stage for a 3D body (give tx,ty,tz)", b->name, L->group, L->ncomp);
  PetscCall(FaceRuleCreate(b->simplex, L->isPressure, &rule));
  PetscCall(BodyLoadGetEdges(b, L, &n, &is));
  if (is) PetscCall(ISGetIndices(is, &pts));
  for (PetscInt i = 0; i < n; ++i) {
    PetscInt  np[9];
    PetscReal fe[9][3];

    if (!b->owned[pts[i] - b->pStart]) continue;
    PetscCall(FaceLoadForces(b, L, pts[i], &rule, np, fe));
    for (PetscInt a = 0; a < rule.nb; ++a) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(s, np[a], &off));
      for (PetscInt d = 0; d < 3; ++d) {
        f[off + d] += fe[a][d];
        r[d] += fe[a][d];
      }
    }
  }
  if (is) {
    PetscCall(ISRestoreIndices(is, &pts));
    PetscCall(ISDestroy(&is));
  }
  PetscCall(PetscFEDestroy(&rule.fe));
  PetscCall(MPIU_Allreduce(&n, &gn, 1, MPIU_INT, MPI_SUM, b->comm));
  PetscCheck(gn > 0, b->comm, PETSC_ERR_FILE_UNEXPECTED, "option -%s_load: physical group '%s' of mesh %s has no faces", b->name, L->group, b->msh);
  PetscFunctionReturn(0);
}

/* Adds load L's nodal forces on this rank's owned edges of its group into
   the local array f, and its resultant (this rank's) into r. */
static PetscErrorCode BodyLoadAssemble(Body b, PetscSection s, const BodyLoad *L, PetscScalar f[], PetscReal r[3])
{
  IS              is;
  PetscInt        n, gn;
  const PetscInt *pts = NULL;

  PetscFunctionBeginUser;
  if (b->dim == 3) {
    PetscCall(BodyLoadAssembleFaces(b, s, L, f, r));
    PetscFunctionReturn(0);
  }
  PetscCheck(L->isPressure || L->ncomp == 2, b->comm, PETSC_ERR_USER_INPUT, "option -%s_load_%s_traction: %" PetscInt_FMT " components a stage for a 2D body (give tx,ty)", b->name, L->group, L->ncomp);
  PetscCall(BodyLoadGetEdges(b, L, &n, &is));
  if (is) PetscCall(ISGetIndices(is, &pts));
  for (PetscInt i = 0; i < n; ++i) {
    PetscInt  np[3];
    PetscReal fe[3][2];

    if (!b->owned[pts[i] - b->pStart]) continue;
    PetscCall(BodyLoadEdgeForces(b, L, pts[i], np, fe));
    for (PetscInt a = 0; a < 3; ++a) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(s, np[a], &off));
      f[off] += fe[a][0];
      f[off + 1] += fe[a][1];
      r[0] += fe[a][0];
      r[1] += fe[a][1];
    }
  }
  if (is) {
    PetscCall(ISRestoreIndices(is, &pts));
    PetscCall(ISDestroy(&is));
  }
  PetscCall(MPIU_Allreduce(&n, &gn, 1, MPIU_INT, MPI_SUM, b->comm));
  PetscCheck(gn > 0, b->comm, PETSC_ERR_FILE_UNEXPECTED, "option -%s_load: physical group '%s' of mesh %s has no edges", b->name, L->group, b->msh);
  PetscFunctionReturn(0);
}

PetscErrorCode BodyLoadsAssemble(Body b, Vec F, PetscBool from)
{
  PetscSection s;
  PetscScalar *f;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(b->dm, &s));
  PetscCall(VecSet(F, 0.0));
  PetscCall(VecGetArray(F, &f));
  for (PetscInt i = 0; i < b->nload; ++i) {
    PetscReal r[3] = {0, 0, 0};
    PetscCall(BodyLoadAssemble(b, s, &b->load[i], f, r));
    PetscCall(MPIU_Allreduce(r, from ? b->load[i].forceFrom : b->load[i].force, b->dim, MPIU_REAL, MPIU_SUM, b->comm));
  }
  PetscCall(VecRestoreArray(F, &f));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyLoadsSetUp(Body b)
{
  PetscFunctionBeginUser;
  if (!b->nload) PetscFunctionReturn(0);
  PetscCall(VecDuplicate(b->Xl, &b->Fl));
  PetscCall(BodyLoadsAssemble(b, b->Fl, PETSC_FALSE));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyLoadsAddEnergyGradient(Body b, const PetscScalar x[], PetscReal *energy, PetscScalar g[])
{
  const PetscScalar *f, *f0 = NULL;
  PetscInt           n;
  PetscReal          e = 0.0;

  PetscFunctionBeginUser;
  if (!b->Fl) PetscFunctionReturn(0);
  PetscCall(VecGetLocalSize(b->Fl, &n));
  PetscCall(VecGetArrayRead(b->Fl, &f));
  if (b->FlFrom) PetscCall(VecGetArrayRead(b->FlFrom, &f0));
  for (PetscInt k = 0; k < n; ++k) { /* the load at the load parameter: w_1 Fl (+ w_0 FlFrom after the first stage; history.c) */
    const PetscReal fk = b->loadWeight[1] * PetscRealPart(f[k]) + (f0 ? b->loadWeight[0] * PetscRealPart(f0[k]) : 0.0);
    e -= fk * PetscRealPart(x[k]);
    g[k] -= fk;
  }
  if (f0) PetscCall(VecRestoreArrayRead(b->FlFrom, &f0));
  PetscCall(VecRestoreArrayRead(b->Fl, &f));
  *energy += e;
  PetscFunctionReturn(0);
}
