"""The rubber-squeeze scene (meshes/rubber-squeeze: a neo-Hookean disc,
nu = 0.45, squeezed by 30 % of its diameter between rigid plates, a
quarter on its symmetry planes) against independent answers, and the cost
of neo-Hookean bodies. Used by tests/test_squeeze.py and by
readme_figures.py --measure squeeze, which writes bench/squeeze/results.json,
the tables of docs/scenes.md and docs/img/rubber-squeeze.png from it.

- the force-squeeze curve (20 load steps, -load_path) on the meshes of
  H (3 meshes halving h, and h = 0.0125 as the finest), its energy
  against the reactions' work, and GetFEM's curve on the same meshes
  (bench/squeeze/getfem-h*.json, written by scripts/getfem_squeeze.py with
  the program's k_p: python3-getfem runs under /usr/bin/python3);
- the cost: the reference scene pushed by 0.01 (largest strain 1.4 %) with
  both bodies linear, both neo-Hookean, and both neo-Hookean with
  -tangent_at_rest, and the squeeze at 1 % of its push likewise,
  interleaved 3 times, median solve times; the squeeze by Newton in one
  solve, in 20 load steps and with -tangent_at_rest, and by L-BFGS
  (-tao_type lmvm; and with H0 without the contact's Hessian, as before
  -tangent_at_rest, which does not converge); the squeeze's rows on the
  scene's own mesh (scene_h(), the options file's).

    python3 scripts/squeeze_study.py            # measures and prints the tables
    python3 scripts/squeeze_study.py --getfem   # and first reruns GetFEM on the meshes of
                                                # GETFEM_H (about 4 minutes), with our k_p
"""
import glob
import json
import os
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OPTS = "meshes/rubber-squeeze/rubber-squeeze.opts"
SCENE = ["-options_file", OPTS]
PUSH = 0.3                      # the plate's travel: the quarter's half of the squeeze, 30 % of the diameter 2
H = (0.1, 0.05, 0.025, 0.0125)  # the curve's meshes (the last the finest, for the convergence)
PATH = ["-load_steps", "20", "-load_path"]
GETFEM_H = (0.1, 0.05, 0.025)   # GetFEM's meshes (h = 0.0125 would take it half an hour)
HERTZ_SMALL = ["-options_file", "meshes/hertz/hertz.opts", "-block_bc_push_values", "-0.01,0"]


def scene_h():
    """The disc's mesh size in the scene's options file (-disc_mesh_size):
    the mesh the scene runs on without -mesh_size."""
    from contactrun import options_file
    h = options_file(os.path.join(ROOT, OPTS)).get("disc_mesh_size")
    if h is None:
        raise SystemExit(f"{OPTS} gives no -disc_mesh_size")
    return float(h)


def path_arrays(summary):
    """(the plate's travel d, the plate's force (down, positive), the
    energy) at each recorded state of a -load_path run."""
    p = summary["load_path"]
    d = PUSH * np.array([q["load"] for q in p])
    F = -np.array([q["reactions"]["plate:contact"][1] for q in p])
    E = np.array([q["energy"] for q in p])
    return d, F, E


def trapezoid_work(d, F):
    """The reactions' work along the path, by the trapezoid rule."""
    return float(np.sum(0.5 * (F[1:] + F[:-1]) * np.diff(d)))


def energy_balance(summary):
    """(relative difference of the trapezoid's work over every increment
    from the stored energy, the same over every other increment, and the
    Richardson extrapolation of the two's): the trapezoid's error is
    O(step^2), so the extrapolation shows what is left once it is removed."""
    d, F, E = path_arrays(summary)
    w1, w2 = trapezoid_work(d, F), trapezoid_work(d[::2], F[::2])
    return w1 / E[-1] - 1, w2 / E[-1] - 1, (4 * w1 - w2) / 3 / E[-1] - 1


def getfem_results():
    """{h: GetFEM's run} of bench/squeeze/getfem-h*.json."""
    out = {}
    for f in glob.glob(os.path.join(ROOT, "bench", "squeeze", "getfem-h*.json")):
        with open(f) as fp:
            out[float(os.path.basename(f)[len("getfem-h"):-len(".json")])] = json.load(fp)
    return out


