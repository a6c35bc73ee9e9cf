"""Rigid bodies (-<body>_rigid): a body given by its curves alone,
moved rigidly by its conditions (translation) and -<body>_rigid_rotation,
with no dofs. The scene meshes/rigid-hertz: a rigid cylinder (R = 1) and the
elastic block (E = 1000, nu = 0.3) pushed onto it by 0.0095, graded to a/10
at the contact. Each figure against an independent answer: Hertz's line
contact with E* = E / (1 - nu^2), the elastic body made stiffer (the rigid
answer is its limit), the same relative motion given to the other body,
a rotation of a circle about its centre, another rank count."""
import math
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT, run_contact
from rigid_study import PUNCH, sadowsky_l2, stiff_options

SCENE = ["-options_file", "meshes/rigid-hertz/rigid-hertz.opts"]
SPHERE = ["-options_file", "meshes/rigid-sphere/rigid-sphere.opts"]
ROLLER = ["-options_file", "meshes/rigid-roller/rigid-roller.opts"]


@pytest.fixture(scope="module")
def rigid_run(tmp_path_factory):
    """The scene as given (mortar; the elastic block is the slave)."""
    tmp = tmp_path_factory.mktemp("rigid")
    return run_contact(SCENE, tmp)


@pytest.fixture(scope="module")
def rigid(rigid_run):
    return rigid_run.summary


def hertz_errors(s):
    return s["fem_pmax"] / s["hertz_pmax"] - 1, s["fem_a_moment"] / s["hertz_a"] - 1


@pytest.mark.parametrize("formulation", ["mortar", "gpts"])
def test_hertz(formulation, rigid, tmp_path):
    """A rigid cylinder in an elastic block matches Hertz with E* = E / (1 - nu^2)
    (the block's alone: 1098.9), at a / h of 10: p_max within 1 % and the
    second-moment half-width within 1 % (measured mortar -0.33 % and +0.41 %,
    gpts +0.43 % and -0.36 %)."""
    s = rigid if formulation == "mortar" else run_contact(SCENE + ["-contact_formulation", formulation, "-output", "none"], tmp_path).summary
    assert s["E_star"] == pytest.approx(1000 / (1 - 0.3 ** 2), rel=1e-12)
    dp, da = hertz_errors(s)
    print(f"{formulation}: p_max {dp:+.2%}, a {da:+.2%}")
    assert abs(dp) <= 0.01 and abs(da) <= 0.01


def test_rigid_slave(tmp_path):
    """The rigid surface as mortar's slave (-contact_mortar_slave first; the
    automatic choice takes the softer body, the block): p_max within 2 % and
    the half-width within 2 % of Hertz (measured +1.45 % and -1.41 %). A
    rigid slave finer than its master oscillates (its nodes ask more than
    the master's can give): at the disc's hc = 0.0038, p_max +13.9 %."""
    s = run_contact(SCENE + ["-contact_mortar_slave", "first", "-output", "none"], tmp_path).summary
    dp, da = hertz_errors(s)
    print(f"rigid slave: p_max {dp:+.2%}, a {da:+.2%}")
    assert abs(dp) <= 0.02 and abs(da) <= 0.02


def test_stiff_limit(rigid, tmp_path):
    """The rigid answer is the limit of the elastic disc made stiffer: at
    E = 1e8 (1e5 times the block's) P is 1.46e-5 from the rigid one, at
    1e10 4.7e-7, the O(1/E) of the disc's own compliance (bounds 4e-5 and
    2e-6); p_max alike (1.28e-5, 7.3e-7). The rigid disc has no dofs: 6672
    against 14028."""
    for E, bound in ((1e8, 4e-5), (1e10, 2e-6)):
        s = run_contact(["-options_file", stiff_options(tmp_path, E), "-output", "none"], tmp_path, name=f"E{E:g}").summary
        dP = rigid["contact_force"] / s["contact_force"] - 1
        dp = rigid["fem_pmax"] / s["fem_pmax"] - 1
        print(f"E = {E:g}: P {dP:.2e}, p_max {dp:.2e}; dofs {rigid['dofs']} against {s['dofs']}")
        assert abs(dP) <= bound and abs(dp) <= bound
    assert rigid["dofs"] < s["dofs"] / 2


