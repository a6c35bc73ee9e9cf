"""Small-strain J2 plasticity with linear isotropic hardening
(-<body>_material plastic: src/body/plasticity.c), the first material with
history: its state at the quadrature points (src/body/bodystate.c) accepted
after each converged load increment, as the friction's is.

The kernels are checked by bin/material-check (tests/kernels/material_check.c)
at random accepted states, in the elastic and the plastic branch. The scenes
are our own: the unit box (tests/meshes/solid/block.geo, skew 0) on rollers
(xmin in x, ymin in y, zmin in z), pulled at xmax in x, free laterally: a
uniaxial stress sigma(eps) in x, uniform, so that P2/Q2 elements hold it
exactly and the finite element answer is the closed form's,

    sigma = E eps                          (eps <= eps_y = sigma_y / E),
    sigma = sigma_y + Et (eps - eps_y),    Et = E H / (E + H),

(sigma = sigma_y + H alpha on the yield surface, eps = sigma / E + alpha),
and unloading is elastic, of slope E, while |sigma| stays below the
hardened yield stress sigma_y + H alpha. E = 1000, nu = 0.3, sigma_y = 1,
H = 100: eps_y = 1e-3, Et = 90.909. Each run pins -tao_gttol 1e-12 (and
-tao_gatol 1e-13), so that a figure's error is the stop's: about 1e-12 of
the gradient at rest, ~E eps, relative to stresses of order sigma_y."""
import math
import subprocess

import pytest

from conftest import ROOT, figure, run_contact

GEO = "tests/meshes/solid/block.geo"
E, NU, SY, HH = 1000.0, 0.3, 1.0, 100.0
EPS_Y = SY / E
ET = E * HH / (E + HH)
TIGHT = ["-tao_gttol", "1e-12", "-tao_gatol", "1e-13"]


def sigma_uniaxial(eps):
    """The closed-form uniaxial stress at a monotonic strain eps >= 0."""
    return E * eps if eps <= EPS_Y else SY + ET * (eps - EPS_Y)


def alpha_uniaxial(eps):
    """The closed-form equivalent plastic strain at a monotonic strain eps."""
    return max(eps - sigma_uniaxial(eps) / E, 0.0)


def bar(hexa=True, h=0.5, name="blk"):
    """The unit box of plastic material on rollers, no load yet."""
    return ["-bodies", name, f"-{name}_geo", GEO, f"-{name}_geo_params", f"hex={int(hexa)},skew=0,n=2", "-mesh_size", repr(h),
            f"-{name}_material", "plastic", f"-{name}_E", repr(E), f"-{name}_nu", repr(NU), f"-{name}_yield", repr(SY),
            f"-{name}_hardening", repr(HH)] + TIGHT


def rollers(name="blk", pulled=True):
    """xmin, ymin, zmin on rollers; xmax held in x (its values given apart) where pulled."""
    groups = "xmin,ymin,zmin" + (",xmax" if pulled else "")
    args = [f"-{name}_bc", groups, f"-{name}_bc_xmin_components", "x", f"-{name}_bc_ymin_components", "y",
            f"-{name}_bc_zmin_components", "z"]
    return args + ([f"-{name}_bc_xmax_components", "x"] if pulled else [])


@pytest.fixture(scope="module")
def kernels():
    """bin/material-check's figures of the plastic material, {name: value}."""
    subprocess.run(["make", "-s", "bin/material-check"], cwd=ROOT, check=True, capture_output=True)
    out = subprocess.run([str(ROOT / "bin" / "material-check")], cwd=ROOT, check=True, capture_output=True, text=True).stdout
    return {name: float(v) for mat, name, v in (l.split() for l in out.splitlines()) if mat == "plastic"}


