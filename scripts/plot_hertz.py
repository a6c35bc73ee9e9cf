#!/usr/bin/env python3
"""Plot the results of a contact run (the HDF5 file written by ``-output``).

Usage:
    python3 scripts/plot_hertz.py out/hertz.h5 -o out/hertz.png
        contact pressure along each interface (both surfaces' profiles, a
        slave's own and, for mortar, a master's transferred from the slave,
        plotted against s - s_c, or with --axis x|y against the current x or
        y coordinate; an axisymmetric scene's against the radius r, the
        Hertz curve centred on the axis) with the Hertz curve when the scene
        declares one;
        a scene without contact pairs is skipped with one line (exit status 0)
    python3 scripts/plot_hertz.py out/ball.h5 [--hertz-3d R,E*[,k]] -o out/ball.png
        a 3D pair (dimension 3): the slave's nodal pressures p_j against the
        distance r from the report's axis (through the pressure's centroid
        along the normal load; reference positions, as the report), with
        the computed P, p_max and a from the second moment (sum p_j A_j
        r_j^2 / sum p_j A_j = 2 a^2 / 5 for Hertz's profile: the report's);
        with --hertz-3d the Hertz curve of a sphere of radius R (E* the
        contact modulus) under k P (P the scene's part's force, k: the
        model's share, 4 for a quarter model, 2 for a half; default 1), by
        default the pair's own (-contact_<pair>_hertz_radii, its share from
        -contact_<pair>_symmetry), a = (3 k P R / (4 E*))^(1/3),
        p0 = 3 k P / (2 pi a^2), and the relative L2 error of the nodal
        pressures (weights A_j) from it
    python3 scripts/plot_hertz.py out/cattaneo.h5 --shear -o out/cattaneo-shear.png
        the shear traction q of each pair with friction along its slave
        surface (node_shear), with Coulomb's bound mu p, the stick zone
        (node_stick; shaded, half-width stick_half_width), the master's
        transferred shear drawn as the slave's and, where the pair
        declares Hertz radii in plane strain, Cattaneo-Mindlin's curve drawn
        with the computed a (second moment) and p0 = 2 P / (pi a) and his
        stick zone c = a sqrt(1 - Q/(mu P)); a 3D pair's nodal shear along
        Q against r (as its pressure) with Mindlin's sphere, mu p0/a
        (sqrt(a^2 - r^2) - sqrt(c^2 - r^2)), p0 = 3 P / (2 pi a^2),
        c = a (1 - Q/(mu P))^(1/3) from the whole model's loads, and its
        relative L2 distance (printed); a file without friction is
        skipped with one line (exit status 0; with --quiet without it, as
        make run does)
    python3 scripts/plot_hertz.py out/hertz.h5 --field [--scale S] -o out/vm.png
        von Mises stress on the deformed bodies; the quadratic (Tri6 / Quad9)
        cells are subdivided through their shape functions so that curved edges
        are drawn smoothly; a 3D scene's file (Tet10 / Hex27 bodies) is
        skipped with one line naming its XDMF file to open in ParaView
        (exit status 0, nothing written)

--scale S magnifies each body's deformation, not its rigid motion: per body the
rigid motion that best fits the computed displacement (least squares over the
body's area: translation and rotation) is kept as it is and only the remainder,
the deformation, is multiplied by S. A pushed body is therefore drawn where it
really is, not pushed S times as far into the other. Magnified, the two sides of
an interface no longer coincide: each is drawn S times as dented as computed, so
a gap (or an overlap) of about (S - 1) times the local deformation appears.

--zoom frames the loaded part of the contact zone (the contact points of every
pair with a pressure above 1e-3 of the pair's largest, as drawn): the field
plot shows a square of F times the loaded length around it (--zoom alone:
F = 3), its colour range that of the window; the pressure plot shows the loaded
arc enlarged F times (without --zoom: 1.5). --zoom x0,x1,y0,y1 gives the field
plot's window explicitly; the pressure plot then shows the contact points
whose current position lies in it. Without loaded points --zoom F is ignored
(one note) and the whole scene is drawn.

The program has no units; axes are labelled without them unless --units or the
HDF5 attributes /metadata:length_unit and /metadata:stress_unit name them (the
option wins). Units are labels only: no number is converted.

Only numpy, h5py and matplotlib (Agg backend) are used.
"""
import argparse
import os
import sys
import tempfile

import h5py
import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.colors import Normalize  # noqa: E402
from mpl_toolkits.axes_grid1 import make_axes_locatable  # noqa: E402

PROG = "plot_hertz.py"
DEFAULT_ZOOM = 3.0   # --zoom alone: a window three times the loaded length
# Local node ids (a, b, mid) of the edges of each cell type, in XDMF order.
EDGES = {"Tri6": [(0, 1, 3), (1, 2, 4), (2, 0, 5)],
         "Quad9": [(0, 1, 4), (1, 2, 5), (2, 3, 6), (3, 0, 7)]}


# A 3D body's cell types: its fields are ParaView's to show (--field says so).
SOLID_CELLS = ("Tet10", "Hex27")


class PlotError(Exception):
    pass


def attr(obj, name, default=None):
    """Attribute ``name`` of an HDF5 object, bytes decoded to str."""
    value = obj.attrs.get(name, default)
    if isinstance(value, (bytes, np.bytes_)):
        return value.decode().strip()
    return value.item() if isinstance(value, np.generic) else value


def lagrange1d(t):
    """Quadratic Lagrange basis on the nodes -1, 0, 1 (columns in that order)."""
    return np.stack([t * (t - 1) / 2, 1 - t * t, t * (t + 1) / 2], axis=-1)


def subdivision(cell_type, n):
    """Shape functions (k, nodes) at a reference sub-grid and its triangles."""
    i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="ij")
    ids = -np.ones((n + 1, n + 1), dtype=int)
    keep = (i + j <= n) if cell_type == "Tri6" else np.ones_like(i, dtype=bool)
    ids[keep] = np.arange(keep.sum())
    tris = []
    for a in range(n):
        for b in range(n):
            p, q, r, s = ids[a, b], ids[a + 1, b], ids[a, b + 1], ids[a + 1, b + 1]
            if min(p, q, r) >= 0:
                tris.append((p, q, r))
            if min(q, s, r) >= 0:
                tris.append((q, s, r))
    u, v = i[keep] / n, j[keep] / n
    if cell_type == "Tri6":
        lam = np.stack([1 - u - v, u, v], axis=-1)
        N = np.column_stack([lam * (2 * lam - 1)] + [4 * lam[:, a] * lam[:, b]
                                                      for a, b, _ in EDGES["Tri6"]])
    else:
        lu, lv = lagrange1d(2 * u - 1), lagrange1d(2 * v - 1)
        # (xi, eta) grid index of each Quad9 node: corners, mid-edges, centre.
        nodes = [(0, 0), (2, 0), (2, 2), (0, 2), (1, 0), (2, 1), (1, 2), (0, 1), (1, 1)]
        N = np.column_stack([lu[:, a] * lv[:, b] for a, b in nodes])
    return N, np.array(tris)


