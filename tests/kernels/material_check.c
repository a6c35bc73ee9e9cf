/* A check of the materials' pointwise kernels of the 3 x 3 displacement
   gradient (material.h) at random 3D states, no mesh needed: bin/material-check,
   driven by tests/test_material_kernels.py, which asserts the figures it
   prints, one "material figure value" a line.

   At NSAMPLE random H (entries in [-0.4, 0.4], kept where J = det(I + H) is
   in [0.5, 2]: finite strain; a quarter with entries in [-1e-3, 1e-3]; one
   in 8 with H_02 = H_12 = H_20 = H_21 = 0, as in r-z, where the kernels take
   a shortcut) and a random direction E (entries in [-1, 1]):
     taylor_P_order_min/max   the order of the remainder
                              |W(H + tE) - W(H) - t P:E| between t and t/2, t = 1e-2 ... 1.25e-3 (2 if P = dW/dF);
     taylor_A_order_min/max   the same of |P(H + tE) - P(H) - t A:E| (2 if A = dP/dF);
     fd_P_rel                 |central difference of W at h - P:E| / max(|P:E|, |P| |E|), h = 1e-4 s
                              (s the sample's entry scale: 1e-3 for a quarter of them, 0.4);
     fd_A_rel                 |central difference of P at h - A:E| / (|A| |E|), the largest component;
     sym_A_rel                max |A_iJkL - A_kLiJ| / max |A|;
     cauchy_sym_rel           max |sigma - sigma^T| / max |sigma|;
     cauchy_PFt_rel           max |sigma - P F^T / J| / max |sigma| (linear: max |sigma - P| / max |sigma|);
     frame_W_rel              |W(Q F) - W(F)| / max(|W|, mu |H|^2), Q the rotation by 60 degrees about (1, 2, 3)/sqrt(14);
     frame_P_rel              max |P(Q F) - Q P(F)| / max |P|;
     rotation_W, rotation_P   W and max |P| / mu at F = Q (a pure rotation);
   and once:
     rest_A_rel               max |A(0) - C| / max |C|, C_ijkl = lambda d_ij d_kl + mu (d_ik d_jl + d_il d_jk);
     plane_W_rel, plane_P_rel (plane strain: row and column 2 of H zero) the largest
                              difference from the 2D kernels' formulas (written out below, as
                              the program had them), relative to |W| and max |P|, P in-plane;
     plane_P22_rel            the same of the out-of-plane P_22 (F^-1_22 = adj_22 / J, not 1 / F_22);
     rz_W_rel, rz_P_rel       the same with H[8] = e3 (axisymmetry's hoop strain).
   The linear material's W is quadratic: its Taylor remainders are exact at
   order 2 and its frame figures are not asked (small strain is not frame
   invariant). */
#include <petscsys.h>
#include "contact.h"
#include "material.h"

#define NSAMPLE 200

#include "checkutil.h"

static PetscReal Energy(const Material *m, const PetscReal p[], const PetscReal H[9], PetscReal P[9])
{
  PetscReal W, Pl[9];
  (void)m->energy(p, NULL, H, &W, P ? P : Pl);
  return W;
}

/* The 2D kernels' formulas (in-plane gu[i*2+J], out-of-plane e3): W, the
   in-plane P and P33. Linear: W = lambda/2 tr^2 + mu (exx^2 + eyy^2 + e3^2 +
   2 exy^2); neo-Hookean: W = mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2 with
   F block diagonal, P = mu (F - F^-T) + lambda ln J F^-T. */
