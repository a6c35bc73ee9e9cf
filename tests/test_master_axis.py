"""A mortar master's transferred pressure (src/contact/mortar.c,
MortarSlavePressureAt): on the axis of an axisymmetric contact, and its
oscillation index on a soft disc pressed on a stiff slab. Expected values
from outside the program:

- the axisymmetric contact patch test (two stacked cylinders with the same
  nu / E, non-matching meshes, pressed by d): a uniform pressure
  p = d / (H1/E1 + H2/E2 + 1/k_p) at every node of both surfaces, the
  master's included, whatever the node's distance from the axis;
- a transferred pressure is the slave's profile resampled, so no more
  oscillating than the slave's own (scripts/profile_metrics.py)."""
import numpy as np
import pytest

from conftest import figure, run_contact

import profile_metrics as pm

D, KP = 0.01, 1e6
P = D / (1 / 1000 + 1 / 2000 + 1 / KP)


@pytest.mark.roundoff
@pytest.mark.parametrize("ranks", [1, 2])
@pytest.mark.parametrize("master", ["tri6", "quad9"])
def test_axis_patch_master_exact(master, ranks, tmp_path):
    """Two stacked cylinders in r-z (below E 1000, nu 0.2, the softer: the
    slave, its mesh h = 0.25; above E 2000, nu 0.4, the master, h = 0.1: its
    nodes at r = 0.05 and 0.1 face the first half of the slave's edge from
    the axis), Quad9 against Tri6 or Tri6 against Quad9, pressed by
    d = 0.01, k_p = 1e6, solved to an absolute gradient of 1e-8: every
    master node's pressure (20, the axis node has no weight) is p
    (`master_err` = 1.5e-11 to 1.4e-9 relative over the cases and
    OpenBLAS's default and Prescott kernels, the solve's: the slave's own
    nodes `slave_err` = 1.6e-11 to 1.4e-9; bound 1e-8). The slave's
    corner on the axis has no weight, hence no pressure of its own, and was
    read as 0: the master's nodes at r = 0.05 and 0.1 showed 0.4 p and
    0.8 p."""
    qlow, qup = (1, 0) if master == "tri6" else (0, 1)
    args = ["-scene", "stack", "-axisymmetric", "-bodies", "low,up",
            "-low_geo", "tests/meshes/plate.geo", "-low_geo_params", f"L=1,H=1,quads={qlow}", "-low_mesh_size", 0.25,
            "-low_E", 1000, "-low_nu", 0.2, "-low_bc", "bottom", "-low_bc_bottom_components", "y",
            "-up_geo", "tests/meshes/plate.geo", "-up_geo_params", f"y0=1,L=1,H=1,quads={qup}", "-up_mesh_size", 0.1,
            "-up_E", 2000, "-up_nu", 0.4, "-up_bc", "top", "-up_bc_top_components", "y", "-up_bc_top_values", -D,
            "-contact_pairs", "i", "-contact_i_surfaces", "low:top,up:bottom", "-contact_penalty", KP,
            "-tao_gatol", 1e-8, "-tao_gttol", 0]
    r = run_contact(args, tmp_path, ranks=ranks)
    with r.h5() as f:
        low, up = f["contact/i/low_top"], f["contact/i/up_bottom"]
        assert low.attrs["slave"] == 1 and up.attrs["slave"] == 0
        pm_, rm = up["node_pressure"][...].ravel(), up["node_X"][:, 0]
        ps = low["node_pressure"][...].ravel()
    first = np.argsort(rm)[:2]
    assert np.allclose(rm[first], [0.05, 0.1])
    merr = figure("master_err", np.max(np.abs(pm_ / P - 1)))
    serr = figure("slave_err", np.max(np.abs(ps / P - 1)))
    print(f"{master} master, {ranks} ranks: first nodes off the axis {pm_[first]} (p {P:.6g}); errors {merr:.1e}, {serr:.1e}")
    assert len(pm_) == 20 and merr < 1e-8 and serr < 1e-8


def test_soft_disc_master_oscillation(tmp_path):
    """A disc (R = 1, E 100, nu 0.3, graded Tri6 hc = 0.02) pushed by 0.02 on
    a slab 1000 times stiffer (E 1e5, Quad9 graded to hc = 0.02), plane
    strain, mortar: the disc is the slave, the slab's pressure transferred.
    The slave's oscillation index `slave_osc` = 0.0073; the master's
    measured with its zone, the slave's (profile_metrics.slave_zone_half_width,
    `master_zone_a` = 0.0911), `master_osc` = 0.0053: at most 0.01 and the
    slave's + 0.002. With the half-width its own samples give
    (`master_own_a` = 0.110, 18 % wide: its nodal gap, weighted over the
    master's edges, stays positive at the last node the pressure reaches)
    the index reads `master_osc_own_a` = 0.044: the Hertz profile it
    subtracts is the wrong one, not the profile oscillating. The same under
    OpenBLAS's default and Prescott kernels."""
    geo = "R=1,xc=-1,yc=0,xclamp=-1.8,xcontact=-0.5,hc=0.02,dc=1"
    args = ["-scene", "softdisc2", "-bodies", "disc,slab",
            "-disc_geo", "meshes/hertz/indenter.geo", "-disc_geo_params", geo, "-disc_mesh_size", 0.1,
            "-disc_E", 100, "-disc_nu", 0.3, "-disc_bc", "clamp", "-disc_bc_clamp_components", "x,y",
            "-disc_bc_clamp_values", "0.02,0",
            "-slab_geo", "meshes/hertz/block.geo", "-slab_geo_params", "x0=0,W=1,H=2,hc=0.02,dc=1", "-slab_mesh_size", 0.1,
            "-slab_E", 1e5, "-slab_nu", 0.3, "-slab_bc", "push", "-slab_bc_push_components", "x,y",
            "-contact_pairs", "i", "-contact_i_surfaces", "disc:contact,slab:contact"]
    r = run_contact(args, tmp_path)
    prof, _ = pm.profiles(r.output_path, masters=True)
    s, p, w, g = prof["slab_contact"]
    a = figure("master_zone_a", pm.slave_zone_half_width(r.output_path, "slab_contact"))
    osc_s = figure("slave_osc", pm.oscillation(*prof["disc_contact"]))
    osc_m = figure("master_osc", pm.oscillation_index(s, p, a))
    figure("master_own_a", pm.half_width(s, p, w, g))
    figure("master_osc_own_a", pm.oscillation(s, p, w, g))
    assert p.min() >= 0
    assert osc_s <= 0.01 and osc_m <= 0.01 and osc_m <= osc_s + 0.002
    assert abs(a / pm.half_width(*prof["disc_contact"]) - 1) < 0.05   # the slave's zone, on the slab's arc
