/* Contact pairs as the scene declares them: the options of every pair, read
   into a ContactPairSpec whatever the formulation, and the registry of
   formulations from which each pair's energy term is created by name. */
#include "contactpair.h"
#include "mortar3d.h"
#include "options.h"

PetscFunctionList ContactFormulationList = NULL;

PetscErrorCode ContactFormulationRegister(const char name[], ContactFormulationCreate create)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListAdd(&ContactFormulationList, name, create));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactFormulationRegisterAll(void)
{
  PetscFunctionBeginUser;
  if (ContactFormulationList) PetscFunctionReturn(0);
  PetscCall(ContactFormulationRegister("gpts", ContactTermCreate_GPTS));
  PetscCall(ContactFormulationRegister("mortar", ContactTermCreate_MortarAnyDim));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactFormulationFinalize(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&ContactFormulationList));
  PetscFunctionReturn(0);
}

/* -contact_<pair>_symmetry x=0,y=0: planes normal to the axes, each axis at
   most once, at finite positions (the entries freed). */
static PetscErrorCode ParseSymmetry(MPI_Comm comm, const char prefix[], PetscInt n, char *entry[], ContactPairSpec *spec)
{
  PetscFunctionBeginUser;
  spec->nsym = n;
  for (PetscInt k = 0; k < n; ++k) {
    const char *e = entry[k];
    char       *end = NULL;
    PetscInt    axis = e[0] == 'x' ? 0 : e[0] == 'y' ? 1 : e[0] == 'z' ? 2 : -1;
    PetscReal   v    = axis >= 0 && e[1] == '=' && e[2] ? (PetscReal)strtod(e + 2, &end) : 0.0;
    PetscCheck(end && !*end && !PetscIsInfOrNanReal(v), comm, PETSC_ERR_USER_INPUT, "option -%ssymmetry: '%s' is not a plane axis=value (x=0, y=0 or z=0: the plane normal to that axis through value)", prefix, e);
    for (PetscInt j = 0; j < k; ++j) PetscCheck(spec->symAxis[j] != axis, comm, PETSC_ERR_USER_INPUT, "option -%ssymmetry: two planes normal to %c", prefix, e[0]);
    spec->symAxis[k]  = axis;
    spec->symValue[k] = v;
  }
  for (PetscInt k = 0; k < n; ++k) PetscCall(PetscFree(entry[k]));
  PetscFunctionReturn(0);
}

/* A penalty option's value: "auto" or a finite number > 0. */
static PetscErrorCode ParsePenalty(MPI_Comm comm, const char option[], const char value[], PetscReal *kp, PetscBool *isAuto)
{
  char *end;

  PetscFunctionBeginUser;
  PetscCall(PetscStrcmp(value, "auto", isAuto));
  if (*isAuto) {
    *kp = -1.0;
    PetscFunctionReturn(0);
  }
  *kp = strtod(value, &end);
  PetscCheck(end != value && !*end && !PetscIsInfOrNanReal(*kp) && *kp > 0, comm, PETSC_ERR_USER_INPUT, "option %s: must be auto or a finite number > 0, got %s", option, value);
  PetscFunctionReturn(0);
}

/* A formulation's constructor; an unknown name is an error that names the
   option and lists the known ones. */
static PetscErrorCode ContactFormulationFind(MPI_Comm comm, const char name[], const char option[], ContactFormulationCreate *create)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListFind(ContactFormulationList, name, create));
  if (!*create) {
    char known[256];
    PetscCall(ContactOptionsListNames(ContactFormulationList, known, sizeof(known)));
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "option %s: unknown contact formulation '%s' (known: %s)", option, name, known);
  }
  PetscFunctionReturn(0);
}

