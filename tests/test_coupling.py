"""The coupler's exchange between bodies, moorings and a fluid."""

import math

import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.errors import ConfigurationError, InputError, TautLineError
from cosim.validation import run
from fluid.analytic import AnalyticFluid
from moorings import CatenaryMooring, MooringLine
from moorings.catenary import solve


def heave_amplitudes(scheme, T=12.0):
    b = MujocoBodies(builders.scene(builders.box("p", (2.0, 1.0), (0, 0, 0.05), density=500.0, planar=True)))
    c = Coupler(bodies=b, fluid=AnalyticFluid(added_mass={"p": [0.0, 600.0, 0.0]}), scheme=scheme)
    zs = []
    c.run(T, callback=lambda i: zs.append(b.kinematics().com[0, 2]))
    zs = np.array(zs)
    up = np.flatnonzero((zs[:-1] < 0) & (zs[1:] >= 0))
    return np.array([zs[up[i]:up[i + 1]].max() for i in range(len(up) - 1)])


def test_explicit_coupling_pumps_energy_and_predictor_corrector_does_not():
    """Undamped heave on the hydrostatic spring: held start-of-step loads add
    energy (amplification ~ (w dt)^2/4 per step); the predictor-corrector keeps
    the amplitude to 0.5 % over 8 periods."""
    explicit = heave_amplitudes("explicit")
    pc = heave_amplitudes("predictor-corrector")
    assert explicit[-1] / explicit[0] > 1.2
    assert abs(pc[-1] / pc[0] - 1) < 5e-3
    assert pc[0] == pytest.approx(0.05, rel=5e-3)


def test_mooring_force_and_torque_reach_the_body():
    """One 3-D line on a fairlead 1 m off the centre of mass: the ledger books the
    catenary force and r x F, and the body feels exactly that (no gravity)."""
    xml = builders.scene(builders.box("b", (2.0, 2.0, 2.0), (0, 0, 0), mass=1e4, sites={"fl": (1.0, 0.0, -1.0)}),
                         gravity=0.0)
    b = MujocoBodies(xml)
    m = CatenaryMooring([MooringLine((40.0, 0.0, -30.0), 60.0, 200.0, name="l")])
    c = Coupler(bodies=b, moorings=[(m, ["fl"])], dt=0.01, scheme="explicit")
    c.step(1.0)
    ref = solve(39.0, 29.0, 60.0, 200.0)
    led = c.ledger.arrays()
    F, T = led["mooring_force"][0, 0], led["mooring_torque"][0, 0]
    np.testing.assert_allclose(F, [ref.H, 0.0, -ref.V], rtol=1e-12)
    np.testing.assert_allclose(T, np.cross([1.0, 0.0, -1.0], F), rtol=1e-12)
    v = b.kinematics().velocity[0]
    np.testing.assert_allclose(v, F / 1e4 * 0.01, rtol=1e-6)


def test_2d_mooring_on_a_planar_body():
    xml = builders.scene(builders.box("b", (2.0, 1.0), (0, 0, 0), mass=1e3, planar=True,
                                      sites={"fl": (1.0, 0.0, -0.5)}), gravity=0.0)
    b = MujocoBodies(xml)
    m = CatenaryMooring([MooringLine((30.0, -20.0), 40.0, 100.0)])
    c = Coupler(bodies=b, moorings=[(m, ["fl"])], dt=0.01, scheme="explicit")
    c.step(1.0)
    ref = solve(29.0, 19.5, 40.0, 100.0)
    F = c.ledger.arrays()["mooring_force"][0, 0]
    np.testing.assert_allclose(F, [ref.H, 0.0, -ref.V], rtol=1e-12)


