"""Cell-linked list against brute force (DESIGN.md, validation tier 1)."""

import numpy as np
import pytest

from fluid.neighbours import Grid, neighbour_pairs, sort_by_cell


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


def test_outside_particles_are_counted_and_sorted_last():
    pos = np.array([[0.5, 0.5], [2.0, 0.5], [0.2, -0.1], [0.9, 0.9]])
    grid = Grid.covering([0, 0], [1, 1], 0.25)
    perm, start, outside = sort_by_cell(pos, grid)
    assert outside == 2
    assert set(perm[-2:].tolist()) == {1, 2}
