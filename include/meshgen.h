#pragma once
#include <petscsys.h>

/* Runs Gmsh on rank 0 to mesh a .geo file at mesh size h with extra -setnumber
   parameters ("name=value") and an optional size field bgm (a Gmsh view file,
   passed with -bgm; "adapt = 1" too where the .geo uses that name, to turn a
   structured mesh into one that follows the field); the .msh is cached in dir and regenerated when the
   .geo is newer. Writes to a temporary name and renames on success.
   Before meshing, a mesh whose estimated dofs exceed *maxDofs (> 0) is
   refused with one line naming the estimate and the limit (described by
   limit[]); else its estimate is taken off *maxDofs (rank 0). estimateOnly:
   that check alone (for every body before any is meshed), no meshing.
   A .geo that Gmsh cannot read is one line naming it with Gmsh's first
   error and line, before any "parameter never used" (a syntax error can
   hide a use). */
PetscErrorCode MeshGenerate(MPI_Comm, const char body[], const char geo[], PetscReal h, PetscInt nparams, char *params[], const char bgm[], const char dir[], PetscReal *maxDofs, const char limit[], PetscBool estimateOnly, char msh[], size_t len);
/* Reads the $PhysicalNames of a Gmsh file on rank 0 and broadcasts them. */
PetscErrorCode MeshReadPhysicalNames(MPI_Comm, const char msh[], PetscInt *n, char ***names, PetscInt **dims, PetscInt **tags);
