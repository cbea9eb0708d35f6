"""The incident sea: one description of the waves for every fluid.

Each kind answers the same questions at any points and times (numpy, vectorised: ``x``,
``y``, ``z`` [m] and ``t`` [s] broadcast together, a scalar ``t`` or an array of times):

- ``elevation(x, y, t)``: η [m] above the still water;
- ``velocity(x, y, z, t)``: the water velocity [m/s], shape ``(..., 3)``;
- ``acceleration(x, y, z, t)``: the local time derivative ∂u/∂t [m/s^2] (not the material
  derivative Du/Dt: the linearised Euler equation and the Froude–Krylov force use ∂u/∂t);
- ``kinematics(x, y, z, t)``: both at once, and ``surface_and_kinematics`` with η too,
  sharing the trigonometry (the cost: a cosine and a sine per point and component);
- ``dynamic_pressure(x, y, z, t, rho)`` [Pa] and ``pressure(...)``, hydrostatic included;
- ``components``: the free linear waves (ω, a, phase, k) that make the sea, for fluids that
  need them (a potential-flow solver's excitation, a relaxation zone);
- the wavenumber, wavelength, group velocity and periods of the sea.

Kinds: :class:`RegularWave` (linear Airy, or Stokes second order), :class:`SpectralSea`
(JONSWAP or Pierson–Moskowitz, random phases) and :class:`RecordedSea` (a measured
elevation series made into linear components by FFT).

Frame (as ``fluid.analytic.LinearWave``): z up, the still water at ``level`` [m], the flat
seabed ``depth`` [m] below it; the waves travel along the horizontal heading ``direction``
[deg] from +x towards +y (long-crested); ``ζ = z − level``. Kinematics are those of the
potential inside ``−depth ≤ ζ ≤ 0``: above the still water (under a crest) they are taken
at ζ = 0, below the seabed at ζ = −depth (constant extrapolation; no Wheeler stretching).
A sea fades in over ``ramp`` [s] (``r = (1 − cos(π t / ramp)) / 2``); with ``source`` [m]
the fade-in starts at the plane ``x cos β + y sin β = source`` (a wavemaker) and travels
at the group velocity (of the peak, for an irregular sea): a point a distance ``s`` ahead
sees ``r(t − s / c_g)``. The accelerations carry ``r'`` so that they are ∂u/∂t exactly.

Every input is checked on construction; a bad one raises :class:`SeaError`
(a ``cosim.errors.InputError``) naming the field and the limit, including the breaking
limits (Miche 1944; McCowan 1894) and Stokes second order's range.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple

import numpy as np
from numba import njit, prange

from errors import InputError
from fluid.wavemaker import wavenumber, wavenumbers  # noqa: F401 (wavenumbers: read from here too)

#: rows of the kinematics :func:`_linear_sums` returns: η, u_h, w, ∂u_h/∂t, ∂w/∂t, p/ρ
ETA, UH, W, AH, AW, P = range(6)


@njit(cache=True)
def _fade_at(s, t, has_source, source, c_front, ramp):
    """The fade-in ``(r, r', r'')`` at position ``s`` [m] along the heading and time ``t``
    [s] (module docstring): ``r = (1 − cos(π q)) / 2``, ``q = τ / ramp`` clipped to [0, 1],
    ``τ = t`` or, from a ``source``, ``t − max(s − source, 0) / c_front``; a step at τ = 0
    where ``ramp`` is 0."""
    tau = t - max(s - source, 0.0) / c_front if has_source else t
    if ramp <= 0.0:
        return (1.0 if tau >= 0.0 or not has_source else 0.0), 0.0, 0.0
    q = min(max(tau / ramp, 0.0), 1.0)
    r = 0.5 * (1.0 - math.cos(math.pi * q))
    if 0.0 < q < 1.0:
        f = math.pi / ramp
        return r, 0.5 * f * math.sin(math.pi * q), 0.5 * f * f * math.cos(math.pi * q)
    return r, 0.0, 0.0


@njit(cache=True)
def _fade_all(s, t, has_source, source, c_front, ramp, out):
    """:func:`_fade_at` at each of the points ``s``, ``t`` (1-D) into ``out`` (3, n)."""
    for i in range(s.shape[0]):
        out[0, i], out[1, i], out[2, i] = _fade_at(s[i], t[i], has_source, source, c_front, ramp)


def _linear_sums(s, zeta, t, w, a, ph, k, depth, g, s_ref, fade, want, out):
    """The linear superposition of the components (``w``, ``a``, ``ph``, ``k``) at points
    ``s`` [m] along the heading, ``zeta`` [m] below the still water (empty: the elevation
    alone) and times ``t`` [s], faded in: rows :data:`ETA` ... :data:`P` of ``out`` (6, n)
    where ``want`` (6 booleans) asks for them, and ``r``, ``r'`` in ``out[6:8]``; ``fade``
    = (has_source, source, c_front, ramp), ``g`` [m/s^2]; each point's sums are
    :func:`point_sums`'."""
    n = s.shape[0]
    have_z = zeta.shape[0] > 0
    den, ap = component_factors(a, k, depth, g)
    for i in prange(n):
        z = zeta[i] if have_z else 0.0
        (out[ETA, i], out[UH, i], out[W, i], out[P, i], out[AH, i], out[AW, i], out[6, i],
         out[7, i]) = point_sums(s[i], z, t[i], have_z, w, a, ph, k, depth, den, ap, s_ref, fade, want)


@njit(cache=True)
def component_factors(a, k, depth, g):
    """Each component's ``den = 1 − e^-2kd`` and ``ap = g a / (1 + e^-2kd)`` (:func:`point_sums`)."""
    m = k.shape[0]
    den, ap = np.empty(m), np.empty(m)
    for j in range(m):
        den[j] = -math.expm1(-2.0 * k[j] * depth)
        ap[j] = g * a[j] / (1.0 + math.exp(-2.0 * k[j] * depth))
    return den, ap


@njit(cache=True)
def point_sums(s, zeta, t, have_z, w, a, ph, k, depth, den, ap, s_ref, fade, want):
    """The linear superposition at one point ``s`` [m] along the heading, ``zeta`` [m] below
    the still water (``have_z`` False: the elevation alone), time ``t`` [s], faded in:
    (η, u_h, w, p/ρ, ∂u_h/∂t, ∂w/∂t, r, r'), each where ``want`` (6 booleans, the rows
    :data:`ETA` ... :data:`P`) asks for it (else 0); ``den``, ``ap`` from
    :func:`component_factors`. Per component, θ = k (s − s_ref) − ω t + phase (Dean &
    Dalrymple 1991, Table 4.1)::

        η = a cos θ,  u_h = a ω ch cos θ,  w = a ω sh sin θ,
        ∂u_h/∂t = a ω² ch sin θ,  ∂w/∂t = −a ω² sh cos θ,  p/ρ = g a cosh k(ζ+d)/cosh kd cos θ

    with ``ch, sh = cosh, sinh k(ζ+d) / sinh kd`` as ``(e1 ± e2) / den``, ``den = 1 −
    e^-2kd``, ``e1 = exp(kζ)``, ``e2 = exp(−k(ζ + 2d))`` (both ≤ 1: no overflow in deep
    water), and ``ap = g a / (1 + e^-2kd)`` (so that ``p/ρ = ap (e1 + e2) cos θ``); each
    times r, and the accelerations plus r' times the velocity (∂/∂t of the faded field)."""
    has_source, source, c_front, ramp = fade
    r, dr, _ = _fade_at(s, t, has_source, source, c_front, ramp)
    eta = uh = wz = ah = aw = p = 0.0
    for j in range(w.shape[0]):
        th = k[j] * (s - s_ref) - w[j] * t + ph[j]
        c = math.cos(th)
        eta += a[j] * c
        if not have_z:
            continue
        kj = k[j]
        e1 = math.exp(kj * zeta)
        e2 = math.exp(-kj * zeta - 2.0 * kj * depth)
        if want[P]:
            p += ap[j] * (e1 + e2) * c
        if want[UH] or want[AH]:
            sn = math.sin(th)
            ch, sh = (e1 + e2) / den[j], (e1 - e2) / den[j]
            awj = a[j] * w[j]
            uh += awj * ch * c
            wz += awj * sh * sn
            ah += awj * w[j] * ch * sn
            aw -= awj * w[j] * sh * c
    return r * eta, r * uh, r * wz, r * p, r * ah + dr * uh, r * aw + dr * wz, r, dr


#: :func:`_linear_sums` on one thread, and over the threads for many points × components
#: (a parallel loop's start costs more than a few thousand of its terms)
_linear_sums_serial = njit(cache=True)(_linear_sums)
_linear_sums_parallel = njit(parallel=True, cache=True)(_linear_sums)
#: points × components above which the parallel form is taken
_PARALLEL_TERMS = 20000


#: the entries of :func:`stokes2_wave`'s array
S2_K, S2_W, S2_PHASE, S2_A2, S2_A, S2_Q4, S2_INV_SH2, S2_DEN, S2_AW2 = range(9)


def stokes2_wave(k: float, w: float, a: float, depth: float, phase: float, a2: float) -> tuple:
    """What :func:`stokes2_point` needs of a Stokes-2 wave (9 floats, a tuple: passed by
    value, numba keeps them in registers), its factors computed once:
    wavenumber ``k`` [rad/m], ``w`` [rad/s], ``phase`` [rad], the second harmonic's amplitude
    ``a2`` [m], ``A = 3/4 a² ω k``, ``8 / (1 − q)⁴`` and ``4 q / (1 − q)²`` with ``q =
    e^-2kd``, ``1 − e^-2kd`` and ``a² ω²`` (amplitude ``a`` [m], depth ``depth`` [m])."""
    q = math.exp(-2.0 * k * depth)
    return tuple(float(v) for v in (k, w, phase, a2, 0.75 * a * a * w * k, 8.0 / (1.0 - q) ** 4,
                                    4.0 * q / (1.0 - q) ** 2, -math.expm1(-2.0 * k * depth), a * a * w * w))


@njit(cache=True)
def stokes2_point(s, zeta, have_z, t, wave, depth, r, dr, want):
    """Stokes second order's terms at one point (:class:`RegularWave`'s docstring: Sorensen
    2006, Eqs. 3.7-3.10, and the pressure derived there): the increments of (η, u_h, w,
    ∂u_h/∂t, ∂w/∂t, p/ρ) that ``want`` (the rows :data:`ETA` ... :data:`P`) asks for (else
    0), faded with ``r²`` (``r``, ``r'`` the linear sums' fade-in), at ``s`` [m] along the
    heading, ``zeta`` [m] below the still water (``have_z`` False: η alone), time ``t`` [s],
    of the wave ``wave`` (:func:`stokes2_wave`) in ``depth`` [m] of water. ``cosh 2k(ζ+d) /
    sinh⁴ kd`` and ``sinh 2k(ζ+d) / sinh⁴ kd`` as ``8 (e1 ± e2) / (1 − e^-2kd)⁴`` with
    ``e1 = exp(2kζ − 2kd)``, ``e2 = exp(−2kζ − 6kd)``, both ≤ 1."""
    k, w = wave[S2_K], wave[S2_W]
    r2, dr2 = r * r, 2.0 * r * dr
    th2 = 2.0 * (k * s - w * t + wave[S2_PHASE])
    c2, s2 = math.cos(th2), math.sin(th2)
    eta = uh = wz = ah = aw = p = 0.0
    if want[ETA]:
        eta = r2 * wave[S2_A2] * c2
    if not have_z:
        return eta, uh, wz, ah, aw, p
    A, q4 = wave[S2_A], wave[S2_Q4]
    e1, e2 = math.exp(2.0 * k * zeta - 2.0 * k * depth), math.exp(-2.0 * k * zeta - 6.0 * k * depth)
    C2, S2 = q4 * (e1 + e2), q4 * (e1 - e2)
    if want[UH]:
        uh = r2 * A * C2 * c2
        wz = r2 * A * S2 * s2
    if want[AH]:
        ah = r2 * A * C2 * 2.0 * w * s2 + dr2 * A * C2 * c2
        aw = -r2 * A * S2 * 2.0 * w * c2 + dr2 * A * S2 * s2
    if want[P]:
        sh = (math.exp(k * zeta) - math.exp(-k * (zeta + 2.0 * depth))) / wave[S2_DEN]  # sinh k(ζ+d)/sinh kd
        p = r2 * wave[S2_AW2] * ((0.75 * C2 - 0.25 * wave[S2_INV_SH2]) * c2 - 0.5 * sh * sh)
    return eta, uh, wz, ah, aw, p


@njit(cache=True)
def _stokes2_terms(s, zeta, t, wave, depth, want, sums):
    """Add :func:`stokes2_point` of ``wave`` (:func:`stokes2_wave`) at each point to the rows
    of ``sums`` (:func:`_linear_sums`'s, its fade-in ``r``, ``r'`` in rows 6-7) that ``want``
    asks for; ``zeta`` empty: η alone."""
    have_z = zeta.shape[0] > 0
    for i in range(s.shape[0]):
        z = zeta[i] if have_z else 0.0
        eta, uh, wz, ah, aw, p = stokes2_point(s[i], z, have_z, t[i], wave, depth, sums[6, i], sums[7, i], want)
        if want[ETA]:  # the rows asked for only: the others are zeros
            sums[ETA, i] += eta
        if want[UH]:
            sums[UH, i] += uh
            sums[W, i] += wz
        if want[AH]:
            sums[AH, i] += ah
            sums[AW, i] += aw
        if want[P]:
            sums[P, i] += p


class SeaError(InputError):
    """A sea-state input out of range: ``field`` is its name (``height``, ``hs``, ...),
    ``problem`` what is wrong and how to fix it."""

    def __init__(self, owner: str, name: str, problem: str):
        self.field, self.problem = name, problem
        super().__init__(f"{owner}: {name}: {problem}")


class Components(NamedTuple):
    """The free linear waves of a sea, ``η = Σ a cos(k (s − s_ref) − ω t + phase)`` with
    ``s = x cos β + y sin β`` [m]: angular frequencies ``omega`` [rad/s], amplitudes
    ``amplitude`` [m], phases ``phase`` [rad], wavenumbers ``k`` [rad/m]."""

    omega: np.ndarray
    amplitude: np.ndarray
    phase: np.ndarray
    k: np.ndarray


def depth_factors(zeta, k, depth: float) -> tuple[np.ndarray, np.ndarray]:
    """``cosh k(ζ+d)/sinh kd`` and ``sinh k(ζ+d)/sinh kd`` (linear theory's orbit factors,
    Dean & Dalrymple 1991, §4.8), (len(ζ), len(k)), at heights ``zeta`` [m] above the still
    water clipped to [−d, 0], without overflow in deep water: with e1 = exp(kζ),
    e2 = exp(−k(ζ + 2d)), both <= 1, they are (e1 ± e2) / (1 − exp(−2kd))."""
    kz = np.multiply.outer(np.clip(zeta, -depth, 0.0), k)
    den = -np.expm1(-2.0 * k * depth)
    e1, e2 = np.exp(kz), np.exp(-kz - 2.0 * k * depth)
    return (e1 + e2) / den, (e1 - e2) / den


def group_velocity(k, depth: float, g: float = 9.81):
    """c_g = (ω/k) (1/2) (1 + 2kd / sinh 2kd) [m/s] (Dean & Dalrymple 1991, eq. 4.79)."""
    k = np.asarray(k, float)
    kd = k * depth
    with np.errstate(over="ignore"):
        ratio = np.where(kd < 350, 2.0 * kd / np.sinh(np.minimum(2.0 * kd, 700.0)), 0.0)
    return 0.5 * (1.0 + ratio) * np.sqrt(g * np.tanh(kd) / k)


def pierson_moskowitz(omega, hs: float, tp: float) -> np.ndarray:
    """The Pierson–Moskowitz spectrum S(ω) [m² s/rad] of significant height ``hs`` [m] and
    peak period ``tp`` [s] (DNV-RP-C205 2010, §3.5.5.1):
    ``S = (5/16) Hs² ωp⁴ ω⁻⁵ exp(−(5/4)(ω/ωp)⁻⁴)``, ωp = 2π/Tp; ∫S dω = Hs²/16 exactly."""
    w = np.asarray(omega, float)
    wp = 2.0 * math.pi / tp
    out = np.zeros_like(w)
    pos = w > 0
    x = wp / w[pos]
    out[pos] = 5.0 / 16.0 * hs**2 * wp**4 / w[pos] ** 5 * np.exp(-1.25 * x**4)
    return out


def jonswap(omega, hs: float, tp: float, gamma: float = 3.3) -> np.ndarray:
    """The JONSWAP spectrum S(ω) [m² s/rad] (Hasselmann et al. 1973; DNV-RP-C205 2010,
    §3.5.5.2): ``A_γ S_PM(ω) γ^exp(−(ω − ωp)² / (2 σ² ωp²))``, σ = 0.07 for ω ≤ ωp and
    0.09 above, with the normalising factor ``A_γ = 1 − 0.287 ln γ``. A_γ is an
    approximation: ∫S dω differs from Hs²/16 by −0.2 % (γ = 2), +0.24 % (3.3), 0 (5),
    −1.8 % (7), −7 % (γ = 10; hence γ ≤ 7 here)."""
    w = np.asarray(omega, float)
    wp = 2.0 * math.pi / tp
    sigma = np.where(w <= wp, 0.07, 0.09)
    peak = gamma ** np.exp(-0.5 * ((w - wp) / (sigma * wp)) ** 2)
    return (1.0 - 0.287 * math.log(gamma)) * pierson_moskowitz(w, hs, tp) * peak


def _number(owner, name, value, unit, hint, lo=0.0, lo_open=True) -> float:
    """A finite float ``value`` above ``lo`` (or unbounded: ``lo=None``), else SeaError."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise SeaError(owner, name, f"{value!r} is not a number; give {hint} [{unit}]") from None
    if not math.isfinite(v) or (lo is not None and (v < lo or (lo_open and v == lo))):
        bound = "" if lo is None else f" {'>' if lo_open else '>='} {lo:g}"
        raise SeaError(owner, name, f"{value!r} {unit}; give a finite number{bound} [{unit}] ({hint})")
    return v


class Sea:
    """The common part of every kind: the frame, the fade-in, and the linear superposition
    of :attr:`components` (subclasses set ``_comp`` and may add higher-order terms)."""

    owner = "sea"
    depth: float
    direction: float
    ramp: float
    source: float | None
    level: float
    g: float
    _comp: Components
    _s_ref: float = 0.0  # the position along the heading of the components' phase reference
    _c_front: float = 1.0  # the speed of the fade-in's front from ``source`` [m/s]

    # -- checks shared by the kinds ----------------------------------------------------
    def _check_frame(self) -> None:
        own = self.owner
        set_ = lambda name, v: object.__setattr__(self, name, v)  # noqa: E731 - frozen dataclasses
        set_("depth", _number(own, "depth", self.depth, "m", "the still-water depth over the seabed"))
        set_("g", _number(own, "g", self.g, "m/s^2", "gravity; waves need it"))
        set_("direction", _number(own, "direction", self.direction, "deg", "the heading, from +x towards +y",
                                  lo=None))
        set_("ramp", _number(own, "ramp", self.ramp, "s", "the fade-in time; 0 for none", lo=0.0, lo_open=False))
        set_("level", _number(own, "level", self.level, "m", "the height of the still water", lo=None))
        if self.source is not None:
            set_("source", _number(own, "source", self.source, "m", "where the waves are made, along the heading",
                                   lo=None))

    # -- what every kind offers --------------------------------------------------------
    @property
    def components(self) -> Components:
        """The free linear waves of the sea (copies)."""
        return Components(*(np.array(c) for c in self._comp))

    @property
    def phase_reference(self) -> float:
        """The position along the heading [m] that the components' phases refer to (0 but for
        a recorded sea, whose phases refer to its gauge)."""
        return self._s_ref

    @property
    def heading(self) -> np.ndarray:
        """Unit vector of propagation, (cos β, sin β, 0)."""
        return np.array([*self._heading2, 0.0])

    @property
    def shortest_period(self) -> float:
        """The period [s] of the highest frequency below which 99.9 % of the sea's variance
        lies: a time step that resolves it resolves the sea."""
        w, a = self._comp.omega, self._comp.amplitude
        order = np.argsort(w)
        share = np.cumsum(a[order] ** 2) / np.sum(a * a)
        return float(2.0 * math.pi / w[order][min(np.searchsorted(share, 0.999), len(w) - 1)])

    def elevation(self, x, y, t) -> np.ndarray:
        """η [m] above the still water at horizontal positions ``x``, ``y`` [m], time ``t`` [s]."""
        return self._evaluate(x, y, None, t, ("eta",))["eta"]

    def velocity(self, x, y, z, t) -> np.ndarray:
        """Water velocity [m/s], ``(..., 3)``, at points ``x``, ``y``, ``z`` [m], time ``t`` [s]."""
        o = self._evaluate(x, y, z, t, ("u",))
        return _world(o["uh"], o["w"], self.heading)

    def acceleration(self, x, y, z, t) -> np.ndarray:
        """The local time derivative ∂u/∂t [m/s^2], ``(..., 3)`` (not Du/Dt)."""
        return self.kinematics(x, y, z, t)[1]

    def kinematics(self, x, y, z, t) -> tuple[np.ndarray, np.ndarray]:
        """(velocity [m/s], ∂u/∂t [m/s^2]), each ``(..., 3)``, world frame, z up."""
        return self._vectors(self._evaluate(x, y, z, t, ("u", "a")))

    def surface_and_kinematics(self, x, y, z, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(η [m] over each point, velocity [m/s], ∂u/∂t [m/s^2]) in one pass: each of the
        sea's components costs a cosine and a sine per point, shared by the three."""
        o = self._evaluate(x, y, z, t, ("eta", "u", "a"))
        return (o["eta"], *self._vectors(o))

    def _vectors(self, o):
        e = self.heading
        return _world(o["uh"], o["w"], e), _world(o["ah"], o["aw"], e)

    def dynamic_pressure(self, x, y, z, t, rho: float) -> np.ndarray:
        """The wave's pressure [Pa] in water of density ``rho`` [kg/m^3]: the total pressure
        less the hydrostatic ρ g (level − z)."""
        return rho * self._evaluate(x, y, z, t, ("p",))["p"]

    def pressure(self, x, y, z, t, rho: float) -> np.ndarray:
        """Total pressure [Pa] above the atmosphere: ρ g (level − z) + the dynamic pressure
        (above the still water, the dynamic part is that at the still water: 0 at a linear
        wave's crest)."""
        zz = np.asarray(z, float)
        return rho * self.g * (self.level - zz) + self.dynamic_pressure(x, y, z, t, rho)

    def displacement(self, x, y, z, t) -> tuple[np.ndarray, np.ndarray]:
        """The linear (first-order) displacement [m] of the water particle whose mean position
        is ``x``, ``y``, ``z`` [m] from it at time ``t`` [s], and its rate [m/s], each
        ``(N, 3)`` (points given as 1-D arrays): per component ``ξ_h = −a cosh k(ζ+d)/sinh kd
        sin θ``, ``ξ_z = a sinh k(ζ+d)/sinh kd cos θ`` (Dean & Dalrymple 1991, §4.8: the
        orbits of linear theory), faded in with the sea (the rate is the exact derivative of
        the faded displacement). A wall whose particles move so follows the incident sea
        without disturbing it (to first order). Higher-order terms (Stokes-2) are left out;
        above the still water the displacement at it, below the seabed at the seabed."""
        xs, ys, zs = (np.atleast_1d(np.asarray(v, float)) for v in (x, y, z))
        w, a, ph, k = self._comp
        e = self.heading
        s_pos = xs * e[0] + ys * e[1]
        th = np.multiply.outer(s_pos - self._s_ref, k) - w * t + ph
        ch, sh = depth_factors(zs - self.level, k, self.depth)
        sn, c = np.sin(th), np.cos(th)
        xh, xz = -(ch * sn) @ a, (sh * c) @ a
        uh, uz = (ch * c) @ (a * w), (sh * sn) @ (a * w)
        r, dr = self._fade(s_pos, np.full_like(s_pos, float(t)))
        disp = np.stack([r * xh * e[0], r * xh * e[1], r * xz], axis=-1)
        rate = np.stack([(r * uh + dr * xh) * e[0], (r * uh + dr * xh) * e[1], r * uz + dr * xz], axis=-1)
        return disp, rate

    # -- the machinery ---------------------------------------------------------------------
    def _fade(self, s, t, second: bool = False):
        """The fade-in r and its rate r' [1/s] at positions ``s`` along the heading and times
        ``t`` (1-D, of one length; and ``second``: r'' [1/s^2] too): :func:`_fade_at`."""
        s, t = (np.ascontiguousarray(v, dtype=float) for v in (s, t))
        out = np.empty((3, s.shape[0]))
        _fade_all(s, t, *self._fade_args(), out)
        return (out[0], out[1], out[2]) if second else (out[0], out[1])

    def _fade_args(self) -> tuple:
        """(has_source, source, c_front, ramp) of :func:`_fade_at`."""
        has = self.source is not None
        return has, float(self.source) if has else 0.0, float(self._c_front), float(self.ramp)

    def _evaluate(self, x, y, z, t, want) -> dict:
        """The quantities in ``want`` ("eta", "u" (uh, w), "a" (ah, aw), "p" (p/ρ)) in the
        broadcast shape of the inputs (:meth:`_sums`)."""
        args = [np.asarray(v, float) for v in ([x, y, t] if z is None else [x, y, z, t])]
        if args[-1].ndim == 0 and all(a.ndim == 1 and a.shape == args[0].shape for a in args[:-1]):
            shape, flat = args[0].shape, args[:-1] + [np.full(args[0].shape, float(args[-1]))]  # points, one time
        else:
            arrays = np.broadcast_arrays(*args)
            shape, flat = arrays[0].shape, [np.ascontiguousarray(a.ravel()) for a in arrays]
        xs, ys, ts = flat[0], flat[1], flat[-1]
        e0, e1 = self._heading2
        s = xs * e0 + ys * e1
        zeta = np.empty(0) if z is None else np.clip(flat[2] - self.level, -self.depth, 0.0)
        flags = _flags(want)
        sums = self._sums(s, zeta, ts, flags)
        return {name: sums[row].reshape(shape) for name, row in _ROWS.items() if flags[row]}

    def velocity_at(self, pos: np.ndarray, t: float) -> np.ndarray:
        """The water velocity [m/s] at the points ``pos`` (M, 2) (x, z; y = 0) or (M, 3)
        [m] at time ``t`` [s], in their columns: :meth:`velocity` for an array of particle
        positions, without its broadcasting (a relaxation zone asks every step)."""
        pos = np.asarray(pos, float)
        n, three = pos.shape[0], pos.shape[1] == 3
        e0, e1 = self._heading2
        s = pos[:, 0] * e0 + pos[:, 1] * e1 if three else pos[:, 0] * e0
        zeta = np.clip(pos[:, -1] - self.level, -self.depth, 0.0)
        flags = _flags(("u",))
        sums = self._sums(s, zeta, np.full(n, float(t)), flags)
        out = np.empty((n, pos.shape[1]))
        np.multiply(sums[UH], e0, out=out[:, 0])
        if three:
            np.multiply(sums[UH], e1, out=out[:, 1])
        out[:, -1] = sums[W]
        return out

    def _sums(self, s, zeta, ts, flags) -> np.ndarray:
        """:func:`_linear_sums` at the points ``s`` [m] along the heading, ``zeta`` [m]
        below the still water (empty: the elevation alone) and times ``ts`` [s] (1-D, of
        one length), then the kind's higher-order terms: the rows of (8, n)."""
        sums = np.empty((8, s.shape[0]))
        w, a, ph, k = self._comp
        kernel = _linear_sums_parallel if s.shape[0] * w.shape[0] > _PARALLEL_TERMS else _linear_sums_serial
        kernel(s, zeta, ts, w, a, ph, k, float(self.depth), float(self.g), float(self._s_ref), self._fade_args(), flags,
               sums)
        self._add_higher_order(sums, s, zeta, ts, flags)
        return sums

    @property
    def _heading2(self) -> tuple[float, float]:
        """(cos β, sin β) of the heading, as floats."""
        b = math.radians(self.direction)
        return math.cos(b), math.sin(b)

    @property
    def linear(self) -> bool:
        """Whether the sea is the linear superposition of its components alone (no
        higher-order terms)."""
        return type(self)._add_higher_order is Sea._add_higher_order

    def _add_higher_order(self, sums, s, zeta, t, want) -> None:
        """Add the terms beyond linear superposition to the rows of ``sums`` (those of
        :func:`_linear_sums`, the fade-in in rows 6-7) that ``want`` asks for; ``zeta``
        empty for the elevation alone. None for a linear sea."""


