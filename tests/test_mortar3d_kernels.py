"""The geometric kernels of 3D mortar contact on curved quadratic faces, no
mesh file and no 3D body needed: bin/mortar3d-check
(tests/kernels/mortar3d_check.c, built by make) runs them and prints the
figures asserted here.

- src/contact/face3d.c: Tri6 and Quad9 faces (map, tangents, normal, area
  element, closest point, a box that holds the curved face) and the weights
  W_j of the weighted gaps: dual (biorthogonal) to Popp-Wohlmuth's
  transformed basis on a Tri6 (alpha = 1/5: a share of each mid-edge
  function moved to its corners, whose plain P2 functions integrate to
  zero), to the Lagrange basis on a Quad9;
- src/contact/clip.c and src/contact/segment3d.c: segment-based integration
  (each slave face in flat sub-triangles, the master's sub-triangles
  projected on their planes and clipped, Gauss points of degree 6 on each
  piece mapped to the slave's parameters, the closest point of the curved
  master by Newton) of A_j = int W_j dS and Q_j = int W_j g dS, g_j = Q_j /
  A_j, with the first derivatives of Q_j (points fixed in the slave's xi;
  the measure and the weights are the slave's reference configuration's,
  so dA_j = 0);
- src/contact/bvh.c: a bounding-volume tree over the faces' boxes.

Figures are the program's, deterministic (a fixed seed; no BLAS): measured
once on this machine (x86-64, -O2, no FMA)."""
import pytest

from conftest import check_program_figures, figure


@pytest.fixture(scope="module")
def figures():
    """The check program's figures, {(case, name): value}."""
    return check_program_figures("mortar3d-check")


FACES = ("tri6_flat", "quad9_flat", "tri6_octant", "quad9_cubeface")


@pytest.mark.roundoff
def test_bases_partition_and_biorthogonality(figures):
    """On a flat Tri6 and Quad9 (affine images of the reference faces) and on
    curved ones (a Tri6 spanning an octant of the unit sphere, a Quad9 a
    cube's face of it, one sixth), at 100 random points: |sum N - 1|,
    |sum Nt - 1| and |sum W - 1| at most `basis_pu` = 2.7e-15 (bound
    1e-13); int W_i Nt_k dS - delta_ik int Nt_k dS over the face rule
    (degree 10, the one the coefficients come from) at most
    `basis_biorth` = 1.2e-15 of max int Nt_k dS (bound 1e-14)."""
    pu = max(figures[(f"basis_{f}", "partition_of_unity")] for f in FACES)
    bio = max(figures[(f"basis_{f}", "biorthogonality")] for f in FACES)
    assert figure("basis_pu", pu) <= 1e-13
    assert figure("basis_biorth", bio) <= 1e-14


@pytest.mark.roundoff
def test_every_node_has_weight(figures):
    """The plain P2 corner function of a flat Tri6 integrates to zero
    (`tri6_p2_corner` = 5.6e-18 of the area): the standard weighted gap
    would give the corners no weight. With the transformed basis and its
    dual, A_j = int W_j dS = int Nt_j dS: on the flat Tri6 the corners get
    2 alpha/3 = 2/15 of the area (`tri6_flat_Amin` = 0.133333) and the
    mid-edge nodes (1 - 2 alpha)/3 = 1/5 (`tri6_flat_Amax` = 0.2); on a
    parallelogram Quad9 the corners 1/36 (`quad9_flat_Amin` = 0.0277778)
    and the centre 4/9 (`quad9_flat_Amax` = 0.444444) (bounds 1e-12 from
    these exact values). Curved faces keep every node positive: the
    octant's Tri6 `tri6_octant_Amin` = 0.134976 (its corner P2 function
    integrates to `tri6_octant_p2_corner` = 0.0027), the cube face's Quad9
    `quad9_cubeface_Amin` = 0.0267216 (bound > 0)."""
    assert figure("tri6_p2_corner", figures[("basis_tri6_flat", "P2_corner_rel")]) <= 1e-14
    assert abs(figure("tri6_flat_Amin", figures[("basis_tri6_flat", "A_min_rel")]) - 2 / 15) <= 1e-12
    assert abs(figure("tri6_flat_Amax", figures[("basis_tri6_flat", "A_max_rel")]) - 1 / 5) <= 1e-12
    assert abs(figure("quad9_flat_Amin", figures[("basis_quad9_flat", "A_min_rel")]) - 1 / 36) <= 1e-12
    assert abs(figure("quad9_flat_Amax", figures[("basis_quad9_flat", "A_max_rel")]) - 4 / 9) <= 1e-12
    figure("tri6_octant_p2_corner", figures[("basis_tri6_octant", "P2_corner_rel")])
    assert figure("tri6_octant_Amin", figures[("basis_tri6_octant", "A_min_rel")]) > 0
    assert figure("quad9_cubeface_Amin", figures[("basis_quad9_cubeface", "A_min_rel")]) > 0


