"""Boundary particles of bodies: sampled from their geoms, placed rigidly.

Dynamic boundary particles (Barreiro et al. 2016, §2.6) fill a band ``layers × dx`` deep
inside each geom's surface (box, sphere, cylinder, capsule, ellipsoid, or a
closed triangle mesh), on a lattice of spacing ``dx`` in the geom's own
frame (cell-centred, so the outer layer sits half a spacing inside the surface,
as the fluid's own particles sit inside their cells); a cylinder's section (from a
radius of a spacing) is laid in rings instead (:func:`disc_rings`), whose points carry the
disc's area at every spacing. They are stored once in body coordinates and placed every
step by the rigid transform of the body's pose, with velocities ``u = V + Ω × (r − r_com)``
(Barreiro et al. 2016, Eq. 13), so they never drift. Plain numpy, no MuJoCo: the geometry
here also serves the analytic fluid.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from errors import InputError


class GeomShape(NamedTuple):
    """A geom in its body's frame (the frame of ``BodyKinematics.origin``)."""

    kind: str  #: "box", "sphere", "cylinder", "capsule", "ellipsoid", "mesh"
    size: np.ndarray  #: MuJoCo size [m]: box half-sizes, sphere radius, cylinder/capsule radius and half-length
    pos: np.ndarray  #: centre [m], (3,)
    rot: np.ndarray  #: orientation, (3, 3): p_body = pos + rot p_geom
    #: a mesh geom's ``(vertices [m] (nv, 3), faces (nf, 3) vertex indices)`` in the geom
    #: frame (a closed triangle surface, see :func:`check_mesh`); None for the other kinds
    mesh: tuple | None = None


class BodyKinematics(NamedTuple):
    """World-frame state of the coupled bodies, arrays with one row per body."""

    com: np.ndarray  #: centre of mass [m], (n, 3)
    origin: np.ndarray  #: body frame origin [m], (n, 3)
    rotation: np.ndarray  #: body frame orientation, (n, 3, 3): p_w = origin + R p_b
    velocity: np.ndarray  #: velocity of the centre of mass [m/s], (n, 3)
    omega: np.ndarray  #: angular velocity [rad/s], (n, 3)


def signed_distance(kind: str, size: np.ndarray, p: np.ndarray, mesh: tuple | None = None) -> np.ndarray:
    """Signed distance [m] from points ``p`` (geom frame, (n, 3)) to the geom's
    surface, negative inside (exact for box, sphere, cylinder, capsule and mesh; a
    first-order estimate for an ellipsoid, exact on its surface). A mesh needs
    ``mesh = (vertices, faces)`` (see :class:`GeomShape`)."""
    if kind == "mesh":
        if mesh is None:
            raise InputError("boundary particles: a mesh geom needs its (vertices, faces); give GeomShape.mesh")
        return mesh_signed_distance(mesh[0], mesh[1], p)
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
                     f"capsule, ellipsoid or mesh)")


def check_mesh(vertices, faces, name: str = "mesh") -> tuple[np.ndarray, np.ndarray]:
    """``(vertices (nv, 3) float, faces (nf, 3) int)`` of a closed triangle surface,
    or an :class:`InputError` saying what is wrong. Closed: every edge is shared by
    exactly two faces, which run along it in opposite directions (a consistently
    oriented surface, so that inside and outside are defined); every face has an area."""
    v = np.asarray(vertices, float)
    f = np.asarray(faces)
    if v.ndim != 2 or v.shape[1] != 3 or f.ndim != 2 or f.shape[1] != 3 or len(f) == 0:
        raise InputError(f"boundary particles: {name} needs vertices (n, 3) and triangular faces (m, 3) as vertex "
                         f"indices; got shapes {v.shape} and {f.shape}")
    if not np.isfinite(v).all() or f.min() < 0 or f.max() >= len(v):
        raise InputError(f"boundary particles: {name} has non-finite vertices or face indices outside 0..{len(v) - 1}")
    f = f.astype(np.int64)
    e = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])  # directed edges
    und, counts = np.unique(np.sort(e, axis=1), axis=0, return_counts=True)
    if (counts != 2).any():
        bad = und[counts != 2][0]
        raise InputError(f"boundary particles: {name} is not a closed surface ({int((counts != 2).sum())} edges are "
                         f"not shared by exactly two faces, e.g. vertices {bad[0]}-{bad[1]}): the fluid needs an "
                         f"inside; close the mesh (or let MuJoCo use its convex hull: give vertices only)")
    if len(np.unique(e, axis=0)) != len(e):
        raise InputError(f"boundary particles: {name}'s faces are not consistently oriented (an edge runs the same "
                         f"way in two faces); orient every face's vertices the same way round, e.g. counter-"
                         f"clockwise seen from outside")
    area = np.linalg.norm(np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]), axis=1)
    flat = area <= 1e-12 * max(float(np.ptp(v, axis=0).max()), 1e-300) ** 2
    if flat.any():
        raise InputError(f"boundary particles: {name} has {int(flat.sum())} face(s) of zero area; "
                         f"remove the degenerate triangles")
    return v, f


