"""Weakly-compressible SPH rates: continuity with density diffusion, momentum with
artificial viscosity and gravity, Tait equation of state, dynamic boundaries.

All pair loops gather: thread ``a`` writes only particle ``a``'s rates, with no branch on the
pair (kernel factors clamped at the support edge, pair masks 0/1 factors); the self pair adds
zero. ``r_ab = r_a - r_b``, ``v_ab = v_a - v_b``, ``grad_a W_ab = F_ab r_ab``.

* Continuity, Barreiro et al. 2016, Eq. 7: ``drho_a/dt = sum_b m_b v_ab . grad_a W_ab + D_a``.
* Density diffusion between fluid particles, ``D_a = delta h c0 sum_b (m_b/rho_b) psi_ab .
  grad_a W_ab``, ``psi_ab = 2 (rho_b - rho_a - rho^H_ba) r_ba / (|r_ab|^2 + eta^2)``:
  ``"molteni"`` (Molteni & Colagrossi 2009, ``rho^H = 0``: Dinçer & Demir 2020, Eq. 1-2
  without Eq. 3-4); ``"antuono"`` (Antuono et al. 2010; Dinçer & Demir 2020, Eq. 1-4: zero
  for any linear density field; a second pair loop); ``"fourtakas"`` (default; Fourtakas et
  al. 2019, DualSPHysics' DDT2, linearised with the local density and sound speed: zero for
  the hydrostatic state, ``rho^H_ba`` taken along the gravity vector, whatever its
  direction); ``"none"``. ``diffusion_at_surface=False`` fades it where the free surface
  cuts the support (:data:`SURFACE_FADE`): for still water, not the default.
* Momentum, Barreiro et al. 2016, Eq. 6 (Sunara et al. 2021, Eq. 5):
  ``dv_a/dt = -sum_b m_b (P_a/rho_a^2 + P_b/rho_b^2 + Pi_ab) grad_a W_ab + g``.
* Artificial viscosity, Sunara et al. 2021, Eq. 6 (Monaghan 1992): ``Pi_ab = -alpha cbar_ab
  mu_ab / rhobar_ab`` if ``v_ab . r_ab < 0`` else 0, ``mu_ab = h v_ab . r_ab / (r_ab^2 +
  eta^2)``, ``eta^2 = 0.01 h^2``; alpha times ``alpha_wall`` between fluid and wall (0: slip).
* Laminar viscosity (optional, ``nu > 0``): Lo & Shao (2002), DualSPHysics' "Laminar"
  (Barreiro et al. 2016, §2.3; Morris et al. 1997), fluid-fluid and fluid-wall (no slip);
  its step limit is in :func:`fluid.integrator.stable_dt`.
* XSPH (optional, ``eps > 0``; Monaghan 1989, Wang et al. 2022, §2): particles move with
  ``v_a + eps sum_b (m_b / rhobar_ab) v_ba W_ab`` (Monaghan's sign; positions only).
* Tait equation of state, Barreiro et al. 2016, Eq. 8, ``B = c0^2 rho0 / gamma`` (Sunara et
  al. 2021, Eq. 8); sound speed ``c = c0 (rho/rho0)^((gamma-1)/2)``.
* Dynamic boundaries, Barreiro et al. 2016, §2.6: continuity over fluid neighbours, the same
  equation of state, prescribed motion; their "acceleration" is the fluid's force per unit
  mass on them, exactly minus what they exert on the fluid (every pair term is antisymmetric).

Each formula is a function of :mod:`fluid.terms`, written once and compiled both for these
loops (``terms.cpu``; ``tp`` in the pair loop) and for the GPU kernels; a new term is one
function there, called from both (docs/fluid_equations.md, "The terms, written once").
Why each choice (the diffusion variants, the surface fade, the wall viscosity, the XSPH
sign), in full and with its measured effect: docs/fluid_equations.md.
"""

from __future__ import annotations

import math
from contextlib import contextmanager
from typing import NamedTuple

import numba
import numpy as np
from numba import njit, prange, uint64

from errors import InputError

from fluid import settings, terms
from fluid.kernels import grad_scale, grad_shape
from fluid.neighbours import XBINS, cell_coords, row_range, row_range_binned, x_bins
from fluid.particles import Kind

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")

#: indices into the float parameter vector ``prm`` of :func:`interact`
P_H, P_AD, P_ALPHA, P_DDT, P_HYDRO, P_RHO0, P_C0, P_G, P_NU4, P_XSPH, P_AWALL, P_RENORM, P_FADE, P_F32 = \
    0, 1, 2, 3, 4, 5, 6, 7, 10, 11, 12, 13, 14, 15
N_PRM = 16

#: arithmetic of the pair loop (:func:`interact`) and the density diffusion terms: the
#: choices of FluidConfig's ``precision`` and ``diffusion`` (:mod:`fluid.settings`)
PRECISION, DIFFUSION = settings.PRECISION, settings.DIFFUSION
#: ``(s0, s1)``: the density diffusion fades from full at ``s_a = s0`` to none at ``s1``
#: when ``diffusion_at_surface`` is False (module docstring): the free-surface row and the
#: row below it lose it on the lattice (s = 0.62, 0.075-0.086 at h = sqrt(2) dx), the
#: bulk of a disordered flow keeps it (median 0.01-0.03 in a 2-D dam break)
SURFACE_FADE = (0.02, 0.05)


