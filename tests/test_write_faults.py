"""A write that fails for want of room stops the run with one line naming the
file and the cause, status 1, and changes nothing: the earlier results of the
same names stay byte for byte and no temporary or lock is left.

The disk is a small tmpfs (mounted by the test: it runs as root, where a
read-only directory does not stop a write), filled by a file of zeros so that
the room left runs out in the HDF5 file or in the JSON summary, or is less
than the room a run holds for the HDF5 file (then the run stops before
meshing): the room left is counted in the tmpfs's pages, from the page of the
lock file, the reserve and the sizes of the earlier run's files, which the
second run writes again (same scene, same names). The XDMF file is written by
the summary's code, into the reserve (it is not reached by filling)."""
import hashlib
import os
import subprocess

import pytest

from conftest import BIN, ENV, ROOT

HERTZ = ["-options_file", str(ROOT / "meshes/hertz/hertz.opts"), "-mesh_size", "0.2",
         "-mesh_dir", str(ROOT / "build/meshes/hertz"), "-quiet"]
SET = ("h.h5", "h.xdmf", "h.json")
# the room a run holds for a failed HDF5 write to close its file (src/io/outputset.c,
# OUTPUT_RESERVE: 1 MiB), in the tmpfs's 4 KiB pages
RESERVE_PAGES = (1 << 20) // 4096


@pytest.fixture
def small_disk(tmp_path):
    """A 4 MiB tmpfs, unmounted afterwards."""
    d = tmp_path / "disk"
    d.mkdir()
    mount = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=4m", "tmpfs", str(d)], capture_output=True, text=True)
    if mount.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs to fill (needs root): {mount.stderr.strip()}")
    try:
        yield d
    finally:
        subprocess.run(["umount", str(d)], check=True)


def run(d, extra=()):
    cmd = [str(BIN)] + HERTZ + ["-output", str(d / "h.h5"), "-summary", str(d / "h.json")] + list(extra)
    return subprocess.run(cmd, cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=300)


def digests(d):
    return {n: hashlib.sha256((d / n).read_bytes()).hexdigest() for n in SET}


def fill(d, pages):
    """Fills the disk but for `pages` pages."""
    st = os.statvfs(d)
    free = st.f_bavail * st.f_frsize
    with open(d / "filler", "wb") as f:
        f.write(b"\0" * (free - pages * st.f_frsize))
    st = os.statvfs(d)
    assert st.f_bavail == pages, (st.f_bavail, pages)


# (extra options of the second run, pages left for it, the file its line names, the line's prefix):
# the HDF5 file finds no room; the summary finds none (no HDF5 file, no reserve); the disk has
# not the reserve, found before meshing
CASES = {
    "h5": ([], 1 + RESERVE_PAGES, "h.h5", "contact: error: cannot write"),
    "json": (["-output", "none"], 1, "h.json", "contact: error: cannot write"),
    "no_reserve": ([], RESERVE_PAGES, "h.h5", "contact: error: option -output: cannot write"),
}


@pytest.mark.parametrize("case", CASES)
def test_full_disk_one_line(case, small_disk):
    """The room runs out: one line "contact: error: cannot write <file>: No
    space left on device", status 1, the earlier set unchanged byte for byte,
    nothing else left (no temporary, no lock)."""
    extra, room, fails, prefix = CASES[case]
    d = small_disk
    first = run(d)
    assert first.returncode == 0, first.stderr
    before = digests(d)
    fill(d, room)
    second = run(d, extra)
    lines = [l for l in second.stderr.splitlines() if l.strip()]
    assert second.returncode == 1, second.stderr[-3000:]
    assert lines == [f"{prefix} {d / fails}: No space left on device"], second.stderr[-3000:]
    assert digests(d) == before
    assert sorted(os.listdir(d)) == sorted(SET + ("filler",))
    if case == "no_reserve":
        assert "Wrote" not in second.stdout and "TAO" not in second.stdout, "solved before finding the disk full"


def test_full_disk_two_ranks(small_disk):
    """On 2 ranks, parallel HDF5 fails inside a collective call on the rank
    whose write found no room while the other waits in it (measured: a hang).
    The room the HDF5 file needs is checked before it is written (its
    bodies' datasets and 1 MiB, src/driver/results.c): the disk that makes
    the HDF5 write fail on 1 rank gives the one line on 2 ranks, within the
    timeout, status nonzero, the earlier set unchanged, nothing left."""
    d = small_disk
    first = run(d)
    assert first.returncode == 0, first.stderr
    before = digests(d)
    fill(d, 1 + RESERVE_PAGES)
    cmd = ["mpiexec", "-n", "2", str(BIN)] + HERTZ + ["-output", str(d / "h.h5"), "-summary", str(d / "h.json")]
    second = subprocess.run(cmd, cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=120)
    ours = [l for l in second.stderr.splitlines() if l.startswith("contact")]
    assert second.returncode != 0, second.stderr[-3000:]
    assert ours == [f"contact: error: cannot write {d / 'h.h5'}: No space left on device"], second.stderr[-3000:]
    assert digests(d) == before
    assert sorted(os.listdir(d)) == sorted(SET + ("filler",))


def test_room_enough_writes(small_disk):
    """The control: with the reserve and the pages the whole set takes (and
    the lock's), the second run writes its set over the first (so the count
    of pages above is right)."""
    d = small_disk
    first = run(d)
    assert first.returncode == 0, first.stderr
    before = digests(d)
    page = os.statvfs(d).f_frsize
    fill(d, 1 + RESERVE_PAGES + sum(-(-(d / n).stat().st_size // page) for n in SET))
    second = run(d)
    assert second.returncode == 0 and not second.stderr.strip(), second.stderr[-3000:]
    after = digests(d)
    assert all(after[n] != before[n] for n in SET)  # a new run id in every file
    assert sorted(os.listdir(d)) == sorted(SET + ("filler",))
