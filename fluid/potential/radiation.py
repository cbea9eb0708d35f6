"""The radiation impulse response of linear potential flow, its checks and its convolution.

What: the retardation (memory) function of the Cummins (1962) equation,

    K(t) = (2/π) ∫_0^∞ B(ω) cos(ωt) dω            (Ogilvie 1964, Eq. 2.16; Newman 1977 Eq. 6.172)

[N/m per m/s ...] from the radiation damping ``B(ω)`` tabulated on the BEM frequencies
(trapezoid rule from ω = 0, where the damping of a floating body vanishes: ``B`` is taken
linear between 0 and the first frequency), tapered to zero by a half cosine from
``taper ω_max`` to ``ω_max`` (a damping cut off sharply while still large, as a squat
hull's pitch damping is, rings in ``K`` as ``sin(ω_max t)/t`` and never decays within a
memory; Harris 1978 on windows), and its inverse,

    A(ω) = A∞ − (1/ω) ∫_0^∞ K(t) sin(ωt) dt,   B(ω) = ∫_0^∞ K(t) cos(ωt) dt   (Ogilvie 1964, Eq. 2.17),

with which :func:`frequency_response` tests ``K`` against the BEM's own ``A(ω)``.

The infinite-frequency added mass of the time-domain model, ``A∞_td``, is fitted so that
the ``A(ω)`` that ``K`` rebuilds matches the BEM's over the trusted band ``ω <= band ω_max``
(the mean of ``A_BEM(ω) + (1/ω) ∫ K sin ωt dt`` there): the damping dropped above ``ω_max``
shifts the rebuilt ``A(ω)`` by ``(2/π) ∫_{ω_max}^∞ B(ν) / (ν² − ω²) dν`` (Kramers–Kronig),
nearly constant for ``ω << ω_max``, which the fit absorbs (with ``A∞`` from the BEM, a
3 m radius, 1.5 m draft cylinder's surge added mass was 5-11 % off below ``ω_max / 2`` with
ω_max = 4 rad/s; fitted, 0.6 %). The BEM's ``A∞`` is kept beside it for comparison.

Checks (:func:`impulse_response`), refused with the measure that failed:

- ``K`` decays within the memory kept: ``max |K_ij(t)|`` over the memory's last 10 %
  at most ``k_tol`` times the peak (each entry against its diagonal pair);
- the memory is inside the window the frequency spacing resolves: the trapezoid sum on
  a spacing Δω repeats with period 2π/Δω, so ``memory <= π / Δω_max``;
- ``K`` and ``A∞_td`` rebuild the BEM's ``A(ω)`` and ``B(ω)`` over the trusted band within
  ``tol`` of each diagonal entry's largest value: a frequency range too short for the
  hull (damping still large at ``ω_max``) or too coarse for the memory fails here.

Units: SI; dof order surge, sway, heave, roll, pitch, yaw.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from errors import InputError

class SettingError(InputError):
    """A setting of the potential fluid that does not fit the hull or the waves; ``key``
    names it (``omega_max``, ``frequencies``, ``memory``), for a scene to point at."""

    def __init__(self, key: str, message: str):
        super().__init__(message)
        self.key = key


#: defaults of the checks (see the module docstring)
K_TOL = 0.02
TOL = 0.05
BAND = 0.5
TAPER = 0.6


@dataclass(frozen=True)
class ImpulseResponse:
    """K(t) tabulated on ``t`` [s] (uniform from 0 to the memory), ``(n_t, 6, 6)``, with the
    time-domain ``A∞`` fitted to it and the checks' measures."""

    t: np.ndarray
    K: np.ndarray
    added_mass_inf: np.ndarray  #: A∞_td, fitted over the trusted band (module docstring), (6, 6)
    decay: float  #: the largest |K| over the memory's last 10 % relative to the peak, [-]
    error_A: float  #: largest error of the rebuilt A(ω) over the band, relative to each entry's peak [-]
    error_B: float  #: the same for B(ω) [-]
    band: float  #: the trusted band's upper frequency [rad/s]

    @property
    def memory(self) -> float:
        return float(self.t[-1])

    def at(self, lags: np.ndarray) -> np.ndarray:
        """K at ``lags`` [s] in [0, memory] (linear between the tabulated times), ``(n, 6, 6)``."""
        s = np.clip(np.asarray(lags, float) / (self.t[1] - self.t[0]), 0.0, len(self.t) - 1.0)
        i = np.minimum(s.astype(int), len(self.t) - 2)
        w = (s - i)[:, None, None]
        return (1.0 - w) * self.K[i] + w * self.K[i + 1]


