#pragma once
/* Dead loads on a body's boundary groups (loads.c). */
#include "bodycore.h"

/* -<body>_load and each group's _traction or _pressure. */
PetscErrorCode BodyLoadsSetFromOptions(Body, const char prefix[], PetscBool help);
/* This rank's edges of load L's group (all, owned or not): their number and points (is NULL if none; ISDestroy). */
PetscErrorCode BodyLoadGetEdges(Body, const BodyLoad *L, PetscInt *n, IS *is);
/* Load L's consistent nodal forces fe[3][2] on boundary edge e, at its nodes pts (corner, corner, mid). */
PetscErrorCode BodyLoadEdgeForces(Body, const BodyLoad *L, PetscInt e, PetscInt pts[3], PetscReal fe[3][2]);
/* Collective: the consistent nodal forces of the loads as they are into F
   (local), and their resultants into each load's force (forceFrom where from). */
PetscErrorCode BodyLoadsAssemble(Body, Vec F, PetscBool from);
/* Collective: the consistent nodal forces of the loads, once the mesh is read. */
PetscErrorCode BodyLoadsSetUp(Body);
/* Adds -f . u (at the load parameter, history.c) to *energy and -f to g (local arrays). */
PetscErrorCode BodyLoadsAddEnergyGradient(Body, const PetscScalar x[], PetscReal *energy, PetscScalar g[]);
