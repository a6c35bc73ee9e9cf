/* -accuracy TOL: a sequence of solves, each on meshes refined around the
   contact zones of the last and where its stress is least accurate, until
   the estimated error of the answer (pressure profiles, contact forces,
   force-controlled displacements) is below TOL.

   Step 0 solves the scene's own meshes. After step k, the contact zone of
   each body is the set of its nodes on which a contact term exerts a force
   (the terms' gradient at the solution: any formulation, both surfaces of a
   pair), and each cell K has the Zienkiewicz-Zhu indicator eta_K (the L2
   norm of the recovered nodal stress minus the cell's, fields.c); the cells
   with the largest eta_K that make up the fraction -accuracy_bulk (0.5) of
   sum eta_K^2 are marked (Doerfler's marking, over every body). Step k + 1's
   meshes come from Gmsh with a size field (MeshGenerate's -bgm) defined on
   the cells of step k's mesh: at a vertex at distance d from the zone,

     h_new = min(h_K, h_z / 2 + g max(0, d - 2 h_z)),   h_K halved if K is marked,

   h_K the cell's size (mean edge length), h_z the mean size of the cells
   that touch the zone, g = -accuracy_grading. So the zone and two of its
   cells around it are halved, the size grows linearly away from them, the
   marked cells (the stress singularities at clamped and pushed corners, say,
   which set the contact force) are halved, and nothing is coarsened.

   Error estimate. The pressure has square-root edges, so its L2 error e_k
   is of first order in the zone's mesh size h (SPEC: even the best P2 fit
   is): halving h halves it, e_{k-1} = 2 e_k. The two profiles' relative
   distance D_k = ||p_k - p_{k-1}|| / ||p_k|| lies between e_{k-1} - e_k = e_k
   (errors of one shape) and sqrt(e_{k-1}^2 + e_k^2) = 2.2 e_k (errors
   unrelated: the zone's edges fall elsewhere among the nodes of each mesh);
   measured on three scenes (bench/accuracy), D_k / e_k is 1.25 to 2 from the
   second refinement on, so the estimate is D_k / 2. The distance
   interpolates p_{k-1} linearly in arc length at step k's samples, weighted
   by their weights (profile_metrics.l2_distance). The force converges
   monotonically: its error is estimated by its relative change, D_k itself.

   Force control (forcecontrol.c). A component of a pair's force is given,
   not computed, where the pair is the only one on a body whose every
   Dirichlet condition holding that component is force-controlled in it
   (AccuracyForceGiven): the body's equilibrium sets it. On the reference
   scene pushed by -block_bc_push_control force,displacement that is x, and
   its change between steps is the solve's residual (3e-7 of P), no error.
   So the force's term covers the computed components alone (the change of
   their norm, relative to P: the block's y there, at most 6e-6), and none
   where every component is given ("force given": the sphere by force). What
   converges with the mesh instead is each controlled displacement U
   (anchors aside: theirs is a vertex's, chosen anew on each mesh). U, an
   integral of the whole field, converges monotonically but not by halving
   (a step halves the zone and the marked cells, not every cell): with
   e_{k-1} = r e_k its relative change D_k = |U_k - U_{k-1}| / |U_k| is
   (r - 1) e_k. Measured on the reference scene by F = -55 (U = -0.1505),
   against U's limit extrapolated from uniform meshes h = 0.025, 0.0125 and
   0.00884 (73,972 to 585,260 dofs, order 0.94 fitted), r = 1.59 to 1.87
   from step 2 to step 5 (18,818 to 126,438 dofs): D_k is 0.59 to 0.87 e_k,
   and with r >= 1.5, e_k <= 2 D_k. The estimate is 2 D_k: measured 1.18 to
   1.73 times the true error there. On the sphere by F = -0.76 (k_p fixed at
   1e8), against a graded mesh of 844,004 dofs (contact zone h = 0.000625,
   elsewhere an eighth of the scene's sizes), U's error falls faster
   (2.4e-5 at step 1, 1.0e-6 at step 2), and the estimate is 14 and 48
   times the true error; at steps 3 and 4 the error measured so is 0.76 and
   1.46 times the estimate (8.3e-7, 6.6e-7), both below what the references
   resolve (the same mesh with the zone at h = 0.00125 is 9.4e-6 from it).
   scripts/accuracy_force_study.py measures all of this
   (bench/accuracy/force_control.json).

   The estimate of step k is the largest of the three over every pair,
   one-sided surface and control. Step 0 is the scene's own mesh, not one of the
   sequence (its zone may be graded, or much coarser than the rest), so the
   estimate of step 1 is printed but the loop stops from step 2 on. */
#include <math.h>
#include <unistd.h>
#include "accuracy.h"
#include "options.h"
#include "progress.h"
#include "outputset.h"
#include "gather.h"
#include "transfer.h"

