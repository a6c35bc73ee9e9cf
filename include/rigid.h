#pragma once
/* A body's rigid motions (rigid.c): the modes themselves, and the algebra
   that counts how many of them its Dirichlet conditions leave free. */
#include "bodycore.h"

/* The rigid modes of the body's dofs: 3 in 2D, 6 in 3D, none for a rigid body (no dofs). */
PetscInt       BodyGetNumRigidModes(Body);
PetscErrorCode BodyAddRigidModes(Body, PetscInt rstart, PetscInt rend, PetscScalar *modes[]);
PetscErrorCode BodyCountFreeRigidModes(Body, PetscInt *nfree);
/* The body's nodes whose free dofs are rows rstart..rend-1 of the joined
   vector: for each, its dim components' rows (-1 where constrained), dim
   entries a node in idx (NULL: only counted); n: how many. A node with every
   component constrained is left out. */
PetscErrorCode BodyGetOwnedNodeRows(Body, PetscInt rstart, PetscInt rend, PetscInt *n, PetscInt idx[]);
/* Adds to the rigid-motion constraint Gram matrix M the row of component c
   fixed at (x, y) (coordinates centred and scaled): (e_c, r_c), r = (-y, x). */
void           BodyRigidGramAddRow(PetscReal M[9], PetscInt c, PetscReal x, PetscReal y);
/* The rank of a rigid-motion constraint Gram matrix (3 x 3: x and y
   translation, rotation), by elimination with full pivoting. */
PetscInt       BodyRigidRank(const PetscReal M[9]);
/* Axisymmetry: the radial translation and the rotation marked held in M. */
void           BodyRigidGramAxisymmetric(Body, PetscReal M[9]);
