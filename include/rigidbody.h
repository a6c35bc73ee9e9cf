#pragma once
/* A rigid body (rigidbody.c): the geometry of its curves and its rigid
   motion. Its mesh gives only the curves (second-order lines of a Gmsh
   .msh: a .geo with curves and no surface is enough); its motion is a
   translation t and a rotation theta about its reference point c, so that a
   point X of it moves by

       u(X) = t + (R(theta) - I)(X - c),   R(theta) the rotation by theta.

   In this first form the motion is prescribed: the translation's components
   by the body's Dirichlet conditions (any of its groups, -<body>_bc_<group>_
   values), the rotation by -<body>_rigid_rotation (default 0: held), both
   scaled by the load factor. The body has no unknowns, no elastic energy;
   its contact surfaces follow the motion and the contact's force on it
   (and moment about its current reference point) is its reaction. */
#include "bodycore.h"

struct _n_BodyRigid {
  PetscInt   nn;        /* nodes of the curves */
  PetscInt  *ids;       /* [nn] Gmsh node numbers, sorted */
  PetscReal *X;         /* [nn][2] reference coordinates */
  PetscInt   ne;        /* second-order line elements */
  PetscInt  *enodes;    /* [ne][3] node indices: the ends, then the middle */
  PetscInt  *etag;      /* [ne] physical tag */
  PetscReal  centre[2]; /* reference point c */
  PetscReal  rotation;  /* the rotation at the full load (radians) */
  PetscReal  tFull[2];  /* the translation at the full load (the conditions' values) */
  PetscReal  t[2], theta; /* the motion at the current load factor */
  PetscReal  force[2], moment; /* the contact's force on the body and its moment about c + t, at the last evaluation */
};

/* The rigid options (-<body>_rigid_centre, -<body>_rigid_rotation), in the body's options block's place. */
PetscErrorCode BodyRigidSetFromOptions(Body, const char prefix[]);
/* Collective: reads the curves of b->msh (rank 0, broadcast), the reference
   point, the conditions' translation; b->nlocal = 0. */
PetscErrorCode BodyRigidSetUp(Body);
PetscErrorCode BodyRigidSetLoadFactor(Body, PetscReal);
/* The displacement of the reference point X under the current motion. */
void           BodyRigidDisplacement(const Body, const PetscReal X[2], PetscReal u[2]);
/* Zeroes the force and moment (before an evaluation). */
void           BodyRigidZeroForce(Body);
/* Adds the gradient g[n][2] at the nodes of reference coordinates X[n][2]
   (summed over ranks) to the body's force and moment. */
void           BodyRigidAddForce(Body, PetscInt n, const PetscReal X[], const PetscReal g[]);
/* The conditions' reactions: each group's held components' share of the force (the whole force). */
PetscErrorCode BodyRigidComputeReactions(Body);
PetscErrorCode BodyRigidDestroy(Body);
/* Whether the body's lines close on themselves (every corner on two lines): it is then the region they enclose. */
PetscBool      BodyRigidClosed(const Body);
/* Whether the reference point p lies inside the region the lines enclose (even-odd rule; meaningful where BodyRigidClosed). */
PetscBool      BodyRigidInside(const Body, const PetscReal p[2]);
/* The line elements of physical tag: their count, and (PetscFree) their indices. */
PetscErrorCode BodyRigidGroupEdges(Body, PetscInt tag, PetscInt *n, PetscInt **edges);
