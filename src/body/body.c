/* An elastic body: options, mesh (Gmsh -> DMPlex), P2/Q2 displacement with
   Dirichlet constraints, the per-cell geometry cache, and the body's energy,
   gradient, stiffness and errors, summed over its cells by element.c's loop
   over the pointwise kernels of its material (material.h: elasticity.c,
   neohookean.c). It orchestrates the body's
   files: it alone calls conditions.c, axis.c, anchors.c and loads.c, which
   take what they share from bodycore.c and rigid.c, below them all. Each
   function that differs for a rigid body calls through the body's table of
   operations (bodyimpl.h): this file's _Elastic implementations fill it in
   BodyCreate, rigidbody.c's in BodySetFromOptions where -<body>_rigid. */
#include "support.h"
#include "body.h"
#include "simplexcoords.h"
#include "anchors.h"
#include "axis.h"
#include "meshgen.h"
#include "mshcheck.h"
#include "partition.h"
#include "options.h"
#include "element.h"
#include "bodyimpl.h"

PetscErrorCode BodyCreate(MPI_Comm comm, const char name[], Body *body)
{
  Body b;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&b));
  b->comm = comm;
  PetscCall(PetscStrncpy(b->name, name, sizeof(b->name)));
  b->h  = 0.1;
  b->E  = 1.0;
  b->nu = 0.0;
  b->loadFactor = 1.0;
  b->nstages    = 1;
  b->loadWeight[1] = 1.0;
  BodyElasticSetOps(b);
  *body = b;
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckFinite(MPI_Comm comm, const char opt[], PetscReal v)
{
  PetscFunctionBeginUser;
  PetscCheck(!PetscIsInfOrNanReal(v), comm, PETSC_ERR_USER_INPUT, "option %s: value %g is not a finite number", opt, (double)v);
  PetscFunctionReturn(0);
}

