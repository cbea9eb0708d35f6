"""Linear waves and line breaking in scenes (issue 18): the analytic fluid's waves from
``waves = LinearWaves(...)``, break loads and ``moorings.release_broken``, in TOML and Python."""

import dataclasses
import json
import math

import numpy as np
import pytest

from cosim.scene import Analytic, Box, Line, LinearWaves, Moorings, Probes, Scene, World
from cosim.scene.build import build

CHAIN = dict(length=25.0, weight=50.0, EA=5e7)


def moored(break_load=None, release=False, dim=2, duration=9.0):
    """A 2 x 1 m box on two chains in 6 s waves, 1.5 m high, 10 m deep (3-D: a 2 x 2 x 1 m
    box, the waves at 0 deg)."""
    size, pos = ((2.0, 1.0), (0.0, 0.0)) if dim == 2 else ((2.0, 2.0, 1.0), (0.0, 0.0, 0.0))
    fl = ({"left": (-1.0, -0.5), "right": (1.0, -0.5)} if dim == 2 else
          {"left": (-1.0, 0.0, -0.5), "right": (1.0, 0.0, -0.5)})
    anchors = [(-20.0, -10.0), (20.0, -10.0)] if dim == 2 else [(-20.0, 0.0, -10.0), (20.0, 0.0, -10.0)]
    damping = [800.0, 800.0, 1500.0, 1500.0, 1500.0, 1500.0]
    return Scene(
        name="waves_break",
        world=World(dim=dim, duration=duration, sample_every=0.1),
        fluid=Analytic(rho=1025.0, linear_damping={"box": damping},
                       added_mass={"box": [500.0, 1000.0, 100.0] if dim == 2 else [500.0, 500.0, 1000.0] + [100.0] * 3}),
        waves=LinearWaves(height=1.5, period=6.0, depth=10.0, ramp=1.0),
        bodies=[Box("box", size=size, pos=pos, density=500.0, fairleads=fl)],
        moorings=Moorings(lines=[Line("box.left", anchor=anchors[0], name="left", break_load=break_load, **CHAIN),
                                 Line("box.right", anchor=anchors[1], name="right", **CHAIN)],
                          release_broken=release),
        probes=Probes(loads=False),
    )


def test_scene_fields_round_trip_through_toml(tmp_path):
    s = moored(800.0, release=True)
    text = s.to_toml()
    assert 'kind = "linear"' in text and "break_load = 800.0" in text and "release_broken = true" in text
    s.to_toml(tmp_path / "s.toml")
    assert Scene.from_toml(tmp_path / "s.toml") == s


@pytest.mark.parametrize("dim", [2, 3])
def test_the_scene_gives_the_analytic_fluid_its_waves(tmp_path, dim):
    s = moored(dim=dim)
    b = build(s, tmp_path)
    w = b.fluid.waves
    assert (w.H, w.T, w.depth, w.direction, w.ramp, w.g) == (1.5, 6.0, 10.0, 0.0, 6.0, s.world.gravity)
    assert w.k == pytest.approx((2 * math.pi / 6.0) ** 2 / 9.81 / math.tanh(w.k * 10.0), rel=1e-12)
    assert b.mooring.n_lines == 2 and not hasattr(b.mooring, "events")  # no break load: the model itself
    b.coupler.run(1.0)


def test_a_break_is_reported_in_the_summary_and_the_run_goes_on(tmp_path):
    r = moored(800.0).run(tmp_path / "out")
    heave = r["box.heave"][r.t > 6.0]
    assert 0.5 < np.ptp(heave) / 1.5 < 1.2  # the box rides the waves (2 m wide in a 46 m wave)
    ev = r.summary["line_breaks"]
    assert len(ev) == 1 and ev[0]["line"] == "left" and ev[0]["released"] is False
    assert ev[0]["tension_N"] > 800.0 and 0 < ev[0]["t_s"] < 9.0
    assert json.loads((tmp_path / "out" / "summary.json").read_text())["line_breaks"] == ev
    t = r["left.tension"]
    assert t[r.t > ev[0]["t_s"]].max() > 0  # it holds: report only
    assert r.t[np.argmax(t > 800.0)] >= ev[0]["t_s"] - 0.1  # no sample saw it past the load earlier


def test_a_released_line_stops_pulling(tmp_path):
    r = moored(800.0, release=True).run(tmp_path / "out")
    ev = r.summary["line_breaks"][0]
    assert ev["released"] is True and ev["line"] == "left"
    after = r.t >= ev["t_s"]
    assert np.all(r["left.tension"][after] == 0.0) and r["right.tension"][after].min() > 0
    assert r["box.surge"][-1] > 1.0  # the right line pulls the box away


def test_gauges_read_the_analytic_fluids_waves(tmp_path):
    """A gauge of a scene with linear waves on the analytic fluid records η of the wave
    (Dean & Dalrymple Table 4.1) at its (x, y), ramp included: the same probe as the SPH
    fluid's, so a scene keeps its gauges whichever fluid it has."""
    s = dataclasses.replace(moored(dim=3, duration=7.0), probes=Probes(gauges=[(0.0, 0.0), (11.5, 3.0)], loads=False,
                                                                       motion=(), tensions=False))
    r = s.run(tmp_path / "out")
    from fluid.analytic import LinearWave

    wave = LinearWave(1.5, 6.0, 10.0, ramp=6.0)
    for i, at in enumerate([(0.0, 0.0), (11.5, 3.0)]):
        want = [wave.elevation(np.array(at), t) for t in r.t]
        np.testing.assert_allclose(r[f"gauge{i + 1}.eta"], want, rtol=0, atol=1e-12)
    assert np.abs(r["gauge1.eta"]).max() == pytest.approx(0.75, rel=0.01)  # a crest at x = 0 at t = 6 s


def test_a_linear_wave_deeper_or_shallower_than_the_flume_is_refused(tmp_path):
    """The analytic fluid's still surface is the flume's depth over its floor (z = 0): a
    linear wave whose depth differs would decay to a seabed that is not there (10 m of
    water, a wave of 20 m depth: tanh(kd) 0.76 against 0.96 at T = 6 s, 20 % in its orbital
    speed at the floor). Refused naming waves.depth, both depths and the fix; equal depths
    build."""
    from cosim.scene import Flume
    from cosim.scene.fields import SceneError

    s = dataclasses.replace(moored(), domain=Flume(length=200.0, depth=10.0, height=15.0),
                            bodies=[Box("box", size=(2.0, 1.0), pos=(100.0, 10.0), density=500.0,
                                        fairleads={"left": (-1.0, -0.5), "right": (1.0, -0.5)})],
                            moorings=None)
    s.validate()  # waves.depth = 10 m, the flume's depth
    for depth in (20.0, 9.5):
        with pytest.raises(SceneError, match=rf"waves.depth: {depth:g} m differs from the flume's still-water "
                                             rf"depth 10 m \(domain.depth\).*give waves.depth = 10"):
            dataclasses.replace(s, waves=dataclasses.replace(s.waves, depth=depth))
    with pytest.raises(SceneError, match="waves.depth"):
        s.with_values(["waves.depth=12.0"])
    assert build(s, tmp_path).fluid.waves.depth == 10.0
