/* A body's data and the queries of its mesh that the body's files share:
   the physical groups by name, the element's reference nodes and cell
   corners, the vertices' coordinates and their bounding box, whether the
   mesh is second order, and a boundary edge's nodes and outward side. The
   Body struct (bodyimpl.h) is read here and in the files above; this file
   calls none of them, so that body.c, which orchestrates, can call each. */
#include "bodycore.h"
#include "bodyimpl.h"

PetscErrorCode BodyCheckGroupsUnique(Body b, const char opt[], PetscInt n, char *const names[])
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt j = 0; j < i; ++j) {
      PetscBool same;
      PetscCall(PetscStrcmp(names[i], names[j], &same));
      PetscCheck(!same, b->comm, PETSC_ERR_USER_INPUT, "option %s: group %s given twice", opt, names[i]);
    }
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGetPhysicalTag(Body b, const char group[], PetscInt dim, PetscInt *tag)
{
  char known[1024] = "";

  PetscFunctionBeginUser;
  *tag = -1;
  for (PetscInt i = 0; i < b->nphys; ++i) {
    PetscBool same;
    PetscCall(PetscStrcmp(b->physNames[i], group, &same));
    if (same && b->physDims[i] == dim) {
      *tag = b->physTags[i];
      PetscFunctionReturn(0);
    }
    if (b->physDims[i] == dim) {
      PetscCall(PetscStrlcat(known, " ", sizeof(known)));
      PetscCall(PetscStrlcat(known, b->physNames[i], sizeof(known)));
    }
  }
  SETERRQ(b->comm, PETSC_ERR_USER_INPUT, "body %s: mesh %s has no physical %s '%s' (it has:%s)", b->name, b->msh, dim == 2 ? "surface" : dim == 1 ? "curve" : dim == 3 ? "volume" : "point", group, known);
}

/* Reference coordinates of the nodes of element fe, in basis order
   ([nb][dim]), and their number (nb, if not NULL). */
static PetscErrorCode FEGetReferenceNodes(PetscFE fe, PetscInt *nb, PetscReal ref[])
{
  PetscDualSpace sp;
  PetscInt       n, dim;

  PetscFunctionBeginUser;
  PetscCall(PetscFEGetDimension(fe, &n));
  PetscCall(PetscFEGetSpatialDimension(fe, &dim));
  PetscCall(PetscFEGetDualSpace(fe, &sp));
  for (PetscInt a = 0; a < n; ++a) {
    PetscQuadrature  fq;
    const PetscReal *pts;
    PetscCall(PetscDualSpaceGetFunctional(sp, a, &fq));
    PetscCall(PetscQuadratureGetData(fq, NULL, NULL, NULL, &pts, NULL));
    for (PetscInt d = 0; d < dim; ++d) ref[dim * a + d] = pts[d];
  }
  if (nb) *nb = n;
  PetscFunctionReturn(0);
}

/* Reference coordinates of the nodes of the scalar element, in basis order. */
PetscErrorCode BodyGetReferenceNodes(Body b, PetscReal ref[])
{
  PetscFunctionBeginUser;
  PetscCall(FEGetReferenceNodes(b->feScalar, NULL, ref));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyPointsBox(Body b, PetscInt n, const PetscReal xy[], PetscReal lo[2], PetscReal hi[2])
{
  PetscReal m[4] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}; /* least x, y, -x, -y */

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < n; ++k)
    for (PetscInt d = 0; d < 2; ++d) {
      m[d]     = PetscMin(m[d], xy[2 * k + d]);
      m[2 + d] = PetscMin(m[2 + d], -xy[2 * k + d]);
    }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, m, 4, MPIU_REAL, MPIU_MIN, b->comm));
  for (PetscInt d = 0; d < 2; ++d) {
    lo[d] = m[d];
    hi[d] = -m[2 + d];
  }
  PetscFunctionReturn(0);
}

/* A first-order mesh has affine coordinates, not a P2/Q2 coordinate field:
   refused in one line, before anything reads the coordinate field. */
