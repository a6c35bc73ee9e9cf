#pragma once
#include "problemtypes.h"

/* -force_control_type outer (forceouter.c): a staged solve (staging.c) for each trial of the controls' displacements. */
PetscErrorCode ProblemSolveControlledOuter(Problem, PetscInt *its, TaoConvergedReason *reason);
