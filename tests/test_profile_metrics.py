"""scripts/profile_metrics.py against analytic profiles (no program run): the
oscillation index of an exact Hertz profile and of one with a saw-tooth, the
L2 distance of a profile from itself and from a scaled copy, the half-width
of a sampled Hertz profile. Each test names the defect it would catch."""
import numpy as np
import pytest

import profile_metrics as pm

EPS = np.finfo(float).eps
A, PMAX, C0 = 0.35, 100.0, 0.2   # half-width, peak and centre of the Hertz profile (about the reference scene's)
R, KP = 1.0, 2e6                  # indenter radius and penalty, for the gaps


def hertz(s, a=A):
    return PMAX * np.sqrt(np.clip(1.0 - ((s - C0) / a) ** 2, 0.0, None))


def uniform():
    """Spacing a / 12 (a/h = 6 for P2 edges), nodes at the centre and the ends, none at 0.8 a."""
    return C0 + A / 12 * np.arange(-20, 21)


def gauss():
    """Three Gauss points on each of 15 edges of length 0.1 (non-uniform: a
    gpts surface), the middle edge's middle point at the centre."""
    e = C0 + 0.1 * np.arange(-7.5, 7.5)
    xi = np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])
    return (e[:, None] + 0.05 * (1 + xi)[None, :]).ravel()


def graded():
    """Spacing growing from 0.005 at the centre to 0.06 at |s - C0| = 0.7 (a graded mesh)."""
    u = np.linspace(-1.0, 1.0, 61)
    return C0 + 0.7 * np.sinh(3.0 * u) / np.sinh(3.0)


GRIDS = {"uniform": uniform, "gauss": gauss, "graded": graded}


@pytest.mark.parametrize("grid", GRIDS)
def test_hertz_profile_has_no_oscillation(grid):
    """Hertz's profile sampled on any grid that has a sample at its peak gives
    an index of 0 to round-off. Catches an index that counts the curvature of
    the square-root edge as oscillation (the former definition gives 0.012 on
    the uniform grid), or that subtracts a Hertz profile with another centre,
    half-width or peak, or at shifted samples. Measured 0 (uniform, graded)
    and 1.4e-16 (gauss), bound 100 EPS (was 1e-12); the sampled peak is PMAX
    exactly, bound 100 EPS of it (was 1e-12)."""
    s = GRIDS[grid]()
    print(f"{grid}: sampled peak {hertz(s).max() - PMAX:.2e} from PMAX")
    assert np.isclose(hertz(s).max(), PMAX, rtol=0, atol=100 * EPS * PMAX)
    osc = pm.oscillation_index(s, hertz(s), A)
    print(f"{grid}: {len(s)} samples, index {osc:.2e}")
    assert osc < 100 * EPS


@pytest.mark.parametrize("grid", GRIDS)
def test_saw_tooth(grid):
    """A saw-tooth of amplitude eps (+eps at the peak, alternating) on the samples
    within 0.95 a adds 2 eps sigma_i (sigma_i = +-1) to each neighbour deviation
    within 0.8 a (whose neighbours are all within 0.95 a).
    The peak becomes PMAX + eps, so the subtracted Hertz profile is (1 + eps /
    PMAX) times the exact one and the index is, exactly,
        max_i |2 sigma_i - dev(hertz)_i / PMAX| eps / (PMAX + eps),
    2 eps / (PMAX + eps) up to the exact profile's neighbour deviation over its
    peak (under 1 % of it here). Catches a wrong amplitude (a deviation from
    one neighbour, or from the mean of the wrong pair), a normalisation other
    than the computed peak, a window other than 0.8 a about the centroid.
    The index against the formula: measured 26 to 52 EPS of it, bound 1000
    EPS of it (was 1e-9 absolute, 1e5 times the index's round-off); the
    formula against 2 eps / (PMAX + eps): measured +0.42 % (graded), +0.62 %
    (uniform), +0.91 % (gauss), bound 2 % (was 1 %, within 10 % of the
    gauss grid's figure)."""
    s = GRIDS[grid]()
    eps = 0.5
    i0 = int(np.argmin(np.abs(s - C0)))
    sigma = np.where((np.arange(len(s)) - i0) % 2 == 0, 1.0, -1.0)
    inner = s[1:-1]
    window = np.abs(inner - C0) <= 0.8 * A
    sawed = np.abs(s - C0) <= 0.95 * A
    i = np.nonzero(window)[0] + 1
    assert sawed[i - 1].all() and sawed[i + 1].all()
    p = hertz(s) + np.where(sawed, eps * sigma, 0.0)
    assert not np.any(np.isclose(np.abs(inner - C0), 0.8 * A))          # no sample on the window's edge
    dh = pm.neighbour_deviation(hertz(s))
    expected = np.max(np.abs(2 * sigma[1:-1] - dh / PMAX)[window]) * eps / (PMAX + eps)
    osc = pm.oscillation_index(s, p, A)
    print(f"{grid}: index {osc:.10f}, expected {expected:.10f}, 2 eps / peak {2 * eps / (PMAX + eps):.10f}")
    assert abs(osc - expected) <= 1000 * EPS * expected
    assert abs(expected / (2 * eps / (PMAX + eps)) - 1) < 0.02


