"""The flagship's surge, read apart: the `wind-turbine-sph` case's kept runs (its wave run in
SPH and the potential-flow and analytic references, ``COSIM_CASE_RUNS/wind-turbine-sph/full``)
fitted over a window with the wave's first harmonic alone (the case's fit: with a constant,
a linear trend and the second harmonic) and with the moored base's free surge mode beside
it (its period fitted too), so that the free mode's leak into the wave's harmonic is told
from a steady excess; the phases against the heave;
and the SPH fluid's horizontal force against what linear potential flow puts on the same
motion (the excitation plus the added mass times the surge's acceleration, from the hull's
boundary-element coefficients at the wave's period, given as options). Prints a markdown
table and the force's split.

    python benchmarks/wind_turbine_surge.py --runs DIR [--sph waves] [--window 30 90]
        [--period 20] [--x-surge 4970 --x-phase 90 --a11 19500]

``--sph``: the SPH run's folder under DIR (``waves`` in the case's; a variant's label in
benchmarks/wind_turbine_levers.py's ``--out``).

The defaults of ``--x-surge``, ``--x-phase`` and ``--a11`` are Capytaine's for the base at
the paper's wave (docs/validation/nearfield.md, "The SPH base's surge phase"): the surge
excitation [N] for the wave's amplitude and its phase [deg] ahead of the elevation at the
base, and the surge added mass [kg] at 20 s.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
from scipy.optimize import minimize_scalar

from cosim.scene.runner import read
from cosim.validations.wave_propagation import harmonics


def fit(t: np.ndarray, y: np.ndarray, omegas) -> tuple[list[complex], float]:
    """Least-squares ``y ~ c + sum Re(z_k exp(i w_k t))``: ([z_k], rms residual)."""
    cols = [np.ones_like(t)]
    for w in omegas:
        cols += [np.cos(w * t), np.sin(w * t)]
    a = np.column_stack(cols)
    c, *_ = np.linalg.lstsq(a, y, rcond=None)
    return [complex(c[1 + 2 * k], -c[2 + 2 * k]) for k in range(len(omegas))], float(np.sqrt(np.mean((y - a @ c) ** 2)))


def with_free_mode(t, y, omega, periods=(6.0, 16.0)) -> tuple[complex, complex, float]:
    """The wave's harmonic with a free mode fitted beside it: (z_wave, z_free, free period [s])."""
    best = minimize_scalar(lambda T: fit(t, y, [omega, 2 * math.pi / T])[1], bounds=periods, method="bounded")
    (zw, zf), _ = fit(t, y, [omega, 2 * math.pi / best.x])
    return zw, zf, float(best.x)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=Path, required=True, help="the case's runs (waves/, potential/, analytic/)")
    ap.add_argument("--sph", default="waves", help="the SPH run's folder under --runs")
    ap.add_argument("--window", type=float, nargs=2, default=(30.0, 90.0))
    ap.add_argument("--period", type=float, default=20.0)
    ap.add_argument("--x-surge", type=float, default=4970.0, help="surge excitation [N] for the wave's amplitude")
    ap.add_argument("--x-phase", type=float, default=90.0, help="its phase ahead of the elevation [deg]")
    ap.add_argument("--a11", type=float, default=19500.0, help="surge added mass at the wave's period [kg]")
    a = ap.parse_args(argv)
    w = 2 * math.pi / a.period
    deg = lambda z: math.degrees(math.atan2(z.imag, z.real))
    print(f"window {a.window[0]:g}-{a.window[1]:g} s; phases against the heave (in phase with the wave)\n")
    print("| fluid | surge, wave's harmonic [m] | with the free mode fitted [m] | free mode [m] at [s] "
          "| surge - heave [deg] | heave [m] | fluid Fx [kN] at [deg] |")
    print("|---|---|---|---|---|---|---|")
    found = {}
    for sub, label in ((a.sph, "SPH"), ("potential", "potential"), ("analytic", "analytic")):
        if not (a.runs / sub / "summary.json").is_file():
            continue
        res = read(a.runs / sub)
        if res.t[-1] < a.window[1] - 1e-6:
            print(f"| {label} | its run ends at {res.t[-1]:g} s, before the window: left out | | | | | |")
            continue
        late = (res.t >= a.window[0] - 1e-9) & (res.t <= a.window[1] + 1e-9)
        ts = res.t[late]

        def h(name):  # the case's first harmonic (a constant, a trend, the second harmonic)
            return complex(harmonics(ts, res[name][late], w, trend=True))

        zh = h("base.heave")
        ref = zh / abs(zh)
        zs, fx = h("base.surge"), h("base.fluid_Fx")
        zw, zf, tf = with_free_mode(ts, res["base.surge"][late], w)
        found[label] = (zs / ref, zw / ref, fx / ref)
        print(f"| {label} | {abs(zs):.3f} | {abs(zw):.3f} | {abs(zf):.3f} at {tf:.1f} | {deg(zs / ref):+.0f} "
              f"| {abs(zh):.3f} | {abs(fx) / 1e3:.2f} at {deg(fx / ref):+.0f} |")
    if "SPH" in found and "potential" in found:
        zs, zw, fx = found["SPH"]
        ps, pw, _ = found["potential"]
        print(f"\nSPH surge against the potential fluid's: {abs(zs) / abs(ps) - 1:+.1%} (the wave's harmonic), "
              f"{abs(zw) / abs(pw) - 1:+.1%} (the free mode fitted beside it)")
        linear = a.x_surge * np.exp(1j * math.radians(a.x_phase)) + a.a11 * w ** 2 * zs  # X - A11 * acceleration
        rest = fx - linear
        print(f"SPH fluid Fx {abs(fx) / 1e3:.2f} kN at {deg(fx):+.0f} deg; linear potential flow on the same motion "
              f"{abs(linear) / 1e3:.2f} kN at {deg(linear):+.0f} deg; the rest {abs(rest) / 1e3:.2f} kN at "
              f"{deg(rest):+.0f} deg")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