PetscErrorCode BodySetFromOptions(Body b, PetscReal meshSizeOverride)
{
  char      prefix[2 * CONTACT_NAME_LEN], opt[4 * CONTACT_NAME_LEN], exact[64] = "none", material[64] = "linear";
  char     *bcnames[CONTACT_MAX_BC];
  PetscInt  nbc = CONTACT_MAX_BC, ngp = 16;
  PetscBool hasGeo = PETSC_FALSE, hasMsh = PETSC_FALSE, help;
  PetscInt  qdeg = 4;

  PetscFunctionBeginUser;
  /* -help lists the options and stops: nothing is required, nothing meshed */
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%s_", b->name));
  PetscOptionsBegin(b->comm, prefix, "Body options", NULL);
  PetscCall(ContactOptionsString(PetscOptionsObject, "-geo", "Gmsh .geo file of the body (this or -<body>_mesh is required)", NULL, b->geo, b->geo, sizeof(b->geo), &hasGeo));
  PetscCall(ContactOptionsString(PetscOptionsObject, "-mesh", "Ready-made second-order Gmsh .msh file (instead of -geo)", NULL, b->msh, b->msh, sizeof(b->msh), &hasMsh));
  PetscCall(PetscOptionsReal("-mesh_size", "Gmsh mesh size h (overridden by -mesh_size)", NULL, b->h, &b->h, NULL));
  PetscCall(ContactOptionsStringArray(PetscOptionsObject, "-geo_params", "Geometry parameters name=value passed to Gmsh -setnumber", NULL, b->geoparams, &ngp, NULL));
  PetscCall(PetscOptionsBool("-rigid", "A rigid body: its mesh gives only its curves (3D: its surfaces, where the mesh has a Physical Volume), its motion is rigid (-<body>_rigid_centre, _rigid_rotation); E and nu are not asked for", NULL, b->rigid, &b->rigid, NULL));
  PetscCall(ContactOptionsFList(PetscOptionsObject, "-material", "Material: linear (small strain, -E, -nu), neohookean (compressible neo-Hookean, finite strain, -E, -nu), mooneyrivlin (compressible Mooney-Rivlin, -C10, -C01, -D1) or plastic (small-strain J2 plasticity, linear isotropic hardening, -E, -nu, -yield, -hardening)", NULL, MaterialList, material, material, sizeof(material), NULL));
  PetscCall(ContactOptionsStringArray(PetscOptionsObject, "-bc", "Dirichlet physical groups (see -<body>_bc_<group>_components, _values)", NULL, bcnames, &nbc, NULL));
  PetscCall(ContactOptionsString(PetscOptionsObject, "-exact", "Exact solution for verification: none, affine, trig (plane strain or 3D), lame (-axisymmetric), sphere (3D)", NULL, exact, exact, sizeof(exact), NULL));
  b->exact.nparams = 16;
  PetscCall(PetscOptionsRealArray("-exact_params", "Parameters of the exact solution", NULL, b->exact.params, &b->exact.nparams, NULL));
  PetscCall(PetscOptionsInt("-quadrature_degree", "Degree of the cell quadrature (the stiffness exact on straight Tri6 cells from 2, on rectangular Quad9 cells from 4: (degree + 2)/2 Gauss points a direction)", NULL, qdeg, &qdeg, NULL));
  PetscOptionsEnd();
  b->ngeoparams = ngp;
  b->qdeg       = qdeg;
  if (help && !nbc) { /* the options of a Dirichlet condition, under a placeholder group */
    PetscCall(PetscStrallocpy("<group>", &bcnames[0]));
    nbc = 1;
  }
  PetscCheck(help || hasGeo || hasMsh, b->comm, PETSC_ERR_USER_INPUT, "body %s: give -%sgeo FILE.geo or -%smesh FILE.msh", b->name, prefix, prefix);
  if (b->rigid) BodyRigidSetOps(b);
  if (b->rigid || help) PetscCall(BodyRigidSetFromOptions(b, prefix));
  if (b->rigid && !help) { /* E and nu are not asked for; a rigid body has no cells to load */
    PetscBool setE, setNu;
    PetscCall(PetscOptionsHasName(NULL, prefix, "-E", &setE));
    PetscCall(PetscOptionsHasName(NULL, prefix, "-nu", &setNu));
    PetscCheck(!setE && !setNu, b->comm, PETSC_ERR_USER_INPUT, "option -%s%s: body %s is rigid (-%srigid): it has no elastic constants", prefix, setE ? "E" : "nu", b->name, prefix);
    b->E  = PETSC_INFINITY;
    b->nu = 0.0;
  }
  /* relative to the options file that names them */
  if (hasMsh && !help) PetscCall(ContactOptionsGetInputFile(b->comm, prefix, "-mesh", b->msh, sizeof(b->msh)));
  else if (hasGeo && !help) PetscCall(ContactOptionsGetInputFile(b->comm, prefix, "-geo", b->geo, sizeof(b->geo)));
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%smesh_size", prefix));
  PetscCall(CheckFinite(b->comm, opt, b->h)); /* checked even where -mesh_size overrides it */
  PetscCheck(b->h > 0, b->comm, PETSC_ERR_USER_INPUT, "option %s: mesh size must be > 0, got %g", opt, (double)b->h);
  if (meshSizeOverride > 0) b->h = meshSizeOverride;
  PetscCheck(qdeg >= 2 && qdeg <= 12, b->comm, PETSC_ERR_USER_INPUT, "option -%squadrature_degree: must be in [2, 12], got %" PetscInt_FMT, prefix, qdeg);
  PetscCall(MaterialFind(material, &b->mat));
  if (!b->mat) {
    char known[256];
    PetscCall(ContactOptionsListNames(MaterialList, known, sizeof(known)));
    SETERRQ(b->comm, PETSC_ERR_USER_INPUT, "option -%smaterial: unknown material '%s' (known: %s)", prefix, material, known);
  }
  PetscCheck(!b->rigid || b->mat->constantTangent, b->comm, PETSC_ERR_USER_INPUT, "option -%smaterial: body %s is rigid (-%srigid): it has no material", prefix, b->name, prefix);
  if (help) { /* every material's options, each reader once */
    char names[256], *s = names, *t;
    PetscErrorCode (*seen[8])(MPI_Comm, const char[], PetscBool, PetscReal[], PetscReal *, PetscReal *);
    PetscInt nseen = 0;
    PetscCall(ContactOptionsListNames(MaterialList, names, sizeof(names)));
    for (; s && *s; s = t) {
      const Material *m;
      PetscBool       dup = PETSC_FALSE;
      t = strchr(s, ',');
      if (t) *t++ = 0;
      while (*s == ' ') ++s;
      PetscCall(MaterialFind(s, &m));
      for (PetscInt k = 0; m && k < nseen; ++k) dup = (PetscBool)(dup || seen[k] == m->setFromOptions);
      if (!m || dup || nseen >= 8) continue;
      seen[nseen++] = m->setFromOptions;
      PetscCall(m->setFromOptions(b->comm, prefix, PETSC_TRUE, b->param, &b->E, &b->nu));
    }
  } else if (!b->rigid) PetscCall(b->mat->setFromOptions(b->comm, prefix, PETSC_FALSE, b->param, &b->E, &b->nu));
  for (PetscInt k = 0; k < b->exact.nparams; ++k) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sexact_params", prefix));
    PetscCall(CheckFinite(b->comm, opt, b->exact.params[k]));
  }
  if (strcmp(exact, "none")) {
    PetscErrorCode (*set)(ExactSolution *) = NULL;
    PetscCall(PetscFunctionListFind(ExactSolutionList, exact, &set));
    PetscCheck(set, b->comm, PETSC_ERR_USER_INPUT, "option -%sexact: unknown exact solution '%s' (known: none, affine, trig, lame, sphere)", prefix, exact);
    PetscCall(ExactSolutionSetType(&b->exact, exact));
    PetscCheck(b->exact.axisymmetric == b->axisym, b->comm, PETSC_ERR_USER_INPUT, "option -%sexact: '%s' is a solution %s, and the scene is %s", prefix, exact, b->exact.axisymmetric ? "in r-z" : "in plane strain", b->axisym ? "axisymmetric (-axisymmetric)" : "in plane strain (give -axisymmetric for lame)");
    /* another material's body force comes from the solution's second derivatives (BodyExactForce) */
    PetscCheck(!b->mat->nstate, b->comm, PETSC_ERR_USER_INPUT, "option -%sexact: -%smaterial %s has history (its stress is not a function of the displacement gradient alone): no exact solution's body force holds for it", prefix, prefix, b->mat->name);
    PetscCheck(b->mat->constantTangent || b->exact.d2u, b->comm, PETSC_ERR_USER_INPUT, "option -%sexact: '%s' has linear elasticity's body force only; with -%smaterial %s, affine and trig are exact", prefix, exact, prefix, b->mat->name);
    b->hasExact      = PETSC_TRUE;
    b->exact.lambda  = b->E * b->nu / ((1.0 + b->nu) * (1.0 - 2.0 * b->nu)); /* linear elasticity's body force (a constant tangent's) */
    b->exact.mu      = b->E / (2.0 * (1.0 + b->nu));
  }
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sbc", prefix));
  PetscCall(BodyCheckGroupsUnique(b, opt, nbc, bcnames));
  b->nbc = nbc;
  for (PetscInt i = 0; i < nbc; ++i) {
    PetscCall(PetscStrncpy(b->bc[i].group, bcnames[i], sizeof(b->bc[i].group)));
    PetscCall(PetscFree(bcnames[i]));
    PetscCall(BodyBCSetFromOptions(b, prefix, &b->bc[i]));
  }
  for (PetscInt i = 0; i < nbc; ++i) /* force control's border is K e_k, a constant stiffness (forcecontrol.c) */
    PetscCheck(b->mat->constantTangent || (!b->bc[i].control[0] && !b->bc[i].control[1]), b->comm, PETSC_ERR_USER_INPUT, "option -%sbc_%s_control: force control needs a constant stiffness, and -%smaterial %s has none: control the displacement", prefix, b->bc[i].group, prefix, b->mat->name);
  PetscCall(BodyLoadsSetFromOptions(b, prefix, help));
  PetscCheck(help || !b->rigid || !b->nload, b->comm, PETSC_ERR_USER_INPUT, "option -%sload: body %s is rigid, and a load on a rigid body is not supported yet", prefix, b->name);
  PetscCheck(!b->rigid || !b->hasExact, b->comm, PETSC_ERR_USER_INPUT, "option -%sexact: body %s is rigid: it has no exact solution", prefix, b->name);
  b->generate = (PetscBool)(hasGeo && !hasMsh && !help);
  PetscFunctionReturn(0);
}

PetscErrorCode BodySetSizeField(Body b, const char path[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(b->bgm, path ? path : "", sizeof(b->bgm)));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGenerateMesh(Body b, const char meshDir[], PetscReal *maxDofs, const char limit[], PetscBool estimateOnly)
{
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  if (!b->generate) PetscFunctionReturn(0);
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogStagePush(contactLog.mesh));
  PetscCall(MeshGenerate(b->comm, b->name, b->geo, b->h, b->ngeoparams, b->geoparams, b->bgm, meshDir, maxDofs, limit, estimateOnly, b->msh, sizeof(b->msh)));
  PetscCall(PetscLogStagePop());
  PetscCall(PetscTime(&t1));
  b->tmesh += t1 - t0;
  PetscFunctionReturn(0);
}

