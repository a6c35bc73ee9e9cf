"""The substructured Newton step's work shared by the ranks in 3D
(src/solver/denselu.c, substructure.c): the capacitance matrix of the
contact zone factored by the ranks together (ScaLAPACK) gives the answers
of one rank and of every rank factoring it whole. The speed-up at 2e5 dofs:
bench/contact3d_ranks/RESULTS.md (scripts/bench_contact3d_ranks.py)."""
import pytest

from conftest import figure, info_args, info_text, run_contact
from test_contact3d import hertz_args


@pytest.mark.roundoff
def test_split_lu_agrees(tmp_path):
    """The quarter Hertz ball at h = 0.04 on 1 rank, on 2 ranks each
    factoring the capacitance matrix whole, and on 2 ranks sharing its
    factorisation (-newton_schur_split_lu 1: from any order; off by
    default): the pair's force and the peak pressure
    agree to what the stop guarantees (test_contact3d.py::test_ranks_agree's
    bound: each run's residual gradient moves a nodal force by at most
    that): `dF_whole` = 4.9e-14 and `dF_split` = 2.1e-14 of P, `dp_whole`
    = up to 4.2e-14 over the kernels and `dp_split` = 1.7e-14 relative; the same nodes are in
    contact, and the shared factorisation did run (its -info line)."""
    args = hertz_args(0.04)
    one = run_contact(args, tmp_path, name="one").summary
    whole = run_contact(args, tmp_path, ranks=2, name="whole").summary
    res = run_contact(args + ["-newton_schur_split_lu", "1"] + info_args(tmp_path, "split", "pc"), tmp_path, ranks=2, name="split")
    split = res.summary
    assert "capacitance matrix factored by the ranks together" in info_text(tmp_path, "split")
    c1 = one["contact"]["c"]
    n = c1["surfaces"][0]["nodes"]
    P = c1["P"]
    for name, other in (("whole", whole), ("split", split)):
        c2 = other["contact"]["c"]
        assert other["ranks"] == 2
        bound = 3 * n ** 0.5 * (one["gradient_norm"] + other["gradient_norm"]) + 1e-13 * P
        dF = max(abs(a - b) for a, b in zip(c1["force"], c2["force"]))
        figure(f"dF_{name}", dF / P)
        assert dF <= bound
        figure(f"dp_{name}", abs(c1["pmax"] - c2["pmax"]) / c1["pmax"])
        assert abs(c1["pmax"] - c2["pmax"]) <= bound / c1["contact_area"] * n
        assert c1["nodes_in_contact"] == c2["nodes_in_contact"]


def test_split_lu_refused(tmp_path):
    """-newton_schur_split_lu below 1: one line naming the option and the
    value, status 1."""
    res = run_contact(hertz_args(0.04) + ["-newton_schur_split_lu", "0"], tmp_path, check=False)
    errors = [l for l in res.stderr.splitlines() if l.startswith("contact: error:")]
    assert res.returncode == 1, res.stderr[-2000:]
    assert len(errors) == 1 and "-newton_schur_split_lu" in errors[0] and "0" in errors[0]
