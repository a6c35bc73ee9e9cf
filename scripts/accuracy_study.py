"""How honest and how cheap `-accuracy TOL` is (bench/accuracy/RESULTS.md).

For each scene (the reference scene `hertz`, `twodiscs`, and a scene written
here that is not in the repository: other radius, moduli and push), the
refinement steps are run one by one (`-accuracy_max_steps m` stops after step
m - 1 and writes its answer). For each target TOL the answer is the first
step k whose estimate is below TOL; its true error is measured against step
k + 2 (two refinements more): the larger of the pressure profile's relative L2
distance (profile_metrics.l2_distance) and the contact force's relative
difference, as the program's own estimate. Then the wall time of the
`-accuracy TOL` run against that of one run on its final meshes alone
(`-<body>_mesh`), both with the meshes already generated, median of
--repeat runs made interleaved.

Cost against the sweep (`make bench`, bench/full/RESULTS.md): the cheapest
uniform or graded configuration there that reaches 1 % (its pressure profile
within 1 % of the finest uniform run, h = 0.0065) is run again here,
interleaved with `-accuracy 0.01` on the same scene. And the curve that
bench.py draws in its error-against-time plot: `-accuracy TOL` on the
reference scene for TOL = 5, 2, 1, 0.5 %, each answer's profile measured as
the sweep measures its runs, against the uniform run at h = 0.0065.

    python3 scripts/accuracy_study.py [--out bench/accuracy] [--repeat 3]
"""
import argparse
import json
import os
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import profile_metrics as pm  # noqa: E402
from contactrun import copy_program, median, run_checked  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.join(ROOT, "bin", "contact")  # main() runs a copy: a rebuild meanwhile does not mix versions
TOLS = [0.05, 0.02, 0.01]
CURVE_TOLS = [0.05, 0.02, 0.01, 0.005]
REF_H = 0.0065  # the sweep's finest uniform mesh: its profile reference

# Not in the repository: a disc of radius 0.6 (E = 2000, nu = 0.25) on a block
# of E = 700, nu = 0.35, pushed by 0.06; the same .geo files, other parameters.
OTHER = """-scene other
-bodies indenter,block
-indenter_geo {root}/meshes/hertz/indenter.geo
-indenter_geo_params R=0.6,xc=-0.6,yc=0,xclamp=-1.1,xcontact=-0.3
-indenter_mesh_size 0.08
-indenter_E 2000
-indenter_nu 0.25
-indenter_bc clamp
-indenter_bc_clamp_components x,y
-indenter_bc_clamp_values 0,0
-block_geo {root}/meshes/hertz/block.geo
-block_geo_params x0=0,W=1,H=2
-block_mesh_size 0.1
-block_E 700
-block_nu 0.35
-block_bc push
-block_bc_push_components x,y
-block_bc_push_values -0.06,0
-contact_pairs interface
-contact_interface_surfaces indenter:contact,block:contact
-contact_penalty 2e6
-contact_interface_hertz_radii 0.6,0
"""


def run(args, tmp, name, ok=(0,)):
    """contactrun.run_checked on the study's copy of the program, -quiet;
    returns (summary, HDF5 path, wall seconds)."""
    res = run_checked(args + ["-quiet"], tmp, name, ok=ok, binary=BIN)
    return res.summary, res.h5, res.wall


def true_error(h5, ref_h5, summ, ref_summ):
    """The program's measure between two answers: the larger of the profiles'
    relative L2 distance and the force's relative difference."""
    prof, ref = pm.profiles(h5)[0], pm.profiles(ref_h5)[0]
    d = max(pm.l2_distance(prof[k], ref[k]) for k in prof if k in ref)
    f = abs(summ["contact_force"] - ref_summ["contact_force"]) / abs(ref_summ["contact_force"])
    return max(d, f), d, f


