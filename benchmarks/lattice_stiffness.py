"""Lattice stiffness of the SPH fluid under pressure: a candidate for the part of the
first sloshing mode's +4.5 % that is not in the walls (cosim.validations.sloshing,
sloshing_frequency).

1. Closed box. A closed 2-D box L x H = 1 x 0.5 m (3 wall layers, ``walls="adami"``) is
filled on the lattice at a uniform pressure p0 [Pa], no gravity, and the fluid particles
are displaced by the divergence-free field of the stream function
``psi = A sin(pi x / L) sin(pi z / H)`` (zero normal displacement at the walls),
A = 1e-3 dx. The densities are kept (a real fluid: no volume change, so no pressure
change), and the rates are taken once. The restoring acceleration a projected on the
displacement u,

    omega^2 = -sum a . u / sum u . u   [rad^2/s^2],

is zero for a fluid; for the SPH fluid it is not. With uniform pressure the momentum
equation (004_1657bd4a51d29840.txt Eq. 6) reduces to ``-(2 p0 / rho^2) grad_a sum_b m_b
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

Measured (NUMBA_NUM_THREADS=1; first mode of the sloshing tank for scale:
omega_1^2 = 28.3 rad^2/s^2; last column: the dynamic result, sloshing-frequency quick
with walls="adami"):

=========  =======  =======  ==================  ====================  ==================
kernel     h / dx   dx [m]   1. box, omega^2     2. sloshing mode,     sloshing-frequency
                             at 2.5 kPa          omega / linear - 1    quick, "adami"
=========  =======  =======  ==================  ====================  ==================
Wendland   1.2      0.05     -16.1               -0.090                +0.018
Wendland   sqrt(2)  0.05     +5.2 (+10.4 at 5    +0.032                +0.046
                             kPa, 0 at 0)
Wendland   sqrt(2)  0.025    +5.1                +0.040                +0.051 (full)
Wendland   1.6      0.05     --                  -0.047                +0.020
Wendland   1.7      0.05     -0.45               --                    no peak (the
                                                                       lattice rearranges)
cubic      sqrt(2)  0.05     +11.9               +0.013                +0.058
=========  =======  =======  ==================  ====================  ==================

At the default h = sqrt(2) dx the configuration alone is +3 ... 4 % stiff for the
sloshing mode and does not converge with dx, as the dynamic bias; with other kernels or
h/dx the two part ways (the density response, which the motion adjusts to, is not in
the static number), so this is a candidate for the default's residual, not a proof. The density response of the box to the same displacement (the kernel-sum
change that continuity integrates, at p0 = 0) gives +0.9 rad^2/s^2.

    .venv/bin/python benchmarks/lattice_stiffness.py
    .venv/bin/python benchmarks/lattice_stiffness.py --h-coef 1.2 --kernel cubic --dx 0.025
    .venv/bin/python benchmarks/lattice_stiffness.py --sloshing --dx 0.025
"""

from __future__ import annotations

import argparse
import math
import os
import sys

_here = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _here]


def omega2(dx: float, p0: float, h_coef: float = math.sqrt(2.0), kernel: str = "wendland",
           amplitude: float = 1e-3, L: float = 1.0, H: float = 0.5) -> float:
    """omega^2 [rad^2/s^2] of the divergence-free displacement (module docstring) at
    pressure ``p0`` [Pa]; ``amplitude`` in units of dx."""
    import numpy as np

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
    import numpy as np

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


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dx", type=float, default=0.05, help="particle spacing [m]")
    ap.add_argument("--h-coef", type=float, default=math.sqrt(2.0), help="h / dx [-]")
    ap.add_argument("--kernel", default="wendland")
    ap.add_argument("--sloshing", action="store_true", help="the sloshing mode in the sloshing tank (2.)")
    a = ap.parse_args(argv)
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
