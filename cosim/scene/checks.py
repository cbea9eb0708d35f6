"""The checks of a scene as a whole (:meth:`cosim.scene.spec.Scene.validate`): what fits
together, named by key path (``moorings.lines[1].fairlead``), before any work is done.

Each field on its own was checked by its class (:mod:`cosim.scene.fields`); here: vector
lengths against the dimension, which fluid goes with which domain and excitation, body
names and fairlead references, bodies inside the tank (clear of its walls, a beach, a
sloping side) and of each other, fairleads above their anchors' seabed with lines long
enough to reach them, water blocks that hold particles and do not overlap, probes inside
the domain (pressure patches on a wall's face, facing the water).

The files a scene names are read here too, as the builder will read them: an MJCF model
is parsed and compiled by MuJoCo (imported only for a scene that has one), an ``.AT2``
accelerogram by :func:`fluid.motion.read_at2` (a ground motion's records must also last
the scene and sample the water's first sloshing period at least 10 times), a table of
motion (base motion, paddle record) as a table of numbers whose times increase and whose motion starts at rest.
"""

from __future__ import annotations

import gzip
import math

from cosim.scene import plausible
from cosim.scene.fields import SceneError, is_name
from cosim.scene.registry import MOORINGS
from cosim.scene.seas import IncidentSea
from cosim.scene.shapes import RigidBody
from cosim.scene.shapes import corners as _corners
from cosim.scene.shapes import hull as _hull
from cosim.scene.shapes import rotation as _rotation
from cosim.scene.spec import (MJCF, SPH, Analytic, LinearWaves, CylinderTank, Earthquake, Flap, Flume, ArchRib,
                              ElasticPlate, GroundMotion, InclinedTank, IrregularWaves, NearField, NoFluid, OpenWater,
                              StillWaves, PaddleRecord, Piston, PolygonTank, Potential, RegularWaves, ROLLS, RollTable,
                              TableMotion, Tank)

#: the fluids whose free surface is a plane (with an incident sea on it), not particles
_SURFACE = (Analytic, Potential)


def body_names(scene) -> list[str]:
    """Names of the scene's bodies (an MJCF file's named ones; its movable bodies are only
    known once it is loaded)."""
    out = []
    for b in scene.bodies:
        out.extend(b.bodies if isinstance(b, MJCF) else [b.name])
    return out


def _pos_key(b) -> str:
    """The field that places a builder body: ``pos``, or an elastic plate's ``base``."""
    return "base" if isinstance(b, ElasticPlate) else "pos"


def _dim_vec(v, dim, path, what="point"):
    if v is not None and len(v) != dim:
        coords = "(x, z)" if dim == 2 else "(x, y, z)"
        raise SceneError(path, f"{list(v)} has {len(v)} coordinates; a {dim}-D scene gives a {what} as {coords}")


def _axis(k: int, dim: int) -> str:
    return "xyz"[k] if dim == 3 else "xz"[k]


def _pt(v) -> str:
    """A point or vector for a message: (0.1, 0.25)."""
    return "(" + ", ".join(f"{x + 0.0:.4g}" for x in v) + ")"


def _span(lo, hi, dim, n=None) -> str:
    """Extents along the axes for a message: x 0 .. 3 m, z 0 .. 0.45 m."""
    return ", ".join(f"{_axis(k, dim)} {lo[k]:.4g} .. {hi[k]:.4g} m" for k in range(n if n is not None else dim))


def check_scene(s) -> None:
    dim = s.world.dim
    _check_tilted_gravity(s)
    plausible.check_scales(s)
    if not s.bodies and not isinstance(s.fluid, SPH):
        raise SceneError("bodies", "the scene has nothing that moves: give bodies, or the SPH fluid in a domain")
    mjcf = [i for i, b in enumerate(s.bodies) if isinstance(b, MJCF)]
    if mjcf and len(s.bodies) > 1:
        raise SceneError(f"bodies[{mjcf[0]}]", "an MJCF file brings all its bodies: give it as the only entry of "
                         "bodies (builder bodies and several files cannot be mixed)")
    _check_fluid_and_domain(s, dim)
    plausible.check_fluid(s)
    _check_excitations(s, dim)
    mj = _check_bodies(s, dim)
    if isinstance(s.domain, Flume) and s.domain.absorber is not None:
        _check_absorber(s, dim)
    plausible.check_bodies(s, dim)
    plausible.check_excitations(s, dim)
    _check_moorings(s, dim, mj)
    _check_forced(s, dim)
    plausible.check_lines(s, dim, mj)
    _check_probes(s, dim, mj)
    if isinstance(s.fluid, Potential):
        _check_potential(s, dim)
    if s.coupling.scheme == "fluid-first" and not isinstance(s.fluid, SPH):
        raise SceneError("coupling.scheme", "'fluid-first' needs the SPH fluid (the loads it exchanged); use 'auto'")
    if s.coupling.fluid_steps > 1 and not (isinstance(s.fluid, SPH) and s.bodies):
        raise SceneError("coupling.fluid_steps", "sub-cycles the SPH fluid between its exchanges with the bodies; "
                         "this scene has " + ("no bodies" if isinstance(s.fluid, SPH) else "no SPH fluid")
                         + ": leave coupling.fluid_steps out (1)")
    if s.coupling.dt is not None and s.coupling.dt > s.world.duration:
        raise SceneError("coupling.dt", f"{s.coupling.dt:g} s is longer than the run ({s.world.duration:g} s); give "
                         f"a step of at most world.duration, or leave coupling.dt out (the participants' stable step)")
    if s.coupling.light_body == "subiterate" and s.coupling.scheme not in ("auto", "fluid-first"):
        raise SceneError("coupling.light_body", "'subiterate' needs the fluid-first scheme; set coupling.scheme to "
                         "'auto' or 'fluid-first'")


def _check_tilted_gravity(s) -> None:
    """What takes gravity along -z only, refused under a tilted ``world.gravity`` (a vector
    not along -z): the analytic and potential fluids' hydrostatics (a free surface level
    at a height), waves (their dispersion, ``omega^2 = g k tanh(k h)``, and the near
    field's sea), the floating placement (a waterline at a height), and every mooring
    model (each line's weight along -z)."""
    w = s.world
    if not w.tilted:
        return
    said = f"gravity {list(w.gravity)} m/s^2, {w.tilt_deg:.3g} deg from -z"
    fix = "give world.gravity as a number (along -z)"
    if isinstance(s.fluid, (Analytic, Potential)):
        raise SceneError("world.gravity", f"{said}: the {s.fluid.model} fluid's hydrostatics hold the free surface at "
                         f"a height (gravity along -z); {fix}, or use fluid.model = \"sph\" or \"none\"")
    if s.waves is not None or isinstance(s.domain, NearField):
        raise SceneError("world.gravity", f"{said}: waves travel on a free surface under gravity along -z; {fix}, "
                         f"or leave waves out")
    for i, b in enumerate(s.bodies):
        if getattr(b, "place", None) == "floating":
            raise SceneError(f"bodies[{i}].place", f"\"floating\" finds a waterline at a height, under gravity along "
                             f"-z, but the scene's is tilted ({said}); place body {b.name!r} at a given pos, or "
                             f"{fix}")
    if s.moorings is not None:
        raise SceneError("moorings.model", f"{s.moorings.model!r}: the mooring models take each line's weight along "
                         f"-z, but the scene's gravity is tilted ({said}); {fix}, or leave moorings out")
    d = s.domain
    if isinstance(s.fluid, SPH) and isinstance(d, Tank) and not d.water and w.g_down > 0:
        # the water at rest under the tilt: its surface normal to g, through the same volume,
        # rises from the tank's centre by half the length (and width) times g's slope
        gx, gy, _ = w.g_vector
        rise = 0.5 * (d.length * abs(gx) + (d.width or 0.0) * abs(gy)) / w.g_down
        if d.depth + rise > d.height:
            raise SceneError("world.gravity", f"{said}: the water at rest under it, its surface normal to gravity, "
                             f"stands {d.depth + rise:.4g} m high at the tank's wall, over its height "
                             f"({d.height:g} m); give the tank more height (domain.height) or less water "
                             f"(domain.depth), or a gravity nearer -z")


def _check_fluid_and_domain(s, dim):
    d = s.domain
    if isinstance(s.fluid, SPH):
        if d is None:
            raise SceneError("domain", "the SPH fluid needs a domain: a tank, flume, inclined-tank, cylinder-tank, "
                             "polygon, nearfield or open water")
    elif isinstance(s.fluid, _SURFACE) and isinstance(d, Flume):
        # the analytic fluid takes a flume's depth (the still level) and its wavemaker's far-field wave
        if s.fluid.level not in (0.0, d.depth):
            raise SceneError("fluid.level", f"{s.fluid.level} m: with a flume the still level is its depth "
                             f"({d.depth} m, the seabed at z = 0); leave fluid.level out")
    elif d is not None:
        raise SceneError("domain", f"a {d.kind} holds the SPH fluid's particles; with fluid.model = "
                         f"{s.fluid.model!r} leave it out (the analytic fluid's surface is fluid.level; it takes "
                         f"a flume, for its depth and wavemaker)")
    if d is None:
        return
    if isinstance(d, NearField):
        _check_near_field(s, dim)
    if isinstance(d, PolygonTank) and dim != 2:
        raise SceneError("domain.kind", f"a {d.kind} is 2-D; set world.dim = 2 or use a tank")
    if isinstance(d, Flume):
        if dim == 3 and d.width is None:
            raise SceneError("domain.width", "a 3-D flume (a wave tank) needs its width along y [m]")
        if dim == 2 and d.width is not None:
            raise SceneError("domain.width", "a 2-D flume is the x-z plane; leave width out")
        if d.sides == "symmetry":
            if dim == 2:
                raise SceneError("domain.sides", "symmetry planes bound a 3-D flume across y; a 2-D flume has no "
                                 "sides: leave sides out")
            if s.bodies:
                raise SceneError("domain.sides", f"a flume between symmetry planes carries waves uniform across y "
                                 f"and no bodies ({len(s.bodies)} given): give sides = \"walls\", or put the "
                                 f"bodies in a near field (domain.kind = \"nearfield\", with its own symmetry plane)")
    if isinstance(d, CylinderTank) and dim != 3:
        raise SceneError("domain.kind", "a cylinder-tank is 3-D; set world.dim = 3")
    if isinstance(d, (Tank, InclinedTank)):
        if dim == 3 and d.width is None:
            raise SceneError("domain.width", f"a 3-D {d.kind} needs its width along y [m]")
        if dim == 2 and d.width is not None:
            raise SceneError("domain.width", "a 2-D scene is the x-z plane; leave width out")
    if isinstance(d, Tank):
        _check_tank_walls(s, d, dim)
        inner = (d.length,) + ((d.width,) if dim == 3 else ()) + (d.height,)
        _check_water_blocks(s, d, dim, (0.0,) * dim, inner, f"the tank 0 .. {list(inner)} m")
    if isinstance(d, OpenWater):
        _check_open_water(s, d, dim)
    if isinstance(d, PolygonTank):
        _check_outline(d.vertices)
    sph = s.fluid
    if isinstance(d, ArchRib) and isinstance(sph, SPH) and d.inner_height < 3 * sph.dx:
        raise SceneError("fluid.dx", f"{sph.dx} m leaves fewer than 3 particles across the rib's cavity "
                         f"(inner_height {d.inner_height:g} m); refine dx to at most {d.inner_height / 3:.3g} m")
    if isinstance(sph, SPH) and not isinstance(d, OpenWater):  # its blocks are checked a spacing thick
        depth = getattr(d, "level", None)
        if isinstance(d, PolygonTank):
            depth = d.fill_level - min(v[1] for v in d.vertices)
        if depth is not None and depth < 2 * sph.dx:
            raise SceneError("fluid.dx", f"{sph.dx} m leaves fewer than 2 particles over the water depth "
                             f"{depth:g} m; refine dx to at most {depth / 4:.3g} m (4 layers)")