def study(scene, base, tmp, repeat, maxsteps=9):
    steps = {}  # step k -> (summary, h5)
    k_needed = None
    for m in range(3, maxsteps + 1):
        summ, h5, _ = run(base + ["-accuracy", "1e-9", "-accuracy_max_steps", str(m)], tmp, f"{scene}-step{m - 1}", ok=(2,))
        steps[m - 1] = (summ, h5)
        est = [s["error_estimate"] for s in summ["adapt_steps"]]
        if k_needed is None and m - 1 >= 2 and est[-1] is not None and est[-1] <= min(TOLS):
            k_needed = m - 1
        if k_needed is not None and m - 1 >= k_needed + 2:
            break
    est = [s["error_estimate"] for s in steps[max(steps)][0]["adapt_steps"]]
    rows = []
    for tol in TOLS:
        k = next((i for i in range(2, len(est)) if est[i] is not None and est[i] <= tol), None)
        if k is None or k + 2 not in steps:
            rows.append({"tol": tol, "reached": False})
            continue
        summ, h5 = steps[k]
        err, d, f = true_error(h5, steps[k + 2][1], summ, steps[k + 2][0])
        meshes = [b["mesh"] for b in summ["bodies"].values()]
        alone = base + sum(([f"-{name}_mesh", b["mesh"]] for name, b in summ["bodies"].items()), [])
        t_acc, t_alone = [], []
        for _ in range(repeat):  # interleaved
            t_acc.append(run(base + ["-accuracy", str(tol)], tmp, f"{scene}-tol{tol}")[2])
            t_alone.append(run(alone, tmp, f"{scene}-alone{tol}")[2])
        rows.append({"tol": tol, "reached": True, "step": k, "dofs": summ["dofs"], "estimate": est[k], "true": err,
                     "true_profile": d, "true_force": f, "ratio": est[k] / err if err > 0 else float("inf"),
                     "wall_accuracy": median(t_acc), "wall_alone": median(t_alone),
                     "steps_dofs": [s["dofs"] for s in summ["adapt_steps"]], "meshes": meshes})
    return {"scene": scene, "estimates": est, "rows": rows}


def cheapest_uniform():
    """The sweep's cheapest configuration reaching 1 % on the pressure profile
    (formulation, scene, h, its wall time there), from bench/full/RESULTS.md."""
    import re
    path = os.path.join(ROOT, "bench", "full", "RESULTS.md")
    best = None
    for line in open(path):
        m = re.match(r"\| (\w+) \| 1 % \| (\S+) h=([0-9.e-]+) (\w+) newton k_p=2e\+06 tol=1e-08 \| (\d+) \| ([0-9.]+) \|", line)
        if m and (best is None or float(m.group(6)) < best["wall_sweep"]):
            best = {"formulation": m.group(1), "scene": m.group(2), "h": float(m.group(3)), "dofs": int(m.group(5)),
                    "wall_sweep": float(m.group(6))}
        if line.startswith("**pressure profile: L2 error against Hertz"):
            break
    return best


def curve(base, tmp, repeat):
    """-accuracy TOL on the reference scene against the sweep's reference run."""
    ref, ref_h5, _ = run(base + ["-mesh_size", str(REF_H)], tmp, "curve-ref")
    rprof = pm.profiles(ref_h5)[0]
    pts = []
    for tol in CURVE_TOLS:
        walls = []
        for r in range(repeat + 1):  # the first run meshes: not timed
            summ, h5, wall = run(base + ["-accuracy", str(tol)], tmp, f"curve{tol}")
            if r:
                walls.append(wall)
        prof = pm.profiles(h5)[0]
        d = [pm.l2_distance(prof[k], rprof[k]) for k in prof if k in rprof]
        pts.append({"tol": tol, "dofs": summ["dofs"], "steps": len(summ["adapt_steps"]), "estimate": summ["error_estimate"],
                    "wall": median(walls), "profile_err": sum(d) / len(d),
                    "P_err": abs(summ["contact_force"] - ref["contact_force"]) / ref["contact_force"]})
    return {"ref_h": REF_H, "ref_dofs": ref["dofs"], "points": pts}


