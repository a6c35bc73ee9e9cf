/* Writing the files of the output set: a failed write is one line naming the
   file and the cause, on every rank, with status 1, and the set is discarded
   (outputset.c), so earlier results stay and no temporary is left.

   The text files (XDMF, JSON) are formatted in memory (open_memstream) and
   written by one loop of write() on rank 0, then closed: the errno of the
   call that failed is the cause (ENOSPC, EDQUOT, EIO, ...). A FILE* written
   piecemeal would report a failed flush in some later fprintf() or in
   fclose(), with errno overwritten in between.

   The HDF5 file is written by PETSc through HDF5 and MPI-IO, and none of them
   hands the cause back: HDF5 says "file write failed" (a short write), Open
   MPI's OMPIO prints "mca_fbtl_posix_pwritev: error in (p)write(v):No space
   left on device" on stderr (opal_output, with no switch to turn it off) and
   returns a bare error, and PETSc prints its traceback for the HDF5 call that
   failed. Measured on a full tmpfs: 79 lines of HDF5's error stack, the OMPIO
   line and PETSc's traceback, then a crash in HDF5's clean-up at
   MPI_Finalize (the file was never closed). So around that write:
   - HDF5's own printing of its error stack is off (H5Eset_auto, results.c);
   - PETSc's errors return without a traceback (PetscReturnErrorHandler), and
     End closes the file in any case, so that no HDF5 file stays open until
     MPI_Finalize; after a failure it first empties the file and frees the
     1 MiB the set holds (outputset.c), so that HDF5's last flush of its
     metadata finds room: if that flush fails too, HDF5 1.10 keeps the
     file's id over freed memory;
   - stderr is redirected into a memory file, so that what a library prints
     is printed after the write if it succeeded, and dropped if it failed
     (the signal handler's message goes to the real stderr meanwhile:
     ContactOutputSetMessageFd);
   - the cause is found by writing again: rank 0 appends up to 64 KiB of
     zeros to the temporary and takes the errno of the write that fails (a
     full disk fails at once: the failed write had filled it), then truncates
     it back. If that write succeeds, the cause is PETSc's message of the
     call that failed ("Error in HDF5 call H5Fflush() Status -1"). */
#define _GNU_SOURCE /* memfd_create() */
#include <petscvec.h>
#include "outputwrite.h"
#include "outputset.h"
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>
#include <sys/mman.h>
#include <sys/stat.h>

#define PROBE_BYTES 65536

PetscErrorCode ContactOutputTextOpen(ContactOutputText *t)
{
  PetscFunctionBeginUser;
  t->buf = NULL;
  t->len = 0;
  t->fp  = open_memstream(&t->buf, &t->len);
  PetscCheck(t->fp, PETSC_COMM_SELF, PETSC_ERR_MEM, "cannot format the output in memory: %s", strerror(errno));
  PetscFunctionReturn(0);
}

/* Rank 0: the whole buffer into path, then closed; 0 or the errno of the
   call that failed. */
static int WriteAll(const char path[], const char *buf, size_t len)
{
  int    fd = open(path, O_WRONLY | O_TRUNC | O_CLOEXEC), e = 0;
  size_t done = 0;

  if (fd < 0) return errno;
  while (done < len && !e) {
    ssize_t n = write(fd, buf + done, len - done);
    if (n < 0 && errno != EINTR) e = errno;
    else if (n > 0) done += (size_t)n;
  }
  if (close(fd) && !e) e = errno;
  return e;
}

PetscErrorCode ContactOutputTextWrite(MPI_Comm comm, ContactOutputText *t, const char tmp[], const char name[])
{
  int  code = 0;
  char msg[CONTACT_OUTPUT_MSG_LEN] = "";

  PetscFunctionBeginUser;
  if (t->fp) {
    int e = fclose(t->fp) ? (errno ? errno : ENOMEM) : 0; /* the memory file: only memory can fail */
    t->fp = NULL;
    if (!e) e = WriteAll(tmp, t->buf, t->len);
    if (e) {
      PetscCall(PetscSNPrintf(msg, sizeof(msg), "cannot write %s: %s", name, strerror(e)));
      code = PETSC_ERR_FILE_WRITE;
    }
    free(t->buf); /* allocated by open_memstream() */
    t->buf = NULL;
  }
  PetscCall(ContactOutputCheckOnRoot(comm, code, msg));
  PetscFunctionReturn(0);
}

static int savedStderr = -1, capture = -1;

/* What the libraries printed on stderr during the write: replayed (the write
   succeeded) or dropped. */
static void StderrRestore(PetscBool replay)
{
  char    buf[4096];
  ssize_t n;

  if (savedStderr < 0) return;
  fflush(stderr);
  dup2(savedStderr, STDERR_FILENO);
  ContactOutputSetMessageFd(STDERR_FILENO);
  close(savedStderr);
  savedStderr = -1;
  if (replay && lseek(capture, 0, SEEK_SET) == 0)
    while ((n = read(capture, buf, sizeof(buf))) > 0)
      if (write(STDERR_FILENO, buf, (size_t)n) != n) break;
  close(capture);
  capture = -1;
}

