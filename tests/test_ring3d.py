"""A ring of fine faces over the contact's edge, where the mesh's resolution
of the edge is what is left of issue 49's bound on the Hertz profile against
the axisymmetric run (docs/formulations.md, "Hertz in 3D"; the same ring on
tests/test_mindlin3d.py's half balls, halfball.geo's ra, hr, wr, gr, is not
tested yet: its run did not finish, "Friction between 3D bodies").

Hertz: the sphere3d quarter graded with tests/test_whole3d.py's ring (hr =
0.003 within 0.006 of r = 0.102, a = 0.102, 0.009 elsewhere within 0.11)
against the r-z run of the same sphere meshed alike (meshes/sphere/ball.geo
given the same ring ra, hr, wr in its meridian, h = 0.009 within 0.11
growing to 0.2 at 0.6, the flat as the 3D block: 0.025 within 0.2 growing
to 0.4 at 0.6).

What parts the two profiles is the 3D faces' midside nodes just inside the
edge, above the r-z run where the corners are not (test_ring_matched). It
is the 3D solution's nodal values, not how a node reads a smooth field: the
r-z profile read over each 3D node's own support reads lower, not higher,
at the midside nodes (test_ring_supports); a midside node beside an open
corner reads a penetration where its own point is apart
(test_ring_midside_gaps). Finer narrow rings (hr 0.002, 0.0015, wr = 2 hr,
and faces of 0.006 inside) bring the profile to 0.63 to 0.71 % of the r-z
run meshed alike, the midside nodes' excess at the edge staying
(test_ring_finer); a ring of 0.0015 four times as wide (0.96 a to 1.04 a)
with faces of 0.006 inside meets the 0.5 % asked: 0.43 % (test_ring_wide)."""
import math

import numpy as np
import pytest

from conftest import figure, run_contact
from test_sphere3d import SCENE, axisymmetric_args
from test_sphere3d_fine import l2, profile
from test_whole3d import ALPHA, GRADED, RING, axisymmetric, axisymmetric_profile, hertz_profile, nodal_averages, tri6_basis

# Hertz: the r-z run meshed as the 3D quarter near the contact (ball: h =
# 0.009 within 0.11 growing to 0.2 at 0.6; flat: 0.025 within 0.2 growing to
# 0.4 at 0.6), with the 3D ring's ra, hr, wr (RING) or without
AXI_BALL = "R=1,tc=30,hfar=0.2,dp=0.11,dc=0.49"
AXI_FLAT = "W=1.5,H=1.5,rc=0.35,hfar=0.4,dp=0.2,dc=0.4"
AXI_RING = "ra=0.102,hr=0.003,wr=0.006,rr=0.6"


def axisymmetric_matched(tmp_path, ring, name, h=0.009):
    """The r-z run of the sphere3d sphere meshed as the graded 3D quarter
    (h = 0.009 at the contact unless given), with the ring (ring:
    "ra=..,hr=..,wr=..,rr=..") or without (ring "")."""
    args = axisymmetric_args()
    for key, value in (("-ball_mesh_size", h), ("-flat_mesh_size", 0.025),
                       ("-ball_geo_params", AXI_BALL + ("," + ring if ring else "")), ("-flat_geo_params", AXI_FLAT)):
        args[args.index(key) + 1] = value
    return run_contact(args, tmp_path, name=name)


