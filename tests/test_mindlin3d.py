"""Cattaneo-Mindlin for two identical spheres: the 3D pair's friction
(src/contact/friction3d.c on src/contact/mortar3d.c) where Mindlin's
assumptions hold (docs/formulations.md, "Friction between 3D bodies").

The scene: two half balls R = 1 (tests/meshes/friction3d/halfball.geo, y >=
0, cut at z = +-0.5, the lower the upper's mirror image about the contact
plane z = 0, dir=-1: 1/R* = 2/R), E 1000, both nu 0.3 (or both 0), mu 0.3,
the planes y = 0 on rollers, parallel to Q. Elastically similar and
mirror-symmetric, the normal problem locks no shear in (equal radial
displacements: Mindlin's similar spheres). The lower's top is held, the
upper's pressed by 0.02 (a/R = 0.105 to 0.107) in a first stage, then moved
along x in three stages of one increment each to Q/(mu P) about 0.2, 0.5
and 0.8, Q and P the upper top's reactions (doubled: half model). Both
meshes graded as tests/test_shear3d.py's (rc = 0.11, zs = 4, hm = 0.04,
rm = 0.2) and meshed apart (not mirror images node for node), or the lower's
the upper's reflected node for node (mirrored_meshes).

Mindlin: a disc of radius c = a (1 - Q/(mu P))^(1/3) sticks, the shear
along Q is mu p0/a (sqrt(a^2 - r^2) - sqrt(c^2 - r^2)) (the second term
within c), p0 = 3 P/(2 pi a^2), exactly parallel to Q at nu = 0 (Johnson,
Contact Mechanics 7.2). make test: a/h = 2.7 (h = 0.04, 17,983 dofs, 2 to 3
min each on the loaded machine), meshed apart and mirrored; make stress: a/h
= 5.3 (h = 0.02, 20,739 and 20,802 dofs, 8 min each) at nu 0.3 and 0, and h
= 0.04 at nu = 0, and a/h = 10.5 (h = 0.01, 35,304 dofs, meshed apart, nu
0.3: 61 min on the loaded machine; mirrored, nu 0.3: 15 min), a/h = 13
mirrored (h = 0.008, 50,504 dofs, nu 0.3: 49 min), and a/h = 10.5 with a ring
of faces of 0.0035 over the slip annulus, mirrored (66,970 dofs: 86 min) and
meshed apart (66,251 dofs: 85 min)."""
import math
import subprocess

import h5py
import numpy as np
import pytest

from conftest import ROOT, figure, run_contact
import hertz
from test_friction3d import contact_radius, mindlin_stage, stick_radius

MU = 0.3
G3 = "tests/meshes/friction3d"
SLAVE = "contact/c/upper_cap"
GRADE = "rc=0.11,zs=4,hm=0.04,rm=0.2"
PRESS = 0.02                      # the upper top's approach to the lower's: a/R about 0.1
DX = (1.25e-3, 3.3e-3, 5.9e-3)   # the upper top's x at stages 2-4: Q/(mu P) about 0.2, 0.5, 0.8
DX0 = (9.7e-4, 2.6e-3, 4.6e-3)   # the same at nu = 0


def scene_args(h, nu=0.3, dx=DX, press=PRESS, grade=GRADE, meshes=None, extra=()):
    """Two half balls R = 1 cut at z = +-0.5 (tests/meshes/friction3d/halfball.geo,
    the lower its mirror image, dir=-1; or the ready-made meshes (upper, lower)),
    E 1000, nu, y = 0 on rollers; the lower's top held, the upper's pressed by
    press, then moved along x by dx in three stages."""
    top = ",".join(f"{x!r},{-press!r}" for x in (0.0,) + tuple(dx))
    args = []
    for i, (b, d) in enumerate((("upper", 1), ("lower", -1))):
        args += ([f"-{b}_geo", f"{G3}/halfball.geo", f"-{b}_geo_params", f"zc=0.05,dir={d},{grade}", f"-{b}_mesh_size", h]
                 if meshes is None else [f"-{b}_mesh", meshes[i]])
        args += [f"-{b}_E", 1000, f"-{b}_nu", nu, f"-{b}_bc", "top,symy", f"-{b}_bc_symy_components", "y"]
    args += ["-bodies", "upper,lower", "-upper_bc_top_components", "x,z", "-upper_bc_top_values", top,
             "-lower_bc_top_components", "x,y,z",
             "-contact_pairs", "c", "-contact_c_surfaces", "upper:cap,lower:cap", "-contact_c_friction", MU,
             "-load_stages", 4, "-load_steps", 1, "-contact_friction_lag_rtol", "1e-6"]
    return args + list(extra)


# A Tet10 (Triangle6) turned inside out by the reflection z -> -z: Gmsh's
# order with its nodes 1 and 2 swapped (corners 0 2 1 3, edges 0-2 2-1 1-0
# 3-0 3-1 3-2; 0 2 1, edges 0-2 2-1 1-0).
REFLECT = {11: [0, 2, 1, 3, 6, 5, 4, 7, 9, 8], 9: [0, 2, 1, 5, 4, 3]}


