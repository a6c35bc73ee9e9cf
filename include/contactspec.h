#pragma once
#include "contact.h"

/* A contact pair as the scene declares it, whatever the formulation: one
   surface (a Gmsh physical curve) on each of two bodies, the penalty, and the
   Hertz comparison or mirror symmetry the report applies (contactpair.c).
   Formulations are energy terms created by name from this description
   (-contact_formulation, registered in ContactFormulationList). */
typedef struct {
  char      name[CONTACT_NAME_LEN], formulation[CONTACT_NAME_LEN];
  PetscInt  body[2];
  char      group[2][CONTACT_NAME_LEN];
  PetscReal kp;           /* the scene's penalty k_p; with kpAuto, set from the mesh in set-up */
  PetscBool kpAuto;       /* -contact_penalty auto: k_p = CONTACT_PENALTY_AUTO E* / h (ContactTermSetUpSurfaces) */
  PetscReal kpH;          /* auto: the contact edges' size h it was chosen for */
  PetscInt  nqp;          /* Gauss points per slave edge (-contact_quadrature_points) */
  PetscReal blend;        /* -contact_blend: fraction of a master edge; < 0: the formulation's default */
  PetscBool hertz;        /* compare with Hertz: radii of the two surfaces (0: flat), E*, R* */
  PetscReal radii[2], Estar, Rstar; /* Estar: the pair's plane-strain modulus, with or without Hertz */
  PetscBool mirror;       /* the scene is the half y >= mirrorY of a symmetric model */
  PetscBool axisym;       /* the bodies are axisymmetric (-axisymmetric): Hertz's point contact of two spheres, P the force over the whole circle */
  PetscReal mirrorY;
  PetscInt  nsym;         /* 3D: the scene is a part of a model symmetric about nsym planes X_symAxis[k] = symValue[k] (-contact_<pair>_symmetry x=0,y=0) */
  PetscInt  symAxis[3];
  PetscReal symValue[3];
  PetscReal friction;        /* Coulomb's coefficient mu (-contact_<pair>_friction; 0: frictionless, the term has no friction at all) */
  PetscReal frictionPenalty; /* the tangential penalty k_t over k_p (-contact_<pair>_friction_penalty) */
} ContactPairSpec;

/* The automatic penalty k_p = CONTACT_PENALTY_AUTO E* / h, h the shortest
   reference edge of the pair's two surfaces (docs/formulations.md, "The
   penalty"), and the ratio k_p h / E* below which the report warns that the
   penalty's error is likely as large as the mesh's. */
#define CONTACT_PENALTY_AUTO 1000.0
#define CONTACT_PENALTY_SOFT 25.0

/* k_p h / E*: the penalty's stiffness against the bodies' at the contact
   (after the set-up, which sets kpH; 1000 with -contact_penalty auto). */
static inline PetscReal ContactPairPenaltyStiffness(const ContactPairSpec *spec)
{
  return spec->kp * spec->kpH / spec->Estar;
}