@pytest.mark.roundoff
def test_patch_flat_nonmatching(figures):
    """A flat slave of 98 Tri6 faces on the unit square (interior corners
    moved by up to 0.2 h) under a flat master of 5 x 6 Quad9 faces (moved
    by up to 0.15 h) at the gap g0 = 0.05: the integration is exact, so
    every g_j = g0 and sum_j A_j is the overlap's area. Level:
    `patch_level_g` = 2.8e-15 relative, `patch_level_area` = 4.4e-16;
    both meshes rotated by 0.7 rad about (1, -2, 0.7) and shifted:
    `patch_tilted_g` = 6.2e-15, `patch_tilted_area` = 6.7e-16; the master
    ending at x = 0.63 inside the slave (tilted): `patch_partial_g` =
    1.1e-14 (nodes with |A_j| >= 0.05 max A), |Q_j - g0 A_j| at every node
    `patch_partial_Q` = 2.8e-15 of g0 max A, `patch_partial_area` = 1.8e-16
    of 0.63; the roles swapped, a tilted Quad9 slave (5 x 4 faces on
    [0.1, 0.9]^2) under a Tri6 master (72 faces on the unit square):
    `patch_quad9slave_g` = 5.1e-15, `patch_quad9slave_area` = 1.7e-16 of
    0.64. Bounds 1e-13. Every node has A_j > 0 where the master covers
    the slave (`patch_tilted_Amin` = 0.136 of max A); where the master ends
    inside a node's support, the dual weight, negative on part of it, can
    leave A_j <= 0 (`patch_partial_negative` = 14 nodes, the least
    `patch_partial_Amin` = -0.134 of max A): the energy term must treat
    those nodes as 2D does (A_j of the whole face, g_j only where the
    covered part carries half of it)."""
    for case in ("level", "tilted", "partial", "quad9slave"):
        assert figure(f"patch_{case}_g", figures[(f"patch_{case}", "g_rel")]) <= 1e-13
        assert figure(f"patch_{case}_area", figures[(f"patch_{case}", "area_rel")]) <= 1e-13
    assert figure("patch_partial_Q", figures[("patch_partial", "Q_rel")]) <= 1e-13
    assert figure("patch_tilted_Amin", figures[("patch_tilted", "A_min_rel")]) > 0
    assert figures[("patch_level", "negative_nodes")] == 0
    assert figures[("patch_quad9slave", "negative_nodes")] == 0
    figure("patch_partial_negative", figures[("patch_partial", "negative_nodes")])
    figure("patch_partial_Amin", figures[("patch_partial", "A_min_rel")])