def test_a_taut_line_stops_the_run_naming_step_time_and_line():
    xml = builders.scene(builders.box("b", (1.0, 1.0, 1.0), (0, 0, 0), mass=10.0, sites={"fl": (0.0, 0.0, 0.0)}),
                         gravity=0.0)
    b = MujocoBodies(xml)
    b.data.qvel[0] = -5.0  # drifting away from the anchor
    m = CatenaryMooring([MooringLine((10.0, 0.0, -5.0), 12.0, 1.0, name="stern")], taut="raise")
    c = Coupler(bodies=b, moorings=[(m, ["fl"])], dt=0.01)
    with pytest.raises(TautLineError, match=r"step \d+, t = [0-9.]+ s: moorings, line 'stern'"):
        c.run(2.0)


class ConstantLoad:
    """A stand-in fluid that pushes every body with one constant force [N]."""

    name = "push"

    def __init__(self, force):
        self.force = np.asarray(force, float)

    def attach_bodies(self, bodies):
        self.n = bodies.n_bodies

    def set_body_kinematics(self, kin):
        pass

    def body_wrenches(self):
        return np.tile(self.force, (self.n, 1)), np.zeros((self.n, 3))

    def initialize(self, t0):
        pass

    def max_dt(self):
        return math.inf

    def advance(self, t, dt):
        pass

    def save_state(self):
        return None

    def load_state(self, state):
        pass


def tethered_body(lines, sites, force, t_end=6.0):
    xml = builders.scene(builders.box("b", (1.0, 1.0, 1.0), (0, 0, 0), mass=50.0, sites=sites), gravity=0.0)
    b = MujocoBodies(xml)
    # heavy damping through a stand-in: MuJoCo joint damping via the model
    b.model.dof_damping[:] = 200.0
    m = CatenaryMooring(lines)
    c = Coupler(bodies=b, fluid=ConstantLoad(force), moorings=[(m, list(sites))], dt=0.005)
    c.run(t_end)
    return b, m, c


@pytest.mark.long
def test_a_pulled_body_is_held_at_the_line_length():
    """Inextensible, nearly weightless line: the body stops with the chord at L
    (to the constraint's softness) and the tether carries the pull."""
    L, F = 10.0, 400.0
    line = MooringLine((-8.0, 0.0, -6.0), L, 1e-3, name="l")
    pull = F * np.array([0.8, 0.0, 0.6])  # along the chord, away from the anchor
    b, m, c = tethered_body([line], {"fl": (0.0, 0.0, 0.0)}, pull)
    fl = b.site_positions([b.site("fl")[0]])[0]
    chord = np.linalg.norm(fl - np.array([-8.0, 0.0, -6.0]))
    assert chord == pytest.approx(L, rel=1e-3)
    assert m.solution.state[0] == 3  # TAUT
    T = c.tether_tensions()["moorings.0"]
    # statics: tether along the chord balances F plus the (tiny) capped catenary pull
    e = (np.array([-8.0, 0.0, -6.0]) - fl) / chord
    total = T * e + m.fairlead_forces()[0]
    np.testing.assert_allclose(total + pull, 0.0, atol=2e-3 * F)


@pytest.mark.long
def test_two_taut_lines_share_a_load_as_statics_says():
    """A buoyant pull F up on a body held by two taut lines at different angles:
    T1 e1 + T2 e2 = -F (a two-bar truss), not Barreiro et al. 2016, Eq. 40's proportional split."""
    F = np.array([0.0, 0.0, 1000.0])
    a1, a2 = np.array([-6.0, 0.0, -8.0]), np.array([4.0, 0.0, -3.0])
    L1, L2 = 10.0, 5.0  # taut with the fairlead at the origin: T1 = 800 N, T2 = 600 N
    lines = [MooringLine(tuple(a1), L1, 1e-3, name="a"), MooringLine(tuple(a2), L2, 1e-3, name="b")]
    b, m, c = tethered_body(lines, {"f1": (0.0, 0.0, 0.0), "f2": (0.0, 0.0, 0.0)}, F)
    e1, e2 = -a1 / L1, -a2 / L2  # unit vectors anchor -> fairlead
    # T1 (-e1) + T2 (-e2) + F = 0 in the x-z plane
    A = -np.array([[e1[0], e2[0]], [e1[2], e2[2]]])
    T_exact = np.linalg.solve(A, -F[[0, 2]])
    T = c.tether_tensions()
    got = np.array([T["moorings.0"], T["moorings.1"]]) + m.fairlead_tensions()
    np.testing.assert_allclose(T_exact, [800.0, 600.0], rtol=1e-12)
    np.testing.assert_allclose(got, T_exact, rtol=5e-3)


