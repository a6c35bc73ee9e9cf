#!/usr/bin/env python3
"""Behaviour unchanged, shown: run every scene (and a 2-rank run and an
-accuracy run) with one build, then compare the outputs of two such sets.

    python3 scripts/same_results.py run DIR [--bin bin/contact]   # writes DIR/<case>.json, .h5
    python3 scripts/same_results.py compare DIR_A DIR_B [--rtol 1e-12]

The comparison takes every number of each JSON summary (timings and the run id
aside) and every dataset and attribute of each HDF5 file (the run id, the
options and the timings aside) and reports the largest relative difference;
it exits 1 if one exceeds rtol (relative to the larger magnitude, with a floor
of rtol times the dataset's largest magnitude, so that a round-off zero does
not count as a relative difference of 1)."""
import argparse
import glob
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contactrun import ROOT, run_case  # noqa: E402

SKIP_JSON = ("time", "run_id", "solve_time")
SKIP_H5 = ("run_id", "options", "time_mesh", "time_setup", "time_solve", "time_output", "time_total")


def cases():
    """(name, options, ranks): every scene at its defaults, the reference scene
    with gpts, on 2 ranks and under -accuracy."""
    out = []
    for opts in sorted(glob.glob(os.path.join(ROOT, "meshes", "*", "*.opts"))):
        out.append((os.path.basename(opts)[:-5], ["-options_file", os.path.relpath(opts, ROOT)], 1))
    hertz = ["-options_file", "meshes/hertz/hertz.opts"]
    out.append(("hertz-gpts", hertz + ["-contact_formulation", "gpts"], 1))
    out.append(("hertz-np2", hertz + ["-mesh_size", "0.06"], 2))
    out.append(("hertz-accuracy", hertz + ["-accuracy", "0.03"], 1))
    out.append(("hertz-taylor", hertz + ["-taylor_test"], 1))
    return out


def run(directory, binary):
    os.makedirs(directory, exist_ok=True)
    for name, opts, ranks in cases():
        r = run_case(opts, directory, name, ranks=ranks, binary=binary)
        with open(os.path.join(directory, name + ".log"), "w") as f:
            f.write(r.stdout + r.stderr)
        print(f"{name}: exit {r.returncode}", flush=True)


def flat(v, key=""):
    if isinstance(v, dict):
        for k, x in v.items():
            if k not in SKIP_JSON:
                yield from flat(x, f"{key}.{k}" if key else k)
    elif isinstance(v, list):
        for i, x in enumerate(v):
            yield from flat(x, f"{key}[{i}]")
    else:
        yield key, v


def differ(a, b, rtol):
    """Largest relative difference of two arrays (None: not comparable)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape:
        return None
    if a.dtype.kind in "SUO" or b.dtype.kind in "SUO":
        return 0.0 if np.array_equal(a, b) else None
    a, b = a.astype(float), b.astype(float)
    nan = np.isnan(a) | np.isnan(b)
    if np.any(np.isnan(a) != np.isnan(b)):
        return None
    a, b = a[~nan], b[~nan]
    if a.size == 0:
        return 0.0
    scale = np.maximum(np.maximum(np.abs(a), np.abs(b)), np.max(np.abs(np.concatenate([a, b]))) * rtol + 1e-300)
    return float(np.max(np.abs(a - b) / scale))


def compare(da, db, rtol):
    import h5py
    worst, bad, counted = 0.0, [], 0
    for name, _, _ in cases():
        ja, jb = os.path.join(da, name + ".json"), os.path.join(db, name + ".json")
        if not (os.path.exists(ja) and os.path.exists(jb)):
            if os.path.exists(ja):
                bad.append(f"{name}: a JSON summary in the first set only")
            elif os.path.exists(jb):
                print(f"{name}: new in the second set, not compared")
            continue
        fa, fb = dict(flat(json.load(open(ja)))), dict(flat(json.load(open(jb))))
        if set(fa) - set(fb):
            bad.append(f"{name}.json: keys gone: {sorted(set(fa) - set(fb))}")
        if set(fb) - set(fa):
            print(f"{name}.json: new keys, not compared: {sorted(set(fb) - set(fa))}")
        for k in fa.keys() & fb.keys():
            a, b = fa[k], fb[k]
            d = differ(a if a is not None else np.nan, b if b is not None else np.nan, rtol)
            counted += 1
            if d is None or d > rtol:
                bad.append(f"{name}.json {k}: {a!r} against {b!r}")
            else:
                worst = max(worst, d)
        ha, hb = os.path.join(da, name + ".h5"), os.path.join(db, name + ".h5")
        if not os.path.exists(ha):
            continue
        with h5py.File(ha) as A, h5py.File(hb) as B:
            items, names = {}, set()
            A.visititems(lambda n, o: items.update({n: o}))  # visit stops at a callback's first non-None
            B.visit(lambda n: names.add(n))
            if set(items) != names:
                bad.append(f"{name}.h5: datasets differ: {sorted(set(items) ^ names)}")
            for n, o in items.items():
                if n not in B:
                    continue
                if isinstance(o, h5py.Dataset):
                    counted += 1
                    d = differ(o[...], B[n][...], rtol)
                    if d is None or d > rtol:
                        bad.append(f"{name}.h5 {n}: differs ({d})")
                    else:
                        worst = max(worst, d)
                for k, v in o.attrs.items():
                    if k in SKIP_H5:
                        continue
                    d = differ(v, B[n].attrs.get(k), rtol) if k in B[n].attrs else None
                    if d is None or d > rtol:
                        bad.append(f"{name}.h5 {n}@{k}: {v!r} against {B[n].attrs.get(k)!r}")
    print(f"{len(cases())} cases, {counted} JSON figures and HDF5 datasets; largest relative difference {worst:.2e}")
    for line in bad:
        print("DIFFERS:", line)
    return 1 if bad else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("dir")
    r.add_argument("--bin", default=os.path.join(ROOT, "bin", "contact"))
    c = sub.add_parser("compare")
    c.add_argument("a")
    c.add_argument("b")
    c.add_argument("--rtol", type=float, default=1e-12)
    args = ap.parse_args()
    if args.cmd == "run":
        run(args.dir, os.path.abspath(args.bin))
        return 0
    return compare(args.a, args.b, args.rtol)


if __name__ == "__main__":
    sys.exit(main())
