#pragma once
#include "contactterm.h"

/* Contact formulation "mortar" between 3D bodies (mortar3d.c): the weighted-gap
   penalty on Tri6 and Quad9 faces; with -contact_<pair>_friction, Coulomb
   friction on its slave (friction3d.c). */
PetscErrorCode ContactTermCreate_Mortar3d(const ContactPairSpec *, EnergyTerm);
/* "mortar" as registered: mortar.c's 2D term, which becomes the 3D one at
   its set-up where the pair's bodies are 3D. */
PetscErrorCode ContactTermCreate_MortarAnyDim(const ContactPairSpec *, EnergyTerm);
