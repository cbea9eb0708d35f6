"""A flume's absorbing zone (``domain.absorber``): built as a relaxation zone towards rest at
the far end, and, run, reflecting a few per cent of the piston's wave where the bare far wall
reflects nearly all of it (two-gauge-array separation, Mansard & Funke 1980)."""

import math

import numpy as np
import pytest

from cosim.scene import SPH, Absorber, Flume, Piston, Probes, Scene, World
from cosim.scene.build import build
from cosim.validations.wave_propagation import harmonics, separate
from fluid.wavemaker import RegularWavemaker

DEPTH, PERIOD, HEIGHT = 0.3, 1.0, 0.03
#: the piston wave's wavenumber [rad/m] (linear dispersion) and wavelength [m]
K = RegularWavemaker("piston", HEIGHT, PERIOD, DEPTH, 1.0, 9.81).k
L = 2.0 * math.pi / K


def flume_scene(absorber, dx=0.03, duration=0.1, gauges=(0.6,)):
    return Scene(name="absorber", world=World(dim=2, duration=duration, sample_every=PERIOD / 32),
                 fluid=SPH(dx=dx), domain=Flume(length=4.8, depth=DEPTH, height=0.45, absorber=absorber),
                 waves=Piston(height=HEIGHT, period=PERIOD, ramp=1.0), probes=Probes(gauges=list(gauges)))


def test_the_absorber_is_a_zone_at_the_far_end_relaxing_at_twice_the_wave_frequency(tmp_path):
    got = build(flume_scene(Absorber(length=2.0)), tmp_path)
    (zone,) = got.sph.zones
    assert (zone.axis, zone.inner, zone.outer) == (0, pytest.approx(2.8), 4.8)
    assert zone.rate == pytest.approx(4.0 * math.pi / PERIOD)
    given = build(flume_scene(Absorber(length=1.0, rate=3.0)), tmp_path / "given")
    assert given.sph.zones[0].rate == 3.0 and given.sph.zones[0].inner == pytest.approx(3.8)
    assert build(flume_scene(None), tmp_path / "none").sph.zones == []


def _reflection(absorber, tmp_path):
    """The reflected over the incident first harmonic at five gauges a quarter wavelength
    apart around x = 1.2 m, over 11-14 s (the front back from the far wall by then)."""
    xs = 1.2 + np.linspace(-0.25, 0.25, 5) * L
    res = flume_scene(absorber, duration=14.0, gauges=xs).run(tmp_path, progress=False, yes=True)
    late = res.t >= 11.0 - 1e-9
    eta = np.column_stack([res[f"gauge{j + 1}.eta"][late] for j in range(len(xs))])
    inc, refl = separate(xs, harmonics(res.t[late], eta, 2.0 * math.pi / PERIOD), K)
    return abs(refl) / abs(inc)


@pytest.mark.slow
def test_the_absorber_takes_the_wave_the_bare_wall_sends_back(tmp_path):
    # 1.5 wavelengths at twice the wave frequency: the wave-propagation case's zone
    absorbed = _reflection(Absorber(length=1.5 * L), tmp_path / "absorber")
    bare = _reflection(None, tmp_path / "bare")
    assert absorbed < 0.05
    assert bare > 0.5
