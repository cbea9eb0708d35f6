"""Linear waves as a sum of components, and the excitation force they give a body.

What: a sea is a list of :class:`WaveComponent` (angular frequency ω [rad/s], amplitude
``a`` [m], phase φ [rad], heading β [deg], towards which it travels, from +x towards +y),
each an Airy wave (Dean & Dalrymple 1991, Table 4.1) in water ``depth`` [m] deep with
wavenumber ``k`` from ``ω² = g k tanh(k d)``::

    η(x, y, t) = r(t) Σ a cos(k (x cos β + y sin β) − ω t + φ)

faded in by ``r(t) = (1 − cos(π t / ramp)) / 2`` up to ``ramp`` [s]. A regular wave is one
component (:func:`regular`); an irregular sea is many (:func:`from_spectrum`: amplitudes
``a_i = sqrt(2 S(ω_i) Δω_i)`` from a one-sided spectrum, random phases; Tucker et al. 1984;
or :func:`from_incident`: the components of a :mod:`fluid.waves` sea).
The interface is the list of components: any wave module that can list its components (a
:class:`fluid.analytic.LinearWave`: :func:`from_linear_wave`) plugs in.

The linear excitation force on a body whose centre of mass rests at horizontal position
``x_0`` [m] (Newman 1977 §6.18; Capytaine's convention, see :mod:`.coefficients`)::

    F(t) = r(t) Σ Re( a e^{iφ} e^{i k (x_0 cos β + y_0 sin β)} X(ω, β) e^{−iωt} )

with ``X(ω, β)`` per unit amplitude interpolated linearly (real and imaginary parts) in ω and
in β (periodic) from the BEM's table: a component outside the table's frequencies is refused.
:func:`band_share` and :func:`cut_for_share` measure what a band leaves out of a sea: the
share of its variance ``m0 = Σ a²/2`` (each component's ``a²/2``) outside the band.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from errors import InputError
from fluid.wavemaker import wavenumber as _wavenumber


def wavenumber(omega: float, depth: float, g: float) -> float:
    """k [rad/m] from ω² = g k tanh(k d) (:func:`fluid.wavemaker.wavenumber`; ω²/g in deep water)."""
    if not math.isfinite(depth):
        return omega * omega / g
    return _wavenumber(2.0 * math.pi / omega, depth, g)


@dataclass(frozen=True)
class WaveComponent:
    """One Airy wave: ``omega`` [rad/s], ``amplitude`` [m], ``phase`` [rad], ``heading`` [deg]."""

    omega: float
    amplitude: float
    phase: float = 0.0
    heading: float = 0.0

    def __post_init__(self):
        for name, v in (("omega", self.omega), ("amplitude", self.amplitude), ("phase", self.phase),
                        ("heading", self.heading)):
            if not math.isfinite(float(v)):
                raise InputError(f"wave component: {name} = {v!r} must be finite")
        if self.omega <= 0 or self.amplitude < 0:
            raise InputError(f"wave component: omega = {self.omega!r} rad/s must be > 0 and amplitude = "
                             f"{self.amplitude!r} m >= 0")


def regular(height: float, period: float, heading: float = 0.0, phase: float = 0.0) -> list[WaveComponent]:
    """A regular wave of ``height`` [m] (crest to trough) and ``period`` [s] as one component."""
    return [WaveComponent(2.0 * math.pi / period, 0.5 * height, phase, heading)]


def from_linear_wave(wave) -> list[WaveComponent]:
    """The component of a :class:`fluid.analytic.LinearWave` (its ``H``, ``T``, ``direction``)."""
    return regular(wave.H, wave.T, wave.direction)


def from_incident(sea) -> "Sea":
    """The :class:`Sea` of the linear components of a :mod:`fluid.waves` sea (a
    ``RegularWave``'s first-order part, a ``SpectralSea``, a ``RecordedSea``): the same
    frequencies, amplitudes and heading, phases moved to the origin (its components' phases
    refer to ``phase_reference`` along the heading), its depth, gravity and fade-in, which
    here acts everywhere at once (a ``source``'s travelling front is not kept); components of
    zero amplitude are left out."""
    c = sea.components
    phase = c.phase - c.k * sea.phase_reference
    keep = c.amplitude > 0
    return Sea([WaveComponent(float(o), float(a), float(p), float(sea.direction))
                for o, a, p in zip(c.omega[keep], c.amplitude[keep], phase[keep])],
               depth=sea.depth, g=sea.g, ramp=sea.ramp)


def from_spectrum(omega: Sequence[float], S: Sequence[float], heading: float = 0.0,
                  seed: int = 0) -> list[WaveComponent]:
    """Components of a one-sided spectrum ``S(ω)`` [m^2 s/rad] at ``omega`` [rad/s]
    (increasing), amplitudes ``sqrt(2 S Δω)``, phases uniform on [0, 2π) from ``seed``."""
    w, s = np.asarray(omega, float), np.asarray(S, float)
    if w.ndim != 1 or len(w) < 2 or w.shape != s.shape or not np.all(np.diff(w) > 0) or (s < 0).any():
        raise InputError("wave spectrum: give increasing frequencies and as many values S >= 0")
    dw = np.gradient(w)
    phases = np.random.default_rng(seed).uniform(0.0, 2.0 * math.pi, len(w))
    return [WaveComponent(float(a), float(b), float(p), heading) for a, b, p in zip(w, np.sqrt(2 * s * dw), phases)]


class Sea:
    """Wave components in water ``depth`` [m] (inf: deep), gravity ``g``, faded in over ``ramp`` [s]."""

    def __init__(self, components: Sequence[WaveComponent], depth: float = math.inf, g: float = 9.81,
                 ramp: float = 0.0):
        self.components = list(components)
        if not self.components:
            raise InputError("sea: give at least one wave component")
        if not (depth > 0) or not (g > 0) or not (math.isfinite(ramp) and ramp >= 0):
            raise InputError(f"sea: depth = {depth!r} m and g = {g!r} m/s^2 must be > 0, ramp = {ramp!r} s >= 0")
        self.depth, self.g, self.ramp = float(depth), float(g), float(ramp)
        self.omega = np.array([c.omega for c in self.components])
        self.amplitude = np.array([c.amplitude for c in self.components])
        self.phase = np.array([c.phase for c in self.components])
        self.heading = np.array([c.heading for c in self.components])
        self.k = np.array([wavenumber(w, self.depth, self.g) for w in self.omega])
        b = np.radians(self.heading)
        self._dir = np.stack([np.cos(b), np.sin(b)], axis=1)

    def subset(self, keep) -> "Sea":
        """The sea of the components where ``keep`` (a boolean mask) is true, same depth, g, fade-in."""
        return Sea([c for c, k in zip(self.components, keep) if k], self.depth, self.g, self.ramp)

    def fade(self, t: float) -> float:
        if self.ramp <= 0 or t >= self.ramp:
            return 1.0
        return 0.0 if t <= 0 else 0.5 * (1.0 - math.cos(math.pi * t / self.ramp))

    def elevation(self, xy, t: float) -> np.ndarray:
        """η [m] at horizontal points ``xy`` [m] ``(n, 2)``."""
        xy = np.atleast_2d(np.asarray(xy, float))[:, :2]
        th = (xy @ self._dir.T) * self.k - self.omega * t + self.phase
        return self.fade(t) * (np.cos(th) @ self.amplitude)

    def velocity(self, p, t: float, level: float = 0.0) -> np.ndarray:
        """Water velocity [m/s] at points ``p`` [m] ``(n, 3)``, the still water at ``level``
        (kinematics of the surface above it, of the seabed below it)."""
        p = np.atleast_2d(np.asarray(p, float))
        zeta = np.minimum(p[:, 2] - level, 0.0)
        if math.isfinite(self.depth):
            zeta = np.maximum(zeta, -self.depth)
            kz = self.k * (zeta[:, None] + self.depth)
            kd = self.k * self.depth
            # cosh k(ζ+d)/sinh kd and sinh k(ζ+d)/sinh kd without overflow
            e1, e2 = np.exp(kz - kd), np.exp(-kz - kd)
            den = 1.0 - np.exp(-2.0 * kd)
            ch, sh = (e1 + e2) / den, (e1 - e2) / den
        else:
            ch = sh = np.exp(self.k * zeta[:, None])
        th = (p[:, :2] @ self._dir.T) * self.k - self.omega * t + self.phase
        aw = self.amplitude * self.omega
        uh = aw * ch * np.cos(th)
        u = np.empty((len(p), 3))
        u[:, 0] = uh @ self._dir[:, 0]
        u[:, 1] = uh @ self._dir[:, 1]
        u[:, 2] = (aw * sh * np.sin(th)).sum(axis=1)
        return self.fade(t) * u


def band_share(sea: Sea, lo: float, hi: float) -> tuple[np.ndarray, float]:
    """Which components lie in [``lo``, ``hi``] [rad/s] (a boolean mask, with a relative
    margin of 1e-9), and the share of the sea's variance m0 = Σ a²/2 outside, [0, 1]."""
    keep = (sea.omega >= lo * (1 - 1e-9)) & (sea.omega <= hi * (1 + 1e-9))
    a2 = sea.amplitude**2
    total = float(a2.sum())
    return keep, (float(a2[~keep].sum()) / total if total > 0 else 0.0)


def cut_for_share(sea: Sea, lo: float, share: float) -> float:
    """The lowest frequency ``hi`` [rad/s] (one of the components') for which the components
    outside [``lo``, ``hi``] carry at most ``share`` of the sea's variance; inf when those
    below ``lo`` alone carry more."""
    a2 = sea.amplitude**2
    total = float(a2.sum())
    if total <= 0:
        return lo
    below = float(a2[sea.omega < lo * (1 - 1e-9)].sum()) / total
    order = np.argsort(sea.omega)[::-1]  # from the highest down: the share above each component
    above = np.concatenate([[0.0], np.cumsum(a2[order])[:-1]]) / total
    fits = np.flatnonzero(below + above <= share)
    if below > share or not fits.size:
        return math.inf
    return float(max(sea.omega[order][fits[-1]], lo))


class Excitation:
    """The excitation force of a :class:`Sea` on one body (module docstring): the complex
    amplitudes of each component, interpolated from the BEM table once, summed in time."""

    def __init__(self, sea: Sea, omega_table, headings_table, X_table, position_xy, name: str = "body"):
        w = np.asarray(omega_table, float)
        beta = np.asarray(headings_table, float)
        X = np.asarray(X_table)  # (n_ω, n_β, 6)
        out = (sea.omega < w[0] * (1 - 1e-9)) | (sea.omega > w[-1] * (1 + 1e-9))
        if out.any():
            bad = sea.omega[out][0]
            raise InputError(f"potential flow: body '{name}': a wave of {bad:.4g} rad/s (period "
                             f"{2 * math.pi / bad:.4g} s) lies outside the coefficients' frequencies "
                             f"{w[0]:.4g}-{w[-1]:.4g} rad/s; widen omega_min/omega_max")
        Xw = np.stack([np.stack([np.interp(sea.omega, w, X[:, j, i].real) + 1j * np.interp(sea.omega, w,
                                                                                             X[:, j, i].imag)
                                 for i in range(6)], axis=-1) for j in range(len(beta))], axis=1)  # (n_c, n_β, 6)
        self.amplitude = np.array([_heading_interp(beta, Xw[c], sea.heading[c], name) for c in range(len(Xw))])
        phase = sea.k * (np.asarray(position_xy, float)[:2] @ sea._dir.T) + sea.phase
        self.amplitude = self.amplitude * (sea.amplitude * np.exp(1j * phase))[:, None]  # (n_c, 6)
        # Re(A e^{-iωt}) = Re(A) cos ωt + Im(A) sin ωt: real products (a complex vector-matrix
        # product took milliseconds for some hundred components, most of a step)
        self._re = np.ascontiguousarray(self.amplitude.real.T)
        self._im = np.ascontiguousarray(self.amplitude.imag.T)
        self.sea = sea

    def force(self, t: float) -> np.ndarray:
        """[F_x, F_y, F_z, M_x, M_y, M_z] [N, N m] about the centre of mass at time ``t`` [s]."""
        wt = self.sea.omega * t
        return self.sea.fade(t) * (self._re @ np.cos(wt) + self._im @ np.sin(wt))


def _heading_interp(beta: np.ndarray, Xb: np.ndarray, heading: float, name: str) -> np.ndarray:
    """X at ``heading`` [deg] from the table's headings (linear, periodic in 360 deg)."""
    if len(beta) == 1:
        if abs((heading - beta[0] + 180.0) % 360.0 - 180.0) > 1e-6:
            raise InputError(f"potential flow: body '{name}': a wave heading {heading:g} deg but coefficients "
                             f"only for {beta[0]:g} deg; add it to the headings")
        return Xb[0]
    order = np.argsort(beta % 360.0)
    b = (beta % 360.0)[order]
    Xs = Xb[order]
    b = np.concatenate([b, [b[0] + 360.0]])
    Xs = np.concatenate([Xs, Xs[:1]])
    h = heading % 360.0
    if h < b[0]:
        h += 360.0
    i = min(int(np.searchsorted(b, h, side="right")) - 1, len(b) - 2)
    w = (h - b[i]) / (b[i + 1] - b[i])
    return (1 - w) * Xs[i] + w * Xs[i + 1]
