#pragma once
#include "body.h"

/* An energy term beside the bodies' elastic energy (a contact pair in one
   formulation or another). It reads the bodies' local displacement vectors,
   adds into their local gradients and into the joined Hessian; after the
   solve it computes its results from the converged state and prints and
   writes them. The problem uses a term only through the functions below;
   only the term's own file knows its data. */
typedef struct _n_EnergyTerm *EnergyTerm;

typedef struct {
  PetscErrorCode (*setup)(EnergyTerm, Body[]);
  PetscErrorCode (*energygradient)(EnergyTerm, Body[], PetscReal *energy);
  PetscErrorCode (*hessian)(EnergyTerm, Body[], Mat H);
  PetscErrorCode (*getdofs)(EnergyTerm, PetscInt *n, PetscInt **idx);
  PetscErrorCode (*setpenaltyfactor)(EnergyTerm, PetscReal);
  PetscErrorCode (*getpenaltystiffness)(EnergyTerm, PetscReal *);
  PetscErrorCode (*sethessianexact)(EnergyTerm, PetscBool);
  PetscErrorCode (*postprocess)(EnergyTerm, Body[]);
  PetscErrorCode (*view)(EnergyTerm, Body[]);
  PetscErrorCode (*writejson)(EnergyTerm, Body[], FILE *, PetscBool summary);
  PetscErrorCode (*writehdf5)(EnergyTerm, Body[], PetscViewer);
  PetscErrorCode (*writexdmf)(EnergyTerm, Body[], FILE *, const char h5[]);
  PetscErrorCode (*getprofile)(EnergyTerm, PetscInt side, PetscInt *n, PetscReal **s, PetscReal **p, PetscReal **w, PetscReal force[2]);
  PetscErrorCode (*diagnose)(EnergyTerm, size_t, char[]);
  PetscErrorCode (*destroy)(EnergyTerm);
} EnergyTermOps;

struct _n_EnergyTerm {
  char          name[CONTACT_NAME_LEN], type[CONTACT_NAME_LEN];
  MPI_Comm      comm;
  PetscBool     couples[CONTACT_MAX_BODIES]; /* bodies whose motion the term resists */
  void         *data;                        /* the implementation's, opaque to everyone else */
  EnergyTermOps ops;
};

PetscErrorCode EnergyTermCreate(MPI_Comm, const char name[], EnergyTerm *);
PetscErrorCode EnergyTermDestroy(EnergyTerm *);
/* Collective: builds what the term needs once the bodies are set up. */
PetscErrorCode EnergyTermSetUp(EnergyTerm, Body[]);
/* Adds the term's gradient into the bodies' local gradients; its energy on this rank. */
PetscErrorCode EnergyTermComputeEnergyGradient(EnergyTerm, Body[], PetscReal *energy);
/* Adds the term's Hessian into H (inside the block of EnergyTermGetDofs). */
PetscErrorCode EnergyTermComputeHessian(EnergyTerm, Body[], Mat H);
/* Indices in the joined vector of the rows and columns the Hessian touches
   (every rank gets all of them; PetscFree the array). */
PetscErrorCode EnergyTermGetDofs(EnergyTerm, PetscInt *n, PetscInt **idx);
/* Continuation: the term's penalty times factor. */
PetscErrorCode EnergyTermSetPenaltyFactor(EnergyTerm, PetscReal factor);
/* After the set-up: the penalty's stiffness against the bodies', k_p h / E*
   (0 for a term without a penalty). */
PetscErrorCode EnergyTermGetPenaltyStiffness(EnergyTerm, PetscReal *stiffness);
/* Adds the second-order part to the Hessian (or not). */
PetscErrorCode EnergyTermSetHessianExact(EnergyTerm, PetscBool);
/* Collective: the term's results from the state in the bodies' local vectors. */
PetscErrorCode EnergyTermPostProcess(EnergyTerm, Body[]);
/* Collective: prints the results of EnergyTermPostProcess. */
PetscErrorCode EnergyTermView(EnergyTerm, Body[]);
/* Rank 0: the results as JSON members; summary: the figures a run is known by, at top level. */
PetscErrorCode EnergyTermWriteJSON(EnergyTerm, Body[], FILE *, PetscBool summary);
/* Collective: the results into an open HDF5 viewer. */
PetscErrorCode EnergyTermWriteHDF5(EnergyTerm, Body[], PetscViewer);
/* Rank 0: XDMF grids of what EnergyTermWriteHDF5 wrote into the file h5 (its
   name as the XDMF file refers to it). */
PetscErrorCode EnergyTermWriteXDMF(EnergyTerm, Body[], FILE *, const char h5[]);
/* Rank 0, after EnergyTermPostProcess: the pressure profile of the term's
   one-sided surface side (0 or 1), n samples sorted by arc position s with
   their pressure p and weight w (PetscFree each; n = 0 where the surface is
   not a slave, whose profile is transferred, or the term is no contact), and
   the contact force it transmits (x and y; its norm is the force P). */
PetscErrorCode EnergyTermGetProfile(EnergyTerm, PetscInt side, PetscInt *n, PetscReal **s, PetscReal **p, PetscReal **w, PetscReal force[2]);
/* After the post-processing: why the term may have kept the solve from converging, or an empty string. */
PetscErrorCode EnergyTermDiagnose(EnergyTerm, size_t n, char why[]);