def test_motion_given_to_the_rigid_body(rigid, tmp_path):
    """The same relative motion given to the rigid disc (translated by
    +0.0095) with the block held gives the same answer: P to the solver's
    stop (measured 1.6e-10, bound 1e-8)."""
    s = run_contact(SCENE + ["-block_bc_push_values", "0,0", "-indenter_bc_back_values", "0.0095,0", "-output", "none"], tmp_path).summary
    d = s["contact_force"] / rigid["contact_force"] - 1
    print(f"P {d:.2e}; the disc's translation {s['bodies']['indenter']['translation']}")
    assert s["bodies"]["indenter"]["translation"] == [0.0095, 0]
    assert abs(d) <= 1e-8


def test_rotation_about_centre(rigid, tmp_path):
    """A circle turned about its centre is the same circle: the rigid disc
    rotated by 0.05 rad about (-1, 0) gives the same P to the solver's stop
    (its nodes move along the arc, which their quadratic edges follow:
    measured 1.4e-9, bound 1e-8), and the contact's moment about the centre
    is nil beside P R (frictionless: every normal passes through the centre;
    measured 6.9e-10, bound 1e-8)."""
    s = run_contact(SCENE + ["-indenter_rigid_centre", "-1,0", "-indenter_rigid_rotation", "0.05", "-output", "none"], tmp_path).summary
    ind = s["bodies"]["indenter"]
    d = s["contact_force"] / rigid["contact_force"] - 1
    m = ind["moment"] / (s["contact_force"] * 1.0)
    print(f"P {d:.2e}, moment / (P R) {m:.2e}, rotation {ind['rotation']}")
    assert ind["rotation"] == 0.05 and ind["centre"] == [-1, 0]
    assert abs(d) <= 1e-8
    assert abs(m) <= 1e-8


def test_balance(rigid):
    """The rigid body's force is the contact's (its reaction, through the
    condition that holds it), to round-off; its default reference point is
    the circle's centre (the curves' centroid by length, whatever the
    grading: x 4.8e-8 off, the quadratic edges' departure from the circle,
    bound 2e-7; y 1.2e-15, bound 1e-12), about which the contact's moment is
    nil (measured 6.7e-12 of P, bound 1e-9); and the block's support carries
    it back to the solver's stop (the block's residual: measured 1.8e-10 of
    P, bound 1e-9)."""
    P = rigid["contact_force"]
    ind = rigid["bodies"]["indenter"]
    r_ind, r_block = rigid["reactions"]["indenter:back"], rigid["reactions"]["block:push"]
    print(ind, r_ind, r_block)
    assert ind["rigid"] and ind["dofs"] == 0
    # the default reference point, the curves' centroid by length: the circle's centre (the mesh is graded)
    assert abs(ind["centre"][0] + 1) <= 2e-7 and abs(ind["centre"][1]) <= 1e-12
    assert abs(ind["moment"]) <= 1e-9 * P   # frictionless on a circle: every normal through the centre
    assert math.hypot(*ind["force"]) == pytest.approx(P, rel=1e-12)
    assert r_ind == ind["force"]
    assert abs(r_ind[0] + r_block[0]) <= 1e-9 * P and abs(r_ind[1] + r_block[1]) <= 1e-9 * P


def test_ranks(rigid, tmp_path):
    """2 ranks give the 1-rank answer: P and p_max to 1e-11 (measured 4.6e-13
    and 2.8e-15)."""
    s = run_contact(SCENE, tmp_path, ranks=2).summary
    for k in ("contact_force", "fem_pmax"):
        print(k, s[k] / rigid[k] - 1)
        assert s[k] == pytest.approx(rigid[k], rel=1e-11)
    assert s["bodies"]["indenter"]["force"][0] == pytest.approx(rigid["bodies"]["indenter"]["force"][0], rel=1e-11)


