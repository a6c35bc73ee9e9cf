#pragma once
#include "configtypes.h"
#include "contactterm.h"

/* Coulomb friction on a mortar pair's slave surface (friction.c; derivation
   there): a tangential penalty with a return map written as a convex C1
   incremental potential per slave node, the normal pressure lagged and
   iterated to a fixed point within each load increment, and the state of
   the last accepted increment (elastic slip, accumulated slip, stick). The
   pairing of slave and master comes from the formulation's quadrature
   points (FrictionPoint), the pressure and the nodal weights from its
   weighted gaps: friction reuses them, it segments nothing itself. */
typedef struct _n_Friction *Friction;

/* One quadrature point of the slave surface as the formulation integrates
   it: slave edge se and its shape functions N, the weights W of the nodal
   gaps, the weight wt (with the reference measure), and the master edge me
   (-1: none, or not a point of the master surface itself) with the master
   shape functions M7 of its closest point (nodes M->mnodes[7 me + k]). */
typedef struct {
  PetscInt  se, me;
  PetscReal N[3], W[3], wt, M7[7], dM7[7];
} FrictionPoint;

/* mu > 0, the tangential penalty k_t = ktScale k_p (k_p the scene's penalty of the pair, not continued: the callers' kp). */
PetscErrorCode FrictionCreate(MPI_Comm, PetscReal mu, PetscReal ktScale, Friction *);
PetscErrorCode FrictionDestroy(Friction *);
/* The slave surface s of the pair's surfaces S (after their set-up). */
PetscErrorCode FrictionSetUp(Friction, const ContactSurface S[2], PetscInt slave);
/* Collective: the lag of the fixed point at the surfaces' current
   coordinates: each rank's points (np of them), the nodal weights A_j and
   C_j (cover) and the nodal pressures p_j of the slave surface (every rank
   alike; NULL: the bound kept, the rows rebuilt); change: the largest change of the bound mu p_j against mu p_max. */
PetscErrorCode FrictionLag(Friction, const ContactSurface S[2], PetscInt np, const FrictionPoint pts[], const PetscReal A[], const PetscReal cover[], const PetscReal p[], PetscReal *change);
/* This rank's part of the energy, and of the gradient into S[*].g (not yet summed over ranks), at the surfaces' current coordinates. */
PetscErrorCode FrictionAddEnergyGradient(Friction, ContactSurface S[2], PetscReal kp, PetscReal *energy);
/* This rank's nodes' Hessian blocks into H. */
PetscErrorCode FrictionAddHessian(Friction, const ContactTerm *, PetscReal kp, Mat H);
/* The converged increment's state (at the surfaces' current coordinates) is
   recorded, to become the accepted one when the next increment begins
   (FrictionBegin); load: the load parameter reached (a stage's end where it
   is a whole number: its stick half-width is kept). */
PetscErrorCode FrictionAccept(Friction, const ContactSurface S[2], PetscReal kp, PetscReal load);
/* An increment begins: the last recorded state becomes the accepted one. */
PetscErrorCode FrictionBegin(Friction);
/* Back to the last accepted state (a cut-back or a trial). */
PetscErrorCode FrictionRestore(Friction);
/* Back to rest: no slip, no pressure, the reference coordinates. */
PetscErrorCode FrictionReset(Friction, const ContactSurface S[2]);
/* An increment from rest starts tied: its rows built at the first state
   evaluated (FrictionRowsPending: the caller then lags with no pressures). */
PetscErrorCode FrictionSetTieAtRest(Friction, const ContactSurface S[2]);
PetscBool      FrictionRowsPending(Friction);
/* A tied pair's next increments start from the accepted bound times growth (the given forces'). */
PetscErrorCode FrictionScaleBound(Friction, PetscReal growth);
/* The last converged increment's stick zone half-width (its ends between
   nodes where the shear reaches Coulomb's bound; r-z: its radius), and the
   number of stage ends recorded with the half-width at each. */
PetscErrorCode FrictionStickHalfWidth(Friction, PetscReal *c);
PetscErrorCode FrictionGetStages(Friction, PetscInt *n, const PetscReal **c);
/* The friction coefficient. */
PetscReal FrictionGetCoefficient(Friction);
/* The last converged increment's shear q_j of each slave node (per unit of
   the slave's reference measure; the slave's traction is -q_j tau_j). */
const PetscReal *FrictionGetShear(Friction);
/* Collective: node_shear, node_slip and node_stick of the slave's nodes
   with a weight (A[j] > 0), sorted by arc position as the report's nodal
   sets, into the viewer's current group. */
PetscErrorCode FrictionWriteHDF5(Friction, const PetscReal A[], PetscViewer);
/* Collective: the same sets at the end of load stage k (1..FrictionGetStages' n). */
PetscErrorCode FrictionWriteStageHDF5(Friction, PetscInt k, const PetscReal A[], PetscViewer);
/* The last converged increment's friction force on the slave's body,
   -sum_j A_j q_j f_j tau_j, f_j the sum of the slave entries of b_j: 1
   (the shape functions sum to 1 and W_j / C_j integrates to 1) but where
   part of node j's points lie past an end of the master, which has no
   material point there to slip against and no entry (a block slid past its
   partner's end: 1.2 % of the shear force there, which then did not
   balance the reactions). */
PetscErrorCode FrictionShearForce(Friction, PetscReal F[2]);
/* At the surfaces' current coordinates, within the increment: the nodes
   that carry a bound (in contact at the lag) and those of them that stick. */
PetscErrorCode FrictionCountStuck(Friction, const ContactSurface S[2], PetscReal kp, PetscInt *stuck, PetscInt *loaded);
/* The same, and the largest trial slip |e_j| of the nodes that carry a bound. */
PetscErrorCode FrictionSlipState(Friction, const ContactSurface S[2], PetscReal kp, PetscInt *stuck, PetscInt *loaded, PetscReal *slip);
/* -contact_friction_lag_* ("Friction lag options"; FrictionLagOptions: configtypes.h). */
PetscErrorCode FrictionLagOptionsSetFromOptions(MPI_Comm, FrictionLagOptions *);