def test_neighbour_deviation():
    """The deviation of each inner sample from the mean of its two neighbours:
    0 on a straight line, 2 eps on an alternating +-eps. Catches an off-by-one
    between the sample and its neighbours. Measured 0 for both, bound 100
    EPS of the values (was 1e-15 absolute)."""
    x = np.linspace(0.0, 1.0, 9)
    alt = 0.25 * (-1.0) ** np.arange(9)
    print(f"line {np.abs(pm.neighbour_deviation(3 * x + 1)).max():.2e}, "
          f"alternating {np.abs(pm.neighbour_deviation(alt) - 2 * alt[1:-1]).max():.2e}")
    assert np.abs(pm.neighbour_deviation(3 * x + 1)).max() <= 100 * EPS * 4
    assert np.abs(pm.neighbour_deviation(alt) - 2 * alt[1:-1]).max() <= 100 * EPS * 0.5


def trapezoid(s):
    w = np.zeros_like(s)
    w[1:] += 0.5 * np.diff(s)
    w[:-1] += 0.5 * np.diff(s)
    return w


@pytest.mark.parametrize("grid", GRIDS)
def test_l2_distance_of_itself_and_scaled(grid):
    """A profile is at distance 0 from itself, and (1 + d) p at distance |d|
    from p (relative to the fine profile). Catches a normalisation by the
    coarse profile (d / (1 + d)), a missing square root (d^2), an
    interpolation at the wrong samples (non-zero distance from itself).
    Measured 0 from itself and 3.5e-18 to 5.6e-17 off |d| for the copies,
    bound 100 EPS (was 1e-12)."""
    s = GRIDS[grid]()
    p, w = hertz(s), trapezoid(s)
    assert pm.l2_distance((s, p), (s, p, w)) == 0.0
    for d in (0.01, -0.03, 0.2):
        print(f"{grid}: d = {d}: {abs(pm.l2_distance((s, (1 + d) * p), (s, p, w)) - abs(d)):.2e} off")
        assert abs(pm.l2_distance((s, (1 + d) * p), (s, p, w)) - abs(d)) <= 100 * EPS


def test_l2_distance_interpolates_linearly():
    """A coarse profile linear between its samples, compared at finer samples
    of the same piecewise-linear function: distance 0 to round-off. Catches
    interpolating the fine profile at the coarse samples instead, or a
    nearest-sample lookup. Measured 0, bound 100 EPS (was 1e-14)."""
    sc = np.linspace(-1.0, 1.0, 11)
    pc = np.abs(np.sin(3 * sc)) + 1.0
    sf = np.linspace(-1.0, 1.0, 101)
    pf = np.interp(sf, sc, pc)
    print(f"distance {pm.l2_distance((sc, pc), (sf, pf, trapezoid(sf))):.2e}")
    assert pm.l2_distance((sc, pc), (sf, pf, trapezoid(sf))) <= 100 * EPS


