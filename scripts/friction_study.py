"""Coulomb friction (src/contact/friction.c) against its analytical references
on meshes/cattaneo, and its cost in Newton iterations against the same
increments without friction. Used by readme_figures.py --measure friction
and --measure friction-cost, which write bench/friction/results.json and the
tables of README.md (friction) and docs/scenes.md (friction-cost) from it.

The references, plane strain, elastically similar bodies (docs/scenes.md#friction):
Cattaneo-Mindlin under the normal force P then the tangential Q < mu P,
c/a = sqrt(1 - Q/(mu P)) and the shear

    q_C(x; c) = mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)]   (the second term for |x| < c only);

Mindlin-Deresiewicz, Q brought back from Q* to Q: c'/a = sqrt(1 - (Q* - Q)/(2 mu P)),
q = q_C(x; c) - 2 q_C(x; c'). Each curve is drawn with the computed a (the
pressure's second moment, a_moment), p0 = 2 P / (pi a) and x from the
pressure's centre; the shear profile's distance from it is relative L2 over
the slave's nodes (weights A_j, node_weight) within |x| < a or in contact:
shear_l2, the measure tests/test_friction.py's load-steps test states.

Iterations per increment are read from the program's -info lines of its
staging (a load increment's penalty stages summed, its friction's fixed
point solves counted); every run here is given -load_path, so that each
increment stops at the final tolerance with friction or without (with
friction every increment does anyway).

    python3 scripts/friction_study.py [--cost]    # measures and prints the table(s)
"""
import math
import os
import re
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))

SCENE = "meshes/cattaneo/cattaneo.opts"
CATTANEO = ["-options_file", SCENE]
HERTZ = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.1"]
SPHERE = ["-options_file", "meshes/sphere/sphere.opts"]


def scene_option(name):
    """The value of -name in the scene's options file."""
    from contactrun import options_file
    return options_file(os.path.join(ROOT, SCENE))[name]


MU = float(scene_option("contact_interface_friction"))     # the scene's friction
P, Q = (float(scene_option("disc_bc_clamp_values").split(",")[k]) for k in (0, -1))   # normal and tangential force
PAIR = "interface"
SLAVE = "contact/interface/disc_contact"
RATIOS = (0.2, 0.5, 0.8)   # Q / (mu P)
QSTAR = 0.6                # Mindlin-Deresiewicz: Q* / (mu P), then back to 0
STEPS = (1, 8)             # -load_steps
HC = (0.0075, 0.00375, 0.001875)   # the contact edges' size of the refinement rows (the scene's is the middle one)
HERTZ_SLIDE = 0.08         # the hertz scene's block moved along the contact in a second stage (Q/(mu P) about 0.4)
INFO = ["-info", ":tao", "-load_path"]
STAGE_LINE = re.compile(r"stage \d+: load (\S+), penalty factor (\S+): (\S+) after (\d+) iterations")
FIXED_POINT = re.compile(r"fixed point (\d+): ")


def cattaneo_shear(x, a, p0, c):
    """Cattaneo-Mindlin's shear q_C(x; c) (0 outside |x| < a)."""
    outer = np.sqrt(np.clip(1 - x**2 / a**2, 0, None))
    inner = np.where(np.abs(x) < c, c / a * np.sqrt(np.clip(1 - x**2 / c**2, 0, None)), 0)
    return MU * p0 * (outer - inner)


def reference_shear(x, a, p0, ratio, unload=None):
    """Mindlin's shear at Q/(mu P) = ratio, or, with unload = Q/(mu P) at the
    end, Mindlin-Deresiewicz's after Q was brought back from ratio to it."""
    q = cattaneo_shear(x, a, p0, a * math.sqrt(1 - ratio))
    if unload is None:
        return q
    return q - 2 * cattaneo_shear(x, a, p0, a * math.sqrt(1 - (ratio - unload) / 2))


