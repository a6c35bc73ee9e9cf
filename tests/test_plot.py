"""scripts/plot_hertz.py on the output of small runs (h = 0.2): exit status, PNG
files with ordinary permissions, --zoom, --units, --scale, a scene without
contact (field plot only), and the pressure plot's curves against the HDF5
datasets (both surfaces, the mortar master's transferred pressure too)."""
import importlib.util
import os
import stat
import subprocess
import sys

import h5py
import numpy as np
import pytest

from conftest import ROOT, figure, run_contact

SCRIPT = ROOT / "scripts" / "plot_hertz.py"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
EPS = np.finfo(float).eps


@pytest.fixture(scope="module")
def hertz(tmp_path_factory):
    d = tmp_path_factory.mktemp("hertz")
    return run_contact(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.2"],
                       d, name="hertz").output_path


@pytest.fixture(scope="module")
def gpts(tmp_path_factory):
    d = tmp_path_factory.mktemp("gpts")
    return run_contact(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.2",
                        "-contact_formulation", "gpts"], d, name="gpts").output_path


@pytest.fixture(scope="module")
def mortar(tmp_path_factory):
    d = tmp_path_factory.mktemp("mortar")
    return run_contact(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.2",
                        "-contact_formulation", "mortar"], d, name="mortar").output_path


@pytest.fixture(scope="module")
def disc(tmp_path_factory):
    d = tmp_path_factory.mktemp("disc")
    return run_contact(["-options_file", "meshes/disc/disc.opts", "-mesh_size", "0.2"],
                       d, name="disc").output_path


def plot(*args):
    """Runs the script with umask 022, as a user's shell would have it."""
    return subprocess.run([sys.executable, str(SCRIPT)] + [str(a) for a in args],
                          capture_output=True, text=True, timeout=120,
                          preexec_fn=lambda: os.umask(0o022))


def assert_png(path):
    assert path.read_bytes()[:8] == PNG_MAGIC
    mode = stat.S_IMODE(path.stat().st_mode)
    assert mode == 0o644, f"{path} has mode {mode:o}"
    assert not [p for p in path.parent.iterdir() if p.name.startswith(".plot_hertz-")]


def pressure_axes(h5, units="none", zoom=None):
    """The pressure plot drawn by the script's own function on a fresh axes."""
    import matplotlib.pyplot as plt
    mod = load_module()
    fig, ax = plt.subplots()
    with h5py.File(h5, "r") as f:
        mod.plot_pressure(f, [ax], mod.parse_units(units), zoom)
    return fig, ax


def test_pressure_plot(hertz, tmp_path):
    """The command writes a PNG; what it draws: the Hertz curve is p_max
    sqrt(1 - (t/a)^2) with the HDF5's a and p_max (to round-off), zero
    outside, and the box's P is the HDF5's. The curve against the formula
    `curve` = 0 and its peak against p_max `peak` = 0 (the same operations),
    bound 100 EPS of p_max; catches a curve drawn with another a or p_max, or
    not centred."""
    import matplotlib.pyplot as plt
    out = tmp_path / "p.png"
    r = plot(hertz, "-o", out)
    assert r.returncode == 0, r.stderr
    assert_png(out)
    fig, ax = pressure_axes(hertz)
    with h5py.File(hertz, "r") as f:
        g = f["contact/interface"]
        a, pmax, P = (float(np.ravel(g.attrs[k])[0]) for k in ("hertz_a", "hertz_pmax", "P"))
    hz, = [l for l in ax.get_lines() if l.get_label() == "Hertz"]
    t, p = hz.get_xdata(), hz.get_ydata()
    dh = np.abs(p - pmax * np.sqrt(np.clip(1 - (t / a) ** 2, 0, None))).max() / pmax
    print(f"Hertz curve against p_max sqrt(1 - (t/a)^2): {dh:.2e} of p_max, peak {p.max() / pmax - 1:.2e}")
    figure("curve", dh), figure("peak", p.max() / pmax - 1)
    assert dh <= 100 * EPS
    assert p.max() == pytest.approx(pmax, rel=100 * EPS) and t.min() <= -a and t.max() >= a
    box = "\n".join(x.get_text() for x in ax.texts)
    assert f"P = {P:.4g}" in box, box
    plt.close(fig)


