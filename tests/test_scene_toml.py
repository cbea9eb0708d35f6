"""A scene as TOML (``cosim.scene.toml_io``): the round trip is exact, for scenes of every
shape hypothesis can build, and the reading side (files, ``--set``) does what it says.

The strategy :func:`scenes` builds only VALID scenes (it keeps to what ``cosim.scene.checks``
and ``cosim.scene.plausible`` accept: bodies inside the domain's box, clear of its walls and
of each other, no denser than osmium, dx fine enough for the depth, waves below the
breaking limit and a paddle stroke the flume holds, base motion within 5 g, names that
exist, fairleads on their body's hull and above their anchors with lines that reach them,
unstretched, and no heavier in water than in air, pressure patches on a wall, files that
read),
then the property is: written as TOML and read back, the scene is the same, field for
field, and written again, the text is the same. Scenes are only constructed, never run.
"""

from __future__ import annotations

import atexit
import hashlib
import math
import shutil
import tempfile
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cosim.errors import InputError
from cosim.scene import (MJCF, SPH, Analytic, Beach, Block, Box, Coupling, Cylinder, CylinderTank, Earthquake, Flap,
                         Flume, InclinedTank, Line, Moorings, NoFluid, PaddleRecord, Patch, Piston, PolygonTank,
                         Probes, Roll, RollTable, Scene, SceneError, Shake, Sphere, TableMotion, Tank,
                         World)
from cosim.scene.limits import (FAIRLEAD_REACH, MAX_BASE_ACCELERATION, MAX_DENSITY, MAX_LINE_EA, MAX_LINE_WEIGHT,
                                MIN_DENSITY, PADDLE_SHARE)
from cosim.scene.plausible import bounding_radius
from cosim.scene.placement import volume_and_height
from cosim.scene.toml_io import from_dict, parse_value, read_toml, to_dict, to_toml, toml_value, with_values
from fluid.wavemaker import RegularWavemaker, wavenumber

#: files for the fields that name one, valid as the checks read them (scenes here are never
#: run): a table of time and 9 columns of values, all at rest; a PEER .AT2 record
FILES = Path(tempfile.mkdtemp(prefix="scene-toml-"))
atexit.register(shutil.rmtree, FILES, True)
TABLE = FILES / "table.txt"
TABLE.write_text("".join(f"{0.25 * k!r}" + " 0.0" * 9 + "\n" for k in range(5)))
AT2 = FILES / "quake.AT2"
AT2.write_text("TEST\nSYNTHETIC\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  50, DT= .0100 SEC\n"
               + "\n".join(" ".join(f"{0.01 * math.sin(0.3 * (k + j)):.6e}" for j in range(5)) for k in range(0, 50, 5))
               + "\n")


def mjcf_file(names) -> str:
    """An MJCF file whose movable bodies are ``names`` (or one, "float"), each with a site
    "s" + its name."""
    names = list(names) or ["float"]
    xml = "<mujoco><worldbody>" + "".join(
        f'<body name="{n}" pos="{3 * k} 0 0"><freejoint/><geom type="sphere" size="0.5"/><site name="s{n}"/></body>'
        for k, n in enumerate(names)) + "</worldbody></mujoco>"
    path = FILES / f"m{hashlib.sha1(xml.encode()).hexdigest()[:16]}.xml"
    path.write_text(xml, encoding="utf-8")
    return str(path)

#: values whose decimal text is awkward: not the shortest-looking decimal, tiny, huge,
#: sub-normal, a power of two, 1/3
AWKWARD = (0.1 + 0.2, 1e-7, 123456.789e3, 1.0 / 3.0, 2.0 ** -30, 5e-324, 2.2250738585072014e-308,
           1.7976931348623157e308, 9007199254740993.0, 1e16, 1e22, 0.1, 100.0, 3.0, 1e-3 + 1e-19, 6.02214076e23,
           -0.0, -(0.1 + 0.2), -1e-7, -123456.789e3)

SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def num(lo=None, hi=None, *, open_lo=False, open_hi=False):
    """A finite float in [lo, hi] (open ends where asked), sometimes an awkward one."""
    def ok(v):
        return ((lo is None or v > lo or (v == lo and not open_lo))
                and (hi is None or v < hi or (v == hi and not open_hi)))
    plain = st.floats(min_value=lo, max_value=hi, exclude_min=open_lo and lo is not None,
                      exclude_max=open_hi and hi is not None, allow_nan=False, allow_infinity=False)
    awkward = [v for v in AWKWARD if ok(v)]
    return st.one_of(plain, st.sampled_from(awkward)) if awkward else plain


def pos_num(hi=None):
    return num(0.0, hi, open_lo=True)


def between(lo, hi):
    """A float well inside [lo, hi] (lo < hi), sometimes at an awkward fraction."""
    frac = st.one_of(st.floats(0.0, 1.0), st.sampled_from([0.1 + 0.2, 1.0 / 3.0, 1e-7, 0.5]))
    return frac.map(lambda f: min(hi, max(lo, lo + f * (hi - lo))))


