"""The 3D mortar's Hessian where its segments move, and Newton on a rigid
cube square to a box (src/contact/mortar3d.c, segment3d.c). Scenes of our
own: the rigid cube (tests/meshes/rigid3d/cube.geo) pressed by a force 1 at
c, 0.05 off its bottom face's centre, onto an elastic box
(tests/meshes/contact3d/box.geo, Hex27 6 x 6 x 3, held at its bottom), the
cube's edges parallel to the box's mesh lines (theta_z = 0), free to turn
about x and y. Two cubes: one of side 0.5 whose bottom (the master) ends
inside the box's top (the slave), its edges on the box's midside nodes, and
one of side 1.2 whose bottom covers the box's top whole (the slave's
surface ends inside the master's: S', the slave's part facing the master,
is then the slave's fixed faces, and no end of S' moves).

Measured: the Hessian's Taylor remainder falls like the step where the
master ends inside the slave, now that the end of S' moving with the
master's border has its term (test_border3d.py: the square cube converges
under the default line search, its Taylor test there), and it is at 3e-8 to
1.2e-7 where the master covers the slave (same box, a like tilt); the cube
covering the box converges in 6 Newton steps (docs/formulations.md,
"mortar between 3D bodies")."""
import math

import pytest

from conftest import figure, run_contact
from test_contact3d import hertz_args, refused
from test_friction3d import ball_args as friction_ball_args
from test_sphere3d import whole_args

BOX = "tests/meshes/contact3d/box.geo"
CUBE = "tests/meshes/rigid3d/cube.geo"
SMALL = "x0=0.25,y0=0.25,z0=0.5,s=0.5,n=4"     # its edges on the box's midside nodes (x, y = 0.25, 0.75)
LARGE = "x0=-0.1,y0=-0.1,z0=0.5,s=1.2,n=4"     # beyond the box's top (0..1) on every side

def square_cube(centre, cube, extra=()):
    return (["-bodies", "block,cube", "-block_geo", BOX, "-block_geo_params", "hex=1,n=6,m=3", "-block_E", "1000",
             "-block_nu", "0.3", "-block_bc", "bottom",
             "-cube_rigid", "-cube_geo", CUBE, "-cube_geo_params", cube,
             "-cube_bc", "top", "-cube_bc_top_control", "displacement,displacement,force", "-cube_bc_top_values", "0,0,-1",
             "-cube_rigid_centre", centre, "-cube_rigid_rotation", "free,free,0",
             "-contact_pairs", "c", "-contact_c_surfaces", "block:top,cube:bottom", "-output", "none"] + list(extra))


@pytest.mark.roundoff
@pytest.mark.parametrize("centre", ["0.55,0.5,0.75", "0.551,0.5,0.75"])
def test_covering_cube_converges(centre, tmp_path):
    """The cube whose bottom covers the box's top, square to it and pressed
    0.05 (and 0.051) off centre: Newton converges (6 steps measured, not
    asserted), the contact carries the force (`dF_cover` = up to 1.4e-10
    over the five kernels, bound 1e-7: the force control's tolerance) and
    the cube tilts towards +x about +y (`tilt_cover` = 2.8e-4 rad, 2.9e-4
    at c_x 0.551) with no turn about x (y symmetric: `tilt_x_cover` = up to
    1.1e-16, bound 1e-9)."""
    res = run_contact(square_cube(centre, LARGE), tmp_path)
    cube = res.summary["bodies"]["cube"]
    assert res.summary["converged"]
    assert figure("dF_cover", abs(cube["force"][2] - 1.0)) <= 1e-7
    assert figure("tilt_cover", cube["rotation"][1]) > 1e-4
    assert figure("tilt_x_cover", abs(cube["rotation"][0])) <= 1e-9


