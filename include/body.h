#pragma once
/* An elastic body (body.c): its life (create, options, mesh, set-up,
   destroy), its energy and stiffness, and the post-processing of a solution.
   body.c orchestrates the body's files below, whose headers this one
   gathers for the callers of the body. */
#include "bodycore.h"
#include "conditions.h"
#include "history.h"
#include "loads.h"
#include "rigid.h"
#include "rigidbody.h"

PetscErrorCode BodyCreate(MPI_Comm, const char name[], Body *);
PetscErrorCode BodySetFromOptions(Body, PetscReal meshSizeOverride);
/* The Gmsh size field (a .pos file) the body's next mesh follows; "" or NULL: none. */
PetscErrorCode BodySetSizeField(Body, const char path[]);
/* Meshes the body's .geo with Gmsh (cached in meshDir), unless the mesh would
   exceed *maxDofs (> 0), which its estimate is taken off (limit describes
   where the limit comes from); estimateOnly: the check alone, no meshing. */
PetscErrorCode BodyGenerateMesh(Body, const char meshDir[], PetscReal *maxDofs, const char limit[], PetscBool estimateOnly);
PetscErrorCode BodySetUp(Body, PetscInt partitioner, PetscBool partitionView);
PetscErrorCode BodyDestroy(Body *);
PetscReal      BodyElementGradients(PetscInt nb, const PetscReal x[][2], const PetscReal D[], PetscReal dNdx[]);
/* The same in dimension dim (2 or 3): x[nb][dim], D[nb][dim], dNdx[nb][dim]; det J. */
PetscReal      BodyElementGradientsDim(PetscInt dim, PetscInt nb, const PetscReal x[], const PetscReal D[], PetscReal dNdx[]);
/* Global node number of a node point (owned or ghost). */
PetscErrorCode BodyGetNodeNumber(Body, PetscInt point, PetscInt *node);
PetscErrorCode BodyGlobalToLocal(Body, Vec Xg, Vec Xl);
PetscErrorCode BodyComputeEnergyGradient(Body, Vec Xl, PetscReal *energy, Vec Gl);
/* Collective: how many energy evaluations found the body inverted (J <= 0
   at a quadrature point: +inf), and where one did (reference x, y). */
PetscErrorCode BodyGetInversions(Body, PetscInt *n, PetscReal xy[2]);
PetscErrorCode BodyAssembleHessian(Body, Mat H);
PetscErrorCode BodyAssembleHessianMapped(Body, const PetscInt map[], Mat H);
/* The tangent stiffness at the body's local vector Xl, added into H (l2b
   indices): the stiffness at rest for a material of constant tangent. */
PetscErrorCode BodyAssembleTangent(Body, Vec Xl, Mat H);
/* Yl = K(Xl) El, local vectors, K the tangent at Xl (NULL: at rest), this rank's cells' part. */
PetscErrorCode BodyApplyTangentLocal(Body, Vec Xl, Vec El, Vec Yl);
PetscErrorCode BodyComputeReactions(Body, Vec Gl);
/* A body's errors against its exact solution, if any (zero without one), with
   the exact solution's norms: L2 of u, energy norm, L2 of the stress. */
typedef struct {
  PetscReal l2, l2norm, energy, energynorm, stress, stressnorm;
} BodyErrors;
PetscErrorCode BodyComputeErrors(Body, Vec Xl, BodyErrors *);
/* Nodal fields for output (fields.c), from the body's local vector Xl:
   coords and disp of dim components, stress of BodyStressComponents(dim)
   (xx, yy, zz, xy; in 3D then yz, xz). */
#define BodyStressComponents(dim) ((dim) == 3 ? 6 : 4)
typedef struct {
  Vec       coords, disp, stress, vm;
  IS        topo;
  PetscInt  nnodes, ncells;
  PetscReal umax, unorm2;
  BodyErrors err; /* against the body's exact solution, if any */
  PetscReal maxStrain; /* the largest principal Green-Lagrange strain (BodyComputeMaxStrain) */
} BodyNodalFields;
PetscErrorCode BodyComputeNodalFields(Body, Vec Xl, BodyNodalFields *);
/* Cell c's nb global node numbers in the order of its XDMF / VTK cell type
   (cellorder.c): Triangle_6, Quadrilateral_9, Tetrahedron_10, Hexahedron_27. */
PetscErrorCode BodyCellOutputNodes(Body, PetscInt c, PetscInt topo[]);
PetscErrorCode BodyNodalFieldsDestroy(BodyNodalFields *);
/* Collective: the largest principal Green-Lagrange strain, in magnitude,
   over the body's quadrature points (fields.c). */
PetscErrorCode BodyComputeMaxStrain(Body, Vec Xl, PetscReal *emax);
/* Collective: the largest strain (as above), where it is (a quadrature
   point's reference position x), its cell's size h, and the largest strain
   between BODY_STRAIN_RING / 2 and BODY_STRAIN_RING h from x (ring); below
   BODY_STRAIN_POINT times the peak, the peak is a singular point's
   (fields.c derives both). */
#define BODY_STRAIN_RING  4.0
#define BODY_STRAIN_POINT 0.8
typedef struct {
  PetscReal emax, x[3], h, ring;
} BodyStrainPeak;
PetscErrorCode BodyComputeStrainPeak(Body, Vec Xl, BodyStrainPeak *);
/* Zienkiewicz-Zhu error indicator of each local cell (fields.c): the L2 norm
   of the recovered (nodal-average) stress minus the cell's stress. */
PetscErrorCode BodyComputeStressIndicator(Body, Vec Xl, PetscReal eta[]);
