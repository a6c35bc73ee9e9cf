#pragma once
#include <petsctao.h>

/* Progress of a run on stderr (progress.c): one line as each phase starts,
   with the elapsed time, and one per Newton iteration. On when stderr is a
   terminal; -progress forces it on, -quiet off. The current phase also names
   where an interrupted run stopped. */
PetscErrorCode ContactProgressSetUp(MPI_Comm);
PetscErrorCode ContactProgressPhase(const char phase[], const char fmt[], ...);
PetscErrorCode ContactProgressTaoMonitor(Tao, void *);
PetscBool      ContactProgressEnabled(void);
/* The phase under way, for a signal handler (a string that lives as long as the run). */
const char *ContactProgressCurrentPhase(void);
