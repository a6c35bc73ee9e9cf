"""The Newton step through the Schur complement on the contact surfaces by
substructuring (src/solver/substructure.c, the default on every rank count):
the same answer on 1 to 4 ranks, with both contact formulations, as MUMPS's
Schur complement of K on one rank and as a full factorisation per step; the
exact (indefinite) contact Hessian through the same step; subdomains that are
empty or all boundary; and the one-rank MUMPS step refused on several ranks.
Expected values come from the other rank counts and the other Newton steps."""
import numpy as np
import pytest

from conftest import figure, info_args, info_text, is_force_key, run_contact
from test_contact import RANK_DEPENDENT, flatten

EPS = np.finfo(float).eps
HERTZ = ["-options_file", "meshes/hertz/hertz.opts"]
RTOL = 2e-11


def compare(ref, got, label, name, rtol=RTOL):
    """Every number of two JSON summaries (but the rank-dependent ones) to
    rtol, a force or a reaction to rtol of the pair's force (a y reaction is a
    sum that cancels to 4.5e-7 of P: relative to itself it differs by
    round-off of P, far above rtol). The largest
    difference (name: the figure recorded) is mostly a pressure profile's L2
    error, a difference of the computed and Hertz's profiles; RTOL = 2e-11
    is 3.6 times the largest measured over the five OpenBLAS kernels (5.5e-12,
    mortar's MUMPS step under Prescott; the bound was 1e-11, 1.8 times it)."""
    a, b = flatten(ref), flatten(got)
    assert set(a) == set(b)
    scale = ref["contact_force"]
    compared, worst = 0, (0.0, "")
    for k, x in a.items():
        if k.startswith(RANK_DEPENDENT):
            continue
        y = b[k]
        if isinstance(x, (int, float)) and not isinstance(x, bool):
            force = is_force_key(k)
            floor = rtol * scale if force else 0.0
            worst = max(worst, (abs(x - y) / (max(abs(x), abs(y)) + floor / rtol or 1.0), k))
            assert abs(x - y) <= rtol * max(abs(x), abs(y)) + floor, f"{label}: {k}: {x} against {y}"
            compared += 1
        else:
            assert x == y, f"{label}: {k}: {x} against {y}"
    figure(name, worst[0])
    print(f"{label}: largest relative difference {worst[0]:.2e} ({worst[1]})")
    return compared


@pytest.mark.roundoff
@pytest.mark.parametrize("formulation", [pytest.param("gpts", marks=pytest.mark.kernels), "mortar"])
def test_substructure_ranks(formulation, tmp_path):
    """h = 0.1: 1, 2, 3 and 4 ranks on the substructured step, the one-rank
    MUMPS Schur step and a full factorisation per step on 2 ranks agree in
    every number of the JSON summary to compare()'s 2e-11, all solved to
    -tao_gttol 1e-13. Measured over the five OpenBLAS kernels and unset,
    twice each (several ranks' runs differ from one run to the next by
    round-off), the largest relative difference: gpts `gpts_np2` = 2.7e-13
    to 8.0e-13, `gpts_np3` = 2.6e-13 to 8.1e-13, `gpts_np4` = 2.6e-13 to
    8.0e-13, `gpts_mumps` = 2.7e-13 to 8.1e-13, `gpts_full` = 2.8e-13 to
    8.1e-13; mortar `mortar_np2` = 8.0e-13 to 4.2e-12, `mortar_np3` =
    5.1e-13 to 4.0e-12, `mortar_np4` = 8.0e-13 to 3.5e-12, `mortar_mumps` =
    1.6e-12 to 5.5e-12, `mortar_full` = 6.1e-13 to 5.3e-12. Catches a substructured step
    that solves another system on some rank counts (a shared node's block
    assembled twice or not at all)."""
    base = HERTZ + ["-mesh_size", "0.1", "-contact_formulation", formulation, "-tao_gttol", "1e-13"]
    runs = {n: run_contact(base + ["-tao_nls_ksp_view"], tmp_path, ranks=n, name=f"np{n}") for n in (1, 2, 3, 4)}
    for n, r in runs.items():
        assert "contact Schur by substructuring" in r.stdout, f"{n} ranks did not take the substructured step"
    ref = runs[1].summary
    for n in (2, 3, 4):
        assert compare(ref, runs[n].summary, f"{n} ranks", f"{formulation}_np{n}") > 40
    mumps = run_contact(base + ["-newton_schur_type", "mumps"], tmp_path, name="mumps").summary
    full = run_contact(base + ["-newton_schur", "0"], tmp_path, ranks=2, name="full").summary
    compare(ref, mumps, "MUMPS Schur step", f"{formulation}_mumps")
    compare(ref, full, "full factorisation", f"{formulation}_full")


