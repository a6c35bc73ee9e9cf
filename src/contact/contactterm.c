/* The part of a contact pair's energy term that every formulation shares:
   its surfaces and searches, and the operations that touch nothing else. */
#include "contactterm.h"
#include "gap.h"

/* The penalty against the mesh. The penalty adds a compliance 1/k_p per unit
   area to the contact: the bodies overlap by d = p/k_p where an element of
   size h at the contact deforms by about p h / E*, so the penalty's share of
   the error goes like E* / (k_p h) while the mesh's goes like h. Measured on
   the mirrored reference scene (h = 0.1 to 0.0125) and hertz-small (h =
   0.008 to 0.002 at the contact), the penalty's error in P is 20 to 30 /
   (k_p h / E*) of the discretisation error, in p_max alike: at k_p h / E* =
   1000 (auto) a fortieth to a thirtieth of it, at 25 about as large
   (CONTACT_PENALTY_SOFT, which the warning names); docs/formulations.md,
   "The penalty". h is the shortest reference edge of the two surfaces, the
   size where a graded mesh is finest, at the contact. */
static PetscErrorCode ContactTermSetPenalty(ContactTerm *b)
{
  ContactPairSpec *spec = &b->spec;
  PetscReal        h    = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s)
    for (PetscInt e = 0; e < b->S[s].ne; ++e) h = PetscMin(h, b->S[s].elen[e]);
  spec->kpH = h;
  if (spec->kpAuto) {
    spec->kp = CONTACT_PENALTY_AUTO * spec->Estar / h;
    b->kp    = spec->kp;
    PetscCall(PetscInfo(NULL, "pair %s: k_p = %g E* / h = %g (E* = %g, h = %g)\n", spec->name, (double)CONTACT_PENALTY_AUTO, (double)spec->kp, (double)spec->Estar, (double)h));
  }
  PetscFunctionReturn(0);
}

/* Bodies that overlap before any load: each surface's nodes against the
   other surface, where their closest point lies on it (not past its ends),
   in the reference configuration. An overlap deeper than
   CONTACT_OVERLAP_WARN of the contact edges' mean length (the shorter of
   the two surfaces' means) is worth a line: an interference fit is legal
   and goes on, but a body put inside another by accident (a sign, a
   misplaced centre) should be visible before it is solved. The nodes of a
   curved surface lie on its geometry and its edges within O(h^3 / R^2) of
   it, far below the fraction on any mesh that resolves the contact. */
#define CONTACT_OVERLAP_WARN 0.05
static PetscErrorCode ContactTermCheckOverlap(ContactTerm *b, Body bodies[])
{
  PetscReal depth = 0.0, hmean = PETSC_MAX_REAL;
  PetscInt  deepest = -1;

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) {
    if (b->S[s].ne > 0) hmean = PetscMin(hmean, ContactSurfaceLength(&b->S[s]) / b->S[s].ne);
    PetscCall(ContactSearchBuild(b->search[s]));
  }
  b->built = PETSC_TRUE;
  for (PetscInt s = 0; s < 2; ++s) {
    const ContactSurface *S = &b->S[s], *M = &b->S[1 - s];
    if (M->ne == 0) continue;
    for (PetscInt n = 0; n < S->nn; ++n) {
      ContactGap P;
      ContactGapProject(M, b->search[1 - s], &S->X[2 * n], &P);
      if (P.me < 0 || P.ext || !(-P.gap > depth)) continue;
      depth   = -P.gap;
      deepest = s;
    }
  }
  if (deepest >= 0 && depth > CONTACT_OVERLAP_WARN * hmean) {
    const ContactSurface *S = &b->S[deepest], *M = &b->S[1 - deepest];
    PetscCall(PetscFPrintf(BodyGetComm(bodies[S->body]), PETSC_STDERR, "contact: warning: pair %s: before any load, surface %s of body %s lies inside body %s by up to %.3g, %.3g times the contact edges' mean length %.3g: an interference fit is solved as given; if it is not one, check the bodies' geometry\n", b->spec.name, S->group, BodyGetName(bodies[S->body]), BodyGetName(bodies[M->body]), (double)depth, (double)(depth / hmean), (double)hmean));
  }
  PetscCall(PetscInfo(NULL, "pair %s: largest overlap before any load %g (edges' mean length %g)\n", b->spec.name, (double)depth, (double)hmean));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactTermSetUpSurfaces(ContactTerm *b, Body bodies[], PetscReal defaultBlend)
{
  const PetscReal blend = b->spec.blend < 0 ? defaultBlend : b->spec.blend;

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) PetscCall(ContactSurfaceSetUp(&b->S[s], bodies[b->S[s].body], b->spec.name, 2.0 * blend)); /* blend width in eta */
  PetscCheck(BodyHasCells(bodies[b->S[0].body]) || BodyHasCells(bodies[b->S[1].body]), BodyGetComm(bodies[b->S[0].body]), PETSC_ERR_USER_INPUT, "contact pair %s: bodies %s and %s are both rigid: a contact between them has no elastic side", b->spec.name, BodyGetName(bodies[b->S[0].body]), BodyGetName(bodies[b->S[1].body]));
  for (PetscInt s = 0; s < 2; ++s) {
    b->body[s] = bodies[b->S[s].body];
    if (!BodyHasCells(b->body[s])) PetscCall(ContactSurfaceOrientRigid(&b->S[s], b->body[s], &b->S[1 - s], b->spec.name)); /* lines alone: oriented against the partner */
  }
  for (PetscInt s = 0; s < 2; ++s) {
    ContactSurface *S = &b->S[s];
    if (b->spec.mirror) PetscCall(ContactSurfaceSetMirror(S, b->spec.mirrorY));
    PetscCall(ContactSearchCreate(S, &b->search[s]));
  }
  PetscCall(ContactTermSetPenalty(b));
  PetscCall(ContactTermCheckOverlap(b, bodies));
  PetscCall(ContactTermCheckGivenForces(b, bodies));
  PetscCall(ContactTermAddSupport(b, bodies));
  if (!b->spec.kpAuto && ContactPairPenaltyStiffness(&b->spec) < CONTACT_PENALTY_SOFT) {
    const ContactPairSpec *spec = &b->spec;
    PetscCall(PetscFPrintf(BodyGetComm(bodies[b->S[0].body]), PETSC_STDERR, "contact: warning: pair %s: k_p = %g is soft for its mesh (k_p h / E* = %.3g with h = %.3g, E* = %.6g): its error in the force and the pressure is likely as large as the mesh's; -contact_%s_penalty auto gives %.3g\n", spec->name, (double)spec->kp, (double)ContactPairPenaltyStiffness(spec), (double)spec->kpH, (double)spec->Estar, spec->name, (double)(CONTACT_PENALTY_AUTO * spec->Estar / spec->kpH)));
  }
  PetscFunctionReturn(0);
}

