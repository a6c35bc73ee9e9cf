"""Force control (src/solver/forcecontrol.c, forcesolve.c, forceborder.c, forceouter.c):
-<body>_bc_<group>_control force turns a component's value into a force; the
group moves rigidly in it by the displacement that makes its reaction that
force, an unknown of the one minimisation (coupled, the default) or of an
outer iteration (-force_control_type outer).

The reference is the displacement-driven run: the reference scene pushed by
0.15 has a reaction F at its pushed edge; driven by F, it must find the push
0.15 again (uniqueness: the reaction grows strictly with the push once the
bodies touch)."""
import re

import numpy as np
import pytest

from conftest import figure, info_args, run_contact

HERTZ = ["-options_file", "meshes/hertz/hertz.opts"]
PUSH = 0.15
EPS = np.finfo(float).eps


@pytest.fixture(scope="module")
def by_displacement(tmp_path_factory):
    return run_contact(HERTZ + ["-output", "none"], tmp_path_factory.mktemp("disp")).summary


def by_force(F, tmp_path, ranks=1, name="force"):
    args = HERTZ + ["-block_bc_push_control", "force,displacement", "-block_bc_push_values", f"{F!r},0", "-output", "none",
                    "-force_control_rtol", "1e-11"]
    return run_contact(args, tmp_path, ranks=ranks, name=name).summary


@pytest.mark.roundoff
def test_force_finds_the_push(by_displacement, tmp_path):
    """Driven by the reaction of the push 0.15 (-55.04 in x), the pushed edge
    moves by -0.15: measured `dU` = 7.2e-13 to 7.3e-13 of it with the coupled
    type over the five kernels (the displacement run's own stop, -tao_gttol
    1e-8, is most of it; the outer iteration: test_solver_options.py), bound
    1e-6 (the issue's). Solved with -force_control_rtol 1e-11, so that the
    control's stop adds nothing; the contact force then balances the force to
    the solve's residual: F - P is the gradient summed over the block's free
    x-dofs, at most sqrt(n) times the gradient norm (measured
    `balance_of_bound` = 2.4e-3 to 6.9e-3 of that bound). The JSON lists the
    control with its force and displacement, and the energy includes the
    force's potential -F U: the displacement run's energy at the push U_d =
    -0.15 minus F U_d, to second order in U - U_d (the energy's slope in U is
    the reaction, F; measured `dE` = 2.0e-16 to 9.8e-16 of it, bound 15 EPS =
    3.3e-15)."""
    F = by_displacement["reactions"]["block:push"][0]
    s = by_force(F, tmp_path)
    (fc,) = s["force_control"]
    U = fc["displacement"]
    print(f"F = {F!r}: U = {U!r} ({abs(U + PUSH) / PUSH:.2e} from -0.15), reaction {fc['reaction']!r}, "
          f"P {s['contact_force']!r} ({abs(s['contact_force'] - abs(F)) / abs(F):.2e}), "
          f"{s['force_control_solves']} solves, {s['iterations']} iterations")
    assert (fc["body"], fc["group"], fc["component"], fc["force"]) == ("block", "push", "x", F)
    assert figure("dU", abs(U + PUSH) / PUSH) <= 1e-6
    bound = np.sqrt(s["dofs"]) * s["gradient_norm"] + 1e-11 * abs(F)
    print(f"F - P: {abs(s['contact_force'] - abs(F)):.3e}, {abs(s['contact_force'] - abs(F)) / bound:.2e} of its bound")
    assert figure("balance_of_bound", abs(s["contact_force"] - abs(F)) / bound) <= 1
    de = s["energy"] - (by_displacement["energy"] + F * PUSH)
    print(f"energy: {s['energy']!r} against {by_displacement['energy'] + F * PUSH!r}: {de:.2e}")
    assert figure("dE", abs(de) / abs(s["energy"])) <= 15 * EPS


