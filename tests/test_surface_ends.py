"""Surfaces that end where their geometry ends (src/contact/gap.c,
ContactGapBeyondEnd; surface.c's endTurn), and the mortar slave chosen
whatever the order of the pair's surfaces (mortar.c, MortarChooseSlaves).

The punch scene (meshes/punch): a flat punch (half-width b = 0.25, E = 1e7,
square corners) pressed by 0.002 into a block 4 x 2 (E = 100). Sadowsky's
pressure under a rigid flat punch on a half-plane, p = P / (pi sqrt(b^2 -
x^2)), holds away from the corners (|x| < 0.6 b); past the punch the block's
top is free. Before the surfaces ended, the block as slave saw the punch's
face continued by its tangent line to x = +-2: P = 0.2639 where the punch as
slave gave 0.1503, and the block's top carried pressure to its ends.

A disc pushed near the end of a short block (the reference scene with the
disc centred at y = 0.9, so that its contact zone reaches past the block's
corner at y = 1): the corner carries the pressure and nothing beyond it.

A stiff disc on a soft slab (hertz-small's geometry, E 5e4 on 200, a/h about
7): the pressure read does not depend on which surface is named first, and
is Hertz's."""
import numpy as np
import pytest

from conftest import figure, run_contact

PUNCH = ["-options_file", "meshes/punch/punch.opts"]
# the stiff punch (E = 1e7 on 100) leaves the default stop's P far from the
# answer: the punch as mortar's slave 0.151127 against 0.150326 at gttol
# 1e-12, gpts 0.1521 against 0.150458, where it stops depending on the BLAS
# kernel (gpts -0.23 % to +0.66 % from mortar's over the five kernels): those
# runs are solved to gttol 1e-12. The block as slave (alone or with the
# punch) runs at the default stop: it crawled past a minute from gttol 1e-10
# on until the ramp past the punch's corners had segments of its own
# (mortar.c, MortarSplitRamp); now its default stop is 2e-5 of P from its
# answer at gttol 1e-12 (4 s).
TIGHT = ["-tao_gttol", "1e-12"]
B = 0.25
ORDERS = {"punch-first": "punch:contact,block:contact", "block-first": "block:contact,punch:contact"}


def profile(h5, pair, surface):
    """(X, x, p, w, slave) of a surface's nodal profile (mortar) or Gauss-point profile (gpts)."""
    g = h5[f"contact/{pair}/{surface}"]
    k = "node_" if "node_X" in g else ""
    return g[k + "X"][...], g[k + "x"][...], g[k + "pressure"][...], g[k + "weight"][...], bool(g.attrs["slave"])


def sadowsky_l2(X, p, w, P):
    """Relative L2 distance (weights w) of p from Sadowsky's p = P / (pi sqrt(b^2 - x^2)) over |x| < 0.6 b."""
    m = np.abs(X[:, 0]) < 0.6 * B
    ps = P / (np.pi * np.sqrt(B * B - X[m, 0] ** 2))
    return float(np.sqrt(np.sum(w[m] * (p[m] - ps) ** 2) / np.sum(w[m] * ps ** 2)))


@pytest.fixture(scope="module")
def punch_runs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("punch")
    runs = {}
    for name, order in ORDERS.items():
        runs["mortar", name] = run_contact(PUNCH + TIGHT + ["-contact_tool_surfaces", order], tmp, name=f"mortar-{name}")
    # the slave named first is the punch, named first: the automatic choice's
    # run (the same P and energy to the last digit, measured)
    runs["mortar", "first"] = runs["mortar", "punch-first"]
    runs["mortar", "second"] = run_contact(PUNCH + ["-contact_mortar_slave", "second"], tmp, name="mortar-second")
    for f, extra in (("gpts", TIGHT + ["-contact_formulation", "gpts"]), ("both", ["-contact_mortar_slave", "both"])):
        runs[f, "punch-first"] = run_contact(PUNCH + extra, tmp, name=f)
    return runs


def test_punch_order_does_not_matter(punch_runs):
    """mortar's automatic slave is the punch, whichever surface is named first
    (its face ends on the block): the same P to round-off, both solved to gttol
    1e-12 (`dP` = 0 to 4.4e-16 over the five kernels, bound 1e-12), the punch's
    nodal pressure within 3 % of Sadowsky's (measured `sadowsky` = 0.0086, both
    orders), and the block's top free beyond one of its elements past the punch
    (the master's transferred pressure is the slave's corner force spread over
    the block element that holds the corner)."""
    P = {}
    for name in ORDERS:
        r = punch_runs["mortar", name]
        with r.h5() as h5:
            X, x, p, w, slave = profile(h5, "tool", "punch_contact")
            P[name] = r.summary["contact"]["tool"]["P"]
            assert slave, f"{name}: the punch is not the slave"
            err = figure("sadowsky", sadowsky_l2(X, p, w, P[name]))
            Xb, xb, pb, wb, slave_b = profile(h5, "tool", "block_contact")
            assert not slave_b
            beyond = np.abs(Xb[:, 0]) > B + 0.0125
            print(f"{name}: P = {P[name]:.6f}, punch's pressure {100 * err:.2f} % from Sadowsky; "
                  f"block's largest |p| beyond b + h: {np.abs(pb[beyond]).max():.3g}")
            assert err <= 0.03
            assert np.all(pb[beyond] == 0.0)
    assert abs(figure("dP", P["punch-first"] / P["block-first"] - 1)) <= 1e-12


