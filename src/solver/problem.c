/* The scene as one minimisation problem, assembled: the bodies' unconstrained
   dofs joined into one vector X (on each rank: body 0's owned dofs, then body
   1's, ...), the total energy Pi(X) = sum_b Pi_b + sum_terms E_t, its gradient
   and Hessian, the reactions, and the results at the solution. Energy terms
   (contact pairs) work on the bodies' local vectors and are added beside the
   bodies' elastic terms without touching them. The solve that minimises Pi
   (solve.c, and its stages, L-BFGS and force control) sits above this file;
   force control's part of the system (forcecontrol.c) below it. */
#include "support.h"
#include "problem.h"
#include "pattern.h"
#include "newtonstep.h"
#include "partition.h"
#include "options.h"
#include "forcecontrol.h"
#include "schedule.h"

const char *const HessianTypes[] = {"gauss_newton", "exact", "auto", "HessianType", "HESSIAN_", NULL};

PetscErrorCode ProblemCreate(MPI_Comm comm, SolverConfig cfg, Problem *problem)
{
  Problem p;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&p));
  p->comm     = comm;
  p->res.load = 1.0;
  p->cfg      = cfg;
  *problem = p;
  PetscFunctionReturn(0);
}

/* The most dofs a mesh may have: -max_dofs, or what the machine's available
   memory holds at CONTACT_BYTES_PER_DOF (rank 0's /proc/meminfo); 0: no
   limit known. */
static PetscErrorCode ProblemDofLimit(Problem p, char limit[], size_t len)
{
  PetscFunctionBeginUser;
  if (p->cfg->scene.maxDofs > 0) {
    PetscCall(PetscSNPrintf(limit, len, "-max_dofs"));
    PetscFunctionReturn(0);
  }
  {
    double      kb = 0;
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
    if (!rank) {
      FILE *fp = fopen("/proc/meminfo", "r");
      char  line[256];
      while (fp && fgets(line, sizeof(line), fp))
        if (sscanf(line, "MemAvailable: %lf kB", &kb) == 1) break;
      if (fp) fclose(fp);
    }
    PetscCallMPI(MPI_Bcast(&kb, 1, MPI_DOUBLE, 0, p->comm));
    p->cfg->scene.maxDofs = kb * 1024.0 / CONTACT_BYTES_PER_DOF;
    PetscCall(PetscSNPrintf(limit, len, "the machine's available memory, %.1f GB; -max_dofs sets another", kb * 1024.0 / 1e9));
  }
  PetscFunctionReturn(0);
}

/* PETSc's own options that the solve relies on, checked like the program's:
   TaoSetFromOptions() stores -tao_max_it -5 or -tao_gatol -1 as given, and
   the solve then stops at once, unconverged. Read from the options database
   (the solver has no prefix) rather than from the solver after
   TaoSetFromOptions(), because the solver is created only after meshing and
   set-up (its Newton defaults need the stiffness): read here, a bad value
   stops the run before anything is meshed or any output is locked.
   -tao_max_funcs -1 is TAO's default, no limit. An integer is quoted as
   given: PETSc reads "default" or "decide" as a negative number. */
/* Reads an option as the check below does without marking it used, so that
   one the solver then never reads is still reported (ProblemCheckUnusedOptions):
   PetscOptionsGet*() marks it, and re-setting the value clears the mark. */
