#!/usr/bin/python3
"""Cattaneo-Mindlin on the program's own cattaneo meshes, solved by GetFEM 5.4
(Debian's python3-getfem, an independent finite element code), to set beside
the program's stick zone and shear profile (scripts/friction_study.py).

The problem is meshes/cattaneo/cattaneo.opts: the disc (R = 1, centre (-1, 0),
Tri6) on the slab [0, 3] x [-3, 3] (Quad9), both E = 1000, nu = 0.3, plane
strain, P2 displacements; the slab's right edge (group push) held; the disc's
clamp arc moved rigidly by an unknown translation U (a global unknown, tied to
the arc by a multiplier) whose resultant is the given force: (P t, 0) in the
first stage, then (P, Q t), P, Q = 0.5 mu P and mu the scene's (P = 1.075,
a/R = 0.05). --scale S makes the contact S times as wide against the bodies:
P and Q times S^2, the contact edges hc and the graded zone's radius rc
times S (friction_study.cattaneo_args'; --scale 2 is the scene as it was
first, a/R = 0.1).
The meshes are made here as the program makes them (src/mesh/meshgen.c):
`gmsh -2 -v 2 -format msh22 -setnumber h <mesh_size> -setnumber <param> ...
<geo> -o <msh>` with the scene's -<body>_geo, -<body>_geo_params and
-<body>_mesh_size; the node counts are checked against the program's.

Two contact formulations, both converged (Newton, max_res 1e-9):

small_sliding: written here in GetFEM's weak form language (its generic
assembly), an integral Alart-Curnier augmented Lagrangian with two scalar
multipliers on the disc's contact arc: ln, the pressure, and lt, the disc's
shear traction along +y (the traction on the disc is (-ln, lt)). A point X
of the arc is paired with the slab's point (0, X_2) (linearised kinematics,
as Mindlin's theory: the slab's contact edge is x = 0, the normal +x); the
gap is g = -X_1 - u1_x + u2_x(0, X_2), the slip increment s = [u1_y - u2_y]
minus its value at the last accepted increment, and

    ln = max(0, ln - r g),   lt = proj_[-f b, f b](lt - r s),  b = max(0, ln - r g)

hold in the L2 sense on the arc (tested by the multipliers' shape
functions), r = E by default (r = 100 and 1e4 give the same answer). The
multiplier is P2 on the arc (its nodes are the program's slave nodes, its
weights the program's A_j) or P1 (the triangles' vertices only).

large_sliding: GetFEM's own add_integral_large_sliding_contact_brick_raytracing
(current configuration, as the program's mortar pairs), a vector multiplier
(P2) on the arc, the slip from the last accepted increment (alpha = 1,
w = its displacements); p and q are its traction decomposed on the slab's
current edge. It is started with the disc moved 0.01 towards the slab (from
rest the free disc flies past the rays' release distance).

Each is run with friction from the first increment and with a frictionless
normal stage (f = 0 for P, then mu for Q; the disc's y, free without
friction, is then held by a spring of stiffness 1 on U_y, whose force,
|U_y| < 1e-5, is recorded as U_normal_stage), 1 and 8 increments a stage.
GetFEM's built-in bricks for two meshes were tried first (FAILED below, the
JSON's "failed").

The figures are the program's definitions: p = ln and q = -lt (the shear
opposing Q, positive, as the program's node_shear) at the multiplier's
nodes, the nodal weight w_j = int_arc phi_j ds; s the arc coordinate
R (theta + pi/3) of the node's reference position; the pressure's centre
s_c = sum w p s / sum w p and a = 2 sqrt(sum w p (s - s_c)^2 / sum w p)
(a_moment, src/contact/hertz.c); Mindlin's q drawn with that a,
p0 = 2 P / (pi a), x = s - s_c, c_M = a sqrt(1 - Q/(mu P)); shear_l2 the
relative L2 distance sqrt(sum w (q - q_M)^2 / sum w q_M^2) over the nodes
with |x| < a or in contact (p > 1e-3 max p: the integral formulation leaves
multiplier values of 1e-3 of max p or less outside the zone). A node sticks
where p > 1e-3 max p and |q| < mu p (1 - 0.01): slipping nodes meet
|q| = mu p to within the "slip_ratio_spread" recorded (0.7 % or less: the
conditions hold in the L2 sense), stuck ones below (the largest ratio is
recorded as stuck_ratio_max, and c/a for other margins as
c_over_a_error_pct_by_margin). The stick zone's
ends are carried past the outermost stuck nodes as the program does
(FrictionStickEnd in src/contact/friction.c: (1 - |q|/(mu p))^2 extrapolated
linearly to zero from the last two stuck nodes, kept before the next node);
"c_nodes" is half the distance between the outermost stuck nodes.

What it found with the contact twice as wide (bench/friction/getfem.json,
--scale 2): the pressure is the program's to 0.7-0.8 % (L2 over the same
nodes); the shear left by a frictional
normal stage depends on the contact kinematics (the linearised pairing,
GetFEM's rays and the program's mortar pairs give different shapes, of
different signs near the zone's ends), and it
dominates the distance from Mindlin's curve when friction acts from the
first increment; with a frictionless normal stage both GetFEM formulations
come within 2.5-3.9 % of Mindlin's shear and -0.55 to -1.4 % of his c/a.
On the scene's own meshes (bench/friction/getfem-scene.json) the P2
multiplier alternates from node to node (its pressure 4.5 % from Hertz's
in L2, the program's 0.44 %; with r from 100 to 1e5 alike), and the large
sliding brick's slipping nodes meet |q| = mu p only to 3 %, so that its
c/a depends on the stick rule's margin.

Run from the repository root (about 1 min each on one core):

    /usr/bin/python3 scripts/getfem_cattaneo.py --scale 2 -o bench/friction/getfem.json
    /usr/bin/python3 scripts/getfem_cattaneo.py -o bench/friction/getfem-scene.json

Options: --mesh-dir (where the .msh files go, default build/getfem_meshes),
--r, --only NAME (one variant), --scale S, --scene OPTS (another scene of the
same layout: bodies disc and slab, groups contact, clamp and push, pair
interface), --plan friction_from_start_P2 (the P2 multipliers with friction
from the first increment alone). The disc on a slab as users write it
(a/R = 0.1, the slab 20 a thick, a/hc = 12; tests/test_friction_similar.py):

    /usr/bin/python3 scripts/getfem_cattaneo.py --scene tests/meshes/friction-similar.opts \
        --plan friction_from_start_P2 --mesh-dir build/getfem_similar -o bench/friction/getfem-similar.json
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import time

import numpy as np

from contactrun import options_file

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "meshes", "cattaneo", "cattaneo.opts")


def geo_param(opts, body, name):
    """One of the scene's -<body>_geo_params."""
    return float(dict(kv.split("=") for kv in opts[body + "_geo_params"].split(","))[name])




