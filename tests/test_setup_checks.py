"""Set-ups checked before solving (src/body/conditions.c, and the group lists
read in src/body/body.c): each check gives one line before any solve.

Refused, status 1, one line `contact: error: ...` naming the body and the
groups, and nothing written (the output and summary paths hold sentinel files
that must come out unchanged, and nothing else may appear beside them):
- a force-controlled group's node that another condition holds in the
  controlled component;
- a load acting at a node in a component that a force control holds;
- a group named twice in -<body>_bc, before anything is meshed.
Warned, one line `contact: warning: ...`, and the run goes on: a load whose
part in a component acts only at nodes held in that component; bodies that
overlap before any load (the reference scene's disc moved into the block).

Beside each check, its valid neighbour runs with nothing on stderr, and its
answer is checked against a solution that does not come from the program:
the plate [0, 2] x [0, 1] (tests/meshes/plate.geo, Quad9, h = 0.25, E = 1000,
nu = 0.3) on rollers under uniform stresses sigma_xx = sx, sigma_yy = sy,
whose displacement is linear (held exactly by Q2): in plane strain
eps_yy = ((1 - nu^2) sy - nu (1 + nu) sx) / E and
eps_xx = ((1 - nu^2) sx - nu (1 + nu) sy) / E."""
import os
import subprocess
import time

import numpy as np
import pytest

from conftest import BIN, ENV, ROOT, run_contact

E, NU, L, H = 1000.0, 0.3, 2.0, 1.0
SENTINEL = "earlier result\n"


def plate(*extra, axisymmetric=False):
    return (["-scene", "plate", "-bodies", "plate", "-plate_geo", "tests/meshes/plate.geo",
             "-plate_geo_params", f"L={L},H={H},quads=1", "-plate_mesh_size", "0.25", "-plate_E", E, "-plate_nu", NU]
            + (["-axisymmetric"] if axisymmetric else []) + list(extra))


# rollers: the bottom held in y, the left in x
ROLLERS = ["-plate_bc_bottom_components", "y", "-plate_bc_left_components", "x"]
# the top held in y by a force control of F = -20, p = 10 over its length 2
TOP_FORCE = ["-plate_bc_top_components", "y", "-plate_bc_top_control", "force", "-plate_bc_top_values", "-20"]
P = 10.0


def refused(args, tmp_path, ranks=1):
    """Runs a set-up that must be refused: status 1, the error lines, the
    outputs untouched and no mesh directory if meshed is False. Returns the
    non-empty stderr lines (the program's, not mpiexec's) and the time taken."""
    run = tmp_path / "run"
    run.mkdir()
    outputs = {run / f: SENTINEL for f in ("out.h5", "out.xdmf", "out.json")}
    for p, text in outputs.items():
        p.write_text(text)
    cmd = [str(BIN)] + [str(a) for a in args] + ["-output", str(run / "out.h5"), "-summary", str(run / "out.json"),
                                                 "-mesh_dir", str(tmp_path / "meshes")]
    if ranks > 1:
        cmd = ["mpiexec", "--oversubscribe", "-n", str(ranks)] + cmd
    t0 = time.monotonic()
    proc = subprocess.run(cmd, cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=120)
    seconds = time.monotonic() - t0
    assert proc.returncode == 1, f"exit {proc.returncode}\n{proc.stdout[-2000:]}\n{proc.stderr[-2000:]}"
    lines = [ln for ln in proc.stderr.splitlines() if ln.strip()]
    if ranks > 1:  # mpiexec's own report of the exit status follows
        lines = [ln for ln in lines if ln.startswith("contact: ")]
        assert "PETSC ERROR" not in proc.stderr
    for p, text in outputs.items():
        assert p.read_text() == text, f"{p.name} was overwritten"
    assert sorted(os.listdir(run)) == sorted(p.name for p in outputs), os.listdir(run)
    return lines, seconds


def one_error(lines, *names):
    assert len(lines) == 1 and lines[0].startswith("contact: error: "), lines
    for n in names:
        assert n in lines[0], f"{lines[0]!r} does not name {n!r}"
    return lines[0]