def test_axisymmetric_ring(tmp_path):
    """The r-z run meshed as the graded 3D quarter (h = 0.009 at the
    contact, a/h = 11.3) against Hertz: without a ring its nodal profile is
    `l2_plain` = 0.0151 from Hertz in L2 (bound 0.03), with the 3D quarter's
    ring (hr = 0.003 within 0.006 of the point r = 0.102, z = 0 in the
    meridian) `l2_ring` = 0.0045 (bound 0.009): the ring does for the r-z
    run what it does for the 3D one (0.72 %: test_ring_matched). a and
    p_max stay: `a_ring` = +0.0007 (bound 0.002), `pmax_ring` = -0.0040
    (bound 0.008), Hertz's half-spaces against a/R = 0.1 and a finite block."""
    plain = axisymmetric_matched(tmp_path, "", "plain").summary["contact"]["ball"]
    ring = axisymmetric_matched(tmp_path, AXI_RING, "ring").summary["contact"]["ball"]
    assert figure("l2_plain", plain["pressure_l2_error"]) <= 0.03
    assert figure("l2_ring", ring["pressure_l2_error"]) <= 0.009
    assert abs(figure("a_ring", ring["fem_a_moment"] / ring["hertz_a"] - 1)) <= 0.002
    assert abs(figure("pmax_ring", ring["fem_pmax"] / ring["hertz_pmax"] - 1)) <= 0.008


@pytest.fixture(scope="module")
def ring_quarter(tmp_path_factory):
    """The graded 3D quarter with test_whole3d.py's ring (58,643 dofs, 2 min
    at a load of 3) and the r-z run meshed alike."""
    d = tmp_path_factory.mktemp("ring3d_hertz")
    return (run_contact(SCENE + RING, d, name="quarter", timeout=3600),
            axisymmetric_matched(d, AXI_RING, "axi"))


def node_classes(quarter):
    """The cap's corner nodes (True) and midside nodes (False) of its Tri6
    faces."""
    import h5py
    with h5py.File(quarter.output_path, "r") as f:
        cells = f["contact/ball/ball_cap/node_cells"][:]
    corner = np.zeros(cells.max() + 1, bool)
    corner[np.unique(cells[:, :3])] = True
    return corner


def profile_against_axisymmetric(quarter, axi, ref=None):
    """The 3D nodal profile's relative L2 distance (weights A_j) from the r-z
    run's (interpolated linearly in r; or from ref(r)), the share of its
    square in the band 0.98 a < r < 1.02 a and the part from r < 0.9 a
    (relative to the whole reference), the mean difference over p0 of the
    faces' corner and midside nodes in 0.95 a < r < a, and the 3D's own
    distance from Hertz."""
    ref = ref or axisymmetric_profile(axi)
    r, p, A, at = profile(quarter.output_path, "ball_cap")
    corner = node_classes(quarter)
    a, pr = at["hertz_a"], ref(r)
    sq = A * (p - pr) ** 2
    band = (r > 0.98 * a) & (r < 1.02 * a)
    edge = (r >= 0.95 * a) & (r < a)
    d = (p - pr) / at["hertz_pmax"]
    return dict(l2=l2(p, A, pr), band=float(np.sum(sq[band]) / np.sum(sq)),
                inner=math.sqrt(np.sum(sq[r < 0.9 * a]) / np.sum(A * pr ** 2)),
                corner=float(np.mean(d[edge & corner])), mid=float(np.mean(d[edge & ~corner])),
                hertz=quarter.summary["contact"]["ball"]["pressure_l2_error"])


def support_readings(quarter, ref, dual=False):
    """The reference ref(r) read over each 3D node's own support (its Nt_j,
    or with dual its W_j: test_whole3d.nodal_averages; the cap projected on
    z = 0, nearly flat at a/R = 0.1) in place of its value at r_j: the 3D
    nodal profile's L2 distance from that reading, the mean differences
    over p0 of the corner and midside nodes in 0.95 a < r < a from it, and
    what the reading itself moves there (the reading minus ref(r_j), over
    p0), midside and corner."""
    r, p, A, at = profile(quarter.output_path, "ball_cap")
    corner = node_classes(quarter)
    avg, _ = nodal_averages(quarter.output_path, ref, dual=dual)
    edge = (r >= 0.95 * at["hertz_a"]) & (r < at["hertz_a"])
    d, e = (p - avg) / at["hertz_pmax"], (avg - ref(r)) / at["hertz_pmax"]
    return dict(l2=l2(p, A, avg), mid=float(np.mean(d[edge & ~corner])), corner=float(np.mean(d[edge & corner])),
                read_mid=float(np.mean(e[edge & ~corner])), read_corner=float(np.mean(e[edge & corner])))


