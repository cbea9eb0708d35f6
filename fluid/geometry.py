"""Geometry builders: fluid blocks and rectangular tanks on a Cartesian lattice of spacing
``dx`` [m], in 2-D (x, z) and 3-D (x, y, z).

Lattice convention: inside a box ``lo``..``hi`` particles sit at ``lo + dx/2 + i dx``, so a
fluid block filling a tank's inner box lies ``dx`` from the first wall layer, and wall
layers ``k = 0..n-1`` lie at ``dx/2 + k dx`` outside the inner faces.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from errors import InputError
from fluid.equations import hydrostatic_density
from fluid.particles import Kind, ParticleSet

log = logging.getLogger(__name__)


def _axes(lo, hi, dx):
    lo = np.asarray(lo, np.float64)
    hi = np.asarray(hi, np.float64)
    if lo.shape != hi.shape or lo.size not in (2, 3):
        raise InputError(f"box corners must both have 2 (x, z) or 3 (x, y, z) components: {lo}, {hi}")
    if not dx > 0:
        raise InputError(f"particle spacing dx must be positive, got {dx} m")
    if not (hi > lo).all():
        raise InputError(f"box upper corner {hi} must exceed lower corner {lo} in every component")
    n = np.floor((hi - lo) / dx + 1e-9).astype(int)
    return [lo[k] + dx * (0.5 + np.arange(n[k])) for k in range(lo.size)]


def block(lo, hi, dx: float) -> np.ndarray:
    """Lattice points filling the box ``lo``..``hi`` [m] at spacing ``dx`` [m]: (N, dim)."""
    g = np.meshgrid(*_axes(lo, hi, dx), indexing="ij")
    return np.stack([a.ravel() for a in g], axis=1)


def tank_walls(inner_lo, inner_hi, dx: float, layers: int = 3, open_top: bool = True) -> np.ndarray:
    """Wall particles of a rectangular tank whose inner (wetted) box is ``inner_lo``..
    ``inner_hi`` [m]: ``layers`` layers [-] on the bottom and the sides (and the lid unless
    ``open_top``); the side walls rise to the inner top ``inner_hi[-1]``."""
    if int(layers) != layers or layers < 1:
        raise InputError(f"a tank needs at least one wall layer, got layers={layers}")
    lo = np.asarray(inner_lo, np.float64)
    hi = np.asarray(inner_hi, np.float64)
    t = layers * dx
    olo = lo - t
    ohi = hi + t
    if open_top:
        ohi[-1] = hi[-1]
    pts = block(olo, ohi, dx)
    inside = np.all((pts > lo) & (pts < hi), axis=1)
    return pts[~inside]


@dataclass(frozen=True)
class Built:
    """A particle set and what the builder had to drop."""

    particles: ParticleSet
    removed_overlap: int  # fluid particles removed because they overlapped a wall


def assemble(dim: int, dx: float, rho0: float, fluid, walls=(), clearance: float = 0.9,
             volume=None) -> Built:
    """Join fluid points and walls into one :class:`ParticleSet` with ``m = rho0 dx^dim``
    (times the fluid points' ``volume`` factors [-], one each, where given).

    fluid: (N, dim) points or a list of them; walls: list of ``(points, kind, group)``.
    Fluid particles closer than ``clearance * dx`` [-] to any wall particle overlap the wall:
    they are removed, counted and logged. A lattice-aligned fluid particle next to a wall is
    exactly ``dx`` away and kept; one inside a wall region is at most ``sqrt(dim)/2 dx`` away
    from a wall particle and removed.
    """
    fl = np.concatenate([np.atleast_2d(f) for f in (fluid if isinstance(fluid, list) else [fluid])])
    if fl.shape[1] != dim:
        raise InputError(f"fluid points have {fl.shape[1]} components, expected dim={dim}")
    m = rho0 * dx**dim
    fm = np.full(len(fl), m) if volume is None else m * np.asarray(volume, np.float64)
    sets = []
    removed = 0
    if walls:
        wp = np.concatenate([np.asarray(w[0], np.float64) for w in walls])
        d, _ = cKDTree(wp).query(fl, k=1, distance_upper_bound=clearance * dx)
        keep = ~np.isfinite(d) | (d >= clearance * dx)
        removed = int((~keep).sum())
        fl, fm = fl[keep], fm[keep]
        if removed:
            log.info("removed %d fluid particles overlapping walls", removed)
    sets.append(ParticleSet.create(fl, rho0, fm))
    for pts, kind, group in walls:
        if Kind(kind) == Kind.FLUID:
            raise InputError("a wall cannot be of kind FLUID")
        sets.append(ParticleSet.create(pts, rho0, m, kind=int(kind), group=int(group)))
    return Built(ParticleSet.concatenate(sets), removed)


def set_hydrostatic(ps: ParticleSet, z_surface: float, rho0: float, c0: float, gamma: float,
                    g) -> None:
    """Give every particle the Tait density of the hydrostatic pressure ``rho0 |g| (z_s -
    z)`` (``z_surface`` [m], ``c0`` [m/s]); above the surface rho0. ``g`` [m/s^2]: a number
    (along -z; ``z`` the height), or gravity's vector (``dim``,), ``z`` then the height along
    -g and ``z_surface`` the free surface's (a plane normal to gravity)."""
    g = np.asarray(g, float)
    if g.ndim == 0:
        ps.rho[:] = hydrostatic_density(z_surface - ps.pos[:, -1], rho0, c0, gamma, float(g))
        return
    size = float(np.linalg.norm(g))
    ps.rho[:] = hydrostatic_density(z_surface - height_along(ps.pos, g), rho0, c0, gamma, size)


def height_along(points: np.ndarray, gravity) -> np.ndarray:
    """The height [m] of each point (N, dim) against ``gravity`` (dim,) [m/s^2]: its
    coordinate along -g / |g| (the z coordinate where gravity acts along -z)."""
    g = np.asarray(gravity, float)
    return -(np.asarray(points, float) @ g) / float(np.linalg.norm(g))


def water_under_gravity(candidates: np.ndarray, count: int, gravity) -> tuple[np.ndarray, float]:
    """The water of a tank at rest under a tilted ``gravity`` (dim,) [m/s^2]: the ``count``
    points of ``candidates`` (N, dim; a lattice filling the tank) lowest against gravity
    (:func:`height_along`), i.e. the same amount of water as a level fill of ``count``
    particles with its free surface turned normal to gravity; and that surface's height
    along -g [m]: midway between the highest point kept and the lowest left out (the level
    between the top row and the one above it, for gravity along -z)."""
    if not 0 < count < len(candidates):
        raise InputError(f"water under gravity: {count} particles from {len(candidates)} lattice points; the "
                         "tank must hold more points than the water")
    up = height_along(candidates, gravity)
    order = np.argsort(up, kind="stable")
    keep = np.sort(order[:count])
    return candidates[keep], 0.5 * float(up[order[count - 1]] + up[order[count]])


def lattice_extent(size: float, dx: float) -> float:
    """The extent [m] of the lattice columns (spacing ``dx`` [m], centres at ``(i + 1/2)
    dx``) that lie strictly inside ``0 .. size`` [m]: ``size`` rounded to a whole number of
    spacings (a half spacing rounds down), the tank's length as its walls and water build
    it."""
    return max(math.ceil(size / dx - 0.5 - 1e-9), 0) * dx


def tank_with_water(dim: int, dx: float, length: float, depth: float, height: float,
                    width: float = 0.0, layers: int = 3, rho0: float = 1000.0) -> Built:
    """A rectangular open tank, inner corner at the origin: ``length`` [m] along x, ``width``
    [m] along y (3-D only), wall ``height`` [m], filled with water to ``depth`` [m]. The
    walls are group 0, kind FIXED_WALL.

    Water and walls share one lattice: the water fills every lattice column inside the
    walls, so a length (width) that is not a whole number of spacings is built as
    :func:`lattice_extent` of it (the nearest whole number; the water's top, in whole rows
    from the floor, is left as :func:`block` lays it). Filling whole columns only up to the
    length would leave the column next to the far wall empty where the length exceeds a
    whole number by more than half a spacing: the water at rest falls into it and turns
    over the whole tank."""
    if dim == 3 and not width > 0:
        raise InputError("a 3-D tank needs a width > 0 m along y")
    if not 0 < depth <= height:
        raise InputError(f"the water depth {depth} m must lie in (0, height={height} m]")
    lo = np.zeros(dim)
    hi = np.array([length, height] if dim == 2 else [length, width, height])
    hi[:-1] = [lattice_extent(x, dx) for x in hi[:-1]]
    top = hi.copy()
    top[-1] = depth
    walls = tank_walls(lo, hi, dx, layers)
    return assemble(dim, dx, rho0, block(lo, top, dx), [(walls, Kind.FIXED_WALL, 0)])
