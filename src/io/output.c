/* Output: per body the second-order nodal mesh (coordinates, Tri6/Quad9
   connectivity in XDMF node order), displacement, stress (xx, yy, zz, xy) and
   von Mises stress averaged at the nodes, in one HDF5 file with an XDMF file
   beside it, and a JSON summary of the run.

   The files of a run are one set, so that two runs never mix theirs and a
   failed run changes none:
   - before meshing (ContactOutputOpen) the set is locked: a lock file
     <stem>.lock beside the files (stem: the XDMF or JSON file's name without
     its extension; out/hertz.lock for the default set), created with O_EXCL,
     holding "pid=<pid> host=<host> run_id=<id>", and flock()ed while the run
     lives. A second run on the same names stops at once naming the first, or
     waits for it (-output_wait). A lock that nobody holds any more (the
     kernel drops a flock with its process, also on SIGKILL, and does not
     mistake a reused pid) is taken over. Then the temporaries <name>.tmp are
     created: a path that cannot be written fails before meshing. Of the
     missing directories only the default out/ is created.
   - the files are written under the temporary names, carry the run id
     (/metadata:run_id, "run_id", an XML comment) and are renamed at the end,
     the XDMF file last (it names the HDF5 file), with the signals held so that
     a Ctrl-C renames all or none; then the lock is removed.
   - a failed or interrupted run removes its temporaries and its lock. */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <petscsf.h>
#include <petscviewerhdf5.h>
#include "problem.h"
#include "xdmf.h"
#include "progress.h"

#define MAX_PENDING  3
#define MAX_LOCKS    2
#define OUT_PATH_LEN (PETSC_MAX_PATH_LEN + 16)
#define OUT_MSG_LEN  (3 * PETSC_MAX_PATH_LEN)

/* The set of the run: final names ("" when not written), temporaries, run id. */
typedef struct {
  char      h5[OUT_PATH_LEN], xdmf[OUT_PATH_LEN], json[OUT_PATH_LEN];
  char      htmp[OUT_PATH_LEN], xtmp[OUT_PATH_LEN], jtmp[OUT_PATH_LEN];
  char      runId[128];
  PetscBool open;
} OutputSet;
static OutputSet set;

/* Temporary files being written and lock files held (rank 0): a failed or
   interrupted run removes them, so that it leaves neither a half-written file
   nor a changed final one. The signal handler only calls async-signal-safe
   functions (unlink, signal, raise). */
static char                  pending[MAX_PENDING][OUT_PATH_LEN];
static volatile sig_atomic_t npending;
static char                  locks[MAX_LOCKS][OUT_PATH_LEN];
static int                   lockfd[MAX_LOCKS];
static volatile sig_atomic_t nlocks;

static const int outputSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

static int                   signalRank;
static volatile sig_atomic_t childPid;
static char                  childFile[OUT_PATH_LEN];

void ContactOutputSetChild(int pid, const char file[])
{
  childPid = 0;
  if (pid && file && strlen(file) < sizeof(childFile)) strcpy(childFile, file);
  childPid = pid;
}

static void Say(const char *s)
{
  ssize_t r = write(STDERR_FILENO, s, strlen(s));
  (void)r;
}

/* Removes the temporaries and the lock. For SIGPIPE (output piped into head)
   dies of the signal, quietly, as Unix tools do; for SIGINT, SIGTERM and
   SIGHUP says on rank 0 in which phase the run was interrupted and exits
   with 128 + the signal's number (130 for Ctrl-C, 143 for SIGTERM). Only
   async-signal-safe calls (unlink, write, kill, _exit, signal, raise). */
static void RemovePendingOnSignal(int sig)
{
  for (int i = 0; i < npending; ++i) unlink(pending[i]);
  for (int i = 0; i < nlocks; ++i) unlink(locks[i]);
  if (childPid) {
    kill(childPid, SIGKILL);
    unlink(childFile);
  }
  if (sig == SIGPIPE) {
    signal(sig, SIG_DFL);
    raise(sig);
    return;
  }
  if (!signalRank) {
    Say("contact: interrupted during ");
    Say(ContactProgressCurrentPhase());
    Say("; no output written\n");
  }
  _exit(128 + sig);
}

/* SIGINT, SIGTERM, SIGHUP, SIGPIPE: see RemovePendingOnSignal. */
PetscErrorCode ContactOutputInstallSignalHandlers(void)
{
  struct sigaction sa;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &signalRank));
  memset(&sa, 0, sizeof(sa));
  sa.sa_handler = RemovePendingOnSignal;
  sigemptyset(&sa.sa_mask);
  for (size_t i = 0; i < sizeof(outputSignals) / sizeof(outputSignals[0]); ++i) PetscCheck(!sigaction(outputSignals[i], &sa, NULL), PETSC_COMM_SELF, PETSC_ERR_SYS, "cannot install the handler of signal %d", outputSignals[i]);
  PetscFunctionReturn(0);
}

