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

    python3 scripts/accuracy_study.py [--out bench/accuracy] [--repeat 3]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import profile_metrics as pm  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
TOLS = [0.05, 0.02, 0.01]

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
    """Runs bin/contact; returns (summary, HDF5 path, wall seconds)."""
    h5, js = os.path.join(tmp, name + ".h5"), os.path.join(tmp, name + ".json")
    cmd = [os.path.join(ROOT, "bin", "contact")] + args + ["-output", h5, "-summary", js, "-quiet"]
    t0 = time.perf_counter()
    p = subprocess.run(cmd, cwd=ROOT, env=ENV, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode not in ok:
        raise SystemExit(f"{' '.join(cmd)} failed ({p.returncode}):\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    with open(js) as f:
        return json.load(f), h5, wall


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
                     "wall_accuracy": statistics.median(t_acc), "wall_alone": statistics.median(t_alone),
                     "steps_dofs": [s["dofs"] for s in summ["adapt_steps"]], "meshes": meshes})
    return {"scene": scene, "estimates": est, "rows": rows}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "accuracy"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--formulation", default="mortar")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    t0 = time.time()
    with tempfile.TemporaryDirectory() as tmp:
        other = os.path.join(tmp, "other.opts")
        with open(other, "w") as f:
            f.write(OTHER.format(root=ROOT))
        form = ["-contact_formulation", args.formulation]
        scenes = {"hertz": ["-options_file", "meshes/hertz/hertz.opts"],
                  "twodiscs": ["-options_file", "meshes/twodiscs/twodiscs.opts"],
                  "other": ["-options_file", other, "-mesh_dir", os.path.join(tmp, "meshes")]}
        res = [study(s, b + form, tmp, args.repeat) for s, b in scenes.items()]
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump(res, f, indent=1)
    lines = ["# `-accuracy TOL`: its estimate against the truth, and its cost", "",
             f"Written by `python3 scripts/accuracy_study.py --repeat {args.repeat}` in {time.time() - t0:.0f} s "
             f"({time.strftime('%Y-%m-%d %H:%M')}), formulation {args.formulation}, one rank.", "",
             "*true error*: against the answer two refinement steps further (the larger of the pressure profile's "
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
    with open(os.path.join(args.out, "RESULTS.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
