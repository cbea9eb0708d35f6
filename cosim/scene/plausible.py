"""Whether a scene can happen: the checks of physics beyond each field's own range and
beyond what fits together (:mod:`cosim.scene.checks`), each refusal stating its limit
(:mod:`cosim.scene.limits`) and the slip that most likely made the value.

- bodies: a floating body needs gravity (without it there is no buoyancy); a body given
  by its mass is no denser than the densest matter; its fairleads lie on or near its hull,
  within ``FAIRLEAD_REACH`` bounding radii of its centre (further out, world coordinates
  were given where body-frame ones are expected);
- excitations: a tank's base motion peaks at most ``MAX_BASE_ACCELERATION`` (5 g: the
  harmonic's ``a (2 pi / T)^2``, a roll's at the tank's farthest corner, a table's
  spline, a record's times its scales); each record of a ground motion acts along its own
  axis (their directions perpendicular); a wavemaker's paddle sweeps forward (half its
  stroke, linear wavemaker theory, Dean & Dalrymple 1991 §6.2) at most ``PADDLE_SHARE``
  of the flume's length, and no body lies in its sweep;
- lines: a submerged weight at most the weight in air (``mass_per_length`` g); an elastic
  line starts stretched by at most ``MAX_LINE_STRAIN`` (its straight anchor-fairlead
  distance over its length: at a given pose, an MJCF site, or for a floating body the
  nearest its fairlead comes over every draft).
"""

from __future__ import annotations

import math

from cosim.scene.fields import Gauges, Num, Part, Parts, SceneError, Table, Vec, Vecs, spec_fields
from cosim.scene.limits import (DENSITY_WHY, FAIRLEAD_REACH, G0, MAX_BASE_ACCELERATION, MAX_DENSITY, MAX_LENGTH,
                                MAX_LINE_STRAIN, MIN_DENSITY, MIN_LENGTH, PADDLE_SHARE)
from cosim.scene.shapes import RigidBody
from cosim.scene.spec import (MJCF, Earthquake, ElasticPlate, Flap, Flume, GroundMotion, NoFluid, PaddleRecord, Piston,
                              Roll, RollTable, Shake, TableMotion)


def _g(x: float) -> str:
    """An acceleration [m/s^2] for a message, with its value in g."""
    return f"{x:.4g} m/s^2 ({x / G0:.3g} g)"


def _at_knots(sig):
    """A tabulated signal's (value, rate, acceleration) at its samples (the spline's knots,
    the ends moved just inside the record, where the spline's derivatives are its own)."""
    import numpy as np

    t = np.asarray(sig.times)
    return sig.sample(np.clip(t, t[0] + 1e-9 * (t[-1] - t[0]), t[-1] - 1e-9 * (t[-1] - t[0])))


# ------------------------------------------------------------------------ scales
def check_scales(spec, prefix: str = "") -> None:
    """Every length and coordinate [m] the scene declares within :data:`MAX_LENGTH` (the
    Earth's radius), every size it declares > 0 (and a box's edges) at least
    :data:`MIN_LENGTH`, every density [kg/m^3] at least :data:`MIN_DENSITY`: beyond them
    the numbers overflow or vanish in the solvers (a body 1e300 m long, a box of 5e-324 m)
    and no physical scene needs them. The fields are walked from their declarations."""
    for name, check, _ in spec_fields(type(spec)):
        key, v = f"{prefix}{name}", getattr(spec, name)
        if v is None:
            continue
        if isinstance(check, (Part, Parts)):
            for i, part in enumerate(v if isinstance(check, Parts) else [v]):
                check_scales(part, f"{key}[{i}]." if isinstance(check, Parts) else f"{key}.")
            continue
        if check.unit == "kg/m^3" and isinstance(check, Num) and v < MIN_DENSITY:
            raise SceneError(key, f"{v:g} kg/m^3 is below {MIN_DENSITY:g} kg/m^3, a tenth of air's density: no body "
                             f"or liquid is that light; give a density >= {MIN_DENSITY:g}")
        if check.unit != "m" and not isinstance(check, Gauges):
            continue
        values = (list(v.values()) if isinstance(check, Table) else [v] if isinstance(check, Num) else list(v))
        flat = [x for item in values for x in (item if isinstance(item, tuple) else (item,))]
        for x in flat:
            if abs(x) > MAX_LENGTH and not (isinstance(check, Num) and check.infinite and x == math.inf):
                raise SceneError(key, f"{x:g} m is beyond {MAX_LENGTH:g} m, the Earth's radius: a scene lies on the "
                                 f"Earth; check the units (m)")
        sizes = (flat if isinstance(check, Vec) and name == "size" else
                 [v] if isinstance(check, Num) and check.lo == 0 and check.lo_open else [])
        for x in sizes:
            if x < MIN_LENGTH:
                raise SceneError(key, f"{x:g} m is below {MIN_LENGTH:g} m, a micron: the water round it is no "
                                 f"continuum for these models; check the units (m)")