static PetscErrorCode ProblemRestoreUnused(const char name[], PetscBool wasUsed)
{
  char value[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  if (wasUsed) PetscFunctionReturn(0);
  PetscCall(PetscOptionsGetString(NULL, NULL, name, value, sizeof(value), NULL));
  PetscCall(PetscOptionsClearValue(NULL, name));
  PetscCall(PetscOptionsSetValue(NULL, name, value));
  PetscFunctionReturn(0);
}

static PetscErrorCode ProblemCheckSolverOptions(Problem p)
{
  /* tolerances: finite and >= 0 (> 0 where zero means nothing) */
  const struct {
    const char *name;
    PetscBool   positive;
  } tols[] = {
    {"-tao_gatol", PETSC_FALSE},        {"-tao_grtol", PETSC_FALSE},      {"-tao_gttol", PETSC_FALSE},
    {"-tao_ls_ftol", PETSC_FALSE},      {"-tao_ls_gtol", PETSC_FALSE},    {"-tao_ls_rtol", PETSC_FALSE},
    {"-tao_ls_stepmin", PETSC_FALSE},   {"-tao_ls_stepmax", PETSC_TRUE},  {"-tao_nls_ksp_rtol", PETSC_FALSE},
    {"-tao_nls_ksp_atol", PETSC_FALSE}, {"-tao_nls_ksp_divtol", PETSC_TRUE},
  };
  /* limits: integers >= 1; -tao_max_funcs also takes -1, no limit */
  const char *const limits[] = {"-tao_max_it", "-tao_max_funcs", "-tao_ls_max_funcs", "-tao_nls_ksp_max_it"};
  PetscReal         tol;
  PetscInt          n;
  PetscBool         set, used;
  char              given[64];

  PetscFunctionBeginUser;
  for (size_t k = 0; k < sizeof(tols) / sizeof(tols[0]); ++k) {
    PetscCall(PetscOptionsUsed(NULL, tols[k].name, &used));
    PetscCall(PetscOptionsGetReal(NULL, NULL, tols[k].name, &tol, &set));
    if (set) PetscCall(ProblemRestoreUnused(tols[k].name, used));
    PetscCheck(!set || (tol >= 0 && !(tols[k].positive && tol == 0) && !PetscIsInfOrNanReal(tol)), p->comm, PETSC_ERR_USER_INPUT, "option %s: must be a finite number %s 0, got %g", tols[k].name, tols[k].positive ? ">" : ">=", (double)tol);
  }
  for (size_t k = 0; k < sizeof(limits) / sizeof(limits[0]); ++k) {
    const PetscBool noLimit = (PetscBool)(k == 1);
    PetscCall(PetscOptionsUsed(NULL, limits[k], &used));
    PetscCall(PetscOptionsGetInt(NULL, NULL, limits[k], &n, &set));
    if (!set) continue;
    PetscCall(ProblemRestoreUnused(limits[k], used));
    PetscCall(PetscOptionsGetString(NULL, NULL, limits[k], given, sizeof(given), NULL));
    PetscCheck(n >= 1 || (noLimit && n == -1), p->comm, PETSC_ERR_USER_INPUT, "option %s: must be an integer >= 1%s, got %s", limits[k], noLimit ? ", or -1 for no limit" : "", given);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SceneOptionsSetFromOptions(MPI_Comm comm, SceneOptions *o)
{
  PetscInt  nb = CONTACT_MAX_BODIES;
  PetscBool set, help, setMeshSize, setMaxDofs;
  char      def[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(o->name, "scene", sizeof(o->name)));
  o->axisymmetric = PETSC_FALSE;
  o->meshSize     = -1.0;
  o->maxDofs      = 0.0;
  PetscOptionsBegin(comm, NULL, "Contact scene options", NULL);
  PetscCall(ContactOptionsString(PetscOptionsObject, "-scene", "Scene name (names the default output files)", NULL, o->name, o->name, sizeof(o->name), NULL));
  PetscCall(ContactOptionsStringArray(PetscOptionsObject, "-bodies", "Comma-separated body names; body options use the prefix -<name>_ (required)", NULL, o->bodies, &nb, &set));
  PetscCall(PetscOptionsBool("-axisymmetric", "Axisymmetric scene: x is the radius r >= 0 and x = 0 the axis, each mesh a meridian section (u_r = 0 held on the axis)", NULL, o->axisymmetric, &o->axisymmetric, NULL));
  PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-mesh_size", "Mesh size h for every body (overrides -<body>_mesh_size)", "unset: each body's own", PETSC_FALSE, &o->meshSize, &setMeshSize));
  PetscCall(PetscSNPrintf(def, sizeof(def), "build/meshes/%s", o->name));
  PetscCall(PetscStrncpy(o->meshDir, def, sizeof(o->meshDir)));
  PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-max_dofs", "The most dofs a generated mesh may have: larger ones are refused before meshing", "the machine's available memory / 3.5 kB", PETSC_FALSE, &o->maxDofs, &setMaxDofs));
  PetscCall(ContactOptionsString(PetscOptionsObject, "-mesh_dir", "Directory of the generated meshes", NULL, o->meshDir, o->meshDir, sizeof(o->meshDir), NULL));
  PetscOptionsEnd();
  PetscCall(ContactOptionsResolvePath(NULL, "-mesh_dir", o->meshDir, sizeof(o->meshDir), NULL, 0)); /* relative to the options file that names it */
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (help && !(set && nb > 0)) { /* -help without a scene: a body's options under a placeholder name */
    PetscCall(PetscStrallocpy("<body>", &o->bodies[0]));
    nb  = 1;
    set = PETSC_TRUE;
  }
  PetscCheck(set && nb > 0, comm, PETSC_ERR_USER_INPUT, "no bodies: give -bodies name1,name2,... (usually in the scene's -options_file)");
  o->nbodies = nb;
  for (PetscInt i = 0; i < nb; ++i) {
    for (PetscInt j = 0; j < i; ++j) {
      PetscBool same;
      PetscCall(PetscStrcmp(o->bodies[i], o->bodies[j], &same));
      PetscCheck(!same, comm, PETSC_ERR_USER_INPUT, "option -bodies: body '%s' given twice", o->bodies[i]);
    }
  }
  PetscCheck(!setMeshSize || (o->meshSize > 0 && !PetscIsInfOrNanReal(o->meshSize)), comm, PETSC_ERR_USER_INPUT, "option -mesh_size: must be a finite number > 0, got %g", (double)o->meshSize);
  if (!setMeshSize) o->meshSize = -1.0; /* each body's own (-<body>_mesh_size) */
  PetscCheck(!setMaxDofs || (o->maxDofs >= 1 && !PetscIsInfOrNanReal(o->maxDofs)), comm, PETSC_ERR_USER_INPUT, "option -max_dofs: must be a finite number >= 1, got %g", (double)o->maxDofs);
  if (!setMaxDofs) o->maxDofs = 0.0; /* from the machine's memory (ProblemDofLimit) */
  PetscFunctionReturn(0);
}

PetscErrorCode TaylorOptionsSetFromOptions(MPI_Comm comm, TaylorOptions *o)
{
  PetscFunctionBeginUser;
  o->test  = PETSC_FALSE;
  o->scale = 1e-4;
  PetscOptionsBegin(comm, NULL, "Taylor test options", NULL);
  PetscCall(PetscOptionsBool("-taylor_test", "Taylor-remainder check of the gradient and Hessian at the solution", NULL, o->test, &o->test, NULL));
  PetscCall(PetscOptionsReal("-taylor_scale", "Size of the Taylor direction relative to max |u| (small, so that no contact point changes sides along it)", NULL, o->scale, &o->scale, NULL));
  PetscOptionsEnd();
  PetscCheck(o->scale > 0 && !PetscIsInfOrNanReal(o->scale), comm, PETSC_ERR_USER_INPUT, "option -taylor_scale: must be a finite number > 0, got %g", (double)o->scale);
  PetscFunctionReturn(0);
}

PetscErrorCode HessianOptionsSetFromOptions(MPI_Comm comm, HessianOptions *o)
{
  PetscFunctionBeginUser;
  o->type       = HESSIAN_AUTO;
  o->switchRtol = 1e-4;
  PetscOptionsBegin(comm, NULL, "Contact Hessian options", NULL);
  PetscCall(PetscOptionsEnum("-contact_hessian", "Contact Hessian: gauss_newton (SPD), exact (adds the second derivative of the gap; may be indefinite) or auto (gauss_newton, exact once the gradient is small)", NULL, HessianTypes, (PetscEnum)o->type, (PetscEnum *)&o->type, NULL));
  PetscCall(PetscOptionsReal("-contact_hessian_switch", "auto: add the second-order term once ||g|| < this times ||g|| at the first iterate", NULL, o->switchRtol, &o->switchRtol, NULL));
  PetscOptionsEnd();
  PetscCheck(o->switchRtol >= 0 && o->switchRtol <= 1, comm, PETSC_ERR_USER_INPUT, "option -contact_hessian_switch: must be in [0, 1], got %g", (double)o->switchRtol);
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetFromOptions(Problem p)
{
  char   **names;
  PetscInt nb;

  PetscFunctionBeginUser;
  PetscCall(ProblemCheckSolverOptions(p));
  names = p->cfg->scene.bodies;
  nb    = p->cfg->scene.nbodies;
  p->exactHessian = (PetscBool)(p->cfg->hessian.type == HESSIAN_EXACT); /* auto starts with Gauss-Newton */
  p->res.load     = (PetscReal)p->cfg->load.stages;                      /* the bodies are set up at the last stage's end */
  PetscCall(ProblemScheduleSetUp(p));
  p->nbodies = nb;
  for (PetscInt i = 0; i < nb; ++i) {
    PetscCall(BodyCreate(p->comm, names[i], &p->bodies[i]));
    BodySetAxisymmetric(p->bodies[i], p->cfg->scene.axisymmetric);
    BodySetNumStages(p->bodies[i], p->cfg->load.stages);
  }
  for (PetscInt i = 0; i < nb; ++i) PetscCall(BodySetFromOptions(p->bodies[i], p->cfg->scene.meshSize));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemGenerateMeshes(Problem p)
{
  char      limit[128];
  PetscReal left;

  PetscFunctionBeginUser;
  PetscCall(ProblemDofLimit(p, limit, sizeof(limit)));
  /* every body's size checked before any is meshed */
  left = p->cfg->scene.maxDofs;
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyGenerateMesh(p->bodies[i], p->cfg->scene.meshDir, &left, limit, PETSC_TRUE));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyGenerateMesh(p->bodies[i], p->cfg->scene.meshDir, NULL, limit, PETSC_FALSE));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemAddTerm(Problem p, EnergyTerm t)
{
  PetscFunctionBeginUser;
  PetscCheck(p->nterms < CONTACT_MAX_TERMS, p->comm, PETSC_ERR_USER_INPUT, "more than %d contact pairs", CONTACT_MAX_TERMS);
  PetscCall(EnergyTermSetHessianExact(t, p->exactHessian));
  p->terms[p->nterms++] = t;
  for (PetscInt i = 0; i < p->nbodies; ++i)
    if (t->couples[i]) BodyAddContactPair(p->bodies[i]);
  PetscFunctionReturn(0);
}

/* The stiffest pair's k_p h / E*. After the terms' set-up. */
PetscErrorCode ProblemGetPenaltyStiffness(Problem p, PetscReal *stiff)
{
  PetscReal s;

  PetscFunctionBeginUser;
  *stiff = 0.0;
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscCall(EnergyTermGetPenaltyStiffness(p->terms[t], &s));
    *stiff = PetscMax(*stiff, s);
  }
  PetscFunctionReturn(0);
}

/* Newton where a pair's penalty is given far stiffer than the automatic one
   (k_p h / E* above NEWTON_STIFF_PENALTY, 1e4 times the automatic 1000) and
   no continuation is: from rest at that penalty its steps overshoot the whole
   contact zone and the line search crawls (hertz at h = 0.1 and k_p = 1e12,
   k_p h / E* = 1.7e8: no answer in 500 iterations; at 1e11, 1.7e7, 52
   iterations), where two stages, the first at the automatic penalty's
   stiffness, take 24 to the same answer (P to 7e-8). -penalty_stages 1 keeps
   the one stage. */
#define NEWTON_STIFF_PENALTY 1e7
#define NEWTON_FIRST_STAGE   1e3 /* k_p h / E* of the first stage: the automatic penalty's */
PetscErrorCode ProblemSetNewtonContinuation(Problem p)
{
  PetscReal stiff;

  PetscFunctionBeginUser;
  if (p->cfg->penalty.stagesSet || p->cfg->penalty.startSet || p->sched.penaltyStages > 1) PetscFunctionReturn(0);
  PetscCall(ProblemGetPenaltyStiffness(p, &stiff));
  if (!(stiff > NEWTON_STIFF_PENALTY)) PetscFunctionReturn(0);
  PetscCall(ProblemSetPenaltyContinuation(p, 2, NEWTON_FIRST_STAGE / stiff));
  PetscCall(PetscInfo(NULL, "Newton: k_p h / E* = %g: 2 penalty stages from %g k_p\n", (double)stiff, (double)(NEWTON_FIRST_STAGE / stiff)));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetInitialGuess(Problem p, Vec X0)
{
  PetscInt n, nx;

  PetscFunctionBeginUser;
  PetscCall(VecGetSize(X0, &n));
  PetscCall(VecGetSize(p->X, &nx));
  if (n == nx) PetscCall(PetscObjectReference((PetscObject)X0));
  else { /* the bodies' dofs alone (Xb's layout): the controls' displacements as they are */
    const PetscScalar *a;
    PetscScalar       *b;
    PetscInt           nb, nl;
    Vec                Y;
    PetscCall(VecGetLocalSize(X0, &nb));
    PetscCall(VecGetLocalSize(p->X, &nl));
    PetscCall(VecDuplicate(p->X, &Y));
    PetscCall(VecGetArrayRead(X0, &a));
    PetscCall(VecGetArray(Y, &b));
    PetscCall(PetscArraycpy(b, a, nb));
    for (PetscInt k = 0; k < nl - nb; ++k) b[nb + k] = p->fc.c[k].U;
    PetscCall(VecRestoreArray(Y, &b));
    PetscCall(VecRestoreArrayRead(X0, &a));
    X0 = Y;
  }
  PetscCall(VecDestroy(&p->X0));
  p->X0 = X0;
  PetscFunctionReturn(0);
}

/* For each body, local dof -> index in X (-1 for constrained dofs; a rigid
   body has none): BodySetJoinedNumbering, from the body's first index on
   this rank. */
static PetscErrorCode ProblemBuildIndexMaps(Problem p)
{
  PetscInt rstart;

  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(p->Xb, &rstart, NULL));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodySetJoinedNumbering(p->bodies[i], rstart + p->offset[i]));
  PetscFunctionReturn(0);
}

/* A body whose Dirichlet conditions leave a rigid motion free has a flat
   direction in its energy: with no contact pair at all the minimisation is
   singular, and frictionless contact does not fix it either (it pushes, it
   does not hold; a body can slide along it, or leave it). Refused here, with
   the cause, rather than left to a factorisation that meets a zero pivot or a
   solver that never converges (BodyCheckHeld; a rigid body's free unknowns
   alike, in no contact pair). */
static PetscErrorCode ProblemCheckSupports(Problem p)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    PetscBool contact = PETSC_FALSE;

    for (PetscInt t = 0; t < p->nterms; ++t) contact = (PetscBool)(contact || p->terms[t]->couples[i]);
    PetscCall(BodyCheckHeld(p->bodies[i], contact));
  }
  PetscFunctionReturn(0);
}

