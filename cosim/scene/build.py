"""From a scene to participants and a coupler, importing only what the scene contains: no
fluid, no fluid kernel compiled; no bodies, no MuJoCo.

What the builder derives so that the user does not: the fluid's set-up
(:mod:`cosim.scene.setup`), wall layers from the kernel (ceil(2 h / dx), the support), a
flume's floor behind the paddle (half the stroke plus dx), the heights of floating bodies
(:mod:`cosim.scene.placement`), one gravity for fluid, bodies and moorings, the coupling
scheme (fluid-first with the SPH fluid), the wavemaker or base motion attached to the
walls (and the base motion to the clamps of elastic plates), a standing plate beyond its
self-weight buckling load bent into its buckling mode, and fairlead sites named
``BODY.NAME`` in the MuJoCo model. What the user should know of the scene as built (a
plate beyond its buckling load, an MJCF model's world parts that do not ride a moving
tank, an MJCF model's own gravity replaced by the world's) is logged as a warning and kept
in :attr:`Built.warnings`.
"""

from __future__ import annotations

import dataclasses
import logging
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from cosim.scene.spec import (MJCF, ROLLS, SPH, Analytic, LinearWaves, CylinderTank, Earthquake, ElasticPlate, Flap,
                              Flume, GroundMotion, InclinedTank, NearField, OpenWater, Piston, PolygonTank, Potential,
                              Roll, RollTable, Shake, TableMotion, Tank)

PADDLE, WALLS = 1, 0  # the flume's paddle group and every tank's wall group

log = logging.getLogger(__name__)


@dataclass
class Built:
    """A scene's participants, ready to run."""

    coupler: object
    fluid: object = None  #: the coupler's fluid participant (SPHFluid, AnalyticFluid), or the bare SPH Fluid
    sph: object = None  #: the fluid.solver.Fluid inside, when the scene has the SPH fluid
    bodies: object = None  #: MujocoBodies, or None
    mooring: object = None  #: the mooring participant, or None
    line_names: list = field(default_factory=list)  #: one label per line, in order
    setup: object = None  #: cosim.scene.setup.Setup of the SPH fluid
    level: float | None = None  #: still-water level [m]
    start_heights: dict = field(default_factory=dict)  #: floating bodies: their computed centre height [m]
    wavemaker: object = None  #: fluid.wavemaker.RegularWavemaker, for regular waves
    base_motion: object = None  #: the tank's rigid motion ``motion(t, ref) -> (pos, vel)`` (fluid.motion), or None
    plates: dict = field(default_factory=dict)  #: elastic plates: name -> bodies.elastic.BeamModel
    warnings: list = field(default_factory=list)  #: what the user is warned of (logged, and in summary.json)
    near_field: object = None  #: a near field's box (fluid.nearfield.BoxChoice), as chosen
    sph_domain: object = None  #: a moving tank's SPH domain (cosim.scene.sph_domain.MovingDomain), as chosen
    sea: object = None  #: a near field's incident sea (fluid.waves)
    controllers: list = field(default_factory=list)  #: the fluid's controllers (fluid.solver.Fluid.controllers)


def site_name(fairlead: str) -> str:
    """The MuJoCo site of a builder body's fairlead ``BODY.NAME``."""
    return fairlead.replace(".", "__")


def water_level(scene) -> float | None:
    d = scene.domain
    if isinstance(scene.fluid, (Analytic, Potential)):
        return scene.fluid.level if d is None else d.level  # a flume's depth: its seabed at z = 0
    if d is None:
        return None
    if isinstance(d, Tank) and d.water:
        return max(b.hi[-1] for b in d.water)
    return d.fill_level if isinstance(d, PolygonTank) else d.level


def fluid_config(scene, setup, numbers_only: bool = False):
    """The SPH fluid's FluidConfig from the scene and its set-up; ``numbers_only``: its
    settings on the CPU, for checks that need its numbers (h, c0) and not its device (a
    GPU that this machine may not have) nor a near-field channel's planes (which the box's
    choice, itself taking h from here, places)."""
    from fluid.solver import FluidConfig

    cfg = {k: v for k, v in setup.config.items() if not (numbers_only and k == "device")}
    if isinstance(scene.domain, NearField) and scene.domain.symmetry:
        cfg["symmetry_y"] = 0.0  # fluid.mirror
    if isinstance(scene.domain, Flume) and scene.domain.sides == "symmetry":  # a slice between two planes
        cfg["symmetry_y"], cfg["symmetry_y_hi"] = 0.0, scene.domain.width
    if isinstance(scene.domain, NearField) and scene.domain.sides == "symmetry" and not numbers_only:
        # a channel between two planes: its sides as the box chooses them (box_for takes
        # only the numbers of this config, so it does not come back here)
        from cosim.scene.nearfield import box_for

        cfg["symmetry_y"], cfg["symmetry_y_hi"] = box_for(scene).y
    if isinstance(scene.domain, OpenWater):  # particles that leave the box are removed
        cfg["domain_lo"], cfg["domain_hi"] = scene.domain.lo, scene.domain.hi
    # the walls' loads only where a probe reads them (wall-pressure patches): a scene pays
    # for what it contains, and the fluid's motion and step are the same either way
    return FluidConfig(dim=scene.world.dim, dx=scene.fluid.dx, g=scene.world.gravity,
                       wall_loads=bool(scene.probes.pressure), **cfg)


def _wavemaker(scene):
    from fluid.wavemaker import MotionRecord, RegularWavemaker, flap, piston

    w = scene.waves
    if isinstance(w, (Piston, Flap)):
        wm = RegularWavemaker(w.kind, w.height, w.period, scene.domain.depth, w.ramp, scene.world.gravity)
        return wm, wm.paddle(), wm.stroke if w.kind == "piston" else wm.stroke * scene.domain.height / wm.depth
    rec = MotionRecord.from_file(w.file, w.column, w.scale, w.t_shift)
    zero = rec(0.0)[0] if w.zero_at_start else 0.0
    reach = float(np.abs(rec.value - zero).max())
    motion = _from_zero(rec, zero) if w.zero_at_start else rec
    if w.paddle == "piston":
        return None, piston(motion), 2 * reach
    return None, flap(motion, hinge=(0.0, 0.0)), 2 * reach * scene.domain.height


