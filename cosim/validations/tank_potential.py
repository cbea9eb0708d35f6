"""The impulsive (incompressible) pressure in a 2-D tank with a vertical left side and a
right side inclined from the vertical, under a horizontal base acceleration: the exact
reference of the inclined-wall case for the tank the SPH runs, where Chwang's solution
(refdata ``inclined_dam_Cp_FEM_thiswork.csv``) is for a semi-infinite reservoir.

The problem (Sunara et al. 2021, §3.2, Chwang 1978 without the infinite reservoir):
water of depth H in the trapezoid 0 <= z <= H, 0 <= x <= L + z tan(beta), the tank
accelerating ``a0`` along +x, the water incompressible and inviscid, the motion small
(the free surface stays at z = H: the excitation is far above the sloshing frequencies).
The dynamic pressure p then solves

    laplace(p) = 0 in the water,  p = 0 on z = H,  dp/dn = -rho a0 n_x on the walls

(n the outward normal; the normal momentum balance rho a.n = -dp/dn at a rigid wall that
the water follows). With p = rho a0 H k_p, k_p depends on x/H, z/H, L/H and beta only.

Solved by linear finite elements on a mapped grid (each row of nodes spans the water's
width at its height; quads split into two triangles), Dirichlet rows eliminated, one sparse
solve. Accuracy (tests/test_tanks.py): the vertical tank (beta = 0) reproduces the exact
series of :func:`cosim.validations.sloshing.westergaard_series` to 9e-4 in k_p at 120
elements over the depth (largest at the free-surface corner; first order there), and with
a long reservoir (L = 12 H) the inclined face reproduces the refdata table of Chwang's
problem to 2e-4 at 60 elements (0.5 s). The 3 m tank's inclined face carries 0.009-0.012
less than Chwang's reservoir at the base.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.linalg import spsolve


def _mesh(length: float, depth: float, beta_deg: float, nz: int, nx: int | None):
    """Nodes (N, 2), triangles (M, 3) and ``nx`` of the trapezoid, rows j = 0..nz bottom to
    top, nx + 1 nodes a row (node j (nx + 1) + i); ``nx`` None: elements about square at
    mid-depth."""
    if not (length > 0 and depth > 0 and 0 <= beta_deg < 90):
        raise ValueError("length > 0, depth > 0 and 0 <= beta_deg < 90 are needed")
    nx = nx or int(math.ceil(nz * (length + 0.5 * depth * math.tan(math.radians(beta_deg))) / depth))
    tb = math.tan(math.radians(beta_deg))
    z = np.linspace(0.0, depth, nz + 1)
    s = np.linspace(0.0, 1.0, nx + 1)
    x = s[None, :] * (length + z[:, None] * tb)
    nodes = np.stack([x.ravel(), np.repeat(z, nx + 1)], axis=1)
    j, i = np.meshgrid(np.arange(nz), np.arange(nx), indexing="ij")
    a = (j * (nx + 1) + i).ravel()
    b, c, d = a + 1, a + nx + 2, a + nx + 1
    tri = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    return nodes, tri, nx


def _stiffness(nodes: np.ndarray, tri: np.ndarray):
    """P1 stiffness matrix (sparse CSR) of the Laplacian on the triangles ``tri`` of ``nodes``."""
    P = nodes[tri]                                                   # (M, 3, 2)
    e1, e2 = P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]
    area2 = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]                # 2 A (> 0: counter-clockwise)
    # gradients of the three hat functions: (y_j - y_k, x_k - x_j) / 2A over the cyclic (i, j, k)
    gx = np.stack([P[:, 1, 1] - P[:, 2, 1], P[:, 2, 1] - P[:, 0, 1], P[:, 0, 1] - P[:, 1, 1]], 1) / area2[:, None]
    gz = np.stack([P[:, 2, 0] - P[:, 1, 0], P[:, 0, 0] - P[:, 2, 0], P[:, 1, 0] - P[:, 0, 0]], 1) / area2[:, None]
    Ke = 0.5 * area2[:, None, None] * (gx[:, :, None] * gx[:, None, :] + gz[:, :, None] * gz[:, None, :])
    rows = np.repeat(tri, 3, axis=1).ravel()
    cols = np.tile(tri, (1, 3)).ravel()
    n = len(nodes)
    return coo_matrix((Ke.ravel(), (rows, cols)), shape=(n, n)).tocsr()


def impulsive_pressure(length: float, depth: float, beta_deg: float, nz: int = 120, nx: int | None = None):
    """k_p = p / (rho a0 H) at the nodes of the tank's mesh for a base acceleration a0 along
    +x. Returns (nodes (N, 2) [m], k_p (N,), nz, nx). ``length`` [m]: the bottom; ``depth``
    [m]: H; ``beta_deg``: the right side's angle from the vertical, leaning outwards."""
    nodes, tri, nx = _mesh(length, depth, beta_deg, nz, nx)
    K = _stiffness(nodes, tri)
    n = len(nodes)
    # Neumann loads, dp/dn = -n_x (rho a0 = 1, H = 1 below: k_p = p / H): the left side
    # (n = -x: +1) and the inclined side (n = (cos b, -sin b): -cos b); the bottom has n_x = 0
    f = np.zeros(n)
    cb = math.cos(math.radians(beta_deg))
    for col, g in ((0, 1.0), (nx, -cb)):
        ids = np.arange(nz + 1) * (nx + 1) + col
        seg = np.hypot(*np.diff(nodes[ids], axis=0).T)
        np.add.at(f, ids[:-1], 0.5 * g * seg)
        np.add.at(f, ids[1:], 0.5 * g * seg)
    free = np.arange(n) < nz * (nx + 1)                              # the top row is p = 0
    p = np.zeros(n)
    p[free] = spsolve(K[free][:, free].tocsc(), f[free])
    return nodes, p / depth, nz, nx


