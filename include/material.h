#pragma once
/* A body's material (-<body>_material NAME): its pointwise kernels of the
   displacement gradient, registered by name (material.c). The element loops
   of body.c and fields.c call them and nothing else of the material.

   Arguments: param = {lambda, mu} (Lame constants from E and nu); gu[i*2+j]
   = du_i/dX_j, the in-plane displacement gradient in the reference
   configuration; e3 the out-of-plane normal component: 0 in plane strain,
   u_r / r in axisymmetry (its limit du_r/dr on the axis), so that
   F = I + [gu 0; 0 e3]. Stresses are listed xx, xy, yx, yy (P[i*2+J]). */
#include <petscsys.h>

typedef struct {
  const char *name;
  /* the energy is quadratic in gu: its Hessian does not depend on u, and
     the stiffness is assembled and factored once per solve */
  PetscBool constantTangent;
  /* Energy density per unit reference volume W, the stress conjugate to gu
     (the first Piola-Kirchhoff P; linear: sigma) and to e3, P33. Returns
     PETSC_FALSE where the material is inverted (J <= 0): W is then +inf,
     P and P33 zero. */
  PetscBool (*energy)(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscReal *W, PetscReal P[], PetscReal *P33);
  /* The Cauchy stress (in-plane sigma[4], out-of-plane s33), in the current
     configuration, attached to the material point (for output). */
  void (*cauchy)(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscReal sigma[], PetscReal *s33);
  /* Adds one quadrature point's w d2W/du_a du_b into the element matrix
     K[2 nb][2 nb] (row-major), the blocks bb >= a only (body.c mirrors
     them): dN[a][2] the basis gradients, B[a] the basis values and r > 0
     the radius in axisymmetry, where e3 = u_r / r adds its terms (r = 0:
     plane strain). */
  /* The tangent A = d2W/dF dF at (gu, e3): A[((i*2+J)*2+k)*2+L] in-plane,
     a3[i*2+J] = A_iJ33, a33 = A_3333 (for a manufactured body force). */
  void (*moduli)(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscReal A[], PetscReal a3[], PetscReal *a33);
  void (*tangent)(const PetscReal param[], const PetscReal gu[], PetscReal e3, PetscInt nb, PetscReal w, const PetscReal dN[], const PetscReal B[], PetscReal r, PetscScalar K[]);
} Material;

extern const Material MaterialLinear, MaterialNeoHookean;
extern PetscFunctionList MaterialList;
PetscErrorCode MaterialRegisterAll(void);
/* The material named name, or NULL if none is. */
PetscErrorCode MaterialFind(const char name[], const Material **);
PetscErrorCode MaterialFinalize(void);
