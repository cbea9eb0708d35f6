"""The scene's near field (``domain.kind = "nearfield"``): the box chosen from the bodies and
the sea (fluid.nearfield.choose_box, cosim.scene.nearfield), what it is refused for, and a
short run that reports the choice."""

import json
import math

import numpy as np
import pytest
from scipy.optimize import brentq

from cosim.scene import Scene
from cosim.scene.fields import SceneError
from cosim.scene.nearfield import box_for, heave_period, reach
from fluid.nearfield import MIN_MARGIN_SUPPORTS, MIN_ZONE_SUPPORTS, choose_box
from fluid.waves import RegularWave

G = 9.81

SCENE = """
name = "nf"
[world]
dim = 2
duration = 0.1
sample_every = 0.05
[fluid]
model = "sph"
dx = 0.02
[domain]
kind = "nearfield"
depth = 0.3
[waves]
kind = "regular"
height = 0.04
period = 1.0
depth = 0.3
[[bodies]]
shape = "box"
name = "box"
size = [0.2, 0.1]
density = 500.0
pos = [1.2]
place = "floating"
[probes]
gauges = [1.0]
motion = ["box"]
"""


def _scene(tmp_path, text=SCENE, *changes):
    p = tmp_path / "nf.toml"
    p.write_text(text)
    s = Scene.from_toml(p)
    return s.with_values(list(changes)) if changes else s


def _wavelength(T, d):
    w = 2 * math.pi / T
    k = brentq(lambda k: G * k * math.tanh(k * d) - w * w, 1e-9, 1e4)
    return 2 * math.pi / k


def test_the_heave_period_of_a_floating_box():
    """2 pi sqrt((m + A33) / (rho g Awp)), A33 = rho pi B^2 / 8 for a 2-D strip, (4/3) rho r^3
    for a 3-D waterplane of equivalent radius r."""
    from cosim.scene.spec import Box, Cylinder, Sphere

    b = Box(name="b", size=(0.2, 0.1), density=500.0, pos=(1.0,), place="floating")
    m, a33 = 500.0 * 0.02, 1000.0 * math.pi * 0.04 / 8
    assert heave_period(b, 2, 1000.0, G) == pytest.approx(2 * math.pi * math.sqrt((m + a33) / (1000 * G * 0.2)))
    c = Cylinder(name="c", radius=3.0, length=3.0, density=500.0, pos=(0.0, 0.0), place="floating")
    m, a33 = 500.0 * math.pi * 9 * 3, 4 / 3 * 1000.0 * 27
    assert heave_period(c, 3, 1000.0, G) == pytest.approx(2 * math.pi * math.sqrt((m + a33) /
                                                                                  (1000 * G * math.pi * 9)))
    ball = Sphere(name="s", radius=0.1, density=500.0, pos=(1.0, 0.0), place="floating")
    assert heave_period(ball, 3, 1000.0, G) is None  # not estimated: the sea's period sets the zones


