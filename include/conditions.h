#pragma once
/* A body's Dirichlet conditions (conditions.c): the scene's read from the
   options and set up on the mesh, the program's own added through one call,
   and all of them checked against each other and the loads. */
#include "bodycore.h"

/* Dirichlet condition bc (its group name set) from the options under
   -<body>_bc_<group>_ (prefix "<body>_"): components, values, the exact
   solution, controls. */
PetscErrorCode BodyBCSetFromOptions(Body, const char prefix[], BodyBC *bc);
/* Collective, in BodySetUp once the mesh is read: each of the scene's
   conditions gets the label of its physical group (faces and their closure)
   and is imposed on the displacement field. */
PetscErrorCode BodyConditionsSetUp(Body);
/* Adds a Dirichlet condition of the program's own, a copy of bc (its group
   name, label, components, values, controls and forces, anchor flag), and
   imposes it; before the section is made. */
PetscErrorCode BodyAddDirichlet(Body, const BodyBC *bc);
/* The index k of component c among bc's components if bc holds c at point p, else -1. */
PetscErrorCode BodyBCHolds(const BodyBC *bc, PetscInt p, PetscInt c, PetscInt *k);
/* The first Dirichlet condition whose label holds component c at point p:
   its index i and the index k of c among its components (-1, -1: none). */
PetscErrorCode BodyBCHolding(Body, PetscInt p, PetscInt c, PetscInt *i, PetscInt *k);
/* Collective, at the end of BodySetUp: refuses a force-controlled group's
   node that another condition holds in the controlled component, and a load
   acting at a node in a component that a force control holds; warns of a
   load whose part in a component acts only at nodes held in it. */
PetscErrorCode BodyCheckConditions(Body);
