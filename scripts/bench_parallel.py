#!/usr/bin/env python3
"""Parallel benchmark of bin/contact (issue "Parallel that pays"): 1 against 2 ranks.

    python3 scripts/bench_parallel.py [--repeat 3] [--sizes 0.06,0.015,0.01,0.0065] [--formulation mortar]
                                      [--out bench/parallel]

The reference scene at each mesh size, the default solver (Newton through the
Schur complement on the contact surfaces), k_p = 2e6, -tao_gttol 1e-8, the
contact formulation --formulation (by default none is passed: the program's
default, read back from each run's summary), on 1
and on 2 ranks (one core each), interleaved: repeat 1 of every configuration,
then repeat 2, ..., so that a change of the machine's load falls on both rank
counts alike. `--configs` adds variants (for instance the one-rank MUMPS Schur
step, `1:mumps`). Every run writes its JSON summary and -log_view; the figures
are medians over the repeats, and the speed-up is the ratio of the medians
(1 rank over 2 ranks) of the solve time (the Solve stage: TAO's Newton
iterations with the factorisations) and of the whole process's wall time
(mpiexec start-up, mesh reading, partitioning, set-up, solve, output).

Writes <out>/results.csv (one row per run) and <out>/RESULTS.md (machine,
load, the speed-up table against the targets, the time per phase and per
event, max over ranks). The machine is shared: the load average before each
run is recorded beside it, and so is the CPU time other processes took during
it (/proc/stat's busy time less this script's children's); a run during which
they took more than --foreign-max of a core is run again (--retries), since
a 2-rank run that shares a core with another job loses far more than a 1-rank
run does (each barrier waits for the slower rank), which would bias the
speed-up against 2 ranks.
"""
import argparse
import csv
import os
import shutil
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contactrun import (copy_program, event_totals, git_info, load_average, machine_info,  # noqa: E402
                        median, mesh_only, parse_log_view, run)

SCENE = "meshes/hertz/hertz.opts"
# configuration name -> (ranks, extra options)
CONFIGS = {
    "1": (1, []),
    "2": (2, []),
    "1:mumps": (1, ["-newton_schur_type", "mumps"]),
    "1:substructure": (1, ["-newton_schur_type", "substructure"]),
    "2:factor": (2, ["-newton_schur", "0"]),
    # the BLAS kernel (-blas_kernel): OpenBLAS's Prescott fallback, and the
    # AVX-512 kernels that the program's auto choice runs on such CPUs
    "1:prescott": (1, ["-blas_kernel", "Prescott"]),
    "2:prescott": (2, ["-blas_kernel", "Prescott"]),
    "1:skylakex": (1, ["-blas_kernel", "SkylakeX"]),
    "2:skylakex": (2, ["-blas_kernel", "SkylakeX"]),
}
EVENTS = ["MeshPartition", "ElasHessian", "ElasEnergyGrad", "ContactEnergyGrad", "ContactSearch", "ContactHessian",
          "MortarEnergyGrad", "MortarSegments", "MortarHessian", "MatCopy", "SubstrFactor", "SubstrInterface", "SubstrStep", "SubstrSolve", "SchurFactorK", "SchurStep", "MatSolve",
          "MatCholFctrNum", "WriteOutput"]
STAGES = ["Mesh", "Setup", "Solve", "PostProcess", "Output"]
# speed-up targets (the issue "Mortar pays in parallel"): h -> least ratio of
# 1-rank to 2-rank solve time, and of the whole run's wall time
TARGETS = {0.06: 1.0, 0.015: 1.6, 0.01: 1.6, 0.0065: 1.7}
WALL_TARGETS = {0.015: 1.4}


def running_processes():
    with open("/proc/stat") as fh:
        for line in fh:
            if line.startswith("procs_running"):
                return int(line.split()[1])
    return 0


def wait_quiet(limit):
    """Waits until no other process is running (procs_running is this reader
    alone at five polls in a row, 0.5 s apart), at most limit seconds; returns
    the time waited."""
    t0, calm = time.time(), 0
    while time.time() - t0 < limit:
        calm = calm + 1 if running_processes() <= 1 else 0
        if calm >= 5:
            break
        time.sleep(0.5)
    return time.time() - t0


def busy_seconds():
    """CPU time spent by every process of the machine so far (user, nice,
    system, interrupts; /proc/stat), seconds."""
    with open("/proc/stat") as fh:
        f = [int(x) for x in fh.readline().split()[1:8]]
    return (f[0] + f[1] + f[2] + f[5] + f[6]) / float(os.sysconf("SC_CLK_TCK"))


