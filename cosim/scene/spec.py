"""The scene: one description of a coupled run, as frozen dataclasses validated on
construction. Every default is here, with its unit; :mod:`cosim.scene.toml_io` reads and
writes the same fields as TOML, key for key.

A scene is made of

- :class:`World`: dimension (2: the x-z plane, 1 m thick; 3), gravity (one value for every
  participant), duration, sampling, snapshot, checkpoint and plot times;
- a fluid: :class:`NoFluid`, :class:`Analytic` (hydrostatics and damping), :class:`Potential`
  (linear potential flow, coefficients from a boundary-element solver) or :class:`SPH`
  (spacing ``dx``; its set-up chosen from the scene, :mod:`cosim.scene.setup`, each
  setting overridable);
- a domain for the SPH fluid: :class:`Tank` (filled to a depth, or holding water blocks),
  :class:`Flume` (2-D or 3-D, with a :class:`Beach`; the analytic fluid takes a flume's
  depth and wavemaker too), :class:`InclinedTank`, :class:`CylinderTank`
  (3-D), :class:`PolygonTank` (2-D), :class:`ArchRib` (2-D, Wang et al. 2022); wall layers
  follow from the kernel;
- excitations: ``waves`` (:class:`Piston`, :class:`Flap`, :class:`PaddleRecord`: a flume's
  wavemaker; :class:`LinearWaves`, :class:`RegularWaves`, :class:`IrregularWaves`: the
  incident sea on the analytic fluid's bodies, :mod:`fluid.waves`) or
  ``base_motion`` of a tank (:class:`Shake`, :class:`Roll`, :class:`RollTable`,
  :class:`TableMotion`, :class:`Earthquake`, :class:`GroundMotion`);
- ``bodies`` (:class:`Box`, :class:`Cylinder`, :class:`Sphere`, :class:`MJCF`), placed at a
  given pose or ``place="floating"`` (at the hydrostatic equilibrium, computed);
- :class:`Moorings`: :class:`Line` records and the one field ``model`` that picks the
  mooring model;
- :class:`Probes`: wave gauges, wall-pressure patches, body motion, tensions, loads, energy;
- :class:`Coupling`: scheme and light-body remedy (``"auto"``: chosen to fit the fluid).

Coordinates: 2-D scenes give points as (x, z), 3-D as (x, y, z) [m], z up, gravity -z (or the
vector ``world.gravity`` gives).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from pathlib import Path

from cosim.scene import limits as L
from cosim.scene import seas, shapes
from cosim.scene.fields import (SceneError, Spec, choice, flag, gauges, is_name, mirror_settings, names, num, part,
                                parts, required, num_or_vec, table, text, vec, vecs, whole)
from cosim.scene.registry import FLUIDS as FLUID_MODELS, MOORINGS, SHAPES, WAVES as WAVE_KINDS
from fluid.settings import SETTINGS as FLUID_SETTINGS

SETUPS = ("auto", "still", "waves", "sloshing", "impulsive", "impact", "defaults")


def tag(value: str):
    """The field that tells a class apart among the others of its place (not an argument)."""
    return dataclasses.field(default=value, init=False)


# ------------------------------------------------------------------------ world
@dataclass(frozen=True)
class World(Spec):
    """What every participant shares, and when things are written. ``gravity`` is one value
    for every participant: a number [m/s^2] along -z (kept as given), or a vector; a vector
    along -z is kept as its length (a number), so ``gravity`` is a number wherever gravity
    acts along -z and a vector only where it is tilted (:attr:`tilted`). :attr:`g`,
    :attr:`g_vector` and :attr:`g_down` read it either way."""

    dim: int = whole(2, "2: the x-z plane (bodies 1 m thick), 3: space", lo=2, hi=3)
    duration: float = num(1.0, "simulated time", "s", lo=0, lo_open=True)
    gravity: float | tuple = num_or_vec(9.81, "acceleration of gravity, for every participant: a number acts along -z; a "
                                "vector (2-D: (gx, gz), 3-D: (gx, gy, gz)) in any direction", "m/s^2",
                                hi=L.MAX_GRAVITY, why=L.GRAVITY_WHY)
    sample_every: float = num(0.01, "interval between probe samples", "s", lo=0, lo_open=True)
    snapshot_every: float = num(0.1, "interval between particle snapshots in run.h5; 0: none", "s", lo=0)
    checkpoint_every: float = num(0.0, "simulated time between checkpoints for --resume, landed on exactly; 0: by "
                                  "wall time only", "s", lo=0)
    checkpoint_wall: float = num(120.0, "wall-clock time between checkpoints for --resume, stretched where writing one "
                                 "takes over 2 % of it; 0: none by wall time; 0 here and in checkpoint_every: no "
                                 "checkpoints", "s", lo=0)
    plot_at: tuple = vecs("times of the particle plots (PNG); those beyond the duration are not drawn (the run "
                          "says so)", "s", sizes=(0,))
    plot_color: str = choice("velocity", "what colours the particle plots", ("velocity", "pressure"))

    def validate(self):
        g = self.gravity
        if isinstance(g, tuple):
            if len(g) != self.dim:
                raise SceneError("gravity", f"{list(g)} has {len(g)} components; a {self.dim}-D scene's gravity is "
                                 f"{'(gx, gz)' if self.dim == 2 else '(gx, gy, gz)'} [m/s^2], or a number along -z")
            if all(x == 0.0 for x in g[:-1]) and g[-1] <= 0.0:  # along -z: the number it has always been
                object.__setattr__(self, "gravity", -g[-1] + 0.0)
        for i, t in enumerate(self.plot_at):
            if t < 0:
                raise SceneError(f"plot_at[{i}]", f"{t} s lies before the run's start (0 s); give a time >= 0")
        if self.sample_every > self.duration:
            raise SceneError("sample_every", f"{self.sample_every} s is longer than the run ({self.duration} s)")

    @property
    def g_vector(self) -> tuple:
        """Gravity [m/s^2] as (x, y, z) world components (2-D: y = 0)."""
        g = self.gravity
        if not isinstance(g, tuple):
            return (0.0, 0.0, -g)
        return (g[0], 0.0, g[1]) if len(g) == 2 else tuple(g)

    @property
    def g(self) -> float:
        """Gravity's magnitude [m/s^2]."""
        return math.sqrt(sum(x * x for x in self.g_vector))

    @property
    def g_down(self) -> float:
        """Gravity's component along -z [m/s^2] (what presses water on the floor)."""
        return -self.g_vector[2] + 0.0

    @property
    def tilted(self) -> bool:
        """Whether gravity acts in another direction than -z."""
        return isinstance(self.gravity, tuple)

    @property
    def tilt_deg(self) -> float:
        """The angle [deg] between gravity and -z."""
        return math.degrees(math.atan2(math.hypot(*self.g_vector[:2]), -self.g_vector[2])) if self.g > 0 else 0.0


# ------------------------------------------------------------------------ fluids
@dataclass(frozen=True)
class NoFluid(Spec):
    """No fluid: bodies, moorings and gravity only."""

    TAG = ("model", "none")
    model: str = tag("none")

    def participant(self, scene, built) -> None:
        """No fluid participant."""


@dataclass(frozen=True)
class Analytic(Spec):
    """The analytic fluid (``fluid.analytic.AnalyticFluid``): hydrostatics of the
    submerged volume under the free surface at ``level`` (moved by ``waves`` of kind
    ``"linear"``, ``"regular"`` or ``"irregular"``, where the scene has them), plus damping per body (6
    coefficients each, world axes: 3 translational, then 3 rotational) and added mass per
    degree of freedom (moved into the body's inertia)."""

    TAG = ("model", "analytic")
    model: str = tag("analytic")
    rho: float = num(1000.0, "water density", "kg/m^3", lo=0, lo_open=True, hi=L.MAX_DENSITY, why=L.DENSITY_WHY)
    level: float = num(0.0, "height of the still free surface", "m")
    linear_damping: dict = table("per body: 6 linear damping coefficients [N s/m, N m s]", sizes=(6,))
    quadratic_damping: dict = table("per body: 6 quadratic damping coefficients [N s^2/m^2, N m s^2]", sizes=(6,))
    added_mass: dict = table("per body: one added mass per degree of freedom (2-D: x, z, rotation; 3-D: 3 "
                             "translations, 3 rotations) [kg, kg m^2]", sizes=(3, 6))

    def participant(self, scene, built) -> None:
        """The analytic fluid and the flume's wavemaker (:mod:`cosim.scene.build`)."""
        from cosim.scene.build import analytic_fluid

        analytic_fluid(scene, built)


@dataclass(frozen=True)
class Potential(Spec):
    """Linear potential flow (``fluid.potential.PotentialFluid``, 3-D): each body's added
    mass, damping and excitation from the boundary-element solver Capytaine on its wetted
    hull at its floating pose (cached), run in time by the Cummins equation, with linear
    hydrostatics and optional quadratic drag per body (6 coefficients, world axes). Needs
    ``pip install cosim-sph[potential]``. Waves: ``kind = "linear"``, or a flume's piston or
    flap (its far-field wave); the depth is the flume's or the waves' (deep water without
    either, unless ``depth`` says)."""

    TAG = ("model", "potential")
    model: str = tag("potential")
    rho: float = num(1000.0, "water density", "kg/m^3", lo=0, lo_open=True, hi=L.MAX_DENSITY, why=L.DENSITY_WHY)
    level: float = num(0.0, "height of the still free surface", "m")
    depth: float = num(None, "water depth under the still surface (unset: the flume's or the waves' depth, else "
                       "deep water)", "m", lo=0, lo_open=True)
    panel_size: float = num(None, "panel size of the hulls (unset: a tenth of each body's smallest horizontal "
                            "dimension)", "m", lo=0, lo_open=True)
    omega_max: float = num(None, "highest BEM frequency (unset: 6 panels per deep-water wavelength)", "rad/s", lo=0,
                           lo_open=True)
    frequencies: int = whole(None, "BEM frequencies, evenly spaced to omega_max from omega_max / frequencies (in "
                             "shallow water from where Capytaine solves, k d = 0.15); unset: 40, or with interaction "
                             "as many as the cross memory needs (the lone bodies' memory plus the travel between the "
                             "bodies at omega_max's group velocity)", lo=4)
    memory: float = num(None, "radiation memory (unset: where the impulse response has decayed)", "s", lo=0,
                        lo_open=True)
    quadratic_drag: dict = table("per body: 6 quadratic drag coefficients [N s^2/m^2, N m s^2]", sizes=(6,))
    drift: bool = flag(False, "the slowly varying wave drift force in surge, sway and yaw: Newman's approximation "
                       "from each freely floating body's mean drift in the far field (needs waves)")
    interaction: bool = flag(False, "solve the bodies together: coupled radiation memory and added mass, each body's "
                             "excitation in the others' presence (one body: as alone; not with drift)")

    def participant(self, scene, built) -> None:
        """The potential fluid and the flume's wavemaker (:mod:`cosim.scene.build`)."""
        from cosim.scene.build import potential_fluid

        built.fluid, built.wavemaker = potential_fluid(scene, built.level)


