"""The catenary mooring participant: world-frame fairlead forces in 2-D and 3-D."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cosim.coupler import Coupler
from cosim.errors import InputError, TautLineError
from cosim.protocol import Mooring, check_participant
from moorings import CatenaryMooring, MooringLine
from moorings.catenary import solve


def spread_3d(n=3, radius=80.0, depth=50.0, L=100.0, w=500.0, EA=None):
    lines = [
        MooringLine((radius * math.cos(a), radius * math.sin(a), -depth), L, w, EA)
        for a in np.linspace(0, 2 * math.pi, n, endpoint=False)
    ]
    return CatenaryMooring(lines)


def test_force_is_horizontal_tension_towards_anchor_and_weight_down():
    line = MooringLine((100.0, 20.0, -50.0), 120.0, 800.0, name="bow")
    m = CatenaryMooring([line], fairleads=[[10.0, -10.0, 0.0]])
    d = np.array([10.0 - 100.0, -10.0 - 20.0])
    X = np.linalg.norm(d)
    ref = solve(X, 50.0, 120.0, 800.0)
    f = m.fairlead_forces()[0]
    np.testing.assert_allclose(f[:2], -ref.H * d / X, rtol=1e-14)
    assert f[2] == -ref.V
    assert m.lines[0].name == "bow"
    np.testing.assert_allclose(m.fairlead_tensions(), [math.hypot(ref.H, ref.V)])
    assert m.anchor_tensions()[0] == pytest.approx(ref.H)  # on the seabed, frictionless


def test_2d_lines_in_the_xz_plane():
    m = CatenaryMooring(
        [MooringLine((-55.0, -50.0), 90.0, 5000.0), MooringLine((55.0, -50.0), 90.0, 5000.0)],
        fairleads=[[3.0, 0.0], [3.0, 0.0]],
    )
    f = m.fairlead_forces()
    a, b = solve(58.0, 50.0, 90.0, 5000.0), solve(52.0, 50.0, 90.0, 5000.0)
    np.testing.assert_array_equal(f, [[-a.H, -a.V], [b.H, -b.V]])
    F, My = m.total_wrench([3.0, 0.0])
    assert F[0] == pytest.approx(b.H - a.H) and My == pytest.approx(0.0, abs=1e-9)
    F, My = m.total_wrench([3.0, -2.0])  # fairleads 2 m above the point
    assert My == pytest.approx(2.0 * F[0])  # M_y = r_z F_x - r_x F_z


def test_same_line_in_2d_and_3d_gives_the_same_force():
    m2 = CatenaryMooring([MooringLine((0.0, -30.0), 60.0, 100.0, 1e6)], fairleads=[[40.0, 0.0]])
    m3 = CatenaryMooring([MooringLine((0.0, 0.0, -30.0), 60.0, 100.0, 1e6)], fairleads=[[40.0, 0.0, 0.0]])
    f2, f3 = m2.fairlead_forces()[0], m3.fairlead_forces()[0]
    assert (f2[0], f2[1]) == (f3[0], f3[2]) and f3[1] == 0.0


@settings(max_examples=200, deadline=None)
@given(
    angle=st.floats(0, 2 * math.pi),
    X=st.floats(0.0, 95.0),
    h=st.floats(0.0, 60.0),
    ax=st.floats(-1e3, 1e3),
    ay=st.floats(-1e3, 1e3),
    EA=st.one_of(st.none(), st.floats(1e3, 1e12)),
)
def test_3d_force_is_invariant_under_rotation_about_z(angle, X, h, ax, ay, EA):
    L, w = 100.0, 300.0
    if EA is None and math.hypot(X, h) >= L:
        return  # taut inextensible: no solution, tested elsewhere
    c, s = math.cos(angle), math.sin(angle)
    base = CatenaryMooring([MooringLine((ax, ay, -h), L, w, EA)], fairleads=[[ax + X, ay, 0.0]])
    rot = CatenaryMooring([MooringLine((ax, ay, -h), L, w, EA)], fairleads=[[ax + c * X, ay + s * X, 0.0]])
    f0, f1 = base.fairlead_forces()[0], rot.fairlead_forces()[0]
    Rf0 = np.array([c * f0[0] - s * f0[1], s * f0[0] + c * f0[1], f0[2]])
    np.testing.assert_allclose(f1, Rf0, rtol=1e-9, atol=1e-9 * (abs(f0).max() + w * L))


def test_symmetric_spread_mooring_has_zero_net_horizontal_force():
    m = spread_3d(n=4)
    m.set_fairlead_motion(np.zeros((4, 3)))
    F, M = m.total_wrench([0.0, 0.0, 0.0])
    assert abs(F[0]) < 1e-9 * abs(F[2]) and abs(F[1]) < 1e-9 * abs(F[2])
    assert np.allclose(M, 0.0, atol=1e-9 * abs(F[2]))
    # an offset along +x is pulled back along -x
    m.set_fairlead_motion(np.tile([5.0, 0.0, 0.0], (4, 1)))
    F, _ = m.total_wrench([5.0, 0.0, 0.0])
    assert F[0] < 0 and abs(F[1]) < 1e-9 * abs(F[0])


def test_protocol_and_coupler_run():
    m = spread_3d()
    check_participant(m, Mooring)
    with pytest.raises(InputError, match="fairlead positions are not set"):
        m.initialize(0.0)
    m.set_fairlead_motion(np.zeros((3, 3)))
    assert m.max_dt() == math.inf
    f0 = m.fairlead_forces()
    state = m.save_state()
    m.set_fairlead_motion(np.tile([1.0, 0.0, 0.0], (3, 1)))
    m.load_state(state)
    np.testing.assert_array_equal(m.fairlead_forces(), f0)
    c = Coupler([m], dt=0.1)
    assert c.run(1.0) == 10 and m.t == pytest.approx(1.0)


def test_taut_inextensible_line_raises_naming_the_line():
    m = CatenaryMooring([MooringLine((0.0, -50.0), 60.0, 10.0, name="stern")])
    with pytest.raises(TautLineError, match=r"line 'stern'.*length 60 m.*span 61\.0\d* m.*EA"):
        m.set_fairlead_motion([[35.0, 0.0]])
    m = CatenaryMooring([MooringLine((0.0, -50.0), 60.0, 10.0, EA=1e6, name="stern")])
    m.set_fairlead_motion([[35.0, 0.0]])  # elastic: stretched, finite
    assert np.isfinite(m.fairlead_forces()).all()


@pytest.mark.parametrize(
    "fairleads, match",
    [
        ([[0.0, 0.0, 0.0]], r"shape \(2, 3\)"),
        ([[0.0, 0.0, 0.0], [1.0, 2.0]], "shape"),
        ([[0.0, 0.0, 0.0], [np.nan, 0.0, 0.0]], "line 'line1'.*not finite"),
        ([[0.0, 0.0, 0.0], [0.0, 0.0, -60.0]], "line 'line1'.*below the seabed"),
    ],
)
def test_bad_fairleads_are_refused(fairleads, match):
    m = CatenaryMooring([MooringLine((50.0, 0.0, -50.0), 80.0, 10.0), MooringLine((-50.0, 0.0, -50.0), 80.0, 10.0)])
    with pytest.raises(InputError, match=match):
        m.set_fairlead_motion(fairleads)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(anchor=(0.0, 0.0), length=-1.0, weight=1.0), "length = -1.0 m"),
        (dict(anchor=(0.0, 0.0), length=1.0, weight=0.0), "weight = 0.0 N/m"),
        (dict(anchor=(0.0, 0.0), length=1.0, weight=1.0, EA=-5.0), "EA = -5.0 N.*EA=None"),
        (dict(anchor=(0.0, np.nan), length=1.0, weight=1.0), "anchor"),
        (dict(anchor=(0.0,), length=1.0, weight=1.0), "anchor"),
        (dict(anchor=(0.0, 0.0), length="long", weight=1.0, name="x"), "line 'x': length must be a number"),
    ],
)
def test_bad_line_parameters_are_refused(kwargs, match):
    with pytest.raises(InputError, match=match):
        MooringLine(**kwargs)


def test_mixed_dimensions_and_duplicate_names_are_refused():
    with pytest.raises(InputError, match="same dimension"):
        CatenaryMooring([MooringLine((0.0, 0.0), 1.0, 1.0), MooringLine((0.0, 0.0, 0.0), 1.0, 1.0)])
    with pytest.raises(InputError, match="repeated: a"):
        CatenaryMooring([MooringLine((0.0, 0.0), 1.0, 1.0, name="a"), MooringLine((1.0, 0.0), 1.0, 1.0, name="a")])
    with pytest.raises(InputError, match="at least one"):
        CatenaryMooring([])
