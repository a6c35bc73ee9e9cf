"""The mortar formulation (-contact_formulation mortar) on curved contact: its
pressure converges under refinement, without oscillation, to Hertz where Hertz
holds, the same at every rank count and through either Newton step. Expected
values come from a finer mesh of the same model, from Hertz's solution at
a/R = 0.1, and from other rank counts. (The contact patch test, exact to
round-off, is tests/test_patch_contact.py.)"""
import math

import numpy as np
import pytest

from conftest import HALF_MORTAR_H, run_contact, is_force_key
from test_contact import RANK_DEPENDENT, flatten

import profile_metrics as pm

EPS = np.finfo(float).eps
MORTAR = ["-contact_formulation", "mortar"]
HALF = ["-options_file", "meshes/hertz-half/hertz-half.opts"] + MORTAR
HS, HREF = list(HALF_MORTAR_H[:-1]), HALF_MORTAR_H[-1]   # 0.1, 0.06, 0.03, 0.015 and the finest, 0.007


@pytest.fixture
def half(half_mortar_runs):
    """The half reference scene (mirrored: the full scene's contact) at HS and
    the finer HREF (conftest.py's session runs), each checked as a test reads
    it (a failed run fails the tests that read it, each naming it)."""
    class Checked(dict):
        def __getitem__(self, h):
            r = dict.__getitem__(self, h)
            assert r.returncode == 0, f"half scene, mortar, h = {h}: exit {r.returncode}\n{r.stdout[-2000:]}\n{r.stderr[-2000:]}"
            return r
    return Checked(half_mortar_runs)


def indenter(run):
    """The slave profile (s, p, w, gap): the pair's first surface, the indenter's arc."""
    return pm.profiles(run.output_path)[0]["indenter_contact"]


def test_convergence(half):
    """The profile's L2 distance from the finest mesh falls monotonically at an
    observed rate of at least 0.9 (least-squares fit over h) and is at most 3 %
    at h = 0.03; from h = 0.03 p_max is within 0.2 % of the finest (measured
    +0.06 and +0.02 %), the half-width within 1.6 % (measured -0.51 and
    -0.44 %: the zone's ends are found between nodes) (L2 measured 4.25,
    1.93, 1.24, 0.49 %; rate 1.08)."""
    ref = indenter(half[HREF])
    d = [pm.l2_distance(indenter(half[h]), ref) for h in HS]
    rate = np.polyfit(np.log(HS), np.log(d), 1)[0]
    pref, aref = ref[1].max(), pm.half_width(*ref)
    print("L2 distance from h =", HREF, ":", [f"{100 * x:.2f} %" for x in d], f"rate {rate:.2f}")
    assert all(b < a for a, b in zip(d, d[1:])), d
    assert rate >= 0.9
    assert d[HS.index(0.03)] <= 0.03
    for h in HS[HS.index(0.03):]:
        p = indenter(half[h])
        print(f"h = {h}: p_max {p[1].max():.5g} ({p[1].max() / pref - 1:+.2%}), a {pm.half_width(*p):.5g} "
              f"({pm.half_width(*p) / aref - 1:+.2%})")
        assert abs(p[1].max() / pref - 1) <= 0.002
        assert abs(pm.half_width(*p) / aref - 1) <= 0.016


def test_no_oscillation(half, tmp_path):
    """The oscillation index (profile_metrics.oscillation: the largest deviation
    of a sample from the mean of its two neighbours, less that of the Hertz
    profile with the profile's computed peak and half-width centred at its
    pressure centroid, within 0.8 a of the centre, over the peak) is at
    most 0.01 for h <= 0.03 and 0.05 for h = 0.05 to 0.08.
    Measured: the half reference scene 0.0188 at h = 0.06, 0.0008 at 0.03,
    0.0002 at 0.015 (0.0074 at 0.1, printed only); hertz-graded 0.0023 at
    h = 0.06 and 0.0026 at its own 0.03; hertz-small and twodiscs, meshed at
    0.004 near the contact, 0.0011 and 0.0044. At a/h about 6 the index
    depends on where the zone's edge falls among the nodes: its neighbours
    h = 0.05, 0.055, 0.065, 0.07, 0.075 and 0.08 measured 0.0104, 0.0025,
    0.0023, 0.0106, 0.0233 and 0.0129 (docs/formulations.md's table), so
    that 0.025 is met at h = 0.06 but is not a bound there: the coarse
    meshes h = 0.05 to 0.08 are held to 0.05, twice the largest."""
    for h in HS:
        osc = pm.oscillation(*indenter(half[h]))
        print(f"hertz-half, h = {h}: oscillation index {osc:.4f}")
        if h <= 0.03:
            assert osc <= 0.01
        elif h == 0.06:
            assert osc <= 0.05
    for h in (0.05, 0.055, 0.065, 0.07, 0.075, 0.08):
        r = run_contact(HALF + ["-mesh_size", h, "-summary", "none"], tmp_path, name=f"half-{h}")
        osc = pm.oscillation(*indenter(r))
        print(f"hertz-half, h = {h}: oscillation index {osc:.4f}")
        assert osc <= 0.05
    cases = [("hertz-graded", [], 0.01), ("hertz-graded", ["-mesh_size", "0.06"], 0.025),
             ("hertz-small", [], 0.01), ("twodiscs", [], 0.01)]
    for i, (scene, extra, bound) in enumerate(cases):
        r = run_contact(["-options_file", f"meshes/{scene}/{scene}.opts"] + MORTAR + extra + ["-summary", "none"],
                        tmp_path, name=f"{scene}-{i}")
        (prof,) = pm.profiles(r.output_path)[0].values()
        osc = pm.oscillation(*prof)
        print(f"{scene} {' '.join(extra)}: oscillation index {osc:.4f}")
        assert osc <= bound