/* The trees depend on the current coordinates alone: they are rebuilt only
   where these have changed since the last update (a Hessian at the point of
   the last energy evaluation, the report at the solution). The ranks agree on
   the change (their x are the same to the bit), and a logical or makes sure. */
PetscErrorCode ContactTermUpdate(ContactTerm *b, Body bodies[], PetscLogEvent search, PetscBool *changed)
{
  PetscBool moved = PETSC_FALSE;

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) {
    PetscBool c;
    PetscCall(ContactSurfaceUpdateCoordinates(&b->S[s], bodies[b->S[s].body], &c));
    moved = (PetscBool)(moved || c);
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &moved, 1, MPIU_BOOL, MPI_LOR, BodyGetComm(bodies[b->S[0].body])));
  moved = (PetscBool)(moved || !b->built);
  if (moved) {
    PetscCall(PetscLogEventBegin(search, 0, 0, 0, 0));
    for (PetscInt s = 0; s < 2; ++s) PetscCall(ContactSearchBuild(b->search[s]));
    PetscCall(PetscLogEventEnd(search, 0, 0, 0, 0));
    b->built = PETSC_TRUE;
  }
  if (changed) *changed = moved;
  PetscFunctionReturn(0);
}

PetscErrorCode ContactTermReportBegin(ContactTerm *b, const PetscBool slave[2])
{
  PetscFunctionBeginUser;
  PetscCall(ContactReportReset(&b->report));
  b->report.kp = b->kp;
  for (PetscInt s = 0; s < 2; ++s) {
    b->report.side[s].nedges = b->S[s].ne;
    b->report.side[s].slave  = slave[s];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ContactTermAddHessian(const ContactTerm *b, Mat H, PetscInt n, const PetscInt idx[], const PetscScalar K[])
{
  PetscFunctionBeginUser;
  PetscCall(MatSetValues(H, n, idx, n, idx, K, ADD_VALUES));
  for (PetscInt s = 0; s < 2; ++s) PetscCall(BodyAddSurfaceHessian(b->body[s], b->S[s].x, n, idx, K)); /* a rigid body's part: its unknowns' border */
  PetscFunctionReturn(0);
}

PetscErrorCode ContactTermDestroy(ContactTerm *b)
{
  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) {
    PetscCall(ContactSearchDestroy(&b->search[s]));
    PetscCall(ContactSurfaceDestroy(&b->S[s]));
  }
  PetscCall(ContactReportReset(&b->report));
  PetscFunctionReturn(0);
}

/* The unconstrained dofs of both surfaces (indices in the joined vector,
   sorted, each once): the only rows and columns the pair's Hessian touches. */
static PetscErrorCode ContactTermGetDofs(EnergyTerm t, PetscInt *n, PetscInt **idx)
{
  const ContactTerm *b = (const ContactTerm *)t->data;
  PetscInt           m = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(2 * (b->S[0].nn + b->S[1].nn) + 1, idx));
  for (PetscInt s = 0; s < 2; ++s)
    for (PetscInt k = 0; k < 2 * b->S[s].nn; ++k)
      if (b->S[s].big[k] >= 0) (*idx)[m++] = b->S[s].big[k];
  PetscCall(PetscSortRemoveDupsInt(&m, *idx));
  *n = m;
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactTermSetPenaltyFactor(EnergyTerm t, PetscReal f)
{
  ContactTerm *b = (ContactTerm *)t->data;

  PetscFunctionBeginUser;
  b->kp = f * b->spec.kp;
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactTermSetHessianExact(EnergyTerm t, PetscBool exact)
{
  ContactTerm *b = (ContactTerm *)t->data;

  PetscFunctionBeginUser;
  b->exactHessian = exact;
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactTermView(EnergyTerm t, Body bodies[])
{
  const ContactTerm *b = (const ContactTerm *)t->data;

  PetscFunctionBeginUser;
  if (b->report.done) PetscCall(ContactReportView(&b->report, &b->spec, bodies, t->comm));
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactTermWriteJSON(EnergyTerm t, Body bodies[], FILE *fp, PetscBool summary)
{
  const ContactTerm *b = (const ContactTerm *)t->data;

  PetscFunctionBeginUser;
  PetscCall(ContactReportWriteJSON(&b->report, &b->spec, bodies, fp, summary));
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactTermWriteHDF5(EnergyTerm t, Body bodies[], PetscViewer v)
{
  const ContactTerm *b = (const ContactTerm *)t->data;

  PetscFunctionBeginUser;
  PetscCall(ContactReportWriteHDF5(&b->report, &b->spec, bodies, v));
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactTermWriteXDMF(EnergyTerm t, Body bodies[], FILE *fp, const char h5[], PetscBool friction)
{
  const ContactTerm *b = (const ContactTerm *)t->data;

  PetscFunctionBeginUser;
  PetscCall(ContactReportWriteXDMF(&b->report, &b->spec, bodies, fp, h5, friction));
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactTermGetProfile(EnergyTerm t, PetscInt side, PetscInt *n, PetscReal **s, PetscReal **p, PetscReal **w, PetscReal force[2])
{
  const ContactTerm *b = (const ContactTerm *)t->data;
  const ContactSide *S = &b->report.side[side];

  PetscFunctionBeginUser;
  force[0] = b->report.resultant[0];
  force[1] = b->report.resultant[1];
  if (!b->report.done || !S->slave || S->n == 0) PetscFunctionReturn(0);
  PetscCall(PetscMalloc1(S->n, s));
  PetscCall(PetscMalloc1(S->n, p));
  PetscCall(PetscMalloc1(S->n, w));
  for (PetscInt i = 0; i < S->n; ++i) {
    (*s)[i] = S->rows[CONTACT_ROW_COLS * i + CONTACT_ROW_S];
    (*p)[i] = S->rows[CONTACT_ROW_COLS * i + CONTACT_ROW_P];
    (*w)[i] = S->rows[CONTACT_ROW_COLS * i + CONTACT_ROW_W];
  }
  *n = S->n;
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactTermDiagnose(EnergyTerm t, size_t n, char why[])
{
  const ContactTerm *b = (const ContactTerm *)t->data;

  PetscFunctionBeginUser;
  PetscCall(ContactReportDiagnose(&b->report, &b->spec, n, why));
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactTermGetPenaltyStiffness(EnergyTerm t, PetscReal *stiffness)
{
  const ContactTerm *b = (const ContactTerm *)t->data;

  PetscFunctionBeginUser;
  *stiffness = ContactPairPenaltyStiffness(&b->spec);
  PetscFunctionReturn(0);
}

PetscErrorCode ContactTermInitialize(ContactTerm *b, const ContactPairSpec *spec, EnergyTerm t)
{
  PetscFunctionBeginUser;
  b->spec         = *spec;
  b->kp           = spec->kp;
  for (PetscInt s = 0; s < 2; ++s) {
    b->S[s].body = spec->body[s];
    PetscCall(PetscStrncpy(b->S[s].group, spec->group[s], sizeof(b->S[s].group)));
  }
  t->ops.getdofs             = ContactTermGetDofs;
  t->ops.setpenaltyfactor    = ContactTermSetPenaltyFactor;
  t->ops.getpenaltystiffness = ContactTermGetPenaltyStiffness;
  t->ops.sethessianexact     = ContactTermSetHessianExact;
  t->ops.view                = ContactTermView;
  t->ops.writejson           = ContactTermWriteJSON;
  t->ops.writehdf5           = ContactTermWriteHDF5;
  t->ops.writexdmf           = ContactTermWriteXDMF;
  t->ops.getprofile          = ContactTermGetProfile;
  t->ops.diagnose            = ContactTermDiagnose;
  PetscFunctionReturn(0);
}
