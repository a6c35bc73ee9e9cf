/* The solve, as the orchestrator of the solver's files: TAO created with
   the program's defaults for its type (the Newton step's solve,
   newtonstep.c; L-BFGS's H0 and schedule, lmvm.c; coupled force control's
   penalty continuation, forcesolve.c), then run: staged (staging.c), or
   under force control (forcesolve.c), and its one line of report. It calls
   each of them; none of them calls it. */
#include "solve.h"
#include "problem.h"
#include "progress.h"
#include "newtonstep.h"
#include "lmvm.h"
#include "forcestop.h"
#include "slidewatch.h"
#include "forceborder.h"
#include "forcesolve.h"
#include "staging.h"

/* TAO's convergence test: TAO's own (or L-BFGS's decrement test, lmvm.c),
   then the forces' test of a last stage (forcestop.c) and the watch for a
   contact that slides without end (slidewatch.c). */
static PetscErrorCode ProblemConvergenceTest(Tao tao, void *ctx)
{
  Problem p = (Problem)ctx;

  PetscFunctionBeginUser;
  PetscCall(ProblemLMVMConvergenceTest(p, tao));
  PetscCall(ProblemForceStopTest(p, tao));
  PetscCall(ProblemSlideWatchTest(p, tao));
  PetscFunctionReturn(0);
}

/* The TAO solver with the program's defaults, then the options. The type is
   looked up first (TaoSetFromOptions() lists and checks it) because the
   defaults depend on it. Without a set-up problem (-help) the solver is only
   configured, so that -help lists the TAO options with the defaults a solve
   would use. */
PetscErrorCode ProblemCreateSolver(Problem p)
{
  char      type[256] = TAONLS;
  PetscBool newton;

  PetscFunctionBeginUser;
  PetscCall(TaoCreate(p->comm, &p->tao));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-tao_type", type, sizeof(type), NULL));
  newton = (PetscBool)(!strcmp(type, TAONLS) || !strcmp(type, TAONTR));
  /* Newton with the Cholesky-factored Gauss-Newton Hessian: the fastest type
     that converges on every scene and extreme of the tests (docs/solver.md, "The solver") */
  PetscCall(TaoSetType(p->tao, newton ? type : TAONLS));
  /* scale-free default: stop when |g| falls by 1e-8 from its initial value */
  PetscCall(TaoSetTolerances(p->tao, 0.0, 0.0, 1e-8));
  if (newton) PetscCall(ProblemSetNewtonDefaults(p));
  if (newton) PetscCall(ProblemSetNewtonContinuation(p));
  if (p->X) {
    if (!p->Htao && p->fc.coupled) PetscCall(ForceBorderMatCreate(p, p->H, NULL, &p->Htao));
    else if (!p->Htao) {
      PetscCall(PetscObjectReference((PetscObject)p->H));
      p->Htao = p->H;
    }
    PetscCall(VecZeroEntries(p->X));
    PetscCall(TaoSetSolution(p->tao, p->X));
    PetscCall(TaoSetObjectiveAndGradient(p->tao, NULL, ProblemComputeObjectiveGradient, p));
    PetscCall(TaoSetHessian(p->tao, p->Htao, p->Htao, ProblemComputeHessian, p));
  }
  PetscCall(ProblemSetLMVMDefaults(p, type));
  if (p->K) PetscCall(ProblemSetControlContinuation(p));
  PetscCall(TaoSetFromOptions(p->tao));
  if (ContactProgressEnabled()) PetscCall(TaoSetMonitor(p->tao, ContactProgressTaoMonitor, NULL, NULL));
  if (p->K) PetscCall(ProblemSetLMVMInitialHessian(p));
  if (p->X) PetscCall(TaoSetConvergenceTest(p->tao, ProblemConvergenceTest, p));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSolve(Problem p, PetscBool *converged)
{
  TaoConvergedReason reason;
  PetscInt           its;
  TaoType            type;

  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(contactLog.solve));
  PetscCall(ProblemCreateSolver(p));
  PetscCall(SubdomainDestroy(&p->sub)); /* the substructured step has consumed it, if it is the step */
  PetscCall(ProblemCheckUnusedOptions(p, PETSC_FALSE));
  if (p->fc.n) PetscCall(ProblemSolveControlled(p, &its, &reason));
  else PetscCall(ProblemSolveStaged(p, &its, &reason));
  p->res.iterations = its;
  p->res.reason     = reason;
  PetscCall(TaoGetType(p->tao, &type));
  *converged = reason > 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(PetscPrintf(p->comm, "TAO %s: %s after %" PetscInt_FMT " iterations, %" PetscInt_FMT " energy evaluations, %" PetscInt_FMT " Hessian evaluations", type, TaoConvergedReasons[reason], its, p->res.nEnergyEvals, p->res.nHessianEvals));
  if (p->cfg->newton.iterative) {
    PetscInt lits;
    PetscCall(TaoGetLinearSolveIterations(p->tao, &lits));
    PetscCall(PetscPrintf(p->comm, ", %" PetscInt_FMT " CG iterations", lits));
  }
  if (p->fc.n) PetscCall(PetscPrintf(p->comm, " (force control: %" PetscInt_FMT " solves)", p->res.controlSolves));
  else if (p->res.cutbacks > 0) PetscCall(PetscPrintf(p->comm, " (%" PetscInt_FMT " stages; the load cut back %" PetscInt_FMT " time%s, the last converged load %g)", p->res.stagesDone, p->res.cutbacks, p->res.cutbacks > 1 ? "s" : "", (double)p->res.loadDone));
  else if (p->cfg->load.stages * p->sched.loadSteps * p->sched.penaltyStages > 1) PetscCall(PetscPrintf(p->comm, " (%" PetscInt_FMT " of %" PetscInt_FMT " stages)", p->res.stagesDone, p->cfg->load.stages * p->sched.loadSteps * p->sched.penaltyStages)); /* -load_stages: each load stage's -load_steps */
  PetscCall(PetscPrintf(p->comm, "\n"));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}
