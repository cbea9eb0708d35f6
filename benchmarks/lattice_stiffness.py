"""Lattice stiffness of the SPH fluid under pressure: a candidate for the part of the
first sloshing mode's +4.5 % at the default h = sqrt(2) dx that is not in the walls
(cosim.validations.sloshing, sloshing_frequency, which runs at h = 2 dx for it), and the
stability of the particle lattice at rest.

1. Closed box. A closed 2-D box L x H = 1 x 0.5 m (3 wall layers, ``walls="adami"``) is
filled on the lattice at a uniform pressure p0 [Pa], no gravity, and the fluid particles
are displaced by the divergence-free field of the stream function
``psi = A sin(pi x / L) sin(pi z / H)`` (zero normal displacement at the walls),
A = 1e-3 dx. The densities are kept (a real fluid: no volume change, so no pressure
change), and the rates are taken once. The restoring acceleration a projected on the
displacement u,

    omega^2 = -sum a . u / sum u . u   [rad^2/s^2],

is zero for a fluid; for the SPH fluid it is not. With uniform pressure the momentum
equation (Barreiro et al. 2016, Eq. 6) reduces to ``-(2 p0 / rho^2) grad_a sum_b m_b
W_ab``: the gradient of the kernel sum of the displaced particles, which for a smooth
divergence-free displacement vanishes in the continuum but not on the lattice, by a
factor set by the kernel and h/dx only. So omega^2 grows in proportion to p0 and does
not change with dx (``c (p0 / rho) k^2`` with k^2 = (pi/L)^2 + (pi/H)^2 and c ~ 0.04 for
Wendland at h = sqrt(2) dx): a pressure-borne shear stiffness (or, negative, an
instability) of the particle lattice.

2. The sloshing mode (``--sloshing``): the tank of sloshing-frequency (L = 1 m, water
0.5 m, hydrostatic densities, walls="adami"), its fluid displaced by the linear first
mode, ``u = A grad(cos(k x) cosh(k z))``, k = pi / L, densities kept: the same Rayleigh
quotient of the change of the rates, against linear theory ``g k tanh(k h)``. This is the
static stiffness of the particle configuration alone (the dynamic frequency also has the
density response, which the motion adjusts to).

3. Stability of the lattice (``--stability``): the same stiffness for every wavelength on
the infinite square (cubic) lattice, from Bloch modes (:func:`lattice_stability`); where the
pressure-borne term is negative the lattice under pressure rearranges, whatever the damping.

    python benchmarks/lattice_stiffness.py [--h-coef C] [--kernel cubic] [--dx DX] [--sloshing | --stability]

Measured stiffnesses and the h / dx stability scan: docs/benchmarks/lattice_stiffness.md.
"""

from __future__ import annotations

import argparse
import math
import os
import sys

import numpy as np

_here = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _here]


def omega2(dx: float, p0: float, h_coef: float = math.sqrt(2.0), kernel: str = "wendland",
           amplitude: float = 1e-3, L: float = 1.0, H: float = 0.5) -> float:
    """omega^2 [rad^2/s^2] of the divergence-free displacement (module docstring) at
    pressure ``p0`` [Pa]; ``amplitude`` in units of dx."""
    from fluid.equations import tait_B
    from fluid.geometry import assemble, block, tank_walls
    from fluid.particles import Kind
    from fluid.solver import Fluid, FluidConfig

    lo, hi = np.zeros(2), np.array([L, H])
    ps = assemble(2, dx, 1000.0, block(lo, hi, dx),
                  [(tank_walls(lo, hi, dx, 3, open_top=False), Kind.FIXED_WALL, 0)]).particles
    cfg = FluidConfig(dim=2, dx=dx, c0=22.1, g=0.0, walls="adami", h_coef=h_coef, kernel=kernel)
    ps.rho[:] = 1000.0 * (1 + p0 / tait_B(1000.0, cfg.speed_of_sound, cfg.gamma)) ** (1 / cfg.gamma)
    fl = np.flatnonzero(ps.kind == Kind.FLUID)
    x, z = ps.pos[fl, 0], ps.pos[fl, 1]
    A = amplitude * dx
    u = np.stack([A * math.pi / H * np.sin(math.pi * x / L) * np.cos(math.pi * z / H),
                  -A * math.pi / L * np.cos(math.pi * x / L) * np.sin(math.pi * z / H)], axis=1)
    ps.pos[fl] += u
    ids = ps.ids[fl]
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    where = np.argsort(f.ps.ids)
    a = f._acc[where][np.searchsorted(f.ps.ids[where], ids)]
    return float(-(a * u).sum() / (u * u).sum())


