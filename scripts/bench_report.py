"""The benchmark's report (scripts/bench.py): RESULTS.md, section by section,
from the rows and the figures that bench_analysis.report_figures gathers.

Each report_* function returns its section's lines; REPORT_SECTIONS holds
them in order, the table of targets (bench_targets.report_targets) among
them; write_results_md writes the file.
"""
import datetime
import math
import os
import sys

from bench_analysis import (ERROR_LEVELS, accuracy_curve, cheapest, default_runs, fixed_cost_share,
                            off_profile_model, on_profile_ref_mesh, on_ref_mesh, search_share)
from bench_sweep import REF_KP, STRATEGIES, config_name, fmt, pct
from bench_targets import report_targets
from contactrun import ROOT, finite, git_info


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


# the sections of RESULTS.md, in order
REPORT_SECTIONS = (report_header, report_machine, report_design, report_definitions, report_targets, report_formulations,
                   report_cheapest, report_scaling, report_ranks, report_half_model, report_graded, report_strategies,
                   report_failures, report_meshes, report_files)


def write_results_md(rows, ctx):
    """<out>/RESULTS.md: its sections (REPORT_SECTIONS) from the rows and the figures of report_figures."""
    L = []
    for section in REPORT_SECTIONS:
        L += section(rows, ctx)
    with open(os.path.join(ctx.out, "RESULTS.md.tmp"), "w") as fh:
        fh.write("\n".join(L) + "\n")
    os.replace(os.path.join(ctx.out, "RESULTS.md.tmp"), os.path.join(ctx.out, "RESULTS.md"))