def mirrored_meshes(tmp_path, h, grade=GRADE):
    """The upper half ball meshed by Gmsh (halfball.geo) and its reflection
    about z = 0, node for node: (upper.msh, lower.msh) in tmp_path."""
    up, lo = tmp_path / "upper.msh", tmp_path / "lower.msh"
    cmd = ["gmsh", "-3", "-v", "0", "-format", "msh22", str(ROOT / G3 / "halfball.geo"), "-setnumber", "h", str(h),
           "-setnumber", "zc", "0.05"]
    for kv in grade.split(","):
        cmd += ["-setnumber"] + kv.split("=")
    subprocess.run(cmd + ["-o", str(up)], check=True, capture_output=True)
    lines = up.read_text().split("\n")
    i, j = lines.index("$Nodes"), lines.index("$Elements")
    for k in range(i + 2, i + 2 + int(lines[i + 1])):
        n, x, y, z = lines[k].split()
        lines[k] = f"{n} {x} {y} {-float(z)!r}"
    for k in range(j + 2, j + 2 + int(lines[j + 1])):
        e = lines[k].split()
        t, head = int(e[1]), 3 + int(e[2])
        if t in REFLECT:
            lines[k] = " ".join(e[:head] + [e[head + q] for q in REFLECT[t]])
    lo.write_text("\n".join(lines))
    return up, lo


def stage_sets(res):
    """Per stage 1..4: reference coordinates, the final pressure and weight,
    that stage's shear (n x 3, the lower's traction on the upper) and stick,
    and its P and Q (the upper top's reactions, doubled: half model)."""
    out = []
    with h5py.File(res.output_path, "r") as f:
        g = f[SLAVE]
        X, p, A = g["node_X"][:], g["node_pressure"][:], g["node_weight"][:]
        n = len(res.summary["load_stages"])
        for k, st in enumerate(res.summary["load_stages"], 1):
            h = f[f"stages/{k}/{SLAVE}"] if k < n else g
            R = st["reactions"]["upper:top"]
            out.append(dict(X=X, p=p, A=A, shear=h["node_shear"][:], stick=h["node_stick"][:],
                            P=2 * abs(R[2]), Q=2 * abs(R[0])))
    return out


def rings(s, a, p0, edges=(0.25, 0.45, 0.65, 0.85)):
    """The shear's radial component (outward on the upper ball) over mu p0,
    its mean over rings of the slave's nodes between edges (r/a), at the
    rings' middles 0.35, 0.55, 0.75."""
    r = np.hypot(s["X"][:, 0], s["X"][:, 1])
    tr = (s["shear"][:, 0] * s["X"][:, 0] + s["shear"][:, 1] * s["X"][:, 1]) / np.maximum(r, 1e-300)
    return [float(np.mean(tr[(r >= lo * a) & (r < hi * a)]) / (MU * p0)) for lo, hi in zip(edges, edges[1:])]


def mindlin_figures(res):
    """Stage 1's (normal) radial shear rings and per tangential stage k = 2, 3, 4:
    Q/(mu P), c/a from Mindlin's (1 - Q/(mu P))^(1/3), the shear along Q
    against Mindlin's mu p0/a (sqrt(a^2 - r^2) - sqrt(c^2 - r^2)) in relative
    L2 over the slave's nodes (weights A_j; his p0, a, c from the computed a
    and the reactions), the normal stage's x shear against it (locked), the
    traction's component across Q relative to the whole in L2, and Coulomb:
    the largest (|t| - mu p)/(mu p_max) and ||t| - mu p|/(mu p_max) where a
    node in contact slips."""
    sets = stage_sets(res)
    a = contact_radius(sets[-1])
    out = dict(a=a, rings=rings(sets[0], a, hertz.peak(sets[0]["P"], a)))
    q1, y1 = -sets[0]["shear"][:, 0], sets[0]["shear"][:, 1]
    for k in range(2, len(sets) + 1):
        s = sets[k - 1]
        t = np.linalg.norm(s["shear"], axis=1)
        out[k] = dict(mindlin_stage(s, a, q1, MU),
                      across_less=math.sqrt(np.sum(s["A"] * (s["shear"][:, 1] - y1) ** 2) / np.sum(s["A"] * t ** 2)))
    # Coulomb at the last stage's end, against its pressure (the stages' own are not written)
    s = sets[-1]
    t, bmax = np.linalg.norm(s["shear"], axis=1), MU * s["p"].max()
    slipping = (s["p"] > 0) & (s["stick"] < 0.5)
    out["coulomb"] = dict(excess=float(np.max(t - MU * s["p"]) / bmax),
                          slip_error=float(np.max(np.abs(t[slipping] - MU * s["p"][slipping])) / bmax),
                          slipping=int(slipping.sum()), stuck=int((s["stick"] > 0.5).sum()),
                          open_shear=float(np.max(t[s["p"] == 0], initial=0.0)))
    return out


