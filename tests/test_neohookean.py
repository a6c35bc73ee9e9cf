"""Neo-Hookean bodies (-<body>_material neohookean, src/body/neohookean.c)
against answers computed here, outside the program:

- a homogeneous deformation gradient F imposed on the whole boundary (a
  stretch and a shear, Tri6 and Quad9) is an exact solution with no body
  force: every node at (F - I) X and the energy W(F) times the area, W
  evaluated here from its formula;
- a rigid rotation by 60 degrees stores no energy and no stress; a linear
  body given the same displacement stores lambda/2 + mu/2 per unit area and
  a stress -(lambda + mu) (sym(R - I) = (cos 60 - 1) I);
- traction-free uniaxial plane-strain stretch 1.5 and compression 0.6 on
  rollers: the lateral stretch l2 from P22 = 0 solved here by bisection, the
  nodes at ((l1 - 1) X, (l2 - 1) Y) and the reaction P11 times the height;
- the Taylor remainders of the energy and of the gradient at large-strain
  iterates (plane strain and r-z), order 2 with the exact Hessian;
- the reference scene at 1e-4 and 2e-4 of its push: neo-Hookean and linear
  differ by O(load);
- a thick-walled tube (R from 1 to 2) inflated by a dead pressure of 100
  (hoop stretch 1.20 at the bore), in plane strain and in r-z, against the
  radial equilibrium ODE integrated here (RK4 and shooting, to 1e-14):
  the nodal error falls at order 3 and more;
- a manufactured solution at finite strain with its neo-Hookean body force
  converges at the P2/Q2 orders;
- 1 and 2 ranks give the same answer;
- -tangent_at_rest (the stiffness at rest for Newton's step) reaches the
  full Newton's answer at small strain.

Each bound quotes the figure it bounds, recorded by figure() and measured
over the five OpenBLAS kernels (2 cores, PETSc 3.18)."""
import math
import re

import numpy as np
import pytest

from conftest import figure, run_contact

E, NU = 1000.0, 0.3
LAM, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
# Newton's quadratic convergence takes the stop to round-off: the gradient
# falls by 1e-14 from rest instead of 1e-8
TIGHT = ["-tao_gttol", "1e-14"]


def W(F, F33=1.0):
    """The compressible neo-Hookean energy density of a block-diagonal F."""
    F = np.asarray(F, float)
    J = np.linalg.det(F) * F33
    return MU / 2 * ((F * F).sum() + F33 * F33 - 3 - 2 * math.log(J)) + LAM / 2 * math.log(J) ** 2


def square(cells, grad, material="neohookean", h=0.25):
    """The unit square (meshes/square) with u = grad X imposed on its whole boundary."""
    p = [0.0, grad[0][0], grad[0][1], 0.0, grad[1][0], grad[1][1]]
    return ["-options_file", "meshes/square/square.opts", "-square_geo_params", f"L=1,quads={int(cells == 'quad9')}",
            "-square_mesh_size", h, "-square_material", material, "-square_exact", "affine",
            "-square_exact_params", ",".join(repr(v) for v in p)]


HOMOGENEOUS = {"stretch": [[0.3, 0.0], [0.0, -0.2]], "shear": [[0.0, 0.4], [0.0, 0.0]]}


@pytest.mark.roundoff
@pytest.mark.parametrize("cells", ["tri6", "quad9"])
@pytest.mark.parametrize("kind", HOMOGENEOUS)
def test_homogeneous_deformation_exact(kind, cells, tmp_path):
    """F = I + H imposed on the boundary (stretch diag(1.3, 0.8), shear [[1,
    0.4], [0, 1]]): the nodes at H X and the energy W(F) times the area 1, to
    round-off. Measured over both cases, both cells and the five kernels: nodes
    `nodes` = 1.4e-16 to 8.3e-16 of max |u|, energy `energy` = 0 to 1.6e-15
    relative; bounds 1e-12 and 1e-12 (the solve's stop, well above the figures,
    far below any error of the model: a wrong P leaves the nodes off by 1e-3
    and more)."""
    H = HOMOGENEOUS[kind]
    r = run_contact(square(cells, H) + TIGHT, tmp_path)
    s = r.summary
    with r.h5() as f:
        X, u = f["bodies/square/geometry"][...], f["bodies/square/displacement"][...]
    exact = X[:, :2] @ np.asarray(H).T
    err = np.abs(u - exact).max() / np.abs(exact).max()
    Wf = W(np.eye(2) + H)
    print(f"{kind} {cells}: nodes {err:.2e}, energy {s['energy']!r} against {Wf!r} ({abs(s['energy'] - Wf) / Wf:.1e})")
    assert figure("nodes", err) <= 1e-12
    assert figure("energy", abs(s["energy"] - Wf) / Wf) <= 1e-12


