/* A rigid body: its curves read from the Gmsh file, its reference point and
   its prescribed rigid motion (rigidbody.h).

   The curves. Gmsh writes the mesh as MSH 2.2 (meshgen.c asks for it): the
   nodes, then the elements, each with its physical tag first. A rigid body
   keeps the second-order lines (type 8: the two ends, then the middle) and
   ignores points and any cells (a .geo that also has the body's surface
   serves as it is). Rank 0 reads the file (MeshCheckFile has checked it
   whole) and broadcasts the curves: they are small, and every rank holds
   every contact surface anyway (surface.c).

   The motion. u(X) = t + (R(theta) - I)(X - c) moves every point rigidly.
   Its translation is prescribed in a component where a condition of the
   body holds that component (of any of its groups: the body is one piece),
   with the condition's value; two conditions that hold the same component
   differently are refused. The load factor scales a prescribed t and theta
   as it scales an elastic body's Dirichlet values. A component that a
   condition force-controls, or that no condition holds, and the rotation
   where -<body>_rigid_rotation free, are unknowns (rigidbody.h): a control's
   force is scaled by the load factor, the others are held by the contact
   alone.

   The unknowns' derivatives. With q = (t_x, t_y, s = L theta), a point at
   x = X + u(X) has dx/dq = J = [(1, 0), (0, 1), perp(x - c - t) / L],
   perp(v) = (-v_y, v_x), and d2x/ds2 = -(x - c - t) / L^2, the others'
   second derivatives zero. The contact energy Pi_c(x(q)) so has the
   gradient J^T g (the force, and the moment about c + t over L) and the
   Hessian J^T H_c J + sum_nodes g . d2x/dq2: the contact's Hessian block
   between the body's surface nodes mapped by J (BodyRigidAddHessian, as
   the formulations add their blocks), plus -sum g.(x - c - t) / L^2 in the
   rotation's corner (curl, from the gradient's evaluation). The coupling to
   the other body's dofs is H_c's mixed block times J: the border's
   columns (forceborder.c).

   The force. The contact terms add their gradient dPi/du at the surface
   nodes (summed over ranks, so the same on every rank); for a rigid body it
   goes into the body's force F = sum g and its moment about the current
   reference point, M = sum (x - c - t) x g = dPi/dtheta (in r-z the axial
   force alone: the radial parts cancel round each ring). F is the reaction
   of the conditions that hold the translation, as the reaction of an
   elastic body's Dirichlet group is the sum of dPi/du over its nodes. */
#include "rigidbody.h"
#include "history.h"
#include "stagedvalues.h"
#include "options.h"
#include "mshcheck.h"
#include "meshgen.h"
#include "bodyimpl.h"

static const char *BodyGetControlComponent_Rigid(Body, PetscInt, PetscInt);

/* The options as given: what they mean depends on the body's dimension,
   which its mesh tells (RigidParseMotion, at the set-up). */
PetscErrorCode BodyRigidSetFromOptions(Body b, const char prefix[])
{
  BodyRigid *r;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&r));
  b->rg = r;
  PetscCall(PetscStrncpy(r->rotOpt, "0", sizeof(r->rotOpt)));
  PetscCall(PetscStrncpy(r->prefix, prefix, sizeof(r->prefix)));
  r->ncentre = 3;
  r->nmom    = 3 * CONTACT_MAX_STAGES + 1;
  PetscOptionsBegin(b->comm, prefix, "Rigid body options", NULL);
  PetscCall(PetscOptionsRealArray("-rigid_centre", "Reference point x,y (3D: x,y,z) of a rigid body's rotation (default the centroid of its curves, weighted by length; 3D of its surfaces, weighted by area)", NULL, r->centreOpt, &r->ncentre, &r->setCentre));
  PetscCall(ContactOptionsString(PetscOptionsObject, "-rigid_rotation", "A rigid body's rotation about its reference point at the full load, radians, counterclockwise (0: held; with -load_stages S, S values, each stage's end), or free (held by the contact alone: the contact's moment about the reference point is zero). 3D: a rotation vector ax,ay,az per stage (its direction the axis, its length the angle), each component a number or free, or free (all three)", NULL, r->rotOpt, r->rotOpt, sizeof(r->rotOpt), &r->setRot));
  PetscCall(PetscOptionsRealArray("-rigid_moment", "The moment on a rigid body's free rotation about its reference point at the full load, counterclockwise (with -load_stages S, S values, each stage's end): its potential -M theta, so that the contact's moment balances M. 3D: mx,my,mz per stage (stage-major), on the components -<body>_rigid_rotation leaves free; -M . theta, theta the rotation vector: the contact's moment about the reference point is T(theta)^-T M, M itself for a rotation about a fixed axis along M", NULL, r->momOpt, &r->nmom, &r->setMom));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