def outline(topology, cell_type, x, n=12):
    """Boundary edges (those used by a single cell), sampled as curves."""
    edges = np.concatenate([topology[:, e] for e in EDGES[cell_type]])
    key = np.sort(edges[:, :2], axis=1)
    _, inv, count = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    bnd = edges[count[inv.ravel()] == 1]
    L = lagrange1d(np.linspace(-1, 1, n))
    return np.einsum("kj,ejd->ekd", L, x[bnd[:, [0, 2, 1]]])



SI_PREFIX = {"G": 9, "M": 6, "k": 3, "": 0, "c": -2, "m": -3, "µ": -6, "u": -6, "n": -9}


def si_exponent(unit, base):
    """The power of ten of an SI unit of base ("MPa": 6, "mm": -3), or None."""
    if not unit.endswith(base):
        return None
    return SI_PREFIX.get(unit[:-len(base)])


class Units:
    """Length and stress unit labels ("" when unknown)."""

    def __init__(self, length="", stress=""):
        self.length, self.stress = length, stress

    def label(self, text, kind):
        unit = self.length if kind == "length" else self.stress
        return f"{text} [{unit}]" if unit else text

    def force(self, axisym):
        """The unit of P: a force (stress x length^2) in r-z, where P is the
        whole circle's; a force per unit thickness (stress x length) in plane
        strain. In newtons where both units are SI (mm, MPa: N and N/mm),
        else as the product."""
        if not (self.length and self.stress):
            return ""
        es, el = si_exponent(self.stress, "Pa"), si_exponent(self.length, "m")
        if es is None or el is None:
            return f"{self.stress}·{self.length}²" if axisym else f"{self.stress}·{self.length}"
        e = es + 2 * el
        name = {v: k for k, v in SI_PREFIX.items() if k != "u"}.get(e)
        newtons = f"{name}N" if name is not None else f"1e{e} N"
        return newtons if axisym else f"{newtons}/{self.length}"

    def value(self, x, kind, axisym=False):
        """x formatted with its unit, if any."""
        unit = self.force(axisym) if kind == "force" else self.length if kind == "length" else self.stress
        return f"{x:.4g} {unit}" if unit else f"{x:.4g}"


def parse_units(text):
    """--units value: "LENGTH,STRESS" (either may be empty) or "none"."""
    if text.strip().lower() == "none":
        return Units()
    parts = text.split(",")
    if len(parts) != 2:
        raise argparse.ArgumentTypeError(
            f"expected LENGTH,STRESS (e.g. mm,MPa) or none, got {text!r}")
    return Units(parts[0].strip(), parts[1].strip())


def parse_zoom(text):
    """--zoom value: a factor F > 0, or a window x0,x1,y0,y1."""
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) == 1 and np.isfinite(values[0]) and values[0] > 0:
        return values[0]
    if (len(values) == 4 and np.all(np.isfinite(values))
            and values[0] < values[1] and values[2] < values[3]):
        return tuple(values)
    raise argparse.ArgumentTypeError(
        f"expected a factor F > 0 or a window x0,x1,y0,y1 (x0 < x1, y0 < y1), got {text!r}")


def zoom_argv(argv):
    """argv with every "--zoom [VALUE]" written "--zoom=VALUE", so that a window
    starting with a minus sign (-0.1,0.1,-0.1,0.1) is not taken for an option
    and a bare --zoom does not swallow the next argument (the file name)."""
    out, i = [], 0
    while i < len(argv):
        if argv[i] == "--zoom":
            value = argv[i + 1] if i + 1 < len(argv) else None
            try:
                parse_zoom(value)
            except (argparse.ArgumentTypeError, AttributeError):
                value = None
            out.append(f"--zoom={value if value is not None else DEFAULT_ZOOM}")
            i += 2 if value is not None else 1
        else:
            out.append(argv[i])
            i += 1
    return out


def file_units(f):
    """Units named by /metadata attributes length_unit and stress_unit, if any."""
    meta = f["metadata"] if "metadata" in f else None
    if meta is None:
        return Units()
    return Units(str(attr(meta, "length_unit", "") or ""),
                 str(attr(meta, "stress_unit", "") or ""))


def node_weights(topology, cell_type, X):
    """Each cell's area shared equally among its nodes (a lumped area per node)."""
    corners = X[topology[:, :3 if cell_type == "Tri6" else 4]]
    nxt = np.roll(corners, -1, axis=1)
    area = 0.5 * np.abs(np.sum(corners[..., 0] * nxt[..., 1] - corners[..., 1] * nxt[..., 0],
                               axis=1))
    w = np.zeros(len(X))
    np.add.at(w, topology, (area / topology.shape[1])[:, None])
    return w


class RigidFit:
    """The rigid motion X -> c + R (X - C) closest to X -> x (area-weighted least
    squares, any rotation angle), and the display map that magnifies the rest."""

    def __init__(self, X, x, w):
        W = w.sum()
        self.C = (w[:, None] * X).sum(0) / W
        self.c = (w[:, None] * x).sum(0) / W
        P, Q = X - self.C, x - self.c
        angle = np.arctan2(np.sum(w * (P[:, 0] * Q[:, 1] - P[:, 1] * Q[:, 0])),
                           np.sum(w * (P * Q).sum(1)))
        cs, sn = np.cos(angle), np.sin(angle)
        self.R = np.array([[cs, -sn], [sn, cs]])

    def rigid(self, X):
        return self.c + (X - self.C) @ self.R.T

    def display(self, X, x, scale):
        """Where a point at X (deformed: x) is drawn: rigid part + scale x the rest."""
        if scale == 1.0:
            return x
        r = self.rigid(X)
        return r + scale * (x - r)


def body_fits(f):
    """RigidFit of every body, by name."""
    fits = {}
    for name, g in f["bodies"].items():
        if attr(g, "rigid", 0):   # no cells: drawn by its contact surfaces
            continue
        cell_type = attr(g, "cell_type")
        if cell_type not in EDGES:
            raise PlotError(f"body '{name}': unsupported cell_type {cell_type!r}")
        topo = g["topology"][()].astype(int)
        X = g["geometry"][()]
        fits[name] = RigidFit(X, X + g["displacement"][()], node_weights(topo, cell_type, X))
    return fits


def sample(side, name):
    """A profile dataset of a one-sided surface: Gauss-point samples (gpts) are
    named s, pressure, ...; nodal ones (mortar) node_s, node_pressure, ..."""
    return side[name][()] if name in side else side["node_" + name][()]


def is_nodal(side):
    return "node_s" in side


def is_slave(side):
    """A slave's pressure is its own; another surface's is transferred from the slave."""
    return bool(attr(side, "slave", 1))


def nodal_curve(s, p, n=12):
    """The pressure's quadratic interpolant along the surface: nodes sorted by
    s alternate corner, mid-edge, corner (a node listed twice is taken
    once); each edge's three nodes give a parabola in s."""
    keep = np.r_[True, np.diff(s) > 1e-12 * max(1.0, np.ptp(s))]
    s, p = s[keep], p[keep]
    if len(s) < 3:
        return s, p
    xs, ys = [], []
    for i in range(0, len(s) - 2, 2):
        t = np.linspace(s[i], s[i + 2], n)
        (a, b, c), (pa, pb, pc) = s[i:i + 3], p[i:i + 3]
        xs.append(t)
        ys.append(pa * (t - b) * (t - c) / ((a - b) * (a - c)) + pb * (t - a) * (t - c) / ((b - a) * (b - c))
                  + pc * (t - a) * (t - b) / ((c - a) * (c - b)))
    return np.concatenate(xs), np.concatenate(ys)


