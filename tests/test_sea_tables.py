"""A many-component sea's kinematics at the near field's cost (fluid.sea_tables): the orbits
at fixed points equal the sea's own sums to round-off, the tabulated velocity is within its
stated interpolation error of them, and the near field's walls and zones use both."""

import math

import numpy as np
import pytest

from fluid.nearfield import following_wall, near_field_box, sea_velocity
from fluid.sea_tables import FRAMES_PER_PERIOD, NODES_PER_WAVELENGTH, PointOrbits, VelocityTable, tabulable
from fluid.waves import RegularWave, SpectralSea

#: a JONSWAP sea (200 components) heading 30° off x, faded in from a source at x = 0.5 m
SEA = SpectralSea(0.04, 1.2, 0.3, level=0.3, ramp=2.4, seed=3, duration=30.0, direction=30.0, source=0.5, g=9.81)


def _points(n, seed=0):
    rng = np.random.default_rng(seed)
    return rng.uniform(-0.5, 3.0, n), rng.uniform(-0.4, 0.4, n), rng.uniform(-0.05, 0.35, n)


def test_only_linear_many_component_seas_are_tabulated():
    assert tabulable(SEA)
    assert not tabulable(RegularWave(0.04, 1.2, 0.3, theory="linear"))
    assert not tabulable(RegularWave(0.04, 1.2, 0.3, theory="stokes2"))


@pytest.mark.parametrize("t", [0.7, 2.0, 3.3, 17.9])
def test_the_orbits_at_fixed_points_are_the_seas_own(t):
    """Displacement and rate as Sea.displacement (the same sums reordered); the acceleration
    as the central difference of its rate, during and after the fade-in (which has a front
    here: the source)."""
    x, y, z = _points(400)
    orbits = PointOrbits(SEA, x, y, z)
    d, r, a = orbits.motion(t)
    d0, r0 = SEA.displacement(x, y, z, t)
    np.testing.assert_allclose(d, d0, rtol=0, atol=1e-13 * np.abs(d0).max())
    np.testing.assert_allclose(r, r0, rtol=0, atol=1e-13 * np.abs(r0).max())
    eps = 1e-5
    fd = (SEA.displacement(x, y, z, t + eps)[1] - SEA.displacement(x, y, z, t - eps)[1]) / (2 * eps)
    np.testing.assert_allclose(a, fd, rtol=0, atol=1e-6 * np.abs(fd).max())


def test_the_tabulated_velocity_is_within_its_interpolation_error():
    """Linear interpolation in s, ζ and t with 24 nodes and 32 frames per shortest period: at
    most (2π/24)²/8 + (2π/32)²/8 = 1.4 % of the shortest components' velocity, which carry
    a small share of it; judged at 1 % of the largest velocity, points above the still
    water and below the seabed included (clipped as the sea clips them)."""
    assert (NODES_PER_WAVELENGTH, FRAMES_PER_PERIOD) == (24, 32)
    x, y, z = _points(3000, seed=1)
    e = SEA.heading
    s = x * e[0] + y * e[1]
    table = VelocityTable(SEA, s.min(), s.max())
    worst = 0.0
    for t in np.linspace(1.0, 25.0, 13) + 0.0037:
        v, v0 = table.velocity(x, y, z, t), SEA.velocity(x, y, z, t)
        worst = max(worst, np.abs(v - v0).max() / np.abs(v0).max())
    assert worst < 0.01
    assert worst > 1e-6  # an interpolation, not the sums themselves


def test_the_table_keeps_two_frames_and_clamps_beyond_its_range():
    table = VelocityTable(SEA, 0.0, 1.0)
    for t in np.arange(0.0, 3.0, 0.001):
        table.velocity(np.array([0.5]), np.zeros(1), np.array([0.2]), t)
    assert len(table._frames) <= 3
    far = table.velocity(np.array([5.0]), np.zeros(1), np.array([0.2]), 3.0)
    edge = table.velocity(np.array([1.0 / SEA.heading[0]]), np.zeros(1), np.array([0.2]), 3.0)
    np.testing.assert_allclose(far, edge, atol=1e-15)


@pytest.mark.parametrize("sea", [SpectralSea(0.04, 1.2, 0.3, level=0.3, ramp=2.4, seed=3, duration=30.0, g=9.81),
                                 RegularWave(0.04, 1.2, 0.3, level=0.3, ramp=2.4, theory="stokes2")])
def test_a_following_wall_has_the_orbits_and_their_exact_acceleration(sea):
    ref = np.column_stack([np.full(30, -0.02), np.linspace(0.01, 0.45, 30)])
    wall = following_wall(sea)
    for t in (1.3, 6.1):
        pos, vel = wall(t, ref)
        d, r = sea.displacement(ref[:, 0], 0.0 * ref[:, 0], ref[:, 1], t)
        np.testing.assert_allclose(pos - ref, d[:, [0, 2]], atol=1e-13)
        np.testing.assert_allclose(vel, r[:, [0, 2]], atol=1e-13)
        eps = 1e-5
        fd = (wall(t + eps, ref)[1] - wall(t - eps, ref)[1]) / (2 * eps)
        np.testing.assert_allclose(wall.particle_acceleration(t, ref), fd, atol=1e-6 * np.abs(fd).max())


def test_the_near_field_zones_read_a_many_component_sea_from_a_table():
    sea = SpectralSea(0.04, 1.2, 0.3, level=0.3, ramp=2.4, seed=3, duration=30.0, g=9.81)
    box = near_field_box(0.02, 0.0, 3.0, sea, 0.5, 0.8)
    lo, hi = box.reach(sea)
    assert lo < 0.0 and hi > 3.0
    pts = box.fluid[box.fluid[:, 0] < 0.8]
    v = sea_velocity(sea, drift=False, reach=(lo, hi))(pts, 7.0)
    v0 = sea.velocity(pts[:, 0], 0.0, pts[:, 1], 7.0)[:, [0, 2]]
    assert np.abs(v - v0).max() < 0.01 * np.abs(v0).max()
    assert math.isclose(np.abs(v).max(), np.abs(v0).max(), rel_tol=0.01)