def sloshing_rayleigh(dx: float, h_coef: float = math.sqrt(2.0), kernel: str = "wendland",
                      walls: str = "adami", L: float = 1.0, h: float = 0.5) -> tuple[float, float]:
    """(omega^2 of the particle configuration for the linear first sloshing mode, linear
    theory g k tanh(k h)) [rad^2/s^2] (module docstring, 2.)."""
    from cosim.validations.sloshing import G, RHO0, _moving_tank
    from fluid.geometry import set_hydrostatic
    from fluid.solver import Fluid, FluidConfig

    k = math.pi / L
    acc = []
    for shift in (False, True):
        ps = _moving_tank(2, dx, L, h, 1.5 * h)
        cfg = FluidConfig(dim=2, dx=dx, u_max=math.sqrt(G * h), c0_factor=10.0, walls=walls, h_coef=h_coef,
                          kernel=kernel)
        set_hydrostatic(ps, h, RHO0, cfg.speed_of_sound, cfg.gamma, cfg.g)
        fl = np.flatnonzero(ps.kind == 0)
        x, z = ps.pos[fl, 0], ps.pos[fl, 1]
        u = 1e-3 * dx * np.stack([-np.sin(k * x) * np.cosh(k * z), np.cos(k * x) * np.sinh(k * z)], 1) / math.sinh(k * h)
        if shift:
            ps.pos[fl] += u
        ids = ps.ids[fl]
        f = Fluid(cfg, ps)
        f.initialize(0.0)
        where = np.argsort(f.ps.ids)
        acc.append(f._acc[where][np.searchsorted(f.ps.ids[where], ids)])
    return float(-((acc[1] - acc[0]) * u).sum() / (u * u).sum()), G * k * math.tanh(k * h)


def _kernel_derivatives(q, kernel: str):
    """dW/dq and d2W/dq2 of the kernel's shape (fluid.kernels, unnormalised)."""
    if kernel == "wendland":  # (1 - q/2)^4 (2q + 1), support 2h
        t = np.clip(1 - q / 2, 0, None)
        return -5 * q * t**3, -5 * t**3 + 7.5 * q * t**2
    if kernel == "cubic":  # 1 - 1.5 q^2 + 0.75 q^3 (q < 1), 0.25 (2 - q)^3 (q < 2)
        d1 = np.where(q < 1, -3 * q + 2.25 * q * q, np.where(q < 2, -0.75 * (2 - q) ** 2, 0.0))
        d2 = np.where(q < 1, -3 + 4.5 * q, np.where(q < 2, 1.5 * (2 - q), 0.0))
        return d1, d2
    raise ValueError(f"kernel {kernel!r}: use 'wendland' or 'cubic'")


