"""Sloshing and base-excitation validations (cosim.validations.sloshing): the analytic
references against the refdata tables, the FFT peak finder, and the quick runs."""

import math

import numpy as np
import pytest

from cosim import refdata, validation
from cosim.validations.sloshing import (run_spheric10, running_mean_max, sloshing_omega,
                                        spectral_peak, spheric10_motion, spheric10_pressure,
                                        westergaard_parabola, westergaard_series)


def test_westergaard_series_and_parabola_match_the_refdata_table():
    tab = np.loadtxt(refdata.path("analytic_hydrodynamics", "westergaard_vertical_dam_Cp.csv"), delimiter=",",
                     comments="#", skiprows=5)
    np.testing.assert_allclose(westergaard_series(tab[:, 0], 1.0), tab[:, 1], atol=2e-5)
    np.testing.assert_allclose(westergaard_parabola(tab[:, 0], 1.0), tab[:, 2], atol=1e-5)
    # base value 8 G / pi^2 (G Catalan's constant)
    assert westergaard_series(np.array([1.0]), 1.0)[0] == pytest.approx(8 * 0.915965594177219 / math.pi**2, abs=1e-5)


def test_compressible_and_finite_tank_limits():
    y = np.linspace(0, 2.0, 9)
    H, c, T = 2.0, 1430.0, 0.03
    # compressible factor 1 / c_n of each odd term (refdata SOURCE.txt A)
    m = np.arange(1, 800, 2)
    cn = np.sqrt(1 - (4 * H / (c * T)) ** 2 / m**2)
    want = 8 / math.pi**2 * (np.sin(np.outer(y, m) * math.pi / (2 * H)) / (m**2 * cn)).sum(axis=1)
    np.testing.assert_allclose(westergaard_series(y, H, c=c, period=T), want, atol=1e-4)
    # a long tank is the semi-infinite reservoir; a short one carries less (tanh(k L/2) < 1)
    np.testing.assert_allclose(westergaard_series(y, H, length=200.0), westergaard_series(y, H), atol=1e-12)
    assert westergaard_series(np.array([H]), H, length=3.0)[0] < westergaard_series(np.array([H]), H)[0] - 0.01
    with pytest.raises(ValueError, match="acoustic"):
        westergaard_series(y, H, c=100.0, period=0.01)


def test_sloshing_frequency_matches_the_housner_table():
    text = refdata.path("analytic_hydrodynamics", "sloshing_frequencies_housner.csv").read_text()
    rows = [r.split(",") for r in text.splitlines() if r.startswith("rectangular")]
    for r in rows:
        L, h, n, omega = float(r[1]), float(r[2]), int(r[3]), float(r[5])
        assert sloshing_omega(L, h, n) == pytest.approx(omega, rel=2e-5)


def test_spectral_peak_finds_a_decaying_tone_far_below_the_bin_width():
    t = np.arange(0, 8.0, 0.02)
    f0 = 0.8461557
    y = np.exp(-0.1 * t) * np.cos(2 * math.pi * f0 * t + 0.4) + 0.1 * np.cos(2 * math.pi * 2.3 * t)
    f, _, _ = spectral_peak(t, y, 0.4, 1.3)
    assert abs(f / f0 - 1) < 2e-3  # the bin width is 1/8 s^-1: 15 % of f0


def test_spheric10_roll_record():
    roll = spheric10_motion()
    th = np.array([roll.signal.state(t)[0] for t in np.linspace(0, 8, 801)])
    assert np.degrees(np.abs(th).max()) == pytest.approx(4.0, abs=0.1)
    # the record's positive angle lowers the left wall (impacts on the left follow it)
    pos, _ = roll(0.6, np.array([[0.0, 0.093], [0.9, 0.093]]))  # the tank's frame: inner corner at the origin
    assert pos[0, 1] < 0.093 - 0.02 and pos[1, 1] > 0.093 + 0.02
    p = spheric10_pressure()
    assert (np.diff(p[:, 0]) >= 0).all() and p[:, 1].max() == pytest.approx(7147.5, abs=1.0)


