"""3D force control from a point contact: tests/test_view3d.py's half ball
(R = 1, E = 1000, nu = 0.3 on a like half block, h = 0.04, the plane y = 0
on rollers and declared) pressed at its top by a force P = 0.35 (the half
model's; force control, -ball_bc_top_control displacement,force, x held)
from rest in one stage. At rest it touches the block at a point: no normal
stiffness, so the Newton step in the controlled displacement is held only
by its cap; in 3D that cap is also the contact's reach along it, the depth
of the two surfaces (src/solver/forcereach.c: the ball's cap is 0.05 deep,
against 0.3 of the body's size, 0.6, which carried the cap through the
block: DIVERGED_LS_FAILURE at the first step before)."""
import numpy as np
import pytest

from conftest import figure, run_contact
from hertz import sphere
from test_view3d import MU, scene_args

P = 0.35            # the half model's force (whole ball 0.7: a/R about 0.1)
FORCE_RTOL = 1e-6   # -stop_force_rtol's default: the stop's gradient against the contacts' nodal forces
ES = 1 / (2 * (1 - 0.3**2) / 1000.0)


def pressed(friction=False, top=("force", -P)):
    """The half ball pressed from rest in one stage: its top's z by a force
    (top = ("force", -P)) or a displacement (("displacement", U)), x held
    at 0; frictionless unless friction."""
    a = [str(x) for x in scene_args()]
    a[a.index("-ball_bc_top_values") + 1] = f"0,{top[1]!r}"
    i = a.index("-load_stages")
    a = a[:i] + a[i + 2:]
    if not friction:
        i = a.index("-contact_c_friction")
        a = a[:i] + a[i + 2:]
        i = a.index("-contact_friction_lag_rtol")
        a = a[:i] + a[i + 2:]
    if top[0] == "force":
        a += ["-ball_bc_top_control", "displacement,force"]
    return a + ["-output", "none"]


def hertz(Pw):
    """Hertz's a and p0 under the whole ball's force Pw (R* = 1, the block flat)."""
    return sphere(Pw, ES)


def force_run(tmp_path, name, friction=False, ranks=1):
    s = run_contact(pressed(friction), tmp_path, name=name, ranks=ranks, timeout=1200).summary
    (fc,) = s["force_control"]
    return s, fc


@pytest.fixture(scope="module")
def frictionless(tmp_path_factory):
    return force_run(tmp_path_factory.mktemp("forceball3d"), "force")


def test_pressed_by_force_from_rest(frictionless):
    """It converges; the control's reaction balances P to `dR` = 5.3e-14
    (bound: 3 times the stop, -stop_force_rtol against the contact's
    force), the contact's z force to `dF` = 9.5e-10 to 4.3e-9 (where the
    solve stops), the top's z control
    (named z) moves U = `U` = -0.00878 (bounds -0.02 to -0.005: Hertz's
    approach a^2/R is 0.0097); against Hertz under the whole force 2P, a
    from the second moment `a_error` = +0.011 and p_max `pmax_error` =
    -0.017 (a/h about 2.5: bounds 0.05 and 0.06, the coarse mesh's)."""
    s, fc = frictionless
    c = s["contact"]["c"]
    F = np.array(c["surfaces"][0]["force"])
    assert s["converged"] and fc["component"] == "z" and fc["force"] == -P
    bound = 3 * FORCE_RTOL * np.linalg.norm(F) / P
    assert figure("dR", abs(fc["reaction"] - fc["force"]) / P) <= bound
    assert figure("dF", abs(F[2] - P) / P) <= bound
    assert -0.02 < figure("U", fc["displacement"]) < -0.005
    a, p0 = hertz(2 * P)
    assert c["P"] == pytest.approx(2 * P, rel=3 * bound)
    assert abs(figure("a_error", c["fem_a_moment"] / a - 1)) <= 0.05
    assert abs(figure("pmax_error", c["fem_pmax"] / p0 - 1)) <= 0.06


def test_same_as_displacement_run(frictionless, tmp_path):
    """The same scene pressed by the displacement the force run found: the
    same answer to what the stops allow. Its force differs from P by
    `dP_disp` = 5.5e-11 (bound 10 times the force stop: the two solves
    stop each within it), a by `da_disp` = 6.7e-9 and p_max by `dp_disp` =
    5.4e-10 (bounds 1e-5, 10 times the stop: each a sum of nodal pressures
    within it)."""
    s, fc = frictionless
    d = run_contact(pressed(top=("displacement", fc["displacement"])), tmp_path, name="disp", timeout=1200).summary
    c, cd = s["contact"]["c"], d["contact"]["c"]
    Fd = np.array(cd["surfaces"][0]["force"])
    assert d["converged"]
    assert figure("dP_disp", abs(Fd[2] - P) / P) <= 10 * FORCE_RTOL * np.linalg.norm(Fd) / P
    assert figure("da_disp", abs(cd["fem_a_moment"] / c["fem_a_moment"] - 1)) <= 1e-5
    assert figure("dp_disp", abs(cd["fem_pmax"] / c["fem_pmax"] - 1)) <= 1e-5


def test_pressed_by_force_with_friction(tmp_path):
    """With friction (mu = 0.3, elastically similar bodies: no slip drives
    it, Q = 0): it converges, P balanced to `dF_friction` = 8.6e-9 (bound:
    3 times the stop), a within `a_error_friction` = +0.011 of Hertz's
    (bound 0.05), the tangential force in x `q_friction` = 1.9e-4 of P
    (bound 1e-3: the bodies alike, friction carries little but the
    mesh's asymmetry)."""
    s, fc = force_run(tmp_path, "friction", friction=True)
    c = s["contact"]["c"]
    F = np.array(c["surfaces"][0]["force"])
    assert s["converged"]
    assert figure("dF_friction", abs(F[2] - P) / P) <= 3 * FORCE_RTOL * np.linalg.norm(F) / P
    a, _ = hertz(2 * P)
    assert abs(figure("a_error_friction", c["fem_a_moment"] / a - 1)) <= 0.05
    assert figure("q_friction", abs(F[0]) / P) <= 1e-3


@pytest.mark.roundoff
def test_two_ranks(frictionless, tmp_path):
    """On 2 ranks (the search and the reach per rank, reduced): the
    displacement found differs from 1 rank's by `dU_ranks` = 7.8e-16 of
    it, a by `da_ranks` = 5.5e-14 (bounds 1e-6: both stop within 1e-6 of
    the force)."""
    s, fc = frictionless
    s2, fc2 = force_run(tmp_path, "ranks", ranks=2)
    assert s2["converged"]
    assert figure("dU_ranks", abs(fc2["displacement"] / fc["displacement"] - 1)) <= 1e-6
    assert figure("da_ranks", abs(s2["contact"]["c"]["fem_a_moment"] / s["contact"]["c"]["fem_a_moment"] - 1)) <= 1e-6
