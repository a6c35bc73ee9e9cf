"""L-BFGS with the contact-aware initial Hessian (-lmvm_h0 contact, the
default for lmvm and blmvm): it reaches Newton's answer, refreshes H0 as
often as it says, and the elastic and the plain H0, the pair screening, the
decrement test and the restarts do what their options say. The references
are Newton's runs of the same scene, solved to -tao_gttol 1e-12 wherever
Newton gets there, so that only L-BFGS's stop adds to the difference.

Then the robustness sweep's cheap cases (those of test_robustness.py: the
half scene at k_p = 1e10 and 1e3, push 0.3, gpts and mortar) with lmvm at its
defaults on 1 and 2 ranks: each converges, its force balances the reaction
within what its own gradient allows, and its P is Newton's to what the two
stops leave. blmvm, the same with bounds (none here), follows lmvm bit for
bit on all of them (the same iterates and P, checked on 1 rank): it is run in
test_lmvm_reaches_newton alone, and on 2 ranks under make stress.

Every test here is marked roundoff: L-BFGS's path, and the point where it
stops, follow the machine's rounding."""
import math
import re

import numpy as np
import pytest

from conftest import figure, run_contact

pytestmark = pytest.mark.roundoff

EPS = np.finfo(float).eps
HERTZ = ["-options_file", "meshes/hertz/hertz.opts", "-tao_gttol", "1e-12", "-output", "none"]


@pytest.fixture(scope="module")
def newton(tmp_path_factory):
    return run_contact(HERTZ, tmp_path_factory.mktemp("newton")).summary


def rel(a, b):
    return abs(a / b - 1)


@pytest.mark.parametrize("tao", ["lmvm", "blmvm"])
def test_lmvm_reaches_newton(tao, newton, tmp_path):
    """P and the energy to Newton's, both solved to -tao_gttol 1e-12: P
    `dP` = 1.7e-12 to 2.0e-12 apart, the energy `dE` = 1 to 11 EPS, over the five
    kernels (lmvm and blmvm alike: blmvm follows lmvm bit for bit, and this
    is its smoke test); bounds 1e-11 = 10 gttol and 32 EPS (the quasi-Newton
    iteration converges linearly, so it stops just below its tolerance,
    where Newton's last quadratic step lands far below it). H0 set up once
    and then at every iteration (-lmvm_h0_refresh 1), so h0_refreshes
    equals the iterations (a contract, whatever their number)."""
    s = run_contact(HERTZ + ["-tao_type", tao], tmp_path).summary
    dP = figure("dP", rel(s["contact_force"], newton["contact_force"]))
    dE = figure("dE", rel(s["energy"], newton["energy"]) / EPS)
    print(f"{tao}: {s['iterations']} iterations, {s['h0_refreshes']} H0 set-ups")
    assert s["converged"]
    assert dP <= 1e-11 and dE <= 32
    assert s["h0_refreshes"] == s["iterations"]


def test_lmvm_refresh_period(tmp_path):
    """-lmvm_h0_refresh 3: H0 set up once, then at iterations 3, 6, ...:
    1 + floor((iterations - 1) / 3) set-ups (one stage: no continuation;
    a contract between the two counts, whatever the iterations)."""
    s = run_contact(HERTZ + ["-tao_type", "lmvm", "-lmvm_h0_refresh", "3", "-penalty_stages", "1"], tmp_path).summary
    assert s["converged"]
    assert s["h0_refreshes"] == 1 + (s["iterations"] - 1) // 3, (s["iterations"], s["h0_refreshes"])


def test_lmvm_h0_elastic(newton, tmp_path):
    """-lmvm_h0 elastic, the stiffness K alone as L-BFGS's initial Hessian
    (no contact part, so none of the contact H0's set-ups and none of its
    defaults: no penalty continuation, and Newton's stop -tao_gttol 1e-8):
    it converges on the reference scene to Newton's P (solved to 1e-12)
    within `dP` = 1.1e-8 to 3.0e-7 over the five kernels, bound 1e-6: the quasi-
    Newton iteration converges linearly and stops just below its tolerance,
    and at 1e-8 that leaves P 2e-7 to 2e-6 from Newton's at h = 0.03 (lmvm.c's
    header). In many more iterations than the contact H0 (`iterations` = 288
    to 386, against test_lmvm_reaches_newton's 18; not asserted),
    which is why the contact H0 is the default. It is not asked for
    -tao_gttol 1e-12, as the contact H0 is above: there its line search
    fails long before (the load cut back, the solve stopped)."""
    args = [a for a in HERTZ if a not in ("-tao_gttol", "1e-12")]
    s = run_contact(args + ["-tao_type", "lmvm", "-lmvm_h0", "elastic"], tmp_path).summary
    dP = figure("dP", rel(s["contact_force"], newton["contact_force"]))
    figure("iterations", s["iterations"])
    print(f"elastic H0: {s['iterations']} iterations ({s['tao_reason']})")
    assert s["converged"] and "h0_refreshes" not in s
    assert dP <= 1e-6


