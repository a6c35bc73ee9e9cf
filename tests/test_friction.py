"""Coulomb friction (src/contact/friction.c on mortar's points, the state
lifecycle of the energy terms driven by src/solver/staging.c):
-contact_friction and -contact_<pair>_friction MU.

The reference is Cattaneo-Mindlin on meshes/cattaneo: an elastically similar
disc on a slab, force-controlled, the normal force P = 1.075 in the first load
stage, then the tangential force Q = 0.5 mu P with P held (mu = 0.3), 8
increments a stage. A central zone |x| < c sticks, c/a = sqrt(1 - Q/(mu P)) =
0.70711; where a node slips its shear is mu p, against its slip. The scene's
bodies are finite (a wide slab, a/R = 0.05) and its contact edges
hc = 0.00375 (a/hc = 13)."""
import json
import os

import h5py
import numpy as np
import pytest

import friction_study
from conftest import GETFEM_PYTHON, ROOT, figure, getfem_available, run_contact

CATTANEO = ["-options_file", "meshes/cattaneo/cattaneo.opts"]
HERTZ = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.1"]
MU, P, Q = friction_study.MU, friction_study.P, friction_study.Q   # the scene's friction, normal and tangential force (0.5 mu P)
SLAVE = "contact/interface/disc_contact"


class LazyRuns(dict):
    """{ranks: run}, each run made the first time a test asks for it (make
    test asks for 1 rank only; make test-kernels for 2 as well)."""

    def __init__(self, make):
        super().__init__()
        self.make = make

    def __missing__(self, n):
        self[n] = self.make(n)
        return self[n]


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """The cattaneo scene on 1 and 2 ranks."""
    tmp = tmp_path_factory.mktemp("cattaneo")
    return LazyRuns(lambda n: run_contact(CATTANEO, tmp, ranks=n, name=f"np{n}"))


def nodal(res):
    """The slave surface's nodal sets: arc position, pressure, shear, slip, stick."""
    with h5py.File(res.output_path, "r") as f:
        g = f[SLAVE]
        return {k: g[f"node_{k}"][:] for k in ("s", "pressure", "shear", "slip", "stick")}


def test_cattaneo_stick_zone(runs):
    """The stick zone's half-width c (the JSON's stick_half_width, from the
    nodes node_stick marks, each end carried to where the shear reaches mu p)
    over the contact's half-width a (the report's second-moment half-width,
    a_moment) is Mindlin's sqrt(1 - Q/(mu P)) = 0.70711: `c_over_a_error` =
    0.0036 (+0.36 %; the README's friction table has +0.43 % at hc = 0.0075
    and +0.34 % at hc = 0.001875). Bound 2 % (the issue's). The first
    stage's zone, under P alone, is nearly the whole contact: `stage1_c_over_a`
    = 0.9994 (the finite disc and slab are not Dundurs' half-spaces, and
    their surfaces spread a little differently at the zone's edges, which
    slip); bounds: at least 0.9 a, and within the contact, at most a plus a
    node spacing (hc = 0.00375: a_moment is an estimate of the edge, not a
    bound on it)."""
    s = runs[1].summary
    pair = s["contact"]["interface"]
    c, a = pair["stick_half_width"], pair["fem_a_moment"]
    theory = np.sqrt(1 - Q / (MU * P))
    err = figure("c_over_a_error", c / a / theory - 1)
    c1 = s["load_stages"][0]["stick_half_width"]["interface"]
    figure("stage1_c_over_a", c1 / a)
    print(f"c = {c:.6f}, a = {a:.6f}, c/a = {c / a:.5f}, Mindlin {theory:.5f}; stage 1: c = {c1:.5f}")
    assert abs(err) <= 0.02
    assert 0.9 * a <= c1 <= a + 0.00375


def test_cattaneo_load_steps(runs, tmp_path):
    """The shear profile of the scene (8 increments a stage, each solved to
    the final tolerance, as every increment with friction) from Mindlin's
    in relative L2 over the slave's nodes (weights A_j), his drawn with the
    computed a (a_moment), p0 = 2 P / (pi a) and c = a sqrt(1 - Q/(mu P))
    about the pressure's centre: `l2_scene` = 0.027; in one increment a
    stage c/a `c_over_a_error_1` = 0.0052 and the profile `l2_1` = 0.041
    (the distance: friction_study.shear_l2, the README table's, which has
    the profile at 1, 2, 4, 8, 16 increments too). Bounds: c/a 2 % (the
    issue's), the profile 10 % (the issue's)."""
    l2 = figure("l2_scene", friction_study.shear_l2(runs[1].output_path, runs[1].summary, Q / (MU * P)))
    assert l2 <= 0.10
    res = run_contact(CATTANEO + ["-load_steps", "1"], tmp_path)
    pair = res.summary["contact"]["interface"]
    a, c = pair["surfaces"][0]["a_moment"], pair["stick_half_width"]
    l2 = figure("l2_1", friction_study.shear_l2(res.output_path, res.summary, Q / (MU * P)))
    err = figure("c_over_a_error_1", c / a / np.sqrt(1 - Q / (MU * P)) - 1)
    assert abs(err) <= 0.02
    assert l2 <= 0.10


@pytest.mark.parametrize("ratio", [0.2, 0.8])
def test_cattaneo_other_loads(ratio, tmp_path):
    """The same at Q/(mu P) = 0.2 and 0.8: c/a against sqrt(1 - Q/(mu P))
    = 0.8944 and 0.4472, `c_over_a_error_0.2` = 0.0034 and
    `c_over_a_error_0.8` = -0.0129, the shear profile from Mindlin's
    `l2_0.2` = 0.062 and `l2_0.8` = 0.021 (a/hc = 13; the small stick zone
    of 0.8 has 6 edges, 12 nodes, across its half; the README's friction
    table has these at hc = 0.0075 and 0.001875 too, and with the contact
    twice as wide against the bodies, a/R = 0.1: the finite bodies' part,
    docs/scenes.md#friction). Bounds: c/a 2 % (the issue's), the profile
    10 % (the issue's). The report's mindlin_c (Hertz's a, the whole force
    across the contact zone's chord as Q, 0.5 % above the load: the slab's
    face tilts under the shear) is within 2 % of c: `mindlin_c_error_0.2` =
    -0.0044, `mindlin_c_error_0.8` = 0.0002 (an independent figure of the
    program's, bound 2 %)."""
    q = ratio * MU * P
    res = run_contact(CATTANEO + ["-disc_bc_clamp_values", f"{P},0,{P},{q!r}"], tmp_path)
    pair = res.summary["contact"]["interface"]
    err = figure(f"c_over_a_error_{ratio}", pair["stick_half_width"] / pair["fem_a_moment"] / np.sqrt(1 - ratio) - 1)
    l2 = figure(f"l2_{ratio}", friction_study.shear_l2(res.output_path, res.summary, ratio))
    dm = figure(f"mindlin_c_error_{ratio}", pair["mindlin_c"] / pair["stick_half_width"] - 1)
    assert abs(err) <= 0.02
    assert l2 <= 0.10
    assert abs(dm) <= 0.02