def measure_curves(tmp):
    """Each mesh of H with -load_path: its dofs, Newton iterations, solve
    time, k_p, the path (d, F, E), the energy balance and its mesh."""
    from contactrun import mesh_only, run_checked
    rows = []
    for h in H:
        args = SCENE + ["-mesh_size", repr(h)] + PATH
        mesh_only(args[:2] + args[2:4])
        s = run_checked(args, tmp, f"h{h}").summary
        d, F, E = path_arrays(s)
        rows.append(dict(h=h, command="bin/contact " + " ".join(args), dofs=s["dofs"], iterations=s["iterations"],
                         solve=s["time"]["solve"], penalty=s["contact"]["squeeze"]["penalty"],
                         strain=s["bodies"]["disc"]["max_green_lagrange_strain"], d=d.tolist(), F=F.tolist(),
                         E=E.tolist(), balance=energy_balance(s), mesh=s["bodies"]["disc"]["mesh"]))
    return rows


def measure_getfem(curves):
    """GetFEM on each mesh of GETFEM_H (scripts/getfem_squeeze.py, by the
    system's python3, which has python3-getfem) with that run's k_p, into
    bench/squeeze/getfem-h<h>.json."""
    import subprocess
    for r in curves:
        if r["h"] in GETFEM_H:
            subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "getfem_squeeze.py"), "--mesh", r["mesh"],
                            "--penalty", repr(r["penalty"]), "-o",
                            os.path.join(ROOT, "bench", "squeeze", f"getfem-h{r['h']:g}.json")], cwd=ROOT, check=True)


def timed(cases, tmp, repeat=3):
    """{label: last summary with the median solve time} of each case, run
    in turn repeat times (interleaved: the machine's load falls on all)."""
    from contactrun import median, mesh_only, run_case
    for _, args in cases:
        mesh_only(args[:2])
    runs = {label: [] for label, _ in cases}
    for _ in range(repeat):
        for label, args in cases:
            runs[label].append(run_case(args, tmp, "t", h5=False).summary)
    return {label: dict(rs[-1], solve_median=median([r["time"]["solve"] for r in rs])) for label, rs in runs.items()}


def cost_row(label, args, s):
    return dict(run=label, command="bin/contact " + " ".join(args), dofs=s["dofs"], converged=True,
                reason=s["tao_reason"], iterations=s["iterations"], stages=s["stages"], cutbacks=s["load_cutbacks"],
                solve=s["solve_median"], P=s["contact_force"])


def failed_row(label, args, run):
    """A run that did not converge (no summary): its TAO line, how far
    its load got and the whole run's wall time."""
    import re
    from contactrun import parse_tao_line
    tao = parse_tao_line(run.stdout) or {}
    m = re.search(r"solved up to ([0-9.eE+-]+) of it", run.stderr + run.stdout)
    stages = re.search(r"\((\d+) (?:of \d+ )?stages; the load cut back (\d+) times", run.stdout)
    return dict(run=label, command="bin/contact " + " ".join(args), converged=False, reason=tao.get("reason"),
                iterations=tao.get("iterations"), evals=tao.get("evals"), stages=int(stages.group(1)) if stages else 1,
                cutbacks=int(stages.group(2)) if stages else 0, load=float(m.group(1)) if m else None, wall=run.wall)


LMVM = [("rubber-squeeze, L-BFGS (lmvm)", SCENE + ["-tao_type", "lmvm"]),
        ("rubber-squeeze, L-BFGS (lmvm), 20 load steps", SCENE + ["-tao_type", "lmvm", "-load_steps", "20"]),
        ("rubber-squeeze, L-BFGS (lmvm), H0 without the contact (-tangent_at_rest 0)",
         SCENE + ["-tao_type", "lmvm", "-tangent_at_rest", "0"]),
        ("rubber-squeeze, L-BFGS (lmvm), H0 without the contact, Armijo's line search",
         SCENE + ["-tao_type", "lmvm", "-tangent_at_rest", "0", "-tao_ls_type", "armijo"])]
NEO_HERTZ = HERTZ_SMALL + ["-indenter_material", "neohookean", "-block_material", "neohookean"]
SQUEEZE_SMALL = SCENE + ["-plate_bc_contact_values", "0,-0.003"]


