"""Rigid 3D bodies' moment control, a rigid face as the mortar slave, and
friction with a rigid body (src/body/rigidbody.c's -<body>_rigid_moment,
src/body/rigid3d.c, src/contact/friction3d.c's rigid blocks). Scenes of our
own: the rigid cube (tests/meshes/rigid3d/cube.geo) on an elastic box
(tests/meshes/contact3d/box.geo), as test_rigid3d.py's. Each figure against
an independent answer: the moment's balance through T(theta), computed here
from Rodrigues' formula by finite differences; the same load given as an
off-centre force; Taylor remainders; the action and reaction of the two
bodies' nodal forces."""
import math

import h5py
import numpy as np
import pytest

from conftest import figure, run_contact
from test_rigid3d import refused, rodrigues, turned_cube

BOX = "tests/meshes/contact3d/box.geo"
CUBE = "tests/meshes/rigid3d/cube.geo"
FACE = np.array([0.5, 0.5, 0.75])   # the cube's reference point above its bottom face's centre
L = math.sqrt(3) * 0.5              # the cube's size (its bounding box's diagonal)


def rotation(theta):
    a = np.linalg.norm(theta)
    return np.eye(3) if a == 0 else rodrigues(theta, a)


def spatial_jacobian(theta, h=1e-6):
    """T with omega = T dtheta: column j the axial vector of
    dR/dtheta_j R^T, by central differences of Rodrigues' R (error h^2)."""
    R = rotation(theta)
    T = np.zeros((3, 3))
    for j in range(3):
        e = np.zeros(3)
        e[j] = h
        W = (rotation(theta + e) - rotation(theta - e)) / (2 * h) @ R.T
        T[:, j] = [W[2, 1], W[0, 2], W[1, 0]]
    return T


def cube_args(centre, extra=(), block="hex=1,n=4,m=2"):
    """The rigid cube [0.25, 0.75]^2 x [0.5, 1] (Quad9, n = 2) on the box
    [0, 1]^2 x [0, 0.5] held at its bottom, the cube's bottom the slave
    (second), its x and y held, pressed by a force 1 (z force-controlled),
    turned by 0.5 about z and free to turn about x and y."""
    return ["-bodies", "block,cube", "-block_geo", BOX, "-block_geo_params", block, "-block_E", 1000.0, "-block_nu", 0.3,
            "-block_bc", "bottom", "-cube_rigid", "-cube_geo", CUBE, "-cube_geo_params", "x0=0.25,y0=0.25,z0=0.5,s=0.5,n=2",
            "-cube_bc", "top", "-cube_bc_top_control", "displacement,displacement,force", "-cube_bc_top_values", "0,0,-1",
            "-cube_rigid_centre", ",".join(repr(float(v)) for v in centre), "-cube_rigid_rotation", "free,free,0.5",
            "-contact_pairs", "c", "-contact_c_surfaces", "block:top,cube:bottom", "-contact_mortar_slave", "second"] + list(extra)


@pytest.mark.roundoff
def test_moment_balance(tmp_path):
    """The cube pressed at its face's centre and turned by the moment
    M = (0, 0.05, 0) (-cube_rigid_moment, the potential -M . theta): it tilts
    about y (`tilt` = 1.06e-3 rad) until dPi/dtheta = T(theta)^T M_c = M on its
    free components, M_c the contact's moment about c + t (the JSON's moment,
    negated) and T computed here from Rodrigues' formula: to `balance` =
    4.5e-9 of |M| (bound 1e-6: the stop's gradient, 1e-10 of the nodal
    forces, over the moment's lever 0.25). With theta_z = 0.5 held, M_c is
    not M itself: its x, y part is off M's by `spatial_gap` = 0.251 of |M|,
    |theta x M| / 2 to first order (0.25; bound 0.2 to 0.3), the meaning
    docs/scenes.md gives: a rotation about a fixed axis along M alone
    takes M exactly."""
    M = np.array([0.0, 0.05, 0.0])
    res = run_contact(cube_args(FACE, ["-cube_rigid_moment", "0,0.05,0", "-output", "none"]), tmp_path)
    cube = res.summary["bodies"]["cube"]
    theta, Mc = np.array(cube["rotation"]), -np.array(cube["moment"])
    assert figure("tilt", theta[1]) > 5e-4
    dpi = spatial_jacobian(theta).T @ Mc
    assert figure("balance", np.abs(dpi[:2] - M[:2]).max() / np.linalg.norm(M)) <= 1e-6
    gap = figure("spatial_gap", np.linalg.norm(Mc[:2] - M[:2]) / np.linalg.norm(M))
    assert 0.2 <= gap <= 0.3
    ctl = {c["component"]: c for c in res.summary["force_control"]}
    assert ctl["rotation_y"]["force"] == pytest.approx(0.05, rel=1e-12) and not ctl["rotation_y"]["anchor"]