def _check_water_blocks(s, d, dim, lo_box, hi_box, box: str) -> None:
    """A domain's water blocks (``domain.water``): each within ``lo_box`` .. ``hi_box`` [m]
    (``box`` says where, for a message), clear of the tank's solid blocks, a spacing thick at
    least, none overlapping another."""
    for i, b in enumerate(d.water):
        _dim_vec(b.lo, dim, f"domain.water[{i}].lo")
        _dim_vec(b.hi, dim, f"domain.water[{i}].hi")
        if any(lo < e for lo, e in zip(b.lo, lo_box)) or any(h > e for h, e in zip(b.hi, hi_box)):
            raise SceneError(f"domain.water[{i}]", f"the block {list(b.lo)} .. {list(b.hi)} m reaches outside "
                             f"{box}")
        for k, w in enumerate(getattr(d, "walls", ())):
            if _blocks_overlap(b, w):
                raise SceneError(f"domain.water[{i}]", f"the block {list(b.lo)} .. {list(b.hi)} m overlaps the "
                                 f"solid domain.walls[{k}] ({list(w.lo)} .. {list(w.hi)} m); let the water end "
                                 f"where the wall begins")
        dx = s.fluid.dx
        for k, (lo, hi) in enumerate(zip(b.lo, b.hi)):
            if math.floor((hi - lo) / dx + 1e-9) < 1:  # as fluid.geometry.block counts its rows
                raise SceneError(f"domain.water[{i}]", f"the block is {hi - lo:.4g} m thick along "
                                 f"{_axis(k, dim)}, less than one particle spacing (fluid.dx = {dx:g} m): it "
                                 f"would hold no particle; make it at least {dx:g} m thick, or refine dx")
    for j, b in enumerate(d.water):
        for i, a in enumerate(d.water[:j]):
            if _blocks_overlap(a, b):
                raise SceneError(f"domain.water[{j}]", f"the block {list(b.lo)} .. {list(b.hi)} m overlaps "
                                 f"domain.water[{i}] ({list(a.lo)} .. {list(a.hi)} m): the water there would be "
                                 f"laid twice, its particles on top of each other; let the blocks meet (one's "
                                 f"hi = the other's lo) without overlapping")


def _check_open_water(s, d, dim) -> None:
    """Open water: its box and blocks in the scene's dimension, nothing that needs walls
    or a still level (a shaken tank, a floating placement)."""
    _dim_vec(d.lo, dim, "domain.lo")
    _dim_vec(d.hi, dim, "domain.hi")
    _check_water_blocks(s, d, dim, d.lo, d.hi, f"the fluid's box {list(d.lo)} .. {list(d.hi)} m")
    if s.base_motion is not None:
        raise SceneError("base_motion", "open water has no tank to move; leave base_motion out, or hold the water "
                         "in a tank (domain.kind = \"tank\")")
    for i, b in enumerate(s.bodies):
        if getattr(b, "place", None) == "floating":
            raise SceneError(f"bodies[{i}].place", f"\"floating\" finds a waterline under a still level; open water "
                             f"has none: place body {b.name!r} at a given pos")
    if isinstance(s.fluid, SPH) and s.fluid.c0 is None and s.fluid.u_max is None:
        from cosim.scene.setup import u_max

        u_max(s, "impact")  # refuses open water that nothing sets moving


#: each sea input (fluid.waves' field names) as the scene's key
_SEA_KEYS = {"height": "waves.height", "period": "waves.period", "depth": "waves.depth", "theory": "waves.theory",
             "phase": "waves.phase", "direction": "waves.direction", "ramp": "waves.ramp", "hs": "waves.hs",
             "tp": "waves.tp", "gamma": "waves.gamma", "seed": "waves.seed", "n_components": "waves.components",
             "elevation": "waves.file", "times": "waves.file", "file": "waves.file", "duration": "waves.file",
             "min_period": "waves.min_period", "at": "waves.at", "g": "world.gravity"}


def _check_absorber(s, dim):
    """A flume's absorbing zone: SPH only, its rate known, no body in it."""
    d = s.domain
    if not isinstance(s.fluid, SPH):
        raise SceneError("domain.absorber", f"the absorbing zone relaxes the SPH fluid's particles; the "
                         f"{s.fluid.model} fluid takes the flume's end as absorbing already: leave absorber out")
    if d.absorber.rate is None and not isinstance(s.waves, (Piston, Flap)):
        raise SceneError("domain.absorber.rate", "give the zone's relaxation rate [1/s] (about twice the waves' "
                         "angular frequency): it defaults to that of a piston or flap wavemaker, and this flume has "
                         "none")
    x_in = d.length - d.absorber.length
    for i, b in enumerate(s.bodies):
        if isinstance(b, MJCF):
            continue
        x = (b.base if isinstance(b, ElasticPlate) else b.pos)[0]
        if x + b.extent(dim)[0] > x_in:
            raise SceneError(f"bodies[{i}].{_pos_key(b)}", f"the body reaches x = {x + b.extent(dim)[0]:.4g} m, into "
                             f"the flume's absorbing zone ({x_in:.4g} .. {d.length:.4g} m), whose water is pulled to "
                             f"rest; move it towards the paddle or shorten domain.absorber.length")


def _check_sea(s, dim):
    """Waves of kind linear, regular or irregular: the incident sea of the analytic fluid."""
    w = s.waves
    if isinstance(s.domain, NearField):
        if isinstance(w, LinearWaves):
            raise SceneError("waves.kind", "a near field takes the sea of kind \"regular\" (theory = \"linear\" is "
                             "the same wave) or \"irregular\"")
        if w.direction != 0.0:
            raise SceneError("waves.direction", f"{w.direction:g} deg: the near field's end walls stand across x; "
                             f"give the sea along +x (0) and turn the bodies and lines instead")
    elif not isinstance(s.fluid, _SURFACE):
        raise SceneError("waves.kind", f"{w.kind} waves act on the analytic or potential fluid's bodies (fluid.model = "
                         f"\"analytic\"); the {s.fluid.model!r} fluid has none: "
                         + ("make waves with a piston or flap in a flume, or take the sea through a near field "
                            "(domain.kind = \"nearfield\")"
                            if isinstance(s.fluid, SPH) else "set fluid.model = \"analytic\""))
    if isinstance(s.fluid, Potential) and getattr(w, "theory", "linear") != "linear":
        raise SceneError("waves.theory", f"{w.theory!r}: the potential fluid is linear; give theory = \"linear\"")
    if dim == 2 and w.direction not in (0.0, 180.0):
        raise SceneError("waves.direction", f"{w.direction} deg: a 2-D scene's waves travel along +x (0) or -x "
                         f"(180)")
    if s.world.gravity <= 0:
        raise SceneError("world.gravity", "waves need gravity > 0 (their length follows from it)")
    d = s.domain
    if d is not None and d.level is not None:
        # the analytic fluid's still surface is the domain's level over its floor: the wave's
        # kinematics must decay to that floor, not to another seabed (refused rather than
        # taken from the domain: waves.depth is a field the user wrote, and a scene whose
        # TOML says one depth while another runs would mislead whoever reads it)
        floor = min(v[1] for v in d.vertices) if isinstance(d, PolygonTank) else 0.0
        depth = d.level - floor
        if not math.isclose(w.depth, depth, rel_tol=1e-9, abs_tol=1e-12):
            key = "domain.fill_level" if isinstance(d, PolygonTank) else "domain.depth"
            raise SceneError("waves.depth", f"{w.depth:g} m differs from the {d.kind}'s still-water depth "
                             f"{depth:g} m ({key}): the analytic fluid's free surface lies at the domain's water "
                             f"level, {depth:g} m above its floor, while the wave's kinematics would decay to a "
                             f"seabed {w.depth:g} m below it; give waves.depth = {depth:g} (or change {key})")
    if isinstance(w, IrregularWaves) and w.spectrum == "series":
        if w.at is not None and len(w.at) != dim - 1:
            raise SceneError("waves.at", f"{list(w.at)}: a {dim}-D scene gives the record's point as "
                             f"{'x [m]' if dim == 2 else '(x, y) [m]'}")
        _file(w.file, "waves.file")
        rows = _rows_of_numbers(w.file, "waves.file", strict=False)
        if not rows:
            raise SceneError("waves.file", f"{w.file!r} holds no row of numbers; give rows of time [s] and "
                             f"elevation [m]")
        width = min(len(r) for r in rows)
        if width <= w.column:
            raise SceneError("waves.column", f"{w.column} is beyond the last column of {w.file!r} ({width} "
                             f"column(s), 0 is the time); give one of 1 .. {width - 1}" if width > 1 else
                             f"{w.file!r} has the time column only; add a column of elevations")
    if isinstance(w, LinearWaves):
        from fluid.analytic import LinearWave

        depth = w.depth
        if math.isinf(depth):
            if not isinstance(s.fluid, Potential):
                raise SceneError("waves.depth", f"inf (deep water) is the potential fluid's; the {s.fluid.model!r} "
                                 f"fluid's wave kinematics decay to a seabed: give the depth [m]")
            # the wave's limits in deep water: at ten deep-water wavelengths tanh(k d) is 1 to round-off
            depth = 10.0 * s.world.gravity * w.period ** 2 / (2 * math.pi)
        try:
            LinearWave(w.height, w.period, depth, w.direction, w.ramp * w.period, s.world.gravity)
        except Exception as e:  # the wave's own limits (breaking)
            raise SceneError("waves.height", str(e).removeprefix("linear wave: ")) from None
        return
    from cosim.scene.build import incident_sea
    from fluid.waves import SeaError

    try:
        incident_sea(s)
    except SeaError as e:  # the sea's own limits (breaking, Stokes-2's range, the repeat period)
        raise SceneError(_SEA_KEYS.get(e.field, "waves"), e.problem) from None


