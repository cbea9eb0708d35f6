"""Metrics of a study: a probe series reduced by a named statistic, ``SERIES:STAT``
(``box.heave:amplitude``, ``gauge1.eta:rms``, ``left_wall.p:peak``).

Statistics of a series x(t) sampled at the run's probe times:

- ``peak``: max |x|; ``max``, ``min``, ``mean``, ``last``;
- ``amplitude``: half the range (max - min) / 2 over the last half of the run (the steady
  part of a forced response);
- ``harmonic``: the amplitude of the sinusoid at the spectrum's peak frequency (as
  ``period``) fitted by least squares with a constant and a linear drift over the last
  half of the run: the forced response without the noise that sets a range;
- ``period``: 1 / the frequency of the largest peak of the spectrum of x over the last half
  of the run (:func:`spectral_peak`: Hann window, zero padding, parabolic vertex; periods
  longer than two thirds of that half are not searched) [s];
- ``arrival``: the first time |x - x(0)| exceeds half of max |x - x(0)| [s];
- ``rms``: the RMS difference between x and the reference series (interpolated onto x's
  times over their common span), over the reference's RMS about its mean: a relative
  error by itself (the study's reference run or a file).
"""

from __future__ import annotations

import numpy as np

from cosim.errors import InputError

STATS = ("peak", "max", "min", "mean", "last", "amplitude", "harmonic", "period", "arrival", "rms")


def spectral_peak(t: np.ndarray, y: np.ndarray, f_lo: float, f_hi: float, pad: int = 64):
    """Frequency [Hz] of the largest peak of the FFT of ``y`` (uniform times ``t`` [s])
    between ``f_lo`` and ``f_hi`` [Hz]: mean removed, Hann window, zero padding ``pad``
    times, and a parabola through the log-magnitude of the top bin and its neighbours
    (the window's main lobe is near-Gaussian there, so the vertex is the peak to a small
    fraction of a padded bin). Returns (frequency, the FFT's frequencies, |FFT|)."""
    dt = t[1] - t[0]
    y = (y - y.mean()) * np.hanning(y.size)
    n = pad * y.size
    spec = np.abs(np.fft.rfft(y, n))
    f = np.fft.rfftfreq(n, dt)
    band = np.flatnonzero((f >= f_lo) & (f <= f_hi))[1:-1]  # a neighbour on each side
    if band.size == 0:
        raise InputError(f"no frequency between {f_lo:.4g} and {f_hi:.4g} Hz in a series of {y.size} samples")
    i = band[np.argmax(spec[band])]
    a, b, c = np.log(spec[i - 1:i + 2] + 1e-300)
    shift = 0.5 * (a - c) / (a - 2 * b + c) if (a - 2 * b + c) != 0 else 0.0
    return float(f[i] + shift * (f[1] - f[0])), f, spec


def parse(spec: str) -> tuple[str, str]:
    """(series, statistic) of ``SERIES:STAT``."""
    if ":" not in spec:
        raise InputError(f"--metric {spec!r}: give SERIES:STAT, e.g. box.heave:amplitude; statistics: "
                         f"{', '.join(STATS)}")
    series, stat = spec.rsplit(":", 1)
    if stat not in STATS:
        raise InputError(f"--metric {spec!r}: unknown statistic {stat!r}; choose from {', '.join(STATS)}")
    return series, stat


def _last_half(t, x):
    keep = t >= t[0] + 0.5 * (t[-1] - t[0])
    return t[keep], x[keep]


def value(stat: str, t: np.ndarray, x: np.ndarray, ref: tuple | None = None) -> float:
    """The statistic ``stat`` of the series ``x`` at times ``t`` [s]; ``ref`` = (t, x) of the
    reference series for ``rms``."""
    t, x = np.asarray(t, float), np.asarray(x, float)
    if len(x) == 0:
        raise InputError("the series is empty")
    if stat == "peak":
        return float(np.abs(x).max())
    if stat in ("max", "min", "mean"):
        return float(getattr(x, stat)())
    if stat == "last":
        return float(x[-1])
    if stat == "amplitude":
        _, y = _last_half(t, x)
        return float(0.5 * (y.max() - y.min()))
    if stat in ("period", "harmonic"):
        tt, y = _last_half(t, x)
        if len(y) < 8:
            raise InputError(f"a {stat} needs at least 8 samples in the last half of the run")
        f = spectral_peak(tt, y, 1.5 / (tt[-1] - tt[0]), np.inf)[0]
        if stat == "period":
            return 1.0 / f
        w = 2 * np.pi * f
        A = np.stack([np.ones_like(tt), tt - tt.mean(), np.sin(w * tt), np.cos(w * tt)], axis=1)
        c = np.linalg.lstsq(A, y, rcond=None)[0]
        return float(np.hypot(c[2], c[3]))
    if stat == "arrival":
        d = np.abs(x - x[0])
        if d.max() == 0:
            return float("nan")
        return float(t[int(np.argmax(d > 0.5 * d.max()))])
    if stat == "rms":
        if ref is None:
            raise InputError("rms needs a reference series")
        tr, xr = np.asarray(ref[0], float), np.asarray(ref[1], float)
        lo, hi = max(t[0], tr[0]), min(t[-1], tr[-1])
        keep = (t >= lo) & (t <= hi)
        xi = np.interp(t[keep], tr, xr)
        scale = float(np.sqrt(np.mean((xr - xr.mean()) ** 2)))
        diff = float(np.sqrt(np.mean((x[keep] - xi) ** 2)))
        return diff / scale if scale > 0 else diff
    raise InputError(f"unknown statistic {stat!r}; choose from {', '.join(STATS)}")
