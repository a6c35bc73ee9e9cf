"""Newton iterations of force control against displacement control, scene by
scene: each scene is first run displacement-controlled; the reaction of the
pushed group there is the force of the force-controlled runs (the coupled
type, the default, and the outer iteration, -force_control_type outer), which
must find the same displacement. Writes results/force_control.json (and the
markdown table results/force_control.md) with, per scene and rank count: the command lines,
the displacement run's iterations, each force type's iterations, solves,
reason, the displacement found and its relative distance from the imposed
one, and whether the coupled run is within the target, 1.5 times the
displacement run's iterations plus 2.

    python3 scripts/force_control_table.py [--ranks 1,2] [--scenes hertz,...] [--out results/force_control.json]
    python3 scripts/force_control_table.py --types coupled --extra "-tao_type lmvm" --both --out results/force_control_lmvm.json
"""
import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contactrun  # noqa: E402

FINE = ["-disc_geo_params", "R=1,xc=-1,yc=0,xclamp=-1.8,xcontact=-0.5,hc=0.0007,dc=1",
        "-slab_geo_params", "x0=0,W=1,H=2,hc=0.0007,dc=1"]
ROLLER = ["-options_file", "meshes/roller/roller.opts", "-upper_bc_back_control", "displacement,displacement",
          "-upper_bc_back_values", "0,-0.0444"]
# name: (options, [(controlled group "body:group", its components, the controlled one's index in them, the imposed displacement)])
SCENES = {
    "hertz": (["-options_file", "meshes/hertz/hertz.opts"], [("block:push", ["x", "y"], 0, -0.15)]),
    "hertz-stiff": (["-options_file", "meshes/hertz/hertz.opts", "-contact_penalty", "1e8"], [("block:push", ["x", "y"], 0, -0.15)]),
    "hertz-fine": (["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.03"], [("block:push", ["x", "y"], 0, -0.15)]),
    "softdisc": (["-options_file", "meshes/softdisc/softdisc.opts"], [("disc:clamp", ["x", "y"], 0, 0.02)]),
    "softdisc-fine": (["-options_file", "meshes/softdisc/softdisc.opts"] + FINE, [("disc:clamp", ["x", "y"], 0, 0.02)]),
    "sphere": (["-options_file", "meshes/sphere/sphere.opts"], [("ball:equator", ["y"], 0, -0.01)]),
    "sphere-deep": (["-options_file", "meshes/sphere/sphere.opts", "-ball_bc_equator_values", "-0.05"],
                    [("ball:equator", ["y"], 0, -0.05)]),
    "pinch": (["-options_file", "meshes/pinch/pinch.opts"], [("left:clamp", ["x", "y"], 0, 0.02),
                                                              ("right:clamp", ["x", "y"], 0, -0.03)]),
    # a body held by contact: the roller's anchors are coupled controls in both runs (no outer type there)
    "roller": (ROLLER, [("upper:back", ["x", "y"], 1, -0.0444)]),
    "roller-coarse": (ROLLER + ["-mesh_size", "0.03"], [("upper:back", ["x", "y"], 1, -0.0444)]),
}
HELD = {"roller", "roller-coarse"}
TYPES = ["coupled", "outer"]


def control_options(group, comps, k, F):
    body, name = group.split(":")
    ctl = ",".join("force" if i == k else "displacement" for i in range(len(comps)))
    vals = ",".join(repr(F) if i == k else "0" for i in range(len(comps)))
    return [f"-{body}_bc_{name}_control", ctl, f"-{body}_bc_{name}_values", vals]


