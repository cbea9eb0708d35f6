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

from errors import InputError
from fluid.geometry import block
from fluid.particles import Kind
from fluid.relaxation import Slab

FIXED_GROUP, NEAR_END_GROUP, FAR_END_GROUP = 0, 1, 2


def _xyz(points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """x, y, z of (N, 2) (x, z) or (N, 3) points."""
    if points.shape[1] == 2:
        return points[:, 0], np.zeros(len(points)), points[:, 1]
    return points[:, 0], points[:, 1], points[:, 2]


def following_wall(sea):
    """The motion ``motion(t, ref) -> (pos, vel)`` (``Fluid.prescribe_motion``) of a wall whose
    particles keep the linear orbits of the sea's water particles at their reference
    positions ``ref`` (N, 2) (x, z) or (N, 3) [m]."""

    def motion(t, ref):
        ref = np.asarray(ref, float)
        disp, rate = sea.displacement(*_xyz(ref), t)
        cols = [0, 2] if ref.shape[1] == 2 else [0, 1, 2]
        return ref + disp[:, cols], rate[:, cols]

    return motion


def return_current(sea) -> np.ndarray:
    """The uniform current [m/s] (3,) that carries back the waves' mass transport, so that a
    box closed by walls on linear orbits (which carry none) keeps its water where it is:
    ``-Q / d`` along the heading, ``Q = sum g a^2 k / (2 omega)`` [m^2/s] the volume flux of
    the waves' Stokes drift per unit crest length (Dean & Dalrymple 1991, §4.9:
    ``E / (rho c)`` per component)."""
    c = sea.components
    q = float(np.sum(sea.g * c.amplitude ** 2 * c.k / (2.0 * c.omega)))
    return -q / sea.depth * sea.heading


def sea_velocity(sea, drift: bool = True):
    """The relaxation target ``target(pos, t) -> vel`` (``fluid.relaxation.Slab``): the sea's
    velocity at the particles, (N, 2) (x, z) or (N, 3); ``drift``: with the
    :func:`return_current` (faded in with the sea)."""
    back = return_current(sea) if drift else np.zeros(3)

    def target(pos, t):
        x, y, z = _xyz(np.asarray(pos, float))
        v = sea.velocity(x, y, z, t)
        if drift:  # the mass transport grows as the square of the faded-in amplitude
            q = min(max(t / sea.ramp, 0.0), 1.0) if sea.ramp > 0 else 1.0
            v = v + (0.5 * (1.0 - math.cos(math.pi * q))) ** 2 * back
        return v[:, [0, 2]] if pos.shape[1] == 2 else v

    return target


@dataclass(frozen=True)
class NearFieldBox:
    """A near-field box of water: ``fluid`` (N, dim) points, ``walls`` as ``(points, kind,
    group)`` (seabed and side walls fixed, group 0; the near and far end walls, groups 1 and
    2, to be moved by :func:`following_wall`), the x range ``x0 .. x1`` [m] of the water and
    the relaxation zones' width ``zone`` [m] at each end."""

    fluid: np.ndarray
    walls: list
    x0: float
    x1: float
    zone: float

    def zones(self, sea, rate: float, drift: bool = True) -> list:
        """The two relaxation zones (near end: weight 1 at x0; far end: at x1), relaxing at
        ``rate`` [1/s] at the walls towards the sea's velocity (``drift``: and its return
        current, :func:`return_current`)."""
        target = sea_velocity(sea, drift)
        return [Slab(0, self.x0 + self.zone, self.x0, rate, target), Slab(0, self.x1 - self.zone, self.x1, rate, target)]


def near_field_box(dx: float, x0: float, x1: float, sea, height: float, zone: float, *, layers: int = 4,
                   width: float | None = None, slack: float | None = None) -> NearFieldBox:
    """Water from ``x0`` to ``x1`` [m] over the sea's seabed (``sea.level - sea.depth``) up
    to its still level, spacing ``dx`` [m]; walls ``height`` [m] above the seabed and
    ``layers`` thick; relaxation zones ``zone`` [m] wide inside each end; 3-D across
    ``0 .. width`` [m] (side walls beyond). The seabed runs on beyond each end wall by
    ``slack`` [m] (default: the sea's largest horizontal excursion there and a layer), so
    that the moving walls always stand on it."""
    for name, v in (("dx", dx), ("height", height), ("zone", zone)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InputError(f"near field: {name} = {v!r} m; give a finite number > 0")
    if not x1 - x0 > 2.0 * zone:
        raise InputError(f"near field: the box {x0} .. {x1} m is not longer than its two zones of {zone} m; "
                         "lengthen it or narrow the zones")
    bed = sea.level - sea.depth
    if not height > sea.depth:
        raise InputError(f"near field: the walls' height {height} m must exceed the water depth {sea.depth} m")
    t = layers * dx
    if slack is None:
        a = float(np.sum(sea.components.amplitude))
        kd = float(np.min(sea.components.k)) * sea.depth
        slack = a * math.cosh(kd) / math.sinh(kd) + dx
    slack = math.ceil(slack / dx) * dx
    if width is None:
        def box(lo, hi):
            return block((lo[0], lo[1]), (hi[0], hi[1]), dx)
        sides = []
    else:
        def box(lo, hi, y=(0.0, width)):
            return block((lo[0], y[0], lo[1]), (hi[0], y[1], hi[1]), dx)
        span = (x0 - t - slack, x1 + t + slack)
        sides = [box((span[0], bed), (span[1], bed + height), (-t, 0.0)),
                 box((span[0], bed), (span[1], bed + height), (width, width + t))]
    floor = (box((x0 - t - slack, bed - t), (x1 + t + slack, bed)) if width is None else
             box((x0 - t - slack, bed - t), (x1 + t + slack, bed), (-t, width + t)))
    near = box((x0 - t, bed), (x0, bed + height))
    far = box((x1, bed), (x1 + t, bed + height))
    water = box((x0, bed), (x1, sea.level))
    walls = [(np.concatenate([floor] + sides), Kind.FIXED_WALL, FIXED_GROUP), (near, Kind.MOVING_WALL, NEAR_END_GROUP),
             (far, Kind.MOVING_WALL, FAR_END_GROUP)]
    return NearFieldBox(water, walls, float(x0), float(x1), float(zone))
