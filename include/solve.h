#pragma once
#include "problemtypes.h"

/* The solve (solve.c): TAO with the program's defaults, then the options,
   and the staged or force-controlled solve it runs. */
/* Creates the TAO solver with the program's defaults and the options (also
   before ProblemSetUp(), for -help). */
PetscErrorCode ProblemCreateSolver(Problem);
PetscErrorCode ProblemSolve(Problem, PetscBool *converged);
