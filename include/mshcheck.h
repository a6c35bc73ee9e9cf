#pragma once
#include <petscsys.h>

/* Checks a Gmsh mesh file (ASCII MSH 2.2 or 4.1) completely on rank 0 before
   PETSc's reader sees it. A fault stops every rank with the same error, whose
   message names the file, the line and what is wrong: PETSC_ERR_FILE_OPEN,
   PETSC_ERR_FILE_READ, or PETSC_ERR_FILE_UNEXPECTED for bad content; a 2D
   mesh off the plane z = 0 (a 3D body's surfaces without its volume)
   PETSC_ERR_USER_INPUT, naming the body. A mesh with 3D elements (Tet10 or
   Hex27) is a 3D body's. */
PetscErrorCode MeshCheckFile(MPI_Comm, const char body[], const char path[]);
/* The same for a rigid body's mesh: its line elements are required, its
   cells (if any) are not used and not checked. */
PetscErrorCode MeshCheckCurvesFile(MPI_Comm, const char body[], const char path[]);
