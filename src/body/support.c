/* What holds a body that no displacement holds: its contacts must be able to
   react the forces given it.

   A contact pushes a body along its surface's inward normal (frictionless),
   or within the cone of half-angle atan(mu) about it (Coulomb), and never
   pulls. So a body whose only support is its contacts (no Dirichlet
   component held by a displacement; every condition force-controlled, or
   none: held by contact) and that carries no pressure or traction can be
   in equilibrium under the force F given it (the force-controlled groups'
   sum, at each stage) only if -F is a sum of such pushes: -F in the cone of
   its contact surfaces' inward normals, widened by atan(mu). In the plane
   that cone is the arc of directions [a, b] the normals span (the circle
   less its largest gap between two normals' angles), or the whole plane
   where no gap exceeds pi. Two cases cannot be solved:
   - F = 0 and the normals within an open half-plane (the arc shorter than
     pi): the contacts can only push the body one way and nothing pushes it
     back, so no contact force can build up (a slab pressed by a punch with
     its base left free: it moves along with the punch, P = 0 after a minute
     of solving, or the line search fails);
   - F outside the cone: no push of the contacts balances it, the body moves
     off along it without end (a force pulling a punch off the block).
   Both are one line naming the body and the motion, before solving. The
   normals are taken in the reference configuration at each edge's ends and
   middle, with a margin of 1e-6 rad, so that only a scene wrong by its
   geometry is refused (a large deformation could turn a normal; then the
   solve decides). In r-z a body moves along the axis alone: the normals'
   and the forces' axial parts are compared (the radial parts cancel round
   the ring). Rotations are not checked (a moment the contacts cannot react
   is left to the solve). */
#include "support.h"
#include "bodyimpl.h"

#define SUPPORT_MARGIN 1e-6

PetscErrorCode BodyAddContactNormals(Body b, PetscInt n, const PetscReal nrm[], PetscReal mu)
{
  PetscReal *all;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(2 * (b->nsupport + n), &all));
  if (b->nsupport) PetscCall(PetscArraycpy(all, b->support, 2 * b->nsupport));
  PetscCall(PetscArraycpy(all + 2 * b->nsupport, nrm, 2 * n));
  PetscCall(PetscFree(b->support));
  b->support = all;
  b->nsupport += n;
  b->supportMu = PetscMax(b->supportMu, mu);
  PetscFunctionReturn(0);
}

PetscErrorCode BodySupportDestroy(Body b)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(b->support));
  b->nsupport = 0;
  PetscFunctionReturn(0);
}

PetscBool BodyGivenForcesAlone(const Body b, PetscReal F[][3], PetscBool held[3])
{
  for (PetscInt k = 0; k < b->nstages; ++k) F[k][0] = F[k][1] = F[k][2] = 0.0;
  if (held) held[0] = held[1] = held[2] = PETSC_FALSE;
  if (b->nload > 0) return PETSC_FALSE;
  for (PetscInt i = 0; i < b->nbc; ++i) {
    const BodyBC *bc = &b->bc[i];
    for (PetscInt j = 0; j < bc->ncomp; ++j) {
      if (!bc->control[j] && held) {
        held[bc->comps[j]] = PETSC_TRUE;
        continue;
      }
      if (!bc->control[j]) return PETSC_FALSE; /* a displacement held reacts any force */
      for (PetscInt k = 0; k < b->nstages; ++k) F[k][bc->comps[j]] += bc->stage[k][j];
    }
  }
  return PETSC_TRUE;
}

static int CompareReal(const void *a, const void *b)
{
  const PetscReal x = *(const PetscReal *)a, y = *(const PetscReal *)b;
  return x < y ? -1 : x > y ? 1 : 0;
}

