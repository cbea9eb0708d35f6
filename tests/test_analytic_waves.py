"""Linear (Airy) waves on the analytic fluid: the dispersion relation in its limits, the
wave's kinematics against their definitions, the Morison force on a fixed small body
against its closed form, and a small floating box that rides a long wave (heave RAO ≈ 1)."""

import math

import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.errors import InputError
from fluid.analytic import AnalyticFluid, LinearWave

RHO, G = 1025.0, 9.81


# ------------------------------------------------------------------------ the wave alone
@pytest.mark.parametrize("T, d", [(100.0, 1.0), (1000.0, 0.5), (20.0, 0.02)])
def test_dispersion_shallow_limit(T, d):
    """kd << 1: ω = k sqrt(g d) (the wave speed of shallow water), to O((kd)^2 / 6)."""
    k = LinearWave(1e-3, T, d, g=G).k
    w = 2 * math.pi / T
    assert k * d < 0.03
    assert k == pytest.approx(w / math.sqrt(G * d), rel=(k * d) ** 2 / 5)


@pytest.mark.parametrize("T, d", [(1.0, 50.0), (5.0, 1000.0), (0.5, 10.0)])
def test_dispersion_deep_limit(T, d):
    """kd >> 1: k = ω^2 / g, λ = g T^2 / 2π."""
    wave = LinearWave(0.01, T, d, g=G)
    assert wave.k * d > 6
    assert wave.k == pytest.approx((2 * math.pi / T) ** 2 / G, rel=1e-9)
    assert wave.wavelength == pytest.approx(G * T**2 / (2 * math.pi), rel=1e-9)


@pytest.mark.parametrize("T, d", [(20.0, 20.0), (2.0, 1.0), (7.0, 30.0)])
def test_dispersion_relation_holds_in_between(T, d):
    k = LinearWave(0.1, T, d, g=G).k
    assert (2 * math.pi / T) ** 2 == pytest.approx(G * k * math.tanh(k * d), rel=1e-13)


def test_kinematics_satisfy_the_linear_boundary_conditions_and_continuity():
    """w(z=0) = ∂η/∂t (kinematic surface condition, once ramped in), w(z=-d) = 0,
    ∂u/∂x + ∂w/∂z = 0, and the returned acceleration is the time derivative of the
    velocity, during the ramp too."""
    wave = LinearWave(0.4, 6.0, 8.0, direction=30.0, ramp=9.0, g=G)
    e = wave.heading
    rng = np.random.default_rng(1)
    p = np.column_stack([rng.uniform(-20, 20, 50), rng.uniform(-20, 20, 50), rng.uniform(-7.9, -0.1, 50)])
    eps = 1e-5
    for t in (4.0, 12.0):  # in the ramp, after it
        u, a = wave.kinematics(p, t)
        du = (wave.kinematics(p, t + eps)[0] - wave.kinematics(p, t - eps)[0]) / (2 * eps)
        assert np.allclose(a, du, atol=1e-7)
        # divergence: the horizontal velocity along the heading, differentiated along it
        dh = (wave.kinematics(p + eps * e, t)[0] - wave.kinematics(p - eps * e, t)[0]) / (2 * eps)
        dz = (wave.kinematics(p + [0, 0, eps], t)[0] - wave.kinematics(p - [0, 0, eps], t)[0]) / (2 * eps)
        assert np.allclose(dh[:, :2] @ e[:2] + dz[:, 2], 0.0, atol=1e-8)
        top = p.copy()
        top[:, 2] = 0.0
        deta = (wave.elevation(top, t + eps) - wave.elevation(top, t - eps)) / (2 * eps)
        if t > wave.ramp:  # (a ramped wave is not a solution while it ramps)
            assert np.allclose(wave.kinematics(top, t)[0][:, 2], deta, atol=1e-8)
        bottom = p.copy()
        bottom[:, 2] = -8.0
        assert np.allclose(wave.kinematics(bottom, t)[0][:, 2], 0.0, atol=1e-12)
    # deep water, at the surface: the orbital speed is a ω, circular
    deep = LinearWave(0.2, 1.0, 100.0, g=G)
    u, _ = deep.kinematics(np.zeros((1, 3)), 0.3)
    assert np.linalg.norm(u[0]) == pytest.approx(0.1 * 2 * math.pi, rel=1e-12)
    assert wave.elevation(p, 0.0) == pytest.approx(0.0)  # the ramp starts from still water