#: the rows of :func:`_linear_sums`' output by name
_ROWS = {"eta": ETA, "uh": UH, "w": W, "ah": AH, "aw": AW, "p": P}
_WANTS = {"eta": (ETA,), "u": (UH, W), "a": (AH, AW), "p": (P,)}
_FLAGS: dict = {}


def _flags(want: tuple) -> np.ndarray:
    """The rows of :func:`_linear_sums` that ``want`` (of "eta", "u", "a", "p") asks for, as
    its 6 booleans (kept per ``want``: the sums are asked for every step)."""
    f = _FLAGS.get(want)
    if f is None:
        f = np.zeros(6, np.bool_)
        for key in want:
            f[list(_WANTS[key])] = True
        _FLAGS[want] = f
    return f


def _world(along: np.ndarray, up: np.ndarray, heading: np.ndarray) -> np.ndarray:
    """The world vectors ``(..., 3)`` of components ``along`` the unit ``heading`` (3,)
    and ``up`` along z."""
    out = np.empty(along.shape + (3,))
    np.multiply(along, heading[0], out=out[..., 0])
    np.multiply(along, heading[1], out=out[..., 1])
    out[..., 2] = up
    return out


# ------------------------------------------------------------------------ regular waves
@dataclass(frozen=True)
class RegularWave(Sea):
    """A regular wave of height ``height`` [m] and period ``period`` [s] in water ``depth``
    [m] deep, ``theory`` "linear" (Airy) or "stokes2" (Stokes second order); ``phase``
    [deg]: η at the origin at t = 0 is a cos(phase) (0: a crest there). ``g`` [m/s^2].

    With a = H/2, ω = 2π/T, k from ω² = g k tanh kd, θ = k (x cos β + y sin β) − ω t +
    phase, linear theory (Dean & Dalrymple 1991, Table 4.1)::

        η = a cos θ,  u_h = a ω cosh k(ζ+d)/sinh kd cos θ,  w = a ω sinh k(ζ+d)/sinh kd sin θ
        p_d = ρ g a cosh k(ζ+d)/cosh kd cos θ

    (u_h along the heading; ∂u/∂t their time derivatives, r' included during the fade-in).

    Stokes second order (Sorensen 2006, Eqs. 3.7–3.10; the profile of §3.2) adds, with
    a₂ = (k a²/4) cosh kd (2 + cosh 2kd)/sinh³ kd (→ k a²/2 in deep water)::

        η₂ = a₂ cos 2θ,  u₂ = (3/4) a² ω k cosh 2k(ζ+d)/sinh⁴ kd cos 2θ,
        w₂ = (3/4) a² ω k sinh 2k(ζ+d)/sinh⁴ kd sin 2θ

    and the pressure from Bernoulli's equation with that potential (derived here; the free-
    surface conditions hold with it to O(a³), tests/test_waves.py), the constant chosen so
    that the mean pressure at the seabed is hydrostatic::

        p₂ = ρ a² ω² [((3/4) cosh 2k(ζ+d)/sinh⁴ kd − 1/(4 sinh² kd)) cos 2θ
                       − (1/2) sinh² k(ζ+d)/sinh² kd]

    The second-order terms fade in with r² (they are those of the amplitude r a). The
    dispersion relation is linear theory's at this order; the mean Eulerian current is 0
    (Stokes' first definition of the celerity). Limits: H/λ ≤ 1/7 (Michell 1893) and
    ≤ 0.142 tanh kd (Miche 1944), H/d ≤ 0.78 (McCowan 1894); Stokes-2 also a₂ ≤ a/4
    (beyond, a secondary crest rises in the trough; Sorensen 2006, Eq. 3.6)."""

    height: float
    period: float
    depth: float
    theory: str = "linear"
    direction: float = 0.0
    phase: float = 0.0
    ramp: float = 0.0
    source: float | None = None
    level: float = 0.0
    g: float = 9.81
    k: float = field(default=math.nan, init=False, compare=False)  #: wavenumber [rad/m]

    owner = "regular wave"

    def __post_init__(self):
        own = self.owner
        H = _number(own, "height", self.height, "m", "the wave height, crest to trough")
        T = _number(own, "period", self.period, "s", "the wave period")
        ph = _number(own, "phase", self.phase, "deg", "the phase at the origin at t = 0", lo=None)
        for name, v in (("height", H), ("period", T), ("phase", ph)):
            object.__setattr__(self, name, v)
        self._check_frame()
        if self.theory not in ("linear", "stokes2"):
            raise SeaError(own, "theory", f"{self.theory!r} is not a theory here; give 'linear' or 'stokes2'")
        k = wavenumber(T, self.depth, self.g)
        object.__setattr__(self, "k", k)
        d, kd = self.depth, k * self.depth
        steep = H * k / (2.0 * math.pi)
        miche = 0.142 * math.tanh(kd)
        if steep > 1.0 / 7.0:
            raise SeaError(own, "height", f"H/λ = {steep:.3f} is beyond the breaking limit 1/7 (Michell 1893); "
                           f"lower H or lengthen T")
        if H > 0.78 * d:
            raise SeaError(own, "height", f"H/d = {H / d:.3f} is beyond the depth-limited breaking limit 0.78 "
                           f"(McCowan 1894); lower H or give a deeper depth")
        if steep > miche:
            raise SeaError(own, "height", f"H/λ = {steep:.4f} is beyond the breaking limit 0.142 tanh(kd) = "
                           f"{miche:.4f} at kd = {kd:.3g} (Miche 1944); lower H or lengthen T")
        a = 0.5 * H
        object.__setattr__(self, "_comp", Components(np.array([self.omega]), np.array([a]),
                                                     np.array([math.radians(ph)]), np.array([k])))
        object.__setattr__(self, "_c_front", self.group_velocity)
        if self.theory == "stokes2" and self.second_harmonic > 0.25 * a:
            lam = 2.0 * math.pi / k
            limit = 0.25 * a / self.second_harmonic * steep  # a₂ ∝ H²: the steepness where a₂ = a/4
            raise SeaError(own, "height", f"the second harmonic's amplitude {self.second_harmonic:.4g} m is above "
                           f"a quarter of the first's ({0.25 * a:.4g} m): a secondary crest rises in the trough, "
                           f"outside Stokes second order's range (Sorensen 2006, Eq. 3.6: H/λ <= {limit:.4f} at "
                           f"d/λ = {d / lam:.3g}; here H/λ = {steep:.4f}, Ursell number H λ²/d³ = "
                           f"{self.ursell:.3g}); lower H, or use theory = 'linear' (a cnoidal theory would fit "
                           f"this shallow a wave)")
        # Stokes second order's wave (stokes2_wave): None for a linear one
        object.__setattr__(self, "_stokes2", stokes2_wave(k, self.omega, a, d, math.radians(ph), self.second_harmonic)
                           if self.theory == "stokes2" else None)

    @property
    def omega(self) -> float:
        """Angular frequency ω = 2π/T [rad/s]."""
        return 2.0 * math.pi / self.period

    @property
    def amplitude(self) -> float:
        """First-order amplitude a = H/2 [m]."""
        return 0.5 * self.height

    @property
    def wavenumber(self) -> float:
        """k [rad/m]."""
        return self.k

    @property
    def wavelength(self) -> float:
        """λ = 2π/k [m]."""
        return 2.0 * math.pi / self.k

    @property
    def peak_period(self) -> float:
        """T [s] (the one period of a regular wave)."""
        return self.period

    @property
    def phase_velocity(self) -> float:
        """c = ω/k [m/s]."""
        return self.omega / self.k

    @property
    def group_velocity(self) -> float:
        """c_g [m/s] (Dean & Dalrymple 1991, eq. 4.79)."""
        return float(group_velocity(self.k, self.depth, self.g))

    @property
    def ursell(self) -> float:
        """Ursell number H λ² / d³."""
        return self.height * self.wavelength**2 / self.depth**3

    @property
    def second_harmonic(self) -> float:
        """a₂ [m], the amplitude of η's second harmonic (0 for linear theory)."""
        if self.theory != "stokes2":
            return 0.0
        kd = self.k * self.depth
        q = math.exp(-2.0 * kd)
        inv_sh2 = 4.0 * q / (1.0 - q) ** 2  # 1 / sinh² kd
        coth = (1.0 + q) / (1.0 - q)
        # cosh kd (2 + cosh 2kd) / sinh³ kd = coth kd (2 + 3 / sinh² kd)
        return 0.25 * self.k * self.amplitude**2 * coth * (2.0 + 3.0 * inv_sh2)

    @property
    def shortest_period(self) -> float:
        return self.period / (2.0 if self.theory == "stokes2" else 1.0)

    @property
    def linear(self) -> bool:
        return self.theory != "stokes2"

    def _add_higher_order(self, sums, s, zeta, t, want) -> None:
        if self._stokes2 is not None:
            _stokes2_terms(s, zeta, t, self._stokes2, float(self.depth), want, sums)


