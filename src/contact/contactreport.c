/* The results of a contact pair, whatever the formulation: the profiles of the
   two surfaces (a slave's own, a master's transferred from the slave where the
   formulation gives one) gathered on rank 0 (mirrored for half models) and
   compared with Hertz, the forces and the largest penetration reduced over
   ranks; the console report, the JSON members and the HDF5 group. */
#include <petscviewerhdf5.h>
#include "contactreport.h"
#include "outputwrite.h"
#include "xdmf.h"

#define CONTACT_MIRROR_ROW_TOL 1e-10 /* a row this close to the line, relative to the arc length, is on it */

PetscErrorCode ContactReportReset(ContactReport *R)
{
  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) PetscCall(PetscFree(R->side[s].rows));
  PetscCall(PetscMemzero(R, sizeof(*R)));
  PetscFunctionReturn(0);
}

/* Gathers one side's rows on rank 0, adds their mirror images for a half
   model (about the end of the arc that lies on the symmetry line: s = 0 or
   the surface's length L; a row there, a node on the line, is its own image
   and becomes the whole model's row, its weight and force doubled), sorts
   them by s and computes the figures. */
static PetscErrorCode ContactSideGather(ContactSide *S, const ContactPairSpec *spec, const ContactReport *R, MPI_Comm comm, PetscInt nloc, const PetscReal rows[], PetscReal L)
{
  const PetscInt C = CONTACT_ROW_COLS;
  PetscMPIInt    rank, size, *cnt, *disp, nl = (PetscMPIInt)(C * nloc);
  PetscReal     *all = NULL;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMalloc2(size, &cnt, size + 1, &disp));
  PetscCallMPI(MPI_Gather(&nl, 1, MPI_INT, cnt, 1, MPI_INT, 0, comm));
  if (!rank) {
    disp[0] = 0;
    for (PetscMPIInt r = 0; r < size; ++r) disp[r + 1] = disp[r] + cnt[r];
    PetscCall(PetscMalloc1(2 * disp[size] + 1, &all));
  }
  PetscCallMPI(MPI_Gatherv(rows, nl, MPIU_REAL, all, cnt, disp, MPIU_REAL, 0, comm));
  if (!rank) {
    PetscInt   m = disp[size] / C, *perm;
    PetscReal *sv;
    if (spec->mirror && m > 0) {
      PetscInt  lo = 0, hi = 0;
      PetscReal scut;
      for (PetscInt i = 1; i < m; ++i) {
        if (all[C * i] < all[C * lo]) lo = i;
        if (all[C * i] > all[C * hi]) hi = i;
      }
      PetscInt  k = m;
      scut = PetscAbsReal(all[C * lo + CONTACT_ROW_Y] - spec->mirrorY) <= PetscAbsReal(all[C * hi + CONTACT_ROW_Y] - spec->mirrorY) ? 0.0 : L;
      for (PetscInt i = 0; i < m; ++i) {
        PetscReal *o = &all[C * i], *r = &all[C * k];
        if (PetscAbsReal(o[CONTACT_ROW_S] - scut) <= CONTACT_MIRROR_ROW_TOL * L) { /* a node on the line is its own image: one row, both halves' weight and force */
          o[CONTACT_ROW_W] *= 2.0;
          o[CONTACT_ROW_FX] *= 2.0;
          o[CONTACT_ROW_FY] = 0.0;
          continue;
        }
        PetscCall(PetscArraycpy(r, o, C));
        r[CONTACT_ROW_S]  = 2.0 * scut - r[CONTACT_ROW_S];
        r[CONTACT_ROW_Y]  = 2.0 * spec->mirrorY - r[CONTACT_ROW_Y];
        r[CONTACT_ROW_YC] = 2.0 * spec->mirrorY - r[CONTACT_ROW_YC];
        r[CONTACT_ROW_FY] = -r[CONTACT_ROW_FY];
        k++;
      }
      m = k;
    }
    PetscCall(PetscMalloc2(m + 1, &perm, m + 1, &sv));
    for (PetscInt i = 0; i < m; ++i) {
      perm[i] = i;
      sv[i]   = all[C * i];
    }
    PetscCall(PetscSortRealWithPermutation(m, sv, perm));
    PetscCall(PetscMalloc1(C * m + C, &S->rows));
    for (PetscInt i = 0; i < m; ++i) PetscCall(PetscArraycpy(&S->rows[C * i], &all[C * perm[i]], C));
    S->n = m;
    ContactProfileCompare(m, S->rows, R->nodal, spec->axisym, spec->hertz, R->hertzA, R->hertzPmax, &S->fig);
    PetscCall(PetscFree2(perm, sv));
    PetscCall(PetscFree(all));
  }
  PetscCall(PetscFree2(cnt, disp));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactReportFinish(ContactReport *R, const ContactPairSpec *spec, MPI_Comm comm, const PetscInt nloc[2], PetscReal *const rows[2], const PetscReal force[2][2], PetscReal maxPen, const PetscReal arcLength[2])
{
  PetscReal f[4] = {force[0][0], force[0][1], force[1][0], force[1][1]};

  PetscFunctionBeginUser;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, f, 4, MPIU_REAL, MPIU_SUM, comm));
  PetscCall(MPIU_Allreduce(&maxPen, &R->maxPen, 1, MPIU_REAL, MPIU_MAX, comm));
  /* In r-z the sums over a surface's nodes have no radial resultant. The
     radial column is sum_j int p n_r N_j 2 pi r dS, the rings' radial line
     loads (on the sphere scene p n_r ~ p r / 2R on the flat's dented face:
     3 pi a / 32 R of P, 3 %), and a ring's radial load points along
     (cos th, sin th) around the circle, so it integrates to zero there: the
     hoop stress carries it, not the other body. The force of a surface and
     of the pair is axial, its radial component 0 by symmetry; the nodes'
     own forces (node_force) keep theirs. */
  if (spec->axisym) f[0] = f[2] = 0.0;
  for (PetscInt s = 0; s < 2; ++s) {
    R->side[s].force[0] = f[2 * s];
    R->side[s].force[1] = f[2 * s + 1];
  }
  R->force[0] = f[0];
  R->force[1] = f[1];
  /* a mirrored half doubles the force across the line and cancels it along */
  R->resultant[0] = spec->mirror ? 2.0 * f[0] : f[0];
  R->resultant[1] = spec->mirror ? 0.0 : f[1];
  R->P            = PetscSqrtReal(PetscSqr(R->resultant[0]) + PetscSqr(R->resultant[1]));
  R->hEdge = PETSC_MAX_REAL;
  for (PetscInt s = 0; s < 2; ++s)
    if (R->side[s].nedges > 0) R->hEdge = PetscMin(R->hEdge, arcLength[s] / R->side[s].nedges);
  if (spec->hertz && spec->axisym) HertzPointContact(R->P, spec->Estar, spec->Rstar, &R->hertzA, &R->hertzPmax);
  else if (spec->hertz) HertzLineContact(R->P, spec->Estar, spec->Rstar, &R->hertzA, &R->hertzPmax);
  for (PetscInt s = 0; s < 2; ++s) {
    PetscCall(ContactSideGather(&R->side[s], spec, R, comm, nloc[s], rows[s], arcLength[s]));
    /* every rank holds the figures (HDF5 attributes are written collectively) */
    PetscCallMPI(MPI_Bcast(&R->side[s].fig, sizeof(ContactProfileFigures) / sizeof(PetscReal), MPIU_REAL, 0, comm));
  }
  { /* the mean over the surfaces that act as slave */
    PetscReal f[4] = {0, 0, 0, 0};
    PetscInt  n    = 0;
    for (PetscInt s = 0; s < 2; ++s) {
      if (!R->side[s].slave) continue;
      f[0] += R->side[s].fig.pmax;
      f[1] += R->side[s].fig.a;
      f[2] += R->side[s].fig.am;
      f[3] += R->side[s].fig.l2err;
      n++;
    }
    for (PetscInt s = 1; s >= 0; --s)
      if (R->side[s].slave) PetscCall(PetscArraycpy(R->zone, R->side[s].fig.zone, 2));
    R->femPmax = f[0] / n;
    R->femA    = f[1] / n;
    R->femAm   = f[2] / n;
    R->l2err   = f[3] / n;
  }
  R->done    = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* The penalty formulations are meant for overlaps small against the
   elements. Deeper than a contact edge, the closest point on the master
   jumps between its edges under small motions and the discrete energy turns
   non-convex (measured on the half hertz scene at k_p = 1e3: saddles where
   Newton's step meets negative curvature, with the solve then wandering to
   lower, asymmetric states): the answer is the penalty's, not the contact's.
   The cure is a stiffer penalty. */
