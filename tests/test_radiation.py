"""The radiation case's pieces (cosim.validations.radiation) and a body's prescribed motion
(``bodies[].motion``): the wave separation against synthetic incident and reflected waves
of known amplitudes, the added mass and damping against a synthetic force of known
coefficients, a forced body following its motion exactly, and the quick case against its
own tolerances."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import j0, y0

from cosim.errors import InputError
from cosim.validations.radiation import added_mass_damping, draft_of, separate

K = 2.0 * math.pi / 7.3  # a wave 7.3 m long
A_OUT, B_IN = 0.021 * np.exp(0.4j), 0.0042 * np.exp(-1.9j)  # reflection 0.2


def plane(x):
    """Incident A exp(i(w t - k x)) and reflected B exp(i(w t + k x)), as complex elevations."""
    return A_OUT * np.exp(-1j * K * x) + B_IN * np.exp(1j * K * x)


def test_two_gauges_recover_a_plane_incident_and_reflected_wave_exactly():
    """Goda & Suzuki 1976: two gauges determine both waves exactly."""
    x = np.array([2.0, 3.1])
    a, b = separate(x, plane(x), K)
    assert abs(a - A_OUT) < 1e-12 and abs(b - B_IN) < 1e-12
    assert abs(b) / abs(a) == pytest.approx(0.2, rel=1e-10)


def test_three_noisy_gauges_recover_the_reflection_by_least_squares():
    """Mansard & Funke 1980: with noise of 1 % of the incident amplitude at each gauge the
    reflection coefficient comes out within 0.02 of 0.2."""
    x = np.array([2.0, 3.1, 4.5])
    noise = 0.01 * abs(A_OUT) * np.exp(1j * np.array([0.3, 2.9, 4.4]))
    a, b = separate(x, plane(x) + noise, K)
    assert abs(abs(b) / abs(a) - 0.2) < 0.02


def test_cylindrical_waves_separate_with_hankel_functions():
    """Outgoing A H0^(2)(k r) and incoming B H0^(1)(k r) (built here from J0 and Y0) come
    apart exactly; a plane-wave separation of the same gauges would misread the 1/sqrt(r)
    decay as reflection."""
    r = np.array([4.5, 6.0, 7.5, 9.0])
    z = A_OUT * (j0(K * r) - 1j * y0(K * r)) + B_IN * (j0(K * r) + 1j * y0(K * r))
    a, b = separate(r, z, K, "cylindrical")
    assert abs(a - A_OUT) < 1e-12 and abs(b - B_IN) < 1e-12
    outgoing = A_OUT * (j0(K * r) - 1j * y0(K * r))
    a, b = separate(r, outgoing, K, "plane")
    assert abs(b) / abs(a) > 0.02


def test_gauges_half_a_wavelength_apart_are_refused():
    x = np.array([1.0, 1.0 + math.pi / K])
    with pytest.raises(InputError, match="do not tell the two waves apart"):
        separate(x, plane(x), K)
    with pytest.raises(InputError, match="at least two"):
        separate([1.0], [0.01], K)
    with pytest.raises(InputError, match="r > 0"):
        separate([0.0, 1.0], [0.01, 0.01], K, "cylindrical")


def test_added_mass_and_damping_from_a_synthetic_force():
    """F = F0 - C z - A z'' - B z' (+ a second harmonic) for z = a sin(w t) over whole
    periods gives A and B back to round-off."""
    a, w, C, A, B = 0.3, 1.7755, 2.77e5, 4.16e4, 2.39e4
    t = np.linspace(0.0, 2.0 * 2.0 * math.pi / w, 400, endpoint=False)
    z, v, acc = a * np.sin(w * t), a * w * np.cos(w * t), -a * w * w * np.sin(w * t)
    f = 4.5e5 - C * z - A * acc - B * v + 3e3 * np.cos(2 * w * t + 0.7)
    got_a, got_b = added_mass_damping(t, f, a, w, C)
    assert got_a == pytest.approx(A, rel=1e-9) and got_b == pytest.approx(B, rel=1e-9)


class _Records:
    """A run's records as ``radiation_metrics`` reads them (``t``, series by name, summary)."""

    def __init__(self, t, series):
        self.t, self._s = t, series
        self.summary = {"particles": 1, "steps": t.size, "cpu_s": 1.0}

    def __getitem__(self, name):
        return self._s[name]