def params(h, ad, alpha, delta, diffusion, rho0, c0, g, nu=0.0, xsph=0.0, alpha_wall=1.0,
           diffusion_at_surface=True, precision="float64") -> np.ndarray:
    """Pack the parameters of :func:`interact`.

    h [m] smoothing length, ad [1/m^dim] kernel normalisation, alpha [-] artificial
    viscosity, delta [-] density-diffusion coefficient, diffusion one of
    :data:`DIFFUSION`, rho0 [kg/m^3], c0 [m/s], g [m/s^2] gravity vector (dim,) (the
    Fourtakas term's hydrostatic density difference is taken along it: ``g . r_ab``),
    nu [m^2/s] kinematic viscosity of the laminar term (0: off), xsph [-] the XSPH
    coefficient epsilon (0: off), alpha_wall [-] the factor on alpha between fluid and
    boundary particles (1: the same viscosity as between fluid particles),
    diffusion_at_surface False: the diffusion fades out where the support is cut by the
    free surface (module docstring), precision one of :data:`PRECISION`: the arithmetic of
    the pair terms (:func:`interact`).
    """
    if precision not in PRECISION:
        raise InputError(f"precision={precision!r}: choose one of {PRECISION}")
    prm = np.zeros(N_PRM)
    prm[P_H], prm[P_AD], prm[P_ALPHA] = h, ad, alpha
    prm[P_DDT] = 0.0 if diffusion == "none" else 2.0 * delta * h * c0
    prm[P_HYDRO] = 1.0 if diffusion == "fourtakas" else 0.0
    prm[P_RENORM] = 1.0 if diffusion == "antuono" else 0.0
    prm[P_RHO0], prm[P_C0] = rho0, c0
    g = np.asarray(g, np.float64)
    prm[P_G:P_G + g.size] = g
    prm[P_NU4] = 4.0 * nu
    prm[P_XSPH] = xsph
    prm[P_AWALL] = alpha_wall
    prm[P_FADE] = 0.0 if diffusion_at_surface else 1.0
    prm[P_F32] = 1.0 if precision == "float32" else 0.0
    return prm


def tait_B(rho0: float, c0: float, gamma: float) -> float:
    """Tait stiffness B = c0^2 rho0 / gamma [Pa] (Barreiro et al. 2016, Eq. 8)."""
    return c0 * c0 * rho0 / gamma


#: the Tait equation of state of :mod:`fluid.terms` (Barreiro et al. 2016, Eq. 8):
#: ``_tait(rho, rho0, c0, gamma, B, e)`` -> (pressure [Pa], sound speed [m/s])
_tait = terms.cpu.tait
#: the pair terms the pair loops call, in their precision: float64 here, rebound to
#: ``terms.cpu_f32`` for the float32 loop (:func:`_make_interact`)
tp = terms.cpu


@njit(parallel=True, **_OPTS)
def equation_of_state(rho, rho0, c0, gamma, p, cs):
    """Tait EOS (Barreiro et al. 2016, Eq. 8): pressure ``p`` [Pa] and sound speed
    ``cs`` [m/s] of every particle from its density [kg/m^3]."""
    B = c0 * c0 * rho0 / gamma
    e = 0.5 * (gamma - 1.0)
    for i in prange(rho.shape[0]):
        p[i], cs[i] = _tait(rho[i], rho0, c0, gamma, B, e)


#: rows of the packed particle table :func:`pack` fills and the pair loops read
X, Y, Z, VX, VY, VZ, RHO, MASS, CS, PR2, VOL, KAP, ISF = range(13)
N_ROWS = 13
#: rows of the float32 table :func:`pack_f32` fills: a particle's offsets [m] from the low
#: corner of its cell, the cell's x index, then the rows of ``S`` from VX on (row r at r + 1)
T_XO, T_YO, T_ZO, T_CX = range(4)
N_ROWS_F32 = N_ROWS + 1
#: rows of the rates table :func:`interact` writes (the accelerations go to their own array)
DRHO, VISC = 0, 1
#: the pair loop runs over neighbour ranges rounded up to a multiple of this many
#: particles, so that it stays in its vector body (see :func:`interact`)
PAD = 8
#: the same for the float32 loop (16 pairs per AVX-512 pass)
PAD_F32 = 16


@njit(parallel=True, **_OPTS)
def pack(pos, vel, rho, mass, kind, rho0, c0, gamma, p, S):
    """Tait EOS (Barreiro et al. 2016, Eq. 8) into ``p`` [Pa], and the packed table
    ``S`` (N_ROWS, N) the pair loop reads: one contiguous row per quantity (positions
    and velocities per component, y = 0 in 2-D, density, mass, sound speed
    ``c = c0 (rho/rho0)^((gamma-1)/2)``, ``p/rho^2``, ``m/rho`` (fluid; 0 for boundary particles), ``rho/c^2`` and 1 for fluid,
    0 for boundary particles), so that a neighbour range is a contiguous slice of each row
    and the pair loop vectorises."""
    B = c0 * c0 * rho0 / gamma
    e = 0.5 * (gamma - 1.0)
    three = pos.shape[1] == 3
    zc = pos.shape[1] - 1
    for i in prange(rho.shape[0]):
        r = rho[i]
        pi, c = _tait(r, rho0, c0, gamma, B, e)
        p[i] = pi
        S[X, i] = pos[i, 0]
        S[Y, i] = pos[i, 1] if three else 0.0
        S[Z, i] = pos[i, zc]
        S[VX, i] = vel[i, 0]
        S[VY, i] = vel[i, 1] if three else 0.0
        S[VZ, i] = vel[i, zc]
        S[RHO, i] = r
        S[MASS, i] = mass[i]
        S[CS, i] = c
        S[PR2, i] = pi / (r * r)
        S[VOL, i] = mass[i] / r if kind[i] == 0 else 0.0  # diffusion acts between fluid particles
        S[KAP, i] = r / (c * c)
        S[ISF, i] = 1.0 if kind[i] == 0 else 0.0