@dataclass(frozen=True)
@mirror_settings(FLUID_SETTINGS, {"rho0": (L.MAX_DENSITY, L.DENSITY_WHY)})
class SPH(Spec):
    """The weakly compressible SPH fluid (``fluid.solver``). ``dx`` is the one setting
    every scene gives; the rest come from the set-up (``setup``, see
    :mod:`cosim.scene.setup`: ``"auto"`` picks it from what the scene contains) unless
    set here. Unset (None) fields take the set-up's value, then ``FluidConfig``'s. The
    fields before ``setup`` are the fluid's own settings, declared in ``fluid.settings``."""

    TAG = ("model", "sph")
    model: str = tag("sph")
    setup: str = choice("auto", "fluid set-up: auto (from the scene), still, waves, sloshing, impulsive, impact, "
                        "defaults", SETUPS)
    settle: float = num(0.0, "damped relaxation of the particles before the run (clock held at 0)", "s", lo=0)
    body_boundary: str = choice("mdbc", "density of the bodies' boundary particles", ("mdbc", "dbc"))

    def validate(self):
        if self.c0 is not None and self.u_max is not None:
            raise SceneError("c0", "give c0 or u_max, not both (c0 = c0_factor * u_max)")

    def participant(self, scene, built) -> None:
        """The SPH fluid in its domain, its set-up, wavemaker and walls' motion
        (:mod:`cosim.scene.build`)."""
        from cosim.scene.build import sph_fluid

        sph_fluid(scene, built)


FLUIDS = (NoFluid, Analytic, Potential, SPH)


# ------------------------------------------------------------------------ domains
@dataclass(frozen=True)
class Block(Spec):
    """A box of water from corner ``lo`` to corner ``hi`` [m]."""

    lo: tuple = required(vec(None, "lower corner", "m"))
    hi: tuple = required(vec(None, "upper corner", "m"))

    def validate(self):
        if len(self.lo) != len(self.hi) or not all(h > lo for lo, h in zip(self.lo, self.hi)):
            raise SceneError("hi", f"{self.hi} must exceed lo = {self.lo} in every coordinate")


@dataclass(frozen=True)
class Tank(Spec):
    """A rectangular open tank, inner corner at the origin: ``length`` along x, ``width``
    along y (3-D only), walls ``height`` high; water to ``depth`` or in ``water`` blocks
    (one or the other). ``walls``: solid blocks inside the tank, part of its walls (filled
    with wall particles on the lattice, moving with the tank): the rigid wall an elastic
    gate hangs from (Antoci et al. 2007), a baffle. Water laid to ``depth`` leaves them
    out; water blocks may not overlap them. Each is at least as thick as the tank's walls
    (their layers, the kernel's support 2h, times dx), so that the water beside it is held
    and does not feel the other side. With SPH the walls lie on the particle lattice from
    the inner corner (water laid to ``depth`` shares it), so a length (width) that is not a
    whole number of spacings is built as the nearest whole number (the build warns, naming
    the sizes that fit, and a water block given up to the far wall that then stops a
    spacing short of it)."""

    TAG = ("kind", "tank")
    kind: str = tag("tank")
    length: float = required(num(None, "inner length along x", "m", lo=0, lo_open=True, optional=False))
    height: float = required(num(None, "wall height", "m", lo=0, lo_open=True, optional=False))
    width: float = num(None, "inner width along y (3-D only)", "m", lo=0, lo_open=True)
    depth: float = num(None, "still-water depth (or give water blocks)", "m", lo=0, lo_open=True)
    water: tuple = parts("boxes of water, e.g. a dam-break column (or give depth)", Block)
    walls: tuple = parts("solid blocks inside the tank, part of its walls: the wall a gate hangs from, a baffle", Block)

    def validate(self):
        if (self.depth is None) == (not self.water):
            raise SceneError("depth", "give either depth (a tank filled to it) or water blocks, one of the two")
        if self.depth is not None and self.depth >= self.height:
            raise SceneError("depth", f"{self.depth} m must be below the wall height {self.height} m")

    @property
    def level(self):
        return self.depth


@dataclass(frozen=True)
class Beach(Spec):
    """A solid ramp rising from the bottom at ``toe`` [m] with ``slope`` (rise over run)."""

    toe: float = required(num(None, "x of the beach's toe", "m", lo=0, lo_open=True, optional=False))
    slope: float = required(num(None, "rise over run", lo=0, lo_open=True, optional=False))


@dataclass(frozen=True)
class Absorber(Spec):
    """An absorbing relaxation zone at a flume's far end: the last ``length`` [m] of water
    before the far wall, whose velocity relaxes towards rest at a rate that grows from 0 at
    its inner edge to ``rate`` [1/s] at the wall (:mod:`fluid.relaxation`: the weight of
    Jacobsen, Fuhrman & Fredsøe 2012, Eq. 5). One to two wavelengths at about two wave
    frequencies reflect a few per cent of the height (``cosim validate wave-propagation``);
    unlike a beach it adds no wall particles and keeps the flume's depth to its end. The
    SPH fluid only: the analytic and potential fluids take the flume's end as perfectly
    absorbing already."""

    length: float = required(num(None, "length of the zone before the far wall (one to two wavelengths)", "m", lo=0,
                                 lo_open=True, optional=False))
    rate: float = num(None, "relaxation rate at the far wall (unset: twice the wavemaker's angular frequency)",
                      "1/s", lo=0, lo_open=True)


@dataclass(frozen=True)
class Flume(Spec):
    """A wave flume: the paddle at x = 0, the far wall at ``length``, water ``depth``
    deep, walls ``height`` high, an optional :class:`Beach` or :class:`Absorber` (SPH); 3-D: a wave tank ``width``
    wide along y (side walls at y = 0 and ``width``, or with ``sides = "symmetry"`` two
    symmetry planes there: the side walls of a narrow slice change the waves that run along
    them, docs/fluid.md), the paddle across the whole width.
    With ``fluid.model = "analytic"`` the flume gives the still level (its depth, the
    seabed at z = 0) and its wavemaker's far-field wave (``cosim.scene.build``)."""

    TAG = ("kind", "flume")
    kind: str = tag("flume")
    length: float = required(num(None, "paddle to far wall", "m", lo=0, lo_open=True, optional=False))
    depth: float = required(num(None, "still-water depth", "m", lo=0, lo_open=True, optional=False))
    height: float = required(num(None, "wall height", "m", lo=0, lo_open=True, optional=False))
    beach: Beach = part(None, "a sloping beach that absorbs the waves", Beach)
    absorber: Absorber = part(None, "an absorbing relaxation zone before the far wall (SPH)", Absorber)
    width: float = num(None, "width along y between the side walls (3-D only)", "m", lo=0, lo_open=True)
    sides: str = choice("walls", "3-D: what bounds the flume across y: walls (slip side walls at y = 0 and width), "
                        "or symmetry (two symmetry planes there: a slice of a flume of any width for waves uniform "
                        "across it, no bodies; fluid.mirror)", ("walls", "symmetry"))

    def validate(self):
        if self.depth >= self.height:
            raise SceneError("depth", f"{self.depth} m must be below the wall height {self.height} m")
        if self.beach is not None and not self.beach.toe < self.length:
            raise SceneError("beach.toe", f"{self.beach.toe} m must lie inside the flume (< length {self.length} m)")
        if self.absorber is not None and not self.absorber.length < self.length:
            raise SceneError("absorber.length", f"{self.absorber.length} m must be shorter than the flume "
                             f"(length {self.length} m): the waves need water to travel in before it")

    @property
    def level(self):
        return self.depth


class _Filled:
    """A container filled with still water to ``depth`` [m], at most its wall ``height``."""

    def validate(self):
        if self.depth > self.height:
            raise SceneError("depth", f"{self.depth} m must not exceed the wall height {self.height} m")

    @property
    def level(self):
        return self.depth


@dataclass(frozen=True)
class InclinedTank(_Filled, Spec):
    """A tank whose right side leans outwards ``angle`` [deg] from the vertical (Sunara et al. 2021,
    §3.2), bottom ``length`` long; 3-D: ``width`` along y."""

    TAG = ("kind", "inclined-tank")
    kind: str = tag("inclined-tank")
    angle: float = required(num(None, "inclination of the right side from the vertical", "deg", lo=0, hi=90,
                                hi_open=True, optional=False))
    length: float = required(num(None, "bottom length", "m", lo=0, lo_open=True, optional=False))
    depth: float = required(num(None, "still-water depth", "m", lo=0, lo_open=True, optional=False))
    height: float = required(num(None, "wall height", "m", lo=0, lo_open=True, optional=False))
    width: float = num(None, "width along y (3-D only)", "m", lo=0, lo_open=True)


@dataclass(frozen=True)
class CylinderTank(_Filled, Spec):
    """A vertical cylindrical tank (3-D, Sunara et al. 2021, §3.3), axis along z through the origin."""

    TAG = ("kind", "cylinder-tank")
    kind: str = tag("cylinder-tank")
    diameter: float = required(num(None, "inner diameter", "m", lo=0, lo_open=True, optional=False))
    depth: float = required(num(None, "still-water depth", "m", lo=0, lo_open=True, optional=False))
    height: float = required(num(None, "wall height", "m", lo=0, lo_open=True, optional=False))