# The bounds: c/a within 2 % of Mindlin's, his shear within 10 % (L2).
C_BOUND, L2_BOUND = 0.02, 0.10
COARSE_H, FINE_H = 0.04, 0.01
# figures measured (mindlin_figures) per tangential stage; the tests' bounds
# 3 times these, never beyond the (xfail strict where a figure is)
COARSE = {2: dict(c_err=0.0231, l2=0.347), 3: dict(c_err=0.0216, l2=0.177), 4: dict(c_err=-0.0171, l2=0.112, across=0.049)}


def within(figs, k, key, bound, ah="2.7", run=None):
    """Stage k's case (run's, where named), xfail (strict) where the measured figure is beyond the issue's bound."""
    values = (k,) if run is None else (run, k)
    if abs(figs[k][key]) <= bound:
        return pytest.param(*values)
    return pytest.param(*values, marks=pytest.mark.xfail(strict=True, reason=f"{key} {figs[k][key]:+.3f} beyond the issue's {bound:g} at a/h {ah}"))


def assert_stick_radius(f, figs, k):
    """Stage k's c/a from Mindlin's (mindlin_figures f) within the issue's 2 %,
    or 3 times the figure recorded in figs where tighter."""
    figure("ratio", f[k]["ratio"])
    err = figure("c_over_a_error", f[k]["c_err"])
    assert abs(err) <= min(C_BOUND, 3 * abs(figs[k]["c_err"]))


def assert_shear(f, figs, k):
    """Stage k's shear along Q against Mindlin's within the issue's 10 % (L2),
    or 3 times the figure recorded in figs where tighter; the normal stage's
    locked shear recorded beside it."""
    figure("locked", f[k]["locked"])
    l2 = figure("l2", f[k]["l2"])
    assert l2 <= min(L2_BOUND, 3 * figs[k]["l2"])


@pytest.fixture(scope="module")
def coarse(tmp_path_factory):
    return run_contact(scene_args(COARSE_H), tmp_path_factory.mktemp("mindlin3d"), timeout=3600)


def test_normal_stage(coarse):
    """The normal stage (P alone) locks no shear in: the mean over rings of
    the slave's nodes of the shear's radial component (outward on the upper
    ball), over mu p0, at r/a = 0.35, 0.55, 0.75: `ring_1` = 0.0044,
    `ring_2` = 0.0059, `ring_3` = -0.018 at a/h = 2.7 (h = 0.04), bound
    0.054 (3 times the largest). Read in the master's plane (as before
    friction3d.c's Friction3dClosingNormal) the same scene locked in 0.060,
    0.045, -0.167, and the ball on the flat block (tests/test_shear3d.py)
    0.054, 0.066, 0.075 at the same a/h."""
    f = mindlin_figures(coarse)
    rings = [figure(f"ring_{i}", v) for i, v in enumerate(f["rings"], 1)]
    assert max(abs(v) for v in rings) <= 0.054


@pytest.fixture(scope="module")
def mirrored(tmp_path_factory):
    d = tmp_path_factory.mktemp("mindlin3d_mirrored")
    return run_contact(scene_args(COARSE_H, meshes=mirrored_meshes(d, COARSE_H)), d, timeout=3600)


def test_mirrored_normal_stage(mirrored):
    """The lower ball's mesh the upper's reflected node for node
    (mirrored_meshes), at a/h = 2.7: the normal stage's radial shear (as
    test_normal_stage) `ring_1` = 0.00033, `ring_2` = 0.00054, `ring_3` =
    0.00047 of mu p0 (bound 0.0016, 3 times the largest), and its x part
    against Mindlin's shear at Q/(mu P) = 0.2 `locked` = 0.016 in L2 (bound
    0.048; 0.175 where the balls are meshed apart): what the normal stage
    locks in on test_normal_stage's scene is the two meshes' difference, at
    the contact's edge. The shear along Q against Mindlin's: `l2_2` = 0.280,
    `l2_3` = 0.178, `l2_4` = 0.109 (0.347, 0.177, 0.112 meshed apart): at
    a/h = 2.7 the mesh's."""
    f = mindlin_figures(mirrored)
    rings = [figure(f"ring_{i}", v) for i, v in enumerate(f["rings"], 1)]
    for k in (2, 3, 4):
        figure(f"l2_{k}", f[k]["l2"])
    assert max(abs(v) for v in rings) <= 0.0016
    assert figure("locked", f[2]["locked"]) <= 0.048


