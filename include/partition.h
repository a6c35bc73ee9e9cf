#pragma once
#include "configtypes.h"

/* Distributes a serial DMPlex over the ranks of its communicator with the
   partitioner chosen by -partitioner (metis: METIS k-way on the cell dual graph,
   linked from libmetis; ptscotch, simple: PETSc's). */
PetscErrorCode DMPlexDistributeWith(DM *dm, PartitionType type, PetscBool view, const char name[]);

/* -partitioner, -partition_view ("Partitioning options"; PartitionType, PartitionOptions: configtypes.h). */
PetscErrorCode PartitionOptionsSetFromOptions(MPI_Comm, PartitionOptions *);