@dataclass(frozen=True)
class PolygonTank(Spec):
    """A 2-D container whose inner outline is the closed polygon ``vertices`` (x, z) [m],
    walled all round, filled to ``fill_level`` [m]."""

    TAG = ("kind", "polygon")
    kind: str = tag("polygon")
    vertices: tuple = required(vecs("the inner outline's corners (x, z)", "m", sizes=(2,), min_len=3))
    fill_level: float = required(num(None, "height of the still water", "m", optional=False))

    def validate(self):
        from fluid.shapes import signed_area

        if abs(signed_area(self.vertices)) <= 0:
            raise SceneError("vertices", "the polygon has no area; give at least 3 corners that enclose one")
        zs = [v[1] for v in self.vertices]
        if not min(zs) < self.fill_level:
            raise SceneError("fill_level", f"{self.fill_level} m is at or below the polygon's lowest point {min(zs)} m")

    @property
    def level(self):
        return self.fill_level


@dataclass(frozen=True)
class ArchRib(PolygonTank):
    """The water inside a hollow catenary arch rib, 2-D (Wang et al. 2022, §4):
    the cavity of ``fluid.shapes.arch_rib_cavity`` (the catenary axis ``z = rise - rise /
    (m - 1) (cosh(k xi) - 1)``, ``xi = 2 x / span``, ``k = arccosh m``, offset by
    ``inner_height`` / 2 on both sides), springings at x = -span/2 and +span/2, z = 0,
    walled all round, each leg filled to ``level`` above the springings. Defaults: the
    paper's rib (span 140 m, rise 23.333 m, design level 15.56 m); ``m`` and
    ``inner_height`` are not in its text (m = 2.24 and 1.458 m give its particle counts
    within 1 %, tests/test_arch_rib.py). :func:`arch_rib_monitors` places the pressure
    patches B1-B18."""

    TAG = ("kind", "arch-rib")
    kind: str = tag("arch-rib")
    # the polygon and its level, made from the fields below (not given)
    vertices: tuple = dataclasses.field(default=(), init=False, repr=False, compare=False)
    fill_level: float = dataclasses.field(default=0.0, init=False, repr=False, compare=False)
    span: float = num(140.0, "horizontal distance between the springings (the axis' ends)", "m", lo=0, lo_open=True)
    rise: float = num(23.333, "height of the axis' crown above the springings", "m", lo=0, lo_open=True)
    m: float = num(2.24, "arch-axis coefficient (1: a parabola; the paper does not give it)", lo=1)
    inner_height: float = num(1.458, "the cavity's inner height across the axis (the box section's, inside)", "m",
                              lo=0, lo_open=True)
    level: float = num(15.56, "still-water level in both legs, above the springings (Wang et al. 2022's design level)", "m")

    def validate(self):
        from cosim.errors import InputError
        from fluid.shapes import arch_rib_cavity

        top = self.rise + 0.5 * self.inner_height  # the cavity's highest point: the crown's upper face
        if self.inner_height >= self.rise:
            raise SceneError("inner_height", f"{self.inner_height} m is not below the rise {self.rise} m: the rib "
                             f"would have no legs to hold water; give an inner height well below the rise")
        if self.level <= 0:
            raise SceneError("level", f"{self.level} m is at or below the springings (z = 0): the legs would hold "
                             f"no water; give a level between 0 and the crown's inner top {top:.4g} m (below "
                             f"{self.rise - 0.5 * self.inner_height:.4g} m the legs hold separate columns)")
        if self.level >= top:
            raise SceneError("level", f"{self.level} m is at or above the crown's inner top {top:.4g} m (rise "
                             f"{self.rise} m + inner_height / 2): the water would not fit, the cavity would be full "
                             f"with no free surface; give a level below {top:.4g} m")
        try:
            v = arch_rib_cavity(self.span, self.rise, self.inner_height, self.m)
        except InputError as e:
            raise SceneError("inner_height", str(e).removeprefix("arch_rib_cavity: ")) from None
        object.__setattr__(self, "vertices", tuple((float(x), float(z)) for x, z in v))
        object.__setattr__(self, "fill_level", self.level)
        super().validate()


def arch_rib_monitors(rib: ArchRib, size: float, heights=None) -> tuple:
    """The wall-pressure patches B1-B18 of Wang et al. 2022, §4.1 on an :class:`ArchRib`, ``size`` [m]
    long. The paper places them only in its Figure 6 ("B1 to B9 on the right side of the
    arch rib, B10 to B18 on the left side, symmetrical about the y-axis", at different
    depths, on the upper and lower surfaces); our choice: Bk (k = 1..9) on the right leg
    where the axis is at z = ``heights[k-1]`` [m] (default 1.4 k m: 1.4 .. 12.6 m, under
    the depth study's lowest level 13 m), on the lower (intrados) face for odd k and the
    upper face for even k; B(9 + k) its mirror image on the left leg. Each patch's centre
    lies on the face (the axis offset by inner_height / 2 along its normal), its normal
    into the water."""
    import math

    span, rise, m, hc = rib.span, rib.rise, rib.m, rib.inner_height
    heights = [1.4 * k for k in range(1, 10)] if heights is None else list(heights)
    kk = math.acosh(m) if m > 1 else 0.0
    out = []
    for side, sign in (("right", 1.0), ("left", -1.0)):
        for i, zc in enumerate(heights):
            if not 0 < zc < rise:
                raise SceneError("heights", f"{zc} m: a monitoring point's axis height must lie between the "
                                 f"springing (0) and the crown ({rise} m)")
            # xi from z on the right leg (the axis' closed form inverted)
            xi = (math.acosh(1 + (rise - zc) * (m - 1) / rise) / kk if m > 1 else math.sqrt(1 - zc / rise))
            dz = (-rise / (m - 1) * kk * math.sinh(kk * xi) if m > 1 else -2 * rise * xi) * 2 / span
            nx, nz = -dz / math.hypot(1.0, dz), 1.0 / math.hypot(1.0, dz)  # the axis' upward normal
            x = 0.5 * span * xi
            face = -1.0 if i % 2 == 0 else 1.0  # odd k: the lower face, its normal into the water is up
            cx, cz = x + face * 0.5 * hc * nx, zc + face * 0.5 * hc * nz
            out.append(Patch(f"B{i + 1 + (9 if sign < 0 else 0)}", (sign * cx, cz), (-face * sign * nx, -face * nz),
                             size))
    return tuple(out)


@dataclass(frozen=True)
class NearField(Spec):
    """An SPH near field inside the scene's incident sea (``waves`` of kind "regular" or
    "irregular", travelling along +x): a box of water ``depth`` [m] deep over a seabed at
    z = 0 around the bodies, whose end walls keep the sea's orbits and whose relaxation
    zones inside them pull the water towards the sea's velocity, so that the incident waves
    pass through and what the bodies send out dies there (:mod:`fluid.nearfield`). 3-D:
    slip walls across y, width/2 each side of the bodies (the incident flow runs along
    them), with zones inside them too unless ``side_zones`` is false (a channel); with
    ``symmetry`` the plane y = 0 is a symmetry plane instead of one of them: only y >= 0
    is simulated, the particles near the plane mirrored across it (:mod:`fluid.mirror`),
    half the particles for a scene symmetric about it; a channel's ``sides = "symmetry"``
    makes both its sides symmetry planes (a slice of a sea uniform across y, no bodies).
    The mooring lines are not in the SPH fluid: their anchors may lie outside the box.
    Extents left unset are chosen from the bodies and the sea
    (:func:`fluid.nearfield.choose_box`: zones half the sea's wavelength, or half that of
    the bodies' heave period when they are small against the sea's; water beyond the
    bodies' reach) and reported with the reasons in summary.json."""

    TAG = ("kind", "nearfield")
    kind: str = tag("nearfield")
    depth: float = required(num(None, "still-water depth over the seabed at z = 0", "m", lo=0, lo_open=True,
                                optional=False))
    height: float = num(None, "wall height above the seabed (unset: the depth, twice the sea's largest height, "
                              "and a margin)", "m", lo=0, lo_open=True)
    x0: float = num(None, "near end of the water, the zone's wall side (unset: chosen)", "m")
    x1: float = num(None, "far end of the water (unset: chosen)", "m")
    width: float = num(None, "3-D: width across y between the side walls, centred on the bodies (unset: chosen)", "m",
                       lo=0, lo_open=True)
    zone: float = num(None, "width of each relaxation zone inside the end (and, 3-D, side) walls (unset: chosen)",
                      "m", lo=0, lo_open=True)
    rate: float = num(2.0, "relaxation rate at the walls, in the sea's (peak) angular frequencies", lo=0,
                      lo_open=True, hi=50)
    absorbing_walls: bool = flag(False, "the end walls also move with the waves that come back to them (active "
                                        "absorption, fluid.wall_absorption): waves much longer than the box, which "
                                        "its zones reflect, leave through them")
    side_zones: bool = flag(True, "3-D: relaxation zones inside the side walls too; false: none, a channel whose "
                                  "slip side walls return what reaches them (plane waves along x, a slice of a "
                                  "flume; bodies far from the sides)")
    sides: str = choice("walls", "3-D channel (side_zones false): what bounds it across y: walls (slip side walls) "
                        "or symmetry (symmetry planes: a slice of a sea uniform across y, of any width; needs the "
                        "width, no bodies; fluid.mirror)", ("walls", "symmetry"))
    symmetry: bool = flag(False, "3-D: the plane y = 0 is a symmetry plane of the scene: only y >= 0 is simulated "
                                 "(half the particles), the water near the plane mirrored across it; the waves, "
                                 "bodies, lines and probes must be symmetric about it")

    def validate(self):
        if self.height is not None and self.height <= self.depth:
            raise SceneError("height", f"{self.height} m must exceed the depth {self.depth} m")
        if self.x0 is not None and self.x1 is not None and not self.x1 > self.x0:
            raise SceneError("x1", f"{self.x1} m must exceed x0 = {self.x0} m")

    @property
    def level(self):
        return self.depth


