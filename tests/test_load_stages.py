"""A load history (-load_stages S, src/body/history.c, src/solver/staging.c,
src/driver/stages.c): every -<body>_bc_<group>_values, _traction and _pressure
gives S end values per component, each stage ramps linearly from the last
one's end, and each stage's end is written (JSON load_stages, HDF5 /stages,
XDMF time steps).

The references are independent of the staging: an elastic frictionless
problem has one equilibrium per load (its energy is convex in the reference
scene's range), so whatever path reaches a load ends where a single solve
at that load does, and unloading to nothing returns the bodies to rest.
The comparisons of two runs are marked roundoff: each run stops at its own
tolerance on a path the machine's rounding chooses."""
import json
import shutil
import subprocess

import h5py
import numpy as np
import pytest

from conftest import ENV, ROOT, figure, run_contact

HERTZ = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.1"]
PUSH = 0.15


def staged(push, clamp_stages=None):
    """The reference scene with the push's x given per stage (y 0), the clamp 0 at every stage."""
    n = len(push)
    args = HERTZ + ["-block_bc_push_values", ",".join(f"{u!r},0" for u in push)]
    if n > 1:
        args += ["-load_stages", n, "-indenter_bc_clamp_values", ",".join(["0,0"] * n)]
    return args


def disp(res, group="/bodies"):
    """Each body's nodal displacement in the run's HDF5 file, under group (/bodies or /stages/k/bodies)."""
    with h5py.File(res.output_path, "r") as f:
        return {b: f[f"{group}/{b}/displacement"][:] for b in ("indenter", "block")}


def field_diff(a, b):
    return max(np.abs(a[k] - b[k]).max() for k in a)


@pytest.fixture(scope="module")
def one(tmp_path_factory):
    """The single solve at the push 0.15."""
    return run_contact(staged([-PUSH]), tmp_path_factory.mktemp("one"))


@pytest.mark.roundoff
def test_one_stage_is_today(one, tmp_path):
    """-load_stages 1 is the run without it, bit for bit (same JSON figures).
    Its P is the one the same scene solved to -tao_gttol 1e-12 gives, to
    what the default stop leaves (measured `dP` = 2.9e-11 over the five
    kernels, bound 1e-8: the stop 1e-8 of the gradient at rest, where
    Newton's last quadratic step lands far below it). And a regression pin:
    P = 55.03693 to 5e-6, the README's quick-start force (the report printed
    before load stages existed, 7 digits; a copy of the program's output,
    not an independent reference). Its load_stages has the one stage, whose
    reactions are the run's."""
    s1 = run_contact(staged([-PUSH]) + ["-load_stages", 1], tmp_path, name="stages1").summary
    tight = run_contact(staged([-PUSH]) + ["-tao_gttol", "1e-12"], tmp_path, name="tight").summary
    s0 = one.summary
    for key in ("energy", "contact_force", "max_displacement", "iterations", "reactions"):
        assert s1[key] == s0[key], (key, s0[key], s1[key])
    dP = figure("dP", abs(s0["contact_force"] / tight["contact_force"] - 1))
    print(f"P = {s0['contact_force']!r}, at -tao_gttol 1e-12 {tight['contact_force']!r}")
    assert dP < 1e-8
    assert abs(s0["contact_force"] - 55.03693) < 5e-6, "regression pin: the README's quick-start P"
    (st,) = s0["load_stages"]
    assert st["load"] == 1 and st["reactions"] == s0["reactions"]
    assert abs(np.hypot(*st["contact_force"]["interface"]) - s0["contact_force"]) <= 1e-12 * s0["contact_force"]


