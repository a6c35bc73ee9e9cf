"""An option that takes a value, given without one (followed by another option,
or last), stops the run with status 1 and one line naming the option, what it
needs and where it was given, for the program's options and PETSc's alike, on
the command line and in an options file; nothing is written. PETSc read such a
number as not given and ran with the default (-tao_gttol -tao_monitor solved to
the default tolerance), and a name as empty (-output alone wrote ".xdmf" and
".tmp" into the current directory). Switches given alone are switches, and
options whose value PETSc makes optional (-tao_monitor, -tao_view) keep their
meaning."""
import json
import os
import subprocess

import pytest

from conftest import BIN, ENV, ROOT

SCENE = ["-options_file", str(ROOT / "meshes/hertz/hertz.opts"), "-mesh_size", "0.3"]
SENTINEL = "earlier result\n"

# (arguments after the scene and the output names, the line expected, refused before meshing)
CASES = {
    "tao_number_then_option": (["-tao_gttol", "-tao_monitor"],
                               "option -tao_gttol needs a number, none given (on the command line, followed by -tao_monitor)", True),
    "tao_number_last": (["-tao_gttol"], "option -tao_gttol needs a number, none given (last on the command line)", True),
    "tao_integer": (["-tao_max_it", "-quiet"], "option -tao_max_it needs an integer, none given (on the command line, followed by -quiet)", True),
    "tao_choice": (["-tao_type"], "option -tao_type needs a known Tao type (lmvm, nls,", False),
    "tao_linesearch_choice": (["-tao_ls_type", "-quiet"], "option -tao_ls_type needs a known TaoLineSearch type (unit, more-thuente", False),
    # read inside PetscInitialize(), before the program's error handler was pushed: PETSc's traceback
    "petsc_initialize_integer": (["-check_pointer_intensity"],
                                 "option -check_pointer_intensity needs an integer, none given (last on the command line)", True),
    "own_number": (["-mesh_size", "-quiet"], "option -mesh_size needs a number, none given (on the command line, followed by -quiet)", True),
    "own_body_number": (["-block_E"], "option -block_E needs a number, none given (last on the command line)", True),
    "own_numbers": (["-contact_interface_hertz_radii"], "option -contact_interface_hertz_radii needs a number, none given", True),
    "own_enum": (["-partitioner"], "option -partitioner needs one of metis, ptscotch, simple, none given (last on the command line)", True),
    "own_name": (["-contact_formulation", "-quiet"], "option -contact_formulation needs a value, none given (on the command line, followed by -quiet)", True),
    "own_number_or_auto": (["-contact_penalty"], "option -contact_penalty needs a value, none given (last on the command line)", True),
    "own_list": (["-block_bc"], "option -block_bc needs a value, none given (last on the command line)", True),
    "own_path": (["-output"], "option -output needs a value, none given (last on the command line)", True),
}


def run_case(args, tmp_path, ranks=1):
    out = tmp_path / "out"
    out.mkdir()
    for f in ("o.h5", "o.xdmf", "o.json"):
        (out / f).write_text(SENTINEL)
    cmd = [str(BIN)] + SCENE + ["-mesh_dir", str(tmp_path / "meshes"), "-output", str(out / "o.h5"),
                                "-summary", str(out / "o.json")] + [str(a) for a in args]
    if ranks > 1:
        cmd = ["mpiexec", "--oversubscribe", "-n", str(ranks)] + cmd
    proc = subprocess.run(cmd, cwd=tmp_path, env=ENV, capture_output=True, text=True, timeout=120)
    lines = [l for l in proc.stderr.splitlines() if l.strip()]
    if ranks > 1:  # mpiexec adds its own lines about the status
        lines = [l for l in lines if l.startswith("contact: ")]
        assert "PETSC ERROR" not in proc.stderr
    assert proc.returncode == 1, f"exit {proc.returncode}\n{proc.stdout[-2000:]}\n{proc.stderr[-2000:]}"
    assert len(lines) == 1 and lines[0].startswith("contact: error: "), proc.stderr[-3000:]
    for f in ("o.h5", "o.xdmf", "o.json"):
        assert (out / f).read_text() == SENTINEL
    assert sorted(os.listdir(out)) == ["o.h5", "o.json", "o.xdmf"], os.listdir(out)
    assert set(os.listdir(tmp_path)) - {"meshes", "extra.opts"} == {"out"}, os.listdir(tmp_path)  # nothing in the current directory
    return lines[0][len("contact: error: "):]


@pytest.mark.parametrize("name", sorted(CASES))
def test_missing_value_command_line(name, tmp_path):
    args, line, before_meshing = CASES[name]
    said = run_case(args, tmp_path)
    assert said.startswith(line), f"{said!r} does not start with {line!r}"
    if before_meshing:
        assert not (tmp_path / "meshes").exists(), "refused only after meshing"


@pytest.mark.parametrize("option, needs", [("-tao_gttol", "a number"), ("-mesh_size", "a number"),
                                           ("-tao_max_funcs", "an integer"), ("-contact_formulation", "a value")])
def test_missing_value_options_file(option, needs, tmp_path):
    """The same in an options file, among switches: the line names the file."""
    opts = tmp_path / "extra.opts"
    opts.write_text(f"-quiet\n{option}\n-newton_iterative\n")
    said = run_case(["-options_file", opts], tmp_path)
    assert said == f"option {option} needs {needs}, none given (in options file {opts})"


def test_missing_value_two_ranks(tmp_path):
    """On two ranks: one line."""
    said = run_case(["-tao_gttol", "-tao_monitor"], tmp_path, ranks=2)
    assert said == CASES["tao_number_then_option"][1]


def solve(tmp_path, name, args):
    proc = subprocess.run([str(BIN)] + SCENE + ["-mesh_dir", str(tmp_path / "meshes"), "-output", "none",
                                                "-summary", str(tmp_path / f"{name}.json")] + args,
                          cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return proc, json.loads((tmp_path / f"{name}.json").read_text())


def test_switches_alone(tmp_path):
    """Switches given alone are true, as before, and options whose value is
    optional keep their meaning: -newton_iterative alone takes CG steps (CG
    iterations counted, P equal to -newton_iterative true's to 1e-12),
    -tao_monitor alone prints one line per iteration and -tao_view the
    solver, -quiet alone silences the progress lines (-progress on)."""
    alone, s_alone = solve(tmp_path, "alone", ["-progress", "-newton_iterative", "-tao_monitor", "-tao_view", "-quiet"])
    given, s_given = solve(tmp_path, "given", ["-progress", "-newton_iterative", "true", "-quiet", "true"])
    assert "CG iterations" in alone.stdout and "CG iterations" in given.stdout
    assert abs(s_alone["contact_force"] / s_given["contact_force"] - 1) <= 1e-12
    monitor = [l for l in alone.stdout.splitlines() if "TAO,  Function value" in l]
    assert len(monitor) == s_alone["iterations"] + 1, alone.stdout[-2000:]
    assert "Tao Object:" in alone.stdout
    assert not alone.stderr.strip() and not given.stderr.strip()