struct _n_Accuracy {
  MPI_Comm  comm;
  PetscReal tol, grading, maxDofs, bulk;
  PetscInt  maxSteps;
  PetscBool set, warm;
};

/* One step's profiles and forces (rank 0), which of the forces' components
   are given (AccuracyForceGiven; forceGiven: all of them), and the
   displacements of the force controls (anchors aside). */
typedef struct {
  PetscInt   nterms, n[CONTACT_MAX_TERMS][2];
  PetscReal *s[CONTACT_MAX_TERMS][2], *p[CONTACT_MAX_TERMS][2], *w[CONTACT_MAX_TERMS][2], force[CONTACT_MAX_TERMS][2];
  PetscBool  given[CONTACT_MAX_TERMS][2], forceGiven;
  PetscInt   ncontrols;
  PetscReal  U[CONTACT_MAX_CONTROLS];
} AccuracyProfiles;

PetscErrorCode AccuracyCreate(MPI_Comm comm, Accuracy *acc)
{
  PetscFunctionBeginUser;
  PetscCall(PetscNew(acc));
  (*acc)->comm     = comm;
  (*acc)->grading  = 0.3;
  (*acc)->bulk     = 0.5;
  (*acc)->warm     = PETSC_TRUE;
  (*acc)->maxSteps = 8;
  PetscFunctionReturn(0);
}

PetscErrorCode AccuracyDestroy(Accuracy *acc)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(*acc));
  PetscFunctionReturn(0);
}

PetscBool AccuracyIsSet(Accuracy acc)
{
  return acc->set;
}

