#!/usr/bin/env python3
"""The documentation's tables of measured figures and the README's phrases
quoting them, generated from committed results, and the README's picture.

    python3 scripts/readme_figures.py --check      # exit 1 if a table or phrase differs from its results
    python3 scripts/readme_figures.py --update     # rewrite the tables and phrases from the results
    python3 scripts/readme_figures.py --measure scenes --measure solver --measure lmvm [--update]
                                                   # run a table's cases first
    python3 scripts/readme_figures.py --measure axisymmetric [--update]
    python3 scripts/readme_figures.py --measure rigid [--update]
    python3 scripts/readme_figures.py --measure rigid-free [--update]
    python3 scripts/readme_figures.py --measure model [--update]
    python3 scripts/readme_figures.py --measure squeeze [--update]
    python3 scripts/readme_figures.py --measure squeeze-newton [--update]
    python3 scripts/readme_figures.py --measure friction [--update]
    python3 scripts/readme_figures.py --measure friction-cost [--update]
    python3 scripts/readme_figures.py --measure ranks [--update]
    python3 scripts/readme_figures.py --measure squeeze-picture
                                                   # redraw docs/img/rubber-squeeze.png
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
- stress-solvers: the same sweep's comparison with lmvm and blmvm
  (bench/stress-lmvm, stress-blmvm) and with lmvm's tighter stops at
  k_p = 1e10 (stress-lmvm-gttol11, stress-lmvm-decrement), against Newton's;
- penalty: bench/penalty/results.json (scripts/penalty_study.py: the automatic
  penalty's error against the mesh's);
- rigid, rigid-adequacy, rigid-free and the phrase rigid-adequacy-phrase: bench/rigid/results.json (written by
  --measure rigid: rigid_study.py's scenes, each run once but the timed
  pairs, alternated 3 times; the reference scene with the disc E2/E1 times
  stiffer against the disc rigid; the rigid bodies' unknowns: force control,
  held by contact, a free rotation, which --measure rigid-free measures alone).
- axisymmetric: bench/axisymmetric/results.json (written by --measure
  axisymmetric: the sphere and ssnv104 scenes at their defaults and the
  sphere under -accuracy 0.01, median of 3 whole-run times; half a minute);
- model: bench/model/results.json (written by --measure model: the reference
  scene pushed by 0.01, 0.05, 0.15 and 0.3 with both bodies linear and both
  neo-Hookean, the model's error against the largest strain; half a minute);
- squeeze, squeeze-cost: bench/squeeze/results.json (written by --measure
  squeeze: squeeze_study.py's force-squeeze curves on 4 meshes, against
  GetFEM's, bench/squeeze/getfem-h*.json, and the cost of neo-Hookean
  bodies; it also draws docs/img/rubber-squeeze.png, which --measure
  squeeze-picture redraws from the committed curves; about 7 minutes,
  5 of them L-BFGS with Armijo's line search, which does not converge;
  --measure squeeze-newton re-measures the Newton rows of the cost alone);
  the phrase squeeze-cost-ratio: the neo-Hookean solve over the linear one
  at small strain, from the same file;
- friction, friction-cost: bench/friction/results.json (written by --measure
  friction: friction_study.py's Cattaneo-Mindlin and Mindlin-Deresiewicz runs
  on meshes/cattaneo, in 1 and 8 increments a stage, each load ratio at
  contact edges twice and half the scene's, and each with the contact twice
  as wide, about three minutes; --measure friction-cost: Newton's iterations
  per increment with friction and without, and L-BFGS with friction, about
  a minute); the phrase friction-cost-ratio: the range of those ratios, the
  increments above 3, and L-BFGS's iterations and stick zone, from the same file;
  the table friction-wider (docs/scenes.md): each load ratio on the scene
  and with the contact twice as wide against the bodies;
- the phrase solid3d-getfem (docs/solver.md): Lame's octant beside GetFEM,
  bench/solid3d/results.json (scripts/bench_solid3d.py --side-by-side 3);
- friction-getfem (docs/scenes.md) and the phrase friction-getfem-phrase
  (README.md): GetFEM on the cattaneo meshes with the contact twice as wide,
  bench/friction/getfem.json, and the phrase friction-getfem-scene
  (docs/scenes.md): on the scene's own, bench/friction/getfem-scene.json
  (both written by --measure friction-getfem: scripts/getfem_cattaneo.py run
  by /usr/bin/python3 with python3-getfem, about two minutes), beside the
  program's rows of bench/friction/results.json;
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
likes; --update writes a stale one on one line. The phrases of README.md:

- solver-speed: Newton's and L-BFGS's (-tao_type lmvm) iterations and solve
  times at h = 0.06, from the solver table (bench/solver/results.json);
- lmvm-ratio: the least and greatest L-BFGS solve time over Newton's in the
  lmvm table (bench/lmvm/results.json), up to its largest k_p;
- ranks-agree: the largest relative differences of P and of the energy over
  the reference scene's runs on 1 to 4 ranks under five OpenBLAS kernels, and
  their largest gradient norm (bench/ranks/results.json, written by
  --measure ranks);
- blas-speed (docs/solver.md): the reference scene's solve time on 1 and 2
  ranks with the program's BLAS kernel, with Prescott's and with SkylakeX's
  (bench/blas/results.csv, from scripts/bench_parallel.py);
- parallel-speedup: the parallel table's solve-time speed-ups, its largest
  mesh's dofs, and the whole run's speed-up where bench_parallel.py sets it a
  target (bench/parallel/results.csv);
- speed-targets: "all met", or the targets not met, of scripts/bench.py's
  targets table of the full sweep (bench/full/results.csv, through bench.py's
  own modules' functions), then the reference scene's solve time at h = 0.06, the worst
  time in linear solves of the same mesh and the solve time's exponent in dofs,
  each with its target.

The phrases of bench/README.md's speed section, all from the full sweep
(bench/full/results.csv and run.json, through bench.py's own modules'
functions: bench_results, bench_analysis, bench_targets; so that they say
what its RESULTS.md says):

- sweep-run: its configurations, program (git), repeats and wall time;
- sweep-targets: "all met", or the targets not met (as in speed-targets);
- sweep-reference-solve, sweep-linear-ratio, sweep-exponent,
  sweep-fixed-costs, sweep-search, sweep-mortar-cost: each target's figures
  (the solve time at h = 0.06 and the fastest strategy's; the worst time in
  linear solves from 1e4 dofs and those below; the fitted exponents and the
  range of linear solves; mesh, set-up and output's share of the largest run;
  the search against an energy evaluation; mortar / gpts at h = 0.06 and on the
  largest mesh, and each formulation's Newton steps);
- formulations-cost: from bench/formulations.csv (bench.py --formulations-cost,
  not the full sweep): mortar / gpts, the Newton steps, the cost per step and
  the shares of the factorisations and the contact terms at each size;
- sweep-profile: mortar's profile distance from the finest run on every mesh
  of the reference scene, gpts' range from h = 0.06;
- sweep-cheapest: the cheapest run within each error level of that distance,
  per formulation, and the uniform run as fine as a graded or half scene's
  reference;
- sweep-half: the half model's P and solve time against the full model's.

The phrase of docs/solver.md, under its lmvm table:

- lmvm-iterations: the lmvm table's range of L-BFGS solve times over Newton's,
  and of L-BFGS's and Newton's iterations.

The picture: --measure picture runs the reference scene as `make run` does
(meshes/hertz/hertz.opts, the program's defaults), its HDF5 output in a
temporary directory, and draws its pressure plot with scripts/plot_hertz.py
into docs/img/hertz-pressure.png, the PNG the README shows (a few seconds).
"""
import argparse
import functools
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


