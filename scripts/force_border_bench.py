"""The cost of coupled force control's border, eliminated by the
substructuring from the contact surfaces (the default) against m solves of
the bodies' Hessian per Hessian (-force_control_border_solves, as before
it): the TaoSolve and ForceBorderSetUp times of -log_view, the Newton
iterations and the answers (the contact force P and the controls'
displacements U) of both, on the scenes whose solve pays for the border.
The two ways run interleaved (the machine is shared), each scene -repeats
times, and the medians are kept. Writes results/force_border.json and the
markdown table results/force_border.md.

    python3 scripts/force_border_bench.py [--repeats 3] [--scenes roller-force,...] [--ranks 1]
"""
import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contactrun  # noqa: E402

ROLLER = ["-options_file", "meshes/roller/roller.opts"]
HERTZ = ["-options_file", "meshes/hertz/hertz.opts"]
SCENES = {
    "roller-force": ("the roller pushed by a force of 1000 (its shipped options)", ROLLER),
    "roller-pressure": ("the roller pushed by a pressure of 100 (the upper race held in x alone)",
                        ROLLER + ["-upper_bc_back_components", "x", "-upper_bc_back_control", "displacement", "-upper_bc_back_values", "0", "-upper_load", "back",
                                  "-upper_load_back_pressure", "100"]),
    "held-block": ("the reference scene's block held by contact, pressed by 27.5 (tests/test_held_by_contact.py)",
                   HERTZ + ["-block_bc_push_components", "y", "-block_bc_push_values", "0", "-block_load", "push",
                            "-block_load_push_pressure", "27.5"]),
    "hertz-force-fine": ("the reference scene at h = 0.03 pushed by 54.847 (results/force_control.md's hertz-fine)",
                         HERTZ + ["-mesh_size", "0.03", "-block_bc_push_control", "force,displacement",
                                  "-block_bc_push_values", "-54.84736949204295,0"]),
}
WAYS = {"surfaces": [], "solves": ["-force_control_border_solves"]}


def one(args, ranks, tmp, name, binary):
    lv = os.path.join(tmp, name + ".log")
    r = contactrun.run(args + ["-output", "none"], ranks, binary, summary=os.path.join(tmp, name + ".json"), log_view=lv)
    if r.returncode != 0 or not r.summary:
        raise SystemExit(f"{' '.join(r.cmd)} failed:\n{r.stdout[-2000:]}{r.stderr[-2000:]}")
    ev = contactrun.event_totals(contactrun.parse_log_view(lv))
    s = r.summary
    return {"command": " ".join(r.cmd), "iterations": s["iterations"], "tao_solve": ev.get("TaoSolve", (0, None))[1],
            "border_setup": ev.get("ForceBorderSetUp", (0, None))[1], "border_setups": ev.get("ForceBorderSetUp", (0, None))[0],
            "contact_force": s["contact_force"], "displacements": [c["displacement"] for c in s["force_control"]],
            "controls": len(s["force_control"]), "dofs": s["dofs"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--ranks", default="1")
    ap.add_argument("--out", default=os.path.join(contactrun.ROOT, "results", "force_border.json"))
    a = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        binary = contactrun.copy_program(tmp)
        for name in a.scenes.split(","):
            what, args = SCENES[name]
            contactrun.mesh_only(args, binary)
            for ranks in [int(x) for x in a.ranks.split(",")]:
                runs = {w: [] for w in WAYS}
                for i in range(a.repeats):
                    for w, extra in WAYS.items():
                        runs[w].append(one(args + extra, ranks, tmp, f"{name}-{w}-{ranks}-{i}", binary))
                row = {"scene": name, "what": what, "ranks": ranks, "dofs": runs["surfaces"][0]["dofs"],
                       "controls": runs["surfaces"][0]["controls"], "load_average": contactrun.load_average()}
                for w in WAYS:
                    row[w] = {"command": runs[w][0]["command"], "iterations": sorted({r["iterations"] for r in runs[w]}),
                              "border_setups": runs[w][0]["border_setups"],
                              "tao_solve": contactrun.median([r["tao_solve"] for r in runs[w]]),
                              "border_setup": contactrun.median([r["border_setup"] for r in runs[w]]),
                              "tao_solve_all": [r["tao_solve"] for r in runs[w]],
                              "contact_force": runs[w][0]["contact_force"], "displacements": runs[w][0]["displacements"]}
                f, s = row["surfaces"], row["solves"]
                row["contact_force_rel"] = abs(f["contact_force"] - s["contact_force"]) / abs(s["contact_force"])
                row["displacement_diff"] = max(abs(x - y) for x, y in zip(f["displacements"], s["displacements"]))
                row["speedup"] = s["tao_solve"] / f["tao_solve"]
                rows.append(row)
                print(f"{name} np{ranks}: TaoSolve {s['tao_solve']:.2f} -> {f['tao_solve']:.2f} s, ForceBorderSetUp "
                      f"{s['border_setup']:.2f} -> {f['border_setup']:.2f} s, iterations {s['iterations']} / {f['iterations']}, "
                      f"|dP|/P {row['contact_force_rel']:.1e}, max |dU| {row['displacement_diff']:.1e}", flush=True)
    res = {"what": "coupled force control's border: from the contact surfaces (default) against m solves a Hessian "
                   "(-force_control_border_solves); scripts/force_border_bench.py",
           "repeats": a.repeats, "git": contactrun.git_info(os.path.dirname(a.out)), "machine": contactrun.machine_info(),
           "rows": rows}
    lines = ["Coupled force control's border eliminated from the contact surfaces (the default) against m solves of the "
             f"bodies' Hessian per Hessian (-force_control_border_solves) (scripts/force_border_bench.py; {res['git']}). "
             f"Medians of {a.repeats} interleaved runs, -log_view's TaoSolve and ForceBorderSetUp; m: the controls, "
             "anchors included.", "",
             "| scene | ranks | dofs | m | Newton iterations | TaoSolve [s]: solves, surfaces | speed-up | "
             "ForceBorderSetUp [s]: solves, surfaces | P apart | U apart | load |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        f, s = r["surfaces"], r["solves"]
        its = "/".join(map(str, s["iterations"])) + (", " + "/".join(map(str, f["iterations"])) if f["iterations"] != s["iterations"] else "")
        lines.append(f"| {r['scene']} | {r['ranks']} | {r['dofs']:,} | {r['controls']} | {its} | {s['tao_solve']:.2f}, "
                     f"{f['tao_solve']:.2f} | {r['speedup']:.2f} | {s['border_setup']:.2f}, {f['border_setup']:.2f} | "
                     f"{r['contact_force_rel']:.1e} | {r['displacement_diff']:.1e} | {r['load_average']:.1f} |")
    contactrun.write_results(a.out, res, lines)


if __name__ == "__main__":
    main()
