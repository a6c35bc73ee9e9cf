"""The iterative Newton step (CG + GAMG, src/solver/iterative.c) on a 3D
contact scene: the quarter Hertz ball of tests/test_contact3d.py at h = 0.04
(10k dofs). With contact pairs GAMG aggregates the nodes on one level
(src/solver/newtonstep.c): the two-level preconditioner, the cells'
vertices first, cannot meet the mortar's penalty on the quadratic faces
(its preconditioned Hessian spread over 0.038 to 520 at the ball's first
contact step, CG stalled at 1e-3 of the residual for thousands of
iterations). The stop is pinned to an absolute gradient of 1e-10 in both
steps, so that their answers differ by what the stop leaves, not by where
each stops."""

from conftest import figure, run_contact
from test_contact3d import hertz_args

STOP = ["-tao_gatol", "1e-10", "-tao_grtol", "0", "-tao_gttol", "0"]


def force(res):
    assert res.returncode == 0, res.stderr
    return res.summary["contact"]["c"]["force"][2]


def test_iterative_meets_direct(tmp_path):
    """CG + GAMG (forced by -newton_iterative 1, one rank and two) against the
    direct step: the pair's force agrees to `iterative_vs_direct` = 6.3e-14 and
    `ranks2_vs_direct` = -2.9e-13 (relative; bound 1e-8, what the stop
    guarantees: the gradient's 1e-10 against nodal forces of 1e-2 to 1), every CG solve converging (no
    DIVERGED in its reasons)."""
    direct = force(run_contact(hertz_args(0.04) + STOP + ["-newton_iterative", "0"], tmp_path, name="direct"))
    for name, ranks in (("iterative_vs_direct", 1), ("ranks2_vs_direct", 2)):
        res = run_contact(hertz_args(0.04) + STOP + ["-newton_iterative", "1", "-tao_nls_ksp_converged_reason"], tmp_path,
                          name=name, ranks=ranks)
        assert "DIVERGED" not in res.stdout
        assert abs(figure(name, force(res) / direct - 1)) <= 1e-8
