#pragma once
/* The values of a load history (stagedvalues.c): an option's S end values
   per component, stage after stage, and the stage a load parameter falls in. */
#include "bodycore.h"

/* The stage k (1..S) and the fraction t in [0, 1] of it at load parameter lambda in [0, S]. */
void LoadHistoryLocate(PetscInt S, PetscReal lambda, PetscInt *k, PetscReal *t);
/* Checks the count n of the values given to option opt (per per stage, S
   stages) and copies them, stage after stage, to out[s * stride + c]. */
PetscErrorCode BodyStagedValues(Body, const char opt[], PetscInt n, PetscInt per, const PetscReal v[], PetscInt stride, PetscReal out[]);
