/* Nodal fields of a body for output: the second-order nodal mesh
   (coordinates, connectivity in XDMF node order: Tri6/Quad9, Tet10/Hex27,
   cellorder.c), displacement, and the stress (xx, yy, zz, xy; in
   axisymmetry rr, zz, thth, rz: the third the hoop stress; a 3D body's
   xx, yy, zz, xy, yz, xz) and von Mises stress recovered at the nodes
   by averaging each cell's stress there over the cells around the node.
   The stress is the material's Cauchy stress (material.h): of the deformed
   configuration, attached to each node's reference position; a material
   with history is given the accepted state of the quadrature point nearest
   the node (NodeState). */
#include <petscsf.h>
#include "body.h"
#include "element.h"
#include "bodyimpl.h"

static PetscErrorCode CreateBlockVec(MPI_Comm comm, PetscInt n, PetscInt bs, const char name[], Vec *v)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreate(comm, v));
  PetscCall(VecSetSizes(*v, n, PETSC_DETERMINE));
  PetscCall(VecSetBlockSize(*v, bs));
  PetscCall(VecSetType(*v, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)*v, name));
  PetscFunctionReturn(0);
}

/* The stress components the output keeps of a Cauchy stress sig[9]: xx,
   yy, zz, xy, and a 3D body's yz, xz too (BodyStressComponents). */
static inline void StressComponents(PetscInt dim, const PetscReal sig[9], PetscReal s[])
{
  s[0] = sig[0];
  s[1] = sig[4];
  s[2] = sig[8];
  s[3] = sig[1];
  if (dim == 3) {
    s[4] = sig[5];
    s[5] = sig[2];
  }
}

/* The accepted state (material.h) the stress at node a of cell c is
   evaluated with: a material with history keeps it at the quadrature
   points alone, so the node takes that of its cell's nearest point (exact
   where the state is uniform over the cell); NULL for a material without. */
static const PetscReal *NodeState(Body b, PetscInt c, PetscInt a)
{
  const PetscInt   dim = b->dim, nq = b->nq, ns = b->mat->nstate;
  const PetscReal *x = &b->xnode[(c * b->nb + a) * dim];
  PetscInt         best = 0;
  PetscReal        dmin = PETSC_MAX_REAL;

  if (!ns) return NULL;
  for (PetscInt iq = 0; iq < nq; ++iq) {
    const PetscReal *y = &b->xq[(c * nq + iq) * dim];
    PetscReal        d = 0.0;
    for (PetscInt i = 0; i < dim; ++i) d += PetscSqr(y[i] - x[i]);
    if (d < dmin) dmin = d, best = iq;
  }
  return &b->state[(c * nq + best) * ns];
}

/* Per local point: the sums of the stress components (StressComponents)
   of the cells around it at the point, and their count (sr[(ns + 1) *
   point], ns = BodyStressComponents), summed over every rank's cells and
   the same on every rank that has the point. */