def profile_sides(g):
    """The surfaces of a pair that carry a profile: the slaves, and (mortar)
    the master, whose pressure is the slave's at its closest points."""
    return [v for v in g.values() if isinstance(v, h5py.Group) and len(sample(v, "s"))]


def loaded_points(f):
    """(body, X, x, s - s_c) of every contact point with positive pressure, by side."""
    out = []
    if "contact" not in f:
        return out
    for g in f["contact"].values():
        sides = profile_sides(g)
        pmax = max([np.max(sample(v, "pressure"), initial=0.0) for v in sides], default=0.0)
        for side in sides:
            p = sample(side, "pressure")
            on = p > 1e-3 * pmax if pmax > 0 else np.zeros(len(p), dtype=bool)
            out.append((attr(side, "body"), sample(side, "X")[on], sample(side, "x")[on],
                        sample(side, "s")[on] - attr(side, "centre", 0.0)))
    return out


def zoom_window(f, zoom, scale, fits):
    """The field plot's window (x0, x1, y0, y1) for --zoom, or None and a note."""
    if isinstance(zoom, tuple):
        return zoom, None
    pts = [fits[body].display(X, x, scale) if body in fits else x
           for body, X, x, _ in loaded_points(f) if len(x)]
    if not pts:
        return None, "no loaded contact points: --zoom ignored, whole scene drawn"
    pts = np.concatenate(pts)
    lo, hi = pts.min(0), pts.max(0)
    centre, size = (lo + hi) / 2, zoom * max(hi - lo)
    if size <= 0:   # a single loaded point: a window of 5 % of the scene
        allx = np.concatenate([g["geometry"][()] for g in f["bodies"].values() if "geometry" in g])
        size = zoom * 0.05 * max(np.ptp(allx, axis=0))
    return (centre[0] - size / 2, centre[0] + size / 2,
            centre[1] - size / 2, centre[1] + size / 2), None


def rigid_outline(g):
    """A rigid body's lines as polylines (corner, middle, corner) at their
    current positions: its group's line_x and lines."""
    x, lines = g["line_x"][()].reshape(-1, 2), g["lines"][()].astype(int).reshape(-1, 3)
    return [x[[c[0], c[2], c[1]]] for c in lines]


def rigid_surface_lines(f, body):
    """The contact surfaces of rigid body ``body`` as polylines (corner,
    middle, corner of each quadratic edge) at their current positions."""
    lines = []
    for pair in f.get("contact", {}).values():
        for sname, sg in pair.items():
            if not sname.startswith(body + "_") or "node_cells" not in sg:
                continue
            x, cells = sg["node_x"][()], sg["node_cells"][()].astype(int)
            lines += [x[[c[0], c[2], c[1]]] for c in cells]
    return lines


def plot_field(f, scale, ax, label, units, zoom=None):
    bodies = f["bodies"]
    fits = body_fits(f)
    data = []
    rigid_lines = []
    for name in bodies:
        g = bodies[name]
        if attr(g, "rigid", 0):
            rigid_lines += rigid_outline(g) if "lines" in g else rigid_surface_lines(f, name)
            continue
        cell_type = attr(g, "cell_type")
        topo = g["topology"][()].astype(int)
        X = g["geometry"][()]
        x = fits[name].display(X, X + g["displacement"][()], scale)
        N, tris = subdivision(cell_type, 6)
        pts = np.einsum("kj,cjd->ckd", N, x[topo]).reshape(-1, 2)
        vals = np.einsum("kj,cj->ck", N, g["von_mises"][()][topo]).ravel()
        tris = (tris[None] + N.shape[0] * np.arange(len(topo))[:, None, None]).reshape(-1, 3)
        data.append((pts, tris, vals, outline(topo, cell_type, x)))
    if not data:
        raise PlotError("no bodies in file")
    window, note = (None, None) if zoom is None else zoom_window(f, zoom, scale, fits)
    shown = [d[2] for d in data]
    if window is not None:
        # colour range of what the window shows (if it shows any sample point)
        inside = [v[(p[:, 0] >= window[0]) & (p[:, 0] <= window[1]) &
                    (p[:, 1] >= window[2]) & (p[:, 1] <= window[3])]
                  for p, _, v, _ in data]
        if sum(len(v) for v in inside):
            shown = [v for v in inside if len(v)]
    norm = Normalize(min(v.min() for v in shown), max(v.max() for v in shown))
    for pts, tris, vals, lines in data:
        mappable = ax.tripcolor(pts[:, 0], pts[:, 1], tris, vals, shading="gouraud",
                                cmap="viridis", norm=norm)
        ax.add_collection(LineCollection(lines, colors="k", linewidths=0.5, alpha=0.6))
    if rigid_lines:   # a rigid body: its contact surfaces, at their current place
        ax.add_collection(LineCollection(rigid_lines, colors="0.3", linewidths=1.5))
    cax = make_axes_locatable(ax).append_axes("right", size="4%", pad=0.1)
    ax.figure.colorbar(mappable, cax=cax, label=units.label("von Mises stress", "stress"))
    ax.set_aspect("equal")
    if window is not None:
        ax.set_xlim(window[0], window[1])
        ax.set_ylim(window[2], window[3])
    axisym = "metadata" in f and bool(attr(f["metadata"], "axisymmetric", 0))
    ax.set_xlabel(units.label("radius r" if axisym else "x", "length"))
    ax.set_ylabel(units.label("axis z" if axisym else "y", "length"))
    how = ("" if scale == 1.0 else
           f" (deformation x {scale:g}, rigid motion not magnified)")
    ax.set_title(f"von Mises stress on the deformed bodies{how}\n{label}")
    return note


def pressure_range(g, zoom, hertz_a=0.0, radial=False):
    """x range of a pair's pressure plot, or None (automatic): the loaded arc
    (s - s_c; and the Hertz zone [-a, a], if any) enlarged by the zoom factor
    about its middle. radial (r-z): the loaded radii (current; Hertz's zone
    [0, a]) instead, enlarged the same way but never past the axis; a zone
    that reaches the axis (a disc) is drawn from it, to F times its radius,
    and one away from it (a ring) about its middle."""
    sides = profile_sides(g)

    def coordinate(side):
        return sample(side, "x")[:, 0] if radial else sample(side, "s") - attr(side, "centre", 0.0)

    if isinstance(zoom, tuple):
        x0, x1, y0, y1 = zoom
        s = [coordinate(side)[(p[:, 0] >= x0) & (p[:, 0] <= x1) & (p[:, 1] >= y0) & (p[:, 1] <= y1)]
             for side in sides for p in [sample(side, "x")]]
        s = np.concatenate(s) if s else np.empty(0)
        return (s.min(), s.max()) if len(s) and s.max() > s.min() else None
    pmax = max([np.max(sample(v, "pressure"), initial=0.0) for v in sides], default=0.0)
    if pmax <= 0:
        return None
    hertz = ([0.0, hertz_a] if radial else [-hertz_a, hertz_a]) if hertz_a > 0 else []
    s = np.concatenate([coordinate(v)[sample(v, "pressure") > 1e-3 * pmax] for v in sides] + [hertz])
    lo, hi = s.min(), s.max()
    factor = 1.5 if zoom is None else zoom
    if radial and lo <= 1e-12 * hi:   # a disc about the axis
        return (0.0, factor * hi)
    half = (hi - lo) / 2 if hi > lo else 1e-3 * max(1.0, abs(lo))
    x0, x1 = (lo + hi) / 2 - factor * half, (lo + hi) / 2 + factor * half
    return (max(x0, 0.0), x1) if radial else (x0, x1)


