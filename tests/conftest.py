"""Helpers shared by the tests: run bin/contact on a scene and read its JSON
summary and HDF5 output."""
import inspect
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
# A rank waiting for another yields its core (mpi_yield_when_idle; Open MPI sets
# it by itself only when there are more ranks than cores): otherwise it polls,
# and on 2 cores shared by the suite's workers a 2-rank run burnt 2 to 6 times
# the CPU of its 1-rank twin, taken from the other workers (the roller by force
# at h = 0.04, load 8: 24 to 28 s of CPU polling, 11 to 15 s yielding, 4.4 s on
# one rank). Set in os.environ, so that every process a test starts has it.
os.environ.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
# The suite runs on one machine: shared memory (ob1 over vader) is all the
# transport it needs. Open MPI's default probes UCX first, whose start
# calibrates a clock for 0.2 s: measured on a run that stops at a bad value,
# 158 ms of CPU and 0.41 s of wall with the default, 123 ms and 0.19 s with
# ob1. (A singleton kept from forking its daemon, ess_singleton_isolated, saves
# as much again, but such singletons share one session directory, which one
# removes while another writes its MPI-IO file there.) Only the transport
# changes, not a figure: the suite's rank comparisons hold as before.
for _k, _v in (("OMPI_MCA_pml", "ob1"), ("OMPI_MCA_btl", "self,vader")):
    os.environ.setdefault(_k, _v)
# HWLOC_COMPONENTS: mpiexec's hardware discovery without its OpenGL component,
# which probes every X display, the tests' own virtual ones included, and dies
# with one that shuts down meanwhile (the program sets it for itself: main.c)
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", HWLOC_COMPONENTS=os.environ.get("HWLOC_COMPONENTS", "-gl"))


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


# GetFEM (python3-getfem), an independent code the squeeze and the friction
# are compared with, runs under the system's interpreter
GETFEM_PYTHON = "/usr/bin/python3"


def getfem_available():
    return os.path.exists(GETFEM_PYTHON) and subprocess.run([GETFEM_PYTHON, "-c", "import getfem"],
                                                            capture_output=True).returncode == 0


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


def info_args(tmp_path, name, classes="sys"):
    """-info into a file per rank (NAME.info.RANK in tmp_path; PETSc's info
    classes as -info takes them): on a shared stdout two ranks'
    block-buffered lines can interleave mid-line, and a line a test looks
    for is lost (one run of the Nehalem kernel's under load)."""
    return ["-info", f"{tmp_path}/{name}.info:{classes}"]


def info_text(tmp_path, name):
    """Every rank's -info lines of info_args(tmp_path, name), rank by rank."""
    return "".join(p.read_text() for p in sorted(Path(tmp_path).glob(f"{name}.info*")))


# A figure a test measured, recorded by name: printed (pytest -s, or a
# failure's captured output shows it) and, where CONTACT_FIGURES names a file,
# appended to it as one JSON line {"test", "name", "value", "kernel"}.
# make test-kernels (scripts/test_kernels.py) records every kernel's figures
# and prints their ranges; make check-figures (scripts/check_figures.py)
# compares each figure a docstring quotes as `name` = VALUE (or `name` = LO to
# HI) with the figures recorded, flagging a factor over 3. A figure's name is
# local to its test function (parametrised cases share the docstring).
def check_program_figures(name):
    """Build bin/<name> (a kernel check program) and run it: its output lines
    are whitespace-separated keys then a value, read as {keys: value} (the
    keys a tuple)."""
    subprocess.run(["make", "-s", "bin/" + name], cwd=ROOT, check=True, capture_output=True)
    out = subprocess.run([str(ROOT / "bin" / name)], cwd=ROOT, check=True, capture_output=True, text=True).stdout
    fig = {}
    for line in out.splitlines():
        *keys, value = line.split()
        fig[tuple(keys)] = float(value)
    return fig


def figure(name, value):
    value = float(value)
    test = os.environ.get("PYTEST_CURRENT_TEST", "?").split(" ")[0]
    print(f"figure {name} = {value:.6g}")
    path = os.environ.get("CONTACT_FIGURES")
    if path:
        rec = {"test": test, "name": name, "value": value, "kernel": os.environ.get("OPENBLAS_CORETYPE", "auto")}
        with open(path, "a") as f:
            f.write(json.dumps(rec) + "\n")
    return value


def is_force_key(k):
    """Whether a flattened summary key is a force or a reaction component
    (the top level's, a pair's, a surface's, a load stage's): compared
    against a floor of the pair's force, since a component that cancels
    (y in the reference scene) is round-off relative to itself."""
    d = f".{k}."
    return ".force." in d or ".reactions." in d or ".contact_force." in d or k.endswith(("force.0", "force.1"))


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
# once per session for the tests that read them (test_mortar).
HALF_MORTAR_H = (0.1, 0.06, 0.03, 0.015)
# The finest, h = 0.007 (462,642 dofs, 12 to 15 s), is not solved in the
# suite: its profile and figures are committed (HALF_MORTAR_REF, written by
# tests/data/half_mortar_reference.py, the command recorded in the file), and
# test_mortar.py::test_reference_is_fresh (make stress) solves it again and
# compares.
HALF_MORTAR_FINE = 0.007
HALF_MORTAR_REF = ROOT / "tests" / "data" / "half-mortar-h0.007.json"


def half_mortar_args(h):
    """The half scene with mortar at mesh size h, solved to -tao_gttol 1e-12."""
    return ["-options_file", "meshes/hertz-half/hertz-half.opts", "-contact_formulation", "mortar",
            "-mesh_size", str(h), "-tao_gttol", "1e-12"]


