"""3D Hertz at a/h >= 10, the whole ball, and what the radial profile's
distance from the axisymmetric run is. The sphere3d scene's sphere (R = 1,
E = 1000, nu = 0.3, on a block of E = 1e5, a/R = 0.10: test_sphere3d.py),
graded as tests/test_sphere3d_fine.py's quarter (h = 0.009 within 0.11 of
the contact point, a/h = 11.3, growing to 0.2 at 0.6), optionally with a
ring of size hr around the contact's edge (meshes/sphere3d/ball.geo's ra,
hr, wr: within wr of the circle r = ra, z = 0).

The profile is the slave's nodal pressures p_j = k_p <-g_j>_+ with weights
A_j (HDF5), as tests/test_sphere3d_fine.py reads it. Most of its L2
distance from Hertz, and from the r-z run, is the nodal pressures' reading
of the square-root edge, which the r-z run shares at the same h: its own
nodal profile is as far from Hertz at the 3D's h (test_axisymmetric_same_h),
and a ring of fine faces at the edge alone brings the 3D's down
(test_ring_against_axisymmetric). Comparing the nodal pressures with the
reference's consistent nodal averages int Nt_j p dS / int Nt_j dS over
the node's support (the same quantity: the pair's nodal force p_j A_j is
the reference's int Nt_j p dS, Nt_j face3d.c's basis) in place of its point
values p(r_j) does not remove it: the penalty's node whose support
straddles the edge has g_j > 0 and no pressure while its average is up to
0.04 p0 (31 such nodes in the graded quarter), and the nodes at 0.93 a to
0.99 a scatter by 0.02 p0 rms about either (inside, where the averages
lessen the nodes' scatter, it is 0.005 p0 rms at most)."""
import math

import numpy as np
import pytest

from conftest import figure, run_contact
from test_sphere3d import SCENE, axisymmetric_args, errors, whole_args
from test_sphere3d_fine import FINE, l2, profile

GRADED = "R=1,rc=0.11,hf=0.2,rf=0.6,zc=0.1"
# a ring of size 0.003 within 0.006 of r = 0.102 (a = 0.1019), growing to
# 0.2 at 0.6: 58,643 dofs in place of the graded quarter's 43,580
RING = ["-ball_geo_params", GRADED + ",ra=0.102,hr=0.003,wr=0.006", "-ball_mesh_size", 0.009]
# the whole ball's top and the block's bottom held in x, y and z; the
# quarter's with the same supports
HELD = ["-ball_bc_top_components", "x,y,z", "-ball_bc_top_values", "0,0,-0.01", "-block_bc_bottom_components", "x,y,z"]
ALPHA = 0.2  # face3d.c's FACE3D_TRI6_ALPHA


def axisymmetric(h, tmp_path):
    """The r-z run of the same sphere of size h near the contact."""
    args = axisymmetric_args()
    args[args.index("-ball_mesh_size") + 1] = h
    args[args.index("-flat_mesh_size") + 1] = h
    return run_contact(args, tmp_path, name=f"axi{h}")


def axisymmetric_profile(res):
    """The r-z run's nodal profile as a function of r: linear between its
    nodes, its first node's value towards the axis (whose corner has no
    weight and no pressure of its own), 0 past its last."""
    r, p, _, _ = profile(res.output_path, "ball_contact")
    order = np.argsort(r)
    return lambda x: np.interp(x, r[order], p[order], right=0.0)


def tri6_rule(n):
    """Points and weights on the unit triangle: n^2 sub-triangles, each with
    the 7-point degree-5 rule (Strang and Fix), so that a reference with a
    kink (Hertz's edge) is integrated to O(1/n^2)."""
    a1, b1, a2, b2 = 0.059715871789770, 0.470142064105115, 0.797426985353087, 0.101286507323456
    bary = [(1 / 3, 1 / 3, 1 / 3), (a1, b1, b1), (b1, a1, b1), (b1, b1, a1), (a2, b2, b2), (b2, a2, b2), (b2, b2, a2)]
    w = [0.225] + [0.132394152788506] * 3 + [0.125939180544827] * 3
    pts, wts, h = [], [], 1.0 / n
    for i in range(n):
        for j in range(n - i):
            tris = [((i * h, j * h), ((i + 1) * h, j * h), (i * h, (j + 1) * h))]
            if i + j < n - 1:
                tris.append((((i + 1) * h, j * h), ((i + 1) * h, (j + 1) * h), (i * h, (j + 1) * h)))
            for t in tris:
                for (l0, l1, l2_), wk in zip(bary, w):
                    pts.append((l0 * t[0][0] + l1 * t[1][0] + l2_ * t[2][0], l0 * t[0][1] + l1 * t[1][1] + l2_ * t[2][1]))
                    wts.append(wk * 0.5 * h * h)
    return np.array(pts), np.array(wts)


