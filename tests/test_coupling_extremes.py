"""Coupling at its extremes: light and heavy bodies, a line going taut in a storm, a
body on the tank floor, a body a few particles across, and checkpoint/restart.
Each case either runs and meets an analytic balance, or stops with a message that
names the step, the body and the cause."""

import math

import mujoco
import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.errors import ConfigurationError, InputError, InstabilityError
from cosim.validations.coupling import momentum_exchange_run, momentum_exchange_scene
from fluid.analytic import AnalyticFluid
from moorings import CatenaryMooring, MooringLine

G = 9.81


class InstantAddedMass:
    """A stand-in fluid of density ``rho`` whose load on each body is a steady push
    ``force`` [N] minus ``m_a`` times the body's acceleration over the last step (what
    an incompressible fluid does, lagged by one exchange as staggered coupling has it),
    with ``m_a`` the displaced mass ``rho V``."""

    name = "instant"

    def __init__(self, rho, force):
        self.rho, self.force = rho, np.asarray(force, float)
        self._v, self._dt = [], None

    def attach_bodies(self, bodies):
        self.n = bodies.n_bodies
        self.m_a = self.rho * np.array([8 * np.prod(g.size) for shapes in bodies.geoms() for g in shapes])

    def set_body_kinematics(self, kin):
        self._v = self._v[-1:] + [kin.velocity.copy()]

    def body_wrenches(self):
        F = np.tile(self.force, (self.n, 1))
        if len(self._v) == 2:
            F = F - self.m_a[:, None] * (self._v[1] - self._v[0]) / self._dt
        return F, np.zeros((self.n, 3))

    def initialize(self, t0):
        pass

    def max_dt(self):
        return math.inf

    def advance(self, t, dt):
        self._dt = dt

    def save_state(self):
        return None

    def load_state(self, state):
        pass


def light_box(ratio, light_body, rho=1000.0, F=1.0):
    """A 0.1 m cube of density ratio ``ratio`` pushed along x by ``F`` [N] in the stand-in fluid."""
    xml = builders.scene(builders.box("b", (0.1, 0.1, 0.1), (0, 0, 0), density=rho * ratio), gravity=0.0)
    b = MujocoBodies(xml)
    return Coupler(bodies=b, fluid=InstantAddedMass(rho, [F, 0, 0]), dt=1e-3, scheme="explicit",
                   light_body=light_body), b


def test_added_mass_instability_stops_the_run_with_body_step_ratio_and_remedy():
    """m_a / m = 10: the lagged reaction multiplies the acceleration by -10 each step;
    the watch stops it (period-2 growth) long before it overflows."""
    c, b = light_box(0.1, "none")
    with pytest.raises(InstabilityError, match=r"step \d+, t = [0-9.e-]+ s: body 'b': its acceleration changed sign "
                                               r"at each of the last 8 steps.* weighs 0.1 x the fluid it displaces, "
                                               r"light-body remedy 'none'"):
        c.run(1.0)
    assert c.steps < 20 and np.isfinite(b.data.qvel).all()  # stopped early; the state stays readable


def test_added_mass_remedy_gives_the_added_mass_acceleration(caplog):
    """With the displaced mass moved into the body's inertia and the lagged reaction
    handed back (cosim.added_mass), the body accelerates at F / (m + m_a) exactly,
    the incompressible answer, at a mass ratio 0.1. The choice is logged."""
    c, b = light_box(0.1, "added-mass")
    with caplog.at_level("INFO", logger="cosim.added_mass"):
        c.initialize()
    assert c.remedies == {"b": "added-mass"}
    assert "body 'b' mass / displaced fluid mass = 0.1 (explicit scheme, light_body='added-mass'): " \
           "light-body remedy added-mass, added inertia per dof [1. " in caplog.text
    c.run(0.5)
    m, m_a = 0.1, 1.0  # kg: 0.1 m cube at 100 and 1000 kg/m^3
    v = b.kinematics().velocity[0]
    np.testing.assert_allclose(v, [1.0 / (m + m_a) * 0.5, 0.0, 0.0], rtol=1e-9, atol=1e-12)


def test_auto_picks_nothing_for_a_fluid_whose_loads_carry_no_added_mass():
    b = MujocoBodies(builders.scene(builders.box("p", (2.0, 1.0), (0, 0, 0.05), density=50.0, planar=True)))
    c = Coupler(bodies=b, fluid=AnalyticFluid(), scheme="explicit")
    c.initialize()
    assert c.remedies == {"p": "none"} and c.added_mass.ratio[0] == pytest.approx(0.05)