@dataclass(frozen=True)
class OpenWater(Spec):
    """Water blocks in open space: no walls, no floor. The SPH fluid lives in the box
    ``lo`` .. ``hi`` [m], which holds every block; a particle that leaves it is removed (and
    counted as lost). For water without gravity (``world.gravity = 0``), where nothing but
    the bodies acts on it: a blob a body strikes, which checks that the coupling exchanges
    momentum exactly; under gravity the blocks fall freely."""

    TAG = ("kind", "open")
    kind: str = tag("open")
    lo: tuple = required(vec(None, "lower corner of the fluid's box", "m"))
    hi: tuple = required(vec(None, "upper corner of the fluid's box", "m"))
    water: tuple = parts("boxes of water, inside the fluid's box (at least one)", Block)

    def validate(self):
        if len(self.lo) != len(self.hi) or not all(h > lo for lo, h in zip(self.lo, self.hi)):
            raise SceneError("hi", f"{list(self.hi)} must exceed lo = {list(self.lo)} in every coordinate")
        if not self.water:
            raise SceneError("water", "give at least one block of water (lo and hi corners)")

    @property
    def level(self):
        """The top of the highest block [m]: open water has no still level."""
        return max(b.hi[-1] for b in self.water)


DOMAINS = (Tank, Flume, InclinedTank, CylinderTank, PolygonTank, ArchRib, NearField, OpenWater)


# ------------------------------------------------------------------------ excitations
@dataclass(frozen=True)
class _Regular(Spec):
    """Regular waves of height ``height`` [m] and period ``period`` [s] from linear
    wavemaker theory (``fluid.wavemaker``), the paddle ramped in over ``ramp`` periods."""

    height: float = required(num(None, "wave height H", "m", lo=0, lo_open=True, optional=False))
    period: float = required(num(None, "wave period T", "s", lo=0, lo_open=True, optional=False))
    ramp: float = num(2.0, "periods over which the paddle motion ramps in", lo=0)


@dataclass(frozen=True)
class Piston(_Regular):
    """A piston wavemaker making regular waves (linear wavemaker theory, ``fluid.wavemaker``)."""

    TAG = ("kind", "piston")
    kind: str = tag("piston")


@dataclass(frozen=True)
class Flap(_Regular):
    """A flap wavemaker hinged at the flume's bottom, making regular waves."""

    TAG = ("kind", "flap")
    kind: str = tag("flap")


@dataclass(frozen=True)
class PaddleRecord(Spec):
    """A paddle driven by a recorded history: time [s] in the first column, the piston's
    displacement [m] or the flap's angle [rad] (times ``scale``) in ``column``. To start the
    run later in the record, shift its times back (``t_shift`` = minus the record time that
    is the run's t = 0) and take the value there as the paddle's zero (``zero_at_start``):
    the flume builds the paddle upright at x = 0, and a constant offset of it makes no wave
    (to first order)."""

    TAG = ("kind", "record")
    kind: str = tag("record")
    paddle: str = required(choice(None, "the paddle the record drives", ("piston", "flap")))
    file: str = required(text(None, "the record: a table of time and value"))
    column: int = whole(1, "the column of the value (0 is time)", lo=1)
    scale: float = num(1.0, "factor on the values (pi/180 for degrees)")
    t_shift: float = num(0.0, "added to the record's times", "s")
    zero_at_start: bool = flag(False, "subtract the record's value at the run's start (t = 0, after t_shift): the "
                               "paddle starts where the flume builds it")


@dataclass(frozen=True)
class LinearWaves(seas.IncidentSea):
    """Regular linear (Airy) waves acting on the bodies of the analytic fluid
    (``fluid.analytic.LinearWave``, the linear ``fluid.waves.RegularWave``: the same wave as
    kind = "regular"): height ``height`` [m], period ``period`` [s], in water
    ``depth`` [m] deep under ``fluid.level``, travelling along ``direction`` [deg] (from +x
    towards +y; 2-D: 0 or 180), crest at x = y = 0 at t = 0, faded in over ``ramp``
    periods. The free surface moves the buoyancy; the water's velocity and acceleration
    load the bodies (Morison: Froude-Krylov and added-mass inertia, drag on the relative
    velocity through the damping coefficients). No wavemaker: the SPH fluid makes its
    waves with a piston or flap in a flume."""

    TAG = ("kind", "linear")
    kind: str = tag("linear")
    height: float = required(num(None, "wave height H, crest to trough", "m", lo=0, lo_open=True, optional=False))
    period: float = required(num(None, "wave period T", "s", lo=0, lo_open=True, optional=False))
    depth: float = required(num(None, "still-water depth over the seabed (for the dispersion relation and the decay "
                                "of the kinematics); inf: deep water (the potential fluid)", "m", lo=0, lo_open=True,
                                optional=False, infinite=True))
    direction: float = num(0.0, "heading of propagation, from +x towards +y (2-D: 0 or 180)", "deg")
    ramp: float = num(2.0, "periods over which the waves fade in", lo=0)

    def sea(self, scene):
        """``fluid.analytic.LinearWave``."""
        from fluid.analytic import LinearWave

        return LinearWave(self.height, self.period, self.depth, self.direction, self.ramp * self.period,
                          scene.world.gravity)


@dataclass(frozen=True)
class RegularWaves(seas.IncidentSea):
    """Regular waves acting on the bodies of the analytic fluid (``fluid.waves.RegularWave``):
    height ``height`` [m], period ``period`` [s], in water ``depth`` [m] deep under the still
    level, ``theory`` "linear" (Airy; the same wave as kind = "linear") or "stokes2" (Stokes
    second order: a sharper crest and flatter trough, refused where a secondary crest would
    rise in the trough), travelling along ``direction`` [deg] (from +x towards +y; 2-D: 0 or
    180), ``phase`` [deg] at x = y = 0 at t = 0 (0: a crest there), faded in over ``ramp``
    periods. Refused beyond breaking: H/L > 0.142 tanh(kd) (Miche 1944), H/d > 0.78. The SPH
    fluid makes its waves with a piston or flap in a flume."""

    TAG = ("kind", "regular")
    kind: str = tag("regular")
    height: float = required(num(None, "wave height H, crest to trough", "m", lo=0, lo_open=True, optional=False))
    period: float = required(num(None, "wave period T", "s", lo=0, lo_open=True, optional=False))
    depth: float = required(num(None, "still-water depth over the seabed (for the dispersion relation and the decay "
                                "of the kinematics)", "m", lo=0, lo_open=True, optional=False))
    theory: str = choice("linear", "wave theory: linear (Airy) or stokes2 (Stokes second order)",
                         ("linear", "stokes2"))
    direction: float = num(0.0, "heading of propagation, from +x towards +y (2-D: 0 or 180)", "deg")
    phase: float = num(0.0, "phase at x = y = 0 at t = 0 (0: a crest there, 90: an up-crossing)", "deg")
    ramp: float = num(2.0, "periods over which the waves fade in", lo=0)

    def sea(self, scene):
        """``fluid.waves.RegularWave`` (:func:`cosim.scene.build.regular_sea`)."""
        from cosim.scene.build import regular_sea

        return regular_sea(scene)


SPECTRA = ("jonswap", "pierson-moskowitz", "series")


@dataclass(frozen=True)
class IrregularWaves(seas.IncidentSea):
    """An irregular long-crested sea acting on the bodies of the analytic fluid, in water
    ``depth`` [m] deep under the still level, travelling along ``direction`` [deg]:
    ``spectrum`` "jonswap" or "pierson-moskowitz" (``fluid.waves.SpectralSea``: ``hs``
    [m], ``tp`` [s], JONSWAP's ``gamma``; ``components`` waves of random phases from
    ``seed``, enough that the sea does not repeat itself within the run, their
    frequencies spread over ``band`` peak frequencies), or "series"
    (``fluid.waves.RecordedSea``: the elevation [m] measured at ``at`` in column ``column``
    of ``file``, time [s] first, evenly sampled, made into linear waves by FFT; the record
    must last the run). Faded in over ``ramp`` peak periods. Refused: Hs/Lp > 0.1 (Lp the
    wavelength at the peak period). The SPH fluid makes its waves with a piston or flap in
    a flume."""

    TAG = ("kind", "irregular")
    kind: str = tag("irregular")
    depth: float = required(num(None, "still-water depth over the seabed (for the dispersion relation and the decay "
                                "of the kinematics)", "m", lo=0, lo_open=True, optional=False))
    spectrum: str = choice("jonswap", "the sea's spectrum: jonswap, pierson-moskowitz, or series (a recorded "
                                      "elevation)", SPECTRA)
    hs: float = num(None, "significant wave height Hs (jonswap, pierson-moskowitz)", "m", lo=0, lo_open=True)
    tp: float = num(None, "peak period Tp (jonswap, pierson-moskowitz)", "s", lo=0, lo_open=True)
    gamma: float = num(None, "JONSWAP peak enhancement factor (unset: 3.3)", lo=1, hi=7)
    seed: int = whole(0, "seed of the random phases (jonswap, pierson-moskowitz)", lo=0)
    components: int = whole(None, "number of wave components (unset: 200, or as many as the run's duration needs)",
                            lo=2)
    band: tuple = vec(None, "the components' frequencies from band[0] to band[1] times the peak frequency (unset: "
                      "0.5 to 4)", sizes=(2,))
    file: str = text(None, "series: the record, a table of time [s] and elevation [m]")
    column: int = whole(1, "series: the column of the elevation (0 is the time)", lo=1)
    at: tuple = vec(None, "series: where the record was measured, x (2-D) or (x, y) (3-D); unset: the origin", "m",
                    sizes=(1, 2))
    min_period: float = num(None, "series: components of shorter periods are left out (unset: none)", "s", lo=0,
                            lo_open=True)
    direction: float = num(0.0, "heading of propagation, from +x towards +y (2-D: 0 or 180)", "deg")
    ramp: float = num(2.0, "peak periods over which the sea fades in", lo=0)

    def validate(self):
        if self.spectrum == "series":
            if self.file is None:
                raise SceneError("file", "is required with spectrum = \"series\": give the record's file (time [s], "
                                 "elevation [m])")
            for name in ("hs", "tp", "gamma", "components", "band"):
                if getattr(self, name) is not None:
                    raise SceneError(name, f"a series' sea is its record; leave {name} out (or give spectrum = "
                                     f"\"jonswap\")")
            return
        for name in ("hs", "tp"):
            if getattr(self, name) is None:
                raise SceneError(name, f"is required with spectrum = {self.spectrum!r}: give "
                                 f"{'the significant wave height [m]' if name == 'hs' else 'the peak period [s]'}")
        if self.band is not None and not 0 < self.band[0] < self.band[1]:
            raise SceneError("band", f"{list(self.band)}: give the lowest and highest component frequency in peak "
                             f"frequencies, 0 < lo < hi (e.g. [0.5, 4.0])")
        if self.spectrum == "pierson-moskowitz" and self.gamma is not None:
            raise SceneError("gamma", "the Pierson-Moskowitz spectrum has no peak enhancement; leave gamma out (or "
                             "give spectrum = \"jonswap\")")
        for name in ("file", "at", "min_period"):
            if getattr(self, name) is not None:
                raise SceneError(name, f"belongs to spectrum = \"series\"; leave it out with {self.spectrum!r}")

    def sea(self, scene):
        """``fluid.waves.SpectralSea`` or ``RecordedSea`` (:func:`cosim.scene.build.irregular_sea`)."""
        from cosim.scene.build import irregular_sea

        return irregular_sea(scene)


