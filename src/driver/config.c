/* The program's configuration as one object: every concern's options, read
   in the order -help lists them, each concern by one function in its own
   file and its own options block (its heading in -help), which sets the
   concern's defaults, reads its options and checks their values:

     Contact scene options          -scene, -bodies, -axisymmetric, -mesh_*, -max_dofs   problem.c
     Partitioning options           -partitioner, -partition_view                       partition.c
     L-BFGS options                 -lmvm_*                                             lmvm.c
     Taylor test options            -taylor_*                                           problem.c
     Newton step options            -newton_*, -tangent_at_rest*                        newtonstep.c
     Load stepping options          -load_*                                             schedule.c
     Penalty continuation options   -penalty_*                                          schedule.c
     Stopping options               -stage_rtol, -stop_force_rtol                       forcestop.c
     Friction lag options           -contact_friction_lag_*                             friction.c
     Force control options          -force_control_*                                    forcecontrol.c
     Contact Hessian options        -contact_hessian*                                   problem.c

   and -config_view here, which prints them all as read. A bad value stops
   the run in its concern's reader, before anything is meshed. The names the
   enumerations choose among are defined by their readers (lmvm.c,
   newtonstep.c, problem.c). The driver creates and reads the configuration
   before the problem, which borrows it (run.c): nothing below reads it back
   up here. */
#include "config.h"
#include "problem.h"
#include "lmvm.h"
#include "newtonstep.h"
#include "schedule.h"
#include "forcestop.h"
#include "forcecontrol.h"
#include "friction.h"
#include "partition.h"


PetscErrorCode SolverConfigCreate(MPI_Comm comm, SolverConfig *config)
{
  PetscFunctionBeginUser;
  PetscCall(PetscNew(config));
  (*config)->comm = comm;
  PetscFunctionReturn(0);
}

PetscErrorCode SolverConfigSetFromOptions(SolverConfig c)
{
  PetscFunctionBeginUser;
  PetscCall(SceneOptionsSetFromOptions(c->comm, &c->scene));
  PetscCall(PartitionOptionsSetFromOptions(c->comm, &c->partition));
  PetscCall(LMVMOptionsSetFromOptions(c->comm, &c->lmvm));
  PetscCall(TaylorOptionsSetFromOptions(c->comm, &c->taylor));
  PetscCall(NewtonOptionsSetFromOptions(c->comm, &c->newton));
  PetscCall(LoadOptionsSetFromOptions(c->comm, &c->load));
  PetscCall(PenaltyOptionsSetFromOptions(c->comm, &c->penalty));
  PetscCall(StopOptionsSetFromOptions(c->comm, &c->stop));
  PetscCall(FrictionLagOptionsSetFromOptions(c->comm, &c->lag));
  PetscCall(ForceControlOptionsSetFromOptions(c->comm, &c->control));
  PetscCall(HessianOptionsSetFromOptions(c->comm, &c->hessian));
  PetscOptionsBegin(c->comm, NULL, "Configuration options", NULL);
  PetscCall(PetscOptionsBool("-config_view", "Print every option above as read (defaults included), by heading, before meshing", NULL, c->view, &c->view, NULL));
  PetscOptionsEnd();
  if (c->view) PetscCall(SolverConfigView(c, PETSC_VIEWER_STDOUT_(c->comm)));
  PetscFunctionReturn(0);
}

/* A value as given, or "auto" where the option is not given and the solver chooses. */
static PetscErrorCode FormatValue(PetscBool given, PetscReal value, char buf[], size_t len)
{
  PetscFunctionBeginUser;
  if (given) PetscCall(PetscSNPrintf(buf, len, "%g", (double)value));
  else PetscCall(PetscStrncpy(buf, "auto", len));
  PetscFunctionReturn(0);
}

