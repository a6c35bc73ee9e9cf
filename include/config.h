#pragma once
/* The program's configuration as one object (config.c; its types in
   configtypes.h): created and read by the driver (run.c) before the problem,
   which borrows it, and destroyed after the problem. */
#include "configtypes.h"

PetscErrorCode SolverConfigCreate(MPI_Comm, SolverConfig *);
/* Collective: every concern's options, in the order -help lists them; each
   bad value stops here, with the option named, before anything is meshed. */
PetscErrorCode SolverConfigSetFromOptions(SolverConfig);
/* Every concern's options in force, as the options would give them. */
PetscErrorCode SolverConfigView(SolverConfig, PetscViewer);
PetscErrorCode SolverConfigDestroy(SolverConfig *);