def vec(n, lo=-1e3, hi=1e3):
    return st.tuples(*[num(lo, hi)] * n)


def nonzero_vec(n):
    return vec(n).filter(lambda v: any(x != 0 for x in v))


#: names of scenes, bodies, fairleads, patches: letters, digits, '_' and '-' (some not ASCII)
NAMES = st.text(alphabet="abcxyzABZ019_-éßΩ", min_size=1, max_size=8)
#: line labels: names joined by single dots
LABELS = st.lists(NAMES, min_size=1, max_size=3).map(".".join)


def maybe(strategy):
    return st.one_of(st.none(), strategy)


# ------------------------------------------------------------------------ the parts
@st.composite
def sph_fluids(draw, dx_max):
    """SPH with dx <= dx_max and a random choice of its optional overrides."""
    kw = {"dx": draw(num(min(1e-4, dx_max / 2), dx_max, open_lo=True))}
    options = {
        "setup": st.sampled_from(["auto", "still", "waves", "sloshing", "impulsive", "impact", "defaults"]),
        "rho0": num(MIN_DENSITY, MAX_DENSITY),
        "c0_factor": num(10.0, 1e3),
        "h_coef": num(1.0, 3.0),
        "kernel": st.sampled_from(["wendland", "cubic"]),
        "walls": st.sampled_from(["dbc", "adami"]),
        "alpha": num(0.0, 1.0),
        "alpha_wall": num(0.0, 1.0),
        "nu": num(0.0, 1.0),
        "xsph_eps": num(0.0, 1.0),
        "diffusion": st.sampled_from(["fourtakas", "antuono", "molteni", "none"]),
        "delta": num(0.0, 1.0),
        "diffusion_at_surface": st.booleans(),
        "cfl": num(0.0, 0.4, open_lo=True),
        "integrator": st.sampled_from(["symplectic", "verlet"]),
        "mls_every": st.integers(0, 1000),
        "threads": st.integers(1, 64),
        "settle": num(0.0, 10.0),
        "body_boundary": st.sampled_from(["mdbc", "dbc"]),
    }
    for key in draw(st.sets(st.sampled_from(sorted(options)))):
        kw[key] = draw(options[key])
    speed = draw(st.sampled_from([None, "c0", "u_max"]))  # one of the two, or neither
    if speed:
        # no slower than the long-wave speed sqrt(g h) of any scene drawn here (g <= 30, h <= 20: 24.5 m/s)
        kw[speed] = draw(num(25.0, 1e4) if speed == "c0" else num(2.5, 1e4))
    return SPH(**kw)


DOMAIN_KINDS = {2: ("tank", "tank-blocks", "inclined", "flume", "polygon"),
                3: ("tank", "tank-blocks", "inclined", "cylinder")}


@st.composite
def domains(draw, dim, kind=None):
    """(domain, its inner box lo, hi, the water depth or None); ``kind`` one of
    DOMAIN_KINDS[dim], or None: any."""
    kind = kind or draw(st.sampled_from(DOMAIN_KINDS[dim]))
    length, height = draw(num(0.5, 50.0)), draw(num(0.2, 20.0))
    width = draw(num(0.2, 50.0)) if dim == 3 and kind in ("tank", "tank-blocks", "inclined") else None
    depth = draw(between(0.05 * height, 0.95 * height))
    if kind == "tank":
        d = Tank(length=length, height=height, width=width, depth=depth)
    elif kind == "tank-blocks":
        inner = [length] + ([width] if dim == 3 else []) + [height]
        blocks, n = [], draw(st.integers(1, 3))
        for k in range(n):  # side by side along x (water blocks must not overlap)
            w = length / n
            lo = [draw(between(k * w, (k + 0.2) * w))] + [draw(between(0.0, 0.45 * e)) for e in inner[1:]]
            hi = [draw(between((k + 0.8) * w, (k + 1) * w))] + [draw(between(0.55 * e, e)) for e in inner[1:]]
            blocks.append(Block(lo=lo, hi=hi))
        d, depth = Tank(length=length, height=height, width=width, water=blocks), None
    elif kind == "inclined":
        d = InclinedTank(angle=draw(num(0.0, 80.0)), length=length, depth=depth, height=height, width=width)
    elif kind == "flume":
        beach = draw(maybe(st.builds(Beach, toe=between(0.1 * length, 0.9 * length), slope=pos_num(10.0))))
        d = Flume(length=length, depth=depth, height=height, beach=beach)
    elif kind == "cylinder":
        d = CylinderTank(diameter=draw(num(0.2, 50.0)), depth=depth, height=height)
    else:  # a polygon: a convex outline round (cx, cz), water above its lowest corner
        n = draw(st.integers(3, 8))
        cx, cz, r = draw(num(-10.0, 10.0)), draw(num(-10.0, 10.0)), draw(num(0.2, 10.0))
        verts = [(cx + r * math.cos(2 * math.pi * k / n + 0.3), cz + r * math.sin(2 * math.pi * k / n + 0.3))
                 for k in range(n)]
        zmin, zmax = min(v[1] for v in verts), max(v[1] for v in verts)
        d = PolygonTank(vertices=verts, fill_level=draw(between(zmin + 0.1 * (zmax - zmin), zmax)))
        depth = d.fill_level - zmin
        xs = [v[0] for v in verts]
        return d, [min(xs), zmin], [max(xs), zmax], depth
    if kind == "cylinder":
        lo, hi = [-0.5 * d.diameter] * 2 + [0.0], [0.5 * d.diameter] * 2 + [height]
    else:
        lo = [0.0] * dim
        hi = [length] + ([width] if dim == 3 else []) + [height]
        if kind == "inclined":
            hi[0] = length + height * math.tan(math.radians(d.angle))
    return d, lo, hi, depth