@pytest.mark.roundoff
@pytest.mark.parametrize("centre", ["0.55,0.5,0.75", "0.551,0.5,0.75"])
def test_square_cube_unit_step(centre, tmp_path):
    """The cube of side 0.5 square to the box, its bottom ending inside the
    box's top on the box's midside nodes (test_border3d.py solves it with the
    default line search), with the line search off (-tao_ls_type unit, every
    Newton step taken whole): Newton converges (8 steps measured; 10 before
    the end term, when the line search stopped the default solve). At the gradient's root the
    contact carries the force (`dF_unit` = up to 1.2e-9 over the five
    kernels, bound 1e-7) and its moment about the loaded point is nil about
    x and y (`moment_unit` = up to 4.2e-11 of F L, bound 1e-7; about z, held,
    it is a reaction), the cube tilted
    about +y (`tilt_unit` = 1.8e-3 rad, 1.9e-3 at c_x 0.551)."""
    res = run_contact(square_cube(centre, SMALL, ["-tao_ls_type", "unit"]), tmp_path)
    cube = res.summary["bodies"]["cube"]
    L = math.sqrt(3) * 0.5
    assert res.summary["converged"]
    assert figure("dF_unit", abs(cube["force"][2] - 1.0)) <= 1e-7
    assert figure("moment_unit", math.hypot(cube["moment"][0], cube["moment"][1]) / L) <= 1e-7
    assert figure("tilt_unit", cube["rotation"][1]) > 1e-3


@pytest.mark.roundoff
def test_taylor_covering(tmp_path):
    """The Taylor test (-taylor_test, -taylor_scale 1e-3) at the covering
    cube's solution: the gradient's remainder at order 2
    (`gradient_order_cover` = 2.000) and the Hessian's relative remainder,
    from the fourth halving on (the steps before cross nodes entering the
    contact), at most `hessian_level_cover` = 6.4e-8 to 1.2e-7 of |H v|
    over the five kernels (bound 3e-7):
    no end of S' moves, the box's faces stay nearly flat, and what is left
    is the Gauss rule's motion with the segments (mortar3d.c)."""
    res = run_contact(square_cube("0.55,0.5,0.75", LARGE, ["-taylor_test", "-taylor_scale", "1e-3"]), tmp_path)
    t = res.summary["taylor"]
    assert 1.9 <= figure("gradient_order_cover", t["gradient_order"]) <= 2.1
    assert figure("hessian_level_cover", max(t["hessian_relative_remainder"][3:])) <= 3e-7


@pytest.mark.roundoff
def test_hertz_level_not_the_rule(tmp_path):
    """The curved slave on an elastic master: test_contact3d.py's quarter
    ball's cap (Tet10, h 0.04) on the block's top, the Taylor test at the
    solution (-taylor_scale 1e-6, as there). The Hessian's relative
    remainder falls from 5.4e-8 to `hertz_level_q4` = 2.4e-9 of |H v| with
    the pieces' Gauss rule of degree 7 (4 points a side; bound 7.5e-9), as
    the whole ball's (test_whole_ball_level), and about the same with degree
    15 (`hertz_level_ratio` = 1.03, bound 0.5 to 1.5): not the rule's error.
    It follows the master's deformation: with the block 100 times stiffer
    (E 1e7, the penalty unchanged, set by the ball) it is
    `hertz_level_ratio_E` = 0.0029 times as high (bound 0.001 to 0.01): the
    gap bends where a slave point's closest point passes from one master
    face to the next, and the pieces' borders lie there only at the
    master's nodes (segment3d.c projects each along its mean normal onto
    the curved slave; 8.0e-9 along the slave sub-triangles' normals). It
    stood at 2.9e-6 while the quarter's energy had slivers of S' along its
    symmetry planes (the block's border projected inside a slave
    sub-triangle; their moving ends had no term): the pieces now reach the
    slave's border there (segment3d.c, a strip beyond the master's border,
    its points on the master face's extension)."""
    level = {}
    for q in (4, 8):
        t = run_contact(hertz_args(0.04) + ["-taylor_test", "-taylor_scale", "1e-6", "-contact_quadrature_points", q],
                        tmp_path, name=f"q{q}").summary["taylor"]
        assert 1.9 <= t["gradient_order"] <= 2.1
        level[q] = t["hessian_relative_remainder"][-1]
    t = run_contact(hertz_args(0.04) + ["-taylor_test", "-taylor_scale", "1e-6", "-base_E", "1e7"],
                    tmp_path, name="stiff").summary["taylor"]
    assert 0.001 <= figure("hertz_level_ratio_E", t["hessian_relative_remainder"][-1] / level[4]) <= 0.01
    assert figure("hertz_level_q4", level[4]) <= 7.5e-9
    assert 0.5 <= figure("hertz_level_ratio", level[8] / level[4]) <= 1.5


