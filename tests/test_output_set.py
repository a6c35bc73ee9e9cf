"""The outputs of a run are one set: locked for the run (a second run on the
same names stops at once naming the first, or waits with -output_wait; a lock
left by a run that is gone is taken over), carrying one run id (HDF5
/metadata:run_id, JSON run_id, a comment in the XDMF file)."""
import json
import os
import re
import subprocess

import h5py
from conftest import BIN, ENV, ROOT

HERTZ = ["-options_file", str(ROOT / "meshes/hertz/hertz.opts")]
SET = ("out.h5", "out.xdmf", "out.json")


def command(d, h, *extra):
    return [str(BIN)] + HERTZ + ["-mesh_size", str(h), "-output", str(d / "out.h5"),
                                 "-summary", str(d / "out.json")] + list(extra)


def run_ids(d):
    """The run id each file of the set carries."""
    with h5py.File(d / "out.h5", "r") as f:
        h5 = f["metadata"].attrs["run_id"]
        h5 = h5.decode() if isinstance(h5, bytes) else str(h5)
        nodes = len(f["bodies/indenter/geometry"])
    xdmf = (d / "out.xdmf").read_text()
    m = re.search(r"<!-- contact run_id (\S+) -->", xdmf)
    assert m, xdmf[:200]
    # the XDMF file describes this HDF5 file (not another run's mesh)
    assert re.search(rf'Dimensions="{nodes} 2"[^>]*>out.h5:/bodies/indenter/geometry<', xdmf)
    return {"h5": h5, "json": json.loads((d / "out.json").read_text())["run_id"], "xdmf": m.group(1)}


