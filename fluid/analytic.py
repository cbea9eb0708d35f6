"""A cheap analytic fluid: hydrostatic buoyancy, damping and added mass.

The same coupling interface as the SPH fluid (``attach_bodies``,
``set_body_kinematics``, ``body_wrenches``, the participant protocol), so a scene
switches between a mooring study that runs in seconds and an SPH run by changing
one line. Per body:

- buoyancy ``ρ g V_sub`` upwards at the centre of buoyancy, from the submerged
  part of each geom below a flat free surface ``z = free_surface_z``; volumes are
  integrated over a lattice of cells in each geom (weights scaled to the geom's
  exact volume), and a cell cut by the surface counts with the fraction of its
  height below it, so the force is continuous in the pose;
- linear and quadratic (Morison-type) damping of the centre-of-mass velocity and
  of the angular velocity, world axes, scaled by the submerged fraction;
- added mass and inertia, moved into MuJoCo's implicit inertia (``dof_armature``:
  inertia without weight), which keeps explicit coupling stable for light bodies;
- optionally an incident sea of :mod:`fluid.waves` (regular linear or Stokes-2 waves, a
  JONSWAP / Pierson–Moskowitz spectrum, a recorded elevation; or :class:`LinearWave`),
  whose free surface moves the hydrostatics (the buoyancy is that of the volume under the
  instantaneous surface) and whose water velocity and acceleration enter the Morison equation
  (Morison et al. 1950; Faltinsen 1990 §7.1 eq. 7.1, Dean & Dalrymple 1991 §10.3) on each
  cell of the submerged volume::

      F = ρ g V(η) e_z + ρ ∫_V(η) a_w dV + m_a ā_w − B_1 v_r − B_2 |v_r| v_r,  v_r = V − ū_w

  The first two terms are the Froude–Krylov force: the incident wave's pressure
  integrated over the wetted surface, closed by the free surface where p = 0, is
  ∫_V(η) −∇p dV = ∫_V(η) ρ (g e_z + ∂u/∂t) dV (linearised Euler equation). The third
  is the diffraction (added-mass) part, with the same added mass m_a that the body
  carries in its inertia, so that the inertia force is C_m ρ V ā_w with
  C_m = 1 + C_a, C_a = m_a / (ρ V) (V the submerged volume V(η)), and the body's own
  −m_a dU/dt stays implicit.
  ``ā_w``, ``ū_w`` are the wave acceleration and velocity averaged over the submerged
  volume; the drag (the damping coefficients) acts on the velocity relative to the
  water. Rotational damping acts on the body's angular velocity (the wave is
  irrotational).

No radiation memory, no diffraction of the wave by the body: this is the speed end of
the speed/accuracy trade. Valid for bodies small against the wavelength.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Mapping, Sequence

import numpy as np

from bodies.sampling import cross, half_extents, mesh_volume, signed_distance
from errors import InputError
from fluid.waves import RegularWave, Sea, SeaError


#: exact volumes [m^3] from MuJoCo sizes (half-sizes, radius, half-length)
_VOLUME = {
    "box": lambda s: 8.0 * s[0] * s[1] * s[2],
    "sphere": lambda s: 4.0 / 3.0 * math.pi * s[0] ** 3,
    "ellipsoid": lambda s: 4.0 / 3.0 * math.pi * s[0] * s[1] * s[2],
    "cylinder": lambda s: math.pi * s[0] ** 2 * 2.0 * s[1],
    "capsule": lambda s: math.pi * s[0] ** 2 * (2.0 * s[1] + 4.0 / 3.0 * s[0]),
}


def geom_volume(kind: str, size, mesh: tuple | None = None) -> float:
    """Exact volume [m^3] of a MuJoCo geom from its kind and MuJoCo size (half-sizes
    [m], radius [m], half-length [m]), or of a mesh geom from its ``mesh = (vertices,
    faces)`` (``bodies.sampling.GeomShape.mesh``); raises for kinds with no volume model."""
    if kind == "mesh" and mesh is not None:
        return mesh_volume(*mesh)
    if kind not in _VOLUME:
        raise InputError(f"geom type {kind!r} has no volume model; use a box, sphere, ellipsoid, cylinder or capsule")
    return float(_VOLUME[kind](np.asarray(size, float)))


def _unit_cells(kind: str, size: np.ndarray, n: int):
    """Cell centres [m] in the geom frame, the geom's exact volume [m^3] and the
    cell's edge lengths [m] along the geom axes."""
    if kind not in _VOLUME:
        raise InputError(f"analytic fluid: geom type {kind!r} has no volume model (use a box, sphere, ellipsoid, "
                         f"cylinder or capsule; meshes load the SPH fluid only)")
    half = half_extents(kind, size)
    edge = 2.0 * half.max() / n
    counts = np.maximum(np.ceil(2.0 * half / edge).astype(int), 1)
    axes = [(np.arange(c) + 0.5) / c * 2.0 * h - h for c, h in zip(counts, half)]
    p = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    p = p[signed_distance(kind, size, p) <= 0.0]
    return p, _VOLUME[kind](size), 2.0 * half / counts