NEWTON_COST = [("hertz pushed by 0.01, linear", HERTZ_SMALL),
               ("hertz pushed by 0.01, neo-Hookean", NEO_HERTZ),
               ("hertz pushed by 0.01, neo-Hookean, -tangent_at_rest", NEO_HERTZ + ["-tangent_at_rest"]),
               ("hertz pushed by 0.01, neo-Hookean, -tangent_at_rest 0", NEO_HERTZ + ["-tangent_at_rest", "0"]),
               ("rubber-squeeze at 1 % of its push, linear", SQUEEZE_SMALL + ["-disc_material", "linear"]),
               ("rubber-squeeze at 1 % of its push, neo-Hookean", SQUEEZE_SMALL),
               ("rubber-squeeze at 1 % of its push, neo-Hookean, -tangent_at_rest", SQUEEZE_SMALL + ["-tangent_at_rest"]),
               ("rubber-squeeze at 1 % of its push, neo-Hookean, -tangent_at_rest 0", SQUEEZE_SMALL + ["-tangent_at_rest", "0"]),
               ("rubber-squeeze, Newton", SCENE),
               ("rubber-squeeze, Newton, 20 load steps", SCENE + ["-load_steps", "20"]),
               ("rubber-squeeze, Newton, -tangent_at_rest", SCENE + ["-tangent_at_rest"]),
               ("rubber-squeeze, Newton, -tangent_at_rest 0", SCENE + ["-tangent_at_rest", "0"])]


def measure_newton_cost(tmp):
    """The cost table's Newton rows, timed, interleaved (the default:
    the stiffness at rest while it converges fast, then the tangent;
    -tangent_at_rest: the stiffness at rest throughout; 0: the tangent)."""
    res = timed(NEWTON_COST, tmp)
    return [cost_row(label, args, res[label]) for label, args in NEWTON_COST]


def measure_lmvm_cost(tmp):
    """L-BFGS's rows, once each (some do not converge)."""
    from contactrun import run_case
    rows = []
    for label, args in LMVM:
        r = run_case(args, tmp, "l", h5=False, timeout=600)
        rows.append(cost_row(label, args, dict(r.summary, solve_median=r.summary["time"]["solve"])) if r.summary
                    else failed_row(label, args, r))
    return rows


def measure_cost(tmp):
    """The cost table's rows (see the module's header)."""
    return measure_newton_cost(tmp) + measure_lmvm_cost(tmp)