def hertz_gap(s, a=A):
    """The nodal gap of a penalty Hertz contact: -p / k_p inside, Hertz's
    separation outside, (a^2 / 2R) (t sqrt(t^2 - 1) - acosh t), t = |s - c| / a."""
    t = np.abs(s - C0) / a
    tt = np.maximum(t, 1.0)
    out = a * a / (2 * R) * (tt * np.sqrt(tt * tt - 1) - np.arccosh(tt))
    return np.where(t < 1, -hertz(s, a) / KP, out)


def brackets(s, a=A):
    """The spacing of the two samples on either side of each end of the zone."""
    lo, hi = C0 - a, C0 + a
    j, k = np.searchsorted(s, lo), np.searchsorted(s, hi)
    return s[j] - s[j - 1], s[k] - s[k - 1]


def shifted_grids():
    """Grids on which the ends of the zone fall at other places between samples,
    and a non-uniform one, without a sample on an end."""
    yield "uniform", C0 + 0.3 * A / 12 + A / 12 * np.arange(-20, 21)
    yield "graded", graded() + 0.0031
    yield "gauss", gauss() + 0.017


@pytest.mark.parametrize("grid, s", list(shifted_grids()))
def test_half_width_with_gaps(grid, s):
    """The zone's ends where the gap, linear between the last loaded and the
    first unloaded sample, vanishes: each end lies within its bracketing
    spacing, so |half_width - a| <= (bracket at the low end + bracket at the
    high end) / 2. With a gap that is itself linear near the ends (|s - c| - a),
    the ends are exact. Catches the wrong pair of samples, a wrong sign in the
    interpolation, an end taken from the last loaded sample. Measured
    |half_width - a| 0.0140 (uniform), 0.0049 (graded), 0.0178 (gauss)
    against those bounds, 0.0292, 0.0370, 0.0387 (the bounds are the
    brackets, not a measured spread); with the linear gap 0 to 5.6e-17,
    bound 100 EPS of a (was 1e-12)."""
    p = hertz(s)
    blo, bhi = brackets(s)
    tol = 0.5 * (blo + bhi)
    hw = pm.half_width(s, p, trapezoid(s), hertz_gap(s))
    print(f"{grid}: half-width {hw:.6f} (a {A}), tolerance {tol:.4f}")
    exact = abs(pm.half_width(s, p, trapezoid(s), np.abs(s - C0) - A) - A)
    print(f"linear gap: half-width {exact:.2e} off")
    assert abs(hw - A) <= tol
    assert exact <= 100 * EPS * A


@pytest.mark.parametrize("grid, s", list(shifted_grids()))
def test_half_width_without_gaps(grid, s):
    """Gauss-point profiles have no gap: each end half-way between the last
    loaded and the first unloaded sample, within half its bracket, so
    |half_width - a| <= (bracket low + bracket high) / 4. Catches ends taken
    at the loaded samples or beyond the unloaded ones. Measured against the
    mid-points 0, bound 100 EPS of a (was 1e-15 absolute); against a 0
    (uniform, gauss: an end falls on a mid-point) and 0.0135 (graded, bound
    0.0185: the bound is the brackets')."""
    blo, bhi = brackets(s)
    lo = s[np.searchsorted(s, C0 - A) - 1:np.searchsorted(s, C0 - A) + 1].mean()
    hi = s[np.searchsorted(s, C0 + A) - 1:np.searchsorted(s, C0 + A) + 1].mean()
    hw = pm.half_width(s, hertz(s), trapezoid(s), None)
    print(f"{grid}: half-width {hw:.6f}, {abs(hw - 0.5 * (hi - lo)):.2e} from the mid-points', {abs(hw - A):.4f} from a "
          f"(bound {0.25 * (blo + bhi):.4f})")
    assert abs(hw - 0.5 * (hi - lo)) <= 100 * EPS * A
    assert abs(hw - A) <= 0.25 * (blo + bhi)