@dataclass(frozen=True)
class StillWater(Sea):
    """Still water ``depth`` [m] deep: no incident wave, one component of zero amplitude at
    ``period`` [s], so that its kinematics are zero everywhere. The period is that of the
    waves the bodies in it radiate (a forced-oscillation test): a near field sizes its
    relaxation zones by it and relaxes at a rate in its frequency
    (:func:`fluid.nearfield.choose_box`), as it does by a sea's peak period."""

    period: float
    depth: float
    direction: float = 0.0
    ramp: float = 0.0
    source: float | None = None
    level: float = 0.0
    g: float = 9.81
    k: float = field(default=math.nan, init=False, compare=False)  #: wavenumber at the period [rad/m]

    owner = "still water"
    height = 0.0

    def __post_init__(self):
        T = _number(self.owner, "period", self.period, "s", "the period of the waves the bodies radiate")
        object.__setattr__(self, "period", T)
        self._check_frame()
        k = float(wavenumbers(2.0 * math.pi / T, self.depth, self.g))
        object.__setattr__(self, "k", k)
        object.__setattr__(self, "_comp", Components(np.array([2.0 * math.pi / T]), np.array([0.0]),
                                                     np.array([0.0]), np.array([k])))

    @property
    def peak_period(self) -> float:
        """The period [s] given."""
        return self.period

    @property
    def shortest_period(self) -> float:
        """The period [s] given (there is no variance to weigh)."""
        return self.period

    @property
    def wavelength(self) -> float:
        """The wavelength [m] at the period (linear dispersion)."""
        return 2.0 * math.pi / self.k


