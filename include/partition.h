#pragma once
#include <petscdmplex.h>

/* Distributes a serial DMPlex over the ranks of its communicator with the
   partitioner chosen by -partitioner (metis: METIS k-way on the cell dual graph,
   linked from libmetis; ptscotch, simple: PETSc's). */
typedef enum { PARTITION_METIS, PARTITION_PTSCOTCH, PARTITION_SIMPLE } PartitionType;
extern const char *const PartitionTypes[];
PetscErrorCode DMPlexDistributeWith(DM *dm, PartitionType type, PetscBool view, const char name[]);
