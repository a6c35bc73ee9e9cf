"""Rigid 3D bodies (-<body>_rigid with a mesh that has a Physical Volume,
src/body/rigid3d.c): surfaces of Tri6 or Quad9 faces moved by a translation
t and a rotation vector theta (x = c + t + R(theta)(X - c), Rodrigues), six
unknowns each prescribed, force-controlled or free, in a 3D mortar pair on
either side. Scenes of our own under tests/meshes/rigid3d: a cube
(cube.geo), a quarter flat punch (punch.geo), a quarter ball (ball.geo), and
a quarter block standing in for a half-space (halfspace.geo), with
tests/meshes/contact3d/box.geo's elastic boxes. Each figure against an
independent answer: Rodrigues' closed form, Taylor remainders,
Boussinesq's rigid flat punch, moment balance, the symmetry of a ball
between two equal plates, another rank count."""
import math

import h5py
import numpy as np
import pytest

from conftest import figure, run_contact
from test_contact3d import refused as contact3d_refused

BOX = "tests/meshes/contact3d/box.geo"
CUBE = "tests/meshes/rigid3d/cube.geo"
PUNCH = "tests/meshes/rigid3d/punch.geo"
HALFSPACE = "tests/meshes/rigid3d/halfspace.geo"
BALL = "tests/meshes/rigid3d/ball.geo"
E, NU = 1000.0, 0.3
ESTAR = E / (1 - NU ** 2)


def surface(res, pair, group):
    """A pair's slave surface from the HDF5 output: reference and current
    node coordinates, nodal pressure, weight and force."""
    with h5py.File(res.output_path, "r") as f:
        g = f[f"contact/{pair}/{group}"]
        return {k: np.array(g[k]) for k in ("node_X", "node_x", "node_pressure", "node_weight", "node_force")}


def rodrigues(axis, angle):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def tangent_map(theta):
    """T of the rotation vector theta (d omega = T d theta, the spatial
    angular velocity): T = I + (1 - cos t)/t^2 [theta]x + (t - sin t)/t^3
    [theta]x^2, t = |theta|."""
    th = np.asarray(theta, float)
    t = np.linalg.norm(th)
    K = np.array([[0, -th[2], th[1]], [th[2], 0, -th[0]], [-th[1], th[0], 0]])
    return np.eye(3) + (1 - math.cos(t)) / t**2 * K + (t - math.sin(t)) / t**3 * K @ K


def free_moment(cube, M=None):
    """T^T M: a moment M about the cube's centre (the contact's on it by
    default) through its rotation's tangent map, whose components are the
    energy's derivatives in theta (less the load's, nil about the centre):
    zero along the free ones at the solution, a reaction along a held one."""
    return tangent_map(cube["rotation"]).T @ np.asarray(cube["moment"] if M is None else M, float)


# A rigid cube [0.3, 0.7]^2 x [2, 2.4] (Quad9 faces) far above an elastic
# box held at its bottom: no contact, the motion alone.
def turned_cube(theta, t, c):
    return ["-bodies", "box,cube", "-box_geo", BOX, "-box_geo_params", "hex=1,n=2,m=1", "-box_E", E, "-box_nu", NU, "-box_bc", "bottom",
            "-cube_rigid", "-cube_geo", CUBE, "-cube_geo_params", "x0=0.3,y0=0.3,z0=2,s=0.4,n=2",
            "-cube_bc", "top", "-cube_bc_top_values", ",".join(repr(float(v)) for v in t),
            "-cube_rigid_rotation", ",".join(repr(float(v)) for v in theta), "-cube_rigid_centre", ",".join(repr(float(v)) for v in c),
            "-contact_pairs", "c", "-contact_c_surfaces", "cube:bottom,box:top", "-contact_mortar_slave", "first"]


@pytest.mark.roundoff
@pytest.mark.parametrize("axis,angle", [((1, 1, 1), math.pi / 2), ((0, 0, 1), math.pi / 2), ((0.2, -1, 0.5), 2.5)])
def test_rotation_exact(axis, angle, tmp_path):
    """A prescribed finite rotation (90 degrees about (1, 1, 1) and about z,
    143 degrees about (0.2, -1, 0.5)) and translation move the rigid cube's
    surface nodes (the slave's node_x of the HDF5 output) to
    c + t + R (X - c), R by Rodrigues' formula in numpy, to round-off
    (`dx` = up to 1.1e-15 of the cube's size 0.4, bound 1e-14): the
    rotation is exact, not linearised, and the JSON reports the rotation
    vector given."""
    theta = np.asarray(axis, float) / np.linalg.norm(axis) * angle
    t, c = np.array([0.1, -0.05, 0.2]), np.array([0.5, 0.5, 2.2])
    res = run_contact(turned_cube(theta, t, c), tmp_path)
    s = surface(res, "c", "cube_bottom")
    X, x = s["node_X"].reshape(-1, 3), s["node_x"].reshape(-1, 3)
    expect = c + t + (X - c) @ rodrigues(axis, angle).T
    assert figure("dx", np.abs(x - expect).max() / 0.4) <= 1e-14
    cube = res.summary["bodies"]["cube"]
    assert cube["rigid"] and np.allclose(cube["rotation"], theta, rtol=0, atol=1e-15)
    assert np.allclose(cube["translation"], t, rtol=0, atol=1e-15)