def interior_split(quarter):
    """The mean over p0 of the midside nodes' difference from Hertz read
    over their supports (Nt_j) less the corner nodes', over r < 0.7 a: the
    faces' split where the profile is smooth."""
    r, p, A, at = profile(quarter.output_path, "ball_cap")
    corner = node_classes(quarter)
    avg, _ = nodal_averages(quarter.output_path, hertz_profile(at))
    d, inside = (p - avg) / at["hertz_pmax"], r < 0.7 * at["hertz_a"]
    return float(np.mean(d[inside & ~corner]) - np.mean(d[inside & corner]))


@pytest.mark.stress
def test_ring_matched(ring_quarter):
    """The 3D quarter with the ring against the r-z run meshed alike (the
    same ring in its meridian, h = 0.009 at the contact): the profile's L2
    distance `profile_l2_matched` = 0.0075 (bound 0.015), as far as from
    the r-z run at h = 0.002 (0.0071: test_whole3d.py's
    test_ring_against_axisymmetric): meshing the r-z run alike does not
    bring the two closer. `band_share` = 0.46 of its square lies in 0.98 a
    < r < 1.02 a; from r < 0.9 a alone `inner` = 0.0044 (bound 0.009), the
    3D nodes' scatter where the faces grow from the ring's 0.003 to 0.009.
    It is the faces' midside nodes: in 0.95 a < r < a they lie `mid` =
    +0.0075 p0 above the r-z run on average (bound 0.02), the corner nodes
    `corner` = +0.0009 (bound 0.003). From Hertz the 3D profile is
    `profile_l2` = 0.0072 (bound 0.015); the r-z run's 0.0045
    (test_axisymmetric_ring)."""
    quarter, axi = ring_quarter
    f = profile_against_axisymmetric(quarter, axi)
    figure("band_share", f["band"])
    assert abs(figure("corner", f["corner"])) <= 0.003
    assert 0 < figure("mid", f["mid"]) <= 0.02
    assert figure("profile_l2_matched", f["l2"]) <= 0.015
    assert figure("inner", f["inner"]) <= 0.009
    assert figure("profile_l2", f["hertz"]) <= 0.015


@pytest.mark.stress
def test_ring_supports(ring_quarter):
    """Why the midside nodes read high at the edge (issue 49, 4): the 3D
    discrete solution (its midside nodes' weighted gaps:
    test_ring_midside_gaps), not a node's reading of a smooth field. The
    r-z run's profile
    read over each 3D node's own support as the pair reads a pressure
    field, int Nt_j p dS / A_j (the consistent reading: the nodal forces of
    p are int N_i p dS, and p_j A_j = int Nt_j p dS for the pair's; the
    same discrete space for both runs), reads lower than its point values
    where the profile is concave, at the midside nodes in 0.95 a < r < a by
    `read_mid` = -0.0013 p0 (bound: below 0, above -0.004) and at the
    corners by `read_corner` = -0.0009 p0 (the same bounds): a midside
    support does not lift the reading. Against it the 3D midside nodes lie
    `mid` = +0.0088 p0 above (bound 0.004 to 0.02, the nodal reading's
    +0.0075: test_ring_matched), the corners `corner` = +0.0018 (bound
    0.005), and the profile's L2 distance is `profile_l2_supports` = 0.0077
    (bound 0.015), beside the nodal 0.0075 (not in its place). Read with the
    dual weights W_j, as the pair averages the gap into g_j (the reference
    as if it were -k_p g), the reading rises at the midside nodes by
    `read_mid_dual` = +0.0033 p0 (bound 0 to 0.007) and at the corners by
    `read_corner_dual` = +0.0011 (bound 0 to 0.003), and the 3D midside
    nodes lie `mid_dual` = +0.0043 p0 above it (bound 0.002 to 0.01): less
    than half of the excess, with the profile farther, `profile_l2_dual` =
    0.0080 (bound 0.016). What is left is the 3D solution's nodal values:
    inside, where the profile is smooth (r < 0.7 a), the midside nodes lie
    `split` = +0.0017 p0 above the corners against Hertz read over their
    supports (bound 0 to 0.004), a split that halves with faces of 0.006
    (test_ring_finer: as h^2) and grows as 1/alpha with face3d.c's
    FACE3D_TRI6_ALPHA (a corner's p_c is its nodal force over A_c = 2 alpha
    A/3 plus its edges' average: 0.0010, 0.0019, 0.0007 at r < 0.3 a for
    alpha 0.2, 0.1, 0.3, builds of the program with the constant changed;
    the nodal profile 0.0075, 0.0087, 0.0080 from the r-z run: alpha = 1/5
    is the best of the three)."""
    quarter, axi = ring_quarter
    ref = axisymmetric_profile(axi)
    nt, w = support_readings(quarter, ref), support_readings(quarter, ref, dual=True)
    assert -0.004 <= figure("read_mid", nt["read_mid"]) < 0
    assert -0.004 <= figure("read_corner", nt["read_corner"]) < 0
    assert 0.004 <= figure("mid", nt["mid"]) <= 0.02
    assert abs(figure("corner", nt["corner"])) <= 0.005
    assert figure("profile_l2_supports", nt["l2"]) <= 0.015
    assert 0 < figure("read_mid_dual", w["read_mid"]) <= 0.007
    assert 0 < figure("read_corner_dual", w["read_corner"]) <= 0.003
    assert 0.002 <= figure("mid_dual", w["mid"]) <= 0.01
    assert figure("profile_l2_dual", w["l2"]) <= 0.016
    assert 0 < figure("split", interior_split(quarter)) <= 0.004


