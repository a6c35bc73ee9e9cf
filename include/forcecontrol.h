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
/* Coupled, at each Hessian (the bodies' local vectors at its X): the columns
   of the controls on a body whose tangent varies (an anchor of a neohookean
   body), K e_k with K the tangent there (tangent) or the stiffness at rest. */
PetscErrorCode ProblemUpdateControlBorder(Problem, PetscBool tangent);
/* Coupled: the controls' displacements from X into the bodies' conditions (in ProblemScatterToBodies). */
PetscErrorCode ProblemSetControlDisplacements(Problem, Vec X);
/* Coupled: their work -F U and gradient R - F added to an evaluation of X (after ProblemEvaluate). */
PetscErrorCode ProblemAddControlWork(Problem, PetscReal *f, Vec G);
/* The scene's largest force at the last evaluation (every load's resultant, force control's force, Dirichlet group's reaction). */
PetscErrorCode ProblemControlSceneForce(Problem, PetscReal *S);
/* Coupled: Y, X's layout, the rest of the displacement run of the controls' displacements in X. */
PetscErrorCode ProblemControlRest(Problem, Vec X, Vec Y);
/* A rigid body's unknowns' border, from the contact's Hessian (rigidbody.h):
   Begin, before the terms' Hessians, zeroes it and lends the bodies its
   columns; End sums it and sets p->fc.B and p->fc.D (the curl of the last
   evaluation, which must be at the Hessian's X, in the rotation's corner). */
/* Control k's reaction at the last evaluation (after the bodies' reactions:
   BodyComputeReactions), its condition's group ("" for a rigid body's unknown
   that no condition controls) and its component: x, y, or rotation (a rigid
   body's, whose unknown is the arc L theta, and reaction the moment over L). */
PetscReal      ProblemControlReaction(Problem, PetscInt k);
const char    *ProblemControlGroup(Problem, PetscInt k);
const char    *ProblemControlComponent(Problem, PetscInt k);
PetscErrorCode ProblemRigidBorderBegin(Problem);
PetscErrorCode ProblemRigidBorderEnd(Problem);
PetscErrorCode ForceControlsDestroy(ForceControls *);
/* -force_control_* ("Force control options"), with their defaults and checks
   (the type among ForceControlList's: after ForceControlRegisterAll). */
PetscErrorCode ForceControlOptionsSetFromOptions(MPI_Comm, ForceControlOptions *);
