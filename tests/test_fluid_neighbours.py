"""Cell-linked list against brute force (DESIGN.md, validation tier 1)."""

import numpy as np
import pytest
from scipy.spatial import cKDTree

from cosim.errors import InstabilityError
from fluid.neighbours import (MAX_PER_CELL, XBINS, Grid, counting_sort, fluid_near_cells, neighbour_pairs,
                              row_range_binned, sort_by_cell, x_bin_array, x_bins)


def brute(pos, radius):
    d = pos[:, None, :] - pos[None, :, :]
    r2 = (d * d).sum(-1)
    i, j = np.nonzero(r2 < radius * radius)
    keep = i != j
    pairs = np.stack([i[keep], j[keep]], 1)
    return pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))]


@pytest.mark.parametrize("reach", [1, 2])
@pytest.mark.parametrize("dim", [2, 3])
def test_random_cloud_equals_brute_force(dim, reach):
    rng = np.random.default_rng(dim)
    pos = rng.uniform(0, 1, (1500 if dim == 2 else 2500, dim))
    for radius in (0.03, 0.11):
        got = neighbour_pairs(pos, radius, reach=reach)
        assert len(got) > 0
        assert np.array_equal(got, brute(pos, radius))


@pytest.mark.parametrize("reach", [1, 2])
@pytest.mark.parametrize("dim", [2, 3])
def test_particles_on_cell_edges(dim, reach):
    """A lattice whose spacing divides the cell side: many particles lie exactly on cell
    faces and many pairs exactly at the search radius (which are not neighbours)."""
    radius = 0.2
    ax = np.arange(0, 11) * 0.1  # 0.0 ... 1.0, every second point on a cell face
    g = np.meshgrid(*([ax] * dim), indexing="ij")
    pos = np.stack([a.ravel() for a in g], 1)
    got = neighbour_pairs(pos, radius, lo=np.zeros(dim), hi=np.ones(dim), reach=reach)
    assert np.array_equal(got, brute(pos, radius))
    # the neighbour count of an interior particle of the lattice, by hand:
    # 2-D: 8 within sqrt(2)*0.1 plus 4 at 0.2 (excluded, r == radius up to rounding)
    i = np.flatnonzero(np.all(np.isclose(pos, 0.5), axis=1))[0]
    n_i = (got[:, 0] == i).sum()
    r = np.linalg.norm(pos - pos[i], axis=1)
    assert n_i == ((r < radius) & (r > 0)).sum()


def test_sort_is_by_cell_then_by_x():
    rng = np.random.default_rng(5)
    pos = rng.uniform(0, 1, (500, 2))
    grid = Grid.covering([0, 0], [1, 1], 0.1)
    perm, start, outside = sort_by_cell(pos, grid)
    assert outside == 0 and sorted(perm.tolist()) == list(range(500))
    cells = (np.floor(pos[perm, 0] / 0.1) + grid.shape[0] * np.floor(pos[perm, 1] / 0.1)).astype(int)
    assert (np.diff(cells) >= 0).all()
    for c in range(grid.ncells):  # start[] delimits each cell's particles
        assert (cells[start[c]:start[c + 1]] == c).all()
    x = pos[perm, 0]
    same = np.diff(cells) == 0  # ordered by x inside a cell ...
    assert (np.diff(x)[same] >= 0).all()
    row = np.floor(pos[perm, 1] / 0.1)  # ... so every row of cells is ordered by x
    assert (np.diff(x)[np.diff(row) == 0] >= 0).all()


@pytest.mark.parametrize("n, ncells", [(0, 4), (5, 1), (10_001, 97)])
def test_counting_sort_is_a_stable_sort(n, ncells):
    """The order is numpy's stable argsort and start[c] the number of particles in the
    cells below c (the sentinel cell last)."""
    cell = np.random.default_rng(n).integers(0, ncells + 1, n)
    perm, start = counting_sort(cell, ncells)
    assert (perm == np.argsort(cell, kind="stable")).all()
    assert (start == np.concatenate([[0], np.cumsum(np.bincount(cell, minlength=ncells + 1))])).all()


def test_outside_particles_are_counted_and_sorted_last():
    pos = np.array([[0.5, 0.5], [2.0, 0.5], [0.2, -0.1], [0.9, 0.9]])
    grid = Grid.covering([0, 0], [1, 1], 0.25)
    perm, start, outside = sort_by_cell(pos, grid)
    assert outside == 2
    assert set(perm[-2:].tolist()) == {1, 2}


