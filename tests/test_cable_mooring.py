"""The SPH cable in water and as a mooring model (cosim.protocol.Mooring)."""

import math

import numpy as np
import pytest

from cosim.errors import InputError
from cosim.protocol import Mooring, check_participant
from moorings.catenary import solve
from moorings.line import MooringLine
from moorings.sph_cable import SPHCable, SPHCableMooring

RHO = 1025.0


def _falling(axis_vertical, dim=2):
    n, L, mu, w, d = 21, 2.0, 1.0, 5.0, 0.05
    s = np.linspace(0.0, L, n)
    pos = np.stack([np.zeros(n), -s], 1) if axis_vertical else np.stack([s, np.zeros(n)], 1)
    if dim == 3:  # the same line in 3-D, its axis turned 40° about z
        c, sn = math.cos(0.7), math.sin(0.7)
        pos = np.stack([c * pos[:, 0], sn * pos[:, 0], pos[:, 1]], 1)
    c = SPHCable(L, n, 1e4, mu, pos[0], pos[-1], weight_per_length=w, free_end="both", positions=pos, omega=0.0,
                 diameter=d, rho_water=RHO)
    return c, mu, w, d


@pytest.mark.parametrize("dim", [2, 3])
def test_morison_normal_added_mass_and_terminal_velocity(dim):
    c, mu, w, d = _falling(axis_vertical=False, dim=dim)
    ma = RHO * math.pi * d * d / 4  # ca_normal = 1
    c.advance(0.0, 1e-3)
    np.testing.assert_allclose(c.v[:, -1] / c.t, -w / (mu + ma), rtol=2e-3)
    while c.t < 3.0:
        c.advance(c.t, 0.1)
    np.testing.assert_allclose(c.v[:, -1], -math.sqrt(2 * w / (RHO * 1.2 * d)), rtol=1e-3)
    np.testing.assert_allclose(c.v[:, :-1], 0.0, atol=1e-9)


def test_morison_tangential_drag_terminal_velocity():
    c, mu, w, d = _falling(axis_vertical=True)
    c.advance(0.0, 1e-3)
    np.testing.assert_allclose(c.v[:, 1] / c.t, -w / mu, rtol=2e-3)  # no tangential added mass
    while c.t < 5.0:
        c.advance(c.t, 0.1)
    np.testing.assert_allclose(c.v[:, 1], -math.sqrt(2 * w / (RHO * 0.008 * math.pi * d)), rtol=1e-3)


def test_seabed_is_not_penetrated():
    L, n = 10.0, 21
    pos = np.stack([np.linspace(0, L, n), np.full(n, 1.0)], 1)
    c = SPHCable(L, n, 1e5, 2.0, pos[0], pos[-1], free_end="both", positions=pos, seabed_z=0.0, omega=0.5)
    z_min = np.inf
    for _ in range(60):
        c.advance(c.t, 0.05)
        z_min = min(z_min, c.x[:, 1].min())
    assert z_min >= 0.0
    np.testing.assert_allclose(c.x[:, 1], 0.0, atol=1e-12)  # it came to rest on the seabed
    assert c.max_speed() < 1e-6


def _line(**kw):
    return MooringLine(anchor=(0.0, -50.0), length=150.0, weight=918.75, EA=1e9, mass_per_length=107.7, **kw)


def test_protocol_and_input_checks():
    m = SPHCableMooring([_line()], fairleads=[[130.0, 0.0]], n_particles=20)
    check_participant(m, Mooring)
    with pytest.raises(InputError, match="mass_per_length"):
        SPHCableMooring([MooringLine(anchor=(0, -50), length=150, weight=900, EA=1e9)])
    with pytest.raises(InputError, match="EA"):
        SPHCableMooring([MooringLine(anchor=(0, -50), length=150, weight=900, mass_per_length=100)])
    with pytest.raises(InputError, match="not set"):
        SPHCableMooring([_line()]).initialize(0.0)
    with pytest.raises(InputError, match="below"):
        SPHCableMooring([_line()], fairleads=[[130.0, -60.0]])
    with pytest.raises(InputError, match="supports"):
        SPHCableMooring([_line()], fairleads=[[200.0, 0.0]], n_particles=20).initialize(0.0)