# The rigid cube [0.25, 0.75]^2 x [0.5, 1] on the box [0, 1]^2 x [0, 0.5]:
# its translation in x and y held, pressed down by a force 1 at its
# reference point c (a force control), turned by 90 degrees about z and free
# to turn about x and y.
def pressed_cube(centre, rotation, block, extra=(), n=4):
    return (["-bodies", "block,cube", "-block_geo", BOX, "-block_geo_params", block, "-block_E", E, "-block_nu", NU,
             "-cube_rigid", "-cube_geo", CUBE, "-cube_geo_params", f"x0=0.25,y0=0.25,z0=0.5,s=0.5,n={n}",
             "-cube_bc", "top", "-cube_bc_top_control", "displacement,displacement,force", "-cube_bc_top_values", "0,0,-1",
             "-cube_rigid_centre", centre, "-cube_rigid_rotation", rotation,
             "-contact_pairs", "c", "-contact_c_surfaces", "block:top,cube:bottom"] + list(extra))


@pytest.mark.roundoff
def test_taylor(tmp_path):
    """Taylor remainders of the energy along a random direction of the rigid
    cube's unknowns (t_z and L theta_x, L theta_y; theta_z held at 90
    degrees, so that the second derivatives are taken at a finite
    rotation), the cube's bottom the slave on the box's top held whole (a
    flat master that no slave point leaves, where the mortar energy has no
    term it leaves undifferentiated: the rigid map's J^T H J and
    sum g . d2x/dq2 are the whole Hessian). The gradient's remainder falls
    at order 2 (`gradient_order` = 2.000) and the Hessian's relative
    remainder halves with the step (order 2 of the remainder itself) over
    the first four halvings (`hessian_rate` = 0.95 to 1.11 a halving on
    average over the five BLAS kernels, from 1.1e-7 down to 7e-9 of |H v|:
    its last step is near round-off, the penalty 1e7 against forces 1;
    bound 0.75 to 1.25, where a missing term of the Hessian leaves the
    relative remainder level, a rate of 0). Where a slave point leaves the master
    along the direction (the cube's face the slave on a box's top of the
    same size), the mortar's remainder stalls at 1.5e-6 of |H v|, its
    segments' motion not differentiated (mortar3d.c), elastic or rigid."""
    args = pressed_cube("0.5,0.5,0.75", "free,free,1.5707963267948966", "hex=1,n=3,m=1",
                        ["-block_bc", "top,bottom", "-contact_mortar_slave", "second", "-taylor_test", "-taylor_scale", "0.3",
                         "-contact_hessian", "exact", "-output", "none"], n=2)
    t = run_contact(args, tmp_path).summary["taylor"]
    assert 1.9 <= figure("gradient_order", t["gradient_order"]) <= 2.1
    r = t["hessian_relative_remainder"]
    rate = math.log2(r[0] / r[4]) / 4
    assert 0.75 <= figure("hessian_rate", rate) <= 1.25 and r[0] <= 1e-5


