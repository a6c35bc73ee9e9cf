"""The materials' pointwise kernels of the full 3 x 3 displacement gradient
(include/material.h: src/body/elasticity.c, src/body/neohookean.c) at random
3D states, no mesh and no 3D body needed: bin/material-check
(tests/kernels/material_check.c, built by make) evaluates them at 200 random
H (a quarter with entries of 1e-3, the rest of 0.4 with J = det(I + H) in
[0.5, 2]: finite strain) and random directions E, E = 1, nu = 0.3, and prints
the figures asserted here:

- P = dW/dF and A = dP/dF: the Taylor remainders of W and P fall at order 2,
  and central differences of W and P at h = 1e-4 of the strain's scale agree
  with P:E and A:E to the differences' O(h^2);
- A is symmetric (A_iJkL = A_kLiJ) and at rest is linear elasticity's C;
- the Cauchy stress is symmetric and equal to P F^T / J (linear: to P);
- neo-Hookean: W(QF) = W(F) and P(QF) = Q P(F) for Q the rotation by 60
  degrees about (1, 2, 3)/sqrt(14), and W and P are zero at F = Q;
- plane strain (row and column 2 of H zero) and r-z (H_22 = u_r / r): W and
  the in-plane P are the 2D kernels' formulas (written out in the program).

bin/element-check (tests/kernels/element_check.c) runs the element loop
(src/body/element.c) on one 3D cell, Hex27 and Tet10, with the cell cache a
3D body would give it: Taylor orders of its gradient and tangent, an affine
patch, the rigid modes, a rigid rotation.

Figures are the program's, deterministic (a fixed seed; no BLAS): measured
once on this machine (x86-64, -O2, no FMA)."""
import math

import pytest

from conftest import check_program_figures, figure


@pytest.fixture(scope="module")
def figures():
    """The check program's figures, {(material, name): value}."""
    return check_program_figures("material-check")


@pytest.mark.roundoff
def test_taylor_orders(figures):
    """|W(H + tE) - W(H) - t P:E| and |P(H + tE) - P(H) - t A:E| at t = 1e-2
    to 1.25e-3 halving: the order between successive t is 2 if P and A are
    the derivatives (1 if either is wrong). Neo-Hookean: W's remainder's order
    from `neo_taylor_P_min` = 1.904 to `neo_taylor_P_max` = 2.018, P's from
    `neo_taylor_A_min` = 1.968 to `neo_taylor_A_max` = 2.017 (the third
    derivative's share at t = 1e-2 of a 1e-3 strain, t W'''/(6 W'') / ln 2,
    moves it by up to 0.1); bound [1.7, 2.3], 3x the largest deviation.
    Linear: W quadratic, the remainder t^2/2 E:C:E exact, order
    `linear_taylor_P_dev` = 0 from 2 (round-off); bound 1e-6."""
    lo, hi = (figure("neo_taylor_P_min", figures[("neohookean", "taylor_P_order_min")]),
              figure("neo_taylor_P_max", figures[("neohookean", "taylor_P_order_max")]))
    alo, ahi = (figure("neo_taylor_A_min", figures[("neohookean", "taylor_A_order_min")]),
                figure("neo_taylor_A_max", figures[("neohookean", "taylor_A_order_max")]))
    assert 1.7 <= lo <= hi <= 2.3
    assert 1.7 <= alo <= ahi <= 2.3
    dev = max(abs(figures[("linear", "taylor_P_order_min")] - 2), abs(figures[("linear", "taylor_P_order_max")] - 2))
    assert figure("linear_taylor_P_dev", dev) <= 1e-6


