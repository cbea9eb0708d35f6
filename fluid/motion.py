"""Base-excitation motions of rigid boundary groups, for :meth:`fluid.solver.Fluid.prescribe_motion`.

A motion is a rigid translation or rotation driven by one scalar *signal* of time:

- :class:`Translation`: ``pos = ref + s(t) e`` along a unit direction ``e`` (``s`` in m);
- :class:`Rotation`: ``pos = c + R(θ(t)) (ref - c)`` about an axis through the point ``c``
  (``θ`` in rad; 2-D: about +y in the x-z plane, as a rolling tank).

Signals give value, first and second derivative at any time, and the derivatives are the
exact derivatives of the value (no finite differences), so the particle velocities a motion
returns are the exact time derivatives of the positions it returns:

- :class:`Harmonic`: ``A sin(ω t + φ)``, from its amplitude or its peak acceleration, either
  as a steady oscillation or started from rest (same acceleration, no jump in velocity);
- :class:`Tabulated`: a record of displacement, velocity or acceleration against time,
  interpolated (C2 cubic spline for displacement and velocity, piecewise linear for
  acceleration as seismic records are sampled) and integrated exactly to displacement;
- :class:`Polyline`: straight between given points (a test rig's constant speeds and holds);
- :class:`Ramped`: any signal multiplied by a half-cosine window rising over ``t_ramp``
  (and optionally falling to zero at ``t_stop``), so that a motion sets off and stops without
  a jump in velocity or acceleration;
- :class:`Combined`: several translations at once, each with its own direction and
  signal (horizontal and vertical ground motion);
- :func:`read_at2`: a PEER NGA ``.AT2`` accelerogram (acceleration in g) as a
  :class:`Tabulated` acceleration record in m/s^2, with :func:`baseline_correct`.

Baseline correction (:func:`baseline_correct`): a recorded accelerogram integrated twice
drifts (a small offset in acceleration grows quadratically in displacement), so a table
shaking the tank would wander off and end moving. The papers do not say how they processed
their records (Wang et al. 2022, §4.1), so we use the classical polynomial fit to the
displacement (Boore 2001, BSSA 91(5) 1199-1211; Boore, Stephens & Joyner 2002, BSSA 92(4)
1543-1560; a step of the PEER processing): the least-squares polynomial
``q(t) = sum_{k=2..n} c_k t^k`` is fitted to the displacement subject to ``q(T) = d(T)`` and
``q'(T) = v(T)``, and removed from displacement, velocity and acceleration. Starting at
``t^2`` keeps the start at rest; the two constraints make the corrected record end at rest
exactly; the change of the acceleration is the smooth ``q''(t)``, small where the drift is.
The fit cannot tell drift from motion as slow as the record itself (one slow pulse of
displacement is erased with its drift; PEER's processed records end at rest already:
``tests/test_records.py``); ``baseline_degree=None`` (:func:`read_at2`) keeps a record as it is.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property
from pathlib import Path

import numpy as np

from errors import InputError

G_STANDARD = 9.80665  #: standard gravity [m/s^2], the unit "g" of accelerograms

QUANTITIES = ("displacement", "velocity", "acceleration")


def _finite(name: str, v, positive: bool = False) -> float:
    ok = isinstance(v, (int, float, np.floating, np.integer)) and not isinstance(v, bool) and math.isfinite(v)
    if not ok or (positive and v <= 0):
        raise InputError(f"{name}={v!r}: give a finite{' positive' if positive else ''} number")
    return float(v)


# ---------------------------------------------------------------------------------------- signals
class Signal:
    """A scalar function of time ``s(t)`` with exact derivatives. Subclasses define
    :meth:`state`; ``signal(t)`` returns ``(s, ds/dt)``."""

    def state(self, t: float):
        """``(s, ds/dt, d2s/dt2)`` at time ``t`` [s]."""
        raise NotImplementedError

    def __call__(self, t: float):
        s, ds, _ = self.state(t)
        return s, ds


@dataclass(frozen=True)
class Harmonic(Signal):
    """``s(t) = amplitude sin(2 pi t / period + phase)``.

    amplitude: [m] for a translation, [rad] for a rotation (may be negative); period [s];
    phase [rad]. ``from_rest=True`` subtracts the linear function of t that makes
    ``s(0) = s'(0) = 0``: the acceleration is the same sinusoid, the motion starts at rest
    and drifts at the mean velocity ``-A w cos(phase)`` (Sunara et al. 2021, §3.1
    prescribes the ground *acceleration* a0 sin(2 pi t / Tp), Fig. 3).
    """

    amplitude: float
    period: float
    phase: float = 0.0
    from_rest: bool = False

    def __post_init__(self):
        _finite("amplitude", self.amplitude)
        _finite("period [s]", self.period, positive=True)
        _finite("phase [rad]", self.phase)
        if not isinstance(self.from_rest, bool):
            raise InputError(f"from_rest={self.from_rest!r}: give True or False")

    @classmethod
    def from_peak_acceleration(cls, peak_acceleration: float, period: float, phase: float = 0.0,
                               from_rest: bool = False) -> "Harmonic":
        """The signal whose second derivative is ``peak_acceleration sin(2 pi t / period +
        phase)`` (peak_acceleration [m/s^2] or [rad/s^2], period [s], phase [rad])."""
        a0 = _finite("peak_acceleration", peak_acceleration)
        w = 2 * math.pi / _finite("period [s]", period, positive=True)
        return cls(-a0 / w**2, period, phase, from_rest)

    @property
    def omega(self) -> float:
        """Angular frequency [rad/s]."""
        return 2 * math.pi / self.period

    @property
    def peak_acceleration(self) -> float:
        """Amplitude of the second derivative [m/s^2] or [rad/s^2]."""
        return abs(self.amplitude) * self.omega**2

    def state(self, t):
        A, w, ph = self.amplitude, self.omega, self.phase
        s = A * math.sin(w * t + ph)
        ds = A * w * math.cos(w * t + ph)
        dds = -A * w * w * math.sin(w * t + ph)
        if self.from_rest:
            s -= A * math.sin(ph) + A * w * math.cos(ph) * t
            ds -= A * w * math.cos(ph)
        return s, ds, dds


@dataclass(frozen=True)
class Tabulated(Signal):
    """A record ``values`` against ``times`` [s] of one quantity: "displacement" ([m] or
    [rad]), "velocity" ([m/s] or [rad/s]) or "acceleration" ([m/s^2] or [rad/s^2]).

    Interpolation: a displacement is a C2 cubic spline through the samples, its velocity
    and acceleration the spline's derivatives; a velocity is a cubic spline integrated
    exactly from ``s(t0) = 0``; an acceleration is piecewise linear between samples (how
    accelerograms are integrated, e.g. Newmark's linear-acceleration assumption) and
    integrated exactly twice from rest. Before the first sample the signal holds its
    first value (velocity and acceleration zero); after the last it holds the final
    displacement with zero velocity; a velocity or acceleration record that does not end
    at rest therefore stops abruptly: use :func:`baseline_correct`, or a :class:`Ramped`
    window. ``baseline`` holds the coefficients ``c_k`` of ``q(t - t0) = sum c_k
    (t - t0)^k`` removed from the record (set by :func:`baseline_correct`).
    """

    times: tuple
    values: tuple
    quantity: str = "displacement"
    baseline: tuple = ()
    _pp: tuple = field(default=(), repr=False, compare=False)

    def __post_init__(self):
        if self.quantity not in QUANTITIES:
            raise InputError(f"Tabulated: quantity={self.quantity!r}; choose one of {QUANTITIES}")
        t = np.asarray(self.times, np.float64)
        v = np.asarray(self.values, np.float64)
        if t.ndim != 1 or v.shape != t.shape:
            raise InputError(f"Tabulated: times and values must be 1-D of one length, got shapes "
                             f"{t.shape} and {v.shape}")
        if t.size < 2:
            raise InputError("Tabulated: a record needs at least 2 samples")
        if not (np.isfinite(t).all() and np.isfinite(v).all()):
            raise InputError("Tabulated: the record holds non-finite times or values; clean it first")
        if not (np.diff(t) > 0).all():
            k = int(np.argmax(np.diff(t) <= 0))
            raise InputError(f"Tabulated: times must increase strictly; sample {k + 1} (t={t[k + 1]} s) "
                             f"does not follow t={t[k]} s (sort the record and drop repeated times)")
        c = np.asarray(self.baseline, np.float64)
        if c.ndim != 1 or not np.isfinite(c).all():
            raise InputError(f"Tabulated: baseline must be a flat tuple of finite coefficients, got {self.baseline!r}")
        from scipy.interpolate import CubicSpline, PPoly  # here: half a second off the start of a run without a record

        if self.quantity == "displacement":
            d = CubicSpline(t, v)
        elif self.quantity == "velocity":
            d = CubicSpline(t, v).antiderivative()
        else:
            lin = PPoly(np.vstack([np.diff(v) / np.diff(t), v[:-1]]), t)
            d = lin.antiderivative(2)
        object.__setattr__(self, "times", tuple(t.tolist()))
        object.__setattr__(self, "values", tuple(v.tolist()))
        object.__setattr__(self, "baseline", tuple(c.tolist()))
        q = np.polynomial.Polynomial(c if c.size else [0.0])
        object.__setattr__(self, "_pp", (d, d.derivative(), d.derivative(2), q, q.deriv(), q.deriv(2)))

    @property
    def duration(self) -> float:
        """Length of the record [s]."""
        return self.times[-1] - self.times[0]

    def state(self, t):
        t0, t1 = self.times[0], self.times[-1]
        d, v, a, q, dq, ddq = self._pp
        if t <= t0:
            return float(d(t0) - q(0.0)), 0.0, 0.0
        if t >= t1:
            return float(d(t1) - q(t1 - t0)), 0.0, 0.0
        # one interval's cubic by Horner (PPoly.__call__ costs ~0.1 ms a call on long
        # records, and a motion is evaluated three times per fluid step)
        x = d.x
        i = min(max(int(np.searchsorted(x, t, side="right")) - 1, 0), x.size - 2)
        c = d.c[:, i].tolist()
        s = t - float(x[i])
        val = der = dd = 0.0
        for ck in c:  # value, first and second derivative together
            dd = dd * s + 2.0 * der
            der = der * s + val
            val = val * s + ck
        qv = qd = qdd = 0.0
        tau = t - t0
        for ck in reversed(self.baseline):
            qdd = qdd * tau + 2.0 * qd
            qd = qd * tau + qv
            qv = qv * tau + ck
        return float(val - qv), float(der - qd), float(dd - qdd)

    def sample(self, t):
        """``(s, ds/dt, d2s/dt2)`` as arrays at the times ``t`` [s] (vectorised)."""
        t = np.asarray(t, np.float64)
        d, v, a, q, dq, ddq = self._pp
        t0, t1 = self.times[0], self.times[-1]
        tc = np.clip(t, t0, t1)
        inside = (t > t0) & (t < t1)
        tau = tc - t0
        return (d(tc) - q(tau), np.where(inside, v(tc) - dq(tau), 0.0),
                np.where(inside, a(tc) - ddq(tau), 0.0))


@dataclass(frozen=True)
class Polyline(Signal):
    """A displacement through the points (``times`` [s], ``values`` [m] or [rad]), straight
    between them: constant velocity on each interval (the slope of the interval that ``t``
    lies in, the later one at a point), zero acceleration. Before the first point it holds
    the first value, after the last the last, at rest. What a test rig does that moves a
    fairlead at constant speed, holds it, or steps it through a list of offsets; the
    velocity jumps at each point, so a motion that
    must start and stop smoothly is a :class:`Tabulated` spline or a :class:`Ramped` one."""

    times: tuple
    values: tuple

    def __post_init__(self):
        t = np.asarray(self.times, np.float64)
        v = np.asarray(self.values, np.float64)
        if t.ndim != 1 or v.shape != t.shape or t.size < 2:
            raise InputError(f"Polyline: times and values must be 1-D of one length, at least 2, got shapes "
                             f"{t.shape} and {v.shape}")
        if not (np.isfinite(t).all() and np.isfinite(v).all()):
            raise InputError("Polyline: the points hold non-finite times or values")
        if not (np.diff(t) > 0).all():
            k = int(np.argmax(np.diff(t) <= 0))
            raise InputError(f"Polyline: times must increase strictly; point {k + 1} (t={t[k + 1]} s) does not "
                             f"follow t={t[k]} s")
        object.__setattr__(self, "times", tuple(t.tolist()))
        object.__setattr__(self, "values", tuple(v.tolist()))

    def state(self, t):
        ts, vs = self.times, self.values
        if t < ts[0]:
            return vs[0], 0.0, 0.0
        if t >= ts[-1]:
            return vs[-1], 0.0, 0.0
        i = int(np.searchsorted(ts, t, side="right")) - 1
        rate = (vs[i + 1] - vs[i]) / (ts[i + 1] - ts[i])
        return vs[i] + rate * (t - ts[i]), rate, 0.0


def baseline_correct(record: Tabulated, degree: int = 6) -> Tabulated:
    """The record with the polynomial baseline ``q(t) = sum_{k=2..degree} c_k (t - t0)^k``
    removed (module docstring: least-squares fit to the displacement, constrained so that
    the corrected displacement and velocity are exactly zero at the end; ``degree`` [-]
    from 3 to 12). Works for any quantity: the constraint and the fit use the exactly
    integrated displacement and velocity of the record."""
    if not isinstance(record, Tabulated):
        raise InputError(f"baseline_correct needs a Tabulated record, got {type(record).__name__}")
    if not isinstance(degree, int) or not 3 <= degree <= 12:
        raise InputError(f"baseline_correct: degree={degree!r}; use an integer from 3 to 12 "
                         "(3 is the least that meets both end conditions, 6 is usual)")
    plain = replace(record, baseline=())
    t = np.asarray(plain.times)
    T = t[-1] - t[0]
    d, v, _, _, _, _ = plain._pp
    # fit on a uniform grid (the record's own samples may be uneven), in the scaled time
    # x = tau / T, so that the normal equations stay well conditioned
    tau = np.linspace(0.0, T, max(4 * degree, min(t.size, 20000)))
    x = tau / T
    k = np.arange(2, degree + 1)
    B = x[:, None] ** k                       # least-squares basis x^k
    C = np.vstack([np.ones_like(k, float),    # q(T) = d(T):   sum b_k = d(T)
                   k.astype(float) / T])      # q'(T) = v(T): sum k b_k / T = v(T)
    rhs = np.array([float(d(t[-1])), float(v(t[-1]))])
    n = k.size
    kkt = np.zeros((n + 2, n + 2))
    kkt[:n, :n] = 2 * B.T @ B
    kkt[:n, n:] = C.T
    kkt[n:, :n] = C
    sol = np.linalg.solve(kkt, np.concatenate([2 * B.T @ d(tau + t[0]), rhs]))
    b = sol[:n]
    coef = np.zeros(degree + 1)
    coef[2:] = b / T**k                       # back to powers of tau [s]
    return replace(plain, baseline=tuple(coef.tolist()))


@dataclass(frozen=True)
class Stopped(Signal):
    """``signal`` brought to rest at ``stop`` [s]: the signal itself until ``stop - fade``,
    then its velocity faded out by the half cosine ``w(t) = (1 + cos(pi (t - stop + fade)
    / fade)) / 2`` over ``fade`` [s], at rest from ``stop`` on where that leaves it:

        s(t) = s(t1) + integral_t1^t w v dt',  v_stopped = w v,  a_stopped = w a + w' v

    (t1 = stop - fade). Velocity and acceleration stay continuous (w' = 0 at both ends);
    the deceleration is about pi v(t1) / (2 fade). The shaking before ``t1`` is exactly
    the signal's (a record's free response after an earthquake that ends at ``stop``;
    cutting the accelerogram and correcting its baseline anew would change the whole
    shaking). The integral is a cubic spline's antiderivative through ``w v`` sampled
    every fade / 4000.

    ``fade = 0``: the signal cut at ``stop`` and held there, ``s(t) = s(stop)`` after it.
    The velocity then jumps from ``v(stop)`` to zero, so give a ``stop`` where the signal
    is at rest (a0 sin(w t) from rest after whole periods, where its acceleration is zero
    too: Sunara et al. 2021, §3.1's excitation stopped without an impulse)."""

    signal: Signal
    stop: float
    fade: float = 0.5
    _pp: tuple = field(default=(), repr=False, compare=False)

    def __post_init__(self):
        if not isinstance(self.signal, Signal):
            raise InputError(f"Stopped: signal must be a Signal (Harmonic, Tabulated, ...), got {self.signal!r}")
        stop, fade = _finite("stop [s]", self.stop), _finite("fade [s]", self.fade)
        if fade < 0:
            raise InputError(f"Stopped: fade={self.fade!r} s; give 0 (cut and hold at stop) or a positive fade time")
        if fade == 0:
            object.__setattr__(self, "_pp", (float(self.signal.state(stop)[0]), None))
            return
        from scipy.interpolate import CubicSpline

        t1 = stop - fade
        t = np.linspace(t1, stop, 4001)
        st = np.array([self.signal.state(float(x)) for x in t])
        wv = 0.5 * (1.0 + np.cos(np.pi * (t - t1) / fade)) * st[:, 1]
        object.__setattr__(self, "_pp", (float(st[0, 0]), CubicSpline(t, wv).antiderivative()))

    def state(self, t):
        t1 = self.stop - self.fade
        if t <= t1:
            return self.signal.state(t)
        s1, integral = self._pp
        if integral is None:  # cut and held
            return s1, 0.0, 0.0
        if t >= self.stop:
            return s1 + float(integral(self.stop)), 0.0, 0.0
        k = math.pi / self.fade
        w, dw = 0.5 * (1.0 + math.cos(k * (t - t1))), -0.5 * k * math.sin(k * (t - t1))
        _, v, a = self.signal.state(t)
        return s1 + float(integral(t)), w * v, w * a + dw * v


@dataclass(frozen=True)
class Ramped(Signal):
    """``w(t) s(t)``: the signal ``signal`` faded in by the half-cosine window
    ``w = (1 - cos(pi (t - t_start) / t_ramp)) / 2`` over ``t_ramp`` [s] from ``t_start``
    [s], and, if ``t_stop`` [s] is given, faded out over the ``t_ramp`` before ``t_stop``
    (zero after it). The window has a continuous first derivative, so the motion's
    velocity is continuous; its acceleration jumps by at most ``(pi/t_ramp)^2 s / 2``."""

    signal: Signal
    t_ramp: float
    t_start: float = 0.0
    t_stop: float | None = None

    def __post_init__(self):
        if not isinstance(self.signal, Signal):
            raise InputError(f"Ramped: signal must be a Signal (Harmonic, Tabulated, ...), got {self.signal!r}")
        _finite("t_ramp [s]", self.t_ramp, positive=True)
        _finite("t_start [s]", self.t_start)
        if self.t_stop is not None:
            _finite("t_stop [s]", self.t_stop)
            if self.t_stop < self.t_start + 2 * self.t_ramp:
                raise InputError(f"Ramped: t_stop={self.t_stop} s leaves no room for the ramps in and out "
                                 f"(needs t_stop >= t_start + 2 t_ramp = {self.t_start + 2 * self.t_ramp} s)")

    def window(self, t):
        """``(w, dw/dt, d2w/dt2)`` at time ``t`` [s]."""
        k = math.pi / self.t_ramp
        if t <= self.t_start or (self.t_stop is not None and t >= self.t_stop):
            return 0.0, 0.0, 0.0
        if t < self.t_start + self.t_ramp:
            x = k * (t - self.t_start)
            return 0.5 * (1 - math.cos(x)), 0.5 * k * math.sin(x), 0.5 * k * k * math.cos(x)
        if self.t_stop is not None and t > self.t_stop - self.t_ramp:
            x = k * (self.t_stop - t)
            return 0.5 * (1 - math.cos(x)), -0.5 * k * math.sin(x), 0.5 * k * k * math.cos(x)
        return 1.0, 0.0, 0.0

    def state(self, t):
        w, dw, ddw = self.window(t)
        if w == 0.0 and dw == 0.0:
            return 0.0, 0.0, 0.0
        s, ds, dds = self.signal.state(t)
        return w * s, dw * s + w * ds, ddw * s + 2 * dw * ds + w * dds


# ---------------------------------------------------------------------------------------- motions
def _check_signal(owner: str, signal):
    if not isinstance(signal, Signal):
        raise InputError(f"{owner}: signal must be a Signal (Harmonic, Tabulated, Ramped), got {signal!r}")


def _check_ref(owner: str, ref: np.ndarray, dim: int) -> np.ndarray:
    ref = np.asarray(ref, np.float64)
    if ref.ndim != 2 or ref.shape[1] != dim:
        raise InputError(f"{owner}: reference positions must be (N, {dim}) for this {dim}-D motion, "
                         f"got shape {ref.shape}; give the direction/axis with as many components as the fluid's dim")
    return ref


@dataclass(frozen=True)
class Translation:
    """Rigid translation ``pos = ref + s(t) e``, ``vel = s'(t) e`` along the unit vector of
    ``direction`` (2 components (x, z) in 2-D, 3 in 3-D; any length, it is normalised);
    ``signal`` in m. A callable for :meth:`fluid.solver.Fluid.prescribe_motion`."""

    direction: tuple
    signal: Signal
    #: every point moves alike (``Fluid.prescribed_acceleration`` differences one of them)
    uniform = True

    def __post_init__(self):
        e = np.asarray(self.direction, np.float64)
        if e.shape not in ((2,), (3,)) or not np.isfinite(e).all() or np.linalg.norm(e) == 0:
            raise InputError(f"Translation: direction={self.direction!r}; give 2 (x, z) or 3 (x, y, z) "
                             "finite components, not all zero")
        _check_signal("Translation", self.signal)
        object.__setattr__(self, "direction", tuple((e / np.linalg.norm(e)).tolist()))

    def __call__(self, t: float, ref):
        e = self._e
        ref = _check_ref("Translation", ref, e.size)
        s, ds = self.signal(t)
        vel = np.empty_like(ref)
        vel[:] = ds * e
        return ref + s * e, vel

    @cached_property
    def _e(self) -> np.ndarray:
        """The unit direction as an array (made once: a paddle is placed every step)."""
        return np.asarray(self.direction)

    def acceleration(self, t: float) -> np.ndarray:
        """Acceleration of every point [m/s^2] (dim,)."""
        return self.signal.state(t)[2] * np.asarray(self.direction)

    def ramped(self, t_ramp: float, t_start: float = 0.0, t_stop: float | None = None) -> "Translation":
        """This motion faded in (and out) by :class:`Ramped` (times in s)."""
        return replace(self, signal=Ramped(self.signal, t_ramp, t_start, t_stop))


def _rotation_matrix(axis: np.ndarray, angle: float) -> np.ndarray:
    """Right-handed rotation by ``angle`` [rad] about the unit ``axis`` (Rodrigues)."""
    K = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


@dataclass(frozen=True)
class Rotation:
    """Rigid rotation by the angle ``signal`` θ(t) [rad] about an axis through ``point``
    [m]: ``pos = c + R(θ) (ref - c)``, ``vel = θ' a x (pos - c)``, right-handed about the
    unit ``axis``. 2-D: ``point`` is (x, z) and the axis is +y (leave ``axis`` None); a
    positive θ turns +x towards -z: ``x' = x cos θ + z sin θ``, ``z' = -x sin θ + z cos θ``
    (relative to the point). 3-D: ``point`` (x, y, z) and ``axis`` (3 components, any
    length). A callable for :meth:`fluid.solver.Fluid.prescribe_motion`."""

    point: tuple
    signal: Signal
    axis: tuple | None = None

    def __post_init__(self):
        c = np.asarray(self.point, np.float64)
        if c.shape not in ((2,), (3,)) or not np.isfinite(c).all():
            raise InputError(f"Rotation: point={self.point!r}; give (x, z) in 2-D or (x, y, z) in 3-D [m]")
        _check_signal("Rotation", self.signal)
        if c.size == 2:
            if self.axis is not None and not np.allclose(np.asarray(self.axis, float) / np.linalg.norm(self.axis),
                                                         (0.0, 1.0, 0.0)):
                raise InputError(f"Rotation: axis={self.axis!r} with a 2-D point; 2-D rotations are about +y "
                                 "(leave axis None, or give a 3-D point)")
            axis = (0.0, 1.0, 0.0)
        else:
            a = np.asarray(self.axis if self.axis is not None else (), np.float64)
            if a.shape != (3,) or not np.isfinite(a).all() or np.linalg.norm(a) == 0:
                raise InputError(f"Rotation: axis={self.axis!r}; a 3-D rotation needs an axis of 3 finite "
                                 "components, not all zero")
            axis = tuple((a / np.linalg.norm(a)).tolist())
        object.__setattr__(self, "point", tuple(c.tolist()))
        object.__setattr__(self, "axis", axis)

    def __call__(self, t: float, ref):
        c = np.asarray(self.point)
        ref = _check_ref("Rotation", ref, c.size)
        th, dth = self.signal(t)
        a = np.asarray(self.axis)
        if c.size == 2:
            cs, sn = math.cos(th), math.sin(th)
            r = ref - c
            x = cs * r[:, 0] + sn * r[:, 1]
            z = -sn * r[:, 0] + cs * r[:, 1]
            pos = np.stack([x, z], axis=1) + c
            # omega = dth * (+y): omega x r = (dth r_z, -dth r_x) in (x, z)
            vel = np.stack([dth * z, -dth * x], axis=1)
            return pos, vel
        r = (ref - c) @ _rotation_matrix(a, th).T
        return c + r, dth * np.cross(a, r)

    def ramped(self, t_ramp: float, t_start: float = 0.0, t_stop: float | None = None) -> "Rotation":
        """This motion faded in (and out) by :class:`Ramped` (times in s)."""
        return replace(self, signal=Ramped(self.signal, t_ramp, t_start, t_stop))


@dataclass(frozen=True)
class Combined:
    """Rigid translation by several independent components at once (a ground motion of
    horizontal and vertical records, Wang et al. 2022, §4.2: "El Centro NS +
    vertical"): ``pos = ref + sum_k s_k(t) e_k``, ``vel = sum_k s_k'(t) e_k``, each
    component a :class:`Translation` with its own direction ``e_k`` and signal ``s_k`` (in
    m). The directions need not be orthogonal; all have the same number of components (2:
    (x, z), or 3). A callable for :meth:`fluid.solver.Fluid.prescribe_motion`."""

    components: tuple
    #: every point moves alike (``Fluid.prescribed_acceleration`` differences one of them)
    uniform = True

    def __post_init__(self):
        comps = tuple(self.components) if isinstance(self.components, (tuple, list)) else ()
        if not comps or not all(isinstance(c, Translation) for c in comps):
            raise InputError(f"Combined: components must be a non-empty list of Translation, got {self.components!r}")
        dims = {len(c.direction) for c in comps}
        if len(dims) != 1:
            raise InputError(f"Combined: the components' directions have {sorted(dims)} coordinates; give all of "
                             "them as (x, z) in 2-D or all as (x, y, z) in 3-D")
        object.__setattr__(self, "components", comps)

    @property
    def dim(self) -> int:
        return len(self.components[0].direction)

    def state(self, t: float):
        """Displacement [m], velocity [m/s] and acceleration [m/s^2] of every point at time
        ``t`` [s], each (dim,)."""
        out = np.zeros((3, self.dim))
        for c in self.components:
            out += np.outer(c.signal.state(t), c.direction)
        return out[0], out[1], out[2]

    def sample(self, t):
        """``(displacement, velocity, acceleration)`` at the times ``t`` [s], each
        (len(t), dim) (vectorised where the signals are :class:`Tabulated`)."""
        t = np.atleast_1d(np.asarray(t, np.float64))
        out = np.zeros((3, t.size, self.dim))
        for c in self.components:
            sig = c.signal
            s = (np.asarray(sig.sample(t)) if isinstance(sig, Tabulated)
                 else np.array([sig.state(float(x)) for x in t]).T)
            out += s[:, :, None] * np.asarray(c.direction)[None, None, :]
        return out[0], out[1], out[2]

    def __call__(self, t: float, ref):
        ref = _check_ref("Combined", ref, self.dim)
        d, v, _ = self.state(t)
        return ref + d, np.broadcast_to(v, ref.shape).copy()

    def acceleration(self, t: float) -> np.ndarray:
        """Acceleration of every point [m/s^2] (dim,)."""
        return self.state(t)[2]

    def ramped(self, t_ramp: float, t_start: float = 0.0, t_stop: float | None = None) -> "Combined":
        """Every component faded in (and out) by :class:`Ramped` (times in s)."""
        return Combined(tuple(c.ramped(t_ramp, t_start, t_stop) for c in self.components))


# ---------------------------------------------------------------------------------------- records
def _at2_header(p: Path, lines: list) -> tuple[int, float]:
    """(NPTS, DT [s]) of a PEER ``.AT2`` file from its 3rd and 4th lines; InputError
    naming the file, the line and the fix when they are not an accelerogram's."""
    if len(lines) < 5:
        raise InputError(f"read_at2: {p} has {len(lines)} lines; a PEER .AT2 file has 4 header lines, then the "
                         "accelerations")
    kind = lines[2].upper()
    if "ACCEL" not in kind:
        other = next((w for w in ("VELOC", "DISPL") if w in kind), None)
        what = {"VELOC": "a velocity record (.VT2)", "DISPL": "a displacement record (.DT2)"}.get(other,
                                                                                                  "not an .AT2 file")
        raise InputError(f"read_at2: line 3 of {p} is {lines[2].strip()!r}: {what}; an accelerogram's 3rd line reads "
                         "'ACCELERATION TIME SERIES IN UNITS OF G'. Give the .AT2 file of the record")
    units = kind.split("UNITS OF", 1)[1].split() if "UNITS OF" in kind else ["G"]
    if not units or units[0].rstrip(".,") != "G":
        raise InputError(f"read_at2: line 3 of {p} gives the accelerations in {' '.join(units) or '?'}, not in g: "
                         "the reader takes PEER records in units of g; convert the values to g and say "
                         "'IN UNITS OF G'")
    head = lines[3].upper().replace(",", " ").replace("=", " = ")
    npts = dt = None
    tok = head.split()
    for i, w in enumerate(tok):
        if w == "NPTS" and i + 2 < len(tok):
            npts = tok[i + 2]
        if w == "DT" and i + 2 < len(tok):
            dt = tok[i + 2]
    if (npts is None or dt is None) and len(tok) >= 2 and _is_float(tok[0]) and _is_float(tok[1]):
        npts, dt = tok[0], tok[1]  # the older form: the line starts with "n dt" ("4000 .0100 NPTS, DT")
    try:
        n, dt = int(npts), float(dt)
    except (TypeError, ValueError):
        raise InputError(f"read_at2: line 4 of {p} should give NPTS and DT, e.g. 'NPTS=  4000, DT= .0050 SEC'; "
                         f"got {lines[3]!r}") from None
    if n < 2 or not (dt > 0 and math.isfinite(dt)):
        raise InputError(f"read_at2: {p} gives NPTS={n}, DT={dt} s; need NPTS >= 2 and DT > 0 (line 4: the "
                         "number of samples and the time between them)")
    return n, dt


def _at2_values(p: Path, lines: list, n: int) -> np.ndarray:
    """The accelerations [g] of the data lines (5 on), checked: numbers, finite, no line
    short of the others before the last (a gap), and exactly ``n`` of them."""
    rows = []  # (line number, values)
    for k, line in enumerate(lines[4:], start=5):
        parts = line.replace(",", " ").split()
        try:
            rows.append((k, [float(w) for w in parts]))
        except ValueError:
            bad = next(w for w in parts if not _is_float(w))
            raise InputError(f"read_at2: line {k} of {p} holds {bad!r}, not a number; the data lines of an .AT2 "
                             "file hold accelerations in g only") from None
    while rows and not rows[-1][1]:  # blank lines at the end
        rows.pop()
    width = max((len(v) for _, v in rows), default=0)
    for k, v in rows[:-1]:
        if len(v) < width:
            raise InputError(f"read_at2: line {k} of {p} holds {len(v)} value(s) where the other data lines hold "
                             f"{width}: a gap in the record (the samples after it would be shifted in time); "
                             "restore the missing values or take the record again from its source")
    acc = np.array([x for _, v in rows for x in v], np.float64)
    if acc.size != n:
        raise InputError(f"read_at2: {p} declares NPTS={n} but holds {acc.size} values; the record is cut short, "
                         "has a gap or its NPTS is wrong: give the whole record, or the NPTS of the values it holds"
                         if acc.size < n else
                         f"read_at2: {p} declares NPTS={n} but holds {acc.size} values; correct NPTS (line 4) to the "
                         "number of values, or remove what follows the record")
    bad = np.flatnonzero(~np.isfinite(acc))
    if bad.size:
        i = int(bad[0])
        raise InputError(f"read_at2: {p} holds a non-finite value ({acc[i]}) at sample {i} (t = {i} DT); "
                         f"{bad.size} of its {n} values are not finite: repair the record")
    return acc


def _is_float(w: str) -> bool:
    try:
        float(w)
        return True
    except ValueError:
        return False


def read_at2(path, baseline_degree: int | None = 6) -> Tabulated:
    """A PEER NGA ``.AT2`` accelerogram as a :class:`Tabulated` acceleration record [m/s^2].

    Format (PEER NGA strong-motion database files): four header lines (title; event, date,
    station, component; "ACCELERATION TIME SERIES IN UNITS OF G"; a line with ``NPTS= n,
    DT= dt SEC`` (also the older "n dt" form)), then the n accelerations in g, the same
    number on every line but the last. Sample k lies at ``t = k dt`` [s], k = 0..n-1, and
    the ground starts at rest at t = 0; the displacement and velocity are the exact
    integrals of the piecewise-linear acceleration (:class:`Tabulated`).
    ``baseline_degree`` [-]: the degree of :func:`baseline_correct` (None: the raw
    record). :class:`InputError` naming the file, the line and the fix for a file that is
    not an accelerogram in g (another header, a velocity or displacement record, other
    units), a bad NPTS or DT, a value that is not a number or not finite, a data line short
    of values before the last (a gap), or a count of values other than NPTS."""
    p = Path(path)
    if not p.is_file():
        raise InputError(f"read_at2: no file {p}")
    try:
        lines = p.read_text(encoding="ascii").splitlines()
    except (UnicodeDecodeError, ValueError):
        raise InputError(f"read_at2: {p} is not a text file (a PEER .AT2 record is plain ASCII text); give the "
                         ".AT2 file of the record") from None
    n, dt = _at2_header(p, lines)
    acc = _at2_values(p, lines, n) * G_STANDARD
    rec = Tabulated(tuple((dt * np.arange(n)).tolist()), tuple(acc.tolist()), "acceleration")
    return rec if baseline_degree is None else baseline_correct(rec, baseline_degree)