@pytest.mark.parametrize("ranks", [1, 2])
def test_force_control_shares_a_node(ranks, tmp_path):
    """The top force-controlled in y, the left clamped (x and y): their corner
    (0, 1) is held in y by both."""
    args = plate("-plate_bc", "bottom,left,top", "-plate_bc_bottom_components", "y", *TOP_FORCE)
    lines, _ = refused(args, tmp_path, ranks=ranks)
    one_error(lines, "body plate: group top, force-controlled in y, shares the node at (0., 1.) with group left",
              "which holds it in y too")


def test_force_control_shares_a_node_hertz(tmp_path):
    """The issue's case: the reference scene's push force-controlled in x, its
    corner (1, -1) shared with a clamped bottom (it ran with status 0, the
    bottom taking most of the force)."""
    args = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.3", "-block_bc", "push,bottom",
            "-block_bc_push_control", "force,displacement", "-block_bc_push_values", "-55,0"]
    lines, _ = refused(args, tmp_path)
    one_error(lines, "body block: group push, force-controlled in x, shares the node at (1., -1.) with group bottom")


def test_force_control_beside_other_component(tmp_path):
    """Neighbour: the left holds only x, so the corner (0, 1) is held in x by
    the left and in y by the top's force control: accepted, no line on
    stderr. The plate is under sigma_yy = -p (sx = 0), so the top moves by
    U = -(1 - nu^2) p H / E = -0.0091; measured to 1.0e-15 of it (the exact
    state is in the Q2 space), bound 1e-8 (-force_control_rtol 1e-9 on the
    reaction)."""
    r = run_contact(plate("-plate_bc", "bottom,left,top", *ROLLERS, *TOP_FORCE, "-output", "none"), tmp_path)
    (fc,) = r.summary["force_control"]
    exact = -(1 - NU**2) * P * H / E
    print(f"U = {fc['displacement']!r} against {exact!r}: {abs(fc['displacement'] / exact - 1):.1e}")
    assert not r.stderr.strip(), r.stderr
    assert (fc["group"], fc["component"]) == ("top", "y")
    assert abs(fc["displacement"] / exact - 1) <= 1e-8


def test_force_control_axis_other_component(tmp_path):
    """Neighbour in r-z: the plate as a cylinder r <= 2 on the axis, its top
    force-controlled in z; the axis's u_r = 0 (r=0) holds the top's node on
    the axis in r only: accepted, no line. Uniaxial stress sigma_zz = -p:
    the top moves by -p H / E = -0.01 under the force -p pi R^2; measured to
    4.4e-16 of it, bound 1e-8."""
    force = -P * np.pi * L**2
    r = run_contact(plate("-plate_bc", "bottom,top", "-plate_bc_bottom_components", "y", "-plate_bc_top_components", "y",
                          "-plate_bc_top_control", "force", "-plate_bc_top_values", repr(force), "-output", "none",
                          axisymmetric=True), tmp_path)
    (fc,) = r.summary["force_control"]
    exact = -P * H / E
    print(f"U = {fc['displacement']!r} against {exact!r}: {abs(fc['displacement'] / exact - 1):.1e}")
    assert not r.stderr.strip(), r.stderr
    assert abs(fc["displacement"] / exact - 1) <= 1e-8


def test_load_on_force_controlled_node(tmp_path):
    """A traction in y on the right, whose corner (2, 1) the top's force
    control holds in y."""
    args = plate("-plate_bc", "bottom,left,top", *ROLLERS, *TOP_FORCE, "-plate_load", "right",
                 "-plate_load_right_traction", "0,1")
    lines, _ = refused(args, tmp_path)
    one_error(lines, "body plate: the load on group right acts in y at the node (2., 1.), which group top holds by its force control in y")


