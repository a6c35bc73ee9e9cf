#!/usr/bin/env python3
"""Robustness sweep: every combination of mesh size, penalty and push, with
both contact formulations, on 1 and 2 ranks; every run must converge, or stop
with one line naming why.

    python3 scripts/stress_sweep.py [--out bench/stress] [--resume]
                                    [--h 0.25 0.1] [--ranks 1] [--formulation mortar]
                                    [--tao-type lmvm]

The scene is the mirrored half of the reference scene
(meshes/hertz-half/hertz-half.opts: the same problem as meshes/hertz at half
the dofs, its contact force that of the whole model), at
h in {0.25, 0.1, 0.03, 0.01, 0.005} x k_p in {1e3, 1e6, 1e10} x push in
{0.01, 0.15, 0.3}, gpts and mortar, 1 and 2 ranks: 180 runs, one at a time,
Newton with the program's defaults (--tao-type: another TAO type, at its
defaults), `-tao_monitor`, `-output none`. About
30 minutes on 2 cores, two thirds of it at h = 0.005 (905,296 dofs; the whole
scene would have 1.8 million, and its slowest case, gpts at k_p = 1e10 and
push 0.3, took 320 s alone).

It writes <out>/results.json (one record per run: the case, the command line,
exit status, converged, TAO reason, Newton iterations, energy evaluations,
solve and wall time, dofs, P, the pair's force and the pushed edge's reaction,
and for a run that stops the one line it printed and the name of the file in
<out>/stopped/ that keeps its whole output, -tao_monitor's lines and the
report of its last iterate; then the agreement of 1 and 2 ranks on P) after
every run, so that an interrupted sweep keeps what it did
(--resume skips the runs already there), and <out>/RESULTS.md (the compact
table and every run). scripts/readme_figures.py renders the compact table into
bench/README.md from results.json.
"""
import argparse
import datetime
import json
import os
import re
import shlex
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from contactrun import copy_program, git, load_average, parse_tao_line, power, program_sha, run_case  # noqa: E402

SCENE = "meshes/hertz-half/hertz-half.opts"
HS = [0.25, 0.1, 0.03, 0.01, 0.005]
KPS = [1e3, 1e6, 1e10]
PUSHES = [0.01, 0.15, 0.3]
FORMULATIONS = ["gpts", "mortar"]
RANKS = [1, 2]
RANK_TOL = 1e-8      # 1 and 2 ranks agree on P to this, relative
TIMEOUT = 1800       # seconds; the slowest run takes about 200
CUTBACKS = re.compile(r"the load cut back (\d+) time")


def key(r):
    return (r["h"], r["kp"], r["push"], r["formulation"], r["ranks"])


TAO_TYPE = "nls"     # --tao-type
OPTIONS = []         # --options: more of the program's options, on every run


def args_of(h, kp, push, form):
    return ["-options_file", SCENE, "-mesh_size", f"{h:g}", "-contact_penalty", f"{kp:g}",
            "-block_bc_push_values", f"{-push:g},0", "-contact_formulation", form, "-tao_monitor"] \
        + (["-tao_type", TAO_TYPE] if TAO_TYPE != "nls" else []) + OPTIONS


def log_name(r):
    return f"h{r['h']:g}-kp{power(r['kp'])}-push{r['push']:g}-{r['formulation']}-np{r['ranks']}.log"


def why(p):
    """The line a run that stopped printed: its last `contact:` line on
    stderr, else the last line it wrote."""
    lines = [ln.strip() for ln in p.stderr.splitlines() if ln.strip()]
    mine = [ln for ln in lines if ln.startswith("contact:")]
    if mine:
        return mine[-1]
    rest = lines or [ln.strip() for ln in p.stdout.splitlines() if ln.strip()]
    return rest[-1] if rest else f"exit status {p.returncode}, no output"