@njit(parallel=True, **_OPTS)
def pack_f32(S, rho0, lo, cell, nx, ny, nz, T):
    """The float32 table ``T`` (N_ROWS_F32, N) of the float32 pair loop from ``S``
    (:func:`pack`): each particle's position as its offsets from the low corner of its
    cell [m] (``lo`` the grid's corner, x, y, z; cells ``cell`` [m] wide, ``nx, ny, nz`` of
    them) and its cell's x index, so that a pair's separation ``(xo_a - xo_b) + (ix_a -
    ix_b) cell`` is a sum of small numbers, its float32 rounding ~1e-7 of the cell and not
    of the position (the y and z indices are those of the neighbour's row of cells); then
    the rows of ``S`` from VX on, the density row as ``rho - rho0`` (float32 rounding near
    2e-6 kg/m^3 instead of 6e-5 at 1000)."""
    inv_cell = 1.0 / cell
    for i in prange(S.shape[1]):
        cx, cy, cz = cell_coords(S[X, i], S[Y, i], S[Z, i], lo, inv_cell, True, nx, ny, nz)
        T[T_XO, i] = S[X, i] - lo[0] - cx * cell
        T[T_YO, i] = S[Y, i] - lo[1] - cy * cell
        T[T_ZO, i] = S[Z, i] - lo[2] - cz * cell
        T[T_CX, i] = cx
        for r in range(VX, N_ROWS):
            T[r + 1, i] = S[r, i] - rho0 if r == RHO else S[r, i]


def hydrostatic_density(depth, rho0: float, c0: float, gamma: float, g: float) -> np.ndarray:
    """Density [kg/m^3] whose Tait pressure is ``rho0 g depth`` (depth [m] below the free
    surface, clipped at 0): the rest state a hydrostatic set-up starts from."""
    B = tait_B(rho0, c0, gamma)
    return rho0 * (1.0 + rho0 * g * np.maximum(depth, 0.0) / B) ** (1.0 / gamma)


#: what the pair loop computes for the tank-wall particles (FIXED_WALL, MOVING_WALL;
#: :func:`interact`'s ``walls``): every rate (their loads are read), the continuity rate
#: only (plain dynamic boundaries whose loads nobody reads), nothing (walls whose densities
#: come from the fluid, fluid.wall_density)
WALLS_FULL, WALLS_CONTINUITY, WALLS_NONE = 0, 1, 2
FIXED_WALL, MOVING_WALL = int(Kind.FIXED_WALL), int(Kind.MOVING_WALL)


@njit(**_OPTS)
def wall_sums(S, xa, ya, za, ux, uy, uz, rhoa, kernel, three, h, lo, cell, cx, cy, cz, nx, ny, nz, start, tab,
              continuity):
    """Over the fluid particles b within 2h of a boundary particle at (xa, ya, za) [m]
    moving at (ux, uy, uz) [m/s] with density ``rhoa`` [kg/m^3] in cell (cx, cy, cz) (cells
    ``cell`` = 2h [m] wide, ``lo`` (x, y, z), ``tab`` the sub-bin table):
    ``sum_b m_b v_ab . r_ab F_ab / Fc``, its continuity rate (Barreiro et al. 2016, Eq. 7)
    without the kernel's constant factor, and ``sum_b (mu_ab / h)^8``, the 8-norm of Eq. 14's
    viscous terms (Sunara et al. 2021) before its root: the same sums, term for term
    and in the same order, as the pair loop's for a boundary particle (boundary-boundary
    pairs do not interact; no diffusion), so that its step bound is the one the full pass
    gives."""
    R2 = 4.0 * h * h
    ih = 1.0 / h
    eta2 = 0.01 * h * h
    inv_w = XBINS / cell
    sd = 0.0
    sv = 0.0
    dys = 3 if three else 1
    tz = za - lo[2] - cz * cell
    ty = ya - lo[1] - cy * cell
    for dz in range(-1, 2):
        for k in range(dys):
            dy = k - 1 if three else 0
            if three and dy != 0 and dz != 0:
                ey2 = ty * ty if dy < 0 else (cell - ty) * (cell - ty)
                ez2 = tz * tz if dz < 0 else (cell - tz) * (cell - tz)
                if ey2 + ez2 >= R2:
                    continue
            j0, j1 = row_range_binned(xa, 2.0 * h, lo[0], inv_w, cy, cz, dy, dz, nx, ny, nz, start, tab, PAD)
            for b in range(uint64(j0), uint64(j1)):
                rx = xa - S[X, b]
                ry = ya - S[Y, b]
                rz = za - S[Z, b]
                vr = (ux - S[VX, b]) * rx + (uy - S[VY, b]) * ry + (uz - S[VZ, b]) * rz
                r2 = rx * rx + ry * ry + rz * rz
                fb = S[ISF, b]
                if continuity:  # loop-invariant: the compiler keeps two loops
                    sd += tp.continuity(S[MASS, b] * fb * tp.kernel_grad_shape(kernel, math.sqrt(r2) * ih), vr)
                inv = tp.pair_division(r2, eta2, rhoa + S[RHO, b])[2]
                sv += tp.viscous_bound(fb, r2, R2, vr, inv, 1.0)
    return sd, sv


