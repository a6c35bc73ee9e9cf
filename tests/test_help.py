"""-help lists the options with the defaults a run uses, and exits with status 0
without meshing, solving or writing anything."""
import re
import subprocess
from pathlib import Path

import pytest

from conftest import BIN, ENV, ROOT

HERTZ = str(ROOT / "meshes/hertz/hertz.opts")


def run(args, cwd):
    return subprocess.run([str(BIN)] + args, cwd=cwd, env=ENV, capture_output=True, text=True, timeout=120)


def option_line(out, name):
    """The -help line of an option (its name followed by a space)."""
    lines = [l.strip() for l in out.splitlines() if l.strip().startswith(name + " ")]
    assert lines, f"{name} not listed"
    return lines[0]


@pytest.mark.parametrize("np", [1, 2])
def test_help_writes_nothing(np, tmp_path):
    """From an empty directory, with the scene's default outputs (out/hertz.*,
    build/meshes/hertz) relative to it and an earlier result given by -output:
    status 0, no solve, nothing created or changed."""
    (tmp_path / "old.h5").write_text("earlier result\n")
    cmd = [str(BIN), "-options_file", HERTZ, "-help"]
    if np > 1:
        cmd = ["mpiexec", "--oversubscribe", "-n", str(np)] + cmd
    proc = subprocess.run(cmd, cwd=tmp_path, env=ENV, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "TAO nls" not in proc.stdout and "Wrote" not in proc.stdout
    assert sorted(p.name for p in tmp_path.iterdir()) == ["old.h5"]
    proc = run(["-options_file", HERTZ, "-help", "-output", str(tmp_path / "old.h5"), "-mesh_dir", str(tmp_path / "m")], tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["old.h5"]
    assert (tmp_path / "old.h5").read_text() == "earlier result\n"


def scene_value(name):
    """The value the scene's options file gives an option."""
    for line in Path(HERTZ).read_text().splitlines():
        words = line.split("#", 1)[0].split()
        if words and words[0] == name:
            return float(words[1])
    raise KeyError(name)


def test_help_required_options(tmp_path):
    """Required options say so and show the scene's value (read here from
    its options file), not a placeholder or a default; the penalty (auto by
    default) shows the scene's value, and the pair's the value it inherits."""
    out = run(["-options_file", HERTZ, "-help"], tmp_path).stdout
    for name in ("-indenter_E", "-block_nu"):
        m = re.match(rf"{name} <(\S+) : required>", option_line(out, name))
        assert m and float(m.group(1)) == scene_value(name), option_line(out, name)
    for name in ("-contact_penalty", "-contact_interface_penalty"):
        m = re.match(rf"{name} <now (\S+) : formerly", option_line(out, name))
        assert m and float(m.group(1)) == scene_value("-contact_penalty"), option_line(out, name)
    assert "(required)" in option_line(out, "-bodies")
    assert "<-1." not in option_line(out, "-contact_penalty")


def test_help_without_scene(tmp_path):
    """Without a scene, a body's and a pair's options under placeholder names."""
    proc = run(["-help"], tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    out = proc.stdout
    assert option_line(out, "-<body>_E").startswith("-<body>_E <required>")
    assert option_line(out, "-contact_penalty").startswith("-contact_penalty <now auto : formerly auto>")
    option_line(out, "-<body>_bc_<group>_values")
    option_line(out, "-contact_<pair>_surfaces")
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("tao", [[], ["-tao_type", "ntr"], ["-tao_type", "lmvm"], ["-tao_max_it", "77"]])
def test_help_defaults_are_used(tao, tmp_path):
    """The maximum iterations and the KSP type -help shows are those of a run
    (TAO's own -tao_view): a default set after the options are listed, or a
    solver's default shown for another, shows as a difference."""
    out = run(["-options_file", HERTZ, "-help"] + tao, tmp_path).stdout
    maxit = int(re.search(r"<now (\d+) :", option_line(out, "-tao_max_it")).group(1))
    assert maxit == {"lmvm": 2000}.get(tao[-1] if tao else "", 77 if "77" in tao else 500)
    view = run(["-options_file", HERTZ, "-mesh_size", "0.3", "-tao_view", "-output", "none", "-summary", "none",
                "-mesh_dir", str(tmp_path / "m")] + tao, ROOT)
    assert view.returncode == 0, view.stderr[-2000:]
    assert f"(max: {maxit})" in view.stdout
    if not tao or tao[-1] != "lmvm":
        prefix = "tao_ntr_" if "ntr" in tao else "tao_nls_"
        ksp = re.search(r"<now (\w+) :", option_line(out, f"-{prefix}ksp_type")).group(1)
        assert re.search(rf"KSP Object: \({prefix}\).*\n\s+type: {ksp}\n", view.stdout), view.stdout[-3000:]
