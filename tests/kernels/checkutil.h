#pragma once
/* What the kernel check programs (material_check.c, element_check.c) share:
   a deterministic random number (xorshift64, its own state in each
   program), the largest magnitude of an array, a 3 x 3 determinant. */
#include <petscsys.h>

static unsigned long long rng = 88172645463325252ULL;

static inline PetscReal Uniform(PetscReal lo, PetscReal hi) /* xorshift64 */
{
  rng ^= rng << 13;
  rng ^= rng >> 7;
  rng ^= rng << 17;
  return lo + (hi - lo) * (PetscReal)(rng >> 11) / (PetscReal)(1ULL << 53);
}

static inline PetscReal MaxAbs(PetscInt n, const PetscReal a[])
{
  PetscReal m = 0.0;
  for (PetscInt k = 0; k < n; ++k) m = PetscMax(m, PetscAbsReal(a[k]));
  return m;
}

static inline PetscReal Det3(const PetscReal F[9])
{
  return F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
}