def test_punch_block_as_slave(punch_runs):
    """The block forced as slave (-contact_mortar_slave): it no longer takes
    the punch's face past its corners (P 0.2639 before, 1.76 times the punch as
    slave's): P within 2 % of the punch as slave's (measured `dP` = -1.8e-3,
    the block as slave at the default stop (PUNCH), the punch as slave at
    gttol 1e-12; 3.1e-4 over the five kernels while the block as slave
    stalled short of its answer; the -0.50 % measured
    before was against the punch as slave at the default stop, which leaves its
    P 0.53 % high, as the 0.4 to 3 % low once quoted over k_p and meshes may
    have been), the block's pressure within 3 % of Sadowsky's under the punch
    (measured `sadowsky` = 0.0043), and zero beyond one of its elements past
    the punch."""
    Pf = punch_runs["mortar", "first"].h5()["contact/tool"].attrs["P"]
    r = punch_runs["mortar", "second"]
    with r.h5() as h5:
        P = h5["contact/tool"].attrs["P"]
        X, x, p, w, slave = profile(h5, "tool", "block_contact")
        assert slave
        err = figure("sadowsky", sadowsky_l2(X, p, w, P))
        figure("dP", P / Pf - 1)
        beyond = np.abs(X[:, 0]) > B + 0.00625
        print(f"block as slave: P = {P:.6f} ({100 * (P / Pf - 1):+.2f} % of the punch as slave's), "
              f"{100 * err:.2f} % from Sadowsky, largest p beyond b + h {p[beyond].max():.3g}")
        assert abs(P / Pf - 1) <= 0.02
        assert err <= 0.03
        assert np.all(p[beyond] == 0.0)


@pytest.mark.parametrize("variant", ["gpts", "both"])
def test_punch_two_way(variant, punch_runs):
    """gpts and mortar with both surfaces as slaves: the punch's face ends at
    its corners for them too (before: P 0.2639, the block's top in contact to
    its ends). P within 3 % of mortar's one-sided (measured `dP_gpts` = 8.8e-4
    over the five kernels, `dP_both` = 1.7e-3, -1.5e-4 while its block half
    stalled short of its answer; gpts solved to gttol 1e-12 as
    the one-sided run, both at the default stop (PUNCH); the +1.18 % and
    +0.97 % measured before were against the one-sided run's default stop,
    0.53 % high, and gpts' own, up to 1 % high), and the block free beyond the
    punch. gpts' pressure under the punch is `sadowsky_gpts` = 0.084 from
    Sadowsky's (its Gauss-point saw-tooth), both's `sadowsky_both` = 0.0046:
    held at 20 % and 3 %, over twice the figures."""
    Pm = punch_runs["mortar", "first"].h5()["contact/tool"].attrs["P"]
    with punch_runs[variant, "punch-first"].h5() as h5:
        P = h5["contact/tool"].attrs["P"]
        X, x, p, w, slave = profile(h5, "tool", "block_contact")
        beyond = np.abs(X[:, 0]) > B + 0.0125
        Xp, xp, pp, wp, _ = profile(h5, "tool", "punch_contact")
        print(f"{variant}: P = {P:.6f} ({100 * (P / Pm - 1):+.2f} % of mortar's), "
              f"punch's pressure {100 * sadowsky_l2(Xp, pp, wp, P):.1f} % from Sadowsky, "
              f"block's largest |p| beyond b + h {np.abs(p[beyond]).max():.3g}")
        assert abs(figure(f"dP_{variant}", P / Pm - 1)) <= 0.03
        assert figure(f"sadowsky_{variant}", sadowsky_l2(Xp, pp, wp, P)) <= {"gpts": 0.2, "both": 0.03}[variant]
        assert np.all(p[beyond] == 0.0)


@pytest.fixture(scope="module")
def corner_runs(tmp_path_factory):
    """The reference scene with the disc at y = 0.9 (h = 0.05), each slave choice once."""
    tmp = tmp_path_factory.mktemp("corner")
    return {slave: run_contact(["-options_file", "meshes/hertz/hertz.opts", "-indenter_geo_params",
                                "R=1,xc=-1,yc=0.9,xclamp=-1.8,xcontact=-0.5", "-mesh_size", "0.05",
                                "-contact_mortar_slave", slave], tmp, name=slave)
            for slave in ("auto", "first")}