@pytest.mark.parametrize("k", [within(COARSE, k, "c_err", C_BOUND) for k in (2, 3, 4)])
def test_stick_radius(coarse, k):
    """At a/h = 2.7, stage k's c/a from Mindlin's (1 - Q/(mu P))^(1/3) (c
    the half disc of the stuck nodes' area, a the pressures' second moment):
    `c_over_a_error` = -0.0171 to +0.0231 (+0.0231, +0.0216, -0.0171 at
    `ratio` = 0.205, 0.497, 0.798), bound the issue's 2 % (3 times the figure
    where tighter): met at 0.8, not at 0.2 and 0.5 on this mesh (xfail,
    strict; a/h = 10.6: test_fine_stick_radius)."""
    f = mindlin_figures(coarse)
    assert_stick_radius(f, COARSE, k)


@pytest.mark.parametrize("k", [within(COARSE, k, "l2", L2_BOUND) for k in (2, 3, 4)])
def test_shear(coarse, k):
    """At a/h = 2.7, stage k's shear along Q against Mindlin's mu p0/a
    (sqrt(a^2 - r^2) - sqrt(c^2 - r^2)), relative L2 over the slave's nodes
    (weights A_j; his p0, a, c from the computed a and the top's reactions):
    `l2` = 0.112 to 0.347 (0.347, 0.177, 0.112 at Q/(mu P) = 0.2, 0.5, 0.8;
    the ball on the block gave 0.43, 0.21, 0.13 at this a/h), not within
    the issue's 10 % on this mesh (xfail, strict; a/h = 10.6:
    test_fine_shear)."""
    f = mindlin_figures(coarse)
    l2 = figure("l2", f[k]["l2"])
    assert l2 <= min(L2_BOUND, 3 * COARSE[k]["l2"])


def test_coulomb(coarse):
    """At the last stage's end (Q/(mu P) = 0.8), against the written
    pressure p: |t_j| <= mu p_j at every node and |t_j| = mu p_j where a
    node in contact slips, to round-off: `excess` = 2.4e-16, the largest
    (|t| - mu p) / (mu p_max), `slip_error` = 2.4e-16, the largest ||t| - mu
    p| / (mu p_max) over the `slipping` = 52 nodes (25 stick) (bounds 1e-12;
    at least 10 slip and 10 stick); no shear where p = 0. Its bounds are
    4000 times the round-off measured, so it runs in make test only, not
    under every BLAS kernel (its fixture's two runs take 2-3 min each)."""
    c = mindlin_figures(coarse)["coulomb"]
    figure("slipping", c["slipping"])
    assert c["slipping"] >= 10 and c["stuck"] >= 10
    assert figure("excess", c["excess"]) <= 1e-12
    assert figure("slip_error", c["slip_error"]) <= 1e-12
    assert c["open_shear"] == 0


def test_across(coarse):
    """The traction's component across Q (y), relative L2 to the whole
    traction's, at Q/(mu P) = 0.8: `across` = 0.049 at a/h = 2.7 (bound 3
    times); less the normal stage's y shear `across_less` = 0.058. At 0.2 and
    0.5 it is 0.21 and 0.088, 0.067 and 0.065 less the normal stage's: the
    mesh's share of the normal stage's shear, small against mu p but not
    against the small Q (docs/formulations.md)."""
    f = mindlin_figures(coarse)
    figure("across_less", f[4]["across_less"])
    assert figure("across", f[4]["across"]) <= 3 * COARSE[4]["across"]


# make stress: the finer meshes. h = 0.02 (a/h 5.3, 20,739 dofs) at nu 0 and
# 0.3 and h = 0.04 at nu 0: the traction's component across Q falls with
# the mesh at nu = 0 (Mindlin's traction parallel to Q exact), and at nu =
# 0.3 stays above it by what is physics (Johnson, Contact Mechanics 7.2).
MEDIUM_H = 0.02
MEDIUM = {2: dict(c_err=0.0066, l2=0.309), 3: dict(c_err=0.0019, l2=0.133), 4: dict(c_err=0.0023, l2=0.085, across=0.040)}
MEDIUM0 = {2: dict(across=0.174), 3: dict(across=0.048), 4: dict(across=0.014)}


def run_scene(tmp_path_factory, h, nu):
    return run_contact(scene_args(h, nu=nu, dx=DX if nu else DX0), tmp_path_factory.mktemp(f"mindlin3d_{h}_{nu}"), timeout=7200)


@pytest.fixture(scope="module")
def coarse0(tmp_path_factory):
    return run_scene(tmp_path_factory, COARSE_H, 0.0)


@pytest.fixture(scope="module")
def medium0(tmp_path_factory):
    return run_scene(tmp_path_factory, MEDIUM_H, 0.0)


@pytest.fixture(scope="module")
def medium(tmp_path_factory):
    return run_scene(tmp_path_factory, MEDIUM_H, 0.3)


