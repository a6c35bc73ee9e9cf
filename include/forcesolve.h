#pragma once
#include "problemtypes.h"

/* Force control's solves (forcesolve.c). */
/* Fills ForceControlList (problemtypes.h): coupled, outer. Before ProblemSetFromOptions. */
PetscErrorCode ForceControlRegisterAll(void);
/* The controlled components' groups, each reaction equal to its force, by
   the type -force_control_type names (coupled where a body is held by contact). */
PetscErrorCode ProblemSolveControlled(Problem, PetscInt *its, TaoConvergedReason *reason);
/* Coupled: penalty continuation where the user chose none (after the terms' set-up). */
PetscErrorCode ProblemSetControlContinuation(Problem);
