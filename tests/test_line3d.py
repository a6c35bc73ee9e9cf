"""A cylinder on a block in plane strain, in 3D on curved Quad9 faces: against
Hertz's line contact and against the 2D program on the same cross-section.

The scene (our own): the lower half of a cylinder R = 1 (its axis along z,
tests/meshes/contact3d/cylinder.geo) pressed by 0.02 onto a block [-2, 2] x
[-2, 0] (slab.geo), both E 1000, nu 0.3, their cross-sections meshed in
quadrilaterals (h at the contact) and extruded along z by Ly = 0.05, the
cylinder in one layer of Hex27 and the block in two (non-matching across
and along the axis), z on rollers at z = 0 and Ly: plane strain, the
contact surfaces the cylinder's curved Quad9 faces (the slave) and the
block's top. The cylinder's top is moved, the block's bottom held (x and y).

Hertz's line contact (Johnson, Contact Mechanics 4.3): under a load P' per
unit length, b = sqrt(4 P' R / (pi E*)), p(x) = p0 sqrt(1 - x^2/b^2), p0 = 2
P' / (pi b), E* = E / (2 (1 - nu^2)); b is read from the nodal pressures'
second moment (sum p A x^2 / sum p A = b^2 / 4 for Hertz's profile), P' is
the pair's force over Ly. The same cross-section's mesh run by the 2D
program (dim2=1: the same Quad9 mesh in the plane, plane strain) is an
independent path through the contact (mortar.c, friction.c against
mortar3d.c, segment3d.c, friction3d.c) to the same discrete problem: the
field is exactly constant along z in the extruded Hex27, and the weighted
gaps of a column of nodes along z are the 2D node's, so the two agree up
to the two segment quadratures' difference (the 3D one on the cylinder's
curved faces, split into flat pieces). Both take -contact_penalty 3e7 (the
automatic one reads different sizes in 2D and 3D)."""
import math

import h5py
import numpy as np
import pytest

import hertz
from conftest import figure, run_contact

E, NU, R, LY, MU = 1000.0, 0.3, 1.0, 0.05, 0.3
ESTAR = hertz.plane_strain_modulus(E, NU, E, NU)
G3 = "tests/meshes/contact3d"
SLAVE = "contact/c/cyl_cap"
STAGES = "0,-0.02,0.002,-0.02,0.005,-0.02,0.009,-0.02"   # the top's (x, y): pressed, then moved along x in 3 stages


def scene_args(h, dim2=False, top="0,-0.02", extra=()):
    """The cylinder on the block at contact mesh size h, in 3D (extruded) or on
    the 2D cross-section (dim2)."""
    args = ["-bodies", "cyl,blk", "-contact_pairs", "c", "-contact_c_surfaces", "cyl:cap,blk:top",
            "-contact_penalty", "3e7"]
    for b, geo, held in (("cyl", "cylinder.geo", "top"), ("blk", "slab.geo", "bottom")):
        args += [f"-{b}_geo", f"{G3}/{geo}", f"-{b}_mesh_size", h, f"-{b}_E", E, f"-{b}_nu", NU,
                 f"-{b}_bc", held if dim2 else f"{held},front,back", f"-{b}_bc_{held}_components", "x,y"]
        if dim2:
            args += [f"-{b}_geo_params", "dim2=1"]
        else:
            args += [f"-{b}_bc_front_components", "z", f"-{b}_bc_back_components", "z"]
    args += ["-cyl_bc_top_values", top]
    return [str(a) for a in args] + list(extra)


def friction_args(h, dim2=False):
    return scene_args(h, dim2, STAGES, ["-contact_c_friction", str(MU), "-load_stages", "4", "-load_steps", "1",
                                        "-contact_friction_lag_rtol", "1e-6"])


def run(tmp_path_factory, name, args):
    return run_contact(args, tmp_path_factory.mktemp(name), timeout=1200)


@pytest.fixture(scope="module")
def pressed(tmp_path_factory):
    """h 0.02: 3D and 2D; h 0.01: 3D."""
    return {"3d": run(tmp_path_factory, "line3d", scene_args(0.02)),
            "2d": run(tmp_path_factory, "line2d", scene_args(0.02, True)),
            "3d_fine": run(tmp_path_factory, "line3d_fine", scene_args(0.01))}


@pytest.fixture(scope="module")
def sheared(tmp_path_factory):
    return {"3d": run(tmp_path_factory, "line3d_mu", friction_args(0.02)),
            "2d": run(tmp_path_factory, "line2d_mu", friction_args(0.02, True))}