static PetscErrorCode BodyStressSums(Body b, const PetscScalar ua[], PetscReal sr[])
{
  const PetscInt  nb = b->nb, dim = b->dim, np = b->pEnd - b->pStart, ns = BodyStressComponents(dim), ns1 = ns + 1;
  PetscSF         sf;
  PetscInt        nroots;
  PetscReal      *sp, refpts[ELEMENT_MAX_DOFS];
  PetscTabulation Tn;

  PetscFunctionBeginUser;
  PetscCall(DMGetPointSF(b->dm, &sf));
  PetscCall(PetscCalloc1(ns1 * np, &sp));
  PetscCall(BodyGetReferenceNodes(b, refpts));
  PetscCall(PetscFECreateTabulation(b->feScalar, 1, nb, refpts, 1, &Tn));
  for (PetscInt c = 0; c < b->ncells; ++c) {
    const PetscInt *pts = &b->cpts[c * nb];
    const PetscReal *x = &b->xnode[c * nb * dim];
    PetscReal        u[ELEMENT_MAX_DOFS], dNdx[ELEMENT_MAX_DOFS];

    ElementGather(b, c, ua, u);
    for (PetscInt a = 0; a < nb; ++a) {
      PetscReal  H[9], sig[9], st[6];
      PetscReal *acc = &sp[ns1 * (pts[a] - b->pStart)];
      (void)BodyElementGradientsDim(dim, nb, x, &Tn->T[1][a * nb * dim], dNdx);
      ElementFormGradient(dim, nb, u, dNdx, H);
      if (b->axisym) H[8] = ElasticityHoopStrain(u[a * dim], H[0], x[a * dim] > b->axisTol ? x[a * dim] : 0.0); /* the node's own u_r and r */
      b->mat->cauchy(b->param, NodeState(b, c, a), H, sig);
      StressComponents(dim, sig, st);
      for (PetscInt j = 0; j < ns; ++j) acc[j] += st[j];
      acc[ns] += 1.0;
    }
  }
  PetscCall(PetscTabulationDestroy(&Tn));
  PetscCall(PetscSFGetGraph(sf, &nroots, NULL, NULL, NULL));
  PetscCall(PetscArraycpy(sr, sp, ns1 * np));
  if (nroots >= 0) {
    MPI_Datatype unit;
    PetscCallMPI(MPI_Type_contiguous((PetscMPIInt)ns1, MPIU_REAL, &unit));
    PetscCallMPI(MPI_Type_commit(&unit));
    PetscCall(PetscSFReduceBegin(sf, unit, sp, sr, MPI_SUM));
    PetscCall(PetscSFReduceEnd(sf, unit, sp, sr, MPI_SUM));
    PetscCall(PetscSFBcastBegin(sf, unit, sr, sr, MPI_REPLACE));
    PetscCall(PetscSFBcastEnd(sf, unit, sr, sr, MPI_REPLACE));
    PetscCallMPI(MPI_Type_free(&unit));
  }
  PetscCall(PetscFree(sp));
  PetscFunctionReturn(0);
}

/* Zienkiewicz-Zhu indicator of each local cell: the L2 norm over the cell of
   the difference between the recovered stress (the nodal averages
   interpolated with the cell's basis) and the cell's own stress,
   eta_K^2 = int_K |sigma* - sigma_h|^2 dA (components xx, yy, zz, xy; xy
   twice; a 3D body's yz and xz twice too). */
PetscErrorCode BodyComputeStressIndicator(Body b, Vec Xl, PetscReal eta[])
{
  const PetscInt     nb = b->nb, nq = b->nq, np = b->pEnd - b->pStart, ns = BodyStressComponents(b->dim), ns1 = ns + 1;
  const PetscScalar *ua;
  PetscReal         *sr;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(ns1 * np, &sr));
  PetscCall(VecGetArrayRead(Xl, &ua));
  PetscCall(BodyStressSums(b, ua, sr));
  for (PetscInt c = 0; c < b->ncells; ++c) {
    const PetscInt *pts = &b->cpts[c * nb];
    PetscReal       e2 = 0.0, u[ELEMENT_MAX_DOFS];

    ElementGather(b, c, ua, u);
    for (PetscInt iq = 0; iq < nq; ++iq) {
      const PetscReal *B = &b->B[iq * nb];
      PetscReal        H[9], sig[9], h[6] = {0, 0, 0, 0, 0, 0}, rec[6] = {0, 0, 0, 0, 0, 0};
      for (PetscInt a = 0; a < nb; ++a) {
        const PetscReal *st = &sr[ns1 * (pts[a] - b->pStart)];
        for (PetscInt j = 0; j < ns; ++j) rec[j] += B[a] * st[j] / st[ns];
      }
      ElementPointGradient(b, c, iq, u, NULL, H);
      b->mat->cauchy(b->param, b->mat->nstate ? &b->state[(c * nq + iq) * b->mat->nstate] : NULL, H, sig);
      StressComponents(b->dim, sig, h);
      if (ns == 4) e2 += b->wdetJ[c * nq + iq] * (PetscSqr(rec[0] - h[0]) + PetscSqr(rec[1] - h[1]) + PetscSqr(rec[2] - h[2]) + 2 * PetscSqr(rec[3] - h[3]));
      else e2 += b->wdetJ[c * nq + iq] * (PetscSqr(rec[0] - h[0]) + PetscSqr(rec[1] - h[1]) + PetscSqr(rec[2] - h[2]) + 2 * (PetscSqr(rec[3] - h[3]) + PetscSqr(rec[4] - h[4]) + PetscSqr(rec[5] - h[5])));
    }
    eta[c] = PetscSqrtReal(e2);
  }
  PetscCall(VecRestoreArrayRead(Xl, &ua));
  PetscCall(PetscFree(sr));
  PetscFunctionReturn(0);
}