def _make_interact(kernel: int, three: bool, laminar: bool, xsph: bool, wall_visc: bool, renorm: bool,
                   fade: bool, f32: bool = False, tilted: bool = False):
    """The pair loop of :func:`interact` compiled for one kernel, dimension, choice of
    optional terms and precision. These are constants of the closure, so the kernel's
    branch, the unused y component and the terms switched off fold away at compile time and
    the inner loop is straight-line code; numba caches each variant apart (the closure's
    values are part of its cache key). ``f32``: the pair terms in float32 (see
    :func:`interact`), read from the float32 table ``T`` of :func:`pack_f32`; otherwise ``T`` is
    ``S`` and every operation is float64. ``tilted``: gravity has a horizontal component, and
    the Fourtakas hydrostatic density difference takes ``g . r_ab``, not ``g_z z_ab``."""
    F = np.float32 if f32 else np.float64
    zero, one = (np.float32(0.0), np.float32(1.0)) if f32 else (0.0, 1.0)  # constants of the closure
    pad = PAD_F32 if f32 else PAD
    o = -1 if f32 else 0  # float32: T's rows are S's shifted by one (the cell's x index first)

    def pair_loop(S, T, n, start, tab, lo, cell, nx, ny, nz, prm, out, acc, xs, G, near, kind, walls, skip):
        h = prm[P_H]
        ad = prm[P_AD]
        ddt = prm[P_DDT]
        nu4 = prm[P_NU4]
        eps2 = 2.0 * prm[P_XSPH] * ad  # m_b / rhobar_ab = 2 m_b / (rho_a + rho_b); W = alpha_d w(q)
        gx = prm[P_G]
        gy = prm[P_G + 1] if three else 0.0
        gz = prm[P_G + 2] if three else prm[P_G + 1]
        # constants taken out of the pair sums
        Fc = grad_scale(kernel, ad, h)  # F = Fc * grad_shape
        # Pi_ab = avh (c_a + c_b) min(v_ab.r_ab, 0) / ((r^2+eta^2)(rho_a+rho_b))
        avh = F(-prm[P_ALPHA] * h)
        # rho^H_ba = -(kap_a + kap_b) (g . r_ab) / 2: hgz (kap_a + kap_b) z_ab for gravity along -z
        hgx = F(-0.5 * prm[P_HYDRO] * gx)
        hgy = F(-0.5 * prm[P_HYDRO] * gy)
        hgz = F(-0.5 * prm[P_HYDRO] * gz)
        irho0 = F(1.0 / prm[P_RHO0])
        rho00 = F(2.0 * prm[P_RHO0])  # float32: T holds rho - rho0
        awall = F(prm[P_AWALL])
        hf = F(h)
        s0, s1 = SURFACE_FADE
        eta2 = F(0.01 * h * h)
        R2 = 4.0 * h * h
        R2f = F(R2)
        ih = F(1.0 / h)
        cellf = F(cell)
        inv_cell = 1.0 / cell
        inv_w = XBINS / cell
        dys = 3 if three else 1
        skip_dry = near.shape[0] > 0
        skip_rows = skip.shape[0] > 0
        for a in prange(n):
            if skip_rows and skip[a]:  # a row whose rates nobody reads (a symmetry plane's image)
                for d in range(acc.shape[1]):
                    acc[a, d] = 0.0
                    if xsph:
                        xs[a, d] = 0.0
                out[DRHO, a] = 0.0
                out[VISC, a] = 0.0
                continue
            xa = S[X, a]
            ya = S[Y, a]
            za = S[Z, a]
            ux = T[VX - o, a]
            uy = T[VY - o, a]
            uz = T[VZ - o, a]
            rhoa = T[RHO - o, a]
            pa = T[PR2 - o, a]
            ka = T[KAP - o, a]
            fa = T[ISF - o, a]
            ca = T[CS - o, a]
            if f32:  # offsets [m] in the particle's cell, and its cell's x index
                xoa = T[T_XO, a]
                yoa = T[T_YO, a]
                zoa = T[T_ZO, a]
                cxa = T[T_CX, a]
            if renorm:
                gxa = F(G[0, a])
                gya = F(G[1, a])
                gza = F(G[2, a])
            cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, True, nx, ny, nz)  # packed rows: always x, y, z
            # a boundary particle with no fluid within 2h: every term below is zero; a
            # tank-wall particle whose load is not wanted: its continuity rate ("dbc") and
            # its viscous terms' bound on the step
            dry = skip_dry and fa == zero and near[cx + nx * (cy + ny * cz)] == 0
            if dry or (walls != WALLS_FULL and fa == zero and (kind[a] == FIXED_WALL or kind[a] == MOVING_WALL)):
                for d in range(acc.shape[1]):
                    acc[a, d] = 0.0
                    if xsph:
                        xs[a, d] = 0.0
                if dry:
                    out[DRHO, a] = 0.0
                    out[VISC, a] = 0.0
                else:  # the step bound stays the full pass's
                    wsd, wsv = wall_sums(S, xa, ya, za, S[VX, a], S[VY, a], S[VZ, a], S[RHO, a], kernel, three, h,
                                         lo, cell, cx, cy, cz, nx, ny, nz, start, tab, walls == WALLS_CONTINUITY)
                    out[DRHO, a] = Fc * wsd
                    out[VISC, a] = h * math.sqrt(math.sqrt(math.sqrt(wsv)))
                continue
            sd = 0.0
            sdd = 0.0
            sx = 0.0
            sy = 0.0
            sz = 0.0
            lx = 0.0
            ly = 0.0
            lz = 0.0
            wx = 0.0
            wy = 0.0
            wz = 0.0
            vmax = 0.0
            gsx = 0.0
            gsy = 0.0
            gsz = 0.0
            # the sums over a row's pairs: float64 straight into the totals; float32 into a
            # partial sum per row (a few tens of terms), added to the float64 totals after it
            qd = zero
            qdd = zero
            qx = zero
            qy = zero
            qz = zero
            qlx = zero
            qly = zero
            qlz = zero
            qwx = zero
            qwy = zero
            qwz = zero
            qv = zero
            qgx = zero
            qgy = zero
            qgz = zero
            if three:  # squared distances to the rows of cells below/above in z and y
                tz = za - lo[2] - cz * cell
                ty = ya - lo[1] - cy * cell
                ez_lo, ez_hi = tz * tz, (cell - tz) * (cell - tz)
                ey_lo, ey_hi = ty * ty, (cell - ty) * (cell - ty)
            for dz in range(-1, 2):
                for k in range(dys):
                    dy = k - 1 if three else 0
                    if three and dy != 0 and dz != 0:
                        # a corner row of cells lies wholly beyond 2h for a fifth of the
                        # particles (1 - pi/4): skip it (5 % of the 3-D loop)
                        ey2 = ey_lo if dy < 0 else ey_hi
                        ez2 = ez_lo if dz < 0 else ez_hi
                        if ey2 + ez2 >= R2:
                            continue
                    # the particles of the row that can lie within 2h, the range
                    # rounded up to a multiple of PAD within the row: what it adds lies
                    # farther than 2h, where every term below is exactly zero, and the
                    # loop rarely runs a scalar tail
                    j0, j1 = row_range_binned(xa, 2.0 * h, lo[0], inv_w, cy, cz, dy, dz, nx, ny, nz, start, tab, pad)
                    if f32:  # every particle of the row lies in the cells y = cy + dy, z = cz + dz
                        yor = yoa - F(dy) * cellf
                        zor = zoa - F(dz) * cellf
                        qd = zero
                        qdd = zero
                        qx = zero
                        qy = zero
                        qz = zero
                        qlx = zero
                        qly = zero
                        qlz = zero
                        qwx = zero
                        qwy = zero
                        qwz = zero
                        qv = zero
                        qgx = zero
                        qgy = zero
                        qgz = zero
                    for b in range(uint64(j0), uint64(j1)):
                        if f32:  # from the offsets in the cells: as exact as float32 allows
                            rx = (xoa - T[T_XO, b]) + (cxa - T[T_CX, b]) * cellf
                            rz = zor - T[T_ZO, b]
                        else:
                            rx = xa - S[X, b]
                            rz = za - S[Z, b]
                        vx = ux - T[VX - o, b]
                        vz = uz - T[VZ - o, b]
                        if three:
                            ry = yor - T[T_YO, b] if f32 else ya - S[Y, b]
                            vy = uy - T[VY - o, b]
                            r2 = rx * rx + ry * ry + rz * rz
                            vr = vx * rx + vy * ry + vz * rz
                        else:
                            ry = zero
                            vy = zero
                            r2 = rx * rx + rz * rz
                            vr = vx * rx + vz * rz
                        q = math.sqrt(r2) * ih
                        Fs = tp.kernel_grad_shape(kernel, q)
                        fb = T[ISF - o, b]
                        mask = max(fa, fb)  # boundary-boundary pairs do not interact
                        mbm = T[MASS - o, b] * mask
                        mbF = mbm * Fs
                        rhob = T[RHO - o, b]
                        # float64 without rho00: a value of the parallel loop's closure, not a constant,
                        # it would hold a register in the inner loop (a spill per pass in 3-D)
                        e2, d, inv = tp.pair_division(r2, eta2, rhoa + rhob + rho00 if f32 else rhoa + rhob)
                        qd += tp.continuity(mbF, vr)
                        # density diffusion between fluid particles (VOL is zero for
                        # boundary particles, fa applied after the loop)
                        if renorm:
                            rhoH = tp.renormalised_hydrostatic(gxa, gya, gza, F(G[0, b]), F(G[1, b]), F(G[2, b]),
                                                               rx, ry, rz, three)
                        else:
                            rhoH = tp.fourtakas_hydrostatic(hgx, hgy, hgz, rx, ry, rz, ka, T[KAP - o, b], tilted)
                        qdd += tp.density_diffusion(T[VOL - o, b], rhoa, rhob, rhoH, Fs, r2, inv)
                        if fade:  # sum_b V_b grad_a W_ab, walls at their volume m_b / rho0
                            vf = tp.support_volume(T[VOL - o, b], fb, T[MASS - o, b], irho0) * Fs
                            qgx += vf * rx
                            qgy += vf * ry
                            qgz += vf * rz
                        Pi = tp.artificial_viscosity(avh, ca, T[CS - o, b], vr, d)
                        if wall_visc:
                            Pi *= tp.wall_viscosity(awall, fa, fb)
                        coef = tp.momentum(mbF, pa, T[PR2 - o, b], Pi)
                        qx -= coef * rx
                        qy -= coef * ry
                        qz -= coef * rz
                        if laminar:
                            lam = tp.laminar_viscosity(mbF, r2, d)
                            qlx += lam * vx
                            qly += lam * vy
                            qlz += lam * vz
                        # h inside the 8-norm's terms in float32 keeps mu^8 in its range
                        qv += tp.viscous_bound(mask, r2, R2f, vr, inv, hf if f32 else 1.0)
                        if xsph:
                            wgt = tp.xsph_weight(mbm, d, e2, tp.kernel_w(kernel, q, one))  # alpha_d after the loop
                            qwx -= wgt * vx
                            qwy -= wgt * vy
                            qwz -= wgt * vz
                    if f32:
                        sd += qd
                        sdd += qdd
                        sx += qx
                        sy += qy
                        sz += qz
                        vmax += qv
                        if laminar:
                            lx += qlx
                            ly += qly
                            lz += qlz
                        if xsph:
                            wx += qwx
                            wy += qwy
                            wz += qwz
                        if fade:
                            gsx += qgx
                            gsy += qgy
                            gsz += qgz
            if not f32:
                sd = qd
                sdd = qdd
                sx = qx
                sy = qy
                sz = qz
                vmax = qv
                lx = qlx
                ly = qly
                lz = qlz
                wx = qwx
                wy = qwy
                wz = qwz
                gsx = qgx
                gsy = qgy
                gsz = qgz
            # the support's cut by the free surface (module docstring)
            fd = terms.cpu.surface_fade(h, Fc, gsx, gsy, gsz, s0, s1) if fade else 1.0
            out[DRHO, a] = terms.cpu.continuity_rate(Fc, sd, ddt, fa, fd, sdd)
            out[VISC, a] = terms.cpu.viscous_speed(1.0 if f32 else h, vmax)  # not ** 0.125: see interact
            acc[a, 0] = terms.cpu.acceleration(Fc, sx, nu4, lx, laminar, fa, gx)
            if three:
                acc[a, 1] = terms.cpu.acceleration(Fc, sy, nu4, ly, laminar, fa, gy)
                acc[a, 2] = terms.cpu.acceleration(Fc, sz, nu4, lz, laminar, fa, gz)
            else:
                acc[a, 1] = terms.cpu.acceleration(Fc, sz, nu4, lz, laminar, fa, gz)
            if xsph:
                xs[a, 0] = eps2 * fa * wx
                if three:
                    xs[a, 1] = eps2 * fa * wy
                    xs[a, 2] = eps2 * fa * wz
                else:
                    xs[a, 1] = eps2 * fa * wz

    return njit(parallel=True, **_OPTS)(terms.rebind(pair_loop, tp=terms.cpu_f32) if f32 else pair_loop)