static void ReleaseLocks(void)
{
  while (nlocks > 0) { /* unlinked while still flocked: a waiter that opened it sees it gone */
    const int k = nlocks - 1;
    unlink(locks[k]);
    close(lockfd[k]);
    nlocks = k;
  }
}

/* Removes the temporaries of an output that did not complete and releases the
   lock (rank 0 names them). */
void ContactOutputDiscard(void)
{
  PetscMPIInt rank = 0;

  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (!rank) {
    for (int i = 0; i < npending; ++i) unlink(pending[i]);
    ReleaseLocks();
  }
  npending = 0;
  set.open = PETSC_FALSE;
}

/* Rank 0's verdict (0 or an error code with its message) on every rank. */
static PetscErrorCode CheckOnRoot(MPI_Comm comm, int code, char msg[])
{
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(&code, 1, MPI_INT, 0, comm));
  if (code) PetscCallMPI(MPI_Bcast(msg, OUT_MSG_LEN, MPI_CHAR, 0, comm));
  PetscCheck(!code, comm, (PetscErrorCode)code, "%s", msg);
  PetscFunctionReturn(0);
}

/* path without the extension ext (if it has it) */
static void Stem(const char path[], const char ext[], char stem[])
{
  size_t l = strlen(path), e = strlen(ext);

  snprintf(stem, OUT_PATH_LEN, "%s", path);
  if (l > e && !strcmp(path + l - e, ext)) stem[l - e] = 0;
}

/* Rank 0: the folder of an output exists (only the default out/ is created)
   and the name is not a folder. */
static int CheckOutputPath(const char opt[], const char path[], char msg[])
{
  char        dir[OUT_PATH_LEN];
  const char *slash = strrchr(path, '/');
  struct stat st;

  if (!stat(path, &st) && S_ISDIR(st.st_mode)) {
    snprintf(msg, OUT_MSG_LEN, "option %s: %s is a directory", opt, path);
    return PETSC_ERR_FILE_OPEN;
  }
  if (!slash) return 0;
  snprintf(dir, sizeof(dir), "%.*s", slash == path ? 1 : (int)(slash - path), path);
  if (!stat(dir, &st)) {
    if (S_ISDIR(st.st_mode)) return 0;
    snprintf(msg, OUT_MSG_LEN, "option %s: cannot write %s: %s is not a directory", opt, path, dir);
    return PETSC_ERR_FILE_OPEN;
  }
  if (errno == ENOENT && (!strcmp(dir, "out") || !strcmp(dir, "./out"))) {
    if (!mkdir(dir, 0777) || errno == EEXIST) return 0;
    snprintf(msg, OUT_MSG_LEN, "option %s: cannot create the output directory %s: %s", opt, dir, strerror(errno));
    return PETSC_ERR_FILE_OPEN;
  }
  if (errno == ENOENT) snprintf(msg, OUT_MSG_LEN, "option %s: cannot write %s: directory %s does not exist", opt, path, dir);
  else snprintf(msg, OUT_MSG_LEN, "option %s: cannot write %s: directory %s: %s", opt, path, dir, strerror(errno));
  return PETSC_ERR_FILE_OPEN;
}

/* Rank 0: creates (empties) a temporary file, recorded first so that a
   signal cannot leave it behind. */
static int CreateTemporary(const char opt[], const char path[], char msg[])
{
  int fd;

  if (npending >= MAX_PENDING) {
    snprintf(msg, OUT_MSG_LEN, "too many temporary files");
    return PETSC_ERR_PLIB;
  }
  snprintf(pending[npending], OUT_PATH_LEN, "%s", path);
  npending = npending + 1;
  fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) {
    snprintf(msg, OUT_MSG_LEN, "option %s: cannot write %s: %s", opt, path, strerror(errno));
    npending = npending - 1;
    return PETSC_ERR_FILE_OPEN;
  }
  close(fd);
  return 0;
}

/* Rank 0, one attempt at the lock file path: 0 with *fd when taken (created,
   or taken over from a run that is gone: *stale, holder[] its line); EBUSY
   with the holder's line in holder[] while another run holds it; else an
   errno. A run holds its lock file by flock(); a file that nobody flocks is
   being created (no full line yet: retried for 2 s), was just released
   (unlinked: retried), or was left by a run that ended without removing it.
   On another host the holder cannot be checked, so its lock counts as held. */
