"""Active absorption at the near field's end walls (fluid.wall_absorption): the elevation read
from the free surface, the control law against its closed form, and the zones that let the
walls' correction pass."""

import math

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.nearfield import FollowingWall, near_field_box
from fluid.wall_absorption import AbsorbingEnd
from fluid.waves import RegularWave, wavenumbers

SEA = RegularWave(0.006, 4.0, 0.3, level=0.3, ramp=4.0)


@pytest.mark.parametrize("dim", [2, 3])
def test_the_elevation_is_the_free_surfaces_over_the_strip(dim):
    """Water at rest 2 cm above the sea's still level (0.3 m) in a tank: the wall's gauges
    (fluid.probes.surface_elevation, the flat surface dx / 2 above the top row, to a
    hundredth of dx) read 2 cm beyond the still level, whatever their weights; beyond the sea, that less the sea's
    elevation averaged at the gauges with the same weights."""
    from fluid.geometry import assemble, block, tank_walls
    from fluid.particles import Kind
    from fluid.solver import Fluid, FluidConfig

    dx = 0.01
    lo = np.zeros(dim)
    hi = np.array([0.4, 0.45] if dim == 2 else [0.4, 0.1, 0.45])
    top = hi.copy()
    top[-1] = 0.32
    b = assemble(dim, dx, 1000.0, block(lo, top, dx), [(tank_walls(lo, hi, dx), Kind.FIXED_WALL, 0)])
    f = Fluid(FluidConfig(dim=dim, dx=dx, c0=20.0, threads=1), b.particles)
    f.initialize(0.0)
    xs = np.array([0.12, 0.15, 0.18])
    g = xs if dim == 2 else np.column_stack([xs, np.full(3, 0.05)])
    for w in ([1 / 3] * 3, [0.2, 0.5, 0.3]):
        end = AbsorbingEnd(SEA, FollowingWall(SEA), 1, g, w)
        assert end.elevation(f) == pytest.approx(0.02, abs=dx / 100)
        t = 9.3
        sea = np.dot(w, SEA.elevation(xs, np.zeros(3), np.full(3, t)))
        assert abs(sea) > 1e-4 and end.beyond_sea(f, t) - end.elevation(f) == pytest.approx(-sea, abs=1e-15)


def test_the_wall_moves_with_the_depth_averaged_velocity_of_a_wave_leaving_the_box():
    """Fed an elevation ``eta_s = A cos(omega t)`` beyond the sea's, the wall's correction
    velocity settles to ``s G`` times it through the two low-passes of time constant
    ``tau_fast`` and the two first-order filters of ``tau`` (the mean taken off, the leak of
    xi): ``s G (i w tau / (1 + i w tau))^2 / (1 + i w tau_fast)^2``,
    ``G = omega / (k d)`` the depth-averaged velocity of a progressive wave per unit
    elevation (its volume flux c eta over the depth); the far end (s = +1) moves with a
    wave leaving along +x, the near end against it. A constant offset does not move it."""
    w = 2 * math.pi / SEA.peak_period
    g_expected = w / (float(wavenumbers(w, 0.3)) * 0.3)
    amp, offset, dt = 1e-3, -2e-3, 1e-3
    for side in (1, -1):
        end = AbsorbingEnd(SEA, FollowingWall(SEA), side, [0.15], [1.0])
        assert end.gain == pytest.approx(g_expected, rel=1e-12)
        ts = np.arange(dt, 20 * end.tau, dt)
        rates = np.empty(ts.size)
        for i, t in enumerate(ts):
            end.beyond_sea = lambda fluid, t: offset + amp * math.cos(w * t)
            end.update(None, t, dt)
            rates[i] = end.rate
        late = ts > 10 * end.tau
        a = np.column_stack([np.cos(w * ts[late]), np.sin(w * ts[late])])
        c, *_ = np.linalg.lstsq(a, rates[late], rcond=None)
        got = complex(c[0], -c[1])
        wt, wf = 1j * w * end.tau, 1j * w * end.tau_fast
        np.testing.assert_allclose(got, side * g_expected * amp * (wt / (1 + wt)) ** 2 / (1 + wf) ** 2, rtol=5e-3)
        assert abs(end.xi(ts[-1])) < 2 * amp * g_expected / w  # bounded: the offset does not accumulate


