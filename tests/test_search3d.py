"""The 3D pair's search across ranks (src/contact/mortar3d.c:
Mortar3dBuildTree, Mortar3dQuery): each rank builds its bounding-volume
tree over the master faces whose boxes meet the box of the slave faces it
searches from (widened by their sizes), the ranks' boxes exchanged and
each master face sent by the rank that gave it; the answers are the same
faces in the same order (increasing number) on any number of ranks.

The scene is split across the ranks: a flat patch, an upper box (Hex27,
12 x 12 cells of its unit square, one layer of height 0.25) pushed down on
a lower one (Hex27, 10 x 10, one layer of height 0.5), the upper's bottom
the slave (144 Quad9 faces), the lower's top the master (100)."""
import math
import re

from conftest import figure, info_args, info_text, run_contact
import test_contact3d as c3

UPPER, LOWER = "hex=1,n=12,m=1,z0=0.5,H=0.25", "hex=1,n=10,m=1,H=0.5"
HELD = re.compile(r"search held up to (\d+) of the (\d+) master faces")


def split_args():
    return (["-bodies", "lower,upper"] + c3.box("lower", LOWER, False) + c3.box("upper", UPPER, True)
            + ["-contact_pairs", "p", "-contact_p_surfaces", "upper:bottom,lower:top", "-output", "none"] + c3.SOLVE)


def test_master_share(tmp_path):
    """On 1, 2 and 3 ranks (-info: each rank's Mortar3dPostProcess line):
    one rank holds every master face; on 2 and 3 ranks no rank holds them
    all, `master_share` = 0.72 to 0.8 of the 100 at most on a rank (0.8
    on 2 ranks, 0.72 on 3: each rank's slave faces and the two layers of
    faces around them its Hessian and search need, widened by a face), and
    the shares cover the master (their sum at least the whole). The runs
    agree as test_contact3d_parallel.py::test_hessian_ranks asks: the
    pair's force within what the stops leave, 3 sqrt(n) times the sum of
    the two gradients' norms (`dF` = up to 9.4e-13 of P), the same nodes in
    contact; and the patch's pressure is the exact one (test_contact3d.py's
    uniaxial strain, H_l = 0.5, H_u = 0.25: `pressure_error` = up to 9.7e-11,
    bound 1e-8) on each."""
    runs = {}
    for n in (1, 2, 3):
        res = run_contact(split_args() + info_args(tmp_path, f"r{n}"), tmp_path, ranks=n, name=f"r{n}", timeout=1200)
        info = info_text(tmp_path, f"r{n}")
        held = [(int(a), int(b)) for a, b in HELD.findall(info)]
        assert len(held) == n, info[-2000:]
        nf = held[0][1]
        assert nf == 100
        if n == 1:
            assert held[0][0] == nf
        else:
            assert figure("master_share", max(h for h, _ in held) / nf) < 1
            assert sum(h for h, _ in held) >= nf
        runs[n] = res.summary
    c1 = runs[1]["contact"]["p"]
    P = math.sqrt(sum(f * f for f in c1["force"]))
    nslave = c1["surfaces"][0]["nodes"]
    for n, s in runs.items():
        c = s["contact"]["p"]
        assert s["ranks"] == n
        p = c3.D / (0.5 / c3.M + 0.25 / c3.M + 1.0 / c["penalty"])  # test_contact3d.py's D, the upper 0.25 high
        assert figure("pressure_error", max(abs(c["pmax"] / p - 1), abs(c["pmin"] / p - 1))) <= 1e-8
        if n == 1:
            continue
        bound = 3 * nslave ** 0.5 * (runs[1]["gradient_norm"] + s["gradient_norm"]) + 1e-13 * P
        dF = max(abs(a - b) for a, b in zip(c1["force"], c["force"]))
        figure("dF", dF / P)
        assert dF <= bound
        assert c["nodes_in_contact"] == c1["nodes_in_contact"] == nslave
