/* The reach of a 3D contact along a force-controlled direction: a bound on
   the Newton step of coupled force control (forceborder.c's cap) where the
   body's own size is far too much.

   A 3D body pressed by a force from a point contact (a ball on a block) has
   no normal stiffness at rest: the contact touches at one point, so the
   stiffness the control feels through the scene, S = dR/dU, is zero to
   round-off, and the step in U is only held by its cap,
   -force_control_step times the body's size (0.3 of it). A 3D contact
   surface is a part of the body's boundary near the contact (a ball's cap,
   z <= zc), and a step that moves it by more than its own depth along the
   control plus its partner's carries it through its partner entirely:
   there the search pairs nothing, the energy is -F U again and lower than
   at any state in contact, and the line search fails
   (DIVERGED_LS_FAILURE at the first Newton step, measured on the half ball
   of tests/test_forceball3d.py: step 0.47 against a cap surface 0.05 deep).
   So in 3D the step in U_k is also held to

       reach_k = max over the pairs of body k (d_own + d_partner),

   d the depth of a surface along the control's component (the extent of
   its reference nodes' coordinate c), and at least 1e-2 of the body's size.
   Within it the surface stays in its partner's range and the line search
   finds where the contact takes the force (the energy falls like -F U
   until it does). A body starting apart from its partner closes the gap by
   steps of at most the reach. Two faces flat across the control (both
   depths 0) keep the cap alone: they touch along a face, which has its
   normal stiffness from the first contact. 2D keeps its cap (its scenes'
   surfaces are whole sides). */
#include "forcereach.h"
#include "bodyfaces.h"
#include "energyterm.h"
#include "controls.h"

/* Collective: the extent of body b's group along component c (reference
   coordinates; 0 for a body without cells, a rigid one). */
static PetscErrorCode GroupDepth(MPI_Comm comm, Body b, const char group[], PetscInt c, PetscReal *depth)
{
  BodyFaces F;
  PetscInt  tag;
  PetscReal lo = PETSC_MAX_REAL, hi = PETSC_MIN_REAL, mm[2];

  PetscFunctionBeginUser;
  *depth = 0.0;
  if (!BodyHasCells(b)) PetscFunctionReturn(0);
  PetscCall(BodyGetGroupFaces(b, group, "force control", &tag, &F));
  for (PetscInt i = 0; i < F.n * F.nb; ++i) {
    lo = PetscMin(lo, F.X[3 * i + c]);
    hi = PetscMax(hi, F.X[3 * i + c]);
  }
  PetscCall(BodyFacesDestroy(&F));
  mm[0] = -lo;
  mm[1] = hi;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, mm, 2, MPIU_REAL, MPIU_MAX, comm));
  if (mm[1] >= -mm[0]) *depth = mm[1] + mm[0];
  PetscFunctionReturn(0);
}

PetscErrorCode ForceControlContactReach(Problem p, PetscInt k, PetscReal *reach)
{
  const ForceControl *fc = &p->fc.c[k];
  Body                b  = p->bodies[fc->body];
  PetscInt            axis;

  PetscFunctionBeginUser;
  *reach = 0.0;
  if (BodyGetDimension(b) != 3 || fc->motion || fc->anchor) PetscFunctionReturn(0);
  axis = BodyGetCondition(b, fc->bc)->comps[fc->c]; /* c indexes the condition's components */
  for (PetscInt t = 0; t < p->nterms; ++t) {
    const EnergyTerm term = p->terms[t];
    PetscReal        d[2];
    if (term->body[0] != fc->body && term->body[1] != fc->body) continue;
    for (PetscInt s = 0; s < 2; ++s) PetscCall(GroupDepth(p->comm, p->bodies[term->body[s]], term->group[s], axis, &d[s]));
    PetscCall(PetscInfo(NULL, "force control %" PetscInt_FMT ": pair %s's surfaces %g and %g deep along %s\n", k, term->name, (double)d[0], (double)d[1], BodyGetControlComponent(b, fc->bc, fc->c)));
    *reach = PetscMax(*reach, d[0] + d[1]);
  }
  if (*reach > 0.0) *reach = PetscMax(*reach, 1e-2 * fc->L);
  PetscFunctionReturn(0);
}
