"""The SPH cable solver (Dinçer & Demir 2020, Eq. 1-12) against analytic results and invariants."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from cosim.errors import InputError
from moorings.sph_cable import SPHCable, catenary_points, material_coordinates


def _rot3(x2):
    """Embed x-z points in 3-D, rotated 30° about z (a 3-D run of a planar problem)."""
    c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)
    x2 = np.atleast_2d(x2)
    return np.stack([c * x2[:, 0], s * x2[:, 0], x2[:, 1]], axis=1)


@pytest.mark.parametrize("dim", [2, 3])
def test_straight_cable_uniform_tension_equals_EA_strain(dim):
    L, EA, strain = 10.0, 2.0e6, 1.5e-3
    direction = np.array([0.6, 0.8]) if dim == 2 else np.array([2.0, -1.0, 2.0]) / 3.0
    c = SPHCable(L, 21, EA, 1.3, np.zeros(dim), L * (1 + strain) * direction, weight_per_length=0.0, omega=0.0)
    c.advance(0.0, 0.01)
    T = EA * strain
    np.testing.assert_allclose(c.tension, T, rtol=1e-9)
    F = c.end_forces()
    # the cable pulls each support towards the other end
    np.testing.assert_allclose(F[0], T * direction, rtol=1e-9)
    np.testing.assert_allclose(F[1], -T * direction, rtol=1e-9)
    assert c.max_speed() < 1e-9 * c.c0


def test_compressed_cable_carries_no_force():
    """Tension only: supports 5 % closer than the length, straight and compressed."""
    L = 10.0
    pos = np.stack([np.linspace(0.0, 0.95 * L, 31), np.zeros(31)], axis=1)
    c = SPHCable(L, 31, 1e6, 1.0, (0, 0), (0.95 * L, 0), weight_per_length=0.0, positions=pos, omega=0.0)
    c.advance(0.0, 0.05)
    assert np.all(c.tension == 0.0)
    np.testing.assert_allclose(c.end_forces(), 0.0, atol=1e-9)
    np.testing.assert_allclose(c.positions, pos, atol=1e-14)


def _axial_mode_period(visc_alpha=0.0):
    L, EA, mu, n = 20.0, 4.0e6, 2.5, 41
    c = SPHCable(L, n, EA, mu, (0, 0), (L * 1.001, 0), weight_per_length=0.0, omega=0.0, visc_alpha=visc_alpha,
                 visc_beta=0.0)
    # first axial mode of a fixed-fixed bar: v = V sin(pi s/L), strain stays > 0 (V/c0 << 1e-3)
    c.v[:, 0] = 0.2 * np.sin(np.pi * c.s / L)
    mid = n // 2
    ts, vs = [], []
    dt = 2e-5
    while c.t < 3.0 * L / c.c0:
        c.advance(c.t, dt)
        ts.append(c.t)
        vs.append(c.v[mid, 0])
    vs = np.array(vs)
    k = int(np.nonzero(np.diff(np.sign(vs)) != 0)[0][0])  # first zero crossing: a quarter period
    t0 = ts[k] - vs[k] * (ts[k + 1] - ts[k]) / (vs[k + 1] - vs[k])
    return 4.0 * t0, 2.0 * L / c.c0


def test_axial_wave_speed_is_sqrt_E_over_rho():
    T_num, T_exact = _axial_mode_period()
    assert T_num == pytest.approx(T_exact, rel=0.01)


@pytest.mark.parametrize("dim", [2, 3])
def test_transverse_string_frequency(dim):
    """A taut weightless cable vibrates at f1 = sqrt(T/mu)/(2 L') (L' stretched span)."""
    L, EA, mu, strain, n = 10.0, 1.0e5, 0.5, 0.01, 41
    span = L * (1 + strain)
    end = np.array([span, 0.0]) if dim == 2 else np.array([span, 0.0, 0.0])
    c = SPHCable(L, n, EA, mu, np.zeros(dim), end, weight_per_length=0.0, omega=0.0, visc_alpha=0.0,
                 visc_beta=0.0)
    c.v[:, -1] = 0.05 * np.sin(np.pi * c.s / L)
    T = EA * strain
    period = 2 * span / math.sqrt(T / (mu / (1 + strain)))  # line density of the stretched cable
    mid = n // 2
    ts, vs = [], []
    while c.t < 0.8 * period:
        c.advance(c.t, period / 400)
        ts.append(c.t)
        vs.append(c.v[mid, -1])
    vs = np.array(vs)
    k = int(np.nonzero(np.diff(np.sign(vs)) != 0)[0][0])
    t0 = ts[k] - vs[k] * (ts[k + 1] - ts[k]) / (vs[k + 1] - vs[k])
    assert 4.0 * t0 == pytest.approx(period, rel=0.01)


def test_mass_proportional_damping_decays_every_mode_at_omega_over_2():
    """Dinçer & Demir 2020, Eq. 12 as implemented (f = -omega m v): a string mode decays as exp(-omega t/2)."""
    L, EA, mu, strain, n, omega = 10.0, 1.0e5, 0.5, 0.01, 41, 0.6
    span = L * (1 + strain)
    c = SPHCable(L, n, EA, mu, (0, 0), (span, 0), weight_per_length=0.0, omega=omega, visc_alpha=0.0,
                 visc_beta=0.0)
    c.v[:, -1] = 0.05 * np.sin(np.pi * c.s / L)
    period = 2 * span / math.sqrt(EA * strain / (mu / (1 + strain)))
    amps = []
    for _ in range(4):  # amplitude of the midpoint over successive periods
        peak = 0.0
        t_end = c.t + period
        while c.t < t_end - 1e-12:
            c.advance(c.t, period / 200)
            peak = max(peak, abs(c.x[n // 2, 1]))
        amps.append(peak)
    ratio = amps[3] / amps[0]
    assert ratio == pytest.approx(math.exp(-0.5 * omega * 3 * period), rel=0.01)


def test_free_cable_conserves_momentum():
    rng = np.random.default_rng(1)
    n = 25
    x = catenary_points((0, 0, 0), (3.0, 1.0, -0.5), 4.0, material_coordinates(4.0, n))
    x *= 1.002  # stretched: tension acts
    c = SPHCable(4.0, n, 5e4, 0.3, x[0], x[-1], weight_per_length=0.0, free_end="both", positions=x, omega=0.0)
    c.v[:] = rng.normal(0.0, 0.5, c.v.shape)
    P0 = (c.m[:, None] * c.v).sum(0)
    L0 = np.cross(c.x, c.m[:, None] * c.v).sum(0)
    for _ in range(20):
        c.advance(c.t, 1e-3)
    P1 = (c.m[:, None] * c.v).sum(0)
    L1 = np.cross(c.x, c.m[:, None] * c.v).sum(0)
    scale = (c.m * np.linalg.norm(c.v, axis=1)).sum()
    assert c.steps > 100
    np.testing.assert_allclose(P1, P0, atol=1e-12 * scale)
    np.testing.assert_allclose(L1, L0, atol=1e-10 * scale * 4.0)


def _v_shape(P, L, span, EA):
    """Weightless cable, point load P at its middle: each half at angle th with
    2 T sin(th) = P and (L/2)(1 + T/EA) cos(th) = span/2."""
    th = brentq(lambda th: 0.5 * L * (1 + P / (2 * math.sin(th)) / EA) * math.cos(th) - 0.5 * span, 1e-6, 1.5)
    T = P / (2 * math.sin(th))
    return T, 0.5 * L * (1 + T / EA) * math.sin(th)


def test_point_load_and_point_mass_match_the_two_segment_solution():
    L, span, EA, P = 10.0, 9.9, 2.0e5, 400.0
    T, sag = _v_shape(P, L, span, EA)
    c = SPHCable(L, 21, EA, 1.0, (0, 0), (span, 0), weight_per_length=0.0, omega=8.0)
    h = c.add_point_load(5.0, (0.0, -P))
    while c.t < 8.0:
        c.advance(c.t, 0.5)
    assert c.position_at(5.0)[1] == pytest.approx(-sag, rel=2e-4)
    np.testing.assert_allclose(c.end_forces().sum(0), [0.0, -P], atol=1e-4 * P)
    assert abs(c.end_forces()[0, 0]) == pytest.approx(T * math.cos(math.asin(sag / (0.5 * L * (1 + T / EA)))),
                                                      rel=2e-4)
    # the same weight from a point mass; once removed, the slack weightless cable carries nothing
    c.remove(h)
    hm = c.add_point_mass(5.0, P / c.gravity)
    while c.t < 16.0:
        c.advance(c.t, 0.5)
    assert c.position_at(5.0)[1] == pytest.approx(-sag, rel=2e-4)
    c.remove(hm)
    while c.t < 24.0:
        c.advance(c.t, 0.5)
    assert np.abs(c.end_forces()).max() < 1e-6 * P


def test_harmonic_end_follows_its_motion():
    c = SPHCable(1.0, 11, 1e4, 0.1, (0, 0), (0.0, -1.0), free_end="b", positions=np.stack(
        [np.zeros(11), -np.linspace(0, 1, 11)], axis=1), omega=0.0)
    c.set_harmonic("a", (0.02, 0.0), 1.5, t_on=0.1, cycles=2)
    for _ in range(120):
        c.advance(c.t, 0.01)
        xa = 0.02 * math.sin(2 * math.pi * 1.5 * (c.t - 0.1)) if 0.1 <= c.t <= 0.1 + 2 / 1.5 else 0.0
        assert c.x[0, 0] == pytest.approx(xa, abs=1e-12)
    assert np.abs(c.x[-1, 0]) > 1e-4  # the motion reached the free end


def test_subcycled_and_single_calls_agree():
    def run(n_calls):
        c = SPHCable(1.272, 25, 50.0, 0.027, (0, 0), (1.2, -0.22), weight_per_length=0.2656, omega=0.0)
        c.set_harmonic("a", (0.025, 0.0), 1.0)
        for k in range(n_calls):
            c.advance(0.2 * k / n_calls, 0.2 / n_calls)
        return c.positions

    a, b = run(1), run(8)
    assert np.abs(a - b).max() < 1e-3 * 0.025  # sub-steps differ (408 vs 416): first-order in dt


def test_bad_input_is_rejected_before_any_work():
    ok = dict(length=1.0, n_particles=11, EA=1e4, mass_per_length=0.1, end_a=(0, 0), end_b=(0.9, 0))
    for key, bad, word in [("n_particles", 0, "n_particles"), ("n_particles", 2, "at least 3"),
                           ("EA", 0.0, "EA"), ("EA", -1.0, "EA"), ("mass_per_length", 0.0, "mass_per_length"),
                           ("end_b", (1.2, 0), "supports"), ("cfl", 2.0, "cfl")]:
        with pytest.raises(InputError, match=word):
            SPHCable(**{**ok, key: bad})
    with pytest.raises(InputError, match="nodes_at"):
        SPHCable(**ok, nodes_at=(2.0,))
    # within the elastic range (max_strain) a stretched start is accepted
    SPHCable(**{**ok, "end_b": (1.05, 0)})


def test_3d_hanging_cable_equals_the_2d_one():
    kw = dict(weight_per_length=0.2656, omega=30.0)
    c2 = SPHCable(1.272, 21, 2.0e4, 0.027, (0, 0), (1.2, -0.22), **kw)
    c3 = SPHCable(1.272, 21, 2.0e4, 0.027, _rot3((0, 0))[0], _rot3((1.2, -0.22))[0], **kw)
    for _ in range(4):
        c2.advance(c2.t, 0.1)
        c3.advance(c3.t, 0.1)
    np.testing.assert_allclose(c3.positions, _rot3(c2.positions), atol=1e-9)


def test_end_motion_from_a_file_follows_the_table(tmp_path):
    from moorings.sph_cable import load_end_motion

    f, amp = 1.5, 0.02
    tt = np.linspace(0.0, 1.0, 401)
    path = tmp_path / "motion.csv"
    path.write_text("# t, x, z\n" + "\n".join(f"{t},{amp * math.sin(2 * math.pi * f * t)},0.0" for t in tt))
    times, pos = load_end_motion(path)
    c = SPHCable(1.0, 11, 1e4, 0.1, (0, 0), (0.0, -1.0), free_end="b",
                 positions=np.stack([np.zeros(11), -np.linspace(0, 1, 11)], axis=1), omega=0.0)
    c.set_end_table("a", times, pos)
    ref = SPHCable(1.0, 11, 1e4, 0.1, (0, 0), (0.0, -1.0), free_end="b",
                   positions=np.stack([np.zeros(11), -np.linspace(0, 1, 11)], axis=1), omega=0.0)
    ref.set_harmonic("a", (amp, 0.0), f, t_on=0.0)
    for k in range(40):  # coupling steps of 0.02 s, table samples every 0.0025 s
        c.advance(0.02 * k, 0.02)
        ref.advance(0.02 * k, 0.02)
        assert c.x[0, 0] == pytest.approx(amp * math.sin(2 * math.pi * f * c.t), abs=1e-9)
    assert np.abs(c.x - ref.x).max() < 0.01 * amp
    with pytest.raises(InputError, match="increasing"):
        c.set_end_table("a", [0.0, 0.0], [[0, 0], [0, 0]])


def _first_period(c, idx, comp, t_max, dt):
    ts, ys = [], []
    y0, t0 = c.x[idx, comp], c.t
    while c.t < t0 + t_max:
        c.advance(c.t, dt)
        ts.append(c.t)
        ys.append(c.x[idx, comp] - y0)
    ys = np.array(ys)
    k = np.nonzero((ys[:-1] > 0) & (ys[1:] <= 0))[0][0]  # displacement starts > 0: first down-crossing
    return 2.0 * (ts[k] - ys[k] * (ts[k + 1] - ts[k]) / (ys[k + 1] - ys[k]) - t0)


def test_suspended_cable_modes_match_irvine():
    """Flat-sag suspended cable (Irvine & Caughey 1974; refdata/cable_static_dynamic item 3):
    out-of-plane mode 1 at omega = pi c/l, in-plane antisymmetric mode 1 at 2 pi c/l,
    c = sqrt(H/m) with H the settled horizontal tension."""
    span, w = 100.0, 10.0
    mu = w / 9.80665
    L = 100.1067  # sag about 2 m (d/l = 0.02)
    res = {}
    modes = (("out", 1, lambda s: np.sin(np.pi * s / L)), ("anti", 2, lambda s: np.sin(2 * np.pi * s / L)))
    for name, comp, shape in modes:
        c = SPHCable(L, 41, 1e7, mu, (0, 0, 0), (span, 0, 0), weight_per_length=w, omega=3.0)
        while c.t < 20.0:
            c.advance(c.t, 1.0)
        H = -c.end_forces()[1, 0]
        c.omega = 0.0
        c.v[:, comp] = 0.01 * shape(c.s)
        idx = 10  # a quarter span: moves in both modes
        T_exact = (2.0 if name == "out" else 1.0) * span / math.sqrt(H / mu)
        res[name] = (_first_period(c, idx, comp, 0.8 * T_exact, T_exact / 200), T_exact)
    for name, (T_num, T_exact) in res.items():
        assert T_num == pytest.approx(T_exact, rel=0.02), name


def test_point_mass_removed_at_a_given_time_inside_one_advance():
    """Dinçer & Demir 2020, Case 2 style: a mass at midspan is released at t = 0.3 s; one advance call
    over [0, 0.6] equals stopping at 0.3 s and removing it by hand."""
    def make():
        return SPHCable(10.0, 21, 2e5, 1.0, (0, 0), (9.9, 0), omega=0.0)

    a = make()
    a.add_point_mass(5.0, 20.0, t_off=0.3)
    a.advance(0.0, 0.6)
    b = make()
    h = b.add_point_mass(5.0, 20.0)
    b.advance(0.0, 0.3)
    b.remove(h)
    b.advance(0.3, 0.3)
    np.testing.assert_allclose(a.positions, b.positions, rtol=0, atol=1e-12)
    assert a.m.sum() == pytest.approx(10.0)  # the mass is gone afterwards
