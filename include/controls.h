#pragma once
/* A body's force controls (controls.c): the components of its motion that
   the solve finds so that a force balances (forcecontrol.c holds them as
   unknowns). An elastic body's are its Dirichlet conditions' force-controlled
   components (anchors.c's anchors included, of force 0); a rigid body's are
   its motion's unknowns (rigidbody.h), each a component force-controlled by a
   condition or held by the contact alone. The body answers for each by its
   condition bc and component c, whatever its kind. */
#include "bodycore.h"

typedef struct {
  PetscInt  bc, c;   /* the condition (an elastic body's; a rigid body's, or -1) and the component: an index into its comps, or a rigid body's x, y, rotation */
  PetscReal force;   /* the force at the full load */
  PetscBool anchor;  /* held by the contact alone: force 0 */
  PetscReal scale;   /* what |R - force| is measured against: |force| and the body's loads (1 where these are 0) */
  PetscReal L;       /* the length a stiffness is scaled by: the body's size (its reference bounding box's diagonal) */
  PetscReal kref;    /* an elastic body's: E (times L in r-z); a motion's: the factor (L in r-z, else 1) on the scene's least E */
  PetscBool motion;  /* a rigid body's motion: no stiffness of its own, its border is the contact's at each Hessian */
} BodyControl;

/* Collective: the body's controls, *n of them (at most 3 CONTACT_MAX_BC + 3). */
PetscErrorCode BodyGetControls(Body, PetscInt *n, BodyControl ctl[]);
/* Sets control (bc, c) to the displacement U (a rotation: the arc L theta). */
PetscErrorCode BodySetControlValue(Body, PetscInt bc, PetscInt c, PetscReal U);
/* Its force at the load parameter last set (history.c), and its reaction
   at the last evaluation (after BodyComputeReactions). */
PetscReal      BodyGetControlForce(Body, PetscInt bc, PetscInt c);
PetscReal      BodyGetControlReaction(Body, PetscInt bc, PetscInt c);
/* Its component's name: x, y (z), or rotation. */
const char    *BodyGetControlComponent(Body, PetscInt bc, PetscInt c);
/* An elastic body's control's column of the border (forcecontrol.c): y = K e
   (a local vector of the body's), e the local vector with 1 on the group's
   nodes in the component and 0 elsewhere, K the stiffness (for a constant
   tangent) or the tangent at Xl (NULL: at rest), and R[j] the reaction of
   each condition j under y; the body's own reactions are left as they were.
   *E: e, kept there for a tangent that varies (made on the first call). */
PetscErrorCode BodyControlColumn(Body, PetscInt bc, PetscInt c, Vec Xl, Vec *E, Vec y, PetscReal R[][3]);
/* Adds the local vector Yl into the body's part g of a joined vector (as its gradient, BodyAddJoinedGradient). */
PetscErrorCode BodyAddLocalToJoined(Body, Vec Yl, PetscScalar g[]);