static void Old2D(PetscBool neo, const PetscReal p[], const PetscReal gu[4], PetscReal e3, PetscReal *W, PetscReal P[4], PetscReal *P33)
{
  const PetscReal lambda = p[0], mu = p[1];
  if (!neo) {
    const PetscReal exx = gu[0], eyy = gu[3], exy = 0.5 * (gu[1] + gu[2]), tr = exx + eyy + e3;
    *W   = 0.5 * lambda * tr * tr + mu * (exx * exx + eyy * eyy + e3 * e3 + 2.0 * exy * exy);
    P[0] = lambda * tr + 2.0 * mu * exx;
    P[1] = P[2] = 2.0 * mu * exy;
    P[3] = lambda * tr + 2.0 * mu * eyy;
    *P33 = lambda * tr + 2.0 * mu * e3;
  } else {
    const PetscReal d2m1 = gu[0] + gu[3] + gu[0] * gu[3] - gu[1] * gu[2], Jm1 = d2m1 + e3 + d2m1 * e3, d2 = 1.0 + d2m1, lnJ = log1p(Jm1), F33 = 1.0 + e3;
    const PetscReal F[4] = {1.0 + gu[0], gu[1], gu[2], 1.0 + gu[3]}, Fi[4] = {F[3] / d2, -F[1] / d2, -F[2] / d2, F[0] / d2};
    const PetscReal I1m3 = 2.0 * (gu[0] + gu[3] + e3) + gu[0] * gu[0] + gu[1] * gu[1] + gu[2] * gu[2] + gu[3] * gu[3] + e3 * e3;
    *W = 0.5 * mu * (I1m3 - 2.0 * lnJ) + 0.5 * lambda * lnJ * lnJ;
    for (PetscInt i = 0; i < 2; ++i)
      for (PetscInt J = 0; J < 2; ++J) P[i * 2 + J] = mu * (F[i * 2 + J] - Fi[J * 2 + i]) + lambda * lnJ * Fi[J * 2 + i];
    *P33 = mu * (F33 - 1.0 / F33) + lambda * lnJ / F33;
  }
}