def test_lmvm_pair_ratio(newton, tmp_path):
    """-lmvm_pair_ratio 1: a pair is kept only if its curvature is H0's
    exactly, so every pair screened is dropped and each step is H0's, the
    Gauss-Newton step at the iterate (with the default 10 no pair is dropped
    on this scene). Each TAO solve screens a pair at every iteration but its
    first, so the dropped pairs are at least the iterations less the solves
    (the penalty stages and the restarts) and at most the iterations:
    measured `dropped` = 35 of `iterations` = 38 on each of the five
    kernels (18 with the pairs: the one pair is what learns the
    second-order term H0 leaves out). The answer is Newton's all the same:
    P `dP` = 6.6e-14 to 2.5e-13 from
    Newton's (both to -tao_gttol 1e-12), bound 1e-11 as in
    test_lmvm_reaches_newton."""
    s = run_contact(HERTZ + ["-tao_type", "lmvm", "-lmvm_pair_ratio", "1"], tmp_path).summary
    dP = figure("dP", rel(s["contact_force"], newton["contact_force"]))
    figure("dropped", s["lmvm_pairs_dropped"])
    figure("iterations", s["iterations"])
    solves = s["stages"] + s["lmvm_restarts"]
    print(f"{s['iterations']} iterations in {solves} solves, {s['lmvm_pairs_dropped']} pairs dropped")
    assert s["converged"]
    assert s["iterations"] - solves <= s["lmvm_pairs_dropped"] <= s["iterations"] and s["lmvm_pairs_dropped"] > 0
    assert dP <= 1e-11


def test_lmvm_h0_none(tmp_path):
    """-lmvm_h0 none: TAO's own L-BFGS, the program's H0 and its defaults off
    (no H0 set-up in the JSON, TAO's history of 5 pairs, no continuation,
    Newton's stop -tao_gttol 1e-8). On the reference scene coarsened to
    h = 0.2 with k_p = 2e4 (at h = 0.1 and k_p = 2e6 it takes 1200 to 1400
    iterations and does not converge in TAO's 2000 on every machine) it
    converges, in `iterations` = 570 to 734 against the contact H0's
    `contact` = 15 over the five kernels: bound 10 times (a cost claim, the
    reason for the contact H0; measured `ratio` = 38 to 49). Its P is
    Newton's (solved to -tao_gttol 1e-12) within `dP` = 6.7e-8 to 4.3e-7,
    bound 1.5e-6: its stop at 1e-8 leaves that much, as -lmvm_h0
    elastic's; the contact H0 at its own default stop 1e-10 within `dPc` =
    1.6e-10, bound 1e-8 (test_robustness's criterion)."""
    args = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.2", "-contact_penalty", "2e4", "-output", "none"]
    ref = run_contact(args + ["-tao_gttol", "1e-12"], tmp_path, name="newton").summary
    none = run_contact(args + ["-tao_type", "lmvm", "-lmvm_h0", "none"], tmp_path, name="none").summary
    contact = run_contact(args + ["-tao_type", "lmvm"], tmp_path, name="contact").summary
    dP = figure("dP", rel(none["contact_force"], ref["contact_force"]))
    dPc = figure("dPc", rel(contact["contact_force"], ref["contact_force"]))
    figure("iterations", none["iterations"])
    figure("contact", contact["iterations"])
    ratio = figure("ratio", none["iterations"] / contact["iterations"])
    assert none["converged"] and contact["converged"]
    assert "h0_refreshes" not in none and contact["h0_refreshes"] > 0
    assert ratio >= 10
    assert dP <= 1.5e-6 and dPc <= 1e-8


