#!/usr/bin/env python3
"""Benchmark of bin/contact (issue "Speed"): error against cost.

    python3 scripts/bench.py [--quick] [--repeat N] [--out bench] [--dry-run]

Runs bin/contact as a black box (`-summary <json> -output none`) over a sweep
of scenes, mesh sizes, solver strategies, penalties and gradient tolerances,
and writes <out>/results.csv (one row per run), <out>/RESULTS.md (design,
machine, targets, tables) and the plots <out>/error_vs_time.png,
<out>/time_vs_dofs.png and <out>/ratio_to_linear.png.

Per mesh, in this order: the meshes are generated (`-mesh_only`, cached in
build/meshes/<scene>, so no timed run includes Gmsh), the linear baseline runs
(`-contact_disable -tao_type nls`: one Newton step, i.e. assembly plus one
sparse direct factorisation and solve of the linear elastic problem), then the
contact runs. Each configuration runs --repeat times (wall time and solve time:
medians); its first repeat of the default strategy at k_p = 2e6, gttol 1e-8
also writes -log_view, from which the contact search and the energy
evaluation costs per call are read. Peak memory is each process's maximum
resident set (GNU time %M), summed over the ranks. A run that fails, times out
or does not converge is a row with its reason, never a stop of the sweep.

Only numpy and matplotlib (no scipy). The half model (hertz-half) reports the
full mirrored problem's figures itself (-contact_interface_mirror_y 0), so its
rows use the program's JSON figures like every other row.
"""
import argparse
import csv
import datetime
import hashlib
import json
import math
import os
import platform
import re
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SCENES = {
    "hertz": "meshes/hertz/hertz.opts",
    "hertz-graded": "meshes/hertz-graded/hertz-graded.opts",
    "hertz-half": "meshes/hertz-half/hertz-half.opts",
}

STRATEGIES = {
    "newton": [],
    "newton+cont": ["-penalty_stages", "3", "-penalty_start", "1e-2"],
    "newton+load": ["-load_steps", "3"],
    "ntr": ["-tao_type", "ntr"],
    "lmvm-h0": ["-tao_type", "lmvm"],
    "lmvm": ["-tao_type", "lmvm", "-lmvm_h0", "none", "-tao_max_it", "100000", "-tao_max_funcs", "200000"],
}
ALL_STRATEGIES = list(STRATEGIES)
KPS = [1e4, 1e5, 2e6, 1e8]
TOLS = [1e-8, 1e-5]
REF_KP, REF_TOL, REF_STRATEGY = 2e6, 1e-8, "newton"

CSV_FIELDS = [
    "scene", "h", "strategy", "kp", "gttol", "ranks", "dofs", "wall_median", "solve_median",
    "iterations", "energy_evals", "peak_mb", "P", "pmax_err", "a_err", "l2_err", "P_ref_err",
    "linear_solve_time", "ratio_to_linear", "search_time_per_call", "energy_time_per_call",
    "converged", "reason",
    # extras
    "a_moment_err", "repeats", "wall_runs", "solve_runs", "time_mesh", "time_setup", "time_output",
    "time_total", "hessian_evals", "json_iterations", "search_calls", "energy_calls",
    "contact_hessian_time_per_call", "P_program", "hertz_a", "hertz_pmax", "fem_pmax", "fem_a",
    "P_ref", "P_ref_h", "note",
]


# --------------------------------------------------------------------- sweep

def sweep_plan(quick):
    """A list of (scene, h, tier) and, per entry, the configurations
    (strategy, kp, gttol, ranks, repeat_override) to run on that mesh."""
    plan = []

    def add(scene, h, configs):
        plan.append({"scene": scene, "h": h, "configs": configs})

    if quick:
        for h in (0.2, 0.1, 0.06):
            strategies = ["newton", "newton+cont", "lmvm-h0"] + (["lmvm"] if h >= 0.2 else [])
            cfg = [(s, kp, 1e-8, 1, None) for s in strategies for kp in (2e6, 1e8)]
            if h == 0.06:
                cfg.append(("newton", 2e6, 1e-8, 2, None))
            add("hertz", h, cfg)
        for scene, h in (("hertz-half", 0.06), ("hertz-graded", 0.03)):
            add(scene, h, [(s, kp, 1e-8, 1, None) for s in ("newton", "newton+cont", "lmvm-h0") for kp in (2e6, 1e8)])
        return plan

    # A: small meshes, the full product (plain lmvm only here: it is slow)
    full = [(s, kp, t, 1, None) for s in ALL_STRATEGIES for kp in KPS for t in TOLS]
    # B: medium meshes, every strategy but plain lmvm
    medium = [(s, kp, t, 1, None) for s in ALL_STRATEGIES if s != "lmvm" for kp in KPS for t in TOLS]
    for h in (0.2, 0.1, 0.06):
        add("hertz", h, full)
    add("hertz-half", 0.06, full)
    add("hertz-graded", 0.06, full)
    for h in (0.04, 0.03):
        add("hertz", h, medium)
    add("hertz-half", 0.03, medium)
    add("hertz-graded", 0.03, medium)
    add("hertz-graded", 0.015, medium)
    # C: large meshes, the default strategy at the reference k_p, both
    # tolerances; at the finest (the reference solution of every k_p) all k_p
    add("hertz", 0.02, [("newton", REF_KP, t, 1, None) for t in TOLS])
    add("hertz", 0.015, [("newton", REF_KP, t, 1, None) for t in TOLS]
        + [("newton", kp, 1e-8, 1, 1) for kp in KPS if kp != REF_KP])
    # D: scaling past 1e6 dofs; 1 and 2 ranks on the largest
    add("hertz", 0.01, [("newton", REF_KP, REF_TOL, 1, None)])
    add("hertz", 0.0065, [("newton", REF_KP, REF_TOL, 1, None), ("newton", REF_KP, REF_TOL, 2, None)])
    return plan


# ------------------------------------------------------------------- running