static int LockTry(const char path[], const char line[], const char host[], int *fd, char holder[], size_t len, PetscBool *stale)
{
  for (int tries = 0;; ++tries) {
    struct stat a, b;
    ssize_t     n;
    int         f = open(path, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644), e;
    char        hhost[256] = "";

    if (f >= 0) {
      if (flock(f, LOCK_EX | LOCK_NB) || write(f, line, strlen(line)) != (ssize_t)strlen(line)) {
        e = errno ? errno : EIO;
        unlink(path);
        close(f);
        return e;
      }
      *fd = f;
      return 0;
    }
    if (errno != EEXIST) return errno;
    if ((f = open(path, O_RDWR | O_CLOEXEC)) < 0) {
      if (errno == ENOENT) continue;
      return errno;
    }
    n         = pread(f, holder, len - 1, 0);
    holder[n > 0 ? n : 0] = 0;
    if (flock(f, LOCK_EX | LOCK_NB)) {
      e = errno;
      close(f);
      return e == EWOULDBLOCK ? EBUSY : e;
    }
    if (fstat(f, &a) || stat(path, &b) || a.st_ino != b.st_ino || a.st_dev != b.st_dev) {
      close(f);
      continue;
    }
    n         = pread(f, holder, len - 1, 0);
    holder[n > 0 ? n : 0] = 0;
    if (!strchr(holder, '\n') && tries < 200) {
      close(f);
      usleep(10000);
      continue;
    }
    { /* the holder's host, if the line names one */
      const char *h = strstr(holder, "host=");
      if (h) sscanf(h + 5, "%255s", hhost);
      if (hhost[0] && strcmp(hhost, host)) {
        close(f);
        return EBUSY;
      }
    }
    *stale = PETSC_TRUE;
    if (ftruncate(f, 0) || pwrite(f, line, strlen(line), 0) != (ssize_t)strlen(line)) {
      e = errno ? errno : EIO;
      close(f);
      return e;
    }
    *fd = f;
    return 0;
  }
}

/* Collective: takes the set's locks in name order (so that two runs waiting
   for each other's second lock cannot happen); with wait, retries every
   0.2 s while another run holds one. */
static PetscErrorCode OutputLock(MPI_Comm comm, PetscInt nwant, char want[][OUT_PATH_LEN], const char *what[], PetscBool wait)
{
  PetscMPIInt rank;
  PetscBool   told = PETSC_FALSE;
  char        line[512], host[256] = "", msg[OUT_MSG_LEN];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (gethostname(host, sizeof(host) - 1)) snprintf(host, sizeof(host), "unknown");
  snprintf(line, sizeof(line), "pid=%d host=%s run_id=%s\n", (int)getpid(), host, set.runId);
  for (;;) {
    int state = 0; /* 0: all held, 1: another run holds one, else an error code */
    msg[0]    = 0;
    if (!rank) {
      while (nlocks < nwant) {
        char      holder[512] = "", *nl;
        PetscBool stale       = PETSC_FALSE;
        int       fd = -1, e = LockTry(want[nlocks], line, host, &fd, holder, sizeof(holder), &stale);
        if ((nl = strchr(holder, '\n'))) *nl = 0;
        if (!e) {
          snprintf(locks[nlocks], OUT_PATH_LEN, "%s", want[nlocks]);
          lockfd[nlocks] = fd;
          nlocks         = nlocks + 1;
          if (stale) fprintf(stderr, "contact: warning: took over %s, left by a run that is gone (%s)\n", want[nlocks - 1], holder[0] ? holder : "empty");
          continue;
        }
        if (e == EBUSY) {
          int  pid = -1;
          char hh[256] = "?", id[128] = "?";
          const char *c;
          if ((c = strstr(holder, "pid="))) sscanf(c + 4, "%d", &pid);
          if ((c = strstr(holder, "host="))) sscanf(c + 5, "%255s", hh);
          if ((c = strstr(holder, "run_id="))) sscanf(c + 7, "%127s", id);
          snprintf(msg, sizeof(msg), "%s is being written by another run: pid %d on host %s (run id %s, lock %s%s)", what[nlocks], pid, hh, id, want[nlocks], strcmp(hh, host) ? "; from this host it cannot be checked: remove the lock if that run has ended" : "");
          state = 1;
        } else {
          snprintf(msg, sizeof(msg), "cannot create the lock file %s of %s: %s", want[nlocks], what[nlocks], strerror(e));
          state = PETSC_ERR_FILE_OPEN;
        }
        break;
      }
    }
    PetscCallMPI(MPI_Bcast(&state, 1, MPI_INT, 0, comm));
    if (!state) break;
    PetscCallMPI(MPI_Bcast(msg, sizeof(msg), MPI_CHAR, 0, comm));
    PetscCheck(state == 1, comm, (PetscErrorCode)state, "%s", msg);
    PetscCheck(wait, comm, PETSC_ERR_FILE_OPEN, "%s; -output_wait waits for it, -output and -summary name other files", msg);
    if (!told) PetscCall(PetscFPrintf(comm, PETSC_STDERR, "contact: waiting: %s\n", msg));
    told = PETSC_TRUE;
    usleep(200000);
  }
  PetscFunctionReturn(0);
}

