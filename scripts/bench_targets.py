"""The benchmark's targets (scripts/bench.py): those of the issue "Speed" and
of the mortar formulation's cost, each measured from the rows, met or not.

Each target_* function returns its rows of RESULTS.md's table of targets,
(target, what was measured, status); TARGETS holds them in order, target_rows
gathers their rows, report_targets makes the table and met reads a status.
"""
import os

from bench_analysis import (cost_ratio_pairs, fastest, fit_runs, fixed_cost_share, linear_ratio_runs,
                            reference_solve_runs, search_share, worst_ratio)
from bench_sweep import fmt
from contactrun import finite


COST_TARGET = 1.5     # mortar solve time / gpts solve time, reference configuration
REF_SOLVE_TARGET = 0.5  # s: the reference scene's solve time at h = 0.06 (gpts, newton, k_p 2e6, gttol 1e-8, one core)
LINEAR_RATIO_TARGET = 10  # time-to-solution in linear solves of the same mesh, on the meshes from 1e4 dofs
EXPONENT_TARGET = 1.2   # solve time growing like dofs^k from 1e4 to 1e6 dofs: k at most this
FIXED_COST_TARGET = 0.2  # mesh reading + set-up + output under this share of the whole run at 1e6 dofs
SEARCH_TARGET = 0.1     # contact search per call under this share of an energy evaluation at 1e6 dofs


def status(ok):
    return "MET" if ok else "NOT MET"


def met(status_text):
    """Whether a target's status says it is met outright (not only with another strategy, not only here)."""
    return status_text.split(" (")[0] == "MET"


def cost_ratio_text(g, m):
    """'ratio (mortar x s / gpts y s, n repeats)' for two rows."""
    return "%.2f (mortar %.3g s / gpts %.3g s; %s and %s repeats, interleaved)" % (
        m["solve_median"] / g["solve_median"], m["solve_median"], g["solve_median"], m.get("repeats", "?"),
        g.get("repeats", "?"))


def target_reference_solve(rows, ctx):
    """Solve time on the reference mesh, h = 0.06 (gpts)."""
    d06, conv06 = reference_solve_runs(rows)
    if not conv06:
        return [("reference scene, h = 0.06, solve <= %g s" % REF_SOLVE_TARGET, "no converged run", "NOT MEASURED")]
    best = fastest(conv06)
    dtxt = ("default (newton) %.3g s" % d06[0]["solve_median"]) if d06 and finite(d06[0].get("solve_median")) else "default: not converged"
    dok = bool(d06) and d06[0]["converged"] and d06[0]["solve_median"] <= REF_SOLVE_TARGET
    st = "MET" if dok else ("MET with %s only" % best["strategy"] if best["solve_median"] <= REF_SOLVE_TARGET
                            else "NOT MET")
    return [("reference scene, h = 0.06, k_p = 2e6, gttol 1e-8, solve time <= %g s on one core (gpts)"
             % REF_SOLVE_TARGET,
             "%s; fastest: %s %.3g s (%d iterations)" % (dtxt, best["strategy"], best["solve_median"],
                                                        best.get("iterations", 0)), st)]


def target_linear_ratio(rows, ctx):
    """Time-to-solution in linear solves of the same mesh."""
    rat, big_rat = linear_ratio_runs(ctx.ref_sel)
    if not big_rat:
        return [("time-to-solution <= %g linear solves" % LINEAR_RATIO_TARGET, "-", "NOT MEASURED")]
    worst = worst_ratio(big_rat)
    small = [r for r in rat if r not in big_rat and r["ratio_to_linear"] > LINEAR_RATIO_TARGET]
    return [("time-to-solution <= %g linear solves of the same mesh (gpts, newton, k_p 2e6, 1e-8, uniform meshes from "
             "1e4 dofs; below, a linear solve takes milliseconds and fixed costs dominate)" % LINEAR_RATIO_TARGET,
             "%s; worst %.1f at %d dofs" % (", ".join("%.1f (%d dofs)" % (r["ratio_to_linear"], r["dofs"]) for r in rat),
                                            worst["ratio_to_linear"], worst["dofs"]),
             "%s%s" % (status(worst["ratio_to_linear"] <= LINEAR_RATIO_TARGET),
                       (" (over %g below 1e4 dofs: %s)" % (LINEAR_RATIO_TARGET,
                                                          ", ".join("%d dofs" % r["dofs"] for r in small)))
                       if small else ""))]


def target_exponent(rows, ctx):
    """The cost exponent from 1e4 to 1e6 dofs."""
    ref_sel = ctx.ref_sel
    fit_solve, n_solve, fit_wall, fit_lin, fit_mort, n_mort = (ctx.fit_solve, ctx.n_solve, ctx.fit_wall, ctx.fit_lin,
                                                                ctx.fit_mort, ctx.n_mort)
    span = [r["dofs"] for r in fit_runs(ref_sel)]
    if fit_solve and span and max(span) >= 5e5:
        return [("cost exponent <= %g from 1e4 to 1e6 dofs (solve time, gpts, newton)" % EXPONENT_TARGET,
                 "%.2f over %d meshes, %d..%d dofs (wall time: %.2f; linear solve: %s; mortar's solve time: %s)"
                 % (fit_solve[0], n_solve, min(span), max(span), fit_wall[0] if fit_wall else float("nan"),
                    fmt(fit_lin[0] if fit_lin else None, "%.2f"),
                    ("%.2f over %d meshes" % (fit_mort[0], n_mort)) if fit_mort else "-"),
                 status(fit_solve[0] <= EXPONENT_TARGET))]
    return [("cost exponent <= %g from 1e4 to 1e6 dofs" % EXPONENT_TARGET,
             "%.2f over %d..%d dofs only" % (fit_solve[0], min(span), max(span)) if fit_solve and span else "-",
             "NOT MEASURED (needs meshes up to 1e6 dofs: full sweep)")]