@pytest.mark.roundoff
def test_moment_as_lever(tmp_path):
    """The same loads twice: the force F = (0, 0, -1) and the supports that
    hold x and y acting through c' = (0.55, 0.5, 0.75), 0.05 off the face's
    centre c; then through c, held where the first run's c went, with the
    moment those loads have about it, M_s = R (c' - c) x (F + S) (spatial, at
    the first run's rotation R; S the supports' force, the contact's x, y
    force negated), given as M = T^T M_s on the free components. The two
    runs end in the same motion: the rotation to `drot` = 1.4e-8 of the
    tilt (`tilt` = 1.10e-3) and the face centre's position to `dpos` = 9.3e-14 (bounds 1e-5 and 1e-8: the stops' gradients, 1e-10 of the nodal
    forces, through the tilt's stiffness)."""
    cp = FACE + [0.05, 0.0, 0.0]
    one = run_contact(cube_args(cp, ["-output", "none"]), tmp_path, name="force").summary["bodies"]["cube"]
    theta = np.array(one["rotation"])
    R = rotation(theta)
    load = np.array([-one["force"][0], -one["force"][1], -1.0])   # F and the supports' S
    M = spatial_jacobian(theta).T @ np.cross(R @ (cp - FACE), load)
    pos1 = cp + np.array(one["translation"]) + R @ (FACE - cp)   # where c went
    t2 = pos1 - FACE
    args = cube_args(FACE, ["-cube_rigid_moment", f"{float(M[0])!r},{float(M[1])!r},0", "-output", "none"])
    args[args.index("-cube_bc_top_values") + 1] = f"{float(t2[0])!r},{float(t2[1])!r},-1"
    two = run_contact(args, tmp_path, name="moment").summary["bodies"]["cube"]
    tilt = figure("tilt", abs(theta[1]))
    assert tilt > 5e-4
    assert figure("drot", np.abs(np.subtract(two["rotation"], one["rotation"])).max() / tilt) <= 1e-5
    assert figure("dpos", np.abs(FACE + np.array(two["translation"]) - pos1).max()) <= 1e-8


@pytest.mark.parametrize("rot,moment,words", [
    ("free,free,0.5", "0,0,0.1", ["-cube_rigid_moment", "about z", "held or prescribed", "free"]),
    ("0,0,0", "0.1,0,0", ["-cube_rigid_moment", "about x", "held or prescribed"]),
    ("free", "0.1,0.2", ["-cube_rigid_moment", "2 values for 3 components"]),
])
def test_bad_moment(rot, moment, words, tmp_path):
    """A moment on a rotation that is held or prescribed, or a count of values
    that is not three a stage: one line naming the option, status 1, nothing
    written."""
    args = turned_cube((0, 0, 0), (0, 0, 0), (0.5, 0.5, 2.2))
    args[args.index("-cube_rigid_rotation") + 1] = rot
    line = refused(args + ["-cube_rigid_moment", moment], tmp_path)
    for w in words:
        assert w in line, line


# The cube's bottom as the slave on the box's top held whole, pressed through
# c' (a force 1, its rotation free about x and y), then moved along x by DX
# in a second stage with friction mu = 0.3: part of its face sticks, part slips.
DX = 3e-5


