"""The SPH fluid loading MuJoCo bodies (cosim.sph_fluid)."""

import math

import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.sph_fluid import SPHFluid
from fluid.geometry import block, tank_walls
from fluid.particles import Kind
from fluid.solver import FluidConfig

G = 9.81


def submerged_box(dx=0.01, L=0.4, H=0.3, D=0.25, box=(0.1, 0.05), centre=(0.2, 0.105)):
    cfg = FluidConfig(dim=2, dx=dx, u_max=math.sqrt(G * D), c0_factor=20.0)
    walls = [(tank_walls(np.zeros(2), np.array([L, H]), dx, 3), Kind.FIXED_WALL, 0)]
    bodies = MujocoBodies(builders.scene(builders.box("b", box, (centre[0], 0.0, centre[1]), density=2000.0,
                                                      planar=True)))
    f = SPHFluid(cfg, block(np.zeros(2), np.array([L, D]), dx), walls, z_surface=D)
    f.attach_bodies(bodies)
    f.set_body_kinematics(bodies.kinematics())
    f.initialize(0.0)
    return f, bodies


def test_a_held_submerged_body_feels_archimedes():
    """A box held still under water: vertical force rho g A (per metre), no side
    force, no torque, over 0.1 s of SPH (lattice-aligned box, dx = 1 cm)."""
    f, bodies = submerged_box()
    assert f.removed_overlap == 50  # the 10 x 5 cells of the box, no fluid left inside
    assert f.displaced_volume == pytest.approx(0.1 * 0.05)
    t, Fz, Fx, Ty = 0.0, [], [], []
    while t < 0.1:
        dt = f.max_dt()
        f.advance(t, dt)
        t += dt
        f.set_body_kinematics(bodies.kinematics())
        F, T = f.body_wrenches()
        Fz.append(F[0, 2])
        Fx.append(F[0, 0])
        Ty.append(T[0, 1])
    exact = 1000.0 * G * 0.1 * 0.05
    assert np.mean(Fz) == pytest.approx(exact, rel=0.01)
    assert abs(np.mean(Fx)) < 1e-9 * exact and abs(np.mean(Ty)) < 1e-9 * exact


def test_fluid_loads_move_with_the_body_pose():
    """Placing the body's particles from a pose: the group follows the body."""
    f, bodies = submerged_box()
    bodies.data.qpos[0] = 0.05  # slide 5 cm in x
    bodies.initialize(0.0)
    f.set_body_kinematics(bodies.kinematics())
    ps = f.fluid.ps
    sel = ps.group == f._g0
    assert ps.pos[sel, 0].mean() == pytest.approx(0.25, abs=1e-12)
    assert (f.fluid.moment_points[f._g0] == bodies.kinematics().com[0, [0, 2]]).all()


def test_momentum_is_exchanged_exactly_with_the_fluid_first_scheme():
    """A free box (no gravity, no walls) pushed at 0.5 m/s into a resting blob of
    SPH water: the fluid's momentum plus the body's is conserved to round-off with
    the fluid-first scheme; taking loads at the start of the step is not exact."""
    from cosim.coupler import Coupler

    def momentum_drift(scheme):
        dx = 0.01
        cfg = FluidConfig(dim=2, dx=dx, g=0.0, c0=20.0, domain_lo=(-1.0, -1.0), domain_hi=(2.0, 2.0))
        blob = block(np.array([0.1, 0.0]), np.array([0.3, 0.2]), dx)
        xml = builders.scene(builders.box("b", (0.05, 0.05), (0.07, 0.0, 0.105), density=800.0, planar=True),
                             gravity=0.0)
        bodies = MujocoBodies(xml)
        bodies.data.qvel[0] = 0.5  # towards the blob
        f = SPHFluid(cfg, blob)
        c = Coupler(bodies=bodies, fluid=f, scheme=scheme)
        M = bodies.masses()[0]

        def total():
            ps = f.fluid.ps
            fl = ps.kind == Kind.FLUID
            return (ps.mass[fl, None] * ps.vel[fl]).sum(axis=0)[0] + M * bodies.kinematics().velocity[0, 0]

        c.initialize()
        p0 = total()
        for _ in range(150):
            c.step(10.0)
        assert bodies.kinematics().velocity[0, 0] < 0.5  # the water slowed the box
        return abs(total() - p0) / abs(p0)

    assert momentum_drift("fluid-first") < 1e-12
    assert momentum_drift("explicit") > 1e-9
