/* A body's Dirichlet conditions: the scene's, each a physical group read
   from the options (-<body>_bc, -<body>_bc_<group>_components, _values,
   _exact, _control) and labelled on the mesh in BodySetUp; the program's own
   (the axis's u_r = 0, axis.c; the anchors of a body held by contact,
   anchors.c), added through BodyAddDirichlet; and the check of them all
   against each other and the loads.

   The check comes once the mesh, the conditions and the loads are set up,
   before anything is solved (the end of BodySetUp). A condition holds component c of a node
   where its group's label holds the node and c is among its components
   (the axis's u_r = 0, "r=0", is one; the anchors of a body held by
   contact, anchors.c, are the program's and placed where nothing else
   holds, so they are left out).

   A force-controlled component c of group G moves G rigidly by U so that
   G's reaction in c, the sum of dPi/du_c over G's nodes, is the force
   (forcecontrol.c). A node of G that another condition H also holds in c
   belongs to both: its value is one condition's, and the force goes partly
   into H. The reference scene's push controlled to a force of -55 with its
   corner shared by a clamped bottom ran to a result: P = 8.07, the bottom
   took 49.5. So that is refused, naming both groups and the node; a node H
   holds only in the other component is no conflict.

   A load acts in c at a node where its consistent nodal force from one of
   its edges (loads.c) has a c-component above round-off, 1e-12 of that
   edge's largest: a traction (0, t) acts in y only, a pressure on a
   straight edge along its normal only. Its share at a node held in c goes
   into the reaction of the condition that holds it, and then:
   - held by a force control, the controlled group transmits its force
     plus that share: refused, naming the load's group and the control's;
   - held by a displacement, the support carries that share: this is how a
     load that reaches a support is discretised (a tube's bore ending on its
     symmetry planes, a cantilever's top at its clamp), so it is accepted;
     but where every node at which the load acts in c is held in c, the
     load's c-part moves nothing at all (a traction on a clamped group): a
     warning line naming the group, the component and the groups that hold
     it, and the run goes on. */
#include "conditions.h"
#include "loads.h"
#include "stagedvalues.h"
#include "options.h"
#include "bodyimpl.h"

