"""The SPH cable of Dinçer & Demir 2020: a 1-D chain of SPH particles with
axial stiffness in tension only, as a stand-alone solver (:class:`SPHCable`) and as a
mooring model (:class:`SPHCableMooring`, the ``cosim.protocol.Mooring`` interface).

The cable is a 1-D continuum in its unstretched arc length ``s`` (total-Lagrangian SPH,
Wendland C2 with h = ds: two neighbours per particle); line density ``lam = rho A`` [kg/m],
tension ``T = sigma A`` [N]. Dinçer & Demir 2020, Eq. 1-12, as read here:

* Continuity, Eq. 1-4, integrated exactly: ``lam = lam0 / (1 + strain)``; the δ-SPH term
  (``delta``) is off by default (in a solid it is creep).
* Stress, Eq. 6-9: uniaxial, at stress points midway between particles (Dyka & Ingel 1995),
  ``T_k = EA max(0, l_k/ds_k - 1)``: engineering strain, tension only.
* Momentum, Eq. 5: ``m_a dv_a/dt = T_k e_k - T_{k-1} e_{k-1} - (viscous) + weight + loads``;
  central, antisymmetric pair forces conserve linear and angular momentum.
* Artificial viscosity, Eq. 10-11, on approaching pairs of taut segments, with a minus
  sign (as printed, ``+pi_ab`` would not dissipate).
* Damping, Eq. 12, read as its stated intent (Section 4): ``f_a = -omega m_a v_a``,
  ``omega`` [1/s] (default 0.04; each underdamped mode decays at omega/2).
* Leap-frog (kick-drift) sub-steps in compiled code (:func:`moorings.sph_cable_kernels.advance`)
  within :meth:`SPHCable.step_limit` (Courant; the highest axial mode with every damping
  rate; the δ-term's diffusion), ``dt_limit`` naming what set it.

Why each choice, the derivations and the step limits in full: docs/sph_cable.md.

Usage::

    from moorings.sph_cable import SPHCable, SPHCableMooring
    c = SPHCable(312.73, 313, 7.184e7, 4.703, (0, 0), (304.8, 0), weight_per_length=46.12,
                 omega=2.5, nodes_at=(125.88,))          # Dinçer & Demir 2020, Case 1
    c.advance(0.0, 30.0)                                 # one call, compiled sub-steps
    c.add_point_load(125.88, (0.0, -35586.0)); c.advance(30.0, 30.0)
    c.position_at(125.88), c.end_forces(), c.tension

    moor = SPHCableMooring(lines, fairleads=fairleads, n_particles=40)  # same lines as
    # CatenaryMooring(lines, fairleads): the coupler swaps one for the other

Discretisation: ``n_particles`` nodes at material coordinates ``s``, both ends included;
a node's mass is half of each adjacent segment's; ``nodes_at`` forces nodes at given ``s``
(point loads or masses off a node are split linearly between the two nearest).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from errors import InputError, InstabilityError
from moorings import sph_cable_kernels as _k
from moorings.fairlead_stiffness import FairleadStiffness, axial
from moorings.line import MooringLine, named_lines, vertical_plane
from moorings.line_events import LineStateLog, node_states

log = logging.getLogger(__name__)

G_STANDARD = 9.80665


def node_shares(ds) -> np.ndarray:
    """Each node's share of the line [m]: half of each adjacent segment of rest lengths
    ``ds`` (n - 1), so ``n`` shares summing to the length (its mass and weight go with it)."""
    half = np.zeros(len(ds) + 1)
    half[:-1] += 0.5 * np.asarray(ds)
    half[1:] += 0.5 * np.asarray(ds)
    return half


def material_coordinates(length: float, n_particles: int, nodes_at=()) -> np.ndarray:
    """Unstretched arc coordinates [m] of ``n_particles`` nodes from 0 to ``length``,
    uniformly spaced between the breakpoints ``nodes_at`` [m], which become nodes too."""
    bps = sorted({0.0, float(length), *[float(s) for s in nodes_at]})
    n_seg = n_particles - 1
    if n_seg < len(bps) - 1:
        raise InputError(f"n_particles = {n_particles} is too few for {len(bps) - 2} nodes_at points")
    lengths = np.diff(bps)
    # distribute segments in proportion to the piece lengths, at least one per piece
    counts = np.maximum(1, np.floor(lengths / length * n_seg).astype(int))
    while counts.sum() < n_seg:
        counts[np.argmax(lengths / counts)] += 1
    while counts.sum() > n_seg:
        i = np.argmin(np.where(counts > 1, lengths / counts, np.inf))
        counts[i] -= 1
    s = [0.0]
    for a, b, c in zip(bps[:-1], bps[1:], counts):
        s.extend(np.linspace(a, b, c + 1)[1:])
    return np.asarray(s)


def catenary_points(a, b, length: float, s) -> np.ndarray:
    """Points at arc coordinates ``s`` [m] of the inextensible catenary of ``length`` [m]
    hanging from ``a`` to ``b`` (z up, in the vertical plane through both); a straight
    line if the supports are ``length`` or more apart."""
    a = np.asarray(a, float)
    d = np.asarray(b, float) - a
    s = np.asarray(s, float)
    X, Z, in_world = vertical_plane(a, b)
    if float(np.linalg.norm(d)) >= length * (1 - 1e-12):
        return a + np.outer(s / length, d)
    if X <= 1e-9 * length:  # vertical: hang down and back up
        raise InputError("supports on one vertical line: give the initial positions explicitly")
    target = math.sqrt(length * length - Z * Z)
    f = lambda c: 2 * c * math.sinh(X / (2 * c)) - target  # noqa: E731
    lo, hi = X * 1e-3, X * 1e6
    while f(lo) == math.inf or not math.isfinite(f(lo)):
        lo *= 2
    c = brentq(f, lo, hi, xtol=1e-14 * X, rtol=1e-15)
    x0 = X / 2 - c * math.asinh(Z / (2 * c * math.sinh(X / (2 * c))))
    xs = x0 + c * np.arcsinh(s / c + math.sinh(-x0 / c))
    zs = c * (np.cosh((xs - x0) / c) - math.cosh(x0 / c))
    return in_world(xs, zs)


@dataclass(frozen=True)
class CableStepLimit:
    """The SPH cable's stable step and what set it.

    ``limiter`` is ``"courant"``, ``"viscosity"``, ``"mass_damping"``, ``"drag"`` (the
    damped highest axial mode, named after its largest damping rate) or
    ``"density_diffusion"``; ``limits`` [s] holds ``courant`` (with ``cfl``), the damped
    mode's bound ``damped_mode`` and ``density_diffusion`` (before ``safety``), and each
    damping rate's own ``2 / rate``."""

    dt: float  # [s]
    limiter: str
    limits: dict  # name -> [s]