@dataclass(frozen=True)
class StillWaves(seas.IncidentSea):
    """Still water ``depth`` [m] deep, no incident wave (``fluid.waves.StillWater``): for
    bodies forced to move in it (``bodies[].motion``), whose radiated waves have the
    ``period`` [s] given; an SPH near field (``domain.kind = "nearfield"``) sizes its
    relaxation zones and their rate by it, as by a sea's peak period."""

    TAG = ("kind", "still")
    kind: str = tag("still")
    period: float = required(num(None, "period of the waves the bodies radiate (a forced body's motion period)",
                                 "s", lo=0, lo_open=True, optional=False))
    depth: float = required(num(None, "still-water depth over the seabed", "m", lo=0, lo_open=True, optional=False))
    direction: float = num(0.0, "heading (a near field's: 0, its end walls across x)", "deg")

    def sea(self, scene):
        """``fluid.waves.StillWater``."""
        from cosim.scene.build import _frame
        from fluid import waves as fw

        return fw.StillWater(self.period, self.depth, **_frame(scene))


WAVES = (Piston, Flap, PaddleRecord, LinearWaves, RegularWaves, IrregularWaves, StillWaves)


@dataclass(frozen=True)
class Shake(Spec):
    """Harmonic base motion of the tank along ``direction``: give ``amplitude`` [m] or the
    peak ``acceleration`` [m/s^2] (the ground acceleration a0 sin(2 pi t / T) of Sunara et al. 2021,
    §3.1, started from rest), ramped in over ``ramp`` [s]. ``stop``: the motion faded out
    over ``ramp`` before it, back to the start; with ``hold``, cut at ``stop`` and the tank
    held at rest where it got to (``fluid.motion.Stopped`` without a fade), which needs the
    tank at rest there: a shake from rest (``acceleration``) at whole periods, where its
    velocity (a0 / w)(1 - cos w t) and its acceleration vanish, having travelled
    a0 T^2 / (2 pi) a period; one of ``amplitude`` at a turning point, T/4 + k T/2."""

    TAG = ("kind", "harmonic")
    kind: str = tag("harmonic")
    period: float = required(num(None, "period", "s", lo=0, lo_open=True, optional=False))
    direction: tuple = vec((1.0, 0.0), "direction of the motion", nonzero=True)
    amplitude: float = num(None, "displacement amplitude (or give acceleration)", "m")
    acceleration: float = num(None, "peak acceleration (or give amplitude)", "m/s^2")
    ramp: float = num(0.0, "fade-in time", "s", lo=0)
    stop: float = num(None, "time at which the motion has faded out (with hold: is cut)", "s", lo=0, lo_open=True)
    hold: bool = flag(False, "true: the motion is cut at `stop` and the tank held at rest where it got to (it must "
                             "be at rest there: whole periods of a shake from rest); false: it fades out over `ramp` "
                             "before `stop`, back to its start")

    #: a held stop's largest velocity at ``stop``, as a fraction of the peak velocity
    HOLD_REST = 1e-3

    def validate(self):
        if (self.amplitude is None) == (self.acceleration is None):
            raise SceneError("amplitude", "give either amplitude [m] or acceleration [m/s^2], one of the two")
        if self.hold:
            self._check_hold()
        elif self.stop is not None and not self.ramp > 0:
            raise SceneError("ramp", f"is 0 s, but stop = {self.stop:g} s fades the shaking out over ramp; give ramp "
                                     "> 0 (e.g. one period), or hold = true to cut the shaking at stop and hold the "
                                     "tank where it got to")

    def _check_hold(self):
        """A held stop: given, after the fade-in, where the tank is at rest (class docstring)."""
        T = self.period
        if self.stop is None:
            raise SceneError("hold", f"= true needs stop, the time [s] at which the tank stops and is held; give "
                                     f"stop, e.g. a whole number of periods ({3 * T:g} s)")
        if self.stop < self.ramp:
            raise SceneError("stop", f"= {self.stop:g} s comes before the fade-in over ramp = {self.ramp:g} s ends; "
                                     "give a later stop or a shorter ramp")
        w = 2 * math.pi / T
        phase = 2 * math.pi * math.remainder(self.stop, T) / T  # w stop, exact to whole periods
        if self.acceleration is not None:   # from rest: v = (a0 / w)(1 - cos w t), at rest at t = k T
            a0 = self.acceleration
            v, peak, first, step = a0 / w * (1 - math.cos(phase)), 2 * a0 / w, T, T
        else:                               # v = A w cos w t, at rest at t = T/4 + k T/2
            v, peak, first, step = self.amplitude * w * math.cos(phase), self.amplitude * w, T / 4, T / 2
        if abs(v) > self.HOLD_REST * abs(peak):
            k = max(0, math.floor((self.stop - first) / step))
            near = [first + j * step for j in (k, k + 1) if first + j * step >= self.ramp]
            raise SceneError("stop", f"= {self.stop:g} s: the tank moves at {abs(v):.3g} m/s there (its peak "
                                     f"{abs(peak):.3g} m/s), and hold cuts the motion at stop, a jump to rest; give a "
                                     f"stop where it is at rest, e.g. {' or '.join(f'{x:g} s' for x in near)}")


@dataclass(frozen=True)
class Roll(Spec):
    """Harmonic roll of the tank by ``amplitude`` [deg] about an axis through ``point``
    (2-D: about +y; 3-D: along ``axis``)."""

    TAG = ("kind", "roll")
    kind: str = tag("roll")
    amplitude: float = required(num(None, "roll amplitude", "deg", optional=False))
    period: float = required(num(None, "period", "s", lo=0, lo_open=True, optional=False))
    point: tuple = required(vec(None, "a point of the roll axis", "m"))
    axis: tuple = vec(None, "the roll axis (3-D only)", sizes=(3,), nonzero=True)
    ramp: float = num(0.0, "fade-in time", "s", lo=0)


@dataclass(frozen=True)
class RollTable(Spec):
    """The tank rolled by a recorded angle about an axis through ``point`` [m] (2-D: about
    +y; 3-D: along ``axis``): time [s] in the first column of ``file``, the angle [deg] in
    ``column``, times ``scale`` (``-1`` turns a record whose positive angle is the other
    way). The angle between samples is a C2 cubic spline through them, its rate and
    acceleration the spline's derivatives (``fluid.motion.Tabulated``); the record starts
    at 0 (the tank is built level) and after its end the tank holds its last angle, at rest.
    E.g. the measured roll of SPHERIC benchmark 10 (Souto-Iglesias, Botia-Vera et al., CEHINAV-UPM)."""

    TAG = ("kind", "roll_table")
    kind: str = tag("roll_table")
    file: str = required(text(None, "the table: time [s], then the roll angle [deg]"))
    point: tuple = required(vec(None, "a point of the roll axis", "m"))
    axis: tuple = vec(None, "the roll axis (3-D only)", sizes=(3,), nonzero=True)
    column: int = whole(1, "the column of the angle (0 is time)", lo=1)
    scale: float = num(1.0, "factor on the angles (-1: the record's sign turned)")


#: the base motions that turn the tank about an axis (the others translate it)
ROLLS = (Roll, RollTable)


@dataclass(frozen=True)
class TableMotion(Spec):
    """Base motion from a table: time [s] in the first column, the ``quantity`` along
    ``direction`` in ``column`` (times ``scale``)."""

    TAG = ("kind", "table")
    kind: str = tag("table")
    file: str = required(text(None, "the table of time and value"))
    quantity: str = choice("displacement", "what the table holds",
                           ("displacement", "velocity", "acceleration"))
    direction: tuple = vec((1.0, 0.0), "direction of the motion", nonzero=True)
    column: int = whole(1, "the column of the value (0 is time)", lo=1)
    scale: float = num(1.0, "factor on the values")


@dataclass(frozen=True)
class Earthquake(Spec):
    """Base motion from a PEER NGA ``.AT2`` accelerogram (in g), baseline-corrected
    (``fluid.motion.read_at2``), times ``scale``, along ``direction``. After the record's
    end the tank rests where the corrected record leaves it. The record must sample the
    water's first sloshing period at least 10 times."""

    TAG = ("kind", "earthquake")
    kind: str = tag("earthquake")
    file: str = required(text(None, "the .AT2 accelerogram"))
    direction: tuple = vec((1.0, 0.0), "direction of the ground motion", nonzero=True)
    scale: float = num(1.0, "factor on the record")
    baseline_degree: int = whole(6, "degree of the baseline correction polynomial: 3 is the least that meets both "
                                    "end conditions, 6 is usual", lo=3, hi=12)


@dataclass(frozen=True)
class Record(Spec):
    """One component of a :class:`GroundMotion`: a PEER NGA ``.AT2`` accelerogram (in g)
    applied along ``direction`` ((x, z) in 2-D, (x, y, z) in 3-D), times ``scale``."""

    file: str = required(text(None, "the .AT2 accelerogram"))
    direction: tuple = required(vec(None, "direction of this component", nonzero=True))
    scale: float = num(1.0, "factor on this record")


