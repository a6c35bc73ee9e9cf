#!/usr/bin/env python3
"""Plot the results of a contact run (the HDF5 file written by ``-output``).

Usage:
    python3 scripts/plot_hertz.py out/hertz.h5 -o out/hertz.png
        contact pressure along each interface (both one-sided profiles,
        plotted against s - s_c) with the Hertz curve when the scene declares one
    python3 scripts/plot_hertz.py out/hertz.h5 --field [--scale S] -o out/vm.png
        von Mises stress on the deformed bodies (displacements magnified by S);
        the quadratic (Tri6 / Quad9) cells are subdivided through their shape
        functions so that curved edges are drawn smoothly

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
# Local node ids (a, b, mid) of the edges of each cell type, in XDMF order.
EDGES = {"Tri6": [(0, 1, 3), (1, 2, 4), (2, 0, 5)],
         "Quad9": [(0, 1, 4), (1, 2, 5), (2, 3, 6), (3, 0, 7)]}


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


def plot_field(f, scale, ax, label):
    bodies = f["bodies"]
    data = []
    for name in bodies:
        g = bodies[name]
        cell_type = attr(g, "cell_type")
        if cell_type not in EDGES:
            raise PlotError(f"body '{name}': unsupported cell_type {cell_type!r}")
        topo = g["topology"][()].astype(int)
        x = g["geometry"][()] + scale * g["displacement"][()]
        N, tris = subdivision(cell_type, 6)
        pts = np.einsum("kj,cjd->ckd", N, x[topo]).reshape(-1, 2)
        vals = np.einsum("kj,cj->ck", N, g["von_mises"][()][topo]).ravel()
        tris = (tris[None] + N.shape[0] * np.arange(len(topo))[:, None, None]).reshape(-1, 3)
        data.append((pts, tris, vals, outline(topo, cell_type, x)))
    if not data:
        raise PlotError("no bodies in file")
    norm = Normalize(min(d[2].min() for d in data), max(d[2].max() for d in data))
    for pts, tris, vals, lines in data:
        mappable = ax.tripcolor(pts[:, 0], pts[:, 1], tris, vals, shading="gouraud",
                                cmap="viridis", norm=norm)
        ax.add_collection(LineCollection(lines, colors="k", linewidths=0.5, alpha=0.6))
    cax = make_axes_locatable(ax).append_axes("right", size="4%", pad=0.1)
    ax.figure.colorbar(mappable, cax=cax, label="von Mises stress [Pa]")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"von Mises stress on the deformed bodies (displacement x {scale:g})"
                 f"\n{label}")


def plot_pressure(f, axes):
    for ax, (pair, g) in zip(axes, f["contact"].items()):
        hertz = "hertz_a" in g.attrs and "hertz_pmax" in g.attrs
        for side in g.values():
            if isinstance(side, h5py.Group):
                s = side["s"][()] - attr(side, "centre", 0.0)
                ax.plot(s, side["pressure"][()], "o-", ms=3, lw=0.8,
                        label=f"{attr(side, 'body')}:{attr(side, 'group')} (one-sided)")
        a = attr(g, "hertz_a") if hertz else attr(g, "fem_a", 0.0)
        text = [f"P = {attr(g, 'P', float('nan')):.4g} N/m"]
        if hertz:
            pmax = attr(g, "hertz_pmax")
            t = np.linspace(-a, a, 401)
            ax.plot(np.r_[-1.5 * a, t, 1.5 * a],
                    np.r_[0, pmax * np.sqrt(np.clip(1 - (t / a) ** 2, 0, None)), 0],
                    "k-", lw=1.5, label="Hertz")
            fa, fp = attr(g, "fem_a"), attr(g, "fem_pmax")
            text += [f"Hertz: a = {a:.4g} m, p_max = {pmax:.4g} Pa",
                     f"computed: a = {fa:.4g} m ({100 * (fa - a) / a:+.1f} %), "
                     f"p_max = {fp:.4g} Pa ({100 * (fp - pmax) / pmax:+.1f} %)",
                     f"relative L2 error of p: {100 * attr(g, 'pressure_l2_error'):.2f} %"]
        if a and a > 0:
            ax.set_xlim(-1.5 * a, 1.5 * a)
        ax.set_ylim(0, 1.45 * ax.get_ylim()[1])
        ax.text(0.02, 0.97, "\n".join(text), transform=ax.transAxes, va="top",
                fontsize=8, bbox=dict(boxstyle="round", fc="w", alpha=0.8))
        ax.legend(loc="upper right", fontsize=8)
        ax.grid(alpha=0.3)
        ax.set_xlabel("arc position s - s_c [m]")
        ax.set_ylabel("pressure p [Pa]")
        ax.set_title(f"contact pressure, pair '{pair}'")


def save(fig, path):
    """Write the figure to a temporary file next to ``path``, then rename it."""
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(suffix=".png", prefix=".plot_hertz-", dir=directory)
    try:
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
    parser.add_argument("--scale", type=float, default=1.0,
                        help="displacement magnification for --field (default 1)")
    args = parser.parse_args()
    try:
        if not os.path.isfile(args.file):
            raise PlotError(f"{args.file}: no such file")
        try:
            f = h5py.File(args.file, "r")
        except OSError as err:
            raise PlotError(f"{args.file}: not a readable HDF5 file ({err})") from err
        with f:
            scene = attr(f["metadata"], "scene", "?") if "metadata" in f else "?"
            label = f"scene '{scene}': {os.path.basename(args.file)}"
            if args.field:
                if "bodies" not in f:
                    raise PlotError(f"{args.file}: no /bodies group")
                fig, ax = plt.subplots(figsize=(9, 6))
                plot_field(f, args.scale, ax, label)
            else:
                if "contact" not in f or not len(f["contact"]):
                    raise PlotError(f"{args.file}: no /contact group (no contact pairs)")
                n = len(f["contact"])
                fig, axes = plt.subplots(n, 1, figsize=(8, 5 * n), squeeze=False,
                                         layout="constrained")
                plot_pressure(f, axes[:, 0])
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