def abscissa(side, axis):
    """The samples' abscissa on the pressure plot, and the map from s - s_c
    (the arc position from the centre) to it: the arc position itself (axis
    "s"), or the samples' current x or y coordinate (interpolated along s
    between them)."""
    s, c = sample(side, "s"), attr(side, "centre", 0.0)
    if axis == "s":
        return s - c, lambda t: t
    x, order = sample(side, "x")[:, "xy".index(axis)], np.argsort(s)
    return x, lambda t: np.interp(np.asarray(t) + c, s[order], x[order])


# Each role's colour, the same in every pair's figure: a slave's own pressure
# (the pair's first slave; where both surfaces are slaves, as in gpts, the
# second its own colour) and a mortar master's, transferred from the slave.
ROLE_COLOURS = {"slave": "C1", "second slave": "C2", "master": "C0"}
MARKERS_SHOWN = 40   # at most about this many markers per curve across the plot: on a finer mesh every k-th sample


def surface_roles(g):
    """(side, role) of each surface of a pair with a profile, in the pair's
    order (attribute surface_index, the place in -contact_<pair>_surfaces;
    by name in a file without it)."""
    sides = sorted(profile_sides(g), key=lambda v: (attr(v, "surface_index", 0), v.name))
    roles, slaves = [], 0
    for side in sides:
        if is_slave(side):
            roles.append((side, "slave" if slaves == 0 else "second slave"))
            slaves += 1
        else:
            roles.append((side, "master"))
    return roles


def thin_markers(ax, lines):
    """Marks every k-th sample of each line, k such that about MARKERS_SHOWN
    of its samples inside the axes' x range are marked (all of them on a
    coarse mesh); the line keeps all its samples."""
    lo, hi = ax.get_xlim()
    for line in lines:
        x = np.asarray(line.get_xdata())
        inside = np.count_nonzero((x >= min(lo, hi)) & (x <= max(lo, hi)))
        line.set_markevery(max(1, int(np.ceil(inside / MARKERS_SHOWN))))


def parse_hertz_3d(text):
    """--hertz-3d R,E*[,k]: three positive finite numbers (k default 1)."""
    try:
        vals = [float(v) for v in text.split(",")]
    except ValueError:
        vals = []
    if len(vals) == 2:
        vals.append(1.0)
    if len(vals) != 3 or not all(np.isfinite(v) and v > 0 for v in vals):
        raise argparse.ArgumentTypeError(f"expected R,E* or R,E*,k (positive numbers), not '{text}'")
    return tuple(vals)


def hertz_3d(P, R, Es):
    """Hertz's sphere on a plane: contact radius a and peak pressure p0 under the load P."""
    a = (3 * P * R / (4 * Es)) ** (1 / 3)
    return a, 3 * P / (2 * np.pi * a * a)


def report_axis(g):
    """The report's centre and axis of a 3D pair (its attributes centre_x,
    ..., axis_z: the pressure's centroid in reference positions moved onto
    the symmetry planes, and the whole model's force direction), or None
    in a file without them."""
    if "centre_x" not in g.attrs:
        return None
    return (np.array([attr(g, f"centre_{c}") for c in "xyz"]),
            np.array([attr(g, f"axis_{c}") for c in "xyz"]))


def radial_profile(side, g):
    """A 3D slave surface's nodes: (r, p, A), r the distance from the
    report's axis (report_axis: through the pressure's centroid along the
    force) in reference positions, as the report measures it
    (src/contact/report3d.c); in a file without the axis, from the node
    of largest pressure in the plane normal to the pair's force."""
    X, p, A = side["node_X"][:], side["node_pressure"][:], side["node_weight"][:]
    axis = report_axis(g)
    if axis is None:
        n = np.array([attr(g, f"force_{c}", 0.0) for c in "xyz"])
        n = n / np.linalg.norm(n) if np.linalg.norm(n) > 0 else np.array([0.0, 0.0, 1.0])
        axis = (X[int(np.argmax(p))], n)
    c, n = axis
    d = X - c
    d -= np.outer(d @ n, n)
    return np.linalg.norm(d, axis=1), p, A


def second_moment_radius(r, p, A):
    """a from the nodal pressures' second moment: sum p A r^2 / sum p A =
    2 a^2 / 5 for Hertz's profile (the nodes in contact, p > 0)."""
    on = p > 0
    return np.sqrt(2.5 * np.sum(p[on] * A[on] * r[on] ** 2) / np.sum(p[on] * A[on]))


def slave_3d(g):
    """A 3D pair's slave surface group (the one with node_pressure)."""
    return next(v for v in g.values() if isinstance(v, h5py.Group) and "node_pressure" in v)


def plot_pressure_3d(ax, pair, g, units, hertz=None):
    """A 3D pair: the slave's nodal pressures against r (radial_profile),
    the Hertz curve where hertz = (R, E*, k), under k times the part's load
    (with friction its normal load, as the report's Hertz takes); the
    figures against Hertz's also printed on stdout."""
    side = slave_3d(g)
    r, p, A = radial_profile(side, g)
    on = p > 0
    share = attr(g, "model_share", 1.0)   # the whole model over the scene's part (-contact_<pair>_symmetry)
    # the part's load: with friction the normal load (the report's Hertz load), else |F|
    P = attr(g, "whole_normal_load", attr(g, "P", float("nan"))) / share
    if hertz is None and "hertz_a" in g.attrs:   # the scene's own Hertz radii
        hertz = (attr(g, "R_star"), attr(g, "E_star"), share)
    if not on.any():
        raise PlotError(f"pair '{pair}': no slave node in contact")
    am = second_moment_radius(r, p, A)
    rmax = 1.6 * max(am, r[on].max())
    near = r <= rmax
    name = f"{attr(side, 'body')}:{attr(side, 'group')}"
    ax.plot(r[near], p[near], "o", ms=3, color=ROLE_COLOURS["slave"], zorder=3, label=f"{name}, nodal pressure (slave)")
    normal = " normal load" if "whole_normal_load" in g.attrs else ""
    text = [f"P = {units.value(P, 'force', True)} (the model's{normal})" if share == 1 else
            f"P = {units.value(share * P, 'force', True)} (the whole model's{normal}, {share:g} times the scene's)",
            f"computed: p_max = {units.value(p.max(), 'stress')}, a = {units.value(am, 'length')} (second moment)"]
    if hertz:
        R, Es, k = hertz
        a, p0 = hertz_3d(k * P, R, Es)
        t = np.linspace(0, max(rmax, 1.2 * a), 401)
        ax.plot(t, p0 * np.sqrt(np.clip(1 - (t / a) ** 2, 0, None)), "k-", lw=1.5, zorder=2.5,
                label=f"Hertz (R = {R:g}, E* = {Es:g}, load {k:g} P)")
        ph = p0 * np.sqrt(np.clip(1 - (r / a) ** 2, 0, None))
        l2 = np.sqrt(np.sum(A * (p - ph) ** 2) / np.sum(A * ph * ph))
        text += [f"Hertz: a = {units.value(a, 'length')}, p_max = {units.value(p0, 'stress')}",
                 f"p_max {100 * (p.max() - p0) / p0:+.2f} %, a (second moment) {100 * (am - a) / a:+.2f} %",
                 f"relative L2 error of the nodal p: {100 * l2:.2f} %"]
        print(f"{PROG}: pair '{pair}' (3D): pressure against Hertz's: a {am:.15g} (second moment), Hertz's a {a:.15g}, "
              f"p_max {p.max():.15g}, Hertz's p0 {p0:.15g}, relative L2 {l2:.15g}")
    ax.set_xlim(0, rmax)
    ax.set_ylim(0, 1.45 * ax.get_ylim()[1])
    ax.text(0.02, 0.97, "\n".join(text), transform=ax.transAxes, va="top",
            fontsize=8, bbox=dict(boxstyle="round", fc="w", alpha=0.8))
    ax.legend(loc="upper right", fontsize=8)
    ax.grid(alpha=0.3)
    ax.set_xlabel(units.label("distance r from the contact's axis (reference positions)", "length"))
    ax.set_ylabel(units.label("pressure p", "stress"))
    ax.set_title(f"contact pressure, pair '{pair}' (3D)")


