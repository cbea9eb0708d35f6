"""Linear (potential-flow) sloshing of a rigid tank under horizontal base acceleration: the
reference of the long-period cases of Sunara et al. 2021 (§3.1-3.3, T_p =
1.0 s and 0.7 s), where the paper shows pressures but no numbers.

Set-up. A tank of depth ``h`` [m] (still surface z = 0, bottom z = -h) moves along x with
acceleration a(t) [m/s^2]. In the tank's frame the water feels the extra body force -a(t)
along x; with the relative velocity potential phi (velocity relative to the walls = grad
phi, no flow through the walls and the bottom), linearised Bernoulli gives

    p = -rho (phi_t + g z + a x),     eta = -(phi_t + a x) / g  at z = 0,

and the kinematic condition eta_t = phi_z. Expanding phi over the tank's sloshing modes
psi_n = S_n(x, y) cosh(k_n (z + h)) / cosh(k_n h), whose surface shapes S_n satisfy the
wall condition, and the coordinate x = sum_n b_n S_n over the free surface, each mode's
surface amplitude eta_n(t) (eta = sum_n eta_n S_n) obeys

    eta_n'' + w_n^2 eta_n = -(w_n^2 b_n / g) a(t),       w_n^2 = g k_n tanh(k_n h),

(a constant a gives eta_n = -b_n a / g: the surface tilted to -a x / g), and the pressure
``p = -rho g z + rho sum_n (g eta_n + b_n a) psi_n - rho a x``.

The last two terms together are the impulsive pressure (zero at the surface, Westergaard's
finite-tank series at a wall); the g eta_n terms the convective (sloshing) pressure. Housner's
analogue (TID-7024) keeps the first mode with an approximate w_1 (refdata
analytic_hydrodynamics/sloshing_frequencies_housner.csv gives both).

Tanks (refdata analytic_hydrodynamics/SOURCE.txt, C):

- rectangular, length L along x, x from the centre: S_n = sin(k_n x), k_n = (2n - 1) pi / L,
  b_n = (4 / L) (-1)^(n+1) / k_n^2 (the odd modes; a horizontal motion excites no even one).
- vertical cylinder, radius R, polar angle theta from +x: S_n = J1(k_n r) cos(theta),
  k_n = xi_n / R with J1'(xi_n) = 0, b_n = 2 R / ((xi_n^2 - 1) J1(xi_n)) (the Dini series of r).
- 2-D tank with its right side inclined beta from the vertical (Sunara et al. 2021, §3.2): no
  closed form; the P1 FEM modes psi_n of :func:`cosim.validations.tank_potential.sloshing_modes`,
  b_n = S_n^T M_s x (M_s the surface's mass matrix, S_n^T M_s S_n = 1, x from the surface's middle).

The excitation is the paper's, a0 sin(w t) from rest (Sunara et al. 2021, Fig. 3), held for
``t_stop`` [s] and zero after it: eta_n in closed form, then free oscillation (linear,
inviscid: no damping).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import special


@dataclass(frozen=True)
class Modes:
    """The first modes of a tank: wavenumbers ``k`` [1/m] (the inclined tank, whose modes
    have none: the wavenumber of each mode's frequency in water ``h`` deep, omega^2 =
    g k tanh(k h)), frequencies ``omega`` [rad/s],
    coefficients ``b`` [m] of x = sum b_n S_n, depth ``h`` [m], the tank's ``shape``
    ("rectangular" with ``size`` = L, or "cylinder" with ``size`` = R) and g [m/s^2]."""

    shape: str
    size: float
    h: float
    k: np.ndarray
    omega: np.ndarray
    b: np.ndarray
    g: float
    #: the inclined tank's FE modes (:func:`trapezoid_modes`); None for the closed forms
    fe: dict | None = None

    def surface_shapes(self, x, y=None) -> np.ndarray:
        """S_n at points (tank frame: x from the centre [m]; y across [m], the cylinder
        only): shape (modes, points)."""
        x = np.atleast_1d(np.asarray(x, float))
        if self.fe is not None:
            return self.psi(x, np.zeros_like(x))
        if self.shape == "rectangular":
            return np.sin(np.outer(self.k, x))
        y = np.zeros_like(x) if y is None else np.atleast_1d(np.asarray(y, float))
        r = np.hypot(x, y)
        cos_t = np.divide(x, r, out=np.zeros_like(x), where=r > 0)
        return special.j1(np.outer(self.k, r)) * cos_t

    def psi(self, x, z, y=None) -> np.ndarray:
        """The modes' potentials psi_n at points (x from the centre, z <= 0 below the still
        surface [m]): (modes, points)."""
        if self.fe is None:
            return self.surface_shapes(x, y) * self.depth_factor(z)
        fe = self.fe
        x = np.atleast_1d(np.asarray(x, float)) + fe["x_mid"]
        zz = np.clip(np.atleast_1d(np.asarray(z, float)) + self.h, 0.0, self.h)
        sx = np.clip(x / (fe["length"] + zz * fe["tan_beta"]), 0.0, 1.0)    # the mapped grid's coordinates
        out = np.empty((self.omega.size, x.size))
        for i, q in enumerate(fe["grid"]):
            out[i] = q(np.column_stack([zz, sx]))
        return out

    def depth_factor(self, z) -> np.ndarray:
        """cosh(k_n (z + h)) / cosh(k_n h) at heights z <= 0 [m] below the still surface:
        (modes, points); written with exponentials, finite for any k h."""
        z = np.atleast_1d(np.asarray(z, float))
        kz, kh = np.outer(self.k, z + self.h), (self.k * self.h)[:, None]
        return (np.exp(kz - kh) + np.exp(-kz - kh)) / (1.0 + np.exp(-2.0 * kh))


def rectangular_modes(L: float, h: float, n: int = 200, g: float = 9.81) -> Modes:
    """The ``n`` odd modes of a rectangular tank ``L`` [m] long, water ``h`` [m] deep."""
    j = np.arange(1, n + 1)
    k = (2 * j - 1) * math.pi / L
    return Modes("rectangular", L, h, k, np.sqrt(g * k * np.tanh(k * h)),
                 (4.0 / L) * (-1.0) ** (j + 1) / k**2, g)


def cylinder_modes(R: float, h: float, n: int = 200, g: float = 9.81) -> Modes:
    """The ``n`` first cos(theta) modes of a vertical cylinder of radius ``R`` [m], water
    ``h`` [m] deep (xi_n: the zeros of J1', scipy.special.jnp_zeros)."""
    xi = special.jnp_zeros(1, n)
    k = xi / R
    return Modes("cylinder", R, h, k, np.sqrt(g * k * np.tanh(k * h)), 2.0 * R / ((xi**2 - 1) * special.j1(xi)), g)


def trapezoid_modes(L: float, h: float, beta_deg: float, n: int = 30, nz: int = 40, g: float = 9.81) -> Modes:
    """The ``n`` first modes of the 2-D tank with a bottom ``L`` [m] long, a vertical left
    side and the right side inclined ``beta_deg`` from the vertical, water ``h`` [m] deep
    (:func:`cosim.validations.tank_potential.sloshing_modes`, ``nz`` elements over the
    depth). x is measured from the middle of the still surface, (L + h tan beta) / 2 from
    the left wall."""
    from scipy.interpolate import RegularGridInterpolator

    from cosim.validations.tank_potential import sloshing_modes

    sm = sloshing_modes(L, h, beta_deg, n, nz)
    nodes, nz, nx, top = sm["nodes"], sm["nz"], sm["nx"], sm["top"]
    tb = math.tan(math.radians(beta_deg))
    x_mid = 0.5 * (L + h * tb)
    surf = sm["phi"][:, top]
    b = surf @ sm["surface_mass"] @ (nodes[top, 0] - x_mid)
    zs, ss = np.linspace(0.0, h, nz + 1), np.linspace(0.0, 1.0, nx + 1)
    grid = [RegularGridInterpolator((zs, ss), p.reshape(nz + 1, nx + 1)) for p in sm["phi"]]
    lam = sm["lam"]  # omega^2 / g
    return Modes("trapezoid", L, h, depth_wavenumber(lam, h), np.sqrt(g * lam), b, g,
                 fe={"x_mid": x_mid, "length": L, "tan_beta": tb, "grid": grid, "beta_deg": beta_deg})


def depth_wavenumber(lam, h: float) -> np.ndarray:
    """The wavenumbers k [1/m] with k tanh(k h) = ``lam`` [1/m] (omega^2 / g) in water ``h``
    [m] deep (the dispersion relation), by Newton's method from the larger of the deep and
    the shallow water's k (both lie below the root: tanh(k h) < 1 and < k h); a handful of
    iterations to round-off."""
    lam = np.atleast_1d(np.asarray(lam, float))
    k = np.maximum(lam, np.sqrt(lam / h))
    for _ in range(60):
        t = np.tanh(k * h)
        step = (k * t - lam) / (t + k * h * (1.0 - t * t))
        k = k - step
        if np.all(np.abs(step) <= 1e-15 * k):
            return k
    raise ArithmeticError(f"depth_wavenumber: Newton's method did not settle for lam = {lam}, h = {h}")


def housner_omega1(shape: str, size: float, h: float, g: float = 9.81) -> float:
    """Housner's first sloshing frequency [rad/s] (TID-7024; the formulas of refdata
    sloshing_frequencies_housner.csv): rectangular ``size`` = L, w^2 = (g/l) sqrt(5/2)
    tanh(sqrt(5/2) h/l), l = L/2; cylinder ``size`` = R, w^2 = 1.837 (g/R) tanh(1.837 h/R)."""
    if shape == "rectangular":
        l = 0.5 * size
        return math.sqrt(g / l * math.sqrt(2.5) * math.tanh(math.sqrt(2.5) * h / l))
    return math.sqrt(1.837 * g / size * math.tanh(1.837 * h / size))


def response(modes: Modes, a0: float, period: float, t_stop: float, t) -> tuple[np.ndarray, np.ndarray]:
    """Modal surface amplitudes eta_n(t) [m] (modes, times) and the acceleration a(t)
    [m/s^2] for a(t) = a0 sin(2 pi t / period) on 0 <= t <= t_stop, 0 after (from rest)."""
    t = np.atleast_1d(np.asarray(t, float))
    w, wn = 2 * math.pi / period, modes.omega[:, None]
    F = -(modes.omega**2 * modes.b * a0 / modes.g)[:, None]
    den = wn**2 - w**2
    if np.any(np.abs(den) < 1e-9 * w**2):
        raise ValueError(f"the excitation period {period} s is a natural period of the tank: the linear response "
                         "grows without bound")

    def forced(tt):
        return F * (np.sin(w * tt) - (w / wn) * np.sin(wn * tt)) / den, F * w * (np.cos(w * tt) - np.cos(wn * tt)) / den

    tf = np.minimum(t, t_stop)[None, :]
    eta, deta = forced(tf)
    tau = np.maximum(t - t_stop, 0.0)[None, :]
    e0, d0 = forced(np.array([[t_stop]]))
    free = e0 * np.cos(wn * tau) + d0 / wn * np.sin(wn * tau)
    eta = np.where(tau > 0, free, eta)
    a = np.where(t <= t_stop, a0 * np.sin(w * t), 0.0)
    return eta, a


def surface(modes: Modes, eta_n: np.ndarray, x, y=None) -> np.ndarray:
    """Free-surface elevation [m] (points, times) from the modal amplitudes."""
    return modes.surface_shapes(x, y).T @ eta_n


def pressure(modes: Modes, eta_n: np.ndarray, a: np.ndarray, x, z, y=None, rho: float = 1000.0) -> np.ndarray:
    """Total pressure [Pa] (points, times) at points (x, [y,] z) of the water (tank frame,
    z <= 0 below the still surface): hydrostatic + convective + impulsive (module docstring)."""
    x = np.atleast_1d(np.asarray(x, float))
    z = np.atleast_1d(np.asarray(z, float))
    psi = modes.psi(x, z, y)                                               # (modes, points)
    conv = modes.g * psi.T @ eta_n                                         # (points, times)
    imp = (psi.T @ modes.b)[:, None] - x[:, None]                       # x = r cos(theta) in the cylinder
    return rho * (-modes.g * z[:, None] + conv + imp * a[None, :])
