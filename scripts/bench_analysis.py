"""The benchmark's analysis (scripts/bench.py): references, errors, cost fits
and the cheapest configurations, from the rows.

attach_references and attach_profile_refs give each row its errors against
the finest run of the same model; default_runs, formulation_ratio_rows,
cost_ratio_pairs, reference_solve_runs and linear_ratio_runs select the runs
that the report and the targets count; fit_exponent fits the cost exponents;
cheapest finds the cheapest configuration reaching an error; accuracy_curve
reads -accuracy's curve; report_figures gathers what the sections of
RESULTS.md share. Nothing here runs the program, draws or writes.
"""
import json
import os
import types

import numpy as np

import profile_metrics
from bench_results import read_formulations_cost
from bench_sweep import FORMULATIONS, REF_FORMULATION, REF_KP, REF_STRATEGY, REF_TOL
from contactrun import ROOT, finite


FIT_DOFS = (1e4, 1.2e6)  # the range of dofs over which the cost exponents are fitted
ERROR_LEVELS = (0.10, 0.03, 0.01)


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
