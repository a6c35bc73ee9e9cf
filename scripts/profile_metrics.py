"""Measures of a computed contact pressure profile, read from the program's
HDF5 output (/contact/<pair>/<body>_<group>/ s, pressure, weight): its
oscillation, its distance from another profile (a finer mesh's), its peak and
half-width. Used by the tests and the benchmark.

    python3 scripts/profile_metrics.py out/a.h5 [--ref out/fine.h5] [--masters]
"""
import argparse

import h5py
import numpy as np


def profiles(path, pair=None, masters=False):
    """{surface: (s, p, w, gap or None)} for every surface that acts as slave
    (its own pressure), sorted by s; with masters, also each surface that is
    not a slave but has a profile (mortar: the pressure transferred from the
    slave, in the same node datasets); and the pair's attributes."""
    with h5py.File(path, "r") as f:
        g = f["contact"]
        pair = pair or sorted(g.keys())[0]
        g = g[pair]
        out = {}
        for k in sorted(g.keys()):
            if not masters and not g[k].attrs.get("slave", 1):
                continue
            pre = "node_" if "node_s" in g[k] else ""   # nodal samples (mortar) or Gauss points
            s = g[k][pre + "s"][...].ravel()
            if s.size == 0:
                continue
            s, p, w, gap = (g[k][pre + n][...].ravel() for n in ("s", "pressure", "weight", "gap"))
            out[k] = (s, p, w, gap if pre else None)   # Gauss-point gaps scatter: not interpolated
        attrs = {k: (v.decode() if isinstance(v, bytes) else np.ravel(v)[0]) for k, v in g.attrs.items()}
    return out, attrs


def neighbour_deviation(p):
    """p_i - (p_{i-1} + p_{i+1}) / 2 at the inner samples 1 .. n-2."""
    return p[1:-1] - 0.5 * (p[:-2] + p[2:])


def oscillation_index(s, p, a):
    """The largest neighbour deviation of the profile (a sample minus the mean
    of its two neighbours) less that of the Hertz profile with the same peak,
    half-width a and centre, sampled at the same s; within 0.8 a of the
    pressure centroid, over the peak:

        q(s) = p_max sqrt(max(0, 1 - ((s - c) / a)^2)),  c = sum s p / sum p
        max |dev(p)_i - dev(q)_i| / p_max  over |s_i - c| <= 0.8 a

    Hertz's own curvature (large near a square-root edge) is not oscillation,
    so a Hertz profile gives 0 on any grid. a is the profile's computed
    half-width (half_width(s, p, w, g); oscillation() passes it), or the exact
    one where it is known; p_max is the largest sample."""
    pmax = float(p.max())
    c = float(np.sum(s * p) / np.sum(p))
    q = pmax * np.sqrt(np.clip(1.0 - ((s - c) / a) ** 2, 0.0, None))
    dev = np.abs(neighbour_deviation(p) - neighbour_deviation(q))[np.abs(s[1:-1] - c) <= 0.8 * a]
    return float(dev.max()) / pmax if dev.size else float("nan")


def oscillation(s, p, w, g):
    """The oscillation index of a profile of profiles(), with its computed half-width."""
    return oscillation_index(s, p, half_width(s, p, w, g))


def l2_distance(coarse, fine):
    """Relative L2 distance of a profile from a finer one: the coarse samples
    interpolated linearly in s at the fine samples, with the fine weights."""
    (sc, pc), (sf, pf, wf) = coarse[:2], fine[:3]
    pi = np.interp(sf, sc, pc, left=0.0, right=0.0)
    return float(np.sqrt(np.sum(wf * (pi - pf) ** 2) / np.sum(wf * pf ** 2)))


def zone_end(s, g, i, j):
    """Where the gap, linear between loaded sample i and unloaded sample j, vanishes."""
    if g is not None and g[i] < 0 <= g[j] < 1e300:
        return s[i] + (s[j] - s[i]) * g[i] / (g[i] - g[j])
    return 0.5 * (s[i] + s[j])


def half_width(s, p, w, g):
    """Half the loaded length, its ends where the nodal weighted gap vanishes
    (half-way between samples for Gauss points), as the program's report."""
    i = np.where(p > 0)[0]
    lo = zone_end(s, g, i[0], i[0] - 1) if i[0] > 0 else s[i[0]]
    hi = zone_end(s, g, i[-1], i[-1] + 1) if i[-1] < len(s) - 1 else s[i[-1]]
    return 0.5 * (hi - lo)


