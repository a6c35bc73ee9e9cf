#pragma once
/* The program's configuration, its types (config.h creates and reads it,
   config.c): what the options say, concern by concern, and nothing else.
   Each concern's options are read by one function in the concern's own file, in its own options block (its
   heading in -help), with their defaults and their checks;
   SolverConfigSetFromOptions calls them in order. What the solve later
   derives from them (the schedule, the Newton step's kind, the Hessian in
   force) lives in the Problem. */
#include "contact.h"
#include <petscksp.h>

/* Friction's fixed point on the normal pressure within each load increment
   (staging.c runs it): -contact_friction_lag_rtol, -contact_friction_lag_max_it
   ("Friction lag options"; the problem's configuration, config.h). */
typedef struct {
  PetscReal rtol;  /* a term's lagged quantity (friction's pressure) is converged when its largest change is below this, relative */
  PetscInt  maxIt; /* the most solves of one increment's fixed point */
} FrictionLagOptions;

/* The mesh partitioner (partition.c). */
typedef enum { PARTITION_METIS, PARTITION_PTSCOTCH, PARTITION_SIMPLE } PartitionType;
extern const char *const PartitionTypes[];

/* -partitioner, -partition_view ("Partitioning options"; the problem's configuration, config.h). */
typedef struct {
  PartitionType type;
  PetscBool     view; /* print the cells per rank of each body */
} PartitionOptions;

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

/* The scene and its meshing (problem.c: "Contact scene options"). */
typedef struct {
  char      name[CONTACT_NAME_LEN];       /* -scene */
  char     *bodies[CONTACT_MAX_BODIES];   /* -bodies (with -help and none given: the placeholder <body>) */
  PetscInt  nbodies;
  PetscBool axisymmetric;                 /* -axisymmetric: every body in r-z (axis.c) */
  PetscReal meshSize;                     /* -mesh_size, or -1: each body's own */
  PetscReal maxDofs;                      /* refuse a generated mesh above this many dofs (-max_dofs; 0: from memory, set when meshing) */
  char      meshDir[PETSC_MAX_PATH_LEN];  /* -mesh_dir */
} SceneOptions;

/* The Taylor-remainder check at the solution (problem.c: "Taylor test options"). */
typedef struct {
  PetscBool test;  /* -taylor_test */
  PetscReal scale; /* -taylor_scale */
} TaylorOptions;

/* L-BFGS (lmvm.c: "L-BFGS options"). */
typedef struct {
  H0Type    h0;
  PetscInt  h0Refresh;      /* -lmvm_h0 contact: the H0 recomputed every this many iterations */
  PetscInt  restarts;       /* -lmvm_restarts: the most restarts of an L-BFGS solve whose line search failed */
  PetscReal pairRatio;      /* -lmvm_pair_ratio: a correction pair kept while its curvature is within this factor of H0's */
  PetscReal decrementFloor; /* -lmvm_decrement_floor: a last stage whose line search fails within this factor of the decrement's tolerance ends converged */
  PetscReal decrementRtol;  /* -lmvm_decrement_rtol: the last stage stops on the decrement g'H0^-1 g (0: off, the gradient tolerances; -1: not given, chosen with the solver) */
} LMVMOptions;

