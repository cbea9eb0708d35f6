"""Bodies solved together by the BEM (fluid.potential.group): reciprocity of the coupled
coefficients, the isolated body's coefficients far apart, a measurable interaction close by,
and the cache keyed by the bodies' positions (coarse meshes, three frequencies)."""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("capytaine")
pytest.importorskip("h5netcdf")

from cosim.errors import InputError  # noqa: E402
from fluid.potential import compute, wetted_hull  # noqa: E402
from fluid.potential.group import compute_group  # noqa: E402

OMEGA = np.array([1.0, 2.0, 3.0])


def _hull():
    return wetted_hull("cylinder", [1.0, 2.0], np.eye(3), [0.0, 0.0, 0.0], 0.4)  # radius 1 m, draft 1 m


def _pair(gap_x: float, cache):
    return compute_group([_hull(), _hull()], [[0.0, 0.0], [gap_x, 0.0]], [0.0, 0.0], names=["a", "b"], omega=OMEGA,
                         headings=[0.0, 30.0], cache=cache)


@pytest.fixture(scope="module")
def cache(tmp_path_factory):
    return tmp_path_factory.mktemp("group")


@pytest.fixture(scope="module")
def alone(cache):
    return compute(_hull(), 0.0, omega=OMEGA, headings=[0.0, 30.0], cache=cache)


def _coupling(grp, which):
    """Largest |block (0, 1)| entry over the frequencies, each against sqrt(A_ii A_jj) of the diagonal blocks."""
    a = getattr(grp, which)
    d = np.sqrt(np.abs(np.einsum("wii->wi", a)))
    ref = np.einsum("wi,wj->wij", d[:, :6], d[:, 6:])
    live = ref > 1e-6 * ref.max()
    return float((np.abs(grp.block(a, 0, 1)) / np.where(live, ref, np.inf)).max())


def test_coupled_coefficients_are_reciprocal(cache):
    g = _pair(4.0, cache)
    assert g.added_mass.shape == (3, 12, 12)
    for a in (g.added_mass, g.damping):
        assert np.allclose(g.block(a, 0, 1), np.swapaxes(g.block(a, 1, 0), -1, -2), rtol=0, atol=1e-9 * np.abs(a).max())
    # the damping matrix of the pair is positive semi-definite: radiated power >= 0
    assert np.linalg.eigvalsh(g.damping).min() > -1e-5 * np.abs(g.damping).max()


@pytest.mark.long
def test_far_apart_each_body_has_its_own_coefficients(cache, alone):
    near, far = _pair(50.0, cache), _pair(200.0, cache)
    for c in far.bodies:
        for ours, its in ((c.added_mass, alone.added_mass), (c.damping, alone.damping)):
            d = np.abs(np.einsum("wii->wi", its))
            assert np.abs(np.einsum("wii->wi", ours - its)).max() < 0.01 * d.max()  # measured 0.64 %
        # referred to each body's own centre (a wrong phase would be off by up to 2x); the other's
        # scattered wave, 1 / sqrt(k r) ~ 0.07 at 3 rad/s, keeps it 5.5 % off (measured)
        assert np.abs(c.excitation - alone.excitation).max() < 0.1 * np.abs(alone.excitation).max()
    # waves carry the interaction: it falls off as 1 / sqrt(k r), not faster (200 m against 50 m: 1/2)
    ratio = _coupling(far, "damping") / _coupling(near, "damping")
    assert 0.3 < ratio < 0.7


@pytest.mark.long
def test_close_bodies_interact_measurably(cache, alone):
    g = _pair(3.0, cache)  # 1 m of water between them
    a = g.bodies[0]
    # in-line surge, measured: added mass 23 %, damping 41 %, excitation 36 % off the lone body's at 3 rad/s
    assert np.abs(a.added_mass[:, 0, 0] / alone.added_mass[:, 0, 0] - 1).max() > 0.1
    assert np.abs(a.damping[:, 0, 0] / alone.damping[:, 0, 0] - 1).max() > 0.1
    assert np.abs(np.abs(a.excitation[:, 0, 0]) / np.abs(alone.excitation[:, 0, 0]) - 1).max() > 0.1
    assert _coupling(g, "added_mass") > 0.1


@pytest.mark.long
def test_cache_keys_on_positions(cache):
    _pair(4.0, cache)  # solved here, or already by another test of this module in this process
    g1 = _pair(4.0, cache)
    assert g1.bodies[0].meta["from_cache"]
    g2 = _pair(4.5, cache)
    assert g2.key != g1.key and not g2.bodies[0].meta["from_cache"]


def test_group_refusals():
    with pytest.raises(InputError, match="distinct body names"):
        compute_group([_hull(), _hull()], [[0, 0], [5, 0]], [0, 0], names=["a", "a"], omega=OMEGA)


