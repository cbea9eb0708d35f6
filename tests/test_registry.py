"""Scene plug-ins from outside the package (:mod:`cosim.scene.registry`): a mooring model, a
body shape, a probe and a fluid (``tests/plugin_example.py``, a module acting as another
package) registered by hand and through entry points, run by the normal runner, with numbers
checked against the closed forms they must give."""

import math
from importlib.metadata import EntryPoint

import numpy as np
import pytest

import cosim.scene.registry as registry
from cosim.errors import ConfigurationError, InputError
from cosim.scene import Box, Cylinder, Line, Moorings, Scene, SceneError, Sphere
from cosim.scene.registry import FLUIDS, MOORINGS, PROBES, SHAPES, WAVES
from cosim.scene.shapes import Shape

from plugin_example import Capsule, Drag, Tether, TetherEnergy

# a capsule (3-D, axis vertical) of 0.4 times the water's density floats with its water line
# D above its lowest point, in the cylinder (the lower cap's 2/3 pi r^3 plus pi r^2 (D - r)
# carry 0.4 of its volume); two horizontal tethers at its centre's height, pre-stretched by
# PRE, hold it; started DX off their middle it surges as a mass on two springs
R, LC, RHO_B = 0.1, 0.2, 400.0
VOLUME = math.pi * R * R * LC + 4.0 / 3.0 * math.pi * R ** 3
D = R + (RHO_B / 1000.0 * VOLUME - 2.0 / 3.0 * math.pi * R ** 3) / (math.pi * R * R)
Z_C = -D + R + 0.5 * LC  # the centre's height above the still water (at z = 0) [m]
M = RHO_B * VOLUME  # kg
PERIOD = 1.0  # s
K_LINE = 0.5 * M * (2 * math.pi / PERIOD) ** 2  # N/m each: together 2 k = M omega^2
L0, PRE, DX, X0 = 1.0, 0.05, 0.02, 1.5
W = 1e-6  # N/m: weightless tethers (the floating placement takes any line's pull as a catenary's)


def _scene(shape: str = "capsule", model: str = "tether") -> Scene:
    """The scene as TOML's tables: a plug-in is named as a built-in is."""
    z = Z_C - 1e-5  # the anchors' seabed just under the fairleads (the placement's catenary needs them above it)
    lines = [dict(fairlead="cap.left", anchor=[X0 - R - L0 - PRE, 0.0, z], length=L0, weight=W, EA=K_LINE * L0),
             dict(fairlead="cap.right", anchor=[X0 + R + L0 + PRE, 0.0, z], length=L0, weight=W, EA=K_LINE * L0)]
    body = dict(shape=shape, name="cap", radius=R, length=LC, pos=[X0 + DX, 0.0], density=RHO_B, place="floating",
                fairleads={"left": [-R, 0.0, 0.0], "right": [R, 0.0, 0.0]})
    return Scene.from_dict({"world": {"dim": 3, "duration": 1.0, "sample_every": 0.01, "snapshot_every": 0.0},
                            "fluid": {"model": "analytic", "level": 0.0}, "bodies": [body],
                            "moorings": {"model": model, "lines": lines}, "probes": {"motion": ["cap"]}})


def _check(res) -> None:
    """Floating where its displaced water carries it; surging as an undamped mass on a
    spring started DX from rest, ``-DX (1 - cos wt)``, its tethers' tension ``k (PRE + DX)``
    and ``k (PRE - DX)`` at the start, their elastic energy ``k (PRE^2 + x^2)`` with ``x``
    the capsule's offset from their middle."""
    assert res.summary["floating_start_z_m"]["cap"] == pytest.approx(Z_C, abs=1e-4 * D)
    exact = -DX * (1.0 - np.cos(2 * math.pi * res.t / PERIOD))
    assert np.abs(res["cap.surge"] - exact).max() < 2e-3 * DX
    energy = K_LINE * (PRE ** 2 + (DX + res["cap.surge"]) ** 2)
    assert np.abs(res["tethers.energy"] - energy).max() < 1e-5 * energy[0]
    assert res["cap.left.tension"][0] == pytest.approx(K_LINE * (PRE + DX), rel=1e-6)
    assert res["cap.right.tension"][0] == pytest.approx(K_LINE * (PRE - DX), rel=1e-6)


