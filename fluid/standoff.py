"""Fluid lattice points fitted to a body's flat faces: the first row half a spacing off
the face, the rows below stretched to meet it and their particles given the mass of
the water they stand for.

Why: an SPH fluid at rest next to a boundary keeps the standoff it started with (the
pressure under a face rises until the kernel's thinner overlap across a wider gap holds
the water back), so a body held at rest carries the weight of every fluid cell missing
around it, not of its own volume: ``F = rho g V_hole``, ``V_hole`` the region no fluid
cell covers. Removing the cells that reach into a body (``cosim.sph_fluid``) leaves the
first row ``s1`` in [dx/2, 3dx/2) off a face, so a face lying between lattice planes
carries ``rho g (s1 - dx/2) A`` too much: up to a whole row, the same sign on every
particle of a face parallel to the lattice (curved faces see every phase, and the water
closes most of their gap: a free 2-D circle floats 0.16-0.21 dx high). A floating body
then settles that much high, and starts with a force far from its weight (0.5-1.3 of it,
from the kernel's overlap across the gap). Measured in docs/validation/nearfield.md ("The
static draft's offset").

What: for each planar face whose outward normal lies along a lattice axis, the fluid
points in front of it (within ``rows`` rows, over the face itself: a point beyond its
edges has water beside the body above it, which a fitted point would crowd) are fitted.
The first row is the lattice row nearest dx/2 off the face (a removed row, up to dx/2
off, is put back where it is nearer than the one left); it moves to dx/2 off, by ``e``
in (-dx/2, dx/2], and the rows behind it by ``e (1 - k / n)``, ``k`` the row (0 first),
``n = rows``, so rows ``k >= n`` stay put; each moved particle's volume, and so its mass
at the same density, is scaled by ``1 - e / (n dx)`` (within 1 -+ 1/(2n)), the stretch's
Jacobian across the face. Then ``V_hole`` is the body's own volume there. Where the
water in front of a face ends within ``rows`` rows (a free surface, a wall), ``n`` is
its last row, which stays put; a geom with water under ``MIN_ROWS`` rows deep in front
of any face is not fitted at all (fitted on some faces only, it would start with its
gaps closing on the others alone). Limits: flat faces along the lattice's axes only
(box faces, cylinder caps, turned by multiples of 90 deg).
"""

from __future__ import annotations

import numpy as np

#: rows of fluid in front of a face over which its standoff is taken up [-]
ROWS = 8
#: fewest rows that may take it: a shorter band would be stretched by more than 1/8
#: (a body within a few rows of the surface or the floor is left unfitted)
MIN_ROWS = 4


def planar_faces(kind: str, size) -> list[tuple[int, float, float, object]]:
    """The flat faces of a geom in its own frame: ``(axis, sign, half, inside)``, the
    face lying on the plane ``x[axis] = sign * half`` [m] with outward normal ``sign``
    along ``axis``, and ``inside(p) -> (n,)`` [m] how far the points' projection on the face
    lies inside its edges (negative outside). Box: six faces; cylinder: its two caps
    (MuJoCo sizes: box half-extents, cylinder radius and half-length)."""
    size = np.asarray(size, float)
    if kind == "box":
        faces = []
        for a in range(3):
            others = [b for b in range(3) if b != a]

            def inside(p, others=others):
                return np.min([size[b] - np.abs(p[:, b]) for b in others], axis=0)

            faces += [(a, 1.0, size[a], inside), (a, -1.0, size[a], inside)]
        return faces
    if kind == "cylinder":
        def cap(p):
            return size[0] - np.hypot(p[:, 0], p[:, 1])

        return [(2, 1.0, size[1], cap), (2, -1.0, size[1], cap)]
    return []


def _lines(p: np.ndarray, j: int, dx: float) -> np.ndarray:
    """Each point's line across a face along lattice axis ``j``: an index shared by the
    points with the same other two coordinates."""
    across = np.delete(p, j, axis=1)
    return np.unique(np.round(across / (1e-6 * dx)).astype(np.int64), axis=0, return_inverse=True)[1].ravel()


