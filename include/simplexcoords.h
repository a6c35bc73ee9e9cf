#pragma once
#include <petscdmplex.h>

/* A 3D simplicial mesh's cellwise second-order coordinates (PETSc's Gmsh
   reader's) rewritten in each cell's closure vertex order, so that the
   mesh is conforming for elements whose nodes follow the closure
   (simplexcoords.c). Serial: before the mesh is distributed (a rank
   without cells does nothing). name, file: for messages. */
PetscErrorCode MeshSimplexCoordinatesInCellOrder(DM dm, const char name[], const char file[]);
