"""3D contact over several ranks (src/contact/mortar3d.c: Mortar3dHessian,
Mortar3dSetUpHessianFaces): each rank integrates its own slave faces and,
for the nodes it assembles, the other ranks' faces around them, so that
every G_j is whole where it is assembled; and a ball slid along a block by
several of its contact widths (large sliding, load stages).

The scenes are test_contact3d.py's: the Tet10-on-Hex27 patch and the
quarter Hertz ball at h = 0.04; for the Hessians' comparison each starts
overlapping (the patch's upper box 0.01 lower, the Hertz block 0.002
higher, a copy of base.geo translated), so that the first Hessian, at the
same state on every rank count, holds the contact."""
import math
import re
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT, figure, info_args, info_text, run_contact
import hertz
from test_contact3d import BASE, E_BALL, E_BASE, NU, SOLVE, UPPERS, hertz_args, patch_args

MAT_FILE_CLASSID = 1211216


def read_matrices(path, count):
    """The first count matrices of a PETSc binary file (MatView, appended):
    (rows, cols, values) each, the row index of every entry."""
    b, o, mats = Path(path).read_bytes(), 0, []
    while o < len(b) and len(mats) < count:
        cid, m, n, nz = np.frombuffer(b, ">i4", 4, o)
        o += 16
        assert cid == MAT_FILE_CLASSID and m == n
        lens = np.frombuffer(b, ">i4", m, o)
        o += 4 * m
        cols = np.frombuffer(b, ">i4", nz, o).astype(np.int64)
        o += 4 * nz
        vals = np.frombuffer(b, ">f8", nz, o)
        o += 8 * nz
        mats.append((np.repeat(np.arange(m), lens), cols, vals))
    return mats


def minus(a, b):
    """a - b over the union of their patterns."""
    n = max(a[0].max(), b[0].max()) + 1
    ka, kb = a[0] * n + a[1], b[0] * n + b[1]
    keys = np.union1d(ka, kb)
    d = np.zeros(len(keys))
    np.add.at(d, np.searchsorted(keys, ka), a[2])
    np.subtract.at(d, np.searchsorted(keys, kb), b[2])
    return keys // n, keys % n, d


def signature(mat):
    """What does not depend on the dofs' numbering (which the ranks' parts
    change): the sorted diagonal, the sorted row sums and the sorted values
    (those above round-off: a difference that cancels gives 0 or 1e-17)."""
    r, c, v = mat
    return np.sort(v[r == c]), np.sort(np.bincount(r, weights=v)), np.sort(v[np.abs(v) > 1e-13 * np.abs(v).max()])


def signatures(path):
    """The first Hessian's signature and those of the next two or three's
    changes from it (the contact part's, at its full penalty in the later)."""
    mats = read_matrices(path, 4)
    assert len(mats) >= 3
    return [signature(mats[0])] + [signature(minus(m, mats[0])) for m in mats[1:]]


def overlapping_base(tmp_path, dz):
    """base.geo moved up by dz (its volume translated, the boxes that pick
    its groups too): the quarter ball overlaps it at rest."""
    def shift(mt):
        a = mt.group(1).split(",")
        for k in (2, 5):
            a[k] = f"{a[k]} + {dz}"
        return "BoundingBox{" + ",".join(a) + "}"

    text = (ROOT / BASE).read_text()
    text = text.replace("e = 1e-6 * W;", f"Translate {{0, 0, {dz}}} {{ Volume{{:}}; }}\ne = 1e-6 * W;", 1)
    text = re.sub(r"BoundingBox\{([^}]*)\}", shift, text)
    geo = Path(tmp_path) / f"base_up{dz}.geo"
    geo.write_text(text)
    return str(geo)


def scene_args(scene, tmp_path):
    if scene == "patch":
        return patch_args(UPPERS["tet10-on-hex27"].replace("z0=0.5", "z0=0.49"), SOLVE)
    args = hertz_args(0.04)
    args[args.index(BASE)] = overlapping_base(tmp_path, 0.002)
    return args


