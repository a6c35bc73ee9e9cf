#pragma once
#include "segment3d.h"
#include "surface3d.h"
#include "support.h"

/* Coulomb friction on the slave surface of a 3D mortar pair (friction3d.c;
   derivation there): 2D's tangential penalty and return map (friction.c)
   with the slip a vector in the plane of each slave node, the normal
   pressure lagged and iterated to a fixed point within each load increment,
   and the state of the last accepted increment. The pairing of slave and
   master comes from the pair's segments (Segment3dPoint), the pressure and
   the nodal weights from its weighted gaps (mortar3d.c). */
typedef struct _n_Friction3d *Friction3d;

/* mu > 0, the tangential penalty k_t = ktScale k_p (the callers' kp: the scene's, not continued). */
PetscErrorCode Friction3dCreate(MPI_Comm, PetscReal mu, PetscReal ktScale, Friction3d *);
PetscErrorCode Friction3dDestroy(Friction3d *);
/* The surfaces S (set up), s the slave. */
PetscErrorCode Friction3dSetUp(Friction3d, const ContactSurface3d S[2], PetscInt s);
/* The lag, in four calls: Begin with the slave's nodal pressures p_j
   (every rank alike; NULL: the bound kept, the rows rebuilt), Face for
   each of this rank's slave faces f with its dual coefficients, the master
   faces mf[nm] it met and its points (their eta the closest points at the
   current coordinates), Exchange (collective) to gather every rank's, End
   with the covered weights C_j; change: the largest change of the bound
   mu p_j against mu p_max. */
PetscErrorCode Friction3dLagBegin(Friction3d, const PetscReal p[]);
PetscErrorCode Friction3dLagFace(Friction3d, const ContactSurface3d S[2], PetscInt f, const PetscReal Adual[], PetscInt nm, const PetscInt mf[], PetscInt np, const Segment3dPoint pts[]);
PetscErrorCode Friction3dLagExchange(Friction3d);
PetscErrorCode Friction3dLagEnd(Friction3d, const PetscReal A[], const PetscReal C[], PetscReal *change);
/* This rank's nodes' energy, and their gradient into S[*].g, at the surfaces' current coordinates. */
PetscErrorCode Friction3dAddEnergyGradient(Friction3d, ContactSurface3d S[2], PetscReal kp, PetscReal *energy);
/* This rank's nodes' Hessian blocks into H (joined indices; constrained dofs left out). */
PetscErrorCode Friction3dAddHessian(Friction3d, const ContactSurface3d S[2], PetscReal kp, Mat H);
/* A block over joined indices (a rigid body's components as codes below -1, rigiddof.h). */
typedef PetscErrorCode (*Friction3dBlockFn)(void *ctx, PetscInt n, const PetscInt idx[], const PetscScalar K[]);
/* fn(ctx, ...) is given each Hessian block too, with a rigid body's codes (its unknowns' border). */
PetscErrorCode Friction3dSetRigidBlock(Friction3d, Friction3dBlockFn fn, void *ctx);
/* The lifecycle, as friction.h's: record a converged increment (load: the
   load parameter; a stage's end where whole), make it the accepted state as
   the next begins, restore the bound of the accepted one, reset to rest. */
PetscErrorCode Friction3dAccept(Friction3d, const ContactSurface3d S[2], PetscReal kp, PetscReal load);
PetscErrorCode Friction3dBegin(Friction3d);
/* A tied pair's (Friction3dChooseStart) next increment starts from the accepted bound times growth. */
PetscErrorCode Friction3dScaleBound(Friction3d, PetscReal growth);
PetscErrorCode Friction3dRestore(Friction3d);
PetscErrorCode Friction3dReset(Friction3d, const ContactSurface3d S[2]);
PetscReal      Friction3dGetCoefficient(Friction3d);
/* The last converged increment's stick zone: the stuck nodes' area (sum A_j)
   and the radius of a disc of that area. */
PetscErrorCode Friction3dStickZone(Friction3d, PetscReal *area, PetscReal *radius);
/* That radius at the end of stage k (1..); has: recorded. */
PetscErrorCode Friction3dGetStage(Friction3d, PetscInt k, PetscReal *radius, PetscBool *has);
/* The last converged increment's nodal sets (every rank alike; shear and
   slip [nn][3], stick [nn]), or those at the end of stage k >= 1 (NULL
   where not recorded); nstage: the stages recorded. */
PetscErrorCode Friction3dGetNodal(Friction3d, PetscInt k, const PetscReal **shear, const PetscReal **slip, const PetscReal **stick, PetscInt *nstage);
/* The shear's force on the slave's body (the last converged increment). */
PetscErrorCode Friction3dShearForce(Friction3d, PetscReal F[3]);
/* At the surfaces' current coordinates: the nodes that carry a bound, those of them that stick, the largest trial slip. */
PetscErrorCode Friction3dSlipState(Friction3d, const ContactSurface3d S[2], PetscReal kp, PetscInt *stuck, PetscInt *loaded, PetscReal *slip);
/* Collective, after Friction3dSetUp, before solving: a body held by this
   frictional pair alone against a flat partner (body[2] the surfaces'),
   given forces alone (rollers normal to the partner's plane allowed), whose
   tangential force exceeds mu times its normal one at some stage, is one
   line naming the pair, the body, the stage and the forces (status 1). */
PetscErrorCode Friction3dCheckGivenForces(Friction3d, const char pair[], const Body body[2]);
/* Collective, after Friction3dSetUp: whether an increment from rest starts
   tied (a body held along the contact by friction alone: friction3d.c). */
PetscErrorCode Friction3dChooseStart(Friction3d, const Body body[2]);
/* Tied at rest with no rows yet: the caller lags the rows (a NULL pressure)
   at the state it evaluates first. */
PetscBool      Friction3dRowsPending(Friction3d);
