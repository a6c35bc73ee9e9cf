"""Contact between 3D bodies (mortar on Tri6 and Quad9 faces,
src/contact/mortar3d.c) on scenes of our own: two boxes of
tests/meshes/contact3d/box.geo (Hex27 transfinite, n cells across and m in
height, or Tet10 of size h) pressed together, the upper's bottom on the
lower's top, through -contact_pairs and -contact_<pair>_surfaces.

The patch scene: the lower box [0, 1]^2 x [0, 0.5] held at its bottom in z,
the upper [0, 1]^2 x [0.5, 1] pushed down by D on its top, every lateral
face of both on rollers (its normal component held). Its exact solution is
uniaxial strain in both boxes: sigma_zz = -p uniform, with

    D = p (H_l / M_l + H_u / M_u) + p / k_p,   M = E (1 - nu) / ((1 + nu)(1 - 2 nu)),

the penetration p / k_p uniform on the interface (the faces stay flat, the
footprints flush), so every slave node's pressure is p and the pair's force
on the upper box is p times the area, (0, 0, p), which the reactions of the
lower's bottom and of the upper's top balance."""
import pytest

from conftest import figure, run_contact
import hertz

GEO = "tests/meshes/contact3d/box.geo"
E, NU, D = 1000.0, 0.3, 0.01
M = E * (1 - NU) / ((1 + NU) * (1 - 2 * NU))
# the stop pinned: a gradient of 1e-10 (the nodal forces are 1e-1 to 1, the
# penetration 4e-6 of a displacement 1e-2: the pressure to 1e-10 of itself)
SOLVE = ["-tao_gatol", "1e-10", "-tao_grtol", "0", "-tao_gttol", "0"]
LOWER = "hex=1,n=3,m=2"
UPPERS = {"hex27-on-hex27": "hex=1,n=4,m=2,z0=0.5", "tet10-on-hex27": "hex=0,h=0.3,z0=0.5"}


def box(name, params, top):
    """A box body (E 1000, nu 0.3), its lateral faces on rollers, held in z
    at its bottom (top: at its top, pushed down by D)."""
    held = "top" if top else "bottom"
    args = ["-" + name + "_geo", GEO, f"-{name}_geo_params", params, f"-{name}_E", E, f"-{name}_nu", NU,
            f"-{name}_bc", f"{held},xmin,xmax,ymin,ymax", f"-{name}_bc_{held}_components", "z"]
    if top:
        args += [f"-{name}_bc_top_values", -D]
    for g, c in (("xmin", "x"), ("xmax", "x"), ("ymin", "y"), ("ymax", "y")):
        args += [f"-{name}_bc_{g}_components", c]
    return args


def patch_args(upper, extra=()):
    return (["-bodies", "lower,upper"] + box("lower", LOWER, False) + box("upper", upper, True)
            + ["-contact_pairs", "p", "-contact_p_surfaces", "upper:bottom,lower:top", "-output", "none"] + list(extra))


def exact_pressure(kp):
    return D / (0.5 / M + 0.5 / M + 1.0 / kp)


@pytest.mark.roundoff
@pytest.mark.parametrize("slave", ["first", "second"])
@pytest.mark.parametrize("case", list(UPPERS))
def test_patch(case, slave, tmp_path):
    """The contact patch test, non-matching meshes (the upper box Hex27 4 x 4
    on the lower's 3 x 3, or Tet10 of size 0.3 on it), either surface as
    slave: every slave node is in contact and its pressure k_p <-g_j>_+ is
    the exact p of the uniaxial strain (the pair's reported k_p in D's
    formula) to 1e-8 (measured: `pressure_error` = up to 6.3e-11 relative
    at the stop's gradient 1e-10); the pair's forces on its two bodies
    balance to round-off (`pair_balance` = up to 4e-16 of P), its lateral
    components are round-off (`lateral` = up to 3.6e-14 of P), and its normal
    component equals p times the area (`force_error` = up to 2.3e-12) and the
    reactions of the lower's bottom and of the upper's top to what the stop
    leaves (`reaction_balance` = up to 2.3e-12 of P; the residual gradient,
    at most 1e-10, bounds each reaction's miss)."""
    s = run_contact(patch_args(UPPERS[case], SOLVE + ["-contact_mortar_slave", slave]), tmp_path).summary
    c = s["contact"]["p"]
    assert c["dimension"] == 3 and c["penalty_auto"]
    slave_side = 0 if slave == "first" else 1
    assert c["surfaces"][slave_side]["slave"]
    nslave = c["surfaces"][slave_side]["nodes"]
    assert c["nodes_in_contact"] == nslave == c["nodes_counted"]
    p = exact_pressure(c["penalty"])
    err = max(abs(c["pmax"] - p), abs(c["pmin"] - p)) / p
    assert figure("pressure_error", err) <= 1e-8
    F = c["surfaces"][0]["force"]       # on the upper box
    G = c["surfaces"][1]["force"]       # on the lower box
    P = abs(F[2])
    assert figure("pair_balance", max(abs(a + b) for a, b in zip(F, G)) / P) <= 1e-13
    assert figure("lateral", max(abs(F[0]), abs(F[1])) / P) <= 1e-10
    assert figure("force_error", abs(F[2] - p) / p) <= 1e-8
    stop = 3 * s["gradient_norm"] * nslave ** 0.5 + 1e-13 * P
    Rl, Ru = s["reactions"]["lower:bottom"], s["reactions"]["upper:top"]
    miss = max(abs(Rl[2] - P), abs(Ru[2] + P))
    figure("reaction_balance", miss / P)
    assert miss <= stop
    assert abs(s["contact_force"] - P) <= 1e-12 * P and abs(s["fem_pmax"] - c["pmax"]) <= 1e-12 * p