/* Reads the mesh, checks it is second order and of one cell type. */
static PetscErrorCode BodyReadMesh(Body b, PetscInt partitioner, PetscBool view)
{
  PetscInt cStart, cEnd, nTypes[2] = {0, 0}, gTypes[2];
  DMPolytopeType want[2];
  char     prefix[2 * CONTACT_NAME_LEN];

  PetscFunctionBeginUser;
  /* first read of the file: an unreadable mesh stops here, on every rank */
  PetscCall(MeshCheckFile(b->comm, b->name, b->msh));
  PetscCall(MeshReadPhysicalNames(b->comm, b->msh, &b->nphys, &b->physNames, &b->physDims, &b->physTags));
  PetscCall(DMPlexCreateFromFile(b->comm, b->msh, b->name, PETSC_TRUE, &b->dm));
  PetscCall(PetscObjectSetName((PetscObject)b->dm, b->name));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%s_", b->name));
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)b->dm, prefix));
  PetscCall(DMGetDimension(b->dm, &b->dim));
  PetscCheck(b->dim == 2 || b->dim == 3, b->comm, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s is %" PetscInt_FMT "D; a body is 2D or 3D", b->name, b->msh, b->dim);
  PetscCheck(b->dim == 2 || !b->axisym, b->comm, PETSC_ERR_USER_INPUT, "body %s: mesh %s is 3D, and -axisymmetric takes 2D bodies (their meridian sections)", b->name, b->msh);
  want[0] = b->dim == 3 ? DM_POLYTOPE_TETRAHEDRON : DM_POLYTOPE_TRIANGLE;
  want[1] = b->dim == 3 ? DM_POLYTOPE_HEXAHEDRON : DM_POLYTOPE_QUADRILATERAL;
  PetscCall(DMPlexGetHeightStratum(b->dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(b->dm, c, &ct));
    if (ct == want[0]) nTypes[0]++;
    else if (ct == want[1]) nTypes[1]++;
    else SETERRQ(b->comm, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s has a cell of type %s", b->name, b->msh, DMPolytopeTypes[ct]);
  }
  PetscCall(MPIU_Allreduce(nTypes, gTypes, 2, MPIU_INT, MPI_SUM, b->comm));
  PetscCheck(gTypes[0] + gTypes[1] > 0, b->comm, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s has no cells", b->name, b->msh);
  PetscCheck(!gTypes[0] || !gTypes[1], b->comm, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s mixes %s", b->name, b->msh, b->dim == 3 ? "tetrahedra and hexahedra" : "triangles and quadrilaterals");
  b->simplex      = gTypes[0] ? PETSC_TRUE : PETSC_FALSE;
  b->ncellsGlobal = gTypes[0] + gTypes[1];
  if (b->dim == 3 && b->simplex) PetscCall(MeshSimplexCoordinatesInCellOrder(b->dm, b->name, b->msh));
  PetscCall(DMPlexDistributeWith(&b->dm, (PartitionType)partitioner, view, b->name));
  PetscCall(DMViewFromOptions(b->dm, NULL, "-dm_view"));
  PetscFunctionReturn(0);
}

/* At one reference point of an element with nb nodes at x, given the reference
   basis gradients D[a][2]: returns det J and the physical gradients dNdx[a][2]. */
PetscReal BodyElementGradients(PetscInt nb, const PetscReal x[][2], const PetscReal D[], PetscReal dNdx[])
{
  PetscReal J[4] = {0, 0, 0, 0}, detJ, iJ[4];

  for (PetscInt a = 0; a < nb; ++a)
    for (PetscInt i = 0; i < 2; ++i)
      for (PetscInt j = 0; j < 2; ++j) J[i * 2 + j] += x[a][i] * D[a * 2 + j];
  detJ  = J[0] * J[3] - J[1] * J[2];
  iJ[0] = J[3] / detJ;
  iJ[1] = -J[1] / detJ;
  iJ[2] = -J[2] / detJ;
  iJ[3] = J[0] / detJ;
  for (PetscInt a = 0; a < nb; ++a) {
    dNdx[2 * a]     = D[a * 2] * iJ[0] + D[a * 2 + 1] * iJ[2];
    dNdx[2 * a + 1] = D[a * 2] * iJ[1] + D[a * 2 + 1] * iJ[3];
  }
  return detJ;
}

/* The same at one reference point in dimension dim (2 or 3): x[a][dim],
   D[a][dim], dNdx[a][dim]. In 2D the function above, bit for bit. */
PetscReal BodyElementGradientsDim(PetscInt dim, PetscInt nb, const PetscReal x[], const PetscReal D[], PetscReal dNdx[])
{
  PetscReal J[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, detJ, iJ[9];

  if (dim == 2) return BodyElementGradients(nb, (const PetscReal(*)[2])x, D, dNdx);
  for (PetscInt a = 0; a < nb; ++a)
    for (PetscInt i = 0; i < 3; ++i)
      for (PetscInt j = 0; j < 3; ++j) J[i * 3 + j] += x[a * 3 + i] * D[a * 3 + j];
  /* the inverse by cofactors: iJ = adj(J) / det J */
  iJ[0] = J[4] * J[8] - J[5] * J[7];
  iJ[1] = J[2] * J[7] - J[1] * J[8];
  iJ[2] = J[1] * J[5] - J[2] * J[4];
  iJ[3] = J[5] * J[6] - J[3] * J[8];
  iJ[4] = J[0] * J[8] - J[2] * J[6];
  iJ[5] = J[2] * J[3] - J[0] * J[5];
  iJ[6] = J[3] * J[7] - J[4] * J[6];
  iJ[7] = J[1] * J[6] - J[0] * J[7];
  iJ[8] = J[0] * J[4] - J[1] * J[3];
  detJ  = J[0] * iJ[0] + J[1] * iJ[3] + J[2] * iJ[6];
  for (PetscInt k = 0; k < 9; ++k) iJ[k] /= detJ;
  for (PetscInt a = 0; a < nb; ++a) /* dN_a/dx_j = dN_a/dxi_k (J^-1)_kj */
    for (PetscInt j = 0; j < 3; ++j) dNdx[3 * a + j] = D[a * 3] * iJ[j] + D[a * 3 + 1] * iJ[3 + j] + D[a * 3 + 2] * iJ[6 + j];
  return detJ;
}

/* Caches per cell the node points, their local dof offsets, the nodal coordinates, the physical
   basis gradients and the quadrature weights times det J. The node positions
   come from evaluating the mesh's own coordinate field (continuous Q2 on quads,
   cellwise P2 on triangles as PETSc's Gmsh reader stores them) at the reference
   nodes of the displacement element, so no node ordering is assumed. */
static PetscErrorCode BodyBuildCellCache(Body b)
{
  PetscSection       s;
  DM                 cdm;
  Vec                coords;
  PetscTabulation    T, Tc;
  PetscQuadrature    q;
  PetscInt           cStart, cEnd, nq, ncb, ncc;
  const PetscReal   *qw;
  PetscReal          ref[27 * 3];
  PetscObject        obj;
  const PetscInt     dim = b->dim;
  PetscFE            cfe;
  PetscReal          bad[6] = {0, 0, 0, 0, 0, 0}; /* first inverted cell here: flag, a node's x, y, det J, det J at its first point, z */
  PetscMPIInt        rank, size, first;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(b->dm, &s));
  PetscCall(DMGetCoordinateDM(b->dm, &cdm));
  PetscCall(BodyCheckSecondOrder(b));
  PetscCall(DMGetField(cdm, 0, NULL, &obj));
  cfe = (PetscFE)obj;
  PetscCall(PetscFEGetDimension(cfe, &ncb));
  PetscCall(DMGetCoordinatesLocal(b->dm, &coords));
  PetscCall(DMPlexGetHeightStratum(b->dm, 0, &cStart, &cEnd));
  PetscCall(PetscFEGetDimension(b->feScalar, &b->nb));
  PetscCall(PetscFEGetQuadrature(b->feScalar, &q));
  PetscCall(PetscQuadratureGetData(q, NULL, NULL, &nq, NULL, &qw));
  PetscCall(PetscFEGetCellTabulation(b->feScalar, 1, &T));
  PetscCall(BodyGetReferenceNodes(b, ref));
  PetscCall(PetscFECreateTabulation(cfe, 1, b->nb, ref, 0, &Tc));
  b->nq     = nq;
  b->ncells = cEnd - cStart;
  b->B      = T->T[0];
  PetscCall(PetscMalloc6(b->ncells * b->nb, &b->cpts, b->ncells * b->nb, &b->cdof, b->ncells * nq * b->nb * dim, &b->dNdx, b->ncells * nq, &b->wdetJ, b->ncells * nq * dim, &b->xq, b->ncells * b->nb * dim, &b->xnode));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscInt    *cl = NULL, ncl, k = 0, ci = c - cStart;
    PetscScalar *xc = NULL;
    PetscReal   *x = &b->xnode[ci * b->nb * dim], sign0 = 1.0, detJ0 = 0.0;

    PetscCall(DMPlexGetTransitiveClosure(b->dm, c, PETSC_TRUE, &ncl, &cl));
    for (PetscInt i = 0; i < ncl; ++i) {
      PetscInt p = cl[2 * i], dof, off;
      PetscCall(PetscSectionGetDof(s, p, &dof));
      if (!dof) continue;
      PetscCheck(k < b->nb, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell %" PetscInt_FMT " has more nodes than the element", c);
      PetscCall(PetscSectionGetOffset(s, p, &off));
      b->cpts[ci * b->nb + k]   = p;
      b->cdof[ci * b->nb + k++] = off;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(b->dm, c, PETSC_TRUE, &ncl, &cl));
    PetscCheck(k == b->nb, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell %" PetscInt_FMT ": %" PetscInt_FMT " nodes, element has %" PetscInt_FMT, c, k, b->nb);
    PetscCall(DMPlexVecGetClosure(cdm, NULL, coords, c, &ncc, &xc));
    PetscCheck(ncc == ncb, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "body %s: cell %" PetscInt_FMT " of %s has %" PetscInt_FMT " coordinate values, expected %" PetscInt_FMT, b->name, c, b->msh, ncc, ncb);
    for (PetscInt a = 0; a < b->nb; ++a) {
      for (PetscInt d = 0; d < dim; ++d) x[a * dim + d] = 0.0;
      for (PetscInt f = 0; f < ncb; ++f)
        for (PetscInt d = 0; d < dim; ++d) x[a * dim + d] += PetscRealPart(xc[f]) * Tc->T[0][(a * ncb + f) * dim + d];
    }
    PetscCall(DMPlexVecRestoreClosure(cdm, NULL, coords, c, &ncc, &xc));
    for (PetscInt iq = 0; iq < nq; ++iq) {
      const PetscReal detJ = BodyElementGradientsDim(dim, b->nb, x, &T->T[1][iq * b->nb * dim], &b->dNdx[(ci * nq + iq) * b->nb * dim]);
      PetscReal       xx[3] = {0, 0, 0};

      /* clockwise cells are fine; a sign change inside a cell is not */
      if (iq == 0) {
        sign0 = detJ > 0 ? 1.0 : -1.0;
        detJ0 = detJ;
      }
      if (!(detJ * sign0 > 0) && bad[0] == 0.0) {
        bad[0] = 1.0;
        bad[1] = x[(b->nb - 1) * dim];
        bad[2] = x[(b->nb - 1) * dim + 1];
        bad[5] = dim == 3 ? x[(b->nb - 1) * dim + 2] : 0.0;
        bad[3] = detJ;
        bad[4] = sign0 * PetscAbsReal(detJ0);
      }
      for (PetscInt a = 0; a < b->nb; ++a)
        for (PetscInt i = 0; i < dim; ++i) xx[i] += x[a * dim + i] * b->B[iq * b->nb + a];
      b->wdetJ[ci * nq + iq] = qw[iq] * PetscAbsReal(detJ) * BodyRadialWeight(b, xx[0]);
      for (PetscInt i = 0; i < dim; ++i) b->xq[(ci * nq + iq) * dim + i] = xx[i];
    }
  }
  PetscCall(PetscTabulationDestroy(&Tc));
  /* the check is collective, so that every rank stops with the same message */
  PetscCallMPI(MPI_Comm_rank(b->comm, &rank));
  PetscCallMPI(MPI_Comm_size(b->comm, &size));
  first = bad[0] != 0.0 ? rank : size;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, b->comm));
  if (first < size) PetscCallMPI(MPI_Bcast(bad, 6, MPIU_REAL, first, b->comm));
  if (dim == 3) PetscCheck(first == size, b->comm, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s has an inverted or degenerate cell near (%g, %g, %g): det J = %g at one quadrature point, %g at another", b->name, b->msh, (double)bad[1], (double)bad[2], (double)bad[5], (double)bad[4], (double)bad[3]);
  PetscCheck(first == size, b->comm, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s has an inverted or degenerate cell near (%g, %g): det J = %g at one quadrature point, %g at another", b->name, b->msh, (double)bad[1], (double)bad[2], (double)bad[4], (double)bad[3]);
  PetscFunctionReturn(0);
}

/* Per chart point: reference coordinates of its node, whether this rank owns it,
   and a global node numbering (one dof per node point, numbered over b->comm). */
static PetscErrorCode BodyBuildNodeData(Body b)
{
  PetscSection    s, ns;
  PetscSF         sf;
  PetscInt        nleaves;
  const PetscInt *leaves;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(b->dm, &s));
  PetscCall(PetscSectionGetChart(s, &b->pStart, &b->pEnd));
  PetscCall(PetscCalloc2(b->dim * (b->pEnd - b->pStart), &b->xpoint, b->pEnd - b->pStart, &b->owned));
  for (PetscInt k = 0; k < b->ncells * b->nb; ++k) {
    const PetscInt p = b->cpts[k] - b->pStart;
    for (PetscInt d = 0; d < b->dim; ++d) b->xpoint[b->dim * p + d] = b->xnode[b->dim * k + d];
  }
  for (PetscInt p = b->pStart; p < b->pEnd; ++p) b->owned[p - b->pStart] = PETSC_TRUE;
  PetscCall(DMGetPointSF(b->dm, &sf));
  PetscCall(PetscSFGetGraph(sf, NULL, &nleaves, &leaves, NULL));
  for (PetscInt i = 0; i < nleaves && leaves; ++i) b->owned[leaves[i] - b->pStart] = PETSC_FALSE;
  if (!leaves)
    for (PetscInt i = 0; i < nleaves; ++i) b->owned[i] = PETSC_FALSE;
  PetscCall(PetscSectionCreate(b->comm, &ns));
  PetscCall(PetscSectionSetChart(ns, b->pStart, b->pEnd));
  for (PetscInt p = b->pStart; p < b->pEnd; ++p) {
    PetscInt dof;
    PetscCall(PetscSectionGetDof(s, p, &dof));
    if (dof) PetscCall(PetscSectionSetDof(ns, p, 1));
  }
  PetscCall(PetscSectionSetUp(ns));
  PetscCall(PetscSectionCreateGlobalSection(ns, sf, PETSC_FALSE, PETSC_FALSE, &b->nodeGS));
  PetscCall(PetscSectionDestroy(&ns));
  PetscFunctionReturn(0);
}

/* Global node number of a node point (owned or ghost). */
PetscErrorCode BodyGetNodeNumber(Body b, PetscInt p, PetscInt *node)
{
  PetscInt off;

  PetscFunctionBeginUser;
  PetscCall(PetscSectionGetOffset(b->nodeGS, p, &off));
  *node = off >= 0 ? off : -(off + 1);
  PetscFunctionReturn(0);
}

PetscErrorCode BodySetUp(Body b, PetscInt partitioner, PetscBool partitionView)
{
  PetscFunctionBeginUser;
  PetscCall(b->ops.setup(b, partitioner, partitionView));
  PetscFunctionReturn(0);
}

static PetscErrorCode BodySetUp_Elastic(Body b, PetscInt partitioner, PetscBool partitionView)
{
  PetscQuadrature q;
  PetscDS         ds;
  PetscInt        qdeg = b->qdeg;
  PetscLogDouble  t0, t1;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogStagePush(contactLog.mesh));
  PetscCall(BodyReadMesh(b, partitioner, partitionView));
  PetscCall(PetscLogStagePop());
  PetscCall(PetscTime(&t1));
  b->tmesh += t1 - t0;
  PetscCall(PetscLogStagePush(contactLog.setup));
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, b->dim, b->dim, b->simplex, 2, PETSC_DETERMINE, &b->fe));
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, b->dim, 1, b->simplex, 2, PETSC_DETERMINE, &b->feScalar));
  if (b->simplex) PetscCall(PetscDTSimplexQuadrature(b->dim, qdeg, PETSCDTSIMPLEXQUAD_DEFAULT, &q));
  else PetscCall(PetscDTGaussTensorQuadrature(b->dim, 1, (qdeg + 2) / 2, -1.0, 1.0, &q));
  PetscCall(PetscFESetQuadrature(b->fe, q));
  PetscCall(PetscFESetQuadrature(b->feScalar, q));
  PetscCall(PetscQuadratureDestroy(&q));
  PetscCall(PetscObjectSetName((PetscObject)b->fe, "displacement"));
  PetscCall(DMSetField(b->dm, 0, NULL, (PetscObject)b->fe));
  PetscCall(DMCreateDS(b->dm));
  PetscCall(DMGetDS(b->dm, &ds));
  if (b->hasExact) PetscCall(ExactSolutionSetDimension(&b->exact, b->dim, b->name));
  PetscCall(BodyConditionsSetUp(b));              /* the scene's Dirichlet conditions */
  if (b->axisym) PetscCall(BodyAddAxis(b));      /* u_r = 0 on the axis */
  if (b->mayAnchor) PetscCall(BodyAddAnchors(b)); /* a body held by contact: its free rigid motions anchored, each anchor force-controlled to zero */
  PetscCall(DMCreateLocalVector(b->dm, &b->Xl));
  PetscCall(VecDuplicate(b->Xl, &b->Gl));
  PetscCall(VecDuplicate(b->Xl, &b->bcl));
  PetscCall(VecSet(b->bcl, 0.0));
  PetscCall(DMPlexInsertBoundaryValues(b->dm, PETSC_TRUE, b->bcl, 0.0, NULL, NULL, NULL));
  PetscCall(VecDuplicate(b->bcl, &b->bclFull));
  PetscCall(VecCopy(b->bcl, b->bclFull));
  PetscCall(DMCreateGlobalVector(b->dm, &b->Xg));
  PetscCall(VecDuplicate(b->Xg, &b->Gg));
  PetscCall(VecGetLocalSize(b->Xg, &b->nlocal));
  PetscCall(VecGetSize(b->Xg, &b->nglobal));
  PetscCall(BodyBuildCellCache(b));
  PetscCall(BodyStateSetUp(b));                  /* a material with history: its quadrature points' state (bodystate.c) */
  if (b->axisym) PetscCall(BodyCheckAxis(b));
  PetscCall(BodyBuildNodeData(b));
  PetscCall(BodyLoadsSetUp(b));
  PetscCall(BodyCheckConditions(b));
  b->stage = 0;
  PetscCall(BodySetLoad(b, (PetscReal)b->nstages)); /* the last stage's end, until the solve sets another */
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGlobalToLocal(Body b, Vec Xg, Vec Xl)
{
  PetscFunctionBeginUser;
  if (b->ops.globaltolocal) PetscCall(b->ops.globaltolocal(b, Xg, Xl));
  PetscFunctionReturn(0);
}