def _from_zero(rec, zero: float):
    """A paddle record ``rec`` (``t -> (value, rate)``) less ``zero``."""
    def motion(t):
        value, rate = rec(t)
        return value - zero, rate

    return motion


def _base_motion(scene):
    from fluid.motion import Combined, Harmonic, Ramped, Rotation, Stopped, Tabulated, Translation, read_at2

    def _scaled(rec, k):  # the baseline correction is linear in the record: scale it with the values
        return rec if k == 1.0 else Tabulated(rec.times, tuple(np.asarray(rec.values) * k), rec.quantity,
                                              tuple(np.asarray(rec.baseline) * k))

    b = scene.base_motion
    if isinstance(b, Shake):
        sig = (Harmonic(b.amplitude, b.period) if b.amplitude is not None
               else Harmonic.from_peak_acceleration(b.acceleration, b.period, from_rest=True))
        m = Translation(b.direction, sig)
        if b.hold:  # faded in, then cut at stop and held where it got to
            m = m.ramped(b.ramp) if b.ramp > 0 else m
            return Translation(b.direction, Stopped(m.signal, b.stop, fade=0.0))
        return m.ramped(b.ramp, 0.0, b.stop) if (b.ramp > 0 or b.stop is not None) else m
    if isinstance(b, Roll):
        sig = Harmonic(math.radians(b.amplitude), b.period)
        if b.ramp > 0:
            sig = Ramped(sig, b.ramp)
        return Rotation(b.point, sig, b.axis)
    if isinstance(b, RollTable):
        return Rotation(b.point, roll_record(b), b.axis)
    if isinstance(b, TableMotion):
        rows = np.loadtxt(b.file, comments="#", delimiter=None, ndmin=2)
        sig = Tabulated(tuple(rows[:, 0]), tuple(rows[:, b.column] * b.scale), b.quantity)
        return Translation(b.direction, sig)
    if isinstance(b, GroundMotion):
        sigs = [_scaled(read_at2(c.file, b.baseline_degree), b.scale * c.scale) for c in b.components]
        if b.stop is not None:
            sigs = [Stopped(x, b.stop, b.fade) for x in sigs]
        return Combined(tuple(Translation(c.direction, x) for c, x in zip(b.components, sigs)))
    assert isinstance(b, Earthquake)
    return Translation(b.direction, _scaled(read_at2(b.file, b.baseline_degree), b.scale))


def roll_record(b):
    """A :class:`RollTable`'s angle [rad] as ``fluid.motion.Tabulated`` (the table's degrees
    times its scale)."""
    from fluid.motion import Tabulated

    rows = np.loadtxt(b.file, comments="#", delimiter=None, ndmin=2)
    return Tabulated(tuple(rows[:, 0]), tuple(np.radians(rows[:, b.column] * b.scale)), "displacement")


def far_field_wave(scene):
    """The wavemaker of a flume scene and the wave it makes far from its paddle, as the
    analytic fluid's :class:`fluid.analytic.LinearWave` (one field swaps the SPH fluid's
    flume for the analytic fluid).

    Linear wavemaker theory (Dean & Dalrymple 1991 §6.2; ``fluid.wavemaker``): the paddle
    moves as ``x_p = (S/2) r(t) sin ωt`` (piston; a flap turns by ``x_p / d``), ``S`` its
    stroke; the progressive mode it radiates has the height ``H = S · (H/S)(kd)`` (piston
    ``2 (cosh 2kd − 1) / (sinh 2kd + 2kd)``, flap ``4 (sinh kd / kd)(kd sinh kd − cosh kd +
    1) / (sinh 2kd + 2kd)``) and its horizontal velocity at the paddle is in phase with the
    paddle's velocity ``(S/2) ω cos ωt``, so ``η = (H/2) cos(k x − ω t)``: the wave's crest
    at x = 0 at t = 0, its phase at a body at ``x`` is ``k x``. The paddle's fade-in
    reaches x after ``x / c_g`` (``LinearWave.source = 0``).

    What this approximates: the evanescent (standing) modes near the paddle, which decay
    as ``exp(−k_n x)`` (within about 2-3 depths of it), are left out; the wave is the
    far-field one everywhere ahead of the paddle (x >= 0; behind it, x < 0, no water). No
    reflection from the far wall or a beach (a perfectly absorbing end); no second-order
    (Stokes) or set-down terms; the paddle's own displacement is not the water's edge. In
    3-D the wave is long-crested across the flume's width (the paddle spans it; no side-wall
    effects)."""
    from fluid.analytic import LinearWave
    from fluid.wavemaker import RegularWavemaker, height_to_stroke

    w, d = scene.waves, scene.domain
    wm = RegularWavemaker(w.kind, w.height, w.period, d.depth, w.ramp, scene.world.gravity)
    H = wm.stroke * height_to_stroke(w.kind, wm.k * d.depth)  # what the paddle's stroke makes
    return wm, LinearWave(H, w.period, d.depth, 0.0, w.ramp * w.period, scene.world.gravity, source=0.0)


def incident_sea(scene):
    """The analytic fluid's incident sea: what the scene's waves (an incident sea,
    :class:`cosim.scene.seas.IncidentSea`) make of it."""
    return scene.waves.sea(scene)


def _frame(scene) -> dict:
    """An incident sea's still water: at the scene's level, its heading, the world's gravity."""
    return dict(direction=scene.waves.direction, level=water_level(scene), g=scene.world.gravity)


def regular_sea(scene):
    """Waves of kind "regular" as :class:`fluid.waves.RegularWave`, its ramp in seconds
    (the scene gives periods)."""
    from fluid import waves as fw

    w = scene.waves
    return fw.RegularWave(w.height, w.period, w.depth, theory=w.theory, phase=w.phase, ramp=w.ramp * w.period,
                          **_frame(scene))


