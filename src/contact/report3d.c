/* The report of a 3D pair: what a user compares with Hertz.

   A scene may be a part of a symmetric model (a quarter ball on a quarter
   block, the planes x = 0 and y = 0 on rollers), declared by
   -contact_<pair>_symmetry x=0,y=0. The whole model is the part and its
   mirror images about each plane: its force is the part's with the
   components normal to the planes cancelled and the others multiplied by
   share = 2^(planes), its contact area share times the part's, and every
   radial figure is the part's (the images of a node lie at its distance
   from the axis through the planes). Nodes on a plane carry in the part
   the half of their weight A_j that lies on its side, so no node is
   counted twice.

   With p_j the slave's nodal pressures and A_j = int W_j dS their weights
   (mortar3d.c), measured in the reference configuration as the r-z
   report does (its rows are the nodes' reference radii):
     area  = share sum_{p_j > 0} A_j, a_area = sqrt(area / pi): the nodal
             contact area, reaching half a node's support past the last
             node in contact: an upper estimate, by up to about h / 2 on a;
     a_m   = sqrt(5/2 sum p_j A_j r_j^2 / sum p_j A_j), since Hertz's
             profile has int p r^2 dA / int p dA = 2 a^2 / 5 (a radius from
             the whole profile, not from where its last node happens to be);
     r_j   the distance from X_j to the axis through the centre c along the
           force's direction n, c the centroid of p_j A_j X_j moved onto
           each symmetry plane (where the whole model's centroid lies).
   Hertz, two spheres (1/R* = 1/R1 + 1/R2, E* of both bodies):
     a = (3 P R* / (4 E*))^(1/3),  p0 = 3 P / (2 pi a^2),
   P the whole model's force, and the relative L2 distance
     sqrt(sum_j A_j (p_j - p_H(r_j))^2 / sum_j A_j p_H(r_j)^2)
   over every slave node, p_H(r) = p0 sqrt(1 - r^2/a^2) inside a. */
#include "report3d.h"
#include "contactreport.h"

static PetscReal Report3dRadius2(const ContactReport3d *R, const PetscReal X[3])
{
  PetscReal d[3], dn = 0.0, d2 = 0.0;

  for (PetscInt k = 0; k < 3; ++k) {
    d[k] = X[k] - R->centre[k];
    dn += d[k] * R->normal[k];
    d2 += d[k] * d[k];
  }
  return PetscMax(d2 - dn * dn, 0.0);
}

/* The whole model's force and its direction. */
static void Report3dForce(const ContactPairSpec *spec, const PetscReal F[3], ContactReport3d *R)
{
  R->share = 1.0;
  for (PetscInt k = 0; k < 3; ++k) R->force[k] = F[k];
  for (PetscInt s = 0; s < spec->nsym; ++s) {
    R->share *= 2.0;
    R->force[spec->symAxis[s]] = 0.0;
  }
  R->P = 0.0;
  for (PetscInt k = 0; k < 3; ++k) {
    R->force[k] *= R->share;
    R->P += R->force[k] * R->force[k];
  }
  R->P = PetscSqrtReal(R->P);
  for (PetscInt k = 0; k < 3; ++k) R->normal[k] = R->P > 0 ? R->force[k] / R->P : (k == 2 ? 1.0 : 0.0);
}

void ContactReport3dCompute(const ContactPairSpec *spec, PetscInt n, const PetscReal X[], const PetscReal p[], const PetscReal A[], const PetscReal F[3], ContactReport3d *R)
{
  PetscReal w = 0.0, m2 = 0.0, err = 0.0, nrm = 0.0;

  PetscMemzero(R, sizeof(*R));
  Report3dForce(spec, F, R);
  for (PetscInt j = 0; j < n; ++j) {
    if (!(p[j] > 0)) continue;
    w += p[j] * A[j];
    for (PetscInt k = 0; k < 3; ++k) R->centre[k] += p[j] * A[j] * X[3 * j + k];
    R->area += A[j];
    R->pmax = PetscMax(R->pmax, p[j]);
  }
  for (PetscInt k = 0; k < 3; ++k) R->centre[k] = w > 0 ? R->centre[k] / w : 0.0;
  for (PetscInt s = 0; s < spec->nsym; ++s) R->centre[spec->symAxis[s]] = spec->symValue[s];
  for (PetscInt j = 0; j < n; ++j)
    if (p[j] > 0) m2 += p[j] * A[j] * Report3dRadius2(R, &X[3 * j]);
  R->area *= R->share;
  R->aArea   = PetscSqrtReal(R->area / PETSC_PI);
  R->aMoment = w > 0 ? PetscSqrtReal(2.5 * m2 / w) : 0.0;
  R->l2err   = (PetscReal)NAN;
  if (!spec->hertz || !(R->P > 0)) return;
  HertzPointContact(R->P, spec->Estar, spec->Rstar, &R->hertzA, &R->hertzP0);
  for (PetscInt j = 0; j < n; ++j) {
    const PetscReal ph = HertzPressure(R->hertzP0, R->hertzA, PetscSqrtReal(Report3dRadius2(R, &X[3 * j])));
    err += A[j] * PetscSqr(p[j] - ph);
    nrm += A[j] * ph * ph;
  }
  R->l2err = nrm > 0 ? PetscSqrtReal(err / nrm) : (PetscReal)NAN;
}

