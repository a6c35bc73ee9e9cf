#pragma once
#include "energyterm.h"
#include "subdomain.h"
#include "unheld.h"

#define CONTACT_MAX_TERMS    16

/* Contact Hessian: Gauss-Newton, exact, or Gauss-Newton until the gradient is small */
typedef enum { HESSIAN_GAUSS_NEWTON, HESSIAN_EXACT, HESSIAN_AUTO } HessianType;
extern const char *const HessianTypes[];

typedef enum { H0_NONE, H0_ELASTIC, H0_CONTACT } H0Type;
extern const char *const H0Types[];

/* How the Newton step's Schur complement on the contact surfaces is formed:
   by substructuring, on any number of ranks (substructure.c), or by MUMPS
   from K, on one rank (schur.c). */
typedef enum { SCHUR_SUBSTRUCTURE, SCHUR_MUMPS } SchurType;
extern const char *const SchurTypes[];

/* What ProblemSetFromOptions reads, and nothing else. */
typedef struct {
  char        scene[CONTACT_NAME_LEN];
  char        meshDir[PETSC_MAX_PATH_LEN];
  PetscReal   meshSize; /* -mesh_size, or -1: each body's own */
  PetscReal   maxDofs;  /* refuse a generated mesh above this many dofs (-max_dofs; 0: from memory, set when meshing) */
  PetscInt    partitioner;
  PetscBool   partitionView, taylor;
  PetscBool   axisymmetric; /* -axisymmetric: every body in r-z (axis.c) */
  PetscReal   taylorScale;
  H0Type      h0;
  PetscInt    h0Refresh; /* -lmvm_h0 contact: the H0 recomputed every this many iterations */
  PetscInt    lmvmRestarts; /* -lmvm_restarts: the most restarts of an L-BFGS solve whose line search failed */
  PetscReal   pairRatio; /* -lmvm_pair_ratio: a correction pair kept while its curvature is within this factor of H0's */
  PetscReal   decrementRtol; /* -lmvm_decrement_rtol: the last stage stops on the decrement g'H0^-1 g (0: off, the gradient tolerances; -1: not given, chosen with the solver) */
  PetscInt    loadSteps, penaltyStages;
  PetscInt    maxCutbacks; /* automatic load cutback: the most a solve may take */
  PetscReal   penaltyStart, stageRtol;
  PetscBool   penaltyStagesSet, penaltyStartSet; /* given by the user (else ProblemSetPenaltyContinuation may choose) */
  char        controlType[64]; /* -force_control_type: coupled (the displacements are unknowns of the one minimisation) or outer (forcecontrol.c) */
  PetscInt    controlMaxIt;  /* force control: the most solves of its outer iteration (outer), of the solve and its refinements (coupled) */
  PetscReal   controlRtol;   /* force control: |reaction - force| <= this |force| ends it */
  PetscBool   controlRtolSet; /* given (coupled force control checks it only then) */
  PetscReal   controlStep;   /* coupled force control: the most a Newton step moves a controlled group, times its body's size */
  PetscBool   schur;     /* Newton through the contact-surface Schur complement */
  PetscBool   iterative; /* Newton by CG + GAMG (iterative.c) */
  SchurType   schurType;
  HessianType hessianType;   /* -contact_hessian */
  PetscReal   hessianSwitch; /* auto: exact once ||g|| < hessianSwitch ||g0|| */
} ProblemOptions;

/* A force-controlled component (forcecontrol.c): body, Dirichlet condition
   and component (an index into its comps), its force, and the displacement
   and reaction of the last solve. */
typedef struct {
  PetscInt  body, bc, c;
  PetscReal force, U, R;
  PetscReal L;     /* the body's size: its reference bounding box's diagonal */
  PetscReal scale; /* what |R - force| is measured against: |force| and the body's loads */
  PetscBool anchor; /* the anchor of a body held by contact (anchors.c): force 0 */
  PetscReal kref;   /* an anchor: a motion stiffer than this is held by the contact (forceborder.c) */
} ForceControl;