@pytest.mark.parametrize("n", [6, 12, 24, 48])
def test_hertz_small(n, tmp_path):
    """Where Hertz holds (hertz-small, a/R = 0.10), meshed with a/h = n elements
    across the half-width (size a/n within 0.14 of the first contact point):
    profile L2 error against Hertz at most 2.6, 0.85, 0.6, 0.7 % (2.5 times
    the measured 1.04, 0.34, 0.22, 0.28 %: from a/h = 24 on, Hertz's own
    error at a/R = 0.1, about 0.3 %, is what remains), p_max within 0.6 %
    from a/h = 12 (measured +0.23, +0.21, +0.21 %)."""
    hc = 0.1036 / n
    geo = f"hc={hc:.6g},rc=0.14,dc=0.3"
    r = run_contact(["-options_file", "meshes/hertz-small/hertz-small.opts"] + MORTAR +
                    ["-indenter_geo_params", "R=1,xc=-1,yc=0,xclamp=-1.8,xcontact=-0.5," + geo,
                     "-block_geo_params", "x0=0,W=1,H=2," + geo, "-output", "none"], tmp_path, timeout=900)
    s = r.summary
    print(f"a/h = {n}: L2 {100 * s['pressure_l2_error']:.2f} %, p_max {s['fem_pmax'] / s['hertz_pmax'] - 1:+.2%}, "
          f"a {s['fem_a'] / s['hertz_a'] - 1:+.2%}, dofs {s['dofs']}")
    assert s["pressure_l2_error"] <= {6: 0.026, 12: 0.0085, 24: 0.006, 48: 0.007}[n]
    if n >= 12:
        assert abs(s["fem_pmax"] / s["hertz_pmax"] - 1) <= 0.006


def test_ranks(tmp_path):
    """1, 2, 3 and 4 ranks: every number of the JSON summary (but timings, the
    run id, the rank count, the stopping residual) agrees to 1e-8 (a near-zero force
    component to 1e-8 of the pair's force): measured over the OpenBLAS kernels
    Nehalem, Sandybridge, Haswell and SkylakeX at most 1.6e-9, always a y
    reaction (4.5e-7 of P, a sum that cancels) relative to itself. Catches a
    figure that is one rank's share or sums a shared node twice."""
    base = ["-options_file", "meshes/hertz/hertz.opts"] + MORTAR + ["-tao_gttol", "1e-13"]
    runs = [run_contact(base, tmp_path, ranks=n, name=f"np{n}") for n in (1, 2, 3, 4)]
    ref = flatten(runs[0].summary)
    scale = runs[0].summary["contact_force"]
    for n, r in zip((2, 3, 4), runs[1:]):
        got = flatten(r.summary)
        assert set(got) == set(ref)
        worst = (0.0, "")
        for k, a in ref.items():
            if k.startswith(RANK_DEPENDENT):
                continue
            b = got[k]
            if isinstance(a, (int, float)) and not isinstance(a, bool):
                floor = 1e-8 * scale if is_force_key(k) else 0.0
                worst = max(worst, (abs(a - b) / (max(abs(a), abs(b)) + floor / 1e-8 or 1.0), k))
                assert abs(a - b) <= 1e-8 * max(abs(a), abs(b)) + floor, f"{k}: {a} at 1 rank, {b} at {n}"
            else:
                assert a == b, f"{k}: {a} at 1 rank, {b} at {n}"
        print(f"{n} ranks: largest relative difference {worst[0]:.2e} ({worst[1]})")


