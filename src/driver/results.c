/* The results of a run, written into its output set (outputset.h): per body
   the second-order nodal mesh (coordinates, Tri6/Quad9 or Tet10/Hex27
   connectivity in XDMF node order), displacement, stress (xx, yy, zz, xy;
   a 3D body's xx, yy, zz, xy, yz, xz) and von Mises stress
   averaged at the nodes, in one HDF5 file with an XDMF file beside it, and a
   JSON summary of the run; each contact term adds its own. */
#include "blaskernel.h"
#include <petscviewerhdf5.h>
#include "run.h"
#include "forcecontrol.h"
#include "outputset.h"
#include "outputwrite.h"
#include "xdmf.h"
#include "stages.h"

/* The XDMF grid of each body (rank 0): its cells and reference coordinates
   from /bodies/<body>, its fields from the group fields/<body> of the HDF5
   file base (/bodies, or a load stage's /stages/<k>/bodies); NaN for the
   contact fields, the friction's too in a scene with friction. */
static PetscErrorCode WriteXDMFBodies(FILE *fp, Problem p, BodyNodalFields F[], const char base[], const char fields[], PetscBool friction)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    Body               b   = p->bodies[i];
    const PetscBool    d3  = (PetscBool)(BodyGetDimension(b) == 3);
    const char        *tt  = d3 ? (BodyIsSimplex(b) ? "Tetrahedron_10" : "Hexahedron_27") : (BodyIsSimplex(b) ? "Triangle_6" : "Quadrilateral_9");
    const char        *g   = BodyGetName(b);
    const char *const *sc  = d3 ? XdmfBodyScalars3D : XdmfBodyScalarNames(BodyIsAxisymmetric(b));
    const PetscInt     nsc = d3 ? XDMF_BODY_SCALARS_3D : XDMF_BODY_SCALARS;
    PetscInt           N = F[i].nnodes, C = F[i].ncells;
    char               path[PETSC_MAX_PATH_LEN];
    if (!BodyHasCells(b)) continue; /* its contact surfaces are the terms' grids */
    fprintf(fp, "   <Grid Name=\"%s\" GridType=\"Uniform\">\n", g);
    fprintf(fp, "    <Topology TopologyType=\"%s\" NumberOfElements=\"%d\">\n", tt, (int)C);
    fprintf(fp, "     <DataItem Dimensions=\"%d %d\" NumberType=\"Int\" Precision=\"%d\" Format=\"HDF\">%s:/bodies/%s/topology</DataItem>\n    </Topology>\n", (int)C, (int)BodyGetNodesPerCell(b), (int)sizeof(PetscInt), base, g);
    fprintf(fp, "    <Geometry GeometryType=\"%s\">\n     <DataItem Dimensions=\"%d %d\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%s:/bodies/%s/geometry</DataItem>\n    </Geometry>\n", d3 ? "XYZ" : "XY", (int)N, d3 ? 3 : 2, base, g);
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s:%s/%s/displacement_xyz", base, fields, g));
    XdmfWriteAttribute(fp, "displacement", (int)N, 3, path);
    for (PetscInt k = 0; k < nsc; ++k) {
      const char *name = sc[k];
      PetscCall(PetscSNPrintf(path, sizeof(path), "%s:%s/%s/%s", base, fields, g, name));
      XdmfWriteAttribute(fp, name, (int)N, 1, path);
    }
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s:/bodies/%s/xdmf_nan", base, g));
    if (d3) { /* a 3D scene's contact fields (xdmf.h): none in a body */
      for (PetscInt k = 0; k < XDMF_CONTACT_SCALARS_3D; ++k) XdmfWriteAttribute(fp, XdmfContactScalars3D[k], (int)N, 1, path);
      PetscCall(PetscSNPrintf(path, sizeof(path), "%s:/bodies/%s/xdmf_nan_xyz", base, g));
      XdmfWriteAttribute(fp, XDMF_CONTACT_VECTOR_3D, (int)N, 3, path);
      for (PetscInt k = 0; k < XDMF_FRICTION_FIELDS_3D && friction; ++k) {
        PetscCall(PetscSNPrintf(path, sizeof(path), "%s:/bodies/%s/%s", base, g, XdmfFrictionComponents3D[k] == 3 ? "xdmf_nan_xyz" : "xdmf_nan"));
        XdmfWriteAttribute(fp, XdmfFrictionFields3D[k], (int)N, XdmfFrictionComponents3D[k], path);
      }
      fprintf(fp, "   </Grid>\n");
      continue;
    }
    for (PetscInt k = 0; k < XDMF_SURFACE_SCALARS; ++k) XdmfWriteAttribute(fp, XdmfSurfaceScalars[k], (int)N, 1, path); /* no contact fields in a body (xdmf.h) */
    for (PetscInt k = 0; k < XDMF_FRICTION_SCALARS && friction; ++k) XdmfWriteAttribute(fp, XdmfFrictionScalars[k], (int)N, 1, path);
    fprintf(fp, "   </Grid>\n");
  }
  PetscFunctionReturn(0);
}

/* The XDMF file: one spatial collection of a grid per body (its second-order
   cells, reference coordinates, displacement as a 3-component vector, stress
   components and von Mises stress) and a line grid per contact surface with a
   profile (EnergyTermWriteXDMF), all on the HDF5 file h5. ParaView's legacy
   reader (XDMFReader) and its Xdmf3 readers read every item alike only as
   plain HDF datasets: the Xdmf3 readers skip Function and HyperSlab items,
   and the readers map the columns of a Tensor6 differently; so the HDF5 file
   holds the displacement with z = 0 and each stress component on its own.
   With -load_stages S > 1 the collections are the time steps 1..S of a
   temporal collection (ParaView's time slider): step k < S the bodies at
   the end of stage k (/stages/k), step S the final state as above. */