/* lambda, mu: the material's Lame constants at rest; old2d: its 2D kernels' formulas are written out here (Old2D). */
static void Check(const Material *m, const PetscReal p[], PetscReal lambda0, PetscReal mu0, PetscBool old2d)
{
  const PetscBool neo = (PetscBool)!m->constantTangent;
  const PetscReal c60 = 0.5, s60 = PetscSqrtReal(3.0) / 2.0;
  PetscReal       n[3] = {1.0 / PetscSqrtReal(14.0), 2.0 / PetscSqrtReal(14.0), 3.0 / PetscSqrtReal(14.0)}, Q[9];
  PetscReal       tPmin = 1e30, tPmax = -1e30, tAmin = 1e30, tAmax = -1e30, fdP = 0, fdA = 0, symA = 0, csym = 0, cPFt = 0, frW = 0, frP = 0;
  PetscReal       plW = 0, plP = 0, plP22 = 0, rzW = 0, rzP = 0;

  /* Rodrigues: Q = cos I + sin [n]x + (1 - cos) n n^T */
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) Q[i * 3 + j] = (i == j ? c60 : 0.0) + (1.0 - c60) * n[i] * n[j];
  Q[1] -= s60 * n[2];
  Q[2] += s60 * n[1];
  Q[3] += s60 * n[2];
  Q[5] -= s60 * n[0];
  Q[6] -= s60 * n[1];
  Q[7] += s60 * n[0];

  for (PetscInt s = 0; s < NSAMPLE; ++s) {
    PetscReal H[9], F[9], E[9], W, P[9], A[81], sig[9], J, scale = s < NSAMPLE / 4 ? 1e-3 : 0.4, h = 1e-4 * scale;
    do {
      for (PetscInt k = 0; k < 9; ++k) H[k] = Uniform(-scale, scale);
      if (s % 8 == 7) H[2] = H[5] = H[6] = H[7] = 0.0; /* block diagonal (r-z): the kernels' shortcut, against the full formulas at H + tE */
      for (PetscInt k = 0; k < 9; ++k) F[k] = (k % 4 == 0 ? 1.0 : 0.0) + H[k];
      J = Det3(F);
    } while (!(J >= 0.5 && J <= 2.0));
    for (PetscInt k = 0; k < 9; ++k) E[k] = Uniform(-1.0, 1.0);
    W = Energy(m, p, H, P);
    m->moduli(p, NULL, H, A);
    m->cauchy(p, NULL, H, sig);
    { /* Taylor remainders of W and P */
      PetscReal rW[4], rP[4], PE = 0.0, AE[9];
      for (PetscInt k = 0; k < 9; ++k) PE += P[k] * E[k];
      for (PetscInt a = 0; a < 9; ++a) {
        AE[a] = 0.0;
        for (PetscInt b = 0; b < 9; ++b) AE[a] += A[a * 9 + b] * E[b];
      }
      for (PetscInt l = 0; l < 4; ++l) {
        const PetscReal t = 1e-2 / (PetscReal)(1 << l);
        PetscReal       Ht[9], Pt[9], Wt, d[9];
        for (PetscInt k = 0; k < 9; ++k) Ht[k] = H[k] + t * E[k];
        Wt = Energy(m, p, Ht, Pt);
        rW[l] = PetscAbsReal(Wt - W - t * PE);
        for (PetscInt k = 0; k < 9; ++k) d[k] = Pt[k] - P[k] - t * AE[k];
        rP[l] = PetscSqrtReal(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + d[3] * d[3] + d[4] * d[4] + d[5] * d[5] + d[6] * d[6] + d[7] * d[7] + d[8] * d[8]);
      }
      for (PetscInt l = 0; l < 3; ++l) {
        const PetscReal oW = PetscLog2Real(rW[l] / rW[l + 1]), oP = PetscLog2Real(rP[l] / rP[l + 1]);
        tPmin = PetscMin(tPmin, oW);
        tPmax = PetscMax(tPmax, oW);
        if (neo) { /* the linear material's P is linear: its remainder is round-off */
          tAmin = PetscMin(tAmin, oP);
          tAmax = PetscMax(tAmax, oP);
        }
      }
      { /* central differences */
        PetscReal Hp[9], Hm[9], Pp[9], Pm[9], Wp, Wm, nE = PetscSqrtReal(9.0) * MaxAbs(9, E);
        for (PetscInt k = 0; k < 9; ++k) {
          Hp[k] = H[k] + h * E[k];
          Hm[k] = H[k] - h * E[k];
        }
        Wp  = Energy(m, p, Hp, Pp);
        Wm  = Energy(m, p, Hm, Pm);
        fdP = PetscMax(fdP, PetscAbsReal((Wp - Wm) / (2 * h) - PE) / PetscMax(PetscAbsReal(PE), MaxAbs(9, P) * nE));
        for (PetscInt k = 0; k < 9; ++k) fdA = PetscMax(fdA, PetscAbsReal((Pp[k] - Pm[k]) / (2 * h) - AE[k]) / (MaxAbs(81, A) * nE));
      }
    }
    for (PetscInt a = 0; a < 9; ++a) /* symmetry of A */
      for (PetscInt b = 0; b < 9; ++b) symA = PetscMax(symA, PetscAbsReal(A[a * 9 + b] - A[b * 9 + a]) / MaxAbs(81, A));
    { /* Cauchy: symmetric, P F^T / J */
      const PetscReal ms = MaxAbs(9, sig);
      for (PetscInt i = 0; i < 3; ++i)
        for (PetscInt j = 0; j < 3; ++j) {
          PetscReal pf = 0.0;
          for (PetscInt k = 0; k < 3; ++k) pf += P[i * 3 + k] * F[j * 3 + k];
          csym = PetscMax(csym, PetscAbsReal(sig[i * 3 + j] - sig[j * 3 + i]) / ms);
          cPFt = PetscMax(cPFt, PetscAbsReal(sig[i * 3 + j] - (neo ? pf / J : P[i * 3 + j])) / ms); /* small strain: sigma = P */
        }
    }
    if (neo) { /* frame invariance: W(QF) = W(F), P(QF) = Q P(F) */
      PetscReal HQ[9], PQ[9], WQ, h2 = 0.0;
      for (PetscInt i = 0; i < 3; ++i)
        for (PetscInt j = 0; j < 3; ++j) {
          HQ[i * 3 + j] = -(i == j ? 1.0 : 0.0);
          for (PetscInt k = 0; k < 3; ++k) HQ[i * 3 + j] += Q[i * 3 + k] * F[k * 3 + j];
        }
      for (PetscInt k = 0; k < 9; ++k) h2 += H[k] * H[k];
      WQ  = Energy(m, p, HQ, PQ);
      frW = PetscMax(frW, PetscAbsReal(WQ - W) / PetscMax(PetscAbsReal(W), mu0 * h2));
      for (PetscInt i = 0; i < 3; ++i)
        for (PetscInt j = 0; j < 3; ++j) {
          PetscReal qp = 0.0;
          for (PetscInt k = 0; k < 3; ++k) qp += Q[i * 3 + k] * P[k * 3 + j];
          frP = PetscMax(frP, PetscAbsReal(PQ[i * 3 + j] - qp) / MaxAbs(9, P));
        }
    }
    if (old2d) { /* plane strain and r-z: the 2D kernels' formulas */
      PetscReal gu[4] = {H[0], H[1], H[3], H[4]}, e3 = H[8], Hp[9] = {H[0], H[1], 0, H[3], H[4], 0, 0, 0, 0}, Hr[9], W2, P2[4], P33, Wn, Pn[9];
      PetscReal d;
      if (1.0 + gu[0] + gu[3] + gu[0] * gu[3] - gu[1] * gu[2] > 0.0 && 1.0 + e3 > 0.0) {
        Old2D(neo, p, gu, 0.0, &W2, P2, &P33);
        Wn  = Energy(m, p, Hp, Pn);
        plW = PetscMax(plW, PetscAbsReal(Wn - W2) / PetscAbsReal(W2));
        d   = PetscMax(PetscMax(PetscAbsReal(Pn[0] - P2[0]), PetscAbsReal(Pn[1] - P2[1])), PetscMax(PetscAbsReal(Pn[3] - P2[2]), PetscAbsReal(Pn[4] - P2[3])));
        plP = PetscMax(plP, d / MaxAbs(9, Pn));
        plP22 = PetscMax(plP22, PetscAbsReal(Pn[8] - P33) / MaxAbs(9, Pn));
        for (PetscInt k = 0; k < 9; ++k) Hr[k] = Hp[k];
        Hr[8] = e3;
        Old2D(neo, p, gu, e3, &W2, P2, &P33);
        Wn  = Energy(m, p, Hr, Pn);
        rzW = PetscMax(rzW, PetscAbsReal(Wn - W2) / PetscAbsReal(W2));
        d   = PetscMax(PetscMax(PetscAbsReal(Pn[0] - P2[0]), PetscAbsReal(Pn[1] - P2[1])), PetscMax(PetscAbsReal(Pn[3] - P2[2]), PetscAbsReal(Pn[4] - P2[3])));
        d   = PetscMax(d, PetscAbsReal(Pn[8] - P33));
        rzP = PetscMax(rzP, d / MaxAbs(9, Pn));
      }
    }
  }
  printf("%s taylor_P_order_min %.6e\n%s taylor_P_order_max %.6e\n", m->name, (double)tPmin, m->name, (double)tPmax);
  if (neo) printf("%s taylor_A_order_min %.6e\n%s taylor_A_order_max %.6e\n", m->name, (double)tAmin, m->name, (double)tAmax);
  printf("%s fd_P_rel %.6e\n%s fd_A_rel %.6e\n%s sym_A_rel %.6e\n", m->name, (double)fdP, m->name, (double)fdA, m->name, (double)symA);
  printf("%s cauchy_sym_rel %.6e\n%s cauchy_PFt_rel %.6e\n", m->name, (double)csym, m->name, (double)cPFt);
  if (old2d) {
    printf("%s plane_P22_rel %.6e\n", m->name, (double)plP22);
    printf("%s plane_W_rel %.6e\n%s plane_P_rel %.6e\n%s rz_W_rel %.6e\n%s rz_P_rel %.6e\n", m->name, (double)plW, m->name, (double)plP, m->name, (double)rzW, m->name, (double)rzP);
  }
  if (neo) {
    PetscReal HQ[9], PQ[9], WQ;
    for (PetscInt k = 0; k < 9; ++k) HQ[k] = Q[k] - (k % 4 == 0 ? 1.0 : 0.0);
    WQ = Energy(m, p, HQ, PQ);
    printf("%s frame_W_rel %.6e\n%s frame_P_rel %.6e\n", m->name, (double)frW, m->name, (double)frP);
    printf("%s rotation_W %.6e\n%s rotation_P %.6e\n", m->name, (double)(WQ / mu0), m->name, (double)(MaxAbs(9, PQ) / mu0));
  }
  { /* at rest: C */
    const PetscReal H0[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, lambda = lambda0, mu = mu0;
    PetscReal       A[81], C[81], d = 0.0;
    m->moduli(p, NULL, H0, A);
    for (PetscInt i = 0; i < 3; ++i)
      for (PetscInt j = 0; j < 3; ++j)
        for (PetscInt k = 0; k < 3; ++k)
          for (PetscInt l = 0; l < 3; ++l) C[((i * 3 + j) * 3 + k) * 3 + l] = lambda * (i == j) * (k == l) + mu * ((i == k) * (j == l) + (i == l) * (j == k));
    for (PetscInt k = 0; k < 81; ++k) d = PetscMax(d, PetscAbsReal(A[k] - C[k]));
    printf("%s rest_A_rel %.6e\n", m->name, (double)(d / MaxAbs(81, C)));
  }
}