static PetscErrorCode BodyGlobalToLocal_Elastic(Body b, Vec Xg, Vec Xl)
{
  PetscFunctionBeginUser;
  PetscCall(VecCopy(b->bcl, Xl));
  PetscCall(DMGlobalToLocalBegin(b->dm, Xg, INSERT_VALUES, Xl));
  PetscCall(DMGlobalToLocalEnd(b->dm, Xg, INSERT_VALUES, Xl));
  PetscFunctionReturn(0);
}

/* Pi_b(u) = int W(grad u) dA - int f . u dA - (the loads' f) . u (loads.c)
   and its gradient, added into Gl, W the body's material's. Where the
   material is inverted (J <= 0 at a quadrature point), Pi_b is +inf and the
   gradient is left partial (finite): the line search that asked backs off,
   and b->inverted counts the evaluation. */
PetscErrorCode BodyComputeEnergyGradient(Body b, Vec Xl, PetscReal *energy, Vec Gl)
{
  PetscFunctionBeginUser;
  PetscCall(b->ops.energygradient(b, Xl, energy, Gl));
  PetscFunctionReturn(0);
}

static PetscErrorCode BodyComputeEnergyGradient_Elastic(Body b, Vec Xl, PetscReal *energy, Vec Gl)
{
  const PetscScalar *x;
  PetscScalar       *g;
  PetscReal          e = 0.0;
  const PetscInt     nb = b->nb, nq = b->nq, dim = b->dim;
  PetscBool          inverted = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCheck(nb <= ELEMENT_MAX_NODES && dim <= 3, b->comm, PETSC_ERR_SUP, "body %s: cells of %" PetscInt_FMT " nodes in %" PetscInt_FMT "D; the element loop takes up to %d nodes in up to 3D", b->name, nb, dim, ELEMENT_MAX_NODES);
  PetscCall(PetscLogEventBegin(contactLog.elasEnergyGrad, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(Xl, &x));
  PetscCall(VecGetArray(Gl, &g));
  for (PetscInt c = 0; c < b->ncells && !inverted; ++c) {
    PetscInt iq;

    if (!ElementAddEnergyGradient(b, c, x, &e, g, &iq)) {
      inverted         = PETSC_TRUE;
      b->invertedAt[0] = b->xq[(c * nq + iq) * dim];
      b->invertedAt[1] = b->xq[(c * nq + iq) * dim + 1];
    }
  }
  PetscCall(BodyLoadsAddEnergyGradient(b, x, &e, g));
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscCall(VecRestoreArray(Gl, &g));
  PetscCall(PetscLogFlops(b->ncells * nq * (nb * 16.0 + 30.0)));
  PetscCall(PetscLogEventEnd(contactLog.elasEnergyGrad, 0, 0, 0, 0));
  if (inverted) {
    b->inverted++;
    PetscCall(PetscInfo(NULL, "body %s: J <= 0 at (%g, %g): energy +inf\n", b->name, (double)b->invertedAt[0], (double)b->invertedAt[1]));
  }
  *energy = inverted ? (PetscReal)INFINITY : e;
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGetInversions(Body b, PetscInt *n, PetscReal xy[2])
{
  PetscMPIInt rank, size, first;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(b->comm, &rank));
  PetscCallMPI(MPI_Comm_size(b->comm, &size));
  PetscCall(MPIU_Allreduce(&b->inverted, n, 1, MPIU_INT, MPI_SUM, b->comm));
  first = b->inverted ? rank : size;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, b->comm));
  xy[0] = b->invertedAt[0];
  xy[1] = b->invertedAt[1];
  if (first < size) PetscCallMPI(MPI_Bcast(xy, 2, MPIU_REAL, first, b->comm));
  PetscFunctionReturn(0);
}