static PetscErrorCode WriteXDMF(Problem p, BodyNodalFields F[], const ContactOutputFiles *out)
{
  const PetscInt    S        = p->cfg->load.stages;
  PetscBool         friction = PETSC_FALSE; /* a term with state (friction): every grid carries its fields (xdmf.h) */
  PetscMPIInt       rank;
  const char       *base = strrchr(out->h5, '/');
  ContactOutputText text = {NULL, NULL, 0};

  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < p->nterms; ++t) friction = (PetscBool)(friction || EnergyTermHasState(p->terms[t]));
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  base = base ? base + 1 : out->h5;
  if (rank == 0) {
    FILE *fp;
    PetscCall(ContactOutputTextOpen(&text));
    fp = text.fp;
    fprintf(fp, "<?xml version=\"1.0\" ?>\n<!-- contact run_id %s -->\n<Xdmf Version=\"3.0\">\n <Domain>\n", out->runId);
    if (S > 1) fprintf(fp, "  <Grid Name=\"%s_stages\" GridType=\"Collection\" CollectionType=\"Temporal\">\n", p->cfg->scene.name);
    for (PetscInt k = 1; k < S; ++k) {
      char fields[64];
      PetscCall(PetscSNPrintf(fields, sizeof(fields), "/stages/%d/bodies", (int)k));
      fprintf(fp, "  <Grid Name=\"%s_stage_%d\" GridType=\"Collection\" CollectionType=\"Spatial\">\n   <Time Value=\"%d\"/>\n", p->cfg->scene.name, (int)k, (int)k);
      PetscCall(WriteXDMFBodies(fp, p, F, base, fields, friction));
      fprintf(fp, "  </Grid>\n");
    }
    fprintf(fp, "  <Grid Name=\"%s\" GridType=\"Collection\" CollectionType=\"Spatial\">\n", p->cfg->scene.name);
    if (S > 1) fprintf(fp, "   <Time Value=\"%d\"/>\n", (int)S);
    PetscCall(WriteXDMFBodies(fp, p, F, base, "/bodies", friction));
    for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermWriteXDMF(p->terms[t], p->bodies, fp, base, friction));
    fprintf(fp, "  </Grid>\n");
    if (S > 1) fprintf(fp, "  </Grid>\n");
    fprintf(fp, " </Domain>\n</Xdmf>\n");
  }
  PetscCall(ContactOutputTextWrite(p->comm, &text, out->xtmp, out->xdmf));
  PetscFunctionReturn(0);
}

/* The fields as the XDMF file reads them: displacement_xyz (z = 0) and
   stress_xx, stress_yy, stress_zz, stress_xy (axisymmetric: stress_rr,
   stress_zz, stress_hoop, stress_rz), beside displacement and stress,
   and xdmf_nan, NaN at every node, for the contact fields a body has not.
   A 3D body's: displacement_xyz (a copy of displacement, so that the XDMF
   reads every scene's alike), the six stress columns as stress_xx, _yy,
   _zz, _xy, _yz, _xz, xdmf_nan and xdmf_nan_xyz (NaN vectors: the
   contact force a body has not). */
static PetscErrorCode WriteXDMFFields(BodyNodalFields *F, PetscBool axisym, PetscViewer v)
{
  Vec                d3, c;
  PetscInt           n, bs;
  const PetscScalar *u;
  PetscScalar       *a;

  PetscFunctionBeginUser;
  PetscCall(VecGetBlockSize(F->disp, &bs));
  if (bs == 3) {
    PetscCall(VecDuplicate(F->disp, &d3));
    PetscCall(VecCopy(F->disp, d3));
    PetscCall(PetscObjectSetName((PetscObject)d3, "displacement_xyz"));
    ContactOutputCall(v, VecView(d3, v));
    PetscCall(VecDestroy(&d3));
    PetscCall(VecDuplicate(F->vm, &c));
    for (PetscInt k = 0; k < 6; ++k) {
      PetscCall(VecStrideGather(F->stress, k, c, INSERT_VALUES));
      PetscCall(PetscObjectSetName((PetscObject)c, XdmfBodyScalars3D[k]));
      ContactOutputCall(v, VecView(c, v));
    }
    PetscCall(VecSet(c, (PetscScalar)NAN));
    PetscCall(PetscObjectSetName((PetscObject)c, "xdmf_nan"));
    ContactOutputCall(v, VecView(c, v));
    PetscCall(VecDestroy(&c));
    PetscCall(VecDuplicate(F->disp, &d3)); /* the contact force a body has not (xdmf.h) */
    PetscCall(VecSet(d3, (PetscScalar)NAN));
    PetscCall(PetscObjectSetName((PetscObject)d3, "xdmf_nan_xyz"));
    ContactOutputCall(v, VecView(d3, v));
    PetscCall(VecDestroy(&d3));
    PetscFunctionReturn(0);
  }
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
  ContactOutputCall(v, VecView(d3, v));
  PetscCall(VecDestroy(&d3));
  PetscCall(VecDuplicate(F->vm, &c));
  for (PetscInt k = 0; k < 4; ++k) {
    PetscCall(VecStrideGather(F->stress, k, c, INSERT_VALUES));
    PetscCall(PetscObjectSetName((PetscObject)c, XdmfBodyScalarNames(axisym)[k])); /* stress_xx, _yy, _zz, _xy (rr, zz, hoop, rz): the XDMF names */
    ContactOutputCall(v, VecView(c, v));
  }
  PetscCall(VecSet(c, (PetscScalar)NAN)); /* the contact fields a body has not (xdmf.h) */
  PetscCall(PetscObjectSetName((PetscObject)c, "xdmf_nan"));
  ContactOutputCall(v, VecView(c, v));
  PetscCall(VecDestroy(&c));
  PetscFunctionReturn(0);
}

