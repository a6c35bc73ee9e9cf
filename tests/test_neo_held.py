"""A neo-Hookean body held by its contacts alone (src/body/anchors.c): its
free rigid motions are anchored by force controls of force zero, whose
border's columns K e_k are made again with each Hessian from the tangent
the Hessian has (forcecontrol.c, ProblemUpdateControlBorder).

Two scenes of our own (tests/meshes/neo-held/): a rubber half disc (radius 1,
E = 1, nu = 0.45, neo-Hookean, the half x >= 0) whose symmetry line x = 0 is
on rollers (u_x = 0: free in y), and a whole rubber disc, held by nothing
but its contacts in x, y and rotation; each between two rigid flat plates,
the lower one fixed at y = -1, the upper one moved down from y = 1 by the
squeeze (30 % of the diameter: 0.6), frictionless. Checked against what
does not come from the program's figures: the body's equilibrium (the two
plates' forces), the anchors' reactions against the stop, the stored energy
against the plate's work (the trapezoid rule over the increments), 1 and 2
ranks, and GetFEM (scripts/getfem_squeeze.py's energy on the quarter disc,
which the symmetry makes the same problem: the half disc's plate carries
the quarter's force, the whole disc's twice it)."""
import json
import os
import subprocess

import numpy as np
import pytest

from conftest import GETFEM_PYTHON, ROOT, figure, getfem_available, run_contact

MESHES = "tests/meshes/neo-held"
SQUEEZE = 0.6   # the upper plate's travel at 30 % of the diameter


def scene(kind, h, steps):
    """The options of the half disc ("half") or the whole disc ("disc") at
    mesh size h, squeezed by 30 % in `steps` increments, each recorded."""
    half = kind == "half"
    x0 = -0.2 if half else -1.5
    args = ["-bodies", "disc,top,bottom",
            "-disc_geo", f"{MESHES}/{'halfdisc' if half else 'disc'}.geo", "-disc_geo_params", "R=1",
            "-disc_E", "1", "-disc_nu", "0.45", "-disc_material", "neohookean"]
    if half:
        args += ["-disc_bc", "symx", "-disc_bc_symx_components", "x"]
    for name, y, push in (("top", 1, -SQUEEZE), ("bottom", -1, 0)):
        args += [f"-{name}_geo", f"{MESHES}/plate.geo", f"-{name}_geo_params", f"Y={y},x0={x0},x1=1.5",
                 f"-{name}_rigid", f"-{name}_bc", "contact", f"-{name}_bc_contact_values", f"0,{push}"]
    args += ["-contact_pairs", "up,down", "-contact_up_surfaces", "disc:upper,top:contact",
             "-contact_down_surfaces", "disc:lower,bottom:contact",
             "-mesh_size", repr(h), "-load_steps", str(steps), "-load_path", "-output", "none"]
    return args


def path(s):
    """(the upper plate's travel, its force (down, positive), the lower
    plate's force (up, positive), the stored energy) at each recorded state."""
    p = s["load_path"]
    d = SQUEEZE * np.array([q["load"] for q in p])
    top = -np.array([q["reactions"]["top:contact"][1] for q in p])
    bottom = np.array([q["reactions"]["bottom:contact"][1] for q in p])
    return d, top, bottom, np.array([q["energy"] for q in p])


def work(d, F):
    return float(np.sum(0.5 * (F[1:] + F[:-1]) * np.diff(d)))


def anchors(s):
    return [c for c in s["force_control"] if c["anchor"]]


@pytest.fixture(scope="module")
def coarse(tmp_path_factory):
    """Each scene at h = 0.2, 6 increments, on 1 and 2 ranks: {(kind, ranks): summary}."""
    tmp = tmp_path_factory.mktemp("neo_held")
    return {(k, n): run_contact(scene(k, 0.2, 6), tmp, ranks=n, name=f"{k}{n}").summary
            for k in ("half", "disc") for n in (1, 2)}