/* The contact Hessian couples surface dofs that come within reach of each other,
   which changes as the bodies move: the whole block of the contact-surface dofs
   (p->surfaceDofs) is reserved once, with explicit zeros, so that no Hessian
   evaluation allocates and the Hessian and the elastic stiffness share one
   nonzero pattern (copied by memcpy). Rows are inserted by their owner. */
static PetscErrorCode ProblemInsertSurfaceBlock(Problem p, Mat A)
{
  const PetscInt *idx;
  PetscInt        n, rstart, rend;
  PetscScalar    *zeros;

  PetscFunctionBeginUser;
  PetscCall(ISGetLocalSize(p->surfaceDofs, &n));
  PetscCall(ISGetIndices(p->surfaceDofs, &idx));
  PetscCall(MatGetOwnershipRange(A, &rstart, &rend));
  PetscCall(PetscCalloc1(n + 1, &zeros));
  for (PetscInt i = 0; i < n; ++i)
    if (idx[i] >= rstart && idx[i] < rend) PetscCall(MatSetValues(A, 1, &idx[i], n, idx, zeros, ADD_VALUES));
  PetscCall(PetscFree(zeros));
  PetscCall(ISRestoreIndices(p->surfaceDofs, &idx));
  PetscFunctionReturn(0);
}

/* The terms' Hessian patterns joined (EnergyTermGetPattern), *n = 0 where
   a term gives none: the block over the surfaces' dofs, dense, in their
   place (2D's terms, whose surfaces are lines of a few hundred dofs; in 3D
   the dense block grows as the square of a surface's nodes). */
static PetscErrorCode ProblemGetPattern(Problem p, PetscInt *n, PetscInt **rows, PetscInt **start, PetscInt **cols)
{
  PetscInt nc = 0;

  PetscFunctionBeginUser;
  *n    = 0;
  *rows = *start = *cols = NULL;
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscBool has;
    PetscInt  m, *r, *s, *c;
    PetscCall(EnergyTermGetPattern(p->terms[t], &has, &m, &r, &s, &c));
    if (!has) {
      PetscCall(PetscFree(*rows));
      PetscCall(PetscFree(*start));
      PetscCall(PetscFree(*cols));
      *n = 0;
      PetscFunctionReturn(0);
    }
    PetscCall(PetscRealloc(sizeof(PetscInt) * (*n + m + 1), rows));
    PetscCall(PetscRealloc(sizeof(PetscInt) * (*n + m + 2), start));
    PetscCall(PetscRealloc(sizeof(PetscInt) * (nc + s[m] + 1), cols));
    PetscCall(PetscArraycpy(*rows + *n, r, m));
    PetscCall(PetscArraycpy(*cols + nc, c, s[m]));
    (*start)[0] = 0;
    for (PetscInt k = 0; k < m; ++k) (*start)[*n + k + 1] = nc + s[k + 1];
    *n += m;
    nc += s[m];
    PetscCall(PetscFree(r));
    PetscCall(PetscFree(s));
    PetscCall(PetscFree(c));
  }
  PetscFunctionReturn(0);
}

/* The pattern's entries (zeros) in the rows this rank owns. A row's columns
   go in sorted: (Seq)AIJ inserts a new column by moving the row's later
   entries up, so columns in the terms' order cost O(w^2) moves in a row of
   w columns (a 3D mortar pair's rows are the widest of the Hessian, and
   grow with the mesh: 1,271 columns at h = 0.04 on the Hertz ball, 3,156 at
   0.02); in order they are appended. */
static PetscErrorCode ProblemInsertPattern(Mat A, PetscInt n, const PetscInt rows[], const PetscInt start[], const PetscInt cols[])
{
  PetscInt     rstart, rend, w = 0, *sorted;
  PetscScalar *zeros;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(A, &rstart, &rend));
  for (PetscInt k = 0; k < n; ++k) w = PetscMax(w, start[k + 1] - start[k]);
  PetscCall(PetscCalloc1(w + 1, &zeros));
  PetscCall(PetscMalloc1(w + 1, &sorted));
  for (PetscInt k = 0; k < n; ++k) {
    const PetscInt nc = start[k + 1] - start[k];
    if (rows[k] < rstart || rows[k] >= rend) continue;
    PetscCall(PetscArraycpy(sorted, &cols[start[k]], nc));
    PetscCall(PetscSortInt(nc, sorted));
    PetscCall(MatSetValues(A, 1, &rows[k], nc, sorted, zeros, ADD_VALUES));
  }
  PetscCall(PetscFree(sorted));
  PetscCall(PetscFree(zeros));
  PetscFunctionReturn(0);
}

/* A node's distinct columns (pattern.c) counted into its rows: apart by
   whether the row's owner owns them (MPIAIJ's diagonal and off-diagonal
   blocks), into the rank's own counts or, for a row owned elsewhere, into
   the vectors summed to its owner. */
