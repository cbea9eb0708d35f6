"""The checks of a scene as a whole (:meth:`cosim.scene.spec.Scene.validate`): what fits
together, named by key path (``moorings.lines[1].fairlead``), before any work is done.

Each field on its own was checked by its class (:mod:`cosim.scene.fields`); here: vector
lengths against the dimension, which fluid goes with which domain and excitation, body
names and fairlead references, bodies inside the tank and above its floor, probes
inside the domain.
"""

from __future__ import annotations

from cosim.scene.fields import SceneError
from cosim.scene.spec import (MJCF, SPH, Analytic, Box, CylinderTank, Cylinder, Flap, Flume, InclinedTank,
                              NoFluid, PaddleRecord, Piston, PolygonTank, Roll, Sphere, Tank)


def body_names(scene) -> list[str]:
    """Names of the scene's bodies (an MJCF file's named ones; its movable bodies are only
    known once it is loaded)."""
    out = []
    for b in scene.bodies:
        out.extend(b.bodies if isinstance(b, MJCF) else [b.name])
    return out


def _dim_vec(v, dim, path, what="point"):
    if v is not None and len(v) != dim:
        coords = "(x, z)" if dim == 2 else "(x, y, z)"
        raise SceneError(path, f"{list(v)} has {len(v)} coordinates; a {dim}-D scene gives a {what} as {coords}")


def check_scene(s) -> None:
    dim = s.world.dim
    if not s.bodies and not isinstance(s.fluid, SPH):
        raise SceneError("bodies", "the scene has nothing that moves: give bodies, or the SPH fluid in a domain")
    mjcf = [i for i, b in enumerate(s.bodies) if isinstance(b, MJCF)]
    if mjcf and len(s.bodies) > 1:
        raise SceneError(f"bodies[{mjcf[0]}]", "an MJCF file brings all its bodies: give it as the only entry of "
                         "bodies (builder bodies and several files cannot be mixed)")
    _check_fluid_and_domain(s, dim)
    _check_excitations(s, dim)
    _check_bodies(s, dim)
    _check_moorings(s, dim)
    _check_probes(s, dim)
    if s.coupling.scheme == "fluid-first" and not isinstance(s.fluid, SPH):
        raise SceneError("coupling.scheme", "'fluid-first' needs the SPH fluid (the loads it exchanged); use 'auto'")
    if s.coupling.light_body == "subiterate" and s.coupling.scheme not in ("auto", "fluid-first"):
        raise SceneError("coupling.light_body", "'subiterate' needs the fluid-first scheme; set coupling.scheme to "
                         "'auto' or 'fluid-first'")


def _check_fluid_and_domain(s, dim):
    d = s.domain
    if isinstance(s.fluid, SPH):
        if d is None:
            raise SceneError("domain", "the SPH fluid needs a domain: a tank, flume, inclined-tank, cylinder-tank or "
                             "polygon")
    elif d is not None:
        raise SceneError("domain", f"a domain holds the SPH fluid's particles; with fluid.model = "
                         f"{s.fluid.model!r} leave it out (the analytic fluid's surface is fluid.level)")
    if d is None:
        return
    if isinstance(d, (Flume, PolygonTank)) and dim != 2:
        raise SceneError("domain.kind", f"a {d.kind} is 2-D; set world.dim = 2 or use a tank")
    if isinstance(d, CylinderTank) and dim != 3:
        raise SceneError("domain.kind", "a cylinder-tank is 3-D; set world.dim = 3")
    if isinstance(d, (Tank, InclinedTank)):
        if dim == 3 and d.width is None:
            raise SceneError("domain.width", f"a 3-D {d.kind} needs its width along y [m]")
        if dim == 2 and d.width is not None:
            raise SceneError("domain.width", "a 2-D scene is the x-z plane; leave width out")
    if isinstance(d, Tank):
        for i, b in enumerate(d.water):
            _dim_vec(b.lo, dim, f"domain.water[{i}].lo")
            _dim_vec(b.hi, dim, f"domain.water[{i}].hi")
            inner = (d.length,) + ((d.width,) if dim == 3 else ()) + (d.height,)
            if any(lo < 0 for lo in b.lo) or any(h > e for h, e in zip(b.hi, inner)):
                raise SceneError(f"domain.water[{i}]", f"the block {list(b.lo)} .. {list(b.hi)} m reaches outside "
                                 f"the tank 0 .. {list(inner)} m")
    sph = s.fluid
    if isinstance(sph, SPH):
        depth = getattr(d, "level", None)
        if isinstance(d, PolygonTank):
            depth = d.fill_level - min(v[1] for v in d.vertices)
        if depth is not None and depth < 2 * sph.dx:
            raise SceneError("fluid.dx", f"{sph.dx} m leaves fewer than 2 particles over the water depth "
                             f"{depth:g} m; refine dx to at most {depth / 4:.3g} m (4 layers)")


