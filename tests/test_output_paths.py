"""Fail fast: the output paths are checked and their temporaries created before
meshing, so a path that cannot be written stops the run in a second, naming
the option and the directory; of the missing directories only the default
out/ is created."""
import os
import subprocess

import pytest

from conftest import BIN, ENV, ROOT

HERTZ = ["-options_file", str(ROOT / "meshes/hertz/hertz.opts")]


@pytest.mark.parametrize("case", ["output_dir", "summary_dir", "output_under_file", "summary_is_dir", "out_subdir"])
def test_output_path_fails_before_meshing(case, tmp_path):
    """A path that cannot be written stops the run before meshing (no mesh
    generated, no file left), naming the option and the directory."""
    (tmp_path / "afile").write_text("x")
    mesh_dir = tmp_path / "meshes"
    args, cause = {
        "output_dir": (["-output", tmp_path / "no/such/out.h5"], f"option -output: cannot write {tmp_path}/no/such/out.h5: directory {tmp_path}/no/such does not exist"),
        "summary_dir": (["-summary", tmp_path / "nodir/s.json"], f"option -summary: cannot write {tmp_path}/nodir/s.json: directory {tmp_path}/nodir does not exist"),
        "output_under_file": (["-output", tmp_path / "afile/out.h5"], f"{tmp_path}/afile is not a directory"),
        "summary_is_dir": (["-summary", tmp_path], f"option -summary: {tmp_path} is a directory"),
        "out_subdir": (["-output", "out/sub/x.h5"], "directory out/sub does not exist"),
    }[case]
    cmd = [str(BIN)] + HERTZ + ["-mesh_size", "0.0123", "-mesh_dir", str(mesh_dir), "-output", str(tmp_path / "o.h5"),
                                "-summary", str(tmp_path / "o.json")] + [str(a) for a in args]
    proc = subprocess.run(cmd, cwd=tmp_path, env=ENV, capture_output=True, text=True, timeout=120)
    lines = [l for l in proc.stderr.splitlines() if l.strip()]
    assert proc.returncode == 1 and len(lines) == 1 and cause in lines[0], proc.stderr
    assert not mesh_dir.exists(), "meshed before checking the outputs"
    assert sorted(os.listdir(tmp_path)) == ["afile"], os.listdir(tmp_path)


def test_default_out_created(tmp_path):
    """The default outputs go to out/, created if missing (from any directory)."""
    proc = subprocess.run([str(BIN)] + HERTZ + ["-mesh_size", "0.2", "-mesh_dir", str(ROOT / "build/meshes/hertz")],
                          cwd=tmp_path, env=ENV, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert sorted(os.listdir(tmp_path / "out")) == ["hertz.h5", "hertz.json", "hertz.xdmf"]
