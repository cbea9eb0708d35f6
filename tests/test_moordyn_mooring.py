"""MoorDynMooring: MoorDyn v2 behind the mooring interface (skipped without moordyn)."""

import math

import numpy as np
import pytest

from cosim.errors import InputError, SolverError
from cosim.protocol import Mooring, check_participant
from moorings.catenary_mooring import CatenaryMooring
from moorings.line import MooringLine
from moorings.moordyn_mooring import MoorDynMooring, moordyn_available

needs_moordyn = pytest.mark.skipif(not moordyn_available(),
                                   reason="the optional 'moordyn' package is not installed (pip install .[moordyn])")


def spread():
    """Three elastic 3-D lines, 120 degrees apart, anchors 60 m below the surface."""
    az = (0.0, 2 * math.pi / 3, 4 * math.pi / 3)
    lines = [MooringLine((120 * math.cos(a), 120 * math.sin(a), -60.0), 150.0, 900.0, EA=2e8, mass_per_length=110.0,
                         name=f"leg{i}") for i, a in enumerate(az)]
    fb = np.array([[8 * math.cos(a), 8 * math.sin(a), -5.0] for a in az])
    fb[:, 0] -= 10.0  # offset: leg0 taut-ish, legs 1 and 2 slacker
    return lines, fb


def _rel(f, g):
    return np.linalg.norm(f - g, axis=1) / np.linalg.norm(g, axis=1)


@needs_moordyn
def test_settles_to_the_catenary_3d():
    lines, fb = spread()
    md = MoorDynMooring(lines, fairleads=fb)
    check_participant(md, Mooring)
    md.initialize(0.0)
    for k in range(40):  # 2 s at rest after MoorDyn's own static initialisation
        md.advance(0.05 * k, 0.05)
    cat = CatenaryMooring(lines, fairleads=fb)
    err = _rel(md.fairlead_forces(), cat.fairlead_forces())
    assert np.all(err < 0.02), err  # lumped masses (20 segments) vs the exact catenary
    assert np.all(np.abs(md.fairlead_tensions() / cat.fairlead_tensions() - 1) < 0.02)
    assert md.t == pytest.approx(2.0)
    md.close()


@needs_moordyn
def test_settles_to_the_catenary_2d_with_a_water_level():
    # 2-D (x, z) lines in a frame whose free surface is at z = 100 m; a resting and a lifted line
    lines = [MooringLine((-80.0, 50.0), 100.0, 500.0, EA=5e7, diameter=0.12, name="left"),
             MooringLine((90.0, 50.0), 110.0, 500.0, EA=5e7, diameter=0.12, name="right")]
    fl = np.array([[-5.0, 90.0], [5.0, 90.0]])
    md = MoorDynMooring(lines, fairleads=fl, water_level=100.0)
    md.initialize(0.0)
    for k in range(30):
        md.advance(0.1 * k, 0.1)
    cat = CatenaryMooring(lines, fairleads=fl)
    f, g = md.fairlead_forces(), cat.fairlead_forces()
    assert f.shape == (2, 2)
    assert np.all(_rel(f, g) < 0.03), (f, g)
    assert np.all(f[:, 1] < 0) and f[0, 0] < 0 < f[1, 0]  # pulled down and towards each anchor
    md.close()


def _motion(t, fb, from_rest):
    """A slow surge of the fairleads (period 40 s, 4 m): position and velocity at t."""
    w = 2 * math.pi / 40.0
    if from_rest:  # starts with zero velocity
        return fb + np.array([4.0 * (1 - math.cos(w * t)), 0, 0]), np.tile([4.0 * w * math.sin(w * t), 0, 0], (3, 1))
    return fb + np.array([4.0 * math.sin(w * t), 0, 0]), np.tile([4.0 * w * math.cos(w * t), 0, 0], (3, 1))


@needs_moordyn
@pytest.mark.parametrize("given_velocities", [True, False])
def test_follows_slow_fairlead_motion_quasi_statically_and_restores_state(given_velocities):
    lines, fb = spread()
    md = MoorDynMooring(lines, fairleads=fb)
    md.initialize(0.0)
    cat = CatenaryMooring(lines)
    errs, t, k = [], 0.0, 0
    snap = after = None
    while t < 12.0 - 1e-9:
        dt = 0.05 if k % 3 else 0.0731  # the coupler's steps need not be multiples of MoorDyn's
        pos, vel = _motion(t, fb, from_rest=True)
        # without velocities MoorDyn gets a backward difference of the positions of consecutive steps
        md.set_fairlead_motion(pos, vel if given_velocities else None)
        md.advance(t, dt)
        t += dt
        k += 1
        cat.set_fairlead_motion(_motion(t, fb, from_rest=True)[0])
        errs.append(_rel(md.fairlead_forces(), cat.fairlead_forces()))
        if snap is None and t > 6.0:
            snap, t_snap, k_snap = md.save_state(), t, k
        elif snap is not None and after is None:
            after = md.fairlead_forces()
    errs = np.array(errs)
    # slow motion: drag and inertia add little to the quasi-static force (measured: max 4.6 %, mean 0.9-2.4 %;
    # 20 lumped segments of a slack line sit ~2 % from the exact catenary even at rest)
    assert errs.max() < 0.05 and np.all(errs.mean(axis=0) < 0.03), (errs.max(axis=0), errs.mean(axis=0))
    # restore the snapshot and repeat the next step: identical forces
    md.load_state(snap)
    assert md.t == t_snap
    dt = 0.05 if k_snap % 3 else 0.0731
    pos, vel = _motion(t_snap, fb, from_rest=True)
    md.set_fairlead_motion(pos, vel if given_velocities else None)
    md.advance(t_snap, dt)
    np.testing.assert_array_equal(md.fairlead_forces(), after)
    md.close()


