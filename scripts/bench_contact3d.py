#!/usr/bin/env python3
"""3D contact's speed (bench/contact3d/): the quarter Hertz ball beside
GetFEM, L-BFGS against Newton, and the cost of a Newton step against the
linear solve's as the contact grows.

The scenes are tests/test_contact3d.py's: the quarter Hertz ball (R = 1,
E 1000 on a block of E 1e5, nu 0.3, pushed 0.01: a/R = 0.10; Tet10 graded
to h within 0.2 of the contact; hertz_args) and the patch (a Tet10 box on a
Hex27 box, patch_args). Each run's figures: the whole process's wall time
and user CPU time, its peak resident memory (/usr/bin/time), the JSON's
set-up and solve times, Newton (or L-BFGS) iterations, and for Hertz the
errors as test_hertz_quarter measures them (P = 4 F_z; a from the nodal
pressures' second moment, p_max the largest nodal pressure, against
Hertz's a = (3PR/(4E*))^(1/3) and p0 = 3P/(2 pi a^2)). The host's load
average is recorded with each run: the machine is shared (2 cores), so
the ratios of runs interleaved in one sitting are what to read.

--side-by-side N: the ball at h (--h, 0.025: the coarsest of
docs/formulations.md's table within 1 % in a and p0) by the program and by
GetFEM 5.4 (scripts/getfem_hertz3d.py: its large sliding augmented
Lagrangian brick, P2 displacements, MUMPS) on the same two .msh files
(the program's, made once into --mesh-dir and given to both: -ball_mesh,
-base_mesh), and with --before BIN an older build, N rounds interleaved;
each kept as its median-wall run with every round's figures.

--lmvm N: Newton (the default) and L-BFGS (-tao_type lmvm) on the Hertz
ball (h 0.04 and 0.025) and on the patch (the test's Tet10 on Hex27 and a
finer pair), N rounds interleaved: the solve times' ratio (the issue's bound
3), iterations, P from Newton's.

--cost: the ball at h = 0.04 down to --cost-hmin, then the finer patch
(every slave face in contact), one run each with -log_view:
the dofs, the slave faces and the nodes in contact, then per Newton step
the contact's work (its Hessian, Mortar3dHessian, and its energy and
gradient evaluations, Mortar3dEnergyGrad, divided by the iterations) against
the linear solve's (the step's set-up and solve: SubstrStep + SubstrSolve
for the direct Schur step, PCSetUp + KSPSolve for CG; the one-off
factorisation SubstrFactor apart).

--cost-cg H,H,...: the ball at these h by CG + GAMG (-newton_iterative 1:
GAMG by nodes on one level, as with contact), on --cost-ranks ranks, one
run each with -log_view: the same figures, the linear step's PCSetUp +
KSPSolve, the CG iterations, and Mortar3dHessian's time on its slowest rank
over its fastest's. h 0.04, 0.02, 0.0125, 0.008, 0.005 give 1.0e4, 3.4e4,
1.0e5, 3.1e5 and 1.2e6 dofs (the ball's cap, the contact surface, graded
to h: its slave faces grow as h^-2).

    python3 scripts/bench_contact3d.py --side-by-side 3 [--before OLD/bin/contact]
    python3 scripts/bench_contact3d.py --lmvm 3
    python3 scripts/bench_contact3d.py --cost [--cost-hmin 0.01]
    python3 scripts/bench_contact3d.py --cost-cg 0.04,0.02,0.0125,0.008 [--cost-ranks 2]
    python3 scripts/bench_contact3d.py --table      # RESULTS.md from results.json
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from test_contact3d import E_BALL, E_BASE, NU, UPPERS, hertz_args, patch_args  # noqa: E402

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_pml="ob1", OMPI_MCA_btl="self,vader")
GEO_PARAMS = {"ball": "rc0.2_zc0.1", "base": "rc0.2_c0.35"}   # the program's mesh names for hertz_args' parameters
COST_H = (0.04, 0.025, 0.015, 0.01, 0.007, 0.005)
FINE_PATCH = ("hex=1,n=8,m=4", "hex=0,h=0.08,z0=0.5")


def load():
    return float(open("/proc/loadavg").read().split()[0])


def strs(args):
    return [str(a) for a in args]


def timed(cmd, tmp):
    """Run cmd under /usr/bin/time: (completed process, wall, user, peak MB, load)."""
    tf = os.path.join(tmp, "time")
    l0, t0 = load(), time.time()
    p = subprocess.run(["/usr/bin/time", "-o", tf, "-f", "%U %M"] + cmd, cwd=ROOT, env=ENV, capture_output=True, text=True)
    wall = time.time() - t0
    user, rss = open(tf).read().split()[-2:]
    return p, wall, float(user), int(rss) / 1024, max(l0, load())


def hertz_errors(s):
    """test_hertz_quarter's measures from a summary."""
    c = next(iter(s["contact"].values()))
    P = 4 * c["force"][2]
    Es = 1 / ((1 - NU ** 2) / E_BALL + (1 - NU ** 2) / E_BASE)
    a = (3 * P * 1.0 / (4 * Es)) ** (1 / 3)
    p0 = 3 * P / (2 * math.pi * a * a)
    rows = c["contact_nodes"]["rows"]
    spa = sum(r[3] * r[4] for r in rows)
    am = math.sqrt(2.5 * sum(r[3] * r[4] * (r[0] ** 2 + r[1] ** 2) for r in rows) / spa)
    return dict(P=P, a_error=am / a - 1, pmax_error=c["pmax"] / p0 - 1, nodes_in_contact=c["nodes_in_contact"],
                slave_faces=c["surfaces"][0]["faces"] if c["surfaces"][0]["slave"] else c["surfaces"][1]["faces"])


