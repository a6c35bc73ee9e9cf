"""Helpers shared by the tests: run bin/contact on a scene and read its JSON
summary and HDF5 output."""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
# the scripts' modules (profile_metrics, accuracy_study, ...) importable by every test
sys.path.insert(0, str(ROOT / "scripts"))
# CONTACT_BIN: another build of the program (make check-sanitize: bin/contact-sanitize)
BIN = Path(os.environ.get("CONTACT_BIN", ROOT / "bin" / "contact"))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


class RunResult:
    def __init__(self, proc, summary_path, output_path):
        self.returncode = proc.returncode
        self.stdout = proc.stdout
        self.stderr = proc.stderr
        self.summary_path = summary_path
        self.output_path = output_path
        self.summary = None
        if proc.returncode == 0 and summary_path.exists():
            self.summary = json.loads(summary_path.read_text())

    def h5(self):
        import h5py
        return h5py.File(self.output_path, "r")


def run_contact(args, tmp_path, ranks=1, name="run", timeout=600, check=True, env=None):
    """Runs bin/contact from the repository root with outputs in tmp_path
    (env: variables added to the environment)."""
    summary = Path(tmp_path) / f"{name}.json"
    output = Path(tmp_path) / f"{name}.h5"
    cmd = [str(BIN)] + [str(a) for a in args] + ["-summary", str(summary), "-output", str(output)]
    if ranks > 1:
        cmd = ["mpiexec", "--oversubscribe", "-n", str(ranks)] + cmd
    proc = subprocess.run(cmd, cwd=ROOT, env=dict(ENV, **(env or {})), capture_output=True, text=True, timeout=timeout)
    res = RunResult(proc, summary, output)
    if check and proc.returncode != 0:
        raise AssertionError(f"{' '.join(cmd)} exited {proc.returncode}:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}")
    return res


def lookup(summary, key):
    """Value of a dotted key ("bodies.block.max_displacement") in a summary."""
    v = summary
    for part in key.split("."):
        v = v[part]
    return v


@pytest.fixture
def contact(tmp_path):
    def _run(args, **kw):
        return run_contact(args, tmp_path, **kw)
    return _run


# The mirrored half of the reference scene with mortar at these mesh sizes, run
# once per session for the tests that read them (test_mortar, test_verification).
HALF_MORTAR_H = (0.1, 0.06, 0.03, 0.015, 0.005)


@pytest.fixture(scope="session")
def half_mortar_runs(tmp_path_factory):
    """Each run of HALF_MORTAR_H by h; a run that fails is kept (check=False)
    and fails the tests that read it, not the others. Solved to -tao_gttol
    1e-12, where Newton ends at round-off on whatever path the machine's
    rounding gives it (at the default 1e-8 the paths of OpenBLAS's kernels
    stopped 2.4e-8 apart in P at h = 0.005; the finest run takes 14
    iterations instead of 12)."""
    tmp = tmp_path_factory.mktemp("half-mortar")
    return {h: run_contact(["-options_file", "meshes/hertz-half/hertz-half.opts", "-contact_formulation", "mortar",
                            "-mesh_size", str(h), "-tao_gttol", "1e-12"], tmp, name=f"h{h}", timeout=900, check=False)
            for h in HALF_MORTAR_H}
