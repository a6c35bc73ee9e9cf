/* The energy-term interface: creation, destruction and the calls through the
   table of operations, each optional operation a no-op where a term has none. */
#include "energyterm.h"

PetscErrorCode EnergyTermCreate(MPI_Comm comm, const char name[], EnergyTerm *term)
{
  EnergyTerm t;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&t));
  t->comm = comm;
  PetscCall(PetscStrncpy(t->name, name, sizeof(t->name)));
  *term = t;
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermDestroy(EnergyTerm *term)
{
  PetscFunctionBeginUser;
  if (!*term) PetscFunctionReturn(0);
  if ((*term)->ops.destroy) PetscCall((*term)->ops.destroy(*term));
  PetscCall(PetscFree(*term));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermSetUp(EnergyTerm t, Body bodies[])
{
  PetscFunctionBeginUser;
  if (t->ops.setup) PetscCall(t->ops.setup(t, bodies));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermComputeEnergyGradient(EnergyTerm t, Body bodies[], PetscReal *energy)
{
  PetscFunctionBeginUser;
  PetscCall(t->ops.energygradient(t, bodies, energy));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermComputeHessian(EnergyTerm t, Body bodies[], Mat H)
{
  PetscFunctionBeginUser;
  PetscCall(t->ops.hessian(t, bodies, H));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermGetDofs(EnergyTerm t, PetscInt *n, PetscInt **idx)
{
  PetscFunctionBeginUser;
  *n   = 0;
  *idx = NULL;
  if (t->ops.getdofs) PetscCall(t->ops.getdofs(t, n, idx));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermGetPattern(EnergyTerm t, PetscBool *has, PetscInt *n, PetscInt **rows, PetscInt **start, PetscInt **cols)
{
  PetscFunctionBeginUser;
  *has = (PetscBool)!!t->ops.getpattern;
  *n   = 0;
  *rows = *start = *cols = NULL;
  if (t->ops.getpattern) PetscCall(t->ops.getpattern(t, n, rows, start, cols));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermSetPenaltyFactor(EnergyTerm t, PetscReal factor)
{
  PetscFunctionBeginUser;
  if (t->ops.setpenaltyfactor) PetscCall(t->ops.setpenaltyfactor(t, factor));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermSetHessianExact(EnergyTerm t, PetscBool exact)
{
  PetscFunctionBeginUser;
  if (t->ops.sethessianexact) PetscCall(t->ops.sethessianexact(t, exact));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermPostProcess(EnergyTerm t, Body bodies[])
{
  PetscFunctionBeginUser;
  if (t->ops.postprocess) PetscCall(t->ops.postprocess(t, bodies));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermView(EnergyTerm t, Body bodies[])
{
  PetscFunctionBeginUser;
  if (t->ops.view) PetscCall(t->ops.view(t, bodies));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermWriteJSON(EnergyTerm t, Body bodies[], FILE *fp, PetscBool summary)
{
  PetscFunctionBeginUser;
  if (t->ops.writejson) PetscCall(t->ops.writejson(t, bodies, fp, summary));
  else if (!summary) fprintf(fp, "{}");
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermWriteHDF5(EnergyTerm t, Body bodies[], PetscViewer v)
{
  PetscFunctionBeginUser;
  if (t->ops.writehdf5) PetscCall(t->ops.writehdf5(t, bodies, v));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermWriteXDMF(EnergyTerm t, Body bodies[], FILE *fp, const char h5[], PetscBool friction)
{
  PetscFunctionBeginUser;
  if (t->ops.writexdmf) PetscCall(t->ops.writexdmf(t, bodies, fp, h5, friction));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermGetProfile(EnergyTerm t, PetscInt side, PetscInt *n, PetscReal **s, PetscReal **p, PetscReal **w, PetscReal force[2])
{
  PetscFunctionBeginUser;
  *n       = 0;
  *s       = *p = *w = NULL;
  force[0] = force[1] = 0.0;
  if (t->ops.getprofile) PetscCall(t->ops.getprofile(t, side, n, s, p, w, force));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermGetPenaltyStiffness(EnergyTerm t, PetscReal *stiffness)
{
  PetscFunctionBeginUser;
  *stiffness = 0.0;
  if (t->ops.getpenaltystiffness) PetscCall(t->ops.getpenaltystiffness(t, stiffness));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermDiagnose(EnergyTerm t, size_t n, char why[])
{
  PetscFunctionBeginUser;
  why[0] = 0;
  if (t->ops.diagnose) PetscCall(t->ops.diagnose(t, n, why));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermGetSlipState(EnergyTerm t, PetscInt *stuck, PetscInt *loaded, PetscReal *slip)
{
  PetscFunctionBeginUser;
  *stuck = *loaded = 0;
  *slip            = 0.0;
  if (t->ops.slipstate) PetscCall(t->ops.slipstate(t, stuck, loaded, slip));
  PetscFunctionReturn(0);
}

PetscBool EnergyTermHasState(EnergyTerm t)
{
  return (PetscBool)(t->ops.accept != NULL);
}

PetscErrorCode EnergyTermLag(EnergyTerm t, Body bodies[], PetscReal *change)
{
  PetscFunctionBeginUser;
  *change = 0.0;
  if (t->ops.lag) PetscCall(t->ops.lag(t, bodies, change));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermAccept(EnergyTerm t, Body bodies[], PetscReal load)
{
  PetscFunctionBeginUser;
  if (t->ops.accept) PetscCall(t->ops.accept(t, bodies, load));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermBegin(EnergyTerm t)
{
  PetscFunctionBeginUser;
  if (t->ops.begin) PetscCall(t->ops.begin(t));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermScaleBound(EnergyTerm t, PetscReal growth)
{
  PetscFunctionBeginUser;
  if (t->ops.scalebound) PetscCall(t->ops.scalebound(t, growth));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermRestore(EnergyTerm t, Body bodies[])
{
  PetscFunctionBeginUser;
  if (t->ops.restore) PetscCall(t->ops.restore(t, bodies));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermReset(EnergyTerm t, Body bodies[])
{
  PetscFunctionBeginUser;
  if (t->ops.reset) PetscCall(t->ops.reset(t, bodies));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyTermGetStickHalfWidth(EnergyTerm t, PetscInt k, PetscReal *c, PetscBool *has)
{
  PetscFunctionBeginUser;
  *c   = 0.0;
  *has = PETSC_FALSE;
  if (t->ops.stickhalfwidth) PetscCall(t->ops.stickhalfwidth(t, k, c, has));
  PetscFunctionReturn(0);
}