@pytest.mark.roundoff
def test_finite_differences(figures):
    """Central differences at h = 1e-4 s (s the sample's strain scale): the
    error is h^2/6 of the third derivative, (h/s)^2 = 1e-8 times a factor of
    order 1 to 10 relative to P and A for J in [0.5, 2]. Neo-Hookean:
    `neo_fd_P` = 2.3e-8 of max(|P:E|, |P| |E|), `neo_fd_A` = 2.3e-8 of |A| |E|;
    bound 1e-6 (100 (h/s)^2). Linear: a quadratic W and linear P, which
    central differences take exactly: round-off alone, eps |W| / (h |P|),
    `linear_fd_P` = 1.4e-12, `linear_fd_A` = 8.8e-13; bound 1e-9."""
    assert figure("neo_fd_P", figures[("neohookean", "fd_P_rel")]) <= 1e-6
    assert figure("neo_fd_A", figures[("neohookean", "fd_A_rel")]) <= 1e-6
    assert figure("linear_fd_P", figures[("linear", "fd_P_rel")]) <= 1e-9
    assert figure("linear_fd_A", figures[("linear", "fd_A_rel")]) <= 1e-9


@pytest.mark.roundoff
def test_moduli_symmetric_and_at_rest(figures):
    """A_iJkL = A_kLiJ (a hyperelastic tangent): the largest difference
    `neo_sym_A` = 1.1e-16 of max |A| (round-off of the two products' order;
    linear `linear_sym_A` = 0); at H = 0, A = C_ijkl = lambda d_ij d_kl + mu
    (d_ik d_jl + d_il d_jk): `neo_rest_A` = 0 and `linear_rest_A` = 0 of max
    |C|. Bounds 1e-14."""
    for mat, tag in (("neohookean", "neo"), ("linear", "linear")):
        assert figure(f"{tag}_sym_A", figures[(mat, "sym_A_rel")]) <= 1e-14
        assert figure(f"{tag}_rest_A", figures[(mat, "rest_A_rel")]) <= 1e-14


@pytest.mark.roundoff
def test_cauchy(figures):
    """The Cauchy stress is symmetric (`neo_cauchy_sym` = 0, `linear_cauchy_sym`
    = 0 of max |sigma|; bound 1e-14) and is P F^T / J for the neo-Hookean
    (`neo_cauchy_PFt` = 1.8e-13 of max |sigma|, round-off of F^-1 at J = 0.5;
    bound 1e-11), P itself for the linear material (`linear_cauchy_P` = 0;
    bound 1e-14)."""
    assert figure("neo_cauchy_sym", figures[("neohookean", "cauchy_sym_rel")]) <= 1e-14
    assert figure("linear_cauchy_sym", figures[("linear", "cauchy_sym_rel")]) <= 1e-14
    assert figure("neo_cauchy_PFt", figures[("neohookean", "cauchy_PFt_rel")]) <= 1e-11
    assert figure("linear_cauchy_P", figures[("linear", "cauchy_PFt_rel")]) <= 1e-14


@pytest.mark.roundoff
def test_frame_invariance(figures):
    """Neo-Hookean, Q the rotation by 60 degrees about (1, 2, 3)/sqrt(14):
    W(QF) = W(F) to `neo_frame_W` = 9.0e-11 of max(|W|, mu |H|^2) (QF - I has
    entries of order 1 where H has 1e-3: W, of order mu |H|^2 = 1e-6 mu, is
    then formed from terms of order 1, eps / |H|^2 = 1e-10; bound 1e-8) and
    P(QF) = Q P(F) to `neo_frame_P` = 5.1e-13 of max |P| (bound 1e-10); at F
    = Q, W = `neo_rotation_W` = -3.5e-18 mu and max |P| = `neo_rotation_P` =
    1.6e-16 mu (bound 1e-14: zero but for round-off)."""
    assert figure("neo_frame_W", figures[("neohookean", "frame_W_rel")]) <= 1e-8
    assert figure("neo_frame_P", figures[("neohookean", "frame_P_rel")]) <= 1e-10
    assert abs(figure("neo_rotation_W", figures[("neohookean", "rotation_W")])) <= 1e-14
    assert figure("neo_rotation_P", figures[("neohookean", "rotation_P")]) <= 1e-14