typedef struct {
  Body        body;
  PetscLayout layout;
  PetscInt    rstart, rend, *dnnz, *onnz;
  Vec         dv, ov;
} StiffnessCount;

static PetscErrorCode StiffnessCountNode(void *ctx, PetscInt dof, PetscInt n, const PetscInt cols[])
{
  StiffnessCount *sc  = (StiffnessCount *)ctx;
  const PetscInt *l2b = BodyGetJoinedMap(sc->body);

  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < BodyGetDimension(sc->body); ++d) {
    const PetscInt g = l2b[dof + d];
    PetscInt       lo = sc->rstart, hi = sc->rend, dc = 0;
    PetscMPIInt    o;

    if (g < 0) continue;
    if (g < sc->rstart || g >= sc->rend) {
      PetscCall(PetscLayoutFindOwner(sc->layout, g, &o));
      lo = sc->layout->range[o];
      hi = sc->layout->range[o + 1];
    }
    for (PetscInt q = 0; q < n; ++q) dc += cols[q] >= lo && cols[q] < hi;
    if (g >= sc->rstart && g < sc->rend) {
      sc->dnnz[g - sc->rstart] += dc;
      sc->onnz[g - sc->rstart] += n - dc;
    } else {
      PetscCall(VecSetValue(sc->dv, g, (PetscScalar)dc, ADD_VALUES));
      PetscCall(VecSetValue(sc->ov, g, (PetscScalar)(n - dc), ADD_VALUES));
    }
  }
  PetscFunctionReturn(0);
}

/* Preallocates the elastic stiffness K (elastic pattern plus the surface
   block): each node's rows get the distinct columns of the cells around it
   (pattern.c: exact on one rank; a row on the partition's interface gets
   the sum of the ranks' counts, a bound), and each surface row the
   surface's columns, or where every term gives its Hessian's pattern (3D
   mortar) the pattern's. On several ranks a rank counts the rows its cells
   touch, and the counts of rows owned elsewhere go to their owner by a
   vector sum. No pass of MatSetValues is needed for the pattern. */
static PetscErrorCode ProblemPreallocateStiffness(Problem p, PetscInt nloc)
{
  PetscMPIInt    size;
  PetscInt      *dnnz, *onnz, rstart, rend, N;
  PetscLayout    layout;
  Vec            dv = NULL, ov = NULL;
  PetscInt       np, *prow, *pstart, *pcol;

  PetscFunctionBeginUser;
  PetscCall(ProblemGetPattern(p, &np, &prow, &pstart, &pcol));
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  PetscCall(VecGetOwnershipRange(p->Xb, &rstart, &rend));
  PetscCall(VecGetSize(p->Xb, &N));
  PetscCall(VecGetLayout(p->Xb, &layout));
  PetscCall(PetscCalloc2(nloc + 1, &dnnz, nloc + 1, &onnz));
  if (size > 1) {
    PetscCall(VecDuplicate(p->Xb, &dv));
    PetscCall(VecDuplicate(p->Xb, &ov));
    PetscCall(VecZeroEntries(dv));
    PetscCall(VecZeroEntries(ov));
  }
  {
    StiffnessCount sc = {0};
    sc.layout = layout;
    sc.rstart = rstart;
    sc.rend   = rend;
    sc.dnnz   = dnnz;
    sc.onnz   = onnz;
    sc.dv     = dv;
    sc.ov     = ov;
    for (PetscInt i = 0; i < p->nbodies; ++i) {
      sc.body = p->bodies[i];
      PetscCall(BodyNodeColumns(sc.body, BodyGetJoinedMap(sc.body), StiffnessCountNode, &sc));
    }
  }
  if (size > 1) {
    const PetscScalar *d, *o;
    PetscCall(VecAssemblyBegin(dv));
    PetscCall(VecAssemblyEnd(dv));
    PetscCall(VecAssemblyBegin(ov));
    PetscCall(VecAssemblyEnd(ov));
    PetscCall(VecGetArrayRead(dv, &d));
    PetscCall(VecGetArrayRead(ov, &o));
    for (PetscInt r = 0; r < nloc; ++r) {
      dnnz[r] += (PetscInt)PetscRealPart(d[r]);
      onnz[r] += (PetscInt)PetscRealPart(o[r]);
    }
    PetscCall(VecRestoreArrayRead(dv, &d));
    PetscCall(VecRestoreArrayRead(ov, &o));
    PetscCall(VecDestroy(&dv));
    PetscCall(VecDestroy(&ov));
  }
  if (np) { /* the terms' patterns (3D): each row's columns, over-counted where they repeat the elastic ones */
    for (PetscInt k = 0; k < np; ++k)
      if (prow[k] >= rstart && prow[k] < rend)
        for (PetscInt e = pstart[k]; e < pstart[k + 1]; ++e) {
          if (pcol[e] >= rstart && pcol[e] < rend) dnnz[prow[k] - rstart]++;
          else onnz[prow[k] - rstart]++;
        }
  } else if (p->surfaceDofs) {
    const PetscInt *idx;
    PetscInt        n, mine = 0;
    PetscCall(ISGetLocalSize(p->surfaceDofs, &n));
    PetscCall(ISGetIndices(p->surfaceDofs, &idx));
    for (PetscInt i = 0; i < n; ++i) mine += idx[i] >= rstart && idx[i] < rend;
    for (PetscInt i = 0; i < n; ++i)
      if (idx[i] >= rstart && idx[i] < rend) {
        dnnz[idx[i] - rstart] += mine;
        onnz[idx[i] - rstart] += n - mine;
      }
    PetscCall(ISRestoreIndices(p->surfaceDofs, &idx));
  }
  for (PetscInt r = 0; r < nloc; ++r) {
    dnnz[r] = PetscMin(dnnz[r], nloc);
    onnz[r] = PetscMin(onnz[r], N - nloc);
  }
  PetscCall(MatCreate(p->comm, &p->K));
  PetscCall(MatSetSizes(p->K, nloc, nloc, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetType(p->K, size > 1 ? MATMPIAIJ : MATSEQAIJ));
  if (size > 1) PetscCall(MatMPIAIJSetPreallocation(p->K, 0, dnnz, 0, onnz));
  else PetscCall(MatSeqAIJSetPreallocation(p->K, 0, dnnz));
  PetscCall(PetscFree2(dnnz, onnz));
  if (np) PetscCall(ProblemInsertPattern(p->K, np, prow, pstart, pcol));
  else if (p->surfaceDofs) PetscCall(ProblemInsertSurfaceBlock(p, p->K));
  PetscCall(PetscFree(prow));
  PetscCall(PetscFree(pstart));
  PetscCall(PetscFree(pcol));
  PetscFunctionReturn(0);
}

/* The dofs of every term's Hessian block (indices in the joined vector,
   sorted, each once; every rank gets the whole set). */
static PetscErrorCode ProblemGetSurfaceDofs(Problem p, IS *is)
{
  PetscInt  n = 0, *all = NULL;

  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscInt m, *idx;
    PetscCall(EnergyTermGetDofs(p->terms[t], &m, &idx));
    PetscCall(PetscRealloc(sizeof(PetscInt) * (n + m + 1), &all));
    PetscCall(PetscArraycpy(all + n, idx, m));
    n += m;
    PetscCall(PetscFree(idx));
  }
  PetscCall(PetscSortRemoveDupsInt(&n, all));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, all, PETSC_OWN_POINTER, is));
  PetscFunctionReturn(0);
}

/* Whether anything in the scene can push a body into a contact: a load, a
   nonzero Dirichlet value, a force control or an exact solution imposed. A
   body held by contact is anchored only then (anchors.c); in a scene that
   loads nothing its free motions have no contact to hold them, and it is
   refused (ProblemCheckSupports). */
static PetscErrorCode ProblemIsLoaded(Problem p, PetscBool *loaded)
{
  PetscFunctionBeginUser;
  *loaded = PETSC_FALSE;
  for (PetscInt i = 0; i < p->nbodies; ++i)
    if (BodyIsLoaded(p->bodies[i])) *loaded = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* A scene's bodies are all 2D (a rigid body's curves included) or all 3D,
   and a pair of 3D bodies is mortar's (mortar3d.c). */
