#pragma once
#include "problem.h"

/* A contact pair: one surface (a Gmsh physical curve) on each of two bodies,
   each acting as slave against the other; the penalty energies of the two
   one-sided integrals are averaged (contactpair.c). */
PetscErrorCode ContactPairsCreateFromOptions(Problem);
PetscErrorCode ContactPairsSetUp(Problem);
PetscErrorCode ContactPairsGetSurfaceDofs(Problem, IS *);
/* Collective: gathers the pressure profiles and Hertz comparison after a solve. */
PetscErrorCode ContactPairsReport(Problem);
PetscErrorCode ContactPairsWriteJSON(Problem, FILE *);
PetscErrorCode ContactPairsWriteHDF5(Problem, PetscViewer);