/* The assembled stiffness: this rank's element stiffnesses at l2b indices. */
PetscErrorCode BodyAssembleHessian(Body b, Mat H)
{
  PetscFunctionBeginUser;
  if (b->ops.hessian) PetscCall(b->ops.hessian(b, H));
  PetscFunctionReturn(0);
}

static PetscErrorCode BodyAssembleHessian_Elastic(Body b, Mat H)
{
  PetscFunctionBeginUser;
  PetscCall(BodyAssembleHessianMapped(b, b->l2b, H));
  PetscFunctionReturn(0);
}

/* Cell c's tangent K_(a i)(b j) = int d2W/du_(a i) du_(b j) dV (n x n, n =
   dim nb, full), at the displacement x (a local array; NULL: at rest, where
   every material's tangent is linear elasticity's): element.c. */
static void BodyCellTangent(Body b, PetscInt c, const PetscScalar x[], PetscScalar K[])
{
  PetscReal u[ELEMENT_MAX_DOFS];

  if (x) ElementGather(b, c, x, u);
  ElementTangent(b, c, x ? u : NULL, K);
}

/* The tangent over this rank's cells at the displacement x (as above), added
   into H at rows and columns map[local dof] (negative: left out). */
static PetscErrorCode BodyAssembleTangentMapped(Body b, const PetscScalar x[], const PetscInt map[], Mat H)
{
  const PetscInt dim = b->dim, nb = b->nb, n = dim * nb;
  PetscScalar   *K;
  PetscInt      *idx;

  PetscFunctionBeginUser;
  PetscCheck(nb <= ELEMENT_MAX_NODES && dim <= 3, b->comm, PETSC_ERR_SUP, "body %s: cells of %" PetscInt_FMT " nodes in %" PetscInt_FMT "D; the element loop takes up to %d nodes in up to 3D", b->name, nb, dim, ELEMENT_MAX_NODES);
  PetscCall(PetscLogEventBegin(contactLog.elasHessian, 0, 0, 0, 0));
  PetscCall(PetscMalloc2(n * n, &K, n, &idx));
  for (PetscInt c = 0; c < b->ncells; ++c) {
    for (PetscInt a = 0; a < nb; ++a)
      for (PetscInt i = 0; i < dim; ++i) idx[dim * a + i] = map[b->cdof[c * nb + a] + i];
    BodyCellTangent(b, c, x, K);
    PetscCall(MatSetValues(H, n, idx, n, idx, K, ADD_VALUES));
  }
  PetscCall(PetscFree2(K, idx));
  PetscCall(PetscLogEventEnd(contactLog.elasHessian, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The stiffness at rest, added into H at rows and columns map[local dof].
   With the joined vector's map l2b, the assembled stiffness; with a map
   onto the rank's own dofs, its subdomain stiffness (substructure.c). */
PetscErrorCode BodyAssembleHessianMapped(Body b, const PetscInt map[], Mat H)
{
  PetscFunctionBeginUser;
  PetscCall(BodyAssembleTangentMapped(b, NULL, map, H));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyAssembleTangent(Body b, Vec Xl, Mat H)
{
  PetscFunctionBeginUser;
  if (b->ops.tangent) PetscCall(b->ops.tangent(b, Xl, H));
  PetscFunctionReturn(0);
}

static PetscErrorCode BodyAssembleTangent_Elastic(Body b, Vec Xl, Mat H)
{
  const PetscScalar *x;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(Xl, &x));
  PetscCall(BodyAssembleTangentMapped(b, b->mat->constantTangent ? NULL : x, b->l2b, H));
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscFunctionReturn(0);
}

/* Yl = K(Xl) El over this rank's cells, local vectors (constrained dofs
   included), K the tangent at Xl (NULL: at rest); only the cells where El
   has an entry are visited, so a column of a few dofs costs a few cells'
   tangents. Like a gradient, Yl holds this rank's cells' part alone. */
PetscErrorCode BodyApplyTangentLocal(Body b, Vec Xl, Vec El, Vec Yl)
{
  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(Yl));
  if (b->ops.applytangent) PetscCall(b->ops.applytangent(b, Xl, El, Yl));
  PetscFunctionReturn(0);
}

static PetscErrorCode BodyApplyTangentLocal_Elastic(Body b, Vec Xl, Vec El, Vec Yl)
{
  const PetscInt     dim = b->dim, nb = b->nb, n = dim * nb;
  const PetscScalar *x = NULL, *e;
  PetscScalar       *y, *K;

  PetscFunctionBeginUser;
  if (Xl && !b->mat->constantTangent) PetscCall(VecGetArrayRead(Xl, &x));
  PetscCall(VecGetArrayRead(El, &e));
  PetscCall(VecGetArray(Yl, &y));
  PetscCall(PetscMalloc1(n * n, &K));
  for (PetscInt c = 0; c < b->ncells; ++c) {
    PetscBool any = PETSC_FALSE;
    for (PetscInt a = 0; a < n && !any; ++a) any = (PetscBool)(e[b->cdof[c * nb + a / dim] + a % dim] != 0.0);
    if (!any) continue;
    BodyCellTangent(b, c, x, K);
    for (PetscInt i = 0; i < n; ++i) {
      PetscScalar s = 0;
      for (PetscInt j = 0; j < n; ++j) s += K[i * n + j] * e[b->cdof[c * nb + j / dim] + j % dim];
      y[b->cdof[c * nb + i / dim] + i % dim] += s;
    }
  }
  PetscCall(PetscFree(K));
  PetscCall(VecRestoreArray(Yl, &y));
  PetscCall(VecRestoreArrayRead(El, &e));
  if (x) PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscFunctionReturn(0);
}

/* Reaction of each Dirichlet group: the sum of dPi/du over its constrained dofs.
   Gl holds only this rank's cell contributions, so summing over every local
   point of the group on every rank counts each cell once. */
PetscErrorCode BodyComputeReactions(Body b, Vec Gl)
{
  PetscFunctionBeginUser;
  PetscCall(b->ops.reactions(b, Gl));
  PetscFunctionReturn(0);
}

static PetscErrorCode BodyComputeReactions_Elastic(Body b, Vec Gl)
{
  PetscSection       s;
  const PetscScalar *g;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(b->dm, &s));
  PetscCall(VecGetArrayRead(Gl, &g));
  for (PetscInt i = 0; i < b->nbc; ++i) {
    BodyBC   *bc = &b->bc[i];
    IS        is;
    PetscReal r[3] = {0, 0, 0};

    PetscCall(DMLabelGetStratumIS(bc->label, 1, &is));
    if (is) {
      const PetscInt *pts;
      PetscInt        n;
      PetscCall(ISGetLocalSize(is, &n));
      PetscCall(ISGetIndices(is, &pts));
      for (PetscInt j = 0; j < n; ++j) {
        PetscInt dof, off;
        PetscCall(PetscSectionGetDof(s, pts[j], &dof));
        if (!dof) continue;
        PetscCall(PetscSectionGetOffset(s, pts[j], &off));
        for (PetscInt k = 0; k < bc->ncomp; ++k) r[bc->comps[k]] += PetscRealPart(g[off + bc->comps[k]]);
      }
      PetscCall(ISRestoreIndices(is, &pts));
      PetscCall(ISDestroy(&is));
    }
    PetscCall(MPIU_Allreduce(r, bc->reaction, b->dim, MPIU_REAL, MPIU_SUM, b->comm));
  }
  PetscCall(VecRestoreArrayRead(Gl, &g));
  PetscFunctionReturn(0);
}

/* Errors of u_h against the body's exact solution u, by the cell quadrature
   (on the curved cells' own geometry), with e = u_h - u:
     L2:          ||e||_L2^2 = int |e|^2 dA                          O(h^3) for P2/Q2,
     energy norm: ||e||_E^2  = int eps(e) : C : eps(e) dA = 2 int W(grad e) dA   O(h^2),
     stress:      ||sigma(u_h) - sigma(u)||_L2^2 = int |sigma(grad e)|^2 dA     O(h^2),
   sigma linear in grad u, |sigma|^2 = xx^2 + yy^2 + zz^2 + 2 xy^2 (the
   plane-strain tensor; in axisymmetry the hoop component for zz and every
   dA a 2 pi r dA); with the norms ||u||_L2, ||u||_E, ||sigma(u)||_L2.
   The a priori estimates (Ciarlet, ch. 3-4; isoparametric cells keep the rates)
   give the orders on the right: the energy norm and the stress error are one
   order below the L2 error. */
static void StressSquared(const PetscReal param[], const PetscReal H[], PetscReal *s2)
{
  PetscReal s[9];

  ElasticityStress(param, H, s);
  *s2 = PetscSqr(s[0]) + PetscSqr(s[4]) + PetscSqr(s[8]) + 2.0 * PetscSqr(s[1]) + 2.0 * PetscSqr(s[2]) + 2.0 * PetscSqr(s[5]);
}

PetscErrorCode BodyComputeErrors(Body b, Vec Xl, BodyErrors *E)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(E, sizeof(*E)));
  if (b->hasExact && b->ops.errors) PetscCall(b->ops.errors(b, Xl, E));
  PetscFunctionReturn(0);
}

