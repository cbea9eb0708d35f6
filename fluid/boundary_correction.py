"""Modified dynamic boundary conditions (mDBC) for boundary particles.

Plain dynamic boundary particles (Barreiro et al. 2016, §2.6) take their density
from the continuity equation, which only grows when fluid has already moved into
them: the fluid stands off the wall by a gap of the order of h, and a body's wetted
surface (hence its displaced volume) is inflated by that gap. mDBC (English,
Domínguez, Vacondio, Crespo, Stansby, Lind, Chiapponi & Gómez-Gesteira 2022,
Comp. Part. Mech. 9: 911-925, §3) gives each boundary particle ``b`` a ghost node
``r_g`` mirrored across the boundary surface into the fluid and sets its density
from the fluid there, extrapolated back to the particle:

    rho_b = rho_g + (r_b - r_g) . grad(rho)_g

with ``rho_g`` and ``grad(rho)_g`` the first-order consistent (linearly corrected)
SPH interpolation at the ghost node (their Eq. 12-13; Liu & Liu 2006): with
``V_j = m_j / rho_j``, ``r_jg = r_j - r_g``, ``W_j = W(|r_g - r_j|)``,
``grad W_j = grad_g W(r_g - r_j)``, solve

    [ sum V_j W_j          sum V_j W_j r_jg^T        ] [ rho_g      ]   [ sum V_j rho_j W_j      ]
    [ sum V_j grad W_j     sum V_j grad W_j r_jg^T   ] [ grad rho_g ] = [ sum V_j rho_j grad W_j ]

which reproduces any linear density field exactly (the hydrostatic one, to first
order). Where the matrix is near singular (|det| below ``det_min``, e.g. a ghost
node at the free surface with few fluid neighbours) the Shepard average
``sum V_j rho_j W_j / sum V_j W_j`` is used instead, as the paper does; a ghost
with no fluid near it gives rho0. The result is clamped below at rho0: a free
surface holds no tension, and a wall that pulled fluid would glue it to the body
(the same clamp as the plain dynamic boundaries of ``fluid.integrator``).

With the boundary particles half a spacing inside the geometric surface (as
``bodies.sampling`` places them) the fluid then rests half a spacing outside it:
the wall sits where the geometry says.

This module only sets boundary densities before a rate evaluation (hook
``Fluid.boundary_correction``); the pair loop is unchanged.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from errors import InputError
from fluid import terms
from fluid.kernels import alpha_d, grad_factor, kernel_id, w_value
from fluid.neighbours import cell_coords, row_range

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")

#: |det| of the correction matrix below which the Shepard (zero-order) value is used
#: [-] (the matrix is dimensionless; 1e-3 is DualSPHysics' default determinant limit)
DET_MIN = 1e-3


@njit(parallel=True, **_OPTS)
def mdbc_density(pos, rho, mass, kind, ids, offset, start, lo, inv_cell, nx, ny, nz, reach, kernel,
                 ad, h, rho0, det_min, n_low):
    """Set ``rho`` of every particle whose ``offset[ids[i]]`` (vector to its ghost
    node [m], (max id + 1, dim)) is non-zero from the fluid at its ghost node (see
    module docstring). Particles sorted by cell (``start``); ``lo`` has 3
    components (y = 0, ``ny = 1`` in 2-D). ``n_low[i]`` is set to 1 where the
    Shepard fallback was taken (for diagnostics)."""
    n, dim = pos.shape
    three = dim == 3
    zc = dim - 1
    dys = 2 * reach + 1 if three else 1
    m = dim + 1
    R2 = 4.0 * h * h
    for i in prange(n):
        n_low[i] = 0
        if kind[i] == 0:
            continue
        o = offset[ids[i]]
        o2 = 0.0
        for k in range(dim):
            o2 += o[k] * o[k]
        if o2 == 0.0:
            continue
        gx = pos[i, 0] + o[0]
        gy = pos[i, 1] + o[1] if three else 0.0
        gz = pos[i, zc] + o[zc]
        A = np.zeros((4, 4))
        bv = np.zeros(4)
        row = np.empty(4)  # the weights V W, V grad W (solver order: x, z or x, y, z)
        col = np.empty(4)  # 1 and r_jg (same order)
        col[0] = 1.0
        cx, cy, cz = cell_coords(gx, gy, gz, lo, inv_cell, True, nx, ny, nz)
        for dz in range(-reach, reach + 1):
            for kk in range(dys):
                dy = kk - reach if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, reach)
                for j in range(j0, j1):
                    if kind[j] != 0:
                        continue
                    rx = pos[j, 0] - gx
                    ry = pos[j, 1] - gy if three else 0.0
                    rz = pos[j, zc] - gz
                    r2 = rx * rx + ry * ry + rz * rz
                    if r2 >= R2:
                        continue
                    q = math.sqrt(r2) / h
                    V = mass[j] / rho[j]
                    VF = -V * grad_factor(kernel, q, ad, h)  # grad_g W(r_g - r_j) = F (r_g - r_j) = -F r_jg
                    terms.cpu.mdbc_add_neighbour(A, bv, row, col, m, V, w_value(kernel, q, ad), VF, rx, ry, rz,
                                                 rho[j], three)
        rho[i], n_low[i] = terms.cpu.mdbc_extrapolate(A, bv, m, o, dim, det_min, rho0)


class MDBC:
    """mDBC densities for a set of boundary particles, addressed by particle id.

    Parameters
    ----------
    dim:
        2 or 3.
    h:
        Smoothing length [m].
    rho0:
        Reference density [kg/m^3].
    kernel:
        Kernel name ("wendland" or "cubic").
    n_ids:
        One more than the largest particle id [-].
    det_min:
        Determinant limit [-] of the first-order correction (see :data:`DET_MIN`).
    """

    def __init__(self, dim: int, h: float, rho0: float, kernel: str, n_ids: int, det_min: float = DET_MIN):
        if dim not in (2, 3):
            raise InputError(f"mDBC: dim must be 2 or 3, got {dim!r}")
        if not (h > 0 and rho0 > 0 and n_ids >= 1 and det_min >= 0):
            raise InputError(f"mDBC: need h > 0 m, rho0 > 0 kg/m^3, n_ids >= 1, det_min >= 0; got "
                             f"{h}, {rho0}, {n_ids}, {det_min}")
        self.dim, self.h, self.rho0 = dim, float(h), float(rho0)
        self.kernel = kernel_id(kernel)
        self.ad = alpha_d(self.kernel, dim, self.h)
        self.det_min = float(det_min)
        #: vector [m] from each particle (by id) to its ghost node; zero: not corrected
        self.offset = np.zeros((int(n_ids), dim))
        #: particles (current order) that took the Shepard fallback in the last call
        self.low_order = np.zeros(0, np.int8)

    def set_offsets(self, ids, offsets) -> None:
        """Ghost-node vectors [m] ``(len(ids), dim)`` of the particles ``ids``: twice the
        distance to the boundary surface along its outward normal (mirror images)."""
        offsets = np.asarray(offsets, np.float64)
        if offsets.shape != (len(ids), self.dim) or not np.isfinite(offsets).all():
            raise InputError(f"mDBC: ghost offsets must be finite, shape ({len(ids)}, {self.dim})")
        self.offset[np.asarray(ids, np.int64)] = offsets

    def __call__(self, ps, start, grid) -> None:
        """Overwrite the densities of the corrected particles of ``ps`` (sorted by cell on
        ``grid``, ``start`` its cell offsets)."""
        lo = grid.lo3
        nx, ny, nz = grid.shape
        if self.low_order.shape[0] != ps.n:
            self.low_order = np.zeros(ps.n, np.int8)
        mdbc_density(ps.pos, ps.rho, ps.mass, ps.kind, ps.ids, self.offset, start, lo, 1.0 / grid.cell,
                     nx, ny, nz, grid.reach, self.kernel, self.ad, self.h, self.rho0, self.det_min,
                     self.low_order)
