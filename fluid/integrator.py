"""Time integration: the symplectic position-Verlet predictor-corrector of DualSPHysics
(Monaghan 2005; "standard predictor-corrector", Sunara et al. 2021, §2.2), with a
variable step from the force and Courant-viscous conditions of
Sunara et al. 2021, Eq. 14:

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

The step also obeys a diffusion limit that DualSPHysics does not apply, ``dt <= C h^2 /
nu_eff``, ``nu_eff = nu + alpha h c_max / (2 (d + 2)) + delta h c0`` (the laminar viscosity,
the continuum shear viscosity of the artificial one (Monaghan 2005), the density diffusion):
``C`` = 0.125 for the predictor-corrector (Morris, Fox & Zhu 1997), ``z_N / (5.8
VERLET_MARGIN)`` for Verlet, whose leap-frog is unstable for any diffusion and held only by
the Euler step every ``verlet_reset`` steps (:func:`verlet_diffusion_edge`). The limiters
name the largest part of ``nu_eff``. The derivation, its measurements and what Eq. 14
covers as it stands: docs/fluid_integrator.md.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from fluid.terms import cpu as tm

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")

#: names of the conditions that can limit a step
LIMITERS = ("force", "courant_viscous", "viscous_diffusion", "artificial_viscosity", "density_diffusion", "dt_max",
            "coupling")

#: Morris et al. (1997)'s factor on h^2 / nu for the predictor-corrector [-]
MORRIS = 0.125
#: the largest eigenvalue of the SPH diffusion operator over nu / h^2 [-] (measured, module docstring)
LAMBDA_H2 = 5.8
#: Verlet's diffusion limit lies this factor below its stability edge z_N / LAMBDA_H2 [-]
VERLET_MARGIN = 1.5


@functools.lru_cache(maxsize=None)
def verlet_diffusion_edge(n: int) -> float:
    """Largest ``z_N = lambda dt`` [-] for which Verlet with a forward-Euler step every ``n``
    steps does not amplify a mode decaying at rate ``lambda`` (``v' = -lambda v``): the gain
    of one cycle is ``G_n(z) = v_n / v_0`` with ``v_1 = (1 - z) v_0`` (Euler) and
    ``v_{k+1} = v_{k-1} - 2 z v_k`` (leap-frog), and ``z_N`` is its first crossing of
    ``|G| = 1`` (2 for n = 1, 0.358 for 10, 0.135 for 40)."""

    def gain(z):
        a, b = 1.0, 1.0 - z
        for _ in range(n - 1):
            a, b = b, a - 2.0 * z * b
        return abs(b)

    zs = np.linspace(0.0, 2.0, 4001)[1:]
    bad = next((z for z in zs if gain(z) > 1.0 + 1e-12), 2.0)
    lo, hi = bad - 2.0 / 4000, bad
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if gain(mid) <= 1.0 + 1e-12 else (lo, mid)
    return float(lo)


def diffusion_coefficient(integrator: str, verlet_reset: int) -> float:
    """``C`` [-] of the diffusion limit ``dt <= C h^2 / nu_eff`` (module docstring):
    Morris' 0.125 for the predictor-corrector, ``z_N / (LAMBDA_H2 VERLET_MARGIN)`` for Verlet."""
    if integrator == "verlet":
        return verlet_diffusion_edge(int(verlet_reset)) / (LAMBDA_H2 * VERLET_MARGIN)
    return MORRIS


@dataclass(frozen=True)
class StepLimit:
    """The stable step and which condition set it."""

    dt: float  # [s]
    limiter: str  # one of LIMITERS
    dt_force: float  # [s] CFL * dt_f
    dt_cv: float  # [s] CFL * dt_cv


@njit(parallel=True, **_OPTS)
def _bounds(acc, visc, cs, kind, h):
    """(max |a|^2 over fluid particles, min h / (c + visc) over all particles, max c), the
    second as h / max (c + visc): no division and no branch per particle (a third of the
    cost)."""
    amax2 = 0.0
    cvmax = 0.0
    cmax = 0.0
    dim = acc.shape[1]
    for i in prange(acc.shape[0]):
        a2 = 0.0
        for k in range(dim):
            a2 += acc[i, k] * acc[i, k]
        amax2 = max(amax2, a2 if kind[i] == 0 else 0.0)
        cvmax = max(cvmax, cs[i] + visc[i])
        cmax = max(cmax, cs[i])
    return amax2, h / cvmax if cvmax > 0.0 else np.inf, cmax


def stable_dt(acc, visc, cs, kind, h: float, cfl: float, dt_max: float = math.inf,
              nu: float = 0.0, *, alpha_eff: float = 0.0, nu_delta: float = 0.0,
              c_diff: float = MORRIS) -> StepLimit:
    """Sunara et al. 2021, Eq. 14 with factor ``cfl``; ``dt_max`` [s] caps it; and the
    diffusion limit ``c_diff h^2 / nu_eff`` (module docstring) with
    ``nu_eff = nu + alpha_eff h c_max + nu_delta``: ``nu`` [m^2/s] the laminar viscosity,
    ``alpha_eff = alpha / (2 (d + 2))`` [-] the artificial viscosity's share, ``nu_delta =
    delta h c0`` [m^2/s] the density diffusion's; ``c_diff`` from
    :func:`diffusion_coefficient` (0.125 for the predictor-corrector)."""
    amax2, cvmin, cmax = _bounds(acc, visc, cs, kind, h) if cs.size else (0.0, math.inf, 0.0)
    return step_limit(amax2, cvmin, cmax, h, cfl, dt_max, nu, alpha_eff=alpha_eff, nu_delta=nu_delta, c_diff=c_diff)


def step_limit(amax2: float, cvmin: float, cmax: float, h: float, cfl: float, dt_max: float = math.inf,
               nu: float = 0.0, *, alpha_eff: float = 0.0, nu_delta: float = 0.0, c_diff: float = MORRIS) -> StepLimit:
    """:func:`stable_dt` from its reductions over the particles (``_bounds``: the largest
    fluid acceleration squared [m^2/s^4], min h / (c + visc) [s], the largest sound speed
    [m/s]), wherever they were taken (the GPU path takes them on the device)."""
    amax = math.sqrt(amax2)
    dt_f = cfl * math.sqrt(h / amax) if amax > 0 else math.inf
    dt_cv = cfl * cvmin
    dt, lim = (dt_f, "force") if dt_f < dt_cv else (dt_cv, "courant_viscous")
    parts = {"viscous_diffusion": nu, "artificial_viscosity": alpha_eff * h * cmax, "density_diffusion": nu_delta}
    nu_eff = sum(parts.values())
    if nu_eff > 0 and c_diff * h * h / nu_eff < dt:
        dt, lim = c_diff * h * h / nu_eff, max(parts, key=parts.get)
    if dt_max < dt:
        dt, lim = dt_max, "dt_max"
    return StepLimit(dt, lim, dt_f, dt_cv)


@njit(parallel=True, **_OPTS)
def predictor(pos, vel, rho, drho, acc, kind, rho0, dt, pos_n, vel_n, rho_n, xs):
    """Save the n state into ``*_n`` and advance ``pos, vel, rho`` to n+1/2 in place
    (:func:`fluid.terms.predictor_density`, :func:`~fluid.terms.predictor_component`).
    ``xs``: the XSPH correction [m/s] (N, dim), or an empty array when off."""
    dim = pos.shape[1]
    use_xs = xs.shape[0] > 0
    for i in prange(pos.shape[0]):
        f = kind[i] == 0
        rho_n[i] = rho[i]
        rho[i] = tm.predictor_density(rho[i], drho[i], dt, f, rho0)
        for k in range(dim):
            vel_n[i, k] = vel[i, k]
            pos_n[i, k] = pos[i, k]
            pos[i, k], vel[i, k] = tm.predictor_component(pos[i, k], vel[i, k], acc[i, k],
                                                          xs[i, k] if use_xs else 0.0, dt, f)


@njit(parallel=True, **_OPTS)
def corrector(pos, vel, rho, drho, acc, kind, rho0, dt, pos_n, vel_n, rho_n, xs):
    """Advance from the saved n state to n+1 with the rates at n+1/2 (in place;
    :func:`fluid.terms.corrector_density`, :func:`~fluid.terms.corrector_component`); ``xs``
    as in :func:`predictor`, at n+1/2."""
    dim = pos.shape[1]
    use_xs = xs.shape[0] > 0
    for i in prange(pos.shape[0]):
        f = kind[i] == 0
        rho[i] = tm.corrector_density(rho_n[i], drho[i], rho[i], dt, f, rho0)
        for k in range(dim):
            pos[i, k], vel[i, k] = tm.corrector_component(pos_n[i, k], vel_n[i, k], acc[i, k],
                                                          xs[i, k] if use_xs else 0.0, dt, f)


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
    """One Verlet step in place with the rates at n (:func:`fluid.terms.verlet_density`,
    :func:`~fluid.terms.verlet_component`); ``vel_m1, rho_m1`` hold the n-1 state on entry
    and the n state on exit. ``euler``: take the forward-Euler form. ``xs`` as in
    :func:`predictor`."""
    dim = pos.shape[1]
    use_xs = xs.shape[0] > 0
    for i in prange(pos.shape[0]):
        f = kind[i] == 0
        r = rho[i]
        rho[i] = tm.verlet_density(r, rho_m1[i], drho[i], dt, euler, f, rho0)
        rho_m1[i] = r
        for k in range(dim):
            v = vel[i, k]
            pos[i, k], vel[i, k] = tm.verlet_component(pos[i, k], v, vel_m1[i, k], acc[i, k],
                                                       xs[i, k] if use_xs else 0.0, dt, euler, f)
            vel_m1[i, k] = v