def set_scene(path):
    """The scene's materials (both bodies alike), friction, forces (the last
    stage's clamp force P, Q) and disc geometry, from its options file."""
    global SCENE, OPTS, E, NU, MU_F, P, Q, LAM, MU, R_DISC, XC, YC, THETA0
    SCENE, OPTS = path, options_file(path)
    E, NU, MU_F = float(OPTS["disc_E"]), float(OPTS["disc_nu"]), float(OPTS["contact_interface_friction"])
    P, Q = (float(v) for v in OPTS["disc_bc_clamp_values"].split(",")[-2:])
    LAM, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
    R_DISC, XC, YC = (geo_param(OPTS, "disc", k) for k in ("R", "xc", "yc"))
    # where the disc's contact arc starts (the geometry's xcontact): s = R (theta - THETA0)
    THETA0 = -math.acos((geo_param(OPTS, "disc", "xcontact") - XC) / R_DISC)


set_scene(SCENE)
EPS_Y = 1.0                    # without friction the disc's y is free: a y spring in a frictionless stage (its force |U_y|, recorded)
RELEASE = 0.05                 # the large sliding brick's release distance (the contact zone's gaps are below 0.006)
EPS = 1e-4                     # a soft spring on U (force 1e-6 of P at the answer): the disc is free until it touches
STICK_MARGIN = 0.01            # a node sticks where |q| < mu p (1 - STICK_MARGIN)
CONTACT_FLOOR = 1e-3           # in contact: p > CONTACT_FLOOR max p

