"""Waves that keep their height (cosim.validations.wave_propagation): the incident/reflected
separation, the viscous decay's closed forms, and the quick case."""

import math

import numpy as np
import pytest

from cosim import validation
from cosim.validations.wave_propagation import harmonics, separate, upward_crossings, viscous_decay_per_wavelength
from cosim.validations.waves import viscous_decay
from fluid.wavemaker import wavenumber


def test_incident_and_reflected_waves_are_separated_exactly():
    """eta = Re(A_i e^{i(wt - kx)} + A_r e^{i(wt + kx)}) sampled over two periods at five
    gauges over half a wavelength: the fit of the harmonics, then the separation, give back
    both complex amplitudes to round-off."""
    k, w = 4.0, 2.0 * math.pi
    Ai, Ar = 0.02 * np.exp(0.3j), 0.003 * np.exp(-1.1j)
    x = 1.0 + np.linspace(-0.25, 0.25, 5) * 2 * math.pi / k
    t = np.linspace(0.0, 2.0, 65)[:, None]
    eta = np.real(Ai * np.exp(1j * (w * t - k * x)) + Ar * np.exp(1j * (w * t + k * x))) + 0.001
    eta = eta + 0.004 * np.cos(2 * w * t - 2 * k * x)  # a second harmonic does not leak in
    a = harmonics(t[:, 0], eta, w)
    got_i, got_r = separate(x, a, k)
    assert abs(got_i - Ai) < 1e-14 and abs(got_r - Ar) < 1e-14


def test_upward_crossings_are_a_sine_waves_to_the_interpolations_error():
    """A sine of period 0.7 s (phase 0.3 rad) sampled every T/32: its upward zero crossings at
    (2 pi n - 0.3) / omega, to the linear interpolation's error (sub-1e-4 T near a zero),
    and none at the downward ones."""
    T, phase = 0.7, 0.3
    t = np.arange(0.0, 5.0, T / 32)
    y = np.sin(2 * np.pi * t / T + phase)
    exact = (np.arange(1, 8) * 2 * np.pi - phase) * T / (2 * np.pi)
    got = upward_crossings(t, y)
    assert got.shape == exact[exact < t[-1]].shape
    assert np.abs(got - exact[exact < t[-1]]).max() < 1e-4 * T


def test_the_interior_decay_is_lambs_and_the_floor_adds_its_boundary_layer():
    """Interior: 1 - exp(-2 nu k^2 L / c_g) (Lamb 1932 §348, cosim.validations.waves.viscous_decay
    per metre); the floor's laminar boundary layer adds sqrt(nu omega / 2) omega^2 /
    (2 g c_g sinh^2 kd) per metre, which falls as sqrt(nu), the interior as nu."""
    nu, T, d = 6.4e-4, 1.0, 0.3
    L = 2 * math.pi / wavenumber(T, d, 9.81)
    assert viscous_decay_per_wavelength(nu, T, d, floor=False) == pytest.approx(
        -math.expm1(-viscous_decay(nu, T, d) * L), rel=1e-12)
    floor = [-math.log1p(-viscous_decay_per_wavelength(n, T, d, True)) + math.log1p(
        -viscous_decay_per_wavelength(n, T, d, False)) for n in (nu, nu / 4)]
    assert floor[0] / floor[1] == pytest.approx(2.0, rel=1e-12)


@pytest.mark.slow  # out of CI's time (docs/development.md); the coarse piston waves and the
# near field's box stay in the long tier
def test_quick_waves_keep_their_height_over_three_wavelengths():
    """cosim validate wave-propagation --quick: 10 rows over the depth, the scenes' wave
    set-up; judged on its declared tolerances (2.5 % per wavelength, 5 % of a period,
    reflection 5 %)."""
    r = validation.run("wave-propagation", quick=True)
    assert r["passed"], r["outside_tolerance"]
    m = r["metrics"]
    assert 0.0 < m["decay_per_wavelength_10"] < 0.025
    assert m["k_over_linear_10"] == pytest.approx(1.0, abs=0.01)


def test_the_linear_reference_is_the_paddles_wave_behind_its_front():
    """linear_elevation: far behind the ramp's front, the first harmonic at every gauge is
    the wave of linear wavemaker theory (height H, phase k x behind the paddle's); ahead of
    the front the water is still."""
    from cosim.validations.wave_propagation import linear_elevation
    from fluid.wavemaker import RegularWavemaker

    wm = RegularWavemaker("piston", H=0.04, T=1.0, depth=0.3, ramp=1.0)
    x = np.array([1.0, 1.3, 2.0])
    t = 20.0 + np.arange(64) / 32.0
    a = harmonics(t, linear_elevation(wm, x, t), 2 * math.pi)
    np.testing.assert_allclose(np.abs(a), 0.02, rtol=2e-3)
    # the phase falls by k per metre along x, from the paddle's velocity's: eta = Re(a e^{iwt})
    # with the paddle at x = 0 moving as (S/2) sin(wt), i.e. velocity (S w/2) cos(wt)
    np.testing.assert_allclose(np.angle(a * np.exp(1j * wm.k * x)), 0.0, atol=2e-3)
    ahead = linear_elevation(wm, np.array([30.0]), np.array([5.0]))
    assert abs(ahead[0, 0]) < 1e-4


