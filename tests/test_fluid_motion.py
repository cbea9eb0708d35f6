"""Base-excitation motions (fluid.motion): exact derivatives, records, baseline correction,
the AT2 reader, and refusals of bad input."""

import math

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.motion import (G_STANDARD, Harmonic, Polyline, Ramped, Rotation, Tabulated, Translation,
                          baseline_correct, read_at2)


def _central(f, t, h=1e-6):
    return (np.asarray(f(t + h)) - np.asarray(f(t - h))) / (2 * h)


SIGNALS = {
    "harmonic": Harmonic(0.01, 0.7, phase=0.3),
    "harmonic_from_rest": Harmonic.from_peak_acceleration(4.905, 0.03, from_rest=True),
    "ramped": Ramped(Harmonic(0.02, 1.1, phase=0.5), t_ramp=0.8, t_start=0.1, t_stop=3.0),
    "tab_disp": Tabulated(tuple(np.linspace(0, 2, 41)), tuple(np.sin(3 * np.linspace(0, 2, 41))), "displacement"),
    "tab_vel": Tabulated(tuple(np.linspace(0, 2, 41)), tuple(np.cos(3 * np.linspace(0, 2, 41))), "velocity"),
    "tab_acc": Tabulated(tuple(np.linspace(0, 2, 41)), tuple(np.sin(5 * np.linspace(0, 2, 41))), "acceleration"),
}


@pytest.mark.parametrize("name", sorted(SIGNALS))
def test_signal_derivatives_are_exact(name):
    """ds/dt and d2s/dt2 against central differences of s and ds/dt, at times off the
    samples and off the ramp joints (the derivatives are continuous there)."""
    sig = SIGNALS[name]
    for t in (0.237, 0.61, 1.333, 1.71, 2.9):
        s, ds, dds = sig.state(t)
        assert ds == pytest.approx(_central(lambda x: sig.state(x)[0], t), rel=1e-6, abs=1e-9)
        assert dds == pytest.approx(_central(lambda x: sig.state(x)[1], t), rel=1e-5, abs=1e-7)


def test_harmonic_from_peak_acceleration_starts_at_rest_with_the_sinusoidal_acceleration():
    a0, Tp = 0.5 * 9.81, 0.03
    sig = Harmonic.from_peak_acceleration(a0, Tp, from_rest=True)
    assert sig.state(0.0) == (0.0, 0.0, 0.0)
    for t in np.linspace(0, 0.1, 17):
        assert sig.state(t)[2] == pytest.approx(a0 * math.sin(2 * math.pi * t / Tp), abs=1e-12)
    assert sig.peak_acceleration == pytest.approx(a0)


def test_ramp_window_is_zero_outside_and_one_inside():
    base = Harmonic(1.0, 1.0, phase=0.7)
    r = Ramped(base, t_ramp=0.5, t_start=1.0, t_stop=4.0)
    assert r.state(0.9) == (0.0, 0.0, 0.0) and r.state(4.1) == (0.0, 0.0, 0.0)
    assert r.state(2.2) == pytest.approx(base.state(2.2))
    assert r.window(1.25)[0] == pytest.approx(0.5) and r.window(3.75)[0] == pytest.approx(0.5)


def test_tabulated_reproduces_its_samples_and_integrates_acceleration_exactly():
    t = np.linspace(0.0, 1.0, 11)
    disp = Tabulated(tuple(t), tuple(t**3), "displacement")
    assert disp.sample(t)[0] == pytest.approx(t**3, abs=1e-12)
    # a linear acceleration record is integrated exactly: a = 2 + 6 t -> v = 2t + 3t^2, d = t^2 + t^3
    acc = Tabulated(tuple(t), tuple(2 + 6 * t), "acceleration")
    tt = np.linspace(0.05, 0.95, 7)
    s, ds, dds = acc.sample(tt)
    np.testing.assert_allclose(dds, 2 + 6 * tt, atol=1e-12)
    np.testing.assert_allclose(ds, 2 * tt + 3 * tt**2, atol=1e-12)
    np.testing.assert_allclose(s, tt**2 + tt**3, atol=1e-12)
    # after the record it holds the final displacement at rest
    assert acc.state(2.0) == pytest.approx((2.0, 0.0, 0.0))


