/* The names the problem's options choose among: the enumerations' names
   (-lmvm_h0, -newton_schur_type, -contact_hessian) and the list of force
   control types (-force_control_type), which problem.c reads and
   forcesolve.c fills. Beside the types of problemtypes.h, below every file
   that reads them. */
#include "problemtypes.h"

const char *const H0Types[]      = {"none", "elastic", "contact", "H0Type", "H0_", NULL};
const char *const SchurTypes[]   = {"substructure", "mumps", "SchurType", "SCHUR_", NULL};
const char *const HessianTypes[] = {"gauss_newton", "exact", "auto", "HessianType", "HESSIAN_", NULL};

PetscFunctionList ForceControlList = NULL;
