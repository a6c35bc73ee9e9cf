#pragma once
#include "subdomain.h"

/* Newton steps through the Schur complement on the contact surfaces on any
   number of ranks, by substructuring: a PCSHELL for the Newton KSP that
   condenses each rank's subdomain onto its interface and contact-surface dofs
   (MUMPS, sequential, once), the interface once more onto the contact
   surfaces, and per step factors only the dense surface block plus the
   contact Hessian (substructure.c). K: the joined elastic stiffness, whose
   rows on each rank are its bodies' dofs, body b's from offset[b]; sub:
   this rank's subdomain on several ranks (consumed), NULL on one. Assumption:
   K does not depend on u. */
PetscErrorCode ContactSubstructurePCSetUp(PC, Mat K, IS surface, PetscInt nbodies, const PetscInt offset[], Subdomain *sub);