PetscInt ProblemGetDimension(Problem p)
{
  return p->nbodies > 0 ? BodyGetDimension(p->bodies[0]) : 2;
}

static PetscErrorCode ProblemCheckDimensions(Problem p)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 1; i < p->nbodies; ++i) {
    const Body     a = p->bodies[0], b = p->bodies[i];
    const PetscInt da = BodyGetDimension(a), db = BodyGetDimension(b);
    PetscCheck(da == db, p->comm, PETSC_ERR_USER_INPUT, "body %s is %" PetscInt_FMT "D (%s) and body %s is %" PetscInt_FMT "D (%s): a scene's bodies are all 2D or all 3D", BodyGetName(a), da, BodyHasCells(a) ? BodyGetMeshFile(a) : "rigid: curves", BodyGetName(b), db, BodyHasCells(b) ? BodyGetMeshFile(b) : "rigid: curves");
  }
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscBool mortar;
    PetscCall(PetscStrcmp(p->terms[t]->type, "mortar", &mortar));
    for (PetscInt i = 0; i < p->nbodies; ++i) PetscCheck(!p->terms[t]->couples[i] || BodyGetDimension(p->bodies[i]) == 2 || mortar, p->comm, PETSC_ERR_USER_INPUT, "contact pair %s: body %s is 3D, and formulation %s is 2D only (3D pairs use mortar)", p->terms[t]->name, BodyGetName(p->bodies[i]), p->terms[t]->type);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetUp(Problem p)
{
  PetscInt    nloc = 0;
  PetscMPIInt size;
  PetscBool   loaded;

  PetscFunctionBeginUser;
  PetscCall(ProblemIsLoaded(p, &loaded));
  for (PetscInt i = 0; i < p->nbodies; ++i) { /* a body in a contact of a loaded scene may be held by it (anchors.c) */
    Body b = p->bodies[i];
    for (PetscInt t = 0; t < p->nterms; ++t)
      if (p->terms[t]->couples[i] && loaded) BodySetMayAnchor(b, PETSC_TRUE);
    PetscCall(BodySetUp(b, p->cfg->partition.type, p->cfg->partition.view));
  }
  PetscCall(ProblemCheckDimensions(p));
  PetscCall(PetscLogStagePush(contactLog.setup));
  PetscCall(ProblemCheckSupports(p));
  PetscCall(ProblemCollectControls(p));
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    p->offset[i] = nloc;
    nloc += BodyGetLocalSize(p->bodies[i]);
  }
  PetscCall(VecCreateMPI(p->comm, nloc, PETSC_DETERMINE, &p->Xb));
  PetscCall(PetscObjectSetName((PetscObject)p->Xb, "u"));
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  if (p->fc.coupled) { /* the controlled displacements: the last entries of rank 0's part */
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
    PetscCall(VecCreateMPI(p->comm, nloc + (rank ? 0 : p->fc.n), PETSC_DETERMINE, &p->X));
    PetscCall(PetscObjectSetName((PetscObject)p->X, "u"));
  } else {
    PetscCall(PetscObjectReference((PetscObject)p->Xb));
    p->X = p->Xb;
  }
  PetscCall(VecDuplicate(p->X, &p->G));
  PetscCall(ProblemBuildIndexMaps(p));
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermSetUp(p->terms[t], p->bodies));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyCheckSupport(p->bodies[i])); /* forces its contacts can react */
  if (p->nterms) PetscCall(ProblemGetSurfaceDofs(p, &p->surfaceDofs));
  /* the elastic stiffness does not depend on u: assembled once; the Hessian
     copies it and adds the contact terms into the reserved surface block */
  PetscCall(ProblemPreallocateStiffness(p, nloc));
  if (size > 1) { /* the sum of the ranks' subdomain stiffnesses, each assembled once (subdomain.c) */
    PetscCall(SubdomainCreate(p->nbodies, p->bodies, &p->sub));
    PetscCall(SubdomainAddTo(p->sub, p->K));
  } else
    for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyAssembleHessian(p->bodies[i], p->K));
  PetscCall(MatAssemblyBegin(p->K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(p->K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetOption(p->K, MAT_SPD, PETSC_TRUE));
  PetscCall(MatDuplicate(p->K, MAT_DO_NOT_COPY_VALUES, &p->H));
  PetscCall(MatSetOptionsPrefix(p->H, "hessian_"));
  PetscCall(MatSetOption(p->H, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(ProblemSetUpControlBorder(p));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

/* Scatters X to every body's local vector (Dirichlet values inserted). */
PetscErrorCode ProblemScatterToBodies(Problem p, Vec X)
{
  const PetscScalar *x;

  PetscFunctionBeginUser;
  PetscCall(ProblemSetControlDisplacements(p, X));
  PetscCall(VecGetArrayRead(X, &x));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodySetJoinedSolution(p->bodies[i], x + p->offset[i]));
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscFunctionReturn(0);
}

/* 1 if the local vector has a NaN or Inf entry. */
static PetscErrorCode VecHasNonFinite(Vec v, PetscReal *bad)
{
  const PetscScalar *a;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArrayRead(v, &a));
  for (PetscInt k = 0; k < n && *bad == 0.0; ++k)
    if (PetscIsInfOrNanScalar(a[k])) *bad = 1.0;
  PetscCall(VecRestoreArrayRead(v, &a));
  PetscFunctionReturn(0);
}

/* Pi(X) and its gradient G, and the energy of each part (bodies, then terms),
   summed over ranks. Each part is checked for NaN and Inf, in its energy and
   in the gradient it adds, so that a non-finite value stops the solve naming
   its source; the flags travel in the energy's sum. */
PetscErrorCode ProblemEvaluate(Problem p, Vec X, PetscReal *f, Vec G, PetscReal parts[])
{
  const PetscInt nparts = p->nbodies + p->nterms;
  PetscReal      sum[1 + 2 * (CONTACT_MAX_BODIES + CONTACT_MAX_TERMS)] = {0}, all[1 + 2 * (CONTACT_MAX_BODIES + CONTACT_MAX_TERMS)], eb, et;
  PetscReal     *bad = sum + 1, *part = sum + 1 + nparts;

  PetscFunctionBeginUser;
  PetscCall(ProblemScatterToBodies(p, X));
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    PetscCall(VecZeroEntries(BodyGetLocalGradient(p->bodies[i])));
    PetscCall(BodyComputeEnergyGradient(p->bodies[i], BodyGetLocalSolution(p->bodies[i]), &eb, BodyGetLocalGradient(p->bodies[i])));
    if (PetscIsInfReal(eb) && eb > 0 && !BodyHasConstantTangent(p->bodies[i])) eb = (PetscReal)INFINITY; /* an inverted element: Pi = +inf, for the line search */
    else if (PetscIsInfOrNanReal(eb)) bad[i] = 1.0;
    else PetscCall(VecHasNonFinite(BodyGetLocalGradient(p->bodies[i]), &bad[i]));
    sum[0] += eb;
    part[i] = eb;
  }
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscCall(EnergyTermComputeEnergyGradient(p->terms[t], p->bodies, &et));
    if (PetscIsInfOrNanReal(et)) bad[p->nbodies + t] = 1.0;
    sum[0] += et;
    part[p->nbodies + t] = et;
  }
  if (p->nterms) {
    PetscReal gbad = 0.0;
    for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(VecHasNonFinite(BodyGetLocalGradient(p->bodies[i]), &gbad));
    if (gbad != 0.0)
      for (PetscInt t = 0; t < p->nterms; ++t) bad[p->nbodies + t] = 1.0;
  }
  PetscCall(MPIU_Allreduce(sum, all, 1 + (parts ? 2 : 1) * nparts, MPIU_REAL, MPIU_SUM, p->comm));
  for (PetscInt k = 0; k < nparts; ++k) {
    PetscInt its = 0;
    if (all[1 + k] == 0.0) continue;
    if (p->tao) PetscCall(TaoGetIterationNumber(p->tao, &its));
    SETERRQ(p->comm, PETSC_ERR_FP, "non-finite (NaN or Inf) energy or gradient in %s %s at TAO iteration %" PetscInt_FMT "; check the scene's magnitudes (loads, moduli, penalty)", k < p->nbodies ? "body" : "contact pair", k < p->nbodies ? BodyGetName(p->bodies[k]) : p->terms[k - p->nbodies]->name, its);
  }
  if (parts) PetscCall(PetscArraycpy(parts, all + 1 + nparts, nparts));
  PetscCall(ProblemGatherGradient(p, G));
  *f = all[0];
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemGatherGradient(Problem p, Vec G)
{
  PetscScalar *g;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(G));
  PetscCall(VecGetArray(G, &g));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyAddJoinedGradient(p->bodies[i], g + p->offset[i])); /* a rigid body: none, its gradient is its force (rigidbody.c) */
  PetscCall(VecRestoreArray(G, &g));
  PetscFunctionReturn(0);
}