PetscErrorCode ContactReportDiagnose(const ContactReport *R, const ContactPairSpec *spec, size_t n, char why[])
{
  PetscFunctionBeginUser;
  why[0] = 0;
  if (!R->done || !(R->maxPen > R->hEdge)) PetscFunctionReturn(0);
  PetscCall(PetscSNPrintf(why, n, "pair %s: the bodies overlap by %.3g, %.3g times the contact edges' mean length %.3g; the penalty k_p = %g is too soft for this load: raise -contact_%s_penalty", spec->name, (double)R->maxPen, (double)(R->maxPen / R->hEdge), (double)R->hEdge, (double)R->kp, spec->name));
  PetscFunctionReturn(0);
}

/* A force as the report prints it: (x, y) in plane strain, its axial
   component alone in r-z (the radial one is 0 by symmetry: ContactReportFinish). */
static PetscErrorCode ContactForceString(const PetscReal f[2], PetscBool axisym, char buf[], size_t n)
{
  PetscFunctionBeginUser;
  if (axisym) PetscCall(PetscSNPrintf(buf, n, "axial %.6e", (double)f[1]));
  else PetscCall(PetscSNPrintf(buf, n, "(%.6e, %.6e)", (double)f[0], (double)f[1]));
  PetscFunctionReturn(0);
}

