#pragma once
#include "body.h"

/* A rank's subdomain: the unconstrained dofs of its cells and their
   stiffness, assembled from its cells alone (subdomain.c). On several ranks
   the assembled stiffness is the sum of the subdomains' (SubdomainAddTo),
   and the substructured Newton step factors each rank's own. */
typedef struct _n_Subdomain *Subdomain;
struct _n_Subdomain {
  PetscInt  n;
  PetscInt *dofs; /* [n] joined-vector index of each dof, sorted */
  Mat       K;    /* n x n, SeqAIJ, rows and columns in the order of dofs */
};

PetscErrorCode SubdomainCreate(PetscInt nbodies, Body bodies[], Subdomain *);
/* Adds the subdomain stiffness into the joined K (rows of other ranks stashed). */
PetscErrorCode SubdomainAddTo(Subdomain, Mat K);
PetscErrorCode SubdomainDestroy(Subdomain *);
