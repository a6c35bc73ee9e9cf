"""The 3D mortar's end term where the master's border lies inside the slave
(src/contact/segment3d.c, Segment3dEndEvaluate and Segment3dEndHessian;
mortar3d.c, Mortar3dHessianEnds). Scenes of our own, test_seghess3d.py's:
a rigid cube of side 0.5 (tests/meshes/rigid3d/cube.geo) pressed by a force
1 at c, 0.05 off its bottom face's centre, onto an elastic box
(tests/meshes/contact3d/box.geo, Hex27 6 x 6 x 3, held at its bottom), free
to turn about x and y; its bottom (the master) ends inside the box's top
(the slave), so the end of S' (the slave's part facing the master) moves
with the cube's edges. Without the end term the gradient missed O(p g)
there: the square cube's Newton never converged under the default line
search, the gradient's Taylor order fell to 0.91 at -taylor_scale 1e-5, the
Hessian's remainder levelled at 8.0e-4 of |H v| and the cube's lateral force
(a reaction: its x held) was 9 % off the energy's derivative."""
import math

import numpy as np
import pytest

from conftest import figure, run_contact
from test_rigid3d import free_moment
from test_seghess3d import SMALL, square_cube

L = math.sqrt(3) * 0.5   # the cube's half diagonal: moments over F L


def moment_xy(cube):
    """The free components (x, y) of free_moment: theta_z is held, its
    component a reaction."""
    return float(np.linalg.norm(free_moment(cube)[:2]))


@pytest.mark.roundoff
@pytest.mark.parametrize("centre", ["0.55,0.5,0.75", "0.551,0.5,0.75"])
def test_square_cube_converges(centre, tmp_path):
    """The cube square to the box (theta_z = 0), its edges on the box's
    midside nodes, pressed 0.05 (and 0.051) off centre: Newton converges
    under the default line search (8 steps measured, not asserted; 500 and
    stalled without the end term), the contact carries the force (`dF` =
    up to 1.1e-9 over the five kernels, bound 1e-7: the force control's
    tolerance), the cube tilts about +y (`tilt` = 1.8e-3 rad) and the
    contact's moment about c is balanced along the free rotations to what
    the stop guarantees: (T^T M)_x,y / L (test_rigid3d.free_moment, L the
    cube's diagonal, sqrt(3) 0.5) are the gradient's entries along the
    cube's unknowns L theta_x, L theta_y (rigid3d.c), so at most the
    gradient's norm at the stop (`moment_over_gradient` = up to 0.13 of it
    over the kernels, bound 1)."""
    res = run_contact(square_cube(centre, SMALL), tmp_path)
    cube = res.summary["bodies"]["cube"]
    assert res.summary["converged"]
    assert figure("dF", abs(cube["force"][2] - 1.0)) <= 1e-7
    assert figure("tilt", cube["rotation"][1]) > 1e-3
    assert figure("moment_over_gradient", moment_xy(cube) / L / res.summary["gradient_norm"]) <= 1.0


@pytest.mark.roundoff
@pytest.mark.parametrize("centre", ["0.55,0.5,0.75", "0.551,0.5,0.75"])
def test_turned_cube_converges(centre, tmp_path):
    """The neighbouring scene: the cube turned by 0.5 about z (its end across
    the box's mesh lines), pressed at c and at c shifted by 1e-3: Newton
    converges as before the end term, the force carried (`dF_turned` = up to
    1.4e-10 over the kernels, bound 1e-7) and the free moment balanced to the stop
    (`moment_over_gradient_turned` = up to 0.41, bound 1)."""
    args = square_cube(centre, SMALL)
    args[args.index("-cube_rigid_rotation") + 1] = "free,free,0.5"
    res = run_contact(args, tmp_path)
    cube = res.summary["bodies"]["cube"]
    assert res.summary["converged"]
    assert figure("dF_turned", abs(cube["force"][2] - 1.0)) <= 1e-7
    assert cube["rotation"][2] == 0.5
    assert figure("moment_over_gradient_turned", moment_xy(cube) / L / res.summary["gradient_norm"]) <= 1.0