@pytest.mark.stress
def test_medium_normal_stage(medium):
    """At a/h = 5.3 (h = 0.02, 20,739 dofs), the normal stage's radial shear
    as test_normal_stage measures it: `ring_1` = -0.0010, `ring_2` = 0.0022,
    `ring_3` = 0.0041 of mu p0 (bound 0.0123, 3 times the largest; the ball
    on the block: 0.049, 0.064, 0.072 at this a/h). Its rms over the nodes
    within r < a/2 falls with the mesh (0.030 mu p0 at a/h 2.7, 0.008 here);
    within 0.8 a < r < a it does not (0.037 and 0.065): see
    docs/formulations.md."""
    f = mindlin_figures(medium)
    rings = [figure(f"ring_{i}", v) for i, v in enumerate(f["rings"], 1)]
    assert max(abs(v) for v in rings) <= 0.0123


@pytest.mark.stress
@pytest.mark.parametrize("k", [within(MEDIUM, k, "c_err", C_BOUND, "5.3") for k in (2, 3, 4)])
def test_medium_stick_radius(medium, k):
    """At a/h = 5.3 (h = 0.02), stage k's c/a from Mindlin's:
    `c_over_a_error` = +0.0019 to +0.0066 (+0.0066, +0.0019, +0.0023 at
    `ratio` = 0.203, 0.500, 0.801), bound the issue's 2 % or 3 times the
    figure where tighter."""
    f = mindlin_figures(medium)
    assert_stick_radius(f, MEDIUM, k)


@pytest.mark.stress
@pytest.mark.parametrize("k", [within(MEDIUM, k, "l2", L2_BOUND, "5.3") for k in (2, 3, 4)])
def test_medium_shear(medium, k):
    """At a/h = 5.3 (h = 0.02), stage k's shear along Q against Mindlin's,
    relative L2 (as test_shear): `l2` = 0.085 to 0.309 (0.309, 0.133, 0.085
    at Q/(mu P) = 0.2, 0.5, 0.8; the ball on the block 0.32, 0.15, 0.093 at
    this a/h), the issue's 10 % met at 0.8, not at 0.2 and 0.5 (xfail,
    strict): at 0.2 Mindlin's shear beyond its peak lies in the annulus c <
    r < a, 0.07 a = 0.4 h wide here, where the normal stage's edge shear
    (test_medium_normal_stage) is most of it. The normal stage's x shear
    against Mindlin's is `locked` = 0.053 to 0.189."""
    f = mindlin_figures(medium)
    assert_shear(f, MEDIUM, k)


@pytest.mark.stress
@pytest.mark.roundoff
def test_medium_coulomb(medium):
    """At a/h = 5.3, Coulomb at the last stage's end as test_coulomb:
    `excess` = 2.4e-16, `slip_error` = 3.2e-16 over `slipping` = 147 nodes
    (92 stick) (bounds 1e-12)."""
    c = mindlin_figures(medium)["coulomb"]
    figure("slipping", c["slipping"])
    assert c["slipping"] >= 10 and c["stuck"] >= 10
    assert figure("excess", c["excess"]) <= 1e-12
    assert figure("slip_error", c["slip_error"]) <= 1e-12
    assert c["open_shear"] == 0


@pytest.mark.stress
def test_across_nu(coarse0, medium0, medium):
    """The traction's component across Q (relative L2, as test_across) at
    Q/(mu P) = 0.5 and 0.8. At nu = 0, where Mindlin's traction parallel to
    Q is exact, it falls with the mesh: `across0_coarse_3` = 0.092,
    `across0_coarse_4` = 0.033 at a/h 2.7, `across0_3` = 0.048, `across0_4`
    = 0.014 at a/h 5.3 (bounds: below the coarse figure, and 3 times the
    figure). At nu = 0.3 `across_3` = 0.061, `across_4` = 0.040 at a/h 5.3
    (0.088, 0.049 at 2.7): at 0.8 about 0.035 of it is not the mesh's but
    the slip's own direction off Q's where nu > 0 (Johnson, Contact
    Mechanics 7.2), bound 3 times. At 0.2 the normal stage's edge shear
    (0.17 at both nu at a/h 5.3) is most of it."""
    c0, m0, m = mindlin_figures(coarse0), mindlin_figures(medium0), mindlin_figures(medium)
    for k in (3, 4):
        cc = figure(f"across0_coarse_{k}", c0[k]["across"])
        a0 = figure(f"across0_{k}", m0[k]["across"])
        assert a0 < cc and a0 <= 3 * MEDIUM0[k]["across"]
        figure(f"across_{k}", m[k]["across"])
    assert m[4]["across"] <= 3 * MEDIUM[4]["across"]


# make stress: the mirrored meshes at a/h = 5.3 (h = 0.02, 20,802 dofs,
# 7.5 min on the loaded machine), nu 0.3 and 0
MIRRORED = {2: dict(c_err=0.0120, l2=0.254, across=0.057), 3: dict(c_err=0.0045, l2=0.119, across=0.044),
            4: dict(c_err=0.0088, l2=0.077, across=0.038)}
