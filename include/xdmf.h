#pragma once
#include <stdio.h>

/* The point fields of the XDMF file's grids (output.c writes the bodies',
   contactreport.c the contact surfaces'). ParaView's Xdmf3ReaderS, the
   reader OpenDataFile picks, reads the file's spatial collection as the
   pieces of one dataset and colours by a field only where every piece has
   it (a body coloured by von_mises rendered uniform grey). So every grid
   carries every field: a body's contact fields are NaN (no value), a
   surface's stress fields NaN and its displacement zero (its grid is drawn at
   the current positions already, so Warp By Vector leaves it there). */
#define XDMF_BODY_SCALARS    5
#define XDMF_SURFACE_SCALARS 3
static const char *const XdmfBodyScalars[XDMF_BODY_SCALARS]       = {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "von_mises"};
/* in an axisymmetric scene (x = r, y = z): the hoop stress is the third */
static const char *const XdmfBodyScalarsAxisym[XDMF_BODY_SCALARS] = {"stress_rr", "stress_zz", "stress_hoop", "stress_rz", "von_mises"};
static inline const char *const *XdmfBodyScalarNames(int axisym)
{
  return axisym ? XdmfBodyScalarsAxisym : XdmfBodyScalars;
}
/* A 3D body's (a scene is all 2D or all 3D, so every grid of a 3D scene,
   the 3D contact surfaces' too, carries these): the stress columns xx, yy,
   zz, xy, yz, xz, then von Mises. */
#define XDMF_BODY_SCALARS_3D 7
static const char *const XdmfBodyScalars3D[XDMF_BODY_SCALARS_3D] = {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_xz", "von_mises"};
static const char *const XdmfSurfaceScalars[XDMF_SURFACE_SCALARS] = {"pressure", "gap", "s"};
/* A 3D scene's contact fields (mortar3d.c's slave surfaces; NaN on the
   bodies): the nodal pressure, weighted gap and weight A_j, and the vector
   XDMF_CONTACT_VECTOR_3D, the pair's force on each node. No arc position s
   (2D's) in 3D. */
#define XDMF_CONTACT_SCALARS_3D 3
static const char *const XdmfContactScalars3D[XDMF_CONTACT_SCALARS_3D] = {"pressure", "gap", "weight"};
#define XDMF_CONTACT_VECTOR_3D "force"
/* In a scene with friction, also on every grid: a frictional pair's slave
   surface has them (its node_shear, node_slip, node_stick), its master the
   shear (transferred), every other grid NaN. A frictionless scene's file has
   none. */
#define XDMF_FRICTION_SCALARS 3
static const char *const XdmfFrictionScalars[XDMF_FRICTION_SCALARS] = {"shear", "slip", "stick"};
/* In a 3D scene with friction, on every grid: the shear and slip vectors and
   the stick flag (a frictional pair's slave surface's node_shear, node_slip,
   node_stick; NaN elsewhere). */
#define XDMF_FRICTION_FIELDS_3D 3
static const char *const XdmfFrictionFields3D[XDMF_FRICTION_FIELDS_3D] = {"shear", "slip", "stick"};
static const char *const XdmfFrictionSets3D[XDMF_FRICTION_FIELDS_3D]   = {"node_shear", "node_slip", "node_stick"};
static const int         XdmfFrictionComponents3D[XDMF_FRICTION_FIELDS_3D] = {3, 3, 1};

/* One node-centred attribute: n tuples of 1 or 3 components in dataset path. */
static inline void XdmfWriteAttribute(FILE *fp, const char name[], int n, int components, const char path[])
{
  if (components == 3) fprintf(fp, "    <Attribute Name=\"%s\" AttributeType=\"Vector\" Center=\"Node\">\n     <DataItem Dimensions=\"%d 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%s</DataItem>\n    </Attribute>\n", name, n, path);
  else fprintf(fp, "    <Attribute Name=\"%s\" AttributeType=\"Scalar\" Center=\"Node\">\n     <DataItem Dimensions=\"%d\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">%s</DataItem>\n    </Attribute>\n", name, n, path);
}