def children_seconds():
    """CPU time of this script's finished child processes (and theirs: mpiexec
    waits for its ranks), seconds."""
    import resource
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_when_quiet(args, binary, opts, ranks, tmp, tag, label):
    """One run, started once no other process is running (--quiet-wait),
    with its JSON summary, -log_view and each rank's peak memory in tmp; run
    again, at most --retries times, while other processes took more than
    --foreign-max of a core during it. Returns the last Run and the figures
    of its load: {load, waited, foreign, attempts}."""
    files = dict(summary=os.path.join(tmp, tag + ".json"), log_view=os.path.join(tmp, tag + ".log"),
                 peak_memory=os.path.join(tmp, tag + ".mem"))
    for attempt in range(1, args.retries + 2):
        waited = wait_quiet(args.quiet_wait)
        load = load_average()
        busy, ours = busy_seconds(), children_seconds()
        res = run(opts, ranks, binary, output="none", timeout=args.timeout, **files)
        if res.timed_out:
            raise SystemExit("%s: no answer after %g s (--timeout)" % (label, args.timeout))
        # CPU time that other processes took during the run, as a fraction of one
        # core; below 0.15 s in all it is taken for the run's own (a 1-rank run's
        # MPI singleton starts an orted of its own, outside this script's children)
        other = max(0.0, (busy_seconds() - busy) - (children_seconds() - ours))
        foreign = other / res.wall
        if res.returncode or foreign <= args.foreign_max or other <= 0.15 or attempt > args.retries:
            break
        print("%s: other processes took %.0f %% of a core during the run (%.2f s); again"
              % (label, 100 * foreign, res.wall), flush=True)
    return res, {"load": load, "waited": waited, "foreign": foreign, "attempts": attempt}


def run_config(args, binary, h, name, rep, tmp):
    """One repeat of configuration name at mesh size h: its row (the run's
    load, wall time and exit status, the summary's figures, peak memory, the
    -log_view events and stages)."""
    ranks, extra = CONFIGS[name]
    tag = "h%s_%s_r%d" % (h, name.replace(":", "-"), rep)
    opts = (["-options_file", SCENE, "-mesh_size", repr(h)]
            + (["-contact_formulation", args.formulation] if args.formulation else []) + extra)
    res, quiet = run_when_quiet(args, binary, opts, ranks, tmp, tag, "h %-6s %-16s repeat %d" % (h, name, rep))
    row = {"h": h, "config": name, "ranks": ranks, "repeat": rep, "load": quiet["load"], "waited": quiet["waited"],
           "wall": res.wall, "rc": res.returncode, "foreign": quiet["foreign"], "attempts": quiet["attempts"]}
    s = res.summary if res.returncode == 0 else None
    if s:
        row.update(dofs=s["dofs"], iterations=s["iterations"], evaluations=s.get("function_evaluations", ""),
                   P=s["contact_force"], energy=s["energy"],
                   formulation=",".join(sorted({c["formulation"] for c in s.get("contact", {}).values()})))
        for k, v in s["time"].items():
            row["time_" + k] = v
    if None not in res.peaks:
        row["mem_max_rank_mb"] = max(res.peaks)
        row["mem_total_mb"] = sum(res.peaks)
    lv = parse_log_view(os.path.join(tmp, tag + ".log"))
    events = event_totals(lv)
    for e in EVENTS:
        row["ev_" + e] = events[e][1] if e in events else ""
    for st in STAGES:
        row["stage_" + st] = lv["stages"].get(st, "")
    if args.keep_logs and rep == 1:
        shutil.copy(os.path.join(tmp, tag + ".log"), os.path.join(args.out, tag + ".log_view.txt"))
    return row


def med(rows, key):
    """The median of a column over rows."""
    return median(r.get(key) for r in rows)


def rank_pairs(rows):
    """[(h, its 1-rank runs, its 2-rank runs)] for each h that has both, largest h first."""
    pairs = []
    for h in sorted({r["h"] for r in rows}, reverse=True):
        one = [r for r in rows if r["h"] == h and r["config"] == "1"]
        two = [r for r in rows if r["h"] == h and r["config"] == "2"]
        if one and two:
            pairs.append((h, one, two))
    return pairs


