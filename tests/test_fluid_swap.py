"""One scene, either fluid: a flume with a wavemaker runs on the SPH fluid or, by the
one field ``fluid.model``, on the analytic fluid, which takes the flume's depth as its
still level and the wavemaker's far-field wave (``cosim.scene.build.far_field_wave``);
and the flume in 3-D (a wave tank, the paddle across its width)."""

import math

import numpy as np
import pytest

from cosim.scene import SPH, Analytic, Box, Flap, Flume, Piston, Probes, Scene, SceneError, World

G = 9.81


def _k(T, d, g=G):
    """The dispersion relation w^2 = g k tanh(k d) by bisection (independent of fluid.wavemaker)."""
    w2, lo, hi = (2 * math.pi / T) ** 2, 1e-9, 1e3
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if G * mid * math.tanh(mid * d) < w2 else (lo, mid)
    return 0.5 * (lo + hi)


def _scene(waves, fluid=None, dim=2, duration=6.0):
    width = {"width": 0.4} if dim == 3 else {}
    pos = (2.0,) if dim == 2 else (2.0, 0.2)
    size = (0.2, 0.1) if dim == 2 else (0.2, 0.2, 0.1)
    gauges = (2.5, 3.0) if dim == 2 else ((2.5, 0.1), (3.0, 0.2))
    return Scene(name="swap", world=World(dim=dim, duration=duration, sample_every=0.02),
                 fluid=fluid or Analytic(), domain=Flume(length=4.0, depth=0.4, height=0.6, **width), waves=waves,
                 bodies=[Box("box", size=size, density=500.0, pos=pos, place="floating")],
                 probes=Probes(gauges=gauges))


@pytest.mark.parametrize("kind", ["piston", "flap"])
def test_analytic_flume_wave_has_wavemaker_theory_height(kind, tmp_path):
    from cosim.scene.build import build

    T, d = 1.2, 0.4
    waves = (Piston if kind == "piston" else Flap)(height=0.04, period=T, ramp=1.0)
    built = build(_scene(waves), tmp_path)
    wave = built.fluid.waves
    # the paddle's stroke, read from its motion after the ramp (x_swl for the flap: angle * depth)
    t = np.linspace(3 * T, 4 * T, 2001)
    x, _ = built.wavemaker.motion(t)
    S = 2 * np.abs(x).max() * (1.0 if kind == "piston" else d)
    kd = _k(T, d) * d
    if kind == "piston":  # Dean & Dalrymple (1991) eq. 6.21
        ratio = 2 * (math.cosh(2 * kd) - 1) / (math.sinh(2 * kd) + 2 * kd)
    else:  # eq. 6.22
        ratio = 4 * (math.sinh(kd) / kd) * (kd * math.sinh(kd) - math.cosh(kd) + 1) / (math.sinh(2 * kd) + 2 * kd)
    assert wave.H == pytest.approx(S * ratio, rel=2e-4)
    assert wave.k == pytest.approx(kd / d, rel=1e-9)
    assert built.level == pytest.approx(d) and built.fluid.eta == pytest.approx(d)


@pytest.mark.long
def test_analytic_flume_gauges_read_the_far_field_wave(tmp_path):
    T = 1.2
    res = _scene(Piston(height=0.04, period=T, ramp=1.0)).run(tmp_path / "a")
    t = res.t
    k, w = _k(T, 0.4), 2 * math.pi / T
    cg = 0.5 * (1 + 2 * k * 0.4 / math.sinh(2 * k * 0.4)) * w / k  # group velocity, 1.12 m/s
    for i, x in enumerate((2.5, 3.0)):
        late = t > x / cg + T + 1e-9  # the paddle's fade-in (1 T) has passed the gauge
        eta = res[f"gauge{i + 1}.eta"][late]
        assert eta.max() == pytest.approx(0.02, rel=2e-3)  # H/2 of the wave the stroke makes
        assert np.allclose(eta, 0.02 * np.cos(k * x - w * t[late]), atol=1e-9)  # crest at x = 0 at t = 0
        early = res[f"gauge{i + 1}.eta"][t < x / cg - 1e-9]  # before the group front arrives: still
        assert np.abs(early).max() < 1e-12
    assert abs(res["box.heave"]).max() > 0.01  # the body rides it
    assert res.summary["wavemaker"]["stroke_m"] > 0


def test_the_same_scene_builds_with_the_sph_fluid(tmp_path):
    from cosim.scene.build import build

    scene = _scene(Piston(height=0.04, period=1.2, ramp=1.0))
    sph = scene.with_values(["fluid.model=sph", "fluid.dx=0.04"])  # the analytic fields (rho, level) go
    assert isinstance(sph.fluid, SPH) and sph.domain == scene.domain and sph.waves == scene.waves
    built = build(sph, tmp_path)
    assert built.sph is not None and built.wavemaker is not None and built.level == pytest.approx(0.4)
    back = Scene.from_dict(sph.with_values(["fluid.model=analytic"]).to_dict())
    assert back.fluid == Analytic()


def test_analytic_fluid_refuses_what_it_cannot_take():
    with pytest.raises(SceneError, match="fluid.level"):
        _scene(Piston(height=0.04, period=1.2), fluid=Analytic(level=0.3))
    with pytest.raises(SceneError, match="domain.width"):
        Scene(world=World(dim=3), fluid=Analytic(), domain=Flume(length=4.0, depth=0.4, height=0.6),
              bodies=[Box("box", size=(0.2, 0.2, 0.1), density=500.0, pos=(2.0, 0.2), place="floating")])


def test_3d_flume_analytic_wave_is_long_crested(tmp_path):
    from cosim.scene.build import build

    built = build(_scene(Piston(height=0.04, period=1.2, ramp=1.0), dim=3), tmp_path)
    w = built.fluid.waves
    p = np.array([[2.5, 0.0, 0.4], [2.5, 0.4, 0.4]])
    assert w.elevation(p, 5.0)[0] == pytest.approx(w.elevation(p, 5.0)[1])


@pytest.mark.long
def test_3d_flume_piston_makes_a_wave_at_the_paddle(tmp_path):
    """A coarse 3-D wave tank (dx = 4 cm, 4 particles across): the piston's water rises at
    the paddle as linear theory's first crest arrives (a machinery check, not accuracy)."""
    T, d, H = 1.0, 0.32, 0.08
    scene = Scene(name="tank3d", world=World(dim=3, duration=0.45, sample_every=0.025, snapshot_every=0.0),
                  fluid=SPH(dx=0.04), domain=Flume(length=0.8, depth=d, height=0.44, width=0.12),
                  waves=Piston(height=H, period=T, ramp=0.25), probes=Probes(gauges=((0.14, 0.06), (0.7, 0.06))))
    from cosim.scene.build import build

    built = build(scene, tmp_path / "b")
    from fluid.particles import Kind

    ps = built.sph.ps
    paddle = ps.kind == Kind.MOVING_WALL
    assert paddle.any() and np.ptp(ps.pos[paddle, 1]) >= 0.12 - 0.04 - 1e-9  # across the width
    res = scene.run(tmp_path / "r")
    near, far = res["gauge1.eta"], res["gauge2.eta"]
    # the paddle pushes (x_p = S/2 sin wt): the water at it rises by a good part of H/2 within the first half period
    assert near.max() > 0.4 * 0.5 * H
    assert abs(far).max() < 0.5 * near.max()  # the far end has barely moved yet