def _check_excitations(s, dim):
    if isinstance(s.waves, IncidentSea):
        _check_sea(s, dim)
    elif s.waves is not None:
        if isinstance(s.fluid, _SURFACE) and (isinstance(s.waves, PaddleRecord) or not isinstance(s.domain, Flume)):
            raise SceneError("waves.kind", f"a {s.waves.kind} wavemaker moves the SPH fluid's paddle; the analytic "
                             f"fluid takes the waves themselves: kind = \"linear\" with height, period and depth, "
                             f"kind = \"regular\" or \"irregular\", or a piston or flap in a flume (its far-field "
                             f"wave)")
        if not isinstance(s.domain, Flume):
            raise SceneError("waves", "a wavemaker needs a flume (domain.kind = \"flume\"); shake a tank with "
                             "base_motion instead")
        if s.base_motion is not None:
            raise SceneError("base_motion", "a flume with a wavemaker cannot also move as a whole; give one of "
                             "waves and base_motion")
        if isinstance(s.waves, (Piston, Flap)):
            from fluid.wavemaker import RegularWavemaker

            if s.world.gravity <= 0:
                raise SceneError("world.gravity", "a wavemaker's waves need gravity > 0 (their length follows "
                                 "from it)")

            try:
                RegularWavemaker(s.waves.kind, s.waves.height, s.waves.period, s.domain.depth, s.waves.ramp,
                                 s.world.gravity)
            except Exception as e:  # the wavemaker's own limits (breaking)
                raise SceneError("waves.height", str(e)) from None
            if isinstance(s.fluid, Analytic):  # the far-field wave it makes: the incident sea's limits
                from cosim.errors import InputError
                from cosim.scene.build import far_field_wave

                try:
                    far_field_wave(s)
                except InputError as e:
                    raise SceneError("waves.height", str(e).removeprefix("linear wave: ")) from None
        if isinstance(s.waves, PaddleRecord):
            _file(s.waves.file, "waves.file")
            _check_paddle_record(s)
    b = s.base_motion
    if b is not None:
        plates = any(isinstance(x, ElasticPlate) for x in s.bodies)
        if s.domain is None and not (plates and isinstance(s.fluid, NoFluid)):
            raise SceneError("base_motion", "base motion moves the SPH fluid's tank and the clamps of elastic plates; "
                             "give a domain and fluid.model = \"sph\", or (fluid.model = \"none\") an elastic "
                             "plate to shake")
        if isinstance(s.domain, Flume):
            raise SceneError("base_motion", "a flume does not move as a whole; use a tank")
        if isinstance(b, ROLLS):
            _dim_vec(b.point, dim, "base_motion.point")
            if dim == 3 and b.axis is None:
                raise SceneError("base_motion.axis", "a 3-D roll needs its axis (3 components)")
            if dim == 2 and b.axis is not None:
                raise SceneError("base_motion.axis", "a 2-D roll is about +y; leave axis out")
        elif isinstance(b, GroundMotion):
            _check_ground_motion(s, dim)
        else:
            if dim == 3 and b.direction == (1.0, 0.0):
                raise SceneError("base_motion.direction", "a 3-D scene needs the direction as (x, y, z), e.g. "
                                 "[1, 0, 0]; the default (1, 0) is the x axis of a 2-D scene")
            _dim_vec(b.direction, dim, "base_motion.direction", "direction")
        if hasattr(b, "file"):
            _file(b.file, "base_motion.file")
        if isinstance(b, Earthquake):
            rec = _check_at2(b.file, b.baseline_degree, "base_motion.file")
            _check_record_sampling(rec.times[1] - rec.times[0], first_sloshing_period(s), "base_motion.file")
        if isinstance(b, TableMotion):
            _check_table_motion(s)
        if isinstance(b, RollTable):
            _check_roll_table(s, dim)
        if s.moorings is not None:
            raise SceneError("moorings", "mooring lines in a moving tank: their anchors are fixed in space and would "
                             "not move with the tank's floor (the mooring models take fixed anchors); leave out "
                             "base_motion or the moorings")


def _file(path, key):
    from pathlib import Path

    if not Path(path).is_file():
        raise SceneError(key, f"no file {path!r} (a relative path is read from the scene file's folder)")


def _check_bodies(s, dim):
    """The bodies' own checks; returns what the MJCF file holds (:func:`_check_mjcf`), or None."""
    seen, mj = {}, None
    for i, b in enumerate(s.bodies):
        key = f"bodies[{i}]"
        if isinstance(b, MJCF):
            _file(b.file, f"{key}.file")
            mj = _check_mjcf(b, key)
            names = b.bodies
        else:
            names = [b.name]
            if isinstance(b, ElasticPlate):
                _check_plate(s, dim, b, key)
            if b.place == "floating":
                if len(b.pos) != dim - 1:
                    raise SceneError(f"{key}.pos", f"{list(b.pos)}: a floating body's height is computed; give "
                                     f"its horizontal position only, {'(x,)' if dim == 2 else '(x, y)'}")
                if isinstance(s.fluid, NoFluid):
                    raise SceneError(f"{key}.place", "a floating body needs a fluid to float on (fluid.model)")
                from cosim.scene.build import water_level

                if water_level(s) is None:  # a fluid model of another package that states no still water
                    raise SceneError(f"{key}.place", f"the {s.fluid.model!r} fluid states no still-water level "
                                     f"to float a body at; place it at a given pos")
            else:
                _dim_vec(b.pos, dim, f"{key}.pos")
            _dim_vec(getattr(b, "velocity", None), dim, f"{key}.velocity", "velocity")
            try:
                b.fit(dim)
            except SceneError as e:
                raise e.under(key) from None
            if dim == 2 and b.euler is not None:
                if b.euler[0] != 0 or b.euler[2] != 0:
                    raise SceneError(f"{key}.euler", f"{list(b.euler)}: a 2-D body turns in the x-z plane, about y "
                                     f"only (its 1 m depth stays along y); give [0, angle, 0]")
            for name, p in b.fairleads.items():
                _dim_vec(p, dim, f"{key}.fairleads.{name}")
        for n in names:
            if n in seen:
                raise SceneError(f"{key}.name", f"{n!r} is also the name of bodies[{seen[n]}]; names must be unique")
            seen[n] = i
    if isinstance(s.fluid, Analytic):
        known = mj["coupled"] if mj is not None else sorted(seen)
        for table in ("linear_damping", "quadratic_damping", "added_mass"):
            for n in getattr(s.fluid, table):
                if n not in known:
                    raise SceneError(f"fluid.{table}.{n}", f"no body named {n!r}; bodies: {sorted(known)}")
        for n, v in s.fluid.added_mass.items():
            if len(v) != (3 if dim == 2 else 6) and mj is None:
                raise SceneError(f"fluid.added_mass.{n}", f"{len(v)} values; a {dim}-D body has "
                                 f"{3 if dim == 2 else 6} degrees of freedom: give one added mass each")
            if any(x < 0 for x in v):
                raise SceneError(f"fluid.added_mass.{n}", f"{list(v)}: an added mass is >= 0 [kg, kg m^2]")
    if isinstance(s.fluid, SPH) and isinstance(s.domain, NearField):
        _check_inside_near_field(s, dim)
    elif isinstance(s.fluid, SPH) and s.domain is not None:
        _check_inside(s, dim)
        _check_walls(s, dim)
    _check_overlaps(s, dim)
    return mj


def _check_forced(s, dim) -> None:
    """A body with a prescribed ``motion`` stands at a given pos (lines may end on it: a
    fairlead moved as a test rig moves it, their pull recorded and taken by the drive), in
    a fluid with particles, the analytic one or none (the potential fluid's bodies are free
    in six degrees of freedom), along an axis of the scene (no sway in 2-D, nor across a
    symmetry plane); heaving through the surface, its amplitude is below its draft (its
    keel stays in the water: a linear forced-oscillation test)."""
    from cosim.scene.build import water_level

    for i, b in enumerate(s.bodies):
        m = getattr(b, "motion", None)
        if m is None:
            continue
        key = f"bodies[{i}]"
        if b.place == "floating":
            raise SceneError(f"{key}.place", f"\"floating\": body {b.name!r} has a prescribed motion about the "
                             f"pos it is given; give place = \"given\" with a full pos")
        if isinstance(s.fluid, Potential):
            raise SceneError(f"{key}.motion", "the potential fluid's bodies are free (the Cummins equation in six "
                             "degrees of freedom); force a body in the SPH or analytic fluid, or leave motion out")
        if m.dof == "sway" and (dim == 2 or (isinstance(s.domain, NearField) and s.domain.symmetry)):
            raise SceneError(f"{key}.motion.dof", "\"sway\" moves the body along y: " +
                             ("a 2-D scene is the x-z plane; give surge or heave" if dim == 2 else
                              "the scene would not stay symmetric about y = 0; give surge or heave, or leave "
                              "domain.symmetry out"))
        level = water_level(s)
        if m.dof == "heave" and level is not None:
            bottom = b.pos[-1] - b.extent(dim)[-1]
            draft = level - bottom
            if 0.0 < draft < 2.0 * b.extent(dim)[-1] and m.amplitude >= draft:
                raise SceneError(f"{key}.motion.amplitude", f"{m.amplitude:g} m is not below the body's draft "
                                 f"{draft:.4g} m: its keel would leave the water at the top of each stroke; give "
                                 f"an amplitude below {draft:.4g} m (a fraction of it for a linear test)")


def _check_plate(s, dim, b, key) -> None:
    """An elastic plate: its base in the scene's dimension, a width in 3-D only, its foot on
    the tank's floor, at least two boundary particles across it (or the thin-wall columns)."""
    _dim_vec(b.base, dim, f"{key}.base")
    if (b.width is None) == (dim == 3):
        raise SceneError(f"{key}.width", "a 3-D plate needs its width along y [m]" if dim == 3 else
                         "a 2-D plate is 1 m wide (the scene's depth); leave width out")
    if not isinstance(s.fluid, SPH):
        return
    if b.angle != 0:
        raise SceneError(f"{key}.angle", f"{b.angle:g} deg: the SPH fluid's boundary stands a plate on the tank's "
                         f"floor (its clamped face open there); a turned plate is for fluid.model = \"none\"; "
                         f"give angle = 0 with the SPH fluid")
    dx = s.fluid.dx
    across = max(1, round(b.thickness / dx))
    if across < 2 and not b.thin_wall:
        raise SceneError(f"{key}.thickness", f"{b.thickness:g} m is {b.thickness / dx:.3g} particle spacings "
                         f"(dx = {dx:g} m): {across} boundary particle across, which lies on the mid-plane and "
                         f"holds neither side's fluid properly; refine fluid.dx to {b.thickness / 2:.3g} m or less, "
                         f"or set thin_wall = true (two columns, one per side; the fluid stands off by up to "
                         f"{max(dx - b.thickness / 2, 0.0):.3g} m on each side)")
    if s.domain is not None:
        floor = _domain_box(s.domain, dim, s)[0][-1]
        if b.direction == "down":
            if b.base[-1] - b.length < floor - 1e-9 * max(1.0, abs(floor)):
                raise SceneError(f"{key}.base", f"z = {b.base[-1]:g} m: a hanging plate {b.length:g} m long clamped "
                                 f"there reaches z = {b.base[-1] - b.length:g} m, below the tank's floor at z = "
                                 f"{floor:g} m; give base z >= {floor + b.length:g} or a shorter length")
            return
        if abs(b.base[-1] - floor) > 1e-9 * max(1.0, abs(floor)):
            raise SceneError(f"{key}.base", f"z = {b.base[-1]:g} m: the plate is clamped by its foot to the tank's "
                             f"floor at z = {floor:g} m; give base z = {floor:g}")


