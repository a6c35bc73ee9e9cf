"""A body held by contact (src/body/anchors.c): the reference scene's block
with only u_y = 0 on its right edge (x translation and the rotation about
that edge free) and a pressure on that edge that presses it onto the disc.
Its free motions are anchored by force-controlled vertices whose force is
zero at the end, so the answer is the free block's. Checked against what
must hold whatever the discretisation: the block is free in x, so the
contact force equals the load (its equilibrium); the anchors carry nothing;
1 and 2 ranks agree; a body that nothing holds is still refused."""
import numpy as np
import pytest

from conftest import figure, run_contact

HELD = ["-options_file", "meshes/hertz/hertz.opts", "-block_bc_push_components", "y", "-block_bc_push_values", "0",
        "-block_load", "push", "-block_load_push_pressure", "27.5"]
LOAD = 27.5 * 2.0   # the pressure times the edge's length


@pytest.mark.roundoff
def test_held_from_rest(tmp_path):
    """Converges from rest with no option chosen for it (exit 0). The contact
    force along x is the load: their difference is the anchors' reactions plus
    the solve's residual (the block's x-equilibrium), measured
    `fx` = 6.3e-4 to 0.017 of its bound over the five kernels, that sum (the
    anchors' reactions, `anchor` = 4.0e-18 to 7.0e-16 of the load, within 1e-9
    of it; plus sqrt(n) times the gradient norm). The contact force's y part,
    `fy` = -1.4e-5 of the load, is the tilt of the free block's rotation,
    carried by the edge's u_y = 0. The load's resultant is the pressure times
    the edge's length (`load` = 3.3e-16 to 1.8e-15 in magnitude, bound 1e-13).
    The JSON lists the anchors as such. Nothing on stderr: the pressure acts in
    x only, on an edge held in y only, so no set-up check speaks
    (conditions.c)."""
    r = run_contact(HELD + ["-output", "none"], tmp_path)
    s = r.summary
    assert not r.stderr.strip(), r.stderr
    anchors = [c for c in s["force_control"] if c["anchor"]]
    assert anchors and all(c["body"] == "block" and c["force"] == 0 for c in anchors)
    residual = sum(abs(c["reaction"]) for c in anchors) + np.sqrt(s["dofs"]) * s["gradient_norm"]
    fx = abs(s["contact"]["interface"]["force"][0])
    print(f"contact force in x {fx!r} against the load {LOAD}: {abs(fx - LOAD):.2e}, "
          f"bound {residual:.2e}; anchors {[(c['group'], c['component'], c['reaction']) for c in anchors]}")
    assert figure("fx", abs(fx - LOAD) / residual) <= 1
    assert all(figure("anchor", abs(c["reaction"]) / LOAD) <= 1e-9 for c in anchors)
    figure("fy", s["contact"]["interface"]["force"][1] / LOAD)
    assert abs(figure("load", s["loads"]["block:push"][0] / LOAD + 1)) <= 1e-13


@pytest.mark.roundoff
def test_held_ranks(tmp_path):
    """1 and 2 ranks: the same contact force to 1e-11 of the load and anchor
    displacements to 1e-12 (the anchors are chosen by coordinates, the same on
    every partition). Both solved to -force_control_rtol 1e-11 and -tao_gttol
    1e-12, so that the stop adds nothing: measured `dP` = up to 2.7e-13
    and `du` = 0 to 5.4e-16 over the five kernels."""
    tight = ["-output", "none", "-force_control_rtol", "1e-11", "-tao_gttol", "1e-12"]
    one = run_contact(HELD + tight, tmp_path, name="np1").summary
    two = run_contact(HELD + tight, tmp_path, ranks=2, name="np2").summary
    assert figure("dP", abs(one["contact_force"] - two["contact_force"]) / LOAD) <= 1e-11
    for a, b in zip(one["force_control"], two["force_control"]):
        assert (a["group"], a["component"]) == (b["group"], b["component"])
        du = figure("du", abs(a["displacement"] - b["displacement"]) / max(abs(a["displacement"]), 1e-3))
        assert du <= 1e-12, (a, b)


@pytest.mark.parametrize("case,extra,cause", [
    ("no_load", ["-options_file", "meshes/hertz/hertz.opts", "-block_bc_push_components", "y", "-block_bc_push_values", "0"],
     "body block: its Dirichlet conditions leave 2 rigid motion(s) free"),
    ("no_contact", HELD + ["-contact_disable"], "and it is in no contact pair"),
])
def test_nothing_holds(case, extra, cause, tmp_path):
    """Without a load pressing it on, or without a contact, the body is still
    refused in one line."""
    r = run_contact(extra, tmp_path, check=False)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert r.returncode == 1 and len(lines) == 1 and lines[0].startswith("contact: error: "), r.stderr
    assert cause in lines[0], lines[0]