/* Dundurs' second constant of two bodies in plane strain:
   beta = [(1 - 2 nu1)/G1 - (1 - 2 nu2)/G2] / [2 ((1 - nu1)/G1 + (1 - nu2)/G2)],
   G the shear modulus (E / (2 (1 + nu)), the material's at rest), a rigid body's terms
   0; 0 for elastically similar bodies, where a normal load makes no
   tangential mismatch (Cattaneo-Mindlin's assumption). */
static PetscReal ContactDundursBeta(Body a, Body b)
{
  PetscReal n = 0.0, d = 0.0;
  Body      ab[2] = {a, b};

  for (PetscInt k = 0; k < 2; ++k) {
    PetscReal E, nu, G;
    BodyGetElasticConstants(ab[k], &E, &nu);
    G = E / (2.0 * (1.0 + nu));
    if (!(G > 0) || PetscIsInfReal(G)) continue; /* a rigid body (E = inf): no compliance */
    n += (k == 0 ? 1.0 : -1.0) * (1.0 - 2.0 * nu) / G;
    d += 2.0 * (1.0 - nu) / G;
  }
  return d > 0 ? n / d : 0.0;
}

PetscErrorCode ContactReportView(const ContactReport *R, const ContactPairSpec *spec, Body bodies[], MPI_Comm comm)
{
  const PetscInt C = CONTACT_ROW_COLS;
  PetscMPIInt    rank;
  char           fs[2][64];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (spec->kpAuto) PetscCall(PetscPrintf(comm, "Contact pair %s (%s, k_p = %g, auto: %g E*/h, E* = %g, h = %g): %s:%s against %s:%s\n", spec->name, spec->formulation, (double)R->kp, (double)CONTACT_PENALTY_AUTO, (double)spec->Estar, (double)spec->kpH, BodyGetName(bodies[spec->body[0]]), spec->group[0], BodyGetName(bodies[spec->body[1]]), spec->group[1]));
  else PetscCall(PetscPrintf(comm, "Contact pair %s (%s, k_p = %g): %s:%s against %s:%s\n", spec->name, spec->formulation, (double)R->kp, BodyGetName(bodies[spec->body[0]]), spec->group[0], BodyGetName(bodies[spec->body[1]]), spec->group[1]));
  PetscCall(ContactForceString(R->resultant, spec->axisym, fs[0], sizeof(fs[0])));
  if (R->friction) { /* the whole force, and its parts */
    const PetscReal whole[2] = {R->resultant[0] + R->shearForce[0], R->resultant[1] + R->shearForce[1]};
    char            ws[128];
    PetscCall(ContactForceString(whole, spec->axisym, ws, sizeof(ws)));
    PetscCall(PetscPrintf(comm, "  contact force on %s%s: %s = pressure %s + shear (%.6e, %.6e), P = %.6e\n", BodyGetName(bodies[spec->body[0]]), spec->axisym ? " (the whole circle's; radial 0 by symmetry)" : "", ws, fs[0], (double)R->shearForce[0], (double)R->shearForce[1], (double)R->P));
  } else PetscCall(PetscPrintf(comm, "  contact force on %s%s: %s, P = %.6e\n", BodyGetName(bodies[spec->body[0]]), spec->mirror ? " (with its mirror image)" : spec->axisym ? " (the whole circle's; radial 0 by symmetry)" : "", fs[0], (double)R->P));
  PetscCall(PetscPrintf(comm, "  largest penetration %.6e (p_max/k_p = %.6e)\n", (double)R->maxPen, (double)(R->femPmax / R->kp)));
  if (R->friction) {
    PetscCall(PetscPrintf(comm, "  friction mu = %g: shear force (%.6e, %.6e); the whole force %.6e along the contact zone's normal, Q = %.6e across, Q/(mu P) = %.4f; stick zone %s c = %.6g", (double)spec->friction, (double)R->shearForce[0], (double)R->shearForce[1], (double)R->normalLoad, (double)R->tangentialLoad, (double)(R->normalLoad > 0 ? R->tangentialLoad / (spec->friction * R->normalLoad) : 0.0), spec->axisym ? "radius" : "half-width", (double)R->stickHalfWidth));
    if (spec->hertz && R->mindlinC > 0) {
      const PetscReal beta = ContactDundursBeta(bodies[spec->body[0]], bodies[spec->body[1]]);
      PetscCall(PetscPrintf(comm, ", Mindlin's %.6g for Q after P at constant P (%+.2f %%)", (double)R->mindlinC, (double)(100.0 * (R->stickHalfWidth / R->mindlinC - 1.0))));
      if (PetscAbsReal(beta) > 1e-3) PetscCall(PetscPrintf(comm, " (his is for elastically similar bodies; these have Dundurs' beta = %.3g)", (double)beta));
    }
    PetscCall(PetscPrintf(comm, "\n"));
  }
  {
    char why[PETSC_MAX_PATH_LEN];
    PetscCall(ContactReportDiagnose(R, spec, sizeof(why), why));
    if (why[0]) PetscCall(PetscPrintf(comm, "  WARNING: %s\n", why));
  }
  if (!rank) {
    for (PetscInt s = 0; s < 2; ++s) {
      const ContactSide *S = &R->side[s];
      PetscInt           first = -1, last = -1, step;
      for (PetscInt i = 0; i < S->n; ++i)
        if (S->rows[C * i + CONTACT_ROW_P] > 0) {
          if (first < 0) first = i;
          last = i;
        }
      if (!S->slave && !S->n) {
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %s:%s: master only\n", BodyGetName(bodies[spec->body[s]]), spec->group[s]));
        continue;
      }
      if (S->slave) PetscCall(PetscPrintf(PETSC_COMM_SELF, "  pressure on %s:%s (centre s = %.6g):\n", BodyGetName(bodies[spec->body[s]]), spec->group[s], (double)S->fig.sc));
      else {
        PetscCall(ContactForceString(S->force, spec->axisym, fs[0], sizeof(fs[0])));
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "  pressure on %s:%s, master: the slave's pressure at its closest points (centre s = %.6g, peak %.6g, force %s):\n", BodyGetName(bodies[spec->body[s]]), spec->group[s], (double)S->fig.sc, (double)S->fig.pmax, fs[0]));
      }
      if (first < 0) {
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "    no contact\n"));
        continue;
      }
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "    contact zone: %s in [%.6g, %.6g], width %.6g\n", spec->axisym ? "reference r" : "s", (double)S->fig.zone[0], (double)S->fig.zone[1], (double)(S->fig.zone[1] - S->fig.zone[0])));
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "    %12s %12s %12s %12s\n", spec->axisym ? "r" : "s - s_c", "p", spec->hertz ? "p Hertz" : "", "gap"));
      first = PetscMax(0, first - 1);
      last  = PetscMin(S->n - 1, last + 1);
      step  = PetscMax(1, (last - first + 1) / 21);
      for (PetscInt i = first; i <= last; i += step) {
        const PetscReal *r  = &S->rows[C * i];
        const PetscReal  ds = spec->axisym ? r[CONTACT_ROW_X] : r[CONTACT_ROW_S] - S->fig.sc;
        char             hz[32] = "", gap[32] = "unpaired"; /* a sample nothing faces has no gap (CONTACT_GAP_NONE) */
        if (spec->hertz) PetscCall(PetscSNPrintf(hz, sizeof(hz), "%12.6g", (double)(R->hertzA > 0 ? HertzPressure(R->hertzPmax, R->hertzA, ds) : 0.0)));
        if (!PetscIsInfOrNanReal(r[CONTACT_ROW_GAP])) PetscCall(PetscSNPrintf(gap, sizeof(gap), "%.4e", (double)r[CONTACT_ROW_GAP]));
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "    %12.5g %12.6g %12s %12s\n", (double)ds, (double)r[CONTACT_ROW_P], hz, gap));
      }
    }
  }
  if (R->nodal) {
    const PetscReal *a = R->side[0].force, *b = R->side[1].force, na = PetscSqrtReal(a[0] * a[0] + a[1] * a[1]);
    PetscCall(ContactForceString(a, spec->axisym, fs[0], sizeof(fs[0])));
    PetscCall(ContactForceString(b, spec->axisym, fs[1], sizeof(fs[1])));
    PetscCall(PetscPrintf(comm, "  nodal contact forces%s: %s:%s %s, %s:%s %s; |sum| / |force| = %.1e\n", spec->mirror ? " (the half model)" : "", BodyGetName(bodies[spec->body[0]]), spec->group[0], fs[0], BodyGetName(bodies[spec->body[1]]), spec->group[1], fs[1], (double)(na > 0 ? PetscSqrtReal(PetscSqr(a[0] + b[0]) + PetscSqr(a[1] + b[1])) / na : 0.0)));
  }
  if (spec->hertz && !(R->P > 0)) PetscCall(PetscPrintf(comm, "  no contact force: nothing to compare with Hertz\n"));
  else if (spec->hertz) {
    PetscCall(PetscPrintf(comm, "  Hertz%s (E* = %g, R* = %g): a = %.6g, p_max = %.6g\n", spec->axisym ? ", two spheres" : "", (double)spec->Estar, (double)spec->Rstar, (double)R->hertzA, (double)R->hertzPmax));
    PetscCall(PetscPrintf(comm, "  computed:              a = %.6g (%+.2f %%), p_max = %.6g (%+.2f %%)\n", (double)R->femA, (double)(100 * (R->femA / R->hertzA - 1)), (double)R->femPmax, (double)(100 * (R->femPmax / R->hertzPmax - 1))));
    PetscCall(PetscPrintf(comm, "  half-width from the profile's second moment: a = %.6g (%+.2f %%)\n", (double)R->femAm, (double)(100 * (R->femAm / R->hertzA - 1))));
    if (PetscIsInfOrNanReal(R->l2err)) PetscCall(PetscPrintf(comm, "  relative L2 error of the pressure profile: n/a (a surface has no point inside Hertz's zone)\n"));
    else if (R->side[0].slave && R->side[1].slave) PetscCall(PetscPrintf(comm, "  relative L2 error of the pressure profile: %.2f %% (surfaces: %.2f %%, %.2f %%)\n", (double)(100 * R->l2err), (double)(100 * R->side[0].fig.l2err), (double)(100 * R->side[1].fig.l2err)));
    else {
      const ContactSide *M = R->side[0].slave ? &R->side[1] : &R->side[0];
      if (M->fig.pmax > 0 && !PetscIsInfOrNanReal(M->fig.l2err)) PetscCall(PetscPrintf(comm, "  relative L2 error of the pressure profile: %.2f %% (the slave's, over the nodes, weights A_j; the master's: %.2f %%)\n", (double)(100 * R->l2err), (double)(100 * M->fig.l2err)));
      else PetscCall(PetscPrintf(comm, "  relative L2 error of the pressure profile: %.2f %%%s\n", (double)(100 * R->l2err), R->nodal ? " (over the nodes, weights A_j)" : ""));
    }
  }
  PetscFunctionReturn(0);
}