def test_an_untethered_mooring_still_raises_at_taut():
    m = CatenaryMooring([MooringLine((0.0, -5.0), 6.0, 1.0)])
    with pytest.raises(TautLineError, match="attach the mooring to bodies through a Coupler"):
        m.set_fairlead_motion([[4.0, 0.0]])


def test_attachment_errors():
    xml = builders.scene(builders.box("b", (1.0, 1.0, 1.0), (0, 0, 0), mass=1.0, sites={"fl": (0, 0, 0)}))
    b = MujocoBodies(xml)
    m = CatenaryMooring([MooringLine((5.0, 0.0, -5.0), 12.0, 1.0), MooringLine((-5.0, 0.0, -5.0), 12.0, 1.0)])
    with pytest.raises(ConfigurationError, match="2 lines but 1 fairlead sites"):
        Coupler(bodies=b, moorings=[(m, ["fl"])])
    with pytest.raises(ConfigurationError, match="pass bodies="):
        Coupler(moorings=[(m, ["fl", "fl"])])
    with pytest.raises(InputError, match="no site named 'x'"):
        Coupler(bodies=b, moorings=[(m, ["fl", "x"])]).initialize()
    with pytest.raises(InputError, match="scheme 'implicit'"):
        Coupler(bodies=b, scheme="implicit")


def test_initialize_twice_adds_nothing_twice():
    xml = builders.scene(builders.box("b", (2.0, 1.0), (0, 0, 0), density=500.0, planar=True,
                                      sites={"fl": (1.0, 0.0, -0.5)}))
    b = MujocoBodies(xml)
    f = AnalyticFluid(added_mass={"b": [0.0, 300.0, 0.0]})
    m = CatenaryMooring([MooringLine((30.0, -20.0), 40.0, 100.0)])
    c = Coupler(bodies=b, fluid=f, moorings=[(m, ["fl"])])
    c.initialize()
    c.initialize()
    assert b.model.ntendon == 1 and b.model.dof_armature[1] == 300.0


def test_checkpoint_restart_reproduces_the_run():
    from cosim.validations import case_scene
    from cosim.validations.coupling import moored_box_scene

    with case_scene.built(moored_box_scene(True)) as built:
        c, b = built.coupler, built.bodies
        c.run(1.0)
        cp = c.save_state()
        c.run(2.0)
        ref = b.kinematics()
        c.load_state(cp)
        assert c.t == 1.0 and len(c.ledger) == cp["ledger"]
        c.run(2.0)
    for a, d in zip(b.kinematics(), ref):
        np.testing.assert_array_equal(a, d)


@pytest.mark.long
def test_moored_body_validation_quick():
    rec = run("moored-body", quick=True)
    assert rec["passed"], rec["metrics"]
    assert rec["metrics"]["position_error"]["z_m"] < 1e-4


def test_participants_share_one_gravity():
    """A fluid and bodies that fall differently are refused at initialisation, naming both."""
    b = MujocoBodies(builders.scene(builders.box("b", (1.0, 1.0), (0, 0, 0), density=500.0, planar=True),
                                    gravity=9.81))
    c = Coupler(bodies=b, fluid=AnalyticFluid(g=9.80665))
    with pytest.raises(ConfigurationError, match=r"fluid 'fluid' has g = 9.80665 m/s\^2 along -z, bodies 'bodies' "
                                                 r"\[0.0, 0.0, -9.81\]"):
        c.initialize()


