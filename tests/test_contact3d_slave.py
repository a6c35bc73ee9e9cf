"""The slave surface of a 3D mortar pair chosen as 2D chooses it
(-contact_mortar_slave auto, src/contact/mortar3d.c, surface3d.c's
ContactSurface3dEndsOn): a surface that ends on the other, else the softer
body's, else the first named; so the answer does not depend on the order in
which the pair names its surfaces.

The punch scene (tests/meshes/contact3d/box.geo): a square punch
[0.3, 0.7]^2 x [0.5, 0.8] (Hex27 4 x 4 x 2), E 10000, its top pushed down
by 0.004 and held in x and y, on a block [0, 1]^2 x [0, 0.5] (Hex27 5 x 5 x 2),
E 1000, held at its bottom. The punch's bottom face ends inside the block's
top (its border's closest points lie inside the top's faces): the punch is
the slave although it is the stiffer body. Two boxes of the same footprint
(the patch scene of test_contact3d.py) end flush: neither ends on the other,
and the softer is the slave."""
import pytest

from conftest import figure, run_contact

GEO = "tests/meshes/contact3d/box.geo"
NU = 0.3


def body(name, params, E, held, comps, value=None, rollers=False):
    args = ["-" + name + "_geo", GEO, f"-{name}_geo_params", params, f"-{name}_E", E, f"-{name}_nu", NU]
    groups = [held] + (["xmin", "xmax", "ymin", "ymax"] if rollers else [])
    args += [f"-{name}_bc", ",".join(groups), f"-{name}_bc_{held}_components", comps]
    if value is not None:
        args += [f"-{name}_bc_{held}_values", value]
    if rollers:
        for g, c in (("xmin", "x"), ("xmax", "x"), ("ymin", "y"), ("ymax", "y")):
            args += [f"-{name}_bc_{g}_components", c]
    return args


def punch_args(order):
    surfaces = "punch:bottom,block:top" if order == "punch-first" else "block:top,punch:bottom"
    return (["-bodies", "punch,block"]
            + body("punch", "hex=1,n=4,m=2,x0=0.3,y0=0.3,L=0.4,H=0.3,z0=0.5", 1e4, "top", "x,y,z", "0,0,-0.004")
            + body("block", "hex=1,n=5,m=2", 1000.0, "bottom", "x,y,z")
            + ["-contact_pairs", "c", "-contact_c_surfaces", surfaces, "-output", "none",
               "-tao_gatol", "1e-10", "-tao_grtol", "0", "-tao_gttol", "0"])


def test_punch_ends_on_block(tmp_path):
    """Auto takes the punch's face as slave whichever surface the pair names
    first (the block, the softer, would be the slave by stiffness alone);
    the two orders then solve the same problem: the force on the punch
    agrees to the stop's 1e-10 gradient (`punch_order_dP` = 0 relative)."""
    P = {}
    for order in ("punch-first", "block-first"):
        c = run_contact(punch_args(order), tmp_path, name=order).summary["contact"]["c"]
        punch = 0 if order == "punch-first" else 1
        assert c["surfaces"][punch]["slave"] and not c["surfaces"][1 - punch]["slave"], order
        P[order] = c["surfaces"][punch]["force"][2]
        assert P[order] > 0  # the block pushes the punch up
    dP = abs(P["punch-first"] - P["block-first"]) / abs(P["punch-first"])
    assert figure("punch_order_dP", dP) <= 1e-8


@pytest.mark.parametrize("stiffer", ["upper", "lower"])
def test_flush_boxes_softer_slave(stiffer, tmp_path):
    """Two boxes of the same footprint end flush, neither on the other: the
    softer body's surface is the slave (the first named where the moduli
    agree)."""
    Eu, El = (2000.0, 1000.0) if stiffer == "upper" else (1000.0, 2000.0)
    args = (["-bodies", "lower,upper"]
            + body("lower", "hex=1,n=3,m=2", El, "bottom", "z", rollers=True)
            + body("upper", "hex=1,n=4,m=2,z0=0.5", Eu, "top", "z", -0.01, rollers=True)
            + ["-contact_pairs", "p", "-contact_p_surfaces", "upper:bottom,lower:top", "-output", "none"])
    c = run_contact(args, tmp_path).summary["contact"]["p"]
    assert c["surfaces"][1 if stiffer == "upper" else 0]["slave"]
    assert not c["surfaces"][0 if stiffer == "upper" else 1]["slave"]