def curve_table(rows, gf):
    """The curve on each mesh: its distance from the finest mesh's and from
    GetFEM's on the same mesh (the largest over the 20 steps, relative to
    the full squeeze's force), the energy balance."""
    fine = np.array(rows[-1]["F"])
    out = ["| h | dofs | Newton iterations (20 steps) | solve | F at 30 % (whole disc) | curve vs h = "
           f"{rows[-1]['h']:g} | curve vs GetFEM, same mesh | energy vs work: trapezoid, 20 steps / 10 steps / extrapolated |",
           "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        F = np.array(r["F"])
        vs_fine = "" if r is rows[-1] else f"{np.max(np.abs(F - fine)) / fine[-1]:.1e}"
        g = gf.get(r["h"])
        vs_gf = "(not run)"
        if g:
            Fg = np.array([s["force"] for s in g["steps"]])
            vs_gf = f"{np.max(np.abs(F - Fg)) / F[-1]:.1e} (GetFEM {g['time']:.0f} s)"
        b = r["balance"]
        out.append(f"| {r['h']:g} | {r['dofs']:,} | {r['iterations']} | {r['solve']:.2f} s | {2 * F[-1]:.6f} | {vs_fine} | "
                   f"{vs_gf} | {b[0]:+.1e} / {b[1]:+.1e} / {b[2]:+.1e} |")
    return "\n".join(out) + "\n"


def cost_table(rows):
    out = ["| run | converged | iterations | solve | P |", "|---|---|---|---|---|"]
    for r in rows:
        cut = f"{r['cutbacks']} cutback" + ("" if r["cutbacks"] == 1 else "s")
        its = f"{r['iterations']}" + (f" ({r['stages']} stages, {cut})" if r["stages"] > 1 else "")
        if r["converged"]:
            out.append(f"| {r['run']} | yes | {its} | {r['solve']:.3f} s | {r['P']:.6g} |")
        else:
            out.append(f"| {r['run']} | no: {r['reason']}, load solved up to {r['load']:g} | {its}, {r['evals']} energy "
                       f"evaluations | {r['wall']:.0f} s (whole run) | |")
    return "\n".join(out) + "\n"


def cost_ratio(rows, scene, variant=""):
    """The neo-Hookean solve's time (with variant, e.g. ", -tangent_at_rest")
    over the linear one's, on scene's small-strain pair."""
    lin, nh = ([r for r in rows if r["run"].startswith(scene) and r["run"].endswith(m)][0]
               for m in (", linear", ", neo-Hookean" + variant))
    return nh["solve"] / lin["solve"]


def draw(rows, gf, h5path, png):
    """The force-squeeze curves (each mesh, GetFEM's), inset the distance of
    each from the finest mesh's, and the deformed disc (h5path: a run of
    the scene on its own mesh, mirrored to the whole disc, von Mises), side
    by side."""
    import h5py
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.8), gridspec_kw={"width_ratios": [1, 1.15]})
    fine = np.array(rows[-1]["F"])
    inset = ax.inset_axes([0.1, 0.45, 0.42, 0.42])
    for r in rows:
        line, = ax.plot(r["d"], 2 * np.array(r["F"]), "-", lw=1, label=f"contact, h = {r['h']:g}")
        if r is not rows[-1]:
            inset.semilogy(r["d"][1:], np.abs(np.array(r["F"]) - fine)[1:] / fine[-1], "-", color=line.get_color(), lw=1)
    for h, g in sorted(gf.items()):
        ax.plot([s["squeeze"] for s in g["steps"]], [2 * s["force"] for s in g["steps"]], "o", ms=4, mfc="none",
                label=f"GetFEM, h = {h:g}")
    inset.set_title(f"|F - F(h = {rows[-1]['h']:g})| / F(30 %)", fontsize=7)
    inset.tick_params(labelsize=7)
    ax.set_xlabel("squeeze / diameter")
    ax.set_ylabel("force per unit thickness / (E R)")
    ax.set_title("neo-Hookean disc, nu = 0.45, between rigid plates", fontsize=10)
    ax.legend(fontsize=7, loc="lower right")
    ax.grid(alpha=0.3)
    with h5py.File(h5path) as f:
        X, U = f["bodies/disc/geometry"][...], f["bodies/disc/displacement"][...]
        cells, vm = f["bodies/disc/topology"][...], f["bodies/disc/von_mises"][...]
    x = X + U
    polys, vals = [], []
    for sx in (1, -1):
        for sy in (1, -1):
            for c in cells:   # Tri6: corners 0-2, mid-edges 3-5 (0-1, 1-2, 2-0)
                polys.append(x[[c[0], c[3], c[1], c[4], c[2], c[5]]] * [sx, sy])
                vals.append(vm[c[:3]].mean())
    # the elements' edges thinner as the mesh is finer (0.15 pt at h = 0.05), so that the colours show through
    pc = PolyCollection(polys, array=np.array(vals), cmap="viridis", edgecolors="k", linewidths=3 * scene_h())
    bx.add_collection(pc)
    for y in (1 - PUSH, PUSH - 1):
        bx.plot([-1.5, 1.5], [y, y], "r-", lw=2)
    bx.set_xlim(-1.5, 1.5)
    bx.set_ylim(-1.05, 1.05)
    bx.set_aspect("equal")
    bx.set_title(f"squeezed by 30 % (h = {scene_h():g}; the quarter mirrored)", fontsize=10)
    fig.colorbar(pc, ax=bx, label="von Mises (Cauchy) / E", shrink=0.8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def redraw(curves, png):
    """The figure from the measured curves, the deformed disc from a run of
    the scene on its own mesh (scene_h(), the options file's)."""
    from contactrun import run_checked
    with tempfile.TemporaryDirectory() as tmp:
        draw(curves, getfem_results(), run_checked(SCENE, tmp, "scene").h5, png)


def measure(png, getfem=False):
    """Everything the tables and the figure need, the figure drawn into png
    (getfem: GetFEM's runs first redone)."""
    with tempfile.TemporaryDirectory() as tmp:
        curves = measure_curves(tmp)
        if getfem:
            measure_getfem(curves)
        cost = measure_cost(tmp)
    redraw(curves, png)
    return {"curves": curves, "cost": cost}


if __name__ == "__main__":
    import sys
    sys.path.insert(0, os.path.join(ROOT, "scripts"))
    res = measure(os.path.join(tempfile.gettempdir(), "rubber-squeeze.png"), "--getfem" in sys.argv)
    print(curve_table(res["curves"], getfem_results()))
    print(cost_table(res["cost"]))