@pytest.mark.roundoff
def test_force_control_ranks(by_displacement, tmp_path):
    """1 and 2 ranks find the same reaction, contact force and displacement
    (the coupled type), within what each run's stop guarantees: each reaction
    within the control's tolerance (-force_control_rtol 1e-11) of the force, so
    2e-11 apart (measured `dR` = 2.2e-15 to 2.4e-14 relative over the five
    kernels); each P within sqrt(n) ||g|| + 1e-11 |F| of the force
    (test_force_finds_the_push), so the two within the sum of those bounds
    (measured `dP` = 3.0e-14 to 1.4e-13 relative,
    `dP_of_bound` = 7.5e-4 to 3.6e-3 of that sum); the displacements within
    what that P difference moves the push, at most 2 U / F per unit force (the
    approach grows as the force times a logarithm and the block's own
    compliance: its slope is below U / F; measured `dU` = 0 to 3.7e-16
    relative, `dU_of_bound` = 0 to 4.7e-6)."""
    F = by_displacement["reactions"]["block:push"][0]
    one = by_force(F, tmp_path, name="np1")
    two = by_force(F, tmp_path, ranks=2, name="np2")
    Pbound = sum(np.sqrt(s["dofs"]) * s["gradient_norm"] + 1e-11 * abs(F) for s in (one, two))
    R1, R2 = one["force_control"][0]["reaction"], two["force_control"][0]["reaction"]
    assert figure("dR", abs(R1 - R2) / abs(F)) <= 2e-11, (R1, R2)
    dP = abs(one["contact_force"] - two["contact_force"])
    figure("dP", dP / one["contact_force"])
    assert figure("dP_of_bound", dP / Pbound) <= 1
    U1, U2 = one["force_control"][0]["displacement"], two["force_control"][0]["displacement"]
    figure("dU", abs(U1 - U2) / abs(U1))
    assert figure("dU_of_bound", abs(U1 - U2) / (2 * abs(U1) / abs(F) * Pbound)) <= 1, (U1, U2)


FINE = ["-disc_geo_params", "R=1,xc=-1,yc=0,xclamp=-1.8,xcontact=-0.5,hc=0.0007,dc=1",
        "-slab_geo_params", "x0=0,W=1,H=2,hc=0.0007,dc=1"]
# name: (options, [(body, group, components, the controlled one's index, the imposed displacement)])
SCENES = {
    "softdisc-fine": (["-options_file", "meshes/softdisc/softdisc.opts"] + FINE, [("disc", "clamp", "xy", 0, 0.02)]),
    "sphere": (["-options_file", "meshes/sphere/sphere.opts"], [("ball", "equator", "y", 0, -0.01)]),
    "pinch": (["-options_file", "meshes/pinch/pinch.opts"], [("left", "clamp", "xy", 0, 0.02),
                                                              ("right", "clamp", "xy", 0, -0.03)]),
}


@pytest.mark.roundoff
@pytest.mark.parametrize("ranks", [1, 2])
@pytest.mark.parametrize("scene", sorted(SCENES))
def test_coupled_finds_the_displacement(scene, ranks, tmp_path):
    """The coupled type (the default) on a soft disc pressed onto a stiff slab
    on its fine mesh (hc = 0.0007), the axisymmetric ball on a flat, and a
    block pinched by two discs driven by two forces at once, each force the
    reaction of the displacement-controlled run (its gradient tolerance
    -tao_gttol 1e-12, so that its reaction is the force of its displacement to
    round-off; the force run's too, and -force_control_rtol 1e-11): the
    displacements found are the imposed ones, and the energy is the
    displacement run's minus F . U to second order in their difference.
    Measured over the scenes, 1 and 2 ranks and the five kernels: displacements
    `dU` = 1.7e-16 to 4.5e-14 (bound 1.5e-13), reactions against the forces
    `dR` = 8.0e-16 to 1.5e-13 (bound 1e-11, the control's tolerance), energies
    `dE` = 0 to 1.5e-15 relative (bound 5e-15)."""
    args, controls = SCENES[scene]
    d = run_contact(args + ["-output", "none", "-tao_gttol", "1e-12"], tmp_path, ranks=ranks, name="disp").summary
    opts, work = [], 0.0
    for body, group, comps, k, U in controls:
        F = d["reactions"][f"{body}:{group}"]["xy".index(comps[k])]
        work += F * U
        opts += [f"-{body}_bc_{group}_control", ",".join("force" if i == k else "displacement" for i in range(len(comps))),
                 f"-{body}_bc_{group}_values", ",".join(repr(F) if i == k else "0" for i in range(len(comps)))]
    f = run_contact(args + opts + ["-output", "none", "-force_control_rtol", "1e-11", "-tao_gttol", "1e-12"], tmp_path,
                    ranks=ranks, name="force").summary
    found = {(c["body"], c["group"]): c for c in f["force_control"]}
    dU = dR = 0.0
    for body, group, comps, k, U in controls:
        c = found[(body, group)]
        print(f"{scene} np{ranks} {body}:{group}: U {c['displacement']!r} against {U}: "
              f"{abs(c['displacement'] - U) / abs(U):.1e}; reaction {c['reaction']!r}, force {c['force']!r}")
        dU = max(dU, abs(c["displacement"] - U) / abs(U))
        dR = max(dR, abs(c["reaction"] - c["force"]) / abs(c["force"]))
    assert figure("dU", dU) <= 1.5e-13
    assert figure("dR", dR) <= 1e-11
    de = f["energy"] - (d["energy"] - work)
    print(f"energy {f['energy']!r} against {d['energy'] - work!r}: {de / abs(f['energy']):.1e}; "
          f"iterations {f['iterations']} against {d['iterations']}")
    assert figure("dE", abs(de) / abs(f["energy"])) <= 5e-15


