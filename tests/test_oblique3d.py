"""P and Q given together from rest on a curved 3D contact, in N load
increments (Johnson, Contact Mechanics 7.2; 2D's: tests/test_oblique2d.py).
The scene: tests/test_view3d.py's half ball (R = 1, E = 1000, nu = 0.3 on
a like half block, h = 0.04, the plane y = 0 on rollers and declared), its
top given the forces (Q, -P) along x and z (force control, both axes; the
half model's P = 0.35, a/R about 0.1) with Q = 0.5 mu P, mu = 0.3, in one
stage from rest. The increment from rest starts tied (Friction3dChooseStart:
given forces alone, the ball is free along the contact), the next ones from
the accepted bound times the given forces' growth (Friction3dScaleBound).

The references: loaded at once (one increment) the contact is Cattaneo's
and Mindlin's, a central disc of radius c = a (1 - Q/(mu P))^(1/3) sticks;
loaded in proportion with Q/P < mu, Mindlin and Deresiewicz's shear is
q = (Q/P) p everywhere, parallel to Q, and nothing slips. In N increments
each ring of the contact carries shear only from the increments after it
touched, so the shear tends to (Q/P) p as N grows."""
import math

import h5py
import numpy as np
import pytest

from conftest import figure, run_contact
from test_friction3d import contact_radius, stick_radius
from test_view3d import MU, SLAVE, scene_args

P = 0.35                # the half model's normal force (as tests/test_forceball3d.py)
Q = 0.5 * MU * P        # along x, in the same stage
FORCE_RTOL = 1e-6       # -stop_force_rtol's default: the stop's gradient against the contacts' nodal forces


def oblique_args(steps):
    """The half ball given (Q, -P) at its top in one stage of `steps` increments."""
    a = [str(x) for x in scene_args()]
    a[a.index("-ball_bc_top_values") + 1] = f"{Q!r},{-P!r}"
    i = a.index("-load_stages")
    a = a[:i] + a[i + 2:]
    a[a.index("-load_steps") + 1] = str(steps)
    return a + ["-ball_bc_top_control", "force,force"]


def measure(res):
    """From the slave's written nodes: dQ (the contact's x force against Q,
    relative), its bound (3 times the stop), c/a (the stick disc's radius
    over a from the pressures' second moment) against (1 - Q/(mu P))^(1/3),
    the relative L2 of |t| - (Q/P) p over the slave's nodes (weights A_j),
    and the traction's part across Q (relative L2 of t_y against |t|)."""
    s = res.summary
    c = s["contact"]["c"]
    F = np.array(c["surfaces"][0]["force"])  # the slave's: the ball's cap
    assert c["surfaces"][0]["body"] == "ball"
    with h5py.File(res.output_path, "r") as f:
        g = f[SLAVE]
        n = dict(X=g["node_X"][:], p=g["node_pressure"][:], A=g["node_weight"][:],
                 t=g["node_shear"][:], stick=g["node_stick"][:])
    t = np.linalg.norm(n["t"], axis=1)
    ref = (Q / P) * n["p"]
    a = contact_radius(n)
    return dict(converged=s["converged"], dQ=abs(F[0] + Q) / Q, bound=3 * FORCE_RTOL * np.linalg.norm(F) / Q,
                dP=abs(F[2] - P) / P,
                c=stick_radius(n) / a, c_err=stick_radius(n) / a / (1 - Q / (MU * P)) ** (1 / 3) - 1,
                l2=math.sqrt(np.sum(n["A"] * (t - ref) ** 2) / np.sum(n["A"] * ref ** 2)),
                across=math.sqrt(np.sum(n["A"] * n["t"][:, 1] ** 2) / np.sum(n["A"] * t ** 2)),
                along=np.sum(n["A"] * n["t"][:, 0]) / np.sum(n["A"] * t))


def run(tmp_path, steps):
    return measure(run_contact(oblique_args(steps), tmp_path, name=f"n{steps}", timeout=1800))


def cattaneo_l2(rho):
    """The relative L2 of Cattaneo-Mindlin's shear (loaded at once, Q/(mu P) =
    rho) from Mindlin-Deresiewicz's (Q/P) p over Hertz's disc, weights the
    area: q = mu p0/a (sqrt(a^2 - r^2) - sqrt(c^2 - r^2)), c = a (1 - rho)^(1/3),
    integrated on r in [0, a] (a = p0 = 1: the ratio is free of both)."""
    r = np.linspace(0.0, 1.0, 200001)
    c = (1 - rho) ** (1 / 3)
    q = MU * (np.sqrt(1 - r * r) - np.sqrt(np.maximum(c * c - r * r, 0)))
    ref = rho * MU * np.sqrt(1 - r * r)
    return math.sqrt(np.trapezoid(r * (q - ref) ** 2, r) / np.trapezoid(r * ref ** 2, r))


def check_balanced(m):
    """Converged, the contact's force balancing Q and P to 3 times the stop."""
    assert m["converged"]
    assert m["dQ"] <= m["bound"] and m["dP"] <= m["bound"] * Q / P


