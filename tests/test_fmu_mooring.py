"""FMUMooring: an FMU as a mooring participant; the exported catenary FMU plugged
back in gives the native law's fairlead forces along a prescribed trajectory."""

import logging
import math

import numpy as np
import pytest

from cosim.errors import InputError, SolverError, TautLineError
from cosim.protocol import Mooring, check_participant
from moorings.catenary_mooring import CatenaryMooring
from moorings.fmu_export import catenary_fmu_variable_map, export_catenary_fmu
from moorings.line import MooringLine
from conftest import requires_cc

pytestmark = requires_cc


def spread_mooring():
    """Three 3-D lines 120 degrees apart on a body: two elastic, one inextensible."""
    lines, fairleads_b = [], []
    for i, (EA, L) in enumerate(((None, 150.0), (2e8, 150.0), (5e7, 155.0))):
        az = 2 * math.pi * i / 3
        c, s = math.cos(az), math.sin(az)
        lines.append(MooringLine((120 * c, 120 * s, -60.0), L, 900.0, EA=EA, name=f"leg {i}"))
        fairleads_b.append((8 * c, 8 * s, -5.0))
    return lines, np.array(fairleads_b)


def fairleads_at(t, fb):
    """A prescribed body motion: surge, sway, heave and yaw oscillations (body at the origin)."""
    x, y, z = 25 * math.sin(0.3 * t), 10 * math.sin(0.2 * t + 1.0), 3 * math.sin(0.5 * t)
    yaw = 0.2 * math.sin(0.25 * t)
    R = np.array([[math.cos(yaw), -math.sin(yaw), 0], [math.sin(yaw), math.cos(yaw), 0], [0, 0, 1]])
    return fb @ R.T + np.array([x, y, z])


@pytest.fixture(scope="module")
def fmu3(tmp_path_factory):
    lines, fb = spread_mooring()
    return export_catenary_fmu(lines, tmp_path_factory.mktemp("fmu") / "spread.fmu", fairleads=fb)


def test_round_trip_equals_native_law_along_trajectory(fmu3):
    lines, fb = spread_mooring()
    from moorings.fmu_mooring import FMUMooring

    m = FMUMooring(fmu3, lines, catenary_fmu_variable_map(lines), fairleads=fb)
    check_participant(m, Mooring)
    native = CatenaryMooring(lines, fairleads=fb)
    m.initialize(0.0)
    native.initialize(0.0)
    dt, worst, states = 0.05, 0.0, set()
    for k in range(400):  # 20 s
        t = k * dt
        pos = fairleads_at(t, fb)
        m.set_fairlead_motion(pos)
        native.set_fairlead_motion(pos)
        f, g = m.fairlead_forces(), native.fairlead_forces()
        worst = max(worst, float(np.max(np.abs(f - g)) / np.max(np.abs(g))))
        states.update(int(s) for s in native.solution.state)
        T = m.get([f"leg_{i}.tension" for i in range(3)])
        worst = max(worst, float(np.max(np.abs(T - native.fairlead_tensions()) / native.fairlead_tensions())))
        m.advance(t, dt)
        native.advance(t, dt)
    assert worst <= 1e-9, worst
    assert m.t == pytest.approx(20.0)
    assert states == {0, 1, 2}  # the trajectory takes leg 0 from resting to fully lifted (0.85 m short of taut)
    m.close()


def test_template_map_n_lines_and_checkpoints(tmp_path):
    from moorings.fmu_mooring import FMUMooring

    lines = [MooringLine((-40.0, -10.0), 50.0, 80.0, EA=1e6), MooringLine((40.0, -10.0), 50.0, 80.0)]  # line0, line1
    path = export_catenary_fmu(lines, tmp_path / "two.fmu")
    m = FMUMooring(path, 2, {"positions": "{line}.fairlead.{axis}", "forces": "{line}.force.{axis}"}, dim=2,
                   parameters={"line1.length": 55.0})
    m.set_fairlead_motion([[-5.0, 2.0], [5.0, 2.0]])
    m.initialize(1.0)
    # the parameter reached the FMU: line1 is 55 m long
    lines55 = [lines[0], MooringLine((40.0, -10.0), 55.0, 80.0)]
    ref = CatenaryMooring(lines55, fairleads=[[-5.0, 2.0], [5.0, 2.0]]).fairlead_forces()
    np.testing.assert_array_equal(m.fairlead_forces(), ref)
    m.advance(1.0, 0.5)
    snap = m.save_state()
    f1 = m.fairlead_forces()
    m.set_fairlead_motion([[5.0, 2.0], [-5.0, 2.0]])  # both lines now partly lifted
    m.advance(1.5, 0.5)
    assert not np.array_equal(m.fairlead_forces(), f1)
    m.load_state(snap)
    assert m.t == 1.5
    np.testing.assert_array_equal(m.fairlead_forces(), f1)
    m.close()
    with pytest.raises(InputError, match="closed"):
        m.fairlead_forces()