def one(h, kp, push, form, ranks, tmp, out, binary):
    args = args_of(h, kp, push, form)
    cmd = "bin/contact " + " ".join(args) + " -output none"
    cmd = (f"mpiexec --oversubscribe -n {ranks} " if ranks > 1 else "") + cmd
    p = run_case(args, tmp, "run", ranks=ranks, h5=False, binary=binary, timeout=TIMEOUT)
    if p.timed_out:
        return dict(h=h, kp=kp, push=push, formulation=form, ranks=ranks, command=cmd, status=None, wall=TIMEOUT,
                    warnings=[], converged=False, message=f"killed by the sweep after {TIMEOUT} s")
    s = p.summary
    r = dict(h=h, kp=kp, push=push, formulation=form, ranks=ranks, command=cmd, status=p.returncode, wall=p.wall,
             warnings=[ln.strip() for ln in p.stderr.splitlines() if ln.startswith("contact:")])
    tao = parse_tao_line(p.stdout)
    if tao:
        r.update(reason=tao["reason"], iterations=tao["iterations"], function_evaluations=tao["evals"])
    c = CUTBACKS.search(p.stdout)
    r["cutbacks"] = int(c.group(1)) if c else 0
    if s is not None:
        pair = s["contact"]["interface"]
        r.update(converged=bool(s["converged"]) and p.returncode == 0, reason=s["tao_reason"],
                 iterations=s["iterations"], function_evaluations=s["function_evaluations"], dofs=s["dofs"],
                 solve=s["time"]["solve"], total=s["time"]["total"], P=s["contact_force"],
                 pair_force=pair["force"][0], reaction=s["reactions"]["block:push"][0],
                 max_penetration=s["max_penetration"])
        r["balance"] = abs(abs(r["pair_force"]) - abs(r["reaction"])) / max(abs(r["reaction"]), 1e-300)
    else:
        r["converged"] = False
    if not r["converged"]:
        r["message"] = why(p)
        r["log"] = os.path.join("stopped", log_name(r))
        os.makedirs(os.path.join(out, "stopped"), exist_ok=True)
        with open(os.path.join(out, r["log"]), "w") as f:
            f.write(f"$ {cmd}\n(exit status {p.returncode})\n{p.stdout}{p.stderr}")
    return r


def rank_agreement(runs):
    """{(h, kp, push, formulation): |P(2 ranks) - P(1 rank)| / |P(1 rank)|}
    over the cases where both converged."""
    by = {key(r): r for r in runs}
    out = {}
    for (h, kp, push, form, n), r in by.items():
        q = by.get((h, kp, push, form, 2))
        if n == 1 and q and r["converged"] and q["converged"]:
            out[(h, kp, push, form)] = abs(q["P"] - r["P"]) / abs(r["P"])
    return out


