"""Forces given to a 3D frictional pair that friction cannot hold, named
before solving (src/contact/friction3d.c, Friction3dCheckGivenForces: 2D's
src/contact/givenforces.c for a 3D pair): a body held along a flat partner
by one frictional pair alone, given forces alone (rollers on planes normal
to the partner allowed: they react along their axis), whose tangential
force exceeds mu times its normal one at some stage, is one line naming the
pair, the body, the stage and the forces, status 1, nothing written (the
solve itself ended "did not converge", status 2).

The scene: tests/test_friction3d.py's flat patch, a Tet10 box [0, 1]^2 x
[0.5, 1] on a wider Hex27 box [-0.1, 1.1]^2 x [0, 0.5] (E 1000, nu 0.3, mu
0.3), the upper's top given P = 5 down in stage 1 and (Q, 5 down) in stage
2 by force control, its faces y = 0 and y = 1 on rollers (held in y, normal
to the partner's plane z = 0)."""
import pytest

from conftest import run_contact

MU, P = 0.3, 5.0
BOX = "tests/meshes/contact3d/box.geo"


def patch_forces(Q):
    return ["-bodies", "lower,upper",
            "-lower_geo", BOX, "-lower_geo_params", "hex=1,n=4,m=2,x0=-0.1,y0=-0.1,L=1.2", "-lower_E", 1000, "-lower_nu", 0.3,
            "-lower_bc", "bottom,xmin,xmax,ymin,ymax", "-lower_bc_bottom_components", "z", "-lower_bc_xmin_components", "x",
            "-lower_bc_xmax_components", "x", "-lower_bc_ymin_components", "y", "-lower_bc_ymax_components", "y",
            "-upper_geo", BOX, "-upper_geo_params", "hex=0,h=0.3,z0=0.5", "-upper_E", 1000, "-upper_nu", 0.3,
            "-upper_bc", "top,ymin,ymax", "-upper_bc_top_components", "x,z", "-upper_bc_top_control", "force,force",
            "-upper_bc_top_values", f"0,{-P},{Q!r},{-P}",
            "-upper_bc_ymin_components", "y", "-upper_bc_ymax_components", "y",
            "-contact_pairs", "p", "-contact_p_surfaces", "upper:bottom,lower:top", "-contact_p_friction", MU,
            "-load_stages", 2]


def lines(r):
    return [l for l in r.stderr.splitlines() if l.strip()]


@pytest.mark.parametrize("ratio", [1.0001, 1.16, 3.0])
def test_force_above_mu_P(ratio, tmp_path):
    """Q = ratio mu P in stage 2: one line naming the pair, the body, stage 2,
    Q (along the partner), P (across it), mu P, Q/(mu P) (to its 6 printed
    digits) and the option to raise, status 1, no output, before any solve."""
    Q = ratio * MU * P
    r = run_contact(patch_forces(Q), tmp_path, check=False)
    out = lines(r)
    assert r.returncode == 1 and len(out) == 1, r.stderr
    assert out[0].startswith("contact: error: pair p: the forces given on body upper at stage 2 are ")
    said = float(out[0].split(" are ")[1].split(" along")[0])
    assert said == pytest.approx(Q, rel=1e-5) and "along lower:top and 5" in out[0]
    assert f"= {MU * P:g};" in out[0] and "-contact_p_friction" in out[0]
    assert float(out[0].split("Q/(mu P) = ")[1].split(")")[0]) == pytest.approx(ratio, rel=1e-5)
    assert not r.summary_path.exists() and not r.output_path.exists()


@pytest.mark.parametrize("extra", [["-upper_bc_top_values", f"0,{-P},{0.9999 * MU * P!r},{-P}"],
                                   ["-upper_bc_top_control", "force,displacement", "-upper_bc_top_values", f"0,-0.01,{3 * MU * P!r},-0.01"],
                                   ["-contact_p_friction", 0]])
def test_not_refused(extra, tmp_path):
    """Not refused where friction may hold or the check cannot know: Q = 0.9999
    mu P; the normal component held by a displacement (it reacts any
    force); no friction. The solve is started (one Newton iteration here)."""
    Q = 1.16 * MU * P
    r = run_contact(patch_forces(Q) + ["-load_steps", 1, "-tao_max_it", 1, "-load_cutbacks", 0] + extra, tmp_path, check=False)
    assert "more than friction holds" not in r.stderr, r.stderr
    assert r.returncode in (0, 2), r.stderr
