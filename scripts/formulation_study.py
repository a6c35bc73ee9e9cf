#!/usr/bin/env python3
"""The contact formulations compared on the contact pressure: convergence under
refinement on the reference scene, oscillation, Hertz where Hertz holds, and
the contact patch test.

    python3 scripts/formulation_study.py [--out bench/formulations]

Runs bin/contact (from the repository root) and writes <out>/results.json
(every figure) and <out>/RESULTS.md (the tables); scripts/readme_figures.py
renders the same tables into docs/formulations.md from results.json. About 8 minutes
on 2 cores.

- Convergence: the mirrored half of the reference scene (hertz-half: the full
  problem's contact) at h = 0.1, 0.06, 0.03, 0.015, each profile's relative L2
  distance from the same formulation's run at h = 0.005, the observed rate (a
  least-squares fit of log distance on log h), the oscillation index
  (profile_metrics.oscillation: a sample's deviation from the mean of its two
  neighbours, less that of the Hertz profile with the profile's computed peak
  and half-width at the same samples, largest within 0.8 a of the centre, over
  the peak), p_max and the half-width against the finest run.
- Hertz where it holds: hertz-small (a/R = 0.10) with a/h = 6, 12, 24, 48
  elements across the half-width (size a/n within 0.14 of the first contact
  point): the profile's relative L2 error against Hertz and p_max.
- Contact patch test: meshes/patch, the largest relative error of the
  pressure at a slave sample against the exact uniform pressure.
- Mortar's design alternatives (weights, slave side, blend) at h = 0.06 and
  0.03, with the patch test of each.
"""
import argparse
import json
import os
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import profile_metrics as pm  # noqa: E402
from contactrun import run_checked  # noqa: E402

FORMULATIONS = ["gpts", "mortar"]
HS = [0.1, 0.06, 0.03, 0.015]
HREF = 0.005
AH = [6, 12, 24, 48]


def slave_profiles(h5):
    return pm.profiles(h5)[0]


def convergence(form, tmp):
    base = ["-options_file", "meshes/hertz-half/hertz-half.opts", "-contact_formulation", form]
    runs = {h: run_checked(base + ["-mesh_size", str(h)], tmp, f"{form}-h{h}") for h in HS + [HREF]}
    ref = slave_profiles(runs[HREF].h5)
    rows = []
    for h in HS:
        summ = runs[h].summary
        prof = slave_profiles(runs[h].h5)
        d, osc, pmax, a = [], [], [], []
        for k, p in prof.items():
            r = ref[k]
            aref = pm.half_width(*r)
            d.append(pm.l2_distance(p, r))
            osc.append(pm.oscillation(*p))
            pmax.append(p[1].max() / r[1].max() - 1)
            a.append(pm.half_width(*p) / aref - 1)
        rows.append(dict(h=h, dofs=summ["dofs"], iterations=summ["iterations"], solve=summ["time"]["solve"],
                         l2=float(np.mean(d)), osc=float(max(osc)), pmax=float(np.mean(pmax)), a=float(np.mean(a)),
                         hertz_l2=summ["pressure_l2_error"]))
    rate = float(np.polyfit(np.log(HS), np.log([r["l2"] for r in rows]), 1)[0])
    return dict(rows=rows, rate=rate, ref_pmax=float(np.mean([p[1].max() for p in ref.values()])),
                ref_dofs=runs[HREF].summary["dofs"])


def hertz_small(form, tmp):
    rows = []
    for n in AH:
        geo = f"hc={0.1036 / n:.6g},rc=0.14,dc=0.3"
        summ = run_checked(["-options_file", "meshes/hertz-small/hertz-small.opts", "-contact_formulation", form,
                            "-indenter_geo_params", "R=1,xc=-1,yc=0,xclamp=-1.8,xcontact=-0.5," + geo,
                            "-block_geo_params", "x0=0,W=1,H=2," + geo], tmp, f"{form}-small{n}").summary
        rows.append(dict(ah=n, dofs=summ["dofs"], l2=summ["pressure_l2_error"],
                         pmax=summ["fem_pmax"] / summ["hertz_pmax"] - 1, a=summ["fem_a"] / summ["hertz_a"] - 1))
    return rows


def patch(form, tmp):
    prof = slave_profiles(run_checked(["-options_file", "meshes/patch/patch.opts", "-contact_formulation", form,
                                       "-tao_gttol", "1e-12"], tmp, f"{form}-patch").h5)
    p = np.concatenate([v[1] for v in prof.values()])
    return dict(pmin=float(p.min()), pmax=float(p.max()), maxrel=float(np.abs(p / 8.0 - 1).max()))


ALTERNATIVES = [("dual", "first", None), ("quadratic", "first", None), ("linear", "first", None),
                ("sublinear", "first", None), ("dual", "both", None), ("dual", "second", None), ("dual", "first", 0.05)]


