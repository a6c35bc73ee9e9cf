#!/usr/bin/python3
"""The quarter Hertz ball of tests/test_contact3d.py solved by GetFEM 5.4
(Debian's python3-getfem, an independent code) with its augmented
Lagrangian contact brick, on the program's own Tet10 meshes (the two .msh
files the program generated): the time and accuracy to set beside ours
(scripts/bench_contact3d.py, bench/contact3d/).

The problem (tests/test_contact3d.py's hertz_args): a quarter of the lower
half of a ball, R = 1, E 1000, nu 0.3 (tests/meshes/contact3d/ball.geo),
on a block [0, 1.5]^2 x [-1.5, 0], E 1e5, nu 0.3 (base.geo); the planes
x = 0 and y = 0 on rollers (u.n = 0) in both bodies, the block's bottom
held in z, the ball's top pushed down by 0.01 (u.n = -0.01), each by a
multiplier (add_normal_Dirichlet_condition_with_multipliers, P2); P2
displacements on the meshes' quadratic (isoparametric) tetrahedra, linear
elasticity. Contact: Model.add_integral_contact_between_nonmatching_meshes_brick
(the ball's "cap" as slave, the block's "top" as master; option 1, the
non-symmetric Alart-Curnier augmented Lagrangian, integrated on the cap;
the multiplier lambda_N P1 on the cap (--mult-degree), r = --r (1000 =
E of the ball: its acceptable range is about E to E / h)). Newton with
GetFEM's default line search, max_res 1e-9, MUMPS on one core.

Measured as the program measures itself (test_hertz_quarter): P = 4 F_z,
F_z the top's reaction (the integral of its multiplier), Hertz's a = (3 P
R / (4 E*))^(1/3) and p0 = 3 P / (2 pi a^2); the contact radius from the
pressure's second moment, a_m^2 = 5/2 int p r^2 / int p (int over the
cap, p = -lambda_N > 0); p_max the largest nodal p. Printed (the last
line, JSON): dofs (every dof, multipliers included, and the displacements'
alone), Newton iterations, the solve's time and the whole script's, P,
a_error = a_m / a - 1, pmax_error = p_max / p0 - 1.

    /usr/bin/python3 scripts/getfem_hertz3d.py --ball BALL.msh --base BASE.msh
"""
import argparse
import json
import math
import re
import time

T0 = time.time()
import numpy as np  # noqa: E402

R, E1, E2, NU, PUSH = 1.0, 1000.0, 1e5, 0.3, 0.01


def tags(msh):
    """{physical name: tag} of a Gmsh 2.2 file (GetFEM's regions are the tags)."""
    text = open(msh).read().split("$EndPhysicalNames", 1)[0]
    return {m.group(2): int(m.group(1)) for m in re.finditer(r'^\d+ (\d+) "([^"]+)"$', text, re.M)}


