#pragma once
#include "contactspec.h"
#include "energyterm.h"

/* The results of a contact pair at the converged state, whatever the
   formulation (contactreport.c): per surface a pressure profile sorted by arc
   position (a slave's own, or, for nodal samples, a master's transferred from
   the slave), the contact force, and the comparison with Hertz (hertz.c);
   printed, and written to JSON and HDF5. A row: arc position, reference and
   current position, gap, pressure, weight, and for nodal samples the pair's
   contact force on the node (else 0). */
enum { CONTACT_ROW_S, CONTACT_ROW_X, CONTACT_ROW_Y, CONTACT_ROW_XC, CONTACT_ROW_YC, CONTACT_ROW_GAP, CONTACT_ROW_P, CONTACT_ROW_W, CONTACT_ROW_FX, CONTACT_ROW_FY, CONTACT_ROW_COLS };

/* The gap of a sample that nothing faces (a point whose closest point is on
   no edge of the other surface, a node its slave's points do not cover):
   undefined, so NaN in the rows and the HDF5's gap, "unpaired" in the
   report. Not PETSc's PETSC_INFINITY, which is a finite number (the largest
   real over 4, 4.49e307) that would be read as a gap. */
#define CONTACT_GAP_NONE ((PetscReal)NAN)

/* A profile's figures: largest pressure, half-width (half the loaded length,
   to half the spacing of the samples), half-width from the second moment,
   pressure centroid, integral of the pressure, relative L2 distance from
   Hertz, and the contact zone's extent [zone[0], zone[1]] in the samples'
   coordinate (the arc position s, or in r-z the radius r; its ends found as
   a's; 0, 0 without contact). In r-z, a and am are radii about the axis and
   mean a zone's size only where it is a disc about the axis (a ring's is its
   extent). */
typedef struct {
  PetscReal pmax, a, am, sc, ptotal, l2err, zone[2];
} ContactProfileFigures;

typedef struct {
  PetscInt              n;        /* rows (on rank 0; 0 elsewhere) */
  PetscReal            *rows;     /* [n][CONTACT_ROW_COLS], sorted by s */
  PetscReal             force[2]; /* contact force on the surface's body */
  PetscInt              nedges;
  PetscBool             slave; /* the surface acts as slave: its profile is its own (else transferred, or none) */
  ContactProfileFigures fig;
} ContactSide;

typedef struct {
  ContactSide side[2];
  PetscReal   kp, force[2], P, maxPen, hertzA, hertzPmax, femPmax, femA, femAm, l2err;
  PetscReal   zone[2];       /* the contact zone's extent on the pair's first slave surface (its fig.zone) */
  PetscReal   resultant[2]; /* the pair's force: force doubled across a mirror line and cancelled along it; P is its norm */
  PetscReal   hEdge; /* the shorter of the two surfaces' mean reference edge lengths */
  PetscBool   nodal; /* the samples are the slave surface's nodes (else Gauss points) */
  PetscBool   friction;       /* the pair has Coulomb friction (spec->friction > 0) */
  PetscReal   stickHalfWidth; /* with friction: the stick zone's half-width, from the nodes that stick */
  PetscReal   shearForce[2];  /* with friction: its force on the first surface's body (force, resultant and P are the pressure's) */
  PetscReal   normalLoad, tangentialLoad; /* with friction (rank 0): the pair's whole force (normal part and shear) along the contact zone's normal, and across it (P and Q of Cattaneo-Mindlin) */
  PetscReal   mindlinC;       /* with friction and Hertz in plane strain: Mindlin's stick half-width a sqrt(1 - Q/(mu P)) (0: Q >= mu P, full sliding) */
  PetscBool   done;
} ContactReport;

/* Collective: from each rank's rows of each side (any order), the local force
   on each side and the local largest penetration, the pair's results: every
   sum and maximum over ranks is taken here, once. */
PetscErrorCode ContactReportFinish(ContactReport *, const ContactPairSpec *, MPI_Comm, const PetscInt nloc[2], PetscReal *const rows[2], const PetscReal force[2][2], PetscReal maxPen, const PetscReal arcLength[2]);
PetscErrorCode ContactReportView(const ContactReport *, const ContactPairSpec *, Body[], MPI_Comm);
/* Why the pair may keep a solve from converging (an overlap deeper than its edges), or an empty string. */
PetscErrorCode ContactReportDiagnose(const ContactReport *, const ContactPairSpec *, size_t, char[]);
PetscErrorCode ContactReportWriteJSON(const ContactReport *, const ContactPairSpec *, Body[], FILE *, PetscBool summary);
PetscErrorCode ContactReportWriteHDF5(const ContactReport *, const ContactPairSpec *, Body[], PetscViewer);
/* Rank 0: each surface with a profile as a line grid of the XDMF file, on the
   datasets ContactReportWriteHDF5 wrote into h5. */
PetscErrorCode ContactReportWriteXDMF(const ContactReport *, const ContactPairSpec *, Body[], FILE *, const char h5[], PetscBool friction);
PetscErrorCode ContactReportReset(ContactReport *);

/* A pair's Hertz figures as JSON members, each preceded by sep: E_star,
   R_star, hertz_a, hertz_pmax, pressure_l2_error (the 2D and 3D reports'). */
void      ContactHertzJSON(FILE *, const char sep[], const ContactPairSpec *, PetscReal a, PetscReal pmax, PetscReal l2err);
/* Hertz's line contact (plane strain) from the force per unit thickness P:
   half-width a = sqrt(4 P R* / (pi E*)), peak 2 P / (pi a) (hertz.c). */
void      HertzLineContact(PetscReal P, PetscReal Estar, PetscReal Rstar, PetscReal *a, PetscReal *pmax);
/* Hertz's point contact of two spheres from the force P over the whole
   circle: a = (3 P R* / (4 E*))^(1/3), peak 3 P / (2 pi a^2) (hertz.c). */
void      HertzPointContact(PetscReal P, PetscReal Estar, PetscReal Rstar, PetscReal *a, PetscReal *pmax);
/* Hertz's pressure at distance ds from the centre. */
PetscReal HertzPressure(PetscReal pmax, PetscReal a, PetscReal ds);
/* Figures of a profile rows[n] sorted by s (nodal: the samples are nodes;
   axisym: their coordinate is the radius, the centre the axis); l2err
   against Hertz if a > 0 (else NaN). */
void      ContactProfileCompare(PetscInt n, const PetscReal rows[], PetscBool nodal, PetscBool axisym, PetscBool hertz, PetscReal hertzA, PetscReal hertzPmax, ContactProfileFigures *);