def test_pressure_zoom_units(hertz, tmp_path):
    """--zoom 3 frames three times the loaded arc (with Hertz's zone) about its
    middle, computed here from the HDF5's samples; --units labels the axes.
    The limits: `xlim` = 0 off (equal to the last bit), bound 100 EPS of the
    window; catches a window about another centre or of another width."""
    import matplotlib.pyplot as plt
    out = tmp_path / "pz.png"
    r = plot(hertz, "--zoom", "3", "--units", "mm,MPa", "-o", out)
    assert r.returncode == 0, r.stderr
    assert_png(out)
    with h5py.File(hertz, "r") as f:
        g = f["contact/interface"]
        a = float(np.ravel(g.attrs["hertz_a"])[0])
        loaded = []
        sides = [g[k] for k in g]
        pmax = max(float(side[("node_" if "node_s" in side else "") + "pressure"][()].max()) for side in sides)
        for side in sides:
            pre = "node_" if "node_s" in side else ""
            sv, pv = side[pre + "s"][()] - side.attrs["centre"], side[pre + "pressure"][()]
            loaded.append(sv[pv > 1e-3 * pmax])
    s = np.concatenate(loaded + [[-a, a]])
    mid, half = (s.min() + s.max()) / 2, (s.max() - s.min()) / 2
    fig, ax = pressure_axes(hertz, "mm,MPa", 3.0)
    print(f"xlim {ax.get_xlim()!r}, expected {(mid - 3 * half, mid + 3 * half)!r}")
    figure("xlim", max(abs(ax.get_xlim()[0] - (mid - 3 * half)), abs(ax.get_xlim()[1] - (mid + 3 * half))) / half)
    assert ax.get_xlim() == pytest.approx((mid - 3 * half, mid + 3 * half), rel=100 * EPS, abs=100 * EPS * half)
    assert ax.get_xlabel() == "arc position s - s_c [mm]" and ax.get_ylabel() == "pressure p [MPa]"
    plt.close(fig)


@pytest.mark.parametrize("extra", [["--zoom"], ["--zoom", "2", "--scale", "5"],
                                   ["--zoom", "-0.3,0.3,-0.3,0.3", "--units", "mm,MPa"]])
def test_field_plot(hertz, tmp_path, extra):
    """The command writes a PNG; what it colours: every body's nodal von Mises
    stress from the HDF5 is among the values drawn (the subdivision's vertices
    include the nodes), one colour scale for all; a window given to --zoom is
    the axes' limits. Each nodal value's distance from the nearest drawn one:
    `miss` = 0, bound 100 EPS of the largest; catches a field drawn from
    another dataset, body or component."""
    import matplotlib.pyplot as plt
    out = tmp_path / "f.png"
    r = plot(hertz, "--field", *extra, "-o", out)
    assert r.returncode == 0, r.stderr
    assert_png(out)
    mod = load_module()
    fig, ax = plt.subplots()
    window = mod.parse_zoom(extra[1]) if len(extra) > 1 and "," in extra[1] else None
    with h5py.File(hertz, "r") as f:
        mod.plot_field(f, 1.0, ax, "", mod.Units(), window)
        nodal = np.concatenate([g["von_mises"][()] for g in f["bodies"].values()])
    drawn = np.concatenate([c.get_array() for c in ax.collections if c.get_array() is not None])
    scale = np.abs(nodal).max()
    miss = np.abs(drawn[None, :] - nodal[:, None]).min(1).max() / scale
    print(f"largest distance of a nodal value from the drawn ones: {miss:.2e} of the largest")
    assert figure("miss", miss) <= 100 * EPS
    norms = {(c.norm.vmin, c.norm.vmax) for c in ax.collections if c.get_array() is not None}
    assert len(norms) == 1
    if window is None:
        assert norms.pop() == pytest.approx((drawn.min(), drawn.max()))
    else:
        assert ax.get_xlim() == window[:2] and ax.get_ylim() == window[2:]
    plt.close(fig)


def test_replaces_existing(hertz, tmp_path):
    """Overwriting keeps the atomic rename and still gives an ordinary mode."""
    out = tmp_path / "p.png"
    out.write_bytes(b"old")
    out.chmod(0o600)
    assert plot(hertz, "-o", out).returncode == 0
    assert_png(out)


def test_bad_options(hertz, tmp_path):
    for bad in (["--units", "mm"], ["--zoom", "0"], ["--zoom", "1,0,0,1"]):
        r = plot(hertz, "--field", *bad, "-o", tmp_path / "x.png")
        assert r.returncode == 2 and "error" in r.stderr, bad
    assert not (tmp_path / "x.png").exists()


