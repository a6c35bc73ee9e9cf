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
to 0.4 at 0.6)."""
import math

import numpy as np
import pytest

from conftest import figure, run_contact
from test_sphere3d import SCENE, axisymmetric_args
from test_sphere3d_fine import l2, profile
from test_whole3d import GRADED, RING, axisymmetric_profile

# Hertz: the r-z run meshed as the 3D quarter near the contact (ball: h =
# 0.009 within 0.11 growing to 0.2 at 0.6; flat: 0.025 within 0.2 growing to
# 0.4 at 0.6), with the 3D ring's ra, hr, wr (RING) or without
AXI_BALL = "R=1,tc=30,hfar=0.2,dp=0.11,dc=0.49"
AXI_FLAT = "W=1.5,H=1.5,rc=0.35,hfar=0.4,dp=0.2,dc=0.4"
AXI_RING = "ra=0.102,hr=0.003,wr=0.006,rr=0.6"


def axisymmetric_matched(tmp_path, ring, name):
    """The r-z run of the sphere3d sphere meshed as the graded 3D quarter
    (h = 0.009 at the contact), with the ring (ring: "ra=..,hr=..,wr=..,rr=..")
    or without (ring "")."""
    args = axisymmetric_args()
    for key, value in (("-ball_mesh_size", 0.009), ("-flat_mesh_size", 0.025),
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


def profile_against_axisymmetric(quarter, axi):
    """The 3D nodal profile's relative L2 distance (weights A_j) from the r-z
    run's (interpolated linearly in r), the share of its square in the band
    0.98 a < r < 1.02 a and the part from r < 0.9 a (relative to the whole
    reference), the mean difference over p0 of the faces' corner and midside
    nodes in 0.95 a < r < a, and the 3D's own distance from Hertz."""
    import h5py
    ref = axisymmetric_profile(axi)
    r, p, A, at = profile(quarter.output_path, "ball_cap")
    with h5py.File(quarter.output_path, "r") as f:
        cells = f["contact/ball/ball_cap/node_cells"][:]
    corner = np.zeros(len(r), bool)
    corner[np.unique(cells[:, :3])] = True
    a, pr = at["hertz_a"], ref(r)
    sq = A * (p - pr) ** 2
    band = (r > 0.98 * a) & (r < 1.02 * a)
    edge = (r >= 0.95 * a) & (r < a)
    d = (p - pr) / at["hertz_pmax"]
    return dict(l2=l2(p, A, pr), band=float(np.sum(sq[band]) / np.sum(sq)),
                inner=math.sqrt(np.sum(sq[r < 0.9 * a]) / np.sum(A * pr ** 2)),
                corner=float(np.mean(d[edge & corner])), mid=float(np.mean(d[edge & ~corner])),
                hertz=quarter.summary["contact"]["ball"]["pressure_l2_error"])


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
@pytest.mark.xfail(strict=True, reason="the 3D profile 0.75 % from the r-z run meshed alike (0.71 % from h = 0.002), "
                   "not the issue's 0.5 %: the nodes' reading of the edge band 0.98 a - 1.02 a")
def test_ring_matched_issue(ring_quarter):
    """The issue's bound, the profile within 0.5 % in L2 of the r-z run of
    the same sphere: not met with the ring (`profile_l2_matched` = 0.0075;
    0.0064 with faces of 0.006 inside and a ring of 0.002,
    docs/formulations.md)."""
    quarter, axi = ring_quarter
    assert figure("profile_l2_matched", profile_against_axisymmetric(quarter, axi)["l2"]) <= 0.005

