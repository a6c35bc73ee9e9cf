/* The materials a body may have, registered by name (-<body>_material):
   linear (elasticity.c, the default), neohookean (neohookean.c),
   mooneyrivlin (mooneyrivlin.c) and plastic (plasticity.c: J2 plasticity,
   a material with history). A new material is one file (its kernels
   and its options, material.h) and one line here. Here too: the elastic
   constants E and nu, the options of linear and neohookean. */
#include "material.h"
#include "options.h"

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

static PetscErrorCode MaterialGetMooneyRivlin(const Material **m)
{
  *m = &MaterialMooneyRivlin;
  return 0;
}

static PetscErrorCode MaterialGetPlastic(const Material **m)
{
  *m = &MaterialPlastic;
  return 0;
}

PetscErrorCode MaterialElasticConstantsSetFromOptions(MPI_Comm comm, const char prefix[], PetscBool help, PetscReal param[], PetscReal *E, PetscReal *nu)
{
  char      name[64], opt[128];
  PetscBool setE, setNu;
  size_t    len;

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(name, prefix, sizeof(name))); /* the body's name: the prefix without its '_' */
  PetscCall(PetscStrlen(name, &len));
  if (len) name[len - 1] = 0;
  PetscOptionsBegin(comm, prefix, "Elastic constants (-<body>_material linear, neohookean, plastic)", NULL);
  PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-E", "Young's modulus (required)", "required", PETSC_FALSE, E, &setE));
  PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-nu", "Poisson's ratio (required)", "required", PETSC_FALSE, nu, &setNu));
  PetscOptionsEnd();
  if (help) PetscFunctionReturn(0);
  PetscCheck(setE, comm, PETSC_ERR_USER_INPUT, "body %s: -%sE is required", name, prefix);
  PetscCheck(setNu, comm, PETSC_ERR_USER_INPUT, "body %s: -%snu is required", name, prefix);
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sE", prefix));
  PetscCheck(!PetscIsInfOrNanReal(*E), comm, PETSC_ERR_USER_INPUT, "option %s: value %g is not a finite number", opt, (double)*E);
  PetscCheck(*E > 0, comm, PETSC_ERR_USER_INPUT, "option %s: Young's modulus must be > 0, got %g", opt, (double)*E);
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%snu", prefix));
  PetscCheck(!PetscIsInfOrNanReal(*nu), comm, PETSC_ERR_USER_INPUT, "option %s: value %g is not a finite number", opt, (double)*nu);
  PetscCheck(*nu > -1.0 && *nu < 0.5, comm, PETSC_ERR_USER_INPUT, "option %s: Poisson's ratio must be in (-1, 0.5), got %g", opt, (double)*nu);
  /* lambda/mu = 2 nu/(1 - 2 nu) is 9 at nu = 0.45 and grows without bound */
  if (*nu >= 0.45) PetscCall(PetscFPrintf(comm, PETSC_STDERR, "contact: warning: body %s: nu = %g is nearly incompressible (lambda/mu = %.3g); P2/Q2 displacement elements may lock, so stresses and contact pressure converge more slowly\n", name, (double)*nu, (double)(2 * *nu / (1 - 2 * *nu))));
  param[1] = *E / (2.0 * (1.0 + *nu));
  param[0] = *E * *nu / ((1.0 + *nu) * (1.0 - 2.0 * *nu));
  PetscFunctionReturn(0);
}

PetscErrorCode MaterialRegisterAll(void)
{
  PetscFunctionBeginUser;
  if (MaterialList) PetscFunctionReturn(0);
  PetscCall(PetscFunctionListAdd(&MaterialList, "linear", MaterialGetLinear));
  PetscCall(PetscFunctionListAdd(&MaterialList, "neohookean", MaterialGetNeoHookean));
  PetscCall(PetscFunctionListAdd(&MaterialList, "mooneyrivlin", MaterialGetMooneyRivlin));
  PetscCall(PetscFunctionListAdd(&MaterialList, "plastic", MaterialGetPlastic));
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