def _outgoing(radius, draft, depth, omega, rho, g, points, panel=None):
    """An outgoing cylindrical wave at ``points`` in place of Capytaine's (tests not about it)."""
    from scipy.special import hankel2

    return hankel2(0, np.hypot(*np.asarray(points, float).T))


def test_the_tare_takes_the_held_bodys_force_and_waves_out_of_the_fit(monkeypatch):
    """A forced run whose force is F0 - C z - A z'' - B z' and whose gauges read an outgoing
    cylindrical wave, both plus the box's own oscillation (a component at the heave's
    frequency, another at 1.3 times it, the same in the held run): less the held run's
    records, A33, B33 and a zero reflection come back to round-off; the untared fit is off
    by the oscillation's share (reported beside)."""
    from scipy.special import hankel2

    from cosim.validations import radiation
    from fluid.waves import wavenumbers

    a_ref, b_ref, c33 = 4.16e4, 2.39e4, 2.77e5
    monkeypatch.setattr(radiation, "reference", lambda *args, **kw: (a_ref, b_ref, c33))
    scene = radiation.radiation_scene(True)
    b, m = scene.bodies[0], scene.bodies[0].motion
    w = 2.0 * math.pi / m.period
    k = float(wavenumbers(w, scene.domain.depth, scene.world.gravity))
    # the reference's wave per unit heave (z = a sin w t: -i a), the gauges' 1.1 times it, 0.2 rad ahead
    gain = 1.1 * np.exp(0.2j)
    monkeypatch.setattr(radiation, "reference_elevation", lambda *args, **kw: 0.05 * hankel2(
        0, k * np.hypot(*np.asarray(args[6], float).T)) / (-1j * m.amplitude) / gain)
    t = np.arange(1, int(round(scene.world.duration / scene.world.sample_every)) + 1) * scene.world.sample_every
    z, v, acc = m.amplitude * np.sin(w * t), m.amplitude * w * np.cos(w * t), -m.amplitude * w * w * np.sin(w * t)
    box = 2e3 * np.cos(w * t + 0.3) + 5e3 * np.sin(1.3 * w * t)
    forced = {f"{b.name}.fluid_Fz": 4.5e5 - c33 * z - a_ref * acc - b_ref * v + box, f"{b.name}.heave": z}
    held = {f"{b.name}.fluid_Fz": 4.5e5 + box, f"{b.name}.heave": 0.0 * t}
    for i, (gx, gy) in enumerate(scene.probes.gauges):
        r = math.hypot(gx - b.pos[0], gy - b.pos[1])
        swell = 0.01 * np.cos(w * t + i)
        forced[f"gauge{i + 1}.eta"] = np.real(0.05 * hankel2(0, k * r) * np.exp(1j * w * t)) + swell
        held[f"gauge{i + 1}.eta"] = swell
    got = radiation.radiation_metrics(_Records(t, forced), scene, _Records(t, held))
    assert got["tared"] and got["A33_error"] < 1e-9 and got["B33_error"] < 1e-9 and got["reflection"] < 1e-9
    assert got["B33_error_untared"] > 0.1 and got["A33_error_untared"] > 1e-3
    for line in got["lines"].values():  # each gauge against the reference's elevation there
        assert line["H1_over_reference"] == pytest.approx([1.1] * 4, abs=1e-4)
        assert line["lag_periods"] == pytest.approx([-0.2 / (2.0 * math.pi)] * 4, abs=1e-4)
        assert line["reflection_floor"] < 1e-9
    with pytest.raises(ValueError, match="sample times"):
        radiation.radiation_metrics(_Records(t, forced), scene, _Records(t[:-1], held))