# Tet10's edges (topology order: 4 corners, then the mid-edge nodes of 01,
# 12, 02, 03, 13, 23), for the block's top faces
TET10_EDGE = {(0, 1): 4, (1, 2): 5, (0, 2): 6, (0, 3): 7, (1, 3): 8, (2, 3): 9}


def point_gaps(quarter):
    """Each cap node's own gap: its current position's distance along the
    block's normal from the block's top, the curved Tri6 face under it
    (the block's Tet10 faces on z = 0 at the current coordinates, found by
    Newton on the face's map in x and y), with the cap's faces, the
    program's weighted gaps g_j (node_gap) and pressures."""
    import h5py
    with h5py.File(quarter.output_path, "r") as f:
        g, b = f["contact/ball/ball_cap"], f["bodies/block"]
        xs, gw, p, cells = g["node_x"][:], g["node_gap"][:], g["node_pressure"][:], g["node_cells"][:]
        X, x, T = b["geometry"][:], b["geometry"][:] + b["displacement"][:], b["topology"][:]
    faces = []
    for t in T:
        top = [i for i in range(4) if abs(X[t[i], 2]) < 1e-12]
        if len(top) == 3:
            i, j, k = top
            faces.append([t[i], t[j], t[k], t[TET10_EDGE[(i, j)]], t[TET10_EDGE[(j, k)]], t[TET10_EDGE[(i, k)]]])
    faces = np.array(faces)
    centre = X[faces[:, :3]].mean(1)[:, :2]

    gp = np.full(len(xs), np.nan)
    for n, q in enumerate(xs):
        for fi in np.argsort(np.sum((centre - q[:2]) ** 2, 1))[:6]:
            xm, xi = x[faces[fi]], np.array([1 / 3, 1 / 3])
            for _ in range(30):
                N, dr, ds = tri6_basis(*xi)
                xi = xi - np.linalg.solve(np.stack([dr @ xm[:, :2], ds @ xm[:, :2]], 1), N @ xm[:, :2] - q[:2])
            if xi.min() >= -1e-9 and xi.sum() <= 1 + 1e-9:
                N, dr, ds = tri6_basis(*xi)
                nrm = np.cross(dr @ xm, ds @ xm)
                gp[n] = (q - N @ xm) @ nrm / (np.linalg.norm(nrm) * np.sign(nrm[2]))
                break
    return gp, gw, p, cells


