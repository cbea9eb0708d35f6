"""The potential-flow fluid as a participant: the Cummins equation in time, on MuJoCo bodies.

What: per body, six degrees of freedom about its centre of mass, world axes (Cummins 1962;
Ogilvie 1964; Newman 1977 §6.20)::

    (M + A∞) ẍ + ∫_0^T K(τ) ẋ(t − τ) dτ + C ξ = F_exc(t) + F_drag

``M`` is MuJoCo's (the body's mass and inertia, gravity included); this participant gives
the rest as the load on the body:

- hydrostatics, linear about the floating pose the body has when attached (its mesh's):
  the buoyancy ``ρ g V`` up at the centre of buoyancy (``V`` the shape's exact displaced
  volume where known, else the mesh's), minus ``C ξ`` with ``ξ`` the centre of
  mass's displacement and the rotation vector of the body's rotation since then (small-angle
  linear theory: no change of the waterplane with the pose; the mean pose may drift far
  horizontally, since ``C`` has no horizontal terms);
- radiation memory ``−∫ K(τ) ẋ(t − τ) dτ`` over the memory ``T`` (:mod:`.radiation`),
  trapezoid rule over the velocities of the accepted coupling steps (rest before the start);
- excitation by the waves of a :class:`~fluid.potential.waves.Sea` (:mod:`.waves`) at the rest
  position, of its components inside the band the coefficients trust (:meth:`_check_sea`);
- optional quadratic (Morison) drag per body, 6 coefficients [N s²/m², N m s²], on the
  velocity relative to the undisturbed wave's at the centre of buoyancy (translations) and on
  the angular velocity (Morison et al. 1950; the drag that potential flow lacks);
- the infinite-frequency added mass ``A∞`` (the time-domain one, :mod:`.radiation`): its
  diagonal moves into MuJoCo's implicit inertia (``dof_armature``: translations along world
  axes, rotations about the body axes at the start), its off-diagonal rest (surge-pitch,
  sway-roll coupling) acts explicitly as ``−A_rest a``, ``a`` the mean acceleration over the
  last accepted step. Why: an added-mass force from a previous acceleration alone is
  unstable once ``A > M`` (a light body; :mod:`cosim.added_mass`), while the rest of a
  positive-definite ``M + A∞`` against its diagonal is a contraction (each 2 x 2 coupled pair
  has ``|A_ij| < sqrt(M_ii + A_ii)(M_jj + A_jj)``), so the lag is stable.
- optional (``drift``) the slowly varying drift force in surge, sway and yaw: Newman's (1974)
  approximation from the freely floating body's mean drift (Maruo 1960; :mod:`.drift`).

Limits: linear potential flow (small motions, small waves); one geom per body (box, cylinder,
sphere) with a free joint (3-D scenes); bodies interact only with ``interaction`` (:mod:`.group`),
then without drift; of second order only the mean and slow drift. The loads react to the body's
acceleration only through the armature, so explicit coupling needs no light-body remedy.
"""

from __future__ import annotations

import logging
import math
from typing import Mapping, Sequence

import numpy as np

from errors import InputError
from fluid.potential.coefficients import Coefficients, compute, require_capytaine
from fluid.potential.drift import MeanDrift, SlowDrift, mean_drift
from fluid.potential.group import compute_group
from fluid.potential.hull import KINDS, check_pierces, default_panel_size, displaced_volume, wetted_hull
from fluid.potential.radiation import BAND, ImpulseResponse, SettingError, impulse_response
from fluid.potential.waves import Excitation, Sea, band_share, cut_for_share, wavenumber
from fluid.waves import group_velocity

log = logging.getLogger(__name__)

#: panels per wavelength at the highest default frequency (the BEM's resolution rule of thumb)
PANELS_PER_WAVELENGTH = 6
#: coupling steps per shortest natural period, wave period and impulse-response period
STEPS_PER_PERIOD = 50
#: BEM frequencies when unset (bodies solved together: as many as their distance needs, :meth:`_group_frequencies`)
FREQUENCIES = 40
#: the most frequencies the distance rule may choose (a group solve costs one BEM problem set per frequency)
MAX_FREQUENCIES = 400
#: the share of the window π/Δω the needed memory may fill (the decay check looks at its last 10 %)
WINDOW_FILL = 0.8
#: the largest share of the sea's variance m0 whose components the fluid may leave out for lying
#: outside the band its coefficients trust: a JONSWAP sea (gamma 3.3) holds 4.9 % of its m0 above
#: 2 fp, 1.0 % above 3 fp, 0.3 % above 4 fp (Pierson-Moskowitz 7.5, 1.5, 0.5 %)
DROP_MAX = 0.01