/* ||f_c||: the terms' gradient alone at X, summed into the bodies' dofs
   (a rigid body's unknowns, which have none, left out). */
PetscErrorCode ProblemContactForceNorm(Problem p, Vec X, PetscReal *fc)
{
  Vec       W;
  PetscReal et;

  PetscFunctionBeginUser;
  *fc = 0.0;
  if (!p->nterms) PetscFunctionReturn(0);
  PetscCall(ProblemScatterToBodies(p, X));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(VecZeroEntries(BodyGetLocalGradient(p->bodies[i])));
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermComputeEnergyGradient(p->terms[t], p->bodies, &et));
  PetscCall(VecDuplicate(X, &W));
  PetscCall(ProblemGatherGradient(p, W));
  PetscCall(VecNorm(W, NORM_2, fc));
  PetscCall(VecDestroy(&W));
  PetscFunctionReturn(0);
}

/* TAO's objective and gradient callback. */
PetscErrorCode ProblemComputeObjectiveGradient(Tao tao, Vec X, PetscReal *f, Vec G, void *ctx)
{
  Problem p = (Problem)ctx;

  PetscFunctionBeginUser;
  (void)tao;
  PetscCall(ProblemEvaluate(p, X, f, G, NULL));
  PetscCall(ProblemAddControlWork(p, f, G));
  p->res.nEnergyEvals++;
  PetscFunctionReturn(0);
}

/* -contact_hessian auto: the Gauss-Newton Hessian (SPD) while the active set
   settles, the exact one once the gradient has fallen by hessianSwitch. The
   term Gauss-Newton drops is small, but it holds the tangential (sliding)
   modes, which only the bodies' soft bending resists otherwise: without it
   Newton converges linearly (by a factor of about 0.7 per step on the hertz
   scene at h = 0.03); with it, quadratically. Far from the solution the
   exact Hessian may be indefinite, which is why it waits. The reference
   ||g0|| is the first iterate's, or for staged solves the full problem's at
   rest (ProblemSolveStaged). */
