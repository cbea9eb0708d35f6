"""The hollow catenary arch rib of 003_7c74773681ee080c.txt §4 in 2-D (span 140 m, rise
23.333 m, water to the design level 15.56 m): the arch axis against its closed forms, the
cavity's outline (constant inner height, area = height x axis length), its filling by
``polygon_tank`` (water in both legs only, symmetric), and the particle counts of the
paper's three resolutions (slow)."""

import math

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.particles import Kind
from fluid.shapes import arch_rib_cavity, catenary_arch_axis, polygon_tank, signed_area

SPAN, RISE, LEVEL = 140.0, 23.333, 15.56  # m (003 §4)
M, HC = 2.24, 1.458  # arch-axis coefficient [-] and inner height [m]: not in the paper's text (see below)


@pytest.mark.parametrize("m", [1.0, 1.347, 2.24, 3.5])
def test_catenary_axis_meets_its_closed_forms(m):
    """Springings at z = 0, crown at the rise, symmetric; the quarter-span height of a
    catenary arch, y_{l/4} / f = 1 / (sqrt(2 (m + 1)) + 2) below the crown (the textbook
    relation of the arch-axis coefficient; m = 1: 1/4, the parabola)."""
    a = catenary_arch_axis(SPAN, RISE, m, n=401)
    assert a[0] == pytest.approx((-SPAN / 2, 0.0), abs=1e-12) and a[-1] == pytest.approx((SPAN / 2, 0.0), abs=1e-12)
    assert a[200] == pytest.approx((0.0, RISE), abs=1e-12)
    np.testing.assert_allclose(a[::-1, 1], a[:, 1], atol=1e-12)
    quarter = a[100]
    assert quarter[0] == pytest.approx(-SPAN / 4)
    assert (RISE - quarter[1]) / RISE == pytest.approx(1 / (math.sqrt(2 * (m + 1)) + 2), rel=1e-12)


def test_catenary_axis_tends_to_the_parabola():
    np.testing.assert_allclose(catenary_arch_axis(SPAN, RISE, 1.0 + 1e-7), catenary_arch_axis(SPAN, RISE, 1.0),
                               atol=1e-5)


def _length(p):
    return float(np.hypot(*np.diff(p, axis=0).T).sum())


def test_cavity_has_a_constant_inner_height_and_the_area_of_a_band():
    """The faces are the axis offset by +-HC/2 along its normal: every vertex of one face
    lies HC from the other face, and the band's area is HC times the axis' length (the
    curvature terms of the two offsets cancel), to the polyline's resolution."""
    from fluid.shapes import distance_to_polyline

    v = arch_rib_cavity(SPAN, RISE, HC, M, n=801)
    lower, upper = v[:801], v[801:][::-1]
    d = distance_to_polyline(lower[5:-5], upper, closed=False)
    np.testing.assert_allclose(d, HC, rtol=1e-5)
    assert signed_area(v) > 0  # counter-clockwise: lower face left to right, upper back
    assert signed_area(v) == pytest.approx(HC * _length(catenary_arch_axis(SPAN, RISE, M, 801)), rel=1e-5)


def test_cavity_refuses_what_cannot_be_built():
    with pytest.raises(InputError, match="folds the lower face: the axis' smallest radius of curvature is"):
        arch_rib_cavity(SPAN, RISE, 300.0, M)
    with pytest.raises(InputError, match="arch-axis coefficient is >= 1"):
        catenary_arch_axis(SPAN, RISE, 0.5)
    with pytest.raises(InputError, match="inner_height=-1.0 m must be positive"):
        arch_rib_cavity(SPAN, RISE, -1.0, M)


def _clipped_area(v, level):
    """Area [m^2] of the polygon ``v`` below z = ``level`` (Sutherland-Hodgman clip by
    one half-plane, then the shoelace formula): the water's exact area."""
    out = []
    for a, b in zip(v, np.roll(v, -1, axis=0)):
        ina, inb = a[1] < level, b[1] < level
        if ina:
            out.append(a)
        if ina != inb:
            s = (level - a[1]) / (b[1] - a[1])
            out.append(a + s * (b - a))
    return signed_area(np.array(out))


def test_the_rib_fills_both_legs_to_the_design_level():
    """dx = 0.1 m: the water lies below 15.56 m in the two legs only (none over the
    crown), as much on each side within a row of particles, its area within 2 % of the
    exact wetted area; the walls (3 layers) follow the whole cavity."""
    dx = 0.1
    v = arch_rib_cavity(SPAN, RISE, HC, M)
    ps = polygon_tank(v, dx, LEVEL, layers=3).particles
    fl = ps.pos[ps.kind == Kind.FLUID]
    assert fl[:, 1].max() < LEVEL
    xs = catenary_arch_axis(SPAN, RISE, M, 4001)
    reach = xs[xs[:, 1] >= LEVEL + HC][:, 0]  # where even the lower face is above the level
    assert not ((fl[:, 0] > reach.min() + 1.0) & (fl[:, 0] < reach.max() - 1.0)).any()
    left, right = (fl[:, 0] < 0).sum(), (fl[:, 0] > 0).sum()
    assert abs(left - right) < HC / dx
    exact = _clipped_area(v, LEVEL)
    assert len(fl) * dx * dx == pytest.approx(exact, rel=0.02)
    walls = (ps.kind != Kind.FLUID).sum()
    assert walls == pytest.approx(3 * _length(np.vstack([v, v[:1]])) / dx, rel=0.02)


@pytest.mark.slow
def test_particle_counts_match_the_papers_three_resolutions():
    """With M = 2.24 and an inner height of 1.458 m (chosen so that the water's area is
    the paper's 36,910 x 0.05^2 = 92.3 m^2; the paper gives neither) and 3 wall layers,
    the counts of 003 §4.1 come out within 1 %: fluid 36,910 / 73,098 / 147,700 and
    boundary 18,159 / 25,665 / 36,287 at dx = 0.05, 0.05/sqrt(2), 0.025 m (measured
    36,826 / 73,694 / 147,390 and 18,204 / 25,818 / 36,440; 3, 4, 28 s to build here): the
    paper's walls line the whole cavity, crown included."""
    v = arch_rib_cavity(SPAN, RISE, HC, M)
    for dx, fluid, walls in ((0.05, 36910, 18159), (0.05 / math.sqrt(2), 73098, 25665), (0.025, 147700, 36287)):
        ps = polygon_tank(v, dx, LEVEL, layers=3).particles
        n = int((ps.kind == Kind.FLUID).sum())
        assert n == pytest.approx(fluid, rel=0.01) and ps.n - n == pytest.approx(walls, rel=0.01)
