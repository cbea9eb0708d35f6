"""Bodies and dynamic mooring lines advanced together (Coupler(lines="subiterate")): the
scheme against its closed form on a body pulled by a dashpot, its failure message, the
dynamic models' side of it (MoorDyn driven to the step's end, the mean forces) and a
restart from a checkpoint."""

import math

import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.errors import ConvergenceError

M, DT = 100.0, 0.01  # kg, s


class Dashpot:
    """A dynamic 'line' that is a linear dashpot c [N s/m] at its fairlead: over a step its
    mean force is -c (x1 - x0) / dt whatever the path, at the step's end -c v1."""

    name, n_lines, dim, dynamic = "dashpot", 1, 3, True

    def __init__(self, c: float, noise: float = 0.0):
        self.c, self.noise, self.tries = c, noise, 0

    def initialize(self, t0):
        self.x0 = self.x1.copy()
        self.end, self.mean = -self.c * self.v1, -self.c * self.v1

    def max_dt(self):
        return math.inf

    def set_fairlead_motion(self, positions, velocities=None):
        self.x1, self.v1 = np.array(positions, float), np.array(velocities, float)

    def advance(self, t, dt):
        self.tries += 1
        self.mean = -self.c * (self.x1 - self.x0) / dt + self.noise * (-1) ** self.tries
        self.end, self.x0 = -self.c * self.v1, self.x1.copy()

    def fairlead_forces(self):
        return self.end.copy()

    def mean_fairlead_forces(self):
        return self.mean.copy()

    def save_state(self):
        return self.x0.copy(), self.x1.copy(), self.v1.copy(), self.end.copy(), self.mean.copy()

    def load_state(self, s):
        self.x0, self.x1, self.v1, self.end, self.mean = (a.copy() for a in s)


def pulled_body(y: float, lines: str, noise: float = 0.0):
    """A free 100 kg body moving at 1 m/s along x, no gravity, its fairlead at its centre on a
    dashpot of c = y M / dt (y: the dashpot's rate times the step)."""
    xml = builders.scene(builders.box("b", (1.0, 1.0, 1.0), (0, 0, 0), mass=M, sites={"fl": (0, 0, 0)}), gravity=0.0)
    b = MujocoBodies(xml)
    b.data.qvel[0] = 1.0
    line = Dashpot(y * M / DT, noise)
    c = Coupler(bodies=b, moorings=[(line, ["fl"])], dt=DT, scheme="explicit", lines=lines)
    return c, b, line


@pytest.mark.parametrize("y", [0.5, 3.0])
def test_a_body_on_a_dashpot_slows_by_the_trapezoid_rule_when_sub_iterated(y):
    """Held over the step, the dashpot's force at the start gives v' = (1 - y) v (unstable
    beyond y = 2: at y = 3 the speed doubles each step); advanced together until the body's
    force is the dashpot's mean over the step, -c (x1 - x0) / dt with the body's exact motion
    under a constant force (RK4), v' = (1 - y / 2) / (1 + y / 2) v: stable at any y."""
    for lines, r in (("subiterate", (1 - y / 2) / (1 + y / 2)), ("explicit", 1 - y)):
        c, b, line = pulled_body(y, lines)
        v = []
        for k in range(1, 5):
            c.run(k * DT)
            v.append(b.kinematics().velocity[0, 0])
        assert v == pytest.approx([r ** k for k in range(1, 5)], rel=2e-3 if lines == "subiterate" else 1e-9), lines
        if lines == "subiterate":
            assert 2 <= c.line_iterations <= 6  # a scalar linear map: Aitken's secant solves it in a few tries
            impulse = sum(c.ledger.arrays()["mooring_force"][:, 0, 0]) * DT  # what the ledger booked on the body
            assert impulse == pytest.approx(b.kinematics().velocity[0, 0] * M - M, rel=1e-9)


def test_sub_iterations_that_do_not_settle_stop_the_run_naming_the_line():
    c, _, _ = pulled_body(0.5, "subiterate", noise=100.0)  # its mean force flips by 200 N at every try
    with pytest.raises(ConvergenceError, match=r"mooring 'dashpot', line 0 \(site 'fl'\): the bodies and the dynamic "
                                               r"lines did not agree on the line's mean force within 30 advances.*"
                                               r"smaller coupling step.*lines='explicit'"):
        c.run(DT)