def test_the_zone_is_half_the_wavelength_of_the_longest_natural_period_within_the_sea():
    sea = RegularWave(0.04, 1.0, 0.3, level=0.3)
    h = 0.04
    c = choose_box(sea, h, ((1.1,), (1.3,)), reach=0.05, periods=(0.7, 1.6))  # 1.6 s is longer than the sea's
    assert c.zone == pytest.approx(0.5 * _wavelength(0.7, 0.3), rel=1e-9)
    margin = 0.05 + MIN_MARGIN_SUPPORTS * 2 * h
    assert c.x == pytest.approx((1.1 - margin - c.zone, 1.3 + margin + c.zone))
    assert c.height == pytest.approx(0.3 + 2 * 0.04 + 4 * h)
    # no body period: the sea's; a tiny wave: the floor of kernel supports
    assert choose_box(sea, h, ((0.0,), (0.0,))).zone == pytest.approx(0.5 * _wavelength(1.0, 0.3), rel=1e-9)
    assert choose_box(sea, h, ((0.0,), (0.0,)), periods=(0.05,)).zone == pytest.approx(MIN_ZONE_SUPPORTS * 2 * h)
    # given values are kept, and said so
    g = choose_box(sea, h, ((0.0,), (0.0,)), zone=0.3, x=(-1.0, None), height=0.5)
    assert (g.zone, g.x[0], g.height) == (0.3, -1.0, 0.5)
    assert g.reasons["zone"] == g.reasons["x0"] == g.reasons["height"] == "given"
    assert "natural period" in c.reasons["zone"] and "peak period" in choose_box(sea, h, ((0,), (0,))).reasons["zone"]
    # 3-D: across y as along x, centred on the bodies
    c3 = choose_box(sea, h, ((1.1, -0.2), (1.3, 0.3)), reach=0.05, periods=(0.7,), dim=3)
    assert c3.y == pytest.approx((-0.2 - margin - c3.zone, 0.3 + margin + c3.zone))
    assert choose_box(sea, h, ((1.1, -0.2), (1.3, 0.3)), dim=3, width=2.0).y == pytest.approx((-0.95, 1.05))
    # a whole number of spacings each side of the centre, so that the lattice is symmetric about it
    dx = 0.03
    c4 = choose_box(sea, h, ((1.1, -0.2), (1.3, 0.3)), reach=0.05, periods=(0.7,), dim=3, dx=dx)
    half = 0.5 * (c4.y[1] - c4.y[0])
    assert half / dx == pytest.approx(round(half / dx), abs=1e-9) and 0 <= half - (c3.y[1] - 0.05) < dx
    assert 0.5 * (c4.y[0] + c4.y[1]) == pytest.approx(0.05)
    # and a whole number along x, widened on both ends alike (on the chosen end where one is given)
    length = c4.x[1] - c4.x[0]
    assert length / dx == pytest.approx(round(length / dx), abs=1e-9) and 0 <= length - (c3.x[1] - c3.x[0]) < dx
    assert 0.5 * (c4.x[0] + c4.x[1]) == pytest.approx(0.5 * (c3.x[0] + c3.x[1]))
    one = choose_box(sea, h, ((1.1,), (1.3,)), reach=0.05, periods=(0.7,), dx=dx, x=(-0.01, None))
    assert one.x[0] == -0.01 and (one.x[1] + 0.01) / dx == pytest.approx(round((one.x[1] + 0.01) / dx), abs=1e-9)
    # both ends given: the far one moves out to whole rows, as the box lays the water, and says so
    both = choose_box(sea, h, ((1.1,), (1.3,)), dx=dx, x=(0.0, 2.005))
    assert both.x == pytest.approx((0.0, 2.01)) and both.reasons["x0"] == "given"
    assert "moved out 0.005 m" in both.reasons["x1"] and both.reasons["x1"].startswith("given (2.005 m)")
    assert choose_box(sea, h, ((1.1,), (1.3,)), dx=dx, x=(0.0, 2.01)).reasons["x1"] == "given"
    # a symmetry plane: from y = 0, as wide as the whole box's half
    c5 = choose_box(sea, h, ((1.1, -0.3), (1.3, 0.3)), reach=0.05, periods=(0.7,), dim=3, dx=dx, symmetric=True)
    whole = choose_box(sea, h, ((1.1, -0.3), (1.3, 0.3)), reach=0.05, periods=(0.7,), dim=3, dx=dx)
    assert c5.y == pytest.approx((0.0, whole.y[1])) and "symmetry plane" in c5.reasons["width"]
    # side zones as wide as the end ones; a channel (no side zones) as wide as the bodies and their margin
    assert c3.side_zone == c3.zone and c.side_zone is None
    ch = choose_box(sea, h, ((1.1, -0.2), (1.3, 0.3)), reach=0.05, periods=(0.7,), dim=3, side_zones=False)
    assert ch.side_zone is None and ch.zone == c3.zone and ch.x == c3.x
    assert ch.y == pytest.approx((-0.2 - margin, 0.3 + margin)) and "no side zones" in ch.reasons["width"]
    assert "channel" in ch.reasons["side_zone"] and ch.as_dict()["side_zone_m"] is None


