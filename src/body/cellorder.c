/* A cell's nodes in the order of its XDMF / VTK cell type, for the output's
   topology: Tri6 and Quad9 (XDMF Triangle_6, Quadrilateral_9: corners
   counter-clockwise, edge (c0, c1), (c1, c2), ..., then the cell node),
   Tet10 and Hex27 (XDMF Tetrahedron_10, Hexahedron_27, which ParaView reads
   as VTK's quadratic tetrahedron and triquadratic hexahedron).

   The order is found from the cell's closure points (cpts: the points that
   carry its nodes, of depth 0 corners, 1 edges, 2 faces, 3 the cell), their
   cones (an edge's two corners) and the corners' positions, never from the
   order PETSc lists them in:
   - corners: a Tri6 / Quad9's as the closure lists them (the 2D cell's
     closure goes round it); a Tet10's as listed, its second and third
     swapped if the corner tetrahedron's volume det(x1 - x0, x2 - x0,
     x3 - x0) is negative; a Hex27's bottom 0-3 are the corners of its first
     face, in order round the face (each to the next by an edge of the cell),
     4-7 the corners joined to 0-3 by the other four edges, the face's order
     reversed if the trilinear corner hexahedron's Jacobian at its centre is
     negative (VTK's cells have a positive one: bottom counter-clockwise
     seen from the top);
   - an edge node is placed by its edge's two corners and a face node by its
     face's four.
   VTK's node order (vtkQuadraticTetra, vtkTriQuadraticHexahedron: their
   parametric coordinates as VTK 9.2 in ParaView 5.11 returns them): Tet10
   corners 0-3, edges (0,1), (1,2), (0,2), (0,3), (1,3), (2,3); Hex27
   corners, edges (0,1), (1,2), (2,3), (3,0), (4,5), (5,6), (6,7), (7,4),
   (0,4), (1,5), (2,6), (3,7), faces x = 0 (0,3,7,4), x = 1 (1,2,6,5),
   y = 0 (0,1,5,4), y = 1 (3,2,6,7), z = 0 (0,1,2,3), z = 1 (4,5,6,7) of the
   reference cube [0,1]^3 (the class's header comment lists the faces in
   another order; its code and interpolation use this one), then the
   centre. */
#include "body.h"
#include "bodyimpl.h"

static const PetscInt TetEdges[6][2]  = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
static const PetscInt HexEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
static const PetscInt HexFaces[6][4]  = {{0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}};

/* Tri6 / Quad9: corners in closure order, then each edge after its first
   corner going round, then the cell node. */
static PetscErrorCode CellNodes2D(Body b, PetscInt c, const PetscInt depth[], const PetscInt node[], PetscInt topo[])
{
  const PetscInt  nb = b->nb, *pts = &b->cpts[c * nb];
  PetscInt        corners[4], nc = 0;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < nb; ++k)
    if (depth[k] == 0) corners[nc++] = k;
  for (PetscInt i = 0; i < nc; ++i) topo[i] = node[corners[i]];
  for (PetscInt i = 0; i < nb; ++i) {
    if (depth[i] == 1) {
      const PetscInt *cone;
      PetscInt        j0 = -1, j1 = -1;
      PetscCall(DMPlexGetCone(b->dm, pts[i], &cone));
      for (PetscInt j = 0; j < nc; ++j) {
        if (pts[corners[j]] == cone[0]) j0 = j;
        if (pts[corners[j]] == cone[1]) j1 = j;
      }
      PetscCheck(j0 >= 0 && j1 >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "edge of cell %" PetscInt_FMT " not on its corners", c);
      topo[nc + (((j1 - j0 + nc) % nc == 1) ? j0 : j1)] = node[i];
    } else if (depth[i] == 2) topo[2 * nc] = node[i];
  }
  PetscFunctionReturn(0);
}

/* The index k in the cell's points of the edge joining points p and q; -1 if none. */
static PetscErrorCode CellEdge(Body b, const PetscInt pts[], const PetscInt depth[], PetscInt p, PetscInt q, PetscInt *k)
{
  PetscFunctionBeginUser;
  *k = -1;
  for (PetscInt i = 0; i < b->nb && *k < 0; ++i) {
    const PetscInt *cone;
    if (depth[i] != 1) continue;
    PetscCall(DMPlexGetCone(b->dm, pts[i], &cone));
    if ((cone[0] == p && cone[1] == q) || (cone[0] == q && cone[1] == p)) *k = i;
  }
  PetscFunctionReturn(0);
}