static void Report3dPlanes(const ContactPairSpec *spec, char buf[], size_t len)
{
  size_t k = 0;

  buf[0] = 0;
  for (PetscInt s = 0; s < spec->nsym && k < len; ++s) k += (size_t)snprintf(buf + k, len - k, "%s%c = %g", s ? ", " : "", "xyz"[spec->symAxis[s]], (double)spec->symValue[s]);
}

PetscErrorCode ContactReport3dView(const ContactReport3d *R, const ContactPairSpec *spec, MPI_Comm comm)
{
  const PetscReal *F = R->force;

  PetscFunctionBeginUser;
  if (spec->nsym) {
    char planes[96];
    Report3dPlanes(spec, planes, sizeof(planes));
    PetscCall(PetscPrintf(comm, "  the whole model (symmetric about %s: %d times this part): force (%.6g, %.6g, %.6g), P = %.6g, contact area %.6g\n", planes, (int)R->share, (double)F[0], (double)F[1], (double)F[2], (double)R->P, (double)R->area));
  }
  PetscCall(PetscPrintf(comm, "  contact radius a = %.6g from the contact area (sqrt(area/pi)), %.6g from the pressure's second moment (sum p A r^2 / sum p A = 2 a^2/5, reference positions, centre (%.4g, %.4g, %.4g)); p_max = %.6g\n", (double)R->aArea, (double)R->aMoment, (double)R->centre[0], (double)R->centre[1], (double)R->centre[2], (double)R->pmax));
  if (!spec->hertz) PetscFunctionReturn(0);
  if (!(R->P > 0)) {
    PetscCall(PetscPrintf(comm, "  no contact force: nothing to compare with Hertz\n"));
    PetscFunctionReturn(0);
  }
  PetscCall(PetscPrintf(comm, "  Hertz, two spheres (E* = %g, R* = %g, P = %.6g): a = %.6g, p0 = %.6g\n", (double)spec->Estar, (double)spec->Rstar, (double)R->P, (double)R->hertzA, (double)R->hertzP0));
  PetscCall(PetscPrintf(comm, "  computed: a = %.6g (%+.2f %%) from the second moment, %.6g (%+.2f %%) from the area; p_max = %.6g (%+.2f %%); relative L2 error of the nodal pressure %.2f %%\n", (double)R->aMoment, (double)(100 * (R->aMoment / R->hertzA - 1)), (double)R->aArea, (double)(100 * (R->aArea / R->hertzA - 1)), (double)R->pmax,
                        (double)(100 * (R->pmax / R->hertzP0 - 1)), (double)(100 * R->l2err)));
  PetscFunctionReturn(0);
}

void ContactReport3dWriteJSON(const ContactReport3d *R, const ContactPairSpec *spec, FILE *fp, const char sep[], const char forceKey[])
{
  ContactJSONKeyReal(fp, sep, forceKey, R->P);
  ContactJSONKeyReal(fp, sep, "fem_pmax", R->pmax);
  ContactJSONKeyReal(fp, sep, "fem_a", R->aArea);
  ContactJSONKeyReal(fp, sep, "fem_a_moment", R->aMoment);
  ContactJSONKeyReal(fp, sep, "contact_area", R->area);
  if (spec->nsym) {
    char planes[96];
    Report3dPlanes(spec, planes, sizeof(planes));
    fprintf(fp, "%s\"symmetry\": \"%s\"", sep, planes);
    ContactJSONKeyReal(fp, sep, "model_share", R->share);
    ContactJSONKeyVector(fp, sep, "whole_force", 3, R->force);
  }
  if (spec->hertz) ContactHertzJSON(fp, sep, spec, R->hertzA, R->hertzP0, R->l2err);
}