def _ground_motion(T=20.0, n=4001):
    """A displacement that starts and ends at rest, its acceleration, and times [s]."""
    t = np.linspace(0.0, T, n)
    w = 2 * math.pi * 1.3

    def d(x):
        return 0.05 * np.sin(math.pi * x / T) ** 4 * np.sin(w * x)

    h = 1e-4
    return t, d, (d(t + h) - 2 * d(t) + d(t - h)) / h**2


def test_a_polyline_moves_at_each_interval_s_constant_speed_and_holds_outside_its_points():
    """Straight between the points: the value interpolates them, the rate is the interval's
    slope (the later interval's at a point), no acceleration; held at rest before and after."""
    p = Polyline((1.0, 3.0, 4.0, 6.0), (0.0, 2.0, 2.0, -1.0))
    assert p.state(0.0) == (0.0, 0.0, 0.0) and p.state(7.0) == (-1.0, 0.0, 0.0)
    assert p.state(2.0) == pytest.approx((1.0, 1.0, 0.0), abs=1e-15)
    assert p.state(3.0) == pytest.approx((2.0, 0.0, 0.0), abs=1e-15)  # the hold starts
    assert p.state(5.0) == pytest.approx((0.5, -1.5, 0.0), abs=1e-15)
    ts = np.linspace(1.05, 5.95, 50)
    s = np.array([p.state(t)[0] for t in ts])
    assert np.allclose(_central(lambda t: np.array([p.state(x)[0] for x in np.atleast_1d(t)]), ts, 1e-7),
                       [p.state(t)[1] for t in ts], atol=1e-6)
    assert s.min() >= -1.0 and s.max() <= 2.0  # no overshoot between the points


def test_baseline_correction_ends_at_rest_and_barely_changes_the_acceleration():
    t, d, acc = _ground_motion()
    drift = 0.02 + 0.002 * t + 0.01 * np.sin(0.2 * t)  # baseline errors of an accelerogram
    raw = Tabulated(tuple(t), tuple(acc + drift), "acceleration")
    assert abs(raw.state(t[-1] - 1e-9)[1]) > 0.1 and abs(raw.state(t[-1])[0]) > 1.0  # drifted away
    cor = baseline_correct(raw, degree=6)
    s_end, v_end, _ = cor.state(t[-1] - 1e-9)
    assert abs(v_end) < 1e-7 and abs(cor.state(t[-1])[0]) < 1e-9
    s, _, a = cor.sample(t)
    # the correction removes the drift: within 1 % of the peak acceleration of the true record
    assert np.abs(a - acc).max() < 0.01 * np.abs(acc).max()
    assert np.abs(s - d(t)).max() < 0.02 * np.abs(d(t)).max()
    # and leaves a record that ends at rest untouched
    clean = baseline_correct(Tabulated(tuple(t), tuple(acc), "acceleration"))
    assert np.abs(clean.sample(t)[2] - acc).max() < 1e-3 * np.abs(acc).max()


def test_read_at2_synthetic_file(tmp_path):
    t, d, acc = _ground_motion(T=10.0, n=2001)
    dt = t[1] - t[0]
    g = acc / G_STANDARD
    body = "\n".join("  ".join(f"{v: .7E}" for v in g[k:k + 5]) for k in range(0, g.size, 5))
    path = tmp_path / "SYNTH.AT2"
    path.write_text("PEER NGA STRONG MOTION DATABASE RECORD\n"
                    "Synthetic 2026, test station, 90\n"
                    "ACCELERATION TIME SERIES IN UNITS OF G\n"
                    f"NPTS=  {g.size}, DT=   {dt:.4f} SEC\n" + body + "\n")
    raw = read_at2(path, baseline_degree=None)
    assert len(raw.times) == g.size and raw.times[1] == pytest.approx(dt)
    np.testing.assert_allclose(np.asarray(raw.values), acc, rtol=1e-6, atol=1e-9)
    cor = read_at2(path)
    assert cor.state(t[-1])[:2] == pytest.approx((0.0, 0.0), abs=1e-8)
    np.testing.assert_allclose(cor.sample(t)[0], d(t), atol=0.01 * np.abs(d(t)).max())
    # the old header form "NPTS DT" works too
    path.write_text("PEER NGA STRONG MOTION DATABASE RECORD\nSYNTHETIC 5/19/40, STATION, 180\n"
                    "ACCELERATION TIME HISTORY IN UNITS OF G\n" + f" {g.size}    {dt:.4f}    NPTS, DT\n" + body)
    assert len(read_at2(path, baseline_degree=None).times) == g.size


