/* The forces a scene gives against what friction can hold, checked before
   solving (contactterm.h).

   A body whose only support along its partner is one frictional pair, and
   whose scene gives it forces alone (every condition force-controlled, no
   displacement held, no pressure or traction: the body of a Cattaneo-Mindlin
   scene pressed by P and pulled by Q), is in equilibrium only if the
   contact's force balances the force given, F. Against a flat partner of
   outward normal n the contact's force has its normal part -(F.n) n and its
   tangential part -(F - (F.n) n), and Coulomb's law bounds the second by mu
   times the first: |F - (F.n) n| <= mu |F.n| (Q <= mu P). Where the scene
   asks more at some stage, no state holds it: the body slides along the
   partner without end, and the solve learns it only by failing, after its
   cutbacks (a minute on the cattaneo scene). So it is said here, before
   meshing is paid for twice: one line naming the pair, the body, the stage
   and both forces.

   Only where the answer is certain: a plane-strain pair (in r-z a body's
   force is axial alone), a partner surface flat in the reference
   configuration (its edges' chords parallel to 1e-9: a curved partner's
   normal depends on where the contact lands), the body in no other pair
   (another pair may hold what this one cannot), and every one of its
   Dirichlet components force-controlled with no load on it (a displacement
   held anywhere reacts any force). A rigid body's components that no
   condition holds are forces of zero, as in the solve. */
#include "contactterm.h"
#include "support.h"

/* The outward unit normal of a flat surface, or PETSC_FALSE if it is not. */
static PetscBool FlatNormal(const ContactSurface *M, PetscReal n[2])
{
  PetscReal t[2] = {0, 0};

  for (PetscInt e = 0; e < M->ne; ++e) {
    const PetscReal *a = &M->X[2 * M->enodes[3 * e]], *b = &M->X[2 * M->enodes[3 * e + 1]];
    PetscReal        d[2] = {b[0] - a[0], b[1] - a[1]}, l = PetscSqrtReal(d[0] * d[0] + d[1] * d[1]);

    if (l <= 0) return PETSC_FALSE;
    d[0] /= l;
    d[1] /= l;
    if (!e) {
      t[0] = d[0];
      t[1] = d[1];
      n[0] = d[1] * M->esign[e];
      n[1] = -d[0] * M->esign[e];
    } else if (PetscAbsReal(t[0] * d[1] - t[1] * d[0]) > 1e-9) return PETSC_FALSE;
  }
  return M->ne > 0 ? PETSC_TRUE : PETSC_FALSE;
}

/* Whether side s's body is one whose given forces the check can judge
   (above): a plane-strain frictional pair, the body given forces alone in
   no other pair, its partner flat (its outward normal into n); its forces
   per stage into F. */
static PetscBool GivenForcesOnFlat(const ContactTerm *b, Body bodies[], PetscInt s, PetscReal F[][3], PetscReal n[2])
{
  const ContactPairSpec *spec = &b->spec;
  const Body             B    = bodies[b->S[s].body];

  if (spec->friction <= 0 || spec->axisym || spec->mirror) return PETSC_FALSE;
  return (PetscBool)(BodyGetNumContactPairs(B) == 1 && BodyGivenForcesAlone(B, F, NULL) && FlatNormal(&b->S[1 - s], n));
}

/* A force's parts across the normal n (Fn, signed) and along it (Ft >= 0). */
static void ForceParts(const PetscReal F[3], const PetscReal n[2], PetscReal *Fn, PetscReal *Ft)
{
  *Fn = F[0] * n[0] + F[1] * n[1];
  *Ft = PetscSqrtReal(PetscSqr(F[0] - *Fn * n[0]) + PetscSqr(F[1] - *Fn * n[1]));
}