def roll_arm(s, dim) -> float:
    """The largest distance [m] from a roll's axis point (``s.base_motion.point``) to a
    corner of the domain's inner box (0 without a domain): the lever of the tank's roll."""
    if s.domain is None:
        return 0.0
    lo, hi = _domain_box(s.domain, dim, s)
    corners = [[lo[k] if (m >> k) & 1 == 0 else hi[k] for k in range(dim)] for m in range(2 ** dim)]
    return max(math.dist(c, s.base_motion.point) for c in corners)


def _domain_box(d, dim, s=None):
    """Lower and upper corners [m] of the domain's inner box (the walls' faces); a near
    field's as chosen for the scene ``s`` (:func:`cosim.scene.nearfield.box_for`)."""
    if isinstance(d, NearField):
        from cosim.scene.nearfield import box_for

        c = box_for(s)
        return [c.x[0]] + ([c.y[0]] if dim == 3 else []) + [0.0], [c.x[1]] + ([c.y[1]] if dim == 3 else []) + [c.height]
    if isinstance(d, OpenWater):
        return list(d.lo), list(d.hi)
    if isinstance(d, (Tank, Flume, InclinedTank)):
        lo = [0.0] * dim
        hi = [d.length] + ([d.width] if dim == 3 else []) + [d.height]
        if isinstance(d, InclinedTank):
            import math

            hi[0] = d.length + d.height * math.tan(math.radians(d.angle))
    elif isinstance(d, CylinderTank):
        lo, hi = [-0.5 * d.diameter] * 2 + [0.0], [0.5 * d.diameter] * 2 + [d.height]
    else:
        xs, zs = [v[0] for v in d.vertices], [v[1] for v in d.vertices]
        lo, hi = [min(xs), min(zs)], [max(xs), max(zs)]
    return lo, hi


def _check_near_field(s, dim):
    """A near field sits in an incident sea, a width only in 3-D, nothing moving it as a
    whole, no wall-pressure patches on its moving walls."""
    d = s.domain
    if not isinstance(s.waves, (RegularWaves, IrregularWaves, LinearWaves, StillWaves)):
        raise SceneError("waves", "a near field sits in an incident sea: give waves of kind \"regular\" or "
                         "\"irregular\" (their depth the domain's), or \"still\" (still water, for bodies forced "
                         "to move in it)")
    if dim == 2:
        for key in ("width", "symmetry"):
            if getattr(d, key) not in (None, False):
                raise SceneError(f"domain.{key}", f"a 2-D near field is the x-z plane; leave {key} out")
        if not d.side_zones:
            raise SceneError("domain.side_zones", "a 2-D near field is the x-z plane, with no side walls; leave "
                             "side_zones out")
    if d.sides == "symmetry":
        _check_channel_planes(s, dim)
    elif d.symmetry:
        _check_symmetric(s)
    if s.base_motion is not None:
        raise SceneError("base_motion", "a near field follows its sea and does not move as a whole; use a tank")
    if s.probes.pressure:
        raise SceneError("probes.pressure", "a near field's walls are not a structure: its wall-pressure patches "
                         "would read its moving end walls; read the bodies' loads instead")
    if isinstance(s.fluid, SPH) and s.fluid.device == "cuda":
        _check_near_field_on_gpu(s)


def _check_channel_planes(s, dim) -> None:
    """A near field between two symmetry planes (``sides = "symmetry"``) is a 3-D channel
    of a given width with nothing in it: a slice of a sea uniform across y."""
    d = s.domain
    if dim == 2 or d.side_zones:
        raise SceneError("domain.sides", "symmetry planes bound a 3-D channel (side_zones = false) across y; "
                         + ("a 2-D near field has no sides: leave sides out" if dim == 2 else
                            "set side_zones = false, or leave sides out"))
    if d.width is None:
        raise SceneError("domain.width", "a channel between symmetry planes needs its width [m] (sides = \"symmetry\")")
    if s.bodies or s.moorings:
        raise SceneError("domain.sides", "a channel between symmetry planes carries a sea uniform across y and no "
                         "bodies or lines: give sides = \"walls\" (or leave sides out)")


def _check_near_field_on_gpu(s) -> None:
    """What a near field asks of the GPU path (fluid.cuda): no symmetry plane (its mirror
    images are the CPU's). Its zones' seas (linear, Stokes-2, irregular) are all relaxed
    there."""
    if s.domain.symmetry:
        raise SceneError("domain.symmetry", "the symmetry plane's mirror images are made on the CPU only: with "
                         "fluid.device = \"cuda\" simulate the whole box (leave symmetry out), or run on the CPU")


def _check_symmetric(s):
    """A scene run on half its domain (``domain.symmetry``) is symmetric about y = 0: each
    body centred on the plane, upright or turned about y only, a builder body (an MJCF
    model's symmetry is not checked, so it is refused); each line's mirror image (fairlead
    and anchor at -y, the same line) in the scene, or the line in the plane. (The near
    field's sea travels along +x: its own mirror image.)"""
    def mirrored(p):
        return (p[0], -p[1], p[2])

    for i, b in enumerate(s.bodies):
        if isinstance(b, ElasticPlate):
            raise SceneError(f"bodies[{i}]", "an elastic plate is not mirrored across a symmetry plane: leave "
                             "domain.symmetry out with elastic plates")
        if isinstance(b, MJCF):
            raise SceneError(f"bodies[{i}]", "an MJCF model's symmetry about y = 0 is not checked: with "
                             "domain.symmetry give builder bodies, or leave symmetry out")
        if b.pos[1] != 0.0:
            raise SceneError(f"bodies[{i}].{_pos_key(b)}", f"y = {b.pos[1]:g} m: with domain.symmetry each body is "
                             f"centred on the symmetry plane y = 0; give y = 0, or leave symmetry out")
        if b.euler is not None and (b.euler[0] != 0.0 or b.euler[2] != 0.0):
            raise SceneError(f"bodies[{i}].euler", f"{_pt(b.euler)} deg: with domain.symmetry a body turns about y "
                             f"only (its mirror image is itself); give [0, angle, 0], or leave symmetry out")
        for name, p in b.fairleads.items():
            if p[1] != 0.0 and mirrored(p) not in b.fairleads.values():
                raise SceneError(f"bodies[{i}].fairleads.{name}", f"{_pt(p)} m has no mirror image {_pt(mirrored(p))} "
                                 f"among the body's fairleads: with domain.symmetry every fairlead off the plane "
                                 f"y = 0 has one; add it, or leave symmetry out")
    if s.moorings is None:
        return
    bodies = {b.name: b for b in s.bodies}
    def point(fairlead):
        body, name = fairlead.split(".")
        return body, tuple(bodies[body].fairleads[name])

    def key(ln, mirror):
        body, p = point(ln.fairlead)
        f = mirrored if mirror else (lambda q: tuple(q))
        return (body, f(p), f(ln.anchor), ln.length, ln.weight, ln.EA, ln.mass_per_length, ln.diameter,
                ln.break_load)

    lines = [key(ln, False) for ln in s.moorings.lines]
    for i, ln in enumerate(s.moorings.lines):
        if key(ln, True) not in lines:
            raise SceneError(f"moorings.lines[{i}]", f"the line from {ln.fairlead} to the anchor {_pt(ln.anchor)} m "
                             f"has no mirror image about y = 0 (the same line from the mirrored fairlead to "
                             f"{_pt(mirrored(ln.anchor))} m): with domain.symmetry the lines are symmetric; add it, "
                             f"or leave symmetry out")


def _check_inside_near_field(s, dim):
    """Bodies stand in the near field's water between its zones, clear of them by the
    reach the box allows for their motion (:func:`cosim.scene.nearfield.box_for`)."""
    from cosim.scene.nearfield import box_for, reach

    c, r = box_for(s), reach(s)
    side = c.side_zone or 0.0
    lo = [c.x[0] + c.zone] + ([c.y[0] + (0.0 if s.domain.symmetry else side)] if dim == 3 else [])
    hi = [c.x[1] - c.zone] + ([c.y[1] - side] if dim == 3 else [])
    keys = ("domain.x0 and domain.x1", "domain.width")
    for i, b in enumerate(s.bodies):
        if isinstance(b, MJCF):
            continue
        half = b.extent(dim)
        centre = b.base if isinstance(b, ElasticPlate) else b.pos
        for k in range(dim - 1):
            a, z = centre[k] - half[k] - r, centre[k] + half[k] + r
            if k == 1 and s.domain.symmetry:  # the half beyond the plane y = 0 is its mirror image
                a = max(a, lo[k])
            if a < lo[k] - 1e-9 or z > hi[k] + 1e-9:
                water = (f"between its relaxation zones ({lo[k]:.4g} .. {hi[k]:.4g} m)" if hi[k] > lo[k] else
                         f"between its relaxation zones, of which there is none: the zones overlap (their inner "
                         f"edges at {lo[k]:.4g} and {hi[k]:.4g} m)")
                raise SceneError(f"bodies[{i}].{_pos_key(b)}", f"the body and its reach {r:.3g} m (the sea's orbit, "
                                 f"doubled) span {a:.4g} .. {z:.4g} m along {'xy'[k]}, beyond the near field's water "
                                 f"{water}: a zone would pull the "
                                 f"water round it towards the sea's; widen the box ({keys[k]}) or narrow the zones "
                                 f"(domain.zone), or leave them unset to be chosen")


def _check_inside(s, dim):
    """Bodies at a given pose lie within the domain's inner box (the walls' faces)."""
    lo, hi = _domain_box(s.domain, dim, s)
    for i, b in enumerate(s.bodies):
        if isinstance(b, MJCF):
            continue
        half = b.extent(dim)
        n = dim - 1 if b.place == "floating" else dim
        for k in range(n):
            if b.pos[k] - half[k] < lo[k] or b.pos[k] + half[k] > hi[k]:
                axis = "xyz"[k] if dim == 3 else "xz"[k]
                raise SceneError(f"bodies[{i}].{_pos_key(b)}", f"the body{_turned(b)} reaches {b.pos[k] - half[k]:g} "
                                 f".. {b.pos[k] + half[k]:g} m along {axis}, outside the domain's {lo[k]:g} .. "
                                 f"{hi[k]:g} m; move it inside the tank")


def _turned(b) -> str:
    """For a message: how a builder body is turned (nothing when upright)."""
    return "" if b.euler is None else f" (turned by euler = {_pt(b.euler)} deg)"