def friction_args(held, extra=(), block="hex=1,n=3,m=1"):
    return ["-bodies", "block,cube", "-block_geo", BOX, "-block_geo_params", block, "-block_E", 1000.0, "-block_nu", 0.3,
            "-block_bc", held, "-cube_rigid", "-cube_geo", CUBE, "-cube_geo_params", "x0=0.25,y0=0.25,z0=0.5,s=0.5,n=2",
            "-cube_bc", "top", "-cube_bc_top_control", "displacement,displacement,force", "-cube_bc_top_values", f"0,0,-1,{DX},0,-1",
            "-load_stages", 2, "-load_steps", 1, "-cube_rigid_centre", "0.55,0.5,0.75", "-cube_rigid_rotation", "free,free,0.5,free,free,0.5",
            "-contact_pairs", "c", "-contact_c_surfaces", "block:top,cube:bottom", "-contact_mortar_slave", "second",
            "-contact_c_friction", 0.3, "-output", "none"] + list(extra)


@pytest.mark.roundoff
def test_friction_taylor(tmp_path):
    """Taylor remainders at the sheared cube's solution (the box held whole:
    the cube's unknowns t_z, L theta_x, L theta_y alone move, and the rigid
    map's blocks are the whole Hessian), friction's blocks mapped to them
    through x(q) (Friction3dSetRigidBlock): the gradient's remainder at
    order 2 (`gradient_order` = 2.000) and the Hessian's relative remainder
    halving with the step (`hessian_rate` = 1.001 a halving over the steps 1/2
    to 1/32, from 4.0e-7 of |H v|; bound 0.75 to 1.25; the first, whole step
    crosses the stick-slip border, 3.3e-2), with nodes both stuck and slipping
    (`stick_fraction` = 0.341 of the contact's area). Without the friction's
    rigid block the remainder stays at 1.0e-3 of |H v| (a rate of 0)."""
    res = run_contact(friction_args("top,bottom", ["-taylor_test", "-taylor_scale", "0.3", "-contact_hessian", "exact"]), tmp_path)
    t, c = res.summary["taylor"], res.summary["contact"]["c"]
    assert 1.9 <= figure("gradient_order", t["gradient_order"]) <= 2.1
    r = t["hessian_relative_remainder"]
    rate = math.log2(r[1] / r[5]) / 4
    assert 0.75 <= figure("hessian_rate", rate) <= 1.25 and r[1] <= 1e-5
    assert 0.05 < figure("stick_fraction", c["stick_area"] / c["contact_area"]) < 0.95


@pytest.mark.roundoff
@pytest.mark.parametrize("held,block", [("top,bottom", "hex=1,n=3,m=1"), ("bottom", "hex=1,n=4,m=2")])
def test_friction_converges(held, block, tmp_path):
    """The sheared cube solved by Newton with friction's rigid blocks in the
    Hessian, the box held whole (Hex27 3 x 3 x 1) or at its bottom alone
    (4 x 4 x 2): it converges under each of the five BLAS kernels (37 or 38
    and 51 or 52 iterations over 25 and 18 friction lags; without the
    blocks DIVERGED_MAXITS after 503 on both, the cube turning away; with
    the lag before the last penalty stage read at the last stage's k_p,
    DIVERGED_USER or DIVERGED_LS_FAILURE under four of them: staging.c's
    ProblemStateLagSofter) and the rotation's gradient T^T M_c on the free
    components vanishes (`moment` = 1.4e-9 and 1.4e-9 of F L, bound 1e-6:
    the stop's gradient)."""
    s = run_contact(friction_args(held, block=block), tmp_path).summary
    assert s["converged"]
    cube = s["bodies"]["cube"]
    theta, Mc = np.array(cube["rotation"]), -np.array(cube["moment"])
    dpi = spatial_jacobian(theta).T @ Mc
    assert figure("moment", np.abs(dpi[:2]).max() / L) <= 1e-6
    assert cube["force"][2] == pytest.approx(1.0, abs=1e-6)