def mesh_volume(vertices, faces) -> float:
    """Volume [m^3] enclosed by a closed triangle surface (:func:`check_mesh`): the
    divergence theorem, ``V = |sum_f a . (b x c)| / 6`` over the faces' corners."""
    v, f = np.asarray(vertices, float), np.asarray(faces, np.int64)
    return float(abs(np.einsum("fi,fi->", v[f[:, 0]], np.cross(v[f[:, 1]], v[f[:, 2]]))) / 6.0)


def mesh_signed_distance(vertices: np.ndarray, faces: np.ndarray, p: np.ndarray,
                         cut_axis: int | None = None) -> np.ndarray:
    """Signed distance [m] from points ``p`` (n, 3) to a closed triangle surface
    (see :func:`check_mesh`), negative inside. The distance is the exact least distance
    to the triangles (to the plane where the foot lies in the triangle, else to its
    nearest edge); the sign is the generalised winding number (Jacobson, Kavan &
    Sorkine-Hornung 2013, ACM TOG 32(4) 33, Eq. 5: ``w = sum Omega_f / 4 pi`` with the
    solid angle of each triangle from Van Oosterom & Strackee 1983, IEEE TBME 30(2) 125,
    ``tan(Omega/2) = a.(b x c) / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|)``), inside
    where ``|w| > 1/2`` (either orientation). ``cut_axis``: the distance leaves out the
    faces whose normal lies along this geom axis (the end caps of a body extruded along
    it, cut away by a 2-D section, as a box's faces are in :func:`_section_distance`)."""
    v, f = np.asarray(vertices, float), np.asarray(faces, np.int64)
    p = np.asarray(p, float)
    A, B, C = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    nrm = np.cross(B - A, C - A)
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    use = np.ones(len(f), bool) if cut_axis is None else np.abs(nrm[:, cut_axis]) < 1.0 - 1e-9
    out = np.empty(len(p))
    chunk = max(1, 2_000_000 // len(f))
    for s in range(0, len(p), chunk):
        q = p[s:s + chunk, None, :]  # (k, 1, 3)
        a, b, c = A[None] - q, B[None] - q, C[None] - q  # corners relative to the points
        la, lb, lc = (np.linalg.norm(x, axis=2) for x in (a, b, c))
        det = np.einsum("kfi,kfi->kf", a, np.cross(b, c))
        den = (la * lb * lc + np.einsum("kfi,kfi->kf", a, b) * lc + np.einsum("kfi,kfi->kf", b, c) * la
               + np.einsum("kfi,kfi->kf", c, a) * lb)
        wind = np.arctan2(det, den).sum(axis=1) / (2.0 * np.pi)  # sum Omega / 4 pi, Omega = 2 atan2
        # unsigned distance: plane distance where the foot is inside the triangle, else edges
        h = -np.einsum("kfi,fi->kf", a, nrm)  # height of the point above each face plane
        foot = -a - h[..., None] * nrm[None]  # foot of the perpendicular, relative to A
        e0, e1, e2 = B - A, C - B, A - C
        inside = ((np.einsum("kfi,fi->kf", np.cross(e0[None], foot), nrm) >= 0)
                  & (np.einsum("kfi,fi->kf", np.cross(e1[None], foot - e0[None]), nrm) >= 0)
                  & (np.einsum("kfi,fi->kf", np.cross(e2[None], foot + e2[None]), nrm) >= 0))
        d = np.where(inside, np.abs(h), np.inf)
        for start, edge in ((a, e0), (b, e1), (c, e2)):  # segment from the corner along the edge
            t = np.clip(-np.einsum("kfi,fi->kf", start, edge) / np.einsum("fi,fi->f", edge, edge), 0.0, 1.0)
            d = np.minimum(d, np.linalg.norm(start + t[..., None] * edge[None], axis=2))
        d = np.where(use[None], d, np.inf).min(axis=1)
        out[s:s + chunk] = np.where(np.abs(wind) > 0.5, -d, d)
    return out


def half_extents(kind: str, size: np.ndarray, mesh: tuple | None = None) -> np.ndarray:
    """Half-sizes [m] of the geom's bounding box along its own axes, centred on the
    geom's origin (a mesh: the largest vertex coordinate each way)."""
    if kind == "mesh":
        return np.abs(np.asarray(mesh[0], float)).max(axis=0)
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


def disc_rings(radius: float, dx: float) -> np.ndarray:
    """Points ``(n, 2)`` [m] filling a disc of ``radius`` [m] on concentric rings, each
    point standing for ``dx^2`` of it, so that a layer of them carries the disc's area.

    Why: a cylinder's section laid on the square lattice keeps the cells whose centres lie
    inside, ``pi R^2 / dx^2`` only on average: +3.5 % at R/dx = 4 and 8, +13 % at 3, +18 %
    at 3.75, -1 % at 6. A body's dynamic boundary particles carry the fluid's pressure in
    proportion to their number, so a body on its bottom cap floats on that area: the
    wind-turbine base's draft was short by as much (docs/validation/nearfield.md,
    "A cylinder's section in rings"). Ring ``k`` (0 the outermost) lies at ``r_k = R -
    (k + 1/2) dr`` with ``dr = R / max(1, round(R / dx))`` (the rings a spacing apart, the
    outermost half of one inside the surface, as the lattice's outer layer) and holds
    ``m_k`` points at angles ``2 pi (j + 1/2) / m_k``, its annulus' area over ``dx^2``
    rounded so that the rings out to it hold their area's count to the nearest whole: the
    layer holds ``round(pi R^2 / dx^2)`` points (within 1.8 % of the area from R/dx = 3,
    1 % from 4), the points about ``dx^2 / dr`` apart along a ring. The points are
    symmetric about the plane y = 0 (a symmetry plane through the axis takes the half on
    its side)."""
    nr = max(1, int(round(radius / dx)))
    dr = radius / nr
    rings, placed = [], 0
    for k in range(nr):
        r = radius - (k + 0.5) * dr
        # the area out to this ring's inner edge, rounded: each ring takes what its own
        # rounding leaves, so the counts' errors do not add up
        m = max(1, int(round(math.pi * (radius**2 - (radius - (k + 1) * dr) ** 2) / dx**2)) - placed)
        placed += m
        a = (np.arange(m) + 0.5) * (2.0 * math.pi / m)
        rings.append(np.column_stack([r * np.cos(a), r * np.sin(a)]))
    return np.concatenate(rings)


def particles_across(g: GeomShape, dx: float, dim: int = 3):
    """The geom's axes that :func:`sample_geoms` lays its lattice along (in 2-D the two in
    the section plane, the axis along the body's y left out), the geom's extent along
    each [m] (its bounding box; a mesh's own, which need not be centred on the geom
    origin) and the number of particles across it there, ``max(1, round(extent /
    dx))``, what :func:`sample_geoms` lays across a box of that extent."""
    if g.kind == "mesh":  # its own bounding box (not centred on the geom origin)
        full = np.ptp(np.asarray(g.mesh[0], dtype=float), axis=0)
    else:
        full = 2.0 * half_extents(g.kind, np.asarray(g.size, dtype=float))
    axes = np.arange(3)
    if dim == 2:
        along_y = np.flatnonzero(np.isclose(np.abs(np.asarray(g.rot)[1]), 1.0))
        if along_y.size == 1:
            axes = axes[axes != along_y[0]]
    extent = full[axes]
    return axes, extent, np.maximum(1, np.round(extent / dx).astype(int))


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
        if g.kind == "mesh":
            check_mesh(*(g.mesh or (None, None)), name=f"geom {gi} (mesh)")
        half = half_extents(g.kind, size, g.mesh)
        axes = [_axis_grid(h, dx) for h in half]
        if dim == 2:
            along_y = np.flatnonzero(np.isclose(np.abs(g.rot[1]), 1.0))
            if along_y.size != 1:
                raise InputError(f"boundary particles: a planar body's geom {gi} ({g.kind}) has no axis along y; "
                                 f"2-D sampling cuts geoms by the x-z plane")
            axes[along_y[0]] = np.array([-g.pos[1] * g.rot[1, along_y[0]]])  # the y = 0 plane of the body
        # a cylinder's section a disc: rings, from a radius of a spacing (below it a disc of
        # two points would lie on one line through the axis, one particle across the other
        # way, which the lattice's 2 x 2 does not)
        if g.kind == "cylinder" and (dim == 3 or along_y[0] == 2) and size[0] >= dx:
            xy = disc_rings(size[0], dx)
            p = np.concatenate([np.column_stack([xy, np.full(len(xy), z)]) for z in axes[2]])
        else:
            p = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
        sd = (signed_distance(g.kind, size, p, g.mesh) if dim == 3
              else _section_distance(g.kind, size, p, along_y[0], g.mesh))
        keep = (sd <= 0.0) & (sd > -layers * dx)
        pts.append(g.pos + p[keep] @ g.rot.T)
        owner.append(np.full(int(keep.sum()), gi))
    points = np.concatenate(pts) if pts else np.zeros((0, 3))
    if dim == 2:
        points[:, 1] = 0.0
    return points, np.concatenate(owner) if owner else np.zeros(0, int)


def _section_distance(kind, size, p, axis, mesh=None):
    """Signed distance within the section of a geom by its mid-plane normal to
    geom axis ``axis`` (points ``p`` lie in that plane). Restricting the 3-D
    distance to the plane is exact except where the depth would be measured to the
    faces cut away (a box's, a mesh's faces normal to the axis, or an end-on
    cylinder's flat ends)."""
    if kind == "mesh":
        return mesh_signed_distance(mesh[0], mesh[1], p, cut_axis=axis)
    if kind == "box":
        s = size[:3].copy()
        s[axis] = np.inf
        return signed_distance("box", s, p)
    if kind == "cylinder" and axis == 2:  # seen end-on: a disc
        return np.hypot(p[:, 0], p[:, 1]) - size[0]
    return signed_distance(kind, size, p)


def _cylinder_rim_ghosts(size, p: np.ndarray, sd: np.ndarray, ghost: np.ndarray) -> np.ndarray:
    """The ghost offsets ``ghost`` (n, 3) [m], geom frame, of the particles ``p`` in a
    cylinder (``size`` = radius, half-length; ``sd`` their signed distances), with those of
    the particles as deep under its side as under an end replaced by their mirror images
    across the side. Why: on that tie the signed distance's gradient is the bisector of
    the two normals, and :func:`disc_rings` puts ring k of the k-th layer from an end on it
    (76 of the 200 particles of the wind-turbine base's hull at R = 4 dx). Mirrored along
    the bisector, or through the rim as a box's edge, those ghosts made the hull forced in
    heave radiate more than on the square lattice, whose particles there lay nearer the
    side and mirrored across it; mirrored across the side they radiate as the lattice's did
    (docs/validation/nearfield.md, "The rings' ghost nodes at the rim")."""
    r = np.hypot(p[:, 0], p[:, 1])
    q_side, q_end = r - size[0], np.abs(p[:, 2]) - size[1]
    tie = (sd <= 0) & (r > 0) & (np.abs(q_side - q_end) <= 1e-9 * max(size[0], size[1], 1.0))
    out = ghost.copy()
    out[tie, :2] = -2.0 * q_side[tie, None] * p[tie, :2] / r[tie, None]
    out[tie, 2] = 0.0
    return out


def ghost_offsets(geoms, points: np.ndarray, dim: int = 3) -> np.ndarray:
    """Vectors [m] (n, 3), body frame, from each boundary particle (``points``, body
    coordinates, e.g. from :func:`sample_geoms`) to its ghost node: its mirror image
    across the nearest surface of the body (modified dynamic boundaries, English et
    al. 2022, Comp. Part. Mech. 9: 911-925, §3). The particle's geom is the one it
    lies deepest in (exact for one geom and for geoms that do not overlap). A box
    reflects the particle across every face at the least depth, so that particles
    on a corner diagonal mirror through the corner; a cylinder mirrors a particle as
    deep under its side as under an end across the side; other shapes mirror along the
    gradient of the signed distance (radial for spheres, cylinders, capsules; for a mesh
    the nearest face's normal, and on a tie between faces, e.g. a particle on the
    diagonal of a mesh box's edge or corner, their bisector: mirrored 2 d along it, where
    a box geom mirrors it through the edge or corner, 2 sqrt(2) d or 2 sqrt(3) d)."""
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
            dist = lambda q, ax=ax: _section_distance(g.kind, size, q, ax, g.mesh)
        else:
            ax = -1
            dist = lambda q: signed_distance(g.kind, size, q, g.mesh)
        sd = dist(p)
        if g.kind == "box":
            half = size[:3].copy()
            if ax >= 0:
                half[ax] = np.inf
            q = np.abs(p) - half  # per-axis signed depth; the largest is the nearest face
            near = q >= sd[:, None] - 1e-9 * max(half[np.isfinite(half)].max(), 1.0)
            ghost_g = -2.0 * np.where(near, q, 0.0) * np.sign(p)
        else:
            eps = 1e-6 * max(float(half_extents(g.kind, size, g.mesh).max()), 1e-9)
            grad = np.zeros_like(p)
            for k in range(3):
                if k == ax:
                    continue
                e = np.zeros(3)
                e[k] = eps
                grad[:, k] = (dist(p + e) - dist(p - e)) / (2 * eps)
            norm = np.linalg.norm(grad, axis=1, keepdims=True)
            ghost_g = -2.0 * sd[:, None] * grad / np.where(norm > 0, norm, 1.0)
            if g.kind == "cylinder" and ax != 2:
                ghost_g = _cylinder_rim_ghosts(size, p, sd, ghost_g)
        take = sd < best
        best = np.where(take, sd, best)
        out[take] = ghost_g[take] @ g.rot.T  # back to the body frame
    if dim == 2:
        out[:, 1] = 0.0
    return out


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise ``a × b`` of ``(n, 3)`` arrays: ``np.cross``'s products and differences in its
    order (the same bits), without its axis moves and checks, which cost more than the
    products on the few rows of a step's bodies, fairleads and boundary particles."""
    out = np.empty((max(len(a), len(b)), 3))  # one row broadcasts against many
    out[:, 0] = a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1]
    out[:, 1] = a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2]
    out[:, 2] = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    return out


def place(points_b: np.ndarray, owner: np.ndarray, kin: BodyKinematics):
    """World positions [m] and velocities [m/s] of particles stored in body
    coordinates: ``x = origin + R p``, ``u = V + Ω × (x − r_com)`` (Barreiro et al. 2016, Eq. 13)."""
    R = kin.rotation[owner]
    x = kin.origin[owner] + np.einsum("nij,nj->ni", R, points_b)
    u = kin.velocity[owner] + cross(kin.omega[owner], x - kin.com[owner])
    return x, u
