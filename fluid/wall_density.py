"""Tank-wall densities that follow the fluid: the wall-pressure extrapolation of Adami,
Hu & Adams (2012, J. Comput. Phys. 231, 7057-7075, Eq. 27) for the FIXED_WALL and
MOVING_WALL particles.

Why: plain dynamic boundary particles (Barreiro et al. 2016, §2.6) integrate the
continuity equation, ``drho_w/dt = sum_f m_f (v_w - v_f) . grad_w W_wf``. A wall particle
does not move with the fluid, so water sliding along the wall changes the fluid it sees:
at the waterline, where the kernel sum of the fluid drops from its full value to zero
over ~2h, water rising at speed ``u`` along a side wall gives
``(1/rho) drho_w/dt ~ u / h`` (0 in the continuum), i.e. a pressure ``c0^2 rho eta / h``
for a rise ``eta`` against the physical ``rho g eta``: a stiff spring at the contact line
that raised the first sloshing frequency by ~10 % (cosim.validations.sloshing,
``sloshing_frequency``).

Here each wall particle ``w`` takes instead the pressure of the fluid near it, carried to
its position by the momentum balance of the wall (Adami et al. 2012, Eq. 27):

    p_w = ( sum_f p_f W_wf + (g - a_w) . sum_f rho_f r_wf W_wf ) / sum_f W_wf,

``r_wf = r_w - r_f``, ``W_wf = W(|r_wf|, h)``, the sums over the fluid particles within
the support 2h, ``g`` the gravity vector and ``a_w`` the wall's (prescribed)
acceleration; its density is the Tait density of that pressure (Barreiro et al. 2016, Eq. 8 inverted),
``rho_w = rho0 (1 + p_w / B)^(1/gamma)``, clamped below at ``rho0`` (``p_w >= 0``: the
wall holds no tension, as the clamp of the plain dynamic boundaries in
``fluid.integrator``). A wall particle with no fluid within 2h takes ``rho0``.

For a fluid at rest in any linear (hydrostatic) pressure field with a uniform density the
extrapolation is exact whatever the neighbours, so a tank started from the hydrostatic
densities (``fluid.geometry.set_hydrostatic``) starts in equilibrium with its walls.

The pair loop is unchanged: this module only sets the tank walls' densities before each
rate evaluation (the ``Fluid.boundary_correction`` hook, as ``fluid.boundary_correction.MDBC``
for bodies), weighting the correction with rho0, not rho_f (they differ by p/(gamma B) < 1 %).
An option (``FluidConfig.walls``), not the default: a tank started at rest on the lattice
moves at its free-surface corners unless settled first (``Fluid.settle``). The measurements
against plain dynamic boundaries, the cost and the corners: docs/validation/modules/wall_density_history.md.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange, uint64

from fluid import terms
from fluid.equations import PAD, require_pair_grid, tait_B
from fluid.kernels import alpha_d, kernel_id, w_value
from fluid.neighbours import XBINS, cell_coords, row_range_binned
from fluid.particles import Kind

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")
#: the least kernel sum (the kernel's shape, 1 at the centre) that counts as fluid near a
#: wall: a fluid particle on the support's edge to round-off (2h within 1e-6 h) weighs
#: less, and which side of 2h it falls on is the rounding's choice (the loop's fused
#: multiply-adds), not the geometry's
SW_MIN = 1e-24
#: the Tait pressure and its inverse of :mod:`fluid.terms` (Barreiro et al. 2016, Eq. 8)
_tait_pressure = terms.cpu.tait_pressure
_tait_density = terms.cpu.tait_density


@njit(parallel=True, **_OPTS)
def _fluid_rows(pos, rho, kind, rho0, B, gamma, R):
    """The rows the wall loop reads, contiguous per quantity: x, y, z [m] (y = 0 in 2-D),
    the Tait pressure [Pa] of fluid particles (0 for boundary particles) and 1 for fluid,
    0 for boundary particles."""
    three = pos.shape[1] == 3
    zc = pos.shape[1] - 1
    for j in prange(rho.shape[0]):
        R[0, j] = pos[j, 0]
        R[1, j] = pos[j, 1] if three else 0.0
        R[2, j] = pos[j, zc]
        f = 1.0 if kind[j] == 0 else 0.0
        R[3, j] = f * _tait_pressure(rho[j], rho0, B, gamma)
        R[4, j] = f


@njit(parallel=True, **_OPTS)
def adami_wall_density(R, rho, kind, acc_w, has_acc, start, tab, near, lo, cell, nx, ny, nz, kernel, h, rho0, B,
                       gamma, g, kmin, kmax, p_floor, skip):
    """Set ``rho`` of every particle with ``kmin <= kind <= kmax`` from Adami et al. (2012)
    Eq. 27 (module docstring). ``R`` the rows of :func:`_fluid_rows`; ``acc_w`` (N, dim)
    [m/s^2] the wall accelerations (read only if ``has_acc``); ``g`` (3,) [m/s^2] gravity
    as (x, y, z); particles sorted by cell (``start``) on cells 2h wide, ``tab`` the cell
    list's sub-bin table (:func:`fluid.neighbours.order_cells_by_x`), ``near`` the cells
    near the fluid (:func:`fluid.neighbours.fluid_near_cells`; the walls of the others
    have no fluid within 2h and take ``rho0`` without a pass); ``lo`` has 3 components
    (y = 0, ``ny = 1`` in 2-D); the rows marked in ``skip`` (bool, empty for none: a
    symmetry plane's images, which take their sources' densities) are left as they are.

    As the pair loop of fluid.equations: each row of cells trimmed to 2h in x and padded
    to whole vectors (:func:`fluid.neighbours.row_range_binned`), the fluid picked by a 0/1
    factor and the kernel clamped at its support, so that the inner loop has no branch
    and vectorises; the kernel's normalisation cancels in the ratio."""
    n = rho.shape[0]
    three = ny > 1
    dys = 3 if three else 1
    R2 = 4.0 * h * h
    ih = 1.0 / h
    inv_gamma = 1.0 / gamma
    inv_cell = 1.0 / cell
    inv_w = XBINS / cell
    skip_rows = skip.shape[0] > 0
    for i in prange(n):
        k = kind[i]
        if k < kmin or k > kmax or (skip_rows and skip[i]):
            continue
        xw = R[0, i]
        yw = R[1, i]
        zw = R[2, i]
        cx, cy, cz = cell_coords(xw, yw, zw, lo, inv_cell, True, nx, ny, nz)
        if near[cx + nx * (cy + ny * cz)] == 0:
            rho[i] = rho0
            continue
        bx = g[0]
        by = g[1]
        bz = g[2]
        if has_acc:
            bx -= acc_w[i, 0]
            if three:
                by -= acc_w[i, 1]
            bz -= acc_w[i, acc_w.shape[1] - 1]
        bx *= rho0
        by *= rho0
        bz *= rho0
        sw = 0.0
        sp = 0.0
        for dz in range(-1, 2):
            for kk in range(dys):
                dy = kk - 1 if three else 0
                j0, j1 = row_range_binned(xw, 2.0 * h, lo[0], inv_w, cy, cz, dy, dz, nx, ny, nz, start, tab, PAD)
                for j in range(uint64(j0), uint64(j1)):
                    rx = xw - R[0, j]
                    ry = yw - R[1, j]
                    rz = zw - R[2, j]
                    r2 = rx * rx + ry * ry + rz * rz
                    w = w_value(kernel, math.sqrt(r2) * ih, 1.0) * (R[4, j] if r2 < R2 else 0.0)
                    sw += w
                    sp += w * terms.cpu.adami_pressure(R[3, j], bx, by, bz, rx, ry, rz)
        rho[i] = _tait_density(terms.cpu.adami_wall_pressure(sp, sw, SW_MIN, p_floor), rho0, B, inv_gamma)


