#pragma once
#include "contactspec.h"

/* A 3D pair's figures as the report gives them (report3d.c): the whole
   model's force and contact area where the scene is a symmetric part of it
   (-contact_<pair>_symmetry), the contact radius from the area and from the
   pressure's second moment, the peak pressure, and with
   -contact_<pair>_hertz_radii Hertz's a and p0 beside them. */
typedef struct {
  PetscReal share;     /* the whole model over the scene's part: 2^(symmetry planes) */
  PetscReal force[3];  /* the whole model's force on the pair's first body */
  PetscReal P;         /* its norm */
  PetscReal normal[3]; /* its direction: r is measured in the plane normal to it */
  PetscReal centre[3]; /* the pressure's centroid (reference), on the symmetry planes */
  PetscReal area;      /* the whole model's contact area, sum A_j over the nodes in contact */
  PetscReal aArea;     /* sqrt(area / pi) */
  PetscReal aMoment;   /* sqrt(5/2 sum p_j A_j r_j^2 / sum p_j A_j) */
  PetscReal pmax;
  PetscReal hertzA, hertzP0, l2err; /* with Hertz radii; l2err the nodal pressures' relative L2 distance (weights A_j) */
} ContactReport3d;

/* From the slave's n nodes (reference positions X[3n], pressures p[n] >= 0,
   weights A[n]) and the scene's force F on the pair's first body. */
void           ContactReport3dCompute(const ContactPairSpec *, PetscInt n, const PetscReal X[], const PetscReal p[], const PetscReal A[], const PetscReal F[3], ContactReport3d *);
PetscErrorCode ContactReport3dView(const ContactReport3d *, const ContactPairSpec *, MPI_Comm);
/* JSON members, each preceded by sep: the summary's (forceKey
   "contact_force") or the pair object's ("P"). */
void           ContactReport3dWriteJSON(const ContactReport3d *, const ContactPairSpec *, FILE *, const char sep[], const char forceKey[]);