def irregular_sea(scene):
    """Waves of kind "irregular" (:mod:`fluid.waves`): a spectrum's components enough for
    the run's duration, or a record that must last it; the ramp in seconds (the scene
    gives peak periods: of the spectrum, or of the record's largest component)."""
    from fluid import waves as fw

    w = scene.waves
    if w.spectrum == "series":
        at = (0.0, 0.0) if w.at is None else tuple(w.at)
        sea = fw.RecordedSea.from_file(w.file, w.depth, w.column, at=at, min_period=w.min_period,
                                       duration=scene.world.duration, **_frame(scene))
        return dataclasses.replace(sea, ramp=w.ramp * sea.peak_period)
    wp = 2 * math.pi / w.tp
    return fw.SpectralSea(w.hs, w.tp, w.depth, spectrum=w.spectrum, gamma=3.3 if w.gamma is None else w.gamma,
                          seed=w.seed, n_components=w.components, duration=scene.world.duration,
                          band=None if w.band is None else (w.band[0] * wp, w.band[1] * wp),
                          ramp=w.ramp * w.tp, **_frame(scene))


def domain_points(scene, cfg, back: float = 0.0):
    """(fluid points, walls) of the scene's domain: walls as ``(points, kind, group)``,
    ``layers`` = ceil(2 h / dx) wall layers (the kernel's support)."""
    return domain_water(scene, cfg, back)[:2]


def domain_water(scene, cfg, back: float = 0.0):
    """:func:`domain_points`, and in a tank under a tilted gravity its water turned to lie
    at rest under it (the level fill's particles, ``fluid.geometry.water_under_gravity``)
    with its surface's height along -g [m] (a plane normal to gravity); that height is None
    where the water lies as the domain lays it (level, or explicit water blocks)."""
    from cosim.errors import InputError
    from fluid.geometry import water_under_gravity

    pts, walls = _domain_points(scene, cfg, back)
    d = scene.domain
    if not scene.world.tilted or isinstance(d, (Flume, OpenWater)) or (isinstance(d, Tank) and d.water):
        return pts, walls, None
    brim, _ = _domain_points(scene, cfg, back, brim=True)
    pts, surface = water_under_gravity(brim, len(pts), cfg.gravity)
    top = float(brim[:, -1].max())
    if pts[:, -1].max() >= top - 1e-9:
        raise InputError(f"world.gravity: {list(scene.world.gravity)} m/s^2, {scene.world.tilt_deg:.3g} deg from -z: "
                         f"the water at rest under it, its surface normal to gravity, reaches the top of the tank's "
                         f"walls; give the tank more height (domain.height) or less water (domain.depth), or a "
                         f"gravity nearer -z")
    return pts, walls, surface


def _domain_points(scene, cfg, back: float = 0.0, brim: bool = False):
    """:func:`domain_points`; ``brim``: a tank's lattice filled to the top of its walls."""
    from fluid.geometry import block, tank_walls, tank_with_water
    from fluid.particles import Kind
    from fluid.shapes import cylinder_tank, inclined_tank, polygon_tank

    d, dx, dim = scene.domain, cfg.dx, cfg.dim
    layers = math.ceil(2.0 * cfg.h_coef - 1e-9)
    walls_kind = Kind.MOVING_WALL if scene.base_motion is not None else Kind.FIXED_WALL  # a shaken tank moves
    if isinstance(d, Flume):
        from fluid.flume import flume

        fl = flume(dx, d.length, d.depth, d.height, layers=layers, back=back,
                   beach=None if d.beach is None else (d.beach.toe, d.beach.slope), width=d.width,
                   side_walls=d.sides == "walls")
        return fl.fluid, fl.walls
    if isinstance(d, OpenWater):
        return np.concatenate([block(b.lo, b.hi, dx) for b in d.water]), []
    if isinstance(d, Tank) and d.water:
        inner = [d.length] + ([d.width] if dim == 3 else []) + [d.height]
        walls = np.concatenate([tank_walls(np.zeros(dim), np.array(inner), dx, layers), *_inner_walls(d, dx, layers)])
        pts = np.concatenate([block(b.lo, b.hi, dx) for b in d.water])
        return pts, [(walls, walls_kind, WALLS)]
    if isinstance(d, Tank) and d.walls:
        built = tank_with_water(dim, dx, d.length, d.height if brim else d.depth, d.height, d.width or 0.0, layers,
                                cfg.rho0)
        ps = built.particles
        fluid = (ps.kind == Kind.FLUID) & ~_in_blocks(ps.pos, d.walls, 0.5 * dx)
        walls = np.concatenate([ps.pos[ps.kind != Kind.FLUID], *_inner_walls(d, dx, layers)])
        return ps.pos[fluid].copy(), [(walls, walls_kind, WALLS)]
    if isinstance(d, Tank):
        built = tank_with_water(dim, dx, d.length, d.height if brim else d.depth, d.height, d.width or 0.0, layers,
                                cfg.rho0)
    elif isinstance(d, InclinedTank):
        built = inclined_tank(dim, dx, d.angle, d.length, d.height if brim else d.depth, d.height, d.width or 1.0,
                              layers, cfg.rho0)
    elif isinstance(d, CylinderTank):
        built = cylinder_tank(dx, d.diameter, d.height if brim else d.depth, d.height, layers, cfg.rho0)
    else:
        built = polygon_tank(d.vertices, dx, None if brim else d.fill_level, layers, cfg.rho0)
    ps = built.particles
    fluid = ps.kind == Kind.FLUID
    return ps.pos[fluid].copy(), [(ps.pos[~fluid].copy(), walls_kind, WALLS)]


def _inner_walls(d, dx: float, layers: int) -> list:
    """The wall particles of a tank's solid blocks (``domain.walls``), each checked to be at
    least ``layers`` spacings thick (the kernel's support behind a wetted face)."""
    from cosim.scene.fields import SceneError
    from fluid.geometry import block

    out = []
    for i, w in enumerate(d.walls):
        thin = min(h - lo for lo, h in zip(w.lo, w.hi))
        if math.floor(thin / dx + 1e-9) < layers:
            raise SceneError(f"domain.walls[{i}]", f"the block {list(w.lo)} .. {list(w.hi)} m is {thin:.4g} m thick, "
                             f"fewer than the walls' {layers} layers of fluid.dx = {dx:g} m (the kernel's support "
                             f"2h behind a wetted face): the water beside it would not be held, and would feel the "
                             f"other side through it; make it at least {layers * dx:.4g} m thick, or refine dx")
        out.append(block(w.lo, w.hi, dx))
    return out