@dataclass
class _Load:
    s: float
    force: np.ndarray  # [N]
    mass: float  # [kg]
    t_on: float = -math.inf  # [s]
    t_off: float = math.inf  # [s]

    def active(self, t: float) -> bool:
        return self.t_on <= t + 1e-12 < self.t_off


#: the largest strain an SPH cable takes elastically by default (``SPHCable``'s ``max_strain``) [-]
MAX_STRAIN = 0.1


class SPHCable:
    """One cable of SPH particles between two ends (Dinçer & Demir 2020, Eq. 1-12).

    Parameters
    ----------
    length : unstretched length [m].
    n_particles : number of SPH particles (nodes), ends included; at least 3.
    EA : axial stiffness E·A [N] (tension only).
    mass_per_length : mass per unit length [kg/m] (in air; add added mass yourself).
    end_a, end_b : positions [m] of the two ends, 2 values (x, z) or 3 (x, y, z).
    weight_per_length : weight per unit length [N/m] acting in -z (submerged weight for a
        line in water); default ``mass_per_length * gravity``.
    free_end : None (both ends held), ``"a"``, ``"b"`` (that end hangs free) or ``"both"``.
    positions : optional initial positions (n_particles, dim) [m]; default the
        inextensible catenary through the ends (a straight line if taut). The initial
        line density follows the initial segment stretch, so a stretched start is stressed.
    nodes_at : material coordinates [m] that must be nodes (point loads, probes).
    cfl : Courant number on the axial wave speed sqrt(EA/mass_per_length) [-]; the step
        also obeys the damping and diffusion bounds of :meth:`step_limit` (module docstring).
    safety : factor [-] on the damping and diffusion bounds of :meth:`step_limit` (0.8).
    omega : mass-proportional damping rate of Dinçer & Demir 2020, Eq. 12 [1/s].
    visc_alpha, visc_beta : artificial viscosity coefficients varphi, phi of Dinçer & Demir 2020, Eq. 10 [-].
    delta : δ-SPH diffusion coefficient of Dinçer & Demir 2020, Eq. 1 [-] (0.1 in the paper; 0 by default: in a solid it is creep).
    max_strain : largest strain the cable takes elastically [-]; supports farther apart
        than ``length * (1 + max_strain)`` are rejected.
    seabed_z : height [m] of a horizontal seabed the particles cannot penetrate (the
        position is projected onto it and a downward velocity removed; no friction); None.
    seabed_friction : Coulomb friction coefficient [-] between the seabed and the line (0:
        frictionless); regularised below 1 mm/s, so a line at rest on a slope creeps slowly.
    diameter : hydrodynamic diameter [m] for Morison drag and added mass in still water;
        None: no hydrodynamic loads. Per particle of unstretched length l (half of each
        adjacent segment): normal drag ``-1/2 rho cd_normal d l |v_n| v_n``, tangential
        ``-1/2 rho cd_tangential pi d l |v_t| v_t``, added mass ``ca_normal rho pi d^2/4 l``
        across and ``ca_tangential rho pi d^2/4 l`` along the tangent (as in MoorDyn).
    rho_water : water density [kg/m^3].
    cd_normal, cd_tangential, ca_normal, ca_tangential : Morison coefficients [-].
    water_z : height [m] of the still water surface; particles above it get no
        hydrodynamic load (default: all submerged).
    gravity : gravitational acceleration [m/s²], used for point masses and the default weight.
    name : label used in messages.
    """

    def __init__(self, length, n_particles, EA, mass_per_length, end_a, end_b, weight_per_length=None,
                 free_end=None, positions=None, nodes_at=(), cfl=0.4, omega=0.04,
                 visc_alpha=1.0, visc_beta=0.2, delta=0.0, max_strain=MAX_STRAIN, seabed_z=None,
                 seabed_friction=0.0, diameter=None, rho_water=1025.0, cd_normal=1.2, cd_tangential=0.008, ca_normal=1.0,
                 ca_tangential=0.0, water_z=math.inf, gravity=G_STANDARD, name="cable", safety=0.8):
        self.name = name
        lab = f"SPH cable '{name}'"

        def pos(val, what, unit):
            try:
                v = float(val)
            except (TypeError, ValueError):
                raise InputError(f"{lab}: {what} must be a number [{unit}], got {val!r}") from None
            if not (math.isfinite(v) and v > 0):
                raise InputError(f"{lab}: {what} = {val!r} {unit}; it must be finite and > 0")
            return v

        if isinstance(n_particles, bool) or not isinstance(n_particles, (int, np.integer)):
            raise InputError(f"{lab}: n_particles must be an integer, got {n_particles!r}")
        if n_particles < 3:
            raise InputError(f"{lab}: n_particles = {n_particles}; a cable needs at least 3 particles")
        self.length = pos(length, "length", "m")
        self.EA = pos(EA, "EA", "N")
        self.mass_per_length = pos(mass_per_length, "mass_per_length", "kg/m")
        self.gravity = pos(gravity, "gravity", "m/s^2")
        self.max_strain = pos(max_strain, "max_strain", "-")
        self.cfl = pos(cfl, "cfl", "-")
        if self.cfl > 1.0:
            raise InputError(f"{lab}: cfl = {cfl}; use a Courant number <= 1 (0.4 is the default)")
        self.safety = pos(safety, "safety", "-")
        if self.safety > 1.0:
            raise InputError(f"{lab}: safety = {safety}; use a factor <= 1 on the stability bounds (0.8 is the "
                             "default)")
        if omega is None or not math.isfinite(float(omega)) or float(omega) < 0:
            raise InputError(f"{lab}: omega = {omega!r} 1/s; the damping rate must be >= 0")
        self.omega = float(omega)
        self.visc_alpha, self.visc_beta, self.delta = float(visc_alpha), float(visc_beta), float(delta)
        if min(self.visc_alpha, self.visc_beta, self.delta) < 0:
            raise InputError(f"{lab}: visc_alpha, visc_beta and delta must be >= 0")
        if weight_per_length is None:
            weight_per_length = self.mass_per_length * self.gravity
        w = float(weight_per_length)
        if not math.isfinite(w):
            raise InputError(f"{lab}: weight_per_length = {weight_per_length!r} N/m must be finite")
        self.weight_per_length = w
        if free_end not in (None, "a", "b", "both"):
            raise InputError(f"{lab}: free_end = {free_end!r}; use None, 'a', 'b' or 'both'")
        self.free_end = free_end
        ea = np.asarray(end_a, float).ravel()
        eb = np.asarray(end_b, float).ravel()
        if ea.size not in (2, 3) or eb.size != ea.size or not (np.all(np.isfinite(ea)) and np.all(np.isfinite(eb))):
            raise InputError(f"{lab}: end_a and end_b must be finite points of equal dimension 2 or 3 [m]")
        self.dim = ea.size
        reach = self.length * (1.0 + self.max_strain)
        span = float(np.linalg.norm(eb - ea))
        if free_end is None and span > reach:
            raise InputError(
                f"{lab}: the supports are {span:.6g} m apart but the cable of length {self.length:.6g} m reaches "
                f"only {reach:.6g} m within max_strain = {self.max_strain:g}; move the supports closer or "
                "lengthen the cable")
        for sv in nodes_at:
            if not 0.0 < float(sv) < self.length:
                raise InputError(f"{lab}: nodes_at value {sv!r} m is not inside the cable (0, {self.length:g})")
        self.s = material_coordinates(self.length, int(n_particles), nodes_at)
        n = self.n = self.s.size
        ds = np.diff(self.s)
        self.ds = np.ascontiguousarray(ds)
        # renormalised (Dinçer & Demir 2020, Eq. 4) neighbour weights: the half-segment shares, mirrored ends
        self._wl = np.zeros(n)
        self._wr = np.zeros(n)
        self._wl[1:-1] = ds[:-1] / (ds[:-1] + ds[1:])
        self._wr[1:-1] = ds[1:] / (ds[:-1] + ds[1:])
        self._wr[0] = 1.0
        self._wl[-1] = 1.0
        self.c0 = math.sqrt(self.EA / self.mass_per_length)
        # masses: inertial (half segments at the ends), kernel (mirrored: full at the ends)
        half = node_shares(ds)
        self._seg_len = half
        kern = half.copy()
        kern[0], kern[-1] = ds[0], ds[-1]
        self.mk = self.mass_per_length * kern
        self._m_line = self.mass_per_length * half
        self.lam0 = np.full(n, self.mass_per_length)
        self.hyd = np.zeros((n, 4))
        if diameter is not None:
            d = pos(diameter, "diameter", "m")
            rw = pos(rho_water, "rho_water", "kg/m^3")
            for j, (cname, cval) in enumerate((("cd_normal", cd_normal), ("cd_tangential", cd_tangential),
                                               ("ca_normal", ca_normal), ("ca_tangential", ca_tangential))):
                cval = float(cval)
                if not (math.isfinite(cval) and cval >= 0):
                    raise InputError(f"{lab}: {cname} = {cval!r}; Morison coefficients must be >= 0")
                fac = (0.5 * rw * d, 0.5 * rw * math.pi * d, rw * math.pi * d * d / 4, rw * math.pi * d * d / 4)[j]
                self.hyd[:, j] = fac * cval * half
        self.water_z = float(water_z)
        if positions is None:
            x = catenary_points(ea, eb, self.length, self.s)
        else:
            x = np.array(positions, float)
            if x.shape != (n, self.dim) or not np.all(np.isfinite(x)):
                raise InputError(f"{lab}: positions must be a finite array of shape ({n}, {self.dim}) [m]")
        self.seabed_z = -math.inf if seabed_z is None else float(seabed_z)
        mu_f = float(seabed_friction)
        if not (math.isfinite(mu_f) and mu_f >= 0):
            raise InputError(f"{lab}: seabed_friction = {seabed_friction!r}; the friction coefficient must be >= 0")
        #: seabed height [m], Coulomb coefficient [-], regularisation speed [m/s]
        self._bed = np.array([self.seabed_z, mu_f, 1e-3])
        if seabed_z is not None:
            x[:, -1] = np.maximum(x[:, -1], self.seabed_z)
        self.x = np.ascontiguousarray(x)
        self.v = np.zeros_like(self.x)
        seg = np.linalg.norm(np.diff(self.x, axis=0), axis=1)
        stretch = seg / ds
        st = np.empty(n)
        st[1:-1] = 0.5 * (stretch[:-1] + stretch[1:])
        st[0], st[-1] = stretch[0], stretch[-1]
        self.lam = self.lam0 / st
        self.t = 0.0
        held = [i for i, e in ((0, "a"), (n - 1, "b")) if free_end not in (e, "both")]
        self._pidx = np.array(held, dtype=np.int64)
        npr = len(held)
        self._free = np.ones(n)
        self._free[self._pidx] = 0.0
        self._p0 = self.x[self._pidx].copy()
        self._v0 = np.zeros((npr, self.dim))
        self._p1 = self._p0.copy()
        self._v1 = np.zeros((npr, self.dim))
        self._amp = np.zeros((npr, self.dim))
        self._om = np.zeros(npr)
        self._ton = np.zeros(npr)
        self._toff = np.full(npr, -1.0)
        self._fend_mean = np.zeros((npr, self.dim))
        self._fend_last = np.zeros((npr, self.dim))
        self._tension = np.zeros(n)
        self._loads: dict[int, _Load] = {}
        self._tables: dict[int, tuple] = {}
        self._warned_strain = False
        self._next_handle = 0
        self._rebuild_external()
        self.steps = 0
        self._state_end_forces()

    def _state_end_forces(self) -> None:
        """End forces and tensions of the present state (before the first advance: a line
        that starts hanging pulls its supports from the start)."""
        _k.state_end_forces(self.x, self.v, self.lam, self.ds, self.m, self.mk, self.lam0, self.EA, self.c0,
                            self.delta, self.visc_alpha, self.visc_beta, self.omega, self.fext, self._wl, self._wr,
                            self.hyd, self.water_z, self._bed, self._pidx, self._fend_last, self._tension)
        self._fend_mean[:] = self._fend_last

    # ------------------------------------------------------------------ set-up
    def _end_slot(self, end):
        idx = {"a": 0, "b": self.n - 1}.get(end)
        if idx is None or idx not in self._pidx:
            raise InputError(f"SPH cable '{self.name}': end {end!r} is not a held end (held: "
                             f"{[('a' if i == 0 else 'b') for i in self._pidx]})")
        return int(np.nonzero(self._pidx == idx)[0][0])

    def _split(self, s):
        s = float(s)
        if not 0.0 <= s <= self.length:
            raise InputError(f"SPH cable '{self.name}': position s = {s} m is not on the cable [0, {self.length:g}]")
        i = int(np.clip(np.searchsorted(self.s, s, side="right") - 1, 0, self.n - 2))
        f = (s - self.s[i]) / (self.s[i + 1] - self.s[i])
        return i, f

    def _rebuild_external(self, t=None):
        """External forces and inertial masses with the point loads/masses active at ``t``
        [s] (default: the cable's time)."""
        t = self.t if t is None else t
        n, dim = self.n, self.dim
        fext = np.zeros((n, dim))
        fext[:, -1] = -self.weight_per_length * self._seg_len
        m = self._m_line.copy()
        for ld in self._loads.values():
            if not ld.active(t):
                continue
            i, f = self._split(ld.s)
            for j, wj in ((i, 1.0 - f), (i + 1, f)):
                fext[j] += wj * ld.force
                fext[j, -1] -= wj * ld.mass * self.gravity
                m[j] += wj * ld.mass
        self.fext, self.m = fext, m

    def add_point_load(self, s, force, t_on=None, t_off=None) -> int:
        """Apply a constant force [N] (dim values, world frame) at material coordinate ``s`` [m],
        from ``t_on`` to ``t_off`` [s] (None: from the next :meth:`advance` on / for ever;
        :meth:`advance` splits its interval at these times); returns a handle for
        :meth:`remove`."""
        f = np.asarray(force, float).ravel()
        if f.size != self.dim or not np.all(np.isfinite(f)):
            raise InputError(f"SPH cable '{self.name}': force must be {self.dim} finite values [N]")
        self._split(s)
        return self._add(_Load(float(s), f, 0.0, *self._window(t_on, t_off)))

    def add_point_mass(self, s, mass, t_on=None, t_off=None) -> int:
        """Attach a point mass [kg] (its inertia and its weight mass·gravity) at ``s`` [m],
        from ``t_on`` to ``t_off`` [s] as for :meth:`add_point_load` (Dinçer & Demir 2020, Case 2
        removes one at a given time)."""
        mass = float(mass)
        if not (math.isfinite(mass) and mass > 0):
            raise InputError(f"SPH cable '{self.name}': point mass = {mass!r} kg must be > 0")
        self._split(s)
        return self._add(_Load(float(s), np.zeros(self.dim), mass, *self._window(t_on, t_off)))

    def _window(self, t_on, t_off):
        a = -math.inf if t_on is None else float(t_on)
        b = math.inf if t_off is None else float(t_off)
        if math.isnan(a) or math.isnan(b) or not a < b:
            raise InputError(f"SPH cable '{self.name}': t_on = {t_on!r} s must come before t_off = {t_off!r} s")
        return a, b

    def _add(self, ld):
        h = self._next_handle
        self._next_handle += 1
        self._loads[h] = ld
        self._rebuild_external()
        return h

    def remove(self, handle: int) -> None:
        """Remove a point load or mass added earlier (it acts no more from the next advance)."""
        if handle not in self._loads:
            raise InputError(f"SPH cable '{self.name}': no point load or mass with handle {handle!r}")
        del self._loads[handle]
        self._rebuild_external()

    def set_end_motion(self, end, position, velocity=None) -> None:
        """Where held end ``end`` ("a"/"b") is at the end of the next :meth:`advance`: position [m]
        and velocity [m/s]; in between it follows a cubic Hermite curve from its current state."""
        i = self._end_slot(end)
        p = np.asarray(position, float).ravel()
        vv = np.zeros(self.dim) if velocity is None else np.asarray(velocity, float).ravel()
        if p.size != self.dim or vv.size != self.dim or not (np.all(np.isfinite(p)) and np.all(np.isfinite(vv))):
            raise InputError(f"SPH cable '{self.name}': end position/velocity must be {self.dim} finite values")
        self._p1[i], self._v1[i] = p, vv

    def set_harmonic(self, end, amplitude, frequency, t_on=0.0, cycles=None) -> None:
        """Superpose amplitude·sin(2π frequency (t - t_on)) on held end ``end``: ``amplitude``
        [m] (dim values), ``frequency`` [Hz], start ``t_on`` [s], for ``cycles`` whole cycles
        (None: forever)."""
        i = self._end_slot(end)
        amp = np.asarray(amplitude, float).ravel()
        fr = float(frequency)
        if amp.size != self.dim or not np.all(np.isfinite(amp)) or not (math.isfinite(fr) and fr > 0):
            raise InputError(f"SPH cable '{self.name}': amplitude needs {self.dim} values [m], frequency > 0 [Hz]")
        self._amp[i] = amp
        self._om[i] = 2 * math.pi * fr
        self._ton[i] = float(t_on)
        self._toff[i] = math.inf if cycles is None else float(t_on) + float(cycles) / fr

    # ------------------------------------------------------------------ stepping
    def step_limit(self) -> CableStepLimit:
        """The cable's stable step now and what sets it (module docstring; docs/sph_cable.md, "Time stepping"):
        ``min(courant, safety * damped highest mode, safety * density diffusion)``."""
        seg = np.linalg.norm(np.diff(self.x, axis=0), axis=1)
        ds = float(self.ds.min())
        # fastest particle, plus what the held ends may reach within the interval
        vmax = float(np.sqrt((self.v ** 2).sum(axis=1)).max()) + float(
            np.max(np.linalg.norm(self._amp, axis=1) * self._om, initial=0.0))
        vmax = max(vmax, float(np.max(np.linalg.norm(self._v1, axis=1), initial=0.0)))
        courant = self.cfl * float(min(seg.min(), ds)) / (self.c0 + vmax)
        w_hm = 2.0 * self.c0 / ds  # highest axial mode [1/s]
        rates = {"viscosity": 15.0 / 8.0 * self.visc_alpha * self.c0 / ds,  # [1/s]
                 "mass_damping": self.omega,
                 "drag": 2.0 * vmax * float(np.max(np.maximum(self.hyd[:, 0] / (self.m + self.hyd[:, 2]),
                                                              self.hyd[:, 1] / (self.m + self.hyd[:, 3]))))}
        zeta = sum(rates.values()) / (2.0 * w_hm)
        damped = 2.0 / w_hm * (math.sqrt(zeta * zeta + 1.0) - zeta)
        diffusion = ds / (2.0 * self.delta * self.c0) if self.delta > 0 else math.inf
        limits = {"courant": courant, "damped_mode": damped, "density_diffusion": diffusion,
                  **{k: (2.0 / r if r > 0 else math.inf) for k, r in rates.items()}}
        cands = {"courant": courant, "damped_mode": self.safety * damped, "density_diffusion": self.safety * diffusion}
        which = min(cands, key=cands.get)
        name = which
        if which == "damped_mode":
            name = max(rates, key=rates.get) if max(rates.values()) > 0 else "courant"
        return CableStepLimit(cands[which], name, limits)

    @property
    def dt_limit(self) -> CableStepLimit:
        """:meth:`step_limit` now (``limiter`` names the term, as the fluid's ``limiter``)."""
        return self.step_limit()

    def stable_dt(self) -> float:
        """The cable's own stable step [s] now (:meth:`step_limit`)."""
        return self.step_limit().dt

    def set_end_table(self, end, times, positions) -> None:
        """Make held end ``end`` follow a table of ``times`` [s] (increasing) and ``positions``
        [m] (len(times), dim): piecewise cubic Hermite through the samples with velocities
        from finite differences; before the first / after the last sample the end rests
        there. :meth:`advance` splits its interval at the samples. ``None`` removes it."""
        i = self._end_slot(end)
        if times is None:
            self._tables.pop(i, None)
            return
        tt = np.asarray(times, float).ravel()
        pp = np.asarray(positions, float)
        if (tt.size < 2 or pp.shape != (tt.size, self.dim) or not np.all(np.isfinite(tt))
                or not np.all(np.isfinite(pp)) or not np.all(np.diff(tt) > 0)):
            raise InputError(f"SPH cable '{self.name}': an end table needs >= 2 increasing finite times [s] and "
                             f"positions of shape (len(times), {self.dim}) [m]")
        self._tables[i] = (tt, pp, np.gradient(pp, tt, axis=0))

    def _table_state(self, i, t):
        tt, pp, vv = self._tables[i]
        if t <= tt[0]:
            return pp[0].copy(), np.zeros(self.dim)
        if t >= tt[-1]:
            return pp[-1].copy(), np.zeros(self.dim)
        return (np.array([np.interp(t, tt, pp[:, d]) for d in range(self.dim)]),
                np.array([np.interp(t, tt, vv[:, d]) for d in range(self.dim)]))

    def advance(self, t: float, dt: float) -> int:
        """Advance from ``t`` to ``t + dt`` [s] in compiled sub-steps; returns their number."""
        if not dt > 0:
            raise InputError(f"SPH cable '{self.name}': dt = {dt!r} s must be > 0")
        t1 = t + dt
        timed = [ld for ld in self._loads.values() if math.isfinite(ld.t_on) or math.isfinite(ld.t_off)]
        if timed:
            self._rebuild_external(t)
        if not self._tables and not timed:
            return self._advance_span(t, dt)
        cuts = {float(x) for tab in self._tables.values() for x in tab[0]}
        cuts |= {x for ld in timed for x in (ld.t_on, ld.t_off)}
        knots = [t, *sorted(x for x in cuts if t + 1e-12 < x < t1 - 1e-12), t1]
        if len(knots) == 2 and not self._tables:
            return self._advance_span(t, dt)
        # the other held ends keep their Hermite curve over the whole interval
        npr = self._pidx.size
        P0, V0, P1, V1 = self._p0.copy(), self._v0.copy(), self._p1.copy(), self._v1.copy()
        zero = np.zeros((npr, self.dim))
        pos, vel, acc = np.empty((npr, self.dim)), np.empty((npr, self.dim)), np.empty((npr, self.dim))
        n_tot = 0
        fmean = np.zeros_like(self._fend_mean)
        for ta, tb in zip(knots[:-1], knots[1:]):
            _k.prescribed_state(tb, t, t1, P0, V0, P1, V1, zero, np.zeros(npr), np.zeros(npr), np.full(npr, -1.0),
                                pos, vel, acc)
            self._p1[:], self._v1[:] = pos, vel
            for i in self._tables:
                self._p1[i], self._v1[i] = self._table_state(i, tb)
            if timed:
                self._rebuild_external(ta)
            n_tot += self._advance_span(ta, tb - ta)
            fmean += self._fend_mean * (tb - ta) / dt
        self._fend_mean[:] = fmean
        self.t = float(t1)
        return n_tot

    def _advance_span(self, t: float, dt: float) -> int:
        sdt = self.stable_dt()
        if not (math.isfinite(sdt) and sdt > 0 and dt / sdt < 1e9):
            a = int(np.argmax(np.nan_to_num(np.linalg.norm(self.v, axis=1), nan=np.inf)))
            raise InstabilityError(
                f"SPH cable '{self.name}': runaway state at t = {t:.9g} s: particle {a} (s = {self.s[a]:.6g} m) "
                f"moves at {np.linalg.norm(self.v[a]):.3g} m/s (stable step {sdt:.3g} s); lower cfl (now "
                f"{self.cfl}) or safety (now {self.safety}), or check the loads and the end motion")
        n_sub = max(1, int(math.ceil(dt / sdt - 1e-9)))
        log.debug("SPH cable '%s': t = %.9g s, dt = %.3g s in %d sub-steps of %.3g s", self.name, t, dt, n_sub,
                  dt / n_sub)
        status, step, part = _k.advance(
            self.x, self.v, self.lam, self.ds, float(t), float(t + dt), n_sub, self.m, self.mk, self.lam0, self.EA,
            self.c0, self.delta, self.visc_alpha, self.visc_beta, self.omega, self.fext, self._wl, self._wr,
            self.hyd, self.water_z, self._free, self._pidx, self._p0, self._v0, self._p1, self._v1, self._amp, self._om, self._ton,
            self._toff, self._bed, self._fend_mean, self._fend_last, self._tension)
        if status != _k.OK:
            what = "non-finite position or velocity" if status == _k.NONFINITE else "non-positive density"
            raise InstabilityError(
                f"SPH cable '{self.name}': {what} at particle {part} (s = {self.s[part]:.6g} m) in sub-step "
                f"{step} of {n_sub} after t = {t:.9g} s (dt = {dt / n_sub:.3g} s); lower cfl (now {self.cfl}) or "
                f"safety (now {self.safety}), or check the loads and the end motion")
        self._p0[:] = self._p1
        self._v0[:] = self._v1
        self.t = float(t + dt)
        self.steps += n_sub
        if not self._warned_strain:
            eps = np.linalg.norm(np.diff(self.x, axis=0), axis=1) / self.ds - 1.0
            k = int(np.argmax(eps))
            if eps[k] > self.max_strain:
                self._warned_strain = True
                log.warning("SPH cable '%s': segment %d (s = %.6g-%.6g m) is stretched %.3g at t = %.9g s, beyond "
                            "max_strain = %g; the linear elastic law is extrapolated (warned once)", self.name, k,
                            self.s[k], self.s[k + 1], eps[k], self.t, self.max_strain)
        return n_sub

    # ------------------------------------------------------------------ outputs
    @property
    def positions(self) -> np.ndarray:
        """Particle positions [m], (n, dim)."""
        return self.x.copy()

    @property
    def velocities(self) -> np.ndarray:
        return self.v.copy()

    @property
    def tension(self) -> np.ndarray:
        """Axial tension [N] of each particle at the end of the last advance."""
        return self._tension.copy()

    def end_forces(self, mean=False) -> np.ndarray:
        """Force [N] the cable exerts on each held end's support, (n_held, dim), ends in order
        a, b; at the end of the last advance, or its mean over the sub-steps (``mean=True``)."""
        return (self._fend_mean if mean else self._fend_last).copy()

    def position_at(self, s) -> np.ndarray:
        """Position [m] of material point ``s`` [m] (linear between nodes)."""
        i, f = self._split(s)
        return (1 - f) * self.x[i] + f * self.x[i + 1]

    def kinetic_energy(self) -> float:
        return 0.5 * float((self.m * (self.v ** 2).sum(axis=1)).sum())

    def mechanical_energy(self) -> float:
        """Kinetic + potential of the constant loads (weight, point loads: ``-sum f . x``) +
        elastic (``EA ds eps^2 / 2`` over the stretched segments) [J]: conserved but for the
        damping, the artificial viscosity and a moving support's work."""
        ell = np.linalg.norm(np.diff(self.x, axis=0), axis=1)
        eps = np.maximum(ell / self.ds - 1.0, 0.0)
        elastic = float((0.5 * self.EA * self.ds * eps**2).sum())
        return self.kinetic_energy() - float((self.fext * self.x).sum()) + elastic

    def max_speed(self) -> float:
        return float(np.sqrt((self.v ** 2).sum(axis=1)).max())

    def save_state(self):
        return (self.x.copy(), self.v.copy(), self.lam.copy(), self.t, self._p0.copy(), self._v0.copy(),
                self._p1.copy(), self._v1.copy(), dict(self._loads), self._tension.copy(),
                self._fend_last.copy(), self._fend_mean.copy(), self.steps)

    def load_state(self, state) -> None:
        (x, v, lam, self.t, p0, v0, p1, v1, loads, ten, fl, fm, self.steps) = state
        self.x[:], self.v[:], self.lam[:] = x, v, lam
        self._p0[:], self._v0[:], self._p1[:], self._v1[:] = p0, v0, p1, v1
        self._loads = dict(loads)
        self._tension[:], self._fend_last[:], self._fend_mean[:] = ten, fl, fm
        self._rebuild_external()