def clear_box(d, lo, hi):
    """(lo, hi) of a box in the domain clear of its walls: short of a flume's beach and an
    inclined side, the square in a cylinder tank's circle, in a polygon's inscribed circle."""
    lo, hi = list(lo), list(hi)
    if isinstance(d, Flume) and d.beach is not None:
        hi[0] = d.beach.toe
    elif isinstance(d, InclinedTank):
        hi[0] = d.length
    elif isinstance(d, CylinderTank):
        a = 0.99 * 0.5 * d.diameter / math.sqrt(2)
        lo[:2], hi[:2] = [-a, -a], [a, a]
    elif isinstance(d, PolygonTank):  # a regular polygon (domains): the square in its inscribed circle
        n = len(d.vertices)
        cx, cz = (sum(v[k] for v in d.vertices) / n for k in (0, 1))
        a = 0.99 * math.dist(d.vertices[0], (cx, cz)) * math.cos(math.pi / n) / math.sqrt(2)
        lo, hi = [cx - a, cz - a], [cx + a, cz + a]
    return lo, hi


@st.composite
def bodies(draw, dim, names, box, can_float):
    """Builder bodies named ``names``, side by side along x (they must not overlap); ``box``
    = (lo, hi) of the part of the domain they must lie in, or None (anywhere)."""
    out = []
    for j, name in enumerate(names):
        shape = draw(st.sampled_from(["box", "cylinder"] + (["sphere"] if dim == 3 else [])))
        if box is not None:  # the j-th slice along x of the box
            w = (box[1][0] - box[0][0]) / len(names)
            slot = ([box[0][0] + j * w] + list(box[0][1:]), [box[0][0] + (j + 1) * w] + list(box[1][1:]))
            ext = [h - lo for lo, h in zip(*slot)]
            small = min(ext)
        else:
            ext, small = [100.0] * dim, 100.0
        if shape == "box":
            size = [draw(num(0.01 * e, 0.4 * e)) for e in ext]
            half, geo = [0.5 * s for s in size], {"size": size}
        elif shape == "cylinder":
            r = draw(num(0.005 * small, 0.2 * small))
            geo = {"radius": r}
            if dim == 3:
                geo["length"] = draw(num(0.01 * ext[2], 0.4 * ext[2]))
            half = [r] * (dim - 1) + [r if dim == 2 else 0.5 * geo.get("length", 0.0)]
        else:
            r = draw(num(0.005 * small, 0.2 * small))
            geo, half = {"radius": r}, [r] * dim
        floating = can_float and draw(st.booleans())
        n = dim - 1 if floating else dim
        shaped = {"box": Box, "cylinder": Cylinder, "sphere": Sphere}[shape](name=name, pos=[0.0] * dim, mass=1.0,
                                                                              **geo)
        # the checks hold a turned body by its bounding box's corners (cosim.scene.shapes.corners),
        # which reach beyond a cylinder's smallest sphere: place it by the box's half diagonal
        radius = bounding_radius(shaped, dim)
        corner = math.sqrt(sum(h * h for h in shaped.half_size(dim)))
        turned = not floating and not (dim == 2 and shape == "cylinder") and draw(st.integers(0, 3)) == 0
        if turned and box is not None:  # a turned body fits its slot by its bounding box's corners
            turned = all(2 * corner < 0.99 * e for e in ext)
            half = [corner] * dim if turned else half
        if box is not None:
            margin = [1e-6 * e for e in ext]
            pos = [draw(between(slot[0][k] + half[k] + margin[k], slot[1][k] - half[k] - margin[k]))
                   for k in range(n)]
        else:
            pos = list(draw(vec(n)))
            pos[0] = draw(num(-50.0, 50.0)) + 300.0 * j
        kw = dict(name=name, pos=pos, **geo)
        if draw(st.booleans()):
            kw["density"] = draw(num(MIN_DENSITY, MAX_DENSITY))
        else:  # no denser than osmium on average, nor lighter than a tenth of air
            f = draw(between(2 * MIN_DENSITY / MAX_DENSITY, 1.0 - 1e-9))  # off the limit by more than round-off
            kw["mass"] = f * MAX_DENSITY * volume_and_height(shaped, dim)[0]
        if floating:
            kw["place"] = "floating"
        elif draw(st.booleans()) or turned:
            kw["place"] = "given"
            if turned:  # in 2-D about y only
                kw["euler"] = draw(vec(3, -360.0, 360.0)) if dim == 3 else (0.0, draw(num(-360.0, 360.0)), 0.0)
        if draw(st.booleans()):  # on or near the hull
            reach = FAIRLEAD_REACH * radius / math.sqrt(dim)
            kw["fairleads"] = draw(st.dictionaries(NAMES, vec(dim, -reach, reach), max_size=3))
        out.append({"box": Box, "cylinder": Cylinder, "sphere": Sphere}[shape](**kw))
    return out