@pytest.mark.roundoff
@pytest.mark.parametrize("held", ["x", "theta_z"])
def test_reaction_is_the_energy_derivative(held, tmp_path):
    """The contact's reaction on a held unknown of the cube against the
    energy's derivative in it at the solution, by central differences of
    three solves (-tao_gatol 1e-13; the step h = 1e-4): the force along x
    on the square cube (its x held at 0), and the moment's component along
    the held theta_z on the cube turned by 0.5 ((T^T M)_z: the moment
    through the rotation vector's tangent map). The end term is the
    energy's change as the cube's border moves across the slave, which the
    reactions left out before: 1.8423e-3 against the energy's 2.0246e-3
    along x, 2.9e-13 against 1.9522e-5 about z. Measured `reaction_fd` =
    1.4e-11 to 4.5e-10 over both and the kernels, of F and F times the unit length (bound
    1e-6: the force control's tolerance 1e-7 moves the cube's z by up to
    1e-7 / k_z = 1.1e-10 (k_z = F / 1.1e-3, its settlement), the energy by
    F times that, a difference of two energies over 2 h by 5.5e-7; the
    central difference's own error, h^2/6 times the reaction's second
    derivative (2e-4 measured along x), is 3e-13)."""
    h = 1e-4
    E, R = {}, {}
    for d in (-h, 0.0, h):
        args = square_cube("0.55,0.5,0.75", SMALL, ["-tao_gatol", "1e-13"])
        if held == "x":
            args[args.index("-cube_bc_top_values") + 1] = f"{d!r},0,-1"
        else:
            args[args.index("-cube_rigid_rotation") + 1] = f"free,free,{0.5 + d!r}"
        res = run_contact(args, tmp_path, name=f"r{d}")
        assert res.summary["converged"]
        cube = res.summary["bodies"]["cube"]
        E[d] = res.summary["energy"]
        R[d] = cube["force"][0] if held == "x" else free_moment(cube)[2]
    fd = -(E[h] - E[-h]) / (2 * h)
    assert abs(R[0.0]) > 1e-5
    assert figure("reaction_fd", abs(R[0.0] - fd)) <= 1e-6


@pytest.mark.roundoff
def test_taylor_square(tmp_path):
    """The Taylor test along a random direction at the square cube's iterate
    (-tao_gatol 1e-3), which moves the cube's border across the slave (the
    cube's tilts) and the slave's nodes under it: the gradient's remainder
    at order 2 at -taylor_scale 1e-5 (`gradient_order_small` = 1.992 to 2.003
    over the kernels; 0.91
    without the end term, whose O(p g) error leads at small steps) and at
    1e-3 (`gradient_order` = 2.000, 2.011 without); the Hessian's relative
    remainder, from the third halving on (the steps before cross nodes
    entering the contact), falls like the step (`hessian_rate` = 0.94 to
    0.98 a halving, bound 0.75 to 1.25; it levelled at 8.0e-4 of |H v| without the
    end term, and at 1.5e-5 with the gradient's end term but not the
    Hessian's) to `hessian_last` = 1.8e-7 to 2.0e-7 of |H v| (bound 1e-6: the falling
    term 5.3e-6 / 2^5 = 1.6e-7 six times; the round-off scale EPS/(e s) is
    2.8e-11)."""
    args = square_cube("0.55,0.5,0.75", SMALL, ["-tao_gatol", "1e-3", "-taylor_test", "-taylor_scale", "1e-3"])
    t = run_contact(args, tmp_path).summary["taylor"]
    assert 1.9 <= figure("gradient_order", t["gradient_order"]) <= 2.1
    r = t["hessian_relative_remainder"]
    assert 0.75 <= figure("hessian_rate", math.log2(r[2] / r[7]) / 5) <= 1.25
    assert figure("hessian_last", r[7]) <= 1e-6
    args = square_cube("0.55,0.5,0.75", SMALL, ["-tao_gatol", "1e-3", "-taylor_test", "-taylor_scale", "1e-5"])
    t = run_contact(args, tmp_path, name="small").summary["taylor"]
    assert 1.9 <= figure("gradient_order_small", t["gradient_order"]) <= 2.1
