"""Bad values, the whole class: every option of the program that -help lists
is given invalid values of its kind, and each must stop the run with status 1
and one line naming the option. The domain of every option is declared here
(DOMAINS); an option that -help lists without one fails the completeness test,
so that a new option is classified when it is added. PETSc's own options
(-tao_*, -ksp_*, ...) are PETSc's.

The values of a kind (bad_values: a number non-numeric, NaN, Inf, -Inf and,
where its domain excludes them, below its least; an integer non-integer and
below its least; a fraction or a unit interval's number outside it; a choice
an unknown name; a switch neither true nor false) make 306 cases, all run by
`make stress`. `make test` runs a pairwise selection of them (FAST, 101 runs),
one run per bad value, since the program stops at the first:

- every option at least once, with a value its own check must refuse (own_values:
  NaN, Inf, the edge of its domain; an integer below its least; an unknown
  name; a non-boolean). The options of a kind take these classes in turn, the
  same option of the two bodies (block_E, indenter_E: one line of body.c) and
  a pair's option beside the global one (contact_interface_friction,
  contact_friction) one after the other so that they take different classes;
  a kind with fewer options than classes gives its options a second run, so
  that every class of every kind is run at least once;
- the values a shared parser refuses before any option's check, once per
  parser (PARSERS): "abc" through PETSc's real (PetscOptionsReal and the
  program's ContactOptionsRealNoDefault, both PetscOptionsGetReal), its real
  arrays and the program's penalty parser (auto or a number); "abc" and "2.5"
  through its integer parser. The error handler turns each into the option's
  line in one place (ParseValueError), the same for every option.

Left to `make stress`: below an option's least by more than the edge (-Inf,
-1e300, -1, -0.5 and 1.5 for a fraction: refused by the comparison the edge
tests), a non-number given to the other options of a parser, and an option's
other own classes (mesh_size runs Inf here, its 0 and NaN in stress)."""
import re
import subprocess

import pytest

from conftest import BIN, ENV, ROOT

SCENE = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.3", "-contact_formulation", "mortar"]