/* The Newton step's linear solve and its matrix (newtonstep.c: "Newton step options"). */
typedef struct {
  PetscBool iterative;        /* Newton by CG + GAMG (iterative.c) */
  PetscBool iterativeSet;     /* -newton_iterative given (else chosen by size in 3D: newtonstep.c) */
  PetscInt  iterativeDofs;    /* -newton_iterative_dofs: a 3D scene above this many dofs takes CG + GAMG by default */
  PetscBool schur;            /* Newton through the contact-surface Schur complement */
  PetscBool schurSet;         /* -newton_schur given (else chosen by the surfaces' size in 3D: newtonstep.c) */
  PetscInt  schurSurfaceDofs; /* -newton_schur_surface_dofs: a 3D scene with more contact-surface dofs factors the whole Hessian by default */
  SchurType schurType;
  PetscBool tangentAtRest, tangentAtRestSet; /* -tangent_at_rest: K, the stiffness at rest, in place of a neohookean body's tangent (and whether given) */
  PetscInt  tangentIts;       /* Newton without -tangent_at_rest: K for this many iterations of each solve, then the tangent (-tangent_at_rest_its) */
  PetscBool iterativeNodal;   /* -newton_iterative_nodal: 3D, GAMG aggregates nodes (iterative.c) */
  PetscBool iterativeTwoLevels; /* -newton_iterative_two_levels: 3D, one rank, by nodes: the vertices' level first */
  PetscBool iterativeTwoLevelsSet; /* -newton_iterative_two_levels given (else off with contact: newtonstep.c) */
  PCMGCycleType iterativeCycle; /* -newton_iterative_cycle: by nodes, the multigrid cycle */
  PetscInt  splitLU;            /* -newton_schur_split_lu: on several ranks, the capacitance matrix's LU shared from this order on (substructure.c) */
} NewtonOptions;

/* Load stepping and the load history (schedule.c: "Load stepping options"). */
typedef struct {
  PetscInt  steps;    /* -load_steps: each stage in this many increments */
  PetscInt  stages;   /* -load_stages: the stages of the load history (history.c) */
  PetscInt  cutbacks; /* -load_cutbacks: automatic load cutback, the most a solve may take */
  PetscBool path;     /* -load_path: record each converged load (staging.c), each solved to the final tolerance */
} LoadOptions;

/* Penalty continuation (schedule.c: "Penalty continuation options"). */
typedef struct {
  PetscInt  stages;              /* -penalty_stages */
  PetscReal start;               /* -penalty_start: the first stage's k_p over the scene's */
  PetscBool stagesSet, startSet; /* given by the user (else the solver may choose: schedule.c) */
} PenaltyOptions;

/* When a stage and the solve stop (forcestop.c: "Stopping options"). */
typedef struct {
  PetscReal stageRtol; /* -stage_rtol: the relative decrease of ||g|| that ends an intermediate stage */
  PetscReal forceRtol; /* -stop_force_rtol: the final stop also asks ||g|| <= this ||f_c||, f_c the contacts' nodal forces (0: off) */
} StopOptions;

/* Force control (forcecontrol.c: "Force control options"). */
typedef struct {
  char      type[64];     /* -force_control_type: coupled (the displacements are unknowns of the one minimisation) or outer */
  PetscInt  maxIt;        /* the most solves of its outer iteration (outer), of the solve and its refinements (coupled) */
  PetscReal rtol;         /* |reaction - force| <= this |force| ends it */
  PetscBool rtolSet;      /* given (coupled force control checks it only then) */
  PetscReal step;         /* coupled: the most a Newton step moves a controlled group, times its body's size */
  PetscBool borderSolves; /* coupled: the border eliminated by m solves a Hessian even where the step's PC can do it from the surfaces */
} ForceControlOptions;

/* The contact terms' Hessian (problem.c: "Contact Hessian options"). */
typedef struct {
  HessianType type;       /* -contact_hessian */
  PetscReal   switchRtol; /* auto: exact once ||g|| < switchRtol ||g0|| (-contact_hessian_switch) */
} HessianOptions;

typedef struct _n_SolverConfig *SolverConfig;
struct _n_SolverConfig {
  MPI_Comm            comm;
  SceneOptions        scene;
  PartitionOptions    partition; /* partition.c */
  LMVMOptions         lmvm;
  TaylorOptions       taylor;
  NewtonOptions       newton;
  LoadOptions         load;
  PenaltyOptions      penalty;
  StopOptions         stop;
  FrictionLagOptions  lag; /* friction.c */
  ForceControlOptions control;
  HessianOptions      hessian;
  PetscBool           view; /* -config_view */
};