HALF = ["-options_file", "meshes/hertz-half/hertz-half.opts", "-block_bc_push_values", "-0.3,0", "-output", "none"]
CASES = [(0.25, 1e10, "gpts"), (0.25, 1e10, "mortar"), (0.1, 1e10, "gpts"), (0.1, 1e10, "mortar"),
         (0.1, 1e3, "gpts"), (0.1, 1e3, "mortar")]


def _case_args(h, kp, formulation):
    return HALF + ["-mesh_size", h, "-contact_penalty", f"{kp:g}", "-contact_formulation", formulation]


@pytest.fixture(scope="module")
def newton_cases(tmp_path_factory):
    """Newton on each case: to -tao_gttol 1e-12 at k_p = 1e3, at its default
    stop at k_p = 1e10, where it does not reach 1e-12."""
    tmp = tmp_path_factory.mktemp("newton-cases")
    return {c: run_contact(_case_args(*c) + (["-tao_gttol", "1e-12"] if c[1] < 1e6 else []), tmp,
                           name=f"{c[0]}-{c[1]:g}-{c[2]}").summary for c in CASES}


@pytest.mark.parametrize("tao,ranks", [("lmvm", 1), ("lmvm", 2), pytest.param("blmvm", 2, marks=pytest.mark.stress)])
@pytest.mark.parametrize("case", CASES, ids=[f"h{c[0]}-kp{c[1]:g}-{c[2]}" for c in CASES])
def test_lmvm_robust(case, tao, ranks, newton_cases, tmp_path):
    """lmvm at its defaults on the robustness cases, on 1 and 2 ranks: it
    converges (exit 0), the pair's force balances the push's reaction within
    what the run's own gradient allows (sqrt(n) ||g||, as test_robustness;
    measured `imbalance` = 1.9e-5 to 0.068 of that bound over the five
    kernels and the cases, the least at k_p = 1e3), and its P is Newton's
    within `dP` = 6.8e-12 to 3.3e-9, bound 1e-8, test_robustness's
    criterion of the same answer. Newton is solved to -tao_gttol 1e-12 at
    k_p = 1e3; at k_p = 1e10 it does not get there (its line search fails)
    and runs at its default stop 1e-8, whose share of P is most of dP there
    (L-BFGS stops on the decrement at 1e-13)."""
    s = run_contact(_case_args(*case) + ["-tao_type", tao], tmp_path, ranks=ranks).summary  # exit 0: converged
    ref = newton_cases[case]
    f = s["contact"]["interface"]["force"][0]
    reaction = s["reactions"]["block:push"][0]
    bound = math.sqrt(s["dofs"]) * s["gradient_norm"] + 1000 * EPS * abs(reaction)
    dP = figure("dP", rel(s["contact_force"], ref["contact_force"]))
    figure("imbalance", abs(abs(f) - abs(reaction)) / bound)
    print(f"{tao} on {ranks}: {s['iterations']} iterations ({s['stages']} stages, {s['h0_refreshes']} H0 set-ups, "
          f"{s['lmvm_pairs_dropped']} pairs dropped, {s['lmvm_restarts']} restarts; Newton {ref['iterations']}); "
          f"P {s['contact_force']:.12g}")
    assert s["converged"]
    assert abs(abs(f) - abs(reaction)) <= bound   # the balance test_robustness asserts, from the run's own gradient
    assert dP <= 2e-8


def test_lmvm_ranks(tmp_path):
    """The reference scene at h = 0.06 on 1 and 2 ranks: the same P, a result
    and not the path (the iteration counts are not compared), to 1e-8 of
    P: each run stops at the default gradient tolerance 1e-10, which leaves
    up to 2.1e-8 of P between L-BFGS and Newton at h = 0.015 (lmvm.c's
    header), so two paths that stop at different iterates may differ by
    that much; measured `dP` = 1.4e-14 to 1.3e-13 over the five kernels."""
    args = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", 0.06, "-output", "none", "-tao_type", "lmvm"]
    s = {n: run_contact(args, tmp_path, ranks=n, name=f"np{n}").summary for n in (1, 2)}
    dP = figure("dP", rel(s[2]["contact_force"], s[1]["contact_force"]))
    print(f"iterations {s[1]['iterations']} and {s[2]['iterations']}")
    for n in (1, 2):
        assert s[n]["converged"]
    assert dP <= 1e-8


PLAN = re.compile(r"L-BFGS: k_p h / E\* = (\S+): (\d+) penalty stages from")


