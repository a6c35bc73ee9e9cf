"""Rigid bodies against their independent answers: the scenes rigid-hertz
(Hertz with E* = E / (1 - nu^2), and the disc made elastic and 1e5 times
stiffer), rigid-punch (Sadowsky's pressure, either slave) and rigid-sphere
(Hertz's point contact in r-z); and the rigid body's unknowns (measure_free):
the disc force-controlled (the displaced run's motion), the roller held by
its contacts (Hertz, and half the race's displacement by symmetry), the
punch turning freely under an eccentric force (Johnson's tilted punch).
Used by tests/test_rigid.py and by readme_figures.py --measure rigid, which
writes bench/rigid/results.json and the README's tables from it.

    python3 scripts/rigid_study.py        # measures and prints the table
"""
import os
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HERTZ = ["-options_file", "meshes/rigid-hertz/rigid-hertz.opts"]
PUNCH = ["-options_file", "meshes/rigid-punch/rigid-punch.opts"]
SPHERE = ["-options_file", "meshes/rigid-sphere/rigid-sphere.opts"]
SSNV104 = ["-options_file", "meshes/ssnv104/ssnv104.opts"]
SSNV104_RIGID = ["-options_file", "meshes/ssnv104-rigid/ssnv104-rigid.opts"]
ROLLER = ["-options_file", "meshes/rigid-roller/rigid-roller.opts"]
# the rigid punch pushed by a force through a point e = 0.1 right of its axis, free to turn about it
TILT = PUNCH + ["-punch_rigid_rotation", "free", "-punch_rigid_centre", "0.1,0.125",
                "-punch_bc_push_control", "displacement,force", "-punch_bc_push_values", "0,-0.15"]
B = 0.25   # the punch's half-width


def rewrite_options(scene, tmp, name, swaps, rename):
    """The scene's options file written to tmp/name with each line that starts
    with a key of swaps replaced by its value (None: dropped), the block's
    geometry path made absolute, and the group names renamed (old, new)."""
    out = []
    with open(os.path.join(ROOT, scene)) as f:
        for line in f.read().splitlines():
            key = next((k for k in swaps if line.startswith(k)), None)
            if key is not None and swaps[key] is None:
                continue
            line = swaps[key] if key is not None else line
            if line.startswith("-block_geo "):
                line = f"-block_geo {ROOT}/meshes/hertz/block.geo"
            out.append(line.replace(*rename))
    path = os.path.join(str(tmp), name)
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return path


def stiff_options(tmp, E):
    """An options file of the rigid-hertz scene with the disc elastic (the
    reference scene's full disc, clamped behind, graded alike) of modulus E."""
    return rewrite_options("meshes/rigid-hertz/rigid-hertz.opts", tmp, f"stiff{E:g}.opts",
                           {"-indenter_geo ": f"-indenter_geo {ROOT}/meshes/hertz/indenter.geo",
                            "-indenter_geo_params": "-indenter_geo_params R=1,xc=-1,yc=0,xclamp=-1.8,xcontact=-0.5,hc=0.0076,dc=1",
                            "-indenter_rigid": f"-indenter_E {E}\n-indenter_nu 0.3"}, ("back", "clamp"))


def rigid_reference_options(tmp):
    """An options file of the reference scene (meshes/hertz) with the disc
    rigid: its circle alone (rigid-hertz's indenter.geo, the same arcs and
    sizes as the elastic disc's boundary), held behind."""
    return rewrite_options("meshes/hertz/hertz.opts", tmp, "hertz-rigid.opts",
                           {"-indenter_geo ": f"-indenter_geo {ROOT}/meshes/rigid-hertz/indenter.geo",
                            "-indenter_geo_params": "-indenter_geo_params R=1,xc=-1,yc=0,xcontact=-0.5",
                            "-indenter_E": "-indenter_rigid", "-indenter_nu": None}, ("clamp", "back"))


ADEQUACY_RATIOS = (10, 100, 1000)


def measure_adequacy():
    """The reference scene with the disc E2/E1 times stiffer than the block
    against the disc rigid: the rigid model's error in P, p_max and the
    second-moment a, each relative to the elastic disc's."""
    from contactrun import run_checked
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        r = run_checked(["-options_file", rigid_reference_options(tmp), "-output", "none"], tmp, "rigid").summary
        for ratio in ADEQUACY_RATIOS:
            e = run_checked(["-options_file", "meshes/hertz/hertz.opts", "-indenter_E", str(1000 * ratio), "-output", "none"],
                            tmp, f"e{ratio}").summary
            rows.append(dict(ratio=ratio, P=e["contact_force"], P_rigid=r["contact_force"], pmax=e["fem_pmax"],
                             pmax_rigid=r["fem_pmax"], a=e["fem_a_moment"], a_rigid=r["fem_a_moment"],
                             dofs=e["dofs"], dofs_rigid=r["dofs"]))
    return rows