MIRRORED0 = {2: dict(c_err=0.0194, l2=0.234, across=0.040), 3: dict(c_err=0.0194, l2=0.109, across=0.019),
             4: dict(c_err=0.0038, l2=0.079, across=0.0077)}


def run_mirrored(tmp_path_factory, h, nu, grade=GRADE, extra=()):
    d = tmp_path_factory.mktemp(f"mindlin3d_mirrored_{h}_{nu}")
    return run_contact(scene_args(h, nu=nu, dx=DX if nu else DX0, meshes=mirrored_meshes(d, h, grade), extra=extra), d, timeout=10800)


@pytest.fixture(scope="module")
def mirrored_medium(tmp_path_factory):
    return run_mirrored(tmp_path_factory, MEDIUM_H, 0.3)


@pytest.fixture(scope="module")
def mirrored_medium0(tmp_path_factory):
    return run_mirrored(tmp_path_factory, MEDIUM_H, 0.0)


@pytest.mark.stress
@pytest.mark.parametrize("k", [within(MIRRORED, k, "c_err", C_BOUND, "5.3") for k in (2, 3, 4)])
def test_mirrored_stick_radius(mirrored_medium, k):
    """Mirrored meshes at a/h = 5.3 (h = 0.02), nu 0.3, stage k's c/a from
    Mindlin's: `c_over_a_error` = +0.0045 to +0.0120 (+0.0120, +0.0045,
    +0.0088 at `ratio` = 0.204, 0.500, 0.801), bound the issue's 2 % (3
    times the figure where tighter). The normal stage's ring means
    `ring_max` = 0.00064 of mu p0 at most."""
    f = mindlin_figures(mirrored_medium)
    figure("ring_max", max(abs(v) for v in f["rings"]))
    assert_stick_radius(f, MIRRORED, k)


@pytest.mark.stress
@pytest.mark.parametrize("k", [within(MIRRORED, k, "l2", L2_BOUND, "5.3") for k in (2, 3, 4)])
def test_mirrored_shear(mirrored_medium, k):
    """Mirrored meshes at a/h = 5.3, nu 0.3, stage k's shear along Q
    against Mindlin's (as test_shear): `l2` = 0.077 to 0.254 (0.254, 0.119,
    0.077 at Q/(mu P) = 0.2, 0.5, 0.8; meshed apart 0.309, 0.133, 0.085),
    the issue's 10 % met at 0.8, not at 0.5 and 0.2 (xfail, strict): the
    annulus c < r < a is 0.4 h wide at 0.2 here, and the normal stage locks
    in `locked` = 0.0065 to 0.023 of Mindlin's shear."""
    f = mindlin_figures(mirrored_medium)
    assert_shear(f, MIRRORED, k)


@pytest.mark.stress
def test_mirrored_across(mirrored_medium0, mirrored_medium):
    """Mirrored meshes at a/h = 5.3, the traction's component across Q
    (relative L2, as test_across). At nu = 0 (Mindlin's traction parallel to
    Q exact): `across0_2` = 0.040, `across0_3` = 0.019, `across0_4` =
    0.0077, the mesh's (meshed apart: 0.033 at 0.8 and a/h 2.7, 0.014 at
    5.3), bound 3 times each. At nu = 0.3: `across_2` = 0.057, `across_3` =
    0.044, `across_4` = 0.038 (0.068, 0.048, 0.040 at a/h 2.7), about 0.04
    at every Q and barely falling with the mesh: the slip's direction off
    Q's where nu > 0 (Johnson, Contact Mechanics 7.2), physics; bound 3
    times each, and above nu = 0's at 0.5 and 0.8. c/a at nu = 0:
    `c_over_a_error0_2` = +0.0194, `c_over_a_error0_3` = +0.0194,
    `c_over_a_error0_4` = +0.0038 (bound 2 %); its shear L2 `l2_0_4` =
    0.079 at 0.8 (bound 10 %; 0.234, 0.109 at 0.2, 0.5)."""
    f0, f = mindlin_figures(mirrored_medium0), mindlin_figures(mirrored_medium)
    for k in (2, 3, 4):
        a0 = figure(f"across0_{k}", f0[k]["across"])
        a = figure(f"across_{k}", f[k]["across"])
        assert a0 <= 3 * MIRRORED0[k]["across"] and a <= 3 * MIRRORED[k]["across"]
        assert abs(figure(f"c_over_a_error0_{k}", f0[k]["c_err"])) <= C_BOUND
        if k > 2:
            assert a > a0
    assert figure("l2_0_4", f0[4]["l2"]) <= L2_BOUND


# make stress: a/h = 10.5 (h = 0.01, meshed apart, nu 0.3; 35,304 dofs, 61
# min on the machine loaded 8 times over its 2 cores)
FINE = {2: dict(c_err=0.0030, l2=0.121), 3: dict(c_err=0.0030, l2=0.060), 4: dict(c_err=-0.0159, l2=0.050, across=0.038)}


