"""Writes tests/data/half-mortar-h0.007.json, the reference profile of the
mirrored half of the reference scene with mortar at h = 0.007 (462,642 dofs),
solved to -tao_gttol 1e-12, which test_mortar, test_verification and
test_accuracy read instead of solving it in every `make test`
(conftest.half_mortar_reference). Run from the repository root:

    python3 tests/data/half_mortar_reference.py

The file records the command it was made with, the OpenBLAS kernel
(OPENBLAS_CORETYPE, "auto" where unset) and the summary's figures (P, the
energy, p_max, the half-width, dofs) beside the indenter's nodal profile
(s, p, w, gap) in full precision. test_mortar.py::test_reference_is_fresh
(`make stress`) solves it again and compares."""
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
sys.path.insert(0, str(ROOT / "tests"))

import profile_metrics as pm  # noqa: E402
from conftest import HALF_MORTAR_FINE, HALF_MORTAR_REF, half_mortar_args, run_contact  # noqa: E402


def dumps(out):
    """JSON, one line per entry and each profile array on one line (repr's 17
    digits: the floats exactly)."""
    head = json.dumps({k: v for k, v in out.items() if k != "indenter_contact"}, indent=1)
    arrays = ",\n".join(f"  {json.dumps(k)}: {json.dumps(v)}" for k, v in out["indenter_contact"].items())
    return head[:-2] + ',\n "indenter_contact": {\n' + arrays + "\n }\n}\n"


def main():
    args = half_mortar_args(HALF_MORTAR_FINE)
    with tempfile.TemporaryDirectory() as tmp:
        r = run_contact(args, tmp, name="ref", timeout=1800)
        s, (prof, _) = r.summary, pm.profiles(r.output_path)
    sp, p, w, g = (prof["indenter_contact"][i].tolist() for i in range(4))
    out = {"command": "python3 tests/data/half_mortar_reference.py",
           "args": [str(a) for a in args],
           "kernel": os.environ.get("OPENBLAS_CORETYPE", "auto"),
           "commit": subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                                    text=True).stdout.strip(),
           "summary": {k: s[k] for k in ("contact_force", "energy", "fem_pmax", "fem_a", "dofs", "gradient_norm")},
           "indenter_contact": {"s": sp, "pressure": p, "weight": w, "gap": g}}
    HALF_MORTAR_REF.write_text(dumps(out))
    print(f"{HALF_MORTAR_REF}: {len(sp)} samples, P {s['contact_force']!r}, dofs {s['dofs']}")


if __name__ == "__main__":
    main()
