"""Solver options each shown to do what docs/solver.md and docs/scenes.md say,
to converge, and to keep the answer:

- -stage_rtol: each intermediate stage of a penalty continuation stops at
  the first iterate whose gradient has fallen by it (TAO's monitor);
- -tangent_at_rest_its: a neo-Hookean body's Newton step takes the
  tangent from that iteration of each solve on (-info names each Hessian);
- -force_control_step: the coupled type's step in a controlled
  displacement is at most that times its body's size (-info prints the
  regularised steps and their cap);
- -force_control_type outer: an outer iteration of displacement-controlled
  solves finds the reference scene's push.

The answers are the same as without the option: the reference scene's push
0.15 for force control (its reaction as the force), the tangent-every-step
run for the neo-Hookean body, a tight final stop for the continuation."""
import math
import re

import pytest

from conftest import figure, run_contact
from test_neohookean import check_tangent_rule, tangent_choices

HERTZ = ["-options_file", "meshes/hertz/hertz.opts", "-output", "none"]
PUSH = 0.15
# the block [0, 1] x [-1, 1] (meshes/hertz/hertz.opts): its size, the diagonal of its box
BLOCK_SIZE = math.hypot(1.0, 2.0)


def monitored_solves(out):
    """The gradient norms TAO's monitor printed, one list per solve (each
    starts at its iteration 0)."""
    solves = []
    for m in re.finditer(r"^\s*(\d+) TAO,.*Residual: (\S+)", out, re.M):
        if int(m[1]) == 0:
            solves.append([])
        solves[-1].append(float(m[2]))
    return solves


@pytest.mark.roundoff
def test_stage_rtol(tmp_path):
    """The reference scene with a penalty continuation (-penalty_stages 3) and
    -stage_rtol 0.1, then 1e-6: each of the two intermediate stages stops at
    its first iterate whose gradient norm is at most stage_rtol times its first
    (every earlier one above it; monitored to 6 digits, judged with a margin of
    1e-5). The last stage stops at the final tolerance (-tao_gttol 1e-12) and
    the two runs reach the same P: measured `dP` = 1.2e-13 to 3.2e-13 apart
    over the five kernels, bound 1e-12."""
    P = {}
    for rtol in (0.1, 1e-6):
        r = run_contact(HERTZ + ["-penalty_stages", 3, "-stage_rtol", rtol, "-tao_gttol", "1e-12", "-tao_monitor"],
                        tmp_path, name=f"rtol{rtol:g}")
        solves = monitored_solves(r.stdout)
        print(rtol, [(len(g), g[-1] / g[0]) for g in solves])
        assert len(solves) >= 3, solves  # at least the three stages
        for g in solves[:-1]:
            assert g[-1] <= rtol * g[0] * (1 + 1e-5), (rtol, g)
            assert all(x > rtol * g[0] * (1 - 1e-5) for x in g[:-1]), (rtol, g)
        P[rtol] = r.summary["contact_force"]
    dP = figure("dP", abs(P[0.1] - P[1e-6]) / P[1e-6])
    assert dP <= 1e-12


def squeeze(push, gatol):
    return ["-options_file", "meshes/rubber-squeeze/rubber-squeeze.opts", "-mesh_size", "0.1", "-output", "none",
            "-plate_bc_contact_values", push, "-tao_gatol", gatol, "-tao_grtol", "0", "-tao_gttol", "0"]


