#pragma once
#include "problem.h"

/* Newton steps through the Schur complement on the contact surfaces: a PCSHELL
   for the Newton KSP that factors the elastic stiffness once (MUMPS, with the
   surface dofs as its Schur block) and, per step, only the dense Schur block
   plus the contact Hessian (schur.c). One rank. */
PetscErrorCode ContactSchurPCSetUp(Problem, PC);
