/* A rank's subdomain: the unconstrained dofs of its cells (a body's local
   vector holds exactly the closure of its cells), numbered by their index in
   the joined vector, sorted, and the stiffness of its cells alone,

       K^r = sum over r's cells of the element stiffnesses,   K = sum_r R_r^T K^r R_r.

   Assembled once, element by element into a sequential matrix (no
   communication), K^r serves twice: its rows, each a sorted run of columns,
   are added into the joined K, a third of the insertions that element
   matrices would need and no second element loop; and the substructured
   Newton step factors it (substructure.c). Rows are preallocated with the
   distinct columns of the cells around their node (pattern.c: exact, each
   of the subdomain's nodes having all its cells on this rank). */
#include "subdomain.h"
#include "pattern.h"

/* A node's distinct columns (pattern.c), the count of each of its rows. */
typedef struct {
  Body            body;
  const PetscInt *map;
  PetscInt       *nnz;
} SubdomainCount;

static PetscErrorCode SubdomainCountNode(void *ctx, PetscInt dof, PetscInt n, const PetscInt cols[])
{
  SubdomainCount *sc = (SubdomainCount *)ctx;

  PetscFunctionBeginUser;
  (void)cols;
  for (PetscInt d = 0; d < BodyGetDimension(sc->body); ++d)
    if (sc->map[dof + d] >= 0) sc->nnz[sc->map[dof + d]] += n;
  PetscFunctionReturn(0);
}

PetscErrorCode SubdomainCreate(PetscInt nbodies, Body bodies[], Subdomain *sub)
{
  Subdomain s;
  PetscInt  n = 0, *map[CONTACT_MAX_BODIES], *nnz;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&s));
  for (PetscInt i = 0; i < nbodies; ++i) {
    const PetscInt *l2b = BodyGetJoinedMap(bodies[i]);
    PetscInt        nl;
    PetscCall(VecGetLocalSize(BodyGetLocalSolution(bodies[i]), &nl));
    for (PetscInt k = 0; k < nl; ++k) n += l2b[k] >= 0;
  }
  PetscCall(PetscMalloc1(n + 1, &s->dofs));
  n = 0;
  for (PetscInt i = 0; i < nbodies; ++i) {
    const PetscInt *l2b = BodyGetJoinedMap(bodies[i]);
    PetscInt        nl;
    PetscCall(VecGetLocalSize(BodyGetLocalSolution(bodies[i]), &nl));
    for (PetscInt k = 0; k < nl; ++k)
      if (l2b[k] >= 0) s->dofs[n++] = l2b[k];
  }
  PetscCall(PetscSortRemoveDupsInt(&n, s->dofs));
  s->n = n;

  PetscCall(PetscCalloc1(n + 1, &nnz));
  for (PetscInt i = 0; i < nbodies; ++i) {
    Body            b   = bodies[i];
    const PetscInt *l2b = BodyGetJoinedMap(b);
    PetscInt        nl;

    PetscCall(VecGetLocalSize(BodyGetLocalSolution(b), &nl));
    PetscCall(PetscMalloc1(nl + 1, &map[i]));
    for (PetscInt k = 0; k < nl; ++k) {
      map[i][k] = -1;
      if (l2b[k] >= 0) PetscCall(PetscFindInt(l2b[k], n, s->dofs, &map[i][k]));
    }
    {
      SubdomainCount sc = {b, map[i], nnz};
      PetscCall(BodyNodeColumns(b, map[i], SubdomainCountNode, &sc));
    }
  }
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, nnz, &s->K));
  PetscCall(PetscFree(nnz));
  for (PetscInt i = 0; i < nbodies; ++i) {
    PetscCall(BodyAssembleHessianMapped(bodies[i], map[i], s->K));
    PetscCall(PetscFree(map[i]));
  }
  PetscCall(MatAssemblyBegin(s->K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(s->K, MAT_FINAL_ASSEMBLY));
  *sub = s;
  PetscFunctionReturn(0);
}

PetscErrorCode SubdomainAddTo(Subdomain s, Mat K)
{
  const PetscInt    *ia, *ja;
  const PetscScalar *v;
  PetscInt           n, *cols, maxlen = 0;
  PetscBool          done;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(contactLog.elasHessian, 0, 0, 0, 0));
  PetscCall(MatGetRowIJ(s->K, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_LIB, "MatGetRowIJ failed on the subdomain stiffness");
  PetscCall(MatSeqAIJGetArrayRead(s->K, &v));
  for (PetscInt i = 0; i < n; ++i) maxlen = PetscMax(maxlen, ia[i + 1] - ia[i]);
  PetscCall(PetscMalloc1(maxlen + 1, &cols));
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt len = ia[i + 1] - ia[i];
    for (PetscInt k = 0; k < len; ++k) cols[k] = s->dofs[ja[ia[i] + k]];
    PetscCall(MatSetValues(K, 1, &s->dofs[i], len, cols, v + ia[i], ADD_VALUES));
  }
  PetscCall(PetscFree(cols));
  PetscCall(MatSeqAIJRestoreArrayRead(s->K, &v));
  PetscCall(MatRestoreRowIJ(s->K, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscCall(PetscLogEventEnd(contactLog.elasHessian, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode SubdomainDestroy(Subdomain *sub)
{
  PetscFunctionBeginUser;
  if (!*sub) PetscFunctionReturn(0);
  PetscCall(PetscFree((*sub)->dofs));
  PetscCall(MatDestroy(&(*sub)->K));
  PetscCall(PetscFree(*sub));
  PetscFunctionReturn(0);
}