@pytest.mark.long
def test_westergaard_quick():
    r = validation.run("westergaard", quick=True)
    m = r["metrics"]
    assert r["passed"] and r["target"].startswith("quick: ")  # judged by its declared tolerances below
    # dx = 0.1 m (10 rows): first-order errors of ~dx/H (see the case's docstring)
    assert m["rms_face_vs_exact"] < 0.06
    assert m["kp_base_face"] == pytest.approx(m["kp_base_exact"], rel=0.06)
    assert m["kp_out_of_phase_max_avg"] < 0.05  # the impulsive pressure follows the acceleration
    assert m["rms_avg_vs_exact"] > m["rms_face_vs_exact"]  # the face correction helps
    # the stated target names plain Eq. 15; it stays in the record with its value beside the face's departure
    assert r["stated"]["tolerances"] == {"rms_raw_vs_exact": 0.04, "rms_avg_vs_exact": 0.02}
    assert r["stated"]["measured"]["rms_avg_vs_exact"] == m["rms_avg_vs_exact"]
    assert "carried to the wall face" in r["departure"]["criterion"]


@pytest.mark.slow  # 3-D, 1-2 CPU-minutes: out of CI's time (docs/development.md); the 2-D case stays
def test_westergaard_3d_quick():
    """A 0.3 m slice of the 3-D tank (dx = 0.075 m, c0 = 700 m/s, 1 + 1 periods, walls
    "adami") against the exact series and against the 2-D section run with the same
    settings: the flow is uniform across, so the 3-D profile is the 2-D one (measured:
    Eq. 15 within 0.008, face within 0.010 row by row; face RMS 0.0156 vs 0.0150 in 2-D)."""
    r = validation.run("westergaard-3d", quick=True)
    m = r["metrics"]
    assert r["passed"] and r["target"].startswith("quick: ")  # judged by its declared tolerances below
    # the stated target (raw < 0.04, plain Eq. 15 < 0.02 RMS) is not met at this resolution, and says so
    assert r["stated"]["tolerances"] == {"rms_raw_vs_exact": 0.04, "rms_avg_vs_exact": 0.02}
    assert r["stated"]["met"] is False and "carried to the wall face" in r["departure"]["criterion"]
    assert r["particles"] > 5000 and m["width_m"] == 0.3
    assert m["rms_face_vs_exact"] < 0.07
    assert m["kp_base_face"] == pytest.approx(m["kp_base_exact"], rel=0.06)
    assert m["kp_out_of_phase_max_avg"] < 0.08  # the impulsive pressure follows the acceleration
    assert m["rms_avg_vs_exact"] > m["rms_face_vs_exact"]  # the face correction helps
    assert m["kp_avg_vs_2d_max"] < 0.03 and m["kp_face_vs_2d_max"] < 0.05


def test_running_mean_max():
    """A 10 ms box of 1 kPa: its largest 20 ms mean is 0.5 kPa, centred anywhere the
    window covers the box (the first such centre is taken)."""
    t = np.linspace(0.0, 1.0, 4001)
    p = np.where((t >= 0.5) & (t < 0.51), 1000.0, 0.0)
    v, tc = running_mean_max(t, p, 0.02, 0.3, 0.7)
    assert v == pytest.approx(500.0, rel=0.03) and 0.495 <= tc <= 0.516


@pytest.mark.long
def test_spheric10_quick():
    r = validation.run("sloshing-spheric10", quick=True)
    m = r["metrics"]
    # 5 rows over the depth, walls="adami": the first swing's run-up (no impact yet) on the
    # wall patch within 20 % and 0.1 s (measured 0.93, -0.043 s; the face probe 1.07)
    assert m["walls"] == "adami" and m["sensor"] == "patch"
    assert r["passed"] and m["swing1_peak_err"] < 0.2 and m["swing1_lag_abs_s"] < 0.1