# ------------------------------------------------------------------------ the SPH fluid
def check_fluid(s) -> None:
    """The SPH fluid's speed of sound at least the water's long-wave speed ``sqrt(g h)``
    (h the still water's depth, or the highest water block's top): slower, gravity waves
    outrun sound and the weakly compressible fluid is no longer nearly incompressible
    (Monaghan 1994 asks c0 >= 10 times the flow's speed, ``fluid.c0_factor``)."""
    from cosim.scene.spec import SPH

    if not isinstance(s.fluid, SPH) or s.domain is None or s.world.g <= 0:
        return
    from cosim.scene.build import fluid_config
    from cosim.scene.setup import choose, u_max

    wave = u_max(s, "still")
    c0 = fluid_config(s, choose(s), numbers_only=True).speed_of_sound
    if c0 < wave:
        key = next((f"fluid.{k}" for k in ("c0", "u_max") if getattr(s.fluid, k) is not None), "fluid.c0")
        raise SceneError(key, f"gives a speed of sound of {c0:.4g} m/s, below the water's long-wave speed sqrt(g h) "
                         f"= {wave:.4g} m/s: gravity waves would outrun sound and the fluid would be no longer nearly "
                         f"incompressible; give c0 >= {10 * wave:.4g} m/s (10 sqrt(g h), Monaghan 1994), or leave "
                         f"c0 and u_max out")


# ------------------------------------------------------------------------ bodies
def bounding_radius(b, dim: int) -> float:
    """The radius [m] of the smallest sphere about a builder body's centre that holds it
    (:meth:`cosim.scene.shapes.Shape.bounding_radius`)."""
    return b.bounding_radius(dim)


def check_bodies(s, dim: int) -> None:
    """Gravity for floating bodies, the mean density of bodies given by mass, and each
    fairlead within reach of its body's hull."""
    for i, b in enumerate(s.bodies):
        if not isinstance(b, RigidBody):
            continue
        if b.place == "floating" and s.world.g == 0 and not isinstance(s.fluid, NoFluid):
            raise SceneError("world.gravity", f"0 m/s^2: body {b.name!r} (bodies[{i}]) is placed floating, but "
                             f"without gravity there is no buoyancy (nor weight) to float it; give world.gravity "
                             f"> 0 (9.81 on Earth), or place it at a given pos")
        if b.mass is not None:
            v = b.volume(dim)
            if b.mass / v < MIN_DENSITY:
                raise SceneError(f"bodies[{i}].mass", f"{b.mass:g} kg in {v:.4g} m^3 is a mean density of "
                                 f"{b.mass / v:.4g} kg/m^3, below {MIN_DENSITY:g}, a tenth of air's: give a mass of "
                                 f"at least {MIN_DENSITY * v:.4g} kg")
            if b.mass / v > MAX_DENSITY:
                per = " per metre of depth" if dim == 2 else ""
                raise SceneError(f"bodies[{i}].mass", f"{b.mass:g} kg in {v:.4g} m^3{per} is a mean density of "
                                 f"{b.mass / v:.4g} kg/m^3, beyond {MAX_DENSITY:g}, {DENSITY_WHY}; give a mass "
                                 f"up to {MAX_DENSITY * v:.4g} kg, or a larger body")
        reach = FAIRLEAD_REACH * b.bounding_radius(dim)
        for name, p in b.fairleads.items():
            r = math.sqrt(sum(x * x for x in p))
            if r > reach:
                rel = tuple(x - c for x, c in zip(p, b.pos)) if len(b.pos) == len(p) else None
                hint = (f"; if {_pt(p)} is where it is in the world, give {_pt(rel)} (it less the body's pos)"
                        if rel is not None and math.sqrt(sum(x * x for x in rel)) <= reach else "")
                raise SceneError(f"bodies[{i}].fairleads.{name}",
                                 f"{_pt(p)} m is {r:.4g} m from the body's centre, beyond {reach:.4g} m "
                                 f"({FAIRLEAD_REACH:g} times its bounding radius {reach / FAIRLEAD_REACH:.4g} m): a "
                                 f"fairlead lies on or near the hull, in the body's frame (from its centre), not in "
                                 f"the world's{hint}")


