#!/usr/bin/env python3
"""Benchmark of bin/contact (issue "Speed"): error against cost.

    python3 scripts/bench.py [--quick] [--repeat N] [--out bench] [--dry-run]
    python3 scripts/bench.py --formulations-cost [--cost-sizes 0.06,0.0065] [--out bench]

Runs bin/contact as a black box (`-summary <json>`, through
scripts/contactrun.py) over a sweep of scenes, mesh sizes, contact
formulations (gpts, mortar), solver strategies, penalties and gradient
tolerances, and writes <out>/results.csv (one row per
configuration), <out>/RESULTS.md (design, machine, targets, tables) and the
plots <out>/error_vs_time.png, <out>/time_vs_dofs.png and
<out>/ratio_to_linear.png.

Per mesh, in this order: the meshes are generated (`-mesh_only`, cached in
build/meshes/<scene>, so no timed run includes Gmsh), the linear baseline runs
(`-contact_disable -tao_type nls`: one Newton step, i.e. assembly plus one
sparse direct factorisation and solve of the linear elastic problem), then the
contact runs. Each configuration runs --repeat times (wall time and solve time:
medians); configurations that differ only in their formulation run
interleaved (gpts, mortar, gpts, mortar, ...), so that their time ratio is
measured under the same load. The first repeat of a one-rank configuration
writes its HDF5 output to a temporary directory, from which the pressure
profile is read (scripts/profile_metrics.py) and compared with the finest run
of the same model (scene, formulation, k_p); that repeat's Output stage is
left out of its wall time, and the other repeats run with `-output none`. The
first repeat of the default strategy at k_p = 2e6, gttol 1e-8 also writes
-log_view, from which the contact search and energy evaluation costs per call
and the contact share of the Solve stage are read. Peak memory is each
process's maximum resident set (GNU time %M), summed over the ranks. A run that
fails, times out or does not converge is a row with its reason, never a stop of
the sweep.

--formulations-cost runs only the reference configuration of both
formulations on the hertz scene at the given sizes, interleaved, --repeat
times each (default 3), every run with -log_view, and writes
<out>/formulations.md and <out>/formulations.csv: the mortar / gpts solve time
ratio per size and where each formulation's solve time goes. RESULTS.md
quotes that file when it is in the same directory.

Only numpy, h5py and matplotlib (no scipy). The half model (hertz-half)
reports the full mirrored problem's figures itself (-contact_interface_mirror_y
0), so its rows use the program's JSON figures like every other row.
"""
import argparse
import csv
import datetime
import json
import math
import os
import re
import shutil
import sys
import tempfile
import time
import types

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import contactrun  # noqa: E402
import profile_metrics  # noqa: E402
from contactrun import (event_totals, finite, git_info, load_average, machine_info, median, mesh_only,  # noqa: E402
                        nproc, parse_log_view, parse_tao_line)

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
    "blmvm-h0": ["-tao_type", "blmvm"],
    "lmvm": ["-tao_type", "lmvm", "-lmvm_h0", "none", "-tao_max_it", "100000", "-tao_max_funcs", "200000"],
}
# the gpts product's strategies; the L-BFGS pair with the mortar formulation (MORTAR_LMVM) runs at
# the reference k_p and tolerance on the uniform hertz meshes down to h = 0.015
ALL_STRATEGIES = [s for s in STRATEGIES if s != "blmvm-h0"]
MORTAR_LMVM = ["lmvm-h0", "blmvm-h0"]
KPS = [1e4, 1e5, 2e6, 1e8]
TOLS = [1e-8, 1e-5]
REF_KP, REF_TOL, REF_STRATEGY = 2e6, 1e-8, "newton"
# -contact_formulation, given on every run (a sweep row's formulation column); REF_FORMULATION is the
# one the strategy and penalty product varies, gpts (the program's default, mortar, runs the reference
# strategies)
FORMULATIONS = ["gpts", "mortar"]
REF_FORMULATION = "gpts"
COST_TARGET = 1.5     # mortar solve time / gpts solve time, reference configuration
REF_SOLVE_TARGET = 0.5  # s: the reference scene's solve time at h = 0.06 (gpts, newton, k_p 2e6, gttol 1e-8, one core)
LINEAR_RATIO_TARGET = 10  # time-to-solution in linear solves of the same mesh, on the meshes from 1e4 dofs
EXPONENT_TARGET = 1.2   # solve time growing like dofs^k from 1e4 to 1e6 dofs: k at most this
FIXED_COST_TARGET = 0.2  # mesh reading + set-up + output under this share of the whole run at 1e6 dofs
SEARCH_TARGET = 0.1     # contact search per call under this share of an energy evaluation at 1e6 dofs
FIT_DOFS = (1e4, 1.2e6)  # the range of dofs over which the cost exponents are fitted
ERROR_LEVELS = (0.10, 0.03, 0.01)

CSV_FIELDS = [
    "scene", "h", "formulation", "strategy", "kp", "gttol", "ranks", "dofs", "wall_median", "solve_median",
    "iterations", "energy_evals", "peak_mb", "P", "pmax_err", "a_err", "l2_err", "P_ref_err",
    "linear_solve_time", "ratio_to_linear", "search_time_per_call", "energy_time_per_call",
    "converged", "reason",
    # extras
    "a_moment_err", "repeats", "wall_runs", "solve_runs", "time_mesh", "time_setup", "time_output",
    "time_total", "hessian_evals", "json_iterations", "search_calls", "energy_calls",
    "contact_hessian_time_per_call", "P_program", "hertz_a", "hertz_pmax", "fem_pmax", "fem_a",
    "P_ref", "P_ref_h",
    # the profile against the finest run of the same model (scene, formulation, k_p)
    "profile_err", "profile_ref_h", "osc", "profile_pmax", "h5_output_time",
    # from -log_view: contact events in the Solve stage
    "contact_solve_time", "solve_stage_time", "contact_share", "segments_time_per_call",
    "note",
]


# --------------------------------------------------------------------- sweep

def sweep_plan(quick):
    """A list of (scene, h) entries and, per entry, the configurations
    (strategy, kp, gttol, ranks, repeat_override, formulation) to run on that
    mesh. The mortar formulation runs the default strategy at the reference
    k_p on the main mesh series (hertz, hertz-half, and the graded scene);
    strategies and penalties are varied with gpts only."""
    plan = []

    def add(scene, h, configs):
        plan.append({"scene": scene, "h": h, "configs": configs})

    def mortar(tols=(REF_TOL,), rep=None):
        return [(REF_STRATEGY, REF_KP, t, 1, rep, "mortar") for t in tols]

    def mortar_lmvm():
        return [(s, REF_KP, REF_TOL, 1, None, "mortar") for s in MORTAR_LMVM]

    if quick:
        for h in (0.2, 0.1, 0.06):
            strategies = ["newton", "newton+cont", "lmvm-h0"] + (["lmvm"] if h >= 0.2 else [])
            # at h = 0.06 the two formulations' reference runs are the cost ratio: median of 3
            rep = 3 if h == 0.06 else None
            cfg = [(s, kp, 1e-8, 1, rep if (s, kp) == (REF_STRATEGY, REF_KP) else None, "gpts")
                   for s in strategies for kp in (2e6, 1e8)]
            cfg += mortar(rep=rep)
            if h == 0.06:
                cfg.append(("newton", 2e6, 1e-8, 2, None, "gpts"))
            add("hertz", h, cfg)
        for scene, h in (("hertz-half", 0.06), ("hertz-graded", 0.03)):
            add(scene, h, [(s, kp, 1e-8, 1, None, "gpts") for s in ("newton", "newton+cont", "lmvm-h0")
                           for kp in (2e6, 1e8)] + mortar())
        return plan

    # A: small meshes, the full product (plain lmvm only here: it is slow)
    full = [(s, kp, t, 1, None, "gpts") for s in ALL_STRATEGIES for kp in KPS for t in TOLS] + mortar(TOLS)
    # B: medium meshes, every strategy but plain lmvm
    medium = ([(s, kp, t, 1, None, "gpts") for s in ALL_STRATEGIES if s != "lmvm" for kp in KPS for t in TOLS]
              + mortar(TOLS))
    for h in (0.2, 0.1, 0.06):
        add("hertz", h, full + mortar_lmvm())
    add("hertz-half", 0.06, full)
    add("hertz-graded", 0.06, full)
    for h in (0.04, 0.03):
        add("hertz", h, medium + mortar_lmvm())
    add("hertz-half", 0.03, medium)
    add("hertz-graded", 0.03, medium)
    add("hertz-graded", 0.015, medium)
    # C: large meshes, the default strategy at the reference k_p, both
    # tolerances; at the finest (the reference solution of every k_p) all k_p
    add("hertz", 0.02, [("newton", REF_KP, t, 1, None, f) for t in TOLS for f in FORMULATIONS] + mortar_lmvm())
    add("hertz", 0.015, [("newton", REF_KP, t, 1, None, f) for t in TOLS for f in FORMULATIONS]
        + [("newton", kp, 1e-8, 1, 1, "gpts") for kp in KPS if kp != REF_KP] + mortar_lmvm())
    # D: scaling past 1e6 dofs; 1 and 2 ranks on the largest (2 ranks: gpts)
    add("hertz", 0.01, [("newton", REF_KP, REF_TOL, 1, None, f) for f in FORMULATIONS])
    add("hertz", 0.0065, [("newton", REF_KP, REF_TOL, 1, None, f) for f in FORMULATIONS]
        + [("newton", REF_KP, REF_TOL, 2, None, "gpts")])
    return plan


# ------------------------------------------------------------------- running

def scene_args(scene, h):
    return ["-options_file", SCENES[scene], "-mesh_size", repr(h)]


class Sweep:
    """The sweep's log, its temporary directory and its copy of the program
    (args.bin): say() prints a line and logs it; mesh() generates a scene's
    meshes; run() runs the program once."""

    def __init__(self, args, tmp, logname="bench.log"):
        self.args = args
        self.tmp = tmp
        self.n = 0
        self.log = open(os.path.join(args.out, logname), "w")

    def say(self, msg):
        line = "[%7.1f s] %s" % (time.time() - self.args.t0, msg)
        print(line, flush=True)
        self.log.write(line + "\n")
        self.log.flush()

    def mesh(self, scene, h):
        """(seconds, None), or (None, why it failed)."""
        res = mesh_only(scene_args(scene, h), self.args.bin)
        if res.returncode != 0:
            return None, "mesh_only failed (rc %d): %s" % (res.returncode, first_error(res.stdout + res.stderr))
        return res.wall, None

    def run(self, args, ranks, summary, output="none", log_view=None):
        """One run under --timeout, its peak memory measured, stderr merged
        into stdout; returns (wall, rc or "timeout", its output, the summary
        where rc is 0 or None, peak MB summed over the ranks or NaN)."""
        self.n += 1
        res = contactrun.run(args, ranks, self.args.bin, summary=summary, output=output, log_view=log_view,
                             peak_memory=os.path.join(self.tmp, "mem%d" % self.n), timeout=self.args.timeout,
                             merge_stderr=True)
        peak = sum(res.peaks) if None not in res.peaks else float("nan")
        return (res.wall, "timeout" if res.timed_out else res.returncode, res.stdout,
                res.summary if res.returncode == 0 else None, peak)


def first_error(text):
    for line in text.split("\n"):
        if "error" in line.lower() and line.strip():
            return line.strip()[:200]
    lines = [l for l in text.split("\n") if l.strip()]
    return lines[-1][:200] if lines else "no output"


