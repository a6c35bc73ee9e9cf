"""How honest `-accuracy`'s displacement estimate is under force control
(src/driver/accuracy.c's header, docs/solver.md#accuracy).

Two scenes driven by a force: the reference scene with its block pushed by
F = -55 in x (-block_bc_push_control force,displacement), and the sphere's
ball pushed by F = -0.76 at its equator (k_p fixed at 1e8, so that the
penalty does not change with the contact's mesh size and the references
below solve the same problem). For each, the refinement steps of
`-accuracy 1e-9 -accuracy_max_steps M` (each step's displacement U_k and
estimate in the JSON's adapt_steps), and the true error of each U_k against
a reference:
- hertz: the limit of uniform meshes h = 0.025, 0.0125, 0.00884 (73,972 to
  585,260 dofs) extrapolated at the order fitted through the three;
- sphere: graded meshes with the contact zone (0.12 around the contact
  point) at h = 0.000625 and elsewhere an eighth of the scene's sizes
  (844,004 dofs), and the same with the zone at 0.00125 (their difference
  bounds what the reference resolves).
Writes bench/accuracy/force_control.json and prints the table.

    python3 scripts/accuracy_force_study.py [--out bench/accuracy]   # about 10 minutes
"""
import argparse
import json
import math
import os
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contactrun import copy_program, run_case  # noqa: E402

HERTZ = ["-options_file", "meshes/hertz/hertz.opts", "-block_bc_push_control", "force,displacement",
         "-block_bc_push_values", "-55,0"]
SPHERE = ["-options_file", "meshes/sphere/sphere.opts", "-ball_bc_equator_control", "force",
          "-ball_bc_equator_values", "-0.76", "-contact_penalty", "1e8"]
HERTZ_H = [0.025, 0.0125, 0.00884]


def sphere_graded(hc, factor):
    """The sphere's meshes with the contact zone at hc and elsewhere the scene's sizes / factor."""
    return ["-ball_mesh_size", hc, "-flat_mesh_size", hc,
            "-ball_geo_params", f"R=1,tc=30,hfar={0.1 / factor!r},dp=0.12,dc=0.5",
            "-flat_geo_params", f"W=2,H=2,rc=0.5,hfar={0.25 / factor!r},dp=0.12,dc=0.5"]


def solve(args, tmp, name, binary, ok=(0,)):
    res = run_case([str(a) for a in args] + ["-quiet"], tmp, name, h5=False, binary=binary)
    if res.returncode not in ok or not res.summary:
        raise SystemExit(f"{' '.join(res.cmd)} failed:\n{res.stdout[-2000:]}{res.stderr[-2000:]}")
    return res.summary


def displacement(summary):
    (fc,) = summary["force_control"]
    return fc["displacement"]


def extrapolate(h, U):
    """U's limit at h = 0 through three (h, U) with U = U0 + C h^p: p by bisection."""
    ratio = (U[0] - U[1]) / (U[1] - U[2])
    lo, hi = 0.2, 4.0
    for _ in range(100):
        p = 0.5 * (lo + hi)
        if ((h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p) - ratio) * \
           ((h[0] ** lo - h[1] ** lo) / (h[1] ** lo - h[2] ** lo) - ratio) > 0:
            lo = p
        else:
            hi = p
    C = (U[1] - U[2]) / (h[1] ** p - h[2] ** p)
    return U[2] - C * h[2] ** p, p


def steps(base, tmp, name, binary, m):
    s = solve(base + ["-accuracy", "1e-9", "-accuracy_max_steps", m], tmp, name, binary, ok=(2,))
    return [{"dofs": a["dofs"], "U": a["displacements"][0], "estimate": a["displacement_estimate"],
             "profile_estimate": a["profile_estimate"], "force_estimate": a["force_estimate"]} for a in s["adapt_steps"]]


def compare(rows, ref):
    for r in rows:
        r["true"] = abs(r["U"] / ref - 1)
        r["true_over_estimate"] = r["true"] / r["estimate"] if r["estimate"] else None
        if len(rows) > 1 and r is not rows[0]:
            prev = rows[rows.index(r) - 1]
            r["error_ratio"] = prev["true"] / r["true"] if r["true"] > 0 else math.inf
    return rows


def table(out):
    lines = []
    for scene in ("hertz", "sphere"):
        o = out[scene]
        lines += [f"{scene}: reference {o['reference']!r} ({o['reference_how']})", "",
                  "| step | dofs | U | estimate (2 D_k) | true error | true / estimate | e_{k-1} / e_k |",
                  "|---|---|---|---|---|---|---|"]
        for k, r in enumerate(o["steps"]):
            est = f"{r['estimate']:.3g}" if r["estimate"] is not None else "-"
            ratio = f"{r['true_over_estimate']:.2f}" if r.get("true_over_estimate") else "-"
            lines.append(f"| {k} | {r['dofs']} | {r['U']:.10g} | {est} | {r['true']:.3g} | {ratio} | "
                         f"{r.get('error_ratio', float('nan')):.2f} |")
        lines.append("")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "bench", "accuracy"))
    args = ap.parse_args()
    t0 = time.time()
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        binary = copy_program(tmp)
        U = [displacement(solve(HERTZ + ["-mesh_size", h], tmp, f"hertz-h{h}", binary)) for h in HERTZ_H]
        ref, p = extrapolate(HERTZ_H, U)
        out["hertz"] = {"uniform": dict(zip(map(str, HERTZ_H), U)), "order": p, "reference": ref,
                        "reference_how": f"uniform h = {HERTZ_H} extrapolated at the fitted order {p:.3f}",
                        "steps": compare(steps(HERTZ, tmp, "hertz-steps", binary, 6), ref)}
        fine = displacement(solve(SPHERE + sphere_graded(0.000625, 8), tmp, "sphere-D", binary))
        coarser = displacement(solve(SPHERE + sphere_graded(0.00125, 8), tmp, "sphere-E", binary))
        out["sphere"] = {"reference": fine, "zone_h_0.00125": coarser, "resolved": abs(fine / coarser - 1),
                         "reference_how": "graded: contact zone h = 0.000625, elsewhere 1/8 of the scene's sizes; "
                                          f"{abs(fine / coarser - 1):.2g} from the zone at h = 0.00125",
                         "steps": compare(steps(SPHERE, tmp, "sphere-steps", binary, 5), fine)}
    out["elapsed"] = time.time() - t0
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "force_control.json"), "w") as f:
        json.dump(out, f, indent=1)
    print(table(out))
    print(f"{out['elapsed']:.0f} s")


if __name__ == "__main__":
    main()
