"""The wetted hull of a body at its floating position, as a panel mesh for the BEM.

What: for a box, vertical or tilted cylinder or sphere (MuJoCo sizes: half-sizes, radius
and half-length, radius), placed by its centre and orientation relative to the body's
centre of mass horizontally and to the still free surface vertically (``z = 0`` is the
surface), the quadrilateral panels of the part below ``z = 0``, outward normals, at most
about ``panel_size`` [m] across. Upright boxes and cylinders (axis vertical) are meshed
from the keel to the waterline directly, so that the waterline lies on panel edges;
tilted bodies and spheres are meshed whole and clipped at ``z = 0`` by Capytaine
(``Mesh.immersed_part``). The mesh carries no panel on the free surface.

Why: linear potential flow solves for the flow about the mean wetted surface of the body
(Newman 1977, §6.16); the panels are its discretisation (Hess & Smith 1964, constant-
strength panels as in Nemoh/Capytaine, Babarit & Delhommeau 2015).

Limits: one geom per body; the body must pierce the surface (neither dry nor submerged:
a submerged body has no waterplane, and its restoring would come from the mass
distribution alone, which linear hydrostatics of the hull cannot give). Units: m.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from errors import InputError

#: the geom kinds this module meshes
KINDS = ("box", "cylinder", "sphere")


@dataclass(frozen=True)
class Hull:
    """A wetted hull as plain arrays: ``vertices`` [m] (n, 3) and ``faces`` (m, 4) vertex
    indices (a triangle repeats its last vertex), coordinates relative to the body's
    centre of mass horizontally and the still water level vertically; ``draft`` [m] the
    depth of its lowest point, ``waterline_span`` [m] its horizontal extents at ``z = 0``
    (x, y)."""

    vertices: np.ndarray
    faces: np.ndarray
    draft: float
    waterline_span: tuple

    @property
    def panels(self) -> int:
        return len(self.faces)


def _upright(rot: np.ndarray) -> bool:
    """Whether the geom's own z axis is vertical (then its x, y axes are horizontal)."""
    return abs(abs(rot[2, 2]) - 1.0) < 1e-9


def _cuts(length: float, panel_size: float, least: int = 1) -> int:
    return max(least, math.ceil(length / panel_size - 1e-9))


def vertical_extent(kind: str, size, rot, centre_z: float) -> tuple[float, float]:
    """Lowest and highest z [m] of a geom of ``kind`` and MuJoCo ``size``, orientation
    ``rot`` (geom to world), centre at height ``centre_z`` [m]."""
    size = np.asarray(size, float)
    rot = np.asarray(rot, float)
    if kind == "box":
        half = float(np.abs(rot[2]) @ size[:3])
    elif kind == "cylinder":
        r, hl = size[0], size[1]
        c = abs(rot[2, 2])  # cosine of the axis' tilt
        half = hl * c + r * math.sqrt(max(1.0 - c * c, 0.0))
    elif kind == "sphere":
        half = size[0]
    else:
        raise InputError(f"potential flow: a {kind!r} geom has no hull model; use a box, cylinder or sphere")
    return centre_z - half, centre_z + half


def check_pierces(name: str, kind: str, size, rot, centre_z: float) -> None:
    """Refuse a body that is dry or fully submerged (its hull has no waterline)."""
    lo, hi = vertical_extent(kind, size, rot, centre_z)
    if lo >= 0.0:
        raise InputError(f"potential flow: body '{name}' is dry (its lowest point is {lo:.4g} m above the still "
                         f"water); place it in the water (place = \"floating\")")
    if hi <= 0.0:
        raise InputError(f"potential flow: body '{name}' is fully submerged (its top is {-hi:.4g} m below the still "
                         f"water): the hull has no waterline, so no linear hydrostatic restoring; this model takes "
                         f"surface-piercing bodies only (use the analytic or SPH fluid)")