# and meshed apart with the ring over the slip annulus of the mirrored runs
# below (RING; 66,251 dofs, 156 Newton iterations, one cutback, 85 min beside
# other runs, the whole Hessian factored)
APART_RING = {2: dict(c_err=-0.0002, l2=0.1136), 3: dict(c_err=-0.0032, l2=0.0559), 4: dict(c_err=-0.0165, l2=0.0493)}
APART_RUNS = {"fine": (FINE, "10.5"), "apart_ring": (APART_RING, "10.5 with a ring")}


def run_cases(runs, key, bound):
    """(run, k) over the runs ({name: (figures, a/h)}: APART_RUNS,
    MIRRORED_RUNS) and stages 2-4, xfail (strict) where the run's figure is
    beyond the issue's bound."""
    return [within(figs, k, key, bound, ah, run) for run, (figs, ah) in runs.items() for k in (2, 3, 4)]


@pytest.fixture(scope="module")
def fine(tmp_path_factory):
    return run_contact(scene_args(FINE_H), tmp_path_factory.mktemp("mindlin3d_fine"), timeout=10800)


@pytest.fixture(scope="module")
def apart_ring(tmp_path_factory):
    return run_contact(scene_args(FINE_H, grade=GRADE + "," + RING, extra=["-newton_schur", 0, "-contact_mortar_pattern_margin", 0.5]),
                       tmp_path_factory.mktemp("mindlin3d_apart_ring"), timeout=21600)


@pytest.mark.stress
@pytest.mark.parametrize("run,k", run_cases(APART_RUNS, "c_err", C_BOUND))
def test_fine_stick_radius(request, run, k):
    """Meshed apart at a/h = 10.5 (h = 0.01), and with the ring of faces of
    0.0035 over the slip annulus, stage k's c/a from Mindlin's:
    `c_over_a_error` = -0.0165 to +0.0030 (+0.0030, +0.0030, -0.0159 at
    `ratio` = 0.203, 0.501, 0.803; with the ring -0.0002, -0.0032, -0.0165 at
    0.204, 0.502, 0.804), bound the issue's 2 % (3 times the figure where
    tighter)."""
    assert_stick_radius(mindlin_figures(request.getfixturevalue(run)), APART_RUNS[run][0], k)


@pytest.mark.stress
@pytest.mark.parametrize("run,k", run_cases(APART_RUNS, "l2", L2_BOUND))
def test_fine_shear(request, run, k):
    """Meshed apart at a/h = 10.5 (h = 0.01), stage k's shear along Q
    against Mindlin's (as test_shear): `l2` = 0.049 to 0.121 (0.121, 0.060,
    0.050 at Q/(mu P) = 0.2, 0.5, 0.8; with the ring 0.114, 0.056, 0.049; the
    ball on the block 0.27, 0.13, 0.082 at a/h 10.6), the issue's 10 % met at
    0.5 and 0.8, not at 0.2 (xfail, strict), with or without the ring: the
    normal stage's x shear against Mindlin's, the two meshes' difference
    (test_mirrored_normal_stage), `locked` = 0.027 to 0.099 (0.099, 0.043,
    0.027; with the ring 0.097, 0.042, 0.027), which the ring does not
    lessen, adds to what the ring takes away (the mirrored meshes with the
    ring: 0.094 at 0.2, test_mirrored_fine_shear)."""
    assert_shear(mindlin_figures(request.getfixturevalue(run)), APART_RUNS[run][0], k)


@pytest.mark.stress
@pytest.mark.roundoff
@pytest.mark.parametrize("meshes", ["fine", "apart_ring", "mirrored_fine", "mirrored_finer", "mirrored_ring"])
def test_fine_coulomb(request, meshes):
    """At a/h = 10.5, meshed apart and mirrored, each also with the ring,
    and 13 mirrored, Coulomb at the last stage's end (as test_coulomb):
    `excess` = 3.2e-16, `slip_error` = 3.2e-16 over `slipping` = 566 to 1844
    nodes (296 to 452 stick) (bounds 1e-12); the normal stage's ring means at
    most `ring_max` = 0.00077 to 0.0015 of mu p0 (bound 0.0025; 0.0015 meshed
    apart with the ring); the traction across Q at 0.8 `across` = 0.038 to
    0.0403 (bound 3 times 0.038; 0.087, 0.037 at 0.2, 0.5 meshed apart)."""
    f = mindlin_figures(request.getfixturevalue(meshes))
    c = f["coulomb"]
    figure("slipping", c["slipping"])
    assert c["slipping"] >= 10 and c["stuck"] >= 10
    assert figure("excess", c["excess"]) <= 1e-12
    assert figure("slip_error", c["slip_error"]) <= 1e-12
    assert c["open_shear"] == 0
    assert figure("ring_max", max(abs(v) for v in f["rings"])) <= 0.0025
    assert figure("across", f[4]["across"]) <= 3 * FINE[4]["across"]


