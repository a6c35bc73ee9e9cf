"""A 3D body's output: the HDF5 file (coordinates and displacement of 3
components, stress of 6 in the order xx, yy, zz, xy, yz, xz, von Mises of
the full 3D stress, Tet10 / Hex27 connectivity in VTK's node order), the
XDMF file ParaView reads it through (Tetrahedron_10, Hexahedron_27), the
JSON's displacement figures over the three components, 1 and 2 ranks alike,
and scripts/plot_hertz.py --field on a 3D file.

The scenes are our own block (tests/meshes/solid/block.geo, as in
tests/test_solid.py): the box [0, 1]^3 (skew 0) or the distorted block
(skew 1, no face plane), Tet10 or Hex27. Each cell's connectivity is
checked here from its nodes' positions (edge nodes at their corners'
midpoints, face nodes at their faces' centres, VTK's orientation), and
ParaView checks it independently through its own cells' interpolation."""
import json
import re
import subprocess
import sys

import numpy as np
import pytest

from conftest import ROOT, figure, run_contact
from test_paraview import colours, display, run_pvpython  # noqa: F401 (display: the session's X server fixture)
from test_solid import block, block_volume, FACES

SOLID = ROOT / "tests" / "paraview_solid.py"
E, NU = 1000.0, 0.3
C0 = np.array([0.01, 0.0, 0.02])
G = np.array([[0.02, -0.01, 0.03], [0.01, 0.015, -0.02], [-0.01, 0.01, 0.005]])
# VTK's quadratic tetrahedron and triquadratic hexahedron (vtkQuadraticTetra,
# vtkTriQuadraticHexahedron's parametric coordinates in ParaView 5.11): each
# edge node's two corners, each face node's four.
TET_EDGES = [(0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)]
HEX_EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
HEX_FACES = [(0, 3, 7, 4), (1, 2, 6, 5), (0, 1, 5, 4), (3, 2, 6, 7), (0, 1, 2, 3), (4, 5, 6, 7)]
VTK_TYPE = {"Tet10": 24, "Hex27": 29}
XDMF_TYPE = {"Tet10": "Tetrahedron_10", "Hex27": "Hexahedron_27"}
STRESS = ("stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_xz")
CASES = [(False, 0.0), (False, 1.0), (True, 0.0), (True, 1.0)]
IDS = ["tet10-box", "tet10-skew", "hex27-box", "hex27-skew"]


def exact_stress(G):
    """sigma = lambda tr(eps) I + 2 mu eps of the small strain eps = (G + G^T) / 2."""
    lam, mu = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
    eps = 0.5 * (G + G.T)
    return lam * np.trace(eps) * np.eye(3) + 2 * mu * eps


def von_mises(s):
    """The von Mises stress of a 3 x 3 stress."""
    return np.sqrt(0.5 * ((s[0, 0] - s[1, 1]) ** 2 + (s[1, 1] - s[2, 2]) ** 2 + (s[2, 2] - s[0, 0]) ** 2)
                   + 3 * (s[0, 1] ** 2 + s[1, 2] ** 2 + s[0, 2] ** 2))


def affine(tmp_path, hexa, skew, name="affine"):
    """u = C0 + G x imposed on the block's whole boundary, solved to a tight stop."""
    params = ",".join(repr(float(v)) for i in range(3) for v in [C0[i]] + list(G[i]))
    args = block(hexa, skew) + ["-blk_bc", ",".join(FACES), "-blk_exact", "affine", "-blk_exact_params", params,
                                "-tao_gttol", "1e-14", "-tao_gatol", "1e-11"]
    return run_contact(args + [f"-blk_bc_{f}_exact" for f in FACES], tmp_path, name=name)


def bend(tmp_path, hexa, ranks=1, name="bend"):
    """The box held at xmin and its xmax face moved 0.1 in z: a stress that
    varies over the body (largest at the held faces' edges)."""
    args = block(hexa, 0.0, h=0.25, n=4) + ["-blk_bc", "xmin,xmax", "-blk_bc_xmax_values", "0,0,0.1",
                                            "-tao_gttol", "1e-14", "-tao_gatol", "1e-11"]
    return run_contact(args, tmp_path, ranks=ranks, name=name)