def test_no_contact_scene(disc, tmp_path):
    """Without contact pairs the pressure plot is skipped with one line and
    status 0; the field plot (also with --zoom, which has no contact zone to
    frame) works."""
    out = tmp_path / "p.png"
    r = plot(disc, "-o", out)
    assert r.returncode == 0, r.stderr
    assert "no contact pairs" in r.stdout and len(r.stdout.strip().splitlines()) == 1
    assert not out.exists()
    for extra in ([], ["--zoom", "--scale", "10"]):
        out = tmp_path / "f.png"
        r = plot(disc, "--field", *extra, "-o", out)
        assert r.returncode == 0, r.stderr
        assert_png(out)


def load_module():
    spec = importlib.util.spec_from_file_location("plot_hertz", SCRIPT)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.roundoff
def test_scale_keeps_rigid_motion():
    """--scale magnifies the deformation only: a rigid displacement (rotation
    and translation) is drawn as it is (`rigid` = 5.7 EPS of the coordinates
    off over the OpenBLAS kernels Prescott, Nehalem, Sandybridge, Haswell and
    SkylakeX, bound 100 EPS of them), and the remainder S times (`remainder` =
    0 EPS, bound 100 EPS). With a strain of 1e-3 added, the fitted rigid part
    is `fit` = 6.7e-5 from the rigid motion (the strain's own weighted mean and
    skew part, fixed by the seed: no round-off), bound 2e-4: a fit that
    magnified the push or missed the rotation (0.3) is 0.1 or more off."""
    mod = load_module()
    rng = np.random.default_rng(1)
    X = rng.uniform(-1, 1, (50, 2))
    w = rng.uniform(0.5, 1.5, 50)
    t = 0.3
    R = np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])
    rigid = X @ R.T + [0.2, -0.5]
    fit = mod.RigidFit(X, rigid, w)
    print(f"rigid motion drawn at scale 10: {np.abs(fit.display(X, rigid, 10.0) - rigid).max():.2e} off")
    figure("rigid", np.abs(fit.display(X, rigid, 10.0) - rigid).max() / (EPS * np.abs(rigid).max()))
    assert np.abs(fit.display(X, rigid, 10.0) - rigid).max() <= 100 * EPS * np.abs(rigid).max()
    d = 1e-3 * np.column_stack([X[:, 0], -0.5 * X[:, 1]])   # a strain, no rotation
    x = rigid + d @ R.T
    fit = mod.RigidFit(X, x, w)
    shown = fit.display(X, x, 20.0)
    print(f"remainder at scale 20: {np.abs(shown - fit.rigid(X) - 20 * (x - fit.rigid(X))).max():.2e} off, "
          f"fitted rigid part {np.abs(fit.rigid(X) - rigid).max():.2e} from the rigid motion")
    figure("remainder", np.abs(shown - fit.rigid(X) - 20 * (x - fit.rigid(X))).max() / (EPS * np.abs(shown).max()))
    figure("fit", np.abs(fit.rigid(X) - rigid).max())
    assert np.abs(shown - fit.rigid(X) - 20 * (x - fit.rigid(X))).max() <= 100 * EPS * np.abs(shown).max()
    assert np.abs(fit.rigid(X) - rigid).max() < 2e-4     # the push is not magnified
    assert np.array_equal(fit.display(X, x, 1.0), x)


def test_units_from_metadata(hertz, tmp_path):
    """/metadata length_unit, stress_unit label the axes; --units overrides
    them."""
    mod = load_module()
    h5 = tmp_path / "units.h5"
    h5.write_bytes(hertz.read_bytes())
    with h5py.File(h5, "a") as f:
        f["metadata"].attrs["length_unit"] = np.bytes_("mm")
        f["metadata"].attrs["stress_unit"] = np.bytes_("MPa")
    import matplotlib.pyplot as plt
    with h5py.File(h5, "r") as f:
        fig, ax = plt.subplots()
        mod.plot_field(f, 1.0, ax, "", mod.file_units(f))
        assert ax.get_xlabel() == "x [mm]"
        plt.close(fig)
        fig, ax = plt.subplots()
        mod.plot_field(f, 1.0, ax, "", mod.parse_units("none"))
        assert ax.get_xlabel() == "x"
        plt.close(fig)
    with h5py.File(hertz, "r") as f:
        assert (mod.file_units(f).length, mod.file_units(f).stress) == ("", "")


