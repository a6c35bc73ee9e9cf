"""The benchmark's plots (scripts/bench.py): error_vs_time.png,
time_vs_dofs.png and ratio_to_linear.png, drawn from the rows.

plots() draws the three; it alone imports matplotlib.
"""
import math
import os

import numpy as np

from bench_analysis import ERROR_LEVELS, accuracy_curve, default_runs, on_profile_ref_mesh, on_ref_mesh
from bench_sweep import FORMULATIONS, REF_FORMULATION, REF_KP, REF_STRATEGY, REF_TOL, STRATEGIES
from bench_targets import LINEAR_RATIO_TARGET
from contactrun import finite


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
