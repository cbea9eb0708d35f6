"""An elastic plate rides with a moving tank (``base_motion``): its clamp is carried by the
tank's support (``bodies.elastic.Support``, driven by ``MujocoBodies.drive``), so the plate
feels the base's acceleration as a base-excited cantilever does.

Reference: the uniform Euler-Bernoulli cantilever under harmonic base translation
``u_g = U sin(w t)``, by modal superposition (Clough & Penzien 1993, Dynamics of
Structures, §18-5, base excitation of distributed-parameter systems; Chopra 2012,
Dynamics of Structures, §16.4): each mode's coordinate obeys ``q_n'' + w_n^2 q_n = -Gamma_n
u_g''`` with ``Gamma_n = int phi_n / int phi_n^2`` (``Gamma_1 = 0.7830`` for the first mode
normalised to ``phi_1(L) = 2``), so the steady-state relative tip displacement is ``U sum_n
Gamma_n phi_n(L) r_n^2 / (1 - r_n^2) sin(w t)``, ``r_n = w / w_n``. Started at rest
relative to the base, each mode also rings at its own frequency; fitting both
frequencies separates the steady state from it (the run is undamped)."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from bodies.elastic import BETA_L
from cosim.scene import Coupling, ElasticPlate, NoFluid, Roll, Scene, Shake, World
from cosim.scene.build import build
from cosim.scene.probes import groups

PLATE = dict(length=0.5, thickness=0.01, E=1e8, density=1000.0, base=(0.3, 0.0))  # L/h = 50, f1 = 2.04 Hz
U = 1e-3  # base amplitude [m]: the tip moves < 1 % of L, so the chain stays linear


def tip_participation(n: int) -> tuple[float, float]:
    """``Gamma_n`` (``phi_n(L) = 2``) and ``Gamma_n phi_n(L)`` of the uniform cantilever's
    n-th mode ``phi = cosh bx - cos bx - s (sinh bx - sin bx)``, ``s = (cosh bL + cos bL) /
    (sinh bL + sin bL)``, L = 1, by quadrature."""
    b = BETA_L[n - 1]
    s = (math.cosh(b) + math.cos(b)) / (math.sinh(b) + math.sin(b))

    def phi(x):
        return math.cosh(b * x) - math.cos(b * x) - s * (math.sinh(b * x) - math.sin(b * x))

    gamma = quad(phi, 0.0, 1.0)[0] / quad(lambda x: phi(x) ** 2, 0.0, 1.0)[0]
    return gamma, gamma * phi(1.0)


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


@pytest.mark.parametrize("r", [0.5, pytest.param(0.85, marks=pytest.mark.long)])
def test_the_relative_tip_motion_of_a_shaken_plate_is_the_base_excited_cantilevers(r, tmp_path):
    """No fluid, no gravity: the tank shaken along x at ``r`` times the chain's own first
    frequency. The clamp moves as the tank does, to round-off; the tip's deflection in the
    tank's frame, at the forcing frequency, is the modal closed form's steady state within
    1.5 % (the chain's frequencies, the continuum's participation factors); the chain's
    first frequency is Euler-Bernoulli's ``1.875^2 sqrt(E I / (rho A L^4)) / 2 pi`` within
    1 % (8 elements: +0.33 %, shear at L/h = 50 included)."""
    probe = Scene(world=World(dim=2, duration=0.01, gravity=0.0), fluid=NoFluid(),
                  bodies=[ElasticPlate("p", **PLATE)])
    beam = build(probe, tmp_path / "probe").plates["p"]
    f_chain = beam_frequencies(beam)
    f_eb = beam.natural_frequencies(1, "euler-bernoulli")[0]
    assert f_chain[0] == pytest.approx(f_eb, rel=0.01)
    w = 2 * math.pi * r * f_chain[0]
    duration = 4.0 if r > 0.6 else 2.0  # a beat of the forcing against the first mode at least
    scene = Scene(world=World(dim=2, duration=duration, gravity=0.0, sample_every=0.005), fluid=NoFluid(),
                  base_motion=Shake(period=2 * math.pi / w, amplitude=U), bodies=[ElasticPlate("p", **PLATE)],
                  coupling=Coupling(scheme="explicit"))
    _, t, cols = sampled(scene, tmp_path / "run", 0.005)
    assert np.abs(cols["p.clamp_x"] - U * np.sin(w * t)).max() < 1e-12
    assert np.abs(cols["p.clamp_z"]).max() < 1e-12
    wn = 2 * math.pi * f_chain
    closed = U * sum(tip_participation(n)[1] * (w / wn[n - 1]) ** 2 / (1 - (w / wn[n - 1]) ** 2) for n in (1, 2, 3))
    A = np.column_stack([f(x * t) for x in (w, wn[0], wn[1]) for f in (np.sin, np.cos)])
    fit, *_ = np.linalg.lstsq(A, cols["p.tip_x"], rcond=None)
    assert fit[0] == pytest.approx(closed, rel=0.015)
    assert abs(fit[1]) < 1e-3 * abs(closed)  # in phase with the base: no damping
    # started at rest on the base, the first mode rings at its own frequency: -r of its steady state
    assert fit[2] == pytest.approx(-r * U * tip_participation(1)[1] * r**2 / (1 - r**2), rel=0.05)


def beam_frequencies(beam):
    """The chain's own first three frequencies [Hz] (welded, linearised, no gravity)."""
    import mujoco

    from bodies import builders
    from bodies.elastic import modal_frequencies

    m = mujoco.MjModel.from_xml_string(builders.scene(beam.xml, gravity=0.0))
    return modal_frequencies(m, mujoco.MjData(m))[:3]


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
def test_in_a_shaken_sph_tank_the_clamp_moves_with_the_walls(tmp_path):
    """2-D SPH tank (dx 1 cm, 0.3 s: 3 s of CPU once the fluid's kernels are compiled)
    shaken at 20 mm: at every sample the plate's clamp has moved exactly as the tank's walls
    (wall particles' displacement), and the plate has not been left behind as the floor
    slid under it (issue 38)."""
    from fluid.particles import Kind

    scene = Scene.from_dict({
        "world": {"dim": 2, "duration": 0.3, "sample_every": 0.05, "snapshot_every": 0.0},
        "fluid": {"model": "sph", "dx": 0.01},
        "domain": {"kind": "tank", "length": 0.4, "height": 0.25, "depth": 0.1},
        "base_motion": {"kind": "harmonic", "period": 0.6, "amplitude": 0.02},
        "bodies": [{"shape": "elastic-plate", "name": "p", "length": 0.08, "thickness": 0.02, "E": 1e6,
                    "density": 2500.0, "base": [0.3, 0.0]}]})
    built = build(scene, tmp_path)
    sph, c = built.sph, built.coupler
    g = next(x for x in groups(scene, built) if x.name == "motion")
    ids = sph.ps.ids[sph.ps.kind == Kind.MOVING_WALL][::50]  # a few wall particles, by their stable ids

    def walls():
        return sph.ps.pos[np.argsort(sph.ps.ids)[ids]]  # ids are 0..N-1

    start, seen = walls(), 0.0
    for k in range(1, 7):
        c.run(0.05 * k)
        row = dict(zip(g.columns, g.sample()))
        shift = walls() - start
        assert np.ptp(shift, axis=0) == pytest.approx([0.0, 0.0], abs=1e-12)  # the walls move rigidly
        assert row["p.clamp_x"] == pytest.approx(shift[0, 0], abs=1e-9)
        assert row["p.clamp_z"] == pytest.approx(shift[0, 1], abs=1e-9)
        seen = max(seen, abs(row["p.clamp_x"]))
    assert seen > 0.015


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
