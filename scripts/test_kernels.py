#!/usr/bin/env python3
"""make test-kernels: the tests whose figures depend on round-off (the
`roundoff` mark: rank comparisons, load paths, Taylor remainders, force
balance, the L-BFGS tests, kernel comparisons) run under each of OpenBLAS's
kernels that this machine kind may meet (OPENBLAS_CORETYPE), since another
CPU rounds otherwise; prints a table of each test's verdict under each
kernel, and the range of every figure the tests recorded (conftest.figure)
over the kernels, and checks the docstrings' quoted figures against them
(scripts/check_figures.py).

    python3 scripts/test_kernels.py [--kernels Prescott,Nehalem,...] [--out out/test-kernels] [-n 3]

Exit 1 if a test fails under any kernel or a quoted figure is flagged.
Writes, under --out, each kernel's JUnit XML and recorded figures (JSON
lines) and table.md.
"""
import argparse
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
KERNELS = ["Prescott", "Nehalem", "Sandybridge", "Haswell", "SkylakeX"]


def run_kernel(kernel, out, jobs, select):
    xml = out / f"junit-{kernel}.xml"
    figs = out / f"figures-{kernel}.jsonl"
    figs.unlink(missing_ok=True)
    env = dict(os.environ, OPENBLAS_CORETYPE=kernel, CONTACT_FIGURES=str(figs))
    cmd = [sys.executable, "-m", "pytest", "-q", "-m", select, f"--junitxml={xml}", "-p", "no:cacheprovider"]
    cmd += ["-n", str(jobs), "--dist", "loadgroup"] if jobs > 0 else ["-p", "no:xdist"]
    cmd.append("tests")
    print(f"test-kernels: {kernel}: {' '.join(cmd[1:])}", flush=True)
    proc = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True)
    tail = proc.stdout.strip().splitlines()[-1:] if proc.stdout.strip() else ["(no output)"]
    print(f"test-kernels: {kernel}: {tail[0]}", flush=True)
    verdicts = {}
    if xml.exists():
        for tc in ET.parse(xml).getroot().iter("testcase"):
            name = f"{tc.get('classname', '').replace('.', '/').removeprefix('tests/')}::{tc.get('name')}"
            v = "pass"
            if tc.find("failure") is not None or tc.find("error") is not None:
                v = "FAIL"
            elif tc.find("skipped") is not None:
                v = "skip"
            verdicts[name] = v
    return verdicts, proc.returncode


def figure_ranges(out, kernels):
    import json
    rng = defaultdict(dict)
    for k in kernels:
        f = out / f"figures-{k}.jsonl"
        if not f.exists():
            continue
        for line in f.read_text().splitlines():
            if line.strip():
                r = json.loads(line)
                key = (r["test"].split("[")[0], r["name"])
                lo, hi = rng[key].get(k, (abs(r["value"]), abs(r["value"])))
                rng[key][k] = (min(lo, abs(r["value"])), max(hi, abs(r["value"])))
    return rng


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--kernels", default=",".join(KERNELS))
    ap.add_argument("--out", default=str(ROOT / "out" / "test-kernels"))
    ap.add_argument("-n", type=int, default=3, help="pytest-xdist workers (0: serially)")
    ap.add_argument("-m", default="roundoff and not stress", help="the tests selected (a pytest mark expression)")
    a = ap.parse_args()
    kernels = [k for k in a.kernels.split(",") if k]
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    table, codes = {}, {}
    for k in kernels:
        table[k], codes[k] = run_kernel(k, out, a.n, a.m)
    tests = sorted({t for v in table.values() for t in v})
    lines = ["| test | " + " | ".join(kernels) + " |", "|---|" + "---|" * len(kernels)]
    for t in tests:
        lines.append(f"| {t} | " + " | ".join(table[k].get(t, "-") for k in kernels) + " |")
    rng = figure_ranges(out, kernels)
    flines = ["| test | figure | " + " | ".join(kernels) + " | all |", "|---|---|" + "---|" * (len(kernels) + 1)]
    for (test, name), per in sorted(rng.items()):
        cells = [f"{per[k][0]:.2g}-{per[k][1]:.2g}" if k in per else "-" for k in kernels]
        lo, hi = min(v[0] for v in per.values()), max(v[1] for v in per.values())
        flines.append(f"| {test.split('::', 1)[-1]} | {name} | " + " | ".join(cells) + f" | {lo:.2g} to {hi:.2g} |")
    text = "\n".join(lines) + "\n\nFigures recorded, |value| range per kernel:\n\n" + "\n".join(flines) + "\n"
    (out / "table.md").write_text(text)
    print(text)
    failed = [(t, k) for t in tests for k in kernels if table[k].get(t) == "FAIL"]
    bad_exit = [k for k in kernels if codes[k] not in (0, 5) and not any(kk == k for _, kk in failed)]
    figs = [str(out / f"figures-{k}.jsonl") for k in kernels if (out / f"figures-{k}.jsonl").exists()]
    chk = subprocess.run([sys.executable, str(ROOT / "scripts" / "check_figures.py"), "--quiet"] + figs,
                         cwd=ROOT, capture_output=True, text=True) if figs else None
    if chk:
        print(chk.stdout, end="")
    print(f"test-kernels: {len(tests)} tests under {len(kernels)} kernels, {len(failed)} failures"
          + (f", pytest exited abnormally under {', '.join(bad_exit)}" if bad_exit else ""))
    return 1 if failed or bad_exit or (chk and chk.returncode) else 0


if __name__ == "__main__":
    sys.exit(main())