def test_errors_are_clear(fmu3, caplog):
    from moorings.fmu_mooring import FMUMooring

    lines, fb = spread_mooring()
    vmap = catenary_fmu_variable_map(lines)
    with pytest.raises(InputError, match="no variable"):
        FMUMooring(fmu3, lines, {"positions": "{line}.pos.{axis}", "forces": vmap["forces"]})
    with pytest.raises(InputError, match="needs Real inputs"):
        FMUMooring(fmu3, lines, {"positions": vmap["forces"], "forces": vmap["forces"]})
    with pytest.raises(InputError, match=r"\(3, 3\)"):
        FMUMooring(fmu3, lines, {"positions": vmap["positions"][:2], "forces": vmap["forces"]})
    with pytest.raises(InputError, match="not a Real parameter"):
        FMUMooring(fmu3, lines, vmap, parameters={"nope": 1.0})
    with pytest.raises(InputError, match="no FMU file"):
        FMUMooring(fmu3.with_name("missing.fmu"), lines, vmap)
    m = FMUMooring(fmu3, lines, vmap)
    with pytest.raises(InputError, match="fairlead positions are not set"):
        m.initialize(0.0)
    m.set_fairlead_motion(fb)
    m.initialize(0.0)
    with pytest.raises(InputError, match="line 'leg 1'.*not finite"):
        m.set_fairlead_motion(np.where(np.arange(9).reshape(3, 3) == 4, np.nan, fb))
    # the inextensible leg 0 pulled beyond its length: TautLineError with the FMU's message
    far = fb.copy()
    far[0] = (120 - 170.0, 0.0, -5.0)
    m.set_fairlead_motion(far)
    with caplog.at_level(logging.ERROR, logger="moorings.fmu_mooring"):
        with pytest.raises(TautLineError, match="line 'leg_0'.*taut"):
            m.fairlead_forces()
    assert any("taut" in r.getMessage() for r in caplog.records)
    # recoverable: back inside, forces as the native law
    m.set_fairlead_motion(fb)
    np.testing.assert_array_equal(m.fairlead_forces(), CatenaryMooring(lines, fairleads=fb).fairlead_forces())
    # a fairlead below the seabed is a SolverError from the FMU naming the line
    low = fb.copy()
    low[2, 2] = -70.0
    m.set_fairlead_motion(low)
    with pytest.raises(SolverError, match="leg_2.*below the seabed"):
        m.advance(0.0, 0.1)
    m.close()


def test_messages_reach_the_right_instance(fmu3, tmp_path):
    """fmpy keeps one logger per process: each FMUMooring still gets its own FMU's messages."""
    from moorings.fmu_mooring import FMUMooring

    lines, fb = spread_mooring()
    a = FMUMooring(fmu3, lines, catenary_fmu_variable_map(lines), fairleads=fb, name="first")
    a.initialize(0.0)
    lines2 = [MooringLine((-40.0, -10.0), 50.0, 80.0, name="solo")]
    b = FMUMooring(export_catenary_fmu(lines2, tmp_path / "solo.fmu"), lines2, catenary_fmu_variable_map(lines2),
                   fairleads=[[0.0, 0.0]], name="second")
    b.initialize(0.0)
    far = fb.copy()
    far[0] = (120 - 170.0, 0.0, -5.0)
    a.set_fairlead_motion(far)
    with pytest.raises(TautLineError, match="first.*leg_0"):
        a.fairlead_forces()
    b.set_fairlead_motion([[-40.0 + 60.0, 0.0]])  # 'solo' (inextensible, 50 m) asked to span 60 m
    with pytest.raises(TautLineError, match="second.*solo"):
        b.fairlead_forces()
    assert all("leg_0" in t for _, t in a.messages) and all("solo" in t for _, t in b.messages)
    a.close()
    b.close()


@pytest.mark.long
def test_same_body_motion_in_a_coupled_scene(fmu3):
    """Issue 6 round trip: the exported FMU in place of CatenaryMooring in a coupled MuJoCo
    scene (the coupler's default scheme, which rolls participants back with save/load_state)
    gives the same body motion, to 1e-9."""
    pytest.importorskip("mujoco")
    from bodies import builders
    from bodies.mujoco_bodies import MujocoBodies
    from cosim.coupler import Coupler
    from moorings.fmu_mooring import FMUMooring

    lines, fb = spread_mooring()
    sites = {f"f{i}": tuple(fb[i]) for i in range(3)}
    xml = builders.scene(builders.box("hull", (16.0, 16.0, 10.0), (0, 0, 0), mass=2e6, sites=sites), gravity=0.0)
    tracks = []
    for model in (CatenaryMooring(lines), FMUMooring(fmu3, lines, catenary_fmu_variable_map(lines))):
        bodies = MujocoBodies(xml)
        bodies.data.qvel[0] = 1.5  # surge towards leg 0's anchor: the moorings pull the hull back
        c = Coupler(bodies=bodies, moorings=[(model, list(sites))], dt=0.05)
        com = []
        c.run(15.0, callback=lambda info: com.append(bodies.kinematics().com[0].copy()))
        tracks.append(np.array(com))
    a, b = tracks
    assert a.shape == b.shape and len(a) >= 300
    assert np.ptp(a[:, 0]) > 5.0  # the hull really moved
    np.testing.assert_allclose(b, a, rtol=0, atol=1e-9 * np.abs(a).max())
