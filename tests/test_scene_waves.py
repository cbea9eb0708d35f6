"""Waves and line breaking in scenes (issue 18): the analytic fluid's waves from
``waves = LinearWaves(...)``, ``RegularWaves`` and ``IrregularWaves``, break loads
and ``moorings.release_broken``, in TOML and Python."""

import dataclasses
import json
import math

import numpy as np
import pytest

from cosim.scene import Analytic, Box, IrregularWaves, Line, LinearWaves, Moorings, Probes, RegularWaves, Scene, World
from cosim.scene.build import build
from fluid import waves as fw

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


@pytest.mark.long
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


@pytest.mark.long
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


# ------------------------------------------------------------------------ regular and irregular kinds
def sea_scene(waves, dim=2, duration=3.0, sample_every=0.1, gauges=(0.0, 7.5)):
    """A thin floating box (few analytic-fluid cells) under gauges, 30 m of water."""
    size = (2.0, 0.2) if dim == 2 else (2.0, 1.0, 0.2)
    return Scene(name="sea", world=World(dim=dim, duration=duration, sample_every=sample_every),
                 fluid=Analytic(rho=1025.0, linear_damping={"box": [800.0, 800.0, 1500.0, 1500.0, 1500.0, 1500.0]}),
                 waves=waves, bodies=[Box("box", size=size, pos=(0.0,) * (dim - 1), density=500.0,
                                          place="floating")],
                 probes=Probes(gauges=list(gauges), loads=False, tensions=False))


def test_regular_and_irregular_kinds_round_trip_through_toml(tmp_path):
    (tmp_path / "eta.txt").write_text("t eta\n" + "".join(f"{0.5 * i} {0.1 * math.sin(0.7 * i)}\n"
                                                          for i in range(64)))
    for w in (RegularWaves(height=1.0, period=6.0, depth=30.0, theory="stokes2", phase=90.0),
              IrregularWaves(depth=30.0, hs=1.5, tp=8.0, gamma=2.0, seed=4, components=50),
              IrregularWaves(depth=30.0, spectrum="pierson-moskowitz", hs=1.5, tp=8.0),
              IrregularWaves(depth=30.0, spectrum="series", file=str(tmp_path / "eta.txt"), at=(2.0,), ramp=0.0)):
        s = sea_scene(w, duration=20.0)
        s.to_toml(tmp_path / "s.toml")
        assert Scene.from_toml(tmp_path / "s.toml") == s


def test_the_scene_gives_the_analytic_fluid_its_sea(tmp_path):
    """A kind's fields reach fluid.waves as given: the ramp in periods (of the wave, or the
    peak), the still level, gravity; a spectrum's components cover the run's duration."""
    b = build(sea_scene(RegularWaves(height=1.0, period=6.0, depth=30.0, theory="stokes2", phase=90.0,
                                     direction=180.0)), tmp_path)
    assert b.fluid.sea == fw.RegularWave(1.0, 6.0, 30.0, theory="stokes2", phase=90.0, direction=180.0,
                                         ramp=12.0, level=0.0, g=9.81)
    s = sea_scene(IrregularWaves(depth=30.0, hs=1.5, tp=8.0, seed=4, ramp=1.5), duration=3600.0)
    sea = build(s, tmp_path).fluid.sea
    assert isinstance(sea, fw.SpectralSea) and (sea.hs, sea.tp, sea.gamma, sea.seed, sea.ramp) == (1.5, 8.0, 3.3, 4,
                                                                                                    12.0)
    assert sea.repeat_period >= 3600.0
    wp = 2 * np.pi / 8.0
    banded = build(sea_scene(IrregularWaves(depth=30.0, hs=1.5, tp=8.0, band=(0.5, 1.65))), tmp_path / "band").fluid.sea
    omega = banded.components.omega
    assert banded.band == (0.5 * wp, 1.65 * wp) and omega.min() >= 0.5 * wp and omega.max() <= 1.65 * wp


def test_gauges_read_the_irregular_sea(tmp_path):
    w = IrregularWaves(depth=30.0, hs=1.0, tp=6.0, seed=2, components=20, ramp=0.5)
    s = sea_scene(w)
    r = s.run(tmp_path / "out")
    sea = fw.SpectralSea(1.0, 6.0, 30.0, seed=2, n_components=20, ramp=3.0, duration=3.0)
    for i, x in enumerate((0.0, 7.5)):
        np.testing.assert_allclose(r[f"gauge{i + 1}.eta"], sea.elevation(x, 0.0, r.t), rtol=0, atol=1e-12)