def _in_blocks(points, blocks, margin: float) -> np.ndarray:
    """Which ``points`` lie within ``margin`` [m] of the inside of any of ``blocks`` (a
    point that far outside a face, as a lattice neighbour is, is kept)."""
    inside = np.zeros(len(points), bool)
    for b in blocks:
        lo, hi = np.asarray(b.lo) - margin + 1e-9, np.asarray(b.hi) + margin - 1e-9
        inside |= np.all((points > lo) & (points < hi), axis=1)
    return inside


def _surface_heights(scene, points):
    """The free surface over each fluid point [m]: the top of its water block, or the level;
    in open water the point itself (water falling freely, or without gravity, carries no
    hydrostatic pressure)."""
    d = scene.domain
    if isinstance(d, OpenWater):
        return points[:, -1].copy()
    if isinstance(d, Tank) and d.water:
        top = np.full(len(points), -np.inf)
        for b in d.water:
            inside = np.all((points >= np.array(b.lo)) & (points <= np.array(b.hi)), axis=1)
            top[inside] = np.maximum(top[inside], b.hi[-1])
        return top
    return np.full(len(points), water_level(scene))


def _support(scene):
    """What the clamps of the scene's elastic plates are fixed to (:class:`bodies.elastic.Support`):
    None in a tank at rest; under base motion the tank, on slides along the scene's world
    axes (x, z in 2-D; x, y, z in 3-D) for a translation (shake, table, earthquake, ground
    motion), on the roll's hinge for a roll."""
    from bodies.elastic import Support

    b, dim = scene.base_motion, scene.world.dim
    if b is None:
        return None
    if isinstance(b, ROLLS):
        point = (b.point[0], 0.0, b.point[1]) if dim == 2 else tuple(b.point)
        axis = (0.0, 1.0, 0.0) if dim == 2 else tuple(np.asarray(b.axis) / np.linalg.norm(b.axis))
        return Support(hinge=(point, axis))
    return Support(slides=((1.0, 0.0, 0.0), (0.0, 0.0, 1.0)) if dim == 2 else tuple(map(tuple, np.eye(3))))


def support_drive(motion):
    """The tank's rigid motion (``fluid.motion``: a translation, several, or a turn) as the
    positions, velocities and accelerations of the support joints of :func:`_support`, a
    callable of time for :meth:`bodies.mujoco_bodies.MujocoBodies.drive`."""
    from fluid.motion import Combined, Rotation, Translation

    if isinstance(motion, Rotation):
        return lambda t: tuple(np.array([x]) for x in motion.signal.state(t))
    if isinstance(motion, Translation):
        e = np.asarray(motion.direction)
        return lambda t: tuple(x * e for x in motion.signal.state(t))
    assert isinstance(motion, Combined)
    return motion.state


def _water_top(scene, b) -> float | None:
    """The still water's level [m] around an elastic plate's foot at the start: the
    domain's level, or the top of the water block it stands in (None: in air)."""
    d = scene.domain
    if not isinstance(scene.fluid, SPH):
        return None
    if isinstance(d, OpenWater) or (isinstance(d, Tank) and d.water):
        foot = b.base
        tops = [w.hi[-1] for w in d.water
                if all(lo <= x <= hi for lo, x, hi in zip(w.lo[:-1], foot[:-1], w.hi[:-1])) and w.lo[-1] <= foot[-1]]
        return max(tops, default=None)
    return water_level(scene)


def self_weight(scene, b):
    """A standing elastic plate's own weight and its buckling (Greenhill's problem,
    :func:`bodies.elastic.self_weight_buckling`): ``(P, factor, slope)``, the weight it
    carries [N] (2-D: per metre), the factor on it at which the straight plate buckles
    (below 1: beyond the limit) and the buckling mode's slope. The weight per length is
    ``rho_s g h W`` in air and ``(rho_s - rho_w) g h W`` below the still water around its
    foot: a submerged column buckles under its effective weight, the water's pressure on
    its bent faces bearing the rest (the effective tension of risers and columns in water,
    Sparks 2007, Fundamentals of Marine Riser Mechanics). ``g`` is gravity's component
    along the plate towards its clamp, ``-g . e`` (``e`` the plate's :attr:`axis`): a plate
    hanging, or turned so that gravity pulls it away from its clamp, is in tension (or,
    across gravity, unloaded along its length) and cannot buckle: ``(P, inf, None)``, P
    the pull [N] (2-D: per metre) at its clamp."""
    from bodies.elastic import self_weight_buckling

    dim = scene.world.dim
    g = -sum(a * c for a, c in zip(scene.world.g_vector, b.axis)) + 0.0
    area = b.thickness * (1.0 if dim == 2 else b.width)
    q_air = b.density * g * area
    if g <= 1e-12 * scene.world.g:  # across gravity to round-off (cos 90 deg is 6e-17): no compression
        return -q_air * b.length + 0.0, math.inf, None
    loads, top = [], _water_top(scene, b)
    wet = 0.0 if top is None else min(max(top - b.base[-1], 0.0), b.length)
    if wet > 0:
        loads.append((0.0, wet, (b.density - scene.fluid.rho0) * g * area))
    if wet < b.length:
        loads.append((wet, b.length, q_air))
    EI = b.E * (1.0 if dim == 2 else b.width) * b.thickness**3 / 12.0
    factor, slope = self_weight_buckling(b.length, EI, loads)
    return sum(q * (s1 - s0) for s0, s1, q in loads), factor, slope


def buckling_warning(scene, i: int) -> str | None:
    """What to tell the user of ``bodies[i]``, an elastic plate, when it stands beyond its
    self-weight buckling load (:func:`self_weight`); None when it does not."""
    from bodies.elastic import GREENHILL, IMPERFECTION

    b = scene.bodies[i]
    P, factor, _ = self_weight(scene, b)
    if factor >= 1.0:
        return None
    EI = b.E * (1.0 if scene.world.dim == 2 else b.width) * b.thickness**3 / 12.0
    per = " per metre" if scene.world.dim == 2 else ""
    top = _water_top(scene, b)
    wet = "; below the still water its weight less its buoyancy" if top is not None and top > b.base[-1] else ""
    return (f"bodies[{i}] ('{b.name}'): the elastic plate stands on its clamped foot under its own weight beyond its "
            f"buckling load: it carries {P:.4g} N{per} (mean q L^3 / (E I) = {P * b.length**2 / EI:.4g}{wet}), and a "
            f"column clamped at its foot and free at its top buckles under {factor * P:.4g} N{per} (Greenhill 1881: "
            f"q L^3 / (E I) = {GREENHILL:.4g} for a uniform weight q per length). The "
            f"straight plate is unstable: it starts bent in its buckling mode, its tip {IMPERFECTION * b.length:.3g} m "
            f"(L/{1 / IMPERFECTION:.0f}) {'along +x' if b.angle == 0 else 'across it'}, so that it buckles as a real "
            f"one would; a stiffer (E, thickness) or shorter plate stands")