def shear_l2(h5, summary, ratio, unload=None, force=P, surface=0, sign=1.0):
    """The slave's nodal shear's relative L2 distance from the reference
    curve (reference_shear), drawn with the computed a (a_moment), p0 =
    2 P / (pi a) and x from the pressure's centre, over the nodes within
    |x| < a or in contact, weights A_j. surface: the pair's surface that is
    the slave (its index in the summary: 0 the disc's, 1 the slab's); sign:
    -1 where that surface's shear is the other body's (the slab's)."""
    import h5py
    surf = summary["contact"][PAIR]["surfaces"][surface]
    a = surf["a_moment"]
    with h5py.File(h5, "r") as f:
        g = f[f"contact/{PAIR}/{surf['body']}_{surf['group']}"]
        s, p, q, w = (g[f"node_{k}"][:] for k in ("s", "pressure", "shear", "weight"))
    q = sign * q
    x = s - surf["centre"]
    qm = reference_shear(x, a, 2 * force / (np.pi * a), ratio, unload)
    m = (np.abs(x) < a) | (p > 0)
    return float(np.sqrt(np.sum(w[m] * (q[m] - qm[m])**2) / np.sum(w[m] * qm[m]**2)))


def increments(text):
    """The increments of a run from its -info lines: [{load, iterations,
    solves}], a load's penalty stages summed, solves the friction's fixed
    point solves of its last stage (1 without friction)."""
    out, solves = [], 0
    for line in (text or "").splitlines():
        m = FIXED_POINT.search(line)
        if m:
            solves = int(m.group(1))
            continue
        m = STAGE_LINE.search(line)
        if not m:
            continue
        load, its = float(m.group(1)), int(m.group(4))
        if out and out[-1]["load"] == load:
            out[-1]["iterations"] += its
        else:
            out.append(dict(load=load, iterations=its, solves=1))
        if solves:
            out[-1]["solves"] = solves
        solves = 0
    return out


def run(args, tmp, name, h5=False, may_fail=False):
    """One run with the staging's -info lines and every increment at the
    final tolerance; its summary, increments, HDF5 path and command (with
    may_fail, a run that does not converge gives its error line instead)."""
    from contactrun import run_case, parse_tao_line
    res = run_case(list(args) + INFO, tmp, name, h5=h5)
    if res.returncode != 0 and may_fail:
        return dict(command="bin/contact " + " ".join(list(args) + INFO), failed=res.stderr.strip().splitlines()[-1])
    if res.returncode != 0:
        raise SystemExit(f"{' '.join(res.cmd)} failed:\n{res.stdout[-2000:]}{res.stderr[-2000:]}")
    inc = increments(res.stdout)
    if not inc:   # one load, one penalty stage: the TAO line alone
        inc = [dict(load=1.0, iterations=parse_tao_line(res.stdout)["iterations"], solves=res.summary.get("friction_lags", 0) or 1)]
    return dict(command="bin/contact " + " ".join(list(args) + INFO), summary=res.summary, increments=inc, h5=res.h5)


def scene_params(body, hc, rc_scale=1.0):
    """The scene's -<body>_geo_params with its hc replaced and its rc (the
    graded zone's radius) scaled by rc_scale."""
    params = re.sub(r"hc=[0-9.e-]+", f"hc={hc!r}", scene_option(f"{body}_geo_params"))
    if rc_scale != 1.0:
        params = re.sub(r"rc=([0-9.e-]+)", lambda m: f"rc={float(m.group(1)) * rc_scale!r}", params)
    return params


def cattaneo_args(ratio, steps, hc=None, scale=1.0):
    """The arguments of a Cattaneo-Mindlin run: the normal force P scale^2,
    then Q = ratio mu P, in steps increments a stage; with hc, the contact
    edges hc and the graded zone's radius scaled by scale (the contact scale
    times as wide against the bodies, where hc scales with it too)."""
    force = P * scale**2
    args = list(CATTANEO)
    if hc is not None:
        args += ["-disc_geo_params", scene_params("disc", hc, scale), "-slab_geo_params", scene_params("slab", hc, scale)]
    return args + ["-disc_bc_clamp_values", f"{force!r},0,{force!r},{ratio * MU * force!r}", "-load_steps", str(steps)]


