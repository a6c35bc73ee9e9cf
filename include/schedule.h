#pragma once
#include "problemtypes.h"

/* The solve's schedule, p->sched (schedule.c): its load steps, penalty
   stages, the first stage's penalty and L-BFGS's decrement test, from the
   options (-load_*, -penalty_*, -lmvm_decrement_rtol) and from what the
   solver chooses where the user gave none. This file alone writes it; the
   staged solve (staging.c) runs it. */
/* -load_steps, -load_stages, -load_cutbacks, -load_path ("Load stepping options"), with their defaults and checks. */
PetscErrorCode LoadOptionsSetFromOptions(MPI_Comm, LoadOptions *);
/* -penalty_stages, -penalty_start ("Penalty continuation options"), with their defaults and checks. */
PetscErrorCode PenaltyOptionsSetFromOptions(MPI_Comm, PenaltyOptions *);
/* The schedule the options give (after the configuration is read). */
PetscErrorCode ProblemScheduleSetUp(Problem);
/* Penalty continuation for a term whose penalty the program chose: stages
   and the first stage's fraction, each where the user gave none. */
PetscErrorCode ProblemSetPenaltyContinuation(Problem, PetscInt stages, PetscReal start);
/* L-BFGS's choice of the last stage's decrement test (0: off), where the user gave none. */
PetscErrorCode ProblemSetDecrementTest(Problem, PetscReal rtol);
/* A solve from a converged state runs one stage: one load step and one
   penalty stage, the schedule's kept in saved for ProblemScheduleRestore. */
PetscErrorCode ProblemScheduleOneStage(Problem, ProblemSchedule *saved);
PetscErrorCode ProblemScheduleRestore(Problem, const ProblemSchedule *saved);