@pytest.mark.parametrize("run", ["gpts", "mortar"])
def test_pressure_curves_are_the_hdf5(run, request, tmp_path):
    """Each surface of the pair is drawn: its samples (markers) are the HDF5's
    s - centre and pressure, labelled with the surface; the mortar master
    (the block, not a slave) as the pressure transferred from the slave."""
    import matplotlib.pyplot as plt
    mod = load_module()
    h5 = request.getfixturevalue(run)
    with h5py.File(h5, "r") as f:
        fig, axes = plt.subplots(1, 1, squeeze=False)
        mod.plot_pressure(f, axes[:, 0], mod.Units())
        lines = axes[0, 0].get_lines()
        g = f["contact/interface"]
        for k in ("indenter_contact", "block_contact"):
            side = g[k]
            pre = "node_" if "node_s" in side else ""
            s = side[pre + "s"][()] - side.attrs["centre"]
            p = side[pre + "pressure"][()]
            assert len(s) > 0, k
            drawn = [l for l in lines if len(l.get_xdata()) == len(s) and np.array_equal(l.get_xdata(), s)
                     and np.array_equal(l.get_ydata(), p)]
            assert len(drawn) == 1, k
            body = k.split("_")[0]
            labels = [l.get_label() for l in lines if l.get_label().startswith(f"{body}:contact")]
            assert len(labels) == 1, labels
            assert ("master" in labels[0]) == (not side.attrs["slave"]), labels[0]
        assert (run == "mortar") == (not g["block_contact"].attrs["slave"])
        plt.close(fig)
    out = tmp_path / "p.png"
    assert plot(h5, "-o", out).returncode == 0
    assert_png(out)


@pytest.mark.parametrize("axis", ["x", "y"])
def test_pressure_against_coordinate(axis, mortar, tmp_path):
    """--axis x|y: each surface's markers are the HDF5's current coordinate
    (node_x's column) and pressure, exactly; the Hertz curve is the HDF5's a
    and p_max, its peak at the slave's centre carried to that coordinate (its
    arc position's coordinate interpolated along s from the HDF5): `peak` = 0
    off, bound 100 EPS. The curve is compared in the squared form (q/p_max)^2 =
    1 - ((t - c)/a)^2, whose round-off is EPS: `curve` = 3.3e-16 to 5e-16,
    bound 100 EPS (the square root's form amplifies a last-bit difference in t
    - c at the zone's ends to sqrt(EPS): 1.5e-6 of p_max under OpenBLAS's
    Sandybridge kernel, which failed it). Catches samples plotted against
    another coordinate or the reference one, or a Hertz curve centred
    elsewhere."""
    import matplotlib.pyplot as plt
    mod = load_module()
    k = "xy".index(axis)
    with h5py.File(mortar, "r") as f:
        fig, ax = plt.subplots()
        mod.plot_pressure(f, [ax], mod.Units(), None, axis)
        lines = ax.get_lines()
        g = f["contact/interface"]
        for name in ("indenter_contact", "block_contact"):
            side = g[name]
            u, p = side["node_x"][()][:, k], side["node_pressure"][()]
            drawn = [l for l in lines if np.array_equal(l.get_xdata(), u) and np.array_equal(l.get_ydata(), p)]
            assert len(drawn) == 1, name
        slave = g["indenter_contact"]
        s, order = slave["node_s"][()], np.argsort(slave["node_s"][()])
        centre = np.interp(slave.attrs["centre"], s[order], slave["node_x"][()][order, k])
        a, pmax = (float(np.ravel(g.attrs[key])[0]) for key in ("hertz_a", "hertz_pmax"))
        hz, = [l for l in lines if l.get_label() == "Hertz"]
        t, q = hz.get_xdata(), hz.get_ydata()
        peak = t[np.argmax(q)]
        print(f"{axis}: Hertz peak at {peak!r}, slave's centre at {centre!r}")
        figure("peak", abs(peak - centre) / max(1.0, abs(centre)))
        curve = figure("curve", np.abs((q / pmax) ** 2 - np.clip(1 - ((t - centre) / a) ** 2, 0, None)).max())
        assert abs(peak - centre) <= 100 * EPS * max(1.0, abs(centre))
        assert curve <= 100 * EPS
        assert ax.get_xlabel() == f"current position {axis}"
        plt.close(fig)
    out = tmp_path / "p.png"
    assert plot(mortar, "--axis", axis, "-o", out).returncode == 0
    assert_png(out)


SPHERE = ["-options_file", "meshes/sphere/sphere.opts", "-mesh_size", "0.02"]


@pytest.fixture(scope="module")
def sphere(tmp_path_factory):
    d = tmp_path_factory.mktemp("sphere")
    return run_contact(SPHERE, d, name="sphere").output_path


def box_text(ax):
    return "\n".join(x.get_text() for x in ax.texts)


