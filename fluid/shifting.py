"""Particle shifting: fluid particles moved a little down their concentration gradient each
step, so that a flow's particles keep a near-uniform arrangement (``FluidConfig(shifting=
"fickian")``).

Fickian shifting (Lind et al. 2012, J. Comput. Phys. 231: 1499, Eq. 21-24): particle a
moves by ``delta r_a = -D grad C_a`` with ``grad C_a = sum_b V_b (1 + R (W_ab / W(dx))^4)
grad_a W_ab`` (the tensile term of Monaghan 2000, R = 0.2) over its fluid neighbours, and
``D = A h |v_a| dt`` (Skillen et al. 2013, Comput. Methods Appl. Mech. Eng. 265: 163, Eq.
13; ``A`` = ``shifting_coef``, 1 ... 6 in their tests, 2 in DualSPHysics): the shift per unit
time does not depend on the step, and still water is not shifted. ``V_b = m_b / rho0``, the
volume of Lind et al.'s incompressible particles: with ``m_b / rho_b`` the hydrostatic
compression (``rho0 g d / B``, 1 % at the floor with c0 = 10 sqrt(g d)) makes a uniform
lattice's C grow upwards, and the shift packs the water down (measured: its level falls 1-2
mm more in 12 s in a 0.3 m flume). Near the free surface the shift has no component along
the surface's normal (Lind et al. 2012's free-surface treatment with alpha = 0): there the
concentration gradient is the support's cut, not disorder, and would push the particles out
through the surface. The surface region and its normal come from the renormalisation matrix
``B_a = sum_b V_b r_ba (x) grad_a W_ab``, the identity in a full support (Marrone et al.
2010, J. Comput. Phys. 229: 3652, as Sun et al. 2017, Comput. Methods Appl. Mech. Eng. 315:
25, use it): its smallest eigenvalue below :data:`LAMBDA_FULL` marks a cut support, and the
normal lies along ``B_a^-1 grad C_a`` (:func:`fluid.terms.fickian_shift`). A particle with
a wall or body particle within 2h is not shifted: measured in the flume, shifting beside the
slip floor costs a travelling wave 3.5 % of its kinetic energy in 8 s (the fluid's rows
slide over the wall's lattice and are shifted towards its hollows), without it 0.5 %.

Where in the step: after the position update of the step (the predictor-corrector's
corrector, Verlet's update), before the next step's neighbour sort and rates. So the rates
of the step, which move the fluid and exchange its loads with the bodies, are those of the
integrator alone, and the shift is a correction of where the integrator left the particles,
made once a step. The velocities and densities are not corrected for the shift (Lind et al.
2012 correct them by a first-order Taylor term): in the 10-row flume (A = 2, |v| = 0.1 m/s,
dt = 4e-4 s, h |grad C| = 0.005 in the bulk) a step shifts by 4e-7 m, a hydrostatic density
error of 1e-5 kg/m^3 and a wave velocity error of 2e-7 m/s; the density's hydrostatic Taylor
term (``rho/c^2 g . delta r``) changed its kinetic energy after 8 s by 2e-4. Mass and
momentum are unchanged by construction (positions only). The shift is computed with the
cell list of the step's last sort (positions half a step or one step older than those
shifted): a neighbour missed at the edge of the support carries a kernel weight of ~0.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange, uint64

from fluid import terms
from fluid.equations import PAD, dynamic_chunks
from fluid.kernels import alpha_d
from fluid.neighbours import XBINS, cell_coords, row_range_binned

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")
tp = terms.cpu

#: the smallest eigenvalue of ``B_a`` from which a support counts as full (no free surface
#: in it). On the square (cubic) lattice the rows under the free surface have 0.50, 0.70,
#: 0.943 (3-D 0.953), then 0.999 in the bulk at h = 2 dx (Wendland); 0.50, 0.87 (0.89), then
#: 0.992 at sqrt(2) dx; the cubic spline at 1.2 dx 0.50, 0.93, then 0.991. A bulk perturbed
#: by 0.05 dx scatters over 0.97-1.01 (1st-99th percentile), by 0.1 dx over 0.93-1.02: there
#: a particle below it is shifted along its gradient's normal plane only, which is little
LAMBDA_FULL = 0.97

#: rows of the packed table :func:`_pack` fills
X, Y, Z, VOL, BND = range(5)
N_ROWS = 5


@njit(parallel=True, **_OPTS)
def _pack(pos, mass, kind, irho0, P):
    """Positions (y = 0 in 2-D), the volume ``m / rho0`` of every fluid particle (0 for
    boundary particles) and 1 for boundary particles (0 for fluid) into the rows of ``P``
    (N_ROWS, N)."""
    three = pos.shape[1] == 3
    zc = pos.shape[1] - 1
    for i in prange(pos.shape[0]):
        f = 1.0 if kind[i] == 0 else 0.0
        P[X, i] = pos[i, 0]
        P[Y, i] = pos[i, 1] if three else 0.0
        P[Z, i] = pos[i, zc]
        P[VOL, i] = f * mass[i] * irho0
        P[BND, i] = 1.0 - f


def _make_loop(kernel: int, three: bool):
    """The shift loop of :func:`fickian_shift` compiled for one kernel and dimension."""

    def shift_loop(P, vel, kind, start, tab, lo, cell, nx, ny, nz, h, Fc, iw_dx, a_dt, lam_full, out):
        ih = 1.0 / h
        inv_cell = 1.0 / cell
        inv_w = XBINS / cell
        dys = 3 if three else 1
        dim = out.shape[1]
        for a in prange(out.shape[0]):
            v2 = 0.0
            for k in range(dim):
                v2 += vel[a, k] * vel[a, k]
            if kind[a] != 0 or v2 == 0.0:  # boundaries, and still water: D = 0
                for k in range(dim):
                    out[a, k] = 0.0
                continue
            xa = P[X, a]
            ya = P[Y, a]
            za = P[Z, a]
            cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, True, nx, ny, nz)
            gx = 0.0
            gy = 0.0
            gz = 0.0
            bxx = 0.0
            bxy = 0.0
            bxz = 0.0
            byy = 0.0
            byz = 0.0
            bzz = 0.0
            wall = 0.0
            for dz in range(-1, 2):
                for k in range(dys):
                    dy = k - 1 if three else 0
                    j0, j1 = row_range_binned(xa, 2.0 * h, lo[0], inv_w, cy, cz, dy, dz, nx, ny, nz, start, tab, PAD)
                    for b in range(uint64(j0), uint64(j1)):
                        rx = xa - P[X, b]
                        rz = za - P[Z, b]
                        ry = ya - P[Y, b] if three else 0.0
                        q = math.sqrt(rx * rx + ry * ry + rz * rz) * ih
                        w = tp.kernel_w(kernel, q, 1.0)  # > 0 within 2h, clamped to 0 beyond
                        wall += P[BND, b] * w
                        vf = P[VOL, b] * tp.kernel_grad_shape(kernel, q)
                        wf = tp.fickian_weight(vf, w, iw_dx)
                        gx += wf * rx
                        gz += wf * rz
                        bxx += vf * rx * rx
                        bxz += vf * rx * rz
                        bzz += vf * rz * rz
                        if three:
                            gy += wf * ry
                            bxy += vf * rx * ry
                            byy += vf * ry * ry
                            byz += vf * ry * rz
            # grad_a W_ab = Fc Fs r_ab; B_a = sum_b V_b r_ba (x) grad_a W_ab = -Fc sum_b V_b Fs r_ab (x) r_ab;
            # D = A h |v_a| dt, none with a boundary particle within 2h
            D = a_dt * h * math.sqrt(v2) if wall == 0.0 else 0.0
            sx, sy, sz = tp.fickian_shift(Fc * gx, Fc * gy, Fc * gz, -Fc * bxx, -Fc * bxy, -Fc * bxz, -Fc * byy,
                                          -Fc * byz, -Fc * bzz, D, lam_full, three)
            out[a, 0] = sx
            if three:
                out[a, 1] = sy
                out[a, 2] = sz
            else:
                out[a, 1] = sz

    return njit(parallel=True, **_OPTS)(shift_loop)


_LOOPS = {}


def fickian_shift(pos, vel, mass, kind, start, xbins, grid, kernel: int, h: float, dx: float, rho0: float,
                  coef: float, dt: float, lam_full: float = LAMBDA_FULL, work=None) -> np.ndarray:
    """The Fickian shift ``delta r_a`` [m] (N, dim) of every particle (zero for boundary
    particles, still ones and those within 2h of one) for a step of ``dt`` [s] (module
    docstring): particles sorted by cell on ``grid`` (cells 2h wide, ``start`` and the
    sub-bin table ``xbins`` from :func:`fluid.neighbours.sort_by_cell`), ``kernel`` id,
    ``h`` [m], ``dx`` [m] the spacing of the tensile term's ``W(dx)``, ``rho0`` [kg/m^3]
    the particles' volume ``m / rho0``, ``coef`` Skillen et al.'s A; ``work`` a
    :class:`fluid.equations.Workspace`."""
    n, dim = pos.shape
    three = dim == 3
    key = (int(kernel), three)
    loop = _LOOPS.get(key)
    if loop is None:
        loop = _LOOPS[key] = _make_loop(*key)
    P = np.empty((N_ROWS, n)) if work is None else work.get("shift_table", (N_ROWS, n))
    out = np.empty((n, dim)) if work is None else work.get("shift", (n, dim))
    _pack(pos, mass, kind, 1.0 / rho0, P)
    Fc = terms.cpu.kernel_grad_scale(kernel, alpha_d(kernel, dim, h), h)
    iw_dx = 1.0 / terms.cpu.kernel_w(kernel, dx / h, 1.0)
    nx, ny, nz = grid.shape
    with dynamic_chunks():
        loop(P, vel, kind, start, xbins, grid.lo3, grid.cell, nx, ny, nz, h, Fc, iw_dx, coef * dt, lam_full, out)
    return out