def test_mindlin_deresiewicz(tmp_path):
    """Unloading from Q* = 0.6 mu P to 0 (a third stage): the edges slip
    backwards and the stick zone of the last increment is Mindlin-
    Deresiewicz's c'/a = sqrt(1 - Q*/(2 mu P)) = 0.83666:
    `unloaded_error` = 0.0040; Q*'s own zone, sqrt(0.4) = 0.63246:
    `qstar_error` = 0.0058. Bounds 2 % and 2.5 % (the issue's 3 % for
    c'). The slip state is carried from stage to stage: a solve that
    forgot it would stick everywhere after the unloading's first increment.
    Each stage's end has its friction sets in the HDF5: the stuck nodes'
    half extent against the JSON's half-width, `extent_gap` = 9.3e-4 at
    most (the JSON's ends are carried between nodes), bound a node spacing
    (hc / 2 = 0.001875 on the graded arc). This run is its own, not the
    module's scene: its second stage is at Q*, not Q, and a stage that is
    not the last is solved to the stop of an intermediate load (the force
    control's last load stops relative to its own gradient)."""
    qs = 0.6 * MU * P
    res = run_contact(CATTANEO + ["-load_stages", "3", "-disc_bc_clamp_values", f"{P},0,{P},{qs!r},{P},0",
                                  "-slab_bc_push_values", "0,0,0,0,0,0"], tmp_path)
    s = res.summary
    a = s["contact"]["interface"]["fem_a_moment"]
    c = [st["stick_half_width"]["interface"] / a for st in s["load_stages"]]
    print(f"c/a per stage {c}, theory {np.sqrt(0.4):.5f} and {np.sqrt(0.7):.5f}")
    assert abs(figure("qstar_error", c[1] / np.sqrt(0.4) - 1)) <= 0.025
    assert abs(figure("unloaded_error", c[2] / np.sqrt(0.7) - 1)) <= 0.02
    # each stage's end in the HDF5 (/stages/k/contact/...; the last is /contact's)
    gaps = []
    with h5py.File(res.output_path, "r") as f:
        arc = f[SLAVE]["node_s"][:]
        for k, st in enumerate(s["load_stages"], 1):
            stuck = f[f"stages/{k}/{SLAVE}" if k < 3 else SLAVE]["node_stick"][:] > 0.5
            half = (arc[stuck].max() - arc[stuck].min()) / 2
            print(f"stage {k}: stuck nodes' half extent {half:.5f}, JSON {st['stick_half_width']['interface']:.5f}")
            gaps.append(abs(half - st["stick_half_width"]["interface"]))
    assert figure("extent_gap", max(gaps)) <= 0.001875


@pytest.mark.roundoff
def test_cattaneo_forces_met(runs):
    """The controlled group's reactions (the program's sum of the clamp's
    nodal forces) are the given P and Q: `P_error` = 2.1e-16 to 6.4e-15
    and `Q_error` = 4.1e-15 to 1.3e-14 of each; the issue's requirement 1e-8 is the bound."""
    fc = runs[1].summary["force_control"]
    for entry, force, name in zip(fc, (P, Q), ("P_error", "Q_error")):
        err = figure(name, abs(entry["reaction"] - force) / force)
        assert err <= 1e-8, (entry, force)


def test_coulomb(runs):
    """At every node |q| <= mu p, p the converged nodal pressure (node_pressure,
    the mortar's at the solution), to 1e-6 of mu p_max (the issue's figure);
    where a node in contact slips, |q| = mu p to the same, and q has the
    sign of its slip. Measured: the largest |q| - mu p is `excess` = 0 (the
    written shear is the accepted state's, clipped at the bound the fixed
    point's last lag took from this pressure: a bookkeeping check), and
    every slipping node slipped along +s with q > 0 (Q pushes the disc along
    +y, which is +s on its arc; `slipping` = 16 nodes slip, `stuck` = 40
    stick; bounds at least 4 and 10): the accumulated slip node_slip has
    the tangential stage's sign here, whose slip is larger than the normal
    stage's at the zone's edges (the sign of the last increment's slip is
    not written)."""
    n = nodal(runs[1])
    p, q, stick, slip = n["pressure"], n["shear"], n["stick"], n["slip"]
    bound = 1e-6 * MU * p.max()
    excess = figure("excess", np.max(np.abs(q) - MU * p) / (MU * p.max()))
    slipping = (p > 0) & (stick == 0)
    figure("slipping", slipping.sum())
    figure("stuck", stick.sum())
    assert excess <= 1e-6
    assert slipping.sum() >= 4 and stick.sum() >= 10
    assert np.max(np.abs(np.abs(q[slipping]) - MU * p[slipping])) <= bound
    assert np.all(q[slipping] * slip[slipping] > 0)
    assert np.all(q[p == 0] == 0)


LAG_RTOL = 1e-8   # -contact_friction_lag_rtol's default (src/solver/problem.c)


@pytest.mark.roundoff
@pytest.mark.kernels
def test_ranks_agree(runs):
    """1 and 2 ranks, each its own solve: the nodal shear apart by `dq` =
    1.6e-11 to 2.1e-11 of its largest, the stick half-width by `dc` =
    9.4e-15 to 1.2e-12 (the sums'
    order differs). Bound from the stops: each increment's fixed point
    ends where the lagged bound mu p changed by at most
    -contact_friction_lag_rtol (1e-8) of mu p_max, so a slipping node's
    shear, and what a stuck one carries beside it, is its run's to that;
    two runs 2e-8 mu p_max apart, as a fraction of the largest shear (the
    half-width, carried to where the shear reaches mu p, moves with it
    relative to the zone). The Newton stop (-tao_gttol 1e-8) adds less: at
    -tao_gttol 1e-12 the figures were the same. A stick flag may differ only
    at a node whose |q| is within that bound of mu p (none did)."""
    a, b = (nodal(runs[n]) for n in (1, 2))
    ca, cb = (runs[n].summary["contact"]["interface"]["stick_half_width"] for n in (1, 2))
    qmax, bmax = np.abs(a["shear"]).max(), MU * a["pressure"].max()
    bound = 2 * LAG_RTOL * bmax / qmax
    dq = figure("dq", np.abs(a["shear"] - b["shear"]).max() / qmax)
    dc = figure("dc", abs(ca - cb) / ca)
    flipped = a["stick"] != b["stick"]
    edge = np.abs(np.abs(a["shear"]) - MU * a["pressure"]) <= bound * qmax
    print(f"bound {bound:.2e}; {flipped.sum()} stick flags differ")
    assert np.all(edge[flipped])
    assert dq <= bound
    assert dc <= bound


