#!/usr/bin/env python3
"""The documentation's tables of measured figures and the README's phrases
quoting them, generated from committed results, and the README's picture.

    python3 scripts/readme_figures.py --check      # exit 1 if a table or phrase differs from its results
    python3 scripts/readme_figures.py --update     # rewrite the tables and phrases from the results
    python3 scripts/readme_figures.py --measure scenes --measure solver --measure lmvm [--update]
                                                   # run a table's cases first
    python3 scripts/readme_figures.py --measure axisymmetric [--update]
    python3 scripts/readme_figures.py --measure picture
                                                   # redraw docs/img/hertz-pressure.png

The pages are README.md, every docs/*.md and bench/README.md. Each table sits
between the markers <!-- figures:NAME:begin --> and <!-- figures:NAME:end -->
on one of them (any one, exactly once over all of them: a table's markers
move with its section) and is rendered by a function of this script from a
committed result file; a test (tests/test_readme_figures.py) runs --check, so
that a table can neither be typed by hand nor go stale. A table whose markers
are missing, doubled or unclosed is an error naming the page. The tables:

- scenes: bench/scenes/results.json (written by --measure scenes: each scene
  with each formulation, Newton with a direct factorisation, a few seconds);
- formulations: bench/formulations/results.json (scripts/formulation_study.py);
- speed: bench/full/results.csv (scripts/bench.py --out bench/full);
- parallel: bench/parallel/results.csv (scripts/bench_parallel.py: 1 against
  2 ranks, the same table as its RESULTS.md); parallel-stages: the same runs'
  median -log_view stages from h = 0.015 down;
- accuracy: bench/accuracy/results.json (scripts/accuracy_study.py);
- oscillation: bench/formulations/oscillation_floor.json (scripts/oscillation_floor.py);
- stress: bench/stress/results.json (scripts/stress_sweep.py, run by make stress);
- penalty: bench/penalty/results.json (scripts/penalty_study.py: the automatic
  penalty's error against the mesh's);
- axisymmetric: bench/axisymmetric/results.json (written by --measure
  axisymmetric: the sphere and ssnv104 scenes at their defaults and the
  sphere under -accuracy 0.01, median of 3 whole-run times; half a minute);
- solver: bench/solver/results.json (written by --measure solver: the solver
  strategies on the reference scene at h = 0.06 with the default formulation
  (mortar), and Newton with gpts, interleaved, median of 3 solve times; about
  2 minutes);
- lmvm: bench/lmvm/results.json (written by --measure lmvm: L-BFGS, lmvm and
  blmvm at their defaults, against Newton on the reference scene for several h,
  k_p and rank counts, interleaved, median of 3 solve times; about 5 minutes).

A phrase is figures inside a sentence: its begin marker stands inside a line
(at a line's start Markdown would take the line for HTML), the phrase follows
it, and the end marker closes it within the paragraph, as in
`it takes <!-- figures:solver-speed:begin -->10 iterations<!-- figures:solver-speed:end -->.`
A phrase is compared word by word, so the page may wrap and indent it as it
likes; --update writes a stale one on one line. The phrases, all in README.md:

- solver-speed: Newton's and L-BFGS's (-tao_type lmvm) iterations and solve
  times at h = 0.06, from the solver table (bench/solver/results.json);
- lmvm-ratio: the least and greatest L-BFGS solve time over Newton's in the
  lmvm table (bench/lmvm/results.json), up to its largest k_p;
- parallel-speedup: the parallel table's solve-time speed-ups, its largest
  mesh's dofs, and the whole run's speed-up where bench_parallel.py sets it a
  target (bench/parallel/results.csv);
- speed-targets: "all met", or the targets not met, of scripts/bench.py's
  targets table of the full sweep (bench/full/results.csv, through bench.py's
  own functions), then the reference scene's solve time at h = 0.06, the worst
  time in linear solves of the same mesh and the solve time's exponent in dofs,
  each with its target.

The picture: --measure picture runs the reference scene as `make run` does
(meshes/hertz/hertz.opts, the program's defaults), its HDF5 output in a
temporary directory, and draws its pressure plot with scripts/plot_hertz.py
into docs/img/hertz-pressure.png, the PNG the README shows (a few seconds).
"""
import argparse
import json
import os
import re
import sys
import tempfile
import types

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PICTURE = os.path.join("docs", "img", "hertz-pressure.png")
sys.path.insert(0, os.path.join(ROOT, "scripts"))

