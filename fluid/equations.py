"""Weakly-compressible SPH rates: continuity with density diffusion, momentum with
artificial viscosity and gravity, Tait equation of state, dynamic boundaries.

All pair loops gather: thread ``a`` writes only particle ``a``'s rates. The loop over
neighbours has no branch on the pair (kernel factors are clamped at the support edge,
pair masks are 0/1 factors), the self pair contributes exactly zero because every term
carries ``r_ab`` or ``v_ab``. Symbols follow the papers: ``a`` the particle, ``b`` its
neighbour, ``r_ab = r_a - r_b``, ``v_ab = v_a - v_b``, ``grad_a W_ab = F_ab r_ab``.

Equations
---------
* Continuity, 004_1657bd4a51d29840.txt Eq. 7:
  ``drho_a/dt = sum_b m_b v_ab . grad_a W_ab + D_a``.
* Density diffusion ``D_a = delta h c0 sum_b (m_b/rho_b) psi_ab . grad_a W_ab`` with
  ``psi_ab = 2 (rho_b - rho_a - rho^H_ba) r_ba / (|r_ab|^2 + eta^2)``:

  - ``"molteni"``: Molteni & Colagrossi (2009), ``rho^H = 0``; this is
    000_7d114ab96e048b26.txt Eq. 1-2 without the renormalised density gradients of
    Eq. 3-4 (Antuono et al.), which would cost a second pair loop and a matrix inversion
    per particle.
  - ``"fourtakas"`` (default): Fourtakas et al. (2019, Comput. Fluids 190), as DualSPHysics'
    DDT2: the hydrostatic part of the density difference is removed,
    ``rho^H_ba = rho0 [(1 + rho0 g.(r_b - r_a)/B)^(1/gamma) - 1]``. We use it linearised
    and with the local density and sound speed, ``rhobar_ab g.(r_b - r_a) / c_ab^2``
    (``rho/c^2`` averaged over the pair): at the surface this is Fourtakas' term, at depth
    it follows the compressed fluid, where Fourtakas' form (referred to rho0, c0) leaves a
    residual of order 1 - (rho/rho0)^(2-gamma) (1.5 % of the Molteni term at p/B = 0.02);
    the dropped quadratic term is below 1e-7 rho0 for any pair within 2h. Why default: in a fluid at rest under gravity the
    Molteni term is not zero (density grows with depth) and drives a spurious mass flux
    upwards that distorts the hydrostatic pressure near the bottom and the free surface;
    Fourtakas' term vanishes exactly for the hydrostatic state, costs no extra loop, and
    is the DualSPHysics variant the speed comparison is made against. Diffusion acts
    between fluid particles only.
  - ``"none"``.
* Momentum, 004_1657bd4a51d29840.txt Eq. 6 (001_14936b82710365b2.txt Eq. 5):
  ``dv_a/dt = -sum_b m_b (P_a/rho_a^2 + P_b/rho_b^2 + Pi_ab) grad_a W_ab + g``.
* Artificial viscosity, 001_14936b82710365b2.txt Eq. 6 (Monaghan 1992):
  ``Pi_ab = -alpha cbar_ab mu_ab / rhobar_ab`` if ``v_ab . r_ab < 0`` else 0,
  ``mu_ab = h v_ab . r_ab / (r_ab^2 + eta^2)``, ``eta^2 = 0.01 h^2``.
* Tait equation of state, 004_1657bd4a51d29840.txt Eq. 8 with
  ``B = c0^2 rho0 / gamma`` (001_14936b82710365b2.txt Eq. 8); sound speed
  ``c = c0 (rho/rho0)^((gamma-1)/2)``.
* Dynamic boundaries, 004_1657bd4a51d29840.txt §2.6: boundary particles obey the
  continuity equation (summed over fluid neighbours; boundary-boundary pairs are masked),
  their pressure follows from the same equation of state, their motion is prescribed.
  Their "acceleration" computed here is the force per unit mass the fluid exerts on
  them (no gravity): ``m_a dv_a/dt`` summed over a group is the fluid load on that group,
  exactly the negative of what the group exerts on the fluid since every pair term is
  antisymmetric.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from fluid.kernels import WENDLAND, grad_factor
from fluid.neighbours import cell_coords, row_range

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")

#: indices into the float parameter vector ``prm`` of :func:`interact`
P_H, P_AD, P_ALPHA, P_DDT, P_HYDRO, P_RHO0, P_C0, P_G = 0, 1, 2, 3, 4, 5, 6, 7
N_PRM = 10

DIFFUSION = ("fourtakas", "molteni", "none")


def params(h, ad, alpha, delta, diffusion, rho0, c0, g) -> np.ndarray:
    """Pack the parameters of :func:`interact`.

    h [m] smoothing length, ad [1/m^dim] kernel normalisation, alpha [-] artificial
    viscosity, delta [-] density-diffusion coefficient, diffusion one of
    :data:`DIFFUSION`, rho0 [kg/m^3], c0 [m/s], g [m/s^2] gravity vector (dim,).
    """
    prm = np.zeros(N_PRM)
    prm[P_H], prm[P_AD], prm[P_ALPHA] = h, ad, alpha
    prm[P_DDT] = 0.0 if diffusion == "none" else 2.0 * delta * h * c0
    prm[P_HYDRO] = 1.0 if diffusion == "fourtakas" else 0.0
    prm[P_RHO0], prm[P_C0] = rho0, c0
    g = np.asarray(g, np.float64)
    prm[P_G:P_G + g.size] = g
    return prm


def tait_B(rho0: float, c0: float, gamma: float) -> float:
    """Tait stiffness B = c0^2 rho0 / gamma [Pa] (004_1657bd4a51d29840.txt Eq. 8)."""
    return c0 * c0 * rho0 / gamma


@njit(parallel=True, **_OPTS)
def equation_of_state(rho, rho0, c0, gamma, p, cs):
    """Tait EOS (004_1657bd4a51d29840.txt Eq. 8): pressure ``p`` [Pa] and sound speed
    ``cs`` [m/s] of every particle from its density [kg/m^3]."""
    B = c0 * c0 * rho0 / gamma
    e = 0.5 * (gamma - 1.0)
    for i in prange(rho.shape[0]):
        x = rho[i] / rho0
        p[i] = B * (x ** gamma - 1.0)
        cs[i] = c0 * x ** e


@njit(parallel=True, **_OPTS)
def pair_terms(rho, mass, p, cs, kind, aux):
    """Per-particle factors the pair loop reads, so that it divides only once per pair:
    ``aux[:, 0] = p / rho^2``, ``aux[:, 1] = m / rho``, ``aux[:, 2] = rho / c^2``,
    ``aux[:, 3] = 1`` for fluid, 0 for boundary particles."""
    for i in prange(rho.shape[0]):
        r = rho[i]
        aux[i, 0] = p[i] / (r * r)
        aux[i, 1] = mass[i] / r
        aux[i, 2] = r / (cs[i] * cs[i])
        aux[i, 3] = 1.0 if kind[i] == 0 else 0.0


def hydrostatic_density(depth, rho0: float, c0: float, gamma: float, g: float) -> np.ndarray:
    """Density [kg/m^3] whose Tait pressure is ``rho0 g depth`` (depth [m] below the free
    surface, clipped at 0): the rest state a hydrostatic set-up starts from."""
    B = tait_B(rho0, c0, gamma)
    return rho0 * (1.0 + rho0 * g * np.maximum(depth, 0.0) / B) ** (1.0 / gamma)


@njit(parallel=True, **_OPTS)
def interact(pos, vel, rho, mass, cs, aux, start, lo, inv_cell, nx, ny, nz, kernel, prm,
             drho, acc, visc):
    """One pass over all pairs; writes, for every particle a,

    ``drho[a]`` [kg/m^3/s] continuity rate (Eq. 7 plus diffusion), ``acc[a]`` [m/s^2]
    momentum rate (Eq. 6; gravity added for fluid only, see module docstring) and
    ``visc[a]`` [m/s] = max_b |h v_ab.r_ab / (r_ab^2 + eta^2)| for the time step
    (001_14936b82710365b2.txt Eq. 14). Particles must be sorted by cell (``start`` from
    :func:`fluid.neighbours.sort_by_cell`); ``aux`` comes from :func:`pair_terms`.
    """
    n = pos.shape[0]
    dim = pos.shape[1]
    three = dim == 3
    zc = dim - 1
    dys = 3 if three else 1
    h = prm[P_H]
    ad = prm[P_AD]
    alpha = prm[P_ALPHA]
    ddt = prm[P_DDT]
    hydro = prm[P_HYDRO]
    gx = prm[P_G]
    gy = prm[P_G + 1] if three else 0.0
    gz = prm[P_G + zc]
    eta2 = 0.01 * h * h
    for a in prange(n):
        xa = pos[a, 0]
        za = pos[a, zc]
        ya = pos[a, 1] if three else 0.0
        ux = vel[a, 0]
        uz = vel[a, zc]
        uy = vel[a, 1] if three else 0.0
        rhoa = rho[a]
        pa = aux[a, 0]
        ka = aux[a, 2]
        fa = aux[a, 3]
        ca = cs[a]
        cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, three, nx, ny, nz)
        sd = 0.0
        sdd = 0.0
        sx = 0.0
        sy = 0.0
        sz = 0.0
        vmax = 0.0
        for dz in range(-1, 2):
            for k in range(dys):
                dy = k - 1 if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start)
                for b in range(j0, j1):
                    rx = xa - pos[b, 0]
                    rz = za - pos[b, zc]
                    ry = (ya - pos[b, 1]) if three else 0.0
                    r2 = rx * rx + ry * ry + rz * rz
                    q = math.sqrt(r2) / h
                    F = grad_factor(kernel, q, ad, h)
                    fb = aux[b, 3]
                    mask = max(fa, fb)  # boundary-boundary pairs do not interact
                    vx = ux - vel[b, 0]
                    vz = uz - vel[b, zc]
                    vy = (uy - vel[b, 1]) if three else 0.0
                    vr = vx * rx + vy * ry + vz * rz
                    mb = mass[b] * mask
                    rhob = rho[b]
                    inv = 1.0 / (r2 + eta2)
                    # continuity (Eq. 7)
                    sd += mb * vr * F
                    # density diffusion, fluid-fluid pairs: psi_ab . grad W = -2 drho F r^2/(r^2+eta^2)
                    rhoH = -0.5 * hydro * (ka + aux[b, 2]) * (gx * rx + gy * ry + gz * rz)
                    sdd += (fa * fb * aux[b, 1]) * (rhob - rhoa - rhoH) * F * r2 * inv
                    # momentum (Eq. 6) with artificial viscosity (001 Eq. 6)
                    mu = h * min(vr, 0.0) * inv
                    Pi = -alpha * (ca + cs[b]) * mu / (rhoa + rhob)
                    coef = -mb * (pa + aux[b, 0] + Pi) * F
                    sx += coef * rx
                    sy += coef * ry
                    sz += coef * rz
                    vmax = max(vmax, mask * abs(h * vr * inv))
        drho[a] = sd - ddt * sdd
        acc[a, 0] = sx + fa * gx
        acc[a, zc] = sz + fa * gz
        if three:
            acc[a, 1] = sy + fa * gy
        visc[a] = vmax