static PetscErrorCode BodyComputeErrors_Elastic(Body b, Vec Xl, BodyErrors *E)
{
  const PetscScalar *x;
  PetscReal          loc[6] = {0, 0, 0, 0, 0, 0}, glob[6];
  const PetscInt     dim = b->dim, nq = b->nq;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(Xl, &x));
  for (PetscInt c = 0; c < b->ncells; ++c) {
    PetscReal u[ELEMENT_MAX_DOFS];

    ElementGather(b, c, x, u);
    for (PetscInt iq = 0; iq < nq; ++iq) {
      const PetscReal *xq = &b->xq[(c * nq + iq) * dim];
      const PetscReal  w  = b->wdetJ[c * nq + iq];
      PetscReal        uh[3], ue[3], du[9], Hh[9], He[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, Hd[9], W, s2, d2 = 0.0, n2 = 0.0;

      ElementPointGradient(b, c, iq, u, uh, Hh);
      b->exact.u(b->exact.params, xq, ue);
      b->exact.du(b->exact.params, xq, du);
      for (PetscInt i = 0; i < dim; ++i)
        for (PetscInt J = 0; J < dim; ++J) He[i * 3 + J] = du[i * dim + J];
      if (b->axisym) He[8] = ue[0] / xq[0]; /* the hoop strains, at a quadrature point (r > 0) */
      for (PetscInt k = 0; k < 9; ++k) Hd[k] = Hh[k] - He[k];
      for (PetscInt i = 0; i < dim; ++i) {
        d2 += PetscSqr(uh[i] - ue[i]);
        n2 += PetscSqr(ue[i]);
      }
      loc[0] += w * d2;
      loc[1] += w * n2;
      ElasticityEnergyDensity(b->param, Hd, &W);
      loc[2] += w * 2.0 * W;
      ElasticityEnergyDensity(b->param, He, &W);
      loc[3] += w * 2.0 * W;
      StressSquared(b->param, Hd, &s2);
      loc[4] += w * s2;
      StressSquared(b->param, He, &s2);
      loc[5] += w * s2;
    }
  }
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscCall(MPIU_Allreduce(loc, glob, 6, MPIU_REAL, MPIU_SUM, b->comm));
  E->l2         = PetscSqrtReal(glob[0]);
  E->l2norm     = PetscSqrtReal(glob[1]);
  E->energy     = PetscSqrtReal(glob[2]);
  E->energynorm = PetscSqrtReal(glob[3]);
  E->stress     = PetscSqrtReal(glob[4]);
  E->stressnorm = PetscSqrtReal(glob[5]);
  PetscFunctionReturn(0);
}