FAILED = [
    dict(name="builtin_integral_nonmatching",
         settings="Model.add_integral_contact_between_nonmatching_meshes_brick (Alart-Curnier, option 1, 3, 4; "
                  "multiplier on the disc's arc P2 (earlier attempt) and P1; r 1e3 to 1e5; alpha = 1, wt = last increment)",
         result="converges in 3 + 1 Newton iterations but the multiplier is not the traction: with P1 and r = 1e4, "
                "1 increment a stage, it is nonzero over 5 vertices only (|y| < 0.015, peaks -199 and -203 against "
                "Hertz's 27.4) and alternates in sign with decaying amplitude beyond; the stick zone and shear "
                "profile cannot be read from it (the earlier script's measure, a from the support and p0 = max p: "
                "c/a 1.0, shear L2 98 %)"),
    dict(name="builtin_penalized_nonmatching",
         settings="Model.add_penalized_contact_between_nonmatching_meshes_brick with friction (earlier attempt)",
         result="no convergence in 200 Newton iterations"),
    dict(name="builtin_nodal_nonmatching",
         settings="Model.add_nodal_contact_between_nonmatching_meshes_brick(mim1, mim2, 'u1', 'u2', 'ln', 'lt', 'r', 'f', 1, 1[, 1, 0, 1])",
         result="refused by the Python interface of Debian's GetFEM 5.4: '(Getfem::InterfaceError) -- Argument 11 must be "
                "a string' for every form of the frictional call (regions as ints or lists, with or without the "
                "optional arguments); its friction has no previous-state argument (dummy_wt in its C++), so its slip "
                "would be total, not incremental, anyway"),
    dict(name="large_sliding frictionless normal stage, the disc's y held by the 1e-4 spring only",
         settings="add_integral_large_sliding_contact_brick_raytracing with f = 0 in the normal stage",
         result="8 increments: no convergence in 100 Newton iterations in every normal increment; 1 increment: a "
                "wrong contact zone (a = 0.073); cured by the y spring EPS_Y during the frictionless stage"),
]
NOTES = [
    "P1 multiplier (vertices only, twice the node spacing): the shear alternates near the stick zone's ends and an "
    "edge node's |q|/(mu p) can fall below 1 - margin, so its c moves with the margin (see c_over_a_error_pct_by_margin); "
    "the P2 variants are the comparison on the program's own nodes.",
    "The stick rule's margin: slipping nodes meet |q| = mu p within slip_ratio_spread (up to 0.7 % in the integral "
    "formulations), so margins of 0.2 % misclassify them; 0.5 to 2 % give the same c except where a stuck node sits "
    "near the bound (stuck_ratio_max).",
    "The shear left by the normal stage (normal_stage_shear_pct, over Mindlin's final shear's norm) is what separates "
    "friction-from-the-start from a frictionless normal stage: for elastically similar half-spaces it would be 0; "
    "here the finite disc stretches along the arc relative to the slab (normal_stage_tangential_stretch, "
    "d(u1_y - u2_y)/dy = 1.8e-3 without friction, linearised) and the current-configuration kinematics add terms "
    "of the gap times the surfaces' slopes.",
]