def test_light_body_option_errors():
    b = MujocoBodies(builders.scene(builders.box("b", (0.1, 0.1, 0.1), (0, 0, 0), density=100.0)))
    with pytest.raises(InputError, match="light_body='implicit' is not one of auto, none, added-mass, subiterate"):
        Coupler(bodies=b, fluid=InstantAddedMass(1000.0, [0, 0, 0]), light_body="implicit")
    with pytest.raises(ConfigurationError, match="iterates the fluid-first scheme"):
        Coupler(bodies=b, fluid=InstantAddedMass(1000.0, [0, 0, 0]), light_body="subiterate").initialize()


# -- SPH: a 2-D tank, 0.4 m long, 0.2 m of water, dx = 2 cm (coarse, for speed) ------------

DX, L, D = 0.02, 0.4, 0.2


def tank(body_xml, scheme="fluid-first", light_body="auto", moorings=(), length=L, floor=True):
    from cosim.sph_fluid import SPHFluid
    from fluid.geometry import block, tank_walls
    from fluid.particles import Kind
    from fluid.solver import FluidConfig

    cfg = FluidConfig(dim=2, dx=DX, u_max=math.sqrt(G * D), c0_factor=20.0)
    walls = [(tank_walls(np.zeros(2), np.array([length, 0.3]), DX, 3), Kind.FIXED_WALL, 0)]
    bodies = MujocoBodies(builders.scene(body_xml, timestep=1e-3, floor_z=0.0 if floor else None))
    fluid = SPHFluid(cfg, block(np.zeros(2), np.array([length, D]), DX), walls, z_surface=D)
    return Coupler(bodies=bodies, fluid=fluid, scheme=scheme, light_body=light_body, moorings=moorings), bodies


def submerged(ratio, **kw):
    """A 0.10 x 0.06 m box of density ratio ``ratio`` released at rest, centre 0.1 m deep."""
    return tank(builders.box("box", (0.1, 0.06), (L / 2, 0.0, 0.1), density=1000.0 * ratio, planar=True), **kw)


def test_light_body_in_sph_fluid_first_oscillates_and_is_stopped():
    """Ratio 0.05, fluid-first, no remedy: the body's acceleration oscillates with a
    growing peak (benchmarks/density_ratio_sweep.py) and the watch stops the run."""
    c, b = submerged(0.05, light_body="none")
    with pytest.raises(InstabilityError, match=r"step \d+, t = [0-9.]+ s: body 'box': its acceleration oscillated "
                                               r"with a peak growing .* weighs 0.05 x the fluid it displaces, "
                                               r"light-body remedy 'none'"):
        c.run(0.1)
    assert np.isfinite(b.data.qvel).all()


@pytest.mark.parametrize("ratio", [0.05, 0.1])
def test_auto_sub_iterates_a_light_body_and_matches_the_explicit_scheme(ratio):
    """Ratios 0.05 and 0.1: "auto" sub-iterates fluid-first; the box then rises as
    with the explicit scheme (stable down to ~0.003 in the sweep): same heave velocity
    to 2 % after 0.06 s (at 0.05 beyond where the unremedied run was stopped, ~0.045 s)."""
    c, b = submerged(ratio)
    ref, rb = submerged(ratio, scheme="explicit")
    c.initialize()
    ref.initialize()
    assert c.remedies == {"box": "subiterate"} and ref.remedies == {"box": "none"}
    iters = []
    c.run(0.06, callback=lambda info: iters.append(c.subiterations))
    ref.run(0.06)
    w, w_ref = b.kinematics().velocity[0, 2], rb.kinematics().velocity[0, 2]
    assert w_ref > 0.2  # m/s: it rises (buoyancy ~19 g over body + added mass)
    assert w == pytest.approx(w_ref, rel=0.02)
    assert 2 < np.mean(iters) < 8  # fluid advances per step: the price of the remedy


def test_sub_iterations_that_do_not_converge_stop_the_run():
    from cosim.errors import ConvergenceError

    c, b = submerged(0.05)
    c.SUBITER_MAX = 1
    with pytest.raises(ConvergenceError, match=r"step 1, t = 0 s: body 'box': the sub-iterations did not converge "
                                               r"in 1 tries .* weighs 0.05 x the fluid it displaces"):
        c.run(0.01)