/* A rigid body's outline: its lines' nodes at their current positions
   (line_x, rank 0's) and each line's nodes (lines: the ends, then the
   middle), for the plots. */
static PetscErrorCode WriteRigidOutline(Body b, PetscViewer v)
{
  PetscMPIInt     rank;
  Vec             x;
  IS              lines;
  PetscScalar    *a;
  PetscReal      *xo;
  const PetscInt *enodes;
  PetscInt        nn, ne;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(BodyGetComm(b), &rank));
  PetscCall(BodyRigidGetOutline(b, &nn, &xo, &ne, &enodes));
  if (rank) nn = ne = 0;
  PetscCall(VecCreate(BodyGetComm(b), &x));
  PetscCall(VecSetSizes(x, 2 * nn, PETSC_DETERMINE));
  PetscCall(VecSetBlockSize(x, 2));
  PetscCall(VecSetType(x, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)x, "line_x"));
  PetscCall(VecGetArray(x, &a));
  for (PetscInt i = 0; i < 2 * nn; ++i) a[i] = xo[i];
  PetscCall(VecRestoreArray(x, &a));
  PetscCall(PetscFree(xo));
  ContactOutputCall(v, VecView(x, v));
  PetscCall(VecDestroy(&x));
  PetscCall(ISCreateGeneral(BodyGetComm(b), 3 * ne, enodes, PETSC_COPY_VALUES, &lines));
  PetscCall(ISSetBlockSize(lines, 3));
  PetscCall(PetscObjectSetName((PetscObject)lines, "lines"));
  ContactOutputCall(v, ISView(lines, v));
  PetscCall(ISDestroy(&lines));
  PetscFunctionReturn(0);
}

/* A body's fields at a state (the group pushed): displacement, stress, von
   Mises and their XDMF forms. */
static PetscErrorCode WriteBodyFields(BodyNodalFields *F, PetscBool axisym, PetscViewer v)
{
  PetscFunctionBeginUser;
  ContactOutputCall(v, VecView(F->disp, v));
  ContactOutputCall(v, VecView(F->stress, v));
  ContactOutputCall(v, VecView(F->vm, v));
  PetscCall(WriteXDMFFields(F, axisym, v));
  PetscFunctionReturn(0);
}

/* -load_stages S > 1: each stage's end, /stages/k/bodies/<body> (k = 1..S)
   with the body's fields at it (the mesh is /bodies/<body>'s), and the
   attributes /stages count = S and /stages/k load = k. Stage S's fields
   are the final state's, F; the earlier ones are computed from the
   recorded states, and the bodies are left holding the final state. */
