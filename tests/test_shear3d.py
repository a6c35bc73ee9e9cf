"""Forces given to a 3D frictional pair that friction cannot hold, named
before solving (src/contact/friction3d.c, Friction3dCheckGivenForces: 2D's
src/contact/givenforces.c for a 3D pair): a body held along a flat partner
by one frictional pair alone, given forces alone (rollers on planes normal
to the partner allowed: they react along their axis), whose tangential
force exceeds mu times its normal one at some stage, is one line naming the
pair, the body, the stage and the forces, status 1, nothing written (the
solve itself ended "did not converge", status 2).

The scene: tests/test_friction3d.py's flat patch, a Tet10 box [0, 1]^2 x
[0.5, 1] on a wider Hex27 box [-0.1, 1.1]^2 x [0, 0.5] (E 1000, nu 0.3, mu
0.3), the upper's top given P = 5 down in stage 1 and (Q, 5 down) in stage
2 by force control, its faces y = 0 and y = 1 on rollers (held in y, normal
to the partner's plane z = 0).

Cattaneo-Mindlin for a sphere at a/h = 10.6 (make stress): c/a within 1 % of
Mindlin's at Q/(mu P) = 0.2, 0.5, 0.8, his shear within 10 % at 0.8 alone;
at 0.2 and 0.5 the shear the normal stage locks in (a radial shear of the
ball's curvature, not the mesh's) keeps it off (docs/formulations.md)."""
import math

import numpy as np
import pytest

from conftest import figure, run_contact
from test_friction3d import contact_radius, mindlin_stage, stage_sets

MU, P = 0.3, 5.0
BOX = "tests/meshes/contact3d/box.geo"


def patch_forces(Q):
    return ["-bodies", "lower,upper",
            "-lower_geo", BOX, "-lower_geo_params", "hex=1,n=4,m=2,x0=-0.1,y0=-0.1,L=1.2", "-lower_E", 1000, "-lower_nu", 0.3,
            "-lower_bc", "bottom,xmin,xmax,ymin,ymax", "-lower_bc_bottom_components", "z", "-lower_bc_xmin_components", "x",
            "-lower_bc_xmax_components", "x", "-lower_bc_ymin_components", "y", "-lower_bc_ymax_components", "y",
            "-upper_geo", BOX, "-upper_geo_params", "hex=0,h=0.3,z0=0.5", "-upper_E", 1000, "-upper_nu", 0.3,
            "-upper_bc", "top,ymin,ymax", "-upper_bc_top_components", "x,z", "-upper_bc_top_control", "force,force",
            "-upper_bc_top_values", f"0,{-P},{Q!r},{-P}",
            "-upper_bc_ymin_components", "y", "-upper_bc_ymax_components", "y",
            "-contact_pairs", "p", "-contact_p_surfaces", "upper:bottom,lower:top", "-contact_p_friction", MU,
            "-load_stages", 2]


def lines(r):
    return [l for l in r.stderr.splitlines() if l.strip()]


@pytest.mark.parametrize("ratio", [1.0001, 1.16, 3.0])
def test_force_above_mu_P(ratio, tmp_path):
    """Q = ratio mu P in stage 2: one line naming the pair, the body, stage 2,
    Q (along the partner), P (across it), mu P, Q/(mu P) (to its 6 printed
    digits) and the option to raise, status 1, no output, before any solve."""
    Q = ratio * MU * P
    r = run_contact(patch_forces(Q), tmp_path, check=False)
    out = lines(r)
    assert r.returncode == 1 and len(out) == 1, r.stderr
    assert out[0].startswith("contact: error: pair p: the forces given on body upper at stage 2 are ")
    said = float(out[0].split(" are ")[1].split(" along")[0])
    assert said == pytest.approx(Q, rel=1e-5) and "along lower:top and 5" in out[0]
    assert f"= {MU * P:g};" in out[0] and "-contact_p_friction" in out[0]
    assert float(out[0].split("Q/(mu P) = ")[1].split(")")[0]) == pytest.approx(ratio, rel=1e-5)
    assert not r.summary_path.exists() and not r.output_path.exists()


