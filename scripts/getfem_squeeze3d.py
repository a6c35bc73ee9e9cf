#!/usr/bin/python3
"""A rubber ball squeezed between two rigid plates, solved by GetFEM 5.4
(Debian python3-getfem), an independent code, on its own mesh: the force at
squeezes of 10, 20 and 30 % of the diameter to compare with ours
(tests/test_squeeze3d.py, tests/data/getfem-squeeze3d-h*.json).

The problem: a ball of radius R = 1 (E = 1, nu = 0.45), an eighth of it
(x, y, z >= 0: tests/meshes/contact3d/eighthball.geo, meshed here by Gmsh
at the size --h near the top and --hf far from it, or the program's .msh of
it, --mesh; Tet10 read with its curved P2 geometry), P2
displacements, the energy of the program's neo-Hookean material (its
src/body/neohookean.c) W = mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2,
written in GetFEM's weak-form language as its first Piola stress P =
mu (F - F^-T) + lambda ln(J) F^-T; u_x = 0 on symx, u_y = 0 on symy,
u_z = 0 on symz (multipliers: the plane z = 0 stands for the lower plate);
the upper plate z = R - d rigid, a penalty on the cap, k_p <z - (R - d)>_+
along z per unit reference area, with the program's k_p (--penalty): for a
flat plate the gap Z + u_z - (R - d) is exact in the current
configuration, so no contact search is needed. d from 0 to 0.3 R in
--steps increments (a squeeze of d / R of the diameter 2R), Newton (MUMPS)
to a residual of 1e-10 at each from the linear predictor of the last two
increments' answers. The plate's force is the eighth's (the whole
ball's is 4 times it). What differs from the program: its mortar contact
(the gap at the slave's quadrature points, weighted by the mortar's nodal
weights) and its plate (an elastic block far stiffer than the ball)
against a penalty at GetFEM's quadrature points of the cap (its
IM_TETRAHEDRON(ORDER) faces' rule) under a rigid plane.

    /usr/bin/python3 scripts/getfem_squeeze3d.py --h 0.075 --hf 0.15 --penalty 23398.91802171221 \\
        --steps 6 -o tests/data/getfem-squeeze3d-h0.075.json        # its finer mesh: 13 minutes
    /usr/bin/python3 scripts/getfem_squeeze3d.py --h 0.1 --hf 0.2 --penalty 23398.91802171221 \\
        --steps 6 -o tests/data/getfem-squeeze3d-h0.1.json          # the scene's mesh: 7 minutes

(the penalty the scene's k_p, its JSON's contact.squeeze.penalty).

(Debian's python3-getfem is for the system's python3, /usr/bin/python3.)
"""
import argparse
import json
import os
import subprocess
import tempfile
import time

import numpy as np

E, NU, R, SQUEEZE, STEPS = 1.0, 0.45, 1.0, 0.3, 30
MU, LAM = E / (2 * (1 + NU)), E * NU / ((1 + NU) * (1 - 2 * NU))
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GEO = os.path.join(ROOT, "tests", "meshes", "contact3d", "eighthball.geo")
REGIONS = {"symx": 1, "symy": 2, "symz": 3, "cap": 4, "side": 5}    # eighthball.geo's physical tags
ORDER = 6


def mesh(h, hf, rc, zc, out):
    """Gmsh's Tet10 mesh of the eighth ball (size h within rc of its top,
    hf from 2 rc) into out, as the program runs Gmsh on a body's .geo."""
    numbers = [("h", h), ("R", R), ("zc", zc)] + [(k, v) for k, v in (("hf", hf), ("rc", rc)) if v is not None]
    subprocess.run(["gmsh", "-3", "-format", "msh22"] + [a for k, v in numbers for a in ("-setnumber", k, repr(v))]
                   + [GEO, "-o", out], check=True, capture_output=True)
    return out