@pytest.mark.parametrize("units, axisym_unit, plane_unit", [
    ("mm,MPa", "N", "N/mm"), ("m,Pa", "N", "N/m"), ("m,MPa", "MN", "MN/m"), ("in,psi", "psi·in²", "psi·in")])
def test_force_unit(units, axisym_unit, plane_unit, sphere, hertz):
    """P is a force in r-z (the whole circle's: stress x length^2, MPa mm^2 =
    1e6 Pa 1e-6 m^2 = 1 N) and a force per unit thickness in plane strain
    (MPa mm = N/mm); units that are not SI stay a product. The box's P is
    the HDF5's P with that unit (was 'MPa·mm' for the sphere)."""
    import matplotlib.pyplot as plt
    for h5, unit in ((sphere, axisym_unit), (hertz, plane_unit)):
        fig, ax = pressure_axes(h5, units)
        with h5py.File(h5, "r") as f:
            P = float(np.ravel(f["contact/interface"].attrs["P"])[0])
        line = box_text(ax).splitlines()[0]
        print(units, line)
        assert line.split(" (")[0] == f"P = {P:.4g} {unit}", line
        plt.close(fig)


@pytest.mark.parametrize("run", ["hertz", "sphere"])
def test_box_quotes_second_moment(run, request):
    """The box's computed half-width is the second-moment one the README
    says to quote: its number is fem_a_moment read from the HDF5 with h5py
    (to the 4 digits shown), its percentage 100 (fem_a_moment / hertz_a - 1)
    (to the 2 decimals shown), and not the edge one, fem_a (at h = 0.2 on
    hertz `edge_hertz` = -23.8 % from Hertz's against the moment's
    `moment_hertz` = -4.02 %; on the sphere at h = 0.02 `edge_sphere` = -6.30 %
    against `moment_sphere` = -0.483 %, over the OpenBLAS
    kernels Prescott, Nehalem, Sandybridge, Haswell and SkylakeX)."""
    import re
    import matplotlib.pyplot as plt
    h5 = request.getfixturevalue(run)
    with h5py.File(h5, "r") as f:
        g = f["contact/interface"]
        am, ae, a = (float(np.ravel(g.attrs[k])[0]) for k in ("fem_a_moment", "fem_a", "hertz_a"))
    fig, ax = pressure_axes(h5)
    m = re.search(r"a = (\S+) \(second moment, ([-+]\d+\.\d\d) %\)", box_text(ax))
    print(box_text(ax), f"\nfem_a_moment {am!r} ({100 * (am / a - 1):+.2f} %), fem_a {ae!r} ({100 * (ae / a - 1):+.2f} %)")
    figure(f"edge_{run}", 100 * (ae / a - 1)), figure(f"moment_{run}", 100 * (am / a - 1))
    assert m, box_text(ax)
    assert float(m.group(1)) == pytest.approx(am, rel=5e-4)
    assert float(m.group(2)) == pytest.approx(100 * (am / a - 1), abs=0.005 + 1e-9)
    assert abs(ae / am - 1) > 1e-3   # the edge half-width would show another number
    plt.close(fig)


@pytest.fixture(scope="module")
def fine(tmp_path_factory):
    d = tmp_path_factory.mktemp("fine")
    return run_contact(["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.03"], d, name="fine").output_path


def visible_markers(line, lo, hi):
    """How many of a line's markers fall inside [lo, hi]."""
    x, k = np.asarray(line.get_xdata()), line.get_markevery()
    k = 1 if k is None else k
    idx = np.arange(0, len(x), k)
    return int(np.count_nonzero((x[idx] >= lo) & (x[idx] <= hi)))