def make_mesh(body, opts, mesh_dir, scale):
    """The body's .msh as the program makes it (src/mesh/meshgen.c's Gmsh command), the
    contact edges hc and the graded zone's radius rc scaled by scale."""
    geo = os.path.normpath(os.path.join(os.path.dirname(SCENE), opts[body + "_geo"]))
    h = opts[body + "_mesh_size"]
    args = ["gmsh", "-2", "-v", "2", "-format", "msh22", "-setnumber", "h", h]
    for param in opts[body + "_geo_params"].split(","):
        name, value = param.split("=")
        if name in ("hc", "rc") and scale != 1.0:
            value = repr(float(value) * scale)
        args += ["-setnumber", name, value]
    msh = os.path.join(mesh_dir, body + ".msh")
    os.makedirs(mesh_dir, exist_ok=True)
    subprocess.run(args + [geo, "-o", msh], check=True, stdout=subprocess.DEVNULL)
    return msh, " ".join(args + [geo, "-o", msh])


def msh_info(msh):
    """Node count, element types and {physical name: tag} of a Gmsh 2.2 file."""
    with open(msh) as f:
        text = f.read()
    names = {m.group(3): int(m.group(2)) for m in re.finditer(r'^(\d+) (\d+) "([^"]+)"$', text, re.M)}
    nodes = int(text.split("$Nodes\n", 1)[1].split("\n", 1)[0])
    elems = text.split("$Elements\n", 1)[1].split("$EndElements", 1)[0].split("\n")[1:-1]
    types = sorted({int(e.split()[1]) for e in elems})
    return nodes, types, names


