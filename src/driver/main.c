/* The program: PETSc's start and end, the error handler, the log events and
   stages, and the pipeline (run.c) run once or under -accuracy (accuracy.c). */
static const char help[] = "Contact between 2D elastic bodies by the penalty method, frictionless or with Coulomb friction,\n"
                           "minimised with TAO. A scene is an options file: see meshes/hertz/hertz.opts.\n"
                           "  mpiexec -n 2 bin/contact -options_file meshes/hertz/hertz.opts -tao_monitor\n\n";

#include "accuracy.h"
#include "blaskernel.h"
#include "progress.h"
#include "contactpair.h"
#include "options.h"
#include "outputset.h"
#include "forcesolve.h"
#include "material.h"

ContactLog contactLog;

PetscErrorCode ContactInitializeLogging(void)
{
  PetscClassId id;

  PetscFunctionBeginUser;
  PetscCall(PetscClassIdRegister("Contact", &id));
  PetscCall(PetscLogStageRegister("Mesh", &contactLog.mesh));
  PetscCall(PetscLogStageRegister("Setup", &contactLog.setup));
  PetscCall(PetscLogStageRegister("Solve", &contactLog.solve));
  PetscCall(PetscLogStageRegister("PostProcess", &contactLog.postprocess));
  PetscCall(PetscLogStageRegister("Output", &contactLog.output));
  PetscCall(PetscLogEventRegister("ElasEnergyGrad", id, &contactLog.elasEnergyGrad));
  PetscCall(PetscLogEventRegister("ElasHessian", id, &contactLog.elasHessian));
  PetscCall(PetscLogEventRegister("MeshGenerate", id, &contactLog.meshGenerate));
  PetscCall(PetscLogEventRegister("MeshPartition", id, &contactLog.partition));
  PetscCall(PetscLogEventRegister("WriteOutput", id, &contactLog.writeOutput));
  PetscFunctionReturn(0);
}

/* Errors caused by the input (options, files) are reported in one line on the
   first rank of the communicator that raised them; anything else gets PETSc's
   full traceback. */
static PetscBool IsInputError(PetscErrorCode n)
{
  switch (n) {
  case PETSC_ERR_USER: /* PETSc's options code: an unknown value of an enumerated option */
  case PETSC_ERR_USER_INPUT:
  case PETSC_ERR_FILE_OPEN:
  case PETSC_ERR_FILE_READ:
  case PETSC_ERR_FILE_WRITE:
  case PETSC_ERR_FILE_UNEXPECTED:
  case PETSC_ERR_ARG_OUTOFRANGE:
  case PETSC_ERR_ARG_UNKNOWN_TYPE:
  case PETSC_ERR_ARG_WRONG:
  case PETSC_ERR_NOT_CONVERGED:
  case PETSC_ERR_FP:
    return PETSC_TRUE;
  default:
    return PETSC_FALSE;
  }
}

static PetscErrorCode ContactErrorHandler(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  if (IsInputError(n)) {
    if (p == PETSC_ERROR_INITIAL) {
      PetscMPIInt rank = 0;
      char        option[2048];

      /* a bad option value, or an unknown choice of an enumerated option
         (PETSc raises it on PETSC_COMM_SELF): the same on every rank, so
         reported once */
      if (ContactOptionsDescribeValueError(fun, mess, option, sizeof(option))) {
        MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
        mess = option;
      } else if (n == PETSC_ERR_USER && mess && strstr(mess, "Unknown option")) MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
      else if (comm != PETSC_COMM_SELF) MPI_Comm_rank(comm, &rank);
      if (!rank) {
        fprintf(stderr, "contact: error: %s\n", mess ? mess : "unknown");
        fflush(stderr);
      }
    }
    return n;
  }
  return PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, ctx);
}

/* The pipeline once (run.h), or in -accuracy's loop. -help lists every
   option with the default a run would use: nothing is meshed, solved or
   written. */
