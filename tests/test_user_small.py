"""Smaller things a new user met (issue 47, item 10): options -help did not
list, a load history's order of values, the r-z plot of a ring, a master's
unpaired nodes, the progress line after a failed solve, the strain warning's
advice at a contact's edge, a 3D .geo, and `make run`'s demo."""
import re
import sys
import subprocess
from pathlib import Path

import numpy as np
import pytest

from conftest import BIN, ENV, ROOT, figure, run_contact
import hertz


def run_bin(args, cwd, ranks=1):
    cmd = [str(BIN)] + [str(a) for a in args]
    if ranks > 1:
        cmd = ["mpiexec", "--oversubscribe", "-n", str(ranks)] + cmd
    return subprocess.run(cmd, cwd=cwd, env=ENV, capture_output=True, text=True, timeout=600)


def option_line(out, name):
    lines = [l.strip() for l in out.splitlines() if l.strip().startswith(name + " ")]
    assert len(lines) == 1, f"{name} listed {len(lines)} times"
    return lines[0]


def options_table(doc):
    """The options docs/scenes.md tables: the first word of each row's first cell."""
    names = set()
    for line in (ROOT / doc).read_text().splitlines():
        m = re.match(r"\| `(-[a-z_<>]+)", line)
        if m:
            names.add(m.group(1))
    return names


SQUARES = ["-bodies", "a,b", "-a_geo", ROOT / "meshes/square/square.geo", "-b_geo", ROOT / "meshes/square/square.geo"]


