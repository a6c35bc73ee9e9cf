"""L-BFGS with the contact-aware initial Hessian (-lmvm_h0 contact, the
default for lmvm and blmvm): it reaches Newton's answer, refreshes H0 as
often as it says, and the elastic H0 and the refresh period remain options.
The references are Newton's runs of the same scene, both solved to
-tao_gttol 1e-12 so that neither stop adds to the difference."""
import numpy as np
import pytest

from conftest import run_contact

EPS = np.finfo(float).eps
HERTZ = ["-options_file", "meshes/hertz/hertz.opts", "-tao_gttol", "1e-12", "-output", "none"]


@pytest.fixture(scope="module")
def newton(tmp_path_factory):
    return run_contact(HERTZ, tmp_path_factory.mktemp("newton")).summary


@pytest.mark.parametrize("tao", ["lmvm", "blmvm"])
def test_lmvm_reaches_newton(tao, newton, tmp_path):
    """P and the energy to Newton's: measured 8.3e-13 and 3.3e-16 = 1.5 EPS
    (lmvm and blmvm alike), bounds 3e-12 and 10 EPS (the quasi-Newton
    iteration converges linearly, so it stops nearer its tolerance than
    Newton's last quadratic step);
    H0 set up once and then at every iteration (-lmvm_h0_refresh 1), so
    h0_refreshes equals the iterations."""
    s = run_contact(HERTZ + ["-tao_type", tao], tmp_path).summary
    dP = abs(s["contact_force"] / newton["contact_force"] - 1)
    dE = abs(s["energy"] / newton["energy"] - 1)
    print(f"{tao}: {s['iterations']} iterations, {s['h0_refreshes']} H0 set-ups; P {dP:.2e}, energy {dE:.2e}")
    assert dP <= 3e-12 and dE <= 10 * EPS
    assert s["h0_refreshes"] == s["iterations"]


def test_lmvm_refresh_period(tmp_path):
    """-lmvm_h0_refresh 3: H0 set up once, then at iterations 3, 6, ...:
    1 + floor((iterations - 1) / 3) set-ups."""
    s = run_contact(HERTZ + ["-tao_type", "lmvm", "-lmvm_h0_refresh", "3"], tmp_path).summary
    assert s["h0_refreshes"] == 1 + (s["iterations"] - 1) // 3, (s["iterations"], s["h0_refreshes"])
