"""The SPH domain of a scene whose tank moves (``base_motion``): the box outside which the
fluid removes particles (``fluid.solver.FluidConfig.domain_lo`` / ``domain_hi``).

Without it the solver takes the particles' extent at the start grown by the larger of 10 %
and 4 h on every side. A shaken tank leaves that box: a0 sin(2 pi t / T) from rest drifts
a0 T^2 / (2 pi) a period (Sunara et al. 2021, §3.1: 2.34 m over three periods of 0.5 g at
T = 1 s), and the water it throws up rises above its walls, so walls and splashes would be
removed. Here the box is

- the extent of every particle at the start (walls and water), moved by the tank's motion
  over the run and the union taken: the motion applied to the extent's corners at times
  sampled over [0, duration] (exact for a translation; for a roll the rotated corners'
  box holds the rotated tank);
- grown by the solver's own margin, the larger of 10 % of the extent and 4 h, on every
  side (what a tank at rest gets);
- and above, by the tank's own height (walls included) again: water leaving the box must
  rise above the wall tops by as much as the tank is tall, at a speed at the wall top of
  at least sqrt(2 g H) (5.9 m/s for a 1.8 m tank), beyond the tank's own speeds and the
  sloshing's (Sunara et al. 2021's 0.5 g in the 3 m tank climbs ~0.9 m above its still
  level, within 1.5 m walls). Such water, were it ever thrown, is removed and counted.

The box and why are reported in ``summary.json`` (``sph_domain``).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

#: the samples of the motion over the run: at least this many, and this many a period
SAMPLES, PER_PERIOD = 4001, 64


@dataclass(frozen=True)
class MovingDomain:
    """The domain box [m] and what it is made of (module docstring): ``start`` the
    particles' extent at the start, ``travel`` the range of the tank's displacement over
    the run (lower, upper corner), ``pad`` the solver's margin per axis, ``splash`` the room
    above, ``reasons`` in words."""

    lo: tuple
    hi: tuple
    start: tuple
    travel: tuple
    pad: tuple
    splash: float
    reasons: dict

    def as_dict(self) -> dict:
        return {"lo_m": list(self.lo), "hi_m": list(self.hi), "start_m": [list(c) for c in self.start],
                "travel_m": [list(c) for c in self.travel], "pad_m": list(self.pad), "splash_m": self.splash,
                "reasons": dict(self.reasons)}


def sample_times(duration: float, period: float | None = None) -> np.ndarray:
    """Times [s] over [0, ``duration``] at which the motion is sampled: :data:`SAMPLES` at
    least and :data:`PER_PERIOD` a ``period`` [s] (a harmonic's extreme is then missed by at
    most 1 - cos(pi / 64) = 0.12 % of its amplitude, well inside the 4 h margin)."""
    n = SAMPLES if period is None else max(SAMPLES, math.ceil(PER_PERIOD * duration / period) + 1)
    return np.linspace(0.0, duration, n)


def moving_tank_domain(points: np.ndarray, motion, times: np.ndarray, h: float) -> MovingDomain:
    """The domain of particles ``points`` (n, dim) [m] at t = 0 whose tank moves by
    ``motion`` (``motion(t, ref) -> (pos, vel)``, :mod:`fluid.motion`) at ``times`` [s],
    at smoothing length ``h`` [m] (module docstring)."""
    pts = np.asarray(points, float)
    lo0, hi0 = pts.min(axis=0), pts.max(axis=0)
    corners = np.array(list(itertools.product(*zip(lo0, hi0))))
    moved = np.concatenate([motion(float(t), corners)[0] for t in times])
    lo1, hi1 = np.minimum(moved.min(axis=0), lo0), np.maximum(moved.max(axis=0), hi0)
    pad = np.maximum(0.1 * (hi0 - lo0), 4.0 * h)
    splash = float(hi0[-1] - lo0[-1])
    lo, hi = lo1 - pad, hi1 + pad
    hi[-1] += splash
    span = f"{times[0]:g}-{times[-1]:g} s"
    travel = f"{np.round(lo1 - lo0, 4).tolist()} .. {np.round(hi1 - hi0, 4).tolist()} m"
    reasons = {"travel": f"the tank's extent at the start moved by its motion over {span} ({len(times)} samples), "
                         f"the union: it travels {travel}",
               "pad": f"the solver's margin on every side, the larger of 10 % of the extent and 4 h = {4 * h:g} m",
               "splash": f"{splash:g} m above, the tank's own height: water leaving the box would rise that far "
                         "above the wall tops"}
    return MovingDomain(tuple(lo.tolist()), tuple(hi.tolist()), (tuple(lo0.tolist()), tuple(hi0.tolist())),
                        (tuple((lo1 - lo0).tolist()), tuple((hi1 - hi0).tolist())), tuple(pad.tolist()), splash,
                        reasons)