def adequacy_table(rows):
    out = ["| E2 / E1 | P, elastic disc | the rigid disc's error in P | in p_max | in the second-moment a |",
           "|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['ratio']:g} | {r['P']:.6g} | {100 * (r['P_rigid'] / r['P'] - 1):+.2f} % | "
                   f"{100 * (r['pmax_rigid'] / r['pmax'] - 1):+.2f} % | {100 * (r['a_rigid'] / r['a'] - 1):+.2f} % |")
    return "\n".join(out) + "\n"


def adequacy_phrase(rows):
    """The adequacy table in a phrase: the rigid disc's error in P at each E2/E1."""
    ratios = " / ".join(f"{r['ratio']:g}" for r in rows)
    dP = " / ".join(f"{100 * (r['P_rigid'] / r['P'] - 1):+.2f}" for r in rows)
    return f"a disc {ratios} times stiffer than the block taken as rigid errs P by {dP} %"


def sadowsky_l2(h5, P):
    """(slave surface, relative L2 distance of its nodal pressure from
    Sadowsky's p = P / (pi sqrt(b^2 - x^2)) over |x| < 0.6 b, node weights)."""
    for name in ("punch_contact", "block_contact"):
        g = h5[f"contact/tool/{name}"]
        if not g.attrs["slave"]:
            continue
        X, p, w = g["node_X"][...], g["node_pressure"][...], g["node_weight"][...]
        m = np.abs(X[:, 0]) < 0.6 * B
        ps = P / (np.pi * np.sqrt(B * B - X[m, 0] ** 2))
        return name, float(np.sqrt(np.sum(w[m] * (p[m] - ps) ** 2) / np.sum(w[m] * ps ** 2)))
    raise ValueError("no slave surface")


def hertz_row(label, s):
    return dict(scene=label, dofs=s["dofs"], iterations=s["iterations"], solve=s["time"]["solve"], P=s["contact_force"],
                fem_pmax=s["fem_pmax"], hertz_pmax=s["hertz_pmax"], fem_a=s["fem_a_moment"], hertz_a=s["hertz_a"])


def timed_pair(rigid_args, elastic_args, tmp, repeat=3):
    """The rigid and the elastic variant of a scene run alternately repeat
    times: each one's last summary with the median of its solve times."""
    from contactrun import median, mesh_only, run_checked
    mesh_only(rigid_args[:2])
    mesh_only(elastic_args[:2])
    runs = {"rigid": [], "elastic": []}
    for _ in range(repeat):
        for key, args in (("rigid", rigid_args), ("elastic", elastic_args)):
            runs[key].append(run_checked(args, tmp, key).summary)
    out = {}
    for key, rs in runs.items():
        out[key] = dict(rs[-1])
        out[key]["time"] = dict(rs[-1]["time"], solve=median([r["time"]["solve"] for r in rs]))
    return out["rigid"], out["elastic"]


def measure():
    """The rows of the table: each run once, but the rigid and stiff variants
    of rigid-hertz (E = 1e8) and of SSNV104, alternated 3 times, with their
    median solve times."""
    import h5py
    from contactrun import run_checked
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        rigid, stiff = timed_pair(HERTZ, ["-options_file", stiff_options(tmp, 1e8)], tmp)
        rows.append(hertz_row("rigid-hertz, mortar (the block as slave)", rigid))
        rows.append(hertz_row("rigid-hertz, gpts", run_checked(HERTZ + ["-contact_formulation", "gpts"], tmp, "g").summary))
        rows.append(hertz_row("rigid-hertz, mortar, the rigid disc as slave",
                              run_checked(HERTZ + ["-contact_mortar_slave", "first"], tmp, "f").summary))
        rows.append(dict(hertz_row("the disc elastic, E = 1e8", stiff), dP=rigid["contact_force"] / stiff["contact_force"] - 1,
                         speedup=stiff["time"]["solve"] / rigid["time"]["solve"]))
        s = run_checked(["-options_file", stiff_options(tmp, 1e10)], tmp, "E1e10").summary
        rows.append(dict(hertz_row("the disc elastic, E = 1e10", s), dP=rigid["contact_force"] / s["contact_force"] - 1))
        rows.append(hertz_row("rigid-sphere (r-z)", run_checked(SPHERE, tmp, "s").summary))
        r, e = timed_pair(SSNV104_RIGID, SSNV104, tmp)
        rows.append(hertz_row("ssnv104-rigid (the plane rigid)", r))
        rows.append(dict(hertz_row("ssnv104 (the plane elastic, 10^4 times stiffer)", e), speedup=e["time"]["solve"] / r["time"]["solve"]))
        for slave in ("auto", "second"):
            r = run_checked(PUNCH + ["-contact_mortar_slave", slave], tmp, f"p{slave}")
            P = r.summary["contact"]["tool"]["P"]
            with h5py.File(r.h5) as h5:
                name, err = sadowsky_l2(h5, P)
            rows.append(dict(scene=f"rigid-punch, {name.split('_')[0]} as slave", dofs=r.summary["dofs"],
                             iterations=r.summary["iterations"], solve=r.summary["time"]["solve"], P=P, sadowsky=err))
    return rows


