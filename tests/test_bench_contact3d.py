"""scripts/bench_contact3d.py's own measures, on a small run: the Hertz
errors it reads from a summary are test_hertz_quarter's, and its per-step
split of a Newton iteration's time comes from the run's -log_view events."""
import json
import math
import os
import sys

import pytest

from conftest import run_contact
import hertz

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "scripts"))
import bench_contact3d as bench  # noqa: E402
from test_contact3d import E_BALL, E_BASE, NU, UPPERS, patch_args  # noqa: E402


def test_hertz_errors():
    """A summary made up for Hertz's own profile (three nodes on a ring of
    radius r at p0 sqrt(1 - r^2/a^2), with the weights that give the
    profile's second moment 2 a^2 / 5): a_error and pmax_error 0 to
    round-off; P is four times the quarter's F_z."""
    P = 2.0
    a, p0 = hertz.sphere(P, hertz.plane_strain_modulus(E_BALL, NU, E_BASE, NU))
    r = a * math.sqrt(0.4)   # a single ring: sum p A r^2 / sum p A = r^2 = 2 a^2 / 5
    rows = [[r, 0, 0, p0 * math.sqrt(0.6), 1.0], [0, r, 0, p0 * math.sqrt(0.6), 1.0]]
    s = {"contact": {"c": {"force": [0, 0, P / 4], "pmax": p0, "contact_nodes": {"rows": rows}, "nodes_in_contact": 2,
                           "surfaces": [{"slave": True, "faces": 7}, {"slave": False, "faces": 9}]}}}
    e = bench.hertz_errors(s)
    assert abs(e["P"] - P) <= 1e-14 * P
    assert abs(e["a_error"]) <= 1e-14 and abs(e["pmax_error"]) <= 1e-14
    assert e["slave_faces"] == 7


@pytest.mark.parametrize("step", ["direct"])
def test_per_step_events(step, tmp_path):
    """The patch (Tet10 on Hex27) with -log_view: the events the script reads
    are there (the contact's Hessian and energy, the Schur step's), each
    counted at least once a Newton iteration, and its per-step figures are
    positive and no more than the whole solve's time."""
    log = tmp_path / "log.txt"
    res = run_contact(patch_args(UPPERS["tet10-on-hex27"], ["-log_view", f":{log}"]), tmp_path)
    s = res.summary
    ev = bench.parse_log(log.read_text())
    for k in ("Mortar3dHessian", "Mortar3dEnergyGrad", "SubstrStep", "SubstrSolve", "SubstrFactor"):
        assert k in ev, k
    assert ev["Mortar3dHessian"][0] >= s["iterations"]
    r = dict(events=ev, iterations=s["iterations"], step=step)
    contact, linear, factor = bench.per_step(r)
    assert 0 < contact * s["iterations"] <= s["time"]["solve"]
    assert 0 < linear * s["iterations"] <= s["time"]["solve"]
    assert factor > 0
    json.dumps(r)
