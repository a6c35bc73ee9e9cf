#pragma once
/* A rigid body (rigidbody.c): the geometry of its curves and its rigid
   motion. Its mesh gives only the curves (second-order lines of a Gmsh
   .msh: a .geo with curves and no surface is enough); its motion is a
   translation t and a rotation theta about its reference point c, so that a
   point X of it moves by

       u(X) = t + (R(theta) - I)(X - c),   R(theta) the rotation by theta.

   Each component of the motion (x, y and the rotation; in r-z y alone) is
   prescribed or an unknown. Prescribed: a translation's component by a
   Dirichlet condition of the body (any of its groups, -<body>_bc_<group>_
   values), the rotation by -<body>_rigid_rotation (default 0: held), both
   with -load_stages S given per stage and followed along the load
   parameter as an elastic body's values are (history.c). An unknown (at most 3): a translation's
   component force-controlled by a condition (_control force: the contact's
   force on the body balances the condition's), or held by no condition,
   and the rotation where -<body>_rigid_rotation free: these two are held by
   the contact alone (a moment and a force of zero), or the rotation turned
   by -<body>_rigid_moment (a moment control, its energy -M theta; 3D: -M .
   theta, rigid3d.c). The unknowns are
   force control's (forcecontrol.c): the last entries of X, bordering the
   Hessian. The rotation's unknown is the arc s = L theta, L the curves'
   size, so that every unknown is a length and every stiffness a force per
   length. The body has no elastic energy; its contact surfaces follow the
   motion, and the contact's force on it (and moment about its current
   reference point) is its reaction, and the unknowns' gradient. */
#include "bodycore.h"
#include "rigiddof.h"

/* What the rest of the program asks of a rigid body beyond body.h: the
   encoding of its surface nodes in the joined indices, the border of its
   unknowns (forcecontrol.c), its outline and size (results.c), and the
   region its lines enclose (surface.c). Its set-up, motion and forces are
   the body's own (src/body/bodyimpl.h). */
/* Whether its unknown q is a rotation's (2D's 2, 3D's 3, 4, 5): shown in radians and moments. */
PetscBool      BodyRigidIsRotation(Body, PetscInt q);
/* The border of a Hessian (forcecontrol.c): from Begin to End, the
   contact's coupling of unknown q to the joined vector's dofs goes into B
   (borrowed) and among the unknowns into the body's D (this rank's part,
   summed over ranks by Sum); Coupling: D's entry (q, s), with the rotation's
   curl beyond the contact's Hessian. */
void           BodyRigidBorderBegin(Body, PetscInt q, Vec B);
PetscErrorCode BodyRigidBorderSum(Body);
void           BodyRigidBorderEnd(Body, PetscInt q);
PetscReal      BodyRigidBorderCoupling(Body, PetscInt q, PetscInt s);
/* Its outline for the plots: its curves' nodes at their current positions,
   x[2 nn] (PetscFree), and each line's nodes, enodes[3 ne] (the ends, then
   the middle; the body's). */
PetscErrorCode BodyRigidGetOutline(Body, PetscInt *nn, PetscReal **x, PetscInt *ne, const PetscInt **enodes);
/* The curves' size L: the rotation's unknown is the arc L theta. */
PetscReal      BodyRigidGetLength(Body);
/* Whether the body's lines close on themselves (every corner on two lines): it is then the region they enclose. */
PetscBool      BodyRigidClosed(const Body);
/* Whether the reference point p lies inside the region the lines enclose (even-odd rule; meaningful where BodyRigidClosed). */
PetscBool      BodyRigidInside(const Body, const PetscReal p[2]);