SCENES = [("hertz", "meshes/hertz/hertz.opts", ["-mesh_size", "0.1"], "hertz, h = 0.1"),
          ("hertz", "meshes/hertz/hertz.opts", ["-mesh_size", "0.06"], "hertz, h = 0.06"),
          ("hertz-small", "meshes/hertz-small/hertz-small.opts", [], "hertz-small"),
          ("twodiscs", "meshes/twodiscs/twodiscs.opts", [], "twodiscs")]
SOLVER = ["-tao_type", "nls", "-tao_nls_ksp_type", "preonly", "-tao_nls_pc_type", "cholesky"]


def save(name, rows):
    os.makedirs(os.path.join(ROOT, "bench", name), exist_ok=True)
    with open(os.path.join(ROOT, "bench", name, "results.json"), "w") as f:
        json.dump(rows, f, indent=1)


def load(name):
    with open(os.path.join(ROOT, "bench", name, "results.json")) as f:
        return json.load(f)


def measure_scenes():
    from contactrun import run_checked
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for form in ("mortar", "gpts"):   # the default first
            for scene, opts, extra, label in SCENES:
                args = ["-options_file", opts] + extra + SOLVER + ["-contact_formulation", form]
                s = run_checked(args, tmp, "s").summary
                rows.append(dict(scene=label, formulation=form, command="bin/contact " + " ".join(args), dofs=s["dofs"],
                                 P=s["contact_force"], fem_a=s["fem_a"], hertz_a=s["hertz_a"], fem_pmax=s["fem_pmax"],
                                 hertz_pmax=s["hertz_pmax"], l2=s["pressure_l2_error"]))
    save("scenes", rows)


def measure_picture():
    """The pressure plot of `make run`'s scene, drawn into PICTURE."""
    import subprocess
    from contactrun import run_checked
    with tempfile.TemporaryDirectory() as tmp:
        h5 = run_checked(["-options_file", "meshes/hertz/hertz.opts"], tmp, "hertz").h5
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "plot_hertz.py"), h5, "-o",
                        os.path.join(ROOT, PICTURE)], cwd=ROOT, check=True)


def render_scenes():
    rows = load("scenes")
    out = ["| scene | formulation | dofs | P | a: FE / Hertz | p_max: FE / Hertz | profile L2 vs Hertz |",
           "|---|---|---|---|---|---|---|"]
    for r in rows:
        da, dp = 100 * (r["fem_a"] / r["hertz_a"] - 1), 100 * (r["fem_pmax"] / r["hertz_pmax"] - 1)
        out.append(f"| {r['scene']} | {r['formulation']} | {r['dofs']:,} | {r['P']:.4g} | {r['fem_a']:.4g} / "
                   f"{r['hertz_a']:.4g} ({da:+.1f} %) | {r['fem_pmax']:.4g} / {r['hertz_pmax']:.4g} ({dp:+.1f} %) "
                   f"| {100 * r['l2']:.1f} % |")
    return "\n".join(out) + "\n"


STRATEGIES = [("Newton, Schur step (default)", []),
              ("Newton, full factorisation per step", ["-newton_schur", "0"]),
              ("Newton, Gauss-Newton contact Hessian throughout", ["-contact_hessian", "gauss_newton"]),
              ("Newton, exact contact Hessian from rest", ["-contact_hessian", "exact"]),
              ("the same + continuation", ["-contact_hessian", "exact", "-penalty_stages", "3"]),
              ("Newton + penalty continuation", ["-penalty_stages", "3"]),
              ("Newton + load stepping", ["-load_steps", "3"]),
              ("Newton, trust region", ["-tao_type", "ntr"]),
              ("L-BFGS, H0 the stiffness + contact Hessian, one pair, continuation (default)", ["-tao_type", "lmvm"]),
              ("the same, bound-constrained type", ["-tao_type", "blmvm"]),
              ("L-BFGS without continuation", ["-tao_type", "lmvm", "-penalty_stages", "1"]),
              ("L-BFGS keeping every pair", ["-tao_type", "lmvm", "-lmvm_pair_ratio", "1e300"]),
              ("L-BFGS, elastic H0", ["-tao_type", "lmvm", "-lmvm_h0", "elastic"]),
              ("plain L-BFGS (the original study's method)", ["-tao_type", "lmvm", "-lmvm_h0", "none"]),
              ("Newton, gpts formulation", ["-contact_formulation", "gpts"])]