@pytest.mark.roundoff
def test_kernels(kernels):
    """At 200 random accepted states and H (material_check.c): central
    differences at h = 1e-4 of the strain's scale against P:E and A:E, each
    in the branch its return takes. Elastic: W quadratic, P linear,
    differences exact but for round-off, `fd_P_elastic` = 3.8e-13,
    `fd_A_elastic` = 4.1e-13 (bound 1e-9); plastic: W smooth in the
    branch, the differences' O(h^2) error, `fd_P_plastic` = 2.8e-9,
    `fd_A_plastic` = 3.1e-9 (bound 1e-6, 100 (h/s)^2: a wrong tangent term
    is O(1)). A symmetric to round-off (`sym_A` = 1.0e-16, bound 1e-12).
    At a zero state below yield W, P and A are linear elasticity's to the
    bit (`linear_diff` = 0 over 50 samples). From the updated state at the
    same H, P and W are the increment's (`accept_P` = 9.3e-16, `accept_W`
    = 3.9e-16, bound 1e-12) and the point is on its yield surface (a second
    return adds `accept_yield` = 6.4e-15 of the increment's alpha, bound
    1e-10)."""
    k = kernels
    assert k["samples_elastic"] >= 20 and k["samples_plastic"] >= 20 and k["samples_linear"] >= 20
    assert figure("fd_P_elastic", k["fd_P_elastic_rel"]) <= 1e-9
    assert figure("fd_A_elastic", k["fd_A_elastic_rel"]) <= 1e-9
    assert figure("fd_P_plastic", k["fd_P_plastic_rel"]) <= 1e-6
    assert figure("fd_A_plastic", k["fd_A_plastic_rel"]) <= 1e-6
    assert figure("sym_A", k["sym_A_rel"]) <= 1e-12
    assert figure("linear_diff", k["linear_diff"]) == 0.0
    assert figure("accept_P", k["accept_P_rel"]) <= 1e-12
    assert figure("accept_W", k["accept_W_rel"]) <= 1e-12
    assert figure("accept_yield", k["accept_yield_rel"]) <= 1e-10


def test_uniaxial_stress_strain(tmp_path):
    """The Hex27 box pulled to eps = 3 eps_y in 6 load steps (-load_path):
    at each converged step the reaction at xmax, the stress times the area
    1, against the closed form, through yield (the second step ends on it)
    and past it: `stress_error` = 1.9e-14 of sigma_y at most (bound 1e-9);
    the slope between the last two steps against Et = E H / (E + H):
    `slope_error` = 1.7e-15 relative (bound 1e-6: the stresses' errors over
    an increment of 5e-4); the equivalent plastic strain at the end (the
    state's range over the quadrature points) against eps - sigma / E:
    `alpha_error` = 4.2e-14 of alpha (bound 1e-8). Each step is a convex
    minimisation of the increment's potential, solved by Newton with the
    consistent tangent."""
    emax = 3 * EPS_Y
    s = run_contact(bar() + rollers() + ["-blk_bc_xmax_values", repr(emax), "-load_steps", "6", "-load_path",
                                         "-output", "none"], tmp_path).summary
    path = s["load_path"]
    assert len(path) == 7
    err = max(abs(p["reactions"]["blk:xmax"][0] - sigma_uniaxial(p["load"] * emax)) / SY for p in path)
    assert figure("stress_error", err) <= 1e-9
    (l1, r1), (l2, r2) = [(p["load"] * emax, p["reactions"]["blk:xmax"][0]) for p in path[-2:]]
    assert figure("slope_error", abs((r2 - r1) / (l2 - l1) / ET - 1)) <= 1e-6
    b = s["bodies"]["blk"]
    a = alpha_uniaxial(emax)
    assert figure("alpha_error", max(abs(b["state_max"][6] - a), abs(b["state_min"][6] - a)) / a) <= 1e-8


def test_unloading_to_zero_displacement(tmp_path):
    """Pulled to eps = 1.5 eps_y in 3 steps, then back to zero displacement
    in 3 (-load_stages 2): unloading is elastic (|sigma| = E alpha = 0.45
    stays below sigma_y + H alpha = 1.05), so the box keeps the plastic
    strain alpha = eps - sigma / E = 4.545e-4 of the first stage's end
    (`alpha_error` = 6.3e-13 relative, every point; bound 1e-8) and the
    residual stress -E alpha (`residual_error` = 7.8e-16 of sigma_y, bound
    1e-9); along the way back the slope is E: each unloading step's
    reaction against sigma_max - E (eps_max - eps) (`unload_error` = 1.2e-15
    of sigma_y, bound 1e-9). The plastic strain is uniaxial and isochoric:
    eps_p = alpha (1, -1/2, -1/2) (`direction_error` = 6.3e-13 of alpha,
    bound 1e-8)."""
    emax = 1.5 * EPS_Y
    smax, a = sigma_uniaxial(emax), alpha_uniaxial(emax)
    s = run_contact(bar() + rollers() + ["-blk_bc_xmax_values", f"{emax!r},0", "-load_stages", "2", "-load_steps", "3",
                                         "-load_path", "-output", "none"], tmp_path).summary
    b = s["bodies"]["blk"]
    assert figure("alpha_error", max(abs(b["state_max"][6] - a), abs(b["state_min"][6] - a)) / a) <= 1e-8
    R = s["reactions"]["blk:xmax"][0]
    assert figure("residual_error", abs(R + E * a) / SY) <= 1e-9
    back = [p for p in s["load_path"] if p["load"] > 1]
    err = max(abs(p["reactions"]["blk:xmax"][0] - (smax - E * emax * (p["load"] - 1))) / SY for p in back)
    assert figure("unload_error", err) <= 1e-9
    want = [a, -a / 2, -a / 2, 0, 0, 0]
    dev = max(max(abs(b["state_max"][k] - w), abs(b["state_min"][k] - w)) for k, w in enumerate(want))
    assert figure("direction_error", dev / a) <= 1e-8