def warm_start(base, tmp, repeat, tol=0.005):
    """-accuracy TOL from the last step's answer and from rest, interleaved."""
    out = {}
    for warm in ("1", "0"):
        run(base + ["-accuracy", str(tol), "-accuracy_warm_start", warm], tmp, "warm-mesh")
    walls = {"1": [], "0": []}
    for _ in range(repeat):
        for warm in ("1", "0"):
            summ, _, wall = run(base + ["-accuracy", str(tol), "-accuracy_warm_start", warm], tmp, f"warm{warm}")
            walls[warm].append(wall)
            out[warm] = {"iterations": [s["iterations"] for s in summ["adapt_steps"]],
                         "solve": sum(s["solve_time"] for s in summ["adapt_steps"]), "P": summ["contact_force"],
                         "pmax": summ["fem_pmax"]}
    for warm in ("1", "0"):
        out[warm]["wall"] = median(walls[warm])
    out["tol"] = tol
    out["answer_change"] = max(abs(out["1"]["P"] / out["0"]["P"] - 1), abs(out["1"]["pmax"] / out["0"]["pmax"] - 1))
    return out


def against_sweep(tmp, repeat):
    """-accuracy 0.01 against the sweep's cheapest configuration reaching 1 %, interleaved."""
    best = cheapest_uniform()
    if not best:
        return None
    args = ["-options_file", f"meshes/{best['scene']}/{best['scene']}.opts", "-contact_formulation", best["formulation"]]
    run(args + ["-accuracy", "0.01"], tmp, "sweep-acc-warm")
    run(args + ["-mesh_size", str(best["h"])], tmp, "sweep-uni-warm")
    ta, tu = [], []
    for _ in range(repeat):
        ta.append(run(args + ["-accuracy", "0.01"], tmp, "sweep-acc")[2])
        tu.append(run(args + ["-mesh_size", str(best["h"])], tmp, "sweep-uni")[2])
    best.update({"wall_accuracy": median(ta), "wall_uniform": median(tu)})
    return best