def rz_point_gaps(axi):
    """The r-z run's slave nodes' own gaps to the flat's top (its quadratic
    segments at the current coordinates; the axis node, which has no
    weight, is not written, so the first segment is extended to the axis),
    with the program's pressures."""
    import h5py
    with h5py.File(axi.output_path, "r") as f:
        s, m = f["contact/ball/ball_contact"], f["contact/ball/flat_contact"]
        xs, p, xm, Xm = s["node_x"][:], s["node_pressure"][:], m["node_x"][:], m["node_X"][:]

    def triples(k0):  # segments whose middle node halves them (the reference flat)
        return [k for k in range(k0, len(Xm) - 2, 2) if abs(Xm[k + 1, 0] - (Xm[k, 0] + Xm[k + 2, 0]) / 2) < 1e-9]
    seg = max(triples(0), triples(1), key=len)
    assert len(seg) == (len(Xm) - 1 - seg[0]) // 2
    gp = np.full(len(xs), np.nan)
    for n, q in enumerate(xs):
        k = next((k for k in seg if q[0] <= xm[k + 2, 0]), seg[-1])
        xi = 0.0
        for _ in range(30):
            N, dN = np.array([xi * (xi - 1) / 2, 1 - xi * xi, xi * (xi + 1) / 2]), np.array([xi - 0.5, -2 * xi, xi + 0.5])
            xi -= (N @ xm[k:k + 3, 0] - q[0]) / (dN @ xm[k:k + 3, 0])
        gp[n] = q[1] - np.array([xi * (xi - 1) / 2, 1 - xi * xi, xi * (xi + 1) / 2]) @ xm[k:k + 3, 1]
    return gp, p


@pytest.mark.stress
def test_ring_midside_gaps(ring_quarter):
    """What in the program lets a midside node near the edge carry more
    (issue 49, 4): its weighted gap. On a flat master the gap is the face's
    quadratic of the nodes' own gaps, and with the dual weights W_j
    biorthogonal to Nt = T N (face3d.c) int W_j N_i dS = (T^-1)_ij A_j:
    a corner's g_j is its own gap, a midside node's (g_e - alpha (g_a +
    g_b)) / (1 - 2 alpha), a and b the corners of its edge (alpha = 1/5:
    g_e + (g_e - (g_a + g_b)/2) / 1.5). Measured against the nodes' own
    gaps to the block's curved top: over the active midside nodes whose
    edge ends at an inactive corner (`open_mids` = 72, all of them lie in
    0.987 a to 1.004 a) the program's g_j is the combination to
    `stencil_error` = 0.075 of the deepest penetration (bound 0.2: the
    block's faces of 0.025 kink under the cap's of 0.003), where their
    own gaps are positive, from `open_gap_min` = 0.71 to `open_gap_max` =
    59 times the deepest penetration (bounds above 0, below 200): the
    open corner's gap, weighted by -alpha / (1 - 2 alpha), makes a midside
    node whose own point is apart read a penetration and carry pressure. No
    corner does (`open_corners` = 0 active corners with a positive own gap),
    nor any node of the r-z run meshed alike, whose weights are the P2
    basis itself (mortar.c): its active nodes' own gaps are at most
    `rz_gap_max` = -0.12 of its deepest penetration (bound below 0).
    In 0.95 a < r < a those midside nodes lie `open_mid` = +0.0146 p0 above
    the r-z run (bound 0.005 to 0.03), the other active midside nodes
    there `other_mid` = +0.0061 (bound 0 to 0.015): about a third of the
    midside nodes' excess (+0.0075 p0: test_ring_matched) is the
    stencil's reach past the edge. Not a defect to mend: the gap weighted
    by Nt itself in place of W (a build with the dual coefficients set to
    the identity) puts the profile 3.8 % from the r-z run (the pressures'
    split 0.017 p0 inside), and alpha = 0.1 and 0.3 0.87 % and 0.80 %
    (test_ring_supports): the dual weights and alpha = 1/5 are the best
    measured."""
    quarter, axi = ring_quarter
    gp, gw, p, cells = point_gaps(quarter)
    r, _, _, at = profile(quarter.output_path, "ball_cap")
    pen = quarter.summary["contact"]["ball"]["max_penetration"]
    corner = node_classes(quarter)
    ends = {}
    for c in cells:
        for e, (i, j) in zip(c[3:], ((0, 1), (1, 2), (0, 2))):
            ends[e] = (c[i], c[j])
    act = p > 0
    mids = np.array([e for e in ends if act[e] and not (act[ends[e][0]] and act[ends[e][1]])])
    comb = np.array([(gp[e] - ALPHA * (gp[ends[e][0]] + gp[ends[e][1]])) / (1 - 2 * ALPHA) for e in mids])
    assert figure("open_mids", len(mids)) >= 20
    assert figure("stencil_error", np.max(np.abs(gw[mids] - comb)) / pen) <= 0.2
    assert 0 < figure("open_gap_min", np.min(gp[mids]) / pen) and figure("open_gap_max", np.max(gp[mids]) / pen) <= 200
    assert figure("open_corners", np.sum(act & corner & (gp > 0))) == 0
    gz, pz = rz_point_gaps(axi)
    assert figure("rz_gap_max", np.max(gz[pz > 0]) / axi.summary["contact"]["ball"]["max_penetration"]) < 0
    d = (p - axisymmetric_profile(axi)(r)) / at["hertz_pmax"]
    edge = (r >= 0.95 * at["hertz_a"]) & (r < at["hertz_a"])
    opened = np.zeros(len(r), bool)
    opened[mids] = True
    assert 0.005 <= figure("open_mid", np.mean(d[edge & opened])) <= 0.03
    assert 0 < figure("other_mid", np.mean(d[edge & ~corner & act & ~opened])) <= 0.015