@pytest.mark.parametrize("scene", [[], ["-contact_formulation", "gpts"], ["-contact_formulation", "mortar"]])
def test_help_lists_mortar_options(scene, tmp_path):
    """-help lists -contact_mortar_slave and -contact_mortar_basis once, with
    their defaults (auto, dual), without a scene and whatever the scene's
    formulation (they were listed only once a mortar pair was created); and
    docs/scenes.md tables both."""
    args = []
    if scene:
        args = SQUARES + ["-contact_pairs", "p", "-contact_p_surfaces", "a:boundary,b:boundary"] + scene
    proc = run_bin(args + ["-help"], tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert option_line(proc.stdout, "-contact_mortar_slave").startswith("-contact_mortar_slave <now auto : formerly auto>")
    assert option_line(proc.stdout, "-contact_mortar_basis").startswith("-contact_mortar_basis <now dual : formerly dual>")
    assert {"-contact_mortar_slave", "-contact_mortar_basis"} <= options_table("docs/scenes.md")
    assert not list(tmp_path.iterdir())


PLATE = ROOT / "tests/meshes/plate.geo"


def test_load_stages_stage_major(tmp_path):
    """-load_stages S: the values are stage-major (x1,y1,x2,y2), as -help's
    text and docs/scenes.md say. A plate held at its bottom, its top moved
    by (0.01, 0) at stage 1's end and (0, -0.02) at stage 2's
    (-a_bc_top_values 0.01,0,0,-0.02): each stage's top displacement, read
    from the HDF5's /stages, is that stage's pair (to 1e-12 of the values:
    imposed, not solved for)."""
    proc = run_bin(["-help", "-bodies", "a", "-a_geo", PLATE], tmp_path)
    for name in ("-load_stages", "-a_bc_<group>_values"):
        assert "stage-major" in option_line(proc.stdout, name) and "x1,y1,x2,y2" in option_line(proc.stdout, name)
    assert "tx1,ty1,tx2,ty2" in option_line(proc.stdout, "-a_load_<group>_traction")
    assert "stage-major" in (ROOT / "docs/scenes.md").read_text()
    r = run_contact(["-bodies", "a", "-a_geo", PLATE, "-a_geo_params", "quads=1", "-a_mesh_size", "0.25",
                     "-a_E", 1, "-a_nu", 0.3, "-a_bc", "bottom,top", "-load_stages", 2,
                     "-a_bc_top_values", "0.01,0,0,-0.02", "-mesh_dir", tmp_path / "m"], tmp_path)
    with r.h5() as f:
        X = f["bodies/a/geometry"][:]
        top = abs(X[:, 1] - 1.0) < 1e-12
        assert top.sum() >= 3
        for k, want in ((1, (0.01, 0.0)), (2, (0.0, -0.02))):
            u = f[f"stages/{k}/bodies/a/displacement"][:]
            for c in range(2):
                assert abs(u[top, c] - want[c]).max() < 1e-12, (k, c, u[top])


# A ring of round section (radius RHO about the circle r = RC) pressed on a
# flat seat, axisymmetric: its contact is a band about r = RC, far from the
# axis (tests/meshes/ring.geo, seat.geo; h = 0.005 at the contact)
RC, RHO, H_RING = 11.2, 0.6, 0.005
RING = ["-axisymmetric", "-bodies", "ring,seat",
        "-ring_geo", ROOT / "tests/meshes/ring.geo", "-ring_geo_params", f"rc={RC},rho={RHO}",
        "-ring_mesh_size", H_RING, "-ring_E", 1000, "-ring_nu", 0.3,
        "-ring_bc", "top", "-ring_bc_top_components", "y", "-ring_bc_top_values", -0.02,
        "-seat_geo", ROOT / "tests/meshes/seat.geo", "-seat_geo_params", f"rc={RC}",
        "-seat_mesh_size", H_RING, "-seat_E", 1000, "-seat_nu", 0.3,
        "-seat_bc", "bottom", "-seat_bc_bottom_components", "y",
        "-contact_pairs", "seat", "-contact_seat_surfaces", "ring:contact,seat:top"]


@pytest.fixture(scope="module")
def ring(tmp_path_factory):
    d = tmp_path_factory.mktemp("ring")
    return {n: run_contact(RING + ["-mesh_dir", d / "m"], d, ranks=n, name=f"ring{n}") for n in (1, 2)}


def test_ring_contact_zone(ring):
    """A ring's contact zone: the report, the JSON and the HDF5 give its
    extent [r1, r2] and width (fem_a, a disc's radius, is here the outer end
    and fem_a_moment a radius about the axis: neither is the band's size).
    The band's width against plane-strain Hertz's 2b of a cylinder of radius
    RHO on a flat (b^2 = 4 P' RHO / (pi E*), P' = P / (2 pi RC) the load per
    unit length of the circle; the ring's hoop curvature changes it by about
    b/RC, 0.8 %): `ring_zone_width_vs_hertz` = -0.0148, bound 4 % (the zone's
    ends are interpolated from the nodal gaps, h = 0.005 against b = 0.088).
    Its middle is RC to `ring_zone_centre_offset` = 1.1e-06, bound h."""
    r = ring[1]
    s, c = r.summary, r.summary["contact"]["seat"]
    r1, r2 = c["zone"]
    assert c["zone_width"] == pytest.approx(r2 - r1, rel=1e-12)
    assert s["zone"] == c["zone"] and s["zone_width"] == c["zone_width"]
    slave = [x for x in c["surfaces"] if x["slave"]][0]
    assert slave["zone"] == c["zone"]
    assert r1 > RC - RHO and r2 < RC + RHO   # a band, not a disc about the axis
    b, _ = hertz.line(c["P"] / (2 * np.pi * RC), hertz.plane_strain_modulus(1000, 0.3, 1000, 0.3), RHO)
    e = figure("ring_zone_width_vs_hertz", (r2 - r1) / (2 * b) - 1)
    assert abs(e) < 0.04, (r1, r2, b)
    assert figure("ring_zone_centre_offset", abs((r1 + r2) / 2 - RC)) < H_RING
    m = re.search(r"pressure on ring:contact.*\n\s+contact zone: reference r in \[(\S+), (\S+)\], width (\S+)", r.stdout)
    assert m, r.stdout
    assert [float(m.group(k)) for k in (1, 2, 3)] == pytest.approx([r1, r2, r2 - r1], rel=1e-5)
    with r.h5() as f:
        g = f["contact/seat"]
        assert (float(g.attrs["zone_start"]), float(g.attrs["zone_end"])) == (r1, r2)
        assert float(f["contact/seat/ring_contact"].attrs["zone_start"]) == r1


@pytest.mark.roundoff
@pytest.mark.kernels
def test_ring_contact_zone_ranks(ring):
    """On 2 ranks the ring's zone (gathered on rank 0, broadcast for the HDF5's
    attributes) is the 1-rank one: `ring_zone_ranks` = 1.0e-14 to 4.1e-14
    of the width (OpenBLAS Prescott, the default kernel), bound 1e-6 (the
    zone's ends are interpolated from the nodal gaps, which two runs stopped
    by the same test leave within the stop's tolerance of each other)."""
    z1, z2 = (ring[n].summary["contact"]["seat"]["zone"] for n in (1, 2))
    d = figure("ring_zone_ranks", np.abs(np.subtract(z2, z1)).max() / (z1[1] - z1[0]))
    assert d < 1e-6, (z1, z2)
    with ring[2].h5() as f:
        assert (float(f["contact/seat"].attrs["zone_start"]), float(f["contact/seat"].attrs["zone_end"])) == tuple(z2)


def plot_module():
    import importlib.util
    spec = importlib.util.spec_from_file_location("plot_hertz", ROOT / "scripts/plot_hertz.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.parametrize("zoom", [None, 3.0, (11.0, 11.25, -0.2, 0.2)])
def test_ring_pressure_plot_range(ring, zoom, tmp_path):
    """The r-z pressure plot of a ring spans its loaded radii (current, p above
    1e-3 of its peak) enlarged 1.5 times about their middle, F times with
    --zoom F, or the radii inside a --zoom window (it spanned 0 to 1.5 fem_a,
    the ring 17 times its zone's width, and ignored --zoom); the box names the
    zone. The command writes the PNG with each."""
    import h5py
    import matplotlib.pyplot as plt
    mod = plot_module()
    h5 = ring[1].output_path
    fig, ax = plt.subplots()
    with h5py.File(h5, "r") as f:
        mod.plot_pressure(f, [ax], mod.parse_units("none"), zoom)
        g = f["contact/seat"]
        r, p = [], []
        for side in ("ring_contact", "seat_top"):
            r.append(g[side]["node_x"][:, 0])
            p.append(g[side]["node_pressure"][:])
        r, p = np.concatenate(r), np.concatenate(p)
        x = np.concatenate([g[side]["node_x"][:] for side in ("ring_contact", "seat_top")])
    if isinstance(zoom, tuple):
        inside = (x[:, 0] >= zoom[0]) & (x[:, 0] <= zoom[1]) & (x[:, 1] >= zoom[2]) & (x[:, 1] <= zoom[3])
        want = (r[inside].min(), r[inside].max())
    else:
        on = r[p > 1e-3 * p.max()]
        mid, half, F = (on.min() + on.max()) / 2, (on.max() - on.min()) / 2, zoom or 1.5
        want = (mid - F * half, mid + F * half)
    assert ax.get_xlim() == pytest.approx(want, rel=1e-12)
    assert "contact zone: reference r in" in "\n".join(t.get_text() for t in ax.texts)
    plt.close(fig)
    args = [] if zoom is None else ["--zoom", str(zoom) if not isinstance(zoom, tuple) else ",".join(map(str, zoom))]
    out = tmp_path / "ring.png"
    proc = subprocess.run([sys.executable, ROOT / "scripts/plot_hertz.py", h5, *args, "-o", out], capture_output=True, text=True)
    assert proc.returncode == 0 and out.exists(), proc.stderr


# A short flat punch (width 0.5) pressed on a long block (width 2): the
# punch's bottom ends on the block's top, so most of the block's top faces
# nothing (tests/meshes/plate.geo for both)
PUNCH_ON_BLOCK = ["-bodies", "punch,block",
                  "-punch_geo", PLATE, "-punch_geo_params", "x0=-0.25,y0=0,L=0.5,H=0.3", "-punch_mesh_size", 0.05,
                  "-punch_E", 1000, "-punch_nu", 0.3, "-punch_bc", "top", "-punch_bc_top_values", "0,-0.002",
                  "-block_geo", PLATE, "-block_geo_params", "x0=-1,y0=-1,L=2,H=1", "-block_mesh_size", 0.1,
                  "-block_E", 1000, "-block_nu", 0.3, "-block_bc", "bottom",
                  "-contact_pairs", "tool", "-contact_tool_surfaces", "punch:bottom,block:top"]


def huge_numbers(obj):
    """Every number in a JSON document above 1e300 in magnitude."""
    if isinstance(obj, dict):
        return [x for v in obj.values() for x in huge_numbers(v)]
    if isinstance(obj, list):
        return [x for v in obj for x in huge_numbers(v)]
    return [obj] if isinstance(obj, float) and abs(obj) > 1e300 else []


@pytest.mark.parametrize("formulation, ranks", [("mortar", 1), ("mortar", 2), ("gpts", 1)])
def test_unpaired_gap(formulation, ranks, tmp_path):
    """A sample that nothing faces has no gap: the report's table prints
    "unpaired" (it printed 4.4942e+307, PETSc's PETSC_INFINITY, the largest
    real over 4, a finite number), the HDF5's gap is NaN there, and no
    number above 1e300 is left in the report, the JSON or any HDF5 gap. With
    mortar, the block's (the master's) nodes further than an edge (h = 0.1)
    from the punch's ends have no gap, those under the punch (within 0.25 - h
    of its middle) have one."""
    r = run_contact(PUNCH_ON_BLOCK + ["-contact_formulation", formulation, "-mesh_dir", tmp_path / "m"],
                    tmp_path, ranks=ranks)
    assert not re.search(r"e\+30[0-9]", r.stdout), r.stdout
    assert "unpaired" in r.stdout
    assert not huge_numbers(r.summary)
    with r.h5() as f:
        g = f["contact/tool"]
        for side in g.values():
            for k in ("gap", "node_gap"):
                if k in side:
                    v = side[k][...]
                    assert not np.any(np.abs(v[np.isfinite(v)]) > 1e300), (side.name, k)
        if formulation == "mortar":
            m = g["block_top"]
            assert m.attrs["slave"] == 0
            x, gap = m["node_X"][:, 0], m["node_gap"][...]
            assert np.all(np.isnan(gap[np.abs(x) > 0.25 + 0.1]))
            assert np.all(np.isfinite(gap[np.abs(x) < 0.25 - 0.1]))
            assert np.isnan(gap).sum() >= 20


def test_progress_after_failed_solve(tmp_path):
    """The progress line says "post-processing the converged state" only after
    a solve that converged; after one that did not (a Newton iteration
    allowed, no cutback) it says the last iterate is post-processed and
    nothing will be written, and the run exits 2 with nothing written."""
    base = PUNCH_ON_BLOCK + ["-mesh_dir", tmp_path / "m", "-progress"]
    ok = run_contact(base, tmp_path, name="ok")
    assert "post-processing the converged state" in ok.stderr and "last iterate" not in ok.stderr
    bad = run_contact(base + ["-tao_max_it", 1, "-load_cutbacks", 0], tmp_path, name="bad", check=False)
    assert bad.returncode == 2, bad.stderr[-2000:]
    assert "converged state" not in bad.stderr, bad.stderr
    assert "post-processing the last iterate (the solve did not converge: nothing will be written)" in bad.stderr
    assert not bad.summary_path.exists() and not bad.output_path.exists()


# A rigid flat punch (half-width 0.25) pressed 0.008 into a block (E 1000)
# meshed at h = 0.01 within 0.35 of the middle of its top (tests/meshes/seat.geo)
RIGID_PUNCH = ["-bodies", "punch,block",
               "-punch_geo", PLATE, "-punch_geo_params", "x0=-0.25,y0=0,L=0.5,H=0.3", "-punch_mesh_size", 0.05,
               "-punch_rigid", "-punch_bc", "top", "-punch_bc_top_values", "0,-0.008",
               "-block_geo", ROOT / "tests/meshes/seat.geo", "-block_geo_params", "x0=-1,L=2,H=1,rc=0,dp=0.35,hfar=0.2",
               "-block_mesh_size", 0.01, "-block_E", 1000, "-block_nu", 0.3, "-block_bc", "bottom",
               "-contact_pairs", "tool", "-contact_tool_surfaces", "punch:bottom,block:top"]


def test_strain_warning_at_punch_edge(tmp_path):
    """The strain under a flat punch's edge is a singular point's (it grows as
    the mesh is refined there: 3.97, 5.15, 5.46 % at h = 0.02, 0.01, 0.005;
    here `punch_edge_strain_percent` = 5.15):
    the warning says it is concentrated there and does not advise a
    neo-Hookean material, which would not remove it. The peak it names lies
    at the punch's edge (|x| within 0.02 of 0.25, just under the surface).
    A plate compressed uniformly by 3 % (rollers on its bottom and left
    side) gets the neo-Hookean advice."""
    r = run_contact(RIGID_PUNCH + ["-mesh_dir", tmp_path / "m"], tmp_path)
    lines = [l for l in r.stdout.splitlines() if "warning: body block" in l]
    assert len(lines) == 1, r.stdout
    assert "neohookean models" not in lines[0] and "would not remove it" in lines[0], lines[0]
    m = re.search(r"its largest strain, (\S+) %, is concentrated at \((\S+), (\S+)\)", lines[0])
    assert m, lines[0]
    x, y = float(m.group(2)), float(m.group(3))
    figure("punch_edge_strain_percent", float(m.group(1)))
    assert abs(abs(x) - 0.25) < 0.02 and -0.02 < y <= 0, (x, y)
    u = run_contact(["-bodies", "a", "-a_geo", PLATE, "-a_geo_params", "quads=1", "-a_mesh_size", 0.25,
                     "-a_E", 1000, "-a_nu", 0.3, "-a_bc", "bottom,left,top",
                     "-a_bc_bottom_components", "y", "-a_bc_left_components", "x",
                     "-a_bc_top_components", "y", "-a_bc_top_values", -0.03, "-mesh_dir", tmp_path / "m"], tmp_path, name="plate")
    assert "warning: body a is linear at a strain of" in u.stdout and "-a_material neohookean models it" in u.stdout, u.stdout


BOX = """// a unit cube: the square extruded along z
If (!Exists(h)) h = 0.25; EndIf
Point(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h}; Point(3) = {1, 1, 0, h}; Point(4) = {0, 1, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
out[] = Extrude {0, 0, 1} { Surface{1}; };
Mesh.ElementOrder = 2;
"""
GROUPS_3D = {
    # a volume and its bottom face as groups, as a 3D scene declares them
    "volume": 'Physical Surface("base") = {1};\nPhysical Volume("body") = {out[1]};\n',
    # no volume group, but a face off the plane z = 0 as the body and one of its edges as a curve
    "top face": 'Physical Surface("body") = {out[0]};\nPhysical Curve("base") = {Boundary{Surface{out[0]};}};\n',
}


@pytest.mark.parametrize("ranks", [1, 2])
@pytest.mark.parametrize("groups", list(GROUPS_3D))
def test_3d_geo(groups, ranks, tmp_path):
    """A 3D .geo (a cube): with its volume a physical group it is a 3D body
    (Tet10), held at its base and solved (status 0); with a face off the
    plane z = 0 as its body and no volume it is refused in one line naming
    the body, the mesh file and what is wrong (a node off the plane z = 0
    and no 3D element): status 1, nothing written."""
    geo = tmp_path / "cube.geo"
    geo.write_text(BOX + GROUPS_3D[groups])
    r = run_contact(["-bodies", "a", "-a_geo", geo, "-a_E", 1000, "-a_nu", 0.3, "-a_bc", "base",
                     "-mesh_dir", tmp_path / "m"], tmp_path, ranks=ranks, check=False)
    if groups == "volume":
        assert r.returncode == 0, r.stderr
        assert r.summary["bodies"]["a"]["cell_type"] == "Tet10"
        return
    assert r.returncode == 1, r.stderr
    lines = [l for l in r.stderr.splitlines() if l.startswith("contact:")]   # (mpiexec adds its own lines)
    assert len(lines) == 1, r.stderr
    assert lines[0].startswith("contact: error: body a: mesh ") and "cube" in lines[0], lines[0]
    assert "off the plane z = 0, and no 3D element" in lines[0] and "a 3D body's .geo has a Volume" in lines[0], lines[0]
    assert not r.summary_path.exists() and not r.output_path.exists()


def test_shear_plot_skipped_quietly(tmp_path):
    """plot_hertz.py --shear --quiet on a file without friction writes nothing
    and says nothing, status 0 (make run's way); without --quiet it says the
    plot is skipped."""
    r = run_contact(PUNCH_ON_BLOCK + ["-mesh_dir", tmp_path / "m"], tmp_path)
    out = tmp_path / "shear.png"
    for extra, said in ((["--quiet"], False), ([], True)):
        p = subprocess.run([sys.executable, ROOT / "scripts/plot_hertz.py", r.output_path, "--shear", *extra, "-o", out],
                           capture_output=True, text=True)
        assert p.returncode == 0 and not out.exists(), p.stderr
        assert ("shear plot skipped" in p.stdout) == said and not p.stderr, p.stdout


@pytest.mark.skipif(not (ROOT / "build/.deps-installed").exists(), reason="make run would install dependencies first")
def test_make_run_demo_clean():
    """`make run` (the demo of the README, on its reference scene): no "shear
    plot skipped" line for the frictionless scene, and each strain warning's
    advice holds: the disc's 13 % is a singular point's, at the end of its
    clamp (x < -1.8), so no neo-Hookean advice; the block's 7.45 % under the
    contact, a smooth field's, keeps it (the README's model table measures
    neo-Hookean's P 1.4 % from the linear one's at this push)."""
    proc = subprocess.run(["make", "--no-print-directory", "run", "SCENE=hertz"], cwd=ROOT, env=ENV,
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    assert "skipped" not in proc.stdout + proc.stderr
    disc = [l for l in proc.stdout.splitlines() if "warning: body indenter" in l]
    block = [l for l in proc.stdout.splitlines() if "warning: body block" in l]
    assert len(disc) == 1 and "neohookean models" not in disc[0] and "concentrated at" in disc[0], disc
    x = float(re.search(r"concentrated at \((\S+),", disc[0]).group(1))
    assert -1.85 < x < -1.7, disc[0]
    assert len(block) == 1 and "-block_material neohookean models it" in block[0], block