@pytest.mark.roundoff
def test_two_stages_path_independent(one, tmp_path):
    """0 -> d/2 -> d ends where the single solve at d does, to the solves'
    stop (-tao_gttol 1e-8: the gradient 1e-8 of its norm at rest, where
    each stage's end stops too): `dR` = 1.3e-12 of P in the push's
    reaction and `du` = 6.9e-11 of d in the displacement field on each of
    the five kernels, bound 1e-8. Its first stage's end is the single solve
    at d/2 (`dR1` = 0, `du1` = 0: the same solve)."""
    r = run_contact(staged([-PUSH / 2, -PUSH]), tmp_path, name="two")
    half = run_contact(staged([-PUSH / 2]), tmp_path, name="half")
    s, P = r.summary, one.summary["contact_force"]
    dR = abs(s["reactions"]["block:push"][0] - one.summary["reactions"]["block:push"][0]) / P
    du = field_diff(disp(r), disp(one)) / PUSH
    du1 = field_diff(disp(r, "/stages/1/bodies"), disp(half)) / PUSH
    dR1 = abs(s["load_stages"][0]["reactions"]["block:push"][0] - half.summary["reactions"]["block:push"][0]) / P
    for k, v in (("dR", dR), ("du", du), ("dR1", dR1), ("du1", du1)):
        figure(k, v)
    assert dR < 1e-8 and du < 1e-8 and dR1 < 1e-8 and du1 < 1e-8
    assert [st["load"] for st in s["load_stages"]] == [1, 2]


@pytest.mark.roundoff
def test_beyond_and_back(one, tmp_path):
    """0 -> 2d -> d (the contact zone grows past the final one, then recedes)
    ends where the single solve at d does: `dR` = 9.0e-13 to 9.1e-13 of P
    in the reaction and `du` = 1.2e-11 of d in the displacement over the
    five kernels, bound 1e-8 as above. The force at 2d is above twice P at
    d (`F1` = 130.28 against `P` = 55.04): the contact stiffens as its zone
    widens."""
    r = run_contact(staged([-2 * PUSH, -PUSH]), tmp_path)
    P = one.summary["contact_force"]
    dR = abs(r.summary["reactions"]["block:push"][0] - one.summary["reactions"]["block:push"][0]) / P
    du = field_diff(disp(r), disp(one)) / PUSH
    F1 = abs(r.summary["load_stages"][0]["reactions"]["block:push"][0])
    for k, v in (("dR", dR), ("du", du), ("F1", F1), ("P", P)):
        figure(k, v)
    assert dR < 1e-8 and du < 1e-8
    assert F1 > 2 * P


@pytest.mark.roundoff
def test_cutback_within_stages(one, tmp_path):
    """The automatic cutback works inside a history: 0 -> 2d -> d with at
    most 3 energy evaluations per line search (-tao_ls_max_funcs 3) fails
    a load on every kernel, goes back to the last converged one and halves
    the step (`cutbacks` = 1 on each of the five kernels, at least one
    asserted), and still ends where the single solve at d does (`dR` =
    9.3e-13 of P, bound 1e-8: the solves' stop)."""
    s = run_contact(staged([-2 * PUSH, -PUSH]) + ["-tao_ls_max_funcs", 3], tmp_path).summary
    dR = abs(s["reactions"]["block:push"][0] - one.summary["reactions"]["block:push"][0]) / one.summary["contact_force"]
    figure("cutbacks", s["load_cutbacks"])
    figure("dR", dR)
    print(f"{s['stages']} stages")
    assert s["load_cutbacks"] >= 1 and dR < 1e-8


@pytest.mark.roundoff
def test_unload_returns_to_rest(tmp_path):
    """0 -> d -> 0 on the reference scene: at the end the bodies are at
    rest, to what the stop (-tao_gttol 1e-8) leaves: the largest
    displacement `umax` = 1.2e-10 of d = 0.15, the reactions `R` = 9.1e-11
    of P (the loaded stage's push reaction) on each of the five
    kernels, bounds 4e-10 of d and of P. The contact force is what that
    displacement allows: the bodies touch without overlap at rest, so no
    point penetrates by more than twice the largest displacement, and the
    force is at most k_p times that over the contact surfaces' length
    (2 pi / 3 of the disc's arc and the block's edge 2); measured `Pc` =
    0 to 3.5e-3 of that bound over the five kernels (0 where no point
    penetrates). The HDF5's stage 2 is the final state, stage 1 the loaded one
    (its largest displacement d, the pushed edge's, to 1e-12)."""
    r = run_contact(staged([-PUSH, 0.0]), tmp_path)
    s = r.summary
    P = abs(s["load_stages"][0]["reactions"]["block:push"][0])
    R = max(abs(v) for g in s["reactions"].values() for v in g)
    umax = figure("umax", s["max_displacement"] / PUSH)
    figure("R", R / P)
    kp = s["contact"]["interface"]["penalty"]
    bound = kp * 2 * s["max_displacement"] * (2 * np.pi / 3 + 2)
    Pc = figure("Pc", s["contact_force"] / bound if bound > 0 else s["contact_force"])
    print(f"max displacement {s['max_displacement']:.2e}, reactions {R:.2e} (P = {P:.4f}), "
          f"contact force {s['contact_force']:.2e} (bound {bound:.2e})")
    assert umax < 4e-10 and R < 4e-10 * P
    assert Pc <= 1
    u1, u2 = disp(r, "/stages/1/bodies"), disp(r, "/stages/2/bodies")
    assert abs(max(np.abs(u).max() for u in u1.values()) - PUSH) < 1e-12
    assert field_diff(u2, disp(r)) == 0


