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
    (4 x 4 x 2): it converges (55 and 99 iterations over 29 and 22 friction
    lags; without the blocks DIVERGED_MAXITS after 503 on both, the cube
    turning away) and the rotation's gradient T^T M_c on the free
    components vanishes (`moment` = 1.4e-9 and 1.4e-9 of F L, bound 1e-6:
    the stop's gradient)."""
    s = run_contact(friction_args(held, block=block), tmp_path).summary
    assert s["converged"]
    cube = s["bodies"]["cube"]
    theta, Mc = np.array(cube["rotation"]), -np.array(cube["moment"])
    dpi = spatial_jacobian(theta).T @ Mc
    assert figure("moment", np.abs(dpi[:2]).max() / L) <= 1e-6
    assert cube["force"][2] == pytest.approx(1.0, abs=1e-6)


@pytest.mark.roundoff
def test_friction_ranks(tmp_path):
    """The sheared cube (test_friction_converges) on 1 and 2 ranks, each
    rank its nodes' friction blocks, their rigid parts summed over the ranks
    into the border: the force on the cube agrees to `dF` = 3.0e-11 (bound
    2e-6: each run's force control to -force_control_rtol 1e-6 of F = 1),
    the tilt to `drot` = 3.6e-10 of it and the sinking t_z to `dt` =
    1.7e-10 of it (bound 1e-6, as test_rigid3d's ranks: the residuals
    through a stiffness 100 times below the contact's)."""
    one = run_contact(friction_args("top,bottom"), tmp_path, name="one").summary
    two = run_contact(friction_args("top,bottom"), tmp_path, ranks=2, name="two").summary
    assert two["ranks"] == 2 and one["converged"] and two["converged"]
    c1, c2 = one["bodies"]["cube"], two["bodies"]["cube"]
    assert figure("dF", np.abs(np.subtract(c1["force"], c2["force"])).max()) <= 2e-6
    assert figure("drot", np.abs(np.subtract(c1["rotation"], c2["rotation"]))[:2].max() / abs(c1["rotation"][1])) <= 1e-6
    assert figure("dt", abs(c1["translation"][2] - c2["translation"][2]) / abs(c1["translation"][2])) <= 1e-6