static PetscErrorCode WriteHDF5Stages(Problem p, BodyNodalFields F[], PetscViewer v)
{
  const PetscInt S = p->cfg->load.stages;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5PushGroup(v, "/stages"));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, "/stages", "count", PETSC_INT, &S));
  PetscCall(PetscViewerHDF5PopGroup(v));
  for (PetscInt k = 1; k <= S; ++k) {
    char      group[2 * CONTACT_NAME_LEN + 32];
    PetscReal load = (PetscReal)k;
    PetscCall(StagesSetState(p, k));
    PetscCall(PetscSNPrintf(group, sizeof(group), "/stages/%d", (int)k));
    PetscCall(PetscViewerHDF5PushGroup(v, group));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "load", PETSC_REAL, &load));
    PetscCall(PetscViewerHDF5PopGroup(v));
    for (PetscInt i = 0; i < p->nbodies; ++i) {
      BodyNodalFields Fk;
      if (!BodyHasCells(p->bodies[i])) continue; /* no fields */
      PetscCall(PetscSNPrintf(group, sizeof(group), "/stages/%d/bodies/%s", (int)k, BodyGetName(p->bodies[i])));
      PetscCall(PetscViewerHDF5PushGroup(v, group));
      if (k == S) PetscCall(WriteBodyFields(&F[i], BodyIsAxisymmetric(p->bodies[i]), v));
      else {
        PetscCall(PetscMemzero(&Fk, sizeof(Fk)));
        PetscCall(BodyComputeNodalFields(p->bodies[i], BodyGetLocalSolution(p->bodies[i]), &Fk));
        PetscCall(WriteBodyFields(&Fk, BodyIsAxisymmetric(p->bodies[i]), v));
        PetscCall(BodyNodalFieldsDestroy(&Fk));
      }
      PetscCall(PetscViewerHDF5PopGroup(v));
    }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode WriteHDF5Contents(Problem p, const RunRecord *rec, BodyNodalFields F[], const char runId[], PetscViewer v)
{
  char       *opts, version[256];
  PetscMPIInt size;
  PetscInt    its;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    char group[2 * CONTACT_NAME_LEN];
    PetscCall(PetscSNPrintf(group, sizeof(group), "/bodies/%s", BodyGetName(p->bodies[i])));
    BodyRigidMotion m;
    if (BodyGetRigidMotion(p->bodies[i], &m) && m.dim == 3) { /* its motion and force, as attributes of three components */
      PetscCall(PetscViewerHDF5PushGroup(v, group));
      ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "rigid", PETSC_INT, &(PetscInt){1}));
      for (PetscInt d = 0; d < 3; ++d) {
        char key[32];
        PetscCall(PetscSNPrintf(key, sizeof(key), "translation_%c", (char)('x' + d)));
        ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, key, PETSC_REAL, &m.t[d]));
        PetscCall(PetscSNPrintf(key, sizeof(key), "rotation_%c", (char)('x' + d)));
        ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, key, PETSC_REAL, &m.rot[d]));
        PetscCall(PetscSNPrintf(key, sizeof(key), "force_%c", (char)('x' + d)));
        ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, key, PETSC_REAL, &m.force[d]));
        PetscCall(PetscSNPrintf(key, sizeof(key), "moment_%c", (char)('x' + d)));
        ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, key, PETSC_REAL, &m.mom[d]));
      }
      PetscCall(PetscViewerHDF5PopGroup(v));
      continue;
    }
    if (BodyGetRigidMotion(p->bodies[i], &m)) { /* its motion and force, no fields */
      PetscCall(PetscViewerHDF5PushGroup(v, group));
      ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "rigid", PETSC_INT, &(PetscInt){1}));
      ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "translation_x", PETSC_REAL, &m.t[0]));
      ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "translation_y", PETSC_REAL, &m.t[1]));
      ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "rotation", PETSC_REAL, &m.theta));
      ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "force_x", PETSC_REAL, &m.force[0]));
      ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "force_y", PETSC_REAL, &m.force[1]));
      ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "moment", PETSC_REAL, &m.moment));
      PetscCall(WriteRigidOutline(p->bodies[i], v));
      PetscCall(PetscViewerHDF5PopGroup(v));
      continue;
    }
    PetscCall(PetscViewerHDF5PushGroup(v, group));
    ContactOutputCall(v, VecView(F[i].coords, v));
    PetscCall(WriteBodyFields(&F[i], BodyIsAxisymmetric(p->bodies[i]), v));
    ContactOutputCall(v, ISView(F[i].topo, v));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "cell_type", PETSC_STRING, BodyGetDimension(p->bodies[i]) == 3 ? (BodyIsSimplex(p->bodies[i]) ? "Tet10" : "Hex27") : (BodyIsSimplex(p->bodies[i]) ? "Tri6" : "Quad9")));
    {
      PetscReal E, nu;
      BodyGetElasticConstants(p->bodies[i], &E, &nu);
      ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "E", PETSC_REAL, &E));
      ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, group, "nu", PETSC_REAL, &nu));
    }
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermWriteHDF5(p->terms[t], p->bodies, v));
  if (p->cfg->load.stages > 1) PetscCall(WriteHDF5Stages(p, F, v));
  PetscCall(PetscOptionsGetAll(NULL, &opts));
  PetscCall(PetscGetVersion(version, sizeof(version)));
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  PetscCall(PetscViewerHDF5PushGroup(v, "/metadata"));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, "/metadata", "scene", PETSC_STRING, p->cfg->scene.name));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, "/metadata", "axisymmetric", PETSC_INT, &(PetscInt){p->cfg->scene.axisymmetric ? 1 : 0}));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, "/metadata", "run_id", PETSC_STRING, runId));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, "/metadata", "options", PETSC_STRING, opts));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, "/metadata", "petsc_version", PETSC_STRING, version));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, "/metadata", "ranks", PETSC_INT, &size));
  its = p->res.iterations; /* over all stages */
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, "/metadata", "iterations", PETSC_INT, &its));
  ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, "/metadata", "energy", PETSC_REAL, &p->res.energy));
  for (PetscInt k = 0; k < RUN_TIME_TOTAL; ++k) { /* the total is not known yet */
    char name[32];
    PetscCall(PetscSNPrintf(name, sizeof(name), "time_%s", RunTimeNames[k]));
    ContactOutputCall(v, PetscViewerHDF5WriteAttribute(v, "/metadata", name, PETSC_REAL, &rec->time[k]));
  }
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(PetscFree(opts));
  PetscFunctionReturn(0);
}

/* On several ranks, room for the HDF5 file before it is written
   (outputwrite.h): the bodies' datasets, HDF5_NODE_VALUES reals a node
   (coordinates 2, displacement 2 and its xyz copy 3, stress 4 and its 4
   components, von Mises 1, the XDMF stand-in 1; a 3D body's
   HDF5_NODE_VALUES_3D: 3, 3 + 3, 6 + 6, 1, 1) and the topology, and
   HDF5_MARGIN for the contact surfaces' datasets and the metadata
   (measured on 2 ranks: the reference scene's file 515 kB, its bodies'
   datasets 378 kB as counted here, the contact's 10 kB; the roller's 4.45
   MB, 4.16 MB and 73 kB). So a disk with room for the file but not for the
   margin is refused too. On one rank a failed write fails where it is. */
#define HDF5_NODE_VALUES    17
#define HDF5_NODE_VALUES_3D 23
#define HDF5_MARGIN      (1 << 20)

static PetscErrorCode WriteHDF5CheckRoom(Problem p, BodyNodalFields F[])
{
  PetscMPIInt size;
  size_t      bytes = HDF5_MARGIN;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  if (size == 1) PetscFunctionReturn(0);
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    PetscInt nodes, cells;
    if (!BodyHasCells(p->bodies[i])) continue; /* no fields */
    PetscCall(VecGetSize(F[i].vm, &nodes));
    PetscCall(ISGetSize(F[i].topo, &cells));
    bytes += (size_t)nodes * (BodyGetDimension(p->bodies[i]) == 3 ? HDF5_NODE_VALUES_3D : HDF5_NODE_VALUES) * sizeof(PetscReal) * (p->cfg->load.stages > 1 ? p->cfg->load.stages + 1 : 1) + (size_t)cells * sizeof(PetscInt); /* -load_stages: each stage's fields too */
  }
  PetscCall(ContactOutputCheckRoom(p->comm, bytes));
  PetscFunctionReturn(0);
}

static PetscErrorCode CloseHDF5(void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(PetscViewerDestroy((PetscViewer *)ctx));
  PetscFunctionReturn(0);
}

