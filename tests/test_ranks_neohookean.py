"""A rigid cylinder pressed into a neo-Hookean pad (tests/meshes/ranks-neo),
Newton with the tangent at every step (-tangent_at_rest 0): 2 ranks reach
the 1-rank answer whatever the partitioner, frictionless and with friction
(press, then drag). The step is MUMPS's LDL^T of the indefinite Hessian; on
2 ranks its pivots are delayed past the workspace the analysis sized, which
MUMPS refused (INFOG(1) = -9) until the workspace margin was raised
(newtonstep.c): TAO then took gradient steps and stopped."""
import pytest

from conftest import figure, run_contact

SCENE = ["-options_file", "tests/meshes/ranks-neo/ranks-neo.opts", "-tangent_at_rest", "0",
         "-pad_mesh_size", "0.06", "-cyl_mesh_size", "0.06", "-tao_gttol", "1e-12"]
FRICTION = ["-load_stages", "2", "-cyl_bc_top_values", "0,-0.1,0.3,-0.1", "-pad_bc_base_values", "0,0,0,0",
            "-contact_press_friction", "0.5"]
# At -tao_gttol 1e-12 both runs stop at round-off of the same minimum: the
# relative differences measured are about 1e-12 and below; 1e-10 is the
# stop's gradient (1e-12 of the first) over the pad's stiffness contrast.
BOUND = 1e-10


def compare(tmp_path, extra, partitioner):
    one = run_contact(SCENE + extra, tmp_path, name="one")
    two = run_contact(SCENE + extra + ["-partitioner", partitioner], tmp_path, ranks=2, name="two", check=False)
    assert two.returncode == 0, f"2 ranks ({partitioner}) exited {two.returncode}:\n{two.stdout[-1500:]}"
    s1, s2 = one.summary, two.summary
    dP = abs(s2["contact_force"] - s1["contact_force"]) / abs(s1["contact_force"])
    dE = abs(s2["energy"] - s1["energy"]) / abs(s1["energy"])
    return dP, dE


@pytest.mark.roundoff
@pytest.mark.parametrize("partitioner", [pytest.param("metis", marks=pytest.mark.kernels), "simple",
                                         pytest.param("ptscotch", marks=pytest.mark.kernels)])
def test_frictionless_partitioners(tmp_path, partitioner):
    """Frictionless, one push (0.01, -0.05): P and the energy on 2 ranks
    within 1e-10 of 1 rank's for each partitioner. Before the fix
    -partitioner simple stopped with DIVERGED_LS_FAILURE after 4 cutbacks
    (status 2). Measured `dP` = up to 9.7e-13, `dE` = 1.3e-15 to 3e-15."""
    dP, dE = compare(tmp_path, [], partitioner)
    figure("dP", dP)
    figure("dE", dE)
    assert dP < BOUND and dE < BOUND


@pytest.mark.roundoff
@pytest.mark.kernels
def test_friction_press_drag(tmp_path):
    """Friction 0.5, pressed by 0.1 then dragged by 0.3 (two stages, full
    sliding): 2 ranks (metis) within 1e-10 of 1 rank in P and the energy.
    Measured `dP` = up to 8.1e-13, `dE` = 2.7e-15 to 7.0e-13."""
    dP, dE = compare(tmp_path, FRICTION, "metis")
    figure("dP", dP)
    figure("dE", dE)
    assert dP < BOUND and dE < BOUND