/* The plastic material (plasticity.c), E = 1, nu = 0.3, sigma_y = 2e-3,
   Hh = 0.1, at NSAMPLE random accepted states (a deviatoric plastic strain
   of entries in [-1e-3, 1e-3], alpha in [0, 2e-3]; a quarter of them zero:
   virgin, with H a quarter the size) and random H (entries in [-s, s],
   s = 3e-3), each in the branch
   its return takes (plastic: update raises alpha), with central differences
   at h = 1e-4 s along a random E where H - hE and H + hE return in the same
   branch as H:
     fd_P_{elastic,plastic}_rel   |difference of W - P:E| / max(|P:E|, |P| |E|);
     fd_A_{elastic,plastic}_rel   |difference of P - A:E| / (|A| |E|), the largest component;
     sym_A_rel                    max |A_iJkL - A_kLiJ| / max |A|;
     linear_diff                  the largest difference of W, P and A from the linear
                                  material's at a zero state and H in the elastic branch
                                  (0: the same sums, to the bit);
     accept_P_rel, accept_W_rel   P and W at H from the updated state against those from the
                                  accepted one (the increment's stress and work are kept);
     accept_yield_rel             the new state's return at the same H: its increment of
                                  alpha, relative to the increment's own (0 up to round-off:
                                  the state is on its yield surface);
     samples_elastic, samples_plastic, samples_linear  how many samples each
                                  branch had, and the virgin elastic ones. */