@pytest.mark.long
def test_a_recorded_series_is_what_its_gauge_reads(tmp_path):
    """A scene's series sea, read from its file (relative to the scene's folder), gives back
    the record (less its mean) at the point where it was measured, at the record's times."""
    t = 0.25 * np.arange(80)
    eta = 0.05 + 0.2 * np.cos(2 * np.pi * t / 5.0 + 0.3) + 0.07 * np.sin(2 * np.pi * t / 2.5)
    np.savetxt(tmp_path / "eta.csv", np.column_stack([t, 9.0 * eta, eta]), delimiter=",", header="t, x, eta")
    text = sea_scene(IrregularWaves(depth=30.0, spectrum="series", file=str(tmp_path / "eta.csv"), column=2,
                                    at=(7.5,), ramp=0.0), duration=10.0, sample_every=0.25).to_toml()
    (tmp_path / "s.toml").write_text(text.replace(repr(str(tmp_path / "eta.csv")).replace("'", '"'), '"eta.csv"'))
    assert 'file = "eta.csv"' in (tmp_path / "s.toml").read_text()
    r = Scene.from_toml(tmp_path / "s.toml").run(tmp_path / "out")
    n = len(r.t)
    np.testing.assert_allclose(r["gauge2.eta"], eta[:n] - eta.mean(), rtol=0, atol=1e-12)


@pytest.mark.parametrize("waves", [RegularWaves(height=0.04, period=1.0, depth=0.3),
                                   IrregularWaves(depth=0.3, hs=0.04, tp=1.0)])
def test_the_sph_fluid_refuses_an_incident_sea(waves):
    from cosim.scene import SPH, Flume
    from cosim.scene.fields import SceneError

    with pytest.raises(SceneError, match=r"waves.kind: \w+ waves act on the analytic or potential fluid's bodies .* the 'sph' "
                                         r"fluid has none: make waves with a piston or flap in a flume"):
        Scene(world=World(dim=2), fluid=SPH(dx=0.02), domain=Flume(length=3.0, depth=0.3, height=0.45),
              waves=waves)


def test_a_run_writes_the_incident_sea_and_its_spectrum(tmp_path):
    """sea_components.csv holds the components and, for a spectrum, the target S(ω) beside a² / 2Δω
    (equal: deterministic amplitudes); without gauges the sea's elevation at the origin is
    a probe; summary.json names the sea."""
    w = IrregularWaves(depth=30.0, hs=1.0, tp=6.0, seed=2, components=20, ramp=0.5)
    s = dataclasses.replace(sea_scene(w, duration=1.0), probes=Probes(loads=False, tensions=False))
    r = s.run(tmp_path / "out")
    sea = fw.SpectralSea(1.0, 6.0, 30.0, seed=2, n_components=20, ramp=3.0, duration=1.0)
    np.testing.assert_allclose(r["sea.eta"], sea.elevation(0.0, 0.0, r.t), rtol=0, atol=1e-12)
    table = np.loadtxt(tmp_path / "out" / "sea_components.csv", delimiter=",", skiprows=1)
    header = (tmp_path / "out" / "sea_components.csv").read_text().splitlines()[0].split(",")
    assert header == ["omega [rad/s]", "amplitude [m]", "phase [rad]", "k [rad/m]", "S [m^2 s/rad]",
                      "S_components [m^2 s/rad]"]
    np.testing.assert_allclose(table[:, :4], np.column_stack(sea.components), rtol=1e-15)
    np.testing.assert_allclose(table[:, 5], table[:, 4], rtol=1e-12)
    assert (tmp_path / "out" / "sea_spectrum.png").is_file()
    info = r.summary["sea"]
    assert info["kind"] == "SpectralSea" and info["hs_m"] == 1.0 and info["components"] == 20
    assert info["hs_components_m"] == pytest.approx(4 * math.sqrt(sea.moment(0)), rel=1e-12)
    assert info["repeat_period_s"] == pytest.approx(sea.repeat_period)