def test_fine_mesh_master_behind(fine, tmp_path):
    """On a finer mesh (h = 0.03: `samples` = 137 to 141 samples, `inside` = 71
    to 73 in the plot's range) the master's curve does not hide the slave's: it
    is drawn thinner and below it (zorder), the Hertz curve between them, and
    each curve marks at most about 40 of its samples inside the plot's range
    (every k-th: `marked` = 35 to 37), its data still all of them
    (test_pressure_curves_are_the_hdf5). The PNG of h = 0.015 (hertz's master
    drawn as a ribbon of squares before) was looked at."""
    import matplotlib.pyplot as plt
    mod = load_module()
    fig, ax = pressure_axes(fine)
    lo, hi = ax.get_xlim()
    curves = {l.get_label(): l for l in ax.get_lines() if not l.get_label().startswith("_")}
    slave, = [l for k, l in curves.items() if "nodal pressure" in k]
    master, = [l for k, l in curves.items() if "master" in k]
    assert master.get_zorder() < curves["Hertz"].get_zorder() < slave.get_zorder()
    assert master.get_linewidth() < slave.get_linewidth()
    marked = [l for l in ax.get_lines() if l.get_marker() not in ("None", "", None)]
    assert sorted(l.get_zorder() for l in marked) == sorted((master.get_zorder(), slave.get_zorder()))
    x = [np.asarray(l.get_xdata()) for l in marked]
    inside = [int(np.count_nonzero((v >= lo) & (v <= hi))) for v in x]
    shown = [visible_markers(l, lo, hi) for l in marked]
    print(f"samples {[len(v) for v in x]}, inside the range {inside}, marked {shown}")
    for v, n, k in zip(x, inside, shown):
        figure("samples", len(v)), figure("inside", n), figure("marked", k)
    assert min(inside) > mod.MARKERS_SHOWN + 1         # a mesh fine enough to need the stride
    assert all(0 < s <= mod.MARKERS_SHOWN + 1 for s in shown)
    plt.close(fig)
    out = tmp_path / "fine.png"
    assert plot(fine, "-o", out).returncode == 0
    assert_png(out)


def two_pairs(d):
    """Two copies of the twodiscs scene (discs R = 1 and 2 of
    meshes/hertz/indenter.geo, the larger pushed), 5 apart, h = 0.2: pair
    'one' lists the small disc first (the slave), pair 'two' the large one,
    so that the slave's group name sorts first in one pair and last in the
    other."""
    geo = "meshes/hertz/indenter.geo"
    args = ["-scene", "twopairs", "-bodies", "small1,large1,small2,large2", "-mesh_size", 0.2,
            "-contact_pairs", "one,two", "-contact_one_surfaces", "small1:contact,large1:contact",
            "-contact_two_surfaces", "large2:contact,small2:contact",
            "-contact_one_hertz_radii", "1,2", "-contact_two_hertz_radii", "2,1",
            "-contact_mortar_slave", "first"]   # the first named is the slave (auto would take the softer small discs)
    for k, yc in (("1", 0), ("2", 5)):
        args += [f"-small{k}_geo", geo, f"-small{k}_geo_params", f"R=1,xc=-1,yc={yc},dir=1,xclamp=-1.8,xcontact=-0.5",
                 f"-small{k}_E", 1000, f"-small{k}_nu", 0.3, f"-small{k}_bc", "clamp",
                 f"-large{k}_geo", geo, f"-large{k}_geo_params", f"R=2,xc=2,yc={yc},dir=-1,xclamp=3.6,xcontact=1",
                 f"-large{k}_E", 3000, f"-large{k}_nu", 0.25, f"-large{k}_bc", "clamp",
                 f"-large{k}_bc_clamp_values", "-0.01,0"]
    return run_contact(args, d, name="twopairs").output_path


def test_role_colours_two_pairs(tmp_path):
    """A scene with two pairs: each role (the slave's own pressure, the
    master's transferred one) has one colour in both pairs' plots, its
    legend entry that colour, the two roles two colours, although HDF5 lists
    the surfaces by name (the slave first in pair 'two', last in 'one': the
    colours followed that order before). The surfaces' attribute
    surface_index is their place in -contact_<pair>_surfaces."""
    import matplotlib.pyplot as plt
    mod = load_module()
    h5 = two_pairs(tmp_path)
    colours = {}
    with h5py.File(h5, "r") as f:
        for pair, first in (("one", "small1_contact"), ("two", "large2_contact")):
            g = f[f"contact/{pair}"]
            assert [int(np.ravel(g[k].attrs["surface_index"])[0]) for k in g] == ([1, 0] if pair == "one" else [0, 1])
            assert bool(np.ravel(g[first].attrs["slave"])[0])
        fig, axes = plt.subplots(2, 1, squeeze=False)
        mod.plot_pressure(f, axes[:, 0], mod.Units())
        for ax, pair in zip(axes[:, 0], ("one", "two")):
            leg = ax.get_legend()
            handles = getattr(leg, "legend_handles", None) or leg.legendHandles   # matplotlib < 3.7: legendHandles
            legend = {t.get_text(): h.get_color() for t, h in zip(leg.get_texts(), handles)}
            for l in ax.get_lines():
                role = "master" if "master" in l.get_label() else "slave" if "nodal pressure" in l.get_label() else None
                if role:
                    colours.setdefault(role, set()).add(l.get_color())
                    assert legend[l.get_label()] == l.get_color()
        plt.close(fig)
    print(colours)
    assert len(colours["slave"]) == 1 and len(colours["master"]) == 1 and colours["slave"] != colours["master"]
    out = tmp_path / "two.png"
    assert plot(h5, "-o", out).returncode == 0
    assert_png(out)


