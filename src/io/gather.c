/* Collective gathers of every rank's reals, in rank order, on rank 0 or on
   every rank: the cells of a body's old mesh for a transfer (transfer.c),
   the records of -accuracy's size fields and contact zones (accuracy.c). */
#include "gather.h"

PetscErrorCode ContactGatherReals(MPI_Comm comm, PetscBool everyone, PetscInt n, const PetscReal loc[], PetscInt *ntot, PetscReal **all)
{
  PetscMPIInt rank, size, nl = (PetscMPIInt)n, *cnt = NULL, *disp = NULL;
  PetscBool   here;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  here  = (PetscBool)(everyone || !rank);
  *ntot = 0;
  *all  = NULL;
  if (here) PetscCall(PetscMalloc2(size, &cnt, size + 1, &disp));
  if (everyone) PetscCallMPI(MPI_Allgather(&nl, 1, MPI_INT, cnt, 1, MPI_INT, comm));
  else PetscCallMPI(MPI_Gather(&nl, 1, MPI_INT, cnt, 1, MPI_INT, 0, comm));
  if (here) {
    disp[0] = 0;
    for (PetscMPIInt r = 0; r < size; ++r) disp[r + 1] = disp[r] + cnt[r];
    PetscCall(PetscMalloc1(disp[size] + 1, all));
    *ntot = disp[size];
  }
  if (everyone) PetscCallMPI(MPI_Allgatherv(loc, nl, MPIU_REAL, *all, cnt, disp, MPIU_REAL, comm));
  else PetscCallMPI(MPI_Gatherv(loc, nl, MPIU_REAL, *all, cnt, disp, MPIU_REAL, 0, comm));
  if (here) PetscCall(PetscFree2(cnt, disp));
  PetscFunctionReturn(0);
}
