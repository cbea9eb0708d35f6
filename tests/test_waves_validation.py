"""The wave and moored-body SPH validation cases (cosim.validations.waves), quick variants."""

import pytest

from cosim.validation import run as run_case
from cosim.validations.waves import HZ_DIR, moored_equilibrium


def test_moored_equilibrium_balances_the_forces():
    """Lines without weight would leave the box at its Archimedes height; heavier
    lines pull it down, by their vertical force over rho g B."""
    from moorings.catenary import solve

    z_free = 0.3 + 0.05 - 0.5 * 0.1
    z = moored_equilibrium(0.2, 0.1, 500.0, 0.5, 0.52, 40.0, 0.3)
    V = solve(0.4, z - 0.05, 0.52, 40.0).V
    assert z_free - z == pytest.approx(2 * V / (1000 * 9.81 * 0.2), rel=1e-9)
    assert moored_equilibrium(0.2, 0.1, 500.0, 0.5, 0.52, 1e-6, 0.3) == pytest.approx(z_free, abs=1e-9)


def test_moored_body_sph_quick():
    r = run_case("moored-body-sph", quick=True)
    assert r["passed"], r["metrics"]
    # the lines pull the box 14 mm below free floating: SPH finds most of it
    assert r["metrics"]["mean_z_last_s_m"] < r["metrics"]["free_floating_z_m"] - 0.007


@pytest.mark.slow
def test_moored_body_sph_full():
    r = run_case("moored-body-sph", quick=False)
    assert r["passed"], r["metrics"]


@pytest.mark.skipif(not HZ_DIR.is_dir(), reason="shared refdata not present")
def test_floating_box_waves_quick():
    r = run_case("floating-box-waves", quick=True)
    assert r["passed"], r["metrics"]


@pytest.mark.slow
@pytest.mark.skipif(not HZ_DIR.is_dir(), reason="shared refdata not present")
@pytest.mark.xfail(strict=True, reason="probes, heave and the sway amplitude are within 15 % (N1 +4 %, N2 -2 %, heave "
                   "+10.9 / -1.3 %, sway +4.5 %), but the sway maximum is 0.56 s early: the measured sway has two "
                   "nearly equal maxima (110 mm at 7.55 s, 116 mm at 8.14 s) and the SPH one is at 7.58 s; see the "
                   "case's docstring")
def test_floating_box_waves_full():
    r = run_case("floating-box-waves", quick=False)
    assert r["passed"], r["metrics"]