@pytest.mark.roundoff
@pytest.mark.parametrize("slave", ["auto", "first"])
def test_disc_past_the_corner(slave, corner_runs):
    """The reference scene with the disc at y = 0.9 (h = 0.05): its contact
    zone (y from about 0.6 to past 1.1 on the undeformed disc) reaches past the
    block's corner at y = 1. auto takes the block as slave (its edge ends on
    the disc): the corner node carries the largest pressure, and the disc's
    transferred pressure is zero beyond one element past the corner (measured 0
    from 0.05 past it). The disc forced as slave: its pressure is zero beyond
    one element past the corner. The pair's force on the block equals minus the
    pushed edge's reaction to what the stop allows: the block's energy is
    invariant under its translation, so the difference is a sum of the gradient
    over the block's free dofs, at most sqrt(n) ||g|| (test_robustness), plus
    1000 EPS of P for the sums (measured `balance` = 0.0016 to 0.006 of that
    bound over both slaves and the five kernels; `imbalance` = 4.3e-14 to
    1.8e-7 of P: the disc as slave, the block's corner inside its edges, stops
    at 4.3e-14 since the ramp past that corner has its own segments, at 2.2e-8
    before)."""
    r = corner_runs[slave]
    with r.h5() as h5:
        X, x, p, w, disc_slave = profile(h5, "interface", "indenter_contact")
        Xb, xb, pb, wb, block_slave = profile(h5, "interface", "block_contact")
        P = h5["contact/interface"].attrs["P"]
    corner = xb[np.argmax(Xb[:, 1]), 1]                # the block's corner, current y
    beyond = x[:, 1] > corner + 0.05
    print(f"{slave}: P = {P:.4f}, corner at y = {corner:.4f}, disc's largest |p| beyond it {np.abs(p[beyond]).max():.3g}; "
          f"block's largest p {pb.max():.4g} at y = {xb[np.argmax(pb), 1]:.4f}")
    assert disc_slave == (slave == "first") and block_slave == (slave == "auto")
    assert np.all(p[beyond] == 0.0)
    if slave == "auto":
        assert np.argmax(pb) == np.argmax(Xb[:, 1])    # the corner node carries the peak
    F = r.summary["contact"]["interface"]["surfaces"][1]["force"]   # on the block
    R = r.summary["reactions"]["block:push"]
    print(f"  force on the block {F}, reaction at its pushed edge {R}")
    bound = np.sqrt(r.summary["dofs"]) * r.summary["gradient_norm"] + 1000 * np.finfo(float).eps * P
    figure("imbalance", np.hypot(F[0] + R[0], F[1] + R[1]) / P)
    assert figure("balance", np.hypot(F[0] + R[0], F[1] + R[1]) / bound) <= 1


def test_disc_past_the_corner_either_slave(corner_runs):
    """The two slave choices of the scene above, each a discretisation of the
    same contact, give P within 0.5 % of each other (measured
    `P` = 41.097 to 41.152, the two apart by `dP` = -0.0013 over the five
    kernels)."""
    P = {k: figure("P", r.summary["contact_force"]) for k, r in corner_runs.items()}
    assert abs(figure("dP", P["first"] / P["auto"] - 1)) <= 0.005


STIFF = ["-options_file", "meshes/hertz-small/hertz-small.opts",
         "-indenter_geo_params", "R=1,xc=-1,yc=0,xclamp=-1.8,xcontact=-0.5,hc=0.017,dc=1",
         "-block_geo_params", "x0=0,W=1,H=2,hc=0.017,dc=1", "-indenter_E", "5e4", "-block_E", "200",
         "-contact_penalty", "auto", "-tao_gttol", "1e-12"]


def test_stiff_disc_either_order(tmp_path):
    """A disc 250 times stiffer than the slab, either surface named first: auto
    takes the slab as slave both times, so the same p_max and profile to
    round-off, both solved to gttol 1e-12 (`dpmax` = 0 and `dl2` = 0 to 1.4e-14
    apart over the five kernels, bound 1e-12), p_max within 2 % of Hertz
    (measured `pmax` = 7.0e-6) and the profile within 8 % (measured
    `l2` = 0.01). (The stiff disc forced as slave is further off: p_max +2.3 %,
    profile 4.3 % here, 24 % where the slab is coarser; measured once, not run
    here.)"""
    figs = []
    for order in ("indenter:contact,block:contact", "block:contact,indenter:contact"):
        s = run_contact(STIFF + ["-contact_interface_surfaces", order], tmp_path, name=order.split(":")[0]).summary
        print(f"{order}: p_max {s['fem_pmax']:.6g} (Hertz {s['hertz_pmax']:.6g}), profile {100 * s['pressure_l2_error']:.2f} %")
        figs.append(s)
    a, b = figs
    assert abs(figure("dpmax", a["fem_pmax"] / b["fem_pmax"] - 1)) <= 1e-12
    assert abs(figure("dl2", a["pressure_l2_error"] / b["pressure_l2_error"] - 1)) <= 1e-12
    assert abs(figure("pmax", a["fem_pmax"] / a["hertz_pmax"] - 1)) <= 0.02
    assert figure("l2", a["pressure_l2_error"]) <= 0.08
