"""MuJoCo bodies participant and MJCF builders."""

import math

import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.errors import InputError, InstabilityError
from cosim.protocol import check_participant


def free_body_scene(gravity=0.0, **kw):
    return builders.scene(builders.box("b", (1.0, 1.0, 1.0), (0, 0, 0), mass=1.0, **kw), gravity=gravity,
                          integrator="RK4", timestep=1e-3)


def test_one_newton_on_one_kilogram_for_one_second_moves_half_a_metre():
    b = MujocoBodies(free_body_scene())
    check_participant(b)
    b.initialize(0.0)
    t = 0.0
    for _ in range(100):  # 100 coupling steps of 10 ms, 10 MuJoCo sub-steps each
        b.set_wrenches([[1.0, 0.0, 0.0]], [[0.0, 0.0, 0.0]])
        b.advance(t, 0.01)
        t += 0.01
    k = b.kinematics()
    assert b.substeps == 10
    assert k.com[0, 0] == pytest.approx(0.5, rel=1e-9)  # RK4 is exact for constant force
    assert k.velocity[0, 0] == pytest.approx(1.0, rel=1e-12)
    assert np.abs(k.com[0, 1:]).max() < 1e-12


def test_loads_are_cleared_after_each_step():
    b = MujocoBodies(free_body_scene())
    b.set_wrenches([[1.0, 0.0, 0.0]], [[0.0, 0.0, 0.0]])
    b.advance(0.0, 0.1)
    assert not b.data.xfrc_applied.any()
    v = b.kinematics().velocity[0, 0]
    b.advance(0.1, 0.1)  # no new load: coasts
    assert b.kinematics().velocity[0, 0] == pytest.approx(v, rel=1e-12)


def test_torque_about_com_spins_the_body():
    b = MujocoBodies(free_body_scene())
    I = 1.0 * (1.0**2 + 1.0**2) / 12  # unit cube, 1 kg
    b.set_wrenches([[0.0, 0.0, 0.0]], [[0.0, 0.0, 2.0]])
    b.advance(0.0, 0.5)
    k = b.kinematics()
    assert k.omega[0, 2] == pytest.approx(2.0 / I * 0.5, rel=1e-9)
    assert np.abs(k.velocity).max() < 1e-12  # a torque about the CoM does not move it


def test_planar_body_moves_only_in_the_xz_plane_and_is_one_metre_thick():
    b = MujocoBodies(builders.scene(builders.box("p", (2.0, 0.5), (0, 0, 0), density=500.0, planar=True),
                                    gravity=0.0))
    assert b.masses()[0] == pytest.approx(500.0 * 2.0 * 0.5 * 1.0)
    b.set_wrenches([[100.0, 50.0, 20.0]], [[3.0, 4.0, 5.0]])
    b.advance(0.0, 0.2)
    k = b.kinematics()
    assert k.com[0, 1] == 0.0 and k.velocity[0, 1] == 0.0
    assert k.omega[0, 0] == 0.0 and k.omega[0, 2] == 0.0 and k.omega[0, 1] != 0.0
    assert k.velocity[0, 0] > 0 and k.velocity[0, 2] > 0


def test_planar_cylinder_is_a_disc_in_the_xz_plane_and_keeps_its_joint_axes():
    b = MujocoBodies(builders.scene(builders.cylinder("c", 0.5, 3.0, (0, 0, 0), density=1000.0, planar=True),
                                    gravity=0.0))
    assert b.masses()[0] == pytest.approx(1000.0 * math.pi * 0.25 * 1.0)  # 1 m thick
    g = b.geoms()[0][0]
    np.testing.assert_allclose(g.rot[:, 2], [0.0, -1.0, 0.0], atol=1e-12)  # geom axis along y
    np.testing.assert_allclose(b.model.jnt_axis, [[1, 0, 0], [0, 0, 1], [0, 1, 0]])
    b.set_wrenches([[0.0, 0.0, 10.0]], [[0.0, 1.0, 0.0]])
    b.advance(0.0, 0.1)
    k = b.kinematics()
    assert k.velocity[0, 2] > 0 and k.velocity[0, 1] == 0.0 and k.omega[0, 1] > 0


def test_mass_and_inertia_come_from_the_geometry():
    b = MujocoBodies(builders.scene(builders.cylinder("c", 0.5, 2.0, (0, 0, 0), density=1000.0)))
    assert b.masses()[0] == pytest.approx(1000.0 * math.pi * 0.25 * 2.0, rel=1e-12)
    np.testing.assert_allclose(b.gravity_forces()[0], [0, 0, -9.81 * b.masses()[0]])


def test_save_and_load_state_re_steps_exactly():
    b = MujocoBodies(free_body_scene(gravity=9.81))
    b.set_wrenches([[1.0, 2.0, 3.0]], [[0.1, 0.2, 0.3]])
    b.advance(0.0, 0.05)
    s = b.save_state()
    for _ in range(2):
        b.load_state(s)
        b.set_wrenches([[0.5, 0.0, 0.0]], [[0.0, 0.3, 0.0]])
        b.advance(0.05, 0.05)
        out = b.kinematics()
        if _ == 0:
            first = out
    for a, c in zip(first, out):
        np.testing.assert_array_equal(a, c)


def test_sites_and_errors():
    xml = builders.scene(builders.box("b", (2.0, 1.0, 1.0), (1.0, 2.0, 3.0), mass=5.0, sites={"fl": (1.0, 0.0, 0.5)}))
    b = MujocoBodies(xml)
    sid, body = b.site("fl")
    assert body == 0
    np.testing.assert_allclose(b.site_positions([sid])[0], [2.0, 2.0, 3.5])
    with pytest.raises(InputError, match="no site named 'nope'"):
        b.site("nope")
    with pytest.raises(InputError, match="no body named 'x'"):
        MujocoBodies(xml, bodies=["x"])
    with pytest.raises(InputError, match="could not load"):
        MujocoBodies("<mujoco><worldbody><body><geom type='box'/></body></worldbody></mujoco>")
    with pytest.raises(InputError, match="does not exist"):
        MujocoBodies("no/such/file.xml")
    with pytest.raises(InputError, match="no movable body"):
        MujocoBodies("<mujoco><worldbody><geom type='plane' size='1 1 1'/></worldbody></mujoco>")
    with pytest.raises(InputError, match="shape"):
        b.set_wrenches(np.zeros((2, 3)), np.zeros((1, 3)))
    with pytest.raises(InstabilityError, match="non-finite force.*body 'b'"):
        b.set_wrenches([[np.nan, 0, 0]], [[0, 0, 0]])
    with pytest.raises(InputError, match="exactly one of density"):
        builders.box("q", (1, 1, 1), (0, 0, 0))
    with pytest.raises(InputError, match="size must be finite and > 0"):
        builders.box("q", (1, -1, 1), (0, 0, 0), mass=1.0)


def test_armature_adds_inertia_without_weight():
    b = MujocoBodies(builders.scene(builders.box("p", (1.0, 1.0), (0, 0, 0), mass=10.0, planar=True), gravity=0.0,
                                    integrator="RK4"))
    b.add_armature(0, [0.0, 10.0, 0.0])  # heave added mass = body mass
    b.set_wrenches([[20.0, 0.0, 20.0]], [[0.0, 0.0, 0.0]])
    b.advance(0.0, 1.0)
    v = b.kinematics().velocity[0]
    assert v[0] == pytest.approx(2.0, rel=1e-9) and v[2] == pytest.approx(1.0, rel=1e-9)
    with pytest.raises(InputError, match="3 degrees of freedom"):
        b.add_armature(0, [1.0, 2.0])