#: |det| of the renormalisation matrix below which the hydrostatic gradient is used
#: (:func:`fluid.terms.renormalised_gradient`)
DET_MIN = terms.DET_MIN


def _make_gradient(kernel: int, three: bool):
    """The renormalised density gradient loop of :func:`density_gradients` compiled for
    one kernel and dimension."""

    @njit(parallel=True, **_OPTS)
    def gradient_loop(S, n, start, tab, lo, cell, nx, ny, nz, prm, G, skip):
        h = prm[P_H]
        gx = prm[P_G]
        gy = prm[P_G + 1] if three else 0.0
        gz = prm[P_G + 2] if three else prm[P_G + 1]
        ih = 1.0 / h
        inv_cell = 1.0 / cell
        inv_w = XBINS / cell
        dys = 3 if three else 1
        skip_rows = skip.shape[0] > 0
        for a in prange(n):
            if S[ISF, a] == 0.0 or (skip_rows and skip[a]):  # boundary particles take no diffusion
                G[0, a] = 0.0
                G[1, a] = 0.0
                G[2, a] = 0.0
                continue
            xa = S[X, a]
            ya = S[Y, a]
            za = S[Z, a]
            rhoa = S[RHO, a]
            cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, True, nx, ny, nz)
            mxx = 0.0
            mxy = 0.0
            mxz = 0.0
            myy = 0.0
            myz = 0.0
            mzz = 0.0
            bx = 0.0
            by = 0.0
            bz = 0.0
            for dz in range(-1, 2):
                for k in range(dys):
                    dy = k - 1 if three else 0
                    j0, j1 = row_range_binned(xa, 2.0 * h, lo[0], inv_w, cy, cz, dy, dz, nx, ny, nz, start, tab, PAD)
                    for b in range(uint64(j0), uint64(j1)):
                        rx = xa - S[X, b]
                        rz = za - S[Z, b]
                        ry = ya - S[Y, b] if three else 0.0
                        q = math.sqrt(rx * rx + ry * ry + rz * rz) * ih
                        w = S[VOL, b] * grad_shape(kernel, q)  # fluid neighbours only (VOL = 0 on walls)
                        d = (S[RHO, b] - rhoa) * w
                        mxx += w * rx * rx
                        mxz += w * rx * rz
                        mzz += w * rz * rz
                        bx += d * rx
                        bz += d * rz
                        if three:
                            mxy += w * rx * ry
                            myy += w * ry * ry
                            myz += w * ry * rz
                            by += d * ry
            # G = -M^-1 b (the kernel's constant factor cancels); exact for linear fields
            G[0, a], G[1, a], G[2, a] = tp.renormalised_gradient(mxx, mxy, mxz, myy, myz, mzz, bx, by, bz, S[KAP, a],
                                                                 gx, gy, gz, three)

    return gradient_loop