/* What a solve and its post-processing found. */
typedef struct {
  PetscInt           nEnergyEvals, nHessianEvals, iterations; /* iterations: TAO's, over all stages */
  PetscInt           stagesDone, cutbacks; /* the stages solved, and how many times the load was cut back */
  PetscReal          loadDone;             /* the load factor of the last converged stage */
  TaoConvergedReason reason;
  PetscReal          energy, gnorm;        /* at the solution (ProblemPostProcess) */
  PetscReal          bodyEnergy[CONTACT_MAX_BODIES]; /* each body's elastic energy at the solution */
  PetscReal          taylorRates[2], taylorRemainders[2][8], taylorEps[8]; /* ProblemTaylorTest */
  PetscInt           taylorN;
  PetscInt           controlSolves; /* force control: the solves of its outer iteration */
  PetscInt           h0Refreshes;   /* -lmvm_h0 contact: the H0 set-ups (the first included) */
  PetscInt           pairsDropped;  /* -lmvm_pair_ratio: the correction pairs dropped */
  PetscInt           lmvmRestarts;  /* -lmvm_restarts: the L-BFGS solves restarted */
  PetscInt           decrementSolves; /* -lmvm_decrement_rtol: the H0 solves of the decrement test */
  PetscInt           decrementFloor;  /* -lmvm_decrement_rtol: last stages ended at the decrement's round-off floor */
  char               why[256];      /* why the solve stopped short, if the problem itself knows ("" else) */
} ProblemResults;

/* What the solve runs: the options' load steps, penalty continuation and
   decrement test, or, where the user gave none, what the program chose
   (ProblemSetPenaltyContinuation, the L-BFGS defaults of lmvm.c); force
   control's solves from a converged state run one stage. */
typedef struct {
  PetscInt  loadSteps, penaltyStages;
  PetscReal penaltyStart;  /* the first stage's k_p over the scene's */
  PetscReal decrementRtol; /* the last stage stops on the decrement (0: on the gradient tolerances; -1: not chosen yet) */
} ProblemSchedule;

/* The whole scene: bodies joined into one vector, energy terms, TAO glue. */
typedef struct _n_Problem *Problem;
struct _n_Problem {
  MPI_Comm       comm;
  ProblemOptions opt;
  ProblemSchedule sched;
  PetscInt       nbodies;
  Body           bodies[CONTACT_MAX_BODIES];
  PetscInt       nterms;
  EnergyTerm     terms[CONTACT_MAX_TERMS];
  PetscInt       offset[CONTACT_MAX_BODIES]; /* start of each body in this rank's part of X */
  Vec            X, G; /* TAO's unknowns and gradient: the bodies' dofs, then (coupled force control, rank 0) the controlled displacements */
  Vec            Xb;   /* the bodies' dofs alone, the layout of K and H (X itself without coupled controls) */
  Vec            X0;   /* the first iterate (NULL: rest; ignored with load or penalty stages) */
  Mat            H, K; /* Hessian, elastic stiffness of the bodies */
  IS             surfaceDofs; /* contact-surface dofs (the contact Hessian's block), or NULL */
  Subdomain      sub;         /* several ranks: this rank's cells and their stiffness, until the Newton step takes it */
  Tao            tao;
  PetscBool      exactHessian; /* the second-order term is in the current Hessian (may be indefinite) */
  PetscReal      hessianG0;    /* ||g|| at the current TAO solve's first iterate */
  PetscInt       ncontrols;
  ForceControl   controls[CONTACT_MAX_CONTROLS];
  PetscBool      coupled;   /* the controls' displacements are the last entries of X (forcecontrol.c) */
  Vec            ctrlB[CONTACT_MAX_CONTROLS]; /* coupled: K_fc 1 of each control (Xb's layout) */
  PetscReal      ctrlD[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS]; /* coupled: 1^T K_cc 1 between controls */
  Unheld         unheld; /* coupled: the anchors' directions the contact does not hold (unheld.c) */
  Mat            Htao;      /* the Hessian TAO sees: H, or H bordered by the controls (forceborder.c) */
  Mat            H0tao;     /* L-BFGS's H0 as TAO sees it: H or K, or either bordered */
  KSP            ctrlKsp, ctrlKsp0; /* coupled: the solves of H (Newton) and of H0 (L-BFGS) inside the bordered ones */
  Vec            lmvmX, lmvmG, lmvmW; /* L-BFGS (lmvm.c): the last iterate and its gradient, work */
  PetscBool      lmvmHave;            /* lmvmX, lmvmG hold an iterate of the current TAO solve */
  PetscReal      lmvmF0, lmvmG0;      /* the energy and gradient norm at the first iterate of the last TAO solve */
  PetscReal      lmvmLambda0;         /* -lmvm_decrement_rtol: the decrement at the first iterate of the staged solve (-1: not yet) */
  PetscReal      lmvmLambda;          /* -lmvm_decrement_rtol: the decrement at the current TAO solve's last iterate (-1: none yet) */
  PetscBool      lmvmFinal;           /* the current TAO solve is the last stage (the decrement test applies) */
  ProblemResults res;
};

