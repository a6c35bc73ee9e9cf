"""Corrupted Gmsh files must stop bin/contact with one line `contact: error: ...`
(or be read and solved): a small fixed set of tests/fuzz_msh.py's cases. A
reader that crashes, hangs, prints a PETSc trace, or reads garbage as a mesh
fails it."""
from conftest import BIN

import fuzz_msh

# Mutations that leave no valid mesh whatever the random choices: an empty or
# header-only file, random bytes, a section marker removed or mangled. Each
# must be rejected, not read (a lenient reader that skips what it does not
# know would accept them).
MUST_REJECT = ("empty", "binary_junk", "remove_marker", "mangle_marker")


def test_fuzz_mesh_files(tmp_path):
    """40 cases, seed 1: no failure (fuzz_msh.classify), every case of the
    MUST_REJECT kinds rejected, and each of those kinds drawn (measured 3, 4,
    1 and 2 cases). The per-case timeout of 20 s is a guard against a hang,
    not a speed bound (the slowest case measured 0.51 s)."""
    res = fuzz_msh.run_fuzz(cases=40, seed=1, jobs=2, bin_path=BIN, out_dir=tmp_path / "failures")
    lines = []
    fuzz_msh.report(res, 1, 2, log=lines.append)
    print("\n".join(lines))
    print(f"slowest case {max(c.seconds for c in res.cases):.2f} s")
    assert len(res.cases) == 40
    assert not res.failures, "\n".join(lines)
    for kind in MUST_REJECT:
        cases = [c for c in res.cases if c.kind == kind]
        assert cases, f"no {kind} case drawn: the check would be vacuous"
        assert all(c.verdict == "rejected" for c in cases), [(c.desc, c.verdict) for c in cases if c.verdict != "rejected"]
