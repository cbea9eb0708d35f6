"""Linear wavemaker theory; paddle motions (piston, flap, recorded) for the SPH fluid."""

import math

import numpy as np
import pytest

from cosim import refdata
from cosim.errors import InputError
from fluid.wavemaker import MotionRecord, RegularWavemaker, flap, height_to_stroke, piston, wavenumber


@pytest.mark.parametrize("T, d", [(1.0, 0.5), (5.0, 3.0), (20.0, 30.0), (0.5, 100.0)])
def test_wavenumber_satisfies_the_dispersion_relation(T, d):
    k = wavenumber(T, d)
    assert (2 * math.pi / T) ** 2 == pytest.approx(9.81 * k * math.tanh(k * d), rel=1e-14)


def test_deep_and_shallow_limits():
    assert wavenumber(0.5, 100.0) == pytest.approx((2 * math.pi / 0.5) ** 2 / 9.81, rel=1e-12)  # deep
    T, d = 60.0, 1.0
    assert wavenumber(T, d) == pytest.approx(2 * math.pi / (T * math.sqrt(9.81 * d)), rel=1e-3)  # shallow
    assert height_to_stroke("piston", 20.0) == pytest.approx(2.0, rel=1e-12)
    assert height_to_stroke("flap", 20.0) == pytest.approx(2.0 * (1 - 1 / 20.0), rel=1e-7)  # 2 (1 - 1/kd)
    assert height_to_stroke("piston", 1e-3) == pytest.approx(1e-3, rel=1e-5)  # H/S -> kd
    assert height_to_stroke("flap", 1e-3) == pytest.approx(0.5e-3, rel=1e-5)  # H/S -> kd/2


@pytest.mark.parametrize("kind", ["piston", "flap"])
def test_deep_water_does_not_overflow(kind):
    """Beyond kd = 20 the ratio is the same function written without overflow: it joins the
    direct form there, and in water deep enough that sinh(2 kd) overflows (kd > 355) it is
    the deep-water limit (2; flap 2 (kd - 1) / kd)."""
    import math

    direct = {"piston": lambda x: 2.0 * (math.cosh(2 * x) - 1.0) / (math.sinh(2 * x) + 2.0 * x),
              "flap": lambda x: 4.0 * (math.sinh(x) / x) * (x * math.sinh(x) - math.cosh(x) + 1.0)
              / (math.sinh(2 * x) + 2.0 * x)}[kind]
    for kd in (20.0 + 1e-9, 25.0, 100.0):
        assert height_to_stroke(kind, kd) == pytest.approx(direct(kd), rel=1e-13)
    for kd in (400.0, 1e6):
        limit = 2.0 if kind == "piston" else 2.0 * (kd - 1.0) / kd
        assert height_to_stroke(kind, kd) == pytest.approx(limit, rel=1e-15)
    wm = RegularWavemaker(kind, 0.01, 0.3, 30.0)  # kd = 1340: the stroke is H / 2
    assert wm.k * wm.depth > 355 and wm.stroke == pytest.approx(0.01 / height_to_stroke(kind, wm.k * wm.depth))


def test_transfer_functions_grow_with_kd_and_a_flap_makes_smaller_waves():
    """A flap moves less water at depth than a piston of the same stroke: its
    waves are smaller, by half in shallow water and alike in deep water."""
    kd = np.linspace(0.01, 6.0, 300)
    piston = np.array([height_to_stroke("piston", x) for x in kd])
    flap = np.array([height_to_stroke("flap", x) for x in kd])
    assert np.all(np.diff(piston) > 0) and np.all(np.diff(flap) > 0)
    assert np.all(flap < piston)
    assert flap[0] / piston[0] == pytest.approx(0.5, rel=1e-3)
    assert height_to_stroke("flap", 40.0) / height_to_stroke("piston", 40.0) == pytest.approx(1.0, abs=0.03)


def test_motion_ramps_in_smoothly_and_reaches_the_stroke():
    wm = RegularWavemaker("piston", H=0.1, T=2.0, depth=1.0, ramp=2.0)
    t = np.linspace(0.0, 20.0, 20001)
    x, v = wm.motion(t)
    assert x[0] == 0.0 and v[0] == 0.0
    late = t > 4.0
    assert x[late].max() == pytest.approx(0.5 * wm.stroke, rel=1e-6)
    np.testing.assert_allclose(np.gradient(x, t)[1:-1], v[1:-1], atol=2e-6 * wm.stroke / wm.T * 1e3)
    flap = RegularWavemaker("flap", H=0.1, T=2.0, depth=1.0)
    th, _ = flap.motion(np.array([10.5, 11.5]))  # crests of sin(pi t)
    assert th[0] == pytest.approx(0.5 * flap.stroke / 1.0, rel=1e-12) and th[1] == pytest.approx(-th[0])