static void CheckPlastic(const Material *m, const Material *lin)
{
  const PetscReal E = 1.0, nu = 0.3, p[4] = {E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu)), 2e-3, 0.1}, sc = 3e-3, h = 1e-4 * sc;
  PetscReal       fdP[2] = {0, 0}, fdA[2] = {0, 0}, symA = 0, lind = 0, accP = 0, accW = 0, accY = 0;
  PetscInt        count[2] = {0, 0}, nlin = 0;

  for (PetscInt s = 0; s < NSAMPLE; ++s) {
    PetscReal st[7] = {0, 0, 0, 0, 0, 0, 0}, sn[7], sp[7], sm[7], H[9], Ev[9], Hp[9], Hm[9], W, P[9], A[81], Wp, Pp[9], Wm, Pm[9], PE = 0, AE[9];
    PetscInt  br;
    if (s >= NSAMPLE / 4) {
      for (PetscInt k = 0; k < 6; ++k) st[k] = Uniform(-1e-3, 1e-3);
      const PetscReal t = (st[0] + st[1] + st[2]) / 3.0;
      for (PetscInt k = 0; k < 3; ++k) st[k] -= t;
      st[6] = Uniform(0.0, 2e-3);
    }
    for (PetscInt k = 0; k < 9; ++k) {
      H[k]  = Uniform(-sc, sc) * (s < NSAMPLE / 4 ? 0.25 : 1.0);
      Ev[k] = Uniform(-1.0, 1.0);
      Hp[k] = H[k] + h * Ev[k];
      Hm[k] = H[k] - h * Ev[k];
    }
    m->update(p, st, H, sn);
    m->update(p, st, Hp, sp);
    m->update(p, st, Hm, sm);
    br = sn[6] > st[6];
    if (br != (sp[6] > st[6]) || br != (sm[6] > st[6])) continue; /* across the yield surface: A jumps there */
    count[br]++;
    (void)m->energy(p, st, H, &W, P);
    m->moduli(p, st, H, A);
    (void)m->energy(p, st, Hp, &Wp, Pp);
    (void)m->energy(p, st, Hm, &Wm, Pm);
    for (PetscInt a = 0; a < 9; ++a) {
      PE += P[a] * Ev[a];
      AE[a] = 0.0;
      for (PetscInt b = 0; b < 9; ++b) AE[a] += A[a * 9 + b] * Ev[b];
    }
    {
      const PetscReal nE = 3.0 * MaxAbs(9, Ev);
      fdP[br] = PetscMax(fdP[br], PetscAbsReal((Wp - Wm) / (2 * h) - PE) / PetscMax(PetscAbsReal(PE), MaxAbs(9, P) * nE));
      for (PetscInt k = 0; k < 9; ++k) fdA[br] = PetscMax(fdA[br], PetscAbsReal((Pp[k] - Pm[k]) / (2 * h) - AE[k]) / (MaxAbs(81, A) * nE));
    }
    for (PetscInt a = 0; a < 9; ++a)
      for (PetscInt b = 0; b < 9; ++b) symA = PetscMax(symA, PetscAbsReal(A[a * 9 + b] - A[b * 9 + a]) / MaxAbs(81, A));
    if (!br && s < NSAMPLE / 4) { /* virgin and elastic: linear elasticity's sums */
      PetscReal Wl, Pl[9], Al[81];
      nlin++;
      (void)lin->energy(p, NULL, H, &Wl, Pl);
      lin->moduli(p, NULL, H, Al);
      lind = PetscMax(lind, PetscAbsReal(W - Wl));
      for (PetscInt k = 0; k < 9; ++k) lind = PetscMax(lind, PetscAbsReal(P[k] - Pl[k]));
      for (PetscInt k = 0; k < 81; ++k) lind = PetscMax(lind, PetscAbsReal(A[k] - Al[k]));
    }
    if (br) { /* the accepted increment: the same stress and work from the new state */
      PetscReal Wn, Pn[9], s2[7];
      (void)m->energy(p, sn, H, &Wn, Pn);
      accW = PetscMax(accW, PetscAbsReal(Wn - W) / PetscAbsReal(W));
      for (PetscInt k = 0; k < 9; ++k) accP = PetscMax(accP, PetscAbsReal(Pn[k] - P[k]) / MaxAbs(9, P));
      m->update(p, sn, H, s2);
      accY = PetscMax(accY, (s2[6] - sn[6]) / (sn[6] - st[6]));
    }
  }
  printf("plastic fd_P_elastic_rel %.6e\nplastic fd_P_plastic_rel %.6e\n", (double)fdP[0], (double)fdP[1]);
  printf("plastic fd_A_elastic_rel %.6e\nplastic fd_A_plastic_rel %.6e\n", (double)fdA[0], (double)fdA[1]);
  printf("plastic sym_A_rel %.6e\nplastic linear_diff %.6e\n", (double)symA, (double)lind);
  printf("plastic accept_P_rel %.6e\nplastic accept_W_rel %.6e\nplastic accept_yield_rel %.6e\n", (double)accP, (double)accW, (double)accY);
  printf("plastic samples_elastic %d\nplastic samples_plastic %d\nplastic samples_linear %d\n", (int)count[0], (int)count[1], (int)nlin);
}