@pytest.fixture(scope="module")
def cattaneo(tmp_path_factory):
    """meshes/cattaneo: Cattaneo-Mindlin, friction mu = 0.3, Q = 0.5 mu P (8 increments a stage)."""
    d = tmp_path_factory.mktemp("cattaneo")
    return run_contact(["-options_file", "meshes/cattaneo/cattaneo.opts"], d, name="cattaneo").output_path


def shear_axes(h5):
    """The shear plot drawn by the script's own function on a fresh axes."""
    import matplotlib.pyplot as plt
    mod = load_module()
    fig, ax = plt.subplots()
    with h5py.File(h5, "r") as f:
        mod.plot_shear(f, [ax], mod.Units())
    return fig, ax


def test_shear_plot(cattaneo, hertz, tmp_path):
    """--shear writes a PNG of the slave's shear; a file without friction
    (hertz) gets one line, status 0 and no file, as the pressure plot
    without contact."""
    out = tmp_path / "q.png"
    r = plot(cattaneo, "--shear", "-o", out)
    assert r.returncode == 0, r.stderr
    assert_png(out)
    out = tmp_path / "none.png"
    r = plot(hertz, "--shear", "-o", out)
    assert r.returncode == 0, r.stderr
    assert "no pair with friction" in r.stdout and len(r.stdout.strip().splitlines()) == 1
    assert not out.exists()


def test_shear_curves_are_the_hdf5_and_mindlin(cattaneo):
    """What the shear plot draws on cattaneo: its markers are the HDF5's
    s - centre and node_shear exactly, filled where node_stick is 1; the
    shaded stick zone is 2 stick_half_width wide; Mindlin's curve is his
    formula at the computed a (fem_a_moment), p0 = 2 P / (pi a) and
    c = a sqrt(1 - Q/(mu P)) with the HDF5's friction, tangential_load and
    normal_load, computed here independently (to 1e-12 of mu p0), whose c/a
    is the report's mindlin_c / hertz_a to 1e-12 (the same Q/(mu P)); and
    the box's L2 of the shear against Mindlin's, `l2` = 2.68 % over the
    OpenBLAS kernels Prescott, Nehalem, Sandybridge, Haswell and SkylakeX
    (with the report's P and Q; test_friction.py measures its own with the
    applied ones), is this test's own sum to the 2 decimals shown and below
    25 % (the plot's box would show a Mindlin curve drawn wrong)."""
    import re
    import matplotlib.pyplot as plt
    fig, ax = shear_axes(cattaneo)
    with h5py.File(cattaneo, "r") as f:
        g, side = f["contact/interface"], f["contact/interface/disc_contact"]
        at = {k: float(np.ravel(g.attrs[k])[0]) for k in
              ("fem_a_moment", "P", "friction", "tangential_load", "normal_load", "mindlin_c", "hertz_a", "stick_half_width")}
        s = side["node_s"][()] - float(np.ravel(side.attrs["centre"])[0])
        q, stick, w, p = side["node_shear"][()], side["node_stick"][()] > 0.5, side["node_weight"][()], side["node_pressure"][()]
    lines = {l.get_label(): l for l in ax.get_lines()}
    for label, keep in (("stuck node", stick), ("slipping or open node", ~stick)):
        assert np.array_equal(lines[label].get_xdata(), s[keep]) and np.array_equal(lines[label].get_ydata(), q[keep]), label
        assert (lines[label].get_markerfacecolor() == "w") == (label != "stuck node")
    a, mu = at["fem_a_moment"], at["friction"]
    p0 = 2 * at["P"] / (np.pi * a)
    c = a * np.sqrt(1 - at["tangential_load"] / (mu * at["normal_load"]))
    assert abs(c / a - at["mindlin_c"] / at["hertz_a"]) <= 1e-12
    mindlin = [l for l in lines.values() if l.get_label().startswith("Mindlin")]
    assert len(mindlin) == 1
    x, y = np.asarray(mindlin[0].get_xdata()), np.asarray(mindlin[0].get_ydata())
    inside = np.abs(x) < a
    want = mu * p0 * (np.sqrt(1 - (x[inside] / a) ** 2)
                      - np.where(np.abs(x[inside]) < c, c / a * np.sqrt(np.clip(1 - (x[inside] / c) ** 2, 0, None)), 0))
    assert np.max(np.abs(y[inside] - want)) <= 1e-12 * mu * p0
    assert np.all(y[~inside] == 0)
    span = [pt for pt in ax.patches if "stick zone" in pt.get_label()]
    assert len(span) == 1
    xs = span[0].get_path().transformed(span[0].get_patch_transform()).vertices[:, 0]   # a Rectangle or a Polygon, by matplotlib's version
    assert xs.max() - xs.min() == pytest.approx(2 * at["stick_half_width"], rel=1e-12)
    m = (np.abs(s) < a) | (p > 0)
    qm = mu * p0 * (np.sqrt(np.clip(1 - (s / a) ** 2, 0, None)) - np.where(np.abs(s) < c, c / a * np.sqrt(np.clip(1 - (s / c) ** 2, 0, None)), 0))
    l2 = np.sqrt(np.sum(w[m] * (q[m] - qm[m]) ** 2) / np.sum(w[m] * qm[m] ** 2))
    shown = re.search(r"relative L2 of q against Mindlin's: (\S+) %", box_text(ax))
    print(box_text(ax), f"\nL2 here {100 * l2:.4f} %")
    figure("l2", 100 * l2)
    assert shown and float(shown.group(1)) == pytest.approx(100 * l2, abs=0.005 + 1e-9)
    assert l2 <= 0.25
    plt.close(fig)