@pytest.mark.roundoff
def test_tangent_at_rest_its(tmp_path):
    """The rubber squeeze at 1 % of its push (neo-Hookean, two stages, each
    converging fast with the stiffness at rest) with -tangent_at_rest_its 2 and
    0: every Hessian's choice (-info) follows the rule with that limit
    (test_neohookean's check_tangent_rule: the tangent from iteration 2, resp.
    at every Hessian; the stiffness at rest before), so each run takes the
    tangent, and P is the tangent-every-step run's (-tangent_at_rest 0), all
    solved to a gradient of 1e-12: measured `dP` = 0 to 1.5e-10 apart over both
    limits and the five kernels (0 with limit 0: the same steps as the
    reference's), bound 5e-10."""
    args = squeeze("0,-0.003", "1e-12")
    ref = run_contact(args + ["-tangent_at_rest", "0"], tmp_path, name="ref").summary
    for its in (2, 0):
        r = run_contact(args + ["-tangent_at_rest_its", its, "-info", ":sys", "-tao_monitor"], tmp_path, name=f"its{its}")
        solves = tangent_choices(r.stdout + r.stderr)
        judged = check_tangent_rule(solves, its=its)
        print(its, [sorted(k for k, t in c.items() if t) for g, c in solves], judged)
        assert judged > 0 and any(any(c.values()) for g, c in solves), solves
        if its == 0:
            assert all(all(c.values()) for g, c in solves), solves
        dP = abs(r.summary["contact_force"] / ref["contact_force"] - 1)
        assert figure("dP", dP) <= 5e-10


@pytest.fixture(scope="module")
def push_force(tmp_path_factory):
    """The reaction of the reference scene's push 0.15: the force that must find it again."""
    return run_contact(HERTZ, tmp_path_factory.mktemp("disp")).summary["reactions"]["block:push"][0]


def driven(F, extra, tmp_path, name):
    return run_contact(HERTZ + ["-block_bc_push_control", "force,displacement", "-block_bc_push_values", f"{F!r},0",
                                "-force_control_rtol", "1e-11"] + extra, tmp_path, name=name)


def test_force_control_step(push_force, tmp_path):
    """-force_control_step 0.01 and 0.003 on the reference scene driven by its
    push's reaction: every step of the controlled displacement that the cap (or
    S's conditioning) regularises reports |dU| at most its cap (-info), and the
    cap is the option times the block's size sqrt(5) (from the scene's
    geometry, to the 6 digits printed); each run finds the push 0.15 (measured
    `dU` = 7.2e-13 to 7.3e-13 of it over both caps and the five kernels, bound
    1e-6, the displacement run's own stop being most of it)."""
    for step in (0.01, 0.003):
        r = driven(push_force, ["-force_control_step", step, "-info", ":sys"], tmp_path, f"step{step}")
        steps = [(float(m[1]), float(m[2])) for m in
                 re.finditer(r"regularised by mu = \S+ \(dU_0 = (\S+), cap (\S+)\)", r.stdout + r.stderr)]
        (fc,) = r.summary["force_control"]
        print(step, len(steps), max(abs(d) for d, c in steps), {c for d, c in steps}, fc["displacement"], r.summary["iterations"])
        assert steps
        for dU, cap in steps:
            assert abs(cap / (step * BLOCK_SIZE) - 1) <= 1e-5, (cap, step)
            assert abs(dU) <= cap * (1 + 1e-5), (dU, cap)
        assert figure("dU", abs(fc["displacement"] + PUSH) / PUSH) <= 1e-6


def test_force_control_outer(push_force, tmp_path):
    """-force_control_type outer: an outer iteration of solves of u, each
    displacement-controlled (the JSON's force_control_solves counts them: more
    than one, where the coupled type's one minimisation is one), finds the push
    0.15 driven by its reaction (measured `dU` = 1.2e-11 of it over the five
    kernels, bound 1e-6), and the contact force balances the force to what the
    last solve's stop and the control's tolerance guarantee: sqrt(n) ||g|| +
    1e-11 |F| (measured `balance_of_bound` = 2.4e-4 of that bound)."""
    s = driven(push_force, ["-force_control_type", "outer"], tmp_path, "outer").summary
    (fc,) = s["force_control"]
    print(f"U {fc['displacement']!r}, {s['force_control_solves']} solves, {s['iterations']} iterations, P {s['contact_force']!r}")
    assert s["force_control_solves"] > 1
    assert figure("dU", abs(fc["displacement"] + PUSH) / PUSH) <= 1e-6
    F = abs(push_force)
    bound = math.sqrt(s["dofs"]) * s["gradient_norm"] + 1e-11 * F
    assert figure("balance_of_bound", abs(s["contact_force"] - F) / bound) <= 1