@pytest.fixture
def by_hand():
    SHAPES.register("capsule", Capsule)  # what an entry point of group cosim.shapes calls
    MOORINGS.register("tether", Tether)
    PROBES.register("tether_energy", TetherEnergy)
    yield
    SHAPES.unregister("capsule")
    MOORINGS.unregister("tether")
    PROBES.unregister("tether_energy")


@pytest.mark.long
def test_a_shape_and_a_mooring_model_registered_by_hand_run_a_python_scene(by_hand, tmp_path):
    scene = _scene()
    assert isinstance(scene.bodies[0], Capsule) and scene.moorings.model == "tether"
    _check(scene.run(tmp_path / "run", progress=False))


@pytest.mark.long
def test_entry_points_register_them_for_a_toml_scene(monkeypatch, tmp_path):
    fake = {"cosim.shapes": [EntryPoint("capsule", "plugin_example:Capsule", "cosim.shapes")],
            "cosim.moorings": [EntryPoint("tether", "plugin_example:Tether", "cosim.moorings")],
            "cosim.probes": [EntryPoint("tether_energy", "plugin_example:TetherEnergy", "cosim.probes")]}
    monkeypatch.setattr(registry, "entry_points", lambda group: fake.get(group, []))
    assert "capsule" not in SHAPES.names() and "tether" not in MOORINGS.names()  # found when looked for again
    for r in (SHAPES, MOORINGS, PROBES):
        r.rediscover()
    try:
        path = tmp_path / "capsule.toml"
        _scene().to_toml(path)
        text = path.read_text()
        assert 'shape = "capsule"' in text and 'model = "tether"' in text
        scene = Scene.from_toml(path)
        assert scene == _scene()
        _check(scene.run(tmp_path / "run", progress=False))
    finally:
        SHAPES.unregister("capsule")
        MOORINGS.unregister("tether")
        PROBES.unregister("tether_energy")
    with pytest.raises(SceneError, match="bodies\\[0\\].shape: 'capsule' is not accepted"):
        Scene.from_toml(path)


@pytest.fixture
def drag():
    FLUIDS.register("drag", Drag)
    yield
    FLUIDS.unregister("drag")


def test_a_fluid_from_outside_loads_the_bodies(drag, tmp_path):
    """A box falling under gravity through a fluid that drags it with ``-c V``
    (tests/plugin_example.py): ``z - z0 = -v_t (t - tau (1 - exp(-t / tau)))``, ``v_t = g
    tau``, ``tau = m / c``."""
    m, tau, g = 500.0 * 0.2 * 0.1, 0.2, 9.81
    box = {"shape": "box", "name": "box", "size": [0.2, 0.1], "pos": [1.0, 0.0], "density": 500.0}
    res = Scene.from_dict({"world": {"dim": 2, "duration": 0.6, "sample_every": 0.01},
                           "fluid": {"model": "drag", "c": m / tau}, "bodies": [box]}).run(tmp_path / "run",
                                                                                           progress=False)
    t = res.t
    exact = -g * tau * (t - tau * (1.0 - np.exp(-t / tau)))
    assert np.abs(res["box.heave"] - exact).max() < 1e-3 * abs(exact[-1])
    # the load over the last coupling step (one sample interval): the predictor-corrector's mean of its ends
    force = m * g * (1.0 - np.exp(-t[-2:] / tau))
    assert res["box.fluid_Fz"][-1] == pytest.approx(force.mean(), rel=1e-3)
    # a fluid without a still-water level floats nothing
    floating = {"fluid": {"model": "drag", "c": 1.0}, "bodies": [dict(box, pos=[1.0], place="floating")]}
    with pytest.raises(SceneError, match="bodies\\[0\\].place: the 'drag' fluid states no still-water level"):
        Scene.from_dict(floating)