def fields(run):
    """The body's datasets and cell type from the run's HDF5 file."""
    with run.h5() as h5:
        g = h5["bodies"]["blk"]
        out = {k: g[k][...] for k in g}
        out["cell_type"] = g.attrs["cell_type"].decode()
    return out


@pytest.mark.roundoff
@pytest.mark.parametrize("hexa,skew", CASES, ids=IDS)
def test_fields_exact(hexa, skew, tmp_path):
    """The affine map u = c + G x on the box and the distorted block: every
    node's coordinates (3 columns) and displacement (3 columns) are the map's
    (the finite-element space holds it; to 1e-12 of |u|, the solve's stop
    1e-14: measured `du` = 8.0e-16 to 1.5e-15), the stress's six columns
    xx, yy, zz, xy, yz, xz the constant sigma(G) at every node (to 1e-10 of
    |sigma|: measured `dsig` = 1.9e-14 to 3.1e-14) and von Mises that of the
    full 3D sigma; the XDMF forms (displacement_xyz, stress_xx ...
    stress_xz) the same columns; the JSON's max_displacement and
    displacement_norm over the three components of every node; the six
    faces' reactions of 3 components each."""
    run = affine(tmp_path, hexa, skew)
    f = fields(run)
    X, u, sig = f["geometry"], f["displacement"], f["stress"]
    n = len(X)
    assert f["cell_type"] == ("Hex27" if hexa else "Tet10")
    assert X.shape == (n, 3) and u.shape == (n, 3) and sig.shape == (n, 6)
    assert f["topology"].shape[1] == (27 if hexa else 10)
    assert sorted(set(f["topology"].ravel())) == list(range(n))  # every node in a cell, numbered 0..n-1
    ue = C0 + X @ G.T
    assert figure("du", np.abs(u - ue).max() / np.abs(ue).max()) <= 1e-12
    s = exact_stress(G)
    want = np.array([s[0, 0], s[1, 1], s[2, 2], s[0, 1], s[1, 2], s[0, 2]])
    assert figure("dsig", np.abs(sig - want).max() / np.abs(want).max()) <= 1e-10
    assert np.abs(f["von_mises"] - von_mises(s)).max() <= 1e-10 * von_mises(s)
    np.testing.assert_array_equal(f["displacement_xyz"], u)
    for k, name in enumerate(STRESS):
        np.testing.assert_array_equal(f[name], sig[:, k])
    assert np.isnan(f["xdmf_nan"]).all() and len(f["xdmf_nan"]) == n
    if skew == 0.0:  # the box: every node in it
        assert X.min() >= -1e-14 and X.max() <= 1 + 1e-14
    summary = run.summary
    norms = np.linalg.norm(u, axis=1)
    assert abs(summary["max_displacement"] - norms.max()) <= 1e-14 * norms.max()
    assert abs(summary["displacement_norm"] - np.sqrt(np.sum(norms ** 2))) <= 1e-13 * np.sqrt(np.sum(norms ** 2))
    assert abs(summary["bodies"]["blk"]["max_displacement"] - norms.max()) <= 1e-14 * norms.max()
    assert summary["bodies"]["blk"]["nodes"] == n
    # the reactions: 3 components a face (their balance is test_solid.py's
    # test_three_components: here the faces share their edges' nodes)
    R = np.array([summary["reactions"][f"blk:{g}"] for g in FACES])
    assert R.shape == (6, 3) and np.isfinite(R).all()
    xdmf = run.output_path.with_suffix(".xdmf").read_text()
    assert f'TopologyType="{XDMF_TYPE[f["cell_type"]]}"' in xdmf
    assert 'GeometryType="XYZ"' in xdmf and f'Dimensions="{n} 3"' in xdmf
    for name in STRESS + ("von_mises",):
        assert f'Attribute Name="{name}"' in xdmf


