#pragma once
/* A body's material (-<body>_material NAME): its pointwise kernels of the
   displacement gradient, registered by name (material.c). The element loop
   (element.c) calls them and nothing else of the material.

   Arguments: param, the material's own parameters (setFromOptions reads
   them: {lambda, mu}, Lame's constants from E and nu, for linear and
   neohookean; {C10, C01, D1} for mooneyrivlin); H[i*3+J]
   = du_i/dX_J, the full 3 x 3 displacement gradient in the reference
   configuration, F = I + H. In 3D H is full; in plane strain its row and
   column 2 are zero; in axisymmetry (x = r, y = z, 2 = theta) they are zero
   but for H[8] = u_r / r, the hoop strain (its limit du_r/dr on the axis,
   ElasticityHoopStrain). One kernel serves the three. Tensors are listed
   row-major: P[i*3+J], sigma[i*3+j], A[(i*3+J)*9 + k*3+L].

   A material with history (nstate > 0: plastic) keeps nstate values at
   each quadrature point, the state of the last accepted (converged) load
   increment, which its kernels take as state[] (NULL for a material
   without: nstate = 0; NULL too for the stiffness at rest, which is the
   virgin state's: every value 0). Its energy is then an incremental
   potential of H for that state (the increment's stored energy plus its
   dissipation, minimised over the internal variables), so that the solver
   minimises it as it minimises friction's; update gives the new state at a
   converged H, which the body (bodystate.c) makes the accepted one. The
   state at rest is zero. */
#include <petscsys.h>

#define MATERIAL_MAX_PARAMS 8
#define MATERIAL_MAX_STATE  8

typedef struct {
  const char *name;
  /* Reads the material's options (prefix: "<body>_", each option with its
     help and default in its own options block) into param, and gives its
     small-strain Young's modulus E and Poisson's ratio nu at rest, which
     the contact's E*, the penalty's scale, force control's reference
     stiffness and the reports use. help: list the options only (nothing
     is required). */
  PetscErrorCode (*setFromOptions)(MPI_Comm comm, const char prefix[], PetscBool help, PetscReal param[], PetscReal *E, PetscReal *nu);
  /* the energy is quadratic in H: its Hessian does not depend on u, and
     the stiffness is assembled and factored once per solve */
  PetscBool constantTangent;
  /* Energy density per unit reference volume W and the stress conjugate to
     H, the first Piola-Kirchhoff P = dW/dF (linear: sigma). Returns
     PETSC_FALSE where the material is inverted (J <= 0): W is then +inf
     and P zero. */
  PetscBool (*energy)(const PetscReal param[], const PetscReal state[], const PetscReal H[9], PetscReal *W, PetscReal P[9]);
  /* The tangent A_iJkL = d2W/dF_iJ dF_kL at H (A[(i*3+J)*9+k*3+L]). */
  void (*moduli)(const PetscReal param[], const PetscReal state[], const PetscReal H[9], PetscReal A[81]);
  /* The Cauchy stress sigma[i*3+j], in the current configuration, attached
     to the material point (for output; NaN where J <= 0). */
  void (*cauchy)(const PetscReal param[], const PetscReal state[], const PetscReal H[9], PetscReal sigma[9]);
  /* State values per quadrature point (0: none, a hyperelastic material),
     at most MATERIAL_MAX_STATE */
  PetscInt nstate;
  /* The state after an increment converged at H from the accepted state
     state (NULL where nstate = 0). */
  void (*update)(const PetscReal param[], const PetscReal state[], const PetscReal H[9], PetscReal stateNew[]);
} Material;

extern const Material MaterialLinear, MaterialNeoHookean, MaterialMooneyRivlin, MaterialPlastic;
/* Linear elasticity's and the neo-Hookean's options: -E and -nu, both
   required, checked (E > 0 finite, -1 < nu < 0.5, a warning from 0.45 on),
   into param = {lambda, mu} (elasticity.c). */
PetscErrorCode MaterialElasticConstantsSetFromOptions(MPI_Comm, const char prefix[], PetscBool help, PetscReal param[], PetscReal *E, PetscReal *nu);
extern PetscFunctionList MaterialList;
PetscErrorCode MaterialRegisterAll(void);
/* The material named name, or NULL if none is. */
PetscErrorCode MaterialFind(const char name[], const Material **);
PetscErrorCode MaterialFinalize(void);