/* The largest principal Green-Lagrange strain, in magnitude, over every
   rank's quadrature points: E = (F^T F - I)/2 with F = I + H (material.h).
   The measure of a linear body's model error: small-strain elasticity
   drops the quadratic terms of E. */
/* The largest eigenvalue, in magnitude, of a symmetric 3 x 3 E: where row
   and column 2 are off-diagonal-free (plane strain, r-z), the (0, 1)
   block's |mean| + radius and |E_22|; else the trigonometric solution of
   the characteristic cubic (Smith 1961), its largest and smallest roots. */
static PetscReal SymmetricMaxAbsEigenvalue(const PetscReal E[9])
{
  if (E[2] == 0.0 && E[5] == 0.0) {
    const PetscReal mean = 0.5 * (E[0] + E[4]), rad = PetscSqrtReal(0.25 * PetscSqr(E[0] - E[4]) + E[1] * E[1]);
    return PetscMax(PetscAbsReal(mean) + rad, PetscAbsReal(E[8]));
  } else {
    const PetscReal q = (E[0] + E[4] + E[8]) / 3.0, p1 = E[1] * E[1] + E[2] * E[2] + E[5] * E[5];
    const PetscReal p = PetscSqrtReal((PetscSqr(E[0] - q) + PetscSqr(E[4] - q) + PetscSqr(E[8] - q) + 2.0 * p1) / 6.0);
    const PetscReal b0 = (E[0] - q) / p, b4 = (E[4] - q) / p, b8 = (E[8] - q) / p, b1 = E[1] / p, b2 = E[2] / p, b5 = E[5] / p;
    const PetscReal r   = 0.5 * (b0 * (b4 * b8 - b5 * b5) - b1 * (b1 * b8 - b5 * b2) + b2 * (b1 * b5 - b4 * b2));
    const PetscReal phi = PetscAcosReal(PetscMax(-1.0, PetscMin(1.0, r))) / 3.0;
    return PetscMax(PetscAbsReal(q + 2.0 * p * PetscCosReal(phi)), PetscAbsReal(q + 2.0 * p * PetscCosReal(phi + 2.0 * PETSC_PI / 3.0)));
  }
}

/* The largest principal Green-Lagrange strain, in magnitude, at quadrature
   point iq of cell c, of nodal displacements u (ElementGather): E_IJ =
   (H_IJ + H_JI + H_kI H_kJ) / 2 of the 3 x 3 displacement gradient (in r-z
   E_22 = e3 + e3^2 / 2 of the hoop strain). */
static PetscReal BodyStrainAt(Body b, const PetscReal u[], PetscInt c, PetscInt iq)
{
  PetscReal H[9], E[9];

  ElementPointGradient(b, c, iq, u, NULL, H);
  for (PetscInt P = 0; P < 3; ++P)
    for (PetscInt Q = 0; Q < 3; ++Q) {
      E[P * 3 + Q] = P == Q ? H[P * 4] + 0.5 * (H[P] * H[P] + H[3 + P] * H[3 + P] + H[6 + P] * H[6 + P]) : 0.5 * (H[P * 3 + Q] + H[Q * 3 + P] + H[P] * H[Q] + H[3 + P] * H[3 + Q] + H[6 + P] * H[6 + Q]);
    }
  return SymmetricMaxAbsEigenvalue(E);
}

