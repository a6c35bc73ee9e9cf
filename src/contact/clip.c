/* The intersection of two convex polygons in a plane, and its triangles.

   Sutherland-Hodgman: the subject polygon P is clipped by each edge of the
   convex clip polygon C in turn. Both are made anticlockwise first (a
   master face projected on the slave's plane comes out clockwise, the two
   normals facing each other), so that the inside of C's edge a -> b is
   where s(x) = (b - a) x (x - a) >= 0. For each edge p -> q of the current
   polygon: q inside keeps q, and adds the crossing p + s_p/(s_p - s_q)
   (q - p) first if p was outside; q outside adds the crossing if p was
   inside. The intersection of two convex polygons is convex, with at most
   |P| + |C| vertices, so a fan from its first vertex triangulates it; a
   vertex repeated by a crossing at a vertex of C, and triangles thinner
   than a tolerance of the polygon's size, are dropped. Pieces that touch
   along an edge or a point (a master face beside the slave's) have zero
   area and give no triangle. */
#include "clip.h"

/* The signed area (shoelace) of the polygon of n points. */
PetscReal ClipSignedArea(PetscInt n, const PetscReal p[])
{
  PetscReal a = 0.0;
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt j = (i + 1) % n;
    a += p[2 * i] * p[2 * j + 1] - p[2 * j] * p[2 * i + 1];
  }
  return 0.5 * a;
}

static void ClipAnticlockwise(PetscInt n, const PetscReal in[], PetscReal out[])
{
  const PetscBool flip = (PetscBool)(ClipSignedArea(n, in) < 0);
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt k = flip ? n - 1 - i : i;
    out[2 * i]       = in[2 * k];
    out[2 * i + 1]   = in[2 * k + 1];
  }
}

/* P (np points) clipped by the convex C (nc points): the intersection's
   *nout points in out[] (anticlockwise; up to CLIP_MAX_VERTICES). */
PetscErrorCode ClipConvex(PetscInt np, const PetscReal P[], PetscInt nc, const PetscReal C[], PetscInt *nout, PetscReal out[])
{
  PetscReal a[2 * CLIP_MAX_VERTICES], b[2 * CLIP_MAX_VERTICES], c[2 * CLIP_MAX_VERTICES];
  PetscInt  na = np;

  PetscFunctionBeginUser;
  PetscCheck(np >= 3 && nc >= 3 && np + nc <= CLIP_MAX_VERTICES, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "clip of polygons of %" PetscInt_FMT " and %" PetscInt_FMT " vertices: each 3 or more, %d in all at most", np, nc, CLIP_MAX_VERTICES);
  ClipAnticlockwise(np, P, a);
  ClipAnticlockwise(nc, C, c);
  for (PetscInt e = 0; e < nc && na > 0; ++e) {
    const PetscReal *p0 = &c[2 * e], *p1 = &c[2 * ((e + 1) % nc)];
    const PetscReal  ex = p1[0] - p0[0], ey = p1[1] - p0[1];
    PetscInt         nb = 0;
    for (PetscInt i = 0; i < na; ++i) {
      const PetscReal *p = &a[2 * ((i + na - 1) % na)], *q = &a[2 * i];
      const PetscReal  sp = ex * (p[1] - p0[1]) - ey * (p[0] - p0[0]);
      const PetscReal  sq = ex * (q[1] - p0[1]) - ey * (q[0] - p0[0]);
      if ((sp >= 0) != (sq >= 0)) {
        const PetscReal f = sp / (sp - sq);
        b[2 * nb]         = p[0] + f * (q[0] - p[0]);
        b[2 * nb + 1]     = p[1] + f * (q[1] - p[1]);
        ++nb;
      }
      if (sq >= 0) {
        b[2 * nb]     = q[0];
        b[2 * nb + 1] = q[1];
        ++nb;
      }
    }
    PetscCheck(nb <= CLIP_MAX_VERTICES, PETSC_COMM_SELF, PETSC_ERR_PLIB, "clipped polygon of %" PetscInt_FMT " vertices: more than %d", nb, CLIP_MAX_VERTICES);
    for (PetscInt k = 0; k < 2 * nb; ++k) a[k] = b[k];
    na = nb;
  }
  *nout = na;
  for (PetscInt k = 0; k < 2 * na; ++k) out[k] = a[k];
  PetscFunctionReturn(0);
}

/* The fan of the convex polygon (n points) from its first vertex: the
   triangles tri[6 t] whose area exceeds tol (a fraction of the polygon's
   size squared chosen by the caller); returns how many. */
PetscInt ClipTriangulate(PetscInt n, const PetscReal p[], PetscReal tol, PetscReal tri[])
{
  PetscInt nt = 0;
  for (PetscInt i = 1; i + 1 < n; ++i) {
    const PetscReal v[6] = {p[0], p[1], p[2 * i], p[2 * i + 1], p[2 * i + 2], p[2 * i + 3]};
    if (ClipSignedArea(3, v) <= tol) continue;
    for (PetscInt k = 0; k < 6; ++k) tri[6 * nt + k] = v[k];
    ++nt;
  }
  return nt;
}
