#pragma once
#include "energyterm.h"
#include "subdomain.h"

#define CONTACT_MAX_TERMS 16

/* Contact Hessian: Gauss-Newton, exact, or Gauss-Newton until the gradient is small */
typedef enum { HESSIAN_GAUSS_NEWTON, HESSIAN_EXACT, HESSIAN_AUTO } HessianType;
extern const char *const HessianTypes[];

typedef enum { H0_NONE, H0_ELASTIC } H0Type;
extern const char *const H0Types[];

/* How the Newton step's Schur complement on the contact surfaces is formed:
   by substructuring, on any number of ranks (substructure.c), or by MUMPS
   from K, on one rank (schur.c). */
typedef enum { SCHUR_SUBSTRUCTURE, SCHUR_MUMPS } SchurType;
extern const char *const SchurTypes[];

/* One step of -accuracy's refinement (accuracy.c): its dofs, solve time and
   error estimates (relative: the pressure profiles', the contact force's, and
   the larger of the two; Inf at the first step). */
typedef struct {
  PetscInt  dofs, iterations;
  PetscReal tsolve, estimate, profile, force;
} AccuracyStep;

/* The whole scene: bodies joined into one vector, energy terms, TAO glue. */
typedef struct _n_Problem *Problem;
struct _n_Problem {
  MPI_Comm  comm;
  char      scene[CONTACT_NAME_LEN];
  char      output[PETSC_MAX_PATH_LEN], summary[PETSC_MAX_PATH_LEN], meshDir[PETSC_MAX_PATH_LEN];
  PetscBool outputWait; /* wait for another run writing the same outputs */
  PetscBool meshOnly;   /* set before ProblemSetFromOptions: mesh, write nothing */
  PetscBool outputOpen; /* set before ProblemSetFromOptions: the output set is already open (an earlier -accuracy step) */
  PetscBool deferView;  /* ProblemPostProcess does not print the terms' reports (ProblemView does) */
  Vec       X0;         /* set before ProblemSolve: the first iterate (NULL: rest; ignored with load or penalty stages) */
  char      bgm[CONTACT_MAX_BODIES][PETSC_MAX_PATH_LEN]; /* set before ProblemSetFromOptions: each body's size field, or empty */
  PetscReal accuracyTarget, errorEstimate; /* -accuracy's target and the estimate of the answer (0: not adaptive) */
  PetscInt  nAccuracySteps;
  const AccuracyStep *accuracySteps;
  PetscReal meshSize;
  PetscReal maxDofs; /* refuse a generated mesh above this many dofs (-max_dofs, else from memory) */
  PetscInt  nbodies;
  Body      bodies[CONTACT_MAX_BODIES];
  PetscInt  nterms;
  EnergyTerm terms[CONTACT_MAX_TERMS];
  PetscInt  partitioner;
  PetscBool partitionView, taylor;
  PetscInt  offset[CONTACT_MAX_BODIES]; /* start of each body in this rank's part of X */
  Vec       X, G;
  Mat       H, K; /* Hessian, elastic stiffness of the bodies */
  IS        surfaceDofs; /* contact-surface dofs (the contact Hessian's block), or NULL */
  Subdomain sub;         /* several ranks: this rank's cells and their stiffness, until the Newton step takes it */
  H0Type    h0;
  Tao       tao;
  PetscInt  nEnergyEvals, nHessianEvals, iterations; /* iterations: TAO's, over all stages */
  PetscReal energy, gnorm;  /* at the solution (ProblemPostProcess) */
  PetscReal bodyEnergy[CONTACT_MAX_BODIES]; /* each body's elastic energy at the solution */
  TaoConvergedReason reason;
  PetscReal time[5]; /* mesh, setup, solve, output, total */
  PetscLogDouble t0; /* start of the run */
  PetscReal taylorRates[2], taylorRemainders[2][8], taylorEps[8];
  PetscInt  taylorN;
  PetscReal taylorScale;
  PetscInt  loadSteps, penaltyStages, stagesDone;
  PetscInt  maxCutbacks, cutbacks; /* automatic load cutback: the limit, and how many a solve took */
  PetscReal loadDone;               /* the load factor of the last converged stage */
  PetscBool schur; /* Newton through the contact-surface Schur complement */
  PetscBool iterative; /* Newton by CG + GAMG (iterative.c) */
  SchurType schurType;
  HessianType hessianType;  /* -contact_hessian */
  PetscReal hessianSwitch;   /* auto: exact once ||g|| < hessianSwitch ||g0|| */
  PetscReal hessianG0;       /* ||g|| at the current TAO solve's first iterate */
  PetscBool exactHessian;    /* the second-order term is in the current Hessian (may be indefinite) */
  PetscReal penaltyStart, stageRtol;
};

PetscErrorCode ProblemCreate(MPI_Comm, Problem *);
PetscErrorCode ProblemSetFromOptions(Problem);
PetscErrorCode ProblemSetUp(Problem);
PetscErrorCode ProblemComputeObjectiveGradient(Tao, Vec, PetscReal *, Vec, void *);
PetscErrorCode ProblemComputeHessian(Tao, Vec, Mat, Mat, void *);
/* Sets every body's local vector (Dirichlet values inserted) from X. */
PetscErrorCode ProblemScatterToBodies(Problem, Vec X);
/* Creates the TAO solver with the program's defaults and the options (also
   before ProblemSetUp(), for -help). */
PetscErrorCode ProblemCreateSolver(Problem);
PetscErrorCode ProblemSolve(Problem, PetscBool *converged);
/* Collective: the results at the converged state X (energy, gradient norm,
   reactions, each term's results) and the report. */
PetscErrorCode ProblemPostProcess(Problem, Vec X, PetscBool converged);
/* Collective: prints each term's report of ProblemPostProcess (there, unless deferView). */
PetscErrorCode ProblemView(Problem);
PetscErrorCode ProblemCheckUnusedOptions(Problem, PetscBool final);
PetscErrorCode ProblemTaylorTest(Problem);
PetscErrorCode ProblemDestroy(Problem *);
PetscErrorCode ProblemWriteOutput(Problem, PetscBool converged);