# events of the two formulations that play the same part
EVENT_ROLES = {
    "search": ("ContactSearch", "MortarSearch"),
    "contact_energy": ("ContactEnergyGrad", "MortarEnergyGrad"),
    "contact_hessian": ("ContactHessian", "MortarHessian"),
    "segments": ("MortarSegments",),
}


def event(ev, role):
    """(count, time) of the event that plays `role` in either formulation."""
    for name in EVENT_ROLES[role]:
        if name in ev:
            return ev[name]
    return (0, 0.0)


def log_figures(lv):
    """Per-call costs and the contact share of the Solve stage from a parsed
    -log_view (contactrun.parse_log_view): contact = energy-gradient + Hessian events of the formulation
    (the search and, for mortar, the segments are inside both)."""
    ev, sv = event_totals(lv), lv["events"].get("Solve", {})
    ns, ts = event(ev, "search")
    nc, tc = event(ev, "contact_energy")
    _, te = ev.get("ElasEnergyGrad", (0, 0.0))
    nh, th = event(ev, "contact_hessian")
    ng, tg = event(ev, "segments")
    solve = lv["stages"].get("Solve", float("nan"))
    contact = event(sv, "contact_energy")[1] + event(sv, "contact_hessian")[1]
    t = {k: sum(sv.get(e, (0, 0.0))[1] for e in names) for k, names in (
        ("t_factor_k", ("SchurFactorK",)), ("t_newton_linear", ("KSPSolve", "PCSetUp")),
        ("t_elastic", ("ElasEnergyGrad", "ElasHessian")))}
    t["t_other"] = solve - contact - sum(t.values())
    return {**t, "search_calls": ns, "energy_calls": nc,
            "search_time_per_call": ts / ns if ns else float("nan"),
            "energy_time_per_call": (tc + te) / nc if nc else float("nan"),
            "contact_hessian_time_per_call": th / nh if nh else float("nan"),
            "segments_time_per_call": tg / ng if ng else float("nan"),
            "contact_solve_time": contact, "solve_stage_time": solve,
            "contact_share": contact / solve if solve and math.isfinite(solve) else float("nan")}


class ConfigRun:
    """The repeats of one configuration on one mesh, run one at a time
    (step), so that configurations can be interleaved; finish() gives the
    row. log_view: None, "first" (the first repeat) or "all" (every repeat;
    the figures are then medians). h5: the first repeat writes HDF5 and its
    pressure profile is kept in row["_profile"]."""

    def __init__(self, R, scene, h, cfg, repeat, log_view=None, h5=False):
        strategy, kp, tol, ranks, _, form = cfg
        self.R, self.repeat, self.log_view, self.h5 = R, repeat, log_view, h5
        self.cmd = (scene_args(scene, h) + ["-contact_formulation", form, "-contact_penalty", "%g" % kp,
                                            "-tao_gttol", "%g" % tol] + STRATEGIES[strategy])
        self.ranks = ranks
        self.row = {"scene": scene, "h": h, "formulation": form, "strategy": strategy, "kp": kp, "gttol": tol,
                    "ranks": ranks, "converged": False, "reason": "", "note": ""}
        self.walls, self.solves, self.summaries, self.peaks, self.logs = [], [], [], [], []
        self.clean_peaks, self.outputs, self.totals = [], [], []
        self.tao = None
        self.done = False

    def step(self, r):
        if self.done or r >= self.repeat:
            return
        R, row = self.R, self.row
        R.n += 1
        jp = os.path.join(R.tmp, "run%d.json" % R.n)
        h5 = os.path.join(R.tmp, "run%d.h5" % R.n) if (self.h5 and r == 0) else None
        lv = None
        if self.log_view == "all" or (self.log_view == "first" and r == 0):
            lv = os.path.join(R.tmp, "log%d.txt" % R.n)
        wall, rc, out, summ, peak = R.run(self.cmd, self.ranks, jp, h5 or "none", lv)
        self.tao = parse_tao_line(out) or self.tao
        if rc == "timeout":
            row["reason"] = "TIMEOUT after %.0f s" % R.args.timeout
            self.walls.append(wall)
            self.done = True
            return
        if summ is None:
            if self.tao and self.tao["reason"] and not self.tao["reason"].startswith("CONVERGED"):
                row["reason"] = self.tao["reason"]
            else:
                row["reason"] = "FAILED rc=%s: %s" % (rc, first_error(out))
            self.walls.append(wall)
            self.peaks.append(peak)
            self.done = True
            return
        t = summ["time"]
        if h5:
            # the HDF5 write is not part of the timing: its Output stage is left out
            row["h5_output_time"] = t["output"]
            wall -= t["output"]
            self.totals.append(t["total"] - t["output"])
            try:
                prof = profile_metrics.profiles(h5)[0]
                row["_profile"] = prof
                osc = [profile_metrics.oscillation(*v) for v in prof.values()]
                row["osc"] = float(np.mean(osc)) if osc else float("nan")
                row["profile_pmax"] = float(np.mean([p.max() for (s, p, w, g) in prof.values()]))
            except (OSError, KeyError, ValueError, IndexError) as e:
                row["note"] = "profile not read: %s" % e
            for f in (h5, os.path.splitext(h5)[0] + ".xdmf"):
                if os.path.exists(f):
                    os.remove(f)
        else:
            self.outputs.append(t["output"])
            self.totals.append(t["total"])
            self.clean_peaks.append(peak)
        self.walls.append(wall)
        self.solves.append(t["solve"])
        self.summaries.append(summ)
        self.peaks.append(peak)
        if lv:
            self.logs.append(log_figures(parse_log_view(lv)))
        if os.path.exists(jp):
            os.remove(jp)

    def finish(self):
        row, walls, solves, summaries = self.row, self.walls, self.solves, self.summaries
        row["repeats"] = len(walls)
        row["wall_runs"] = " ".join("%.3f" % w for w in walls)
        row["solve_runs"] = " ".join("%.3f" % s for s in solves)
        row["wall_median"] = median(walls)
        # the repeats without HDF5 output where there are any
        peaks = self.clean_peaks or self.peaks
        row["peak_mb"] = max(peaks) if peaks else float("nan")
        tao = self.tao
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
            row["solve_median"] = median(solves)
            row["dofs"] = s["dofs"]
            row["json_iterations"] = s.get("iterations")
            for k in ("mesh", "setup"):
                row["time_" + k] = median([x["time"][k] for x in summaries])
            # output: the repeats with -output none (0 when every repeat wrote HDF5: its
            # Output stage is left out of the wall and total times)
            row["time_output"] = median(self.outputs) if self.outputs else 0.0
            row["time_total"] = median(self.totals)
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
        if self.logs:
            for k in self.logs[0]:
                row[k] = median(x[k] for x in self.logs)
        return row


def interleave_groups(configs):
    """The configurations grouped by all but their formulation, in order of
    first appearance: each group runs interleaved."""
    groups = {}
    for c in configs:
        groups.setdefault(tuple(c[:5]), []).append(c)
    return list(groups.values())


def run_interleaved(R, scene, h, configs, repeat_default, log_view, h5):
    """The configurations' repeats in turn (a1 b1 a2 b2 ...); the rows in the
    order of configs."""
    runs = [ConfigRun(R, scene, h, c, c[4] or repeat_default, log_view(c), h5(c)) for c in configs]
    for r in range(max(x.repeat for x in runs)):
        for x in runs:
            x.step(r)
    return [x.finish() for x in runs]


def rel(x, ref):
    try:
        if x is None or ref is None or ref == 0 or not math.isfinite(x) or not math.isfinite(ref):
            return float("nan")
        return x / ref - 1.0
    except TypeError:
        return float("nan")


def run_linear(R, scene, h, ranks, repeat):
    cmd = scene_args(scene, h) + ["-contact_disable", "-tao_type", "nls"]
    solves, walls, dofs, peak, reason = [], [], None, float("nan"), ""
    for _ in range(repeat):
        R.n += 1
        jp = os.path.join(R.tmp, "lin%d.json" % R.n)
        wall, rc, out, summ, peak = R.run(cmd, ranks, jp)
        if summ is None:
            reason = "linear baseline failed (rc %s): %s" % (rc, first_error(out))
            break
        solves.append(summ["time"]["solve"])
        walls.append(wall)
        dofs = summ["dofs"]
        reason = summ.get("tao_reason", "")
        os.remove(jp)
    return {"solve": median(solves), "wall": median(walls),
            "dofs": dofs, "peak_mb": peak, "reason": reason}


# ------------------------------------------------------------------ analysis

def default_runs(rows, scene, kp=None, h=None, formulation=REF_FORMULATION):
    """The converged one-rank runs of a scene with the default strategy at
    gttol 1e-8, at k_p = kp and mesh size h where given, of one formulation
    (None: both)."""
    return [r for r in rows if r["scene"] == scene and r["strategy"] == REF_STRATEGY and r["gttol"] == REF_TOL
            and r["ranks"] == 1 and r["converged"] and (kp is None or r["kp"] == kp) and (h is None or r["h"] == h)
            and (formulation is None or r["formulation"] == formulation)]


def attach_references(rows):
    """P_ref per formulation and k_p: the converged run of the default
    strategy at gttol 1e-8 on the finest uniform mesh that has that
    formulation and k_p. Graded and half-model runs are compared with the
    same uniform reference (the half model reports the full problem's P)."""
    refs = {}
    for r in rows:
        if (r["scene"] == "hertz" and r["strategy"] == REF_STRATEGY and r["gttol"] == REF_TOL
                and r["ranks"] == 1 and r["converged"] and finite(r.get("P"))):
            key = (r["formulation"], r["kp"])
            cur = refs.get(key)
            if cur is None or r["h"] < cur[1]:
                refs[key] = (r["P"], r["h"])
    for r in rows:
        ref = refs.get((r["formulation"], r["kp"]))
        if ref and finite(r.get("P")):
            r["P_ref"], r["P_ref_h"] = ref
            r["P_ref_err"] = abs(r["P"] - ref[0]) / ref[0]
    return refs


def attach_profile_refs(rows):
    """profile_err: the relative L2 distance of a run's pressure profile from
    that of the finest run of the same model (scene, formulation, k_p; the
    default strategy at gttol 1e-8, one rank), by
    profile_metrics.l2_distance (the coarse profile interpolated at the fine
    samples, weighted by the fine weights), the mean over the one-sided
    surfaces that both have (gpts: both surfaces; mortar: the slave). Rows
    read back from a CSV keep their stored figures."""
    fine = {}
    for r in rows:
        if (r.get("_profile") and r["strategy"] == REF_STRATEGY and r["gttol"] == REF_TOL and r["ranks"] == 1
                and r["converged"]):
            key = (r["scene"], r["formulation"], r["kp"])
            if key not in fine or r["h"] < fine[key]["h"]:
                fine[key] = r
    for r in rows:
        f = fine.get((r["scene"], r["formulation"], r["kp"]))
        if not f or not r.get("_profile") or not r["converged"]:
            continue
        d = [profile_metrics.l2_distance(r["_profile"][k], f["_profile"][k]) for k in r["_profile"]
             if k in f["_profile"]]
        if d:
            r["profile_err"] = float(np.mean(d))
            r["profile_ref_h"] = f["h"]
    return {k: v["h"] for k, v in fine.items()}


def on_ref_mesh(r):
    return r["scene"] in ("hertz", "hertz-half") and r.get("P_ref_h") == r["h"]


def on_profile_ref_mesh(r):
    """A run on the mesh of its own profile reference (its distance is the
    solver's, not the discretisation's)."""
    return r.get("profile_ref_h") == r["h"]