def sweep(out, hs, kps, ranks, forms, resume, binary, redo=False):
    """The runs of hs x kps x PUSHES x forms x ranks not in <out>/results.json
    (all, unless resume; with redo, those there too, which they replace) with
    the program binary (None: bin/contact), copied once so that a rebuild
    during the sweep does not mix versions."""
    path = os.path.join(out, "results.json")
    res = dict(scene=SCENE, runs=[])
    if resume and os.path.exists(path):
        with open(path) as f:
            res = json.load(f)
    elif os.path.isdir(os.path.join(out, "stopped")):
        for name in os.listdir(os.path.join(out, "stopped")):
            os.remove(os.path.join(out, "stopped", name))
    chosen = [(h, kp, push, f, n) for h in hs for kp in kps for push in PUSHES for f in forms for n in ranks]
    replaced = [r for r in res["runs"] if redo and key(r) in chosen]
    res["runs"] = [r for r in res["runs"] if r not in replaced]
    for r in replaced:  # a replaced stopped run's kept output goes with it
        if r.get("log") and os.path.exists(os.path.join(out, r["log"])):
            os.remove(os.path.join(out, r["log"]))
    done = {key(r) for r in res["runs"]}
    res.setdefault("started", datetime.datetime.now().isoformat(timespec="seconds"))
    res.setdefault("tao_type", TAO_TYPE)
    res.setdefault("options", " ".join(OPTIONS))
    if (res["tao_type"], res["options"]) != (TAO_TYPE, " ".join(OPTIONS)):
        raise SystemExit(f"--resume: {path} holds runs of --tao-type {res['tao_type']} --options '{res['options']}', "
                         f"not of --tao-type {TAO_TYPE} --options '{' '.join(OPTIONS)}'")
    res.setdefault("load_start", load_average())
    res.setdefault("nice", os.nice(0))
    head = git("rev-parse", "--short", "HEAD") + (" (with changes to src/ or include/)"
                                                  if git("status", "--porcelain", "src", "include") else "")
    res.setdefault("commit", head)
    source = os.path.abspath(binary or os.path.join(ROOT, "bin", "contact"))
    # every invocation that adds runs: its command line, commit, program and start, for RESULTS.md's header
    invocation = dict(args=shlex.join(sys.argv[1:]), started=datetime.datetime.now().isoformat(timespec="seconds"),
                      commit=head, binary=f"{os.path.relpath(source, ROOT) if source.startswith(ROOT) else source}, "
                                          f"sha256 {program_sha(source)}", load_start=load_average(), runs=0)
    if replaced:
        invocation["replaced"] = len(replaced)
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        program = copy_program(tmp, source)
        for h, kp, push, form, n in chosen:
            if (h, kp, push, form, n) in done:
                continue
            r = one(h, kp, push, form, n, tmp, out, program)
            res["runs"].append(r)
            if not invocation["runs"]:
                res.setdefault("invocations", []).append(invocation)
            invocation["runs"] += 1
            print(f"h {h:g} k_p {kp:g} push {push:g} {form} {n} rank(s): " + (
                f"{r['reason']} in {r['iterations']} iterations, {r['solve']:.3g} s, P {r['P']:.8g}"
                if r["converged"] else f"STOPPED: {r['message']}"), flush=True)
            res["sweep_seconds"] = res.get("sweep_seconds", 0.0) + r["wall"]
            save(path, res)
    res["elapsed_seconds"] = res.get("elapsed_seconds", 0.0) + time.perf_counter() - t0
    res["load_end"] = invocation["load_end"] = load_average()
    order = {k: i for i, k in enumerate((h, kp, push, f, n) for h in HS for kp in KPS for push in PUSHES
                                        for f in FORMULATIONS for n in RANKS)}
    res["runs"].sort(key=lambda r: order.get(key(r), len(order)))
    res["rank_agreement"] = [dict(h=k[0], kp=k[1], push=k[2], formulation=k[3], rel=v)
                             for k, v in rank_agreement(res["runs"]).items()]
    save(path, res)
    return res


def save(path, res):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(res, f, indent=1)
    os.replace(tmp, path)


def verdict(runs):
    """yes, no: <the formulations that stopped>, or - where nothing ran."""
    bad = [r for r in runs if not r["converged"]]
    if not runs:
        return "-"
    return "yes" if not bad else "no: " + ", ".join(r["formulation"] for r in bad)


def iteration_spread(runs):
    """The largest relative difference of the iteration counts between 1
    and 2 ranks over the formulations converged on both, marked * where
    the two took a different number of load cutbacks; - where none."""
    get = {(r["formulation"], r["ranks"]): r for r in runs if r["converged"]}
    d = [(abs(get[(f, 2)]["iterations"] - get[(f, 1)]["iterations"]) / get[(f, 1)]["iterations"],
          get[(f, 2)].get("cutbacks", 0) != get[(f, 1)].get("cutbacks", 0))
         for f in FORMULATIONS if (f, 1) in get and (f, 2) in get]
    if not d:
        return "-"
    v, cut = max(d)
    return f"{100 * v:.0f} %" + (" *" if cut else "")


def largest(xs, fmt):
    return format(max(xs), fmt) if xs else "-"


def row_of(h, kp, push, runs, agree, dofs):
    """One line of the compact table: the four runs of a case (dofs: that of
    the mesh, from any run at h that wrote it)."""
    get = {(r["formulation"], r["ranks"]): r for r in runs}
    its = " / ".join(str(get[(f, 1)].get("iterations", "-")) if (f, 1) in get else "-" for f in FORMULATIONS)
    dofs = format(dofs, ",") if dofs else "-"
    m = get.get(("mortar", 1))
    P = f"{m['P']:.6g}" if m and m["converged"] else "-"
    d = [agree[(h, kp, push, f)] for f in FORMULATIONS if (h, kp, push, f) in agree]
    solve = [r["solve"] for r in runs if "solve" in r]
    conv = [verdict([r for r in runs if r["ranks"] == n]) for n in RANKS]
    return (f"| {h:g} | {dofs} | {power(kp)} | {push:g} | {its} | {conv[0]} | {conv[1]} | {P} | {largest(d, '.1e')} "
            f"| {iteration_spread(runs)} | {largest(solve, '.3g')} |")


