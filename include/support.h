#pragma once
#include "bodycore.h"

/* What holds a body that no displacement holds (support.c). */
/* Adds n inward unit normals nrm[n][2] of a contact surface of the body, in
   a pair of friction mu (the contact formulations' set-up). */
PetscErrorCode BodyAddContactNormals(Body, PetscInt n, const PetscReal nrm[], PetscReal mu);
/* Collective, before solving: a body given forces alone (no displacement
   held, no load) whose contacts cannot react them (a force pulling it off
   its contacts, or none at all where its contacts can only push it one way)
   is one line naming the body and the motion nothing holds. */
PetscErrorCode BodyCheckSupport(Body);
/* Whether the body is given forces alone (every Dirichlet component
   force-controlled, or none; no pressure or traction), and then the force
   controls' sum F[k] at the end of each stage k. With held (3D: a
   component some condition holds by a displacement reacts any force along
   its axis, a symmetry plane's roller) such components are marked there
   instead of answering no. */
PetscBool      BodyGivenForcesAlone(const Body, PetscReal F[][3], PetscBool held[3]);
PetscErrorCode BodySupportDestroy(Body);
