"""The analytic fluid: buoyancy, damping and added mass on MuJoCo bodies."""

import math

import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.errors import InputError
from fluid.analytic import AnalyticFluid

RHO, G = 1000.0, 9.81


def floating(body_xml, **fluid_kw):
    b = MujocoBodies(builders.scene(body_xml, gravity=G, timestep=2e-3))
    f = AnalyticFluid(rho=RHO, g=G, **fluid_kw)
    return b, f, Coupler(bodies=b, fluid=f)


@pytest.mark.parametrize("z, expected", [(0.3, 0.2), (0.0, 0.5), (-0.6, 1.0), (0.8, 0.0)])
def test_buoyancy_of_a_level_box_is_exact(z, expected):
    """A 2 x 1 x 1 m box, 1 m tall, centre at z: submerged height clip(0.5 - z, 0, 1)."""
    b, f, c = floating(builders.box("b", (2.0, 1.0, 1.0), (0, 0, z), density=500.0))
    c.initialize()
    F, T = f.body_wrenches()
    assert F[0, 2] == pytest.approx(RHO * G * 2.0 * expected, rel=1e-12, abs=1e-9)
    assert np.abs(T).max() < 1e-6 * max(F[0, 2], 1)


@pytest.mark.parametrize("kind", ["sphere", "cylinder"])
def test_submerged_volume_is_the_exact_volume(kind):
    xml = (builders.sphere("s", 0.4, (0, 0, -2.0), density=800.0) if kind == "sphere"
           else builders.cylinder("s", 0.3, 1.5, (0, 0, -3.0), density=800.0))
    b, f, c = floating(xml)
    c.initialize()
    exact = 4 / 3 * math.pi * 0.4**3 if kind == "sphere" else math.pi * 0.09 * 1.5
    assert f.submerged_volume[0] == pytest.approx(exact, rel=1e-12)
    assert f.body_wrenches()[0][0, 2] == pytest.approx(RHO * G * exact, rel=1e-12)


def test_tilted_planar_box_has_the_polygon_area_and_a_righting_moment():
    """A 2 x 1 m planar box tilted 20 deg about y, centre on the surface: the
    submerged area is half the rectangle by symmetry; a wide box rights itself."""
    b, f, c = floating(builders.box("p", (2.0, 1.0), (0, 0, 0.0), density=500.0, planar=True, euler=(0, 20, 0)))
    c.initialize()
    assert f.submerged_volume[0] == pytest.approx(1.0, rel=2e-3)
    F, T = f.body_wrenches()
    # centre of buoyancy displaced towards the low side gives a moment opposing the tilt
    assert T[0, 1] < 0


def test_box_floats_at_archimedes_draft_and_heave_damps():
    h, rho_b = 1.0, 500.0
    b, f, c = floating(builders.box("p", (2.0, h), (0, 0, 0.3), density=rho_b, planar=True),
                       linear_damping={"p": [0.0, 0.0, 4000.0, 0.0, 0.0, 0.0]})
    c.run(20.0)
    z = b.kinematics().com[0, 2]
    draft = 0.5 * h - z
    assert draft == pytest.approx(rho_b / RHO * h, rel=1e-3)
    assert abs(b.kinematics().velocity[0, 2]) < 1e-4
    led = c.ledger.arrays()
    assert led["fluid_force"].shape == (c.steps, 1, 3)
    assert led["gravity"][0, 0, 2] == pytest.approx(-rho_b * h * 2.0 * G)


def heave_period(dt=None, h=1.0, rho_b=500.0, width=2.0, ma=600.0, T=6.0):
    b = MujocoBodies(builders.scene(builders.box("p", (width, h), (0, 0, 0.05), density=rho_b, planar=True),
                                    gravity=G, timestep=2e-3))
    f = AnalyticFluid(rho=RHO, g=G, added_mass={"p": [0.0, ma, 0.0]})
    c = Coupler(bodies=b, fluid=f, dt=dt)
    zs, ts = [], []
    c.run(T, callback=lambda info: (zs.append(b.kinematics().com[0, 2]), ts.append(info.t)))
    zs, ts = np.array(zs), np.array(ts)
    z_eq = 0.5 * h - rho_b / RHO * h
    up = np.flatnonzero((zs[:-1] < z_eq) & (zs[1:] >= z_eq))
    # interpolate the upward crossings of the equilibrium
    tc = ts[up] + (z_eq - zs[up]) / (zs[up + 1] - zs[up]) * (ts[up + 1] - ts[up])
    expected = 2 * math.pi * math.sqrt((rho_b * h * width + ma) / (RHO * G * width))
    return np.mean(np.diff(tc)), expected, f


@pytest.mark.long
def test_undamped_heave_period_matches_hydrostatics_with_added_mass():
    """T = 2 pi sqrt((m + m_a) / (rho g A_wp)) for a wall-sided box, at the default
    (stability-limited) coupling step, and converging as the step shrinks."""
    period, expected, f = heave_period()
    assert f.dt_limit == "hydrostatic stiffness"
    assert period == pytest.approx(expected, rel=1e-3)
    errs = [abs(heave_period(dt)[0] - expected) for dt in (0.016, 0.008, 0.004)]
    assert errs[0] > 3 * errs[1] > 9 * errs[2]  # second order in the coupling step
    assert errs[2] < 1e-4 * expected


def test_a_stiff_rotational_damping_bounds_the_step():
    """A pitch damping B [N m s] on a 2 x 1 m planar box (1 m thick) bounds the step to I / B,
    I its smallest principal moment (a safe side of the pitch's own), as a translational
    one bounds it to m / B: with B = 1e6 the damper, held over a step beyond 2 I / B,
    overshoots. At that step the box, its hull tilted 10 deg, turns back towards level
    slowly and monotonically (overdamped), where a step beyond the bound would flip the
    damper's sign every step."""
    B = 1e6
    b, f, c = floating(builders.box("p", (2.0, 1.0), (0, 0, 0.0), density=500.0, planar=True, euler=(0, 10, 0)),
                       linear_damping={"p": [0.0, 0.0, 0.0, 0.0, B, 0.0]})
    c.initialize()
    inertia = b.inertias()[0].min()
    assert inertia == pytest.approx(1000.0 * (1.0 ** 2 + 1.0 ** 2) / 12.0, rel=1e-9)  # about x: m (b^2 + c^2) / 12
    assert f.max_dt() == pytest.approx(inertia / B, rel=1e-12) and f.dt_limit == "damping"
    angles = []
    c.run(0.05, callback=lambda info: angles.append(b.kinematics().rotation[0][0, 2]))
    turn = np.diff(np.asarray(angles))
    assert np.all(np.isfinite(angles)) and (np.all(turn <= 0) or np.all(turn >= 0)) and abs(angles[-1]) < 1e-3


def test_bad_input():
    with pytest.raises(InputError, match="rho must be finite"):
        AnalyticFluid(rho=-1.0)
    b = MujocoBodies(builders.scene(builders.box("p", (1.0, 1.0), (0, 0, 0), density=500.0, planar=True)))
    with pytest.raises(InputError, match=r"unknown bodies \['q'\]"):
        Coupler(bodies=b, fluid=AnalyticFluid(linear_damping={"q": [0] * 6})).initialize()
    with pytest.raises(InputError, match="6 finite values"):
        Coupler(bodies=b, fluid=AnalyticFluid(linear_damping={"p": [1, 2]})).initialize()
