#pragma once
/* The element loop (element.c), written once for any dimension: per cell,
   the nodal displacements u[nb][dim], the displacement gradient H (3 x 3,
   material.h) at each quadrature point, the material's pointwise kernels
   there, and their contraction with the basis into the cell's energy,
   gradient and tangent. body.c and fields.c call it for every element
   quantity; no material assembles an element matrix. */
#include "bodycore.h"

/* The largest element: Hex27 (27 nodes) in 3D, 81 dofs. */
#define ELEMENT_MAX_NODES 27
#define ELEMENT_MAX_DOFS  (3 * ELEMENT_MAX_NODES)

/* u[a*dim+i]: component i of cell c's node a in the local array x (NULL: zero). */
void ElementGather(Body, PetscInt c, const PetscScalar x[], PetscReal u[]);
/* H[i*3+J] = sum_a u[a*dim+i] dN[a*dim+J] for i, J < dim, the rest zero:
   the gradient at a point of nb nodal values u with the basis gradients dN. */
void ElementFormGradient(PetscInt dim, PetscInt nb, const PetscReal u[], const PetscReal dN[], PetscReal H[9]);
/* At quadrature point iq of cell c with nodal values u: the displacement
   uq[dim] (NULL: not asked) and H, with, in axisymmetry, H[8] = u_r / r. */
void ElementPointGradient(Body, PetscInt c, PetscInt iq, const PetscReal u[], PetscReal uq[], PetscReal H[9]);
/* Cell c's energy at the displacement x (a local array), added into *e,
   and its gradient, added into the local array g, with the exact
   solution's body force if the body has one. Returns PETSC_FALSE at the
   first quadrature point where the material is inverted (its index in
   *iqBad): *e and g then have the points before it. */
PetscBool ElementAddEnergyGradient(Body, PetscInt c, const PetscScalar x[], PetscReal *e, PetscScalar g[], PetscInt *iqBad);
/* Cell c's tangent K[n][n], n = dim nb, full and symmetric, at the nodal
   displacements u (NULL: at rest). */
void ElementTangent(Body, PetscInt c, const PetscReal u[], PetscScalar K[]);