/* Collective, before meshing: the run id, the output set's names, its locks,
   and its temporaries created. h5 or json may be "none". */
PetscErrorCode ContactOutputOpen(MPI_Comm comm, const char h5[], const char json[], PetscBool wait)
{
  PetscMPIInt rank;
  PetscBool   noh5, nojs;
  char        msg[OUT_MSG_LEN] = "", want[MAX_LOCKS][OUT_PATH_LEN], stem[OUT_PATH_LEN];
  const char *what[MAX_LOCKS];
  PetscInt    nwant = 0;
  int         code  = 0;

  PetscFunctionBeginUser;
  PetscCheck(!set.open, comm, PETSC_ERR_ORDER, "the output set is already open");
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMemzero(&set, sizeof(set)));
  PetscCall(PetscStrcmp(h5, "none", &noh5));
  PetscCall(PetscStrcmp(json, "none", &nojs));
  if (!rank) {
    char      host[256] = "", ts[32];
    time_t    now       = time(NULL);
    struct tm tm;
    if (gethostname(host, sizeof(host) - 1)) PetscCall(PetscSNPrintf(host, sizeof(host), "unknown"));
    strftime(ts, sizeof(ts), "%Y%m%dT%H%M%S", localtime_r(&now, &tm));
    PetscCall(PetscSNPrintf(set.runId, sizeof(set.runId), "%s-%s-%d", ts, host, (int)getpid()));
  }
  PetscCallMPI(MPI_Bcast(set.runId, sizeof(set.runId), MPI_CHAR, 0, comm));
  if (!noh5) {
    PetscCall(PetscSNPrintf(set.h5, OUT_PATH_LEN, "%s", h5));
    Stem(h5, ".h5", stem);
    PetscCall(PetscSNPrintf(set.xdmf, OUT_PATH_LEN, "%s.xdmf", stem));
    PetscCall(PetscSNPrintf(set.htmp, OUT_PATH_LEN, "%s.tmp", set.h5));
    PetscCall(PetscSNPrintf(set.xtmp, OUT_PATH_LEN, "%s.tmp", set.xdmf));
    Stem(set.xdmf, ".xdmf", stem);
    PetscCall(PetscSNPrintf(want[nwant], OUT_PATH_LEN, "%s.lock", stem));
    what[nwant++] = set.h5;
  }
  if (!nojs) {
    PetscCall(PetscSNPrintf(set.json, OUT_PATH_LEN, "%s", json));
    PetscCall(PetscSNPrintf(set.jtmp, OUT_PATH_LEN, "%s.tmp", set.json));
    Stem(json, ".json", stem);
    PetscCall(PetscSNPrintf(want[nwant], OUT_PATH_LEN, "%s.lock", stem));
    what[nwant++] = set.json;
  }
  if (nwant == 2 && !strcmp(want[0], want[1])) nwant = 1; /* out/hertz.{h5,xdmf,json}: one lock */
  else if (nwant == 2 && strcmp(want[0], want[1]) > 0) { /* in name order */
    const char *w = what[0];
    memcpy(stem, want[0], sizeof(stem));
    memcpy(want[0], want[1], sizeof(stem));
    memcpy(want[1], stem, sizeof(stem));
    what[0] = what[1];
    what[1] = w;
  }
  PetscCheck(noh5 || nojs || (strcmp(set.h5, set.json) && strcmp(set.xdmf, set.json)), comm, PETSC_ERR_USER_INPUT, "options -output and -summary: %s is named twice", set.json);
  if (!rank) {
    if (!noh5) code = CheckOutputPath("-output", set.h5, msg);
    if (!code && !nojs) code = CheckOutputPath("-summary", set.json, msg);
  }
  PetscCall(CheckOnRoot(comm, code, msg));
  PetscCall(OutputLock(comm, nwant, want, what, wait));
  if (!rank) {
    if (!noh5) code = CreateTemporary("-output", set.htmp, msg);
    if (!code && !noh5) code = CreateTemporary("-output", set.xtmp, msg);
    if (!code && !nojs) code = CreateTemporary("-summary", set.jtmp, msg);
  }
  PetscCall(CheckOnRoot(comm, code, msg));
  set.open = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* Collective: the renames that publish the set, the XDMF file last, with the
   signals held (rank 0), then the lock removed. */