@pytest.mark.parametrize("scene,args,words", [
    (SCENE, ["-indenter_bc", "back,contact", "-indenter_bc_contact_components", "x", "-indenter_bc_contact_values", "0",
             "-indenter_bc_back_control", "force,displacement"], ["rigid", "both give its translation in x"]),
    (SCENE, ["-indenter_bc_back_control", "force,displacement", "-force_control_type", "outer"], ["-force_control_type", "coupled only"]),
    (SCENE, ["-indenter_rigid_rotation", "nan"], ["-indenter_rigid_rotation", "finite"]),
    (SCENE, ["-indenter_rigid_rotation", "abc"], ["-indenter_rigid_rotation", "a number"]),
    (SCENE, ["-indenter_rigid_centre", "1"], ["-indenter_rigid_centre", "two numbers"]),
    (SCENE, ["-indenter_E", "1000"], ["-indenter_E", "rigid", "no elastic constants"]),
    (SCENE, ["-accuracy", "0.05"], ["-accuracy", "rigid", "not supported"]),
    (SPHERE, ["-ball_rigid_rotation", "free"], ["-ball_rigid_rotation", "r-z", "along the axis"]),
    (SPHERE, ["-ball_bc_equator_components", "x,y", "-ball_bc_equator_control", "force,displacement",
              "-ball_bc_equator_values", "1,-0.01"], ["-ball_bc_equator_control", "r-z", "radial force control"]),
])
def test_refused(scene, args, words, tmp_path):
    """What a rigid body cannot do yet, or a bad value: one line naming it,
    status 1, no output."""
    r = run_contact(scene + args, tmp_path, check=False)
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    assert r.returncode == 1 and len(lines) == 1, r.stderr[-2000:]
    for w in words:
        assert w in lines[0], lines[0]
    assert not r.summary_path.exists() and not r.output_path.exists()


def test_no_curves(tmp_path):
    """A rigid body's mesh without line elements: one line naming the file."""
    geo = Path(tmp_path) / "dot.geo"
    geo.write_text("Point(1) = {xc + R + 0 * yc * xcontact * hc, 0, 0, h};\nPhysical Point(\"back\") = {1};\nMesh.ElementOrder = 2;\n")
    r = run_contact(SCENE + ["-indenter_geo", geo], tmp_path, check=False)
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    assert r.returncode == 1 and len(lines) == 1, r.stderr[-2000:]
    assert "line" in lines[0] and ".msh" in lines[0], lines[0]



@pytest.mark.parametrize("slave", ["auto", "second"])
def test_punch_sadowsky(slave, tmp_path):
    """A rigid flat punch (its four sides alone, square corners) pressed into
    a soft block: the slave's pressure within 3 % of Sadowsky's over
    |x| < 0.6 b, either slave (auto: the punch, whose face ends on the
    block, measured 0.85 %; the block, 0.39 %), and the two P within 0.5 %
    of each other (measured 0.15 %). The elastic punch at E = 1e5 to 1e7
    solved to gttol 1e-14 tends to the rigid P (0.150262, 0.150320,
    0.150326 against 0.150331); at the default stop the E = 1e7 punch ends
    at 0.151127, its gradient dominated by the stiff punch's residual."""
    r = run_contact(PUNCH + ["-contact_mortar_slave", slave], tmp_path)
    P = r.summary["contact"]["tool"]["P"]
    with r.h5() as h5:
        name, err = sadowsky_l2(h5, P)
    print(f"slave {slave} ({name}): P = {P:.6f}, {100 * err:.2f} % from Sadowsky")
    assert name == ("punch_contact" if slave == "auto" else "block_contact")
    assert err <= 0.03
    assert P == pytest.approx(0.150331, rel=5e-3)


