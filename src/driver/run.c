/* The pipeline of a run (run.h): each step of main() and of each -accuracy
   step, with the progress phase it announces and the time slot it fills. */
#include "run.h"
#include "contactpair.h"
#include "config.h"
#include "options.h"
#include "outputset.h"
#include "progress.h"
#include "schedule.h"

const char *const RunTimeNames[] = {"mesh", "setup", "solve", "output", "total"};

PetscErrorCode RunOptionsSetFromOptions(MPI_Comm comm, const char scene[], RunOptions *o)
{
  char *paths[2] = {o->output, o->summary};
  const char *opts[2] = {"-output", "-summary"};

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(o->output, sizeof(o->output), "out/%s.h5", scene));
  PetscCall(PetscSNPrintf(o->summary, sizeof(o->summary), "out/%s.json", scene));
  PetscOptionsBegin(comm, NULL, "Output options", NULL);
  PetscCall(PetscOptionsBool("-mesh_only", "Generate the scene's meshes and stop", NULL, o->meshOnly, &o->meshOnly, NULL));
  PetscCall(ContactOptionsString(PetscOptionsObject, "-output", "HDF5 output file, an XDMF file beside it (none: no output)", NULL, o->output, o->output, sizeof(o->output), NULL));
  PetscCall(ContactOptionsString(PetscOptionsObject, "-summary", "JSON summary file (none: no summary)", NULL, o->summary, o->summary, sizeof(o->summary), NULL));
  PetscCall(PetscOptionsBool("-output_wait", "Wait for another run writing the same output files (else stop at once)", NULL, o->outputWait, &o->outputWait, NULL));
  PetscOptionsEnd();
  for (PetscInt k = 0; k < 2; ++k) { /* relative to the options file that names them */
    PetscBool none;
    PetscCall(PetscStrcmp(paths[k], "none", &none));
    if (!none) PetscCall(ContactOptionsResolvePath(NULL, opts[k], paths[k], PETSC_MAX_PATH_LEN, NULL, 0));
  }
  PetscFunctionReturn(0);
}

/* The scene's options read (the problem's, its bodies', its contact pairs'),
   and the contact terms created and handed to the problem. */
PetscErrorCode RunCreateProblem(MPI_Comm comm, Problem *problem)
{
  Problem      p;
  SolverConfig cfg;
  EnergyTerm   terms[CONTACT_MAX_TERMS];
  PetscInt     nterms;
  PetscBool    autoPenalty;

  PetscFunctionBeginUser;
  PetscCall(SolverConfigCreate(comm, &cfg));
  PetscCall(SolverConfigSetFromOptions(cfg));
  PetscCall(ProblemCreate(comm, cfg, &p));
  PetscCall(ProblemSetFromOptions(p));
  PetscCall(ContactPairsCreateFromOptions(comm, p->nbodies, p->bodies, CONTACT_MAX_TERMS, &nterms, terms, &autoPenalty));
  for (PetscInt t = 0; t < nterms; ++t) PetscCall(ProblemAddTerm(p, terms[t]));
  /* the automatic penalty is stiff (1000 E* / h): reached from 30 E* / h in two
     stages, which takes as many Newton iterations as the soft penalty alone
     (docs/formulations.md, "The penalty") */
  if (autoPenalty) PetscCall(ProblemSetPenaltyContinuation(p, 2, 0.03));
  *problem = p;
  PetscFunctionReturn(0);
}

PetscErrorCode RunDestroyProblem(Problem *problem)
{
  SolverConfig cfg;

  PetscFunctionBeginUser;
  if (!*problem) PetscFunctionReturn(0);
  cfg = (*problem)->cfg;
  PetscCall(ProblemDestroy(problem));
  PetscCall(SolverConfigDestroy(&cfg));
  PetscFunctionReturn(0);
}

PetscErrorCode RunMesh(Problem p, char fields[][PETSC_MAX_PATH_LEN])
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodySetSizeField(p->bodies[i], fields ? fields[i] : NULL));
  PetscCall(ProblemGenerateMeshes(p));
  PetscFunctionReturn(0);
}

/* The set-up, and the time slots of the pass begun at rec->mark: meshing is
   the bodies' generating and reading of their meshes, set-up the rest. */
PetscErrorCode RunSetUp(Problem p, RunRecord *rec)
{
  PetscLogDouble t;
  PetscReal      tmesh = 0;

  PetscFunctionBeginUser;
  PetscCall(ProblemSetUp(p));
  PetscCall(PetscTime(&t));
  for (PetscInt i = 0; i < p->nbodies; ++i) tmesh += BodyGetMeshTime(p->bodies[i]);
  rec->time[RUN_TIME_MESH] += tmesh;
  rec->time[RUN_TIME_SETUP] += (t - rec->mark) - tmesh;
  PetscFunctionReturn(0);
}

PetscErrorCode RunSolve(Problem p, RunRecord *rec, PetscBool *converged)
{
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t0));
  PetscCall(ProblemSolve(p, converged));
  PetscCall(PetscTime(&t1));
  rec->time[RUN_TIME_SOLVE] += t1 - t0;
  PetscFunctionReturn(0);
}

PetscErrorCode RunPostProcess(Problem p, PetscBool converged)
{
  PetscFunctionBeginUser;
  PetscCall(ProblemPostProcess(p, p->X, converged));
  PetscFunctionReturn(0);
}

/* Why a solve stopped, in one line: TAO's reason, the load it reached, and
   what a term found wrong with the state. */