@pytest.mark.parametrize("X", [115.0, 130.0, 140.0])
def test_settled_line_matches_the_elastic_catenary_with_seabed(X):
    """At rest the SPH mooring line pulls the fairlead as the quasi-static elastic
    catenary with seabed contact does (moorings.catenary.solve)."""
    m = SPHCableMooring([_line()], fairleads=[[X, 0.0]], n_particles=40, omega=1.0)
    m.initialize(0.0)
    check_participant(m, Mooring)
    assert m.max_dt() == math.inf and 0 < m.stable_dt() < 1e-3
    for _ in range(60):
        m.advance(m.t, 1.0)
    r = solve(X, 50.0, 150.0, 918.75, 1e9)
    F = m.fairlead_forces()[0]
    assert np.hypot(*F) == pytest.approx(math.hypot(r.H, r.V), rel=0.01)
    assert F[0] == pytest.approx(-r.H, rel=0.03)
    assert F[1] == pytest.approx(-r.V, rel=0.01)
    # the anchor is pulled towards the fairlead; line weight closes the vertical balance
    Fa = m.anchor_forces()[0]
    assert Fa[0] == pytest.approx(-F[0], rel=1e-6)
    shape = m.shapes()[0]
    assert shape[:, 1].min() >= -50.0


def test_save_and_load_state_replays_exactly():
    m = SPHCableMooring([_line()], fairleads=[[130.0, 0.0]], n_particles=20, omega=0.04)
    m.initialize(0.0)
    m.advance(0.0, 0.5)
    snap = m.save_state()
    m.set_fairlead_motion([[131.0, 0.5]], [[1.0, 0.0]])
    m.advance(0.5, 0.5)
    a = m.fairlead_forces()
    m.load_state(snap)
    m.set_fairlead_motion([[131.0, 0.5]], [[1.0, 0.0]])
    m.advance(0.5, 0.5)
    np.testing.assert_array_equal(m.fairlead_forces(), a)


@pytest.mark.long
def test_swaps_for_the_catenary_in_a_coupled_scene():
    """The same MooringLine list drives either model through the coupler; with a (nearly)
    fixed body the settled SPH line pulls the fairlead as the catenary does."""
    from bodies import builders
    from bodies.mujoco_bodies import MujocoBodies
    from cosim.coupler import Coupler
    from moorings.catenary_mooring import CatenaryMooring

    xml = builders.scene(builders.box("b", (2.0, 1.0), (0, 0, 0), mass=1e9, planar=True,
                                      sites={"fl": (1.0, 0.0, -0.5)}), gravity=0.0)
    lines = [MooringLine((30.0, -20.0), 40.0, 100.0, EA=1e7, mass_per_length=12.0)]
    forces = []
    for model in (CatenaryMooring(lines), SPHCableMooring(lines, n_particles=30, omega=2.0)):
        c = Coupler(bodies=MujocoBodies(xml), moorings=[(model, ["fl"])], dt=0.25, scheme="explicit")
        c.run(40.0)
        forces.append(c.ledger.arrays()["mooring_force"][-1, 0])
    np.testing.assert_allclose(forces[1], forces[0], rtol=0.01, atol=1e-3 * np.abs(forces[0]).max())


def test_three_line_spread_mooring_in_3d():
    """Three 3-D lines at 120° around a fixed fairlead triangle: each settled line pulls its
    fairlead like the elastic catenary with seabed, in its own vertical plane."""
    lines, fair = [], []
    for k in range(3):
        a = 2 * math.pi * k / 3 + 0.3
        e = np.array([math.cos(a), math.sin(a), 0.0])
        lines.append(MooringLine(anchor=tuple(125.0 * e + [0, 0, -50.0]), length=150.0, weight=918.75, EA=1e9,
                                 mass_per_length=107.7, name=f"l{k}"))
        fair.append(-5.0 * e)
    m = SPHCableMooring(lines, fairleads=fair, n_particles=30, omega=1.0)
    m.initialize(0.0)
    for _ in range(60):
        m.advance(m.t, 1.0)
    F = m.fairlead_forces()
    r = solve(130.0, 50.0, 150.0, 918.75, 1e9)
    for k, ln in enumerate(lines):
        horiz = (np.array(ln.anchor) - fair[k])[:2]
        e = horiz / np.linalg.norm(horiz)
        np.testing.assert_allclose(F[k, :2], r.H * e, rtol=0.01, atol=0.01 * r.H)
        assert F[k, 2] == pytest.approx(-r.V, rel=0.01)
    # symmetric spread: the horizontal forces cancel
    assert np.abs(F[:, :2].sum(axis=0)).max() < 1e-3 * r.H