def test_the_wall_keeps_the_orbits_and_adds_its_correction():
    ref = np.array([[0.0, 0.29], [0.0, 0.1]])
    orbits = FollowingWall(SEA)
    end = AbsorbingEnd(SEA, orbits, -1, [0.15], [1.0])
    end.load_state({"t_n": 5.0, "xi_n": 0.003, "rate": -0.01, "mean": 0.0, "eta_s": 0.0, "fast": [0.0, 0.0]})
    pos, vel = end(5.5, ref)
    p0, v0 = orbits(5.5, ref)
    np.testing.assert_allclose(pos - p0, [[0.003 - 0.005, 0.0]] * 2, atol=1e-15)
    np.testing.assert_allclose(vel - v0, [[-0.01, 0.0]] * 2, atol=1e-15)
    assert end.save_state()["xi_n"] == 0.003
    with pytest.raises(InputError, match="side"):
        AbsorbingEnd(SEA, orbits, 0, [0.15], [1.0])
    with pytest.raises(InputError, match="weights"):
        AbsorbingEnd(SEA, orbits, 1, [0.15, 0.16], [0.5, 0.6])


def test_the_end_zones_let_the_walls_correction_pass():
    """The zone inside each absorbing end wall relaxes towards the sea's velocity plus that
    wall's correction velocity; the gauges lie in front of the walls, beyond the sea's
    excursion, inside the zones (3-D: across the width, a support from the side walls, from
    a symmetry plane itself)."""
    box = near_field_box(0.02, 0.0, 2.0, SEA, 0.45, 0.4, layers=4)
    near, far = box.absorbing_ends(SEA, 0.02, 0.028)
    assert near.side == -1 and far.side == 1
    assert 0.02 < near.gauges.min() < near.gauges.max() < 0.4 and 1.6 < far.gauges.min() < far.gauges.max() < 1.98
    for y, mirror, first in (((0.0, 0.3), False, 0.056), ((0.0, 0.3), True, 0.0)):
        box3 = near_field_box(0.02, 0.0, 2.0, SEA, 0.45, 0.4, layers=4, y=y, side_zone=0.1, mirror=mirror)
        g = box3.absorbing_ends(SEA, 0.02, 0.028)[1].gauges
        assert g[:, 1].min() == pytest.approx(first) and g[:, 1].max() == pytest.approx(0.3 - 0.056)
    near.rate, far.rate = 0.01, -0.02
    plain = box.zones(SEA, 5.0, drift=False)
    zones = box.zones(SEA, 5.0, drift=False, ends=(near, far))
    pos = np.array([[0.1, 0.15], [1.9, 0.15]])
    for z0, z, extra in zip(plain, zones, (0.01, -0.02)):
        np.testing.assert_allclose(z.target(pos, 7.0) - z0.target(pos, 7.0), [[extra, 0.0]] * 2, atol=1e-15)


def test_both_end_walls_read_their_strips_in_one_pass_as_each_would_alone():
    """The box's two end walls share one reader (one surface pass a step): each reads what a
    wall with a reader of its own gauges reads, to the bit; the reading is taken again once
    the fluid's particles move (a new sort), and the sea's at a new time."""
    from fluid.geometry import assemble, tank_walls
    from fluid.particles import Kind
    from fluid.solver import Fluid, FluidConfig

    dx = 0.02
    box = near_field_box(dx, 0.0, 2.0, SEA, 0.45, 0.4, layers=4)
    near, far = box.absorbing_ends(SEA, dx, 2 * dx)
    assert near.reader is far.reader
    lo, hi = np.array([-0.1, 0.0]), np.array([2.1, 0.45])
    b = assemble(2, dx, 1000.0, box.fluid[box.fluid[:, 1] < 0.32 - 0.05 * box.fluid[:, 0]],
                 [(tank_walls(lo, hi, dx), Kind.FIXED_WALL, 0)])
    f = Fluid(FluidConfig(dim=2, dx=dx, c0=20.0, threads=1), b.particles)
    f.initialize(0.0)
    read = [end.beyond_sea(f, 3.1) for end in (near, far)]
    alone = [AbsorbingEnd(SEA, FollowingWall(SEA), e.side, e.gauges, e.weights).beyond_sea(f, 3.1) for e in (near, far)]
    assert read == alone and read[0] - read[1] > 0.05  # the surface slopes down along x
    f.advance(0.0, 0.02)
    again = AbsorbingEnd(SEA, FollowingWall(SEA), 1, far.gauges, far.weights)
    assert far.beyond_sea(f, 3.3) == again.beyond_sea(f, 3.3) != read[1]
    with pytest.raises(InputError, match="rows"):
        AbsorbingEnd(SEA, FollowingWall(SEA), 1, far.gauges, far.weights, reader=near.reader, rows=slice(0, 4))
