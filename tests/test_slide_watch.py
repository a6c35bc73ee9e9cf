"""A frictional contact that slides without end, found by the solve where the
scene's forces do not decide it (src/solver/slidewatch.c): the cattaneo disc
pressed by a displacement (x, 0.003: P = 0.4988, mu P = 0.1496, from the
solve) and pulled along the slab by a force Q. Above mu P there is no
equilibrium: the run stops at the first increment whose slip keeps growing,
with one line naming the pair and its friction, status 2, nothing written,
no cutback (before: TAO's More-Thuente line search broke down with "dx *
(stp-stx) >= 0.0", reported as bad input, status 1; with the rigid punch,
four cutbacks each failing again). Below mu P it converges."""
import time

import pytest

from conftest import ROOT, figure, run_contact

MU, P = 0.3, 0.4988
DISC = ["-options_file", str(ROOT / "meshes" / "cattaneo" / "cattaneo.opts"), "-load_steps", "2",
        "-disc_bc_clamp_control", "displacement,force"]


def pulled(q):
    return DISC + ["-disc_bc_clamp_values", f"0.003,0,0.003,{q!r}"]


def slides(r, pair="interface"):
    lines = [l for l in r.stderr.splitlines() if l.startswith("contact")]  # mpiexec's own lines left out
    print(lines)
    assert r.returncode == 2, r.stderr[-2000:]
    assert len(lines) == 1 and f"pair {pair} slides" in lines[0] and f"-contact_{pair}_friction" in lines[0]
    assert "cut back" not in lines[0]
    assert not r.summary_path.exists() and not r.output_path.exists()


@pytest.mark.parametrize("ratio", [1.1, pytest.param(3.34, marks=pytest.mark.stress)])
def test_disc_pulled_beyond_friction(ratio, tmp_path):
    """Q = 1.1 (and in make stress 3.34) mu P: refused by the solve in one
    line (`wall` = 1.2 to 8 s, the most on a loaded machine, where the run at
    0.9 mu P converges in 3.0 s on a quiet one)."""
    t0 = time.time()
    r = run_contact(pulled(ratio * MU * P), tmp_path, check=False)
    figure("wall", time.time() - t0)
    slides(r)


def test_disc_pulled_below_friction(tmp_path):
    """Q = 0.9 mu P: an equilibrium, found; the shear the contact carries is
    the force given (`dQ` = 6e-15 of Q) and below mu P."""
    q = 0.9 * MU * P
    r = run_contact(pulled(q), tmp_path)
    assert r.summary["converged"]
    shear = abs(r.summary["reactions"]["disc:clamp"][1])
    dq = figure("dQ", abs(shear - q) / q)
    assert dq <= 1e-6
    assert shear < MU * abs(r.summary["reactions"]["disc:clamp"][0])


def test_two_ranks(tmp_path):
    """2 ranks stop the same way, with the same line."""
    slides(run_contact(pulled(1.1 * MU * P), tmp_path, ranks=2, check=False))


def test_rigid_punch_without_limits(tmp_path):
    """The rigid punch pressed by a displacement and pulled by Q = 0.06
    (mu P = 0.045; test_friction.py::test_rigid_punch_slides, which caps
    the iterations and the cutbacks): without those caps, one line too."""
    args = ["-options_file", "meshes/rigid-punch/rigid-punch.opts", "-punch_rigid_rotation", "free",
            "-punch_rigid_centre", "0.1,0.125", "-load_stages", "2", "-block_bc_base_values", "0,0,0,0",
            "-contact_friction", "0.3", "-punch_mesh_size", "0.05", "-block_mesh_size", "0.025",
            "-punch_bc_push_control", "force,displacement", "-punch_bc_push_values", "0,-0.002,0.06,-0.002"]
    slides(run_contact(args, tmp_path, check=False), pair="tool")