_GRADIENTS = {}


def density_gradients(S, start, tab, lo, cell, nx, ny, nz, kernel, prm, G, skip=None) -> None:
    """The renormalised density gradient ``G[:, a]`` [kg/m^4] (rows x, y, z; y = 0 in 2-D)
    of every fluid particle a, Dinçer & Demir 2020, Eq. 3-4:
    ``<grad rho>_a = L_a sum_b V_b (rho_b - rho_a) grad_a W_ab`` with
    ``L_a = [sum_b V_b r_ba (x) grad_a W_ab]^-1`` over the fluid neighbours (the paper prints
    ``r_ab``, which gives the gradient's negative with ``grad_a W_ab``; with ``r_ba = r_b -
    r_a`` it reproduces any linear field exactly). Where ``L_a`` is near singular (|det| of
    its inverse below :data:`DET_MIN` of the mean diagonal's power), the hydrostatic
    gradient ``rho_a g / c_a^2``; 0 on boundary particles (and on the ``skip`` rows).
    Arguments as :func:`interact`."""
    key = (int(kernel), bool(ny > 1))
    loop = _GRADIENTS.get(key)
    if loop is None:
        loop = _GRADIENTS[key] = _make_gradient(*key)
    with dynamic_chunks():
        loop(S, G.shape[1], start, tab, lo, cell, nx, ny, nz, prm, G, _NO_SKIP if skip is None else skip)