def off_profile_model(r):
    """A run the cheapest configurations by profile distance leave out: one on its reference's own mesh
    (its distance is the solver's) or at another k_p than the scenes' (another model)."""
    return on_profile_ref_mesh(r) or r["kp"] != REF_KP


def fit_runs(runs):
    """The runs within FIT_DOFS, over which fit_exponent fits."""
    return [r for r in runs if FIT_DOFS[0] <= r["dofs"] <= FIT_DOFS[1]]


def fit_exponent(x, y, lo=FIT_DOFS[0], hi=FIT_DOFS[1]):
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
    s = "%s h=%g %s %s k_p=%g tol=%g" % (r["scene"], r["h"], r.get("formulation", REF_FORMULATION), r["strategy"],
                                         r["kp"], r["gttol"])
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


# ------------------------------------------------------------------- plots

def accuracy_curve(rows):
    """bench/accuracy/results.json's -accuracy curve, if its profile reference
    is this sweep's (the finest uniform mortar run of the reference scene)."""
    path = os.path.join(ROOT, "bench", "accuracy", "results.json")
    ref = {r.get("profile_ref_h") for r in rows if r["scene"] == "hertz" and r["formulation"] == "mortar"
           and finite(r.get("profile_ref_h"))}
    if not os.path.exists(path) or not ref:
        return None
    with open(path) as fh:
        acc = json.load(fh).get("curve")
    return acc if acc and any(abs(acc["ref_h"] - h) < 1e-12 for h in ref) else None


# the plots' styles: a colour per strategy (C3 is mortar's), a marker per scene, a colour and a line style
# per formulation
STRATEGY_COLORS = {s: c for s, c in zip(STRATEGIES, ["C0", "C1", "C2", "C9", "C4", "C5", "C6"])}
SCENE_MARKERS = {"hertz": "o", "hertz-graded": "s", "hertz-half": "^"}
FORM_COLORS = {"gpts": "C0", "mortar": "C3"}
FORM_STYLES = {"gpts": "-", "mortar": "--"}


def seconds_axis(plt, axis):
    """A logarithmic axis of seconds labelled in plain numbers, the minor ticks at 2, 3 and 5 of each decade
    too, or all of them on an axis spanning less than a factor of 4 (matplotlib labels every minor tick of
    an axis spanning about a decade, where 3 x 10^0 and 4 x 10^0 run into each other)."""
    def minor(v, _):
        lo, hi = sorted(axis.get_view_interval())
        lead = v / 10 ** math.floor(math.log10(v))
        return "%g" % v if hi < 4 * lo or min(abs(lead - d) for d in (2, 3, 5)) < 1e-6 else ""
    axis.set_major_formatter(plt.FuncFormatter(lambda v, _: "%g" % v))
    axis.set_minor_formatter(plt.FuncFormatter(minor))


def series_color(form, strategy):
    """A colour per strategy, the formulations told apart by the line style; mortar's newton its
    formulation's colour."""
    return FORM_COLORS[form] if (form != REF_FORMULATION and strategy == REF_STRATEGY) else STRATEGY_COLORS[strategy]


def error_front(ax, pts, key, color, ls, label):
    """Scatter of the runs (marker per scene) and the line of the best error so far."""
    for sc, mk in SCENE_MARKERS.items():
        q = [r for r in pts if r["scene"] == sc]
        if q:
            ax.scatter([r["wall_median"] for r in q], [abs(r[key]) for r in q], s=14, marker=mk,
                       color=color, alpha=0.35)
    pts = sorted(pts, key=lambda r: r["wall_median"])
    fx, fy, best = [], [], float("inf")
    for r in pts:
        if abs(r[key]) < best:
            best = abs(r[key])
            fx.append(r["wall_median"])
            fy.append(best)
    if fx:
        # on to the slowest run, so that a front of one point is a line too
        fx.append(max(pts[-1]["wall_median"], fx[-1] * 1.15))
        fy.append(fy[-1])
        ax.step(fx, fy, where="post", color=color, ls=ls, label=label, lw=1.8)


def plottable(r, key):
    return (r["converged"] and r["ranks"] == 1 and finite(r.get(key)) and finite(r.get("wall_median"))
            and abs(r[key]) > 0)


def plot_error_vs_time(plt, rows, out):
    """error_vs_time.png: error against time per formulation (the profile's
    distance from the finest run of the same model, and from Hertz), and per
    formulation and strategy (P against the finest mesh)."""
    fig, axes = plt.subplots(1, 3, figsize=(18, 5.4))
    for ax, key, title, excl in (
            (axes[0], "profile_err", "pressure profile: L2 distance from the finest run of the same model\n"
                                     "(scene, formulation; k_p = 2e6; runs on that mesh left out)",
             on_profile_ref_mesh),
            (axes[1], "l2_err", "pressure profile: L2 error against Hertz\n"
                                "(not exact on the reference scene: a/R = 0.36)", None)):
        for form in FORMULATIONS:
            pts = [r for r in rows if r["formulation"] == form and plottable(r, key) and not (excl and excl(r))
                   and (key != "profile_err" or r["kp"] == REF_KP)]
            error_front(ax, pts, key, FORM_COLORS[form], FORM_STYLES[form], form)
        ax.set_title(title, fontsize=10)
    acc = accuracy_curve(rows)
    if acc:  # -accuracy TOL on the reference scene (scripts/accuracy_study.py), measured as these runs
        pts = sorted(acc["points"], key=lambda p: p["wall"])
        axes[0].plot([p["wall"] for p in pts], [p["profile_err"] for p in pts], "D-", color="C2", lw=1.8,
                     label="mortar -accuracy TOL")
        groups = {}  # targets that ended on the same mesh (the same error) share one label
        for p in pts:
            groups.setdefault(p["profile_err"], []).append(p)
        for same in groups.values():
            tols = sorted((q["tol"] for q in same), reverse=True)
            axes[0].annotate("%s %%" % ", ".join("%g" % (100 * t) for t in tols), (same[0]["wall"], same[0]["profile_err"]),
                             fontsize=7, xytext=(4, 4), textcoords="offset points", color="C2")
    for form in FORMULATIONS:
        for s in STRATEGIES:
            pts = [r for r in rows if r["formulation"] == form and r["strategy"] == s and plottable(r, "P_ref_err")
                   and not on_ref_mesh(r)]
            error_front(axes[2], pts, "P_ref_err", series_color(form, s), FORM_STYLES[form], "%s %s" % (form, s))
    axes[2].set_title("|P - P_ref| / P_ref (finest uniform mesh, same formulation and k_p;\n"
                      "its own runs left out)", fontsize=10)
    for ax in axes:
        for t in ERROR_LEVELS:
            ax.axhline(t, color="gray", lw=0.6, ls=":")
        ax.set_xscale("log")
        ax.set_yscale("log")
        seconds_axis(plt, ax.xaxis)
        ax.set_xlabel("wall time per run, median [s]")
        ax.set_ylabel("relative error")
        ax.grid(True, which="both", alpha=0.3)
    for ax, t in ((axes[0], "formulation (lines: best error so far)"), (axes[1], "formulation"),
                  (axes[2], "formulation, strategy")):
        if ax.get_legend_handles_labels()[0]:
            ax.legend(title=t, fontsize=8)
    fig.text(0.5, 0.005, "markers: o uniform, s graded, ^ half model; converged runs, 1 rank; "
             "dotted: 10 %, 3 %, 1 %", ha="center", fontsize=8)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    fig.savefig(os.path.join(out, "error_vs_time.png"), dpi=120)
    plt.close(fig)