def measure(name, ranks, tmp, types, extra, both=False):
    args, controls = SCENES[name]
    args = args + ["-output", "none"] + (extra if both else [])
    extra = [] if both else extra
    disp = contactrun.run_case(args, tmp, f"{name}-d{ranks}", ranks=ranks, h5=False)
    tao = contactrun.parse_tao_line(disp.stdout)
    if disp.returncode != 0 or not disp.summary:
        raise SystemExit(f"{' '.join(disp.cmd)} failed:\n{disp.stdout[-2000:]}{disp.stderr[-2000:]}")
    forces = [disp.summary["reactions"][g]["xy".index(comps[k])] for g, comps, k, U in controls]
    opts = sum((control_options(g, comps, k, F) for (g, comps, k, U), F in zip(controls, forces)), [])
    row = {"scene": name, "ranks": ranks, "dofs": disp.summary["dofs"], "forces": forces,
           "displacements": [c[3] for c in controls],
           "displacement_run": {"command": " ".join(disp.cmd), "iterations": tao["iterations"], "reason": tao["reason"]}}
    for t in types:
        if t != "coupled" and name in HELD:
            continue  # a scene with a body held by contact is always coupled
        r = contactrun.run_case(args + opts + ["-force_control_type", t] + extra, tmp, f"{name}-{t}{ranks}", ranks=ranks,
                                h5=False)
        tt = contactrun.parse_tao_line(r.stdout) or {}
        found = [c.get("displacement") for c in ((r.summary or {}).get("force_control") or []) if not c.get("anchor")]
        ok = len(found) == len(controls)
        row[t] = {"command": " ".join(r.cmd), "status": r.returncode, "iterations": tt.get("iterations"),
                  "reason": tt.get("reason"), "solves": (r.summary or {}).get("force_control_solves"),
                  "displacements_found": found,
                  "relative_error": max(abs(u - c[3]) / abs(c[3]) for u, c in zip(found, controls)) if ok else None}
    row["target"] = 1.5 * row["displacement_run"]["iterations"] + 2
    row["coupled_within_target"] = bool(row["coupled"]["status"] == 0 and row["coupled"]["iterations"] <= row["target"])
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ranks", default="1,2")
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--out", default=os.path.join(contactrun.ROOT, "results", "force_control.json"))
    ap.add_argument("--types", default=",".join(TYPES), help="force control types to run (the outer iteration is slow)")
    ap.add_argument("--extra", default="", help="more options for the force-controlled runs (space-separated)")
    ap.add_argument("--both", action="store_true", help="--extra for the displacement runs too (another solver on both)")
    a = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name in a.scenes.split(","):
            for ranks in [int(x) for x in a.ranks.split(",")]:
                rows.append(measure(name, ranks, tmp, a.types.split(","), a.extra.split(), a.both))
                r = rows[-1]
                print(f"{name} np{ranks}: displacement {r['displacement_run']['iterations']}, coupled "
                      f"{r['coupled']['iterations']} ({r['coupled']['reason']}, U {r['coupled']['displacements_found']})"
                      + (f", outer {r['outer']['iterations']} ({r['outer']['reason']}, {r['outer']['solves']} solves)" if "outer" in r else ""),
                      flush=True)
    res = {"what": "Newton iterations, force control against displacement control (scripts/force_control_table.py)",
           "options": a.extra + (" (both runs)" if a.both else " (force-controlled runs)") if a.extra else "",
           "git": contactrun.git_info(os.path.dirname(a.out)), "machine": contactrun.machine_info(), "rows": rows}
    lines = ["Iterations of force control against displacement control (scripts/force_control_table.py; "
             f"{res['git']}{'; options ' + res['options'] if res['options'] else ''}). Each force is the displacement "
             "run's reaction; *coupled* is the default (-force_control_type coupled), *outer* the outer iteration. "
             "roller: the roller is held by its contacts alone, its anchors coupled controls of force 0 in both runs "
             "(src/solver/unheld.c).", "",
             "| scene | ranks | dofs | displacement | coupled | target 1.5 d + 2 | outer (solves) | U found (coupled), largest rel. error |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        c, o = r["coupled"], r.get("outer")
        outer = f"{o.get('iterations')} ({o.get('solves')})" if o else "held: coupled"
        lines.append(f"| {r['scene']} | {r['ranks']} | {r['dofs']} | {r['displacement_run']['iterations']} | {c['iterations']} "
                     f"| {r['target']:g} | {outer} | "
                     f"{', '.join(f'{u:.6g}' for u in c['displacements_found'])}, {c['relative_error']:.1e} |")
    contactrun.write_results(a.out, res, lines)


if __name__ == "__main__":
    main()
