"""What a run tells the user: the verification scenes' error against their
exact solution in the console report, and `make run`'s list of figures."""
import re
import subprocess

import pytest

from conftest import ENV, ROOT, figure


@pytest.mark.parametrize("scene", ["disc", "square"])
def test_console_reports_l2_error(scene, contact):
    """One line per body with an exact solution: its relative L2 error, the
    JSON summary's l2_error / l2_norm to the printed digits (%.6e: half a unit
    of the last digit is at most 5e-7 relative: `digits` = 3.1e-8 to 3.5e-8),
    and small, as the manufactured solution's at h = 0.2 is: below 1.2e-3
    (`l2_disc` = 0.000439, `l2_square` = 0.000457, over the OpenBLAS kernels
    Prescott, Nehalem, Sandybridge, Haswell and SkylakeX). A report of the
    absolute error, of another body's, or of an error against the wrong exact
    solution fails."""
    r = contact(["-options_file", f"meshes/{scene}/{scene}.opts", "-mesh_size", "0.2"])
    body = r.summary["bodies"][scene]
    lines = re.findall(r"body (\w+): relative L2 error against the exact solution \((\w+)\): (\S+)", r.stdout)
    assert len(lines) == 1 and lines[0][:2] == (scene, body["exact"]), r.stdout
    print(f"{scene}: printed {lines[0][2]}, summary {body['l2_error'] / body['l2_norm']:.6e} ({abs(float(lines[0][2]) / (body['l2_error'] / body['l2_norm']) - 1):.1e})")
    figure("digits", abs(float(lines[0][2]) / (body["l2_error"] / body["l2_norm"]) - 1))
    figure(f"l2_{scene}", body["l2_error"] / body["l2_norm"])
    assert float(lines[0][2]) == pytest.approx(body["l2_error"] / body["l2_norm"], rel=5e-7)
    assert float(lines[0][2]) < 1.2e-3


def test_console_no_l2_error_without_exact_solution(contact):
    """No error line for a body without an exact solution (not a made-up 0)."""
    r = contact(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.3"])
    assert "exact solution" not in r.stdout


@pytest.mark.skipif(not (ROOT / "build/.deps-installed").exists(), reason="make run would install dependencies first")
@pytest.mark.parametrize("scene", ["disc", "hertz", "cattaneo"])
def test_make_run_lists_the_figures_written(scene):
    """The Figures line names the PNGs this run wrote: no pressure plot for a
    scene without contact, no shear plot for one without friction (the
    shear's for cattaneo), and no stale one from before. make run's ARGS
    reach the program (cattaneo in one increment a stage: its JSON's
    stages)."""
    stale = ROOT / "out" / f"{scene}-pressure.png"
    stale.parent.mkdir(exist_ok=True)
    stale.write_bytes(b"stale")
    stale_shear = ROOT / "out" / f"{scene}-shear.png"
    stale_shear.write_bytes(b"stale")
    # the cattaneo scene in one increment a stage (8 by default): the figures
    # listed, not the path, are the point
    args = ["ARGS=-load_steps 1"] if scene == "cattaneo" else []
    proc = subprocess.run(["make", "--no-print-directory", "run", f"SCENE={scene}"] + args, cwd=ROOT, env=ENV,
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    line = [l for l in proc.stdout.splitlines() if l.startswith("Figures:")][-1]
    figures = line.split(";")[0].split()[1:]
    expected = ([f"out/{scene}-pressure.png"] if scene != "disc" else []) \
        + ([f"out/{scene}-shear.png"] if scene == "cattaneo" else []) + [f"out/{scene}-vonmises.png"]
    assert figures == expected, line
    for f in figures:
        assert (ROOT / f).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert stale.exists() == (scene != "disc")
    assert stale_shear.exists() == (scene == "cattaneo")
    if scene == "cattaneo":
        import json
        s = json.loads((ROOT / "out" / "cattaneo.json").read_text())
        # the scene's 8 increments a stage would make at least 16 solves
        assert len(s["load_stages"]) == 2 and s["stages"] < 16, (s["stages"], s["load_stages"])