@dataclass(frozen=True)
class GroundMotion(Spec):
    """Base motion from several earthquake records at once, each along its own direction
    (horizontal and vertical: Wang et al. 2022, §4.2's "El Centro NS + vertical"; three in 3-D):
    the tank translates by the sum of the components' displacements, each read by
    ``fluid.motion.read_at2``, baseline-corrected and integrated exactly, all starting at
    t = 0. The records' times must cover ``world.duration`` unless ``hold`` lets the tank
    rest after them, or ``stop`` brings the tank to rest at one time (the free response
    after the earthquake: ``fluid.motion.Stopped``); each must sample the water's first sloshing period at least 10
    times. ``cosim/refdata/earthquake_el_centro_1940`` ships El Centro 1940 (NS, EW, UP)."""

    TAG = ("kind", "ground_motion")
    kind: str = tag("ground_motion")
    components: tuple = parts("the records, one per direction, at most one per axis of the scene", (Record,))
    scale: float = num(1.0, "factor on every record")
    baseline_degree: int = whole(6, "degree of the baseline correction polynomial: 3 is the least that meets both "
                                    "end conditions, 6 is usual", lo=3, hi=12)
    hold: bool = flag(False, "true: each record's motion stops where its record ends, the tank at rest there "
                             "(false: a scene longer than a record is refused)")
    stop: float = num(None, "the shaking ends here: the records' motion as given until `stop - fade`, then its "
                            "velocity faded out by a half cosine, the tank at rest from `stop` on and the water "
                            "ringing free", "s", lo=0, lo_open=True)
    fade: float = num(0.5, "how long the tank takes to come to rest before `stop`", "s", lo=0, lo_open=True)

    def validate(self):
        if self.stop is not None and self.stop <= self.fade:
            raise SceneError("stop", f"= {self.stop:g} s leaves no room for the {self.fade:g} s fade before it; give "
                             "a later stop, or a shorter fade")
        if not self.components:
            raise SceneError("components", "is empty; give at least one record, e.g. [{ file = \"ELC180.AT2\", "
                             "direction = [1.0, 0.0] }]")


BASE_MOTIONS = (Shake, Roll, RollTable, TableMotion, Earthquake, GroundMotion)


# ------------------------------------------------------------------------ bodies
@dataclass(frozen=True)
class ForcedMotion(Spec):
    """A rigid body's prescribed harmonic motion along one axis, a forced-oscillation test
    (radiation: the fluid's load gives added mass and damping): its centre at ``pos`` plus
    ``amplitude w(t) sin(2 pi t / period)`` along x (``dof = "surge"``), y (``"sway"``, 3-D)
    or z (``"heave"``), ``w`` a half-cosine window rising over ``ramp`` periods from rest
    (:class:`fluid.motion.Ramped`); with ``cycles``, cut after that many periods and held
    there (``fluid.motion.Stopped``: a shaken support stopped; its velocity jumps to zero
    unless it stops at a turning point). The body has that one slide and no other
    freedom, driven (:meth:`bodies.mujoco_bodies.MujocoBodies.drive`): what the fluid does
    to it moves nothing and is recorded (``probes.loads``)."""

    TAG = ("kind", "harmonic")
    kind: str = tag("harmonic")
    amplitude: float = required(num(None, "displacement amplitude", "m", lo=0, lo_open=True, optional=False))
    period: float = required(num(None, "period", "s", lo=0, lo_open=True, optional=False))
    dof: str = choice("heave", "the axis of the motion: surge (x), sway (y, 3-D) or heave (z)",
                      ("surge", "sway", "heave"))
    ramp: float = num(2.0, "periods over which the amplitude fades in (0: none)", lo=0)
    cycles: float = num(None, "periods after which the motion stops, the body held where it got to (unset: never)",
                        lo=0, lo_open=True)

    @property
    def axis(self) -> str:
        """The world axis of the motion, "x", "y" or "z"."""
        return {"surge": "x", "sway": "y", "heave": "z"}[self.dof]

    def signal(self):
        """The displacement [m] as a :class:`fluid.motion.Signal` (value, rate, acceleration)."""
        from fluid.motion import Harmonic, Ramped, Stopped

        sig = Harmonic(self.amplitude, self.period)
        sig = Ramped(sig, self.ramp * self.period) if self.ramp > 0 else sig
        return sig if self.cycles is None else Stopped(sig, self.cycles * self.period, fade=0.0)


@dataclass(frozen=True)
class ForcedTable(Spec):
    """A rigid body's prescribed motion along one axis through given points: its centre at
    ``pos`` plus ``s(t)`` along x (``dof = "surge"``), y (``"sway"``, 3-D) or z (``"heave"``),
    ``points`` the pairs (t [s], s [m]), straight between them (``fluid.motion.Polyline``:
    constant speed on each interval, held before the first and after the last). The first
    point's ``s`` is 0 (the body starts at ``pos``). A test rig's fairlead: moved at a
    constant speed, held, stepped through offsets, with the lines' tensions recorded
    (``probes.tensions``, ``probes.loads``). Driven as :class:`ForcedMotion` is."""

    TAG = ("kind", "table")
    kind: str = tag("table")
    points: tuple = required(vecs("the points (t [s], s [m]), times increasing", sizes=(2,), min_len=2))
    dof: str = choice("heave", "the axis of the motion: surge (x), sway (y, 3-D) or heave (z)",
                      ("surge", "sway", "heave"))

    def validate(self):
        super().validate()
        t = [p[0] for p in self.points]
        if any(b <= a for a, b in zip(t, t[1:])):
            k = next(i for i, (a, b) in enumerate(zip(t, t[1:])) if b <= a)
            raise SceneError(f"points[{k + 1}]", f"t = {t[k + 1]:g} s does not follow t = {t[k]:g} s; give the "
                             "points in increasing time, each time once")
        if self.points[0][1] != 0.0:
            raise SceneError("points[0]", f"s = {self.points[0][1]:g} m: the motion starts at the body's pos; give "
                             "0 as the first point's s (and pos where the body starts)")

    @property
    def axis(self) -> str:
        """The world axis of the motion, "x", "y" or "z"."""
        return {"surge": "x", "sway": "y", "heave": "z"}[self.dof]

    @property
    def amplitude(self) -> float:
        """The largest displacement from ``pos`` [m]."""
        return max(abs(p[1]) for p in self.points)

    def signal(self):
        """The displacement [m] as a :class:`fluid.motion.Polyline`."""
        from fluid.motion import Polyline

        return Polyline(tuple(p[0] for p in self.points), tuple(p[1] for p in self.points))


#: a body's prescribed motions (``bodies[].motion``)
BODY_MOTIONS = (ForcedMotion, ForcedTable)


_BODY_COMMON = """``pos`` is the centre [m] ((x, z) in 2-D, (x, y, z) in 3-D); with ``place =
"floating"`` give the horizontal position only ((x,) or (x, y)): the height is the
hydrostatic equilibrium with the moorings' pull. ``fairleads``: named points in the body
frame [m], referred to by lines as ``"BODY.NAME"``. Give ``density`` or ``mass``. ``motion``:
a prescribed motion instead of a free body (:class:`ForcedMotion`, :class:`ForcedTable`).
``velocity``: a free body's velocity at the start [m/s] ((x, z) in 2-D, (x, y, z) in 3-D),
without spin."""


@dataclass(frozen=True)
class Box(shapes.BoxShape):
    __doc__ = "A box body of edge lengths ``size`` [m] ((x, z) in 2-D, (x, y, z) in 3-D). " + _BODY_COMMON
    TAG = ("shape", "box")
    shape: str = tag("box")
    name: str = required(text(None, "the body's name", name=True))
    size: tuple = required(vec(None, "edge lengths", "m"))
    pos: tuple = required(vec(None, "centre position", "m", sizes=(1, 2, 3)))
    density: float = num(None, "density (or give mass)", "kg/m^3", lo=0, lo_open=True, hi=L.MAX_DENSITY,
                         why=L.DENSITY_WHY)
    mass: float = num(None, "mass (or give density)", "kg", lo=0, lo_open=True)
    place: str = choice("given", "given: at pos; floating: at its hydrostatic equilibrium", ("given", "floating"))
    euler: tuple = vec(None, "initial orientation (Euler angles)", "deg", sizes=(3,))
    fairleads: dict = table("named points in the body frame", "m")
    motion: Spec = part(None, "a prescribed motion, harmonic or through points (unset: a free body)", BODY_MOTIONS)
    velocity: tuple = vec(None, "initial velocity of its centre of mass (unset: at rest)", "m/s", sizes=(2, 3))

    def validate(self):
        super().validate()
        if any(s <= 0 for s in self.size):
            raise SceneError("size", f"{self.size}: every edge length must be > 0 m")


@dataclass(frozen=True)
class Cylinder(shapes.CylinderShape):
    __doc__ = ("A cylinder of ``radius`` [m]: in 2-D a circle in the x-z plane (1 m long), in "
               "3-D of ``length`` [m] with its axis along z. " + _BODY_COMMON)
    TAG = ("shape", "cylinder")
    shape: str = tag("cylinder")
    name: str = required(text(None, "the body's name", name=True))
    radius: float = required(num(None, "radius", "m", lo=0, lo_open=True, optional=False))
    pos: tuple = required(vec(None, "centre position", "m", sizes=(1, 2, 3)))
    length: float = num(None, "length along its axis (3-D only)", "m", lo=0, lo_open=True)
    density: float = num(None, "density (or give mass)", "kg/m^3", lo=0, lo_open=True, hi=L.MAX_DENSITY,
                         why=L.DENSITY_WHY)
    mass: float = num(None, "mass (or give density)", "kg", lo=0, lo_open=True)
    place: str = choice("given", "given: at pos; floating: at its hydrostatic equilibrium", ("given", "floating"))
    euler: tuple = vec(None, "initial orientation (Euler angles)", "deg", sizes=(3,))
    fairleads: dict = table("named points in the body frame", "m")
    motion: Spec = part(None, "a prescribed motion, harmonic or through points (unset: a free body)", BODY_MOTIONS)
    velocity: tuple = vec(None, "initial velocity of its centre of mass (unset: at rest)", "m/s", sizes=(2, 3))