def test_a_scene_gets_its_box_from_its_bodies_and_sea(tmp_path):
    s = _scene(tmp_path)
    c = box_for(s)
    sea = RegularWave(0.04, 1.0, 0.3, level=0.3)
    kd = sea.wavenumber * 0.3
    assert reach(s) == pytest.approx(2 * 0.02 / math.tanh(kd))
    # k size = 0.46: not small against the sea's wavelength, whose half sets the zones
    assert c.zone == pytest.approx(0.5 * sea.wavelength, rel=1e-9) and "not small" in c.reasons["zone"]
    assert 0.5 * (c.x[0] + c.x[1]) == pytest.approx(1.2)  # the body in the middle
    # a small body (k size <= 0.1): its own heave period's wavelength
    tiny = _scene(tmp_path, SCENE, "bodies[0].size=[0.04, 0.02]")
    tn = heave_period(tiny.bodies[0], 2, 1000.0, G)
    assert box_for(tiny).zone == pytest.approx(max(0.5 * _wavelength(tn, 0.3), MIN_ZONE_SUPPORTS * 2 * 0.04),
                                               rel=1e-9)
    # no body: the sea's wavelength sets the zones
    bare = _scene(tmp_path, SCENE.split("[[bodies]]")[0] + "[probes]\ngauges = [0.0]\n")
    assert box_for(bare).zone == pytest.approx(0.5 * sea.wavelength, rel=1e-9)


@pytest.mark.parametrize("change, key", [
    (("waves.direction=180",), "waves.direction"),
    (("domain.width=1.0",), "domain.width"),
    (("domain.x0=1.0",), "bodies[0].pos"),
    (("domain.zone=0.5", "domain.x0=0.6", "domain.x1=1.8"), "bodies[0].pos"),
    (("domain.height=0.2",), "domain.height"),
    (("domain.x0=2.0", "domain.x1=1.0"), "domain.x1"),
])
def test_bad_near_fields_are_refused_naming_the_key(tmp_path, change, key):
    with pytest.raises(SceneError) as e:
        _scene(tmp_path, SCENE, *change)
    assert e.value.path == key


def test_a_near_field_needs_an_incident_sea(tmp_path):
    with pytest.raises(SceneError) as e:
        _scene(tmp_path, SCENE.replace('kind = "regular"', 'kind = "piston"').replace("depth = 0.3\n[[", "[["))
    assert e.value.path.startswith("waves")


def test_a_short_run_reports_the_box_and_moves_its_end_walls_with_the_sea(tmp_path):
    s = _scene(tmp_path)
    res = s.run(out=tmp_path / "out")
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    nf = summary["near_field"]
    c = box_for(s)
    assert nf["x_m"] == pytest.approx(list(c.x)) and nf["zone_m"] == pytest.approx(c.zone)
    assert set(nf["reasons"]) == {"zone", "x0", "x1", "height"}
    assert summary["setup"]["name"] == "waves"
    assert (tmp_path / "out" / "sea_components.csv").exists()
    # the estimate counted the particles the box holds, within a few per cent
    est = summary["estimate"]
    assert est["particles"] == pytest.approx(summary["particles"], rel=0.05)
    assert np.isfinite(res.series["box.heave"]).all()


def test_a_near_field_scene_reads_back_from_its_toml(tmp_path):
    s = _scene(tmp_path, SCENE, "domain.zone=0.35", "domain.rate=3.0")
    again = Scene.from_dict(__import__("tomllib").loads(s.to_toml()))
    assert again == s and again.domain.zone == 0.35 and again.domain.rate == 3.0


WIND_TURBINE_BASE = """
name = "wt"
[world]
dim = 3
duration = 0.2
sample_every = 0.05
[fluid]
model = "sph"
dx = 1.5
rho0 = 1025.0
[domain]
kind = "nearfield"
depth = 20.0
[waves]
kind = "regular"
height = 0.7
period = 20.0
depth = 20.0
[[bodies]]
shape = "cylinder"
name = "base"
radius = 3.0
length = 3.0
mass = 16000.0
pos = [70.0, Y]
place = "floating"
fairleads = { back = [3.0, 0.0, -1.5], port = [-1.5, 2.5981, -1.5], starboard = [-1.5, -2.5981, -1.5] }
[moorings]
lines = [
  { fairlead = "base.back", anchor = [107.0, Y, 0.0], length = 45.0, weight = 3769.85 },
  { fairlead = "base.port", anchor = [51.5, Y + 32.0429, 0.0], length = 45.0, weight = 3769.85 },
  { fairlead = "base.starboard", anchor = [51.5, Y - 32.0429, 0.0], length = 45.0, weight = 3769.85 },
]
[probes]
motion = ["base"]
gauges = [[70.0, -12.0], [70.0, 12.0]]
"""