@pytest.mark.stress
@pytest.mark.xfail(strict=True, reason="the 3D profile 0.75 % from the r-z run meshed alike (0.71 % from h = 0.002), "
                   "not the issue's 0.5 %: the midside nodes' excess in the edge band 0.98 a - 1.02 a "
                   "(test_ring_midside_gaps; a wide ring meets it: test_ring_wide)")
def test_ring_matched_issue(ring_quarter):
    """The issue's bound, the profile within 0.5 % in L2 of the r-z run of
    the same sphere: not met with the ring (`profile_l2_matched` = 0.0075;
    nor with finer narrow rings, test_ring_finer; met with a wide ring of
    0.0015 and faces of 0.006 inside, test_ring_wide)."""
    quarter, axi = ring_quarter
    assert figure("profile_l2_matched", profile_against_axisymmetric(quarter, axi)["l2"]) <= 0.005


# Finer rings (hr, wr = 2 hr) on the graded quarter (h inside), each against
# the r-z run meshed alike; CG + GAMG steps (-newton_iterative 1: the same
# minimiser, at hr 0.0015 the direct step's profile figures to 1e-6 and P to
# 1e-11; 1.1 to 1.5 GB where the direct step took 4.1 GB at hr 0.002 and
# 5.0 GB at 0.0015)
FINER = (("hr002", 0.002, 0.009), ("hr0015", 0.0015, 0.009), ("hr0015_h006", 0.0015, 0.006))


@pytest.fixture(scope="module")
def finer_rings(tmp_path_factory):
    d = tmp_path_factory.mktemp("ring3d_finer")
    runs = {}
    for name, hr, h in FINER:
        ring = f"ra=0.102,hr={hr},wr={2 * hr:g}"
        args = ["-ball_geo_params", GRADED + "," + ring, "-ball_mesh_size", h, "-newton_iterative", 1]
        runs[name] = (run_contact(SCENE + args, d, name=name, timeout=3600),
                      axisymmetric_matched(d, ring + ",rr=0.6", "axi_" + name, h=h))
    return runs


