"""Prescribed motion of a MOVING_WALL group: exact placement at every stage, clear errors."""

import math

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.geometry import assemble, block, set_hydrostatic, tank_walls
from fluid.particles import Kind
from fluid.solver import Fluid, FluidConfig

DX = 0.02


def _tank_with_piston(integrator):
    """A 2-D tank whose left wall layers (x < 0) are a separate MOVING_WALL group 1."""
    walls = tank_walls((0.0, 0.0), (0.6, 0.4), DX, layers=3)
    piston = walls[:, 0] < 0.0
    built = assemble(2, DX, 1000.0, block((0.0, 0.0), (0.6, 0.2), DX),
                     [(walls[~piston], Kind.FIXED_WALL, 0), (walls[piston], Kind.MOVING_WALL, 1)])
    cfg = FluidConfig(dim=2, dx=DX, c0=20.0, integrator=integrator)
    set_hydrostatic(built.particles, 0.2, cfg.rho0, cfg.c0, cfg.gamma, cfg.g)
    return Fluid(cfg, built.particles)


def _stroke(t, ref):
    a, w = 0.01, 2 * math.pi / 0.5
    pos = ref.copy()
    pos[:, 0] += a * math.sin(w * t)
    vel = np.zeros_like(ref)
    vel[:, 0] = a * w * math.cos(w * t)
    return pos, vel


@pytest.mark.parametrize("integrator", ["symplectic", "verlet"])
def test_group_follows_the_motion_exactly_and_pushes_the_fluid(integrator):
    fluid = _tank_with_piston(integrator)
    sel = fluid.ps.group == 1
    ref = fluid.ps.pos[sel][np.argsort(fluid.ps.ids[sel])].copy()
    fluid.prescribe_motion(1, _stroke)
    fluid.initialize(0.0)
    t = 0.0
    while t < 0.1:
        dt = fluid.max_dt()
        fluid.advance(t, dt)
        t += dt
    sel = fluid.ps.group == 1
    order = np.argsort(fluid.ps.ids[sel])
    want_pos, want_vel = _stroke(t, ref)
    np.testing.assert_allclose(fluid.ps.pos[sel][order], want_pos, atol=1e-14)
    np.testing.assert_allclose(fluid.ps.vel[sel][order], want_vel, atol=1e-14)
    # the piston moved +x over the first quarter period: the fluid moved with it
    fl = fluid.ps.kind == Kind.FLUID
    assert fluid.ps.vel[fl, 0].mean() > 1e-3
    assert fluid.group_forces_now()[0][1, 0] < 0.0  # the water pushes on the piston towards -x


def test_prescribing_a_fixed_wall_or_missing_group_is_refused():
    fluid = _tank_with_piston("symplectic")
    with pytest.raises(InputError, match="not a MOVING_WALL"):
        fluid.prescribe_motion(0, _stroke)
    with pytest.raises(InputError, match="no boundary group 7"):
        fluid.prescribe_motion(7, _stroke)
    with pytest.raises(InputError, match="shapes"):
        fluid.prescribe_motion(1, lambda t, ref: (ref[:3], ref[:3]))


def _full_difference(motion, t, ref, eps=1e-6):
    """The central difference of the motion's velocity at every point (what
    ``Fluid.prescribed_acceleration`` takes for a motion without its own acceleration)."""
    return (np.asarray(motion(t + eps, ref)[1]) - np.asarray(motion(t - eps, ref)[1])) / (2.0 * eps)


@pytest.mark.parametrize("kind", ["translation", "combined", "piston", "flap"])
def test_a_uniform_motions_acceleration_is_its_one_point_difference_for_all(kind):
    """A motion that moves every point alike (``uniform``: a translation, several at once, a
    piston paddle) has its velocity differenced at one point, bit for bit the difference at
    each; a flap (a rotation: every point its own) is differenced at each point."""
    from fluid.motion import Combined, Harmonic, Translation
    from fluid.wavemaker import RegularWavemaker, flap

    paddle = RegularWavemaker("piston", 0.02, 1.0, 0.2)
    motion = {"translation": Translation((1.0, 0.0), Harmonic(0.01, 0.5)),
              "combined": Combined((Translation((1.0, 0.0), Harmonic(0.01, 0.5)),
                                    Translation((0.0, 1.0), Harmonic(0.004, 0.3, phase=0.4)))),
              "piston": paddle.paddle(),
              "flap": flap(lambda t: (0.05 * math.sin(3.0 * t), 0.15 * math.cos(3.0 * t)), hinge=(0.0, 0.0))}[kind]
    assert getattr(motion, "uniform", False) == (kind != "flap")
    fluid = _tank_with_piston("symplectic")
    sel = fluid.ps.group == 1
    ref = fluid.ps.pos[sel][np.argsort(fluid.ps.ids[sel])].copy()
    fluid.prescribe_motion(1, motion)
    fluid.initialize(0.3)
    acc = fluid.prescribed_acceleration()
    rows = fluid._rows_of(np.sort(fluid.ps.ids[fluid.ps.group == 1]))
    want = _full_difference(motion, 0.3, ref)
    assert np.array_equal(acc[rows], want)
    assert (acc[fluid.ps.group != 1] == 0).all()
    assert np.abs(want).max() > 1e-3  # [m/s^2] it accelerates
    assert (kind == "flap") == (np.ptp(want, axis=0).max() > 0)  # a rotation's differs from point to point