# ------------------------------------------------------------------------ irregular seas
def _check_duration(owner, name, repeat: float, duration, how: str) -> None:
    if duration is not None and repeat < duration:
        raise SeaError(owner, name, f"the sea repeats itself every {repeat:.4g} s (2π/Δω), less than the "
                       f"run's {duration:.4g} s; {how}")


def _check_steepness(owner, name, hs, k_peak) -> None:
    steep = hs * k_peak / (2.0 * math.pi)
    if steep > 0.1:
        raise SeaError(owner, name, f"Hs/Lp = {steep:.4f} is beyond 0.1 (Lp the linear wavelength at the peak "
                       f"period): its largest waves would break (severe seas have 1/16 to 1/20); lower Hs or "
                       f"lengthen Tp")


@dataclass(frozen=True)
class SpectralSea(Sea):
    """A long-crested irregular sea of significant height ``hs`` [m] and peak period ``tp``
    [s] with the ``spectrum`` "jonswap" (peak enhancement ``gamma``, 1 to 7; see
    :func:`jonswap`) or "pierson-moskowitz" (:func:`pierson_moskowitz`), in water ``depth``
    [m] deep: the linear superposition of ``n_components`` waves of frequencies ω_j = j Δω
    (integers j) spread evenly over ``band`` [rad/s] (default 0.5 ωp to 4 ωp, which holds
    all but 0.2–0.5 % of the variance), amplitudes a_j = sqrt(2 S(ω_j) Δω) (deterministic)
    and phases drawn uniformly in [0, 2π) from ``numpy.random.default_rng(seed)``; k_j from
    the dispersion relation. The record repeats itself every 2π/Δω: give the run's
    ``duration`` [s] and the default number of components (200, or more) makes that at
    least the duration, or a given number that is too small is refused. Refused: Hs/Lp >
    0.1 (Lp the wavelength at Tp)."""

    hs: float
    tp: float
    depth: float
    spectrum: str = "jonswap"
    gamma: float = 3.3
    seed: int = 0
    n_components: int | None = None
    band: tuple | None = None
    duration: float | None = None
    direction: float = 0.0
    ramp: float = 0.0
    source: float | None = None
    level: float = 0.0
    g: float = 9.81

    owner = "irregular sea"
    SPECTRA = ("jonswap", "pierson-moskowitz")

    def __post_init__(self):
        own = self.owner
        hs = _number(own, "hs", self.hs, "m", "the significant wave height")
        tp = _number(own, "tp", self.tp, "s", "the peak period")
        object.__setattr__(self, "hs", hs)
        object.__setattr__(self, "tp", tp)
        self._check_frame()
        if self.spectrum not in self.SPECTRA:
            raise SeaError(own, "spectrum", f"{self.spectrum!r} is not a spectrum here; give one of "
                           f"{', '.join(map(repr, self.SPECTRA))}")
        gamma = 1.0 if self.spectrum == "pierson-moskowitz" else _number(own, "gamma", self.gamma, "-",
                                                                          "the peak enhancement factor", lo=1.0,
                                                                          lo_open=False)
        if gamma > 7.0:
            raise SeaError(own, "gamma", f"{gamma:g} is above 7: the JONSWAP normalisation A_γ = 1 − 0.287 ln γ "
                           f"misses the variance by more than 2 % there; give 1 <= gamma <= 7 (3.3: the mean "
                           f"JONSWAP sea)")
        object.__setattr__(self, "gamma", gamma)
        if isinstance(self.seed, bool) or not isinstance(self.seed, (int, np.integer)) or self.seed < 0:
            raise SeaError(own, "seed", f"{self.seed!r}; give a whole number >= 0 (the random phases' seed)")
        if self.duration is not None:
            object.__setattr__(self, "duration", _number(own, "duration", self.duration, "s", "the run's length"))
        wp = self.omega_peak
        lo, hi = (0.5 * wp, 4.0 * wp) if self.band is None else self.band
        lo = _number(own, "band", lo, "rad/s", "the lowest frequency of the components", lo=0.0)
        hi = _number(own, "band", hi, "rad/s", "the highest frequency of the components", lo=lo)
        if not lo < wp < hi:
            raise SeaError(own, "band", f"({lo:.4g}, {hi:.4g}) rad/s leaves out the peak ωp = {wp:.4g} rad/s; give "
                           f"a band around it")
        n = self.n_components
        if n is None:
            need = 0 if self.duration is None else math.ceil(self.duration * (hi - lo) / (2.0 * math.pi))
            n = max(200, need)
        elif isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2:
            raise SeaError(own, "n_components", f"{n!r}; give a whole number >= 2 of wave components")
        dw = (hi - lo) / n
        if self.duration is not None:
            _check_duration(own, "n_components", 2.0 * math.pi / dw, self.duration,
                            f"give at least {math.ceil(self.duration * (hi - lo) / (2.0 * math.pi))} components (or "
                            f"leave them unset)")
        j0 = max(1, round(lo / dw + 0.5))  # ω_j = j Δω: the record is periodic in 2π/Δω
        w = dw * np.arange(j0, j0 + n)
        a = np.sqrt(2.0 * self.spectrum_at(w) * dw)
        phase = np.random.default_rng(int(self.seed)).uniform(0.0, 2.0 * math.pi, n)
        k = wavenumbers(w, self.depth, self.g)
        object.__setattr__(self, "n_components", int(n))
        object.__setattr__(self, "_dw", dw)
        object.__setattr__(self, "_comp", Components(w, a, phase, k))
        kp = float(wavenumbers(wp, self.depth, self.g))
        object.__setattr__(self, "_kp", kp)
        object.__setattr__(self, "_c_front", float(group_velocity(kp, self.depth, self.g)))
        _check_steepness(own, "hs", hs, kp)

    def spectrum_at(self, omega) -> np.ndarray:
        """The target spectrum S(ω) [m² s/rad] at ``omega`` [rad/s]."""
        if self.spectrum == "pierson-moskowitz":
            return pierson_moskowitz(omega, self.hs, self.tp)
        return jonswap(omega, self.hs, self.tp, self.gamma)

    @property
    def omega_peak(self) -> float:
        """ωp = 2π/Tp [rad/s]."""
        return 2.0 * math.pi / self.tp

    @property
    def peak_period(self) -> float:
        return self.tp

    @property
    def d_omega(self) -> float:
        """Δω [rad/s], the spacing of the components."""
        return self._dw

    @property
    def repeat_period(self) -> float:
        """2π/Δω [s]: the record repeats itself after this."""
        return 2.0 * math.pi / self._dw

    @property
    def wavenumber(self) -> float:
        """k at the peak period [rad/m]."""
        return self._kp

    @property
    def wavelength(self) -> float:
        """Lp [m], the linear wavelength at the peak period."""
        return 2.0 * math.pi / self._kp

    @property
    def group_velocity(self) -> float:
        """c_g at the peak period [m/s]."""
        return self._c_front

    def moment(self, n: int) -> float:
        """The spectral moment m_n = Σ ω_j^n a_j²/2 of the components [m² (rad/s)^n]."""
        w, a = self._comp.omega, self._comp.amplitude
        return float(np.sum(w**n * a * a) / 2.0)

    @property
    def zero_crossing_period(self) -> float:
        """Tz = 2π sqrt(m0/m2) [s] of the components."""
        return 2.0 * math.pi * math.sqrt(self.moment(0) / self.moment(2))


