"""Options of the contact, the bodies and the partition, each on the
reference scene (hertz at h = 0.1, the meshes `make meshes` made, solved to
-tao_gttol 1e-12): the option changes the figure it should, the answer stays
the default's within a bound set by what the option changes, and a bad value
is one line with status 1 (the values test_bad_values does not give: the top
of a domain, a pair's own option). Where the problem is the same and only the
path changes (the Hessian, the partition, a rule on polynomials it integrates
exactly), the bound is 3 times the worst of the five OpenBLAS kernels'
figures at -tao_gttol 1e-12; where the path is the same too (a pair's own
formulation against the global option's), STOP, the 1e-11 to which two solves
of one problem agree at that stop (test_parallel's compare()); where the
problem changes (another quadrature), the change must exceed STOP."""
import re

import pytest

from conftest import figure, run_contact

HERTZ = ["-options_file", "meshes/hertz/hertz.opts", "-tao_gttol", "1e-12"]
# the solve's path: the switch to the exact contact Hessian, the gradient norms
MONITOR = ["-info", ":tao", "-tao_monitor"]
STOP = 1e-11  # two solves of one problem at -tao_gttol 1e-12, relative (compare()'s rtol in test_parallel)
EPS = 2.0 ** -52


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The default run (mortar, 4 Gauss points a segment, cell quadrature
    degree 4, the Hessian's switch at 1e-4), with its path printed."""
    return run_contact(HERTZ + MONITOR, tmp_path_factory.mktemp("reference"), name="reference")


def rel(a, b, key):
    return abs(a.summary[key] / b.summary[key] - 1)


def test_pair_formulation_overrides_global(reference, tmp_path):
    """-contact_<pair>_formulation overrides -contact_formulation for its
    pair, both ways: the pair is built in its own formulation (the summary
    and the pair's line name it), and solves the problem that formulation
    gives, the run with it as the global option's (P `dP_same` = 0 apart,
    bit for bit: one code path; bound STOP), not the other's (the two
    formulations' P `dP_formulations` = 9.4e-4 apart at h = 0.1)."""
    gpts = run_contact(HERTZ + ["-contact_formulation", "gpts"], tmp_path, name="gpts")
    for glob, pair, same, other in (("gpts", "mortar", reference, gpts), ("mortar", "gpts", gpts, reference)):
        r = run_contact(HERTZ + ["-contact_formulation", glob, "-contact_interface_formulation", pair], tmp_path, name=pair)
        assert r.summary["contact"]["interface"]["formulation"] == pair
        assert f"Contact pair interface ({pair}," in r.stdout
        d_same, d_other = figure("dP_same", rel(r, same, "contact_force")), figure("dP_formulations", rel(r, other, "contact_force"))
        assert d_same <= STOP and rel(r, same, "energy") <= STOP, (pair, d_same)
        assert d_other > 1e-5, f"the pair's {pair} run is not far from the global {glob}'s: {d_other:.2e}"


def test_contact_quadrature_points(reference, tmp_path):
    """-contact_quadrature_points: mortar's Gauss rule on each segment (4
    points by default). 3 points move the energy by `dE3` = 3.4e-9 and P by
    `dP3` = 5.4e-8 (relative): the option reaches the rule (far above
    STOP); 8 points move them by less, `dE8` = 1.6e-13 and `dP8` = 1.6e-12
    to 2.0e-12: a Gauss rule on a smooth integrand converges, so the default's
    quadrature error, which 8 points measure, is below the 3-point rule's."""
    three = run_contact(HERTZ + ["-contact_quadrature_points", "3"], tmp_path, name="q3")
    eight = run_contact(HERTZ + ["-contact_quadrature_points", "8"], tmp_path, name="q8")
    dE3, dP3 = figure("dE3", rel(three, reference, "energy")), figure("dP3", rel(three, reference, "contact_force"))
    dE8, dP8 = figure("dE8", rel(eight, reference, "energy")), figure("dP8", rel(eight, reference, "contact_force"))
    assert dE3 > STOP and dP3 > STOP, "3 Gauss points gave the 4-point answer"
    assert dE8 < dE3 and dP8 < dP3, (dE8, dE3, dP8, dP3)


def test_body_quadrature_degree(reference, tmp_path):
    """-indenter_quadrature_degree: the disc's Tri6 cells along its arc are
    curved, where no rule is exact. Degree 2 moves the energy by `dE2` =
    1.9e-6 (relative; far above STOP), degree 8 by less, `dE8`
    = 6.9e-10 (the default degree 4's error, which degree 8 measures, below
    degree 2's), and P likewise (`dP2` = 2.0e-6, `dP8` = 4.7e-10)."""
    two = run_contact(HERTZ + ["-indenter_quadrature_degree", "2"], tmp_path, name="d2")
    eight = run_contact(HERTZ + ["-indenter_quadrature_degree", "8"], tmp_path, name="d8")
    dE2, dP2 = figure("dE2", rel(two, reference, "energy")), figure("dP2", rel(two, reference, "contact_force"))
    dE8, dP8 = figure("dE8", rel(eight, reference, "energy")), figure("dP8", rel(eight, reference, "contact_force"))
    assert dE2 > STOP and dP2 > STOP, "degree 2 gave degree 4's answer"
    assert dE8 < dE2 and dP8 < dP2, (dE8, dE2, dP8, dP2)


@pytest.mark.roundoff
def test_block_quadrature_exact(reference, tmp_path):
    """-block_quadrature_degree: the block's Quad9 cells are rectangles, whose
    stiffness is a polynomial of degree 4 in each coordinate, integrated
    exactly by Gauss's (degree + 2) / 2 = 3 points a direction of the default
    degree 4: degree 6 (4 points) gives the same answer to round-off (energy
    `dE6` = 2.2e-16 to 3.8e-15 apart, bound 50 EPS; P `dP6` = 8.2e-14 to
    2.1e-13, bound 6e-13), while degree 2 (2 points, exact to degree 3 only)
    moves it (energy `dE2` = 1.1e-4, above STOP): the option reaches the
    block's cells."""
    six = run_contact(HERTZ + ["-block_quadrature_degree", "6"], tmp_path, name="b6")
    two = run_contact(HERTZ + ["-block_quadrature_degree", "2"], tmp_path, name="b2")
    dE6, dP6 = figure("dE6", rel(six, reference, "energy")), figure("dP6", rel(six, reference, "contact_force"))
    assert dE6 <= 50 * EPS and dP6 <= 6e-13, (dE6, dP6)
    assert figure("dE2", rel(two, reference, "energy")) > STOP


def switch_at(run):
    """(the gradient norm at which the exact contact Hessian was switched on,
    or None; every iterate's gradient norm from -tao_monitor)."""
    norms = [float(m) for m in re.findall(r"^\s*\d+ TAO,.*Residual: (\S+)", run.stdout, re.M)]
    m = re.search(r"contact Hessian: exact from iteration \d+ \(\|\|g\|\| = (\S+)\)", run.stdout)
    return (float(m.group(1)) if m else None), norms


@pytest.mark.roundoff
def test_contact_hessian_switch(reference, tmp_path):
    """-contact_hessian_switch s: -contact_hessian auto adds the exact
    contact term at the first iterate whose gradient norm is below s times
    the first's: at 1e-4 (the default) and 1e-2 that iterate is the first
    below the threshold (-tao_monitor's norms against -info's line), at 0
    never. The answer is the default's: only the Hessian, not the energy,
    changes (P at 1e-2 `dP_s2` = 6.7e-12 to 7.0e-12 apart, bound 2e-11: it
    stops at another point within -tao_gttol, ||g|| `g_s2` = 9.2e-10 where
    the default's is `g_ref` = 6.2e-12 to 8.9e-12; at 0 `dP_s0` = 5.8e-15
    to 1.8e-13, bound 5e-13)."""
    early = run_contact(HERTZ + MONITOR + ["-contact_hessian_switch", "1e-2"], tmp_path, name="s2")
    for s, run in ((1e-4, reference), (1e-2, early)):
        g, norms = switch_at(run)
        assert g is not None and norms, f"switch {s}: no switch to the exact Hessian in the output"
        first = next(n for n in norms if n < s * norms[0])
        assert abs(g / first - 1) < 1e-5, f"switch {s}: exact at ||g|| = {g}, the first iterate below {s} ||g0|| has {first}"
    never = run_contact(HERTZ + MONITOR + ["-contact_hessian_switch", "0"], tmp_path, name="s0")
    assert switch_at(never)[0] is None
    figure("g_s2", early.summary["gradient_norm"]), figure("g_ref", reference.summary["gradient_norm"])
    assert figure("dP_s2", rel(early, reference, "contact_force")) <= 2e-11
    assert figure("dP_s0", rel(never, reference, "contact_force")) <= 5e-13


@pytest.mark.roundoff
def test_partitioner_simple(reference, tmp_path):
    """-partitioner simple on 2 ranks: PETSc's simple partitioner, cells in
    contiguous blocks of equal size (counts within one of each other, as
    -partition_view prints them; METIS's differ by its imbalance), and the
    1-rank answer (P `dP` = 2.5e-14 to 1.9e-13 apart, bound 6e-13; energy
    `dE` = 1.0e-15 to 2.0e-15, bound 30 EPS)."""
    two = run_contact(HERTZ + ["-partitioner", "simple", "-partition_view"], tmp_path, ranks=2, name="simple")
    for body in ("indenter", "block"):
        block = re.search(rf"Partition of body {body} \(simple\):\n((?:  rank \d+: \d+ cells\n)+)", two.stdout)
        assert block, two.stdout[:2000]
        counts = [int(c) for c in re.findall(r"(\d+) cells", block.group(1))]
        assert len(counts) == 2 and sum(counts) == two.summary["bodies"][body]["cells"] and max(counts) - min(counts) <= 1, (body, counts)
    assert figure("dP", rel(two, reference, "contact_force")) <= 6e-13
    assert figure("dE", rel(two, reference, "energy")) <= 30 * EPS


BAD = {
    "quadrature_points_above": (["-contact_quadrature_points", "9"], "-contact_quadrature_points", 1),
    "quadrature_degree_above": (["-indenter_quadrature_degree", "13"], "-indenter_quadrature_degree", 1),
    "hessian_switch_above": (["-contact_hessian_switch", "1.5"], "-contact_hessian_switch", 1),
    # the pair's own option, not the global one, is named
    "pair_formulation": (["-contact_formulation", "gpts", "-contact_interface_formulation", "nosuch"], "-contact_interface_formulation", 1),
    # found here and fixed: an unknown global formulation was taken silently
    # where every pair has its own; an unknown value of an enumerated option
    # (PETSc raises it on PETSC_COMM_SELF) was printed once per rank
    "global_formulation_overridden": (["-contact_formulation", "nosuch", "-contact_interface_formulation", "mortar"], "-contact_formulation", 1),
    "partitioner_two_ranks": (["-partitioner", "nosuch"], "-partitioner", 2),
}


@pytest.mark.parametrize("case", list(BAD))
def test_bad_value(case, tmp_path):
    """Status 1, one line (on 2 ranks too) naming the option, no output.
    Two cases were bugs found here: an unknown -contact_formulation was taken
    (status 0) where every pair has its own formulation; an unknown value of
    an enumerated option (-partitioner nosuch) was printed by every rank."""
    args, option, ranks = BAD[case][:3]
    r = run_contact(HERTZ + args, tmp_path, ranks=ranks, check=False, timeout=120)
    lines = [l for l in r.stderr.splitlines() if l.strip() and (ranks == 1 or l.startswith("contact: "))]
    assert r.returncode == 1, f"exit {r.returncode}\n{r.stderr[-2000:]}"
    assert len(lines) == 1 and lines[0].startswith("contact: error: ") and option in lines[0], r.stderr[-2000:]
    assert re.search(rf"{option}\b(?!_)", lines[0]), lines[0]
    assert not r.summary_path.exists() and not r.output_path.exists()
