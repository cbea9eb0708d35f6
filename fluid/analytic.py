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
  inertia without weight), which keeps explicit coupling stable for light bodies.

No waves, no radiation memory: this is the speed end of the speed/accuracy trade.
"""

from __future__ import annotations

import math
from typing import Mapping, Sequence

import numpy as np

from bodies.sampling import half_extents, mesh_volume, signed_distance
from cosim.errors import InputError


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
    """

    #: its loads do not react to body acceleration (added mass goes into the bodies'
    #: inertia instead), so explicit coupling needs no light-body remedy
    #: (``cosim.added_mass``)
    loads_carry_added_mass = False

    def __init__(self, *, rho: float = 1000.0, g: float = 9.81, free_surface_z: float = 0.0,
                 linear_damping: Mapping[str, Sequence[float]] | None = None,
                 quadratic_damping: Mapping[str, Sequence[float]] | None = None,
                 added_mass: Mapping[str, Sequence[float]] | None = None, cells: int = 24,
                 name: str = "fluid"):
        for label, v in (("rho", rho), ("g", g)):
            if not (math.isfinite(v) and v > 0):
                raise InputError(f"analytic fluid: {label} must be finite and > 0, got {v!r}")
        if not math.isfinite(free_surface_z):
            raise InputError(f"analytic fluid: free_surface_z must be finite, got {free_surface_z!r}")
        if int(cells) < 2:
            raise InputError(f"analytic fluid: cells must be at least 2, got {cells!r}")
        self.rho, self.g, self.eta = float(rho), float(g), float(free_surface_z)
        self.name = name
        self.cells = int(cells)
        self._coeffs = {"linear_damping": dict(linear_damping or {}),
                        "quadratic_damping": dict(quadratic_damping or {}), "added_mass": dict(added_mass or {})}
        self.t = 0.0
        self._kin = None
        self.submerged_volume = np.zeros(0)  #: per body [m^3], at the last kinematics
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
        self._lin = np.zeros((self.n_bodies, 6))
        self._quad = np.zeros((self.n_bodies, 6))
        for table, arr in ((self._coeffs["linear_damping"], self._lin), (self._coeffs["quadratic_damping"], self._quad)):
            for body, c in table.items():
                c = np.asarray(c, dtype=float)
                if c.shape != (6,) or (c < 0).any() or not np.isfinite(c).all():
                    raise InputError(f"analytic fluid: damping of body '{body}' takes 6 finite values >= 0, got {c}")
                arr[names.index(body)] = c
        for body, ma in self._coeffs["added_mass"].items():
            bodies.add_armature(names.index(body), ma)
        self._mass = bodies.masses()

    def set_body_kinematics(self, kin) -> None:
        """New body kinematics; the loads for them are computed here."""
        self._kin = kin
        R = kin.rotation[self._owner]
        p_w = kin.origin[self._owner] + np.einsum("nij,nj->ni", R, self._pts)
        height = np.abs(np.einsum("nj,njk->nk", R[:, 2, :], self._cell_axes)).sum(axis=1)  # vertical cell extent
        frac = np.clip((self.eta - p_w[:, 2]) / height + 0.5, 0.0, 1.0)  # exact for cells level with the surface
        wv = self._w * frac
        vsub = np.bincount(self._owner, wv, minlength=self.n_bodies)
        moment = np.stack([np.bincount(self._owner, wv * p_w[:, k], minlength=self.n_bodies) for k in range(3)], 1)
        centre = np.divide(moment, vsub[:, None], out=kin.com.copy(), where=vsub[:, None] > 0)
        F = np.zeros((self.n_bodies, 3))
        F[:, 2] = self.rho * self.g * vsub
        T = np.cross(centre - kin.com, F)
        s = (vsub / self.volume)[:, None]
        F -= s * (self._lin[:, :3] * kin.velocity + self._quad[:, :3] * np.abs(kin.velocity) * kin.velocity)
        T -= s * (self._lin[:, 3:] * kin.omega + self._quad[:, 3:] * np.abs(kin.omega) * kin.omega)
        self.submerged_volume = vsub
        self._wrench = (F, T)

    def body_wrenches(self):
        """Force [N] and torque about the centre of mass [N m] on each body, world
        frame, for the kinematics last given."""
        return self._wrench

    # -- participant protocol --------------------------------------------------
    def initialize(self, t0: float) -> None:
        if self._kin is None:
            raise InputError("analytic fluid: no bodies attached; add it to a Coupler with bodies=")
        self.t = t0

    def max_dt(self) -> float:
        """The stable step of loads held over a coupling step. Damping needs
        dt < m / B (taken with a factor 2 margin) and the hydrostatic spring
        k = ρ g A_wp at least 50 steps per heave period 2π sqrt(m / k) (held loads
        lengthen the period by ~1 % at 20 steps, ~0.2 % at 50). Both use bounds
        valid at any pose (full submergence, the largest waterplane), since a body
        out of or under the water now may cross the surface within the step.
        :attr:`dt_limit` says which one limits."""
        if self._kin is None:
            return math.inf
        B = self._lin[:, :3] + self._quad[:, :3] * np.abs(self._kin.velocity)
        with np.errstate(divide="ignore"):
            dt_damp = np.min(np.where(B > 0, self._mass[:, None] / B, math.inf))
            k = self.rho * self.g * self._waterplane_bound
            dt_hydro = np.min(0.02 * 2.0 * math.pi * np.sqrt(self._mass / k))
        self.dt_limit = "damping" if dt_damp < dt_hydro else "hydrostatic stiffness"
        return float(min(dt_damp, dt_hydro))

    def advance(self, t: float, dt: float) -> None:
        self.t = t + dt

    def save_state(self):
        return self.t

    def load_state(self, state) -> None:
        self.t = state