def _bounding_radius(kind: str, size: np.ndarray) -> float:
    if kind == "box":
        return float(np.linalg.norm(size[:3]))
    if kind in ("sphere",):
        return float(size[0])
    if kind == "ellipsoid":
        return float(size[:3].max())
    if kind == "cylinder":
        return float(math.hypot(size[0], size[1]))
    return float(size[0] + size[1])  # capsule


def _finite(owner: str, name: str, value, unit: str, hint: str, positive: bool = True) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{owner}: {name} must be a number [{unit}], got {value!r}") from None
    if not math.isfinite(v) or (positive and v <= 0):
        raise InputError(f"{owner}: {name} = {value!r} {unit}; give a finite number{' > 0' if positive else ''} "
                         f"({hint})")
    return v


@dataclass(frozen=True)
class LinearWave:
    """A regular linear (Airy) wave of height ``H`` [m] and period ``T`` [s] in water
    ``depth`` [m] deep, travelling along the horizontal heading ``direction`` [deg]
    (from +x towards +y; a 2-D scene takes 0 or 180), faded in over ``ramp`` [s]
    (``r(t) = (1 − cos(π t / ramp)) / 2`` up to ``ramp``, then 1; 0: none); ``source``
    [m]: the plane ``x cos β + y sin β = source`` where it is made, its fade-in travelling
    from there at the group velocity (None: everywhere at once). ``g`` [m/s^2].

    The wave is :class:`fluid.waves.RegularWave` (``theory="linear"``; its docstring has
    the formulas, Dean & Dalrymple 1991, Table 4.1), held in :attr:`sea`; this class keeps
    the calls of points as rows ``p`` = (x, y[, z]) and the still level given per call.
    Above the still water (under a crest) the kinematics are those at the still water;
    below the seabed those at the seabed."""

    H: float
    T: float
    depth: float
    direction: float = 0.0
    ramp: float = 0.0
    g: float = 9.81
    source: float | None = None
    k: float = field(default=math.nan, init=False, compare=False)  #: wavenumber [rad/m], from the dispersion relation
    sea: RegularWave = field(default=None, init=False, compare=False, repr=False)  #: the wave, still level at z = 0

    def __post_init__(self):
        own = "linear wave"
        H = _finite(own, "H", self.H, "m", "the wave height, crest to trough")
        T = _finite(own, "T", self.T, "s", "the wave period")
        d = _finite(own, "depth", self.depth, "m", "the still-water depth over the seabed")
        g = _finite(own, "g", self.g, "m/s^2", "gravity; waves need it")
        beta = _finite(own, "direction", self.direction, "deg", "the heading, from +x towards +y", positive=False)
        ramp = _finite(own, "ramp", self.ramp, "s", "the fade-in time; 0 for none", positive=False)
        if ramp < 0:
            raise InputError(f"{own}: ramp = {self.ramp!r} s; give a fade-in time >= 0 s (0: none)")
        for name, v in (("H", H), ("T", T), ("depth", d), ("g", g), ("direction", beta), ("ramp", ramp)):
            object.__setattr__(self, name, v)
        try:
            sea = RegularWave(H, T, d, direction=beta, ramp=ramp, source=self.source, g=g)
        except SeaError as e:
            raise InputError(f"{own}: {e.problem}") from None
        object.__setattr__(self, "sea", sea)
        object.__setattr__(self, "k", sea.k)

    @property
    def omega(self) -> float:
        """Angular frequency ω = 2π/T [rad/s]."""
        return self.sea.omega

    @property
    def wavelength(self) -> float:
        """λ = 2π/k [m]."""
        return self.sea.wavelength

    @property
    def group_velocity(self) -> float:
        """c_g [m/s] (Dean & Dalrymple 1991 eq. 4.79)."""
        return self.sea.group_velocity

    @property
    def heading(self) -> np.ndarray:
        """Unit vector of propagation, (cos β, sin β, 0)."""
        return self.sea.heading

    def elevation(self, p, t: float) -> np.ndarray:
        """η [m] above the still water at the horizontal positions of points ``p`` [m]
        (``(..., 2)`` or ``(..., 3)``: x, y first) at time ``t`` [s]."""
        p = np.asarray(p, float)
        return self.sea.elevation(p[..., 0], p[..., 1], t)

    def kinematics(self, p, t: float, level: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
        """Water velocity [m/s] and acceleration ∂u/∂t [m/s^2] at points ``p`` [m]
        (``(n, 3)``, world frame, z up), the still water at ``level`` [m]."""
        p = np.asarray(p, float)
        return self.sea.kinematics(p[:, 0], p[:, 1], p[:, 2] - level, t)


class AnalyticFluid:
    """Hydrostatics plus damping and added mass for the bodies of a scene.

    Parameters
    ----------
    rho:
        Water density [kg/m^3].
    g:
        Gravity [m/s^2] (downwards, −z).
    free_surface_z:
        Height of the flat free surface [m].
    linear_damping, quadratic_damping:
        Per body name, 6 coefficients in world axes: 3 translational
        [N s/m | N s^2/m^2] then 3 rotational [N m s | N m s^2], applied at full
        submergence and scaled by the submerged fraction.
    added_mass:
        Per body name, one value per degree of freedom of its joints (see
        ``bodies.MujocoBodies.add_armature``) [kg, kg m^2].
    cells:
        Lattice cells along the longest axis of each geom (accuracy of the
        centre of buoyancy; volumes are exact for submerged geoms).
    waves:
        A sea of :mod:`fluid.waves` (its ``level`` the ``free_surface_z``) or a
        :class:`LinearWave` (None: still water): the free surface is
        ``free_surface_z + η`` over each cell, and the wave's kinematics load the
        bodies (Froude–Krylov and added-mass inertia, drag on the relative velocity;
        see the module docstring). The diffraction term uses each body's
        translational ``added_mass``: of 6 values (a free joint) the first 3, along
        x, y, z; of 3 values, the first two, along x and z (the planar joints slide
        x, slide z, hinge y of a 2-D body, as ``bodies.builders`` makes them); a
        body with other joints gets the Froude–Krylov part only.
    """

    #: its loads do not react to body acceleration (added mass goes into the bodies'
    #: inertia instead), so explicit coupling needs no light-body remedy
    #: (``cosim.added_mass``)
    loads_carry_added_mass = False

    def __init__(self, *, rho: float = 1000.0, g: float = 9.81, free_surface_z: float = 0.0,
                 linear_damping: Mapping[str, Sequence[float]] | None = None,
                 quadratic_damping: Mapping[str, Sequence[float]] | None = None,
                 added_mass: Mapping[str, Sequence[float]] | None = None, cells: int = 24,
                 waves: LinearWave | None = None, name: str = "fluid"):
        for label, v in (("rho", rho), ("g", g)):
            if not (math.isfinite(v) and v > 0):
                raise InputError(f"analytic fluid: {label} must be finite and > 0, got {v!r}")
        if not math.isfinite(free_surface_z):
            raise InputError(f"analytic fluid: free_surface_z must be finite, got {free_surface_z!r}")
        if int(cells) < 2:
            raise InputError(f"analytic fluid: cells must be at least 2, got {cells!r}")
        if waves is not None and not isinstance(waves, (LinearWave, Sea)):
            raise InputError(f"analytic fluid: waves must be a sea of fluid.waves or a fluid.analytic.LinearWave, "
                             f"got {type(waves).__name__}")
        if waves is not None and not math.isclose(waves.g, g, rel_tol=1e-12):
            raise InputError(f"analytic fluid: the wave's gravity g = {waves.g!r} m/s^2 differs from the fluid's "
                             f"{g!r} m/s^2; give both the same")
        if isinstance(waves, Sea) and not math.isclose(waves.level, free_surface_z, rel_tol=1e-12, abs_tol=1e-12):
            raise InputError(f"analytic fluid: the sea's still level {waves.level!r} m differs from free_surface_z = "
                             f"{free_surface_z!r} m; give both the same")
        self.waves = waves  #: as given
        #: the incident sea (fluid.waves' interface), its still water at free_surface_z
        self.sea = (dataclasses.replace(waves.sea, level=float(free_surface_z)) if isinstance(waves, LinearWave)
                    else waves)
        self.rho, self.g, self.eta = float(rho), float(g), float(free_surface_z)
        self.name = name
        self.cells = int(cells)
        self._coeffs = {"linear_damping": dict(linear_damping or {}),
                        "quadratic_damping": dict(quadratic_damping or {}), "added_mass": dict(added_mass or {})}
        self.t = 0.0
        self._kin = None
        self._dirty = False  # the loads are computed when asked for, for the last kinematics and time
        self._vsub = np.zeros(0)
        self.dt_limit = "none"  #: the condition that set max_dt()

    # -- coupling --------------------------------------------------------------
    def attach_bodies(self, bodies) -> None:
        """Take the geometry of the coupled bodies and move the added mass into
        their inertia. Called once by the coupler."""
        names = list(bodies.body_names)
        for key, table in self._coeffs.items():
            unknown = sorted(set(table) - set(names))
            if unknown:
                raise InputError(f"analytic fluid: {key} given for unknown bodies {unknown}; bodies: {names}")
        pts, w, axes, owner = [], [], [], []
        for i, shapes in enumerate(bodies.geoms()):
            if not shapes:
                raise InputError(f"analytic fluid: body '{names[i]}' has no solid geom to float")
            for g in shapes:
                p, vol, cell = _unit_cells(g.kind, np.asarray(g.size, float), self.cells)
                pts.append(g.pos + p @ g.rot.T)  # body frame
                w.append(np.full(len(p), vol / len(p)))
                axes.append(np.broadcast_to(g.rot * cell[None, :], (len(p), 3, 3)))  # cell edges, body frame
                owner.append(np.full(len(p), i))
        # a bound on the waterplane area at any pose: the central section of each
        # geom's bounding sphere (the stable step must hold when the body crosses
        # the surface, not only where it is now)
        self._waterplane_bound = np.zeros(len(names))
        for i, shapes in enumerate(bodies.geoms()):
            for g in shapes:
                self._waterplane_bound[i] += math.pi * _bounding_radius(g.kind, np.asarray(g.size, float)) ** 2
        self._pts, self._w = np.concatenate(pts), np.concatenate(w)
        self._cell_axes, self._owner = np.concatenate(axes), np.concatenate(owner)
        self.n_bodies = len(names)
        self.volume = np.bincount(self._owner, self._w, minlength=self.n_bodies)
        self._membership = np.zeros((self.n_bodies, len(self._owner)))  # 1 where a cell belongs to a body
        self._membership[self._owner, np.arange(len(self._owner))] = 1.0
        edges = np.searchsorted(self._owner, np.arange(self.n_bodies + 1))  # each body's cells are contiguous
        self._cells_of = [slice(a, b) for a, b in zip(edges[:-1], edges[1:])]
        self._lin = np.zeros((self.n_bodies, 6))
        self._quad = np.zeros((self.n_bodies, 6))
        for table, arr in ((self._coeffs["linear_damping"], self._lin), (self._coeffs["quadratic_damping"], self._quad)):
            for body, c in table.items():
                c = np.asarray(c, dtype=float)
                if c.shape != (6,) or (c < 0).any() or not np.isfinite(c).all():
                    raise InputError(f"analytic fluid: damping of body '{body}' takes 6 finite values >= 0, got {c}")
                arr[names.index(body)] = c
        self._ma = np.zeros((self.n_bodies, 3))  # translational added mass along the world axes [kg]
        for body, ma in self._coeffs["added_mass"].items():
            bodies.add_armature(names.index(body), ma)
            ma = np.asarray(ma, dtype=float)
            if ma.shape == (6,):  # a free joint: x, y, z, then rotations
                self._ma[names.index(body)] = ma[:3]
            elif ma.shape == (3,):  # the planar joints of a 2-D body: slide x, slide z, hinge y
                self._ma[names.index(body)] = (ma[0], 0.0, ma[1])
        self._mass = bodies.masses()
        inertias = getattr(bodies, "inertias", None)  # the smallest principal moment [kg m^2], for the rotations' damping
        self._inertia = inertias().min(axis=1) if callable(inertias) else np.full(self.n_bodies, np.inf)
        self._vrel = np.zeros((self.n_bodies, 3))

    def set_body_kinematics(self, kin) -> None:
        """New body kinematics; the loads are for them (at the fluid's time)."""
        self._kin = kin
        self._dirty = True

    def set_time(self, t: float) -> None:
        """Take the loads at time ``t`` [s] for the kinematics last given (the coupler's
        predictor asks for the loads at the end of its step; only waves depend on it)."""
        self.t = float(t)
        self._dirty = self._dirty or self.sea is not None

    @property
    def submerged_volume(self) -> np.ndarray:
        """Submerged volume of each body [m^3], for the last kinematics and time."""
        self._refresh()
        return self._vsub

    def _refresh(self) -> None:
        if self._dirty and self._kin is not None:
            self._update()
            self._dirty = False

    def _per_body(self, values: np.ndarray) -> np.ndarray:
        """Sums of per-cell rows ``(n_cells, 3)`` over each body, ``(n_bodies, 3)``."""
        return self._membership @ values

    def _update(self) -> None:
        kin = self._kin
        p_w, height = np.empty_like(self._pts), np.empty(len(self._pts))
        for b, cells in enumerate(self._cells_of):  # a rigid motion per body
            R = kin.rotation[b]
            p_w[cells] = kin.origin[b] + self._pts[cells] @ R.T
            height[cells] = np.abs(np.einsum("j,njk->nk", R[2], self._cell_axes[cells])).sum(axis=1)  # vertical
        sea = self.sea
        if sea is None:
            surface = self.eta
        else:
            eta, u, a = sea.surface_and_kinematics(p_w[:, 0], p_w[:, 1], p_w[:, 2], self.t)
            surface = self.eta + eta
        frac = np.clip((surface - p_w[:, 2]) / height + 0.5, 0.0, 1.0)  # exact for cells level with the surface
        wv = self._w * frac
        vsub = np.bincount(self._owner, wv, minlength=self.n_bodies)
        moment = self._per_body(wv[:, None] * p_w)
        centre = np.divide(moment, vsub[:, None], out=kin.com.copy(), where=vsub[:, None] > 0)
        F = np.zeros((self.n_bodies, 3))
        F[:, 2] = self.rho * self.g * vsub
        T = cross(centre - kin.com, F)
        v_rel = kin.velocity
        if sea is not None:
            f_fk = self.rho * wv[:, None] * a  # Froude–Krylov inertia of each cell [N]
            F += self._per_body(f_fk)
            T += self._per_body(cross(p_w - kin.com[self._owner], f_fk))
            inside = vsub[:, None] > 0
            u_mean = np.divide(self._per_body(wv[:, None] * u), vsub[:, None], out=np.zeros((self.n_bodies, 3)),
                               where=inside)
            a_mean = np.divide(self._per_body(wv[:, None] * a), vsub[:, None], out=np.zeros((self.n_bodies, 3)),
                               where=inside)
            f_am = self._ma * a_mean  # diffraction: the added mass times the water's acceleration, at the centre
            F += f_am  #                of buoyancy
            T += cross(centre - kin.com, f_am)
            v_rel = kin.velocity - u_mean
        s = (vsub / self.volume)[:, None]
        F -= s * (self._lin[:, :3] * v_rel + self._quad[:, :3] * np.abs(v_rel) * v_rel)
        T -= s * (self._lin[:, 3:] * kin.omega + self._quad[:, 3:] * np.abs(kin.omega) * kin.omega)
        self._vsub = vsub
        self._vrel = v_rel
        self._wrench = (F, T)

    def body_wrenches(self):
        """Force [N] and torque about the centre of mass [N m] on each body, world
        frame, for the kinematics last given, at the fluid's time."""
        self._refresh()
        return self._wrench

    # -- participant protocol --------------------------------------------------
    def initialize(self, t0: float) -> None:
        if self._kin is None:
            raise InputError("analytic fluid: no bodies attached; add it to a Coupler with bodies=")
        self.t = t0

    def max_dt(self) -> float:
        """The stable step of loads held over a coupling step. Damping needs
        dt < m / B (taken with a factor 2 margin; a rotational coefficient, dt < I / B with I
        the body's smallest principal moment of inertia) and the hydrostatic spring
        k = ρ g A_wp at least 50 steps per heave period 2π sqrt(m / k) (held loads
        lengthen the period by ~1 % at 20 steps, ~0.2 % at 50); with waves, at least
        50 steps per shortest wave period in the sea. The first two use bounds
        valid at any pose (full submergence, the largest waterplane), since a body
        out of or under the water now may cross the surface within the step.
        :attr:`dt_limit` says which one limits."""
        if self._kin is None:
            return math.inf
        self._refresh()
        B = self._lin[:, :3] + self._quad[:, :3] * np.abs(self._vrel)
        with np.errstate(divide="ignore", over="ignore"):  # a vanishing coefficient: no bound
            dt_damp = np.min(np.where(B > 0, self._mass[:, None] / B, math.inf))
            B_rot = self._lin[:, 3:]
            dt_damp = min(dt_damp, np.min(np.where(B_rot > 0, self._inertia[:, None] / B_rot, math.inf)))
            k = self.rho * self.g * self._waterplane_bound
            dt_hydro = np.min(0.02 * 2.0 * math.pi * np.sqrt(self._mass / k))
        limits = {"damping": dt_damp, "hydrostatic stiffness": dt_hydro}
        if self.sea is not None:
            limits["wave period"] = 0.02 * self.sea.shortest_period
        self.dt_limit = min(limits, key=limits.get)
        return float(limits[self.dt_limit])

    def advance(self, t: float, dt: float) -> None:
        self.set_time(t + dt)

    def save_state(self):
        return self.t

    def load_state(self, state) -> None:
        self.set_time(state)
