"""Density re-initialisation by a first-order moving-least-squares (MLS) interpolation,
001_14936b82710365b2.txt Eq. 9-12 (also used by 003_7c74773681ee080c.txt; Colagrossi &
Landrini 2003, Dilts 1999):

    rho_a^new = sum_b m_b W^MLS_ab,
    W^MLS_ab  = beta(r_a) . [1, r_a - r_b] W_ab,        (Eq. 10)
    beta(r_a) = A^-1 [1, 0, 0, 0]^T,  A = sum_b W_ab A~_ab V_b,   V_b = m_b / rho_b  (Eq. 11)

with ``A~_ab`` the moment matrix of ``[1, x_ab, y_ab, z_ab]`` (Eq. 12; 3x3 in 2-D, 4x4 in
3-D). Eq. 10 as printed reads ``beta . (r_a - r_b) W_ab``, which drops the constant entry
of the basis: with a four-component beta and the 4x4 matrix of Eq. 12 the basis is
``[1, r_a - r_b]`` (Dilts 1999), which is what is implemented.

Since ``A`` is symmetric, ``rho_a^new = e_1 . A^-1 s`` with ``s = sum_b m_b W_ab [1, r_ab]``:
one pass over the neighbours builds ``A`` and ``s``, and one small linear solve per
particle gives the new density. The interpolation reproduces a density field that is
linear in space exactly (first-order consistency), also where the support is truncated
(free surface, walls) as long as ``A`` is invertible.

Choices (documented because the papers leave them open):

* Neighbours are fluid and boundary particles (as DualSPHysics does): the dynamic
  boundary particles carry a density from the same continuity equation, so near a wall the
  support is complete and the interpolation does not extrapolate. Only fluid densities are
  replaced; boundary densities keep following their continuity equation.
* Where ``A`` is ill-conditioned (a splash particle, a thin jet: the neighbours do not span
  the plane/space) the linear fit would extrapolate wildly; there the zeroth-order Shepard
  filter ``rho_a = sum_b m_b W_ab / sum_b V_b W_ab`` is used instead. Criterion: the
  determinant of ``A`` scaled to unit diagonal (1 for a symmetric full support, 0 for
  neighbours on a line) below ``MIN_SCALED_DET`` = 0.01. On a lattice (Wendland, h = sqrt(2) dx) it is 1 inside, 0.70 at
  a flat free surface (2-D and 3-D), 0.49 at a 2-D corner and 0.35 at a 3-D corner, and 0
  for a one-particle-wide jet: surfaces and corners keep the linear correction (which is
  what keeps the hydrostatic density gradient there), degenerate supports fall back.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from fluid.kernels import w_value
from fluid.neighbours import cell_coords, row_range

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")

#: below this determinant of the unit-diagonal moment matrix the Shepard filter is used [-]
MIN_SCALED_DET = 0.01


@njit(**_OPTS)
def _solve_first(M, n):
    """First component of the solution of the n x n system ``M[:, :n] x = M[:, n]``
    (Gaussian elimination with partial pivoting, in place)."""
    for c in range(n):
        p = c
        for r in range(c + 1, n):
            if abs(M[r, c]) > abs(M[p, c]):
                p = r
        if p != c:
            for k in range(n + 1):
                t = M[c, k]
                M[c, k] = M[p, k]
                M[p, k] = t
        piv = M[c, c]
        for r in range(c + 1, n):
            f = M[r, c] / piv
            for k in range(c, n + 1):
                M[r, k] -= f * M[c, k]
    x = np.zeros(n)
    for r in range(n - 1, -1, -1):
        s = M[r, n]
        for k in range(r + 1, n):
            s -= M[r, k] * x[k]
        x[r] = s / M[r, r]
    return x[0]


@njit(**_OPTS)
def _scaled_det(M, n):
    """Determinant of the n x n block of ``M`` scaled to unit diagonal (a copy is reduced)."""
    A = np.empty((n, n))
    for i in range(n):
        for j in range(n):
            A[i, j] = M[i, j] / math.sqrt(M[i, i] * M[j, j])
    det = 1.0
    for c in range(n):
        p = c
        for r in range(c + 1, n):
            if abs(A[r, c]) > abs(A[p, c]):
                p = r
        if A[p, c] == 0.0:
            return 0.0
        if p != c:
            det = -det
            for k in range(n):
                t = A[c, k]
                A[c, k] = A[p, k]
                A[p, k] = t
        det *= A[c, c]
        for r in range(c + 1, n):
            f = A[r, c] / A[c, c]
            for k in range(c, n):
                A[r, k] -= f * A[c, k]
    return det


@njit(parallel=True, **_OPTS)
def mls_density(pos, rho, mass, kind, start, lo, inv_cell, nx, ny, nz, reach, kernel, ad, h,
                min_det, out, used_mls):
    """MLS densities (Eq. 9-12) of the fluid particles into ``out`` (boundary particles:
    their own density). Particles sorted by cell (``start`` from
    :func:`fluid.neighbours.sort_by_cell`, cells >= 2h / reach); ``lo`` as the grid's.
    ``used_mls[a]`` is 1 where the linear correction was applied, 0 where the Shepard filter
    was (ill-conditioned moment matrix) or for boundary particles."""
    n, dim = pos.shape
    three = dim == 3
    zc = dim - 1
    dys = 2 * reach + 1 if three else 1
    nb = dim + 1  # basis [1, x, (y,) z]
    ih = 1.0 / h
    R2 = 4.0 * h * h
    for a in prange(n):
        if kind[a] != 0:
            out[a] = rho[a]
            used_mls[a] = 0
            continue
        xa = pos[a, 0]
        za = pos[a, zc]
        ya = pos[a, 1] if three else 0.0
        cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, three, nx, ny, nz)
        M = np.zeros((nb, nb + 1))  # [A | s], coordinates in units of h for conditioning
        d = np.zeros(nb)
        for dz in range(-reach, reach + 1):
            for k in range(dys):
                dy = k - reach if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, reach)
                for b in range(j0, j1):
                    rx = xa - pos[b, 0]
                    rz = za - pos[b, zc]
                    ry = ya - pos[b, 1] if three else 0.0
                    r2 = rx * rx + ry * ry + rz * rz
                    if r2 >= R2:
                        continue
                    w = w_value(kernel, math.sqrt(r2) * ih, ad)
                    mw = mass[b] * w
                    vw = mw / rho[b]
                    d[0] = 1.0
                    d[1] = rx * ih
                    if three:
                        d[2] = ry * ih
                        d[3] = rz * ih
                    else:
                        d[2] = rz * ih
                    for i in range(nb):
                        for j in range(i, nb):
                            M[i, j] += vw * d[i] * d[j]
                        M[i, nb] += mw * d[i]
        for i in range(nb):
            for j in range(i):
                M[i, j] = M[j, i]
        shepard = M[0, nb] / M[0, 0]
        ok = True
        for i in range(1, nb):
            if not M[i, i] > 0.0:
                ok = False
        if ok and _scaled_det(M, nb) > min_det:
            out[a] = _solve_first(M, nb)
            used_mls[a] = 1
        else:
            out[a] = shepard
            used_mls[a] = 0


def reinitialise(pos, rho, mass, kind, start, grid, kernel: int, ad: float, h: float,
                 min_det: float = MIN_SCALED_DET):
    """New densities [kg/m^3] (N,) of particles sorted by cell on ``grid`` (see
    :func:`mls_density`; ``kernel`` a :mod:`fluid.kernels` id, ``ad`` [1/m^dim] its
    normalisation, ``h`` [m] the smoothing length), and the (N,) 0/1 flags where the
    linear correction was applied."""
    n, dim = pos.shape
    out = np.empty(n)
    used = np.empty(n, np.int8)
    nx, ny, nz = grid.shape
    mls_density(pos, rho, mass, kind, start, grid.lo, 1.0 / grid.cell, nx, ny, nz, grid.reach,
                kernel, ad, h, min_det, out, used)
    return out, used