@pytest.mark.roundoff
def test_plane_strain_reduction(figures):
    """With row and column 2 of H zero (plane strain) W and the in-plane P are
    the 2D kernels' (the program's formulas of gu[4] and e3 = 0, written out
    in material_check.c), by the same operations: `neo_plane_W` = 0,
    `neo_plane_P` = 0, `linear_plane_W` = 0, `linear_plane_P` = 0 relative
    (bound 1e-15; scripts/same_results.py shows the scenes bit-identical).
    The out-of-plane P_22, from F^-1_22 = adj_22 / J rather than 1 / F_22:
    `neo_plane_P22` = 2.8e-13 of max |P| (bound 1e-11). In r-z, H_22 = e3 the
    hoop strain: W `neo_rz_W` = 0 and P (in-plane and P_22) `neo_rz_P` =
    4.3e-13 of max |P| (bounds 1e-15 and 1e-11); linear `linear_rz_W` = 0,
    `linear_rz_P` = 0."""
    for mat, tag in (("neohookean", "neo"), ("linear", "linear")):
        assert figure(f"{tag}_plane_W", figures[(mat, "plane_W_rel")]) <= 1e-15
        assert figure(f"{tag}_plane_P", figures[(mat, "plane_P_rel")]) <= 1e-15
        assert figure(f"{tag}_rz_W", figures[(mat, "rz_W_rel")]) <= 1e-15
        assert figure(f"{tag}_rz_P", figures[(mat, "rz_P_rel")]) <= 1e-11
    assert figure("neo_plane_P22", figures[("neohookean", "plane_P22_rel")]) <= 1e-11
    assert not math.isnan(figures[("neohookean", "plane_P22_rel")])


@pytest.fixture(scope="module")
def element_figures():
    """The element loop's figures on one 3D cell, {(cell, material, name): value}."""
    return check_program_figures("element-check")


CELLS = ("hex27", "tet10")
MATERIALS = ("linear", "neohookean")


@pytest.mark.roundoff
def test_element_loop_3d_taylor(element_figures):
    """The element loop (src/body/element.c) on one 3D cell with dim = 3, 27
    or 10 nodes, as a 3D body's cell cache would give it
    (tests/kernels/element_check.c: PETSc's Q2 and P2 elements on the
    reference cell mapped by a fixed affine map, random nodal u and v of
    size 0.05): the cell's energy, gradient and tangent with no change of
    the loop. |Pi(u + tv) - Pi(u) - t g.v| and |g(u + tv) - g(u) - t K v|
    at t = 0.5 to 0.0625 halving fall at order 2: linear g
    `hex27_linear_g_dev` = 0, `tet10_linear_g_dev` = 0 from 2 (bound 1e-6);
    neo-Hookean g from `neo3d_g_min` = 1.995 to `neo3d_g_max` = 2.015, K from
    `neo3d_K_min` = 1.972 to `neo3d_K_max` = 2.071 over both cells (bound
    [1.7, 2.3]); K symmetric to `K3d_sym` = 1.1e-16 of max |K| (bound 1e-14)."""
    for cell in CELLS:
        dev = max(abs(element_figures[(cell, "linear", f"taylor_g_order_{e}")] - 2) for e in ("min", "max"))
        assert figure(f"{cell}_linear_g_dev", dev) <= 1e-6
    g = [element_figures[(c, "neohookean", f"taylor_g_order_{e}")] for c in CELLS for e in ("min", "max")]
    k = [element_figures[(c, "neohookean", f"taylor_K_order_{e}")] for c in CELLS for e in ("min", "max")]
    assert 1.7 <= figure("neo3d_g_min", min(g)) and figure("neo3d_g_max", max(g)) <= 2.3
    assert 1.7 <= figure("neo3d_K_min", min(k)) and figure("neo3d_K_max", max(k)) <= 2.3
    sym = max(element_figures[(c, m, "K_sym_rel")] for c in CELLS for m in MATERIALS)
    assert figure("K3d_sym", sym) <= 1e-14