def test_load_beside_force_control(tmp_path):
    """Neighbour: a traction (1, 0) on the right acts in x at the corner that
    the top holds in y only: accepted, no line. Uniform state sx = 1, sy =
    -p: the top moves by eps_yy H = -0.00949; measured to 1.1e-15 of it, bound
    1e-8."""
    r = run_contact(plate("-plate_bc", "bottom,left,top", *ROLLERS, *TOP_FORCE, "-plate_load", "right",
                          "-plate_load_right_traction", "1,0", "-output", "none"), tmp_path)
    (fc,) = r.summary["force_control"]
    exact = ((1 - NU**2) * -P - NU * (1 + NU) * 1.0) / E * H
    print(f"U = {fc['displacement']!r} against {exact!r}: {abs(fc['displacement'] / exact - 1):.1e}")
    assert not r.stderr.strip(), r.stderr
    assert abs(fc["displacement"] / exact - 1) <= 1e-8


def test_bc_group_twice(tmp_path):
    """A group named twice in -<body>_bc: refused while the options are read,
    before anything is meshed (no mesh directory appears)."""
    lines, seconds = refused(plate("-plate_bc", "bottom,left,bottom", *ROLLERS), tmp_path)
    print(f"refused in {seconds:.2f} s")
    one_error(lines, "option -plate_bc: group bottom given twice")
    assert not (tmp_path / "meshes").exists(), "refused only after meshing"


def test_bc_group_twice_hertz(tmp_path):
    """The same in a scene with contact, on the block's only condition."""
    lines, seconds = refused(["-options_file", "meshes/hertz/hertz.opts", "-block_bc", "push,push"], tmp_path)
    print(f"refused in {seconds:.2f} s")
    one_error(lines, "option -block_bc: group push given twice")
    assert not (tmp_path / "meshes").exists(), "refused only after meshing"


def nodal_error(r, sx, sy):
    """The largest nodal error of u against the uniform state (sx, sy) with
    u_x = 0 on the left and u_y = 0 on the bottom, relative to max |u|."""
    with r.h5() as f:
        X, u = f["bodies/plate/geometry"][...], f["bodies/plate/displacement"][...]
    exx = ((1 - NU**2) * sx - NU * (1 + NU) * sy) / E
    eyy = ((1 - NU**2) * sy - NU * (1 + NU) * sx) / E
    exact = np.stack([exx * X[:, 0], eyy * X[:, 1]], 1)
    return np.max(np.abs(u - exact)) / np.max(np.abs(exact))


def test_load_on_held_group_warns(tmp_path):
    """A traction (0, -p) on the top, which is held in y (by u_y = -0.0091,
    the displacement of the uniform sigma_yy = -p): one warning line naming
    the body, the group and the component; the run solves (status 0) and the
    load moves nothing: every nodal displacement is the uniform state's
    (measured 5.0e-15 of max |u|, bound 1e-12), the bottom's reaction p L
    (measured to 1.2e-15, bound 1e-12), and the top's reaction, the elastic
    force minus the load's resultant, zero (measured 2.2e-15 of p L, bound
    1e-12)."""
    uy = -(1 - NU**2) * P * H / E
    r = run_contact(plate("-plate_bc", "bottom,left,top", *ROLLERS, "-plate_bc_top_components", "y",
                          "-plate_bc_top_values", repr(uy), "-plate_load", "top", "-plate_load_top_traction", f"0,{-P}"),
                    tmp_path)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("contact: warning: body plate: "), lines
    assert "the load on group top acts in y is held in y (by top): the load moves nothing" in lines[0], lines[0]
    s = r.summary
    err = nodal_error(r, 0.0, -P)
    print(f"nodal error {err:.1e}; reactions {s['reactions']}")
    assert err < 1e-12
    assert abs(s["reactions"]["plate:bottom"][1] - P * L) < 1e-12 * P * L
    assert abs(s["reactions"]["plate:top"][1]) < 1e-12 * P * L


