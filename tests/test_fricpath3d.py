"""Friction's solve paths in 3D (src/contact/friction3d.c, src/solver/staging.c).

A tangential force from rest: the flat patch of tests/test_shear3d.py (a
Tet10 box [0, 1]^2 x [0.5, 1] on a wider Hex27 box [-0.1, 1.1]^2 x [0, 0.5],
E 1000, nu 0.3, mu 0.3; the upper's faces y = 0 and y = 1 on rollers) given
(Q, -P) at its top by force control in one stage from rest. The first solve
of an increment from rest has no lagged pressure: frictionless, the upper is
free along x and the solve ended DIVERGED_LS_FAILURE after four cutbacks
(status 2). Now it starts tied (Friction3dChooseStart); so does a half ball
pressed by a displacement and pushed by a force from rest. The rigid cube's
Newton path with friction: tests/test_rigidm3d.py (staging.c's
ProblemStateLagSofter)."""
import numpy as np
import pytest

from conftest import figure, run_contact
from test_friction3d import LAG_RTOL, patch_nodes
from test_shear3d import MU, P, patch_forces
from test_view3d import scene_args

FORCE_RTOL = 1e-6   # -stop_force_rtol's default: the stop's gradient against the contacts' nodal forces


def patch_from_rest(Q, extra=(), normal=("force", -P)):
    """test_shear3d's patch given (Q, normal) in one stage from rest; normal:
    the top's z control and value (-P given, or a displacement)."""
    args = patch_forces(Q)
    assert args[-2:] == ["-load_stages", 2]
    args = args[:-2]
    args[args.index("-upper_bc_top_control") + 1] = f"force,{normal[0]}"
    args[args.index("-upper_bc_top_values") + 1] = f"{Q!r},{normal[1]!r}"
    return args + list(extra)


def test_tangential_force_from_rest(tmp_path):
    """Q = 0.5 mu P and P given together from rest, one stage: it converges;
    the contact's force on the upper balances Q along x to `dQ` = 4.9e-9 of Q
    (bound: 3 times the stop, -stop_force_rtol 1e-6 of the contact's force
    over Q) and P across; the shear's resultant (Friction3dShearForce, the
    friction's part) is Q to `shear_gap` = 1.4e-3 of it (bound 1 %: the
    lower's top tilts under the shear, its strain Q/(G A) = 2e-3, and the
    pressure along its normal takes the rest of Q), and part of the face
    sticks: `stick_fraction` = 0.78 of the contact's area (bounds 0.05 to
    0.95: the edges, where the pressure peaks least against the shear they
    carry, slip)."""
    Q = 0.5 * MU * P
    res = run_contact(patch_from_rest(Q, ["-output", "none"]), tmp_path)
    s = res.summary
    c = s["contact"]["p"]
    F = np.array(c["surfaces"][0]["force"])  # the slave's: the upper's bottom
    assert s["converged"] and c["surfaces"][0]["body"] == "upper"
    bound = 3 * FORCE_RTOL * np.linalg.norm(F) / Q
    assert figure("dQ", abs(F[0] + Q) / Q) <= bound
    assert abs(F[2] - P) <= 3 * FORCE_RTOL * np.linalg.norm(F)
    assert figure("shear_gap", abs(c["tangential_load"] / Q - 1)) <= 0.01
    assert 0.05 < figure("stick_fraction", c["stick_area"] / c["contact_area"]) < 0.95


def test_tangential_force_pressed_by_displacement(tmp_path):
    """The same patch pressed by a displacement of its top (-0.01, P = 14.2
    from the contact) and given Q = 1 along x from rest: the normal held,
    the body still free along the contact but for friction (the tied start
    applies: Friction3dChooseStart takes the held axes out). It converges,
    Q/(mu P) = `q_ratio` = 0.235 (bounds 0.1 to 0.9: held within mu P), the
    contact's force balances Q to `dQ` = 2.7e-10 of it (bound as above) and
    `stick_fraction` = 0.89 of the face sticks (bounds 0.05 to 0.95)."""
    Q = 1.0
    s = run_contact(patch_from_rest(Q, ["-output", "none"], normal=("displacement", -0.01)), tmp_path).summary
    c = s["contact"]["p"]
    F = np.array(c["surfaces"][0]["force"])
    assert s["converged"]
    assert 0.1 < figure("q_ratio", Q / (MU * F[2])) < 0.9
    assert figure("dQ", abs(F[0] + Q) / Q) <= 3 * FORCE_RTOL * np.linalg.norm(F) / Q
    assert 0.05 < figure("stick_fraction", c["stick_area"] / c["contact_area"]) < 0.95


def test_above_mu_P_from_rest(tmp_path):
    """Q = 1.16 mu P with P in the same stage from rest: still refused before
    solving (Friction3dCheckGivenForces), one line naming the pair, the
    body, stage 1 and Q/(mu P), status 1, nothing written."""
    r = run_contact(patch_from_rest(1.16 * MU * P), tmp_path, check=False)
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    assert r.returncode == 1 and len(lines) == 1, r.stderr
    assert lines[0].startswith("contact: error: pair p: the forces given on body upper at stage 1 are ")
    assert float(lines[0].split("Q/(mu P) = ")[1].split(")")[0]) == pytest.approx(1.16, rel=1e-5)
    assert not r.summary_path.exists() and not r.output_path.exists()