def force_run(forces, tmp_path, name, ranks=1):
    n = len(forces)
    args = HERTZ + ["-block_bc_push_control", "force,displacement", "-force_control_rtol", "1e-11",
                    "-block_bc_push_values", ",".join(f"{F!r},0" for F in forces)]
    if n > 1:
        args += ["-load_stages", n, "-indenter_bc_clamp_values", ",".join(["0,0"] * n)]
    return run_contact(args, tmp_path, name=name, ranks=ranks).summary


@pytest.mark.roundoff
def test_force_control_stages(tmp_path):
    """The push's x by force, -20 -> -40 and -80 -> -40: each stage's end
    carries its own force (the reaction is the force given, to 1e-11 of it:
    -force_control_rtol), and the last ends at the push the single solve by
    -40 finds: `dU` = 0 to 6.0e-16 of it over the five kernels and both
    histories, bound 1e-8 (the solves' stop)."""
    one = force_run([-40.0], tmp_path, "one")
    U = one["force_control"][0]["displacement"]
    for forces in ([-20.0, -40.0], [-80.0, -40.0]):
        s = force_run(forces, tmp_path, "stages")
        got = [st["reactions"]["block:push"][0] for st in s["load_stages"]]
        dU = figure("dU", abs(s["force_control"][0]["displacement"] - U) / abs(U))
        print(f"{forces}: reactions {got}, U {s['force_control'][0]['displacement']!r} ({dU:.1e} of U)")
        assert all(abs(g - F) <= 1e-11 * abs(F) for g, F in zip(got, forces))
        assert dU < 1e-8


@pytest.mark.roundoff
def test_pressure_stages_linear(tmp_path):
    """The tube's bore pressure in two stages, 20 then 10: a linear body's
    displacement is linear in the pressure, so stage 1's end is twice the
    final one (`d12` = 2.6e-14 to 3.8e-13 of the largest displacement over
    the five kernels) and the final is the single solve at 10 (`d2` =
    1.3e-14 to 1.9e-13); bound 1e-12."""
    base = ["-options_file", "meshes/tube/tube.opts", "-mesh_size", "0.2"]
    one = run_contact(base, tmp_path, name="one")
    r = run_contact(base + ["-load_stages", 2, "-tube_load_inner_pressure", "20,10"], tmp_path, name="two")
    with h5py.File(r.output_path, "r") as f:
        u1, u2 = f["/stages/1/bodies/tube/displacement"][:], f["/stages/2/bodies/tube/displacement"][:]
    with h5py.File(one.output_path, "r") as f:
        u = f["/bodies/tube/displacement"][:]
    scale = np.abs(u).max()
    figure("d12", np.abs(u1 - 2 * u2).max() / scale)
    figure("d2", np.abs(u2 - u).max() / scale)
    assert np.abs(u1 - 2 * u2).max() < 1e-12 * scale and np.abs(u2 - u).max() < 1e-12 * scale
    assert r.summary["loads"]["tube:inner"] == pytest.approx(one.summary["loads"]["tube:inner"], abs=1e-12)


