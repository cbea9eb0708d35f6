"""Cell-linked list: particles binned in cells of side >= the kernel support and sorted by
cell, so that the neighbours of a particle lie in a few contiguous index ranges.

The grid is fixed by the domain box: cell ``(ix, iy, iz)`` has linear index
``ix + nx * (iy + ny * iz)`` (2-D: ``ny = 1`` and the second coordinate is z). Sorting is a
stable counting sort, O(N + cells). The cell side is the search radius divided by ``reach``
(1 or 2): a particle's neighbours lie within ``reach`` cells in every direction, and with
cells sorted this way the ``2 reach + 1`` cells adjacent in x are one contiguous range, so
a particle visits ``2 reach + 1`` (2-D) or ``(2 reach + 1)^2`` (3-D) ranges. ``reach = 2``
scans 25 h^2 per particle in 2-D instead of 36 h^2, but its shorter rows vectorise worse:
the solver uses ``reach = 1`` (measured 1.4 times faster).
Particles outside the box get the sentinel cell ``ncells`` and are sorted to the end;
the caller removes them.

The pair loops of fluid.equations inline the jitted helpers of this module; numba's cache
keys a compiled function on its own file only, so after editing a helper here, delete
``fluid/__pycache__/*.nbi`` (or touch the modules that use it) or a stale inlined copy runs.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit, prange, uint64

from errors import InputError, InstabilityError

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")


@dataclass(frozen=True)
class Grid:
    """A box ``lo``..``hi`` [m] cut into cubic cells of side ``cell`` [m] = radius / reach."""

    lo: np.ndarray
    cell: float
    shape: tuple  # (nx, ny, nz); ny = 1 in 2-D
    reach: int = 1

    @classmethod
    def covering(cls, lo, hi, radius: float, reach: int = 1) -> "Grid":
        """The grid over ``lo``..``hi`` [m] for neighbours closer than ``radius`` [m]."""
        if reach not in (1, 2):
            raise InputError(f"reach must be 1 or 2 cells, got {reach}")
        cell = radius / reach
        lo = np.asarray(lo, np.float64)
        hi = np.asarray(hi, np.float64)
        if cell <= 0 or lo.shape != hi.shape or lo.size not in (2, 3) or not (hi > lo).all():
            raise InputError(f"bad grid: lo={lo}, hi={hi}, cell={cell}; need hi > lo and cell > 0")
        n = np.floor((hi - lo) / cell).astype(np.int64) + 1
        shape = (int(n[0]), 1, int(n[1])) if lo.size == 2 else tuple(int(v) for v in n)
        if shape[0] * shape[1] * shape[2] > 200_000_000:
            raise InputError(f"the domain {lo}..{hi} m holds {np.prod(shape)} cells of {cell} m; "
                             "give a smaller domain box")
        return cls(lo, float(cell), shape, reach)

    @property
    def ncells(self) -> int:
        return self.shape[0] * self.shape[1] * self.shape[2]

    @property
    def lo3(self) -> np.ndarray:
        """The low corner as (x, y, z) [m], y = 0 in 2-D: the pair loops' rows are always
        x, y, z."""
        if self.lo.size == 3:
            return self.lo.copy()
        return np.array([self.lo[0], 0.0, self.lo[1]])


@njit(parallel=True, **_OPTS)
def bin_particles(pos, lo, inv_cell, nx, ny, nz, cell):
    """Cell index of every particle into ``cell``; returns how many are outside the box."""
    n = pos.shape[0]
    three = pos.shape[1] == 3
    zc = pos.shape[1] - 1
    ncells = nx * ny * nz
    outside = 0
    for i in prange(n):
        fx = (pos[i, 0] - lo[0]) * inv_cell
        fz = (pos[i, zc] - lo[zc]) * inv_cell
        fy = (pos[i, 1] - lo[1]) * inv_cell if three else 0.0
        ok = (fx >= 0.0) and (fz >= 0.0) and (fy >= 0.0) and (fx < nx) and (fy < ny) and (fz < nz)
        if ok:
            cell[i] = int(fx) + nx * (int(fy) + ny * int(fz))
        else:
            cell[i] = ncells
            outside += 1
    return outside


@njit(**_OPTS)
def counting_sort(cell, ncells):
    """Stable sort by cell: ``perm`` (new -> old) and ``start`` (ncells + 2 offsets)."""
    n = cell.shape[0]
    start = np.zeros(ncells + 2, np.int64)
    for i in range(n):
        start[cell[i] + 1] += 1
    for c in range(ncells + 1):
        start[c + 1] += start[c]
    fill = start[:-1].copy()
    perm = np.empty(n, np.int64)
    for i in range(n):
        c = cell[i]
        perm[fill[c]] = i
        fill[c] += 1
    return perm, start


#: sub-bins per cell along x (:func:`order_cells_by_x`): a row range found by look-up
#: (:func:`row_range_binned`) is on average one sub-bin, cell / XBINS (a sixth of a
#: spacing with the default h), longer than the exact one (8 sub-bins let a lattice's
#: next row of particles, 3 spacings away against 2h = 2.83, into every range: 35 %
#: more pairs); a power of two, so that the look-up divides by shifting
XBINS = 16
#: most particles a cell may hold when sub-bins are tabulated (uint16 offsets)
MAX_PER_CELL = 65535


@njit(parallel=True, **_OPTS)
def order_cells_by_x(perm, start, pos, lo_x, cell, nx, tab):
    """Reorder ``perm`` within every cell by the particles' x coordinate (insertion sort:
    a cell holds a few particles, and from step to step their order barely changes), so
    that each row of x-adjacent cells is sorted by x as a whole. If ``tab`` is not empty
    ((ncells + 1) XBINS uint16), also tabulate where each of the :data:`XBINS` sub-bins of
    every occupied cell begins: ``tab[c XBINS + i]`` is the offset from the start of cell
    ``c`` of its first particle with ``x >= x_c + i cell / XBINS`` (``x_c`` the cell's left
    edge [m]). Empty cells are not written (four in five are empty in a dam-break tank;
    :func:`row_range_binned` clamps each offset at the cell's count, so what they hold does
    not matter). Returns how many cells hold more than :data:`MAX_PER_CELL` particles
    (their offsets would not fit)."""
    fill = tab.shape[0] > 0
    inv_w = XBINS / cell
    over = 0
    for c in prange(start.shape[0] - 2):  # the last cell is the outside sentinel
        j0 = start[c]
        j1 = start[c + 1]
        for j in range(j0 + 1, j1):
            p = perm[j]
            x = pos[p, 0]
            i = j - 1
            while i >= j0 and pos[perm[i], 0] > x:
                perm[i + 1] = perm[i]
                i -= 1
            perm[i + 1] = p
        if fill and j1 > j0:
            if j1 - j0 > MAX_PER_CELL:
                over += 1
            x0 = lo_x + (c % nx) * cell
            base = c * XBINS
            b = 0  # tab[base + b'] for b' < b are set: the particles of sub-bins below b'
            for j in range(j0, j1):
                sb = min(max(int((pos[perm[j], 0] - x0) * inv_w), 0), XBINS - 1)
                while b <= sb:
                    tab[base + b] = j - j0
                    b += 1
            for k in range(b, XBINS):
                tab[base + k] = j1 - j0
    return over


def sort_by_cell(pos: np.ndarray, grid: Grid, xbins: np.ndarray | None = None):
    """Bin ``pos`` on ``grid``: returns (perm, start, n_outside); apply ``perm`` to every
    array. Within a cell the particles are ordered by x. With ``xbins`` (uint16,
    ``(ncells + 1) XBINS``, from :func:`x_bin_array`) it is filled with the sub-bin table of
    :func:`order_cells_by_x` and returned as a fourth item."""
    nx, ny, nz = grid.shape
    cell = np.empty(pos.shape[0], np.int64)
    outside = bin_particles(pos, grid.lo, 1.0 / grid.cell, nx, ny, nz, cell)
    perm, start = counting_sort(cell, grid.ncells)
    tab = np.empty(0, np.uint16) if xbins is None else xbins
    _order_cells(perm, start, pos, grid, tab)
    return (perm, start, outside) if xbins is None else (perm, start, outside, tab)


def _order_cells(perm, start, pos, grid: Grid, tab) -> None:
    """:func:`order_cells_by_x`, stopping the run if a cell is too full for its table."""
    over = order_cells_by_x(perm, start, pos, grid.lo[0], grid.cell, grid.shape[0], tab)
    if over:
        raise InstabilityError(f"{over} cells of {grid.cell:.4g} m hold more than {MAX_PER_CELL} particles "
                               "each: particles have collapsed onto each other (an unstable run)")


def x_bin_array(grid: Grid) -> np.ndarray:
    """An array for the sub-bin table of :func:`order_cells_by_x` on ``grid``, zeroed: a
    sort fills the entries of the cells that hold particles, and a checkpoint saves the
    whole table, so that two runs of the same scene write the same bytes."""
    return np.zeros((grid.ncells + 1) * XBINS, np.uint16)


def x_bins(xs: np.ndarray, start: np.ndarray, grid: Grid) -> np.ndarray:
    """The sub-bin table of :func:`order_cells_by_x` for particles already sorted by
    :func:`sort_by_cell` (``xs`` their x [m])."""
    tab = x_bin_array(grid)
    pos = np.ascontiguousarray(xs, np.float64).reshape(-1, 1)
    _order_cells(np.arange(len(xs)), start, pos, grid, tab)
    return tab


@njit(**_OPTS)
def cell_coords(x, y, z, lo, inv_cell, three, nx, ny, nz):
    """Integer cell coordinates of a point inside the box (clamped at the box edges)."""
    zc = 2 if three else 1
    cx = min(max(int((x - lo[0]) * inv_cell), 0), nx - 1)
    cz = min(max(int((z - lo[zc]) * inv_cell), 0), nz - 1)
    cy = min(max(int((y - lo[1]) * inv_cell), 0), ny - 1) if three else 0
    return cx, cy, cz


@njit(**_OPTS)
def row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, reach):
    """Index range [a, b) of the (up to) 2 reach + 1 cells x-adjacent to (cx, cy+dy, cz+dz)."""
    y = cy + dy
    z = cz + dz
    if y < 0 or y >= ny or z < 0 or z >= nz:
        return 0, 0
    x0 = max(cx - reach, 0)
    x1 = min(cx + reach, nx - 1)
    base = nx * (y + ny * z)
    return start[base + x0], start[base + x1 + 1]


@njit(**_OPTS)
def row_range_binned(x, radius, lo_x, inv_w, cy, cz, dy, dz, nx, ny, nz, start, tab, pad):
    """:func:`row_range` for a point at ``x`` [m] in cell ``(., cy, cz)``, trimmed to the
    particles with ``x - radius < x_b < x + radius``, found with two look-ups in the
    sub-bin table ``tab`` of :func:`order_cells_by_x` (``inv_w = XBINS / cell``), to within
    one sub-bin (no search: a binary search per bound cost a fifth of the pair loop); then
    its end moved up to make the length a multiple of ``pad``, as far as the row of cells
    goes. Everything it adds lies at least ``radius`` away in x, where the kernel and every
    pair term vanish, so a pair loop over it needs no test, visits a third fewer pairs
    than whole rows of cells and rarely runs a scalar tail. Requires ``reach = 1``
    (cell = radius)."""
    yy = cy + dy
    zz = cz + dz
    if yy < 0 or yy >= ny or zz < 0 or zz >= nz:
        return 0, 0
    row = nx * (yy + ny * zz)
    nb = nx * XBINS
    g0 = min(max(int((x - radius - lo_x) * inv_w), 0), nb - 1)
    g1 = min(max(int((x + radius - lo_x) * inv_w), 0), nb - 1) + 1  # one past the last bin
    c0 = row + g0 // XBINS
    c1 = row + g1 // XBINS  # row + nx at the end of the row: its start is the row's end
    j0 = start[c0] + min(tab[c0 * XBINS + g0 % XBINS], start[c0 + 1] - start[c0])
    j1 = max(start[c1] + min(tab[c1 * XBINS + g1 % XBINS], start[c1 + 1] - start[c1]), j0)
    return j0, min(j0 + ((j1 - j0 + pad - 1) // pad) * pad, start[row + nx])


@njit(**_OPTS)
def _or3(src, dst, lo, hi, below, above):
    """``dst[c] = src[c - below] | src[c] | src[c + above]`` for ``lo <= c < hi`` (``below``
    and ``above`` 0 or the step to the neighbour; unsigned indices: no wrap-around test, so
    the loop vectorises, 40 times faster)."""
    b = uint64(below)
    a = uint64(above)
    for c in range(uint64(lo), uint64(hi)):
        dst[c] = src[c - b] | src[c] | src[c + a]


@njit(parallel=True, **_OPTS)
def _near_cells(kind, start, nx, ny, nz, a, b):
    """:func:`fluid_near_cells` into ``b``: the cells holding fluid dilated by one cell along
    x, then y, then z (rows of cells in parallel)."""
    for r in prange(ny * nz):  # the cells with fluid, into b; with their x neighbours, into a
        base = r * nx
        for c in range(base, base + nx):
            f = 0
            for j in range(start[c], start[c + 1]):
                if kind[j] == 0:
                    f = 1
                    break
            b[c] = f
        if nx == 1:
            a[base] = b[base]
        else:
            _or3(b, a, base, base + 1, 0, 1)
            _or3(b, a, base + 1, base + nx - 1, 1, 1)
            _or3(b, a, base + nx - 1, base + nx, 1, 0)
    if ny > 1:  # y: a -> b, then back into a
        for r in prange(ny * nz):
            iy = r % ny
            _or3(a, b, r * nx, (r + 1) * nx, nx if iy > 0 else 0, nx if iy < ny - 1 else 0)
        for r in prange(ny * nz):
            _or3(b, a, r * nx, (r + 1) * nx, 0, 0)
    plane = nx * ny
    for iz in prange(nz):  # z: a -> b
        _or3(a, b, iz * plane, (iz + 1) * plane, plane if iz > 0 else 0, plane if iz < nz - 1 else 0)


def fluid_near_cells(kind: np.ndarray, start: np.ndarray, grid: Grid, work=None) -> np.ndarray:
    """For particles sorted by cell on ``grid`` (``start`` from :func:`sort_by_cell`, kind 0
    fluid): a uint8 flag per cell, 1 where a fluid particle lies in the cell or in one of the
    cells around it (``reach`` 1: 27 cells in 3-D, 9 in 2-D), i.e. 0 where every particle
    of the cell is farther than one cell from all the fluid. With cells as wide as the
    kernel's support, a boundary particle in a cell flagged 0 has no fluid neighbour: every
    pair term it has vanishes, so the pair loops can skip it (dry walls: the tank above the
    water, the walls' outer layers beyond the support). O(N + cells). ``work``: a
    :class:`fluid.equations.Workspace` whose two flag arrays are reused (and the result is
    one of them, overwritten by the next call)."""
    if grid.reach != 1:
        raise InputError(f"fluid_near_cells needs a grid of reach 1, got {grid.reach}")
    nx, ny, nz = grid.shape
    if work is None:
        a, b = np.empty(grid.ncells, np.uint8), np.empty(grid.ncells, np.uint8)
    else:
        a, b = work.get("near_a", (grid.ncells,), np.uint8), work.get("near_b", (grid.ncells,), np.uint8)
    _near_cells(kind, start, nx, ny, nz, a, b)
    return b


@njit(parallel=True, **_OPTS)
def _count(pos, lo, inv_cell, nx, ny, nz, start, reach, r2max, counts):
    n = pos.shape[0]
    three = pos.shape[1] == 3
    zc = pos.shape[1] - 1
    dys = 2 * reach + 1 if three else 1
    for i in prange(n):
        xi = pos[i, 0]
        zi = pos[i, zc]
        yi = pos[i, 1] if three else 0.0
        cx, cy, cz = cell_coords(xi, yi, zi, lo, inv_cell, three, nx, ny, nz)
        c = 0
        for dz in range(-reach, reach + 1):
            for k in range(dys):
                dy = k - reach if three else 0
                a, b = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, reach)
                for j in range(a, b):
                    rx = xi - pos[j, 0]
                    rz = zi - pos[j, zc]
                    ry = yi - pos[j, 1] if three else 0.0
                    if j != i and rx * rx + ry * ry + rz * rz < r2max:
                        c += 1
        counts[i] = c


@njit(parallel=True, **_OPTS)
def _fill(pos, lo, inv_cell, nx, ny, nz, start, reach, r2max, offsets, out):
    n = pos.shape[0]
    three = pos.shape[1] == 3
    zc = pos.shape[1] - 1
    dys = 2 * reach + 1 if three else 1
    for i in prange(n):
        xi = pos[i, 0]
        zi = pos[i, zc]
        yi = pos[i, 1] if three else 0.0
        cx, cy, cz = cell_coords(xi, yi, zi, lo, inv_cell, three, nx, ny, nz)
        c = offsets[i]
        for dz in range(-reach, reach + 1):
            for k in range(dys):
                dy = k - reach if three else 0
                a, b = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, reach)
                for j in range(a, b):
                    rx = xi - pos[j, 0]
                    rz = zi - pos[j, zc]
                    ry = yi - pos[j, 1] if three else 0.0
                    if j != i and rx * rx + ry * ry + rz * rz < r2max:
                        out[c] = j
                        c += 1


def neighbour_lists(pos: np.ndarray, radius: float, lo=None, hi=None, reach: int = 1):
    """Every particle's neighbours closer than ``radius`` [m] (itself left out), found with
    the cell list, as compressed rows in the cell order: returns ``(perm, offsets, idx)``,
    where the neighbours of particle ``perm[i]`` are ``perm[idx[offsets[i]:offsets[i + 1]]]``
    (``idx`` indexes ``pos[perm]``). Both passes (count, fill) run in parallel."""
    pos = np.ascontiguousarray(pos, np.float64)
    lo = pos.min(axis=0) if lo is None else np.asarray(lo, np.float64)
    hi = pos.max(axis=0) if hi is None else np.asarray(hi, np.float64)
    grid = Grid.covering(lo, hi, radius, reach)
    perm, start, outside = sort_by_cell(pos, grid)
    if outside:
        raise InputError(f"{outside} particles lie outside the box {lo}..{hi}")
    sp = np.ascontiguousarray(pos[perm])
    nx, ny, nz = grid.shape
    counts = np.empty(len(sp), np.int64)
    _count(sp, grid.lo, 1.0 / grid.cell, nx, ny, nz, start, reach, radius * radius, counts)
    offsets = np.zeros(len(sp) + 1, np.int64)
    np.cumsum(counts, out=offsets[1:])
    idx = np.empty(offsets[-1], np.int64)
    _fill(sp, grid.lo, 1.0 / grid.cell, nx, ny, nz, start, reach, radius * radius, offsets, idx)
    return perm, offsets, idx


def neighbour_pairs(pos: np.ndarray, radius: float, lo=None, hi=None, reach: int = 1) -> np.ndarray:
    """All ordered pairs (i, j), i != j, closer than ``radius`` [m], in the caller's indexing,
    found with the cell list (for tests and diagnostics; the solver's loops traverse the
    cells directly). Returns an (M, 2) int64 array sorted lexicographically."""
    perm, offsets, idx = neighbour_lists(pos, radius, lo, hi, reach)
    i = np.repeat(np.arange(len(perm)), np.diff(offsets))
    pairs = np.stack([perm[i], perm[idx]], axis=1)
    return pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))]