def plates(scene) -> dict:
    """The scene's elastic plates as MuJoCo chains (``bodies.elastic.elastic_beam``), by
    name; under base motion their clamps on the tank's support (:func:`_support`)."""
    from bodies.elastic import elastic_beam

    dim, out, support = scene.world.dim, {}, _support(scene)
    for b in scene.bodies:
        if isinstance(b, ElasticPlate):
            base = (b.base[0], 0.0, b.base[1]) if dim == 2 else tuple(b.base)
            out[b.name] = elastic_beam(b.name, b.length, b.thickness, E=b.E, rho=b.density,
                                       width=1.0 if dim == 2 else b.width, nu=b.nu, n_elements=b.elements,
                                       base=base, beta=b.damping, thin_wall=b.thin_wall, direction=b.direction,
                                       support=support, angle=b.angle)
    return out


def _mjcf_bodies(scene, level, rho):
    """The MuJoCo model of the scene's builder bodies, floating ones at their computed height;
    elastic plates as chains, MuJoCo's step at most half the stiffest chain's stable step."""
    from bodies import builders

    from cosim.scene.placement import floating_height

    dim, parts, heights = scene.world.dim, [], {}
    lines = scene.moorings.lines if scene.moorings is not None else ()
    beams = plates(scene)
    timestep = min([scene.coupling.body_timestep] + [0.5 * m.stable_dt() for m in beams.values()])
    for i, b in enumerate(scene.bodies):
        if isinstance(b, ElasticPlate):
            parts.append(beams[b.name].xml)
            continue
        mine = [k for k, ln in enumerate(lines) if ln.fairlead.split(".")[0] == b.name]
        if b.place == "floating":
            z = floating_height(b, dim, level, rho, scene.world.gravity, [lines[k] for k in mine], i,
                                [f"moorings.lines[{k}]" for k in mine])
            heights[b.name] = z
            pos = (b.pos[0], 0.0, z) if dim == 2 else (b.pos[0], b.pos[1], z)
        else:
            pos = (b.pos[0], 0.0, b.pos[1]) if dim == 2 else tuple(b.pos)
        sites = {site_name(f"{b.name}.{k}"): ((p[0], 0.0, p[1]) if dim == 2 else p) for k, p in b.fairleads.items()}
        parts.append(b.mjcf(pos, dim, sites))
    xml = builders.scene(*parts, gravity=scene.world.g_vector, timestep=timestep)
    return xml, heights


def _bodies(scene, level, rho, warnings=None):
    from bodies.mujoco_bodies import MujocoBodies

    if any(isinstance(b, MJCF) for b in scene.bodies):
        m = scene.bodies[0]
        bodies = MujocoBodies(m.file, bodies=list(m.bodies) or None)
        own, world = bodies.model.opt.gravity.tolist(), list(scene.world.g_vector)
        if own != world and warnings is not None:  # one gravity for every participant: the world's
            warnings.append(f"bodies[0].file: the MJCF model's own gravity {own} m/s^2 is replaced by the world's, "
                            f"{world} m/s^2 (world.gravity = {scene.world.gravity}): one gravity for every "
                            f"participant")
        bodies.set_gravity(world)
        return bodies, {}
    xml, heights = _mjcf_bodies(scene, level, rho)
    if not any(isinstance(b, ElasticPlate) for b in scene.bodies):
        return MujocoBodies(xml), heights
    beams = plates(scene)  # a plate couples every link, the welded foot's too (its load goes into the clamp)
    coupled = [n for b in scene.bodies for n in (beams[b.name].link_names if b.name in beams else [b.name])]
    return MujocoBodies(xml, bodies=coupled), heights


def _start_plates(scene, out: Built) -> None:
    """The elastic plates at the start: under base motion their clamps' supports driven by
    the tank's motion (:func:`support_drive`); a standing plate beyond its self-weight
    buckling load bent into its buckling mode, its tip ``IMPERFECTION`` L along +x
    (:meth:`bodies.elastic.BeamModel.imperfection`), and a warning (:func:`buckling_warning`)."""
    from bodies.elastic import IMPERFECTION

    for i, b in enumerate(scene.bodies):
        if not isinstance(b, ElasticPlate):
            continue
        beam = out.plates[b.name]
        if beam.support is not None:
            out.bodies.drive(beam.support_joints, support_drive(out.base_motion))
        _, factor, slope = self_weight(scene, b)
        if factor < 1.0:
            out.bodies.set_joints(beam.imperfection(slope, IMPERFECTION * b.length))
            out.warnings.append(buckling_warning(scene, i))


def forced_drive(motion):
    """A body's prescribed motion (:class:`cosim.scene.spec.ForcedMotion`) as the callable of
    time that :meth:`bodies.mujoco_bodies.MujocoBodies.drive` takes: its slide's position
    [m], velocity and acceleration, each ``(1,)``."""
    signal = motion.signal()

    def drive(t):
        return tuple(np.array([x]) for x in signal.state(t))

    return drive


def _drive_forced(scene, out: Built) -> None:
    """The bodies given a ``motion``: their one slide (:func:`bodies.builders.slide_joint`)
    driven by it."""
    from bodies.builders import slide_joint

    for b in scene.bodies:
        if getattr(b, "motion", None) is not None:
            out.bodies.drive([slide_joint(b.name)], forced_drive(b.motion))


def _start_velocities(scene, out: Built) -> None:
    """The free bodies given a ``velocity``: moving at it at the start, without spin (in
    2-D the scene's (x, z), the x-z plane's)."""
    for b in scene.bodies:
        v = getattr(b, "velocity", None)
        if v is not None:
            out.bodies.set_velocity(out.bodies.body_names.index(b.name), (v[0], 0.0, v[1]) if len(v) == 2 else v)