def test_spheric10_refuses_an_unknown_sensor():
    with pytest.raises(ValueError, match="patch"):
        run_spheric10(0.0186, t_end=0.01, sensor="wall")


@pytest.mark.long
def test_sloshing_frequency_quick():
    """h = 2 dx with walls="adami" (the case's set-up): measured -0.95 % at dx = h/10."""
    r = validation.run("sloshing-frequency", quick=True)
    assert r["passed"] and r["metrics"]["f1_rel_err"] < 0.02


@pytest.mark.slow
def test_sloshing_frequency_full():
    """dx = 0.025 m (20 rows), 8 free periods, the scene's set-up ("sloshing", fluid.solver.SLOSHING_2D):
    measured +0.84 %."""
    r = validation.run("sloshing-frequency", quick=False)
    assert r["passed"] and r["metrics"]["f1_rel_err"] < 0.02


@pytest.mark.long
def test_sloshing_frequency_with_the_default_settings_is_9_percent_high():
    """The solver's defaults (h = sqrt(2) dx, dynamic walls) on the same quick tank: the
    first mode is 9.4 % above linear theory (the case's docstring: the contact-line spring
    of dynamic walls and the lattice's pressure-borne shear stiffness). Kept as a test so
    that a change of the defaults shows here."""
    from cosim.validations.sloshing import run_sloshing_frequency

    m = run_sloshing_frequency(0.05, cycles_forced=2, cycles_free=4, c0_factor=10.0, setup="defaults")["metrics"]
    assert 0.05 < m["f1_signed_rel_err"] < 0.15


@pytest.mark.slow
def test_spheric10_first_impact():
    """dx = 3.1 mm (30 rows; the full case's resolution), to 2.7 s: the first impact on
    the case's sensor (the wall patch) against the measured record in its largest 20 ms
    mean (2.15 kPa measured), its impulse and its time (measured 1.053, 0.921, +0.025 s;
    ~12 min; at 6.2 mm the 20 ms mean is 0.796, converging). Its peak is not asserted: it
    moves between 0.28 and 6.4 of the measured one with c0, alpha, delta, MLS and dx (see
    the case's docstring)."""
    m = run_spheric10(0.0031, t_end=2.7)["metrics"]
    assert abs(m["impact1_mean20ms_ratio"] - 1) < 0.2
    assert abs(m["impact1_impulse_ratio"] - 1) < 0.2
    assert abs(m["impact1_lag_s"]) < 0.05


@pytest.mark.slow
def test_westergaard_3d_full():
    """The whole 3.0 x 1.0 x 1.5 m tank at dx = 0.05 m with walls="adami", 1 + 1 periods
    (the case's set-up): both targets of the 2-D case on the mid-plane (see the case's
    docstring for the measured figures), and the rows next to the side walls within 0.02
    of the mid-plane's (the flow is uniform across in theory; 0.010 at dx = 0.1 m)."""
    r = validation.run("westergaard-3d")
    m = r["metrics"]
    assert r["passed"] and m["rms_raw_vs_exact"] < 0.04 and m["rms_face_vs_exact"] < 0.02
    # plain Eq. 15 (the stated target's): 0.035 measured, kept visible
    assert r["stated"]["measured"]["rms_avg_vs_exact"] == m["rms_avg_vs_exact"]
    assert m["kp_base_face"] == pytest.approx(m["kp_base_exact"], rel=0.03)
    assert m["kp_face_side_vs_mid_max"] < 0.02 and r["particles"] == 44628


@pytest.mark.slow
def test_westergaard_full():
    """dx = 0.025 m (40 rows) with walls="adami" (the case's set-up): the wall particles'
    own pressure meets the raw target (measured 0.018; 0.173 with the plain dynamic
    boundaries) and the pressure carried to the wall face the averaged one (0.009)."""
    r = validation.run("westergaard")
    m = r["metrics"]
    assert r["passed"] and m["rms_raw_vs_exact"] < 0.04 and m["rms_face_vs_exact"] < 0.02