def lattice_stability(dim: int, h_coef: float, kernel: str = "wendland", n: int = 24):
    """Linear stability of the square (cubic) particle lattice of the SPH fluid under a
    uniform pressure p0, infinite and without gravity (module docstring, 3.).

    Bloch modes u_a = U exp(i k . R_a) of the momentum equation (Barreiro et al. 2016,
    Eq. 6) with the continuity equation (Eq. 7) and p = p0 + c0^2 (rho - rho0) give
    ``omega^2 U = (2 p0 / rho0) V D(k) U + V^2 (c0^2 - 2 p0 / rho0) S (S . U)`` with
    ``D(k) = sum_R (1 - cos k.R) Hess W(R)`` and ``S(k) = sum_R sin(k.R) grad W(R)``.
    The second term is the acoustic one (c0^2 >> p0 / rho0): modes with S . U != 0 are
    stiff. The others change no density, and only the pressure-borne ``D`` holds them:
    the lattice is stable if D is positive on the plane normal to S for every k. (In the
    continuum D = k k^T: a uniform pressure has no shear stiffness, 0 on that plane.)

    Returns (the smallest eigenvalue of D on that plane, divided by |k|^2 [in units of the
    kernel shape, lattice spacing 1], over the short waves |k| >= pi / (4 dx) (wavelengths
    of 8 dx and less, whose growth, ~ |k|, is fast); the k [pi / dx] where it occurs; the
    same over the long waves). Scan of the Brillouin zone on an (n + 1)^dim grid."""
    import itertools

    m = int(math.ceil(2 * h_coef)) + 1
    R = np.array([p for p in itertools.product(range(-m, m + 1), repeat=dim) if any(p)], float)
    r = np.linalg.norm(R, axis=1)
    d1, d2 = _kernel_derivatives(r / h_coef, kernel)
    d1, d2 = d1 / h_coef, d2 / h_coef**2
    e = R / r[:, None]
    ee = e[:, :, None] * e[:, None, :]
    hess = d2[:, None, None] * ee + (d1 / r)[:, None, None] * (np.eye(dim) - ee)
    grad = d1[:, None] * e
    worst, where, worst_long = math.inf, None, math.inf
    ks = np.linspace(0.0, math.pi, n + 1)
    for k in itertools.product(ks, repeat=dim):
        k = np.asarray(k)
        if not k.any():
            continue
        D = ((1 - np.cos(R @ k))[:, None, None] * hess).sum(axis=0)
        S = (np.sin(R @ k)[:, None] * grad).sum(axis=0)
        if np.linalg.norm(S) > 1e-9 * np.abs(D).max():
            basis = np.linalg.qr(np.c_[S, np.eye(dim)])[0][:, 1:dim]  # the plane normal to S
            D = basis.T @ D @ basis
        lam = np.linalg.eigvalsh(D).min() / (k @ k)
        if k @ k < (0.25 * math.pi) ** 2:
            worst_long = min(worst_long, lam)
        elif lam < worst:
            worst, where = lam, k / math.pi
    return float(worst), where, float(worst_long)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dx", type=float, default=0.05, help="particle spacing [m]")
    ap.add_argument("--h-coef", type=float, default=math.sqrt(2.0), help="h / dx [-]")
    ap.add_argument("--kernel", default="wendland")
    ap.add_argument("--sloshing", action="store_true", help="the sloshing mode in the sloshing tank (2.)")
    ap.add_argument("--stability", action="store_true",
                    help="linear stability of the infinite square lattice over h / dx, 2-D and 3-D (3.)")
    a = ap.parse_args(argv)
    if a.stability:
        for dim in (2, 3):
            for hc in (1.2, 1.3, math.sqrt(2.0), 1.5, 1.6, 1.7, 1.8, 1.9, 2.0, 2.2, 2.4):
                lam, k, long = lattice_stability(dim, hc, a.kernel, n=24 if dim == 2 else 12)
                print(f"{dim}-D {a.kernel} h/dx={hc:.3f}: short waves: smallest shear eigenvalue / k^2 {lam:+.2e} "
                      f"at k = {np.array2string(k, precision=2)} pi/dx ({'stable' if lam > -1e-12 else 'UNSTABLE'}); "
                      f"long waves {long:+.2e}")
        return
    if a.sloshing:
        w2, lin = sloshing_rayleigh(a.dx, a.h_coef, a.kernel)
        print(f"kernel={a.kernel} h/dx={a.h_coef:.4g} dx={a.dx} sloshing mode: omega^2={w2:.3f} rad^2/s^2, "
              f"linear {lin:.3f}: omega / linear - 1 = {math.sqrt(max(w2, 0.0) / lin) - 1:+.4f}")
        return
    for p0 in (0.0, 2500.0, 5000.0):
        w2 = omega2(a.dx, p0, a.h_coef, a.kernel)
        print(f"kernel={a.kernel} h/dx={a.h_coef:.4g} dx={a.dx} p0={p0:.0f} Pa omega^2={w2:+.3f} rad^2/s^2 "
              f"(sloshing mode 1: {9.81 * math.pi * math.tanh(math.pi / 2):.2f})")


if __name__ == "__main__":
    main()