def solve(gf, disc, slab, steps, r, kmul, normal_friction, formulation):
    """One load path; the multipliers at their nodes and the solver's figures. formulation: "small_sliding"
    (the weak form above) or "large_sliding" (GetFEM's raytracing large sliding brick)."""
    m1, m2 = gf.Mesh("import", "gmsh", disc), gf.Mesh("import", "gmsh", slab)
    r1, r2 = msh_info(disc)[2], msh_info(slab)[2]
    CONTACT1, CLAMP, CONTACT2, PUSH = r1["contact"], r1["clamp"], r2["contact"], r2["push"]
    mfu1, mfu2 = gf.MeshFem(m1, 2), gf.MeshFem(m2, 2)
    mfu1.set_classical_fem(2)
    mfu2.set_classical_fem(2)
    mim1 = gf.MeshIm(m1, gf.Integ("IM_TRIANGLE(6)"))
    mim2 = gf.MeshIm(m2, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,6)"))
    md = gf.Model("real")
    md.add_fem_variable("u1", mfu1)
    md.add_fem_variable("u2", mfu2)
    md.add_initialized_data("lambda", [LAM])
    md.add_initialized_data("mu", [MU])
    md.add_isotropic_linearized_elasticity_brick(mim1, "u1", "lambda", "mu")
    md.add_isotropic_linearized_elasticity_brick(mim2, "u2", "lambda", "mu")
    md.add_Dirichlet_condition_with_multipliers(mim2, "u2", mfu2, PUSH)
    # the clamp arc moves rigidly by U, whose force is F
    mfc = gf.MeshFem(m1, 2)
    mfc.set_classical_fem(2)
    md.add_filtered_fem_variable("lc", mfc, CLAMP)
    md.add_variable("U", 2)
    md.add_linear_term(mim1, "lc.(Test_u1 - Test_U) + (u1 - U).Test_lc", CLAMP)
    Lc = gf.asm_generic(mim1, 0, "1", CLAMP)
    md.add_initialized_data("F", [0.0, 0.0])
    md.add_initialized_data("Lc", [Lc])
    md.add_initialized_data("eps", [EPS, EPS])
    md.add_source_term(mim1, "F.Test_U / Lc", CLAMP)
    md.add_linear_term(mim1, "(eps(1) * U(1) * Test_U(1) + eps(2) * U(2) * Test_U(2)) / Lc", CLAMP)
    md.add_initialized_data("r", [r])
    md.add_initialized_data("f", [MU_F])
    md.add_initialized_fem_data("w1", mfu1, np.zeros(mfu1.nbdof()))   # the displacements of the last accepted increment
    md.add_initialized_fem_data("w2", mfu2, np.zeros(mfu2.nbdof()))
    mfl = gf.MeshFem(m1, 1)     # the multipliers' scalar space on the arc (their nodes and weights)
    mfl.set_classical_fem(kmul)
    if formulation == "small_sliding":
        md.add_filtered_fem_variable("ln", mfl, CONTACT1)
        md.add_filtered_fem_variable("lt", mfl, CONTACT1)
        md.add_interpolate_transformation_from_expression("Pair", m1, m2, "[0; X(2)]")
        gap = "(-X(1) - u1(1) + Interpolate(u2,Pair)(1))"
        slip = "((u1(2) - Interpolate(u2,Pair)(2)) - (w1(2) - Interpolate(w2,Pair)(2)))"
        bound = "(f*pos_part(ln - r*%s))" % gap
        trial = "(lt - r*%s)" % slip
        proj = "(%s - pos_part(%s - %s) + pos_part(-%s - %s))" % (trial, trial, bound, trial, bound)
        # the virtual work of the traction (-ln, lt) on the disc and its opposite on the slab (left-hand side: minus it)
        md.add_nonlinear_term(mim1, "(ln*Test_u1(1) - lt*Test_u1(2))"
                                    " - (ln*Interpolate(Test_u2,Pair)(1) - lt*Interpolate(Test_u2,Pair)(2))", CONTACT1)
        md.add_nonlinear_term(mim1, "(ln - pos_part(ln - r*%s))*Test_ln/r + (lt - %s)*Test_lt/r" % (gap, proj), CONTACT1)
    else:
        # GetFEM's own large sliding brick: rays from the disc's arc to the slab's edge in the current
        # configuration, the multiplier lam the traction on the disc (a vector), slip (u - w) of both surfaces
        mfv = gf.MeshFem(m1, 2)
        mfv.set_classical_fem(kmul)
        md.add_filtered_fem_variable("lam", mfv, CONTACT1)
        md.add_initialized_data("alpha", [1.0])
        ib = md.add_integral_large_sliding_contact_brick_raytracing("r", RELEASE, "f", "alpha", 0)
        md.add_master_contact_boundary_to_large_sliding_contact_brick(ib, mim2, CONTACT2, "u2", "w2")
        md.add_slave_contact_boundary_to_large_sliding_contact_brick(ib, mim1, CONTACT1, "u1", "lam", "w1")
        # a start within the rays' release distance (from rest the disc, free until it touches, would fly off)
        u0 = np.zeros(mfu1.nbdof())
        u0[0::2] = 0.01
        md.set_variable("u1", u0)
        md.set_variable("U", [0.01, 0.0])
    dofs = mfl.basic_dof_on_region(CONTACT1)      # sorted: the filtered variables' order
    X = mfl.basic_dof_nodes()[:, dofs]

    def traction():
        """p and q at the nodes: (ln, -lt); for the large sliding brick the traction on the disc decomposed
        on the slab's current edge (its slope du2_x/dy at (0, Y) by central differences)."""
        if formulation == "small_sliding":
            return np.array(md.variable("ln")), -np.array(md.variable("lt"))
        lam, u2, h = md.variable("lam"), md.variable("u2"), 1e-4
        k = (gf.compute_interpolate_on(mfu2, u2, np.vstack([0 * X[0], X[1] + h]))[0]
             - gf.compute_interpolate_on(mfu2, u2, np.vstack([0 * X[0], X[1] - h]))[0]) / (2 * h)
        n = np.sqrt(1 + k * k)
        lx, ly = lam[0::2], lam[1::2]
        return (-lx + k * ly) / n, -(k * lx + ly) / n

    path = [(P * k / steps, 0.0, MU_F if normal_friction else 0.0) for k in range(1, steps + 1)] \
        + [(P, Q * k / steps, MU_F) for k in range(1, steps + 1)]
    t0, its, converged, q_normal, du_normal = time.time(), [], True, None, None
    for k, (Fx, Fy, fr) in enumerate(path):
        md.set_variable("F", [Fx, Fy])
        md.set_variable("f", [fr])
        md.set_variable("eps", [EPS, EPS if fr > 0 else EPS_Y])
        n = int(np.ravel(md.solve("max_res", 1e-9, "max_iter", 100, "lsearch", "default"))[0])
        its.append(n)
        converged = converged and n < 100
        md.set_variable("w1", md.variable("u1"))
        md.set_variable("w2", md.variable("u2"))
        if k == steps - 1:
            q_normal = traction()[1]     # the shear left by the normal stage
            U_normal = [float(v) for v in md.variable("U")]
            du_normal = gf.compute_interpolate_on(mfu1, md.variable("u1"), X)[1] \
                - gf.compute_interpolate_on(mfu2, md.variable("u2"), np.vstack([0 * X[0], X[1]]))[1]
    seconds = time.time() - t0
    w = gf.asm_generic(mim1, 1, "Test_t", CONTACT1, "t", 1, mfl, np.zeros(mfl.nbdof()))[dofs]
    p, q = traction()
    return dict(X=X, w=w, p=p, q=q, q_normal=q_normal, du_normal=du_normal, iterations=its,
                converged=converged, seconds=seconds, U=[float(v) for v in md.variable("U")], U_normal=U_normal)


