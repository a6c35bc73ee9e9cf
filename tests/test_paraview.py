"""ParaView reads the XDMF output right: Debian's ParaView 5.11 (pvpython on
one virtual X server, Xvfb, for the session; both installed by
scripts/install-deps.sh) opens the file of a small run
through its legacy reader (XDMFReader) and its Xdmf3 readers (Xdmf3ReaderS,
Xdmf3ReaderT); every block's point count, cells and point arrays are compared
with the HDF5 file read by h5py: the bodies' coordinates, displacement (3
components, z = 0), stress components and von Mises stress; each contact
surface with a profile as a line mesh on its current positions with its
pressure and gap; and Warp By Vector on the displacement gives the current
positions. Both formulations: Gauss-point samples (polylines) and nodal
samples (quadratic edges), where the master surface (the block's edge, mortar)
shows the pressure transferred from the slave, so that no contact edge is
empty. Every grid carries every field (a body's contact fields NaN, a contact
line's stress NaN and its displacement zero), and each reader renders the
bodies coloured by each body field (test_readers_show_colours). A scene with
friction adds the slave's shear, slip and stick to every grid, and the shear
ParaView colours by has the HDF5's range (test_friction_shear)."""
import json
import os
import select
import shutil
import subprocess

import numpy as np
import pytest

from conftest import ENV, ROOT, run_contact

PROBE = ROOT / "tests" / "paraview_probe.py"
DEPS_STAMP = ROOT / "build" / ".deps-installed"
BODIES = ("indenter", "block")  # the order of -bodies in meshes/hertz/hertz.opts
SURFACES = ("indenter_contact", "block_contact")  # -contact_interface_surfaces
VTK_CELL = {"Tri6": 22, "Quad9": 28, "Edge_3": 21, "Polyline": 4}  # quadratic triangle, biquadratic quad, ...
READERS = ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT")


def paraview():
    """(Xvfb, pvpython); skips only where the project's set-up never ran."""
    tools = {t: shutil.which(t) for t in ("Xvfb", "pvpython")}
    missing = [t for t, path in tools.items() if not path]
    if missing:
        if DEPS_STAMP.exists():
            pytest.fail(f"{', '.join(missing)} missing although scripts/install-deps.sh ran "
                        f"({DEPS_STAMP.relative_to(ROOT)} exists): it installs paraview, python3-paraview, xvfb")
        pytest.skip(f"{', '.join(missing)} not installed and scripts/install-deps.sh not run "
                    "(make deps installs ParaView and xvfb)")
    return tools["Xvfb"], tools["pvpython"]


@pytest.fixture(scope="session")
def display(tmp_path_factory):
    """One virtual X server for every pvpython run of the session, started
    with -displayfd: the server itself takes the first display whose lock
    and sockets are all free, and writes its number when it accepts
    connections. Before, each run had its own `xvfb-run -a`, which picks a
    number by the lock files alone and, on its way out, kills its server
    without waiting for it, so a run that followed could be given a display
    the dying server still answered on: pvpython's window then found no X
    connection and aborted (SIGABRT in vtkXOpenGLRenderWindow::CreateAWindow,
    1.3 s in; once in CI, in the run after the probes). The server runs with
    -noreset: without it, an X server resets itself whenever its last client
    leaves, and a pvpython that connects during that reset aborts the same
    way (once in CI, between the two colour runs, which follow each other
    with no client left in between)."""
    xvfb, _ = paraview()
    log = tmp_path_factory.mktemp("xvfb") / "xvfb.log"
    ready, write = os.pipe()
    with open(log, "w") as sink:
        server = subprocess.Popen([xvfb, "-displayfd", str(write), "-screen", "0", "1280x1024x24",
                                   "-nolisten", "tcp", "-noreset"], pass_fds=(write,), stdout=sink, stderr=subprocess.STDOUT)
    os.close(write)
    with os.fdopen(ready) as pipe:
        shown, _, _ = select.select([pipe], [], [], 60)
        number = pipe.readline().strip() if shown else ""
    if not number.isdigit():
        server.kill()
        server.wait()
        pytest.fail(f"Xvfb gave no display within 60 s (exit {server.returncode}): {log.read_text()[-2000:]}")
    yield dict(ENV, DISPLAY=":" + number)
    server.terminate()
    server.wait(timeout=60)


def run_pvpython(script, args, cwd, env):
    """Runs a ParaView script on the session's X server; on failure, shows
    the first lines of its output (the cause) as well as the last."""
    _, exe = paraview()
    proc = subprocess.run([exe, str(script), *map(str, args)], cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=600)
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, f"pvpython {script.name} exited {proc.returncode}:\n{text[:2000]}\n...\n{text[-2000:]}"
    return text