@pytest.mark.stress
def test_ring_finer(finer_rings):
    """Finer rings at the edge (issue 49, 4), each against the r-z run
    meshed alike (the same h, hr, wr in its meridian): with h = 0.009
    inside, a ring of 0.002 (`dofs_hr002` = 62919; 8 Newton iterations,
    86 s and 4.1 GB with the direct step on the shared machine, 1.1 GB
    with CG + GAMG) gives the
    profile `l2_hr002` = 0.0071 from the r-z run (bound 0.014), a ring of
    0.0015 (`dofs_hr0015` = 65594; 87 s, 1.1 GB with CG + GAMG)
    `l2_hr0015` = 0.0063 (bound 0.013): from 0.0075 at 0.003
    (test_ring_matched), not 0.5 %, for the faces of 0.009 inside hold
    `inner_hr002` = 0.0046 and `inner_hr0015` = 0.0042 of it from r < 0.9
    a alone (bounds 0.009). With faces of 0.006 inside as well and the
    ring of 0.0015 (`dofs_hr0015_h006` = 110883; 9 iterations, 177 s, 1.5
    GB with CG + GAMG) the part inside falls, `inner_hr0015_h006` = 0.0030
    (bound 0.006), but the band 0.98 a < r < 1.02 a holds `band_hr0015_h006`
    = 0.60 of the square, and the profile lies `l2_hr0015_h006` = 0.0068
    from the r-z run meshed alike (bound 0.014; 0.0065 from the r-z run at
    h = 0.002). The midside nodes in 0.95 a < r < a lie above it at every
    ring, `mid_hr002` = +0.0028, `mid_hr0015` = +0.0055, `mid_hr0015_h006`
    = +0.0057 p0 (bounds 0 to 0.02), the corners `corner_hr002` = -0.0042,
    `corner_hr0015` = +0.0004, `corner_hr0015_h006` = -0.0005 (bounds
    0.01): the edge's excess does not fall with hr, where the interior's
    split (test_ring_supports) does with h (the edge's excess falls with
    a wider ring: test_ring_wide): `split_h009` = +0.0017 at h =
    0.009 (the ring of 0.0015), `split_h006` = +0.0009 at 0.006 (bounds 0
    to 0.004; their ratio `split_ratio` = 0.48, bound 0.7, (0.006/0.009)^2
    = 0.44)."""
    f = {name: profile_against_axisymmetric(*finer_rings[name]) for name, _, _ in FINER}
    for name, _, _ in FINER:
        figure(f"dofs_{name}", finer_rings[name][0].summary["dofs"])
        assert figure(f"l2_{name}", f[name]["l2"]) <= (0.013 if name == "hr0015" else 0.014)
        assert figure(f"inner_{name}", f[name]["inner"]) <= (0.006 if name.endswith("h006") else 0.009)
        assert 0 < figure(f"mid_{name}", f[name]["mid"]) <= 0.02
        assert abs(figure(f"corner_{name}", f[name]["corner"])) <= 0.01
    figure("band_hr0015_h006", f["hr0015_h006"]["band"])
    s9, s6 = interior_split(finer_rings["hr0015"][0]), interior_split(finer_rings["hr0015_h006"][0])
    assert 0 < figure("split_h009", s9) <= 0.004 and 0 < figure("split_h006", s6) <= 0.004
    assert figure("split_ratio", s6 / s9) <= 0.7


@pytest.mark.stress
@pytest.mark.xfail(strict=True, reason="finer narrow rings bring the 3D profile to 0.63 to 0.71 % of the r-z run meshed "
                   "alike, not the issue's 0.5 %: the midside nodes' excess at the edge does not fall with the ring's hr "
                   "(a wide ring meets it: test_ring_wide)")
def test_ring_finer_issue(finer_rings):
    """The issue's 0.5 % with the finest narrow ring: not met (`l2_hr0015`
    = 0.0063, test_ring_finer; met with a wide ring: test_ring_wide)."""
    assert figure("l2_hr0015", profile_against_axisymmetric(*finer_rings["hr0015"])["l2"]) <= 0.005