#: particles per chunk of the pair loops, handed to the threads as they come free: with
#: numba's default (one block per thread) a thread with the free surface or the walls in
#: its block waits for the other; 2-D dam break, 2 threads: 6.9-8.4 -> 10.2-11.9 M
#: particle-steps/s (median of 15 blocks of 30 steps, two runs each)
PAIR_CHUNK = 256


@contextmanager
def dynamic_chunks():
    """Run the enclosed parallel loops with chunks of :data:`PAIR_CHUNK` particles."""
    old = numba.set_parallel_chunksize(PAIR_CHUNK)
    try:
        yield
    finally:
        numba.set_parallel_chunksize(old)


_LOOPS = {}
#: ``near`` for a pair loop that skips no particle
_NOWHERE = np.zeros(0, np.uint8)
_NO_KINDS = np.zeros(0, np.int8)
_NO_SKIP = np.zeros(0, np.bool_)


def interact(S, start, tab, lo, cell, nx, ny, nz, kernel, prm, out, acc, xs, G, T=None, near=None, kind=None,
             walls: int = WALLS_FULL, skip=None):
    """One pass over all pairs of the ``n = acc.shape[0]`` particles; writes, for every
    particle a:

    ``out[DRHO, a]`` [kg/m^3/s] continuity rate (Eq. 7 plus diffusion), ``acc[a]``
    [m/s^2] momentum rate (Eq. 6 with artificial and, if ``nu > 0``, laminar viscosity;
    gravity added for fluid only, see module docstring), ``out[VISC, a]`` [m/s]
    ~ max_b |h v_ab.r_ab / (r_ab^2 + eta^2)| over the support for the time step
    (Sunara et al. 2021, Eq. 14) and, if ``prm[P_XSPH] > 0``, the XSPH velocity
    correction ``xs[a]`` [m/s] (fluid only; zero for boundary particles). Particles must
    be sorted by cell (``start`` and the sub-bin table ``tab`` from
    :func:`fluid.neighbours.sort_by_cell` or :func:`fluid.neighbours.x_bins`, cells ``cell``
    = 2h [m] wide); ``S`` comes from :func:`pack`; ``lo`` has 3 components (x, y, z; y = 0
    and ``ny = 1`` in 2-D).

    The inner loop is kept vectorised (packed AVX-512, 8 float64 pairs a pass): compiled per
    kernel, dimension and optional term (:func:`_make_interact`); each neighbour row trimmed to
    within 2h in x by the sub-bin table ``tab`` and padded to :data:`PAD`; one division per pair;
    masks and clamps instead of branches; the largest viscous term ``max_b |mu_ab|`` of Eq. 14
    taken as the 8-norm over the pairs (an upper bound within ``N_b^(1/8)``: a slightly
    conservative step). A boundary particle with no fluid within one cell (``near``) gets zero
    rates without a pass; tank walls whose loads nobody reads (``walls``) get only their
    continuity rate and viscous bound (:func:`wall_sums`), as DualSPHysics' fixed boundaries;
    the rows marked in ``skip`` (bool, (n,); a symmetry plane's mirror images, neighbours
    only) get zero rates without a pass: between two planes 2h apart they are two thirds
    of the rows.
    With ``precision="float32"`` every pair term is float32 (16 pairs a pass), read from the
    table ``T`` of :func:`pack_f32`, separations from in-cell offsets and densities as ``rho -
    rho0``, summed into float64 totals. Why each, and what it measured: docs/fluid_equations.md.
    """
    renorm = bool(prm[P_RENORM] > 0.0)
    f32 = bool(prm[P_F32] > 0.0)
    key = (int(kernel), bool(ny > 1), bool(prm[P_NU4] > 0.0), bool(prm[P_XSPH] > 0.0), bool(prm[P_AWALL] != 1.0),
           renorm, bool(prm[P_FADE] > 0.0), f32, bool(prm[P_G] != 0.0 or (ny > 1 and prm[P_G + 1] != 0.0)))
    loop = _LOOPS.get(key)
    if loop is None:
        loop = _LOOPS[key] = _make_interact(*key)
    if renorm and G.shape != (3, acc.shape[0]):
        raise InputError(f"interact: the renormalised diffusion needs the density gradients G (3, {acc.shape[0]}), "
                         f"got {G.shape}: density_gradients(...)")
    if f32 and T is None:
        T = np.empty((N_ROWS_F32, S.shape[1]), np.float32)
        pack_f32(S, prm[P_RHO0], lo, cell, nx, ny, nz, T)
    if walls != WALLS_FULL and (kind is None or kind.shape[0] != acc.shape[0]):
        raise InputError(f"interact: walls={walls} picks the wall particles by kind; give kind ({acc.shape[0]},)")
    with dynamic_chunks():
        loop(S, S if T is None or not f32 else T, acc.shape[0], start, tab, lo, cell, nx, ny, nz, prm, out, acc, xs, G,
             _NOWHERE if near is None else near, _NO_KINDS if kind is None else kind, walls,
             _NO_SKIP if skip is None else skip)


def require_pair_grid(grid, h: float) -> None:
    """Refuse a grid other than the pair loops' own: cells 2h wide (``h`` [m]), reach 1."""
    if grid.reach != 1 or abs(grid.cell - 2.0 * h) > 1e-12 * grid.cell:
        raise InputError(f"the pair loop needs a grid of cells 2h = {2.0 * h} m wide with reach 1, got "
                         f"cell {grid.cell} m, reach {grid.reach}: Grid.covering(lo, hi, 2 * h)")


