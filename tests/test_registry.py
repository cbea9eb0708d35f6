"""Scene plug-ins from outside the package (:mod:`cosim.scene.registry`): a mooring model
(``tests/plugin_example.py``, a module acting as another package) registered by hand and
through an entry point, run by the normal runner, with numbers checked against the closed
form they must give."""

import math
from importlib.metadata import EntryPoint

import numpy as np
import pytest

import cosim.scene.registry as registry
from cosim.errors import ConfigurationError, InputError
from cosim.scene import Analytic, Box, Line, Moorings, Probes, Scene, SceneError, World
from cosim.scene.registry import MOORINGS

from plugin_example import Tether

# a 2-D box 0.2 m x 0.1 m of half the water's density, floating at its equilibrium (centre
# at the still level: draft = half its height), between two horizontal tethers pre-stretched
# by PRE; started DX off their middle, it surges as a mass on the two springs
M = 500.0 * 0.2 * 0.1  # kg per metre
PERIOD = 1.0  # s
K_LINE = 0.5 * M * (2 * math.pi / PERIOD) ** 2  # N/m each: together 2 k = M omega^2
L0, PRE, DX, X0 = 1.0, 0.05, 0.02, 1.5


def _tethered(model: str) -> Scene:
    lines = [Line("box.left", anchor=(X0 - 0.1 - L0 - PRE, 0.0), length=L0, weight=1.0, EA=K_LINE * L0),
             Line("box.right", anchor=(X0 + 0.1 + L0 + PRE, 0.0), length=L0, weight=1.0, EA=K_LINE * L0)]
    return Scene(world=World(dim=2, duration=1.0, sample_every=0.01, snapshot_every=0.0),
                 fluid=Analytic(level=0.0),
                 bodies=[Box("box", size=(0.2, 0.1), pos=(X0 + DX, 0.0), density=500.0,
                             fairleads={"left": (-0.1, 0.0), "right": (0.1, 0.0)})],
                 moorings=Moorings(model=model, lines=lines), probes=Probes(motion=["box"]))


def _check_spring_motion(res) -> None:
    """Surge of an undamped mass on a spring started DX from rest: ``-DX (1 - cos wt)``."""
    exact = -DX * (1.0 - np.cos(2 * math.pi * res.t / PERIOD))
    assert np.abs(res["box.surge"] - exact).max() < 1e-3 * DX
    assert res["box.left.tension"][0] == pytest.approx(K_LINE * (PRE + DX), rel=1e-9)
    assert res["box.right.tension"][0] == pytest.approx(K_LINE * (PRE - DX), rel=1e-9)


@pytest.fixture
def tether_by_hand():
    MOORINGS.register("tether", Tether)  # what an entry point of group cosim.moorings calls
    yield
    MOORINGS.unregister("tether")


def test_a_mooring_model_registered_from_outside_runs_a_python_scene(tether_by_hand, tmp_path):
    _check_spring_motion(_tethered("tether").run(tmp_path / "run", progress=False))


def test_an_entry_point_registers_a_mooring_model_for_a_toml_scene(monkeypatch, tmp_path):
    fake = [EntryPoint(name="tether", value="plugin_example:Tether", group="cosim.moorings")]
    monkeypatch.setattr(registry, "entry_points", lambda group: fake if group == "cosim.moorings" else [])
    assert "tether" not in MOORINGS.names()  # found only when the registry looks again
    MOORINGS.rediscover()
    try:
        path = tmp_path / "tethered.toml"
        _tethered("catenary").to_toml(path)
        path.write_text(path.read_text().replace('model = "catenary"', 'model = "tether"'))
        scene = Scene.from_toml(path)
        assert scene.moorings.model == "tether"
        _check_spring_motion(scene.run(tmp_path / "run", progress=False))
    finally:
        MOORINGS.unregister("tether")
    with pytest.raises(SceneError, match="moorings.model: 'tether' is not accepted"):
        Scene.from_toml(path)


def test_a_model_states_the_line_fields_it_needs(tether_by_hand):
    with pytest.raises(SceneError, match=r"lines\[0\].EA: the 'tether' model needs it"):
        Moorings(model="tether", lines=[Line("box.left", anchor=(0.0, 0.0), length=1.0, weight=1.0)])


def test_bad_registrations_are_refused_naming_what_to_fix(monkeypatch):
    with pytest.raises(ConfigurationError, match="not a MooringModel"):
        MOORINGS.register("tether", object())
    with pytest.raises(ConfigurationError, match="'catenary' is registered twice"):
        MOORINGS.register("catenary", Tether)
    with pytest.raises(InputError, match="did you mean 'catenary'"):
        MOORINGS["catenery"]
    broken = [EntryPoint(name="broken", value="plugin_example:NoSuchModel", group="cosim.moorings")]
    monkeypatch.setattr(registry, "entry_points", lambda group: broken)
    with pytest.raises(ConfigurationError, match="entry point 'broken'.*fix or uninstall"):
        MOORINGS.rediscover()
    monkeypatch.undo()
    MOORINGS.rediscover()
    assert MOORINGS.names() == ["catenary", "sph-cable", "moordyn", "fmu"]
