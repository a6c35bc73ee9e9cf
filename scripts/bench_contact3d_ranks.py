#!/usr/bin/env python3
"""3D contact on 1 against 2 ranks (bench/contact3d_ranks/RESULTS.md).

The quarter Hertz ball of
tests/test_contact3d.py (ball.geo on base.geo, Tet10 graded to h within 0.2
of the contact point) refined to about 2e5 dofs, the Newton step the program
chooses (a 3D scene with contact: the direct substructured step; the line it
prints is recorded with each run), run on 1 and 2 ranks in
interleaved rounds (1, 2, 1, 2, ...: the machine is shared, its load moves
during a study, and a ratio within one round sees the same load). Every
run's whole wall time, its JSON phases and its -log_view events are kept;
bench/contact3d_ranks/RESULTS.md and results.json are rewritten after each
run, so that a study cut short leaves what it measured.

    python3 scripts/bench_contact3d_ranks.py --h 0.0095 --rounds 3"""
import argparse
import json
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contactrun import copy_program, event_totals, git_info, load_average, median, parse_log_view, run  # noqa: E402

EVENTS = ["Mortar3dEnergyGrad", "Mortar3dHessian", "ElasHessian", "ElasEnergyGrad", "KSPSolve", "PCSetUp", "MatAssemblyEnd", "MatCopy",
          "SubstrFactor", "SubstrInterface", "SubstrStep", "SubstrSolve", "SubstrCapFactor"]
COLUMNS = ["SubstrFactor", "SubstrInterface", "SubstrStep", "SubstrSolve", "Mortar3dHessian", "Mortar3dEnergyGrad"]
E_BALL, E_BASE, NU = 1000.0, 1e5, 0.3


def scene(h):
    """The quarter Hertz ball at mesh size h (tests/test_contact3d.py's hertz_args)."""
    args = ["-bodies", "ball,base"]
    for name, geo, E, params, held in (("ball", "tests/meshes/contact3d/ball.geo", E_BALL, "rc=0.2,zc=0.1", "top"),
                                       ("base", "tests/meshes/contact3d/base.geo", E_BASE, "rc=0.2,c=0.35", "bottom")):
        args += [f"-{name}_geo", geo, f"-{name}_geo_params", params, f"-{name}_mesh_size", h, f"-{name}_E", E, f"-{name}_nu", NU,
                 f"-{name}_bc", f"{held},symx,symy", f"-{name}_bc_{held}_components", "z",
                 f"-{name}_bc_symx_components", "x", f"-{name}_bc_symy_components", "y"]
    return [str(a) for a in args + ["-ball_bc_top_values", -0.01, "-contact_pairs", "c", "-contact_c_surfaces", "ball:cap,base:top"]]


def write(out, cmdline, info, runs):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "results.json"), "w") as f:
        json.dump({"command": cmdline, "info": info, "runs": runs}, f, indent=1)
    L = ["# 3D contact: 1 against 2 ranks\n",
         f"`{cmdline}`, commit {info['commit']}. The quarter Hertz ball (tests/test_contact3d.py's scene) at h = {info['h']}, "
         f"{info.get('dofs', '?')} dofs, `-output none`; {'; '.join(sorted(info.get('steps', []))) or 'Newton step: ?'}. Rounds interleaved (1 rank, then 2, each round); "
         "the machine is shared (2 cores; the load average before each run is listed), so each round's ratio is the figure, "
         "not one run's time. Events: -log_view's time, the largest over the ranks, summed over the stages.\n",
         "| round | ranks | load before | wall [s] | solve [s] | Newton its (energy evals) | "
         + " | ".join(f"{e} [s]" for e in COLUMNS) + " | P |",
         "|---|---|---|---|---|---|" + "---|" * len(COLUMNS) + "---|"]
    for r in runs:
        ev = r["events"]
        L.append(f"| {r['round']} | {r['ranks']} | {r['load']:.1f} | {r['wall']:.1f} | {r['solve']:.1f} | {r['iterations']} ({r['evaluations']}) | "
                 + " | ".join(f"{ev.get(e, (0, float('nan')))[1]:.2f}" for e in COLUMNS)
                 + f" | {r['P']:.6g} |")
    ratios = []
    for k in sorted({r["round"] for r in runs}):
        one = [r for r in runs if r["round"] == k and r["ranks"] == 1]
        two = [r for r in runs if r["round"] == k and r["ranks"] == 2]
        if one and two:
            ratios.append((k, one[0]["wall"] / two[0]["wall"], one[0]["solve"] / two[0]["solve"]))
    L.append("\nSpeed-up of 2 ranks over 1 in each round (whole run's wall time; the solve phase):\n")
    for k, w, s in ratios:
        L.append(f"- round {k}: wall {w:.2f}x, solve {s:.2f}x")
    if ratios:
        L.append(f"\nMedian: wall {median([w for _, w, _ in ratios]):.2f}x, solve {median([s for _, _, s in ratios]):.2f}x (target 1.6x).")
    with open(os.path.join(out, "RESULTS.md"), "w") as f:
        f.write("\n".join(L) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--h", type=float, default=0.0095, help="mesh size near the contact (0.0095: 213,161 dofs)")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "contact3d_ranks"))
    ap.add_argument("--timeout", type=float, default=3600)
    a = ap.parse_args()
    cmdline = "python3 scripts/bench_contact3d_ranks.py " + " ".join(sys.argv[1:])
    info = {"h": a.h, "commit": git_info(a.out)}
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        binary = copy_program(tmp)
        for k in range(1, a.rounds + 1):
            for ranks in (1, 2):
                tag = f"r{k}_n{ranks}"
                load = load_average()
                res = run(scene(a.h) + ["-output", "none"], ranks=ranks, binary=binary, summary=os.path.join(tmp, tag + ".json"),
                          log_view=os.path.join(tmp, tag + ".log"), timeout=a.timeout)
                s = res.summary or {}
                if res.returncode != 0 or not s:
                    print(f"{tag}: exited {res.returncode}", file=sys.stderr)
                    continue
                lv = parse_log_view(os.path.join(tmp, tag + ".log"))
                tot = event_totals(lv)
                info["dofs"] = s.get("dofs")
                step = [line.strip() for line in (res.stdout or "").splitlines() if line.startswith("Newton step:")]
                info.setdefault("steps", [])
                for line in step:
                    if line not in info["steps"]:
                        info["steps"].append(line)
                runs.append({"round": k, "ranks": ranks, "load": load, "wall": res.wall,
                             "solve": s["time"]["solve"], "time": s["time"], "iterations": s.get("iterations"),
                             "evaluations": s.get("function_evaluations"), "P": s.get("contact_force"),
                             "step": step[0] if step else None,
                             "events": {e: tot[e] for e in EVENTS if e in tot}})
                os.makedirs(a.out, exist_ok=True)
                with open(os.path.join(tmp, tag + ".log")) as src, open(os.path.join(a.out, tag + ".log_view.txt"), "w") as dst:
                    dst.write(src.read())
                write(a.out, cmdline, info, runs)
                print(f"{tag}: wall {res.wall:.1f} s, solve {s['time']['solve']:.1f} s", flush=True)


if __name__ == "__main__":
    main()