@pytest.mark.parametrize("kind", ["half", "disc"])
def test_held_by_contacts(kind, coarse):
    """Solved (exit 0), where it was refused ("held by its contacts alone,
    it would be anchored by force controls, which need a constant
    stiffness"). The anchors are the disc's (half disc: u_y at one vertex;
    whole disc: x, y at one and x at another); their reactions are zero
    within what the stop guarantees: a held direction's reaction is its
    entry of the gradient, at most the gradient norm; the whole disc's slide
    along the plates and its rotation are motions frictionless plates do not
    hold, frozen within the allowance of unheld.c, 1e-3 of the scene's
    largest force. Measured: the largest anchor reaction over the force
    `anchor` = 2e-13 (half) to 5e-6 (disc). The body's equilibrium: the two
    plates' forces differ by at most the anchors' reactions plus sqrt(n)
    |g|: `balance` = 1e-15 to 4e-6 of the force."""
    s = coarse[(kind, 1)]
    a = anchors(s)
    assert a and all(c["body"] == "disc" and c["force"] == 0 for c in a)
    assert len(a) == (1 if kind == "half" else 3)
    d, top, bottom, E = path(s)
    F = top[-1]
    worst = max(abs(c["reaction"]) for c in a)
    figure("anchor", worst / F)
    limit = s["gradient_norm"] if kind == "half" else 1e-3 * F + s["gradient_norm"]
    assert worst <= limit
    figure("balance", abs(top[-1] - bottom[-1]) / F)
    assert abs(top[-1] - bottom[-1]) <= sum(abs(c["reaction"]) for c in a) + np.sqrt(s["dofs"]) * s["gradient_norm"]


@pytest.mark.parametrize("kind", ["half", "disc"])
def test_energy_is_work(kind, coarse):
    """The stored energy at 30 % against the upper plate's work along the 6
    increments by the trapezoid rule (the lower plate and the rollers do no
    work; the anchors' reactions are zero): `balance` = 0.03 (relative),
    the rule's own error, O(step^2), largest over the first increment where
    the contact starts from a point. Estimated from the run itself by
    Richardson (the rule over every other increment): `rule` = 0.026 to
    0.027, and what is left once it is removed `left` = 3e-3 to 4e-3.
    Bound: what is left under a third of the rule's estimated error (the
    balance is the rule's error, not a missing work)."""
    s = coarse[(kind, 1)]
    d, top, _, E = path(s)
    assert len(d) == 7 and E[0] == 0
    w6, w3 = work(d, top), work(d[::2], top[::2])
    figure("balance", w6 / E[-1] - 1)
    rule = figure("rule", (w3 - w6) / 3 / E[-1])
    left = figure("left", (4 * w6 - w3) / 3 / E[-1] - 1)
    assert abs(left) <= abs(rule) / 3


@pytest.mark.roundoff
@pytest.mark.parametrize("kind", ["half", "disc"])
def test_two_ranks(kind, coarse):
    """1 and 2 ranks: the plate's force along the path. Each run stops each
    increment within the final tolerance, so a state whose gradient is g is
    off its answer by a residual force g, of which the plate takes at most
    sqrt(n) |g|; for two runs sqrt(n) (|g1| + |g2|) with the final g (a
    bound for the last increment's; the earlier ones stopped at the same
    absolute tolerance). Measured: `dP` = 1e-13 to 4e-12 of the force."""
    one, two = coarse[(kind, 1)], coarse[(kind, 2)]
    _, F1, _, _ = path(one)
    _, F2, _, _ = path(two)
    assert len(F1) == len(F2)
    figure("dP", abs(F1[-1] - F2[-1]) / F1[-1])
    bound = np.sqrt(one["dofs"]) * (one["gradient_norm"] + two["gradient_norm"])
    assert abs(F1[-1] - F2[-1]) <= bound


