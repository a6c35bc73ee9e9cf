/* The materials a body may have, registered by name (-<body>_material):
   linear (elasticity.c, the default) and neohookean (neohookean.c). A new
   material is one file of kernels (material.h) and one line here. */
#include "material.h"

PetscFunctionList MaterialList = NULL;

static PetscErrorCode MaterialGetLinear(const Material **m)
{
  *m = &MaterialLinear;
  return 0;
}

static PetscErrorCode MaterialGetNeoHookean(const Material **m)
{
  *m = &MaterialNeoHookean;
  return 0;
}

PetscErrorCode MaterialRegisterAll(void)
{
  PetscFunctionBeginUser;
  if (MaterialList) PetscFunctionReturn(0);
  PetscCall(PetscFunctionListAdd(&MaterialList, "linear", MaterialGetLinear));
  PetscCall(PetscFunctionListAdd(&MaterialList, "neohookean", MaterialGetNeoHookean));
  PetscFunctionReturn(0);
}

PetscErrorCode MaterialFind(const char name[], const Material **m)
{
  PetscErrorCode (*get)(const Material **) = NULL;

  PetscFunctionBeginUser;
  *m = NULL;
  PetscCall(PetscFunctionListFind(MaterialList, name, &get));
  if (get) PetscCall((*get)(m));
  PetscFunctionReturn(0);
}

PetscErrorCode MaterialFinalize(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&MaterialList));
  PetscFunctionReturn(0);
}