@pytest.mark.parametrize("formulation", ["gpts", "mortar"])
def test_lmvm_ranks_stiff(formulation, tmp_path):
    """At a stiff penalty (the half scene at h = 0.1, k_p = 1e10, push 0.3:
    k_p h / E* = 1.7e6) the default continuation starts where k_p h / E* is
    1 and climbs by at most 32 a stage: 1 + ceil(log_32(k_p h / E*)) stages
    (6), from the JSON's penalty_stiffness, against the plan the run reports
    (-info :tao; the stages done, a path, count cutbacks' stages too). 1 and
    2 ranks reach the same P to 4e-9, the default stop's share (the
    decrement at 1e-13; measured `dP` = 4.8e-11 to 1.2e-9 over the five
    kernels and both formulations). The iterations, a path, are printed and
    not compared."""
    args = _case_args(0.1, 1e10, formulation) + ["-tao_type", "lmvm"]
    s, plan = {}, None
    for n in (1, 2):
        r = run_contact(args + (["-info", ":tao"] if n == 1 else []), tmp_path, ranks=n, name=f"np{n}")
        s[n] = r.summary
        if n == 1:
            plan = PLAN.findall(r.stdout)
    stiff = s[1]["contact"]["interface"]["penalty_stiffness"]
    dP = figure("dP", rel(s[2]["contact_force"], s[1]["contact_force"]))
    print(f"k_p h / E* = {stiff:.3g}: planned {plan}, {s[1]['stages']} stages done; iterations {s[1]['iterations']} and "
          f"{s[2]['iterations']}")
    assert len(plan) == 1 and int(plan[0][1]) == 1 + math.ceil(math.log(stiff) / math.log(32)), plan
    assert s[1]["converged"] and s[2]["converged"]
    assert dP <= 4e-9


@pytest.mark.parametrize("case", ["hertz", "half-kp1e10"])
def test_lmvm_decrement(case, newton, newton_cases, tmp_path):
    """-lmvm_decrement_rtol 1e-12 (the last stage stops on the decrement in
    H0's norm instead of the gradient): it converges, with one decrement
    solve per iteration after the first of the last stage (between 1 and the
    iterations + 1: the test was applied), and P is Newton's within 1e-11 on
    the reference scene (Newton solved to -tao_gttol 1e-12; 5 times the
    worst kernel's figure) and within 1e-8 on the coarse mortar half scene
    at k_p = 1e10, push 0.3 (Newton at its default stop, as in
    test_lmvm_robust), where -tao_gttol 1e-11 stops at the gradient's
    round-off; measured `dP_hertz` = 1.8e-12 to 2.1e-12 on the reference
    scene and `dP_half` = 6.5e-11 to 3.8e-9 on the half scene over the five
    kernels."""
    args = HERTZ if case == "hertz" else _case_args(0.25, 1e10, "mortar")
    ref = newton if case == "hertz" else newton_cases[(0.25, 1e10, "mortar")]
    s = run_contact(args + ["-tao_type", "lmvm", "-lmvm_decrement_rtol", "1e-12"], tmp_path, name="lmvm").summary
    dP = figure("dP_hertz" if case == "hertz" else "dP_half", rel(s["contact_force"], ref["contact_force"]))
    print(f"{s['iterations']} iterations ({s['tao_reason']}), {s['lmvm_decrement_solves']} decrement solves")
    assert s["converged"]
    assert 0 < s["lmvm_decrement_solves"] <= s["iterations"] + 1
    assert dP <= (1e-11 if case == "hertz" else 1e-8)


def test_lmvm_decrement_default(tmp_path):
    """Without -lmvm_decrement_rtol, the last stage stops on the decrement
    (r = 1e-13) where a pair's k_p h / E* exceeds 1e4 (the coarse mortar half
    scene at k_p = 1e10: 3.8e6) and no gradient tolerance is given, and on
    the gradient tolerances otherwise: -tao_gttol given there, or the
    reference scene's k_p = 2e6 (k_p h / E* = 347 at h = 0.1). Which test
    applied is read from the decrement solves the JSON counts (none without
    the decrement test); each run converges. (1 and 2 ranks at the stiff
    penalty: test_lmvm_ranks_stiff.)"""
    stiff = _case_args(0.25, 1e10, "mortar") + ["-tao_type", "lmvm"]
    s = run_contact(stiff, tmp_path, name="stiff").summary
    given = run_contact(stiff + ["-tao_gttol", "1e-10"], tmp_path, name="gttol").summary
    ref = run_contact(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", 0.1, "-output", "none",
                       "-tao_type", "lmvm"], tmp_path, name="ref").summary
    print(f"stiff: {s['iterations']} iterations ({s['tao_reason']}), {s['lmvm_decrement_solves']} decrement solves")
    assert s["converged"] and s["lmvm_decrement_solves"] > 0
    for r in (given, ref):
        assert r["converged"] and "lmvm_decrement_solves" not in r


