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