def test_a_plugin_is_checked_with_the_scene(by_hand):
    with pytest.raises(SceneError, match=r"lines\[0\].EA: the 'tether' model needs it"):
        Moorings(model="tether", lines=[Line("cap.left", anchor=(0.0, 0.0), length=1.0, weight=1.0)])
    two_d = dict(world={"dim": 2}, fluid={"model": "analytic"},
                 bodies=[dict(shape="capsule", name="cap", radius=R, length=LC, pos=[1.0, 0.0], density=RHO_B)])
    with pytest.raises(SceneError, match="bodies\\[0\\].shape: a capsule is 3-D"):
        Scene.from_dict(two_d)


@pytest.mark.parametrize("body, dim, rel", [
    (Box("b", size=(0.3, 0.1), pos=(1.0, 0.0), density=1.0), 2, 1e-12),
    (Box("b", size=(0.3, 0.2, 0.1), pos=(1.0, 0.0, 0.0), density=1.0), 3, 1e-12),
    (Cylinder("c", radius=0.1, pos=(1.0, 0.0), density=1.0), 2, 4e-4),
    (Cylinder("c", radius=0.1, length=0.3, pos=(1.0, 0.0, 0.0), density=1.0), 3, 4e-4),
    (Sphere("s", radius=0.1, pos=(1.0, 0.0, 0.0), density=1.0), 3, 3e-5)], ids=str)
def test_the_default_quadrature_gives_the_built_in_shapes_volumes(body, dim, rel):
    """A shape without its own submerged volume takes the quadrature of its signed distance
    (Shape.submerged_volume): against the built-in shapes' closed forms at three drafts."""
    height = 2 * body.half_size(dim)[-1]
    for d in (0.3 * height, 0.5 * height, height):
        assert Shape.submerged_volume(body, dim, d) == pytest.approx(body.submerged_volume(dim, d), rel=rel)


def test_bad_registrations_are_refused_naming_what_to_fix(monkeypatch):
    with pytest.raises(ConfigurationError, match="not a MooringModel"):
        MOORINGS.register("tether", object())
    with pytest.raises(ConfigurationError, match="'catenary' is registered twice"):
        MOORINGS.register("catenary", Tether)
    with pytest.raises(ConfigurationError, match=r"Capsule.TAG is \('shape', 'capsule'\); give it TAG"):
        SHAPES.register("pill", Capsule)
    with pytest.raises(ConfigurationError, match="not a scene class of this kind.*seas.IncidentSea"):
        WAVES.register("capsule", Capsule)
    with pytest.raises(ConfigurationError, match="not a scene class of this kind.*shapes.RigidBody"):
        SHAPES.register("drag", Drag)
    with pytest.raises(InputError, match="did you mean 'catenary'"):
        MOORINGS["catenery"]
    broken = [EntryPoint(name="broken", value="plugin_example:NoSuchModel", group="cosim.moorings")]
    monkeypatch.setattr(registry, "entry_points", lambda group: broken)
    with pytest.raises(ConfigurationError, match="entry point 'broken'.*fix or uninstall"):
        MOORINGS.rediscover()
    monkeypatch.undo()
    MOORINGS.rediscover()
    assert MOORINGS.names() == ["catenary", "sph-cable", "moordyn", "fmu"]
    assert SHAPES.names() == ["box", "cylinder", "sphere", "mjcf", "elastic-plate"]
    assert FLUIDS.names() == ["none", "analytic", "potential", "sph"]
    assert PROBES.names() == ["motion", "loads", "tensions", "line_states", "line_points", "gauges", "pressure", "energy",
                              "line_energy", "end_walls"]