@needs_moordyn
def test_errors_name_the_line():
    lines, fb = spread()
    inext = [MooringLine(lines[0].anchor, 150.0, 900.0, mass_per_length=110.0, name="chain")]
    with pytest.raises(InputError, match="line 'chain'.*elastic lines only.*EA"):
        MoorDynMooring(inext)
    with pytest.raises(InputError, match="line 'bare'.*mass per length"):
        MoorDynMooring([MooringLine(lines[0].anchor, 150.0, 900.0, EA=1e8, name="bare")])
    with pytest.raises(InputError, match="disagrees"):
        MoorDynMooring([MooringLine(lines[0].anchor, 150.0, 900.0, EA=1e8, mass_per_length=110.0, diameter=0.5)])
    with pytest.raises(InputError, match="one flat seabed"):
        MoorDynMooring([lines[0], MooringLine((0.0, 100.0, -50.0), 150.0, 900.0, EA=2e8, mass_per_length=110.0)])
    with pytest.raises(InputError, match="below the water level"):
        MoorDynMooring(lines, water_level=-80.0)
    md = MoorDynMooring(lines)
    with pytest.raises(InputError, match="fairlead positions are not set"):
        md.initialize(0.0)
    bad = fb.copy()
    bad[1, 2] = math.nan
    with pytest.raises(InputError, match="line 'leg1'.*not finite"):
        md.set_fairlead_motion(bad)
    md.set_fairlead_motion(fb)
    md.initialize(0.0)
    far = fb.copy()
    far[2] = (-3000.0, -3000.0, -5.0)  # leg2 yanked 4 km away in one step
    md.set_fairlead_motion(far)
    with pytest.raises(SolverError, match="line 'leg2' \\(MoorDyn line 3\\)"):
        md.advance(0.0, 0.05)
    md.close()


def test_missing_moordyn_is_a_clear_error(monkeypatch):
    import moorings.moordyn_mooring as mm

    monkeypatch.setattr(mm, "moordyn_available", lambda: False)
    lines, _ = spread()
    with pytest.raises(InputError, match=r"pip install"):
        mm.MoorDynMooring(lines)


@needs_moordyn
def test_two_systems_in_one_process_are_independent():
    lines, fb = spread()
    other = [MooringLine((-60.0, -40.0), 70.0, 400.0, EA=3e7, mass_per_length=50.0, name="solo")]

    def run(models, steps=20):
        out = {}
        for m in models:
            m.initialize(0.0)
        for k in range(steps):
            for m in models:
                m.advance(0.05 * k, 0.05)
        for m in models:
            out[m.name] = m.fairlead_forces()
            m.close()
        return out

    alone_a = run([MoorDynMooring(lines, fairleads=fb, name="a")])
    alone_b = run([MoorDynMooring(other, fairleads=[[0.0, 0.0]], name="b")])
    both = run([MoorDynMooring(lines, fairleads=fb, name="a"), MoorDynMooring(other, fairleads=[[0.0, 0.0]], name="b")])
    np.testing.assert_array_equal(both["a"], alone_a["a"])
    np.testing.assert_array_equal(both["b"], alone_b["b"])
    assert both["b"].shape == (1, 2) and both["b"][0, 0] < 0 and both["b"][0, 1] < 0


@needs_moordyn
def test_swaps_for_the_catenary_in_a_coupled_scene():
    """The same MooringLine list drives MoorDyn through the coupler (which hands it the fairlead
    velocities and rolls it back with save/load_state): a slow surge decay tracks the catenary's."""
    pytest.importorskip("mujoco")
    from bodies import builders
    from bodies.mujoco_bodies import MujocoBodies
    from cosim.coupler import Coupler

    lines, fb = spread()
    fb[:, 0] += 10.0  # spread() offsets the fairleads; here the hull itself sits at the origin
    sites = {f"f{i}": tuple(fb[i]) for i in range(3)}
    xml = builders.scene(builders.box("hull", (16.0, 16.0, 10.0), (0, 0, 0), mass=5e6, sites=sites), gravity=0.0)
    tracks = []
    for model in (CatenaryMooring(lines), MoorDynMooring(lines)):
        bodies = MujocoBodies(xml)
        bodies.data.qvel[0] = 0.5
        c = Coupler(bodies=bodies, moorings=[(model, list(sites))], dt=0.05)
        com = []
        c.run(10.0, callback=lambda info: com.append(bodies.kinematics().com[0, 0]))
        tracks.append(np.array(com))
    a, b = tracks
    assert np.ptp(a) > 2.0
    assert np.max(np.abs(b - a)) < 0.02 * np.ptp(a), (np.max(np.abs(b - a)), np.ptp(a))  # measured 0.7 %