PetscErrorCode SolverConfigView(SolverConfig c, PetscViewer v)
{
  const SceneOptions *s = &c->scene;
  char                a[32], b[32];

  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(v, "Configuration:\n"));
  PetscCall(PetscViewerASCIIPushTab(v));
  PetscCall(PetscViewerASCIIPrintf(v, "scene: -scene %s -bodies ", s->name));
  PetscCall(PetscViewerASCIIUseTabs(v, PETSC_FALSE));
  for (PetscInt i = 0; i < s->nbodies; ++i) PetscCall(PetscViewerASCIIPrintf(v, "%s%s", i ? "," : "", s->bodies[i]));
  PetscCall(FormatValue((PetscBool)(s->meshSize > 0), s->meshSize, a, sizeof(a)));
  PetscCall(FormatValue((PetscBool)(s->maxDofs > 0), s->maxDofs, b, sizeof(b)));
  PetscCall(PetscViewerASCIIPrintf(v, " -axisymmetric %s -mesh_size %s -max_dofs %s -mesh_dir %s\n", PetscBools[s->axisymmetric], a, b, s->meshDir));
  PetscCall(PetscViewerASCIIUseTabs(v, PETSC_TRUE));
  PetscCall(PetscViewerASCIIPrintf(v, "partitioning: -partitioner %s -partition_view %s\n", PartitionTypes[c->partition.type], PetscBools[c->partition.view]));
  PetscCall(FormatValue((PetscBool)(c->lmvm.decrementRtol >= 0), c->lmvm.decrementRtol, a, sizeof(a)));
  PetscCall(PetscViewerASCIIPrintf(v, "L-BFGS: -lmvm_h0 %s -lmvm_h0_refresh %" PetscInt_FMT " -lmvm_restarts %" PetscInt_FMT " -lmvm_decrement_rtol %s -lmvm_decrement_floor %g -lmvm_pair_ratio %g\n", H0Types[c->lmvm.h0], c->lmvm.h0Refresh, c->lmvm.restarts, a, (double)c->lmvm.decrementFloor,
                                   (double)c->lmvm.pairRatio));
  PetscCall(PetscViewerASCIIPrintf(v, "Taylor test: -taylor_test %s -taylor_scale %g\n", PetscBools[c->taylor.test], (double)c->taylor.scale));
  PetscCall(PetscViewerASCIIPrintf(v, "Newton step: -newton_iterative %s -newton_iterative_dofs %" PetscInt_FMT " -newton_iterative_nodal %s -newton_iterative_two_levels %s -newton_iterative_cycle %s -newton_schur %s -newton_schur_surface_dofs %" PetscInt_FMT " -newton_schur_split_lu %" PetscInt_FMT " -newton_schur_type %s -tangent_at_rest %s -tangent_at_rest_its %" PetscInt_FMT "\n", c->newton.iterativeSet ? PetscBools[c->newton.iterative] : "auto",
                                   c->newton.iterativeDofs, PetscBools[c->newton.iterativeNodal], PetscBools[c->newton.iterativeTwoLevels], PCMGCycleTypes[c->newton.iterativeCycle], c->newton.schurSet ? PetscBools[c->newton.schur] : "auto", c->newton.schurSurfaceDofs, c->newton.splitLU, SchurTypes[c->newton.schurType], c->newton.tangentAtRestSet ? PetscBools[c->newton.tangentAtRest] : "auto", c->newton.tangentIts));
  PetscCall(PetscViewerASCIIPrintf(v, "load stepping: -load_steps %" PetscInt_FMT " -load_stages %" PetscInt_FMT " -load_cutbacks %" PetscInt_FMT " -load_path %s\n", c->load.steps, c->load.stages, c->load.cutbacks, PetscBools[c->load.path]));
  PetscCall(FormatValue(c->penalty.stagesSet, (PetscReal)c->penalty.stages, a, sizeof(a)));
  PetscCall(FormatValue(c->penalty.startSet, c->penalty.start, b, sizeof(b)));
  PetscCall(PetscViewerASCIIPrintf(v, "penalty continuation: -penalty_stages %s -penalty_start %s\n", a, b));
  PetscCall(PetscViewerASCIIPrintf(v, "stopping: -stage_rtol %g -stop_force_rtol %g\n", (double)c->stop.stageRtol, (double)c->stop.forceRtol));
  PetscCall(PetscViewerASCIIPrintf(v, "friction lag: -contact_friction_lag_rtol %g -contact_friction_lag_max_it %" PetscInt_FMT "\n", (double)c->lag.rtol, c->lag.maxIt));
  PetscCall(PetscViewerASCIIPrintf(v, "force control: -force_control_type %s -force_control_max_it %" PetscInt_FMT " -force_control_rtol %g -force_control_step %g -force_control_border_solves %s\n", c->control.type, c->control.maxIt, (double)c->control.rtol, (double)c->control.step,
                                   PetscBools[c->control.borderSolves]));
  PetscCall(PetscViewerASCIIPrintf(v, "contact Hessian: -contact_hessian %s -contact_hessian_switch %g\n", HessianTypes[c->hessian.type], (double)c->hessian.switchRtol));
  PetscCall(PetscViewerASCIIPopTab(v));
  PetscFunctionReturn(0);
}

PetscErrorCode SolverConfigDestroy(SolverConfig *config)
{
  PetscFunctionBeginUser;
  if (!*config) PetscFunctionReturn(0);
  for (PetscInt i = 0; i < (*config)->scene.nbodies; ++i) PetscCall(PetscFree((*config)->scene.bodies[i]));
  PetscCall(PetscFree(*config));
  PetscFunctionReturn(0);
}
