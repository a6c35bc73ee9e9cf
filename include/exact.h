#pragma once
#include <petscsys.h>

/* An exact (analytical or manufactured) displacement field with its gradient
   (du[i*2+j] = du_i/dx_j; du[i*3+j] in 3D) and its body force f = -div sigma(u), for patch tests
   and convergence studies (exact.c). */
typedef struct {
  char      name[64];
  PetscReal params[16];
  PetscInt  nparams;
  PetscReal lambda, mu;
  void (*u)(const PetscReal params[], const PetscReal x[], PetscReal u[]);
  void (*du)(const PetscReal params[], const PetscReal x[], PetscReal du[]);
  void (*f)(const PetscReal params[], PetscReal lambda, PetscReal mu, const PetscReal x[], PetscReal f[]);
  /* d2u[(k*2+J)*2+L] = d2u_k/dx_J dx_L, for another material's body force (body.c); NULL: none (lame) */
  void (*d2u)(const PetscReal params[], const PetscReal x[], PetscReal d2u[]);
  PetscBool axisymmetric; /* a solution in r-z (-axisymmetric), else in plane strain */
  PetscInt  dim;          /* 3: a 3D body's (du[i*3+j], d2u[(k*3+J)*3+L]); else 2 */
} ExactSolution;

PetscErrorCode ExactSolutionRegisterAll(void);
PetscErrorCode ExactSolutionSetType(ExactSolution *, const char[]);
/* Once the body's dimension is known: trig's 3D form on a 3D body; a solution of the other dimension refused (body: for the message). */
PetscErrorCode ExactSolutionSetDimension(ExactSolution *, PetscInt dim, const char body[]);
PetscErrorCode ExactSolutionFinalize(void);
extern PetscFunctionList ExactSolutionList;
