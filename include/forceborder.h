#pragma once
#include "problemtypes.h"

/* The Hessian bordered by coupled force controls (forceborder.c): a MATSHELL
   of X's size over the bodies' Hessian Hin (Xb's layout) and the controls'
   border, p->fc.B and p->fc.D; with a KSP kin that solves Hin, a PCSHELL
   that solves the bordered system by eliminating the controls (m + 1 solves
   of kin per set-up of Hin, one per application). */
PetscErrorCode ForceBorderMatCreate(Problem, Mat Hin, KSP kin, Mat *M);
/* pc: the bordered solve of M (created by ForceBorderMatCreate with a KSP). */
PetscErrorCode ForceBorderPCSetUp(Mat M, PC pc);
