"""A module acting as another package that plugs into cosim's scenes
(:mod:`cosim.scene.registry`): a mooring model of weightless elastic tethers, a capsule body
shape, a probe of the tethers' elastic energy and a fluid that only drags. Its
``pyproject.toml`` would declare them as

    [project.entry-points."cosim.moorings"]
    tether = "plugin_example:Tether"

    [project.entry-points."cosim.shapes"]
    capsule = "plugin_example:Capsule"

    [project.entry-points."cosim.probes"]
    tether_energy = "plugin_example:TetherEnergy"

    [project.entry-points."cosim.fluids"]
    drag = "plugin_example:Drag"

and ``tests/test_registry.py`` registers them both ways: by hand, with the call an entry
point makes, and through faked entry points."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from cosim.scene.fields import SceneError, Spec, choice, num, required, table, text, vec
from cosim.scene.mooring_models import MooringModel
from cosim.scene.probes import Group, Probe
from cosim.scene.shapes import RigidBody
from cosim.scene.spec import tag


class TetherMooring:
    """Weightless elastic tethers, a :class:`cosim.protocol.Mooring`: each line pulls its
    fairlead towards its anchor with the tension of a linear elastic rod, ``T = (EA / L)
    (s - L)`` for a span ``s`` longer than its length ``L``, none when slack (Hooke's law,
    ``T = EA strain``). Quasi-static: its force is a function of the fairleads' positions."""

    dynamic = False

    def __init__(self, lines, name: str = "tethers"):
        self.name, self.lines = name, list(lines)
        self.n_lines, self.dim = len(self.lines), len(self.lines[0].anchor)
        self.anchors = np.array([ln.anchor for ln in self.lines], float)
        self.L = np.array([ln.length for ln in self.lines], float)
        self.k = np.array([ln.EA / ln.length for ln in self.lines], float)
        self._pos = None

    def initialize(self, t0: float) -> None:
        if self._pos is None:
            raise ValueError(f"mooring '{self.name}': give the fairlead positions before the run")

    def max_dt(self) -> float:
        return math.inf

    def advance(self, t: float, dt: float) -> None:
        pass

    def save_state(self):
        return {"pos": self._pos.copy()}

    def load_state(self, state) -> None:
        self._pos = np.array(state["pos"], float)

    def set_fairlead_motion(self, positions, velocities=None) -> None:
        self._pos = np.array(positions, float)

    def fairlead_forces(self) -> np.ndarray:
        d = self.anchors - self._pos
        s = np.linalg.norm(d, axis=1)
        T = self.k * np.maximum(s - self.L, 0.0)
        return (T / s)[:, None] * d


class Tether(MooringModel):
    """The scene's side of :class:`TetherMooring`: every line needs ``EA``."""

    line_fields = ("EA",)

    def from_scene(self, scene, lines, *, level, rho, workdir):
        return TetherMooring(lines)


@dataclass(frozen=True)
class Capsule(RigidBody):
    """A capsule (3-D): a cylinder of ``radius`` [m] and ``length`` [m] along z capped by two
    half spheres. Its volume, submerged volume, turned extent and the rest follow from
    :meth:`half_size` and :meth:`signed_distance` (the defaults of
    :class:`cosim.scene.shapes.Shape`); MuJoCo's capsule geom (which the SPH fluid samples and
    the analytic fluid integrates)."""

    TAG = ("shape", "capsule")
    shape: str = tag("capsule")
    name: str = required(text(None, "the body's name", name=True))
    radius: float = required(num(None, "radius", "m", lo=0, lo_open=True, optional=False))
    length: float = required(num(None, "length of the cylinder between the caps", "m", lo=0, optional=False))
    pos: tuple = required(vec(None, "centre position", "m", sizes=(2, 3)))
    density: float = num(None, "density (or give mass)", "kg/m^3", lo=0, lo_open=True)
    mass: float = num(None, "mass (or give density)", "kg", lo=0, lo_open=True)
    place: str = choice("given", "given: at pos; floating: at its hydrostatic equilibrium", ("given", "floating"))
    euler: tuple = vec(None, "initial orientation (Euler angles)", "deg", sizes=(3,))
    fairleads: dict = table("named points in the body frame", "m")

    geom = "capsule"

    def half_size(self, dim):
        return [self.radius, self.radius, 0.5 * self.length + self.radius]

    def signed_distance(self, p, dim):
        z = np.clip(p[:, 2], -0.5 * self.length, 0.5 * self.length)
        return np.linalg.norm(p - np.column_stack([0 * z, 0 * z, z]), axis=1) - self.radius

    def fit(self, dim):
        if dim != 3:
            raise SceneError("shape", "a capsule is 3-D")

    def mjcf(self, pos, dim, sites):
        mass = f'density="{self.density!r}"' if self.mass is None else f'mass="{self.mass!r}"'
        turn = "" if self.euler is None else f' euler="{" ".join(map(repr, self.euler))}"'
        xml_sites = "".join(f'<site name="{k}" pos="{" ".join(map(repr, p))}" size="0.01"/>' for k, p in sites.items())
        return (f'<body name="{self.name}" pos="{" ".join(map(repr, pos))}"{turn}><freejoint name="{self.name}_free"/>'
                f'<geom name="{self.name}_geom" type="capsule" size="{self.radius!r} {0.5 * self.length!r}" {mass}/>'
                f'{xml_sites}</body>')


class TetherEnergy(Probe):
    """The elastic energy [J] the tethers hold, ``sum (EA / 2 L) (s - L)^2`` over the taut
    ones, as one series ``tethers.energy``."""

    def names(self, scene):
        return ["tethers.energy"] if scene.moorings is not None and scene.moorings.model == "tether" else []

    def groups(self, scene, built):
        if not self.names(scene):
            return []
        m = built.mooring

        def energy():
            stretch = np.maximum(np.linalg.norm(m.anchors - m._pos, axis=1) - m.L, 0.0)
            return np.array([float(np.sum(0.5 * m.k * stretch ** 2))])

        return [Group("tether_energy", ["tethers.energy"], ["J"], energy)]


class DragFluid:
    """A fluid that only resists motion, a :class:`cosim.protocol.Fluid`: the force
    ``-c V`` [N] on each body moving at ``V`` [m/s], no torque (linear, Stokes-like drag)."""

    name = "drag"
    loads_carry_added_mass = False  # no added mass in these loads: no light-body remedy

    def __init__(self, c: float):
        self.c, self._v = c, None

    def initialize(self, t0: float) -> None:
        pass

    def max_dt(self) -> float:
        return math.inf

    def advance(self, t: float, dt: float) -> None:
        pass

    def save_state(self):
        return {}

    def load_state(self, state) -> None:
        pass

    def attach_bodies(self, bodies) -> None:
        self._v = np.zeros((bodies.n_bodies, 3))

    def set_body_kinematics(self, kinematics) -> None:
        self._v = np.array(kinematics.velocity, float)

    def body_wrenches(self):
        return -self.c * self._v, np.zeros_like(self._v)


@dataclass(frozen=True)
class Drag(Spec):
    """A fluid that only drags: each body feels ``-c V``."""

    TAG = ("model", "drag")
    model: str = tag("drag")
    c: float = required(num(None, "linear drag coefficient", "N s/m", lo=0, lo_open=True, optional=False))

    def participant(self, scene, built) -> None:
        built.fluid = DragFluid(self.c)