def ours(args, binary=None, log_view=False, ranks=1):
    """One run of the program (on ranks MPI ranks): its figures (and -log_view's events where asked)."""
    with tempfile.TemporaryDirectory() as tmp:
        summary = os.path.join(tmp, "s.json")
        extra = ["-output", "none", "-summary", summary] + (["-log_view", ":" + os.path.join(tmp, "log.txt")] if log_view else [])
        mpi = ["mpiexec", "-n", str(ranks)] if ranks > 1 else []
        p, wall, user, rss, ld = timed(mpi + [binary or os.path.join(ROOT, "bin", "contact")] + strs(args) + extra, tmp)
        if p.returncode:
            raise RuntimeError(f"status {p.returncode}: {p.stdout[-1500:]}\n{p.stderr[-1500:]}")
        s = json.load(open(summary))
        log = open(os.path.join(tmp, "log.txt")).read() if log_view else None
        events, stages = (parse_log(log), parse_stages(log)) if log_view else (None, None)
    r = dict(dofs=s["dofs"], wall=wall, user=user, rss_mb=rss, load=ld, setup=s["time"]["setup"], solve=s["time"]["solve"],
             iterations=s["iterations"], evaluations=s["function_evaluations"], converged=s["converged"], reason=s["tao_reason"],
             step="CG + GAMG" if "Newton step: CG" in p.stdout or "-newton_iterative 1" in " ".join(strs(args)) else "direct")
    if s.get("contact"):
        c = next(iter(s["contact"].values()))
        r.update(hertz_errors(s) if str(args[1]) == "ball,base" else {})
        r["P_pair"] = c["force"][2]
        r["nodes_in_contact"] = c["nodes_in_contact"]
        r["slave_faces"] = next(x["faces"] for x in c["surfaces"] if x["slave"])
    m = re.search(r"(\d+) CG iterations", p.stdout)
    r["cg"] = int(m.group(1)) if m else None
    if events is not None:
        r["events"], r["stages"], r["ranks"] = events, stages, ranks
    return r