PetscErrorCode BodyComputeMaxStrain(Body b, Vec Xl, PetscReal *emax)
{
  const PetscScalar *ua;
  PetscReal          m = 0.0;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(Xl, &ua));
  for (PetscInt c = 0; c < b->ncells; ++c) {
    PetscReal u[ELEMENT_MAX_DOFS];
    ElementGather(b, c, ua, u);
    for (PetscInt iq = 0; iq < b->nq; ++iq) m = PetscMax(m, BodyStrainAt(b, u, c, iq));
  }
  PetscCall(VecRestoreArrayRead(Xl, &ua));
  PetscCall(MPIU_Allreduce(&m, emax, 1, MPIU_REAL, MPIU_MAX, b->comm));
  PetscFunctionReturn(0);
}

/* Where the largest strain sits and whether it is a point's. A smooth strain
   field changes over a length of the load's scale (a Hertz zone, a wall's
   thickness), many elements: 2 to 4 elements from its peak it is still
   0.9 to 1.0 of it (measured: the reference scene's block under the contact
   0.90 at h = 0.1, the sphere's bodies 0.996 and 0.998, the roller's 0.99 to
   0.997, the tube's 1.0, the rubber disc's 0.9993). At a singular point,
   where the strain goes as r^-lambda (a punch's corner, the end of a
   clamped boundary, a re-entrant corner), the peak is the element's next to
   the point and grows as the mesh is refined there, and 2 to 4 elements away
   the strain is a third to three quarters of it (the reference scene's disc
   at the end of its clamp 0.36, and 0.33 at h = 0.05; the meshes/punch
   block at the punch's corner 0.31, the punch 0.43; a rigid flat punch's
   edge in a block at h = 0.02, 0.01, 0.0075, 0.005: 0.53, 0.61, 0.75,
   0.72, the penalty's contact edge spreading over about an element). Below
   BODY_STRAIN_POINT = 0.8 of the peak, between the two, the peak is taken
   for a point's; the margin to the smooth fields is thin (0.75 against
   0.90), and a peak whose ring reaches another singular point reads as
   smooth (the old advice). ring is the largest strain between
   BODY_STRAIN_RING / 2 and BODY_STRAIN_RING cell sizes h from the peak (h
   the square root of the peak's cell's area, 0.66 of a Tri6's edge; a 3D
   body's: the cube root of its volume, and x has 3 coordinates). */