def test_shear_master_drawn_as_slave(cattaneo):
    """The master's transferred shear (the slab's node_shear, signed along its
    own arc: the slave's traction opposite) is drawn on the slave's axes as the
    slave's: its open squares are the HDF5's s - centre and -node_shear
    exactly, both arcs running the same way on cattaneo (up the slab's face);
    its largest is the slave's to 4 % (`master_peak` = 0.016 relative over the
    OpenBLAS kernels Prescott, Nehalem, Sandybridge, Haswell and SkylakeX: the
    transfer's interpolation between the slave's nodes flattens the peak at the
    stick zone's edge)."""
    import matplotlib.pyplot as plt
    fig, ax = shear_axes(cattaneo)
    with h5py.File(cattaneo, "r") as f:
        m, sl = f["contact/interface/slab_contact"], f["contact/interface/disc_contact"]
        xm = m["node_s"][()] - float(np.ravel(m.attrs["centre"])[0])
        qm, qs = m["node_shear"][()], sl["node_shear"][()]
    drawn = [l for l in ax.get_lines() if l.get_marker() == "s"]
    assert len(drawn) == 1
    assert np.array_equal(drawn[0].get_xdata(), xm) and np.array_equal(drawn[0].get_ydata(), -qm)
    print(f"master's largest {np.max(-qm):.4f}, slave's {np.max(qs):.4f}: {np.max(-qm) / np.max(qs) - 1:+.4f}")
    assert abs(figure("master_peak", np.max(-qm) / np.max(qs) - 1)) <= 0.04
    plt.close(fig)


def test_shear_against_coordinate(cattaneo):
    """--axis y: the slave's markers are its nodes' current y (node_x's
    column) and node_shear, exactly; the master's its own nodes' y; the x
    range holds the loaded nodes (pressure > 0)."""
    import matplotlib.pyplot as plt
    mod = load_module()
    fig, ax = plt.subplots()
    with h5py.File(cattaneo, "r") as f:
        mod.plot_shear(f, [ax], mod.Units(), axis="y")
        sl, m = f["contact/interface/disc_contact"], f["contact/interface/slab_contact"]
        y, q, stick, p = sl["node_x"][()][:, 1], sl["node_shear"][()], sl["node_stick"][()] > 0.5, sl["node_pressure"][()]
        ym, qm = m["node_x"][()][:, 1], m["node_shear"][()]
    lines = {l.get_label(): l for l in ax.get_lines()}
    for label, keep in (("stuck node", stick), ("slipping or open node", ~stick)):
        assert np.array_equal(lines[label].get_xdata(), y[keep]) and np.array_equal(lines[label].get_ydata(), q[keep]), label
    (master,) = [l for l in ax.get_lines() if l.get_marker() == "s"]
    assert np.array_equal(master.get_xdata(), ym) and np.array_equal(master.get_ydata(), -qm)
    lo, hi = ax.get_xlim()
    assert lo <= y[p > 0].min() and y[p > 0].max() <= hi
    assert ax.get_xlabel() == "current position y"
    plt.close(fig)