def test_unloading_to_zero_force(tmp_path):
    """A traction on xmax (stage 1: sigma = sigma_y + Et eps_y / 2, past
    yield; stage 2: zero) instead of a displacement: at zero force the
    elastic strain is zero and the box keeps the plastic strain alone,
    alpha = (sigma - sigma_y) / H (`alpha_error` = 5.5e-14 relative; bound
    1e-8): its corner (1, 1, 1) moves by alpha (1, -1/2, -1/2), the largest
    displacement alpha sqrt(3/2) (`displacement_error` = 1.1e-14 relative,
    bound 1e-8)."""
    smax = SY + ET * EPS_Y / 2
    a = (smax - SY) / HH
    s = run_contact(bar() + rollers(pulled=False) + ["-blk_load", "xmax", "-blk_load_xmax_traction", f"{smax!r},0,0,0,0,0",
                                                     "-load_stages", "2", "-load_steps", "3", "-output", "none"], tmp_path).summary
    b = s["bodies"]["blk"]
    assert figure("alpha_error", max(abs(b["state_max"][6] - a), abs(b["state_min"][6] - a)) / a) <= 1e-8
    assert figure("displacement_error", abs(b["max_displacement"] / (a * math.sqrt(1.5)) - 1)) <= 1e-8


def test_axisymmetric(tmp_path):
    """Supported in r-z, where the hoop strain u_r / r is one more component
    of the strain: a solid cylinder (radius 0.5, height 1: tests/meshes/
    plate.geo, Quad9, -axisymmetric) on rollers at its bottom, its top moved
    in z to 1.5 eps_y and back to 0, free at r = 0.5: uniaxial stress in z,
    the reaction at the top sigma pi r^2, against the closed form at every
    step (`stress_error` = 2.0e-14 of sigma_y, bound 1e-9), and the residual
    alpha (`alpha_error` = 2.7e-14 relative, bound 1e-8); the hoop plastic
    strain is -alpha / 2 (`hoop_error` = 1.4e-14 of alpha, bound 1e-8)."""
    emax = 1.5 * EPS_Y
    smax, a = sigma_uniaxial(emax), alpha_uniaxial(emax)
    args = ["-axisymmetric", "-bodies", "bar", "-bar_geo", "tests/meshes/plate.geo", "-bar_geo_params", "x0=0,y0=0,L=0.5,H=1,quads=1",
            "-mesh_size", "0.25", "-bar_material", "plastic", "-bar_E", repr(E), "-bar_nu", repr(NU), "-bar_yield", repr(SY),
            "-bar_hardening", repr(HH), "-bar_bc", "bottom,top", "-bar_bc_bottom_components", "y", "-bar_bc_top_components", "y",
            "-bar_bc_top_values", f"{emax!r},0", "-load_stages", "2", "-load_steps", "3", "-load_path", "-output", "none"] + TIGHT
    s = run_contact(args, tmp_path).summary
    area = math.pi * 0.25
    err = 0.0
    for p in s["load_path"]:
        lam = p["load"]
        want = sigma_uniaxial(lam * emax) if lam <= 1 else smax - E * emax * (lam - 1)
        err = max(err, abs(p["reactions"]["bar:top"][1] / area - want) / SY)
    assert figure("stress_error", err) <= 1e-9
    b = s["bodies"]["bar"]
    assert figure("alpha_error", max(abs(b["state_max"][6] - a), abs(b["state_min"][6] - a)) / a) <= 1e-8
    assert figure("hoop_error", max(abs(b["state_max"][2] + a / 2), abs(b["state_min"][2] + a / 2)) / a) <= 1e-8