@st.composite
def moorings(draw, dim, body_list, g):
    points = [f"{b.name}.{f}" for b in body_list for f in b.fairleads]
    if not points or not draw(st.booleans()):
        return None
    chosen = draw(st.lists(st.sampled_from(points), min_size=1, max_size=4, unique=True))
    model = draw(st.sampled_from(["catenary", "sph-cable", "moordyn", "fmu"]))
    dynamic = model in ("sph-cable", "moordyn")
    lines, labels = [], set(chosen)
    by_name = {b.name: b for b in body_list}
    for fl in chosen:
        anchor, length = list(draw(vec(dim))), draw(num(1e-3, 1e4))
        body = by_name[fl.split(".")[0]]
        reach = math.hypot(*body.fairleads[fl.split(".")[1]])
        if body.place != "floating":  # the fairlead above the anchor's seabed, the line long enough, turned or not
            anchor[-1] = min(anchor[-1], body.pos[-1] - reach)
            length = max(length, math.dist(anchor, body.pos) + reach)
        else:  # long enough at any draft: not stretched where the fairlead comes nearest
            height = volume_and_height(body, dim)[1]
            length = max(length, math.dist(anchor[:-1], body.pos) + abs(anchor[-1]) + 200.0 + height + reach)
        kw = dict(fairlead=fl, anchor=anchor, length=length, weight=draw(pos_num(1e4)))
        for key, lo, hi in (("EA", 0.0, MAX_LINE_EA), ("mass_per_length", 0.0, 1e4), ("diameter", 1e-3, 10.0)):
            if dynamic or draw(st.booleans()):
                kw[key] = draw(num(lo, hi, open_lo=lo == 0.0))
        if "mass_per_length" in kw and g > 0:  # no heavier in water than in air
            kw["mass_per_length"] = max(kw["mass_per_length"], 1e-6)  # its weight in air not below the floats
            kw["weight"] = draw(between(1e-3, 1.0)) * min(kw["mass_per_length"] * g, MAX_LINE_WEIGHT)
        if draw(st.booleans()):
            name = draw(LABELS)
            if name not in labels:  # a line's label (its name, or its fairlead) is its own
                kw["name"] = name
                labels.add(name)
        lines.append(Line(**kw))
    kw = {"model": model, "lines": lines}
    if draw(st.booleans()):
        kw["segments"] = draw(st.integers(2, 500))
    return Moorings(**kw)


@st.composite
def floor_patch(draw, name, domain, dim, dx):
    """A pressure patch on the domain's floor (a polygon's lowest edge), facing the water,
    at least a particle spacing across."""
    size = draw(num(dx, max(dx, 10.0)))
    if isinstance(domain, PolygonTank):
        v = domain.vertices
        n = len(v)
        k = min(range(n), key=lambda i: v[i][1] + v[(i + 1) % n][1])
        (x0, z0), (x1, z1) = v[k], v[(k + 1) % n]
        f = draw(between(0.3, 0.7))
        cx, cz = (sum(p[i] for p in v) / n for i in (0, 1))
        normal = (z0 - z1, x1 - x0)
        if normal[0] * (cx - x0) + normal[1] * (cz - z0) < 0:
            normal = (-normal[0], -normal[1])
        return Patch(name=name, centre=(x0 + f * (x1 - x0), z0 + f * (z1 - z0)), normal=normal, size=size)
    if isinstance(domain, CylinderTank):
        a = 0.5 * domain.diameter / math.sqrt(2)
        return Patch(name=name, centre=(draw(between(-a, a)), draw(between(-a, a)), 0.0), normal=(0.0, 0.0, 1.0),
                     size=size)
    end = domain.beach.toe if isinstance(domain, Flume) and domain.beach is not None else domain.length
    x = draw(between(0.0, 0.9 * end))
    if dim == 2:
        return Patch(name=name, centre=(x, 0.0), normal=(0.0, 1.0), size=size)
    return Patch(name=name, centre=(x, draw(between(0.0, domain.width)), 0.0), normal=(0.0, 0.0, 1.0), size=size)