PetscErrorCode BodyComputeStrainPeak(Body b, Vec Xl, BodyStrainPeak *pk)
{
  const PetscInt     nq = b->nq, dim = b->dim;
  const PetscScalar *ua;
  struct {
    double v;
    int    r;
  } loc = {0.0, 0}, glob;
  PetscMPIInt rank;
  PetscInt    cbest = -1, qbest = -1;
  PetscReal   xh[4] = {0, 0, 0, 0}, m = 0.0; /* x, y, z, h */

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(b->comm, &rank));
  PetscCall(VecGetArrayRead(Xl, &ua));
  for (PetscInt c = 0; c < b->ncells; ++c) {
    PetscReal u[ELEMENT_MAX_DOFS];
    ElementGather(b, c, ua, u);
    for (PetscInt iq = 0; iq < nq; ++iq) {
      const PetscReal e = BodyStrainAt(b, u, c, iq);
      if (cbest < 0 || e > loc.v) {
        loc.v = (double)e;
        cbest = c;
        qbest = iq;
      }
    }
  }
  loc.r = (int)rank;
  PetscCallMPI(MPI_Allreduce(&loc, &glob, 1, MPI_DOUBLE_INT, MPI_MAXLOC, b->comm));
  if (rank == glob.r && cbest >= 0) {
    PetscReal area = 0.0;
    for (PetscInt iq = 0; iq < nq; ++iq) area += b->wdetJ[cbest * nq + iq] / BodyRadialWeight(b, b->xq[(cbest * nq + iq) * dim]);
    for (PetscInt d = 0; d < dim; ++d) xh[d] = b->xq[(cbest * nq + qbest) * dim + d];
    xh[3] = dim == 3 ? PetscCbrtReal(area) : PetscSqrtReal(area);
  }
  PetscCallMPI(MPI_Bcast(xh, 4, MPIU_REAL, glob.r, b->comm));
  pk->emax = (PetscReal)glob.v;
  pk->x[0] = xh[0];
  pk->x[1] = xh[1];
  pk->x[2] = xh[2];
  pk->h    = xh[3];
  for (PetscInt c = 0; c < b->ncells; ++c) {
    PetscReal u[ELEMENT_MAX_DOFS];
    ElementGather(b, c, ua, u);
    for (PetscInt iq = 0; iq < nq; ++iq) {
      const PetscReal *x = &b->xq[(c * nq + iq) * dim], e = BodyStrainAt(b, u, c, iq);
      const PetscReal  d = dim == 3 ? PetscSqrtReal(PetscSqr(x[0] - pk->x[0]) + PetscSqr(x[1] - pk->x[1]) + PetscSqr(x[2] - pk->x[2])) : PetscSqrtReal(PetscSqr(x[0] - pk->x[0]) + PetscSqr(x[1] - pk->x[1]));
      if (d > 0.5 * BODY_STRAIN_RING * pk->h && d <= BODY_STRAIN_RING * pk->h) m = PetscMax(m, e);
    }
  }
  PetscCall(VecRestoreArrayRead(Xl, &ua));
  PetscCall(MPIU_Allreduce(&m, &pk->ring, 1, MPIU_REAL, MPIU_MAX, b->comm));
  PetscFunctionReturn(0);
}

/* Node values are computed per local point (arrays over the chart); owned
   points are numbered by the body's node numbering, and the stress sums of the
   cells around a node are reduced from ghosts to owners over the point SF. */