def test_tangent_at_rest(tmp_path):
    """With -tangent_at_rest 1 the Hessian is the stiffness at rest, and the
    border's columns are made from it too (the same stiffness as the
    Hessian's): the half disc converges to the same force as with the
    tangent, within the two stops' bound sqrt(n) (|g1| + |g2|). Measured
    `dP` = 1e-10 of the force."""
    full = run_contact(scene("half", 0.2, 6), tmp_path, name="full").summary
    rest = run_contact(scene("half", 0.2, 6) + ["-tangent_at_rest", "1"], tmp_path, name="rest").summary
    F1, F2 = path(full)[1][-1], path(rest)[1][-1]
    figure("dP", abs(F1 - F2) / F1)
    assert abs(F1 - F2) <= np.sqrt(full["dofs"]) * (full["gradient_norm"] + rest["gradient_norm"])


def getfem_quarter(tmp, h, steps):
    """GetFEM's quarter disc (meshes/rubber-squeeze/disc.geo meshed by gmsh
    at h) squeezed by 0.3 in `steps` increments (scripts/getfem_squeeze.py,
    the same energy, k_p = 1000 E*/h): its steps' list."""
    msh = os.path.join(str(tmp), f"quarter-h{h}.msh")
    subprocess.run(["gmsh", "-2", "-setnumber", "h", str(h), "-setnumber", "R", "1",
                    os.path.join(str(ROOT), "meshes", "rubber-squeeze", "disc.geo"), "-o", msh],
                   check=True, capture_output=True)
    out = os.path.join(str(tmp), f"getfem-h{h}.json")
    code = ("import json, sys; sys.path.insert(0, %r); import getfem_squeeze as g; "
            "json.dump(g.solve(%r, %r, steps=%d), open(%r, 'w'))"
            % (os.path.join(str(ROOT), "scripts"), msh, 1000 / (1 - 0.45 ** 2) / h, steps, out))
    subprocess.run([GETFEM_PYTHON, "-c", code], check=True, capture_output=True, timeout=1800)
    with open(out) as f:
        return json.load(f)["steps"]


@pytest.mark.stress
@pytest.mark.skipif(not getfem_available(), reason="GetFEM (python3-getfem) is not installed")
def test_getfem(tmp_path):
    """The squeeze force at 10, 20 and 30 % of the diameter, the half disc
    and the whole disc at h = 0.1 in 30 increments on 1 and 2 ranks, against
    GetFEM's quarter disc at h = 0.05 (the half disc's plate carries the
    quarter's force, the whole disc's twice it). Measured, the largest
    relative difference over the three squezes: `half` = 2.6e-3, `disc` =
    2.6e-3 (GetFEM's own from h = 0.1 to 0.05: 2e-3); 2 ranks the same
    force as 1 to `ranks` = 1e-11. Bound 2 %. The energy at 30 % against
    GetFEM's: `energy` = 2e-3 (whole disc, half of it against GetFEM's
    quarter times 4... the whole disc's stored energy is 4 quarters')."""
    ref = getfem_quarter(tmp_path, 0.05, 30)
    Fg = np.array([ref[k]["force"] for k in (10, 20, 30)])
    Eg = ref[30]["energy"]
    for kind, factor in (("half", 1), ("disc", 2)):
        runs = [run_contact(scene(kind, 0.1, 30), tmp_path, ranks=n, name=f"{kind}{n}").summary for n in (1, 2)]
        F = [path(s)[1][[10, 20, 30]] / factor for s in runs]
        err = np.max(np.abs(F[0] / Fg - 1))
        print(kind, F[0], Fg)
        figure(kind, err)
        figure("ranks", np.max(np.abs(F[1] / F[0] - 1)))
        assert err <= 0.02
        assert np.max(np.abs(F[1] / Fg - 1)) <= 0.02
        figure("energy", abs(path(runs[0])[3][-1] / (2 * factor * Eg) - 1))
        assert abs(path(runs[0])[3][-1] / (2 * factor * Eg) - 1) <= 0.02