def lame(E):
    return E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ball", required=True)
    ap.add_argument("--base", required=True)
    ap.add_argument("--r", type=float, default=1000.0, help="the augmentation parameter")
    ap.add_argument("--mult-degree", type=int, default=1, help="the contact multiplier's degree on the cap")
    ap.add_argument("--option", type=int, default=1, help="the brick's option (1 non-symmetric Alart-Curnier, 2 symmetric, 3, 4)")
    ap.add_argument("--brick", default="large_sliding", choices=("large_sliding", "nonmatching"))
    ap.add_argument("--release", type=float, default=0.1, help="the large sliding brick's release distance")
    a = ap.parse_args()
    import getfem as gf
    gf.util_trace_level(0)
    gf.util_warning_level(0)
    m1, m2 = gf.Mesh("import", "gmsh", a.ball), gf.Mesh("import", "gmsh", a.base)
    t1, t2 = tags(a.ball), tags(a.base)
    mfu1, mfu2 = gf.MeshFem(m1, 3), gf.MeshFem(m2, 3)
    mfu1.set_classical_fem(2)
    mfu2.set_classical_fem(2)
    mim1, mim2 = gf.MeshIm(m1, 4), gf.MeshIm(m2, 4)
    md = gf.Model("real")
    md.add_fem_variable("u1", mfu1)
    md.add_fem_variable("u2", mfu2)
    for k, (E, mim, u) in enumerate(((E1, mim1, "u1"), (E2, mim2, "u2"))):
        lam, mu = lame(E)
        md.add_initialized_data(f"lambda{k}", [lam])
        md.add_initialized_data(f"mu{k}", [mu])
        md.add_isotropic_linearized_elasticity_brick(mim, u, f"lambda{k}", f"mu{k}")
    mfm1, mfm2 = gf.MeshFem(m1, 1), gf.MeshFem(m2, 1)
    mfm1.set_classical_fem(2)
    mfm2.set_classical_fem(2)
    md.add_initialized_data("push", [-PUSH])
    md.add_filtered_fem_variable("mtop", mfm1, t1["top"])
    md.add_normal_Dirichlet_condition_with_multipliers(mim1, "u1", "mtop", t1["top"], "push")
    for g in ("symx", "symy"):
        md.add_normal_Dirichlet_condition_with_multipliers(mim1, "u1", mfm1, t1[g])
    for g in ("symx", "symy", "bottom"):
        md.add_normal_Dirichlet_condition_with_multipliers(mim2, "u2", mfm2, t2[g])
    cap, top = t1["cap"], t2["top"]
    mfl = gf.MeshFem(m1, 1)
    mfl.set_classical_fem(a.mult_degree)
    if a.brick == "nonmatching":
        md.add_filtered_fem_variable("lambda_n", mfl, cap)
    else:
        mfv = gf.MeshFem(m1, 3)
        mfv.set_classical_fem(a.mult_degree)
        md.add_filtered_fem_variable("lambda", mfv, cap)
    md.add_initialized_data("r", [a.r])
    if a.brick == "nonmatching":
        md.add_integral_contact_between_nonmatching_meshes_brick(mim1, "u1", "u2", "lambda_n", "r", cap, top, a.option)
    else:
        md.add_initialized_data("f", [0.0])
        md.add_initialized_data("alpha", [1.0])
        ib = md.add_integral_large_sliding_contact_brick_raytracing("r", a.release, "f", "alpha", 0)
        md.add_master_contact_boundary_to_large_sliding_contact_brick(ib, mim2, top, "u2")
        md.add_slave_contact_boundary_to_large_sliding_contact_brick(ib, mim1, cap, "u1", "lambda")
    t0 = time.time()
    its = int(np.ravel(md.solve("max_res", 1e-9, "max_iter", 100, "lsolver", "mumps", "lsearch", "default"))[0])
    solve = time.time() - t0
    Fz = abs(gf.asm_generic(mim1, 0, "mtop", t1["top"], md))
    P = 4 * Fz
    Es = 1 / ((1 - NU ** 2) / E1 + (1 - NU ** 2) / E2)
    aH = (3 * P * R / (4 * Es)) ** (1 / 3)
    p0 = 3 * P / (2 * math.pi * aH * aH)
    # p = -lambda_n (compressive) on the cap: its integral and second moment
    ln = "-lambda_n" if a.brick == "nonmatching" else "lambda(3)"
    ip = gf.asm_generic(mim1, 0, ln, cap, md)
    ipr2 = gf.asm_generic(mim1, 0, f"{ln} * (X(1) * X(1) + X(2) * X(2))", cap, md)
    am = math.sqrt(2.5 * ipr2 / ip)
    pmax = float(np.max(-np.asarray(md.variable("lambda_n")))) if a.brick == "nonmatching" else float(np.max(np.asarray(md.variable("lambda"))[2::3]))
    print(json.dumps(dict(dofs=int(md.nbdof()), u_dofs=int(mfu1.nbdof() + mfu2.nbdof()), iterations=its, solve=solve,
                          total=time.time() - T0, P=P, a_hertz=aH, p0=p0, a_moment=am, pmax=pmax, a_error=am / aH - 1,
                          pmax_error=pmax / p0 - 1, force_from_pressure=4 * ip, r=a.r, mult_degree=a.mult_degree,
                          option=a.option, cells=[int(m1.nbcvs()), int(m2.nbcvs())])))


if __name__ == "__main__":
    main()
