"""Validation cases of the SPH cable (VALIDATION.md: cable-case1, cable-exp2-static)."""

import math

import numpy as np
import pytest

from cosim import validation
from cosim.validations.cable import elastic_catenary


def test_elastic_catenary_reference_reproduces_refdata():
    """The independent exact solution in refdata/cable_static_dynamic (O'Brien & Francis cable)."""
    EA = 131e9 * 548.4e-6
    H0, Q0, p0 = elastic_catenary(304.8, 0.0, 312.73, 46.12, EA, s=[125.88])
    H1, Q1, p1 = elastic_catenary(304.8, 0.0, 312.73, 46.12, EA, loads=[(125.88, 35586.0)], s=[125.88])
    assert H0 == pytest.approx(17766.2, abs=0.1)
    assert -Q0 == pytest.approx(7211.6, abs=0.1)
    assert H1 == pytest.approx(89297.8, abs=0.1)
    assert -Q1 == pytest.approx(28695.3, abs=0.1)
    np.testing.assert_allclose(p0[0], [121.939, -29.329], atol=1e-3)
    np.testing.assert_allclose(p1[0], [121.078, -34.960], atol=1e-3)
    # inextensible limit: a symmetric catenary has the sag of z = a (cosh(x/a) - 1)
    H, Q, p = elastic_catenary(10.0, 0.0, 12.0, 2.0, 1e15, s=[6.0])
    a = H / 2.0
    assert -Q == pytest.approx(2.0 * 6.0, rel=1e-9)
    assert -p[0, 1] == pytest.approx(a * (math.cosh(5.0 / a) - 1), rel=1e-9)


def test_cable_case1_quick():
    r = validation.run("cable-case1", quick=True)
    m = r["metrics"]
    assert r["passed"], m
    assert abs(m["err_dz_vs_table2"]) < 0.005 and abs(m["err_dx_vs_table2"]) < 0.005
    assert abs(m["err_dz_vs_exact"]) < 0.005 and abs(m["err_dx_vs_exact"]) < 0.005
    assert m["H_loaded_N"] == pytest.approx(m["H_loaded_exact_N"], rel=1e-3)
    assert m["residual_speed_m_s"] < 1e-5


def test_cable_exp2_static_quick():
    """The case's scene (P0 a held body, the far support the line's anchor, no seabed, no
    water): the settled cable's pull on P0 and its anchor tension are the exact elastic
    catenary's, and P0's vertical pull and the anchor's share of the weight sum to it."""
    r = validation.run("cable-exp2-static", quick=True)
    m = r["metrics"]
    assert r["passed"], m
    assert m["reaction_x_P0_N"] == pytest.approx(-m["H_exact_N"], rel=0.01)
    assert m["anchor_tension_N"] == pytest.approx(m["anchor_tension_exact_N"], rel=0.01)
    V_anchor = math.sqrt(m["anchor_tension_N"] ** 2 - m["reaction_x_P0_N"] ** 2)
    assert m["reaction_z_P0_N"] + V_anchor == pytest.approx(0.338, rel=0.01)
    assert m["shape_max_err_m"] < 1e-3
    # the measured points lie 15-19 mm from the exact 1.272 m catenary (VALIDATION.md)
    assert all(0.010 < d < 0.025 for d in m["dist_to_measured_P1_P5_m"])


def test_cable_vs_catenary_quick():
    r = validation.run("cable-vs-catenary", quick=True)
    assert r["passed"], r["metrics"]
    assert r["metrics"]["max_abs_err_tension"] < 0.02


@pytest.mark.slow  # out of CI's time (docs/development.md)
def test_cable_exp2_shake_quick():
    """Dinçer & Demir 2020, Experiment 2 shaken: the free period within 7 % of the measured
    0.42 s on the length implied by the measured static shape (Table 5); at the
    stated 1.272 m the 1.5 Hz shake's is 8-9 % short, which the record reports beside it
    (the 1.0 Hz shake's strongest free motion there is the second mode's)."""
    r = validation.run("cable-exp2-shake", quick=True)
    m = r["metrics"]
    assert r["passed"], m
    assert abs(m["err_period_type1_measured_shape"]) < 0.07 and abs(m["err_period_type2_measured_shape"]) < 0.07
    assert 1.28 < m["length_fit_m"] < 1.29
    assert -0.10 < m["err_period_type2_stated"] < -0.07
    # mass damping: late motion decays like exp(-omega t / 2) (within 5 %)
    assert abs(m["rms_last2s_damped_over_undamped"] / m["expected_exp(-omega t/2)"] - 1) < 0.05


def test_cable_free_fall_quick():
    r = validation.run("cable-free-fall", quick=True)
    m = r["metrics"]
    assert r["passed"], m
    assert m["max_energy_rise_J"] <= 1e-6 * m["energy_scale_J"]
    assert 0.0 < m["dissipated_fraction_of_w_L_L"] < 0.1
    # the Table 4 points lie 7-10 mm off the 1 m catenary between the supports (measured)
    assert all(d < 0.012 for d in m["initial_vs_table4_m"])


@pytest.mark.slow
@pytest.mark.parametrize("name", ["cable-case1", "cable-exp2-static", "cable-vs-catenary", "cable-exp2-shake",
                                  "cable-free-fall"])
def test_cable_full(name):
    r = validation.run(name, quick=False)
    assert r["passed"], r["metrics"]