PetscErrorCode BodyBCSetFromOptions(Body b, const char prefix[], BodyBC *bc)
{
  char      opt[5 * CONTACT_NAME_LEN], bprefix[4 * CONTACT_NAME_LEN], *comps[3] = {NULL, NULL, NULL}, *control[3] = {NULL, NULL, NULL};
  PetscReal v[3 * CONTACT_MAX_STAGES + 1] = {0};
  PetscInt  nc = 3, nv, nctl = 3;
  PetscBool setc, setv, setctl, help;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(bprefix, sizeof(bprefix), "%sbc_%s_", prefix, bc->group));
  bc->values[0] = bc->values[1] = bc->values[2] = 0.0;
  PetscOptionsBegin(b->comm, bprefix, "Dirichlet condition", NULL);
  help = (PetscBool)PetscOptionsObject->printhelp;
  nv   = help ? 2 * b->nstages : 3 * CONTACT_MAX_STAGES + 1; /* -help shows two components a stage (PETSc lists nv entries where none are given) */
  PetscCall(ContactOptionsStringArray(PetscOptionsObject, "-components", "Constrained components: x, y, z (z in 3D; default every component of the body)", NULL, comps, &nc, &setc));
  PetscCall(PetscOptionsRealArray("-values", "Imposed displacement of each constrained component (a force where -control force; default 0); with -load_stages S, S values per component, stage-major: stage 1's components, then stage 2's (x1,y1,x2,y2,...)", NULL, v, &nv, &setv));
  PetscCall(PetscOptionsBool("-exact", "Impose the body's exact solution", NULL, bc->exact, &bc->exact, NULL));
  PetscCall(ContactOptionsStringArray(PetscOptionsObject, "-control", "Each component's control: displacement (the value is imposed) or force (the group moves rigidly so that its reaction is the value); default displacement", NULL, control, &nctl, &setctl));
  PetscOptionsEnd();
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%svalues", bprefix));
  bc->allComps = (PetscBool)!setc;
  if (!setc) { /* every component of the body, whose dimension the mesh gives (BodyBCResolve): as many as the values (or controls) give a stage, else 2 until then */
    const PetscInt S = b->nstages, per = setv ? (nv % S ? -1 : nv / S) : setctl ? nctl : 2;
    PetscCheck(per == 2 || per == 3, b->comm, PETSC_ERR_USER_INPUT, "option %s: %" PetscInt_FMT " values: give one per component of the body (x,y in 2D, x,y,z in 3D) for each of the %" PetscInt_FMT " load stages, or name the components (-%scomponents)", setv ? opt : "-control", setv ? nv : nctl, S, bprefix);
    bc->ncomp = per;
    for (PetscInt c = 0; c < per; ++c) bc->comps[c] = c;
  } else {
    bc->ncomp = nc;
    for (PetscInt c = 0; c < nc; ++c) {
      PetscBool isx, isy, isz;
      PetscCall(PetscStrcmp(comps[c], "x", &isx));
      PetscCall(PetscStrcmp(comps[c], "y", &isy));
      PetscCall(PetscStrcmp(comps[c], "z", &isz));
      PetscCheck(isx || isy || isz, b->comm, PETSC_ERR_USER_INPUT, "option -%scomponents: unknown component '%s' (use x, y, z)", bprefix, comps[c]);
      bc->comps[c] = isx ? 0 : isy ? 1 : 2;
      for (PetscInt d = 0; d < c; ++d) PetscCheck(bc->comps[d] != bc->comps[c], b->comm, PETSC_ERR_USER_INPUT, "option -%scomponents: component %s given twice", bprefix, comps[c]);
      PetscCall(PetscFree(comps[c]));
    }
  }
  if (setv && !help) PetscCall(BodyStagedValues(b, opt, nv, bc->ncomp, v, 3, &bc->stage[0][0]));
  for (PetscInt c = 0; c < bc->ncomp; ++c) bc->values[c] = bc->stage[b->nstages - 1][c]; /* the last stage's, until the solve sets another */
  PetscCheck(!bc->exact || b->hasExact, b->comm, PETSC_ERR_USER_INPUT, "option -%sexact: body %s has no -%sexact solution", bprefix, b->name, prefix);
  PetscCheck(!setctl || nctl == bc->ncomp, b->comm, PETSC_ERR_USER_INPUT, "option -%scontrol: %" PetscInt_FMT " entries for %" PetscInt_FMT " components", bprefix, nctl, bc->ncomp);
  for (PetscInt c = 0; setctl && c < nctl; ++c) {
    PetscBool disp, force;
    PetscCall(PetscStrcmp(control[c], "displacement", &disp));
    PetscCall(PetscStrcmp(control[c], "force", &force));
    PetscCheck(disp || force, b->comm, PETSC_ERR_USER_INPUT, "option -%scontrol: unknown control '%s' (use displacement, force)", bprefix, control[c]);
    PetscCheck(!force || !bc->exact, b->comm, PETSC_ERR_USER_INPUT, "option -%scontrol: a force-controlled component cannot impose the exact solution", bprefix);
    bc->control[c] = force;
    if (force) { /* the value is the force; the displacement starts at 0 */
      bc->force[c]  = bc->values[c];
      bc->values[c] = 0.0;
    }
    PetscCall(PetscFree(control[c]));
  }
  PetscFunctionReturn(0);
}

/* After the mesh: condition bc's components against the body's dimension
   (the default, every component, now means dim of them). */
static PetscErrorCode BodyBCResolve(Body b, BodyBC *bc)
{
  const char *axis[3] = {"x", "y", "z"};

  PetscFunctionBeginUser;
  if (bc->allComps && !bc->anchor) {
    PetscBool given = PETSC_FALSE;
    for (PetscInt c = 0; c < bc->ncomp; ++c)
      for (PetscInt st = 0; st < b->nstages; ++st)
        if (bc->stage[st][c] != 0 || bc->control[c]) given = PETSC_TRUE;
    PetscCheck(!given || bc->ncomp == b->dim, b->comm, PETSC_ERR_USER_INPUT, "option -%s_bc_%s_values: %" PetscInt_FMT " components a stage for a %" PetscInt_FMT "D body (mesh %s)", b->name, bc->group, bc->ncomp, b->dim, b->msh);
    bc->ncomp = b->dim;
    for (PetscInt c = 0; c < b->dim; ++c) bc->comps[c] = c;
  }
  for (PetscInt c = 0; c < bc->ncomp; ++c) PetscCheck(bc->comps[c] < b->dim, b->comm, PETSC_ERR_USER_INPUT, "option -%s_bc_%s_components: component %s of a %" PetscInt_FMT "D body (mesh %s)", b->name, bc->group, axis[bc->comps[c]], b->dim, b->msh);
  PetscFunctionReturn(0);
}

/* The displacement condition ctx = {b, bc} imposes at x (DMAddBoundary's
   function): bc's values in its components, or the exact solution. */