@pytest.mark.roundoff
def test_element_loop_3d_patch_and_rigid(element_figures):
    """The same cells: an affine u = H0 x (H0 of 0.07 at most) gives the
    energy W(H0) times the volume, to `patch3d_W` = up to 1.0e-15 relative, and
    forces that balance (sum_a N_a = 1), their sum `patch3d_g_sum` = 9.9e-16
    of the largest (bounds 1e-13); the stiffness at rest takes the six rigid
    modes to `rest3d_null` = 5.3e-16 of max |K| max |r| (bound 1e-13); a
    neo-Hookean cell rotated by 60 degrees stores `rot3d_W` = up to 2.8e-17 mu vol
    and has forces `rot3d_g` = 7.9e-16 mu vol (bounds 1e-13)."""
    W = max(element_figures[(c, m, "patch_W_rel")] for c in CELLS for m in MATERIALS)
    gs = max(element_figures[(c, m, "patch_g_sum_rel")] for c in CELLS for m in MATERIALS)
    null = max(element_figures[(c, m, "rest_null_rel")] for c in CELLS for m in MATERIALS)
    assert figure("patch3d_W", W) <= 1e-13
    assert figure("patch3d_g_sum", gs) <= 1e-13
    assert figure("rest3d_null", null) <= 1e-13
    rw = max(abs(element_figures[(c, "neohookean", "rotation_W")]) for c in CELLS)
    rg = max(element_figures[(c, "neohookean", "rotation_g")] for c in CELLS)
    assert figure("rot3d_W", rw) <= 1e-13
    assert figure("rot3d_g", rg) <= 1e-13


@pytest.mark.roundoff
def test_mooney_rivlin(figures):
    """The compressible Mooney-Rivlin material (src/body/mooneyrivlin.c: W
    of the isochoric invariants and J, its P and A from the invariants'
    derivatives), C10 = 0.12, C01 = 0.07, D1 = 2.5, at the same 200 states:
    A's Taylor order from `mr_taylor_A_min` = 1.975 to `mr_taylor_A_max` =
    2.018 (bound [1.7, 2.3]); W's from `mr_taylor_P_min` = 1.18 to
    `mr_taylor_P_max` = 2.016 (the 1.18 one state's first halving, where
    the third derivative's share is large: 1.72 and 1.88 at the next two;
    bound [1.0, 2.3], with central differences `mr_fd_P` = 1.8e-8 and
    `mr_fd_A` = 1.0e-8 (bound 1e-6) showing P and A the derivatives); A
    symmetric `mr_sym_A` = 3.4e-16 and at rest C with mu = 2 (C10 + C01),
    lambda = 2/D1 - 2 mu/3: `mr_rest_A` = 0 (bounds 1e-14); Cauchy symmetric
    `mr_cauchy_sym` = 6.3e-16 and P F^T/J (`mr_cauchy_PFt` = 0; bounds
    1e-14, 1e-11); frame invariance `mr_frame_W` = 2.7e-10 (bound 1e-8),
    `mr_frame_P` = 7.5e-13 (1e-10), zero at a rotation: `mr_rotation_W` =
    -1.7e-16, `mr_rotation_P` = 4.4e-16 of mu (bound 1e-14)."""
    f = lambda k: figures[("mooneyrivlin", k)]
    assert 1.7 <= figure("mr_taylor_A_min", f("taylor_A_order_min")) <= figure("mr_taylor_A_max", f("taylor_A_order_max")) <= 2.3
    assert 1.0 <= figure("mr_taylor_P_min", f("taylor_P_order_min")) <= figure("mr_taylor_P_max", f("taylor_P_order_max")) <= 2.3
    assert figure("mr_fd_P", f("fd_P_rel")) <= 1e-6 and figure("mr_fd_A", f("fd_A_rel")) <= 1e-6
    assert figure("mr_sym_A", f("sym_A_rel")) <= 1e-14 and figure("mr_rest_A", f("rest_A_rel")) <= 1e-14
    assert figure("mr_cauchy_sym", f("cauchy_sym_rel")) <= 1e-14 and figure("mr_cauchy_PFt", f("cauchy_PFt_rel")) <= 1e-11
    assert figure("mr_frame_W", f("frame_W_rel")) <= 1e-8 and figure("mr_frame_P", f("frame_P_rel")) <= 1e-10
    assert abs(figure("mr_rotation_W", f("rotation_W"))) <= 1e-14 and figure("mr_rotation_P", f("rotation_P")) <= 1e-14
