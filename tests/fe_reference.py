"""An independent assembly of the internal nodal forces f = K u of plane-strain
P2 (Tri6) and Q2 (Quad9) elements, isoparametric, from what the program writes
to HDF5 for a body (geometry, topology in XDMF node order, displacement, E, nu):

    f_a = sum_cells int sigma(grad u_h) . grad N_a dA,
    sigma = lambda tr(eps) I + 2 mu eps,  eps = (grad u_h + grad u_h^T) / 2.

At a free node f_a is zero at equilibrium, at a contact node it is the contact
force on the body there, at a Dirichlet node the reaction. The quadrature is
the program's (the 6-point degree-4 rule on triangles, 3 x 3 Gauss on
quadrilaterals, -<body>_quadrature_degree 4), so that on curved cells, where
no rule is exact, the two assemblies agree to round-off. internal_forces_rz is
the same for an axisymmetric body (the hoop term, 2 pi r dA)."""
import numpy as np


def _tri6_rule():
    a, b = 0.445948490915965, 0.091576213509771
    wa, wb = 0.223381589678011 / 2, 0.109951743655322 / 2
    pts = [(a, a), (1 - 2 * a, a), (a, 1 - 2 * a), (b, b), (1 - 2 * b, b), (b, 1 - 2 * b)]
    return np.array(pts), np.array([wa] * 3 + [wb] * 3)


def _tri6_dN(xi, eta):
    """Reference gradients; corners 0, 1, 2, then the edges (0,1), (1,2), (2,0)."""
    L = (1 - xi - eta, xi, eta)
    dL = np.array([[-1, -1], [1, 0], [0, 1]], float)
    d = np.zeros((6, 2))
    for i in range(3):
        d[i] = (4 * L[i] - 1) * dL[i]
    for k, (i, j) in enumerate(((0, 1), (1, 2), (2, 0))):
        d[3 + k] = 4 * (L[i] * dL[j] + L[j] * dL[i])
    return d


def _quad9_rule():
    g, w = np.polynomial.legendre.leggauss(3)
    return np.array([(x, y) for x in g for y in g]), np.array([wx * wy for wx in w for wy in w])


def _quad9_dN(xi, eta):
    """Reference gradients; corners (-1,-1), (1,-1), (1,1), (-1,1) in turn, then
    the edges between them, then the centre (index of each node in the 1D
    quadratic basis on -1, 0, 1)."""
    def l(t):
        return np.array([t * (t - 1) / 2, 1 - t * t, t * (t + 1) / 2])

    def dl(t):
        return np.array([t - 0.5, -2 * t, t + 0.5])
    ij = [(0, 0), (2, 0), (2, 2), (0, 2), (1, 0), (2, 1), (1, 2), (0, 1), (1, 1)]
    lx, ly, dx, dy = l(xi), l(eta), dl(xi), dl(eta)
    return np.array([[dx[i] * ly[j], lx[i] * dy[j]] for i, j in ij])


def _tri6_N(xi, eta):
    L = (1 - xi - eta, xi, eta)
    return np.array([L[i] * (2 * L[i] - 1) for i in range(3)] + [4 * L[i] * L[j] for i, j in ((0, 1), (1, 2), (2, 0))])


def _quad9_N(xi, eta):
    def l(t):
        return np.array([t * (t - 1) / 2, 1 - t * t, t * (t + 1) / 2])
    ij = [(0, 0), (2, 0), (2, 2), (0, 2), (1, 0), (2, 1), (1, 2), (0, 1), (1, 1)]
    lx, ly = l(xi), l(eta)
    return np.array([lx[i] * ly[j] for i, j in ij])


def internal_forces(X, topo, u, E, nu):
    """f[node] = K u (n x 2) for nodes X (n x 2), cells topo (Tri6 or Quad9)."""
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    tri = topo.shape[1] == 6
    pts, wts = _tri6_rule() if tri else _quad9_rule()
    f = np.zeros_like(u)
    xe, ue = X[topo], u[topo]                      # [cell, node, component]
    for (xi, eta), w in zip(pts, wts):
        D = _tri6_dN(xi, eta) if tri else _quad9_dN(xi, eta)
        J = np.einsum("cai,aj->cij", xe, D)        # dx_i / dxi_j
        det = np.linalg.det(J)
        G = np.einsum("aj,cji->cai", D, np.linalg.inv(J))
        gu = np.einsum("cai,caj->cij", ue, G)      # du_i / dx_j
        eps = 0.5 * (gu + gu.transpose(0, 2, 1))
        sig = 2 * mu * eps + lam * (eps[:, 0, 0] + eps[:, 1, 1])[:, None, None] * np.eye(2)
        np.add.at(f, topo, np.einsum("cij,caj->cai", sig, G) * (w * np.abs(det))[:, None, None])
    return f


def internal_forces_rz(X, topo, u, E, nu):
    """The same for an axisymmetric body (x = r, y = z, the whole circle's
    forces): f_a = sum_cells int (sigma_rr dN_a/dr + sigma_rz dN_a/dz
    + sigma_hoop N_a / r, sigma_rz dN_a/dr + sigma_zz dN_a/dz) 2 pi r dA, with
    the hoop strain u_r / r at the quadrature points (all at r > 0). Also
    returns the hoop part of the radial column, int sigma_hoop N_a 2 pi dA,
    alone: at a node on the axis the rest of the column balances it but for
    the discretisation's error, which is the node's reaction."""
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    tri = topo.shape[1] == 6
    pts, wts = _tri6_rule() if tri else _quad9_rule()
    f, hoop = np.zeros_like(u), np.zeros(len(u))
    xe, ue = X[topo], u[topo]
    for (xi, eta), w in zip(pts, wts):
        D = _tri6_dN(xi, eta) if tri else _quad9_dN(xi, eta)
        N = _tri6_N(xi, eta) if tri else _quad9_N(xi, eta)
        J = np.einsum("cai,aj->cij", xe, D)
        det = np.linalg.det(J)
        G = np.einsum("aj,cji->cai", D, np.linalg.inv(J))
        r = xe[:, :, 0] @ N
        gu = np.einsum("cai,caj->cij", ue, G)
        eps = 0.5 * (gu + gu.transpose(0, 2, 1))
        eth = (ue[:, :, 0] @ N) / r
        tr = eps[:, 0, 0] + eps[:, 1, 1] + eth
        sig = 2 * mu * eps + lam * tr[:, None, None] * np.eye(2)
        sth = 2 * mu * eth + lam * tr
        dV = 2 * np.pi * r * w * np.abs(det)
        fa = np.einsum("cij,caj->cai", sig, G)
        h = (sth / r)[:, None] * N[None, :]
        fa[:, :, 0] += h
        np.add.at(f, topo, fa * dV[:, None, None])
        np.add.at(hoop, topo, h * dV[:, None])
    return f, hoop