class SPHCableMooring:
    """Mooring lines as SPH cables, behind the ``cosim.protocol.Mooring`` interface.

    Each :class:`~moorings.line.MooringLine` becomes an :class:`SPHCable` from its anchor
    (fixed; the seabed is the horizontal plane through it) to the fairlead given by
    :meth:`set_fairlead_motion` (prescribed; between two coupling times it follows a cubic
    Hermite curve through the given positions and velocities). Weight per length is the
    line's submerged ``weight``, inertia its ``mass_per_length``, stiffness its ``EA``;
    a line with a ``diameter`` gets Morison drag and added mass (still water).
    With ``seabed`` a line starts at the static equilibrium of its own discrete chain
    (moorings.chain_equilibrium, from the elastic catenary with seabed contact), so it
    starts at rest; without, on the inextensible catenary through anchor and fairlead.

    Parameters
    ----------
    lines : the mooring lines (all 2-D or all 3-D).
    fairleads : optional initial fairlead positions [m], ``(n_lines, dim)``.
    n_particles : SPH particles per line (ends included).
    seabed : keep particles above the seabed plane through each anchor (no penetration).
    point_loads : per line, ``(s, force)`` pairs: constant forces [N] (world frame) at material
        points ``s`` [m] from the anchor (:meth:`SPHCable.add_point_load`), from the start.
    nodes_at : per line, material points [m] from the anchor that must be nodes (point loads,
        recorded points: :meth:`points_at` reads them there, not between two nodes).
    released : per line, whether its fairlead end is free from the start (it starts hanging
        between anchor and fairlead: a line parted at the fairlead, Dinçer & Demir 2020's
        Experiment 1); it then pulls on nothing.
    name : participant name used in messages.
    **cable_options : passed to :class:`SPHCable` (``omega`` [1/s], ``cfl``, Morison
        coefficients, ``water_z`` [m], ...).
    """

    def __init__(self, lines: list[MooringLine], fairleads=None, n_particles: int = 40, seabed: bool = True,
                 point_loads=None, nodes_at=None, released=None, name="sph_cable", **cable_options):
        self.lines = named_lines(lines)
        self.name = name
        self.n_lines = len(self.lines)
        self.dim = self.lines[0].dim
        for ln in self.lines:
            if ln.mass_per_length is None:
                raise InputError(f"{name}, line '{ln.name}': the SPH cable needs mass_per_length [kg/m]")
            if ln.inextensible:
                raise InputError(f"{name}, line '{ln.name}': the SPH cable needs a finite EA [N] (axial stiffness)")
        self.anchors = np.array([ln.anchor for ln in self.lines], dtype=float)
        self.n_particles = n_particles
        self.seabed = seabed
        self._opts = cable_options
        for what, given in (("point_loads", point_loads), ("nodes_at", nodes_at), ("released", released)):
            if given is not None and len(given) != len(self.lines):
                raise InputError(f"{name}: {what} has {len(given)} entries for {len(self.lines)} lines; give one "
                                 "(possibly empty) list per line")
        self._point_loads = [list(x) for x in point_loads] if point_loads is not None else [[] for _ in self.lines]
        self._nodes_at = [tuple(x) for x in nodes_at] if nodes_at is not None else [() for _ in self.lines]
        self.released = np.array([bool(x) for x in released] if released is not None else [False] * len(self.lines))
        self.cables: list[SPHCable] = []
        self._fpos = None
        self._fvel = None
        self.t = 0.0
        #: when each line became fully lifted or taut (:mod:`moorings.line_events`), after every step
        self.state_log = LineStateLog([ln.name for ln in self.lines])
        if fairleads is not None:
            self.set_fairlead_motion(fairleads)

    def set_fairlead_motion(self, positions, velocities=None) -> None:
        """Fairlead positions [m] and velocities [m/s], ``(n_lines, dim)``, reached at the end
        of the next :meth:`advance`."""
        try:
            p = np.asarray(positions, float)
            vv = np.zeros_like(p) if velocities is None else np.asarray(velocities, float)
        except (TypeError, ValueError):
            raise InputError(f"{self.name}: fairlead positions/velocities must be numbers") from None
        if p.shape != (self.n_lines, self.dim) or not np.all(np.isfinite(p)):
            raise InputError(f"{self.name}: fairlead positions must be finite, shape ({self.n_lines}, {self.dim}) [m]")
        if vv.shape != p.shape or not np.all(np.isfinite(vv)):
            raise InputError(f"{self.name}: fairlead velocities must be finite, shape {p.shape} [m/s]")
        if self.seabed and (p[:, -1] < self.anchors[:, -1]).any():
            i = int(np.argmax(p[:, -1] < self.anchors[:, -1]))
            raise InputError(f"{self.name}, line '{self.lines[i].name}': fairlead at z = {p[i, -1]:.6g} m is below "
                             f"the seabed through its anchor (z = {self.anchors[i, -1]:.6g} m)")
        self._fpos, self._fvel = p.copy(), vv.copy()
        for c, pi, vi, free in zip(self.cables, p, vv, self.released):
            if not free:
                c.set_end_motion("b", pi, vi)

    def initialize(self, t0: float) -> None:
        """Build the cables (checks every line before any work)."""
        if self._fpos is None:
            raise InputError(f"{self.name}: fairlead positions are not set; call set_fairlead_motion() "
                             "or pass fairleads= before the run")
        cables = []
        for ln, fp, loads, nodes, free in zip(self.lines, self._fpos, self._point_loads, self._nodes_at, self.released):
            opts = dict(self._opts)
            if free:
                opts["free_end"] = "b"
            if nodes:
                opts["nodes_at"] = tuple(sorted(set(opts.get("nodes_at", ())) | set(nodes)))
            if ln.diameter is not None:
                opts.setdefault("diameter", ln.diameter)
            if self.seabed and "positions" not in opts:
                opts["positions"] = self._quasi_static_shape(ln, fp, opts.get("nodes_at", ()))
            c = SPHCable(ln.length, self.n_particles, ln.EA, ln.mass_per_length, ln.anchor, fp,
                         weight_per_length=ln.weight, seabed_z=ln.anchor[-1] if self.seabed else None,
                         name=ln.name, **opts)
            for s_load, force in loads:
                c.add_point_load(s_load, force)
            c.t = float(t0)
            cables.append(c)
        self.cables = cables
        self.t = float(t0)
        self.set_fairlead_motion(self._fpos, self._fvel)
        if self.state_log.state is None:  # a resumed run keeps its log
            self.state_log.update(self.t, self.line_states())

    def _quasi_static_shape(self, ln: MooringLine, fairlead, nodes_at=()) -> np.ndarray:
        """Particle positions [m] at the static equilibrium of the line's own discrete chain
        (:func:`moorings.chain_equilibrium.discrete_equilibrium`: its chords stretched by the
        tension they carry, its nodes' weights, the seabed through the anchor), in the
        vertical plane through anchor and fairlead, started from the elastic catenary with
        seabed (moorings.catenary): the line starts at rest instead of settling into it.
        A resting line (H = 0: it hangs straight and lies slack on the bed) and one whose
        chain equilibrium is not found (logged) start on the continuous law's curve."""
        from moorings.catenary import LineState, shape, solve
        from moorings.chain_equilibrium import discrete_equilibrium

        X, Z, in_world = vertical_plane(ln.anchor, fairlead)
        ds = np.diff(material_coordinates(ln.length, self.n_particles, nodes_at))
        law = solve(X, Z, ln.length, ln.weight, ln.EA)
        # a resting line (H = 0) hangs straight: no curved chords to correct
        found = None if law.state == LineState.RESTING else discrete_equilibrium(
            ln.anchor, fairlead, ds, ln.weight * node_shares(ds), ln.EA, (law.H, law.V))
        if found is not None:
            return found[0]
        if law.state != LineState.RESTING:
            log.warning("%s, line '%s': the discrete chain's equilibrium was not found; the nodes start on the "
                        "continuous catenary (the line settles in its first steps)", self.name, ln.name)
        _, xs, zs = shape(X, Z, ln.length, ln.weight, ln.EA, n=self.n_particles)
        pos = in_world(xs, zs)
        pos[-1] = fairlead  # exactly on the fairlead (round-off of the closed form)
        return pos

    def points_at(self, line: int, s) -> np.ndarray:
        """Positions [m] of line ``line``'s material points ``s`` [m] from its anchor, (k, dim)
        (:meth:`SPHCable.position_at`: linear between nodes; exact at ``nodes_at``)."""
        c = self.cables[line]
        return np.array([c.position_at(x) for x in s], float).reshape(-1, self.dim)

    def max_dt(self) -> float:
        """No limit: each cable sub-cycles to the coupling time (see :meth:`stable_dt`)."""
        return math.inf

    def stable_dt(self) -> float:
        """The smallest stable sub-step [s] of the lines now."""
        return min(c.stable_dt() for c in self.cables)

    def advance(self, t: float, dt: float) -> None:
        for c in self.cables:
            c.advance(t, dt)
        self.t = float(t + dt)
        self.state_log.update(self.t, self.line_states())

    def _seabed_tol(self, c) -> float:
        """Nodes this close to the seabed [m] lie on it: the contact is a projection (a node
        on the bed sits exactly at its height), so a thousandth of the node spacing."""
        return 1e-3 * float(c.ds.min())

    def line_states(self) -> np.ndarray:
        """Each line's :class:`~moorings.catenary.LineState` now, from its particles
        (:func:`moorings.line_events.node_states`: taut where the anchor-fairlead distance is
        at least the unstretched length, lifted where no particle but the anchor's lies on
        the seabed). Without ``seabed`` no particle is ever on it."""
        if not self.cables:
            raise InputError(f"{self.name}: not initialised; call initialize() first")
        bed = [ln.anchor[-1] if self.seabed else -math.inf for ln in self.lines]
        return node_states(self.anchors, [c.x[-1] for c in self.cables], [ln.length for ln in self.lines],
                           [c.x for c in self.cables], bed, [self._seabed_tol(c) for c in self.cables])

    def fairlead_stiffness(self) -> FairleadStiffness:
        """Each line's spring and dashpot at its fairlead over a coupling step
        (:func:`moorings.fairlead_stiffness.axial`): ``EA`` over the suspended length along
        the last segment, and the axial impedance ``sqrt(EA m)`` plus the artificial
        viscosity's dashpot on that segment, ``(15/32) visc_alpha`` times it (module
        docstring, "Time stepping")."""
        if not self.cables:
            raise InputError(f"{self.name}: not initialised; call initialize() first")
        k, c = zip(*(axial(cb.x, cb.s, ln.EA, ln.mass_per_length, ln.anchor[-1] if self.seabed else -math.inf,
                           self._seabed_tol(cb), 15.0 / 32.0 * cb.visc_alpha)
                     for cb, ln in zip(self.cables, self.lines)))
        k, c = np.array(k), np.array(c)
        k[self.released], c[self.released] = 0.0, 0.0  # a released line holds nothing
        return FairleadStiffness(k, c)

    #: a dynamic line: its force over a step is an integral (the coupler advances it with the bodies)
    dynamic = True

    def fairlead_forces(self) -> np.ndarray:
        """Force [N] each line exerts on its fairlead, ``(n_lines, dim)``, world frame."""
        return self._fairlead_end_forces(mean=False)

    def mean_fairlead_forces(self) -> np.ndarray:
        """Mean force [N] each line exerted on its fairlead over the last advance (the
        mean over its sub-steps), ``(n_lines, dim)``."""
        return self._fairlead_end_forces(mean=True)

    def _fairlead_end_forces(self, mean: bool) -> np.ndarray:
        """Each cable's force on its fairlead end (its second held end; a released line's:
        zero), at the last sub-step or its mean over the last advance."""
        if not self.cables:
            raise InputError(f"{self.name}: not initialised; call initialize() first")
        return np.array([np.zeros(self.dim) if free else c.end_forces(mean=mean)[1]
                         for c, free in zip(self.cables, self.released)])

    def anchor_forces(self) -> np.ndarray:
        """Force [N] each line exerts on its anchor, ``(n_lines, dim)``."""
        return np.array([c.end_forces()[0] for c in self.cables])

    def fairlead_tensions(self) -> np.ndarray:
        """Magnitude [N] of the fairlead force of each line."""
        return np.linalg.norm(self.fairlead_forces(), axis=1)

    def anchor_tensions(self) -> np.ndarray:
        """Magnitude [N] of the anchor force of each line."""
        return np.linalg.norm(self.anchor_forces(), axis=1)

    def line_energies(self) -> np.ndarray:
        """Each line's mechanical energy [J] (:meth:`SPHCable.mechanical_energy`)."""
        return np.array([c.mechanical_energy() for c in self.cables])

    def shapes(self) -> list[np.ndarray]:
        """Particle positions [m] of each line."""
        return [c.positions for c in self.cables]

    def total_wrench(self, point):
        """Total mooring force [N] and its moment [N m] about ``point`` [m] (3-D: a 3-vector;
        2-D: ``M_y = r_z F_x - r_x F_z``)."""
        f = self.fairlead_forces()
        r = self._fpos - np.asarray(point, dtype=float)
        if self.dim == 3:
            return f.sum(axis=0), np.cross(r, f).sum(axis=0)
        return f.sum(axis=0), float(np.sum(r[:, 1] * f[:, 0] - r[:, 0] * f[:, 1]))

    def save_state(self):
        return ([c.save_state() for c in self.cables], None if self._fpos is None else self._fpos.copy(),
                None if self._fvel is None else self._fvel.copy(), self.t, self.state_log.save())

    def load_state(self, state) -> None:
        cs, self._fpos, self._fvel, self.t, log_ = state
        for c, s in zip(self.cables, cs):
            c.load_state(s)
        self.state_log.load(log_)


def load_end_motion(path):
    """Read a prescribed end motion from a text/CSV file: columns t [s] and the position
    [m] (x, z or x, y, z), comma- or space-separated, ``#`` comments. Returns
    (times, positions) for :meth:`SPHCable.set_end_table`."""
    try:
        with open(path) as fh:
            rows = [ln.replace(",", " ").split() for ln in fh if ln.strip() and not ln.lstrip().startswith("#")]
        data = np.array([[float(v) for v in r] for r in rows])
    except (OSError, ValueError) as exc:
        raise InputError(f"end motion file {path!r}: {exc}") from None
    if data.ndim != 2 or data.shape[1] not in (3, 4) or data.shape[0] < 2:
        raise InputError(f"end motion file {path!r}: need >= 2 rows of t, x, z (or t, x, y, z)")
    return data[:, 0], data[:, 1:]


__all__ = ["CableStepLimit", "SPHCable", "SPHCableMooring", "material_coordinates", "node_shares", "catenary_points",
           "load_end_motion"]
