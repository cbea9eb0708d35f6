"""The mean wave drift force of the potential fluid (fluid.potential.drift): a fixed vertical
cylinder against the closed form, the far field's energy balance, Newman's approximation
against the regular-wave mean, and a moored body's mean offset in time."""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("capytaine")
pytest.importorskip("h5netcdf")

from scipy.special import h1vp, jvp  # noqa: E402

from cosim.errors import InputError  # noqa: E402
from fluid.potential import compute, wetted_hull  # noqa: E402
from fluid.potential.drift import MeanDrift, SlowDrift, mean_drift, response  # noqa: E402
from fluid.potential.waves import Sea, WaveComponent, regular  # noqa: E402

RHO, G = 1000.0, 9.81
KA = np.array([1.0, 1.5, 2.0])


def cylinder_drift(ka: float, a: float = 1.0, terms: int = 60, angles: int = 2048) -> float:
    """Mean drift per squared amplitude [N/m^2] on a fixed vertical cylinder of radius ``a``
    through the whole depth, deep water: Maruo's (1960) far-field momentum balance,
    ``D = ρ g (c_g / c) / (π k) ∫ |f(θ)|² (1 − cos θ) dθ``, with the scattered far field
    ``f(θ) = −Σ ε_m J_m'(ka) / H_m'(ka) cos mθ`` of MacCamy & Fuchs (1954), as Havelock (1940)
    (limits: 5π²/16 (ka)³ ρ g a for small ka, 2/3 ρ g a for large)."""
    k = ka / a
    th = np.linspace(0.0, 2.0 * math.pi, angles, endpoint=False)
    m = np.arange(terms)
    f = -(np.where(m == 0, 1.0, 2.0) * jvp(m, ka) / h1vp(m, ka)) @ np.cos(np.outer(m, th))
    return RHO * G * 0.5 / (math.pi * k) * 2.0 * math.pi * float(np.mean(np.abs(f) ** 2 * (1.0 - np.cos(th))))


def test_closed_form_has_havelocks_limits():
    assert cylinder_drift(0.05) == pytest.approx(5 * math.pi**2 / 16 * 0.05**3 * RHO * G, rel=0.01)
    assert cylinder_drift(40.0) == pytest.approx(2.0 / 3.0 * RHO * G, rel=0.01)


@pytest.fixture(scope="module")
def deep_cylinder(tmp_path_factory):
    """A vertical cylinder of radius 1 m drawing 4 m in deep water (e^{-k d} <= 2 % at the test's
    ka: nearly the cylinder through the whole depth), panels 0.3 m, at ka = 1, 1.5, 2."""
    hull = wetted_hull("cylinder", [1.0, 4.0], np.eye(3), [0.0, 0.0, -2.0], 0.3)
    return compute(hull, 0.0, omega=np.sqrt(KA * G), headings=[0.0, 90.0], rho=RHO, g=G,
                   cache=tmp_path_factory.mktemp("drift"), kochin=True)


@pytest.mark.long
def test_fixed_cylinder_drift_is_havelocks(deep_cylinder):
    d = mean_drift(deep_cylinder)
    ref = np.array([cylinder_drift(ka) for ka in KA])
    assert d.D[:, 0, 0] == pytest.approx(ref, rel=0.05)  # measured 3.9, 1.0, 1.1 %
    assert d.D[:, 1, 1] == pytest.approx(d.D[:, 0, 0], rel=0.01)  # waves turned 90 deg: sway (the panels are not)
    assert np.abs(d.D[:, 0, [1, 5]]).max() < 2e-3 * ref.min()  # no sway force, no yaw moment (to the panels)
    assert np.abs(d.D[..., 2:5]).max() == 0.0


def _power_balance(c, H):
    """Extinction ``ω (−Im H(β = 0))`` and scattering ``k² ∫ |H|² dθ`` (deep water), per frequency."""
    th = c.theta
    turn = (th > -1e-9) & (th < 2 * math.pi + 1e-9)
    i0 = int(np.argmin(np.abs(th)))
    return c.omega * -H[:, 0, i0].imag, c.wavenumber**2 * np.trapezoid(np.abs(H[:, 0, turn]) ** 2, th[turn], axis=-1)


@pytest.mark.long
def test_far_field_conserves_energy(deep_cylinder):
    """A body that dissipates nothing removes from the incident wave the power it scatters and
    radiates (the optical theorem: Newman 1967; Maruo 1960), fixed or floating freely."""
    c = deep_cylinder
    ext, sca = _power_balance(c, 1j * c.kochin_diffraction)
    assert ext == pytest.approx(sca, rel=0.02)  # measured 0.8 %
    m = RHO * math.pi * 4.0
    M = np.diag([m, m, m, m * (3 + 16) / 12, m * (3 + 16) / 12, m / 2])
    xi = response(c, M)
    ext, sca = _power_balance(c, 1j * (c.kochin_diffraction + np.einsum("wbj,wjt->wbt", xi, c.kochin_radiation)))
    assert ext == pytest.approx(sca, rel=0.03)
    free, fixed = mean_drift(c, M).D[:, 0, 0], mean_drift(c).D[:, 0, 0]
    assert np.abs(free / fixed - 1).max() > 0.05  # its motions count: they change the drift