def stick_end(s, p, q, i, j, o):
    """FrictionStickEnd (src/contact/friction.c): the stick zone's end past its outermost stuck node i
    (j the next inward, o the next outward, -1 where none)."""
    so = s[o] if o >= 0 else s[i]
    if j >= 0 and p[i] > 0 and p[j] > 0:
        yi, yj = (1 - abs(q[i]) / (MU_F * p[i])) ** 2, (1 - abs(q[j]) / (MU_F * p[j])) ** 2
        if yj > yi:
            e = s[i] + (s[i] - s[j]) * yi / (yj - yi)
            return min(e, so) if s[i] < so else max(e, so)
    return 0.5 * (s[i] + so)


def stick_zone(x, p, q, on, ratio, margin, a, c_m):
    """The stick zone's figures with the rule |q| < mu p (1 - margin) (x from the pressure's centre, in arc order)."""
    stick = on & (ratio < 1 - margin)
    out = dict(stuck_nodes=int(stick.sum()),
               slip_ratio_spread=float(np.max(np.abs(ratio[on & ~stick] - 1))) if (on & ~stick).any() else None,
               stuck_ratio_max=float(ratio[stick].max()) if stick.any() else None)
    if stick.any():
        idx = np.flatnonzero(stick)
        lo, hi, n = idx[0], idx[-1], len(x)
        left = stick_end(x, p, q, lo, lo + 1 if lo < hi else -1, lo - 1 if lo > 0 else -1)
        right = stick_end(x, p, q, hi, hi - 1 if hi > lo else -1, hi + 1 if hi + 1 < n else -1)
        c = 0.5 * (right - left)
        out.update(c=c, c_over_a=c / a, c_over_a_error_pct=100 * (c / c_m - 1), stick_zone=[float(left), float(right)],
                   c_nodes=0.5 * (x[hi] - x[lo]), c_nodes_over_a=0.5 * (x[hi] - x[lo]) / a)
    return out