def _check_moorings(s, dim, mj):
    m = s.moorings
    if m is None:
        return
    if not s.bodies:
        raise SceneError("moorings", "mooring lines end on bodies; add the body that carries the fairleads")
    builders = {b.name: b for b in s.bodies if not isinstance(b, MJCF)}
    for i, ln in enumerate(m.lines):
        key = f"moorings.lines[{i}]"
        _dim_vec(ln.anchor, dim, f"{key}.anchor")
        body, site = ln.fairlead.split(".")
        if mj is not None:
            _check_mjcf_fairlead(mj, ln.fairlead, f"{key}.fairlead")
        elif body not in builders:
            raise SceneError(f"{key}.fairlead", f"no body named {body!r}; bodies: {sorted(builders)}")
        elif site not in builders[body].fairleads:
            raise SceneError(f"{key}.fairlead", f"body {body!r} has no fairlead {site!r}; its fairleads: "
                             f"{sorted(builders[body].fairleads)}")
    first, labels = {}, {}
    for i, ln in enumerate(m.lines):
        if ln.fairlead in first:
            raise SceneError(f"moorings.lines[{i}].fairlead", f"{ln.fairlead!r} is also the fairlead of "
                             f"moorings.lines[{first[ln.fairlead]}]; give each line its own fairlead")
        first[ln.fairlead] = i
        label = ln.name or ln.fairlead
        if label in labels:
            raise SceneError(f"moorings.lines[{i}].name", f"{label!r} is also the label of moorings.lines"
                             f"[{labels[label]}] (its name, or its fairlead when it has none): a line's label names "
                             f"its outputs ({label}.tension); give each line its own name")
        labels[label] = i
    for i, ln in enumerate(m.lines):
        _check_line_start(s, dim, ln, f"moorings.lines[{i}]", builders.get(ln.fairlead.split(".")[0]))


def _check_line_start(s, dim, ln, key, body) -> None:
    """For a body at a given pose: the fairlead at or above its anchor's seabed, and an
    inextensible line long enough to reach it (a floating body's are checked when its
    height is computed, :mod:`cosim.scene.placement`)."""
    if body is None or body.place == "floating":
        return
    a, p = ln.anchor, body.fairleads[ln.fairlead.split(".")[1]]
    if dim == 3 and body.euler is not None:  # a 2-D body's frame stays the world's (bodies.builders)
        r = _rotation(body.euler)
        p = [sum(r[i][j] * p[j] for j in range(3)) for i in range(3)]
    f = [c + o for c, o in zip(body.pos, p)]
    tol = 1e-9 * max(1.0, *(abs(x) for x in f + list(a)))
    if f[-1] < a[-1] - tol:
        raise SceneError(f"{key}.anchor", f"the fairlead {ln.fairlead!r} starts at z = {f[-1]:.4g} m, below this "
                         f"anchor's seabed z = {a[-1]:.4g} m (the horizontal plane through the anchor); put the "
                         f"anchor at or below the fairlead's height (or the body higher)")
    dist = math.dist(f, a)
    if ln.EA is None and dist > ln.length + tol:
        raise SceneError(f"{key}.length", f"{ln.length:g} m is shorter than the straight distance {dist:.4g} m "
                         f"from the anchor {_pt(a)} m to the fairlead {ln.fairlead!r} at {_pt(f)} m at the start: "
                         f"an inextensible line cannot reach; give a length of at least {dist:.4g} m, move the "
                         f"anchor closer, or give EA (an elastic line that starts stretched)")


def _outline_differs(d) -> bool:
    """Whether the domain is not its box (a beach, a sloping side, a polygon, a round wall)."""
    return type(d) in _WALLS and not (isinstance(d, Flume) and d.beach is None)


def _check_probes(s, dim, mj):
    p = s.probes
    names = set(mj["coupled"]) if mj is not None else set(body_names(s))
    for i, n in enumerate(p.motion):
        if n != "all" and n not in names and mj is not None:
            raise SceneError(f"probes.motion[{i}]", f"{n!r} is not one of the bodies coupled from the MJCF file: "
                             f"{mj['coupled']} (or \"all\"); name one of them, or add it to bodies[0].bodies")
        if n != "all" and n not in names:
            raise SceneError(f"probes.motion[{i}]", f"no body named {n!r}; bodies: {sorted(names)} (or \"all\")")
    # the analytic and potential fluids' gauges read their incident sea (given, or a flume's wavemaker's far-field wave)
    linear = isinstance(s.fluid, _SURFACE) and isinstance(s.waves, (IncidentSea, Piston, Flap))
    line_energy = s.moorings is not None and "energy" in MOORINGS[s.moorings.model].extras
    fluid_probes = (p.gauges and not linear) or p.pressure or (p.energy and not line_energy)
    if fluid_probes and not isinstance(s.fluid, SPH):
        which = "gauges" if p.gauges and not linear else "pressure" if p.pressure else "energy"
        raise SceneError(f"probes.{which}", "wave gauges, pressure patches and the fluid's energy need the SPH "
                         "fluid (fluid.model = \"sph\")" + ("; the analytic fluid's gauges read its incident sea "
                                                             "(waves.kind = \"linear\", \"regular\" or "
                                                             "\"irregular\")" if which == "gauges" else
                                                             "; the lines' energy, moorings.model = \"sph-cable\""
                                                             if which == "energy" else ""))
    for i, g in enumerate(p.gauges):
        n = 1 if isinstance(g, float) else len(g)
        if n != dim - 1:
            raise SceneError(f"probes.gauges[{i}]", f"{g}: a {dim}-D scene gives a gauge as "
                             f"{'x [m]' if dim == 2 else '(x, y) [m]'}")
        if s.domain is not None:
            lo, hi = _domain_box(s.domain, dim, s)
            plane = isinstance(s.domain, NearField) and s.domain.symmetry  # y = 0 a symmetry plane, not a wall
            for k, x in enumerate((g,) if isinstance(g, float) else g):
                where = "" if dim == 2 else f"{list(g)}: "
                if plane and k == 1:  # a gauge at y < 0 reads its mirror image
                    lo = (lo[0], -hi[1])
                if not lo[k] <= x <= hi[k]:
                    raise SceneError(f"probes.gauges[{i}]", f"{where}{'xy'[k]} = {x:g} m lies outside the domain's "
                                     f"{lo[k]:g} .. {hi[k]:g} m; put the gauge over the water")
                half = 0.5 * s.fluid.dx if isinstance(s.fluid, SPH) else 0.0
                if min(x - lo[k], hi[k] - x) < half:  # the first particles stand half a spacing off the walls
                    raise SceneError(f"probes.gauges[{i}]", f"{where}{'xy'[k]} = {x:g} m is on the domain's wall "
                                     f"(within half a particle spacing, {half:g} m, of {lo[k]:g} .. {hi[k]:g} m), "
                                     f"where no free surface is found; put the gauge over the water, at least "
                                     f"{half:g} m from the walls")
    seen = set()
    for i, pr in enumerate(p.pressure):
        _dim_vec(pr.centre, dim, f"probes.pressure[{i}].centre")
        _dim_vec(pr.normal, dim, f"probes.pressure[{i}].normal", "direction")
        if pr.name in seen:
            raise SceneError(f"probes.pressure[{i}].name", f"{pr.name!r} is used twice; give each patch its own")
        seen.add(pr.name)
        if isinstance(s.fluid, SPH) and s.domain is not None:
            _check_patch(s, dim, pr, f"probes.pressure[{i}]")


def _check_patch(s, dim, pr, key) -> None:
    """A wall-pressure patch (``fluid.probes.wall_patch_pressure``) is at least a particle
    spacing across, centred on a wall's face (within half a spacing), its normal into the
    water (within 60 degrees of the wall's)."""
    d, dx = s.domain, s.fluid.dx
    if pr.size < dx:
        raise SceneError(f"{key}.size", f"{pr.size:g} m is less than one particle spacing (fluid.dx = {dx:g} m): "
                         f"the patch would hold no wall particle; give at least {dx:g} m (a few spacings read "
                         f"steadier)")
    c = pr.centre
    sd = _sd_domain(d, dim, c)
    lo, hi = _domain_box(d, dim, s)
    if sd > 0.5 * dx:
        raise SceneError(f"{key}.centre", f"{_pt(c)} m lies outside the domain ({_span(lo, hi, dim)}"
                         f"{', less its ' + _WALLS[type(d)] if _outline_differs(d) else ''}), {sd:.3g} m behind "
                         f"the nearest wall face; put the centre on the face of a wall, where the water meets it")
    if sd < -0.5 * dx:
        raise SceneError(f"{key}.centre", f"{_pt(c)} m lies in the water, {-sd:.3g} m from the nearest wall: a patch "
                         f"reads the wall particles just behind its centre; put the centre on the face of a wall "
                         f"(within {0.5 * dx:g} m, half a particle spacing)")
    inward = [round(x, 12) + 0.0 for x in _inward(d, dim, c, 0.25 * dx)]
    n = pr.normal
    if sum(a * b for a, b in zip(n, inward)) < 0.5 * math.hypot(*n):
        hint = [round(x, 3) + 0.0 for x in inward]
        raise SceneError(f"{key}.normal", f"{list(n)} does not point into the water from the wall at {_pt(c)} m, "
                         f"whose normal into the domain is {_pt(inward)}; give that normal, e.g. {hint}")


# ------------------------------------------------------------------------ the domain's shape
def _outline(d) -> list[tuple[float, float]]:
    """The inner outline (x, z) [m] of a domain's vertical section: a closed polygon, its
    open top closed at the walls' height (a flume's beach and an inclined side included)."""
    if isinstance(d, PolygonTank):
        return [tuple(v) for v in d.vertices]
    if isinstance(d, InclinedTank):
        top = d.length + d.height * math.tan(math.radians(d.angle))
        return [(0.0, 0.0), (d.length, 0.0), (top, d.height), (0.0, d.height)]
    if isinstance(d, Flume) and d.beach is not None:
        toe, slope = d.beach.toe, d.beach.slope
        rise = slope * (d.length - toe)
        if rise < d.height:
            return [(0.0, 0.0), (toe, 0.0), (d.length, rise), (d.length, d.height), (0.0, d.height)]
        return [(0.0, 0.0), (toe, 0.0), (toe + d.height / slope, d.height), (0.0, d.height)]
    return [(0.0, 0.0), (d.length, 0.0), (d.length, d.height), (0.0, d.height)]


def _sd_polygon(v, p) -> float:
    """Signed distance [m] of the point ``p`` (x, z) from the closed polygon ``v``: < 0 inside."""
    x, z = p
    inside, best = False, math.inf
    for k in range(len(v)):
        (x0, z0), (x1, z1) = v[k], v[(k + 1) % len(v)]
        ex, ez = x1 - x0, z1 - z0
        t = max(0.0, min(1.0, ((x - x0) * ex + (z - z0) * ez) / (ex * ex + ez * ez)))
        best = min(best, math.hypot(x - x0 - t * ex, z - z0 - t * ez))
        if (z0 > z) != (z1 > z) and x < x0 + (z - z0) * ex / ez:
            inside = not inside
    return -best if inside else best


def _sd_domain(d, dim, p) -> float:
    """Signed distance [m] of the point ``p`` from the domain's walls (their faces): < 0 in
    the domain, > 0 in or beyond a wall (exact inside, a lower bound outside)."""
    if dim == 2:
        return _sd_polygon(_outline(d), p)
    if isinstance(d, CylinderTank):
        return max(math.hypot(p[0], p[1]) - 0.5 * d.diameter, -p[2], p[2] - d.height)
    across = max(-p[1], p[1] - d.width)
    if isinstance(d, (InclinedTank, Flume)):  # the section's outline (a beach), extruded across y
        return max(_sd_polygon(_outline(d), (p[0], p[2])), across)
    return max(-p[0], p[0] - d.length, across, -p[2], p[2] - d.height)


