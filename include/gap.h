#pragma once
#include "search.h"

/* The normal gap of a slave point against the master surface, and its first
   and second derivatives with respect to the 20 dofs it depends on: the slave
   edge's 3 nodes and the master edge's 7 (gap.c; derivation there). Shared by
   every formulation. */
typedef struct {
  PetscInt  me;  /* master edge (-1 only for an empty master surface) */
  PetscReal eta; /* closest point on it; beyond +-1 on the straight extension past an end of the surface */
  PetscReal M7[7], dM7[7], d2M7[7], xm[2], tm[2], xpp[2], tn, n[2], gap;
  PetscBool fan; /* the closest point is a corner node: g is the distance to it */
  PetscBool ext; /* the point is past an end of the master surface: g = d . n1 + kappa s(eps), and n = dg/dx_s = n1 + kappa s' t_out is not a unit vector (gap.c, ContactGapBeyondEnd) */
  PetscBool ramp; /* ext: within the lift's quadratic start (0 < eps < h0 past a turning end; ContactGapRampLength), where g'' jumps at both ends */
  PetscReal en[2], et[2], ev[2], eq, egt, es2, edp, je, delta; /* ext: the end's outward normal n1 and unit tangent tau, v, q = d . v, d . m, kappa s'', d . tau_p, the end (+-1), the master rows' tangent factor (ContactGapBeyondEnd) */
  PetscBool mirror; /* the closest point is on the master's mirror image (a half model): n, x_m are those of the reflected slave point */
  PetscReal ns[2];  /* the normal as seen by the slave point: n, reflected where mirror (the slave rows of dg) */
} ContactGap;

/* Closest point of the master surface to the slave point xs, its outward
   normal n and the gap g = (xs - x_m) . n. */
void ContactGapProject(const ContactSurface *M, ContactSearch, const PetscReal xs[2], ContactGap *);
/* The same against master edge e alone (its closest point to xs), or its mirror image. */
void ContactGapOnEdge(const ContactSurface *M, PetscInt e, PetscBool mirror, const PetscReal xs[2], ContactGap *);
/* Whether end j (0: eta = -1, 1: eta = +1) of master edge e is blended into its neighbour (no corner there). */
PetscBool ContactGapEndBlended(const ContactSurface *M, PetscInt e, PetscInt j);
/* The length h0 of the lift's quadratic start past end j (0: eta = -1, 1:
   +1) of master edge e, an end of the surface: 0 where the boundary goes on
   smoothly (no lift), so that no cut is needed there. */
PetscReal ContactGapRampLength(const ContactSurface *M, PetscInt e, PetscInt j);
/* w = -dg/dx_j of master node j (M->mnodes[7 me + j]): M_j n, and past an
   end the turn of the end's normal with its tangent. */
void ContactGapMasterWeight(const ContactGap *, PetscInt j, PetscReal w[2]);
/* The indices in the joined vector of the 20 dofs: slave edge sn's nodes, then the master edge's. */
void ContactGapIndices(const ContactSurface *S, const PetscInt sn[3], const ContactSurface *M, const ContactGap *, PetscInt idx[20]);
/* dg over the 20 dofs, with N the slave edge's shape functions at the point. */
void ContactGapFirst(const ContactGap *, const PetscReal N[3], PetscReal dg[20]);
/* K += c d2g. */
void ContactGapAddSecond(const ContactGap *, const PetscReal N[3], PetscReal c, PetscScalar K[400]);
