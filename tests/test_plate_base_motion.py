"""An elastic plate rides with a moving tank (``base_motion``): its clamp is carried by the
tank's support (``bodies.elastic.Support``, driven by ``MujocoBodies.drive``), so the plate
feels the base's acceleration as a base-excited cantilever does.

Reference: the base-excited uniform cantilever's modal closed form (Clough & Penzien 1993,
§18-5; Chopra 2012, §16.4), as the ``shaken-cantilever`` validation case computes and fits
it (:mod:`cosim.validations.shaken_cantilever`), whose runs these tests make."""

import math

import numpy as np
import pytest

from cosim.scene import Coupling, ElasticPlate, NoFluid, Roll, Scene, World
from cosim.scene.build import build
from cosim.scene.probes import groups
from cosim.validations.shaken_cantilever import (cantilever_scene, chain_frequencies, continuum_frequencies,
                                                 shaken_run, sph_clamp_run, tip_participation)

PLATE = dict(length=0.5, thickness=0.01, E=1e8, density=1000.0, base=(0.3, 0.0))  # L/h = 50, f1 = 2.04 Hz


def sampled(scene, tmp_path, every):
    """Build the scene, step it, sample its motion probes every ``every`` s: (t, columns)."""
    built = build(scene, tmp_path)
    g = next(x for x in groups(scene, built) if x.name == "motion")
    ts, rows = [0.0], [g.sample()]
    for k in range(1, round(scene.world.duration / every) + 1):
        built.coupler.run(k * every)
        ts.append(built.coupler.t)
        rows.append(g.sample())
    return built, np.array(ts), dict(zip(g.columns, np.array(rows).T))


def test_the_first_mode_takes_gamma_1_of_a_uniform_cantilever():
    g1, tip1 = tip_participation(1)
    assert g1 == pytest.approx(0.7830, abs=5e-5) and tip1 == pytest.approx(1.5660, abs=1e-4)


def test_the_chain_of_the_case_has_euler_bernoullis_first_frequency():
    """The plate of the shaken-cantilever case as an 8-element chain (shear included, L/h =
    50): its first frequency within 1 % of ``1.875^2 sqrt(E I / (rho A L^4)) / 2 pi`` (+0.33 %),
    and its support's rigid-body modes left out of its own frequencies."""
    scene = cantilever_scene(0.5, 8)
    f_chain, f_eb = chain_frequencies(scene), continuum_frequencies(scene.bodies[0])
    assert f_eb[0] == pytest.approx(2.0433, abs=1e-4)
    assert f_chain[0] == pytest.approx(f_eb[0], rel=0.01) and f_chain[0] > f_eb[0]
    assert f_chain[1] == pytest.approx(f_eb[1], rel=0.02)


@pytest.mark.parametrize("r, elements, tol", [(0.5, 8, 0.015), pytest.param(1.5, 8, 0.01, marks=pytest.mark.long),
                                              pytest.param(0.85, 16, 0.01, marks=pytest.mark.long)])
def test_the_relative_tip_motion_of_a_shaken_plate_is_the_base_excited_cantilevers(r, elements, tol):
    """No fluid, no gravity: the tank shaken along x at ``r`` times the plate's first
    frequency (the shaken-cantilever case's runs). The clamp moves as the tank does, to
    round-off; the tip's deflection in the tank's frame, at the forcing frequency, is the
    continuum's modal closed form's steady state within ``tol`` (8 elements: the chain's f1
    +0.33 %, which the closed form amplifies by 2 / (1 - r^2)), in phase with the base below
    the first mode and in antiphase above it, with no part in quadrature (undamped); started
    at rest on the base, the first mode rings at -r of its steady part."""
    run = shaken_run(cantilever_scene(r, elements))
    assert run["clamp_error_m"] < 1e-12
    assert run["tip_error"] < tol
    assert np.sign(run["steady_tip_m"]) == (1 if r < 1 else -1)
    assert run["quadrature_over_closed"] < 1e-3
    assert run["ringing_over_predicted"] == pytest.approx(1.0, abs=0.05)