class AdamiWalls:
    """Tank-wall densities from Adami et al. (2012) Eq. 27 (module docstring), a
    ``Fluid.boundary_correction`` hook: ``AdamiWalls(fluid)`` then
    ``fluid.boundary_correction = hook`` (what ``FluidConfig(walls="adami")`` does).

    Applies to FIXED_WALL and MOVING_WALL particles; BODY particles are left to their own
    treatment. The acceleration ``a_w`` of a MOVING_WALL group driven by a prescribed
    motion is the central difference of the motion's velocity about the time the fluid
    last placed it (:meth:`fluid.solver.Fluid.prescribed_acceleration`); walls moved
    otherwise (``set_group_velocity``) take ``a_w = 0``."""

    def __init__(self, fluid):
        c = fluid.config
        self.fluid = fluid
        self.kernel = kernel_id(c.kernel)
        self.ad = alpha_d(self.kernel, c.dim, c.h)
        self.B = tait_B(c.rho0, c.speed_of_sound, c.gamma)
        self.g = c.gravity3
        self._zero = np.zeros((0, c.dim))
        #: lowest wall pressure [Pa] (0: no tension, the clamp of the plain dynamic boundaries)
        self.p_floor = 0.0
        self._rows = np.empty((5, 0))

    def __call__(self, ps, start, grid) -> None:
        c = self.fluid.config
        require_pair_grid(grid, c.h)
        lo = grid.lo3
        nx, ny, nz = grid.shape
        acc = self.fluid.prescribed_acceleration()
        has = acc is not None
        if self._rows.shape[1] != ps.n:
            self._rows = np.empty((5, ps.n))
        _fluid_rows(ps.pos, ps.rho, ps.kind, c.rho0, self.B, c.gamma, self._rows)
        adami_wall_density(self._rows, ps.rho, ps.kind, acc if has else self._zero, has, start, self.fluid.x_bins,
                           self.fluid.near_fluid, lo, grid.cell, nx, ny, nz, self.kernel, c.h, c.rho0, self.B,
                           c.gamma, self.g, int(Kind.FIXED_WALL), int(Kind.MOVING_WALL), self.p_floor,
                           self.fluid.image_rows)
