#!/usr/bin/env python3
"""Benchmark of bin/contact (issue "Speed"): error against cost.

    python3 scripts/bench.py [--quick] [--repeat N] [--out bench] [--dry-run]
    python3 scripts/bench.py --formulations-cost [--cost-sizes 0.06,0.0065] [--out bench]

Runs bin/contact as a black box (`-summary <json>`, through
scripts/contactrun.py) over a sweep of scenes, mesh sizes, contact
formulations (gpts, mortar), solver strategies, penalties and gradient
tolerances, and writes <out>/results.csv (one row per
configuration), <out>/RESULTS.md (design, machine, targets, tables) and the
plots <out>/error_vs_time.png, <out>/time_vs_dofs.png and
<out>/ratio_to_linear.png.

Per mesh, in this order: the meshes are generated (`-mesh_only`, cached in
build/meshes/<scene>, so no timed run includes Gmsh), the linear baseline runs
(`-contact_disable -tao_type nls`: one Newton step, i.e. assembly plus one
sparse direct factorisation and solve of the linear elastic problem), then the
contact runs. Each configuration runs --repeat times (wall time and solve time:
medians); configurations that differ only in their formulation run
interleaved (gpts, mortar, gpts, mortar, ...), so that their time ratio is
measured under the same load. The first repeat of a one-rank configuration
writes its HDF5 output to a temporary directory, from which the pressure
profile is read (scripts/profile_metrics.py) and compared with the finest run
of the same model (scene, formulation, k_p); that repeat's Output stage is
left out of its wall time, and the other repeats run with `-output none`. The
first repeat of the default strategy at k_p = 2e6, gttol 1e-8 also writes
-log_view, from which the contact search and energy evaluation costs per call
and the contact share of the Solve stage are read. Peak memory is each
process's maximum resident set (GNU time %M), summed over the ranks. A run that
fails, times out or does not converge is a row with its reason, never a stop of
the sweep.

--formulations-cost runs only the reference configuration of both
formulations on the hertz scene at the given sizes, interleaved, --repeat
times each (default 3), every run with -log_view, and writes
<out>/formulations.md and <out>/formulations.csv: the mortar / gpts solve time
ratio per size and where each formulation's solve time goes. RESULTS.md
quotes that file when it is in the same directory.

Only numpy, h5py and matplotlib (no scipy). The half model (hertz-half)
reports the full mirrored problem's figures itself (-contact_interface_mirror_y
0), so its rows use the program's JSON figures like every other row.

The code is split by concern: bench_sweep.py (the plan), bench_run.py
(running it), bench_results.py (results.csv, run.json), bench_analysis.py
(references, fits, cheapest configurations), bench_targets.py (the
targets), bench_plots.py (the plots), bench_report.py (RESULTS.md) and
bench_cost.py (--formulations-cost); this file reads the command line and
ties them.
"""
import argparse
import json
import os
import shutil
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import contactrun  # noqa: E402
from bench_analysis import attach_profile_refs, report_figures  # noqa: E402
from bench_cost import formulations_cost  # noqa: E402
from bench_plots import plots  # noqa: E402
from bench_report import now_minute, write_results_md  # noqa: E402
from bench_results import read_csv, read_run, write_csv  # noqa: E402
from bench_run import Sweep, config_key, profile_references, sweep_mesh  # noqa: E402
from bench_sweep import select_plan  # noqa: E402
from contactrun import git_info, load_average, machine_info  # noqa: E402


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="the quick variant (target: under 5 minutes on 2 cores)")
    ap.add_argument("--repeat", type=int, default=None, help="runs per configuration (default 3; quick 1)")
    ap.add_argument("--out", default="bench", help="output directory (default bench)")
    ap.add_argument("--bin", default="bin/contact", help="the program (copied once at the start, so that a "
                    "rebuild during the sweep does not mix versions)")
    ap.add_argument("--timeout", type=float, default=None, help="per-run time limit in s (default 1800; quick 90)")
    ap.add_argument("--only", default=None, help="restrict to scene[:h] entries, comma-separated (e.g. hertz:0.01)")
    ap.add_argument("--strategies", default=None, help="restrict to these strategies, comma-separated")
    ap.add_argument("--formulations", default=None, help="restrict to these formulations, comma-separated")
    ap.add_argument("--merge", action="store_true", help="run the (restricted) plan and merge its rows into "
                    "<out>/results.csv (a row of the same configuration replaced), then rewrite RESULTS.md and "
                    "the plots as --report-only does")
    ap.add_argument("--dry-run", action="store_true", help="print the plan and exit")
    ap.add_argument("--report-only", action="store_true", help="rewrite RESULTS.md and the plots from "
                    "<out>/results.csv and <out>/run.json, running nothing")
    ap.add_argument("--formulations-cost", action="store_true", help="only the mortar / gpts cost comparison "
                    "(hertz, reference configuration, interleaved, -log_view): <out>/formulations.md and .csv")
    ap.add_argument("--cost-sizes", default="0.06,0.0065", help="mesh sizes of --formulations-cost "
                    "(default 0.06,0.0065: the reference mesh and the largest of the full sweep)")
    args = ap.parse_args()
    args.repeat = args.repeat or (1 if args.quick else 3)
    args.timeout = args.timeout or (90.0 if args.quick else 1800.0)
    args.t0 = time.time()
    return args


