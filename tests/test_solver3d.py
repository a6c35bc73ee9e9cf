"""The Newton step's linear solver in 3D: CG + GAMG against the direct
factorisation on a block, and the default chosen by size
(-newton_iterative_dofs, docs/solver.md "3D bodies: the step by size").

The scene is our own Hex27 block (tests/meshes/solid/block.geo, the unit
box, n cells an edge), linear (E 1000, nu 0.3), with the smooth trig
solution (-blk_exact trig) imposed on its whole boundary and its body
force."""
import re

import pytest

from conftest import figure, run_contact

GEO = "tests/meshes/solid/block.geo"
FACES = ("xmin", "xmax", "ymin", "ymax", "zmin", "zmax")


def block(n, hexa=True):
    args = ["-bodies", "blk", "-blk_geo", GEO, "-blk_geo_params", f"hex={int(hexa)},skew=0,n={n}", "-mesh_size", "0.3",
            "-blk_E", "1000", "-blk_nu", "0.3", "-blk_bc", ",".join(FACES), "-blk_exact", "trig",
            "-blk_exact_params", "0.001,2", "-output", "none"]
    return args + [f"-blk_bc_{f}_exact" for f in FACES]


def chosen(res):
    """The step the run took: its 'Newton step:' line's choice, and whether CG iterated."""
    m = re.search(r"Newton step: (CG \+ GAMG|direct factorisation) \(3D, (\d+) dofs", res.stdout)
    return (m.group(1) if m else None), ("CG iterations" in res.stdout)


@pytest.mark.roundoff
@pytest.mark.parametrize("ranks", [1, 2])
def test_iterative_matches_direct(ranks, tmp_path):
    """The block at n = 6 (3993 free dofs) solved by the direct step and by
    CG + GAMG (-newton_iterative 0 and 1), both to -tao_gttol 1e-12: the
    displacement differs by K^-1 (g1 - g2), g the gradients the stops
    leave, |g| <= 1e-12 |g0|, so the answers agree to about 1e-12 over K's
    smallest eigenvalue relative to the load's; bound 1e-9 on the relative
    difference of the displacement's norm and of the energy, 1e-6 on that
    of the L2 error against the exact solution, which is 3.4e-4 of the
    norm, so that its relative difference is the displacement's over 3.4e-4
    (measured `du` = up to 2.2e-16, `dE` = up to 6.7e-16, `derr` = up to 1.6e-14: CG
    stops at 1e-9 of the gradient where the Hessian is constant, and the
    direct step's second Newton iteration lands as close)."""
    runs = []
    for it in ("0", "1"):
        res = run_contact(block(6) + ["-newton_iterative", it, "-tao_gttol", "1e-12"], tmp_path, ranks=ranks, name=f"it{it}")
        runs.append((res.summary, chosen(res)))
    (d, (dc, dcg)), (i, (ic, icg)) = runs
    assert d["dofs"] == i["dofs"] == 3993
    assert dc is None and not dcg, "given -newton_iterative 0: no size choice, no CG"
    assert ic is None and icg, "given -newton_iterative 1: CG"
    bd, bi = d["bodies"]["blk"], i["bodies"]["blk"]
    assert figure("du", abs(d["displacement_norm"] / i["displacement_norm"] - 1)) <= 1e-9
    assert figure("dE", abs(bd["energy"] / bi["energy"] - 1)) <= 1e-9
    assert figure("derr", abs(bd["l2_error"] / bi["l2_error"] - 1)) <= 1e-6
    assert bd["l2_error"] / bd["l2_norm"] < 1e-3  # the discretisation's (3.4e-4), not the solver's


def default_dofs(tmp_path):
    """-newton_iterative_dofs's default as -help prints it."""
    res = run_contact(["-help"], tmp_path, name="help", check=False)
    m = re.search(r"-newton_iterative_dofs <now (\d+)", res.stdout)
    assert m, res.stdout[-2000:]
    return int(m.group(1))