/* The term of a pair in formulation spec->formulation. */
static PetscErrorCode ContactFormulationCreateTerm(MPI_Comm comm, const ContactPairSpec *spec, const char option[], EnergyTerm *term)
{
  ContactFormulationCreate create;

  PetscFunctionBeginUser;
  PetscCall(ContactFormulationFind(comm, spec->formulation, option, &create));
  PetscCall(EnergyTermCreate(comm, spec->name, term));
  PetscCall(PetscStrncpy((*term)->type, spec->formulation, sizeof((*term)->type)));
  (*term)->couples[spec->body[0]] = PETSC_TRUE;
  (*term)->couples[spec->body[1]] = PETSC_TRUE;
  for (PetscInt k = 0; k < 2; ++k) {
    (*term)->body[k] = spec->body[k];
    PetscCall(PetscStrncpy((*term)->group[k], spec->group[k], sizeof((*term)->group[k])));
  }
  PetscCall((*create)(spec, *term));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactPairsCreateFromOptions(MPI_Comm comm, PetscInt nbodies, Body bodies[], PetscInt maxTerms, PetscInt *nterms, EnergyTerm terms[], PetscBool *autoPenalty)
{
  char     *names[64], formulation[CONTACT_NAME_LEN] = "mortar", penalty[64] = "auto";
  PetscInt  np = 64, nq = 4;
  PetscReal kp = -1.0, blend = 0.05, mu = 0.0, ktScale = 0.01;
  PetscBool disable = PETSC_FALSE, kpAuto, setBlend, help;

  PetscFunctionBeginUser;
  *nterms      = 0;
  *autoPenalty = PETSC_FALSE;
  PetscCall(PetscOptionsHasHelp(NULL, &help)); /* -help: list the options; a penalty or a pair's surfaces are not required */
  PetscCall(ContactFormulationRegisterAll());
  PetscOptionsBegin(comm, NULL, "Contact options", NULL);
  PetscCall(ContactOptionsStringArray(PetscOptionsObject, "-contact_pairs", "Contact pair names (see -contact_<pair>_surfaces; none: no contact)", NULL, names, &np, NULL));
  PetscCall(ContactOptionsFList(PetscOptionsObject, "-contact_formulation", "Formulation of every pair (-contact_<pair>_formulation overrides it per pair)", NULL, ContactFormulationList, formulation, formulation, sizeof(formulation), NULL));
  PetscCall(ContactOptionsString(PetscOptionsObject, "-contact_penalty", "Penalty k_p of every pair: a number (pressure per unit penetration), or auto: 1000 E*/h, h the contact edges' size", NULL, penalty, penalty, sizeof(penalty), NULL));
  PetscCall(PetscOptionsInt("-contact_quadrature_points", "Gauss points per slave edge (gpts), per segment (mortar, at least 3)", NULL, nq, &nq, NULL));
  PetscCall(PetscOptionsReal("-contact_blend", "Fraction of a master edge, at each end, over which its tangent is blended into its neighbour's (0: quadratic edges meeting at corners; default 0.05 for gpts, 0 for mortar)", NULL, blend, &blend, &setBlend));
  PetscCall(PetscOptionsReal("-contact_friction", "Coulomb friction coefficient mu of every pair (-contact_<pair>_friction overrides it per pair; 0: frictionless)", NULL, mu, &mu, NULL));
  PetscCall(PetscOptionsReal("-contact_friction_penalty", "Tangential penalty k_t of every frictional pair over its normal penalty k_p (0.01: with -contact_penalty auto k_t = 10 E*/h)", NULL, ktScale, &ktScale, NULL));
  PetscCall(PetscOptionsBool("-contact_disable", "Ignore the scene's contact pairs", NULL, disable, &disable, NULL));
  PetscOptionsEnd();
  if (help && !np) { /* -help without pairs: a pair's options under a placeholder name */
    PetscCall(PetscStrallocpy("<pair>", &names[0]));
    np = 1;
  }
  { /* checked even where every pair gives its own */
    ContactFormulationCreate create;
    PetscCall(ContactFormulationFind(comm, formulation, "-contact_formulation", &create));
  }
  PetscCheck(blend >= 0 && blend <= 0.5, comm, PETSC_ERR_USER_INPUT, "option -contact_blend: must be in [0, 0.5], got %g", (double)blend);
  PetscCheck(nq >= 1 && nq <= 8, comm, PETSC_ERR_USER_INPUT, "option -contact_quadrature_points: must be in [1, 8], got %" PetscInt_FMT, nq);
  PetscCall(ParsePenalty(comm, "-contact_penalty", penalty, &kp, &kpAuto));
  PetscCheck(!PetscIsInfOrNanReal(mu) && mu >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "option -contact_friction: must be a finite number >= 0, got %g", (double)mu);
  PetscCheck(!PetscIsInfOrNanReal(ktScale) && ktScale > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "option -contact_friction_penalty: must be a finite number > 0, got %g", (double)ktScale);
  PetscCheck(np <= maxTerms, comm, PETSC_ERR_USER_INPUT, "option -contact_pairs: %" PetscInt_FMT " pairs, at most %" PetscInt_FMT, np, maxTerms);
  for (PetscInt i = 0; i < np; ++i) {
    ContactPairSpec spec;
    char            prefix[2 * CONTACT_NAME_LEN], option[3 * CONTACT_NAME_LEN], *surf[2] = {NULL, NULL};
    PetscInt        ns = 2, nr = 2, nsym = 3;
    char           *sym[3] = {NULL, NULL, NULL};
    PetscBool       setSym;
    PetscBool       setPair, setForm;
    char            pairPenalty[64];

    PetscCall(PetscMemzero(&spec, sizeof(spec)));
    PetscCall(PetscStrncpy(spec.name, names[i], sizeof(spec.name)));
    PetscCall(PetscFree(names[i]));
    for (PetscInt j = 0; j < *nterms; ++j) {
      PetscBool same;
      PetscCall(PetscStrcmp(terms[j]->name, spec.name, &same));
      PetscCheck(!same, comm, PETSC_ERR_USER_INPUT, "option -contact_pairs: pair '%s' given twice", spec.name);
    }
    PetscCall(PetscStrncpy(spec.formulation, formulation, sizeof(spec.formulation)));
    spec.kp           = kp;
    spec.kpAuto       = kpAuto;
    spec.nqp          = nq;
    spec.blend        = setBlend ? blend : -1.0;
    spec.friction        = mu;
    spec.frictionPenalty = ktScale;
    PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "contact_%s_", spec.name));
    PetscCall(PetscStrncpy(pairPenalty, penalty, sizeof(pairPenalty)));
    PetscOptionsBegin(comm, prefix, "Contact pair options", NULL);
    PetscCall(ContactOptionsStringArray(PetscOptionsObject, "-surfaces", "The two surfaces, body:group,body:group (required)", NULL, surf, &ns, &setPair));
    PetscCall(ContactOptionsFList(PetscOptionsObject, "-formulation", "Formulation of this pair (default -contact_formulation)", NULL, ContactFormulationList, spec.formulation, spec.formulation, sizeof(spec.formulation), &setForm));
    PetscCall(ContactOptionsString(PetscOptionsObject, "-penalty", "Penalty k_p of this pair: a number, or auto (default -contact_penalty)", NULL, pairPenalty, pairPenalty, sizeof(pairPenalty), NULL));
    PetscCall(PetscOptionsRealArray("-hertz_radii", "Radii of the two surfaces for the Hertz comparison (0: flat): cylinders in plane strain, spheres with -axisymmetric and between 3D bodies", NULL, spec.radii, &nr, &spec.hertz));
    PetscCall(ContactOptionsRealNoDefault(PetscOptionsObject, "-mirror_y", "Half model mirrored about the line y = value: the contact continues each surface by its mirror image past the line, the report doubles the force across it and mirrors the profiles", "off", PETSC_FALSE, &spec.mirrorY, &spec.mirror));
    PetscCall(ContactOptionsStringArray(PetscOptionsObject, "-symmetry", "3D: the scene is a part of a model symmetric about these planes, each axis=value (x=0,y=0: a quarter; the planes held on rollers): the report gives the whole model's force, contact area and radii, and compares them with Hertz", NULL, sym, &nsym, &setSym));
    PetscCall(PetscOptionsReal("-friction", "Coulomb friction coefficient mu of this pair (default -contact_friction; 0: frictionless)", NULL, spec.friction, &spec.friction, NULL));
    PetscCall(PetscOptionsReal("-friction_penalty", "Tangential penalty k_t of this pair over its normal penalty k_p (default -contact_friction_penalty)", NULL, spec.frictionPenalty, &spec.frictionPenalty, NULL));
    PetscOptionsEnd();
    PetscCheck(!PetscIsInfOrNanReal(spec.friction) && spec.friction >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "option -%sfriction: must be a finite number >= 0, got %g", prefix, (double)spec.friction);
    PetscCheck(!PetscIsInfOrNanReal(spec.frictionPenalty) && spec.frictionPenalty > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "option -%sfriction_penalty: must be a finite number > 0, got %g", prefix, (double)spec.frictionPenalty);
    if (help && !setPair) { /* -help: a pair without surfaces (the placeholder) is only listed */
      for (PetscInt k = 0; k < nsym; ++k) PetscCall(PetscFree(sym[k]));
      for (PetscInt s = 0; s < ns; ++s) PetscCall(PetscFree(surf[s]));
      continue;
    }
    if (setSym) PetscCall(ParseSymmetry(comm, prefix, nsym, sym, &spec));
    PetscCheck(setPair && ns == 2, comm, PETSC_ERR_USER_INPUT, "option -%ssurfaces: give two surfaces body:group,body:group", prefix);
    PetscCheck(!spec.hertz || nr == 2, comm, PETSC_ERR_USER_INPUT, "option -%shertz_radii: give two radii (0 for a flat surface)", prefix);
    PetscCall(PetscSNPrintf(option, sizeof(option), "-%spenalty", prefix));
    PetscCall(ParsePenalty(comm, option, pairPenalty, &spec.kp, &spec.kpAuto));
    for (PetscInt s = 0; s < 2; ++s) {
      char *colon = strchr(surf[s], ':');
      PetscCheck(colon, comm, PETSC_ERR_USER_INPUT, "option -%ssurfaces: '%s' is not body:group", prefix, surf[s]);
      *colon       = 0;
      spec.body[s] = -1;
      for (PetscInt b = 0; b < nbodies; ++b) {
        PetscBool same;
        PetscCall(PetscStrcmp(BodyGetName(bodies[b]), surf[s], &same));
        if (same) spec.body[s] = b;
      }
      PetscCheck(spec.body[s] >= 0, comm, PETSC_ERR_USER_INPUT, "option -%ssurfaces: no body named '%s'", prefix, surf[s]);
      PetscCall(PetscStrncpy(spec.group[s], colon + 1, sizeof(spec.group[s])));
      PetscCall(PetscFree(surf[s]));
    }
    PetscCheck(spec.body[0] != spec.body[1], comm, PETSC_ERR_USER_INPUT, "option -%ssurfaces: both surfaces are on body %s: a pair joins two bodies (self-contact is not modelled)", prefix, BodyGetName(bodies[spec.body[0]]));
    PetscCheck(!spec.mirror || !PetscIsInfOrNanReal(spec.mirrorY), comm, PETSC_ERR_USER_INPUT, "option -%smirror_y: must be a finite number, got %g", prefix, (double)spec.mirrorY);
    for (PetscInt s = 0; s < 2; ++s) PetscCheck(!spec.hertz || (spec.radii[s] >= 0 && !PetscIsInfOrNanReal(spec.radii[s])), comm, PETSC_ERR_USER_INPUT, "option -%shertz_radii: radius %g must be >= 0", prefix, (double)spec.radii[s]);
    PetscCheck(!spec.hertz || spec.radii[0] > 0 || spec.radii[1] > 0, comm, PETSC_ERR_USER_INPUT, "option -%shertz_radii: at least one surface must be curved", prefix);
    {
      const Body b0 = bodies[spec.body[0]], b1 = bodies[spec.body[1]];
      PetscReal  E0, nu0, E1, nu1;
      BodyGetElasticConstants(b0, &E0, &nu0);
      BodyGetElasticConstants(b1, &E1, &nu1);
      spec.Estar = 1.0 / ((1.0 - nu0 * nu0) / E0 + (1.0 - nu1 * nu1) / E1);
      spec.axisym = BodyIsAxisymmetric(b0);
    }
    PetscCheck(!spec.axisym || !spec.mirror, comm, PETSC_ERR_USER_INPUT, "option -%smirror_y: an axisymmetric scene is not mirrored (its axis is x = 0)", prefix);
    if (spec.hertz) {
      PetscReal iR = 0.0;
      for (PetscInt s = 0; s < 2; ++s)
        if (spec.radii[s] > 0) iR += 1.0 / spec.radii[s];
      spec.Rstar = 1.0 / iR;
    }
    if (disable) continue; /* read and checked like the others, then dropped */
    PetscCall(PetscSNPrintf(option, sizeof(option), setForm ? "-%sformulation" : "-contact_formulation", prefix));
    PetscCall(ContactFormulationCreateTerm(comm, &spec, option, &terms[*nterms]));
    if (spec.kpAuto) *autoPenalty = PETSC_TRUE;
    (*nterms)++;
  }
  if (help) { /* listed once, whether or not a pair is mortar, 2D or 3D */
    PetscReal margin;
    PetscInt  edgePoints;
    PetscCall(ContactMortarOptionsHelp(comm));
    PetscCall(ContactMortar3dOptionsRead(comm, &margin, &edgePoints));
  }
  PetscFunctionReturn(0);
}