@pytest.mark.roundoff
@pytest.mark.parametrize("scene", ["patch", "hertz"])
def test_taylor(scene, tmp_path):
    """The Taylor test (-taylor_test) at the solution, the Hessian exact
    near it (-contact_hessian auto: k_p G_j G_j^T / A_j plus the gap's second
    derivative, the master normal's turning and the closest point's motion).
    The Tet10-on-Hex27 patch: the gradient's and the Hessian's remainders
    fall as eps^2 (`gradient_order` = 2.000, `hessian_order` = 1.98 to 2.004,
    bounds [1.9, 2.1]; Gauss-Newton alone gives 1.000 there, its remainder
    2.3e-5 of |H v|). The quarter Hertz ball at h = 0.04, in a direction
    small enough (-taylor_scale 1e-6) that no node enters or leaves the
    contact: the gradient's order 2.000 too, the Hessian's remainder falls
    to `hessian_remainder` = 2.4e-9 of |H v| and levels there (the
    pieces' borders straight between the master's nodes, where the gap's
    gradient jumps along a curve: with -contact_mortar_edge_points 3 it
    falls at order 2 to round-off, test_seghess3d.py; the whole
    ball's 1.55e-9; 8.0e-9 while the master's nodes were projected along
    the slave sub-triangles' normals, 2.9e-6 before the symmetry planes'
    slivers were closed; Gauss-Newton alone 3.8e-6); bound 7.5e-9."""
    if scene == "patch":
        args = patch_args(UPPERS["tet10-on-hex27"], ["-taylor_test"])
    else:
        args = hertz_args(0.04) + ["-taylor_test", "-taylor_scale", "1e-6"]
    t = run_contact(args, tmp_path).summary["taylor"]
    assert 1.9 <= figure("gradient_order", t["gradient_order"]) <= 2.1
    figure("hessian_order", t["hessian_order"])
    if scene == "patch":
        assert 1.9 <= t["hessian_order"] <= 2.1
    else:
        assert figure("hessian_remainder", t["hessian_relative_remainder"][-1]) <= 7.5e-9


@pytest.mark.roundoff
@pytest.mark.parametrize("scene", ["patch", "hertz"])
def test_ranks_agree(scene, tmp_path):
    """The Tet10-on-Hex27 patch and the quarter Hertz ball at h = 0.04
    (test_hertz_quarter: a curved slave, a contact zone that ends inside
    both surfaces) on 1 and 2 ranks: the pair's force and the nodal
    pressures agree to what the stop guarantees (each run's residual
    gradient moves a nodal force by at most that, and a nodal pressure by
    that over the node's weight, bounded here by n over the contact area;
    `dF` = up to 2.0e-12 of P, `dp` = up to 1.8e-10 relative, the largest
    at the Hertz zone's edge, where p is 0.4 of a peak of 69), and the same
    nodes are in contact."""
    args = patch_args(UPPERS["tet10-on-hex27"], SOLVE) if scene == "patch" else hertz_args(0.04)
    one = run_contact(args, tmp_path, name="one").summary
    two = run_contact(args, tmp_path, ranks=2, name="two").summary
    assert two["ranks"] == 2
    pair = "p" if scene == "patch" else "c"
    c1, c2 = one["contact"][pair], two["contact"][pair]
    P = c1["P"]
    n = c1["surfaces"][0]["nodes"]
    bound = 3 * n ** 0.5 * (one["gradient_norm"] + two["gradient_norm"]) + 1e-13 * P
    dF = max(abs(a - b) for a, b in zip(c1["force"], c2["force"]))
    figure("dF", dF / P)
    assert dF <= bound
    for k in ("pmax", "pmin"):
        figure("dp", abs(c1[k] - c2[k]) / c1[k])
        assert abs(c1[k] - c2[k]) <= bound / c1["contact_area"] * n
    assert c1["nodes_in_contact"] == c2["nodes_in_contact"]


def refused(args, tmp_path):
    res = run_contact(args, tmp_path, check=False)
    errors = [l for l in res.stderr.splitlines() if l.startswith("contact: error:")]
    assert res.returncode == 1, res.stderr[-2000:]
    assert len(errors) == 1, res.stderr[-2000:]
    assert "PETSC ERROR" not in res.stderr
    return errors[0]