def test_moordyn_driven_to_the_step_end_ends_on_the_fairlead_given_and_reports_the_mean_force():
    """Standalone, the motion given is the fairlead's at the step's start, moving on with its
    velocity; after drive_to_step_end() (what the coupler calls) it is the state at the
    step's end, reached in a straight line. The mean force is the trapezoid rule's."""
    pytest.importorskip("moordyn")
    from moorings import MooringLine
    from moorings.moordyn_mooring import MoorDynMooring

    line = MooringLine((60.0, 0.0, -40.0), 80.0, 900.0, EA=2e8, mass_per_length=110.0, name="leg")
    fb = np.array([[5.0, 0.0, -5.0]])
    step, vel = np.array([[0.3, 0.0, 0.1]]), np.array([[2.0, 0.0, 0.0]])
    for drive, end in ((False, fb + step + 0.1 * vel), (True, fb + step)):
        md = MoorDynMooring([line], fairleads=fb)
        md.initialize(0.0)
        if drive:
            md.drive_to_step_end()
        f0 = md.fairlead_forces()
        md.set_fairlead_motion(fb + step, vel)
        md.advance(0.0, 0.1)
        assert md.nodes()[0][-1] == pytest.approx(end[0], abs=1e-9), drive
        assert md.mean_fairlead_forces() == pytest.approx(0.5 * (f0 + md.fairlead_forces()), rel=1e-12)
        assert abs(md.fairlead_forces()[0, 0] - f0[0, 0]) > 1e3  # the line was pulled: the test sees a change
        md.close()


def test_a_run_with_sub_iterated_lines_restarts_from_a_checkpoint_exactly(tmp_path):
    """Barreiro et al. 2016's base on SPH cables: 0.1 s, a checkpoint, 0.1 s more; back to the checkpoint
    and the same 0.1 s again give the same bodies and lines to the last bit."""
    from pathlib import Path

    from cosim.scene import Scene
    from cosim.scene.build import build

    wt = Path(__file__).resolve().parents[1] / "examples" / "wind_turbine_base.toml"
    c = build(Scene.from_toml(wt).with_values(["moorings.model=sph-cable"]), tmp_path).coupler
    c.run(0.1)
    state = c.save_state()
    c.run(0.2)
    first = (c.bodies.kinematics().com.copy(), c.moorings[0].mooring.fairlead_forces(), c.line_iterations)
    c.load_state(state)
    c.run(0.2)
    assert np.array_equal(c.bodies.kinematics().com, first[0])
    assert np.array_equal(c.moorings[0].mooring.fairlead_forces(), first[1]) and c.line_iterations == first[2]


def test_a_dynamic_line_whose_mean_force_is_not_finite_stops_the_run_naming_it():
    from cosim.errors import InstabilityError

    c, _, _ = pulled_body(0.5, "subiterate", noise=float("nan"))
    with pytest.raises(InstabilityError, match=r"step 1, t = 0 s: .*mooring 'dashpot' returned a non-finite force "
                                               r"\[nan nan nan\] on the fairlead of its line 0 \(site 'fl'\)"):
        c.run(DT)


@pytest.mark.long
def test_a_light_body_on_a_dynamic_line_in_sph_water_rises_at_the_lines_terminal_speed():
    """A submerged 2-D box of density ratio 0.1 (sub-iterated with the SPH fluid) held by a
    dashpot line (dynamic, sub-iterated inside each of the fluid's tries) rises steadily at
    the speed where the dashpot balances the fluid's lift less its weight, (F_z - m g) / c,
    after ~7 time constants (M + m_a) / c; both sub-iterations take several tries. (The lift is
    the SPH fluid's at 3 particles across the box, 1.3 times Archimedes' (rho - rho_b) A g.)"""
    from test_coupling_extremes import L, tank

    ratio, B, H = 0.1, 0.1, 0.06
    c_line = 1000.0 * (1 - ratio) * B * H * 9.81 / 0.05  # N s/m per metre: 0.05 m/s at Archimedes' lift
    box = builders.box("box", (B, H), (L / 2, 0.0, 0.1), density=1000.0 * ratio, planar=True,
                       sites={"fl": (0.0, 0.0, 0.0)})
    c, b = tank(box, moorings=[(Dashpot(c_line), ["fl"])])
    c.initialize()
    assert c.remedies == {"box": "subiterate"} and c.lines == "subiterate"
    tries, w = [], []
    c.run(0.06, callback=lambda info: (tries.append((c.subiterations, c.line_iterations)),
                                       w.append(b.kinematics().velocity[0, 2])))
    led = c.ledger.arrays()
    lift = (led["fluid_force"][-10:, 0, 2] + led["gravity"][-10:, 0, 2]).mean()
    assert np.ptp(w[-10:]) < 0.01 * w[-1]  # steady
    assert w[-1] == pytest.approx(lift / c_line, rel=0.01)
    assert max(t[0] for t in tries) >= 2 and max(t[1] for t in tries) >= 2  # both sub-iterated
