"""Linear wavemaker theory."""

import math

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.wavemaker import RegularWavemaker, height_to_stroke, wavenumber


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
