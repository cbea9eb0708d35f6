"""The long-period tanks of Sunara et al. 2021 (cosim.validations.long_period): the frequency
fit, bad input, and the quick case."""

import numpy as np
import pytest

from cosim import validation
from cosim.errors import InputError
from cosim.validations import case_scene
from cosim.validations.long_period import (LINEAR_TOLERANCES, free_decay, free_frequency, long_period_scene,
                                          run_long_period)


def test_free_frequency_of_a_damped_wave_with_a_harmonic():
    t = np.arange(0.0, 6.7, 0.02)
    w = 2.9
    rng = np.random.default_rng(1)
    y = (0.06 * np.exp(-0.05 * t) * np.cos(w * t + 0.3) + 0.004 * np.cos(2 * w * t) + 0.01
         + 0.002 * rng.standard_normal(t.size))
    assert free_frequency(t, y, 2.83) == pytest.approx(w, rel=2e-3)
    # and its decay rate, found from a grid of rates (a wave damped 20 times faster)
    y = 0.06 * np.exp(-1.0 * t) * np.cos(w * t + 0.3) + 0.0005 * rng.standard_normal(t.size)
    assert free_decay(t, y, 2.83, rates=np.linspace(0.0, 2.0, 11)) == pytest.approx((w, 1.0), rel=1e-2)


def test_the_quick_variants_scene_is_the_file_and_each_tank_its_own():
    """The quick variant runs the case's scene file as written; the other tanks and regimes
    change its domain, dimension, spacing and shaking, held at rest after whole periods
    (the inclined tank settled 1 s first: its lattice water is not at rest on the slope)."""
    from cosim.scene.toml_io import to_dict

    assert to_dict(validation.cases()["long-period"].scene(True)) == to_dict(case_scene.load("long-period"))
    inclined = long_period_scene("inclined", 0.05, 2, a0=4.905)
    assert inclined.domain.kind == "inclined-tank" and inclined.domain.angle == 45.0
    assert inclined.fluid.settle == 1.0 and inclined.base_motion.acceleration == 4.905
    cyl = long_period_scene("cylinder", 0.06, 3)
    assert cyl.domain.kind == "cylinder-tank" and cyl.world.dim == 3 and cyl.base_motion.direction == (1.0, 0.0, 0.0)
    # 3 periods of 0.7 s, then 3 of the cylinder's first mode, to whole samples of 0.02 s
    assert cyl.base_motion.stop == pytest.approx(2.1) and cyl.base_motion.hold
    assert cyl.world.duration / 0.02 == pytest.approx(round(cyl.world.duration / 0.02), abs=1e-9)
    assert cyl.world.duration > 2.1 and cyl.fluid.settle == 0.0


def test_bad_input_is_refused_before_any_work():
    with pytest.raises(InputError, match="shape='square'"):
        run_long_period("square")
    with pytest.raises(InputError, match="cylinder is 3-D"):
        run_long_period("cylinder", dim=2)
    # 1.0 m of water at dx = 0.075 m: the lattice fills 13 rows (0.975 m), the gauges would read 25 mm low
    with pytest.raises(InputError, match=r"13.33 particle rows in the rectangular tank's depth 1 m.*1/13 = 0.07692 m"):
        run_long_period("rectangular", dx=0.075, dim=3)
    with pytest.raises(InputError, match=r"8.57 particle rows in the cylinder tank's depth 0.6 m"):
        run_long_period("cylinder", dx=0.07, dim=3)


@pytest.mark.slow  # out of CI's time (docs/development.md); the scene and its tanks stay
def test_long_period_quick():
    """The rectangular tank's 2-D section at dx = 0.1 m: linear theory holds at 0.05 g
    (judged against the declared quick tolerances); at the paper's 0.5 g it does not."""
    r = validation.run("long-period", quick=True)
    m = r["metrics"]
    assert r["passed"], r["outside_tolerance"]
    assert r["stated"]["tolerances"] == {f"rectangular 2-D, 0.05 g.{k}": v for k, v in LINEAR_TOLERANCES.items()}
    small, paper = m["rectangular 2-D, 0.05 g"], m["rectangular 2-D, 0.5 g"]
    # Housner's first mode is within 0.5 % of the exact one for this tank (2.846 against 2.832 rad/s)
    assert small["omega1_housner_rel_err"] == pytest.approx(0.0050, abs=2e-4)
    # at 0.5 g the surface leaves linear theory (by 20 % of its peak) while the tank is shaken
    # (linear theory's own run-up reaches 0.5 m, half the depth, in the first period)
    assert paper["departure_time_s"] is not None and paper["departure_time_s"] < paper["t_stop_s"]
    assert small["departure_time_s"] is None or small["departure_time_s"] > paper["departure_time_s"]
    assert paper["gauge_rms_rel_forced"] > 1.5 * small["gauge_rms_rel_forced"]
    assert small["particles_lost"] == 0
    # the scene's count (particles that leave the domain are counted back in)
    with case_scene.built(long_period_scene("rectangular", small["dx_m"], 2)) as b:
        assert paper["particles"] == small["particles"] == b.sph.ps.n
    assert "rectangular 2-D, 0.5 g: total pressure on the left wall (Sunara et al. 2021, Fig. 7/13/18)" in r["series"]