def test_sphere_rz(tmp_path):
    """A rigid ball (its meridian's curves) on an elastic flat in r-z: Hertz's
    point contact with E* = E / (1 - nu^2), p_max and the second-moment a
    within 1 % (measured +0.44 % and -0.09 %); the ball moves along the axis
    alone, and its force is the contact's, along the axis (pressing it up)."""
    s = run_contact(SPHERE + ["-output", "none"], tmp_path).summary
    dp, da = hertz_errors(s)
    ball = s["bodies"]["ball"]
    print(f"sphere: p_max {dp:+.2%}, a {da:+.2%}; ball {ball}")
    assert abs(dp) <= 0.01 and abs(da) <= 0.01
    assert ball["translation"] == [0, -0.01]
    assert ball["force"][0] == 0 and ball["moment"] == 0
    assert -ball["force"][1] == pytest.approx(s["contact_force"], rel=1e-12)


def test_ssnv104_rigid_plane(tmp_path):
    """SSNV104 with its plane of symmetry rigid (the line y = 0 alone) gives
    the stiff flat's figures with half the dofs (9,044 against 18,228): P
    8.7e-5 above it (the flat, 10^4 times stiffer than the sphere, gives way
    by about 1e-4 of the approach; bound 2e-4), p_max and the second-moment
    a within 3e-4 of it (measured 1.0e-4 and -5e-6)."""
    r = run_contact(["-options_file", "meshes/ssnv104-rigid/ssnv104-rigid.opts", "-output", "none"], tmp_path, name="rigid").summary
    e = run_contact(["-options_file", "meshes/ssnv104/ssnv104.opts", "-output", "none"], tmp_path, name="stiff").summary
    dP = r["contact_force"] / e["contact_force"] - 1
    dp, da = r["fem_pmax"] / e["fem_pmax"] - 1, r["fem_a_moment"] / e["fem_a_moment"] - 1
    print(f"P {dP:.2e}, p_max {dp:.2e}, a {da:.2e}; dofs {r['dofs']} against {e['dofs']}")
    assert 0 < dP <= 2e-4
    assert abs(dp) <= 3e-4 and abs(da) <= 3e-4
    assert r["dofs"] < 0.6 * e["dofs"]


def test_output(rigid_run, tmp_path):
    """The HDF5 holds the rigid body's motion, force and outline (its 204
    nodes at their current positions, its lines), no fields; the report
    prints its line; the plots draw it by its outline."""
    with rigid_run.h5() as h5:
        g = h5["bodies/indenter"]
        assert g.attrs["rigid"] == 1 and "displacement" not in g
        assert g.attrs["force_x"] == pytest.approx(rigid_run.summary["bodies"]["indenter"]["force"][0], rel=1e-15)
        x, lines = g["line_x"][()].reshape(-1, 2), g["lines"][()].reshape(-1, 3)
        assert len(x) == rigid_run.summary["bodies"]["indenter"]["nodes"] == 204
        r = ((x[:, 0] + 1) ** 2 + x[:, 1] ** 2) ** 0.5   # the circle, held: radius 1 about (-1, 0)
        assert abs(r - 1).max() <= 1e-12 and lines.max() < len(x)
    assert "rigid body indenter: moved (0., 0.)" in rigid_run.stdout
    for extra in ([], ["--field"]):
        p = subprocess.run([sys.executable, "scripts/plot_hertz.py", str(rigid_run.output_path), *extra, "-o",
                            str(tmp_path / f"p{len(extra)}.png")], cwd=ROOT, capture_output=True, text=True, timeout=120)
        assert p.returncode == 0, p.stderr


# The rigid body's unknowns: its translation where a condition force-controls
# it or none holds it, its rotation where -<body>_rigid_rotation free.