/* The HDF5 file, a write whose failure is one line naming the file and the
   cause (outputwrite.h): HDF5 does not print its error stack, and the viewer
   is closed whether or not the write succeeded, so that no HDF5 file is left
   open until MPI_Finalize(). */
static PetscErrorCode WriteHDF5(Problem p, const RunRecord *rec, BodyNodalFields F[], const ContactOutputFiles *out)
{
  PetscViewer    v = NULL;
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(WriteHDF5CheckRoom(p, F));
  PetscCheck(H5Eset_auto2(H5E_DEFAULT, NULL, NULL) >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "cannot turn off HDF5's error printing");
  PetscCall(ContactOutputLibraryWriteBegin());
  ierr = PetscViewerHDF5Open(p->comm, out->htmp, FILE_MODE_WRITE, &v);
  if (!ierr) ierr = WriteHDF5Contents(p, rec, F, out->runId, v);
  PetscCall(ContactOutputLibraryWriteEnd(p->comm, ierr, CloseHDF5, &v, out->htmp, out->h5));
  PetscFunctionReturn(0);
}

/* The reaction of every Dirichlet group, R[3 k .. 3 k + 2] for the k-th
   (the bodies' groups in order), keyed body:group, as many components as
   the scene's dimension; each entry after indent, the closing brace after
   end. */
static void JSONReactionSet(FILE *fp, Problem p, const char sep[], const char indent[], const char end[], const PetscReal R[])
{
  const PetscInt nd = BodyGetDimension(p->bodies[0]);

  fprintf(fp, "%s\"reactions\": {", sep);
  for (PetscInt i = 0, k = 0; i < p->nbodies; ++i)
    for (PetscInt j = 0; j < BodyGetNumConditions(p->bodies[i]); ++j, ++k) {
      char key[2 * CONTACT_NAME_LEN + 2];
      (void)PetscSNPrintf(key, sizeof(key), "%s:%s", BodyGetName(p->bodies[i]), BodyGetCondition(p->bodies[i], j)->group);
      fprintf(fp, "%s", k ? "," : "");
      ContactJSONKeyVector(fp, indent, key, nd, R + 3 * k);
    }
  fprintf(fp, "%s}", end);
}

static PetscErrorCode JSONReactions(FILE *fp, Problem p)
{
  PetscReal R[3 * CONTACT_MAX_BODIES * CONTACT_MAX_BC];

  PetscFunctionBeginUser;
  for (PetscInt i = 0, k = 0; i < p->nbodies; ++i)
    for (PetscInt j = 0; j < BodyGetNumConditions(p->bodies[i]); ++j, k += 3) PetscCall(PetscArraycpy(R + k, BodyGetCondition(p->bodies[i], j)->reaction, 3));
  JSONReactionSet(fp, p, ",\n  ", "\n    ", "\n  ", R);
  PetscFunctionReturn(0);
}

/* -load_path: the converged states from rest, each with its load factor,
   energy and reactions (staging.c). */
static void JSONLoadPath(FILE *fp, Problem p)
{
  const LoadPath *lp = &p->res.path;

  if (!p->cfg->load.path) return;
  fprintf(fp, ",\n  \"load_path\": [");
  for (PetscInt k = 0; k < lp->n; ++k) {
    ContactJSONKeyReal(fp, k ? ",\n    {" : "\n    {", "load", lp->load[k]);
    ContactJSONKeyReal(fp, ", ", "energy", lp->energy[k]);
    JSONReactionSet(fp, p, ", ", " ", " ", lp->reaction + 3 * k * lp->ngroups);
    fprintf(fp, "}");
  }
  fprintf(fp, "\n  ]");
}

/* -load_stages: each stage's end, its load parameter k (1..S), the
   reaction of every Dirichlet group and each contact pair's force (on its
   first surface, as the report's "contact force"), and each frictional
   pair's stick zone half-width. The last is the final state's. */
static PetscErrorCode JSONLoadStages(FILE *fp, Problem p)
{
  const StageEnds *e = &p->res.ends;
  PetscInt         n;

  PetscFunctionBeginUser;
  fprintf(fp, ",\n  \"load_stages\": [");
  for (PetscInt k = 1; k <= p->cfg->load.stages; ++k) {
    ContactJSONKeyReal(fp, k > 1 ? ",\n    {" : "\n    {", "load", (PetscReal)k);
    JSONReactionSet(fp, p, ", ", " ", " ", e->reaction[k - 1]);
    fprintf(fp, ", \"contact_force\": {");
    for (PetscInt t = 0; t < p->nterms; ++t) ContactJSONKeyPair(fp, t ? ", " : "", p->terms[t]->name, e->force[k - 1][t]);
    fprintf(fp, "}");
    n = 0;
    for (PetscInt t = 0; t < p->nterms; ++t) { /* frictional pairs: the stick zone's half-width */
      PetscReal c;
      PetscBool has;
      PetscCall(EnergyTermGetStickHalfWidth(p->terms[t], k, &c, &has));
      if (has) ContactJSONKeyReal(fp, n++ ? ", " : ", \"stick_half_width\": {", p->terms[t]->name, c);
    }
    fprintf(fp, n ? "}}" : "}");
  }
  fprintf(fp, "\n  ]");
  PetscFunctionReturn(0);
}

/* Each load's resultant, at the load factor solved (only with loads), of
   the body's dim components. In
   r-z it is axial: the radial sum of a load's nodal forces is its rings'
   radial load, which cancels round the circle (as a contact pair's,
   contactreport.c), so its radial component is written 0. */
