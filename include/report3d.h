#pragma once
#include "contactspec.h"

/* A 3D pair's figures as the report gives them (report3d.c): the whole
   model's force and contact area where the scene is a symmetric part of it
   (-contact_<pair>_symmetry), the contact radius from the area and from the
   pressure's second moment, the zone's half-axes where it is not a disc,
   the peak pressure, and with
   -contact_<pair>_hertz_radii Hertz's a and p0 beside them. */
typedef struct {
  PetscReal share;     /* the whole model over the scene's part: 2^(symmetry planes) */
  PetscReal force[3];  /* the whole model's force on the pair's first body */
  PetscReal P;         /* its norm */
  PetscReal N;         /* the normal load: P without friction, |force - shear| with it (Hertz's load) */
  PetscReal normal[3]; /* its direction: r is measured in the plane normal to it */
  PetscReal centre[3]; /* the pressure's centroid (reference), on the symmetry planes */
  PetscReal area;      /* the whole model's contact area, sum A_j over the nodes in contact */
  PetscReal aArea;     /* sqrt(area / pi) */
  PetscReal aMoment;   /* sqrt(5/2 sum p_j A_j r_j^2 / sum p_j A_j) */
  PetscReal axes[2];   /* the zone's half-axes from the principal second moments, larger first: sqrt(5 lambda_i) */
  PetscReal axisDir[2][3]; /* their directions (in the plane normal to the normal load) */
  PetscReal pmax;
  PetscReal hertzA, hertzP0, l2err; /* with Hertz radii; l2err the nodal pressures' relative L2 distance (weights A_j) */
  PetscBool friction;                /* a pair with friction: the whole model's figures below */
  PetscReal mu, shear[3];            /* the coefficient; the friction's force on the pair's first body */
  PetscReal Q;                       /* the tangential load |shear| */
  PetscReal stickArea, stickRadius;  /* the stuck nodes' A_j summed, sqrt(stickArea / pi) */
  PetscReal mindlinC;                /* Mindlin's stick radius aMoment (1 - Q/(mu N))^(1/3), 0 at Q >= mu N */
  PetscInt  ncut;                    /* planes not declared symmetric that cut the zone where both surfaces end (ContactReport3dCuts) */
  PetscInt  cutAxis[3];
  PetscReal cutValue[3], cutP[3];    /* the plane x_axis = value; the largest pressure on it over p_max */
} ContactReport3d;

/* From the slave's n nodes (reference positions X[3n], pressures p[n] >= 0,
   weights A[n]) and the scene's force F on the pair's first body; with
   friction (shear not NULL) the friction's part of F, so that r is
   measured from the normal load's axis and Hertz takes the normal load. */
void           ContactReport3dCompute(const ContactPairSpec *, PetscInt n, const PetscReal X[], const PetscReal p[], const PetscReal A[], const PetscReal F[3], const PetscReal shear[], ContactReport3d *);
/* After ContactReport3dCompute: the coordinate planes along the normal
   load, not declared by -contact_<pair>_symmetry, on which the zone ends
   at nodes of the slave's border (sbnd[n]) carrying at least half p_max
   and on which nodes of the master's border lie (Xb[3 nb], reference),
   the zone's other side along that axis not so: a part of a symmetric
   model, cut through its zone, whose report would be the part's
   (ContactReport3dView names the option). */
void           ContactReport3dCuts(const ContactPairSpec *, PetscInt n, const PetscReal X[], const PetscReal p[], const PetscBool sbnd[], PetscInt nb, const PetscReal Xb[], ContactReport3d *);
PetscErrorCode ContactReport3dView(const ContactReport3d *, const ContactPairSpec *, MPI_Comm);
/* With friction, after ContactReport3dCompute: the coefficient and the
   part's stuck area, giving the whole model's stick radius and Mindlin's. */
void           ContactReport3dFriction(PetscReal mu, PetscReal stickArea, ContactReport3d *);
/* The HDF5 attributes of the report a plot reads (names and values; at
   most CONTACT_REPORT3D_ATTRS): the centre and axis r is measured from,
   the zone's half-axes and their directions, and, with friction, the whole model's loads, stick radius, Mindlin's c
   and the shear's direction. Returns their count. */
#define CONTACT_REPORT3D_ATTRS 24
PetscInt       ContactReport3dAttributes(const ContactReport3d *, const char *names[], PetscReal vals[]);
/* JSON members, each preceded by sep: the summary's (forceKey
   "contact_force") or the pair object's ("P"). */
void           ContactReport3dWriteJSON(const ContactReport3d *, const ContactPairSpec *, FILE *, const char sep[], const char forceKey[]);
/* The pair object's friction members (whole_normal_load, whole_tangential_load,
   whole_stick_area, whole_stick_radius, mindlin_c), each preceded by sep. */
void           ContactReport3dWriteFrictionJSON(const ContactReport3d *, FILE *, const char sep[]);