def wall_profiles(length: float, depth: float, beta_deg: float, nz: int = 120) -> dict:
    """k_p along both sides, bottom to top: ``z`` (nz + 1,) [m], ``left`` and ``right`` (the
    right side's suction taken positive: k_p on the wall the tank accelerates towards the
    water, the convention of Sunara et al. 2021, Eq. 18)."""
    nodes, kp, nz, nx = impulsive_pressure(length, depth, beta_deg, nz)
    rows = np.arange(nz + 1) * (nx + 1)
    return {"z": nodes[rows, 1], "left": kp[rows], "right": -kp[rows + nx]}


def sloshing_modes(length: float, depth: float, beta_deg: float, n_modes: int = 30, nz: int = 40,
                   nx: int | None = None) -> dict:
    """Linear sloshing modes of the same tank (the relative velocity potential: Laplace's
    equation, no flow through the walls, phi_z = (w^2 / g) phi on the still surface z = H):
    P1 FEM on the mesh of :func:`impulsive_pressure`, the interior condensed onto the
    surface nodes (K_ss - K_si K_ii^-1 K_is) phi_s = lambda M_s phi_s with the surface's
    consistent mass matrix M_s, w_n^2 = g lambda_n; the constant mode (lambda = 0) left out.

    Returns ``nodes`` (N, 2) [m], ``nz``, ``nx``, ``lam`` (n_modes,) [1/m] ascending, and
    ``phi`` (n_modes, N): each mode at every node, scaled so that its surface values S
    satisfy S^T M_s S = 1 [m]. The vertical tank (beta = 0) gives lambda = k tanh(k H),
    k = n pi / L (tests/test_forced_sloshing.py)."""
    from scipy.linalg import cho_solve_banded, cholesky_banded, eigh

    nodes, tri, nx = _mesh(length, depth, beta_deg, nz, nx)
    K = _stiffness(nodes, tri).tocsc()
    n = len(nodes)
    top = np.arange(nz * (nx + 1), n)
    inner = np.arange(nz * (nx + 1))
    Kii, Kis = K[inner][:, inner].tocoo(), K[inner][:, top].toarray()
    Kss = K[top][:, top].toarray()
    u = nx + 2                                                       # the mapped grid's bandwidth
    band = np.zeros((u + 1, inner.size))
    up = Kii.row <= Kii.col
    band[u + Kii.row[up] - Kii.col[up], Kii.col[up]] = Kii.data[up]
    X = cho_solve_banded((cholesky_banded(band), False), Kis)       # K_ii^-1 K_is (SPD, banded)
    S = Kss - Kis.T @ X
    S = 0.5 * (S + S.T)
    seg = np.diff(nodes[top, 0])
    M = np.zeros((top.size, top.size))
    i = np.arange(seg.size)
    M[i, i] += seg / 3
    M[i + 1, i + 1] += seg / 3
    M[i, i + 1] += seg / 6
    M[i + 1, i] += seg / 6
    lam, vec = eigh(S, M, subset_by_index=[1, n_modes])              # skips lambda_0 = 0
    phi = np.zeros((n_modes, n))
    phi[:, top] = vec.T
    phi[:, inner] = -(X @ vec).T
    return {"nodes": nodes, "nz": nz, "nx": nx, "lam": lam, "phi": phi, "surface_mass": M, "top": top}