static void JSONLoads(FILE *fp, Problem p)
{
  PetscInt n = 0;

  for (PetscInt i = 0; i < p->nbodies; ++i)
    for (PetscInt j = 0; j < BodyGetNumLoads(p->bodies[i]); ++j, ++n) {
      const BodyLoad *L = BodyGetLoad(p->bodies[i], j);
      char            key[2 * CONTACT_NAME_LEN + 2];
      PetscReal       f[3] = {0, 0, 0};
      BodyLoadResultant(p->bodies[i], j, f);
      if (p->cfg->scene.axisymmetric) f[0] = 0.0;
      (void)PetscSNPrintf(key, sizeof(key), "%s:%s", BodyGetName(p->bodies[i]), L->group);
      ContactJSONKeyVector(fp, n ? ",\n    " : ",\n  \"loads\": {\n    ", key, BodyGetDimension(p->bodies[i]), f); /* [fx, fy], a 3D body's [fx, fy, fz] */
    }
  if (n) fprintf(fp, "\n  }");
}

/* Each force-controlled component: its force and the displacement found
   (with the reaction, which equals the force to -force_control_rtol). */
static void JSONForceControl(FILE *fp, Problem p)
{
  if (!p->fc.n) return;
  fprintf(fp, ",\n  \"force_control_solves\": %d,\n  \"force_control\": [", (int)p->res.controlSolves);
  for (PetscInt k = 0; k < p->fc.n; ++k) {
    const ForceControl *fc = &p->fc.c[k];
    const PetscReal     L  = fc->motion && BodyRigidIsRotation(p->bodies[fc->body], fc->c) ? BodyRigidGetLength(p->bodies[fc->body]) : 1.0; /* a rotation: radians and moments */
    fprintf(fp, "%s\n    {\"body\": \"%s\", \"group\": \"%s\", \"anchor\": %s, \"component\": \"%s\"", k ? "," : "", BodyGetName(p->bodies[fc->body]), ProblemControlGroup(p, k), fc->anchor ? "true" : "false", ProblemControlComponent(p, k));
    if (fc->motion) fprintf(fp, ", \"rigid\": true");
    ContactJSONKeyReal(fp, ", ", "force", fc->force * L);
    ContactJSONKeyReal(fp, ", ", "displacement", fc->U / L);
    ContactJSONKeyReal(fp, ", ", "reaction", fc->R * L);
    fprintf(fp, "}");
  }
  fprintf(fp, "\n  ]");
}

/* The first pair's figures at top level, then every pair's under "contact". */
static PetscErrorCode JSONContact(FILE *fp, Problem p)
{
  PetscFunctionBeginUser;
  if (!p->nterms) PetscFunctionReturn(0);
  PetscCall(EnergyTermWriteJSON(p->terms[0], p->bodies, fp, PETSC_TRUE));
  fprintf(fp, ",\n  \"contact\": {");
  for (PetscInt t = 0; t < p->nterms; ++t) {
    fprintf(fp, "%s\n    \"%s\": ", t ? "," : "", p->terms[t]->name);
    PetscCall(EnergyTermWriteJSON(p->terms[t], p->bodies, fp, PETSC_FALSE));
  }
  fprintf(fp, "\n  }");
  PetscFunctionReturn(0);
}

static void JSONBodies(FILE *fp, Problem p, const BodyNodalFields F[])
{
  fprintf(fp, ",\n  \"bodies\": {");
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    Body              b = p->bodies[i];
    const BodyErrors *e = &F[i].err;
    PetscInt          ndofs, ncells;
    BodyRigidMotion   m;
    if (BodyGetRigidMotion(b, &m)) { /* its motion, and the contact's force and moment on it */
      fprintf(fp, "%s\n    \"%s\": {\"rigid\": true, \"dofs\": 0, \"nodes\": %d", i ? "," : "", BodyGetName(b), (int)m.nodes);
      if (m.dim == 3) { /* the rotation vector, and the moment's three components */
        ContactJSONKeyVector(fp, ", ", "translation", 3, m.t);
        ContactJSONKeyVector(fp, ", ", "rotation", 3, m.rot);
        ContactJSONKeyVector(fp, ", ", "centre", 3, m.centre);
        ContactJSONKeyVector(fp, ", ", "force", 3, m.force);
        ContactJSONKeyVector(fp, ", ", "moment", 3, m.mom);
        fprintf(fp, ", \"mesh\": \"%s\"", BodyGetMeshFile(b));
        ContactJSONKeyReal(fp, ", ", "h", BodyGetMeshSize(b));
        fprintf(fp, "}");
        continue;
      }
      ContactJSONKeyPair(fp, ", ", "translation", m.t);
      ContactJSONKeyReal(fp, ", ", "rotation", m.theta);
      ContactJSONKeyPair(fp, ", ", "centre", m.centre);
      ContactJSONKeyPair(fp, ", ", "force", m.force);
      ContactJSONKeyReal(fp, ", ", "moment", m.moment);
      fprintf(fp, ", \"mesh\": \"%s\"", BodyGetMeshFile(b));
      ContactJSONKeyReal(fp, ", ", "h", BodyGetMeshSize(b));
      fprintf(fp, "}");
      continue;
    }
    BodyGetGlobalSizes(b, &ndofs, &ncells);
    fprintf(fp, "%s\n    \"%s\": {\"dofs\": %d, \"cells\": %d, \"nodes\": %d, \"cell_type\": \"%s\"", i ? "," : "", BodyGetName(b), (int)ndofs, (int)ncells, (int)F[i].nnodes, BodyGetDimension(b) == 3 ? (BodyIsSimplex(b) ? "Tet10" : "Hex27") : (BodyIsSimplex(b) ? "Tri6" : "Quad9"));
    ContactJSONKeyReal(fp, ", ", "energy", p->res.bodyEnergy[i]);
    ContactJSONKeyReal(fp, ", ", "max_displacement", F[i].umax);
    fprintf(fp, ", \"material\": \"%s\"", BodyGetMaterial(b)->name);
    ContactJSONKeyReal(fp, ", ", "max_green_lagrange_strain", F[i].maxStrain);
    if (F[i].nstate) { /* a material with history: each state value's range over the quadrature points */
      ContactJSONKeyVector(fp, ", ", "state_min", F[i].nstate, F[i].stateMin);
      ContactJSONKeyVector(fp, ", ", "state_max", F[i].nstate, F[i].stateMax);
    }
    fprintf(fp, ", \"mesh\": \"%s\"", BodyGetMeshFile(b));
    ContactJSONKeyReal(fp, ", ", "h", BodyGetMeshSize(b));
    if (BodyGetExactSolution(b)) { /* each error with the exact solution's norm */
      const char     *keys[6] = {"l2_error", "l2_norm", "energy_error", "energy_norm", "stress_l2_error", "stress_l2_norm"};
      const PetscReal vals[6] = {e->l2, e->l2norm, e->energy, e->energynorm, e->stress, e->stressnorm};
      fprintf(fp, ", \"exact\": \"%s\"", BodyGetExactSolution(b)->name);
      for (PetscInt k = 0; k < 6; ++k) ContactJSONKeyReal(fp, ", ", keys[k], vals[k]);
    }
    fprintf(fp, "}");
  }
  fprintf(fp, "\n  },\n");
}

