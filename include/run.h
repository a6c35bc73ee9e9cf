#pragma once
/* The driver (src/driver): the one pipeline of a run over a Problem, which
   main() runs once and -accuracy runs in a loop (accuracy.c):

     RunCreateProblem   the scene's options read (the configuration, config.h,
                        then the problem's), its contact terms created
     RunMesh            each body meshed (a size field per body, or none)
     RunSetUp           meshes read and distributed, the stiffness assembled
     RunSolve           TAO, from rest or from a given first iterate
     RunPostProcess     the results at the solution
     RunFinish          the report, checks, and the output set written
                        (RunWriteResults) or discarded

   The run's own figures (its time slots, whether it converged, -accuracy's
   steps) live in a RunRecord, which the writer takes beside the problem. */
#include "problem.h"
#include "solve.h"

/* Where the run's time went, in the JSON's "time" and the HDF5's time_*
   attributes. Under -accuracy each slot sums over the steps. */
typedef enum { RUN_TIME_MESH, RUN_TIME_SETUP, RUN_TIME_SOLVE, RUN_TIME_OUTPUT, RUN_TIME_TOTAL, RUN_TIME_N } RunTime;
extern const char *const RunTimeNames[];

/* -accuracy's estimates of one step (relative; Inf at the first step): the
   step's, the largest of the others; the pressure profiles'; the contact
   forces' (Inf where every force is given by force controls: forceGiven);
   the force-controlled displacements' (0 where there are none). */
typedef enum { ACCURACY_ESTIMATE, ACCURACY_PROFILE, ACCURACY_FORCE, ACCURACY_DISPLACEMENT, ACCURACY_N } AccuracyEstimateKind;

/* One step of -accuracy's refinement: its dofs, solve time, error estimates,
   and the displacements of its force controls (anchors aside). */
typedef struct {
  PetscInt  dofs, iterations, ncontrols;
  PetscReal tsolve, est[ACCURACY_N];
  PetscBool forceGiven;
  PetscReal U[CONTACT_MAX_CONTROLS];
} AccuracyStep;

/* The program's own options: its output set, and meshing alone. */
typedef struct {
  char      output[PETSC_MAX_PATH_LEN], summary[PETSC_MAX_PATH_LEN];
  PetscBool outputWait; /* wait for another run writing the same outputs */
  PetscBool meshOnly;   /* mesh the scene, solve and write nothing */
} RunOptions;

/* What a run writes beside the problem's own state. */
typedef struct {
  PetscLogDouble      start; /* the program's start */
  PetscLogDouble      mark;  /* the start of the current pass of the pipeline */
  PetscReal           time[RUN_TIME_N];
  PetscBool           converged; /* the state written is a converged solve */
  int                 status;    /* the exit status: 0, or 2 for an unconverged solve or -accuracy's target missed */
  PetscReal           accuracyTarget, errorEstimate; /* -accuracy's target and the answer's estimate (0: not adaptive) */
  PetscInt            nsteps;
  const AccuracyStep *steps;
} RunRecord;

/* Reads -mesh_only, -output, -summary, -output_wait (the outputs named after
   the scene by default). */
PetscErrorCode RunOptionsSetFromOptions(MPI_Comm, const char scene[], RunOptions *);
PetscErrorCode RunCreateProblem(MPI_Comm, Problem *);
/* The problem and the configuration it borrows. */
PetscErrorCode RunDestroyProblem(Problem *);
/* fields: each body's size field, or NULL (none). */
PetscErrorCode RunMesh(Problem, char fields[][PETSC_MAX_PATH_LEN]);
PetscErrorCode RunSetUp(Problem, RunRecord *);
PetscErrorCode RunSolve(Problem, RunRecord *, PetscBool *converged);
PetscErrorCode RunPostProcess(Problem, PetscBool converged);
/* After the last solve: the Taylor test, the check for options nobody read,
   and the output set written (rec->converged) or discarded with one line
   saying why; the total time. */
PetscErrorCode RunFinish(Problem, RunRecord *);
/* Writes the HDF5 + XDMF and the JSON summary of the open output set, each to
   its temporary, then publishes them (ContactOutputCommit). */
PetscErrorCode RunWriteResults(Problem, RunRecord *);