@dataclass(frozen=True)
class Sphere(shapes.SphereShape):
    __doc__ = "A sphere of ``radius`` [m] (3-D only). " + _BODY_COMMON
    TAG = ("shape", "sphere")
    shape: str = tag("sphere")
    name: str = required(text(None, "the body's name", name=True))
    radius: float = required(num(None, "radius", "m", lo=0, lo_open=True, optional=False))
    pos: tuple = required(vec(None, "centre position", "m", sizes=(2, 3)))
    density: float = num(None, "density (or give mass)", "kg/m^3", lo=0, lo_open=True, hi=L.MAX_DENSITY,
                         why=L.DENSITY_WHY)
    mass: float = num(None, "mass (or give density)", "kg", lo=0, lo_open=True)
    place: str = choice("given", "given: at pos; floating: at its hydrostatic equilibrium", ("given", "floating"))
    euler: tuple = vec(None, "initial orientation (Euler angles)", "deg", sizes=(3,))
    fairleads: dict = table("named points in the body frame", "m")
    motion: Spec = part(None, "a prescribed motion, harmonic or through points (unset: a free body)", BODY_MOTIONS)
    velocity: tuple = vec(None, "initial velocity of its centre of mass (unset: at rest)", "m/s", sizes=(2, 3))


@dataclass(frozen=True)
class MJCF(Spec):
    """Bodies from an MJCF file (MuJoCo's XML): every body with degrees of freedom, or
    those named in ``bodies``. Fairleads are the file's sites, ``"BODY.SITE"``. The model's
    own gravity is replaced by the world's (one gravity for every participant; where they
    differ the build warns that it did)."""

    TAG = ("shape", "mjcf")
    shape: str = tag("mjcf")
    file: str = required(text(None, "the MJCF file"))
    bodies: tuple = names("names of the coupled bodies (empty: every movable body)")

@dataclass(frozen=True)
class ElasticPlate(shapes.PlateShape):
    """An elastic plate (a cantilever) clamped by its foot to the tank's floor at ``base``
    [m] (the centre of the foot: (x, z) in 2-D, (x, y, z) in 3-D) and rising ``length`` [m]
    along z, or (``direction = "down"``) clamped by its top at ``base`` and hanging
    ``length`` along -z, its free end at or above the floor (a gate, e.g. Antoci et al.'s);
    ``thickness`` [m] along x (the bending direction), in 3-D ``width`` [m] along y
    (2-D: 1 m). A chain of ``elements`` rigid links joined by bending hinges ``E I / l`` and
    shear slides ``kappa G A / l`` (a discrete Timoshenko beam, :mod:`bodies.elastic`); the
    SPH fluid's boundary particles follow its deformed surface. Probes: the displacement of
    its upper left corner (top, -x face) and of its tip (top centre); when hanging, of its
    free end's (bottom) left corner and centre. ``thin_wall``: a plate fewer than two
    particle spacings thick gets two columns of boundary particles anyway,
    one for each side (the fluid stands off it by up to half a spacing); without it such a
    plate is refused. Under ``base_motion`` the clamp rides with the tank (the chain's
    clamped link on joints driven by the tank's motion, ``bodies.elastic.Support``: the
    plate feels the base's acceleration as a base-excited cantilever does, and starts at
    rest on it); its corner and tip probes then read the deflection in the tank's frame,
    and ``clamp_x``, ``clamp_z`` (3-D ``clamp_y``) the clamp's displacement in the world. A
    standing plate whose own weight (less its buoyancy below the still water) passes its
    self-weight buckling load (Greenhill 1881: ``q L^3 / (E I) = 7.837`` for a uniform
    weight ``q`` per length) is warned of when the scene is built, with both loads, and
    starts bent in its buckling mode, its tip ``L / 1000`` along +x, so that it buckles
    rather than stand perfectly still; a hanging plate is in tension and never buckles.
    ``angle`` turns a standing plate about y from +z towards +x (90: lying along +x from its
    clamp, a horizontal cantilever bending under its own weight; without the SPH fluid,
    whose boundary stands a plate on the floor); the buckling check then takes
    gravity's component along the plate (``world.gravity`` may be a vector)."""

    TAG = ("shape", "elastic-plate")
    shape: str = tag("elastic-plate")
    name: str = required(text(None, "the body's name", name=True))
    length: float = required(num(None, "height from the clamp to the top", "m", lo=0, lo_open=True, optional=False))
    thickness: float = required(num(None, "thickness along x", "m", lo=0, lo_open=True, optional=False))
    E: float = required(num(None, "Young's modulus", "Pa", lo=0, lo_open=True, hi=L.MAX_YOUNG, why=L.YOUNG_WHY,
                            optional=False))
    density: float = required(num(None, "density", "kg/m^3", lo=0, lo_open=True, hi=L.MAX_DENSITY,
                                  why=L.DENSITY_WHY, optional=False))
    base: tuple = required(vec(None, "centre of the clamped end: the foot, on the floor (the top when hanging)", "m"))
    width: float = num(None, "width along y (3-D only)", "m", lo=0, lo_open=True)
    nu: float = num(0.0, "Poisson's ratio", lo=-1.0, hi=0.5, lo_open=True, hi_open=True)
    elements: int = whole(8, "elements along the plate (8: first three frequencies within 1 %)", lo=4)
    damping: float = num(0.0, "stiffness-proportional damping beta (joint damping beta k)", "s", lo=0)
    thin_wall: bool = flag(False, "two columns of boundary particles for a plate under two spacings thick")
    direction: str = choice("up", "up: clamped by its foot, rising along z; down: clamped by its top, hanging along -z",
                            ("up", "down"))
    angle: float = num(0.0, "a standing plate turned about y from +z towards +x (90: lying along +x, a horizontal "
                       "cantilever; -90: along -x)", "deg", lo=-180.0, hi=180.0)

    # what the checks of the other bodies read: a plate stands at a given pose
    place = "given"
    fairleads: dict = dataclasses.field(default_factory=dict, init=False, repr=False, compare=False)

    def validate(self):
        if self.direction == "down" and self.angle != 0:
            raise SceneError("angle", f"{self.angle:g} deg: a hanging plate (direction = \"down\") hangs along -z; "
                             f"give angle = 0, or a standing plate (direction = \"up\") turned by the angle")

    @property
    def euler(self) -> tuple | None:
        """The plate's turn [deg] as Euler angles (about y by ``angle``; None: upright)."""
        return (0.0, self.angle, 0.0) if self.angle != 0 else None

    @property
    def axis(self) -> tuple:
        """Unit vector (x, y, z) along the plate from its clamp to its free end."""
        if self.direction == "down":
            return (0.0, 0.0, -1.0)
        a = math.radians(self.angle)
        return (math.sin(a), 0.0, math.cos(a))

    @property
    def pos(self) -> tuple:
        """The plate's centre [m] (undeformed)."""
        e = self.axis
        half = [0.5 * self.length * c for c in ((e[0], e[2]) if len(self.base) == 2 else e)]
        return tuple(b + d for b, d in zip(self.base, half))


BODIES = (Box, Cylinder, Sphere, MJCF, ElasticPlate)


# ------------------------------------------------------------------------ moorings
@dataclass(frozen=True)
class PointLoad(Spec):
    """A constant force ``force`` [N] ((x, z) in 2-D, (x, y, z) in 3-D, the world's axes) on
    a line at the material point ``s`` [m] along its unstretched length from the anchor: a
    clump weight or a buoy's net lift, a load hung from a cable (the sph-cable model)."""

    s: float = required(num(None, "where, along the unstretched line from its anchor", "m", lo=0, lo_open=True,
                            optional=False))
    force: tuple = required(vec(None, "the force", "N"))


@dataclass(frozen=True)
class Line(Spec):
    """One mooring line from a fixed ``anchor`` [m] to the fairlead ``"BODY.NAME"``
    (``moorings.MooringLine``). The dynamic models (sph-cable, moordyn) need ``EA`` and
    ``mass_per_length``, MoorDyn also ``diameter`` (an SPH cable without one feels no
    water: a cable in air); the catenary uses ``EA`` when given. The sph-cable also takes
    ``point_loads`` on the line and lets go of a ``released`` line's fairlead end; it and
    the catenary record the positions of the line's material ``points``."""

    fairlead: str = required(text(None, "the fairlead, as BODY.NAME"))
    anchor: tuple = required(vec(None, "anchor position; the seabed is the horizontal plane through it", "m"))
    length: float = required(num(None, "unstretched length", "m", lo=0, lo_open=True, optional=False))
    weight: float = required(num(None, "submerged weight per metre", "N/m", lo=0, lo_open=True,
                                 hi=L.MAX_LINE_WEIGHT, why=L.LINE_WEIGHT_WHY, optional=False))
    EA: float = num(None, "axial stiffness (unset: inextensible)", "N", lo=0, lo_open=True, hi=L.MAX_LINE_EA,
                    why=L.LINE_EA_WHY)
    mass_per_length: float = num(None, "mass per metre in air", "kg/m", lo=0, lo_open=True, hi=L.MAX_LINE_MASS,
                                 why=L.LINE_MASS_WHY)
    diameter: float = num(None, "hydrodynamic diameter", "m", lo=0, lo_open=True, hi=L.MAX_LINE_DIAMETER,
                          why=L.LINE_DIAMETER_WHY)
    name: str = text("", "label in outputs; empty: the fairlead's name", name="label")
    break_load: float = num(None, "tension at which the line breaks (unset: never); reported, and released with "
                            "moorings.release_broken", "N", lo=0, lo_open=True, hi=L.MAX_BREAK_LOAD,
                            why=L.BREAK_LOAD_WHY)
    point_loads: tuple = parts("forces on the line at points along it (the sph-cable model)", PointLoad)
    points: tuple = vecs("material points, arc lengths along the unstretched line from its anchor, whose positions "
                         "are recorded (LINE.pointK_x, ...; the sph-cable and catenary models)", "m", sizes=(0,))
    released: bool = flag(False, "true: the line is let go of at its fairlead at the start (it starts hanging between "
                          "anchor and fairlead, then that end is free: a line parted at the fairlead; the sph-cable "
                          "model)")

    def validate(self):
        if self.fairlead.count(".") != 1 or not all(is_name(x) for x in self.fairlead.split(".")):
            raise SceneError("fairlead", f"{self.fairlead!r}: give it as BODY.NAME, two names of letters, digits, "
                             f"'_' and '-', e.g. \"box.left\"")
        for i, p in enumerate(self.point_loads):
            if p.s >= self.length:
                raise SceneError(f"point_loads[{i}].s", f"{p.s:g} m is not inside the line (0 .. {self.length:g} m "
                                 "from its anchor); give a point on it")
        for i, x in enumerate(self.points):
            if not 0.0 <= x <= self.length:
                raise SceneError(f"points[{i}]", f"{x:g} m is not on the line (0 .. {self.length:g} m from its "
                                 "anchor); give arc lengths along it")