@pytest.mark.roundoff
@pytest.mark.kernels
def test_taylor(tmp_path):
    """The Taylor test at the cattaneo solution (the energy of the last
    increment), along a direction of 2e-5 of max |u| (-taylor_scale): its
    steps up to eps = 1/32 stay inside each slipping node's slip branch,
    where the default 1e-4 crosses the kink k_t |e| = mu p at all but the
    smallest step (the contact is small against the disc: a = 0.05). The
    energy's remainder falls at order 2 (`gradient_order_error` = 2.2e-7
    to 1.7e-6 off 2), the gradient's with the exact Hessian too
    (`hessian_order_error` = -8.0e-5 to 2.3e-4 off 2; the relative remainder at the
    smallest step `remainder` = 5.8e-7, round-off showing below it).
    Bounds: orders within 1e-3 of 2 (the round-off in the solution and the
    remainder moves the fitted order by up to 2.3e-4 from kernel to kernel;
    a missing Hessian term gives order 1), the smallest remainder 1.8e-6. With
    the default the report says that an order off 2 may be the steps
    crossing a kink, and that a smaller -taylor_scale keeps them inside;
    along 2e-5 it does not."""
    note = "may be the direction's steps crossing a kink of the energy"
    default = run_contact(CATTANEO + ["-taylor_test", "-output", "none"], tmp_path, name="default")
    assert note in default.stdout and "-taylor_scale (now 0.0001)" in default.stdout
    res = run_contact(CATTANEO + ["-taylor_test", "-taylor_scale", "2e-5"], tmp_path)
    assert note not in res.stdout
    t = res.summary["taylor"]
    assert abs(figure("gradient_order_error", t["gradient_order"] - 2.0)) <= 1e-3
    assert abs(figure("hessian_order_error", t["hessian_order"] - 2.0)) <= 1e-3
    assert figure("remainder", t["hessian_relative_remainder"][-1]) <= 1.8e-6


@pytest.mark.roundoff
def test_mu_zero_is_frictionless(tmp_path):
    """-contact_friction 0 is the frictionless run, bit for bit (the term has
    no friction at all); a friction of 1e-13, which runs the friction's
    machinery (the lag at the softer penalty stage's answer, the fixed point)
    gives the frictionless answer: the energy `dE` = 3.0e-15 to 3.1e-15 apart, P
    `dP` = 0 (relative). All three solved to -tao_gttol 1e-12, where Newton
    ends at round-off whatever path it took. Bound 1e-12: ten times mu, the
    most the shear can be of the pressure, plus the round-off."""
    args = HERTZ + ["-tao_gttol", "1e-12", "-output", "none"]
    base = run_contact(args, tmp_path, name="base").summary
    zero = run_contact(args + ["-contact_friction", "0"], tmp_path, name="zero").summary
    tiny = run_contact(args + ["-contact_friction", "1e-13"], tmp_path, name="tiny").summary
    for key in ("energy", "contact_force", "max_displacement", "displacement_norm"):
        assert zero[key] == base[key], key
    dE = figure("dE", abs(tiny["energy"] - base["energy"]) / abs(base["energy"]))
    dP = figure("dP", abs(tiny["contact_force"] - base["contact_force"]) / abs(base["contact_force"]))
    assert dE <= 1e-12 and dP <= 1e-12


@pytest.mark.parametrize("args,needle", [
    (["-contact_formulation", "gpts", "-contact_friction", "0.2"], "formulation gpts has no friction"),
    (["-contact_friction", "-0.1"], "option -contact_friction: must be a finite number >= 0"),
    (["-contact_interface_friction", "nan"], "option -contact_interface_friction: must be a finite number >= 0"),
    (["-contact_friction", "0.2", "-contact_mortar_slave", "both"], "friction needs one slave surface"),
    (["-contact_friction", "0.2", "-contact_friction_penalty", "0"], "option -contact_friction_penalty"),
    (["-contact_friction", "0.2", "-contact_friction_lag_rtol", "1"], "option -contact_friction_lag_rtol: must be in (0, 1), got 1"),
    (["-contact_friction", "0.2", "-contact_friction_lag_max_it", "0"], "option -contact_friction_lag_max_it: must be >= 1, got 0"),
])
def test_bad_friction(args, needle, tmp_path):
    """Friction where it cannot be: one line naming the option and value, status 1, nothing written."""
    res = run_contact(HERTZ + ["-mesh_size", "0.3"] + args, tmp_path, check=False)
    lines = [l for l in res.stderr.splitlines() if l.strip()]
    print(lines)
    assert res.returncode == 1
    assert len(lines) == 1 and lines[0].startswith("contact: error: ") and needle in lines[0]
    assert not res.output_path.exists()


@pytest.mark.parametrize("args,needle", [
    (["-options_file", "meshes/hertz-half/hertz-half.opts", "-mesh_size", "0.3", "-contact_friction", "0.2"],
     "friction in a mirrored half model is not implemented"),
])
def test_bad_friction_scene(args, needle, tmp_path):
    """Friction where the formulation lacks it as yet (a mirrored half model): one line, status 1."""
    res = run_contact(args, tmp_path, check=False)
    lines = [l for l in res.stderr.splitlines() if l.strip()]
    print(lines)
    assert res.returncode == 1
    assert len(lines) == 1 and needle in lines[0]
    assert not res.output_path.exists()


@pytest.mark.parametrize("args,needle", [
    (["-load_stages", "1", "-disc_bc_clamp_values", "1,0.1", "-slab_bc_push_values", "0,0", "-force_control_type", "outer"],
     "option -force_control_type outer: each trial goes on from the last"),
])
def test_bad_friction_cattaneo(args, needle, tmp_path):
    """Force control's outer type, whose trials go on from one another, with friction: one line, status 1."""
    res = run_contact(CATTANEO + args, tmp_path, check=False)
    lines = [l for l in res.stderr.splitlines() if l.strip()]
    print(lines)
    assert res.returncode == 1
    assert len(lines) == 1 and needle in lines[0]


def test_sliding_stops_in_one_line(tmp_path):
    """A tangential force above mu P (Q/(mu P) = 1.16) on the disc pressed by
    a force: no equilibrium, and the scene's forces say so before any solve
    (src/contact/givenforces.c): status 1, one line naming the pair, the
    body, the stage and the friction, nothing written. The solve's own
    detection, where the forces given do not decide it, is
    test_rigid_punch_slides'; the check's cases, tests/test_given_forces.py."""
    res = run_contact(CATTANEO + ["-disc_bc_clamp_values", f"{P},0,{P},{1.16 * MU * P!r}"], tmp_path, check=False)
    lines = [l for l in res.stderr.splitlines() if l.strip()]
    print(lines)
    assert res.returncode == 1
    assert len(lines) == 1 and "pair interface: the forces given on body disc at stage 2" in lines[0] \
        and "-contact_interface_friction" in lines[0]
    assert not res.output_path.exists() and not res.summary_path.exists()


