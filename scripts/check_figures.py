#!/usr/bin/env python3
"""Checks the figures the tests' docstrings quote against the figures the
tests recorded.

    python3 scripts/check_figures.py out/figures/*.jsonl     # exit 1 on a flag

A test records a figure it measured with conftest.figure(name, value), which
appends {"test", "name", "value", "kernel"} to the file CONTACT_FIGURES names
(make check-figures: the suite on this machine's kernel; make test-kernels:
the roundoff subset under each of five OpenBLAS kernels). A docstring quotes
it as `name` = VALUE, or `name` = LO to HI for a range (over the kernels, or
over a test's parametrised cases: a figure's name is local to its test
function, whose cases share the docstring). A quoted figure is flagged when a
recorded value lies outside [LO / 3, 3 HI] (absolute values; a range across
zero, -LO to HI, is [0, 3 max(LO, HI)], and so is `name` = up to HI, a
figure at round-off whose last bits vary from run to run, quoted by its
largest value; a figure (or a range's lower end) quoted below ROUNDOFF =
1e-9 is at round-off too, and its lower end is not checked: the last bits of a rank comparison vary
from run to run and from kernel to kernel, and a smaller one misstates
nothing; a quoted 0 takes no recorded value
above 1e-300), or when the test ran and recorded other
figures but not this one. Figures recorded and not quoted are listed, not
flagged. Only the standard library is used.
"""
import argparse
import ast
import json
import re
import sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
QUOTE = re.compile(r"`([A-Za-z_][\w.]*)`\s*=\s*(up to\s+)?(" + NUM + r")(?:\s+to\s+(" + NUM + r"))?")
FACTOR = 3.0
ROUNDOFF = 1e-9


def quoted(tests_dir):
    """{(file, function): {name: (lo, hi, text)}} from every docstring."""
    out = {}
    for path in sorted(Path(tests_dir).glob("test_*.py")):
        tree = ast.parse(path.read_text())
        funcs = []
        for node in tree.body:
            if isinstance(node, ast.FunctionDef) and node.name.startswith("test"):
                funcs.append((node.name, node))
            elif isinstance(node, ast.ClassDef) and node.name.startswith("Test"):
                funcs += [(f"{node.name}::{m.name}", m) for m in node.body
                          if isinstance(m, ast.FunctionDef) and m.name.startswith("test")]
        for name, node in funcs:
            doc = ast.get_docstring(node) or ""
            figs = {}
            for m in QUOTE.finditer(" ".join(doc.split())):
                lo, hi = float(m.group(3)), float(m.group(4) or m.group(3))
                # a signed range across zero (-4.9e-7 to 3.9e-7) spans every magnitude below its ends'
                lo, hi = (0.0, max(abs(lo), abs(hi))) if lo * hi < 0 or m.group(2) else sorted((abs(lo), abs(hi)))
                figs[m.group(1)] = (lo, hi, m.group(0))
            if figs:
                out[(path.name, name)] = figs
    return out


def recorded(paths):
    """{(file, function): {name: [(value, kernel)]}}"""
    out = defaultdict(lambda: defaultdict(list))
    for p in paths:
        for line in Path(p).read_text().splitlines():
            if not line.strip():
                continue
            r = json.loads(line)
            test = r["test"].split("[")[0]
            file, _, func = test.partition("::")
            out[(Path(file).name, func)][r["name"]].append((r["value"], r.get("kernel", "auto")))
    return out


def check(quotes, records):
    flags, unquoted = [], []
    for key, figs in sorted(quotes.items()):
        rec = records.get(key)
        if not rec:
            continue  # the test did not run in these records
        for name, (lo, hi, text) in sorted(figs.items()):
            vals = rec.get(name)
            if not vals:
                flags.append(f"{key[0]}::{key[1]}: {text}: not recorded (recorded: {', '.join(sorted(rec))})")
                continue
            low, high = (lo / FACTOR, hi * FACTOR) if hi > 0 else (0.0, 1e-300)
            if lo < ROUNDOFF:
                low = 0.0
            bad = [(v, k) for v, k in vals if not low <= abs(v) <= high]
            if bad:
                got = ", ".join(f"{v:.3g} ({k})" for v, k in bad[:6])
                flags.append(f"{key[0]}::{key[1]}: {text}: recorded {got}, outside a factor {FACTOR:g}")
    for key, rec in sorted(records.items()):
        for name in sorted(rec):
            if name not in quotes.get(key, {}):
                vals = [v for v, _ in rec[name]]
                unquoted.append(f"{key[0]}::{key[1]}: `{name}` = {min(vals, key=abs):.3g} to {max(vals, key=abs):.3g} (not quoted)")
    return flags, unquoted


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("records", nargs="+", help="files of recorded figures (JSON lines)")
    ap.add_argument("--tests", default=str(ROOT / "tests"))
    ap.add_argument("--quiet", action="store_true", help="do not list the figures recorded and not quoted")
    a = ap.parse_args()
    quotes, records = quoted(a.tests), recorded(a.records)
    flags, unquoted = check(quotes, records)
    n = sum(len(f) for k, f in quotes.items() if k in records)
    if not a.quiet:
        for u in unquoted:
            print(u)
    for f in flags:
        print("FLAG", f)
    print(f"check_figures: {n} quoted figures of tests that ran, {len(flags)} flagged, {len(unquoted)} recorded figures not quoted")
    return 1 if flags else 0


if __name__ == "__main__":
    sys.exit(main())