ROTATION = [[math.cos(math.pi / 3) - 1, -math.sin(math.pi / 3)], [math.sin(math.pi / 3), math.cos(math.pi / 3) - 1]]


@pytest.mark.roundoff
@pytest.mark.parametrize("material", ["neohookean", "linear"])
def test_rigid_rotation(material, tmp_path):
    """u = (R - I) X with R the rotation by 60 degrees, on the whole boundary.
    Neo-Hookean: no energy, no stress (measured over the five kernels: energy
    `energy_of_mu` = 2.6e-18 to 9.3e-18 of mu = 385, stress
    `stress_of_mu` = 1.4e-14 to 3.1e-14 of mu; bounds 1e-11 and 1e-9). Linear:
    the rotation's symmetric part (cos 60 - 1) I strains it, energy lambda/2 +
    mu/2 = 480.77 and sigma_xx = sigma_yy = -(lambda + mu) = -961.54, sigma_zz
    = -lambda (measured: energy `energy_rel` = 0 to 1.5e-15 relative, stresses
    `stress_rel` = 1.3e-14 to 1.8e-14 of lambda + mu; bound 1e-10): the figure
    the README quotes."""
    r = run_contact(square("quad9", ROTATION, material) + TIGHT, tmp_path)
    s = r.summary
    with r.h5() as f:
        st = {k: f[f"bodies/square/stress_{k}"][...] for k in ("xx", "yy", "zz", "xy")}
        vm = f["bodies/square/von_mises"][...]
    print(material, s["energy"], {k: (v.min(), v.max()) for k, v in st.items()}, vm.max(), s["load_cutbacks"])
    if material == "neohookean":
        assert figure("energy_of_mu", abs(s["energy"]) / MU) <= 1e-11
        assert figure("stress_of_mu", max(np.abs(v).max() for v in st.values()) / MU) <= 1e-9
    else:
        lin = LAM / 2 + MU / 2
        assert figure("energy_rel", abs(s["energy"] - lin) / lin) <= 1e-10
        exact = (("xx", -(LAM + MU)), ("yy", -(LAM + MU)), ("zz", -LAM), ("xy", 0.0))
        assert figure("stress_rel", max(np.abs(st[k] - v).max() for k, v in exact) / (LAM + MU)) <= 1e-10


def lateral_stretch(l1):
    """l2 with P22 = mu (l2 - 1/l2) + lambda ln(l1 l2) / l2 = 0, by bisection
    (P22 increases with l2 from -inf at 0+)."""
    lo, hi = 1e-6, 10.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if MU * (mid - 1 / mid) + LAM * math.log(l1 * mid) / mid > 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


