"""The tank of benchmarks/standing_wave_decay.py (10 rows, 1.38 m, the wave set-up) at rest,
1 s after its 2 s settle, drawn twice: with the lattice column by the far wall left empty, as
``fluid.geometry.tank_with_water`` built a tank 45.77 spacings long before
``lattice_extent``, and with every column filled. The empty column turns the water over
(docs/validation/wave-propagation_history.md, "The standing-wave probe's empty column").

    python benchmarks/tank_at_rest_figure.py docs/validation/figures/standing-wave-tank_empty-column.png
"""

import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from fluid.geometry import set_hydrostatic, tank_with_water
from fluid.solver import Fluid, FluidConfig
from cosim.scene.setup import settings


def main(path: str) -> None:
    dx, d, L = 0.03, 0.3, 1.38
    fig, axs = plt.subplots(2, 1, figsize=(9, 5.2), sharex=True)
    for ax, hole in zip(axs, (True, False)):
        cfg = FluidConfig(dim=2, dx=dx, g=9.81, u_max=math.sqrt(9.81 * d), **settings("waves", 2))
        ps = tank_with_water(2, dx, L, d, 0.48, layers=4).particles
        if hole:
            keep = ~((ps.kind == 0) & (ps.pos[:, 0] > L - dx))
            ps = ps.select(keep)
        set_hydrostatic(ps, d, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
        f = Fluid(cfg, ps)
        f.initialize(0.0)
        f.settle(2.0)
        f.advance(0.0, 1.0)
        w = f.ps.kind == 0
        p, v = f.ps.pos[w], f.ps.vel[w]
        sp = np.sqrt((v ** 2).sum(1))
        ax.quiver(p[:, 0], p[:, 1], v[:, 0], v[:, 1], scale=1.0, width=0.002)
        wall = f.ps.pos[~w]
        ax.plot(wall[:, 0], wall[:, 1], ".", color="0.7", ms=2)
        what = "the column by the far wall empty (before)" if hole else "every column filled (lattice_extent)"
        ax.set_title(f"{what}: largest speed {1e3 * sp.max():.1f} mm/s, rms {1e3 * np.sqrt((sp ** 2).mean()):.2f} mm/s",
                     fontsize=9)
        ax.set_aspect("equal")
        ax.set_ylim(-0.12, 0.33)
        ax.set_ylabel("z [m]")
        print(f"{'empty column' if hole else 'filled'}: largest speed {sp.max():.4g} m/s, rms {np.sqrt((sp ** 2).mean()):.4g} m/s")
    axs[-1].set_xlabel("x [m]")
    fig.suptitle("standing_wave_decay's tank at rest, 10 rows, 1 s after a 2 s settle (arrows: 1 m/s per m)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


if __name__ == "__main__":
    main(sys.argv[1])