/* 2D: -rigid_rotation, a number per stage or free, and -rigid_centre x,y. */
static PetscErrorCode RigidParseMotion2D(Body b, BodyRigid *r)
{
  const char *prefix = r->prefix;
  PetscReal   v[CONTACT_MAX_STAGES + 1];
  PetscInt    nv = 0;
  PetscBool   free;
  char        rot[64 * CONTACT_MAX_STAGES], opt[2 * CONTACT_NAME_LEN], *tok, *save = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(rot, r->rotOpt, sizeof(rot)));
  PetscCall(PetscStrcmp(rot, "free", &free));
  PetscCheck(!free || !b->axisym, b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_rotation: a rigid body in r-z moves along the axis only, and cannot turn freely", prefix);
  r->unknown[2] = free;
  for (tok = strtok_r(rot, ",", &save); tok && !free && nv <= CONTACT_MAX_STAGES; tok = strtok_r(NULL, ",", &save)) {
    char *end;
    v[nv] = strtod(tok, &end);
    PetscCheck(end != tok && !*end, b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_rotation: must be a number (radians), got '%s'", prefix, tok);
    PetscCheck(!PetscIsInfOrNanReal(v[nv]), b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_rotation: must be finite, got %g", prefix, (double)v[nv]);
    PetscCheck(!b->axisym || v[nv] == 0.0, b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_rotation: a rigid body in r-z moves along the axis only, got %g", prefix, (double)v[nv]);
    nv++;
  }
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%srigid_rotation", prefix));
  if (r->setRot && !free) PetscCall(BodyStagedValues(b, opt, nv, 1, v, 1, r->rotation)); /* else 0 at every stage */
  PetscCheck(!r->setCentre || r->ncentre == 2, b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_centre: give two numbers x,y", prefix);
  PetscFunctionReturn(0);
}

/* The reference point where given (checked finite), else the centroid, once read. */
static PetscErrorCode RigidSetCentre(Body b, BodyRigid *r)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < r->ncentre && r->setCentre; ++k) PetscCheck(!PetscIsInfOrNanReal(r->centreOpt[k]), b->comm, PETSC_ERR_USER_INPUT, "option -%srigid_centre: must be finite, got %g", r->prefix, (double)r->centreOpt[k]);
  if (r->setCentre)
    for (PetscInt k = 0; k < r->dim; ++k) r->centre[k] = r->centreOpt[k];
  else r->centre[0] = r->centre[1] = r->centre[2] = PETSC_MAX_REAL; /* the centroid, once read */
  PetscFunctionReturn(0);
}

/* Rank 0: the nodes and second-order lines of an MSH 2.2 file. */
static PetscErrorCode RigidReadCurves(Body b, BodyRigid *r)
{
  FILE    *fp;
  char     line[4096];
  PetscInt nnodes = 0, *ids = NULL, nel = 0, ne = 0, *en = NULL, *tag = NULL;
  PetscReal *X    = NULL;

  PetscFunctionBeginUser;
  fp = fopen(b->msh, "r");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "body %s: cannot open mesh %s", b->name, b->msh);
  while (fgets(line, sizeof(line), fp)) {
    if (!strncmp(line, "$Nodes", 6)) {
      PetscCheck(fgets(line, sizeof(line), fp) && sscanf(line, "%" PetscInt_FMT, &nnodes) == 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: bad $Nodes", b->name, b->msh);
      PetscCall(PetscMalloc2(nnodes, &ids, 2 * nnodes, &X));
      for (PetscInt i = 0; i < nnodes; ++i) {
        double x, y, z;
        PetscCheck(fgets(line, sizeof(line), fp) && sscanf(line, "%" PetscInt_FMT " %lf %lf %lf", &ids[i], &x, &y, &z) == 4, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: bad node line", b->name, b->msh);
        X[2 * i]     = x;
        X[2 * i + 1] = y;
      }
    } else if (!strncmp(line, "$Elements", 9)) {
      PetscCheck(fgets(line, sizeof(line), fp) && sscanf(line, "%" PetscInt_FMT, &nel) == 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: bad $Elements", b->name, b->msh);
      PetscCall(PetscMalloc2(3 * nel + 3, &en, nel + 1, &tag));
      for (PetscInt i = 0; i < nel; ++i) {
        long  v[16];
        int   nv = 0;
        char *s  = line, *end;
        PetscCheck(fgets(line, sizeof(line), fp), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: short $Elements", b->name, b->msh);
        for (long x = strtol(s, &end, 10); end != s && nv < 16; x = strtol(s, &end, 10)) {
          v[nv++] = x;
          s       = end;
        }
        if (nv < 3 || v[1] != 8) continue; /* id, type (8: 3-node line), ntags, tags..., nodes */
        PetscCheck(nv == 3 + v[2] + 3 && v[2] >= 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: bad line element %ld", b->name, b->msh, v[0]);
        tag[ne] = (PetscInt)v[3];
        for (PetscInt j = 0; j < 3; ++j) en[3 * ne + j] = (PetscInt)v[3 + v[2] + j];
        ne++;
      }
    }
  }
  fclose(fp);
  PetscCheck(ne > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s has no second-order lines: a rigid body is given by its curves (Mesh.ElementOrder = 2)", b->name, b->msh);
  /* nodes of the lines only, sorted by Gmsh number; lines' nodes as indices */
  {
    PetscInt  n = 3 * ne, *used, *perm;
    PetscCall(PetscMalloc1(n, &used));
    PetscCall(PetscArraycpy(used, en, n));
    PetscCall(PetscSortRemoveDupsInt(&n, used));
    PetscCall(PetscMalloc1(nnodes, &perm));
    for (PetscInt i = 0; i < nnodes; ++i) perm[i] = i;
    PetscCall(PetscSortIntWithArray(nnodes, ids, perm));
    r->nn = n;
    PetscCall(PetscMalloc2(n, &r->ids, 2 * n, &r->X));
    for (PetscInt i = 0; i < n; ++i) {
      PetscInt loc;
      PetscCall(PetscFindInt(used[i], nnodes, ids, &loc));
      PetscCheck(loc >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s: a line's node %" PetscInt_FMT " is not among its nodes", b->name, b->msh, used[i]);
      r->ids[i]       = used[i];
      r->X[2 * i]     = X[2 * perm[loc]];
      r->X[2 * i + 1] = X[2 * perm[loc] + 1];
    }
    r->ne = ne;
    PetscCall(PetscMalloc2(3 * ne, &r->enodes, ne, &r->etag));
    for (PetscInt e = 0; e < ne; ++e) {
      r->etag[e] = tag[e];
      for (PetscInt j = 0; j < 3; ++j) PetscCall(PetscFindInt(en[3 * e + j], n, r->ids, &r->enodes[3 * e + j]));
    }
    PetscCall(PetscFree(used));
    PetscCall(PetscFree(perm));
  }
  PetscCall(PetscFree2(ids, X));
  PetscCall(PetscFree2(en, tag));
  PetscFunctionReturn(0);
}

/* The translation's components from the conditions: prescribed by one
   condition's value or by several alike, force-controlled by one, or held
   by no condition (an unknown the contact holds). */
static PetscErrorCode RigidConditions(Body b, BodyRigid *r)
{
  PetscReal   value[CONTACT_MAX_STAGES][3];
  PetscInt    by[3] = {-1, -1, -1};
  const char *axis[3] = {"x", "y", "z"};

  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < RIGID_MAX_UNKNOWNS; ++q) r->qbc[q] = -1;
  PetscCall(PetscArrayzero(&value[0][0], 3 * CONTACT_MAX_STAGES));
  for (PetscInt i = 0; i < b->nbc; ++i) {
    const BodyBC *bc = &b->bc[i];
    PetscInt      tag;
    PetscCall(BodyGetPhysicalTag(b, bc->group, r->dim - 1, &tag));
    PetscCheck(!bc->exact, b->comm, PETSC_ERR_USER_INPUT, "option -%s_bc_%s_exact: body %s is rigid: it has no exact solution", b->name, bc->group, b->name);
    for (PetscInt k = 0; k < bc->ncomp; ++k) {
      const PetscInt c    = bc->comps[k];
      PetscBool      same = PETSC_TRUE;
      for (PetscInt s = 0; s < b->nstages; ++s) same = (PetscBool)(same && value[s][c] == bc->stage[s][k]);
      PetscCheck(by[c] < 0 || (!bc->control[k] && !r->control[c] && same), b->comm, PETSC_ERR_USER_INPUT, "body %s is rigid: groups %s and %s both give its translation in %s (%s %g, %s %g); give it once", b->name, b->bc[PetscMax(by[c], 0)].group, bc->group, axis[c], by[c] >= 0 && r->control[c] ? "force" : "value", (double)value[b->nstages - 1][c], bc->control[k] ? "force" : "value", (double)(bc->control[k] ? bc->force[k] : bc->values[k]));
      PetscCheck(!(c == 0 && b->axisym && bc->control[k]), b->comm, PETSC_ERR_USER_INPUT, "option -%s_bc_%s_control: body %s is rigid in r-z: it moves along the axis only, and a radial force control has nothing to move", b->name, bc->group, b->name);
      by[c] = i;
      for (PetscInt s = 0; s < b->nstages; ++s) value[s][c] = bc->stage[s][k]; /* a displacement, or a control's force */
      if (bc->control[k]) {
        r->unknown[c] = r->control[c] = PETSC_TRUE;
        r->qforce[c]  = bc->force[k];
        r->qbc[c]     = i;
      }
    }
  }
  for (PetscInt c = 0; c < r->dim; ++c) {
    if (c == 0 && b->axisym) { /* r-z: the body moves along the axis alone */
      for (PetscInt s = 0; s < b->nstages; ++s) PetscCheck(by[0] < 0 || value[s][0] == 0.0, b->comm, PETSC_ERR_USER_INPUT, "body %s is rigid in r-z: it moves along the axis only, and group %s gives it a radial motion %g", b->name, b->bc[by[0]].group, (double)value[s][0]);
      continue;
    }
    if (by[c] < 0) r->unknown[c] = PETSC_TRUE; /* held by the contact alone */
  }
  for (PetscInt s = 0; s < b->nstages; ++s)
    for (PetscInt c = 0; c < r->dim; ++c) r->tEnd[s][c] = r->unknown[c] ? 0.0 : value[s][c];
  for (PetscInt c = 0; c < r->dim; ++c) r->t[c] = r->tEnd[b->nstages - 1][c]; /* at the last stage's end until BodySetLoad */
  PetscFunctionReturn(0);
}

/* The centroid of the body's curves, each point weighted by its length: the
   same whatever the mesh's grading (a circle's is its centre, a
   rectangle's its middle). Each quadratic line (nodes at xi = -1, +1, 0)
   by 4-point Gauss. */
static PetscErrorCode RigidCurvesCentroid(BodyRigid *r)
{
  PetscReal gx[4], gw[4], L = 0.0, c[2] = {0, 0};

  PetscFunctionBeginUser;
  PetscCall(PetscDTGaussQuadrature(4, -1.0, 1.0, gx, gw));
  for (PetscInt e = 0; e < r->ne; ++e)
    for (PetscInt q = 0; q < 4; ++q) {
      const PetscReal xi = gx[q], N[3] = {0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi}, dN[3] = {xi - 0.5, xi + 0.5, -2.0 * xi};
      PetscReal       p[2] = {0, 0}, t[2] = {0, 0}, w;
      for (PetscInt k = 0; k < 3; ++k)
        for (PetscInt d = 0; d < 2; ++d) {
          p[d] += N[k] * r->X[2 * r->enodes[3 * e + k] + d];
          t[d] += dN[k] * r->X[2 * r->enodes[3 * e + k] + d];
        }
      w = gw[q] * PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
      L += w;
      c[0] += w * p[0];
      c[1] += w * p[1];
    }
  r->centre[0] = c[0] / L;
  r->centre[1] = c[1] / L;
  PetscFunctionReturn(0);
}

/* 2D: the curves, read by rank 0 and broadcast, their centroid and size. */
static PetscErrorCode RigidSetUpCurves(Body b, BodyRigid *r)
{
  PetscMPIInt rank;
  PetscInt    n[2];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(b->comm, &rank));
  PetscCall(MeshCheckCurvesFile(b->comm, b->name, b->msh));
  PetscCall(MeshReadPhysicalNames(b->comm, b->msh, &b->nphys, &b->physNames, &b->physDims, &b->physTags));
  if (!rank) PetscCall(RigidReadCurves(b, r));
  n[0] = r->nn;
  n[1] = r->ne;
  PetscCallMPI(MPI_Bcast(n, 2, MPIU_INT, 0, b->comm));
  if (rank) {
    r->nn = n[0];
    r->ne = n[1];
    PetscCall(PetscMalloc2(r->nn, &r->ids, 2 * r->nn, &r->X));
    PetscCall(PetscMalloc2(3 * r->ne, &r->enodes, r->ne, &r->etag));
  }
  PetscCallMPI(MPI_Bcast(r->ids, (PetscMPIInt)r->nn, MPIU_INT, 0, b->comm));
  PetscCallMPI(MPI_Bcast(r->X, (PetscMPIInt)(2 * r->nn), MPIU_REAL, 0, b->comm));
  PetscCallMPI(MPI_Bcast(r->enodes, (PetscMPIInt)(3 * r->ne), MPIU_INT, 0, b->comm));
  PetscCallMPI(MPI_Bcast(r->etag, (PetscMPIInt)r->ne, MPIU_INT, 0, b->comm));
  if (r->centre[0] == PETSC_MAX_REAL) PetscCall(RigidCurvesCentroid(r));
  {
    PetscReal lo[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[2] = {PETSC_MIN_REAL, PETSC_MIN_REAL};
    for (PetscInt i = 0; i < r->nn; ++i)
      for (PetscInt d = 0; d < 2; ++d) {
        lo[d] = PetscMin(lo[d], r->X[2 * i + d]);
        hi[d] = PetscMax(hi[d], r->X[2 * i + d]);
      }
    r->L = PetscSqrtReal(PetscSqr(hi[0] - lo[0]) + PetscSqr(hi[1] - lo[1]));
  }
  PetscFunctionReturn(0);
}

/* -rigid_moment: per stage the moment on the rotation's components
   (2D: one, 3D: three), once the body's size L is known. A component that
   carries a moment in some stage is moment-controlled: an unknown of force
   M / L (its unknown is the arc L theta, so that the potential -F U is
   -M theta); it must be free, a held or prescribed rotation having no
   moment to balance. A component whose moment is 0 at every stage stays
   free (held by the contact alone, as without the option). */
static PetscErrorCode RigidParseMoment(Body b, BodyRigid *r)
{
  const PetscInt nc = r->dim == 3 ? 3 : 1, S = b->nstages;
  const char    *axis[3] = {"x", "y", "z"};
  char           opt[2 * CONTACT_NAME_LEN];

  PetscFunctionBeginUser;
  if (!r->setMom) PetscFunctionReturn(0);
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%srigid_moment", r->prefix));
  PetscCheck(r->nmom <= 3 * CONTACT_MAX_STAGES, b->comm, PETSC_ERR_USER_INPUT, "option %s: more than %d values", opt, 3 * CONTACT_MAX_STAGES);
  PetscCall(BodyStagedValues(b, opt, r->nmom, nc, r->momOpt, 3, &r->momEnd[0][0]));
  for (PetscInt c = 0; c < nc; ++c) {
    const PetscInt q = r->dim + c;
    PetscBool      given = PETSC_FALSE;
    for (PetscInt s = 0; s < S; ++s) given = (PetscBool)(given || r->momEnd[s][c] != 0.0);
    if (!given) continue;
    PetscCheck(!b->axisym, b->comm, PETSC_ERR_USER_INPUT, "option %s: a rigid body in r-z moves along the axis only, and a moment has nothing to turn", opt);
    PetscCheck(r->unknown[q], b->comm, PETSC_ERR_USER_INPUT, "option %s: body %s's rotation%s%s is held or prescribed, so a moment on it has nothing to turn; make it free (-%srigid_rotation%s)", opt, b->name, nc == 3 ? " about " : "", nc == 3 ? axis[c] : "", r->prefix, nc == 3 ? ", that component free" : " free");
    r->control[q] = PETSC_TRUE;
    r->qforce[q]  = r->momEnd[S - 1][c] / r->L;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BodyRigidSetUp(Body b)
{
  BodyRigid *r = b->rg;
  PetscBool  is3;

  PetscFunctionBeginUser;
  PetscCall(Rigid3dIs(b, &is3));
  r->dim = is3 ? 3 : 2;
  r->nq  = is3 ? 6 : 3;
  if (is3) PetscCall(Rigid3dParseRotation(b, r));
  else PetscCall(RigidParseMotion2D(b, r));
  PetscCall(RigidSetCentre(b, r));
  if (is3) PetscCall(Rigid3dSetUpSurfaces(b, r));
  else PetscCall(RigidSetUpCurves(b, r));
  PetscCall(RigidConditions(b, r));
  PetscCall(RigidParseMoment(b, r));
  b->dim     = r->dim;
  b->nlocal  = 0;
  b->nglobal = 0;
  PetscCall(VecCreateMPI(b->comm, 0, 0, &b->Xg));
  PetscCall(VecDuplicate(b->Xg, &b->Gg));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 0, &b->Xl));
  PetscCall(VecDuplicate(b->Xl, &b->Gl));
  if (is3) PetscCall(PetscInfo(NULL, "body %s is rigid (3D): %" PetscInt_FMT " nodes, %" PetscInt_FMT " faces, reference point (%g, %g, %g)\n", b->name, r->nn, r->nf, (double)r->centre[0], (double)r->centre[1], (double)r->centre[2]));
  else PetscCall(PetscInfo(NULL, "body %s is rigid: %" PetscInt_FMT " nodes, %" PetscInt_FMT " lines, reference point (%g, %g)\n", b->name, r->nn, r->ne, (double)r->centre[0], (double)r->centre[1]));
  PetscFunctionReturn(0);
}

static PetscErrorCode BodySetLoad_Rigid(Body b)
{
  BodyRigid      *r = b->rg;
  const PetscInt  k = b->stage;
  const PetscReal w0 = b->loadWeight[0], w1 = b->loadWeight[1];

  PetscFunctionBeginUser;
  for (PetscInt c = 0; c < r->dim; ++c)
    if (!r->unknown[c]) r->t[c] = (k > 1 ? w0 * r->tEnd[k - 2][c] : 0.0) + w1 * r->tEnd[k - 1][c];
  if (r->dim == 3) { /* the rotation vector along the stage: exact at its ends */
    for (PetscInt c = 0; c < 3; ++c)
      if (!r->unknown[3 + c]) r->rot[c] = (k > 1 ? w0 * r->rotEnd[k - 2][c] : 0.0) + w1 * r->rotEnd[k - 1][c];
    PetscFunctionReturn(0);
  }
  if (!r->unknown[2]) r->theta = (k > 1 ? w0 * r->rotation[k - 2] : 0.0) + w1 * r->rotation[k - 1];
  PetscFunctionReturn(0);
}

void BodyRigidSetUnknown(Body b, PetscInt q, PetscReal v)
{
  if (b->rg->dim == 3) {
    if (q < 3) b->rg->t[q] = v;
    else b->rg->rot[q - 3] = v / b->rg->L;
    return;
  }
  if (q < 2) b->rg->t[q] = v;
  else b->rg->theta = v / b->rg->L;
}

PetscReal BodyRigidGetUnknown(const Body b, PetscInt q)
{
  if (b->rg->dim == 3) return q < 3 ? b->rg->t[q] : b->rg->rot[q - 3] * b->rg->L;
  return q < 2 ? b->rg->t[q] : b->rg->theta * b->rg->L;
}

PetscReal BodyRigidUnknownGradient(const Body b, PetscInt q)
{
  if (b->rg->dim == 3) return q < 3 ? b->rg->force[q] : b->rg->grot[q - 3] / b->rg->L;
  return q < 2 ? b->rg->force[q] : b->rg->moment / b->rg->L;
}

void BodyRigidContactForce(const Body b, PetscReal f[2], PetscReal *moment)
{
  f[0]    = -b->rg->force[0];
  f[1]    = -b->rg->force[1];
  *moment = -b->rg->moment;
}

void BodyRigidJacobian(const Body b, const PetscReal x[2], PetscReal J[3][2])
{
  const BodyRigid *r = b->rg;

  J[0][0] = J[1][1] = 1.0;
  J[0][1] = J[1][0] = 0.0;
  J[2][0]           = -(x[1] - r->centre[1] - r->t[1]) / r->L;
  J[2][1]           = (x[0] - r->centre[0] - r->t[0]) / r->L;
}

PetscErrorCode BodyRigidAddHessian(Body b, const PetscReal x[], PetscInt n, const PetscInt idx[], const PetscScalar K[])
{
  BodyRigid *r = b->rg;
  PetscInt   pos[1024], nr = 0;
  PetscReal  Jr[1024][3];

  PetscFunctionBeginUser;
  if (r->dim == 3) {
    PetscCall(Rigid3dAddHessian(b, x, n, idx, K));
    PetscFunctionReturn(0);
  }
  for (PetscInt a = 0; a < n; ++a) {
    PetscInt  j, d;
    PetscReal J[3][2];
    if (!ContactRigidDofDecode(idx[a], &j, &d)) continue;
    PetscCheck(nr < 1024, PETSC_COMM_SELF, PETSC_ERR_PLIB, "rigid body %s: a Hessian block with more than 1024 of its dofs", b->name);
    BodyRigidJacobian(b, &x[2 * j], J);
    for (PetscInt q = 0; q < 3; ++q) Jr[nr][q] = J[q][d];
    pos[nr++] = a;
  }
  if (!nr) PetscFunctionReturn(0);
  for (PetscInt q = 0; q < 3; ++q) {
    if (!r->unknown[q] || !r->B[q]) continue;
    for (PetscInt e = 0; e < n; ++e) { /* K symmetric: row e's coupling to the body's dofs */
      PetscScalar v = 0;
      if (idx[e] < 0) continue;
      for (PetscInt k = 0; k < nr; ++k) v += K[e * n + pos[k]] * Jr[k][q];
      if (v != 0.0) PetscCall(VecSetValue(r->B[q], idx[e], v, ADD_VALUES));
    }
    for (PetscInt q2 = 0; q2 < 3; ++q2)
      for (PetscInt k = 0; k < nr && r->unknown[q2]; ++k)
        for (PetscInt l = 0; l < nr; ++l) r->D[3 * q + q2] += Jr[k][q] * PetscRealPart(K[pos[k] * n + pos[l]]) * Jr[l][q2];
  }
  PetscFunctionReturn(0);
}

void BodyRigidDisplacement(const Body b, const PetscReal X[2], PetscReal u[2])
{
  const BodyRigid *r = b->rg;
  const PetscReal  dx = X[0] - r->centre[0], dy = X[1] - r->centre[1];
  const PetscReal  c = PetscCosReal(r->theta), s = PetscSinReal(r->theta);

  u[0] = r->t[0] + (c - 1.0) * dx - s * dy;
  u[1] = r->t[1] + s * dx + (c - 1.0) * dy;
}

void BodyRigidZeroForce(Body b)
{
  b->rg->force[0] = b->rg->force[1] = b->rg->moment = b->rg->curl = 0.0;
  b->rg->force[2] = 0.0;
  PetscArrayzero(b->rg->mom, 3);
  PetscArrayzero(b->rg->grot, 3);
  PetscArrayzero(b->rg->curl3, 9);
}

void BodyRigidAddForce(Body b, PetscInt n, const PetscReal X[], const PetscReal g[])
{
  BodyRigid *r = b->rg;

  if (r->dim == 3) {
    Rigid3dAddForce(r, n, X, g);
    return;
  }
  for (PetscInt i = 0; i < n; ++i) {
    PetscReal u[2], d[2];
    BodyRigidDisplacement(b, &X[2 * i], u);
    d[0] = X[2 * i] + u[0] - r->centre[0] - r->t[0];
    d[1] = X[2 * i + 1] + u[1] - r->centre[1] - r->t[1];
    r->force[1] += g[2 * i + 1];
    if (b->axisym) continue; /* r-z: the radial parts cancel round the ring, and the body turns about no axis */
    r->force[0] += g[2 * i];
    r->moment += d[0] * g[2 * i + 1] - d[1] * g[2 * i];
    r->curl -= d[0] * g[2 * i] + d[1] * g[2 * i + 1];
  }
}

/* Each condition's reaction: the force's components it holds (a component
   held by several groups: the first carries it). */
PetscErrorCode BodyRigidComputeReactions(Body b)
{
  PetscBool given[3] = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE};

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < b->nbc; ++i) {
    BodyBC *bc = &b->bc[i];
    bc->reaction[0] = bc->reaction[1] = bc->reaction[2] = 0.0;
    for (PetscInt k = 0; k < bc->ncomp; ++k) {
      const PetscInt c = bc->comps[k];
      if (given[c]) continue;
      bc->reaction[c] = b->rg->force[c];
      given[c]        = PETSC_TRUE;
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BodyRigidGroupEdges(Body b, PetscInt tag, PetscInt *n, PetscInt **edges)
{
  const BodyRigid *r = b->rg;
  PetscInt         k = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(r->ne + 1, edges));
  for (PetscInt e = 0; e < r->ne; ++e)
    if (r->etag[e] == tag) (*edges)[k++] = e;
  *n = k;
  PetscFunctionReturn(0);
}

PetscBool BodyRigidClosed(const Body b)
{
  const BodyRigid *r = b->rg;
  PetscInt        *deg;
  PetscBool        closed = PETSC_TRUE;

  if (PetscCalloc1(r->nn, &deg)) return PETSC_FALSE;
  for (PetscInt e = 0; e < r->ne; ++e) {
    deg[r->enodes[3 * e]]++;
    deg[r->enodes[3 * e + 1]]++;
  }
  for (PetscInt v = 0; v < r->nn; ++v) closed = (PetscBool)(closed && (deg[v] == 0 || deg[v] == 2));
  (void)PetscFree(deg);
  return closed;
}

/* Even-odd rule over the lines as polylines (corner, middle, corner): a
   ray from p along +x crosses the boundary an odd number of times. */
PetscBool BodyRigidInside(const Body b, const PetscReal p[2])
{
  const BodyRigid *r = b->rg;
  PetscInt         cross = 0;

  for (PetscInt e = 0; e < r->ne; ++e) {
    const PetscInt order[3] = {r->enodes[3 * e], r->enodes[3 * e + 2], r->enodes[3 * e + 1]};
    for (PetscInt k = 0; k < 2; ++k) {
      const PetscReal *a = &r->X[2 * order[k]], *c = &r->X[2 * order[k + 1]];
      if ((a[1] > p[1]) != (c[1] > p[1])) {
        const PetscReal x = a[0] + (p[1] - a[1]) * (c[0] - a[0]) / (c[1] - a[1]);
        if (x > p[0]) cross++;
      }
    }
  }
  return (PetscBool)(cross % 2);
}

PetscErrorCode BodyRigidDestroy(Body b)
{
  PetscFunctionBeginUser;
  if (!b->rg) PetscFunctionReturn(0);
  PetscCall(PetscFree2(b->rg->ids, b->rg->X));
  PetscCall(PetscFree2(b->rg->enodes, b->rg->etag));
  PetscCall(PetscFree2(b->rg->fnodes, b->rg->ftag));
  PetscCall(PetscFree(b->rg));
  PetscFunctionReturn(0);
}

/* Its curves and motion alone: no cells, no dofs. */
static PetscErrorCode BodySetUp_Rigid(Body b, PetscInt partitioner, PetscBool partitionView)
{
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  (void)partitioner;
  (void)partitionView;
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogStagePush(contactLog.mesh));
  PetscCall(BodyRigidSetUp(b));
  b->stage = 0;
  PetscCall(BodySetLoad(b, (PetscReal)b->nstages)); /* the last stage's end, until the solve sets another */
  PetscCall(PetscLogStagePop());
  PetscCall(PetscTime(&t1));
  b->tmesh += t1 - t0;
  PetscFunctionReturn(0);
}

/* No elastic energy; the contact terms add its force. */
static PetscErrorCode BodyComputeEnergyGradient_Rigid(Body b, Vec Xl, PetscReal *energy, Vec Gl)
{
  PetscFunctionBeginUser;
  (void)Xl;
  (void)Gl;
  BodyRigidZeroForce(b);
  *energy = 0.0;
  PetscFunctionReturn(0);
}

static PetscErrorCode BodyComputeReactions_Rigid(Body b, Vec Gl)
{
  PetscFunctionBeginUser;
  (void)Gl;
  PetscCall(BodyRigidComputeReactions(b));
  PetscFunctionReturn(0);
}

/* Its unknowns are held by its contacts, or by nothing. */
static PetscErrorCode BodyCheckHeld_Rigid(Body b, PetscBool contact)
{
  const BodyRigid *r = b->rg;

  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < r->nq && !contact && r->dim == 3; ++q)
    PetscCheck(!r->unknown[q], b->comm, PETSC_ERR_USER_INPUT, "body %s is rigid and in no contact pair, and its %s is %s, so the problem is singular; hold it with -%s_bc or -%s_rigid_rotation", b->name, BodyGetControlComponent_Rigid(b, -1, q), r->control[q] ? (q >= 3 ? "moment-controlled" : "force-controlled") : "free", b->name, b->name);
  for (PetscInt q = 0; q < 3 && !contact; ++q)
    PetscCheck(!r->unknown[q], b->comm, PETSC_ERR_USER_INPUT, "body %s is rigid and in no contact pair, and %s, so the problem is singular; hold it with -%s_bc%s", b->name,
               q == 2 ? "its rotation is free" : (r->control[q] ? (q ? "a force controls its translation in y" : "a force controls its translation in x") : (q ? "no condition holds its translation in y" : "no condition holds its translation in x")), b->name, q == 2 ? " and -<body>_rigid_rotation" : "");
  PetscFunctionReturn(0);
}

/* Its motion and the contact's force on it. */
static PetscErrorCode BodyViewSolution_Rigid(Body b, PetscBool axisymmetric)
{
  const BodyRigid *r = b->rg;
  PetscReal        f[2], mo;

  PetscFunctionBeginUser;
  if (r->dim == 3) {
    PetscCall(Rigid3dViewSolution(b));
    PetscFunctionReturn(0);
  }
  BodyRigidContactForce(b, f, &mo);
  if (axisymmetric) PetscCall(PetscPrintf(b->comm, "  rigid body %s: moved %g along the axis; the contact's force on it %.6e along the axis\n", b->name, (double)r->t[1], (double)f[1]));
  else PetscCall(PetscPrintf(b->comm, "  rigid body %s: moved (%g, %g), turned %g about (%g, %g); the contact's force on it (%.6e, %.6e), moment %.6e\n", b->name, (double)r->t[0], (double)r->t[1], (double)r->theta, (double)r->centre[0], (double)r->centre[1], (double)f[0], (double)f[1], (double)mo));
  PetscFunctionReturn(0);
}

/* Its unknowns (rigidbody.h): a force-controlled component with its
   condition's force, the others (held by the contact alone) anchors of
   force 0. */
static PetscErrorCode BodyGetControls_Rigid(Body b, PetscInt *n, BodyControl ctl[])
{
  const BodyRigid *r = b->rg;

  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < r->nq; ++q) {
    BodyControl *k;
    if (!r->unknown[q]) continue;
    k         = &ctl[(*n)++];
    k->bc     = r->qbc[q];
    k->c      = q;
    k->force  = r->qforce[q];
    k->anchor = (PetscBool)!r->control[q];
    k->scale  = k->force != 0.0 ? PetscAbsReal(k->force) : 1.0;
    k->L      = r->L;
    k->kref   = b->axisym ? r->L : 1.0;
    k->motion = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

/* The motion itself, whatever the load factor. */
static PetscErrorCode BodySetControlValue_Rigid(Body b, PetscInt bc, PetscInt q, PetscReal U)
{
  PetscFunctionBeginUser;
  (void)bc;
  BodyRigidSetUnknown(b, q, U);
  PetscFunctionReturn(0);
}

static PetscReal BodyGetControlForce_Rigid(Body b, PetscInt bc, PetscInt q)
{
  (void)bc;
  return BodyRigidControlForce(b, q);
}

/* dPi/dq: the contact's force, or its moment over L. */
static PetscReal BodyGetControlReaction_Rigid(Body b, PetscInt bc, PetscInt q)
{
  (void)bc;
  return BodyRigidUnknownGradient(b, q);
}

static const char *BodyGetControlComponent_Rigid(Body b, PetscInt bc, PetscInt q)
{
  const char *name3[6] = {"x", "y", "z", "rotation_x", "rotation_y", "rotation_z"};

  (void)bc;
  if (b->rg->dim == 3) return name3[q];
  return q == 2 ? "rotation" : (q ? "y" : "x");
}

void BodyRigidBorderBegin(Body b, PetscInt q, Vec B)
{
  b->rg->B[q] = B;
  PetscArrayzero(b->rg->D, b->rg->nq * b->rg->nq);
}

PetscErrorCode BodyRigidBorderSum(Body b)
{
  PetscFunctionBeginUser;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, b->rg->D, b->rg->nq * b->rg->nq, MPIU_REAL, MPIU_SUM, b->comm));
  PetscFunctionReturn(0);
}

void BodyRigidBorderEnd(Body b, PetscInt q)
{
  b->rg->B[q] = NULL;
}

PetscReal BodyRigidBorderCoupling(Body b, PetscInt q, PetscInt s)
{
  const BodyRigid *r = b->rg;

  if (r->dim == 3) return r->D[6 * q + s] + (q >= 3 && s >= 3 ? r->curl3[3 * (q - 3) + s - 3] / PetscSqr(r->L) : 0.0);
  return r->D[3 * q + s] + (q == 2 && s == 2 ? r->curl / PetscSqr(r->L) : 0.0);
}

PetscBool BodyRigidIsRotation(Body b, PetscInt q)
{
  return (PetscBool)(q >= b->rg->dim);
}

PetscReal BodyRigidGetLength(Body b)
{
  return b->rg->L;
}

void BodyRigidSetOps(Body b)
{
  BodyOps *ops = &b->ops;

  PetscMemzero(ops, sizeof(*ops));
  ops->setup             = BodySetUp_Rigid;
  ops->energygradient    = BodyComputeEnergyGradient_Rigid;
  ops->reactions         = BodyComputeReactions_Rigid;
  ops->checkheld         = BodyCheckHeld_Rigid;
  ops->viewsolution      = BodyViewSolution_Rigid;
  ops->groupedges        = BodyRigidGroupEdgesAsSurface;
  ops->boundaryedgesat   = BodyRigidBoundaryEdgesAt;
  ops->mapnodes          = BodyRigidMapNodes;
  ops->nodedisplacements = BodyRigidNodeDisplacements;
  ops->addnodeforces     = BodyRigidAddNodeForces;
  ops->addsurfacehessian = BodyRigidAddHessian;
  ops->getcontrols       = BodyGetControls_Rigid;
  ops->setcontrol        = BodySetControlValue_Rigid;
  ops->controlforce      = BodyGetControlForce_Rigid;
  ops->controlreaction   = BodyGetControlReaction_Rigid;
  ops->controlcomponent  = BodyGetControlComponent_Rigid;
  ops->setload           = BodySetLoad_Rigid;
  ops->destroy           = BodyRigidDestroy;
}