# (kind, least valid value or None, whether the least is excluded)
REAL_POS = ("real", 0.0, True)        # > 0
REAL_NONNEG = ("real", 0.0, False)    # >= 0
REAL_ANY = ("real", None, False)      # any finite number
DOMAINS = {
    "mesh_size": REAL_POS, "max_dofs": ("real", 1.0, False), "taylor_scale": REAL_POS, "penalty_start": REAL_POS, "stage_rtol": REAL_POS, "stop_force_rtol": ("unit",),
    "contact_hessian_switch": REAL_NONNEG, "load_steps": ("int", 1, False), "load_stages": ("int", 1, False), "load_cutbacks": ("int", 0, False), "penalty_stages": ("int", 1, False),
    "contact_penalty": REAL_POS, "contact_blend": REAL_NONNEG, "contact_quadrature_points": ("int", 3, False),
    "contact_interface_penalty": REAL_POS, "contact_interface_mirror_y": REAL_ANY,
    "contact_friction": REAL_NONNEG, "contact_interface_friction": REAL_NONNEG,
    "contact_friction_penalty": REAL_POS, "contact_interface_friction_penalty": REAL_POS,
    "contact_friction_lag_rtol": ("fraction",), "contact_friction_lag_max_it": ("int", 1, False),
    "contact_interface_hertz_radii": ("reals", 0.0, False),
    "indenter_mesh_size": REAL_POS, "block_mesh_size": REAL_POS,
    "indenter_E": REAL_POS, "block_E": REAL_POS, "indenter_nu": ("real", -1.0, True), "block_nu": ("real", -1.0, True),
    "indenter_quadrature_degree": ("int", 1, False), "block_quadrature_degree": ("int", 1, False),
    "indenter_bc_clamp_values": ("reals", None, False), "block_bc_push_values": ("reals", None, False),
    "indenter_exact_params": ("reals", None, False), "block_exact_params": ("reals", None, False),
    "partitioner": ("choice",), "lmvm_h0": ("choice",), "lmvm_h0_refresh": ("int", 1, False),
    "lmvm_restarts": ("int", 0, False), "tangent_at_rest_its": ("int", 0, False), "newton_iterative_dofs": ("int", 0, False), "newton_schur_split_lu": ("int", 1, False), "newton_schur_surface_dofs": ("int", 0, False), "lmvm_pair_ratio": ("real", 1.0, False), "lmvm_decrement_floor": ("real", 1.0, False), "lmvm_decrement_rtol": REAL_NONNEG, "contact_hessian": ("choice",),
    "contact_formulation": ("choice",), "contact_interface_formulation": ("choice",),
    "contact_mortar_basis": ("choice",), "contact_mortar_slave": ("choice",),
    "indenter_exact": ("choice",), "block_exact": ("choice",), "indenter_material": ("choice",), "block_material": ("choice",),
    "mesh_only": ("bool",), "config_view": ("bool",), "progress": ("bool",), "quiet": ("bool",), "output_wait": ("bool",),
    "partition_view": ("bool",), "load_path": ("bool",), "tangent_at_rest": ("bool",), "newton_iterative": ("bool",), "newton_iterative_nodal": ("bool",), "newton_iterative_two_levels": ("bool",), "newton_iterative_cycle": ("choice",), "newton_schur_type": ("choice",), "taylor_test": ("bool",), "axisymmetric": ("bool",), "newton_schur": ("bool",), "contact_disable": ("bool",),
    "indenter_bc_clamp_exact": ("bool",), "block_bc_push_exact": ("bool",),
    "indenter_rigid": ("bool",), "block_rigid": ("bool",),
    "indenter_rigid_centre": ("reals", None, False), "block_rigid_centre": ("reals", None, False),
    "indenter_rigid_rotation": REAL_ANY, "block_rigid_rotation": REAL_ANY,
    "indenter_rigid_moment": ("reals", None, False), "block_rigid_moment": ("reals", None, False),
    # names, paths and lists of names: their own tests (test_bad_input.py, test_scene_files.py)
    "contact_interface_symmetry": ("name",),  # planes of a 3D pair: test_sphere3d.py::test_symmetry_refused
    "scene": ("name",), "bodies": ("name",), "mesh_dir": ("name",), "output": ("name",), "summary": ("name",),
    "indenter_geo": ("name",), "block_geo": ("name",), "indenter_mesh": ("name",), "block_mesh": ("name",),
    "indenter_geo_params": ("name",), "block_geo_params": ("name",), "indenter_bc": ("name",), "block_bc": ("name",),
    "indenter_bc_clamp_components": ("name",), "block_bc_push_components": ("name",),
    "contact_pairs": ("name",), "contact_interface_surfaces": ("name",),
    "accuracy": ("fraction",), "accuracy_max_dofs": ("real", 1.0, False), "accuracy_max_steps": ("int", 3, False),
    "accuracy_grading": REAL_POS, "accuracy_bulk": ("unit",), "accuracy_warm_start": ("bool",),
    "force_control_max_it": ("int", 1, False), "force_control_rtol": ("fraction",),
    "force_control_type": ("choice",), "force_control_step": REAL_POS, "force_control_border_solves": ("bool",),
    # a list of choices and lists of group names: their own tests (test_force_control.py, test_loads.py)
    "indenter_bc_clamp_control": ("name",), "block_bc_push_control": ("name",),
    "indenter_load": ("name",), "block_load": ("name",),
    # -help's placeholder -<body>_load_<group>_traction, _pressure for a load the scene has not (read up
    # to the "<"; a real group's values: test_loads.py)
    "indenter_load_": ("name",), "block_load_": ("name",),
}
# the sections of -help that are the program's own
SECTIONS = ("Program options", "Output options", "Progress options", "Contact scene options", "Body options", "Rigid body options",
            "Dirichlet condition", "Body loads", "Load on a boundary group", "Contact options", "Contact pair options",
            "Mortar contact options", "Accuracy options",
            # the configuration's concerns (src/solver/config.c)
            "Partitioning options", "L-BFGS options", "Taylor test options", "Newton step options", "Load stepping options",
            "Penalty continuation options", "Stopping options", "Friction lag options", "Force control options",
            "Contact Hessian options", "Configuration options")


