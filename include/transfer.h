#pragma once
/* A body's displacement carried from one of its meshes to another (transfer.c). */
#include "bodycore.h"

/* Collective: the displacement U (a local vector of from, set up) at the
   nodes of to (the same body on another mesh, set up) that this rank owns
   and solves for, inserted into X at to->l2b's indices (a vector of the
   joined numbering to belongs to; constrained components are left alone).
   X is not assembled: the caller assembles it once every body is in. */
PetscErrorCode BodyTransferDisplacement(Body from, Vec U, Body to, Vec X);
