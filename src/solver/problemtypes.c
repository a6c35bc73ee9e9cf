/* The list of force control types (-force_control_type), which
   forcecontrol.c reads and forcesolve.c fills. Beside the types of
   problemtypes.h, below every file that reads them. */
#include "problemtypes.h"

PetscFunctionList ForceControlList = NULL;
