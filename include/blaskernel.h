#pragma once
#include <petscsys.h>

/* The BLAS kernel the program runs on (blaskernel.c). OpenBLAS picks its
   kernels from the CPU when it loads, and on a CPU newer than the library it
   falls back to its oldest (Prescott): half the speed of the kernels the CPU
   supports. BlasKernelSelect(), first thing in main(), before MPI_Init(),
   chooses the kernel from the CPU's own features where OpenBLAS fell below
   them, or takes -blas_kernel NAME, and if that is not the kernel loaded it
   starts the program again (execv) with OPENBLAS_CORETYPE set, which OpenBLAS
   reads as it loads. OPENBLAS_CORETYPE set by the user is kept (unless
   -blas_kernel is given). Plain C: PETSc and MPI do not exist yet. */
void BlasKernelSelect(int argc, char **argv);

/* -blas_kernel in -help with its default; a name the CPU cannot run, an
   unknown one, or one given where BlasKernelSelect() could not see it
   (PETSC_OPTIONS) is one line, PETSC_ERR_USER_INPUT. */
PetscErrorCode BlasKernelSetFromOptions(MPI_Comm comm);

/* The kernel in use ("Cooperlake", "SkylakeX", ...; "none" where the BLAS
   is not OpenBLAS) and how it was chosen ("OpenBLAS", "cpu", "-blas_kernel",
   "OPENBLAS_CORETYPE"), for the JSON and the -log_view header line. */
const char *BlasKernelName(void);
const char *BlasKernelSource(void);
/* The kernel loaded before the program started again on this one, else "". */
const char *BlasKernelFallback(void);
/* "BLAS: OpenBLAS kernel SkylakeX (the CPU's features, in place of Prescott)" */
PetscErrorCode BlasKernelView(MPI_Comm comm);