def slave(res, stage=None):
    """The slave's reference coordinates, pressure, weight (and with stage,
    that stage's shear and stick) from the HDF5 file."""
    with h5py.File(res.output_path, "r") as f:
        g = f[SLAVE]
        out = dict(X=g["node_X"][:], p=g["node_pressure"][:], A=g["node_weight"][:])
        if stage is not None:
            s = f[f"stages/{stage}/{SLAVE}"] if f"stages/{stage}/{SLAVE}" in f else g
            out.update(shear=s["node_shear"][:], stick=s["node_stick"][:])
    return out


def moment_half_width(s):
    """The slave nodes' x about the pressure's centroid and the half-width b
    from the second moment, sum p A x^2 / sum p A = b^2 / 4 for Hertz's line
    contact profile."""
    x = s["X"][:, 0] - np.sum(s["p"] * s["A"] * s["X"][:, 0]) / np.sum(s["p"] * s["A"])
    return x, math.sqrt(4 * np.sum(s["p"] * s["A"] * x ** 2) / np.sum(s["p"] * s["A"]))


def line_figures(res, length):
    """p_max/p0 - 1, b/b_Hertz - 1 (second moment), the profile's relative L2
    against Hertz's (weights A_j), from the pair's force over length."""
    s = slave(res)
    c = res.summary["contact"]["c"]
    b, p0 = hertz.line(abs(c["force"][1]) / length, ESTAR, R)
    x, bm = moment_half_width(s)
    ph = p0 * np.sqrt(np.clip(1 - x ** 2 / b ** 2, 0, None))
    return dict(p=s["p"].max() / p0 - 1, b=bm / b - 1,
                l2=math.sqrt(np.sum(s["A"] * (s["p"] - ph) ** 2) / np.sum(s["A"] * ph ** 2)))


def columns(X3, X2):
    """For each 2D node, the 3D slave nodes over it (same x, y; every z)."""
    return [np.flatnonzero(np.hypot(X3[:, 0] - x[0], X3[:, 1] - x[1]) <= 1e-12) for x in X2]


@pytest.mark.roundoff
@pytest.mark.parametrize("run_name,h", [("3d", 0.02), ("3d_fine", 0.01)])
def test_line_hertz(pressed, run_name, h):
    """The 3D cylinder against Hertz's line contact at b/h 5.5 (h 0.02) and
    11 (h 0.01): `p_max_error` = 0.0027 to 0.0042 (+0.0042 at h 0.02,
    +0.0027 at 0.01), `b_error` = -0.0038 to -0.0025, `l2` = 0.0064 to 0.0158
    (0.0158 at h 0.01: the nodes nearest the edge, at 0.986 b, carry 3.4 where
    Hertz's profile gives 5.0 on its steep end; the same under the five BLAS
    kernels); bounds a sphere's (the issue's 1 % for p_max and a, 2 % in L2)."""
    f = line_figures(pressed[run_name], LY)
    assert abs(figure("p_max_error", f["p"])) <= 0.01
    assert abs(figure("b_error", f["b"])) <= 0.01
    assert figure("l2", f["l2"]) <= 0.02


@pytest.mark.roundoff
def test_line_as_2d(pressed):
    """The 3D run against the 2D program's on the same cross-section (h
    0.02): the pair's force per unit length `dP` = 2.3e-9 of P' (bound 1e-7),
    each slave node's pressure `dp` = 2.6e-8 of p_max from the 2D node's
    (bound 1e-6), and along z, over each column of 3D nodes, `dp_z` =
    3.0e-8 of p_max (bound 1e-7: plane strain; the block's border nodes, at
    the ends, are projected on the slave along its sub-triangles' normals
    and the others along their mean normals, segment3d.c, so the end
    columns' pieces are not the middle's and their quadratures of the gap's
    bends differ by about what 3D's and 2D's do, dp; 1.0e-10 while all were
    projected alike); the same to 2 digits under the five BLAS kernels."""
    r3, r2 = pressed["3d"], pressed["2d"]
    P3 = abs(r3.summary["contact"]["c"]["force"][1]) / LY
    P2 = abs(r2.summary["contact"]["c"]["force"][1])
    s3, s2 = slave(r3), slave(r2)
    cols = columns(s3["X"], s2["X"])
    assert all(len(c) == 3 for c in cols) and sum(len(c) for c in cols) == len(s3["X"])
    pmax = s2["p"].max()
    dp = max(np.max(np.abs(s3["p"][c] - p)) for c, p in zip(cols, s2["p"])) / pmax
    dpz = max(np.ptp(s3["p"][c]) for c in cols) / pmax
    assert figure("dP", abs(P3 - P2) / P2) <= 1e-7
    assert figure("dp", dp) <= 1e-6
    assert figure("dp_z", dpz) <= 1e-7