def _warn_tilted_water(scene, out: Built) -> None:
    """Under a tilted gravity a tank's water starts at rest (its surface normal to g,
    :func:`domain_water`), but explicit water blocks (``domain.water``) start as given, level,
    with the hydrostatic pressure of gravity's -z component: not at rest, so they flow; said,
    not hidden."""
    w, d = scene.world, scene.domain
    if w.tilted and isinstance(scene.fluid, SPH) and isinstance(d, Tank) and d.water:
        out.warnings.append(f"world.gravity: {list(w.gravity)} m/s^2 is tilted {w.tilt_deg:.3g} deg from -z; the "
                            f"water blocks start as given, level, with the hydrostatic pressure of gravity's -z "
                            f"component ({w.g_down:.4g} m/s^2), and are not at rest under the tilted gravity: they "
                            f"flow until their surface stands normal to g")


def _warn_partial_row(scene, out: Built) -> None:
    """The SPH water is built in whole rows of ``dx`` from the floor, so a depth that is
    not a whole number of spacings leaves the still level up to a spacing below the scene's
    (bodies are placed for the scene's level and float high by as much): said, with a
    depth that fits. (A tank filled by water blocks lays its blocks as given.)"""
    d = scene.domain
    depth = getattr(d, "depth", None)
    if not isinstance(scene.fluid, SPH) or depth is None or getattr(d, "water", None):
        return
    dx = scene.fluid.dx
    rows = math.floor(depth / dx + 1e-9)
    short = depth - rows * dx
    if short > 1e-6 * dx:
        out.warnings.append(f"domain.depth: {depth:g} m is {depth / dx:.4g} spacings of fluid.dx = {dx:g} m; the "
                            f"water is laid in whole rows, so its still level lies {short:.4g} m below the "
                            f"{depth:g} m the scene states (a floating body placed for it sits that much high); give "
                            f"a depth of {rows * dx:.6g} or {(rows + 1) * dx:.6g} m, or a dx that divides {depth:g} m")


def _warn_partial_column(scene, out: Built) -> None:
    """A tank's walls lie on its water's lattice, so a length (width) that is not a whole
    number of spacings is built as the nearest whole number (``fluid.geometry.lattice_extent``):
    said, with the lengths that fit. Water blocks are laid in whole columns from their
    lower corner, so a block given up to the far wall may stop half a spacing or more short
    of the built face: an empty column the water at rest falls into (said too)."""
    d = scene.domain
    if not isinstance(scene.fluid, SPH) or type(d) is not Tank:
        return
    from fluid.geometry import lattice_extent  # here: a scene without SPH loads no fluid module

    dx = scene.fluid.dx
    for axis, key in enumerate(("length", "width") if scene.world.dim == 3 else ("length",)):
        size = getattr(d, key)
        built = lattice_extent(size, dx)
        if abs(built - size) > 1e-6 * dx:
            n = math.floor(size / dx + 1e-9)
            # a block laid as given up to the far wall: its last column's face, whole spacings from its lo
            faces = [b.lo[axis] + math.floor((b.hi[axis] - b.lo[axis]) / dx + 1e-9) * dx for b in d.water
                     if b.hi[axis] >= size - 1e-6 * dx]
            gap = "" if not faces or built - min(faces) < 0.5 * dx else (
                f"; the water block reaching the far wall stops at {min(faces):.6g} m, {built - min(faces):.3g} m "
                f"short of its face: an empty column the water at rest falls into")
            out.warnings.append(f"domain.{key}: {size:g} m is {size / dx:.4g} spacings of fluid.dx = {dx:g} m; the "
                                f"tank's walls lie on the particle lattice from its inner corner, so it is built "
                                f"{built:.6g} m ({round(built / dx)} spacings) "
                                f"{'long' if key == 'length' else 'wide'}{gap}; give a {key} of {n * dx:.6g} or "
                                f"{(n + 1) * dx:.6g} m, or a dx that divides {size:g} m")


def _warn_mjcf_world(scene, out: Built) -> None:
    """Under base motion, what an MJCF model fixes to its world stays where it is while the
    tank moves (the model's world is the inertial frame): bodies welded to it, joints that
    tie a body to it (other than a free joint, or the free slides and hinge of a 2-D
    body), equality constraints to it and geoms on it that collide. Free bodies ride the
    water."""
    if scene.base_motion is None or not any(isinstance(b, MJCF) for b in scene.bodies):
        return
    import mujoco

    m, named = out.bodies.model, []

    def name(kind, i):
        return mujoco.mj_id2name(m, kind, i) or f"#{i}"

    J, B = mujoco.mjtJoint, mujoco.mjtObj.mjOBJ_BODY
    for k in range(1, m.nbody):
        if m.body_parentid[k] != 0:
            continue
        joints = range(m.body_jntadr[k], m.body_jntadr[k] + m.body_jntnum[k])
        types = sorted(int(m.jnt_type[j]) for j in joints)
        free = types == [int(J.mjJNT_FREE)] or (
            types == sorted([int(J.mjJNT_SLIDE)] * 2 + [int(J.mjJNT_HINGE)])
            and not any(m.jnt_stiffness[j] or m.jnt_limited[j] for j in joints))
        if not free:
            named.append(f"body '{name(B, k)}' ({'welded to' if not types else 'jointed to'} the world)")
    for e in range(m.neq):
        if int(m.eq_type[e]) in (int(mujoco.mjtEq.mjEQ_CONNECT), int(mujoco.mjtEq.mjEQ_WELD)) and \
                0 in (m.eq_obj1id[e], m.eq_obj2id[e]):
            named.append(f"equality '{name(mujoco.mjtObj.mjOBJ_EQUALITY, e)}' (to the world)")
    for g in range(m.ngeom):
        if m.geom_bodyid[g] == 0 and (m.geom_contype[g] or m.geom_conaffinity[g]):
            named.append(f"geom '{name(mujoco.mjtObj.mjOBJ_GEOM, g)}' (on the world)")
    if named:
        out.warnings.append(f"base_motion: the MJCF model's world stands still while the tank moves: "
                            f"{', '.join(named)} stay where they are, not on the tank (only its free bodies ride "
                            f"the water); leave them out of the model, or give them a free joint")


