"""Line breaking (issue 18): a line whose fairlead tension passes its break load is reported
with the time, its name and the tension, and optionally released (it stops acting)."""

import math

import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.errors import InputError
from cosim.protocol import Mooring, check_participant
from fluid.analytic import AnalyticFluid, LinearWave
from moorings import CatenaryMooring, MooringLine
from moorings.breaking import BreakingMooring

RHO, G = 1025.0, 9.81
CHAIN = dict(length=25.0, weight=50.0, EA=5e7)


@pytest.mark.parametrize("value", [0.0, -1.4e6, math.nan, math.inf])
def test_break_load_must_be_positive(value):
    with pytest.raises(InputError, match=r"mooring line 'bow': break_load = .* N; it must be a finite number > 0 "
                                         r"\(the tension at which the line breaks; None: it never breaks\)"):
        MooringLine((0.0, -10.0), 25.0, 50.0, name="bow", break_load=value)
    m = CatenaryMooring([MooringLine((0.0, -10.0), 25.0, 50.0, name="bow")])
    with pytest.raises(InputError, match="line 'bow': break_load = .* N; give the tension at which the line breaks"):
        BreakingMooring(m, break_loads=[value])


def test_one_break_load_per_line():
    m = CatenaryMooring([MooringLine((0.0, -10.0), 25.0, 50.0), MooringLine((9.0, -10.0), 25.0, 50.0)])
    with pytest.raises(InputError, match="1 break loads for 2 lines; give one per line"):
        BreakingMooring(m, break_loads=[1e5])
    check_participant(BreakingMooring(m), Mooring)


def moored_box(break_loads=(None, None), release=False, H=1.5, T=6.0):
    """A 2-D box (2 x 1 m, half as dense as the water) on two elastic catenary lines in a
    wave of H [m], T [s] in 10 m; the fairleads' tensions oscillate with the wave."""
    box = builders.box("box", (2.0, 1.0), (0.0, 0.0, 0.0), density=500.0, planar=True,
                       sites={"left": (-1.0, 0.0, -0.5), "right": (1.0, 0.0, -0.5)})
    b = MujocoBodies(builders.scene(box, gravity=G, timestep=2e-3))
    f = AnalyticFluid(rho=RHO, g=G, waves=LinearWave(H, T, 10.0, ramp=T, g=G), cells=8,
                      linear_damping={"box": [800.0, 0.0, 1500.0, 0.0, 1500.0, 0.0]},
                      added_mass={"box": [500.0, 1000.0, 100.0]})
    lines = [MooringLine((-20.0, -10.0), name="left", break_load=break_loads[0], **CHAIN),
             MooringLine((20.0, -10.0), name="right", break_load=break_loads[1], **CHAIN)]
    m = CatenaryMooring(lines)
    if any(x is not None for x in break_loads):
        m = BreakingMooring(m, release=release)
    c = Coupler(bodies=b, fluid=f, moorings=[(m, ("left", "right"))])
    return c, m, b


def run(c, m, b, t_end):
    rows = []
    c.run(t_end, callback=lambda info: rows.append(
        (info.t, *np.linalg.norm(m.fairlead_forces(), axis=1), *b.kinematics().com[0])))
    return np.array(rows)


@pytest.mark.long
def test_a_break_is_reported_at_the_first_step_past_the_load_and_the_run_goes_on():
    """Report only: the run is the same as without break loads, bit for bit; the event is
    the first step at which the line's tension exceeds its break load."""
    c, m, b = moored_box()
    ref = run(c, m, b, 12.0)
    load = ref[0, 1] + 0.75 * (ref[:, 1].max() - ref[0, 1])  # above the pretension: passed once the wave is in
    c, m, b = moored_box((load, None))
    got = run(c, m, b, 12.0)
    np.testing.assert_array_equal(got, ref)
    first = int(np.argmax(ref[:, 1] > load))
    assert first > 10
    assert len(m.events) == 1  # once, though the tension passes the load every wave
    ev = m.events[0]
    assert (ev.line, ev.t, ev.tension, ev.break_load, ev.released) == ("left", ref[first, 0], ref[first, 1], load,
                                                                       False)
    assert ev.tension > load and ref[first - 1, 1] <= load
    assert m.released_lines() == []