def test_default_by_size(tmp_path):
    """The default Newton step in 3D is the direct factorisation at or below
    -newton_iterative_dofs and CG + GAMG above (docs/solver.md; the default
    as -help shows it); -newton_iterative 0 or 1 forces either; a 2D scene
    keeps the direct step whatever its size."""
    limit = default_dofs(tmp_path)
    small = run_contact(block(4), tmp_path, name="small")
    kind, cg = chosen(small)
    assert small.summary["dofs"] <= limit and kind == "direct factorisation" and not cg
    # the same block with the limit below its dofs: CG + GAMG, and the same answer
    n = small.summary["dofs"]
    big = run_contact(block(4) + ["-newton_iterative_dofs", str(n - 1)], tmp_path, name="big")
    kind, cg = chosen(big)
    assert kind == "CG + GAMG" and cg
    assert abs(big.summary["bodies"]["blk"]["energy"] / small.summary["bodies"]["blk"]["energy"] - 1) <= 1e-6
    at = run_contact(block(4) + ["-newton_iterative_dofs", str(n)], tmp_path, name="at")
    assert chosen(at) == ("direct factorisation", False)
    forced = run_contact(block(4) + ["-newton_iterative_dofs", str(n - 1), "-newton_iterative", "0"], tmp_path, name="forced")
    assert chosen(forced) == (None, False)
    flat = run_contact(["-bodies", "sheet", "-sheet_geo", "tests/meshes/plate.geo", "-sheet_E", "1", "-sheet_nu", "0.3",
                        "-sheet_bc", "bottom", "-sheet_bc_bottom_values", "0,-0.01", "-newton_iterative_dofs", "1",
                        "-output", "none"], tmp_path, name="flat")
    assert chosen(flat) == (None, False)


def shell(h):
    """Lame's octant (tests/meshes/solid/shell.geo: radii 1 and 2, Tet10 at
    size h) under inner pressure 10, on rollers on its three symmetry planes
    (one component held per node there), with Lame's exact solution."""
    p, a, b, E, nu = 10.0, 1.0, 2.0, 1000.0, 0.3
    A = p * a ** 3 * (1 - 2 * nu) / (E * (b ** 3 - a ** 3))
    B = p * a ** 3 * b ** 3 * (1 + nu) / (2 * E * (b ** 3 - a ** 3))
    return ["-bodies", "sh", "-sh_geo", "tests/meshes/solid/shell.geo", "-mesh_size", repr(h), "-sh_E", repr(E),
            "-sh_nu", repr(nu), "-sh_bc", "symx,symy,symz", "-sh_bc_symx_components", "x", "-sh_bc_symy_components", "y",
            "-sh_bc_symz_components", "z", "-sh_load", "inner", "-sh_load_inner_pressure", repr(p), "-sh_exact", "sphere",
            "-sh_exact_params", f"{A!r},{B!r}", "-output", "none"]


@pytest.mark.roundoff
@pytest.mark.parametrize("ranks", [1, 2])
def test_nodal_gamg_matches(ranks, tmp_path):
    """The iterative step's preconditioners (src/solver/iterative.c) on
    Lame's octant at h = 0.25 (7226 free dofs; rollers hold one component
    of each node on the symmetry planes, so the free dofs are not whole
    nodes there): the default (on one rank two levels, the nodes by
    Chebyshev and the cells' vertices by GAMG; on two GAMG by nodes, the
    Hessian with every node's three components, a held one an identity row,
    block size 3), GAMG by nodes (-newton_iterative_two_levels 0), GAMG on
    the free dofs alone (-newton_iterative_nodal 0) and the direct step, all
    to -tao_gttol 1e-12: the answers differ by H^-1 of the gradients the
    stops leave (as test_iterative_matches_direct); bound 1e-9 on the
    relative difference of the displacement's norm and of the energy, 1e-6
    on that of the L2 error against Lame's solution (1.6e-3 of the norm)
    (measured over the OpenBLAS kernels `nodal_du` = up to 1.7e-15, `nodal_dE` = up to 1.8e-15,
    `nodal_derr` = up to 3.9e-13). The default's KSP view names what it
    ran: two levels on one rank, GAMG by nodes of block size 3 on two."""
    runs = {}
    for name, opts in (("default", ["-newton_iterative", "1", "-tao_nls_ksp_view"]),
                       ("nodes", ["-newton_iterative", "1", "-newton_iterative_two_levels", "0"]),
                       ("free", ["-newton_iterative", "1", "-newton_iterative_nodal", "0"]),
                       ("direct", ["-newton_iterative", "0"])):
        runs[name] = run_contact(shell(0.25) + opts + ["-tao_gttol", "1e-12"], tmp_path, ranks=ranks, name=name)
    view = runs["default"].stdout
    assert "GAMG by nodes" in view and re.search(r"rows=\d+, cols=\d+, bs=3", view)
    assert ("two levels: the nodes" in view) == (ranks == 1)
    assert "GAMG by nodes" not in runs["free"].stdout
    n = runs["default"].summary
    assert n["dofs"] == 7226
    for other in ("nodes", "free", "direct"):
        o = runs[other].summary
        assert o["dofs"] == n["dofs"]
        bn, bo = n["bodies"]["sh"], o["bodies"]["sh"]
        assert figure("nodal_du", abs(n["displacement_norm"] / o["displacement_norm"] - 1)) <= 1e-9
        assert figure("nodal_dE", abs(bn["energy"] / bo["energy"] - 1)) <= 1e-9
        assert figure("nodal_derr", abs(bn["l2_error"] / bo["l2_error"] - 1)) <= 1e-6
    assert n["bodies"]["sh"]["l2_error"] / n["bodies"]["sh"]["l2_norm"] < 3e-3  # the discretisation's