def _pt(v) -> str:
    return "(" + ", ".join(f"{x + 0.0:.4g}" for x in v) + ")"


# ------------------------------------------------------------------------ excitations
def check_excitations(s, dim: int) -> None:
    """Base motion's peak acceleration and axes, and the wavemaker's stroke."""
    if s.base_motion is not None:
        _check_base_motion(s, dim)
    if isinstance(s.waves, (Piston, Flap, PaddleRecord)) and isinstance(s.domain, Flume):
        _check_paddle(s, dim)


def _refuse_peak(key: str, peak: float, what: str, fix) -> None:
    """Refuse a base motion whose peak acceleration ``peak`` [m/s^2] passes the limit;
    ``fix()`` says what to give instead (called only then: it may divide by the peak)."""
    if peak > MAX_BASE_ACCELERATION:
        raise SceneError(key, f"{what} peaks at {_g(peak)}, beyond {_g(MAX_BASE_ACCELERATION)}, more than the "
                         f"strongest shaking tables and recorded earthquakes reach (about 3-4 g); {fix()}")


def _check_base_motion(s, dim: int) -> None:
    from fluid.motion import read_at2

    b = s.base_motion
    if isinstance(b, Shake):
        w = 2 * math.pi / b.period
        w2 = w * w  # inf for a sub-normal period, never an OverflowError
        if b.acceleration is not None:
            _refuse_peak("base_motion.acceleration", abs(b.acceleration), "the shaking",
                         lambda: f"give at most {MAX_BASE_ACCELERATION:.4g} m/s^2")
        else:
            _refuse_peak("base_motion.amplitude", abs(b.amplitude) * w2, f"the shaking ({abs(b.amplitude):g} m at "
                         f"{b.period:g} s: amplitude (2 pi / period)^2)", lambda: f"give an amplitude up to "
                         f"{MAX_BASE_ACCELERATION / w2:.4g} m, or a longer period")
    elif isinstance(b, Roll):
        from cosim.scene.checks import roll_arm

        arm = roll_arm(s, dim)
        w = 2 * math.pi / b.period
        peak = math.radians(abs(b.amplitude)) * w * w * arm
        _refuse_peak("base_motion.amplitude", peak, f"the roll ({abs(b.amplitude):g} deg at {b.period:g} s, at the "
                     f"tank's corner {arm:.4g} m from the axis)", lambda: "give a smaller amplitude or a longer period")
    elif isinstance(b, RollTable):
        import numpy as np

        from cosim.scene.build import roll_record
        from cosim.scene.checks import roll_arm

        arm, sig = roll_arm(s, dim), roll_record(b)
        _, rate, acc = _at_knots(sig)
        peak = float(np.hypot(acc, rate ** 2).max()) * arm  # tangential and centripetal at the farthest corner
        _refuse_peak("base_motion.scale", peak, f"the recorded roll (times scale = {b.scale:g}, at the tank's "
                     f"corner {arm:.4g} m from the axis)",
                     lambda: f"check that the table's angles are in degrees, and give a scale up to "
                             f"{abs(b.scale) * MAX_BASE_ACCELERATION / peak:.4g}")
    elif isinstance(b, TableMotion):
        import numpy as np

        from cosim.scene.checks import _rows_of_numbers
        from fluid.motion import Tabulated

        rows = np.array(_rows_of_numbers(b.file, "base_motion.file", strict=True), float)
        sig = Tabulated(tuple(rows[:, 0]), tuple(rows[:, b.column] * b.scale), b.quantity)
        peak = float(np.abs(_at_knots(sig)[2]).max())
        _refuse_peak("base_motion.scale", peak, f"the table's motion (times scale = {b.scale:g})",
                     lambda: f"check the table's units and give a scale up to "
                             f"{abs(b.scale) * MAX_BASE_ACCELERATION / peak:.4g}")
    elif isinstance(b, Earthquake):
        peak = max(abs(x) for x in read_at2(b.file, None).values) * abs(b.scale)
        _refuse_peak("base_motion.scale", peak, f"the record times scale = {b.scale:g}",
                     lambda: f"give a scale up to {abs(b.scale) * MAX_BASE_ACCELERATION / peak:.4g}")
    elif isinstance(b, GroundMotion):
        _check_ground_motion(s, dim, read_at2)


