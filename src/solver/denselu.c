/* A dense LU factorisation split over the ranks of a communicator.

   The substructured Newton step (substructure.c) factors at every Hessian
   the capacitance matrix I + G_AA C_AA, of order |A| (the surface dofs in
   contact: 3,300 on the quarter Hertz ball at 2e5 dofs), 2/3 |A|^3 flops
   that every rank used to repeat whole. Here the matrix is laid out as
   ScaLAPACK's on a grid of 1 x size ranks, columns cyclic by blocks of NB:
   column j on rank (j / NB) mod size, at local position
   (j / (NB size)) NB + j mod NB. Each rank forms its own columns only,
   pdgetrf factors them (its panels hold every row, so partial pivoting
   searches a column on one rank; the trailing update is split by columns),
   and the factors are gathered whole on every rank. pdgetrf swaps the rows
   of the columns to the left of each panel as getrf does, and its ipiv is
   global row numbers on every rank of the grid's row: the gathered LU and
   ipiv are getrf's, so getrs solves with them unchanged (per step the
   solves are a few, against one factorisation). The order of the
   operations differs from getrf's: the factors agree to round-off. */
#include "denselu.h"

/* BLACS and ScaLAPACK (libscalapack-openmpi, which MUMPS links too; Fortran
   integers are C ints) */
extern int  Csys2blacs_handle(MPI_Comm);
extern void Cfree_blacs_system_handle(int);
extern void Cblacs_gridinit(int *, const char *, int, int);
extern void Cblacs_gridinfo(int, int *, int *, int *, int *);
extern void Cblacs_gridexit(int);
extern void descinit_(int *, const int *, const int *, const int *, const int *, const int *, const int *, const int *, const int *, int *);
extern void pdgetrf_(const int *, const int *, double *, const int *, const int *, const int *, int *, int *);

#define DENSELU_NB 64 /* ScaLAPACK's usual block */

struct _n_DenseLU {
  MPI_Comm     comm;
  PetscMPIInt  size, rank;
  int          handle, ctxt, col; /* BLACS: system handle, grid, this rank's column of the grid */
  PetscInt     n, nloc, cap, capn; /* order; this rank's columns; capacity of a (entries) and of cols, ipiv */
  PetscInt    *cols;              /* [nloc] */
  PetscScalar *a;                 /* [n nloc] */
  PetscInt     capAll;
  PetscScalar *all;               /* [n n] the gathered columns, rank by rank */
  int         *ipiv;              /* [n + NB] pdgetrf's */
};

PetscErrorCode DenseLUCreate(MPI_Comm comm, DenseLU *lu)
{
  DenseLU d;
  int     nprow, npcol, row;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&d));
  d->comm = comm;
  PetscCallMPI(MPI_Comm_size(comm, &d->size));
  PetscCallMPI(MPI_Comm_rank(comm, &d->rank));
  d->handle = Csys2blacs_handle(comm);
  d->ctxt   = d->handle;
  Cblacs_gridinit(&d->ctxt, "Row", 1, (int)d->size);
  Cblacs_gridinfo(d->ctxt, &nprow, &npcol, &row, &d->col);
  PetscCheck(nprow == 1 && npcol == (int)d->size && d->col >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "BLACS grid of 1 x %d ranks not made (got %d x %d)", (int)d->size, nprow, npcol);
  *lu = d;
  PetscFunctionReturn(0);
}

PetscErrorCode DenseLUGetLocalColumns(DenseLU d, PetscInt n, PetscInt *nloc, const PetscInt **cols, PetscScalar **a)
{
  const PetscInt stride = (PetscInt)DENSELU_NB * d->size;

  PetscFunctionBeginUser;
  d->n    = n;
  d->nloc = 0;
  for (PetscInt j0 = (PetscInt)DENSELU_NB * d->col; j0 < n; j0 += stride) d->nloc += PetscMin(DENSELU_NB, n - j0);
  if (n + 1 > d->capn) { /* the arrays of n entries grow with n; a with n nloc */
    PetscCall(PetscFree2(d->cols, d->ipiv));
    d->capn = n + 1;
    PetscCall(PetscMalloc2(d->capn, &d->cols, d->capn + DENSELU_NB, &d->ipiv));
  }
  if (n * d->nloc + 1 > d->cap) {
    PetscCall(PetscFree(d->a));
    d->cap = n * d->nloc + 1;
    PetscCall(PetscMalloc1(d->cap, &d->a));
  }
  d->nloc = 0;
  for (PetscInt j0 = (PetscInt)DENSELU_NB * d->col; j0 < n; j0 += stride)
    for (PetscInt j = j0; j < PetscMin(j0 + DENSELU_NB, n); ++j) d->cols[d->nloc++] = j;
  *nloc = d->nloc;
  *cols = d->cols;
  *a    = d->a;
  PetscFunctionReturn(0);
}