@st.composite
def probes(draw, dim, sph, names, box, domain=None, dx=None):
    kw = {}
    if sph:  # gauges over the domain's box, half a spacing off its walls
        lo, hi = [x + 0.51 * dx for x in box[0]], [x - 0.51 * dx for x in box[1]]
        gauge = (between(lo[0], hi[0]) if dim == 2 else st.tuples(between(lo[0], hi[0]), between(lo[1], hi[1])))
        room = all(a < b for a, b in zip(lo[:dim - 1], hi[:dim - 1]))  # a domain narrower than a spacing: none
        kw["gauges"] = draw(st.lists(gauge, max_size=4 if room else 0))
        patch_names = draw(st.lists(NAMES, max_size=3, unique=True))
        kw["pressure"] = [draw(floor_patch(n, domain, dim, dx)) for n in patch_names]
        kw["energy"] = draw(st.booleans())
    if names and draw(st.booleans()):
        kw["motion"] = draw(st.lists(st.sampled_from(list(names) + ["all"]), max_size=3))
    kw["tensions"], kw["loads"] = draw(st.booleans()), draw(st.booleans())
    return Probes(**kw)


@st.composite
def couplings(draw, sph, dt=None):
    scheme = draw(st.sampled_from(["auto", "explicit", "predictor-corrector"] + (["fluid-first"] if sph else [])))
    light = draw(st.sampled_from(["auto", "none", "added-mass"]
                                 + (["subiterate"] if scheme in ("auto", "fluid-first") else [])))
    return Coupling(scheme=scheme, light_body=light, dt=dt, body_timestep=draw(pos_num(1.0)))


@st.composite
def worlds(draw, dim, need_gravity):
    duration = draw(num(1e-3, 1e4))
    plot_at = draw(st.lists(between(0.0, duration), max_size=3))
    gravity = num(1.0, 30.0) if need_gravity else st.one_of(st.just(0.0), num(0.1, 30.0))  # none, or a world's
    return World(dim=dim, duration=duration, gravity=draw(gravity),
                 sample_every=draw(between(1e-6 * duration, duration)),
                 snapshot_every=draw(num(0.0, 1e3)), checkpoint_every=draw(num(0.0, 1e3)), plot_at=plot_at,
                 plot_color=draw(st.sampled_from(["velocity", "pressure"])))


@st.composite
def waves_for(draw, flume, gravity, kind):
    if kind == "record":
        return PaddleRecord(paddle=draw(st.sampled_from(["piston", "flap"])), file=str(TABLE),
                            column=draw(st.integers(1, 9)), scale=draw(num(-10.0, 10.0)),
                            t_shift=draw(num(-10.0, 10.0)))
    period = draw(num(0.3, 10.0))
    wavelength = 2 * math.pi / wavenumber(period, flume.depth, gravity)
    height = draw(between(1e-3, 0.9)) * wavelength / 7
    wm = RegularWavemaker(kind, height, period, flume.depth, 1.0, gravity)
    stroke = wm.stroke if kind == "piston" else wm.stroke * flume.height / wm.depth
    height *= min(1.0, 0.99 * PADDLE_SHARE * flume.length / (0.5 * stroke))  # the stroke is linear in the height
    return (Piston if kind == "piston" else Flap)(height=height, period=period, ramp=draw(num(0.0, 10.0)))


@st.composite
def base_motions(draw, dim, box):
    """A tank's base motion, peaking within 5 g (``box``: the tank's inner box, for a roll's arm)."""
    kind = draw(st.sampled_from(["shake", "roll", "roll_table", "table", "earthquake"]))
    top = 0.99 * MAX_BASE_ACCELERATION
    if kind == "shake":
        period = draw(pos_num(100.0))
        kw = dict(period=period, direction=draw(nonzero_vec(dim)), ramp=draw(num(0.0, 10.0)))
        if kw["ramp"] > 0:  # a stop fades the shaking out over the ramp
            kw["stop"] = draw(maybe(pos_num(100.0)))
        if draw(st.booleans()):
            w = 2 * math.pi / period
            kw["amplitude"] = draw(num(-10.0, 10.0)) * min(1.0, top / 10.0 / (w * w))
        else:
            kw["acceleration"] = draw(num(-top, top))
            if kw["ramp"] < 1e6 * period and draw(st.booleans()):  # or is cut after whole periods, at rest, and held
                kw.update(hold=True, stop=period * (math.ceil(kw["ramp"] / period) + draw(st.integers(1, 50))))
        return Shake(**kw)
    if kind == "roll":
        amplitude, point = draw(num(-45.0, 45.0)), draw(vec(dim))
        arm = max(math.dist([box[m >> k & 1][k] for k in range(dim)], point) for m in range(2 ** dim))
        fastest = 2 * math.pi * math.sqrt(math.radians(abs(amplitude)) * arm / top)
        return Roll(amplitude=amplitude, period=max(draw(pos_num(100.0)), fastest), point=point,
                    axis=draw(nonzero_vec(3)) if dim == 3 else None, ramp=draw(num(0.0, 10.0)))
    if kind == "roll_table":
        return RollTable(file=str(TABLE), point=draw(vec(dim)), axis=draw(nonzero_vec(3)) if dim == 3 else None,
                         column=draw(st.integers(1, 5)), scale=draw(num(-5.0, 5.0)))
    if kind == "table":
        return TableMotion(file=str(TABLE),
                           quantity=draw(st.sampled_from(["displacement", "velocity", "acceleration"])),
                           direction=draw(nonzero_vec(dim)), column=draw(st.integers(1, 5)), scale=draw(num(-5.0, 5.0)))
    return Earthquake(file=str(AT2), direction=draw(nonzero_vec(dim)), scale=draw(num(-5.0, 5.0)),
                      baseline_degree=draw(st.integers(3, 9)))


