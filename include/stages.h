#pragma once
/* The results of a load history's stages (stages.c, -load_stages): each
   stage's end state, recorded by the staged solve, made the problem's state
   again after the solve for its figures and fields. */
#include "problem.h"

/* Collective: the bodies at the end of stage k (1..-load_stages): its load
   and its recorded X scattered to the bodies' local vectors; k = S the
   final state, p->X. */
PetscErrorCode StagesSetState(Problem, PetscInt k);
/* Collective, after ProblemPostProcess: each stage end's reactions and
   contact forces into p->res.ends (the last stage's from the final state,
   which the bodies and the terms hold again after it). */
PetscErrorCode StagesComputeFigures(Problem);
