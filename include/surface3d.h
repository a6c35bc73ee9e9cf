#pragma once
#include "bodyfaces.h"
#include "face3d.h"

/* A 3D contact surface: a Gmsh physical surface of a 3D elastic body,
   held whole on every rank (surface3d.c), as the 2D surfaces are
   (surface.h): its curved quadratic faces (Tri6 or Quad9, face3d.h) and
   their nodes, the nodes' reference and current coordinates, a gradient
   array over them, their joined indices, and the faces this rank
   integrates as slave. */
typedef struct {
  PetscInt    body, tag;
  char        group[CONTACT_NAME_LEN];
  Face3dType  type;
  PetscInt    nb;          /* nodes per face: 6 or 9 */
  PetscInt    nf, nn;      /* faces and nodes (whole surface, every rank) */
  PetscInt   *fnodes;      /* [nf][nb] node indices, Gmsh's order, outward */
  PetscInt   *nodeId;      /* [nn] global node numbers, sorted */
  PetscReal  *X, *x, *g;   /* [nn][3] reference, current coordinates, gradient (this rank's part) */
  PetscReal  *gsum;        /* [nn][3] the gradient summed over ranks at the last ContactSurface3dAddGradient */
  PetscInt   *big;         /* [nn][3] index in the joined vector, -1 if constrained */
  BodyNodeMap map;         /* the nodes among the body's owned points, and their local offsets */
  PetscInt    nown, *ownFaces; /* faces this rank integrates as slave (those it gave) */
  PetscReal   hmin, hmax;  /* the shortest and longest chord between a face's corners (reference) */
} ContactSurface3d;

/* Collective on the body: gathers the group's faces from every rank, numbers
   their nodes and maps them to the body's vectors; pair names the errors. */
PetscErrorCode ContactSurface3dSetUp(ContactSurface3d *, Body, const char pair[]);
PetscErrorCode ContactSurface3dDestroy(ContactSurface3d *);
/* Collective: x = X + u from the body's local vector; changed: whether x
   differs from the last (the same answer on every rank). */
PetscErrorCode ContactSurface3dUpdateCoordinates(ContactSurface3d *, Body, PetscBool *changed);
/* Collective: sums g over ranks into gsum and adds it to the body's local gradient. */
PetscErrorCode ContactSurface3dAddGradient(ContactSurface3d *, Body);
/* The nodes on the border of the surface (bnd[nn], to free): of the edges one face alone has. */
PetscErrorCode ContactSurface3dBorderNodes(const ContactSurface3d *, PetscBool **);
/* Whether a border node of A (bndA), within tol of A's least distance to B, has its closest point inside B, away from its border (bndB). */
PetscErrorCode ContactSurface3dEndsOn(const ContactSurface3d *, const PetscBool[], const ContactSurface3d *, const PetscBool[], PetscReal, PetscBool *);
/* Face f's node coordinates xf[3 nb] from c (S->X or S->x). */
static inline void ContactSurface3dFaceCoords(const ContactSurface3d *S, PetscInt f, const PetscReal c[], PetscReal xf[])
{
  for (PetscInt i = 0; i < S->nb; ++i)
    for (PetscInt d = 0; d < 3; ++d) xf[3 * i + d] = c[3 * S->fnodes[S->nb * f + i] + d];
}