@dataclass(frozen=True)
class Moorings(Spec):
    """The mooring lines and the one field that picks their model: ``"catenary"``
    (quasi-static, Barreiro et al. 2016, §3), ``"sph-cable"`` (Dinçer & Demir 2020), ``"moordyn"`` or ``"fmu"``
    (the catenary exported as an FMU and run through FMPy). A line with a ``break_load``
    is watched: the time, line and tension at which its fairlead tension first passes it
    go into the log and ``summary.json`` (``line_breaks``). ``seabed``, ``damping`` and the
    lines' ``point_loads`` and ``released`` are the sph-cable model's, ``points`` its and
    the catenary's (another model refuses them); with ``probes.energy`` the sph-cable
    records each line's mechanical energy."""

    model: str = choice("catenary", "the mooring model", MOORINGS)
    lines: tuple = parts("the lines", Line)
    segments: int = whole(20, "segments per line of the dynamic models (SPH-cable particles, MoorDyn segments)",
                          lo=2)
    release_broken: bool = flag(False, "true: a line whose tension passes its break_load stops acting (false: the "
                                "break is reported and the line holds)")
    seabed: bool = flag(True, "false: the lines hang free, no seabed under them (a cable between two supports in "
                        "air; the sph-cable model)")
    damping: float = num(None, "mass-proportional damping rate of the lines (unset: the model's own; the sph-cable "
                         "model, Dinçer & Demir 2020, Eq. 12, 0.04 1/s)", "1/s", lo=0)

    def validate(self):
        if not self.lines:
            raise SceneError("lines", "give at least one line (or leave moorings out)")
        for i, ln in enumerate(self.lines):
            for key in MOORINGS[self.model].line_fields:
                if getattr(ln, key) is None:
                    raise SceneError(f"lines[{i}].{key}", f"the {self.model!r} model needs it for every line; "
                                     f"give it, or use model = \"catenary\"")
        takes = MOORINGS[self.model].extras
        unusual = [("seabed", not self.seabed), ("damping", self.damping is not None)]
        unusual += [(f"lines[{i}].{k}", bool(getattr(ln, k))) for i, ln in enumerate(self.lines)
                    for k in ("point_loads", "points", "released")]
        for key, given in unusual:
            if given and key.split(".")[-1] not in takes:
                raise SceneError(key, f"the {self.model!r} model does not take it; give model = \"sph-cable\", or "
                                 "leave it out")


# ------------------------------------------------------------------------ probes and coupling
@dataclass(frozen=True)
class Patch(Spec):
    """A wall-pressure transducer (``fluid.probes.wall_patch_pressure``): the fluid's normal
    force on the wall behind a patch of ``size`` [m] centred at ``centre`` on the wall's
    face, ``normal`` pointing into the water, over its area."""

    name: str = required(text(None, "the probe's name", name=True))
    centre: tuple = required(vec(None, "centre on the wall face", "m"))
    normal: tuple = required(vec(None, "normal into the water", nonzero=True))
    size: float = required(num(None, "length (2-D) or diameter (3-D)", "m", lo=0, lo_open=True, optional=False))


@dataclass(frozen=True)
class Probes(Spec):
    """What is sampled every ``world.sample_every``. ``gauges``: free-surface gauges at
    x [m] (2-D) or (x, y) [m] (3-D), the elevation above the still water; ``pressure``:
    wall patches (only with them does the SPH fluid compute the walls' loads, up to a
    quarter of a 3-D step); ``motion``: the bodies whose surge, sway, heave, roll, pitch, yaw are
    recorded (``["all"]``: every body); ``tensions``: each fairlead's tension;
    ``loads``: fluid and mooring force on each body; ``energy``: the SPH fluid's energy.
    Gauges and patches are fixed to the tank: under ``base_motion`` they move with it (and
    an elastic plate's deflection is read in the tank's frame)."""

    gauges: tuple = gauges("wave gauges: x (2-D) or (x, y) (3-D)")
    pressure: tuple = parts("wall-pressure patches", Patch)
    motion: tuple = names("bodies whose motion is recorded; [\"all\"]: every body", default=("all",))
    tensions: bool = flag(True, "fairlead tensions")
    loads: bool = flag(True, "fluid and mooring loads on each body")
    energy: bool = flag(False, "kinetic and potential energy of the SPH fluid; the SPH cables' mechanical energy")


@dataclass(frozen=True)
class Coupling(Spec):
    """How the coupler exchanges loads (``cosim.coupler.Coupler``). ``"auto"`` scheme:
    fluid-first with the SPH fluid (bodies receive exactly the impulse the fluid
    exchanged), explicit where nothing gives the bodies loads (no fluid and no mooring:
    every scheme steps them alike), predictor-corrector otherwise."""

    scheme: str = choice("auto", "coupling scheme", ("auto", "explicit", "predictor-corrector", "fluid-first"))
    light_body: str = choice("auto", "remedy for bodies lighter than the fluid they displace",
                             ("auto", "none", "subiterate", "added-mass"))
    lines: str = choice("auto", "exchange with dynamic mooring lines (SPH cable, MoorDyn): advanced with the bodies "
                        "until their mean force agrees, or their force at the step's start held",
                        ("auto", "subiterate", "explicit"))
    dt: float = num(None, "fixed coupling step (unset: the participants' stable step): the step taken, so it divides "
                    "the output intervals (world.sample_every, snapshot_every with particles, checkpoint_every) and is "
                    "not above any participant's stable step at the start, else it is refused; summary.json's "
                    "coupling counts every step by what set it", "s", lo=0, lo_open=True)
    fluid_steps: int = whole(1, "the SPH fluid's stable steps per exchange with the bodies and lines (1: each step): "
                             "above 1 the fluid sub-steps across an exchange, the bodies' particles moving with the "
                             "bodies' motion at its start and the bodies taking the impulse the fluid exchanged; it "
                             "saves the exchange's own work where that is a large part of a step (small scenes), for "
                             "a lag of (fluid_steps - 1) / 2 fluid steps in the bodies' motion", lo=1, hi=100)
    body_timestep: float = num(1e-3, "MuJoCo's largest step", "s", lo=0, lo_open=True)


# ------------------------------------------------------------------------ the scene
@dataclass(frozen=True)
class Scene(Spec):
    """One coupled run. See the module docstring; ``Scene.from_toml(path)``,
    ``scene.to_toml()``, ``scene.run(out=...)``."""

    world: World = part(World(), "dimension, gravity, duration, output times", World)
    fluid: Spec = part(NoFluid(), "none, analytic, potential or SPH", FLUID_MODELS)
    domain: Spec = part(None, "the SPH fluid's container (the analytic fluid: a flume, for its depth and wavemaker)",
                        DOMAINS)
    waves: Spec = part(None, "a flume's wavemaker, or regular or irregular waves on the analytic fluid", WAVE_KINDS)
    base_motion: Spec = part(None, "motion of the tank and of the elastic plates clamped to it", BASE_MOTIONS)
    bodies: tuple = parts("the bodies", SHAPES)
    moorings: Moorings = part(None, "mooring lines and their model", Moorings)
    probes: Probes = part(Probes(), "what is recorded", Probes)
    coupling: Coupling = part(Coupling(), "coupling scheme and light-body remedy", Coupling)
    name: str = text("scene", "the scene's name: the default output folder out/NAME, plot titles", name=True)

    def validate(self):
        from cosim.scene.checks import check_scene
        from cosim.scene.timing import check_fixed_step

        check_scene(self)
        check_fixed_step(self)

    # -- convenience (the implementations live in their own modules)
    @classmethod
    def from_toml(cls, path) -> "Scene":
        from cosim.scene.toml_io import read_toml

        return read_toml(path)

    @classmethod
    def from_dict(cls, data: dict, base_dir=None) -> "Scene":
        from cosim.scene.toml_io import from_dict

        return from_dict(data, base_dir)

    def to_dict(self) -> dict:
        from cosim.scene.toml_io import to_dict

        return to_dict(self)

    def to_toml(self, path=None) -> str:
        from cosim.scene.toml_io import to_toml

        return to_toml(self, path)

    def with_values(self, assignments) -> "Scene":
        """This scene with ``KEY.PATH=VALUE`` assignments applied (``cosim run --set``)."""
        from cosim.scene.toml_io import with_values

        return with_values(self, assignments)

    @property
    def body_names(self) -> list[str]:
        from cosim.scene.checks import body_names

        return body_names(self)

    def run(self, out=None, *, resume: bool = False, resume_any_version: bool = False, overwrite: bool = False,
            progress=None, yes: bool = False, ask=None):
        """Run the scene, writing its outputs into ``out`` (default ``out/<name>``), a new or
        empty folder; returns a :class:`cosim.scene.runner.Results`. ``overwrite``: clear
        the folder of an earlier run first; ``resume``: continue from the checkpoint in
        ``out`` (``resume_any_version``: even one written by other code). A run whose
        estimated CPU time passes a day (:mod:`cosim.scene.cost`) runs with ``yes``, or
        where ``ask(question)`` returns True; else it is refused."""
        from cosim.scene.runner import run

        return run(self, out if out is not None else Path("out") / self.name, resume=resume,
                   resume_any_version=resume_any_version, overwrite=overwrite, progress=progress, yes=yes, ask=ask)


__all__ = ["World", "NoFluid", "Analytic", "Potential", "SPH", "Block", "Tank", "Beach", "Absorber", "Flume", "InclinedTank",
           "CylinderTank", "PolygonTank", "ArchRib", "NearField", "OpenWater", "arch_rib_monitors", "Piston", "Flap",
           "PaddleRecord",
           "LinearWaves", "RegularWaves", "IrregularWaves", "StillWaves",
           "Shake", "Roll", "RollTable", "TableMotion",
           "Earthquake", "Record", "GroundMotion", "Box", "Cylinder", "Sphere", "MJCF", "ElasticPlate", "Line",
           "Moorings", "PointLoad", "Patch", "ForcedMotion", "ForcedTable",
           "Probes", "Coupling",
           "Scene", "SceneError", "SETUPS"]