def mindlin_shear_3d(r, a, p0, mu, c):
    """Mindlin's shear traction of a sphere at the distance r from the axis:
    mu p0/a (sqrt(a^2 - r^2) - sqrt(c^2 - r^2)), the second term inside the
    stick disc r < c alone, 0 outside a: Coulomb's bound mu p of Hertz's
    pressure in the slip annulus, less a Hertz-like profile of radius c
    inside it."""
    return mu * p0 / a * (np.sqrt(np.clip(a * a - r * r, 0, None)) - np.sqrt(np.clip(c * c - r * r, 0, None)))


def mindlin_figures_3d(g):
    """Mindlin's figures of a 3D pair from its attributes (the report's,
    the whole model's): a the second moment's (fem_a_moment), the normal
    load P and tangential load Q, p0 = 3 P / (2 pi a^2), mu, and
    c = a (1 - Q/(mu P))^(1/3) (0 at Q >= mu P); None without them or
    where the pair declares no Hertz radii (not a sphere: no Mindlin)."""
    if "whole_normal_load" not in g.attrs or "hertz_a" not in g.attrs:
        return None
    a, P, Q, mu = attr(g, "fem_a_moment"), attr(g, "whole_normal_load"), attr(g, "whole_tangential_load"), attr(g, "friction")
    if not (a > 0 and P > 0 and mu > 0):
        return None
    ratio = Q / (mu * P)
    return dict(a=a, P=P, Q=Q, mu=mu, ratio=ratio, p0=3 * P / (2 * np.pi * a * a),
                c=a * (1 - ratio) ** (1 / 3) if ratio < 1 else 0.0)


def shear_along_q(side, g):
    """Each slave node's shear traction along the whole model's tangential
    load (the attribute shear_axis_x..z; in a file without it, along the
    A_j-weighted sum of the nodal shears)."""
    t = side["node_shear"][:]
    if "shear_axis_x" in g.attrs:
        e = np.array([attr(g, f"shear_axis_{c}") for c in "xyz"])
    else:
        e = (side["node_weight"][:, None] * t).sum(0)
        e = e / np.linalg.norm(e) if np.linalg.norm(e) > 0 else e
    return t @ e


def plot_shear_3d(ax, pair, g, side, units):
    """A 3D pair with friction at the run's end: the slave's nodal shear
    along Q against r (radial_profile), its stuck nodes filled and the
    slipping or open ones hollow, Coulomb's bound mu p, the computed stick
    radius (the whole model's stick area as a disc; shaded) and Mindlin's
    curve and stick radius from the computed a and Q/(mu P) where the pair
    declares Hertz radii, with the nodal shear's relative L2 distance from
    it (weights A_j, every slave node), also printed on stdout."""
    r, p, A = radial_profile(side, g)
    q = shear_along_q(side, g)
    stick = side["node_stick"][:] > 0.5
    mu = attr(g, "friction")
    sign = 1.0 if np.sum(A * q) >= 0 else -1.0
    q = sign * q   # drawn positive along the net shear
    mf = mindlin_figures_3d(g)
    on = p > 0
    if not on.any():
        raise PlotError(f"pair '{pair}': no slave node in contact")
    rmax = 1.6 * max(mf["a"] if mf else 0.0, r[on].max())
    near = r <= rmax
    colour = ROLE_COLOURS["slave"]
    name = f"{attr(side, 'body')}:{attr(side, 'group')}"
    ax.plot(r[near & stick], q[near & stick], "o", ms=3.5, color=colour, zorder=3,
            label=f"{name}, nodal shear along Q: stuck node")
    ax.plot(r[near & ~stick], q[near & ~stick], "o", ms=4, mfc="w", mew=0.9, color=colour, zorder=3,
            label="slipping or open node")
    ax.plot(r[near], mu * p[near], ".", ms=3, color="0.45", zorder=2, label="Coulomb's bound mu p (computed p)")
    c = attr(g, "whole_stick_radius", attr(g, "stick_radius", 0.0))
    if c > 0:
        ax.axvspan(0.0, c, color=colour, alpha=0.12, zorder=1, label="computed stick radius c (stick area as a disc)")
    text = [f"mu = {mu:g}"]
    if mf:
        a, cm = mf["a"], mf["c"]
        t = np.unique(np.r_[np.linspace(0, max(rmax, 1.2 * a), 801), [cm, a]])
        ax.plot(t, mindlin_shear_3d(t, a, mf["p0"], mu, cm), "k-", lw=1.5, zorder=2.5,
                label="Mindlin (computed a, p0 = 3P/(2 pi a^2))")
        if cm > 0:
            ax.axvline(cm, color="k", ls=":", lw=1.0, zorder=2)
        qm = mindlin_shear_3d(r, a, mf["p0"], mu, cm)
        l2 = np.sqrt(np.sum(A * (q - qm) ** 2) / np.sum(A * qm * qm))
        text += [f"P = {units.value(mf['P'], 'force', True)}, Q = {units.value(mf['Q'], 'force', True)} "
                 f"(the whole model's), Q/(mu P) = {mf['ratio']:.4f}",
                 f"a = {units.value(a, 'length')} (second moment), mu p0 = {units.value(mu * mf['p0'], 'stress')}",
                 f"stick radius: c/a = {c / a:.4f}, Mindlin's {cm / a:.4f}" + (" (dotted)" if cm > 0 else " (full sliding)"),
                 f"relative L2 of q against Mindlin's: {100 * l2:.2f} %"]
        print(f"{PROG}: pair '{pair}' (3D): shear along Q against Mindlin's: Q/(mu P) {mf['ratio']:.6g}, "
              f"a {a:.6g}, c {c:.6g}, Mindlin's c {cm:.6g}, relative L2 {l2:.15g}")
    else:
        if "whole_normal_load" in g.attrs:
            P, Q = attr(g, "whole_normal_load"), attr(g, "whole_tangential_load")
            text += [f"P = {units.value(P, 'force', True)}, Q = {units.value(Q, 'force', True)}, "
                     f"Q/(mu P) = {Q / (mu * P):.4f}" if P > 0 and mu > 0 else ""]
        text += [f"stick radius c = {units.value(c, 'length')} (no Hertz radii: no Mindlin curve)"]
    ax.set_xlim(0, rmax)
    lo, hi = ax.get_ylim()
    ax.set_ylim(min(lo, 0.0), hi + 0.5 * (hi - min(lo, 0.0)))
    ax.axhline(0.0, color="0.6", lw=0.6, zorder=1)
    ax.text(0.02, 0.97, "\n".join(text), transform=ax.transAxes, va="top", fontsize=8,
            bbox=dict(boxstyle="round", fc="w", alpha=0.8))
    ax.legend(loc="upper right", fontsize=7)
    ax.grid(alpha=0.3)
    ax.set_xlabel(units.label("distance r from the contact's axis (reference positions)", "length"))
    ax.set_ylabel(units.label("shear traction q along Q", "stress"))
    ax.set_title(f"shear traction, pair '{pair}' (3D, friction mu = {mu:g})")