#: the smallest k d at which Capytaine 3.0's finite-depth Green function returns values (it
#: returned NaN at k d = 0.129 and below, values from 0.143 on, on two depths), with a margin
KD_MIN = 0.15


def lowest_omega(depth: float, g: float = 9.81) -> float:
    """The lowest frequency [rad/s] Capytaine solves in water ``depth`` [m] deep (k d = :data:`KD_MIN`); 0 when deep."""
    if not math.isfinite(depth):
        return 0.0
    return math.sqrt(g * KD_MIN / depth * math.tanh(KD_MIN))


def frequency_grid(omega_max: float, n: int, depth: float = math.inf, g: float = 9.81) -> np.ndarray:
    """``n`` frequencies [rad/s] evenly spaced up to ``omega_max``: from ``omega_max / n`` (so that
    the spacing is the lowest frequency), or in shallow water from :func:`lowest_omega` if higher."""
    lo = max(omega_max / n, lowest_omega(depth, g))
    if lo >= omega_max:
        raise SettingError("omega_max", f"potential flow: omega_max = {omega_max:g} rad/s is at or below "
                           f"{lo:.4g} rad/s, the lowest frequency solvable in {depth:g} m of water; raise it")
    return np.linspace(lo, omega_max, n)


def default_omega(panel_size: float, g: float = 9.81, n: int = 40, depth: float = math.inf) -> np.ndarray:
    """:func:`frequency_grid` up to ω_max, the frequency whose deep-water wavelength ``2π g / ω²``
    spans :data:`PANELS_PER_WAVELENGTH` panels of ``panel_size`` [m]."""
    w_max = math.sqrt(2.0 * math.pi * g / (PANELS_PER_WAVELENGTH * panel_size))
    return frequency_grid(w_max, n, depth, g)


def _mass_matrix(mass: float, inertia: np.ndarray) -> np.ndarray:
    """The 6 x 6 rigid-body mass matrix about the centre of mass [kg, kg m^2] from the mass and
    the inertia tensor there (world axes)."""
    M = np.zeros((6, 6))
    M[:3, :3] = mass * np.eye(3)
    M[3:, 3:] = inertia
    return M


def _rotvec(R: np.ndarray) -> np.ndarray:
    """The rotation vector (axis times angle [rad]) of a rotation matrix."""
    from scipy.spatial.transform import Rotation

    return Rotation.from_matrix(R).as_rotvec()


