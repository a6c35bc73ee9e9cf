#pragma once
#include "subdomain.h"

/* Newton steps through the Schur complement on the contact surfaces on any
   number of ranks, by substructuring: a PCSHELL for the Newton KSP that
   condenses each rank's subdomain onto its interface and contact-surface dofs
   (MUMPS, sequential, once), the interface once more onto the contact
   surfaces, and per step factors only the dense surface block plus the
   contact Hessian (substructure.c). K: the joined elastic stiffness, whose
   rows on each rank are its bodies' dofs, body b's from offset[b]; sub:
   this rank's subdomain on several ranks (consumed), NULL on one; splitLU:
   on several ranks, the order of the capacitance matrix from which the
   ranks share its factorisation (denselu.c). Assumption: K does not depend
   on u. */
PetscErrorCode ContactSubstructurePCSetUp(PC, Mat K, IS surface, PetscInt nbodies, const PetscInt offset[], PetscInt splitLU, Subdomain *sub);
/* Coupled force control's bordered step [H B; B^T D] through the PC of H
   (forceborder.c), where the PC can (the substructuring's does; any other
   leaves *has false and the border falls back on m solves of H): the m
   constant columns B_k, condensed once (SetColumns); per set-up of the PC,
   B^T H^-1 B (m x m, row k column l at k m + l, on every rank) from the
   surfaces alone (GetCoupling); per step, the first half of H^-1 r, giving
   B^T H^-1 r (Condense), then z = H^-1 (r - B dU) (Expand), one solve of H
   in all. Collective. */
PetscErrorCode ContactBorderPCSetColumns(PC, PetscInt m, const Vec B[], PetscBool *has);
PetscErrorCode ContactBorderPCGetCoupling(PC, PetscReal BHB[]);
PetscErrorCode ContactBorderPCCondense(PC, Vec r, PetscReal BHr[]);
PetscErrorCode ContactBorderPCExpand(PC, const PetscReal dU[], Vec z);