def test_force_controlled(rigid, tmp_path):
    """The disc force-controlled in x by the force the displaced block gave
    it (the fixture's P), the block held: the disc moves by the block's
    0.0095 to 1e-7 (measured 1.7e-10), the profile's p_max is the
    fixture's to 1e-7 (measured 3.6e-9), and 2 ranks find the same motion to 1e-9 (the two
    solves' stops)."""
    F = rigid["bodies"]["indenter"]["force"][0]
    args = SCENE + ["-block_bc_push_values", "0,0", "-indenter_bc_back_control", "force,displacement",
                    "-indenter_bc_back_values", f"{F!r},0", "-output", "none"]
    s = run_contact(args, tmp_path).summary
    t = s["bodies"]["indenter"]["translation"]
    print(f"t = {t}, {t[0] / 0.0095 - 1:.2e}; p_max {s['fem_pmax'] / rigid['fem_pmax'] - 1:.2e}")
    assert t[0] == pytest.approx(0.0095, rel=1e-7) and t[1] == 0
    assert s["fem_pmax"] == pytest.approx(rigid["fem_pmax"], rel=1e-7)
    c = s["force_control"][0]
    assert c["rigid"] and c["component"] == "x" and c["reaction"] == pytest.approx(F, rel=1e-8)
    s2 = run_contact(args, tmp_path, ranks=2, name="two").summary
    assert s2["bodies"]["indenter"]["translation"][0] == pytest.approx(t[0], rel=1e-9)


def test_force_controlled_rz(tmp_path):
    """In r-z: the ball force-controlled along the axis by the force the
    displacement run (ball moved by -0.01) gave it, the flat's base moved
    up by 0.01 instead: the ball stays where it is, to 1e-9 of 0.01
    (measured 6.5e-13, both solved to a gradient of 1e-11), and p_max is
    the displacement run's to 1e-9 (5.3e-13)."""
    tight = ["-tao_gatol", "1e-11", "-tao_grtol", "0", "-tao_gttol", "0", "-output", "none"]
    d = run_contact(SPHERE + tight, tmp_path, name="disp").summary
    F = d["bodies"]["ball"]["force"][1]
    s = run_contact(SPHERE + tight + ["-ball_bc_equator_control", "force", "-ball_bc_equator_values", repr(F),
                                      "-flat_bc_bottom_values", "0.01"], tmp_path, name="force").summary
    t = s["bodies"]["ball"]["translation"]
    print(f"t = {t}; p_max {s['fem_pmax'] / d['fem_pmax'] - 1:.2e}")
    assert t[0] == 0 and abs(t[1]) <= 1e-9 * 0.01
    assert s["fem_pmax"] == pytest.approx(d["fem_pmax"], rel=1e-9)


@pytest.fixture(scope="module")
def roller(tmp_path_factory):
    return run_contact(ROLLER + ["-output", "none"], tmp_path_factory.mktemp("roller")).summary


def test_roller_held_by_contact(roller):
    """meshes/rigid-roller: a rigid roller between two races, held by its two
    contacts alone (no condition: its x and y are unknowns of force zero),
    the upper race pushed by 1000. By symmetry the roller moves by half
    the upper race's displacement (to 1e-9; measured 2.3e-14); each
    contact carries the 1000 (to 1e-8) and matches Hertz's rigid cylinder
    on a flat with E* = E / (1 - nu^2): p_max and the second-moment a
    within 1 % (measured -0.26 % and +0.31 %); the force left on the
    roller is within the allowance of a motion the contacts do not hold
    (x, along the flat races: 1e-3 of the load; measured 7.9e-7)."""
    t = roller["bodies"]["roller"]["translation"]
    U = roller["force_control"][0]["displacement"]
    print(f"roller t = {t}, upper race U = {U}: {t[1] / (U / 2) - 1:.1e}")
    assert t[1] == pytest.approx(U / 2, rel=1e-9)
    for name, c in roller["contact"].items():
        dp, da = c["fem_pmax"] / c["hertz_pmax"] - 1, c["fem_a_moment"] / c["hertz_a"] - 1
        print(f"{name}: P {c['P']:.9f}, p_max {dp:+.2%}, a {da:+.2%}")
        assert c["P"] == pytest.approx(1000, rel=1e-8)
        assert abs(dp) <= 0.01 and abs(da) <= 0.01
    f = roller["bodies"]["roller"]["force"]
    assert abs(f[0]) <= 1e-3 * 1000 and abs(f[1]) <= 1e-8 * 1000