static PetscErrorCode ProblemSelectHessian(Problem p, Tao tao)
{
  PetscInt           its;
  PetscReal          f, gnorm, cnorm, step;
  TaoConvergedReason reason;
  PetscBool          exact;

  PetscFunctionBeginUser;
  if (p->cfg->hessian.type != HESSIAN_AUTO) PetscFunctionReturn(0);
  PetscCall(TaoGetSolutionStatus(tao, &its, &f, &gnorm, &cnorm, &step, &reason));
  if (p->hessianG0 < 0) p->hessianG0 = gnorm; /* the first Hessian of this TaoSolve */
  exact = (PetscBool)(gnorm > 0 && gnorm < p->cfg->hessian.switchRtol * p->hessianG0);
  if (exact != p->exactHessian) PetscCall(PetscInfo(tao, "contact Hessian: %s from iteration %" PetscInt_FMT " (||g|| = %g)\n", exact ? "exact" : "Gauss-Newton", its, (double)gnorm));
  p->exactHessian = exact;
  for (PetscInt t = 0; t < p->nterms; ++t)
    PetscCall(EnergyTermSetHessianExact(p->terms[t], exact));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemSetHessianSwitchReference(Problem p, PetscReal g0)
{
  PetscFunctionBeginUser;
  p->hessianG0 = g0;
  PetscFunctionReturn(0);
}

PetscBool ProblemTangentVaries(Problem p)
{
  for (PetscInt i = 0; i < p->nbodies; ++i)
    if (!BodyHasConstantTangent(p->bodies[i])) return PETSC_TRUE;
  return PETSC_FALSE;
}

PetscBool ProblemTangentReassembled(Problem p)
{
  return (PetscBool)(ProblemTangentVaries(p) && !p->cfg->newton.tangentAtRest);
}

/* Newton without -tangent_at_rest: the stiffness at rest serves while two
   steps divide the gradient by more than 1 / TANGENT_SLOW (from the third
   iteration: the first steps move the contact zone, and their gradients
   rise whatever the Hessian); once they do not, the modified steps converge
   slowly (the strains are large) and the tangent takes over for the rest of
   the solve. */
#define TANGENT_SLOW 0.5

PetscBool ProblemTangentChosen(Problem p)
{
  return (PetscBool)(ProblemTangentVaries(p) && !p->cfg->newton.tangentAtRestSet);
}

/* P = K where a term's Hessian has grown P past K's pattern: K laid out in P's
   pattern once per growth (Kh, by MatAXPY with SUBSET_NONZERO_PATTERN), then
   copied as it stands each Hessian (MatCopy with DIFFERENT_NONZERO_PATTERN
   would build P anew each time: 0.26 s a Hessian at 2e4 dofs). */
static PetscErrorCode ProblemCopyStiffnessGrown(Problem p, Mat P)
{
  PetscObjectState state;

  PetscFunctionBeginUser;
  PetscCall(MatGetNonzeroState(P, &state));
  if (!p->Kh || state != p->khState) {
    PetscCall(MatDestroy(&p->Kh));
    PetscCall(MatDuplicate(P, MAT_DO_NOT_COPY_VALUES, &p->Kh));
    PetscCall(MatAXPY(p->Kh, 1.0, p->K, SUBSET_NONZERO_PATTERN));
    p->khState = state;
  }
  PetscCall(MatCopy(p->Kh, P, SAME_NONZERO_PATTERN));
  PetscFunctionReturn(0);
}

/* P = K + the terms' Hessians at X, in their current order (exact or
   Gauss-Newton); K the bodies' tangent at X where a body's varies
   (neohookean) and -tangent_at_rest is not given, else the stiffness
   assembled once. */
PetscErrorCode ProblemAssembleHessian(Problem p, Vec X, Mat P)
{
  PetscFunctionBeginUser;
  if (p->fc.rigid) { /* a rigid body's unknowns: the gradient at X gives the rotation's curl (ProblemRigidBorderEnd) */
    PetscReal f;
    Vec       G;
    PetscCall(VecDuplicate(p->Xb, &G));
    PetscCall(ProblemEvaluate(p, X, &f, G, NULL));
    PetscCall(VecDestroy(&G));
  }
  PetscCall(ProblemScatterToBodies(p, X));
  p->tangentFull = ProblemTangentReassembled(p);
  if (p->tangentAuto) { /* the stiffness at rest while it converges fast, the tangent after (and for the Taylor test) */
    PetscInt           its = 0;
    PetscReal          f, gnorm = 0, cnorm, step;
    TaoConvergedReason reason;
    if (p->tao) PetscCall(TaoGetSolutionStatus(p->tao, &its, &f, &gnorm, &cnorm, &step, &reason));
    if (its == 0) p->tangentSlow = PETSC_FALSE; /* a new solve */
    if (its < 3) p->tangentG[its] = gnorm;
    else {
      if (gnorm > TANGENT_SLOW * p->tangentG[(its - 2) % 3]) p->tangentSlow = PETSC_TRUE;
      p->tangentG[its % 3] = gnorm;
    }
    p->tangentFull = (PetscBool)(p->tangentForce || p->tangentSlow || its >= p->cfg->newton.tangentIts);
    PetscCall(PetscInfo(NULL, "Hessian at iteration %" PetscInt_FMT ": %s\n", its, p->tangentFull ? "the tangent" : "the stiffness at rest"));
  }
  if (p->tangentFull) {
    PetscCall(MatZeroEntries(P));
    for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyAssembleTangent(p->bodies[i], BodyGetLocalSolution(p->bodies[i]), P));
  } else if (p->hessianGrown) PetscCall(ProblemCopyStiffnessGrown(p, P));
  else PetscCall(MatCopy(p->K, P, SAME_NONZERO_PATTERN));
  PetscCall(ProblemUpdateControlBorder(p, p->tangentFull)); /* an anchor of a neohookean body: its column of the same stiffness */
  PetscCall(ProblemRigidBorderBegin(p));
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermComputeHessian(p->terms[t], p->bodies, P));
  PetscCall(ProblemRigidBorderEnd(p));
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  if (!p->hessianGrown) { /* a term's entries outside its pattern (MAT_NEW_NONZERO_ALLOCATION_ERR false: H grows there) */
    MatInfo ik, ih;
    PetscCall(MatGetInfo(p->K, MAT_GLOBAL_SUM, &ik));
    PetscCall(MatGetInfo(P, MAT_GLOBAL_SUM, &ih));
    p->hessianGrown = (PetscBool)(ih.nz_used > ik.nz_used);
    if (p->hessianGrown) PetscCall(PetscInfo(NULL, "the Hessian has %g entries, the stiffness %g: a contact term left its pattern, H grows\n", ih.nz_used, ik.nz_used));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemComputeHessian(Tao tao, Vec X, Mat H, Mat P, void *ctx)
{
  Problem p = (Problem)ctx;

  PetscFunctionBeginUser;
  PetscCall(ProblemSelectHessian(p, tao));
  PetscCall(ProblemAssembleHessian(p, X, p->H));
  for (PetscInt k = 0; k < 2; ++k) { /* a bordered Hessian (coupled force control) or another matrix: its state moves with H's */
    Mat A = k ? P : H;
    if (A == p->H || (k && P == H)) continue;
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  }
  p->res.nHessianEvals++;
  PetscFunctionReturn(0);
}

/* Unused options are an error: a misspelled option would otherwise be silently
   ignored. Before the solve, every option must have been read, except those that
   PETSc reads lazily during the solve (viewers, monitors, converged reasons,
   factorisation packages -mat_*, the inner solvers of multilevel and block
   preconditioners, set up with the first step); after it (final), all of them. */
static PetscBool OptionReadLazily(const char name[])
{
  const char *const inner[] = {"mg_levels_", "mg_coarse_", "sub_", "fieldsplit_", "redundant_"};

  /* a factor's MUMPS controls carry its solver's prefix (-tao_nls_mat_mumps_icntl_14) */
  if (strstr(name, "view") || strstr(name, "monitor") || strstr(name, "test_hessian") || strstr(name, "converged_reason") || !strncmp(name, "mat_", 4) || strstr(name, "_mat_mumps_")) return PETSC_TRUE;
  for (size_t i = 0; i < sizeof(inner) / sizeof(inner[0]); ++i)
    if (strstr(name, inner[i])) return PETSC_TRUE;
  return PETSC_FALSE;
}

PetscErrorCode ProblemCheckUnusedOptions(Problem p, PetscBool final)
{
  PetscInt  n;
  char    **names, **values;
  char      bad[256] = "";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n && !bad[0]; ++i) {
    const char *v = values[i] && !ContactOptionsGivenWithoutValue(values[i]) ? values[i] : NULL; /* as given */
    if (final || !OptionReadLazily(names[i])) PetscCall(PetscSNPrintf(bad, sizeof(bad), "-%s%s%s", names[i], v ? " " : "", v ? v : ""));
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  /* KSPSetFromOptions() reads no tolerance of a preonly KSP, the direct Newton step */
  PetscCheck(!bad[0] || !strstr(bad, "-tao_nls_ksp_") || strstr(bad, "ksp_type"), p->comm, PETSC_ERR_ARG_WRONG, "option %s: unused: the Newton step is a direct solve (-tao_nls_ksp_type preonly), which has no iterations or tolerances; -newton_iterative or -tao_nls_ksp_type cg make it iterative", bad);
  PetscCheck(!bad[0], p->comm, PETSC_ERR_ARG_WRONG, "unknown or unused option %s (misspelled? see -help)", bad);
  PetscFunctionReturn(0);
}

/* After TAO has returned: the energy and gradient at X (the reactions are the
   gradient's components on the constrained dofs), each body's energy, and each
   term's results from X, computed here, with every sum over ranks taken where
   the value is made; then the report. An unconverged state is announced
   before any figure. */
PetscErrorCode ProblemSetLoad(Problem p, PetscReal lambda)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodySetLoad(p->bodies[i], lambda));
  p->res.load = lambda;
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemPostProcess(Problem p, Vec X, PetscBool converged)
{
  PetscReal parts[CONTACT_MAX_BODIES + CONTACT_MAX_TERMS];

  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(contactLog.postprocess));
  if (!converged) PetscCall(PetscPrintf(p->comm, "WARNING: the solve did not converge (%s): the figures below are not a solution\n", TaoConvergedReasons[p->res.reason]));
  PetscCall(ProblemContactForceNorm(p, X, &p->res.contactForceNorm)); /* before the evaluation whose bodies' gradients the reactions read */
  PetscCall(ProblemEvaluate(p, X, &p->res.energy, p->G, parts));
  for (PetscInt k = 0; k < p->fc.n; ++k) p->res.energy -= p->fc.c[k].force * p->fc.c[k].U; /* the forces' potential, as the loads' (forcecontrol.c) */
  PetscCall(VecNorm(p->G, NORM_2, &p->res.gnorm));
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    p->res.bodyEnergy[i] = parts[i];
    PetscCall(BodyComputeReactions(p->bodies[i], BodyGetLocalGradient(p->bodies[i])));
  }
  if (converged && p->cfg->stop.forceRtol > 0 && p->res.contactForceNorm > 0 && p->res.gnorm > p->cfg->stop.forceRtol * p->res.contactForceNorm)
    PetscCall(PetscFPrintf(p->comm, PETSC_STDERR, "contact: warning: the solve stopped with its gradient %.1e of the contacts' nodal forces, above -stop_force_rtol %g: the forces are about that far from converged\n", (double)(p->res.gnorm / p->res.contactForceNorm), (double)p->cfg->stop.forceRtol));
  if (p->res.contactForceNorm > 0) PetscCall(PetscPrintf(p->comm, "  energy %.12e, gradient norm %.3e (%.1e of the contacts' nodal forces)\n", (double)p->res.energy, (double)p->res.gnorm, (double)(p->res.gnorm / p->res.contactForceNorm)));
  else PetscCall(PetscPrintf(p->comm, "  energy %.12e, gradient norm %.3e\n", (double)p->res.energy, (double)p->res.gnorm));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyViewSolution(p->bodies[i], p->cfg->scene.axisymmetric)); /* a rigid body: its motion and the contact's force on it */
  for (PetscInt i = 0; i < p->nbodies; ++i) { /* verification scenes: the error against the manufactured solution */
    Body                 b  = p->bodies[i];
    const ExactSolution *ex = BodyGetExactSolution(b);
    BodyErrors           e;

    if (!ex) continue;
    PetscCall(BodyComputeErrors(b, BodyGetLocalSolution(b), &e)); /* X, scattered by ProblemEvaluate() */
    PetscCall(PetscPrintf(p->comm, "  body %s: relative L2 error against the exact solution (%s): %.6e\n", BodyGetName(b), ex->name, (double)(e.l2norm > 0 ? e.l2 / e.l2norm : e.l2)));
    PetscCall(PetscPrintf(p->comm, "  body %s: relative energy-norm error %.6e, relative L2 error of the stress %.6e\n", BodyGetName(b), (double)(e.energynorm > 0 ? e.energy / e.energynorm : e.energy), (double)(e.stressnorm > 0 ? e.stress / e.stressnorm : e.stress)));
  }
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermPostProcess(p->terms[t], p->bodies));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemView(Problem p)
{
  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermView(p->terms[t], p->bodies));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemComputeReactions(Problem p, Vec X)
{
  PetscReal f;

  PetscFunctionBeginUser;
  PetscCall(ProblemEvaluate(p, X, &f, p->G, NULL));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyComputeReactions(p->bodies[i], BodyGetLocalGradient(p->bodies[i])));
  PetscFunctionReturn(0);
}

