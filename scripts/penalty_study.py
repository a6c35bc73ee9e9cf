#!/usr/bin/env python3
"""How stiff a penalty the mesh needs: the measurement behind -contact_penalty
auto (k_p = 1000 E*/h, src/contact/contactterm.c) and its warning (k_p h / E*
below 25).

    python3 scripts/penalty_study.py [--out bench/penalty]     # about 5 minutes

For two scenes and a sequence of contact mesh sizes h, the pair is solved
with k_p = c E*/h for c = 30, 100, 300, 1000, with auto (c = 1000 reached in
two stages from c = 30, as the program does), and with k_p = 1e10 (penalty
continuation from 1e-4 of it): the penalty's limit at that mesh. The
penalty's error in the contact force P and the peak pressure p_max is each
run's distance from that limit; the mesh's error is the limit's distance
from the limit on a mesh twice finer than the finest listed (a reference, not
a run of the table). The ratio of the two is what the rule keeps small:

- hertz-half (the mirrored reference scene, a/R = 0.34): -mesh_size h, the
  contact edges' size h;
- hertz-small (a/R = 0.10): the contact size hc of both bodies' .geo.

Writes results.json (one record per run) into the output directory; the table
in docs/formulations.md is rendered from it by scripts/readme_figures.py.
"""
import argparse
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contactrun import ROOT, copy_program, run_checked  # noqa: E402

ESTAR = 1.0 / (2 * (1 - 0.3 ** 2) / 1000.0)   # both scenes: E = 1000, nu = 0.3 on both sides
CS = [30, 100, 300, 1000]
TIGHT = ["-tao_gttol", "1e-10"]


def half(h):
    return ["-options_file", "meshes/hertz-half/hertz-half.opts", "-mesh_size", str(h)]


def small(hc):
    return ["-options_file", "meshes/hertz-small/hertz-small.opts",
            "-indenter_geo_params", f"R=1,xc=-1,yc=0,xclamp=-1.8,xcontact=-0.5,hc={hc},dc=1",
            "-block_geo_params", f"x0=0,W=1,H=2,hc={hc},dc=1"]


SCENES = {"hertz-half": (half, [0.1, 0.05, 0.025, 0.0125], 0.00625),
          "hertz-small": (small, [0.008, 0.004, 0.002], 0.001)}


BINARY = None  # a copy of bin/contact (main), so that a rebuild meanwhile does not mix versions


def solve(args, tmp, name):
    s = run_checked(args + TIGHT + ["-output", "none"], tmp, name, binary=BINARY).summary
    c = s["contact"][next(iter(s["contact"]))]
    return dict(P=s["contact_force"], pmax=s["fem_pmax"], iterations=s["iterations"], stages=s["stages"],
                penalty=c["penalty"], edge=c["penalty_h"], stiffness=c["penalty_stiffness"])


def measure(scene, tmp):
    mesh, hs, href = SCENES[scene]
    print(f"{scene}: the reference, h = {href}", flush=True)
    limit = ["-contact_penalty", "1e10", "-penalty_stages", "4", "-penalty_start", "1e-4"]
    ref = solve(mesh(href) + limit, tmp, "ref")
    rows = []
    for h in hs:
        lim = solve(mesh(h) + limit, tmp, "limit")
        for c in CS + ["auto"]:
            if c == "auto":
                r = solve(mesh(h) + ["-contact_penalty", "auto"], tmp, "run")
            else:  # c E*/h with the h the program reports (the shortest contact edge)
                r = solve(mesh(h) + ["-contact_penalty", f"{c * ESTAR / lim['edge']:.9g}"], tmp, "run")
            rec = dict(scene=scene, h=h, c=c, **r)
            for k in ("P", "pmax"):
                rec[f"{k}_penalty_error"] = abs(r[k] - lim[k]) / abs(lim[k])
                rec[f"{k}_mesh_error"] = abs(lim[k] - ref[k]) / abs(ref[k])
            rec["limit_iterations"] = lim["iterations"]
            rows.append(rec)
            print(json.dumps(rec), flush=True)
    return rows


def table(rows):
    """The docs' table: per scene and h, each c's iterations and the
    penalty's error over the mesh's, for P and p_max."""
    out = ["| scene | h | k_p h / E* | iterations | P: penalty error / mesh error | p_max: penalty error / mesh error |",
           "|---|---|---|---|---|---|"]
    for r in rows:
        c = "auto (1000)" if r["c"] == "auto" else f"{r['c']}"
        ratio = [r[f"{k}_penalty_error"] / r[f"{k}_mesh_error"] if r[f"{k}_mesh_error"] > 0 else float("nan")
                 for k in ("P", "pmax")]
        out.append(f"| {r['scene']} | {r['h']:g} | {c} | {r['iterations']} | {ratio[0]:.3f} | {ratio[1]:.3f} |")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "penalty"))
    args = ap.parse_args()
    global BINARY
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        BINARY = copy_program(tmp)
        for scene in SCENES:
            rows += measure(scene, tmp)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump(rows, f, indent=1)
    print(table(rows))


if __name__ == "__main__":
    main()