static PetscErrorCode RunSayNotConverged(Problem p)
{
  char why[PETSC_MAX_PATH_LEN] = "", cut[128] = "";

  PetscFunctionBeginUser;
  if (p->res.why[0]) PetscCall(PetscStrncpy(why, p->res.why, sizeof(why)));
  for (PetscInt t = 0; t < p->nterms && !why[0]; ++t) PetscCall(EnergyTermDiagnose(p->terms[t], sizeof(why), why));
  for (PetscInt i = 0; i < p->nbodies; ++i) { /* a body whose elements invert on the way (neohookean): named, first */
    PetscInt  n;
    PetscReal xy[2];
    PetscCall(BodyGetInversions(p->bodies[i], &n, xy));
    if (n && p->res.reason != TAO_DIVERGED_MAXITS) {
      PetscCall(PetscSNPrintf(why, sizeof(why), "body %s inverts: J <= 0 near (%g, %g) in %" PetscInt_FMT " of the energy evaluations (smaller load steps, -load_steps, or a finer mesh there may pass)", BodyGetName(p->bodies[i]), (double)xy[0], (double)xy[1], n));
      break;
    }
  }
  if (p->res.cutbacks > 0 && p->cfg->load.stages > 1) PetscCall(PetscSNPrintf(cut, sizeof(cut), "; the load cut back %" PetscInt_FMT " time%s, solved up to %.4g of its %" PetscInt_FMT " stages", p->res.cutbacks, p->res.cutbacks > 1 ? "s" : "", (double)p->res.loadDone, p->cfg->load.stages));
  else if (p->res.cutbacks > 0) PetscCall(PetscSNPrintf(cut, sizeof(cut), "; the load cut back %" PetscInt_FMT " time%s, solved up to %.4g of it", p->res.cutbacks, p->res.cutbacks > 1 ? "s" : "", (double)p->res.loadDone));
  PetscCall(PetscFPrintf(p->comm, PETSC_STDERR, "contact: the solve did not converge (%s%s)%s%s; no output written\n", TaoConvergedReasons[p->res.reason], cut, why[0] ? ": " : "", why));
  PetscFunctionReturn(0);
}

/* The model's error, as the mesh's is measured: each body's largest
   principal Green-Lagrange strain; a linear body above 2 % is warned in the
   report, its model's error being of the order of the strain there (it
   drops E's quadratic terms and tells a rotation from a strain no better).
   Where that strain is a singular point's (BodyComputeStrainPeak), the
   warning says so instead: no material law removes it, a finer mesh only
   raises it, and what the 2 % is about is the strain away from it. */
static PetscErrorCode RunReportStrains(Problem p)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    Body           b = p->bodies[i];
    BodyStrainPeak pk;
    PetscReal      e;
    char           at[96];
    if (!BodyHasCells(b)) continue; /* no strain */
    PetscCall(BodyComputeStrainPeak(b, BodyGetLocalSolution(b), &pk));
    e = pk.emax;
    PetscCall(PetscPrintf(p->comm, "  body %s (%s): largest Green-Lagrange strain %.3g %%\n", BodyGetName(b), BodyGetMaterial(b)->name, (double)(100 * e)));
    if (!BodyGetMaterial(b)->constantTangent || !(e > 0.02)) continue;
    if (BodyGetDimension(b) == 3) PetscCall(PetscSNPrintf(at, sizeof(at), "(%.4g, %.4g, %.4g)", (double)pk.x[0], (double)pk.x[1], (double)pk.x[2]));
    else PetscCall(PetscSNPrintf(at, sizeof(at), "(%.4g, %.4g)", (double)pk.x[0], (double)pk.x[1]));
    if (pk.ring < BODY_STRAIN_POINT * pk.emax) PetscCall(PetscPrintf(p->comm, "  warning: body %s: its largest strain, %.3g %%, is concentrated at %s, falling to %.3g %% %d to %d elements from it: a singular point (a corner, the end of a held boundary or a contact's edge), where the strain grows as the mesh is refined whatever the material: -%s_material neohookean would not remove it, and the linear model's 2 %% limit is about the strain away from such points\n", BodyGetName(b), (double)(100 * e), at, (double)(100 * pk.ring), (int)(0.5 * BODY_STRAIN_RING), (int)BODY_STRAIN_RING, BodyGetName(b)));
    else PetscCall(PetscPrintf(p->comm, "  warning: body %s is linear at a strain of %.3g %%, above 2 %%, where small-strain elasticity's error is of the order of the strain: -%s_material neohookean models it\n", BodyGetName(b), (double)(100 * e), BodyGetName(b)));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RunFinish(Problem p, RunRecord *rec)
{
  PetscLogDouble t;

  PetscFunctionBeginUser;
  if (rec->converged) PetscCall(RunReportStrains(p));
  if (p->cfg->taylor.test) {
    PetscCall(ContactProgressPhase("the Taylor test", "Taylor test"));
    PetscCall(ProblemTaylorTest(p));
  }
  PetscCall(ProblemCheckUnusedOptions(p, PETSC_TRUE));
  if (rec->converged) {
    PetscCall(ContactProgressPhase("the output", "output"));
    PetscCall(RunWriteResults(p, rec));
  } else {
    PetscCall(RunSayNotConverged(p));
    ContactOutputDiscard();
  }
  PetscCall(PetscTime(&t));
  rec->time[RUN_TIME_TOTAL] = t - rec->start;
  PetscFunctionReturn(0);
}