@pytest.mark.roundoff
@pytest.mark.kernels
def test_rigid_body_stages(tmp_path):
    """A rigid body's prescribed motion follows the stages: the rigid punch
    pressed to 0.004 turned by 0.003, then to 0.002 turned by 0.001, ends
    where the single solve at (0.002, 0.001) does: the punch's outline in
    the HDF5 (line_x, its nodes where the stage's translation and rotation
    put them) is the single solve's (`du` = 0 of the push 0.002 on each of
    the five kernels, bound 1e-12), and so are the reactions (solved to
    -tao_gttol 1e-12: the punch's corners leave the default stop's
    reactions 3e-5 apart from the base's; `dR` = 6.2e-13 to 2.2e-12 of the
    force, bound 1e-9). And a rigid disc force-controlled by 8 then 5 (the
    block held) moves where the single solve by 5 moves it (`dt` = 1.5e-15
    to 4.2e-14 of it, bound 1e-8: the solves' stop), each stage's end
    carrying its force (to 1e-8 of it, the stop)."""
    punch = ["-options_file", "meshes/rigid-punch/rigid-punch.opts", "-tao_gttol", "1e-12"]
    r1 = run_contact(punch + ["-punch_rigid_rotation", "0.001"], tmp_path, name="one")
    r2 = run_contact(punch + ["-load_stages", 2, "-punch_bc_push_values", "0,-0.004,0,-0.002", "-block_bc_base_values", "0,0,0,0",
                              "-punch_rigid_rotation", "0.003,0.001"], tmp_path, name="two")
    one, two = r1.summary, r2.summary
    P = abs(one["reactions"]["punch:push"][1])
    dR = figure("dR", max(abs(x - y) for g in one["reactions"] for x, y in zip(one["reactions"][g], two["reactions"][g])) / P)
    with h5py.File(r1.output_path, "r") as f1, h5py.File(r2.output_path, "r") as f2:
        x1, x2 = f1["/bodies/punch/line_x"][:], f2["/bodies/punch/line_x"][:]
    du = figure("du", np.abs(x2 - x1).max() / 0.002)
    disc = ["-options_file", "meshes/rigid-hertz/rigid-hertz.opts", "-indenter_bc_back_control", "force,displacement"]
    f1 = run_contact(disc + ["-block_bc_push_values", "0,0", "-indenter_bc_back_values", "5,0"], tmp_path, name="f1").summary
    f2 = run_contact(disc + ["-load_stages", 2, "-block_bc_push_values", "0,0,0,0", "-indenter_bc_back_values", "8,0,5,0"],
                     tmp_path, name="f2").summary
    t1, t2 = f1["bodies"]["indenter"]["translation"][0], f2["bodies"]["indenter"]["translation"][0]
    got = [st["reactions"]["indenter:back"][0] for st in f2["load_stages"]]
    dt = figure("dt", abs(t2 - t1) / abs(t1))
    print(f"disc: stage ends' forces {got}")
    assert du < 1e-12 and dR < 1e-9 and dt < 1e-8
    assert all(abs(g - F) < 1e-8 * F for g, F in zip(got, (8.0, 5.0)))


@pytest.mark.roundoff
def test_two_ranks(tmp_path):
    """Load, load on, unload (-0.075, -0.15, 0) on 1 and 2 ranks, each
    solved to -tao_gttol 1e-12 (at the default 1e-8 each stage's end is
    wherever its path stopped: the unloaded stage's contact force, a
    penetration of 5e-13 times k_p, is 1e-6 on one rank count and 0 on the
    other): every stage's reactions and contact force agree to 1e-12 of P
    (measured `worst` = 1.0e-13 to 2.6e-13 of P over the five kernels)."""
    args = staged([-PUSH / 2, -PUSH, 0.0]) + ["-tao_gttol", "1e-12"]
    a = run_contact(args, tmp_path, name="one").summary["load_stages"]
    b = run_contact(args, tmp_path, name="two", ranks=2).summary["load_stages"]
    P = abs(a[1]["reactions"]["block:push"][0])
    worst = max(abs(x - y) for sa, sb in zip(a, b) for key in ("reactions", "contact_force")
                for g in sa[key] for x, y in zip(sa[key][g], sb[key][g]))
    figure("worst", worst / P)
    assert len(a) == len(b) == 3 and worst < 1e-12 * P