@dataclass(frozen=True)
class RecordedSea(Sea):
    """The sea whose elevation ``eta`` [m] was recorded at times ``times`` [s] (evenly
    spaced) at the horizontal point ``at`` = (x, y) [m]: the record, less its mean (a
    gauge's datum, not a wave), is split by FFT into linear components of frequencies
    ω_j = 2π j / (N Δt), j = 1 .. N/2, each a free wave with k from the dispersion relation
    travelling along ``direction``; at ``at`` the sum reproduces the samples to round-off
    (and is periodic in the record's length N Δt, which must cover the run's ``duration``
    [s] when given). ``min_period`` [s]: components of shorter periods are left out (default
    none: up to the Nyquist frequency, 2 Δt); so are those below 1e-13 of the largest (the
    transform's round-off). The fade-in's front (``source``) travels at the
    group velocity of the largest component. Refused: a record of fewer than 4 samples,
    uneven or not increasing times, non-finite values, no wave at all, Hs/Lp > 0.1."""

    times: tuple
    eta: tuple
    depth: float
    at: tuple = (0.0, 0.0)
    min_period: float | None = None
    duration: float | None = None
    direction: float = 0.0
    ramp: float = 0.0
    source: float | None = None
    level: float = 0.0
    g: float = 9.81

    owner = "recorded sea"

    def __post_init__(self):
        own = self.owner
        t = np.asarray(self.times, float)
        eta = np.asarray(self.eta, float)
        if t.ndim != 1 or t.shape != eta.shape or t.size < 4:
            raise SeaError(own, "elevation", f"need matching 1-D times and elevations of at least 4 samples, got "
                           f"shapes {t.shape} and {eta.shape}")
        if not (np.isfinite(t).all() and np.isfinite(eta).all()):
            raise SeaError(own, "elevation", "times and elevations must be finite numbers")
        dt = np.diff(t)
        step = (t[-1] - t[0]) / (t.size - 1)
        if not (dt > 0).all() or np.abs(dt - step).max() > 1e-6 * step:
            raise SeaError(own, "times", f"the samples must be evenly spaced and increasing (steps from "
                           f"{dt.min():.6g} to {dt.max():.6g} s); resample the record to one step")
        self._check_frame()
        try:
            at = tuple(float(v) for v in self.at)
        except (TypeError, ValueError):
            at = ()
        if len(at) not in (1, 2) or not all(map(math.isfinite, at)):
            raise SeaError(own, "at", f"{self.at!r}; give the record's point as (x, y) [m]")
        at = at + (0.0,) * (2 - len(at))
        object.__setattr__(self, "at", at)
        if self.duration is not None:
            object.__setattr__(self, "duration", _number(own, "duration", self.duration, "s", "the run's length"))
        if self.min_period is not None:
            object.__setattr__(self, "min_period", _number(own, "min_period", self.min_period, "s",
                                                           "the shortest period kept"))
        n = t.size
        length = n * step
        _check_duration(own, "duration", length, self.duration, "give a record at least as long as the run")
        mean = float(eta.mean())
        X = np.fft.rfft(eta - mean)
        j = np.arange(1, n // 2 + 1)
        w = 2.0 * math.pi * j / length
        amp = 2.0 * np.abs(X[1:]) / n
        if n % 2 == 0:
            amp[-1] *= 0.5  # the Nyquist term appears once
        phase = w * t[0] - np.angle(X[1:])  # η(t_m) = Σ a cos(ω (t_m − t_0) + arg X) = Σ a cos(φ − ω t_m)
        if self.min_period is not None:
            keep = w <= 2.0 * math.pi / self.min_period
            if not keep.any():
                raise SeaError(own, "min_period", f"{self.min_period:g} s leaves no component (the longest period "
                               f"in the record is {length:.4g} s); give a shorter one")
            w, amp, phase = w[keep], amp[keep], phase[keep]
        if not amp.max() > 0:
            raise SeaError(own, "elevation", "the record holds no wave (it is constant); give a measured elevation")
        keep = amp > 1e-13 * amp.max()  # the others are the transform's round-off
        w, amp, phase = w[keep], amp[keep], phase[keep]
        k = wavenumbers(w, self.depth, self.g)
        e = self.heading
        object.__setattr__(self, "_s_ref", at[0] * e[0] + at[1] * e[1])
        object.__setattr__(self, "_comp", Components(w, amp, phase, k))
        object.__setattr__(self, "mean", mean)
        object.__setattr__(self, "_length", float(length))
        peak = int(np.argmax(amp))
        object.__setattr__(self, "_peak", peak)
        object.__setattr__(self, "_c_front", float(group_velocity(k[peak], self.depth, self.g)))
        _check_steepness(own, "elevation", self.hs, k[peak])

    @classmethod
    def from_file(cls, path, depth: float, column: int = 1, **kw) -> "RecordedSea":
        """Read a whitespace- or comma-separated table: the time [s] first, the elevation [m]
        in ``column`` (text lines before the first row of numbers are a header)."""
        path = Path(path)
        if not path.is_file():
            raise SeaError(cls.owner, "file", f"no file {str(path)!r}")
        rows = []
        for line in path.read_text().splitlines():
            parts = line.replace(",", " ").split()
            try:
                rows.append((float(parts[0]), float(parts[column])))
            except (ValueError, IndexError):
                if rows:
                    raise SeaError(cls.owner, "file", f"{str(path)!r}: cannot read line {line!r} (time, elevation "
                                   f"in column {column})") from None
        if not rows:
            raise SeaError(cls.owner, "file", f"{str(path)!r} holds no row of numbers")
        a = np.array(rows)
        return cls(tuple(a[:, 0]), tuple(a[:, 1]), depth, **kw)

    @property
    def hs(self) -> float:
        """Significant height 4 sqrt(m0) [m] of the components."""
        return 4.0 * math.sqrt(float(np.sum(self._comp.amplitude**2)) / 2.0)

    @property
    def peak_period(self) -> float:
        """The period of the largest component [s]."""
        return float(2.0 * math.pi / self._comp.omega[self._peak])

    @property
    def repeat_period(self) -> float:
        """The record's length N Δt [s]: the sea repeats itself after it."""
        return self._length

    @property
    def wavenumber(self) -> float:
        """k of the largest component [rad/m]."""
        return float(self._comp.k[self._peak])

    @property
    def wavelength(self) -> float:
        """The wavelength of the largest component [m]."""
        return 2.0 * math.pi / self.wavenumber

    @property
    def group_velocity(self) -> float:
        """c_g of the largest component [m/s]."""
        return self._c_front