@pytest.mark.roundoff
@pytest.mark.parametrize("l1,cells", [(1.5, 1), (0.6, 0)], ids=["stretch-quad9", "compression-tri6"])
def test_uniaxial_rollers(l1, cells, tmp_path):
    """The unit square on rollers (left edge u_x = 0, bottom u_y = 0), its
    right edge moved to x = l1, top free: plane-strain uniaxial stress, F =
    diag(l1, l2) with l2 from P22 = 0 (0.82492 at 1.5, 1.21443 at 0.6). Every
    node at ((l1 - 1) X, (l2 - 1) Y) and the right edge's reaction P11 = mu (l1
    - 1/l1) + lambda ln(l1 l2) / l1 times the height 1. The nodal Cauchy stress
    written, against sigma = P F^T / J: sigma_xx = P11 / l2, sigma_zz = lambda
    ln J / J, the others 0. Measured over both cases and the five kernels:
    nodes `nodes` = 7.8e-16 to 2.6e-15 of max |u|, reaction
    `reaction` = 0 to 1.3e-15 relative, stress `stress` = 6.2e-15 to 3.7e-14 of
    P11; bounds 1e-11, 1e-11, 1e-10."""
    l2 = lateral_stretch(l1)
    P11 = MU * (l1 - 1 / l1) + LAM * math.log(l1 * l2) / l1
    args = ["-scene", "uni", "-bodies", "b", "-b_geo", "tests/meshes/plate.geo", "-b_geo_params", f"L=1,H=1,quads={cells}",
            "-b_mesh_size", 0.25, "-b_E", E, "-b_nu", NU, "-b_material", "neohookean",
            "-b_bc", "left,bottom,right", "-b_bc_left_components", "x", "-b_bc_bottom_components", "y",
            "-b_bc_right_components", "x", "-b_bc_right_values", repr(l1 - 1)] + TIGHT
    r = run_contact(args, tmp_path)
    s = r.summary
    with r.h5() as f:
        X, u = f["bodies/b/geometry"][...], f["bodies/b/displacement"][...]
        st = {k: f[f"bodies/b/stress_{k}"][...] for k in ("xx", "yy", "zz", "xy")}
    exact = np.stack([(l1 - 1) * X[:, 0], (l2 - 1) * X[:, 1]], 1)
    err = np.abs(u - exact).max() / np.abs(exact).max()
    R = s["reactions"]["b:right"][0]
    # the Cauchy stress written: sigma = P F^T / J, so sigma_xx = P11 / l2 (the
    # force per current height), sigma_yy = sigma_xy = 0, sigma_zz = lambda ln J / J
    J = l1 * l2
    cauchy = {"xx": P11 / l2, "yy": 0.0, "zz": LAM * math.log(J) / J, "xy": 0.0}
    serr = max(np.abs(st[k] - v).max() for k, v in cauchy.items()) / abs(P11)
    print(f"l1 {l1}: l2 {l2!r}, nodes {err:.2e}, reaction {R!r} against P11 H = {P11!r} ({abs(R - P11) / abs(P11):.1e}), "
          f"Cauchy stress {serr:.1e}, cutbacks {s['load_cutbacks']}")
    assert figure("nodes", err) <= 1e-11
    assert figure("reaction", abs(R - P11) / abs(P11)) <= 1e-11
    assert figure("stress", serr) <= 1e-10


TUBE = ["-scene", "tube", "-axisymmetric", "-bodies", "tube", "-tube_geo", "tests/meshes/plate.geo",
        "-tube_geo_params", "x0=1,y0=0,L=1,H=0.5,quads=1", "-tube_mesh_size", 0.25, "-tube_E", E, "-tube_nu", NU,
        "-tube_material", "neohookean", "-tube_bc", "bottom,top,left", "-tube_bc_bottom_components", "y",
        "-tube_bc_top_components", "y", "-tube_bc_left_components", "x", "-tube_bc_left_values", 0.5]


@pytest.mark.roundoff
@pytest.mark.parametrize("scene", ["plane", "rz"])
def test_taylor_large_strain(scene, tmp_path):
    """The Taylor remainders at an iterate of large strain, away from the
    minimiser (-tao_gatol 10 stops the solve early, in plane strain at the
    tangent predictor's first iterate itself): plane strain, the square under F
    = [[1.3, 0.2], [-0.1, 1.2]]; r-z, a tube (r from 1 to 2) whose bore is
    pushed out by 0.5, hoop stretch 1.5 there. Both remainders fall at order 2
    (measured `gradient_order` = 2 and `hessian_order` = 2 over both scenes and
    the five kernels; bounds 1.9 to 2.1: a wrong gradient gives 1 in the first,
    a wrong or Gauss-Newton tangent 1 in the second). The iterate is away from
    the minimiser: its gradient norm `gradient_norm` = 0.385 to 4 (the
    minimiser's: 1e-5), bound 0.1."""
    args = square("quad9", [[0.3, 0.2], [-0.1, 0.2]]) if scene == "plane" else TUBE
    s = run_contact(args + ["-tao_gatol", "10", "-taylor_test", "-output", "none"], tmp_path).summary
    t = s["taylor"]
    print(scene, s["gradient_norm"], t)
    assert figure("gradient_norm", s["gradient_norm"]) >= 0.1
    assert 1.9 <= figure("gradient_order", t["gradient_order"]) <= 2.1
    assert 1.9 <= figure("hessian_order", t["hessian_order"]) <= 2.1