def _base_at(tmp_path, y: float, *changes):
    text = WIND_TURBINE_BASE.replace("Y + 32.0429", f"{y + 32.0429}").replace("Y - 32.0429", f"{y - 32.0429}")
    text = text.replace("gauges = [[70.0, -12.0], [70.0, 12.0]]", f"gauges = [[70.0, {y - 12}], [70.0, {y + 12}]]")
    return _scene(tmp_path, text.replace("Y", f"{y}"), *changes)


def test_a_3d_near_field_is_centred_on_its_bodies(tmp_path):
    """The wind-turbine base of Barreiro et al. 2016 (§5) off the origin: the box centred on
    it across y, zones inside the side walls too (the base is small against the 20 s wave:
    its heave period sets them), a whole number of spacings each side."""
    s = _base_at(tmp_path, 20.0)
    c = box_for(s)
    assert 0.5 * (c.y[0] + c.y[1]) == pytest.approx(20.0) and c.y[1] - c.y[0] == pytest.approx(c.x[1] - c.x[0], abs=3.0)
    assert (c.y[1] - 20.0) / 1.5 == pytest.approx(round((c.y[1] - 20.0) / 1.5), abs=1e-9)
    assert "natural period" in c.reasons["zone"]


def test_a_3d_channel_has_zones_at_its_ends_only(tmp_path):
    """``domain.side_zones = false``: the box as wide as the base and its margin, slip side
    walls with no zone inside them (two slabs, both across x), and the base may stand
    nearer the sides than the zones' width; with side zones (the default) four slabs."""
    from cosim.scene.build import build

    zoned, channel = _base_at(tmp_path, 0.0), _base_at(tmp_path, 0.0, "domain.side_zones=false")
    cz, cc = box_for(zoned), box_for(channel)
    assert cc.side_zone is None and cz.side_zone == cz.zone
    assert cz.y[1] - cc.y[1] == pytest.approx(cz.zone, abs=1.5)  # the zone's width, to a spacing
    slabs = {}
    for name, s in (("zoned", zoned), ("channel", channel)):
        b = build(s, tmp_path / name)
        slabs[name] = sorted(z.axis for z in b.sph.zones)
    assert slabs == {"zoned": [0, 0, 1, 1], "channel": [0, 0]}
    # a box 40 m wide: its side zones (24 m) would reach the base and its reach; the channel's water holds them
    with pytest.raises(SceneError) as e:
        _base_at(tmp_path, 0.0, "domain.width=40.0")
    assert e.value.path == "bodies[0].pos" and "relaxation zones" in e.value.problem
    assert box_for(_base_at(tmp_path, 0.0, "domain.width=40.0", "domain.side_zones=false")).y == (-20.0, 20.0)


