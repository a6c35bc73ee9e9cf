"""The configuration (src/solver/config.c): every concern's options read by
one function in the concern's own file, in its own options block, so that
-help lists each option once, with its default, under its concern's heading
(GROUPS: the headings and the options each must hold, written here from the
option names, not read from the program); a bad value of any concern's
option still stops the run before anything is meshed, with status 1 and one
line naming the option; and -config_view prints the values in force: the
ones given, and -help's defaults for the rest.

The scene is the plate of test_setup_checks.py (tests/meshes/plate.geo,
Quad9, h = 0.25, on rollers), of which these tests mesh at most one."""
import re
import subprocess

import pytest

from conftest import BIN, ENV, ROOT

GROUPS = {
    "Contact scene options": ["scene", "bodies", "axisymmetric", "mesh_size", "max_dofs", "mesh_dir"],
    "Partitioning options": ["partitioner", "partition_view"],
    "L-BFGS options": ["lmvm_h0", "lmvm_h0_refresh", "lmvm_restarts", "lmvm_decrement_rtol", "lmvm_decrement_floor", "lmvm_pair_ratio"],
    "Taylor test options": ["taylor_test", "taylor_scale"],
    "Newton step options": ["newton_iterative", "newton_iterative_dofs", "newton_iterative_nodal", "newton_iterative_two_levels", "newton_iterative_cycle", "newton_schur", "newton_schur_surface_dofs", "newton_schur_split_lu", "newton_schur_type", "tangent_at_rest", "tangent_at_rest_its"],
    "Load stepping options": ["load_steps", "load_stages", "load_cutbacks", "load_path"],
    "Penalty continuation options": ["penalty_stages", "penalty_start"],
    "Stopping options": ["stage_rtol", "stop_force_rtol"],
    "Friction lag options": ["contact_friction_lag_rtol", "contact_friction_lag_max_it"],
    "Force control options": ["force_control_type", "force_control_max_it", "force_control_rtol", "force_control_step", "force_control_border_solves"],
    "Contact Hessian options": ["contact_hessian", "contact_hessian_switch"],
    "Configuration options": ["config_view"],
}

PLATE = ["-scene", "plate", "-bodies", "plate", "-plate_geo", "tests/meshes/plate.geo", "-plate_geo_params", "L=2,H=1,quads=1",
         "-plate_mesh_size", "0.25", "-plate_E", "1000", "-plate_nu", "0.3",
         "-plate_bc_bottom_components", "y", "-plate_bc_left_components", "x"]


def run(args, tmp_path):
    cmd = [str(BIN)] + PLATE + [str(a) for a in args] + ["-output", str(tmp_path / "o.h5"), "-summary", str(tmp_path / "o.json"),
                                                         "-mesh_dir", str(tmp_path / "meshes")]
    return subprocess.run(cmd, cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=120)


def sections(out):
    """-help's sections: heading -> the option lines under it, in order."""
    secs, cur = {}, None
    for line in out.splitlines():
        if line.endswith(":") and not line.startswith(" "):
            cur = line[:-1]
            secs.setdefault(cur, [])
        elif cur and re.match(r"\s+-\w", line):
            secs[cur].append(line.strip())
    return secs


def option_name(line):
    return re.match(r"-([\w<>]+)", line).group(1)


@pytest.fixture(scope="module")
def help_out(tmp_path_factory):
    p = run(["-help"], tmp_path_factory.mktemp("help"))
    assert p.returncode == 0, p.stderr[-2000:]
    return p.stdout


def test_help_groups(help_out):
    """Each heading is listed, holds exactly its concern's options (none lost,
    none from another concern), and each of them appears exactly once in the
    whole of -help, with a default shown."""
    secs = sections(help_out)
    for heading, names in GROUPS.items():
        assert heading in secs, f"no heading {heading!r}"
        assert [option_name(l) for l in secs[heading]] == names, (heading, secs[heading])
        for line in secs[heading]:
            assert "<" in line and ">" in line, f"no default shown: {line}"
    every = [option_name(l) for lines in secs.values() for l in lines]
    for names in GROUPS.values():
        for n in names:
            assert every.count(n) == 1, f"-{n} listed {every.count(n)} times"


# one bad value of each concern's options: (option, value)
BAD = [("mesh_size", "0"), ("partitioner", "nosuch"), ("lmvm_h0_refresh", "0"), ("taylor_scale", "0"),
       ("newton_iterative_dofs", "-1"), ("tangent_at_rest_its", "-1"), ("load_stages", "0"), ("penalty_start", "2"),
       ("stage_rtol", "1"), ("contact_friction_lag_max_it", "0"), ("force_control_type", "nosuch"),
       ("contact_hessian_switch", "2"), ("config_view", "maybe")]


def test_bad_values_cover_every_concern():
    """BAD holds an option of every concern."""
    concern = {n: h for h, names in GROUPS.items() for n in names}
    assert {concern[n] for n, _ in BAD} == set(GROUPS)


@pytest.mark.parametrize("name,value", BAD, ids=[n for n, _ in BAD])
def test_bad_value_stops(name, value, tmp_path):
    """Status 1, one line `contact: error: ...` naming the option, before
    anything is meshed or written."""
    p = run([f"-{name}", value], tmp_path)
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    assert p.returncode == 1, f"-{name} {value}: exit {p.returncode}\n{p.stdout[-1500:]}\n{p.stderr[-1500:]}"
    assert len(lines) == 1 and lines[0].startswith("contact: error: "), p.stderr[-2000:]
    assert f"-{name}" in lines[0], lines[0]
    assert sorted(x.name for x in tmp_path.iterdir()) == []


def help_default(line):
    """The default -help shows for an option (None where it shows a sentence)."""
    m = re.search(r"<now (\S+) : formerly", line) or re.search(r"<(\S+) : \S+>", line)
    return m.group(1) if m else None


def same_value(a, b):
    try:
        return float(a) == float(b)
    except ValueError:
        return a.lower() == b.lower()


def test_config_view(help_out, tmp_path):
    """-config_view (with -mesh_only: nothing solved) prints each concern's
    options once: the values given as given, "auto" for those the solver
    chooses where not given, and -help's default for every other."""
    given = {"load_steps": "3", "penalty_start": "0.25", "lmvm_h0": "elastic", "contact_hessian": "exact",
             "stop_force_rtol": "1e-07", "newton_schur": "false", "contact_friction_lag_max_it": "7"}
    args = ["-config_view", "-mesh_only"] + [x for k, v in given.items() for x in (f"-{k}", v)]
    p = run(args, tmp_path)
    assert p.returncode == 0, p.stderr[-2000:]
    view = p.stdout[p.stdout.index("Configuration:"):]
    shown = dict(re.findall(r" -(\w+) (\S+)", view))
    defaults = {option_name(l): help_default(l) for lines in sections(help_out).values() for l in lines}
    for names in GROUPS.values():
        for n in names:
            if n == "config_view":
                continue
            assert len(re.findall(rf" -{n} ", view)) == 1, f"-{n} not shown once:\n{view}"
            if n in given:
                assert same_value(shown[n], given[n]), (n, shown[n], given[n])
            elif n == "bodies":
                assert shown[n] == "plate"
            elif n == "mesh_dir":
                assert shown[n] == str(tmp_path / "meshes")
            elif shown[n] != "auto" and defaults.get(n) is not None:
                assert same_value(shown[n], defaults[n]), (n, shown[n], defaults[n])
    for n in ("penalty_stages", "lmvm_decrement_rtol", "newton_iterative", "tangent_at_rest"):
        assert shown[n] == "auto", (n, shown[n])