# The ring of 0.0015 four times as wide (wr = 0.006: 0.96 a to 1.04 a) with
# faces of 0.006 inside, CG + GAMG steps
WIDE = ["-ball_geo_params", GRADED + ",ra=0.102,hr=0.0015,wr=0.006", "-ball_mesh_size", 0.006, "-newton_iterative", 1]


@pytest.fixture(scope="module")
def wide_ring(tmp_path_factory):
    """The graded quarter with the wide ring, the r-z run meshed alike, and
    the r-z runs at h = 0.001 and 0.002."""
    d = tmp_path_factory.mktemp("ring3d_wide")
    return (run_contact(SCENE + WIDE, d, name="wide", timeout=3600),
            axisymmetric_matched(d, "ra=0.102,hr=0.0015,wr=0.006,rr=0.6", "axi_wide", h=0.006),
            axisymmetric(0.001, d), axisymmetric(0.002, d))


@pytest.mark.stress
def test_ring_wide(wide_ring):
    """The issue's 0.5 % (issue 49, 4), met with a wide ring: faces of
    0.0015 within 0.006 of r = a (0.96 a to 1.04 a, where the narrow rings
    of test_ring_finer reach 0.98 a to 1.02 a) and of 0.006 inside
    (`dofs` = 139918; 10 Newton iterations, 247 s and 2.1 GB with CG +
    GAMG on the shared machine). The profile lies `l2_matched` = 0.0043
    from the r-z run meshed alike (bound 0.005, the issue's) and `l2_h001`
    = 0.0042 from the r-z run at h = 0.001 (bound 0.005), `profile_l2` =
    0.0046 from Hertz (bound 0.01); the band 0.98 a < r < 1.02 a holds
    `band` = 0.35 of its square (0.60 with the narrow ring), the part from
    r < 0.9 a is `inner` = 0.0030 (bound 0.006), and the midside nodes in
    0.95 a < r < a lie `mid` = +0.0011 p0 above the r-z run (bound 0 to
    0.005; +0.0057 with the narrow ring), the corners `corner` = -0.0025
    (bound 0.006). The narrow ring's transition to the coarser faces lay
    just inside the edge. Against the r-z run at h = 0.002 the profile is
    `l2_h002` = 0.0055 (bound 0.011: not within 0.5 %), as that run's own
    nodal profile lies `axi_h002_h001` = 0.0028 from the r-z run's at h =
    0.001 (bound 0.006; the r-z run meshed alike `axi_matched_h001` =
    0.0014, bound 0.003): at 0.5 % the r-z reference's own nodes matter.
    (The wide ring with faces of 0.009 inside, 96,234 dofs and 17 Newton
    iterations, lay 0.56 % from its r-z run meshed alike, 0.44 % of it
    from r < 0.9 a; a wide ring of 0.002 with faces of 0.006 inside,
    120,159 dofs, 0.60 % from its r-z run meshed alike and 0.49 % from
    the r-z run at h = 0.001.)"""
    quarter, axi, axi001, axi002 = wide_ring
    figure("dofs", quarter.summary["dofs"])
    f = profile_against_axisymmetric(quarter, axi)
    assert figure("l2_matched", f["l2"]) <= 0.005
    assert figure("l2_h001", profile_against_axisymmetric(quarter, axi001)["l2"]) <= 0.005
    assert figure("profile_l2", f["hertz"]) <= 0.01
    figure("band", f["band"])
    assert figure("inner", f["inner"]) <= 0.006
    assert 0 < figure("mid", f["mid"]) <= 0.005
    assert abs(figure("corner", f["corner"])) <= 0.006
    assert figure("l2_h002", profile_against_axisymmetric(quarter, axi002)["l2"]) <= 0.011
    ref = axisymmetric_profile(axi001)
    for name, res, bound in (("axi_h002_h001", axi002, 0.006), ("axi_matched_h001", axi, 0.003)):
        r, p, A, _ = profile(res.output_path, "ball_contact")
        assert figure(name, l2(p, A, ref(r))) <= bound