static PetscErrorCode OutputCommit(MPI_Comm comm)
{
  PetscMPIInt rank;
  int         code = 0;
  char        msg[OUT_MSG_LEN] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    const char *from[3] = {set.htmp, set.jtmp, set.xtmp}, *to[3] = {set.h5, set.json, set.xdmf};
    sigset_t    block, old;
    sigemptyset(&block);
    for (size_t i = 0; i < sizeof(outputSignals) / sizeof(outputSignals[0]); ++i) sigaddset(&block, outputSignals[i]);
    sigprocmask(SIG_BLOCK, &block, &old);
    for (int k = 0; k < 3 && !code; ++k)
      if (to[k][0] && rename(from[k], to[k])) {
        snprintf(msg, sizeof(msg), "cannot rename %s to %s: %s", from[k], to[k], strerror(errno));
        code = PETSC_ERR_FILE_WRITE;
      }
    if (!code) {
      npending = 0;
      ReleaseLocks();
    }
    sigprocmask(SIG_SETMASK, &old, NULL);
  }
  PetscCall(CheckOnRoot(comm, code, msg));
  npending = 0;
  set.open = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* The XDMF file: one spatial collection of a grid per body (its second-order
   cells, reference coordinates, displacement as a 3-component vector, stress
   components and von Mises stress) and a line grid per contact surface with a
   profile (EnergyTermWriteXDMF), all on the HDF5 file h5. ParaView's legacy
   reader (XDMFReader) and its Xdmf3 readers read every item alike only as
   plain HDF datasets: the Xdmf3 readers skip Function and HyperSlab items,
   and the readers map the columns of a Tensor6 differently; so the HDF5 file
   holds the displacement with z = 0 and each stress component on its own. */
static PetscErrorCode WriteXDMF(Problem p, BodyNodalFields F[], const char path[], const char h5[], const char runId[])
{
  PetscMPIInt rank;
  const char *base = strrchr(h5, '/');

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  base = base ? base + 1 : h5;
  if (rank == 0) {
    FILE *fp = fopen(path, "w");
    PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s: %s", path, strerror(errno));
    fprintf(fp, "<?xml version=\"1.0\" ?>\n<!-- contact run_id %s -->\n<Xdmf Version=\"3.0\">\n <Domain>\n", runId);
    fprintf(fp, "  <Grid Name=\"%s\" GridType=\"Collection\" CollectionType=\"Spatial\">\n", p->scene);
    for (PetscInt i = 0; i < p->nbodies; ++i) {
      Body        b  = p->bodies[i];
      const char *tt = b->simplex ? "Triangle_6" : "Quadrilateral_9";
      const char *g  = b->name;
      PetscInt    N = F[i].nnodes, C = F[i].ncells;
      fprintf(fp, "   <Grid Name=\"%s\" GridType=\"Uniform\">\n", g);
      fprintf(fp, "    <Topology TopologyType=\"%s\" NumberOfElements=\"%d\">\n", tt, (int)C);
      fprintf(fp, "     <DataItem Dimensions=\"%d %d\" NumberType=\"Int\" Precision=\"%d\" Format=\"HDF\">%s:/bodies/%s/topology</DataItem>\n    </Topology>\n", (int)C, (int)b->nb, (int)sizeof(PetscInt), base, g);
      fprintf(fp, "    <Geometry GeometryType=\"XY\">\n     <DataItem Dimensions=\"%d 2\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%s:/bodies/%s/geometry</DataItem>\n    </Geometry>\n", (int)N, base, g);
      char        path[PETSC_MAX_PATH_LEN];
      PetscCall(PetscSNPrintf(path, sizeof(path), "%s:/bodies/%s/displacement_xyz", base, g));
      XdmfWriteAttribute(fp, "displacement", (int)N, 3, path);
      for (PetscInt k = 0; k < XDMF_BODY_SCALARS; ++k) {
        PetscCall(PetscSNPrintf(path, sizeof(path), "%s:/bodies/%s/%s", base, g, XdmfBodyScalars[k]));
        XdmfWriteAttribute(fp, XdmfBodyScalars[k], (int)N, 1, path);
      }
      PetscCall(PetscSNPrintf(path, sizeof(path), "%s:/bodies/%s/xdmf_nan", base, g));
      for (PetscInt k = 0; k < XDMF_SURFACE_SCALARS; ++k) XdmfWriteAttribute(fp, XdmfSurfaceScalars[k], (int)N, 1, path); /* no contact fields in a body (xdmf.h) */
      fprintf(fp, "   </Grid>\n");
    }
    for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermWriteXDMF(p->terms[t], p->bodies, fp, base));
    fprintf(fp, "  </Grid>\n </Domain>\n</Xdmf>\n");
    PetscCheck(!ferror(fp) && !fclose(fp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "error writing %s", path);
  }
  PetscFunctionReturn(0);
}

/* The fields as the XDMF file reads them: displacement_xyz (z = 0) and
   stress_xx, stress_yy, stress_zz, stress_xy, beside displacement and stress,
   and xdmf_nan, NaN at every node, for the contact fields a body has not. */
