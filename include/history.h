#pragma once
/* A body's load history (history.c): -load_stages S gives every Dirichlet
   value, force control's force and load S end values, and the body's
   conditions and loads are functions of the load parameter lambda in
   [0, S] (stage k from lambda = k - 1 to k, linear between its start and
   its end). */
#include "stagedvalues.h"

/* Collective: puts the body's conditions and loads (a rigid body's motion) at load parameter lambda. */
PetscErrorCode BodySetLoad(Body, PetscReal lambda);
/* Moves Dirichlet condition i's component c (an index into its comps) to
   the value U (a force-controlled component's displacement, the same in
   every stage: scaled by the load factor). */
PetscErrorCode BodySetBCValue(Body, PetscInt i, PetscInt c, PetscReal U);
/* The force of condition i's force-controlled component c at the load parameter last set. */
PetscReal BodyControlForce(Body, PetscInt i, PetscInt c);
/* A rigid body's unknown q's force at the load parameter last set: its
   condition's force where force-controlled, a rotation's -rigid_moment over
   the body's size L where moment-controlled, else 0 (held by the contact). */
PetscReal BodyRigidControlForce(Body, PetscInt q);
/* Load l's resultant at the load parameter last set, into f[dim] (f[3]). */
void BodyLoadResultant(Body, PetscInt l, PetscReal f[3]);
/* Whether anything of the body can push it into a contact: a load, a
   nonzero Dirichlet value (a force control's force included) or an exact
   solution imposed, in any stage. */
PetscBool BodyIsLoaded(Body);