class PotentialFluid:
    """Linear potential flow on the coupled bodies (module docstring).

    Parameters
    ----------
    rho, g:
        Water density [kg/m^3], gravity [m/s^2] (along -z).
    free_surface_z:
        Height of the still free surface [m].
    depth:
        Water depth [m] under the still surface (inf: deep water).
    omega:
        BEM frequencies [rad/s], increasing, evenly spaced (:func:`frequency_grid`; None:
        ``frequencies`` of them to ``omega_max``).
    omega_max, frequencies:
        The grid when ``omega`` is None: :func:`frequency_grid` to ``omega_max`` [rad/s] (None:
        per body from its panel size, :func:`default_omega`), ``frequencies`` of them (None:
        :data:`FREQUENCIES`, or with ``interaction`` as many as the bodies' distance needs).
    headings:
        Wave headings [deg] the excitation is computed for (None: those of ``sea``, or 0).
    panel_size:
        Panel size [m], one for all bodies or per body name (None: a tenth of each body's
        smallest horizontal dimension, :func:`fluid.potential.hull.default_panel_size`).
    memory:
        Radiation memory [s] (None: where the impulse response has decayed).
    sea:
        The waves (None: still water).
    quadratic_drag:
        Per body name, 6 coefficients [N s^2/m^2, N m s^2] (translations, rotations).
    cache:
        Folder of the coefficients' cache (None: :func:`fluid.potential.cache_dir`).
    coefficients:
        Precomputed coefficients per body name (their hulls must be the bodies' own): skips
        the BEM for those bodies.
    drift:
        Add the slowly varying drift force (module docstring; needs ``sea``, and Kochin
        functions in given coefficients).
    interaction:
        Solve the bodies together (:mod:`.group`): coupled radiation memory and added mass,
        each body's excitation in the others' presence (one body: the same as alone).
    """

    loads_carry_added_mass = False  #: A∞ goes into the bodies' inertia (module docstring)

    def __init__(self, *, rho: float = 1000.0, g: float = 9.81, free_surface_z: float = 0.0,
                 depth: float = math.inf, omega: Sequence[float] | None = None, omega_max: float | None = None,
                 frequencies: int | None = None,
                 headings: Sequence[float] | None = None, panel_size: float | Mapping[str, float] | None = None,
                 memory: float | None = None, sea: Sea | None = None,
                 quadratic_drag: Mapping[str, Sequence[float]] | None = None, cache=None,
                 coefficients: Mapping[str, Coefficients] | None = None, drift: bool = False,
                 interaction: bool = False, name: str = "fluid"):
        for label, v in (("rho", rho), ("g", g)):
            if not (math.isfinite(v) and v > 0):
                raise InputError(f"potential fluid: {label} must be finite and > 0, got {v!r}")
        if not math.isfinite(free_surface_z):
            raise InputError(f"potential fluid: free_surface_z must be finite, got {free_surface_z!r}")
        if not depth > 0:
            raise InputError(f"potential fluid: depth = {depth!r} m; give a depth > 0 (inf: deep water)")
        if sea is not None and not isinstance(sea, Sea):
            raise InputError(f"potential fluid: sea must be a fluid.potential.waves.Sea, got {type(sea).__name__}")
        if sea is not None and (sea.depth != depth or sea.g != g):
            raise InputError(f"potential fluid: the sea's depth {sea.depth:g} m and gravity {sea.g:g} m/s^2 differ "
                             f"from the fluid's {depth:g} m and {g:g} m/s^2; give both the same")
        if drift and sea is None:
            raise InputError("potential fluid: drift = True needs waves (sea); without them there is no drift force")
        if interaction and (drift or coefficients):
            raise InputError("potential fluid: interaction = True takes neither drift nor precomputed coefficients "
                             "(the bodies' group solve has no Kochin functions; it makes every body's coefficients)")
        if memory is not None and not (math.isfinite(memory) and memory > 0):
            raise InputError(f"potential fluid: memory = {memory!r} s; give a time > 0 s (None: from the decay)")
        if not coefficients:
            require_capytaine()
        self.rho, self.g, self.eta, self.depth = float(rho), float(g), float(free_surface_z), float(depth)
        self.omega = None if omega is None else np.asarray(omega, float)
        if frequencies is not None and int(frequencies) < 4:
            raise InputError(f"potential fluid: frequencies = {frequencies!r}; give at least 4")
        if omega_max is not None and not (math.isfinite(omega_max) and omega_max > 0):
            raise InputError(f"potential fluid: omega_max = {omega_max!r} rad/s; give a frequency > 0")
        self.frequencies = None if frequencies is None else int(frequencies)
        self.omega_max = omega_max
        self.headings = (np.asarray(headings, float) if headings is not None else
                         np.unique(sea.heading) if sea is not None else np.array([0.0]))
        self.panel_size, self.memory, self.sea = panel_size, memory, sea
        self.quadratic_drag = dict(quadratic_drag or {})
        self.cache, self.name = cache, name
        self._given = dict(coefficients or {})
        self.t = 0.0
        self._kin = None
        self._dirty = False
        self.dt_limit = "none"  #: the condition that set max_dt()
        self.coefficients: list[Coefficients] = []  #: per body, in the bodies' order
        self.impulse: list[ImpulseResponse] = []  #: per body
        self.drift, self.interaction = bool(drift), bool(interaction)
        self.group = None  #: the bodies' GroupCoefficients, with interaction
        self.group_impulse: ImpulseResponse | None = None  #: their coupled impulse response
        self.mean_drift: list[MeanDrift] = []  #: per body, with drift
        self.sea_left_out: dict = {}  #: per body name, the share of the sea's variance left out (:meth:`_check_sea`)

    @property
    def waves(self) -> Sea | None:
        """The sea (its ``elevation(xy, t)`` is what a scene's wave gauges read)."""
        return self.sea

    # -- set-up ------------------------------------------------------------------
    def _panel_size(self, body: str, kind: str, size) -> float:
        ps = self.panel_size
        if isinstance(ps, Mapping):
            ps = ps.get(body)
        return default_panel_size(kind, size) if ps is None else float(ps)

    def _check_sea(self, name: str, omega) -> tuple[Sea | None, float]:
        """The sea's components inside the band the impulse response is trusted in
        (:mod:`.radiation`: the lowest frequency to ``BAND`` x the highest), which the excitation
        and drift take; those outside may carry at most :data:`DROP_MAX` of the sea's variance
        (an irregular sea's tail above 2-3 peak frequencies), else refused naming the setting
        to change (``omega_max`` with the value that would keep all but that share); the kept
        sea and the share left out."""
        if self.sea is None:
            return None, 0.0
        lo, hi = float(omega[0]), BAND * float(omega[-1])
        keep, share = band_share(self.sea, lo, hi)
        if share > DROP_MAX:
            out = self.sea.omega[~keep]
            w = float(out[np.argmax(self.sea.amplitude[~keep])])
            head = (f"potential flow: body '{name}': the sea's components outside the coefficients' trusted band "
                    f"{lo:.4g}-{hi:.4g} rad/s (the lowest frequency to {BAND:g} x the highest) carry {share:.1%} of "
                    f"its variance (the largest of them {w:.4g} rad/s, period {2 * math.pi / w:.4g} s); at most "
                    f"{DROP_MAX:.0%} may be left out")
            cut = cut_for_share(self.sea, lo, DROP_MAX)
            if not math.isfinite(cut):
                raise SettingError("frequencies", f"{head}; the lowest frequency {lo:.4g} rad/s is too high: give more "
                                   f"frequencies (they start at omega_max / frequencies)")
            need = cut / BAND
            raise SettingError("omega_max", f"{head}; set omega_max >= {need:.4g} rad/s (it keeps all but "
                               f"{DROP_MAX:.0%}), with panels of at most "
                               f"{2 * math.pi * self.g / (PANELS_PER_WAVELENGTH * need**2):.3g} m "
                               f"({PANELS_PER_WAVELENGTH} per wavelength there)")
        return (self.sea if keep.all() else self.sea.subset(keep)), share

    def attach_bodies(self, bodies) -> None:
        """Compute (or read) each body's coefficients at its pose now, its floating pose;
        move A∞'s diagonal into its inertia. Called once by the coupler."""
        names = list(bodies.body_names)
        unknown = sorted((set(self.quadratic_drag) | set(self._given)) - set(names))
        if unknown:
            raise InputError(f"potential fluid: drag or coefficients given for unknown bodies {unknown}; bodies: "
                             f"{names}")
        kin = bodies.kinematics()
        n = len(names)
        self.n_bodies, self.body_names = n, names
        self._mass = bodies.masses()
        self._com0, self._R0 = kin.com.copy(), kin.rotation.copy()
        self._F0 = np.zeros((n, 6))
        self._drag = np.zeros((n, 6))
        self._armature = np.zeros((n, 6))
        self._exc: list[Excitation | None] = []
        self._kept: list[Sea | None] = []  #: per body, the sea's components its excitation takes
        self.sea_left_out = {}
        self._cob = np.zeros((n, 3))
        self._slow: list[SlowDrift] = []
        self.coefficients, self.impulse, self.mean_drift = [], [], []
        grouped = self._solve_together(names, bodies, kin) if self.interaction and n > 1 else {}
        for k, (name, shapes) in enumerate(zip(names, bodies.geoms())):
            geom, rot, centre = self._geom(k, name, shapes, kin, bodies)
            R = kin.rotation[k]
            c = grouped.get(name) or self._given.get(name)
            if c is None:
                ps = self._panel_size(name, geom.kind, geom.size)
                omega = self._grid(ps)
                self._check_omega(name, omega)
                hull = wetted_hull(geom.kind, geom.size, rot, centre, ps, name=name)
                c = compute(hull, float(kin.com[k, 2] - self.eta), omega=omega, headings=self.headings,
                            depth=self.depth, rho=self.rho, g=self.g, cache=self.cache, name=name,
                            kochin=self.drift)
            irf = impulse_response(c.omega, c.added_mass, c.damping, self.memory, name=name)
            log.info("potential fluid: body '%s': %d panels, %d frequencies to %.3g rad/s, memory %.3g s (decays "
                     "to %.2g %%), A(w) rebuilt within %.2g %%, B(w) %.2g %% below %.3g rad/s", name, c.panels,
                     len(c.omega), c.omega[-1], irf.memory, 100 * irf.decay, 100 * irf.error_A,
                     100 * irf.error_B, irf.band)
            self.coefficients.append(c)
            self.impulse.append(irf)
            # the buoyancy at rest from the shape's exact volume where known, so that a body placed at
            # its equilibrium stays there (the flat panels' polygonal waterline holds a little less)
            exact = displaced_volume(geom.kind, geom.size, rot, float(centre[2]))
            F0 = np.array([0.0, 0.0, self.rho * self.g * (c.volume if exact is None else exact)])
            self._cob[k] = c.centre_of_buoyancy - c.centre_of_mass
            self._F0[k] = np.concatenate([F0, np.cross(self._cob[k], F0)])
            if name in self.quadratic_drag:
                d = np.asarray(self.quadratic_drag[name], float)
                if d.shape != (6,) or (d < 0).any() or not np.isfinite(d).all():
                    raise InputError(f"potential fluid: quadratic drag of body '{name}' takes 6 finite values >= "
                                     f"0, got {d}")
                self._drag[k] = d
            A = irf.added_mass_inf if self.group_impulse is None else \
                self.group_impulse.added_mass_inf[6 * k:6 * k + 6, 6 * k:6 * k + 6]
            rr = R.T @ A[3:, 3:] @ R  # the rotational block in the body axes of the free joint
            arm = np.clip(np.concatenate([np.diag(A[:3, :3]), np.diag(rr)]), 0.0, None)
            bodies.add_armature(k, arm)
            self._armature[k] = arm
            sea, share = self._check_sea(name, c.omega)
            if share > 0:
                self.sea_left_out[name] = share
                log.info("potential fluid: body '%s': %d of the sea's %d components lie outside the trusted band "
                         "%.3g-%.3g rad/s, left out of its excitation: %.2g %% of the sea's variance", name,
                         len(self.sea.omega) - len(sea.omega), len(self.sea.omega), c.omega[0], irf.band, 100 * share)
            self._kept.append(sea)
            self._exc.append(None if sea is None else
                             Excitation(sea, c.omega, c.headings, c.excitation, kin.com[k, :2], name=name))
            if self.drift:
                md = mean_drift(c, _mass_matrix(self._mass[k], bodies.inertia_tensors()[k]), name=name)
                self.mean_drift.append(md)
                self._slow.append(SlowDrift(sea, md, kin.com[k, :2], name=name))
        self._inertia = np.array([bodies.dof_inertia(k) for k in range(n)])  # own, armature left out
        self._hist_t = np.zeros(0)
        self._hist_v = np.zeros((0, n, 6))

    def _check_omega(self, name: str, omega) -> None:
        """The frequencies fit the sea and the depth (before any solve)."""
        self._check_sea(name, omega)
        if omega[0] < lowest_omega(self.depth, self.g) * (1 - 1e-9):
            raise SettingError("frequencies", f"potential flow: body '{name}': the lowest frequency "
                               f"{omega[0]:.4g} rad/s is below {lowest_omega(self.depth, self.g):.4g} "
                               f"rad/s (k d = {KD_MIN:g} in {self.depth:g} m of water), where Capytaine's "
                               f"finite-depth solver returns no value; start the frequencies there")

    def _solve_together(self, names, bodies, kin) -> dict:
        """Every body's coefficients from one group solve (:mod:`.group`) on the frequencies given
        or those of the smallest default panel, and the coupled impulse response."""
        hulls, sizes = [], []
        for k, (name, shapes) in enumerate(zip(names, bodies.geoms())):
            geom, rot, centre = self._geom(k, name, shapes, kin, bodies)
            ps = self._panel_size(name, geom.kind, geom.size)
            sizes.append(ps)
            hulls.append(wetted_hull(geom.kind, geom.size, rot, centre, ps, name=name))
        omega = self._grid(min(sizes))
        self._check_omega(", ".join(names), omega)
        if self.memory is None and self.omega is None:
            omega = self._group_frequencies(names, hulls, kin, omega, min(sizes))
        self.group = compute_group(hulls, kin.com[:, :2], kin.com[:, 2] - self.eta, names=names, omega=omega,
                                   headings=self.headings, depth=self.depth, rho=self.rho, g=self.g,
                                   cache=self.cache)
        g = self.group
        self.group_impulse = impulse_response(g.omega, g.added_mass, g.damping, self.memory, name="+".join(names))
        return dict(zip(names, g.bodies))

    def _grid(self, panel_size: float, n: int | None = None) -> np.ndarray:
        """The BEM frequencies: those given, else ``n`` (or :attr:`frequencies`, or
        :data:`FREQUENCIES`) to ``omega_max`` or the panel's :func:`default_omega`."""
        if self.omega is not None:
            return self.omega
        n = n or self.frequencies or FREQUENCIES
        if self.omega_max is None:
            return default_omega(panel_size, self.g, n, self.depth)
        return frequency_grid(self.omega_max, n, self.depth, self.g)

    def _group_frequencies(self, names, hulls, kin, omega, panel: float) -> np.ndarray:
        """The grid (on ``panel`` [m]) for bodies solved together, spaced finely enough for the
        coupled memory: the window π/Δω must hold, within :data:`WINDOW_FILL`, the longest lone body's memory
        (its impulse response's decay, from its own coefficients at ``omega``) plus the
        longest round trip between two bodies (a body's wave scattered back by another: the
        diagonal blocks carry it) at the slowest group velocity the kernel keeps, that at
        ω_max (Dean & Dalrymple 1991, Eq. 4.79). ``frequencies`` unset: as many as that
        needs (at least :data:`FREQUENCIES`, at most :data:`MAX_FREQUENCIES`); given and too
        few: refused with the count needed."""
        xy = kin.com[:, :2]
        r = float(np.max(np.linalg.norm(xy[:, None] - xy[None], axis=-1)))
        w = float(omega[-1])
        k = wavenumber(w, self.depth, self.g)
        cg = float(group_velocity(k, self.depth, self.g)) if math.isfinite(self.depth) else self.g / (2.0 * w)
        own = 0.0
        for k_, (name, hull) in enumerate(zip(names, hulls)):
            c = compute(hull, float(kin.com[k_, 2] - self.eta), omega=omega, headings=self.headings, depth=self.depth,
                        rho=self.rho, g=self.g, cache=self.cache, name=name)
            own = max(own, impulse_response(c.omega, c.added_mass, c.damping, None, name=name).memory)
        need = own + 2.0 * r / cg
        span = float(np.diff(omega).max()) * len(omega)  # Δω n: ω_max (from ω_max / n), a little more in shallow water
        n = max(FREQUENCIES, math.ceil(need / WINDOW_FILL * span / math.pi))
        what = (f"bodies {', '.join(names)}: the cross memory needs {need:.4g} s (the lone bodies' {own:.3g} s plus "
                f"twice {r:.4g} m at the group velocity {cg:.3g} m/s of omega_max = {w:.4g} rad/s), so pi / spacing >= "
                f"{need / WINDOW_FILL:.4g} s: {n} frequencies to {w:.4g} rad/s")
        if self.frequencies is not None:
            if self.frequencies < n:
                raise SettingError("frequencies", f"potential flow: {what}; frequencies = {self.frequencies} is too "
                                   f"few: give at least {n} (or leave it unset)")
            return omega
        if n > MAX_FREQUENCIES:
            raise SettingError("frequencies", f"potential flow: {what}, more than {MAX_FREQUENCIES}: bring the bodies "
                               f"closer, lower omega_max (with coarser panels) or set interaction = false")
        log.info("potential fluid: %s (%d BEM problems)", what, n * (6 * len(names) + len(self.headings)))
        return self._grid(panel, n)

    def _geom(self, k: int, name: str, shapes, kin, bodies):
        """The body's one solid geom, its orientation and its centre relative to (centre of mass
        x, y; still water), checked: one box, cylinder or sphere, a free joint, piercing the surface."""
        solids = [s for s in shapes if s.kind in KINDS]
        if len(shapes) != 1 or not solids:
            raise InputError(f"potential fluid: body '{name}' has {len(shapes)} geoms "
                             f"({', '.join(s.kind for s in shapes) or 'none'}); this model takes one box, "
                             f"cylinder or sphere per body")
        dofs = bodies.dofs(k)
        if dofs.stop - dofs.start != 6:
            raise InputError(f"potential fluid: body '{name}' has {dofs.stop - dofs.start} degrees of freedom; "
                             f"linear potential flow is 3-D: give it a free joint (a 3-D scene)")
        geom = solids[0]
        R = kin.rotation[k]
        rot = R @ geom.rot
        centre = kin.origin[k] + R @ geom.pos - np.array([kin.com[k, 0], kin.com[k, 1], self.eta])
        check_pierces(name, geom.kind, geom.size, rot, float(centre[2]))
        return geom, rot, centre

    # -- coupling ----------------------------------------------------------------
    def set_body_kinematics(self, kin) -> None:
        """New body kinematics; the loads are for them (at the fluid's time)."""
        self._kin = kin
        self._dirty = True

    def set_time(self, t: float) -> None:
        """Take the loads at time ``t`` [s] for the kinematics last given."""
        self.t = float(t)
        self._dirty = True

    def _velocities(self, kin) -> np.ndarray:
        return np.concatenate([kin.velocity, kin.omega], axis=1)

    def _record(self) -> None:
        """Append the current velocities at the current time (an accepted step's end)."""
        keep = self._hist_t < self.t - 1e-12
        self._hist_t = np.append(self._hist_t[keep], self.t)
        self._hist_v = np.concatenate([self._hist_v[keep], self._velocities(self._kin)[None]])
        memories = [irf.memory for irf in self.impulse + [self.group_impulse] if irf is not None]
        horizon = max(memories) + 1.0
        old = np.flatnonzero(self._hist_t < self.t - horizon)
        if old.size > 1:  # one sample before the window stays, so the window's start is covered
            self._hist_t, self._hist_v = self._hist_t[old[-1]:], self._hist_v[old[-1]:]

    def radiation_force(self) -> np.ndarray:
        """∫ K(τ) ẋ(t − τ) dτ per body [N, N m] ``(n, 6)`` (the load is minus this)."""
        keep = self._hist_t < self.t - 1e-12
        T = np.append(self._hist_t[keep], self.t)
        V = np.concatenate([self._hist_v[keep], self._velocities(self._kin)[None]])
        out = np.zeros((self.n_bodies, 6))
        if len(T) < 2:
            return out
        lag = self.t - T
        if self.group_impulse is not None:  # the coupled memory: body i's load from every body's velocities
            inside = lag <= self.group_impulse.memory
            tau, v = lag[inside], V[inside].reshape(int(inside.sum()), -1)
            if len(tau) < 2:
                return out
            w = np.zeros(len(tau))
            d = -np.diff(tau)
            w[:-1] += 0.5 * d
            w[1:] += 0.5 * d
            return np.einsum("n,nij,nj->i", w, self.group_impulse.at(tau), v).reshape(self.n_bodies, 6)
        for k, irf in enumerate(self.impulse):
            inside = lag <= irf.memory
            tau, v = lag[inside], V[inside, k]
            if len(tau) < 2:
                continue
            w = np.zeros(len(tau))  # trapezoid weights over the (decreasing) lags
            d = -np.diff(tau)
            w[:-1] += 0.5 * d
            w[1:] += 0.5 * d
            out[k] = np.einsum("n,nij,nj->i", w, irf.at(tau), v)
        return out

    def _acceleration(self) -> np.ndarray:
        """The bodies' mean acceleration over the last accepted step, ``(n, 6)`` (0 before one)."""
        keep = self._hist_t < self.t - 1e-12
        T, V = self._hist_t[keep], self._hist_v[keep]
        if len(T) < 2:
            return np.zeros((self.n_bodies, 6))
        return (V[-1] - V[-2]) / (T[-1] - T[-2])

    def _update(self) -> None:
        kin = self._kin
        n = self.n_bodies
        F = self._F0.copy()
        acc = self._acceleration()
        for k in range(n):
            c = self.coefficients[k]
            xi = np.concatenate([kin.com[k] - self._com0[k], _rotvec(kin.rotation[k] @ self._R0[k].T)])
            F[k] -= c.stiffness @ xi
            R = kin.rotation[k]
            arm = np.zeros((6, 6))
            arm[:3, :3] = np.diag(self._armature[k, :3])
            arm[3:, 3:] = R @ np.diag(self._armature[k, 3:]) @ R.T
            if self.group_impulse is None:
                F[k] -= (self.impulse[k].added_mass_inf - arm) @ acc[k]
            else:  # the coupled A∞ on every body's acceleration, less this body's armature
                s = slice(6 * k, 6 * k + 6)
                A = self.group_impulse.added_mass_inf[s]
                F[k] -= A @ acc.ravel() - arm @ acc[k]
            if self._exc[k] is not None:
                F[k] += self._exc[k].force(self.t)
            if self._slow:
                F[k] += self._slow[k].force(self.t)
        F -= self.radiation_force()
        if self._drag.any():
            v = kin.velocity.copy()
            if self.sea is not None:
                cob = kin.com + np.einsum("nij,nj->ni", kin.rotation @ np.transpose(self._R0, (0, 2, 1)), self._cob)
                v -= self.sea.velocity(cob, self.t, self.eta)
            F[:, :3] -= self._drag[:, :3] * np.abs(v) * v
            F[:, 3:] -= self._drag[:, 3:] * np.abs(kin.omega) * kin.omega
        self._wrench = (F[:, :3].copy(), F[:, 3:].copy())

    def body_wrenches(self):
        """Force [N] and torque about the centre of mass [N m] on each body, world frame,
        for the kinematics last given, at the fluid's time."""
        if self._dirty and self._kin is not None:
            self._update()
            self._dirty = False
        return self._wrench

    # -- participant protocol ------------------------------------------------------
    def initialize(self, t0: float) -> None:
        if self._kin is None:
            raise InputError("potential fluid: no bodies attached; add it to a Coupler with bodies=")
        self.t = float(t0)
        self._hist_t = np.zeros(0)
        self._hist_v = np.zeros((0, self.n_bodies, 6))
        self._record()
        self._dirty = True

    def max_dt(self) -> float:
        """A fiftieth of the shortest of: each body's natural periods in heave, roll and pitch
        ``2π sqrt((M_ii + A∞_ii) / C_ii)``, the waves' periods, and the period ``2π/ω_max``
        that the impulse response resolves (:attr:`dt_limit` says which)."""
        if self._kin is None:
            return math.inf
        limits = {"impulse response": min(2 * math.pi / c.omega[-1] for c in self.coefficients)}
        nat = math.inf
        for k, c in enumerate(self.coefficients):
            m = self._inertia[k] + np.diag(self.impulse[k].added_mass_inf)
            for i in (2, 3, 4):
                if c.stiffness[i, i] > 0:
                    nat = min(nat, 2 * math.pi * math.sqrt(m[i] / c.stiffness[i, i]))
        limits["natural period"] = nat
        if self.sea is not None:  # the components the loads carry
            limits["wave period"] = float(2 * math.pi / max(s.omega.max() for s in self._kept))
        self.dt_limit = min(limits, key=limits.get)
        return float(limits[self.dt_limit]) / STEPS_PER_PERIOD

    def advance(self, t: float, dt: float) -> None:
        self.t = float(t + dt)
        self._record()
        self._dirty = True

    def save_state(self):
        return self.t, self._hist_t.copy(), self._hist_v.copy()

    def load_state(self, state) -> None:
        self.t, ht, hv = state
        self._hist_t, self._hist_v = ht.copy(), hv.copy()
        self._dirty = True
