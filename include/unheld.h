#pragma once
#include <petscsys.h>

#define CONTACT_MAX_CONTROLS 8 /* the most force-controlled components, anchors included */

/* The directions of the anchors' displacements that the contact does not
   hold, frozen where their residual is within the allowance (unheld.c):
   coupled force control's state for bodies held by contact. */
typedef struct {
  PetscInt  m;                 /* the controls, anchors among them */
  PetscBool anchor[CONTACT_MAX_CONTROLS];
  PetscReal kref[CONTACT_MAX_CONTROLS];  /* an anchor: a motion stiffer than this is held by the contact */
  PetscReal raw[CONTACT_MAX_CONTROLS];   /* the controls' gradient R - F at the last evaluation, before the projection */
  PetscReal allowance;         /* the residual an unheld direction may keep: UNHELD_NEUTRAL times the scene's largest force there */
  PetscInt  n;                 /* the frozen directions, projected out of every gradient from now on */
  PetscReal V[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS]; /* their unit vectors in the controls' space (column j: V[j m + k]) */
  PetscInt  nc;                /* the directions the step has no part along: these and the last gradient's (orthonormal) */
  PetscReal Vc[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS];
} Unheld;

PetscErrorCode UnheldSetUp(Unheld *, PetscInt m, const PetscBool anchor[], const PetscReal kref[]);
PetscBool      UnheldAny(const Unheld *);
/* g: the controls' gradient R - F; keeps it as raw and projects the frozen directions out of g. */
PetscErrorCode UnheldSetGradient(Unheld *, PetscReal sceneForce, PetscReal g[]);
/* S: the controls' stiffness through the scene (m x m, symmetric): freezes the
   anchors' directions softer than kref whose raw residual is within the allowance. */
PetscErrorCode UnheldUpdate(Unheld *, const PetscReal S[]);
/* A (m x m) and r: the controls' step system A dU = r; afterwards P A P + a V V^T and P r,
   whose solution has no part along a frozen direction (a: A's largest diagonal entry). */
void UnheldConstrain(const Unheld *, PetscReal A[], PetscReal r[]);