@pytest.mark.slow  # a minute of CPU: out of CI's time (docs/development.md); the mirror's own tests stay
def test_a_symmetry_plane_runs_half_the_particles_and_the_whole_boxs_motion(tmp_path):
    """The base on its three lines (one in the plane y = 0, two mirrored) in a 3-D near field
    at a coarse spacing, the whole box and its half y >= 0 with a symmetry plane
    (fluid.mirror): the same motions, loads, tensions and gauges to round-off (the whole
    box's lattice is symmetric about the base, so both run the same physics), half the
    particles, as many as the estimate counted; a gauge at y < 0 reads its mirror image.
    The explicit scheme (the flagship's, wind-turbine-sph.toml): one fluid advance a step."""
    runs = {}
    for sym in (False, True):
        s = _base_at(tmp_path, 0.0, f"domain.symmetry={'true' if sym else 'false'}", "coupling.scheme=explicit")
        res = s.run(out=tmp_path / f"out{sym}")
        runs[sym] = (res, json.loads((tmp_path / f"out{sym}" / "summary.json").read_text()))
    (whole, sw), (half, sh) = runs[False], runs[True]
    assert sh["near_field"]["y_m"] == pytest.approx([0.0, sw["near_field"]["y_m"][1]])
    assert 2 * sh["fluid_particles"] == sw["fluid_particles"]
    assert sh["estimate"]["particles"] == pytest.approx(sh["particles"], rel=0.05)
    assert sw["estimate"]["particles"] == pytest.approx(sw["particles"], rel=0.05)
    assert set(whole.series) == set(half.series)

    def family(key):  # compared against the largest of its kind: the whole box's side loads are rounding
        return "load" if "_F" in key or "tension" in key else "motion" if key.startswith("base.") else key

    scale = {}
    for k, a in whole.series.items():
        scale[family(k)] = max(scale.get(family(k), 0.0), np.abs(a).max())
    for k, a in whole.series.items():
        np.testing.assert_allclose(half.series[k], a, rtol=0, atol=1e-9 * scale[family(k)], err_msg=k)
    assert np.abs(whole.series["base.heave"]).max() > 1e-3  # it moved
    np.testing.assert_array_equal(half.series["gauge1.eta"], half.series["gauge2.eta"])


def test_a_near_field_re_initialises_its_density(tmp_path):
    """The near field's set-up (fluid.solver.NEAR_FIELD): the waves set-up and the density
    re-initialised every 150 steps, which holds the box's mean level; a scene's own
    mls_every overrides it."""
    from cosim.scene.setup import choose
    from fluid.solver import NEAR_FIELD, TRAVELLING_WAVES

    near = choose(_scene(tmp_path))
    assert near.name == "waves" and near.config["mls_every"] == NEAR_FIELD["mls_every"] == 150
    assert "near field" in near.reason
    assert all(near.config[k] == v for k, v in TRAVELLING_WAVES.items())
    assert choose(_scene(tmp_path, SCENE, "fluid.mls_every=0")).config["mls_every"] == 0


@pytest.mark.long
def test_absorbing_end_walls_record_their_correction_and_resume_bit_for_bit(tmp_path):
    """``domain.absorbing_walls``: the end walls' correction and the elevation they read
    are recorded (``end_walls``: near_wall.xi, ...); a run stopped at a checkpoint and
    resumed equals the run made in one go (the walls' state travels with the fluid's);
    without the field there is no such series."""
    s = _scene(tmp_path, SCENE, "domain.absorbing_walls=true", "world.duration=0.1", "world.sample_every=0.025",
               "world.checkpoint_every=0.05")
    whole = s.run(out=tmp_path / "whole", progress=False)
    s.with_values(["world.duration=0.05"]).run(out=tmp_path / "split", progress=False)
    resumed = s.run(out=tmp_path / "split", resume=True, progress=False)
    assert resumed.summary["resumed"]
    for name in whole.names:
        np.testing.assert_array_equal(resumed[name], whole[name], err_msg=name)
    # the walls' reading starts at the fluid's own offset, which the filter takes off:
    # within a tenth of a second the correction stays far below a spacing
    xi = np.abs(np.concatenate([whole["near_wall.xi"], whole["far_wall.xi"]]))
    assert np.isfinite(xi).all() and xi.max() < 0.05 * 0.02 and np.isfinite(whole["far_wall.eta"]).all()
    assert (tmp_path / "whole" / "end_walls.csv").exists()
    assert "near_wall.xi" not in _scene(tmp_path).run(out=tmp_path / "plain", progress=False).names


def test_a_kept_run_from_before_a_new_field_is_the_same_scene(tmp_path):
    """A run kept before a field was added to the scenes (its scene.toml lacks it) is the
    same scene as one that has the field at its default, and another where it differs."""
    from cosim.scene.runner import kept_scene_difference

    s = _scene(tmp_path)
    text = s.to_toml()
    assert "\nabsorbing_walls = false\n" in text
    (tmp_path / "scene.toml").write_text(text.replace("\nabsorbing_walls = false\n", "\n"))
    assert kept_scene_difference(s, tmp_path) is None
    assert kept_scene_difference(s.with_values(["domain.absorbing_walls=true"]), tmp_path) == "domain.absorbing_walls"