def corner_volumes(x, hexa):
    """The corners' signed volume as VTK orients a cell: a tetrahedron's
    det(x1 - x0, x2 - x0, x3 - x0) / 6; a hexahedron's trilinear map's
    Jacobian determinant at its 8 corners (each positive for a cell VTK
    reads right side out)."""
    if not hexa:
        return [np.linalg.det(np.array([x[1] - x[0], x[2] - x[0], x[3] - x[0]])) / 6]
    ref = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    dets = []
    for a, b, c in ref:
        J = np.zeros((3, 3))
        for n, (i, j, k) in enumerate(ref):
            wi, wj, wk = (a if i else 1 - a), (b if j else 1 - b), (c if k else 1 - c)
            J += np.outer(x[n], [(1 if i else -1) * wj * wk, wi * (1 if j else -1) * wk, wi * wj * (1 if k else -1)])
        dets.append(np.linalg.det(J))
    return dets


@pytest.mark.parametrize("hexa,skew", CASES, ids=IDS)
def test_cells_in_vtk_order(hexa, skew, tmp_path):
    """Each cell's connectivity, checked from its nodes' positions: the
    corners oriented as VTK expects (every corner tetrahedron, or the
    trilinear corner hexahedron's Jacobian at each corner, positive), each
    edge node at the midpoint of its edge's corners, a Hex27's face nodes
    at the centres of its faces' corners in VTK's face order (x = 0, x = 1,
    y = 0, y = 1, z = 0, z = 1 of the reference cube) and its last node at
    the cell's centre: on the box, where every cell's edges are straight
    and its faces plane (to 1e-12). On the distorted block, the Hex27's
    cells are trilinear too (its transfinite mesh: measured the same
    checks hold) and the Tet10's edges on the block's faces are curved, so
    there only the orientation is checked. The corners' volumes sum to the
    mesh's: the box's 1 (the Tet10's to 1e-12; a trilinear hexahedron's
    volume is not its corner determinant's mean, so the Hex27's volume is
    ParaView's test below)."""
    f = fields(affine(tmp_path, hexa, skew))
    X, T = f["geometry"], f["topology"].astype(int)
    exact_nodes = hexa or skew == 0.0
    vol = 0.0
    for cell in T:
        x = X[cell]
        dets = corner_volumes(x, hexa)
        assert min(dets) > 0, (cell, dets)
        vol += dets[0]
        if not exact_nodes:
            continue
        nc = 8 if hexa else 4
        for k, (a, b) in enumerate(HEX_EDGES if hexa else TET_EDGES):
            assert np.abs(x[nc + k] - 0.5 * (x[a] + x[b])).max() <= 1e-12, (cell, k)
        if hexa:
            for k, face in enumerate(HEX_FACES):
                assert np.abs(x[20 + k] - x[list(face)].mean(axis=0)).max() <= 1e-12, (cell, k)
            assert np.abs(x[26] - x[:8].mean(axis=0)).max() <= 1e-12
    if not hexa and skew == 0.0:
        assert abs(vol - 1.0) <= 1e-12