@pytest.mark.parametrize("stop", [6.0, 6.0012])
def test_a_stopped_record_is_the_record_then_comes_to_rest(stop):
    """``Stopped``: the baseline-corrected record exactly until ``stop - fade``, then its
    velocity faded out by the half cosine (acceleration ``w a + w' v``), the displacement
    the integral of that velocity (its difference quotient), continuous at both ends, and
    at rest from ``stop`` on: an earthquake that ends at ``stop``."""
    from fluid.motion import Stopped

    t, _, acc = _ground_motion(T=10.0, n=2001)
    rec = baseline_correct(Tabulated(tuple(t), tuple(acc), "acceleration"))
    sig = Stopped(rec, stop, fade=0.5)
    t1 = stop - 0.5
    for x in np.linspace(0.0, t1, 37):
        assert sig.state(x) == rec.state(x)
    for x in np.linspace(t1 + 1e-3, stop - 1e-3, 23):
        w = 0.5 * (1 + np.cos(np.pi * (x - t1) / 0.5))
        dw = -0.5 * np.pi / 0.5 * np.sin(np.pi * (x - t1) / 0.5)
        _, v, a = rec.state(x)
        d, vs, as_ = sig.state(x)
        assert (vs, as_) == pytest.approx((w * v, w * a + dw * v), rel=1e-12, abs=1e-15)
        h = 1e-5
        assert (sig.state(x + h)[0] - sig.state(x - h)[0]) / (2 * h) == pytest.approx(vs, rel=1e-6, abs=1e-9)
    eps = 1e-9
    assert sig.state(t1 + eps) == pytest.approx(rec.state(t1), abs=1e-6)  # continuous where the fade starts
    d_stop = sig.state(stop)[0]
    assert sig.state(stop - eps) == pytest.approx((d_stop, 0.0, 0.0), abs=1e-6)  # and where it ends
    for x in (stop + 0.1, 9.0, 20.0):
        assert sig.state(x) == (d_stop, 0.0, 0.0)
    assert abs(rec.state(t1)[1]) > 0.01  # the record does move there: the fade has work to do
    with pytest.raises(InputError, match="fade"):
        Stopped(rec, stop, fade=-0.1)


def test_a_harmonic_stopped_without_a_fade_is_held_where_it_got_to():
    """``Stopped(fade=0)``: a0 sin(w t) from rest exactly until ``stop``, then held at rest
    at its value there. After N whole periods from rest the tank has travelled
    a0 T^2 N / (2 pi) (its mean velocity a0 / w, Sunara et al. 2021, §3.1's excitation) and
    is at rest with zero acceleration, so the cut is continuous in all three."""
    from fluid.motion import Stopped

    a0, T, N = 4.905, 1.0, 3
    h = Harmonic.from_peak_acceleration(a0, T, from_rest=True)
    sig = Stopped(h, N * T, fade=0.0)
    for x in np.linspace(0.0, N * T, 31):
        assert sig.state(x) == h.state(x)
    held = sig.state(N * T + 1e-9)
    assert held == (h.state(N * T)[0], 0.0, 0.0)
    assert held[0] == pytest.approx(a0 * T**2 * N / (2 * math.pi), rel=1e-12)
    assert sig.state(N * T - 1e-9) == pytest.approx(held, abs=1e-7)
    assert sig.state(50.0) == held


