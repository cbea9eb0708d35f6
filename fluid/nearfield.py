"""An SPH near field inside an incident sea: a box of water around the bodies whose end
walls follow the sea's orbital motion and whose outer layers relax the water towards the
sea's velocity, so that the incident waves pass through and what the bodies radiate and
scatter is absorbed before it reaches the walls.

Why walls that move: a box much shorter than the wavelength must let the whole surface
rise and fall with the wave, which a closed box of fixed walls forbids (its volume is
fixed). A wall whose particles keep the orbits of linear theory (``fluid.waves.Sea.
displacement``: each particle on the orbit of the water particle at its mean position)
encloses the volume the incident wave needs, to first order, as a piston wavemaker does for
one wave (a wall at the near end makes the waves, the one at the far end takes them out).
The relaxation zones (:mod:`fluid.relaxation`, Jacobsen, Fuhrman & Fredsøe 2012, Eq. 5
weight as a rate) next to each moving wall pull the fluid's velocity towards the sea's, so
the scattered and radiated part dies out there (DualSPHysics does the same with its
relaxation zones, Altomare et al. 2018, Appl. Ocean Res. 81). The seabed is a fixed wall;
in 3-D the side walls are fixed slip walls (``alpha_wall = 0``): the incident velocity is
tangential to them for head seas (the heading along x).

Frame: the sea's frame (``fluid.waves``: still water at ``sea.level``, seabed ``sea.depth``
below it); 2-D positions are (x, z), y = 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from errors import InputError
from fluid.geometry import block
from fluid.particles import Kind
from fluid.relaxation import Slab, zone_factor
from fluid.sea_tables import PointOrbits, VelocityTable, tabulable
from fluid.waves import component_factors, point_sums, wavenumbers

FIXED_GROUP, NEAR_END_GROUP, FAR_END_GROUP = 0, 1, 2


def _xyz(points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """x, y, z of (N, 2) (x, z) or (N, 3) points."""
    if points.shape[1] == 2:
        return points[:, 0], np.zeros(len(points)), points[:, 1]
    return points[:, 0], points[:, 1], points[:, 2]


def excursion(sea) -> float:
    """A bound [m] on how far the water at the surface (and an end wall on its orbit) moves
    along the heading from its mean place: the sum of the sea's amplitudes over
    ``tanh(k d)`` of its longest component (linear theory's horizontal semi-axis at z = 0)."""
    kd = float(np.min(sea.components.k)) * sea.depth
    return float(np.sum(sea.components.amplitude)) / math.tanh(kd)


class FollowingWall:
    """The motion ``motion(t, ref) -> (pos, vel)`` (``Fluid.prescribe_motion``) of a wall whose
    particles keep the linear orbits of the sea's water particles at their reference
    positions ``ref`` (N, 2) (x, z) or (N, 3) [m], and its exact :meth:`particle_acceleration`
    (which ``Fluid.prescribed_acceleration`` takes). The orbits come from
    :class:`fluid.sea_tables.PointOrbits` (the sea's own sums, their factors kept), one per
    ``ref`` array (the fluid gives each wall its own, every time), with the last time's
    motion (the fluid asks for the acceleration where it has just placed the wall)."""

    def __init__(self, sea):
        self.sea = sea
        self._kept = {}  # id(ref) -> [ref, its orbits, (t, pos, vel, acc)]: ref is held, so its id stays its own

    def _motion(self, t: float, ref) -> tuple:
        ref = np.asarray(ref, float)
        kept = self._kept.get(id(ref))
        if kept is None or kept[0] is not ref:
            kept = self._kept[id(ref)] = [ref, PointOrbits(self.sea, *_xyz(ref)), None]
        if kept[2] is None or kept[2][0] != t:
            disp, rate, acc = kept[1].motion(t, ref.shape[1])
            kept[2] = (t, ref + disp, rate, acc)
        return kept[2]

    def __call__(self, t: float, ref):
        _, pos, vel, _ = self._motion(t, ref)
        return pos.copy(), vel.copy()

    def particle_acceleration(self, t: float, ref) -> np.ndarray:
        """The wall particles' acceleration [m/s^2] at time ``t`` [s]."""
        return self._motion(t, ref)[3].copy()


def following_wall(sea) -> FollowingWall:
    """The motion of a wall on the sea's orbits (:class:`FollowingWall`)."""
    return FollowingWall(sea)


def return_current(sea) -> np.ndarray:
    """The uniform current [m/s] (3,) that carries back the waves' mass transport, so that a
    box closed by walls on linear orbits (which carry none) keeps its water where it is:
    ``-Q / d`` along the heading, ``Q = sum g a^2 k / (2 omega)`` [m^2/s] the volume flux of
    the waves' Stokes drift per unit crest length (Dean & Dalrymple 1991, §4.9:
    ``E / (rho c)`` per component)."""
    c = sea.components
    q = float(np.sum(sea.g * c.amplitude ** 2 * c.k / (2.0 * c.omega)))
    return -q / sea.depth * sea.heading


def sea_velocity(sea, drift: bool = True, reach: tuple | None = None) -> "SeaVelocity":
    """The relaxation target ``target(pos, t) -> vel`` (``fluid.relaxation.Slab``): the sea's
    velocity at the particles, (N, 2) (x, z) or (N, 3); ``drift``: with the
    :func:`return_current` (faded in with the sea). ``reach``: the range (lo, hi) [m] along
    the heading that the particles asking can reach; a many-component sea is then read
    from a :class:`fluid.sea_tables.VelocityTable` over it (within 1 % of its shortest
    components' velocity) instead of summed at each particle (:class:`SeaVelocity`)."""
    table = VelocityTable(sea, *reach).velocity if reach is not None and tabulable(sea) else None
    return SeaVelocity(sea, return_current(sea) if drift else None, table)


class SeaVelocity:
    """The sea's velocity as a relaxation target (:func:`sea_velocity`): called as
    ``target(pos, t) -> vel``, and able to relax a zone itself (:meth:`relax`, the
    ``fluid.relaxation.Slab`` hook) in one compiled pass where the sea is a linear sum read
    directly (not tabulated): a zone asks every step, and the calls of the general path cost
    more than a small box's step. ``back``: the return current [m/s] (3,) or None; ``table``:
    a ``VelocityTable.velocity`` or None; ``wall``: an absorbing end wall
    (``fluid.wall_absorption.AbsorbingEnd``) whose correction's velocity along x is added,
    so that the zone lets pass what the wall absorbs."""

    def __init__(self, sea, back=None, table=None, wall=None):
        self.sea, self.back, self.table, self.wall = sea, back, table, wall

    def with_wall(self, wall) -> "SeaVelocity":
        """This target plus the end wall ``wall``'s correction velocity along x."""
        return SeaVelocity(self.sea, self.back, self.table, wall)

    def _current(self, t: float) -> np.ndarray:
        """The return current at time ``t`` [s] (3,): the waves' mass transport grows as the
        square of the faded-in amplitude."""
        sea = self.sea
        q = min(max(t / sea.ramp, 0.0), 1.0) if sea.ramp > 0 else 1.0
        return (0.5 * (1.0 - math.cos(math.pi * q))) ** 2 * self.back

    def __call__(self, pos, t):
        pos = np.asarray(pos, float)
        if self.table is None:
            v = self.sea.velocity_at(pos, t)
        else:
            v = self.table(*_xyz(pos), t)
            v = v[:, [0, 2]] if pos.shape[1] == 2 else v
        if self.back is not None:
            v += self._current(t)[[0, 2]] if pos.shape[1] == 2 else self._current(t)
        if self.wall is not None:
            v[:, 0] += self.wall.rate
        return v

    def relax(self, slab, pos, vel, kind, t: float, dt: float, extra) -> bool:
        """Relax ``slab``'s fluid particles towards this target over ``dt`` [s] at ``t`` [s]
        as ``Slab.apply`` does (``extra``: a second velocity array alike, or None) in one
        compiled pass (:func:`_relax_to_sea`); False where it cannot (a tabulated or
        higher-order sea: the caller takes the general path)."""
        sea = self.sea
        if self.table is not None or not sea.linear:
            return False
        w, a, ph, k = sea._comp
        e0, e1 = sea._heading2
        current = self._current(t) if self.back is not None else np.zeros(3)
        wall = self.wall.rate if self.wall is not None else 0.0
        _relax_to_sea(pos, vel, np.zeros((0, vel.shape[1])) if extra is None else extra, kind, slab.axis,
                      float(slab.inner), float(slab.outer), float(slab.rate), float(dt), float(t), e0, e1,
                      float(sea.level), float(sea.depth), float(sea.g), w, a, ph, k, float(sea._s_ref),
                      sea._fade_args(), current, self.back is not None, float(wall), self.wall is not None)
        return True


_U_ONLY = np.array([False, True, True, False, False, False])  # point_sums' rows: the velocity


@njit(parallel=True, cache=True)
def _relax_to_sea(pos, vel, extra, kind, axis, x_in, x_out, rate, dt, t, e0, e1, level, depth, g, w, a, ph, k,
                  s_ref, fade, current, has_current, wall, has_wall):
    """``fluid.relaxation.Slab.apply`` towards :class:`SeaVelocity`'s target in one pass: each
    fluid particle in the slab (``chi > 0``) relaxed over ``dt`` with the factor
    ``exp(-sigma(chi) dt)``, towards the sea's velocity at it (``fluid.waves.point_sums``,
    as ``Sea.velocity_at``), plus the return ``current`` (3,) and the ``wall``'s rate along
    x where given, in that order (the general path's); ``extra`` alike when not empty."""
    inv = 1.0 / (x_out - x_in)
    dim = pos.shape[1]
    three = dim == 3
    den, ap = component_factors(a, k, depth, g)
    for i in prange(pos.shape[0]):
        f = zone_factor(pos, kind, i, axis, x_in, inv, rate, dt)
        if f < 0.0:
            continue
        s = pos[i, 0] * e0 + pos[i, 1] * e1 if three else pos[i, 0] * e0
        zeta = min(max(pos[i, dim - 1] - level, -depth), 0.0)
        _, uh, wz, _, _, _, _, _ = point_sums(s, zeta, t, True, w, a, ph, k, depth, den, ap, s_ref, fade, _U_ONLY)
        vx, vy, vz = uh * e0, uh * e1, wz
        if has_current:
            vx += current[0]
            vy += current[1]
            vz += current[2]
        if has_wall:
            vx += wall
        _relax_row(vel, i, vx, vy, vz, f, three)
        if extra.shape[0] > 0:
            _relax_row(extra, i, vx, vy, vz, f, three)


@njit(cache=True)
def _relax_row(vel, i, vx, vy, vz, f, three):
    """``vel[i] <- vt + (vel[i] - vt) f``, ``vt`` = (vx, vz) in 2-D, (vx, vy, vz) in 3-D."""
    vel[i, 0] = vx + (vel[i, 0] - vx) * f
    if three:
        vel[i, 1] = vy + (vel[i, 1] - vy) * f
    vel[i, -1] = vz + (vel[i, -1] - vz) * f


@dataclass(frozen=True)
class NearFieldBox:
    """A near-field box of water: ``fluid`` (N, dim) points, ``walls`` as ``(points, kind,
    group)`` (seabed and side walls fixed, group 0; the near and far end walls, groups 1 and
    2, to be moved by :func:`following_wall`), the x range ``x0 .. x1`` [m] of the water,
    3-D its y range ``y`` [m] (None in 2-D), the relaxation zones' width ``zone`` [m] inside
    each end wall and ``side_zone`` [m] inside each side wall (None: no side zones, a
    channel); ``mirror``: y = y[0] is a symmetry plane, with no wall or zone; ``planes``:
    both y[0] and y[1] are (a channel between symmetry planes, :mod:`fluid.mirror`)."""

    fluid: np.ndarray
    walls: list
    x0: float
    x1: float
    zone: float
    y: tuple | None = None
    side_zone: float | None = None
    mirror: bool = False
    planes: bool = False

    def reach(self, sea) -> tuple[float, float]:
        """The range [m] along the sea's heading that the box's water can reach: its corners'
        positions, widened by the sea's :func:`excursion`."""
        e = sea.heading
        ys = (0.0, 0.0) if self.y is None else self.y
        s = [x * e[0] + y * e[1] for x in (self.x0, self.x1) for y in ys]
        return min(s) - excursion(sea), max(s) + excursion(sea)

    def zones(self, sea, rate: float, drift: bool = True, ends: tuple | None = None) -> list:
        """The relaxation zones (weight 1 at the walls), relaxing at ``rate`` [1/s] there
        towards the sea's velocity (``drift``: and its return current,
        :func:`return_current`): one inside each end wall, 3-D one inside each side wall
        when the box has side zones. ``ends``: the near and far end walls' absorbing
        motions (:meth:`absorbing_ends`), whose correction's velocity each end zone adds to
        its target, so that the zone lets pass what the wall absorbs."""
        target = sea_velocity(sea, drift, self.reach(sea))
        near, far = (target, target) if ends is None else (target.with_wall(e) for e in ends)
        out = [Slab(0, self.x0 + self.zone, self.x0, rate, near), Slab(0, self.x1 - self.zone, self.x1, rate, far)]
        if self.y is not None and self.side_zone is not None:
            (y0, y1), w = self.y, self.side_zone
            out.append(Slab(1, y1 - w, y1, rate, target))
            if not self.mirror:
                out.append(Slab(1, y0 + w, y0, rate, target))
        return out

    def absorbing_ends(self, sea, dx: float, h: float) -> tuple:
        """The near and far end walls' motions on the sea's orbits with active absorption
        (:class:`fluid.wall_absorption.AbsorbingEnd`), each reading the free surface over a
        strip two kernel supports (4 ``h``) wide in front of it, beyond the sea's
        :func:`excursion` and a spacing ``dx`` [m] from its mean place: four gauges across
        the strip (sine-squared weights), in 3-D on lines a kernel support (2 ``h``) apart
        across the box's width, a support from its side walls (a symmetry plane's side: from
        the plane). Add both to the fluid's ``controllers`` and pass them to :meth:`zones`.
        Both read their strips in one pass a step (a shared
        :class:`fluid.wall_absorption.StripReader`)."""
        from fluid.wall_absorption import AbsorbingEnd, StripReader

        gap, strip = excursion(sea) + dx, 4.0 * h
        u = (np.arange(4) + 0.5) / 4
        w = np.sin(math.pi * u) ** 2
        w /= w.sum()
        strips = []  # (side, gauges, weights) of each end
        for side, a in ((-1, self.x0 + gap), (1, self.x1 - gap - strip)):
            xs = a + strip * u
            if self.y is None:
                strips.append((side, xs, w))
                continue
            lo = self.y[0] + (0.0 if self.mirror or self.planes else 2.0 * h)
            hi = self.y[1] - (0.0 if self.planes else 2.0 * h)
            n = max(1, int(round((hi - lo) / (2.0 * h))) + 1)
            ys = np.linspace(lo, hi, n) if hi > lo else np.array([0.5 * (self.y[0] + self.y[1])])
            strips.append((side, np.array([(x, y) for x in xs for y in ys]), np.repeat(w, ys.size) / ys.size))
        orbits = FollowingWall(sea)
        reader = StripReader(sea, np.concatenate([g for _, g, _ in strips]))
        m = len(strips[0][1])
        return tuple(AbsorbingEnd(sea, orbits, side, g, wt, reader=reader, rows=slice(i * m, (i + 1) * m))
                     for i, (side, g, wt) in enumerate(strips))


def whole_spacings(x0: float, x1: float, dx: float) -> float:
    """``x1`` [m] moved out to the nearest whole number of spacings ``dx`` from ``x0``: the
    water's lattice fills ``x0 .. x1`` from ``x0`` in whole rows, so a remainder would leave
    the water its last row up to 1.5 dx off the far end wall instead of dx / 2, a gap that
    water at rest keeps as a step in pressure and falls into (the level drops at that end:
    docs/validation/nearfield.md, "The near field at h = sqrt(2) dx lost its level")."""
    n = math.ceil((x1 - x0) / dx - 1e-9)
    return x0 + n * dx


def near_field_box(dx: float, x0: float, x1: float, sea, height: float, zone: float, *, layers: int = 4,
                   y: tuple | None = None, side_zone: float | None = None,
                   slack: float | None = None, mirror: bool = False, planes: bool = False) -> NearFieldBox:
    """Water from ``x0`` to ``x1`` [m] over the sea's seabed (``sea.level - sea.depth``) up
    to its still level, spacing ``dx`` [m]; walls ``height`` [m] above the seabed and
    ``layers`` thick (``x1`` moved out to a whole number of spacings, :func:`whole_spacings`);
    relaxation zones ``zone`` [m] wide inside each end wall; 3-D across
    ``y = (y0, y1)`` [m] with fixed side walls beyond, zones ``side_zone`` [m] wide inside
    them (None: none); ``mirror``: the plane y = y0 is a symmetry plane (:mod:`fluid.mirror`),
    with no wall or zone at it; ``planes``: y0 and y1 both are, no side walls (a channel: no
    side zones). The seabed runs on beyond each end wall by
    ``slack`` [m] (default: the sea's largest horizontal excursion there and a layer), so
    that the moving walls always stand on it."""
    for name, v in (("dx", dx), ("height", height), ("zone", zone)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InputError(f"near field: {name} = {v!r} m; give a finite number > 0")
    if not x1 - x0 > 2.0 * zone:
        raise InputError(f"near field: the box {x0} .. {x1} m is not longer than its two zones of {zone} m; "
                         "lengthen it or narrow the zones")
    if y is not None and side_zone is not None and not y[1] - y[0] > (1.0 if mirror else 2.0) * side_zone:
        raise InputError(f"near field: the box's width {y[0]} .. {y[1]} m is not wider than its side zones of "
                         f"{side_zone} m; widen it or narrow the zones")
    x1 = whole_spacings(x0, x1, dx)
    bed = sea.level - sea.depth
    if not height > sea.depth:
        raise InputError(f"near field: the walls' height {height} m must exceed the water depth {sea.depth} m")
    t = layers * dx
    if slack is None:
        slack = excursion(sea) + dx
    slack = math.ceil(slack / dx) * dx
    span = (x0 - t - slack, x1 + t + slack)
    if y is None:
        def box(lo, hi):
            return block((lo[0], lo[1]), (hi[0], hi[1]), dx)
        sides = []
        floor = box((span[0], bed - t), (span[1], bed))
    else:
        def box(lo, hi, across=tuple(y)):
            return block((lo[0], across[0], lo[1]), (hi[0], across[1], hi[1]), dx)
        # a symmetry plane's water is mirrored, not walled
        inner, outer = (y[0] if mirror or planes else y[0] - t), (y[1] if planes else y[1] + t)
        sides = [] if planes else [box((span[0], bed), (span[1], bed + height), (y[1], y[1] + t))]
        if not (mirror or planes):
            sides.append(box((span[0], bed), (span[1], bed + height), (y[0] - t, y[0])))
        floor = box((span[0], bed - t), (span[1], bed), (inner, outer))
    near = box((x0 - t, bed), (x0, bed + height))
    far = box((x1, bed), (x1 + t, bed + height))
    water = box((x0, bed), (x1, sea.level))
    walls = [(np.concatenate([floor] + sides), Kind.FIXED_WALL, FIXED_GROUP), (near, Kind.MOVING_WALL, NEAR_END_GROUP),
             (far, Kind.MOVING_WALL, FAR_END_GROUP)]
    if (mirror or planes) and y is None:
        raise InputError("near field: a symmetry plane y = y0 is for a 3-D box; give y")
    if planes and side_zone is not None:
        raise InputError("near field: a channel between symmetry planes has no side zones; give side_zone=None")
    return NearFieldBox(water, walls, float(x0), float(x1), float(zone), None if y is None else tuple(map(float, y)),
                        None if y is None or side_zone is None else float(side_zone), bool(mirror), bool(planes))


#: the fewest kernel supports (2 h) a relaxation zone spans, and the water kept between a
#: body's reach and a zone: a zone thinner than a few supports is a wall to the waves
MIN_ZONE_SUPPORTS, MIN_MARGIN_SUPPORTS = 4, 2
#: ``k size`` below which bodies count as small against the sea's wavelength (their zones
#: sized by their own periods): their scattered and radiated waves at the sea's period are
#: then small (diffraction is commonly neglected up to D/L ~ 0.2, k a ~ 0.6, the Morison
#: regime of Sarpkaya & Isaacson 1981; stricter here, for radiation near resonance)
SMALL_BODY_KA = 0.1


@dataclass(frozen=True)
class BoxChoice:
    """The near-field box chosen for a scene (:func:`choose_box`): the water's x range ``x``
    and 3-D y range ``y`` [m] (walls outside), the end zones' width ``zone`` [m], the wall
    ``height`` [m] above the seabed, ``reasons``: for each, what set it, and 3-D the side
    zones' width ``side_zone`` [m] (None: none, in 2-D or a channel)."""

    x: tuple
    y: tuple | None
    zone: float
    height: float
    reasons: dict
    side_zone: float | None = None

    def as_dict(self) -> dict:
        return {"x_m": list(self.x), "y_m": None if self.y is None else list(self.y), "zone_m": self.zone,
                "side_zone_m": self.side_zone, "height_m": self.height, "reasons": dict(self.reasons)}


def choose_box(sea, h: float, footprint: tuple, *, reach: float = 0.0, periods=(), size: float = 0.0,
               symmetric: bool = False, dx: float | None = None, dim: int = 2, zone: float | None = None, x=(None, None),
               width: float | None = None, height: float | None = None,
               side_zones: bool = True) -> BoxChoice:
    """A near-field box for bodies whose horizontal extent is ``footprint = (lo, hi)``
    ((x,) or (x, y) corners [m]; no bodies: a point), in ``sea`` (heading +x), at smoothing
    length ``h`` [m].

    - The zones absorb what the bodies send out: waves at the sea's frequencies and at the
      bodies' own natural ``periods`` [s] (heave, pitch: a free body rings at them). A
      relaxation zone reflects the less the wider it is against the wavelength (Jacobsen,
      Fuhrman & Fredsøe 2012 use one to two); the zone is half the wavelength of the
      longest of those periods that is not longer than the sea's peak period, and at least
      ``MIN_ZONE_SUPPORTS`` kernel supports. The sea's own period counts unless the bodies
      are small against its wavelength, ``k size <= SMALL_BODY_KA`` (``size`` [m] the
      largest body's half extent across the waves): a small body scatters and radiates
      little at the sea's period, and the waves it rings with are its own, shorter ones.
      Longer waves are not absorbed by width but pass with the sea. Measured on a 2-D
      moored box (k size = 0.46, docs/validation/nearfield.md): zones of half its heave
      period's wavelength cut its heave by a third, half the sea's left it within 6 %.
    - Between the bodies and the zones: ``reach`` [m] (how far a body moves from its place:
      the sea's orbit amplitude, its drift) and ``MIN_MARGIN_SUPPORTS`` supports of still
      water, so that no body enters a zone.
    - The walls rise above the seabed by the depth, twice the sea's largest height (the sum
      of its components' heights 2a) and two supports.

    ``zone``, ``x = (x0, x1)``, ``width`` and ``height`` given are kept (reason "given").
    3-D: the box is centred across y on the bodies (``symmetric``: from y = 0, a symmetry
    plane), with zones as wide as the end ones inside its side walls, or (``side_zones``
    False) none: a channel whose slip side walls return what reaches them, for plane waves
    along x (a flume's slice) or bodies far enough from the sides; a length and a width it
    chooses are whole numbers of spacings ``dx`` [m] when given (the length widened on both
    chosen ends alike), so that the particles' lattice meets the walls at dx / 2 and is
    symmetric about the centre as the scene may be."""
    lo, hi = (np.atleast_1d(np.asarray(v, float)) for v in footprint)
    reasons = {}
    peak = sea.peak_period
    if zone is None:
        ka = float(wavenumbers(2.0 * math.pi / peak, sea.depth, sea.g)) * size
        small = bool(periods) and ka <= SMALL_BODY_KA
        kept = [p for p in periods if 0.0 < p <= peak] if small else []
        p = max(kept, default=peak)
        wl = 2.0 * math.pi / float(wavenumbers(2.0 * math.pi / p, sea.depth, sea.g))
        floor = MIN_ZONE_SUPPORTS * 2.0 * h
        zone = max(0.5 * wl, floor)
        if kept:
            what = f"the bodies' natural period {p:.4g} s (small against the sea's wavelength: k size = {ka:.3g})"
        elif periods and not small:
            what = f"the sea's peak period {p:.4g} s (the bodies are not small against it: k size = {ka:.3g})"
        else:
            what = f"the sea's peak period {p:.4g} s"
        reasons["zone"] = (f"half the wavelength {wl:.4g} m of {what}" if zone > floor else
                           f"{MIN_ZONE_SUPPORTS} kernel supports (half the wavelength of {what} is less)")
    else:
        reasons["zone"] = "given"
    margin = reach + MIN_MARGIN_SUPPORTS * 2.0 * h
    water = f"the bodies' reach {reach:.4g} m and {MIN_MARGIN_SUPPORTS} kernel supports of water"
    why = water + ", then the zone"
    x0 = lo[0] - margin - zone if x[0] is None else float(x[0])
    x1 = hi[0] + margin + zone if x[1] is None else float(x[1])
    reasons["x0"] = "given" if x[0] is not None else why
    reasons["x1"] = "given" if x[1] is not None else why
    free = (x[0] is None) + (x[1] is None)
    if dx is not None and free:  # a whole number of spacings (whole_spacings), widened where chosen
        pad = whole_spacings(x0, x1, dx) - x1
        x0 -= pad / free if x[0] is None else 0.0
        x1 += pad / free if x[1] is None else 0.0
    elif dx is not None:  # both given: the far end moves out to whole rows, as the box lays the water
        given, x1 = x1, whole_spacings(x0, x1, dx)
        if x1 != given:
            reasons["x1"] = f"given ({given:.6g} m), moved out {x1 - given:.3g} m to a whole number of spacings"
    y = None
    if dim == 3:
        centre = 0.0 if symmetric else 0.5 * float(lo[1] + hi[1])
        if width is None:
            half = max(hi[1] - centre, centre - lo[1]) + margin + (zone if side_zones else 0.0)
            if dx is not None:
                half = math.ceil(half / dx - 1e-9) * dx
            reasons["width"] = ((why if side_zones else water + ", no side zones") +
                                (" (y >= 0: a symmetry plane at y = 0)" if symmetric else ", on both sides"))
        else:
            half = 0.5 * float(width)
            reasons["width"] = "given"
        y = (0.0 if symmetric else centre - half, centre + half)
    if height is None:
        largest = 2.0 * float(np.sum(sea.components.amplitude))
        height = sea.depth + 2.0 * largest + 2.0 * 2.0 * h
        reasons["height"] = f"the depth, twice the sea's largest height ({largest:.4g} m) and two kernel supports"
    else:
        reasons["height"] = "given"
    side_zone = float(zone) if y is not None and side_zones else None
    if y is not None:
        reasons["side_zone"] = "as wide as the end zones" if side_zones else "none: a channel (side_zones false)"
    return BoxChoice((float(x0), float(x1)), y, float(zone), float(height), reasons, side_zone)