def tilt_angle(P=0.15, e=0.1, E=100.0, nu=0.3):
    """Johnson's rigid flat punch on a half-space, tilted by the moment P e
    (Contact Mechanics, 2.8): alpha = 4 P e / (pi E* b^2), E* = E / (1 - nu^2)."""
    return 4 * P * e / (np.pi * E / (1 - nu * nu) * B * B)


def measure_free():
    """The rigid bodies' unknowns, each run once: the disc force-controlled by
    the displaced run's force, the roller held by contact, the tilted punch;
    mortar and gpts."""
    from contactrun import run_checked
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for f in ("mortar", "gpts"):
            form = ["-contact_formulation", f]
            d = run_checked(HERTZ + form, tmp, f"d{f}").summary
            F = -d["bodies"]["indenter"]["force"][0]   # the force to apply: minus the contact's on it
            s = run_checked(HERTZ + form + ["-block_bc_push_values", "0,0", "-indenter_bc_back_control", "force,displacement",
                                            "-indenter_bc_back_values", f"{F!r},0"], tmp, f"f{f}").summary
            rows.append(dict(scene=f"rigid-hertz, the disc force-controlled, {f}", dofs=s["dofs"], iterations=s["iterations"],
                             solve=s["time"]["solve"], P=s["contact_force"],
                             ref=f"the displaced run's motion 0.0095: {s['bodies']['indenter']['translation'][0] / 0.0095 - 1:+.1e}"))
            s = run_checked(ROLLER + form, tmp, f"r{f}").summary
            c = s["contact"]["below"]
            sym = s["bodies"]["roller"]["translation"][1] / (s["force_control"][0]["displacement"] / 2) - 1
            rows.append(dict(scene=f"rigid-roller, held by its contacts, {f}", dofs=s["dofs"], iterations=s["iterations"],
                             solve=s["time"]["solve"], P=c["P"],
                             ref=(f"Hertz: p_max {100 * (c['fem_pmax'] / c['hertz_pmax'] - 1):+.2f} %, a "
                                  f"{100 * (c['fem_a_moment'] / c['hertz_a'] - 1):+.2f} %; half the race's motion {sym:+.0e}")))
            s = run_checked(TILT + form, tmp, f"t{f}").summary
            rows.append(dict(scene=f"rigid-punch, turning freely under an eccentric force, {f}", dofs=s["dofs"],
                             iterations=s["iterations"], solve=s["time"]["solve"], P=s["bodies"]["punch"]["force"][1],
                             ref=f"Johnson's tilt {tilt_angle():.4e}: {-s['bodies']['punch']['rotation'] / tilt_angle() - 1:+.2%}"))
    return rows


def free_table(rows):
    """One row per case, mortar's and gpts' figures side by side."""
    out = ["| run | P | mortar: Newton iterations, solve, against its reference | gpts: the same |", "|---|---|---|---|"]
    cases = {}
    for r in rows:
        case, form = r["scene"].rsplit(", ", 1)
        cases.setdefault(case, {})[form] = r
    for case, by in cases.items():
        cells = [f"{by[f]['iterations']}, {by[f]['solve']:.2f} s, {by[f]['ref']}" for f in ("mortar", "gpts")]
        out.append(f"| {case} ({by['mortar']['dofs']:,} dofs) | {by['mortar']['P']:.6g} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def table(rows, free=()):
    """The scenes' rows, then the rigid unknowns' cases with mortar (free: measure_free's rows; gpts beside them in free_table)."""
    out = ["| run | dofs | Newton iterations | solve | P | against its reference |", "|---|---|---|---|---|---|"]
    rigidP = rows[0]["P"]
    for r in rows:
        if "sadowsky" in r:
            ref = f"Sadowsky's pressure, L2 over \\|x\\| < 0.6 b: {100 * r['sadowsky']:.2f} %"
        elif "dP" in r:
            ref = f"the rigid disc's P {rigidP:.6g}: {r['dP']:+.1e}"
            if "speedup" in r:
                ref += f"; the rigid disc's solve {r['speedup']:.2f} times as fast"
        elif "speedup" in r:
            ref = (f"Hertz: p_max {100 * (r['fem_pmax'] / r['hertz_pmax'] - 1):+.2f} %, a "
                   f"{100 * (r['fem_a'] / r['hertz_a'] - 1):+.2f} %; the rigid one's solve {r['speedup']:.2f} times as fast")
        else:
            ref = (f"Hertz: p_max {100 * (r['fem_pmax'] / r['hertz_pmax'] - 1):+.2f} %, second-moment a "
                   f"{100 * (r['fem_a'] / r['hertz_a'] - 1):+.2f} %")
        out.append(f"| {r['scene']} | {r['dofs']:,} | {r['iterations']} | {r['solve']:.2f} s | {r['P']:.6g} | {ref} |")
    for r in free:
        if r["scene"].endswith(", mortar"):
            out.append(f"| {r['scene']} | {r['dofs']:,} | {r['iterations']} | {r['solve']:.2f} s | {r['P']:.6g} | {r['ref']} |")
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    import sys
    sys.path.insert(0, os.path.join(ROOT, "scripts"))
    print(adequacy_table(measure_adequacy()))
    print(table(measure()))
