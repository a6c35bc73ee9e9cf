#pragma once
#include "problemtypes.h"

/* The Hessian bordered by coupled force controls (forceborder.c): a MATSHELL
   of X's size over the bodies' Hessian Hin (Xb's layout) and the controls'
   border, p->fc.B and p->fc.D; with a KSP kin that solves Hin, a PCSHELL
   that solves the bordered system by eliminating the controls: one solve of
   kin per application, and m per set-up of Hin unless kin's PC eliminates
   the border from the contact surfaces itself (the substructuring's;
   ContactBorderPCSetColumns). */
PetscErrorCode ForceBorderMatCreate(Problem, Mat Hin, KSP kin, Mat *M);
/* pc: the bordered solve of M (created by ForceBorderMatCreate with a KSP). */
PetscErrorCode ForceBorderPCSetUp(Mat M, PC pc);
