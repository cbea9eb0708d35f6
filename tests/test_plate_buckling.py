"""A standing elastic plate under its own weight: beyond Greenhill's self-weight buckling
load the scene warns when it is built (the critical load and the actual one) and the plate
starts bent in its buckling mode, its tip L/1000 off, so that it buckles instead of
standing perfectly still; below the load, and hanging (in tension), it is not warned of.

References: Greenhill (1881), the column clamped at its foot and free at its top under
its own uniform weight q buckles at ``q L^3 / (E I) = (9/4) j^2 = 7.837``, j the first zero
of the Bessel function J_{-1/3} (Timoshenko & Gere 1961, Theory of Elastic Stability,
§2.13); Euler's clamped-free column under a tip load, ``P = pi^2 E I / (4 L^2)`` (ibid.
§2.1)."""

import logging
import math

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import jv

from bodies.elastic import GREENHILL, IMPERFECTION, self_weight_buckling
from cosim.scene import ElasticPlate, NoFluid, Scene, World
from cosim.scene.build import buckling_warning, build, self_weight

#: Greenhill's (q L^3 / (E I))_cr from the Bessel function's first zero
GREENHILL_EXACT = 9.0 / 4.0 * brentq(lambda x: jv(-1.0 / 3.0, x), 1.0, 2.5) ** 2

L, H, RHO = 0.5, 0.01, 1000.0  # plate [m], [m], [kg/m^3]; 2-D: 1 m wide
EI_PER_E = H**3 / 12.0
Q = RHO * 9.81 * H  # its weight per length [N/m]


def e_for(ratio):
    """Young's modulus [Pa] that puts the plate at ``ratio`` times its buckling load."""
    return Q * L**3 / (ratio * GREENHILL_EXACT * EI_PER_E)


def plate_scene(ratio, direction="up", duration=2.0):
    base = (0.3, 0.0) if direction == "up" else (0.3, L)
    return Scene(world=World(dim=2, duration=duration, sample_every=0.01), fluid=NoFluid(),
                 bodies=[ElasticPlate("p", length=L, thickness=H, E=e_for(ratio), density=RHO, base=base,
                                      direction=direction)])


def test_the_ritz_solution_is_greenhills_and_eulers():
    factor, slope = self_weight_buckling(2.0, 3.0, [(0.0, 2.0, 1.5)])
    assert GREENHILL_EXACT == pytest.approx(7.837347, abs=1e-6) and GREENHILL == pytest.approx(GREENHILL_EXACT,
                                                                                                abs=1e-6)
    assert factor * 1.5 * 2.0**3 / 3.0 == pytest.approx(GREENHILL_EXACT, rel=1e-9)
    assert slope(0.0) == 0.0 and slope(2.0) > 0  # clamped, bending towards +x
    split, _ = self_weight_buckling(2.0, 3.0, [(0.0, 0.7, 1.5), (0.7, 2.0, 1.5)])  # the same load in two pieces
    assert split == pytest.approx(factor, rel=1e-12)
    tip, _ = self_weight_buckling(1.0, 1.0, [(1.0 - 1e-7, 1.0, 1e7)])  # 1 N at the tip
    assert tip == pytest.approx(math.pi**2 / 4.0, rel=1e-6)
    assert self_weight_buckling(2.0, 3.0, [(0.0, 2.0, -1.5)]) == (math.inf, None)  # hanging: tension


def test_beyond_the_limit_the_scene_warns_with_both_loads_and_bends_the_plate(tmp_path, caplog):
    scene = plate_scene(2.0)
    with caplog.at_level(logging.WARNING, logger="cosim.scene.build"):
        built = build(scene, tmp_path)
    (msg,) = built.warnings
    assert msg in caplog.text
    P, P_cr = Q * L, GREENHILL_EXACT * e_for(2.0) * EI_PER_E / L**2
    assert P_cr == pytest.approx(P / 2.0)
    assert f"carries {P:.4g} N per metre" in msg and f"buckles under {P_cr:.4g} N per metre" in msg
    assert "bodies[0] ('p')" in msg and "Greenhill 1881" in msg and "buoyancy" not in msg  # in air
    b = built.bodies
    tip = b.site_positions([b.site("p_tip")[0]])[0]
    assert tip[0] - 0.3 == pytest.approx(IMPERFECTION * L, rel=1e-9)  # L/1000 along +x
    assert tip[2] == pytest.approx(L, abs=1e-6)


@pytest.mark.parametrize("ratio,direction", [(0.5, "up"), (2.0, "down")])
def test_below_the_limit_or_hanging_there_is_no_warning_and_no_imperfection(ratio, direction, tmp_path):
    scene = plate_scene(ratio, direction)
    assert buckling_warning(scene, 0) is None
    built = build(scene, tmp_path)
    assert built.warnings == []
    b = built.bodies
    assert b.site_positions([b.site("p_tip")[0]])[0, 0] == pytest.approx(0.3, abs=1e-15)


def tip_history(built, every=0.02):
    b, c = built.bodies, built.coupler
    tip = b.site("p_tip")[0]
    out = []
    for k in range(1, round(c.t + 2.0 / every) + 1):
        c.run(k * every)
        out.append(b.site_positions([tip])[0, 0] - 0.3)
    return np.array(out)


def test_the_imperfect_column_buckles_beyond_the_limit_and_stands_below_it(tmp_path):
    """No fluid, 2 s. Beyond (twice the load) the imperfect plate leaves the straight line:
    its tip moves 50 times the imperfection and more. Below (half the load), the same
    imperfection given by hand, it swings about the straight line and its tip stays
    within twice the imperfection."""
    above = build(plate_scene(2.0), tmp_path / "above")
    assert np.abs(tip_history(above)).max() > 50 * IMPERFECTION * L
    scene = plate_scene(0.5)
    below = build(scene, tmp_path / "below")
    _, factor, slope = self_weight(scene, scene.bodies[0])
    assert factor == pytest.approx(2.0, rel=1e-6)
    below.bodies.set_joints(below.plates["p"].imperfection(slope, IMPERFECTION * L))
    history = tip_history(below)
    assert np.abs(history).max() < 2 * IMPERFECTION * L
    assert history.min() < 0  # it swung through the straight line: the straight plate is stable


def test_under_water_the_plate_carries_its_weight_less_its_buoyancy():
    """Filled to 0.3 m, a plate 0.5 m tall: below the still level its weight per length is
    (rho_s - rho_w) g h, above rho_s g h; lighter than water and submerged it is pulled up."""
    def scene(density, depth):
        return Scene.from_dict({
            "world": {"dim": 2, "duration": 1.0},
            "fluid": {"model": "sph", "dx": 0.005},
            "domain": {"kind": "tank", "length": 1.0, "height": 0.6, "depth": depth},
            "bodies": [{"shape": "elastic-plate", "name": "p", "length": L, "thickness": H, "E": 1e6,
                        "density": density, "base": [0.5, 0.0]}]})

    s = scene(2500.0, 0.3)
    P, factor, _ = self_weight(s, s.bodies[0])
    assert P == pytest.approx((1500.0 * 0.3 + 2500.0 * 0.2) * 9.81 * H, rel=1e-12)
    assert factor < 1.0 and "below the still water its weight less its buoyancy" in buckling_warning(s, 0)
    s = scene(900.0, 0.55)  # lighter than water, all under it
    P, factor, _ = self_weight(s, s.bodies[0])
    assert P == pytest.approx(-100.0 * L * 9.81 * H, rel=1e-12) and factor == math.inf
    assert buckling_warning(s, 0) is None