def test_heavy_body_rests_on_the_tank_floor():
    """Ratio 10, a MuJoCo floor at the tank bottom: the box sinks 2 mm onto it and
    comes to rest; MuJoCo's contact force plus the fluid's load then balance its
    weight, and the fluid pushes *down* by the water column over its top, since no
    water is under it (rho g (D - top) * width)."""
    c, b = tank(builders.box("box", (0.1, 0.06), (0.12, 0.0, 0.032), density=1e4, planar=True), length=0.24)
    c.run(0.2)
    m, d = b.model, b.data
    contact, f = 0.0, np.zeros(6)
    for i in range(d.ncon):
        mujoco.mj_contactForce(m, d, i, f)
        contact += f[0]  # normal force; the floor's normal is +z
    led = c.ledger.arrays()
    weight = b.masses()[0] * G
    assert abs(b.kinematics().velocity[0, 2]) < 2e-3
    assert contact + led["fluid_force"][-1, 0, 2] == pytest.approx(weight, rel=0.01)
    # the mean of the second half (-124 N against -137 N): the load still swings by about
    # 10 % as the water sloshes after the impact (means of its eighths: -112 ... -136 N)
    late = led["fluid_force"][len(led["t"]) // 2:, 0, 2].mean()
    assert late == pytest.approx(-1000.0 * G * (D - 0.06) * 0.1, rel=0.15)


def test_a_body_three_particles_across_floats():
    """A 6 cm square box at dx = 2 cm (3 particles across), density ratio 0.5, released
    at its equilibrium: it runs, keeps its orientation, and heaves within one particle
    spacing of the equilibrium (the resolution such a body has)."""
    c, b = tank(builders.box("box", (0.06, 0.06), (L / 2, 0.0, D), density=500.0, planar=True))
    z = []
    c.run(0.2, callback=lambda info: z.append(b.kinematics().com[0, 2]))
    assert np.abs(np.array(z) - D).max() < DX
    assert abs(b.data.qpos[2]) < 1e-9 and abs(b.kinematics().com[0, 0] - L / 2) < 1e-9


def test_checkpoint_restart_of_sph_body_and_catenary_is_bitwise(tmp_path):
    """SPH fluid + floating box + catenary line: going back to a checkpoint (in memory,
    and through a file into a freshly built coupler) repeats the run bit for bit."""
    def make():
        box = builders.box("box", (0.1, 0.06), (L / 2, 0.0, D), density=500.0, planar=True,
                           sites={"fl": (0.0, 0.0, -0.03)})
        line = CatenaryMooring([MooringLine((0.05, 0.0), 0.25, 5.0, name="l")])
        return tank(box, moorings=[(line, ["fl"])])

    c, b = make()
    c.run(0.02)
    cp = c.save_state()
    path = tmp_path / "run.ckpt"
    c.write_checkpoint(path)
    c.run(0.04)
    ref_kin, ref_pos = b.kinematics(), c.fluid.fluid.ps.pos.copy()
    ref_ledger = c.ledger.arrays()
    ref_fl = c.moorings[0].mooring.fairlead_forces().copy()
    assert np.abs(ref_fl).max() > 0.1  # N: the line pulls
    c.load_state(cp)
    assert c.t == 0.02
    c.run(0.04)
    for a, r in zip(b.kinematics(), ref_kin):
        np.testing.assert_array_equal(a, r)
    np.testing.assert_array_equal(c.fluid.fluid.ps.pos, ref_pos)
    fresh, fb = make()
    fresh.read_checkpoint(path)
    assert fresh.t == 0.02 and fresh.steps == cp["steps"]
    fresh.run(0.04)
    for a, r in zip(fb.kinematics(), ref_kin):
        np.testing.assert_array_equal(a, r)
    np.testing.assert_array_equal(fresh.fluid.fluid.ps.pos, ref_pos)
    np.testing.assert_array_equal(fresh.moorings[0].mooring.fairlead_forces(), ref_fl)
    # the ledger of the restarted run holds the steps before the checkpoint too
    assert len(ref_ledger["t"]) == fresh.steps
    for k, v in fresh.ledger.arrays().items():
        np.testing.assert_array_equal(v, ref_ledger[k])
    path.write_bytes(b"not a checkpoint")
    with pytest.raises(InputError, match=r"run.ckpt is not a checkpoint \(not an HDF5 file\)"):
        fresh.read_checkpoint(path)


class Storm(AnalyticFluid):
    """The analytic fluid plus a steady storm load [N] on every body (wind and current
    drag, held)."""

    def __init__(self, push, **kw):
        super().__init__(**kw)
        self.push = np.asarray(push, float)

    def body_wrenches(self):
        F, T = super().body_wrenches()
        return F + self.push, T


@pytest.mark.long
def test_a_storm_pulls_the_catenary_taut_and_the_tether_holds_the_box():
    """A 2 x 1 m box (500 kg/m^3, 1 m thick) on one slack inextensible catenary line
    (25 m, 50 N/m, anchor 20 m upwind and 10 m down) is pushed downwind by 10 kN:
    the line goes taut and MuJoCo's tether takes the load. At rest the chord is the
    line's length and the box is in equilibrium: tether T along the chord + the capped
    catenary pull + buoyancy and damping + push + weight = 0."""
    sites = {"fl": (-1.0, 0.0, -0.5)}
    xml = builders.scene(builders.box("box", (2.0, 1.0), (0.0, 0.0, 0.0), density=500.0, planar=True, sites=sites),
                         timestep=2e-3)
    b = MujocoBodies(xml)
    push = np.array([1e4, 0.0, 0.0])
    fluid = Storm(push, cells=8, linear_damping={"box": [3000.0, 0.0, 3000.0, 0.0, 3000.0, 0.0]})
    anchor = np.array([-20.0, 0.0, -10.0])
    line = CatenaryMooring([MooringLine((anchor[0], anchor[2]), 25.0, 50.0, name="l")])
    c = Coupler(bodies=b, fluid=fluid, moorings=[(line, ["fl"])])
    c.initialize()
    assert line.solution.state[0] != 3  # slack (not TAUT) at the start
    c.run(12.0)
    fl = b.site_positions([b.site("fl")[0]])[0]
    chord = np.linalg.norm(fl - anchor)
    assert chord == pytest.approx(25.0, rel=1e-3)
    assert line.solution.state[0] == 3  # TAUT
    T = c.tether_tensions()["moorings.0"]
    # N: the tether takes what the catenary law, capped at its taut shape (H = 6.9 kN
    # here), cannot: 3.3 kN
    assert T > 1e3
    led = c.ledger.arrays()
    e = (anchor - fl) / chord
    total = T * e + led["fluid_force"][-1, 0] + led["mooring_force"][-1, 0] + led["gravity"][-1, 0]
    np.testing.assert_allclose(total, 0.0, atol=5e-3 * push[0])
    assert np.abs(b.kinematics().velocity).max() < 1e-3


@pytest.mark.long
def test_a_heavy_body_without_a_floor_stops_with_a_message_not_a_crash():
    """Ratio 10 with no MuJoCo floor: only the SPH wall holds the box, and at dx = 2 cm
    it sinks through; the run stops naming the step, the body and the fix."""
    c, b = tank(builders.box("box", (0.1, 0.06), (L / 2, 0.0, 0.06), density=1e4, planar=True), floor=False)
    with pytest.raises(InstabilityError, match=r"step \d+, t = [0-9.]+ s: fluid 'fluid' could not place the bodies' "
                                               r"particles .*'box' at .* needs a floor to rest on"):
        c.run(0.5)


def test_sub_iterated_fluid_first_keeps_momentum_to_round_off():
    """A free light box (100 kg/m^3, ratio 0.1) hits a blob of SPH water with no
    gravity and no walls, sub-iterated: the bodies still receive exactly the impulse
    the fluid exchanged, so the linear and angular momentum of fluid + box (about the
    origin, per metre) stay constant to round-off while the water slows and spins it."""
    scene = momentum_exchange_scene(values=[f"fluid.dx={DX}", "bodies[0].density=100.0", "bodies[0].size=[0.06, 0.06]",
                                            "bodies[0].pos=[0.06, 0.17]", 'coupling.light_body="subiterate"'])
    r = momentum_exchange_run(scene, 150)
    vx, omega = r["body_vx_m_s"][1], r["body_omega_rad_s"][1]
    assert vx < 0.4 and abs(omega) > 0.1  # the water slowed and spun the box
    assert r["max_subiterations"] > 1
    assert r["linear_drift"] < 1e-12
    assert r["angular_drift"] < 1e-12