def _table(D):
    w = np.array([0.5, 1.0, 1.5])
    return MeanDrift(w, np.array([0.0]), np.broadcast_to(np.asarray(D, float)[:, None, :], (3, 1, 6)).copy(), True)


def test_newman_one_component_is_the_regular_wave_mean():
    D = np.zeros((3, 6))
    D[:, 0], D[:, 1], D[:, 5] = [100.0, 200.0, 300.0], [-50.0, -60.0, -70.0], 5.0
    sea = Sea([WaveComponent(1.2, 0.5, 0.7)])
    slow = SlowDrift(sea, _table(D), [3.0, 1.0])
    D12 = np.array([np.interp(1.2, [0.5, 1.0, 1.5], D[:, i]) for i in range(6)])
    for t in (0.0, 1.3, 17.0):
        assert slow.force(t) == pytest.approx(0.25 * D12, rel=1e-12, abs=1e-12)  # a² D, negative sway kept


def test_newman_two_components_beat_at_the_difference_frequency():
    D = np.zeros((3, 6))
    D[:, 0] = [100.0, 400.0, 900.0]
    sea = Sea([WaveComponent(0.6, 0.3, 0.2), WaveComponent(1.4, 0.4, -1.0)])
    slow = SlowDrift(sea, _table(D), [0.0, 0.0])
    t = np.linspace(0.0, 2 * math.pi / 0.8, 4001)[:-1]  # one difference period
    Fx = np.array([slow.force(s)[0] for s in t])
    d1, d2 = np.interp(0.6, [0.5, 1.0, 1.5], D[:, 0]), np.interp(1.4, [0.5, 1.0, 1.5], D[:, 0])
    assert Fx.mean() == pytest.approx(0.09 * d1 + 0.16 * d2, rel=1e-9)  # Σ a_j² D_j
    assert np.ptp(Fx) / 2 == pytest.approx(2 * 0.3 * 0.4 * math.sqrt(d1 * d2), rel=1e-6)  # T_12 = sqrt(D_1 D_2)


@pytest.mark.long
def test_drift_refusals(deep_cylinder):
    from fluid.potential.participant import PotentialFluid

    with pytest.raises(InputError, match="drift = True needs waves"):
        PotentialFluid(drift=True)
    bare = compute(wetted_hull("cylinder", [1.0, 1.0], np.eye(3), [0.0, 0.0, -0.2], 0.5), 0.0, omega=[0.5, 1.0],
                   use_cache=False)
    with pytest.raises(InputError, match="no Kochin functions"):
        mean_drift(bare)
    with pytest.raises(InputError, match="outside the drift coefficients' frequencies"):
        SlowDrift(Sea(regular(0.1, 1.0)), mean_drift(deep_cylinder), [0.0, 0.0])


@pytest.mark.long
def test_moored_cylinder_mean_offset_is_drift_over_stiffness(tmp_path):
    """The cylinder of potential-cylinder-rao on a horizontal spring (a long MuJoCo tendon, surge
    period about 13 s) in a regular wave faded in over 40 s: the drift force moves its mean surge
    by ``a² D / k`` (the difference to the same run without it), the run without it stays put."""
    from bodies import builders
    from bodies.mujoco_bodies import MujocoBodies
    from cosim.coupler import Coupler
    from cosim.validations.potential import DRAFT, L_CYL, R_CYL
    from fluid.potential.participant import PotentialFluid

    k_spring, a, w, far = 2.0e4, 0.5, 1.5, 1.0e3
    m = RHO * math.pi * R_CYL**2 * DRAFT
    body = builders.cylinder("cyl", R_CYL, L_CYL, (0.0, 0.0, 0.5 * L_CYL - DRAFT), mass=m, sites={"fair": (0, 0, 0)})
    tendon = (f'<site name="anchor" pos="{-far} 0 0"/></worldbody><tendon><spatial stiffness="{k_spring}" '
              f'springlength="{far}"><site site="anchor"/><site site="fair"/></spatial></tendon>')
    xml = builders.scene(body, gravity=G, timestep=0.005).replace("</worldbody>", tendon)
    runs = {}
    for drift in (False, True):
        bodies = MujocoBodies(xml)
        fluid = PotentialFluid(rho=RHO, g=G, omega=np.linspace(0.15, 3.0, 20), panel_size=1.0,
                               sea=Sea([WaveComponent(w, a)], ramp=40.0), cache=tmp_path, drift=drift)
        coupler = Coupler(bodies=bodies, fluid=fluid)
        coupler.initialize()
        x0 = float(bodies.data.qpos[0])
        ts, xs = [], []
        coupler.run(90.0, callback=lambda info: (ts.append(info.t), xs.append(bodies.data.qpos[0] - x0)))
        runs[drift] = np.array(xs)
    t = np.array(ts)
    D = float(np.interp(w, fluid.mean_drift[0].omega, fluid.mean_drift[0].D[:, 0, 0]))
    late = t >= t[-1] - 12 * 2 * math.pi / w  # twelve wave periods, about four surge periods
    span = t[late][-1] - t[late][0]
    mean = {d: float(np.trapezoid(x[late], t[late]) / span) for d, x in runs.items()}
    expected = a * a * D / k_spring
    assert D > 100.0
    assert mean[True] - mean[False] == pytest.approx(expected, rel=0.05)
    assert abs(mean[False]) < 0.2 * expected