def test_one_run_id_per_set(tmp_path):
    """The three files carry one run id and describe one mesh (a file renamed
    from another run's temporary, or a stale XDMF, would not), and neither the
    lock nor a temporary is left."""
    proc = subprocess.run(command(tmp_path, 0.2), cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    ids = run_ids(tmp_path)
    assert len(set(ids.values())) == 1, ids
    assert sorted(os.listdir(tmp_path)) == sorted(SET)  # no lock, no temporary left


class HeldLock:
    """The set's lock held by this test as a run holds it (a line naming this
    process, flock()ed), so that another run meets a live holder for as long
    as the test wants: no race with a first run's speed. Released as a run
    releases it: unlinked while still flocked, then closed."""

    def __init__(self, d):
        import fcntl
        self.path = d / "out.lock"
        self.fd = os.open(self.path, os.O_RDWR | os.O_CREAT | os.O_EXCL, 0o644)
        fcntl.flock(self.fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        os.write(self.fd, f"pid={os.getpid()} host={os.uname().nodename} run_id=held-by-test\n".encode())

    def release(self):
        os.unlink(self.path)
        os.close(self.fd)


def test_second_run_stops_at_once(tmp_path):
    """A run on names another run holds stops before it meshes, with one line
    naming the holder (its pid and run id) and -output_wait, writes nothing,
    and leaves the holder's lock alone."""
    lock = HeldLock(tmp_path)
    try:
        second = subprocess.run(command(tmp_path, 0.2, "-progress"), cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=300)
        lines = [l for l in second.stderr.splitlines() if l.strip() and not l.startswith("contact: [")]
        assert second.returncode == 1 and len(lines) == 1, second.stderr
        assert lines[0].startswith("contact: error: ") and f"pid {os.getpid()} " in lines[0] and "held-by-test" in lines[0], lines[0]
        assert "-output_wait" in lines[0]
        assert "set-up" not in second.stderr, second.stderr  # it stopped in the first phase, before meshing
        assert sorted(os.listdir(tmp_path)) == ["out.lock"]
        assert "held-by-test" in (tmp_path / "out.lock").read_text()
    finally:
        lock.release()


def test_second_run_waits(tmp_path):
    """With -output_wait a run waits while another holds the set, then writes
    its own whole set over the earlier one (its mesh, its run id in every
    file)."""
    first = subprocess.run(command(tmp_path, 0.2), cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=300)
    assert first.returncode == 0, first.stderr
    first_nodes = json.loads((tmp_path / "out.json").read_text())["bodies"]["indenter"]["nodes"]
    lock = HeldLock(tmp_path)
    second = subprocess.Popen(command(tmp_path, 0.1, "-output_wait"), cwd=ROOT, env=ENV, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)
    try:
        line = second.stderr.readline()  # blocks until the run says it waits (or ends)
        assert line.startswith("contact: waiting: ") and f"pid {os.getpid()} " in line, line
    finally:
        lock.release()
    out, err = second.communicate(timeout=600)
    assert second.returncode == 0, err
    ids = run_ids(tmp_path)
    assert set(ids.values()) == {ids["json"]} and ids["json"].endswith(f"-{second.pid}"), ids
    summary = json.loads((tmp_path / "out.json").read_text())
    with h5py.File(tmp_path / "out.h5", "r") as f:
        nodes = len(f["bodies/indenter/geometry"])
    assert nodes == summary["bodies"]["indenter"]["nodes"] != first_nodes  # the second run's mesh, h = 0.1
    assert sorted(os.listdir(tmp_path)) == sorted(SET)


def test_stale_lock_taken_over(tmp_path):
    """A lock left by a run that is gone (killed by SIGKILL) is taken over."""
    dead = subprocess.Popen(["true"])
    dead.wait()
    (tmp_path / "out.lock").write_text(f"pid={dead.pid} host={os.uname().nodename} run_id=gone\n")
    (tmp_path / "out.h5.tmp").write_text("half-written\n")
    proc = subprocess.run(command(tmp_path, 0.2), cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert "took over" in proc.stderr and f"pid={dead.pid}" in proc.stderr, proc.stderr
    assert len(set(run_ids(tmp_path).values())) == 1
    assert sorted(os.listdir(tmp_path)) == sorted(SET)


def test_killed_run_lock_taken_over(tmp_path):
    """A run killed by SIGKILL (no handler runs) leaves its lock; the next run
    takes it over, naming the dead holder's pid, and writes its whole set. The
    kill is sent once the first run reports its first Newton iteration
    (-progress), when it holds the lock: no waiting on the clock."""
    run = subprocess.Popen(command(tmp_path, 0.02, "-progress"), cwd=ROOT, env=ENV, stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, text=True)
    seen = []
    for line in run.stderr:
        seen.append(line)
        if "solve: iteration   1," in line:
            run.kill()
            break
    run.wait()
    assert run.returncode == -9, f"the first run was not killed while solving (exit {run.returncode}):\n{''.join(seen)[-3000:]}"
    assert (tmp_path / "out.lock").exists()
    proc = subprocess.run(command(tmp_path, 0.2), cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0 and f"pid={run.pid}" in proc.stderr, proc.stderr
    assert len(set(run_ids(tmp_path).values())) == 1
    assert sorted(os.listdir(tmp_path)) == sorted(SET)


def test_lock_of_another_host_kept(tmp_path):
    """A lock whose holder names another host cannot be checked from here (its
    process is not ours to see, and flock does not cross hosts on every file
    system), so it counts as held: the run stops at once (status 1) with one
    line naming the holder's pid, host and run id and saying how to proceed;
    the lock and the earlier results are left as they were. Its neighbour,
    the same lock naming this host and a process that is gone, is taken over
    (test_stale_lock_taken_over)."""
    line = "pid=4242 host=another-host.example run_id=far\n"
    (tmp_path / "out.lock").write_text(line)
    for f in SET:
        (tmp_path / f).write_text("earlier result\n")
    proc = subprocess.run(command(tmp_path, 0.2), cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=300)
    lines = [ln for ln in proc.stderr.splitlines() if ln.strip()]
    assert proc.returncode == 1, proc.stderr
    assert len(lines) == 1 and lines[0].startswith("contact: error: "), lines
    for part in ("pid 4242 on host another-host.example", "run id far", "cannot be checked", "remove the lock"):
        assert part in lines[0], lines[0]
    assert (tmp_path / "out.lock").read_text() == line
    for f in SET:
        assert (tmp_path / f).read_text() == "earlier result\n", f
    assert sorted(os.listdir(tmp_path)) == sorted(SET + ("out.lock",))
