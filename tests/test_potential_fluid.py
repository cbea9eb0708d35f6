"""The potential-flow fluid in time (the Cummins equation on MuJoCo through the coupler): rest,
heave decay and a regular-wave response against the frequency domain, on coarse meshes; the
registered validation cases (quick)."""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("capytaine")
pytest.importorskip("h5netcdf")

from cosim import validation  # noqa: E402
from cosim.errors import InputError  # noqa: E402
from cosim.validations import potential as P  # noqa: E402

GRID = np.linspace(0.15, 3.0, 20)


@pytest.fixture(scope="module", autouse=True)
def _cache(tmp_path_factory):
    """One cache for the module: the first test solves, the others read (the cache's own
    behaviour is tested in test_potential_coefficients.py)."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("COSIM_POTENTIAL_CACHE", str(tmp_path_factory.mktemp("potential")))
        yield


@pytest.mark.long
def test_a_body_at_its_floating_pose_stays_at_rest():
    coupler, bodies, fluid = P.floating_cylinder(1.0, GRID)
    p0 = bodies.data.qpos.copy()
    coupler.run(5.0)
    assert np.abs(bodies.data.qpos - p0).max() < 1e-9
    # A∞'s diagonal went into the implicit inertia; the off-diagonal surge-pitch rest is explicit
    A = fluid.impulse[0].added_mass_inf
    assert np.allclose(bodies.model.dof_armature[:5], np.diag(A)[:5], rtol=1e-12)


@pytest.mark.long
def test_heave_decay_period_is_the_natural_period():
    d = P.heave_decay(P.rao_scene(True))
    assert np.mean(d["periods"][:2]) == pytest.approx(d["natural_period"], rel=0.015)
    assert 0.03 < d["damping_ratio"] < 0.1  # a squat cylinder radiates: the decay is visible


@pytest.mark.long
def test_regular_wave_response_is_the_frequency_domain_rao():
    scene = P.rao_scene(True, 0.8, periods=16)
    assert scene.waves.depth == math.inf and scene.world.duration == pytest.approx(16 * 2 * math.pi / 0.8)
    r = P.time_domain_rao(scene, fit=6)
    np.testing.assert_allclose(r["fluid"].coefficients[0].omega, GRID, rtol=1e-14)  # the case's grid before
    for dof in ("surge", "heave"):
        assert abs(r["td"][dof] - r["fd"][dof]) < 0.02 * abs(r["fd"][dof]), dof
    assert abs(r["fd"]["heave"]) == pytest.approx(1.0, abs=0.05)  # a long wave: the body rides it


def test_bad_inputs_are_refused_before_any_solve(tmp_path):
    from fluid.potential.participant import PotentialFluid
    from fluid.potential.waves import Sea, regular

    with pytest.raises(InputError, match="depth"):
        PotentialFluid(depth=0.0)
    with pytest.raises(InputError, match="differ from the fluid's"):
        PotentialFluid(depth=20.0, sea=Sea(regular(0.1, 5.0), depth=30.0))
    with pytest.raises(InputError, match="memory"):
        PotentialFluid(memory=-1.0)
    with pytest.raises(InputError, match="outside the coefficients' trusted band 0.15-1.5 rad/s"):
        P.floating_cylinder(1.0, GRID, sea=Sea(regular(0.1, 2.5)))  # a 2.5 s wave: 2.5 rad/s


@pytest.mark.long
def test_hemisphere_quick(tmp_path):
    r = validation.run("potential-hemisphere", quick=True)
    assert r["passed"], r["metrics"]
    _plots_in_the_report(r, tmp_path, 2)


def _plots_in_the_report(r, folder, n):
    """The record's series are plots the report draws (cosim.report.plot_series): n PNGs."""
    from cosim import report

    plots = report.plot_series(r["series"], folder, r["name"])
    assert len(plots) == n and all((folder / f).read_bytes()[:4] == b"\x89PNG" for _, f in plots)


