#pragma once
#include "problemtypes.h"

/* The solve's schedule, p->sched (schedule.c): its load steps, penalty
   stages, the first stage's penalty and L-BFGS's decrement test, from the
   options (-load_*, -penalty_*, -lmvm_decrement_rtol) and from what the
   solver chooses where the user gave none. The staged solve (staging.c)
   runs it. */
/* -load_steps, -load_stages, -load_cutbacks, -load_path ("Load stepping options"), with their defaults and checks. */
PetscErrorCode LoadOptionsSetFromOptions(MPI_Comm, LoadOptions *);
/* -penalty_stages, -penalty_start ("Penalty continuation options"), with their defaults and checks. */
PetscErrorCode PenaltyOptionsSetFromOptions(MPI_Comm, PenaltyOptions *);
/* The schedule the options give (after the configuration is read). */
PetscErrorCode ProblemScheduleSetUp(Problem);
/* Penalty continuation for a term whose penalty the program chose: stages
   and the first stage's fraction, each where the user gave none. */
PetscErrorCode ProblemSetPenaltyContinuation(Problem, PetscInt stages, PetscReal start);