/* The life of a problem: Create, SetFromOptions (reads the scene's options
   and its bodies' and nothing else), GenerateMeshes (each body's mesh, sizes
   checked first), AddTerm (the contact terms, created by the caller), SetUp,
   Solve, PostProcess, View, Destroy. */
PetscErrorCode ProblemCreate(MPI_Comm, Problem *);
PetscErrorCode ProblemSetFromOptions(Problem);
/* Collective: generates every body's mesh (with its size field, if one was
   set by BodySetSizeField), refusing one above -max_dofs before any is made. */
PetscErrorCode ProblemGenerateMeshes(Problem);
/* Adds an energy term; the problem takes the reference and destroys it. */
PetscErrorCode ProblemAddTerm(Problem, EnergyTerm);
/* Penalty continuation for a term whose penalty the program chose: stages
   and the first stage's fraction, where the user gave none. */
PetscErrorCode ProblemSetPenaltyContinuation(Problem, PetscInt stages, PetscReal start);
/* The first iterate of ProblemSolve (after ProblemSetUp; referenced). */
PetscErrorCode ProblemSetInitialGuess(Problem, Vec X0);
PetscErrorCode ProblemSetUp(Problem);
PetscErrorCode ProblemComputeObjectiveGradient(Tao, Vec, PetscReal *, Vec, void *);
PetscErrorCode ProblemComputeHessian(Tao, Vec, Mat, Mat, void *);
/* P = K + the terms' Hessians at X, in their current order (exact or Gauss-Newton). */
PetscErrorCode ProblemAssembleHessian(Problem, Vec X, Mat P);
/* A direct solve by Cholesky: CHOLMOD on one rank, MUMPS on several or for a matrix that may be indefinite. */
PetscErrorCode ContactPCSetCholesky(PC, MPI_Comm, PetscBool indefinite);
/* Sets every body's local vector (Dirichlet values inserted) from X. */
PetscErrorCode ProblemScatterToBodies(Problem, Vec X);
/* Creates the TAO solver with the program's defaults and the options (also
   before ProblemSetUp(), for -help). */
PetscErrorCode ProblemCreateSolver(Problem);
PetscErrorCode ProblemSolve(Problem, PetscBool *converged);
/* Collective: the results at the converged state X (energy, gradient norm,
   reactions, each term's results). */
PetscErrorCode ProblemPostProcess(Problem, Vec X, PetscBool converged);
/* Collective: prints each term's report of ProblemPostProcess. */
PetscErrorCode ProblemView(Problem);
PetscErrorCode ProblemCheckUnusedOptions(Problem, PetscBool final);
PetscErrorCode ProblemTaylorTest(Problem);
/* Collective: the reaction of every Dirichlet condition at X (each body's bc[].reaction). */
PetscErrorCode ProblemComputeReactions(Problem, Vec X);
/* The solve's stages (load steps, penalty continuation, cutbacks) from X0 or
   rest: its TAO iterations and reason (problem.c). */
PetscErrorCode ProblemSolveStaged(Problem, PetscInt *its, TaoConvergedReason *reason);
/* Force control (forcecontrol.c): the controlled components found, each
   group's reaction equal to its force, by the type -force_control_type
   names. */
PetscErrorCode ProblemCollectControls(Problem);
PetscErrorCode ProblemSolveControlled(Problem, PetscInt *its, TaoConvergedReason *reason);
/* -force_control_type outer (forceouter.c): a solve of ProblemSolveStaged for each trial. */
PetscErrorCode ProblemSolveControlledOuter(Problem, PetscInt *its, TaoConvergedReason *reason);
/* Coupled force control (forcecontrol.c): the border of the Hessian (after
   the stiffness's assembly); the controls' displacements from X into the
   bodies' conditions (in ProblemScatterToBodies); their work -F U and
   gradient R - F added to an evaluation of X (after ProblemEvaluate). */
PetscErrorCode ProblemSetUpControlBorder(Problem);
PetscErrorCode ProblemSetControlDisplacements(Problem, Vec X);
PetscErrorCode ProblemAddControlWork(Problem, PetscReal *f, Vec G);
/* The scene's largest force at the last evaluation (every load's resultant, force control's force, Dirichlet group's reaction). */
PetscErrorCode ProblemControlSceneForce(Problem, PetscReal *S);
/* Coupled force control: penalty continuation where the user chose none (after the terms' set-up). */
PetscErrorCode ProblemSetControlContinuation(Problem);
/* The force control types by name (-force_control_type): coupled, outer. */
extern PetscFunctionList ForceControlList;
PetscErrorCode           ForceControlRegisterAll(void);
PetscErrorCode ProblemDestroy(Problem *);