def mooring_lines(scene) -> list:
    """The scene's mooring lines as :class:`moorings.MooringLine` records, each named by its
    label (its ``name``, else its fairlead ``BODY.NAME``)."""
    from moorings import MooringLine

    return [MooringLine(ln.anchor, ln.length, ln.weight, EA=ln.EA, mass_per_length=ln.mass_per_length,
                        diameter=ln.diameter, name=ln.name or ln.fairlead, break_load=ln.break_load)
            for ln in scene.moorings.lines]


def _fairlead_sites(scene) -> list[str]:
    """The MuJoCo site of each line's fairlead."""
    mjcf = any(isinstance(b, MJCF) for b in scene.bodies)
    return [ln.fairlead.split(".")[1] if mjcf else site_name(ln.fairlead) for ln in scene.moorings.lines]


def fairleads_at_start(scene) -> np.ndarray:
    """Where each mooring line's fairlead is when the scene's run starts [m], world frame,
    ``(n_lines, dim)``: the bodies placed as the run places them (a floating one at its
    computed height), nothing else built."""
    level = water_level(scene)
    rho = scene.fluid.rho0 if isinstance(scene.fluid, SPH) else getattr(scene.fluid, "rho", 1000.0)
    bodies, _ = _bodies(scene, level, rho)
    p = bodies.site_positions([bodies.site(s)[0] for s in _fairlead_sites(scene)])
    return p[:, [0, 2]] if scene.world.dim == 2 else p


def _mooring(scene, level, rho, workdir: Path):
    """The mooring participant of the scene's lines and model
    (:data:`cosim.scene.registry.MOORINGS`), with the MuJoCo site of each fairlead."""
    from cosim.scene.registry import MOORINGS

    m = scene.moorings
    lines = mooring_lines(scene)
    mooring = MOORINGS[m.model].from_scene(scene, lines, level=level, rho=rho, workdir=workdir)
    if any(ln.break_load is not None for ln in lines):
        from moorings.breaking import BreakingMooring

        mooring = BreakingMooring(mooring, release=m.release_broken)
    return mooring, _fairlead_sites(scene), [ln.name for ln in lines]


def build(scene, workdir: Path) -> Built:
    """The participants and coupler of ``scene``; files a participant needs (an exported
    FMU) go into ``workdir``."""
    from cosim.coupler import Coupler

    level = water_level(scene)
    rho = scene.fluid.rho0 if isinstance(scene.fluid, SPH) else getattr(scene.fluid, "rho", 1000.0)
    out = Built(coupler=None, level=level)
    if scene.base_motion is not None:
        out.base_motion = _base_motion(scene)
    if scene.bodies:
        out.bodies, out.start_heights = _bodies(scene, level, rho, out.warnings)
        out.plates = plates(scene)
        _start_plates(scene, out)
        _drive_forced(scene, out)
        _start_velocities(scene, out)
        _warn_mjcf_world(scene, out)
    _warn_tilted_water(scene, out)
    _warn_partial_row(scene, out)
    _warn_partial_column(scene, out)
    for w in out.warnings:
        log.warning("%s", w)
    moorings = []
    if scene.moorings is not None:
        out.mooring, sites, out.line_names = _mooring(scene, level, rho, Path(workdir))
        moorings = [(out.mooring, sites)]
    scene.fluid.participant(scene, out)  # the fluid model's (cosim.scene.registry.FLUIDS)
    scheme = scene.coupling.scheme  # "auto": the coupler's (fluid-first with a fluid that reports its exchange)
    if out.bodies is None:
        others = [out.fluid] if out.fluid is not None else []
        out.coupler = Coupler(others, dt=scene.coupling.dt)
    else:
        out.coupler = Coupler(bodies=out.bodies, fluid=out.fluid, moorings=moorings, dt=scene.coupling.dt,
                              scheme=scheme, light_body=scene.coupling.light_body, lines=scene.coupling.lines,
                              fluid_steps=scene.coupling.fluid_steps)
    _initialize(scene, out.coupler)
    if isinstance(scene.fluid, SPH) and out.bodies is not None:
        out.sph = out.fluid.fluid
    return out


def analytic_fluid(scene, out: Built) -> None:
    """The analytic fluid (``fluid.analytic.AnalyticFluid``) of the scene: its incident sea,
    or a flume's wavemaker's far-field wave."""
    from fluid.analytic import AnalyticFluid

    from cosim.scene.seas import IncidentSea

    f, w = scene.fluid, scene.waves
    waves = None
    if isinstance(w, IncidentSea):
        waves = w.sea(scene)
    elif isinstance(w, (Piston, Flap)):
        out.wavemaker, waves = far_field_wave(scene)
    out.fluid = AnalyticFluid(rho=f.rho, g=scene.world.gravity, free_surface_z=out.level,
                              linear_damping=f.linear_damping or None, quadratic_damping=f.quadratic_damping or None,
                              added_mass=f.added_mass or None, waves=waves)


def potential_fluid(scene, level):
    """The potential fluid (``fluid.potential.PotentialFluid``) of the scene and the flume's
    wavemaker, if any: its frequencies (``fluid.potential.participant.frequency_grid`` to
    ``omega_max``; unset: per body, from its panel size), the scene's waves as one component (a
    flume's: its far-field wave, faded in everywhere at once rather than travelling from the paddle)."""
    from cosim.scene.checks import potential_depth
    from fluid.potential import PotentialFluid
    from fluid.potential.waves import Sea, from_incident, regular

    f, w, g = scene.fluid, scene.waves, scene.world.gravity
    depth = potential_depth(scene)
    wavemaker, sea = None, None
    if isinstance(w, LinearWaves):
        sea = Sea(regular(w.height, w.period, w.direction), depth=depth, g=g, ramp=w.ramp * w.period)
    elif isinstance(w, (Piston, Flap)):
        wavemaker, lw = far_field_wave(scene)
        sea = Sea(regular(lw.H, lw.T, lw.direction), depth=depth, g=g, ramp=lw.ramp)
    elif w is not None:  # an incident sea: the linear components of its fluid.waves sea (its depth the scene's)
        sea = from_incident(w.sea(scene))
    fluid = PotentialFluid(rho=f.rho, g=g, free_surface_z=level, depth=depth, omega_max=f.omega_max,
                           frequencies=f.frequencies, panel_size=f.panel_size, memory=f.memory, sea=sea,
                           quadratic_drag=f.quadratic_drag or None, drift=f.drift,
                           interaction=f.interaction)
    return fluid, wavemaker