static PetscErrorCode BCValue(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  void  **c  = (void **)ctx;
  Body    b  = (Body)c[0];
  BodyBC *bc = (BodyBC *)c[1];

  (void)dim; (void)t;
  for (PetscInt i = 0; i < Nc; ++i) u[i] = 0.0;
  if (bc->exact) {
    PetscReal ue[3];
    b->exact.u(b->exact.params, x, ue);
    for (PetscInt i = 0; i < Nc && i < 3; ++i) u[i] = ue[i];
  } else
    for (PetscInt i = 0; i < bc->ncomp; ++i) u[bc->comps[i]] = bc->values[i];
  return 0;
}

/* Imposes condition i on the displacement field: its components, at the
   points where its label is 1, take BCValue's values. */
static PetscErrorCode BodyBCImpose(Body b, PetscInt i)
{
  BodyBC   *bc  = &b->bc[i];
  void    **ctx = b->bcctx[i];
  PetscInt  one = 1;

  PetscFunctionBeginUser;
  ctx[0] = b;
  ctx[1] = bc;
  PetscCall(DMAddBoundary(b->dm, DM_BC_ESSENTIAL, bc->group, bc->label, 1, &one, 0, bc->ncomp, bc->comps, (void (*)(void))BCValue, NULL, ctx, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyConditionsSetUp(Body b)
{
  DMLabel faces;

  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(b->dm, "Face Sets", &faces));
  for (PetscInt i = 0; i < b->nbc; ++i) {
    BodyBC  *bc = &b->bc[i];
    char     lname[2 * CONTACT_NAME_LEN];
    IS       is = NULL;
    PetscInt n = 0, gn;

    PetscCall(BodyBCResolve(b, bc));
    PetscCall(BodyGetPhysicalTag(b, bc->group, b->dim - 1, &bc->tag));
    PetscCall(PetscSNPrintf(lname, sizeof(lname), "bc_%s", bc->group));
    PetscCall(DMCreateLabel(b->dm, lname));
    PetscCall(DMGetLabel(b->dm, lname, &bc->label));
    if (faces) PetscCall(DMLabelGetStratumIS(faces, bc->tag, &is));
    if (is) {
      const PetscInt *pts;
      PetscCall(ISGetLocalSize(is, &n));
      PetscCall(ISGetIndices(is, &pts));
      for (PetscInt j = 0; j < n; ++j) PetscCall(DMLabelSetValue(bc->label, pts[j], 1));
      PetscCall(ISRestoreIndices(is, &pts));
      PetscCall(ISDestroy(&is));
    }
    PetscCall(MPIU_Allreduce(&n, &gn, 1, MPIU_INT, MPI_SUM, b->comm));
    PetscCheck(gn > 0, b->comm, PETSC_ERR_FILE_UNEXPECTED, "body %s: physical group '%s' of mesh %s has no %s", b->name, bc->group, b->msh, b->dim == 3 ? "faces" : "edges");
    PetscCall(DMPlexLabelComplete(b->dm, bc->label));
    PetscCall(BodyBCImpose(b, i));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BodyAddDirichlet(Body b, const BodyBC *bc)
{
  PetscFunctionBeginUser;
  PetscCheck(b->nbc < CONTACT_MAX_BC, b->comm, PETSC_ERR_USER_INPUT, "body %s: no room for its condition %s: at most %d Dirichlet conditions", b->name, bc->group, CONTACT_MAX_BC);
  b->bc[b->nbc] = *bc;
  PetscCall(BodyBCImpose(b, b->nbc++));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyBCHolds(const BodyBC *bc, PetscInt p, PetscInt c, PetscInt *k)
{
  PetscInt val;

  PetscFunctionBeginUser;
  *k = -1;
  PetscCall(DMLabelGetValue(bc->label, p, &val));
  for (PetscInt l = 0; l < bc->ncomp && val == 1; ++l)
    if (bc->comps[l] == c) *k = l;
  PetscFunctionReturn(0);
}

PetscErrorCode BodyBCHolding(Body b, PetscInt p, PetscInt c, PetscInt *i, PetscInt *k)
{
  PetscFunctionBeginUser;
  *i = *k = -1;
  for (PetscInt j = 0; j < b->nbc && *i < 0; ++j) {
    PetscCall(BodyBCHolds(&b->bc[j], p, c, k));
    if (*k >= 0) *i = j;
  }
  PetscFunctionReturn(0);
}

/* Collective: whether some rank found a conflict, and the first such rank's
   description info[n] on every rank (so that every rank stops with the same line). */
static PetscErrorCode ShareFirst(Body b, PetscBool found, PetscInt n, PetscReal info[], PetscBool *any)
{
  PetscMPIInt rank, size, first;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(b->comm, &rank));
  PetscCallMPI(MPI_Comm_size(b->comm, &size));
  first = found ? rank : size;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, b->comm));
  *any = (PetscBool)(first < size);
  if (*any) PetscCallMPI(MPI_Bcast(info, (PetscMPIInt)n, MPIU_REAL, first, b->comm));
  PetscFunctionReturn(0);
}

static const char *const Component[2] = {"x", "y"};

/* Point p's node coordinates for a message, into xy[2]: the round-off of
   the cell's coordinate field (1e-17 for a corner at 0) shown as 0. */
static void NodeShown(Body b, PetscInt p, PetscReal xy[])
{
  const PetscReal *x = &b->xpoint[2 * (p - b->pStart)];

  for (PetscInt d = 0; d < 2; ++d) xy[d] = PetscAbsReal(x[d]) <= 1e-12 * PetscAbsReal(x[1 - d]) ? 0.0 : x[d];
}

/* Refuses a node of a force-controlled group that another condition holds
   in the controlled component. */
static PetscErrorCode CheckForceControls(Body b)
{
  PetscSection s;
  PetscReal    info[5] = {0, 0, 0, 0, 0}; /* G, H, c, x, y */
  PetscBool    found = PETSC_FALSE, any;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(b->dm, &s));
  for (PetscInt i = 0; i < b->nbc && !found; ++i) {
    const BodyBC   *G = &b->bc[i];
    IS              is;
    PetscInt        n = 0;
    const PetscInt *pts = NULL;

    if (G->anchor) continue;
    PetscCall(DMLabelGetStratumIS(G->label, 1, &is));
    if (is) {
      PetscCall(ISGetLocalSize(is, &n));
      PetscCall(ISGetIndices(is, &pts));
    }
    for (PetscInt k = 0; k < G->ncomp && !found; ++k) {
      if (!G->control[k]) continue;
      for (PetscInt q = 0; q < n && !found; ++q) {
        PetscInt dof;
        PetscCall(PetscSectionGetDof(s, pts[q], &dof));
        for (PetscInt j = 0; j < b->nbc && dof && !found; ++j) {
          PetscInt l;
          if (j == i || b->bc[j].anchor) continue;
          PetscCall(BodyBCHolds(&b->bc[j], pts[q], G->comps[k], &l));
          if (l < 0) continue;
          found   = PETSC_TRUE;
          info[0] = i;
          info[1] = j;
          info[2] = G->comps[k];
          NodeShown(b, pts[q], &info[3]);
        }
      }
    }
    if (is) {
      PetscCall(ISRestoreIndices(is, &pts));
      PetscCall(ISDestroy(&is));
    }
  }
  PetscCall(ShareFirst(b, found, 5, info, &any));
  if (any) {
    const char *G = b->bc[(PetscInt)info[0]].group, *H = b->bc[(PetscInt)info[1]].group, *c = Component[(PetscInt)info[2]];
    SETERRQ(b->comm, PETSC_ERR_USER_INPUT, "body %s: group %s, force-controlled in %s, shares the node at (%g, %g) with group %s, which holds it in %s too: part of the force would go into %s; let no other condition hold a force-controlled group's nodes in the controlled component", b->name, G, c, (double)info[3], (double)info[4], H, c, H);
  }
  PetscFunctionReturn(0);
}

/* The groups of the conditions in the bit set held, as "a", "a and b", "a, b and c". */
static PetscErrorCode GroupList(Body b, PetscInt held, size_t len, char list[])
{
  PetscInt n = 0, m = 0;

  PetscFunctionBeginUser;
  list[0] = 0;
  for (PetscInt j = 0; j < b->nbc; ++j) n += (held >> j) & 1;
  for (PetscInt j = 0; j < b->nbc; ++j) {
    if (!((held >> j) & 1)) continue;
    if (m) PetscCall(PetscStrlcat(list, m == n - 1 ? " and " : ", ", len));
    PetscCall(PetscStrlcat(list, b->bc[j].group, len));
    ++m;
  }
  PetscFunctionReturn(0);
}

/* Collective: warns of load L where, in a component it acts in (acts, over
   this rank's nodes), no node it acts at is free (loose); held: the
   conditions (bits) that hold the nodes it acts at, per component. */
static PetscErrorCode WarnHeldLoad(Body b, const BodyLoad *L, PetscInt acts[2], PetscInt loose[2], PetscInt held[2])
{
  PetscBool   x, y, whole;
  const char *c;
  char        by[CONTACT_MAX_BC * (CONTACT_NAME_LEN + 8)], part[32] = "the load";

  PetscFunctionBeginUser;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, acts, 2, MPIU_INT, MPI_MAX, b->comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, loose, 2, MPIU_INT, MPI_MAX, b->comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, held, 2, MPIU_INT, MPI_BOR, b->comm));
  x     = (PetscBool)(acts[0] && !loose[0]);
  y     = (PetscBool)(acts[1] && !loose[1]);
  whole = (PetscBool)(!loose[0] && !loose[1]); /* in every component it acts in */
  if (!x && !y) PetscFunctionReturn(0);
  c = x && y ? "x and y" : x ? "x" : "y";
  PetscCall(GroupList(b, (x ? held[0] : 0) | (y ? held[1] : 0), sizeof(by), by));
  if (!whole) PetscCall(PetscSNPrintf(part, sizeof(part), "its %s part", c));
  PetscCall(PetscFPrintf(b->comm, PETSC_STDERR, "contact: warning: body %s: every node where the load on group %s acts in %s is held in %s (by %s): %s moves nothing and goes into the reactions\n", b->name, L->group, c, c, by, part));
  PetscFunctionReturn(0);
}