@pytest.mark.roundoff
@pytest.mark.parametrize("scene", ["patch", "hertz"])
def test_hessian_ranks(scene, tmp_path):
    """The Hessians themselves on 1, 2 and 3 ranks (MatView of each, by
    -hessian_mat_view binary:FILE::append): the first three of each run
    (the first at the start, the same state on every rank count; the next
    two after Newton steps whose solves differ by round-off) have the same
    sorted diagonal, row sums and values (numbering-free) to
    `hessian_diff` = up to 1.8e-14 of the largest entry (bound 1e-10); and
    the runs agree as test_contact3d.py::test_ranks_agree asks (force
    within what the stops leave, `dF` = up to 2.2e-12 of P; the same nodes in
    contact). Each rank integrates its own faces and a layer of the others'
    along its border (the -info line): the 2 and 3 rank runs have slave
    nodes whose faces lie on two ranks, and no rank integrates every face
    (`hessian_faces` = 0.64 to 0.74 of them at most on a rank, on these small surfaces)."""
    args = scene_args(scene, tmp_path)
    runs, sigs = {}, {}
    for n in (1, 2, 3):
        mat = Path(tmp_path) / f"H{n}.bin"
        res = run_contact(args + ["-hessian_mat_view", f"binary:{mat}::append"] + info_args(tmp_path, f"r{n}"), tmp_path, ranks=n, name=f"r{n}")
        runs[n] = res.summary
        sigs[n] = signatures(mat)
        info = info_text(tmp_path, f"r{n}")
        shared = [int(x) for x in re.findall(r"(\d+) slave nodes with faces on more than one rank", info)]
        assert len(shared) == n, info[-2000:]
        assert (max(shared) > 0) == (n > 1)
        work = [tuple(int(x) for x in w) for w in re.findall(r"integrates (\d+) faces for the Hessian \((\d+) its own\), searches from (\d+) of (\d+)", info)]
        nf = work[0][3]
        assert len(work) == n and sum(w[1] for w in work) == nf
        if n > 1:
            assert figure("hessian_faces", max(w[0] for w in work) / nf) < 1
    pair = "p" if scene == "patch" else "c"
    c1 = runs[1]["contact"][pair]
    P = math.sqrt(sum(f * f for f in c1["force"]))
    nslave = c1["surfaces"][0]["nodes"]
    for n in (2, 3):
        assert runs[n]["ranks"] == n
        for k in range(min(len(sigs[1]), len(sigs[n]))):
            scale = np.abs(sigs[1][k][2]).max()
            assert scale > 0
            for a, b in zip(sigs[1][k], sigs[n][k]):
                assert len(a) == len(b)
                assert figure("hessian_diff", np.abs(a - b).max() / scale) <= 1e-10
        cn = runs[n]["contact"][pair]
        bound = 3 * nslave ** 0.5 * (runs[1]["gradient_norm"] + runs[n]["gradient_norm"]) + 1e-13 * P
        dF = max(abs(a - b) for a, b in zip(c1["force"], cn["force"]))
        figure("dF", dF / P)
        assert dF <= bound
        assert cn["nodes_in_contact"] == c1["nodes_in_contact"]


# The sliding scene: half of the Hertz ball (slide_ball.geo, R = 1, E 1000,
# y >= 0) on a block 100 times stiffer (slide_block.geo, [-1, s + 1] x
# [0, 1] x [-1, 0], refined along the path), y = 0 on rollers for both, the
# block held at its bottom; the ball's top pushed down by 0.01 in the first
# load stage (a/R = 0.10, as the quarter scene), then moved along x by
# SLIDE / (STAGES - 1) a stage, frictionless.
SLIDE_BALL, SLIDE_BLOCK = "tests/meshes/contact3d/slide_ball.geo", "tests/meshes/contact3d/slide_block.geo"
SLIDE, STAGES = 0.4, 5


