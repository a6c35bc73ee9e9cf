#!/usr/bin/env python3
"""The Newton step's linear solvers on 3D elastic bodies: time, peak memory
and accuracy by size, 1 and 2 ranks (bench/solid3d/).

Blocks: the unit box (tests/meshes/solid/block.geo, skew 0), Hex27
(transfinite, n cells an edge) or Tet10 (Gmsh's, size h), linear (E 1000,
nu 0.3), the smooth trig solution u_i = A sin(2 x_i) prod cos(2 x_j)
(-blk_exact trig) imposed on the whole boundary with its body force: each
run's relative L2 error against it shows the iterative runs as accurate as
the direct. Lame's octant (tests/meshes/solid/shell.geo: a = 1, b = 2,
p = 10, Tet10 at h = 0.1) beside GetFEM's solve of the same .msh
(scripts/getfem_lame.py).

Each case: the whole process's wall time, the JSON's set-up and solve
times, every rank's peak resident memory (/usr/bin/time's %M under
mpiexec), the CG iterations, the relative L2 error. The host's load
average is recorded with each run (the machine is shared: timings under
load are slower by up to the load over the cores).

    python3 scripts/bench_solid3d.py --out bench/solid3d            # every case not yet in results.json
    python3 scripts/bench_solid3d.py --out bench/solid3d --only hex27-1e4
    python3 scripts/bench_solid3d.py --out bench/solid3d --table    # RESULTS.md from results.json
    python3 scripts/bench_solid3d.py --out bench/solid3d --side-by-side 3 [--before OLD/bin/contact]
        # Lame's octant only: ours (default step) and GetFEM (and an older
        # build), interleaved, 3 rounds in one sitting, each kept as its
        # median-wall run with every round's figures
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GEO = "tests/meshes/solid/block.geo"
SHELL = "tests/meshes/solid/shell.geo"
FACES = ("xmin", "xmax", "ymin", "ymax", "zmin", "zmax")
E, NU = 1000.0, 0.3
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_pml="ob1", OMPI_MCA_btl="self,vader")

# the meshes: name -> block.geo parameters and -mesh_size (about 1e4, 1e5, 1e6 free dofs)
MESHES = {
    "hex27-1e4": ("hex=1,skew=0,n=8", 0.1),
    "hex27-1e5": ("hex=1,skew=0,n=17", 0.1),
    "hex27-1e6": ("hex=1,skew=0,n=35", 0.1),
    "tet10-1e4": ("hex=0,skew=0", 0.117),
    "tet10-1e5": ("hex=0,skew=0", 0.055),
    "tet10-1e6": ("hex=0,skew=0", 0.025),
}
# the solvers: name -> (ranks, options)
SOLVERS = {
    "direct (CHOLMOD)": (1, ["-newton_iterative", "0"]),
    "direct (MUMPS)": (1, ["-newton_iterative", "0", "-tao_nls_pc_factor_mat_solver_type", "mumps"]),
    "CG + GAMG, smoothed": (1, ["-newton_iterative", "1", "-tao_nls_pc_gamg_agg_nsmooths", "1"]),
    "CG + GAMG, unsmoothed": (1, ["-newton_iterative", "1", "-tao_nls_pc_gamg_agg_nsmooths", "0"]),
    "direct (MUMPS), 2 ranks": (2, ["-newton_iterative", "0"]),
    "CG + GAMG, smoothed, 2 ranks": (2, ["-newton_iterative", "1", "-tao_nls_pc_gamg_agg_nsmooths", "1"]),
    "CG + GAMG, unsmoothed, 2 ranks": (2, ["-newton_iterative", "1", "-tao_nls_pc_gamg_agg_nsmooths", "0"]),
}
# what runs at 1e6 dofs: a direct factorisation's fill grows as N^(4/3) in 3D
# (measured at 1e5: see the table's peaks), beyond the host's 24 GB shared
BIG = ("CG + GAMG, unsmoothed, 2 ranks", "CG + GAMG, smoothed, 2 ranks")


def load():
    return float(open("/proc/loadavg").read().split()[0])


def run(args, ranks, tmp, binary=None):
    """One run of bin/contact (or binary): its JSON summary, stdout and every rank's peak RSS [MB]."""
    summary = os.path.join(tmp, "s.json")
    times = os.path.join(tmp, "rss")
    cmd = ["/usr/bin/time", "-a", "-o", times, "-f", "%M", binary or os.path.join(ROOT, "bin", "contact")] + args + [
        "-output", "none", "-summary", summary]
    if ranks > 1:
        cmd = ["mpiexec", "--oversubscribe", "-n", str(ranks)] + cmd
    if os.path.exists(times):
        os.remove(times)
    l0, t0 = load(), time.time()
    p = subprocess.run(cmd, cwd=ROOT, env=ENV, capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode:
        raise RuntimeError(f"{' '.join(cmd)}\n{p.stdout[-2000:]}\n{p.stderr[-2000:]}")
    s = json.load(open(summary))
    rss = [int(l) / 1024 for l in open(times).read().split()]
    m = re.search(r"(\d+) CG iterations", p.stdout)
    return dict(dofs=s["dofs"], wall=wall, setup=s["time"]["setup"], solve=s["time"]["solve"], mesh=s["time"]["mesh"],
                rss_mb=rss, cg=int(m.group(1)) if m else None, newton=s["iterations"], load=max(l0, load()),
                chosen=("CG + GAMG" if "Newton step: CG" in p.stdout else "direct" if "Newton step: direct" in p.stdout else None),
                summary=s)


def block_args(mesh):
    params, h = MESHES[mesh]
    args = ["-bodies", "blk", "-blk_geo", GEO, "-blk_geo_params", params, "-mesh_size", repr(h), "-blk_E", repr(E),
            "-blk_nu", repr(NU), "-blk_bc", ",".join(FACES), "-blk_exact", "trig", "-blk_exact_params", "0.001,2",
            "-max_dofs", "5e6"]
    return args + [f"-blk_bc_{f}_exact" for f in FACES]


def lame_args(h):
    p, a, b = 10.0, 1.0, 2.0
    A = p * a ** 3 * (1 - 2 * NU) / (E * (b ** 3 - a ** 3))
    B = p * a ** 3 * b ** 3 * (1 + NU) / (2 * E * (b ** 3 - a ** 3))
    return ["-bodies", "sh", "-sh_geo", SHELL, "-mesh_size", repr(h), "-sh_E", repr(E), "-sh_nu", repr(NU),
            "-sh_bc", "symx,symy,symz", "-sh_bc_symx_components", "x", "-sh_bc_symy_components", "y",
            "-sh_bc_symz_components", "z", "-sh_load", "inner", "-sh_load_inner_pressure", repr(p),
            "-sh_exact", "sphere", "-sh_exact_params", f"{A!r},{B!r}"]


def cases():
    """Smallest first; Lame's octant before the 1e6 blocks."""
    for size in ("1e4", "1e5"):
        for mesh in (f"hex27-{size}", f"tet10-{size}"):
            for solver, (ranks, opts) in SOLVERS.items():
                yield f"{mesh} | {solver}", block_args(mesh) + opts, ranks
    for solver in ("direct (CHOLMOD)", "direct (MUMPS)", "CG + GAMG, smoothed", "CG + GAMG, unsmoothed"):
        ranks, opts = SOLVERS[solver]
        yield f"lame-h0.1 | {solver}", lame_args(0.1) + opts, ranks
    for mesh in ("hex27-1e4", "hex27-1e5", "lame-h0.1"):
        yield f"{mesh} | default", (lame_args(0.1) if mesh.startswith("lame") else block_args(mesh)), 1
    for mesh in ("hex27-1e6", "tet10-1e6"):
        for solver in BIG:
            ranks, opts = SOLVERS[solver]
            yield f"{mesh} | {solver}", block_args(mesh) + opts, ranks


def getfem_run():
    """GetFEM on the Lame octant's own .msh (the program's, generated by its run)."""
    msh = os.path.join(ROOT, "build", "meshes", "scene", "shell-h0.1.msh")
    t0, l0 = time.time(), load()
    p = subprocess.run(["/usr/bin/time", "-f", "%M", "/usr/bin/python3", os.path.join(ROOT, "scripts", "getfem_lame.py"),
                        "--mesh", msh], capture_output=True, text=True, cwd=ROOT)
    if p.returncode:
        raise RuntimeError(p.stderr[-2000:])
    r = json.loads(p.stdout.strip().splitlines()[-1])
    r.update(wall=time.time() - t0, rss_mb=[int(p.stderr.strip().splitlines()[-1]) / 1024], load=max(l0, load()))
    return r


def getfem(out, results):
    results["lame-h0.1 | GetFEM 5.4 (P2, MUMPS)"] = getfem_run()


def ours(args, binary=None):
    with tempfile.TemporaryDirectory() as tmp:
        r = run(args, 1, tmp, binary)
    b = next(iter(r.pop("summary")["bodies"].values()))
    r["error"] = b["l2_error"] / b["l2_norm"]
    return r


def median_run(runs):
    """The run of median wall time, with every run's wall, set-up, solve and load listed."""
    m = sorted(runs, key=lambda r: r["wall"])[len(runs) // 2]
    return dict(m, repeats={k: [r[k] for r in runs] for k in ("wall", "setup", "solve", "cg", "load") if k in m})


def side_by_side(results, repeat, before=None):
    """Lame's octant: ours (the default step), GetFEM and, given before (an
    older build of the program), that build, interleaved repeat times in one
    sitting (the host is shared: each round sees about the same load); each
    kept as its median-wall run, every run's figures in 'repeats'."""
    cases = [("lame-h0.1 | default", lambda: ours(lame_args(0.1))), ("lame-h0.1 | GetFEM 5.4 (P2, MUMPS)", getfem_run)]
    if before:
        cases.insert(0, ("lame-h0.1 | default, before", lambda: ours(lame_args(0.1), before)))
    runs = {name: [] for name, _ in cases}
    for i in range(repeat):
        for name, fn in cases:
            r = fn()
            runs[name].append(r)
            print(f"{name} #{i + 1}: wall {r['wall']:.2f} s, solve {r['solve']:.2f} s, cg {r.get('cg')}, load {r['load']:.1f}", flush=True)
    for name, rs in runs.items():
        results[name] = median_run(rs)


def fmt(v, f="{:.3g}"):
    return "" if v is None else f.format(v)


def table(out):
    R = json.load(open(os.path.join(out, "results.json")))
    lines = ["# 3D elastic bodies: the Newton step's solvers by size", "",
             "Generated by `python3 scripts/bench_solid3d.py --out bench/solid3d --table` from `results.json`;",
             "the cases and how they are run: the script's docstring. Times in s (wall: the whole process,",
             "mesh reading and output included), peak memory per rank in MB (ru_maxrss), `error` the relative",
             "L2 error against the exact solution (trig on the blocks, Lame's on the octant), `load` the host's",
             "1-minute load average during the run (2 cores, shared: above 2 every time here is slowed).", "",
             "| case | solver | dofs | wall | set-up | solve | CG its | peak MB/rank | MB per 1e3 dofs | error | load |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for k, r in R.items():
        mesh, solver = k.split(" | ")
        rss = r.get("rss_mb", [])
        per = sum(rss) / r["dofs"] * 1e3 if rss else None
        lines.append(f"| {mesh} | {solver} | {r['dofs']:,} | {fmt(r.get('wall'))} | {fmt(r.get('setup'))} | {fmt(r.get('solve'))} | "
                     f"{fmt(r.get('cg'), '{}')} | {' + '.join(f'{m:.0f}' for m in rss)} | {fmt(per)} | {fmt(r.get('error'), '{:.2e}')} | "
                     f"{fmt(r.get('load'), '{:.1f}')} |")
    ours, theirs, before = R.get("lame-h0.1 | default"), R.get("lame-h0.1 | GetFEM 5.4 (P2, MUMPS)"), R.get("lame-h0.1 | default, before")
    if ours and theirs:
        def runs(r, key, f="{:.2f}"):
            return ", ".join(f.format(v) for v in r["repeats"][key]) if "repeats" in r else f.format(r[key])
        rounds = len(ours["repeats"]["wall"]) if "repeats" in ours else 1
        lines += ["", "## Lame's octant beside GetFEM", "",
                  "The same .msh (h = 0.1, Tet10, 18,028 cells); GetFEM counts every dof, the program the free ones. "
                  f"`--side-by-side {rounds}`: the runs interleaved, {rounds} rounds in one sitting; each row is its median-wall run,",
                  "the brackets every round's figure in order.", "",
                  "| code | dofs | wall [s] | set-up [s] | solve [s] | CG its | peak MB | relative L2 error of u (volume) | of u_r over the nodes | load |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        rows = ([("this program before (main's build: CG + GAMG on the free dofs, V-cycle)", before)] if before else []) + \
               [("this program (default: CG, two levels: Chebyshev on the nodes, GAMG on the vertices)", ours)]
        for label, r in rows:
            lines.append(f"| {label} | {r['dofs']:,} | {r['wall']:.2f} ({runs(r, 'wall')}) | {r['setup']:.2f} | {r['solve']:.2f} ({runs(r, 'solve')}) | "
                         f"{r['cg']} | {r['rss_mb'][0]:.0f} | {r['error']:.3e} | | {r['load']:.1f} ({runs(r, 'load', '{:.1f}')}) |")
        lines += [f"| GetFEM 5.4 (P2 isoparametric, MUMPS, one core) | {theirs['dofs']:,} | {theirs['wall']:.2f} ({runs(theirs, 'wall')}) | | "
                  f"{theirs['solve']:.2f} ({runs(theirs, 'solve')}) | | {theirs['rss_mb'][0]:.0f} | {theirs['error']:.3e} | {theirs['error_nodes']:.3e} | "
                  f"{theirs['load']:.1f} ({runs(theirs, 'load', '{:.1f}')}) |", "",
                  f"Our whole process takes {ours['wall'] / theirs['wall']:.2f} of GetFEM's (the target: 1/3, "
                  f"{'reached' if ours['wall'] <= theirs['wall'] / 3 else 'not reached'}), "
                  f"our solve {ours['solve'] / theirs['solve']:.2f} of its assembly and factorisation"
                  + (f"; before, {before['wall'] / theirs['wall']:.2f} and {before['solve'] / theirs['solve']:.2f}." if before else ".")]
    for name, title in (("preallocation.json", "direct"), ("preallocation-cg.json", "CG + GAMG, unsmoothed")):
        path = os.path.join(out, name)
        if not os.path.exists(path):
            continue
        P = json.load(open(path))
        lines += ["", f"## The stiffness's preallocation, before and after ({title})", "",
                  "Before: each cell gave each of its rows dim nb columns (a bound); after: the distinct columns of the cells",
                  "around each node (src/solver/pattern.c). Peak memory per rank [MB], measured once each.", "",
                  "| case | dofs | before | after | change |", "|---|---|---|---|---|"]
        for k in P:
            if not k.endswith("| before"):
                continue
            a, b = P[k], P[k.replace("| before", "| after")]
            lines.append(f"| {k.rsplit(' | ', 1)[0].replace(' | ', ', ')} | {a['dofs']:,} | {' + '.join(f'{m:.0f}' for m in a['rss_mb'])} | "
                         f"{' + '.join(f'{m:.0f}' for m in b['rss_mb'])} | {sum(b['rss_mb']) / sum(a['rss_mb']) - 1:+.0%} |")
    lines += ["", open(os.path.join(out, "NOTES.md")).read() if os.path.exists(os.path.join(out, "NOTES.md")) else ""]
    open(os.path.join(out, "RESULTS.md"), "w").write("\n".join(lines).rstrip() + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "solid3d"))
    ap.add_argument("--only", help="run the cases whose name contains this (again, even if recorded)")
    ap.add_argument("--table", action="store_true", help="only regenerate RESULTS.md")
    ap.add_argument("--getfem", action="store_true", help="run GetFEM's Lame octant (after ours, which meshes it)")
    ap.add_argument("--side-by-side", type=int, metavar="N", help="only Lame's octant: ours and GetFEM interleaved, N rounds")
    ap.add_argument("--before", help="with --side-by-side: an older build of bin/contact to interleave as well")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    path = os.path.join(a.out, "results.json")
    results = json.load(open(path)) if os.path.exists(path) else {}
    if a.side_by_side:
        side_by_side(results, a.side_by_side, a.before)
        json.dump(results, open(path, "w"), indent=1)
    elif not a.table:
        for name, args, ranks in cases():
            if (a.only and a.only not in name) or (not a.only and name in results):
                continue
            print(name, flush=True)
            with tempfile.TemporaryDirectory() as tmp:
                try:
                    r = run(args, ranks, tmp)
                except RuntimeError as e:
                    print(f"  failed: {e}", file=sys.stderr)
                    continue
            b = next(iter(r.pop("summary")["bodies"].values()))
            r["error"] = b["l2_error"] / b["l2_norm"]
            results[name] = r
            print(f"  {r['dofs']} dofs, wall {r['wall']:.1f} s, solve {r['solve']:.1f} s, rss {r['rss_mb']}, cg {r['cg']}, "
                  f"error {r['error']:.2e}, load {r['load']:.1f}", flush=True)
            json.dump(results, open(path, "w"), indent=1)
        if a.getfem:
            getfem(a.out, results)
            json.dump(results, open(path, "w"), indent=1)
    table(a.out)


if __name__ == "__main__":
    main()
