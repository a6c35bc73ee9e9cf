"""L-BFGS with the contact-aware initial Hessian (-lmvm_h0 contact, the
default for lmvm and blmvm): it reaches Newton's answer, refreshes H0 as
often as it says, and the elastic H0 and the refresh period remain options.
The references are Newton's runs of the same scene, both solved to
-tao_gttol 1e-12 so that neither stop adds to the difference.

Then the robustness sweep's cheap cases (those of test_robustness.py: the
half scene at k_p = 1e10 and 1e3, push 0.3, gpts and mortar) with lmvm and
blmvm at their defaults, and lmvm on 2 ranks: each converges, its force
balances the reaction within what its own gradient allows, and its P is
Newton's to 1e-8, the criterion of "the same answer" that test_robustness
applies to Newton's 1 and 2 ranks (measured 8.8e-11 to 4.1e-9 here, 1 against
2 ranks 0 to 1.9e-9)."""
import math

import numpy as np
import pytest

from conftest import run_contact

EPS = np.finfo(float).eps
HERTZ = ["-options_file", "meshes/hertz/hertz.opts", "-tao_gttol", "1e-12", "-output", "none"]


@pytest.fixture(scope="module")
def newton(tmp_path_factory):
    return run_contact(HERTZ, tmp_path_factory.mktemp("newton")).summary


@pytest.mark.parametrize("tao", ["lmvm", "blmvm"])
def test_lmvm_reaches_newton(tao, newton, tmp_path):
    """P and the energy to Newton's: measured 1.97e-12 and 2.44e-15 = 11 EPS
    (lmvm and blmvm alike, with their default continuation; 1.85e-12 and 3
    EPS before mortar's gradient followed its Gauss points' motion with the
    crossings), bounds 1e-11 = 10 gttol and 32 EPS (the quasi-Newton iteration
    converges linearly, so it stops just below its tolerance, where Newton's
    last quadratic step lands far below it);
    H0 set up once and then at every iteration (-lmvm_h0_refresh 1), so
    h0_refreshes equals the iterations."""
    s = run_contact(HERTZ + ["-tao_type", tao], tmp_path).summary
    dP = abs(s["contact_force"] / newton["contact_force"] - 1)
    dE = abs(s["energy"] / newton["energy"] - 1)
    print(f"{tao}: {s['iterations']} iterations, {s['h0_refreshes']} H0 set-ups; P {dP:.2e}, energy {dE:.2e}")
    assert dP <= 1e-11 and dE <= 32 * EPS
    assert s["h0_refreshes"] == s["iterations"]


def test_lmvm_refresh_period(tmp_path):
    """-lmvm_h0_refresh 3: H0 set up once, then at iterations 3, 6, ...:
    1 + floor((iterations - 1) / 3) set-ups (one stage: no continuation)."""
    s = run_contact(HERTZ + ["-tao_type", "lmvm", "-lmvm_h0_refresh", "3", "-penalty_stages", "1"], tmp_path).summary
    assert s["h0_refreshes"] == 1 + (s["iterations"] - 1) // 3, (s["iterations"], s["h0_refreshes"])


def test_lmvm_h0_elastic(newton, tmp_path):
    """-lmvm_h0 elastic, the stiffness K alone as L-BFGS's initial Hessian
    (no contact part, so none of the contact H0's set-ups and no penalty
    continuation): it converges on the reference scene at the default stop
    to Newton's P within 3e-7 (measured 8.8e-8; the quasi-Newton iteration
    converges linearly and stops just below its tolerance), in many more
    iterations than the contact H0 (measured 316 against 18, printed, not
    asserted), which is why the contact H0 is the default. Asked for -tao_gttol 1e-12, as the contact
    H0 is above, it does not get there (measured: the line search fails
    after 2540 iterations, the load cut back 4 times), so this test runs at
    the default stop."""
    args = [a for a in HERTZ if a not in ("-tao_gttol", "1e-12")]
    s = run_contact(args + ["-tao_type", "lmvm", "-lmvm_h0", "elastic"], tmp_path).summary
    dP = abs(s["contact_force"] / newton["contact_force"] - 1)
    print(f"elastic H0: {s['iterations']} iterations ({s['tao_reason']}), P {dP:.2e} from Newton's")
    assert s["converged"] and "h0_refreshes" not in s
    assert dP <= 3e-7