PetscErrorCode BodyComputeNodalFields(Body b, Vec Xl, BodyNodalFields *F)
{
  PetscSection       s;
  const PetscScalar *ua;
  const PetscInt     nb = b->nb, np = b->pEnd - b->pStart, dim = b->dim, ns = BodyStressComponents(dim), ns1 = ns + 1;
  PetscInt           nown = 0, rstart = 0, *topo;
  PetscReal         *sr;
  PetscReal          loc[2] = {0, 0}, glob[2];
  PetscScalar       *ax, *au, *as, *av;

  PetscFunctionBeginUser;
  if (b->rigid) { /* no cells: no fields */
    PetscCall(PetscMemzero(F, sizeof(*F)));
    PetscFunctionReturn(0);
  }
  PetscCall(DMGetLocalSection(b->dm, &s));
  for (PetscInt p = b->pStart; p < b->pEnd; ++p) {
    PetscInt gdof;
    PetscCall(PetscSectionGetDof(b->nodeGS, p, &gdof));
    if (gdof > 0) nown += gdof;
  }
  PetscCallMPI(MPI_Exscan(&nown, &rstart, 1, MPIU_INT, MPI_SUM, b->comm));
  PetscCall(CreateBlockVec(b->comm, dim * nown, dim, "geometry", &F->coords));
  PetscCall(CreateBlockVec(b->comm, dim * nown, dim, "displacement", &F->disp));
  PetscCall(CreateBlockVec(b->comm, ns * nown, ns, "stress", &F->stress));
  PetscCall(CreateBlockVec(b->comm, nown, 1, "von_mises", &F->vm));
  PetscCall(VecGetSize(F->vm, &F->nnodes));
  PetscCall(PetscMalloc1(ns1 * np, &sr));
  PetscCall(PetscMalloc1(b->ncells * nb, &topo));
  PetscCall(VecGetArrayRead(Xl, &ua));
  for (PetscInt c = 0; c < b->ncells; ++c) PetscCall(BodyCellOutputNodes(b, c, &topo[c * nb]));
  PetscCall(BodyStressSums(b, ua, sr));
  PetscCall(VecGetArray(F->coords, &ax));
  PetscCall(VecGetArray(F->disp, &au));
  PetscCall(VecGetArray(F->stress, &as));
  PetscCall(VecGetArray(F->vm, &av));
  for (PetscInt p = b->pStart; p < b->pEnd; ++p) {
    PetscInt   gdof, goff, off, i;
    PetscReal  um2 = 0.0, *st = &sr[ns1 * (p - b->pStart)];
    PetscCall(PetscSectionGetDof(b->nodeGS, p, &gdof));
    if (gdof <= 0) continue;
    PetscCall(PetscSectionGetOffset(b->nodeGS, p, &goff));
    PetscCall(PetscSectionGetOffset(s, p, &off));
    i             = goff - rstart;
    for (PetscInt d = 0; d < dim; ++d) {
      ax[dim * i + d] = b->xpoint[dim * (p - b->pStart) + d];
      au[dim * i + d] = ua[off + d];
    }
    for (PetscInt j = 0; j < ns; ++j) as[ns * i + j] = st[j] / st[ns];
    {
      const PetscReal xx = st[0] / st[ns], yy = st[1] / st[ns], zz = st[2] / st[ns], xy = st[3] / st[ns];
      const PetscReal yz = dim == 3 ? st[4] / st[ns] : 0.0, xz = dim == 3 ? st[5] / st[ns] : 0.0;
      const PetscReal sg[9] = {xx, xy, xz, xy, yy, yz, xz, yz, zz};
      av[i] = ElasticityVonMises(sg);
    }
    for (PetscInt d = 0; d < dim; ++d) um2 += PetscSqr(PetscRealPart(ua[off + d])); /* every component's: a 3D body's three */
    loc[0] = PetscMax(loc[0], PetscSqrtReal(um2));
    loc[1] += um2;
  }
  PetscCall(VecRestoreArray(F->coords, &ax));
  PetscCall(VecRestoreArray(F->disp, &au));
  PetscCall(VecRestoreArray(F->stress, &as));
  PetscCall(VecRestoreArray(F->vm, &av));
  PetscCall(VecRestoreArrayRead(Xl, &ua));
  PetscCall(PetscFree(sr));
  PetscCall(MPIU_Allreduce(&loc[0], &glob[0], 1, MPIU_REAL, MPIU_MAX, b->comm));
  PetscCall(MPIU_Allreduce(&loc[1], &glob[1], 1, MPIU_REAL, MPIU_SUM, b->comm));
  F->umax   = glob[0];
  F->unorm2 = glob[1];
  PetscCall(ISCreateGeneral(b->comm, b->ncells * nb, topo, PETSC_OWN_POINTER, &F->topo));
  PetscCall(ISSetBlockSize(F->topo, nb));
  PetscCall(PetscObjectSetName((PetscObject)F->topo, "topology"));
  F->ncells = b->ncellsGlobal;
  PetscCall(BodyComputeErrors(b, Xl, &F->err));
  PetscCall(BodyComputeMaxStrain(b, Xl, &F->maxStrain));
  F->nstate = BodyHasState(b) ? b->mat->nstate : 0;
  for (PetscInt k = 0; k < F->nstate; ++k) PetscCall(BodyGetStateRange(b, k, &F->stateMin[k], &F->stateMax[k]));
  PetscFunctionReturn(0);
}

PetscErrorCode BodyNodalFieldsDestroy(BodyNodalFields *F)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&F->coords));
  PetscCall(VecDestroy(&F->disp));
  PetscCall(VecDestroy(&F->stress));
  PetscCall(VecDestroy(&F->vm));
  PetscCall(ISDestroy(&F->topo));
  PetscFunctionReturn(0);
}
