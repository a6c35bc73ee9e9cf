"""The final stop against the forces the contacts carry (-stop_force_rtol,
src/solver/forcestop.c). TAO's test alone is relative to the gradient at
rest, which a stiff displaced body inflates: a punch of E = 1e7 pushed into
a layer of E = 1 (tests/meshes/stiff-punch, the tests' own scene) has a
gradient at rest about 1e8 times its contact's nodal forces, and that stop
met Newton after two iterations with the force 9 % off (19 % with the layer
at h = 0.0125), reported converged.
The stop now also asks ||g|| <= 1e-6 ||f_c||; the force read off the
solution is then within about that of the converged one."""
import pytest

from conftest import ROOT, figure, run_contact

SCENE = ["-options_file", str(ROOT / "tests" / "meshes" / "stiff-punch" / "stiff-punch.opts")]


def punch_force(r):
    """P, the contact's force on the punch pushing it up (JSON contact_force is the slave's)."""
    return abs(r.summary["reactions"]["punch:push"][1])


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The same scene solved far past the default stop (||g|| <= 1e-7 ||f_c||):
    the minimiser the default stops must approach."""
    tmp = tmp_path_factory.mktemp("ref")
    r = run_contact(SCENE + ["-stop_force_rtol", "1e-7"], tmp)
    assert r.summary["force_residual"] <= 1e-7
    return r


@pytest.mark.parametrize("solver", ["nls", "lmvm"])
def test_force_within_the_stop(solver, reference, tmp_path):
    """At the default stop the gradient is at most 1e-6 of the contacts' nodal
    forces (the JSON's force_residual: `residual` = 3.4e-8 to 7.6e-7), and
    the punch's force is within 1e-5 of the reference's, relative
    (`dP` = 0 to 8e-9, Newton and L-BFGS); the layer's base reacts it to
    the same (`balance` = 2.7e-10 to 4e-9)."""
    r = run_contact(SCENE + ["-tao_type", solver], tmp_path)
    assert r.summary["converged"]
    res = figure("residual", r.summary["force_residual"])
    assert res <= 1e-6
    p, pref = punch_force(r), punch_force(reference)
    dp = figure("dP", abs(p - pref) / pref)
    assert dp <= 1e-5
    base = abs(r.summary["reactions"]["layer:base"][1])
    bal = figure("balance", abs(base - p) / p)
    assert bal <= 1e-5


def test_gradient_at_rest_alone_was_off(reference, tmp_path):
    """The stop of TAO's test alone (-stop_force_rtol 0) ends Newton with the
    force far off (`dP` = 0.09), and the JSON's force_residual says so
    (`residual` = 0.45): the figure a user can read the stop's accuracy from."""
    r = run_contact(SCENE + ["-stop_force_rtol", "0"], tmp_path)
    p, pref = punch_force(r), punch_force(reference)
    dp = figure("dP", abs(p - pref) / pref)
    res = figure("residual", r.summary["force_residual"])
    assert dp > 0.05 and res > 0.05
    assert r.summary["force_stop"]["continued"] == 0


@pytest.mark.roundoff
@pytest.mark.kernels
def test_two_ranks(reference, tmp_path):
    """2 ranks stop by the same test: the force within 1e-5 of the reference
    (`dP` = 3.5e-10 to 7.1e-9 over the five kernels)."""
    r = run_contact(SCENE, tmp_path, ranks=2)
    assert r.summary["force_residual"] <= 1e-6
    dp = figure("dP", abs(punch_force(r) - punch_force(reference)) / punch_force(reference))
    assert dp <= 1e-5


@pytest.mark.parametrize("value", ["-1", "1", "abc"])
def test_bad_value(value, tmp_path):
    """A value outside [0, 1) is one line naming the option, status 1, nothing written."""
    r = run_contact(SCENE + ["-stop_force_rtol", value], tmp_path, check=False)
    lines = [l for l in r.stderr.splitlines() if l.strip() and "warning" not in l]
    assert r.returncode == 1 and len(lines) == 1 and "-stop_force_rtol" in lines[0], r.stderr
    assert not r.summary_path.exists() and not r.output_path.exists()


def test_listed_in_help(tmp_path):
    """-help lists the option with its default."""
    r = run_contact(SCENE + ["-help"], tmp_path, check=False)
    line = [l for l in r.stdout.splitlines() if "-stop_force_rtol" in l]
    assert line and "1e-06" in line[0], r.stdout[-2000:]
