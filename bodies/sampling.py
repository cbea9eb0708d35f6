"""Boundary particles of bodies: sampled from their geoms, placed rigidly.

Dynamic boundary particles (seed 004 §2.6) fill a band ``layers × dx`` deep
inside each geom's surface, on a lattice of spacing ``dx`` in the geom's own
frame (cell-centred, so the outer layer sits half a spacing inside the surface,
as the fluid's own particles sit inside their cells). They are stored once in
body coordinates and placed every step by the rigid transform of the body's pose,
with velocities ``u = V + Ω × (r − r_com)`` (seed 004 Eq. 13), so they never
drift. Plain numpy, no MuJoCo: the geometry here also serves the analytic fluid.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from cosim.errors import InputError


class GeomShape(NamedTuple):
    """A geom in its body's frame (the frame of ``BodyKinematics.origin``)."""

    kind: str  #: "box", "sphere", "cylinder", "capsule", "ellipsoid"
    size: np.ndarray  #: MuJoCo size [m]: box half-sizes, sphere radius, cylinder/capsule radius and half-length
    pos: np.ndarray  #: centre [m], (3,)
    rot: np.ndarray  #: orientation, (3, 3): p_body = pos + rot p_geom


class BodyKinematics(NamedTuple):
    """World-frame state of the coupled bodies, arrays with one row per body."""

    com: np.ndarray  #: centre of mass [m], (n, 3)
    origin: np.ndarray  #: body frame origin [m], (n, 3)
    rotation: np.ndarray  #: body frame orientation, (n, 3, 3): p_w = origin + R p_b
    velocity: np.ndarray  #: velocity of the centre of mass [m/s], (n, 3)
    omega: np.ndarray  #: angular velocity [rad/s], (n, 3)


