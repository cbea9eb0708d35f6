"""Relaxation zones: layers of the fluid whose velocity is pulled towards a target, to absorb
waves at a flume's end (target: rest) or to impose an incident wave (target: a theory's
velocity field).

Inside a zone each fluid particle's velocity relaxes towards the target at a rate that
grows smoothly from the zone's inner edge (``chi = 0``) to its outer edge (``chi = 1``),

    dv/dt = -sigma(chi) (v - v_target),   sigma(chi) = rate * w(chi),
    w(chi) = (exp(chi^3.5) - 1) / (exp(1) - 1)

(the weight of Jacobsen, Fuhrman & Fredsøe 2012, Int. J. Numer. Meth. Fluids 70, Eq. 5,
applied as a rate, as a sponge layer is: Israeli & Orszag 1981, J. Comput. Phys. 41).
Each step the exact solution over ``dt`` is taken, ``v <- v_t + (v - v_t) exp(-sigma dt)``,
so the result does not depend on the step. DualSPHysics' damping zone (Altomare et al.
2017, Coastal Eng. 127, Eq. 15) is the same with ``w = chi^4`` to first order in ``dt``.

A wave entering an absorbing zone is reflected the less, the smoother and longer the zone
is against its wavelength; ``rate`` [1/s] of a few wave frequencies and a zone of one to
two wavelengths reflect a few per cent of the height (measured in ``cosim validate
wave-propagation``). Only fluid particles are touched; the step of the integrator is not.

A zone is a slab between two planes normal to a coordinate axis (:class:`Slab`); its
``target`` is None (rest) or a callable ``target(pos, t) -> vel`` over the particles inside
(``pos`` (M, dim) [m], ``t`` [s]).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np
from numba import njit, prange

from errors import InputError

_E1 = math.e - 1.0


@njit(cache=True)
def _weight(chi):
    """Jacobsen et al. (2012) Eq. 5 weight, 0 at the inner edge, 1 at the outer one."""
    return (math.exp(chi ** 3.5) - 1.0) / _E1


@njit(cache=True)
def zone_factor(pos, kind, i, axis, x_in, inv, rate, dt):
    """Row ``i``'s factor ``exp(-sigma(chi) dt)`` over a step ``dt`` [s] in the slab from
    ``x_in`` (``inv`` = 1 / (x_out - x_in)) along ``axis`` (chi clipped at 1), or -1 where
    the row is not a fluid particle inside it (``chi > 0``)."""
    if kind[i] != 0:
        return -1.0
    chi = (pos[i, axis] - x_in) * inv
    if chi <= 0.0:
        return -1.0
    return math.exp(-rate * _weight(min(chi, 1.0)) * dt)


@njit(parallel=True, cache=True)
def _damp_to_rest(pos, vel, kind, axis, x_in, x_out, rate, dt, extra):
    """Multiply the velocity of fluid particles in the slab by exp(-sigma dt), and the rows
    of ``extra`` (another velocity array in step with ``vel``, or an empty one) alike."""
    inv = 1.0 / (x_out - x_in)
    dim = vel.shape[1]
    use_extra = extra.shape[0] > 0
    for i in prange(pos.shape[0]):
        f = zone_factor(pos, kind, i, axis, x_in, inv, rate, dt)
        if f < 0.0:
            continue
        for k in range(dim):
            vel[i, k] *= f
            if use_extra:
                extra[i, k] *= f


@njit(cache=True)
def _zone_rows(pos, kind, axis, x_in, x_out, rate, dt):
    """The rows of the fluid particles inside the slab (``chi > 0``) and each one's factor
    ``exp(-sigma(chi) dt)`` (chi clipped at 1)."""
    inv = 1.0 / (x_out - x_in)
    n = 0
    for i in range(pos.shape[0]):
        if kind[i] == 0 and (pos[i, axis] - x_in) * inv > 0.0:
            n += 1
    rows = np.empty(n, np.int64)
    f = np.empty(n)
    n = 0
    for i in range(pos.shape[0]):
        fi = zone_factor(pos, kind, i, axis, x_in, inv, rate, dt)
        if fi >= 0.0:
            rows[n] = i
            f[n] = fi
            n += 1
    return rows, f


@njit(cache=True)
def _relax_rows(vel, rows, f, vt):
    """``vel[rows] <- vt + (vel[rows] - vt) f`` (the exact relaxation over the step)."""
    for m in range(rows.shape[0]):
        i = rows[m]
        for k in range(vel.shape[1]):
            vel[i, k] = vt[m, k] + (vel[i, k] - vt[m, k]) * f[m]


@dataclass(frozen=True)
class Slab:
    """A relaxation zone between the planes ``coordinate[axis] = inner`` (weight 0) and
    ``= outer`` (weight 1; beyond it the weight stays 1), ``outer`` on either side of
    ``inner``; ``rate`` [1/s] the relaxation rate at the outer edge; ``target`` None (rest)
    or ``target(pos, t) -> vel``. A target that can relax the zone itself in one compiled
    pass has ``target.relax(slab, pos, vel, kind, t, dt, extra) -> bool``, True when it
    did (``fluid.nearfield.SeaVelocity``)."""

    axis: int
    inner: float
    outer: float
    rate: float
    target: Callable | None = None

    def __post_init__(self):
        if not isinstance(self.axis, int) or self.axis < 0:
            raise InputError(f"relaxation zone: axis {self.axis!r}; give 0 (x), 1 (y, 3-D) or the last (z)")
        for name in ("inner", "outer", "rate"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v)):
                raise InputError(f"relaxation zone: {name} = {v!r}; give a finite number")
        if self.inner == self.outer:
            raise InputError(f"relaxation zone: inner = outer = {self.inner} m; give the zone a width")
        if self.rate <= 0:
            raise InputError(f"relaxation zone: rate = {self.rate!r} 1/s; give a positive rate (a few wave "
                             "frequencies)")
        if self.target is not None and not callable(self.target):
            raise InputError("relaxation zone: target must be None (rest) or a callable target(pos, t) -> vel")

    @property
    def width(self) -> float:
        """The zone's width [m]."""
        return abs(self.outer - self.inner)

    def chi(self, pos: np.ndarray) -> np.ndarray:
        """The zone coordinate of each position (M, dim): 0 at the inner edge, 1 at the outer
        one, clipped to [0, 1]."""
        return np.clip((pos[:, self.axis] - self.inner) / (self.outer - self.inner), 0.0, 1.0)

    def apply(self, pos, vel, kind, t: float, dt: float, extra=None) -> None:
        """Relax ``vel`` (N, dim) in place over ``dt`` [s] at time ``t`` [s] (the end of the
        step); ``extra``: a second velocity array relaxed alike (Verlet's n-1 velocity)."""
        if self.axis >= pos.shape[1]:
            raise InputError(f"relaxation zone: axis {self.axis} does not exist in {pos.shape[1]}-D")
        if self.target is None:
            e = extra if extra is not None else np.zeros((0, vel.shape[1]))
            _damp_to_rest(pos, vel, kind, self.axis, float(self.inner), float(self.outer), float(self.rate),
                          float(dt), e)
            return
        relax = getattr(self.target, "relax", None)
        if relax is not None and relax(self, pos, vel, kind, t, dt, extra):
            return
        rows, f = _zone_rows(pos, kind, self.axis, float(self.inner), float(self.outer), float(self.rate), float(dt))
        if rows.size == 0:
            return
        vt = np.asarray(self.target(pos[rows], t), dtype=np.float64)
        if vt.shape != (rows.size, vel.shape[1]):
            raise InputError(f"relaxation zone: target gave shape {vt.shape}, expected {(rows.size, vel.shape[1])}")
        _relax_rows(vel, rows, f, vt)
        if extra is not None:
            _relax_rows(extra, rows, f, vt)