def _weights(omega: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Frequencies from 0 and their trapezoid weights [rad/s]."""
    w = np.concatenate([[0.0], omega])
    dw = np.diff(w)
    q = np.zeros_like(w)
    q[:-1] += 0.5 * dw
    q[1:] += 0.5 * dw
    return w, q


def kernel(omega: np.ndarray, B: np.ndarray, t: np.ndarray, taper: float = TAPER) -> np.ndarray:
    """K(t) (Ogilvie 1964, Eq. 2.16) at times ``t`` [s] from ``B`` ``(n, 6, 6)`` at ``omega``,
    tapered from ``taper ω_max`` (module docstring; 1: no taper)."""
    w, q = _weights(np.asarray(omega, float))
    s = np.clip((w - taper * w[-1]) / max((1.0 - taper) * w[-1], 1e-300), 0.0, 1.0)
    q = q * 0.5 * (1.0 + np.cos(math.pi * s))
    Bz = np.concatenate([np.zeros((1,) + B.shape[1:]), B])
    c = np.cos(np.outer(t, w)) * q  # (n_t, n_ω)
    return (2.0 / math.pi) * np.einsum("tw,wij->tij", c, Bz)


def _rebuilt(t: np.ndarray, K: np.ndarray, omega: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(1/ω) ∫ K sin ωt dt and ∫ K cos ωt dt over [0, t_end] (trapezoid rule)."""
    q = np.full(len(t), t[1] - t[0])
    q[0] = q[-1] = 0.5 * (t[1] - t[0])
    s = np.sin(np.outer(omega, t)) * q
    c = np.cos(np.outer(omega, t)) * q
    return np.einsum("wt,tij->wij", s, K) / omega[:, None, None], np.einsum("wt,tij->wij", c, K)


def _relative(err: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """Largest |err_ii| over frequencies relative to the largest |ref_ii|, per dof (0 where ref is 0)."""
    e = np.abs(np.einsum("wii->wi", err)).max(axis=0)
    r = np.abs(np.einsum("wii->wi", ref)).max(axis=0)
    live = r > 1e-9 * max(r.max(), 1e-300)
    return np.where(live, e / np.where(live, r, 1.0), 0.0)


def impulse_response(omega, A, B, memory: float | None = None, *, name: str = "body", k_tol: float = K_TOL,
                     tol: float = TOL, band: float = BAND, taper: float = TAPER,
                     dt: float | None = None) -> ImpulseResponse:
    """K(t) on [0, ``memory``] [s] (None: the shortest memory after which it stays below
    ``k_tol`` of its peak, within π/Δω) from the BEM's ``A``, ``B`` ``(n, 6, 6)`` at
    ``omega`` [rad/s], with ``A∞_td`` fitted over ``ω <= band ω_max``, ``B`` tapered from
    ``taper ω_max``, checked (module
    docstring); ``dt`` [s] its tabulation step (default: 1/40 of the period 2π/ω_max)."""
    omega, A, B = np.asarray(omega, float), np.asarray(A, float), np.asarray(B, float)
    dofs = "surge sway heave roll pitch yaw".split()
    window = math.pi / float(np.diff(omega).max())  # the spacing's period (0 to ω_1 is one linear piece)
    if memory is not None and memory > window * (1 + 1e-12):
        raise SettingError("memory", f"potential flow: body '{name}': a memory of {memory:g} s is longer than the "
                           f"{window:.4g} s that the frequency spacing resolves (π/Δω); give more frequencies or a "
                           f"shorter memory")
    dt = dt if dt is not None else 2.0 * math.pi / omega[-1] / 40.0
    span = memory if memory is not None else window
    t = np.linspace(0.0, span, max(int(math.ceil(span / dt)), 8) + 1)
    if not 0 < band <= taper <= 1:
        raise InputError(f"potential flow: need 0 < band ({band!r}) <= taper ({taper!r}) <= 1")
    K = kernel(omega, B, t, taper)
    peak = np.abs(K).max(axis=0)  # (6, 6) peak of each entry
    ref = np.sqrt(np.outer(np.diag(peak), np.diag(peak)))  # each entry against its diagonal pair
    rel = np.abs(K) / np.where(ref > 0, ref, np.inf)
    if memory is None:  # the shortest memory after which K stays below k_tol, within the window
        above = np.flatnonzero(rel.max(axis=(1, 2)) > 0.5 * k_tol)
        end = int(above[-1]) + 1 if above.size else 1
        n = int(math.ceil(end / 0.9)) + 2  # the memory's last 10 % lies after it
        if n > len(t):
            raise SettingError("frequencies", f"potential flow: body '{name}': the impulse response is still at "
                               f"{rel[int(0.9 * (len(t) - 1)):].max():.1%} of its peak over the last 10 % of the "
                               f"{t[-1]:.4g} s that the frequency spacing resolves (π/Δω); give more frequencies "
                               f"(a finer spacing) so that it can decay below {0.5 * k_tol:.0%}")
        t, K, rel = t[:n], K[:n], rel[:n]
    decay = float(rel[int(0.9 * (len(t) - 1)):].max())
    if decay > k_tol:
        raise SettingError("memory", f"potential flow: body '{name}': the impulse response has decayed only to "
                           f"{decay:.1%} of its peak over the last 10 % of the {t[-1]:g} s memory (at most "
                           f"{k_tol:.0%}); give a longer memory, with frequencies spaced finely enough for it "
                           f"(π/Δω >= memory)")
    sin_part, B_td = _rebuilt(t, K, omega)
    trusted = omega <= band * omega[-1] * (1 + 1e-12)
    if trusted.sum() < 2:
        raise SettingError("frequencies", f"potential flow: body '{name}': fewer than 2 frequencies lie in the "
                           f"trusted band (<= {band:g} x omega_max = {band * omega[-1]:.4g} rad/s); give more "
                           f"frequencies")
    A_inf = np.mean(A[trusted] + sin_part[trusted], axis=0)
    A_inf = 0.5 * (A_inf + A_inf.T)
    err_A = _relative((A_inf - sin_part - A)[trusted], A[trusted])
    err_B = _relative((B_td - B)[trusted], B)
    for what, err in (("added mass", err_A), ("damping", err_B)):
        if err.max() > tol:
            i = int(np.argmax(err))
            raise SettingError("omega_max", f"potential flow: body '{name}': the impulse response rebuilds the "
                               f"{dofs[i % 6]} {what} only within {err[i]:.1%} below {band * omega[-1]:.4g} rad/s "
                               f"(at most {tol:.0%}; Ogilvie 1964): the frequency range is too short for this "
                               f"hull (its damping is still {_tail(B)[i]:.0%} of its peak at omega_max = "
                               f"{omega[-1]:.4g} rad/s) or too coarse; raise omega_max (with a panel size that resolves it) or give more "
                               f"frequencies")
    return ImpulseResponse(t, K, A_inf, decay, float(err_A.max()), float(err_B.max()), float(band * omega[-1]))


def _tail(B: np.ndarray) -> np.ndarray:
    d = np.abs(np.einsum("wii->wi", B))
    peak = d.max(axis=0)
    return np.where(peak > 0, d[-1] / np.where(peak > 0, peak, 1.0), 0.0)


def frequency_response(irf: ImpulseResponse, omega) -> tuple[np.ndarray, np.ndarray]:
    """A(ω) and B(ω) of the time-domain model: rebuilt from K and A∞_td (Ogilvie 1964, Eq. 2.17)."""
    sin_part, B = _rebuilt(irf.t, irf.K, np.asarray(omega, float))
    return irf.added_mass_inf[None] - sin_part, B
