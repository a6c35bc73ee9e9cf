"""Bodies held by contact alone (src/body/anchors.c, src/solver/unheld.c).

The roller scene (meshes/roller): a roller (R = 5, E = 2e5, nu = 0.3) with
no condition of its own between two races of the same material, the lower
clamped at its back, the upper loaded by a force of 1000 (the scene's
default), a displacement or a pressure of 100 over its width 10. The
roller's anchors must end with no force the contact can take (its squeeze),
so both contacts carry the load. The references are independent of the
program: the load itself (each contact carries it: the roller and the upper
race are free along y), Hertz's cylinder on a flat (plane strain, P per unit
thickness: E* = E / (2 (1 - nu^2)), a = sqrt(4 P R / (pi E*)), p_max =
2 P / (pi a); a/R = 0.048 here, where the circular profile's departure from
Hertz's parabola is below 0.1 %), and the displacement-driven run at the
displacement the force-driven one found.

The ball (meshes/sphere's geometry, r-z): the hemisphere without its
pushed equator, a pressure on that face instead, resting on the flat: held
by the contact alone along the axis; Hertz for a sphere on a flat, a =
(3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2).

Before anchors were coupled controls, the roller was refused ("3 rigid
motions free"); given a zero traction so that its anchors engaged, force
control's Broyden iteration stopped with DIVERGED_MAXITS after 40 solves and
700 Newton iterations (the anchors' tolerance was 1e-9 absolute: the
roller's own load is zero); an outer iteration on the anchors then took 20
solves and 116 Newton iterations by the force, 57 by a displacement."""
import math
import re

import numpy as np
import pytest

from conftest import ROOT, run_contact

ROLLER = ["-options_file", "meshes/roller/roller.opts", "-output", "none"]
PRESSURE = ["-upper_bc_back_components", "x", "-upper_bc_back_values", "0", "-upper_bc_back_control", "displacement",
            "-upper_load", "back", "-upper_load_back_pressure", "100"]
LOAD = 1000.0
E, NU, R = 2e5, 0.3, 5.0


def hertz_cylinder(P, E=E, nu=NU, R=R):
    """Hertz's a and p_max for a cylinder of radius R on a flat of the same material."""
    Es = E / (2 * (1 - nu ** 2))
    a = math.sqrt(4 * P * R / (math.pi * Es))
    return a, 2 * P / (math.pi * a)


def contacts(s):
    return {name: c for name, c in s["contact"].items()}


def check_hertz(s, bound):
    """Each pair's p_max and second-moment half-width against Hertz for its own P."""
    for name, c in contacts(s).items():
        a, pmax = hertz_cylinder(c["P"])
        ea, ep = c["fem_a_moment"] / a - 1, c["fem_pmax"] / pmax - 1
        print(f"{name}: P {c['P']!r}, p_max {c['fem_pmax']:.6g} ({100 * ep:+.3f} %), a {c['fem_a_moment']:.6g} ({100 * ea:+.3f} %)")
        assert abs(ep) <= bound and abs(ea) <= bound


@pytest.fixture(scope="module")
def by_force(tmp_path_factory):
    return run_contact(ROLLER, tmp_path_factory.mktemp("roller-force")).summary


def test_force_both_contacts_carry_it(by_force):
    """Pushed by a force of 1000 from rest: each contact carries it to 1e-8
    (measured 1.2e-10 and 6.9e-10 on 1 rank, in one solve of 26 Newton
    iterations), and each matches Hertz within 0.2 % (measured p_max
    +0.066 %, second-moment a -0.053 %; the issue asks 1 %). The roller's
    anchors end with a y reaction of 2.9e-8 (bound 1e-5: the contact holds
    the squeeze, so the solve converges it) and x reactions of 1.2e-4
    (1.2e-7 of the load: the roller's sliding, which the flat races cannot
    hold, frozen within the 1e-3 of the load unheld.c allows there; bound
    1e-5 of it)."""
    s = by_force
    print({n: repr(c["P"]) for n, c in contacts(s).items()}, s["force_control_solves"], s["iterations"])
    for c in contacts(s).values():
        assert abs(c["P"] - LOAD) <= 1e-8 * LOAD
    check_hertz(s, 2e-3)
    anchors = {(a["group"], a["component"]): a for a in s["force_control"] if a["anchor"]}
    assert set(anchors) == {("anchor_a", "x"), ("anchor_a", "y"), ("anchor_b", "x")}
    assert abs(anchors["anchor_a", "y"]["reaction"]) <= 1e-8 * LOAD
    assert all(abs(a["reaction"]) <= 1e-5 * LOAD for a in anchors.values())


