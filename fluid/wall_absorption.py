"""Active absorption at a near field's end walls: a wall that follows the incident sea's
orbits and also moves with what comes back to it, so that a wave much longer than the
box, which no relaxation zone of the box's size can absorb, leaves through the wall
instead of standing in the box.

A near field shorter than the wavelength (the wind-turbine base's box is a sixth of its
sea's 280 m wave) is, for the waves its bodies scatter and radiate at the sea's period, a
closed tank: its relaxation zones, a few kernel supports wide, hold the water at the
incident velocity and reflect such a wave as a wall would, and the box's own sloshing
builds up (measured: the base's surge grows with the box). A piston that absorbs a long
wave moves with the wave's depth-averaged velocity, ``U = (omega / k) eta / d`` for a
progressive wave of elevation ``eta`` (its volume flux ``c eta``): the wall is given that
velocity for the elevation ``eta_s = eta - eta_I`` it finds in front of it beyond the
incident sea's: the shallow-water active absorption reviewed by Schäffer & Klopman 2000
(J. Waterway Port Coastal Ocean Eng. 126(2), 88-97), which DualSPHysics' AWAS applies to
its piston (Altomare et al. 2017, Coastal Eng. 127, 37-54), with the phase speed of the
sea's peak frequency in place of ``sqrt(g d)``.

The elevation in front of the wall is the water's volume over a strip of the seabed next
to it, ``sum_i (m_i / rho_i) phi(x_i) / (int phi dx * width)``, ``phi`` a sine-squared
bump over the strip (smooth, so that a particle crossing its edge does not jump the
reading), above the bed; the incident sea's elevation is averaged over the strip alike.
Slow changes are not the waves' (the fluid's settling, its level's drift): the reading's
mean is followed with a time constant ``tau`` and taken off, and the correction ``xi``
leaks back to zero at the same rate, so that

    d(xi)/dt = s G (eta_s - <eta_s>) - xi / tau,     G = omega_p / (k_p d),

``s`` +1 at the far end, -1 at the near one (the outward normal along the heading), at
the sea's peak frequency; at ``tau = 2`` peak periods a wave at the peak passes both
filters with 0.6 % less amplitude and 9 degrees of lead. The correction is uniform over
the wall (a plane wave along the heading: the box's width is far below the wavelength).

Limits: linear, long-wave (the gain of one frequency, the depth-averaged velocity); what a
body sends out obliquely reaches the end wall as the channel's plane mode only where the
box's width is small against the wavelength.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from errors import InputError
from fluid.waves import wavenumbers


@njit(cache=True)
def _strip_volume(pos, mass, rho, kind, ids, a, b):
    """``sum_i (m_i / rho_i) sin^2(pi (x_i - a) / (b - a))`` over fluid particles (kind 0;
    not mirror images, whose ids are negative: ``fluid.mirror``) with ``a < x_i < b``
    [m^dim]."""
    s = 0.0
    inv = math.pi / (b - a)
    for i in range(pos.shape[0]):
        x = pos[i, 0]
        if kind[i] != 0 or ids[i] < 0 or x <= a or x >= b:
            continue
        w = math.sin((x - a) * inv)
        s += mass[i] / rho[i] * w * w
    return s


class AbsorbingEnd:
    """The motion ``motion(t, ref) -> (pos, vel)`` of one end wall of a near field
    (``Fluid.prescribe_motion``): the incident sea's orbits (``orbits``, a
    :class:`fluid.nearfield.FollowingWall`) plus a uniform displacement ``xi`` [m] along x
    that absorbs what comes back (module docstring), and the per-step update of ``xi`` from
    the fluid (:meth:`update`, a ``Fluid.controllers`` member).

    ``side``: +1 for the far end (water at x below it), -1 for the near end; ``strip``:
    ``(a, b)`` [m], the x range next to the wall where the elevation is read; ``width``
    [m]: the water's extent across y (3-D; 1 in 2-D); ``bed`` [m]: the seabed's z;
    ``tau`` [s]: the filters' time constant (default 2 peak periods)."""

    def __init__(self, sea, orbits, side: int, strip: tuple, width: float, bed: float, tau: float | None = None):
        if side not in (-1, 1):
            raise InputError(f"absorbing end wall: side = {side!r}; give +1 (far end) or -1 (near end)")
        a, b = (float(v) for v in strip)
        if not b > a:
            raise InputError(f"absorbing end wall: the strip {a} .. {b} m is empty; give a < b")
        self.sea, self.orbits, self.side = sea, orbits, side
        self.strip, self.width, self.bed = (a, b), float(width), float(bed)
        omega = 2.0 * math.pi / sea.peak_period
        k = float(wavenumbers(omega, sea.depth, sea.g))
        self.gain = omega / (k * sea.depth)
        self.tau = 2.0 * sea.peak_period if tau is None else float(tau)
        # the sea's elevation over the strip, averaged with the strip's weight
        xs = a + (b - a) * (np.arange(16) + 0.5) / 16
        w = np.sin(math.pi * (xs - a) / (b - a)) ** 2
        self._xs, self._ws = xs, w / w.sum()
        self.reset()

    def reset(self) -> None:
        """Back to the incident sea's orbits alone (no correction, no reading yet)."""
        self.t_n, self.xi_n, self.rate, self.mean = 0.0, 0.0, 0.0, math.nan
        self.eta_s = math.nan  #: the last reading [m] (beyond_sea)

    def save_state(self) -> dict:
        return {"t_n": self.t_n, "xi_n": self.xi_n, "rate": self.rate, "mean": self.mean, "eta_s": self.eta_s}

    def load_state(self, state: dict) -> None:
        self.t_n, self.xi_n, self.rate = float(state["t_n"]), float(state["xi_n"]), float(state["rate"])
        self.mean, self.eta_s = float(state["mean"]), float(state["eta_s"])

    def xi(self, t: float) -> float:
        """The correction [m] at time ``t`` [s] (carried on at its last rate)."""
        return self.xi_n + self.rate * (t - self.t_n)

    def __call__(self, t: float, ref):
        pos, vel = self.orbits(t, ref)
        pos[:, 0] += self.xi(t)
        vel[:, 0] += self.rate
        return pos, vel

    def particle_acceleration(self, t: float, ref) -> np.ndarray:
        """The orbits' acceleration [m/s^2] (the correction's is left out: it changes once a
        step, by what the waves that come back change it)."""
        return self.orbits.particle_acceleration(t, ref)

    def elevation(self, ps) -> float:
        """The water's elevation [m] over the strip above the sea's still level, from the
        fluid particles' volumes (module docstring)."""
        a, b = self.strip
        v = _strip_volume(ps.pos, ps.mass, ps.rho, ps.kind, ps.ids, a, b)
        return v / (0.5 * (b - a) * self.width) - (self.sea.level - self.bed)

    def beyond_sea(self, ps, t: float) -> float:
        """The elevation [m] over the strip beyond the incident sea's at time ``t`` [s]:
        what comes back to the wall (and the fluid's own offset)."""
        n = self._xs.size
        return self.elevation(ps) - float(self._ws @ self.sea.elevation(self._xs, np.zeros(n), np.full(n, float(t))))

    def update(self, ps, t: float, dt: float) -> None:
        """Read the elevation in front of the wall at the end of a step (time ``t`` [s], the
        step ``dt`` [s]) and set the correction's rate for the next one."""
        self.eta_s = self.beyond_sea(ps, t)
        xi = self.xi(t)
        if math.isnan(self.mean):  # the first reading: the fluid's own offset, not a wave
            self.mean = self.eta_s
        f = dt / self.tau
        self.mean += (self.eta_s - self.mean) * min(f, 1.0)
        self.t_n, self.xi_n = float(t), xi
        self.rate = self.side * self.gain * (self.eta_s - self.mean) - xi / self.tau