@pytest.mark.roundoff
def test_line_friction_as_2d(sheared):
    """With friction (mu 0.3; pressed, then the top moved along x by 0.002,
    0.005, 0.009: Q/(mu P') 0.21, 0.51, 0.88), 3D against 2D on the same
    cross-section at each stage's end: Q `dQ` = 3.0e-6 of Q at most (bound
    3e-5), the shear along the surface `dshear` = up to 2.8e-4 of its peak
    (bound 1e-3; 1.8e-5 in the normal stage; the same at a lag tolerance of
    1e-10: not the fixed point's stop but the two formulations' slip
    measures, 2D's along the master's tangent, 3D's in the closing plane's
    basis turned between accepted states), the same nodes stuck (`stick_differ`
    = 0), the shear along z `shear_z` = 7.3e-8 of the peak at most (bound 2e-7:
    the end columns' pieces, as dp_z in test_line_as_2d; 4.8e-9 before),
    and Coulomb exact where a 3D node slips at the end (`slip_error` =
    1.9e-16, bound 1e-12). Not Cattaneo's: c/b 3.98 %, -0.19 %, -4.3 % from
    sqrt(1 - Q/(mu P')), because the cylinder on the block is not Mindlin's
    similar pair (the normal stage locks in 0.18 mu p0; 0.30 at h 0.01:
    the 3D Cattaneo-Mindlin check takes mirrored half balls, test_mindlin3d.py)."""
    r3, r2 = sheared["3d"], sheared["2d"]
    st3, st2 = r3.summary["load_stages"], r2.summary["load_stages"]
    assert len(st3) == len(st2) == 4
    s3, s2 = slave(r3), slave(r2)
    cols = columns(s3["X"], s2["X"])
    first = [c[0] for c in cols]
    worst = dict(dQ=0.0, dshear=0.0, shear_z=0.0, stick_differ=0)
    for k in range(1, 5):
        Q3, Q2 = abs(st3[k - 1]["reactions"]["cyl:top"][0]) / LY, abs(st2[k - 1]["reactions"]["cyl:top"][0])
        if k > 1:
            worst["dQ"] = max(worst["dQ"], abs(Q3 - Q2) / Q2)
        a3, a2 = slave(r3, k), slave(r2, k)
        t3 = a3["shear"][first]
        along = -np.sign(t3[:, 0]) * np.hypot(t3[:, 0], t3[:, 1])   # 2D's sign: along the slave's tangent, -x here
        peak = np.abs(a2["shear"]).max()
        worst["dshear"] = max(worst["dshear"], np.max(np.abs(along - a2["shear"])) / peak)
        worst["shear_z"] = max(worst["shear_z"], np.abs(a3["shear"][:, 2]).max() / peak)
        worst["stick_differ"] = max(worst["stick_differ"], int(np.sum((a3["stick"][first] > 0.5) != (a2["stick"] > 0.5))))
    end = slave(r3, 4)
    t = np.linalg.norm(end["shear"], axis=1)
    slipping = (end["p"] > 0) & (end["stick"] < 0.5)
    assert slipping.sum() >= 10
    assert figure("dQ", worst["dQ"]) <= 3e-5
    assert figure("dshear", worst["dshear"]) <= 1e-3
    assert figure("stick_differ", worst["stick_differ"]) == 0
    assert figure("shear_z", worst["shear_z"]) <= 2e-7
    assert figure("slip_error", np.max(np.abs(t[slipping] - MU * end["p"][slipping])) / (MU * end["p"].max())) <= 1e-12


def test_line_report(pressed):
    """The report of the 3D cylinder names the zone's half-axes, a strip not
    a disc (report3d.c): along x 2/sqrt(5) of the larger is the second
    moment's half-width b as this file computes it from the HDF5 file (to
    1e-9), along (1, 0, 0) to 1e-6."""
    r = pressed["3d"]
    c = r.summary["contact"]["c"]
    _, b = moment_half_width(slave(r))
    assert "the zone is not a disc: half-axes" in r.stdout
    assert c["fem_half_axes"][0] * 2 / math.sqrt(5) == pytest.approx(b, rel=1e-9)
    assert np.allclose(c["fem_half_axis_1"], [1, 0, 0], atol=1e-6)