HALF = ["-options_file", "meshes/hertz-half/hertz-half.opts", "-block_bc_push_values", "-0.3,0", "-output", "none"]
CASES = [(0.25, 1e10, "gpts"), (0.25, 1e10, "mortar"), (0.1, 1e10, "gpts"), (0.1, 1e10, "mortar"),
         (0.1, 1e3, "gpts"), (0.1, 1e3, "mortar")]


def _case_args(h, kp, formulation):
    return HALF + ["-mesh_size", h, "-contact_penalty", f"{kp:g}", "-contact_formulation", formulation]


@pytest.fixture(scope="module")
def newton_cases(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("newton-cases")
    return {c: run_contact(_case_args(*c), tmp, name=f"{c[0]}-{c[1]:g}-{c[2]}").summary for c in CASES}


@pytest.mark.parametrize("tao,ranks", [("lmvm", 1), ("blmvm", 1), ("lmvm", 2),
                                       pytest.param("blmvm", 2, marks=pytest.mark.stress)])
@pytest.mark.parametrize("case", CASES, ids=[f"h{c[0]}-kp{c[1]:g}-{c[2]}" for c in CASES])
def test_lmvm_robust(case, tao, ranks, newton_cases, tmp_path):
    s = run_contact(_case_args(*case) + ["-tao_type", tao], tmp_path, ranks=ranks).summary  # exit 0: converged
    ref = newton_cases[case]
    f = s["contact"]["interface"]["force"][0]
    reaction = s["reactions"]["block:push"][0]
    bound = math.sqrt(s["dofs"]) * s["gradient_norm"] + 1000 * EPS * abs(reaction)
    dP = abs(s["contact_force"] / ref["contact_force"] - 1)
    print(f"{tao} on {ranks}: {s['iterations']} iterations ({s['stages']} stages, {s['h0_refreshes']} H0 set-ups, "
          f"{s['lmvm_pairs_dropped']} pairs dropped, {s['lmvm_restarts']} restarts; Newton {ref['iterations']}); "
          f"P {s['contact_force']:.12g}, {dP:.1e} from Newton's; imbalance {abs(abs(f) - abs(reaction)) / bound:.2e} of its bound")
    assert abs(abs(f) - abs(reaction)) <= bound   # the balance test_robustness asserts, from the run's own gradient
    assert dP <= 1e-8


def test_lmvm_ranks(tmp_path):
    """The reference scene at h = 0.06 on 1 and 2 ranks: the same P, a result
    and not the path (the iteration counts are not compared), to 1e-8 of
    P: each run stops at the default gradient tolerance, which leaves up to
    4.1e-9 of P between L-BFGS and Newton (this file's docstring), so two
    paths that stop at different iterates may differ by that much
    (measured 2e-12 at h = 0.015)."""
    args = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", 0.06, "-output", "none", "-tao_type", "lmvm"]
    s = {n: run_contact(args, tmp_path, ranks=n, name=f"np{n}").summary for n in (1, 2)}
    dP = abs(s[2]["contact_force"] / s[1]["contact_force"] - 1)
    print(f"iterations {s[1]['iterations']} and {s[2]['iterations']}; P {dP:.1e} apart")
    for n in (1, 2):
        assert s[n]["converged"]
    assert dP <= 1e-8


@pytest.mark.parametrize("formulation", ["gpts", "mortar"])
def test_lmvm_ranks_stiff(formulation, tmp_path):
    """At a stiff penalty (the half scene at h = 0.1, k_p = 1e10, push 0.3:
    k_p h / E* = 1.7e6) the default continuation starts where k_p h / E* is
    1 and climbs by at most 32 a stage: 1 + ceil(log_32(k_p h / E*)) stages
    (6), from the JSON's penalty_stiffness. 1 and 2 ranks reach the same P to
    3e-9, the default stop's share (measured 5.4e-10 to 7.4e-10 with gpts,
    1.0e-10 to 1.0e-9 with mortar; the
    iterations, a path, are printed and not compared: measured equal, gpts
    30 and mortar 21). With
    the first stage at 1e-3 k_p, as before (k_p h / E* = 1.7e3 there), they
    took 53 and 59 (gpts) and 71 and 128 iterations (mortar, the 2 ranks
    after a cutback)."""
    args = _case_args(0.1, 1e10, formulation) + ["-tao_type", "lmvm"]
    s = {n: run_contact(args, tmp_path, ranks=n, name=f"np{n}").summary for n in (1, 2)}
    stiff = s[1]["contact"]["interface"]["penalty_stiffness"]
    dP = abs(s[2]["contact_force"] / s[1]["contact_force"] - 1)
    print(f"k_p h / E* = {stiff:.3g}: {s[1]['stages']} stages; iterations {s[1]['iterations']} and "
          f"{s[2]['iterations']}; P {dP:.1e} apart")
    assert s[1]["stages"] == 1 + math.ceil(math.log(stiff) / math.log(32)) and s[1]["load_cutbacks"] == 0
    assert s[2]["converged"]
    assert dP <= 3e-9


@pytest.mark.parametrize("case", ["hertz", "half-kp1e10"])
def test_lmvm_decrement(case, tmp_path):
    """-lmvm_decrement_rtol 1e-12 (the last stage stops on the decrement in
    H0's norm instead of the gradient): P to Newton's within 1e-11 on the
    reference scene (Newton solved to -tao_gttol 1e-12; measured 1.9e-12)
    and within 5e-9 on the coarse mortar half scene at k_p = 1e10, push 0.3
    (Newton at its default stop; measured 1.6e-9), where -tao_gttol 1e-11 stops at the gradient's round-off;
    one decrement solve per iteration after the first of the last stage."""
    args = HERTZ if case == "hertz" else _case_args(0.25, 1e10, "mortar")
    ref = run_contact(args, tmp_path, name="newton").summary
    s = run_contact(args + ["-tao_type", "lmvm", "-lmvm_decrement_rtol", "1e-12"], tmp_path, name="lmvm").summary
    dP = abs(s["contact_force"] / ref["contact_force"] - 1)
    print(f"{s['iterations']} iterations ({s['tao_reason']}), {s['lmvm_decrement_solves']} decrement solves; P {dP:.1e}")
    assert s["tao_reason"] == "CONVERGED_USER"
    assert dP <= (1e-11 if case == "hertz" else 5e-9)
    assert 0 < s["lmvm_decrement_solves"] <= s["iterations"] + 1


def test_lmvm_decrement_default(tmp_path):
    """Without -lmvm_decrement_rtol, the last stage stops on the decrement
    (r = 1e-13) where a pair's k_p h / E* exceeds 1e4 (the coarse mortar half
    scene at k_p = 1e10: 3.8e6) and no gradient tolerance is given, and on
    the gradient tolerances otherwise: -tao_gttol given there, or the
    reference scene's k_p = 2e6 (k_p h / E* = 347 at h = 0.1). At the stiff
    penalty 1 and 2 ranks give the same P to 1e-8 (measured 1.9e-9; each
    stops on the decrement at 1e-13, which leaves that much)."""
    stiff = _case_args(0.25, 1e10, "mortar") + ["-tao_type", "lmvm"]
    s = {n: run_contact(stiff, tmp_path, ranks=n, name=f"np{n}").summary for n in (1, 2)}
    dP = abs(s[2]["contact_force"] / s[1]["contact_force"] - 1)
    print(f"stiff: {s[1]['iterations']} and {s[2]['iterations']} iterations ({s[1]['tao_reason']}), P {dP:.1e} apart")
    assert s[1]["tao_reason"] == "CONVERGED_USER" and s[1]["lmvm_decrement_solves"] > 0
    assert s[2]["converged"]
    assert dP <= 1e-8
    given = run_contact(stiff + ["-tao_gttol", "1e-10"], tmp_path, name="gttol").summary
    ref = run_contact(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", 0.1, "-output", "none",
                       "-tao_type", "lmvm"], tmp_path, name="ref").summary
    for r in (given, ref):
        assert r["tao_reason"] == "CONVERGED_GATOL" and "lmvm_decrement_solves" not in r