@pytest.mark.roundoff
def test_moment_balance(tmp_path):
    """The rigid cube pressed by a force 1 at c = (0.55, 0.5, 0.75), 0.05
    off its face's centre, onto the elastic box (Hex27 6 x 6 x 3), turned by
    0.5 about z and free to turn about x and y: it tilts towards +x about
    +y (`tilt` = 1.6e-3 rad) until the contact's moment about its current
    reference point is zero along its free rotations (free_moment's x and y:
    `moment` = up to 2.8e-11 of F L over the kernels, bound 1e-7; the
    stop's gradient bounds it; about z, held, a reaction of 2.3e-5 F L,
    the end of S' at the cube's border, test_border3d.py), the contact
    carries the force (`dF` = up to 1.4e-10, bound 1e-7: the force control's
    tolerance), and the box's own nodal forces, summed independently from
    the HDF5 output at their nodes' current positions, have the same free
    moment about c + t (`lever` = up to 4.8e-11 of the face's size, bound
    1e-4: the slave's nodes carry them, the master's a gap of 2e-6 apart)."""
    res = run_contact(pressed_cube("0.55,0.5,0.75", "free,free,0.5", "hex=1,n=6,m=3", ["-block_bc", "bottom"]), tmp_path)
    cube = res.summary["bodies"]["cube"]
    L = math.sqrt(3) * 0.5
    assert figure("moment", np.linalg.norm(free_moment(cube)[:2]) / L) <= 1e-7
    assert figure("dF", abs(cube["force"][2] - 1.0)) <= 1e-7
    assert figure("tilt", cube["rotation"][1]) > 5e-4
    s = surface(res, "c", "block_top")
    x, f = s["node_x"].reshape(-1, 3), -s["node_force"].reshape(-1, 3)   # the box's forces on the cube
    p = np.array([0.55, 0.5, 0.75]) + np.array(cube["translation"])
    M = np.cross(x - p, f).sum(axis=0)
    assert figure("lever", np.linalg.norm(free_moment(cube, M)[:2]) / np.linalg.norm(f.sum(axis=0)) / 0.5) <= 1e-4


def test_held_by_contact(tmp_path):
    """A rigid quarter ball (R = 1, Tet10 of size 0.1) between two equal
    elastic plates (Hex27 8 x 8 x 3, 0.4 x 0.4 x 0.3, rollers on the
    symmetry planes), the upper pushed down by 0.02, the lower held at its
    bottom; the ball's translation in x and y is held (the symmetry planes),
    its rotation held, its z held by nothing but the two contacts (an
    unknown of force 0). By the symmetry of the plates it sinks by half the
    push (`dz` = 1.4e-6 of 0.01 from -0.01, bound 1e-3: only its Tet10
    halves' meshes differ), the two pairs' forces are opposite (`balance`
    = 4e-12 of P) and the ball's net force in z vanishes."""
    args = ["-bodies", "lower,ball,upper"]
    for name, z0, held in (("lower", -1.3, "bottom"), ("upper", 1.0, "top")):
        args += [f"-{name}_geo", BOX, f"-{name}_geo_params", f"hex=1,n=8,m=3,L=0.4,H=0.3,z0={z0}", f"-{name}_E", E, f"-{name}_nu", NU,
                 f"-{name}_bc", f"{held},xmin,ymin", f"-{name}_bc_xmin_components", "x", f"-{name}_bc_ymin_components", "y"]
    args += ["-upper_bc_top_values", "0,0,-0.02", "-ball_rigid", "-ball_geo", BALL, "-ball_mesh_size", 0.1,
             "-ball_bc", "symx", "-ball_bc_symx_components", "x,y",
             "-contact_pairs", "lo,up", "-contact_lo_surfaces", "lower:top,ball:lower", "-contact_up_surfaces", "upper:bottom,ball:upper"]
    s = run_contact(args, tmp_path).summary
    ball = s["bodies"]["ball"]
    assert figure("dz", abs(ball["translation"][2] + 0.01) / 0.01) <= 1e-3
    lo, up = s["contact"]["lo"]["surfaces"][0]["force"], s["contact"]["up"]["surfaces"][0]["force"]
    P = abs(lo[2])
    assert P > 0.1
    assert figure("balance", abs(lo[2] + up[2]) / P) <= 1e-8
    assert abs(ball["force"][2]) <= 1e-8 * P


def punch_args(h, W, a=0.5, delta=0.005):
    return ["-bodies", "block,punch", "-block_geo", HALFSPACE, "-block_geo_params", f"W={W},rc={1.2 * a},g=0.3,c={1.2 * a}",
            "-block_mesh_size", h, "-block_E", E, "-block_nu", NU,
            "-block_bc", "symx,symy,bottom", "-block_bc_symx_components", "x", "-block_bc_symy_components", "y",
            "-punch_rigid", "-punch_geo", PUNCH, "-punch_geo_params", f"a={a},H={0.4 * a}", "-punch_mesh_size", h,
            "-punch_bc", "top", "-punch_bc_top_values", f"0,0,{-delta}",
            "-contact_pairs", "c", "-contact_c_surfaces", "block:top,punch:face", "-max_dofs", "1e9"]