def measure_solver(repeat=3):
    """The strategies at h = 0.06, interleaved, median of repeat solve times."""
    from contactrun import median, run_checked
    times = {name: [] for name, _ in STRATEGIES}
    its = {}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(repeat):
            for name, opts in STRATEGIES:
                summ = run_checked(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.06"] + opts, tmp,
                                   "s").summary
                times[name].append(summ["time"]["solve"])
                its[name] = summ["iterations"]
    save("solver", [dict(strategy=name, options=" ".join(opts), iterations=its[name],
                         solve=median(times[name]), runs=times[name]) for name, opts in STRATEGIES])


# (h, k_p, ranks) of the L-BFGS table; k_p None: the scene's 2e6
LMVM_CASES = [(0.06, None, 1), (0.03, None, 1), (0.015, None, 1), (0.015, None, 2), (0.03, 2e7, 1), (0.03, 1e8, 1)]
LMVM_TYPES = ["nls", "lmvm", "blmvm"]


def measure_lmvm(repeat=3):
    """Newton, lmvm and blmvm on LMVM_CASES, the three interleaved within
    each case, median of repeat solve times (meshes made first)."""
    from contactrun import median, mesh_only, run_case
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for h, kp, ranks in LMVM_CASES:
            args = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", str(h)] + \
                (["-contact_penalty", f"{kp:g}"] if kp else [])
            mesh_only(args)
            runs = {t: [] for t in LMVM_TYPES}
            for _ in range(repeat):
                for t in LMVM_TYPES:
                    r = run_case(args + ["-tao_type", t], tmp, "s", ranks=ranks, h5=False)
                    if r.returncode != 0:
                        raise SystemExit(f"{' '.join(r.cmd)} failed:\n{r.stdout[-2000:]}{r.stderr[-2000:]}")
                    runs[t].append(r.summary)
            for t in LMVM_TYPES:
                s = runs[t][-1]
                rows.append(dict(h=h, kp=kp or 2e6, ranks=ranks, tao=t, dofs=s["dofs"], iterations=s["iterations"],
                                 evaluations=s["function_evaluations"], stages=s["stages"],
                                 h0=s.get("h0_refreshes", 0), dropped=s.get("lmvm_pairs_dropped", 0),
                                 restarts=s.get("lmvm_restarts", 0), P=s["contact_force"],
                                 solve=median([x["time"]["solve"] for x in runs[t]]),
                                 runs=[x["time"]["solve"] for x in runs[t]],
                                 command="bin/contact " + " ".join(args + ["-tao_type", t])))
    save("lmvm", rows)


def lmvm_pairs():
    """[(row, Newton's row of the same case)] of bench/lmvm/results.json, in its order."""
    rows = load("lmvm")
    newton = {(r["h"], r["kp"], r["ranks"]): r for r in rows if r["tao"] == "nls"}
    return [(r, newton[(r["h"], r["kp"], r["ranks"])]) for r in rows]


def kp_text(kp):
    """A penalty as the pages write it: 2e6, 1e8."""
    return f"{kp:.0e}".replace("e+0", "e")


