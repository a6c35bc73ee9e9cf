#!/usr/bin/python3
"""The rubber-squeeze scene solved by GetFEM 5.4 (Debian python3-getfem), an
independent code, on the program's own meshes: the force-squeeze curve to
compare with ours (scripts/squeeze_study.py, bench/squeeze/).

The same problem: the quarter disc (meshes/rubber-squeeze/disc.geo, the .msh
the program generated, Tri6 read with its curved P2 geometry), P2
displacements, plane strain, the energy W = mu/2 (I1 - 3 - 2 ln J) +
lambda/2 (ln J)^2 with I1 = tr(F^T F) + 1 (F33 = 1), written in GetFEM's
weak-form language as its first Piola stress P = mu (F - F^-T) + lambda ln(J)
F^-T; u_x = 0 on symx and u_y = 0 on symy (multipliers); the rigid plate
y = 1 - d as a penalty on the arc, k_p <y - (1 - d)>_+ along y per unit
reference length, with the program's own k_p (its JSON's) unless --penalty:
for a flat plate the gap Y + u_y - (1 - d) is exact in the current
configuration, so no contact search is needed. Newton to a residual of
1e-11 at each of the 20 increments d = 0.3 k / 20 from rest. What differs
from the program: its mortar contact (the gap at the slave's quadrature
points, weighted by the mortar's nodal weights) against a penalty on
GetFEM's quadrature points of the arc (order 10), and the plate's reaction
summed from the penalty's force here.

    /usr/bin/python3 scripts/getfem_squeeze.py --mesh build/meshes/rubber-squeeze/disc-h0.05_R1.msh \\
        --penalty 25544.6 -o bench/squeeze/getfem-h0.05.json

(Debian's python3-getfem is for the system's python3, /usr/bin/python3.)
"""
import argparse
import json
import time

import numpy as np

E, NU, SQUEEZE, STEPS = 1.0, 0.45, 0.3, 20
MU, LAM = E / (2 * (1 + NU)), E * NU / ((1 + NU) * (1 - 2 * NU))


def solve(msh, penalty, steps=STEPS):
    import getfem as gf
    gf.util_trace_level(0)
    gf.util_warning_level(0)
    m = gf.Mesh("import", "gmsh", msh)
    regions = {"contact": 1, "symx": 2, "symy": 3}    # the .msh's physical tags (disc.geo's order)
    mfu = gf.MeshFem(m, 2)
    mfu.set_classical_fem(2)
    mim = gf.MeshIm(m, gf.Integ("IM_TRIANGLE(10)"))
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("mu", [MU])
    md.add_initialized_data("lam", [LAM])
    md.add_initialized_data("kp", [penalty])
    md.add_initialized_data("top", [1.0])
    md.add_macro("F", "Id(2) + Grad_u")
    md.add_macro("J", "Det(F)")
    md.add_nonlinear_term(mim, "(mu * (F - Inv(F)') + lam * log(J) * Inv(F)') : Grad_Test_u")
    md.add_nonlinear_term(mim, "kp * pos_part(X(2) + u(2) - top) * Test_u(2)", regions["contact"])
    mfm = gf.MeshFem(m, 1)
    mfm.set_classical_fem(2)
    md.add_normal_Dirichlet_condition_with_multipliers(mim, "u", mfm, regions["symx"])
    md.add_normal_Dirichlet_condition_with_multipliers(mim, "u", mfm, regions["symy"])
    energy_expr = "mu / 2 * (Norm_sqr(F) + 1 - 3 - 2 * log(J)) + lam / 2 * sqr(log(J))"
    rows = [dict(squeeze=0.0, force=0.0, energy=0.0, iterations=0)]
    t0 = time.time()
    for k in range(1, steps + 1):
        d = SQUEEZE * k / steps
        md.set_variable("top", [1.0 - d])
        its = md.solve("max_res", 1e-11, "max_iter", 100, "lsearch", "simplest")
        its = int(its[0]) if isinstance(its, (list, tuple, np.ndarray)) else int(its)
        force = gf.asm("generic", mim, 0, "kp * pos_part(X(2) + u(2) - top)", regions["contact"], md)
        W = gf.asm("generic", mim, 0, energy_expr, -1, md)
        Wc = gf.asm("generic", mim, 0, "kp / 2 * sqr(pos_part(X(2) + u(2) - top))", regions["contact"], md)
        rows.append(dict(squeeze=d, force=float(force), energy=float(W + Wc), iterations=its))
    return dict(mesh=msh, dofs=int(mfu.nbdof()), penalty=penalty, time=time.time() - t0, steps=rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mesh", required=True)
    ap.add_argument("--penalty", type=float, required=True)
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    r = solve(a.mesh, a.penalty)
    with open(a.output, "w") as f:
        json.dump(r, f, indent=1)
    print(f"{a.mesh}: {r['dofs']} dofs, force at the full squeeze {r['steps'][-1]['force']:.10g}, "
          f"energy {r['steps'][-1]['energy']:.10g}, {r['time']:.1f} s")


if __name__ == "__main__":
    main()