def test_roller_ranks_and_gpts(roller, tmp_path):
    """The rigid roller on 2 ranks: the same motion in y to 1e-9 (the
    solves' stops; x, which the contacts do not hold, is not compared);
    with gpts the symmetry holds (1e-9) and Hertz within 1.5 % (measured
    p_max +1.07 %, a -0.09 %)."""
    s = run_contact(ROLLER + ["-output", "none"], tmp_path, ranks=2, name="two").summary
    assert s["bodies"]["roller"]["translation"][1] == pytest.approx(roller["bodies"]["roller"]["translation"][1], rel=1e-9)
    g = run_contact(ROLLER + ["-output", "none", "-contact_formulation", "gpts"], tmp_path, name="gpts").summary
    assert g["bodies"]["roller"]["translation"][1] == pytest.approx(g["force_control"][0]["displacement"] / 2, rel=1e-9)
    for c in g["contact"].values():
        assert abs(c["fem_pmax"] / c["hertz_pmax"] - 1) <= 0.015 and abs(c["fem_a_moment"] / c["hertz_a"] - 1) <= 0.015


TILT = ["-options_file", "meshes/rigid-punch/rigid-punch.opts", "-output", "none", "-punch_rigid_rotation", "free",
        "-punch_rigid_centre", "0.1,0.125", "-punch_bc_push_control", "displacement,force", "-punch_bc_push_values", "0,-0.15"]


@pytest.mark.parametrize("formulation", ["mortar", "gpts"])
def test_free_rotation_tilt(formulation, tmp_path):
    """The rigid flat punch (half-width b = 0.25) pushed by a force
    P = 0.15 through the point 0.1 right of its axis, free to turn about
    it: the punch tilts until the contact's moment about that point is zero
    (to 1e-6 of P e; measured 2e-8 and 4e-8), by Johnson's tilted punch on a
    half-space (Contact Mechanics, 2.8) alpha = 4 P e / (pi E* b^2) =
    2.781e-3 with E* = E / (1 - nu^2), within 3 % (the block is finite;
    measured -0.80 % mortar, -1.34 % gpts; e < b / 2, so the whole face
    stays in contact). The Taylor test at the answer, the rigid body's
    unknowns included: the gradient's remainder second order, and the
    Hessian's (the rotation's second derivative and the contact's coupling
    through J) second order (measured 2.01 and 2.39). With the block as
    mortar's slave the Hessian's order is 1.0 as with an elastic punch:
    the master's corners, not the rigid body."""
    args = TILT + ["-contact_formulation", formulation, "-taylor_test"]
    r = run_contact(args, tmp_path)
    s = r.summary
    punch = s["bodies"]["punch"]
    P, e, b, Es = 0.15, 0.1, 0.25, 100 / (1 - 0.3 ** 2)
    alpha = 4 * P * e / (math.pi * Es * b ** 2)
    print(f"{formulation}: rotation {punch['rotation']:.6e} against -{alpha:.6e} ({-punch['rotation'] / alpha - 1:+.2%}), moment {punch['moment']:.2e}")
    assert abs(-punch["rotation"] / alpha - 1) <= 0.03
    assert abs(punch["moment"]) <= 1e-6 * P * e
    assert punch["force"][1] == pytest.approx(-P, rel=1e-7)
    orders = s["taylor"]["gradient_order"], s["taylor"]["hessian_order"]
    print("Taylor orders", orders)
    assert orders[0] >= 1.9 and orders[1] >= 1.9