PetscErrorCode ContactTermCheckGivenForces(const ContactTerm *b, Body bodies[])
{
  const ContactPairSpec *spec = &b->spec;
  const PetscReal        mu   = spec->friction;

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) {
    const Body B = bodies[b->S[s].body];
    PetscReal  F[CONTACT_MAX_STAGES][3], n[2];

    if (!GivenForcesOnFlat(b, bodies, s, F, n)) continue; /* none given: 0 <= mu 0 */
    for (PetscInt k = 0; k < BodyGetNumStages(B); ++k) {
      PetscReal Fn, Ft;

      ForceParts(F[k], n, &Fn, &Ft);
      PetscCheck(Ft <= mu * PetscAbsReal(Fn) * (1.0 + 1e-12), BodyGetComm(B), PETSC_ERR_USER_INPUT,
                 "pair %s: the forces given on body %s at stage %" PetscInt_FMT " are %g along %s:%s and %g across it, more than friction holds (mu = %g times %g = %g; Q/(mu P) = %.6g): it would slide without end; lower the tangential force or raise -contact_%s_friction",
                 spec->name, BodyGetName(B), k + 1, (double)Ft, BodyGetName(bodies[b->S[1 - s].body]), b->S[1 - s].group, (double)PetscAbsReal(Fn), (double)mu, (double)PetscAbsReal(Fn), (double)(mu * PetscAbsReal(Fn)), (double)(Ft / (mu * PetscAbsReal(Fn))), spec->name);
    }
  }
  PetscFunctionReturn(0);
}

/* Whether an increment from rest must start tied (friction.c,
   FrictionSetTieAtRest): a body of the pair given forces alone, in no
   other pair, pressed against a flat partner and given at the first stage
   a force with a part along it. Its first solve from rest has no rows and
   so no friction: nothing holds it along the contact, and the force given
   there carries it off (the cattaneo scene given P and Q = 0.5 mu P at one
   stage: DIVERGED_USER after its cutbacks, "slides"). Not against a curved
   partner (its normal depends on where the contact lands: as before). */
PetscBool ContactTermTiesAtRest(const ContactTerm *b, Body bodies[])
{
  for (PetscInt s = 0; s < 2; ++s) {
    PetscReal F[CONTACT_MAX_STAGES][3], n[2], Fn, Ft;

    if (!GivenForcesOnFlat(b, bodies, s, F, n)) continue;
    ForceParts(F[0], n, &Fn, &Ft);
    if (Ft > 1e-12 * PetscAbsReal(Fn)) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

/* Each surface's inward unit normals at its edges' ends and middles
   (reference configuration), handed to its body (support.c). On a
   quadratic edge x(eta) = N0 X0 + N1 X1 + N2 Xm, the tangent is
   (eta - 1/2) X0 + (eta + 1/2) X1 - 2 eta Xm. */
PetscErrorCode ContactTermAddSupport(const ContactTerm *b, Body bodies[])
{
  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) {
    const ContactSurface *S = &b->S[s];
    PetscReal            *nrm;
    PetscInt              n = 0;

    PetscCall(PetscMalloc1(6 * S->ne, &nrm));
    for (PetscInt e = 0; e < S->ne; ++e) {
      const PetscReal *X0 = &S->X[2 * S->enodes[3 * e]], *X1 = &S->X[2 * S->enodes[3 * e + 1]], *Xm = &S->X[2 * S->enodes[3 * e + 2]];
      for (PetscInt q = 0; q < 3; ++q) {
        const PetscReal eta = (PetscReal)(q - 1);
        const PetscReal t[2] = {(eta - 0.5) * X0[0] + (eta + 0.5) * X1[0] - 2.0 * eta * Xm[0], (eta - 0.5) * X0[1] + (eta + 0.5) * X1[1] - 2.0 * eta * Xm[1]};
        const PetscReal l = PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
        if (l <= 0) continue;
        nrm[2 * n]     = -t[1] * S->esign[e] / l; /* inward: the outward (t_y, -t_x) esign reversed */
        nrm[2 * n + 1] = t[0] * S->esign[e] / l;
        ++n;
      }
    }
    PetscCall(BodyAddContactNormals(bodies[S->body], n, nrm, b->spec.friction));
    PetscCall(PetscFree(nrm));
  }
  PetscFunctionReturn(0);
}