@pytest.mark.slow
def test_cylinder_rao_quick():
    r = validation.run("potential-cylinder-rao", quick=True)
    assert r["passed"], r["metrics"]
    assert math.isfinite(r["metrics"]["decay_period_s"])


@pytest.mark.slow
def test_irregular_quick(tmp_path):
    r = validation.run("potential-irregular", quick=True)
    assert r["passed"], r["metrics"]
    _plots_in_the_report(r, tmp_path, 2)
    assert r["metrics"]["heave_rao_range"][1] > 1.3  # the band reaches up towards the heave resonance


def test_welch_spectrum_of_a_sine_holds_its_variance():
    # a 0.2 Hz sine of amplitude 0.5 m: the spectrum integrates to its variance a^2 / 2
    t = 0.1 * np.arange(36000)
    omega, S = P.welch_spectrum(0.5 * np.cos(2 * math.pi * 0.2 * t + 0.3), 600.0)
    assert np.trapezoid(S, omega) == pytest.approx(0.125, rel=1e-3)
    assert omega[np.argmax(S)] == pytest.approx(2 * math.pi * 0.2, abs=1e-9)


def test_band_errors_are_the_ratio_of_band_means():
    omega = np.linspace(0.1, 3.0, 2000)
    S = np.exp(-omega)
    e = P.band_errors(omega, 1.1 * S, S, 0.1)
    assert list(e) == [f"{a:.2f}-{a + 0.1:.2f}" for a in np.arange(0.7, 1.45, 0.1)]
    assert np.allclose(list(e.values()), 0.1, rtol=1e-12)


def test_gaussian_sigma_is_the_scatter_of_white_noise():
    # band means of Welch estimates of Gaussian white noise scatter as gaussian_sigma says
    rng = np.random.default_rng(1)
    wp = 2 * math.pi / P.TP
    out = []
    for _ in range(300):
        omega, S = P.welch_spectrum(rng.standard_normal(12000), 300.0)
        m = (omega >= 0.7 * wp) & (omega < 0.9 * wp)
        out.append(S[m].mean())
    rel = np.std(out, ddof=1) / np.mean(out)
    assert rel == pytest.approx(P.gaussian_sigma(1200.0, 300.0, 0.2), rel=0.1)


def test_a_spectral_sea_reaches_the_potential_fluid_unchanged():
    from fluid.potential.waves import from_incident

    inc = P.jonswap_sea(3, 600.0)
    sea = from_incident(inc)
    assert len(sea.omega) == inc.n_components and sea.depth == P.DEPTH_SEA and sea.ramp == inc.ramp
    for t in (5.0, 40.0, 333.3):
        xy = np.array([[0.0, 0.0], [12.0, -4.0], [-30.0, 7.5]])
        assert np.allclose(sea.elevation(xy, t), inc.elevation(xy[:, 0], xy[:, 1], t), atol=1e-12)


def test_the_irregular_cases_scene_is_its_sea_and_cylinder():
    """potential-irregular's scene file holds the case's sea (the constants its target and
    jonswap_sea use: the same components) and the cylinder of floating_cylinder (half
    submerged, its centre on the still water)."""
    scene = P.irregular_scene(True, 3, 600.0)
    w, body = scene.waves, scene.bodies[0]
    assert (w.hs, w.tp, w.gamma, w.depth, w.seed, tuple(w.band)) == (P.HS, P.TP, P.GAMMA, P.DEPTH_SEA, 3, P.SEA_BAND)
    assert w.sea(scene) == P.jonswap_sea(3, P.T_START + 600.0)
    assert (body.radius, body.length, tuple(body.pos)) == (P.R_CYL, P.L_CYL, (0.0, 0.0, 0.0))
    assert body.density * P.L_CYL == pytest.approx(P.RHO * P.DRAFT, rel=1e-12)
    assert (scene.fluid.panel_size, scene.fluid.omega_max, scene.fluid.frequencies) == P.IRREGULAR_GRID[True]