def test_border_from_the_surfaces(tmp_path):
    """A rigid body's unknowns border the Hessian with columns that change at
    each Hessian and live on the contact surfaces alone: the substructuring
    condenses them anew with no interior solve (one solve of the bodies'
    Hessian a step), where -force_control_border_solves makes m + 1 solves.
    The disc force-controlled in x, free to turn: the two give the same
    motion to 1e-10 (measured 5e-14)."""
    args = SCENE + ["-block_bc_push_values", "0,0", "-indenter_bc_back_control", "force,displacement",
                    "-indenter_bc_back_values", "5.0234614148,0", "-indenter_rigid_rotation", "free", "-output", "none"]
    fast = run_contact(args + ["-info", ":sys"], tmp_path, name="fast")
    assert "eliminated by the PC of the bodies' step from the surfaces" in fast.stdout + fast.stderr
    slow = run_contact(args + ["-force_control_border_solves"], tmp_path, name="slow").summary
    a, b = fast.summary["bodies"]["indenter"]["translation"][0], slow["bodies"]["indenter"]["translation"][0]
    print(f"fast {a!r}, solves {b!r}: {a / b - 1:.1e}")
    assert a == pytest.approx(b, rel=1e-10)


def test_unknown_without_contact(tmp_path):
    """A rigid body in no contact pair whose translation in y no condition
    holds: nothing would hold it, so one line names the body and the
    component, status 1, nothing written."""
    src = ROOT / "meshes" / "rigid-hertz" / "rigid-hertz.opts"
    lines = [l for l in src.read_text().splitlines() if not l.startswith("-contact_")]
    lines = [l.replace("indenter.geo", str(src.parent / "indenter.geo")).replace("../hertz/block.geo", str(ROOT / "meshes" / "hertz" / "block.geo"))
             for l in lines]
    opts = Path(tmp_path) / "nocontact.opts"
    opts.write_text("\n".join(lines) + "\n")
    r = run_contact(["-options_file", opts, "-indenter_bc_back_components", "x", "-indenter_bc_back_values", "0"], tmp_path, check=False)
    err = [l for l in r.stderr.splitlines() if l.strip()]
    assert r.returncode == 1 and len(err) == 1, r.stderr[-2000:]
    assert "body indenter is rigid and in no contact pair" in err[0] and "translation in y" in err[0]
    assert not r.summary_path.exists() and not r.output_path.exists()


@pytest.mark.parametrize("scene", ["rigid-hertz", "rigid-roller", "rigid-sphere"])
def test_help(scene, tmp_path):
    """-help on a scene with a rigid body lists its options with their
    defaults and exits 0, writing nothing."""
    r = run_contact(["-options_file", f"meshes/{scene}/{scene}.opts", "-help"], tmp_path, check=False)
    assert r.returncode == 0, r.stderr[-2000:]
    assert "_rigid_rotation <now 0" in r.stdout and "_rigid_centre" in r.stdout
    assert not r.summary_path.exists() and not r.output_path.exists()


def test_force_controlled_plate_on_rubber(tmp_path):
    """meshes/rubber-squeeze (h = 0.1) with its rigid plate pushed by the
    force the displaced plate (0.3) gave it, in place of the displacement:
    the plate moves by that 0.3 to 1e-9 (measured 5e-14, both solved to a
    gradient of 1e-12) and p_max is the displaced run's to 1e-9 (2e-12): a
    rigid body's force control on a neo-Hookean partner, whose contact
    Hessian the border carries at every step."""
    scene = ["-options_file", "meshes/rubber-squeeze/rubber-squeeze.opts", "-output", "none", "-mesh_size", "0.1",
             "-tao_gatol", "1e-12", "-tao_grtol", "0", "-tao_gttol", "0"]
    d = run_contact(scene, tmp_path, name="disp").summary
    F = d["bodies"]["plate"]["force"][1]
    s = run_contact(scene + ["-plate_bc_contact_control", "displacement,force", "-plate_bc_contact_values", f"0,{F!r}"],
                    tmp_path, name="force").summary
    t = s["bodies"]["plate"]["translation"]
    print(f"plate {t}, {t[1] / -0.3 - 1:.1e}; p_max {s['fem_pmax'] / d['fem_pmax'] - 1:.1e}")
    assert t[1] == pytest.approx(-0.3, rel=1e-9)
    assert s["fem_pmax"] == pytest.approx(d["fem_pmax"], rel=1e-9)