def plot_pressure(f, axes, units, zoom=None, axis="s", hertz3d=None):
    """Each pair's pressure profiles against the arc position s - s_c (axis
    "s") or the current x or y coordinate (the Hertz curve then centred at
    the slave's centre, its half-width along that axis). A master's curve is
    drawn thinner and behind the slave's, the Hertz curve between them."""
    axisym = "metadata" in f and bool(attr(f["metadata"], "axisymmetric", 0))
    if axisym:   # a meridian section: against the current radius, Hertz centred on the axis
        axis = "x"
    for ax, (pair, g) in zip(axes, f["contact"].items()):
        if attr(g, "dimension", 2) == 3:
            plot_pressure_3d(ax, pair, g, units, hertz3d)
            continue
        hertz = "hertz_a" in g.attrs and "hertz_pmax" in g.attrs
        centre, marked = 0.0, []
        for side, role in surface_roles(g):
            (u, to), p = abscissa(side, axis), sample(side, "pressure")
            s = sample(side, "s") - attr(side, "centre", 0.0)
            name, colour = f"{attr(side, 'body')}:{attr(side, 'group')}", ROLE_COLOURS[role]
            if role == "slave" and not axisym:
                centre = float(to(0.0))
            z = 2 if role == "master" else 3
            if is_nodal(side) and is_slave(side):
                t, q = nodal_curve(s, p)
                ax.plot(to(t), q, "-", lw=1.4, color=colour, zorder=z,
                        label=f"{name}, nodal pressure (quadratic interpolant)")
                marked += ax.plot(u, p, "o", ms=3.5, color=colour, zorder=z)
            elif is_nodal(side):
                t, q = nodal_curve(s, p)
                ax.plot(to(t), q, "--", lw=0.9, color=colour, zorder=z,
                        label=f"{name}, master: slave's pressure at closest points")
                marked += ax.plot(u, p, "s", ms=3.5, mfc="none", mew=0.8, color=colour, zorder=z)
            else:
                marked += ax.plot(u, p, "o-", ms=3, lw=0.8, color=colour, zorder=z,
                                  label=f"{name} (one-sided, Gauss points)")
        a = attr(g, "hertz_a") if hertz else attr(g, "fem_a", 0.0)
        text = [f"P = {units.value(attr(g, 'P', float('nan')), 'force', axisym)}"
                + (" (the whole circle)" if axisym else "")]
        xr = (pressure_range(g, zoom, a if hertz and a > 0 else 0.0, radial=axisym)
              if axis == "s" or axisym else None)
        if hertz and a > 0:
            pmax = attr(g, "hertz_pmax")
            t = np.linspace(-a, a, 401)
            ends = (min(-a, xr[0]), max(a, xr[1])) if xr else (-1.5 * a, 1.5 * a)
            ax.plot(centre + np.r_[ends[0], t, ends[1]],
                    np.r_[0, pmax * np.sqrt(np.clip(1 - (t / a) ** 2, 0, None)), 0],
                    "k-", lw=1.5, zorder=2.5, label="Hertz")
            # the half-width the README says to quote: the second moment's, not where the loaded nodes end
            fa, fp = attr(g, "fem_a_moment"), attr(g, "fem_pmax")
            text += [f"Hertz: a = {units.value(a, 'length')}, "
                     f"p_max = {units.value(pmax, 'stress')}",
                     f"computed: p_max = {units.value(fp, 'stress')} ({100 * (fp - pmax) / pmax:+.2f} %),",
                     f"    a = {units.value(fa, 'length')} (second moment, {100 * (fa - a) / a:+.2f} %)",
                     f"relative L2 error of p: {100 * attr(g, 'pressure_l2_error'):.2f} %"]
        if "zone_start" in g.attrs and attr(g, "zone_end") > attr(g, "zone_start"):
            r1, r2 = attr(g, "zone_start"), attr(g, "zone_end")   # the slave's: r in r-z, its arc's s in plane strain
            text += [f"contact zone: reference r in [{units.value(r1, 'length')}, {units.value(r2, 'length')}], "
                     f"width {units.value(r2 - r1, 'length')}" if axisym else
                     f"contact zone width {units.value(r2 - r1, 'length')}"]
        if xr is not None:
            ax.set_xlim(*xr)
        thin_markers(ax, marked)
        low = min([np.min(sample(v, "pressure"), initial=0.0) for v in profile_sides(g)], default=0.0)
        ax.set_ylim(1.45 * low, 1.45 * ax.get_ylim()[1])   # a master corner node may take a small negative share
        ax.text(0.02, 0.97, "\n".join(text), transform=ax.transAxes, va="top",
                fontsize=8, bbox=dict(boxstyle="round", fc="w", alpha=0.8))
        ax.legend(loc="upper right", fontsize=8)
        ax.grid(alpha=0.3)
        ax.set_xlabel(units.label("radius r (current)" if axisym else "arc position s - s_c" if axis == "s" else f"current position {axis}", "length"))
        ax.set_ylabel(units.label("pressure p", "stress"))
        ax.set_title(f"contact pressure, pair '{pair}'")


def frictional_pairs(f):
    """(pair name, group, slave side) of each pair whose slave surface has a
    shear (node_shear: a pair with friction)."""
    out = []
    for pair, g in f.get("contact", {}).items():
        if attr(g, "dimension", 2) == 3:
            if "node_shear" in slave_3d(g):
                out.append((pair, g, slave_3d(g)))
            continue
        for side, role in surface_roles(g):
            if role == "slave" and "node_shear" in side:
                out.append((pair, g, side))
    return out


def loaded_direction(side):
    """The unit chord from the first to the last loaded node (pressure > 0) of
    a surface, current positions, in the order of its arc; None without two."""
    x, p = sample(side, "x"), sample(side, "pressure")
    on = np.flatnonzero(p > 0)
    if len(on) < 2:
        return None
    t = x[on[-1]] - x[on[0]]
    n = np.hypot(*t)
    return t / n if n > 0 else None