def solve(msh, penalty, steps=STEPS, order=ORDER):
    import getfem as gf
    gf.util_trace_level(0)
    gf.util_warning_level(0)
    m = gf.Mesh("import", "gmsh", msh)
    mfu = gf.MeshFem(m, 3)
    mfu.set_classical_fem(2)
    mim = gf.MeshIm(m, gf.Integ(f"IM_TETRAHEDRON({order})"))
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("mu", [MU])
    md.add_initialized_data("lam", [LAM])
    md.add_initialized_data("kp", [penalty])
    md.add_initialized_data("top", [R])
    md.add_macro("F", "Id(3) + Grad_u")
    md.add_macro("J", "Det(F)")
    md.add_nonlinear_term(mim, "(mu * (F - Inv(F)') + lam * log(J) * Inv(F)') : Grad_Test_u")
    md.add_nonlinear_term(mim, "kp * pos_part(X(3) + u(3) - top) * Test_u(3)", REGIONS["cap"])
    mfm = gf.MeshFem(m, 1)
    mfm.set_classical_fem(2)
    for g in ("symx", "symy", "symz"):
        md.add_normal_Dirichlet_condition_with_multipliers(mim, "u", mfm, REGIONS[g])
    energy_expr = "mu / 2 * (Norm_sqr(F) - 3 - 2 * log(J)) + lam / 2 * sqr(log(J))"
    rows = [dict(d=0.0, squeeze=0.0, force=0.0, energy=0.0, iterations=0, contact_area=0.0)]
    t0 = time.time()
    last = md.from_variables()
    for k in range(1, steps + 1):
        d = SQUEEZE * R * k / steps
        md.set_variable("top", [R - d])
        now = md.from_variables()
        if k > 1:
            md.to_variables(2 * now - last)     # the linear predictor from the last two increments
        last = now
        its = md.solve("max_res", 1e-10, "max_iter", 100, "lsearch", "simplest", "lsolver", "mumps")
        its = int(its[0]) if isinstance(its, (list, tuple, np.ndarray)) else int(its)
        force = gf.asm("generic", mim, 0, "kp * pos_part(X(3) + u(3) - top)", REGIONS["cap"], md)
        W = gf.asm("generic", mim, 0, energy_expr, -1, md)
        Wc = gf.asm("generic", mim, 0, "kp / 2 * sqr(pos_part(X(3) + u(3) - top))", REGIONS["cap"], md)
        area = gf.asm("generic", mim, 0, "Heaviside(X(3) + u(3) - top)", REGIONS["cap"], md)
        rows.append(dict(d=d, squeeze=d / R, force=float(force), energy=float(W + Wc), iterations=its,
                         contact_area=float(area)))
        print(f"d {d:.4f}: force {float(force):.8g}, energy {float(W + Wc):.8g}, {its} iterations, "
              f"{time.time() - t0:.0f} s", flush=True)
    return dict(dofs=int(mfu.nbdof()), penalty=penalty, integration=f"IM_TETRAHEDRON({order})",
                time=time.time() - t0, steps=rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--h", type=float, help="the ball's mesh size near its top (Gmsh meshes eighthball.geo)")
    ap.add_argument("--hf", type=float, help="eighthball.geo's far size (its default: h)")
    ap.add_argument("--rc", type=float, help="eighthball.geo's fine radius (its default: 0.5 R)")
    ap.add_argument("--mesh", help="the ball's .msh instead (the program's, of eighthball.geo)")
    ap.add_argument("--zc", type=float, default=0.4, help="the cap's lower edge (the contact surface z >= zc)")
    ap.add_argument("--penalty", type=float, required=True, help="k_p, per unit reference area")
    ap.add_argument("--steps", type=int, default=STEPS, help="increments from rest to the 30 %% squeeze")
    ap.add_argument("--order", type=int, default=ORDER, help="IM_TETRAHEDRON's order")
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    if (a.h is None) == (a.mesh is None):
        ap.error("give one of --h and --mesh")
    with tempfile.TemporaryDirectory() as tmp:
        r = solve(a.mesh or mesh(a.h, a.hf, a.rc, a.zc, os.path.join(tmp, "ball.msh")), a.penalty, a.steps, a.order)
    r.update(h=a.h, hf=a.hf, rc=a.rc, mesh=a.mesh, zc=a.zc, E=E, nu=NU, R=R)
    with open(a.output, "w") as f:
        json.dump(r, f, indent=1)
    last = r["steps"][-1]
    print(f"{a.mesh or 'h ' + repr(a.h)}: {r['dofs']} dofs, force at the 30 % squeeze {last['force']:.10g}, "
          f"energy {last['energy']:.10g}, {r['time']:.1f} s")


if __name__ == "__main__":
    main()