def test_displacement_is_the_force_runs_reference(by_force, tmp_path):
    """Pushed by the displacement the force-driven run found (U = -0.0443925),
    the race's reaction is the force, 1000, and each contact carries it, to
    1e-5 (measured 3.0e-6): the two runs differ where the roller sits, which
    nothing holds along the races (the force-driven run's first steps, before
    any contact, moved it 0.023 to the side; the displacement-driven one
    stays at 0.0002), and the contacts then meet other elements (p_max
    +0.060 % against +0.066 %: measured 5.7e-5 apart, bound 1e-3). Within
    the displacement run, the contacts balance to 1e-8 (measured 7.1e-10,
    one solve of 28 Newton iterations). The force run costs at most 1.5
    times the displacement run's Newton iterations plus 2 (issue 33; 26
    against 28)."""
    (U,) = [c["displacement"] for c in by_force["force_control"] if not c["anchor"]]
    d = run_contact(ROLLER + ["-upper_bc_back_control", "displacement,displacement", "-upper_bc_back_values", f"0,{U!r}"],
                    tmp_path).summary
    react = d["reactions"]["upper:back"][1]
    print(f"U {U!r}: reaction {react!r}, contacts {[repr(c['P']) for c in contacts(d).values()]}, "
          f"{d['force_control_solves']} solves, {d['iterations']} iterations")
    assert abs(-react - LOAD) <= 1e-5 * LOAD
    for name, c in contacts(d).items():
        assert abs(c["P"] - contacts(by_force)[name]["P"]) <= 1e-5 * LOAD
        assert abs(c["fem_pmax"] / contacts(by_force)[name]["fem_pmax"] - 1) <= 1e-3
    a, b = [c["P"] for c in contacts(d).values()]
    assert abs(a - b) <= 1e-8 * LOAD
    check_hertz(d, 2e-3)
    assert by_force["iterations"] <= 1.5 * d["iterations"] + 2, (by_force["iterations"], d["iterations"])


def test_pressure_both_contacts_carry_it(tmp_path):
    """A pressure of 100 on the upper race's back (held there in x only, so
    that it is held by contact along y as the roller is): both contacts 1000
    to 1e-8 (measured 3.1e-9 and 3.6e-10, one solve of 29 Newton
    iterations), Hertz within 0.2 % (measured p_max +0.066 % and +0.041 %, a
    -0.053 % and -0.028 %)."""
    s = run_contact(ROLLER + PRESSURE, tmp_path).summary
    print({n: repr(c["P"]) for n, c in contacts(s).items()}, s["force_control_solves"], s["iterations"])
    assert abs(s["loads"]["upper:back"][1] + LOAD) <= 1e-12 * LOAD
    for c in contacts(s).values():
        assert abs(c["P"] - LOAD) <= 1e-8 * LOAD
    check_hertz(s, 2e-3)


def test_roller_ranks(by_force, tmp_path):
    """2 ranks against 1: the contact forces to 3e-9 of the load (measured
    up to 5.3e-10, each run balancing to its solve's stop: 1.2e-10 and
    6.9e-10 of the load on 1 rank), the race's displacement to 1e-12
    and the Hertz figures to 1e-6 (measured p_max 3.1e-9 and 4.3e-9)."""
    two = run_contact(ROLLER, tmp_path, ranks=2).summary
    for name, c in contacts(two).items():
        c1 = contacts(by_force)[name]
        print(name, repr(c["P"]), repr(c1["P"]), c["fem_pmax"] / c1["fem_pmax"] - 1)
        assert abs(c["P"] - c1["P"]) <= 3e-9 * LOAD
        assert abs(c["fem_pmax"] / c1["fem_pmax"] - 1) <= 1e-6
        assert abs(c["fem_a_moment"] / c1["fem_a_moment"] - 1) <= 1e-6
    (u1,) = [c["displacement"] for c in by_force["force_control"] if not c["anchor"]]
    (u2,) = [c["displacement"] for c in two["force_control"] if not c["anchor"]]
    assert abs(u1 - u2) <= 1e-12 * abs(u1)