/* -accuracy's steps: each one's estimates (null where there is none: the
   first step's, a force estimate where every force is given), and under force
   control the displacements found and their estimate. */
static void JSONAccuracy(FILE *fp, const RunRecord *rec)
{
  const char *keys[ACCURACY_N] = {"error_estimate", "profile_estimate", "force_estimate", "displacement_estimate"};

  if (!(rec->accuracyTarget > 0)) return;
  ContactJSONKeyReal(fp, "  ", "accuracy_target", rec->accuracyTarget);
  ContactJSONKeyReal(fp, ",\n  ", "error_estimate", rec->errorEstimate);
  fprintf(fp, ",\n  \"adapt_steps\": [");
  for (PetscInt k = 0; k < rec->nsteps; ++k) {
    const AccuracyStep *a = &rec->steps[k];
    fprintf(fp, "%s\n    {\"dofs\": %d, \"iterations\": %d", k ? "," : "", (int)a->dofs, (int)a->iterations);
    ContactJSONKeyReal(fp, ", ", "solve_time", a->tsolve);
    for (PetscInt e = 0; e < ACCURACY_N; ++e)
      if (e != ACCURACY_DISPLACEMENT || a->ncontrols) ContactJSONKeyReal(fp, ", ", keys[e], a->est[e]);
    fprintf(fp, ", \"force_given\": %s", a->forceGiven ? "true" : "false");
    if (a->ncontrols) {
      fprintf(fp, ", \"displacements\": [");
      for (PetscInt c = 0; c < a->ncontrols; ++c) {
        if (c) fprintf(fp, ", ");
        ContactJSONReal(fp, a->U[c]);
      }
      fprintf(fp, "]");
    }
    fprintf(fp, "}");
  }
  fprintf(fp, "\n  ],\n");
}

static void JSONTaylor(FILE *fp, Problem p)
{
  const PetscReal *rows[3] = {p->res.taylorEps, p->res.taylorRemainders[0], p->res.taylorRemainders[1]};
  const char      *keys[3] = {"eps", "gradient_remainder", "hessian_relative_remainder"};

  if (!p->cfg->taylor.test) return;
  fprintf(fp, "  \"taylor\": {");
  ContactJSONKeyReal(fp, "", "gradient_order", p->res.taylorRates[0]);
  ContactJSONKeyReal(fp, ", ", "hessian_order", p->res.taylorRates[1]);
  for (PetscInt r = 0; r < 3; ++r) {
    fprintf(fp, ", \"%s\": [", keys[r]);
    for (PetscInt k = 0; k < p->res.taylorN; ++k) fprintf(fp, "%s%.17g", k ? ", " : "", (double)rows[r][k]);
    fprintf(fp, "]");
  }
  fprintf(fp, "},\n");
}

/* The summary (rank 0): the solve, the reactions, the contact, the bodies,
   -accuracy's steps, the Taylor test, the time slots. */
