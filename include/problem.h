#pragma once
#include "problemtypes.h"

/* The assembled system (problem.c): the life of a problem, its layout, the
   energy, gradient, Hessian and reactions of X, and the results at the
   solution. The solve (solve.c) and its strategies sit above it. */

/* The life of a problem: Create, SetFromOptions (reads the configuration,
   config.h, and the bodies' options, and nothing else), GenerateMeshes (each body's mesh, sizes
   checked first), AddTerm (the contact terms, created by the caller), SetUp,
   Solve (solve.c), PostProcess, View, Destroy. */
/* cfg: the configuration, read (config.h); the problem borrows it, and its
   creator destroys it after the problem (run.c). */
PetscErrorCode ProblemCreate(MPI_Comm, SolverConfig cfg, Problem *);
/* Collective: the schedule the configuration gives, and the bodies it names
   with their options. */
PetscErrorCode ProblemSetFromOptions(Problem);
/* The options of this file's concerns, each with its defaults and checks
   (config.h): -scene, -bodies, -axisymmetric and the meshing's ("Contact
   scene options"); -taylor_* ("Taylor test options"); -contact_hessian*
   ("Contact Hessian options"). */
PetscErrorCode SceneOptionsSetFromOptions(MPI_Comm, SceneOptions *);
PetscErrorCode TaylorOptionsSetFromOptions(MPI_Comm, TaylorOptions *);
PetscErrorCode HessianOptionsSetFromOptions(MPI_Comm, HessianOptions *);
/* Collective: generates every body's mesh (with its size field, if one was
   set by BodySetSizeField), refusing one above -max_dofs before any is made. */
PetscErrorCode ProblemGenerateMeshes(Problem);
/* Adds an energy term; the problem takes the reference and destroys it. */
PetscErrorCode ProblemAddTerm(Problem, EnergyTerm);
/* The scene's dimension, 2 or 3 (its bodies agree: ProblemSetUp checks it); 2 with no body. */
PetscInt ProblemGetDimension(Problem);
PetscErrorCode ProblemGetPenaltyStiffness(Problem, PetscReal *stiff);
PetscErrorCode ProblemSetNewtonContinuation(Problem);
/* The first iterate of ProblemSolve (after ProblemSetUp; referenced). */
PetscErrorCode ProblemSetInitialGuess(Problem, Vec X0);
PetscErrorCode ProblemSetUp(Problem);
/* Pi(X) and its gradient G (the bodies' and the terms' parts; not the
   controls' work), and the energy of each part if parts is given. */
PetscErrorCode ProblemEvaluate(Problem, Vec X, PetscReal *f, Vec G, PetscReal parts[]);
PetscErrorCode ProblemComputeObjectiveGradient(Tao, Vec, PetscReal *, Vec, void *);
PetscErrorCode ProblemComputeHessian(Tao, Vec, Mat, Mat, void *);
/* -contact_hessian auto: the gradient norm the switch to the exact Hessian
   is relative to (-1: the first Hessian's of each TAO solve). */
PetscErrorCode ProblemSetHessianSwitchReference(Problem, PetscReal g0);
/* Whether a body's tangent depends on u (a neohookean body): K is then
   reassembled at every Hessian, and the steps that condense it once (the
   Schur step, L-BFGS's contact H0) do not apply. */
PetscBool      ProblemTangentVaries(Problem);
/* Whether the Hessian takes the bodies' tangent at X: a body's tangent
   varies and -tangent_at_rest is not given. Otherwise K, the stiffness at
   rest assembled once, stands for it (exact for linear bodies; for a
   neohookean body a modified Newton step and L-BFGS's contact H0), and the
   steps that condense it once apply. */
PetscBool      ProblemTangentReassembled(Problem);
/* Whether Newton's step may choose between the stiffness at rest and a
   neohookean body's tangent at each Hessian (-tangent_at_rest not given). */
PetscBool      ProblemTangentChosen(Problem);
/* P = K + the terms' Hessians at X, in their current order (exact or Gauss-Newton). */
PetscErrorCode ProblemAssembleHessian(Problem, Vec X, Mat P);
/* Collective: puts every body's conditions and loads at load parameter
   lambda in [0, -load_stages] (history.c). */
PetscErrorCode ProblemSetLoad(Problem, PetscReal lambda);
/* Sets every body's local vector (Dirichlet values inserted) from X. */
PetscErrorCode ProblemScatterToBodies(Problem, Vec X);
/* G (the joined layout) = the bodies' local gradients Gl summed into their dofs (a rigid body's unknowns left out). */
PetscErrorCode ProblemGatherGradient(Problem, Vec G);
/* ||f_c||, the contacts' nodal forces at X (the terms' gradient alone; 0 without terms): -stop_force_rtol's measure (forcestop.c). */
PetscErrorCode ProblemContactForceNorm(Problem, Vec X, PetscReal *fc);
/* Collective: the results at the converged state X (energy, gradient norm,
   reactions, each term's results). */
PetscErrorCode ProblemPostProcess(Problem, Vec X, PetscBool converged);
/* Collective: prints each term's report of ProblemPostProcess. */
PetscErrorCode ProblemView(Problem);
PetscErrorCode ProblemCheckUnusedOptions(Problem, PetscBool final);
PetscErrorCode ProblemTaylorTest(Problem);
/* Collective: the reaction of every Dirichlet condition at X (each body's bc[].reaction). */
PetscErrorCode ProblemComputeReactions(Problem, Vec X);
PetscErrorCode ProblemDestroy(Problem *);
