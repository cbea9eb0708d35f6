"""Where a ``place = "floating"`` body starts: at the height where the water it displaces
carries its weight and the vertical pull of its mooring lines.

Balance (upright body, draft d below the still-water level ``level``)::

    rho g V_sub(d) = m g + sum_lines V_line(z_fairlead(d))

with ``V_sub`` the shape's :meth:`~cosim.scene.shapes.Shape.submerged_volume` (exact for
the built-in shapes: box: A d; 2-D cylinder, a circle of radius r: the segment r^2
acos((r - d)/r) - (r - d) sqrt(2 r d - d^2) per metre; 3-D cylinder, axis vertical: pi r^2
d; sphere: the cap pi d^2 (3 r - d) / 3) and ``V_line`` the vertical
force of each line on its fairlead from the quasi-static catenary
(``moorings.catenary.solve``, Barreiro et al. 2016, Eq. 35-39, elastic when the line
has EA) whatever the scene's mooring model: a static start, which a dynamic line
relaxes from. Solved by bisection on d to 1e-12 of the body's height.
"""

from __future__ import annotations

import math

from cosim.scene.fields import SceneError


def volume_and_height(body, dim: int) -> tuple[float, float]:
    """Volume [m^3] (2-D: per metre of depth) and height [m] of an upright builder body."""
    return body.volume(dim), 2 * body.half_size(dim)[-1]


def submerged_volume(body, dim: int, d: float) -> float:
    """Volume [m^3] below the water line at draft ``d`` [m] (clipped to the body)."""
    return body.submerged_volume(dim, d)


def _line_pull(lines, fairleads_w) -> float:
    """Sum of the lines' downward pull [N] on their fairleads at these positions (a
    fairlead at its anchor's seabed height or above it: the callers keep to those)."""
    from moorings.catenary import solve

    total = 0.0
    for ln, p in zip(lines, fairleads_w):
        h = max(p[-1] - ln.anchor[-1], 0.0)  # round-off at the draft where it reaches the seabed
        X = math.dist(p[:-1], ln.anchor[:-1])
        r = solve(X, h, ln.length, ln.weight, ln.EA)
        total += float(r.V)
    return total


def _bisect(f, lo: float, hi: float, scale: float) -> float:
    """The root of ``f`` (increasing, f(lo) <= 0 < f(hi)) to 1e-12 of ``scale``."""
    while hi - lo > 1e-12 * scale:
        mid = 0.5 * (lo + hi)
        if f(mid) > 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def floating_height(body, dim: int, level: float, rho: float, g: float, lines=(), index: int = 0,
                    keys=None) -> float:
    """Height [m] of the centre of the upright ``body`` floating on water of density
    ``rho`` [kg/m^3] with its surface at ``level`` [m], pulled by the mooring ``lines``
    (``Line`` records ending on it) at its fairleads; ``index`` names it in errors, ``keys``
    the lines (their key paths, default ``moorings.lines[k]`` for the k-th of ``lines``).

    Refused (:class:`SceneError`): a body that sinks (``bodies[index].place``); a fairlead
    that comes down to its anchor's seabed before the body floats (the line's ``anchor``:
    the seabed is the horizontal plane through the anchor, and a fairlead below it has no
    catenary); an inextensible line too short to reach its fairlead at any draft (the
    line's ``length``)."""
    volume, height = volume_and_height(body, dim)
    mass = body.mass if body.mass is not None else body.density * volume
    horiz = tuple(body.pos)
    offsets = [body.fairleads[ln.fairlead.split(".")[1]] for ln in lines]
    keys = list(keys) if keys is not None else [f"moorings.lines[{k}]" for k in range(len(lines))]

    def points(d):  # the fairleads [m] at draft d
        zc = level - d + 0.5 * height
        if dim == 2:
            return [(horiz[0] + o[0], zc + o[1]) for o in offsets]
        return [(horiz[0] + o[0], horiz[1] + o[1], zc + o[2]) for o in offsets]

    def free(d):  # buoyancy minus weight [N] at draft d
        return rho * g * submerged_volume(body, dim, d) - mass * g

    def excess(d):  # buoyancy minus the loads [N] at draft d
        return free(d) - _line_pull(lines, points(d))

    def sinks():
        return SceneError(f"bodies[{index}].place", f"body {body.name!r} ({mass:.4g} kg) sinks: fully submerged it "
                          f"displaces {rho * volume:.4g} kg of water, less than it and its lines' pull weigh; "
                          f"lighten it or place it at a given pos")

    def too_short(d, how):  # the first inextensible line that cannot reach its fairlead at draft d
        for k, (ln, p) in enumerate(zip(lines, points(d))):
            dist = math.dist(p, ln.anchor)
            if ln.EA is None and dist > ln.length * (1 + 1e-12):
                return SceneError(f"{keys[k]}.length", f"{ln.length:g} m is shorter than the straight distance "
                                  f"{dist:.4g} m from its anchor to its fairlead {ln.fairlead!r} with body "
                                  f"{body.name!r} {how}, the nearest it comes: an inextensible line cannot reach; "
                                  f"give a length of at least {dist:.4g} m, move the anchor closer, or give EA "
                                  f"(an elastic line that starts stretched)")
        return None

    if free(height) <= 0:
        raise sinks()
    # the draft at which each fairlead comes down to its anchor's seabed: the deepest there is
    reach = [level + 0.5 * height + o[-1] - ln.anchor[-1] for ln, o in zip(lines, offsets)]
    k = min(range(len(lines)), key=reach.__getitem__, default=None)
    d_hi = height if k is None or reach[k] >= height else reach[k]
    if d_hi <= 0 or excess(d_hi) <= 0:
        err = None if d_hi <= 0 else too_short(d_hi, "fully submerged" if d_hi == height else
                                                f"sunk until the fairlead {lines[k].fairlead!r} is down at its "
                                                f"anchor's seabed")
        if err is not None:
            raise err
        if d_hi == height:
            raise sinks()
        ln, d0 = lines[k], _bisect(free, 0.0, height, height)
        z0 = level - d0 + 0.5 * height + offsets[k][-1]
        where = (f"even with the body's bottom at the water level its fairlead {ln.fairlead!r} is at z = "
                 f"{level + 0.5 * height + offsets[k][-1]:.4g} m" if d_hi <= 0 else
                 f"it floats only at a draft beyond {d_hi:.4g} m, where its fairlead {ln.fairlead!r} is below it")
        raise SceneError(f"{keys[k]}.anchor", f"body {body.name!r} starts below this anchor's seabed z = "
                         f"{ln.anchor[-1]:g} m (the horizontal plane through the anchor): {where}; put the anchor "
                         f"lower, below z = {z0:.4g} m (the fairlead's height when the body floats without lines)")
    return level - _bisect(excess, 0.0, d_hi, height) + 0.5 * height
