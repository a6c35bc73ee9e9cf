#pragma once
#include "contactreport.h"
#include "search.h"

/* What every contact formulation's energy term holds and does alike
   (contactterm.c): the pair's description, its two surfaces with a search
   over each as master, the penalty in use, the Hessian's order, the results.
   A formulation's context starts with it, and the operations that only touch
   it (the Hessian's dofs, penalty continuation, the Hessian switch, printing
   and writing the results) are set once here for every formulation. */
typedef struct {
  ContactPairSpec spec;
  ContactSurface  S[2];
  ContactSearch   search[2];   /* over S[s] as master */
  PetscReal       kp;          /* penalty in use (continuation) */
  PetscBool       exactHessian; /* add the second-order terms to the Hessian */
  PetscBool       built;       /* the searches have been built (at the surfaces' current coordinates) */
  Body            body[2];     /* the surfaces' bodies (a rigid one takes its part of the Hessian to its unknowns' border, BodyAddSurfaceHessian) */
  ContactReport   report;
} ContactTerm;

/* t->data must point to a struct whose first member is the ContactTerm. */
PetscErrorCode ContactTermInitialize(ContactTerm *, const ContactPairSpec *, EnergyTerm t);
/* Collective: both surfaces (blend: the formulation's default where the scene sets none) and their searches. */
PetscErrorCode ContactTermSetUpSurfaces(ContactTerm *, Body[], PetscReal defaultBlend);
/* Collective: the surfaces' current coordinates, the searches rebuilt (in the
   log event given) if these changed; changed (or NULL): whether they did, or
   this is the first update. */
PetscErrorCode ContactTermUpdate(ContactTerm *, Body[], PetscLogEvent search, PetscBool *changed);
/* Starts a new report: the penalty, the surfaces' edge counts and which act as slave. */
PetscErrorCode ContactTermReportBegin(ContactTerm *, const PetscBool slave[2]);
/* Adds a formulation's Hessian block K (n x n, symmetric) over the joined
   vector's indices idx to H (a constrained dof's -1 and a rigid body's
   surface dofs are left out) and a rigid body's part to its unknowns'
   border (BodyAddSurfaceHessian). */
PetscErrorCode ContactTermAddHessian(const ContactTerm *, Mat H, PetscInt n, const PetscInt idx[], const PetscScalar K[]);
/* Collective, before solving (givenforces.c): a body held by this frictional
   pair alone against a flat partner, whose scene gives it a force that friction
   cannot hold (its part along the partner's surface above mu times its part
   across it) at some stage, is one line naming the pair, the body, the stage
   and the forces. */
PetscErrorCode ContactTermCheckGivenForces(const ContactTerm *, Body[]);
/* Whether the pair's friction starts an increment from rest tied (givenforces.c). */
PetscBool ContactTermTiesAtRest(const ContactTerm *, Body[]);
/* Each surface's inward normals handed to its body, for the check of what
   holds it (support.h), before solving. */
PetscErrorCode ContactTermAddSupport(const ContactTerm *, Body[]);
PetscErrorCode ContactTermDestroy(ContactTerm *);

/* The formulations (one file each). */
PetscErrorCode ContactTermCreate_GPTS(const ContactPairSpec *, EnergyTerm);
PetscErrorCode ContactTermCreate_Mortar(const ContactPairSpec *, EnergyTerm);

/* -help: lists mortar's options (-contact_mortar_slave, -contact_mortar_basis)
   with their defaults whatever the scene's formulations (listed once). */
PetscErrorCode ContactMortarOptionsHelp(MPI_Comm);
PetscErrorCode ContactMortar3dOptionsRead(MPI_Comm, PetscReal *, PetscInt *);