@pytest.mark.long
def test_a_released_line_stops_acting():
    c, m, b = moored_box()
    ref = run(c, m, b, 12.0)
    load = ref[0, 1] + 0.75 * (ref[:, 1].max() - ref[0, 1])
    c, m, b = moored_box((load, None), release=True)
    got = run(c, m, b, 12.0)
    first = int(np.argmax(ref[:, 1] > load))
    assert first > 10
    np.testing.assert_array_equal(got[:first], ref[:first])  # the same run up to the break
    np.testing.assert_array_equal(got[first, 2:], ref[first, 2:])  # the step in which it broke
    assert m.events[0].released and m.released_lines() == [0] and m.events[0].t == ref[first, 0]
    assert np.all(got[first:, 1] == 0.0)  # the left line no longer pulls
    assert got[-1, 3] > ref[-1, 3] + 1.0  # the right line drags the box away to the right
    assert c.ledger.arrays()["mooring_force"][-1, 0, 0] > 0
    # a checkpoint keeps the break, and the run goes on from it bit for bit
    state = c.save_state()
    c2, m2, b2 = moored_box((load, None), release=True)
    c2.load_state(state)
    assert m2.released_lines() == [0] and m2.events == m.events
    np.testing.assert_array_equal(run(c, m, b, 14.0), run(c2, m2, b2, 14.0))


def test_a_released_tether_stays_released_after_a_checkpoint():
    net = (RHO - 500.0) * G * 1.0
    c, m, b = tension_leg(0.8 * net, release=True)
    c.run(1.0)
    assert m.released_lines() == [0]
    state = c.save_state()
    c2, m2, b2 = tension_leg(0.8 * net, release=True)
    c2.load_state(state)  # the tether is model data: the coupler releases it again
    c.run(3.0)
    c2.run(3.0)
    np.testing.assert_allclose(b.kinematics().com, b2.kinematics().com, rtol=1e-12, atol=1e-12)
    assert b2.kinematics().com[0, 2] > -1.0


def tension_leg(break_load=None, release=False):
    """A buoyant 3-D box held under the still water by a vertical inextensible line (a
    tension leg): the line is taut and its length constraint carries the net buoyancy."""
    box = builders.box("buoy", (1.0, 1.0, 1.0), (0.0, 0.0, -2.0), density=500.0, sites={"keel": (0.0, 0.0, -0.5)})
    b = MujocoBodies(builders.scene(box, gravity=G, timestep=2e-3))
    f = AnalyticFluid(rho=RHO, g=G, linear_damping={"buoy": [2000.0] * 3 + [500.0] * 3})
    m = CatenaryMooring([MooringLine((0.0, 0.0, -10.0), 7.6, 20.0, name="leg")])
    if break_load is not None:
        m = BreakingMooring(m, break_loads=[break_load], release=release)
    return Coupler(bodies=b, fluid=f, moorings=[(m, ("keel",))]), m, b


@pytest.mark.long
def test_the_tension_of_a_taut_lines_constraint_counts():
    net = (RHO - 500.0) * G * 1.0  # net buoyancy of the submerged box [N]
    c, m, b = tension_leg()
    c.run(6.0)
    catenary = np.linalg.norm(m.fairlead_forces()[0])  # capped near taut (CatenaryMooring's slack)
    total = catenary + c.tether_tensions()["moorings.0"]
    assert total == pytest.approx(net, rel=1e-6)  # the box is held: the line carries the net buoyancy
    assert catenary < 0.2 * net  # without its constraint's share, no break would be seen below
    c, m, b = tension_leg(0.8 * net, release=True)
    c.run(6.0)
    ev = m.events[0]
    # it breaks as it goes taut: the snap of an inextensible line is a constraint impulse (7 x net here)
    assert ev.line == "leg" and ev.released and ev.tension > 0.8 * net and ev.t < 0.5
    assert c.tether_tensions()["moorings.0"] == 0.0 and np.all(m.fairlead_forces() == 0.0)
    z = b.kinematics().com[0, 2]
    assert z > -1.0  # the box rose towards the surface once the leg broke
