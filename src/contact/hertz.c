/* The comparison of a computed contact pressure profile with Hertz.

   Hertz, a cylinder on a half-space or two cylinders, plane strain:
     1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,   1/R* = 1/R1 + 1/R2,
     a = sqrt(4 P R* / (pi E*)),   p_max = 2 P / (pi a),
     p(s) = p_max sqrt(1 - ((s - s_c)/a)^2)  for |s - s_c| < a,
   with P the contact force per unit thickness and s_c the pressure centroid
   (Hertz's zone is centred where the computed one is). The profile's own
   figures: p_max its largest sample; a half the length of the zone p > 0,
   whose ends are where the weighted gap, interpolated linearly between the
   outermost loaded node and the next, vanishes (for Gauss-point samples,
   whose gaps scatter, half-way between them);
   a from the second moment, since Hertz's profile has
   int p (s - s_c)^2 / int p = a^2/4 (a half-width from the whole profile, not
   from where its last loaded sample happens to be); and the relative L2
   distance from Hertz with the samples' weights.

   Hertz, two spheres (axisymmetric scenes, x = r on a meridian section):
     a = (3 P R* / (4 E*))^(1/3),   p0 = 3 P / (2 pi a^2),
     p(r) = p0 sqrt(1 - r^2/a^2)   for r < a,
   with P the contact force over the whole circle and the zone centred on
   the axis (s_c = 0, the distance from the centre the radius r). The
   samples' weights carry 2 pi r, so the second moment is over the disc:
   int p r^2 dA / int p dA = 2 a^2 / 5, and a = sqrt(5/2 m2); the zone's
   end is the outer end of the loaded radii. */
#include <math.h>
#include "contactreport.h"

void HertzLineContact(PetscReal P, PetscReal Estar, PetscReal Rstar, PetscReal *a, PetscReal *pmax)
{
  *a    = PetscSqrtReal(4.0 * P * Rstar / (PETSC_PI * Estar));
  *pmax = *a > 0 ? 2.0 * P / (PETSC_PI * *a) : 0.0;
}

void HertzPointContact(PetscReal P, PetscReal Estar, PetscReal Rstar, PetscReal *a, PetscReal *pmax)
{
  *a    = PetscCbrtReal(3.0 * P * Rstar / (4.0 * Estar));
  *pmax = *a > 0 ? 3.0 * P / (2.0 * PETSC_PI * *a * *a) : 0.0;
}

PetscReal HertzPressure(PetscReal pmax, PetscReal a, PetscReal ds)
{
  const PetscReal z = ds / a;

  return PetscAbsReal(z) < 1 ? pmax * PetscSqrtReal(1 - z * z) : 0.0;
}

/* Where the zone ends between a loaded sample and the unloaded one next to it:
   for nodal samples (weighted gaps) the zero of the gap interpolated linearly
   between them; else, or if the outer gap is not finite (no master faces it),
   half-way. */
static PetscReal ContactZoneEnd(const PetscReal in[], const PetscReal out[], PetscBool nodal, PetscInt col)
{
  const PetscReal gi = in[CONTACT_ROW_GAP], go = out[CONTACT_ROW_GAP];

  if (nodal && gi < 0 && go >= 0 && !PetscIsInfOrNanReal(go)) return in[col] + (out[col] - in[col]) * gi / (gi - go);
  return 0.5 * (in[col] + out[col]);
}

void ContactProfileCompare(PetscInt n, const PetscReal rows[], PetscBool nodal, PetscBool axisym, PetscBool hertz, PetscReal hertzA, PetscReal hertzPmax, ContactProfileFigures *F)
{
  const PetscInt C = CONTACT_ROW_COLS, col = axisym ? CONTACT_ROW_X : CONTACT_ROW_S; /* the samples' coordinate: r, or the arc position */
  PetscInt       i0 = -1, i1 = -1;
  PetscReal      num = 0, den = 0, err = 0, nrm = 0, m2 = 0.0;

  F->pmax   = 0.0;
  F->ptotal = 0.0;
  for (PetscInt i = 0; i < n; ++i) {
    const PetscReal *r = &rows[C * i];
    F->pmax = PetscMax(F->pmax, r[CONTACT_ROW_P]);
    F->ptotal += r[CONTACT_ROW_P] * r[CONTACT_ROW_W];
    num += r[col] * r[CONTACT_ROW_P] * r[CONTACT_ROW_W];
    den += r[CONTACT_ROW_P] * r[CONTACT_ROW_W];
    if (r[CONTACT_ROW_P] > 0) {
      if (i0 < 0) i0 = i;
      i1 = i;
    }
  }
  F->sc = den > 0 && !axisym ? num / den : 0.0;
  for (PetscInt i = 0; i < n; ++i) m2 += rows[C * i + CONTACT_ROW_P] * rows[C * i + CONTACT_ROW_W] * PetscSqr(rows[C * i + col] - F->sc);
  F->am = den > 0 ? (axisym ? PetscSqrtReal(2.5 * m2 / den) : 2.0 * PetscSqrtReal(m2 / den)) : 0.0;
  F->a       = 0.0;
  F->zone[0] = F->zone[1] = 0.0;
  if (i0 >= 0) {
    const PetscReal lo = i0 > 0 ? ContactZoneEnd(&rows[C * i0], &rows[C * (i0 - 1)], nodal, col) : rows[C * i0 + col];
    const PetscReal hi = i1 < n - 1 ? ContactZoneEnd(&rows[C * i1], &rows[C * (i1 + 1)], nodal, col) : rows[C * i1 + col];
    F->a               = axisym ? PetscMax(lo, hi) : 0.5 * (hi - lo);
    F->zone[0]         = lo;
    F->zone[1]         = hi;
  }
  F->l2err = (PetscReal)NAN; /* no Hertz profile to compare with */
  if (hertz && hertzA > 0) {
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal *r  = &rows[C * i];
      const PetscReal  ph = HertzPressure(hertzPmax, hertzA, r[col] - F->sc);
      err += r[CONTACT_ROW_W] * PetscSqr(r[CONTACT_ROW_P] - ph);
      nrm += r[CONTACT_ROW_W] * ph * ph;
    }
    F->l2err = nrm > 0 ? PetscSqrtReal(err / nrm) : (PetscReal)NAN; /* no sample inside the Hertz zone */
  }
}
