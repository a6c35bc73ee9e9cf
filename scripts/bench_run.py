"""Running the benchmark's configurations (scripts/bench.py), one mesh of the
plan at a time.

Sweep holds the log, the temporary directory and the copied program;
ConfigRun runs the repeats of one configuration one step at a time, so that
the configurations that differ only in their formulation run interleaved
(run_interleaved); log_figures reads the per-call costs and the contact share
from -log_view; run_linear and linear_baselines run a mesh's linear baseline;
sweep_mesh runs one entry of the plan, and profile_references the finest runs
whose profiles a --merge needs.
"""
import math
import os
import time

import numpy as np

import contactrun
import profile_metrics
from bench_results import write_csv
from bench_sweep import REF_KP, REF_STRATEGY, REF_TOL, SCENES, STRATEGIES, config_name, fmt, pct
from contactrun import event_totals, finite, median, mesh_only, parse_log_view, parse_tao_line


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
