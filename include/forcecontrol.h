#pragma once
#include "problemtypes.h"

/* Force control in the assembled system (forcecontrol.c): the controlled
   components found, the border of the Hessian, the controls' displacements
   into the bodies' conditions and their work added to an evaluation. The
   solves under force control are forcesolve.c's. */
/* Collective, at the set-up: the controlled components, and whether they are coupled. */
PetscErrorCode ProblemCollectControls(Problem);
/* Coupled: the border of the Hessian, p->fc.B and p->fc.D (after the stiffness's assembly). */
PetscErrorCode ProblemSetUpControlBorder(Problem);
/* Coupled: the controls' displacements from X into the bodies' conditions (in ProblemScatterToBodies). */
PetscErrorCode ProblemSetControlDisplacements(Problem, Vec X);
/* Coupled: their work -F U and gradient R - F added to an evaluation of X (after ProblemEvaluate). */
PetscErrorCode ProblemAddControlWork(Problem, PetscReal *f, Vec G);
/* The scene's largest force at the last evaluation (every load's resultant, force control's force, Dirichlet group's reaction). */
PetscErrorCode ProblemControlSceneForce(Problem, PetscReal *S);
/* Coupled: Y, X's layout, the rest of the displacement run of the controls' displacements in X. */
PetscErrorCode ProblemControlRest(Problem, Vec X, Vec Y);
PetscErrorCode ForceControlsDestroy(ForceControls *);
