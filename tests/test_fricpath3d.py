"""Friction's solve paths in 3D (src/contact/friction3d.c, src/solver/staging.c).

A tangential force from rest: the flat patch of tests/test_shear3d.py (a
Tet10 box [0, 1]^2 x [0.5, 1] on a wider Hex27 box [-0.1, 1.1]^2 x [0, 0.5],
E 1000, nu 0.3, mu 0.3; the upper's faces y = 0 and y = 1 on rollers) given
(Q, -P) at its top by force control in one stage from rest. The first solve
of an increment from rest has no lagged pressure: frictionless, the upper is
free along x and the solve ended DIVERGED_LS_FAILURE after four cutbacks
(status 2). Now it starts tied (Friction3dChooseStart)."""
import h5py
import numpy as np
import pytest

from conftest import figure, run_contact

MU, P = 0.3, 5.0
BOX = "tests/meshes/contact3d/box.geo"
LAG_RTOL = 1e-8     # -contact_friction_lag_rtol's default
FORCE_RTOL = 1e-6   # -stop_force_rtol's default: the stop's gradient against the contacts' nodal forces


def patch_from_rest(Q, extra=()):
    return ["-bodies", "lower,upper",
            "-lower_geo", BOX, "-lower_geo_params", "hex=1,n=4,m=2,x0=-0.1,y0=-0.1,L=1.2", "-lower_E", 1000, "-lower_nu", 0.3,
            "-lower_bc", "bottom,xmin,xmax,ymin,ymax", "-lower_bc_bottom_components", "z", "-lower_bc_xmin_components", "x",
            "-lower_bc_xmax_components", "x", "-lower_bc_ymin_components", "y", "-lower_bc_ymax_components", "y",
            "-upper_geo", BOX, "-upper_geo_params", "hex=0,h=0.3,z0=0.5", "-upper_E", 1000, "-upper_nu", 0.3,
            "-upper_bc", "top,ymin,ymax", "-upper_bc_top_components", "x,z", "-upper_bc_top_control", "force,force",
            "-upper_bc_top_values", f"{Q!r},{-P}",
            "-upper_bc_ymin_components", "y", "-upper_bc_ymax_components", "y",
            "-contact_pairs", "p", "-contact_p_surfaces", "upper:bottom,lower:top", "-contact_p_friction", MU] + list(extra)


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
    = 7.7e-11 of its largest, the stick area by `dA` = 0 (relative), the
    same nodes stuck (matched by their reference coordinates). Bound from
    the stops, as tests/test_friction3d.py's: each run's lagged bound is its
    pressure's to -contact_friction_lag_rtol 1e-8 of mu p_max, two runs'
    shear 2e-8 mu p_max apart; times 3."""
    args = patch_from_rest(0.5 * MU * P)
    one = run_contact(args, tmp_path, name="one")
    two = run_contact(args, tmp_path, ranks=2, name="two")
    assert two.summary["ranks"] == 2 and one.summary["converged"] and two.summary["converged"]
    sets = []
    for res in (one, two):
        with h5py.File(res.output_path, "r") as f:
            g = f["contact/p/upper_bottom"]
            X = g["node_X"][:]
            o = np.lexsort((X[:, 2], X[:, 1], X[:, 0]))
            sets.append((X[o], g["node_shear"][:][o], g["node_stick"][:][o], g["node_pressure"][:][o]))
    (X1, q1, s1, p1), (X2, q2, s2, _) = sets
    assert np.abs(X1 - X2).max() <= 1e-12
    qmax = np.abs(q1).max()
    bound = 3 * 2 * LAG_RTOL * MU * p1.max() / qmax
    assert figure("dq", np.abs(q1 - q2).max() / qmax) <= bound
    a1, a2 = one.summary["contact"]["p"]["stick_area"], two.summary["contact"]["p"]["stick_area"]
    assert figure("dA", abs(a1 / a2 - 1)) <= bound
    assert np.array_equal(s1, s2)
