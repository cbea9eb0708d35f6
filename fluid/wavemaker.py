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

The SPH fluid moves a paddle as a MOVING_WALL group placed exactly from a
prescribed motion (``fluid.solver.Fluid.prescribe_motion``; dynamic boundary
particles, Barreiro et al. 2016, §2.6): :func:`piston` translates the group
along x by a displacement history, :func:`flap` rotates it about a hinge line
along y (through ``hinge`` in the x-z plane). The history is a callable
``s(t) -> (value, rate)``: :meth:`RegularWavemaker.motion`, or a record read
from a file (:class:`MotionRecord`, e.g. the measured flap angle of Hadzic et
al. 2005). :meth:`RegularWavemaker.paddle` gives the wall motion directly.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np

from errors import InputError
from fluid.motion import Rotation, Signal, Tabulated, Translation


def wavenumbers(omega, depth: float, g: float = 9.81) -> np.ndarray:
    """k [rad/m] of linear waves of angular frequencies ``omega`` [rad/s] (> 0) in water
    ``depth`` [m] deep: the dispersion relation ω² = g k tanh(k d) (Dean & Dalrymple 1991,
    Table 4.1), by Newton's method from Eckart's (1952) estimate, to round-off."""
    w2 = np.asarray(omega, float) ** 2
    k = w2 / g / np.sqrt(np.tanh(w2 * depth / g))
    for _ in range(50):
        th = np.tanh(k * depth)
        step = (g * k * th - w2) / (g * th + g * k * depth * (1.0 - th * th))
        k = k - step
        if np.all(np.abs(step) <= 1e-15 * k):
            break
    return k


def wavenumber(T: float, depth: float, g: float = 9.81) -> float:
    """k [rad/m] of linear waves of period T [s] in depth [m] (:func:`wavenumbers`)."""
    if not (T > 0 and depth > 0 and g > 0) or not all(map(math.isfinite, (T, depth, g))):
        raise InputError(f"wavenumber: T, depth and g must be finite and > 0, got {T!r}, {depth!r}, {g!r}")
    return float(wavenumbers(2.0 * math.pi / T, depth, g))


def height_to_stroke(kind: str, kd: float) -> float:
    """H/S, wave height over paddle stroke, for ``kind`` "piston" or "flap" (Dean &
    Dalrymple 1991, Eq. 6.21 and 6.22). Beyond kd = 20 the same ratios with the
    hyperbolic functions written through ``a = exp(-kd)``, which do not overflow in deep
    water: piston ``2 (1 - b)^2 / (1 - b^2 + 4 kd b)`` with ``b = a^2``, flap
    ``2 (1 - a^2) (kd (1 - a^2) - (1 - a)^2) / (kd (1 - a^4 + 4 kd a^2))``; their deep-water
    limits are 2 and 2 (kd - 1) / kd."""
    if kind not in ("piston", "flap"):
        raise InputError(f"wavemaker kind must be 'piston' or 'flap', got {kind!r}")
    if kd > 20.0:
        a = math.exp(-kd)
        if kind == "piston":
            b = a * a
            return 2.0 * (1.0 - b) ** 2 / (1.0 - b * b + 4.0 * kd * b)
        return 2.0 * (1.0 - a * a) * (kd * (1.0 - a * a) - (1.0 - a) ** 2) / (kd * (1.0 - a ** 4 + 4.0 * kd * a * a))
    s2, c2 = math.sinh(2 * kd), math.cosh(2 * kd)
    if kind == "piston":
        return 2.0 * (c2 - 1.0) / (s2 + 2.0 * kd)
    return 4.0 * (math.sinh(kd) / kd) * (kd * math.sinh(kd) - math.cosh(kd) + 1.0) / (s2 + 2.0 * kd)


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

    @cached_property
    def k(self) -> float:
        """Wavenumber [rad/m] of the period in the depth (solved once: the paddle's motion
        reads it every step)."""
        return wavenumber(self.T, self.depth, self.g)

    @property
    def wavelength(self) -> float:
        return 2.0 * math.pi / self.k

    @cached_property
    def stroke(self) -> float:
        """Paddle stroke S [m] (piston) or stroke at the still-water level [m] (flap)."""
        return self.H / height_to_stroke(self.kind, self.k * self.depth)

    def _ramp(self, t):
        if np.ndim(t) == 0:  # one time, as a paddle is placed every step: no arrays to make
            t = float(t)
            if self.ramp == 0:
                return 1.0, 0.0
            s = min(max(t / (self.ramp * self.T), 0.0), 1.0)
            r = 0.5 * (1.0 - np.cos(math.pi * s))
            return r, (0.5 * math.pi * np.sin(math.pi * s) / (self.ramp * self.T) if 0.0 < s < 1.0 else 0.0)
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
        t = float(t) if np.ndim(t) == 0 else np.asarray(t, dtype=float)
        return a * r * np.sin(w * t), a * (dr * np.sin(w * t) + r * w * np.cos(w * t))

    def paddle(self, x0: float = 0.0, z_bottom: float = 0.0):
        """The wall motion ``motion(t, ref) -> (pos, vel)`` of this paddle for
        ``Fluid.prescribe_motion``: a piston translates along x; a flap rotates
        about the hinge at the bottom, (``x0``, ``z_bottom``) [m], its angle
        θ = x_swl / depth (the theory's small-angle flap)."""
        if self.kind == "piston":
            return piston(self.motion)
        return flap(self.motion, hinge=(x0, z_bottom))