def test_sphere_converges(figures):
    """A slave sphere of radius 1 (an octahedron's faces divided n x n,
    curved Tri6, nodes on the sphere) inside a concentric master of radius
    1 + g0, g0 = 0.01 (a cube's faces divided 3n/2 x 3n/2, curved Quad9,
    normals inward), non-matching, candidates from the tree: the largest
    |g_j - g0| falls as the quadratic surfaces' distance error, h^3: from
    n = 2 to 16 `sphere_g_n4` = 0.249, `sphere_g_n8` = 0.0358,
    `sphere_g_n16` = 0.00473 of g0, orders `sphere_order_n8` = 2.80 and
    `sphere_order_n16` = 2.92 (bound |order - 3| <= 0.6, 3x the largest
    deviation); sum_j A_j the sphere's area to `sphere_area_n16` = 2.7e-6
    (order 4); every node's A_j positive (`sphere_Amin_n16` = 0.286 of
    the mean)."""
    figure("sphere_g_n4", figures[("sphere_n4", "g_err_rel")])
    figure("sphere_g_n8", figures[("sphere_n8", "g_err_rel")])
    assert figure("sphere_g_n16", figures[("sphere_n16", "g_err_rel")]) <= 0.015
    for n in (8, 16):
        assert abs(figure(f"sphere_order_n{n}", figures[(f"sphere_n{n}", "g_order")]) - 3) <= 0.6
    assert figure("sphere_area_n16", figures[("sphere_n16", "area_rel")]) <= 1e-5
    for n in (2, 4, 8, 16):
        assert figures[(f"sphere_n{n}", "A_min_rel")] > 0
    figure("sphere_Amin_n16", figures[("sphere_n16", "A_min_rel")])


@pytest.mark.roundoff
def test_derivatives_against_differences(figures):
    """dQ_j with respect to the slave's and the masters' nodes against
    central differences (h = 1e-6) of Q_j at the same points (their slave
    xi fixed, the closest point found again): a curved Tri6 slave on 4
    curved Quad9 masters `deriv_tri6_quad9` = 6.4e-11 of max |dQ|, a curved
    Quad9 slave on a curved Tri6 master `deriv_quad9_tri6` = 6.4e-11; the
    closest point's d eta* (from the projection's equations) against
    differences of Newton's answer `deta_tri6_quad9` = 7.6e-11,
    `deta_quad9_tri6` = 5.1e-11. Bounds 1e-7. The whole computation
    differenced (segments made again at each step, a master node moving in
    every face that shares it) on the tilted flat patch: `deriv_whole_flat`
    = 8.1e-11 (bound 1e-7: the integrand is polynomial there, so the
    moving cuts change nothing); on the sphere (n = 4 on m = 6)
    `deriv_whole_sphere` = 6.1e-6 (bound 2e-5): the Gauss rule's error on
    pieces whose cuts move with the nodes, which the derivative at fixed
    points leaves out (2D's mortar differentiates its rule at its cuts for
    a Taylor order of 2; 3D will need the same)."""
    assert figure("deriv_tri6_quad9", figures[("deriv_tri6_quad9", "dQ_fd_rel")]) <= 1e-7
    assert figure("deriv_quad9_tri6", figures[("deriv_quad9_tri6", "dQ_fd_rel")]) <= 1e-7
    assert figure("deta_tri6_quad9", figures[("deriv_tri6_quad9", "deta_fd_rel")]) <= 1e-7
    assert figure("deta_quad9_tri6", figures[("deriv_quad9_tri6", "deta_fd_rel")]) <= 1e-7
    assert figure("deriv_whole_flat", figures[("deriv_whole_tilted", "dQ_fd_rel")]) <= 1e-7
    assert figure("deriv_whole_sphere", figures[("deriv_whole_sphere", "dQ_fd_rel")]) <= 2e-5


def test_tree_equals_brute_force(figures):
    """5000 random boxes (50 of them identical), 500 random query boxes and
    one equal to a box: the tree's answers are the boxes that meet the
    query, each once (`bvh_mismatch` = 0 of `bvh_answers` = 3880 answers).
    The box of a face's Bezier control points holds the curved face: of
    100 random Tri6 and Quad9 faces, 200 points each, none lies outside
    (`bvh_box_outside` = 0)."""
    assert figure("bvh_mismatch", figures[("bvh", "mismatches")]) == 0
    assert figure("bvh_answers", figures[("bvh", "answers")]) > 1000
    assert figure("bvh_box_outside", figures[("bvh", "box_outside")]) <= 0.0
