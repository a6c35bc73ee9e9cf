/* The output set of a run: its HDF5 file, the XDMF file beside it and its
   JSON summary (what goes into them: src/driver/results.c). The files of a
   run are one set, so that two runs never mix theirs and a
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
     missing directories only the default out/ is created. The XDMF file's
     temporary holds 1 MiB until it is written, room for a failed HDF5 write
     to close its file (outputwrite.c); a disk without it fails here too.
   - the files are written under the temporary names, carry the run id
     (/metadata:run_id, "run_id", an XML comment) and are renamed at the end,
     the XDMF file last (it names the HDF5 file), with the signals held so that
     a Ctrl-C renames all or none; then the lock is removed.
   - a failed or interrupted run removes its temporaries and its lock. */
#include "outputset.h"
#include "progress.h"
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>
#include <sys/file.h>
#include <sys/stat.h>

#define MAX_PENDING  3
#define MAX_LOCKS    2
#define OUT_PATH_LEN (PETSC_MAX_PATH_LEN + 16)
#define OUT_MSG_LEN  CONTACT_OUTPUT_MSG_LEN
#define OUTPUT_RESERVE (1 << 20) /* bytes; HDF5's metadata of a scene is 100 to 200 kB */

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

/* Where the signal handler writes: stderr, or the real stderr while a
   library's output is held back (outputwrite.c). */
static volatile sig_atomic_t messageFd = STDERR_FILENO;

void ContactOutputSetMessageFd(int fd)
{
  messageFd = fd;
}

static void Say(const char *s)
{
  ssize_t r = write(messageFd, s, strlen(s));
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

PetscErrorCode ContactOutputCheckOnRoot(MPI_Comm comm, int code, char msg[])
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

/* Rank 0: room for the HDF5 file to close after a failed write, held in the
   XDMF file's temporary until that file is written (outputwrite.c): HDF5
   1.10 flushes its metadata when it closes a file, and if that flush fails
   too, it keeps the file's id over freed memory and crashes in MPI_Finalize().
   A disk without this room fails here, before meshing. */
static int Allocate(const char path[], off_t bytes, PetscBool keep)
{
  int fd = open(path, O_WRONLY | O_CLOEXEC), e;

  if (fd < 0) return errno;
  e = posix_fallocate(fd, 0, bytes);
  if (!keep && ftruncate(fd, 0) && !e) e = errno;
  close(fd);
  return e;
}

static int Reserve(const char opt[], const char path[], const char name[], char msg[])
{
  const int e = Allocate(path, OUTPUT_RESERVE, PETSC_TRUE);

  if (!e) return 0;
  snprintf(msg, OUT_MSG_LEN, "option %s: cannot write %s: %s", opt, name, strerror(e));
  return PETSC_ERR_FILE_WRITE;
}

PetscErrorCode ContactOutputCheckRoom(MPI_Comm comm, size_t bytes)
{
  PetscMPIInt rank;
  int         code = 0;
  char        msg[OUT_MSG_LEN] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    const int e = Allocate(set.htmp, (off_t)bytes, PETSC_FALSE);
    if (e) {
      snprintf(msg, OUT_MSG_LEN, "cannot write %s: %s", set.h5, strerror(e));
      code = PETSC_ERR_FILE_WRITE;
    }
  }
  PetscCall(ContactOutputCheckOnRoot(comm, code, msg));
  PetscFunctionReturn(0);
}

void ContactOutputReleaseReserve(void)
{
  if (set.open && set.xtmp[0]) (void)!truncate(set.xtmp, 0);
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
  PetscCall(ContactOutputCheckOnRoot(comm, code, msg));
  PetscCall(OutputLock(comm, nwant, want, what, wait));
  if (!rank) {
    if (!noh5) code = CreateTemporary("-output", set.htmp, msg);
    if (!code && !noh5) code = CreateTemporary("-output", set.xtmp, msg);
    if (!code && !nojs) code = CreateTemporary("-summary", set.jtmp, msg);
    if (!code && !noh5) code = Reserve("-output", set.xtmp, set.h5, msg);
  }
  PetscCall(ContactOutputCheckOnRoot(comm, code, msg));
  set.open = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* Collective: the renames that publish the set, the XDMF file last, with the
   signals held (rank 0), then the lock removed. */
PetscErrorCode ContactOutputCommit(MPI_Comm comm)
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
  PetscCall(ContactOutputCheckOnRoot(comm, code, msg));
  npending = 0;
  set.open = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode ContactOutputGetFiles(ContactOutputFiles *f)
{
  PetscFunctionBeginUser;
  PetscCheck(set.open, PETSC_COMM_SELF, PETSC_ERR_ORDER, "ContactOutputOpen() was not called");
  f->h5    = set.h5;
  f->xdmf  = set.xdmf;
  f->json  = set.json;
  f->htmp  = set.htmp;
  f->xtmp  = set.xtmp;
  f->jtmp  = set.jtmp;
  f->runId = set.runId;
  PetscFunctionReturn(0);
}