def render_lmvm():
    out = ["| h | dofs | k_p | ranks | solver | iterations | energy evaluations | H0 set-ups | pairs dropped "
           "| solve [s] | / Newton | P from Newton's |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r, n in lmvm_pairs():
        lm = r["tao"] != "nls"
        dP = f"{abs(r['P'] / n['P'] - 1):.1e}" if lm else ""
        out.append(f"| {r['h']:g} | {r['dofs']:,} | {kp_text(r['kp'])} | {r['ranks']} | {r['tao']} | {r['iterations']} "
                   f"| {r['evaluations']} | {r['h0'] if lm else ''} | {r['dropped'] if lm else ''} "
                   f"| {r['solve']:.2f} | {r['solve'] / n['solve']:.2f} | {dP} |")
    return "\n".join(out) + "\n"


def render_solver():
    rows = load("solver")
    out = ["| strategy | options | iterations | solve [s] |", "|---|---|---|---|"]
    for r in rows:
        opts = f"`{r['options']}`" if r["options"] else ""
        out.append(f"| {r['strategy']} | {opts} | {r['iterations']:,} | {r['solve']:.2f} |")
    return "\n".join(out) + "\n"


def render_speed():
    """The reference scene's scaling rows of the full sweep: mortar (the
    default) and gpts, newton, k_p = 2e6, gttol 1e-8, one rank; the linear
    solve, ratio, fixed costs and memory are mortar's."""
    import csv
    with open(os.path.join(ROOT, "bench", "full", "results.csv")) as f:
        rows = list(csv.DictReader(f))
    pick = {}
    for r in rows:
        if (r["scene"] == "hertz" and r["strategy"] == "newton" and float(r["kp"]) == 2e6 and r["gttol"] == "1e-08"
                and r["ranks"] == "1" and r["solve_median"] and float(r["h"]) <= 0.06):
            pick.setdefault(float(r["h"]), {})[r.get("formulation") or "gpts"] = r
    out = ["| h | dofs | iterations mortar / gpts | solve mortar / gpts [s] | one linear solve [s] | ratio "
           "| mesh + set-up + output | peak memory |", "|---|---|---|---|---|---|---|---|"]
    for h in sorted(pick, reverse=True):
        g, m = pick[h].get("gpts"), pick[h].get("mortar")
        if not g or not m:
            continue
        sv = lambda x: f"{float(x):.3g}"  # noqa: E731
        frac = (float(m["time_mesh"]) + float(m["time_setup"]) + float(m["time_output"])) / float(m["time_total"])
        mb = float(m["peak_mb"])
        mem = f"{mb / 1024:.1f} GB" if mb >= 1024 else f"{mb:.0f} MB"
        out.append(f"| {h:g} | {int(m['dofs']):,} | {m['iterations']} / {g['iterations']} | {sv(m['solve_median'])} / "
                   f"{sv(g['solve_median'])} | {sv(m['linear_solve_time'])} | {float(m['ratio_to_linear']):.1f} "
                   f"| {100 * frac:.0f} % | {mem} |")
    return "\n".join(out) + "\n"


def render_stress_solvers():
    import stress_sweep
    newton = load("stress")
    return stress_sweep.solver_table([("Newton", newton), ("lmvm", load("stress-lmvm")),
                                      ("blmvm", load("stress-blmvm")),
                                      ("lmvm, -tao_gttol 1e-11", load("stress-lmvm-gttol11"))], newton)


def parallel_rows():
    """bench/parallel/results.csv's rows (scripts/bench_parallel.py)."""
    import bench_parallel
    return bench_parallel.load_rows(os.path.join(ROOT, "bench", "parallel", "results.csv"))


def render_parallel():
    import bench_parallel
    rows = parallel_rows()
    forms = sorted({r["formulation"] for r in rows if r.get("formulation")}) or ["gpts"]
    return ("Contact formulation: %s.\n\n" % ", ".join(forms)
            + "\n".join(bench_parallel.speedup_table(bench_parallel.rank_pairs(rows))) + "\n")


def render_parallel_stages():
    import bench_parallel
    pairs = [p for p in bench_parallel.rank_pairs(parallel_rows()) if p[0] <= 0.015]
    head, rule = "| stage |", "|---|"
    for h, _, _ in pairs:
        head += f" h = {h:g}, 1 rank [s] | 2 ranks [s] | speed-up |"
        rule += "---|---|---|"
    out = [head, rule]
    for st in bench_parallel.STAGES:
        line = f"| {st} |"
        for _, one, two in pairs:
            a, b = bench_parallel.med(one, "stage_" + st), bench_parallel.med(two, "stage_" + st)
            line += f" {a:.3g} | {b:.3g} | {a / b:.2f} |"
        out.append(line)
    return "\n".join(out) + "\n"


def render_accuracy():
    import accuracy_study
    return accuracy_study.tables(load("accuracy"))


def render_oscillation():
    import oscillation_floor
    with open(os.path.join(ROOT, "bench", "formulations", "oscillation_floor.json")) as f:
        return oscillation_floor.tables(json.load(f))


def render_formulations():
    import formulation_study
    return formulation_study.tables(load("formulations"))


def render_stress():
    import stress_sweep
    return stress_sweep.tables(load("stress"))


def render_penalty():
    import penalty_study
    return penalty_study.table(load("penalty"))


AXISYMMETRIC = [("sphere", ["-options_file", "meshes/sphere/sphere.opts"]),
                ("sphere, -accuracy 0.01", ["-options_file", "meshes/sphere/sphere.opts", "-accuracy", "0.01"]),
                ("ssnv104", ["-options_file", "meshes/ssnv104/ssnv104.opts"])]
SSNV104_REF = {"a": 10.0, "p0": 2798.3}   # code_aster V6.04.104: Hertz from the approach 4


def measure_axisymmetric(repeat=3):
    """The axisymmetric scenes at their defaults (meshes generated first, not
    timed), and the sphere under -accuracy 0.01: median of 3 whole-run times
    (the JSON's time.total), the figures against Hertz."""
    from contactrun import median, mesh_only, run_checked
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for label, args in AXISYMMETRIC:
            mesh_only(args[:2])
            runs = [run_checked(args, tmp, "s").summary for _ in range(repeat)]
            s = runs[-1]
            rows.append(dict(scene=label, command="bin/contact " + " ".join(args), dofs=s["dofs"],
                             steps=len(s.get("adapt_steps", [])) or 1, iterations=s["iterations"],
                             time=median([r["time"]["total"] for r in runs]), P=s["contact_force"],
                             fem_pmax=s["fem_pmax"], hertz_pmax=s["hertz_pmax"], fem_a=s["fem_a_moment"],
                             hertz_a=s["hertz_a"], l2=s["pressure_l2_error"]))
    save("axisymmetric", rows)


def render_axisymmetric():
    rows = load("axisymmetric")
    out = ["| scene | dofs (last step) | time | P | p_max: FE / Hertz | a (second moment): FE / Hertz | profile L2 |",
           "|---|---|---|---|---|---|---|"]
    for r in rows:
        dp, da = 100 * (r["fem_pmax"] / r["hertz_pmax"] - 1), 100 * (r["fem_a"] / r["hertz_a"] - 1)
        steps = f", {r['steps']} steps" if r["steps"] > 1 else ""
        out.append(f"| {r['scene']} | {r['dofs']:,}{steps} | {r['time']:.2f} s | {r['P']:.5g} | {r['fem_pmax']:.5g} / "
                   f"{r['hertz_pmax']:.5g} ({dp:+.2f} %) | {r['fem_a']:.4g} / {r['hertz_a']:.4g} ({da:+.2f} %) "
                   f"| {100 * r['l2']:.2f} % |")
    ss = [r for r in rows if r["scene"] == "ssnv104"][0]
    out.append("")
    out.append(f"SSNV104 against code_aster's reference, Hertz from the approach (a = {SSNV104_REF['a']:g}, "
               f"p0 = {SSNV104_REF['p0']:g}): a {ss['fem_a']:.4g} ({100 * (ss['fem_a'] / SSNV104_REF['a'] - 1):+.1f} %), "
               f"p_max {ss['fem_pmax']:.5g} ({100 * (ss['fem_pmax'] / SSNV104_REF['p0'] - 1):+.1f} %).")
    return "\n".join(out) + "\n"


def and_list(items):
    """'a', 'a and b', 'a, b and c'."""
    return ", ".join(items[:-1]) + " and " + items[-1] if len(items) > 1 else "".join(items)


def render_solver_speed():
    """Newton's (the default) and L-BFGS's (-tao_type lmvm, its default H0) iterations and solve times in the
    solver table."""
    rows = {r["options"]: r for r in load("solver")}
    n, lb = rows[""], rows["-tao_type lmvm"]
    return (f"{n['iterations']} iterations and {n['solve']:.2f} s, where L-BFGS (`-tao_type lmvm`, its H0 the "
            f"stiffness plus the contact's Hessian) takes {lb['iterations']} and {lb['solve']:.2f} s")


def render_lmvm_ratio():
    """The least and the greatest of the lmvm table's L-BFGS solve times over Newton's, and its largest k_p."""
    pairs = [(r, n) for r, n in lmvm_pairs() if r["tao"] != "nls"]
    ratios = [r["solve"] / n["solve"] for r, n in pairs]
    return (f"{min(ratios):.2f} to {max(ratios):.2f} times Newton's time up to "
            f"k_p = {kp_text(max(r['kp'] for r, _ in pairs))}")


def render_parallel_speedup():
    """The parallel table's solve-time speed-ups and their h, the largest mesh's dofs, and the whole run's
    speed-up where it has a target (bench_parallel.WALL_TARGETS)."""
    import bench_parallel
    pairs = bench_parallel.rank_pairs(parallel_rows())

    def speedup(one, two, key):
        return f"{bench_parallel.med(one, key) / bench_parallel.med(two, key):.2f}"
    solve = and_list([speedup(one, two, "time_solve") for _, one, two in pairs])
    sizes = and_list([f"{h:g}" for h, _, _ in pairs])
    text = (f"2 ranks solve the reference scene {solve} times faster than one at h = {sizes} "
            f"({pairs[-1][1][0]['dofs']:,} dofs)")
    for h, one, two in pairs:
        if h in bench_parallel.WALL_TARGETS:
            text += f", the whole run {speedup(one, two, 'wall')} times at h = {h:g}"
    return text


def target_name(target):
    """A target of bench.py's table without its parentheses."""
    return re.sub(r" \([^()]*\)", "", target)


def render_speed_targets():
    """Whether the full sweep meets its targets, as scripts/bench.py's table of them says (those not met
    named), and the three of speed: the reference scene's solve time at h = 0.06, the worst time in
    linear solves of the same mesh and the exponent of the solve time in dofs."""
    import bench
    out = os.path.join(ROOT, "bench", "full")
    rows = bench.read_csv(os.path.join(out, "results.csv"))
    ctx = bench.report_figures(rows, types.SimpleNamespace(out=out), None, None, None, None)
    missed = [f"{target_name(t)} ({st})" for t, _, st in bench.target_rows(rows, ctx) if not bench.met(st)]
    d06 = [r for r in bench.reference_solve_runs(rows)[0] if r["converged"]]
    ratios = bench.linear_ratio_runs(ctx.ref_sel)[1]
    return ("all met" if not missed else "met but for " + "; ".join(missed)) + ": " + ", ".join([
        (f"the reference scene at h = 0.06 solved in {d06[0]['solve_median']:.3g} s" if d06
         else "the reference scene at h = 0.06 not solved by the default strategy")
        + f" (target {bench.REF_SOLVE_TARGET:g} s)",
        (f"at most {max(r['ratio_to_linear'] for r in ratios):.1f} linear solves of the same mesh up to "
         f"{max(r['dofs'] for r in ratios):,} dofs" if ratios else "no time in linear solves from 1e4 dofs")
        + f" (target {bench.LINEAR_RATIO_TARGET:g})",
        (f"solve time growing like dofs^{ctx.fit_solve[0]:.2f}" if ctx.fit_solve
         else "no exponent of the solve time in dofs") + f" (target {bench.EXPONENT_TARGET:g})"])


RENDER = {"scenes": render_scenes, "axisymmetric": render_axisymmetric, "formulations": render_formulations,
          "solver": render_solver, "lmvm": render_lmvm,
          "speed": render_speed, "accuracy": render_accuracy, "oscillation": render_oscillation,
          "stress": render_stress, "stress-solvers": render_stress_solvers, "parallel": render_parallel, "parallel-stages": render_parallel_stages,
          "penalty": render_penalty}
# the phrases: figures inside a sentence of the README, each a line of text without its line breaks
PHRASES = {"solver-speed": render_solver_speed, "lmvm-ratio": render_lmvm_ratio,
           "parallel-speedup": render_parallel_speedup, "speed-targets": render_speed_targets}


def kind(name):
    """What a block is called in messages."""
    return "table" if name in RENDER else "phrase"


def pages():
    """The pages that may hold tables and phrases, relative to ROOT: README.md, every
    docs/*.md, bench/README.md."""
    docs = os.path.join(ROOT, "docs")
    found = sorted(os.path.join("docs", f) for f in os.listdir(docs) if f.endswith(".md")) if os.path.isdir(docs) else []
    return ["README.md"] + found + [os.path.join("bench", "README.md")]


def blocks(text, page="README.md"):
    """{name: (start, end)} of the text between each pair of markers. A
    table's begin marker ends its line; a phrase's stands inside a line (at
    its start Markdown would take the line for HTML) with the phrase after it
    on that line, and the phrase stays within its paragraph. A marker doubled,
    a begin without its end, or the other kind's form is an error naming page."""
    out = {}
    for name in list(RENDER) + list(PHRASES):
        b, e = f"<!-- figures:{name}:begin -->", f"<!-- figures:{name}:end -->"
        if text.count(b) > 1 or text.count(e) > 1:
            raise SystemExit(f"{page}: the markers of {kind(name)} {name} appear more than once")
        if b in text:
            k = text.index(b)
            i = k + len(b)
            if name in RENDER and not text.startswith("\n", i):
                raise SystemExit(f"{page}: table {name}'s begin marker must end its line")
            if name in PHRASES and (text.startswith("\n", i) or not text[text.rfind("\n", 0, k) + 1:k].strip()):
                raise SystemExit(f"{page}: phrase {name}'s begin marker must stand inside a line, the phrase after it")
            if name in RENDER:
                i += 1
            if e not in text[i:]:
                raise SystemExit(f"{page}: {kind(name)} {name} has no end marker <!-- figures:{name}:end -->")
            out[name] = (i, text.index(e, i))
            if name in PHRASES and re.search(r"\n\s*\n", text[i:out[name][1]]):
                raise SystemExit(f"{page}: phrase {name} runs over a paragraph's end")
        elif e in text:
            raise SystemExit(f"{page}: {kind(name)} {name} has an end marker without its begin marker")
    return out


def locate(texts):
    """{name: page} of every table and phrase over the pages {page: text};
    one on two pages, or on none, is an error naming them."""
    where = {}
    for page, text in texts.items():
        for name in blocks(text, page):
            if name in where:
                raise SystemExit(f"{kind(name)} {name} has markers on two pages: {where[name]} and {page}")
            where[name] = page
    missing = sorted(set(RENDER) - set(where)) + sorted(set(PHRASES) - set(where))
    if missing:
        raise SystemExit(f"no page ({', '.join(texts)}) has markers for: {', '.join(missing)}")
    return where


def differs(name, old, new):
    """Whether a block's text is not its rendering: a table's to the letter, a
    phrase's word by word (its line breaks and indentation are the page's)."""
    return old != new if name in RENDER else old.split() != new.split()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--update", action="store_true")
    ap.add_argument("--measure", choices=["scenes", "solver", "lmvm", "picture", "axisymmetric"], action="append", default=[])
    args = ap.parse_args()
    if "scenes" in args.measure:
        measure_scenes()
    if "solver" in args.measure:
        measure_solver()
    if "lmvm" in args.measure:
        measure_lmvm()
    if "picture" in args.measure:
        measure_picture()
    if "axisymmetric" in args.measure:
        measure_axisymmetric()
    texts = {}
    for page in pages():
        with open(os.path.join(ROOT, page)) as f:
            texts[page] = f.read()
    where = locate(texts)
    stale = []
    for page, text in texts.items():
        for name, (i, j) in sorted(blocks(text, page).items(), key=lambda kv: -kv[1][0]):
            new = (RENDER.get(name) or PHRASES[name])()
            if differs(name, text[i:j], new):
                stale.append(f"{name} ({page})")
                text = text[:i] + new + text[j:]
        if args.update and text != texts[page]:
            with open(os.path.join(ROOT, page), "w") as f:
                f.write(text)
    if args.update:
        print("updated:", ", ".join(stale) if stale else "nothing (all up to date)")
    elif stale:
        print("tables and phrases that differ from their committed results:", ", ".join(stale),
              "(python3 scripts/readme_figures.py --update)")
        sys.exit(1)
    else:
        print("tables and phrases match their results:", ", ".join(f"{n} ({where[n]})" for n in sorted(where)))


if __name__ == "__main__":
    main()
