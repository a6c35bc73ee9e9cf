/* Axisymmetric bodies (-axisymmetric): x is the radius r >= 0, y the axis
   z, and the mesh is a meridian section. Every volume integral carries
   2 pi r (BodyRadialWeight: the cell quadrature's weights, the loads', the
   contact's), and the strain gains the hoop component u_r / r
   (elasticity.c).

   On the axis a point does not move radially: u_r = 0 there, or the hoop
   strain u_r / r would be infinite. So the points on the axis (the vertices
   at x = 0, up to 1e-10 of the body's size, and the edges between two of
   them) get a Dirichlet condition of their own, u_r = 0, named "r=0". A
   scene need not declare it; where a scene's own condition already holds
   u_r on the axis, it must hold it at 0, and that point is left to it. A
   node at x < 0 is not in the meridian half-plane: refused. */
#include "axis.h"
#include "conditions.h"
#include "bodyimpl.h"

PetscErrorCode BodyAddAxis(Body b)
{
  DMLabel   label;
  PetscInt  vs, ve, es, ee, n = 0, gn, moves = -1;
  PetscReal lo[2], hi[2], size, *xy;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(b->dm, 0, &vs, &ve));
  PetscCall(BodyVertexCoordinates(b, &xy));
  PetscCall(BodyPointsBox(b, ve - vs, xy, lo, hi));
  size       = PetscMax(hi[0] - lo[0], hi[1] - lo[1]);
  b->axisTol = 1e-10 * (size > 0 ? size : 1.0);
  PetscCheck(lo[0] >= -b->axisTol, b->comm, PETSC_ERR_USER_INPUT, "body %s: mesh %s has a vertex at x = %g: under -axisymmetric x is the radius, so a body lies in x >= 0 (its axis at x = 0)", b->name, b->msh, (double)lo[0]);
  PetscCall(DMPlexGetDepthStratum(b->dm, 1, &es, &ee));
  PetscCall(DMCreateLabel(b->dm, "r=0"));
  PetscCall(DMGetLabel(b->dm, "r=0", &label));
  for (PetscInt p = vs; p < ee; ++p) {
    PetscBool on = PETSC_TRUE;
    PetscInt  i, k;
    if (p < ve) on = (PetscBool)(PetscAbsReal(xy[2 * (p - vs)]) <= b->axisTol);
    else if (p >= es) {
      const PetscInt *cone;
      PetscCall(DMPlexGetCone(b->dm, p, &cone));
      for (PetscInt j = 0; j < 2; ++j) on = (PetscBool)(on && PetscAbsReal(xy[2 * (cone[j] - vs)]) <= b->axisTol);
    } else on = PETSC_FALSE;
    if (!on) continue;
    PetscCall(BodyBCHolding(b, p, 0, &i, &k));
    if (i >= 0) { /* the scene's own condition holds u_r here: at 0, and by itself */
      if (b->bc[i].control[k] || b->bc[i].exact || b->bc[i].values[k] != 0.0) moves = PetscMax(moves, 2 * i + k);
      continue;
    }
    PetscCall(DMLabelSetValue(label, p, 1));
    n++;
  }
  PetscCall(PetscFree(xy));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &moves, 1, MPIU_INT, MPI_MAX, b->comm)); /* 2 i + k of a condition i moving component k there: every rank stops */
  PetscCheck(moves < 0, b->comm, PETSC_ERR_USER_INPUT, "body %s: Dirichlet group %s moves points on the axis radially (u_r = %g): on the axis u_r = 0", b->name, b->bc[moves / 2].group, (double)b->bc[moves / 2].values[moves % 2]);
  PetscCall(MPIU_Allreduce(&n, &gn, 1, MPIU_INT, MPI_SUM, b->comm));
  if (!gn) { /* no point on the axis (a ring), or the scene holds them all */
    PetscCall(DMRemoveLabel(b->dm, "r=0", NULL));
    PetscFunctionReturn(0);
  }
  {
    const BodyBC axis = {.group = "r=0", .ncomp = 1, .comps = {0}, .label = label};
    PetscCall(BodyAddDirichlet(b, &axis));
  }
  PetscCall(PetscInfo(NULL, "body %s: u_r = 0 held on %" PetscInt_FMT " points on the axis\n", b->name, gn));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyCheckAxis(Body b)
{
  PetscReal xmin = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < b->ncells * b->nb; ++k) xmin = PetscMin(xmin, b->xnode[2 * k]);
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &xmin, 1, MPIU_REAL, MPIU_MIN, b->comm));
  PetscCheck(xmin >= -b->axisTol, b->comm, PETSC_ERR_USER_INPUT, "body %s: mesh %s has a node at x = %g (a curved edge's mid-node): under -axisymmetric a body lies in x >= 0", b->name, b->msh, (double)xmin);
  PetscFunctionReturn(0);
}
