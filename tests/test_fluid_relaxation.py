"""Relaxation zones (fluid.relaxation): the rate profile of Jacobsen et al. (2012) applied
exactly over a step, to fluid particles only."""

import math

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.particles import Kind
from fluid.relaxation import Slab


def _particles(n=41, dim=2, seed=0):
    rng = np.random.default_rng(seed)
    pos = np.zeros((n, dim))
    pos[:, 0] = np.linspace(-1.0, 3.0, n)
    vel = rng.normal(size=(n, dim))
    kind = np.full(n, Kind.FLUID, np.int8)
    kind[::7] = Kind.FIXED_WALL
    return pos, vel, kind


def _weight(chi):
    return (np.exp(chi ** 3.5) - 1.0) / (math.e - 1.0)


@pytest.mark.parametrize("inner, outer", [(0.0, 2.0), (2.0, 0.0)])
def test_damping_to_rest_is_the_exact_exponential_of_the_weighted_rate(inner, outer):
    pos, vel, kind = _particles()
    v0 = vel.copy()
    zone = Slab(0, inner, outer, rate=7.0)
    zone.apply(pos, vel, kind, t=0.0, dt=0.03)
    chi = np.clip((pos[:, 0] - inner) / (outer - inner), 0.0, 1.0)
    expect = v0 * np.exp(-7.0 * _weight(chi) * 0.03)[:, None]
    expect[kind != Kind.FLUID] = v0[kind != Kind.FLUID]
    np.testing.assert_allclose(vel, expect, rtol=1e-13, atol=0)
    # outside the zone (chi = 0) nothing moves; beyond the outer edge the full rate acts
    assert np.array_equal(vel[chi == 0], v0[chi == 0])
    far = (chi == 1) & (kind == Kind.FLUID)
    np.testing.assert_allclose(vel[far], v0[far] * math.exp(-7.0 * 0.03), rtol=1e-13)


def test_the_result_does_not_depend_on_the_step():
    pos, vel, kind = _particles(dim=3)
    a, b = vel.copy(), vel.copy()
    zone = Slab(0, 0.5, 2.5, rate=4.0)
    zone.apply(pos, a, kind, 0.0, 0.1)
    for _ in range(10):
        zone.apply(pos, b, kind, 0.0, 0.01)
    np.testing.assert_allclose(a, b, rtol=1e-12)


def test_a_target_velocity_is_approached_exactly_and_the_second_array_alike():
    pos, vel, kind = _particles()
    extra = vel.copy() + 1.0
    v0, e0 = vel.copy(), extra.copy()

    def target(p, t):
        return np.stack([np.sin(p[:, 0] + t), np.cos(p[:, 0])], axis=1)

    zone = Slab(0, 0.0, 2.0, rate=3.0, target=target)
    zone.apply(pos, vel, kind, t=0.4, dt=0.05, extra=extra)
    chi = np.clip(pos[:, 0] / 2.0, 0.0, 1.0)
    f = np.exp(-3.0 * _weight(chi) * 0.05)[:, None]
    vt = target(pos, 0.4)
    inside = (chi > 0) & (kind == Kind.FLUID)
    np.testing.assert_allclose(vel[inside], (vt + (v0 - vt) * f)[inside], rtol=1e-13)
    np.testing.assert_allclose(extra[inside], (vt + (e0 - vt) * f)[inside], rtol=1e-13)
    assert np.array_equal(vel[~inside], v0[~inside])
    # after a long time the velocity is the target's
    for _ in range(200):
        zone.apply(pos, vel, kind, 0.4, 1.0)
    far = (chi == 1) & (kind == Kind.FLUID)
    np.testing.assert_allclose(vel[far], vt[far], atol=1e-12)


@pytest.mark.parametrize("kwargs, field", [
    (dict(axis=0, inner=1.0, outer=1.0, rate=1.0), "width"),
    (dict(axis=0, inner=0.0, outer=1.0, rate=0.0), "rate"),
    (dict(axis=0, inner=0.0, outer=math.nan, rate=1.0), "outer"),
    (dict(axis=-1, inner=0.0, outer=1.0, rate=1.0), "axis"),
    (dict(axis=0, inner=0.0, outer=1.0, rate=1.0, target=3.0), "target"),
])
def test_bad_zones_are_refused(kwargs, field):
    with pytest.raises(InputError, match=field):
        Slab(**kwargs)
