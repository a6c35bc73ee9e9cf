"""Forces a scene gives that friction cannot hold, named before solving
(src/contact/givenforces.c): a body held along a flat partner by one
frictional pair alone, given forces alone, whose tangential force exceeds mu
times its normal one at some stage, is one line naming the pair, the body,
the stage and the forces, status 1, nothing written, before any solve (the
solve would only fail after its cutbacks: 35 s on the cattaneo scene in one
increment a stage, a minute with its 8)."""
import time

import pytest

from conftest import run_contact

CATTANEO = ["-options_file", "meshes/cattaneo/cattaneo.opts"]
P, MU = 1.075, 0.3
PUNCH = ["-options_file", "meshes/rigid-punch/rigid-punch.opts", "-punch_rigid_rotation", "free",
         "-punch_bc_push_control", "force,force", "-contact_tool_friction", "0.3", "-load_stages", "2",
         "-block_bc_base_values", "0,0,0,0"]


def one_line(r):
    return [l for l in r.stderr.splitlines() if l.strip()]


@pytest.mark.parametrize("ratio", [1.0001, 1.16, 3.0])
def test_cattaneo_above_mu_P(ratio, tmp_path):
    """Q = ratio mu P in the second stage (the disc pressed by P, then pulled
    by Q): one line naming the pair, the body, stage 2, Q, P, mu P and
    Q/(mu P) (to its 6 printed digits), in well under the solve's time (no
    mesh is solved)."""
    Q = ratio * MU * P
    t0 = time.time()
    r = run_contact(CATTANEO + ["-disc_bc_clamp_values", f"{P},0,{P},{Q!r}"], tmp_path, check=False)
    wall = time.time() - t0
    lines = one_line(r)
    print(wall, lines)
    assert r.returncode == 1 and len(lines) == 1, r.stderr
    assert lines[0].startswith("contact: error: pair interface: the forces given on body disc at stage 2 are ")
    got = [float(x) for x in lines[0].split(" are ")[1].split(" along")[0:1]]
    ratio_said = float(lines[0].split("Q/(mu P) = ")[1].split(")")[0])
    assert got[0] == pytest.approx(Q, rel=1e-5) and f"{P:g} across it" in lines[0] and "-contact_interface_friction" in lines[0]
    assert ratio_said == pytest.approx(ratio, rel=1e-5)
    assert not r.summary_path.exists() and not r.output_path.exists()
    assert wall < 20


@pytest.mark.parametrize("ratio", [0.5, 0.9999])
def test_cattaneo_within_mu_P_goes_on(ratio, tmp_path):
    """Q within mu P: not refused (the solve is started: one Newton
    iteration here, the answer is test_friction's)."""
    Q = ratio * MU * P
    r = run_contact(CATTANEO + ["-disc_bc_clamp_values", f"{P},0,{P},{Q!r}", "-load_steps", "1", "-tao_max_it", "1",
                                "-load_cutbacks", "0"], tmp_path, check=False)
    assert "more than friction holds" not in r.stderr, r.stderr
    assert r.returncode in (0, 2), r.stderr


def test_rigid_punch_force_controlled(tmp_path):
    """A rigid punch given a force (x: 0.06 in stage 2, y: -0.15) on a flat
    block with mu = 0.3 (mu P = 0.045): refused before solving."""
    r = run_contact(PUNCH + ["-punch_bc_push_values", "0,-0.15,0.06,-0.15"], tmp_path, check=False)
    lines = one_line(r)
    print(lines)
    assert r.returncode == 1 and len(lines) == 1 and "pair tool: the forces given on body punch at stage 2 are 0.06 along block:contact and 0.15 across it" in lines[0], r.stderr


@pytest.mark.parametrize("case,args", [
    ("displacement held", ["-disc_bc_clamp_control", "value,force", "-disc_bc_clamp_values", f"-0.002,0,-0.002,{2 * MU * P!r}"]),
    ("frictionless", ["-contact_interface_friction", "0", "-disc_bc_clamp_values", f"{P},0,{P},0"]),
])
def test_not_applied(case, args, tmp_path):
    """Where a displacement is held (it reacts any force), or without
    friction, the check says nothing."""
    r = run_contact(CATTANEO + args + ["-load_steps", "1", "-tao_max_it", "1", "-load_cutbacks", "0"], tmp_path, check=False)
    assert "more than friction holds" not in r.stderr, (case, r.stderr)
