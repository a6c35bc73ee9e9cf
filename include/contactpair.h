#pragma once
#include "contactterm.h"

typedef PetscErrorCode (*ContactFormulationCreate)(const ContactPairSpec *, EnergyTerm);
extern PetscFunctionList ContactFormulationList;
PetscErrorCode ContactFormulationRegister(const char name[], ContactFormulationCreate);
PetscErrorCode ContactFormulationRegisterAll(void);
PetscErrorCode ContactFormulationFinalize(void);

/* Reads -contact_pairs and each pair's options, and creates each pair's energy
   term in its formulation (at most maxTerms), Gauss-Newton Hessian to start;
   autoPenalty: whether a pair's penalty is auto. */
PetscErrorCode ContactPairsCreateFromOptions(MPI_Comm, PetscInt nbodies, Body bodies[], PetscInt maxTerms, PetscInt *nterms, EnergyTerm terms[], PetscBool *autoPenalty);
