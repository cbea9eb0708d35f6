"""A linear sea's kinematics where the near field asks for them every step, at a cost
independent of the number of wave components per particle.

A many-component sea (``fluid.waves.SpectralSea``: 200 components or more) evaluated
directly costs a cosine, a sine and two exponentials per particle and component: at every
step for the particles of the relaxation zones (their target velocity) and several times
a step for the end walls (their orbits and the finite difference of their velocity), which
can cost several times the SPH itself in a 2-D near field. Both separate:

- The phase ``θ = α − β``, ``α = k (s − s_ref)`` fixed in space and ``β = ω t − phase`` in
  time, so ``cos θ = cos α cos β + sin α sin β`` and ``sin θ = sin α cos β − cos α sin β``;
  the depth factors ``cosh k(ζ+d)/sinh kd`` and ``sinh k(ζ+d)/sinh kd`` depend on ζ alone.
- :class:`PointOrbits`: the orbit displacement and its rate at fixed mean positions (the end
  walls' particles never change theirs): the space and depth factors are kept per point,
  and each time costs four sums over the components per point, with no transcendental.
  The same sums as ``Sea.displacement`` in another order, exact to round-off.
- :class:`VelocityTable`: the velocity on a grid in (s, ζ) at times ``n Δt``, each frame
  (s nodes × ζ nodes) sums over the components with no transcendental, read at the
  particles by linear interpolation in s, ζ and t. :data:`NODES_PER_WAVELENGTH` nodes
  per wavelength and :data:`FRAMES_PER_PERIOD` frames per period of the sea's shortest
  period (``Sea.shortest_period``, 99.9 % of the variance): the interpolation's error,
  ``(k Δ)² / 8`` and ``(ω Δt)² / 8`` of a component's velocity, is below 1.4 % for those
  components and below 0.03 % at a peak 2.5 times longer.

The orbits are linear for every sea, as ``Sea.displacement``'s. The velocity table is for
linear seas only: a sea with terms beyond linear superposition (Stokes-2) is evaluated
directly (:func:`tabulable`); so is one of few components, where nothing is to be gained.
The linear theory is Dean & Dalrymple (1991), §4 (as in ``fluid.waves``); the fade-in is
the sea's own (``Sea._fade``).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from fluid.waves import depth_factors, wavenumbers

#: table nodes per wavelength of the sea's shortest period (linear interpolation error
#: (2π/24)²/8 = 0.9 % of those components' velocity)
NODES_PER_WAVELENGTH = 24
#: frames per period of the sea's shortest period (error (2π/32)²/8 = 0.5 %)
FRAMES_PER_PERIOD = 32
#: seas of fewer components are evaluated directly
MIN_COMPONENTS = 8


def tabulable(sea) -> bool:
    """Whether ``sea`` is a linear superposition of at least :data:`MIN_COMPONENTS` waves
    (no higher-order terms), which the tables here evaluate."""
    return sea.linear and len(sea._comp.omega) >= MIN_COMPONENTS


def _time_factors(sea, t: float) -> tuple[np.ndarray, np.ndarray]:
    """cos β and sin β of each component at time ``t`` [s], ``β = ω t − phase``."""
    c = sea._comp
    beta = c.omega * t - c.phase
    return np.cos(beta), np.sin(beta)


def _along(sea, x, y) -> np.ndarray:
    e = sea.heading
    return np.asarray(x, float) * e[0] + np.asarray(y, float) * e[1]


@njit(cache=True, fastmath=True)
def _orbit_motion(chc, chs, shc, shs, a, w, cb, sb, r, dr, ddr, ex, ey, out):
    """Per point p, with ``θ = α − β``, ``chc = ch cos α``, ``chs = ch sin α`` (``sh``
    alike), ``cb = cos β``, ``sb = sin β``: the sums ξ_h = −Σ_j a_j ch sin θ, ξ_z = Σ_j a_j
    sh cos θ, u = ∂ξ/∂t (Σ a_j ω_j (ch cos θ, sh sin θ)) and ∂u/∂t (Σ a_j ω_j² (ch sin θ,
    −sh cos θ)), faded with the point's ``r``, ``r'``, ``r''`` (``r ξ``, ``r u + r' ξ``, ``r
    ∂u/∂t + 2 r' u + r'' ξ``) into ``out`` (3, N, 3): displacement, rate, second rate, the
    horizontal part along the heading (``ex``, ``ey``); ``out`` (3, N, 2): their (x, z)
    columns."""
    for p in range(chc.shape[0]):
        o0 = o1 = o2 = o3 = o4 = o5 = 0.0
        for j in range(chc.shape[1]):
            chsin = chs[p, j] * cb[j] - chc[p, j] * sb[j]
            shcos = shc[p, j] * cb[j] + shs[p, j] * sb[j]
            a1 = a[j] * w[j]
            o0 += a[j] * chsin
            o1 += a[j] * shcos
            o2 += a1 * (chc[p, j] * cb[j] + chs[p, j] * sb[j])
            o3 += a1 * (shs[p, j] * cb[j] - shc[p, j] * sb[j])
            o4 += a1 * w[j] * chsin
            o5 += a1 * w[j] * shcos
        xh, xz, uh, uz, ah, az = -o0, o1, o2, o3, o4, -o5
        parts = ((r[p] * xh, r[p] * xz), (r[p] * uh + dr[p] * xh, r[p] * uz + dr[p] * xz),
                 (r[p] * ah + 2.0 * dr[p] * uh + ddr[p] * xh, r[p] * az + 2.0 * dr[p] * uz + ddr[p] * xz))
        for q in range(3):
            h, v = parts[q]
            out[q, p, 0] = h * ex
            if out.shape[2] == 3:
                out[q, p, 1] = h * ey
            out[q, p, out.shape[2] - 1] = v


class PointOrbits:
    """The linear orbits of the sea's water particles whose mean positions are ``x``, ``y``,
    ``z`` [m] (1-D arrays): :meth:`displacement` equals ``sea.displacement(x, y, z, t)``;
    :meth:`motion` adds the acceleration."""

    def __init__(self, sea, x, y, z):
        self.sea = sea
        w, a, ph, k = sea._comp
        self.s = _along(sea, x, y)
        alpha = np.multiply.outer(self.s - sea._s_ref, k)
        ca, sa = np.cos(alpha), np.sin(alpha)
        ch, sh = depth_factors(np.asarray(z, float) - sea.level, k, sea.depth)
        self._f = tuple(np.ascontiguousarray(f) for f in (ch * ca, ch * sa, sh * ca, sh * sa))
        self._a, self._w = a, w

    def motion(self, t: float, dim: int = 3) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(displacement [m], its rate [m/s], its second rate [m/s^2]), each (N, 3) (``dim``
        2: their (x, z) columns, (N, 2)), at time ``t`` [s], the fade-in r(t) included: ``r
        ξ``, ``r u + r' ξ``, ``r ∂u/∂t + 2 r' u + r'' ξ``, with ξ = (−Σ a ch sin θ, Σ a sh
        cos θ) the linear displacement, u = ∂ξ/∂t its velocity (θ = α − ω t + phase)."""
        sea = self.sea
        cb, sb = _time_factors(sea, t)
        r, dr, ddr = sea._fade(self.s, np.full_like(self.s, float(t)), second=True)
        e0, e1 = sea._heading2
        out = np.empty((3, len(self.s), dim))
        _orbit_motion(*self._f, self._a, self._w, cb, sb, r, dr, ddr, e0, e1, out)
        return out[0], out[1], out[2]

    def displacement(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """(displacement [m], its rate [m/s]), each (N, 3), at time ``t`` [s]: as
        ``Sea.displacement``."""
        return self.motion(t)[:2]


@njit(parallel=True, cache=True, fastmath=True)
def _frame(ca, sa, cb, sb, ch, sh, r, uh, uz):
    """One time's table: ``uh[i, m] = r_i Σ_j ch[m, j] (ca[i, j] cb_j + sa[i, j] sb_j)`` and
    ``uz[i, m] = r_i Σ_j sh[m, j] (sa[i, j] cb_j − ca[i, j] sb_j)`` (``ch``, ``sh`` carry a ω)."""
    nj = ca.shape[1]
    for i in prange(ca.shape[0]):
        c = np.empty(nj)
        s = np.empty(nj)
        for j in range(nj):
            c[j] = ca[i, j] * cb[j] + sa[i, j] * sb[j]
            s[j] = sa[i, j] * cb[j] - ca[i, j] * sb[j]
        for m in range(ch.shape[0]):
            a = 0.0
            b = 0.0
            for j in range(nj):
                a += ch[m, j] * c[j]
                b += sh[m, j] * s[j]
            uh[i, m] = r[i] * a
            uz[i, m] = r[i] * b


@njit(parallel=True, cache=True)
def _trilinear(h0, z0_, h1, z1_, q, s0, ds, z0, dz, s, zeta, out_h, out_z):
    """Linear interpolation between the frames (``h0``, ``z0_``) and (``h1``, ``z1_``) (Gs,
    Gz) at the fraction ``q`` of the time between them, and bilinear in each on nodes
    ``s0 + i ds``, ``z0 + j dz``, at the points ``s``, ``zeta``, clamped to the table."""
    gs, gz = h0.shape
    for p in prange(s.shape[0]):
        fs = min(max((s[p] - s0) / ds, 0.0), gs - 1.0)
        fz = min(max((zeta[p] - z0) / dz, 0.0), gz - 1.0)
        i = min(int(fs), gs - 2)
        j = min(int(fz), gz - 2)
        a, b = fs - i, fz - j
        w00, w10, w01, w11 = (1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b
        u0 = w00 * h0[i, j] + w10 * h0[i + 1, j] + w01 * h0[i, j + 1] + w11 * h0[i + 1, j + 1]
        u1 = w00 * h1[i, j] + w10 * h1[i + 1, j] + w01 * h1[i, j + 1] + w11 * h1[i + 1, j + 1]
        v0 = w00 * z0_[i, j] + w10 * z0_[i + 1, j] + w01 * z0_[i, j + 1] + w11 * z0_[i + 1, j + 1]
        v1 = w00 * z1_[i, j] + w10 * z1_[i + 1, j] + w01 * z1_[i, j + 1] + w11 * z1_[i + 1, j + 1]
        out_h[p] = u0 + q * (u1 - u0)
        out_z[p] = v0 + q * (v1 - v0)


class VelocityTable:
    """The sea's linear velocity tabulated over ``s_lo .. s_hi`` [m] along the heading (s =
    x cos β + y sin β), the whole depth and time; :meth:`velocity` reads it at points.
    Points beyond the table take its edge's value: give the range the particles can reach.
    Above the still water the velocity is that at it, below the seabed that at the seabed
    (as ``Sea.velocity``). The two frames last used are kept."""

    def __init__(self, sea, s_lo: float, s_hi: float):
        period = sea.shortest_period
        k = wavenumbers(np.array([2.0 * math.pi / period]), sea.depth, sea.g)[0]
        spacing = 2.0 * math.pi / k / NODES_PER_WAVELENGTH
        self.sea, self.dt = sea, period / FRAMES_PER_PERIOD
        self.s = np.linspace(s_lo, s_hi, max(2, math.ceil((s_hi - s_lo) / spacing) + 1))
        self.zeta = np.linspace(-sea.depth, 0.0, max(2, math.ceil(sea.depth / spacing) + 1))
        w, a, _, k = sea._comp
        alpha = np.multiply.outer(self.s - sea._s_ref, k)
        self._ca, self._sa = np.cos(alpha), np.sin(alpha)
        ch, sh = depth_factors(self.zeta, k, sea.depth)
        self._ch, self._sh = np.ascontiguousarray(ch * (a * w)), np.ascontiguousarray(sh * (a * w))
        self._frames = {}

    @property
    def shape(self) -> tuple[int, int]:
        """The table's nodes (along s, along ζ)."""
        return len(self.s), len(self.zeta)

    def _at(self, n: int):
        """The frame at time ``n dt``: (uh, uz) (Gs, Gz)."""
        if n not in self._frames:
            t = n * self.dt
            cb, sb = _time_factors(self.sea, t)
            r, _ = self.sea._fade(self.s, np.full_like(self.s, t))
            uh, uz = np.empty(self.shape), np.empty(self.shape)
            _frame(self._ca, self._sa, cb, sb, self._ch, self._sh, r, uh, uz)
            self._frames = {m: f for m, f in self._frames.items() if m >= n - 1} | {n: (uh, uz)}
        return self._frames[n]

    def velocity(self, x, y, z, t: float) -> np.ndarray:
        """Water velocity [m/s], (N, 3), at points ``x``, ``y``, ``z`` [m] (1-D), time ``t`` [s]."""
        sea = self.sea
        n = math.floor(t / self.dt)
        (h0, z0), (h1, z1) = self._at(n), self._at(n + 1)
        s = np.ascontiguousarray(_along(sea, x, y))
        zeta = np.ascontiguousarray(np.asarray(z, float) - sea.level)
        uh, uz = np.empty(s.size), np.empty(s.size)
        _trilinear(h0, z0, h1, z1, t / self.dt - n, self.s[0], self.s[1] - self.s[0], self.zeta[0],
                   self.zeta[1] - self.zeta[0], s, zeta, uh, uz)
        e = sea.heading
        return np.stack([uh * e[0], uh * e[1], uz], axis=-1)
