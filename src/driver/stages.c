/* The results of a load history's stages (-load_stages): the staged solve
   (staging.c) keeps X at each stage's end; after the solve and its
   post-processing each earlier end is made the state again, at its load,
   for its figures (every Dirichlet group's reaction and each contact term's
   force, for the JSON's load_stages) and for its fields (the HDF5's
   /stages, results.c). The last stage's end is the final state, whose
   results are the run's own; the bodies and the terms are left holding it. */
#include "stages.h"

PetscErrorCode StagesSetState(Problem p, PetscInt k)
{
  const PetscInt S = p->cfg->load.stages;
  Vec            X = k < S ? p->res.ends.X[k - 1] : p->X;

  PetscFunctionBeginUser;
  PetscCheck(X, p->comm, PETSC_ERR_PLIB, "load stage %" PetscInt_FMT ": its end state was not recorded", k);
  PetscCall(ProblemSetLoad(p, (PetscReal)k));
  PetscCall(ProblemScatterToBodies(p, X));
  PetscFunctionReturn(0);
}

/* The reactions and the contact forces of the state the bodies and terms
   hold (after an evaluation, whose gradients give the reactions where
   react, and the terms' post-processing), as stage k's. */
static PetscErrorCode StagesRecordFigures(Problem p, PetscInt k, PetscBool react)
{
  StageEnds *e = &p->res.ends;

  PetscFunctionBeginUser;
  for (PetscInt i = 0, g = 0; i < p->nbodies; ++i) {
    if (react) PetscCall(BodyComputeReactions(p->bodies[i], BodyGetLocalGradient(p->bodies[i])));
    for (PetscInt j = 0; j < BodyGetNumConditions(p->bodies[i]); ++j, g += 3) PetscCall(PetscArraycpy(&e->reaction[k - 1][g], BodyGetCondition(p->bodies[i], j)->reaction, 3));
  }
  for (PetscInt t = 0; t < p->nterms; ++t) {
    PetscInt   n = 0;
    PetscReal *s = NULL, *pr = NULL, *w = NULL;
    PetscCall(EnergyTermGetProfile(p->terms[t], 0, &n, &s, &pr, &w, e->force[k - 1][t]));
    PetscCall(PetscFree(s));
    PetscCall(PetscFree(pr));
    PetscCall(PetscFree(w));
  }
  PetscFunctionReturn(0);
}

/* The state at the end of stage k evaluated and post-processed by the terms. */
static PetscErrorCode StagesEvaluate(Problem p, PetscInt k)
{
  const PetscInt S = p->cfg->load.stages;
  Vec            X = k < S ? p->res.ends.X[k - 1] : p->X;
  PetscReal      f;

  PetscFunctionBeginUser;
  PetscCall(ProblemSetLoad(p, (PetscReal)k));
  PetscCall(ProblemEvaluate(p, X, &f, p->G, NULL));
  for (PetscInt t = 0; t < p->nterms; ++t) PetscCall(EnergyTermPostProcess(p->terms[t], p->bodies));
  PetscFunctionReturn(0);
}

PetscErrorCode StagesComputeFigures(Problem p)
{
  const PetscInt S = p->cfg->load.stages;

  PetscFunctionBeginUser;
  PetscCall(StagesRecordFigures(p, S, PETSC_FALSE)); /* the final state's, as ProblemPostProcess left it */
  if (S == 1) PetscFunctionReturn(0);
  for (PetscInt k = 1; k < S; ++k) {
    PetscCall(StagesEvaluate(p, k));
    PetscCall(StagesRecordFigures(p, k, PETSC_TRUE));
  }
  PetscCall(StagesEvaluate(p, S)); /* the final state again, in the bodies and the terms */
  for (PetscInt i = 0; i < p->nbodies; ++i) PetscCall(BodyComputeReactions(p->bodies[i], BodyGetLocalGradient(p->bodies[i])));
  PetscFunctionReturn(0);
}