@pytest.mark.roundoff
def test_from_rest_ranks(tmp_path):
    """The tangential force from rest on 1 and 2 ranks (the tied start's rows
    built on each rank's faces and gathered): the nodal shear apart by `dq`
    = 3.8e-11 to 7.7e-11 of its largest (the five kernels), the stick area
    by `dA` = up to 4.4e-16 (relative), the
    same nodes stuck (matched by their reference coordinates). Bound from
    the stops, as tests/test_friction3d.py's: each run's lagged bound is its
    pressure's to -contact_friction_lag_rtol 1e-8 of mu p_max, two runs'
    shear 2e-8 mu p_max apart; times 3."""
    args = patch_from_rest(0.5 * MU * P)
    one = run_contact(args, tmp_path, name="one")
    two = run_contact(args, tmp_path, ranks=2, name="two")
    assert two.summary["ranks"] == 2 and one.summary["converged"] and two.summary["converged"]
    (X1, q1, s1, p1), (X2, q2, s2, _) = patch_nodes(one), patch_nodes(two)
    assert np.abs(X1 - X2).max() <= 1e-12
    qmax = np.abs(q1).max()
    bound = 3 * 2 * LAG_RTOL * MU * p1.max() / qmax
    assert figure("dq", np.abs(q1 - q2).max() / qmax) <= bound
    a1, a2 = one.summary["contact"]["p"]["stick_area"], two.summary["contact"]["p"]["stick_area"]
    assert figure("dA", abs(a1 / a2 - 1)) <= bound
    assert np.array_equal(s1, s2)


def test_ball_pushed_from_rest(tmp_path):
    """A curved contact from rest: tests/test_view3d.py's half ball (R = 1,
    h = 0.04) pressed 0.01 into its half block at its top and given Q =
    0.055 along x there (force control) in the same increment, mu 0.3. At
    rest the segments pair the cap's nodes around the first contact point,
    apart from the block but for it: the tied start holds them all, and the
    lag lets the open ones go. It converges, Q/(mu P) = `q_ratio` = 0.43
    (bounds 0.1 to 0.9), the contact's force balances Q to `dQ` = 8.7e-8 of
    it (bound: 3 times the stop, as above) and part of the contact sticks,
    `stick_fraction` = 0.34 of its area (bounds 0.05 to 0.95: in one
    increment from rest the stuck zone's shear would peak at its edge, where
    the pressure falls to 0, so its rim slips)."""
    args = scene_args()
    args[args.index("-ball_bc_top_values") + 1] = "0.055,-0.01"
    i = args.index("-load_stages")
    args = args[:i] + args[i + 2:] + ["-ball_bc_top_control", "force,displacement", "-output", "none"]
    s = run_contact(args, tmp_path, timeout=1200).summary
    c = s["contact"]["c"]
    F = np.array(c["surfaces"][0]["force"])  # the slave's: the ball's cap
    assert s["converged"] and c["surfaces"][0]["body"] == "ball"
    assert 0.1 < figure("q_ratio", 0.055 / (MU * F[2])) < 0.9
    assert figure("dQ", abs(F[0] + 0.055) / 0.055) <= 3 * FORCE_RTOL * np.linalg.norm(F) / 0.055
    assert 0.05 < figure("stick_fraction", c["stick_area"] / c["contact_area"]) < 0.95


def test_proportional_increments(tmp_path):
    """P and Q = 0.5 mu P given together from rest in 4 increments of one
    stage (the flat patch above). The second increment's first solve used to
    hold the last increment's bound mu p_j, which the force given in
    proportion outgrows (Q_2/(mu P_1) = 1: "none of its 101 nodes in contact
    sticks", DIVERGED_USER); it now starts from that bound times the given
    forces' growth (Friction3dScaleBound, as 2D's FrictionScaleBound). It
    converges; the contact balances Q to `dQ4` = 1.3e-8 of it (bound 3 times
    the stop); on a flat patch the contact's area does not grow and the load
    is proportional, so the answer is the one-increment run's but for the
    finite sliding's geometry: the same nodes stick, and the nodal shear
    differs by `dq4` = 5.2e-4 of its largest (bound 2e-3)."""
    args = patch_from_rest(0.5 * MU * P)
    one = run_contact(args, tmp_path, name="one")
    four = run_contact(args + ["-load_steps", 4], tmp_path, name="four")
    assert one.summary["converged"] and four.summary["converged"]
    F = np.array(four.summary["contact"]["p"]["surfaces"][0]["force"])
    assert figure("dQ4", abs(F[0] + 0.5 * MU * P) / (0.5 * MU * P)) <= 3 * FORCE_RTOL * np.linalg.norm(F) / (0.5 * MU * P)
    (X1, q1, s1, _), (X4, q4, s4, _) = patch_nodes(one), patch_nodes(four)
    assert np.abs(X1 - X4).max() <= 1e-12 and np.array_equal(s1, s4)
    assert figure("dq4", np.abs(q1 - q4).max() / np.abs(q1).max()) <= 2e-3