def same(a, b):
    """Bit for bit: ParaView reads the HDF5 doubles themselves, and Warp By
    Vector makes the same one, correctly rounded, addition X + u (measured
    difference 0 in every array of both formulations and all three readers,
    with each of the OpenBLAS kernels Nehalem, Sandybridge, Haswell and
    SkylakeX: no summation order enters, so no round-off allowance)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert a.shape == b.shape, (a.shape, b.shape)
    np.testing.assert_array_equal(a, b)


def expected_blocks(h5):
    """What the XDMF file should show, in its order, from the HDF5 file."""
    blocks = []
    for b in BODIES:
        g = h5["bodies"][b]
        X, u, sig = g["geometry"][...], g["displacement"][...], g["stress"][...]
        nan = np.full(len(X), np.nan)  # a body has no contact fields (every grid carries every field)
        blocks.append({"name": b, "kind": "body", "X": X, "u": u, "cells": len(g["topology"]),
                       "cell_type": VTK_CELL[g.attrs["cell_type"].decode()],
                       "arrays": {"displacement": np.c_[u, np.zeros(len(X))],
                                  "stress_xx": sig[:, 0], "stress_yy": sig[:, 1], "stress_zz": sig[:, 2],
                                  "stress_xy": sig[:, 3], "von_mises": g["von_mises"][...],
                                  "pressure": nan, "gap": nan, "s": nan}})
    for side in SURFACES:
        g = h5["contact/interface"][side]
        pre = "node_" if g.attrs["samples"].decode() == "nodes" else ""
        if len(g[pre + "s"]) == 0:
            continue  # a surface without a profile
        cells = g[pre + "cells"][...]
        n = len(g[pre + "s"])
        nan = np.full(n, np.nan)  # no stress on a contact line; no displacement to apply (it is drawn where it is)
        blocks.append({"name": "interface:" + side.replace("_", ":"), "kind": "surface", "X": g[pre + "x"][...],
                       "cells": len(cells), "cell_type": VTK_CELL[g.attrs["cell_type"].decode()],
                       "arrays": {"pressure": g[pre + "pressure"][...], "gap": g[pre + "gap"][...],
                                  "s": g[pre + "s"][...], "displacement": np.zeros((n, 3)),
                                  "stress_xx": nan, "stress_yy": nan, "stress_zz": nan, "stress_xy": nan,
                                  "von_mises": nan}, "weight": g[pre + "weight"][...],
                       "slave": bool(g.attrs["slave"])})
    return blocks


@pytest.fixture(scope="module", params=["gpts", "mortar"])
def probed(request, tmp_path_factory, display):
    tmp = tmp_path_factory.mktemp(request.param)
    run = run_contact(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.2",
                       "-contact_formulation", request.param], tmp, name="hertz")
    xdmf = run.output_path.with_suffix(".xdmf")
    out = tmp / "probe.json"
    text = run_pvpython(PROBE, [xdmf, out], tmp, display)
    with run.h5() as h5:
        expected = expected_blocks(h5)
    return request.param, expected, json.loads(out.read_text()), text, run.summary


def test_readers_warn_nothing(probed):
    """No array skipped (Xdmf3 on Function items) nor mis-sized (legacy on a 4-column vector)."""
    log = probed[3]
    for bad in ("Skipping", "tuples", "rror", "arning"):
        assert bad not in log, log[-3000:]


@pytest.mark.parametrize("reader", READERS)
def test_blocks_match_hdf5(probed, reader):
    """Each block as the HDF5 file has it: a block missing or out of order, a
    wrong Dimensions or cell type in the XDMF, a vector read with the wrong
    number of components, or an array of another dataset shows."""
    formulation, expected, got, _, summary = probed
    blocks = got[reader]["blocks"]
    assert len(blocks) == len(expected), [b["name"] for b in blocks]
    assert len(expected) == 4  # two bodies, two contact lines (mortar's master too)
    for e, b in zip(expected, blocks):
        if b["name"] is not None:  # Xdmf3ReaderS names no block
            assert b["name"] == e["name"]
        n = len(e["X"])
        assert len(b["points"]) == n, (e["name"], len(b["points"]), n)
        same(np.asarray(b["points"])[:, :2], e["X"])
        same(np.asarray(b["points"])[:, 2], np.zeros(n))
        assert b["cells"] == e["cells"] and b["cell_types"] == [e["cell_type"]], e["name"]
        want = e["arrays"]
        assert sorted(b["arrays"]) == sorted(want), (e["name"], sorted(b["arrays"]))
        for name, values in want.items():
            a = b["arrays"][name]
            assert a["tuples"] == n and a["components"] == (3 if name == "displacement" else 1), (e["name"], name, a["components"])
            same(a["values"], values)
        if e["kind"] == "surface":
            # the pressure ParaView shows carries the contact force, so that no
            # array compared above is a trivial one (zeros match zeros): int p ds
            # (the HDF5 weights) is the JSON's P = |int p n ds|. A slave's to
            # 2.5e-2 (measured at h = 0.2: gpts +9.9e-3 disc, -3.1e-3 block;
            # mortar's slave +3.5e-3; the normal turns along the curved zone).
            # Mortar's master carries the slave's pressure moved to its nodes,
            # a transfer whose error is the coarse mesh's: to 5e-2 (measured
            # -3.2e-2 at h = 0.2, where 7 of its nodes carry pressure; -4.5e-3,
            # +9.6e-3, +4.6e-3, +1.3e-2 at h = 0.25, 0.22, 0.18, 0.15; +4.4e-3
            # at 0.1 and +8.0e-4 at 0.05)
            P = float(np.sum(e["weight"] * np.asarray(b["arrays"]["pressure"]["values"])))
            print(f"{formulation} {reader} {e['name']}: int p ds / P - 1 = {P / summary['contact_force'] - 1:.2e}")
            bound = 2.5e-2 if e["slave"] else 5e-2
            assert abs(P / summary["contact_force"] - 1) <= bound, (e["name"], bound)


@pytest.mark.parametrize("reader", READERS)
def test_warp_by_displacement(probed, reader):
    """Warp By Vector moves each body to its current configuration; the contact
    lines, already there, stay."""
    _, expected, got, _, _ = probed
    warped = got[reader]["warped_points"]
    for e, w in zip(expected, warped):
        w = np.asarray(w)
        same(w[:, :2], e["X"] + e["u"] if e["kind"] == "body" else e["X"])


FIELDS = ("von_mises", "stress_xx", "displacement")
RENDER = ROOT / "tests" / "paraview_render.py"


def colours(png):
    """The number of distinct colours in an image."""
    import matplotlib.image
    a = (matplotlib.image.imread(png)[:, :, :3] * 255).round().astype(np.int64).reshape(-1, 3)
    return len(np.unique(a, axis=0))


@pytest.mark.parametrize("formulation", ["gpts", "mortar"])
def test_readers_show_colours(formulation, tmp_path, display):
    """What a user sees: each reader ParaView offers for the XDMF file
    (legacy, Xdmf3ReaderS, Xdmf3ReaderT, and what OpenDataFile picks, which
    is Xdmf3ReaderS) renders the bodies coloured by each body field, not in
    one solid grey. Xdmf3ReaderS reads the file's grids as pieces of one
    dataset and colours by a field only where every piece has it, so before
    every grid carried every field it drew the bodies grey (325 colours on
    screen with or without the field, against 1,305 with Xdmf3ReaderT).
    Counted on screen: the coloured view has at least twice the colours of
    the same view in one solid colour (measured 4.1 to 5.2 times with every
    reader; the file without the padding measured 1.00 with Xdmf3ReaderS and
    OpenDataFile, 4.1 to 5.1 with the others)."""
    run = run_contact(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.1",
                       "-contact_formulation", formulation], tmp_path, name="hertz")
    out = tmp_path / "png"
    run_pvpython(RENDER, [run.output_path.with_suffix(".xdmf"), out, *FIELDS], tmp_path, display)
    for reader in ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT", "OpenDataFile"):
        solid = colours(out / f"{reader}-solid.png")
        for field in FIELDS:
            n = colours(out / f"{reader}-{field}.png")
            print(f"{formulation} {reader} {field}: {n} colours, solid {solid}: {n / solid:.2f} times")
            assert n >= 2 * solid, (reader, field, n, solid)


AXI_FIELDS = ("stress_rr", "stress_zz", "stress_hoop", "stress_rz", "von_mises")


def test_axisymmetric_hoop_stress(tmp_path, display):
    """An axisymmetric scene (sphere, h = 0.02) opens as its meridian section:
    every reader shows each body with the stresses named rr, zz, hoop, rz,
    each the HDF5's `stress` column bit for bit (hoop the third), and the
    contact lines with them as NaN; and the view coloured by stress_hoop has
    at least twice the colours of the solid one (measured 3.28 times with
    every reader)."""
    run = run_contact(["-options_file", "meshes/sphere/sphere.opts", "-mesh_size", "0.02"], tmp_path, name="sphere")
    xdmf = run.output_path.with_suffix(".xdmf")
    probe = tmp_path / "probe.json"
    run_pvpython(PROBE, [xdmf, probe], tmp_path, display)
    got = json.loads(probe.read_text())
    with run.h5() as h5:
        want = [(b, h5["bodies"][b]["stress"][...]) for b in ("ball", "flat")]
    for reader in READERS:
        blocks = got[reader]["blocks"]
        assert len(blocks) == 4, [b["name"] for b in blocks]
        for (name, sig), b in zip(want, blocks):
            for k, f in enumerate(AXI_FIELDS[:4]):
                same(b["arrays"][f]["values"], sig[:, k])
            assert "stress_xx" not in b["arrays"]
        for b in blocks[2:]:
            assert np.all(np.isnan(b["arrays"]["stress_hoop"]["values"]))
    out = tmp_path / "png"
    run_pvpython(RENDER, [xdmf, out, "stress_hoop"], tmp_path, display)
    for reader in ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT", "OpenDataFile"):
        solid, n = colours(out / f"{reader}-solid.png"), colours(out / f"{reader}-stress_hoop.png")
        print(f"{reader} stress_hoop: {n} colours, solid {solid}: {n / solid:.2f} times")
        assert n >= 2 * solid, (reader, n, solid)


SHEAR = ROOT / "tests" / "paraview_shear.py"


def test_friction_shear(tmp_path, display):
    """A scene with friction (cattaneo: two load stages, so the file's last
    time step) shows the friction's fields in every reader: the disc's
    contact line (the slave's) carries the HDF5's node_shear, node_slip and
    node_stick bit for bit, the slab's (the master's) its node_shear, the
    slave's transferred, and the other two as NaN, the bodies all three as
    NaN, so that Xdmf3ReaderS and OpenDataFile colour by them. The shear's
    range in ParaView's data information, and the colour map's once a view
    is coloured by the shear and rescaled to the data, is the HDF5's (min,
    max) over both lines, exactly (the colour map's to 4 ulp: measured 1 ulp
    above the largest, its end points rescaled), ParaView skipping the NaN (measured -2.7788,
    the master's, signed along its own arc, to 2.8226, the slave's largest
    where its stick zone meets the slip at 0.69 mu p_max). The shear shown
    is no trivial array: the slave's sum with the HDF5's weights A_j is the
    JSON's tangential load Q to 4e-3 (measured +2.2e-4, 18 times; with the
    contact twice as wide +1.43e-3: Q is the whole force across the normal
    of the zone's chord, the sum runs along the curved arc). Threshold on
    the shear keeps the two contact lines alone (their points and cells,
    the bodies' NaN dropped), and they, framed on their loaded part,
    coloured by the shear show at least 3 times the colours of the same
    view in one solid colour (measured 9.87 to 10.80 times: 296 to 324
    colours against 30; the lines lie on each other, the legacy reader
    draws the master's on top, the Xdmf3 readers the slave's)."""
    run = run_contact(["-options_file", "meshes/cattaneo/cattaneo.opts"], tmp_path, name="cattaneo")
    out, png = tmp_path / "shear.json", tmp_path / "png"
    run_pvpython(SHEAR, [run.output_path.with_suffix(".xdmf"), out, png], tmp_path, display)
    got = json.loads(out.read_text())
    with run.h5() as h5:
        g = h5["contact/interface/disc_contact"]
        want = {f: g[f"node_{f}"][...] for f in ("shear", "slip", "stick")}
        w = g["node_weight"][...]
        m = h5["contact/interface/slab_contact"]
        master = m["node_shear"][...]
        sizes = [len(h5["bodies/disc/geometry"]), len(h5["bodies/slab/geometry"]), len(w), len(master)]
        lines = [len(w) + len(master), len(g["node_cells"]) + len(m["node_cells"])]
    Q = run.summary["contact"]["interface"]["tangential_load"]
    both = np.r_[want["shear"], master]
    print(f"int q ds / Q - 1 = {np.sum(w * want['shear']) / Q - 1:+.2e}, shear range {both.min()} .. {both.max()}")
    assert abs(np.sum(w * want["shear"]) / Q - 1) <= 4e-3
    for reader, r in got.items():
        assert r["times"] == [1.0, 2.0], reader
        assert [b["points"] for b in r["blocks"]] == sizes, reader
        for k, b in enumerate(r["blocks"]):
            for f, values in want.items():
                a = b["arrays"][f]
                assert a is not None, (reader, k, f)
                if k == 2:   # the disc's contact line, the slave's
                    same(a, values)
                elif k == 3 and f == "shear":   # the slab's, the master's: the shear transferred
                    same(a, master)
                else:
                    assert np.all(np.isnan(a)), (reader, k, f)
        expected = [float(both.min()), float(both.max())]
        assert r["range"] == expected, (reader, r["range"])
        np.testing.assert_allclose(r["colour_range"], expected, rtol=4 * np.finfo(float).eps, atol=0)
        assert r["threshold"] == lines, (reader, r["threshold"], lines)
        solid, n = colours(png / f"{reader}-solid.png"), colours(png / f"{reader}-shear.png")
        print(f"{reader} shear: {n} colours, solid {solid}: {n / solid:.2f} times")
        assert n >= 3 * solid, (reader, n, solid)
