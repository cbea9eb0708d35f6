"""The flagship's near field without its base: the `wind-turbine-sph` case's scene with the
base and its lines taken out and the box, zones and sea kept (the box the scene chooses for
the base, given explicitly), so that what the box does to the incident wave is read apart
from what the base does: each gauge's first-harmonic height over the sea's and its lag,
along y = 1 m from the near zone to the far one and across the box at x = 70 m.

    python benchmarks/wind_turbine_empty_box.py --out OUT [--dx 2.0] [--duration 60]
        [--walls orbits absorbing]

One run per ``--walls`` choice: the end walls on the sea's orbits, or absorbing
(``domain.absorbing_walls``). First harmonics over the last 40 s. Prints one line per run
and a markdown table.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from cosim.scene.toml_io import from_dict, to_dict
from cosim.validations import wind_turbine_sph as case

#: the box the scene chooses for the base at dx = 1.0 m (x, full width with the mirror, zone) [m]
BOX = {"x0": 48.0, "x1": 92.0, "width": 44.0, "zone": 11.313708498984761}
GAUGES = [[x, 1.0] for x in (52.0, 56.0, 60.0, 65.0, 70.0, 75.0, 80.0, 84.0, 88.0)] + [[70.0, 10.0], [70.0, 18.0]]


def empty_scene(dx: float, duration: float, absorbing: bool):
    """The case's full scene without the base and its lines, at ``dx`` [m] for ``duration`` [s]."""
    d = to_dict(case.sph_scene(False))
    d.pop("bodies")
    d.pop("moorings", None)
    d["domain"].update(BOX, absorbing_walls=absorbing)
    d["fluid"]["dx"] = dx
    d["world"]["duration"] = duration
    d["probes"] = {"gauges": GAUGES, "tensions": False}
    return from_dict(d)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", type=Path, required=True)
    ap.add_argument("--dx", type=float, default=2.0)
    ap.add_argument("--duration", type=float, default=60.0)
    ap.add_argument("--walls", nargs="+", choices=("orbits", "absorbing"), default=["orbits", "absorbing"])
    a = ap.parse_args(argv)
    rows = {}
    for walls in a.walls:
        scene = empty_scene(a.dx, a.duration, walls == "absorbing")
        res = scene.run(a.out / walls, overwrite=True, progress=False, yes=True)
        g = case.gauge_figures(res, scene, (a.duration - 40.0, a.duration))
        rows[walls] = g
        print(f"{walls}: {res.summary.get('particles')} particles, {res.summary.get('cpu_s'):.0f} CPU-s; H1/H "
              f"{np.round(g['H1_over_H'], 3).tolist()}", flush=True)
    print("\n| gauge (x, y) [m] | " + " | ".join(f"walls {w}: height / sea, lag [periods]" for w in rows) + " |")
    print("|---" * (1 + len(rows)) + "|")
    for i, p in enumerate(GAUGES):
        print(f"| ({p[0]:g}, {p[1]:g}) | " + " | ".join(f"{g['H1_over_H'][i]:.3f}, {g['lag_periods'][i]:+.3f}"
                                                      for g in rows.values()) + " |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
