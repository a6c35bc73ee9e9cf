"""The benchmark's files (scripts/bench.py): results.csv, run.json and
formulations.csv, their columns, reading and writing.

results.csv holds one row per configuration (CSV_FIELDS; write_csv,
read_csv); run.json the settings and figures of the sweep that wrote it
(read_run), from which --report-only and --merge write the report again;
formulations.csv the rows of --formulations-cost (COST_FIELDS,
read_formulations_cost).
"""
import csv
import json
import os
import re

from bench_sweep import REF_FORMULATION


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


COST_FIELDS = ["date", "h", "formulation", "dofs", "repeats", "solve_runs", "wall_runs", "solve_median", "wall_median",
               "ratio", "iterations", "energy_evals", "hessian_evals", "converged", "reason", "P", "l2_err",
               "peak_mb", "solve_stage_time", "contact_solve_time", "contact_share", "t_factor_k", "t_newton_linear",
               "t_elastic", "t_other", "search_time_per_call", "segments_time_per_call", "energy_time_per_call",
               "contact_hessian_time_per_call"]


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


def read_run(out):
    """<out>/run.json: the settings and figures of the sweep that wrote <out>/results.csv (repeat, elapsed,
    bin_git, ...)."""
    with open(os.path.join(out, "run.json")) as fh:
        return json.load(fh)


def read_formulations_cost(out):
    """The rows of <out>/formulations.csv (--formulations-cost), or []."""
    path = os.path.join(out, "formulations.csv")
    if not os.path.exists(path):
        return []
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))