def _inward(d, dim, p, h) -> list[float]:
    """The unit normal into the domain at the wall point ``p`` (-grad of the signed
    distance, central differences of step ``h``)."""
    g = []
    for k in range(dim):
        a, b = list(p), list(p)
        a[k] += h
        b[k] -= h
        g.append(-(_sd_domain(d, dim, a) - _sd_domain(d, dim, b)) / (2 * h))
    n = math.hypot(*g)
    return [x / n for x in g] if n > 0 else g


def _check_outline(v) -> None:
    """A polygon tank's outline does not cross itself."""
    n = len(v)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    for i in range(n):
        a, b = v[i], v[(i + 1) % n]
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue  # the edges that meet at the first corner
            c, e = v[j], v[(j + 1) % n]
            d1, d2, d3, d4 = cross(c, e, a), cross(c, e, b), cross(a, b, c), cross(a, b, e)
            if ((d1 > 0) != (d2 > 0) and (d3 > 0) != (d4 > 0)) or (0.0 in (d1, d2, d3, d4) and _touch(a, b, c, e)):
                raise SceneError("domain.vertices", f"edge {i} ({_pt(a)} to {_pt(b)} m) and edge {j} ({_pt(c)} to "
                                 f"{_pt(e)} m) cross: the outline must not cross itself; list the corners in order "
                                 f"round the container")


def _touch(a, b, c, e) -> bool:
    """Whether the segments a-b and c-e share a point (for collinear or end-on cases)."""
    def on(p, q, r):  # r on the segment p-q, given the three are collinear
        return (min(p[0], q[0]) <= r[0] <= max(p[0], q[0]) and min(p[1], q[1]) <= r[1] <= max(p[1], q[1])
                and (q[0] - p[0]) * (r[1] - p[1]) == (q[1] - p[1]) * (r[0] - p[0]))

    return on(a, b, c) or on(a, b, e) or on(c, e, a) or on(c, e, b)


# ------------------------------------------------------------------------ files of motion
def _check_at2(file, degree, key):
    """The accelerogram reads as the builder will read it (:func:`fluid.motion.read_at2`);
    returns it."""
    from cosim.errors import InputError
    from fluid.motion import read_at2

    try:
        return read_at2(file, degree)
    except (InputError, OSError, ValueError) as e:
        raise SceneError(key, f"{e}. A PEER NGA .AT2 record has 4 header lines, the 4th giving NPTS "
                         f"and DT (e.g. 'NPTS=  4000, DT= .0050 SEC'), then NPTS accelerations in g; fix the file "
                         f"or give another") from None


def first_sloshing_period(s) -> float | None:
    """The water's first (longest) sloshing period [s] by linear theory, ``omega^2 = g k
    tanh(k h)`` with ``k = pi / L`` over the free surface's length ``L`` (the longer side
    of a 3-D tank; a polygon's or an inclined tank's width at the still level) or ``k =
    1.8412 / R`` in a cylinder (e.g. Ibrahim 2005, Liquid Sloshing Dynamics, §1.2-1.3);
    None without a domain."""
    d, g = s.domain, s.world.g  # a tilted gravity: its magnitude, an estimate
    if d is None or isinstance(d, Flume) or g <= 0:
        return None
    if isinstance(d, CylinderTank):
        k, h = 1.8412 / (0.5 * d.diameter), d.depth
    elif isinstance(d, PolygonTank):
        xs, zs = [v[0] for v in d.vertices], [v[1] for v in d.vertices]
        k, h = math.pi / (max(xs) - min(xs)), d.fill_level - min(zs)
    elif isinstance(d, InclinedTank):
        k, h = math.pi / (d.length + d.depth * math.tan(math.radians(d.angle))), d.depth
    else:
        h = d.depth if d.depth is not None else max(b.hi[-1] for b in d.water)
        k = math.pi / max(d.length, d.width or 0.0)
    w2 = g * k * math.tanh(k * h)
    return 2 * math.pi / math.sqrt(w2) if w2 > 0 and math.isfinite(w2) else None  # a subnormal g underflows


def _check_ground_motion(s, dim) -> None:
    """Each record of a :class:`GroundMotion`: its direction, its file (read as the builder
    reads it), a record that lasts the scene (or ``hold``, or ``stop``) and reaches ``stop``, and a sampling step that
    resolves the water's first sloshing period (:func:`first_sloshing_period`) at least 10
    times: a coarser record cannot carry the motion that excites it. (A record sampled
    more finely than the fluid steps is fine: the walls are placed from the exactly
    integrated record at every stage of every step.)"""
    b = s.base_motion
    if len(b.components) > dim:
        raise SceneError("base_motion.components", f"has {len(b.components)} records; a {dim}-D scene moves along "
                         f"at most {dim} axes {'(x, z)' if dim == 2 else '(x, y, z)'}: give one record per direction")
    t1 = first_sloshing_period(s)
    for i, c in enumerate(b.components):
        key = f"base_motion.components[{i}]"
        _dim_vec(c.direction, dim, f"{key}.direction", "direction")
        _file(c.file, f"{key}.file")
        rec = _check_at2(c.file, b.baseline_degree, f"{key}.file")
        dt, end = rec.times[1] - rec.times[0], rec.times[-1]
        if b.stop is not None and b.stop > end:
            raise SceneError("base_motion.stop", f"= {b.stop:g} s lies after the end of {key}'s record ({end:.6g} s); "
                             f"give at most {end:.6g} s, or leave stop out to keep the whole records")
        if end < s.world.duration and not b.hold and b.stop is None:
            raise SceneError(f"{key}.file", f"the record ends at {end:.6g} s, before world.duration = "
                             f"{s.world.duration:.6g} s; shorten world.duration to at most {end:.6g} s, or set "
                             "base_motion.hold = true to keep the tank at rest after the record")
        _check_record_sampling(dt, t1, f"{key}.file")


def _check_record_sampling(dt, t1, key) -> None:
    """An accelerogram sampled every ``dt`` [s] must resolve the water's first sloshing
    period ``t1`` [s] (None: not known) at least 10 times: a coarser record cannot carry the
    motion that excites it."""
    if t1 is not None and dt > t1 / 10:
        raise SceneError(key, f"sampled every {dt:.4g} s: too coarse for the water's first sloshing "
                         f"period of {t1:.3g} s (linear theory), which needs at least 10 samples (DT <= "
                         f"{t1 / 10:.3g} s); the record cannot carry the motion that excites it: give a record "
                         "sampled more finely")


def _rows_of_numbers(path, key, strict: bool) -> list[list[float]]:
    """The numeric rows of a table file. ``strict``: every line that is not a comment
    (``#``) must be whitespace-separated numbers, as ``numpy.loadtxt`` reads them (base
    motion); otherwise (a paddle record, ``MotionRecord.from_file``) commas also separate
    and text lines before the first row of numbers are a header. A strict table that numpy
    reads whole comes back as its (rows, columns) array (a long record in a fraction of a
    second); one it refuses is parsed line by line, to name the line."""
    if strict:
        import warnings

        import numpy as np

        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # an empty table: its own message below
                table = np.loadtxt(path, comments="#", ndmin=2)
            if table.size:
                return table
        except (OSError, ValueError):
            pass
    try:  # a .gz file gunzipped, as numpy.loadtxt reads it
        opened = gzip.open(path, "rt", encoding="utf-8") if str(path).endswith(".gz") else open(path, encoding="utf-8")
        with opened as fh:
            text = fh.read()
    except (OSError, ValueError) as e:
        raise SceneError(key, f"{path!r} cannot be read as text ({e}); give a table of numbers") from None
    rows = []
    for n, line in enumerate(text.splitlines(), 1):
        body = line.split("#", 1)[0] if strict else line
        parts = body.split() if strict else body.replace(",", " ").split()
        if not parts:
            continue
        try:
            rows.append([float(x) for x in parts])
        except ValueError:
            if not strict and not rows:
                continue  # a header
            how = ("numbers separated by spaces or tabs (lines starting with # are comments)" if strict else
                   "numbers separated by spaces, tabs or commas (text lines before the first row are a header)")
            raise SceneError(key, f"line {n} of {path!r} is not a row of numbers: {line.strip()[:60]!r}; give "
                             f"rows of {how}: the time [s] first, then the values") from None
    return rows


def _samples(rows, path, column, file_key, column_key, strict: bool):
    """(times, values) of ``column`` of a table's rows (lists, or the array of a strict
    table), checked: enough columns and rows (``strict``: every row as wide as the first),
    finite, times increasing."""
    import numpy as np

    if len(rows) == 0:
        raise SceneError(file_key, f"{path!r} holds no row of numbers; give rows of time [s] and values")
    widths = (np.full(len(rows), rows.shape[1]) if isinstance(rows, np.ndarray) else np.array([len(r) for r in rows]))
    width = int(widths.min())
    if width != widths.max() and (strict or width <= column):
        short = int(np.flatnonzero(widths != widths[0])[0])
        raise SceneError(file_key, f"row {short + 1} of {path!r} has {widths[short]} value(s), row 1 has "
                         f"{widths[0]}; give every row the same columns")
    if width <= column:
        last = (f"its value columns are 1 .. {width - 1}; give one of them" if width > 1
                else "it has the time column only; add a column of values")
        raise SceneError(column_key, f"{column} is beyond the last column of {path!r} ({width} column(s), 0 is the "
                         f"time): {last}")
    if isinstance(rows, np.ndarray):
        t, v = rows[:, 0], rows[:, column]
    else:
        t, v = np.array([r[0] for r in rows], float), np.array([r[column] for r in rows], float)
    if len(rows) < 4:
        raise SceneError(file_key, f"{path!r} has {len(rows)} row(s); a record needs at least 4 samples (a cubic "
                         f"spline runs through them): give more rows")
    bad = np.flatnonzero(~(np.isfinite(t) & np.isfinite(v)))
    if bad.size:
        k = int(bad[0])
        raise SceneError(file_key, f"row {k + 1} of {path!r} holds a value that is not finite ({float(t[k])!r}, "
                         f"{float(v[k])!r}); give finite numbers")
    back = np.flatnonzero(~(np.diff(t) > 0))
    if back.size:
        k = int(back[0]) + 1
        raise SceneError(file_key, f"the times of {path!r} must increase: row {k + 1} (t = {t[k]:g} s) follows "
                         f"t = {t[k - 1]:g} s; sort the rows by time and drop repeated times")
    return t, v


def _at_rest(shift, dx, key, what, fix="") -> None:
    """A prescribed wall starts where it is built: its displacement ``shift`` [m] at t = 0
    is below a tenth of the particle spacing."""
    if abs(shift) > 0.1 * dx:
        raise SceneError(key, f"{what} {shift:.4g} m from where the walls are built at t = 0 (the record's value "
                         f"there, times scale): they would jump that far into the water at the first step; give "
                         f"a record that starts at 0 (subtract its value at t = 0){fix}")