def test_small_load_matches_linear(tmp_path):
    """The reference scene at 1e-4 and 2e-4 of its push, both bodies linear and
    both neo-Hookean: the contact force and the energy differ by O(load), the
    model's own error at small strain. Measured at 1e-4: force `dP` = 1.5e-6
    relative, energy `dE` = 9.9e-7 (bound 1e-5); their ratios at 2e-4 to 1e-4
    `ratio` = 2 to 2.06 (bound 2 +- 0.1)."""
    rel = {}
    for f in (1e-4, 2e-4):
        res = {}
        for m in ("linear", "neohookean"):
            res[m] = run_contact(["-options_file", "meshes/hertz/hertz.opts", "-indenter_material", m, "-block_material", m,
                                  "-block_bc_push_values", f"{-0.15 * f!r},0", "-output", "none"], tmp_path, name=f"{m}{f}").summary
        P = [res[m]["reactions"]["block:push"][0] for m in ("linear", "neohookean")]
        En = [res[m]["energy"] for m in ("linear", "neohookean")]
        rel[f] = (abs(P[1] - P[0]) / abs(P[0]), abs(En[1] - En[0]) / En[0])
    print(rel)
    for k, name in ((0, "dP"), (1, "dE")):
        assert figure(name, rel[1e-4][k]) <= 1e-5
        assert abs(figure("ratio", rel[2e-4][k] / rel[1e-4][k]) - 2.0) <= 0.1


def tube_ode(a, b, p, n=1000):
    """The inflated tube, F = diag(dr/dR, r/R, 1) in polar axes (plane strain;
    in r-z with the ends held axially the same principal stretches, the hoop
    one F33): P_RR = mu (l_r - 1/l_r) + lambda ln J / l_r and P_TT alike with
    l_t = r/R, J = l_r l_t, in equilibrium dP_RR/dR + (P_RR - P_TT)/R = 0 with
    P_RR(a) = -p and P_RR(b) = 0. Written for r'' (dP_RR/dl_r = mu (1 +
    1/l_r^2) + lambda (1 - ln J)/l_r^2, dP_RR/dl_t = lambda/J), integrated by
    RK4 from R = a, shot on r(a) by the secant method (l_r(a) from P_RR(a) =
    -p by bisection). Returns R and (r, dr/dR) on the grid: n = 1000 and 2000
    agree to 1.8e-14."""
    def prr(lr, lt):
        return MU * (lr - 1 / lr) + LAM * math.log(lr * lt) / lr

    def rhs(R, y):
        r, lr = y
        lt = r / R
        lnJ = math.log(lr * lt)
        ptt = MU * (lt - 1 / lt) + LAM * lnJ / lt
        return np.array([lr, (-(prr(lr, lt) - ptt) / R - LAM / (lr * lt) * (lr - lt) / R) / (MU * (1 + 1 / lr**2) + LAM * (1 - lnJ) / lr**2)])

    def shoot(ra):
        lo, hi = 1e-3, 10.0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if prr(mid, ra / a) > -p else (mid, hi)
        y, h = np.array([ra, 0.5 * (lo + hi)]), (b - a) / n
        ys = [y]
        for i in range(n):
            R = a + i * h
            k1 = rhs(R, y)
            k2 = rhs(R + h / 2, y + h / 2 * k1)
            k3 = rhs(R + h / 2, y + h / 2 * k2)
            k4 = rhs(R + h, y + h * k3)
            y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            ys.append(y)
        return np.array(ys)

    def miss(ra):
        Y = shoot(ra)
        return prr(Y[-1, 1], Y[-1, 0] / b)
    x0, x1 = 1.01 * a, 1.2 * a
    f0, f1 = miss(x0), miss(x1)
    while abs(x1 - x0) > 1e-15 * a and f1 != f0:
        x0, f0, x1 = x1, f1, x1 - f1 * (x1 - x0) / (f1 - f0)
        f1 = miss(x1)
    return np.linspace(a, b, n + 1), shoot(x1)


def tube_radius(Rg, Y, R):
    """r(R) at the points R: cubic Hermite from the grid's r and dr/dR (error of order h^4, 1e-12 here)."""
    h = Rg[1] - Rg[0]
    i = np.clip(((R - Rg[0]) / h).astype(int), 0, len(Rg) - 2)
    t = (R - Rg[i]) / h
    return ((2 * t**3 - 3 * t**2 + 1) * Y[i, 0] + (t**3 - 2 * t**2 + t) * h * Y[i, 1]
            + (-2 * t**3 + 3 * t**2) * Y[i + 1, 0] + (t**3 - t**2) * h * Y[i + 1, 1])