def signed_distance(kind: str, size: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Signed distance [m] from points ``p`` (geom frame, (n, 3)) to the geom's
    surface, negative inside (exact for box, sphere, cylinder and capsule; a
    first-order estimate for an ellipsoid, exact on its surface)."""
    if kind == "box":
        q = np.abs(p) - size[:3]
        return np.linalg.norm(np.maximum(q, 0.0), axis=1) + np.minimum(q.max(axis=1), 0.0)
    if kind == "sphere":
        return np.linalg.norm(p, axis=1) - size[0]
    if kind == "cylinder":
        d = np.stack([np.hypot(p[:, 0], p[:, 1]) - size[0], np.abs(p[:, 2]) - size[1]], axis=1)
        return np.linalg.norm(np.maximum(d, 0.0), axis=1) + np.minimum(d.max(axis=1), 0.0)
    if kind == "capsule":
        z = np.clip(p[:, 2], -size[1], size[1])
        return np.linalg.norm(p - np.stack([0 * z, 0 * z, z], axis=1), axis=1) - size[0]
    if kind == "ellipsoid":
        r = size[:3]
        k0 = np.linalg.norm(p / r, axis=1)
        k1 = np.linalg.norm(p / r**2, axis=1)
        return np.where(k1 > 0, k0 * (k0 - 1.0) / np.where(k1 > 0, k1, 1.0), -r.min())
    raise InputError(f"boundary particles: geom type {kind!r} cannot be sampled (use box, sphere, cylinder, "
                     f"capsule or ellipsoid)")


def half_extents(kind: str, size: np.ndarray) -> np.ndarray:
    """Half-sizes [m] of the geom's bounding box along its own axes."""
    if kind in ("box", "ellipsoid"):
        return size[:3].copy()
    if kind == "sphere":
        return np.full(3, size[0])
    if kind == "cylinder":
        return np.array([size[0], size[0], size[1]])
    return np.array([size[0], size[0], size[1] + size[0]])  # capsule


def _axis_grid(half: float, dx: float) -> np.ndarray:
    """Cell-centred coordinates across [-half, half], spacing as close to dx as fits."""
    n = max(1, int(round(2.0 * half / dx)))
    return (np.arange(n) + 0.5) * (2.0 * half / n) - half


def sample_geoms(geoms, dx: float, layers: int, dim: int = 3):
    """Boundary particles of a body's geoms, in body coordinates.

    Parameters
    ----------
    geoms:
        The body's :class:`GeomShape` list.
    dx:
        Particle spacing [m] (the fluid's).
    layers:
        Number of particle layers inside the surface (>= 1).
    dim:
        3, or 2 for a planar body: the section by the body's y = 0 plane, which
        needs each geom to have one axis along the body's y axis.

    Returns
    -------
    points (n, 3) [m] in body coordinates and the index of the geom of each.
    """
    if not (np.isfinite(dx) and dx > 0):
        raise InputError(f"boundary particles: dx must be finite and > 0, got {dx!r}")
    if int(layers) != layers or layers < 1:
        raise InputError(f"boundary particles: layers must be a whole number >= 1, got {layers!r}")
    if dim not in (2, 3):
        raise InputError(f"boundary particles: dim must be 2 or 3, got {dim!r}")
    pts, owner = [], []
    for gi, g in enumerate(geoms):
        size = np.asarray(g.size, dtype=float)
        half = half_extents(g.kind, size)
        axes = [_axis_grid(h, dx) for h in half]
        if dim == 2:
            along_y = np.flatnonzero(np.isclose(np.abs(g.rot[1]), 1.0))
            if along_y.size != 1:
                raise InputError(f"boundary particles: a planar body's geom {gi} ({g.kind}) has no axis along y; "
                                 f"2-D sampling cuts geoms by the x-z plane")
            axes[along_y[0]] = np.array([-g.pos[1] * g.rot[1, along_y[0]]])  # the y = 0 plane of the body
        p = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
        sd = signed_distance(g.kind, size, p) if dim == 3 else _section_distance(g.kind, size, p, along_y[0])
        keep = (sd <= 0.0) & (sd > -layers * dx)
        pts.append(g.pos + p[keep] @ g.rot.T)
        owner.append(np.full(int(keep.sum()), gi))
    points = np.concatenate(pts) if pts else np.zeros((0, 3))
    if dim == 2:
        points[:, 1] = 0.0
    return points, np.concatenate(owner) if owner else np.zeros(0, int)


def _section_distance(kind, size, p, axis):
    """Signed distance within the section of a geom by its mid-plane normal to
    geom axis ``axis`` (points ``p`` lie in that plane). Restricting the 3-D
    distance to the plane is exact except where the depth would be measured to the
    faces cut away (a box's, or an end-on cylinder's flat ends)."""
    if kind == "box":
        s = size[:3].copy()
        s[axis] = np.inf
        return signed_distance("box", s, p)
    if kind == "cylinder" and axis == 2:  # seen end-on: a disc
        return np.hypot(p[:, 0], p[:, 1]) - size[0]
    return signed_distance(kind, size, p)


def ghost_offsets(geoms, points: np.ndarray, dim: int = 3) -> np.ndarray:
    """Vectors [m] (n, 3), body frame, from each boundary particle (``points``, body
    coordinates, e.g. from :func:`sample_geoms`) to its ghost node: its mirror image
    across the nearest surface of the body (modified dynamic boundaries, English et
    al. 2022, Comp. Part. Mech. 9: 911-925, §3). The particle's geom is the one it
    lies deepest in (exact for one geom and for geoms that do not overlap). A box
    reflects the particle across every face at the least depth, so that particles
    on a corner diagonal mirror through the corner; other shapes mirror along the
    gradient of the signed distance (radial for spheres, cylinders, capsules)."""
    points = np.asarray(points, float)
    best = np.full(len(points), np.inf)
    out = np.zeros((len(points), 3))
    for gi, g in enumerate(geoms):
        size = np.asarray(g.size, dtype=float)
        p = (points - g.pos) @ g.rot  # geom frame
        if dim == 2:
            along_y = np.flatnonzero(np.isclose(np.abs(g.rot[1]), 1.0))
            if along_y.size != 1:
                raise InputError(f"ghost nodes: a planar body's geom {gi} ({g.kind}) has no axis along y")
            ax = int(along_y[0])
            dist = lambda q, ax=ax: _section_distance(g.kind, size, q, ax)
        else:
            ax = -1
            dist = lambda q: signed_distance(g.kind, size, q)
        sd = dist(p)
        if g.kind == "box":
            half = size[:3].copy()
            if ax >= 0:
                half[ax] = np.inf
            q = np.abs(p) - half  # per-axis signed depth; the largest is the nearest face
            near = q >= sd[:, None] - 1e-9 * max(half[np.isfinite(half)].max(), 1.0)
            ghost_g = -2.0 * np.where(near, q, 0.0) * np.sign(p)
        else:
            eps = 1e-6 * max(float(size.max()), 1e-9)
            grad = np.zeros_like(p)
            for k in range(3):
                if k == ax:
                    continue
                e = np.zeros(3)
                e[k] = eps
                grad[:, k] = (dist(p + e) - dist(p - e)) / (2 * eps)
            norm = np.linalg.norm(grad, axis=1, keepdims=True)
            ghost_g = -2.0 * sd[:, None] * grad / np.where(norm > 0, norm, 1.0)
        take = sd < best
        best = np.where(take, sd, best)
        out[take] = ghost_g[take] @ g.rot.T  # back to the body frame
    if dim == 2:
        out[:, 1] = 0.0
    return out


def place(points_b: np.ndarray, owner: np.ndarray, kin: BodyKinematics):
    """World positions [m] and velocities [m/s] of particles stored in body
    coordinates: ``x = origin + R p``, ``u = V + Ω × (x − r_com)`` (seed 004 Eq. 13)."""
    R = kin.rotation[owner]
    x = kin.origin[owner] + np.einsum("nij,nj->ni", R, points_b)
    u = kin.velocity[owner] + np.cross(kin.omega[owner], x - kin.com[owner])
    return x, u