def _check_table_motion(s) -> None:
    import numpy as np

    from cosim.errors import InputError
    from fluid.motion import Tabulated

    b = s.base_motion
    rows = _rows_of_numbers(b.file, "base_motion.file", strict=True)
    t, v = _samples(rows, b.file, b.column, "base_motion.file", "base_motion.column", strict=True)
    try:  # as the builder reads it
        np.loadtxt(b.file, comments="#", delimiter=None, ndmin=2)
        sig = Tabulated(tuple(t), tuple(x * b.scale for x in v), b.quantity)
    except (InputError, ValueError) as e:
        raise SceneError("base_motion.file", f"{b.file!r}: {e}; give rows of numbers: the time [s] first, then the "
                         f"values") from None
    if isinstance(s.fluid, SPH):  # without a fluid the clamps it carries start where it puts them
        _at_rest(float(sig.state(0.0)[0]), s.fluid.dx, "base_motion.file", "the table moves the tank")


def _blocks_overlap(a, b) -> bool:
    """Whether two blocks share a volume (meeting faces do not count)."""
    tol = 1e-9 * max(max(abs(x) for x in a.hi + b.hi), 1.0)
    return all(min(ah, bh) - max(al, bl) > tol for al, ah, bl, bh in zip(a.lo, a.hi, b.lo, b.hi))


def _check_tank_walls(s, d, dim) -> None:
    """A tank's inner walls (``domain.walls``): blocks of the scene's dimension inside the
    tank, apart from each other (their thickness against the kernel is the build's check,
    which knows the set-up's h)."""
    inner = (d.length,) + ((d.width,) if dim == 3 else ()) + (d.height,)
    for i, w in enumerate(d.walls):
        _dim_vec(w.lo, dim, f"domain.walls[{i}].lo")
        _dim_vec(w.hi, dim, f"domain.walls[{i}].hi")
        if any(lo < 0 for lo in w.lo) or any(h > e for h, e in zip(w.hi, inner)):
            raise SceneError(f"domain.walls[{i}]", f"the block {list(w.lo)} .. {list(w.hi)} m reaches outside the "
                             f"tank 0 .. {list(inner)} m (the tank's own walls are built around that box)")
        for k, v in enumerate(d.walls[:i]):
            if _blocks_overlap(v, w):
                raise SceneError(f"domain.walls[{i}]", f"the block {list(w.lo)} .. {list(w.hi)} m overlaps "
                                 f"domain.walls[{k}] ({list(v.lo)} .. {list(v.hi)} m): its particles would be laid "
                                 f"twice; let the blocks meet without overlapping")


def _check_roll_table(s, dim) -> None:
    """A recorded roll: a strict table, its angle at t = 0 moving no wall point by more
    than a tenth of a spacing (:func:`_at_rest`)."""
    b = s.base_motion
    rows = _rows_of_numbers(b.file, "base_motion.file", strict=True)
    t, v = _samples(rows, b.file, b.column, "base_motion.file", "base_motion.column", strict=True)
    if isinstance(s.fluid, SPH):
        _at_rest(roll_arm(s, dim) * math.radians(v[0] * b.scale), s.fluid.dx, "base_motion.file",
                 f"the record's first angle ({v[0] * b.scale:.4g} deg at t = {t[0]:g} s) turns the tank's farthest "
                 f"corner")


def _check_paddle_record(s) -> None:
    from cosim.errors import InputError
    from fluid.wavemaker import MotionRecord

    w = s.waves
    rows = _rows_of_numbers(w.file, "waves.file", strict=False)
    _samples(rows, w.file, w.column, "waves.file", "waves.column", strict=False)
    try:  # as the builder reads it
        value = float(MotionRecord.from_file(w.file, w.column, w.scale, w.t_shift)(0.0)[0])
    except InputError as e:
        raise SceneError("waves.file", f"{e}; give rows of numbers: the time [s] first, then the values") from None
    if w.zero_at_start:  # the paddle starts where it is built, whatever the record's value there
        return
    fix = ", a t_shift that starts it there, or set waves.zero_at_start = true"
    if w.paddle == "piston":
        _at_rest(value, s.fluid.dx, "waves.file", "the record puts the piston", fix)
    else:  # the flap's top moves by the angle times the flume's height
        _at_rest(value * s.domain.height, s.fluid.dx, "waves.file",
                 f"the record turns the flap by {value:.4g} rad, which puts its top", fix)


# ------------------------------------------------------------------------ an MJCF file
def _check_mjcf(b, key) -> dict:
    """Parse and compile the MJCF file as the builder will (MuJoCo, imported here only);
    the bodies named in ``bodies`` must be in it and free to move. Returns the names of
    the file's bodies (``all``), of the coupled ones (``coupled``), each site's body
    (``sites``) and where each site starts in the world (``site_pos``, x, y, z [m])."""
    import xml.etree.ElementTree as ET

    try:
        ET.parse(b.file)
    except ET.ParseError as e:
        raise SceneError(f"{key}.file", f"{b.file!r} is not XML ({e}); give an MJCF file, MuJoCo's XML model "
                         f"(<mujoco> ... </mujoco>)") from None
    import mujoco

    try:
        m = mujoco.MjSpec.from_file(str(b.file)).compile()
    except ValueError as e:  # MuJoCo's own parse and compile errors
        what = "; ".join(x.strip() for x in str(e).strip().splitlines() if x.strip())
        raise SceneError(f"{key}.file", f"MuJoCo refuses {b.file!r}: {what}; correct the file there") from None
    body = mujoco.mjtObj.mjOBJ_BODY
    every = [mujoco.mj_id2name(m, body, k) for k in range(1, m.nbody)]
    for k, n in enumerate(b.bodies):
        i = mujoco.mj_name2id(m, body, n)
        if i < 0:
            raise SceneError(f"{key}.bodies[{k}]", f"{n!r}: the file has no body of that name; its bodies: "
                             f"{[x for x in every if x]}")
        if m.body_weldid[i] == 0:
            raise SceneError(f"{key}.bodies[{k}]", f"{n!r} is fixed to the world (neither it nor a body it hangs "
                             f"from has a joint): it cannot move; give it a joint (e.g. <freejoint/>) or leave it "
                             f"out of bodies")
    coupled = list(b.bodies) or [mujoco.mj_id2name(m, body, k) for k in range(1, m.nbody) if m.body_dofnum[k] > 0]
    if not coupled:
        raise SceneError(f"{key}.file", f"{b.file!r} has no body that can move (none has a joint); give the "
                         f"floating bodies a joint, e.g. <freejoint/>")
    for n in coupled:  # their names become the outputs' columns and series
        if not is_name(n):
            what = f"body {n!r}" if n else f"an unnamed body (the {len(coupled)} movable ones: {coupled})"
            raise SceneError(f"{key}.file", f"{what} of {b.file!r} is coupled, and its name goes into the outputs: "
                             f"give it a name of letters, digits, '_' and '-' in the file (name=\"...\")")
    sites = {mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_SITE, k): mujoco.mj_id2name(m, body, int(m.site_bodyid[k]))
             for k in range(m.nsite)}
    d = mujoco.MjData(m)
    mujoco.mj_kinematics(m, d)
    where = {mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_SITE, k): d.site_xpos[k].tolist() for k in range(m.nsite)}
    return {"all": [x for x in every if x], "coupled": coupled, "sites": sites, "site_pos": where}


def _check_mjcf_fairlead(mj, fairlead, key) -> None:
    """``BODY.SITE`` of an MJCF model: a site of the file, on that body, which is coupled."""
    body, site = fairlead.split(".")
    if body not in mj["all"]:
        raise SceneError(key, f"no body named {body!r} in the MJCF file; its bodies: {mj['all']}")
    if body not in mj["coupled"]:
        raise SceneError(key, f"body {body!r} is not one of the coupled bodies {mj['coupled']}: a line on it "
                         f"would pull on nothing that moves; add it to bodies[0].bodies, or give it a joint")
    if site not in mj["sites"]:
        mine = sorted(k for k, v in mj["sites"].items() if v == body)
        raise SceneError(key, f"the MJCF file has no site {site!r}; the sites of body {body!r}: {mine}; add "
                         f"<site name=\"{site}\" pos=\"...\"/> to the body, or name one of these")
    if mj["sites"][site] != body:
        raise SceneError(key, f"site {site!r} is on body {mj['sites'][site]!r} in the MJCF file, not on {body!r}; "
                         f"give it as \"{mj['sites'][site]}.{site}\"")


# ------------------------------------------------------------------------ bodies' geometry
def _convex(a):
    """A solid (:meth:`cosim.scene.shapes.Shape.solid`) as a hull (2-D) or an oriented box (3-D; an upright
    cylinder: the box round it); a ball stays a ball."""
    if a[0] in ("ball", "hull", "obb"):
        return a
    if a[0] == "cyl":
        return ("obb", a[1], [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]], [a[2], a[2], a[3]])
    c, h = a[1], a[2]
    if len(c) == 2:
        return ("hull", [(c[0] + sx * h[0], c[1] + sz * h[1]) for sx, sz in ((-1, -1), (1, -1), (1, 1), (-1, 1))])
    return ("obb", c, [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]], h)