/* Not PetscFunctionBeginUser: an error here is the write's, returned as it
   is (Begin's handler prints no traceback). */
PetscErrorCode ContactOutputCollective(PetscViewer v, PetscErrorCode ierr)
{
  PetscMPIInt e = (PetscMPIInt)ierr, any = 0;

  if (MPI_Allreduce(&e, &any, 1, MPI_INT, MPI_MAX, PetscObjectComm((PetscObject)v)) != MPI_SUCCESS) return PETSC_ERR_MPI;
  return any ? (ierr ? ierr : PETSC_ERR_FILE_WRITE) : 0;
}

PetscErrorCode ContactOutputWriteValues(PetscViewer v, MPI_Comm comm, const char name[], PetscInt n, const PetscReal val[], const PetscInt order[])
{
  Vec          vec;
  PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(VecCreate(comm, &vec));
  PetscCall(VecSetSizes(vec, n, PETSC_DETERMINE));
  PetscCall(VecSetType(vec, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)vec, name));
  PetscCall(VecGetArray(vec, &a));
  for (PetscInt i = 0; i < n; ++i) a[i] = val[order ? order[i] : i];
  PetscCall(VecRestoreArray(vec, &a));
  ContactOutputCall(v, VecView(vec, v));
  PetscCall(VecDestroy(&vec));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactOutputLibraryWriteBegin(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  fflush(stderr);
  capture = memfd_create("contact-stderr", MFD_CLOEXEC);
  if (capture >= 0 && (savedStderr = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3)) >= 0) {
    ContactOutputSetMessageFd(savedStderr);
    if (dup2(capture, STDERR_FILENO) < 0) StderrRestore(PETSC_FALSE);
  } else if (capture >= 0) { /* no stderr to restore: nothing held back */
    close(capture);
    capture = -1;
  }
  PetscFunctionReturn(0);
}

/* Rank 0: the errno of a write at the end of path (up to PROBE_BYTES), which
   is then truncated back; 0 if the write succeeds. */
static int ProbeWrite(const char path[])
{
  static const char zeros[4096];
  struct stat       st;
  int               fd = open(path, O_WRONLY | O_CLOEXEC), e = 0;
  off_t             off;

  if (fd < 0) return errno;
  if (fstat(fd, &st)) {
    e = errno;
    close(fd);
    return e;
  }
  for (off = st.st_size; !e && off < st.st_size + PROBE_BYTES;) {
    ssize_t n = pwrite(fd, zeros, sizeof(zeros), off);
    if (n < 0 && errno != EINTR) e = errno;
    else if (n > 0) off += n;
  }
  if (ftruncate(fd, st.st_size) && !e) e = errno;
  close(fd);
  return e;
}

PetscErrorCode ContactOutputLibraryWriteEnd(MPI_Comm comm, PetscErrorCode ierr, PetscErrorCode (*close)(void *), void *ctx, const char tmp[], const char name[])
{
  int         failed = ierr ? 1 : 0, any = 0, code = 0;
  PetscMPIInt rank;
  char        msg[CONTACT_OUTPUT_MSG_LEN] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, comm));
  if (any && !rank) {
    const char *text = NULL;
    char       *specific = NULL;
    const int   e = ProbeWrite(tmp);

    if (e) PetscCall(PetscSNPrintf(msg, sizeof(msg), "cannot write %s: %s", name, strerror(e)));
    else if (ierr && !PetscErrorMessage(ierr, &text, &specific) && specific && specific[0]) PetscCall(PetscSNPrintf(msg, sizeof(msg), "cannot write %s: %s", name, specific));
    else PetscCall(PetscSNPrintf(msg, sizeof(msg), "cannot write %s: %s", name, ierr && text ? text : "the write failed on another rank"));
    code = PETSC_ERR_FILE_WRITE;
    /* the file is discarded: emptied, and the set's reserve freed, so that closing it finds room for what it still writes */
    if (truncate(tmp, 0)) PetscCall(PetscInfo(NULL, "cannot empty %s: %s\n", tmp, strerror(errno)));
    ContactOutputReleaseReserve();
  }
  if (any) PetscCallMPI(MPI_Barrier(comm));
  failed = close(ctx) ? 1 : 0;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, comm));
  if (failed && !any && !rank) {
    const int e = ProbeWrite(tmp);
    PetscCall(PetscSNPrintf(msg, sizeof(msg), "cannot write %s: %s", name, e ? strerror(e) : "closing it failed"));
    code = PETSC_ERR_FILE_WRITE;
  }
  StderrRestore((PetscBool)!(any || failed));
  PetscCall(PetscPopErrorHandler());
  PetscCall(ContactOutputCheckOnRoot(comm, code, msg));
  PetscFunctionReturn(0);
}