class Workspace:
    """Arrays :func:`evaluate` reuses from call to call (allocating and first touching a
    few MB per step costs as much as the equation of state)."""

    def __init__(self):
        self.arrays = {}

    def get(self, name: str, shape, dtype=np.float64) -> np.ndarray:
        a = self.arrays.get(name)
        if a is None or a.shape != tuple(shape) or a.dtype != dtype:
            a = self.arrays[name] = np.empty(shape, dtype)
        return a



class Rates(NamedTuple):
    """What :func:`evaluate` returns; every array in the particles' current order."""

    drho: np.ndarray  # (N,) [kg/m^3/s]
    acc: np.ndarray  # (N, dim) [m/s^2]
    visc: np.ndarray  # (N,) [m/s] the viscous term of the time-step condition
    cs: np.ndarray  # (N,) [m/s] sound speed
    xsph: np.ndarray | None  # (N, dim) [m/s] XSPH velocity correction; None when off


def evaluate(pos, vel, rho, mass, kind, start, grid, kernel: int, prm, rho0: float, c0: float,
             gamma: float, p, work: Workspace | None = None, xbins: np.ndarray | None = None,
             near: np.ndarray | None = None, walls: int = WALLS_FULL, images=None,
             skip: np.ndarray | None = None) -> Rates:
    """EOS and all pair rates of particles sorted by cell on ``grid``. Writes the pressure
    into ``p`` [Pa]. With a ``work`` space the returned arrays are its own and are
    overwritten by the next call with it. ``xbins``: the sub-bin table that
    ``sort_by_cell(pos, grid, xbins)`` filled with ``start`` (tabulated here if not given).
    ``near``: the cells near the fluid (:func:`fluid.neighbours.fluid_near_cells`); the
    boundary particles of the other cells get zero rates without a pass over their
    neighbours (what the pass would give); None: every particle is passed over.
    ``walls``: what the tank-wall particles get (:data:`WALLS_FULL`, :data:`WALLS_CONTINUITY`,
    :data:`WALLS_NONE`); their other rates are zero. ``images``: a symmetry plane's
    :class:`fluid.mirror.Mirror`, which gives its images the first pass's density gradients
    of their sources before the pair loop reads them as neighbours. ``skip``: rows whose
    rates are not wanted (bool, (n,); the images), zero without a pass."""
    n, dim = pos.shape
    work = Workspace() if work is None else work
    S = work.get("S", (N_ROWS, n))
    pack(pos, vel, rho, mass, kind, rho0, c0, gamma, p, S)
    out = work.get("out", (2, n))
    acc = work.get("acc", (n, dim))
    xsph = prm[P_XSPH] > 0.0
    xs = work.get("xsph", (n, dim)) if xsph else work.get("xsph0", (0, dim))
    lo = grid.lo3
    nx, ny, nz = grid.shape
    require_pair_grid(grid, prm[P_H])
    tab = x_bins(S[X], start, grid) if xbins is None else xbins
    if prm[P_RENORM] > 0.0:
        G = work.get("grad", (3, n))
        density_gradients(S, start, tab, lo, grid.cell, nx, ny, nz, kernel, prm, G, skip)
        if images is not None:
            images.reflect_rows(G)
    else:
        G = work.get("grad0", (3, 0))
    T = None
    if prm[P_F32] > 0.0:
        T = work.get("T", (N_ROWS_F32, n), np.float32)
        pack_f32(S, rho0, lo, grid.cell, nx, ny, nz, T)
    interact(S, start, tab, lo, grid.cell, nx, ny, nz, kernel, prm, out, acc, xs, G, T, near, kind, walls, skip)
    return Rates(out[DRHO], acc, out[VISC], S[CS], xs if xsph else None)


@njit(parallel=True, **_OPTS)
def _boundary_pressure(S, p, start, lo, inv_cell, nx, ny, nz, h, out):
    n = p.shape[0]
    three = ny > 1
    dys = 3 if three else 1
    R2 = 4.0 * h * h
    for a in prange(n):
        if S[ISF, a] > 0.5:
            out[a] = p[a]
            continue
        xa = S[X, a]
        ya = S[Y, a]
        za = S[Z, a]
        cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, True, nx, ny, nz)  # packed rows: always x, y, z
        num = 0.0
        den = 0.0
        for dz in range(-1, 2):
            for k in range(dys):
                dy = k - 1 if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, 1)
                for b in range(j0, j1):
                    rx = xa - S[X, b]
                    ry = ya - S[Y, b]
                    rz = za - S[Z, b]
                    r2 = rx * rx + ry * ry + rz * rz
                    if S[ISF, b] > 0.5 and r2 < R2:
                        w = 1.0 / math.sqrt(r2)
                        num += w * p[b]
                        den += w
        out[a] = num / den if den > 0.0 else 0.0


def boundary_pressure(pos, vel, rho, mass, kind, start, grid, rho0: float, c0: float,
                      gamma: float) -> np.ndarray:
    """Pressure [Pa] for reporting at every particle: fluid particles their own; boundary
    particles the inverse-distance average of the fluid pressures within the support 2h,
    ``P_a = sum_b (P_b / |r_b - r_a|) / sum_b (1 / |r_b - r_a|)``
    (Sunara et al. 2021, Eq. 15); 0 for a boundary particle with no fluid near it.
    Particles sorted by cell on ``grid`` (reach 1, cell 2h)."""
    n, dim = pos.shape
    S = np.empty((N_ROWS, n))
    p = np.empty(n)
    pack(pos, vel, rho, mass, kind, rho0, c0, gamma, p, S)
    lo = grid.lo3
    out = np.empty(n)
    nx, ny, nz = grid.shape
    _boundary_pressure(S, p, start, lo, 1.0 / grid.cell, nx, ny, nz, 0.5 * grid.cell * grid.reach, out)
    return out