void ContactHertzJSON(FILE *fp, const char sep[], const ContactPairSpec *spec, PetscReal a, PetscReal pmax, PetscReal l2err)
{
  ContactJSONKeyReal(fp, sep, "E_star", spec->Estar);
  ContactJSONKeyReal(fp, sep, "R_star", spec->Rstar);
  ContactJSONKeyReal(fp, sep, "hertz_a", a);
  ContactJSONKeyReal(fp, sep, "hertz_pmax", pmax);
  ContactJSONKeyReal(fp, sep, "pressure_l2_error", l2err);
}

/* The figures of a pair, each preceded by sep. */
static void PairFiguresJSON(FILE *fp, const ContactReport *R, const ContactPairSpec *spec, const char sep[], const char forceKey[])
{
  ContactJSONKeyReal(fp, sep, forceKey, R->P);
  ContactJSONKeyReal(fp, sep, "max_penetration", R->maxPen);
  ContactJSONKeyReal(fp, sep, "overlap_edges", R->hEdge > 0 && R->hEdge < PETSC_MAX_REAL ? R->maxPen / R->hEdge : 0.0); /* over 1: the report's warning */
  ContactJSONKeyReal(fp, sep, "fem_pmax", R->femPmax);
  ContactJSONKeyReal(fp, sep, "fem_a", R->femA);
  ContactJSONKeyReal(fp, sep, "fem_a_moment", R->femAm);
  ContactJSONKeyPair(fp, sep, "zone", R->zone);
  ContactJSONKeyReal(fp, sep, "zone_width", R->zone[1] - R->zone[0]);
  if (spec->hertz) ContactHertzJSON(fp, sep, spec, R->hertzA, R->hertzPmax, R->l2err);
}