def cattaneo_row(tmp, case, ratio, steps, hc=None, scale=1.0):
    """One Cattaneo-Mindlin run (cattaneo_args) and its row."""
    force = P * scale**2
    r = run(cattaneo_args(ratio, steps, hc, scale), tmp, case, h5=True)
    row = dict(brief(r), case=case, ratio=ratio, steps=steps, l2=shear_l2(r["h5"], r["summary"], ratio, force=force))
    if hc is not None:
        row["hc"] = hc
    return row


def stage_c(s):
    """Each load stage's stick half-width over the last stage's a_moment."""
    a = s["contact"][PAIR]["fem_a_moment"]
    return [st["stick_half_width"][PAIR] / a for st in s["load_stages"]]


def brief(r):
    """The figures a row keeps of a run."""
    s = r["summary"]
    return dict(command=r["command"], dofs=s["dofs"], iterations=s["iterations"], solve=s["time"]["solve"],
                increments=r["increments"], c_over_a=stage_c(s), a=s["contact"][PAIR]["fem_a_moment"],
                pressure_l2=s["contact"][PAIR]["pressure_l2_error"])


def measure():
    """The accuracy rows: Cattaneo-Mindlin at each ratio in 1 and 8
    increments a stage, Mindlin-Deresiewicz's unloading likewise, each
    ratio at contact edges twice and half the scene's likewise, and each
    ratio with the contact twice as wide against the bodies."""
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        rows += [cattaneo_row(tmp, "cattaneo", ratio, n) for ratio in RATIOS for n in STEPS]
        for n in STEPS:
            args = CATTANEO + ["-load_stages", "3", "-disc_bc_clamp_values", f"{P},0,{P},{QSTAR * MU * P!r},{P},0",
                               "-slab_bc_push_values", "0,0,0,0,0,0", "-load_steps", str(n)]
            r = run(args, tmp, "md", h5=True)
            rows.append(dict(brief(r), case="deresiewicz", ratio=QSTAR, steps=n,
                             l2=shear_l2(r["h5"], r["summary"], QSTAR, unload=0.0)))
        rows += [cattaneo_row(tmp, "refinement", ratio, n, hc) for ratio in RATIOS for hc in (HC[0], HC[2]) for n in STEPS]
        # each ratio with the contact twice as wide against the disc (a/R = 0.1: 4 P, the
        # mesh's contact edges and graded zone scaled with a): further from Mindlin's half-spaces
        rows += [cattaneo_row(tmp, "wider", ratio, n, 2 * HC[1], 2.0) for ratio in RATIOS for n in STEPS]
    return rows


def wider_table(rows):
    """docs/scenes.md's table: each load ratio on the scene (a/R = 0.05) and
    with the contact twice as wide against the bodies (a/R = 0.1), c/a's
    distance from Mindlin's and the shear profile's, 1 / 8 increments."""
    out = ["| Q/(mu P) | c/a from Mindlin's, a/R = 0.05 (the scene): 1 / 8 increments | a/R = 0.1 | shear profile L2 from Mindlin's, a/R = 0.05: 1 / 8 | a/R = 0.1 |",
           "|---|---|---|---|---|"]
    for ratio in RATIOS:
        ref = math.sqrt(1 - ratio)
        cell = {}
        for case in ("cattaneo", "wider"):
            d = {r["steps"]: r for r in rows if r["case"] == case and r["ratio"] == ratio}
            cell[case] = (" / ".join(pct(d[n]["c_over_a"][-1] / ref - 1) for n in STEPS),
                          " / ".join(f"{100 * d[n]['l2']:.1f} %" for n in STEPS))
        out.append(f"| {ratio:g} | {cell['cattaneo'][0]} | {cell['wider'][0]} | {cell['cattaneo'][1]} | {cell['wider'][1]} |")
    return "\n".join(out) + "\n"