@pytest.mark.parametrize("extra", [["-upper_bc_top_values", f"0,{-P},{0.9999 * MU * P!r},{-P}"],
                                   ["-upper_bc_top_control", "force,displacement", "-upper_bc_top_values", f"0,-0.01,{3 * MU * P!r},-0.01"],
                                   ["-contact_p_friction", 0]])
def test_not_refused(extra, tmp_path):
    """Not refused where friction may hold or the check cannot know: Q = 0.9999
    mu P; the normal component held by a displacement (it reacts any
    force); no friction. The solve is started (one Newton iteration here)."""
    Q = 1.16 * MU * P
    r = run_contact(patch_forces(Q) + ["-load_steps", 1, "-tao_max_it", 1, "-load_cutbacks", 0] + extra, tmp_path, check=False)
    assert "more than friction holds" not in r.stderr, r.stderr
    assert r.returncode in (0, 2), r.stderr


# Cattaneo-Mindlin for a sphere where Mindlin's assumptions hold as well as
# 2D's verification (tests/test_friction_similar.py: a/hc 12, a/R 0.1): the
# half ball on the half block of tests/test_friction3d.py (R = 1, cut at z =
# 0.5; the block 1.2 x 0.6 x 0.6; E 1000, nu 0.3 both; mu 0.3; the symmetry
# plane y = 0 on rollers, parallel to Q; pressed 0.01 at the top, a/R =
# 0.106, then moved along x in three stages of one increment to Q/(mu P)
# about 0.2, 0.5, 0.8), both meshes graded to h within rc = 0.11 of the first
# contact point and within rc/4 of the plane z = 0 (zs = 4: the size field's
# distance stretched 4 times across the contact plane), growing to hm = 0.04
# within 0.2 and to 0.2 beyond. h = 0.01 (a/h = 10.6, 38,103 dofs, 14 min of
# one core, 2.8 GB) is the verification, under make stress; make test has the
# coarse one (tests/test_friction3d.py, h = 0.025: a/h = 4.2).
G3 = "tests/meshes/friction3d"
SLAVE = "contact/c/ball_cap"
DX = (6.1e-4, 1.65e-3, 3.0e-3)


def graded_args(h):
    top = ",".join(f"{x},-0.01" for x in (0.0,) + DX)
    grade = "rc=0.11,zs=4,hm=0.04,rm=0.2"
    return ["-bodies", "ball,block",
            "-ball_geo", f"{G3}/halfball.geo", "-ball_geo_params", f"zc=0.05,{grade}", "-ball_mesh_size", h,
            "-ball_E", 1000, "-ball_nu", 0.3, "-ball_bc", "top,symy", "-ball_bc_top_components", "x,z",
            "-ball_bc_symy_components", "y", "-ball_bc_top_values", top,
            "-block_geo", f"{G3}/halfblock.geo", "-block_geo_params", f"c=0.2,{grade}", "-block_mesh_size", h,
            "-block_E", 1000, "-block_nu", 0.3, "-block_bc", "bottom,symy", "-block_bc_bottom_components", "x,y,z",
            "-block_bc_symy_components", "y",
            "-contact_pairs", "c", "-contact_c_surfaces", "ball:cap,block:top", "-contact_c_friction", MU,
            "-load_stages", 4, "-load_steps", 1, "-contact_friction_lag_rtol", "1e-6"]


def mindlin_figures(res):
    """Per tangential stage k = 2, 3, 4: Q/(mu P), c/a from Mindlin's (1 -
    Q/(mu P))^(1/3) (c the half disc of the stuck nodes' area, a the
    pressures' second moment about the first contact point), the shear along
    Q against Mindlin's mu p0/a (sqrt(a^2 - r^2) - sqrt(c^2 - r^2)) in
    relative L2 over the slave's nodes (weights A_j; his p0, a, c from the
    computed a and the top's reactions), the same for the shear the normal
    stage left (stage 1's, along x: what is locked in before any Q), and the
    traction's component across Q relative to the whole in L2."""
    sets = stage_sets(res)
    a = contact_radius(sets[-1])
    q1 = -sets[0]["shear"][:, 0]
    out = {}
    for k in (2, 3, 4):
        s = sets[k - 1]
        out[k] = mindlin_stage(s, a, q1, MU)
    return a, out