# The scenes the README's solver claims range over (issue 34, "claims measured where
# users run"): (label, arguments); a scene whose folder is missing is left out.
CLAIM_SCENES = [
    ("reference, h = 0.03", ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.03"]),
    ("reference", ["-options_file", "meshes/hertz/hertz.opts"]),
    ("half model", ["-options_file", "meshes/hertz-half/hertz-half.opts"]),
    ("sphere (r-z)", ["-options_file", "meshes/sphere/sphere.opts"]),
    ("reference by force", ["-options_file", "meshes/hertz/hertz.opts",
                            "-block_bc_push_control", "force,displacement", "-block_bc_push_values", "-55,0"]),
    ("punch", ["-options_file", "meshes/punch/punch.opts"]),
    ("stiff punch on a soft layer", ["-options_file", "tests/meshes/stiff-punch/stiff-punch.opts",
                                     "-layer_mesh_size", "0.0125", "-punch_mesh_size", "0.025"]),
    ("roller", ["-options_file", "meshes/roller/roller.opts"]),
]
# (solver, ranks) of each scene, interleaved; a run past CLAIM_TIMEOUT seconds counts as failed
CLAIM_RUNS = [("nls", 1), ("lmvm", 1), ("nls", 2)]
CLAIM_TIMEOUT = 120


def claim_scenes():
    return [(label, args) for label, args in CLAIM_SCENES if os.path.exists(os.path.join(ROOT, args[1]))]


def measure_claims(repeat=3):
    """Newton on 1 and 2 ranks and L-BFGS on 1 rank on each of CLAIM_SCENES,
    interleaved, median of repeat solve times (meshes made first). A run that
    fails is recorded as such (its exit status and last line), not dropped."""
    from contactrun import median, mesh_only, run_case
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for label, args in claim_scenes():
            mesh_only(args)
            runs = {k: [] for k in CLAIM_RUNS}
            for _ in range(repeat):
                for tao, ranks in CLAIM_RUNS:
                    if runs[tao, ranks] and runs[tao, ranks][-1].returncode != 0:
                        continue   # failed or timed out once: not timed again
                    runs[tao, ranks].append(run_case(args + ["-tao_type", tao], tmp, "s", ranks=ranks, h5=False,
                                                     timeout=CLAIM_TIMEOUT))
            for (tao, ranks), rs in runs.items():
                ok = [r for r in rs if r.returncode == 0]
                row = dict(scene=label, tao=tao, ranks=ranks, converged=len(ok) == len(rs),
                           command=("mpiexec -n 2 " if ranks > 1 else "") + "bin/contact " + " ".join(args + ["-tao_type", tao]))
                if ok:
                    s = ok[-1].summary
                    row.update(dofs=s["dofs"], iterations=s["iterations"], P=s["contact_force"],
                               solve=median([r.summary["time"]["solve"] for r in ok]),
                               runs=[r.summary["time"]["solve"] for r in ok])
                if len(ok) < len(rs):
                    bad = next(r for r in rs if r.returncode != 0)
                    lines = [ln for ln in (bad.stderr or "").splitlines() if ln.startswith("contact:")]
                    why = f"not done in {CLAIM_TIMEOUT} s" if bad.returncode is None else (lines[-1] if lines else "")
                    row.update(status=bad.returncode, why=why)
                rows.append(row)
    save("claims", rows)


def claim_table():
    """{scene: {(tao, ranks): row}} of bench/claims/results.json, in its order."""
    out = {}
    for r in load("claims"):
        out.setdefault(r["scene"], {})[r["tao"], r["ranks"]] = r
    return out


def render_claims():
    out = ["| scene | dofs | Newton: iterations, solve [s] | L-BFGS: iterations, solve [s] | L-BFGS / Newton "
           "| 2 ranks: solve [s] | speed-up |", "|---|---|---|---|---|---|---|"]
    for scene, t in claim_table().items():
        n, lb, two = t["nls", 1], t["lmvm", 1], t["nls", 2]

        def cell(r):
            return f"{r['iterations']}, {r['solve']:.2f}" if r["converged"] else f"fails: {r.get('why') or r.get('status')}"
        ratio = f"{lb['solve'] / n['solve']:.2f}" if lb["converged"] and n["converged"] else ""
        speed = f"{n['solve'] / two['solve']:.2f}" if two["converged"] and n["converged"] else ""
        out.append(f"| {scene} | {n.get('dofs', 0):,} | {cell(n)} | {cell(lb)} | {ratio} | {cell(two)} | {speed} |")
    return "\n".join(out) + "\n"


def render_claims_lmvm():
    """L-BFGS's solve time over Newton's, least to greatest, over the claims' scenes, and where it fails."""
    t = claim_table()
    ratios = [(v["lmvm", 1]["solve"] / v["nls", 1]["solve"], k) for k, v in t.items()
              if v["lmvm", 1]["converged"] and v["nls", 1]["converged"]]
    slow = [k for k, v in t.items() if not v["lmvm", 1]["converged"] and v["lmvm", 1].get("status") is None]
    failed = [k for k, v in t.items() if not v["lmvm", 1]["converged"] and v["lmvm", 1].get("status") is not None]
    lo, hi = min(ratios), max(ratios)
    text = f"{lo[0]:.2f} ({lo[1]}) to {hi[0]:.2f} ({hi[1]}) times Newton's solve time on {len(ratios)} of {len(t)} scenes"
    if slow:
        text += f"; on {', '.join(slow)} it does not finish within {CLAIM_TIMEOUT} s"
    if failed:
        text += f"; on {', '.join(failed)} it stops unconverged"
    return text


def render_claims_parallel():
    """2 ranks' speed-up of Newton's solve, least to greatest, over the claims' scenes
    where 1 and 2 ranks take the same iterations (elsewhere the ratio is the path's:
    the stiff punch's Newton creeps 131 iterations on 1 rank and 49 on 2)."""
    t = claim_table()
    sp = [(v["nls", 1]["solve"] / v["nls", 2]["solve"], k) for k, v in t.items()
          if v["nls", 2]["converged"] and v["nls", 1]["converged"] and v["nls", 2]["iterations"] == v["nls", 1]["iterations"]]
    lo, hi = min(sp), max(sp)
    return f"{lo[0]:.2f} ({lo[1]}) to {hi[0]:.2f} ({hi[1]}) times as fast as one over the same scenes, where both take the same iterations"


def lmvm_pairs():
    """[(row, Newton's row of the same case)] of bench/lmvm/results.json, in its order."""
    rows = load("lmvm")
    newton = {(r["h"], r["kp"], r["ranks"]): r for r in rows if r["tao"] == "nls"}
    return [(r, newton[(r["h"], r["kp"], r["ranks"])]) for r in rows]


def render_lmvm():
    from contactrun import power
    out = ["| h | dofs | k_p | ranks | solver | iterations | energy evaluations | H0 set-ups | pairs dropped "
           "| solve [s] | / Newton | P from Newton's |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r, n in lmvm_pairs():
        lm = r["tao"] != "nls"
        dP = f"{abs(r['P'] / n['P'] - 1):.1e}" if lm else ""
        out.append(f"| {r['h']:g} | {r['dofs']:,} | {power(r['kp'])} | {r['ranks']} | {r['tao']} | {r['iterations']} "
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


@functools.lru_cache(maxsize=None)
def full_sweep():
    """bench/full (scripts/bench.py's whole sweep): its rows, the figures its RESULTS.md is made of
    (bench_analysis.report_figures) and its run.json."""
    import bench_analysis
    import bench_results
    out = os.path.join(ROOT, "bench", "full")
    rows = bench_results.read_csv(os.path.join(out, "results.csv"))
    return (rows, bench_analysis.report_figures(rows, types.SimpleNamespace(out=out), None, None, None, None),
            bench_results.read_run(out))


def render_speed():
    """The reference scene's scaling rows of the full sweep: mortar (the
    default) and gpts, newton, k_p = 2e6, gttol 1e-8, one rank, from h = 0.06
    down; the linear solve, ratio, fixed costs and memory are mortar's."""
    import bench_analysis
    out = ["| h | dofs | iterations mortar / gpts | solve mortar / gpts [s] | one linear solve [s] | ratio "
           "| mesh + set-up + output | peak memory |", "|---|---|---|---|---|---|---|---|"]
    for h, g, m in bench_analysis.formulation_ratio_rows(full_sweep()[0]):
        if h > 0.06:
            continue
        mb = m["peak_mb"]
        mem = f"{mb / 1024:.1f} GB" if mb >= 1024 else f"{mb:.0f} MB"
        out.append(f"| {h:g} | {m['dofs']:,} | {m['iterations']} / {g['iterations']} | {m['solve_median']:.3g} / "
                   f"{g['solve_median']:.3g} | {m['linear_solve_time']:.3g} | {m['ratio_to_linear']:.1f} "
                   f"| {100 * bench_analysis.fixed_cost_share(m):.0f} % | {mem} |")
    return "\n".join(out) + "\n"


def render_stress_solvers():
    import stress_sweep
    newton = load("stress")
    return stress_sweep.solver_table([("Newton", newton), ("lmvm", load("stress-lmvm")),
                                      ("blmvm", load("stress-blmvm")),
                                      ("lmvm, -tao_gttol 1e-11 (an earlier build)", load("stress-lmvm-gttol11"), False),
                                      ("lmvm, -lmvm_decrement_rtol 1e-12 (an earlier build)", load("stress-lmvm-decrement"),
                                       False)], newton)


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


MODEL_PUSHES = [0.01, 0.05, 0.15, 0.3]   # the reference scene's push is 0.15


def measure_model():
    """The reference scene (h = 0.1) pushed by each of MODEL_PUSHES, both
    bodies linear and both neo-Hookean: P, p_max, the second-moment a, the
    largest Green-Lagrange strain of either body and Newton's iterations."""
    from contactrun import run_checked
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for d in MODEL_PUSHES:
            for m in ("linear", "neohookean"):
                args = ["-options_file", "meshes/hertz/hertz.opts", "-indenter_material", m, "-block_material", m,
                        "-block_bc_push_values", f"{-d!r},0"]
                s = run_checked(args, tmp, "m").summary
                rows.append(dict(push=d, material=m, command="bin/contact " + " ".join(args), P=s["contact_force"],
                                 fem_pmax=s["fem_pmax"], fem_a=s["fem_a_moment"], iterations=s["iterations"],
                                 strain=max(b["max_green_lagrange_strain"] for b in s["bodies"].values())))
    save("model", rows)


def render_model():
    rows = load("model")
    out = ["| push | largest strain | P: linear / neo-Hookean | p_max: linear / neo-Hookean | a: linear / neo-Hookean | Newton iterations |",
           "|---|---|---|---|---|---|"]
    for d in sorted({r["push"] for r in rows}):
        lin, nh = ([r for r in rows if r["push"] == d and r["material"] == m][0] for m in ("linear", "neohookean"))
        cells = [f"{lin[k]:.5g} / {nh[k]:.5g} ({100 * (nh[k] / lin[k] - 1):+.2f} %)" for k in ("P", "fem_pmax", "fem_a")]
        out.append(f"| {d:g} | {100 * lin['strain']:.3g} % / {100 * nh['strain']:.3g} % | " + " | ".join(cells)
                   + f" | {lin['iterations']} / {nh['iterations']} |")
    return "\n".join(out) + "\n"


def measure_rigid():
    """The rigid bodies' scenes against their references (rigid_study.py)."""
    import rigid_study
    save("rigid", {"scenes": rigid_study.measure(), "adequacy": rigid_study.measure_adequacy(), "free": rigid_study.measure_free()})


def render_rigid():
    import rigid_study
    return rigid_study.table(load("rigid")["scenes"], load("rigid")["free"])


def measure_rigid_free():
    """The rigid bodies' unknowns alone (rigid_study.measure_free), into the rigid results."""
    import rigid_study
    save("rigid", dict(load("rigid"), free=rigid_study.measure_free()))


def render_rigid_free():
    import rigid_study
    return rigid_study.free_table(load("rigid")["free"])


SQUEEZE_PNG = os.path.join("docs", "img", "rubber-squeeze.png")


def measure_squeeze():
    """The rubber-squeeze study (squeeze_study.py) and its figure."""
    import squeeze_study
    save("squeeze", squeeze_study.measure(os.path.join(ROOT, SQUEEZE_PNG)))


def measure_squeeze_newton():
    """The squeeze's Newton cost rows alone (squeeze_study.measure_newton_cost), its L-BFGS rows kept."""
    import squeeze_study
    res = load("squeeze")
    with tempfile.TemporaryDirectory() as tmp:
        newton = squeeze_study.measure_newton_cost(tmp)
    res["cost"] = newton + [r for r in res["cost"] if "L-BFGS" in r["run"]]
    save("squeeze", res)


def measure_squeeze_picture():
    """The rubber-squeeze figure redrawn from the committed curves."""
    import squeeze_study
    squeeze_study.redraw(load("squeeze")["curves"], os.path.join(ROOT, SQUEEZE_PNG))


def render_squeeze():
    import squeeze_study
    return squeeze_study.curve_table(load("squeeze")["curves"], squeeze_study.getfem_results())


def render_squeeze_cost():
    import squeeze_study
    return squeeze_study.cost_table(load("squeeze")["cost"])


def render_squeeze_cost_ratio():
    import squeeze_study
    rows = load("squeeze")["cost"]
    full = ", -tangent_at_rest 0"
    return (f"{squeeze_study.cost_ratio(rows, 'hertz'):.2f} times the linear run's solve on the reference scene pushed "
            f"by 0.01 and {squeeze_study.cost_ratio(rows, 'rubber-squeeze'):.2f} times on the squeeze at 1 % of its push; "
            f"with the tangent at every step (-tangent_at_rest 0) {squeeze_study.cost_ratio(rows, 'hertz', full):.2f} and "
            f"{squeeze_study.cost_ratio(rows, 'rubber-squeeze', full):.2f} times")


def measure_friction():
    """Friction against Cattaneo-Mindlin and Mindlin-Deresiewicz (friction_study.measure), its cost kept."""
    import friction_study
    old = load("friction") if os.path.exists(os.path.join(ROOT, "bench", "friction", "results.json")) else {}
    save("friction", dict(old, accuracy=friction_study.measure()))


def measure_friction_cost():
    """Friction's cost in iterations per increment (friction_study.measure_cost), its accuracy rows kept."""
    import friction_study
    old = load("friction") if os.path.exists(os.path.join(ROOT, "bench", "friction", "results.json")) else {}
    save("friction", dict(old, cost=friction_study.measure_cost()))


def render_friction():
    import friction_study
    return friction_study.table(load("friction")["accuracy"])


def render_friction_cost():
    import friction_study
    return friction_study.cost_table(load("friction")["cost"])


def render_friction_wider():
    import friction_study
    return friction_study.wider_table(load("friction")["accuracy"])


def measure_friction_getfem():
    """GetFEM on the cattaneo meshes with the contact twice as wide (getfem.json) and on the
    scene's own (getfem-scene.json) (scripts/getfem_cattaneo.py, run by the system's python3
    with python3-getfem)."""
    import subprocess
    for extra, name in ((["--scale", "2"], "getfem.json"), ([], "getfem-scene.json")):
        subprocess.run(["/usr/bin/python3", os.path.join("scripts", "getfem_cattaneo.py")] + extra
                       + ["-o", os.path.join("bench", "friction", name)], cwd=ROOT, check=True)


def getfem_friction(name="getfem.json"):
    with open(os.path.join(ROOT, "bench", "friction", name)) as f:
        return json.load(f)


def render_friction_getfem():
    import friction_study
    return friction_study.getfem_table(load("friction")["accuracy"], getfem_friction())


def render_friction_getfem_phrase():
    import friction_study
    return friction_study.getfem_phrase(load("friction")["accuracy"], getfem_friction())


def render_solid3d_getfem():
    """Lame's octant at h = 0.1 beside GetFEM (bench/solid3d/results.json,
    scripts/bench_solid3d.py --side-by-side: interleaved, median-wall runs)."""
    R = load("solid3d")
    ours, theirs, before = R["lame-h0.1 | default"], R["lame-h0.1 | GetFEM 5.4 (P2, MUMPS)"], R.get("lame-h0.1 | default, before")
    text = (f"the default takes {ours['wall']:.1f} s for the whole process against GetFEM's {theirs['wall']:.1f} s on the same "
            f"mesh (P2, MUMPS, one core; its assembly and factorisation {theirs['solve']:.1f} s, our solve {ours['solve']:.1f} s, "
            f"{ours['cg']} CG iterations), at the same error ({ours['error']:.2e} against {theirs['error']:.2e}, relative L2 of u): "
            f"{ours['wall'] / theirs['wall']:.2f} of its time" + (", within the third aimed at" if ours['wall'] <= theirs['wall'] / 3 else ", short of the third aimed at"))
    if before:
        text += (f" (before, GAMG on the free dofs, in the same sitting: {before['wall']:.1f} s, {before['cg']} CG iterations, "
                 f"{before['wall'] / theirs['wall']:.2f})")
    return text


def render_friction_getfem_scene():
    import friction_study
    return friction_study.getfem_scene_phrase(load("friction")["accuracy"], getfem_friction("getfem-scene.json"))


def render_friction_cost_ratio():
    import friction_study
    return friction_study.cost_phrase(load("friction")["cost"])


def render_rigid_adequacy():
    import rigid_study
    return rigid_study.adequacy_table(load("rigid")["adequacy"])


def render_rigid_adequacy_phrase():
    import rigid_study
    return rigid_study.adequacy_phrase(load("rigid")["adequacy"])


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


def lmvm_ratio_range():
    """'least to greatest' of the lmvm table's L-BFGS solve times over Newton's in the same case."""
    ratios = [r["solve"] / n["solve"] for r, n in lmvm_pairs() if r["tao"] != "nls"]
    return f"{min(ratios):.2f} to {max(ratios):.2f}"


def render_lmvm_ratio():
    """The least and the greatest of the lmvm table's L-BFGS solve times over Newton's, and its largest k_p."""
    from contactrun import power
    kp = max(r["kp"] for r, _ in lmvm_pairs() if r["tao"] != "nls")
    return f"{lmvm_ratio_range()} times Newton's time up to k_p = {power(kp)}"


def render_lmvm_iterations():
    """The lmvm table's range of L-BFGS solve times over Newton's, and the ranges of L-BFGS's and Newton's
    iterations over its cases."""
    lm = [r["iterations"] for r, _ in lmvm_pairs() if r["tao"] != "nls"]
    nl = [r["iterations"] for r, _ in lmvm_pairs() if r["tao"] == "nls"]
    return (f"{lmvm_ratio_range()} here: the issue's bound was 3); L-BFGS takes {min(lm)} to "
            f"{max(lm)} iterations whatever h and k_p, Newton {min(nl)} to {max(nl)}")


def render_blas_speed():
    """The reference scene's median solve time on 1 and 2 ranks with the
    program's own kernel choice, with -blas_kernel Prescott (OpenBLAS's
    fallback) and with -blas_kernel SkylakeX, and each 2-rank speed-up
    (bench/blas/results.csv, scripts/bench_parallel.py's configurations 1, 2,
    1:prescott, 2:prescott, 1:skylakex, 2:skylakex)."""
    import bench_parallel
    rows = bench_parallel.load_rows(os.path.join(ROOT, "bench", "blas", "results.csv"))
    h = max(r["h"] for r in rows)
    rows = [r for r in rows if r["h"] == h]

    def med(config):
        return bench_parallel.med([r for r in rows if r["config"] == config], "time_solve")
    out = []
    for label, one, two in (("the program's choice", "1", "2"), ("Prescott", "1:prescott", "2:prescott"),
                            ("SkylakeX", "1:skylakex", "2:skylakex")):
        a, b = med(one), med(two)
        out.append(f"{label} {a:.2f} s on 1 rank and {b:.2f} s on 2 ({a / b:.2f} times)")
    reps = max(r["repeat"] for r in rows)
    return (f"the reference scene at h = {h:g} solves (median of {reps}, interleaved) in " + "; ".join(out)
            + " (`python3 scripts/bench_parallel.py --sizes 0.015 --repeat 5 --configs "
            "1,2,1:prescott,2:prescott,1:skylakex,2:skylakex --out bench/blas`)")


RANK_KERNELS = ["Prescott", "Nehalem", "Sandybridge", "Haswell", "SkylakeX"]


def measure_ranks():
    """The reference scene (its own options: h = 0.1, mortar, Newton's
    default stop) on 1 to 4 ranks under each of the five OpenBLAS kernels
    (-blas_kernel): bench/ranks/results.json, one row per run."""
    import contactrun
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for kernel in RANK_KERNELS:
            for n in (1, 2, 3, 4):
                r = contactrun.run_case(["-options_file", "meshes/hertz/hertz.opts", "-blas_kernel", kernel], tmp,
                                        f"{kernel}-{n}", ranks=n, h5=False)
                if r.returncode != 0 or not r.summary:
                    raise SystemExit(f"{' '.join(r.cmd)} failed:\n{(r.stdout or '')[-2000:]}")
                s = r.summary
                rows.append({"kernel": kernel, "ranks": n, "P": s["contact_force"], "energy": s["energy"],
                             "gradient_norm": s["gradient_norm"], "dofs": s["dofs"]})
    save("ranks", rows)


def render_ranks_agree():
    """The largest relative difference in P and in the energy between any two of
    bench/ranks/results.json's runs (1 to 4 ranks, five kernels)."""
    rows = load("ranks")
    P = [r["P"] for r in rows]
    E = [r["energy"] for r in rows]
    dP = (max(P) - min(P)) / max(abs(p) for p in P)
    dE = (max(E) - min(E)) / max(abs(e) for e in E)
    g = max(r["gradient_norm"] for r in rows)
    return (f"On the reference scene (h = 0.1, Newton's default stop, gradient norm at most {g:.1e}) "
            f"{min(r['ranks'] for r in rows)} to {max(r['ranks'] for r in rows)} ranks under {len(set(r['kernel'] for r in rows))} "
            f"OpenBLAS kernels give P within {dP:.1e} of each other and the energy within {dE:.1e}")


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


def targets_met():
    """'all met', or 'met but for' the full sweep's targets not met with their status, as scripts/bench.py's
    table of them says."""
    import bench_targets
    rows, ctx, _ = full_sweep()
    missed = [f"{target_name(t)} ({st})" for t, _, st in bench_targets.target_rows(rows, ctx)
              if not bench_targets.met(st)]
    return "all met" if not missed else "met but for " + "; ".join(missed)


def reference_default():
    """The full sweep's converged run of the default strategy on the reference scene at h = 0.06 (gpts), or
    None."""
    import bench_analysis
    d06 = [r for r in bench_analysis.reference_solve_runs(full_sweep()[0])[0] if r["converged"]]
    return d06[0] if d06 else None


def ratio_runs():
    """The full sweep's reference runs with a time in linear solves, and those the target counts (from 1e4 dofs)."""
    import bench_analysis
    return bench_analysis.linear_ratio_runs(full_sweep()[1].ref_sel)


def render_speed_targets():
    """Whether the full sweep meets its targets, as scripts/bench.py's table of them says (those not met
    named), and the three of speed: the reference scene's solve time at h = 0.06, the worst time in
    linear solves of the same mesh and the exponent of the solve time in dofs."""
    import bench_analysis
    import bench_targets
    ctx, d06, ratios = full_sweep()[1], reference_default(), ratio_runs()[1]
    return targets_met() + ": " + ", ".join([
        (f"the reference scene at h = 0.06 solved in {d06['solve_median']:.3g} s" if d06
         else "the reference scene at h = 0.06 not solved by the default strategy")
        + f" (target {bench_targets.REF_SOLVE_TARGET:g} s)",
        (f"at most {bench_analysis.worst_ratio(ratios)['ratio_to_linear']:.1f} linear solves of the same mesh up to "
         f"{max(r['dofs'] for r in ratios):,} dofs" if ratios else "no time in linear solves from 1e4 dofs")
        + f" (target {bench_targets.LINEAR_RATIO_TARGET:g})",
        (f"solve time growing like dofs^{ctx.fit_solve[0]:.2f}" if ctx.fit_solve
         else "no exponent of the solve time in dofs") + f" (target {bench_targets.EXPONENT_TARGET:g})"])


def render_sweep_run():
    """The full sweep's size, program, repeats and wall time (results.csv's rows, run.json)."""
    rows, _, run = full_sweep()
    return (f"{len(rows)} configurations of the program at git {run.get('bin_git', '?')}, median of "
            f"{run['repeat']}, {run['elapsed'] / 60:.0f} minutes")


def render_sweep_reference_solve():
    """The reference scene's solve time at h = 0.06 by the default strategy (gpts) against its target, and
    the fastest strategy's where it is another."""
    import bench_analysis
    import bench_sweep
    import bench_targets
    rows = full_sweep()[0]
    d06, conv = reference_default(), bench_analysis.reference_solve_runs(rows)[1]
    text = (f"h = 0.06 solved to `-tao_gttol 1e-8` in {d06['solve_median']:.3g} s" if d06
            else "h = 0.06 not solved by the default strategy")
    text += f" (<= {bench_targets.REF_SOLVE_TARGET:g} s; {bench_sweep.REF_FORMULATION}, {bench_sweep.REF_STRATEGY}"
    best = bench_analysis.fastest(conv) if conv else None
    if best and best is not d06:
        text += f"; the fastest strategy, {best['strategy']}, {best['solve_median']:.3g} s"
    return text + ")"


def render_sweep_linear_ratio():
    """The worst time in linear solves of the same mesh from 1e4 dofs, its span and target, and the
    ratios on the smaller meshes."""
    import bench_analysis
    import bench_targets
    rat, big = ratio_runs()
    if not big:
        return "no time-to-solution in linear solves from 1e4 dofs"
    small = [r for r in rat if r not in big]
    text = (f"time-to-solution at most {bench_analysis.worst_ratio(big)['ratio_to_linear']:.1f} linear solves "
            f"of the same mesh from {big[0]['dofs']:,} to {big[-1]['dofs']:,} dofs "
            f"(<= {bench_targets.LINEAR_RATIO_TARGET:g}")
    if small:
        ratios = and_list([f"{r['ratio_to_linear']:.1f}" for r in small])
        dofs = and_list([f"{r['dofs']:,}" for r in small])
        text += f"; {ratios} on the meshes of {dofs} dofs, where fixed costs dominate"
    return text + ")"


def render_sweep_exponent():
    """The fitted exponents in dofs of the solve time (gpts, mortar), the wall time and one linear solve,
    and the range of the solve time in linear solves over the fit's meshes."""
    import bench_analysis
    import bench_targets
    _, ctx, run = full_sweep()
    if not ctx.fit_solve:
        return "no exponent of the solve time in dofs"
    span = bench_analysis.fit_runs(ctx.ref_sel)
    ratios = [r["ratio_to_linear"] for r in ratio_runs()[1]]
    exp = lambda fit: f"{fit[0]:.2f}" if fit else "-"  # noqa: E731
    return (f"solve time growing like dofs^{ctx.fit_solve[0]:.2f} from {span[0]['dofs']:,} to {span[-1]['dofs']:,} "
            f"dofs (<= {bench_targets.EXPONENT_TARGET:g}; a fit over {ctx.n_solve} meshes, "
            f"median of {run['repeat']} each; "
            f"mortar's {exp(ctx.fit_mort)}; wall time {exp(ctx.fit_wall)}, its fixed start-up costs weighing on small "
            f"meshes). One sparse direct linear solve of the same meshes grows like dofs^{exp(ctx.fit_lin)} (MUMPS and "
            f"CHOLMOD factorisations), and the contact solve costs {min(ratios):.1f} to {max(ratios):.1f} of them "
            f"at every size from 1e4 dofs")


def render_sweep_fixed_costs():
    """Mesh reading, set-up and output against the whole run on the largest mesh (gpts), and the target."""
    import bench_analysis
    import bench_targets
    big = full_sweep()[1].ref_sel[-1]
    return (f"mesh reading, set-up and output {100 * bench_analysis.fixed_cost_share(big):.1f} % of the run at "
            f"{big['dofs']:,} dofs (< {100 * bench_targets.FIXED_COST_TARGET:g} %)")


def render_sweep_search():
    """The contact search against an energy evaluation per call on the largest mesh (gpts)."""
    import bench_analysis
    import bench_sweep
    import bench_targets
    big = full_sweep()[1].ref_sel[-1]
    return (f"contact search {1e3 * big['search_time_per_call']:.3g} ms against "
            f"{1e3 * big['energy_time_per_call']:.3g} ms per energy evaluation at {big['dofs']:,} dofs "
            f"({bench_sweep.pct(bench_analysis.search_share(big))}; "
            f"< {100 * bench_targets.SEARCH_TARGET:g} %)")


def render_sweep_mortar_cost():
    """Mortar's solve time over gpts' at h = 0.06 and on the largest mesh, and the two formulations' Newton
    steps over the reference scene's meshes."""
    import bench_analysis
    rows, ctx, _ = full_sweep()
    pairs = bench_analysis.cost_ratio_pairs(rows)
    if not pairs:
        return "no pair of converged mortar and gpts runs in the sweep"
    where = lambda h, g: "h = 0.06" if h == 0.06 else f"{g['dofs']:,} dofs"  # noqa: E731
    steps = lambda sel: f"{min(r['iterations'] for r in sel)} to {max(r['iterations'] for r in sel)}"  # noqa: E731
    return (and_list([f"{m['solve_median'] / g['solve_median']:.2f} at {where(h, g)}"
                      for h, g, m in pairs])
            + f" in the sweep, mortar taking {steps(ctx.mort_sel)} Newton steps per mesh, gpts {steps(ctx.ref_sel)}")


def render_formulations_cost():
    """bench/formulations.csv (scripts/bench.py --formulations-cost) at each size: mortar's solve time over
    gpts', the two formulations' Newton steps, mortar's cost per step over gpts', and the shares of mortar's
    solve that the factorisations (SchurFactorK and the Newton linear algebra) and the contact terms take,
    beside gpts' contact share."""
    import bench_results
    by = {}
    for r in bench_results.read_formulations_cost(os.path.join(ROOT, "bench")):
        by.setdefault(float(r["h"]), {})[r["formulation"]] = r
    pairs = [(by[h]["gpts"], by[h]["mortar"]) for h in sorted(by, reverse=True) if {"gpts", "mortar"} <= set(by[h])]
    if not pairs:
        return "(no size with both formulations in bench/formulations.csv)"
    x = lambda r, k: float(r[k])  # noqa: E731
    step = lambda r: x(r, "solve_median") / x(r, "iterations")  # noqa: E731
    where = lambda g: "h = 0.06" if x(g, "h") == 0.06 else f"{int(g['dofs']):,} dofs"  # noqa: E731
    factor = lambda r: 100 * (x(r, "t_factor_k") + x(r, "t_newton_linear")) / x(r, "solve_stage_time")  # noqa: E731
    return (and_list([f"{x(m, 'solve_median') / x(g, 'solve_median'):.2f}" for g, m in pairs])
            + " in `bench/formulations.md` (`make bench-formulations`), which shows where the solve goes: mortar's"
            " Newton steps there " + ", ".join(f"{m['iterations']} against gpts' {g['iterations']}" for g, m in pairs)
            + ", at " + and_list([f"{step(m) / step(g):.2f}" for g, m in pairs]) + " times gpts' cost per step;"
            " the factorisations (the elastic stiffness once, the dense surface block per step) "
            + and_list([f"{factor(m):.0f} %" for g, m in pairs]) + " of mortar's solve and the contact terms "
            + and_list([f"{100 * x(m, 'contact_share'):.0f} % (gpts {100 * x(g, 'contact_share'):.0f} %)" for g, m in pairs])
            + ", at " + and_list([where(g) for g, m in pairs]))


def render_sweep_profile():
    """The profile's distance from the finest run of the same model, for mortar on every mesh of the
    reference scene, and its range for gpts from h = 0.06."""
    import bench_analysis
    _, ctx, _ = full_sweep()
    measured = [r for r in ctx.ref_sel + ctx.mort_sel
                if "profile_err" in r and not bench_analysis.on_profile_ref_mesh(r)]
    mort = sorted((r for r in measured if r["formulation"] == "mortar"), key=lambda r: -r["h"])
    gpts = [100 * r["profile_err"] for r in measured if r["formulation"] == "gpts" and r["h"] <= 0.06]
    if not (mort and gpts):
        return "(no profile distances of both formulations in the sweep)"
    return (f"(h = {mort[0]['profile_ref_h']:g} on hertz) is "
            f"{', '.join('%#.2g' % (100 * r['profile_err']) for r in mort)} % for mortar at h = {mort[0]['h']:g} "
            f"... {mort[-1]['h']:g}, and {min(gpts):.1f} to {max(gpts):.1f} % for gpts at every h from 0.06")


def render_sweep_cheapest():
    """The cheapest configuration within each error level of the profile's distance from its scene's finest
    run (k_p = 2e6), per formulation, as bench/full/RESULTS.md's table; and, for a cheapest run of a scene
    other than the uniform one, the uniform run that is as fine as its scene's reference and its distance."""
    import bench_analysis
    import bench_sweep
    rows = full_sweep()[0]
    parts, other = [], {}
    for form in ("mortar", "gpts"):
        best = bench_analysis.cheapest([r for r in rows if r["formulation"] == form], "profile_err",
                                       bench_analysis.ERROR_LEVELS, bench_analysis.off_profile_model)
        groups = []   # [[levels], run], levels of the same run joined
        for t, r in best:
            if groups and groups[-1][1] is r:
                groups[-1][0].append(t)
            else:
                groups.append([[t], r])
        text = []
        for levels, r in groups:
            run = "none" if r is None else (
                f"{r['scene']} h = {r['h']:g}"
                + (f" {r['strategy']}" if r["strategy"] != bench_sweep.REF_STRATEGY else "")
                + f" ({r['wall_median']:.3g} s)")
            text.append("within " + and_list([f"{100 * t:g}" for t in levels]) + f" % {run}")
            if r is not None and r["scene"] != "hertz":
                other.setdefault((r["scene"], r["profile_ref_h"]), set()).add(form)
        parts.append(f"{form} " + ", ".join(text))
    notes = []
    for (scene, ref_h), forms in sorted(other.items()):
        uni = [f"{bench_sweep.pct(u[0]['profile_err'])} ({f})" for f in ("mortar", "gpts") if f in forms
               for u in [bench_analysis.default_runs(rows, "hertz", bench_sweep.REF_KP, ref_h, f)] if u]
        notes.append(f"a {scene} run is measured against that scene's finest, h = {ref_h:g}, no finer than the "
                     f"uniform h = {ref_h:g} run, which is {and_list(uni)} from the uniform finest")
    return "; ".join(parts + notes)


def render_sweep_half():
    """The half model's contact force and solve time against the full model's at h = 0.06 (gpts)."""
    import bench_analysis
    import bench_sweep
    rows = full_sweep()[0]
    half = bench_analysis.default_runs(rows, "hertz-half", bench_sweep.REF_KP, 0.06)
    full = bench_analysis.default_runs(rows, "hertz", bench_sweep.REF_KP, 0.06)
    if not (half and full):
        return "at h = 0.06 (no pair of converged runs in the sweep)"
    return (f"at h = 0.06 ({bench_sweep.REF_FORMULATION}) P = {half[0]['P']:.6g} against {full[0]['P']:.6g}, solved in "
            f"{half[0]['solve_median']:.3g} s against {full[0]['solve_median']:.3g} s")


RENDER = {"scenes": render_scenes, "axisymmetric": render_axisymmetric, "rigid": render_rigid, "rigid-adequacy": render_rigid_adequacy, "rigid-free": render_rigid_free, "formulations": render_formulations,
          "solver": render_solver, "lmvm": render_lmvm,
          "speed": render_speed, "accuracy": render_accuracy, "oscillation": render_oscillation,
          "stress": render_stress, "stress-solvers": render_stress_solvers, "parallel": render_parallel, "parallel-stages": render_parallel_stages,
          "penalty": render_penalty, "claims": render_claims, "model": render_model,
          "squeeze": render_squeeze, "squeeze-cost": render_squeeze_cost,
          "friction": render_friction, "friction-cost": render_friction_cost, "friction-wider": render_friction_wider,
          "friction-getfem": render_friction_getfem}
# the phrases: figures inside a sentence of the README, each a line of text without its line breaks
PHRASES = {"claims-lmvm": render_claims_lmvm, "claims-parallel": render_claims_parallel,
           "solver-speed": render_solver_speed, "lmvm-ratio": render_lmvm_ratio, "lmvm-iterations": render_lmvm_iterations,
           "parallel-speedup": render_parallel_speedup, "speed-targets": render_speed_targets,
           "sweep-run": render_sweep_run, "sweep-targets": targets_met,
           "sweep-reference-solve": render_sweep_reference_solve, "sweep-linear-ratio": render_sweep_linear_ratio,
           "sweep-exponent": render_sweep_exponent, "sweep-fixed-costs": render_sweep_fixed_costs,
           "sweep-search": render_sweep_search, "sweep-mortar-cost": render_sweep_mortar_cost,
           "sweep-profile": render_sweep_profile, "sweep-cheapest": render_sweep_cheapest,
           "sweep-half": render_sweep_half, "formulations-cost": render_formulations_cost,
           "squeeze-cost-ratio": render_squeeze_cost_ratio, "friction-cost-ratio": render_friction_cost_ratio,
           "friction-getfem-phrase": render_friction_getfem_phrase, "friction-getfem-scene": render_friction_getfem_scene,
           "rigid-adequacy-phrase": render_rigid_adequacy_phrase, "ranks-agree": render_ranks_agree,
           "blas-speed": render_blas_speed, "solid3d-getfem": render_solid3d_getfem}


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


PROSE_WIDTH = 88   # the pages' prose lines


def wrap_phrase(text, i, j, new):
    """A phrase's new words (text[i:j] replaced) laid out as the page's prose:
    from where the phrase starts on its line, then on lines indented as the
    phrase's second line was, or else as the line it starts on continues (a
    list item's text), each line within PROSE_WIDTH where the words allow."""
    start = text.rfind("\n", 0, i) + 1
    old = text[i:j]
    if "\n" in old:
        indent = re.match(r"[ \t]*", old.split("\n", 1)[1]).group(0)
    else:
        m = re.match(r"([ \t]*)([-*] |\d+\. )?", text[start:i])
        indent = m.group(1) + " " * len(m.group(2) or "")
    lines, col = [[]], i - start
    for w in new.split():
        if lines[-1] and col + 1 + len(w) > PROSE_WIDTH:
            lines.append([])
            col = len(indent)
        col += len(w) + (1 if lines[-1] else 0)
        lines[-1].append(w)
    return ("\n" + indent).join(" ".join(ws) for ws in lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--update", action="store_true")
    ap.add_argument("--measure", choices=["scenes", "solver", "lmvm", "picture", "axisymmetric", "rigid", "rigid-free", "claims", "model",
                                          "squeeze", "squeeze-newton", "squeeze-picture", "friction", "friction-cost", "friction-getfem", "ranks"], action="append",
                    default=[])
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
    if "rigid" in args.measure:
        measure_rigid()
    if "rigid-free" in args.measure:
        measure_rigid_free()
    if "squeeze-newton" in args.measure:
        measure_squeeze_newton()
    if "claims" in args.measure:
        measure_claims()
    if "model" in args.measure:
        measure_model()
    if "squeeze" in args.measure:
        measure_squeeze()
    if "squeeze-picture" in args.measure:
        measure_squeeze_picture()
    if "friction" in args.measure:
        measure_friction()
    if "friction-cost" in args.measure:
        measure_friction_cost()
    if "friction-getfem" in args.measure:
        measure_friction_getfem()
    if "ranks" in args.measure:
        measure_ranks()
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
                text = text[:i] + (new if name in RENDER else wrap_phrase(text, i, j, new)) + text[j:]
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