def test_one_increment_is_cattaneo(tmp_path):
    """In one increment from rest (the tied start, then the fixed point): it
    converges, the contact's force balances Q to `dQ_1` = 4.4e-7 of it (bound:
    3 times the stop, -stop_force_rtol of the contact's force over Q) and P;
    the stick disc's radius over a (a from the pressures' second moment, c
    from the stuck nodes' area) is within `c_err_1` = +0.037 of Cattaneo-
    Mindlin's (1 - Q/(mu P))^(1/3) = 0.794 (bound 0.1: a/h about 2.5, the zone's
    edge placed between nodes); the shear's L2 from (Q/P) p is Cattaneo's own,
    0.544 over Hertz's disc (computed here), to `l2_gap_1` = +0.011 (bound
    0.035); the traction lies along -x: its part across Q is `across_1` = 0.13
    of it in L2 (bound 0.3: the coarse mesh's, the ball pressed alone with
    friction leaves a like shear, about 0.13 of (Q/P) p across) and the
    weighted mean of t_x/|t| is `along_1` = -0.989 (bound -0.97)."""
    m = run(tmp_path, 1)
    check_balanced(m)
    figure("dQ_1", m["dQ"])
    assert abs(figure("c_err_1", m["c_err"])) <= 0.1
    assert abs(figure("l2_gap_1", m["l2"] - cattaneo_l2(0.5))) <= 0.035
    assert figure("across_1", m["across"]) <= 0.3
    assert figure("along_1", m["along"]) <= -0.97


def test_proportional_tends_to_no_slip(tmp_path):
    """In 2, 4 and 8 increments every run converges and balances Q and P to
    3 times the stop; the shear's L2 from Mindlin-Deresiewicz's (Q/P) p
    falls at each doubling by at least a tenth (measured: 55 % in one
    increment, then by 39, 26 and 24 %: `l2_2` = 0.337, `l2_4` = 0.250,
    `l2_8` = 0.190; bound 0.4 in 8), the stick zone widens to the whole
    contact (c/a `c_8` = 0.990 in 8, 0.95 in 2; bound 0.97) and the
    traction stays along -x (`across_8` = 0.125 across in L2, bound 0.3)."""
    last = None
    for n in (2, 4, 8):
        m = run(tmp_path, n)
        check_balanced(m)
        figure(f"l2_{n}", m["l2"])
        assert m["across"] <= 0.3 and m["along"] <= -0.97
        if last is not None:
            assert m["l2"] < 0.9 * last
        last = m["l2"]
    assert m["l2"] <= 0.4
    assert figure("c_8", m["c"]) >= 0.97
    figure("across_8", m["across"])


@pytest.mark.stress
def test_many_increments(tmp_path):
    """32 increments (2 minutes alone, 3.5 beside other runs): it converges and balances Q and P
    to 3 times the stop; the shear's L2 from (Q/P) p is `l2_32` = 0.136
    (bound 0.25: it levels from 16 increments on, 0.150 there, near the
    shear the normal load alone leaves on this mesh), c/a `c_32` = 0.996
    (bound 0.97)."""
    m = run(tmp_path, 32)
    check_balanced(m)
    assert figure("l2_32", m["l2"]) <= 0.25
    assert figure("c_32", m["c"]) >= 0.97


def sorted_nodes(res):
    """The slave's nodes in the order of their reference coordinates (the
    ranks number them apart): X, shear, stick, pressure."""
    with h5py.File(res.output_path, "r") as f:
        g = f[SLAVE]
        X = g["node_X"][:]
        o = np.lexsort((X[:, 2], X[:, 1], X[:, 0]))
        return X[o], g["node_shear"][:][o], g["node_stick"][:][o], g["node_pressure"][:][o]


def test_ranks_agree(tmp_path):
    """2 increments on 1 and 2 ranks (the tied start's rows and the scaled
    bound each rank's whole): the nodal shear apart by `dq_ranks` = 8.5e-12
    of its largest, the same nodes stuck. Bound from the stops, far above
    round-off (make test alone): each run's lagged bound is its pressure's
    to -contact_friction_lag_rtol 1e-6 of mu p_max, two runs' shear 2e-6 mu
    p_max apart; times 3."""
    args = oblique_args(2)
    one = run_contact(args, tmp_path, name="one", timeout=1800)
    two = run_contact(args, tmp_path, ranks=2, name="two", timeout=1800)
    assert one.summary["converged"] and two.summary["converged"] and two.summary["ranks"] == 2
    (X1, q1, s1, p1), (X2, q2, s2, _) = sorted_nodes(one), sorted_nodes(two)
    assert np.abs(X1 - X2).max() <= 1e-12
    qmax = np.abs(q1).max()
    assert figure("dq_ranks", np.abs(q1 - q2).max() / qmax) <= 3 * 2e-6 * MU * p1.max() / qmax
    assert np.array_equal(s1, s2)
