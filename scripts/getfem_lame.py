#!/usr/bin/python3
"""Lame's thick hollow sphere solved by GetFEM 5.4 (Debian python3-getfem),
an independent code, on the program's own Tet10 mesh of the octant
(tests/meshes/solid/shell.geo, the .msh the program generated): the time and
error to set beside ours (scripts/bench_solid3d.py, bench/solid3d/).

The same problem: inner radius a = 1, outer b = 2, E 1000, nu 0.3, pressure
p = 10 on the inner face; the symmetry planes on rollers (u.n = 0 by
multipliers); P2 displacements on the mesh's quadratic (isoparametric)
tetrahedra; linear elasticity; the linear system by MUMPS on one core. The
exact u_r(r) = p a^3 / (E (b^3 - a^3)) [(1 - 2 nu) r + (1 + nu) b^3 / (2 r^2)].
Printed (the last line, JSON): the dofs, the solve's time (assembly and
factorisation), the whole script's, and the relative L2 error of u_r over
the mesh's nodes and over the volume (the program's measure).

    /usr/bin/python3 scripts/getfem_lame.py --mesh build/meshes/scene/shell-h0.1.msh
"""
import argparse
import json
import time

T0 = time.time()
import numpy as np  # noqa: E402

E, NU, P, A, B = 1000.0, 0.3, 10.0, 1.0, 2.0
LAM, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
CA = P * A ** 3 * (1 - 2 * NU) / (E * (B ** 3 - A ** 3))
CB = P * A ** 3 * B ** 3 * (1 + NU) / (2 * E * (B ** 3 - A ** 3))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mesh", required=True)
    a = ap.parse_args()
    import getfem as gf
    gf.util_trace_level(0)
    gf.util_warning_level(0)
    m = gf.Mesh("import", "gmsh", a.mesh)
    # regions by face position (the physical tags' order is shell.geo's; found here by geometry instead)
    faces = m.outer_faces()
    reg = {"symx": 101, "symy": 102, "symz": 103, "inner": 104}
    cvs, fs = faces[0], faces[1]
    sel = {k: [] for k in reg}
    for cv, f in zip(cvs, fs):
        pid = m.pid_in_faces(np.array([[cv], [f]]))
        X = m.pts(pid)
        r = np.linalg.norm(X, axis=0)
        if np.all(np.abs(X[0]) < 1e-9):
            sel["symx"].append((cv, f))
        elif np.all(np.abs(X[1]) < 1e-9):
            sel["symy"].append((cv, f))
        elif np.all(np.abs(X[2]) < 1e-9):
            sel["symz"].append((cv, f))
        elif np.all(np.abs(r - A) < 1e-3):
            sel["inner"].append((cv, f))
    for k, v in sel.items():
        m.set_region(reg[k], np.array(v, dtype=int).T)
    mfu = gf.MeshFem(m, 3)
    mfu.set_classical_fem(2)
    mim = gf.MeshIm(m, 4)
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("lam", [LAM])
    md.add_initialized_data("mu", [MU])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lam", "mu")
    md.add_initialized_data("p", [P])
    md.add_source_term_brick(mim, "u", "p * X / Norm(X)", reg["inner"])  # the pressure pushes outward, along X / |X| on r = a
    mfm = gf.MeshFem(m, 1)
    mfm.set_classical_fem(2)
    for k in ("symx", "symy", "symz"):
        md.add_normal_Dirichlet_condition_with_multipliers(mim, "u", mfm, reg[k])
    t0 = time.time()
    md.solve("max_res", 1e-10, "lsolver", "mumps")
    solve = time.time() - t0
    U = md.variable("u")
    X = mfu.basic_dof_nodes()[:, ::3]
    u = U.reshape(-1, 3).T
    r = np.linalg.norm(X, axis=0)
    ur = np.sum(u * X, axis=0) / r
    ex = CA * r + CB / r ** 2
    nodal = float(np.linalg.norm(ur - ex) / np.linalg.norm(ex))
    md.add_initialized_data("CA", [CA])
    md.add_initialized_data("CB", [CB])
    e2 = gf.asm("generic", mim, 0, "Norm_sqr(u - (CA + CB / pow(Norm(X), 3)) * X)", -1, md)
    n2 = gf.asm("generic", mim, 0, "Norm_sqr((CA + CB / pow(Norm(X), 3)) * X)", -1, md)
    print(json.dumps(dict(dofs=int(mfu.nbdof()), solve=solve, total=time.time() - T0, error_nodes=nodal,
                          error=float(np.sqrt(e2 / n2)), cells=int(m.nbcvs()))))


if __name__ == "__main__":
    main()