# observed nodal orders at h = 0.2 -> 0.1 -> 0.05, bounds about 10 % below
TUBE_ORDERS = {"plane": 2.8, "rz": 3.6}


@pytest.mark.parametrize("scene", TUBE_ORDERS)
def test_tube_against_ode(scene, tmp_path):
    """The thick-walled tube (a = 1, b = 2, E = 1000, nu = 0.3) inflated by a
    dead pressure 100 on its bore: in plane strain the quarter annulus of
    meshes/tube (Quad9, curved), in r-z the meridian rectangle [1, 2] x [0, h]
    held axially on both ends (the same stretches). Nodal displacement against
    the ODE's r(R) - R (radial), at h = 0.2, 0.1, 0.05. Measured: plane, the
    least order `order_plane` = 3.1 and the finest error
    `finest_plane` = 4.3e-7 of max |u|; r-z `order_rz` = 3.98 (the nodes of a
    quasi one-dimensional mesh superconverge) and `finest_rz` = 4.2e-8; bounds
    2.8 and 3.6 on each order and the finest error below 1e-6 and 1e-7. A wrong
    hoop term (F33) or a wrong P_TT shifts r(a) by a percent and stalls the
    orders."""
    Rg, Y = tube_ode(1.0, 2.0, 100.0)
    errs, hs = [], [0.2, 0.1, 0.05]
    for h in hs:
        if scene == "plane":
            args = ["-options_file", "meshes/tube/tube.opts", "-tube_material", "neohookean", "-tube_load_inner_pressure", 100, "-mesh_size", h]
        else:
            args = ["-scene", "tube", "-axisymmetric", "-bodies", "tube", "-tube_geo", "tests/meshes/plate.geo",
                    "-tube_geo_params", f"x0=1,y0=0,L=1,H={h},quads=1", "-tube_mesh_size", h, "-tube_E", E, "-tube_nu", NU,
                    "-tube_material", "neohookean", "-tube_bc", "bottom,top", "-tube_bc_bottom_components", "y",
                    "-tube_bc_top_components", "y", "-tube_load", "left", "-tube_load_left_pressure", 100]
        r = run_contact(args + ["-tao_gttol", "1e-12"], tmp_path, name=f"h{h}")  # 1e-14 is below the pressure's round-off
        with r.h5() as f:
            X, u = f["bodies/tube/geometry"][...], f["bodies/tube/displacement"][...]
        Rn = np.hypot(X[:, 0], X[:, 1]) if scene == "plane" else X[:, 0]
        ur = tube_radius(Rg, Y, Rn) - Rn
        exact = (ur / Rn)[:, None] * X[:, :2] if scene == "plane" else np.stack([ur, 0 * ur], 1)
        errs.append(np.abs(u - exact).max() / np.abs(exact).max())
    orders = [math.log(errs[i] / errs[i + 1]) / math.log(hs[i] / hs[i + 1]) for i in range(2)]
    print(scene, f"r(a) = {Y[0, 0]!r}", errs, orders)
    assert figure(f"order_{scene}", min(orders)) >= TUBE_ORDERS[scene]
    assert figure(f"finest_{scene}", errs[-1]) <= (1e-6 if scene == "plane" else 1e-7)


# observed orders at h = 0.2 -> 0.1 -> 0.05, bounds about 10 % below the least
MMS_ORDERS = {"tri6": (2.55, 1.65), "quad9": (2.7, 1.8)}