def test_read_at2_refuses_bad_files(tmp_path):
    p = tmp_path / "bad.AT2"
    with pytest.raises(InputError, match="no file"):
        read_at2(p)
    head = "PEER\nSYNTHETIC\nACCELERATION TIME SERIES IN UNITS OF G\n"
    p.write_text(head + "NPTS= 10, DT= 0.01 SEC\n0.1 0.2 0.3\n")
    with pytest.raises(InputError, match="declares NPTS=10 but holds 3"):
        read_at2(p)
    p.write_text(head + "nothing here\n0.1 0.2 0.3\n")
    with pytest.raises(InputError, match="NPTS and DT"):
        read_at2(p)


def test_translation_and_rotation_velocities_are_the_derivatives_of_positions():
    rng = np.random.default_rng(3)
    sig = Ramped(Harmonic(0.3, 0.9, phase=0.2), 0.4)
    moves = [Translation((1.0, 0.0), sig), Translation((1.0, 2.0, -1.0), sig),
             Rotation((0.1, 0.2), sig), Rotation((0.1, 0.2, -0.3), sig, axis=(1.0, 1.0, 0.5))]
    for mv in moves:
        dim = len(mv.point) if isinstance(mv, Rotation) else len(mv.direction)
        ref = rng.normal(size=(7, dim))
        for t in (0.13, 0.55, 1.7):
            pos, vel = mv(t, ref)
            fd = _central(lambda x: mv(x, ref)[0], t)
            np.testing.assert_allclose(vel, fd, rtol=1e-6, atol=1e-8)
            if isinstance(mv, Rotation):  # rigid: distances to the point kept
                c = np.asarray(mv.point)
                np.testing.assert_allclose(np.linalg.norm(pos - c, axis=1), np.linalg.norm(ref - c, axis=1))


def test_2d_rotation_sign_convention():
    """A positive angle about +y turns +x towards -z (right-handed)."""
    pos, vel = Rotation((0.0, 0.0), Tabulated((0.0, 1.0), (math.pi / 2, math.pi / 2)))(0.5, np.array([[1.0, 0.0]]))
    np.testing.assert_allclose(pos, [[0.0, -1.0]], atol=1e-12)


@pytest.mark.parametrize("make, msg", [
    (lambda: Harmonic(0.01, 0.0), "period"),
    (lambda: Harmonic(float("nan"), 1.0), "amplitude"),
    (lambda: Tabulated((0.0, 0.0, 1.0), (1.0, 2.0, 3.0)), "increase strictly"),
    (lambda: Tabulated((0.0, 1.0), (1.0,)), "one length"),
    (lambda: Tabulated((0.0, 1.0), (1.0, 2.0), "jerk"), "quantity"),
    (lambda: Ramped(Harmonic(1.0, 1.0), 1.0, 0.0, t_stop=1.5), "no room"),
    (lambda: Polyline((0.0, 1.0, 1.0), (0.0, 1.0, 2.0)), "increase strictly"),
    (lambda: Polyline((0.0,), (0.0,)), "at least 2"),
    (lambda: Polyline((0.0, 1.0), (0.0, float("inf"))), "non-finite"),
    (lambda: Ramped(Harmonic(1.0, 1.0), -1.0), "t_ramp"),
    (lambda: Translation((0.0, 0.0), Harmonic(1.0, 1.0)), "not all zero"),
    (lambda: Translation((1.0, 0.0), lambda t: (0, 0)), "Signal"),
    (lambda: Rotation((0.0, 0.0, 0.0), Harmonic(1.0, 1.0)), "axis"),
    (lambda: Rotation((0.0, 0.0), Harmonic(1.0, 1.0), axis=(1.0, 0.0, 0.0)), "about \\+y"),
    (lambda: baseline_correct(Tabulated((0.0, 1.0), (1.0, 2.0)), degree=2), "degree"),
])
def test_bad_input_is_refused(make, msg):
    with pytest.raises(InputError, match=msg):
        make()


def test_motion_refuses_reference_of_the_wrong_dimension():
    with pytest.raises(InputError, match="\\(N, 2\\)"):
        Translation((1.0, 0.0), Harmonic(1.0, 1.0))(0.0, np.zeros((4, 3)))
