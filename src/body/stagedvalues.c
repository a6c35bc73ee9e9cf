/* The values a load history gives (-load_stages S): an option's S end
   values per component, checked and stored stage after stage, and where
   in the history a load parameter falls. The options' readers (conditions,
   loads, a rigid body's motion) call this; history.c puts the body at a
   load parameter from what they stored. */
#include "stagedvalues.h"
#include "bodyimpl.h"

void LoadHistoryLocate(PetscInt S, PetscReal lambda, PetscInt *k, PetscReal *t)
{
  *k = (PetscInt)PetscCeilReal(lambda - 1e-12);
  *k = PetscMin(PetscMax(*k, 1), S);
  *t = PetscMin(PetscMax(lambda - (PetscReal)(*k - 1), 0.0), 1.0);
}

PetscErrorCode BodyStagedValues(Body b, const char opt[], PetscInt n, PetscInt per, const PetscReal v[], PetscInt stride, PetscReal out[])
{
  const PetscInt S = b->nstages;

  PetscFunctionBeginUser;
  PetscCheck(S > 1 || n == per, b->comm, PETSC_ERR_USER_INPUT, "option %s: %" PetscInt_FMT " values for %" PetscInt_FMT " components", opt, n, per);
  PetscCheck(n == per * S, b->comm, PETSC_ERR_USER_INPUT, "option %s: %" PetscInt_FMT " values for %" PetscInt_FMT " components and -load_stages %" PetscInt_FMT " (give %" PetscInt_FMT ", stage-major: stage 1's components, then stage 2's, x1,y1,x2,y2,...)", opt, n, per, S, per * S);
  for (PetscInt s = 0; s < S; ++s)
    for (PetscInt c = 0; c < per; ++c) {
      PetscCheck(!PetscIsInfOrNanReal(v[s * per + c]), b->comm, PETSC_ERR_USER_INPUT, "option %s: must be finite, got %g", opt, (double)v[s * per + c]);
      out[s * stride + c] = v[s * per + c];
    }
  PetscFunctionReturn(0);
}