def _face_plan(pts, origin, rot, axis, sign, half, inside, dx, rows, clear):
    """The fit in front of one face: ``(idx, extra, k, e, n, step)`` (the points' rows,
    the rows put back, row numbers, moves, band lengths (inf: too short), the outward
    lattice step), or None where the face is not along a lattice axis or has no water."""
    normal = sign * rot[:, axis]
    j = int(np.argmax(np.abs(normal)))
    if abs(normal[j]) < 1.0 - 1e-9:  # not along a lattice axis: its rows see every phase
        return None
    tol = 1e-6 * dx
    step = np.sign(normal[j]) * np.eye(3)[j]  # outward, along the lattice axis
    p = (pts - origin) @ rot  # geom frame
    s = sign * p[:, axis] - half
    near = np.flatnonzero((s > 0.5 * dx - tol) & (s < (rows + 1.5) * dx) & (inside(p) >= -tol))
    if not len(near):
        return None
    k = np.floor((s[near] - 0.5 * dx + tol) / dx)
    s1 = s[near] - k * dx  # the first row's standoff, in [dx/2, 3dx/2)
    # the removed row in front of a first row more than dx off stood nearer dx/2: put it
    # back (then |e| <= dx/2, the stretch half as large)
    cand = np.flatnonzero((k == 0) & (s1 > dx + tol))
    if clear is not None and len(cand):  # where it would stand once fitted: dx/2 off
        cand = cand[clear(pts[near[cand]] - (s1[cand] - 0.5 * dx)[:, None] * step)]
    extra = pts[near[cand]] - dx * step  # its lattice point
    line = _lines(np.concatenate([pts[near], extra]), j, dx)
    shifted = np.zeros(line.max() + 1, bool)
    shifted[line[len(near):]] = True
    moved = shifted[line[: len(near)]]
    k = np.concatenate([k + moved, np.zeros(len(extra))])
    s1 = np.concatenate([s1 - dx * moved, s1[cand] - dx])
    last = np.full(line.max() + 1, -1.0)
    np.maximum.at(last, line, k)
    n = np.minimum(rows, last[line])  # the water may end sooner: its last row stays
    n = np.where(n >= MIN_ROWS, n, np.inf)  # too few rows to take the stretch
    return near, extra, k, 0.5 * dx - s1, n, step


def fit_to_faces(points: np.ndarray, geoms, dx: float, *, rows: int = ROWS,
                 clear=None) -> tuple[np.ndarray, np.ndarray]:
    """Fitted fluid lattice ``points`` (n, 3) [m] and each one's volume factor [-]
    (module docstring); more points than given where a removed row is put back.
    ``geoms``: ``(kind, size, origin (3,), rotation (3, 3))`` per geom, rotation taking the
    geom's frame to the world's. The points given stand at least dx/2 off every geom (the
    cells reaching in removed); ``clear(points) -> bool (n,)``: whether put-back points
    stand clear of every body (default: all). A geom with water too shallow in front of
    any of its faces to take the fit is left as it is, all faces: a body fitted on some
    faces only would start with its gaps closing on the others alone. A geom's faces are
    planned together: the water each one fits (in front of it, over it) is no other's."""
    pts = np.array(points, float)
    factor = np.ones(len(pts))
    for kind, size, origin, rot in geoms:
        plans = [pl for f in planar_faces(kind, size) if (pl := _face_plan(pts, origin, rot, *f, dx, rows, clear))]
        if any(np.isinf(pl[4]).any() for pl in plans):
            continue
        for near, extra, k, e, n, step in plans:
            idx = np.concatenate([near, len(pts) + np.arange(len(extra))])
            pts = np.concatenate([pts, extra])
            factor = np.concatenate([factor, np.ones(len(extra))])
            band = k < n
            pts[idx] += np.where(band, e * (1.0 - k / n), 0.0)[:, None] * step
            factor[idx] *= np.where(band, 1.0 - e / (n * dx), 1.0)
    return pts, factor