def plot_time_vs_dofs(plt, rows, out, fit_solve, fit_lin):
    """time_vs_dofs.png: time against dofs."""
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    sel = sorted(default_runs(rows, "hertz", REF_KP), key=lambda r: r["dofs"])
    if sel:
        d = np.array([r["dofs"] for r in sel], float)
        ax.loglog(d, [r["solve_median"] for r in sel], "o-", color="C0", label="contact solve (newton), gpts")
        ax.loglog(d, [r["wall_median"] for r in sel], "s--", color="C0", alpha=0.5, label="contact wall")
        ax.loglog(d, [r.get("linear_solve_time", float("nan")) for r in sel], "^-", color="C2",
                  label="one linear elastic solve")
        for fit, col, name in ((fit_solve, "C0", "contact solve"), (fit_lin, "C2", "linear solve")):
            if fit:
                k, c = fit
                xx = np.array([max(1e4, d.min()), min(1.2e6, d.max())])
                ax.loglog(xx, np.exp(c) * xx ** k, ":", color=col, lw=2,
                          label="%s fit 1e4..1e6: exponent %.2f" % (name, k))
    msel = sorted(default_runs(rows, "hertz", REF_KP, formulation="mortar"), key=lambda r: r["dofs"])
    if msel:
        ax.loglog([r["dofs"] for r in msel], [r["solve_median"] for r in msel], "o--", color="C3",
                  label="contact solve (newton), mortar")
    other = [r for r in rows if r["scene"] != "hertz" and r["strategy"] == REF_STRATEGY and r["kp"] == REF_KP
             and r["gttol"] == REF_TOL and r["ranks"] == 1 and r["converged"] and r["formulation"] == "gpts"]
    for sc, mk in (("hertz-graded", "s"), ("hertz-half", "^")):
        q = [r for r in other if r["scene"] == sc]
        if q:
            ax.loglog([r["dofs"] for r in q], [r["solve_median"] for r in q], mk, color="C7", label=sc + " solve")
    ax.set_xlabel("dofs")
    ax.set_ylabel("time [s]")
    ax.set_title("time against dofs (k_p = 2e6, gttol 1e-8, 1 rank; fits and other scenes: gpts)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "time_vs_dofs.png"), dpi=120)
    plt.close(fig)


def plot_ratio_to_linear(plt, rows, out):
    """ratio_to_linear.png: the solve time in linear solves."""
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    for form in FORMULATIONS:
        for s in STRATEGIES:
            q = sorted([r for r in rows if r["scene"] == "hertz" and r["strategy"] == s and r["kp"] == REF_KP
                        and r["gttol"] == REF_TOL and r["ranks"] == 1 and r["converged"] and r["formulation"] == form
                        and finite(r.get("ratio_to_linear"))], key=lambda r: r["dofs"])
            if q:
                ax.loglog([r["dofs"] for r in q], [r["ratio_to_linear"] for r in q], "o" + FORM_STYLES[form],
                          color=series_color(form, s), mfc="none" if form != REF_FORMULATION else None,
                          label="%s %s" % (form, s))
    for sc, mk in (("hertz-graded", "s"), ("hertz-half", "^")):
        q = [r for r in rows if r["scene"] == sc and r["kp"] == REF_KP and r["gttol"] == REF_TOL and r["converged"]
             and r["ranks"] == 1 and finite(r.get("ratio_to_linear"))]
        for r in q:
            mortar = r["formulation"] != REF_FORMULATION
            ax.loglog(r["dofs"], r["ratio_to_linear"], mk, color=series_color(r["formulation"], r["strategy"]),
                      alpha=0.6, mfc="none" if mortar else None)
    ax.axhline(LINEAR_RATIO_TARGET, color="k", ls="--", lw=1, label="target: %g" % LINEAR_RATIO_TARGET)
    ax.set_xlabel("dofs")
    ax.set_ylabel("solve time / one linear elastic solve")
    ax.set_title("time-to-solution in linear solves (k_p = 2e6, gttol 1e-8; s graded, ^ half;\n"
                 "dashed, open: mortar, its newton red)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "ratio_to_linear.png"), dpi=120)
    plt.close(fig)


def plots(rows, out, fit_solve, fit_lin):
    """The sweep's three plots in out."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    plot_error_vs_time(plt, rows, out)
    plot_time_vs_dofs(plt, rows, out, fit_solve, fit_lin)
    plot_ratio_to_linear(plt, rows, out)


# ------------------------------------------------------------------ report

def write_csv(rows, path, fields=CSV_FIELDS):
    with open(path + ".tmp", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=fields, extrasaction="ignore")
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
            for k in ("scene", "formulation", "strategy", "reason", "note", "wall_runs", "solve_runs"):
                if k in r:
                    r[k] = str(r[k])
            r.setdefault("formulation", REF_FORMULATION)    # a CSV from before the mortar formulation
            r["h"] = float(r["h"])
            r["kp"] = float(r["kp"])
            r["gttol"] = float(r["gttol"])
            r.setdefault("reason", "")
            r.setdefault("converged", False)
            rows.append(r)
    return rows


def formulation_ratio_rows(rows):
    """Per mesh size of the hertz scene where both formulations' reference
    runs converged (one rank): (h, gpts row, mortar row), finest last."""
    out = []
    for h in sorted({r["h"] for r in rows if r["scene"] == "hertz"}, reverse=True):
        g = default_runs(rows, "hertz", REF_KP, h, "gpts")
        m = default_runs(rows, "hertz", REF_KP, h, "mortar")
        if g and m and finite(g[0].get("solve_median")) and finite(m[0].get("solve_median")):
            out.append((h, g[0], m[0]))
    return out


def read_formulations_cost(out):
    """The rows of <out>/formulations.csv (--formulations-cost), or []."""
    path = os.path.join(out, "formulations.csv")
    if not os.path.exists(path):
        return []
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def cost_ratio_text(g, m):
    """'ratio (mortar x s / gpts y s, n repeats)' for two rows."""
    return "%.2f (mortar %.3g s / gpts %.3g s; %s and %s repeats, interleaved)" % (
        m["solve_median"] / g["solve_median"], m["solve_median"], g["solve_median"], m.get("repeats", "?"),
        g.get("repeats", "?"))


def bin_git(args):
    """The git state recorded when the program was copied (HEAD then, and
    whether the tree differed from it); for a sweep that did not record it,
    HEAD now."""
    return getattr(args, "bin_git", None) or git_info(args.out) + ", at the report"


def now_minute():
    return datetime.datetime.now().strftime("%Y-%m-%d %H:%M")


def report_header(rows, ctx):
    """The title, and how, when, on which binary and under what load the sweep ran."""
    args, elapsed, load = ctx.args, ctx.elapsed, ctx.load
    L = []
    A = L.append
    A("# Benchmark: error against cost (`scripts/bench.py%s`)" % (" --quick" if args.quick else ""))
    A("")
    A("Generated %s by `python3 scripts/bench.py %s` in %.0f s of wall time (%d configurations). Binary: `%s` "
      "(git %s; sha256 %s). Figures are from one shared machine: other work ran beside the sweep "
      "(load average %s at the start, %s at the end), so single timings carry noise of tens of per cent; "
      "ratios of runs made interleaved are the steadier figures."
      % (getattr(args, "generated", None) or now_minute(), " ".join(sys.argv[1:]), elapsed,
         len(rows), os.path.relpath(args.bin_orig, ROOT) if args.bin_orig.startswith(ROOT) else args.bin_orig,
         bin_git(args), args.bin_sha, load[0], load[1]))
    A("")
    return L


def report_machine(rows, ctx):
    """The machine's table: cores, CPU, memory, BLAS, PETSc, OS."""
    info = ctx.info
    L = []
    A = L.append
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
    return L


def report_design(rows, ctx):
    """Which meshes, strategies, penalties and formulations were run, and how often."""
    args = ctx.args
    L = []
    A = L.append
    A("## Design")
    A("")
    if args.quick:
        A("Quick variant: uniform hertz meshes h = 0.2, 0.1, 0.06; strategies newton, newton+cont, lmvm-h0 "
          "(plain lmvm at h = 0.2 only); k_p = 2e6 and 1e8; gttol 1e-8; the half model at h = 0.06 and the "
          "graded scene at h = 0.03 (its patch resolution) with the same strategies and k_p; one 2-rank run at "
          "h = 0.06; repeat %d (3 for both formulations' reference runs at h = 0.06, the cost ratio); per-run time "
          "limit %g s. The reference P and profile (\"finest mesh\") are therefore the h = 0.06 uniform runs: "
          "errors against them say how far coarser meshes and other strategies are from them, not from the "
          "converged answer (the full sweep's are h = 0.0065). The scaling targets need the full sweep."
          % (args.repeat, args.timeout))
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
    A("Formulations (`-contact_formulation`, given on every run; column `formulation`): **gpts** (Gauss point "
      "to segment, both surfaces as slave) runs every configuration above; **mortar** (the program's default: "
      "nodal weighted gaps, the pair's first surface as slave) runs the default strategy (newton) at k_p = 2e6 on every mesh of hertz, "
      "hertz-half and hertz-graded%s, and not the other strategies, penalties or the "
      "2-rank run: those measure the solver and the penalty, which the gpts rows cover, and leaving them "
      "out keeps the full sweep near an hour. "
      "On each mesh the two formulations' runs of a configuration alternate (gpts, mortar, gpts, ...), so "
      "that their time ratio is measured under the same load."
      % ("" if args.quick else " at both tolerances, and L-BFGS (lmvm-h0 and blmvm-h0, the program's defaults "
         "for them) at k_p = 2e6, gttol 1e-8 on the uniform hertz meshes down to h = 0.015 (rows added to an "
         "earlier sweep by `--merge`, where the header says so)"))
    A("")
    A("Strategies: " + "; ".join("**%s** `%s`" % (s, " ".join(v) or "(defaults: -tao_type nls)")
                                 for s, v in STRATEGIES.items()) + ".")
    A("")
    return L


def report_definitions(rows, ctx):
    """What each column means, and the references P_ref."""
    refs = ctx.refs
    L = []
    A = L.append
    A("Definitions. *wall*: the process's wall time (start to exit, mesh read included, Gmsh not: meshes "
      "are generated beforehand), median of the repeats. *solve*: the program's Solve stage (JSON time.solve). "
      "*linear*: the Solve stage of `-contact_disable -tao_type nls` on the same mesh, run just before that mesh's "
      "contact runs (one Newton step: assembly, one sparse direct factorisation and solve); *ratio* = solve / "
      "linear. *peak MB*: maximum resident set (GNU time %M), summed over ranks. *iterations, energy evals*: "
      "the totals printed on the program's `TAO ...` line (over all stages for continuation and load steps). "
      "Errors against Hertz are the program's (p_max: largest pressure sample; a: half the loaded "
      "length; l2: relative L2 error of the profile; gpts: means of the two one-sided surfaces, mortar: its "
      "slave surface; the half model reports those of the full mirrored problem). *P_ref_err* = |P - P_ref| / "
      "P_ref, P_ref = the newton, gttol 1e-8 run on the finest uniform mesh run with that formulation and k_p "
      "(graded and half-model runs compared with the same uniform reference). *profile err* (`profile_err`): "
      "the relative L2 distance of the run's pressure profile from that of the finest run of the same model "
      "(same scene, formulation and k_p; newton, gttol 1e-8, one rank), `scripts/profile_metrics.py`'s "
      "`l2_distance` (the coarse profile interpolated linearly at the fine samples, weighted by the fine "
      "weights: Gauss weights for gpts, nodal weights for mortar), mean over the one-sided surfaces; *osc*: "
      "its oscillation index (`oscillation`: largest deviation of a sample from the mean of its neighbours, less "
      "that of the Hertz profile with the computed peak and half-width at the same samples, within 0.8 a of "
      "the centre, over the peak). The profiles come from HDF5 output that the first repeat of every "
      "one-rank configuration writes to a temporary directory; the Output stage of that repeat is left out "
      "of its wall and total time (the other repeats run with `-output none`; *output* in mesh+setup+output "
      "is theirs, 0 where every repeat wrote HDF5, and *peak MB* is theirs where there are any). "
      "*search / energy per call*: "
      "from -log_view of the newton, k_p = 2e6, 1e-8 run of each mesh and formulation: ContactSearch "
      "(MortarSearch) time per call, and (ContactEnergyGrad + ElasEnergyGrad time) per ContactEnergyGrad "
      "call (MortarEnergyGrad for mortar; the search is inside it). *contact share*: (ContactEnergyGrad + "
      "ContactHessian) or (MortarEnergyGrad + MortarHessian) time in the Solve stage over that stage's time "
      "(the search and the mortar segments are inside these events).")
    A("")
    A("References P_ref: " + ", ".join("%s k_p = %g: P = %.6g (h = %g)" % (f, k, v[0], v[1])
                                        for (f, k), v in sorted(refs.items())) + ".")
    A("")
    return L


def report_formulations(rows, ctx):
    """Each formulation's default runs against the finest run of the same model, and mortar / gpts
    on the same mesh."""
    forms, pairs = ctx.forms, ctx.pairs
    L = []
    A = L.append
    A("## Formulations: error against the finest mesh of the same model")
    A("")
    A("Newton, k_p = 2e6, gttol 1e-8, one rank. *profile err*: the L2 distance of the profile from the finest "
      "run of the same scene and formulation (its h in the column *ref h*), next to the error against Hertz "
      "(not exact on these scenes, a/R = 0.36). *contact share*: contact events in the Solve stage.")
    A("")
    A("| scene | formulation | h | dofs | iterations | solve [s] | wall [s] | profile err | ref h | osc "
      "| l2 err vs Hertz | p_max err vs Hertz | P_ref err | contact share |")
    A("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for sc in ("hertz", "hertz-half", "hertz-graded"):
        for form in forms:
            for r in sorted(default_runs(rows, sc, REF_KP, formulation=form), key=lambda r: -r["h"]):
                A("| %s | %s | %g | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                    sc, form, r["h"], r["dofs"], r.get("iterations", "-"), fmt(r.get("solve_median")),
                    fmt(r.get("wall_median")),
                    pct(r.get("profile_err")) if not on_profile_ref_mesh(r) else "(reference)",
                    fmt(r.get("profile_ref_h"), "%g"), fmt(r.get("osc"), "%.3f"), pct(r.get("l2_err")),
                    pct(r.get("pmax_err")), pct(r.get("P_ref_err")), pct(r.get("contact_share"))))
    A("")
    if pairs:
        A("Mortar / gpts on the same mesh (hertz, the runs above, interleaved):")
        A("")
        A("| h | dofs | solve gpts [s] | solve mortar [s] | ratio | iterations gpts / mortar | energy evals gpts / "
          "mortar | solve per iteration, ratio | contact share gpts / mortar |")
        A("|---|---|---|---|---|---|---|---|---|")
        for h, g, m in pairs:
            per_it = ((m["solve_median"] / m["iterations"]) / (g["solve_median"] / g["iterations"])
                      if g.get("iterations") and m.get("iterations") else float("nan"))
            A("| %g | %d | %.3g | %.3g | %.2f | %s / %s | %s / %s | %s | %s / %s |" % (
                h, g["dofs"], g["solve_median"], m["solve_median"], m["solve_median"] / g["solve_median"],
                g.get("iterations", "-"), m.get("iterations", "-"), g.get("energy_evals", "-"),
                m.get("energy_evals", "-"), fmt(per_it, "%.2f"), pct(g.get("contact_share")),
                pct(m.get("contact_share"))))
        A("")
    return L


def report_cheapest(rows, ctx):
    """The cheapest configuration reaching each error level, per error measure and formulation."""
    forms = ctx.forms
    L = []
    A = L.append
    A("## Cheapest configuration reaching an error")
    A("")
    A("Cheapest = smallest median wall time among converged one-rank runs, per formulation. The error against "
      "the finest mesh of the same model counts the runs of the scenes' own model, k_p = 2e6 (SPEC: the "
      "penalty is part of the reference scene; any strategy, tolerance and mesh); a run at another k_p solves "
      "another model, whose distance from its own finest mesh (results.csv) says nothing of its distance from "
      "this one. It leaves out the runs on the reference's mesh (their distance is the solver's), and it is "
      "only as good as that reference: a run close to a coarse reference may be far from the converged answer "
      "(the column *ref h* says which; the graded and half scenes' references are coarser than the uniform "
      "scene's, and their profiles' arc positions differ from its, so they are not compared with it).")
    A("")
    for key, title, excl, show_ref in (
            ("profile_err", "pressure profile: L2 distance from the finest run of the same model "
                            "(scene, formulation; k_p = 2e6)",
             off_profile_model, True),
            ("l2_err", "pressure profile: L2 error against Hertz", None, False),
            ("P_ref_err", "contact force P against the finest-mesh reference of the same formulation and k_p "
                          "(runs at the reference's h left out, the half model's too: they share its "
                          "discretisation)", on_ref_mesh, False)):
        A("**%s**" % title)
        A("")
        A("| formulation | error <= | configuration | dofs | wall [s] | solve [s] | error |%s iterations |"
          % (" ref h |" if show_ref else ""))
        A("|---|---|---|---|---|---|---|%s---|" % ("---|" if show_ref else ""))
        for form in forms:
            sel = [r for r in rows if r["formulation"] == form]
            for t, r in cheapest(sel, key, ERROR_LEVELS, excl):
                if r is None:
                    A("| %s | %g %% | none reached it | | | | |%s |" % (form, 100 * t, " |" if show_ref else ""))
                else:
                    A("| %s | %g %% | %s | %d | %.3g | %.3g | %s |%s %s |" % (
                        form, 100 * t, config_name(r), r["dofs"], r["wall_median"], r["solve_median"], pct(r[key]),
                        (" %s |" % fmt(r.get("profile_ref_h"), "%g")) if show_ref else "", r.get("iterations", "-")))
        A("")
        acc = accuracy_curve(rows) if key == "profile_err" else None
        if acc:
            A("`-accuracy TOL` on the reference scene (mortar; `scripts/accuracy_study.py`, bench/accuracy/RESULTS.md, "
              "measured there against this sweep's reference run, h = %g; whole-process wall time with the meshes "
              "generated, as here, median of its repeats, on another day): %s. It is the line *mortar -accuracy TOL* "
              "of error_vs_time.png." % (acc["ref_h"], "; ".join(
                  "TOL %g %%: distance %s, %d dofs, %.3g s" % (100 * p["tol"], pct(p["profile_err"]), p["dofs"], p["wall"])
                  for p in acc["points"])))
            A("")
    fin = []
    for form in forms:
        q = sorted(default_runs(rows, "hertz", REF_KP, formulation=form), key=lambda r: r["h"])
        if q and finite(q[0].get("l2_err")):
            fin.append("%s %s at h = %g" % (form, pct(q[0]["l2_err"]), q[0]["h"]))
    A("On the reference scene Hertz is not exact (a/R = 0.36, a block 1 wide): the profile error against Hertz "
      "levels off as h falls (finest runs here: %s; README: gpts near 8 %%), so 3 %% and 1 %% against Hertz are "
      "out of reach of any configuration of this scene; the distance from the finest mesh of the same model is "
      "the discretisation measure." % (", ".join(fin) or "-"))
    A("")
    return L


def report_scaling(rows, ctx):
    """The default runs of the reference scene by mesh size, and the fitted cost exponents."""
    ref_sel, mort_sel = ctx.ref_sel, ctx.mort_sel
    fit_solve, n_solve, fit_wall, fit_lin, fit_mort, n_mort = (ctx.fit_solve, ctx.n_solve, ctx.fit_wall, ctx.fit_lin,
                                                                ctx.fit_mort, ctx.n_mort)
    L = []
    A = L.append
    A("## Scaling: newton, k_p = 2e6, gttol 1e-8, uniform meshes")
    A("")
    A("| formulation | h | dofs | iterations | energy evals | solve [s] | wall [s] | linear [s] | ratio | peak MB | "
      "mesh+setup+output | search / call [ms] | energy eval / call [ms] | search share | contact Hessian / call [ms] "
      "| contact share of solve |")
    A("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in ref_sel + mort_sel:
        frac = fixed_cost_share(r) if finite(r.get("time_total")) else float("nan")
        sh = search_share(r) if finite(r.get("search_time_per_call")) else float("nan")
        A("| %s | %g | %d | %s | %s | %.3g | %.3g | %s | %s | %.0f | %s | %s | %s | %s | %s | %s |" % (
            r["formulation"], r["h"], r["dofs"], r.get("iterations", "-"), r.get("energy_evals", "-"), r["solve_median"],
            r["wall_median"], fmt(r.get("linear_solve_time")), fmt(r.get("ratio_to_linear"), "%.1f"), r["peak_mb"],
            pct(frac), fmt(1e3 * r["search_time_per_call"] if finite(r.get("search_time_per_call")) else None),
            fmt(1e3 * r["energy_time_per_call"] if finite(r.get("energy_time_per_call")) else None), pct(sh),
            fmt(1e3 * r["contact_hessian_time_per_call"] if finite(r.get("contact_hessian_time_per_call")) else None),
            pct(r.get("contact_share"))))
    A("")
    if fit_solve:
        A("Fitted exponents over 1e4..1.2e6 dofs (gpts, %d meshes): solve time %.2f, wall %s, one linear solve %s%s."
          % (n_solve, fit_solve[0], fmt(fit_wall[0] if fit_wall else None, "%.2f"),
             fmt(fit_lin[0] if fit_lin else None, "%.2f"),
             ("; mortar's solve time %.2f (%d meshes)" % (fit_mort[0], n_mort)) if fit_mort else ""))
    else:
        A("Fitted exponent: fewer than two meshes in 1e4..1.2e6 dofs.")
    A("")
    return L


def report_ranks(rows, ctx):
    """1 against 2 ranks on the largest mesh."""
    info = ctx.info
    L = []
    A = L.append
    A("## 1 and 2 ranks on the largest mesh (gpts)")
    A("")
    two = [r for r in rows if r["ranks"] == 2]
    if two:
        t = two[0]
        one = [r for r in rows if r["scene"] == t["scene"] and r["h"] == t["h"] and r["strategy"] == t["strategy"]
               and r["kp"] == t["kp"] and r["gttol"] == t["gttol"] and r["ranks"] == 1
               and r["formulation"] == t["formulation"]]
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
    return L


def report_half_model(rows, ctx):
    """The half model's figures against the full model's."""
    L = []
    A = L.append
    A("## Half model (y = 0 symmetry)")
    A("")
    half = default_runs(rows, "hertz-half", formulation=None)
    if half:
        A("hertz-half is the upper half of the reference scene, cut at y = 0 with u_y = 0 on the cut. Its pair's "
          "`-contact_interface_mirror_y 0` makes the program report the full mirrored problem (P = 2 abs(f_x), "
          "profiles mirrored about the cut), so its figures compare directly with the full model's at the same h, "
          "formulation and k_p (newton, gttol 1e-8).")
        A("")
        A("| formulation | h | k_p | dofs half / full | P half / full | P difference | profile L2 error half / full "
          "| solve half / full [s] |")
        A("|---|---|---|---|---|---|---|---|")
        for r in half:
            f = default_runs(rows, "hertz", r["kp"], r["h"], r["formulation"])
            f = f[0] if f else {}
            A("| %s | %g | %g | %d / %s | %.7g / %s | %s | %s / %s | %s / %s |" % (
                r["formulation"], r["h"], r["kp"], r["dofs"], f.get("dofs", "-"), r["P"], fmt(f.get("P"), "%.7g"),
                ("%+.1e" % (r["P"] / f["P"] - 1)) if finite(f.get("P")) else "-",
                pct(r["l2_err"]), pct(f.get("l2_err")), fmt(r.get("solve_median")), fmt(f.get("solve_median"))))
    else:
        A("No converged half-model run.")
    A("")
    return L


def report_graded(rows, ctx):
    """The graded meshes against uniform ones."""
    L = []
    A = L.append
    A("## Graded meshes")
    A("")
    gr = default_runs(rows, "hertz-graded", formulation=None)
    if gr:
        A("`-mesh_size h` is the size on the contact patch (within 0.5 of the first contact point); the far field "
          "is 0.1 in the disc and 0.2 in the block (meshes/hertz-graded/hertz-graded.opts).")
        A("")
        A("| formulation | h (patch) | k_p | dofs | solve [s] | wall [s] | l2 err | p_max err | a err | P_ref err "
          "| uniform at same h: dofs, l2 err | uniform with nearest dofs: h, dofs, l2 err |")
        A("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for r in gr:
            f = default_runs(rows, "hertz", r["kp"], r["h"], r["formulation"])
            u = default_runs(rows, "hertz", r["kp"], formulation=r["formulation"])
            u = min(u, key=lambda x: abs(math.log(x["dofs"] / r["dofs"]))) if u else None
            A("| %s | %g | %g | %d | %.3g | %.3g | %s | %s | %s | %s | %s | %s |" % (
                r["formulation"], r["h"], r["kp"], r["dofs"], r["solve_median"], r["wall_median"], pct(r["l2_err"]),
                pct(r["pmax_err"]), pct(r["a_err"]), pct(r.get("P_ref_err")),
                ("%d, %s" % (f[0]["dofs"], pct(f[0]["l2_err"]))) if f else "not run",
                ("%g, %d, %s" % (u["h"], u["dofs"], pct(u["l2_err"]))) if u else "-"))
    else:
        A("No converged graded run.")
    A("")
    return L


def report_strategies(rows, ctx):
    """Every strategy on the reference mesh (hertz, h = 0.06)."""
    L = []
    A = L.append
    A("## Strategies on the reference mesh (hertz, h = 0.06)")
    A("")
    A("| formulation | strategy | k_p | gttol | iterations | energy evals | solve [s] | wall [s] | peak MB | l2 err "
      "| profile err | P_ref err | reason |")
    A("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if r["scene"] == "hertz" and r["h"] == 0.06 and r["ranks"] == 1:
            A("| %s | %s | %g | %g | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                r["formulation"], r["strategy"], r["kp"], r["gttol"], r.get("iterations", "-"),
                r.get("energy_evals", "-"), fmt(r.get("solve_median")), fmt(r.get("wall_median")),
                fmt(r.get("peak_mb"), "%.0f"), pct(r.get("l2_err")),
                "(reference)" if r.get("profile_err") == 0 and on_profile_ref_mesh(r) else pct(r.get("profile_err")),
                pct(r.get("P_ref_err")), r["reason"]))
    A("")
    return L


def report_failures(rows, ctx):
    """The runs that failed or did not converge."""
    L = []
    A = L.append
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
    return L


def report_meshes(rows, ctx):
    """Each mesh's generation time and linear baseline."""
    meshes = ctx.meshes
    L = []
    A = L.append
    if meshes:
        A("## Meshes")
        A("")
        A("| scene | h | dofs | Gmsh / -mesh_only [s] | linear solve [s] | linear note |")
        A("|---|---|---|---|---|---|")
        for m in meshes:
            A("| %s | %g | %s | %s | %s | %s |" % (m["scene"], m["h"], m.get("dofs") or "-", fmt(m.get("mesh_time")),
                                                 fmt(m.get("linear")), m.get("note", "")))
        A("")
    return L


def report_files(rows, ctx):
    """The files of the sweep's directory."""
    fc = ctx.fc
    L = []
    A = L.append
    A("Files: results.csv (one row per configuration), error_vs_time.png, time_vs_dofs.png, ratio_to_linear.png, "
      "bench.log (the run's log), run.json (its settings; `--report-only` rewrites this file and the plots from "
      "them)%s." % (", formulations.md and formulations.csv (`--formulations-cost`)" if fc else ""))
    return L


def fixed_cost_share(r):
    """Mesh reading, set-up and output over a run's whole time."""
    return (r["time_mesh"] + r["time_setup"] + r["time_output"]) / r["time_total"]


def search_share(r):
    """A mesh's contact search per call over its energy evaluation per call."""
    return r["search_time_per_call"] / r["energy_time_per_call"]


def fastest(runs):
    """The run of least median solve time."""
    return min(runs, key=lambda r: r["solve_median"])


def worst_ratio(runs):
    """The run of most linear solves of its mesh."""
    return max(runs, key=lambda r: r["ratio_to_linear"])


def cost_ratio_pairs(rows):
    """The pairs of formulation_ratio_rows the mortar cost target counts: h = 0.06 and the largest mesh
    (one pair where they are the same)."""
    pairs = formulation_ratio_rows(rows)
    return [p for p in pairs if p[0] == 0.06] + [p for p in pairs[-1:] if p[0] != 0.06]


def reference_solve_runs(rows):
    """The reference scene's one-rank runs at h = 0.06, k_p 2e6, gttol 1e-8 (gpts): those of the default
    strategy, and the converged ones with a solve time."""
    h06 = [r for r in rows if r["scene"] == "hertz" and r["h"] == 0.06 and r["kp"] == REF_KP and r["gttol"] == REF_TOL
           and r["ranks"] == 1 and r["formulation"] == REF_FORMULATION]
    return ([r for r in h06 if r["strategy"] == REF_STRATEGY],
            [r for r in h06 if r["converged"] and finite(r.get("solve_median"))])


def linear_ratio_runs(ref_sel):
    """The reference runs (ctx.ref_sel) with a solve time in linear solves, and those of them the target
    counts: from 1e4 dofs (below, a linear solve takes milliseconds and fixed costs dominate)."""
    rat = [r for r in ref_sel if finite(r.get("ratio_to_linear"))]
    return rat, [r for r in rat if r["dofs"] >= 1e4]


def target_reference_solve(rows, ctx):
    """Solve time on the reference mesh, h = 0.06 (gpts)."""
    d06, conv06 = reference_solve_runs(rows)
    if not conv06:
        return [("reference scene, h = 0.06, solve <= %g s" % REF_SOLVE_TARGET, "no converged run", "NOT MEASURED")]
    best = fastest(conv06)
    dtxt = ("default (newton) %.3g s" % d06[0]["solve_median"]) if d06 and finite(d06[0].get("solve_median")) else "default: not converged"
    dok = bool(d06) and d06[0]["converged"] and d06[0]["solve_median"] <= REF_SOLVE_TARGET
    st = "MET" if dok else ("MET with %s only" % best["strategy"] if best["solve_median"] <= REF_SOLVE_TARGET
                            else "NOT MET")
    return [("reference scene, h = 0.06, k_p = 2e6, gttol 1e-8, solve time <= %g s on one core (gpts)"
             % REF_SOLVE_TARGET,
             "%s; fastest: %s %.3g s (%d iterations)" % (dtxt, best["strategy"], best["solve_median"],
                                                        best.get("iterations", 0)), st)]


def target_linear_ratio(rows, ctx):
    """Time-to-solution in linear solves of the same mesh."""
    rat, big_rat = linear_ratio_runs(ctx.ref_sel)
    if not big_rat:
        return [("time-to-solution <= %g linear solves" % LINEAR_RATIO_TARGET, "-", "NOT MEASURED")]
    worst = worst_ratio(big_rat)
    small = [r for r in rat if r not in big_rat and r["ratio_to_linear"] > LINEAR_RATIO_TARGET]
    return [("time-to-solution <= %g linear solves of the same mesh (gpts, newton, k_p 2e6, 1e-8, uniform meshes from "
             "1e4 dofs; below, a linear solve takes milliseconds and fixed costs dominate)" % LINEAR_RATIO_TARGET,
             "%s; worst %.1f at %d dofs" % (", ".join("%.1f (%d dofs)" % (r["ratio_to_linear"], r["dofs"]) for r in rat),
                                            worst["ratio_to_linear"], worst["dofs"]),
             "%s%s" % (status(worst["ratio_to_linear"] <= LINEAR_RATIO_TARGET),
                       (" (over %g below 1e4 dofs: %s)" % (LINEAR_RATIO_TARGET,
                                                          ", ".join("%d dofs" % r["dofs"] for r in small)))
                       if small else ""))]


def target_exponent(rows, ctx):
    """The cost exponent from 1e4 to 1e6 dofs."""
    ref_sel = ctx.ref_sel
    fit_solve, n_solve, fit_wall, fit_lin, fit_mort, n_mort = (ctx.fit_solve, ctx.n_solve, ctx.fit_wall, ctx.fit_lin,
                                                                ctx.fit_mort, ctx.n_mort)
    span = [r["dofs"] for r in fit_runs(ref_sel)]
    if fit_solve and span and max(span) >= 5e5:
        return [("cost exponent <= %g from 1e4 to 1e6 dofs (solve time, gpts, newton)" % EXPONENT_TARGET,
                 "%.2f over %d meshes, %d..%d dofs (wall time: %.2f; linear solve: %s; mortar's solve time: %s)"
                 % (fit_solve[0], n_solve, min(span), max(span), fit_wall[0] if fit_wall else float("nan"),
                    fmt(fit_lin[0] if fit_lin else None, "%.2f"),
                    ("%.2f over %d meshes" % (fit_mort[0], n_mort)) if fit_mort else "-"),
                 status(fit_solve[0] <= EXPONENT_TARGET))]
    return [("cost exponent <= %g from 1e4 to 1e6 dofs" % EXPONENT_TARGET,
             "%.2f over %d..%d dofs only" % (fit_solve[0], min(span), max(span)) if fit_solve and span else "-",
             "NOT MEASURED (needs meshes up to 1e6 dofs: full sweep)")]


def target_fixed_costs(rows, ctx):
    """Mesh reading, set-up and output against the total at the largest mesh."""
    big = ctx.ref_sel[-1] if ctx.ref_sel else None
    if not (big and finite(big.get("time_total"))):
        return []
    frac = fixed_cost_share(big)
    ok = big["dofs"] >= 5e5
    return [("mesh reading + set-up + output < %g %% of the total at 1e6 dofs" % (100 * FIXED_COST_TARGET),
             "%.1f %% at %d dofs (mesh %.2f s, set-up %.2f s, output %.2f s of %.2f s; output off: -output none)"
             % (100 * frac, big["dofs"], big["time_mesh"], big["time_setup"], big["time_output"], big["time_total"]),
             status(frac < FIXED_COST_TARGET) if ok
             else "NOT MEASURED at 1e6 dofs (largest mesh here %d dofs: %s there)" % (big["dofs"],
                                                                                    status(frac < FIXED_COST_TARGET)))]


def target_search(rows, ctx):
    """The contact search against an energy evaluation at the largest mesh."""
    big = ctx.ref_sel[-1] if ctx.ref_sel else None
    if not (big and finite(big.get("search_time_per_call"))):
        return []
    f = search_share(big)
    ok = big["dofs"] >= 5e5
    return [("contact search a small fraction of an energy evaluation at 1e6 dofs",
             "search %.3g ms per call, energy evaluation %.3g ms per call: %.2f %% at %d dofs"
             % (1e3 * big["search_time_per_call"], 1e3 * big["energy_time_per_call"], 100 * f, big["dofs"]),
             (status(f < SEARCH_TARGET) + " (taken as < %g %%)" % (100 * SEARCH_TARGET)) if ok
             else "NOT MEASURED at 1e6 dofs (%s at %d dofs)" % (status(f < SEARCH_TARGET), big["dofs"]))]


def target_mortar_cost(rows, ctx):
    """Mortar's solve time against gpts' on the same mesh (this sweep's pairs)."""
    out = ctx.out
    pairs = cost_ratio_pairs(rows)
    finest = pairs[-1] if pairs else None
    items = [("h = 0.06" if p[0] == 0.06 else "largest mesh of this sweep, h = %g (%d dofs)" % (p[0], p[1]["dofs"]), p)
             for p in pairs]
    if not items:
        return [("mortar / gpts solve time <= %g at h = 0.06 and at the largest mesh" % COST_TARGET,
                 "no pair of converged runs", "NOT MEASURED")]
    ratios = [p[2]["solve_median"] / p[1]["solve_median"] for _, p in items]
    ok = all(x <= COST_TARGET for x in ratios)
    text = "; ".join("%s: %s" % (label, cost_ratio_text(p[1], p[2])) for label, p in items)
    if finest[1]["dofs"] < 5e5:
        text += "; h = %g is this sweep's largest mesh" % finest[0]
    return [("mortar / gpts solve time <= %g (hertz, newton, k_p 2e6, gttol 1e-8, one core; medians of runs made "
             "interleaved) at h = 0.06 and at the largest mesh" % COST_TARGET, text,
             status(ok) if finest[1]["dofs"] >= 5e5
             else "%s here; at 1e6 dofs: NOT MEASURED in this sweep%s" % (
                 status(ok), " (see the next row)" if os.path.exists(os.path.join(out, "formulations.csv")) else ""))]


def target_formulations_cost(rows, ctx):
    """The same ratio from formulations.csv (--formulations-cost), where it exists."""
    fc = ctx.fc
    if not fc:
        return []
    sizes = sorted({float(r["h"]) for r in fc}, reverse=True)
    parts, oks = [], []
    for h in sizes:
        rr = {r["formulation"]: r for r in fc if float(r["h"]) == h}
        if "gpts" in rr and "mortar" in rr and rr["mortar"].get("ratio"):
            ratio = float(rr["mortar"]["ratio"])
            oks.append(ratio <= COST_TARGET)
            parts.append("h = %g (%s dofs): %.2f (mortar %.3g s / gpts %.3g s)" % (
                h, rr["gpts"]["dofs"], ratio, float(rr["mortar"]["solve_median"]),
                float(rr["gpts"]["solve_median"])))
    return [("the same, from `formulations.md` (`--formulations-cost`, %s, median of %s, interleaved)"
             % (fc[0].get("date", "?"), fc[0].get("repeats", "?")), "; ".join(parts) or "-",
             status(all(oks)) if oks else "NOT MEASURED")]


def target_rows(rows, ctx):
    """The targets' rows, each (target, what was measured, status), in the order of TARGETS."""
    return [row for target in TARGETS for row in target(rows, ctx)]


def met(status_text):
    """Whether a target's status says it is met outright (not only with another strategy, not only here)."""
    return status_text.split(" (")[0] == "MET"


def report_targets(rows, ctx):
    """The targets of the issue "Speed" and of the mortar formulation's cost, each measured, met or
    not."""
    return (["## Targets", "", "| target | measured | status |", "|---|---|---|"]
            + ["| %s | %s | %s |" % row for row in target_rows(rows, ctx)] + [""])


# the targets, in order: each returns its rows of the targets' table, (target, what was measured, status)
TARGETS = (target_reference_solve, target_linear_ratio, target_exponent, target_fixed_costs, target_search,
           target_mortar_cost, target_formulations_cost)


def report_figures(rows, args, info, meshes, elapsed, load):
    """What the sections of RESULTS.md share: the references attached to the rows, the reference scene's
    default runs of each formulation and their fitted cost exponents, the formulations present, the
    mortar / gpts pairs, formulations.csv's rows, and the sweep's settings."""
    ctx = types.SimpleNamespace(out=args.out, args=args, info=info, meshes=meshes, elapsed=elapsed, load=load)
    ctx.refs = attach_references(rows)
    attach_profile_refs(rows)
    ctx.ref_sel = sorted(default_runs(rows, "hertz", REF_KP), key=lambda r: r["dofs"])
    dofs = [r["dofs"] for r in ctx.ref_sel]
    ctx.fit_solve, ctx.n_solve = fit_exponent(dofs, [r["solve_median"] for r in ctx.ref_sel])
    ctx.fit_wall, _ = fit_exponent(dofs, [r["wall_median"] for r in ctx.ref_sel])
    ctx.fit_lin, _ = fit_exponent(dofs, [r.get("linear_solve_time") for r in ctx.ref_sel])
    ctx.mort_sel = sorted(default_runs(rows, "hertz", REF_KP, formulation="mortar"), key=lambda r: r["dofs"])
    ctx.fit_mort, ctx.n_mort = fit_exponent([r["dofs"] for r in ctx.mort_sel], [r["solve_median"] for r in ctx.mort_sel])
    ctx.forms = [f for f in FORMULATIONS if any(r["formulation"] == f for r in rows)]
    ctx.pairs = formulation_ratio_rows(rows)
    ctx.fc = read_formulations_cost(args.out)
    return ctx


# the sections of RESULTS.md, in order
REPORT_SECTIONS = (report_header, report_machine, report_design, report_definitions, report_targets, report_formulations,
                   report_cheapest, report_scaling, report_ranks, report_half_model, report_graded, report_strategies,
                   report_failures, report_meshes, report_files)


def report(rows, args, info, meshes, elapsed, load):
    """RESULTS.md, results.csv and the plots of a sweep, from its rows."""
    ctx = report_figures(rows, args, info, meshes, elapsed, load)
    write_csv(rows, os.path.join(args.out, "results.csv"))
    try:
        plots(rows, args.out, ctx.fit_solve, ctx.fit_lin)
    except Exception as e:
        print("plots failed: %s" % e, file=sys.stderr)
    L = []
    for section in REPORT_SECTIONS:
        L += section(rows, ctx)
    with open(os.path.join(args.out, "RESULTS.md.tmp"), "w") as fh:
        fh.write("\n".join(L) + "\n")
    os.replace(os.path.join(args.out, "RESULTS.md.tmp"), os.path.join(args.out, "RESULTS.md"))


def status(ok):
    return "MET" if ok else "NOT MET"


# ------------------------------------------------------- formulations cost

COST_FIELDS = ["date", "h", "formulation", "dofs", "repeats", "solve_runs", "wall_runs", "solve_median", "wall_median",
               "ratio", "iterations", "energy_evals", "hessian_evals", "converged", "reason", "P", "l2_err",
               "peak_mb", "solve_stage_time", "contact_solve_time", "contact_share", "t_factor_k", "t_newton_linear",
               "t_elastic", "t_other", "search_time_per_call", "segments_time_per_call", "energy_time_per_call",
               "contact_hessian_time_per_call"]


def measure_formulations_cost(args, R, sizes, date):
    """Both formulations' reference runs on hertz at each size, interleaved,
    --repeat times, -log_view on every run: the rows, each with its solve
    time's ratio to gpts'."""
    rows = []
    for h in sizes:
        mt, err = R.mesh("hertz", h)
        cfgs = [(REF_STRATEGY, REF_KP, REF_TOL, 1, None, f) for f in FORMULATIONS]
        if err:
            R.say("hertz h=%g: %s" % (h, err))
            rows += [{"h": h, "formulation": c[5], "converged": False, "reason": err} for c in cfgs]
            continue
        done = run_interleaved(R, "hertz", h, cfgs, args.repeat, lambda c: "all", lambda c: False)
        g = done[0]
        for row in done:
            row["date"] = date
            if finite(row.get("solve_median")) and finite(g.get("solve_median")):
                row["ratio"] = row["solve_median"] / g["solve_median"]
            R.say("%-52s %8s dofs  it %5s  solve %s s (%s)  ratio to gpts %s  contact share %s  %s" % (
                config_name(row), row.get("dofs", "-"), row.get("iterations", "-"), fmt(row.get("solve_median")),
                row.get("solve_runs", ""), fmt(row.get("ratio"), "%.2f"), pct(row.get("contact_share")),
                row["reason"]))
        rows += done
    return rows


def cost_header(args, date, load0):
    """formulations.md's title, provenance and design."""
    L = []
    A = L.append
    A("# Cost of the mortar formulation (`scripts/bench.py --formulations-cost`)")
    A("")
    A("Generated %s by `python3 scripts/bench.py %s` in %.0f s. Binary: `%s` (git %s; sha256 %s). One shared "
      "machine (%s cores; load average %s at the start, %.2f at the end)."
      % (date, " ".join(sys.argv[1:]), time.time() - args.t0,
         os.path.relpath(args.bin_orig, ROOT) if args.bin_orig.startswith(ROOT) else args.bin_orig,
         bin_git(args), args.bin_sha, nproc(), load0, load_average()))
    A("")
    A("The reference scene (hertz), newton, k_p = 2e6, gttol 1e-8, one rank, `-output none`, each formulation "
      "run %d times, interleaved (gpts, mortar, gpts, mortar, ...), so that both see the same load; every run "
      "writes -log_view (both alike). Solve: the program's Solve stage (JSON time.solve), median of the "
      "repeats. Target: mortar / gpts solve time <= %g at h = 0.06 and at the largest mesh (issue \"A contact "
      "pressure that converges\", item 7)." % (args.repeat, COST_TARGET))
    A("")
    return L


def cost_ratio_table(rows, sizes):
    """The mortar / gpts solve time ratio per size, against the target."""
    L = []
    A = L.append
    A("| h | dofs | solve gpts [s] | solve mortar [s] | mortar / gpts | status |")
    A("|---|---|---|---|---|---|")
    for h in sizes:
        rr = {r["formulation"]: r for r in rows if r["h"] == h}
        g, m = rr.get("gpts", {}), rr.get("mortar", {})
        ok = finite(m.get("ratio")) and g.get("converged") and m.get("converged")
        A("| %g | %s | %s | %s | %s | %s |" % (
            h, g.get("dofs", "-"), g.get("solve_runs") or g.get("reason", "-"),
            m.get("solve_runs") or m.get("reason", "-"), fmt(m.get("ratio"), "%.2f"),
            status(m["ratio"] <= COST_TARGET) if ok else "NOT MEASURED"))
    A("")
    A("(solve columns: the repeats in the order run; the ratio is that of the medians.)")
    A("")
    return L


def cost_breakdown_table(rows):
    """Where each formulation's Solve stage goes, per size."""
    L = []
    A = L.append
    A("Where the Solve stage goes (medians over the repeats' -log_view, Solve stage only). *factor K*: "
      "SchurFactorK, the sparse factorisation of the elastic stiffness, once per solve; *Newton linear "
      "algebra*: KSPSolve + PCSetUp (per step: the surface block's dense factorisation and the solves through "
      "the factor); *elastic*: ElasEnergyGrad + ElasHessian; *contact*: ContactEnergyGrad + ContactHessian "
      "(gpts) or MortarEnergyGrad + MortarHessian (mortar), search and segments included; *other*: the rest "
      "(TAO's vector work, the line search).")
    A("")
    A("| h | formulation | iterations | energy evals | Hessians | solve [s] | solve / iteration [s] | factor K "
      "| Newton linear algebra | elastic | contact | other | contact share | search / call [ms] "
      "| segments / call [ms] | peak MB | P | l2 vs Hertz |")
    A("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if not finite(r.get("solve_median")):
            A("| %g | %s | %s |%s" % (r["h"], r["formulation"], r.get("reason", "-"), " |" * 15))
            continue
        st = r.get("solve_stage_time")

        def part(k):
            return ("%.3g s (%s)" % (r[k], pct(r[k] / st))) if finite(r.get(k)) and finite(st) and st > 0 else "-"
        A("| %g | %s | %s | %s | %s | %.3g | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.0f | %s | %s |" % (
            r["h"], r["formulation"], r.get("iterations", "-"), r.get("energy_evals", "-"),
            r.get("hessian_evals", "-"), r["solve_median"],
            fmt(r["solve_median"] / r["iterations"] if r.get("iterations") else None), part("t_factor_k"),
            part("t_newton_linear"), part("t_elastic"), part("contact_solve_time"), part("t_other"),
            pct(r.get("contact_share")), fmt(1e3 * r["search_time_per_call"] if finite(r.get("search_time_per_call")) else None),
            fmt(1e3 * r["segments_time_per_call"] if finite(r.get("segments_time_per_call")) else None),
            r.get("peak_mb", float("nan")), fmt(r.get("P"), "%.6g"), pct(r.get("l2_err"))))
    A("")
    return L


def formulations_cost(args, R):
    """Both formulations' reference runs on hertz at each size of
    --cost-sizes, interleaved, --repeat times, -log_view on every run:
    <out>/formulations.csv and <out>/formulations.md."""
    sizes = [float(x) for x in args.cost_sizes.split(",")]
    date = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    load0 = "%.2f" % load_average()
    rows = measure_formulations_cost(args, R, sizes, date)
    write_csv(rows, os.path.join(args.out, "formulations.csv"), COST_FIELDS)
    L = cost_header(args, date, load0) + cost_ratio_table(rows, sizes) + cost_breakdown_table(rows)
    L.append("Files: formulations.csv (one row per size and formulation), formulations.log (the run's log).")
    with open(os.path.join(args.out, "formulations.md.tmp"), "w") as fh:
        fh.write("\n".join(L) + "\n")
    os.replace(os.path.join(args.out, "formulations.md.tmp"), os.path.join(args.out, "formulations.md"))
    R.say("done: %s/formulations.md, formulations.csv" % args.out)


# -------------------------------------------------------------------- main

def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="the quick variant (target: under 5 minutes on 2 cores)")
    ap.add_argument("--repeat", type=int, default=None, help="runs per configuration (default 3; quick 1)")
    ap.add_argument("--out", default="bench", help="output directory (default bench)")
    ap.add_argument("--bin", default="bin/contact", help="the program (copied once at the start, so that a "
                    "rebuild during the sweep does not mix versions)")
    ap.add_argument("--timeout", type=float, default=None, help="per-run time limit in s (default 1800; quick 90)")
    ap.add_argument("--only", default=None, help="restrict to scene[:h] entries, comma-separated (e.g. hertz:0.01)")
    ap.add_argument("--strategies", default=None, help="restrict to these strategies, comma-separated")
    ap.add_argument("--formulations", default=None, help="restrict to these formulations, comma-separated")
    ap.add_argument("--merge", action="store_true", help="run the (restricted) plan and merge its rows into "
                    "<out>/results.csv (a row of the same configuration replaced), then rewrite RESULTS.md and "
                    "the plots as --report-only does")
    ap.add_argument("--dry-run", action="store_true", help="print the plan and exit")
    ap.add_argument("--report-only", action="store_true", help="rewrite RESULTS.md and the plots from "
                    "<out>/results.csv and <out>/run.json, running nothing")
    ap.add_argument("--formulations-cost", action="store_true", help="only the mortar / gpts cost comparison "
                    "(hertz, reference configuration, interleaved, -log_view): <out>/formulations.md and .csv")
    ap.add_argument("--cost-sizes", default="0.06,0.0065", help="mesh sizes of --formulations-cost "
                    "(default 0.06,0.0065: the reference mesh and the largest of the full sweep)")
    args = ap.parse_args()
    args.repeat = args.repeat or (1 if args.quick else 3)
    args.timeout = args.timeout or (90.0 if args.quick else 1800.0)
    args.t0 = time.time()
    return args


def select_plan(args):
    """The sweep's plan, kept to --only's entries where given."""
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
    for opt, i in ((args.strategies, 0), (args.formulations, 5)):
        if opt:
            names = opt.split(",")
            for e in plan:
                e["configs"] = [c for c in e["configs"] if c[i] in names]
    return [e for e in plan if e["configs"]]


def read_run(out):
    """<out>/run.json: the settings and figures of the sweep that wrote <out>/results.csv (repeat, elapsed,
    bin_git, ...)."""
    with open(os.path.join(out, "run.json")) as fh:
        return json.load(fh)


def report_only(args):
    """RESULTS.md and the plots again from <out>/results.csv and
    <out>/run.json (the settings and figures of the run that wrote them)."""
    meta = read_run(args.out)
    for k in ("quick", "repeat", "timeout", "bin_orig", "bin_sha"):
        setattr(args, k, meta[k])
    args.bin_git = meta.get("bin_git")
    args.generated = meta.get("generated")  # the sweep's own date, not the report's (older run.json: none)
    sys.argv = [sys.argv[0]] + meta["argv"]
    report(read_csv(os.path.join(args.out, "results.csv")), args, meta["info"], meta["meshes"],
           meta["elapsed"], meta["load"])
    print("rewrote %s/RESULTS.md and the plots" % args.out)


def linear_baselines(R, e, args):
    """The linear baseline of a plan entry's mesh at each rank count of its
    configurations: {ranks: {solve, wall, dofs, peak_mb, reason}}."""
    scene, h = e["scene"], e["h"]
    lin = {}
    for ranks in sorted({c[3] for c in e["configs"]}):
        # the baseline is cheap beside the contact runs: at least 3 repeats, except on
        # the meshes whose contact runs are single
        rep = 1 if all(c[4] == 1 for c in e["configs"] if c[3] == ranks) else max(args.repeat, 3)
        lin[ranks] = run_linear(R, scene, h, ranks, rep)
        R.say("%s h=%g: linear baseline, %d rank(s): solve %.3g s, %s dofs %s" % (
            scene, h, ranks, lin[ranks]["solve"], lin[ranks]["dofs"], lin[ranks]["reason"]))
    return lin


def attach_linear(row, lin):
    """A row's linear solve time (its rank count's baseline, else one
    rank's), its ratio to it, and its dofs where the run gave none."""
    base = lin.get(row["ranks"]) or lin.get(1)
    if not row.get("dofs") and base and base.get("dofs"):
        row["dofs"] = base["dofs"]
    row["linear_solve_time"] = base["solve"] if base else float("nan")
    if finite(row.get("solve_median")) and base and finite(base["solve"]) and base["solve"] > 0:
        row["ratio_to_linear"] = row["solve_median"] / base["solve"]


def spread_event_costs(rows, scene, h, ev_rows):
    """The mesh's search/energy costs (from the -log_view of ev_rows, one
    row per formulation), on every row of that mesh and formulation."""
    for form, ev_row in ev_rows.items():
        for r in rows:
            if (r["scene"] == scene and r["h"] == h and r["formulation"] == form
                    and not finite(r.get("search_time_per_call"))):
                for k in ("search_time_per_call", "energy_time_per_call", "contact_hessian_time_per_call",
                          "segments_time_per_call"):
                    r[k] = ev_row.get(k)


def sweep_mesh(R, e, rows, args):
    """One entry of the plan: its meshes, its linear baselines, then its
    configurations in interleaved groups; their rows appended to rows (and
    written to results.csv); returns the mesh's record."""
    scene, h = e["scene"], e["h"]
    m = {"scene": scene, "h": h}
    mt, err = R.mesh(scene, h)
    m["mesh_time"] = mt
    if err:
        R.say("%s h=%g: %s" % (scene, h, err))
        m["note"] = err
        for (s, kp, tol, ranks, rep, form) in e["configs"]:
            rows.append({"scene": scene, "h": h, "formulation": form, "strategy": s, "kp": kp, "gttol": tol,
                         "ranks": ranks, "converged": False, "reason": err})
        return m
    lin = linear_baselines(R, e, args)
    m["dofs"], m["linear"] = lin[1]["dofs"] if 1 in lin else None, lin.get(1, {}).get("solve")
    m["note"] = lin.get(1, {}).get("reason", "")
    ev_rows = {}
    for group in interleave_groups(e["configs"]):
        done = run_interleaved(R, scene, h, group, args.repeat,
                               lambda c: "first" if c[:3] == (REF_STRATEGY, REF_KP, REF_TOL) else None,
                               lambda c: c[3] == 1)
        for row in done:
            attach_linear(row, lin)
            if row["ranks"] == 1 and finite(row.get("search_time_per_call")):
                ev_rows.setdefault(row["formulation"], row)
            rows.append(row)
            R.say("%-52s %8s dofs  it %5s  solve %7s s  wall %7s s  %6s MB  l2 %8s  %s" % (
                config_name(row), row.get("dofs", "-"), row.get("iterations", "-"),
                fmt(row.get("solve_median")), fmt(row.get("wall_median")), fmt(row.get("peak_mb"), "%.0f"),
                pct(row.get("l2_err")), row["reason"]))
    spread_event_costs(rows, scene, h, ev_rows)
    write_csv(rows, os.path.join(args.out, "results.csv"))
    return m


def config_key(r):
    return (r["scene"], float(r["h"]), r["formulation"], r["strategy"], float(r["kp"]), float(r["gttol"]),
            int(r["ranks"]))


def model_key(r):
    return (r["scene"], r["formulation"], float(r["kp"]))


def profile_references(R, new, stored):
    """The reference of profile_err (attach_profile_refs: the finest converged
    run of the default strategy at gttol 1e-8 on one rank of the same model)
    for every model of the merged rows new whose reference the merge did not
    run: that run of stored (results.csv) run once more, with its output, for
    its profile, which only a run holds. Its row is not merged."""
    def is_ref(r):
        return r["strategy"] == REF_STRATEGY and float(r["gttol"]) == REF_TOL and int(r["ranks"]) == 1 \
            and r.get("converged")
    refs = []
    for model in sorted({model_key(r) for r in new}):
        cands = [r for r in new + stored if model_key(r) == model and is_ref(r)]   # new first: min keeps it on a tie
        if not cands:
            continue
        f = min(cands, key=lambda r: float(r["h"]))
        if f.get("_profile"):
            continue   # the merge ran it
        scene, form, kp = model
        _, err = R.mesh(scene, f["h"])
        if err:
            continue
        row = run_interleaved(R, scene, f["h"], [(REF_STRATEGY, kp, REF_TOL, 1, 1, form)], 1,
                              lambda c: None, lambda c: True)[0]
        R.say("%-52s profile reference of the merged rows (not merged)" % config_name(row))
        refs.append(row)
    return refs


def merge_sweep(args, plan, nconf, tmp):
    """The (restricted) plan's rows merged into <out>/results.csv, then the
    report from the merged rows with the settings of the run that wrote the
    file (run.json; its argv and elapsed time gain this run's). The merged
    rows' profile errors are against their models' references, run again for
    their profiles where the plan does not hold them (profile_references)."""
    R = Sweep(args, tmp, "merge.log")
    R.say("merge: %d meshes, %d configurations, repeat %d, into %s/results.csv" % (len(plan), nconf, args.repeat,
                                                                                  args.out))
    new = []
    for e in plan:
        sweep_mesh(R, e, new, argparse.Namespace(**dict(vars(args), out=tmp)))
    path = os.path.join(args.out, "results.csv")
    stored = read_csv(path)
    attach_profile_refs(new + profile_references(R, new, stored))
    for r in new:   # their figures now stored ones: the report's attach_profile_refs keeps them
        r.pop("_profile", None)
    keys = {config_key(r) for r in new}
    rows = [r for r in stored if config_key(r) not in keys] + new
    meta = read_run(args.out)
    meta["argv"] = meta["argv"] + ["+ merged (binary sha256 %s, git %s):" % (args.bin_sha, args.bin_git)] \
        + sys.argv[1:]
    meta["elapsed"] += time.time() - args.t0
    meta["generated"] = args.generated = now_minute()
    with open(os.path.join(args.out, "run.json"), "w") as fh:
        json.dump(meta, fh, indent=1)
    for k in ("quick", "repeat", "timeout", "bin_orig", "bin_sha"):
        setattr(args, k, meta[k])
    args.bin_git = meta.get("bin_git")
    sys.argv = [sys.argv[0]] + meta["argv"]
    report(rows, args, meta["info"], meta["meshes"], meta["elapsed"], meta["load"])
    R.say("merged %d rows into %s" % (len(new), path))


def run_sweep(args, plan, nconf, tmp):
    """The plan, mesh by mesh, then run.json and the report."""
    R = Sweep(args, tmp)
    info = machine_info()
    load0 = "%.2f" % load_average()
    R.say("%d meshes, %d configurations, repeat %d, timeout %g s, out %s" % (len(plan), nconf, args.repeat,
                                                                              args.timeout, args.out))
    rows = []
    meshes = [sweep_mesh(R, e, rows, args) for e in plan]
    elapsed = time.time() - args.t0
    load = (load0, "%.2f" % load_average())
    args.generated = now_minute()
    with open(os.path.join(args.out, "run.json"), "w") as fh:
        json.dump({"quick": args.quick, "repeat": args.repeat, "timeout": args.timeout, "bin_orig": args.bin_orig,
                   "bin_sha": args.bin_sha, "bin_git": args.bin_git, "argv": sys.argv[1:], "info": info, "meshes": meshes,
                   "elapsed": elapsed, "load": load, "generated": args.generated}, fh, indent=1)
    report(rows, args, info, meshes, elapsed, load)
    R.say("done in %.0f s: %s/results.csv, RESULTS.md, error_vs_time.png, time_vs_dofs.png, ratio_to_linear.png"
          % (elapsed, args.out))


def main():
    args = parse_args()
    os.chdir(ROOT)
    plan = select_plan(args)
    nconf = sum(len(e["configs"]) for e in plan)
    if args.dry_run:
        for e in plan:
            print("%-13s h=%-6g %3d configurations" % (e["scene"], e["h"], len(e["configs"])))
        print("total %d configurations (x repeat %d, plus one linear baseline per mesh)" % (nconf, args.repeat))
        return 0
    os.makedirs(args.out, exist_ok=True)
    args.out = os.path.abspath(args.out)
    if args.report_only:
        report_only(args)
        return 0
    tmp = tempfile.mkdtemp(prefix="bench-")
    try:
        args.bin_orig = os.path.abspath(args.bin)
        args.bin_sha = contactrun.program_sha(args.bin_orig)
        args.bin_git = git_info(args.out)  # the tree when the program was copied
        args.bin = contactrun.copy_program(tmp, args.bin_orig)
        if args.formulations_cost:
            formulations_cost(args, Sweep(args, tmp, "formulations.log"))
        elif args.merge:
            merge_sweep(args, plan, nconf, tmp)
        else:
            run_sweep(args, plan, nconf, tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