# the hertz scene (h = 0.1, mu = 0.3) pressed, then its block moved 0.08 along the contact in a
# second stage (friction_study.HERTZ_SLIDE): some nodes slip; 0.2 s a run
HERTZ_SLIDE = HERTZ + ["-contact_friction", "0.3", "-load_stages", "2", "-indenter_bc_clamp_values", "0,0,0,0",
                       "-block_bc_push_values", f"-0.15,0,-0.15,{friction_study.HERTZ_SLIDE!r}"]


def lag_changes(stdout):
    """The fixed point's changes of the lagged bound, per increment, from -info :tao."""
    incs = []
    for line in stdout.splitlines():
        if "fixed point" in line and "changed by" in line:
            k, change = int(line.split("fixed point ")[1].split(":")[0]), float(line.split("changed by ")[1].split()[0])
            if k == 1:
                incs.append([])
            incs[-1].append(change)
    return incs


def test_friction_lag_rtol(tmp_path):
    """-contact_friction_lag_rtol is the fixed point's stop: an increment is
    solved again with the pressure of its last solution until the lagged
    bound mu p changes by at most that of mu p_max. On the hertz scene's
    slide (2 increments, the second with `slipping` = 3 nodes slipping),
    at the default 1e-8 and at 2e-3: each increment's fixed point is the
    same sequence up to the looser stop, which ends it sooner
    (`lags_default` = 12 and `lags_loose` = 6 lag updates; bound: fewer),
    each at its first change below the stop (from -info: the sequences
    read, the stop's guarantee asserted on each). The answers: the nodal
    shear `dq` = 5.4e-4 of mu p_max apart, within the looser stop's
    remaining fixed-point error (below its last change when the changes
    fall by more than half from one solve to the next, as they do: bound
    2e-3), and more than the default's own stop (1e-8): the option acts."""
    def one(name, extra):
        res = run_contact(HERTZ_SLIDE + ["-info", ":tao"] + extra, tmp_path, name=name)
        with h5py.File(res.output_path, "r") as f:
            (g,) = [g for g in f["contact/interface"].values() if "node_stick" in g]
            p, q, stick = g["node_pressure"][:], g["node_shear"][:], g["node_stick"][:]
        return res.summary, lag_changes(res.stdout), p, q, stick

    rtol = 2e-3
    sd, cd, pd, qd, stickd = one("default", [])
    sl, cl, pl, ql, _ = one("loose", ["-contact_friction_lag_rtol", repr(rtol)])
    print("default", cd, "\nloose", cl)
    for changes, tol in ((cd, LAG_RTOL), (cl, rtol)):
        assert len(changes) == 2
        for inc in changes:     # each increment stopped at its first change within the stop
            assert inc[-1] <= tol and all(c > tol for c in inc[:-1]), (inc, tol)
    figure("slipping", np.sum((pd > 0) & (stickd == 0)))
    assert figure("lags_loose", sl["friction_lags"]) < figure("lags_default", sd["friction_lags"])
    dq = figure("dq", np.abs(ql - qd).max() / (MU * pd.max()))
    assert LAG_RTOL < dq <= rtol


def test_friction_lag_max_it(tmp_path):
    """-contact_friction_lag_max_it bounds the fixed point's solves of an
    increment. With -contact_friction_lag_rtol 2e-3 the hertz slide's
    increments settle at their third lag update (changes from the -info
    lines: the second's 8.6e-3 and 6.9e-3 above the stop, the third's
    2.4e-4 and 5.8e-4 under it): with at most 3 solves an increment the run
    converges, within the bound (`lags` = 6 lag updates, at most 3 an
    increment); with at most 2 it stops with one line that names the
    option, status 2, nothing written."""
    loose = HERTZ_SLIDE + ["-contact_friction_lag_rtol", "2e-3"]
    ok = run_contact(loose + ["-contact_friction_lag_max_it", "3", "-info", ":tao"], tmp_path, name="three")
    changes = lag_changes(ok.stdout)
    print(changes)
    assert len(changes) == 2 and all(len(inc) <= 3 for inc in changes)
    assert ok.summary["converged"] and figure("lags", ok.summary["friction_lags"]) <= 3 * 2
    assert any(inc[1] > 2e-3 for inc in changes)   # so that 2 solves do not settle it
    res = run_contact(loose + ["-contact_friction_lag_max_it", "2"], tmp_path, name="two", check=False)
    lines = [l for l in res.stderr.splitlines() if l.strip()]
    print(lines)
    assert res.returncode == 2
    assert len(lines) == 1 and "-contact_friction_lag_max_it 2 solves of the increment" in lines[0]
    assert not res.output_path.exists() and not res.summary_path.exists()


def test_axisymmetric_runs(tmp_path):
    """Friction in r-z (the sphere scene, a ball pressed on a flat of the same
    material, mu = 0.3): the solve converges, the stick zone is a disc about
    the axis whose radius c is the JSON's stick_half_width (`c_over_a` =
    0.989 of a = 0.1013, the edges slipping a little as the ball flattens),
    the rings' radial shear has no resultant (written 0, as the pair's force)
    and no Mindlin figure is given (plane strain's). Bounds: c at least
    0.8 a, and within the contact: at most a plus the contact's mesh size
    (0.005; a, the second moment's half-width, estimates the edge)."""
    s = run_contact(["-options_file", "meshes/sphere/sphere.opts", "-contact_friction", "0.3"], tmp_path).summary
    pair = s["contact"]["interface"]
    c, a = pair["stick_half_width"], pair["fem_a_moment"]
    print(f"c = {c:.5f}, a = {a:.5f}, shear force {pair['shear_force']}")
    figure("c_over_a", c / a)
    assert 0.8 * a <= c <= a + 0.005
    assert pair["shear_force"][0] == 0
    assert "mindlin_c" not in pair