# ------------------------------------------------------------------------ the scene
@st.composite
def scenes(draw, dim=None, fluid_kind=None, domain_kind=None):
    """A valid scene: 2-D or 3-D; no fluid, the analytic fluid or SPH in each domain that
    fits the dimension; waves with a flume, base motion with a tank; bodies at given poses
    inside the domain or floating; moorings on their fairleads; probes, coupling, world.
    ``dim``, ``fluid_kind`` ("none", "analytic", "sph"), ``domain_kind`` (DOMAIN_KINDS) fix
    the shape; None: drawn."""
    dim = dim or draw(st.sampled_from([2, 3]))
    fluid_kind = fluid_kind or draw(st.sampled_from(["none", "analytic", "sph"]))
    kw = {}
    box = None
    waves = base = None
    if fluid_kind == "sph":
        domain, lo, hi, depth = draw(domains(dim, domain_kind))
        box, clear = (lo, hi), clear_box(domain, lo, hi)
        kw["domain"] = domain
        dx_max = depth / 4 if depth is not None else 0.1 * min(h - lo_ for lo_, h in zip(lo, hi))
        kw["fluid"] = draw(sph_fluids(dx_max))
        if isinstance(domain, Flume):
            waves = draw(st.sampled_from([None, "piston", "flap", "record"]))
        elif draw(st.booleans()):
            base = draw(base_motions(dim, box))
    world = draw(worlds(dim, need_gravity=bool(waves)))
    if waves:
        kw["waves"] = w = draw(waves_for(kw["domain"], world.gravity, waves))
        if waves in ("piston", "flap"):  # the bodies beyond the paddle's sweep
            d = kw["domain"]
            wm = RegularWavemaker(waves, w.height, w.period, d.depth, 1.0, world.gravity)
            half = 0.5 * (wm.stroke if waves == "piston" else wm.stroke * d.height / wm.depth)
            clear = ([max(clear[0][0], 1.01 * half)] + list(clear[0][1:]), clear[1])
    if base is not None:
        kw["base_motion"] = base

    mjcf = fluid_kind != "sph" and draw(st.integers(0, 9)) == 0
    if mjcf:  # an MJCF file is the only entry of bodies
        names = draw(st.lists(NAMES, max_size=3, unique=True))
        body_list = [MJCF(file=mjcf_file(names), bodies=names)]
    else:
        n = draw(st.integers(0 if fluid_kind == "sph" else 1, 3))
        if box and clear[1][0] <= clear[0][0]:  # a paddle sweeping up to the beach: no room for a body
            n = 0
        names = draw(st.lists(NAMES, min_size=n, max_size=n, unique=True))
        can_float = fluid_kind != "none" and world.gravity > 0  # no buoyancy without gravity
        body_list = draw(bodies(dim, names, clear if box else None, can_float=can_float))
    kw["bodies"] = body_list
    if fluid_kind == "analytic":
        rows = st.dictionaries(st.sampled_from(names), vec(6, 0.0, 1e6), max_size=len(names)) if names else st.just({})
        kw["fluid"] = Analytic(rho=draw(num(MIN_DENSITY, MAX_DENSITY)), level=draw(num(-100.0, 100.0)),
                               linear_damping=draw(rows), quadratic_damping=draw(rows))
    elif fluid_kind == "none" and draw(st.booleans()):
        kw["fluid"] = NoFluid()
    if base is not None:
        pass  # a moving tank takes no mooring lines (their anchors would not move with it)
    elif not mjcf:
        kw["moorings"] = draw(moorings(dim, body_list, world.gravity))
    elif names:
        lines = []
        for k, n in enumerate(names):  # long enough to reach the site, at (3 k, 0, 0)
            anchor = draw(vec(dim))
            site = (3.0 * k, 0.0, 0.0)[:dim] if dim == 3 else (3.0 * k, 0.0)
            lines.append(Line(fairlead=f"{n}.s{n}", anchor=anchor, weight=1.0,
                              length=max(draw(num(1e-3, 1e3)), math.dist(anchor, site) * (1 + 1e-9))))
        kw["moorings"] = Moorings(lines=lines)
    kw["probes"] = draw(probes(dim, fluid_kind == "sph", names, box, kw.get("domain"),
                               kw["fluid"].dx if fluid_kind == "sph" else None))
    dt = None
    if draw(st.booleans()):  # a fixed step lands on the output intervals (cosim.scene.timing)
        dt = world.sample_every / draw(st.integers(1, 1000))
        world = world.replace(**{k: world.sample_every * draw(st.integers(0, 1000))
                                 for k in ("snapshot_every", "checkpoint_every")})
    kw["coupling"] = draw(couplings(fluid_kind == "sph", dt))
    if draw(st.booleans()):
        kw["name"] = draw(NAMES)
    return Scene(world=world, **kw)