def _check_ground_motion(s, dim, read_at2) -> None:
    """Each record on its own axis, each record's peak times its scales within the limit."""
    b = s.base_motion
    unit = [tuple(x / math.sqrt(sum(y * y for y in c.direction)) for x in c.direction) for c in b.components]
    for j, c in enumerate(b.components):
        for i in range(j):
            cos = sum(x * y for x, y in zip(unit[i], unit[j]))
            if abs(cos) > 1e-9:
                same = abs(abs(cos) - 1) <= 1e-9
                raise SceneError(f"base_motion.components[{j}].direction",
                                 f"{_pt(c.direction)} is {'along the same axis as' if same else 'not perpendicular to'}"
                                 f" base_motion.components[{i}].direction {_pt(b.components[i].direction)} (the angle "
                                 f"between them is {math.degrees(math.acos(max(-1.0, min(1.0, cos)))):.4g} deg): each "
                                 f"record is the ground's motion along its own axis, and two along one axis would add "
                                 f"up; give perpendicular directions, e.g. [1, 0] and [0, 1], or join the records")
    for j, c in enumerate(b.components):
        k = abs(b.scale * c.scale)
        peak = max(abs(x) for x in read_at2(c.file, None).values) * k
        _refuse_peak(f"base_motion.components[{j}].scale", peak, f"record {j} times its scales ({b.scale:g} x "
                     f"{c.scale:g})", lambda: f"give scales whose product base_motion.scale x "
                     f"base_motion.components[{j}].scale is at most {k * MAX_BASE_ACCELERATION / peak:.4g}")


def paddle_stroke(s) -> float:
    """The horizontal stroke [m] of a flume's paddle (a flap's at the flume's top): twice
    its largest excursion from x = 0 (linear wavemaker theory for a piston or flap,
    ``fluid.wavemaker``; a record's largest value)."""
    from fluid.wavemaker import RegularWavemaker

    w, d = s.waves, s.domain
    if isinstance(w, (Piston, Flap)):
        wm = RegularWavemaker(w.kind, w.height, w.period, d.depth, w.ramp, s.world.gravity)
        return wm.stroke if w.kind == "piston" else wm.stroke * d.height / wm.depth
    from fluid.wavemaker import MotionRecord

    reach = float(max(abs(x) for x in MotionRecord.from_file(w.file, w.column, w.scale, w.t_shift).value))
    return 2 * reach * (1.0 if w.paddle == "piston" else d.height)


def _check_paddle(s, dim: int) -> None:
    """The paddle sweeps at most ``PADDLE_SHARE`` of the flume forward and strikes no body."""
    d, w = s.domain, s.waves
    half = 0.5 * paddle_stroke(s)
    what = (f"waves of {w.height:g} m at {w.period:g} s in {d.depth:g} m of water need a paddle stroke of "
            f"{2 * half:.4g} m (linear wavemaker theory)" if isinstance(w, (Piston, Flap)) else
            f"the record moves the paddle {2 * half:.4g} m end to end")
    fix = ("a shorter period or a lower wave, or a longer flume" if isinstance(w, (Piston, Flap)) else
           "check the record's units (m, or rad for a flap) and its scale")
    if half > PADDLE_SHARE * d.length:
        raise SceneError("waves.period" if isinstance(w, (Piston, Flap)) else "waves.file",
                         f"{what}: the paddle would sweep {half:.4g} m into the flume (and as far back, where the "
                         f"builder lays the floor behind it), beyond {PADDLE_SHARE:g} of its length "
                         f"({PADDLE_SHARE * d.length:.4g} m of {d.length:g} m); {fix}")
    for i, b in enumerate(s.bodies):
        if isinstance(b, MJCF):
            continue
        near = b.pos[0] - b.extent(dim)[0]
        if near < half:
            raise SceneError(f"bodies[{i}].{'base' if isinstance(b, ElasticPlate) else 'pos'}",
                             f"the body starts at x = {near:.4g} m, within the paddle's sweep ({what}: it reaches "
                             f"x = {half:.4g} m); move the body beyond x = {half:.4g} m")