@pytest.mark.roundoff
def test_ranks(tmp_path):
    """The Tet10 box (unstructured, h = 0.4) pulled to 1.5 eps_y and back to
    zero force (a traction, as above) at 1 and 2 ranks: each rank updates its
    own cells' points, and the runs agree: the plastic strain's range
    (`alpha_diff` = 5.1e-14 relative), the largest displacement
    (`displacement_diff` = 2.0e-14 relative) and the energy (`energy_diff`
    = 2.2e-14 relative); bound 1e-9, the stop's 1e-12 of the gradient at
    rest times the condition of the box's stiffness and over 3x what is
    measured."""
    smax = SY + ET * EPS_Y / 2
    args = bar(hexa=False, h=0.4) + rollers(pulled=False) + ["-blk_load", "xmax", "-blk_load_xmax_traction",
                                                            f"{smax!r},0,0,0,0,0", "-load_stages", "2", "-load_steps", "3", "-output", "none"]
    one = run_contact(args, tmp_path, name="np1").summary
    two = run_contact(args, tmp_path, name="np2", ranks=2).summary
    b1, b2 = one["bodies"]["blk"], two["bodies"]["blk"]
    a = b1["state_max"][6]
    assert a > 0
    da = max(abs(b1["state_max"][6] - b2["state_max"][6]), abs(b1["state_min"][6] - b2["state_min"][6])) / a
    assert figure("alpha_diff", da) <= 1e-9
    assert figure("displacement_diff", abs(b1["max_displacement"] / b2["max_displacement"] - 1)) <= 1e-9
    assert figure("energy_diff", abs(one["energy"] / two["energy"] - 1)) <= 1e-9


@pytest.mark.roundoff
def test_taylor(tmp_path):
    """-taylor_test at the end of a plastic increment (the Hex27 box pulled
    to 1.5 eps_y in 3 steps): the body's energy is still the increment's
    potential (the state the increment recorded becomes the accepted one as
    the next begins, bodystate.c), smooth where the points flow, so the
    energy's remainder falls at order 2 (`gradient_order_error` = -8.2e-5
    to 1.2e-5 off 2 over the OpenBLAS kernels) and so does the gradient's with the consistent tangent
    (`hessian_order_error` = -1.6e-5 to 1.4e-5 off 2); bounds 1e-3 of 2 (an elastic
    tangent in the plastic branch gives order 1)."""
    s = run_contact(bar() + rollers() + ["-blk_bc_xmax_values", repr(1.5 * EPS_Y), "-load_steps", "3", "-taylor_test",
                                         "-output", "none"], tmp_path).summary
    t = s["taylor"]
    assert abs(figure("gradient_order_error", t["gradient_order"] - 2.0)) <= 1e-3
    assert abs(figure("hessian_order_error", t["hessian_order"] - 2.0)) <= 1e-3


@pytest.mark.parametrize("case", ["no_yield", "bad_hardening", "exact", "accuracy"])
def test_refused(case, tmp_path):
    """-yield is required and > 0, -hardening >= 0, no exact solution's
    body force holds a material with history, and -accuracy's refined meshes
    would lose it (the state's transfer to a new mesh is not written): one
    line each, status 1."""
    args = bar() + rollers() + ["-blk_bc_xmax_values", "0.001"]
    if case == "no_yield":
        args = [a for a in args if a not in ("-blk_yield", repr(SY))]
        want = "-blk_yield is required"
    elif case == "bad_hardening":
        args += ["-blk_hardening", "-1"]
        want = "-blk_hardening"
    elif case == "exact":
        args += ["-blk_exact", "affine", "-blk_exact_params", ",".join(["0"] * 12)]
        want = "-blk_exact"
    else:
        args += ["-accuracy", "0.01"]
        want = "-accuracy: body blk's material (-blk_material plastic) has history"
    res = run_contact(args + ["-output", "none"], tmp_path, check=False)
    errors = [l for l in res.stderr.splitlines() if l.startswith("contact: error:")]
    assert res.returncode == 1, res.stderr[-2000:]
    assert len(errors) == 1 and want in errors[0], res.stderr[-2000:]
