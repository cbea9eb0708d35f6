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
    m = CatenaryMooring([MooringLine((10.0, 0.0, -5.0), 12.0, 1.0, name="stern")])
    c = Coupler(bodies=b, moorings=[(m, ["fl"])], dt=0.01)
    with pytest.raises(TautLineError, match=r"step \d+, t = [0-9.]+ s: moorings, line 'stern'"):
        c.run(2.0)


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


def test_checkpoint_restart_reproduces_the_run():
    def make():
        from cosim.validations.coupling import moored_box_scene
        bodies, fluid, mooring, sites = moored_box_scene(cells=8)
        return Coupler(bodies=bodies, fluid=fluid, moorings=[(mooring, sites)]), bodies
    c, b = make()
    c.run(1.0)
    cp = c.save_state()
    c.run(2.0)
    ref = b.kinematics()
    c.load_state(cp)
    assert c.t == 1.0 and len(c.ledger) == cp["ledger"]
    c.run(2.0)
    for a, d in zip(b.kinematics(), ref):
        np.testing.assert_array_equal(a, d)


def test_moored_body_validation_quick():
    rec = run("moored-body", quick=True)
    assert rec["passed"], rec["metrics"]
    assert rec["metrics"]["position_error"]["z_m"] < 1e-4