def test_refused(tmp_path):
    """What 3D contact does not do yet, one line each naming the pair: gpts
    (a 2D formulation), a 2D half model's mirror, and
    -contact_mortar_slave both; and a surface its body's mesh has not, one
    line naming the body and the group (friction: tests/test_friction3d.py;
    the Hertz report of a 3D pair: tests/test_sphere3d.py)."""
    up = UPPERS["hex27-on-hex27"]
    line = refused(patch_args(up, ["-contact_formulation", "gpts"]), tmp_path)
    assert "contact pair p" in line and "gpts" in line and "mortar" in line
    line = refused(patch_args(up, ["-contact_p_mirror_y", "0"]), tmp_path)
    assert "mirror" in line and "contact pair p" in line
    line = refused(patch_args(up, ["-contact_mortar_slave", "both"]), tmp_path)
    assert "contact pair p" in line and "both" in line
    line = refused(patch_args(up, ["-contact_p_surfaces", "upper:bottom,lower:nosuch"]), tmp_path)
    assert "body lower" in line and "no physical surface 'nosuch'" in line


# The Hertz scene: a quarter ball (tests/meshes/contact3d/ball.geo, R = 1,
# E 1000) on a block 100 times stiffer (base.geo), both Tet10 graded to the
# mesh size h within 0.2 of the contact point, the symmetry planes x = 0 and
# y = 0 on rollers, the block held at its bottom in z, the ball's top pushed
# down by 0.01: a/R = 0.10. The contact surfaces are the ball's cap below
# z = 0.1 and the block's top square [0, 0.35]^2.
BALL, BASE = "tests/meshes/contact3d/ball.geo", "tests/meshes/contact3d/base.geo"
E_BALL, E_BASE = 1000.0, 1e5


def hertz_args(h):
    args = ["-bodies", "ball,base"]
    for name, geo, E, params, held in (("ball", BALL, E_BALL, "rc=0.2,zc=0.1", "top"), ("base", BASE, E_BASE, "rc=0.2,c=0.35", "bottom")):
        args += [f"-{name}_geo", geo, f"-{name}_geo_params", params, f"-{name}_mesh_size", h, f"-{name}_E", E, f"-{name}_nu", NU,
                 f"-{name}_bc", f"{held},symx,symy", f"-{name}_bc_{held}_components", "z",
                 f"-{name}_bc_symx_components", "x", f"-{name}_bc_symy_components", "y"]
    return args + ["-ball_bc_top_values", -0.01, "-contact_pairs", "c", "-contact_c_surfaces", "ball:cap,base:top", "-output", "none"]


def test_hertz_quarter(tmp_path):
    """A quarter ball on a block against Hertz (a = (3PR/(4E*))^(1/3),
    p0 = 3P/(2 pi a^2), P four times the quarter's force) at h = 0.04, about
    2.5 elements across a: the nodal pressures' peak `pmax_error` = -1.7 %
    from p0, the contact radius from their second moment (sum p_j A_j r_j^2
    / sum p_j A_j = 2 a^2 / 5 for Hertz's profile) `a_error` = +1.1 % from
    a; bounds 5 % and 3 %. The pressures carry the pair's force: 4 sum p_j
    A_j is P to `force_sum` = -1.2e-6 (not round-off: on the curved cap the
    pieces' rule integrates W_j over a node's faces, C_j, to 3e-4 of the
    faces' own rule's A_j at worst, and the block's top tilts under the
    load; bound 1e-5). At h = 0.025 (docs/formulations.md) the errors are
    -0.95 % and +0.52 %. The scene declares no symmetry plane: the report
    notes that x = 0 and y = 0 cut the zone where both surfaces end, and
    names -contact_c_symmetry x=0,y=0 (report3d.c)."""
    import math
    r = run_contact(hertz_args(0.04), tmp_path)
    s = r.summary
    c = s["contact"]["c"]
    note = next(line for line in r.stdout.splitlines() if "note: the zone is cut" in line)  # no symmetry declared
    assert "the planes x = 0 (up to 1.00 p_max on it), y = 0" in note and "-contact_c_symmetry x=0,y=0" in note
    assert c["surfaces"][0]["slave"]
    P = 4 * c["force"][2]
    a, p0 = hertz.sphere(P, hertz.plane_strain_modulus(E_BALL, NU, E_BASE, NU))
    rows = c["contact_nodes"]["rows"]
    spa = sum(r[3] * r[4] for r in rows)
    am = hertz.moment_radius(rows)
    assert abs(figure("pmax_error", c["pmax"] / p0 - 1)) <= 0.05
    assert abs(figure("a_error", am / a - 1)) <= 0.03
    assert abs(figure("force_sum", 1 - 4 * spa / P)) <= 1e-5
    assert c["nodes_in_contact"] == len(rows) > 10