NORMAL = ["-load_stages", "1", "-slab_bc_push_values", "0,0"]
# each case: its label, the short name the README's sentence uses (None: left
# out of it: without friction the disc's y is held by no contact, and its
# increments take 10 to 480 iterations), the run with friction, the
# frictionless one's arguments added (None: none), the load stage measured;
# a case without arguments is the next stage of the case above it, the same runs
COST_CASES = [
    ("cattaneo, normal stage (P; the disc's y force-controlled, 0, as in the scene)", None,
     CATTANEO + NORMAL + ["-disc_bc_clamp_values", f"{P},0"], ["-contact_interface_friction", "0"], 1),
    ("cattaneo, normal stage (P; the disc's y held, u_y = 0)", "cattaneo's normal stage",
     CATTANEO + NORMAL + ["-disc_bc_clamp_control", "force,displacement", "-disc_bc_clamp_values", f"{P},0"],
     ["-contact_interface_friction", "0"], 1),
    ("cattaneo, tangential stage (Q = 0.5 mu P)", None, CATTANEO, None, 2),
    ("hertz (h = 0.1, mu = 0.3), normal stage (push 0.15)", "hertz's normal stage",
     HERTZ + ["-contact_friction", "0.3", "-load_stages", "2", "-block_bc_push_values", f"-0.15,0,-0.15,{HERTZ_SLIDE!r}",
              "-indenter_bc_clamp_values", "0,0,0,0"], ["-contact_friction", "0"], 1),
    ("hertz (h = 0.1, mu = 0.3), tangential stage (the block moved 0.08 along the contact)", "hertz's tangential stage",
     None, None, 2),
    ("sphere (r-z, mu = 0.3), normal", "the sphere (r-z)", SPHERE + ["-contact_friction", "0.3"], ["-contact_friction", "0"], 1),
]


def stage_increments(incs, stage):
    """The increments of load stage stage (loads in (stage - 1, stage])."""
    return [i for i in incs if stage - 1 < i["load"] <= stage + 1e-12]


def measure_cost():
    """Newton iterations per increment with friction and without, in 1 and 8
    increments a stage; L-BFGS with friction on the cattaneo scene."""
    rows, runs = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        for label, short, args, frictionless, stage in COST_CASES:
            for n in STEPS:
                if args is None:   # the stage of the case above, same runs
                    fr, nf = runs[n]
                else:
                    steps = ["-load_steps", str(n)]
                    fr = run(args + steps, tmp, "f")
                    nf = run(args + steps + frictionless, tmp, "n") if frictionless else None
                    runs[n] = (fr, nf)
                rows.append(dict(case=label, short=short, steps=n, command=fr["command"],
                                 frictionless=nf["command"] if nf else None,
                                 friction=stage_increments(fr["increments"], stage),
                                 without=stage_increments(nf["increments"], stage) if nf else None,
                                 solve=fr["summary"]["time"]["solve"], solve_without=nf["summary"]["time"]["solve"] if nf else None))
        newton = run(CATTANEO, tmp, "newton")
        lbfgs = [(label, args, 1) for label, _, args, _, _ in COST_CASES[:2]] + [("cattaneo, both stages", CATTANEO, None)]
        for label, args, stage in lbfgs:
            fr = run(args + ["-tao_type", "lmvm"], tmp, "lf")
            nf = run(args + ["-tao_type", "lmvm", "-contact_interface_friction", "0"], tmp, "ln", may_fail=True) if stage else None
            failed = nf.pop("failed", None) if nf else None
            c = fr["summary"]["contact"][PAIR]["stick_half_width"]
            cn = newton["summary"]["contact"][PAIR]["stick_half_width"] if stage is None else None
            rows.append(dict(case=f"L-BFGS (-tao_type lmvm): {label}", steps=int(scene_option("load_steps")), command=fr["command"],
                             frictionless=nf["command"] if nf else None, frictionless_failed=failed,
                             friction=fr["increments"], without=nf["increments"] if nf and not failed else None,
                             newton=newton["increments"] if stage is None else None,
                             solve=fr["summary"]["time"]["solve"], solve_without=nf["summary"]["time"]["solve"] if nf and not failed else None,
                             stick=c, stick_newton=cn))
    return rows