static PetscErrorCode WriteJSON(Problem p, const RunRecord *rec, BodyNodalFields F[], const ContactOutputFiles *out)
{
  PetscMPIInt        rank, size;
  PetscInt           dofs;
  TaoConvergedReason reason;
  TaoType            type;
  PetscReal          umax = 0, unorm2 = 0;
  ContactOutputText  text = {NULL, NULL, 0};
  FILE              *fp;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  reason = p->res.reason; /* the solve's, as printed: TAO's last, or the program's (a decrement floor, force control) */
  PetscCall(TaoGetType(p->tao, &type));
  PetscCall(VecGetSize(p->Xb, &dofs));
  for (PetscInt i = 0; i < p->nbodies; ++i) {
    umax = PetscMax(umax, F[i].umax);
    unorm2 += F[i].unorm2;
  }
  if (!rank) {
    PetscCall(ContactOutputTextOpen(&text));
    fp = text.fp;
    fprintf(fp, "{\n  \"scene\": \"%s\",\n  \"run_id\": \"%s\",\n  \"dofs\": %d,\n  \"ranks\": %d,\n  \"tao_type\": \"%s\",\n", p->cfg->scene.name, out->runId, (int)dofs, (int)size, type);
    fprintf(fp, "  \"axisymmetric\": %s,\n", p->cfg->scene.axisymmetric ? "true" : "false");
    /* the BLAS kernel, how it was chosen, and the one it replaced (null: none) */
    fprintf(fp, "  \"blas_kernel\": {\"name\": \"%s\", \"source\": \"%s\", \"replaced\": ", BlasKernelName(), BlasKernelSource());
    fprintf(fp, BlasKernelFallback()[0] ? "\"%s\"},\n" : "null},\n", BlasKernelFallback());
    fprintf(fp, "  \"tao_reason\": \"%s\",\n  \"converged\": %s,\n  \"iterations\": %d,\n", TaoConvergedReasons[reason], rec->converged ? "true" : "false", (int)p->res.iterations);
    fprintf(fp, "  \"function_evaluations\": %d,\n  \"hessian_evaluations\": %d,\n", (int)p->res.nEnergyEvals, (int)p->res.nHessianEvals);
    fprintf(fp, "  \"stages\": %d,\n  \"load_cutbacks\": %d,\n", (int)p->res.stagesDone, (int)p->res.cutbacks);
    if (p->res.lagSolves) fprintf(fp, "  \"friction_lags\": %d,\n", (int)p->res.lagSolves); /* friction: the fixed points' lag updates */
    if (p->res.h0Refreshes) fprintf(fp, "  \"h0_refreshes\": %d,\n", (int)p->res.h0Refreshes); /* -lmvm_h0 contact */
    if (p->res.h0Refreshes) fprintf(fp, "  \"lmvm_pairs_dropped\": %d,\n", (int)p->res.pairsDropped); /* -lmvm_pair_ratio */
    if (p->res.h0Refreshes) fprintf(fp, "  \"lmvm_restarts\": %d,\n", (int)p->res.lmvmRestarts); /* -lmvm_restarts */
    if (p->res.decrementSolves) fprintf(fp, "  \"lmvm_decrement_solves\": %d,\n", (int)p->res.decrementSolves); /* -lmvm_decrement_rtol */
    if (p->res.decrementSolves) fprintf(fp, "  \"lmvm_decrement_floor_stops\": %d,\n", (int)p->res.decrementFloor);
    ContactJSONKeyReal(fp, "  ", "energy", p->res.energy);
    ContactJSONKeyReal(fp, ",\n  ", "gradient_norm", p->res.gnorm);
    /* the gradient against the contacts' nodal forces, and the stop's test of it (-stop_force_rtol) */
    if (p->res.contactForceNorm > 0) ContactJSONKeyReal(fp, ",\n  ", "force_residual", p->res.gnorm / p->res.contactForceNorm);
    else fprintf(fp, ",\n  \"force_residual\": null");
    fprintf(fp, ",\n  \"force_stop\": {\"rtol\": %.6g, \"continued\": %d, \"floors\": %d, \"fallbacks\": %d}", (double)p->cfg->stop.forceRtol, (int)p->fstop.continued, (int)p->fstop.floors, (int)p->fstop.fallbacks);
    ContactJSONKeyReal(fp, ",\n  ", "max_displacement", umax);
    ContactJSONKeyReal(fp, ",\n  ", "displacement_norm", PetscSqrtReal(unorm2));
    PetscCall(JSONReactions(fp, p));
    JSONLoadPath(fp, p);
    PetscCall(JSONLoadStages(fp, p));
    JSONLoads(fp, p);
    JSONForceControl(fp, p);
    PetscCall(JSONContact(fp, p));
    JSONBodies(fp, p, F);
    JSONAccuracy(fp, rec);
    JSONTaylor(fp, p);
    fprintf(fp, "  \"time\": {");
    for (PetscInt k = 0; k < RUN_TIME_N; ++k) ContactJSONKeyReal(fp, k ? ", " : "", RunTimeNames[k], rec->time[k]);
    fprintf(fp, "}\n}\n");
  }
  PetscCall(ContactOutputTextWrite(p->comm, &text, out->jtmp, out->json));
  PetscFunctionReturn(0);
}

PetscErrorCode RunWriteResults(Problem p, RunRecord *rec)
{
  BodyNodalFields    F[CONTACT_MAX_BODIES];
  ContactOutputFiles out;
  PetscLogDouble     t0, t1;

  PetscFunctionBeginUser;
  PetscCall(ContactOutputGetFiles(&out));
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogStagePush(contactLog.output));
  PetscCall(PetscLogEventBegin(contactLog.writeOutput, 0, 0, 0, 0));
  PetscCall(PetscMemzero(F, sizeof(F)));
  PetscCall(StagesComputeFigures(p)); /* -load_stages: each stage end's reactions and contact forces */
  PetscCall(ProblemScatterToBodies(p, p->X)); /* the fields of the solution */
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyComputeNodalFields(p->bodies[i], BodyGetLocalSolution(p->bodies[i]), &F[i]));
  if (out.h5[0]) {
    PetscCall(WriteHDF5(p, rec, F, &out));
    PetscCall(WriteXDMF(p, F, &out));
  }
  PetscCall(PetscTime(&t1));
  rec->time[RUN_TIME_OUTPUT] = t1 - t0;
  rec->time[RUN_TIME_TOTAL]  = t1 - rec->start;
  if (out.json[0]) PetscCall(WriteJSON(p, rec, F, &out));
  PetscCall(ContactOutputCommit(p->comm));
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyNodalFieldsDestroy(&F[i]));
  PetscCall(PetscLogEventEnd(contactLog.writeOutput, 0, 0, 0, 0));
  PetscCall(PetscLogStagePop());
  if (out.h5[0]) PetscCall(PetscPrintf(p->comm, "Wrote %s and %s\n", out.h5, out.xdmf));
  if (out.json[0]) PetscCall(PetscPrintf(p->comm, "Wrote %s\n", out.json));
  PetscFunctionReturn(0);
}