def _check_excitations(s, dim):
    if s.waves is not None:
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
        if isinstance(s.waves, PaddleRecord):
            _file(s.waves.file, "waves.file")
    b = s.base_motion
    if b is not None:
        if s.domain is None:
            raise SceneError("base_motion", "base motion moves the SPH fluid's tank; give a domain and "
                             "fluid.model = \"sph\"")
        if isinstance(s.domain, Flume):
            raise SceneError("base_motion", "a flume does not move as a whole; use a tank")
        if isinstance(b, Roll):
            _dim_vec(b.point, dim, "base_motion.point")
            if dim == 3 and b.axis is None:
                raise SceneError("base_motion.axis", "a 3-D roll needs its axis (3 components)")
            if dim == 2 and b.axis is not None:
                raise SceneError("base_motion.axis", "a 2-D roll is about +y; leave axis out")
        else:
            if dim == 3 and b.direction == (1.0, 0.0):
                raise SceneError("base_motion.direction", "a 3-D scene needs the direction as (x, y, z), e.g. "
                                 "[1, 0, 0]; the default (1, 0) is the x axis of a 2-D scene")
            _dim_vec(b.direction, dim, "base_motion.direction", "direction")
        if hasattr(b, "file"):
            _file(b.file, "base_motion.file")


def _file(path, key):
    from pathlib import Path

    if not Path(path).is_file():
        raise SceneError(key, f"no file {path!r} (a relative path is read from the scene file's folder)")


def _check_bodies(s, dim):
    seen = {}
    for i, b in enumerate(s.bodies):
        key = f"bodies[{i}]"
        if isinstance(b, MJCF):
            _file(b.file, f"{key}.file")
            names = b.bodies
        else:
            names = [b.name]
            if b.place == "floating":
                if len(b.pos) != dim - 1:
                    raise SceneError(f"{key}.pos", f"{list(b.pos)}: a floating body's height is computed; give "
                                     f"its horizontal position only, {'(x,)' if dim == 2 else '(x, y)'}")
                if isinstance(s.fluid, NoFluid):
                    raise SceneError(f"{key}.place", "a floating body needs a fluid to float on (fluid.model)")
            else:
                _dim_vec(b.pos, dim, f"{key}.pos")
            if isinstance(b, Box):
                _dim_vec(b.size, dim, f"{key}.size", "size")
            if isinstance(b, Sphere) and dim != 3:
                raise SceneError(f"{key}.shape", "a sphere is 3-D; in 2-D use a cylinder (a circle in x-z)")
            if isinstance(b, Cylinder) and (b.length is None) == (dim == 3):
                raise SceneError(f"{key}.length", "a 3-D cylinder needs its length [m]" if dim == 3 else
                                 "a 2-D cylinder is a circle in the x-z plane, 1 m long; leave length out")
            for name, p in b.fairleads.items():
                _dim_vec(p, dim, f"{key}.fairleads.{name}")
        for n in names:
            if n in seen:
                raise SceneError(f"{key}.name", f"{n!r} is also the name of bodies[{seen[n]}]; names must be unique")
            seen[n] = i
    if isinstance(s.fluid, Analytic):
        for table in ("linear_damping", "quadratic_damping"):
            for n in getattr(s.fluid, table):
                if n not in seen and not any(isinstance(b, MJCF) for b in s.bodies):
                    raise SceneError(f"fluid.{table}.{n}", f"no body named {n!r}; bodies: {sorted(seen)}")
    if isinstance(s.fluid, SPH) and s.domain is not None:
        _check_inside(s, dim)


def _extent(b, dim):
    """Half extents [m] of a builder body along (x, [y,] z), upright."""
    if isinstance(b, Box):
        return [0.5 * x for x in b.size]
    if isinstance(b, Cylinder):
        return [b.radius] * (dim - 1) + [b.radius if dim == 2 else 0.5 * b.length]
    return [b.radius] * dim