def test_sub_bin_table_and_binned_row_ranges():
    """The sub-bin table (order_cells_by_x) gives, in every occupied cell, where each of the
    XBINS sub-bins starts; the same from sort_by_cell and from x_bins on sorted particles;
    a binned row range holds every particle of its row within the radius in x and adds
    only particles beyond it (less than one sub-bin on each side, then the padding)."""
    rng = np.random.default_rng(11)
    pos = rng.uniform(0, 1, (3000, 2))
    grid = Grid.covering([0, 0], [1, 1], 0.1)
    tab = x_bin_array(grid)
    perm, start, outside, tab = sort_by_cell(pos, grid, tab)
    sp = pos[perm]
    nx = grid.shape[0]
    again = x_bins(sp[:, 0], start, grid)
    w = grid.cell / XBINS
    for c in range(grid.ncells):
        s0, s1 = start[c], start[c + 1]
        if s1 == s0:
            continue
        assert np.array_equal(tab[c * XBINS:(c + 1) * XBINS], again[c * XBINS:(c + 1) * XBINS])
        sub = np.floor((sp[s0:s1, 0] - (c % nx) * grid.cell) / w).clip(0, XBINS - 1)
        want = [np.searchsorted(sub, b) for b in range(XBINS)]  # sub-bins are sorted in a cell
        assert tab[c * XBINS:(c + 1) * XBINS].tolist() == want
    for i in rng.choice(len(sp), 200, replace=False):
        x, z = sp[i]
        cz = int(z / grid.cell)
        for dz in (-1, 0, 1):
            j0, j1 = row_range_binned(x, grid.cell, 0.0, XBINS / grid.cell, 0, cz, 0, dz, nx, 1, grid.shape[2],
                                      start, tab, 8)
            if not 0 <= cz + dz < grid.shape[2]:
                assert j0 == j1 == 0
                continue
            row = slice(start[nx * (cz + dz)], start[nx * (cz + dz + 1)])
            xr = sp[row, 0]
            idx = np.arange(row.start, row.stop)
            inside = idx[np.abs(xr - x) < grid.cell]
            assert j0 <= inside.min(initial=j1) and inside.max(initial=j0 - 1) < j1
            assert (j1 - j0) % 8 == 0 or j1 == row.stop
            core = (idx >= j0) & (idx < j1)
            trimmed = idx[core & (np.abs(xr - x) >= grid.cell)]  # what the range adds
            assert (sp[trimmed[trimmed < inside.min(initial=j1)], 0] > x - grid.cell - w).all()


def test_a_cell_too_full_for_the_sub_bin_table_stops_the_run():
    pos = np.full((MAX_PER_CELL + 1, 2), 0.5)
    grid = Grid.covering([0, 0], [1, 1], 0.1)
    with pytest.raises(InstabilityError, match="collapsed"):
        sort_by_cell(pos, grid, x_bin_array(grid))


@pytest.mark.parametrize("dim", [2, 3])
def test_cells_near_the_fluid(dim):
    """fluid_near_cells flags exactly the cells within one cell (in every direction) of a
    cell holding fluid; every boundary particle with fluid within a cell's width lies in a
    flagged cell, so a loop may skip the others."""
    rng = np.random.default_rng(7 + dim)
    n = 3000
    pos = rng.uniform(0, 1, (n, dim))
    kind = np.where(pos[:, 0] + 0.5 * pos[:, -1] < 0.45, 0, 1).astype(np.int8)  # fluid in a corner
    grid = Grid.covering(np.zeros(dim), np.ones(dim), 0.09)
    perm, start, out = sort_by_cell(pos, grid)
    assert out == 0
    pos, kind = pos[perm], kind[perm]
    near = fluid_near_cells(kind, start, grid)
    nx, ny, nz = grid.shape
    ijk = np.stack(np.unravel_index(np.arange(grid.ncells), (nz, ny, nx)), 1)  # (iz, iy, ix)
    wet = np.zeros(grid.ncells, bool)
    for c in np.unique(np.searchsorted(start, np.nonzero(kind == 0)[0], side="right") - 1):
        wet |= (np.abs(ijk - ijk[c]) <= 1).all(axis=1)
    assert 0 < wet.sum() < grid.ncells
    assert np.array_equal(near.astype(bool), wet)
    cell_of = np.searchsorted(start, np.arange(n), side="right") - 1
    d, _ = cKDTree(pos[kind == 0]).query(pos, k=1)
    assert (near[cell_of[d < grid.cell]] == 1).all() and (near[cell_of] == 0).any()