def target_fixed_costs(rows, ctx):
    """Mesh reading, set-up and output against the total at the largest mesh."""
    big = ctx.ref_sel[-1] if ctx.ref_sel else None
    if not (big and finite(big.get("time_total"))):
        return []
    frac = fixed_cost_share(big)
    ok = big["dofs"] >= 5e5
    return [("mesh reading + set-up + output < %g %% of the total at 1e6 dofs" % (100 * FIXED_COST_TARGET),
             "%.1f %% at %d dofs (mesh %.2f s, set-up %.2f s, output %.2f s of %.2f s; output off: -output none)"
             % (100 * frac, big["dofs"], big["time_mesh"], big["time_setup"], big["time_output"], big["time_total"]),
             status(frac < FIXED_COST_TARGET) if ok
             else "NOT MEASURED at 1e6 dofs (largest mesh here %d dofs: %s there)" % (big["dofs"],
                                                                                    status(frac < FIXED_COST_TARGET)))]


def target_search(rows, ctx):
    """The contact search against an energy evaluation at the largest mesh."""
    big = ctx.ref_sel[-1] if ctx.ref_sel else None
    if not (big and finite(big.get("search_time_per_call"))):
        return []
    f = search_share(big)
    ok = big["dofs"] >= 5e5
    return [("contact search a small fraction of an energy evaluation at 1e6 dofs",
             "search %.3g ms per call, energy evaluation %.3g ms per call: %.2f %% at %d dofs"
             % (1e3 * big["search_time_per_call"], 1e3 * big["energy_time_per_call"], 100 * f, big["dofs"]),
             (status(f < SEARCH_TARGET) + " (taken as < %g %%)" % (100 * SEARCH_TARGET)) if ok
             else "NOT MEASURED at 1e6 dofs (%s at %d dofs)" % (status(f < SEARCH_TARGET), big["dofs"]))]


def target_mortar_cost(rows, ctx):
    """Mortar's solve time against gpts' on the same mesh (this sweep's pairs)."""
    out = ctx.out
    pairs = cost_ratio_pairs(rows)
    finest = pairs[-1] if pairs else None
    items = [("h = 0.06" if p[0] == 0.06 else "largest mesh of this sweep, h = %g (%d dofs)" % (p[0], p[1]["dofs"]), p)
             for p in pairs]
    if not items:
        return [("mortar / gpts solve time <= %g at h = 0.06 and at the largest mesh" % COST_TARGET,
                 "no pair of converged runs", "NOT MEASURED")]
    ratios = [p[2]["solve_median"] / p[1]["solve_median"] for _, p in items]
    ok = all(x <= COST_TARGET for x in ratios)
    text = "; ".join("%s: %s" % (label, cost_ratio_text(p[1], p[2])) for label, p in items)
    if finest[1]["dofs"] < 5e5:
        text += "; h = %g is this sweep's largest mesh" % finest[0]
    return [("mortar / gpts solve time <= %g (hertz, newton, k_p 2e6, gttol 1e-8, one core; medians of runs made "
             "interleaved) at h = 0.06 and at the largest mesh" % COST_TARGET, text,
             status(ok) if finest[1]["dofs"] >= 5e5
             else "%s here; at 1e6 dofs: NOT MEASURED in this sweep%s" % (
                 status(ok), " (see the next row)" if os.path.exists(os.path.join(out, "formulations.csv")) else ""))]


def target_formulations_cost(rows, ctx):
    """The same ratio from formulations.csv (--formulations-cost), where it exists."""
    fc = ctx.fc
    if not fc:
        return []
    sizes = sorted({float(r["h"]) for r in fc}, reverse=True)
    parts, oks = [], []
    for h in sizes:
        rr = {r["formulation"]: r for r in fc if float(r["h"]) == h}
        if "gpts" in rr and "mortar" in rr and rr["mortar"].get("ratio"):
            ratio = float(rr["mortar"]["ratio"])
            oks.append(ratio <= COST_TARGET)
            parts.append("h = %g (%s dofs): %.2f (mortar %.3g s / gpts %.3g s)" % (
                h, rr["gpts"]["dofs"], ratio, float(rr["mortar"]["solve_median"]),
                float(rr["gpts"]["solve_median"])))
    return [("the same, from `formulations.md` (`--formulations-cost`, %s, median of %s, interleaved)"
             % (fc[0].get("date", "?"), fc[0].get("repeats", "?")), "; ".join(parts) or "-",
             status(all(oks)) if oks else "NOT MEASURED")]


def target_rows(rows, ctx):
    """The targets' rows, each (target, what was measured, status), in the order of TARGETS."""
    return [row for target in TARGETS for row in target(rows, ctx)]


def report_targets(rows, ctx):
    """The targets of the issue "Speed" and of the mortar formulation's cost, each measured, met or
    not."""
    return (["## Targets", "", "| target | measured | status |", "|---|---|---|"]
            + ["| %s | %s | %s |" % row for row in target_rows(rows, ctx)] + [""])


# the targets, in order: each returns its rows of the targets' table, (target, what was measured, status)
TARGETS = (target_reference_solve, target_linear_ratio, target_exponent, target_fixed_costs, target_search,
           target_mortar_cost, target_formulations_cost)
