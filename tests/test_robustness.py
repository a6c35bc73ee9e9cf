"""A cheap subset of the robustness sweep (scripts/stress_sweep.py, run by
`make stress`): the mirrored half of the reference scene at the sweep's
hardest penalty and push (k_p = 1e10, push 0.3) at h = 0.25 and 0.1, and at
its softest penalty (k_p = 1e3, push 0.3: the bodies 0.1 into each other) at
h = 0.1, the finest mesh where that case converges; with both formulations,
on 1 and 2 ranks (about 10 s in all).

Each run converges, and its answer is checked against what it must satisfy
whatever the discretisation: the contact pair's force on the indenter equals
the reaction at the pushed edge (equilibrium of the block, two independent
sums; measured 1.2e-10 to 1.3e-8, bound 1e-6), and 1 and 2 ranks give the same
P (measured 0 to 1.5e-9, bound 1e-8) although at k_p = 1e10 they may take
different Newton paths (62 against 49 iterations for gpts at h = 0.25)."""
import math

import pytest

from conftest import run_contact

HALF = ["-options_file", "meshes/hertz-half/hertz-half.opts"]
CASES = [(0.25, 1e10, 0.3), (0.1, 1e10, 0.3), (0.1, 1e3, 0.3)]


@pytest.mark.parametrize("formulation", ["gpts", "mortar"])
@pytest.mark.parametrize("h,kp,push", CASES)
def test_extreme_case(h, kp, push, formulation, tmp_path):
    args = HALF + ["-mesh_size", h, "-contact_penalty", f"{kp:g}", "-block_bc_push_values", f"{-push:g},0",
                   "-contact_formulation", formulation]
    P = {}
    for n in (1, 2):
        r = run_contact(args, tmp_path, ranks=n, name=f"np{n}")
        s = r.summary  # exit 0: converged (run_contact checks it; an unconverged solve exits 2)
        assert all(math.isfinite(x) for x in (s["contact_force"], s["energy"], s["gradient_norm"]))
        f = s["contact"]["interface"]["force"][0]
        reaction = s["reactions"]["block:push"][0]
        print(f"{n} rank(s): {s['iterations']} iterations, P {s['contact_force']:.10g}, force {f:.10g}, "
              f"reaction {reaction:.10g}")
        assert f < 0 < s["contact_force"], "the block pushes the indenter away (-x)"
        assert abs(abs(f) - abs(reaction)) <= 1e-6 * abs(reaction), (f, reaction)
        # the half model's P is that of the whole: twice the half's force
        assert abs(s["contact_force"] - 2 * abs(f)) <= 1e-12 * s["contact_force"]
        P[n] = s["contact_force"]
    assert abs(P[2] - P[1]) <= 1e-8 * abs(P[1]), P