int main(int argc, char **argv)
{
  const char *names[] = {"linear", "neohookean", "mooneyrivlin"};
  /* E = 1, nu = 0.3: lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)) */
  const PetscReal p[2] = {0.3 / (1.3 * 0.4), 1.0 / 2.6};
  /* Mooney-Rivlin C10 = 0.12, C01 = 0.07, D1 = 2.5: mu = 2 (C10 + C01), K = 2 / D1, lambda = K - 2 mu / 3 */
  const PetscReal q[3] = {0.12, 0.07, 2.5}, muq = 2 * (0.12 + 0.07), lq = 2 / 2.5 - 2 * muq / 3;

  PetscCall(PetscInitialize(&argc, &argv, NULL, "Checks the materials' pointwise kernels (tests/test_material_kernels.py)"));
  PetscCall(MaterialRegisterAll());
  for (PetscInt k = 0; k < 3; ++k) {
    const Material *m;
    PetscCall(MaterialFind(names[k], &m));
    PetscCheck(m, PETSC_COMM_SELF, PETSC_ERR_PLIB, "material %s is not registered", names[k]);
    if (k < 2) Check(m, p, p[0], p[1], PETSC_TRUE);
    else Check(m, q, lq, muq, PETSC_FALSE);
  }
  {
    const Material *m, *lin;
    PetscCall(MaterialFind("plastic", &m));
    PetscCall(MaterialFind("linear", &lin));
    PetscCheck(m && lin, PETSC_COMM_SELF, PETSC_ERR_PLIB, "material plastic is not registered");
    CheckPlastic(m, lin);
  }
  PetscCall(MaterialFinalize());
  PetscCall(PetscFinalize());
  return 0;
}