def pct(x):
    return f"{100 * x:+.2f} %"


def table(rows):
    """The accuracy table: one row per reference and load; c/a and the shear
    profile at the three contact edge sizes (Mindlin-Deresiewicz: the
    scene's alone), 1 and 8 increments a stage side by side."""
    scene = next(r for r in rows if r["case"] == "cattaneo")
    sizes = ", ".join(f"{hc:g} (a/hc = {scene['a'] / hc:.0f}{', the scene' if hc == HC[1] else ''})" for hc in HC)
    out = [f"| case | reference | c/a, 1 increment a stage, at contact edges hc = {sizes} | 8 increments a stage (the scene's), the same sizes "
           "| shear profile L2 from the reference: 1 / 8 increments | Newton iterations, the scene's mesh: 1 / 8 |",
           "|---|---|---|---|---|---|"]

    def sized(ratio, n):
        """The runs of one ratio and step count, coarsest contact edges first."""
        got = [r for r in rows if r["ratio"] == ratio and r["steps"] == n
               and (r["case"] == "refinement" or r["case"] == "cattaneo")]
        return sorted(got, key=lambda r: -r.get("hc", HC[1]))

    for ratio in RATIOS:
        ref = math.sqrt(1 - ratio)
        runs = {n: sized(ratio, n) for n in STEPS}
        cells = [", ".join(f"{r['c_over_a'][-1]:.4f} ({pct(r['c_over_a'][-1] / ref - 1)})" for r in runs[n]) for n in STEPS]
        l2 = " / ".join(", ".join(f"{100 * r['l2']:.1f}" for r in runs[n]) + " %" for n in STEPS)
        its = " / ".join(str(next(r for r in runs[n] if r["case"] == "cattaneo")["iterations"]) for n in STEPS)
        out.append(f"| Cattaneo-Mindlin, Q/(mu P) = {ratio:g} | c/a = sqrt(1 - Q/(mu P)) = {ref:.4f} | " + " | ".join(cells)
                   + f" | {l2} | {its} |")
    d = {r["steps"]: r for r in rows if r["case"] == "deresiewicz"}
    one, eight = d[1], d[8]
    ratio = one["ratio"]
    ref, refs = math.sqrt(1 - ratio / 2), math.sqrt(1 - ratio)
    cells = [f"the scene's mesh: {x['c_over_a'][-1]:.4f} ({pct(x['c_over_a'][-1] / ref - 1)}); at Q*: {x['c_over_a'][1]:.4f} "
             f"({pct(x['c_over_a'][1] / refs - 1)})" for x in (one, eight)]
    out.append(f"| Mindlin-Deresiewicz, Q* = {ratio:g} mu P, then 0 | c'/a = sqrt(1 - Q*/(2 mu P)) = {ref:.4f}; "
               f"at Q*: {refs:.4f} | " + " | ".join(cells)
               + f" | {100 * one['l2']:.1f} % / {100 * eight['l2']:.1f} % | {one['iterations']} / {eight['iterations']} |")
    return "\n".join(out) + "\n"


def its_list(incs):
    return " ".join(str(i["iterations"]) for i in incs)


