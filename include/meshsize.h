#pragma once
#include <petscsys.h>

/* About how large a mesh Gmsh will make of a .geo, asked of Gmsh before the
   mesh is made (src/mesh/meshsize.c says how). */
typedef struct {
  double    nodes, elements; /* of the mesh (elements: of the surface); < 0: unknown */
  double    scale;           /* Gmsh's -clscale of the probe that was scaled (1: the mesh itself); 0: the geometry's extent */
  PetscBool kept;            /* the probe was the mesh itself and is now the cached mesh msh */
  PetscBool coarsens;        /* whether the curves' meshes coarsen with -clscale (not where transfinite) */
  int       probes;          /* Gmsh runs it took */
  double    seconds;         /* and their wall time */
} MeshSize;

/* argv: Gmsh's command for the mesh ("gmsh", "-2", options...), up to the
   .geo file, NULL-terminated; h the mesh size it sets. msh: where the mesh is
   cached (a probe that is the mesh itself is kept there, its log beside it). */
PetscErrorCode MeshEstimateSize(char *const argv[], const char geo[], double h, const char msh[], MeshSize *size);
/* "Gmsh's mesh", "Gmsh's mesh at 4 times the size, scaled", ...: where
   size's figures come from, for a message. */
PetscErrorCode MeshSizeSource(const MeshSize *size, char buf[], size_t len);