def test_moment_2d_punch(tmp_path):
    """2D: the rigid flat punch (half-width b = 0.25, meshes/rigid-punch's
    shapes, coarser: h = 0.0125 in the block, 0.025 on the punch) pressed by
    P = 0.15 (force-controlled) and turned by the moment M = -0.015
    (-punch_rigid_moment, clockwise; exact in 2D, the rotation's axis being
    fixed): the contact's moment on it balances M (`dM` = 4.6e-8 of |M|,
    bound 1e-6: the force control's -force_control_rtol) and its tilt is
    Johnson's 4 M / (pi E* b^2) on a half-plane to `tilt_error` = -1.2 %
    (bound 3 %: the block is 16 b wide, the mesh coarse; the readme's
    eccentric force e = M / P turned the punch to -0.79 % at h = 0.00625)."""
    b, P, M, E, nu = 0.25, 0.15, -0.015, 100.0, 0.3
    args = ["-bodies", "punch,block", "-punch_geo", "meshes/rigid-punch/punch.geo", "-punch_geo_params", f"b={b},Hp=0.25",
            "-punch_mesh_size", 0.025, "-punch_rigid", "-punch_bc", "push", "-punch_bc_push_components", "x,y",
            "-punch_bc_push_control", "displacement,force", "-punch_bc_push_values", f"0,{-P}",
            "-punch_rigid_rotation", "free", "-punch_rigid_moment", M,
            "-block_geo", "meshes/punch/block.geo", "-block_geo_params", "W=4,H=2,hfar=0.25,dp=0.4,dc=1", "-block_mesh_size", 0.0125,
            "-block_E", E, "-block_nu", nu, "-block_bc", "base", "-block_bc_base_components", "x,y",
            "-contact_pairs", "tool", "-contact_tool_surfaces", "punch:contact,block:contact", "-output", "none"]
    punch = run_contact(args, tmp_path).summary["bodies"]["punch"]
    assert figure("dM", abs(punch["moment"] + M) / abs(M)) <= 1e-6
    johnson = 4 * M / (math.pi * E / (1 - nu ** 2) * b * b)
    assert abs(figure("tilt_error", punch["rotation"] / johnson - 1)) <= 0.03


@pytest.mark.roundoff
def test_rigid_slave_moment(tmp_path):
    """The cube's face as the mortar slave, pressed through c' (0.05 off its
    face's centre; test_rigid3d's moment balance with the slave forced,
    where |M| over its three components was 9.1e-5 of F L against 6e-10
    with the cube as master). The free components balance: T^T M_c, the
    rotation's gradient, is `free_moment` = 1.5e-12 of F L on x and y (bound
    1e-6: the stop). What is left is M_c's z component, the reaction of
    the held theta_z (`held_moment` = 5.4e-6 of F L here, 9.1e-5 on
    test_rigid3d's meshes): with the rigid face as slave the traction
    follows the elastic master's normal, which tilts where the box's top
    bends around the cube's edges, so the contact's force on the cube has
    an x, y part (`tangential` = 4.0e-4 of F) whose moment about z the held
    rotation takes; with the rigid face as master the traction is along
    its own normal. The cube's nodal forces from the HDF5, summed here at
    their nodes' current positions about c' + t, give the JSON's moment
    (`sum_gap` = 1.1e-17 of F L, bound 1e-8)."""
    cp = FACE + [0.05, 0.0, 0.0]
    res = run_contact(cube_args(cp), tmp_path)
    cube = res.summary["bodies"]["cube"]
    theta, Mc = np.array(cube["rotation"]), -np.array(cube["moment"])
    dpi = spatial_jacobian(theta).T @ Mc
    assert figure("free_moment", np.abs(dpi[:2]).max() / L) <= 1e-6
    figure("held_moment", abs(Mc[2]) / L)
    figure("tangential", math.hypot(cube["force"][0], cube["force"][1]))
    with h5py.File(res.output_path, "r") as f:
        g = f["contact/c/cube_bottom"]
        x, gn = np.array(g["node_x"]).reshape(-1, 3), np.array(g["node_force"]).reshape(-1, 3)
    p = cp + np.array(cube["translation"])
    M = np.cross(x - p, gn).sum(axis=0)
    gap = np.abs(M + Mc).max() / L   # node_force is minus the gradient: its moment is the JSON's, -M_c
    assert figure("sum_gap", gap) <= 1e-8


