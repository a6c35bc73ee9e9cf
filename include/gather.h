#pragma once
/* Collective gathers of every rank's reals (gather.c). */
#include <petscsys.h>

/* Every rank's n reals loc[] gathered in rank order on rank 0, or on every
   rank (everyone): *all and *ntot there (PetscFree), NULL and 0 elsewhere. */
PetscErrorCode ContactGatherReals(MPI_Comm comm, PetscBool everyone, PetscInt n, const PetscReal loc[], PetscInt *ntot, PetscReal **all);
