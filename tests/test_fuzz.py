"""Corrupted Gmsh files must stop bin/contact with one line `contact: error: ...`
(or be read and solved): a small fixed set of tests/fuzz_msh.py's cases."""
from conftest import BIN

import fuzz_msh


def test_fuzz_mesh_files(tmp_path):
    res = fuzz_msh.run_fuzz(cases=40, seed=1, jobs=2, bin_path=BIN, out_dir=tmp_path / "failures")
    lines = []
    fuzz_msh.report(res, 1, 2, log=lines.append)
    print("\n".join(lines))
    assert len(res.cases) == 40
    assert sum(c.verdict == "rejected" for c in res.cases) >= 20, "most corrupted files should be rejected"
    assert not res.failures, "\n".join(lines)
