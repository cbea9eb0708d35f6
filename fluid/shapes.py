"""Geometry builders beyond boxes: 2-D polygons filled with fluid or used as walls, the
tank with one inclined side (Sunara et al. 2021, §3.2) and the cylindrical tank
(Sunara et al. 2021, §3.3), the cavity of a hollow catenary arch rib
(Wang et al. 2022, §4), on the lattice convention of :mod:`fluid.geometry`
(particles at ``(i + 1/2) dx`` from the origin).

Walls along a slanted or curved surface are not taken from the lattice (a staircase, which
Sunara et al. 2021, §3.2 names as the cause of its "uneven particle distribution on the sloping walls"):
each wall layer ``k = 0..layers-1`` is the boundary offset by ``(k + 1/2) dx`` away from the
fluid and sampled at a spacing as close to ``dx`` as a whole number of intervals allows.
Fluid comes from the lattice; fluid that overlaps a wall is removed and counted by
:func:`fluid.geometry.assemble`.

2-D shapes live in the x-z plane; polygons are (M, 2) vertex arrays [m] in either
orientation.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.spatial import cKDTree

from errors import InputError
from fluid.geometry import Built, _axes, assemble, block
from fluid.particles import Kind


def _vertices(vertices, closed: bool) -> np.ndarray:
    v = np.asarray(vertices, np.float64)
    need = 3 if closed else 2
    if v.ndim != 2 or v.shape[1] != 2 or len(v) < need or not np.isfinite(v).all():
        raise InputError(f"a {'polygon' if closed else 'polyline'} needs at least {need} finite (x, z) "
                         f"vertices as an (M, 2) array [m], got shape {np.shape(vertices)}")
    seg = np.diff(np.vstack([v, v[:1]]) if closed else v, axis=0)
    if (np.hypot(seg[:, 0], seg[:, 1]) == 0).any():
        raise InputError("repeated consecutive vertex: every edge needs a positive length")
    return v


def signed_area(vertices) -> float:
    """Area [m^2] of a closed polygon, positive when counter-clockwise in (x, z)."""
    v = _vertices(vertices, True)
    x, z = v[:, 0], v[:, 1]
    return 0.5 * float(np.sum(x * np.roll(z, -1) - np.roll(x, -1) * z))


def inside_polygon(points, vertices) -> np.ndarray:
    """(N,) bool: which (x, z) points [m] lie inside the closed polygon (even-odd rule).
    Points go through in chunks, so that memory stays ~``2e6`` x 8 bytes per temporary
    whatever N x M (a 140 m arch rib at dx = 35 mm: 3e6 lattice points, 400 vertices)."""
    v = _vertices(vertices, True)
    p = np.asarray(points, np.float64)
    x0, z0 = v[:, 0], v[:, 1]
    x1, z1 = np.roll(x0, -1), np.roll(z0, -1)
    out = np.empty(len(p), bool)
    step = max(1, 2_000_000 // len(v))
    for i in range(0, len(p), step):
        x, z = p[i:i + step, 0, None], p[i:i + step, 1, None]
        crosses = (z0 > z) != (z1 > z)
        with np.errstate(divide="ignore", invalid="ignore"):
            xc = x0 + (z - z0) * (x1 - x0) / (z1 - z0)
        out[i:i + step] = (np.count_nonzero(crosses & (x < xc), axis=1) % 2) == 1
    return out


def _lattice_inside(lo, hi, dx: float, v: np.ndarray) -> np.ndarray:
    """:func:`inside_polygon` of the points of ``block(lo, hi, dx)``, in its order, row by
    row (the edges' crossings of each lattice row z, sorted once): the same test and the
    same numbers, without the points x vertices work (a 140 m arch rib at dx = 25 mm:
    5.6e6 points, 400 vertices)."""
    xs, zs = _axes(lo, hi, dx)
    x0, z0 = v[:, 0], v[:, 1]
    x1, z1 = np.roll(x0, -1), np.roll(z0, -1)
    mask = np.empty((xs.size, zs.size), bool)
    for j, z in enumerate(zs):
        crosses = (z0 > z) != (z1 > z)
        with np.errstate(divide="ignore", invalid="ignore"):
            xc = np.sort((x0 + (z - z0) * (x1 - x0) / (z1 - z0))[crosses])
        mask[:, j] = (xc.size - np.searchsorted(xc, xs, side="right")) % 2 == 1  # crossings right of x
    return mask.ravel()


def polygon_fluid(vertices, dx: float, conform_layers: int = 0) -> np.ndarray:
    """Fluid points (spacing ``dx`` [m]) inside the closed polygon: (N, 2) [m]. Each
    stands for ``dx^2`` of fluid; the count times ``dx^2`` approaches the area with an
    error of order perimeter x dx.

    ``conform_layers`` = 0: lattice points only. n > 0: the n layers next to the outline
    follow it (the outline offset inwards by ``(k + 1/2) dx``, sampled at ~dx, like the
    wall layers) and lattice points fill the rest from ``n dx`` inwards; next to a
    slanted wall the fluid then lies dx from the first wall layer instead of 1.0-1.3 dx.
    The cut at ``n dx`` leaves lattice cells straddling the last conforming layer by up
    to dx/2 either way (no net gap on average)."""
    v = _vertices(vertices, True)
    if not dx > 0:
        raise InputError(f"particle spacing dx must be positive, got {dx} m")
    if int(conform_layers) != conform_layers or conform_layers < 0:
        raise InputError(f"conform_layers must be a whole number >= 0, got {conform_layers}")
    lo = np.floor(v.min(0) / dx) * dx
    hi = np.ceil(v.max(0) / dx) * dx
    pts = block(lo, hi, dx)
    pts = pts[_lattice_inside(lo, hi, dx, v)]
    n = int(conform_layers)
    if n == 0:
        return pts
    inward = signed_area(v) > 0  # the left normal of a ccw polygon points inside
    pts = pts[distance_to_polyline(pts, v, True) >= n * dx]
    layers = [_sample_polyline(_offset_polyline(v, (k + 0.5) * dx, True, inward), dx, True) for k in range(n)]
    return np.vstack([pts] + layers)


def distance_to_polyline(points, vertices, closed: bool = True) -> np.ndarray:
    """Distance [m] of (N, 2) points [m] to the polyline (or closed polygon) ``vertices``."""
    p = np.asarray(points, np.float64)
    v = np.asarray(vertices, np.float64)
    ends = np.vstack([v, v[:1]]) if closed else v
    d = np.full(len(p), np.inf)
    for a, b in zip(ends[:-1], ends[1:]):
        t = np.clip(((p - a) @ (b - a)) / ((b - a) @ (b - a)), 0.0, 1.0)
        d = np.minimum(d, np.linalg.norm(p - (a + t[:, None] * (b - a)), axis=1))
    return d


def _offset_polyline(v: np.ndarray, d: float, closed: bool, left: bool) -> np.ndarray:
    """The polyline ``v`` moved by ``d`` [m] along its left (or right) normal, with mitred
    corners (each vertex where the neighbouring offset edges meet)."""
    seg = np.diff(np.vstack([v, v[:1]]) if closed else v, axis=0)
    t = seg / np.hypot(seg[:, 0], seg[:, 1])[:, None]
    nrm = np.stack([-t[:, 1], t[:, 0]], axis=1) * (1.0 if left else -1.0)
    m = len(v)
    out = np.empty_like(v)
    for i in range(m):
        e_in = (i - 1) % len(seg) if (closed or i > 0) else None
        e_out = i if (closed or i < m - 1) else None
        if e_in is None or e_out is None:  # an open end: move along its only edge's normal
            out[i] = v[i] + d * nrm[e_out if e_in is None else e_in]
            continue
        n1, n2 = nrm[e_in], nrm[e_out]
        c = 1.0 + float(n1 @ n2)  # miter: v + d (n1 + n2) / (1 + n1.n2)
        if c < 1e-6:
            raise InputError(f"the edges at vertex {v[i]} fold back on themselves; no wall can follow them")
        out[i] = v[i] + d * (n1 + n2) / c
    return out


def _sample_polyline(v: np.ndarray, dx: float, closed: bool) -> np.ndarray:
    """Points along every edge at the spacing nearest ``dx`` [m] that divides the edge,
    starting at its first vertex (so every corner holds exactly one point; an open
    polyline's last vertex is added)."""
    ends = np.vstack([v, v[:1]]) if closed else v
    out = []
    for a, b in zip(ends[:-1], ends[1:]):
        n = max(1, round(math.hypot(*(b - a)) / dx))
        s = np.arange(n) / n
        out.append(a + s[:, None] * (b - a))
    if not closed:
        out.append(v[-1:])
    return np.concatenate(out)


def polyline_wall(vertices, dx: float, layers: int = 3, closed: bool = True,
                  outside: bool = True) -> np.ndarray:
    """Wall particles along a polyline (open, e.g. a tank's bottom and sides) or closed
    polygon: ``layers`` [-] layers at ``(k + 1/2) dx`` from it, each sampled at ~``dx``
    [m]. For a closed polygon ``outside`` puts the wall outside (a tank around the polygon's
    fluid) or inside (a solid obstacle: fluid around it). An open polyline is walked from
    its first vertex: the fluid is on its left (counter-clockwise, like a tank's bottom
    walked left to right), the wall on its right."""
    if int(layers) != layers or layers < 1:
        raise InputError(f"a wall needs at least one layer, got layers={layers}")
    if not dx > 0:
        raise InputError(f"particle spacing dx must be positive, got {dx} m")
    v = _vertices(vertices, closed)
    if closed:
        ccw = signed_area(v) > 0
        left = ccw != outside  # the left normal of a ccw polygon points inside
    else:
        left = False
    return np.concatenate([_sample_polyline(_offset_polyline(v, (k + 0.5) * dx, closed, left), dx, closed)
                           for k in range(int(layers))])


def polygon_tank(vertices, dx: float, fill_level: float | None = None, layers: int = 3,
                 rho0: float = 1000.0, conform_layers: int = 1) -> Built:
    """A 2-D container whose inner (wetted) outline is the closed polygon ``vertices``
    [m], walled all round, filled with fluid up to ``fill_level`` [m] (None: full), the
    fluid's first ``conform_layers`` layers along the walls (see :func:`polygon_fluid`;
    0 for a pure lattice). Walls are group 0, FIXED_WALL."""
    v = _vertices(vertices, True)
    fl = polygon_fluid(v, dx, conform_layers)
    if fill_level is not None:
        fl = fl[fl[:, 1] < fill_level]
    return assemble(2, dx, rho0, fl, [(polyline_wall(v, dx, layers, True, True), Kind.FIXED_WALL, 0)])


def catenary_arch_axis(span: float, rise: float, m: float, n: int = 201) -> np.ndarray:
    """The axis of a catenary arch, (n, 2) points (x, z) [m] from the left springing
    (x = -span/2, z = 0) over the crown (x = 0, z = ``rise``) to the right springing:
    ``z = rise - rise / (m - 1) (cosh(k xi) - 1)``, ``xi = 2 x / span``, ``k = arccosh(m)``,
    the arch-axis curve of (Chinese) masonry and concrete arch bridges, for which the arch
    rib of Wang et al. 2022, §4 is designed ("the arch rib has a catenary curve
    shape"; span 140 m, rise 23.333 m). ``m`` [-] >= 1 is the arch-axis coefficient, the
    ratio of the dead load per length at the springings to that at the crown (usually
    1.3-3.5; m = 1 is the parabola ``z = rise (1 - xi^2)``); the paper does not give it. The
    points are equally spaced in x."""
    if not (span > 0 and rise > 0 and math.isfinite(span) and math.isfinite(rise)):
        raise InputError(f"catenary_arch_axis: span={span!r} m and rise={rise!r} m must be positive")
    if not (math.isfinite(m) and m >= 1):
        raise InputError(f"catenary_arch_axis: m={m!r}; the arch-axis coefficient is >= 1 (1: a parabola)")
    if int(n) != n or n < 3:
        raise InputError(f"catenary_arch_axis: n={n!r}; give a whole number of points >= 3")
    xi = np.linspace(-1.0, 1.0, int(n))
    if m == 1.0:
        z = rise * (1.0 - xi**2)
    else:
        z = rise - rise / (m - 1.0) * (np.cosh(math.acosh(m) * xi) - 1.0)
    return np.column_stack([0.5 * span * xi, z])


def arch_rib_cavity(span: float, rise: float, inner_height: float, m: float, n: int = 201) -> np.ndarray:
    """The inner (wetted) outline of a hollow arch rib in 2-D, a closed polygon (2n, 2)
    [m]: the catenary axis (:func:`catenary_arch_axis`) offset by ``inner_height``/2 [m]
    along its normal on both sides (the inner faces of the rib's box section), closed by
    the section lines at the springings. Counter-clockwise: the lower face from left to
    right, then the upper face back. For :func:`polygon_tank` (the water to a level in
    both legs) or a scene's ``PolygonTank``. The paper (Wang et al. 2022, §4, Figure 8) draws the box
    section but its dimensions are not in the text: from its particle counts (36,910 fluid
    particles of 0.05 m filled to 15.56 m, 92.3 m^2) the inner height is about 1.4-1.5 m
    depending on ``m`` (tests/test_arch_rib.py)."""
    if not (inner_height > 0 and math.isfinite(inner_height)):
        raise InputError(f"arch_rib_cavity: inner_height={inner_height!r} m must be positive")
    a = catenary_arch_axis(span, rise, m, n)
    x = a[:, 0]
    # the axis' slope and curvature, exactly
    xi = 2 * x / span
    k = math.acosh(m) if m > 1 else 0.0
    if m == 1.0:
        dz, ddz = -2 * rise * xi * 2 / span, np.full_like(x, -4 * rise / span**2)
    else:
        dz = -rise / (m - 1) * k * np.sinh(k * xi) * 2 / span
        ddz = -rise / (m - 1) * k * k * np.cosh(k * xi) * 4 / span**2
    radius = (1 + dz**2) ** 1.5 / np.abs(ddz)
    if inner_height / 2 >= radius.min():
        raise InputError(f"arch_rib_cavity: inner_height={inner_height} m folds the lower face: the axis' smallest "
                         f"radius of curvature is {radius.min():.4g} m; give inner_height < {2 * radius.min():.4g} m")
    nrm = np.column_stack([-dz, np.ones_like(dz)]) / np.hypot(1.0, dz)[:, None]  # upward
    lower = a - 0.5 * inner_height * nrm
    upper = a + 0.5 * inner_height * nrm
    return np.vstack([lower, upper[::-1]])


def inclined_tank_outline(length: float, height: float, angle_deg: float) -> np.ndarray:
    """Inner outline (x, z) [m] of a tank with a flat bottom of ``length`` [m] from x = 0,
    a vertical left side and a right side inclined ``angle_deg`` [deg] from the vertical,
    leaning outwards (the water lies over the slope, as on the upstream face of Chwang's
    dam), sides ``height`` [m] high; open top. Returned as the open polyline top-left ->
    bottom-left -> bottom-right -> top-right."""
    if not 0 <= angle_deg < 90:
        raise InputError(f"the inclined side's angle from the vertical must be in [0, 90) deg, got {angle_deg}")
    if not (length > 0 and height > 0):
        raise InputError(f"tank length {length} m and height {height} m must be positive")
    top_right = length + height * math.tan(math.radians(angle_deg))
    return np.array([[0.0, height], [0.0, 0.0], [length, 0.0], [top_right, height]])


def inclined_tank(dim: int, dx: float, angle_deg: float, length: float = 3.0, depth: float = 1.0,
                  height: float = 1.5, width: float = 1.0, layers: int = 3,
                  rho0: float = 1000.0, conform_layers: int = 1) -> Built:
    """The tank of Sunara et al. 2021, §3.2: the 3.0 x 1.0 x 1.5 m tank of §3.1
    (``length`` x ``width`` x ``height`` [m]) with its right side inclined ``angle_deg``
    [deg] from the vertical (15, 30, 45 in the paper), water ``depth`` [m] (1.0).
    The text gives no figure dimensions for the slope; we keep the bottom ``length`` and let
    the inclined side lean outwards, so that the water lies over it (Chwang's inclined dam
    face, which the paper compares with). 2-D: the x-z section; 3-D: extruded over
    ``width`` along y with ``layers`` wall layers front and back, each holding the
    section's own points (the water's, conforming layers included, and the side walls'),
    so that every y-layer, wall or water, is the same section. Walls group 0, FIXED_WALL,
    open top.

    The fluid's first ``conform_layers`` [-] layers follow the walls (default 1; 0 is the
    paper's pure Cartesian grid). Why: next to a slanted side the lattice fluid lies
    1.0-1.3 dx from the first wall layer instead of dx, and at rest it settles into that
    gap, which Sunara et al. 2021, §3.2 also reports as larger errors on the slopes. Measured in 2-D
    (length 0.4 m, depth 0.2 m, dx = 0.02 m, solver defaults, c0 = 20 sqrt(g H), 3 s at
    rest), at 45 deg: lattice fill (0): speeds up to 0.11 sqrt(g H), kinetic energy up to
    7.8e-2 J/m, particles by the lower end of the slope moved 8 dx; one conforming layer
    (1): up to 2.7e-2 sqrt(g H) and 6.9e-3 J/m, decaying to 6e-3 to 8e-3 sqrt(g H) at
    2.5-3 s, largest displacement 1.4 dx; two layers (2) are worse (the lattice then meets
    the second layer as close as 0.62 dx: 6e-2 sqrt(g H)). With a vertical side (0 deg) the
    lattice tank stays below 4e-4 sqrt(g H). Let a slanted tank settle before exciting it.
    In 3-D (a slice 3 rows wide, the 15 deg tank of Sunara et al. 2021, §3.2 at dx = 0.1 m, c0 = 1430 m/s,
    ``walls="adami"``, 0.06 s at rest) the water moves at up to 0.11 m/s, 0.03 m/s across
    the slice (the 2-D section: 0.07 m/s); front and back walls filled from the lattice
    instead, a staircase beside the water's conforming layer, push the rows next to them
    to 0.16 m/s, 0.12 m/s across.
    """
    if dim not in (2, 3):
        raise InputError(f"dim must be 2 or 3, got {dim}")
    if not 0 < depth <= height:
        raise InputError(f"the water depth {depth} m must lie in (0, height={height} m]")
    outline = inclined_tank_outline(length, height, angle_deg)
    closed = np.vstack([outline[1:], outline[:1]])  # bottom-left, bottom-right, top-right, top-left
    fl2 = polygon_fluid(closed, dx, conform_layers)
    fl2 = fl2[fl2[:, 1] < depth]
    w2 = polyline_wall(outline, dx, layers, closed=False)  # walked down, across, up: water on the left
    if dim == 2:
        return assemble(2, dx, rho0, fl2, [(w2, Kind.FIXED_WALL, 0)])
    if not width > 0:
        raise InputError("a 3-D tank needs a width > 0 m along y")
    ny = int(math.floor(width / dx + 1e-9))
    ys = dx * (0.5 + np.arange(ny))
    yw = np.concatenate([ys, -dx * (0.5 + np.arange(layers)), width + dx * (0.5 + np.arange(layers))])
    # front and back walls: the section's points as the fluid fills it (its conforming
    # layers and the lattice, clear of the side walls as assemble clears the fluid, at all
    # heights) and the side walls' section, so that every y-layer, wall or water, holds
    # the same (x, z) points and the rows next to the front and back walls are balanced as
    # the middle ones (a lattice section there, a staircase beside the fluid's conforming
    # layer, pushes them across the tank and along a slanted side)
    inner = polygon_fluid(closed, dx, conform_layers)
    d, _ = cKDTree(w2).query(inner, k=1, distance_upper_bound=0.9 * dx)
    sect = np.vstack([inner[~(d < 0.9 * dx)], w2])
    walls = np.vstack([_extrude(w2, ys), _extrude(sect, yw[ny:])])
    return assemble(3, dx, rho0, _extrude(fl2, ys), [(walls, Kind.FIXED_WALL, 0)])


def _extrude(xz: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """(x, z) points repeated at every y of ``ys``: (len(xz) * len(ys), 3) as (x, y, z)."""
    n = len(xz)
    out = np.empty((n * len(ys), 3))
    out[:, 0] = np.tile(xz[:, 0], len(ys))
    out[:, 1] = np.repeat(ys, n)
    out[:, 2] = np.tile(xz[:, 1], len(ys))
    return out


def cylinder_tank(dx: float, diameter: float = 2.0, depth: float = 0.6, height: float = 1.0,
                  layers: int = 3, rho0: float = 1000.0) -> Built:
    """The vertical cylindrical tank of Sunara et al. 2021, §3.3 (3-D): inner
    ``diameter`` [m] (2.0), wall ``height`` [m] (1.0), water ``depth`` [m] (0.6), axis
    along z through the origin, bottom at z = 0, open top.

    Fluid: at every lattice height, concentric rings at radii ``(j + 1/2) dr``
    (``dr = R / round(R / dx)``, = dx when R is a multiple of dx), each ring sampled at ~dx
    round its circumference: every particle stands for the same volume ~dx^3 (the "equal
    volume" distribution of Sunara et al. 2021, §3.3) and the count x dx^3 equals pi R^2 depth up to the
    rounding of the ring counts (the midpoint rule sum_j 2 pi r_j dr is exactly pi R^2),
    while a Cartesian lattice cut at r < R and cleared of the wall would lose a ring of
    ~0.4 dx (4 % at D = 2 m, dx = 5 cm). Side wall: ``layers`` shells at ``R + (k + 1/2) dx``
    sampled the same way; bottom: ``layers`` lattice layers of the disc that covers the
    shells. Walls group 0, FIXED_WALL.

    At rest (a small tank: D = 0.2 m, water 0.1 m, dx = 0.02 m, 1752 particles, solver
    defaults, c0 = 20 sqrt(g H)): speeds 1.5e-2 to 2.5e-2 sqrt(g H) over 1.5 s, largest
    displacement 0.84 dx, pressure 1.7 % RMS of rho g H: the rings settle against the
    shells; coarse (5 layers, 5 rings), not a validation."""
    if not (diameter > 0 and 0 < depth <= height):
        raise InputError(f"need diameter > 0 and 0 < depth <= height; got {diameter}, {depth}, {height} m")
    if int(layers) != layers or layers < 1:
        raise InputError(f"a wall needs at least one layer, got layers={layers}")
    if not 0 < dx <= 0.25 * diameter:
        raise InputError(f"dx={dx} m: give a positive spacing of at most a quarter of the diameter")
    R = 0.5 * diameter
    nr = max(1, round(R / dx))
    dr = R / nr
    fl_xy = np.vstack([_ring((j + 0.5) * dr, dx, j % 2) for j in range(nr)])
    fluid = _stack(fl_xy, dx * (0.5 + np.arange(int(math.floor(depth / dx + 1e-9)))))
    zs = dx * (0.5 + np.arange(int(math.floor(height / dx + 1e-9))))
    shells = [_stack(_ring(R + (k + 0.5) * dx, dx, (nr + k) % 2), zs) for k in range(int(layers))]
    Ro = R + layers * dx
    n = int(math.ceil(Ro / dx))
    disc = block([-n * dx, -n * dx], [n * dx, n * dx], dx)
    bottom = _stack(disc[np.hypot(disc[:, 0], disc[:, 1]) < Ro], -dx * (0.5 + np.arange(int(layers))))
    return assemble(3, dx, rho0, fluid, [(np.vstack(shells + [bottom]), Kind.FIXED_WALL, 0)])


def _ring(r: float, dx: float, stagger: int) -> np.ndarray:
    """Points on the circle of radius ``r`` [m] at the spacing nearest ``dx`` [m]; every
    other ring turned by half a spacing so that neighbouring rings do not line up."""
    m = max(3, round(2 * math.pi * r / dx))
    phi = 2 * math.pi * (np.arange(m) + 0.5 * stagger) / m
    return np.column_stack([r * np.cos(phi), r * np.sin(phi)])


def _stack(xy: np.ndarray, zs: np.ndarray) -> np.ndarray:
    """(x, y) points repeated at every height of ``zs``: (len(xy) * len(zs), 3)."""
    return np.column_stack([np.tile(xy, (len(zs), 1)), np.repeat(zs, len(xy))])