PetscErrorCode AccuracySetFromOptions(Accuracy acc)
{
  PetscBool setMax;

  PetscFunctionBeginUser;
  PetscOptionsBegin(acc->comm, NULL, "Accuracy options", NULL);
  PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-accuracy", "Target relative error of the contact pressure profile (L2), the contact force and a force-controlled group's displacement: refine around the contact zones until the estimate is below it", "unset: one solve on the scene's meshes", PETSC_FALSE, &acc->tol, &acc->set));
  PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-accuracy_max_dofs", "-accuracy: the most dofs a step may have; a target that needs more stops there", "-max_dofs, else the machine's memory", PETSC_FALSE, &acc->maxDofs, &setMax));
  PetscCall(PetscOptionsInt("-accuracy_max_steps", "-accuracy: the most solves (refinement steps + 1)", NULL, acc->maxSteps, &acc->maxSteps, NULL));
  PetscCall(PetscOptionsReal("-accuracy_bulk", "-accuracy: the cells whose stress indicators make up this fraction of the total (largest first) are halved too", NULL, acc->bulk, &acc->bulk, NULL));
  PetscCall(PetscOptionsBool("-accuracy_warm_start", "-accuracy: start each solve from the last step's answer interpolated onto the new meshes (else from rest)", NULL, acc->warm, &acc->warm, NULL));
  PetscCall(PetscOptionsReal("-accuracy_grading", "-accuracy: growth of the mesh size per unit distance from the contact zones", NULL, acc->grading, &acc->grading, NULL));
  PetscOptionsEnd();
  PetscCheck(!acc->set || (acc->tol > 0 && acc->tol < 1), acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy: must be a relative error in (0, 1), got %g", (double)acc->tol);
  PetscCheck(!setMax || (acc->maxDofs >= 1 && !PetscIsInfOrNanReal(acc->maxDofs)), acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy_max_dofs: must be a finite number >= 1, got %g", (double)acc->maxDofs);
  if (!setMax) acc->maxDofs = 0.0;
  PetscCheck(acc->maxSteps >= 3, acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy_max_steps: must be >= 3 (the scene's meshes and two refinements, whose difference is the estimate), got %" PetscInt_FMT, acc->maxSteps);
  PetscCheck(acc->bulk >= 0 && acc->bulk <= 1, acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy_bulk: must be in [0, 1], got %g", (double)acc->bulk);
  PetscCheck(acc->grading > 0 && acc->grading <= 10, acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy_grading: must be in (0, 10], got %g", (double)acc->grading);
  PetscFunctionReturn(0);
}

/* Whether component d of term t's force is given rather than computed: t is
   the only term on one of its bodies, and every Dirichlet condition of that
   body holding d is force-controlled in d (anchors included, force 0), so
   that body's equilibrium in d sets the contact force from given forces and
   loads; or d is r-z's radial component, 0 by symmetry (contactreport.c). */
static PetscBool AccuracyForceGiven(Problem p, PetscInt t, PetscInt d)
{
  if (p->cfg->scene.axisymmetric && d == 0) return PETSC_TRUE;
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    const Body b      = p->bodies[i];
    PetscInt   nterms = 0, computed = 0;

    if (!p->terms[t]->couples[i]) continue;
    for (PetscInt u = 0; u < p->nterms; ++u) nterms += p->terms[u]->couples[i] ? 1 : 0;
    for (PetscInt k = 0; k < BodyGetNumConditions(b); ++k) {
      const BodyBC *bc = BodyGetCondition(b, k);
      for (PetscInt c = 0; c < bc->ncomp; ++c) computed += (bc->comps[c] == d && !bc->control[c]) ? 1 : 0;
    }
    if (nterms == 1 && !computed) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

static PetscErrorCode AccuracyProfilesGet(Problem p, AccuracyProfiles *P)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(P, sizeof(*P)));
  P->nterms     = p->nterms;
  P->forceGiven = PETSC_TRUE;
  for (PetscInt t = 0; t < p->nterms; ++t) {
    for (PetscInt s = 0; s < 2; ++s) PetscCall(EnergyTermGetProfile(p->terms[t], s, &P->n[t][s], &P->s[t][s], &P->p[t][s], &P->w[t][s], P->force[t]));
    for (PetscInt d = 0; d < 2; ++d) {
      P->given[t][d] = AccuracyForceGiven(p, t, d);
      if (!P->given[t][d]) P->forceGiven = PETSC_FALSE;
    }
  }
  for (PetscInt k = 0; k < p->fc.n; ++k)
    if (!BodyGetCondition(p->bodies[p->fc.c[k].body], p->fc.c[k].bc)->anchor) P->U[P->ncontrols++] = p->fc.c[k].U;
  PetscFunctionReturn(0);
}

static PetscErrorCode AccuracyProfilesDestroy(AccuracyProfiles *P)
{
  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < P->nterms; ++t)
    for (PetscInt s = 0; s < 2; ++s) {
      PetscCall(PetscFree(P->s[t][s]));
      PetscCall(PetscFree(P->p[t][s]));
      PetscCall(PetscFree(P->w[t][s]));
    }
  P->nterms = 0;
  PetscFunctionReturn(0);
}

/* Relative L2 distance of a coarse profile from a fine one: the coarse one
   interpolated linearly in s at the fine samples (0 outside its range),
   weighted by the fine weights. */
static PetscReal ProfileDistance(PetscInt nc, const PetscReal sc[], const PetscReal pc[], PetscInt nf, const PetscReal sf[], const PetscReal pf[], const PetscReal wf[])
{
  PetscReal num = 0.0, den = 0.0;
  PetscInt  j   = 0;

  for (PetscInt i = 0; i < nf; ++i) {
    PetscReal v = 0.0;
    while (j + 1 < nc && sc[j + 1] < sf[i]) ++j;
    if (nc > 1 && sf[i] >= sc[0] && sf[i] <= sc[nc - 1]) {
      const PetscInt  k = PetscMin(j, nc - 2);
      const PetscReal L = sc[k + 1] - sc[k];
      v = L > 0 ? pc[k] + (pc[k + 1] - pc[k]) * (sf[i] - sc[k]) / L : pc[k];
    }
    num += wf[i] * (v - pf[i]) * (v - pf[i]);
    den += wf[i] * pf[i] * pf[i];
  }
  return den > 0 ? PetscSqrtReal(num / den) : (num > 0 ? PETSC_INFINITY : 0.0);
}

/* The norm of the computed (not given) components of a term's force. */
static PetscReal ComputedForce(const PetscReal f[2], const PetscBool given[2])
{
  return PetscSqrtReal((given[0] ? 0.0 : PetscSqr(f[0])) + (given[1] ? 0.0 : PetscSqr(f[1])));
}

/* Rank 0: the estimates of step cur from step prev (above); est[ACCURACY_FORCE]
   Inf where every force is given. */
static void AccuracyEstimate(const AccuracyProfiles *prev, const AccuracyProfiles *cur, PetscReal est[])
{
  PetscReal profile = 0.0, force = 0.0, disp = 0.0;

  for (PetscInt t = 0; t < cur->nterms; ++t) {
    const PetscReal P = PetscSqrtReal(PetscSqr(cur->force[t][0]) + PetscSqr(cur->force[t][1]));
    for (PetscInt s = 0; s < 2; ++s)
      if (cur->n[t][s]) profile = PetscMax(profile, 0.5 * ProfileDistance(prev->n[t][s], prev->s[t][s], prev->p[t][s], cur->n[t][s], cur->s[t][s], cur->p[t][s], cur->w[t][s]));
    if (P != 0) force = PetscMax(force, PetscAbsReal(ComputedForce(cur->force[t], cur->given[t]) - ComputedForce(prev->force[t], cur->given[t])) / P);
  }
  for (PetscInt k = 0; k < cur->ncontrols && k < prev->ncontrols; ++k)
    if (cur->U[k] != 0) disp = PetscMax(disp, 2.0 * PetscAbsReal(cur->U[k] - prev->U[k]) / PetscAbsReal(cur->U[k]));
  est[ACCURACY_PROFILE]      = profile;
  est[ACCURACY_FORCE]        = cur->forceGiven ? (PetscReal)INFINITY : force;
  est[ACCURACY_DISPLACEMENT] = disp;
  est[ACCURACY_ESTIMATE]     = PetscMax(PetscMax(profile, disp), cur->forceGiven ? 0.0 : force);
}

/* Every rank: the reference coordinates of the nodes of body b on which a
   contact term exerts a force at the state in the bodies' local vectors
   (the terms' gradient, evaluated by the caller into BodyGetLocalGradient(b)). */
static PetscErrorCode AccuracyZone(Body b, PetscInt *nz, PetscReal **z)
{
  const MPI_Comm     comm = BodyGetComm(b);
  PetscSection       sec;
  const PetscScalar *g;
  const PetscBool   *owned;
  const PetscReal   *xpoint;
  PetscReal          gmax = 0.0, *loc;
  PetscInt           m = 0, pStart, pEnd;

  PetscFunctionBeginUser;
  BodyGetNodePoints(b, &pStart, &pEnd, &owned, &xpoint);
  PetscCall(DMGetLocalSection(BodyGetDM(b), &sec));
  PetscCall(VecGetArrayRead(BodyGetLocalGradient(b), &g));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt dof, off;
    PetscCall(PetscSectionGetDof(sec, p, &dof));
    PetscCall(PetscSectionGetOffset(sec, p, &off));
    if (dof == 2) gmax = PetscMax(gmax, PetscSqrtReal(PetscSqr(PetscRealPart(g[off])) + PetscSqr(PetscRealPart(g[off + 1]))));
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &gmax, 1, MPIU_REAL, MPIU_MAX, comm));
  PetscCall(PetscMalloc1(2 * (pEnd - pStart) + 1, &loc));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt dof, off;
    PetscCall(PetscSectionGetDof(sec, p, &dof));
    PetscCall(PetscSectionGetOffset(sec, p, &off));
    if (dof != 2 || !owned[p - pStart]) continue;
    if (PetscSqrtReal(PetscSqr(PetscRealPart(g[off])) + PetscSqr(PetscRealPart(g[off + 1]))) <= 1e-8 * gmax || gmax == 0) continue;
    loc[2 * m]     = xpoint[2 * (p - pStart)];
    loc[2 * m + 1] = xpoint[2 * (p - pStart) + 1];
    ++m;
  }
  PetscCall(VecRestoreArrayRead(BodyGetLocalGradient(b), &g));
  PetscCall(ContactGatherReals(comm, PETSC_TRUE, 2 * m, loc, nz, z));
  *nz /= 2;
  PetscCall(PetscFree(loc));
  PetscFunctionReturn(0);
}

/* A cell's record in the size field: vertex count, then x, y, size per vertex. */
#define FIELD_REC 13

static int CompareRecords(const void *a, const void *b)
{
  const PetscReal *x = (const PetscReal *)a, *y = (const PetscReal *)b;
  PetscReal        cx = 0, cy = 0, dx = 0, dy = 0;

  for (PetscInt v = 0; v < (PetscInt)x[0]; ++v) {
    cx += x[1 + 3 * v] / x[0];
    cy += x[2 + 3 * v] / x[0];
  }
  for (PetscInt v = 0; v < (PetscInt)y[0]; ++v) {
    dx += y[1 + 3 * v] / y[0];
    dy += y[2 + 3 * v] / y[0];
  }
  return cx < dx ? -1 : cx > dx ? 1 : cy < dy ? -1 : cy > dy ? 1 : 0;
}

/* Collective: writes body b's size field for the next step (above) to path
   (rank 0), a Gmsh view of its cells in a canonical order (so that the mesh
   does not depend on the number of ranks). */
static PetscErrorCode AccuracyWriteField(Body b, PetscInt nz, const PetscReal z[], const PetscReal eta[], PetscReal eta2min, PetscReal grading, const char path[])
{
  const MPI_Comm   comm = BodyGetComm(b);
  const PetscInt   ncells = BodyGetNumLocalCells(b), nb = BodyGetNodesPerCell(b);
  const PetscReal *xnode  = BodyGetCellNodeCoordinates(b);
  PetscReal        ref[2 * 64], *rec, hz[2] = {0, 0}, *all = NULL;
  PetscInt         corner[4], nv = 0, ntot;
  PetscMPIInt      rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(BodyGetCellCorners(b, ref, corner, &nv));
  PetscCall(PetscMalloc1(FIELD_REC * ncells + 1, &rec));
  for (PetscInt c = 0; c < ncells; ++c) { /* first each cell's size, its vertices and their distances from the zone; h_z */
    const PetscReal *x = &xnode[2 * nb * c];
    PetscReal       *r = &rec[FIELD_REC * c], h = 0.0, dmin = PETSC_MAX_REAL;
    for (PetscInt v = 0; v < nv; ++v) {
      const PetscReal *p = &x[2 * corner[v]], *q = &x[2 * corner[(v + 1) % nv]];
      PetscReal        d = PETSC_MAX_REAL;
      h += PetscSqrtReal(PetscSqr(p[0] - q[0]) + PetscSqr(p[1] - q[1])) / nv;
      for (PetscInt j = 0; j < nz; ++j) d = PetscMin(d, PetscSqr(p[0] - z[2 * j]) + PetscSqr(p[1] - z[2 * j + 1]));
      r[1 + 3 * v] = p[0];
      r[2 + 3 * v] = p[1];
      r[3 + 3 * v] = PetscSqrtReal(d);
      dmin         = PetscMin(dmin, r[3 + 3 * v]);
    }
    r[0] = h;
    if (dmin <= 0.5 * h) {
      hz[0] += h;
      hz[1] += 1;
    }
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, hz, 2, MPIU_REAL, MPIU_SUM, comm));
  for (PetscInt c = 0; c < ncells; ++c) { /* then the sizes at the vertices */
    PetscReal      *r = &rec[FIELD_REC * c];
    const PetscReal h = PetscSqr(eta[c]) >= eta2min ? 0.5 * r[0] : r[0]; /* a marked cell: halved */
    r[0]              = (PetscReal)nv;
    for (PetscInt v = 0; v < nv; ++v) {
      if (hz[1] > 0) {
        const PetscReal hzone = hz[0] / hz[1];
        r[3 + 3 * v]          = PetscMin(h, 0.5 * hzone + grading * PetscMax(0.0, r[3 + 3 * v] - 2.0 * hzone));
      } else r[3 + 3 * v] = h;
    }
  }
  PetscCall(ContactGatherReals(comm, PETSC_FALSE, FIELD_REC * ncells, rec, &ntot, &all));
  if (!rank) {
    const PetscInt n  = ntot / FIELD_REC;
    FILE          *fp = fopen(path, "w");
    PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write the size field %s", path);
    qsort(all, (size_t)n, FIELD_REC * sizeof(PetscReal), CompareRecords);
    fprintf(fp, "View \"size\" {\n");
    for (PetscInt c = 0; c < n; ++c) {
      const PetscReal *r = &all[FIELD_REC * c];
      const PetscInt   k = (PetscInt)r[0];
      fprintf(fp, "%s(", k == 3 ? "ST" : "SQ");
      for (PetscInt v = 0; v < k; ++v) fprintf(fp, "%s%.10g,%.10g,0", v ? "," : "", (double)r[1 + 3 * v], (double)r[2 + 3 * v]);
      fprintf(fp, "){");
      for (PetscInt v = 0; v < k; ++v) fprintf(fp, "%s%.6g", v ? "," : "", (double)r[3 + 3 * v]);
      fprintf(fp, "};\n");
    }
    fprintf(fp, "};\n");
    PetscCheck(!ferror(fp) && !fclose(fp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "error writing the size field %s", path);
    PetscCall(PetscFree(all));
  }
  PetscCall(PetscFree(rec));
  PetscFunctionReturn(0);
}

/* Collective: the size fields of every body for the step after the one
   solved in p, written to paths[] (see above). */
static PetscErrorCode AccuracyRefine(Accuracy acc, Problem p, PetscInt step, char paths[][PETSC_MAX_PATH_LEN])
{
  PetscReal  *eta[CONTACT_MAX_BODIES], *e2, eta2min = PETSC_MAX_REAL, *all = NULL;
  PetscInt    n = 0, ntot;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  /* the stress indicators; the threshold of the largest that make up the fraction -accuracy_bulk of the total */
  PetscCall(ProblemScatterToBodies(p, p->X));
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    PetscCall(PetscMalloc1(BodyGetNumLocalCells(p->bodies[i]) + 1, &eta[i]));
    PetscCall(BodyComputeStressIndicator(p->bodies[i], BodyGetLocalSolution(p->bodies[i]), eta[i]));
    n += BodyGetNumLocalCells(p->bodies[i]);
  }
  PetscCall(PetscMalloc1(n + 1, &e2));
  n = 0;
  for (PetscInt i = 0; i < p->nbodies; ++i)
    for (PetscInt c = 0; c < BodyGetNumLocalCells(p->bodies[i]); ++c) e2[n++] = PetscSqr(eta[i][c]);
  PetscCall(ContactGatherReals(p->comm, PETSC_FALSE, n, e2, &ntot, &all));
  if (!rank) {
    PetscReal total = 0.0, sum = 0.0;
    PetscCall(PetscSortReal(ntot, all));
    for (PetscInt k = 0; k < ntot; ++k) total += all[k];
    for (PetscInt k = ntot - 1; k >= 0 && acc->bulk > 0 && sum < acc->bulk * total; --k) {
      sum += all[k];
      eta2min = all[k];
    }
    PetscCall(PetscFree(all));
  }
  PetscCallMPI(MPI_Bcast(&eta2min, 1, MPIU_REAL, 0, p->comm));
  PetscCall(PetscFree(e2));
  /* the contact zones: where the terms' gradient is not zero */
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(VecZeroEntries(BodyGetLocalGradient(p->bodies[i])));
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscReal e;
    PetscCall(EnergyTermComputeEnergyGradient(p->terms[t], p->bodies, &e));
  }
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    Body       b  = p->bodies[i];
    PetscInt   nz = 0;
    PetscReal *z  = NULL;
    PetscCall(AccuracyZone(b, &nz, &z));
    PetscCall(PetscSNPrintf(paths[i], PETSC_MAX_PATH_LEN, "%s/%s-field%d-step%d.pos", p->cfg->scene.meshDir, BodyGetName(b), (int)getpid(), (int)step));
    PetscCall(AccuracyWriteField(b, nz, z, eta[i], eta2min, acc->grading, paths[i]));
    PetscCall(PetscFree(z));
    PetscCall(PetscFree(eta[i]));
  }
  PetscFunctionReturn(0);
}