def alternatives(tmp):
    """The mortar design choices at h = 0.06 and 0.03 on the half reference
    scene, against the default's finest run; and the patch test of each."""
    ref = slave_profiles(run_checked(["-options_file", "meshes/hertz-half/hertz-half.opts", "-contact_formulation",
                                      "mortar", "-mesh_size", str(HREF)], tmp, "alt-ref").h5)
    rows = []
    for basis, slave, blend in ALTERNATIVES:
        opts = ["-contact_formulation", "mortar", "-contact_mortar_basis", basis, "-contact_mortar_slave", slave]
        opts += ["-contact_blend", str(blend)] if blend is not None else []
        row = dict(basis=basis, slave=slave, blend=blend if blend is not None else 0.0)
        for h in (0.06, 0.03):
            prof = slave_profiles(run_checked(["-options_file", "meshes/hertz-half/hertz-half.opts", "-mesh_size",
                                               str(h)] + opts, tmp, f"alt-{basis}-{slave}-{blend}-{h}").h5)
            r = ref["indenter_contact"]
            row[f"osc{h}"] = max(pm.oscillation(*p) for p in prof.values())
            row[f"pmax{h}"] = float(np.mean([p[1].max() for p in prof.values()]))
            if "indenter_contact" in prof:
                row[f"l2{h}"] = pm.l2_distance(prof["indenter_contact"], r)
        h5 = run_checked(["-options_file", "meshes/patch/patch.opts", "-tao_gttol", "1e-12"] + opts, tmp,
                         f"alt-{basis}-{slave}-{blend}-patch").h5
        pp = np.concatenate([v[1] for v in slave_profiles(h5).values()])
        row["patch"] = float(np.abs(pp / 8.0 - 1).max())
        rows.append(row)
    return rows


def tables(res):
    pct = lambda x: f"{100 * x:.2f} %"  # noqa: E731
    out = ["Reference scene (its mirrored half, `hertz-half`), k_p = 2e6, against the same formulation's run at "
           f"h = {HREF} ({res['mortar']['conv']['ref_dofs']:,} dofs); the oscillation index is the largest deviation "
           "of a pressure sample from the mean of its two neighbours, less the same deviation of the Hertz profile "
           "with the computed peak and half-width centred at the pressure centroid (so 0 for a Hertz profile on any "
           "grid), within 0.8 a of the centre, over the peak:", "",
           "| formulation | h | dofs | Newton iterations | L2 distance from the finest | oscillation index "
           "| p_max vs finest | half-width vs finest |", "|---|---|---|---|---|---|---|---|"]
    for form in FORMULATIONS:
        c = res[form]["conv"]
        for r in c["rows"]:
            out.append(f"| {form} | {r['h']} | {r['dofs']:,} | {r['iterations']} | {pct(r['l2'])} | {r['osc']:.4f} "
                       f"| {100 * r['pmax']:+.2f} % | {100 * r['a']:+.2f} % |")
    out += ["", "Observed rate of the L2 distance (least-squares fit over h): " +
            ", ".join(f"{form} {res[form]['conv']['rate']:.2f}" for form in FORMULATIONS) +
            "; finest p_max: " + ", ".join(f"{form} {res[form]['conv']['ref_pmax']:.2f}" for form in FORMULATIONS) + ".",
            "", "Where Hertz holds (`hertz-small`, a/R = 0.10), a/h elements across the half-width:", "",
            "| formulation | a/h | dofs | profile L2 error vs Hertz | p_max vs Hertz | a vs Hertz |",
            "|---|---|---|---|---|---|"]
    for form in FORMULATIONS:
        for r in res[form]["small"]:
            out.append(f"| {form} | {r['ah']} | {r['dofs']:,} | {pct(r['l2'])} | {100 * r['pmax']:+.2f} % "
                       f"| {100 * r['a']:+.2f} % |")
    out += ["", "Mortar design alternatives (`-contact_mortar_basis`, `-contact_mortar_slave`, `-contact_blend`), "
            "the half reference scene against the default's run at h = 0.005 (L2 distance of the disc's profile, "
            "where the disc is a slave), and the patch test's largest relative pressure error:", "",
            "| weights | slave | blend | L2 h = 0.06 | L2 h = 0.03 | oscillation 0.06 | oscillation 0.03 "
            "| p_max 0.03 | patch test |", "|---|---|---|---|---|---|---|---|---|"]
    for r in res["alternatives"]:
        l2 = [pct(r[k]) if k in r else "-" for k in ("l20.06", "l20.03")]
        out.append(f"| {r['basis']} | {r['slave']} | {r['blend']:g} | {l2[0]} | {l2[1]} | {r['osc0.06']:.4f} "
                   f"| {r['osc0.03']:.4f} | {r['pmax0.03']:.2f} | {r['patch']:.1e} |")
    out += ["", "Contact patch test (`meshes/patch`, exact pressure 8): " +
            "; ".join(f"{form} {res[form]['patch']['pmin']:.6g} to {res[form]['patch']['pmax']:.6g} "
                      f"(largest relative error {res[form]['patch']['maxrel']:.1e})" for form in FORMULATIONS) + "."]
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "formulations"))
    args = ap.parse_args()
    res = {}
    with tempfile.TemporaryDirectory() as tmp:
        for form in FORMULATIONS:
            res[form] = dict(conv=convergence(form, tmp), small=hertz_small(form, tmp), patch=patch(form, tmp))
            print(form, "done", flush=True)
        res["alternatives"] = alternatives(tmp)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump(res, f, indent=1)
    text = tables(res)
    with open(os.path.join(args.out, "RESULTS.md"), "w") as f:
        f.write("# Contact formulations: the pressure\n\nWritten by `python3 scripts/formulation_study.py`.\n\n" + text)
    print(text)


if __name__ == "__main__":
    main()