def schur_choice(res):
    """A 3D contact run's 'Newton step:' line: 'whole' (the whole Hessian
    factored, with the contact-surface dofs it names) or 'schur'."""
    m = re.search(r"Newton step: direct factorisation of the whole Hessian \(3D, \d+ dofs, with contact pairs on (\d+) surface dofs", res.stdout)
    if m:
        return "whole", int(m.group(1))
    return ("schur" if re.search(r"Newton step: direct factorisation \(3D, \d+ dofs, with contact pairs;", res.stdout) else None), None


def test_schur_by_surface(tmp_path):
    """With contact pairs the default 3D step is the Schur step on the
    contact surfaces up to -newton_schur_surface_dofs of them and the whole
    Hessian's factorisation above (its dense surface blocks grow as the
    surfaces' dofs squared: tests/test_mindlin3d.py's half balls with an
    edge ring, 24,568 surface dofs, held 16.8 GB that way, 2.3 GB factoring
    the whole Hessian; docs/solver.md). The quarter Hertz ball at h = 0.04
    (test_contact3d.py's hertz_args) by the default and with the limit
    below its surface dofs, both to -tao_gttol 1e-12: the same step
    otherwise (Newton on the same Hessian), so the answers differ by H^-1
    of the gradients the stops leave: the contact force and the energy
    `dP` = 2.6e-14 and `dE` = 1.1e-16 apart (relative; bound 1e-9). The
    limit at the surface dofs keeps the Schur step; -newton_schur 1 forces
    it below."""
    from test_contact3d import hertz_args
    common = [str(a) for a in hertz_args(0.04)] + ["-tao_gttol", "1e-12"]
    schur = run_contact(common, tmp_path, name="schur")
    assert schur_choice(schur) == ("schur", None)
    whole = run_contact(common + ["-newton_schur_surface_dofs", "100"], tmp_path, name="whole")
    kind, nc = schur_choice(whole)
    assert kind == "whole" and nc > 100
    s, w = schur.summary, whole.summary
    assert s["dofs"] == w["dofs"]
    assert figure("dP", abs(w["contact_force"] / s["contact_force"] - 1)) <= 1e-9
    assert figure("dE", abs(w["energy"] / s["energy"] - 1)) <= 1e-9
    at = run_contact(common + ["-newton_schur_surface_dofs", str(nc), "-tao_max_it", "1"], tmp_path, name="at", check=False)
    assert schur_choice(at) == ("schur", None)
    forced = run_contact(common + ["-newton_schur_surface_dofs", "100", "-newton_schur", "1", "-tao_max_it", "1"], tmp_path, name="forced", check=False)
    assert schur_choice(forced) == ("schur", None)


def test_lmvm_h0_by_surface(tmp_path):
    """L-BFGS's H0 (the stiffness and the contact's Gauss-Newton Hessian)
    takes the Newton step's choice: the Schur step up to
    -newton_schur_surface_dofs contact-surface dofs, the whole H0 factored
    by Cholesky at each refresh above (where the Schur step's dense blocks
    would not fit), said in one line. The quarter Hertz ball at h = 0.04 by
    -tao_type lmvm, by default and with the limit below its surface dofs:
    the same H0 factored otherwise, so the answers differ by what the stops
    leave: the contact force and the energy `dP` = 1.8e-14 and `dE` = 6.7e-16
    apart (relative; bound 1e-9)."""
    from test_contact3d import hertz_args
    common = [str(a) for a in hertz_args(0.04)] + ["-tao_type", "lmvm"]
    schur = run_contact(common, tmp_path, name="schur")
    assert "L-BFGS H0: direct factorisation of the whole H0" not in schur.stdout
    whole = run_contact(common + ["-newton_schur_surface_dofs", "100"], tmp_path, name="whole")
    m = re.search(r"L-BFGS H0: direct factorisation of the whole H0 at each refresh \(3D, with contact pairs on (\d+) surface dofs", whole.stdout)
    assert m and int(m.group(1)) > 100
    s, w = schur.summary, whole.summary
    assert s["converged"] and w["converged"]
    assert figure("dP", abs(w["contact_force"] / s["contact_force"] - 1)) <= 1e-9
    assert figure("dE", abs(w["energy"] / s["energy"] - 1)) <= 1e-9
    forced = run_contact(common + ["-newton_schur_surface_dofs", "100", "-newton_schur", "1", "-tao_max_it", "1"], tmp_path, name="forced", check=False)
    assert "L-BFGS H0: direct factorisation" not in forced.stdout