class HalfMortarReference:
    """The committed h = 0.007 run: summary (P, the energy, p_max, fem_a, dofs,
    gradient_norm) and the indenter's profile (s, p, w, gap) as
    profile_metrics.profiles gives it."""
    def __init__(self, path=HALF_MORTAR_REF):
        import numpy as np
        d = json.loads(Path(path).read_text())
        self.args, self.kernel, self.summary = d["args"], d["kernel"], d["summary"]
        c = d["indenter_contact"]
        self.profile = tuple(np.array(c[k]) for k in ("s", "pressure", "weight", "gap"))


@pytest.fixture
def half_mortar_reference():
    """The committed reference (function-scoped: reading it is cheap, and a
    session scope would put its readers in one xdist group)."""
    return HalfMortarReference()


@pytest.fixture(scope="session")
def half_mortar_runs(tmp_path_factory):
    """Each run of HALF_MORTAR_H by h; a run that fails is kept (check=False)
    and fails the tests that read it, not the others. Solved to -tao_gttol
    1e-12, where Newton ends at round-off on whatever path the machine's
    rounding gives it (at the default 1e-8 the paths of OpenBLAS's kernels
    stopped 2.4e-8 apart in P at h = 0.005)."""
    tmp = tmp_path_factory.mktemp("half-mortar")
    return {h: run_contact(half_mortar_args(h), tmp, name=f"h{h}", timeout=900, check=False) for h in HALF_MORTAR_H}



# `make test` runs the suite on both cores (pytest-xdist, -n 2 --dist
# loadgroup). A test that uses a module- or session-scoped fixture of this
# directory (the runs a module shares, half_mortar_runs,
# the X server of test_paraview) runs on the worker that runs every other test
# using that fixture, so that each is computed once, as in a serial run; the
# other tests are handed out one by one. Each worker has its own basetemp, so
# tmp_path and tmp_path_factory never meet across workers.
#
# The groups are worked out where the tests are collected, in the workers,
# and reach the scheduler in the controller through a file named in each
# worker's workerinput: xdist's own loadgroup passes its xdist_group marks as
# a suffix of the test's node id, which pytest 9.2's node ids no longer take
# (pytest-xdist issue 1386: every test is then scheduled alone). The
# scheduler below is loadgroup's (xdist's LoadScopeScheduling with a scope
# per group), fed from that file; explicit xdist_group marks are kept.
GROUPS_INPUT = "contact_groups_file"


def _shared_fixtures(item):
    """Group keys of the module- and session-scoped fixtures of tests/ that
    item uses: its module's name for a module scope, the fixture's name for a
    session scope."""
    here = Path(__file__).resolve().parent
    keys = set()
    for name in item.fixturenames:
        for fdef in item._fixtureinfo.name2fixturedefs.get(name, ()):
            scope = getattr(fdef.scope, "value", fdef.scope)
            try:
                src = Path(inspect.getsourcefile(fdef.func)).resolve()
            except TypeError:
                continue
            if src.parent == here and scope in ("module", "session"):
                keys.add(item.module.__name__ if scope == "module" else name)
    return keys


def xdist_groups(items):
    """{node id: group} of the tests that share a fixture (above) or carry
    an xdist_group mark; keys met in one test are merged (union-find), so a
    test using two shared fixtures joins every test that uses either."""
    parent = {}

    def find(k):
        while parent.setdefault(k, k) != k:
            k = parent[k]
        return k

    keyed = []
    for item in items:
        keys = sorted(_shared_fixtures(item) | {"mark:" + str(m.args[0] if m.args else m.kwargs.get("name", "default"))
                                                 for m in item.iter_markers("xdist_group")})
        for k in keys[1:]:
            parent[find(k)] = find(keys[0])
        keyed.append((item.nodeid, keys))
    return {nodeid: find(keys[0]) for nodeid, keys in keyed if keys}


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(config, items):
    """In a worker of a loadgroup run: writes the groups for the scheduler
    (every worker collects the same tests and writes the same file)."""
    path = getattr(config, "workerinput", {}).get(GROUPS_INPUT)
    if path:
        tmp = Path(f"{path}.{os.getpid()}")
        tmp.write_text(json.dumps(xdist_groups(items)))
        tmp.replace(path)


def pytest_configure(config):
    if not hasattr(config, "workerinput") and config.pluginmanager.hasplugin("xdist") \
            and config.getoption("dist", "no") == "loadgroup" and config.getoption("numprocesses"):
        import tempfile
        config.contact_groups_dir = Path(tempfile.mkdtemp(prefix="contact-xdist-"))


def pytest_unconfigure(config):
    d = getattr(config, "contact_groups_dir", None)
    if d:
        import shutil
        shutil.rmtree(d, ignore_errors=True)


@pytest.hookimpl(optionalhook=True)
def pytest_configure_node(node):
    d = getattr(node.config, "contact_groups_dir", None)
    if d:
        node.workerinput[GROUPS_INPUT] = str(d / "groups.json")


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_make_scheduler(config, log):
    d = getattr(config, "contact_groups_dir", None)
    if not d:
        return None
    from xdist.scheduler import LoadScopeScheduling

    class SharedFixtureScheduling(LoadScopeScheduling):
        """One work unit per group of the workers' file, one per test
        elsewhere. Called once every worker has collected (schedule()), so
        the file is complete; without it every test is its own unit."""
        groups = None

        def _split_scope(self, nodeid):
            if self.groups is None:
                try:
                    self.groups = json.loads((d / "groups.json").read_text())
                except (OSError, ValueError):
                    self.groups = {}
            return self.groups.get(nodeid, nodeid)

    return SharedFixtureScheduling(config, log)