def sliding_patch(tmp_path, H):
    """meshes/patch with the lower block widened to W = 1.4 (the upper one,
    W = 1, stays on it as it slides), the upper block H high (its mesh size
    0.05 where H < 1), its top moved down by 0.015204 H in the first stage,
    then 0.05 sideways in the second (its symmetry condition dropped),
    mu = 0.3: the options file's arguments."""
    text = (ROOT / "meshes/patch/patch.opts").read_text()
    u = f"{-0.015204 * H:.6g}"
    sub = {"-lower_geo lower.geo": f"-lower_geo {ROOT}/meshes/patch/lower.geo",
           "-upper_geo upper.geo": f"-upper_geo {ROOT}/meshes/patch/upper.geo",
           "-lower_geo_params W=1,H=1": "-lower_geo_params W=1.4,H=1",
           "-upper_geo_params W=1,H=1,": f"-upper_geo_params W=1,H={H},",
           "-upper_bc symmetry,push": "-upper_bc push",
           "-upper_bc_symmetry_components x\n": "", "-upper_bc_symmetry_values 0\n": "",
           "-upper_bc_push_components y": "-upper_bc_push_components x,y",
           "-upper_bc_push_values -0.015204": f"-upper_bc_push_values 0,{u},0.05,{u}",
           "-lower_bc_symmetry_values 0": "-lower_bc_symmetry_values 0,0",
           "-lower_bc_base_values 0": "-lower_bc_base_values 0,0"}
    if H < 1:
        sub["-upper_mesh_size 0.1"] = "-upper_mesh_size 0.05"
    for old, new in sub.items():
        assert old in text, old
        text = text.replace(old, new)
    opts = tmp_path / f"slide-{H}.opts"
    opts.write_text(text + "-load_stages 2\n-contact_friction 0.3\n")
    return ["-options_file", opts, "-mesh_dir", tmp_path / "meshes"]


def sliding_figures(res):
    """A sliding run's slave (its name), its nodal shear and stick, the nodes
    in contact, the largest ||q| - mu p| over mu p_max there, the pair's
    |shear force| / (mu P) - 1 and its whole force (the pressure's and the
    shear's)."""
    pair = res.summary["contact"]["interface"]
    with h5py.File(res.output_path, "r") as f:
        (name,) = [k for k, g in f["contact/interface"].items() if "node_stick" in g]
        g = f[f"contact/interface/{name}"]
        p, q, stick = g["node_pressure"][:], g["node_shear"][:], g["node_stick"][:]
    on = p > 0
    dev = np.max(np.abs(np.abs(q[on]) - MU * p[on])) / (MU * p.max())
    ratio = np.hypot(*pair["shear_force"]) / (MU * pair["P"]) - 1
    return name, q, stick, on, dev, ratio, np.array(pair["force"])   # the whole force: pressure and shear


@pytest.mark.roundoff
@pytest.mark.parametrize("H,bound", [(0.2, 1e-6), (1, 1e-4)], ids=["layer", "block"])
def test_full_sliding(H, bound, tmp_path):
    """A non-matching block patch (meshes/patch: E 1300 / 800, nu 0.3 / 0.2)
    pressed, then pushed sideways by 0.05, many times the sliding
    interface's elastic shear: every slave node in contact slips
    (node_stick 0) and carries |q| = mu p, q of one sign, to 1e-6 of
    mu p_max (`dev_0.2` = 0 and `dev_1` = 0: the return map clips exactly).
    The pair's whole shear force against mu times its normal force P: the
    contact acts on the deformed surfaces, and the nodes' forces, each in
    its own frame, add as vectors. On a layer H = 0.2 high the face stays
    flat: `ratio_0.2` = 1.6e-7, bound 1e-6 (the issue's); on a block H = 1
    high the sideways push's moment turns the face by 3e-3 on average:
    `ratio_1` = 2.9e-5, bound 1e-4. The upper body's push reaction
    balances the pair's forces (the shear's plus the pressure's:
    `balance_1` = 4.4e-9 of P on the block, `balance_0.2` = 4.3e-9 on the
    layer, the solve's stopping tolerance; bound 1.5e-8). The same path without
    friction converges too (the block). With both blocks W = 1 the upper
    one slides off the lower one's end, whose corner then cuts into it: that
    converges too (tests/test_slide_off.py has such scenes)."""
    args = sliding_patch(tmp_path, H)
    res = run_contact(args, tmp_path, name=f"H{H}")
    s = res.summary
    pair = s["contact"]["interface"]
    name, q, stick, on, dev, ratio, total = sliding_figures(res)
    push = np.array(s["reactions"]["upper:push"])
    balance = np.max(np.abs(push - total)) / pair["P"]
    print(f"H = {H}: {on.sum()} nodes in contact, {int(stick[on].sum())} stuck; push reaction {push} against the pair's {total}")
    figure(f"dev_{H}", dev)
    figure(f"ratio_{H}", ratio)
    figure(f"balance_{H}", balance)
    assert on.sum() >= 10 and stick[on].sum() == 0
    assert dev <= 1e-6
    assert len(set(np.sign(q[on]))) == 1
    assert abs(ratio) <= bound
    assert balance <= 1.5e-8
    if H == 1:
        frictionless = run_contact(args + ["-contact_friction", "0"], tmp_path, name="mu0").summary
        assert frictionless["contact"]["interface"]["P"] > 0


@pytest.mark.roundoff
def test_accuracy_with_friction(tmp_path):
    """-accuracy on a scene with friction (hertz, mu = 0.3, one load stage):
    each refined mesh's solve is its own from rest, the friction's state at
    rest, so the warm start (the last step's answer interpolated) changes
    only its first iterate: with -accuracy_warm_start 1 and 0 the stick
    half-width agrees to `dc` = 1.8e-11 to 2.7e-11 and the energy to `dE` =
    3.6e-16 to 3.2e-15
    (bounds 1e-8, the fixed point's stop, and 1e-10, the energy being
    second order in the stop); the target (1 %, the pressure's and the
    force's estimate) is reached."""
    args = HERTZ[:2] + ["-contact_friction", "0.3", "-accuracy", "0.01", "-output", "none"]
    runs = {w: run_contact(args + ["-accuracy_warm_start", w], tmp_path, name=f"warm{w}") for w in ("1", "0")}
    c = {w: r.summary["contact"]["interface"]["stick_half_width"] for w, r in runs.items()}
    e = {w: r.summary["energy"] for w, r in runs.items()}
    print(c, e)
    assert "target 1 % reached" in runs["1"].stdout
    assert figure("dc", abs(c["1"] - c["0"]) / c["0"]) <= 1e-8
    assert figure("dE", abs(e["1"] - e["0"]) / abs(e["0"])) <= 1e-10


def rigid_plane_layer(tmp_path):
    """sliding_patch's layer (H = 0.2) with the lower block rigid (-lower_rigid,
    its E and nu dropped): a rigid plane the layer is pressed on and slid along."""
    args = sliding_patch(tmp_path, 0.2)
    opts = args[1]
    text = opts.read_text()
    for old, new in (("-lower_E 1300\n", "-lower_rigid\n"), ("-lower_nu 0.3\n", "")):
        assert old in text, old
        text = text.replace(old, new)
    opts.write_text(text)
    return args


