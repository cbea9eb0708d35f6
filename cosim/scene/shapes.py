"""The geometry of the scene's body shapes: what the checks, the floating placement, the
builder and the cost estimate ask of a body, so that none of them needs to know which
shape it is.

A rigid shape derives :class:`RigidBody` and gives :meth:`~Shape.half_size`,
:meth:`~RigidBody.signed_distance` and :meth:`~RigidBody.mjcf`; its volume, submerged
volume, extent when turned, bounding radius, surface area, radius of gyration and the
solid the overlap checks use follow from those (:class:`Shape`'s defaults), and a shape
overrides any of them where it knows it exactly. The SPH fluid samples its surface from
the geom its MJCF holds (:mod:`bodies.sampling`: box, sphere, cylinder, capsule,
ellipsoid, mesh), the analytic fluid integrates the same geom. It is registered in
:data:`cosim.scene.registry.SHAPES` (entry-point group ``cosim.shapes``).

Adding a built-in shape touches two files: its class (a frozen dataclass with its fields,
``TAG = ("shape", NAME)``, here or in its own module) and its entry in
:data:`cosim.scene.spec.BODIES`; ``docs/scenes.md`` is then regenerated. The built-in
:class:`cosim.scene.spec.Box`, ``Cylinder`` and ``Sphere`` declare their fields in
:mod:`cosim.scene.spec` and take their geometry from :class:`BoxShape`,
:class:`CylinderShape` and :class:`SphereShape` here.

Frames: a point of the body is (x, z) in 2-D (the body 1 m thick along y) and (x, y, z)
in 3-D, from its centre, upright (before ``euler`` turns it) [m]; volumes in 2-D are per
metre of depth [m^2], surface areas the section's perimeter [m].
"""

from __future__ import annotations

import math

import numpy as np

from cosim.scene import limits as L
from cosim.scene.fields import SceneError, Spec


def rotation(euler):
    """MuJoCo's rotation of the Euler angles [deg] (its default sequence, intrinsic x-y-z)."""
    a, b, c = (math.radians(x) for x in euler)
    ca, sa, cb, sb, cc, sc = math.cos(a), math.sin(a), math.cos(b), math.sin(b), math.cos(c), math.sin(c)
    rx = [[1, 0, 0], [0, ca, -sa], [0, sa, ca]]
    ry = [[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]]
    rz = [[cc, -sc, 0], [sc, cc, 0], [0, 0, 1]]

    def mul(p, q):
        return [[sum(p[i][k] * q[k][j] for k in range(3)) for j in range(3)] for i in range(3)]

    return mul(mul(rx, ry), rz)


def corners(b, dim):
    """The corners [m] of a builder body's bounding box, turned by its ``euler``, as world
    points (x, y, z); a 2-D body is 1 m thick along y."""
    half = b.half_size(dim)
    h3 = half if dim == 3 else [half[0], 0.5, half[1]]
    c = list(b.pos) if dim == 3 else [b.pos[0], 0.0, b.pos[-1]]
    r = rotation(b.euler) if b.euler is not None else [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]]
    out = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            for sz in (-1, 1):
                q = (sx * h3[0], sy * h3[1], sz * h3[2])
                out.append([c[k] + sum(r[k][j] * q[j] for j in range(3)) for k in range(3)])
    return out


