"""The near-field box a scene gets (``domain.kind = "nearfield"``): its extents from the
bodies' footprint, their natural periods and the sea (:func:`fluid.nearfield.choose_box`),
what the scene gives kept."""

from __future__ import annotations

import math

import numpy as np

from cosim.scene.spec import MJCF, Box, Cylinder, ElasticPlate


def heave_period(b, dim: int, rho: float, g: float) -> float | None:
    """An estimate of a floating body's natural heave period [s], ``2 pi sqrt((m + A33) /
    (rho g Awp))`` (Newman 1977, Marine Hydrodynamics §6.17), for an upright box and (3-D)
    an upright cylinder: ``m`` its mass, ``Awp`` its waterplane area, ``A33`` that of a disc
    (3-D: ``(4/3) rho r^3``, half the deep-submerged disc's ``(8/3) rho r^3``, Newman 1977
    Table 4.2, ``r`` the waterplane's equivalent radius) or strip (2-D: ``rho pi B^2 / 8``)
    at the surface. None for other bodies (not floating, spheres, 2-D circles): their
    period is not estimated."""
    if b.place != "floating":
        return None
    if isinstance(b, Box):
        volume = math.prod(b.size) if dim == 3 else b.size[0] * b.size[1]
        awp = b.size[0] * (b.size[1] if dim == 3 else 1.0)
    elif isinstance(b, Cylinder) and dim == 3:
        volume = math.pi * b.radius**2 * b.length
        awp = math.pi * b.radius**2
    else:
        return None
    m = b.mass if b.mass is not None else b.density * volume
    if dim == 3:
        added = 4.0 / 3.0 * rho * math.sqrt(awp / math.pi) ** 3
    else:
        added = rho * math.pi * b.size[0] ** 2 / 8.0
    return 2.0 * math.pi * math.sqrt((m + added) / (rho * g * awp))


def footprint(scene) -> tuple:
    """The bodies' horizontal extent ``(lo, hi)``: (x,) or (x, y) corners [m] of the boxes
    round them (a point at the origin without bodies)."""
    dim = scene.world.dim
    n = dim - 1
    lo, hi = [math.inf] * n, [-math.inf] * n
    for b in scene.bodies:
        half = b.extent(dim)
        centre = b.base if isinstance(b, ElasticPlate) else b.pos
        for k in range(n):
            lo[k], hi[k] = min(lo[k], centre[k] - half[k]), max(hi[k], centre[k] + half[k])
    if not scene.bodies:
        lo, hi = [0.0] * n, [0.0] * n
    return tuple(lo), tuple(hi)


def box_for(scene):
    """The :class:`fluid.nearfield.BoxChoice` of the scene's near field: what its domain
    gives, the rest chosen from the bodies and the sea (:func:`fluid.nearfield.choose_box`,
    the bodies' :func:`reach`)."""
    from cosim.scene.build import fluid_config, incident_sea
    from cosim.scene.setup import choose
    from fluid.nearfield import choose_box

    d, dim = scene.domain, scene.world.dim
    if any(isinstance(b, MJCF) for b in scene.bodies) and (d.x0 is None or d.x1 is None or
                                                            (dim == 3 and d.width is None)):
        from cosim.scene.fields import SceneError

        raise SceneError("domain.x0", "the near field's extent is chosen from builder bodies only; with an MJCF model "
                         "give domain.x0, domain.x1" + (" and domain.width" if dim == 3 else ""))
    sea = incident_sea(scene)
    h = fluid_config(scene, choose(scene), numbers_only=True).h
    rho, g = scene.fluid.rho0, scene.world.gravity
    rigid = [b for b in scene.bodies if not isinstance(b, (MJCF, ElasticPlate))]
    periods = [p for p in (heave_period(b, dim, rho, g) for b in rigid) if p is not None]
    if any(isinstance(b, MJCF) for b in scene.bodies):
        fp, size = ((0.0,) * (dim - 1), (0.0,) * (dim - 1)), 0.0
    else:
        fp = footprint(scene)
        size = max((b.extent(dim)[0] for b in scene.bodies), default=0.0)
    return choose_box(sea, h, fp, reach=reach(scene), periods=periods, size=size, symmetric=d.symmetry,
                      dx=scene.fluid.dx, dim=dim, zone=d.zone, x=(d.x0, d.x1), width=d.width, height=d.height,
                      side_zones=d.side_zones)


def reach(scene) -> float:
    """How far [m] the near field allows its bodies to move from their places: the sea's
    orbit amplitude at the surface (the sum of its components' ``a / tanh(k d)``, linear
    theory's horizontal semi-axis at z = 0), doubled for the slow drift, or a forced body's
    horizontal amplitude (``motion``, surge or sway) if larger; 0 without bodies."""
    from cosim.scene.build import incident_sea

    if not scene.bodies:
        return 0.0
    sea = incident_sea(scene)
    c = sea.components
    forced = [b.motion.amplitude for b in scene.bodies
              if getattr(b, "motion", None) is not None and b.motion.dof != "heave"]
    return max([2.0 * float((c.amplitude / np.tanh(c.k * sea.depth)).sum())] + forced)