/* Collective: the last step's displacement at the new meshes' nodes (X0, the
   first iterate of the next solve), each body's carried onto its new mesh
   (transfer.c). */
static PetscErrorCode AccuracyInterpolate(Problem prev, Problem cur, Vec X0)
{
  PetscFunctionBeginUser;
  PetscCall(ProblemScatterToBodies(prev, prev->X));
  PetscCall(VecZeroEntries(X0));
  for (PetscInt i = 0; i < cur->nbodies; ++i) PetscCall(BodyTransferDisplacement(prev->bodies[i], BodyGetLocalSolution(prev->bodies[i]), cur->bodies[i], X0));
  PetscCall(VecAssemblyBegin(X0));
  PetscCall(VecAssemblyEnd(X0));
  PetscFunctionReturn(0);
}

/* Step 0's checks: the scene has a contact pair, none in gpts, and no rigid body. */
static PetscErrorCode AccuracyCheckScene(Accuracy acc, Problem p)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->nbodies; ++i) /* each step's meshes start from rest, or from the last step's displacement as one increment */
    PetscCheck(!BodyHasState(p->bodies[i]), acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy: body %s's material (-%s_material %s) has history, and its transfer to the refined meshes is not written yet", BodyGetName(p->bodies[i]), BodyGetName(p->bodies[i]), BodyGetMaterial(p->bodies[i])->name);
  PetscCheck(p->nterms > 0, acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy: the scene has no contact pair, whose pressure it refines for");
  PetscCheck(p->cfg->load.stages == 1, acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy: with -load_stages %" PetscInt_FMT " it would refine for the last stage's end alone; -accuracy with a load history is not supported yet", p->cfg->load.stages);
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCheck(BodyHasCells(p->bodies[i]), acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy: body %s is rigid (-%s_rigid), and -accuracy with a rigid body is not supported yet", BodyGetName(p->bodies[i]), BodyGetName(p->bodies[i]));
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscBool gpts;
    PetscCall(PetscStrcmp(p->terms[t]->type, "gpts", &gpts));
    /* gpts' pressure does not converge under refinement (it oscillates at
       every h: docs/formulations.md, gpts), so the distance between two steps'
       profiles says nothing of the error */
    PetscCheck(!gpts, acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy: pair %s uses the gpts formulation, whose pressure does not converge under refinement, so no error estimate of it can be honest; use -contact_formulation mortar (the default)", p->terms[t]->name);
  }
  PetscFunctionReturn(0);
}

/* Step 0's check once its meshes are read (they give the dimension): no 3D
   body, refused before the solve. The size field written for Gmsh
   (AccuracyWriteField) and the estimate's profiles along an arc
   (AccuracyProfilesGet) are a plane section's. */
static PetscErrorCode AccuracyCheckDimension(Accuracy acc, Problem p)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->nbodies; ++i)
    PetscCheck(BodyGetDimension(p->bodies[i]) != 3, acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy: body %s is 3D, and -accuracy refines 2D and axisymmetric scenes only (its size field and error estimate are a plane section's); refine a 3D scene with -mesh_size or -%s_mesh_size", BodyGetName(p->bodies[i]), BodyGetName(p->bodies[i]));
  PetscFunctionReturn(0);
}

/* One step's problem meshed (with the last step's size fields, then removed)
   and set up, its first iterate interpolated from the last step's answer. */
static PetscErrorCode AccuracyStepSetUp(Accuracy acc, PetscInt k, Problem prev, Problem cur, char fields[][PETSC_MAX_PATH_LEN], RunRecord *rec)
{
  PetscMPIInt rank;
  PetscInt    n, nprev;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(acc->comm, &rank));
  if (k == 0) PetscCall(AccuracyCheckScene(acc, cur));
  PetscCall(ContactProgressPhase("meshing", "accuracy step %" PetscInt_FMT ": meshing", k));
  PetscCall(RunMesh(cur, fields));
  if (!rank)
    for (PetscInt i = 0; i < CONTACT_MAX_BODIES; ++i)
      if (fields[i][0]) (void)unlink(fields[i]);
  if (acc->maxDofs <= 0) acc->maxDofs = cur->cfg->scene.maxDofs;
  PetscCall(ContactProgressPhase("set-up", "accuracy step %" PetscInt_FMT ": set-up", k));
  PetscCall(RunSetUp(cur, rec));
  if (k == 0) PetscCall(AccuracyCheckDimension(acc, cur));
  if (!prev) PetscFunctionReturn(0);
  PetscCall(VecGetSize(cur->Xb, &n));
  PetscCall(VecGetSize(prev->Xb, &nprev));
  PetscCheck(n > nprev, acc->comm, PETSC_ERR_USER_INPUT, "option -accuracy: the refined meshes have %" PetscInt_FMT " dofs, no more than the last step's %" PetscInt_FMT ": a .geo ignores the size field (a transfinite mesh without the adapt parameter? see docs/scenes.md, Geometry files)", n, nprev);
  if (acc->warm) { /* from the last step's answer */
    Vec X0;
    PetscCall(VecDuplicate(cur->Xb, &X0));
    PetscCall(AccuracyInterpolate(prev, cur, X0));
    PetscCall(ProblemSetInitialGuess(cur, X0));
    PetscCall(VecDestroy(&X0));
  }
  PetscFunctionReturn(0);
}

/* The step's estimate against the last step's profiles, printed: the
   force's part "given" where every force is, the displacements' part where
   there are force controls. */
static PetscErrorCode AccuracyStepEstimate(Accuracy acc, PetscInt k, const AccuracyProfiles *pp, const AccuracyProfiles *pc, AccuracyStep *st)
{
  PetscMPIInt rank;
  char        force[64], disp[64] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(acc->comm, &rank));
  for (PetscInt e = 0; e < ACCURACY_N; ++e) st->est[e] = (PetscReal)INFINITY; /* none yet: null in the JSON */
  st->forceGiven = pc->forceGiven;
  st->ncontrols  = pc->ncontrols;
  for (PetscInt c = 0; c < pc->ncontrols; ++c) st->U[c] = pc->U[c];
  if (!rank && k > 0) AccuracyEstimate(pp, pc, st->est);
  PetscCallMPI(MPI_Bcast(st->est, ACCURACY_N, MPIU_REAL, 0, acc->comm));
  if (k == 0) {
    PetscCall(PetscPrintf(acc->comm, "accuracy step %" PetscInt_FMT ": %" PetscInt_FMT " dofs, solve %.3g s (no estimate yet: it compares two steps of refinement)\n", k, st->dofs, (double)st->tsolve));
    PetscFunctionReturn(0);
  }
  if (st->forceGiven) PetscCall(PetscSNPrintf(force, sizeof(force), "force given"));
  else PetscCall(PetscSNPrintf(force, sizeof(force), "force %.3g %%", (double)(100 * st->est[ACCURACY_FORCE])));
  if (st->ncontrols) PetscCall(PetscSNPrintf(disp, sizeof(disp), ", displacement %.3g %%", (double)(100 * st->est[ACCURACY_DISPLACEMENT])));
  PetscCall(PetscPrintf(acc->comm, "accuracy step %" PetscInt_FMT ": %" PetscInt_FMT " dofs, solve %.3g s, estimated error %.3g %% (pressure profile %.3g %%, %s%s), target %.3g %%\n", k, st->dofs, (double)st->tsolve, (double)(100 * st->est[ACCURACY_ESTIMATE]), (double)(100 * st->est[ACCURACY_PROFILE]), force, disp, (double)(100 * acc->tol)));
  PetscFunctionReturn(0);
}

/* Whether the loop stops after step k (stop says why, unless the target is reached). */
static PetscBool AccuracyStepLast(Accuracy acc, PetscInt k, const AccuracyStep steps[], PetscReal problemMaxDofs, PetscBool *reached, char stop[], size_t len)
{
  *reached = (PetscBool)(k >= 2 && steps[k].est[ACCURACY_ESTIMATE] <= acc->tol);
  if (*reached) return PETSC_TRUE;
  if (k + 1 == acc->maxSteps) {
    (void)PetscSNPrintf(stop, len, "-accuracy_max_steps %" PetscInt_FMT " reached", acc->maxSteps);
    return PETSC_TRUE;
  }
  { /* the next step's size: this step's growth over the last (3 at first) */
    const PetscReal growth = k > 0 ? (PetscReal)steps[k].dofs / steps[k - 1].dofs : 3.0, next = growth * steps[k].dofs;
    if (acc->maxDofs > 0 && next > acc->maxDofs) {
      (void)PetscSNPrintf(stop, len, "the next step would have about %.3g dofs, more than %.3g (%s)", (double)next, (double)acc->maxDofs, acc->maxDofs == problemMaxDofs ? "-max_dofs or the machine's memory; -accuracy_max_dofs sets another" : "-accuracy_max_dofs");
      return PETSC_TRUE;
    }
  }
  return PETSC_FALSE;
}

/* The pipeline of run.h in a loop: step 0 is the problem given (created
   from the scene's options, its output set open), each later step a new
   problem on refined meshes. The last converged step is reported and
   written. */
PetscErrorCode AccuracySolve(Accuracy acc, Problem *first, RunRecord *rec)
{
  Problem          prev = NULL, cur = *first;
  AccuracyProfiles pp, pc;
  AccuracyStep    *steps;
  char             (*fields)[PETSC_MAX_PATH_LEN];
  char             stop[512] = "";
  PetscBool        reached = PETSC_FALSE, converged = PETSC_FALSE;
  PetscInt         k, last = -1;

  PetscFunctionBeginUser;
  *first = NULL;
  PetscCall(PetscMemzero(&pp, sizeof(pp)));
  PetscCall(PetscMemzero(&pc, sizeof(pc)));
  PetscCall(PetscCalloc1(acc->maxSteps, &steps));
  PetscCall(PetscCalloc1(CONTACT_MAX_BODIES, &fields));
  for (k = 0; k < acc->maxSteps; ++k) {
    AccuracyStep *st = &steps[k];
    PetscReal     t0 = rec->time[RUN_TIME_SOLVE];

    if (!cur) {
      PetscCall(PetscTime(&rec->mark));
      PetscCall(RunCreateProblem(acc->comm, &cur));
    }
    PetscCall(AccuracyStepSetUp(acc, k, prev, cur, fields, rec));
    PetscCall(VecGetSize(cur->Xb, &st->dofs));
    PetscCall(ContactProgressPhase("the solve", "accuracy step %" PetscInt_FMT ": solve, %" PetscInt_FMT " dofs", k, st->dofs));
    PetscCall(RunSolve(cur, rec, &converged));
    st->tsolve = rec->time[RUN_TIME_SOLVE] - t0;
    if (!converged) {
      PetscCall(PetscSNPrintf(stop, sizeof(stop), "the solve of step %" PetscInt_FMT " (%" PetscInt_FMT " dofs) did not converge (%s)", k, st->dofs, TaoConvergedReasons[cur->res.reason]));
      st->dofs = 0;
      break;
    }
    PetscCall(ContactProgressPhase("post-processing", "accuracy step %" PetscInt_FMT ": post-processing", k));
    PetscCall(RunPostProcess(cur, converged));
    PetscCall(AccuracyProfilesGet(cur, &pc));
    st->iterations = cur->res.iterations;
    PetscCall(AccuracyStepEstimate(acc, k, &pp, &pc, st));
    PetscCall(RunDestroyProblem(&prev));
    PetscCall(AccuracyProfilesDestroy(&pp));
    pp   = pc;
    prev = cur;
    cur  = NULL;
    last = k;
    if (AccuracyStepLast(acc, k, steps, prev->cfg->scene.maxDofs, &reached, stop, sizeof(stop))) break;
    PetscCall(AccuracyRefine(acc, prev, k + 1, fields));
  }
  PetscCall(RunDestroyProblem(&cur)); /* a step that did not converge: the answer is the last one that did */
  if (prev) {
    rec->accuracyTarget = acc->tol;
    rec->errorEstimate  = steps[last].est[ACCURACY_ESTIMATE];
    rec->nsteps         = last + 1;
    rec->steps          = steps;
    rec->converged      = PETSC_TRUE;
    rec->status         = reached ? 0 : 2;
    PetscCall(ProblemView(prev));
    if (reached) PetscCall(PetscPrintf(acc->comm, "accuracy: target %.3g %% reached: estimated error %.3g %% after %" PetscInt_FMT " steps, %" PetscInt_FMT " dofs\n", (double)(100 * acc->tol), (double)(100 * steps[last].est[ACCURACY_ESTIMATE]), last + 1, steps[last].dofs));
    else PetscCall(PetscFPrintf(acc->comm, PETSC_STDERR, "contact: accuracy: target %.3g %% not reached: estimated error %.3g %% at %" PetscInt_FMT " dofs; stopped because %s; writing that answer\n", (double)(100 * acc->tol), (double)(100 * steps[last].est[ACCURACY_ESTIMATE]), steps[last].dofs, stop));
    PetscCall(RunFinish(prev, rec));
  } else {
    PetscCall(PetscFPrintf(acc->comm, PETSC_STDERR, "contact: accuracy: %s; no output written\n", stop));
    ContactOutputDiscard();
    rec->status = 2;
  }
  PetscCall(RunDestroyProblem(&prev));
  PetscCall(AccuracyProfilesDestroy(&pp));
  PetscCall(PetscFree(fields));
  PetscCall(PetscFree(steps));
  PetscFunctionReturn(0);
}