static PetscReal Det3(const PetscReal a[3], const PetscReal b[3], const PetscReal c[3])
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/* The corner points of a Hex27, v[8], in VTK's order (the header). */
static PetscErrorCode HexCorners(Body b, const PetscInt pts[], const PetscInt depth[], PetscInt v[8])
{
  PetscInt  vStart, vEnd, f = -1, ncl, *cl = NULL, fv[4], nf = 0, e;
  PetscReal J[3][3] = {{0}};

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(b->dm, 0, &vStart, &vEnd));
  for (PetscInt k = 0; k < b->nb && f < 0; ++k)
    if (depth[k] == 2) f = pts[k];
  PetscCall(DMPlexGetTransitiveClosure(b->dm, f, PETSC_TRUE, &ncl, &cl));
  for (PetscInt i = 0; i < ncl; ++i)
    if (cl[2 * i] >= vStart && cl[2 * i] < vEnd && nf < 4) fv[nf++] = cl[2 * i];
  PetscCall(DMPlexRestoreTransitiveClosure(b->dm, f, PETSC_TRUE, &ncl, &cl));
  PetscCheck(nf == 4, PETSC_COMM_SELF, PETSC_ERR_PLIB, "a face of a Hex27 with %" PetscInt_FMT " corners", nf);
  /* round the face: in a hexahedron two corners of a face are joined by an edge iff they are neighbours in it */
  v[0] = fv[0];
  for (PetscInt i = 1; i < 4; ++i) {
    v[i] = -1;
    for (PetscInt j = 1; j < 4 && v[i] < 0; ++j) {
      const PetscInt q = fv[j];
      PetscBool      used = PETSC_FALSE;
      for (PetscInt m = 0; m < i; ++m) used = (PetscBool)(used || v[m] == q);
      if (used) continue;
      PetscCall(CellEdge(b, pts, depth, v[i - 1], q, &e));
      if (e >= 0) v[i] = q;
    }
    PetscCheck(v[i] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "a face of a Hex27 whose corners are not joined round it");
  }
  for (PetscInt pass = 0; pass < 2; ++pass) {
    /* the top: each bottom corner's edge leaving the face */
    for (PetscInt i = 0; i < 4; ++i) {
      v[4 + i] = -1;
      for (PetscInt k = 0; k < b->nb && v[4 + i] < 0; ++k) {
        const PetscInt *cone;
        PetscInt        other;
        if (depth[k] != 1) continue;
        PetscCall(DMPlexGetCone(b->dm, pts[k], &cone));
        if (cone[0] != v[i] && cone[1] != v[i]) continue;
        other = cone[0] == v[i] ? cone[1] : cone[0];
        if (other != fv[0] && other != fv[1] && other != fv[2] && other != fv[3]) v[4 + i] = other;
      }
      PetscCheck(v[4 + i] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "a Hex27's corner with no edge off its face");
    }
    if (pass) break;
    /* the trilinear map's Jacobian at the centre: columns d x / d xi, eta, zeta of VTK's reference cube */
    for (PetscInt d = 0; d < 3; ++d) {
      PetscReal x[8];
      for (PetscInt i = 0; i < 8; ++i) x[i] = b->xpoint[(v[i] - b->pStart) * 3 + d];
      J[0][d] = 0.25 * ((x[1] - x[0]) + (x[2] - x[3]) + (x[5] - x[4]) + (x[6] - x[7]));
      J[1][d] = 0.25 * ((x[3] - x[0]) + (x[2] - x[1]) + (x[7] - x[4]) + (x[6] - x[5]));
      J[2][d] = 0.25 * ((x[4] - x[0]) + (x[5] - x[1]) + (x[6] - x[2]) + (x[7] - x[3]));
    }
    if (Det3(J[0], J[1], J[2]) > 0) break;
    e    = v[1]; /* the other way round the face */
    v[1] = v[3];
    v[3] = e;
  }
  PetscFunctionReturn(0);
}