PetscErrorCode BodyDestroy(Body *body)
{
  Body b = *body;

  PetscFunctionBeginUser;
  if (!b) PetscFunctionReturn(0);
  PetscCall(BodySupportDestroy(b));
  for (PetscInt i = 0; i < b->ngeoparams; ++i) PetscCall(PetscFree(b->geoparams[i]));
  for (PetscInt i = 0; i < b->nphys; ++i) PetscCall(PetscFree(b->physNames[i]));
  PetscCall(PetscFree(b->physNames));
  PetscCall(PetscFree2(b->physDims, b->physTags));
  PetscCall(PetscFree6(b->cpts, b->cdof, b->dNdx, b->wdetJ, b->xq, b->xnode));
  PetscCall(PetscFree(b->state));
  PetscCall(PetscFree(b->stateNew));
  PetscCall(PetscFree(b->l2b));
  PetscCall(PetscFree2(b->xpoint, b->owned));
  PetscCall(PetscSectionDestroy(&b->nodeGS));
  PetscCall(VecDestroy(&b->Xg));
  PetscCall(VecDestroy(&b->Gg));
  PetscCall(VecDestroy(&b->Xl));
  PetscCall(VecDestroy(&b->Gl));
  PetscCall(VecDestroy(&b->Fl));
  PetscCall(VecDestroy(&b->bcl));
  PetscCall(VecDestroy(&b->bclFull));
  PetscCall(VecDestroy(&b->bclFrom));
  PetscCall(VecDestroy(&b->FlFrom));
  PetscCall(PetscFEDestroy(&b->fe));
  PetscCall(PetscFEDestroy(&b->feScalar));
  PetscCall(DMDestroy(&b->dm));
  if (b->ops.destroy) PetscCall(b->ops.destroy(b));
  PetscCall(PetscFree(b));
  *body = NULL;
  PetscFunctionReturn(0);
}

