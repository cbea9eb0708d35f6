"""A piston paddle in SPH water makes the waves linear wavemaker theory asks for."""

import math

import numpy as np
import pytest

from fluid.flume import PADDLE_GROUP, flume
from fluid.geometry import assemble, set_hydrostatic
from fluid.probes import surface_elevation
from fluid.solver import Fluid, FluidConfig
from fluid.wavemaker import RegularWavemaker

D, T, H = 0.3, 1.0, 0.04  # depth [m], period [s], height [m]: kd = 1.37, wavelength 1.37 m, H/S = 1.30


def piston_wave_heights(dx: float, gauges, t_end: float, length: float = 2.0):
    """Crest-to-trough height [m] at each gauge x [m] over the last period before
    ``t_end`` [s], in a flume of ``length`` [m] whose far wall's reflection has not
    yet come back to the gauges (group velocity 0.93 m/s)."""
    wm = RegularWavemaker("piston", H=H, T=T, depth=D, ramp=1.0)
    f = flume(dx, length, D, 1.6 * D, back=0.5 * wm.stroke + dx)
    cfg = FluidConfig(dim=2, dx=dx, u_max=math.sqrt(9.81 * D), c0_factor=10.0)
    ps = assemble(2, dx, cfg.rho0, f.fluid, f.walls).particles
    set_hydrostatic(ps, D, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    fluid = Fluid(cfg, ps)
    fluid.prescribe_motion(PADDLE_GROUP, wm.paddle())
    fluid.initialize(0.0)
    t, eta = 0.0, []
    while t < t_end - 1e-12:
        dt = min(fluid.max_dt(), 0.01, t_end - t)
        fluid.advance(t, dt)
        t += dt
        if t > t_end - T:
            eta.append(surface_elevation(fluid, gauges))
    eta = np.array(eta)
    return eta.max(axis=0) - eta.min(axis=0)


def test_piston_waves_have_the_height_of_linear_theory_coarse():
    """dx = 2 cm (15 particles over the depth, H = 2 dx), a gauge 2 depths from the
    paddle (past its evanescent modes), over the period that ends at 2.5 s (the
    ramp's end has passed it; the far wall's reflection has not come back):
    measured 0.92 H (0.94 H for waves half as high: the rest of the deficit is
    nonlinearity, H/d = 0.13). The waves lose about 5 % per depth travelled at
    this resolution (0.86 H at 3 depths): more than the artificial viscosity's
    exp(-2 nu k^2 t) alone (nu = alpha h c0 / 8 = 6e-4 m^2/s gives 1 %)."""
    heights = piston_wave_heights(0.02, [2 * D], t_end=2.5)
    np.testing.assert_allclose(heights / H, 1.0, atol=0.15)


@pytest.mark.slow
def test_piston_waves_have_the_height_of_linear_theory_fine():
    """dx = 1 cm in a longer flume (reflection back after 4 s), gauges 2 and 3
    depths out, the period ending at 3.5 s: within 10 % of theory."""
    fine = piston_wave_heights(0.01, [2 * D, 3 * D], t_end=3.5, length=3.0)
    np.testing.assert_allclose(fine / H, 1.0, atol=0.10)