/* The arc of directions the normals span: from angle a, of length L (2 pi: all) */
static PetscErrorCode NormalsArc(const Body b, PetscReal *a, PetscReal *L)
{
  PetscReal *ang, gap = -1.0;
  PetscInt   n = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(b->nsupport, &ang));
  for (PetscInt i = 0; i < b->nsupport; ++i) {
    PetscReal x = b->support[2 * i], y = b->support[2 * i + 1];
    if (b->axisym) { /* the axial part alone */
      if (PetscAbsReal(y) < SUPPORT_MARGIN) continue;
      x = 0.0;
      y = y > 0 ? 1.0 : -1.0;
    }
    ang[n] = PetscAtan2Real(y, x);
    if (ang[n] < 0) ang[n] += 2.0 * PETSC_PI;
    ++n;
  }
  *a = 0.0;
  *L = 2.0 * PETSC_PI;
  if (n) {
    qsort(ang, (size_t)n, sizeof(PetscReal), CompareReal);
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal g = i + 1 < n ? ang[i + 1] - ang[i] : ang[0] + 2.0 * PETSC_PI - ang[i];
      if (g > gap) {
        gap = g;
        *a  = i + 1 < n ? ang[i + 1] : ang[0];
      }
    }
    *L = 2.0 * PETSC_PI - gap;
  } else *L = -1.0; /* no normal: nothing holds it */
  PetscCall(PetscFree(ang));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyCheckSupport(Body b)
{
  PetscReal F[CONTACT_MAX_STAGES][3], a = 0.0, L = 0.0, w;

  PetscFunctionBeginUser;
  if (!b->npairs || !BodyGivenForcesAlone(b, F, NULL)) PetscFunctionReturn(0);
  PetscCall(NormalsArc(b, &a, &L));
  if (L < 0) PetscFunctionReturn(0);
  w = PetscAtanReal(b->supportMu); /* the friction cone's half-angle */
  if (L + 2.0 * w >= 2.0 * PETSC_PI - SUPPORT_MARGIN) PetscFunctionReturn(0); /* pushes every way */
  for (PetscInt k = 0; k < b->nstages; ++k) {
    const PetscReal Fk[2] = {b->axisym ? 0.0 : F[k][0], F[k][1]};
    PetscReal       f;

    f = PetscSqrtReal(Fk[0] * Fk[0] + Fk[1] * Fk[1]);
    if (f == 0.0) {
      const PetscReal mid = a + 0.5 * L, d[2] = {PetscCosReal(mid), PetscSinReal(mid)};
      PetscCheck(L + 2.0 * w >= PETSC_PI - SUPPORT_MARGIN, b->comm, PETSC_ERR_USER_INPUT,
                 "body %s: held by its contacts alone, which can only push it towards (%.3g, %.3g), and nothing given holds it back: no contact force can build up (it would move along with what presses it); hold it with a Dirichlet condition (e.g. on its far side) or give it a force against its contacts", b->name, (double)(PetscAbsReal(d[0]) < 1e-12 ? 0.0 : d[0]), (double)(PetscAbsReal(d[1]) < 1e-12 ? 0.0 : d[1]));
    } else {
      PetscReal phi = PetscAtan2Real(-Fk[1], -Fk[0]) - (a - w);
      while (phi < 0) phi += 2.0 * PETSC_PI;
      while (phi >= 2.0 * PETSC_PI) phi -= 2.0 * PETSC_PI;
      PetscCheck(phi <= L + 2.0 * w + SUPPORT_MARGIN || phi >= 2.0 * PETSC_PI - SUPPORT_MARGIN, b->comm, PETSC_ERR_USER_INPUT,
                 "body %s: the force given it at stage %" PetscInt_FMT ", (%g, %g), is not one its contacts can react (they only push it, along their normals or within friction's cone): it would move off along (%.3g, %.3g) without end; give the force against the contacts, or hold the body with a displacement", b->name, k + 1, (double)F[k][0], (double)F[k][1], (double)(Fk[0] / f), (double)(Fk[1] / f));
    }
  }
  PetscFunctionReturn(0);
}