def slave_zone_half_width(path, surface, pair=None):
    """The half-width, along surface's own arc s, of the zone where the pair's
    slave presses (one slave: mortar's one-sided pairs): the slave's zone ends
    (its nodal gaps' zeros between its loaded and open samples, as
    half_width) at their current positions, projected on the polyline of
    surface's nodes' current positions. A mortar master's profile is the
    slave's resampled at the master's nodes, so its zone is the slave's; its
    own samples place the zone's end only to a node spacing (a transferred
    pressure that falls to 0 between two master nodes, the master's gap
    weighted over its edges positive at the last loaded one), and the
    oscillation index, which compares the profile with Hertz's of the
    half-width given, reads that as oscillation (a soft disc on a stiff
    slab: 0.044 with the master's own half-width, 18 % wide, 0.0053 with
    this one, the slave's 0.0073: tests/test_master_axis.py)."""
    with h5py.File(path, "r") as f:
        g = f["contact"]
        g = g[pair or sorted(g.keys())[0]]
        slaves = [k for k in g if g[k].attrs.get("slave", 1) and "node_s" in g[k]]
        if len(slaves) != 1:
            raise ValueError(f"{path}: {len(slaves)} slave surfaces, the zone is not one slave's")
        sl, m = g[slaves[0]], g[surface]
        ss, ps, gs, xs = (sl[n][...] for n in ("node_s", "node_pressure", "node_gap", "node_x"))
        sm, xm = m["node_s"][...].ravel(), m["node_x"][...]
    ss, ps, gs = ss.ravel(), ps.ravel(), gs.ravel()
    i = np.where(ps > 0)[0]

    def end(k, j):
        if j < 0 or j >= len(ss):
            return xs[k]
        t = gs[k] / (gs[k] - gs[j]) if gs[k] < 0 <= gs[j] < 1e300 else 0.5
        return xs[k] + t * (xs[j] - xs[k])

    def arc(x):
        best = (np.inf, 0.0)
        for a in range(len(sm) - 1):
            d = xm[a + 1] - xm[a]
            t = float(np.clip(np.dot(x - xm[a], d) / np.dot(d, d), 0.0, 1.0))
            dist = float(np.linalg.norm(xm[a] + t * d - x))
            if dist < best[0]:
                best = (dist, sm[a] + t * (sm[a + 1] - sm[a]))
        return best[1]

    return 0.5 * abs(arc(end(i[-1], i[-1] + 1)) - arc(end(i[0], i[0] - 1)))


def summary(path, ref=None, masters=False):
    """Per surface: oscillation index, peak, half-width, and the L2 distance
    from the same surface in ref."""
    prof = profiles(path, masters=masters)[0]
    rprof = profiles(ref, masters=masters)[0] if ref else {}
    out = {}
    with h5py.File(path, "r") as f:
        g0 = f["contact"][sorted(f["contact"].keys())[0]]
        slave = {k: g0[k].attrs.get("slave", 1) for k in g0}
    for k, (s, p, w, g) in prof.items():
        d = {"osc": oscillation(s, p, w, g), "pmax": float(p.max()), "a": half_width(s, p, w, g)}
        if not slave[k]:   # a master: its zone is the slave's (slave_zone_half_width)
            d["a_slave_zone"] = slave_zone_half_width(path, k)
            d["osc_slave_zone"] = oscillation_index(s, p, d["a_slave_zone"])
        if k in rprof:
            d["l2_ref"] = l2_distance((s, p), rprof[k])
            d["pmax_ref"] = float(rprof[k][1].max())
            d["a_ref"] = half_width(*rprof[k])
        out[k] = d
    return out


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("h5", nargs="+")
    ap.add_argument("--ref", help="a finer run's HDF5 to measure the distance from")
    ap.add_argument("--masters", action="store_true", help="also the surfaces that are not slaves (transferred pressure)")
    args = ap.parse_args()
    for path in args.h5:
        for k, d in summary(path, args.ref, args.masters).items():
            print(path, k, " ".join(f"{x}={v:.4g}" for x, v in d.items()))