PetscErrorCode BodyCheckSecondOrder(Body b)
{
  DM           cdm;
  PetscInt     nf;
  PetscObject  obj = NULL;
  PetscClassId cid = 0;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDM(b->dm, &cdm));
  PetscCall(DMGetNumFields(cdm, &nf));
  if (nf == 1) PetscCall(DMGetField(cdm, 0, NULL, &obj));
  if (obj) PetscCall(PetscObjectGetClassId(obj, &cid));
  PetscCheck(obj && cid == PETSCFE_CLASSID, b->comm, PETSC_ERR_FILE_UNEXPECTED, "body %s: mesh %s is first order; the solver needs second-order elements (%s: Mesh.ElementOrder = 2)", b->name, b->msh, b->dim == 3 ? "Tet10 or Hex27" : "Tri6 or Quad9");
  PetscFunctionReturn(0);
}

/* The coordinates of this rank's vertices ([v - vStart][dim], PetscFree), by
   evaluating each cell's coordinate field at the displacement element's
   reference nodes (continuous Q2 on quads, cellwise P2 on triangles: a
   vertex need not carry coordinates of its own). Node k of a cell is the
   k-th point of its closure that carries a displacement node: every vertex
   and edge, and a quadrilateral itself (the cell cache's order). Usable
   once the elements exist, before the displacement section does. */