def test_the_damping_is_also_fitted_period_by_period(monkeypatch):
    """A force whose damping changes from one fitted period to the next (B33 1.0, 1.2, 0.9,
    1.1, 0.8, 1.3 times the reference's, each over one whole period): each period's fit
    gives its own B33 back, and the spread reported is their standard error of the mean."""
    from cosim.validations import radiation

    a_ref, b_ref, c33 = 4.16e4, 2.39e4, 2.77e5
    monkeypatch.setattr(radiation, "reference", lambda *args, **kw: (a_ref, b_ref, c33))
    monkeypatch.setattr(radiation, "reference_elevation", _outgoing)
    scene = radiation.radiation_scene(True)
    b, m = scene.bodies[0], scene.bodies[0].motion
    w = 2.0 * math.pi / m.period
    t = np.arange(1, int(round(scene.world.duration / scene.world.sample_every)) + 1) * scene.world.sample_every
    factors = np.array([1.0, 1.2, 0.9, 1.1, 0.8, 1.3])
    window = np.clip(np.floor((t - (t[-1] - radiation.FIT_PERIODS * m.period)) / m.period + 1e-6), 0, 5)
    damping = b_ref * factors[window.astype(int)]
    z, v, acc = m.amplitude * np.sin(w * t), m.amplitude * w * np.cos(w * t), -m.amplitude * w * w * np.sin(w * t)
    forced = {f"{b.name}.fluid_Fz": 4.5e5 - c33 * z - a_ref * acc - damping * v, f"{b.name}.heave": z}
    for i in range(len(scene.probes.gauges)):
        forced[f"gauge{i + 1}.eta"] = 0.01 * np.cos(w * t + i)
    got = radiation.radiation_metrics(_Records(t, forced), scene)
    assert np.asarray(got["B33_per_period_kg_s"]) / b_ref == pytest.approx(factors, abs=1e-5)
    spread = np.std(factors, ddof=1) / math.sqrt(factors.size)
    assert got["B33_error_standard"] == pytest.approx(spread, rel=1e-4)


def test_the_excess_splits_into_a_part_independent_of_the_amplitude_and_a_drags():
    """An excess ``12 + 200 a`` at five amplitudes gives L = 12 and D = 200 back with no
    residual; with two amplitudes the line through them and no standard errors; with
    noise of a known spread the standard errors are least squares' (sigma^2 (X'X)^-1)
    estimated from the residuals, and the truth lies within a few of them."""
    from cosim.validations.radiation import excess_split

    a = np.array([0.025, 0.05, 0.1, 0.2, 0.4])
    f = excess_split(a, 12.0 + 200.0 * a)
    assert f["L"] == pytest.approx(12.0, rel=1e-12) and f["D"] == pytest.approx(200.0, rel=1e-12)
    assert f["L_se"] < 1e-9 and f["D_se"] < 1e-9
    two = excess_split([0.1, 0.3], [5.0, 9.0])
    assert (two["L"], two["D"]) == (pytest.approx(3.0), pytest.approx(20.0)) and two["L_se"] is None
    rng = np.random.default_rng(7)
    e = 12.0 + 200.0 * a + rng.normal(0.0, 1.0, a.size)
    f = excess_split(a, e)
    x = np.column_stack([np.ones_like(a), a])
    resid = e - x @ np.array([f["L"], f["D"]])
    cov = resid @ resid / (a.size - 2) * np.linalg.inv(x.T @ x)
    assert (f["L_se"], f["D_se"]) == (pytest.approx(math.sqrt(cov[0, 0])), pytest.approx(math.sqrt(cov[1, 1])))
    assert abs(f["L"] - 12.0) < 4.0 * f["L_se"] and abs(f["D"] - 200.0) < 4.0 * f["D_se"]


@pytest.mark.parametrize("a, e", [([0.1], [3.0]), ([0.1, 0.1], [3.0, 4.0]), ([0.1, 0.2], [3.0])])
def test_an_excess_split_needs_two_amplitudes_one_value_each(a, e):
    from cosim.validations.radiation import excess_split

    with pytest.raises(ValueError, match="two different amplitudes"):
        excess_split(a, e)


def test_the_reflection_floor_is_the_split_of_the_references_own_wave(monkeypatch):
    """Where the reference's wave at the gauges is not a pure outgoing one (near the body its
    evanescent modes are not in the split's basis), the split reads a reflection from it:
    the floor reported is that, whatever the gauges read (here 3 % built in)."""
    from scipy.special import hankel1, hankel2

    from cosim.validations import radiation
    from fluid.waves import wavenumbers

    monkeypatch.setattr(radiation, "reference", lambda *args, **kw: (4.16e4, 2.39e4, 2.77e5))
    scene = radiation.radiation_scene(True)
    b, m = scene.bodies[0], scene.bodies[0].motion
    w = 2.0 * math.pi / m.period
    k = float(wavenumbers(w, scene.domain.depth, scene.world.gravity))

    def reference_wave(*args, **kw):
        r = k * np.hypot(*np.asarray(args[6], float).T)
        return hankel2(0, r) + 0.03 * np.exp(1.0j) * hankel1(0, r)

    monkeypatch.setattr(radiation, "reference_elevation", reference_wave)
    t = np.arange(1, int(round(scene.world.duration / scene.world.sample_every)) + 1) * scene.world.sample_every
    z = m.amplitude * np.sin(w * t)
    forced = {f"{b.name}.fluid_Fz": 4.5e5 - 2.77e5 * z, f"{b.name}.heave": z}
    for i, (gx, gy) in enumerate(scene.probes.gauges):
        forced[f"gauge{i + 1}.eta"] = np.real(0.05 * hankel2(0, k * math.hypot(gx, gy)) * np.exp(1j * w * t))
    got = radiation.radiation_metrics(_Records(t, forced), scene)
    for line in got["lines"].values():
        assert line["reflection"] < 1e-9 and line["reflection_floor"] == pytest.approx(0.03, rel=1e-6)


