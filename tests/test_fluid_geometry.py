"""Geometry builders: lattice counts, wall layers, overlap removal."""

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.geometry import assemble, block, tank_walls, tank_with_water
from fluid.particles import Kind


def test_block_lattice():
    p = block([0, 0], [0.1, 0.05], 0.01)
    assert p.shape == (50, 2)
    np.testing.assert_allclose(p.min(0), [0.005, 0.005])
    np.testing.assert_allclose(p.max(0), [0.095, 0.045])
    assert block([0, 0, 0], [0.1, 0.1, 0.1], 0.02).shape == (125, 3)


@pytest.mark.parametrize("layers", [1, 3])
def test_tank_wall_counts(layers):
    dx, L, Hw = 0.01, 0.4, 0.25
    w = tank_walls([0, 0], [L, Hw], dx, layers)
    # open top: a (L + 2 n dx) x n dx floor plus two n dx x Hw sides
    nL, nH = round(L / dx), round(Hw / dx)
    assert len(w) == (nL + 2 * layers) * layers + 2 * layers * nH
    # every wall particle is outside the wetted box, the nearest ones dx/2 from its faces
    inside = np.all((w > 0) & (w < [L, Hw]), axis=1)
    assert not inside.any()
    np.testing.assert_allclose(w[:, 1].min(), -(layers - 0.5) * dx)
    w3 = tank_walls([0, 0, 0], [0.1, 0.08, 0.1], 0.02, 2)
    assert len(w3) == (5 + 4) * (4 + 4) * 2 + 5 * (2 * (5 + 4) * 2 + 2 * 4 * 2)


def test_tank_with_water_2d_and_3d():
    b = tank_with_water(2, 0.01, 0.4, 0.2, 0.25)
    ps = b.particles
    assert b.removed_overlap == 0
    assert (ps.kind == Kind.FLUID).sum() == 40 * 20
    np.testing.assert_allclose(ps.mass, 1000 * 0.01**2)
    b3 = tank_with_water(3, 0.02, 0.2, 0.1, 0.14, width=0.1)
    assert (b3.particles.kind == Kind.FLUID).sum() == 10 * 5 * 5
    with pytest.raises(InputError):
        tank_with_water(3, 0.02, 0.2, 0.1, 0.14)  # no width


def test_fluid_overlapping_a_wall_is_removed_and_counted():
    dx = 0.01
    walls = tank_walls([0, 0], [0.2, 0.2], dx, 2)
    # a fluid block that extends 3 dx into the left wall and 1 dx below the floor,
    # shifted by a quarter spacing so that it is not aligned with the wall lattice
    fl = block([-0.03, -0.01], [0.1, 0.1], dx) + 0.25 * dx
    b = assemble(2, dx, 1000.0, fl, [(walls, Kind.FIXED_WALL, 0)])
    kept = b.particles.pos[b.particles.kind == Kind.FLUID]
    assert b.removed_overlap + len(kept) == len(fl)
    # everything inside the wall region went, and nothing further than dx from it
    assert (kept.min(0) > 0).all()
    in_wall_region = np.any(fl < 0, axis=1)
    assert b.removed_overlap >= in_wall_region.sum()
    d = np.min(np.linalg.norm(kept[:, None] - walls[None], axis=2), axis=1)
    assert d.min() >= 0.9 * dx