def parse_log(text):
    """-log_view's events: {name: [count, time, time's max/min over ranks]} (the first line of each name:
    the first stage that has it; the contact's and the step's events are all in the Solve stage)."""
    ev = {}
    for line in text.splitlines():
        f = line.split()
        if len(f) > 5 and re.match(r"^[A-Za-z][A-Za-z0-9_]*$", f[0]) and re.match(r"^\d+$", f[1]) and f[0] not in ev:
            try:
                ev[f[0]] = [int(f[1]), float(f[3]), float(f[4])]
            except ValueError:
                continue
    return ev


def parse_stages(text):
    """-log_view's summary of stages: {name: time [s]} (the first table's, its lines up to a blank one)."""
    st = {}
    for line in text.split("Summary of Stages", 1)[-1].split("\n\n", 1)[0].splitlines()[2:]:
        m = re.match(r"^\s*\d+:\s+([^:]+): ([0-9.e+-]+)", line)
        if m:
            st[m.group(1).strip()] = float(m.group(2))
    return st


def mesh_files(h, mesh_dir):
    """The ball's and the block's .msh at h, made once by the program (-mesh_only)."""
    files = {b: os.path.join(mesh_dir, f"{b}-h{h:g}_{GEO_PARAMS[b]}.msh") for b in ("ball", "base")}
    if not all(os.path.exists(f) for f in files.values()):
        subprocess.run([os.path.join(ROOT, "bin", "contact")] + strs(hertz_args(h)) + ["-mesh_dir", mesh_dir, "-mesh_only"],
                       cwd=ROOT, env=ENV, check=True, capture_output=True)
    missing = [f for f in files.values() if not os.path.exists(f)]
    if missing:
        raise RuntimeError(f"meshes not made: {missing} (in {sorted(os.listdir(mesh_dir))})")
    return files


def hertz_on(files, h):
    return hertz_args(h) + ["-ball_mesh", files["ball"], "-base_mesh", files["base"]]


def getfem_run(files, extra=()):
    with tempfile.TemporaryDirectory() as tmp:
        p, wall, user, rss, ld = timed(["/usr/bin/python3", os.path.join(ROOT, "scripts", "getfem_hertz3d.py"),
                                        "--ball", files["ball"], "--base", files["base"]] + list(extra), tmp)
    if p.returncode:
        raise RuntimeError(p.stderr[-2000:])
    r = json.loads(p.stdout.strip().splitlines()[-1])
    r.update(wall=wall, user=user, rss_mb=rss, load=ld)
    return r


