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

import numpy as np

import standing_wave_decay as tank  # beside this script
from machine import cpu_name  # beside this script
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


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=("tank", "flume"))
    ap.add_argument("--rows", nargs="+", type=int, default=[10], help="particle rows over the depth")
    ap.add_argument("--wavelengths", type=int, default=8, help="the flume's stations")
    args = ap.parse_args(argv)
    print(f"# CPU: {cpu_name()}")
    for rows in args.rows:
        if args.what == "tank":
            r = tank.run(rows, 6, {}, make_fluid=floor_fluid)
        else:
            r = wp.propagate(wp.WP_DEPTH / rows, wp.WP_DEPTH, wp.WP_HEIGHT, wp.WP_PERIOD, wavelengths=args.wavelengths,
                             make_fluid=floor_fluid, **travelling_waves(rows))
        line = {k: (np.round(v, 4).tolist() if isinstance(v, np.ndarray) else v) for k, v in r.items()}
        print(json.dumps({"what": args.what, "floor": "mirror", "rows": rows, **line}), flush=True)


if __name__ == "__main__":
    main()