@pytest.mark.parametrize("rtol", ["1e-13", "1e-14"])
def test_lmvm_decrement_floor(rtol, tmp_path):
    """-lmvm_decrement_rtol at and beside the decrement's round-off floor on
    the coarse mortar half scene at k_p = 1e10, push 0.3 (the decrement's
    round-off is 7e-15 to 2.5e-14 of the first iterate's). 1e-13, above the
    floor, stops on the decrement with no floor stop. 1e-14 asks for less
    than the floor allows on some machines and not on others: there the last
    stage's line search may fail within 10 of the tolerance, and the solve
    then ends converged (TAO reason CONVERGED_USER, at most one floor stop;
    measured one, 30 iterations). Either way no cutback, and P within 1e-8 of
    Newton's (each stop's share). Below the factor of 10 it is not a floor:
    1e-15 cuts the load back 4 times and stops (DIVERGED_LS_FAILURE after 602
    iterations), which is not asserted (a machine with less round-off could
    converge)."""
    args = _case_args(0.25, 1e10, "mortar")
    ref = run_contact(args, tmp_path, name="newton").summary
    s = run_contact(args + ["-tao_type", "lmvm", "-lmvm_decrement_rtol", rtol], tmp_path, name="lmvm").summary
    dP = abs(s["contact_force"] / ref["contact_force"] - 1)
    print(f"{rtol}: {s['iterations']} iterations ({s['tao_reason']}), {s['lmvm_decrement_floor_stops']} floor stops; P {dP:.1e}")
    assert s["tao_reason"] == "CONVERGED_USER" and s["load_cutbacks"] == 0
    assert s["lmvm_decrement_floor_stops"] == (0 if rtol == "1e-13" else s["lmvm_decrement_floor_stops"])
    assert s["lmvm_decrement_floor_stops"] <= 1
    assert dP <= 1e-8