@pytest.mark.roundoff
def test_rigid_full_sliding(tmp_path):
    """Friction against a rigid body's surface: the layer of test_full_sliding
    (E 800, nu 0.2, H = 0.2) pressed on a rigid plane and pushed sideways by
    0.05: every slave node in contact (the layer's, the rigid plane the
    master) slips with |q| = mu p to 1e-6 of mu p_max (`dev` = 0), and the
    pair's shear force is mu P to `ratio` = 9.3e-10 (the plane does not
    turn, so the nodes' frames agree better than on the elastic lower
    block); bound 1e-6 (the issue's). The rigid plane's force (the
    contact's on it) is the pair's whole force, pressure and shear, on its
    first surface's body, the plane (`balance` = 3.4e-17 to 2.7e-16 of P;
    bound 1e-8 of P): one sign for both."""
    res = run_contact(rigid_plane_layer(tmp_path), tmp_path, name="rigid-layer")
    s = res.summary
    pair = s["contact"]["interface"]
    name, q, stick, on, dev, ratio, total = sliding_figures(res)
    rigid = np.array(s["bodies"]["lower"]["force"])
    print(f"slave {name}: {on.sum()} nodes in contact, {int(stick[on].sum())} stuck; ||q| - mu p| {dev:.1e}; "
          f"|shear force| / (mu P) - 1 = {ratio:.2e}; the plane's force {rigid} against the pair's {total}: "
          f"{np.max(np.abs(rigid - total)) / pair['P']:.1e} of P")
    assert name == "upper_contact" and s["bodies"]["lower"]["rigid"]
    assert on.sum() >= 10 and stick[on].sum() == 0
    assert figure("dev", dev) <= 1e-6
    assert abs(figure("ratio", ratio)) <= 1e-6
    assert figure("balance", np.max(np.abs(rigid - total)) / pair["P"]) <= 1e-8     # both the contact's force on the plane


# the rigid punch (meshes/rigid-punch, b = 0.25) on coarser meshes, free to turn about a point
# 0.1 right of its axis, pressed by a force of 0.15, then pushed sideways by Q with friction
RIGID_PUNCH = ["-options_file", "meshes/rigid-punch/rigid-punch.opts", "-punch_rigid_rotation", "free",
               "-punch_rigid_centre", "0.1,0.125", "-punch_bc_push_control", "force,force", "-load_stages", "2",
               "-block_bc_base_values", "0,0,0,0", "-contact_friction", "0.3", "-punch_mesh_size", "0.05",
               "-block_mesh_size", "0.025"]


@pytest.fixture(scope="module")
def punch_runs(tmp_path_factory):
    """The rigid punch held by friction (Q = 0.02 = 0.44 mu P) on 1 and 2 ranks."""
    tmp = tmp_path_factory.mktemp("rigid-punch")
    return {n: run_contact(RIGID_PUNCH + ["-punch_bc_push_values", "0,-0.15,0.02,-0.15"], tmp, ranks=n, name=f"np{n}")
            for n in (1, 2)}


@pytest.mark.roundoff
def test_rigid_punch_held_by_friction(punch_runs):
    """A rigid slave surface with friction: the punch, free to turn and
    force-controlled in x and y, is held along the block by friction alone
    (Q = 0.02 against mu P = 0.045). Its force balance: the contact's force
    on it is minus the force given, (-0.02, 0.15), to the solve's stop (`force_error` =
    2.6e-8 of P; bound 1e-6 of P), its moment about the free point 0
    (`moment_error` = 1.3e-8 of P b; bound 1e-6 of P b). Coulomb on its
    nodes: |q| <= mu p to 1e-6 of mu p_max (`excess` = 0), some stuck
    (`stuck` = 16 of 21 in contact), the slipping ones at |q| = mu p. 1
    and 2 ranks: the shear `dq` = 5.3e-12 to 4.3e-11 of its largest apart,
    the stick half-width `dc` = 3.9e-12 to 4.3e-11; bounds 1e-8, the fixed point's stop."""
    s = punch_runs[1].summary
    P, b = 0.15, 0.25
    force, moment = np.array(s["bodies"]["punch"]["force"]), s["bodies"]["punch"]["moment"]
    with h5py.File(punch_runs[1].output_path, "r") as f:
        (name,) = [k for k, g in f["contact/tool"].items() if "node_stick" in g]
        g = f[f"contact/tool/{name}"]
        p, q, stick = g["node_pressure"][:], g["node_shear"][:], g["node_stick"][:]
    with h5py.File(punch_runs[2].output_path, "r") as f:
        q2 = f[f"contact/tool/{name}"]["node_shear"][:]
    on = p > 0
    slipping = on & (stick == 0)
    excess = np.max(np.abs(q) - MU * p) / (MU * p.max())
    c1, c2 = (punch_runs[n].summary["contact"]["tool"]["stick_half_width"] for n in (1, 2))
    ranks = np.abs(q - q2).max() / np.abs(q).max()
    print(f"slave {name}: force {force}, moment {moment:.2e}; {on.sum()} in contact, {int(stick[on].sum())} stuck; "
          f"excess {excess:.1e}; ranks: shear {ranks:.1e}, stick half-width {abs(c1 - c2) / c1:.1e}")
    assert name == "punch_contact" and s["converged"]
    assert figure("force_error", np.max(np.abs(force + [0.02, -0.15])) / P) <= 1e-6
    assert figure("moment_error", abs(moment) / (P * b)) <= 1e-6
    figure("stuck", stick[on].sum())
    assert figure("excess", excess) <= 1e-6 and stick[on].sum() >= 5 and slipping.sum() >= 1
    assert np.max(np.abs(np.abs(q[slipping]) - MU * p[slipping])) <= 1e-6 * MU * p.max()
    assert figure("dq", ranks) <= 1e-8 and figure("dc", abs(c1 - c2) / c1) <= 1e-8


@pytest.mark.roundoff
def test_rigid_punch_taylor(tmp_path):
    """The Taylor test at the rigid punch's solution with friction: the
    energy's remainder at order 2 (`gradient_order_error` = -4.9e-7 to
    3.9e-7 off 2),
    the gradient's with the exact Hessian, through the rigid body's
    rotation and translation, too (`hessian_order_error` = -0.016 to
    -0.0037 off 2:
    before, the friction's Hessian dropped the rigid surface's dofs, and
    its remainder fell at order 1). Bounds: within 0.05 of 2."""
    t = run_contact(RIGID_PUNCH + ["-punch_bc_push_values", "0,-0.15,0.02,-0.15", "-taylor_test", "-output", "none"],
                    tmp_path).summary["taylor"]
    assert abs(figure("gradient_order_error", t["gradient_order"] - 2.0)) <= 0.05
    assert abs(figure("hessian_order_error", t["hessian_order"] - 2.0)) <= 0.05