@pytest.mark.parametrize("hexa,skew", CASES, ids=IDS)
def test_paraview_reads_cells(hexa, skew, tmp_path, display):  # noqa: F811
    """ParaView 5.11 reads the XDMF file with each of its readers (legacy
    XDMFReader, Xdmf3ReaderS, Xdmf3ReaderT) as one grid of VTK quadratic
    tetrahedra (type 24) or triquadratic hexahedra (29), its points the
    HDF5 geometry and its arrays the HDF5 datasets bit for bit
    (displacement of 3 components, stress_xx ... stress_xz, von_mises), and
    the volume through VTK's own interpolation of each cell (the integral of
    det J from VTK's shape functions' derivatives: a node out of VTK's order
    moves the geometry; two face nodes swapped in the skewed Hex27 file gave
    0.62, two edge nodes 0.98) is the mesh's: the box's 1 and the distorted
    block's trilinear volume (block_volume; its Tet10 mesh's quadratic faces
    hold the bilinear ones exactly) to 1e-12 (measured `dvol` = 2.2e-16 to
    7.8e-16). IntegrateVariables' volume (VTK splits each Tet10 into 8
    linear tetrahedra through its edge nodes) is the box's 1 too; on the
    distorted block it differs by the split's flattening of the curved
    cells (measured `split` = 3.0e-4 relative at h = 0.5, 1.2e-5 at h =
    0.1; bound 1e-3), and for a Hex27 ParaView
    5.11 gives 0 (VTK 9.2's vtkTriQuadraticHexahedron::Triangulate returns
    2 points; so do Tessellate and Cell Size), hence the volume through
    the cell's interpolation."""
    run = affine(tmp_path, hexa, skew)
    f = fields(run)
    out = tmp_path / "pv.json"
    run_pvpython(SOLID, [run.output_path.with_suffix(".xdmf"), out, tmp_path / "view"], tmp_path, display)
    got = json.loads(out.read_text())
    want_volume = block_volume(skew)
    for reader in ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT"):
        (grid,) = got[reader]["grids"]
        assert grid["cells"] == len(f["topology"]) and grid["cell_types"] == [VTK_TYPE[f["cell_type"]]], reader
        np.testing.assert_array_equal(np.asarray(grid["points"]), f["geometry"])
        a = grid["arrays"]
        np.testing.assert_array_equal(np.asarray(a["displacement"]), f["displacement"])
        for k, name in enumerate(STRESS):
            np.testing.assert_array_equal(np.asarray(a[name]), f["stress"][:, k])
        np.testing.assert_array_equal(np.asarray(a["von_mises"]), f["von_mises"])
        assert figure("dvol", abs(grid["interpolated_volume"] / want_volume - 1)) <= 1e-12, reader
        if not hexa and skew == 0.0:
            assert abs(got[reader]["volume"] - 1.0) <= 1e-12, reader
        if not hexa and skew == 1.0:
            assert figure("split", abs(got[reader]["volume"] / want_volume - 1)) <= 1e-3, reader


@pytest.mark.parametrize("hexa", [False, True], ids=["tet10", "hex27"])
def test_paraview_renders_von_mises(hexa, tmp_path, display):  # noqa: F811
    """What a user sees: the bent box (held at xmin, xmax moved 0.1 in z)
    rendered by ParaView coloured by von Mises stress (red along the held
    faces' edges, blue in the middle of the top face: looked at) has at
    least five times the colours of the same view in one solid colour
    (measured `ratio` = 16.6 to 17.2), and the coloured view is not one
    colour: both its bluest and its reddest body pixels are there."""
    run = bend(tmp_path, hexa)
    prefix = tmp_path / "view"
    run_pvpython(SOLID, [run.output_path.with_suffix(".xdmf"), tmp_path / "pv.json", prefix], tmp_path, display)
    solid, coloured = colours(f"{prefix}-solid.png"), colours(f"{prefix}-von_mises.png")
    assert figure("ratio", coloured / solid) >= 5
    import matplotlib.image
    img = (matplotlib.image.imread(f"{prefix}-von_mises.png")[:, :, :3] * 255).round().astype(int).reshape(-1, 3)
    red = img[:, 0] - img[:, 2]
    assert red.max() > 100 and red.min() < -60  # warm and cool ends of the colour map both shown


@pytest.mark.roundoff
@pytest.mark.parametrize("hexa", [False, True], ids=["tet10", "hex27"])
def test_ranks_write_the_same(hexa, tmp_path):
    """The bent box on 1 and 2 ranks: the same nodes (matched by their
    coordinates) with the same displacement, stress and von Mises, the
    same number of cells, and each cell the same nodes. The solves stop at
    1e-14 of the gradient and the problem is linear (one Newton step):
    measured `du` = up to 2.6e-15, `dsig` = up to 9.2e-15, `dvm` = up to
    9.7e-15 of the largest; bound 1e-10. A node is matched to the other
    run's nearest: a Tet10 node's position, evaluated in one of its cells,
    moves by round-off with the partition (measured `dx` = up to 1.7e-15,
    bound 1e-12)."""
    one, two = fields(bend(tmp_path, hexa, name="one")), fields(bend(tmp_path, hexa, ranks=2, name="two"))
    X1, X2 = one["geometry"], two["geometry"]
    assert len(X1) == len(X2) and len(one["topology"]) == len(two["topology"])
    # each node of one run the nearest of the other's (docstring)
    d = np.linalg.norm(X1[:, None, :] - X2[None, :, :], axis=2)
    m = d.argmin(axis=1)
    assert sorted(m) == list(range(len(X1)))
    assert figure("dx", d[np.arange(len(X1)), m].max()) <= 1e-12
    for name, tag in (("displacement", "du"), ("stress", "dsig"), ("von_mises", "dvm")):
        a, b = one[name], two[name][m]
        assert figure(tag, np.abs(a - b).max() / np.abs(a).max()) <= 1e-10, name
    # the cells: the same, each with its nodes in the same (VTK's) order
    assert sorted(map(tuple, m[one["topology"].astype(int)])) == sorted(map(tuple, two["topology"].astype(int)))


