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
           normal load's direction n, c the centroid of p_j A_j X_j moved onto
           each symmetry plane (where the whole model's centroid lies);
     a_1 >= a_2, the zone's half-axes: sqrt(5 lambda_i), lambda_i the
           eigenvalues of sum p_j A_j d_j d_j^T / sum p_j A_j in the plane
           normal to n (d_j = X_j - c there; about a symmetry plane the
           images cancel the products across it), since Hertz's elliptical
           profile has int p x_i^2 dA / int p dA = a_i^2 / 5 along its axes
           (a_1 = a_2 = a_m on a disc; a line contact's half-width b, its
           profile p0 sqrt(1 - x^2/b^2), is 2 sqrt(lambda_1) = a_1 / 1.118).
           The report names them where a_1 > 1.2 a_2, a zone a disc's radius
           does not describe (a cylinder's strip, crossed cylinders).
   Hertz, two spheres (1/R* = 1/R1 + 1/R2, E* of both bodies):
     a = (3 P R* / (4 E*))^(1/3),  p0 = 3 P / (2 pi a^2),
   P the whole model's normal load, and the relative L2 distance
     sqrt(sum_j A_j (p_j - p_H(r_j))^2 / sum_j A_j p_H(r_j)^2)
   over every slave node, p_H(r) = p0 sqrt(1 - r^2/a^2) inside a.

   With friction, the friction's force on the first body (the part's shear
   force s) is made the whole model's as the force is (its components
   normal to the planes cancel, the rest times share): the tangential load
   Q = |s| and the normal load N = |F - s| of the whole model, so that Q/(mu N)
   is not tilted by the part's share of the radial shear a normal load
   locks in. N, not |F|, is Hertz's load and its direction n the axis r
   is measured from: under Q = 0.15 N the force leans 0.15 rad off the
   normal, which would shorten r along Q by 1.1 % (the second moment's a
   by 0.56 % on tests/test_view3d.py's half ball) and put +0.4 % on
   Hertz's a. The stuck nodes' area, times share, gives the stick radius
   c = sqrt(stick area / pi) (a disc of that area, as a_area is), beside
   Mindlin's c = a (1 - Q/(mu N))^(1/3) of a sphere with the computed a
   (the second moment's); 0 at Q >= mu N (full sliding).

   A part of a symmetric model whose plane is not declared reports the
   part's figures: ContactReport3dCuts finds a coordinate plane along the
   load (not declared) on which the zone ends at nodes of the slave's
   border carrying half p_max or more, and on which nodes of the master's
   border lie (both surfaces end there: a punch's edge on a larger block
   is not such a plane), the zone's other side along that axis not so (a
   patch test's blocks end flush on both), and the report names it and
   the option. */
#include "report3d.h"
#include "contactreport.h"
#include "face3d.h"

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

/* The whole model's force, its friction part S (with friction), the normal
   load N = |F - S| and its direction. */
static void Report3dForce(const ContactPairSpec *spec, const PetscReal F[3], const PetscReal S[], ContactReport3d *R)
{
  PetscReal n[3], t2 = 0.0;

  R->share    = 1.0;
  R->friction = (PetscBool)(S != NULL);
  for (PetscInt k = 0; k < 3; ++k) {
    R->force[k] = F[k];
    R->shear[k] = S ? S[k] : 0.0;
  }
  for (PetscInt s = 0; s < spec->nsym; ++s) {
    R->share *= 2.0;
    R->force[spec->symAxis[s]] = 0.0;
    R->shear[spec->symAxis[s]] = 0.0;
  }
  R->P = R->N = 0.0;
  for (PetscInt k = 0; k < 3; ++k) {
    R->force[k] *= R->share;
    R->shear[k] *= R->share;
    n[k] = R->force[k] - R->shear[k];
    R->P += R->force[k] * R->force[k];
    R->N += n[k] * n[k];
    t2 += R->shear[k] * R->shear[k];
  }
  R->P = PetscSqrtReal(R->P);
  R->N = PetscSqrtReal(R->N);
  R->Q = PetscSqrtReal(t2);
  for (PetscInt k = 0; k < 3; ++k) R->normal[k] = R->N > 0 ? n[k] / R->N : (k == 2 ? 1.0 : 0.0);
}

/* The zone's half-axes and their directions (R->axes, R->axisDir) from the
   second moments of p_j A_j about the centre in the plane normal to the
   normal load; w = sum p_j A_j. */
static void Report3dAxes(const ContactPairSpec *spec, PetscInt n, const PetscReal X[], const PetscReal p[], const PetscReal A[], PetscReal w, ContactReport3d *R)
{
  PetscReal T[3][3] = {{0}}, e[6], m[3] = {0, 0, 0}, lam[2], phi, c, s;

  if (!(w > 0)) return;
  for (PetscInt j = 0; j < n; ++j) {
    PetscReal d[3], dn = 0.0;
    if (!(p[j] > 0)) continue;
    for (PetscInt k = 0; k < 3; ++k) dn += (X[3 * j + k] - R->centre[k]) * R->normal[k];
    for (PetscInt k = 0; k < 3; ++k) d[k] = X[3 * j + k] - R->centre[k] - dn * R->normal[k];
    for (PetscInt a = 0; a < 3; ++a)
      for (PetscInt b = 0; b < 3; ++b) T[a][b] += p[j] * A[j] * d[a] * d[b] / w;
  }
  for (PetscInt q = 0; q < spec->nsym; ++q) /* a mirror image flips its plane's coordinate */
    for (PetscInt b = 0; b < 3; ++b)
      if (b != spec->symAxis[q]) T[spec->symAxis[q]][b] = T[b][spec->symAxis[q]] = 0.0;
  Face3dPlaneBasis(R->normal, e);
  for (PetscInt a = 0; a < 3; ++a) /* m = (e1 T e1, e1 T e2, e2 T e2) */
    for (PetscInt b = 0; b < 3; ++b) {
      m[0] += e[a] * T[a][b] * e[b];
      m[1] += e[a] * T[a][b] * e[3 + b];
      m[2] += e[3 + a] * T[a][b] * e[3 + b];
    }
  c      = PetscSqrtReal(PetscSqr(m[0] - m[2]) + 4 * m[1] * m[1]);
  lam[0] = 0.5 * (m[0] + m[2] + c);
  lam[1] = PetscMax(0.5 * (m[0] + m[2] - c), 0.0);
  phi    = 0.5 * PetscAtan2Real(2 * m[1], m[0] - m[2]);
  c      = PetscCosReal(phi);
  s      = PetscSinReal(phi);
  for (PetscInt i = 0; i < 2; ++i) R->axes[i] = PetscSqrtReal(5 * lam[i]);
  for (PetscInt k = 0; k < 3; ++k) {
    R->axisDir[0][k] = c * e[k] + s * e[3 + k];
    R->axisDir[1][k] = -s * e[k] + c * e[3 + k];
  }
  for (PetscInt i = 0; i < 2; ++i) { /* each direction's largest component positive */
    PetscInt big = 0;
    for (PetscInt k = 1; k < 3; ++k)
      if (PetscAbsReal(R->axisDir[i][k]) > PetscAbsReal(R->axisDir[i][big])) big = k;
    if (R->axisDir[i][big] < 0)
      for (PetscInt k = 0; k < 3; ++k) R->axisDir[i][k] = -R->axisDir[i][k];
  }
}

/* Where the zone's half-axes differ by more than this ratio the report
   names them. */
#define REPORT3D_ELONGATED 1.2

void ContactReport3dCompute(const ContactPairSpec *spec, PetscInt n, const PetscReal X[], const PetscReal p[], const PetscReal A[], const PetscReal F[3], const PetscReal shear[], ContactReport3d *R)
{
  PetscReal w = 0.0, m2 = 0.0, err = 0.0, nrm = 0.0;

  PetscMemzero(R, sizeof(*R));
  Report3dForce(spec, F, shear, R);
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
  Report3dAxes(spec, n, X, p, A, w, R);
  R->area *= R->share;
  R->aArea   = PetscSqrtReal(R->area / PETSC_PI);
  R->aMoment = w > 0 ? PetscSqrtReal(2.5 * m2 / w) : 0.0;
  R->l2err   = (PetscReal)NAN;
  if (!spec->hertz || !(R->N > 0)) return;
  HertzPointContact(R->N, spec->Estar, spec->Rstar, &R->hertzA, &R->hertzP0);
  for (PetscInt j = 0; j < n; ++j) {
    const PetscReal ph = HertzPressure(R->hertzP0, R->hertzA, PetscSqrtReal(Report3dRadius2(R, &X[3 * j])));
    err += A[j] * PetscSqr(p[j] - ph);
    nrm += A[j] * ph * ph;
  }
  R->l2err = nrm > 0 ? PetscSqrtReal(err / nrm) : (PetscReal)NAN;
}

/* Nodes within this fraction of the zone's extent of a plane lie on it. */
#define REPORT3D_CUT_TOL 1e-8

void ContactReport3dCuts(const ContactPairSpec *spec, PetscInt n, const PetscReal X[], const PetscReal p[], const PetscBool sbnd[], PetscInt nb, const PetscReal Xb[], ContactReport3d *R)
{
  R->ncut = 0;
  if (!(R->pmax > 0)) return;
  for (PetscInt k = 0; k < 3; ++k) {
    PetscReal lo = PETSC_MAX_REAL, hi = -PETSC_MAX_REAL, tol, pv[2] = {0.0, 0.0};
    PetscBool declared = PETSC_FALSE, cut[2];
    for (PetscInt s = 0; s < spec->nsym; ++s) declared = (PetscBool)(declared || spec->symAxis[s] == k);
    if (declared || PetscAbsReal(R->normal[k]) > 0.5) continue;
    for (PetscInt j = 0; j < n; ++j)
      if (p[j] > 0) {
        lo = PetscMin(lo, X[3 * j + k]);
        hi = PetscMax(hi, X[3 * j + k]);
      }
    if (!(hi > lo)) continue;
    tol = REPORT3D_CUT_TOL * (hi - lo);
    for (PetscInt e = 0; e < 2; ++e) {
      const PetscReal v  = e ? hi : lo;
      PetscInt        ns = 0, nm = 0;
      for (PetscInt j = 0; j < n; ++j)
        if (p[j] > 0 && sbnd[j] && PetscAbsReal(X[3 * j + k] - v) <= tol) {
          ns++;
          pv[e] = PetscMax(pv[e], p[j]);
        }
      for (PetscInt j = 0; j < nb; ++j) nm += PetscAbsReal(Xb[3 * j + k] - v) <= tol;
      cut[e] = (PetscBool)(ns >= 2 && nm >= 2 && pv[e] >= 0.5 * R->pmax);
    }
    if (cut[0] == cut[1]) continue; /* a zone the surfaces' ends bound on both sides (a patch test's blocks end flush) is not a half */
    R->cutAxis[R->ncut]  = k;
    R->cutValue[R->ncut] = cut[0] ? (PetscAbsReal(lo) <= tol ? 0.0 : lo) : (PetscAbsReal(hi) <= tol ? 0.0 : hi); /* a plane through the origin, not its round-off */
    R->cutP[R->ncut++]   = pv[cut[0] ? 0 : 1] / R->pmax;
  }
}

void ContactReport3dFriction(PetscReal mu, PetscReal stickArea, ContactReport3d *R)
{
  R->mu          = mu;
  R->stickArea   = R->share * stickArea;
  R->stickRadius = PetscSqrtReal(R->stickArea / PETSC_PI);
  R->mindlinC    = mu > 0 && R->Q < mu * R->N ? R->aMoment * PetscCbrtReal(1 - R->Q / (mu * R->N)) : 0.0;
}

PetscInt ContactReport3dAttributes(const ContactReport3d *R, const char *names[], PetscReal vals[])
{
  const char *fixed[] = {"centre_x", "centre_y", "centre_z", "axis_x", "axis_y", "axis_z", "half_axis_1", "half_axis_2", "half_axis_1_x", "half_axis_1_y", "half_axis_1_z"};
  const char *fric[]  = {"whole_normal_load", "whole_tangential_load", "whole_stick_area", "whole_stick_radius", "mindlin_c", "shear_axis_x", "shear_axis_y", "shear_axis_z"};
  PetscInt    n       = 0;

  for (PetscInt k = 0; k < 3; ++k) {
    names[n]   = fixed[k];
    vals[n++]  = R->centre[k];
  }
  for (PetscInt k = 0; k < 3; ++k) {
    names[n]  = fixed[3 + k];
    vals[n++] = R->normal[k];
  }
  for (PetscInt k = 0; k < 2; ++k) {
    names[n]  = fixed[6 + k];
    vals[n++] = R->axes[k];
  }
  for (PetscInt k = 0; k < 3; ++k) {
    names[n]  = fixed[8 + k];
    vals[n++] = R->axisDir[0][k];
  }
  if (!R->friction) return n;
  {
    const PetscReal v[5] = {R->N, R->Q, R->stickArea, R->stickRadius, R->mindlinC};
    for (PetscInt k = 0; k < 5; ++k) {
      names[n]  = fric[k];
      vals[n++] = v[k];
    }
  }
  for (PetscInt k = 0; k < 3; ++k) {
    names[n]  = fric[5 + k];
    vals[n++] = R->Q > 0 ? R->shear[k] / R->Q : 0.0;
  }
  return n;
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
  if (R->ncut) {
    char   planes[96], opt[64];
    size_t k = 0, o = 0;
    for (PetscInt c = 0; c < spec->nsym; ++c) o += (size_t)snprintf(opt + o, sizeof(opt) - o, "%c=%g,", "xyz"[spec->symAxis[c]], (double)spec->symValue[c]);
    for (PetscInt c = 0; c < R->ncut; ++c) {
      k += (size_t)snprintf(planes + k, sizeof(planes) - k, "%s%c = %g (up to %.2f p_max on it)", c ? ", " : "", "xyz"[R->cutAxis[c]], (double)R->cutValue[c], (double)R->cutP[c]);
      o += (size_t)snprintf(opt + o, sizeof(opt) - o, "%s%c=%g", c ? "," : "", "xyz"[R->cutAxis[c]], (double)R->cutValue[c]);
    }
    PetscCall(PetscPrintf(comm, "  note: the zone is cut by the plane%s %s, where both surfaces end: if the scene is a part of a symmetric model, -contact_%s_symmetry %s reports the whole model (its load, contact radius and Hertz's figures), which the part's above are not\n", R->ncut > 1 ? "s" : "", planes, spec->name, opt));
  }
  if (R->axes[0] > REPORT3D_ELONGATED * R->axes[1]) {
    const PetscReal *d = R->axisDir[0], *e = R->axisDir[1];
    PetscCall(PetscPrintf(comm, "  the zone is not a disc: half-axes %.6g along (%.3g, %.3g, %.3g) and %.6g along (%.3g, %.3g, %.3g) (sqrt(5 sum p A x_i^2 / sum p A), Hertz's ellipse; a line contact's half-width is %.6g, 2 sqrt(sum p A x^2 / sum p A)), so a disc's radius above is not its size\n", (double)R->axes[0], (double)d[0], (double)d[1], (double)d[2],
                          (double)R->axes[1], (double)e[0], (double)e[1], (double)e[2], (double)(R->axes[0] * 2 / PetscSqrtReal(5.0))));
  }
  if (R->friction) {
    PetscCall(PetscPrintf(comm, "  %s: P = %.6g (the normal load), Q = %.6g, Q/(mu P) = %.6g; a = %.6g (area), %.6g (second moment); p_max = %.6g; stick radius c = %.6g (sqrt(stick area/pi), c/a = %.4f, a the second moment's); Mindlin's c = %.6g (c/a = (1 - Q/(mu P))^(1/3) = %.4f, for Q after P at constant P)\n", spec->nsym ? "the whole model" : "the pair",
                          (double)R->N, (double)R->Q, (double)(R->N > 0 ? R->Q / (R->mu * R->N) : 0.0), (double)R->aArea, (double)R->aMoment, (double)R->pmax, (double)R->stickRadius, (double)(R->aMoment > 0 ? R->stickRadius / R->aMoment : 0.0), (double)R->mindlinC,
                          (double)(R->aMoment > 0 ? R->mindlinC / R->aMoment : 0.0)));
  }
  if (!spec->hertz) PetscFunctionReturn(0);
  if (!(R->N > 0)) {
    PetscCall(PetscPrintf(comm, "  no contact force: nothing to compare with Hertz\n"));
    PetscFunctionReturn(0);
  }
  PetscCall(PetscPrintf(comm, "  Hertz, two spheres (E* = %g, R* = %g, P = %.6g): a = %.6g, p0 = %.6g\n", (double)spec->Estar, (double)spec->Rstar, (double)R->N, (double)R->hertzA, (double)R->hertzP0));
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
  ContactJSONKeyVector(fp, sep, "fem_half_axes", 2, R->axes);
  ContactJSONKeyVector(fp, sep, "fem_half_axis_1", 3, R->axisDir[0]);
  if (spec->nsym) {
    char planes[96];
    Report3dPlanes(spec, planes, sizeof(planes));
    fprintf(fp, "%s\"symmetry\": \"%s\"", sep, planes);
    ContactJSONKeyReal(fp, sep, "model_share", R->share);
    ContactJSONKeyVector(fp, sep, "whole_force", 3, R->force);
  }
  if (spec->hertz) ContactHertzJSON(fp, sep, spec, R->hertzA, R->hertzP0, R->l2err);
}

void ContactReport3dWriteFrictionJSON(const ContactReport3d *R, FILE *fp, const char sep[])
{
  ContactJSONKeyReal(fp, sep, "whole_normal_load", R->N);
  ContactJSONKeyReal(fp, sep, "whole_tangential_load", R->Q);
  ContactJSONKeyReal(fp, sep, "whole_stick_area", R->stickArea);
  ContactJSONKeyReal(fp, sep, "whole_stick_radius", R->stickRadius);
  ContactJSONKeyReal(fp, sep, "mindlin_c", R->mindlinC);
}