@pytest.mark.long
def test_a_plate_in_a_rolling_tank_turns_with_it(tmp_path):
    """A roll about a point below the floor: the clamp goes round the axis as the tank's
    points do (``fluid.motion.Rotation``), the tip's deflection in the tank's frame stays
    a small part of the tip's travel, and the plate's foot link keeps the tank's angle."""
    roll = Roll(amplitude=4.0, period=0.6, point=(0.3, -0.2), ramp=0.3)
    scene = Scene(world=World(dim=2, duration=0.6, sample_every=0.01), fluid=NoFluid(), base_motion=roll,
                  bodies=[ElasticPlate("p", **{**PLATE, "E": 1e10})], coupling=Coupling(scheme="explicit"))
    built, t, cols = sampled(scene, tmp_path, 0.05)
    move = built.base_motion
    foot = np.array([move(x, np.array([[0.3, 0.0]]))[0][0] for x in t]) - (0.3, 0.0)
    assert np.abs(cols["p.clamp_x"] - foot[:, 0]).max() < 1e-12
    assert np.abs(cols["p.clamp_z"] - foot[:, 1]).max() < 1e-12
    tip = np.array([move(x, np.array([[0.3, 0.5]]))[0][0] for x in t]) - (0.3, 0.5)
    assert np.abs(tip).max() > 0.04  # the tip of a rigid plate would travel 4.9 cm
    assert np.abs(cols["p.tip_x"]).max() < 0.02 * np.abs(tip).max()
    k = built.bodies.kinematics()
    angle = math.atan2(k.rotation[0, 0, 2], k.rotation[0, 2, 2])
    assert angle == pytest.approx(roll_angle(move, built.coupler.t), abs=1e-12)


def roll_angle(move, t):
    """The tank's angle about +y [rad] at ``t``, from the turn of its x axis
    (``fluid.motion.Rotation``: +x turns towards -z)."""
    o, e = move(t, np.array([[0.0, 0.0], [1.0, 0.0]]))[0]
    return math.atan2(o[1] - e[1], e[0] - o[0])


@pytest.mark.long
def test_in_a_shaken_sph_tank_the_clamp_moves_with_the_walls():
    """The case's 2-D SPH tank (dx 1 cm, 0.3 s: 3 s of CPU once the fluid's kernels are
    compiled) shaken at 20 mm: at every sample the plate's clamp has moved exactly as the
    tank's walls (wall particles' displacement), the walls rigidly, and the plate has not
    been left behind as the floor slid under it."""
    run = sph_clamp_run()
    assert run["clamp_vs_walls_m"] < 1e-9 and run["walls_spread_m"] < 1e-12
    assert run["walls_moved_m"] > 0.015


def test_what_an_mjcf_model_fixes_to_its_world_is_warned_of_under_base_motion(tmp_path):
    """The MJCF model's world stands still while the tank moves: a body hinged to it and a
    colliding geom on it are named; a free body rides the water and is not."""
    from bodies.mujoco_bodies import MujocoBodies
    from cosim.scene.build import Built, _warn_mjcf_world

    xml = tmp_path / "m.xml"
    xml.write_text('<mujoco><worldbody><geom name="ground" type="plane" size="1 1 0.1"/>'
                   '<body name="float" pos="0.5 0.25 0.3"><freejoint/><geom type="sphere" size="0.05"/></body>'
                   '<body name="flap" pos="0.2 0.25 0.2"><joint type="hinge" axis="0 1 0"/>'
                   '<geom type="box" size="0.01 0.1 0.05"/></body></worldbody></mujoco>')
    data = {"world": {"dim": 3, "duration": 1.0}, "fluid": {"model": "sph", "dx": 0.02},
            "domain": {"kind": "tank", "length": 1.0, "width": 0.5, "height": 0.6, "depth": 0.2},
            "bodies": [{"shape": "mjcf", "file": str(xml), "bodies": ["float", "flap"]}]}
    out = Built(coupler=None, bodies=MujocoBodies(str(xml), bodies=["float", "flap"]))
    _warn_mjcf_world(Scene.from_dict(data), out)
    assert out.warnings == []  # a tank at rest: nothing to say
    data["base_motion"] = {"kind": "harmonic", "period": 1.0, "direction": [1.0, 0.0, 0.0], "amplitude": 0.01}
    _warn_mjcf_world(Scene.from_dict(data), out)
    (msg,) = out.warnings
    assert "body 'flap' (jointed to the world)" in msg and "geom 'ground' (on the world)" in msg
    assert "'float'" not in msg