@pytest.mark.parametrize("cells", MMS_ORDERS)
def test_manufactured_convergence(cells, tmp_path):
    """The manufactured solution u = A (sin kx cos ky, cos kx sin ky), A = 0.1,
    k = 2 (grad u up to 0.2: finite strain) on the unit square, u on its whole
    boundary and the neo-Hookean body force f_i = -A_iJkL(F) d2u_k/dX_J dX_L
    (src/body/body.c's BodyExactForce, the tangent of neohookean.c and the
    second derivatives of exact.c), at h = 0.2, 0.1, 0.05: the P2/Q2 orders, 3
    in L2 and 2 for the gradient (the JSON's energy-norm error, the norm of the
    error's gradient weighted by linear elasticity's C). Measured, the least of
    the two orders: Quad9 L2 `l2_order_quad9` = 3, gradient
    `grad_order_quad9` = 2; Tri6 L2 `l2_order_tri6` = 2.85, gradient
    `grad_order_tri6` = 1.88. A wrong tangent in the body force leaves an O(1)
    residual force and the L2 error stalls at its first value's order."""
    e, eg, hs = [], [], [0.2, 0.1, 0.05]
    for h in hs:
        s = run_contact(["-options_file", "meshes/square/square.opts", "-square_geo_params", f"L=1,quads={int(cells == 'quad9')}",
                         "-square_material", "neohookean", "-square_exact_params", "0.1,2", "-square_mesh_size", h,
                         "-output", "none"], tmp_path, name=f"h{h}").summary
        b = s["bodies"]["square"]
        e.append(b["l2_error"] / b["l2_norm"])
        eg.append(b["energy_error"] / b["energy_norm"])
    orders = [[math.log(x[i] / x[i + 1]) / math.log(hs[i] / hs[i + 1]) for i in range(2)] for x in (e, eg)]
    print(cells, e, eg, orders)
    assert figure(f"l2_order_{cells}", min(orders[0])) >= MMS_ORDERS[cells][0]
    assert figure(f"grad_order_{cells}", min(orders[1])) >= MMS_ORDERS[cells][1]


@pytest.mark.roundoff
@pytest.mark.parametrize("material", ["linear", "neohookean"])
def test_largest_strain_reported(material, tmp_path):
    """Each body's largest principal Green-Lagrange strain, in the report and
    the JSON (max_green_lagrange_strain), against E = (F^T F - I)/2 of the
    stretch F = diag(1.3, 0.8) imposed on the square: 0.345 (and -0.18), the
    same for both materials (a measure of the displacement, not of the model;
    measured `strain_error` = 2.1e-15 to 3.6e-15 off, bound 1e-12). The linear
    body, above 2 %, gets the report's warning line naming -square_material
    neohookean; the neo-Hookean one does not."""
    r = run_contact(square("quad9", HOMOGENEOUS["stretch"], material) + TIGHT, tmp_path)
    e = r.summary["bodies"]["square"]["max_green_lagrange_strain"]
    warned = [ln for ln in r.stdout.splitlines() if ln.startswith("  warning: body square")]
    print(material, e, warned)
    assert figure("strain_error", abs(e - 0.345)) <= 1e-12
    assert r.summary["bodies"]["square"]["material"] == material
    assert f"body square ({material}): largest Green-Lagrange strain 34.5 %" in r.stdout
    if material == "linear":
        assert len(warned) == 1 and "-square_material neohookean" in warned[0]
    else:
        assert not warned


@pytest.mark.roundoff
def test_two_ranks(tmp_path):
    """The reference scene with both bodies neo-Hookean on 1 and 2 ranks (the
    tangent assembled from each rank's cells, MUMPS's LDL^T of the whole
    Hessian, the tangent predictor), each solved to a tight stop (-tao_gttol
    1e-12, which Newton's quadratic convergence reaches in one or two more
    iterations): the same energy and contact force. Measured
    `dE` = 1.5e-15 to 4.3e-15 and `dP` = up to 1.4e-13 apart (relative)
    over the five kernels; bounds 1.5e-14 and 4e-13, about 3 times the largest."""
    args = ["-options_file", "meshes/hertz/hertz.opts", "-indenter_material", "neohookean", "-block_material", "neohookean",
            "-output", "none", "-tao_gttol", "1e-12"]
    one, two = (run_contact(args, tmp_path, ranks=n, name=f"r{n}").summary for n in (1, 2))
    print(one["iterations"], two["iterations"], one["energy"], two["energy"], one["contact_force"], two["contact_force"])
    assert figure("dE", abs(one["energy"] - two["energy"]) / one["energy"]) <= 1.5e-14
    assert figure("dP", abs(one["contact_force"] - two["contact_force"]) / one["contact_force"]) <= 4e-13


def residuals(out):
    """The gradient norms TAO's monitor printed, in order."""
    return [float(x) for x in re.findall(r"^\s*\d+ TAO,.*Residual: (\S+)", out, re.M)]


