#pragma once
#include <petscdmplex.h>

/* Distributes a serial DMPlex over the ranks of its communicator with the
   partitioner chosen by -partitioner (metis: METIS k-way on the cell dual graph,
   linked from libmetis; ptscotch, simple: PETSc's). */
typedef enum { PARTITION_METIS, PARTITION_PTSCOTCH, PARTITION_SIMPLE } PartitionType;
extern const char *const PartitionTypes[];
PetscErrorCode DMPlexDistributeWith(DM *dm, PartitionType type, PetscBool view, const char name[]);

/* -partitioner, -partition_view ("Partitioning options"; the problem's configuration, config.h). */
typedef struct {
  PartitionType type;
  PetscBool     view; /* print the cells per rank of each body */
} PartitionOptions;
PetscErrorCode PartitionOptionsSetFromOptions(MPI_Comm, PartitionOptions *);