def test_load_part_on_held_group_warns(tmp_path):
    """A traction (1, -p) on the same top, held in y only: its y part moves
    nothing (the warning says so), its x part acts; the run solves, and the
    left's reaction balances the x part, -1 times L (measured to 7.7e-15,
    bound 1e-12)."""
    r = run_contact(plate("-plate_bc", "bottom,left,top", *ROLLERS, "-plate_bc_top_components", "y",
                          "-plate_load", "top", "-plate_load_top_traction", f"1,{-P}", "-output", "none"), tmp_path)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("contact: warning: body plate: "), lines
    assert "group top acts in y is held in y (by top): its y part moves nothing" in lines[0], lines[0]
    print(f"reactions {r.summary['reactions']}")
    assert abs(r.summary["reactions"]["plate:left"][0] + L) < 1e-12 * L


@pytest.mark.parametrize("held", ["x", "none"])
def test_load_on_group_held_in_other_component(held, tmp_path):
    """Neighbour: the traction (0, -p) on a top held only in x (or free, its
    corner (0, 1) held in x by the left): no line, and the load acts: the
    bottom, the only support in y, carries p L (measured to 1e-15, bound
    1e-12); free, the state is the uniform one (as in test_loads)."""
    bcs = ["-plate_bc", "bottom,left,top", "-plate_bc_top_components", "x"] if held == "x" else ["-plate_bc", "bottom,left"]
    r = run_contact(plate(*bcs, *ROLLERS, "-plate_load", "top", "-plate_load_top_traction", f"0,{-P}"), tmp_path)
    print(f"reactions {r.summary['reactions']}" + (f"; nodal error {nodal_error(r, 0.0, -P):.1e}" if held == "none" else ""))
    assert not r.stderr.strip(), r.stderr
    assert abs(r.summary["reactions"]["plate:bottom"][1] - P * L) < 1e-12 * P * L
    if held == "none":
        assert nodal_error(r, 0.0, -P) < 1e-12


def hertz_moved(xc, *extra):
    """The reference scene (h = 0.1) with the disc's centre at (xc, 0): its
    arc reaches x = xc + 1, past the block's face x = 0 by 1 + xc."""
    return ["-options_file", "meshes/hertz/hertz.opts",
            "-indenter_geo_params", f"R=1,xc={xc},yc=0,xclamp=-1.8,xcontact=-0.5", *extra]


@pytest.mark.parametrize("xc,order", [(-0.99, "indenter"), (-0.9, "indenter"), (-0.9, "block")])
def test_overlap_at_start_warns(xc, order, tmp_path):
    """Bodies that overlap before any load: the disc moved into the block by
    d = 1 + xc (0.01 and 0.1, about 0.1 and 1 times the contact edges' mean
    length 0.096). One warning line names the pair, the surface, both
    bodies and the depth, which is the geometry's: the disc's nodes lie on
    its circle, the deepest at the angle of the node nearest the axis, so
    the depth printed is d to 3 digits (measured 0.01 and 0.1); the run goes
    on and solves the interference fit (status 0). Either surface order
    (the block's surface named first) gives the line."""
    pairs = [] if order == "indenter" else ["-contact_interface_surfaces", "block:contact,indenter:contact"]
    r = run_contact(hertz_moved(xc, *pairs), tmp_path)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("contact: warning: pair interface: before any load, surface "), lines
    line = lines[0]
    for name in ("indenter", "block"):
        assert f"body {name}" in line, line
    depth = float(line.split("by up to ")[1].split(",")[0])
    print(line)
    assert abs(depth - (1 + xc)) <= 5e-3 * (1 + xc), (depth, 1 + xc)
    assert r.summary["contact_force"] > 0


@pytest.mark.parametrize("xc", [-1.0, -0.999])
def test_touching_or_shallow_fit_is_quiet(xc, tmp_path):
    """Its neighbours: the disc touching the block (the shipped scene, largest
    overlap measured 8e-17) and moved in by 1e-3, 0.01 of the edges' mean
    length (below the warning's 0.05): nothing on stderr, status 0."""
    r = run_contact(hertz_moved(xc), tmp_path)
    assert r.stderr.strip() == "", r.stderr[-2000:]
    assert r.summary["contact_force"] > 0
