"""The benchmark's sweep (scripts/bench.py): what it runs, and the names and
number formats of its configurations.

The scenes, solver strategies, penalties, tolerances and contact
formulations, and the reference configuration (REF_*); sweep_plan, the
meshes and configurations of the whole sweep or of --quick, and select_plan,
that plan kept to --only, --strategies and --formulations; config_name, fmt
and pct, which the log and the reports share.
"""
import math

from contactrun import finite


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
