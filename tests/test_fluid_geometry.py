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


@pytest.mark.parametrize("columns, built", [(15.3, 15), (15.5, 15), (15.7, 16), (16.0, 16)])
def test_a_tank_of_any_length_has_its_water_one_spacing_from_every_wall(columns, built):
    """Walls and water share one lattice: whatever the length (and width), the water fills
    every column inside the walls, so the last column and the far wall's first layer are one
    spacing apart (an empty column there lets the water at rest fall into it), and the tank
    is built the length rounded to whole spacings (a half rounds down)."""
    from fluid.geometry import lattice_extent

    dx = 0.02
    assert lattice_extent(columns * dx, dx) == pytest.approx(built * dx)
    for dim in (2, 3):
        ps = tank_with_water(dim, dx, columns * dx, 0.1, 0.14, width=columns * dx, layers=3).particles
        fluid, wall = ps.pos[ps.kind == Kind.FLUID], ps.pos[ps.kind != Kind.FLUID]
        for axis in range(dim - 1):
            assert (fluid[:, axis].max() + 0.5 * dx) == pytest.approx(built * dx)
            beside = wall[(wall[:, -1] > 0) & (wall[:, axis] > fluid[:, axis].max() + 0.5 * dx)]
            assert beside[:, axis].min() - fluid[:, axis].max() == pytest.approx(dx)
        assert len(fluid) == built ** (dim - 1) * 5


def test_a_tank_whose_length_is_not_whole_spacings_stays_at_rest():
    """The hydrostatic tank 15.7 spacings long, settled, then left alone for 1 s: its
    largest speed stays below 1 % of the long-wave speed sqrt(g d) (0.18 % measured; with
    the column at the far wall left empty, as before ``lattice_extent``, the water falls
    into it and turns the tank over: 8 %)."""
    from fluid.geometry import set_hydrostatic
    from fluid.solver import Fluid, FluidConfig

    dx, depth = 0.02, 0.1
    cfg = FluidConfig(dx=dx, u_max=(9.81 * depth) ** 0.5, h_coef=2.0, walls="adami", alpha=0.01)
    ps = tank_with_water(2, dx, 15.7 * dx, depth, 0.14, layers=4).particles
    set_hydrostatic(ps, depth, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    f.settle(0.5)
    f.advance(0.0, 1.0)
    assert f.max_speed() < 0.01 * (9.81 * depth) ** 0.5