def hull(points) -> list[tuple[float, float]]:
    """The convex hull of 2-D points, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(set((float(x), float(z)) for x, z in points))
    if len(pts) < 3:
        return pts

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def _turn(euler):
    return rotation(euler) if euler is not None else [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]


class Shape(Spec):
    """What every builder body (a rigid shape, an elastic plate) tells the checks."""

    #: slabs and lattice cells per axis of the default quadrature (:meth:`submerged_volume`)
    QUADRATURE = 200

    def half_size(self, dim: int) -> list[float]:
        """Half extents [m] of the upright body's bounding box along its axes."""
        raise NotImplementedError(f"{type(self).__name__}.half_size")

    def signed_distance(self, p: np.ndarray, dim: int) -> np.ndarray:
        """Signed distance [m] of the points ``p`` ``(n, dim)`` (body frame, upright) from
        the surface, negative inside (exact or a lower bound of its size outside)."""
        raise NotImplementedError(f"{type(self).__name__}.signed_distance")

    def submerged_volume(self, dim: int, draft: float) -> float:
        """Volume [m^3; 2-D m^2] of the upright body below a water line ``draft`` [m]
        above its lowest point (clipped to the body). Default: the midpoint rule over
        :attr:`QUADRATURE` slabs along z, each slab's section the cells of a lattice over
        its bounding box (:attr:`QUADRATURE` per axis in 3-D, ten times as many along x in
        2-D) whose centre has :meth:`signed_distance` < 0; linear in the draft within a
        slab. Exact for a box; a cylinder's volume within 4e-4, a sphere's 3e-5."""
        h = self.half_size(dim)
        n = self.QUADRATURE
        dz = 2 * h[-1] / n
        sections = self.__dict__.get("_sections")
        if sections is None or sections[0] != dim:
            axes = [np.linspace(-x, x, (n if dim == 3 else 10 * n) + 1) for x in h[:-1]]
            mids = [0.5 * (a[1:] + a[:-1]) for a in axes]
            grid = np.stack([g.ravel() for g in np.meshgrid(*mids, indexing="ij")], axis=1)
            cell = math.prod(2 * x / len(m) for x, m in zip(h[:-1], mids))
            area = []
            for k in range(n):
                z = -h[-1] + (k + 0.5) * dz
                p = np.column_stack([grid, np.full(len(grid), z)])
                area.append(cell * np.count_nonzero(self.signed_distance(p, dim) < 0))
            sections = (dim, np.array(area))
            object.__setattr__(self, "_sections", sections)
        wet = np.clip(draft - dz * np.arange(n), 0.0, dz)
        return float(sections[1] @ wet)

    def volume(self, dim: int) -> float:
        """Volume [m^3; 2-D m^2 per metre]."""
        return self.submerged_volume(dim, 2 * self.half_size(dim)[-1])

    def surface_area(self, dim: int) -> float:
        """Surface area [m^2; 2-D: the section's perimeter, m] (what the SPH fluid's
        boundary particles cover). Default: its bounding box's, an upper bound."""
        e = [2 * x for x in self.half_size(dim)]
        return 2 * sum(e) if dim == 2 else 2 * (e[0] * e[1] + e[1] * e[2] + e[0] * e[2])

    def bounding_radius(self, dim: int) -> float:
        """The radius [m] of the smallest sphere about its centre that holds it (default:
        its bounding box's half diagonal, an upper bound)."""
        return math.sqrt(sum(x * x for x in self.half_size(dim)))

    def gyration2(self, dim: int) -> float:
        """The smallest squared radius of gyration [m^2] about an axis through its centre,
        at uniform density (default: its bounding box's, ``(a^2 + b^2) / 12`` of two edges)."""
        e = [2 * x for x in self.half_size(dim)]
        return min(e[i] ** 2 + e[j] ** 2 for i in range(len(e)) for j in range(i + 1, len(e))) / 12.0

    def extent(self, dim: int) -> list[float]:
        """Half extents [m] along the world's axes, of its bounding box turned by its
        ``euler`` (exact along each axis for a box: the support function ``sum_j |R_kj|
        h_j``), the box itself when upright."""
        half = self.half_size(dim)
        if getattr(self, "euler", None) is None:
            return half
        r = _turn(self.euler)
        h3 = half if dim == 3 else [half[0], 0.5, half[1]]  # a 2-D body is 1 m thick along y
        e = [sum(abs(r[k][j]) * h3[j] for j in range(3)) for k in range(3)]
        return e if dim == 3 else [e[0], e[2]]

    def solid(self, dim: int, floating: bool) -> tuple:
        """The solid the overlap checks compare (:func:`cosim.scene.checks._overlap`):
        ("box", centre, half extents) upright, ("hull", its section's outline in x-z)
        turned in 2-D, ("obb", centre, rotation, half extents) turned in 3-D; floating, its
        footprint ("box" over the horizontal axes). Default: its bounding box."""
        c = list(self.pos)
        if floating:
            return ("box", c, self.extent(dim)[:dim - 1])
        if getattr(self, "euler", None) is not None:
            if dim == 2:
                return ("hull", hull([(q[0], q[2]) for q in corners(self, dim)]))
            return ("obb", c, _turn(self.euler), self.half_size(3))
        return ("box", c, self.extent(dim))

    def fit(self, dim: int) -> None:
        """Refuse (:class:`SceneError`, the path relative to the body) what does not fit a
        ``dim``-D scene; called with the scene's checks."""