def test_rigid_punch_slides(tmp_path):
    """The rigid punch pressed by a displacement (y, 0.002: P = 0.150, mu P =
    0.045) and pulled by a force Q = 0.06 in x: no equilibrium, which only
    the solve can find (P comes from the displacement): one line saying the
    pair slides and naming its friction, status 2, nothing written."""
    res = run_contact(RIGID_PUNCH + ["-punch_bc_push_control", "force,displacement",
                                     "-punch_bc_push_values", "0,-0.002,0.06,-0.002", "-load_cutbacks", "0",
                                     "-tao_max_it", "60"], tmp_path, check=False)
    lines = [l for l in res.stderr.splitlines() if l.strip()]
    print(lines)
    assert res.returncode == 2
    assert len(lines) == 1 and "pair tool slides" in lines[0] and "-contact_tool_friction" in lines[0]
    assert not res.output_path.exists() and not res.summary_path.exists()


def test_rigid_mu_zero_is_frictionless(tmp_path):
    """Against a rigid body too, -contact_friction 0 is the frictionless run
    bit for bit (rigid-hertz)."""
    args = ["-options_file", "meshes/rigid-hertz/rigid-hertz.opts", "-mesh_size", "0.2", "-output", "none"]
    base = run_contact(args, tmp_path, name="base").summary
    zero = run_contact(args + ["-contact_friction", "0"], tmp_path, name="zero").summary
    for key in ("energy", "contact_force", "max_displacement", "displacement_norm"):
        assert zero[key] == base[key], key


def shear_over_pressure(res):
    """The slave's shear over its pressure in relative L2 (weights A_j)."""
    with h5py.File(res.output_path, "r") as f:
        (g,) = [g for g in f["contact/interface"].values() if "node_stick" in g]
        p, q, w = g["node_pressure"][:], g["node_shear"][:], g["node_weight"][:]
    return float(np.sqrt(np.sum(w * q * q) / np.sum(w * p * p)))


def test_similar_bodies_carry_no_shear(tmp_path):
    """Dundurs: between elastically similar bodies (beta = 0) a normal load
    makes no tangential displacement mismatch, so friction has nothing to
    resist. The cattaneo scene's normal force alone, in 8 increments with
    mu = 0.3 from the first: the shear over the pressure (relative L2)
    `similar` = 0.0033 (at the zone's edges, where the finite disc and
    slab depart from half-spaces). The neighbour: the slab 5 times softer
    (Dundurs beta = 0.19), the same load: `dissimilar` = 0.117. Bounds: 2 %
    for the similar pair, and the dissimilar one at least 5 times the
    similar one.
    The report's stick zone beside Mindlin's names Dundurs' beta (-0.19)
    where the bodies are not similar, his being for similar bodies."""
    base = CATTANEO + ["-load_stages", "1", "-disc_bc_clamp_values", f"{P},0", "-slab_bc_push_values", "0,0",
                       "-load_steps", "8"]
    runs = {k: run_contact(base + extra, tmp_path, name=k) for k, extra in (("similar", []), ("dissimilar", ["-slab_E", "200"]))}
    similar, dissimilar = (figure(k, shear_over_pressure(runs[k])) for k in ("similar", "dissimilar"))
    print(f"shear / pressure: similar {similar:.4f}, slab 5 times softer {dissimilar:.4f}")
    assert similar <= 0.02
    assert dissimilar >= 5 * similar
    # the report's Mindlin figure says it is for similar bodies where they are not: Dundurs'
    # beta of the disc (E = 1000) and the slab (E = 200), nu = 0.3, from his formula here
    G1, G2, nu = 1000 / 2.6, 200 / 2.6, 0.3
    beta = ((1 - 2 * nu) / G1 - (1 - 2 * nu) / G2) / (2 * ((1 - nu) / G1 + (1 - nu) / G2))
    line = next(l for l in runs["dissimilar"].stdout.splitlines() if "Mindlin's" in l)
    assert f"these have Dundurs' beta = {beta:.3g})" in line, line
    assert "Dundurs" not in runs["similar"].stdout


def radial_slip(res):
    """(X, slip, shear, pressure, stick, weight) of the slave's nodes by radius."""
    with h5py.File(res.output_path, "r") as f:
        (g,) = [g for g in f["contact/interface"].values() if "node_stick" in g]
        X, s, q, p, st, w = (g[k][:] for k in ("node_X", "node_slip", "node_shear", "node_pressure", "node_stick", "node_weight"))
    o = np.argsort(X[:, 0])
    return X[o, 0], s[o], q[o], p[o], st[o], w[o]


AXI_SLIP = ["-options_file", "meshes/sphere/sphere.opts", "-flat_E", "200", "-load_steps", "4"]


def axisymmetric_slip(tmp_path, h):
    """The r-z dissimilar scene at mesh size h: (stick radius c, the radial
    slip's integral over the loaded surface, its largest, the slipping
    loaded nodes whose slip has the sign of their shear, all of them)."""
    res = run_contact(AXI_SLIP + ["-contact_friction", "0.3", "-ball_mesh_size", h, "-flat_mesh_size", h], tmp_path, name=f"h{h}")
    X, slip, q, p, stick, w = radial_slip(res)
    slipping = (p > 0) & (stick < 0.5) & (q != 0)
    return (res.summary["contact"]["interface"]["stick_half_width"], np.sum(w[p > 0] * slip[p > 0]),
            np.max(np.abs(slip[p > 0])), int(np.count_nonzero(np.sign(slip[slipping]) == np.sign(q[slipping]))),
            int(np.count_nonzero(slipping)))


def test_axisymmetric_radial_slip(tmp_path):
    """r-z, dissimilar bodies (the sphere scene with the flat 5 times softer
    than the ball, Dundurs beta = -0.19, mu = 0.3, 4 increments): under a
    normal load alone the flat's surface spreads radially more than the
    ball's, and the edges of the contact slip: at h = 0.02 and 0.01
    `slipping` = 1 to 2 loaded nodes slip, and at every one its
    accumulated radial slip has the sign of its shear (Coulomb: the shear
    opposes the slip). The stick zone's radius c (stick_half_width) moves
    by `dc` = 0.031 (relative) from h = 0.02 to 0.01; bound 10 % (the
    stress test follows it to h = 0.005, where the change falls to 0.04
    times this). mu = 0 is the frictionless run (the same P and energy, bit
    for bit)."""
    runs = {h: axisymmetric_slip(tmp_path, h) for h in (0.02, 0.01)}
    for h, (c, total, largest, signed, slipping) in runs.items():
        print(f"h = {h}: c = {c:.5f}, slip integral {total:.3e}, largest {largest:.3e}; {signed} of {slipping} slipping nodes signed")
        figure("slipping", slipping)
        assert slipping > 0 and signed == slipping, h
    dc = figure("dc", abs(runs[0.01][0] / runs[0.02][0] - 1))
    assert dc <= 0.10
    coarse = AXI_SLIP + ["-ball_mesh_size", "0.02", "-flat_mesh_size", "0.02", "-output", "none"]
    zero = run_contact(coarse + ["-contact_friction", "0"], tmp_path, name="mu0").summary
    none = run_contact(coarse, tmp_path, name="frictionless").summary
    assert zero["contact_force"] == none["contact_force"] and zero["energy"] == none["energy"]