def analyse(res):
    """The program's figures (friction_study.py's shear_l2, hertz.c's a_moment, friction.c's stick half-width)."""
    X, w, p, q = res["X"], res["w"], res["p"], res["q"]
    s = R_DISC * (np.arctan2(X[1] - YC, X[0] - XC) - THETA0)
    o = np.argsort(s)
    s, w, p, q, qn, du = s[o], w[o], p[o], q[o], res["q_normal"][o], res["du_normal"][o]
    sc = np.sum(w * p * s) / np.sum(w * p)
    a = 2 * math.sqrt(np.sum(w * p * (s - sc) ** 2) / np.sum(w * p))
    p0 = 2 * P / (math.pi * a)
    c_m = a * math.sqrt(1 - Q / (MU_F * P))
    x = s - sc
    qm = MU_F * p0 * (np.sqrt(np.clip(1 - x ** 2 / a ** 2, 0, None))
                      - np.where(np.abs(x) < c_m, c_m / a * np.sqrt(np.clip(1 - x ** 2 / c_m ** 2, 0, None)), 0))
    on = p > CONTACT_FLOOR * p.max()
    m = (np.abs(x) < a) | on
    l2 = math.sqrt(np.sum(w[m] * (q[m] - qm[m]) ** 2) / np.sum(w[m] * qm[m] ** 2))
    ratio = np.where(on, np.abs(q) / (MU_F * np.where(on, p, 1)), 0)
    out = dict(P_met=float(np.sum(w * p)), Q_met=float(np.sum(w * q)), a=a, centre=float(sc), p0=p0,
               pmax=float(p.max()), contact_nodes=int(on.sum()),
               shear_l2=l2, shear_l2_pct=100 * l2, mindlin_c_over_a=c_m / a,
               normal_stage_shear_pct=100 * math.sqrt(np.sum(w[m] * qn[m] ** 2) / np.sum(w[m] * qm[m] ** 2)),
               normal_stage_tangential_stretch=float(np.sum(w[on] * x[on] * du[on]) / np.sum(w[on] * x[on] ** 2)))
    out.update(stick_zone(s - sc, p, q, on, ratio, STICK_MARGIN, a, c_m))
    out["c_over_a_error_pct_by_margin"] = {str(mg): stick_zone(s - sc, p, q, on, ratio, mg, a, c_m).get("c_over_a_error_pct")
                                           for mg in (0.002, 0.005, 0.01, 0.02, 0.05)}
    out["profile"] = dict(x=[round(float(v), 7) for v in x[m]], w=[round(float(v), 8) for v in w[m]],
                          p=[round(float(v), 5) for v in p[m]], q=[round(float(v), 5) for v in q[m]],
                          q_mindlin=[round(float(v), 5) for v in qm[m]], q_normal_stage=[round(float(v), 5) for v in qn[m]],
                          stuck=[int(v) for v in (on & (ratio < 1 - STICK_MARGIN))[m]])
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mesh-dir", default=os.path.join(ROOT, "build", "getfem_meshes"))
    ap.add_argument("--r", type=float, help="the augmentation parameter (default the scene's E)")
    ap.add_argument("--scene", help="another scene's options file of the same layout (bodies disc and slab, groups contact, "
                                    "clamp and push, pair interface), e.g. tests/meshes/friction-similar.opts")
    ap.add_argument("--plan", default="all", choices=("all", "friction_from_start_P2"),
                    help="the variants: all, or the P2 multipliers with friction from the start alone")
    ap.add_argument("--only")
    ap.add_argument("--scale", type=float, default=1.0,
                    help="the contact scale times as wide against the bodies: P and Q times scale^2, hc and rc times scale")
    ap.add_argument("-o", "--output")
    args = ap.parse_args()
    if args.scene:
        set_scene(os.path.abspath(args.scene))
    if args.r is None:
        args.r = E
    import getfem as gf
    gf.util_trace_level(0)
    gf.util_warning_level(0)
    global P, Q
    P, Q = P * args.scale**2, Q * args.scale**2
    opts = OPTS
    meshes, paths = {}, {}
    for body in ("disc", "slab"):
        msh, cmd = make_mesh(body, opts, args.mesh_dir, args.scale)
        nodes, types, _ = msh_info(msh)
        paths[body] = msh
        meshes[body] = dict(msh=os.path.relpath(msh, ROOT), gmsh=cmd.replace(ROOT + "/", ""), nodes=nodes,
                            gmsh_element_types=types)
    SETTINGS = {
        "small_sliding": "GetFEM's weak form language (generic assembly), written here: integral Alart-Curnier, "
                         "non-symmetric, the arc's point X paired with the slab's (0, X_2), normal +x, slip from "
                         "the last accepted increment",
        "large_sliding": "GetFEM's add_integral_large_sliding_contact_brick_raytracing (version 0, non-symmetric; "
                         f"release distance {RELEASE}; alpha = 1, w = the last accepted increment's displacements): "
                         "current configuration; p, q the traction on the disc along the slab's current normal and edge"}
    plan = [("small_sliding", 2, True), ("small_sliding", 2, False), ("small_sliding", 1, True),
            ("large_sliding", 2, True), ("large_sliding", 2, False)]
    variants = []
    if args.plan != "all":
        plan = [v for v in plan if v[1] == 2 and v[2]]
    for formulation, kmul, normal_friction in plan:
        for steps in (1, 8):
            name = f"{formulation}_P{kmul}_{'friction_from_start' if normal_friction else 'frictionless_normal_stage'}_{steps}"
            if args.only and args.only != name:
                continue
            res = solve(gf, paths["disc"], paths["slab"], steps, args.r, kmul, normal_friction, formulation)
            v = dict(name=name, steps_per_stage=steps, friction_in_normal_stage=normal_friction,
                     settings=dict(formulation=SETTINGS[formulation],
                                   multiplier=f"P{kmul} on the disc's contact arc",
                                   displacements="P2 (Tri6 disc, Quad9 slab), linear elasticity", r=args.r,
                                   newton="GetFEM Model.solve, max_res 1e-9, lsearch default, max_iter 100"),
                     iterations=res["iterations"], iterations_total=int(sum(res["iterations"])),
                     converged=res["converged"], seconds=round(res["seconds"], 2), U=res["U"],
                     U_normal_stage=res["U_normal"])
            v.update(analyse(res))
            variants.append(v)
            print(f"{name}: its {v['iterations']}, {v['seconds']} s, P {v['P_met']:.4f}, Q {v['Q_met']:.4f}, "
                  f"a {v['a']:.5f}, c/a {v.get('c_over_a', float('nan')):.4f} "
                  f"({v.get('c_over_a_error_pct', float('nan')):+.2f} %), shear L2 {v['shear_l2_pct']:.2f} %, "
                  f"normal stage's shear {v['normal_stage_shear_pct']:.2f} %", flush=True)
    out = dict(problem=f"{os.path.relpath(SCENE, ROOT)}: disc R = {R_DISC:g} on a slab, E = {E:g}, nu = {NU:g}, plane strain, "
                       f"P = {P:g} then Q = {Q:g} with P held, mu = {MU_F:g}"
                       + (f"; the contact {args.scale:g} times as wide (hc and rc times {args.scale:g})" if args.scale != 1.0 else ""),
               scale=args.scale,
               getfem=gf.__version__ if hasattr(gf, "__version__") else "5.4 (Debian python3-getfem)",
               command="/usr/bin/python3 scripts/getfem_cattaneo.py " + " ".join(sys.argv[1:]),
               meshes=meshes, mindlin_c_over_a=math.sqrt(1 - Q / (MU_F * P)),
               stick_rule=f"p > {CONTACT_FLOOR} max p and |q| < mu p (1 - {STICK_MARGIN}); ends as friction.c's FrictionStickEnd",
               variants=variants, failed=FAILED, notes=NOTES)
    if args.output:
        with open(args.output, "w") as f:
            json.dump(out, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
