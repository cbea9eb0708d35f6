"""A wave flume on the particle lattice, 2-D or 3-D: fluid, fixed walls (bottom, far
end, an optional sloping beach; in 3-D side walls at y = 0 and y = ``width``) and a
paddle wall group for a wavemaker (in 3-D across the whole width: a wave tank).

Lattice convention as in :mod:`fluid.geometry`: fluid fills ``0 < x < length``,
``0 < z < depth`` at ``dx/2 + i dx``; wall layers lie outside it. The paddle is
the ``layers`` columns at ``x < 0`` from the bottom to the top of the flume, a
MOVING_WALL group (``PADDLE_GROUP``) to be driven by
``fluid.wavemaker.piston``/``flap`` through ``Fluid.prescribe_motion``; the bottom
runs on behind the paddle by ``back`` [m] so that water following a retreating
piston still has a floor. A beach (``beach=(x_toe, slope)``) is a solid ramp of
``layers`` particles' thickness rising from the bottom at ``x_toe`` [m] with
``slope`` [-] (rise over run) up to the top; waves run up and break on it, which
absorbs most of their energy. In 3-D every piece is extruded across the width, the
side walls run from behind the paddle (its ``back`` floor) to the far wall, and the
paddle slides (piston) or turns (flap, about the y axis) between them:
``fluid.wavemaker.piston``/``flap`` move 3-D wall groups as 2-D ones. With
``side_walls=False`` the flume has no side walls and its floor, paddle and far wall span
y = 0 .. ``width`` only: a slice between two symmetry planes there (the fluid's
``symmetry_y = 0`` and ``symmetry_y_hi = width``, :mod:`fluid.mirror`), for waves uniform
across a flume of any width.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from errors import InputError
from fluid.geometry import block
from fluid.particles import Kind

WALL_GROUP, PADDLE_GROUP = 0, 1


@dataclass(frozen=True)
class Flume:
    """Points of a flume: ``fluid`` (N, dim) and ``walls``, a list of
    ``(points, kind, group)`` for ``fluid.geometry.assemble`` or
    ``cosim.sph_fluid.SPHFluid`` (fixed walls group 0, the paddle group 1)."""

    fluid: np.ndarray
    walls: list
    depth: float
    length: float
    height: float
    width: float | None = None  #: 3-D: between the side walls [m]; 2-D: None


def flume(dx: float, length: float, depth: float, height: float, *, layers: int = 3, back: float = 0.0,
          beach: tuple[float, float] | None = None, width: float | None = None, side_walls: bool = True) -> Flume:
    """A flume of ``length`` [m] (paddle at x = 0 to the far wall), still water
    ``depth`` [m], walls ``height`` [m] high, spacing ``dx`` [m]; ``layers`` [-]
    wall layers; ``back`` [m] of extra floor behind the paddle (at least the
    paddle's largest retreat); ``beach`` = (toe x [m], slope [-]) or None;
    ``width`` [m]: a 3-D tank that wide along y (None: 2-D, x-z plane); ``side_walls``
    False: 3-D without side walls, for two symmetry planes at y = 0 and ``width``."""
    dims = (("dx", dx), ("length", length), ("depth", depth), ("height", height))
    for name, v in dims + ((("width", width),) if width is not None else ()):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InputError(f"flume: {name} must be finite and > 0 m, got {v!r}")
    if not depth < height:
        raise InputError(f"flume: the water depth {depth} m must be below the wall height {height} m")
    if int(layers) != layers or layers < 1:
        raise InputError(f"flume: layers must be a positive whole number, got {layers!r}")
    if not (math.isfinite(back) and back >= 0):
        raise InputError(f"flume: back must be >= 0 m, got {back!r}")
    t = layers * dx
    back = math.ceil(back / dx - 1e-9) * dx
    if width is None:
        def box(lo, hi):  # (x, z) corners
            return block(lo, hi, dx)
        sides = []
    else:
        def box(lo, hi, y=(0.0, width)):  # (x, z) corners, extruded across y
            return block((lo[0], y[0], lo[1]), (hi[0], y[1], hi[1]), dx)
        sides = [box((-t - back, 0.0), (length + t, height), (-t, 0.0)),
                 box((-t - back, 0.0), (length + t, height), (width, width + t))] if side_walls else []
    floor = (box((-t - back, -t), (length + t, 0.0)) if width is None else
             box((-t - back, -t), (length + t, 0.0), (-t, width + t) if side_walls else (0.0, width)))
    far = box((length, 0.0), (length + t, height))
    paddle = box((-t, 0.0), (0.0, height))
    fixed = [floor, far] + sides
    fl = box((0.0, 0.0), (length, depth))
    if beach is not None:
        x_toe, slope = beach
        if not (0 < x_toe < length and slope > 0 and math.isfinite(slope)):
            raise InputError(f"flume: beach = (toe x, slope) needs 0 < toe < length={length} m and slope > 0, "
                             f"got {beach!r}")
        ramp = box((x_toe - t, 0.0), (length, height))
        top = slope * (ramp[:, 0] - x_toe)  # the beach surface over each point
        # the solid: a band of thickness t (measured normal to the surface) under it
        band = (ramp[:, -1] < top) & (ramp[:, -1] > top - t * math.sqrt(1 + slope**2))
        fixed.append(ramp[band])
        # water only above the beach, a particle spacing clear of its surface
        fl = fl[fl[:, -1] > slope * (fl[:, 0] - x_toe) + 0.5 * dx]
    walls = [(np.concatenate(fixed), Kind.FIXED_WALL, WALL_GROUP), (paddle, Kind.MOVING_WALL, PADDLE_GROUP)]
    return Flume(fl, walls, float(depth), float(length), float(height), None if width is None else float(width))