@pytest.mark.roundoff
def test_coupled_lbfgs(by_displacement, tmp_path):
    """L-BFGS (-tao_type lmvm, its H0 bordered by the control as Newton's
    Hessian is) finds the reference scene's push too: measured `dU` = 3.0e-12
    of 0.15 over the five kernels (Newton's is the displacement run's own
    error; L-BFGS stops at its own -tao_gttol 1e-10, relative to the
    displacement run's gradient at rest once it has found U), bound 1e-11."""
    F = by_displacement["reactions"]["block:push"][0]
    s = run_contact(HERTZ + ["-block_bc_push_control", "force,displacement", "-block_bc_push_values", f"{F!r},0",
                             "-output", "none", "-tao_type", "lmvm"], tmp_path).summary
    (fc,) = s["force_control"]
    print(f"lmvm: U = {fc['displacement']!r}, {abs(fc['displacement'] + PUSH) / PUSH:.1e} from 0.15, {s['iterations']} iterations")
    assert figure("dU", abs(fc["displacement"] + PUSH) / PUSH) <= 1e-11


PINCH = ["-options_file", "meshes/pinch/pinch.opts", "-left_bc_clamp_control", "force,displacement", "-left_bc_clamp_values",
         "6.28,0", "-right_bc_clamp_control", "force,displacement", "-right_bc_clamp_values", "-8.03,0", "-output", "none"]


def border_info(out):
    """The -info lines of forceborder.c: how the border is eliminated, and
    the controls' stiffness S (m x m) and own D_kk at every Hessian."""
    how = re.findall(r"force control: the border eliminated (.*)", out)
    steps = [([float(x) for x in re.split(r"[ ;]+", m.group(1).strip())], [float(x) for x in m.group(2).split()])
             for m in re.finditer(r"\[0\] .*S = \[([^\]]*)\], own D_kk = \[([^\]]*)\]", out)]
    return how, steps


