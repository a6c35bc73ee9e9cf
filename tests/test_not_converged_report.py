"""A solve that does not converge prints no contact report (its pressure,
force and shear are not a solution's): TAO's line, the warning, the energy
and gradient norm it stopped at, and the one line on stderr; status 2,
nothing written."""
from conftest import run_contact


def test_no_report_of_a_non_solution(tmp_path):
    """The cattaneo scene stopped after 5 Newton iterations (no cutback): no
    'Contact pair' block, no pressure table, no shear line on stdout."""
    r = run_contact(["-options_file", "meshes/cattaneo/cattaneo.opts", "-load_steps", "1", "-load_cutbacks", "0",
                     "-tao_max_it", "5"], tmp_path, check=False)
    print(r.stdout)
    assert r.returncode == 2
    assert "did not converge" in r.stdout and "gradient norm" in r.stdout
    for word in ("Contact pair", "pressure on", "shear force", "contact force on"):
        assert word not in r.stdout, word
    assert not r.summary_path.exists() and not r.output_path.exists()


def test_report_of_a_solution(tmp_path):
    """The same scene converged prints its report (the test above can fail)."""
    r = run_contact(["-options_file", "meshes/cattaneo/cattaneo.opts", "-load_steps", "1", "-output", "none"], tmp_path)
    assert "Contact pair interface" in r.stdout and "shear force" in r.stdout