def cost_table(rows):
    """The cost table: Newton iterations of each increment with friction and
    without, their largest ratio, the fixed point's solves."""
    out = ["| run, stage | increments a stage | iterations per increment: with friction | without | largest ratio | solves per increment (fixed point) | the run's solve time: with / without |",
           "|---|---|---|---|---|---|---|"]
    for r in rows:
        fr, nf = r["friction"], r["without"]
        ratio = f"{max(f['iterations'] / n['iterations'] for f, n in zip(fr, nf)):.2f}" if nf else "none"
        solves = " ".join(str(f["solves"]) for f in fr)
        times = f"{r['solve']:.2f} s / {r['solve_without']:.2f} s" if r["solve_without"] is not None else f"{r['solve']:.2f} s"
        case = r["case"]
        without = its_list(nf) if nf else (f"not converged: {r['frictionless_failed']}" if r.get("frictionless_failed")
                                           else "no equilibrium: the disc slides")
        if r.get("newton"):
            case += f": its stick half-width {r['stick']:.6g}, Newton's {r['stick_newton']:.6g} ({r['stick'] / r['stick_newton'] - 1:+.1e})"
            without = f"Newton with friction: {its_list(r['newton'])}"
            ratio = f"{max(f['iterations'] / n['iterations'] for f, n in zip(fr, r['newton'])):.1f} (Newton's)"
        out.append(f"| {case} | {r['steps']} | {its_list(fr)} | {without} | {ratio} | {solves} | {times} |")
    return "\n".join(out) + "\n"


def cost_phrase(rows):
    """The README's sentence on the cost: the range of the Newton rows'
    ratios per increment, the rows above 3, and L-BFGS with friction."""
    ratios = []
    for r in rows:
        if r["without"] and r.get("short"):
            ratios += [(f["iterations"] / n["iterations"], r["short"], r["steps"]) for f, n in zip(r["friction"], r["without"])]
    above = {}
    for x, short, steps in ratios:
        if x > 3:
            key = f"{short} in {steps} increment{'s' if steps > 1 else ''} a stage"
            above[key] = max(above.get(key, 0), x)
    lb = [r for r in rows if r.get("newton")][0]
    text = (f"a frictional increment took {min(ratios)[0]:.2f} to {max(ratios)[0]:.2f} times the Newton iterations of the same "
            f"increment without friction")
    text += ("; above 3: " + "; ".join(f"{k} ({v:.2f})" for k, v in above.items())) if above else ", never above 3"
    n_lb, n_newton = sum(i["iterations"] for i in lb["friction"]), sum(i["iterations"] for i in lb["newton"])
    return (text + f". L-BFGS (-tao_type lmvm) with friction finds Newton's stick zone to {abs(lb['stick'] / lb['stick_newton'] - 1):.0e} "
            f"in {n_lb} iterations against Newton's {n_newton}")


GETFEM_KIND = {"small_sliding": "GetFEM, small sliding (its weak form language: integral Alart-Curnier, linearised pairing)",
               "large_sliding": "GetFEM, large sliding (its raytracing brick: current configuration, as ours)"}


def getfem_case(gf):
    """The program's rows run on GetFEM's meshes: the scene's, or the contact twice as wide."""
    return "cattaneo" if gf.get("scale", 1.0) == 1.0 else "wider"


def getfem_rows(rows, gf):
    """(label, increments, friction in the normal stage, c/a error %, shear L2 %,
    Newton iterations, seconds) of the program's Q = 0.5 mu P runs and of
    each GetFEM variant (bench/friction/getfem*.json) on the same meshes."""
    ref = math.sqrt(1 - 0.5)
    out = [("the program (mortar, -contact_friction)", r["steps"], True, 100 * (r["c_over_a"][-1] / ref - 1), 100 * r["l2"],
            r["iterations"], r["solve"]) for r in rows if r["case"] == getfem_case(gf) and r["ratio"] == 0.5]
    for v in gf["variants"]:
        kind = next(k for k in GETFEM_KIND if v["name"].startswith(k))
        mult = "P1" if "_P1_" in v["name"] else "P2"
        out.append((f"{GETFEM_KIND[kind]}, {mult} multiplier", v["steps_per_stage"], v["friction_in_normal_stage"],
                    v["c_over_a_error_pct"], v["shear_l2_pct"], v["iterations_total"], v["seconds"]))
    return out