@pytest.mark.parametrize("h", [0.08, 0.05])
def test_boussinesq_punch(h, tmp_path):
    """Boussinesq's rigid flat punch (radius a = 0.5, pushed down by 0.01 a)
    on a quarter block 320 a wide and deep (halfspace.geo: symmetry planes on
    rollers, the bottom held; Tet10 of size h within 1.2 a of the punch's
    centre, growing by 0.3 of the distance beyond). The punch's force on the
    whole, 4 P_quarter, against P = 2 a E* delta (E* = E / (1 - nu^2)):
    `stiffness_error` = 6.4e-3 at h = a/6, 3.4e-3 at h = a/10 (bound 1 %);
    the finite block's share, measured at h = a/6 over blocks 10 a to
    320 a wide, falls like a / W: 9.6, 4.7, 2.6, 1.4, 0.90, 0.64 % at
    W = 10, 20, 40, 80, 160, 320 a (Richardson in a / W: about 0.1 % at an
    infinite block), so what is left at W = 320 a is half the block's, half
    the mesh's. The nodal pressures of the block's surface against
    p(r) = P / (2 pi a sqrt(a^2 - r^2)) with the punch's own P, in L2 over
    r < 0.6 a weighted by the nodes' A_j: `pressure_l2` = 6.5e-3 at
    h = a/6, 3.9e-3 at h = a/10 (bound 3 %)."""
    a, delta = 0.5, 0.005
    res = run_contact(punch_args(h, 320 * a), tmp_path)
    P = 4 * res.summary["bodies"]["punch"]["force"][2]
    err = P / (2 * a * ESTAR * delta) - 1
    assert 0 <= figure("stiffness_error", err) <= 0.01
    s = surface(res, "c", "block_top")
    X = s["node_X"].reshape(-1, 3)
    r = np.hypot(X[:, 0], X[:, 1])
    m = r < 0.6 * a
    p, A = s["node_pressure"][m], s["node_weight"][m]
    pe = P / (2 * math.pi * a * np.sqrt(a * a - r[m] ** 2))
    l2 = math.sqrt(np.sum(A * (p - pe) ** 2) / np.sum(A * pe ** 2))
    assert figure("pressure_l2", l2) <= 0.03


@pytest.mark.roundoff
def test_ranks_agree(tmp_path):
    """The tilted cube (test_moment_balance) on 1 and 2 ranks at the default
    stop (each run's gradient 6.8e-11 and 7.3e-11, 3.4e-10 and 3.7e-10 of
    the contact's nodal forces): the force on the cube agrees to `dF` = up
    to 7.2e-11 over the kernels, its z part (bound: each run's miss of the
    force asked, |F_z - 1|, its force control's stop, plus its gradient's
    norm, summed over the two runs: 3.2e-10), the motion to `dt` = up to
    2.4e-14 of the translation and `drot` = up to 4.6e-14 of the tilt (bound
    1e-6: the residual, 3.7e-10 of the nodal forces, through a stiffness 100
    times below the contact's)."""
    args = pressed_cube("0.55,0.5,0.75", "free,free,0.5", "hex=1,n=6,m=3", ["-block_bc", "bottom", "-output", "none"])
    s1 = run_contact(args, tmp_path, name="one").summary
    s2 = run_contact(args, tmp_path, ranks=2, name="two").summary
    assert s2["ranks"] == 2
    one, two = s1["bodies"]["cube"], s2["bodies"]["cube"]
    dt = np.abs(np.subtract(one["translation"], two["translation"])).max() / abs(one["translation"][2])
    drot = np.abs(np.subtract(one["rotation"], two["rotation"]))[:2].max() / abs(one["rotation"][1])
    dF = np.abs(np.subtract(one["force"], two["force"])).max()
    miss = abs(one["force"][2] - 1) + abs(two["force"][2] - 1)
    assert figure("dF", dF) <= miss + s1["gradient_norm"] + s2["gradient_norm"]
    assert figure("dt", dt) <= 1e-6
    assert figure("drot", drot) <= 1e-6


def refused(args, tmp_path):
    """test_contact3d's one-line refusal, and nothing written."""
    line = contact3d_refused(args, tmp_path)
    assert not (tmp_path / "run.json").exists() and not (tmp_path / "run.h5").exists()
    return line


@pytest.mark.parametrize("opt,value,words", [
    ("-cube_rigid_rotation", "0.1,0.2", ["-cube_rigid_rotation", "3D", "rotation vector", "got 2"]),
    ("-cube_rigid_rotation", "0,abc,0", ["-cube_rigid_rotation", "a number (radians) or free", "'abc'"]),
    ("-cube_rigid_centre", "0.5,0.5", ["-cube_rigid_centre", "3D", "three numbers"]),
])
def test_bad_options(opt, value, words, tmp_path):
    """A 3D rigid body's motion options that do not fit it: one line naming
    the option and the value, status 1, nothing written."""
    args = turned_cube((0, 0, 0), (0, 0, 0), (0.5, 0.5, 2.2))
    i = args.index(opt)
    args[i + 1] = value
    line = refused(args, tmp_path)
    for w in words:
        assert w in line, line
