#pragma once
#include <petscksp.h>

/* The Newton step where it chooses, at each Hessian, between the bodies'
   stiffness at rest and a neohookean body's tangent (tangentswitch.c; the
   problem chooses by the iteration, -tangent_at_rest_its): a
   PCSHELL over two preconditioners of the same operator, rest (the Schur
   step, K condensed once) and full (a factorisation of the whole Hessian),
   applying the one *full names; each is set up only when applied. Takes a
   reference to rest and full. */
PetscErrorCode ContactTangentSwitchPCSetUp(PC pc, PC rest, PC full, const PetscBool *full_in_use);