static PetscErrorCode WriteXDMFFields(BodyNodalFields *F, PetscViewer v)
{
  Vec                d3, c;
  PetscInt           n;
  const PetscScalar *u;
  PetscScalar       *a;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(F->vm, &n));
  PetscCall(VecCreate(PetscObjectComm((PetscObject)F->vm), &d3));
  PetscCall(VecSetSizes(d3, 3 * n, PETSC_DETERMINE));
  PetscCall(VecSetBlockSize(d3, 3));
  PetscCall(VecSetType(d3, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)d3, "displacement_xyz"));
  PetscCall(VecGetArrayRead(F->disp, &u));
  PetscCall(VecGetArray(d3, &a));
  for (PetscInt i = 0; i < n; ++i) {
    a[3 * i]     = u[2 * i];
    a[3 * i + 1] = u[2 * i + 1];
    a[3 * i + 2] = 0.0;
  }
  PetscCall(VecRestoreArray(d3, &a));
  PetscCall(VecRestoreArrayRead(F->disp, &u));
  PetscCall(VecView(d3, v));
  PetscCall(VecDestroy(&d3));
  PetscCall(VecDuplicate(F->vm, &c));
  for (PetscInt k = 0; k < 4; ++k) {
    PetscCall(VecStrideGather(F->stress, k, c, INSERT_VALUES));
    PetscCall(PetscObjectSetName((PetscObject)c, XdmfBodyScalars[k])); /* stress_xx, _yy, _zz, _xy: the XDMF names */
    PetscCall(VecView(c, v));
  }
  PetscCall(VecSet(c, (PetscScalar)NAN)); /* the contact fields a body has not (xdmf.h) */
  PetscCall(PetscObjectSetName((PetscObject)c, "xdmf_nan"));
  PetscCall(VecView(c, v));
  PetscCall(VecDestroy(&c));
  PetscFunctionReturn(0);
}

static PetscErrorCode WriteHDF5(Problem p, BodyNodalFields F[], const char path[])
{
  PetscViewer v;
  char       *opts, version[256];
  PetscMPIInt size;
  PetscInt    its;
  const char *names[5] = {"time_mesh", "time_setup", "time_solve", "time_output", "time_total"};

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5Open(p->comm, path, FILE_MODE_WRITE, &v));
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    char group[2 * CONTACT_NAME_LEN];
    PetscCall(PetscSNPrintf(group, sizeof(group), "/bodies/%s", p->bodies[i]->name));
    PetscCall(PetscViewerHDF5PushGroup(v, group));
    PetscCall(VecView(F[i].coords, v));
    PetscCall(VecView(F[i].disp, v));
    PetscCall(VecView(F[i].stress, v));
    PetscCall(VecView(F[i].vm, v));
    PetscCall(WriteXDMFFields(&F[i], v));
    PetscCall(ISView(F[i].topo, v));
    PetscCall(PetscViewerHDF5WriteAttribute(v, group, "cell_type", PETSC_STRING, p->bodies[i]->simplex ? "Tri6" : "Quad9"));
    PetscCall(PetscViewerHDF5WriteAttribute(v, group, "E", PETSC_REAL, &p->bodies[i]->E));
    PetscCall(PetscViewerHDF5WriteAttribute(v, group, "nu", PETSC_REAL, &p->bodies[i]->nu));
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermWriteHDF5(p->terms[t], p->bodies, v));
  PetscCall(PetscOptionsGetAll(NULL, &opts));
  PetscCall(PetscGetVersion(version, sizeof(version)));
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  PetscCall(PetscViewerHDF5PushGroup(v, "/metadata"));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/metadata", "scene", PETSC_STRING, p->scene));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/metadata", "run_id", PETSC_STRING, set.runId));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/metadata", "options", PETSC_STRING, opts));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/metadata", "petsc_version", PETSC_STRING, version));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/metadata", "ranks", PETSC_INT, &size));
  its = p->iterations; /* over all stages */
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/metadata", "iterations", PETSC_INT, &its));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/metadata", "energy", PETSC_REAL, &p->energy));
  for (PetscInt k = 0; k < 4; ++k) PetscCall(PetscViewerHDF5WriteAttribute(v, "/metadata", names[k], PETSC_REAL, &p->time[k]));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(PetscFree(opts));
  PetscCall(PetscViewerDestroy(&v));
  PetscFunctionReturn(0);
}

void ContactJSONReal(FILE *fp, PetscReal v)
{
  if (PetscIsInfOrNanReal(v)) fprintf(fp, "null");
  else fprintf(fp, "%.17g", (double)v);
}