/* Rank 0. summary: the figures as top-level members (",\n  key: value" each);
   else the pair's object. */
PetscErrorCode ContactReportWriteJSON(const ContactReport *R, const ContactPairSpec *spec, Body bodies[], FILE *fp, PetscBool summary)
{
  PetscFunctionBeginUser;
  if (summary) {
    PairFiguresJSON(fp, R, spec, ",\n  ", "contact_force");
    PetscFunctionReturn(0);
  }
  fprintf(fp, "{\"formulation\": \"%s\"", spec->formulation);
  ContactJSONKeyReal(fp, ", ", "penalty", R->kp);
  fprintf(fp, ", \"penalty_auto\": %s", spec->kpAuto ? "true" : "false");
  ContactJSONKeyReal(fp, ", ", "penalty_h", spec->kpH);                            /* the contact edges' size h of the rule */
  ContactJSONKeyReal(fp, ", ", "penalty_stiffness", ContactPairPenaltyStiffness(spec)); /* k_p h / E*: 1000 auto, below 25 soft */
  { /* the pair's whole force on its first surface's body, and its parts */
    const PetscReal whole[2] = {R->force[0] + (R->friction ? R->shearForce[0] : 0.0), R->force[1] + (R->friction ? R->shearForce[1] : 0.0)};
    ContactJSONKeyPair(fp, ", ", "force", whole);
    ContactJSONKeyPair(fp, ", ", "pressure_force", R->force);
  }
  ContactJSONKeyReal(fp, ", ", "friction", spec->friction);
  if (R->friction) {
    ContactJSONKeyReal(fp, ", ", "stick_half_width", R->stickHalfWidth);
    ContactJSONKeyPair(fp, ", ", "shear_force", R->shearForce);
    ContactJSONKeyReal(fp, ", ", "tangential_load", R->tangentialLoad);
    if (spec->hertz && !spec->axisym) ContactJSONKeyReal(fp, ", ", "mindlin_c", R->mindlinC);
  }
  PairFiguresJSON(fp, R, spec, ", ", "P");
  fprintf(fp, ", \"surfaces\": [");
  for (PetscInt s = 0; s < 2; ++s) {
    const ContactSide *S = &R->side[s];
    fprintf(fp, "%s{\"body\": \"%s\", \"group\": \"%s\", \"edges\": %d, \"slave\": %s", s ? ", " : "", BodyGetName(bodies[spec->body[s]]), spec->group[s], (int)S->nedges, S->slave ? "true" : "false");
    ContactJSONKeyReal(fp, ", ", "pmax", S->fig.pmax);
    ContactJSONKeyReal(fp, ", ", "a", S->fig.a);
    ContactJSONKeyReal(fp, ", ", "a_moment", S->fig.am);
    ContactJSONKeyReal(fp, ", ", "centre", S->fig.sc);
    ContactJSONKeyPair(fp, ", ", "zone", S->fig.zone);
    ContactJSONKeyReal(fp, ", ", "pressure_integral", S->fig.ptotal);
    ContactJSONKeyPair(fp, ", ", "force", S->force);
    if (spec->hertz) ContactJSONKeyReal(fp, ", ", "pressure_l2_error", S->fig.l2err);
    fprintf(fp, "}");
  }
  fprintf(fp, "]}");
  PetscFunctionReturn(0);
}

