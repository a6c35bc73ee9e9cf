"""3D Hertz at a/h >= 10: the sphere3d scene's quarter ball (R = 1, E =
1000, nu = 0.3, on a block of E = 1e5, a/R = 0.10) with its contact graded
finely (the ball's cap of size h within rc of the contact point, growing to
hf at rf: meshes/sphere3d/ball.geo's parameters), against Hertz and against
the axisymmetric run of the same sphere (test_sphere3d.axisymmetric_args, h
= 0.004 near the contact, a/h = 25). The radial profile is read from the
HDF5 files: the slave's nodal pressures p_j and weights A_j at their
reference radii r_j, its relative L2 distance sqrt(sum A_j (p_j -
p(r_j))^2 / sum A_j p(r_j)^2) from Hertz's p0 sqrt(1 - r^2/a^2) under the
run's P (the report's pressure_l2_error) and from the r-z run's nodal
profile (interpolated linearly between its nodes, 0 past its last)."""
import math

import numpy as np
import pytest

from conftest import figure, run_contact
from test_sphere3d import SCENE, axisymmetric_args, errors

# The ball at h = 0.009 within 0.11 of the contact point (a = 0.102: a/h =
# 11.3), growing to 0.2 at 0.6; the block as the scene's (0.025 within 0.2):
# it is flat and 100 times stiffer, a finer block (0.01) moved P, a and p_max
# by 2e-4 at most and doubled the solve (measured at h = 0.01)
FINE = ["-ball_geo_params", "R=1,rc=0.11,hf=0.2,rf=0.6,zc=0.1", "-ball_mesh_size", 0.009]


def profile(path, group):
    """The slave's nodal profile: reference radius from the z axis,
    pressure, weight, and the pair's attributes."""
    import h5py
    with h5py.File(path, "r") as f:
        g = f[f"contact/ball/{group}"]
        X, p, A = g["node_X"][:], g["node_pressure"][:], g["node_weight"][:]
        attrs = dict(f["contact/ball"].attrs)
    r = np.hypot(X[:, 0], X[:, 1]) if X.shape[1] == 3 else X[:, 0]
    return r, p, A, attrs


def l2(p, A, ref):
    return math.sqrt(np.sum(A * (p - ref) ** 2) / np.sum(A * ref**2))


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fine3d")
    axi = run_contact(axisymmetric_args(), tmp, name="axi")
    quarter = run_contact(SCENE + FINE, tmp, name="quarter")
    return axi, quarter


def test_fine_quarter_against_hertz(runs):
    """The quarter at a/h = 11.3 (43,580 dofs) against Hertz under its
    whole P: a from the second moment `a_moment_error` = +0.0015 (bound
    0.005), p_max `pmax_error` = -0.0034 (bound 0.01: the issue's 1 %; the
    r-z run's own is -0.0030, a/R = 0.1 and a finite block), the radial
    profile's relative L2 distance from Hertz's `profile_l2` = 0.0153
    (bound 0.02, the issue's; 93 % of its square from 0.8 a < r < 1.2 a,
    the nodal sampling of the square-root edge: 0.0234 at h = 0.01, 0.0142
    at 0.008, growing to 0.2 by 3 rc; 0.050 at the scene's 0.025), a from the contact area
    `a_area_error` = +0.0095 (an upper estimate, bound 0.03). The profile
    read from the HDF5 gives the report's L2 to 1e-9."""
    _, quarter = runs
    c = quarter.summary["contact"]["ball"]
    da, dp, darea = errors(c)
    assert abs(figure("a_moment_error", da)) <= 0.005
    assert abs(figure("pmax_error", dp)) <= 0.01
    assert 0 < figure("a_area_error", darea) <= 0.03
    r, p, A, at = profile(quarter.output_path, "ball_cap")
    ph = at["hertz_pmax"] * np.sqrt(np.clip(1 - (r / at["hertz_a"]) ** 2, 0, None))
    err = l2(p, A, ph)
    assert err == pytest.approx(c["pressure_l2_error"], rel=1e-9)
    assert figure("profile_l2", err) <= 0.02


def test_fine_quarter_against_axisymmetric(runs):
    """The same quarter against the r-z run of the same sphere (a/h = 25,
    Hertz's to +0.0008 in a and -0.0030 in p_max): P `dP` = +0.0009, a from
    the second moment `da` = +0.0010, p_max `dpmax` = -0.0001 (bounds
    0.003, within the issue's 0.5 %; with the ball's size growing to 0.2 by
    0.33 in place of 0.6 the coarser ball was stiffer, P +0.0038 and a
    +0.0017), and the radial profile's L2 distance from the r-z run's
    `profile_l2_axi` = 0.0141 (bound 0.02: not the 0.5 % of a and p_max;
    as against Hertz, 97 % of its square lies in 0.8 a < r < 1.2 a, the
    square-root edge sampled by nodes 0.009 apart, falling with h: 0.020 at
    h = 0.01, 0.011 at 0.008)."""
    axi, quarter = runs
    ca, cq = axi.summary["contact"]["ball"], quarter.summary["contact"]["ball"]
    assert abs(figure("dP", cq["P"] / ca["P"] - 1)) <= 0.003
    assert abs(figure("da", cq["fem_a_moment"] / ca["fem_a_moment"] - 1)) <= 0.003
    assert abs(figure("dpmax", cq["fem_pmax"] / ca["fem_pmax"] - 1)) <= 0.003
    ra, pa, _, _ = profile(axi.output_path, "ball_contact")
    order = np.argsort(ra)
    r, p, A, _ = profile(quarter.output_path, "ball_cap")
    assert figure("profile_l2_axi", l2(p, A, np.interp(r, ra[order], pa[order], right=0.0))) <= 0.02