def tri6_basis(r, s):
    """Gmsh's Triangle6 shape functions and their r and s derivatives at (r, s)
    (numbers or arrays of points: the last axis the 6 nodes)."""
    l0 = 1 - r - s
    return (np.stack([l0 * (2 * l0 - 1), r * (2 * r - 1), s * (2 * s - 1), 4 * l0 * r, 4 * r * s, 4 * s * l0], -1),
            np.stack([1 - 4 * l0, 4 * r - 1, 0 * r, 4 * (l0 - r), 4 * s, -4 * s], -1),
            np.stack([1 - 4 * l0, 0 * r, 4 * s - 1, -4 * r, 4 * r, 4 * (l0 - s)], -1))


def nodal_averages(path, ref, n=6, dual=False):
    """A reference profile ref(r) read as the pair reads pressure: for each
    slave node int Nt_j ref dS / int Nt_j dS over the Tri6 faces of the
    cap (reference coordinates; Nt face3d.c's transformed basis, alpha =
    1/5), and the int Nt_j dS (= the program's A_j). A pressure field p
    gives the nodal forces int N_i p dS; the pair's are sum_j p_j int W_j
    N_i dS, and since the dual weights W_j are biorthogonal to Nt, T f =
    (p_j A_j) (Nt = T N): p_j A_j = int Nt_j p dS. With dual, int W_j ref
    dS / int W_j dS with the dual weights themselves (face3d.c: W = A Nt,
    A = D M^-1 face by face), how the pair averages the gap into g_j: the
    reference read as if it were -k_p g."""
    import h5py
    with h5py.File(path, "r") as f:
        g = f["contact/ball/ball_cap"]
        X, cells = g["node_X"][:], g["node_cells"][:]
    P, wq = tri6_rule(n)
    N, dr, ds = tri6_basis(P[:, 0], P[:, 1])
    Nt = np.stack([N[:, 0] + ALPHA * (N[:, 3] + N[:, 5]), N[:, 1] + ALPHA * (N[:, 3] + N[:, 4]),
                   N[:, 2] + ALPHA * (N[:, 4] + N[:, 5])] + [(1 - 2 * ALPHA) * N[:, k] for k in (3, 4, 5)], -1)
    A, Q = np.zeros(len(X)), np.zeros(len(X))
    for c in cells:
        x = X[c]
        xq = N @ x
        w = wq * np.linalg.norm(np.cross(dr @ x, ds @ x), axis=1)
        W = Nt
        if dual:
            W = Nt @ ((Nt.T @ w)[:, None] * np.linalg.inv(Nt.T @ (w[:, None] * Nt))).T
        A[c] += W.T @ w
        Q[c] += W.T @ (w * ref(np.hypot(xq[:, 0], xq[:, 1])))
    return Q / A, A


def hertz_profile(at):
    return lambda r: at["hertz_pmax"] * np.sqrt(np.clip(1 - (r / at["hertz_a"]) ** 2, 0, None))


def test_axisymmetric_same_h(tmp_path):
    """The r-z run's own nodal profile at the 3D quarter's h near the edge
    (its meridian's size as the 3D's faces: a/h = 10.2 and 11.3) is as far
    from Hertz as the 3D's (2.34 % and 1.53 %: docs/formulations.md): L2
    `l2_h010` = 0.0241 and `l2_h009` = 0.0121 (bounds 0.05, 0.03), 95 % of
    its square or more in 0.8 a < r < 1.2 a, how the last nodes in contact
    fall against the square-root edge; at h = 0.006 `l2_h006` = 0.0041
    (bound 0.01; irregular as the nodes fall: 0.0087 at 0.008, 0.0065 at
    0.004, 0.0033 at 0.003, 0.0026 from h = 0.002 on, where a/R = 0.1 and
    the finite block part it from Hertz's half-spaces). a and p_max
    meanwhile stay near Hertz's: `a_h010` = +0.0001, `a_h009` = +0.0012,
    `a_h006` = +0.0006 (bounds 0.004), `pmax_h010` = -0.0039, `pmax_h009`
    = -0.0041, `pmax_h006` = -0.0032 (bounds 0.01)."""
    out = {}
    for h, name, bound in ((0.01, "h010", 0.05), (0.009, "h009", 0.03), (0.006, "h006", 0.01)):
        res = axisymmetric(h, tmp_path)
        c = res.summary["contact"]["ball"]
        r, p, A, at = profile(res.output_path, "ball_contact")
        ph = hertz_profile(at)(r)
        err = l2(p, A, ph)
        assert err == pytest.approx(c["pressure_l2_error"], rel=1e-9)
        assert figure(f"l2_{name}", err) <= bound
        edge = (r > 0.8 * at["hertz_a"]) & (r < 1.2 * at["hertz_a"])
        out[name] = np.sum((A * (p - ph) ** 2)[edge]) / np.sum(A * (p - ph) ** 2)
        da, dp, _ = errors(c)
        assert abs(figure(f"a_{name}", da)) <= 0.004 and abs(figure(f"pmax_{name}", dp)) <= 0.01
    assert out["h010"] >= 0.9 and out["h009"] >= 0.9