def test_the_errors_against_the_first_panels_reference_are_kept_beside(monkeypatch):
    """The case is judged against Capytaine's reference at ``PANEL``; the figures against
    the reference it was first judged by (``FIRST_PANEL``, another A33, B33 and C33) come
    beside: a force made exactly of the first reference's coefficients reads zero error
    there and the two references' difference in the judged fields."""
    from cosim.validations import radiation

    refs = {radiation.PANEL: (4.15e4, 2.41e4, 2.773e5), radiation.FIRST_PANEL: (4.16e4, 2.39e4, 2.769e5)}
    monkeypatch.setattr(radiation, "reference", lambda *args, panel=radiation.PANEL, **kw: refs[panel])
    monkeypatch.setattr(radiation, "reference_elevation", _outgoing)
    scene = radiation.radiation_scene(True)
    b, m = scene.bodies[0], scene.bodies[0].motion
    w = 2.0 * math.pi / m.period
    t = np.arange(1, int(round(scene.world.duration / scene.world.sample_every)) + 1) * scene.world.sample_every
    a1, b1, c1 = refs[radiation.FIRST_PANEL]
    z, v, acc = m.amplitude * np.sin(w * t), m.amplitude * w * np.cos(w * t), -m.amplitude * w * w * np.sin(w * t)
    forced = {f"{b.name}.fluid_Fz": 4.5e5 - c1 * z - a1 * acc - b1 * v, f"{b.name}.heave": z}
    for i in range(len(scene.probes.gauges)):
        forced[f"gauge{i + 1}.eta"] = 0.01 * np.cos(w * t + i)
    got = radiation.radiation_metrics(_Records(t, forced), scene)
    assert got["A33_error_panel_0.1R"] < 1e-9 and got["B33_error_panel_0.1R"] < 1e-9
    a0, b0, c0 = refs[radiation.PANEL]
    assert got["B33_error"] == pytest.approx(abs(b1 / b0 - 1.0), rel=1e-6)
    assert got["A33_error"] == pytest.approx(abs((a1 + (c0 - c1) / w**2) / a0 - 1.0), rel=1e-6)
    assert got["reference_panel_R"] == radiation.PANEL


def test_the_held_scene_is_the_forced_one_with_its_body_still():
    """The tare's scene differs from the case's only in the body's motion, which holds it at
    its position over the whole run."""
    from cosim.scene.toml_io import to_dict
    from cosim.validations.radiation import held_scene, radiation_scene

    scene = radiation_scene(True)
    held = held_scene(scene)
    sig = held.bodies[0].motion.signal()
    assert all(sig(tt)[0] == 0.0 and sig(tt)[1] == 0.0 for tt in np.linspace(0.0, scene.world.duration, 7))
    a, h = to_dict(scene), to_dict(held)
    a["bodies"][0].pop("motion"), h["bodies"][0].pop("motion")
    assert a == h


def test_another_hulls_amplitude_changes_its_forced_run_only():
    """benchmarks/radiation_hull.py --amplitude: the forced scene heaves through the amplitude
    asked for, and the tare is the same scene whatever the amplitude (one tare serves them);
    --set reaches both runs."""
    from benchmarks.radiation_hull import scene_for
    from cosim.scene.toml_io import to_dict

    forced = scene_for("cylinder", 3.0, 4.0, 6, False, amplitude=0.15)
    sig = forced.bodies[0].motion.signal()
    t = np.linspace(3.54, forced.world.duration, 400)  # after the one-period ramp
    assert max(sig(tt)[0] for tt in t) == pytest.approx(0.15, rel=1e-3)
    assert to_dict(scene_for("cylinder", 3.0, 4.0, 6, True, amplitude=0.15)) \
        == to_dict(scene_for("cylinder", 3.0, 4.0, 6, True, amplitude=0.6))
    assert forced.fluid.nu > 0.0
    assert [scene_for("cylinder", 3.0, 4.0, 6, held, settings=["fluid.nu=0"]).fluid.nu for held in (False, True)] \
        == [0.0, 0.0]


