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
particle of a face parallel to the lattice (curved faces see every phase and average
out). A floating body then settles that much high, and starts with a force far from
its weight (0.5-1.3 of it, from the kernel's overlap across the gap). Measured in
docs/validation/nearfield.md ("The static draft's offset").

What: for each planar face whose outward normal lies along a lattice axis, the fluid
points in front of it (within ``rows`` rows, over the face itself: a point beyond its
edges has water beside the body above it, which a fitted point would crowd) move along
the normal by ``e (1 - k / n)``, ``k`` the row (0 first), ``e = dx/2 - s1`` (<= 0:
towards the face) and ``n = rows``, so the first row stands exactly dx/2 off and rows
``k >= n`` stay put; each moved particle's volume, and so its mass at the same density,
grows by ``1 - e / (n dx)`` (<= 1 + 1/n), the stretch's Jacobian across the face. Then
``V_hole`` is the body's own volume there. Where the water in front of a face ends
within ``rows`` rows (a free surface, a wall), ``n`` is its last row, which stays put;
under ``MIN_ROWS`` rows, no fit. Limits: flat faces along the lattice's axes only (box
faces, cylinder caps, turned by multiples of 90 deg).
"""

from __future__ import annotations

import numpy as np

#: rows of fluid in front of a face over which its standoff is taken up [-]
ROWS = 8
#: fewest rows that may take it: a shorter band would be stretched by more than 1/4
#: (a body within a few rows of the surface or the floor keeps its gap there)
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


def _band(p: np.ndarray, k: np.ndarray, j: int, rows: int, dx: float) -> np.ndarray:
    """Per point, the rows its line across the face stretches over: ``rows``, or fewer
    where the water ends sooner (a free surface or a wall within the band: its last row
    there stays put, so the level and the wall's gap are kept); none where fewer than
    :data:`MIN_ROWS` would take the stretch."""
    across = np.delete(p, j, axis=1)
    _, line = np.unique(np.round(across / (1e-6 * dx)).astype(np.int64), axis=0, return_inverse=True)
    last = np.full(line.max() + 1, -1.0)
    np.maximum.at(last, line.ravel(), k)
    n = np.minimum(rows, last[line.ravel()])
    return np.where(n >= MIN_ROWS, n, 0.0)


def fit_to_faces(points: np.ndarray, geoms, dx: float, *, rows: int = ROWS) -> tuple[np.ndarray, np.ndarray]:
    """Fitted copies of fluid lattice ``points`` (n, 3) [m] and each one's volume factor
    (n,) [-] (module docstring). ``geoms``: ``(kind, size, origin (3,), rotation (3, 3))``
    per geom, rotation taking the geom's frame to the world's. Points already removed
    where the geoms' cells reach in (standoff >= dx/2)."""
    pts = np.array(points, float)
    factor = np.ones(len(pts))
    tol = 1e-6 * dx
    for kind, size, origin, rot in geoms:
        for axis, sign, half, inside in planar_faces(kind, size):
            normal = sign * rot[:, axis]
            j = int(np.argmax(np.abs(normal)))
            if abs(normal[j]) < 1.0 - 1e-9:  # not along a lattice axis: its rows see every phase
                continue
            p = (pts - origin) @ rot  # geom frame
            s = sign * p[:, axis] - half
            near = (s > 0.5 * dx - tol) & (s < (rows + 1.5) * dx) & (inside(p) >= -tol)
            if not near.any():
                continue
            k = np.floor((s[near] - 0.5 * dx + tol) / dx)
            e = 0.5 * dx - (s[near] - k * dx)  # in (-dx, 0]
            n = _band(pts[near], k, j, rows, dx)
            band = k < n
            move = np.where(band, e * (1.0 - k / np.maximum(n, 1)), 0.0)
            rows_idx = np.flatnonzero(near)
            pts[rows_idx] += move[:, None] * np.sign(normal[j]) * np.eye(3)[j]
            factor[rows_idx] *= np.where(band, 1.0 - e / (np.maximum(n, 1) * dx), 1.0)
    return pts, factor