@pytest.mark.parametrize("funcs", ["3", "4"])
def test_lmvm_restarts(funcs, tmp_path):
    """-lmvm_restarts: a line search held to a strict curvature condition
    (-tao_ls_gtol 1e-3) with few evaluations (-tao_ls_max_funcs 3, and the
    neighbour 4) fails in L-BFGS's first stage on the reference scene. At
    the default (50 restarts) the solve restarts from where it stopped
    (measured: 1 restart, no load cutback, 17 iterations); with
    -lmvm_restarts 0 the failure goes to the load cutback instead (3
    cutbacks, 68 iterations). Both end at Newton's P within 1e-8, the
    criterion of test_robustness (measured 1.1e-11 and 4.9e-11 at either
    funcs), so the restart changes the path and not the answer."""
    opts = ["-options_file", "meshes/hertz/hertz.opts", "-output", "none"]
    ls = ["-tao_type", "lmvm", "-tao_ls_gtol", "1e-3", "-tao_ls_max_funcs", funcs]
    ref = run_contact(opts, tmp_path, name="newton").summary
    on = run_contact(opts + ls, tmp_path, name="restarts").summary
    off = run_contact(opts + ls + ["-lmvm_restarts", "0"], tmp_path, name="norestart").summary
    print({k: (s["lmvm_restarts"], s["load_cutbacks"], s["iterations"], abs(s["contact_force"] / ref["contact_force"] - 1))
           for k, s in (("on", on), ("off", off))})
    assert on["lmvm_restarts"] >= 1 and on["load_cutbacks"] == 0
    assert off["lmvm_restarts"] == 0 and off["load_cutbacks"] >= 1
    for s in (on, off):
        assert abs(s["contact_force"] / ref["contact_force"] - 1) <= 1e-8