BAD = {
    "count": (staged([-PUSH, 0.0]) + ["-block_bc_push_values", "-0.15,0,0"],
              "option -block_bc_push_values: 3 values for 2 components and -load_stages 2 (give 4"),
    "one_stage_given": (staged([-PUSH, 0.0]) + ["-indenter_bc_clamp_values", "0,0"],
                        "option -indenter_bc_clamp_values: 2 values for 2 components and -load_stages 2 (give 4"),
    "zero": (HERTZ + ["-load_stages", "0"], "option -load_stages: must be in [1, 64], got 0"),
    "not_integer": (HERTZ + ["-load_stages", "1.5"], "-load_stages"),
    "not_number": (HERTZ + ["-load_stages", "two"], "-load_stages"),
    "too_many": (HERTZ + ["-load_stages", "65"], "option -load_stages: must be in [1, 64], got 65"),
    "pressure_count": (["-options_file", "meshes/tube/tube.opts", "-load_stages", "2"],
                       "option -tube_load_inner_pressure: 1 values for 1 components and -load_stages 2 (give 2"),
    "rigid_translation": (["-options_file", "meshes/rigid-hertz/rigid-hertz.opts", "-load_stages", "2", "-block_bc_push_values", "0,0,0,0"],
                          "option -indenter_bc_back_values: 2 values for 2 components and -load_stages 2 (give 4"),
    "rigid_rotation": (["-options_file", "meshes/rigid-punch/rigid-punch.opts", "-load_stages", "2", "-punch_bc_push_values", "0,-0.004,0,-0.002",
                        "-block_bc_base_values", "0,0,0,0", "-punch_rigid_rotation", "0.001"],
                       "option -punch_rigid_rotation: 1 values for 1 components and -load_stages 2 (give 2"),
    "outer": (staged([-20.0, -40.0]) + ["-block_bc_push_control", "force,displacement", "-force_control_type", "outer"],
              "option -force_control_type outer"),
    "accuracy": (staged([-PUSH / 2, -PUSH]) + ["-accuracy", "0.05"], "option -accuracy: with -load_stages 2"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_stages(case, tmp_path):
    """A value count that is not the stages' (a condition given one stage
    where there are two included; a rigid body's translation and rotation),
    -load_stages 0, 1.5, two or above 64, force control's outer type or
    -accuracy with a history: one line naming the option and the counts,
    status 1, nothing written."""
    args, cause = BAD[case]
    r = run_contact(args, tmp_path, check=False)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    print(lines)
    assert r.returncode == 1 and len(lines) == 1 and lines[0].startswith("contact: error: "), r.stderr
    assert cause in lines[0], lines[0]
    assert not r.output_path.exists() and not r.summary_path.exists()
    assert not list(tmp_path.glob("*.json")) and not list(tmp_path.glob("*.h5")) and not list(tmp_path.glob("*.xdmf"))


PROBE = ROOT / "tests" / "paraview_times.py"


def test_xdmf_time_steps(tmp_path):
    """ParaView's three XDMF readers see the three stages of 0 -> d/2 -> d
    -> 0 as time steps 1, 2, 3, with the largest displacement component of
    each stage's end: d at stage 2 (the pushed edge), about 0 at stage 3
    (`u3` = 1.7e-11, bound 1e-9), and at stage 1 d/2 within 1e-3 of d
    (`u1` = 0.075043 on each of the five kernels: the block's bottom edge by
    the contact, a little past the pushed edge's d/2)."""
    if not (shutil.which("pvpython") and shutil.which("xvfb-run")):
        pytest.skip("pvpython or xvfb-run not installed (make deps installs them)")
    r = run_contact(staged([-PUSH / 2, -PUSH, 0.0]), tmp_path)
    out = tmp_path / "times.json"
    p = subprocess.run(["xvfb-run", "-a", "pvpython", str(PROBE), str(r.output_path.with_suffix(".xdmf")), str(out)],
                       cwd=tmp_path, env=ENV, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    got = json.loads(out.read_text())
    for reader, t in got.items():
        print(reader, t)
        figure("u1", t["umax"][0])
        figure("u3", t["umax"][2])
        assert t["times"] == [1.0, 2.0, 3.0]
        assert abs(t["umax"][0] - PUSH / 2) < 1e-3 * PUSH and abs(t["umax"][1] - PUSH) < 1e-12 and t["umax"][2] < 1e-9