class Runner:
    def __init__(self, args, tmp):
        self.args = args
        self.tmp = tmp
        self.n = 0
        self.env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                        OMPI_MCA_rmaps_base_oversubscribe="1")
        self.log = open(os.path.join(args.out, "bench.log"), "w")

    def say(self, msg):
        line = "[%7.1f s] %s" % (time.time() - self.args.t0, msg)
        print(line, flush=True)
        self.log.write(line + "\n")
        self.log.flush()

    def base_cmd(self, scene, h):
        return [self.args.bin, "-options_file", SCENES[scene], "-mesh_size", repr(h)]

    def mesh(self, scene, h):
        cmd = self.base_cmd(scene, h) + ["-mesh_only"]
        t = time.perf_counter()
        p = subprocess.run(cmd, cwd=ROOT, env=self.env, capture_output=True, text=True)
        if p.returncode != 0:
            return None, "mesh_only failed (rc %d): %s" % (p.returncode, first_error(p.stdout + p.stderr))
        return time.perf_counter() - t, None

    def run_once(self, cmd, ranks, timeout, json_path, extra_files=()):
        """One process; returns (wall, rc, stdout, summary or None, peak_mb)."""
        self.n += 1
        mem = os.path.join(self.tmp, "mem%d" % self.n)
        for f in (json_path,) + tuple(extra_files):
            if f and os.path.exists(f):
                os.remove(f)
        if ranks == 1:
            full = ["/usr/bin/time", "-f", "%M", "-o", mem] + cmd
        else:
            full = (["mpiexec", "--allow-run-as-root", "--oversubscribe", "-n", str(ranks), "sh", "-c",
                     'exec /usr/bin/time -f %M -o "$0.$OMPI_COMM_WORLD_RANK" "$@"', mem] + cmd)
        t = time.perf_counter()
        p = subprocess.Popen(full, cwd=ROOT, env=self.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True, start_new_session=True)
        try:
            out, _ = p.communicate(timeout=timeout)
            rc = p.returncode
        except subprocess.TimeoutExpired:
            try:
                os.killpg(p.pid, signal.SIGTERM)
                out, _ = p.communicate(timeout=10)
            except (subprocess.TimeoutExpired, ProcessLookupError):
                try:
                    os.killpg(p.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                out, _ = p.communicate()
            rc = "timeout"
        wall = time.perf_counter() - t
        peak = 0.0
        files = [mem] if ranks == 1 else [mem + ".%d" % r for r in range(ranks)]
        for f in files:
            try:
                with open(f) as fh:
                    lines = [l for l in fh.read().split("\n") if l.strip()]
                peak += int(lines[-1]) / 1024.0
                os.remove(f)
            except (OSError, ValueError, IndexError):
                peak = float("nan")
        summary = None
        if rc == 0 and os.path.exists(json_path):
            try:
                with open(json_path) as fh:
                    summary = json.load(fh)
            except (OSError, ValueError):
                summary = None
        return wall, rc, out, summary, peak


def first_error(text):
    for line in text.split("\n"):
        if "error" in line.lower() and line.strip():
            return line.strip()[:200]
    lines = [l for l in text.split("\n") if l.strip()]
    return lines[-1][:200] if lines else "no output"


TAO_LINE = re.compile(r"TAO (\S+): (\S+) after (\d+) iterations, (\d+) energy evaluations, (\d+) Hessian")


def parse_tao_line(out):
    m = None
    for m in TAO_LINE.finditer(out or ""):
        pass
    if not m:
        return None
    return {"type": m.group(1), "reason": m.group(2), "iterations": int(m.group(3)),
            "evals": int(m.group(4)), "hessians": int(m.group(5))}


def parse_log_view(path):
    """Total count and max time of the events of interest, over all stages."""
    ev = {}
    try:
        with open(path) as fh:
            text = fh.read()
    except OSError:
        return ev
    # only the first (per-event) table: it ends where the object summary starts
    text = text.split("Memory usage is given in bytes")[0]
    for line in text.split("\n"):
        parts = line.split()
        if len(parts) > 4 and parts[0] in ("ContactSearch", "ContactEnergyGrad", "ElasEnergyGrad",
                                           "ContactHessian", "ElasHessian"):
            try:
                count, t = int(parts[1]), float(parts[3])
            except ValueError:
                continue
            c0, t0 = ev.get(parts[0], (0, 0.0))
            ev[parts[0]] = (c0 + count, t0 + t)
    return ev


def run_config(R, scene, h, strategy, kp, tol, ranks, repeat, log_view):
    a = R.args
    cmd = R.base_cmd(scene, h) + ["-contact_penalty", "%g" % kp, "-tao_gttol", "%g" % tol] + STRATEGIES[strategy]
    row = {"scene": scene, "h": h, "strategy": strategy, "kp": kp, "gttol": tol, "ranks": ranks,
           "converged": False, "reason": "", "note": ""}
    walls, solves, summaries, peaks = [], [], [], []
    tao = None
    ev = {}
    for r in range(repeat):
        R.n += 1
        jp = os.path.join(R.tmp, "run%d.json" % R.n)
        extra = ["-summary", jp, "-output", "none"]
        lv = None
        if log_view and r == 0:
            lv = os.path.join(R.tmp, "log%d.txt" % R.n)
            extra += ["-log_view", ":" + lv]
        wall, rc, out, summ, peak = R.run_once(cmd + extra, ranks, a.timeout, jp,
                                                 extra_files=(lv,) if lv else ())
        tao = parse_tao_line(out) or tao
        if rc == "timeout":
            row["reason"] = "TIMEOUT after %.0f s" % a.timeout
            walls.append(wall)
            break
        if summ is None:
            if tao and tao["reason"] and not tao["reason"].startswith("CONVERGED"):
                row["reason"] = tao["reason"]
            else:
                row["reason"] = "FAILED rc=%s: %s" % (rc, first_error(out))
            walls.append(wall)
            peaks.append(peak)
            break
        walls.append(wall)
        solves.append(summ["time"]["solve"])
        summaries.append(summ)
        peaks.append(peak)
        if lv:
            ev = parse_log_view(lv)
        if jp and os.path.exists(jp):
            os.remove(jp)
    row["repeats"] = len(walls)
    row["wall_runs"] = " ".join("%.3f" % w for w in walls)
    row["solve_runs"] = " ".join("%.3f" % s for s in solves)
    row["wall_median"] = statistics.median(walls) if walls else float("nan")
    row["peak_mb"] = max(peaks) if peaks else float("nan")
    if tao:
        row["iterations"] = tao["iterations"]
        row["energy_evals"] = tao["evals"]
        row["hessian_evals"] = tao["hessians"]
        if not row["reason"]:
            row["reason"] = tao["reason"]
    if summaries:
        s = summaries[0]
        row["converged"] = bool(s.get("converged", False)) and len(summaries) == len(walls)
        row["reason"] = s.get("tao_reason", row["reason"])
        row["solve_median"] = statistics.median(solves)
        row["dofs"] = s["dofs"]
        row["json_iterations"] = s.get("iterations")
        for k in ("mesh", "setup", "output", "total"):
            row["time_" + k] = statistics.median([x["time"][k] for x in summaries])
        fig = {k: s.get(k) for k in ("contact_force", "hertz_a", "hertz_pmax", "fem_pmax", "fem_a",
                                     "fem_a_moment", "pressure_l2_error")}
        fig["P"] = fig.pop("contact_force")
        row["P_program"] = fig["P"]
        row["P"] = fig["P"]
        for k in ("hertz_a", "hertz_pmax", "fem_pmax", "fem_a"):
            row[k] = fig[k]
        row["pmax_err"] = rel(fig["fem_pmax"], fig["hertz_pmax"])
        row["a_err"] = rel(fig["fem_a"], fig["hertz_a"])
        row["a_moment_err"] = rel(fig["fem_a_moment"], fig["hertz_a"])
        row["l2_err"] = fig["pressure_l2_error"]
    if ev:
        ns, ts = ev.get("ContactSearch", (0, 0.0))
        nc, tc = ev.get("ContactEnergyGrad", (0, 0.0))
        _, te = ev.get("ElasEnergyGrad", (0, 0.0))
        nh, th = ev.get("ContactHessian", (0, 0.0))
        row["search_calls"] = ns
        row["energy_calls"] = nc
        row["search_time_per_call"] = ts / ns if ns else float("nan")
        row["energy_time_per_call"] = (tc + te) / nc if nc else float("nan")
        row["contact_hessian_time_per_call"] = th / nh if nh else float("nan")
    return row


def rel(x, ref):
    try:
        if x is None or ref is None or ref == 0 or not math.isfinite(x) or not math.isfinite(ref):
            return float("nan")
        return x / ref - 1.0
    except TypeError:
        return float("nan")


def run_linear(R, scene, h, ranks, repeat):
    cmd = R.base_cmd(scene, h) + ["-contact_disable", "-tao_type", "nls", "-output", "none"]
    solves, walls, dofs, peak, reason = [], [], None, float("nan"), ""
    for _ in range(repeat):
        R.n += 1
        jp = os.path.join(R.tmp, "lin%d.json" % R.n)
        wall, rc, out, summ, peak = R.run_once(cmd + ["-summary", jp], ranks, R.args.timeout, jp)
        if summ is None:
            reason = "linear baseline failed (rc %s): %s" % (rc, first_error(out))
            break
        solves.append(summ["time"]["solve"])
        walls.append(wall)
        dofs = summ["dofs"]
        reason = summ.get("tao_reason", "")
        os.remove(jp)
    return {"solve": statistics.median(solves) if solves else float("nan"),
            "wall": statistics.median(walls) if walls else float("nan"),
            "dofs": dofs, "peak_mb": peak, "reason": reason}


# ------------------------------------------------------------------ analysis

def finite(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def default_runs(rows, scene, kp=None, h=None):
    """The converged one-rank runs of a scene with the default strategy at
    gttol 1e-8, at k_p = kp and mesh size h where given."""
    return [r for r in rows if r["scene"] == scene and r["strategy"] == REF_STRATEGY and r["gttol"] == REF_TOL
            and r["ranks"] == 1 and r["converged"] and (kp is None or r["kp"] == kp) and (h is None or r["h"] == h)]


def attach_references(rows):
    """P_ref per k_p: the converged run of the default strategy at gttol 1e-8
    on the finest uniform mesh that has that k_p. Graded and half-model runs
    are compared with the same uniform reference (the half model reports the
    full problem's P)."""
    refs = {}
    for r in rows:
        if (r["scene"] == "hertz" and r["strategy"] == REF_STRATEGY and r["gttol"] == REF_TOL
                and r["ranks"] == 1 and r["converged"] and finite(r.get("P"))):
            cur = refs.get(r["kp"])
            if cur is None or r["h"] < cur[1]:
                refs[r["kp"]] = (r["P"], r["h"])
    for r in rows:
        ref = refs.get(r["kp"])
        if ref and finite(r.get("P")):
            r["P_ref"], r["P_ref_h"] = ref
            r["P_ref_err"] = abs(r["P"] - ref[0]) / ref[0]
    return refs


def on_ref_mesh(r):
    return r["scene"] in ("hertz", "hertz-half") and r.get("P_ref_h") == r["h"]


def fit_exponent(x, y, lo=1e4, hi=1.2e6):
    pts = [(a, b) for a, b in zip(x, y) if finite(a) and finite(b) and lo <= a <= hi and b > 0]
    if len(pts) < 2:
        return None, len(pts)
    lx = np.log([p[0] for p in pts])
    ly = np.log([p[1] for p in pts])
    k, c = np.polyfit(lx, ly, 1)
    return (float(k), float(c)), len(pts)


def fmt(x, f="%.3g"):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    if isinstance(x, str):
        return x
    return f % x


def pct(x):
    if not finite(x):
        return "-"
    return ("%.2f %%" % (100 * x)) if abs(x) >= 1e-3 else ("%.2g %%" % (100 * x))


def config_name(r):
    s = "%s h=%g %s k_p=%g tol=%g" % (r["scene"], r["h"], r["strategy"], r["kp"], r["gttol"])
    if r["ranks"] != 1:
        s += " (%d ranks)" % r["ranks"]
    return s


def cheapest(rows, key, thresholds, exclude=None):
    out = []
    for t in thresholds:
        best = None
        for r in rows:
            if not r["converged"] or r["ranks"] != 1 or not finite(r.get(key)) or not finite(r.get("wall_median")):
                continue
            if exclude and exclude(r):
                continue
            if abs(r[key]) <= t and (best is None or r["wall_median"] < best["wall_median"]):
                best = r
        out.append((t, best))
    return out


def machine_info():
    info = {}
    info["nproc"] = subprocess.run(["nproc"], capture_output=True, text=True).stdout.strip()
    cpu = ""
    try:
        with open("/proc/cpuinfo") as fh:
            for line in fh:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    info["cpu"] = cpu
    try:
        with open("/proc/meminfo") as fh:
            info["mem"] = "%.1f GB" % (int(fh.readline().split()[1]) / 1024 ** 2)
    except (OSError, ValueError, IndexError):
        info["mem"] = "?"
    p = subprocess.run(["update-alternatives", "--display", "libblas.so.3-x86_64-linux-gnu"],
                       capture_output=True, text=True)
    blas = [l.strip() for l in p.stdout.split("\n") if "currently points" in l]
    info["blas"] = blas[0] if blas else (p.stdout.strip().split("\n")[0] if p.stdout else "unknown")
    p = subprocess.run(["pkg-config", "--modversion", "petsc"], capture_output=True, text=True)
    info["petsc"] = p.stdout.strip() or "?"
    info["os"] = platform.platform()
    return info


def git_info():
    def g(*a):
        p = subprocess.run(["git"] + list(a), cwd=ROOT, capture_output=True, text=True)
        return p.stdout.strip()
    head = g("rev-parse", "--short", "HEAD")
    dirty = g("status", "--short", "--untracked-files=no")
    return head + (" (with uncommitted changes)" if dirty else "")


# ------------------------------------------------------------------- plots

def plots(rows, out, fit_solve, fit_lin):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    colors = {s: c for s, c in zip(ALL_STRATEGIES, ["C0", "C1", "C2", "C3", "C4", "C5"])}
    markers = {"hertz": "o", "hertz-graded": "s", "hertz-half": "^"}

    # error against time, one curve (Pareto front) per strategy
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2))
    for ax, key, title in ((axes[0], "l2_err", "profile L2 error against Hertz"),
                           (axes[1], "P_ref_err", "|P - P_ref| / P_ref (finest uniform mesh, same k_p; its own runs left out)")):
        for s in ALL_STRATEGIES:
            pts = [r for r in rows if r["strategy"] == s and r["converged"] and r["ranks"] == 1
                   and finite(r.get(key)) and finite(r.get("wall_median")) and abs(r[key]) > 0
                   and not (key == "P_ref_err" and on_ref_mesh(r))]
            if not pts:
                continue
            for sc, mk in markers.items():
                q = [r for r in pts if r["scene"] == sc]
                if q:
                    ax.scatter([r["wall_median"] for r in q], [abs(r[key]) for r in q], s=14, marker=mk,
                               color=colors[s], alpha=0.35)
            pts.sort(key=lambda r: r["wall_median"])
            fx, fy, best = [], [], float("inf")
            for r in pts:
                if abs(r[key]) < best:
                    best = abs(r[key])
                    fx.append(r["wall_median"])
                    fy.append(best)
            ax.step(fx, fy, where="post", color=colors[s], label=s, lw=1.8)
        for t in (0.1, 0.03, 0.01):
            ax.axhline(t, color="gray", lw=0.6, ls=":")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time per run, median [s]")
        ax.set_ylabel("relative error")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(title="strategy (lines: best error so far)", fontsize=8)
    fig.text(0.5, 0.005, "markers: o uniform, s graded, ^ half model; converged runs, 1 rank", ha="center", fontsize=8)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    fig.savefig(os.path.join(out, "error_vs_time.png"), dpi=120)
    plt.close(fig)

    # time against dofs
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    sel = sorted(default_runs(rows, "hertz", REF_KP), key=lambda r: r["dofs"])
    if sel:
        d = np.array([r["dofs"] for r in sel], float)
        ax.loglog(d, [r["solve_median"] for r in sel], "o-", color="C0", label="contact solve (newton)")
        ax.loglog(d, [r["wall_median"] for r in sel], "s--", color="C0", alpha=0.5, label="contact wall")
        ax.loglog(d, [r.get("linear_solve_time", float("nan")) for r in sel], "^-", color="C2",
                  label="one linear elastic solve")
        for fit, col, name in ((fit_solve, "C0", "contact solve"), (fit_lin, "C2", "linear solve")):
            if fit:
                k, c = fit
                xx = np.array([max(1e4, d.min()), min(1.2e6, d.max())])
                ax.loglog(xx, np.exp(c) * xx ** k, ":", color=col, lw=2,
                          label="%s fit 1e4..1e6: exponent %.2f" % (name, k))
    other = [r for r in rows if r["scene"] != "hertz" and r["strategy"] == REF_STRATEGY and r["kp"] == REF_KP
             and r["gttol"] == REF_TOL and r["ranks"] == 1 and r["converged"]]
    for sc, mk in (("hertz-graded", "s"), ("hertz-half", "^")):
        q = [r for r in other if r["scene"] == sc]
        if q:
            ax.loglog([r["dofs"] for r in q], [r["solve_median"] for r in q], mk, color="C3", label=sc + " solve")
    ax.set_xlabel("dofs")
    ax.set_ylabel("time [s]")
    ax.set_title("time against dofs (k_p = 2e6, gttol 1e-8, 1 rank)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "time_vs_dofs.png"), dpi=120)
    plt.close(fig)

    # ratio to one linear solve
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    for s in ALL_STRATEGIES:
        q = sorted([r for r in rows if r["scene"] == "hertz" and r["strategy"] == s and r["kp"] == REF_KP
                    and r["gttol"] == REF_TOL and r["ranks"] == 1 and r["converged"]
                    and finite(r.get("ratio_to_linear"))], key=lambda r: r["dofs"])
        if q:
            ax.loglog([r["dofs"] for r in q], [r["ratio_to_linear"] for r in q], "o-", color=colors[s], label=s)
    for sc, mk in (("hertz-graded", "s"), ("hertz-half", "^")):
        q = [r for r in rows if r["scene"] == sc and r["kp"] == REF_KP and r["gttol"] == REF_TOL and r["converged"]
             and r["ranks"] == 1 and finite(r.get("ratio_to_linear"))]
        for r in q:
            ax.loglog(r["dofs"], r["ratio_to_linear"], mk, color=colors[r["strategy"]], alpha=0.6)
    ax.axhline(10, color="k", ls="--", lw=1, label="target: 10")
    ax.set_xlabel("dofs")
    ax.set_ylabel("solve time / one linear elastic solve")
    ax.set_title("time-to-solution in linear solves (k_p = 2e6, gttol 1e-8; s graded, ^ half)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "ratio_to_linear.png"), dpi=120)
    plt.close(fig)


# ------------------------------------------------------------------ report

def write_csv(rows, path):
    with open(path + ".tmp", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=CSV_FIELDS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (repr(v) if isinstance(v, float) else v) for k, v in r.items() if v is not None})
    os.replace(path + ".tmp", path)


def read_csv(path):
    rows = []
    with open(path, newline="") as fh:
        for rec in csv.DictReader(fh):
            r = {}
            for k, v in rec.items():
                if v is None or v == "":
                    continue
                if v in ("True", "False"):
                    r[k] = v == "True"
                    continue
                try:
                    r[k] = int(v) if re.fullmatch(r"-?\d+", v) else float(v)
                except ValueError:
                    r[k] = v
            for k in ("scene", "strategy", "reason", "note", "wall_runs", "solve_runs"):
                if k in r:
                    r[k] = str(r[k])
            r["h"] = float(r["h"])
            r["kp"] = float(r["kp"])
            r["gttol"] = float(r["gttol"])
            r.setdefault("reason", "")
            r.setdefault("converged", False)
            rows.append(r)
    return rows


def report(rows, args, info, meshes, elapsed, load):
    out = args.out
    refs = attach_references(rows)
    ref_sel = sorted(default_runs(rows, "hertz", REF_KP), key=lambda r: r["dofs"])
    fit_solve, n_solve = fit_exponent([r["dofs"] for r in ref_sel], [r["solve_median"] for r in ref_sel])
    fit_wall, _ = fit_exponent([r["dofs"] for r in ref_sel], [r["wall_median"] for r in ref_sel])
    fit_lin, _ = fit_exponent([r["dofs"] for r in ref_sel], [r.get("linear_solve_time") for r in ref_sel])
    write_csv(rows, os.path.join(out, "results.csv"))
    try:
        plots(rows, out, fit_solve, fit_lin)
    except Exception as e:
        print("plots failed: %s" % e, file=sys.stderr)

    L = []
    A = L.append
    A("# Benchmark: error against cost (`scripts/bench.py%s`)" % (" --quick" if args.quick else ""))
    A("")
    A("Generated %s by `python3 scripts/bench.py %s` in %.0f s of wall time (%d runs). Binary: `%s` "
      "(git %s; sha256 %s). Figures are from one shared machine: other work ran beside the sweep "
      "(load average %s at the start, %s at the end), so single timings carry noise of tens of per cent."
      % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), " ".join(sys.argv[1:]), elapsed,
         len(rows), os.path.relpath(args.bin_orig, ROOT) if args.bin_orig.startswith(ROOT) else args.bin_orig,
         git_info(), args.bin_sha, load[0], load[1]))
    A("")
    A("## Machine")
    A("")
    A("| | |")
    A("|---|---|")
    A("| cores (nproc) | %s |" % info["nproc"])
    A("| CPU | %s |" % info["cpu"])
    A("| memory | %s |" % info["mem"])
    A("| BLAS (`update-alternatives --display libblas.so.3-x86_64-linux-gnu`) | %s |" % info["blas"])
    A("| PETSc | %s |" % info["petsc"])
    A("| OS | %s |" % info["os"])
    A("")
    A("## Design")
    A("")
    if args.quick:
        A("Quick variant: uniform hertz meshes h = 0.2, 0.1, 0.06; strategies newton, newton+cont, lmvm-h0 "
          "(plain lmvm at h = 0.2 only); k_p = 2e6 and 1e8; gttol 1e-8; the half model at h = 0.06 and the "
          "graded scene at h = 0.03 (its patch resolution) with the same strategies and k_p; one 2-rank run at "
          "h = 0.06; repeat %d; per-run time limit %g s. The reference P (\"finest mesh\") is therefore the h = 0.06 "
          "uniform run: errors against it say how far coarser meshes and other strategies are from it, not from "
          "the converged answer. The scaling targets need the full sweep." % (args.repeat, args.timeout))
    else:
        A("The full product (every mesh x strategy x k_p x tolerance) is too large; the sweep is tiered:")
        A("")
        A("| tier | meshes | strategies | k_p | gttol | repeats |")
        A("|---|---|---|---|---|---|")
        A("| A | hertz h = 0.2, 0.1, 0.06; hertz-half 0.06; hertz-graded 0.06 | all six (plain lmvm only here) "
          "| 1e4, 1e5, 2e6, 1e8 | 1e-8, 1e-5 | %d |" % args.repeat)
        A("| B | hertz h = 0.04, 0.03; hertz-half 0.03; hertz-graded 0.03, 0.015 | all but plain lmvm "
          "| 1e4, 1e5, 2e6, 1e8 | 1e-8, 1e-5 | %d |" % args.repeat)
        A("| C | hertz h = 0.02, 0.015 | newton | 2e6 (0.015: all four, 1e-8, once: the references) "
          "| 1e-8, 1e-5 | %d |" % args.repeat)
        A("| D | hertz h = 0.01, 0.0065 (about 0.46e6 and 1.07e6 dofs) | newton; 1 and 2 ranks at 0.0065 | 2e6 "
          "| 1e-8 | %d |" % args.repeat)
        A("")
        A("Plain lmvm (the original study's method) is limited to tier A because it needs thousands of "
          "iterations. Per-run time limit: %g s (a run over it is a row with reason TIMEOUT)." % args.timeout)
    A("")
    A("Strategies: " + "; ".join("**%s** `%s`" % (s, " ".join(v) or "(defaults: -tao_type nls)")
                                 for s, v in STRATEGIES.items()) + ".")
    A("")
    A("Definitions. *wall*: the process's wall time (start to exit, mesh read included, Gmsh not: meshes "
      "are generated beforehand), median of the repeats. *solve*: the program's Solve stage (JSON time.solve). "
      "*linear*: the Solve stage of `-contact_disable -tao_type nls` on the same mesh, run just before that mesh's "
      "contact runs (one Newton step: assembly, one sparse direct factorisation and solve); *ratio* = solve / "
      "linear. *peak MB*: maximum resident set (GNU time %M), summed over ranks. *iterations, energy evals*: "
      "the totals printed on the program's `TAO ...` line (over all stages for continuation and load steps). "
      "Errors against Hertz are the program's (p_max: largest Gauss-point pressure; a: half the loaded "
      "length; l2: relative L2 error of the profile; means of the two one-sided surfaces; the half model "
      "reports those of the full mirrored problem). *P_ref_err* = |P - P_ref| / P_ref, P_ref = the newton, gttol 1e-8 run on the finest "
      "uniform mesh run at that k_p (graded and half-model runs compared with the same uniform reference). "
      "*search / energy per call*: from -log_view of the newton, k_p = 2e6, 1e-8 run of each mesh: "
      "ContactSearch time per call, and (ContactEnergyGrad + ElasEnergyGrad time) per ContactEnergyGrad call "
      "(the search is inside ContactEnergyGrad).")
    A("")
    A("References P_ref: " + ", ".join("k_p = %g: P = %.6g (h = %g)" % (k, v[0], v[1]) for k, v in sorted(refs.items())) + ".")
    A("")

    # targets
    A("## Targets")
    A("")
    A("| target | measured | status |")
    A("|---|---|---|")
    h06 = [r for r in rows if r["scene"] == "hertz" and r["h"] == 0.06 and r["kp"] == REF_KP and r["gttol"] == REF_TOL
           and r["ranks"] == 1]
    d06 = [r for r in h06 if r["strategy"] == REF_STRATEGY]
    conv06 = [r for r in h06 if r["converged"] and finite(r.get("solve_median"))]
    if conv06:
        best = min(conv06, key=lambda r: r["solve_median"])
        dtxt = ("default (newton) %.3g s" % d06[0]["solve_median"]) if d06 and finite(d06[0].get("solve_median")) else "default: not converged"
        dok = bool(d06) and d06[0]["converged"] and d06[0]["solve_median"] <= 0.5
        st = "MET" if dok else ("MET with %s only" % best["strategy"] if best["solve_median"] <= 0.5 else "NOT MET")
        A("| reference scene, h = 0.06, k_p = 2e6, gttol 1e-8, solve time <= 0.5 s on one core | %s; fastest: %s "
          "%.3g s (%d iterations) | %s |" % (dtxt, best["strategy"], best["solve_median"], best.get("iterations", 0), st))
    else:
        A("| reference scene, h = 0.06, solve <= 0.5 s | no converged run | NOT MEASURED |")
    rat = [r for r in ref_sel if finite(r.get("ratio_to_linear"))]
    big_rat = [r for r in rat if r["dofs"] >= 1e4]
    if big_rat:
        worst = max(big_rat, key=lambda r: r["ratio_to_linear"])
        small = [r for r in rat if r["dofs"] < 1e4 and r["ratio_to_linear"] > 10]
        A("| time-to-solution <= 10 linear solves of the same mesh (newton, k_p 2e6, 1e-8, uniform meshes from 1e4 "
          "dofs; below, a linear solve takes milliseconds and fixed costs dominate) | %s; worst %.1f at %d dofs | %s%s |"
          % (", ".join("%.1f (%d dofs)" % (r["ratio_to_linear"], r["dofs"]) for r in rat), worst["ratio_to_linear"],
             worst["dofs"], status(worst["ratio_to_linear"] <= 10),
             (" (over 10 below 1e4 dofs: %s)" % ", ".join("%d dofs" % r["dofs"] for r in small)) if small else ""))
    else:
        A("| time-to-solution <= 10 linear solves | - | NOT MEASURED |")
    span = [r["dofs"] for r in ref_sel if 1e4 <= r["dofs"] <= 1.2e6]
    if fit_solve and span and max(span) >= 5e5:
        A("| cost exponent <= 1.2 from 1e4 to 1e6 dofs (solve time, newton) | %.2f over %d meshes, %d..%d dofs "
          "(wall time: %.2f; linear solve: %s) | %s |" % (fit_solve[0], n_solve, min(span), max(span),
                                                          fit_wall[0] if fit_wall else float("nan"),
                                                          fmt(fit_lin[0] if fit_lin else None, "%.2f"),
                                                          status(fit_solve[0] <= 1.2)))
    else:
        A("| cost exponent <= 1.2 from 1e4 to 1e6 dofs | %s | NOT MEASURED (needs meshes up to 1e6 dofs: full sweep) |"
          % ("%.2f over %d..%d dofs only" % (fit_solve[0], min(span), max(span)) if fit_solve and span else "-"))
    big = ref_sel[-1] if ref_sel else None
    if big and finite(big.get("time_total")):
        frac = (big["time_mesh"] + big["time_setup"] + big["time_output"]) / big["time_total"]
        ok = big["dofs"] >= 5e5
        A("| mesh reading + set-up + output < 20 %% of the total at 1e6 dofs | %.1f %% at %d dofs (mesh %.2f s, "
          "set-up %.2f s, output %.2f s of %.2f s; output off: -output none) | %s |"
          % (100 * frac, big["dofs"], big["time_mesh"], big["time_setup"], big["time_output"], big["time_total"],
             status(frac < 0.2) if ok else "NOT MEASURED at 1e6 dofs (largest mesh here %d dofs: %s there)"
             % (big["dofs"], status(frac < 0.2))))
    if big and finite(big.get("search_time_per_call")):
        f = big["search_time_per_call"] / big["energy_time_per_call"]
        ok = big["dofs"] >= 5e5
        A("| contact search a small fraction of an energy evaluation at 1e6 dofs | search %.3g ms per call, "
          "energy evaluation %.3g ms per call: %.2f %% at %d dofs | %s |"
          % (1e3 * big["search_time_per_call"], 1e3 * big["energy_time_per_call"], 100 * f, big["dofs"],
             (status(f < 0.1) + " (taken as < 10 %)") if ok else "NOT MEASURED at 1e6 dofs (%s at %d dofs)" % (status(f < 0.1), big["dofs"])))
    A("")

    # cheapest
    A("## Cheapest configuration reaching an error")
    A("")
    A("Cheapest = smallest median wall time among converged one-rank runs.")
    A("")
    for key, title, excl in (
            ("l2_err", "profile L2 error against Hertz", None),
            ("P_ref_err", "contact force P against the finest-mesh reference of the same k_p (runs at the "
                          "reference's h left out, the half model's too: they share its discretisation)",
             on_ref_mesh)):
        A("**%s**" % title)
        A("")
        A("| error <= | configuration | dofs | wall [s] | solve [s] | error | iterations |")
        A("|---|---|---|---|---|---|---|")
        for t, r in cheapest(rows, key, (0.10, 0.03, 0.01), excl):
            if r is None:
                A("| %g %% | none reached it | | | | | |" % (100 * t))
            else:
                A("| %g %% | %s | %d | %.3g | %.3g | %s | %s |" % (100 * t, config_name(r), r["dofs"], r["wall_median"],
                                                                  r["solve_median"], pct(r[key]), r.get("iterations", "-")))
        A("")
    A("On the reference scene Hertz is not exact (a/R = 0.36, a block 1 wide): the profile error against Hertz "
      "levels off near 8-9 % as h falls (README), so 3 % and 1 % against Hertz are out of reach of any "
      "configuration of this scene; the P error against the finest mesh is the discretisation/solver measure.")
    A("")

    # scaling table
    A("## Scaling: newton, k_p = 2e6, gttol 1e-8, uniform meshes")
    A("")
    A("| h | dofs | iterations | energy evals | solve [s] | wall [s] | linear [s] | ratio | peak MB | "
      "mesh+setup+output | search / call [ms] | energy eval / call [ms] | search share | contact Hessian / call [ms] |")
    A("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in ref_sel:
        frac = ((r["time_mesh"] + r["time_setup"] + r["time_output"]) / r["time_total"]) if finite(r.get("time_total")) else float("nan")
        sh = (r["search_time_per_call"] / r["energy_time_per_call"]) if finite(r.get("search_time_per_call")) else float("nan")
        A("| %g | %d | %s | %s | %.3g | %.3g | %s | %s | %.0f | %s | %s | %s | %s | %s |" % (
            r["h"], r["dofs"], r.get("iterations", "-"), r.get("energy_evals", "-"), r["solve_median"], r["wall_median"],
            fmt(r.get("linear_solve_time")), fmt(r.get("ratio_to_linear"), "%.1f"), r["peak_mb"], pct(frac),
            fmt(1e3 * r["search_time_per_call"] if finite(r.get("search_time_per_call")) else None),
            fmt(1e3 * r["energy_time_per_call"] if finite(r.get("energy_time_per_call")) else None), pct(sh),
            fmt(1e3 * r["contact_hessian_time_per_call"] if finite(r.get("contact_hessian_time_per_call")) else None)))
    A("")
    if fit_solve:
        A("Fitted exponents over 1e4..1.2e6 dofs (%d meshes): solve time %.2f, wall %s, one linear solve %s."
          % (n_solve, fit_solve[0], fmt(fit_wall[0] if fit_wall else None, "%.2f"), fmt(fit_lin[0] if fit_lin else None, "%.2f")))
    else:
        A("Fitted exponent: fewer than two meshes in 1e4..1.2e6 dofs.")
    A("")

    # ranks
    A("## 1 and 2 ranks on the largest mesh")
    A("")
    two = [r for r in rows if r["ranks"] == 2]
    if two:
        t = two[0]
        one = [r for r in rows if r["scene"] == t["scene"] and r["h"] == t["h"] and r["strategy"] == t["strategy"]
               and r["kp"] == t["kp"] and r["gttol"] == t["gttol"] and r["ranks"] == 1]
        A("| ranks | h | dofs | iterations | solve [s] | wall [s] | peak MB (sum) | P | converged |")
        A("|---|---|---|---|---|---|---|---|---|")
        for r in one + two:
            A("| %d | %g | %s | %s | %s | %s | %s | %s | %s |" % (r["ranks"], r["h"], r.get("dofs", "-"), r.get("iterations", "-"),
                                                             fmt(r.get("solve_median")), fmt(r.get("wall_median")),
                                                             fmt(r.get("peak_mb"), "%.0f"), fmt(r.get("P"), "%.7g"),
                                                             r["converged"] or r["reason"]))
        if one and finite(one[0].get("solve_median")) and finite(t.get("solve_median")):
            A("")
            A("Speed-up of the solve on 2 ranks: %.2f (the machine has %s cores, shared)." %
              (one[0]["solve_median"] / t["solve_median"], info["nproc"]))
    else:
        A("No 2-rank run in this sweep.")
    A("")

    # half model
    A("## Half model (y = 0 symmetry)")
    A("")
    half = default_runs(rows, "hertz-half")
    if half:
        A("hertz-half is the upper half of the reference scene, cut at y = 0 with u_y = 0 on the cut. Its pair's "
          "`-contact_interface_mirror_y 0` makes the program report the full mirrored problem (P = 2 abs(f_x), "
          "profiles mirrored about the cut), so its figures compare directly with the full model's at the same h "
          "and k_p (newton, gttol 1e-8).")
        A("")
        A("| h | k_p | dofs half / full | P half / full | P difference | profile L2 error half / full "
          "| solve half / full [s] |")
        A("|---|---|---|---|---|---|---|")
        for r in half:
            f = default_runs(rows, "hertz", r["kp"], r["h"])
            f = f[0] if f else {}
            A("| %g | %g | %d / %s | %.7g / %s | %s | %s / %s | %s / %s |" % (
                r["h"], r["kp"], r["dofs"], f.get("dofs", "-"), r["P"], fmt(f.get("P"), "%.7g"),
                ("%+.1e" % (r["P"] / f["P"] - 1)) if finite(f.get("P")) else "-",
                pct(r["l2_err"]), pct(f.get("l2_err")), fmt(r.get("solve_median")), fmt(f.get("solve_median"))))
    else:
        A("No converged half-model run.")
    A("")

    # graded
    A("## Graded meshes")
    A("")
    gr = default_runs(rows, "hertz-graded")
    if gr:
        A("`-mesh_size h` is the size on the contact patch (within 0.5 of the first contact point); the far field "
          "is 0.1 in the disc and 0.2 in the block (meshes/hertz-graded/hertz-graded.opts).")
        A("")
        A("| h (patch) | k_p | dofs | solve [s] | wall [s] | l2 err | p_max err | a err | P_ref err "
          "| uniform at same h: dofs, l2 err | uniform with nearest dofs: h, dofs, l2 err |")
        A("|---|---|---|---|---|---|---|---|---|---|---|")
        for r in gr:
            f = default_runs(rows, "hertz", r["kp"], r["h"])
            u = default_runs(rows, "hertz", r["kp"])
            u = min(u, key=lambda x: abs(math.log(x["dofs"] / r["dofs"]))) if u else None
            A("| %g | %g | %d | %.3g | %.3g | %s | %s | %s | %s | %s | %s |" % (
                r["h"], r["kp"], r["dofs"], r["solve_median"], r["wall_median"], pct(r["l2_err"]), pct(r["pmax_err"]),
                pct(r["a_err"]), pct(r.get("P_ref_err")),
                ("%d, %s" % (f[0]["dofs"], pct(f[0]["l2_err"]))) if f else "not run",
                ("%g, %d, %s" % (u["h"], u["dofs"], pct(u["l2_err"]))) if u else "-"))
    else:
        A("No converged graded run.")
    A("")

    # strategies at h = 0.06
    A("## Strategies on the reference mesh (hertz, h = 0.06)")
    A("")
    A("| strategy | k_p | gttol | iterations | energy evals | solve [s] | wall [s] | peak MB | l2 err | P_ref err | reason |")
    A("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if r["scene"] == "hertz" and r["h"] == 0.06 and r["ranks"] == 1:
            A("| %s | %g | %g | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                r["strategy"], r["kp"], r["gttol"], r.get("iterations", "-"), r.get("energy_evals", "-"),
                fmt(r.get("solve_median")), fmt(r.get("wall_median")), fmt(r.get("peak_mb"), "%.0f"),
                pct(r.get("l2_err")), pct(r.get("P_ref_err")), r["reason"]))
    A("")

    bad = [r for r in rows if not r["converged"]]
    A("## Runs that failed or did not converge (%d of %d)" % (len(bad), len(rows)))
    A("")
    if bad:
        A("| configuration | reason | iterations | wall [s] |")
        A("|---|---|---|---|")
        for r in bad:
            A("| %s | %s | %s | %s |" % (config_name(r), r["reason"], r.get("iterations", "-"), fmt(r.get("wall_median"))))
    else:
        A("None.")
    A("")
    if meshes:
        A("## Meshes")
        A("")
        A("| scene | h | dofs | Gmsh / -mesh_only [s] | linear solve [s] | linear note |")
        A("|---|---|---|---|---|---|")
        for m in meshes:
            A("| %s | %g | %s | %s | %s | %s |" % (m["scene"], m["h"], m.get("dofs") or "-", fmt(m.get("mesh_time")),
                                                 fmt(m.get("linear")), m.get("note", "")))
        A("")
    A("Files: results.csv (one row per configuration), error_vs_time.png, time_vs_dofs.png, ratio_to_linear.png, "
      "bench.log (the run's log), run.json (its settings; `--report-only` rewrites this file and the plots from them).")
    with open(os.path.join(out, "RESULTS.md.tmp"), "w") as fh:
        fh.write("\n".join(L) + "\n")
    os.replace(os.path.join(out, "RESULTS.md.tmp"), os.path.join(out, "RESULTS.md"))


def status(ok):
    return "MET" if ok else "NOT MET"


# -------------------------------------------------------------------- main

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="the quick variant (target: under 5 minutes on 2 cores)")
    ap.add_argument("--repeat", type=int, default=None, help="runs per configuration (default 3; quick 1)")
    ap.add_argument("--out", default="bench", help="output directory (default bench)")
    ap.add_argument("--bin", default="bin/contact", help="the program (copied once at the start, so that a "
                    "rebuild during the sweep does not mix versions)")
    ap.add_argument("--timeout", type=float, default=None, help="per-run time limit in s (default 1800; quick 90)")
    ap.add_argument("--only", default=None, help="restrict to scene[:h] entries, comma-separated (e.g. hertz:0.01)")
    ap.add_argument("--dry-run", action="store_true", help="print the plan and exit")
    ap.add_argument("--report-only", action="store_true", help="rewrite RESULTS.md and the plots from "
                    "<out>/results.csv and <out>/run.json, running nothing")
    args = ap.parse_args()
    args.repeat = args.repeat or (1 if args.quick else 3)
    args.timeout = args.timeout or (90.0 if args.quick else 1800.0)
    args.t0 = time.time()
    os.chdir(ROOT)

    plan = sweep_plan(args.quick)
    if args.only:
        keep = []
        for e in plan:
            for o in args.only.split(","):
                sc, _, h = o.partition(":")
                if e["scene"] == sc and (not h or abs(float(h) - e["h"]) < 1e-12):
                    keep.append(e)
                    break
        plan = keep
    nconf = sum(len(e["configs"]) for e in plan)
    if args.dry_run:
        for e in plan:
            print("%-13s h=%-6g %3d configurations" % (e["scene"], e["h"], len(e["configs"])))
        print("total %d configurations (x repeat %d, plus one linear baseline per mesh)" % (nconf, args.repeat))
        return 0

    os.makedirs(args.out, exist_ok=True)
    args.out = os.path.abspath(args.out)
    if args.report_only:
        with open(os.path.join(args.out, "run.json")) as fh:
            meta = json.load(fh)
        for k in ("quick", "repeat", "timeout", "bin_orig", "bin_sha"):
            setattr(args, k, meta[k])
        sys.argv = [sys.argv[0]] + meta["argv"]
        report(read_csv(os.path.join(args.out, "results.csv")), args, meta["info"], meta["meshes"],
               meta["elapsed"], meta["load"])
        print("rewrote %s/RESULTS.md and the plots" % args.out)
        return 0
    tmp = tempfile.mkdtemp(prefix="bench-")
    try:
        args.bin_orig = os.path.abspath(args.bin)
        with open(args.bin_orig, "rb") as fh:
            args.bin_sha = hashlib.sha256(fh.read()).hexdigest()[:12]
        args.bin = os.path.join(tmp, "contact")
        shutil.copy2(args.bin_orig, args.bin)
        R = Runner(args, tmp)
        info = machine_info()
        load0 = "%.2f" % os.getloadavg()[0]
        R.say("%d meshes, %d configurations, repeat %d, timeout %g s, out %s" % (len(plan), nconf, args.repeat,
                                                                                  args.timeout, args.out))
        rows, meshes = [], []
        for e in plan:
            scene, h = e["scene"], e["h"]
            m = {"scene": scene, "h": h}
            meshes.append(m)
            mt, err = R.mesh(scene, h)
            m["mesh_time"] = mt
            if err:
                R.say("%s h=%g: %s" % (scene, h, err))
                m["note"] = err
                for (s, kp, tol, ranks, rep) in e["configs"]:
                    rows.append({"scene": scene, "h": h, "strategy": s, "kp": kp, "gttol": tol, "ranks": ranks,
                                 "converged": False, "reason": err})
                continue
            lin = {}
            for ranks in sorted({c[3] for c in e["configs"]}):
                # the baseline is cheap beside the contact runs: at least 3 repeats, except on
                # the meshes whose contact runs are single
                rep = 1 if all(c[4] == 1 for c in e["configs"] if c[3] == ranks) else max(args.repeat, 3)
                lin[ranks] = run_linear(R, scene, h, ranks, rep)
                R.say("%s h=%g: linear baseline, %d rank(s): solve %.3g s, %s dofs %s" % (
                    scene, h, ranks, lin[ranks]["solve"], lin[ranks]["dofs"], lin[ranks]["reason"]))
            m["dofs"], m["linear"] = lin[1]["dofs"] if 1 in lin else None, lin.get(1, {}).get("solve")
            m["note"] = lin.get(1, {}).get("reason", "")
            ev_row = None
            for (s, kp, tol, ranks, rep) in e["configs"]:
                want_log = (s == REF_STRATEGY and kp == REF_KP and tol == REF_TOL)
                row = run_config(R, scene, h, s, kp, tol, ranks, rep or args.repeat, want_log)
                L = lin.get(ranks) or lin.get(1)
                if not row.get("dofs") and L and L.get("dofs"):
                    row["dofs"] = L["dofs"]
                row["linear_solve_time"] = L["solve"] if L else float("nan")
                if finite(row.get("solve_median")) and L and finite(L["solve"]) and L["solve"] > 0:
                    row["ratio_to_linear"] = row["solve_median"] / L["solve"]
                if want_log and ranks == 1 and finite(row.get("search_time_per_call")):
                    ev_row = row
                rows.append(row)
                R.say("%-45s %8s dofs  it %5s  solve %7s s  wall %7s s  %6s MB  l2 %8s  %s" % (
                    config_name(row), row.get("dofs", "-"), row.get("iterations", "-"), fmt(row.get("solve_median")),
                    fmt(row.get("wall_median")), fmt(row.get("peak_mb"), "%.0f"), pct(row.get("l2_err")), row["reason"]))
            # the mesh's search/energy costs, on every row of that mesh
            if ev_row:
                for r in rows:
                    if r["scene"] == scene and r["h"] == h and not finite(r.get("search_time_per_call")):
                        for k in ("search_time_per_call", "energy_time_per_call", "contact_hessian_time_per_call"):
                            r[k] = ev_row[k]
            write_csv(rows, os.path.join(args.out, "results.csv"))
        elapsed = time.time() - args.t0
        load = (load0, "%.2f" % os.getloadavg()[0])
        with open(os.path.join(args.out, "run.json"), "w") as fh:
            json.dump({"quick": args.quick, "repeat": args.repeat, "timeout": args.timeout, "bin_orig": args.bin_orig,
                       "bin_sha": args.bin_sha, "argv": sys.argv[1:], "info": info, "meshes": meshes,
                       "elapsed": elapsed, "load": load}, fh, indent=1)
        report(rows, args, info, meshes, elapsed, load)
        R.say("done in %.0f s: %s/results.csv, RESULTS.md, error_vs_time.png, time_vs_dofs.png, ratio_to_linear.png"
              % (elapsed, args.out))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