def test_lmvm_decrement_floor(newton_cases, tmp_path):
    """The decrement's round-off floor, forced: on the coarse mortar half
    scene at k_p = 1e10, push 0.3 the decrement reaches 2e-14 to 8e-14 of the
    first iterate's before the line search fails (measured with
    -lmvm_decrement_rtol 1e-16 under the five kernels; 7e-15 to 2.5e-14
    elsewhere, lmvm.c's header). Asked for -lmvm_decrement_rtol 1e-15,
    below that floor, with -lmvm_decrement_floor 1000 (a failure with the
    decrement under 1e-12 of the first iterate's is the floor), the last
    stage's line search fails at the floor and the solve ends converged
    there: the JSON counts one floor stop (`floor_stops` = 1 on each of the
    five kernels; at least one asserted), and P is Newton's within 1e-8 as
    in test_lmvm_decrement (measured `dP` = 4.6e-10 to 2.0e-9)."""
    case = (0.25, 1e10, "mortar")
    s = run_contact(_case_args(*case) + ["-tao_type", "lmvm", "-lmvm_decrement_rtol", "1e-15",
                                         "-lmvm_decrement_floor", "1000"], tmp_path, name="lmvm").summary
    dP = figure("dP", rel(s["contact_force"], newton_cases[case]["contact_force"]))
    stops = figure("floor_stops", s["lmvm_decrement_floor_stops"])
    print(f"{s['iterations']} iterations ({s['tao_reason']}), {s['load_cutbacks']} cutbacks, {stops:g} floor stops")
    assert s["converged"] and stops >= 1
    assert dP <= 1e-8


def test_lmvm_restarts(newton, tmp_path):
    """-lmvm_restarts: a line search held to a strict curvature condition
    (-tao_ls_gtol 1e-3) with 3 evaluations (-tao_ls_max_funcs 3) fails on
    the reference scene after lowering the energy, on every kernel. At the
    default (50 restarts) the solve restarts from where it stopped
    (`restarts` = 1 to 4 over the five kernels, at least 1 asserted; some
    kernels' paths also cut the load back) and converges to Newton's P
    (solved to -tao_gttol 1e-12) within `dP` = 3.9e-11 to 3.2e-9, bound 1e-8, the
    criterion of test_robustness: L-BFGS's stop at 1e-10 of the gradient
    leaves up to 2.1e-8 (lmvm.c's header), and the restarts stop where the
    first solve would. With -lmvm_restarts 0 no solve is restarted: the
    failure goes to the load cutback instead, which on some kernels' paths
    runs out of cutbacks (the run then stops on the line search failure)."""
    opts = ["-options_file", "meshes/hertz/hertz.opts", "-output", "none"]
    ls = ["-tao_type", "lmvm", "-tao_ls_gtol", "1e-3", "-tao_ls_max_funcs", "3"]
    on = run_contact(opts + ls, tmp_path, name="restarts").summary
    off = run_contact(opts + ls + ["-lmvm_restarts", "0"], tmp_path, name="norestart", check=False)
    dP = figure("dP", rel(on["contact_force"], newton["contact_force"]))
    figure("restarts", on["lmvm_restarts"])
    print(f"on: {on['lmvm_restarts']} restarts, {on['load_cutbacks']} cutbacks, {on['iterations']} iterations; "
          f"off: exit {off.returncode}, {off.summary and (off.summary['load_cutbacks'], off.summary['iterations'])}")
    assert on["converged"] and on["lmvm_restarts"] >= 1
    assert dP <= 1e-8
    if off.returncode == 0:
        assert off.summary["lmvm_restarts"] == 0 and off.summary["load_cutbacks"] >= 1
    else:
        assert "DIVERGED_LS_FAILURE; the load cut back" in off.stderr, off.stderr