def master_shear_as_slave(g, slave):
    """The pair's master surface with a transferred shear, its samples
    mapped onto the slave's plot: (side, x, q) with x its arc position from
    its centre and q its shear as the slave's, both turned where the arcs
    run opposite ways. The master's traction is the slave's opposite, so
    q_m tau_m = -q_s tau_s: along the same direction q_s = -q_m, else q_m;
    None without a master shear."""
    for side, role in surface_roles(g):
        if role != "master" or "node_shear" not in side:
            continue
        tm, ts = loaded_direction(side), loaded_direction(slave)
        d = 1.0 if tm is None or ts is None or np.dot(tm, ts) >= 0 else -1.0
        x = sample(side, "s") - attr(side, "centre", 0.0)
        return side, d * x, -d * side["node_shear"][()]
    return None


def mindlin_shear(x, a, p0, mu, c):
    """Cattaneo-Mindlin's shear traction at x (from the contact's centre):
    mu p0 sqrt(1 - x^2/a^2) in the slip zones c < |x| < a, less
    mu p0 (c/a) sqrt(1 - x^2/c^2) in the stick zone |x| < c; 0 outside."""
    q = mu * p0 * np.sqrt(np.clip(1 - (x / a) ** 2, 0, None))
    if c > 0:
        q = q - np.where(np.abs(x) < c, mu * p0 * (c / a) * np.sqrt(np.clip(1 - (x / c) ** 2, 0, None)), 0.0)
    return q


def mindlin_figures(g):
    """Mindlin's curve's parameters from the pair's attributes, or None where
    the pair has no Mindlin figure (no Hertz radii, or r-z): the computed
    half-width a (the second moment's, fem_a_moment), p0 = 2 P / (pi a),
    mu, and c = a sqrt(1 - Q/(mu P)) with Q the tangential load and P the
    normal load across and along the contact zone (the report's Q/(mu P);
    c = 0 at Q >= mu P, full sliding)."""
    if "mindlin_c" not in g.attrs:
        return None
    a, P, mu = attr(g, "fem_a_moment"), attr(g, "P"), attr(g, "friction")
    if not (a > 0 and P > 0 and mu > 0):
        return None
    ratio = attr(g, "tangential_load") / (mu * attr(g, "normal_load", P))
    return dict(a=a, p0=2 * P / (np.pi * a), mu=mu, ratio=ratio,
                c=a * np.sqrt(1 - ratio) if ratio < 1 else 0.0)


def plot_shear(f, axes, units, zoom=None, axis="s"):
    """Each frictional pair's shear traction q on its slave surface against
    the arc position from the pressure's centre (in r-z against the current
    radius), with Coulomb's bound mu p of the computed pressure, the master's
    transferred shear drawn as the slave's (plane strain), the computed
    stick zone shaded (its nodes marked filled, the slipping and open ones
    hollow) and, where the pair has Hertz radii in plane strain, Mindlin's
    curve drawn with the computed a and p0 = 2 P / (pi a) and his stick zone
    |x| < c. Mindlin's curve takes the sign of the computed shear's sum.
    With axis "x" or "y" against the current coordinate instead, as the
    pressure plot: the master's at its own nodes' coordinates."""
    axisym = "metadata" in f and bool(attr(f["metadata"], "axisymmetric", 0))
    if axisym:
        axis = "x"
    for ax, (pair, g, side) in zip(axes, frictional_pairs(f)):
        if attr(g, "dimension", 2) == 3:
            plot_shear_3d(ax, pair, g, side, units)
            continue
        (u, to), s = abscissa(side, axis), sample(side, "s") - attr(side, "centre", 0.0)
        q, p, w = side["node_shear"][()], sample(side, "pressure"), sample(side, "weight")
        stick = side["node_stick"][()] > 0.5
        mu = attr(g, "friction")
        sign = 1.0 if np.sum(w * q) >= 0 else -1.0
        name, colour = f"{attr(side, 'body')}:{attr(side, 'group')}", ROLE_COLOURS["slave"]
        t, qi = nodal_curve(s, q)
        ax.plot(to(t), qi, "-", lw=1.4, color=colour, zorder=3,
                label=f"{name}, nodal shear q (quadratic interpolant)")
        marked = ax.plot(u[stick], q[stick], "o", ms=4, color=colour, zorder=3, label="stuck node")
        marked += ax.plot(u[~stick], q[~stick], "o", ms=4.5, mfc="w", mew=1.0, color=colour, zorder=3,
                          label="slipping or open node")
        t, pi_ = nodal_curve(s, p)
        ax.plot(to(t), sign * mu * pi_, "--", lw=0.9, color="0.45", zorder=2,
                label="Coulomb's bound mu p (computed p)")
        master = None if axisym else master_shear_as_slave(g, side)
        if master is not None:
            mside, xm, qm_ = master
            if axis != "s":
                xm = sample(mside, "x")[:, "xy".index(axis)]
            order = np.argsort(xm)
            t, qi = nodal_curve(xm[order], qm_[order])
            ax.plot(t, qi, "--", lw=0.9, color=ROLE_COLOURS["master"], zorder=2.2,
                    label=f"{attr(mside, 'body')}:{attr(mside, 'group')}, master: transferred, as the slave's")
            marked += ax.plot(xm, qm_, "s", ms=3.5, mfc="none", mew=0.8, color=ROLE_COLOURS["master"], zorder=2.2)
        c = attr(g, "stick_half_width", 0.0)
        text = [f"mu = {mu:g}, P = {units.value(attr(g, 'P'), 'force', axisym)}"
                + (" (the whole circle)" if axisym else
                   f", Q = {units.value(attr(g, 'tangential_load'), 'force', axisym)}")]
        if stick.any() and c > 0:
            mid = 0.5 * (s[stick].min() + s[stick].max())
            lo, hi = (0.0, c) if axisym else sorted((float(to(mid - c)), float(to(mid + c))))
            ax.axvspan(lo, hi, color=colour, alpha=0.12, zorder=1,   # in r-z from the axis
                       label=f"computed stick zone ({'radius' if axisym else 'half-width'} c)")
        mf = None if axisym else mindlin_figures(g)
        xr = pressure_range(g, zoom, mf["a"] if mf else 0.0, radial=axisym) if axis == "s" or axisym else None
        if mf:
            a, cm = mf["a"], mf["c"]
            x = np.unique(np.r_[np.linspace(-a, a, 801), [-cm, cm]])
            ends = (min(-a, xr[0]), max(a, xr[1])) if xr else (-1.5 * a, 1.5 * a)
            ax.plot(to(np.r_[ends[0], x, ends[1]]),
                    sign * np.r_[0, mindlin_shear(x, a, mf["p0"], mf["mu"], cm), 0],
                    "k-", lw=1.5, zorder=2.5, label="Mindlin (computed a, p0 = 2P/(pi a))")
            for xc in (-cm, cm):
                ax.axvline(float(to(xc)), color="k", ls=":", lw=1.0, zorder=2)
            m = (np.abs(s) < a) | (p > 0)
            qm = sign * mindlin_shear(s, a, mf["p0"], mf["mu"], cm)
            l2 = np.sqrt(np.sum(w[m] * (q[m] - qm[m]) ** 2) / np.sum(w[m] * qm[m] ** 2))
            text += [f"Q/(mu P) = {mf['ratio']:.4f}; a = {units.value(a, 'length')} (second moment), "
                     f"mu p0 = {units.value(mf['mu'] * mf['p0'], 'stress')}",
                     f"stick zone: c/a = {c / a:.4f}, Mindlin's {cm / a:.4f} ({100 * (c / cm - 1):+.2f} %; dotted)"
                     if cm > 0 else f"stick zone: c/a = {c / a:.4f}, Mindlin's 0 (full sliding)",
                     f"relative L2 of q against Mindlin's: {100 * l2:.2f} %"]
        else:
            text += [f"stick zone {'radius' if axisym else 'half-width'}: c = {units.value(c, 'length')}"]
        if xr is not None:
            ax.set_xlim(*xr)
        else:   # against a coordinate: the arc's range mapped to it
            xs = pressure_range(g, zoom, mf["a"] if mf else 0.0)
            if xs is not None:
                ax.set_xlim(*sorted((float(to(xs[0])), float(to(xs[1])))))
        thin_markers(ax, marked)
        lo, hi = ax.get_ylim()
        ax.set_ylim(lo - 0.45 * (hi - lo) * (sign < 0), hi + 0.45 * (hi - lo) * (sign > 0))
        ax.axhline(0.0, color="0.6", lw=0.6, zorder=1)
        ax.text(0.02, 0.97 if sign > 0 else 0.03, "\n".join(text), transform=ax.transAxes,
                va="top" if sign > 0 else "bottom", fontsize=8, bbox=dict(boxstyle="round", fc="w", alpha=0.8))
        ax.legend(loc="upper right" if sign > 0 else "lower right", fontsize=7)
        ax.grid(alpha=0.3)
        ax.set_xlabel(units.label("radius r (current)" if axisym else "arc position s - s_c" if axis == "s" else f"current position {axis}", "length"))
        ax.set_ylabel(units.label("shear traction q (along the arc)", "stress"))
        ax.set_title(f"shear traction, pair '{pair}' (friction mu = {mu:g})")


