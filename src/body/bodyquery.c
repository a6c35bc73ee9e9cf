/* What the rest of the program may read of a body: its name, communicator,
   dimension, material, mesh, vectors, conditions and loads, one function
   each, so that the Body's struct (bodyimpl.h) stays private to src/body/.
   Each reads a member and computes nothing; a question that differs between
   an elastic and a rigid body is asked by name (BodyHasCells), not by the
   body's kind. */
#include "body.h"
#include "rigidbody.h"
#include "bodyimpl.h"

const char *BodyGetName(Body b)
{
  return b->name;
}

MPI_Comm BodyGetComm(Body b)
{
  return b->comm;
}

PetscInt BodyGetDimension(Body b)
{
  return b->rigid ? (b->rg && b->rg->dim == 3 ? 3 : 2) : b->dim;
}

PetscBool BodyIsAxisymmetric(Body b)
{
  return b->axisym;
}

PetscBool BodyHasCells(Body b)
{
  return (PetscBool)!b->rigid;
}

void BodyGetElasticConstants(Body b, PetscReal *E, PetscReal *nu)
{
  *E  = b->E;
  *nu = b->nu;
}

PetscBool BodyGetRigidMotion(Body b, BodyRigidMotion *m)
{
  const BodyRigid *r = b->rg;

  if (!b->rigid) return PETSC_FALSE;
  m->dim   = r->dim;
  m->theta = r->theta;
  m->nodes = r->nn;
  for (PetscInt d = 0; d < 3; ++d) {
    m->t[d]      = r->t[d];
    m->centre[d] = r->centre[d];
    m->rot[d]    = r->rot[d];
    m->mom[d]    = -r->mom[d];
  }
  BodyRigidContactForce(b, m->force, &m->moment);
  m->force[2] = -r->force[2];
  return PETSC_TRUE;
}

PetscInt BodyGetNodesPerCell(Body b)
{
  return b->nb;
}

PetscInt BodyGetNumLocalCells(Body b)
{
  return b->ncells;
}

const PetscReal *BodyGetCellNodeCoordinates(Body b)
{
  return b->xnode;
}

void BodyGetNodePoints(Body b, PetscInt *pStart, PetscInt *pEnd, const PetscBool **owned, const PetscReal **xpoint)
{
  *pStart = b->pStart;
  *pEnd   = b->pEnd;
  *owned  = b->owned;
  *xpoint = b->xpoint;
}

const Material *BodyGetMaterial(Body b)
{
  return b->mat;
}

PetscBool BodyHasConstantTangent(Body b)
{
  return (PetscBool)(!b->mat || b->mat->constantTangent);
}

const char *BodyGetMeshFile(Body b)
{
  return b->msh;
}

PetscReal BodyGetMeshSize(Body b)
{
  return b->h;
}

PetscBool BodyIsSimplex(Body b)
{
  return b->simplex;
}

void BodyGetGlobalSizes(Body b, PetscInt *ndofs, PetscInt *ncells)
{
  if (ndofs) *ndofs = b->nglobal;
  if (ncells) *ncells = b->ncellsGlobal;
}

PetscLogDouble BodyGetMeshTime(Body b)
{
  return b->tmesh;
}

const ExactSolution *BodyGetExactSolution(Body b)
{
  return b->hasExact ? &b->exact : NULL;
}

Vec BodyGetLocalSolution(Body b)
{
  return b->Xl;
}

Vec BodyGetLocalGradient(Body b)
{
  return b->Gl;
}

DM BodyGetDM(Body b)
{
  return b->dm;
}

PetscInt BodyGetLocalSize(Body b)
{
  return b->nlocal;
}

const PetscInt *BodyGetJoinedMap(Body b)
{
  return b->l2b;
}

PetscInt BodyGetNumConditions(Body b)
{
  return b->nbc;
}

const BodyBC *BodyGetCondition(Body b, PetscInt j)
{
  return &b->bc[j];
}

PetscInt BodyGetNumLoads(Body b)
{
  return b->nload;
}

const BodyLoad *BodyGetLoad(Body b, PetscInt l)
{
  return &b->load[l];
}

PetscInt BodyGetNumStages(Body b)
{
  return b->nstages;
}

void BodySetNumStages(Body b, PetscInt n)
{
  b->nstages = n;
}

void BodySetAxisymmetric(Body b, PetscBool axisym)
{
  b->axisym = axisym;
}

void BodyAddContactPair(Body b)
{
  b->npairs++;
}

PetscInt BodyGetNumContactPairs(Body b)
{
  return b->npairs;
}

void BodySetMayAnchor(Body b, PetscBool may)
{
  b->mayAnchor = (PetscBool)(!b->rigid && may);
}

PetscReal BodyGetLoadFactor(Body b)
{
  return b->loadFactor;
}