def wetted_hull(kind: str, size, rot, centre, panel_size: float, name: str = "body") -> Hull:
    """The wetted hull of one geom (see the module docstring). ``centre`` [m]: the geom's
    centre relative to (centre of mass x, y; still water level); ``rot``: geom to world;
    ``panel_size`` [m] > 0."""
    import capytaine as cpt

    size = np.asarray(size, float)
    rot = np.asarray(rot, float)
    centre = np.asarray(centre, float)
    if not (math.isfinite(panel_size) and panel_size > 0):
        raise InputError(f"potential flow: panel_size = {panel_size!r} m; give a panel size > 0 m")
    check_pierces(name, kind, size, rot, centre[2])
    lo, _ = vertical_extent(kind, size, rot, centre[2])
    draft = -lo
    h = panel_size
    if kind in ("box", "cylinder") and _upright(rot):
        yaw = math.atan2(rot[1, 0], rot[0, 0])
        if kind == "box":
            lx, ly = 2.0 * size[0], 2.0 * size[1]
            mesh = cpt.mesh_parallelepiped(size=(lx, ly, draft), center=(0.0, 0.0, -0.5 * draft),
                                           resolution=(_cuts(lx, h), _cuts(ly, h), _cuts(draft, h)),
                                           missing_sides={"top"})
        else:
            r = size[0]
            mesh = cpt.mesh_vertical_cylinder(length=draft, radius=r, center=(0.0, 0.0, -0.5 * draft),
                                              resolution=(_cuts(r, h), _cuts(2 * math.pi * r, h, 12),
                                                          _cuts(draft, h)))
            mesh = mesh.extract_faces(np.flatnonzero(mesh.faces_centers[:, 2] < -1e-9 * draft))  # no top cap
        mesh = mesh.rotated_z(yaw).translated((centre[0], centre[1], 0.0))
    else:
        if kind == "sphere":
            r = size[0]
            n = _cuts(math.pi * r, h, 8)
            full = cpt.mesh_sphere(radius=r, center=(0.0, 0.0, 0.0),
                                   resolution=(n + n % 2, _cuts(2 * math.pi * r, h, 12)))
        elif kind == "cylinder":
            r, hl = size[0], size[1]
            full = cpt.mesh_vertical_cylinder(length=2 * hl, radius=r, center=(0.0, 0.0, 0.0),
                                              resolution=(_cuts(r, h), _cuts(2 * math.pi * r, h, 12),
                                                          _cuts(2 * hl, h)))
        else:
            full = cpt.mesh_parallelepiped(size=tuple(2.0 * size[:3]), center=(0.0, 0.0, 0.0),
                                           resolution=tuple(_cuts(2.0 * s, h) for s in size[:3]))
        mesh = full.rotated_with_matrix(rot).translated(tuple(centre)).immersed_part()
        mesh = mesh.extract_faces(np.flatnonzero(mesh.faces_centers[:, 2] < -1e-9 * draft))
    v = np.asarray(mesh.vertices, float)
    at_surface = np.abs(v[:, 2]) <= 1e-9 * max(draft, 1.0)
    span = (float(np.ptp(v[at_surface, 0])), float(np.ptp(v[at_surface, 1]))) if at_surface.any() else (0.0, 0.0)
    return Hull(v, np.asarray(mesh.faces, np.int64), float(draft), span)


def displaced_volume(kind: str, size, rot, centre_z: float) -> float | None:
    """The exact volume [m^3] below ``z = 0`` of an upright box or cylinder or of a sphere
    (the flat-panel hull's differs by its polygonal waterline: a 32-gon's area is 0.6 %
    short of the circle's), or None for a tilted box or cylinder."""
    size = np.asarray(size, float)
    lo, hi = vertical_extent(kind, size, rot, centre_z)
    d = min(max(-lo, 0.0), hi - lo)
    if kind == "sphere":
        r = size[0]
        return math.pi * d * d * (3.0 * r - d) / 3.0
    if not _upright(np.asarray(rot, float)):
        return None
    if kind == "box":
        return 4.0 * size[0] * size[1] * d
    return math.pi * size[0] ** 2 * d


def default_panel_size(kind: str, size) -> float:
    """A panel size [m] for a body: a tenth of its smallest horizontal dimension (the
    circumference of a 3 m radius cylinder in 32 panels; a hemisphere of radius a in 0.2 a
    panels, whose heave added mass and damping are within 3.7 % of Hulme's (1982) for
    ``K a <= 2``, 1.7 % at 0.1 a: ``cosim/validations/potential.py``)."""
    size = np.asarray(size, float)
    if kind == "box":
        return float(2.0 * min(size[0], size[1]) / 10.0)
    return float(2.0 * size[0] / 10.0)
