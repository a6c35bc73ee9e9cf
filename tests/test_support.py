"""What holds a body that no displacement holds (src/body/support.c): a body
given forces alone (every condition force-controlled, or none) whose contacts
cannot react them is one line naming the body and the motion, status 1,
nothing written, before solving. Scenes of the tests' own: the rigid punch's
geometry with the block's base left free, the punch pulled off the block,
and scenes that are held (the roller between its races, the cattaneo disc
pressed by a force, the punch pressed onto a held block) that must pass."""
import re
import time
from pathlib import Path

import pytest

from conftest import ROOT, run_contact

PUNCH = ROOT / "meshes" / "rigid-punch" / "rigid-punch.opts"


def free_block_scene(tmp_path):
    """The rigid-punch scene without the block's base condition: the block is
    held by its contact with the punch alone."""
    text = []
    for line in PUNCH.read_text().splitlines():
        if line.startswith("-block_bc"):
            continue
        line = line.replace("-punch_geo punch.geo", f"-punch_geo {ROOT}/meshes/rigid-punch/punch.geo")
        line = line.replace("-block_geo ../punch/block.geo", f"-block_geo {ROOT}/meshes/punch/block.geo")
        text.append(line)
    path = Path(tmp_path) / "free.opts"
    path.write_text("\n".join(text) + "\n")
    return ["-options_file", str(path)]


def refused(r, needle, wall):
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    print(f"{wall:.1f} s", lines)
    assert r.returncode == 1 and len(lines) == 1 and needle in lines[0], r.stderr[-2000:]
    assert not r.summary_path.exists() and not r.output_path.exists()


@pytest.mark.parametrize("control", ["force", "displacement"])
def test_free_block_under_punch(control, tmp_path):
    """The punch pushed down by a force (before: the line search failed after
    20 s, "dx * (stp-stx) >= 0.0") or by a displacement (before: P = 1.2e-10
    after a minute, status 0) on a block held by nothing but the punch: the
    block is named, with the direction its contact pushes it, (0, -1)."""
    args = free_block_scene(tmp_path)
    if control == "force":
        args += ["-punch_bc_push_control", "force,force", "-punch_bc_push_values", "0,-0.15"]
    t0 = time.time()
    r = run_contact(args, tmp_path, check=False)
    refused(r, "body block: held by its contacts alone, which can only push it towards (0, -1)", time.time() - t0)


def test_punch_pulled_off(tmp_path):
    """A force pulling the rigid punch off the block (0.15 up): nothing
    reacts it; the body, the stage, the force and the motion are named."""
    t0 = time.time()
    r = run_contact(["-options_file", str(PUNCH), "-punch_bc_push_control", "force,force", "-punch_bc_push_values", "0,0.15"],
                    tmp_path, check=False)
    refused(r, "body punch: the force given it at stage 1, (0., 0.15), is not one its contacts can react", time.time() - t0)
    assert "(0, 1)" in r.stderr


def test_sideways_beyond_friction_cone(tmp_path):
    """The punch given a sideways force and a downward one on a frictionless
    block: the contacts (normals straight up) react no sideways force."""
    r = run_contact(["-options_file", str(PUNCH), "-punch_bc_push_control", "force,force",
                     "-punch_bc_push_values", "0.01,-0.15"], tmp_path, check=False)
    refused(r, "body punch: the force given it at stage 1, (0.01, -0.15), is not one its contacts can react", 0)


@pytest.mark.parametrize("scene,args", [
    ("rigid-roller", []),
    ("roller", []),
    ("cattaneo", ["-load_steps", "1"]),
    ("rigid-punch", ["-punch_bc_push_control", "force,force", "-punch_bc_push_values", "0,-0.15"]),
    ("rigid-punch", ["-punch_bc_push_control", "force,force", "-punch_bc_push_values", "0.01,-0.15",
                     "-contact_tool_friction", "0.3"]),
])
def test_held_scenes_pass(scene, args, tmp_path):
    """Bodies their contacts hold: a roller between two races (normals both
    ways), a disc pressed by a force into its partner, a punch pushed onto a
    held block, and sideways within the friction cone (0.01 < 0.3 x 0.15):
    not refused (the solve is started)."""
    r = run_contact(["-options_file", f"meshes/{scene}/{scene}.opts", "-tao_max_it", "1", "-load_cutbacks", "0"] + args,
                    tmp_path, check=False)
    assert "contact: error" not in r.stderr, r.stderr[-2000:]