# ------------------------------------------------------------------------ lines
def check_lines(s, dim: int, mj) -> None:
    """Each line's weight against its mass, and the strain an elastic line starts at."""
    from cosim.scene.shapes import rotation as _rotation

    m = s.moorings
    if m is None:
        return
    g = s.world.gravity
    builders = {b.name: b for b in s.bodies if not isinstance(b, MJCF)}
    for i, ln in enumerate(m.lines):
        key = f"moorings.lines[{i}]"
        if ln.mass_per_length is not None and g > 0 and ln.weight > ln.mass_per_length * g * (1 + 1e-9):
            raise SceneError(f"{key}.weight", f"{ln.weight:g} N/m is more than the line weighs in air, mass_per_length "
                             f"x g = {ln.mass_per_length:g} x {g:g} = {ln.mass_per_length * g:.4g} N/m: a submerged "
                             f"weight is the weight in air less the buoyancy; give at most {ln.mass_per_length * g:.4g}"
                             f" N/m")
        body, site = ln.fairlead.split(".")
        if ln.EA is None and body in builders:
            continue  # a builder body's inextensible line is checked with its start (cosim.scene.checks)
        b = builders.get(body)
        if b is None:
            if mj is None or site not in mj["site_pos"]:
                continue
            q = mj["site_pos"][site]
            dist, where = math.dist(q if dim == 3 else (q[0], q[2]), ln.anchor), "at the start"
        elif b.place == "floating":
            dist, where = _nearest_floating(s, dim, b, b.fairleads[site], ln.anchor), "at the nearest it comes, " \
                "over every draft"
        else:
            p = b.fairleads[site]
            if dim == 3 and b.euler is not None:
                r = _rotation(b.euler)
                p = [sum(r[k][j] * p[j] for j in range(3)) for k in range(3)]
            dist, where = math.dist([c + o for c, o in zip(b.pos, p)], ln.anchor), "at the start"
        strain = dist / ln.length - 1.0
        if ln.EA is None and strain > 1e-12:
            raise SceneError(f"{key}.length", f"{ln.length:g} m is shorter than the straight distance {dist:.4g} m "
                             f"from the anchor {_pt(ln.anchor)} m to the fairlead {ln.fairlead!r} {where}: an "
                             f"inextensible line cannot reach; give a length of at least {dist:.4g} m, move the "
                             f"anchor closer, or give EA (an elastic line that starts stretched)")
        if ln.EA is not None and strain > MAX_LINE_STRAIN:
            raise SceneError(f"{key}.length", f"{ln.length:g} m is shorter than the straight distance {dist:.4g} m "
                             f"from the anchor {_pt(ln.anchor)} m to the fairlead {ln.fairlead!r} {where}: the "
                             f"elastic line would start stretched by {100 * strain:.3g} %, beyond "
                             f"{100 * MAX_LINE_STRAIN:g} %, more than any mooring material takes before it breaks "
                             f"(steel about 2 %, polyester 12 %, nylon about 25 %); give a length of at least "
                             f"{dist / (1 + MAX_LINE_STRAIN):.4g} m, or check the anchor's units (m)")


def _nearest_floating(s, dim, b, offset, anchor) -> float:
    """The shortest distance [m] from ``anchor`` to a floating body's fairlead at ``offset``
    over every draft (its centre between half its height below and above the level)."""
    from cosim.scene.build import water_level

    height = 2 * b.half_size(dim)[-1]
    level = water_level(s)
    level = 0.0 if level is None else level
    lo, hi = level - 0.5 * height + offset[-1], level + 0.5 * height + offset[-1]
    dz = 0.0 if lo <= anchor[-1] <= hi else min(abs(lo - anchor[-1]), abs(hi - anchor[-1]))
    horiz = math.dist([c + o for c, o in zip(b.pos, offset[:-1])], anchor[:-1])
    return math.hypot(horiz, dz)