static PetscErrorCode WriteJSON(Problem p, BodyNodalFields F[], PetscBool converged, const char path[])
{
  PetscMPIInt        rank, size;
  PetscInt           its, dofs;
  TaoConvergedReason reason;
  TaoType            type;
  PetscReal          umax = 0, unorm2 = 0;
  const char        *tnames[5] = {"mesh", "setup", "solve", "output", "total"};

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  its = p->iterations; /* over all stages */
  PetscCall(TaoGetConvergedReason(p->tao, &reason));
  PetscCall(TaoGetType(p->tao, &type));
  PetscCall(VecGetSize(p->X, &dofs));
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    umax = PetscMax(umax, F[i].umax);
    unorm2 += F[i].unorm2;
  }
  if (rank == 0) {
    FILE *fp = fopen(path, "w");
    PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write summary %s", path);
    fprintf(fp, "{\n  \"scene\": \"%s\",\n  \"run_id\": \"%s\",\n  \"dofs\": %d,\n  \"ranks\": %d,\n  \"tao_type\": \"%s\",\n", p->scene, set.runId, (int)dofs, (int)size, type);
    fprintf(fp, "  \"tao_reason\": \"%s\",\n  \"converged\": %s,\n  \"iterations\": %d,\n", TaoConvergedReasons[reason], converged ? "true" : "false", (int)its);
    fprintf(fp, "  \"function_evaluations\": %d,\n  \"hessian_evaluations\": %d,\n", (int)p->nEnergyEvals, (int)p->nHessianEvals);
    fprintf(fp, "  \"stages\": %d,\n  \"load_cutbacks\": %d,\n", (int)p->stagesDone, (int)p->cutbacks);
    fprintf(fp, "  \"energy\": ");
    ContactJSONReal(fp, p->energy);
    fprintf(fp, ",\n  \"gradient_norm\": ");
    ContactJSONReal(fp, p->gnorm);
    fprintf(fp, ",\n  \"max_displacement\": ");
    ContactJSONReal(fp, umax);
    fprintf(fp, ",\n  \"displacement_norm\": ");
    ContactJSONReal(fp, PetscSqrtReal(unorm2));
    fprintf(fp, ",\n  \"reactions\": {");
    for (PetscInt i = 0, first = 1; i < p->nbodies; ++i)
      for (PetscInt j = 0; j < p->bodies[i]->nbc; ++j, first = 0) {
        fprintf(fp, "%s\n    \"%s:%s\": [", first ? "" : ",", p->bodies[i]->name, p->bodies[i]->bc[j].group);
        ContactJSONReal(fp, p->bodies[i]->bc[j].reaction[0]);
        fprintf(fp, ", ");
        ContactJSONReal(fp, p->bodies[i]->bc[j].reaction[1]);
        fprintf(fp, "]");
      }
    fprintf(fp, "\n  }");
    if (p->nterms) { /* the first pair's figures at top level, then every pair */
      PetscCall(EnergyTermWriteJSON(p->terms[0], p->bodies, fp, PETSC_TRUE));
      fprintf(fp, ",\n  \"contact\": {");
      for (PetscInt t = 0; t < p->nterms; ++t) {
        fprintf(fp, "%s\n    \"%s\": ", t ? "," : "", p->terms[t]->name);
        PetscCall(EnergyTermWriteJSON(p->terms[t], p->bodies, fp, PETSC_FALSE));
      }
      fprintf(fp, "\n  }");
    }
    fprintf(fp, ",\n  \"bodies\": {");
    for (PetscInt i = 0; i < p->nbodies; ++i) {
      Body            b   = p->bodies[i];
      const BodyErrors *e = &F[i].err;
      fprintf(fp, "%s\n    \"%s\": {\"dofs\": %d, \"cells\": %d, \"nodes\": %d, \"cell_type\": \"%s\", \"energy\": ", i ? "," : "", b->name, (int)b->nglobal, (int)b->ncellsGlobal, (int)F[i].nnodes, b->simplex ? "Tri6" : "Quad9");
      ContactJSONReal(fp, p->bodyEnergy[i]);
      fprintf(fp, ", \"max_displacement\": ");
      ContactJSONReal(fp, F[i].umax);
      fprintf(fp, ", \"mesh\": \"%s\", \"h\": ", b->msh);
      ContactJSONReal(fp, b->h);
      if (b->hasExact) { /* each error with the exact solution's norm */
        const char     *keys[6] = {"l2_error", "l2_norm", "energy_error", "energy_norm", "stress_l2_error", "stress_l2_norm"};
        const PetscReal vals[6] = {e->l2, e->l2norm, e->energy, e->energynorm, e->stress, e->stressnorm};
        fprintf(fp, ", \"exact\": \"%s\"", b->exact.name);
        for (PetscInt k = 0; k < 6; ++k) {
          fprintf(fp, ", \"%s\": ", keys[k]);
          ContactJSONReal(fp, vals[k]);
        }
      }
      fprintf(fp, "}");
    }
    fprintf(fp, "\n  },\n");
    if (p->accuracyTarget > 0) {
      fprintf(fp, "  \"accuracy_target\": ");
      ContactJSONReal(fp, p->accuracyTarget);
      fprintf(fp, ",\n  \"error_estimate\": ");
      ContactJSONReal(fp, p->errorEstimate);
      fprintf(fp, ",\n  \"adapt_steps\": [");
      for (PetscInt k = 0; k < p->nAccuracySteps; ++k) {
        const AccuracyStep *a = &p->accuracySteps[k];
        fprintf(fp, "%s\n    {\"dofs\": %d, \"iterations\": %d, \"solve_time\": ", k ? "," : "", (int)a->dofs, (int)a->iterations);
        ContactJSONReal(fp, a->tsolve);
        fprintf(fp, ", \"error_estimate\": ");
        ContactJSONReal(fp, a->estimate);
        fprintf(fp, ", \"profile_estimate\": ");
        ContactJSONReal(fp, a->profile);
        fprintf(fp, ", \"force_estimate\": ");
        ContactJSONReal(fp, a->force);
        fprintf(fp, "}");
      }
      fprintf(fp, "\n  ],\n");
    }
    if (p->taylor) {
      fprintf(fp, "  \"taylor\": {\"gradient_order\": ");
      ContactJSONReal(fp, p->taylorRates[0]);
      fprintf(fp, ", \"hessian_order\": ");
      ContactJSONReal(fp, p->taylorRates[1]);
      fprintf(fp, ", \"eps\": [");
      for (PetscInt k = 0; k < p->taylorN; ++k) fprintf(fp, "%s%.17g", k ? ", " : "", (double)p->taylorEps[k]);
      fprintf(fp, "], \"gradient_remainder\": [");
      for (PetscInt k = 0; k < p->taylorN; ++k) fprintf(fp, "%s%.17g", k ? ", " : "", (double)p->taylorRemainders[0][k]);
      fprintf(fp, "], \"hessian_relative_remainder\": [");
      for (PetscInt k = 0; k < p->taylorN; ++k) fprintf(fp, "%s%.17g", k ? ", " : "", (double)p->taylorRemainders[1][k]);
      fprintf(fp, "]},\n");
    }
    fprintf(fp, "  \"time\": {");
    for (PetscInt k = 0; k < 5; ++k) {
      fprintf(fp, "%s\"%s\": ", k ? ", " : "", tnames[k]);
      ContactJSONReal(fp, p->time[k]);
    }
    fprintf(fp, "}\n}\n");
    PetscCheck(!ferror(fp) && !fclose(fp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "error writing %s", path);
  }
  PetscFunctionReturn(0);
}