def program_options():
    """The options -help lists in the program's own sections."""
    p = subprocess.run([str(BIN)] + SCENE + ["-help"], cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, p.stderr
    names, own = set(), False
    for line in p.stdout.splitlines():
        if line.endswith(":") and not line.startswith(" "):
            own = line[:-1] in SECTIONS
        elif own:
            m = re.match(r"\s+-(\w+)", line)
            if m:
                names.add(m.group(1))
    return names


def test_every_option_classified():
    """Every program option -help lists has a declared domain."""
    names = program_options()
    assert names, "no program options parsed from -help"
    missing = sorted(names - set(DOMAINS))
    assert not missing, f"options without a declared domain: {missing}"


def bad_values(kind):
    k = kind[0]
    if k == "real":
        least, strict = kind[1], kind[2]
        out = ["abc", "nan", "inf", "-inf"]
        if least is not None:
            out += [repr(least) if strict else repr(least - 1.0), "-1e300"]
            if least == 0.0 and strict:
                out.append("-1")
        return out
    if k == "reals":
        least = kind[1]
        out = ["abc", "nan", "1,inf"]
        if least is not None:
            out.append(repr(least - 1.0))
        return out
    if k == "int":
        return ["abc", "2.5", str(kind[1] - 1)]
    if k == "fraction":  # in (0, 1)
        return ["abc", "nan", "inf", "0", "1", "-0.5", "1.5"]
    if k == "unit":  # in [0, 1]
        return ["abc", "nan", "inf", "-0.5", "1.5"]
    if k == "choice":
        return ["nosuch"]
    if k == "bool":
        return ["maybe"]
    return []


CASES = [(name, v) for name, kind in sorted(DOMAINS.items()) for v in bad_values(kind)]


def own_values(kind):
    """The classes of bad values that reach an option's own check (past the
    parser): non-finite, the edge of its domain, an unknown name."""
    k = kind[0]
    if k == "real":
        least, strict = kind[1], kind[2]
        if least is None:
            return ["nan", "inf", "-inf"]
        return ["nan", "inf", repr(least) if strict else repr(least - 1.0)]
    if k == "reals":
        return ["nan", "1,inf"] + ([repr(kind[1] - 1.0)] if kind[1] is not None else [])
    if k == "int":
        return [str(kind[1] - 1)]
    if k == "fraction":
        return ["nan", "inf", "0", "1"]
    if k == "unit":
        return ["nan", "inf", "-0.5", "1.5"]
    return bad_values(kind)  # choice, bool: the one class


# A value a shared parser refuses, once per parser (the docstring)
PARSERS = [("mesh_size", "abc"), ("contact_friction", "abc"), ("block_bc_push_values", "abc"),
           ("contact_penalty", "abc"), ("load_steps", "abc"), ("load_steps", "2.5")]


def base_name(name):
    """block_E and indenter_E, contact_interface_friction and
    contact_friction side by side in a kind's order."""
    return re.sub(r"^(block|indenter)_", "", name).replace("contact_interface_", "contact_")


def fast_cases():
    """The selection make test runs (the docstring): per kind, its options
    (in base_name order) take its own classes in turn until every option and
    every class has run; then PARSERS."""
    kinds = {}
    for name, kind in DOMAINS.items():
        if own_values(kind):
            kinds.setdefault(kind, []).append(name)
    fast = set()
    for kind, names in kinds.items():
        names.sort(key=lambda n: (base_name(n), n))
        own = own_values(kind)
        for i in range(max(len(names), len(own))):
            fast.add((names[i % len(names)], own[i % len(own)]))
    return fast | set(PARSERS)


FAST = fast_cases()


@pytest.fixture(scope="module")
def mesh_dir(tmp_path_factory):
    """One mesh cache for the module: a value checked after meshing costs Gmsh once."""
    return tmp_path_factory.mktemp("meshes")


def test_selection_within_the_class():
    """Every case make test runs is one of the whole class's (a value of
    own_values or PARSERS that bad_values no longer lists would run only
    here), and every option with bad values is among them."""
    assert FAST <= set(CASES), sorted(FAST - set(CASES))
    assert {n for n, _ in CASES} == {n for n, _ in FAST}


# CASES, those not in FAST marked stress
MARKED = [pytest.param(n, v, marks=() if (n, v) in FAST else pytest.mark.stress, id=f"{n}={v}") for n, v in CASES]


@pytest.mark.parametrize("name,value", MARKED)
def test_bad_value(name, value, tmp_path, mesh_dir):
    """Status 1, one line naming the option, no output: a value taken
    silently (atof's 0 for "abc", a NaN that propagates, a negative size that
    meshes forever) or a PETSc trace instead of the line fails it."""
    cmd = [str(BIN)] + SCENE + [f"-{name}", value, "-output", str(tmp_path / "o.h5"), "-summary",
                                str(tmp_path / "o.json"), "-mesh_dir", str(mesh_dir)]
    p = subprocess.run(cmd, cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=120)
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    assert p.returncode == 1, f"-{name} {value}: exit {p.returncode}\n{p.stdout[-1500:]}\n{p.stderr[-1500:]}"
    assert len(lines) == 1 and lines[0].startswith("contact: error: "), p.stderr[-2000:]
    assert f"-{name}" in lines[0] or (name.startswith("contact_interface_") and "-contact_" in lines[0]), lines[0]
    assert not (tmp_path / "o.h5").exists() and not (tmp_path / "o.json").exists()