PetscErrorCode BodyViewSolution(Body b, PetscBool axisymmetric)
{
  PetscFunctionBeginUser;
  if (b->ops.viewsolution) PetscCall(b->ops.viewsolution(b, axisymmetric));
  PetscFunctionReturn(0);
}

void BodyElasticSetOps(Body b)
{
  BodyOps *ops = &b->ops;

  PetscMemzero(ops, sizeof(*ops));
  ops->setup              = BodySetUp_Elastic;
  ops->globaltolocal      = BodyGlobalToLocal_Elastic;
  ops->energygradient     = BodyComputeEnergyGradient_Elastic;
  ops->hessian            = BodyAssembleHessian_Elastic;
  ops->tangent            = BodyAssembleTangent_Elastic;
  ops->applytangent       = BodyApplyTangentLocal_Elastic;
  ops->reactions          = BodyComputeReactions_Elastic;
  ops->errors             = BodyComputeErrors_Elastic;
  ops->setjoinednumbering = BodySetJoinedNumbering_Elastic;
  ops->addjoinedgradient  = BodyAddJoinedGradient_Elastic;
  ops->checkheld          = BodyCheckHeld_Elastic;
  ops->groupedges         = BodyGetGroupEdges_Elastic;
  ops->boundaryedgesat    = BodyBoundaryEdgesAt_Elastic;
  ops->mapnodes           = BodyMapNodes_Elastic;
  ops->nodedisplacements  = BodyGetNodeDisplacements_Elastic;
  ops->addnodeforces      = BodyAddNodeForces_Elastic;
  ops->getcontrols        = BodyGetControls_Elastic;
  ops->setcontrol         = BodySetControlValue_Elastic;
  ops->controlforce       = BodyGetControlForce_Elastic;
  ops->controlreaction    = BodyGetControlReaction_Elastic;
  ops->controlcomponent   = BodyGetControlComponent_Elastic;
}
