"""Bodies on a prescribed motion (``bodies[].motion``) with lines on them: a test rig. The
body follows its motion exactly, whatever the lines pull; the lines' tensions and points
are recorded."""

import math

import numpy as np
import pytest

RIG = """
name = "rig"
[world]
dim = 2
duration = 4.0
sample_every = 0.05
snapshot_every = 0.0
[fluid]
model = "none"
[[bodies]]
shape = "box"
name = "support"
size = [0.02, 0.02]
mass = 0.1
pos = [0.0, 0.0]
fairleads = { p0 = [0.0, 0.0] }
motion = MOTION
[moorings]
model = "sph-cable"
segments = 11
seabed = false
lines = [{ fairlead = "support.p0", name = "cable", anchor = [1.2, -0.22], length = 1.272, weight = 0.2656, EA = 21402.1, mass_per_length = 0.027084, points = [0.636, 1.272] }]
[probes]
motion = ["support"]
[coupling]
body_timestep = 0.05
"""


def _run(tmp_path, motion: str):
    from cosim.scene import Scene

    path = tmp_path / "rig.toml"
    path.write_text(RIG.replace("MOTION", motion))
    return Scene.from_toml(path).run(tmp_path / "out", progress=False)


def test_a_shake_of_some_cycles_stops_where_it_got_to_and_the_line_follows_its_end(tmp_path):
    """Harmonic, 25 mm at 1 s, no ramp, 3 cycles: the support is at 0.025 sin(2 pi t) until
    t = 3 s and held at 0 after; the cable's recorded end (s = L from the anchor) is the
    support's point at every sample; the cable hangs below its anchor with no seabed."""
    res = _run(tmp_path, '{ kind = "harmonic", dof = "surge", amplitude = 0.025, period = 1.0, ramp = 0.0, '
                         'cycles = 3.0 }')
    t, x = res.t, res["support.surge"]
    expected = np.where(t < 3.0, 0.025 * np.sin(2.0 * math.pi * t), 0.0)
    assert np.abs(x - expected).max() < 1e-12
    assert np.abs(res["cable.point2_x"] - x).max() < 1e-9 and np.abs(res["cable.point2_z"]).max() < 1e-9
    assert res["cable.point1_z"].min() < -0.25  # the middle sags below the anchor at -0.22 m


def test_a_table_motion_holds_its_last_point_and_refuses_a_first_point_off_pos(tmp_path):
    """Straight between the points, held after the last: 0.1 m over 2 s, then still."""
    res = _run(tmp_path, '{ kind = "table", dof = "surge", points = [[0.0, 0.0], [2.0, 0.1]] }')
    t, x = res.t, res["support.surge"]
    assert np.abs(x - np.minimum(0.05 * t, 0.1)).max() < 1e-12
    from cosim.scene.fields import SceneError

    with pytest.raises(SceneError, match="the motion starts at the body's pos"):
        _run(tmp_path, '{ kind = "table", dof = "surge", points = [[0.0, 0.1], [2.0, 0.2]] }')


def test_a_rig_s_dynamic_line_is_advanced_once_a_step_and_its_mean_force_is_the_load(tmp_path):
    """A body on prescribed joints moves as it does whatever its lines pull: the coupler
    takes the first advance of a dynamic line as the converged one (``line_iterations`` 1),
    and the load it books is the line's own mean force over the step."""
    from cosim.scene import Scene
    from cosim.scene.build import build

    path = tmp_path / "rig.toml"
    path.write_text(RIG.replace("MOTION", '{ kind = "harmonic", dof = "surge", amplitude = 0.025, period = 1.0, '
                                          'ramp = 0.0 }'))
    built = build(Scene.from_toml(path), tmp_path / "work")
    c, m = built.coupler, built.mooring
    c.initialize()
    for _ in range(5):
        c.step(c.t + 0.05)
        assert c.line_iterations == 1
        booked = c.ledger.last()["mooring_force"][0]
        assert np.allclose(booked[[0, 2]], m.mean_fairlead_forces()[0], rtol=1e-12, atol=0.0)
