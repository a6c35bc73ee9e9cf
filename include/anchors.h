#pragma once
/* A body held by contact (anchors.c): anchors the rigid motions its
   Dirichlet conditions leave free (in BodySetUp, before the section is made). */
#include "bodycore.h"

PetscErrorCode BodyAddAnchors(Body);