/* Refuses load l where it acts at a node that a force control holds in the
   same component; warns where its part in a component acts only at held nodes. */
static PetscErrorCode CheckLoad(Body b, PetscInt l)
{
  const BodyLoad *L = &b->load[l];
  IS              is;
  PetscInt        n, acts[2] = {0, 0}, loose[2] = {0, 0}, held[2] = {0, 0}; /* per component: acts somewhere, at an unheld node, the conditions (bits) that hold it */
  const PetscInt *edges = NULL;
  PetscReal       info[4] = {0, 0, 0, 0}; /* control's condition, c, x, y */
  PetscBool       found = PETSC_FALSE, any;

  PetscFunctionBeginUser;
  PetscCall(BodyLoadGetEdges(b, L, &n, &is));
  if (is) PetscCall(ISGetIndices(is, &edges));
  for (PetscInt e = 0; e < n; ++e) {
    PetscInt  pts[3];
    PetscReal fe[3][2], big = 0;

    PetscCall(BodyLoadEdgeForces(b, L, edges[e], pts, fe));
    for (PetscInt a = 0; a < 3; ++a) big = PetscMax(big, PetscMax(PetscAbsReal(fe[a][0]), PetscAbsReal(fe[a][1])));
    for (PetscInt a = 0; a < 3; ++a)
      for (PetscInt c = 0; c < 2; ++c) {
        PetscBool h = PETSC_FALSE;
        if (!(PetscAbsReal(fe[a][c]) > 1e-12 * big)) continue;
        acts[c] = 1;
        for (PetscInt j = 0; j < b->nbc; ++j) {
          PetscInt k;
          if (b->bc[j].anchor) continue;
          PetscCall(BodyBCHolds(&b->bc[j], pts[a], c, &k));
          if (k < 0) continue;
          h = PETSC_TRUE;
          held[c] |= (PetscInt)1 << j;
          if (b->bc[j].control[k] && !found) {
            found   = PETSC_TRUE;
            info[0] = j;
            info[1] = c;
            NodeShown(b, pts[a], &info[2]);
          }
        }
        if (!h) loose[c] = 1;
      }
  }
  if (is) {
    PetscCall(ISRestoreIndices(is, &edges));
    PetscCall(ISDestroy(&is));
  }
  PetscCall(ShareFirst(b, found, 4, info, &any));
  if (any) {
    const char *G = b->bc[(PetscInt)info[0]].group, *c = Component[(PetscInt)info[1]];
    SETERRQ(b->comm, PETSC_ERR_USER_INPUT, "body %s: the load on group %s acts in %s at the node (%g, %g), which group %s holds by its force control in %s: that part of the load would go into the control's reaction; load no node of a force-controlled group in the controlled component", b->name, L->group, c, (double)info[2], (double)info[3], G, c);
  }
  PetscCall(WarnHeldLoad(b, L, acts, loose, held));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyCheckConditions(Body b)
{
  PetscFunctionBeginUser;
  PetscCall(CheckForceControls(b));
  for (PetscInt l = 0; l < b->nload && b->dim == 2; ++l) PetscCall(CheckLoad(b, l)); /* a 3D body's face loads: not yet checked against its force controls */
  PetscFunctionReturn(0);
}
