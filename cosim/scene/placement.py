"""Where a ``place = "floating"`` body starts: at the height where the water it displaces
carries its weight and the vertical pull of its mooring lines.

Balance (upright body, draft d below the still-water level ``level``)::

    rho g V_sub(d) = m g + sum_lines V_line(z_fairlead(d))

with ``V_sub`` exact for the builder shapes (box: A d; 2-D cylinder, a circle of radius r:
the segment r^2 acos((r - d)/r) - (r - d) sqrt(2 r d - d^2) per metre; 3-D cylinder, axis
vertical: pi r^2 d; sphere: the cap pi d^2 (3 r - d) / 3) and ``V_line`` the vertical
force of each line on its fairlead from the quasi-static catenary
(``moorings.catenary.solve``, 004_1657bd4a51d29840.txt Eq. 35-39, elastic when the line
has EA) whatever the scene's mooring model: a static start, which a dynamic line
relaxes from. Solved by bisection on d to 1e-12 of the body's height.
"""

from __future__ import annotations

import math

from cosim.scene.fields import SceneError
from cosim.scene.spec import Box, Cylinder, Sphere


def volume_and_height(body, dim: int) -> tuple[float, float]:
    """Volume [m^3] (2-D: per metre of depth) and height [m] of an upright builder body."""
    if isinstance(body, Box):
        v = math.prod(body.size)
        return v, body.size[-1]
    if isinstance(body, Cylinder):
        if dim == 2:
            return math.pi * body.radius**2, 2 * body.radius
        return math.pi * body.radius**2 * body.length, body.length
    return 4.0 / 3.0 * math.pi * body.radius**3, 2 * body.radius


def submerged_volume(body, dim: int, d: float) -> float:
    """Volume [m^3] below the water line at draft ``d`` [m] (clipped to the body)."""
    _, height = volume_and_height(body, dim)
    d = min(max(d, 0.0), height)
    if isinstance(body, Box):
        return math.prod(body.size[:-1]) * d
    r = body.radius
    if isinstance(body, Cylinder) and dim == 3:
        return math.pi * r * r * d
    if isinstance(body, Cylinder):
        return r * r * math.acos((r - d) / r) - (r - d) * math.sqrt(max(2 * r * d - d * d, 0.0))
    return math.pi * d * d * (3 * r - d) / 3.0


def _line_pull(lines, fairleads_w) -> float:
    """Sum of the lines' downward pull [N] on their fairleads at these positions."""
    from moorings.catenary import solve

    total = 0.0
    for ln, p in zip(lines, fairleads_w):
        h = p[-1] - ln.anchor[-1]
        X = math.dist(p[:-1], ln.anchor[:-1])
        if h <= 0:
            return math.inf  # the fairlead at or below its anchor: drafts that deep are not it
        r = solve(X, h, ln.length, ln.weight, ln.EA)
        total += float(r.V)
    return total


def floating_height(body, dim: int, level: float, rho: float, g: float, lines=(), index: int = 0) -> float:
    """Height [m] of the centre of the upright ``body`` floating on water of density
    ``rho`` [kg/m^3] with its surface at ``level`` [m], pulled by the mooring ``lines``
    (``Line`` records ending on it) at its fairleads; ``index`` names it in errors."""
    volume, height = volume_and_height(body, dim)
    mass = body.mass if body.mass is not None else body.density * volume
    horiz = tuple(body.pos)
    offsets = [body.fairleads[ln.fairlead.split(".")[1]] for ln in lines]

    def excess(d):  # buoyancy minus the loads [N] at draft d
        zc = level - d + 0.5 * height
        if dim == 2:
            pts = [(horiz[0] + o[0], zc + o[1]) for o in offsets]
        else:
            pts = [(horiz[0] + o[0], horiz[1] + o[1], zc + o[2]) for o in offsets]
        return rho * g * submerged_volume(body, dim, d) - mass * g - _line_pull(lines, pts)

    if excess(height) <= 0:
        raise SceneError(f"bodies[{index}].place", f"body {body.name!r} ({mass:.4g} kg) sinks: fully submerged it "
                         f"displaces {rho * volume:.4g} kg of water, less than it and its lines' pull weigh; "
                         f"lighten it or place it at a given pos")
    lo, hi = 0.0, height
    while hi - lo > 1e-12 * height:
        mid = 0.5 * (lo + hi)
        if excess(mid) > 0:
            hi = mid
        else:
            lo = mid
    return level - 0.5 * (lo + hi) + 0.5 * height
