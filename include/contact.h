#pragma once
/* Shared types of the contact solver: one Body per elastic body, a Problem that
   joins the bodies (and later contact terms) into one TAO unknown. */
#include <petscdmplex.h>
#include <petsctao.h>
#include <petscsf.h>

#define CONTACT_MAX_BODIES 8
#define CONTACT_MAX_BC     8
#define CONTACT_MAX_STAGES 64 /* -load_stages: the most stages of a load history */
#define CONTACT_NAME_LEN   64
/* Peak memory per dof of a run on one rank (measured: 3.5 GB at 1.07e6 dofs) */
#define CONTACT_BYTES_PER_DOF 3.5e3

/* Log stages and events, registered once in ContactInitializeLogging(). */
typedef struct {
  PetscLogStage mesh, setup, solve, postprocess, output;
  PetscLogEvent elasEnergyGrad, elasHessian, meshGenerate, partition, writeOutput;
} ContactLog;
extern ContactLog contactLog;
PetscErrorCode ContactInitializeLogging(void);
/* mkdir -p; returns 0 or errno (meshgen.c). */
int ContactMakeDirs(const char dir[]);
/* A real in JSON: null for NaN and Inf (json.c). */
void ContactJSONReal(FILE *fp, PetscReal v);
/* sep "key": v, and sep "key": [v0, v1] (json.c). */
void ContactJSONKeyReal(FILE *fp, const char sep[], const char key[], PetscReal v);
/* key: [v0, ..., v(n-1)] */
void ContactJSONKeyVector(FILE *, const char sep[], const char key[], PetscInt n, const PetscReal v[]);
void ContactJSONKeyPair(FILE *fp, const char sep[], const char key[], const PetscReal v[2]);

/* Pointwise elasticity kernels (elasticity.c): params = {lambda, mu}, H the
   3 x 3 displacement gradient (material.h: row and column 2 zero in plane
   strain, H[8] the hoop strain in axisymmetry). */
void ElasticityEnergyDensity(const PetscReal params[], const PetscReal H[], PetscReal *W);
void ElasticityStress(const PetscReal params[], const PetscReal H[], PetscReal sigma[]);
void ElasticityTangent(const PetscReal params[], PetscReal C[]);
/* The strain's components e = {xx, yy, zz, xy, xz, yz} of H, and its
   trace; the energy density and stress of a strain e (an elastic strain:
   plasticity.c), the same sums as of H's. */
PetscReal ElasticityStrain(const PetscReal H[], PetscReal e[6]);
void ElasticityStrainEnergyStress(const PetscReal params[], const PetscReal e[6], PetscReal *W, PetscReal sigma[]);
PetscReal ElasticityHoopStrain(PetscReal ur, PetscReal durdr, PetscReal r);
PetscReal ElasticityVonMises(const PetscReal sigma[]);