@pytest.mark.roundoff
def test_whole_ball_level(tmp_path):
    """The whole ball on the whole block (test_sphere3d.py's whole_args, h
    0.04, no symmetry plane), the Taylor test at the solution (-taylor_scale
    1e-6): the Hessian's relative remainder falls from 5.2e-8 at the first
    step to `whole_level` = 1.55e-9 of |H v| (1.53e-9 and 1.49e-9 with 3 and
    6 points a side; bound 5e-9; 4.9e-9 while the master's nodes were
    projected along the slave sub-triangles' normals), the quarter ball's
    to 2.4e-9: the whole's over the quarter's `level_ratio` = 0.65 (bound
    0.2 to 5: the symmetry planes add little now; 1.7e-3 while the
    quarter's slivers had no end term). With the segments frozen in xi over
    the test (an experiment, not in the code, before the mean normals) the
    remainder fell to 5.2e-10: the Hessian is exact for fixed segments, and
    what is left (following the master's deformation: 7.2e-12 with the
    block 100 times stiffer) is the segments' own motion."""
    run = run_contact(whole_args(0.04) + ["-taylor_test", "-taylor_scale", "1e-6", "-output", "none"], tmp_path, name="whole")
    assert "note: the zone is cut" not in run.stdout  # no plane cuts the whole ball's zone (report3d.c)
    whole = run.summary["taylor"]
    quarter = run_contact(hertz_args(0.04) + ["-taylor_test", "-taylor_scale", "1e-6"],
                          tmp_path, name="quarter").summary["taylor"]
    assert 1.9 <= whole["gradient_order"] <= 2.1
    level = figure("whole_level", whole["hessian_relative_remainder"][-1])
    assert level <= 5e-9
    assert whole["hessian_relative_remainder"][0] >= 5 * level
    assert 0.2 <= figure("level_ratio", level / quarter["hessian_relative_remainder"][-1]) <= 5


def friction_args():
    """test_friction3d.py's half ball (h 0.04) pressed, then its top moved
    along x to about Q/(mu P) = 0.5 (some nodes stuck, some slipping), on a
    block 100 times stiffer (E 1e5), as the Hertz balls' blocks are."""
    args = friction_ball_args(h=0.04)
    args[args.index("-ball_bc_top_values") + 1] = "0.0,-0.01,1.65e-3,-0.01"
    args[args.index("-load_stages") + 1] = 2
    return args + ["-block_E", "1e5", "-output", "none"]


EDGE_SCENES = {"quarter": lambda: hertz_args(0.04), "whole": lambda: whole_args(0.04) + ["-output", "none"],
               "friction": friction_args}


def window_order(t, k0=2, k1=5):
    """The Hessian remainder's order from the step eps_k0 to eps_k1 (its
    relative remainder falls as eps at order 2); by default from 1/4 to
    1/32 of the direction, above round-off."""
    r = t["hessian_relative_remainder"]
    return 1 + math.log2(r[k0] / r[k1]) / (k1 - k0)


