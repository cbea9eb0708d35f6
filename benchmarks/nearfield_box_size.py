"""Does a near field's result depend on its box? The moored box of the
`nearfield-floating-box` case (2-D, d = 0.3 m) in a wave much longer than the near field
(T = 4 s, L = 6.7 m, H = 6 mm: the flagship's regime, where the box is a fifth of the
wavelength and the zones are sized by the body's own heave period), in boxes of several
lengths, with and without absorbing end walls (``domain.absorbing_walls``,
fluid.wall_absorption). Prints the first harmonics over the window of the body's surge,
heave and pitch and of the gauges (amplitude and phase [deg]) and, with absorbing walls,
of each wall's correction, as a markdown table.

    python benchmarks/nearfield_box_size.py --out OUT [--pad 0 0.25 0.5 1.0] [--duration 30]
        [--window 12 30] [--absorbing both|on|off]

``--pad``: metres added to the chosen box (0.52 .. 1.88 m) at each end; at 1.0 m the box
is half the wavelength long, the length of its first sloshing mode at the wave's period.
Runs are kept in ``OUT/LABEL`` and read back when the script runs again.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

from cosim.scene import Scene
from cosim.validations.nearfield import FLOATING_SCENE
from cosim.validations.wave_propagation import harmonics
from cosim.validations.wind_turbine_sph import run_or_resume

#: the chosen box's ends for this sea and body [m] (summary.json's near_field)
X0, X1 = 0.52, 1.88
SEA = ("waves.kind=regular", "waves.depth=0.3", "waves.period=4.0", "waves.height=0.006")


def scene(pad: float, absorbing: bool, duration: float):
    return Scene.from_toml(FLOATING_SCENE).with_values(
        ["domain.kind=nearfield", *SEA, f"world.duration={duration}", f"domain.x0={X0 - pad:.6g}",
         f"domain.x1={X1 + pad:.6g}", f"domain.absorbing_walls={'true' if absorbing else 'false'}"])


def first_harmonic(t, y, omega: float, window) -> complex:
    """The first harmonic at ``omega`` over ``window`` (the near-field cases' fit: a constant,
    a trend and the second harmonic beside it)."""
    m = (t >= window[0]) & (t <= window[1])
    return complex(harmonics(t[m], y[m], omega, trend=True))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", type=Path, required=True)
    ap.add_argument("--pad", type=float, nargs="+", default=[0.0, 0.25, 0.5, 1.0])
    ap.add_argument("--duration", type=float, default=30.0)
    ap.add_argument("--window", type=float, nargs=2, default=(12.0, 30.0))
    ap.add_argument("--absorbing", choices=("both", "on", "off"), default="both")
    a = ap.parse_args(argv)
    modes = {"both": (False, True), "on": (True,), "off": (False,)}[a.absorbing]
    omega = 2 * math.pi / 4.0
    cols = ["box.surge", "box.heave", "box.pitch", "gauge1.eta", "gauge2.eta", "gauge3.eta"]
    print("| box [m] | absorbing walls | " + " | ".join(cols) + " | walls' correction (near, far) [mm] | CPU s |")
    print("|---" * (len(cols) + 4) + "|")
    for pad in a.pad:
        for absorbing in modes:
            s = scene(pad, absorbing, a.duration)
            res, _ = run_or_resume(s, a.out / f"pad{pad:g}{'_abs' if absorbing else ''}")
            cells = []
            for c in cols:
                z = first_harmonic(res.t, res[c], omega, a.window)
                cells.append(f"{abs(z) * (1 if c.endswith('pitch') else 1000):.3g}{'' if c.endswith('pitch') else ' mm'}"
                             f" at {math.degrees(np.angle(z)):.0f}")
            walls = ("" if "near_wall.xi" not in res.names else
                     ", ".join(f"{abs(first_harmonic(res.t, res[w], omega, a.window)) * 1000:.2f}"
                               for w in ("near_wall.xi", "far_wall.xi")))
            cpu = res.summary["cpu_s"]  # every segment's
            print(f"| {X0 - pad:.2f} .. {X1 + pad:.2f} | {'yes' if absorbing else 'no'} | " + " | ".join(cells)
                  + f" | {walls} | {cpu:.0f} |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