def getfem_table(rows, gf):
    """docs/scenes.md's table: the program against GetFEM on the cattaneo meshes."""
    out = ["| code, formulation | increments a stage | friction in the normal stage | c/a from Mindlin's | shear profile L2 from Mindlin's | Newton iterations | solve |",
           "|---|---|---|---|---|---|---|"]
    for label, n, fr, ca, l2, its, t in getfem_rows(rows, gf):
        out.append(f"| {label} | {n} | {'yes' if fr else 'no (mu = 0, then mu)'} | {ca:+.2f} % | {l2:.1f} % | {its} | {t:.2f} s |")
    return "\n".join(out) + "\n"


def getfem_phrase(rows, gf):
    """The README's sentence: the program's shear profile against GetFEM's
    large-sliding brick's, both with friction from the first increment."""
    got = getfem_rows(rows, gf)
    ours = {n: l2 for label, n, fr, ca, l2, its, t in got if label.startswith("the program")}
    theirs = {n: l2 for label, n, fr, ca, l2, its, t in got if label.startswith(GETFEM_KIND["large_sliding"]) and fr}
    return (f"on the same meshes (the contact twice as wide, a/R = 0.1), friction from the first increment, GetFEM's "
            f"frictional brick is {theirs[1]:.1f} % / {theirs[8]:.1f} % from Mindlin's shear in 1 / 8 increments a stage, ours "
            f"{ours[1]:.1f} % / {ours[8]:.1f} %")


def hertz_pressure_l2(v, scale):
    """A GetFEM variant's pressure's relative L2 distance from Hertz's (his a
    and p_max, about the pressure's centre, weights w), as the program's
    pressure_l2_error (src/contact/hertz.c)."""
    E, nu = float(scene_option("disc_E")), float(scene_option("disc_nu"))
    estar = E / (2 * (1 - nu**2))              # two bodies of the same E and nu; R* = the disc's radius 1
    force = P * scale**2
    a = math.sqrt(4 * force / (math.pi * estar))
    x, p, w = (np.array(v["profile"][k]) for k in ("x", "p", "w"))
    ph = 2 * force / (math.pi * a) * np.sqrt(np.clip(1 - x**2 / a**2, 0, None))
    return float(np.sqrt(np.sum(w * (p - ph) ** 2) / np.sum(w * ph**2)))


def getfem_scene_phrase(rows, gf):
    """docs/scenes.md's sentence on GetFEM on the scene's own meshes
    (bench/friction/getfem-scene.json): its pressures' distance from Hertz's
    against ours, and the shear profiles' from Mindlin's."""
    ours = {r["steps"]: r for r in rows if r["case"] == "cattaneo" and r["ratio"] == 0.5}
    v = {(x["name"].split("_P")[0], x["friction_in_normal_stage"], x["steps_per_stage"]): x
         for x in gf["variants"] if "_P2_" in x["name"]}
    ph = [hertz_pressure_l2(x, 1.0) for x in v.values()]
    big = v[("large_sliding", True, 1)], v[("large_sliding", True, 8)]
    return (f"on the scene's own meshes GetFEM's P2 multiplier alternates from node to node: its pressures are "
            f"{100 * min(ph):.1f} to {100 * max(ph):.1f} % from Hertz's in L2 (ours {100 * ours[1]['pressure_l2']:.2f} %), "
            f"its large-sliding brick's shear {big[0]['shear_l2_pct']:.1f} % / {big[1]['shear_l2_pct']:.1f} % from Mindlin's "
            f"in 1 / 8 increments a stage (ours {100 * ours[1]['l2']:.1f} % / {100 * ours[8]['l2']:.1f} %), and its slipping "
            f"nodes meet |q| = mu p only to {100 * max(x['slip_ratio_spread'] for x in big):.1f} %")


if __name__ == "__main__":
    if "--cost" in sys.argv:
        print(cost_table(measure_cost()))
    else:
        print(table(measure()))
