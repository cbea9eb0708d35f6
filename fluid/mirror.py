"""A symmetry plane y = y0 in 3-D: the fluid simulates the particles on y >= y0 only, and
the mirror image of each one within the kernel's support 2h of the plane (its y reflected,
its velocity's y component reversed, its density, mass and kind kept) takes part in every
particle sum as a neighbour: the ghost particles of a free-slip boundary (Libersky et al.
1993, J. Comput. Phys. 109, 67-75; Colagrossi & Landrini 2003, J. Comput. Phys. 191,
448-475, their mirrored fluid at a solid wall), here at a plane of symmetry, where they
are exact: for a flow symmetric about the plane every particle's neighbours are then the
same as in the whole domain, so the half domain gives the whole one's rates.

Why not a wall at the plane: a wall of boundary particles loads a body that crosses the
plane as fluid on one side only; the body's particles within 2h of it miss the fluid
beyond. Measured on a held box (docs/validation/nearfield.md): a slip wall gave -12 % of
the buoyancy, the mirror images the whole tank's.

Mirror images are rows of the fluid's particle set with a negative id (``-1 - id`` of
their source) and group -1: rebuilt from the sources at every sort (:meth:`Mirror.extend`,
:meth:`Mirror.finish`), brought to their sources' state before every rate evaluation
(:meth:`Mirror.refresh`); their own rates are not used (their neighbourhoods are cut at
the band's edge), so the pair loops skip them (zero rates), and nothing integrates them
for more than one step. A source closer to
the plane than 1e-9 dx is its own image and has none; a particle that crosses the plane
is reflected back (specular: its place and its normal velocity), as the symmetric flow it
stands for cannot cross it.

A second plane ``y = y1`` above the first makes the simulated particles a slice between two
symmetry planes, each with its own images: a flow uniform across y (a plane wave along x)
in a slice of a flume of any width, without side walls. Each image reflects across one
plane only, so the slice is at least the band (2h) wide: a particle's support then reaches
past one plane, or past both but no farther than either band. Why: Adami-type side walls
along a free surface change the waves that run along them (the surface meets the wall
along the whole flume): a standing wave in a slice 5 spacings wide between walls runs
2.3 % fast and grows 4 % a period, between two symmetry planes it runs as the 2-D water
(docs/validation/wave-propagation_history.md, "Side walls, not the 3-D water").
"""

from __future__ import annotations

import numpy as np

from errors import InputError

Y = 1  #: the plane's normal axis (y)


class Mirror:
    """The mirror images across ``y = y0`` [m] of the particles within ``band`` [m] (the
    kernel's support 2h) of the plane; ``dx`` [m] sets the tolerance of "on the plane".
    ``y1`` [m]: a second plane above the first, at least ``band`` from it, with the images
    of the particles within ``band`` below it (None: one plane)."""

    def __init__(self, y0: float, band: float, dx: float, y1: float | None = None):
        self.y0, self.band, self.tol = float(y0), float(band), 1e-9 * float(dx)
        self.y1 = None if y1 is None else float(y1)
        if self.y1 is not None and not self.y1 - self.y0 >= self.band:
            raise InputError(f"symmetry planes y = {self.y0:g} and {self.y1:g} m are closer than the kernel's "
                             f"support {self.band:g} m: an image would need images; widen the slice")
        self.rows = np.zeros(0, np.int64)  #: rows of the images after the last sort
        self.src = np.zeros(0, np.int64)  #: rows of their sources
        self.plane = np.zeros(0)  #: the y [m] of the plane each image is reflected across
        self._source_ext = np.zeros(0, np.int64)
        self._plane_ext = np.zeros(0)

    @staticmethod
    def _reflect(ps, aux: dict, rows: np.ndarray, plane) -> None:
        """Reflect the places and velocities of ``rows`` across the plane(s) y = ``plane``
        (a number, or one per row), and those of the integrator's saved state ``aux``."""
        for k, a in (("pos", ps.pos), ("vel", ps.vel), *((k, aux[k]) for k in ("pos", "vel") if k in aux)):
            a[rows, Y] = 2.0 * plane - a[rows, Y] if k == "pos" else -a[rows, Y]

    def reflect_crossing(self, ps, aux: dict) -> None:
        """Reflect back the simulated particles that have crossed a plane (y < y0, or y >
        y1), and their integrator's saved state with them."""
        real = ps.ids >= 0
        below = np.flatnonzero((ps.pos[:, Y] < self.y0) & real)
        if below.size:
            self._reflect(ps, aux, below, self.y0)
        if self.y1 is not None:
            above = np.flatnonzero((ps.pos[:, Y] > self.y1) & real)
            if above.size:
                self._reflect(ps, aux, above, self.y1)

    def extend(self, ps) -> tuple[np.ndarray, np.ndarray, int]:
        """(rows, positions, n) of the set to sort: the ``n`` simulated particles' rows,
        then their sources' rows again with the positions of their images."""
        real = np.flatnonzero(ps.ids >= 0)
        d = ps.pos[real, Y] - self.y0
        near = np.flatnonzero((d > self.tol) & (d < self.band))
        plane = np.full(near.size, self.y0)
        if self.y1 is not None:
            d = self.y1 - ps.pos[real, Y]
            top = np.flatnonzero((d > self.tol) & (d < self.band))
            near, plane = np.concatenate([near, top]), np.concatenate([plane, np.full(top.size, self.y1)])
        self._source_ext = near  # each image's source: its row among the simulated ones
        self._plane_ext = plane
        rows = np.concatenate([real, real[near]])
        pos = ps.pos[rows]
        pos[real.size:, Y] = 2.0 * plane - pos[real.size:, Y]
        return rows, pos, real.size

    def finish(self, ps, aux: dict, perm: np.ndarray, kept: int, n: int) -> None:
        """Make the images of a set gathered by ``rows[perm[:kept]]`` (:meth:`extend`'s rows,
        the sort's ``perm`` over them, ``kept`` rows inside the domain, ``n`` simulated):
        reflect their places and velocities (and the saved state's), give them their ids
        and no group, and note each image's source row (images whose source left the
        domain keep the state they were given here)."""
        order = perm[:kept]
        rows = np.flatnonzero(order >= n)
        at = np.empty(perm.size, np.int64)
        at[perm] = np.arange(perm.size)
        src = at[self._source_ext[order[rows] - n]]
        plane = self._plane_ext[order[rows] - n]
        ok = src < kept
        self._reflect(ps, aux, rows, plane)
        ps.ids[rows] = -1 - ps.ids[rows]
        ps.group[rows] = -1
        self.rows, self.src, self.plane = rows[ok], src[ok], plane[ok]

    def refresh(self, ps, density_only: bool = False) -> None:
        """Bring the images to their sources' state (density; and place and velocity)."""
        r, s = self.rows, self.src
        ps.rho[r] = ps.rho[s]
        if not density_only:
            ps.pos[r] = ps.pos[s]
            ps.pos[r, Y] = 2.0 * self.plane - ps.pos[s, Y]
            ps.vel[r] = ps.vel[s]
            ps.vel[r, Y] = -ps.vel[s, Y]

    def reflect_rows(self, G: np.ndarray) -> None:
        """A per-particle vector field ``G`` (3, N), as the pair loop's first pass writes it,
        given to the images from their sources (its y row reversed)."""
        if G.shape[1]:
            G[:, self.rows] = G[:, self.src]
            G[Y, self.rows] = -G[Y, self.src]
