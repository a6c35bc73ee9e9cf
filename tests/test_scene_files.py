"""Scene files: a relative path in an options file is relative to that file's
folder, one on the command line to the current directory, so that a scene runs
from any directory; a .geo file that ignores the mesh size h gets a warning."""
import json
import os
import shutil
import subprocess

import pytest

from conftest import BIN, ENV, ROOT

COARSE = ["-mesh_size", "0.3"]


def run(args, cwd, timeout=300):
    return subprocess.run([str(BIN)] + [str(a) for a in args], cwd=cwd, env=ENV, capture_output=True, text=True,
                          timeout=timeout)


@pytest.mark.parametrize("scene", ["hertz", "hertz-small", "disc", "sphere3d"])
def test_scene_runs_from_another_directory(scene, tmp_path):
    """The scene's file named by an absolute path and by a path relative to the
    current directory, from a directory outside the repository: its .geo files
    (beside it, or ../hertz/ for hertz-small) are found, and the default outputs
    (out/<scene>.*, build/meshes/<scene>/) are written relative to the current
    directory."""
    opts = ROOT / "meshes" / scene / f"{scene}.opts"
    for i, name in enumerate([opts, os.path.relpath(opts, tmp_path)]):
        cwd = tmp_path / f"run{i}"
        cwd.mkdir()
        proc = run(["-options_file", name if i == 0 else os.path.join("..", name)] + COARSE, cwd)
        assert proc.returncode == 0, proc.stderr[-3000:]
        assert (cwd / "out" / f"{scene}.json").exists() and (cwd / "out" / f"{scene}.h5").exists()
        assert list((cwd / "build" / "meshes" / scene).glob("*.msh"))
    a, b = (json.loads((tmp_path / f"run{i}/out/{scene}.json").read_text()) for i in (0, 1))
    assert a["energy"] == b["energy"]


def test_paths_in_options_file_relative_to_it(tmp_path):
    """An options file in a folder of its own includes the scene by a relative
    path and names its outputs and a .geo relatively: all are taken beside it,
    while the program runs elsewhere; the same names on the command line are
    taken in the current directory."""
    case = tmp_path / "case"
    case.mkdir()
    shutil.copy(ROOT / "meshes/hertz/block.geo", case / "myblock.geo")
    scene = os.path.relpath(ROOT / "meshes/hertz/hertz.opts", case)
    (case / "run.opts").write_text(f"-options_file {scene}\n-block_geo myblock.geo\n"
                                   "-output result.h5\n-summary result.json\n-mesh_dir meshes\n")
    cwd = tmp_path / "elsewhere"
    cwd.mkdir()
    proc = run(["-options_file", "../case/run.opts"] + COARSE, cwd)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert (case / "result.h5").exists() and (case / "result.json").exists()
    assert [p.name.split("-")[0] for p in sorted((case / "meshes").glob("*.msh"))] == ["indenter", "myblock"]
    assert not list(cwd.iterdir())
    # on the command line: relative to the current directory
    shutil.copy(ROOT / "meshes/hertz/block.geo", cwd / "cmdblock.geo")
    proc = run(["-options_file", "../case/run.opts", "-block_geo", "cmdblock.geo", "-summary", "cmd.json"] + COARSE, cwd)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert (cwd / "cmd.json").exists()
    assert json.loads((cwd / "cmd.json").read_text())["bodies"]["block"]["mesh"].split("/")[-1].startswith("cmdblock-")


def test_geo_without_mesh_size_warns(tmp_path):
    """A .geo whose sizes are fixed numbers (h defined but unused, and named
    only in a comment and a string) meshes, with one warning line. (It reads
    the scene's geometry parameters x0, W, H: one it never used would be an
    error, test_bad_input.py.)"""
    geo = tmp_path / "fixed.geo"
    geo.write_text("""// A block meshed at a fixed size; the size h is not used
If (!Exists(h)) h = 0.1; EndIf
If (!Exists(x0)) x0 = 0; EndIf If (!Exists(W)) W = 1; EndIf If (!Exists(H)) H = 2; EndIf
Point(1) = {x0, -H/2, 0, 0.25}; Point(2) = {x0 + W, -H/2, 0, 0.25}; Point(3) = {x0 + W, H/2, 0, 0.25}; Point(4) = {x0, H/2, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Recombine Surface{1};
Physical Curve("contact") = {4}; Physical Curve("push") = {2}; Physical Surface("body") = {1};
Printf("h is not used"); /* h */
Mesh.ElementOrder = 2; Mesh.SecondOrderIncomplete = 0; Mesh.MshFileVersion = 2.2;
""")
    args = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_only", "-mesh_dir", tmp_path / "m"] + COARSE
    proc = run(args + ["-block_geo", geo], ROOT)
    assert proc.returncode == 0, proc.stderr
    lines = [l for l in proc.stderr.splitlines() if l.strip()]
    assert len(lines) == 1 and lines[0].startswith("contact: warning: ") and "fixed.geo never uses the mesh size h" in lines[0]
    proc = run(args, ROOT)  # the scene's own .geo files use h
    assert proc.returncode == 0 and not proc.stderr.strip(), proc.stderr