class RigidBody(Shape):
    """A rigid builder body: a frozen dataclass with the fields ``name``, ``pos``,
    ``density``, ``mass``, ``place``, ``euler`` and ``fairleads`` (see
    :class:`cosim.scene.spec.Box`) besides its own sizes, ``TAG = ("shape", NAME)``."""

    #: the MuJoCo geom type of its MJCF (the potential fluid meshes "box", "cylinder", "sphere")
    geom = ""

    def validate(self):
        if (self.density is None) == (self.mass is None):
            raise SceneError("density", "give either density [kg/m^3] or mass [kg], one of the two")
        if self.place == "floating" and self.euler is not None:
            raise SceneError("euler", "a floating body is placed upright; give place = \"given\" with a full pos "
                             "to turn it")
        v = getattr(self, "velocity", None)
        if v is not None and getattr(self, "motion", None) is not None:
            raise SceneError("velocity", "a body with a prescribed motion moves as its motion says; leave velocity "
                             "out (or the motion, for a free body)")
        speed = math.hypot(*v) if v is not None else 0.0
        if speed > L.MAX_BODY_SPEED:
            raise SceneError("velocity", f"{list(v)} m/s: {speed:.4g} m/s is beyond {L.MAX_BODY_SPEED:g} "
                             f"m/s, {L.BODY_SPEED_WHY}; give the body's speed in m/s")

    def mjcf(self, pos, dim: int, sites: dict) -> str:
        """The MuJoCo ``<body>`` element of the body with its centre at ``pos`` (x, y, z)
        [m], its fairleads as the named ``sites`` (body frame, x, y, z) [m]; in 2-D it
        slides in x and z and hinges about y (:mod:`bodies.builders`)."""
        raise NotImplementedError(f"{type(self).__name__}.mjcf")

    def _common(self, sites) -> dict:
        motion = getattr(self, "motion", None)  # a forced body: one slide joint, driven (cosim.scene.build)
        return dict(density=self.density, mass=self.mass, sites=sites, slide=None if motion is None else motion.axis)


class BoxShape(RigidBody):
    """A box of edge lengths ``size`` [m]: its bounding box is itself."""

    geom = "box"

    def half_size(self, dim):
        return [0.5 * x for x in self.size]

    def signed_distance(self, p, dim):
        q = np.abs(p) - np.array(self.half_size(dim))
        return np.linalg.norm(np.maximum(q, 0.0), axis=1) + np.minimum(q.max(axis=1), 0.0)

    def volume(self, dim):
        return math.prod(self.size)

    def submerged_volume(self, dim, draft):
        return math.prod(self.size[:-1]) * min(max(draft, 0.0), self.size[-1])

    def bounding_radius(self, dim):
        return 0.5 * math.sqrt(sum(x * x for x in self.size))

    def surface_area(self, dim):
        if dim == 2:
            return 2 * (self.size[0] + self.size[1])
        x, y, z = self.size
        return 2 * (x * y + y * z + x * z)

    def fit(self, dim):
        if len(self.size) != dim:
            raise SceneError("size", f"{list(self.size)} has {len(self.size)} coordinates; a {dim}-D scene gives a "
                             f"size as {'(x, z)' if dim == 2 else '(x, y, z)'}")

    def mjcf(self, pos, dim, sites):
        from bodies import builders

        return builders.box(self.name, self.size, pos, planar=dim == 2, euler=self.euler, **self._common(sites))