def test_tilted_punch(tmp_path):
    """A rigid flat circular punch (a = 0.5) tilted by a moment on a block
    standing in for a half-space: test_rigid3d's quarter punch and quarter
    block (W = 80 a, Tet10 of size h = a/6 near the punch), with the tilt's
    antisymmetry on the plane x = 0 (u_y = u_z = 0 there; on y = 0 the
    rollers), the punch held but for its rotation about y through its face's
    centre, turned by M_q = (0, 0.01 E* a^3 / 3, 0) (-punch_rigid_moment;
    theta along M from rest: exact). In the quarter x, y > 0 the pressure is
    compressive, so the unilateral contact is the bilateral one, whose
    rocking stiffness is M = 4 E* a^3 theta / 3 (= 8 G a^3 / (3 (1 - nu)),
    the tilted punch's pressure 3 M x / (2 pi a^3 sqrt(a^2 - r^2))), M = 4
    M_q for the whole punch: theta = 3 M_q / (E* a^3) = 0.01 to
    `tilt_error` = -0.78 % (bound 2 %; at h = 0.08, -0.54 % at W = 80 a and
    -1.05 % at W = 20 a). The block's
    nodes on x = 0, held in z by the antisymmetry, take a pressure where the
    punch's face descends over their support (a line of force along the
    y axis, there in the quarter's force and its moment about x, not about
    y)."""
    a, E, nu = 0.5, 1000.0, 0.3
    es = E / (1 - nu ** 2)
    Mq = 0.01 * es * a ** 3 / 3
    args = ["-bodies", "block,punch", "-block_geo", "tests/meshes/rigid3d/halfspace.geo",
            "-block_geo_params", f"W={80 * a},rc={1.2 * a},g=0.3,c={1.2 * a}", "-block_mesh_size", a / 6, "-block_E", E, "-block_nu", nu,
            "-block_bc", "symx,symy,bottom", "-block_bc_symx_components", "y,z", "-block_bc_symy_components", "y",
            "-punch_rigid", "-punch_geo", "tests/meshes/rigid3d/punch.geo", "-punch_geo_params", f"a={a},H={0.4 * a}", "-punch_mesh_size", a / 6,
            "-punch_bc", "top", "-punch_bc_top_values", "0,0,0", "-punch_rigid_centre", "0,0,0",
            "-punch_rigid_rotation", "0,free,0", "-punch_rigid_moment", f"0,{Mq!r},0",
            "-contact_pairs", "c", "-contact_c_surfaces", "block:top,punch:face", "-max_dofs", "1e9", "-output", "none"]
    punch = run_contact(args, tmp_path).summary["bodies"]["punch"]
    theta = punch["rotation"][1]
    assert abs(figure("tilt_error", theta / (3 * Mq / (es * a ** 3)) - 1)) <= 0.02


@pytest.mark.roundoff
def test_friction_ranks(tmp_path):
    """The sheared cube (test_friction_converges) on 1 and 2 ranks, each
    rank its nodes' friction blocks, their rigid parts summed over the ranks
    into the border: the force on the cube agrees to `dF` = 2.6e-11 to
    5.9e-11 (the five kernels; bound 2e-6: each run's force control to
    -force_control_rtol 1e-6 of F = 1), the tilt to `drot` = 8.2e-11 to
    2.6e-10 of it and the sinking t_z to `dt` = 4.9e-12 to 1.1e-10 of it
    (bound 1e-6, as test_rigid3d's ranks: the residuals through a
    stiffness 100 times below the contact's)."""
    one = run_contact(friction_args("top,bottom"), tmp_path, name="one").summary
    two = run_contact(friction_args("top,bottom"), tmp_path, ranks=2, name="two").summary
    assert two["ranks"] == 2 and one["converged"] and two["converged"]
    c1, c2 = one["bodies"]["cube"], two["bodies"]["cube"]
    assert figure("dF", np.abs(np.subtract(c1["force"], c2["force"])).max()) <= 2e-6
    assert figure("drot", np.abs(np.subtract(c1["rotation"], c2["rotation"]))[:2].max() / abs(c1["rotation"][1])) <= 1e-6
    assert figure("dt", abs(c1["translation"][2] - c2["translation"][2]) / abs(c1["translation"][2])) <= 1e-6