/* Rank 0: the line cells through a side's samples, sorted by s, for the XDMF
   file: quadratic edges (Edge_3: corner, corner, mid) when the samples are the
   nodes of the surface's quadratic edges from one end to the other (an odd
   count), else 2-node segments between consecutive samples. None for a side
   without samples. */
static void ContactSideLineCells(const ContactSide *S, PetscBool nodal, PetscInt *ncells, PetscInt *nper)
{
  *nper   = nodal && S->n % 2 == 1 ? 3 : 2;
  *ncells = S->n < 2 ? 0 : (*nper == 3 ? (S->n - 1) / 2 : S->n - 1);
}

/* Per surface, /contact/<pair>/<body>_<group>/: s, X (reference), x
   (current), gap, pressure, weight, from rank 0 (named node_s, node_X, ...
   when the samples are nodes: for a slave its weighted gap, nodal pressure
   and A_j, for a master its gap weighted over the slave's points, the
   transferred pressure and int N_j dS; then also node_force, the pair's
   contact force on each node, in r-z each node's own radial component
   too), and the line cells through them (cells or node_cells,
   ContactSideLineCells); empty datasets and no cells for a surface without
   a profile; as attributes its body, group, centre, samples, slave and
   surface_index. The pair's figures as attributes of /contact/<pair>,
   with friction also mu (friction), stick_half_width, normal_load,
   tangential_load and, where Hertz radii are declared in plane strain,
   mindlin_c, as the JSON has them (collective). */
