#pragma once
#include <petscsys.h>

/* A rigid body's surface node's component among the joined vector's
   indices, as the contact surfaces and formulations write it (2D:
   surface.c, 3D: surface3d.c, mortar3d.c) and the rigid body reads it
   back (rigidbody.c, rigid3d.c): codes below -1, so that a matrix or
   vector insertion leaves them out. */
/* A surface node's component in the joined vector's indices: -2 - (2 j + d), node j of the surface, d its component. */
static inline PetscInt ContactRigidDof(PetscInt j, PetscInt d)
{
  return -2 - (2 * j + d);
}
static inline PetscBool ContactRigidDofDecode(PetscInt i, PetscInt *j, PetscInt *d)
{
  if (i > -2) return PETSC_FALSE;
  *j = (-2 - i) / 2;
  *d = (-2 - i) % 2;
  return PETSC_TRUE;
}
/* A 3D rigid body's surface node's component: -2 - (3 j + d). */
static inline PetscInt ContactRigidDof3(PetscInt j, PetscInt d)
{
  return -2 - (3 * j + d);
}
static inline PetscBool ContactRigidDofDecode3(PetscInt i, PetscInt *j, PetscInt *d)
{
  if (i > -2) return PETSC_FALSE;
  *j = (-2 - i) / 3;
  *d = (-2 - i) % 3;
  return PETSC_TRUE;
}