@pytest.mark.roundoff
@pytest.mark.parametrize("ranks", [1, 2])
def test_border_from_the_surfaces(ranks, tmp_path):
    """The substructuring eliminates the border itself (SubBorder* in
    substructure.c: B^T H^-1 B from the contact surfaces, one solve a step) and
    gives what the m solves of H per Hessian give
    (-force_control_border_solves): on the pinched block driven by two forces,
    each run reports S = D - B^T H^-1 B at every Hessian it assembles, and at
    the first (at rest, the same H in both runs) the two agree: measured
    `dS` = 3.0e-16 to 1.3e-15 of max D_kk over 1 and 2 ranks and the five
    kernels, bound 5e-15. Both solved to a tight stop (-tao_gttol 1e-12), they
    find the same displacements and contact force: measured
    `dU` = 1.7e-16 to 1.5e-15 and `dP` = 3.8e-15 to 3.1e-14 apart (relative),
    bounds 1e-14 and 1e-13. A step without the substructuring (-newton_schur 0,
    Cholesky) falls back on the m solves and finds the same (1 rank:
    `dU_chol` = 1.0e-15 to 2.7e-15, `dP_chol` = 5.0e-15 to 3.5e-14, the same
    bounds)."""
    tight = PINCH + ["-tao_gttol", "1e-12"]
    # -info into a file per rank, rank 0's read: on stdout two ranks' lines can interleave (one of 10 lost under load)
    fast = run_contact(tight + info_args(tmp_path, "fast"), tmp_path, ranks=ranks, name="fast")
    slow = run_contact(tight + info_args(tmp_path, "solves") + ["-force_control_border_solves"], tmp_path, ranks=ranks, name="solves")
    (how_f, sf), (how_s, ss) = [border_info((tmp_path / f"{n}.info.0").read_text()) for n in ("fast", "solves")]
    assert how_f and all(h.startswith("by the PC") for h in how_f), how_f
    assert how_s == [], how_s  # never asked: the m solves
    assert len(sf) == fast.summary["hessian_evaluations"] > 1
    assert len(ss) == slow.summary["hessian_evaluations"] > 1
    d = max(ss[0][1])
    dev = max(abs(a - b) for a, b in zip(sf[0][0], ss[0][0])) / d
    print(f"np{ranks}: S at rest apart by {dev:.1e} of max D_kk = {d:.6g}; "
          f"{fast.summary['iterations']} and {slow.summary['iterations']} iterations")
    assert figure("dS", dev) <= 5e-15

    def apart(a, b, tag):
        dU = max(abs(x["displacement"] - y["displacement"]) / abs(y["displacement"])
                 for x, y in zip(a["force_control"], b["force_control"]))
        dP = abs(a["contact_force"] - b["contact_force"]) / b["contact_force"]
        print(f"  {tag}: U {dU:.1e}, P {dP:.1e} apart")
        assert figure(f"dU{tag}", dU) <= 1e-14
        assert figure(f"dP{tag}", dP) <= 1e-13

    apart(fast.summary, slow.summary, "")
    if ranks == 1:
        chol = run_contact(tight + ["-info", f"{tmp_path}/chol.info:sys", "-newton_schur", "0"], tmp_path, name="chol")
        how_c, sc = border_info((tmp_path / "chol.info.0").read_text())
        assert how_c and all(h.startswith("by m solves") for h in how_c), how_c
        apart(chol.summary, fast.summary, "_chol")


BAD = {
    "count": (["-block_bc_push_control", "force"], "option -block_bc_push_control: 1 entries for 2 components"),
    "unknown": (["-block_bc_push_control", "force,pressure"], "unknown control 'pressure'"),
    "max_it": (["-force_control_max_it", "0"], "option -force_control_max_it: must be >= 1"),
    "type": (["-force_control_type", "broyden"], "option -force_control_type: unknown type 'broyden' (known: coupled, outer)"),
    "step": (["-force_control_step", "0"], "option -force_control_step: must be a finite number > 0, got 0"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_control(case, tmp_path):
    extra, cause = BAD[case]
    r = run_contact(HERTZ + extra, tmp_path, check=False)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert r.returncode == 1 and len(lines) == 1 and lines[0].startswith("contact: error: "), r.stderr
    assert cause in lines[0], lines[0]


@pytest.mark.parametrize("kind", ["outer", "coupled"])
def test_force_control_gives_up_in_one_line(kind, tmp_path):
    """A limit too small: the solve stops, says why in one line naming the
    option and the group, writes nothing, exit 2. The outer iteration with 2
    solves; the coupled type with 1 solve and a tolerance below round-off
    (-force_control_rtol 1e-15), which only a second solve could try."""
    extra = ["-force_control_max_it", "2"] if kind == "outer" else ["-force_control_max_it", "1", "-force_control_rtol", "1e-15"]
    r = run_contact(HERTZ + ["-block_bc_push_control", "force,displacement", "-block_bc_push_values", "-55,0",
                             "-force_control_type", kind] + extra, tmp_path, check=False)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert r.returncode == 2, r.stderr
    assert len(lines) == 1 and f"-force_control_max_it {extra[1]}" in lines[0] and "push" in lines[0], lines
    assert not (tmp_path / "run.json").exists()
