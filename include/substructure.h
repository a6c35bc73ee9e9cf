#pragma once
#include "problem.h"

/* Newton steps through the Schur complement on the contact surfaces on any
   number of ranks, by substructuring: a PCSHELL for the Newton KSP that
   condenses each rank's subdomain onto its interface and contact-surface dofs
   (MUMPS, sequential, once), the interface once more onto the contact
   surfaces, and per step factors only the dense surface block plus the
   contact Hessian (substructure.c). */
PetscErrorCode ContactSubstructurePCSetUp(Problem, PC);