/* pdgetrf on the filled columns, then each rank's columns gathered (rank by
   rank, then put in place: rank q's local column l is column
   ((l / NB) size + q) NB + l mod NB). */
PetscErrorCode DenseLUFactor(DenseLU d, PetscScalar LU[], PetscBLASInt ipiv[])
{
  int          desc[9], n, nb = DENSELU_NB, zero = 0, one = 1, lld, info = 0;
  PetscMPIInt *counts, *displs, len;

  PetscFunctionBeginUser;
  if (!d->n) PetscFunctionReturn(0);
  PetscCall(PetscBLASIntCast(d->n, &n));
  lld = n;
  descinit_(desc, &n, &n, &nb, &nb, &zero, &zero, &d->ctxt, &lld, &info);
  PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "ScaLAPACK descinit: info %d", info);
  pdgetrf_(&n, &n, d->a, &one, &one, desc, d->ipiv, &info);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &info, 1, MPI_INT, MPI_MAX, d->comm));
  PetscCheck(info <= 0, d->comm, PETSC_ERR_LIB, "the surface block of the Hessian is singular (pdgetrf info %d)", info);
  PetscCheck(info == 0, d->comm, PETSC_ERR_LIB, "pdgetrf: argument %d illegal", -info);
  PetscCall(PetscLogFlops(2.0 / 3.0 * (double)d->n * d->n * d->n / d->size));

  if (d->n * d->n > d->capAll) {
    PetscCall(PetscFree(d->all));
    d->capAll = d->n * d->n;
    PetscCall(PetscMalloc1(d->capAll, &d->all));
  }
  PetscCall(PetscMalloc2(d->size, &counts, d->size + 1, &displs));
  PetscCall(PetscMPIIntCast(d->n * d->nloc, &len));
  PetscCallMPI(MPI_Allgather(&len, 1, MPI_INT, counts, 1, MPI_INT, d->comm));
  displs[0] = 0;
  for (PetscMPIInt q = 0; q < d->size; ++q) PetscCall(PetscMPIIntCast((PetscInt)displs[q] + counts[q], &displs[q + 1]));
  PetscCallMPI(MPI_Allgatherv(d->a, len, MPIU_SCALAR, d->all, counts, displs, MPIU_SCALAR, d->comm));
  for (PetscMPIInt q = 0; q < d->size; ++q) {
    const PetscInt nq = counts[q] / d->n;
    for (PetscInt l = 0; l < nq; ++l) {
      const PetscInt j = ((l / DENSELU_NB) * d->size + q) * DENSELU_NB + l % DENSELU_NB;
      PetscCall(PetscArraycpy(LU + j * d->n, d->all + displs[q] + l * d->n, d->n));
    }
  }
  PetscCall(PetscFree2(counts, displs));
  for (PetscInt i = 0; i < d->n; ++i) ipiv[i] = (PetscBLASInt)d->ipiv[i];
  PetscFunctionReturn(0);
}

PetscErrorCode DenseLUDestroy(DenseLU *lu)
{
  DenseLU d = *lu;

  PetscFunctionBeginUser;
  if (!d) PetscFunctionReturn(0);
  Cblacs_gridexit(d->ctxt);
  Cfree_blacs_system_handle(d->handle);
  PetscCall(PetscFree2(d->cols, d->ipiv));
  PetscCall(PetscFree(d->a));
  PetscCall(PetscFree(d->all));
  PetscCall(PetscFree(d));
  *lu = NULL;
  PetscFunctionReturn(0);
}
