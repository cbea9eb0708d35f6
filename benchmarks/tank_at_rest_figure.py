"""The tank of benchmarks/standing_wave_decay.py (10 rows, 1.38 m, the wave set-up) at rest,
1 s after its 2 s settle, drawn twice: with the lattice column by the far wall left empty, as
``fluid.geometry.tank_with_water`` built a tank 45.77 spacings long before
``lattice_extent``, and with every column filled. The empty column turns the water over
(docs/validation/wave-propagation_history.md, "The standing-wave probe's empty column").

    python benchmarks/tank_at_rest_figure.py docs/validation/figures/standing-wave-tank_empty-column.png
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from standing_wave_decay import DEPTH, started_tank, tank_mode  # noqa: E402  (beside this script)
from fluid.solver import Fluid  # noqa: E402

ROWS = 10


def main(path: str) -> None:
    length = tank_mode(DEPTH / ROWS)[0]
    fig, axs = plt.subplots(2, 1, figsize=(9, 5.2), sharex=True)
    for ax, hole in zip(axs, (True, False)):
        def emptied(cfg, ps):  # the column by the far wall taken out of the water
            return Fluid(cfg, ps.select(~((ps.kind == 0) & (ps.pos[:, 0] > length - cfg.dx))))

        f, _ = started_tank(ROWS, {}, make_fluid=emptied if hole else None, amplitude=0.0)
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
