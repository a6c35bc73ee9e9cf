#pragma once
#include <petscksp.h>

/* Newton steps through the Schur complement on the contact surfaces: a PCSHELL
   for the Newton KSP that factors the elastic stiffness K once (MUMPS, with
   the surface dofs as its Schur block) and, per step, only the dense Schur
   block plus the contact Hessian (schur.c). One rank. exact: whether the
   Hessian has its second-order term (read at each step: then it may be
   indefinite). Assumption: K does not depend on u. */
PetscErrorCode ContactSchurPCSetUp(PC, Mat K, IS surface, const PetscBool *exact);
