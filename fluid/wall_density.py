"""Tank-wall densities that follow the fluid: the wall-pressure extrapolation of Adami,
Hu & Adams (2012, J. Comput. Phys. 231, 7057-7075, Eq. 27) for the FIXED_WALL and
MOVING_WALL particles.

Why: plain dynamic boundary particles (004_1657bd4a51d29840.txt §2.6) integrate the
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
acceleration; its density is the Tait density of that pressure (004 Eq. 8 inverted),
``rho_w = rho0 (1 + p_w / B)^(1/gamma)``, clamped below at ``rho0`` (``p_w >= 0``: the
wall holds no tension, as the clamp of the plain dynamic boundaries in
``fluid.integrator``). A wall particle with no fluid within 2h takes ``rho0``.

For a fluid at rest in any linear (hydrostatic) pressure field ``p = p0 + rho g . r``
with a uniform density the extrapolation is exact, whatever the neighbours: the wall
particle holds the pressure of the field at its own position. So a tank started from the
hydrostatic densities (``fluid.geometry.set_hydrostatic``) starts in equilibrium with it,
and the wall carries the fluid's pressure field through it (the wetted face of the wall
sees the pressure the fluid has beside it, not the fluid's kernel sum).

The wall pressure is a Shepard (zero-order) average of the fluid plus the exact
hydrostatic/inertial correction; the pair loop (``fluid.equations``) is unchanged: this
module only sets the tank walls' densities before each rate evaluation (the
``Fluid.boundary_correction`` hook), as ``fluid.boundary_correction.MDBC`` does for bodies.
Adami et al. weight the correction with the fluid density rho_f; here it is rho0, the
density ``fluid.geometry.set_hydrostatic`` builds the rest state with (p = rho0 g depth):
the two differ by p/(gamma B) < 1 % (a weakly compressible fluid), and with rho0 a tank
set up at rest starts with exactly the wall densities the plain dynamic boundaries start
with (the first rates agree to round-off: tests/test_fluid_wall_density.py).

Measured against the plain dynamic boundaries when these walls came in (the quick
variants of sloshing-frequency, westergaard, dambreak-2d, sloshing-spheric10 and the
hydrostatic tanks, "dbc" -> "adami"): docs/validation/modules/wall_density_history.md;
the cases' current figures are in their docstrings. The sloshing tank's first mode came
down from +9.4 % to +4.6 % of linear theory (quick), and the wall pressure follows the
wave as linear theory says.

Cost: 0.14 ms of CPU per rate evaluation for the 2008 wall particles of the 2-D dam
break of benchmarks/fluid_throughput.py (22 008 particles, one thread; the rates take
2.8 ms): +4 % on a Verlet step, twice that on a symplectic one (two evaluations). An
A/B of the benchmark (``--case 2d --dp 0.01 --threads 1 --steps 200 --walls adami``
against ``--walls dbc``, alternating, on a loaded machine) gave +0.2 ... 0.3 ms of CPU
per step.

A hydrostatic tank started on the lattice moves: a free-surface corner, not the start
(the first rates are those of the plain boundaries). The top fluid row settles into SPH's
free-surface equilibrium, which holds more than rho g dx/2 beside the wall; the "adami"
wall holds the fluid's pressure there, with no wall particles on the air's side to
balance it, so the two top corner particles move 0.15 dx off the walls and launch the
symmetric sloshing mode (2-D, dx = 0.02 m: largest speed 2.4e-2 sqrt(g H) at 0.1 s,
4e-3 still at 2 s). It is the start, though, not an instability: relaxed first with
damped velocities (``Fluid.settle``, 1 s), the corner particles find their place and the
tank stays at rest, 1.8e-4 sqrt(g H) and 0.82 % RMS at dx = 0.02 m, 1.0e-4 and 0.67 % at
0.01 m (``run_hydrostatic(2, dx, t_end, settle_s=1.0, walls="adami")``). Hence an option
(``FluidConfig.walls``), not the default; the wave set-up ``fluid.solver.WAVES_2D`` uses
these walls. The mechanism in full and the clamp tried off: the history file named above.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from fluid.equations import tait_B
from fluid.kernels import alpha_d, kernel_id, w_value
from fluid.neighbours import cell_coords, row_range
from fluid.particles import Kind

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")


@njit(parallel=True, **_OPTS)
def adami_wall_density(pos, rho, kind, acc_w, has_acc, start, lo, inv_cell, nx, ny, nz, reach, kernel, ad, h,
                       rho0, B, gamma, g, kmin, kmax, p_floor):
    """Set ``rho`` of every particle with ``kmin <= kind <= kmax`` from Adami et al. (2012)
    Eq. 27 (module docstring). ``acc_w`` (N, dim) [m/s^2] the wall accelerations (read only
    if ``has_acc``); ``g`` (3,) [m/s^2] gravity as (x, y, z); particles sorted by cell
    (``start``); ``lo`` has 3 components (y = 0, ``ny = 1`` in 2-D)."""
    n, dim = pos.shape
    three = dim == 3
    zc = dim - 1
    dys = 2 * reach + 1 if three else 1
    R2 = 4.0 * h * h
    ih = 1.0 / h
    inv_gamma = 1.0 / gamma
    seven = gamma == 7.0
    for i in prange(n):
        k = kind[i]
        if k < kmin or k > kmax:
            continue
        xw = pos[i, 0]
        yw = pos[i, 1] if three else 0.0
        zw = pos[i, zc]
        bx = g[0]
        by = g[1]
        bz = g[2]
        if has_acc:
            bx -= acc_w[i, 0]
            if three:
                by -= acc_w[i, 1]
            bz -= acc_w[i, zc]
        sw = 0.0
        sp = 0.0
        cx, cy, cz = cell_coords(xw, yw, zw, lo, inv_cell, True, nx, ny, nz)
        for dz in range(-reach, reach + 1):
            for kk in range(dys):
                dy = kk - reach if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, reach)
                for j in range(j0, j1):
                    if kind[j] != 0:
                        continue
                    rx = xw - pos[j, 0]
                    ry = yw - pos[j, 1] if three else 0.0
                    rz = zw - pos[j, zc]
                    r2 = rx * rx + ry * ry + rz * rz
                    if r2 >= R2:
                        continue
                    w = w_value(kernel, math.sqrt(r2) * ih, ad)
                    x = rho[j] / rho0
                    if seven:  # pow costs more than the rest of the pair
                        x3 = x * x * x
                        pj = B * (x3 * x3 * x - 1.0)
                    else:
                        pj = B * (x ** gamma - 1.0)
                    sw += w
                    sp += w * (pj + rho0 * (bx * rx + by * ry + bz * rz))
        p = max(sp / sw, p_floor) if sw > 0.0 else 0.0
        rho[i] = rho0 * (1.0 + p / B) ** inv_gamma


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
        g = np.zeros(3)
        g[2] = -c.g
        self.g = g
        self._zero = np.zeros((0, c.dim))
        #: lowest wall pressure [Pa] (0: no tension, the clamp of the plain dynamic boundaries)
        self.p_floor = 0.0

    def __call__(self, ps, start, grid) -> None:
        c = self.fluid.config
        lo = np.zeros(3)
        if c.dim == 3:
            lo[:] = grid.lo
        else:
            lo[0], lo[2] = grid.lo
        nx, ny, nz = grid.shape
        acc = self.fluid.prescribed_acceleration()
        has = acc is not None
        adami_wall_density(ps.pos, ps.rho, ps.kind, acc if has else self._zero, has, start, lo,
                           1.0 / grid.cell, nx, ny, nz, grid.reach, self.kernel, self.ad, c.h, c.rho0, self.B,
                           c.gamma, self.g, int(Kind.FIXED_WALL), int(Kind.MOVING_WALL), self.p_floor)
