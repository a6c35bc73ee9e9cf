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
  /* optional: the Hessian's sparsity, by row (joined indices, every rank the
     whole): rows[n] sorted, row k's columns cols[start[k] .. start[k + 1]) */
  PetscErrorCode (*getpattern)(EnergyTerm, PetscInt *n, PetscInt **rows, PetscInt **start, PetscInt **cols);
  PetscErrorCode (*setpenaltyfactor)(EnergyTerm, PetscReal);
  PetscErrorCode (*getpenaltystiffness)(EnergyTerm, PetscReal *);
  PetscErrorCode (*sethessianexact)(EnergyTerm, PetscBool);
  PetscErrorCode (*postprocess)(EnergyTerm, Body[]);
  PetscErrorCode (*view)(EnergyTerm, Body[]);
  PetscErrorCode (*writejson)(EnergyTerm, Body[], FILE *, PetscBool summary);
  PetscErrorCode (*writehdf5)(EnergyTerm, Body[], PetscViewer);
  PetscErrorCode (*writexdmf)(EnergyTerm, Body[], FILE *, const char h5[], PetscBool friction);
  PetscErrorCode (*getprofile)(EnergyTerm, PetscInt side, PetscInt *n, PetscReal **s, PetscReal **p, PetscReal **w, PetscReal force[2]);
  PetscErrorCode (*diagnose)(EnergyTerm, size_t, char[]);
  PetscErrorCode (*slipstate)(EnergyTerm, PetscInt *stuck, PetscInt *loaded, PetscReal *slip);
  PetscErrorCode (*lag)(EnergyTerm, Body[], PetscReal *change);
  PetscErrorCode (*accept)(EnergyTerm, Body[], PetscReal load);
  PetscErrorCode (*begin)(EnergyTerm);
  PetscErrorCode (*scalebound)(EnergyTerm, PetscReal growth);
  PetscErrorCode (*stickhalfwidth)(EnergyTerm, PetscInt stage, PetscReal *c, PetscBool *has);
  PetscErrorCode (*restore)(EnergyTerm, Body[]);
  PetscErrorCode (*reset)(EnergyTerm, Body[]);
  PetscErrorCode (*destroy)(EnergyTerm);
} EnergyTermOps;

struct _n_EnergyTerm {
  char          name[CONTACT_NAME_LEN], type[CONTACT_NAME_LEN];
  MPI_Comm      comm;
  PetscBool     couples[CONTACT_MAX_BODIES]; /* bodies whose motion the term resists */
  PetscInt      body[2];                     /* a contact pair's two bodies and their surfaces' groups (contactpair.c) */
  char          group[2][CONTACT_NAME_LEN];
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
/* The term's Hessian pattern (ops.getpattern; PetscFree each of rows, start, cols),
   has false where the term gives none (its block is then EnergyTermGetDofs's, dense). */
PetscErrorCode EnergyTermGetPattern(EnergyTerm, PetscBool *has, PetscInt *n, PetscInt **rows, PetscInt **start, PetscInt **cols);
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
   name as the XDMF file refers to it); friction: the scene has friction, so
   every grid carries the friction's fields (xdmf.h). */
PetscErrorCode EnergyTermWriteXDMF(EnergyTerm, Body[], FILE *, const char h5[], PetscBool friction);
/* Rank 0, after EnergyTermPostProcess: the pressure profile of the term's
   one-sided surface side (0 or 1), n samples sorted by arc position s with
   their pressure p and weight w (PetscFree each; n = 0 where the surface is
   not a slave, whose profile is transferred, or the term is no contact), and
   the contact force it transmits (x and y; its norm is the force P). */
PetscErrorCode EnergyTermGetProfile(EnergyTerm, PetscInt side, PetscInt *n, PetscReal **s, PetscReal **p, PetscReal **w, PetscReal force[2]);
/* State across load increments (a friction's slip; none for most terms):
   whether the term has any. A term with state holds some quantity lagged
   within an increment, updated by EnergyTermLag at the bodies' state (the
   solve is repeated until the largest relative change is small: a fixed
   point); EnergyTermAccept records the bodies' state (a converged
   increment, at load parameter load), which EnergyTermBegin makes the
   accepted one as the next increment begins (until then the term's energy
   is still the converged increment's); EnergyTermRestore goes back to the
   accepted state (a cut-back, a failed trial; the bodies hold it again);
   EnergyTermReset goes back to rest (a solve from rest). Each is
   collective, and a no-op for a term without state (change 0). */
PetscBool      EnergyTermHasState(EnergyTerm);
PetscErrorCode EnergyTermLag(EnergyTerm, Body[], PetscReal *change);
PetscErrorCode EnergyTermAccept(EnergyTerm, Body[], PetscReal load);
PetscErrorCode EnergyTermBegin(EnergyTerm);
/* A term whose increment from rest starts tied (friction.c, FrictionSetTieAtRest):
   the next increments' first solve with the accepted bound times growth, the
   given forces' (a no-op for any other term). */
PetscErrorCode EnergyTermScaleBound(EnergyTerm, PetscReal growth);
PetscErrorCode EnergyTermRestore(EnergyTerm, Body[]);
PetscErrorCode EnergyTermReset(EnergyTerm, Body[]);
/* A frictional term's stick zone half-width at the end of load stage k
   (1..-load_stages; has: whether the term has friction and that end was
   reached). */
PetscErrorCode EnergyTermGetStickHalfWidth(EnergyTerm, PetscInt k, PetscReal *c, PetscBool *has);
/* After the post-processing: why the term may have kept the solve from converging, or an empty string. */
PetscErrorCode EnergyTermDiagnose(EnergyTerm, size_t n, char why[]);
/* Friction at the state last evaluated: the nodes in contact that carry a
   bound, those of them that stick, and the largest trial slip of the
   increment (all 0 for a term without friction; the same on every rank). */
PetscErrorCode EnergyTermGetSlipState(EnergyTerm, PetscInt *stuck, PetscInt *loaded, PetscReal *slip);
