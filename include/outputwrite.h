#pragma once
#include <petscviewer.h>
/* Writing the files of the output set (outputwrite.c) so that a failed write
   (a full disk, a quota, an I/O error) stops the run with one line naming the
   file and the cause, "cannot write out/hertz.h5: No space left on device",
   on every rank; the set is then discarded (outputset.h), so that earlier
   results stay and no temporary is left. */
#include <petscsys.h>

/* A text file (XDMF, JSON) formatted in memory on rank 0 and written with one
   checked write; fp is NULL on the other ranks. */
typedef struct {
  FILE  *fp;
  char  *buf;
  size_t len;
} ContactOutputText;

/* Rank 0: fp ready for fprintf(). Not collective. */
PetscErrorCode ContactOutputTextOpen(ContactOutputText *);
/* Collective: rank 0 writes the text into tmp; a failure names the file name. */
PetscErrorCode ContactOutputTextWrite(MPI_Comm, ContactOutputText *, const char tmp[], const char name[]);

/* A file written by a library (the HDF5 file, through PETSc, HDF5 and MPI-IO):
   between Begin and End, PETSc's errors return without a traceback and what the
   libraries print on stderr is held back (printed at End if the write
   succeeded, dropped if it failed). End is collective: ierr is this rank's
   result of the write; close(ctx) closes the file, also after a failure (the
   file emptied and the set's reserve freed first, so that closing finds
   room); if the write or the close failed on any rank, End stops with the one
   line naming name and the cause (tmp: the file being written). */
PetscErrorCode ContactOutputLibraryWriteBegin(void);
/* Between Begin and End, each collective call of the write (a VecView, an
   attribute) through ContactOutputCall(v, call): where it failed on one rank,
   it fails on every rank of v's communicator, which would otherwise go on to
   the next collective call and wait there for the rank that failed. */
PetscErrorCode ContactOutputCollective(PetscViewer, PetscErrorCode ierr);
#define ContactOutputCall(v, call) PetscCall(ContactOutputCollective((v), (call)))
/* Collective, between Begin and End: this rank's n values val[order[i]]
   (order NULL: val[i]) as a dataset name in v's current group. */
PetscErrorCode ContactOutputWriteValues(PetscViewer v, MPI_Comm, const char name[], PetscInt n, const PetscReal val[], const PetscInt order[]);
PetscErrorCode ContactOutputLibraryWriteEnd(MPI_Comm, PetscErrorCode ierr, PetscErrorCode (*close)(void *), void *ctx, const char tmp[], const char name[]);
