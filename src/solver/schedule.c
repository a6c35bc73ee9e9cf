/* The solve's schedule (p->sched), written here alone: its load steps and
   penalty continuation, as the options give them (-load_steps,
   -penalty_stages, -penalty_start, -lmvm_decrement_rtol) or, where the user
   gave none, as the solver chooses them at its set-up (a program-chosen
   penalty: run.c; Newton on a stiff penalty: problem.c; L-BFGS: lmvm.c;
   coupled force control: forcesolve.c), and the one stage that force
   control's solves from a converged state run (forcesolve.c, forceouter.c).
   The staged solve (staging.c) reads it. The options of the load history
   and of the continuation are read here too. */
#include "schedule.h"

PetscErrorCode LoadOptionsSetFromOptions(MPI_Comm comm, LoadOptions *o)
{
  PetscFunctionBeginUser;
  o->steps    = 1;
  o->stages   = 1;
  o->cutbacks = 4;
  o->path     = PETSC_FALSE;
  PetscOptionsBegin(comm, NULL, "Load stepping options", NULL);
  PetscCall(PetscOptionsInt("-load_steps", "Load stepping: solve with the Dirichlet values and loads scaled by 1/n, 2/n, ..., 1, each from the last", NULL, o->steps, &o->steps, NULL));
  PetscCall(PetscOptionsInt("-load_stages", "Load history: every -<body>_bc_<group>_values, -<body>_load_<group>_traction and _pressure gives this many end values per component, stage-major: stage 1's components, then stage 2's (x1,y1,x2,y2,...); each stage ramps linearly from the last one's end in -load_steps increments", NULL, o->stages, &o->stages, NULL));
  PetscCall(PetscOptionsInt("-load_cutbacks", "Automatic cutback: a load stage whose line search fails is retried from the last converged state with half the load increment, at most this many times in all (0: off)", NULL, o->cutbacks, &o->cutbacks, NULL));
  PetscCall(PetscOptionsBool("-load_path", "Record the load path in the JSON summary's load_path: at rest and at each converged load step, the load factor, the energy and every Dirichlet group's reaction; each load step's last stage then stops at the final tolerance, as the last load's", NULL, o->path, &o->path, NULL));
  PetscOptionsEnd();
  PetscCheck(o->steps >= 1, comm, PETSC_ERR_USER_INPUT, "option -load_steps: must be >= 1, got %" PetscInt_FMT, o->steps);
  PetscCheck(o->stages >= 1 && o->stages <= CONTACT_MAX_STAGES, comm, PETSC_ERR_USER_INPUT, "option -load_stages: must be in [1, %d], got %" PetscInt_FMT, CONTACT_MAX_STAGES, o->stages);
  PetscCheck(o->cutbacks >= 0, comm, PETSC_ERR_USER_INPUT, "option -load_cutbacks: must be >= 0, got %" PetscInt_FMT, o->cutbacks);
  PetscFunctionReturn(0);
}

PetscErrorCode PenaltyOptionsSetFromOptions(MPI_Comm comm, PenaltyOptions *o)
{
  PetscFunctionBeginUser;
  o->stages = 1;
  o->start  = 1e-2;
  PetscOptionsBegin(comm, NULL, "Penalty continuation options", NULL);
  PetscCall(PetscOptionsInt("-penalty_stages", "Penalty continuation: k_p raised geometrically in this many stages, each from the last (with -contact_penalty auto: 2; with Newton where k_p h / E* exceeds 1e7: 2, the first at 1000; with lmvm/blmvm: 3, more where k_p h / E* exceeds 1000, a factor of at most 32 a stage)", NULL, o->stages, &o->stages, &o->stagesSet));
  PetscCall(PetscOptionsReal("-penalty_start", "Continuation: k_p of the first stage relative to the scene's (with -contact_penalty auto: 0.03; with lmvm/blmvm: 0.001, or where k_p h / E* is 1 if lower)", NULL, o->start, &o->start, &o->startSet));
  PetscOptionsEnd();
  PetscCheck(o->stages >= 1, comm, PETSC_ERR_USER_INPUT, "option -penalty_stages: must be >= 1, got %" PetscInt_FMT, o->stages);
  PetscCheck(o->start > 0 && o->start <= 1, comm, PETSC_ERR_USER_INPUT, "option -penalty_start: must be in (0, 1], got %g", (double)o->start);
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemScheduleSetUp(Problem p)
{
  PetscFunctionBeginUser;
  p->sched.loadSteps     = p->cfg->load.steps;
  p->sched.penaltyStages = p->cfg->penalty.stages;
  p->sched.penaltyStart  = p->cfg->penalty.start;
  p->sched.decrementRtol = p->cfg->lmvm.decrementRtol;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetPenaltyContinuation(Problem p, PetscInt stages, PetscReal start)
{
  PetscFunctionBeginUser;
  if (!p->cfg->penalty.stagesSet) p->sched.penaltyStages = stages;
  if (!p->cfg->penalty.startSet) p->sched.penaltyStart = start;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetDecrementTest(Problem p, PetscReal rtol)
{
  PetscFunctionBeginUser;
  p->sched.decrementRtol = rtol;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemScheduleOneStage(Problem p, ProblemSchedule *saved)
{
  PetscFunctionBeginUser;
  *saved                 = p->sched;
  p->sched.loadSteps     = 1;
  p->sched.penaltyStages = 1;
  PetscFunctionReturn(0);
}

/* The load steps and penalty stages alone: the start and the decrement test as they are now. */
PetscErrorCode ProblemScheduleRestore(Problem p, const ProblemSchedule *saved)
{
  PetscFunctionBeginUser;
  p->sched.loadSteps     = saved->loadSteps;
  p->sched.penaltyStages = saved->penaltyStages;
  PetscFunctionReturn(0);
}
