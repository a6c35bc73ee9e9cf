static const char help[] = "Frictionless contact between 2D linear-elastic bodies by the penalty method,\n"
                           "minimised with TAO. A scene is an options file: see meshes/hertz/hertz.opts.\n"
                           "  mpiexec -n 2 bin/contact -options_file meshes/hertz/hertz.opts -tao_monitor\n\n";

#include "accuracy.h"
#include "progress.h"
#include "contactpair.h"
#include "options.h"

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
      char        option[1024];

      /* a bad option value: the same on every rank, so reported once */
      if (ContactOptionsDescribeValueError(fun, mess, option, sizeof(option))) {
        MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
        mess = option;
      } else if (comm != PETSC_COMM_SELF) MPI_Comm_rank(comm, &rank);
      if (!rank) {
        fprintf(stderr, "contact: error: %s\n", mess ? mess : "unknown");
        fflush(stderr);
      }
    }
    return n;
  }
  return PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, ctx);
}

static PetscErrorCode Run(int *status)
{
  Problem        problem;
  Accuracy       acc;
  PetscBool      converged = PETSC_FALSE, meshOnly = PETSC_FALSE, help;
  PetscLogDouble t0, t1, t2, t3;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t0));
  PetscCall(ContactInitializeLogging());
  PetscCall(ExactSolutionRegisterAll());
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "Program options", NULL);
  PetscCall(PetscOptionsBool("-mesh_only", "Generate the scene's meshes and stop", NULL, meshOnly, &meshOnly, NULL));
  PetscOptionsEnd();
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  PetscCall(ContactProgressSetUp(PETSC_COMM_WORLD));
  PetscCall(AccuracyCreate(PETSC_COMM_WORLD, &acc));
  PetscCall(AccuracySetFromOptions(acc));
  if (!help && !meshOnly && AccuracyIsSet(acc)) { /* a sequence of problems */
    PetscCall(AccuracySolve(acc, t0, status));
    PetscCall(AccuracyDestroy(&acc));
    PetscFunctionReturn(0);
  }
  PetscCall(AccuracyDestroy(&acc));
  PetscCall(ProblemCreate(PETSC_COMM_WORLD, &problem));
  problem->meshOnly = meshOnly;
  PetscCall(ContactProgressPhase("meshing", "scene and meshes"));
  PetscCall(ProblemSetFromOptions(problem));
  if (help) { /* every option listed with the default a run would use; nothing meshed, solved or written */
    PetscCall(ProblemCreateSolver(problem));
    converged = PETSC_TRUE;
  } else if (!meshOnly) {
    PetscInt n;
    PetscCall(ContactProgressPhase("set-up", "set-up: reading and distributing the meshes, the stiffness"));
    PetscCall(ProblemSetUp(problem));
    PetscCall(VecGetSize(problem->X, &n));
    PetscCall(PetscTime(&t1));
    PetscCall(ContactProgressPhase("the solve", "solve: %" PetscInt_FMT " dofs", n));
    PetscCall(ProblemSolve(problem, &converged));
    PetscCall(PetscTime(&t2));
    PetscCall(ContactProgressPhase("post-processing", "post-processing the converged state"));
    PetscCall(ProblemPostProcess(problem, problem->X, converged));
    if (problem->taylor) {
      PetscCall(ContactProgressPhase("the Taylor test", "Taylor test"));
      PetscCall(ProblemTaylorTest(problem));
    }
    for (PetscInt i = 0; i < problem->nbodies; ++i) problem->time[0] += problem->bodies[i]->tmesh;
    problem->time[1] = (t1 - t0) - problem->time[0];
    problem->time[2] = t2 - t1;
    problem->t0      = t0;
    PetscCall(ProblemCheckUnusedOptions(problem, PETSC_TRUE));
    if (converged) {
      PetscCall(ContactProgressPhase("the output", "output"));
      PetscCall(ProblemWriteOutput(problem, converged));
    }
    else {
      TaoConvergedReason reason;
      char               why[PETSC_MAX_PATH_LEN] = "", cut[128] = "";
      PetscCall(TaoGetConvergedReason(problem->tao, &reason));
      for (PetscInt t = 0; t < problem->nterms && !why[0]; ++t) PetscCall(EnergyTermDiagnose(problem->terms[t], sizeof(why), why));
      if (problem->cutbacks > 0) PetscCall(PetscSNPrintf(cut, sizeof(cut), "; the load cut back %" PetscInt_FMT " time%s, solved up to %.4g of it", problem->cutbacks, problem->cutbacks > 1 ? "s" : "", (double)problem->loadDone));
      PetscCall(PetscFPrintf(PETSC_COMM_WORLD, PETSC_STDERR, "contact: the solve did not converge (%s%s)%s%s; no output written\n", TaoConvergedReasons[reason], cut, why[0] ? ": " : "", why));
      ContactOutputDiscard();
    }
    PetscCall(PetscTime(&t3));
    problem->time[4] = t3 - t0;
  } else converged = PETSC_TRUE;
  PetscCall(ProblemDestroy(&problem));
  *status = converged ? 0 : 2;
  PetscFunctionReturn(0);
}

/* MPI is started before PETSc so that the options files can be read first
   (options.c): a bad file is one line, not a traceback from PetscInitialize(). */
int main(int argc, char **argv)
{
  PetscErrorCode ierr;
  int            status = 1, provided;
  char           err[4096];

  MPI_Init_thread(&argc, &argv, PETSC_MPI_THREAD_REQUIRED, &provided);
  if (ContactOptionsExpandFiles(MPI_COMM_WORLD, &argc, &argv, err, sizeof(err))) {
    int rank;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (!rank) fprintf(stderr, "contact: error: %s\n", err);
    ContactOptionsFinalize();
    MPI_Finalize();
    return 1;
  }
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscPushErrorHandler(ContactErrorHandler, NULL));
  PetscCall(ContactOutputInstallSignalHandlers());
  ierr = Run(&status);
  if (ierr) {
    status = 1;
    ContactOutputDiscard();
  }
  PetscCall(ExactSolutionFinalize());
  PetscCall(ContactFormulationFinalize());
  PetscCall(PetscFinalize());
  ContactOptionsFinalize();
  MPI_Finalize();
  return status;
}