PetscErrorCode BodyVertexCoordinates(Body b, PetscReal **xy)
{
  DM              cdm;
  Vec             coords;
  PetscFE         cfe;
  PetscTabulation Tc;
  PetscInt        vs, ve, cs, ce, nb, ncb, dim = b->dim, *numDof;
  PetscReal       ref[27 * 3];
  PetscDualSpace  sp;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(b->dm, 0, &vs, &ve));
  PetscCall(DMPlexGetHeightStratum(b->dm, 0, &cs, &ce));
  PetscCall(DMGetCoordinateDM(b->dm, &cdm));
  PetscCall(DMGetField(cdm, 0, NULL, (PetscObject *)&cfe));
  PetscCall(PetscFEGetDimension(cfe, &ncb));
  PetscCall(DMGetCoordinatesLocal(b->dm, &coords));
  PetscCall(FEGetReferenceNodes(b->feScalar, &nb, ref));
  PetscCall(PetscFEGetDualSpace(b->feScalar, &sp));
  PetscCall(PetscDualSpaceGetNumDof(sp, (const PetscInt **)&numDof)); /* the nodes at each depth: every depth but a triangle's or a tetrahedron's faces and cell */
  PetscCall(PetscFECreateTabulation(cfe, 1, nb, ref, 0, &Tc));
  PetscCall(PetscCalloc1(dim * (ve - vs) + dim, xy));
  for (PetscInt c = cs; c < ce; ++c) {
    PetscInt    *cl = NULL, ncl, k = 0, ncc;
    PetscScalar *xc = NULL;
    PetscCall(DMPlexGetTransitiveClosure(b->dm, c, PETSC_TRUE, &ncl, &cl));
    PetscCall(DMPlexVecGetClosure(cdm, NULL, coords, c, &ncc, &xc));
    for (PetscInt i = 0; i < ncl && k < nb; ++i) {
      const PetscInt p = cl[2 * i];
      PetscInt       depth;
      PetscCall(DMPlexGetPointDepth(b->dm, p, &depth));
      if (!numDof[depth]) continue;
      if (depth == 0)
        for (PetscInt d = 0; d < dim; ++d) {
          PetscReal x = 0.0, tmax = 0.0;
          PetscInt  fmax = -1;
          for (PetscInt f = 0; f < ncb; ++f) {
            const PetscReal t = Tc->T[0][(k * ncb + f) * dim + d];
            x += PetscRealPart(xc[f]) * t;
            if (PetscAbsReal(t) > tmax) {
              tmax = PetscAbsReal(t);
              fmax = f;
            }
          }
          /* a Lagrange coordinate field at its own node: the stored value
             itself, the same bits from every cell and on every rank (the
             anchors and the axis compare vertices across ranks) */
          if (fmax >= 0 && PetscAbsReal(tmax - 1.0) < 1e-10) x = PetscRealPart(xc[fmax]);
          (*xy)[dim * (p - vs) + d] = x;
        }
      k++;
    }
    PetscCall(DMPlexVecRestoreClosure(cdm, NULL, coords, c, &ncc, &xc));
    PetscCall(DMPlexRestoreTransitiveClosure(b->dm, c, PETSC_TRUE, &ncl, &cl));
  }
  PetscCall(PetscTabulationDestroy(&Tc));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyEdgeNodes(Body b, PetscInt e, PetscInt pts[3], PetscReal x[6])
{
  const PetscInt *cone;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetCone(b->dm, e, &cone));
  pts[0] = cone[0];
  pts[1] = cone[1];
  pts[2] = e;
  for (PetscInt j = 0; j < 3; ++j) {
    x[2 * j]     = b->xpoint[2 * (pts[j] - b->pStart)];
    x[2 * j + 1] = b->xpoint[2 * (pts[j] - b->pStart) + 1];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BodyEdgeOutwardSign(Body b, PetscInt e, const PetscReal x[6], const char what[], const char group[], PetscReal *sign)
{
  PetscSection    s;
  const PetscInt *supp;
  PetscInt        nsupp, *cl = NULL, ncl;
  PetscReal       xc[2] = {0, 0}, t[2], nrm[2], cnt = 0;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(b->dm, &s));
  PetscCall(DMPlexGetSupportSize(b->dm, e, &nsupp));
  PetscCall(DMPlexGetSupport(b->dm, e, &supp));
  PetscCheck(nsupp == 1, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: an edge of group '%s' of body %s is not on the boundary", what, group, b->name);
  PetscCall(DMPlexGetTransitiveClosure(b->dm, supp[0], PETSC_TRUE, &ncl, &cl));
  for (PetscInt j = 0; j < ncl; ++j) {
    PetscInt dof;
    PetscCall(PetscSectionGetDof(s, cl[2 * j], &dof));
    if (!dof) continue;
    xc[0] += b->xpoint[2 * (cl[2 * j] - b->pStart)];
    xc[1] += b->xpoint[2 * (cl[2 * j] - b->pStart) + 1];
    cnt += 1;
  }
  PetscCall(DMPlexRestoreTransitiveClosure(b->dm, supp[0], PETSC_TRUE, &ncl, &cl));
  t[0]   = x[2] - x[0];
  t[1]   = x[3] - x[1];
  nrm[0] = t[1];
  nrm[1] = -t[0];
  *sign  = (nrm[0] * (x[4] - xc[0] / cnt) + nrm[1] * (x[5] - xc[1] / cnt)) > 0 ? 1.0 : -1.0;
  PetscFunctionReturn(0);
}

PetscErrorCode BodyGetCellCorners(Body b, PetscReal ref[], PetscInt corner[4], PetscInt *nv)
{
  PetscFunctionBeginUser;
  PetscCheck(b->nb <= 64, b->comm, PETSC_ERR_SUP, "body %s: %" PetscInt_FMT " nodes per cell", b->name, b->nb);
  PetscCall(BodyGetReferenceNodes(b, ref));
  *nv = 0;
  for (PetscInt a = 0; a < b->nb && *nv < 4; ++a) {
    const PetscReal x = ref[2 * a], y = ref[2 * a + 1];
    const PetscBool c = b->simplex ? (PetscBool)(PetscAbsReal(x + y) < 1e-12 || (x < -1 + 1e-12 && y < -1 + 1e-12)) : (PetscBool)(PetscAbsReal(PetscAbsReal(x) - 1) < 1e-12 && PetscAbsReal(PetscAbsReal(y) - 1) < 1e-12);
    if (c && (!b->simplex || PetscAbsReal(PetscAbsReal(x) - 1) < 1e-12)) corner[(*nv)++] = a;
  }
  PetscCheck(*nv == (b->simplex ? 3 : 4), b->comm, PETSC_ERR_PLIB, "body %s: %" PetscInt_FMT " vertices found in a cell", b->name, *nv);
  if (!b->simplex) {
    PetscInt  o[4] = {0, 0, 0, 0};
    PetscReal want[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (PetscInt k = 0; k < 4; ++k)
      for (PetscInt v = 0; v < 4; ++v)
        if (ref[2 * corner[v]] == want[k][0] && ref[2 * corner[v] + 1] == want[k][1]) o[k] = corner[v];
    for (PetscInt k = 0; k < 4; ++k) corner[k] = o[k];
  }
  PetscFunctionReturn(0);
}