def test_neighbour_mesh(tmp_path):
    """The neighbouring mesh size h = 0.03 (a/h = 8; the scene's is 0.02),
    pushed by a pressure: one solve of 51 Newton iterations, both contacts
    1000 to 1e-7 (measured 6.2e-8 and 1.2e-9: the frozen motion of the race
    rocking on the sliding roller carries a little of the roller's y anchor,
    6e-5) and Hertz within 0.5 % (measured p_max +0.076 % and +0.052 %, a
    -0.044 % and -0.020 %)."""
    s = run_contact(ROLLER + PRESSURE + ["-mesh_size", "0.03"], tmp_path).summary
    print({n: repr(c["P"]) for n, c in contacts(s).items()}, s["force_control_solves"], s["iterations"], s["dofs"])
    for c in contacts(s).values():
        assert abs(c["P"] - LOAD) <= 1e-7 * LOAD
    check_hertz(s, 5e-3)


def ball_options(tmp_path, pressure):
    """meshes/sphere/sphere.opts without the ball's Dirichlet condition, a
    pressure on its equator face instead."""
    lines = (ROOT / "meshes/sphere/sphere.opts").read_text().splitlines()
    lines = [re.sub(r"^(-\w+_geo) (\S+)", lambda m: f"{m[1]} {ROOT / 'meshes/sphere' / m[2]}", l) for l in lines]
    lines = [l for l in lines if not l.startswith("-ball_bc")]
    lines += ["-ball_load equator", f"-ball_load_equator_pressure {pressure!r}"]
    p = tmp_path / "ball.opts"
    p.write_text("\n".join(lines) + "\n")
    return p


@pytest.mark.parametrize("P", [0.7, 0.7e-3])
def test_ball_on_a_plate(P, tmp_path):
    """A ball (R = 1) resting on a plate in r-z, pressed by a pressure on its
    equator face (P = p pi R^2 over the whole circle), held along the axis
    by the contact alone: the contact carries P to 1e-8 (measured 1.3e-9 at
    P = 0.7) and matches Hertz for a sphere on a flat within 1 % (h = 0.01,
    a/h = 10 at P = 0.7: p_max -0.37 %, second-moment a +0.011 %) and 3 % at
    P = 7e-4 (a/h = 1: only the force is checked there to 1e-8). The
    anchor's tolerance scales with the force: the same test at a load 1000
    times smaller converges as well."""
    s = run_contact(["-options_file", ball_options(tmp_path, P / math.pi), "-mesh_size", "0.01", "-output", "none"],
                    tmp_path).summary
    c = s["contact"]["interface"]
    Es = 1000 / (2 * (1 - 0.3 ** 2))
    a = (3 * c["P"] * 1.0 / (4 * Es)) ** (1 / 3)
    p0 = 3 * c["P"] / (2 * math.pi * a * a)
    print(f"P {c['P']!r} for {P}: a {c['fem_a_moment']:.6g} ({100 * (c['fem_a_moment'] / a - 1):+.3f} %), "
          f"p_max {c['fem_pmax']:.6g} ({100 * (c['fem_pmax'] / p0 - 1):+.3f} %), {s['force_control_solves']} solves, "
          f"{s['iterations']} iterations")
    assert abs(c["P"] - P) <= 1e-8 * P
    if P > 0.1:
        assert abs(c["fem_pmax"] / p0 - 1) <= 1e-2 and abs(c["fem_a_moment"] / a - 1) <= 1e-2