@pytest.mark.roundoff
@pytest.mark.parametrize("scene", sorted(EDGE_SCENES))
def test_edge_points_order2(scene, tmp_path):
    """-contact_mortar_edge_points 3: the pieces' borders follow the master
    edges' curved images (3 points between each two nodes of an edge,
    projected as the nodes are) and the border nodes go along their lines
    where the master's border runs along the slave's (the symmetry planes):
    the Taylor test's remainder falls at order 2 until round-off, where with
    the pieces straight between the nodes it levels (the quadrature of the
    gap's gradient, which jumps where a slave point's closest point passes
    from one master face to the next, moved with the pieces). The quarter
    and the whole Hertz balls and the half ball sheared with Coulomb
    friction (stuck and slipping nodes; the friction's rows are fixed within
    a lag, its Hessian exact there: test_friction3d.py's patch), the Taylor
    test at the solution (-taylor_scale 1e-6); the Hessian takes the kink
    lines' motion (segment3d.c, Segment3dKinkHessian) and dQ_j the layout's
    (Segment3dKinkEvaluate). From 1/4 to 1/32 of
    the direction (above round-off) the order is `edge_order` = 1.98 to 2.00
    (bound 1.93); the default's `default_order` = 1.47 to 1.84 (friction,
    quarter, whole; bound below 1.9). The remainder at 1/128 of the
    direction, `edge_remainder` = 4.6e-10 to 1.8e-9 of |H v| (bound 3e-9),
    is near round-off (along -taylor_scale 1e-7 it rises again from about
    5e-10, as 1/eps); the default's `default_remainder` = 1.55e-9 to 1.5e-8
    (whole, quarter, friction). The answers
    move by the quadrature's gain and the stop (P by `dP_edges` = 2.8e-10 to
    3.4e-9 of itself, bound 1e-8)."""
    base = EDGE_SCENES[scene]() + ["-taylor_test", "-taylor_scale", "1e-6"]
    edge = run_contact(base + ["-contact_mortar_edge_points", 3], tmp_path, name="edges").summary
    plain = run_contact(base, tmp_path, name="plain").summary
    for s in (edge, plain):
        assert 1.9 <= s["taylor"]["gradient_order"] <= 2.1
    assert figure("edge_order", window_order(edge["taylor"])) >= 1.93
    assert figure("default_order", window_order(plain["taylor"])) < 1.9
    assert figure("edge_remainder", edge["taylor"]["hessian_relative_remainder"][-1]) <= 3e-9
    figure("default_remainder", plain["taylor"]["hessian_relative_remainder"][-1])
    assert figure("dP_edges", abs(edge["contact_force"] / plain["contact_force"] - 1)) <= 1e-8


@pytest.mark.roundoff
def test_edge_points_soft_master(tmp_path):
    """A block as soft as the ball (E 1000 both, test_friction3d.py's half
    ball, one stage with friction): the master bends between its faces 100
    times as much, and between a piece's straight border and the curved
    line where the closest point changes face the pieces integrate the other
    face's gap, so Q_j moves with the pieces' layout; dQ_j takes that motion
    (Segment3dKinkEvaluate: the Gauss-Newton part k_p dQ_j dQ_j^T holds it)
    and with -contact_mortar_edge_points 3 the remainder falls at order 2
    (bound 1.93 from 1/4 to 1/32 of the direction, as
    test_edge_points_order2's) to `soft_level` = 9.4e-9 to 1.0e-8 of |H v|
    at 1/128 of it over the five BLAS kernels (bound 3e-8), where it levelled at 8.9e-8 without that term and
    1.1e-6 with the pieces straight (docs/formulations.md)."""
    args = friction_ball_args(h=0.04) + ["-output", "none", "-taylor_test", "-taylor_scale", "1e-6",
                                         "-contact_mortar_edge_points", 3]
    args[args.index("-load_stages") + 1] = 1
    args[args.index("-ball_bc_top_values") + 1] = "0.0,-0.01"
    t = run_contact(args, tmp_path).summary["taylor"]
    assert figure("soft_level", t["hessian_relative_remainder"][-1]) <= 3e-8
    assert window_order(t) >= 1.93


@pytest.mark.parametrize("value,says", [("-1", "must be in [0, 8], got -1"), ("9", "must be in [0, 8], got 9"),
                                        ("abc", "'abc' is not an integer")])
def test_edge_points_refused(value, says, tmp_path):
    """A bad -contact_mortar_edge_points: one line naming the option and
    the value, status 1."""
    line = refused(hertz_args(0.04) + ["-contact_mortar_edge_points", value], tmp_path)
    assert "option -contact_mortar_edge_points" in line and says in line