def _overlap_turned(a, b, tol) -> bool:
    """Whether two solids overlap by more than ``tol`` [m] when one is turned: convex
    outlines (2-D) or oriented boxes (3-D) by the separating axis theorem (Gottschalk et
    al. 1996: two convex bodies are apart if and only if their projections on some axis
    are; for boxes the 15 face normals and edge cross products suffice), a ball by its
    centre's distance from the other."""
    a, b = _convex(a), _convex(b)
    if a[0] == "ball":
        a, b = b, a
    if b[0] == "ball":
        p, r = b[1], b[2]
        if a[0] == "hull":
            return _sd_polygon(a[1], (p[0], p[-1])) < r - tol
        c, R, h = a[1:]
        q = [sum(R[k][j] * (p[k] - c[k]) for k in range(3)) for j in range(3)]  # p in the box's frame
        return _dist_box(q, [0.0] * 3, h) < r - tol
    if a[0] == "hull":
        axes = [(e[1] - d[1], d[0] - e[0]) for poly in (a[1], b[1]) for d, e in zip(poly, poly[1:] + poly[:1])]

        def spans(poly, n):
            v = [n[0] * x + n[1] * z for x, z in poly]
            return min(v), max(v)
    else:
        ra, rb = [[row[j] for row in a[2]] for j in range(3)], [[row[j] for row in b[2]] for j in range(3)]
        axes = ra + rb + [[u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
                          for u in ra for w in rb]

        def spans(box, n):
            mid = sum(x * y for x, y in zip(box[1], n))
            reach = sum(abs(sum(box[2][k][j] * n[k] for k in range(3))) * box[3][j] for j in range(3))
            return mid - reach, mid + reach
    for n in axes:
        norm = math.sqrt(sum(x * x for x in n))
        if norm < 1e-12:
            continue  # parallel edges: a face normal covers it
        n = [x / norm for x in n]
        (lo1, hi1), (lo2, hi2) = spans(a if a[0] == "obb" else a[1], n), spans(b if b[0] == "obb" else b[1], n)
        if min(hi1, hi2) - max(lo1, lo2) <= tol:
            return False
    return True


def _dist_box(p, c, h) -> float:
    return math.hypot(*(max(abs(x - y) - e, 0.0) for x, y, e in zip(p, c, h)))


def _overlap(a, b, tol) -> bool:
    """Whether two solids (:meth:`cosim.scene.shapes.Shape.solid`) overlap by more than ``tol`` [m]."""
    if "hull" in (a[0], b[0]) or "obb" in (a[0], b[0]):
        return _overlap_turned(a, b, tol)
    if a[0] > b[0]:
        a, b = b, a
    kinds = (a[0], b[0])
    if kinds == ("box", "box"):
        return all(abs(x - y) < ha + hb - tol for x, y, ha, hb in zip(a[1], b[1], a[2], b[2]))
    if kinds == ("ball", "ball"):
        return math.dist(a[1], b[1]) < a[2] + b[2] - tol
    if kinds == ("ball", "box"):
        return _dist_box(a[1], b[1], b[2]) < a[2] - tol
    if kinds == ("ball", "cyl"):
        (p, r), (c, R, hz) = a[1:], b[1:]
        out = math.hypot(max(math.hypot(p[0] - c[0], p[1] - c[1]) - R, 0.0), max(abs(p[2] - c[2]) - hz, 0.0))
        return out < r - tol
    if kinds == ("box", "cyl"):
        (c, h), (q, R, hz) = a[1:], b[1:]
        return _dist_box(q[:2], c[:2], h[:2]) < R - tol and abs(c[2] - q[2]) < h[2] + hz - tol
    (p, r, hp), (q, R, hq) = a[1:], b[1:]  # two cylinders
    return math.hypot(p[0] - q[0], p[1] - q[1]) < r + R - tol and abs(p[2] - q[2]) < hp + hq - tol


def _bounds(b, dim, floating) -> str:
    half = b.extent(dim)
    n = dim - 1 if floating else dim
    return _span([b.pos[k] - half[k] for k in range(n)], [b.pos[k] + half[k] for k in range(n)], dim, n)


def _check_overlaps(s, dim) -> None:
    """Builder bodies at given poses do not start inside each other (turned ones by
    :func:`_overlap_turned`); two floating ones do not share their footprint (their
    heights are computed later)."""
    solids = []
    for j, b in enumerate(s.bodies):
        if isinstance(b, MJCF):
            continue
        floating = b.place == "floating"
        me = b.solid(dim, floating)
        for i, a, other, a_floating in solids:
            if a_floating != floating:
                continue  # one floating, one given: the floating one's height is not known yet
            tol = 1e-9 * max(1.0, *(abs(x) for x in b.pos + a.pos))
            if _overlap(me, other, tol):
                raise SceneError(f"bodies[{j}].{_pos_key(b)}",
                                 f"body {b.name!r}{_turned(b)} ({_bounds(b, dim, floating)}) overlaps "
                                 f"body {a.name!r}{_turned(a)} (bodies[{i}], {_bounds(a, dim, floating)}) at the start"
                                 f"{': both float, so their footprints must be apart' if floating else ''}; move "
                                 f"one clear of the other")
        solids.append((j, b, me, floating))


_WALLS = {Flume: "beach", InclinedTank: "inclined side", PolygonTank: "polygon's wall", CylinderTank: "round wall",
          ArchRib: "rib's wall"}


def _check_walls(s, dim) -> None:
    """Beyond the domain's box (:func:`_check_inside`): bodies at a given pose clear of a
    flume's beach, an inclined side and a polygon's walls; any body within a cylinder
    tank's round wall. A turned body by its turned box's corners (a 3-D cylinder's: of the
    box round it, which errs towards refusing)."""
    d = s.domain
    if type(d) not in _WALLS or (isinstance(d, Flume) and d.beach is None):
        return
    wall = _WALLS[type(d)]
    for i, b in enumerate(s.bodies):
        if isinstance(b, MJCF):
            continue
        floating = b.place == "floating"
        solid = b.solid(dim, floating)
        tol = 1e-9 * max(1.0, *(abs(x) for x in b.pos))
        fix = "move it (or make it smaller) so that it lies in the water"
        if isinstance(d, CylinderTank):
            R, (x, y) = 0.5 * d.diameter, b.pos[:2]
            if solid[0] == "box" and floating:  # its footprint
                half = solid[2]
                far = max(math.hypot(x + sx * half[0], y + sy * half[1]) for sx in (-1, 1) for sy in (-1, 1))
            elif solid[0] in ("ball", "cyl"):
                far = math.hypot(x, y) + solid[2]
            else:
                far = max(math.hypot(q[0], q[1]) for q in _corners(b, dim))
            if far > R + tol:
                raise SceneError(f"bodies[{i}].{_pos_key(b)}",
                                 f"the body{_turned(b)} reaches {far:.4g} m from the tank's axis, beyond its "
                                 f"radius {R:g} m, into the {wall}; {fix}")
            continue
        if floating:
            continue  # its height is computed when it is built
        v = _outline(d)
        c = (b.pos[0], b.pos[-1])
        if solid[0] == "ball":
            gap, r = -_sd_polygon(v, c), solid[2]
            if gap < r - tol:
                raise SceneError(f"bodies[{i}].pos", f"the body (radius {r:g} m about {_pt(c)} m in x-z) "
                                 f"reaches {r - gap:.4g} m into the {wall}; {fix}")
            continue
        hull = _hull([(q[0], q[2]) for q in _corners(b, dim)])  # the body seen along y: its section's outline
        depth, q = max((_sd_polygon(v, q), q) for q in hull)
        if depth > tol:
            raise SceneError(f"bodies[{i}].{_pos_key(b)}",
                             f"the body's corner {_pt(q)} m (in x-z){_turned(b)} lies {depth:.3g} m deep in "
                             f"the {wall}; {fix}")
        for q in v:
            if _sd_polygon(hull, q) < -tol:
                raise SceneError(f"bodies[{i}].{_pos_key(b)}", f"the {wall}'s corner {_pt(q)} m lies inside the body "
                                 f"({_bounds(b, dim, False)}){_turned(b)}; {fix}")


def potential_depth(s) -> float:
    """The potential fluid's water depth [m]: its own, else the flume's or the waves', else deep."""
    if s.fluid.depth is not None:
        return s.fluid.depth
    if isinstance(s.domain, Flume):
        return s.domain.depth
    if isinstance(s.waves, IncidentSea):
        return s.waves.depth
    return math.inf


def _check_potential(s, dim) -> None:
    """The potential fluid: 3-D, builder bodies that pierce the surface, one water depth, waves
    inside the band its frequencies trust, a memory the frequency spacing resolves."""
    from fluid.potential.capytaine_io import EXTRA

    f = s.fluid
    try:
        import capytaine  # noqa: F401
        import h5netcdf  # noqa: F401
    except ImportError as e:
        raise SceneError("fluid.model", f"\"potential\" needs Capytaine and h5netcdf ({e.name} is not installed): "
                         f"{EXTRA}") from None
    if dim != 3:
        raise SceneError("world.dim", "linear potential flow about a body is 3-D; set world.dim = 3 (or use the "
                         "analytic fluid in 2-D)")
    from fluid.potential.hull import KINDS

    for i, b in enumerate(s.bodies):
        if not (isinstance(b, RigidBody) and b.geom in KINDS):
            raise SceneError(f"bodies[{i}].shape", f"the potential fluid meshes boxes, cylinders and spheres; a "
                             f"{b.shape!r} body needs the analytic or SPH fluid")
        if b.place == "given":  # its vertical half extent, turned by its euler where given
            half = b.extent(dim)[-1]
            lo, hi = b.pos[-1] - half, b.pos[-1] + half
            if lo >= f.level or hi <= f.level:
                where = "dry, above" if lo >= f.level else "fully submerged, below"
                raise SceneError(f"bodies[{i}].pos", f"body '{b.name}' spans z = {lo:g} .. {hi:g} m: {where} the "
                                 f"still water at {f.level:g} m; linear potential flow takes bodies that pierce the "
                                 f"surface (place = \"floating\", or a pos whose body crosses fluid.level)")
    if f.drift and s.waves is None:
        raise SceneError("fluid.drift", "the drift force needs waves: give waves (linear, irregular, or a flume's "
                         "wavemaker), or leave drift out")
    if f.interaction and f.drift:
        raise SceneError("fluid.interaction", "the drift force is a far-field momentum balance (Maruo 1960), "
                         "which gives the group's total, not each body's (that needs near-field pressure "
                         "integration, not implemented); set drift = false, or interaction = false for each body's own "
                         "drift without the others")
    for n in f.quadratic_drag:
        if n not in body_names(s):
            raise SceneError(f"fluid.quadratic_drag.{n}", f"no body named {n!r}; bodies: {sorted(body_names(s))}")
    scene_depth = (s.domain.depth if isinstance(s.domain, Flume) else
                   s.waves.depth if isinstance(s.waves, IncidentSea) else None)
    if f.depth is not None and scene_depth is not None and not math.isclose(f.depth, scene_depth, rel_tol=1e-9):
        what = "flume's depth (domain.depth)" if isinstance(s.domain, Flume) else "waves' depth (waves.depth)"
        raise SceneError("fluid.depth", f"{f.depth:g} m differs from the {what}, {scene_depth:g} m: the coefficients "
                         f"would be for another sea; leave fluid.depth out (it takes {scene_depth:g} m)")
    if f.omega_max is None:
        return
    from fluid.potential.participant import FREQUENCIES, frequency_grid
    from fluid.potential.radiation import BAND, SettingError

    try:
        grid = frequency_grid(f.omega_max, f.frequencies or FREQUENCIES, potential_depth(s), s.world.gravity)
    except SettingError as e:
        raise SceneError("fluid.omega_max", str(e).removeprefix("potential flow: omega_max = ")) from None
    period = (s.waves.period if isinstance(s.waves, (LinearWaves, RegularWaves, Piston, Flap)) else
              s.waves.tp if isinstance(s.waves, IrregularWaves) and s.waves.spectrum != "series" else None)
    if period is not None:
        w = 2 * math.pi / period
        if not grid[0] <= w <= BAND * f.omega_max:
            raise SceneError("fluid.omega_max", f"{f.omega_max:g} rad/s: the waves' {w:.4g} rad/s (period "
                             f"{period:g} s) lies outside the band the impulse response is trusted in, "
                             f"{grid[0]:.4g} .. {BAND * f.omega_max:.4g} rad/s (the lowest frequency .. omega_max "
                             f"/ 2); give more frequencies or an omega_max from {w / BAND:.4g} rad/s up")
    if f.memory is not None and (f.frequencies is not None or not f.interaction):  # else: chosen for the bodies
        window = math.pi / (grid[1] - grid[0])
        if f.memory > window:
            raise SceneError("fluid.memory", f"{f.memory:g} s is longer than the {window:.4g} s that {len(grid)} "
                             f"frequencies up to {f.omega_max:g} rad/s resolve (pi / spacing); give more "
                             f"frequencies or a shorter memory (unset: where the impulse response has decayed)")