@pytest.mark.parametrize("kw, field, says", [
    (dict(H=0.0), "H", "H = 0.0 m; give a finite number > 0"),
    (dict(H=-0.7), "H", "H = -0.7 m"),
    (dict(T=0.0), "T", "T = 0.0 s; give a finite number > 0 (the wave period)"),
    (dict(T=-20.0), "T", "T = -20.0 s"),
    (dict(depth=0.0), "depth", "depth = 0.0 m; give a finite number > 0 (the still-water depth"),
    (dict(depth=-20.0), "depth", "depth = -20.0 m"),
    (dict(depth=math.nan), "depth", "depth = nan m"),
    (dict(ramp=-1.0), "ramp", "ramp = -1.0 s; give a fade-in time >= 0 s"),
    (dict(T=1.0, H=0.5), "H", "H/λ = 0.320 is beyond the breaking limit 1/7"),
    (dict(depth=0.5), "H", "H/d = 1.400 is beyond the depth-limited breaking limit 0.78"),
])
def test_bad_wave_input_is_refused_naming_the_field(kw, field, says):
    args = dict(H=0.7, T=20.0, depth=20.0) | kw
    with pytest.raises(InputError, match="linear wave: ") as e:
        LinearWave(**args)
    assert says in str(e.value)
    assert field in str(e.value)


# ------------------------------------------------------------------------ a fixed small body
def test_morison_force_on_a_fixed_small_sphere():
    """A sphere of radius 0.2 m held 3 m under the still water of a 7 s wave in 12 m:
    F_x = C_m ρ V ∂u/∂t + ½ ρ C_d A |u| u, F_z = ρ g V + C_m ρ V ∂w/∂t (Morison et al.
    1950; Faltinsen 1990 eq. 7.1), with C_a = 0.5 (a sphere) given as the added mass
    C_a ρ V and C_d = 1.2 as the quadratic damping ½ ρ C_d A; kinematics at the centre."""
    r, z0, Ca, Cd = 0.2, -3.0, 0.5, 1.2
    V, A = 4 / 3 * math.pi * r**3, math.pi * r**2
    wave = LinearWave(1.0, 7.0, 12.0, g=G)
    b = MujocoBodies(builders.scene(builders.sphere("s", r, (0, 0, z0), density=1000.0), gravity=G))
    f = AnalyticFluid(rho=RHO, g=G, waves=wave, cells=16,
                      added_mass={"s": [Ca * RHO * V] * 3 + [0.0] * 3},
                      quadratic_damping={"s": [0.5 * RHO * Cd * A] * 3 + [0.0] * 3})
    f.attach_bodies(b)
    f.set_body_kinematics(b.kinematics())
    ts = np.linspace(0.0, 7.0, 57)
    got, want = [], []
    for t in ts:
        f.set_time(t)
        got.append(f.body_wrenches()[0][0])
        u, a = wave.kinematics(np.array([[0.0, 0.0, z0]]), t)
        q = 0.5 * RHO * Cd * A
        want.append([(1 + Ca) * RHO * V * a[0, 0] + q * abs(u[0, 0]) * u[0, 0], 0.0,
                     RHO * G * V + (1 + Ca) * RHO * V * a[0, 2] + q * abs(u[0, 2]) * u[0, 2]])
    got, want = np.array(got), np.array(want)
    amp_x = np.abs(want[:, 0]).max()
    assert np.abs(got[:, 0] - want[:, 0]).max() < 2e-3 * amp_x
    assert np.abs(got[:, 2] - want[:, 2]).max() < 2e-3 * np.abs(want[:, 2] - RHO * G * V).max()
    assert np.abs(got[:, 1]).max() < 1e-9 * amp_x
    # the inline amplitude: F = A_I sin θ + A_D |cos θ| cos θ peaks at A_I while A_D <= A_I / 2,
    # else at A_D + A_I^2 / (4 A_D) (Dean & Dalrymple 1991 §10.3); here KC = u T / D = 4.6 and both count
    u0, a0 = (abs(v[0, 0]) for v in wave.kinematics(np.array([[0.0, 0.0, z0]]), 0.0))
    A_I, A_D = (1 + Ca) * RHO * V * wave.omega * u0, 0.5 * RHO * Cd * A * u0**2
    assert A_D > A_I / 2
    assert np.abs(got[:, 0]).max() == pytest.approx(A_D + A_I**2 / (4 * A_D), rel=2e-3)


