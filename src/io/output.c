/* Output: per body the second-order nodal mesh (coordinates, Tri6/Quad9
   connectivity in XDMF node order), displacement, stress (xx, yy, zz, xy) and
   von Mises stress averaged at the nodes, in one HDF5 file with an XDMF file
   beside it, and a JSON summary of the run. Every file is written under a
   temporary name and renamed only when complete. */
#include <errno.h>
#include <signal.h>
#include <unistd.h>
#include <petscsf.h>
#include <petscviewerhdf5.h>
#include "problem.h"

/* Temporary files being written: a failed or interrupted run removes them, so
   that it leaves neither a half-written file nor a changed final one. The
   signal handler only calls async-signal-safe functions (unlink, signal, raise). */
#define MAX_PENDING 3
static char         pending[MAX_PENDING][PETSC_MAX_PATH_LEN + 16];
static volatile int npending;

static void RemovePendingOnSignal(int sig)
{
  for (int i = 0; i < npending; ++i) unlink(pending[i]);
  signal(sig, SIG_DFL);
  raise(sig);
}

/* SIGINT, SIGTERM, SIGHUP, SIGPIPE (output piped into head): remove the
   temporaries, then die of the signal, quietly, as Unix tools do. */
PetscErrorCode ContactOutputInstallSignalHandlers(void)
{
  struct sigaction sa;
  const int        sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

  PetscFunctionBeginUser;
  memset(&sa, 0, sizeof(sa));
  sa.sa_handler = RemovePendingOnSignal;
  sigemptyset(&sa.sa_mask);
  for (size_t i = 0; i < sizeof(sigs) / sizeof(sigs[0]); ++i) PetscCheck(!sigaction(sigs[i], &sa, NULL), PETSC_COMM_SELF, PETSC_ERR_SYS, "cannot install the handler of signal %d", sigs[i]);
  PetscFunctionReturn(0);
}

static PetscErrorCode PendingAdd(const char path[])
{
  PetscFunctionBeginUser;
  PetscCheck(npending < MAX_PENDING, PETSC_COMM_SELF, PETSC_ERR_PLIB, "too many temporary files");
  PetscCall(PetscStrncpy(pending[npending], path, sizeof(pending[0])));
  npending = npending + 1;
  PetscFunctionReturn(0);
}

/* Removes the temporaries of an output that did not complete (rank 0 names them). */
void ContactOutputRemovePending(void)
{
  PetscMPIInt rank = 0;

  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (!rank)
    for (int i = 0; i < npending; ++i) unlink(pending[i]);
  npending = 0;
}

static PetscErrorCode EnsureParentDir(MPI_Comm comm, const char path[])
{
  char        dir[PETSC_MAX_PATH_LEN], *slash;
  PetscMPIInt rank;
  int         err = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscStrncpy(dir, path, sizeof(dir)));
  slash = strrchr(dir, '/');
  if (rank == 0 && slash && slash != dir) {
    *slash = 0;
    err    = ContactMakeDirs(dir);
    if (!err && access(dir, W_OK)) err = errno;
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_OPEN, "cannot write output %s: directory %s: %s", path, dir, strerror(err));
  PetscFunctionReturn(0);
}

static PetscErrorCode RenameOnRoot(MPI_Comm comm, const char from[], const char to[])
{
  PetscMPIInt rank;
  int         err = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0 && rename(from, to)) err = errno;
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_WRITE, "cannot rename %s to %s: %s", from, to, strerror(err));
  PetscFunctionReturn(0);
}

static const char *const stressNames[4] = {"stress_xx", "stress_yy", "stress_zz", "stress_xy"};

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
      fprintf(fp, "    <Attribute Name=\"displacement\" AttributeType=\"Vector\" Center=\"Node\">\n     <DataItem Dimensions=\"%d 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%s:/bodies/%s/displacement_xyz</DataItem>\n    </Attribute>\n", (int)N, base, g);
      for (PetscInt k = 0; k < 4; ++k) fprintf(fp, "    <Attribute Name=\"%s\" AttributeType=\"Scalar\" Center=\"Node\">\n     <DataItem Dimensions=\"%d\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%s:/bodies/%s/%s</DataItem>\n    </Attribute>\n", stressNames[k], (int)N, base, g, stressNames[k]);
      fprintf(fp, "    <Attribute Name=\"von_mises\" AttributeType=\"Scalar\" Center=\"Node\">\n     <DataItem Dimensions=\"%d\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%s:/bodies/%s/von_mises</DataItem>\n    </Attribute>\n", (int)N, base, g);
      fprintf(fp, "   </Grid>\n");
    }
    for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermWriteXDMF(p->terms[t], p->bodies, fp, base));
    fprintf(fp, "  </Grid>\n </Domain>\n</Xdmf>\n");
    PetscCheck(!ferror(fp) && !fclose(fp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "error writing %s", path);
  }
  PetscFunctionReturn(0);
}

