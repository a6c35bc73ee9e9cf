#pragma once
#include <petscsys.h>

/* An exact (analytical or manufactured) displacement field with its gradient
   (du[i*2+j] = du_i/dx_j) and its body force f = -div sigma(u), for patch tests
   and convergence studies (exact.c). */
typedef struct {
  char      name[64];
  PetscReal params[16];
  PetscInt  nparams;
  PetscReal lambda, mu;
  void (*u)(const PetscReal params[], const PetscReal x[], PetscReal u[]);
  void (*du)(const PetscReal params[], const PetscReal x[], PetscReal du[]);
  void (*f)(const PetscReal params[], PetscReal lambda, PetscReal mu, const PetscReal x[], PetscReal f[]);
  PetscBool axisymmetric; /* a solution in r-z (-axisymmetric), else in plane strain */
} ExactSolution;

PetscErrorCode ExactSolutionRegisterAll(void);
PetscErrorCode ExactSolutionSetType(ExactSolution *, const char[]);
PetscErrorCode ExactSolutionFinalize(void);
extern PetscFunctionList ExactSolutionList;
