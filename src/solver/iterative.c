/* Newton steps by an iterative solver, for problems whose factorisation no
   longer fits in memory: conjugate gradients on the Hessian H = K + C,
   preconditioned by aggregation algebraic multigrid (PCGAMG).
   Elasticity needs the multigrid's coarse spaces to represent the rigid
   motions, which the stiffness of a body free of its Dirichlet conditions
   annihilates: they are given as H's near-nullspace, three per 2D body
   (translations in x and y, rotation; six per 3D body: three translations,
   three rotations), each supported on its own body's
   dofs, orthonormalised. The contact Hessian couples the bodies only through
   their surfaces, a low-rank change GAMG sees in its matrix. Each Newton step
   is solved to -tao_nls_ksp_rtol (1e-6 by default, relative to the gradient):
   Newton's convergence is then quadratic down to that level and linear with
   factor 1e-6 below it, so -tao_gttol 1e-8 is met in a step or two more than
   with the exact step. GAMG is set up again at every step, its
   interpolation too (PCGAMG's default reuses the first step's, built without
   contact, and the preconditioner turns indefinite once the penalty acts),
   except where H does not change (no contact term, the bodies' stiffness
   at rest): then its first set-up serves every step and stage (on the Hex27
   block of 89k dofs, under load, GAMG's set-up took 9 s a step, its 13 CG
   iterations 2.4 s).
   In 3D the aggregation is unsmoothed (-pc_gamg_agg_nsmooths 0): a
   quadratic 3D cell couples each node to up to 125 others, so that the
   smoothed prolongator's Galerkin product A P is most of the set-up; without
   it the set-up is several times cheaper for some 40 % more CG
   iterations (on the Hex27 block of 108k dofs, one rank: 6.8 s against
   10.2 s for the solve, 28 against 18 iterations; bench/solid3d/RESULTS.md).
   Where H is constant the problem is linear and Newton's first step is its
   answer: solved to 1e-9 in place of 1e-6, it meets -tao_gttol 1e-8 in one
   step, with no second solve to restart CG from (Lame's octant, 79k dofs:
   53 CG iterations in one step against 73 in two, solve 4.2 s against 5.0 s).
   The Gauss-Newton contact Hessian is symmetric positive semi-definite, so
   CG applies; the exact one, which auto adds only once the gradient is
   small, leaves H positive definite there. */
#include "iterative.h"

PetscErrorCode ContactIterativeKSPSetUp(KSP ksp, Mat H, PetscInt nbodies, Body bodies[], PetscBool constant)
{
  Vec          modes[6 * CONTACT_MAX_BODIES];
  PetscInt     n = 0, rstart, rend, dim = 2;
  MatNullSpace nsp;
  PC           pc;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(H, &rstart, &rend));
  for (PetscInt i = 0; i < nbodies; ++i) {
    Vec          v[6];
    PetscScalar *a[6];
    PetscInt     first = n, nm;

    nm = BodyGetNumRigidModes(bodies[i]);
    if (!nm) continue; /* no dofs (a rigid body): its motion is the border's (forceborder.c) */
    dim = BodyGetDimension(bodies[i]);
    for (PetscInt k = 0; k < nm; ++k) {
      PetscCall(MatCreateVecs(H, &v[k], NULL));
      PetscCall(VecZeroEntries(v[k]));
      PetscCall(VecGetArray(v[k], &a[k]));
    }
    PetscCall(BodyAddRigidModes(bodies[i], rstart, rend, a));
    for (PetscInt k = 0; k < nm; ++k) PetscCall(VecRestoreArray(v[k], &a[k]));
    for (PetscInt k = 0; k < nm; ++k) { /* Gram-Schmidt within the body (bodies' modes are disjoint) */
      PetscReal norm;
      for (PetscInt j = first; j < n; ++j) {
        PetscScalar d;
        PetscCall(VecDot(v[k], modes[j], &d));
        PetscCall(VecAXPY(v[k], -d, modes[j]));
      }
      PetscCall(VecNorm(v[k], NORM_2, &norm));
      if (norm == 0.0) { /* a body without free dofs on the whole problem */
        PetscCall(VecDestroy(&v[k]));
        continue;
      }
      PetscCall(VecScale(v[k], 1.0 / norm));
      modes[n++] = v[k];
    }
  }
  PetscCall(MatNullSpaceCreate(PetscObjectComm((PetscObject)H), PETSC_FALSE, n, modes, &nsp));
  PetscCall(MatSetNearNullSpace(H, nsp));
  PetscCall(MatNullSpaceDestroy(&nsp));
  for (PetscInt k = 0; k < n; ++k) PetscCall(VecDestroy(&modes[k]));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetTolerances(ksp, constant ? 1e-9 : 1e-6, PETSC_DEFAULT, PETSC_DEFAULT, 10000));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCGAMG));
  PetscCall(PCGAMGSetReuseInterpolation(pc, PETSC_FALSE));
  if (dim == 3) PetscCall(PCGAMGSetNSmooths(pc, 0));
  PetscCall(KSPSetReusePreconditioner(ksp, constant));
  PetscFunctionReturn(0);
}
