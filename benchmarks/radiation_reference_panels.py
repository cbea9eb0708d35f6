"""How nearfield-radiation's reference converges with Capytaine's panels: A33, B33 and C33 of
the case's cylinder (``cosim.validations.radiation.reference``: R = 3 m, draft 1.5 m, 6 m of
water, the case's frequency) at each panel size, and Richardson's estimate of the limit
from the last three (``cosim.study``'s: ``X(h) = X_inf + C h^p`` through the three; Richardson
1911, Roache 1998 §5.4). The sharp edge between side and bottom makes B33 converge slowly
(docs/validation/nearfield.md, "The reference's panels").

    python benchmarks/radiation_reference_panels.py [--panels 0.2 0.1 0.05] [--cache DIR]

``--panels``: sizes in radii, coarsest first. Solved results are cached (default
Capytaine's cache of ``fluid.potential``); CPU seconds are the solve's (next to none when
read from the cache). Prints one line per size, then the estimate.
"""

from __future__ import annotations

import argparse
import math
import time

from cosim.errors import InputError
from cosim.study import _richardson
from cosim.validations.radiation import PANEL, draft_of, radiation_scene, reference


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--panels", type=float, nargs="+", default=[0.2, 0.1, PANEL], help="panel sizes in radii")
    ap.add_argument("--cache", default=None, help="Capytaine's cache folder (default fluid.potential's)")
    args = ap.parse_args(argv)
    scene = radiation_scene(True)
    b, d = scene.bodies[0], scene.domain
    w = 2.0 * math.pi / b.motion.period
    draft = draft_of(scene)
    rows = []
    for p in args.panels:
        t = time.process_time()
        rows.append(reference(b.radius, draft, d.depth, w, scene.fluid.rho0, scene.world.gravity, args.cache, panel=p))
        a, bb, c = rows[-1]
        print(f"panel {p:g} R: A33 {a:.1f} kg, B33 {bb:.1f} kg/s, C33 {c:.1f} N/m "
              f"({time.process_time() - t:.1f} CPU-s)", flush=True)
    if len(rows) >= 3:
        for name, j in (("A33", 0), ("B33", 1), ("C33", 2)):
            x = [r[j] for r in rows[-3:]]
            try:  # finest first, as cosim study extrapolates its spacings
                lim, order = _richardson(args.panels[-1:-4:-1], x[::-1])
            except InputError as exc:  # not converging over these sizes: no limit to estimate
                print(f"{name}: {exc.args[0].split(';')[0]} (spread {(max(x) - min(x)) / abs(x[-1]):.2%} of the last)")
                continue
            print(f"{name}: limit {lim:.1f} (order {order:.2f}); the last size {rows[-1][j] / lim - 1.0:+.2%} from it, "
                  f"{args.panels[-2]:g} R {rows[-2][j] / lim - 1.0:+.2%}")


if __name__ == "__main__":
    main()
