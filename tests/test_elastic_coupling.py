"""The elastic cantilever (bodies/elastic.py) coupled to the SPH fluid (cosim/sph_fluid.py,
``SPHFluid(elastic=[beam])``): boundary particles on the deformed plate, the fluid's
force on each split between the two links that carry it. Momentum is exchanged exactly,
as for rigid bodies (tests/test_sph_bodies.py, validation case momentum-exchange)."""

import numpy as np
import pytest

from bodies import builders
from bodies.elastic import elastic_beam
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.sph_fluid import SPHFluid
from fluid.geometry import block
from fluid.particles import Kind
from fluid.solver import FluidConfig

PLATE = dict(length=0.08, thickness=0.012, E=1e6, rho=2500.0, n_elements=8)  # seed 002's plate


def blob_on_plate(dim, free_base=False, dx=0.004):
    """No gravity, no walls: a block of water moving at 1 m/s in +x hits the plate
    (clamped at x = 0.3 m, z = 0 to the world, or to a free 3 kg base)."""
    beam = elastic_beam("p", **PLATE, base=(0.3, 0.0, 0.0) if not free_base else (0.0, 0.0, 0.02),
                        width=1.0 if dim == 2 else 0.04)
    xml, names = beam.xml, beam.link_names
    if free_base:
        xml = ('<body name="base" pos="0.3 0 -0.02"><freejoint/><geom type="box" size="0.02 0.02 0.02" '
               'density="3000" contype="0" conaffinity="0"/>' + xml + '</body>')
        names = ["base", *names]
    bodies = MujocoBodies(builders.scene(xml, gravity=0.0), bodies=names)
    lo, hi = ([0.2, 0.0], [0.29, 0.06]) if dim == 2 else ([0.2, -0.02, 0.0], [0.29, 0.02, 0.06])
    cfg = FluidConfig(dim=dim, dx=dx, g=0.0, c0=20.0, domain_lo=(-1.0,) * dim, domain_hi=(2.0,) * dim)
    fluid = SPHFluid(cfg, block(np.array(lo), np.array(hi), dx), elastic=[beam])
    coupler = Coupler(bodies=bodies, fluid=fluid)
    coupler.initialize()
    ps = fluid.fluid.ps
    ps.vel[ps.kind == Kind.FLUID, 0] = 1.0
    fluid.fluid._rates()  # noqa: SLF001 - the rates of the new velocities
    return coupler, bodies, fluid


def fluid_momentum(fluid):
    """Linear momentum (3,) and angular momentum about the origin along y of the fluid."""
    ps = fluid.fluid.ps
    fl = ps.kind == Kind.FLUID
    m, x, v = ps.mass[fl], ps.pos[fl], ps.vel[fl]
    if fluid.config.dim == 2:
        x = np.stack([x[:, 0], 0 * x[:, 0], x[:, 1]], axis=1)
        v = np.stack([v[:, 0], 0 * v[:, 0], v[:, 1]], axis=1)
    return (m[:, None] * v).sum(axis=0), (m[:, None] * np.cross(x, v)).sum(axis=0)[1]


@pytest.mark.parametrize("dim,steps", [(2, 300), (3, 60)])
def test_momentum_lost_by_the_fluid_is_what_the_links_receive_to_round_off(dim, steps):
    """Fixed clamp: the fluid's change of linear and angular momentum is minus the impulse
    the coupler booked on the links (the welded foot link's share goes into the clamp),
    to round-off: each particle's force is split between its two links with weights that
    sum to one, each part acting at the particle."""
    coupler, bodies, fluid = blob_on_plate(dim)
    P0, L0 = fluid_momentum(fluid)
    J, K = np.zeros(3), 0.0
    for _ in range(steps):
        kin0 = bodies.kinematics()
        dt = coupler.step(10.0).dt
        led = coupler.ledger.last()
        F, T = led["fluid_force"], led["fluid_torque"]
        J += dt * F.sum(axis=0)
        # MuJoCo applies F at the moving centre of mass: about the origin, over the step,
        # (c0 + V dt / 2) x F + T (the coupler's fluid-first torque is about the moving centre)
        K += dt * (np.cross(kin0.com + 0.5 * dt * kin0.velocity, F) + T).sum(axis=0)[1]
    P, L = fluid_momentum(fluid)
    assert J[0] > 0 and (bodies.kinematics().velocity[:, 0] > 0).any()  # the blow was struck, the plate moves
    # round-off of the fluid's own sums: relative to the momentum it holds
    assert np.abs(P - P0 + J).max() < 1e-13 * np.abs(P0).max()
    assert abs(L - L0 + K) < 1e-13 * abs(L0)
    if dim == 2:
        assert J[1] == 0.0


def test_clamped_to_a_free_base_fluid_and_structure_keep_their_momentum():
    """The clamp on a free base: its reaction is internal, and fluid + base + links keep
    their total linear momentum to MuJoCo's RK4 truncation (a chain's momentum is not
    linear in its joint velocities, so not to round-off: 5e-10 of the exchange)."""
    coupler, bodies, fluid = blob_on_plate(2, free_base=True)

    def total():
        k = bodies.kinematics()
        return fluid_momentum(fluid)[0], (bodies.masses()[:, None] * k.velocity).sum(axis=0)

    Pf0, Pb0 = total()
    for _ in range(400):
        coupler.step(10.0)
    Pf, Pb = total()
    exchanged = np.abs(Pf - Pf0).max()
    assert exchanged > 1.0
    assert np.abs(Pf + Pb - Pf0 - Pb0).max() < 1e-8 * exchanged