def report(rows, args, info, meshes, elapsed, load):
    """RESULTS.md, results.csv and the plots of a sweep, from its rows."""
    ctx = report_figures(rows, args, info, meshes, elapsed, load)
    write_csv(rows, os.path.join(args.out, "results.csv"))
    try:
        plots(rows, args.out, ctx.fit_solve, ctx.fit_lin)
    except Exception as e:
        print("plots failed: %s" % e, file=sys.stderr)
    write_results_md(rows, ctx)


def report_only(args):
    """RESULTS.md and the plots again from <out>/results.csv and
    <out>/run.json (the settings and figures of the run that wrote them)."""
    meta = read_run(args.out)
    for k in ("quick", "repeat", "timeout", "bin_orig", "bin_sha"):
        setattr(args, k, meta[k])
    args.bin_git = meta.get("bin_git")
    args.generated = meta.get("generated")  # the sweep's own date, not the report's (older run.json: none)
    sys.argv = [sys.argv[0]] + meta["argv"]
    report(read_csv(os.path.join(args.out, "results.csv")), args, meta["info"], meta["meshes"],
           meta["elapsed"], meta["load"])
    print("rewrote %s/RESULTS.md and the plots" % args.out)


def merge_sweep(args, plan, nconf, tmp):
    """The (restricted) plan's rows merged into <out>/results.csv, then the
    report from the merged rows with the settings of the run that wrote the
    file (run.json; its argv and elapsed time gain this run's). The merged
    rows' profile errors are against their models' references, run again for
    their profiles where the plan does not hold them (profile_references)."""
    R = Sweep(args, tmp, "merge.log")
    R.say("merge: %d meshes, %d configurations, repeat %d, into %s/results.csv" % (len(plan), nconf, args.repeat,
                                                                                  args.out))
    new = []
    for e in plan:
        sweep_mesh(R, e, new, argparse.Namespace(**dict(vars(args), out=tmp)))
    path = os.path.join(args.out, "results.csv")
    stored = read_csv(path)
    attach_profile_refs(new + profile_references(R, new, stored))
    for r in new:   # their figures now stored ones: the report's attach_profile_refs keeps them
        r.pop("_profile", None)
    keys = {config_key(r) for r in new}
    rows = [r for r in stored if config_key(r) not in keys] + new
    meta = read_run(args.out)
    meta["argv"] = meta["argv"] + ["+ merged (binary sha256 %s, git %s):" % (args.bin_sha, args.bin_git)] \
        + sys.argv[1:]
    meta["elapsed"] += time.time() - args.t0
    meta["generated"] = args.generated = now_minute()
    with open(os.path.join(args.out, "run.json"), "w") as fh:
        json.dump(meta, fh, indent=1)
    for k in ("quick", "repeat", "timeout", "bin_orig", "bin_sha"):
        setattr(args, k, meta[k])
    args.bin_git = meta.get("bin_git")
    sys.argv = [sys.argv[0]] + meta["argv"]
    report(rows, args, meta["info"], meta["meshes"], meta["elapsed"], meta["load"])
    R.say("merged %d rows into %s" % (len(new), path))


def run_sweep(args, plan, nconf, tmp):
    """The plan, mesh by mesh, then run.json and the report."""
    R = Sweep(args, tmp)
    info = machine_info()
    load0 = "%.2f" % load_average()
    R.say("%d meshes, %d configurations, repeat %d, timeout %g s, out %s" % (len(plan), nconf, args.repeat,
                                                                              args.timeout, args.out))
    rows = []
    meshes = [sweep_mesh(R, e, rows, args) for e in plan]
    elapsed = time.time() - args.t0
    load = (load0, "%.2f" % load_average())
    args.generated = now_minute()
    with open(os.path.join(args.out, "run.json"), "w") as fh:
        json.dump({"quick": args.quick, "repeat": args.repeat, "timeout": args.timeout, "bin_orig": args.bin_orig,
                   "bin_sha": args.bin_sha, "bin_git": args.bin_git, "argv": sys.argv[1:], "info": info, "meshes": meshes,
                   "elapsed": elapsed, "load": load, "generated": args.generated}, fh, indent=1)
    report(rows, args, info, meshes, elapsed, load)
    R.say("done in %.0f s: %s/results.csv, RESULTS.md, error_vs_time.png, time_vs_dofs.png, ratio_to_linear.png"
          % (elapsed, args.out))


def main():
    args = parse_args()
    os.chdir(ROOT)
    plan = select_plan(args)
    nconf = sum(len(e["configs"]) for e in plan)
    if args.dry_run:
        for e in plan:
            print("%-13s h=%-6g %3d configurations" % (e["scene"], e["h"], len(e["configs"])))
        print("total %d configurations (x repeat %d, plus one linear baseline per mesh)" % (nconf, args.repeat))
        return 0
    os.makedirs(args.out, exist_ok=True)
    args.out = os.path.abspath(args.out)
    if args.report_only:
        report_only(args)
        return 0
    tmp = tempfile.mkdtemp(prefix="bench-")
    try:
        args.bin_orig = os.path.abspath(args.bin)
        args.bin_sha = contactrun.program_sha(args.bin_orig)
        args.bin_git = git_info(args.out)  # the tree when the program was copied
        args.bin = contactrun.copy_program(tmp, args.bin_orig)
        if args.formulations_cost:
            formulations_cost(args, Sweep(args, tmp, "formulations.log"))
        elif args.merge:
            merge_sweep(args, plan, nconf, tmp)
        else:
            run_sweep(args, plan, nconf, tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
