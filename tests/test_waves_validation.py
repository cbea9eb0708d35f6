"""The wave and moored-body SPH validation cases (cosim.validations.waves), quick variants."""

import pytest

from cosim.validation import run as run_case
from cosim.validations.waves import moored_equilibrium


def test_moored_equilibrium_balances_the_forces():
    """Lines without weight would leave the box at its Archimedes height; heavier
    lines pull it down, by their vertical force over rho g B."""
    from moorings.catenary import solve

    z_free = 0.3 + 0.05 - 0.5 * 0.1
    z = moored_equilibrium(0.2, 0.1, 500.0, 0.5, 0.52, 40.0, 0.3)
    V = solve(0.4, z - 0.05, 0.52, 40.0).V
    assert z_free - z == pytest.approx(2 * V / (1000 * 9.81 * 0.2), rel=1e-9)
    assert moored_equilibrium(0.2, 0.1, 500.0, 0.5, 0.52, 1e-6, 0.3) == pytest.approx(z_free, abs=1e-9)


@pytest.mark.long
def test_moored_body_sph_quick():
    r = run_case("moored-body-sph", quick=True)
    assert r["passed"], r["metrics"]
    # the lines pull the box 14 mm below free floating: SPH finds most of it
    assert r["metrics"]["mean_z_last_s_m"] < r["metrics"]["free_floating_z_m"] - 0.007


@pytest.mark.slow
def test_moored_body_sph_full():
    r = run_case("moored-body-sph", quick=False)
    assert r["passed"], r["metrics"]


def test_best_lag_finds_the_shift_of_a_history():
    """A chirp and its copy delayed by 60 ms (sampled apart, with a drift added): the lag
    of best correlation is the delay, to the scan's step; a copy ahead gives it negative."""
    import numpy as np

    from cosim.validations.waves import best_lag

    def chirp(t):
        return np.sin(2 * np.pi * (0.8 * t + 0.15 * t**2)) + 0.3 * t

    tm = np.linspace(6.3, 8.1, 91)
    t = np.linspace(5.0, 8.5, 3501)
    for delay in (0.06, -0.08):
        lag, r = best_lag(t, chirp(t - delay), tm, chirp(tm))
        assert lag == pytest.approx(delay, abs=0.002) and r > 0.999


@pytest.mark.long
def test_floating_box_waves_quick():
    r = run_case("floating-box-waves", quick=True)
    assert r["passed"], r["metrics"]


@pytest.mark.slow
def test_floating_box_waves_full():
    """dx = 1 cm (13 min of one core): heave +10.9 / -1.3 %, sway +4.5 %, lags of best
    correlation +0.012 s and +0.002 s (measured; see the case's docstring)."""
    r = run_case("floating-box-waves", quick=False)
    assert r["passed"], r["metrics"]
