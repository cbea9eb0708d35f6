"""Active absorption at the near field's end walls (fluid.wall_absorption): the elevation read
from the water's volume, the control law against its closed form, and the zones that let
the walls' correction pass."""

import math
from types import SimpleNamespace

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.nearfield import FollowingWall, near_field_box
from fluid.wall_absorption import AbsorbingEnd
from fluid.waves import RegularWave, wavenumbers

SEA = RegularWave(0.006, 4.0, 0.3, level=0.3, ramp=4.0)


def water(dx, x0, x1, top, dim=2, y=(0.0, 0.1), rho=1000.0):
    """Fluid particles on a lattice filling x0..x1 (3-D: across y) from the bed z = 0 to
    ``top``, each of mass rho dx^dim (a ``ps``-like namespace)."""
    xs = np.arange(x0 + 0.5 * dx, x1, dx)
    zs = np.arange(0.5 * dx, top, dx)
    if dim == 2:
        pos = np.array([(x, z) for x in xs for z in zs])
    else:
        ys = np.arange(y[0] + 0.5 * dx, y[1], dx)
        pos = np.array([(x, yy, z) for x in xs for yy in ys for z in zs])
    n = len(pos)
    return SimpleNamespace(pos=pos, mass=np.full(n, rho * dx ** dim), rho=np.full(n, rho), kind=np.zeros(n, np.int8),
                           ids=np.arange(n))


@pytest.mark.parametrize("dim", [2, 3])
def test_the_elevation_is_the_waters_volume_over_the_strip(dim):
    """A column of water 0.32 m deep over the bed (level 0.3 m): 2 cm above the still level,
    read over a strip whose ends lie on the lattice's cell faces (the sine-squared weight's
    discrete sum is then exactly its integral); 3-D over the box's width; compressed water
    (a density 1 % above the particles' nominal one) stands lower by its volume; a mirror
    image (negative id) or a wall particle inside the strip is not counted."""
    dx = 0.01
    ps = water(dx, 0.0, 0.4, 0.32, dim)
    end = AbsorbingEnd(SEA, FollowingWall(SEA), 1, (0.1, 0.2), 0.1 if dim == 3 else 1.0, 0.0)
    assert end.elevation(ps) == pytest.approx(0.02, abs=1e-12)
    squeezed = SimpleNamespace(**{**vars(ps), "rho": ps.rho * 1.01})
    assert end.elevation(squeezed) == pytest.approx(0.32 / 1.01 - 0.3, abs=1e-12)
    extra = SimpleNamespace(**{k: np.concatenate([v, v[:1]]) for k, v in vars(ps).items()})
    extra.pos[-1] = ps.pos[0] + np.r_[0.15, np.zeros(dim - 1)]
    extra.ids[-1] = -1
    assert end.elevation(extra) == pytest.approx(0.02, abs=1e-12)
    extra.ids[-1], extra.kind[-1] = 5, 1
    assert end.elevation(extra) == pytest.approx(0.02, abs=1e-12)


def test_the_wall_moves_with_the_depth_averaged_velocity_of_a_wave_leaving_the_box():
    """Fed an elevation ``eta_s = A cos(omega t)`` beyond the sea's, the wall's correction
    velocity settles to ``s G`` times it through the two first-order filters of time
    constant ``tau`` (the mean taken off, the leak of xi): ``s G (i w tau / (1 + i w tau))^2``,
    ``G = omega / (k d)`` the depth-averaged velocity of a progressive wave per unit
    elevation (its volume flux c eta over the depth); the far end (s = +1) moves with a
    wave leaving along +x, the near end against it. A constant offset does not move it."""
    w = 2 * math.pi / SEA.peak_period
    g_expected = w / (float(wavenumbers(w, 0.3)) * 0.3)
    amp, offset, dt = 1e-3, -2e-3, 1e-3
    for side in (1, -1):
        end = AbsorbingEnd(SEA, FollowingWall(SEA), side, (0.1, 0.2), 1.0, 0.0)
        assert end.gain == pytest.approx(g_expected, rel=1e-12)
        ts = np.arange(dt, 20 * end.tau, dt)
        rates = np.empty(ts.size)
        for i, t in enumerate(ts):
            end.beyond_sea = lambda ps, t: offset + amp * math.cos(w * t)
            end.update(None, t, dt)
            rates[i] = end.rate
        late = ts > 10 * end.tau
        a = np.column_stack([np.cos(w * ts[late]), np.sin(w * ts[late])])
        c, *_ = np.linalg.lstsq(a, rates[late], rcond=None)
        got = complex(c[0], -c[1])
        wt = 1j * w * end.tau
        np.testing.assert_allclose(got, side * g_expected * amp * (wt / (1 + wt)) ** 2, rtol=5e-3)
        assert abs(end.xi(ts[-1])) < 2 * amp * g_expected / w  # bounded: the offset does not accumulate


def test_the_wall_keeps_the_orbits_and_adds_its_correction():
    ref = np.array([[0.0, 0.29], [0.0, 0.1]])
    orbits = FollowingWall(SEA)
    end = AbsorbingEnd(SEA, orbits, -1, (0.1, 0.2), 1.0, 0.0)
    end.load_state({"t_n": 5.0, "xi_n": 0.003, "rate": -0.01, "mean": 0.0, "eta_s": 0.0})
    pos, vel = end(5.5, ref)
    p0, v0 = orbits(5.5, ref)
    np.testing.assert_allclose(pos - p0, [[0.003 - 0.005, 0.0]] * 2, atol=1e-15)
    np.testing.assert_allclose(vel - v0, [[-0.01, 0.0]] * 2, atol=1e-15)
    assert end.save_state()["xi_n"] == 0.003
    with pytest.raises(InputError, match="side"):
        AbsorbingEnd(SEA, orbits, 0, (0.1, 0.2), 1.0, 0.0)
    with pytest.raises(InputError, match="strip"):
        AbsorbingEnd(SEA, orbits, 1, (0.2, 0.1), 1.0, 0.0)


def test_the_end_zones_let_the_walls_correction_pass():
    """The zone inside each absorbing end wall relaxes towards the sea's velocity plus that
    wall's correction velocity; the strips lie in front of the walls, beyond the sea's
    excursion."""
    box = near_field_box(0.02, 0.0, 2.0, SEA, 0.45, 0.4, layers=4)
    near, far = box.absorbing_ends(SEA, 0.02, 0.028)
    assert near.side == -1 and far.side == 1
    assert 0.0 < near.strip[0] < near.strip[1] < 0.4 and 1.6 < far.strip[0] < far.strip[1] < 2.0
    near.rate, far.rate = 0.01, -0.02
    plain = box.zones(SEA, 5.0, drift=False)
    zones = box.zones(SEA, 5.0, drift=False, ends=(near, far))
    pos = np.array([[0.1, 0.15], [1.9, 0.15]])
    for z0, z, extra in zip(plain, zones, (0.01, -0.02)):
        np.testing.assert_allclose(z.target(pos, 7.0) - z0.target(pos, 7.0), [[extra, 0.0]] * 2, atol=1e-15)
