"""Contact at finite strain in 3D: a rubber ball (radius 1, E = 1,
nu = 0.45, neo-Hookean) squeezed between two flat plates by 10, 20 and 30 %
of its diameter, an eighth of it on its symmetry planes
(tests/meshes/contact3d/squeeze3d.opts: Tet10 of size 0.1 near the top,
0.2 far from it, the lower
plate the plane z = 0 by symmetry, the upper plate a Hex27 block 1e4 times
stiffer than the ball, its top moved down by 0.1, 0.2, 0.3 in three load
stages), against answers that do not come from the program's own figures:

- the stored energy against the work of the plate's reaction along the
  load path (-load_steps 10 -load_path: 10 increments a stage), at each
  stage's end;
- GetFEM (python3-getfem under /usr/bin/python3,
  scripts/getfem_squeeze3d.py) with the same energy W on its own finer mesh
  (0.075 near the top, 0.15 far, stored:
  tests/data/getfem-squeeze3d-h0.075.json), the plate a rigid plane
  there; where GetFEM is installed, rerun on the scene's own mesh;
- the plate's compliance: the same scene with a plate 10 times stiffer.

Each docstring quotes the figures its test records (figure()), as measured
(2 cores, PETSc 3.18, OpenBLAS)."""
import json
import os
import subprocess

import numpy as np
import pytest

from conftest import GETFEM_PYTHON, ROOT, figure, getfem_available, run_contact

SCENE = ["-options_file", "tests/meshes/contact3d/squeeze3d.opts"]
PUSH = 0.1                      # the plate's travel a stage: 10 % of the diameter 2
STEPS = 10                      # increments a stage (even: Simpson's rule over pairs of them)
PATH = ["-load_steps", str(STEPS), "-load_path"]
LEVELS = (1, 2, 3)              # the stages' ends: squeezes of 10, 20, 30 %
TIMEOUT = 3600                  # 3D at finite strain, 30 increments: minutes on a loaded machine
DATA = ROOT / "tests" / "data"


def stage_forces(summary):
    """The plate's force (down, positive) at each stage's end."""
    return np.array([-st["reactions"]["plate:top"][2] for st in summary["load_stages"]])


def path_arrays(summary):
    """(the plate's travel d, its force (down, positive), the energy) at
    rest and at each converged increment of a -load_path run."""
    p = summary["load_path"]
    d = PUSH * np.array([q["load"] for q in p])
    F = -np.array([q["reactions"]["plate:top"][2] for q in p])
    E = np.array([q["energy"] for q in p])
    return d, F, E


def work(d, F, rule):
    """The reaction's work from rest to every recorded state (the
    trapezoid rule) or to every second one (Simpson's rule over pairs of
    increments), as {index: work}."""
    if rule == "trapezoid":
        w = np.concatenate([[0.0], np.cumsum(0.5 * (F[1:] + F[:-1]) * np.diff(d))])
        return {k: w[k] for k in range(len(d))}
    out, w = {0: 0.0}, 0.0
    for k in range(2, len(d), 2):
        h = 0.5 * (d[k] - d[k - 2])
        w += h / 3 * (F[k - 2] + 4 * F[k - 1] + F[k])
        out[k] = w
    return out


def getfem_reference(h):
    """GetFEM's stored run at the mesh size h: ({d: its increment}, the run)."""
    with open(DATA / f"getfem-squeeze3d-h{h:g}.json") as f:
        g = json.load(f)
    return {round(st["d"], 12): st for st in g["steps"]}, g


@pytest.fixture(scope="module")
def squeeze(tmp_path_factory):
    """The scene's load path, 10 increments a stage."""
    return run_contact(SCENE + PATH, tmp_path_factory.mktemp("squeeze3d"), timeout=TIMEOUT).summary


def test_energy_is_work_of_reactions(squeeze):
    """The stored energy at each stage's end (squeezes of 10, 20, 30 %)
    against the plate's reaction integrated along the increments (the
    symmetry planes' and the plate's rollers' reactions do no work; the
    path starts at rest, whose energy is 0 to round-off). Simpson's rule over pairs of
    increments: `simpson` = -1.3e-5 to 4.1e-5 (relative). The trapezoid
    misses by `trapezoid` = 4.8e-4 to 3.2e-3 (10 %: 3.2e-3): its error,
    O(step^2), is largest over the first increments, where the contact
    grows from a point and the force as d^(3/2). Bound 1e-3 on Simpson's at
    every level."""
    d, F, E = path_arrays(squeeze)
    assert len(d) == 3 * STEPS + 1 and abs(E[0]) <= 1e-12 * E[-1]
    simpson, trapezoid = work(d, F, "simpson"), work(d, F, "trapezoid")
    for level in LEVELS:
        k = level * STEPS
        assert abs(d[k] - level * PUSH) < 1e-12
        figure("trapezoid", trapezoid[k] / E[k] - 1)
        assert abs(figure("simpson", simpson[k] / E[k] - 1)) <= 1e-3