def _check_history(history, what: str):
    if not callable(history):
        raise InputError(f"{what}: the history is a callable s(t) -> (value, rate), got {history!r}")


@dataclass(frozen=True)
class _History(Signal):
    """A paddle history ``history(t) -> (value, rate)`` as the signal of a rigid wall
    motion (placing a wall needs no second derivative)."""

    history: object

    def state(self, t: float):
        value, rate = self.history(t)
        return float(value), float(rate), math.nan


def piston(displacement):
    """Wall motion of a piston paddle: every particle moves along +x by
    ``displacement(t) -> (x [m], u [m/s])`` from its reference position (2-D or
    3-D): a :class:`fluid.motion.Translation`. Returns ``motion(t, ref) -> (pos, vel)``
    for ``Fluid.prescribe_motion``."""
    _check_history(displacement, "piston")
    signal = _History(displacement)
    by_dim = {2: Translation((1.0, 0.0), signal), 3: Translation((1.0, 0.0, 0.0), signal)}

    def motion(t, ref):
        return by_dim[np.shape(ref)[-1]](t, ref)

    motion.uniform = True  # a translation: every point moves alike
    return motion


def flap(angle, hinge=(0.0, 0.0)):
    """Wall motion of a flap paddle: the particles rotate rigidly about the
    hinge line along y through ``hinge`` = (x, z) [m] by ``angle(t) -> (θ [rad],
    θ' [rad/s])``, θ > 0 turning the top of the flap towards +x (into the water
    of a flume that lies at x > hinge): a point at r = (x, z) from the hinge goes
    to (x cos θ + z sin θ, −x sin θ + z cos θ), velocity θ' (z', −x') (a
    right-handed rotation about +y, :class:`fluid.motion.Rotation`). 2-D (x, z) or
    3-D (x, y, z) reference positions. (The flap record of Hadzic et al. 2005 as
    DualSPHysics ships it is positive the other way: see ``cosim.validations.waves``.)"""
    _check_history(angle, "flap")
    hinge = np.asarray(hinge, float)
    if hinge.shape != (2,) or not np.isfinite(hinge).all():
        raise InputError(f"flap: hinge is the (x, z) point [m] of the hinge line, got {hinge!r}")
    signal = _History(angle)
    x, z = hinge.tolist()
    by_dim = {2: Rotation((x, z), signal), 3: Rotation((x, 0.0, z), signal, axis=(0.0, 1.0, 0.0))}

    def motion(t, ref):
        return by_dim[np.shape(ref)[-1]](t, ref)

    return motion


class MotionRecord:
    """A recorded paddle history, ``s(t) -> (value, rate)``: a cubic spline
    through samples ``(t [s], value)``, held at its end values outside the record
    (rate 0 there). ``scale`` multiplies the values (e.g. ``math.pi / 180`` for an
    angle in degrees); ``t_shift`` [s] is added to the record's times (to start a
    run later in the record, give the run's start time and the record's times
    unchanged). The spline is :class:`fluid.motion.Tabulated`'s displacement record
    (:attr:`signal`), the one interpolation of tabulated motion in the code."""

    def __init__(self, t, value, scale: float = 1.0, t_shift: float = 0.0):
        t = np.asarray(t, float)
        v = np.asarray(value, float) * float(scale)
        if t.ndim != 1 or t.shape != v.shape or t.size < 4:
            raise InputError(f"motion record: need matching 1-D time and value arrays of >= 4 samples, "
                             f"got shapes {t.shape} and {v.shape}")
        if not (np.isfinite(t).all() and np.isfinite(v).all()):
            raise InputError("motion record: times and values must be finite")
        if not (np.diff(t) > 0).all():
            i = int(np.argmin(np.diff(t)))
            raise InputError(f"motion record: times must increase strictly; sample {i + 1} at t={t[i + 1]!r} s "
                             f"follows t={t[i]!r} s")
        self.t = t + float(t_shift)
        self.value = v
        #: the record as a displacement signal (C2 cubic spline, held outside the record)
        self.signal = Tabulated(self.t, v, "displacement")

    @classmethod
    def from_file(cls, path, column: int = 1, scale: float = 1.0, t_shift: float = 0.0) -> "MotionRecord":
        """Read a whitespace- or comma-separated table whose first column is the time
        [s] and whose ``column`` holds the value (non-numeric header lines are
        skipped)."""
        path = Path(path)
        if not path.is_file():
            raise InputError(f"motion record: no file {path}")
        rows = []
        for line in path.read_text().splitlines():
            parts = line.replace(",", " ").split()
            try:
                rows.append((float(parts[0]), float(parts[column])))
            except (ValueError, IndexError):
                if rows:  # a bad line after the data started is an error, a header is not
                    raise InputError(f"motion record {path}: cannot read line {line!r} (time, value in column "
                                     f"{column})") from None
        if not rows:
            raise InputError(f"motion record {path}: no numeric rows")
        a = np.array(rows)
        return cls(a[:, 0], a[:, 1], scale, t_shift)

    def __call__(self, t):
        if np.ndim(t) == 0:
            v, r, _ = self.signal.state(float(t))
            return v, r
        v, r, _ = self.signal.sample(t)
        return v, r