def test_the_figures_of_linear_theorys_own_wave_are_linear_theory():
    """flume_figures read at the case's gauges (five across each of 8 stations) from linear
    theory's wave itself, long after the ramp's front has passed: every station's height
    and phase are theory's, no decay, no reflection, theory's wavenumber."""
    from cosim.validations.wave_propagation import _wave, flume_figures, linear_elevation, station_gauges

    wm, L, _ = _wave(0.04, 1.0, 0.3)
    ts = 40.0 + np.arange(97) / 32.0
    eta = linear_elevation(wm, station_gauges(L, 8), ts)
    f = flume_figures(ts, eta, wm, 8)
    np.testing.assert_allclose(f["H1_over_H"], 1.0, atol=1e-9)
    np.testing.assert_allclose(f["phase_lag_periods"], 0.0, atol=1e-9)
    assert abs(f["decay_per_wavelength"]) < 1e-9 and f["reflection"] < 1e-5
    assert f["k_over_linear"] == pytest.approx(1.0, abs=1e-9)
    np.testing.assert_allclose(f["stations_m"], L * np.arange(1, 9))


@pytest.mark.long
def test_a_kept_flume_run_is_read_back_with_the_same_figures(tmp_path, monkeypatch, caplog):
    """run_scene in a kept folder (the full variant's, resumable across processes): run
    once, then read back, not run, with the same figures and its CPU as read back; read
    back by other code, the run is warned of and named as that code's."""
    from cosim import version
    from cosim.validations.wave_propagation import run_scene, wave_scene

    scene = wave_scene(10, 2).with_values(["world.duration=2.0"])
    first = run_scene(scene, tmp_path / "kept")
    again = run_scene(scene, tmp_path / "kept")
    assert first["read_back_cpu_s"] == 0.0 and first["cpu_s"] > 0.0
    assert again["cpu_s"] == 0.0 and again["read_back_cpu_s"] == pytest.approx(first["cpu_s"])
    for k in ("H1_over_H", "phase_lag_periods", "reflection"):
        np.testing.assert_array_equal(again[k], first[k])
    assert first["read_back_other_code"] is None and again["read_back_other_code"] is None
    made_by = version.code_version()
    monkeypatch.setattr(version, "code_version", lambda: "0123456789abcdef")
    with caplog.at_level("WARNING", logger="cosim.validations.case_scene"):
        later = run_scene(scene, tmp_path / "kept")
    assert later["read_back_other_code"] == made_by and "made by other code" in caplog.text
    np.testing.assert_array_equal(later["H1_over_H"], first["H1_over_H"])


def test_the_3d_flume_is_the_2d_flume_extruded_with_its_gauges_on_the_mid_line():
    """wave_scene's 3-D flume (the full variant's): the 2-D scene's flume, wave, spacing,
    set-up and duration, ``width_rows`` rows wide, each gauge at the 2-D one's x on the
    mid-line."""
    from cosim.validations.wave_propagation import wave_scene

    flat, deep = wave_scene(10, 3), wave_scene(10, 3, 5)
    assert (flat.world.dim, deep.world.dim) == (2, 3)
    assert deep.domain.width == pytest.approx(5 * flat.fluid.dx)
    assert [g[0] for g in deep.probes.gauges] == list(flat.probes.gauges)
    assert [g[1] for g in deep.probes.gauges] == pytest.approx([0.5 * deep.domain.width] * len(flat.probes.gauges))
    for part in ("fluid", "waves"):
        assert getattr(deep, part) == getattr(flat, part)
    assert (deep.domain.length, deep.domain.depth, deep.domain.absorber) == (
        flat.domain.length, flat.domain.depth, flat.domain.absorber)
    assert deep.world.duration == flat.world.duration


def test_the_flume_is_sampled_over_the_periods_asked_for():
    """propagate passes its settle and fit periods to read_flume: the samples (kept with
    ``series``) run every T/32 over the last ``fit_periods`` of a run that ends
    ``settle_periods + fit_periods`` after the ramp's front has passed the last station."""
    from cosim.validations.wave_propagation import _duration, propagate
    from fluid.solver import travelling_waves

    r = propagate(0.3 / 4, 0.3, 0.04, 1.0, wavelengths=2, settle_periods=0.5, fit_periods=1.0, series=True,
                  **travelling_waves(4))
    t_end = _duration(0.04, 1.0, 0.3, 2, 0.5, 1.0)
    assert r["t_end_s"] == pytest.approx(t_end)
    np.testing.assert_allclose(r["ts"], t_end - 1.0 + np.arange(33) / 32.0, atol=1e-9)
    assert r["eta"].shape == (33, 10) and np.all(np.abs(r["eta"]) < 0.04)


def test_the_fronts_tail_has_passed_every_station_when_the_case_reads_it():
    """The case reads its 8 stations over the last periods of a run that ends four periods
    after the ramp's front (at the group velocity) has passed the last one. Linear theory's
    own wave, read there, is within 0.25 % of its steady height at every station with the
    case's ramp (WP_RAMP periods); with a ramp of one period, read as long after it ends,
    its front's dispersive tail still swings the far stations by more than 1 %, as much as
    the decay the case measures."""
    from cosim.validations.wave_propagation import (FIT_PERIODS, WP_RAMP, _duration, _wave, linear_elevation,
                                                    station_gauges)

    def worst_height_error(ramp: float) -> float:
        wm, L, _ = _wave(0.04, 1.0, 0.3, ramp)
        ts = _duration(0.04, 1.0, 0.3, 8) - (WP_RAMP - ramp) - FIT_PERIODS + np.arange(97) / 32.0
        x = station_gauges(L, 8)
        a = harmonics(ts, linear_elevation(wm, x, ts), 2 * math.pi).reshape(8, 5)
        incident = np.array([abs(separate(xs, z, wm.k)[0]) for xs, z in zip(x.reshape(8, 5), a)])
        return float(np.abs(incident / 0.02 - 1.0).max())

    assert worst_height_error(WP_RAMP) < 2.5e-3
    assert worst_height_error(1.0) > 0.01
