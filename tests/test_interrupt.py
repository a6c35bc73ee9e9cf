"""Interrupted runs: a run killed part-way (while it meshes, solves, or writes
its files) leaves the earlier results intact and no temporary file behind, and
says in one line in which phase it was interrupted (status 130 for SIGINT, 143
for SIGTERM).

The temporaries are created empty before meshing (the output set is checked
and locked then); the write window is caught by polling the output directory
for a temporary file with content and signalling the process as soon as one
appears. Either way no temporary file and no lock file is left."""
import json
import re
import os
import signal
import subprocess
import time

import pytest

from conftest import BIN, ENV, ROOT

SENTINEL = "earlier result\n"
NAMES = ("out.h5", "out.xdmf", "out.json")


def size(path):
    try:
        return path.stat().st_size
    except FileNotFoundError:  # renamed meanwhile
        return 0


def start(tmp_path, h, *extra):
    for f in NAMES:
        (tmp_path / f).write_text(SENTINEL)
    cmd = [str(BIN), "-options_file", "meshes/hertz/hertz.opts", "-mesh_size", str(h),
           "-output", str(tmp_path / "out.h5"), "-summary", str(tmp_path / "out.json")] + list(extra)
    return subprocess.Popen(cmd, cwd=ROOT, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def check_outcome(proc, tmp_path, phase=r"[\w -]+"):
    """Either finished (all files new and complete) or killed in the phase
    named (all files as before). -progress lines are not the error line."""
    rc = proc.wait(timeout=300)
    left = sorted(os.listdir(tmp_path))
    assert left == sorted(NAMES), f"files left behind: {left}"
    if rc == 0:
        import h5py
        with h5py.File(tmp_path / "out.h5", "r") as f:
            assert "bodies" in f
        json.loads((tmp_path / "out.json").read_text())
        return False
    err = proc.stderr.read()
    lines = [l for l in err.splitlines() if l.strip() and not l.startswith("contact: [")]
    # SIGINT: 130, SIGTERM: 143, and one line naming the phase, no PETSc dump
    assert rc in (130, 143), f"exit {rc}: {err[-2000:]}"
    assert len(lines) == 1 and re.fullmatch(rf"contact: interrupted during {phase}; no output written", lines[0]), err
    for f in NAMES:
        assert (tmp_path / f).read_text() == SENTINEL, f"{f} changed by a killed run"
    return True


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_killed_while_writing(sig, tmp_path):
    hit = False
    for attempt in range(5):
        d = tmp_path / f"a{attempt}"
        d.mkdir()
        proc = start(d, 0.04)
        while proc.poll() is None:
            if any(n.endswith(".tmp") and size(d / n) > 0 for n in os.listdir(d)):
                proc.send_signal(sig)
                break
            time.sleep(0.0005)
        hit = check_outcome(proc, d, "the output") or hit
        if hit:
            break
    assert hit, "the write was never interrupted in 5 attempts"


def test_killed_while_solving(tmp_path):
    """SIGTERM once the run reports its first Newton iteration (-progress; the
    solve at h = 0.02 takes 8 or more): no waiting on the clock, so a faster
    or slower machine signals in the same phase, which the line must name."""
    proc = start(tmp_path, 0.02, "-progress")
    for line in proc.stderr:
        if "solve: iteration   1," in line:
            proc.send_signal(signal.SIGTERM)
            break
    else:
        pytest.fail("the run ended without reporting its first Newton iteration")
    assert check_outcome(proc, tmp_path, "the solve")


@pytest.mark.parametrize("sig,status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_interrupted_while_meshing(sig, status, tmp_path):
    """Ctrl-C while Gmsh runs is not lost (the program waits for Gmsh itself,
    not through system(), which ignores SIGINT): Gmsh is stopped, its partial
    mesh removed, and the one line names the phase."""
    mesh_dir = tmp_path / "meshes"
    cmd = [str(BIN), "-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.006", "-mesh_dir", str(mesh_dir),
           "-output", str(tmp_path / "out.h5"), "-summary", str(tmp_path / "out.json")]
    proc = subprocess.Popen(cmd, cwd=ROOT, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 60
    while time.time() < deadline and not (mesh_dir.exists() and any(p.suffix == ".log" for p in mesh_dir.iterdir())):
        time.sleep(0.01)
    proc.send_signal(sig)  # Gmsh runs: its log is there, its mesh at h = 0.006 takes seconds
    rc = proc.wait(timeout=120)
    err = proc.stderr.read()
    assert rc == status, err
    assert err.strip() == "contact: interrupted during meshing; no output written", err
    assert not [p for p in mesh_dir.iterdir() if p.suffix == ".msh"], list(mesh_dir.iterdir())
    assert not (tmp_path / "out.h5").exists() and not (tmp_path / "out.json").exists()