def test_explicit_loads_held_over_sub_steps_are_warned_of(caplog):
    """The explicit scheme over a step of several MuJoCo sub-steps says so once, with the
    schemes that avoid it; the predictor-corrector, and the explicit scheme at a coupling
    step no longer than MuJoCo's, say nothing."""
    def run_with(scheme, dt=None):
        b = MujocoBodies(builders.scene(builders.box("p", (2.0, 1.0), (0, 0, 0.05), density=500.0, planar=True)))
        c = Coupler(bodies=b, fluid=AnalyticFluid(), scheme=scheme, dt=dt)
        caplog.clear()
        with caplog.at_level("WARNING", logger="cosim.coupler"):
            c.run(0.5)
        return b, [r.getMessage() for r in caplog.records if "holds the loads" in r.getMessage()]

    b, said = run_with("explicit")
    assert len(said) == 1 and "sub-steps" in said[0] and "predictor-corrector" in said[0]
    assert not run_with("predictor-corrector")[1]
    assert not run_with("explicit", dt=b.dt_mujoco)[1]


def test_auto_scheme_fits_the_fluid():
    """scheme="auto" (the default): fluid-first with a fluid that reports the loads it
    exchanged (the SPH fluid), predictor-corrector with the analytic fluid."""
    class Exchanging(AnalyticFluid):
        def exchanged_wrenches(self):
            return self.body_wrenches()

    def bodies():
        return MujocoBodies(builders.scene(builders.box("b", (1.0, 1.0), (0, 0, 0), density=500.0, planar=True)))

    assert Coupler(bodies=bodies(), fluid=AnalyticFluid()).scheme == "predictor-corrector"
    assert Coupler(bodies=bodies(), fluid=Exchanging()).scheme == "fluid-first"
    assert Coupler(bodies=bodies()).scheme == "explicit"  # nothing gives the bodies loads


def test_without_loads_every_scheme_steps_the_bodies_alike(caplog):
    """No fluid, no mooring, no other participant: the explicit and predictor-corrector
    schemes give the same motion bit for bit (a box falling and bouncing on MuJoCo's
    ground), so "auto" takes the explicit one's single advance, and its held-loads warning,
    about loads nobody gives, is not said."""
    def run_with(scheme):
        xml = builders.scene(builders.box("b", (0.2, 0.1), (0, 0, 0.3), density=500.0, planar=True), floor_z=0.0)
        b = MujocoBodies(xml)
        c = Coupler(bodies=b, scheme=scheme, dt=0.01)
        caplog.clear()
        with caplog.at_level("WARNING", logger="cosim.coupler"):
            c.run(0.5)
        assert not [r for r in caplog.records if "holds the loads" in r.getMessage()]
        return b.kinematics().com.copy(), c.scheme

    (auto, scheme), (pc, _) = run_with("auto"), run_with("predictor-corrector")
    assert scheme == "explicit" and np.array_equal(auto, pc) and auto[0, 2] < 0.3 - 0.05


def test_a_non_finite_fluid_load_stops_the_run_naming_fluid_and_body():
    """Nothing non-finite crosses the coupler: the step, the fluid and the body are named."""
    from cosim.errors import InstabilityError

    class Broken(AnalyticFluid):
        def body_wrenches(self):
            F, T = super().body_wrenches()
            if self.t > 0.05:
                F[0, 2] = np.nan
            return F, T

    b = MujocoBodies(builders.scene(builders.box("hull", (1.0, 1.0), (0, 0, 0), density=500.0, planar=True)))
    c = Coupler(bodies=b, fluid=Broken(), dt=0.01)
    with pytest.raises(InstabilityError, match=r"step \d+, t = 0\.0\d+ s: fluid 'fluid' returned a non-finite load on "
                                               r"body 'hull' \(force \[ *0\. +0\. +nan\]"):
        c.run(1.0)
    assert c.t < 0.1
