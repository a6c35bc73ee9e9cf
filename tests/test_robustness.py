"""A cheap subset of the robustness sweep (scripts/stress_sweep.py, run by
`make stress`): the mirrored half of the reference scene at the sweep's
hardest penalty and push (k_p = 1e10, push 0.3) at h = 0.25 and 0.1, and at
its softest penalty (k_p = 1e3, push 0.3: the bodies 0.1 into each other) at
h = 0.1, the finest mesh where that case converges; with both formulations,
on 1 and 2 ranks (about 10 s in all).

Each run converges, and its answer is checked against what it must satisfy
whatever the discretisation: the contact pair's force on the indenter equals
the reaction at the pushed edge (equilibrium of the block, two independent
sums, equal to the solver's stopping residual; measured over the OpenBLAS
kernels Nehalem, Sandybridge, Haswell and SkylakeX 1e-11 to 3.2e-9, and
1.32e-8 for the softest penalty with gpts, bound 1e-6, what the stopping test
allows at k_p = 1e10 (the sweep measures 1.7e-6 at h = 0.01): catches a
reaction summed over the wrong dofs or ranks, a force reported from another
state), 1 and 2 ranks give the same P (measured 0 to 2.1e-9, bound 1e-8:
catches a rank's share reported as the whole) although at k_p = 1e10 they
may take different Newton paths (62 against 49 iterations for gpts at
h = 0.25), and the half model's P is twice its pair's force (measured
exactly, bound 100 EPS: catches a mirror that does not double it)."""
import math

import numpy as np
import pytest

from conftest import run_contact

HALF = ["-options_file", "meshes/hertz-half/hertz-half.opts"]
EPS = np.finfo(float).eps
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
              f"reaction {reaction:.10g}: balance {abs(abs(f) - abs(reaction)) / abs(reaction):.2e}, "
              f"P - 2|f| {abs(s['contact_force'] - 2 * abs(f)) / s['contact_force']:.2e}")
        assert f < 0 < s["contact_force"], "the block pushes the indenter away (-x)"
        assert abs(abs(f) - abs(reaction)) <= 1e-6 * abs(reaction), (f, reaction)
        # the half model's P is that of the whole: twice the half's force
        assert abs(s["contact_force"] - 2 * abs(f)) <= 100 * EPS * s["contact_force"]
        P[n] = s["contact_force"]
    print(f"1 against 2 ranks: P {abs(P[2] - P[1]) / abs(P[1]):.2e}")
    assert abs(P[2] - P[1]) <= 1e-8 * abs(P[1]), P


def _edge_length(h5, pair, surface):
    """Mean reference edge length of a contact surface, from the HDF5's node
    coordinates and edges (independent of the program's own figure)."""
    import h5py
    import numpy as np
    with h5py.File(h5) as f:
        g = f[f"/contact/{pair}/{surface}"]
        X, cells = g["node_X"][...], g["node_cells"][...]
    # node_cells joins consecutive nodes along the surface (corner and mid-edge
    # nodes alike): an edge of the quadratic mesh is two of them
    return np.linalg.norm(X[cells[:, 1]] - X[cells[:, 0]], axis=1).sum() / (len(cells) // 2)


def test_deep_overlap_named(tmp_path):
    """A penalty too soft for its load lets the bodies overlap by more than an
    element, where the penalty's answer is no longer the contact's (and Newton
    may meet the saddles of a non-convex discrete energy): the report says so,
    with the overlap against the contact edges' length and the option to
    raise. Here (half scene, h = 0.05, k_p = 1e3, push 0.3) the overlap is
    0.10, about two edges; the default penalty (2e6) overlaps by 5e-5 and
    gets no warning."""
    r = run_contact(HALF + ["-mesh_size", 0.05, "-contact_penalty", "1e3", "-block_bc_push_values", "-0.3,0"],
                    tmp_path, name="soft")
    warn = [ln for ln in r.stdout.splitlines() if "bodies overlap" in ln]
    assert len(warn) == 1 and warn[0].lstrip().startswith("WARNING: pair interface") and \
        "-contact_interface_penalty" in warn[0], warn
    ratio = float(warn[0].split(", ")[1].split(" times")[0])
    h_edge = min(_edge_length(r.output_path, "interface", s) for s in ("indenter_contact", "block_contact"))
    expected = r.summary["contact"]["interface"]["max_penetration"] / h_edge
    print(f"overlap {r.summary['contact']['interface']['max_penetration']:.4g}, edges {h_edge:.4g}: "
          f"ratio {expected:.4g}, printed {ratio}")
    assert expected > 1.5
    assert abs(ratio - expected) <= 0.005 * expected   # printed to 3 digits
    stiff = run_contact(HALF + ["-mesh_size", 0.05], tmp_path, name="stiff")
    assert "bodies overlap" not in stiff.stdout


def test_deep_overlap_names_the_stop(tmp_path):
    """A solve that stops while the bodies overlap by more than an element
    ends in one line naming that cause, not TAO's reason alone: stopped here
    after 2 Newton iterations (-tao_max_it 2), the first step from rest having
    pushed the indenter 0.1 deep at k_p = 1e3."""
    r = run_contact(HALF + ["-mesh_size", 0.05, "-contact_penalty", "1e3", "-block_bc_push_values", "-0.3,0",
                            "-tao_max_it", 2], tmp_path, name="stop", check=False)
    assert r.returncode == 2, r.stderr
    lines = [ln for ln in r.stderr.splitlines() if ln.startswith("contact:")]
    assert len(lines) == 1, r.stderr
    assert lines[0].startswith("contact: the solve did not converge (DIVERGED_MAXITS): pair interface: the bodies overlap by")
    assert "raise -contact_interface_penalty" in lines[0] and lines[0].endswith("no output written")
