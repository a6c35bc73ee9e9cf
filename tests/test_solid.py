"""3D bodies (Tet10 and Hex27) read from Gmsh: what a 3D scene is refused
for, in one line each, and what it is solved to.

The scene is our own block (tests/meshes/solid/block.geo): the box [0, 1]^3
whose corners `skew` moves, so that its faces are not plane and its cells
are distorted, meshed by Tet10 (unstructured) or Hex27 (transfinite, n cells
an edge); its faces are the physical surfaces xmin, ..., zmax."""
import pytest

from conftest import run_contact

GEO = "tests/meshes/solid/block.geo"
FACES = ("xmin", "xmax", "ymin", "ymax", "zmin", "zmax")


def block(hexa=False, skew=1.0, h=0.5, n=2, name="blk", extra=""):
    """A block body's options (E 1000, nu 0.3), no condition."""
    params = f"hex={int(hexa)},skew={skew},n={n}" + (f",{extra}" if extra else "")
    return ["-bodies", name, f"-{name}_geo", GEO, f"-{name}_geo_params", params, f"-{name}_E", "1000",
            f"-{name}_nu", "0.3", "-mesh_size", repr(h)]


def refused(args, tmp_path):
    """The run's status and its error line (the one line starting contact: error:)."""
    res = run_contact(args + ["-output", "none"], tmp_path, check=False)
    errors = [l for l in res.stderr.splitlines() if l.startswith("contact: error:")]
    assert res.returncode == 1, res.stderr[-2000:]
    assert len(errors) == 1, res.stderr[-2000:]
    assert "PETSC ERROR" not in res.stderr
    return errors[0]


@pytest.mark.parametrize("hexa", [False, True])
def test_six_free_rigid_motions(hexa, tmp_path):
    """A 3D body with no condition: its 6 rigid motions free, named as the
    2D check names its 3; with xmin held in x alone, 3 are left (y, z and
    the rotation about x); with xmin held wholly, none (it solves)."""
    line = refused(block(hexa), tmp_path)
    assert "leave 6 rigid motion(s) free" in line and "blk" in line
    line = refused(block(hexa) + ["-blk_bc", "xmin", "-blk_bc_xmin_components", "x"], tmp_path)
    assert "leave 3 rigid motion(s) free" in line


def test_first_order_refused(tmp_path):
    """Tet4 and Hex8 meshes: refused by name, with how to mesh Tet10/Hex27."""
    for hexa, shape in ((False, "4-node (first-order) tetrahedron"), (True, "8-node (first-order) hexahedron")):
        line = refused(block(hexa, extra="order=1") + ["-blk_bc", "xmin"], tmp_path)
        assert shape in line and "Tet10" in line and "Hex27" in line and "Mesh.ElementOrder = 2" in line


def test_mixed_dimensions_refused(tmp_path):
    """A 3D block beside a 2D body: one line naming both; a 3D body under
    -axisymmetric: one line."""
    args = block() + ["-blk_bc", "xmin"]
    args[1] = "blk,sheet"
    args += ["-sheet_geo", "tests/meshes/plate.geo", "-sheet_geo_params", "x0=0,y0=2,L=1,H=0.2", "-sheet_E", "1", "-sheet_nu", "0.3",
             "-sheet_bc", "bottom"]
    line = refused(args, tmp_path)
    assert "body blk is 3D" in line and "body sheet is 2D" in line and "all 2D or all 3D" in line
    line = refused(block() + ["-blk_bc", "xmin", "-axisymmetric"], tmp_path)
    assert "-axisymmetric" in line and "3D" in line


def test_components(tmp_path):
    """z is a component of a 3D body only; by default a condition holds
    every component of its body, so a 2D body's takes 2 values a stage and a
    3D body's 3."""
    line = refused(["-bodies", "sheet", "-sheet_geo", "tests/meshes/plate.geo", "-sheet_E", "1", "-sheet_nu", "0.3",
                    "-sheet_bc", "bottom", "-sheet_bc_bottom_components", "x,z"], tmp_path)
    assert "component z of a 2D body" in line
    line = refused(["-bodies", "sheet", "-sheet_geo", "tests/meshes/plate.geo", "-sheet_E", "1", "-sheet_nu", "0.3",
                    "-sheet_bc", "bottom", "-sheet_bc_bottom_values", "0,0.1,0.2"], tmp_path)
    assert "3 components a stage for a 2D body" in line
    line = refused(block() + ["-blk_bc", "xmin", "-blk_bc_xmin_values", "0,0.1"], tmp_path)
    assert "2 components a stage for a 3D body" in line
    line = refused(block() + ["-blk_bc", "xmin", "-blk_bc_xmin_components", "x,x"], tmp_path)
    assert "component x given twice" in line


def test_contact_refused(tmp_path):
    """A contact pair with a 3D body: refused in one line (3D contact is the
    next capability)."""
    args = block() + ["-blk_bc", "xmin"]
    args[1] = "blk,top"
    args += block(name="top")[2:-2] + ["-top_bc", "xmax", "-contact_pairs", "p", "-contact_p_surfaces", "blk:zmax,top:zmin"]
    line = refused(args, tmp_path)
    assert "contact pair p" in line and "3D" in line