@pytest.mark.roundoff
def test_tangent_at_rest(tmp_path):
    """-tangent_at_rest: Newton's step takes the stiffness at rest in place of
    the neo-Hookean tangent (the linear bodies' Schur step, K condensed once),
    the gradient still the material's, so the answer is the full Newton's to
    the stop. The reference scene pushed by 0.01 (largest strain 1.4 %), both
    bodies neo-Hookean, against -tangent_at_rest 0 (the tangent reassembled and
    factored at every step), both solved to a tight stop (-tao_gttol 1e-12):
    the two take different paths (their monitored gradient norms differ:
    modified Newton's converge linearly, Newton's quadratically) to the same
    answer, P `dP` = 3.9e-13 to 7.5e-13 and the energy
    `dE` = 1.0e-15 to 3.7e-15 apart (relative) over the five kernels, bounds
    2.5e-12 and 1.2e-14; -tangent_at_rest on 2 ranks gives it too (P
    `dP_ranks` = 1.8e-14 to 1.3e-13, energy `dE_ranks` = 5.0e-16 to 4.5e-15
    apart; bounds 4e-13 and 1.5e-14)."""
    args = ["-options_file", "meshes/hertz/hertz.opts", "-indenter_material", "neohookean", "-block_material", "neohookean",
            "-block_bc_push_values", "-0.01,0", "-output", "none", "-tao_gttol", "1e-12", "-tao_monitor"]
    full = run_contact(args + ["-tangent_at_rest", "0"], tmp_path, name="full")
    rest = run_contact(args + ["-tangent_at_rest"], tmp_path, name="rest")
    rest2 = run_contact(args + ["-tangent_at_rest"], tmp_path, ranks=2, name="rest2").summary
    gf, gr = residuals(full.stdout), residuals(rest.stdout)
    full, rest = full.summary, rest.summary
    print("tangent", gf, "\nat rest", gr)
    print(full["iterations"], rest["iterations"], rest2["iterations"], rest["contact_force"] / full["contact_force"] - 1,
          rest["energy"] / full["energy"] - 1, rest2["contact_force"] / rest["contact_force"] - 1)
    assert len(gf) > 1 and len(gr) > 1 and gf != gr, "the same path: -tangent_at_rest 0 changed nothing"
    assert figure("dP", abs(rest["contact_force"] - full["contact_force"]) / full["contact_force"]) <= 2.5e-12
    assert figure("dE", abs(rest["energy"] - full["energy"]) / full["energy"]) <= 1.2e-14
    assert figure("dP_ranks", abs(rest2["contact_force"] - rest["contact_force"]) / rest["contact_force"]) <= 4e-13
    assert figure("dE_ranks", abs(rest2["energy"] - rest["energy"]) / rest["energy"]) <= 1.5e-14


