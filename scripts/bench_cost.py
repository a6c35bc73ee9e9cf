"""The mortar / gpts cost comparison (scripts/bench.py --formulations-cost):
its runs, formulations.csv and formulations.md.

Both formulations' reference runs on the hertz scene at each size,
interleaved, every run with -log_view: the ratio of their solve times per
size against the target, and where each formulation's Solve stage goes.
"""
import datetime
import os
import sys
import time

from bench_report import bin_git
from bench_results import COST_FIELDS, write_csv
from bench_run import run_interleaved
from bench_sweep import FORMULATIONS, REF_KP, REF_STRATEGY, REF_TOL, config_name, fmt, pct
from bench_targets import COST_TARGET, status
from contactrun import ROOT, finite, load_average, nproc


def measure_formulations_cost(args, R, sizes, date):
    """Both formulations' reference runs on hertz at each size, interleaved,
    --repeat times, -log_view on every run: the rows, each with its solve
    time's ratio to gpts'."""
    rows = []
    for h in sizes:
        mt, err = R.mesh("hertz", h)
        cfgs = [(REF_STRATEGY, REF_KP, REF_TOL, 1, None, f) for f in FORMULATIONS]
        if err:
            R.say("hertz h=%g: %s" % (h, err))
            rows += [{"h": h, "formulation": c[5], "converged": False, "reason": err} for c in cfgs]
            continue
        done = run_interleaved(R, "hertz", h, cfgs, args.repeat, lambda c: "all", lambda c: False)
        g = done[0]
        for row in done:
            row["date"] = date
            if finite(row.get("solve_median")) and finite(g.get("solve_median")):
                row["ratio"] = row["solve_median"] / g["solve_median"]
            R.say("%-52s %8s dofs  it %5s  solve %s s (%s)  ratio to gpts %s  contact share %s  %s" % (
                config_name(row), row.get("dofs", "-"), row.get("iterations", "-"), fmt(row.get("solve_median")),
                row.get("solve_runs", ""), fmt(row.get("ratio"), "%.2f"), pct(row.get("contact_share")),
                row["reason"]))
        rows += done
    return rows


def cost_header(args, date, load0):
    """formulations.md's title, provenance and design."""
    L = []
    A = L.append
    A("# Cost of the mortar formulation (`scripts/bench.py --formulations-cost`)")
    A("")
    A("Generated %s by `python3 scripts/bench.py %s` in %.0f s. Binary: `%s` (git %s; sha256 %s). One shared "
      "machine (%s cores; load average %s at the start, %.2f at the end)."
      % (date, " ".join(sys.argv[1:]), time.time() - args.t0,
         os.path.relpath(args.bin_orig, ROOT) if args.bin_orig.startswith(ROOT) else args.bin_orig,
         bin_git(args), args.bin_sha, nproc(), load0, load_average()))
    A("")
    A("The reference scene (hertz), newton, k_p = 2e6, gttol 1e-8, one rank, `-output none`, each formulation "
      "run %d times, interleaved (gpts, mortar, gpts, mortar, ...), so that both see the same load; every run "
      "writes -log_view (both alike). Solve: the program's Solve stage (JSON time.solve), median of the "
      "repeats. Target: mortar / gpts solve time <= %g at h = 0.06 and at the largest mesh (issue \"A contact "
      "pressure that converges\", item 7)." % (args.repeat, COST_TARGET))
    A("")
    return L


def cost_ratio_table(rows, sizes):
    """The mortar / gpts solve time ratio per size, against the target."""
    L = []
    A = L.append
    A("| h | dofs | solve gpts [s] | solve mortar [s] | mortar / gpts | status |")
    A("|---|---|---|---|---|---|")
    for h in sizes:
        rr = {r["formulation"]: r for r in rows if r["h"] == h}
        g, m = rr.get("gpts", {}), rr.get("mortar", {})
        ok = finite(m.get("ratio")) and g.get("converged") and m.get("converged")
        A("| %g | %s | %s | %s | %s | %s |" % (
            h, g.get("dofs", "-"), g.get("solve_runs") or g.get("reason", "-"),
            m.get("solve_runs") or m.get("reason", "-"), fmt(m.get("ratio"), "%.2f"),
            status(m["ratio"] <= COST_TARGET) if ok else "NOT MEASURED"))
    A("")
    A("(solve columns: the repeats in the order run; the ratio is that of the medians.)")
    A("")
    return L


def cost_breakdown_table(rows):
    """Where each formulation's Solve stage goes, per size."""
    L = []
    A = L.append
    A("Where the Solve stage goes (medians over the repeats' -log_view, Solve stage only). *factor K*: "
      "SchurFactorK, the sparse factorisation of the elastic stiffness, once per solve; *Newton linear "
      "algebra*: KSPSolve + PCSetUp (per step: the surface block's dense factorisation and the solves through "
      "the factor); *elastic*: ElasEnergyGrad + ElasHessian; *contact*: ContactEnergyGrad + ContactHessian "
      "(gpts) or MortarEnergyGrad + MortarHessian (mortar), search and segments included; *other*: the rest "
      "(TAO's vector work, the line search).")
    A("")
    A("| h | formulation | iterations | energy evals | Hessians | solve [s] | solve / iteration [s] | factor K "
      "| Newton linear algebra | elastic | contact | other | contact share | search / call [ms] "
      "| segments / call [ms] | peak MB | P | l2 vs Hertz |")
    A("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if not finite(r.get("solve_median")):
            A("| %g | %s | %s |%s" % (r["h"], r["formulation"], r.get("reason", "-"), " |" * 15))
            continue
        st = r.get("solve_stage_time")

        def part(k):
            return ("%.3g s (%s)" % (r[k], pct(r[k] / st))) if finite(r.get(k)) and finite(st) and st > 0 else "-"
        A("| %g | %s | %s | %s | %s | %.3g | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.0f | %s | %s |" % (
            r["h"], r["formulation"], r.get("iterations", "-"), r.get("energy_evals", "-"),
            r.get("hessian_evals", "-"), r["solve_median"],
            fmt(r["solve_median"] / r["iterations"] if r.get("iterations") else None), part("t_factor_k"),
            part("t_newton_linear"), part("t_elastic"), part("contact_solve_time"), part("t_other"),
            pct(r.get("contact_share")), fmt(1e3 * r["search_time_per_call"] if finite(r.get("search_time_per_call")) else None),
            fmt(1e3 * r["segments_time_per_call"] if finite(r.get("segments_time_per_call")) else None),
            r.get("peak_mb", float("nan")), fmt(r.get("P"), "%.6g"), pct(r.get("l2_err"))))
    A("")
    return L


def formulations_cost(args, R):
    """Both formulations' reference runs on hertz at each size of
    --cost-sizes, interleaved, --repeat times, -log_view on every run:
    <out>/formulations.csv and <out>/formulations.md."""
    sizes = [float(x) for x in args.cost_sizes.split(",")]
    date = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    load0 = "%.2f" % load_average()
    rows = measure_formulations_cost(args, R, sizes, date)
    write_csv(rows, os.path.join(args.out, "formulations.csv"), COST_FIELDS)
    L = cost_header(args, date, load0) + cost_ratio_table(rows, sizes) + cost_breakdown_table(rows)
    L.append("Files: formulations.csv (one row per size and formulation), formulations.log (the run's log).")
    with open(os.path.join(args.out, "formulations.md.tmp"), "w") as fh:
        fh.write("\n".join(L) + "\n")
    os.replace(os.path.join(args.out, "formulations.md.tmp"), os.path.join(args.out, "formulations.md"))
    R.say("done: %s/formulations.md, formulations.csv" % args.out)