def _domain_box(d, dim):
    """Lower and upper corners [m] of the domain's inner box (the walls' faces)."""
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


def _check_inside(s, dim):
    """Bodies at a given pose lie within the domain's inner box (the walls' faces)."""
    lo, hi = _domain_box(s.domain, dim)
    for i, b in enumerate(s.bodies):
        if isinstance(b, MJCF) or b.euler is not None:
            continue
        half = _extent(b, dim)
        n = dim - 1 if b.place == "floating" else dim
        for k in range(n):
            if b.pos[k] - half[k] < lo[k] or b.pos[k] + half[k] > hi[k]:
                axis = "xyz"[k] if dim == 3 else "xz"[k]
                raise SceneError(f"bodies[{i}].pos", f"the body reaches {b.pos[k] - half[k]:g} .. "
                                 f"{b.pos[k] + half[k]:g} m along {axis}, outside the domain's {lo[k]:g} .. "
                                 f"{hi[k]:g} m; move it inside the tank")


def _check_moorings(s, dim):
    m = s.moorings
    if m is None:
        return
    if not s.bodies:
        raise SceneError("moorings", "mooring lines end on bodies; add the body that carries the fairleads")
    builders = {b.name: b for b in s.bodies if not isinstance(b, MJCF)}
    mjcf = any(isinstance(b, MJCF) for b in s.bodies)
    for i, ln in enumerate(m.lines):
        key = f"moorings.lines[{i}]"
        _dim_vec(ln.anchor, dim, f"{key}.anchor")
        body, site = ln.fairlead.split(".")
        if body in builders:
            if site not in builders[body].fairleads:
                raise SceneError(f"{key}.fairlead", f"body {body!r} has no fairlead {site!r}; its fairleads: "
                                 f"{sorted(builders[body].fairleads)}")
        elif not mjcf:
            raise SceneError(f"{key}.fairlead", f"no body named {body!r}; bodies: {sorted(builders)}")
    first = {}
    for i, ln in enumerate(m.lines):
        if ln.fairlead in first:
            raise SceneError(f"moorings.lines[{i}].fairlead", f"{ln.fairlead!r} is also the fairlead of "
                             f"moorings.lines[{first[ln.fairlead]}]; give each line its own fairlead")
        first[ln.fairlead] = i


def _check_probes(s, dim):
    p = s.probes
    names = set(body_names(s))
    for i, n in enumerate(p.motion):
        if n != "all" and n not in names and not any(isinstance(b, MJCF) for b in s.bodies):
            raise SceneError(f"probes.motion[{i}]", f"no body named {n!r}; bodies: {sorted(names)} (or \"all\")")
    fluid_probes = p.gauges or p.pressure or p.energy
    if fluid_probes and not isinstance(s.fluid, SPH):
        which = "gauges" if p.gauges else "pressure" if p.pressure else "energy"
        raise SceneError(f"probes.{which}", "wave gauges, pressure patches and the fluid's energy need the SPH "
                         "fluid (fluid.model = \"sph\")")
    for i, g in enumerate(p.gauges):
        n = 1 if isinstance(g, float) else len(g)
        if n != dim - 1:
            raise SceneError(f"probes.gauges[{i}]", f"{g}: a {dim}-D scene gives a gauge as "
                             f"{'x [m]' if dim == 2 else '(x, y) [m]'}")
        if s.domain is not None:
            lo, hi = _domain_box(s.domain, dim)
            for k, x in enumerate((g,) if isinstance(g, float) else g):
                if not lo[k] <= x <= hi[k]:
                    where = "" if dim == 2 else f"{list(g)}: "
                    raise SceneError(f"probes.gauges[{i}]", f"{where}{'xy'[k]} = {x:g} m lies outside the domain's "
                                     f"{lo[k]:g} .. {hi[k]:g} m; put the gauge over the water")
    seen = set()
    for i, pr in enumerate(p.pressure):
        _dim_vec(pr.centre, dim, f"probes.pressure[{i}].centre")
        _dim_vec(pr.normal, dim, f"probes.pressure[{i}].normal", "direction")
        if pr.name in seen:
            raise SceneError(f"probes.pressure[{i}].name", f"{pr.name!r} is used twice; give each patch its own")
        seen.add(pr.name)