@pytest.mark.parametrize("args,needle", [
    (["-indenter_material", "rubber"], "option -indenter_material: unknown material 'rubber' (known: linear, neohookean, mooneyrivlin, plastic)"),
    (["-indenter_material", "neohookean", "-indenter_nu", "0.5"], "option -indenter_nu: Poisson's ratio must be in (-1, 0.5), got 0.5"),
])
def test_bad_material(args, needle, tmp_path):
    """An unknown material names the known ones; nu = 0.5 with a neo-Hookean
    body (lambda infinite) is refused: one line each, status 1, nothing
    written."""
    r = run_contact(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.3"] + args, tmp_path, check=False)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    print(lines)
    assert r.returncode == 1 and len(lines) == 1 and lines[0] == "contact: error: " + needle
    assert not r.output_path.exists()


def test_inversion_stops_in_one_line(tmp_path):
    """A step that cannot avoid inversion: the unit square on rollers with
    its right edge moved to x = -0.1, through the left one, so that every
    admissible state has J <= 0 somewhere and the energy is +infinity there.
    The line search backs off, the load is cut back (as often as
    -load_cutbacks allows) and the run stops with one line naming the body
    and where it inverts, status 2, nothing written; no crash from a log of
    a negative J."""
    args = ["-scene", "uni", "-bodies", "b", "-b_geo", "tests/meshes/plate.geo", "-b_geo_params", "L=1,H=1,quads=0",
            "-b_mesh_size", 0.25, "-b_E", E, "-b_nu", NU, "-b_material", "neohookean",
            "-b_bc", "left,bottom,right", "-b_bc_left_components", "x", "-b_bc_bottom_components", "y",
            "-b_bc_right_components", "x", "-b_bc_right_values", "-1.1"]
    r = run_contact(args, tmp_path, check=False)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    print(r.returncode, lines)
    assert r.returncode == 2 and len(lines) == 1
    assert lines[0].startswith("contact: the solve did not converge") and "body b inverts: J <= 0 near" in lines[0]
    assert not r.output_path.exists() and not r.summary_path.exists()


TANGENT_ITS = 10  # -tangent_at_rest_its's default
TANGENT_SLOW = 0.5  # two steps must divide the gradient by more than 1 / TANGENT_SLOW


def tangent_choices(out):
    """The Newton solves of a run from -tao_monitor and -info :sys: for each,
    the gradient norms g_0, g_1, ... and the Hessian chosen at each
    iteration k >= 1 (True: the tangent), assembled after g_(k-1)."""
    solves = []
    for ln in out.splitlines():
        m = re.match(r"\s*(\d+) TAO,.*Residual: (\S+)", ln)
        if m:
            if int(m[1]) == 0:
                solves.append(([], {}))
            solves[-1][0].append(float(m[2]))
        m = re.search(r"Hessian at iteration (\d+): (the tangent|the stiffness at rest)", ln)
        if m:
            solves[-1][1][int(m[1])] = m[2] == "the tangent"
    return solves


def check_tangent_rule(solves, its=TANGENT_ITS):
    """The documented choice (docs/solver.md; src/solver/problem.c): the
    stiffness at rest while two steps divide the gradient by more than 2
    (g_(k-1) <= g_(k-3) / 2 at the Hessian of iteration k >= 3) and for at
    most `its` iterations, then the tangent for the rest of the solve.
    Asserted: the tangent wherever the rule within the solve asks for it,
    and the stiffness at rest wherever no step of the run so far was slow
    and k < its. (A solve after one whose steps were slow keeps the tangent
    from its first iteration: the program's slowness flag is reset at an
    iteration 0, which Newton's Hessians never see; not asserted either
    way.) Ratios within 1e-4 of the threshold (the monitor prints 6
    digits) are not judged. Returns the number of Hessians judged."""
    judged, slow_run = 0, False
    for g, chosen in solves:
        slow = False
        for k in sorted(chosen):
            unsure = False
            if k >= 3 and k - 1 < len(g):
                ratio = g[k - 1] / g[k - 3]
                unsure = abs(ratio / TANGENT_SLOW - 1) < 1e-4
                slow = slow or ratio > TANGENT_SLOW
            slow_run = slow_run or slow
            if unsure:
                break
            if slow or k >= its:
                assert chosen[k], (k, g, chosen)
            elif not slow_run:
                assert not chosen[k], (k, g, chosen)
            judged += 1
    return judged


@pytest.mark.roundoff
def test_tangent_chosen_by_convergence(tmp_path):
    """Newton without -tangent_at_rest takes the stiffness at rest while its
    steps divide the gradient by more than 2, then the tangent: on the rubber
    squeeze at 1 % of its push and at the full push, every Hessian's choice
    (-info names each) follows that rule applied to the gradient norms the run
    monitored (check_tangent_rule), and at the full push (52 % strain) the
    tangent is taken. Both answers are the tangent-every-step runs'
    (-tangent_at_rest 0), all solved to a gradient of 1e-12 at 1 % and 1e-10 at
    the full push (its round-off floor is near 1e-11): P measured
    `dP_small` = 4.3e-11 to 2.8e-10 and `dP_full` = 4.7e-13 to 1.3e-12 apart
    over the five kernels, bounds 1e-9 and 4e-12."""
    scene = ["-options_file", "meshes/rubber-squeeze/rubber-squeeze.opts", "-mesh_size", "0.1", "-output", "none",
             "-tao_grtol", "0", "-tao_gttol", "0"]
    for push, gatol, tag, bound in (("0,-0.003", "1e-12", "small", 1e-9), ("0,-0.3", "1e-10", "full", 4e-12)):
        args = scene + ["-plate_bc_contact_values", push, "-tao_gatol", gatol]
        r = run_contact(args + ["-info", ":sys", "-tao_monitor"], tmp_path, name="auto")
        solves = tangent_choices(r.stdout + r.stderr)
        judged = check_tangent_rule(solves)
        assert judged > 0, solves
        if tag == "full":
            assert any(any(c.values()) for g, c in solves), solves
        full = run_contact(args + ["-tangent_at_rest", "0"], tmp_path, name="full").summary
        dP = abs(r.summary["contact_force"] / full["contact_force"] - 1)
        print(push, [(len(g), sum(c.values())) for g, c in solves], judged, dP)
        assert figure(f"dP_{tag}", dP) <= bound