def _initialize(scene, coupler) -> None:
    """Initialise the coupler; what it refuses that only the built scene shows is refused
    naming the scene's key: the potential fluid's settings that do not fit the hulls
    (known once their coefficients are), a ``coupling.dt`` above a participant's or the
    lines' stable step."""
    from cosim.errors import ConfigurationError
    from cosim.scene.fields import SceneError

    try:
        if not isinstance(scene.fluid, Potential):
            coupler.initialize()
            return
        from fluid.potential.radiation import SettingError

        try:
            coupler.initialize()
        except SettingError as e:
            raise SceneError(f"fluid.{e.key}", str(e).removeprefix("potential flow: ")) from None
    except ConfigurationError as e:
        if scene.coupling.dt is not None and str(e).startswith("coupling step dt"):  # a participant's, the lines' bound
            raise SceneError("coupling.dt", str(e)) from None
        raise


def sph_fluid(scene, out: Built) -> None:
    """The SPH fluid (:mod:`fluid.solver`; with bodies, ``cosim.sph_fluid.SPHFluid``) in
    the scene's domain, its set-up, the wavemaker's paddle and the tank's motion."""
    from cosim.scene.setup import choose

    out.setup = choose(scene)
    cfg = fluid_config(scene, out.setup)
    motions, back, zones, turned = {}, 0.0, [], None
    if isinstance(scene.domain, NearField):
        pts, walls, motions, zones = _near_field(scene, cfg, out)
    else:
        if scene.waves is not None:
            out.wavemaker, paddle, stroke = _wavemaker(scene)
            motions[PADDLE] = paddle
            back = 0.5 * stroke + cfg.dx
        if out.base_motion is not None:
            motions[WALLS] = out.base_motion
        pts, walls, turned = domain_water(scene, cfg, back)
        zones = _absorber(scene)
        if out.base_motion is not None:  # the box covers the tank's travel and its splashes
            cfg = _moving_domain(scene, cfg, pts, walls, out)
    if out.bodies is not None:
        from cosim.sph_fluid import SPHFluid

        z_surface = None if isinstance(scene.domain, OpenWater) else out.level if turned is None else turned
        out.fluid = SPHFluid(cfg, pts, walls, z_surface=z_surface,
                             surface_normal_to_gravity=turned is not None, boundary=scene.fluid.body_boundary,
                             motions=motions, elastic=list(out.plates.values()), zones=zones,
                             controllers=out.controllers)
        return
    from fluid.equations import hydrostatic_density
    from fluid.geometry import assemble, set_hydrostatic
    from fluid.particles import Kind
    from fluid.solver import Fluid

    built = assemble(cfg.dim, cfg.dx, cfg.rho0, pts, walls)
    ps = built.particles
    if turned is not None:  # the surface a plane normal to gravity
        set_hydrostatic(ps, turned, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.gravity)
    else:
        fl = ps.kind == Kind.FLUID
        top = np.full(ps.n, out.level)
        top[fl] = _surface_heights(scene, ps.pos[fl])
        ps.rho[:] = hydrostatic_density(top - ps.pos[:, -1], cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g_down)
    fluid = Fluid(cfg, ps)
    for group, motion in motions.items():
        fluid.prescribe_motion(group, motion)
    fluid.zones.extend(zones)
    fluid.controllers.extend(out.controllers)
    out.fluid = out.sph = fluid


def _moving_domain(scene, cfg, pts, walls, out: Built):
    """``cfg`` with the SPH domain of the moving tank (:mod:`cosim.scene.sph_domain`), kept
    in ``out.sph_domain``."""
    from cosim.scene.sph_domain import moving_tank_domain, sample_times

    every = np.concatenate([pts] + [w[0] for w in walls])
    times = sample_times(scene.world.duration, getattr(scene.base_motion, "period", None))
    d = out.sph_domain = moving_tank_domain(every, out.base_motion, times, cfg.h)
    return dataclasses.replace(cfg, domain_lo=d.lo, domain_hi=d.hi)


def _absorber(scene) -> list:
    """A flume's absorbing zone (:class:`~cosim.scene.spec.Absorber`) as a relaxation zone
    towards rest, its rate by default twice the wavemaker's angular frequency."""
    d = scene.domain
    if not isinstance(d, Flume) or d.absorber is None:
        return []
    from fluid.relaxation import Slab

    rate = d.absorber.rate if d.absorber.rate is not None else 2.0 * 2.0 * math.pi / scene.waves.period
    return [Slab(0, d.length - d.absorber.length, d.length, rate)]


def _near_field(scene, cfg, out: Built):
    """A near field's box, built once at ``cfg``'s spacing and wall layers
    (:func:`fluid.nearfield.near_field_box`, extents from :func:`cosim.scene.nearfield.box_for`,
    kept in ``out.near_field``, its sea in ``out.sea``): ``(fluid points, walls, wall motions
    {group: motion}, relaxation zones)``, the end walls on the sea's orbits."""
    from cosim.scene.nearfield import box_for
    from fluid.nearfield import FAR_END_GROUP, NEAR_END_GROUP, following_wall, near_field_box

    sea = out.sea = incident_sea(scene)
    c = out.near_field = box_for(scene)
    box = near_field_box(cfg.dx, c.x[0], c.x[1], sea, c.height, c.zone, layers=math.ceil(2.0 * cfg.h_coef - 1e-9),
                         y=c.y, side_zone=c.side_zone, mirror=scene.domain.symmetry,
                         planes=scene.domain.sides == "symmetry")
    rate = scene.domain.rate * 2.0 * math.pi / sea.peak_period
    if scene.domain.absorbing_walls:
        ends = box.absorbing_ends(sea, cfg.dx, cfg.h)
        out.controllers.extend(ends)
        return box.fluid, box.walls, {NEAR_END_GROUP: ends[0], FAR_END_GROUP: ends[1]}, box.zones(sea, rate, ends=ends)
    wall = following_wall(sea)
    return box.fluid, box.walls, {NEAR_END_GROUP: wall, FAR_END_GROUP: wall}, box.zones(sea, rate)
