#pragma once
#include <petscsys.h>
#include <petscblaslapack.h>

/* The LU factorisation with partial pivoting of a dense n x n matrix shared
   out by columns over the ranks of a communicator: each rank forms the
   columns it is given, ScaLAPACK factors them together (pdgetrf, a 1 x size
   grid, columns cyclic by blocks), and every rank receives the factors whole
   in LAPACK's layout (getrf's LU and ipiv, for getrs) (denselu.c). The
   factorisation's flops are split; its result is getrf's up to round-off. */
typedef struct _n_DenseLU *DenseLU;

PetscErrorCode DenseLUCreate(MPI_Comm, DenseLU *);
/* The order n (the next DenseLUFactor's); the columns this rank forms: nloc,
   their indices in the matrix (ascending), and the array to fill with them
   (n x nloc, by columns, leading dimension n). */
PetscErrorCode DenseLUGetLocalColumns(DenseLU, PetscInt n, PetscInt *nloc, const PetscInt **cols, PetscScalar **a);
/* Factors the columns the ranks filled; LU (n x n, by columns) and ipiv (n)
   whole on every rank. Collective; a singular matrix is reported on every
   rank. */
PetscErrorCode DenseLUFactor(DenseLU, PetscScalar LU[], PetscBLASInt ipiv[]);
PetscErrorCode DenseLUDestroy(DenseLU *);