/* Taylor remainders at the solution u along a random direction v:
     r1(e) = |Pi(u + e v) - Pi(u) - e g(u).v|      falls like e^2,
     r2(e) = |g(u + e v) - g(u) - e H(u) v|        falls like e^2 (zero for a
   quadratic energy, so it is reported relative to e |H v|). */
PetscErrorCode ProblemTaylorTest(Problem p)
{
  Vec         U, V, W, G0, G1, HV;
  PetscRandom rnd;
  PetscReal   f0, f1, gv, umax, hvn;
  PetscBool   roundE, roundH;
  const PetscInt n = 8;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(p->X, &U));
  PetscCall(VecCopy(p->X, U));
  PetscCall(VecDuplicate(p->X, &V));
  PetscCall(VecDuplicate(p->X, &W));
  PetscCall(VecDuplicate(p->X, &G0));
  PetscCall(VecDuplicate(p->X, &G1));
  PetscCall(VecDuplicate(p->X, &HV));
  PetscCall(PetscRandomCreate(p->comm, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -1.0, 1.0));
  PetscCall(PetscRandomSetSeed(rnd, 7));
  PetscCall(PetscRandomSeed(rnd));
  PetscCall(VecSetRandom(V, rnd));
  PetscCall(VecNorm(U, NORM_INFINITY, &umax));
  if (umax == 0.0) umax = 1e-3;
  PetscCall(VecScale(V, p->cfg->taylor.scale * umax));
  PetscCall(ProblemComputeObjectiveGradient(p->tao, U, &f0, G0, p));
  p->tangentForce = PETSC_TRUE; /* the Hessian's remainder is measured against the tangent */
  PetscCall(ProblemComputeHessian(p->tao, U, p->Htao, p->Htao, p));
  p->tangentForce = PETSC_FALSE;
  PetscCall(MatMult(p->Htao, V, HV));
  PetscCall(VecNorm(HV, NORM_2, &hvn));
  PetscCall(VecDot(G0, V, &gv));
  p->res.taylorN = n;
  PetscCall(PetscPrintf(p->comm, "Taylor test: eps, |E(u+eps v)-E(u)-eps g.v|, |g(u+eps v)-g(u)-eps H v|/(eps |H v|)\n"));
  for (PetscInt k = 0; k < n; ++k) {
    PetscReal eps = PetscPowReal(2.0, -(PetscReal)k), r2;
    PetscCall(VecWAXPY(W, eps, V, U));
    PetscCall(ProblemComputeObjectiveGradient(p->tao, W, &f1, G1, p));
    PetscCall(VecAXPY(G1, -1.0, G0));
    PetscCall(VecAXPY(G1, -eps, HV));
    PetscCall(VecNorm(G1, NORM_2, &r2));
    p->res.taylorEps[k]           = eps;
    p->res.taylorRemainders[0][k] = PetscAbsReal(f1 - f0 - eps * gv);
    p->res.taylorRemainders[1][k] = r2 / (eps * hvn);
    PetscCall(PetscPrintf(p->comm, "  %.4e  %.6e  %.6e\n", (double)eps, (double)p->res.taylorRemainders[0][k], (double)p->res.taylorRemainders[1][k]));
  }
  /* rate of the gradient remainder over the last halvings; for r2 the rate of
     r2 itself, i.e. 1 + rate of the relative remainder */
  p->res.taylorRates[0] = PetscLog2Real(p->res.taylorRemainders[0][n - 2] / p->res.taylorRemainders[0][n - 1]);
  p->res.taylorRates[1] = 1.0 + PetscLog2Real(p->res.taylorRemainders[1][n - 2] / p->res.taylorRemainders[1][n - 1]);
  PetscCall(PetscPrintf(p->comm, "  observed orders: gradient remainder %.3f, Hessian remainder %.3f\n", (double)p->res.taylorRates[0], (double)p->res.taylorRates[1]));
  /* where a remainder is round-off its order means nothing: say so; a
     direction whose steps cross a kink of the energy (a node entering the
     contact, or turning from stick to slip) leaves an order off 2 at the
     larger steps: say what keeps it inside */
  roundE = (PetscBool)(p->res.taylorRemainders[0][n - 1] <= 1e3 * PETSC_MACHINE_EPSILON * PetscAbsReal(f0));
  roundH = (PetscBool)(p->res.taylorRemainders[1][0] <= 1e-9);
  if ((!roundE && PetscAbsReal(p->res.taylorRates[0] - 2.0) > 0.1) || (!roundH && PetscAbsReal(p->res.taylorRates[1] - 2.0) > 0.1)) PetscCall(PetscPrintf(p->comm, "  note: an order off 2 may be the direction's steps crossing a kink of the energy (a node entering the contact, or turning from stick to slip): a smaller -taylor_scale (now %g) keeps them inside\n", (double)p->cfg->taylor.scale));
  if (roundE) PetscCall(PetscPrintf(p->comm, "  note: the energy remainder is at round-off (%.1e against |E| = %.3e): its order is not measured\n", (double)p->res.taylorRemainders[0][n - 1], (double)f0));
  if (roundH) PetscCall(PetscPrintf(p->comm, "  note: the Hessian remainder is at round-off (at most %.1e of |H v|): the energy is quadratic along v, the Hessian exact; its order is not measured\n", (double)p->res.taylorRemainders[1][0]));
  PetscCall(ProblemComputeObjectiveGradient(p->tao, U, &f0, G0, p)); /* the bodies back at the answer: a rigid body's force is its last evaluation's */
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&U));
  PetscCall(VecDestroy(&V));
  PetscCall(VecDestroy(&W));
  PetscCall(VecDestroy(&G0));
  PetscCall(VecDestroy(&G1));
  PetscCall(VecDestroy(&HV));
  PetscFunctionReturn(0);
}

PetscErrorCode ProblemDestroy(Problem *problem)
{
  Problem p = *problem;

  PetscFunctionBeginUser;
  if (!p) PetscFunctionReturn(0);
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermDestroy(&p->terms[t]));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyDestroy(&p->bodies[i]));
  PetscCall(TaoDestroy(&p->tao));
  PetscCall(VecDestroy(&p->fstop.Xmet)); /* the force stop's kept iterate (forcestop.c) */
  PetscCall(MatDestroy(&p->Htao));
  PetscCall(ForceControlsDestroy(&p->fc));
  PetscCall(MatDestroy(&p->H));
  PetscCall(ISDestroy(&p->surfaceDofs));
  PetscCall(SubdomainDestroy(&p->sub));
  PetscCall(MatDestroy(&p->K));
  PetscCall(MatDestroy(&p->Kh));
  PetscCall(VecDestroy(&p->X0));
  PetscCall(VecDestroy(&p->X));
  PetscCall(VecDestroy(&p->Xb));
  PetscCall(VecDestroy(&p->G));
  PetscCall(PetscFree3(p->res.path.load, p->res.path.energy, p->res.path.reaction));
  for (PetscInt k = 0; k < CONTACT_MAX_STAGES; ++k) PetscCall(VecDestroy(&p->res.ends.X[k]));
  PetscCall(PetscFree(p));
  *problem = NULL;
  PetscFunctionReturn(0);
}
