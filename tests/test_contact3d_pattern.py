"""The 3D contact Hessian's preallocated pattern (src/contact/mortar3d.c,
Mortar3dGetPattern; src/solver/problem.c): a 3D mortar pair gives the
columns its Hessian can touch, and the stiffness and the Hessian reserve
those in place of a dense block over both surfaces' dofs. An entry outside
the pattern (a pair that slides farther than -contact_mortar_pattern_margin
face sizes) makes the Hessian grow there, with the same results.

The scene: test_contact3d.py's patch test, Tet10 (h = 0.3) on Hex27, the
stop pinned at a gradient of 1e-10."""
import pytest

from conftest import figure, info_args, info_text, run_contact
from test_contact3d import SOLVE, UPPERS, patch_args

GROWN = "a contact term left its pattern, H grows"


def patch(tmp_path, name, extra=(), ranks=1):
    """The run, its -info lines (every rank's) as .info."""
    args = patch_args(UPPERS["tet10-on-hex27"], SOLVE + info_args(tmp_path, name) + list(extra))
    res = run_contact(args, tmp_path, name=name, ranks=ranks)
    res.info = info_text(tmp_path, name)
    return res


@pytest.mark.roundoff
@pytest.mark.parametrize("ranks", [1, 2])
def test_outside_pattern(ranks, tmp_path):
    """With -contact_mortar_pattern_margin -10 the pattern holds no master
    face (only the slave nodes' couplings): every slave-master entry of the
    Hessian lands outside it, the Hessian grows (its -info line says so), and
    the run ends as with the default margin, whose pattern holds every entry
    (no such line): the pair's force and nodal pressures agree to
    `force_diff` = 0.0 and `pressure_diff` = 0.0 relative on 1 and 2 ranks
    (the same Hessian's values in a larger pattern; bound 1e-9, what the
    stop's gradient 1e-10 leaves on pressures of order 0.3 is 3e-10)."""
    ref = patch(tmp_path, "ref", ranks=ranks)
    grown = patch(tmp_path, "grown", ["-contact_mortar_pattern_margin", "-10"], ranks=ranks)
    assert GROWN not in ref.info
    assert GROWN in grown.info
    a, b = ref.summary["contact"]["p"], grown.summary["contact"]["p"]
    P = abs(a["force"][2])
    assert figure("force_diff", max(abs(x - y) for x, y in zip(a["force"], b["force"])) / P) <= 1e-9
    assert figure("pressure_diff", max(abs(a[k] - b[k]) for k in ("pmax", "pmin")) / a["pmax"]) <= 1e-9
    assert a["nodes_in_contact"] == b["nodes_in_contact"]