def tables(out):
    """The tables of RESULTS.md (and docs/solver.md's), from results.json."""
    res, sweep, cur, repeat = out["scenes"], out["sweep"], out["curve"], out["repeat"]
    lines = ["*true error*: against the answer two refinement steps further (the larger of the pressure profile's "
             "relative L2 distance and the contact force's relative difference, the program's own measure). "
             "*wall*: whole-process wall time, meshes already generated (cached), median of the repeats, runs interleaved; "
             "*alone*: one run on the final step's meshes (`-<body>_mesh`).", "",
             "| scene | TOL | steps | dofs per step | estimate | true error | estimate / true | true / TOL | wall, -accuracy [s] | wall, final meshes alone [s] | ratio |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in res:
        for row in r["rows"]:
            if not row["reached"]:
                lines.append(f"| {r['scene']} | {100 * row['tol']:g} % | not reached | | | | | | | | |")
                continue
            lines.append(f"| {r['scene']} | {100 * row['tol']:g} % | {row['step'] + 1} | {', '.join(map(str, row['steps_dofs']))} | "
                         f"{100 * row['estimate']:.3g} % | {100 * row['true']:.3g} % | {row['ratio']:.2f} | {row['true'] / row['tol']:.2f} | "
                         f"{row['wall_accuracy']:.2f} | {row['wall_alone']:.2f} | {row['wall_accuracy'] / row['wall_alone']:.2f} |")
    if sweep:
        lines += ["", "Against the sweep's cheapest configuration reaching 1 % (bench/full/RESULTS.md: "
                  f"{sweep['scene']} h = {sweep['h']:g}, {sweep['formulation']}, {sweep['dofs']} dofs, wall {sweep['wall_sweep']:g} s there), "
                  "run again here interleaved with `-accuracy 0.01` on the same scene, meshes already generated:", "",
                  "| run | wall [s] |", "|---|---|",
                  f"| uniform h = {sweep['h']:g} | {sweep['wall_uniform']:.2f} |",
                  f"| -accuracy 0.01 | {sweep['wall_accuracy']:.2f} |",
                  f"| ratio | {sweep['wall_accuracy'] / sweep['wall_uniform']:.2f} |"]
    lines += ["", f"The curve in bench.py's error-against-time plot (reference scene, profile distance from the uniform run at "
              f"h = {cur['ref_h']:g}, {cur['ref_dofs']} dofs, as the sweep measures its runs; wall: median of {repeat} after one that meshes):", "",
              "| TOL | steps | dofs | estimate | profile distance from h = %g | force vs h = %g | wall [s] |" % (cur["ref_h"], cur["ref_h"]),
              "|---|---|---|---|---|---|---|"]
    for p in cur["points"]:
        lines.append(f"| {100 * p['tol']:g} % | {p['steps']} | {p['dofs']} | {100 * p['estimate']:.3g} % | {100 * p['profile_err']:.3g} % | "
                     f"{100 * p['P_err']:.3g} % | {p['wall']:.2f} |")
    w = out.get("warm")
    if w:
        lines += ["", f"Warm start (reference scene, `-accuracy {w['tol']:g}`, with and without `-accuracy_warm_start`, "
                  f"interleaved, wall: median of {repeat}; the answers differ by {w['answer_change']:.1e} relative in P and p_max):", "",
                  "| first iterate | Newton iterations per step | solve time, all steps [s] | wall [s] |", "|---|---|---|---|"]
        for k, name in (("0", "rest"), ("1", "last step's answer")):
            lines.append(f"| {name} | {', '.join(map(str, w[k]['iterations']))} | {w[k]['solve']:.2f} | {w[k]['wall']:.2f} |")
    return "\n".join(lines) + "\n"


def write_results(out, path):
    lines = ["# `-accuracy TOL`: its estimate against the truth, and its cost", "",
             f"Written by `python3 scripts/accuracy_study.py --repeat {out['repeat']}` in {out['elapsed']:.0f} s "
             f"({out['date']}), formulation {out['formulation']}, one rank.", "", tables(out)]
    with open(path, "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "accuracy"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--formulation", default="mortar")
    ap.add_argument("--report-only", action="store_true", help="rewrite RESULTS.md from <out>/results.json")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.report_only:
        with open(os.path.join(args.out, "results.json")) as f:
            write_results(json.load(f), os.path.join(args.out, "RESULTS.md"))
        return
    t0 = time.time()
    global BIN
    with tempfile.TemporaryDirectory() as tmp:
        BIN = copy_program(tmp)
        other = os.path.join(tmp, "other.opts")
        with open(other, "w") as f:
            f.write(OTHER.format(root=ROOT))
        form = ["-contact_formulation", args.formulation]
        scenes = {"hertz": ["-options_file", "meshes/hertz/hertz.opts"],
                  "twodiscs": ["-options_file", "meshes/twodiscs/twodiscs.opts"],
                  "other": ["-options_file", other, "-mesh_dir", os.path.join(tmp, "meshes")]}
        res = [study(s, b + form, tmp, args.repeat) for s, b in scenes.items()]
        sweep = against_sweep(tmp, args.repeat) if args.formulation == "mortar" else None
        cur = curve(scenes["hertz"] + form, tmp, args.repeat)
        warm = warm_start(scenes["hertz"] + form, tmp, args.repeat)
    out = {"formulation": args.formulation, "repeat": args.repeat, "elapsed": time.time() - t0,
           "date": time.strftime("%Y-%m-%d %H:%M"), "scenes": res, "sweep": sweep, "curve": cur, "warm": warm}
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump(out, f, indent=1)
    write_results(out, os.path.join(args.out, "RESULTS.md"))


if __name__ == "__main__":
    main()
