"""How far regular waves keep their height: piston waves read at every wavelength of a 2-D
flume (cosim.validations.wave_propagation.propagate), for a fluid set-up at several
spacings. Prints one JSON line per run and a table of the decay per wavelength.

    python benchmarks/wave_propagation.py --setup waves sloshing --rows 10 20 --wavelengths 8
    python benchmarks/wave_propagation.py --set alpha=0 --rows 10
    python benchmarks/wave_propagation.py --rows 10 --set shifting=fickian shifting_coef=2
    python benchmarks/wave_propagation.py --rows 40 --height 0.075
    python benchmarks/wave_propagation.py --rows 10 --wavelengths 3 --width 5 --height 0.01 0.04

``--setup``: the scenes' set-ups (cosim.scene.setup.settings: "waves" is a flume's,
fluid.solver.travelling_waves at the rows, "sloshing" the sloshing one); ``--set KEY=VALUE`` adds
FluidConfig settings on top (numbers, true/false or text). The wave: d = 0.3 m, T = 1 s,
H = 4 cm (kd = 1.37), as the wave-propagation case; ``--height`` other heights [m], one run
each (H/dx, the height in spacings, is printed: the issue's "H/dx >= 10" at 40 rows is H =
7.5 cm). ``--width ROWS``: the flume as a 3-D slice that many spacings wide between slip
walls, as the case's 3-D flume. ``k / linear``: the wavenumber the waves travel with over
linear theory's (a wave that travels fast is long: below 1).
"""

from __future__ import annotations

import argparse
import json
import numpy as np

from machine import cpu_name  # benchmarks/machine.py, beside this script
from cosim.scene.setup import settings
from fluid.solver import travelling_waves
from cosim.validations.wave_propagation import WP_DEPTH, WP_HEIGHT, WP_PERIOD, propagate


def setting_value(text: str):
    """A ``--set KEY=VALUE`` value: true/false, a whole number (an int: counts such as
    ``mls_every``), another number (a float), or the text."""
    if text in ("true", "false"):
        return text == "true"
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        return text


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--setup", nargs="+", default=["waves"], help="scene set-ups to compare")
    ap.add_argument("--rows", nargs="+", type=int, default=[10, 20], help="particle rows over the depth")
    ap.add_argument("--wavelengths", type=int, default=8)
    ap.add_argument("--height", type=float, nargs="+", default=[WP_HEIGHT], help="the wave's heights [m]")
    ap.add_argument("--width", type=int, default=0, metavar="ROWS",
                    help="a 3-D slice this many spacings wide (default: 2-D)")
    ap.add_argument("--set", nargs="*", default=[], metavar="KEY=VALUE", help="FluidConfig settings on top")
    args = ap.parse_args(argv)
    extra = {k: setting_value(v) for k, v in (s.split("=", 1) for s in args.set)}
    print(f"# CPU: {cpu_name()}")
    table = []
    dim = 3 if args.width else 2
    for setup in args.setup:
        for rows in args.rows:
            cfg = {**(travelling_waves(rows) if setup == "waves" else settings(setup, dim)), **extra}
            for height in args.height:
                r = propagate(WP_DEPTH / rows, WP_DEPTH, height, WP_PERIOD, wavelengths=args.wavelengths,
                              width=args.width * WP_DEPTH / rows if args.width else None, **cfg)
                r["H_over_dx"] = height * rows / WP_DEPTH
                line = {k: (np.round(v, 4).tolist() if isinstance(v, np.ndarray) else v) for k, v in r.items()}
                print(json.dumps({"setup": setup, "rows": rows, "width_rows": args.width, "height_m": height,
                                  "config": cfg, **line}), flush=True)
                table.append((setup, rows, r))
    print("\n| set-up | rows over the depth | H/dx | H1/H at 1, 2, ... wavelengths | decay per wavelength | lag at the "
          "last [periods] | k / linear | particles | steps | CPU s |\n|---|---|---|---|---|---|---|---|---|---|")
    for setup, rows, r in table:
        h = " ".join(f"{v:.3f}" for v in r["H1_over_H"])
        print(f"| {setup} | {rows} | {r['H_over_dx']:.1f} | {h} | {100 * r['decay_per_wavelength']:.2f} % "
              f"| {r['phase_lag_periods'][-1]:.3f} | {r['k_over_linear']:.4f} | {r['particles']} | {r['steps']} "
              f"| {r['cpu_s']:.0f} |")


if __name__ == "__main__":
    main()
