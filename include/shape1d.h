#pragma once
#include <petscsys.h>

/* The quadratic Lagrange shape functions on [-1, 1], nodes at -1, +1, 0:
   the 2D contact surfaces' edges (edge.h) and, as tensor products, the 3D
   Quad9 faces (face3d.c). Inline: they sit in the innermost loops. */
static inline void EdgeShape(PetscReal e, PetscReal N[3], PetscReal dN[3])
{
  N[0]  = 0.5 * e * (e - 1.0);
  N[1]  = 0.5 * e * (e + 1.0);
  N[2]  = 1.0 - e * e;
  dN[0] = e - 0.5;
  dN[1] = e + 0.5;
  dN[2] = -2.0 * e;
}