def test_bad_input():
    with pytest.raises(InputError, match="piston' or 'flap'"):
        RegularWavemaker("plunger", 0.1, 2.0, 1.0)
    with pytest.raises(InputError, match="H must be"):
        RegularWavemaker("piston", -0.1, 2.0, 1.0)
    with pytest.raises(InputError, match="breaking limit"):
        RegularWavemaker("piston", 1.0, 1.0, 1.0)
    with pytest.raises(InputError, match="finite and > 0"):
        wavenumber(0.0, 1.0)


# -- paddle motions for the SPH fluid --------------------------------------------------------------

def test_piston_translates_and_flap_rotates_rigidly():
    ref = np.array([[-0.01, 0.0], [-0.01, 0.2], [-0.03, 0.4]])
    pos, vel = piston(lambda t: (0.02, -0.3))(1.0, ref)
    np.testing.assert_allclose(pos, ref + [0.02, 0.0], rtol=0, atol=1e-15)
    np.testing.assert_allclose(vel, [[-0.3, 0.0]] * 3, rtol=0, atol=1e-15)
    th, w = 0.1, 0.5
    hinge = np.array([0.0, 0.05])
    pos, vel = flap(lambda t: (th, w), hinge=hinge)(0.0, ref)
    r0, r1 = ref - hinge, pos - hinge
    np.testing.assert_allclose(np.linalg.norm(r1, axis=1), np.linalg.norm(r0, axis=1), rtol=1e-14)  # rigid
    # the top of the flap (above the hinge) turns towards +x by theta
    top = np.arctan2(r1[2, 0], r1[2, 1]) - np.arctan2(r0[2, 0], r0[2, 1])
    assert top == pytest.approx(th, rel=1e-12)
    np.testing.assert_allclose(vel, w * np.stack([r1[:, 1], -r1[:, 0]], axis=1), rtol=1e-14)  # omega x r
    p3, _ = flap(lambda t: (th, w), hinge=hinge)(0.0, np.insert(ref, 1, 7.0, axis=1))  # 3-D: y untouched
    np.testing.assert_allclose(p3[:, [0, 2]], pos, rtol=1e-14)
    assert (p3[:, 1] == 7.0).all()


@pytest.mark.parametrize("kind", ["piston", "flap"])
def test_paddle_velocity_is_the_derivative_of_its_position(kind):
    wm = RegularWavemaker(kind, H=0.05, T=1.2, depth=0.4, ramp=1.0)
    ref = np.array([[-0.005, 0.1], [-0.005, 0.35]])
    m = wm.paddle()
    t, e = 0.9, 1e-6
    fd = (m(t + e, ref)[0] - m(t - e, ref)[0]) / (2 * e)
    np.testing.assert_allclose(m(t, ref)[1], fd, rtol=1e-6, atol=1e-9)
    if kind == "flap":  # the theory's flap: x at the still-water level = theta * depth
        x_swl = m(3.3, np.array([[0.0, 0.4]]))[0][0, 0]
        assert x_swl == pytest.approx(math.sin(wm.motion(3.3)[0]) * 0.4, rel=1e-12)


def test_motion_record_interpolates_its_samples_and_holds_outside():
    t = np.linspace(0.0, 2.0, 201)
    rec = MotionRecord(t, np.sin(3 * t), scale=2.0)
    np.testing.assert_allclose(rec(t)[0], 2 * np.sin(3 * t), atol=1e-14)
    tm = np.linspace(0.05, 1.95, 37)
    np.testing.assert_allclose(rec(tm)[1], 6 * np.cos(3 * tm), atol=1e-4)
    assert rec(5.0) == (pytest.approx(2 * math.sin(6.0)), 0.0)
    with pytest.raises(InputError, match="increase strictly"):
        MotionRecord([0, 1, 1, 2], [0, 0, 0, 0])
    with pytest.raises(InputError, match="no file"):
        MotionRecord.from_file("/nonexistent/flap.dat")


def test_the_hadzic_flap_record_reads_as_published():
    rec = MotionRecord.from_file(refdata.path("floating_box_waves_hadzic2005", "CaseFloatingWavesVal_Flap.dat"),
                                 scale=math.pi / 180)
    assert rec.t[0] == 0.0 and rec.t[-1] == pytest.approx(10.9, abs=1e-6) and len(rec.t) == 10901
    assert math.degrees(rec.value.min()) == pytest.approx(-4.670678616, rel=1e-9)  # at t = 5.023 s
    assert math.degrees(rec(5.023)[0]) == pytest.approx(-4.670678616, rel=1e-6)


def test_bad_paddle_input():
    with pytest.raises(InputError, match="callable"):
        piston(0.1)
    with pytest.raises(InputError, match="hinge"):
        flap(lambda t: (0, 0), hinge=(0.0, 0.0, 0.0))