def speedup_table(pairs):
    """The Markdown lines of the speed-up table (RESULTS.md and bench/README.md's
    generated copy, scripts/readme_figures.py): medians, each run's solve
    time, the targets and their verdicts."""
    def verdict(ratio, target):
        return ((">= %.1f" % target), "MET" if ratio >= target else "NOT MET") if target else ("", "")
    L = ["| h | dofs | iterations (evaluations) | solve 1 rank [s] | solve 2 ranks [s] | speed-up (solve) "
         "| target | | wall 1 rank [s] | wall 2 ranks [s] | speed-up (wall) | target | |",
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for h, one, two in pairs:
        s1, s2, w1, w2 = med(one, "time_solve"), med(two, "time_solve"), med(one, "wall"), med(two, "wall")
        runs1 = ", ".join("%.2f" % r["time_solve"] for r in one if isinstance(r.get("time_solve"), float))
        runs2 = ", ".join("%.2f" % r["time_solve"] for r in two if isinstance(r.get("time_solve"), float))
        L.append("| %s | %s | %s (%s) | %.2f (%s) | %.2f (%s) | **%.2f** | %s | %s | %.2f | %.2f | **%.2f** | %s | %s |"
                 % ((h, "{:,}".format(int(one[0].get("dofs", 0))), one[0].get("iterations", "?"),
                     one[0].get("evaluations", "?"), s1, runs1, s2, runs2, s1 / s2) + verdict(s1 / s2, TARGETS.get(h))
                    + (w1, w2, w1 / w2) + verdict(w1 / w2, WALL_TARGETS.get(h))))
    return L


def load_rows(path):
    """The rows of a results.csv, numbers as numbers."""
    rows = []
    with open(path) as fh:
        for r in csv.DictReader(fh):
            for k, v in r.items():
                if k in ("config", "formulation"):
                    continue
                try:
                    r[k] = int(v) if k in ("ranks", "repeat", "rc", "dofs", "iterations", "evaluations",
                                            "attempts") else float(v)
                except (TypeError, ValueError):
                    pass
            rows.append(r)
    return rows


def report(args, rows, info, elapsed):
    sizes = sorted({r["h"] for r in rows}, reverse=True)
    names = [c for c in args.configs]
    L = []
    L.append("# Parallel benchmark: 1 against 2 ranks\n")
    L.append("`python3 scripts/bench_parallel.py --repeat %d --sizes %s --configs %s%s` (%.0f s), commit %s.\n"
             % (args.repeat, ",".join(str(h) for h in sizes), ",".join(names),
                " --formulation " + args.formulation if args.formulation else "", elapsed, git_info()))
    L.append("Machine: %s, %s cores, %s, %s; PETSc %s. Load average before the runs: median %.2f, max %.2f "
             "(the machine is shared; a run's load includes other users' jobs).\n"
             % (info["cpu"], info["nproc"], info["mem"], info["blas"], info["petsc"],
                median(r["load"] for r in rows), max(r["load"] for r in rows)))
    forms = sorted({r["formulation"] for r in rows if r.get("formulation")})
    L.append("Reference scene, contact formulation %s (%s), default solver, k_p = 2e6, `-tao_gttol 1e-8`, "
             "`-output none`; configurations interleaved, %d repeats, medians. Speed-up: median over 1 rank "
             "divided by median over 2 ranks. Each run started once no other process was running (waiting at "
             "most %g s; median wait %.1f s); a run during which other processes took more than %.0f %% of a core "
             "was run again, at most %d times (%d of %d runs were; the last try is kept, and other processes took a "
             "median %.1f %%, at most %.0f %% of a core during the kept runs).\n"
             % (", ".join(forms) or "?", "`-contact_formulation %s`" % args.formulation if args.formulation
                else "the program's default", args.repeat, args.quiet_wait,
                median(r["waited"] for r in rows), 100 * args.foreign_max, args.retries,
                sum(r["attempts"] > 1 for r in rows), len(rows), 100 * median(r["foreign"] for r in rows),
                100 * max(r["foreign"] for r in rows)))
    pairs = rank_pairs(rows)
    L += speedup_table(pairs)
    L.append("")
    L.append("Median time per -log_view stage (average over ranks), seconds, and its speed-up:\n")
    L.append("| h | stage | 1 rank | 2 ranks | speed-up |")
    L.append("|---|---|---|---|---|")
    for h, one, two in pairs:
        for st in STAGES:
            a, b = med(one, "stage_" + st), med(two, "stage_" + st)
            L.append("| %s | %s | %.3g | %.3g | %.2f |" % (h, st, a, b, a / b if b > 0 else float("nan")))
    L.append("")
    L.append("Median time per phase (JSON summary, rank 0) and per event (-log_view, max over ranks), seconds; "
             "peak resident memory (GNU time), MB, of the largest rank and summed over ranks:\n")
    cols = ["time_mesh", "time_setup", "time_solve", "time_output", "time_total", "wall", "mem_max_rank_mb",
            "mem_total_mb"] + ["ev_" + e for e in EVENTS]
    present = [c for c in cols if any(isinstance(r.get(c), (int, float)) for r in rows)]
    L.append("| h | config | " + " | ".join(c.replace("time_", "").replace("ev_", "") for c in present) + " |")
    L.append("|---|---|" + "---|" * len(present))
    for h in sizes:
        for n in names:
            sel = [r for r in rows if r["h"] == h and r["config"] == n]
            if sel:
                L.append("| %s | %s | " % (h, n) + " | ".join("%.3g" % med(sel, c) for c in present) + " |")
    L.append("")
    failed = [r for r in rows if r["rc"] != 0]
    if failed:
        L.append("Failed runs: " + ", ".join("h %s %s repeat %d (rc %s)" % (r["h"], r["config"], r["repeat"], r["rc"])
                                           for r in failed) + "\n")
    with open(os.path.join(args.out, "RESULTS.md"), "w") as fh:
        fh.write("\n".join(L) + "\n")
    print("\n".join(L))


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sizes", default="0.06,0.015,0.01,0.0065")
    ap.add_argument("--configs", default="1,2", help="comma-separated, from: " + ", ".join(CONFIGS))
    ap.add_argument("--formulation", default=None, help="-contact_formulation of every run (default: none "
                    "passed, the program's own default)")
    ap.add_argument("--out", default="bench/parallel")
    ap.add_argument("--bin", default="bin/contact")
    ap.add_argument("--timeout", type=float, default=1200)
    ap.add_argument("--keep-logs", action="store_true", help="copy the first repeat's -log_view of each "
                    "configuration and size into --out")
    ap.add_argument("--foreign-max", type=float, default=0.05, help="a run during which other processes took more "
                    "than this fraction of a core is run again (a 2-rank run that shares a core waits at every "
                    "barrier for its slower rank; a 1-rank run hardly notices)")
    ap.add_argument("--retries", type=int, default=3, help="runs again at most this many times (the last one is kept)")
    ap.add_argument("--quiet-wait", type=float, default=60, help="before each run, wait up to this many seconds "
                    "for no other process to be running (the machine is shared; 0: start at once)")
    args = ap.parse_args()
    args.configs = args.configs.split(",")
    for c in args.configs:
        if c not in CONFIGS:
            ap.error("unknown configuration %s (known: %s)" % (c, ", ".join(CONFIGS)))
    os.makedirs(os.path.join(ROOT, args.out), exist_ok=True)
    args.out = os.path.join(ROOT, args.out)
    return args


def measure(args, sizes):
    """Every configuration at every size, interleaved (repeat 1 of each,
    then repeat 2, ...), on a copy of the program, the meshes generated
    first: the rows."""
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench-par-") as tmp:
        binary = copy_program(tmp, os.path.join(ROOT, args.bin))
        for h in sizes:
            res = mesh_only(["-options_file", SCENE, "-mesh_size", repr(h)], binary)
            if res.returncode:
                raise SystemExit("%s failed:\n%s%s" % (" ".join(res.cmd), res.stdout, res.stderr))
        for h in sizes:
            for rep in range(1, args.repeat + 1):
                for name in args.configs:
                    r = run_config(args, binary, h, name, rep, tmp)
                    rows.append(r)
                    print("h %-6s %-16s repeat %d: solve %s s, wall %.2f s, load %.2f" %
                          (h, name, rep, "%.2f" % r["time_solve"] if "time_solve" in r else "FAILED rc %s" % r["rc"],
                           r["wall"], r["load"]), flush=True)
    return rows


def write_rows(rows, path):
    """results.csv: one row per run, the columns in order of first appearance."""
    keys = []
    for r in rows:
        for k in r:
            if k not in keys:
                keys.append(k)
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow(r)


def main():
    args = parse_args()
    info = machine_info()
    t0 = time.time()
    rows = measure(args, [float(h) for h in args.sizes.split(",")])
    write_rows(rows, os.path.join(args.out, "results.csv"))
    report(args, rows, info, time.time() - t0)


if __name__ == "__main__":
    main()
