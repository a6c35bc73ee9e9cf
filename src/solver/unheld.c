/* Bodies held by contact, in coupled force control: the anchors' directions
   the contact does not hold.

   A body held by contact is anchored (anchors.c): at most three Dirichlet
   components at two of its vertices, each force-controlled with force zero,
   so that its displacements U are unknowns of the one minimisation beside
   the other force controls' (forcecontrol.c, forceborder.c). At the minimum
   each anchor's reaction is zero and the body is held by the contact alone.
   Before the contact holds it the body floats: its anchors' stiffness
   through the scene, the Schur complement S = dR/dU of forceborder.c, is
   zero in the directions of its free motions, and forceborder.c's
   regularised step pushes the body towards its partners while a residual
   there stands (the anchors carry a load). But some motions the contact
   never holds: a roller between two flat frictionless races slides along
   them and turns without changing the energy, but for the discretisation's
   tangential force (an unsymmetric mesh's: 6.8e-7 of the load on the
   roller scene at h = 0.02). Newton steps along such a direction divide
   that force by a stiffness of about zero, the line search accepts them
   (the energy hardly changes), the contact zone moves, and the gradient
   never settles (measured on the roller pushed by 1000 with every anchor
   free: 511 iterations, DIVERGED_MAXITS at a gradient norm of 0.19).

   So at every Newton step (UnheldUpdate, from the step's S): in the
   anchors' block of S (every held body's together: a race free in y rocks
   on a roller that slides beneath it, a motion of the two that changes no
   energy), an eigenvector v whose stiffness is below kref = UNHELD_STIFF
   times the least E of the held bodies (times its size in r-z, where
   forces are over the whole circle) is a motion the contact does not hold;
   where the anchors' residual along it, |v . (R - F)|, is also within the
   allowance, UNHELD_NEUTRAL times the scene's largest force (every load's
   resultant, every force control's force, every Dirichlet group's reaction,
   anchors' included: forcecontrol.c), the direction is frozen: the step
   has no part along it (UnheldConstrain), and the gradient TAO sees has
   that part projected out (UnheldSetGradient), so that the minimisation is
   over the anchors' displacements with those motions fixed where they are,
   and its stopping test measures what it can resolve. The projection
   removes from the gradient only what every step is orthogonal to, so the
   line search's energy and slope stay consistent: a step has no part along
   the directions frozen now nor along those the gradient it starts from
   was projected by (measured: without the latter, Moré-Thuente's line
   search stopped with "dx * (stp-stx) >= 0.0" on the roller pushed by a
   pressure). A direction whose residual grows past the allowance is free
   again at the next step. The
   answer's anchor reactions along frozen directions are reported as they
   are: within the allowance, the discretisation's force on a motion the
   scene does not determine. */
#include "unheld.h"
#include <petscblaslapack.h>

#define UNHELD_STIFF   1e-4 /* held: stiffness at least this times E (E L in r-z) */
#define UNHELD_NEUTRAL 1e-3 /* an unheld direction's residual allowed, relative to the scene's largest force */

PetscErrorCode UnheldSetUp(Unheld *u, PetscInt m, const PetscBool anchor[], const PetscReal kref[])
{
  PetscFunctionBeginUser;
  PetscCheck(m <= CONTACT_MAX_CONTROLS, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "more than %d controls", CONTACT_MAX_CONTROLS);
  PetscCall(PetscMemzero(u, sizeof(*u)));
  u->m = m;
  for (PetscInt k = 0; k < m; ++k) {
    u->anchor[k] = anchor[k];
    u->kref[k]   = UNHELD_STIFF * kref[k];
  }
  PetscFunctionReturn(0);
}

PetscBool UnheldAny(const Unheld *u)
{
  for (PetscInt k = 0; k < u->m; ++k)
    if (u->anchor[k]) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* g <- g - V V^T g, V the n orthonormal columns of m entries */
static void UnheldProject(PetscInt m, PetscInt n, const PetscReal V[], PetscReal g[])
{
  for (PetscInt j = 0; j < n; ++j) {
    const PetscReal *v = &V[j * m];
    PetscReal        d = 0;
    for (PetscInt k = 0; k < m; ++k) d += v[k] * g[k];
    for (PetscInt k = 0; k < m; ++k) g[k] -= d * v[k];
  }
}

PetscErrorCode UnheldSetGradient(Unheld *u, PetscReal sceneForce, PetscReal g[])
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < u->m; ++k) u->raw[k] = g[k];
  u->allowance = UNHELD_NEUTRAL * sceneForce;
  UnheldProject(u->m, u->n, u->V, g);
  PetscFunctionReturn(0);
}

