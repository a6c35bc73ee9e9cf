#pragma once
#include "energyterm.h"

/* A contact pair as the scene declares it, whatever the formulation: one
   surface (a Gmsh physical curve) on each of two bodies, the penalty, and the
   Hertz comparison or mirror symmetry the report applies (contactpair.c).
   Formulations are energy terms created by name from this description
   (-contact_formulation, registered in ContactFormulationList). */
typedef struct {
  char      name[CONTACT_NAME_LEN], formulation[CONTACT_NAME_LEN];
  PetscInt  body[2];
  char      group[2][CONTACT_NAME_LEN];
  PetscReal kp;           /* the scene's penalty k_p */
  PetscInt  nqp;          /* Gauss points per slave edge (-contact_quadrature_points) */
  PetscReal blend;        /* -contact_blend: fraction of a master edge; < 0: the formulation's default */
  PetscBool hertz;        /* compare with Hertz: radii of the two surfaces (0: flat), E*, R* */
  PetscReal radii[2], Estar, Rstar;
  PetscBool mirror;       /* the scene is the half y >= mirrorY of a symmetric model */
  PetscReal mirrorY;
} ContactPairSpec;

typedef PetscErrorCode (*ContactFormulationCreate)(const ContactPairSpec *, EnergyTerm);
extern PetscFunctionList ContactFormulationList;
PetscErrorCode ContactFormulationRegister(const char name[], ContactFormulationCreate);
PetscErrorCode ContactFormulationRegisterAll(void);
PetscErrorCode ContactFormulationFinalize(void);

/* Reads -contact_pairs and each pair's options, and creates each pair's energy
   term in its formulation (at most maxTerms), Gauss-Newton Hessian to start. */
PetscErrorCode ContactPairsCreateFromOptions(MPI_Comm, PetscInt nbodies, Body bodies[], PetscInt maxTerms, PetscInt *nterms, EnergyTerm terms[]);

/* The formulations (one file each). */
PetscErrorCode ContactTermCreate_GPTS(const ContactPairSpec *, EnergyTerm);
PetscErrorCode ContactTermCreate_Mortar(const ContactPairSpec *, EnergyTerm);