static PetscErrorCode Run(int *status)
{
  Problem    problem;
  Accuracy   acc;
  RunOptions ro;
  RunRecord  rec;
  PetscBool  help;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&ro, sizeof(ro)));
  PetscCall(PetscMemzero(&rec, sizeof(rec)));
  PetscCall(PetscTime(&rec.start));
  rec.mark = rec.start;
  PetscCall(ContactInitializeLogging());
  PetscCall(ExactSolutionRegisterAll());
  PetscCall(MaterialRegisterAll());
  PetscCall(ForceControlRegisterAll());
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  PetscCall(BlasKernelSetFromOptions(PETSC_COMM_WORLD));
  PetscCall(ContactProgressSetUp(PETSC_COMM_WORLD));
  PetscCall(AccuracyCreate(PETSC_COMM_WORLD, &acc));
  PetscCall(AccuracySetFromOptions(acc));
  PetscCall(ContactProgressPhase("meshing", "scene and meshes"));
  PetscCall(RunCreateProblem(PETSC_COMM_WORLD, &problem));
  PetscCall(RunOptionsSetFromOptions(PETSC_COMM_WORLD, problem->cfg->scene.name, &ro));
  if (help) PetscCall(ProblemCreateSolver(problem));
  else if (ro.meshOnly) PetscCall(RunMesh(problem, NULL));
  else {
    /* the outputs locked and checked before meshing, so that a bad path or a busy set fails at once */
    PetscCall(ContactOutputOpen(PETSC_COMM_WORLD, ro.output, ro.summary, ro.outputWait));
    if (AccuracyIsSet(acc)) { /* the pipeline in a loop of refinements, from the scene's options on */
      PetscCall(AccuracySolve(acc, &problem, &rec));
    } else {
      PetscInt n;
      PetscCall(RunMesh(problem, NULL));
      PetscCall(ContactProgressPhase("set-up", "set-up: reading and distributing the meshes, the stiffness"));
      PetscCall(RunSetUp(problem, &rec));
      PetscCall(VecGetSize(problem->Xb, &n));
      PetscCall(ContactProgressPhase("the solve", "solve: %" PetscInt_FMT " dofs", n));
      PetscCall(RunSolve(problem, &rec, &rec.converged));
      /* not converged: the last iterate is post-processed for the report and the reason, and nothing is written */
      if (rec.converged) PetscCall(ContactProgressPhase("post-processing", "post-processing the converged state"));
      else PetscCall(ContactProgressPhase("post-processing", "post-processing the last iterate (the solve did not converge: nothing will be written)"));
      PetscCall(RunPostProcess(problem, rec.converged));
      if (rec.converged) PetscCall(ProblemView(problem)); /* the contact report: of a solution, or none */
      rec.status = rec.converged ? 0 : 2;
      PetscCall(RunFinish(problem, &rec));
    }
  }
  PetscCall(RunDestroyProblem(&problem));
  PetscCall(AccuracyDestroy(&acc));
  *status = rec.status;
  PetscFunctionReturn(0);
}

/* The BLAS kernel is chosen first (blaskernel.c: the program may start
   again on another). MPI is started before PETSc so that the options files
   can be read first (options.c): a bad file is one line, not a traceback from
   PetscInitialize(). -log_view's summary, printed by PetscFinalize(), is
   headed by the BLAS kernel's line. MPI's hardware discovery (hwloc) leaves
   out its OpenGL component, which probes every X display it can reach
   (:0, :1, ...): a solver has no use for one, and where a display it
   connected to goes away (a virtual X server shut down beside the run) Xlib
   ends the process ("X connection to :2 broken", once in CI). The user's
   HWLOC_COMPONENTS, if set, is kept. */
int main(int argc, char **argv)
{
  PetscErrorCode ierr;
  int            status = 1, provided;
  char           err[4096];
  PetscBool      logView = PETSC_FALSE;

  BlasKernelSelect(argc, argv);
  setenv("HWLOC_COMPONENTS", "-gl", 0);
  MPI_Init_thread(&argc, &argv, PETSC_MPI_THREAD_REQUIRED, &provided);
  if (ContactOptionsExpandFiles(MPI_COMM_WORLD, &argc, &argv, err, sizeof(err))) {
    int rank;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (!rank) fprintf(stderr, "contact: error: %s\n", err);
    ContactOptionsFinalize();
    MPI_Finalize();
    return 1;
  }
  /* the handler in place already while PetscInitialize() reads its own options
     (a number given without its value: options.h) */
  PetscCall(PetscPushErrorHandler(ContactErrorHandler, NULL));
  if (PetscInitialize(&argc, &argv, NULL, help)) {
    ContactOptionsFinalize();
    MPI_Finalize();
    return 1;
  }
  PetscCall(ContactOutputInstallSignalHandlers());
  ierr = Run(&status);
  if (ierr) {
    status = 1;
    ContactOutputDiscard();
  }
  PetscCall(ExactSolutionFinalize());
  PetscCall(MaterialFinalize());
  PetscCall(ContactFormulationFinalize());
  PetscCall(PetscOptionsHasName(NULL, NULL, "-log_view", &logView));
  if (logView) PetscCall(BlasKernelView(PETSC_COMM_WORLD));
  PetscCall(PetscFinalize());
  ContactOptionsFinalize();
  MPI_Finalize();
  return status;
}