def stopped_cases(failed):
    """The stopped runs, a case's rank counts together, and the line each
    printed (once, where all printed the same)."""
    cases = {}
    for r in failed:
        cases.setdefault((r["h"], r["kp"], r["push"], r["formulation"]), []).append(r)
    lines = sorted({r["message"] for r in failed})
    text = []
    for (h, kp, push, form), rs in cases.items():
        reasons = sorted({r.get("reason", "?") for r in rs})
        its = " / ".join(str(r.get("iterations", "?")) for r in rs)
        ranks = " / ".join(str(r["ranks"]) for r in rs)
        text.append(f"h = {h:g}, k_p = {power(kp)}, push = {push:g}, {form}: {', '.join(reasons)} after {its} "
                    f"iterations on {ranks} rank{'s' if len(rs) > 1 or rs[0]['ranks'] > 1 else ''}"
                    + (f" (`{rs[0]['message']}`)" if len(lines) > 1 else ""))
    return "; ".join(text) + (f"; each printed `{lines[0]}`" if len(lines) == 1 else "")


def tables(res):
    """The compact table (one row per h x k_p x push) and the summary lines;
    rendered into bench/README.md by scripts/readme_figures.py."""
    runs = res["runs"]
    agree = {(a["h"], a["kp"], a["push"], a["formulation"]): a["rel"] for a in res["rank_agreement"]}
    ok = sum(r["converged"] for r in runs)
    dofs = {r["h"]: r["dofs"] for r in runs if "dofs" in r}
    tao = res.get("tao_type", "nls")
    solver = "Newton" if tao == "nls" else f"TAO {tao}"
    opts = f" and `{res['options']}`" if res.get("options") else ""
    out = [f"Scene `{res['scene']}` (the reference scene's mirrored half; P is the whole model's), {solver} with "
           f"the defaults{opts}, `-tao_monitor -output none`, one run at a time (niceness {res['nice']}) on a shared "
           "2-core machine: "
           f"{ok} of {len(runs)} runs converged. Iterations: {solver} iterations at 1 rank (gpts / mortar); "
           "converged: every run of the row at that rank count (both formulations); |dP|/P: the largest relative "
           f"difference of P between 1 and 2 ranks over the two formulations (target {RANK_TOL:g}); iterations 1 vs 2: "
           "the largest relative difference of their iteration counts (* where the two rank counts cut the load "
           "back a different number of times); solve: the largest solve time of the row's four runs; - where "
           "nothing ran.", "",
           "| h | dofs | k_p | push | iterations gpts / mortar | converged 1 rank | converged 2 ranks | P (mortar) "
           "| 1 vs 2 ranks \\|dP\\|/P | iterations 1 vs 2 | max solve [s] |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for h in HS:
        for kp in KPS:
            for push in PUSHES:
                case = [r for r in runs if (r["h"], r["kp"], r["push"]) == (h, kp, push)]
                if case:
                    out.append(row_of(h, kp, push, case, agree, dofs.get(h)))
    failed = [r for r in runs if not r["converged"]]
    off = sorted((v, k) for k, v in agree.items() if v > RANK_TOL)
    ranks = (f"1 against 2 ranks: the largest relative difference of P is {largest(list(agree.values()), '.1e')} "
             f"over {len(agree)} pairs")
    if not agree:
        ranks = "1 against 2 ranks: no case ran converged on both"
    elif off:
        ranks += f"; above {RANK_TOL:g}: " + ", ".join(
            f"h = {k[0]:g}, k_p = {power(k[1])}, push = {k[2]:g}, {k[3]} ({v:.1e})" for v, k in off)
    else:
        ranks += f", all within {RANK_TOL:g}"
    balance = largest([r["balance"] for r in runs if "balance" in r], ".1e")
    stopped = f"Runs that stopped: {len(failed)}" + ("." if not failed else ": " + stopped_cases(failed) + ".")
    cut = [r for r in runs if r["converged"] and r.get("cutbacks", 0) > 0]
    if cut:
        stopped += (f" Runs that converged after the automatic load cutback: {len(cut)} ("
                    + ", ".join(f"h = {r['h']:g}, k_p = {power(r['kp'])}, push = {r['push']:g}, {r['formulation']}, "
                                f"{r['ranks']} rank{'s' if r['ranks'] > 1 else ''}: {r['cutbacks']}" for r in cut) + ").")
    out += ["", f"{ranks}. The largest relative difference between the pair's force and the pushed edge's "
            f"reaction: {balance}. {stopped} The sweep's runs took {res.get('sweep_seconds', 0) / 60:.0f} minutes."]
    return "\n".join(out) + "\n"


def provenance(res):
    """RESULTS.md's header: the runs' history as written before invocations
    were recorded (or the sweep's first start), then each invocation that
    added runs: its command line, commit, start, runs and load averages."""
    out = [f"Written by `python3 scripts/stress_sweep.py`, TAO type {res.get('tao_type', 'nls')} (`make stress` "
           "runs the sweep with nls, the program's default)."]
    calls = res.get("invocations", [])
    if res.get("history"):
        out.append(res["history"])
    elif not calls:
        out.append(f"Started {res['started']} at commit {res['commit']}; load average {res['load_start']:.2f} at "
                   f"the start, {res['load_end']:.2f} at the end.")
    elif sum(c["runs"] for c in calls) < len(res["runs"]):  # runs from before invocations were recorded
        out.append(f"Started {res['started']} at commit {res['commit']} (load average {res['load_start']:.2f}).")
    text = " ".join(out)
    if calls:
        text += " Runs added by:\n\n" + "\n".join(
            f"- `python3 scripts/stress_sweep.py {c['args']}`: {c['runs']} runs"
            + (f" (replacing {c['replaced']} earlier runs)" if c.get("replaced") else "") + f", started {c['started']} at commit "
            f"{c['commit']}" + (f" (program {c['binary']})" if "binary" in c else "") + (f"; load average {c['load_start']:.2f} at the start, {c['load_end']:.2f} at the end"
                                if "load_end" in c else "") for c in calls)
    return text


def solver_rows(label, res, newton):
    """Per k_p, one line of the comparison of a sweep (res) with Newton's
    (newton, the same cases at the defaults): runs converged, the stopped
    ones and whether Newton stops there too, 1 against 2 ranks (largest
    |dP|/P, pairs above RANK_TOL, pairs whose iteration counts differ by
    more than 10 %), and the summed solve time over Newton's on the cases
    both converged."""
    by = {key(r): r for r in res["runs"]}
    nby = {key(r): r for r in newton["runs"]} if newton else {}
    agree = rank_agreement(res["runs"])
    out = []
    for kp in KPS:
        runs = [r for r in res["runs"] if r["kp"] == kp]
        if not runs:
            continue
        stopped = [r for r in runs if not r["converged"]]
        also = sum(1 for r in stopped if key(r) in nby and not nby[key(r)]["converged"])
        d = [v for k, v in agree.items() if k[1] == kp]
        its = [k for k in agree if k[1] == kp
               and abs(by[k + (2,)]["iterations"] - by[k + (1,)]["iterations"]) > 0.1 * by[k + (1,)]["iterations"]]
        both = [r for r in runs if r["converged"] and nby.get(key(r), {}).get("converged")]
        t = sum(r["solve"] for r in both) / sum(nby[key(r)]["solve"] for r in both) if both and newton else None
        hs = sorted({r["h"] for r in runs}, reverse=True)
        out.append(f"| {label} | {power(kp)} | {hs[0]:g} to {hs[-1]:g} | {len(runs) - len(stopped)} of {len(runs)} "
                   f"| {len(stopped)}" + (f" ({also} where Newton stops)" if stopped and newton else "")
                   + f" | {largest(d, '.1e')} | {sum(v > RANK_TOL for v in d)} of {len(d)} | {len(its)} of {len(d)} "
                   f"| {'-' if t is None else format(t, '.2f')} |")
    return out


def solver_table(sweeps, newton):
    """The comparison table of several sweeps [(label, res) or (label, res,
    False)] with Newton's; False: a sweep of another build than Newton's,
    whose times and stops are not compared."""
    return "\n".join(["| sweep | k_p | h | converged | stopped | 1 vs 2 ranks \\|dP\\|/P | pairs above "
                      f"{power(RANK_TOL)} | pairs with iterations > 10 % apart | summed solve / Newton's |",
                      "|---|---|---|---|---|---|---|---|---|"]
                     + [line for label, res, *same in sweeps
                        for line in solver_rows(label, res, None if res is newton or same == [False] else newton)]) + "\n"


def every_run(res):
    out = ["| h | k_p | push | formulation | ranks | dofs | converged | TAO reason | iterations | energy evaluations "
           "| solve [s] | wall [s] | P | largest penetration | force vs reaction | stopped with |", "|" + "---|" * 16]
    for r in res["runs"]:
        g = lambda k, f: format(r[k], f) if k in r else "-"  # noqa: E731
        out.append(f"| {r['h']:g} | {power(r['kp'])} | {r['push']:g} | {r['formulation']} | {r['ranks']} "
                   f"| {g('dofs', ',')} | {'yes' if r['converged'] else 'no'} | {r.get('reason', '-')} "
                   f"| {g('iterations', 'd')} | {g('function_evaluations', 'd')} | {g('solve', '.3g')} "
                   f"| {r['wall']:.3g} | {g('P', '.10g')} | {g('max_penetration', '.3g')} | {g('balance', '.1e')} "
                   f"| {r.get('message', '')} |")
    stopped = [r for r in res["runs"] if "log" in r]
    if stopped:
        out += ["", "Each stopped run's output (its -tao_monitor lines and the report of the last iterate): "
                + ", ".join(f"[{r['log']}]({r['log']})" for r in stopped) + "."]
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "stress"))
    ap.add_argument("--resume", action="store_true", help="keep the runs already in <out>/results.json")
    ap.add_argument("--redo", action="store_true", help="with --resume: run the chosen cases again, replacing their runs "
                    "in <out>/results.json (a new build's figures for part of a sweep)")
    ap.add_argument("--h", type=float, nargs="+", default=HS, help="a subset of the mesh sizes")
    ap.add_argument("--kp", type=float, nargs="+", default=KPS, help="a subset of the penalties")
    ap.add_argument("--ranks", type=int, nargs="+", default=RANKS, choices=RANKS)
    ap.add_argument("--formulation", nargs="+", default=FORMULATIONS, choices=FORMULATIONS)
    ap.add_argument("--tao-type", default="nls", help="the TAO type of every run (default nls, the program's)")
    ap.add_argument("--options", default="", help="more of the program's options for every run, one string "
                    "(e.g. '-tao_gttol 1e-11'); a sweep resumed must name the same")
    ap.add_argument("--bin", default=None, help="the program (default bin/contact), copied once at the start")
    ap.add_argument("--report-only", action="store_true", help="rewrite RESULTS.md from <out>/results.json")
    args = ap.parse_args()
    global TAO_TYPE, OPTIONS
    TAO_TYPE = args.tao_type
    OPTIONS = args.options.split()
    if args.redo and not args.resume:
        raise SystemExit("--redo: only with --resume (without it every run is new)")
    bad = [h for h in args.h if h not in HS]
    if bad:
        raise SystemExit(f"--h: {bad} not among the sweep's sizes {HS}")
    bad = [kp for kp in args.kp if kp not in KPS]
    if bad:
        raise SystemExit(f"--kp: {bad} not among the sweep's penalties {KPS}")
    os.makedirs(args.out, exist_ok=True)
    if args.report_only:
        if not os.path.exists(os.path.join(args.out, "results.json")):
            raise SystemExit(f"--report-only: {os.path.join(args.out, 'results.json')} does not exist")
        with open(os.path.join(args.out, "results.json")) as f:
            res = json.load(f)
    else:
        res = sweep(args.out, args.h, args.kp, args.ranks, args.formulation, args.resume, args.bin, args.redo)
    text = tables(res)
    with open(os.path.join(args.out, "RESULTS.md"), "w") as f:
        f.write("# Robustness sweep\n\n" + provenance(res) + "\n\n" + text + "\nEvery run:\n\n" + every_run(res))
    print(text)
    # a run may stop, with its one line naming the cause; one that stopped otherwise is a failure
    silent = [r for r in res["runs"] if not r["converged"] and not r.get("message", "").startswith("contact:")]
    if silent:
        sys.exit(f"{len(silent)} run(s) stopped without the program's one line, e.g. {silent[0]['command']}: "
                 f"{silent[0].get('message')}")


if __name__ == "__main__":
    main()