PetscErrorCode ContactReportWriteHDF5(const ContactReport *R, const ContactPairSpec *spec, Body bodies[], PetscViewer v)
{
  MPI_Comm    comm;
  PetscMPIInt rank;
  char        group[4 * CONTACT_NAME_LEN];

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)v, &comm));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  for (PetscInt s = 0; s < 2; ++s) {
    const ContactSide *S        = &R->side[s];
    const char        *gauss[7] = {"s", "X", "x", "gap", "pressure", "weight", "force"}, *nodal[7] = {"node_s", "node_X", "node_x", "node_gap", "node_pressure", "node_weight", "node_force"};
    const char *const *names    = R->nodal ? nodal : gauss;
    const PetscInt     cols[7]  = {CONTACT_ROW_S, CONTACT_ROW_X, CONTACT_ROW_XC, CONTACT_ROW_GAP, CONTACT_ROW_P, CONTACT_ROW_W, CONTACT_ROW_FX}, bs[7] = {1, 2, 2, 1, 1, 1, 2};
    const PetscInt     n        = rank ? 0 : S->n, nsets = R->nodal ? 7 : 6; /* nodal forces: nodes only */

    PetscCall(PetscSNPrintf(group, sizeof(group), "/contact/%s/%s_%s", spec->name, BodyGetName(bodies[spec->body[s]]), spec->group[s]));
    PetscCall(PetscViewerHDF5PushGroup(v, group));
    for (PetscInt k = 0; k < nsets; ++k) {
      Vec          vec;
      PetscScalar *a;
      PetscCall(VecCreate(comm, &vec));
      PetscCall(VecSetSizes(vec, n * bs[k], PETSC_DETERMINE));
      PetscCall(VecSetBlockSize(vec, bs[k]));
      PetscCall(VecSetType(vec, VECSTANDARD));
      PetscCall(PetscObjectSetName((PetscObject)vec, names[k]));
      PetscCall(VecGetArray(vec, &a));
      for (PetscInt i = 0; i < n; ++i)
        for (PetscInt j = 0; j < bs[k]; ++j) a[i * bs[k] + j] = S->rows[CONTACT_ROW_COLS * i + cols[k] + j];
      PetscCall(VecRestoreArray(vec, &a));
      ContactOutputCall(v, VecView(vec, v));
      PetscCall(VecDestroy(&vec));
    }
    for (PetscInt k = 0; k < 2; ++k) { /* the XDMF grid's stand-ins for the bodies' fields (xdmf.h) */
      Vec vec;
      PetscCall(VecCreate(comm, &vec));
      PetscCall(VecSetSizes(vec, n * (k ? 3 : 1), PETSC_DETERMINE));
      PetscCall(VecSetBlockSize(vec, k ? 3 : 1));
      PetscCall(VecSetType(vec, VECSTANDARD));
      PetscCall(PetscObjectSetName((PetscObject)vec, k ? "xdmf_zero_xyz" : "xdmf_nan"));
      PetscCall(VecSet(vec, k ? 0.0 : (PetscScalar)NAN));
      ContactOutputCall(v, VecView(vec, v));
      PetscCall(VecDestroy(&vec));
    }
    { /* the line cells, decided on rank 0 (it holds the samples) */
      PetscInt lc[2] = {0, 2}, m, *idx;
      IS       is;
      if (!rank) ContactSideLineCells(S, R->nodal, &lc[0], &lc[1]);
      PetscCallMPI(MPI_Bcast(lc, 2, MPIU_INT, 0, comm));
      if (lc[0] > 0) {
        m = rank ? 0 : lc[0];
        PetscCall(PetscMalloc1(m * lc[1] + 1, &idx));
        for (PetscInt c = 0; c < m; ++c) {
          if (lc[1] == 3) {
            idx[3 * c]     = 2 * c;
            idx[3 * c + 1] = 2 * c + 2;
            idx[3 * c + 2] = 2 * c + 1;
          } else {
            idx[2 * c]     = c;
            idx[2 * c + 1] = c + 1;
          }
        }
        PetscCall(ISCreateGeneral(comm, m * lc[1], idx, PETSC_OWN_POINTER, &is));
        PetscCall(ISSetBlockSize(is, lc[1]));
        PetscCall(PetscObjectSetName((PetscObject)is, R->nodal ? "node_cells" : "cells"));
        ContactOutputCall(v, ISView(is, v));
        PetscCall(ISDestroy(&is));
        ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "cell_type", PETSC_STRING, lc[1] == 3 ? "Edge_3" : "Polyline"));
      }
    }
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "body", PETSC_STRING, BodyGetName(bodies[spec->body[s]])));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "group", PETSC_STRING, spec->group[s]));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "centre", PETSC_REAL, &S->fig.sc));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "zone_start", PETSC_REAL, &S->fig.zone[0]));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "zone_end", PETSC_REAL, &S->fig.zone[1]));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "samples", PETSC_STRING, R->nodal ? "nodes" : "gauss_points"));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "slave", PETSC_INT, &(PetscInt){S->slave ? 1 : 0}));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "surface_index", PETSC_INT, &s)); /* its place in -contact_<pair>_surfaces (HDF5 lists groups by name) */
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  PetscCall(PetscSNPrintf(group, sizeof(group), "/contact/%s", spec->name));
  PetscCall(PetscViewerHDF5PushGroup(v, group));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "formulation", PETSC_STRING, spec->formulation));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "penalty", PETSC_REAL, &R->kp));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "P", PETSC_REAL, &R->P));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "max_penetration", PETSC_REAL, &R->maxPen));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "fem_pmax", PETSC_REAL, &R->femPmax));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "fem_a", PETSC_REAL, &R->femA));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "fem_a_moment", PETSC_REAL, &R->femAm));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "zone_start", PETSC_REAL, &R->zone[0]));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "zone_end", PETSC_REAL, &R->zone[1]));
  if (spec->hertz) {
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "E_star", PETSC_REAL, &spec->Estar));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "R_star", PETSC_REAL, &spec->Rstar));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "hertz_a", PETSC_REAL, &R->hertzA));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "hertz_pmax", PETSC_REAL, &R->hertzPmax));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "pressure_l2_error", PETSC_REAL, &R->l2err));
  }
  if (R->friction) { /* the JSON's friction figures, as rank 0 has them, for plot_hertz.py's Mindlin curve */
    const char *names[5] = {"friction", "stick_half_width", "normal_load", "tangential_load", "mindlin_c"};
    PetscReal   val[5]   = {spec->friction, R->stickHalfWidth, R->normalLoad, R->tangentialLoad, R->mindlinC};
    PetscCallMPI(MPI_Bcast(val, 5, MPIU_REAL, 0, comm));
    for (PetscInt k = 0; k < (spec->hertz && !spec->axisym ? 5 : 4); ++k) ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, names[k], PETSC_REAL, &val[k]));
  }
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscFunctionReturn(0);
}

