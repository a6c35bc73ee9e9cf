#pragma once
/* The output set of a run (outputset.c): ContactOutputOpen() locks it, checks
   its paths and creates its temporaries before meshing (h5 or json may be
   "none"; wait: wait for another run that holds the lock); the writer fills
   the temporaries and ContactOutputCommit() publishes them; a failed or
   interrupted run discards the set (its temporaries and lock removed, earlier
   files intact). Nothing here knows what the files hold. */
#include <petscsys.h>

/* The set's final names ("" when not written), temporaries and run id. */
typedef struct {
  const char *h5, *xdmf, *json, *htmp, *xtmp, *jtmp, *runId;
} ContactOutputFiles;

PetscErrorCode ContactOutputOpen(MPI_Comm, const char h5[], const char json[], PetscBool wait);
PetscErrorCode ContactOutputGetFiles(ContactOutputFiles *);
PetscErrorCode ContactOutputCommit(MPI_Comm);
PetscErrorCode ContactOutputInstallSignalHandlers(void);
void           ContactOutputDiscard(void);
/* A child process (Gmsh) and the file it writes: an interrupted run stops it
   and removes the file (pid 0: none). */
void           ContactOutputSetChild(int pid, const char file[]);
/* Rank 0's verdict, 0 or an error code with its message (msg:
   CONTACT_OUTPUT_MSG_LEN characters on every rank), raised on every rank. */
#define CONTACT_OUTPUT_MSG_LEN (3 * PETSC_MAX_PATH_LEN)
PetscErrorCode ContactOutputCheckOnRoot(MPI_Comm, int code, char msg[]);
/* Rank 0: frees the room the set holds for the HDF5 file to close after a
   failed write (outputset.c, Reserve). */
void           ContactOutputReleaseReserve(void);
/* Collective, before the HDF5 file is written on several ranks: whether the
   disk has room for bytes in its temporary (rank 0 allocates them and frees
   them again, as the reserve is allocated); if not, the one line naming the
   HDF5 file and the cause, on every rank. Parallel HDF5 fails inside a
   collective call on the rank whose write found no room, and the others wait
   in it: this check is what keeps a full disk from hanging such a run. */
PetscErrorCode ContactOutputCheckRoom(MPI_Comm, size_t bytes);
/* The descriptor the signal handler's message goes to (default stderr). */
void           ContactOutputSetMessageFd(int fd);