/* Tet10 / Hex27 in VTK's order (the header). */
static PetscErrorCode CellNodes3D(Body b, PetscInt c, const PetscInt depth[], const PetscInt node[], PetscInt topo[])
{
  const PetscInt  nb = b->nb, *pts = &b->cpts[c * nb];
  const PetscBool hex = (PetscBool)(nb == 27);
  const PetscInt  nc = hex ? 8 : 4, ne = hex ? 12 : 6;
  PetscInt        v[8], nv = 0, k;

  PetscFunctionBeginUser;
  PetscCheck(nb == 10 || nb == 27, PETSC_COMM_SELF, PETSC_ERR_SUP, "3D cell of %" PetscInt_FMT " nodes: only Tet10 and Hex27", nb);
  for (PetscInt i = 0; i < nb; ++i) topo[i] = -1;
  if (hex) PetscCall(HexCorners(b, pts, depth, v));
  else {
    PetscReal a[3][3];
    for (PetscInt i = 0; i < nb; ++i)
      if (depth[i] == 0 && nv < 4) v[nv++] = pts[i];
    PetscCheck(nv == 4, PETSC_COMM_SELF, PETSC_ERR_PLIB, "a Tet10 with %" PetscInt_FMT " corners", nv);
    for (PetscInt i = 0; i < 3; ++i)
      for (PetscInt d = 0; d < 3; ++d) a[i][d] = b->xpoint[(v[i + 1] - b->pStart) * 3 + d] - b->xpoint[(v[0] - b->pStart) * 3 + d];
    if (Det3(a[0], a[1], a[2]) < 0) {
      k    = v[1];
      v[1] = v[2];
      v[2] = k;
    }
  }
  for (PetscInt i = 0; i < nc; ++i) {
    for (k = 0; k < nb && pts[k] != v[i]; ++k) { }
    topo[i] = node[k];
  }
  for (PetscInt j = 0; j < ne; ++j) {
    const PetscInt *ends = hex ? HexEdges[j] : TetEdges[j];
    PetscCall(CellEdge(b, pts, depth, v[ends[0]], v[ends[1]], &k));
    PetscCheck(k >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell %" PetscInt_FMT ": no edge between its corners %" PetscInt_FMT " and %" PetscInt_FMT, c, ends[0], ends[1]);
    topo[nc + j] = node[k];
  }
  for (PetscInt i = 0; hex && i < nb; ++i) {
    if (depth[i] == 3) topo[26] = node[i];
    else if (depth[i] == 2) {
      PetscInt vStart, vEnd, ncl, *cl = NULL, fv[4], nf = 0;
      PetscCall(DMPlexGetDepthStratum(b->dm, 0, &vStart, &vEnd));
      PetscCall(DMPlexGetTransitiveClosure(b->dm, pts[i], PETSC_TRUE, &ncl, &cl));
      for (PetscInt m = 0; m < ncl; ++m)
        if (cl[2 * m] >= vStart && cl[2 * m] < vEnd && nf < 4) fv[nf++] = cl[2 * m];
      PetscCall(DMPlexRestoreTransitiveClosure(b->dm, pts[i], PETSC_TRUE, &ncl, &cl));
      for (PetscInt j = 0; j < 6; ++j) {
        PetscInt found = 0;
        for (PetscInt m = 0; m < 4; ++m)
          for (PetscInt n = 0; n < nf; ++n) found += v[HexFaces[j][m]] == fv[n];
        if (found == 4) topo[20 + j] = node[i];
      }
    }
  }
  for (PetscInt i = 0; i < nb; ++i) PetscCheck(topo[i] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell %" PetscInt_FMT ": its node %" PetscInt_FMT " in VTK's order not found", c, i);
  PetscFunctionReturn(0);
}

PetscErrorCode BodyCellOutputNodes(Body b, PetscInt c, PetscInt topo[])
{
  const PetscInt  nb = b->nb, *pts = &b->cpts[c * nb];
  PetscInt        depth[27], node[27];

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < nb; ++k) {
    PetscCall(BodyGetNodeNumber(b, pts[k], &node[k]));
    PetscCall(DMPlexGetPointDepth(b->dm, pts[k], &depth[k]));
  }
  if (b->dim == 3) PetscCall(CellNodes3D(b, c, depth, node, topo));
  else PetscCall(CellNodes2D(b, c, depth, node, topo));
  PetscFunctionReturn(0);
}
