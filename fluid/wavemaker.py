"""Wavemaker motions: regular waves from linear wavemaker theory, or a record.

A piston (a wall translating in x) or a flap (a wall hinged at the bottom,
rotating about y) in water of depth ``d`` makes, far from the paddle, a
progressive wave of height ``H`` and period ``T`` when its stroke ``S`` (the
double amplitude of the paddle at the still-water level) obeys linear wavemaker
theory (Biésel & Suquet 1951; Dean & Dalrymple 1991, §6.2), with ``k`` the
wavenumber of the dispersion relation ``ω² = g k tanh(k d)``:

    piston:  H / S = 2 (cosh 2kd − 1) / (sinh 2kd + 2kd)
    flap:    H / S = 4 (sinh kd / kd) (kd sinh kd − cosh kd + 1) / (sinh 2kd + 2kd)

Shallow water (kd → 0): piston H/S → kd, flap H/S → kd/2; deep water: 2 and 2.
The motion starts with a smooth ramp (half a cosine over ``ramp`` periods) so
the paddle sets off without a jump in acceleration.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from cosim.errors import InputError


def wavenumber(T: float, depth: float, g: float = 9.81) -> float:
    """k [rad/m] of linear waves of period T [s] in depth [m]: ω² = g k tanh(k d),
    by Newton from the Eckart (1952) estimate (a handful of iterations to 1e-15)."""
    if not (T > 0 and depth > 0 and g > 0) or not all(map(math.isfinite, (T, depth, g))):
        raise InputError(f"wavenumber: T, depth and g must be finite and > 0, got {T!r}, {depth!r}, {g!r}")
    w2 = (2.0 * math.pi / T) ** 2
    k = w2 / g / math.sqrt(math.tanh(w2 * depth / g))  # Eckart
    for _ in range(50):
        th = math.tanh(k * depth)
        f = g * k * th - w2
        df = g * th + g * k * depth * (1.0 - th * th)
        step = f / df
        k -= step
        if abs(step) <= 1e-15 * k:
            break
    return k


def height_to_stroke(kind: str, kd: float) -> float:
    """H/S, wave height over paddle stroke, for ``kind`` "piston" or "flap"."""
    s2, c2 = math.sinh(2 * kd), math.cosh(2 * kd)
    if kind == "piston":
        return 2.0 * (c2 - 1.0) / (s2 + 2.0 * kd)
    if kind == "flap":
        return 4.0 * (math.sinh(kd) / kd) * (kd * math.sinh(kd) - math.cosh(kd) + 1.0) / (s2 + 2.0 * kd)
    raise InputError(f"wavemaker kind must be 'piston' or 'flap', got {kind!r}")


@dataclass(frozen=True)
class RegularWavemaker:
    """A paddle making regular waves of height ``H`` [m] and period ``T`` [s] in
    water of depth ``depth`` [m]; ``kind`` "piston" or "flap"; the motion ramps in
    over ``ramp`` periods (>= 0). ``g`` [m/s^2]."""

    kind: str
    H: float
    T: float
    depth: float
    ramp: float = 2.0
    g: float = 9.81

    def __post_init__(self):
        for name in ("H", "T", "depth", "g"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise InputError(f"wavemaker: {name} must be finite and > 0, got {v!r}")
        if not (math.isfinite(self.ramp) and self.ramp >= 0):
            raise InputError(f"wavemaker: ramp must be a number of periods >= 0, got {self.ramp!r}")
        height_to_stroke(self.kind, 1.0)  # checks the kind
        if self.H / self.wavelength > 1.0 / 7.0:
            raise InputError(f"wavemaker: H/λ = {self.H / self.wavelength:.3f} is beyond the breaking limit 1/7; "
                             f"lower H or lengthen T")

    @property
    def k(self) -> float:
        return wavenumber(self.T, self.depth, self.g)

    @property
    def wavelength(self) -> float:
        return 2.0 * math.pi / self.k

    @property
    def stroke(self) -> float:
        """Paddle stroke S [m] (piston) or stroke at the still-water level [m] (flap)."""
        return self.H / height_to_stroke(self.kind, self.k * self.depth)

    def _ramp(self, t):
        t = np.asarray(t, dtype=float)
        if self.ramp == 0:
            return np.ones_like(t), np.zeros_like(t)
        s = np.clip(t / (self.ramp * self.T), 0.0, 1.0)
        r = 0.5 * (1.0 - np.cos(math.pi * s))
        dr = np.where((s > 0) & (s < 1), 0.5 * math.pi * np.sin(math.pi * s) / (self.ramp * self.T), 0.0)
        return r, dr

    def motion(self, t):
        """Paddle displacement and velocity at times ``t`` [s]: for a piston [m],
        [m/s]; for a flap the rotation angle [rad] and rate [rad/s] about the hinge
        (positive towards the waves, small-angle: θ = x_swl / depth)."""
        w = 2.0 * math.pi / self.T
        a = 0.5 * self.stroke if self.kind == "piston" else 0.5 * self.stroke / self.depth
        r, dr = self._ramp(t)
        t = np.asarray(t, dtype=float)
        return a * r * np.sin(w * t), a * (dr * np.sin(w * t) + r * w * np.cos(w * t))
