"""scripts/check_figures.py: a docstring's quoted figure against the figures
the tests recorded (conftest.figure), on a test file and records of its own."""
import json
import subprocess
import sys

from conftest import ROOT

SCRIPT = ROOT / "scripts" / "check_figures.py"
TEST = '''
def test_a():
    """P apart `dP` = 1.1e-8 to 3.0e-7 over the kernels, the energy `dE` = 2e-15."""


def test_b():
    """Nothing quoted."""
'''


def check(tmp_path, records):
    tests = tmp_path / "tests"
    tests.mkdir(exist_ok=True)
    (tests / "test_x.py").write_text(TEST)
    rec = tmp_path / "r.jsonl"
    rec.write_text("".join(json.dumps({"test": f"tests/test_x.py::{t}", "name": n, "value": v, "kernel": k}) + "\n"
                           for t, n, v, k in records))
    return subprocess.run([sys.executable, str(SCRIPT), "--tests", str(tests), str(rec)], capture_output=True, text=True)


def test_within_factor_passes(tmp_path):
    """Values inside [LO/3, 3 HI] (signs ignored) pass; a parametrised case's
    id is stripped."""
    p = check(tmp_path, [("test_a[1]", "dP", 4e-9, "Prescott"), ("test_a[2]", "dP", -8.9e-7, "Haswell"),
                         ("test_a", "dE", 6e-15, "auto"), ("test_b", "other", 1.0, "auto")])
    assert p.returncode == 0, p.stdout
    assert "2 quoted figures of tests that ran, 0 flagged" in p.stdout


def test_outside_factor_flagged(tmp_path):
    """A value 3.4 times the top of the range, one 3.1 times below its
    bottom, and a quoted figure the test did not record are each flagged."""
    p = check(tmp_path, [("test_a", "dP", 1.02e-6, "Prescott"), ("test_a", "dP", 3.5e-9, "Haswell"),
                         ("test_a", "dE", 2e-15, "auto")])
    assert p.returncode == 1
    flags = [l for l in p.stdout.splitlines() if l.startswith("FLAG")]
    assert len(flags) == 1 and "1.02e-06 (Prescott), 3.5e-09 (Haswell)" in flags[0], p.stdout
    p = check(tmp_path, [("test_a", "dP", 1e-7, "auto")])
    assert p.returncode == 1 and "`dE` = 2e-15: not recorded" in p.stdout, p.stdout


def test_roundoff_checked_above_only(tmp_path):
    """A figure quoted below 1e-9 (`dE` = 2e-15), or a range whose lower end
    is (`dP` = 1.1e-8 to 3.0e-7 is not), is round-off there: a recorded
    value far below it is not flagged, one 3.5 times above it is."""
    p = check(tmp_path, [("test_a", "dP", 1e-7, "auto"), ("test_a", "dE", 1e-18, "Nehalem")])
    assert p.returncode == 0, p.stdout
    p = check(tmp_path, [("test_a", "dP", 1e-7, "auto"), ("test_a", "dE", 7e-15, "Nehalem")])
    assert p.returncode == 1 and "7e-15 (Nehalem)" in p.stdout, p.stdout


def test_not_run_not_flagged(tmp_path):
    """A test with no records did not run: its quotes are not flagged."""
    p = check(tmp_path, [("test_b", "other", 1.0, "auto")])
    assert p.returncode == 0 and "0 quoted figures" in p.stdout, p.stdout


def test_signed_range_spans_zero(tmp_path):
    """A signed range across zero (`e` = -4.9e-7 to 3.9e-7) takes any value
    of smaller magnitude (an order error on either side of 2), not one over
    3 times its larger end."""
    tests = tmp_path / "tests"
    tests.mkdir()
    (tests / "test_y.py").write_text('def test_c():\n    """`e` = -4.9e-7 to 3.9e-7."""\n')
    rec = tmp_path / "r.jsonl"
    rec.write_text(json.dumps({"test": "tests/test_y.py::test_c", "name": "e", "value": 1.1e-8, "kernel": "auto"}) + "\n")
    p = subprocess.run([sys.executable, str(SCRIPT), "--tests", str(tests), str(rec)], capture_output=True, text=True)
    assert p.returncode == 0, p.stdout
    rec.write_text(json.dumps({"test": "tests/test_y.py::test_c", "name": "e", "value": -1.6e-6, "kernel": "auto"}) + "\n")
    p = subprocess.run([sys.executable, str(SCRIPT), "--tests", str(tests), str(rec)], capture_output=True, text=True)
    assert p.returncode == 1, p.stdout