PetscErrorCode UnheldUpdate(Unheld *u, const PetscReal S[])
{
  const PetscInt m = u->m;
  PetscInt       idx[CONTACT_MAX_CONTROLS], na = 0;
  PetscScalar    A[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS], work[3 * CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS];
  PetscReal      w[CONTACT_MAX_CONTROLS], kref = PETSC_MAX_REAL;
  PetscBLASInt   bn, lwork = 3 * CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS, info;

  PetscFunctionBeginUser;
  u->nc = u->n; /* the last gradient's: its slope along the step is the energy's only if the step has no part along them */
  PetscCall(PetscArraycpy(u->Vc, u->V, u->n * m));
  u->n = 0;
  for (PetscInt k = 0; k < m; ++k) /* every held body's anchors together: a motion of two bodies may be free (a race rocking on a roller that slides) */
    if (u->anchor[k]) {
      idx[na++] = k;
      kref      = PetscMin(kref, u->kref[k]);
    }
  if (!na) PetscFunctionReturn(0);
  for (PetscInt a = 0; a < na; ++a)
    for (PetscInt b = 0; b < na; ++b) A[a * na + b] = S[idx[a] * m + idx[b]];
  PetscCall(PetscBLASIntCast(na, &bn));
  PetscCallBLAS("LAPACKsyev", LAPACKsyev_("V", "L", &bn, A, &bn, w, work, &lwork, &info));
  PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "held by contact: syev info %d", (int)info);
  for (PetscInt j = 0; j < na && w[j] < kref; ++j) { /* eigenvector j: A[j na + a], ascending */
    PetscReal r = 0, *v = &u->V[u->n * m];
    for (PetscInt a = 0; a < na; ++a) r += PetscRealPart(A[j * na + a]) * u->raw[idx[a]];
    if (!(PetscAbsReal(r) <= u->allowance)) continue;
    for (PetscInt k = 0; k < m; ++k) v[k] = 0;
    for (PetscInt a = 0; a < na; ++a) v[idx[a]] = PetscRealPart(A[j * na + a]);
    u->n++;
    if (u->nc < m) { /* and to the step's: v less its parts along them, where it is not one of them */
      PetscReal *c = &u->Vc[u->nc * m], nrm = 0;
      PetscCall(PetscArraycpy(c, v, m));
      UnheldProject(m, u->nc, u->Vc, c);
      for (PetscInt k = 0; k < m; ++k) nrm += c[k] * c[k];
      nrm = PetscSqrtReal(nrm);
      if (nrm > 1e-6) {
        for (PetscInt k = 0; k < m; ++k) c[k] /= nrm;
        u->nc++;
      }
    }
  }
  PetscCall(PetscInfo(NULL, "held by contact: %" PetscInt_FMT " of the anchors' %" PetscInt_FMT " directions frozen (least stiffness %g, held above %g; allowance %g)\n", u->n, na, (double)w[0], (double)kref, (double)u->allowance));
  PetscFunctionReturn(0);
}

void UnheldConstrain(const Unheld *u, PetscReal A[], PetscReal r[])
{
  const PetscInt m = u->m;
  PetscReal      a = 0;

  if (!u->nc) return;
  for (PetscInt k = 0; k < m; ++k) a = PetscMax(a, A[k * m + k]);
  for (PetscInt k = 0; k < m; ++k) { /* rows of A: A <- A P (A symmetric: row k projected) */
    PetscReal row[CONTACT_MAX_CONTROLS];
    for (PetscInt l = 0; l < m; ++l) row[l] = A[k * m + l];
    UnheldProject(m, u->nc, u->Vc, row);
    for (PetscInt l = 0; l < m; ++l) A[k * m + l] = row[l];
  }
  for (PetscInt l = 0; l < m; ++l) { /* columns: A <- P A */
    PetscReal col[CONTACT_MAX_CONTROLS];
    for (PetscInt k = 0; k < m; ++k) col[k] = A[k * m + l];
    UnheldProject(m, u->nc, u->Vc, col);
    for (PetscInt k = 0; k < m; ++k) A[k * m + l] = col[k];
  }
  for (PetscInt j = 0; j < u->nc; ++j)
    for (PetscInt k = 0; k < m; ++k)
      for (PetscInt l = 0; l < m; ++l) A[k * m + l] += a * u->Vc[j * m + k] * u->Vc[j * m + l];
  UnheldProject(m, u->nc, u->Vc, r);
}