def test_seabed_friction_decelerates_a_sliding_line_at_mu_g():
    L, n, mu_f, g = 10.0, 21, 0.3, 9.80665
    pos = np.stack([np.linspace(0, L, n), np.zeros(n)], 1)
    c = SPHCable(L, n, 1e5, 2.0, pos[0], pos[-1], free_end="both", positions=pos, seabed_z=0.0, seabed_friction=mu_f,
                 omega=0.0)
    c.v[:, 0] = 1.0
    c.advance(0.0, 0.2)
    np.testing.assert_allclose(c.v[:, 0], 1.0 - mu_f * g * 0.2, rtol=2e-3)
    c.advance(0.2, 0.3)
    assert np.abs(c.v).max() < 1e-3  # stopped (after 1/(mu g) = 0.34 s)
    # stopping distance v0^2 / (2 mu g)
    assert c.x[0, 0] == pytest.approx(1.0 / (2 * mu_f * g), rel=0.01)


def test_a_resting_line_starts_at_rest():
    """The main example's line (L = 0.9 m, 5 N/m, EA = 1e5 N, fairlead 0.6 m from the
    anchor and 0.25 m up: X < L - h, part of it slack on the bed), fairlead held: over the
    first 0.1 s the fairlead tension stays near the catenary's w h = 1.25 N (measured
    1.26-1.36 N; it started at 4.9 kN when the quasi-static shape put the hanging part at
    x = L - h, past the fairlead)."""
    line = MooringLine((0.5, 0.0), 0.9, 5.0, EA=1e5, mass_per_length=5.0 / 9.81 + 1000 * math.pi * 0.01**2 / 4)
    m = SPHCableMooring([line], fairleads=[[1.1, 0.25]], n_particles=20)
    m.initialize(0.0)
    T = []
    for _ in range(100):
        m.advance(m.t, 1e-3)
        T.append(m.fairlead_tensions()[0])
    assert min(T) > 0.9 * 1.25 and max(T) < 1.15 * 1.25


@pytest.mark.parametrize("n", [20, 40])
def test_a_stiff_curved_line_starts_in_its_own_equilibrium(n):
    """The wind-turbine base's chain (examples/wind_turbine_base.toml: 45 m, 3770 N/m, EA =
    1.9e9 N, fairlead 34 m out and 18.5 m up, 21 m on the bed): its chords' deficit on the
    continuous curve, (kappa ds)^2 / 24 ~ 1e-3, is 25 times its stretch, so nodes on the
    law's curve started slack (H / V 8.7 / 35.2 kN at 20 nodes, 21.1 / 78.9 at 40, against
    24.4 / 91.0 kN) and jerked 22 / 6 mm in 2 s. On the chain's own equilibrium the fairlead force at t = 0 is the
    law's to O(ds^2) (-0.2 / -0.08 % at 40 nodes) and no node moves."""
    X, h = 34.0, 18.5
    line = MooringLine((0.0, 0.0, 0.0), 45.0, 3769.9, EA=1.9e9, mass_per_length=442.0, diameter=0.268)
    m = SPHCableMooring([line], fairleads=[[X, 0.0, h]], n_particles=n)
    m.initialize(0.0)
    law = solve(X, h, 45.0, 3769.9, 1.9e9)
    F0, x0 = m.fairlead_forces()[0].copy(), m.cables[0].x.copy()
    assert -F0[0] == pytest.approx(law.H, rel=0.01) and -F0[2] == pytest.approx(law.V, rel=0.005)
    for _ in range(50):
        m.advance(m.t, 0.01)
    assert np.abs(m.cables[0].x - x0).max() < 1e-5
    assert m.fairlead_forces()[0] == pytest.approx(F0, rel=1e-4, abs=1e-4 * law.V)