def slide_args(h, slide=SLIDE, stages=STAGES):
    xs = [0.0] + [slide * k / (stages - 1) for k in range(1, stages)]
    top = ",".join(f"{x:.6g},-0.01" for x in xs)
    return ["-bodies", "ball,block",
            "-ball_geo", SLIDE_BALL, "-ball_geo_params", "rc=0.2,zc=0.1", "-ball_mesh_size", h, "-ball_E", E_BALL, "-ball_nu", NU,
            "-ball_bc", "top,symy", "-ball_bc_top_components", "x,z", "-ball_bc_symy_components", "y",
            "-ball_bc_top_values", top,
            "-block_geo", SLIDE_BLOCK, "-block_geo_params", f"s={slide},rc=0.15", "-block_mesh_size", h, "-block_E", E_BASE, "-block_nu", NU,
            "-block_bc", "bottom,symy", "-block_bc_symy_components", "y",
            "-load_stages", stages, "-contact_pairs", "c", "-contact_c_surfaces", "ball:cap,block:top", "-output", "none"]


GROWN = "a contact term left its pattern, H grows"


WIDENED = "slid past the Hessian's pattern"


def test_slide(tmp_path):
    """Large sliding: the half ball pressed on the block, then slid along x
    by SLIDE = 0.4, four times its contact radius a (0.102), in four load
    stages, frictionless, on 1 and 2 ranks. On a half-space a frictionless
    slide keeps the force of a prescribed indentation: the normal force P
    (twice the reaction on the half ball's top, at each stage's end) stays
    the first stage's within `slide_dP` = up to 7.1e-6 relative (bound
    1e-3: the contact zone crosses a mesh it does not match), the lateral
    force is `slide_Fx` = up to 1.2e-6 of it (bound 1e-3), and at the end a
    and p0 are Hertz's for that P as on the quarter scene (`slide_a_error`
    = +1.3 %, `slide_pmax_error` = -2.4 %; bounds 3 % and 5 %): no contact
    lost. The ball leaves the Hessian's preallocated pattern (the master
    faces met at the end are ten face sizes from those met at rest, past
    -contact_mortar_pattern_margin 2): the pair widens the preallocation
    (its -info line, Mortar3dGrowPattern) rather than letting PETSc grow it
    entry by entry. 1 and 2 ranks agree at every stage to what the stops
    leave (`slide_dF` = up to 4.9e-15 of P)."""
    runs = {n: run_contact(slide_args(0.04) + info_args(tmp_path, f"slide{n}"), tmp_path, ranks=n, name=f"slide{n}", timeout=1800)
            for n in (1, 2)}
    for n, res in runs.items():
        info = info_text(tmp_path, f"slide{n}")
        assert WIDENED in info and GROWN in info
        s = res.summary
        R = [st["reactions"]["ball:top"] for st in s["load_stages"]]
        assert len(R) == STAGES
        P = [2 * abs(r[2]) for r in R]
        for k in range(1, STAGES):
            assert abs(figure("slide_dP", P[k] / P[0] - 1)) <= 1e-3
        for r in R:
            assert figure("slide_Fx", abs(r[0] / r[2])) <= 1e-3
        c = s["contact"]["c"]
        assert c["surfaces"][0]["slave"]
        a, p0 = hertz.sphere(P[-1], hertz.plane_strain_modulus(E_BALL, NU, E_BASE, NU))
        am = hertz.moment_radius(c["contact_nodes"]["rows"])
        assert abs(figure("slide_a_error", am / a - 1)) <= 0.03
        assert abs(figure("slide_pmax_error", c["pmax"] / p0 - 1)) <= 0.05
        assert SLIDE >= 3 * a
    one, two = runs[1].summary, runs[2].summary
    n = one["contact"]["c"]["surfaces"][0]["nodes"]
    bound = 3 * n ** 0.5 * (one["gradient_norm"] + two["gradient_norm"])
    for s1, s2 in zip(one["load_stages"], two["load_stages"]):
        f1, f2 = s1["reactions"]["ball:top"], s2["reactions"]["ball:top"]
        dF = max(abs(x - y) for x, y in zip(f1, f2))
        figure("slide_dF", dF / abs(f1[2]))
        assert dF <= bound + 1e-12 * abs(f1[2])