@pytest.mark.roundoff
def test_substructure_exact_hessian(tmp_path):
    """The exact contact Hessian from rest (indefinite while the active set
    settles; penalty continuation keeps the iterations few): the surface
    system is then factored by LU, and 2 ranks agree with one and with the
    one-rank MUMPS step, all solved to -tao_gttol 1e-12: measured over the
    five OpenBLAS kernels P `dP_np2` = 1.8e-14 to 1.8e-13 and
    `dP_mumps` = 1.6e-14 to 2.1e-13 apart, bound 8e-13 (was 6e-13, 2.9 times
    the largest), the energy `dE_np2` = 2.2e-16 to 1.3e-15 and
    `dE_mumps` = 1.1e-16 to 1.3e-15, 6 EPS, bound 20 EPS (was 100 EPS).
    Catches a surface system factored as if definite, or otherwise solved
    differently on 2 ranks or by MUMPS."""
    base = HERTZ + ["-mesh_size", "0.1", "-contact_hessian", "exact", "-penalty_stages", "3", "-tao_gttol", "1e-12"]
    one = run_contact(base, tmp_path, name="np1").summary
    two = run_contact(base, tmp_path, ranks=2, name="np2").summary
    mumps = run_contact(base + ["-newton_schur_type", "mumps"], tmp_path, name="mumps").summary
    for s, label, name in ((two, "2 ranks", "np2"), (mumps, "MUMPS Schur step", "mumps")):
        dP = figure(f"dP_{name}", abs(s["contact_force"] / one["contact_force"] - 1))
        dE = figure(f"dE_{name}", abs(s["energy"] / one["energy"] - 1))
        print(f"{label}: P {dP:.2e}, energy {dE:.2e}")
        assert dP <= 8e-13, label
        assert dE <= 20 * EPS, label


@pytest.mark.roundoff
def test_substructure_tiny_subdomains(tmp_path):
    """h = 0.5 (320 dofs) on 24 ranks: subdomains of a few dofs, empty ones and
    ones without an interior dof, some whose MUMPS workspace estimate falls
    short and is enlarged; the answer is one rank's to compare()'s 2e-11
    (measured over the five OpenBLAS kernels and unset, twice each,
    `worst_np24` = 5.1e-14 to 2.0e-12). Catches a subdomain of no interior dof, or none at all, that
    drops or doubles its surface rows."""
    base = HERTZ + ["-mesh_size", "0.5", "-tao_gttol", "1e-12"]
    one = run_contact(base, tmp_path, name="np1").summary
    many = run_contact(base + info_args(tmp_path, "np24"), tmp_path, ranks=24, name="np24")
    sizes = [line.split("subdomain:")[1] for line in info_text(tmp_path, "np24").splitlines() if "subdomain:" in line]
    assert len(sizes) == 24
    assert any(s.strip().startswith("0 dofs") for s in sizes)
    assert any(", 0 interior" in s and not s.strip().startswith("0 dofs") for s in sizes)
    compare(one, many.summary, "24 ranks", "worst_np24")


def test_mumps_schur_one_rank_only(tmp_path):
    """MUMPS Schur complements are sequential in PETSc 3.18: the MUMPS step on
    2 ranks is refused with one line naming the option, status 1."""
    r = run_contact(HERTZ + ["-mesh_size", "0.2", "-newton_schur_type", "mumps"], tmp_path, ranks=2, check=False)
    assert r.returncode == 1
    assert "contact: error: option -newton_schur_type mumps: one rank only" in r.stderr


@pytest.mark.roundoff
@pytest.mark.parametrize("formulation,ranks", [("gpts", 1), ("gpts", 2), ("mortar", 2)])
def test_iterative_step(formulation, ranks, tmp_path):
    """-newton_iterative (CG preconditioned by GAMG with the bodies' rigid
    motions as near-nullspace, each step to relative residual 1e-6) reaches
    the direct step's solution. Both solved to -tao_gttol 1e-12, where either
    path ends at round-off whatever machine takes it (at the default 1e-8 the
    two stop at different residuals: gpts measured 2.7e-10 apart): P
    `dP` = 4.9e-15 to 2.3e-13 apart over the five OpenBLAS kernels (gpts on
    1 and 2 ranks, mortar on 2), bound 8e-13 (was 6e-13, 2.6 times the
    largest); the energy, stationary there, `dE` = 0 to 3.4e-15, 16 EPS,
    bound 50 EPS. Catches a CG step that solves another system than the
    direct one (a wrong operator or near-nullspace): Newton then converges
    elsewhere, or not within the iteration limit."""
    base = HERTZ + ["-mesh_size", "0.1", "-contact_formulation", formulation, "-tao_gttol", "1e-12"]
    it = run_contact(base + ["-newton_iterative"], tmp_path, ranks=ranks, name="iterative")
    direct = run_contact(base, tmp_path, name="direct").summary
    assert " CG iterations" in it.stdout
    s = it.summary
    dP = figure("dP", abs(s["contact_force"] / direct["contact_force"] - 1))
    dE = figure("dE", abs(s["energy"] / direct["energy"] - 1))
    print(f"P {dP:.2e}, energy {dE:.2e}")
    assert dP <= 8e-13
    assert dE <= 50 * EPS