class CylinderShape(RigidBody):
    """A cylinder of ``radius`` [m]: a circle in x-z in 2-D, ``length`` [m] along z in 3-D."""

    geom = "cylinder"

    def half_size(self, dim):
        r = self.radius
        return [r, r] if dim == 2 else [r, r, 0.5 * self.length]

    def signed_distance(self, p, dim):
        if dim == 2:
            return np.linalg.norm(p, axis=1) - self.radius
        d = np.stack([np.hypot(p[:, 0], p[:, 1]) - self.radius, np.abs(p[:, 2]) - 0.5 * self.length], axis=1)
        return np.linalg.norm(np.maximum(d, 0.0), axis=1) + np.minimum(d.max(axis=1), 0.0)

    def volume(self, dim):
        return math.pi * self.radius ** 2 * (1.0 if dim == 2 else self.length)

    def submerged_volume(self, dim, draft):
        """3-D, axis vertical: ``pi r^2 d``; 2-D, a circle: the segment ``r^2 acos((r - d)
        / r) - (r - d) sqrt(2 r d - d^2)`` per metre."""
        r, d = self.radius, min(max(draft, 0.0), 2 * self.half_size(dim)[-1])
        if dim == 3:
            return math.pi * r * r * d
        return r * r * math.acos((r - d) / r) - (r - d) * math.sqrt(max(2 * r * d - d * d, 0.0))

    def surface_area(self, dim):
        r = self.radius
        return 2 * math.pi * r if dim == 2 else 2 * math.pi * r * (r + self.length)

    def bounding_radius(self, dim):
        return self.radius if dim == 2 else math.hypot(self.radius, 0.5 * self.length)

    def gyration2(self, dim):
        r = self.radius
        return 0.5 * r * r if dim == 2 else min(0.5 * r * r, (3 * r * r + self.length ** 2) / 12.0)

    def extent(self, dim):
        """Turned (3-D), exact along each axis: ``L/2 |a_k| + R sqrt(1 - a_k^2)`` for its
        axis ``a``; a 2-D cylinder is a circle, turned or not."""
        if dim == 2 or self.euler is None:
            return [self.radius] * 2 if dim == 2 else self.half_size(dim)
        r = _turn(self.euler)
        return [0.5 * self.length * abs(r[k][2]) + self.radius * math.sqrt(max(0.0, 1.0 - r[k][2] ** 2))
                for k in range(3)]

    def solid(self, dim, floating):
        c = list(self.pos)
        if dim == 2:
            return ("box", c, [self.radius]) if floating else ("ball", c, self.radius)
        if floating:
            return ("ball", c, self.radius)
        if self.euler is not None:
            return ("obb", c, _turn(self.euler), self.half_size(3))
        return ("cyl", c, self.radius, 0.5 * self.length)

    def fit(self, dim):
        if (self.length is None) == (dim == 3):
            raise SceneError("length", "a 3-D cylinder needs its length [m]" if dim == 3 else
                             "a 2-D cylinder is a circle in the x-z plane, 1 m long; leave length out")
        if dim == 2 and self.euler is not None:
            raise SceneError("euler", "a 2-D cylinder is a circle in the x-z plane: turned, it is the same circle; "
                             "leave euler out")

    def mjcf(self, pos, dim, sites):
        from bodies import builders

        return builders.cylinder(self.name, self.radius, self.length or 1.0, pos, planar=dim == 2, euler=self.euler,
                                 **self._common(sites))


class SphereShape(RigidBody):
    """A sphere of ``radius`` [m] (3-D)."""

    geom = "sphere"

    def half_size(self, dim):
        return [self.radius] * dim

    def signed_distance(self, p, dim):
        return np.linalg.norm(p, axis=1) - self.radius

    def volume(self, dim):
        return 4.0 / 3.0 * math.pi * self.radius ** 3

    def submerged_volume(self, dim, draft):
        """The cap ``pi d^2 (3 r - d) / 3``."""
        r = self.radius
        d = min(max(draft, 0.0), 2 * r)
        return math.pi * d * d * (3 * r - d) / 3.0

    def surface_area(self, dim):
        return 4 * math.pi * self.radius ** 2

    def bounding_radius(self, dim):
        return self.radius

    def gyration2(self, dim):
        return 0.4 * self.radius ** 2

    def extent(self, dim):
        return [self.radius] * dim

    def solid(self, dim, floating):
        return ("ball", list(self.pos), self.radius)

    def fit(self, dim):
        if dim != 3:
            raise SceneError("shape", "a sphere is 3-D; in 2-D use a cylinder (a circle in x-z)")

    def mjcf(self, pos, dim, sites):
        from bodies import builders

        return builders.sphere(self.name, self.radius, pos, **self._common(sites))


class PlateShape(Shape):
    """An elastic plate's undeformed box: ``thickness`` along x, ``width`` along y (3-D;
    2-D 1 m), ``length`` along z, before its ``euler`` (the plate's ``angle`` about y) turns it."""

    def half_size(self, dim):
        return [0.5 * self.thickness] + ([0.5 * self.width] if dim == 3 else []) + [0.5 * self.length]

    def volume(self, dim):
        return self.length * self.thickness * (self.width if dim == 3 else 1.0)

    def surface_area(self, dim):
        t, L = self.thickness, self.length
        if dim == 2:
            return 2 * (L + t)
        w = self.width
        return 2 * (L * t + L * w + t * w)