def save(fig, path):
    """Write the figure to a temporary file next to ``path``, then rename it.

    mkstemp creates its file with mode 0600 (private, whatever the umask); the
    rename would carry that mode to ``path``. So the temporary file is given
    the mode an ordinary new file gets, 0666 less the umask, before the rename.
    """
    directory = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(directory):
        raise PlotError(f"{path}: no directory {directory}")
    fd, tmp = tempfile.mkstemp(suffix=".png", prefix=".plot_hertz-", dir=directory)
    try:
        umask = os.umask(0o022)
        os.umask(umask)
        os.fchmod(fd, 0o666 & ~umask)
        with os.fdopen(fd, "wb") as out:
            fig.savefig(out, format="png", dpi=150, bbox_inches="tight")
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def main():
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file", help="HDF5 output of bin/contact (-output)")
    parser.add_argument("-o", "--output", required=True, help="PNG file to write")
    parser.add_argument("--field", action="store_true",
                        help="plot von Mises stress on the deformed bodies instead")
    parser.add_argument("--shear", action="store_true",
                        help="plot the shear traction of each pair with friction, "
                             "with Mindlin's curve, instead")
    parser.add_argument("--scale", type=float, default=1.0, metavar="S",
                        help="--field: magnify each body's deformation S times; its "
                             "best-fit rigid motion (translation, rotation) is drawn "
                             "unmagnified (default 1: as computed)")
    parser.add_argument("--zoom", type=parse_zoom, nargs="?", const=DEFAULT_ZOOM, default=None,
                        metavar="F|x0,x1,y0,y1",
                        help="frame the loaded contact zone enlarged F times (alone: "
                             "F = 3; the pressure plot's default is 1.5), or the "
                             "window x0,x1,y0,y1 (field plot coordinates)")
    parser.add_argument("--axis", choices=("s", "x", "y"), default="s",
                        help="the pressure plot's abscissa: the arc position from the "
                             "contact centre (s, the default) or the current x or y "
                             "coordinate (the Hertz curve centred at the slave's centre)")
    parser.add_argument("--hertz-3d", type=parse_hertz_3d, default=None, metavar="R,E*[,k]",
                        help="a 3D pair's Hertz curve: a sphere of radius R, contact "
                             "modulus E*, under k times the pair's force (k = 4 for a "
                             "quarter model; default 1)")
    parser.add_argument("--quiet", action="store_true",
                        help="skip a file with nothing to draw (no contact pairs; no pair "
                             "with friction for --shear) without a line")
    parser.add_argument("--units", type=parse_units, default=None, metavar="LENGTH,STRESS",
                        help="unit labels for the axes, e.g. mm,MPa (either may be "
                             "empty), or none; default: /metadata attributes "
                             "length_unit, stress_unit if present, else no units")
    args = parser.parse_args(zoom_argv(sys.argv[1:]))
    if not np.isfinite(args.scale):
        parser.error(f"argument --scale: not a finite number: {args.scale}")
    try:
        if not os.path.isfile(args.file):
            raise PlotError(f"{args.file}: no such file")
        try:
            f = h5py.File(args.file, "r")
        except OSError as err:
            raise PlotError(f"{args.file}: not a readable HDF5 file ({err})") from err
        with f:
            units = args.units if args.units is not None else file_units(f)
            scene = attr(f["metadata"], "scene", "?") if "metadata" in f else "?"
            label = f"scene '{scene}': {os.path.basename(args.file)}"
            if args.field:
                if "bodies" not in f:
                    raise PlotError(f"{args.file}: no /bodies group")
                solid = [name for name, g in f["bodies"].items() if attr(g, "cell_type") in SOLID_CELLS]
                if solid:
                    xdmf = os.path.splitext(args.file)[0] + ".xdmf"
                    print(f"{PROG}: {args.file} has 3D bodies ({', '.join(solid)}): open {xdmf} in "
                          f"ParaView for their fields (a plane plot would show one slice); nothing written")
                    return 0
                fig, ax = plt.subplots(figsize=(9, 6))
                note = plot_field(f, args.scale, ax, label, units, args.zoom)
                if note:
                    print(f"{PROG}: note: {note}", file=sys.stderr)
            elif args.shear:
                pairs = frictional_pairs(f)
                if not pairs:
                    if not args.quiet:
                        print(f"{PROG}: {args.file} has no pair with friction: shear plot "
                              f"skipped, nothing written")
                    return 0
                fig, axes = plt.subplots(len(pairs), 1, figsize=(8, 5 * len(pairs)), squeeze=False,
                                         layout="constrained")
                plot_shear(f, axes[:, 0], units, args.zoom, args.axis)
                fig.suptitle(label)
            else:
                if "contact" not in f or not len(f["contact"]):
                    solid = "bodies" in f and any(attr(g, "cell_type") in SOLID_CELLS for g in f["bodies"].values())
                    hint = "its XDMF file in ParaView shows the stress" if solid else "--field plots the stress"
                    if not args.quiet:
                        print(f"{PROG}: {args.file} has no contact pairs: pressure plot "
                              f"skipped, nothing written ({hint})")
                    return 0
                n = len(f["contact"])
                fig, axes = plt.subplots(n, 1, figsize=(8, 5 * n), squeeze=False,
                                         layout="constrained")
                plot_pressure(f, axes[:, 0], units, args.zoom, args.axis, args.hertz_3d)
                fig.suptitle(label)
        save(fig, args.output)
    except (OSError, KeyError, ValueError, TypeError, PlotError) as err:
        msg = str(err).splitlines()[0] if str(err) else type(err).__name__
        print(f"{PROG}: error: {msg}", file=sys.stderr)
        return 1
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
