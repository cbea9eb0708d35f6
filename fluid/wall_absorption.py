"""Active absorption at a near field's end walls: a wall that follows the incident sea's
orbits and also moves with what comes back to it, so that a wave much longer than the
box, which no relaxation zone of the box's size can absorb, leaves through the wall
instead of standing in the box.

A near field shorter than the wavelength is, for the waves its bodies scatter and radiate
at the sea's period, a closed tank: its relaxation zones, a few kernel supports wide, hold
the water at the incident velocity and reflect such a wave as a wall would, and the box's
own sloshing builds up (docs/validation/nearfield.md). A piston that absorbs a long
wave moves with the wave's depth-averaged velocity, ``U = (omega / k) eta / d`` for a
progressive wave of elevation ``eta`` (its volume flux ``c eta``): the wall is given that
velocity for the elevation ``eta_s = eta - eta_I`` it finds in front of it beyond the
incident sea's: the shallow-water active absorption reviewed by Schäffer & Klopman 2000
(J. Waterway Port Coastal Ocean Eng. 126(2), 88-97), which DualSPHysics' AWAS applies to
its piston (Altomare et al. 2017, Coastal Eng. 127, 37-54), with the phase speed of the
sea's peak frequency in place of ``sqrt(g d)``.

The elevation in front of the wall is the free surface's (:func:`fluid.probes.surface_elevation`,
where the water's pressure is nil, so that the fluid's compression and its acoustic noise
do not enter) at gauges over a strip of the seabed next to it, averaged with a
sine-squared weight across the strip (and evenly across the box's width in 3-D); the
incident sea's elevation is averaged at the same gauges alike.
Slow changes are not the waves' (the fluid's settling, its level's drift): the reading's
mean is followed with a time constant ``tau`` and taken off, and the correction ``xi``
leaks back to zero at the same rate. Nor are fast ones: the box's acoustic modes (period
``2 L / c0``) move the surface the wall reads, and a wall that answered them would pump
them, so the reading passes two first-order low-passes of time constant ``tau_fast``
first (docs/validation/nearfield.md). So, with ``L`` those two,

    d(xi)/dt = s G (L[eta_s] - <L[eta_s]>) - xi / tau,     G = omega_p / (k_p d),

``s`` +1 at the far end, -1 at the near one (the outward normal along the heading), at
the sea's peak frequency; at ``tau = 2`` and ``tau_fast = 1/40`` peak periods a wave at the
peak passes with 3 % less amplitude and 9 degrees of lag, one at a sixteenth of it with a
seventh. The correction is uniform over the wall (a plane wave along the heading).

Limits: linear, long-wave (the gain of one frequency, the depth-averaged velocity); what a
body sends out obliquely reaches the end wall as the channel's plane mode only where the
box's width is small against the wavelength.
"""

from __future__ import annotations

import math

import numpy as np

from errors import InputError
from fluid.probes import surface_elevation
from fluid.waves import wavenumbers


class StripReader:
    """The free surface (:func:`fluid.probes.surface_elevation`) and the incident sea's
    elevation at the gauges of every absorbing end wall of a box, each read in one pass
    once a step (both ends ask at the end of each step; a pass each would cost twice the
    calls). ``gauges``: 2-D x positions (M,) [m], 3-D (x, y) positions (M, 2) [m]."""

    def __init__(self, sea, gauges):
        g = np.asarray(gauges, float)
        self.sea, self.gauges = sea, g
        gx, gy = (g, np.zeros(g.shape[0])) if g.ndim == 1 else (g[:, 0], g[:, 1])
        self._gx, self._gy = np.ascontiguousarray(gx), np.ascontiguousarray(gy)
        self._surface = (None, None)  # (the fluid's cell list it was read on, the heights)
        self._sea = (math.nan, None)  # (t, the elevations)

    def surface(self, fluid) -> np.ndarray:
        """The free surface's height [m] at every gauge, kept while the fluid's particles stay
        as sorted (each sort makes a new cell list)."""
        fluid.refresh_rates()
        cells, eta = self._surface
        if cells is not fluid.cells_version:
            eta = surface_elevation(fluid, self.gauges)
            self._surface = (fluid.cells_version, eta)
        return eta

    def sea_elevation(self, t: float) -> np.ndarray:
        """The incident sea's elevation [m] above its still level at every gauge at time
        ``t`` [s]."""
        t_kept, eta = self._sea
        if t_kept != t:
            eta = self.sea.elevation(self._gx, self._gy, float(t))
            self._sea = (t, eta)
        return eta