@pytest.mark.roundoff
def test_load_stages(tmp_path):
    """-load_stages 2 on the bent Hex27 box (xmax moved 0.05, then 0.1 in
    z): /stages/1 and /stages/2 hold each stage end's fields of 3 and 6
    columns, and the XDMF file one Hexahedron_27 grid a stage; the body is
    linear, so stage 1's displacement and stress are half stage 2's (to
    1e-10 of the largest, the solves' stop 1e-14: measured `half` = 1.2e-15
    to 5.8e-15), and stage 2's are the final ones of /bodies."""
    args = block(True, 0.0, h=0.25, n=4) + ["-blk_bc", "xmin,xmax", "-blk_bc_xmax_values", "0,0,0.05,0,0,0.1",
                                            "-load_stages", "2", "-tao_gttol", "1e-14", "-tao_gatol", "1e-11"]
    run = run_contact(args, tmp_path, name="stages")
    with run.h5() as h5:
        s1, s2, fin = (h5[p]["blk"] for p in ("stages/1/bodies", "stages/2/bodies", "bodies"))
        for name, cols in (("displacement", 3), ("stress", 6)):
            a, b = s1[name][...], s2[name][...]
            assert a.shape[1] == cols and b.shape == a.shape
            assert figure("half", np.abs(2 * a - b).max() / np.abs(b).max()) <= 1e-10, name
            np.testing.assert_array_equal(b, fin[name][...])
    assert run.output_path.with_suffix(".xdmf").read_text().count('TopologyType="Hexahedron_27"') == 2


def test_json_loads(tmp_path):
    """A traction (0.3, -0.2, 1) per unit area on the box's zmax face (area
    1), held at zmin: the JSON's loads give its resultant with its three
    components (to 1e-12), and the zmin reaction balances it (to 1e-10,
    the stop's: the only other force)."""
    args = block(True, 0.0) + ["-blk_bc", "zmin", "-blk_load", "zmax", "-blk_load_zmax_traction", "0.3,-0.2,1",
                               "-tao_gttol", "1e-14", "-tao_gatol", "1e-11"]
    s = run_contact(args, tmp_path, name="loads").summary
    F = np.array(s["loads"]["blk:zmax"])
    assert F.shape == (3,) and np.abs(F - [0.3, -0.2, 1.0]).max() <= 1e-12
    assert np.abs(np.array(s["reactions"]["blk:zmin"]) + F).max() <= 1e-10


def test_plot_field_says_paraview(tmp_path):
    """scripts/plot_hertz.py on a 3D file: --field says in one line to open
    the XDMF file in ParaView (status 0, nothing written), and the pressure
    plot says the file has no contact pairs (status 0)."""
    run = affine(tmp_path, True, 0.0)
    png = tmp_path / "field.png"
    plot = [sys.executable, str(ROOT / "scripts" / "plot_hertz.py"), str(run.output_path)]
    res = subprocess.run(plot + ["--field", "-o", str(png)], capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    lines = (res.stdout + res.stderr).strip().splitlines()
    assert len(lines) == 1 and "ParaView" in lines[0] and str(run.output_path.with_suffix(".xdmf")) in lines[0], lines
    assert not png.exists()
    res = subprocess.run(plot + ["-o", str(png)], capture_output=True, text=True)
    assert res.returncode == 0 and "no contact pairs" in res.stdout and not png.exists()
    assert not re.search(r"contact force|penetration|Hertz", run.stdout)
