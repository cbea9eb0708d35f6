"""Does a 2-D wave lose less height over a floor of mirror images than over the floor's wall
particles? A probe of the floor's loss that the energy budget finds at 40 rows
(docs/validation/wave-propagation_history.md, "What holds the 2-D decay at 0.9 %").

The floor's wall particles (``walls="adami"``: their pressure carried from the fluid, Adami
et al. 2012) are replaced by the mirror images across z = 0 of every particle within 2h of
it (free-slip ghost particles: Colagrossi & Landrini 2003, J. Comput. Phys. 191, 448-475),
the image's pressure that of its source plus ``rho0 g (z_source - z_image)`` so that the
hydrostatic pressure carries on through the floor (the body-force term with which Adami et
al. 2012, Eq. 27, carry the fluid's pressure to a wall particle) and the Fourtakas
diffusion sees no density step across it. The end walls and the paddle keep their particles above the
floor, and their images stand for them below it. Not a supported set-up: the solver's
symmetry plane (fluid.mirror, ``symmetry_y`` in 3-D) is used here as a floor in 2-D (its
axis 1 is z there), past the check that keeps it to 3-D, with the images' density set
hydrostatically; no test covers it.

    python benchmarks/mirror_floor_probe.py tank --rows 10 20 40
    python benchmarks/mirror_floor_probe.py flume --rows 20 --wavelengths 8

``tank``: the standing wave of benchmarks/standing_wave_decay.py (6 periods), its decay per
period (the floor's wall particles: that benchmark). ``flume``: the wave-propagation case's
piston flume (cosim.validations.wave_propagation.propagate's), its heights and decay per
wavelength (the floor's wall particles: benchmarks/wave_propagation.py).
"""

from __future__ import annotations

import argparse
import json
import math

import numpy as np

import standing_wave_decay as tank  # beside this script
from machine import cpu_name  # beside this script
from cosim.scene.setup import settings
from cosim.validations import wave_propagation as wp
from fluid.mirror import Mirror
from fluid.solver import Fluid, FluidConfig, travelling_waves


class HydrostaticFloor(Mirror):
    """Mirror images across z = 0 in 2-D whose pressure is their source's plus
    ``rho0 g (z_source - z_image)`` (the Tait density for it)."""

    def __init__(self, cfg: FluidConfig):
        super().__init__(0.0, 2.0 * cfg.h, cfg.dx)
        self.cfg = cfg

    def refresh(self, ps, density_only: bool = False) -> None:
        super().refresh(ps, density_only)
        c, r, s = self.cfg, self.rows, self.src
        B = c.rho0 * c.speed_of_sound ** 2 / c.gamma
        p = B * ((ps.rho[s] / c.rho0) ** c.gamma - 1.0) + c.rho0 * c.g * 2.0 * ps.pos[s, 1]
        ps.rho[r] = c.rho0 * np.maximum(p / B + 1.0, 1e-6) ** (1.0 / c.gamma)


def floor_fluid(cfg: FluidConfig, ps) -> Fluid:
    """A 2-D fluid of ``ps`` less the particles under z = 0, its floor :class:`HydrostaticFloor`."""
    object.__setattr__(cfg, "symmetry_y", 0.0)  # room for the images below the floor
    fluid = Fluid(cfg, ps.select(ps.pos[:, 1] >= 0.0))
    fluid.mirror = HydrostaticFloor(cfg)
    return fluid


def started_tank(rows: int, extra: dict, width_rows: int = 0):
    """standing_wave_decay.started_tank's tank with the mirror floor (2-D only)."""
    from fluid.geometry import set_hydrostatic, tank_with_water

    k, omega = 2.0 * math.pi / tank.LENGTH, 2.0 * math.pi / tank.WP_PERIOD
    dx = tank.DEPTH / rows
    cfg = FluidConfig(dim=2, dx=dx, g=tank.G,
                      **{"u_max": math.sqrt(tank.G * tank.DEPTH), **settings("waves", 2), **extra})
    ps = tank_with_water(2, dx, tank.LENGTH, tank.DEPTH, 1.6 * tank.DEPTH, width=0.0,
                         layers=math.ceil(2.0 * cfg.h_coef - 1e-9)).particles
    set_hydrostatic(ps, tank.DEPTH, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    fluid = floor_fluid(cfg, ps)
    fluid.initialize(0.0)
    fluid.settle(2.0)
    water = (fluid.ps.kind == 0) & (fluid.ps.ids >= 0)
    x, z = fluid.ps.pos[water, 0], fluid.ps.pos[water, -1]
    A = tank.AMPLITUDE * tank.G * k / (omega * math.cosh(k * tank.DEPTH))
    fluid.ps.vel[water, 0] = -A * np.cosh(k * z) * np.sin(k * x)
    fluid.ps.vel[water, -1] = A * np.sinh(k * z) * np.cos(k * x)
    return fluid, A


def flume(rows: int, wavelengths: int) -> dict:
    """wave_propagation.propagate's flume (the case's wave, the chooser's set-up) with the
    mirror floor."""
    from fluid.flume import PADDLE_GROUP, flume as build
    from fluid.geometry import assemble, set_hydrostatic
    from fluid.relaxation import Slab

    depth, H, T = wp.WP_DEPTH, wp.WP_HEIGHT, wp.WP_PERIOD
    dx = depth / rows
    wm, L, _ = wp._wave(H, T, depth)
    x_abs = (wavelengths + 0.5) * L
    length = x_abs + wp.WP_ABSORBER * L
    cfg = FluidConfig(dim=2, dx=dx, g=wp.G, u_max=math.sqrt(wp.G * depth), **travelling_waves(rows))
    f = build(dx, length, depth, 1.5 * depth, layers=math.ceil(2.0 * cfg.h_coef - 1e-9), back=0.5 * wm.stroke + dx)
    ps = assemble(2, dx, cfg.rho0, f.fluid, f.walls).particles
    set_hydrostatic(ps, depth, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    fluid = floor_fluid(cfg, ps)
    fluid.prescribe_motion(PADDLE_GROUP, wm.paddle())
    fluid.zones.append(Slab(0, x_abs, length, 2.0 * 2.0 * math.pi / T))  # as propagate's rate_per_omega = 2
    fluid.initialize(0.0)
    return wp.read_flume(fluid, depth, H, T, wavelengths)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=("tank", "flume"))
    ap.add_argument("--rows", nargs="+", type=int, default=[10], help="particle rows over the depth")
    ap.add_argument("--wavelengths", type=int, default=8, help="the flume's stations")
    args = ap.parse_args(argv)
    print(f"# CPU: {cpu_name()}")
    for rows in args.rows:
        if args.what == "tank":
            tank.started_tank = started_tank
            r = tank.run(rows, 6, {})
        else:
            r = flume(rows, args.wavelengths)
        line = {k: (np.round(v, 4).tolist() if isinstance(v, np.ndarray) else v) for k, v in r.items()}
        print(json.dumps({"what": args.what, "floor": "mirror", "rows": rows, **line}), flush=True)


if __name__ == "__main__":
    main()
