/* The part of a contact pair's energy term that every formulation shares:
   its surfaces and searches, and the operations that touch nothing else. */
#include "contactterm.h"

PetscErrorCode ContactTermSetUpSurfaces(ContactTerm *b, Body bodies[], PetscReal defaultBlend)
{
  const PetscReal blend = b->spec.blend < 0 ? defaultBlend : b->spec.blend;

  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < 2; ++s) {
    ContactSurface *S = &b->S[s];
    PetscCall(ContactSurfaceSetUp(S, bodies[S->body], b->spec.name, 2.0 * blend)); /* blend width in eta */
    if (b->spec.mirror) PetscCall(ContactSurfaceSetMirror(S, b->spec.mirrorY));
    PetscCall(ContactSearchCreate(S, &b->search[s]));
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
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &moved, 1, MPIU_BOOL, MPI_LOR, bodies[b->S[0].body]->comm));
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

static PetscErrorCode ContactTermWriteXDMF(EnergyTerm t, Body bodies[], FILE *fp, const char h5[])
{
  const ContactTerm *b = (const ContactTerm *)t->data;

  PetscFunctionBeginUser;
  PetscCall(ContactReportWriteXDMF(&b->report, &b->spec, bodies, fp, h5));
  PetscFunctionReturn(0);
}

static PetscErrorCode ContactTermGetProfile(EnergyTerm t, PetscInt side, PetscInt *n, PetscReal **s, PetscReal **p, PetscReal **w, PetscReal *force)
{
  const ContactTerm *b = (const ContactTerm *)t->data;
  const ContactSide *S = &b->report.side[side];

  PetscFunctionBeginUser;
  *force = b->report.P;
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

PetscErrorCode ContactTermInitialize(ContactTerm *b, const ContactPairSpec *spec, EnergyTerm t)
{
  PetscFunctionBeginUser;
  b->spec         = *spec;
  b->kp           = spec->kp;
  for (PetscInt s = 0; s < 2; ++s) {
    b->S[s].body = spec->body[s];
    PetscCall(PetscStrncpy(b->S[s].group, spec->group[s], sizeof(b->S[s].group)));
  }
  t->ops.getdofs          = ContactTermGetDofs;
  t->ops.setpenaltyfactor = ContactTermSetPenaltyFactor;
  t->ops.sethessianexact  = ContactTermSetHessianExact;
  t->ops.view             = ContactTermView;
  t->ops.writejson        = ContactTermWriteJSON;
  t->ops.writehdf5        = ContactTermWriteHDF5;
  t->ops.writexdmf        = ContactTermWriteXDMF;
  t->ops.getprofile       = ContactTermGetProfile;
  t->ops.diagnose         = ContactTermDiagnose;
  PetscFunctionReturn(0);
}