class AbsorbingEnd:
    """The motion ``motion(t, ref) -> (pos, vel)`` of one end wall of a near field
    (``Fluid.prescribe_motion``): the incident sea's orbits (``orbits``, a
    :class:`fluid.nearfield.FollowingWall`) plus a uniform displacement ``xi`` [m] along x
    that absorbs what comes back (module docstring), and the per-step update of ``xi`` from
    the fluid (:meth:`update`, a ``Fluid.controllers`` member).

    ``side``: +1 for the far end (water at x below it), -1 for the near end; ``gauges``:
    where the elevation is read, 2-D x positions (M,) [m], 3-D (x, y) positions (M, 2) [m],
    and ``weights`` (M,) their shares of the reading (summing to 1); ``tau``, ``tau_fast``
    [s]: the filters' time constants (default 2 and 1/40 peak periods); ``reader``: a
    :class:`StripReader` shared with the box's other end wall and ``rows``, this wall's
    gauges among its (default: a reader of this wall's gauges alone)."""

    def __init__(self, sea, orbits, side: int, gauges, weights, tau: float | None = None,
                 tau_fast: float | None = None, reader: StripReader | None = None, rows=None):
        if side not in (-1, 1):
            raise InputError(f"absorbing end wall: side = {side!r}; give +1 (far end) or -1 (near end)")
        g = np.asarray(gauges, float)
        w = np.asarray(weights, float)
        if g.shape[0] == 0 or w.shape != (g.shape[0],) or not abs(w.sum() - 1.0) < 1e-9:
            raise InputError(f"absorbing end wall: {g.shape[0]} gauges with weights of shape {w.shape} summing to "
                             f"{w.sum():.6g}; give one weight per gauge, summing to 1")
        self.sea, self.orbits, self.side = sea, orbits, side
        self.gauges, self.weights = g, w
        if reader is None:
            reader, rows = StripReader(sea, g), slice(None)
        if not np.array_equal(reader.gauges[rows], g):
            raise InputError("absorbing end wall: the shared reader's rows are not this wall's gauges; give the "
                             "rows of its gauges among the reader's")
        self.reader, self.rows = reader, rows
        omega = 2.0 * math.pi / sea.peak_period
        k = float(wavenumbers(omega, sea.depth, sea.g))
        self.gain = omega / (k * sea.depth)
        self.tau = 2.0 * sea.peak_period if tau is None else float(tau)
        self.tau_fast = sea.peak_period / 40.0 if tau_fast is None else float(tau_fast)
        self.reset()

    def reset(self) -> None:
        """Back to the incident sea's orbits alone (no correction, no reading yet)."""
        self.t_n, self.xi_n, self.rate = 0.0, 0.0, 0.0
        self.eta_s = math.nan  #: the last reading [m] (beyond_sea)
        self.fast = [math.nan, math.nan]  #: the reading through the first and both low-passes [m]
        self.mean = math.nan  #: the low-passed reading's slow mean [m]

    _STATE = ("t_n", "xi_n", "rate", "eta_s", "mean")

    def save_state(self) -> dict:
        return {k: getattr(self, k) for k in self._STATE} | {"fast": list(self.fast)}

    def load_state(self, state: dict) -> None:
        for k in self._STATE:
            setattr(self, k, float(state[k]))
        self.fast = [float(v) for v in state["fast"]]

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

    def elevation(self, fluid) -> float:
        """The free surface's elevation [m] over the strip above the sea's still level
        (module docstring); ``fluid``: the ``fluid.solver.Fluid``."""
        return float(self.weights @ self.reader.surface(fluid)[self.rows]) - self.sea.level

    def beyond_sea(self, fluid, t: float) -> float:
        """The elevation [m] over the strip beyond the incident sea's at time ``t`` [s]:
        what comes back to the wall (and the fluid's own offset)."""
        return self.elevation(fluid) - float(self.weights @ self.reader.sea_elevation(t)[self.rows])

    def update(self, fluid, t: float, dt: float) -> None:
        """Read the elevation in front of the wall at the end of a step (time ``t`` [s], the
        step ``dt`` [s]) and set the correction's rate for the next one."""
        self.eta_s = x = self.beyond_sea(fluid, t)
        xi = self.xi(t)
        if math.isnan(self.mean):  # the first reading: the fluid's own offset, not a wave
            self.fast, self.mean = [x, x], x
        a = -math.expm1(-dt / self.tau_fast)
        self.fast[0] += (x - self.fast[0]) * a
        self.fast[1] += (self.fast[0] - self.fast[1]) * a
        self.mean += (self.fast[1] - self.mean) * -math.expm1(-dt / self.tau)
        self.t_n, self.xi_n = float(t), xi
        self.rate = self.side * self.gain * (self.fast[1] - self.mean) - xi / self.tau