def _heave_decay(xs, interaction, cache, duration=10.0):
    """Cylinders of potential-cylinder-rao at ``xs`` [m] (centres), the first released 0.1 m above
    its rest: its heave history."""
    import mujoco

    from bodies import builders
    from bodies.mujoco_bodies import MujocoBodies
    from cosim.coupler import Coupler
    from cosim.validations.potential import DRAFT, L_CYL, R_CYL
    from fluid.potential.participant import PotentialFluid

    m = 1000.0 * math.pi * R_CYL**2 * DRAFT
    xml = builders.scene(*[builders.cylinder(f"c{i}", R_CYL, L_CYL, (x, 0.0, 0.5 * L_CYL - DRAFT), mass=m)
                           for i, x in enumerate(xs)], timestep=0.005)
    bodies = MujocoBodies(xml)
    fluid = PotentialFluid(omega=np.linspace(0.15, 3.0, 20), panel_size=1.0, cache=cache, interaction=interaction)
    coupler = Coupler(bodies=bodies, fluid=fluid)
    coupler.initialize()
    z0 = float(bodies.data.qpos[2])
    bodies.data.qpos[2] += 0.1
    mujoco.mj_forward(bodies.model, bodies.data)
    fluid.set_body_kinematics(bodies.kinematics())
    zs = []
    coupler.run(duration, callback=lambda info: zs.append(bodies.data.qpos[2] - z0))
    return np.array(zs), fluid


@pytest.mark.long
def test_time_domain_interaction(cache):
    """In time, with interaction: a neighbour 7 m off (1 m of water between) changes the released
    body's heave measurably (more than 3 % of its amplitude) through the coupled memory and added
    mass. Far apart: test_bodies_far_apart_get_the_frequencies_their_cross_memory_needs."""
    alone, _ = _heave_decay([0.0], False, cache)
    near, fluid = _heave_decay([0.0, 7.0], True, cache)
    assert fluid.group is not None and fluid.group_impulse.K.shape[1:] == (12, 12)
    amp = np.abs(alone).max()
    assert np.abs(near - alone).max() > 0.03 * amp


def _far_pair_scene(gap: float, frequencies=None):
    """Two small cylinders (radius 1 m, draft 1 m, 0.5 m panels: omega_max 4.53 rad/s) ``gap`` m
    apart along x, solved together, the frequencies left to the fluid unless given."""
    from cosim.scene import Scene

    fluid = {"model": "potential", "panel_size": 0.5, "interaction": True}
    if frequencies is not None:
        fluid["frequencies"] = frequencies
    body = {"shape": "cylinder", "radius": 1.0, "length": 2.0, "place": "floating", "density": 500.0}
    return Scene.from_dict({"world": {"dim": 3, "duration": 1.0, "sample_every": 0.1}, "fluid": fluid,
                            "bodies": [dict(body, name="a", pos=[0.0, 0.0]), dict(body, name="b", pos=[gap, 0.0])]})


@pytest.mark.slow  # out of CI's time (docs/development.md)
def test_bodies_far_apart_get_the_frequencies_their_cross_memory_needs(tmp_path, monkeypatch):
    """20 m apart, frequencies unset: the fluid picks a spacing whose window holds the waves'
    round trip (81 frequencies instead of 40, which the impulse-response check refused); the
    cross heave kernel peaks when the waves that carry the most of it arrive: by stationary
    phase on K_ab(t) = (2/π) ∫ B_ab cos ωt dω with B_ab ~ B_33(ω) J0(k r) (heave radiates
    alike all round) and deep-water k = ω²/g, at t = r / c_g(ω*) = 2 r ω* / g, ω* the maximum
    of B_33(ω) / ω (the lone body's damping over sqrt(k)); measured 6.93 s against 6.39 s.
    Given 40 frequencies, the scene is refused naming fluid.frequencies and the count."""
    from cosim.scene.build import build
    from cosim.scene.fields import SceneError

    monkeypatch.setenv("COSIM_POTENTIAL_CACHE", str(tmp_path / "cache"))
    gap = 20.0
    res = _far_pair_scene(gap).run(tmp_path / "out", progress=False)
    assert np.isfinite(res["a.heave"]).all()
    built = build(_far_pair_scene(gap), tmp_path / "work")
    built.coupler.initialize()
    fluid = built.fluid
    assert len(fluid.group.omega) > 40
    irf = fluid.group_impulse
    assert irf.memory < math.pi / np.diff(fluid.group.omega).max()
    t_peak = irf.t[np.argmax(np.abs(irf.K[:, 2, 8]))]  # a's heave load from b's heave velocity
    lone = compute(wetted_hull("cylinder", [1.0, 1.0], np.eye(3), [0.0, 0.0, 0.0], 0.5), 0.0,
                   omega=fluid.group.omega, cache=tmp_path / "cache")
    w = lone.omega
    w_star = w[np.argmax(lone.damping[:, 2, 2] / w)]
    assert t_peak == pytest.approx(2 * gap * w_star / 9.81, rel=0.12)
    with pytest.raises(SceneError, match=r"fluid\.frequencies: bodies a, b: the cross memory needs .* frequencies = 40 "
                                         r"is too few: give at least \d+"):
        _far_pair_scene(gap, frequencies=40).run(tmp_path / "out2", progress=False)