/* Rank 0. A surface as a line mesh on its current positions (x), with the
   pressure, the gap (weighted, for nodes) and the arc position s at its
   points; the grid is named <pair>:<body>:<group>. In a scene with friction
   (friction) also the shear, slip and stick: a frictional pair's slave
   surface's node_shear, node_slip and node_stick, its master's node_shear
   (transferred) and NaN for the other two, NaN on any other surface. */
PetscErrorCode ContactReportWriteXDMF(const ContactReport *R, const ContactPairSpec *spec, Body bodies[], FILE *fp, const char h5[], PetscBool friction)
{
  const char *pre = R->nodal ? "node_" : "";

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) {
    const ContactSide *S = &R->side[s];
    const char        *body = BodyGetName(bodies[spec->body[s]]), *grp = spec->group[s];
    PetscInt           nc, nper;
    char               g[4 * CONTACT_NAME_LEN], path[PETSC_MAX_PATH_LEN];

    ContactSideLineCells(S, R->nodal, &nc, &nper);
    if (!nc) continue;
    PetscCall(PetscSNPrintf(g, sizeof(g), "%s:/contact/%s/%s_%s/%s", h5, spec->name, body, grp, pre));
    fprintf(fp, "   <Grid Name=\"%s:%s:%s\" GridType=\"Uniform\">\n", spec->name, body, grp);
    if (nper == 3) fprintf(fp, "    <Topology TopologyType=\"Edge_3\" NumberOfElements=\"%d\">\n", (int)nc);
    else fprintf(fp, "    <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"%d\">\n", (int)nc);
    fprintf(fp, "     <DataItem Dimensions=\"%d %d\" NumberType=\"Int\" Precision=\"%d\" Format=\"HDF\">%scells</DataItem>\n    </Topology>\n", (int)nc, (int)nper, (int)sizeof(PetscInt), g);
    fprintf(fp, "    <Geometry GeometryType=\"XY\">\n     <DataItem Dimensions=\"%d 2\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%sx</DataItem>\n    </Geometry>\n", (int)S->n, g);
    for (PetscInt k = 0; k < XDMF_SURFACE_SCALARS; ++k) {
      PetscCall(PetscSNPrintf(path, sizeof(path), "%s%s", g, XdmfSurfaceScalars[k]));
      XdmfWriteAttribute(fp, XdmfSurfaceScalars[k], (int)S->n, 1, path);
    }
    for (PetscInt k = 0; k < XDMF_FRICTION_SCALARS && friction; ++k) {
      if (R->friction && (S->slave || k == 0)) PetscCall(PetscSNPrintf(path, sizeof(path), "%s%s", g, XdmfFrictionScalars[k])); /* the master has the shear alone, transferred */
      else PetscCall(PetscSNPrintf(path, sizeof(path), "%s:/contact/%s/%s_%s/xdmf_nan", h5, spec->name, body, grp));
      XdmfWriteAttribute(fp, XdmfFrictionScalars[k], (int)S->n, 1, path);
    }
    /* the bodies' fields (xdmf.h): no displacement to apply (the grid is at the current positions), no stress */
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s:/contact/%s/%s_%s/xdmf_zero_xyz", h5, spec->name, body, grp));
    XdmfWriteAttribute(fp, "displacement", (int)S->n, 3, path);
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s:/contact/%s/%s_%s/xdmf_nan", h5, spec->name, body, grp));
    for (PetscInt k = 0; k < XDMF_BODY_SCALARS; ++k) XdmfWriteAttribute(fp, XdmfBodyScalarNames(spec->axisym)[k], (int)S->n, 1, path);
    fprintf(fp, "   </Grid>\n");
  }
  PetscFunctionReturn(0);
}