# ------------------------------------------------------------------------ properties
#: every shape of scene, each drawn as often (hypothesis alone favours the first choices)
SHAPES = ([(dim, fluid, None) for dim in (2, 3) for fluid in ("none", "analytic")]
          + [(dim, "sph", kind) for dim in (2, 3) for kind in DOMAIN_KINDS[dim]])


def check_round_trip(scene):
    text = to_toml(scene)
    data = tomllib.loads(text)
    back = from_dict(data)
    assert back == scene
    assert to_toml(back) == text
    assert data == to_dict(scene)
    assert text.isascii()


@pytest.mark.parametrize("dim, fluid, domain", SHAPES, ids=[f"{d}d-{f}{'-' + k if k else ''}" for d, f, k in SHAPES])
@settings(SETTINGS, max_examples=15)
@given(data=st.data())
def test_toml_round_trip_is_exact(dim, fluid, domain, data):
    """Written as TOML and read back: the same scene, and the same text written again
    (15 scenes of each of the 13 shapes)."""
    check_round_trip(data.draw(scenes(dim, fluid, domain), label="scene"))


@settings(SETTINGS, max_examples=60)
@given(scenes())
def test_toml_round_trip_of_any_scene(scene):
    check_round_trip(scene)


@settings(SETTINGS, max_examples=60)
@given(scenes())
def test_no_assignments_change_nothing(scene):
    assert with_values(scene, []) == scene
    assert from_dict(to_dict(scene)) == scene


# ------------------------------------------------------------------------ examples
MOORED = """
name = "moored"

[world]
dim = 2
duration = 4.0

[fluid]
model = "analytic"
rho = 1025

[[bodies]]
shape = "box"
name = "box"
size = [2, 1]
pos = [3.0]
place = "floating"
density = 500
fairleads = { left = [-1.0, -0.5], right = [1.0, -0.5] }

[moorings]
lines = [
  { fairlead = "box.left", anchor = [-20.0, -10.0], length = 25.0, weight = 50.0 },
  { fairlead = "box.right", anchor = [20.0, -10.0], length = 25.0, weight = 50.0 },
]
"""


def test_read_toml_of_a_file(tmp_path):
    path = tmp_path / "moored.toml"
    path.write_text(MOORED)
    scene = read_toml(path)
    assert scene == Scene.from_toml(path)
    assert scene.name == "moored"
    assert scene.world == World(dim=2, duration=4.0)
    assert scene.fluid == Analytic(rho=1025.0)
    assert scene.bodies == (Box("box", size=(2.0, 1.0), pos=(3.0,), place="floating", density=500.0,
                                fairleads={"left": (-1.0, -0.5), "right": (1.0, -0.5)}),)
    assert [ln.fairlead for ln in scene.moorings.lines] == ["box.left", "box.right"]
    assert scene.moorings.model == "catenary"
    # ints given for floats are floats from here on
    assert isinstance(scene.fluid.rho, float) and isinstance(scene.bodies[0].size[0], float)
    # written and read again: the same
    again = tmp_path / "again.toml"
    scene.to_toml(again)
    assert read_toml(again) == scene