def test_force_against_getfem(squeeze):
    """The plate's force at 10, 20 and 30 % against GetFEM's run of the same
    energy on its own finer mesh (eighthball.geo at h = 0.075, hf = 0.15
    against the scene's 0.1 and 0.2; P2 on the curved Tet10, the plate a
    rigid plane as a penalty at its quadrature points, our k_p;
    tests/data/getfem-squeeze3d-h0.075.json, written by
    scripts/getfem_squeeze3d.py --h 0.075 --hf 0.15 --penalty 23398.9
    --steps 6): `dF` = -8.6e-4 to 1.3e-3 (relative; 10 %: -8.6e-4, 20 %:
    +1.3e-3, 30 %: +4.5e-4). Bound 2 %. The forces of the eighth at 10,
    20, 30 %: 0.01541, 0.04863, 0.1015 (the whole ball's 4 times them), at
    29 % Green-Lagrange strain. GetFEM's own mesh trend, from the scene's
    mesh to its finer one: 2.7e-4, 1.1e-3, 5.0e-4."""
    g, _ = getfem_reference(0.075)
    F = stage_forces(squeeze)
    for level, f in zip(LEVELS, F):
        ref = g[round(level * PUSH, 12)]["force"]
        assert abs(figure("dF", f / ref - 1)) <= 0.02


def test_plate_compliance(squeeze, tmp_path):
    """The plate is an elastic block 1e4 times stiffer than the ball, not
    rigid: the same scene with a plate 10 times stiffer again (E = 1e5, one
    increment a stage: a frictionless elastic scene has one equilibrium a
    load) moves the forces at the three levels by `stiffer` = 2.7e-5 to
    3.4e-5 (relative). The plate's compliance goes as 1/E, so a rigid
    plate's force is 10/9 of that change from the scene's: `rigid` =
    3.0e-5 to 3.8e-5, bound
    2e-4, a hundredth of the 2 % of test_force_against_getfem."""
    stiff = run_contact(SCENE + ["-plate_E", "1e5", "-load_steps", "1"], tmp_path, timeout=TIMEOUT).summary
    F, Fs = stage_forces(squeeze), stage_forces(stiff)
    for f, fs in zip(F, Fs):
        figure("stiffer", fs / f - 1)
        assert abs(figure("rigid", 10 / 9 * (fs / f - 1))) <= 2e-4


@pytest.mark.skipif(not getfem_available(), reason="python3-getfem is not installed (apt-get install python3-getfem)")
def test_getfem_same_mesh(squeeze, tmp_path):
    """GetFEM rerun (scripts/getfem_squeeze3d.py) on the scene's own .msh
    with its k_p, 6 increments: its forces at 10, 20, 30 % against ours,
    `dF` = -1.1e-3 to 2.1e-4 (the same mesh: the codes differ in the
    contact, mortar against a penalty at quadrature points, and in the
    plate, elastic against rigid; 10 %, where the contact zone is 4 faces
    across, the most); bound 4e-3. And against its stored run on the mesh
    Gmsh makes of eighthball.geo at the scene's sizes
    (tests/data/getfem-squeeze3d-h0.1.json, --h 0.1 --hf 0.2), `stored` =
    1.8e-14 to 2.9e-13 (both stop at a residual of 1e-10): bound 1e-6."""
    out = tmp_path / "getfem.json"
    mesh = squeeze["bodies"]["ball"]["mesh"]
    subprocess.run([GETFEM_PYTHON, os.path.join(str(ROOT), "scripts", "getfem_squeeze3d.py"), "--mesh", mesh,
                    "--penalty", repr(squeeze["contact"]["squeeze"]["penalty"]), "--steps", "6", "-o", str(out)],
                   cwd=ROOT, check=True, capture_output=True, timeout=TIMEOUT)
    g = {round(st["d"], 12): st for st in json.loads(out.read_text())["steps"]}
    stored, _ = getfem_reference(0.1)
    F = stage_forces(squeeze)
    for level, f in zip(LEVELS, F):
        mine = g[round(level * PUSH, 12)]["force"]
        assert abs(figure("dF", f / mine - 1)) <= 4e-3
        assert figure("stored", abs(stored[round(level * PUSH, 12)]["force"] / mine - 1)) <= 1e-6