def test_another_hulls_depth_keeps_its_draft_and_the_air_above():
    """benchmarks/radiation_hull.py --depth: the water, the wave theory and the body's
    waterline move to the depth asked for, the draft and the walls' height above the water
    stay."""
    from benchmarks.radiation_hull import scene_for

    case, deep = scene_for("cylinder", 3.0, 4.0, 6, False), scene_for("cylinder", 3.0, 4.0, 6, False, depth=12.0)
    assert (deep.domain.depth, deep.waves.depth) == (12.0, 12.0)
    assert deep.domain.height - deep.domain.depth == pytest.approx(case.domain.height - case.domain.depth)
    for s in (case, deep):
        assert draft_of(s) == pytest.approx(3.0)
        assert s.bodies[0].pos[-1] == pytest.approx(s.domain.depth)


FORCED = """
name = "forced"
[world]
dim = 2
duration = 2.0
sample_every = 0.05
[fluid]
model = "analytic"
[[bodies]]
shape = "box"
name = "box"
size = [2.0, 1.0]
pos = [0.0, 0.0]
density = 500.0
motion = { kind = "harmonic", amplitude = 0.2, period = 1.0, ramp = 1.0 }
[probes]
tensions = false
"""


def test_a_forced_body_follows_its_motion_whatever_the_fluid_does(tmp_path):
    """A box forced in heave by 0.2 m at 1 s, faded in over one period, in the analytic
    fluid whose buoyancy changes by rho g B z (19.6 kN per metre of heave): its heave is
    0.2 w(t) sin(2 pi t) at every sample (w the half-cosine window), its surge and pitch
    stay 0, and the fluid's force is recorded."""
    from cosim.scene import Scene

    path = tmp_path / "forced.toml"
    path.write_text(FORCED)
    res = Scene.from_toml(path).run(tmp_path / "out", progress=False)
    t = res.t
    window = np.where(t < 1.0, 0.5 * (1.0 - np.cos(math.pi * t)), 1.0)
    assert np.abs(res["box.heave"] - 0.2 * window * np.sin(2.0 * math.pi * t)).max() < 1e-9
    assert np.abs(res["box.surge"]).max() == 0.0 and np.abs(res["box.pitch"]).max() == 0.0
    f = res["box.fluid_Fz"]
    assert f[0] == pytest.approx(1000.0 * 9.81 * 1.0, rel=1e-9)  # half the 2 x 1 m box under the level
    assert f.max() - f.min() > 0.5 * 1000.0 * 9.81 * 2.0 * 0.4  # the buoyancy swings with the heave


@pytest.mark.slow
def test_quick_case_meets_its_own_tolerances():
    """cosim validate nearfield-radiation --quick (R/dx = 4, six periods and the tare; about
    half an hour of CPU)."""
    from cosim import validation

    r = validation.run("nearfield-radiation", quick=True)
    assert r["passed"], (r["outside_tolerance"], {k: r["metrics"][k] for k in r["tolerances"]})


def test_still_water_has_no_motion_and_the_radiated_wavelength():
    """fluid.waves.StillWater: zero elevation, velocity and orbits; its wavenumber satisfies
    the dispersion relation w^2 = g k tanh(k d) at the period given."""
    from fluid.waves import SeaError, StillWater

    s = StillWater(3.54, 6.0, level=6.0)
    w, k = 2.0 * math.pi / 3.54, 2.0 * math.pi / s.wavelength
    assert w * w == pytest.approx(9.81 * k * math.tanh(6.0 * k), rel=1e-10)
    x = np.array([0.0, 3.0, 9.0])
    assert not np.any(s.elevation(x, 0.0, 2.0))
    assert not np.any(s.velocity(x, 0.0, np.full(3, 4.0), 2.0))
    assert not np.any(s.displacement(x, np.zeros(3), np.full(3, 4.0), 2.0)[0])
    with pytest.raises(SeaError, match="period"):
        StillWater(0.0, 6.0)