/* The fields as the XDMF file reads them: displacement_xyz (z = 0) and
   stress_xx, stress_yy, stress_zz, stress_xy, beside displacement and stress. */
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
    PetscCall(PetscObjectSetName((PetscObject)c, stressNames[k]));
    PetscCall(VecView(c, v));
  }
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
    fprintf(fp, "{\n  \"scene\": \"%s\",\n  \"dofs\": %d,\n  \"ranks\": %d,\n  \"tao_type\": \"%s\",\n", p->scene, (int)dofs, (int)size, type);
    fprintf(fp, "  \"tao_reason\": \"%s\",\n  \"converged\": %s,\n  \"iterations\": %d,\n", TaoConvergedReasons[reason], converged ? "true" : "false", (int)its);
    fprintf(fp, "  \"function_evaluations\": %d,\n  \"hessian_evaluations\": %d,\n", (int)p->nEnergyEvals, (int)p->nHessianEvals);
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
      const PetscReal err = F[i].l2err, nrm = F[i].l2norm;
      fprintf(fp, "%s\n    \"%s\": {\"dofs\": %d, \"cells\": %d, \"nodes\": %d, \"cell_type\": \"%s\", \"energy\": ", i ? "," : "", b->name, (int)b->nglobal, (int)b->ncellsGlobal, (int)F[i].nnodes, b->simplex ? "Tri6" : "Quad9");
      ContactJSONReal(fp, p->bodyEnergy[i]);
      fprintf(fp, ", \"max_displacement\": ");
      ContactJSONReal(fp, F[i].umax);
      fprintf(fp, ", \"mesh\": \"%s\", \"h\": ", b->msh);
      ContactJSONReal(fp, b->h);
      if (b->hasExact) {
        fprintf(fp, ", \"exact\": \"%s\", \"l2_error\": ", b->exact.name);
        ContactJSONReal(fp, err);
        fprintf(fp, ", \"l2_norm\": ");
        ContactJSONReal(fp, nrm);
      }
      fprintf(fp, "}");
    }
    fprintf(fp, "\n  },\n");
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
   -summary none), each to "<name>.tmp" first and renamed at the end. */
PetscErrorCode ProblemWriteOutput(Problem p, PetscBool converged)
{
  BodyNodalFields F[CONTACT_MAX_BODIES];
  PetscBool  h5, js;
  char       htmp[PETSC_MAX_PATH_LEN + 8], jtmp[PETSC_MAX_PATH_LEN + 8], xdmf[PETSC_MAX_PATH_LEN + 8], xtmp[PETSC_MAX_PATH_LEN + 16];
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogStagePush(contactLog.output));
  PetscCall(PetscLogEventBegin(contactLog.writeOutput, 0, 0, 0, 0));
  PetscCall(PetscStrcmp(p->output, "none", &h5));
  PetscCall(PetscStrcmp(p->summary, "none", &js));
  h5 = (PetscBool)!h5;
  js = (PetscBool)!js;
  PetscCall(PetscMemzero(F, sizeof(F)));
  PetscCall(ProblemScatterToBodies(p, p->X)); /* the fields of the solution */
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyComputeNodalFields(p->bodies[i], p->bodies[i]->Xl, &F[i]));
  if (h5) {
    size_t l;
    PetscCall(EnsureParentDir(p->comm, p->output));
    PetscCall(PetscSNPrintf(htmp, sizeof(htmp), "%s.tmp", p->output));
    PetscCall(PetscStrncpy(xdmf, p->output, sizeof(xdmf)));
    PetscCall(PetscStrlen(xdmf, &l));
    if (l > 3 && !strcmp(xdmf + l - 3, ".h5")) xdmf[l - 3] = 0;
    PetscCall(PetscStrlcat(xdmf, ".xdmf", sizeof(xdmf)));
    PetscCall(PetscSNPrintf(xtmp, sizeof(xtmp), "%s.tmp", xdmf));
    PetscCall(PendingAdd(htmp));
    PetscCall(PendingAdd(xtmp));
    PetscCall(WriteHDF5(p, F, htmp));
    PetscCall(WriteXDMF(p, F, xtmp, p->output, ""));
  }
  PetscCall(PetscTime(&t1));
  p->time[3] = t1 - t0;
  p->time[4] = t1 - p->t0;
  if (js) {
    PetscCall(EnsureParentDir(p->comm, p->summary));
    PetscCall(PetscSNPrintf(jtmp, sizeof(jtmp), "%s.tmp", p->summary));
    PetscCall(PendingAdd(jtmp));
    PetscCall(WriteJSON(p, F, converged, jtmp));
  }
  if (h5) {
    PetscCall(RenameOnRoot(p->comm, htmp, p->output));
    PetscCall(RenameOnRoot(p->comm, xtmp, xdmf));
  }
  if (js) PetscCall(RenameOnRoot(p->comm, jtmp, p->summary));
  npending = 0;
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyNodalFieldsDestroy(&F[i]));
  PetscCall(PetscLogEventEnd(contactLog.writeOutput, 0, 0, 0, 0));
  PetscCall(PetscLogStagePop());
  if (h5) PetscCall(PetscPrintf(p->comm, "Wrote %s and %s\n", p->output, xdmf));
  if (js) PetscCall(PetscPrintf(p->comm, "Wrote %s\n", p->summary));
  PetscFunctionReturn(0);
}