def test_still_water_loads_are_unchanged_by_a_vanishing_wave():
    b = MujocoBodies(builders.scene(builders.box("p", (2.0, 1.0), (0, 0, 0.1), density=500.0, planar=True),
                                    gravity=G))
    still = AnalyticFluid(rho=RHO, g=G, linear_damping={"p": [10.0] * 6})
    wavy = AnalyticFluid(rho=RHO, g=G, linear_damping={"p": [10.0] * 6}, waves=LinearWave(1e-12, 10.0, 10.0, g=G))
    for f in (still, wavy):
        f.attach_bodies(b)
        f.set_body_kinematics(b.kinematics())
    assert np.allclose(still.body_wrenches()[0], wavy.body_wrenches()[0], rtol=1e-9, atol=1e-6)


# ------------------------------------------------------------------------ a small body riding a long wave
def ride(dim, direction=0.0, H=0.7, T=20.0, d=20.0, periods=2):
    """A 1 m box (0.5 m tall, half as dense as the water) free in a long wave, ramped in
    over half a period; returns (t, com, wave, com0, fluid)."""
    wave = LinearWave(H, T, d, direction=direction, ramp=0.5 * T, g=G)
    size = (1.0, 0.5) if dim == 2 else (1.0, 1.0, 0.5)
    draft = 0.25
    xml = builders.box("b", size, (0, 0, 0.25 - draft), density=RHO / 2, planar=dim == 2)
    b = MujocoBodies(builders.scene(xml, gravity=G, timestep=5e-3))
    lin = [0.0, 0.0, 200.0, 0.0, 0.0, 0.0]  # heave, on the velocity relative to the water: damps the start
    f = AnalyticFluid(rho=RHO, g=G, waves=wave, cells=8, linear_damping={"b": lin},
                      added_mass={"b": [100.0, 150.0, 20.0] if dim == 2 else [100.0, 100.0, 150.0, 5.0, 5.0, 5.0]})
    c = Coupler(bodies=b, fluid=f)
    com0 = b.kinematics().com[0].copy()
    ts, zs = [], []
    c.run(periods * T, callback=lambda info: (ts.append(info.t), zs.append(b.kinematics().com[0].copy())))
    return np.array(ts), np.array(zs), wave, com0, f


def harmonic(t, y, w):
    """Amplitude and phase (of cos(w t - phase)) of y, with a mean and a drift taken out."""
    M = np.column_stack([np.cos(w * t), np.sin(w * t), np.ones_like(t), t])
    c = np.linalg.lstsq(M, y, rcond=None)[0]
    return math.hypot(c[0], c[1]), math.atan2(c[1], c[0])


@pytest.mark.long
@pytest.mark.parametrize("dim, direction", [(2, 0.0), (3, 30.0)])
def test_small_floating_box_rides_a_long_wave(dim, direction):
    """T = 20 s in 20 m (the Barreiro et al. 2016 wave, λ = 271 m) on a 1 m box: heave RAO = 1 and in
    phase with η at the box (quasi-static: its heave period is 1 s); the box moves with the
    water particles, surge amplitude a / tanh(kd) at the surface, along the heading."""
    t, com, wave, com0, f = ride(dim, direction)
    assert f.dt_limit == "hydrostatic stiffness"
    last = t > 20.0  # the second period, after the ramp
    a, w = 0.5 * wave.H, wave.omega
    heave, ph = harmonic(t[last], com[last, 2] - com0[2], w)
    assert heave / a == pytest.approx(1.0, abs=0.01)  # measured 0.9998
    mean = com0.copy()  # the ramp leaves the box drifted by ~0.55 m: η where it rides
    mean[:2] = com[last, :2].mean(axis=0)
    eta = np.array([wave.elevation(mean[None, :], s)[0] for s in t[last]])
    assert harmonic(t[last], eta, w)[0] == pytest.approx(a, rel=1e-9)
    assert abs(math.remainder(ph - harmonic(t[last], eta, w)[1], 2 * math.pi)) < 2e-3  # measured 1.4e-4, 1.9e-4 rad
    horiz = (com[last, :2] - com0[:2]) @ wave.heading[:2]
    surge, _ = harmonic(t[last], horiz, w)
    orbit = a / math.tanh(wave.k * wave.depth)
    assert surge / orbit == pytest.approx(1.0, abs=0.01)  # measured 0.99996
    if dim == 3:  # the motion is along the heading
        across = (com[last, :2] - com0[:2]) @ np.array([-wave.heading[1], wave.heading[0]])
        assert harmonic(t[last], across, w)[0] < 1e-3 * surge