def test_read_toml_refuses_a_missing_file_and_bad_toml(tmp_path):
    with pytest.raises(SceneError, match="no scene file"):
        read_toml(tmp_path / "nothing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("[world\ndim = 2\n")
    with pytest.raises(SceneError, match="is not valid TOML"):
        read_toml(bad)


def test_relative_file_fields_are_read_from_the_scene_files_folder(tmp_path):
    (tmp_path / "data").mkdir()
    (tmp_path / "data" / "shake.csv").write_text("0 0\n1 0.01\n2 0\n3 -0.01\n")
    (tmp_path / "scenes").mkdir()
    path = tmp_path / "scenes" / "tank.toml"
    path.write_text("""
[fluid]
model = "sph"
dx = 0.01

[domain]
kind = "tank"
length = 1.0
height = 0.5
depth = 0.2

[base_motion]
kind = "table"
file = "../data/shake.csv"
""")
    scene = read_toml(path)
    assert Path(scene.base_motion.file) == tmp_path / "scenes" / ".." / "data" / "shake.csv"
    assert Path(scene.base_motion.file).is_file()
    # an absolute name stays as it is
    path.write_text(path.read_text().replace("../data/shake.csv", str(tmp_path / "data" / "shake.csv")))
    assert read_toml(path).base_motion.file == str(tmp_path / "data" / "shake.csv")
    # from a dict without a folder, the name is taken as it is (from the working directory)
    with pytest.raises(SceneError) as err:
        from_dict(tomllib.loads(path.read_text().replace(str(tmp_path / "data"), "../data")))
    assert err.value.path == "base_motion.file" and "no file '../data/shake.csv'" in str(err.value)


def test_set_values_are_parsed_as_toml():
    assert parse_value("0.01") == 0.01 and isinstance(parse_value("0.01"), float)
    assert parse_value("600") == 600 and isinstance(parse_value("600"), int)
    assert parse_value("moordyn") == "moordyn"  # a bare word is a string
    assert parse_value('"sph-cable"') == "sph-cable"
    assert parse_value("sph-cable") == "sph-cable"
    assert parse_value("[0.5, 1.0]") == [0.5, 1.0]
    assert parse_value("true") is True
    assert math.isnan(parse_value("nan")) and parse_value("-inf") == -math.inf


def test_set_assignments():
    scene = from_dict(tomllib.loads(MOORED))
    scene = from_dict(to_dict(scene) | {"fluid": {"model": "sph", "dx": 0.05},
                                        "domain": {"kind": "flume", "length": 8.0, "depth": 1.0, "height": 2.0}}
                      | {"bodies": [to_dict(scene.bodies[0]) | {"size": [1.0, 0.5], "fairleads": {
                          "left": [-0.5, -0.25], "right": [0.5, -0.25]}}]})
    new = with_values(scene, ["fluid.dx=0.01", "moorings.model=moordyn", "probes.gauges=[0.5, 1.0]",
                              "bodies[0].density=600", "moorings.lines[0].EA=1e6", "moorings.lines[1].EA = 2e6",
                              "moorings.lines[0].mass_per_length=6", "moorings.lines[1].mass_per_length=6",
                              "moorings.lines[0].diameter=0.01", "moorings.lines[1].diameter=0.01",
                              "world.plot_at=[1, 2.5]", "name=my_scene"])
    assert new.fluid.dx == 0.01 and isinstance(new.fluid.dx, float)
    assert new.moorings.model == "moordyn"
    assert new.probes.gauges == (0.5, 1.0)
    assert new.bodies[0].density == 600.0 and isinstance(new.bodies[0].density, float)
    assert new.moorings.lines[1].EA == 2e6
    assert new.world.plot_at == (1.0, 2.5) and isinstance(new.world.plot_at[0], float)
    assert new.name == "my_scene"
    # everything else as it was
    assert new.replace(fluid=scene.fluid, moorings=scene.moorings, probes=scene.probes, bodies=scene.bodies,
                       world=scene.world, name=scene.name) == scene
    # a new table is made where there was none; the scene method is the same function
    assert scene.with_values(["coupling.dt=0.001"]).coupling.dt == 0.001
    # an assignment that makes the scene invalid is refused, by key path
    with pytest.raises(InputError) as err:
        with_values(scene, ["fluid.dx=-0.01"])
    assert err.value.path == "fluid.dx"


def test_toml_text_is_valid_and_keeps_ints_and_floats():
    scene = Scene(world=World(dim=3, duration=2, plot_at=[1]), fluid=SPH(dx=0.1, mls_every=20, threads=2),
                  domain=Tank(length=2, width=1, height=1, depth=0.5),
                  bodies=[Sphere("s", radius=0.1, pos=(1, 0.5, 0.7), density=500)],
                  moorings=None, probes=Probes(gauges=[(1, 0.5)]), name="tank-Ω")
    text = to_toml(scene)
    data = tomllib.loads(text)
    assert data["world"]["dim"] == 3 and type(data["world"]["dim"]) is int
    assert type(data["fluid"]["mls_every"]) is int and type(data["fluid"]["threads"]) is int
    assert type(data["world"]["duration"]) is float and data["world"]["duration"] == 2.0
    assert type(data["domain"]["length"]) is float
    assert all(type(x) is float for x in data["bodies"][0]["pos"])
    assert data["probes"]["gauges"] == [[1.0, 0.5]]
    assert data["name"] == scene.name
    assert "dim = 3\n" in text and "duration = 2.0\n" in text
    assert text.isascii() and from_dict(data) == scene
    # a text: ASCII; TOML forbids raw control characters (DEL included) in strings, and
    # escapes of surrogates (a character beyond U+FFFF is one \U escape)
    awkward = 'a "quoted" \\ text\t\n\x7f😀'
    line = f"x = {toml_value(awkward)}"
    assert line.isascii() and "\x7f" not in line and "\\ud83d" not in line.lower() and "\\U0001f600" in line
    assert tomllib.loads(line)["x"] == awkward


def test_awkward_floats_keep_every_bit():
    values = [v for v in AWKWARD if v > 0]
    scene = Scene(world=World(plot_at=[v for v in values if v <= 1.0]),
                  bodies=[Box("b", size=(v, v), pos=(v, -v), mass=v) for v in values[:1]],
                  coupling=Coupling(dt=values[1]))
    back = from_dict(tomllib.loads(to_toml(scene)))
    assert back == scene
    assert [x.hex() for x in back.world.plot_at] == [x.hex() for x in scene.world.plot_at]
    assert "0.30000000000000004" in to_toml(scene) and "5e-324" in to_toml(scene)
