"""Time integration: the symplectic position-Verlet predictor-corrector of DualSPHysics
(Monaghan 2005; "standard predictor-corrector", 001_14936b82710365b2.txt §2.2), with a
variable step from the force and Courant-viscous conditions of
001_14936b82710365b2.txt Eq. 14:

    dt = CFL * min(dt_f, dt_cv),  dt_f = min_a sqrt(h / |f_a|),
    dt_cv = min_a h / (c_a + max_b |h v_ab . r_ab / (r_ab^2 + eta^2)|)

(the paper's factor 0.3 is our ``cfl``, default 0.2).

Predictor (half step, rates at n):   rho^{n+1/2} = rho^n + dt/2 drho^n,
    v^{n+1/2} = v^n + dt/2 a^n,      r^{n+1/2} = r^n + dt/2 v^n.
Corrector (rates at n+1/2):          eps = -(drho^{n+1/2} / rho^{n+1/2}) dt,
    rho^{n+1} = rho^n (2 - eps) / (2 + eps),  v^{n+1} = v^n + dt a^{n+1/2},
    r^{n+1} = r^n + dt (v^n + v^{n+1}) / 2.
Boundary particles take the same density update (clamped below at rho0, as DualSPHysics
does, so that a wall never pulls fluid in) and move with their prescribed velocity.

Option ``"verlet"`` (Monaghan 1989, as in DualSPHysics; one pair loop per step instead of
two): ``v^{n+1} = v^{n-1} + 2 dt a^n``, ``rho^{n+1} = rho^{n-1} + 2 dt drho^n``,
``r^{n+1} = r^n + dt v^n + dt^2/2 a^n``; every ``verlet_reset`` steps (and on the first) the
forward-Euler form ``v^{n+1} = v^n + dt a^n``, ``rho^{n+1} = rho^n + dt drho^n`` decouples the
odd and even steps.

XSPH (optional, fluid.equations): fluid particles move with ``v + dv_x``, the XSPH
correction ``dv_x`` taken with the rates (at n; at n+1/2 in the corrector):
predictor ``r^{n+1/2} = r^n + dt/2 (v^n + dv_x^n)``, corrector
``r^{n+1} = r^n + dt ((v^n + v^{n+1})/2 + dv_x^{n+1/2})``, Verlet
``r^{n+1} = r^n + dt (v^n + dv_x^n) + dt^2/2 a^n``. Velocities are not changed by it.

With laminar viscosity ``nu > 0`` the step also obeys the viscous diffusion limit
``dt <= 0.125 h^2 / nu`` (Morris, Fox & Zhu 1997, J. Comput. Phys. 136, Eq. 29 of that
paper; DualSPHysics does not apply it, we do: for a small ``dx`` and a large ``nu`` it is
the binding limit), limiter ``"viscous_diffusion"``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")

#: names of the conditions that can limit a step
LIMITERS = ("force", "courant_viscous", "viscous_diffusion", "dt_max", "coupling")


@dataclass(frozen=True)
class StepLimit:
    """The stable step and which condition set it."""

    dt: float  # [s]
    limiter: str  # one of LIMITERS
    dt_force: float  # [s] CFL * dt_f
    dt_cv: float  # [s] CFL * dt_cv


@njit(parallel=True, **_OPTS)
def _bounds(acc, visc, cs, kind, h):
    """(max |a|^2 over fluid particles, min h / (c + visc) over all particles), the latter
    as h / max (c + visc): no division and no branch per particle (a third of the cost)."""
    amax2 = 0.0
    cvmax = 0.0
    dim = acc.shape[1]
    for i in prange(acc.shape[0]):
        a2 = 0.0
        for k in range(dim):
            a2 += acc[i, k] * acc[i, k]
        amax2 = max(amax2, a2 if kind[i] == 0 else 0.0)
        cvmax = max(cvmax, cs[i] + visc[i])
    return amax2, h / cvmax if cvmax > 0.0 else np.inf


def stable_dt(acc, visc, cs, kind, h: float, cfl: float, dt_max: float = math.inf,
              nu: float = 0.0) -> StepLimit:
    """001_14936b82710365b2.txt Eq. 14 with factor ``cfl``; ``dt_max`` [s] caps it; with a
    laminar kinematic viscosity ``nu`` [m^2/s] > 0 also ``0.125 h^2 / nu`` (Morris et al.
    1997)."""
    amax2, cvmin = _bounds(acc, visc, cs, kind, h) if cs.size else (0.0, math.inf)
    amax = math.sqrt(amax2)
    dt_f = cfl * math.sqrt(h / amax) if amax > 0 else math.inf
    dt_cv = cfl * cvmin
    dt, lim = (dt_f, "force") if dt_f < dt_cv else (dt_cv, "courant_viscous")
    if nu > 0 and 0.125 * h * h / nu < dt:
        dt, lim = 0.125 * h * h / nu, "viscous_diffusion"
    if dt_max < dt:
        dt, lim = dt_max, "dt_max"
    return StepLimit(dt, lim, dt_f, dt_cv)


@njit(parallel=True, **_OPTS)
def predictor(pos, vel, rho, drho, acc, kind, rho0, dt, pos_n, vel_n, rho_n, xs):
    """Save the n state into ``*_n`` and advance ``pos, vel, rho`` to n+1/2 in place.
    ``xs``: the XSPH correction [m/s] (N, dim), or an empty array when off."""
    half = 0.5 * dt
    dim = pos.shape[1]
    use_xs = xs.shape[0] > 0
    for i in prange(pos.shape[0]):
        f = kind[i] == 0
        r = rho[i]
        rho_n[i] = r
        rn = r + half * drho[i]
        rho[i] = rn if f else max(rn, rho0)
        for k in range(dim):
            v = vel[i, k]
            vel_n[i, k] = v
            pos_n[i, k] = pos[i, k]
            pos[i, k] += half * (v + xs[i, k]) if use_xs else half * v
            if f:
                vel[i, k] = v + half * acc[i, k]


@njit(parallel=True, **_OPTS)
def corrector(pos, vel, rho, drho, acc, kind, rho0, dt, pos_n, vel_n, rho_n, xs):
    """Advance from the saved n state to n+1 with the rates at n+1/2 (in place); ``xs`` as
    in :func:`predictor`, at n+1/2."""
    dim = pos.shape[1]
    use_xs = xs.shape[0] > 0
    for i in prange(pos.shape[0]):
        f = kind[i] == 0
        eps = -drho[i] / rho[i] * dt
        rn = rho_n[i] * (2.0 - eps) / (2.0 + eps)
        rho[i] = rn if f else max(rn, rho0)
        for k in range(dim):
            v0 = vel_n[i, k]
            v1 = v0 + dt * acc[i, k] if f else v0
            vel[i, k] = v1
            pos[i, k] = pos_n[i, k] + 0.5 * dt * (v0 + v1) + (dt * xs[i, k] if use_xs else 0.0)


@njit(cache=True)  # no fastmath here: it would let LLVM assume there are no NaNs
def first_non_finite(pos, vel, rho):
    """Index of the first particle with a NaN or infinite position, velocity or density;
    -1 if none. (Serial with early exit: cheap next to a pair loop.)"""
    dim = pos.shape[1]
    for i in range(pos.shape[0]):
        s = rho[i]
        for k in range(dim):
            s += pos[i, k] + vel[i, k]
        if not np.isfinite(s):
            return i
    return -1


@njit(parallel=True, **_OPTS)
def verlet(pos, vel, rho, drho, acc, kind, rho0, dt, vel_m1, rho_m1, euler, xs):
    """One Verlet step in place with the rates at n; ``vel_m1, rho_m1`` hold the n-1 state
    on entry and the n state on exit. ``euler``: take the forward-Euler form. ``xs`` as in
    :func:`predictor`."""
    dim = pos.shape[1]
    use_xs = xs.shape[0] > 0
    w = dt if euler else 2.0 * dt
    for i in prange(pos.shape[0]):
        f = kind[i] == 0
        r = rho[i]
        base = r if euler else rho_m1[i]
        rn = base + w * drho[i]
        rho_m1[i] = r
        rho[i] = rn if f else max(rn, rho0)
        for k in range(dim):
            v = vel[i, k]
            if f:
                vb = v if euler else vel_m1[i, k]
                pos[i, k] += dt * (v + xs[i, k] if use_xs else v) + 0.5 * dt * dt * acc[i, k]
                vel[i, k] = vb + w * acc[i, k]
            else:
                pos[i, k] += dt * v
            vel_m1[i, k] = v
