/* Partitioning: METIS k-way on the cell dual graph (Debian's PETSc has no METIS
   partitioner, so the partition is computed here and handed to DMPlexDistribute
   through a shell partitioner), or PETSc's PTScotch / simple partitioners. */
#include <metis.h>
#include "contact.h"
#include "partition.h"

const char *const PartitionTypes[] = {"metis", "ptscotch", "simple", "PartitionType", "PARTITION_", NULL};

static PetscErrorCode PartitionMetis(DM dm, PetscPartitioner part)
{
  PetscMPIInt size, rank;
  PetscInt    nv, *offsets = NULL, *adj = NULL, *sizes, *points = NULL;
  IS          gnum;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)dm), &size));
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)dm), &rank));
  PetscCall(DMPlexCreatePartitionerGraph(dm, 0, &nv, &offsets, &adj, &gnum));
  PetscCall(PetscCalloc1(size, &sizes));
  if (nv > 0) {
    idx_t  n = (idx_t)nv, ncon = 1, nparts = (idx_t)size, objval;
    idx_t *xadj, *adjncy, *part;
    idx_t  opts[METIS_NOPTIONS];
    int    status;

    PetscCheck(rank == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "METIS partitioning expects a serial mesh on rank 0");
    PetscCall(PetscMalloc3(nv + 1, &xadj, offsets[nv], &adjncy, nv, &part));
    for (PetscInt i = 0; i <= nv; ++i) xadj[i] = (idx_t)offsets[i];
    for (PetscInt i = 0; i < offsets[nv]; ++i) adjncy[i] = (idx_t)adj[i];
    METIS_SetDefaultOptions(opts);
    opts[METIS_OPTION_SEED]    = 0;
    opts[METIS_OPTION_NUMBERING] = 0;
    if (size == 1) for (PetscInt i = 0; i < nv; ++i) part[i] = 0;
    else {
      status = METIS_PartGraphKway(&n, &ncon, xadj, adjncy, NULL, NULL, NULL, &nparts, NULL, NULL, opts, &objval, part);
      PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS_PartGraphKway failed with status %d", status);
    }
    PetscCall(PetscMalloc1(nv, &points));
    for (PetscInt i = 0; i < nv; ++i) sizes[part[i]]++;
    {
      PetscInt *start;
      PetscCall(PetscCalloc1(size + 1, &start));
      for (PetscMPIInt r = 0; r < size; ++r) start[r + 1] = start[r] + sizes[r];
      for (PetscInt i = 0; i < nv; ++i) points[start[part[i]]++] = i;
      PetscCall(PetscFree(start));
    }
    PetscCall(PetscFree3(xadj, adjncy, part));
  }
  PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSHELL));
  PetscCall(PetscPartitionerShellSetPartition(part, size, sizes, points));
  PetscCall(PetscFree(sizes));
  PetscCall(PetscFree(points));
  PetscCall(PetscFree(offsets));
  PetscCall(PetscFree(adj));
  PetscCall(ISDestroy(&gnum));
  PetscFunctionReturn(0);
}

PetscErrorCode DMPlexDistributeWith(DM *dm, PartitionType type, PetscBool view, const char name[])
{
  PetscMPIInt      size;
  PetscPartitioner part;
  DM               dist = NULL;
  MPI_Comm         comm = PetscObjectComm((PetscObject)*dm);

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (size > 1) {
    PetscCall(PetscLogEventBegin(contactLog.partition, 0, 0, 0, 0));
    PetscCall(DMPlexGetPartitioner(*dm, &part));
    switch (type) {
    case PARTITION_METIS: PetscCall(PartitionMetis(*dm, part)); break;
    case PARTITION_PTSCOTCH: PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERPTSCOTCH)); break;
    case PARTITION_SIMPLE: PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSIMPLE)); break;
    }
    PetscCall(DMPlexDistribute(*dm, 0, NULL, &dist));
    if (dist) {
      PetscCall(DMDestroy(dm));
      *dm = dist;
    }
    PetscCall(PetscLogEventEnd(contactLog.partition, 0, 0, 0, 0));
  }
  if (view) {
    PetscInt cStart, cEnd;
    PetscCall(DMPlexGetHeightStratum(*dm, 0, &cStart, &cEnd));
    PetscCall(PetscPrintf(comm, "Partition of body %s (%s):\n", name, PartitionTypes[type]));
    PetscCall(PetscSynchronizedPrintf(comm, "  rank %d: %" PetscInt_FMT " cells\n", PetscGlobalRank, cEnd - cStart));
    PetscCall(PetscSynchronizedFlush(comm, PETSC_STDOUT));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PartitionOptionsSetFromOptions(MPI_Comm comm, PartitionOptions *o)
{
  PetscFunctionBeginUser;
  o->type = PARTITION_METIS;
  o->view = PETSC_FALSE;
  PetscOptionsBegin(comm, NULL, "Partitioning options", NULL);
  PetscCall(PetscOptionsEnum("-partitioner", "Mesh partitioner", NULL, PartitionTypes, (PetscEnum)o->type, (PetscEnum *)&o->type, NULL));
  PetscCall(PetscOptionsBool("-partition_view", "Print the cells per rank of each body", NULL, o->view, &o->view, NULL));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}
