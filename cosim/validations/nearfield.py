"""The SPH near field inside an incident sea (:mod:`fluid.nearfield`): regular waves through
a box with no body, read at gauges across it against the sea's own elevation."""

from __future__ import annotations

import math
import time

import numpy as np

from cosim.validations.wave_propagation import harmonics
from cosim.validations.waves import G


def nearfield_waves(dx: float, depth: float, H: float, T: float, length: float, zone: float, periods: float,
                    theory: str = "linear", rate_per_omega: float = 2.0, fit_periods: float = 3.0,
                    gauges: int = 9, drift: bool = True, progress: bool = False, **config) -> dict:
    """Regular waves (``fluid.waves.RegularWave``, ``theory``) of height ``H`` [m], period
    ``T`` [s] in ``depth`` [m] of water through a 2-D near-field box ``length`` [m] long at
    spacing ``dx`` [m], with relaxation zones ``zone`` [m] wide relaxing at
    ``rate_per_omega`` wave frequencies at the walls, run ``periods`` periods (the sea faded
    in over two). ``gauges`` gauges spread over the water between the zones. Returns per
    gauge the first-harmonic height and phase over the sea's [m, periods] over the last
    ``fit_periods`` periods, the mean level [m] over each period (its drift), the lost
    fluid particles and the run's cost. ``config``: FluidConfig settings."""
    from fluid.geometry import assemble, set_hydrostatic
    from fluid.nearfield import FAR_END_GROUP, NEAR_END_GROUP, following_wall, near_field_box
    from fluid.probes import surface_elevation
    from fluid.solver import Fluid, FluidConfig
    from fluid.waves import RegularWave

    sea = RegularWave(H, T, depth, theory=theory, ramp=2.0 * T, level=depth, g=G)
    config.setdefault("u_max", math.sqrt(G * depth))
    cfg = FluidConfig(dim=2, dx=dx, g=G, **config)
    box = near_field_box(dx, 0.0, length, sea, 1.6 * depth, zone, layers=math.ceil(2.0 * cfg.h_coef - 1e-9))
    ps = assemble(2, dx, cfg.rho0, box.fluid, box.walls).particles
    set_hydrostatic(ps, depth, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    fluid = Fluid(cfg, ps)
    for group in (NEAR_END_GROUP, FAR_END_GROUP):
        fluid.prescribe_motion(group, following_wall(sea))
    omega = 2.0 * math.pi / T
    fluid.zones.extend(box.zones(sea, rate_per_omega * omega, drift=drift))
    gx = np.linspace(zone, length - zone, gauges)
    gall = np.linspace(0.5 * dx, length - 0.5 * dx, 41)  # the mean level over the whole box
    fluid.initialize(0.0)
    every = T / 32.0
    n = int(round(periods * 32))
    ts, eta, cpu0 = [], [], time.process_time()
    for i in range(1, n + 1):
        t = i * every
        fluid.advance(fluid.t, t - fluid.t)
        ts.append(t)
        eta.append(surface_elevation(fluid, np.concatenate([gx, gall])) - depth)
        if progress and i % 32 == 0:
            print(f"  t = {t:6.2f} s, {fluid.counters.steps} steps", flush=True)
    cpu = time.process_time() - cpu0
    ts, eta_all = np.array(ts), np.array(eta)
    eta, box_eta = eta_all[:, :len(gx)], eta_all[:, len(gx):]
    fit = ts > ts[-1] - fit_periods * T + 1e-9
    a = harmonics(ts[fit], eta[fit], omega)
    a_sea = harmonics(ts[fit], sea.elevation(gx[None, :], 0.0, ts[fit][:, None]), omega)
    ratio = a / a_sea
    per = int(round(T / every))
    mean_level = eta[: (len(ts) // per) * per].reshape(-1, per, len(gx)).mean(axis=(1, 2))
    box_level = box_eta[: (len(ts) // per) * per].reshape(-1, per, box_eta.shape[1]).mean(axis=(1, 2))
    return {"gauges_m": gx, "H1_over_H": np.abs(ratio), "lag_periods": -np.angle(ratio) / (2.0 * math.pi),
            "mean_level_m": mean_level, "box_level_m": box_level, "particles": int(ps.n), "steps": int(fluid.counters.steps), "cpu_s": cpu,
            "removed": int(sum(fluid.counters.removed.values())), "wavelength_m": sea.wavelength}
