"""A shaken tank as a scene: a harmonic base motion cut at ``base_motion.stop`` and held
where it got to (``hold = true``), and the SPH domain that covers the tank's travel over
the run and the water above its walls (cosim.scene.sph_domain)."""

import json
import math

import numpy as np
import pytest

from cosim.scene import Scene
from cosim.scene.build import build
from cosim.scene.sph_domain import moving_tank_domain, sample_times
from fluid.motion import Harmonic, Translation
from fluid.particles import Kind

G = 9.81


def _scene(a0=0.5 * G, period=1.0, stop=3.0, duration=5.0, dx=0.1, length=3.0, height=1.5, depth=1.0, hold=True):
    return Scene.from_dict({
        "name": "shaken", "world": {"dim": 2, "duration": duration, "sample_every": 0.05},
        "fluid": {"model": "sph", "dx": dx},
        "domain": {"kind": "tank", "length": length, "height": height, "depth": depth},
        "base_motion": {"kind": "harmonic", "period": period, "acceleration": a0, "stop": stop, "hold": hold,
                        "direction": [1.0, 0.0]}})


def test_a_held_shake_is_held_where_it_got_to(tmp_path):
    """Sunara et al. 2021, §3.1's a0 sin(2 pi t / T) from rest, cut after N = 3 whole periods:
    the motion until then, and after it the tank at rest at its value at the stop, having
    travelled a0 T^2 N / (2 pi) = 2.342 m at 0.5 g and T = 1 s."""
    a0, T, N = 0.5 * G, 1.0, 3
    b = build(_scene(a0, T, N * T), tmp_path)
    h = Harmonic.from_peak_acceleration(a0, T, from_rest=True)
    ref = np.zeros((1, 2))
    for t in np.linspace(0.0, N * T, 13):
        assert b.base_motion(t, ref)[0][0, 0] == h.state(t)[0]
    for t in (N * T + 1e-6, 4.0, 10.0):
        pos, vel = b.base_motion(t, ref)
        assert pos[0, 0] == h.state(N * T)[0]
        assert pos[0, 0] == pytest.approx(a0 * T**2 * N / (2 * math.pi), rel=1e-12)
        assert vel.tolist() == [[0.0, 0.0]]


def test_a_fading_stop_still_returns_to_the_start(tmp_path):
    """``hold = false`` (the default) keeps the fade over ``ramp``, which ends at rest at
    the start."""
    s = Scene.from_dict({
        "name": "shaken", "world": {"dim": 2, "duration": 5.0}, "fluid": {"model": "sph", "dx": 0.1},
        "domain": {"kind": "tank", "length": 3.0, "height": 1.5, "depth": 1.0},
        "base_motion": {"kind": "harmonic", "period": 1.0, "amplitude": 0.05, "ramp": 1.0, "stop": 3.0}})
    b = build(s, tmp_path)
    assert b.base_motion(4.0, np.zeros((1, 2)))[0].tolist() == [[0.0, 0.0]]


def test_the_domain_covers_the_tank_travel_and_the_splashes(tmp_path):
    """The domain holds the tank's walls at every time of the run (sampled here every 5 ms,
    independently of the domain's own samples), its travel along x is the held drift
    a0 T^2 N / (2 pi) exactly, the margin is the solver's max(10 %, 4 h) and the room above
    the walls the tank's own height."""
    a0, T, N, duration = 0.5 * G, 1.0, 3, 5.0
    b = build(_scene(a0, T, N * T, duration), tmp_path)
    f = b.sph
    cfg, d = f.config, b.sph_domain
    lo, hi = np.array(cfg.domain_lo), np.array(cfg.domain_hi)
    walls = f.ps.pos[f.ps.kind == Kind.MOVING_WALL].copy()
    start_lo, start_hi = f.ps.pos.min(0), f.ps.pos.max(0)
    for t in np.arange(0.0, duration + 1e-9, 0.005):
        moved = b.base_motion(t, walls)[0]
        assert (moved >= lo).all() and (moved < hi).all(), t
    drift = a0 * T**2 * N / (2 * math.pi)
    assert d.travel[1][0] == pytest.approx(drift, rel=1e-12)
    assert d.travel[0] == (0.0, 0.0) and d.travel[1][1] == 0.0
    pad = np.maximum(0.1 * (start_hi - start_lo), 4 * cfg.h)
    np.testing.assert_allclose(lo, start_lo - pad, rtol=0, atol=1e-12)
    np.testing.assert_allclose(hi, start_hi + pad + [drift, start_hi[1] - start_lo[1]], rtol=0, atol=1e-12)
    assert hi[0] - start_hi[0] > 2.0     # the solver's own box would have lost the right wall


def test_a_roll_is_covered_by_its_turned_corners():
    """Under a roll by 30 deg about the origin the box holds the turned extent: its
    corner (1, 0) reaches z = -sin 30 deg = -0.5 m and (1, 1) x = cos 30 + sin 30."""
    from fluid.motion import Rotation

    pts = np.array([[0.0, 0.0], [1.0, 1.0]])
    d = moving_tank_domain(pts, Rotation((0.0, 0.0), Harmonic(math.radians(30.0), 4.0)), sample_times(1.0), 0.0)
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    assert d.travel[0][1] == pytest.approx(-s, abs=1e-12)          # z' = -x sin + z cos at (1, 0)
    assert d.travel[1][0] == pytest.approx(c + s - 1.0, abs=1e-12)  # x' = x cos + z sin at (1, 1)
    assert d.pad == (0.1, 0.1) and d.splash == 1.0
    assert d.hi[1] == pytest.approx(1.0 + (d.travel[1][1]) + 0.1 + 1.0)


@pytest.mark.long
def test_no_wall_particle_leaves_over_a_long_shake(tmp_path):
    """A small tank (0.6 m, dx = 5 cm) shaken at 2 m/s^2 with a 0.4 s period from rest for
    10 periods, held, then 1 s at rest: it drifts a0 T^2 N / (2 pi) = 0.51 m, more than the
    solver's own margin (4 h = 0.4 m), and no particle, wall or water, is removed."""
    a0, T, N = 2.0, 0.4, 10
    s = _scene(a0, T, N * T, N * T + 1.0, dx=0.05, length=0.6, height=0.4, depth=0.2)
    b = build(s, tmp_path)
    drift = a0 * T**2 * N / (2 * math.pi)
    assert b.sph_domain.travel[1][0] == pytest.approx(drift, rel=1e-12) and drift > 4 * b.sph.config.h
    n = b.sph.ps.n
    b.coupler.run(s.world.duration)
    assert b.sph.counters.removed == {k.name: 0 for k in Kind}
    assert b.sph.ps.n == n
    walls = b.sph.ps.pos[b.sph.ps.kind == Kind.MOVING_WALL]
    assert walls[:, 0].max() > b.sph_domain.start[1][0] + 0.99 * drift   # they did travel


def test_the_summary_reports_the_domain(tmp_path):
    """summary.json's ``sph_domain``: the box the fluid was given, and why."""
    s = _scene(duration=0.05)
    s.run(tmp_path / "run")
    dom = json.loads((tmp_path / "run" / "summary.json").read_text())["sph_domain"]
    b = build(s, tmp_path / "b")
    assert dom["lo_m"] == list(b.sph.config.domain_lo) and dom["hi_m"] == list(b.sph.config.domain_hi)
    assert set(dom["reasons"]) == {"travel", "pad", "splash"}