@pytest.mark.stress
def test_ring_against_axisymmetric(tmp_path):
    """The graded quarter with a ring of faces of size 0.003 at the edge
    (a/hr = 34; 0.009 elsewhere within 0.11, 58,643 dofs) against the r-z
    run at h = 0.002 (172,064 dofs, its profile 0.26 % from Hertz's, as at
    h = 0.001): the profile's L2 distance `profile_l2_axi` = 0.0071
    (bound 0.015; not the 0.5 % asked) from the r-z nodal profile, falling
    with the ring's size (0.0137, 0.0097, 0.0085, 0.0071 at hr = 0.009,
    0.006, 0.0045, 0.003: as hr^0.6), the rest the faces of 0.009 inside
    (0.0043 from r < 0.9 a); from Hertz `profile_l2` = 0.0072 (bound
    0.015); P `dP` = +0.0008, a `da` = +0.0010, p_max `dpmax` = -0.0003
    from the r-z run's (bounds 0.003). Against the same reference read as
    the pair reads pressure (its consistent nodal averages int Nt_j p dS /
    A_j: nodal_averages, whose A_j are the program's to `A_check` =
    5.5e-13, bound 1e-9) the distance is `profile_l2_axi_avg` = 0.0073
    (bound 0.015): the nodes' reading of the reference is not what parts
    them."""
    axi = axisymmetric(0.002, tmp_path)
    quarter = run_contact(SCENE + RING, tmp_path, name="ring")
    ca, cq = axi.summary["contact"]["ball"], quarter.summary["contact"]["ball"]
    ref = axisymmetric_profile(axi)
    r, p, A, at = profile(quarter.output_path, "ball_cap")
    assert figure("profile_l2_axi", l2(p, A, ref(r))) <= 0.015
    assert figure("profile_l2", cq["pressure_l2_error"]) <= 0.015
    assert abs(figure("dP", cq["P"] / ca["P"] - 1)) <= 0.003
    assert abs(figure("da", cq["fem_a_moment"] / ca["fem_a_moment"] - 1)) <= 0.003
    assert abs(figure("dpmax", cq["fem_pmax"] / ca["fem_pmax"] - 1)) <= 0.003
    avg, Aj = nodal_averages(quarter.output_path, ref)
    assert figure("A_check", np.max(np.abs(Aj - A)) / np.max(A)) <= 1e-9
    assert figure("profile_l2_axi_avg", l2(p, A, avg)) <= 0.015


@pytest.mark.stress
def test_whole_ball_fine(tmp_path):
    """The whole ball (whole=1, no symmetry plane, its top and the block's
    bottom held in x, y and z) graded as the fine quarter (h = 0.009 within
    0.11, a/h = 11.3; 151,977 dofs, the direct step: 8 Newton iterations,
    284 s of CPU, 9.9 GB, 12 minutes on the shared machine) against Hertz:
    a from the second moment `a_moment_error` = +0.0014 and p_max
    `pmax_error` = -0.0028 (bounds 0.004 and 0.008, within the issue's
    0.01), the profile `profile_l2` = 0.0161 (bound 0.02, the issue's), the
    pair's force along z (its x and y part `lateral` = 5.9e-8 of P, bound
    1e-6: the mesh's asymmetry and the stop; 6.9e-7 at h = 0.025). Against
    the quarter of the same mesh and supports (tests/test_sphere3d_fine.py's
    FINE with the top and bottom held: P +1.8 % over the rollers'): P `dP`
    = +0.0003, a `da` = +0.0002, p_max `dpmax` = +0.0005 (bounds 0.001,
    0.001, 0.0015), the profile's L2 `dl2` = -0.0004 (bound 0.0015): the
    whole mesh and the quarter's four images read the same contact at
    this h, where at h = 0.025 p_max differed by 0.9 %
    (test_sphere3d.py::test_whole_ball)."""
    args = whole_args(0.025) + ["-ball_geo_params", GRADED + ",whole=1", "-ball_mesh_size", 0.009]
    c = run_contact(args, tmp_path, name="whole", timeout=3600).summary["contact"]["ball"]
    assert "model_share" not in c and c["P"] == pytest.approx(math.hypot(*c["force"]), rel=1e-12)
    assert figure("lateral", math.hypot(*c["force"][:2]) / c["P"]) <= 1e-6
    da, dp, _ = errors(c)
    assert abs(figure("a_moment_error", da)) <= 0.004
    assert abs(figure("pmax_error", dp)) <= 0.008
    assert figure("profile_l2", c["pressure_l2_error"]) <= 0.02
    q = run_contact(SCENE + FINE + HELD + ["-output", "none"], tmp_path, name="quarter").summary["contact"]["ball"]
    assert abs(figure("dP", c["P"] / q["P"] - 1)) <= 0.001
    assert abs(figure("da", c["fem_a_moment"] / q["fem_a_moment"] - 1)) <= 0.001
    assert abs(figure("dpmax", c["fem_pmax"] / q["fem_pmax"] - 1)) <= 0.0015
    assert abs(figure("dl2", c["pressure_l2_error"] - q["pressure_l2_error"])) <= 0.0015