def median_run(runs):
    m = sorted(runs, key=lambda r: r["wall"])[len(runs) // 2]
    return dict(m, repeats={k: [r.get(k) for r in runs] for k in ("wall", "user", "solve", "load")})


def side_by_side(results, rounds, h, mesh_dir, before, getfem_opts):
    files = mesh_files(h, mesh_dir)
    cases = [(f"hertz-h{h:g} | this program", lambda: ours(hertz_on(files, h))),
             (f"hertz-h{h:g} | GetFEM 5.4", lambda: getfem_run(files, getfem_opts))]
    if before:
        cases.insert(0, (f"hertz-h{h:g} | this program, before", lambda: ours(hertz_on(files, h), before)))
    runs = {name: [] for name, _ in cases}
    for i in range(rounds):
        for name, fn in cases:
            r = fn()
            runs[name].append(r)
            print(f"{name} #{i + 1}: wall {r['wall']:.2f} s, user {r['user']:.2f} s, solve {r['solve']:.2f} s, its {r['iterations']}, "
                  f"a {r['a_error']:+.3%}, pmax {r['pmax_error']:+.3%}, load {r['load']:.1f}", flush=True)
    for name, rs in runs.items():
        results.setdefault("side_by_side", {})[name] = median_run(rs)
    results["side_by_side_meshes"] = {k: os.path.relpath(v, ROOT) for k, v in files.items()}


def lmvm_cases(mesh_dir):
    for h in (0.04, 0.025):
        files = mesh_files(h, mesh_dir)
        yield f"hertz-h{h:g}", hertz_on(files, h)
    yield "patch tet10-on-hex27", patch_args(UPPERS["tet10-on-hex27"])
    lower, upper = FINE_PATCH
    yield "patch tet10-on-hex27, finer", [a if a != "hex=1,n=3,m=2" else lower for a in patch_args(upper)]


def lmvm(results, rounds, mesh_dir, only=None, save=None):
    for scene, args in lmvm_cases(mesh_dir):
        if only and scene not in only:
            continue
        runs = {"nls": [], "lmvm": []}
        for i in range(rounds):
            for solver in runs:
                try:
                    r = ours(args + ["-tao_type", solver])
                except RuntimeError as e:
                    r = dict(failed=str(e)[-300:], wall=float("inf"))
                runs[solver].append(r)
                print(f"{scene} | {solver} #{i + 1}: " + (f"its {r['iterations']}, solve {r['solve']:.2f} s, wall {r['wall']:.2f} s, "
                      f"load {r['load']:.1f}" if "failed" not in r else r["failed"]), flush=True)
        for solver, rs in runs.items():
            ok = [r for r in rs if "failed" not in r]
            results.setdefault("lmvm", {})[f"{scene} | {solver}"] = median_run(ok) if ok else rs[0]
        if save:
            save()


def cost(results, hmin, mesh_dir):
    for h in COST_H:
        if h < hmin:
            break
        name = f"hertz-h{h:g}"
        if name in results.get("cost", {}):
            continue
        files = mesh_files(h, mesh_dir)
        try:
            r = ours(hertz_on(files, h), log_view=True)
        except RuntimeError as e:
            print(f"{name}: failed: {e}", file=sys.stderr)
            break
        results.setdefault("cost", {})[name] = r
        print(f"{name}: {r['dofs']} dofs, {r['slave_faces']} slave faces, wall {r['wall']:.1f} s, its {r['iterations']}, "
              f"{r['step']}, load {r['load']:.1f}", flush=True)
        yield
    if "patch-finer" not in results.get("cost", {}):  # the whole surface in contact
        results.setdefault("cost", {})["patch-finer"] = patch_cost()
        yield


def cost_cg(results, hs, ranks, mesh_dir, force=False):
    """The ball at each h by CG + GAMG (-newton_iterative 1, GAMG by nodes on one level with
    contact) on ranks MPI ranks, one run each with -log_view (kept where already in results)."""
    for h in hs:
        name = f"hertz-h{h:g}, CG + GAMG" + (f", {ranks} ranks" if ranks > 1 else "")
        if name in results.get("cost", {}) and not force:
            continue
        files = mesh_files(h, mesh_dir)
        try:
            r = ours(hertz_on(files, h) + ["-newton_iterative", 1], log_view=True, ranks=ranks)
        except RuntimeError as e:
            print(f"{name}: failed: {e}", file=sys.stderr)
            break
        results.setdefault("cost", {})[name] = r
        c, l, _ = per_step(r)
        print(f"{name}: {r['dofs']} dofs, {r['slave_faces']} slave faces, wall {r['wall']:.1f} s, its {r['iterations']}, "
              f"contact/linear {c / l:.3f}, peak {r['rss_mb']:.0f} MB, load {r['load']:.1f}", flush=True)
        yield


def patch_cost():
    """The finer patch (every slave face in contact) with -log_view."""
    lower, upper = FINE_PATCH
    return ours([a if a != "hex=1,n=3,m=2" else lower for a in patch_args(upper)], log_view=True)


def per_step(r):
    """Per Newton iteration: the contact's work and the linear solve's [s]."""
    ev, its = r["events"], max(r["iterations"], 1)
    t = lambda k: ev.get(k, [0, 0.0])[1]  # noqa: E731
    contact = (t("Mortar3dHessian") + t("Mortar3dEnergyGrad")) / its
    if r["step"] == "direct":
        linear = (t("SubstrStep") + t("SubstrSolve")) / its
    else:
        linear = (t("PCSetUp") + t("KSPSolve")) / its
    return contact, linear, t("SubstrFactor")


def fmt(v, f="{:.3g}"):
    return "" if v is None else f.format(v)


def runs_of(r, key, f="{:.2f}"):
    return ", ".join(f.format(v) for v in r["repeats"][key]) if "repeats" in r else f.format(r[key])


def table(out):
    R = json.load(open(os.path.join(out, "results.json")))
    L = ["# 3D contact: the Hertz ball beside GetFEM, L-BFGS, the cost of a Newton step", "",
         "Generated by `python3 scripts/bench_contact3d.py --table` from `results.json`; the cases and how they",
         "are run: the script's docstring. Times in s: wall the whole process (mesh reading and output included),",
         "user its CPU time (less sensitive to the shared host's load), peak memory in MB (ru_maxrss), `load` the",
         "host's 1-minute load average over the run (2 cores: above 2 every wall time is slowed).", ""]
    sb = R.get("side_by_side", {})
    if sb:
        mine = next((v for k, v in sb.items() if k.endswith("| this program")), None)
        theirs = next((v for k, v in sb.items() if k.endswith("| GetFEM 5.4")), None)
        before = next((v for k, v in sb.items() if k.endswith("| this program, before")), None)
        rounds = len(mine["repeats"]["wall"]) if mine else 0
        L += ["## The quarter Hertz ball beside GetFEM", "",
              f"The same two .msh files ({', '.join(R.get('side_by_side_meshes', {}).values())}); GetFEM counts every dof "
              "(multipliers included), the program the free ones. "
              f"{rounds} rounds interleaved in one sitting; each row is its median-wall run, the brackets every round's figure in order.", "",
              "| code | dofs | wall [s] | user [s] | solve [s] | Newton its | peak MB | a vs Hertz | p_max vs p0 | load |",
              "|---|---|---|---|---|---|---|---|---|---|"]
        for name, r in sb.items():
            L.append(f"| {name.split(' | ')[1]} | {r['dofs']:,} | {r['wall']:.2f} ({runs_of(r, 'wall')}) | {r['user']:.2f} ({runs_of(r, 'user')}) | "
                     f"{r['solve']:.2f} | {r['iterations']} | {r['rss_mb']:.0f} | {r['a_error']:+.2%} | {r['pmax_error']:+.2%} | "
                     f"{r['load']:.1f} ({runs_of(r, 'load', '{:.1f}')}) |")
        if mine and theirs:
            ok = all(abs(mine[k]) <= 0.01 for k in ("a_error", "pmax_error"))
            L += ["", f"GetFEM's whole process over ours: {theirs['wall'] / mine['wall']:.1f} in wall time "
                      f"(rounds: {', '.join(f'{t / o:.1f}' for t, o in zip(theirs['repeats']['wall'], mine['repeats']['wall']))}), "
                      f"{theirs['user'] / mine['user']:.1f} in CPU time; the target 5, "
                      f"{'reached' if theirs['wall'] >= 5 * mine['wall'] else 'not reached'} in wall time; "
                      f"ours within 1 % in a and p0: {'yes' if ok else 'no'}"
                      + (f"; with main's build before (the `before` row): {theirs['wall'] / before['wall']:.1f} in wall time, "
                         f"{theirs['user'] / before['user']:.1f} in CPU time." if before else ".")]
    lm = R.get("lmvm", {})
    if lm:
        L += ["", "## L-BFGS against Newton", "",
              "`-tao_type lmvm` (its defaults: H0 the stiffness plus the contact's Gauss-Newton Hessian through the Schur step, "
              "penalty continuation) against the default Newton, interleaved; the median-wall run of each, the brackets every round's figure. The whole process's CPU time (user) includes the set-up both share.", "",
              "| scene | dofs | solver | converged | iterations | energy evaluations | solve [s] | / Newton | user [s] | / Newton | P from Newton's | load |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for key, r in lm.items():
            scene, solver = key.split(" | ")
            if "failed" in r:
                L.append(f"| {scene} | | {solver} | failed: {r['failed'][-120:]} | | | | | | | | |")
                continue
            n = lm.get(f"{scene} | nls")
            ratio = r["solve"] / n["solve"] if n and "failed" not in n else None
            uratio = r["user"] / n["user"] if n and "failed" not in n else None
            dP = abs(r["P_pair"] / n["P_pair"] - 1) if n and "failed" not in n and solver != "nls" else None
            L.append(f"| {scene} | {r['dofs']:,} | {solver} | {r['converged']} | {r['iterations']} | {r['evaluations']} | "
                     f"{r['solve']:.2f} ({runs_of(r, 'solve')}) | {fmt(ratio, '{:.2f}')} | {r['user']:.2f} ({runs_of(r, 'user')}) | "
                     f"{fmt(uratio, '{:.2f}')} | {fmt(dP, '{:.1e}')} | {r['load']:.1f} |")
    co = R.get("cost", {})
    if co:
        L += ["", "## The cost of a Newton step against the linear solve's, by size", "",
              "One run each with `-log_view`; the `direct` rows by the direct Schur step (h 0.04, 0.025 and the patch by the program's "
              "default of their time, h 0.015 forced), the `CG + GAMG` rows by `-newton_iterative 1`. Per Newton iteration: `contact` the contact's Hessian and its energy and gradient "
              "evaluations (line search included), `linear` the step's own set-up and solve (direct: the capacitance "
              "factorisation and the substitutions; CG: GAMG's set-up and the CG solve); `factor` the direct step's one-off "
              "condensation of the stiffness.", "",
              "`ranks` the MPI ranks (the times then each event's largest over the ranks, `peak MB` the largest process's); "
              "`CG its` the CG iterations over the Newton steps; `Hessian max/min` Mortar3dHessian's time on its slowest rank over "
              "its fastest's. The `CG + GAMG` rows are `-newton_iterative 1` (GAMG by nodes on one level, as with contact).", "",
              "| scene | ranks | dofs | slave faces | nodes in contact | step | Newton its | energy evaluations | CG its | contact / step [s] | linear / step [s] | contact / linear | contact / step / slave face [ms] | factor (once) [s] | Hessian max/min | wall [s] | user [s] | peak MB | a vs Hertz | p_max vs p0 | load |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for name, r in co.items():
            c, l, fac = per_step(r)
            hr = r["events"].get("Mortar3dHessian", [0, 0, None])
            L.append(f"| {name} | {r.get('ranks', 1)} | {r['dofs']:,} | {r['slave_faces']} | {r['nodes_in_contact']} | {r['step']} | {r['iterations']} | "
                     f"{r['evaluations']} | {fmt(r.get('cg'), '{:d}')} | {c:.3f} | {l:.3f} | {c / l if l else float('nan'):.2f} | {1e3 * c / r['slave_faces']:.2f} | {fmt(fac if fac else None, '{:.2f}')} | "
                     f"{fmt(hr[2] if len(hr) > 2 else None, '{:.2f}')} | {r['wall']:.1f} | "
                     f"{fmt(r.get('user'), '{:.2f}')} | {r['rss_mb']:.0f} | {fmt(r.get('a_error'), '{:+.2%}')} | {fmt(r.get('pmax_error'), '{:+.2%}')} | "
                     f"{r['load']:.1f} |")
        cg = {k: r for k, r in co.items() if r["step"] == "CG + GAMG"}
        if cg:
            L += ["", "The same runs' unit costs (the CG + GAMG rows): the contact's per evaluation and slave face, the linear "
                  "step's per Newton step and dof, and the share of the machine each run had (`wall / user`, the whole process's wall time over its CPU time a rank: "
                  "roughly the load's inflation of every event time, by which to divide a time to compare rows). `pattern growths` the times the "
                  "Hessian's pattern was widened and their time (the Mortar3dGrow event, part of the Hessian's; blank: a build before the event).", "",
                  "| scene | ranks | energy evaluation / slave face [ms] | Hessian / slave face [ms] | pattern growths [s] | linear / step / dof [us] | "
                  "CG its / step | peak KB / dof | wall / user |",
                  "|---|---|---|---|---|---|---|---|---|"]
            for name, r in cg.items():
                e, F = r["events"], r["slave_faces"]
                eg, hs = e["Mortar3dEnergyGrad"], e["Mortar3dHessian"]
                _, lin, _ = per_step(r)
                gr = e.get("Mortar3dGrow")
                grows = "" if gr is None else f"{gr[0]} ({gr[1]:.2f})"
                L.append(f"| {name} | {r.get('ranks', 1)} | {1e3 * eg[1] / eg[0] / F:.3f} | {1e3 * hs[1] / hs[0] / F:.3f} | {grows} | "
                         f"{1e6 * lin / r['dofs']:.1f} | {r['cg'] / max(r['iterations'], 1):.1f} | {r['rss_mb'] * 1024 / r['dofs']:.1f} | "
                         f"{r['wall'] * r.get('ranks', 1) / r['user']:.2f} |")
    notes = os.path.join(out, "NOTES.md")
    if os.path.exists(notes):
        L += ["", open(notes).read()]
    open(os.path.join(out, "RESULTS.md"), "w").write("\n".join(L).rstrip() + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "contact3d"))
    ap.add_argument("--mesh-dir", default=os.path.join(ROOT, "build", "meshes", "contact3d"))
    ap.add_argument("--h", type=float, default=0.025, help="the side by side's mesh size at the contact")
    ap.add_argument("--side-by-side", type=int, metavar="N")
    ap.add_argument("--before", help="with --side-by-side: an older build of bin/contact, interleaved")
    ap.add_argument("--getfem-options", default="", help="passed to getfem_hertz3d.py")
    ap.add_argument("--lmvm", type=int, metavar="N")
    ap.add_argument("--lmvm-scenes", help="with --lmvm: these scenes only (names separated by ;)")
    ap.add_argument("--cost", action="store_true")
    ap.add_argument("--cost-hmin", type=float, default=0.01)
    ap.add_argument("--cost-cg", metavar="H,H,...", help="the ball at these h by CG + GAMG (-newton_iterative 1), with -log_view")
    ap.add_argument("--cost-ranks", type=int, default=1, help="with --cost-cg: MPI ranks")
    ap.add_argument("--force", action="store_true", help="with --cost-cg: run again where results.json has the case")
    ap.add_argument("--table", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    os.makedirs(a.mesh_dir, exist_ok=True)
    path = os.path.join(a.out, "results.json")
    results = json.load(open(path)) if os.path.exists(path) else {}

    def save():
        json.dump(results, open(path, "w"), indent=1)

    if a.side_by_side:
        side_by_side(results, a.side_by_side, a.h, a.mesh_dir, a.before, a.getfem_options.split())
        save()
    if a.lmvm:
        lmvm(results, a.lmvm, a.mesh_dir, a.lmvm_scenes.split(";") if a.lmvm_scenes else None, save)
    if a.cost:
        for _ in cost(results, a.cost_hmin, a.mesh_dir):
            save()
    if a.cost_cg:
        for _ in cost_cg(results, [float(h) for h in a.cost_cg.split(",")], a.cost_ranks, a.mesh_dir, a.force):
            save()
    table(a.out)


if __name__ == "__main__":
    main()