@pytest.fixture(scope="module")
def fine(tmp_path_factory):
    return run_contact(graded_args(0.01), tmp_path_factory.mktemp("mindlin3d"), timeout=7200)


# The bounds: c/a within 2 % of Mindlin's, his shear within 10 % (L2);
# the fine run's figures (h = 0.01) per stage, the tests' bounds 3 times
# these where that is tighter.
C_BOUND, L2_BOUND = 0.02, 0.10
FINE = {2: dict(c_err=0.0042, l2=0.270, across=0.233), 3: dict(c_err=0.0031, l2=0.127, across=0.098),
        4: dict(c_err=-0.0093, l2=0.082, across=0.063)}


@pytest.mark.stress
def test_mindlin_fine_stick(fine):
    """At a/h = 10.6 (h = 0.01; 38,103 dofs, 14 min of one core), each
    tangential stage's c/a from Mindlin's (mindlin_figures):
    `c_over_a_error_2` = +0.0042, `c_over_a_error_3` = +0.0031,
    `c_over_a_error_4` = -0.0093 at `ratio_2` = 0.2018, `ratio_3` = 0.5095,
    `ratio_4` = 0.8265 (bounds 3 times each, not beyond the issue's 2 %;
    a/h = 4.2 gave +2.3 %, +1.2 %, +0.65 %: tests/test_friction3d.py). The
    traction's component across Q in L2: `across_2` = 0.233, `across_3` =
    0.098, `across_4` = 0.063, bound 3 times at 0.8 alone (as
    tests/test_friction3d.py's 0.2 there): at 0.2 and 0.5 the normal
    stage's radial shear (its y part: 0.105 and 0.072 without it) is most
    of it."""
    _, f = mindlin_figures(fine)
    for k in (2, 3, 4):
        figure(f"ratio_{k}", f[k]["ratio"])
        err = figure(f"c_over_a_error_{k}", f[k]["c_err"])
        figure(f"across_{k}", f[k]["across"])
        assert abs(err) <= min(C_BOUND, 3 * abs(FINE[k]["c_err"]))
    assert f[4]["across"] <= 3 * FINE[4]["across"]


def bounded(k):
    """Stage k's case, xfail (strict) where the fine run's shear is not within the issue's 10 %."""
    if FINE[k]["l2"] <= L2_BOUND:
        return k
    return pytest.param(k, marks=pytest.mark.xfail(strict=True, reason=f"shear {FINE[k]['l2']:.2f} from Mindlin's: the normal stage's radial shear (docs/formulations.md)"))


@pytest.mark.stress
@pytest.mark.parametrize("k", [bounded(k) for k in (2, 3, 4)])
def test_mindlin_fine_shear(fine, k):
    """At a/h = 10.6 (h = 0.01), stage k's shear along Q against Mindlin's,
    relative L2 (mindlin_figures): `l2` = 0.270 to 0.082 (0.270, 0.127,
    0.082 at Q/(mu P) = 0.2, 0.5, 0.8; a/h = 4.2 gave 0.39, 0.17, 0.11),
    bound the issue's 10 % (3 times the figure where tighter). The normal
    stage's locked-in shear alone (its x part) is `locked` = 0.275 to 0.073
    (0.275, 0.117, 0.073) of Mindlin's; the shear less it is 0.151, 0.091,
    0.087 from his. At 0.2 and 0.5 the shear is not within 10 %: xfail
    (strict). What keeps it off is that radial shear of the normal stage,
    outward on the ball, about 0.065 mu p0 at r = 0.5 to 0.7 a at a/h =
    2.7, 5.3 and 10.6 alike (not the mesh's), halved at a/R = 0.05 (the
    ball's curvature: Mindlin's half-spaces have none;
    docs/formulations.md)."""
    _, f = mindlin_figures(fine)
    figure("locked", f[k]["locked"])
    l2 = figure("l2", f[k]["l2"])
    assert l2 <= min(L2_BOUND, 3 * FINE[k]["l2"])