/* Writes the HDF5 + XDMF (unless -output none) and the JSON summary (unless
   -summary none) of the set ContactOutputOpen() opened, each to its
   temporary, then publishes them (OutputCommit). */
PetscErrorCode ProblemWriteOutput(Problem p, PetscBool converged)
{
  BodyNodalFields F[CONTACT_MAX_BODIES];
  PetscLogDouble  t0, t1;

  PetscFunctionBeginUser;
  PetscCheck(set.open, p->comm, PETSC_ERR_ORDER, "ContactOutputOpen() was not called");
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogStagePush(contactLog.output));
  PetscCall(PetscLogEventBegin(contactLog.writeOutput, 0, 0, 0, 0));
  PetscCall(PetscMemzero(F, sizeof(F)));
  PetscCall(ProblemScatterToBodies(p, p->X)); /* the fields of the solution */
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyComputeNodalFields(p->bodies[i], p->bodies[i]->Xl, &F[i]));
  if (set.h5[0]) {
    PetscCall(WriteHDF5(p, F, set.htmp));
    PetscCall(WriteXDMF(p, F, set.xtmp, set.h5, set.runId));
  }
  PetscCall(PetscTime(&t1));
  p->time[3] = t1 - t0;
  p->time[4] = t1 - p->t0;
  if (set.json[0]) PetscCall(WriteJSON(p, F, converged, set.jtmp));
  PetscCall(OutputCommit(p->comm));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyNodalFieldsDestroy(&F[i]));
  PetscCall(PetscLogEventEnd(contactLog.writeOutput, 0, 0, 0, 0));
  PetscCall(PetscLogStagePop());
  if (set.h5[0]) PetscCall(PetscPrintf(p->comm, "Wrote %s and %s\n", set.h5, set.xdmf));
  if (set.json[0]) PetscCall(PetscPrintf(p->comm, "Wrote %s\n", set.json));
  PetscFunctionReturn(0);
}
