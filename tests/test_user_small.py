"""Smaller things a new user met (issue 47, item 10): options -help did not
list, a load history's order of values, the r-z plot of a ring, a master's
unpaired nodes, the progress line after a failed solve, the strain warning's
advice at a contact's edge, a 3D mesh, and `make run`'s demo."""
import re
import subprocess
from pathlib import Path

import pytest

from conftest import BIN, ENV, ROOT, figure, run_contact


def run_bin(args, cwd, ranks=1):
    cmd = [str(BIN)] + [str(a) for a in args]
    if ranks > 1:
        cmd = ["mpiexec", "--oversubscribe", "-n", str(ranks)] + cmd
    return subprocess.run(cmd, cwd=cwd, env=ENV, capture_output=True, text=True, timeout=600)


def option_line(out, name):
    lines = [l.strip() for l in out.splitlines() if l.strip().startswith(name + " ")]
    assert len(lines) == 1, f"{name} listed {len(lines)} times"
    return lines[0]


def options_table(doc):
    """The options docs/scenes.md tables: the first word of each row's first cell."""
    names = set()
    for line in (ROOT / doc).read_text().splitlines():
        m = re.match(r"\| `(-[a-z_<>]+)", line)
        if m:
            names.add(m.group(1))
    return names


SQUARES = ["-bodies", "a,b", "-a_geo", ROOT / "meshes/square/square.geo", "-b_geo", ROOT / "meshes/square/square.geo"]


@pytest.mark.parametrize("scene", [[], ["-contact_formulation", "gpts"], ["-contact_formulation", "mortar"]])
def test_help_lists_mortar_options(scene, tmp_path):
    """-help lists -contact_mortar_slave and -contact_mortar_basis once, with
    their defaults (auto, dual), without a scene and whatever the scene's
    formulation (they were listed only once a mortar pair was created); and
    docs/scenes.md tables both."""
    args = []
    if scene:
        args = SQUARES + ["-contact_pairs", "p", "-contact_p_surfaces", "a:boundary,b:boundary"] + scene
    proc = run_bin(args + ["-help"], tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert option_line(proc.stdout, "-contact_mortar_slave").startswith("-contact_mortar_slave <now auto : formerly auto>")
    assert option_line(proc.stdout, "-contact_mortar_basis").startswith("-contact_mortar_basis <now dual : formerly dual>")
    assert {"-contact_mortar_slave", "-contact_mortar_basis"} <= options_table("docs/scenes.md")
    assert not list(tmp_path.iterdir())


PLATE = ROOT / "tests/meshes/plate.geo"


def test_load_stages_stage_major(tmp_path):
    """-load_stages S: the values are stage-major (x1,y1,x2,y2), as -help's
    text and docs/scenes.md say. A plate held at its bottom, its top moved
    by (0.01, 0) at stage 1's end and (0, -0.02) at stage 2's
    (-a_bc_top_values 0.01,0,0,-0.02): each stage's top displacement, read
    from the HDF5's /stages, is that stage's pair (to 1e-12 of the values:
    imposed, not solved for)."""
    proc = run_bin(["-help", "-bodies", "a", "-a_geo", PLATE], tmp_path)
    for name in ("-load_stages", "-a_bc_<group>_values"):
        assert "stage-major" in option_line(proc.stdout, name) and "x1,y1,x2,y2" in option_line(proc.stdout, name)
    assert "tx1,ty1,tx2,ty2" in option_line(proc.stdout, "-a_load_<group>_traction")
    assert "stage-major" in (ROOT / "docs/scenes.md").read_text()
    r = run_contact(["-bodies", "a", "-a_geo", PLATE, "-a_geo_params", "quads=1", "-a_mesh_size", "0.25",
                     "-a_E", 1, "-a_nu", 0.3, "-a_bc", "bottom,top", "-load_stages", 2,
                     "-a_bc_top_values", "0.01,0,0,-0.02", "-mesh_dir", tmp_path / "m"], tmp_path)
    with r.h5() as f:
        X = f["bodies/a/geometry"][:]
        top = abs(X[:, 1] - 1.0) < 1e-12
        assert top.sum() >= 3
        for k, want in ((1, (0.01, 0.0)), (2, (0.0, -0.02))):
            u = f[f"stages/{k}/bodies/a/displacement"][:]
            for c in range(2):
                assert abs(u[top, c] - want[c]).max() < 1e-12, (k, c, u[top])
