"""The regression harness: every tests/cases/*.toml is a case (scene, options,
expected figures with tolerances and where each expected value comes from).
Adding a case needs no code. Case keys:

  description     what the case shows
  options_file    the scene
  args            extra options
  ranks           list of rank counts; each [[expect]] is checked at each
  [[expect]]      key (dotted, in the JSON summary) or dataset (in the HDF5),
                  value, rtol and/or atol, reduce (max, min, maxabs) for lists,
                  source (why the value is right, and the measured figure the
                  tolerance guards: 2-3 times it, or for a round-off figure
                  a multiple of EPS times its scale, measured over several
                  OpenBLAS kernels (OPENBLAS_CORETYPE); -s prints each error)
  [compare_ranks] keys that must agree between the rank counts, rtol
  [convergence]   option, values: one run per value of the option, and
  [[convergence.rate]] key, min_rate, source: the observed order of key
                  between successive values must be at least min_rate
"""
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from conftest import lookup, run_contact

CASES = sorted((Path(__file__).parent / "cases").glob("*.toml"))


def load(path):
    with open(path, "rb") as f:
        case = tomllib.load(f)
    for e in case.get("expect", []) + case.get("convergence", {}).get("rate", []):
        assert "source" in e, f"{path.name}: every expectation names its source"
    return case


def check_value(label, got, e):
    want = e["value"]
    rtol, atol = e.get("rtol", 0.0), e.get("atol", 0.0)
    got = np.asarray(got, dtype=float)
    if "reduce" in e:
        got = {"max": np.max, "min": np.min, "maxabs": lambda a: np.max(np.abs(a))}[e["reduce"]](got)
    err = np.abs(got - np.asarray(want, dtype=float))
    bound = atol + rtol * np.abs(np.asarray(want, dtype=float))
    print(f"{label}: max error {np.max(err):.3e}, bound {np.max(bound):.3e}")
    assert np.all(err <= bound), (f"{label}: got {got if np.size(got) < 8 else '...'} want {want} "
                                  f"(max error {np.max(err):.3e} > tolerance; source: {e['source']})")


# rank comparisons and Taylor remainders depend on round-off: make test-kernels runs them under each kernel
ROUNDOFF = ("ranks_", "taylor_")


@pytest.mark.parametrize("path", [pytest.param(p, marks=pytest.mark.roundoff) if p.stem.startswith(ROUNDOFF) else p
                                  for p in CASES], ids=[p.stem for p in CASES])
def test_case(path, tmp_path):
    case = load(path)
    base = ["-options_file", case["options_file"]] + [str(a) for a in case.get("args", [])]
    results = {}
    if "convergence" in case:
        conv, h = case["convergence"], case["convergence"]["values"]
        runs = [run_contact(base + [conv["option"], str(v)], tmp_path, name=f"c{v}").summary for v in h]
        failed = []
        for rate in conv["rate"]:
            errs = [lookup(s, rate["key"]) for s in runs]
            orders = [math.log(errs[i] / errs[i + 1]) / math.log(h[i] / h[i + 1]) for i in range(len(h) - 1)]
            print(f"{rate['key']}: {errs}, observed orders {orders}")
            if min(orders) < rate["min_rate"]:
                failed.append(f"{rate['key']}: observed orders {orders} < {rate['min_rate']} ({rate['source']})")
        assert not failed, "\n".join(failed)
        return
    for n in case.get("ranks", [1]):
        r = run_contact(base, tmp_path, ranks=n, name=f"np{n}")
        results[n] = r
        for e in case.get("expect", []):
            if "key" in e:
                check_value(f"{e['key']} at {n} ranks", lookup(r.summary, e["key"]), e)
            else:
                with r.h5() as f:
                    check_value(f"{e['dataset']} at {n} ranks", f[e["dataset"]][...], e)
    if "compare_ranks" in case:
        cmp = case["compare_ranks"]
        ref = results[min(results)]
        for n, r in results.items():
            if r is ref:
                continue
            for key in cmp["keys"]:
                a, b = lookup(ref.summary, key), lookup(r.summary, key)
                print(f"{key}: {abs(a - b) / max(abs(a), abs(b), 1e-300):.1e} between {min(results)} and {n} ranks")
                assert abs(a - b) <= cmp["rtol"] * max(abs(a), abs(b)), f"{key}: {a} at {min(results)} ranks, {b} at {n}"