def test_schur_step(tmp_path):
    """The Newton step through the Schur complement on the contact surfaces
    (the default on one rank) and a full factorisation per step give the same
    answer: the mortar Hessian stays in the surface block (an entry outside
    it, dropped by the Schur step, gives another Newton path, which stops
    elsewhere within the stopping test). Measured over the OpenBLAS kernels Nehalem,
    Sandybridge, Haswell and SkylakeX: P 1.5e-14 to 1.7e-13 apart, bound 5e-13
    (was 1e-8); the energy 3.3e-16 to 6.7e-16 = 3 EPS, bound 100 EPS (was
    1e-10)."""
    base = ["-options_file", "meshes/hertz/hertz.opts"] + MORTAR + ["-tao_gttol", "1e-12", "-output", "none"]
    a = run_contact(base, tmp_path, name="schur").summary
    b = run_contact(base + ["-newton_schur", "0"], tmp_path, name="full").summary
    print(a["iterations"], b["iterations"], a["contact_force"], b["contact_force"],
          f"P {a['contact_force'] / b['contact_force'] - 1:.2e}, energy {a['energy'] / b['energy'] - 1:.2e}")
    assert abs(a["contact_force"] / b["contact_force"] - 1) <= 5e-13
    assert abs(a["energy"] / b["energy"] - 1) <= 100 * EPS


@pytest.mark.parametrize("kernels", ["Nehalem"])   # Sandybridge and Haswell: the same figures (measured); kept out for make test's time
def test_blas_kernels(kernels, half, tmp_path):
    """The finest half run (h = 0.007, whose first Newton step from rest pushes
    the disc about 0.1 into the block) converges to the same answer with
    OpenBLAS's kernels for other processors (OPENBLAS_CORETYPE; the machine's
    own are used by the fixture): the rounding of another machine must not
    decide whether Newton converges. Before the search lost its reach limit
    and the master's ends their cut-off, Nehalem's, Sandybridge's and
    Haswell's failed at h = 0.005 (DIVERGED_LS_FAILURE after 2 iterations,
    as did Zen's) and SkylakeX converged. Both solved to gttol 1e-12 (the
    fixture's), where every path ends at round-off: measured at h = 0.007
    with Nehalem and Haswell against this machine's SkylakeX (9 iterations
    each), P 1.6e-14 apart at most, bound 2e-13 (at h = 0.005 5.1e-14; at the
    default 1e-8 the paths stopped 2.4e-8 apart, and the bound was 1e-6); the
    energy 5.9e-14 at most (1.3e-13 at 0.005), bound 4e-13 (was 1e-10).
    Catches a solve that stops at another answer with other kernels (a
    stopping test on a residual that depends on the summation order)."""
    ref = half[HREF]
    r = run_contact(HALF + ["-mesh_size", str(HREF), "-output", "none", "-tao_gttol", "1e-12"], tmp_path, timeout=900,
                    env={"OPENBLAS_CORETYPE": kernels}, check=False)
    assert r.returncode == 0, f"{kernels}: exit {r.returncode}\n{r.stdout[-2000:]}"
    a, b = ref.summary, r.summary
    print(f"{kernels}: P {b['contact_force'] / a['contact_force'] - 1:.2e}, energy {b['energy'] / a['energy'] - 1:.2e}")
    assert abs(b["contact_force"] / a["contact_force"] - 1) <= 2e-13
    assert abs(b["energy"] / a["energy"] - 1) <= 4e-13


@pytest.mark.parametrize("tao_type", ["nls", "lmvm"])
def test_energy_continuous_at_mirror_line(tao_type, tmp_path):
    """The half scene's slave node on the mirror line is as close to the
    master's end edge as to its image, and round-off picks either. Taken as
    two regions, the choice made MortarSplit cut that edge to its depth limit
    at some states and not at others, so the energy jumped by the change of
    its quadrature error: 1.389e-9 (2.8e-7 of it) at k_p = 1e10, h = 0.25,
    push 0.01, where L-BFGS's line search failed and the load was cut back 3
    times (41 iterations). A Taylor test whose steps are 1e-11 to 8e-14 of
    max |u| (-taylor_scale 1e-11) measures that: for a continuous energy the
    remainder is round-off, the eps^2 term far below it (measured 9e-19 to
    8e-18 against |E| = 4.9e-3; before, the jump at 2 of the 8 steps with nls,
    1 with lmvm, 6 at the iterate where the line search failed). L-BFGS then
    converges without a cutback (7 iterations)."""
    s = run_contact(HALF + ["-mesh_size", "0.25", "-contact_penalty", "1e10", "-block_bc_push_values", "-0.01,0",
                            "-tao_type", tao_type, "-taylor_test", "-taylor_scale", "1e-11", "-output", "none"], tmp_path).summary
    rem = s["taylor"]["gradient_remainder"]
    print(tao_type, s["iterations"], s["load_cutbacks"], s["energy"], rem)
    assert max(rem) <= 1e-13 * abs(s["energy"])
    assert s["load_cutbacks"] == 0
