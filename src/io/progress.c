/* Progress lines on stderr, rank 0 only: "contact: [  12.3 s] solve: ...". A
   long run is never silent; a script's or a test's stderr stays quiet unless
   asked (-progress), so that a failure there is one line. */
#include <stdarg.h>
#include <unistd.h>
#include "progress.h"

static PetscBool      enabled;
static PetscMPIInt    rank;
static PetscLogDouble t0;
static char           phaseName[64] = "start-up";
static PetscReal      g0 = -1.0;

PetscErrorCode ContactProgressSetUp(MPI_Comm comm)
{
  PetscBool on = PETSC_FALSE, off = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t0));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscOptionsBegin(comm, NULL, "Progress options", NULL);
  PetscCall(PetscOptionsBool("-progress", "Print a line on stderr as each phase starts and at each Newton iteration (default: when stderr is a terminal)", NULL, on, &on, NULL));
  PetscCall(PetscOptionsBool("-quiet", "No progress lines", NULL, off, &off, NULL));
  PetscOptionsEnd();
  enabled = (PetscBool)(!off && (on || isatty(STDERR_FILENO)));
  PetscCallMPI(MPI_Bcast(&enabled, 1, MPIU_BOOL, 0, comm)); /* rank 0's terminal decides */
  PetscFunctionReturn(0);
}

PetscBool ContactProgressEnabled(void)
{
  return enabled;
}

const char *ContactProgressCurrentPhase(void)
{
  return phaseName;
}

static void Line(const char fmt[], va_list ap)
{
  PetscLogDouble t;

  if (PetscTime(&t)) t = t0;
  fprintf(stderr, "contact: [%7.1f s] ", (double)(t - t0));
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  fflush(stderr);
}

PetscErrorCode ContactProgressPhase(const char phase[], const char fmt[], ...)
{
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(phaseName, phase, sizeof(phaseName)));
  if (enabled && !rank) {
    va_list ap;
    va_start(ap, fmt);
    Line(fmt, ap);
    va_end(ap);
  }
  PetscFunctionReturn(0);
}

static void Say(const char fmt[], ...)
{
  va_list ap;

  va_start(ap, fmt);
  Line(fmt, ap);
  va_end(ap);
}

/* One line per Newton (TAO) iteration: the gradient norm against the first. */
PetscErrorCode ContactProgressTaoMonitor(Tao tao, void *ctx)
{
  PetscInt           its;
  PetscReal          f, gnorm, cnorm, step;
  TaoConvergedReason reason;

  PetscFunctionBeginUser;
  (void)ctx;
  if (!enabled || rank) PetscFunctionReturn(0);
  PetscCall(TaoGetSolutionStatus(tao, &its, &f, &gnorm, &cnorm, &step, &reason));
  if (!its || g0 < 0) g0 = gnorm;
  Say("solve: iteration %3" PetscInt_FMT ", gradient norm %.3e (%.1e of the first)", its, (double)gnorm, (double)(g0 > 0 ? gnorm / g0 : 0.0));
  PetscFunctionReturn(0);
}
