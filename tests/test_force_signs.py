"""One sign for every force the program reports: the force exerted on the
body named by what is named (docs/scenes.md, rigid bodies' "Force"). The
report's rigid-body line and pair line, the JSON's bodies.<name>.force and
contact.<pair>.force, and the HDF5's attributes give the contact's force on
the body with one sign; a support's reaction is its opposite; a pair's force
is its whole force, pressure and shear, with its parts beside it."""
import re

import h5py
import numpy as np

from conftest import run_contact


def floats(text):
    return [float(x) for x in re.findall(r"[-+]?\d+\.\d+e[-+]\d+", text)]


def test_rigid_punch_one_sign(tmp_path):
    """The rigid punch pressed down 0.002 on the block: the contact pushes it
    up (its force's y > 0) in the rigid-body line, the pair line, the JSON's
    body and pair and the HDF5; the push group's reaction is its opposite."""
    r = run_contact(["-options_file", "meshes/rigid-punch/rigid-punch.opts"], tmp_path)
    body_line = [l for l in r.stdout.splitlines() if "rigid body punch:" in l][0]
    pair_line = [l for l in r.stdout.splitlines() if "contact force on punch:" in l][0]
    on_body = floats(body_line.split("the contact's force on it")[1])[:2]
    on_pair = floats(pair_line)[:2]
    s = r.summary
    js_body, js_pair = s["bodies"]["punch"]["force"], s["contact"]["tool"]["force"]
    with h5py.File(r.output_path, "r") as f:
        h5 = [f["bodies/punch"].attrs["force_x"], f["bodies/punch"].attrs["force_y"]]
    print(on_body, on_pair, js_body, js_pair, h5, s["reactions"]["punch:push"])
    assert on_body[1] > 0 and on_pair[1] > 0
    for v in (on_pair, js_body, js_pair, h5):
        assert np.allclose(v, on_body, rtol=1e-6, atol=1e-12 * abs(on_body[1])), v
    assert np.allclose(s["reactions"]["punch:push"], -np.array(js_body), rtol=1e-12, atol=1e-14)


def test_pair_force_whole_with_parts(tmp_path):
    """The cattaneo disc pressed by P and pulled by Q (one increment a
    stage): the pair's force on the disc is its pressure's and shear's sum,
    and, the disc held by the given forces alone, their opposite to the
    solve's stop (1e-6 of P); the report's pair line gives the whole and
    both parts."""
    r = run_contact(["-options_file", "meshes/cattaneo/cattaneo.opts", "-load_steps", "1"], tmp_path)
    pair = r.summary["contact"]["interface"]
    whole, pres, shear = (np.array(pair[k]) for k in ("force", "pressure_force", "shear_force"))
    given = np.array([1.075, 0.16125])
    print(whole, pres, shear)
    assert np.allclose(whole, pres + shear, rtol=1e-14, atol=1e-15)
    assert np.max(np.abs(whole + given)) <= 1e-6 * given[0]
    line = [l for l in r.stdout.splitlines() if "contact force on disc:" in l][0]
    assert " = pressure (" in line and " + shear (" in line
    assert np.allclose(floats(line)[:2], whole, rtol=1e-6)