@pytest.mark.stress
def test_axisymmetric_radial_slip_converges(tmp_path):
    """The same scene at h = 0.02, 0.01, 0.005 (make stress: the finest mesh
    costs 25 s). The stick radius c converges with the mesh: 0.09565,
    0.09265, 0.09253 measured (0.09276 at 0.0025), the second change
    `c_ratio` = 0.04 times the first; bound 0.25 times. The radial slip
    converges in its integral over the loaded surface (sum of node_weight
    times node_slip over the nodes in contact: -5.40e-7, -6.43e-7,
    -6.39e-7, `integral_ratio` = 0.04) and in its largest (3.81e-5,
    6.78e-5, 6.50e-5, at the contact's edge: `largest_ratio` = 0.09);
    bounds 0.25 times. Node by node the slip accumulated inside the stick
    zone is the history of the increments in which the contact grew over
    the node: it alternates node to node and follows the load steps (with
    16 increments at h = 0.005, c = 0.0988), so its profile is not compared
    node by node."""
    runs = {h: axisymmetric_slip(tmp_path, h) for h in (0.02, 0.01, 0.005)}
    for k, name in ((0, "c_ratio"), (1, "integral_ratio"), (2, "largest_ratio")):
        v = {h: r[k] for h, r in runs.items()}
        e1, e2 = abs(v[0.02] - v[0.01]), abs(v[0.01] - v[0.005])
        print(f"{name}: {v[0.02]:.5g}, {v[0.01]:.5g}, {v[0.005]:.5g}; changes {e1:.2e}, {e2:.2e}")
        assert figure(name, e2 / e1) <= 0.25, name
    assert all(r[3] == r[4] > 0 for r in runs.values())


@pytest.mark.roundoff
def test_master_shear_transferred(runs):
    """The master surface (the slab's face) gets the slave's shear as it gets
    its pressure: at each master node the slave's traction at the node's
    closest point of the slave, opposite, per unit of the master's own
    reference length, signed as the slave's (its traction is -q tau along
    its own arc; both arcs run the same way here, so the two profiles have
    opposite signs). The master's shear force against the slave's:
    `dQ` = 1.0e-3 apart (the linear interpolation between the slave's
    nodes), bound 3e-3. Coulomb on the master: |q| <= mu p at every node
    to 1e-6 of mu p_max (`excess` = 0: equality where the slave slips).
    1 and 2 ranks: `dq` = 1.4e-11 to 1.9e-11 of the peak apart, bound 1e-9 (within the
    slave's bound from the fixed point's stop, test_ranks_agree's)."""
    sets = {}
    for n in (1, 2):
        with h5py.File(runs[n].output_path, "r") as f:
            sets[n] = {k: {d: g[d][:] for d in ("node_shear", "node_pressure", "node_weight")}
                       for k, g in f["contact/interface"].items()}
    one = sets[1]
    slave, master = one["disc_contact"], one["slab_contact"]
    Qs = np.sum(slave["node_weight"] * slave["node_shear"])
    Qm = np.sum(master["node_weight"] * master["node_shear"])
    excess = np.max(np.abs(master["node_shear"]) - MU * master["node_pressure"]) / (MU * master["node_pressure"].max())
    ranks = np.max(np.abs(sets[2]["slab_contact"]["node_shear"] - master["node_shear"])) / np.abs(master["node_shear"]).max()
    print(f"shear force: slave {Qs:.6f}, master {Qm:.6f} ({abs(Qm / Qs) - 1:+.2e}); master's Coulomb excess {excess:.1e}; ranks {ranks:.1e}")
    assert abs(figure("dQ", abs(Qm / Qs) - 1)) <= 3e-3 and Qm * Qs < 0
    assert figure("excess", excess) <= 1e-6
    assert figure("dq", ranks) <= 1e-9


@pytest.mark.skipif(not getfem_available(), reason="python3-getfem is not installed (apt-get install python3-getfem)")
def test_getfem_same_mesh(tmp_path):
    """GetFEM 5.4 on the same meshes (scripts/getfem_cattaneo.py --scale 2: its
    large-sliding frictional brick, the current configuration as ours,
    friction from the first increment, one increment a stage, the disc
    driven by the same forces), measured as ours (friction_study.shear_l2's
    definitions), with the contact twice as wide as the scene's (a/R = 0.1,
    4 P, hc and the graded zone twice the scene's): on the scene's own
    meshes GetFEM's P2 multiplier alternates from node to node (its
    pressure 4.5 % from ours, whatever its r; docs/scenes.md#friction).
    The pressures at the same slave nodes: `dp` = 0.0065 apart (relative
    L2), bound 1.5 %. Both stick zones within 2 % of Mindlin's (ours
    `c_over_a_error` = -0.0051, GetFEM's `getfem_c_over_a_error` = 0.0058).
    Our shear profile nearer Mindlin's than GetFEM's on the same mesh, as
    the issue asks: `l2` = 0.063 against `getfem_l2` = 0.123."""
    import subprocess
    out = tmp_path / "getfem.json"
    subprocess.run([GETFEM_PYTHON, os.path.join(str(ROOT), "scripts", "getfem_cattaneo.py"), "--scale", "2", "--only",
                    "large_sliding_P2_friction_from_start_1", "--mesh-dir", str(tmp_path), "-o", str(out)],
                   cwd=str(ROOT), check=True, capture_output=True, timeout=300)
    (g,) = json.loads(out.read_text())["variants"]
    res = run_contact(friction_study.cattaneo_args(0.5, 1, 2 * friction_study.HC[1], 2.0), tmp_path)
    ours = friction_study.shear_l2(res.output_path, res.summary, 0.5, force=4 * P)
    pair = res.summary["contact"]["interface"]
    surf = pair["surfaces"][0]
    with h5py.File(res.output_path, "r") as f:
        s, p = f[SLAVE]["node_s"][:], f[SLAVE]["node_pressure"][:]
    x = s - surf["centre"]
    gx, gp, gw = (np.array(g["profile"][k]) for k in ("x", "p", "w"))
    mine = np.interp(gx + g["centre"] - surf["centre"], x, p)    # GetFEM's nodes are ours (the same mesh)
    dp = float(np.sqrt(np.sum(gw * (mine - gp) ** 2) / np.sum(gw * gp ** 2)))
    ca = pair["stick_half_width"] / surf["a_moment"] / np.sqrt(0.5) - 1
    figure("dp", dp)
    figure("c_over_a_error", ca)
    figure("getfem_c_over_a_error", g["c_over_a_error_pct"] / 100)
    figure("l2", ours)
    figure("getfem_l2", g["shear_l2"])
    assert dp <= 0.015
    assert abs(ca) <= 0.02 and abs(g["c_over_a_error_pct"]) <= 2
    assert ours < g["shear_l2"]