# make stress: the mirrored meshes at a/h = 10.5 (h = 0.01, nu 0.3; 15 min,
# 3.1 GB, beside another run on the 2 cores) and a/h = 13 (h = 0.008; 50,504
# dofs, 74 Newton iterations, 49 min, 5.5 GB beside another run)
MIRRORED_FINE = {2: dict(c_err=0.0021, l2=0.101), 3: dict(c_err=0.0061, l2=0.054), 4: dict(c_err=-0.0160, l2=0.048)}
FINER_H = 0.008
MIRRORED_FINER = {2: dict(c_err=0.0063, l2=0.118), 3: dict(c_err=0.0029, l2=0.059), 4: dict(c_err=-0.0204, l2=0.052)}
# and a/h = 10.5 with a ring over the slip annulus (faces of 0.0035 within
# 0.006 of r = 0.102 on both balls, growing to h over 0.02: halfball.geo's ra,
# hr, wr, gr; 66,970 dofs, 153 Newton iterations, 86 min and 7.4 GB beside the
# CI run, the whole Hessian factored)
RING = "ra=0.102,hr=0.0035,wr=0.006,gr=0.02"
MIRRORED_RING = {2: dict(c_err=-0.0007, l2=0.0936), 3: dict(c_err=-0.0020, l2=0.0496), 4: dict(c_err=-0.0165, l2=0.0499)}
MIRRORED_RUNS = {"mirrored_fine": (MIRRORED_FINE, "10.5"), "mirrored_finer": (MIRRORED_FINER, "13"),
                 "mirrored_ring": (MIRRORED_RING, "10.5 with a ring")}



@pytest.fixture(scope="module")
def mirrored_fine(tmp_path_factory):
    return run_mirrored(tmp_path_factory, FINE_H, 0.3)


@pytest.fixture(scope="module")
def mirrored_finer(tmp_path_factory):
    return run_mirrored(tmp_path_factory, FINER_H, 0.3)


@pytest.fixture(scope="module")
def mirrored_ring(tmp_path_factory):
    return run_mirrored(tmp_path_factory, FINE_H, 0.3, grade=GRADE + "," + RING,
                        extra=["-newton_schur", 0, "-contact_mortar_pattern_margin", 0.5])


@pytest.mark.stress
@pytest.mark.parametrize("run,k", run_cases(MIRRORED_RUNS, "c_err", C_BOUND))
def test_mirrored_fine_stick_radius(request, run, k):
    """Mirrored meshes at a/h = 10.5 (h = 0.01) and 13 (h = 0.008), and
    10.5 with a ring of faces of 0.0035 over the slip annulus, nu 0.3,
    stage k's c/a from Mindlin's: `c_over_a_error` = -0.0204 to +0.0063
    (+0.0021, +0.0061, -0.0160 at `ratio` = 0.203, 0.501, 0.803 at a/h
    10.5; +0.0063, +0.0029, -0.0204 at 0.204, 0.502, 0.803 at a/h 13;
    -0.0007, -0.0020, -0.0165 at 0.204, 0.502, 0.804 with the ring), bound
    the issue's 2 % (3 times the figure where tighter): at 0.8 the finer
    mesh's c/a lies 2.04 % below Mindlin's (xfail, strict), farther than
    the coarser's (-0.88 % at a/h 5.3, -1.60 % at 10.5); Coulomb and the
    normal stage's ring means: test_fine_coulomb."""
    assert_stick_radius(mindlin_figures(request.getfixturevalue(run)), MIRRORED_RUNS[run][0], k)


@pytest.mark.stress
@pytest.mark.parametrize("run,k", run_cases(MIRRORED_RUNS, "l2", L2_BOUND))
def test_mirrored_fine_shear(request, run, k):
    """Mirrored meshes at a/h = 10.5 and 13, and 10.5 with the ring, nu
    0.3, stage k's shear along Q against Mindlin's (as test_shear): `l2` =
    0.048 to 0.118 (0.101, 0.054, 0.048 at Q/(mu P) = 0.2, 0.5, 0.8 at a/h
    10.5; 0.118, 0.059, 0.052 at 13; meshed apart at 10.5 0.121, 0.060,
    0.050), the issue's 10 % met at 0.5 and 0.8, not at 0.2 (xfail,
    strict), where the normal stage locks in `locked` = 0.0060 to 0.027 of
    Mindlin's shear (meshed apart 0.099 at 0.2): not the meshes'
    difference, and not falling from a/h 10.5 to 13 (the annulus c < r < a
    0.7 h and 0.9 h wide), but the annulus one element wide: with faces of
    0.0035 over it (the ring) the shear is within 10 % at all three,
    0.0936, 0.0496, 0.0499."""
    f = mindlin_figures(request.getfixturevalue(run))
    assert_shear(f, MIRRORED_RUNS[run][0], k)
