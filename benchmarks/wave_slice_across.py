"""The piston flume's first-harmonic height across a 3-D slice's width, station by
station, against linear theory and the 2-D flume: is the 3-D slice's high wave
(docs/validation/wave-propagation_history.md) a pattern across the width, a side-wall
effect, or the same on every column?

The wave-propagation case's scene (`cosim.validations.wave_propagation`: H = 4 cm, T = 1 s,
d = 0.3 m) one wavelength long plus its absorber, run for ``--duration`` seconds, with a
gauge on every particle column of half the width (y = 0.5, 1.5, ... dx; the other half is
its mirror image) at ``--per-wavelength`` stations a wavelength from L / N to 1.25 L; the
first harmonic at each over the last three periods, over linear theory's progressive wave
at the same x (`linear_elevation`, the paddle's evanescent modes not in it). A single gauge
carries the absorber's reflection (a partial standing wave, period L / 2 in x): the case's
stations separate it out, this does not. ``--width 0``: the 2-D flume, one gauge a station.

    python benchmarks/wave_slice_across.py --rows 10 --width 9
    python benchmarks/wave_slice_across.py --rows 10 --width 5 --per-wavelength 8
    python benchmarks/wave_slice_across.py --rows 10 --width 0 --per-wavelength 8
"""

from __future__ import annotations

import argparse
import json
import math

import numpy as np

from machine import cpu_name  # benchmarks/machine.py, beside this script
from cosim.validations import case_scene
from cosim.validations.wave_propagation import (WP_ABSORBER, WP_DEPTH, WP_HEIGHT, WP_PERIOD, _wave, harmonics,
                                                linear_elevation)


def stations(rows: int, per_wavelength: int) -> tuple[np.ndarray, float]:
    """The stations' x [m] (L / N to 1.25 L) and the spacing dx [m] at ``rows``."""
    _, L, _ = _wave(WP_HEIGHT, WP_PERIOD, WP_DEPTH)
    return np.arange(1, math.floor(1.25 * per_wavelength + 1e-9) + 1) * L / per_wavelength, WP_DEPTH / rows


def slice_scene(rows: int, width_rows: int, duration: float, gauges=(), values=()):
    """The case's flume one wavelength long plus its absorber, ``width_rows`` wide (0: 2-D),
    run ``duration`` [s], with ``gauges`` (scene values' strings) and ``values`` on top."""
    n = case_scene.number
    _, L, _ = _wave(WP_HEIGHT, WP_PERIOD, WP_DEPTH)
    dx = WP_DEPTH / rows
    scene_values = [f"fluid.dx={n(dx)}", f"domain.length={n(1.5 * L + WP_ABSORBER * L)}",
                    f"domain.absorber.length={n(WP_ABSORBER * L)}", f"world.duration={n(duration)}"]
    if width_rows:
        scene_values += ["world.dim=3", f"domain.width={n(width_rows * dx)}"]
    return case_scene.load("wave-propagation", scene_values + ["probes.gauges=[" + ", ".join(gauges) + "]"]
                           + list(values))


def arguments(doc: str, width: int, per_wavelength: int | None, argv=None):
    """The command line the slice benchmarks take."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rows", type=int, default=10, help="particle rows over the depth")
    ap.add_argument("--width", type=int, default=width, help="the slice's width in spacings (0: the 2-D flume)")
    if per_wavelength is not None:  # None: a benchmark without stations
        ap.add_argument("--per-wavelength", type=int, default=per_wavelength, help="stations a wavelength")
    ap.add_argument("--duration", type=float, default=6.5, help="the run [s]; the last 3 periods are read")
    ap.add_argument("--set", nargs="*", default=[], metavar="KEY=VALUE", help="scene values on top (cosim run --set)")
    args = ap.parse_args(argv)
    print(f"# CPU: {cpu_name()}")
    return args


def run(rows: int, width_rows: int, per_wavelength: int, duration: float, values=()) -> dict:
    """One flume: ``rows`` particle rows over the depth, ``width_rows`` wide (0: 2-D)."""
    n = case_scene.number
    wm, L, _ = _wave(WP_HEIGHT, WP_PERIOD, WP_DEPTH)
    xs, dx = stations(rows, per_wavelength)
    ys = (np.arange((width_rows + 1) // 2) + 0.5) * dx
    if width_rows:
        gauges = [f"[{n(x)}, {n(y)}]" for x in xs for y in ys]
    else:
        ys = np.array([0.0])
        gauges = [n(x) for x in xs]
    scene = slice_scene(rows, width_rows, duration, gauges, values)
    res = case_scene.run_once(scene)
    fit = res.t >= duration - 3.0 * WP_PERIOD - 1e-9
    eta = np.column_stack([res[f"gauge{i + 1}.eta"][fit] for i in range(len(gauges))])
    omega = 2.0 * math.pi / WP_PERIOD
    a = np.abs(harmonics(res.t[fit], eta, omega)).reshape(len(xs), len(ys))
    a_lin = np.abs(harmonics(res.t[fit], linear_elevation(wm, xs, res.t[fit]), omega))
    return {"rows": rows, "width_rows": width_rows, "set": list(values), "x_over_L": np.round(xs / L, 4).tolist(),
            "y_over_dx": np.round(ys / dx, 2).tolist(), "H1_over_linear": np.round(a / a_lin[:, None], 4).tolist(),
            "mean_level_mm": np.round(1000.0 * eta.mean(axis=0).reshape(len(xs), len(ys)), 2).tolist(),
            "particles": int(res.summary["particles"]), "cpu_s": float(res.summary["cpu_s"])}


def main(argv=None) -> None:
    args = arguments(__doc__, 9, 4, argv)
    r = run(args.rows, args.width, args.per_wavelength, args.duration, args.set)
    print(json.dumps(r))
    print("\n| x / L | " + " | ".join(f"y = {y} dx" for y in r["y_over_dx"]) + " |")
    print("|---" * (1 + len(r["y_over_dx"])) + "|")
    for x, row in zip(r["x_over_L"], r["H1_over_linear"]):
        print(f"| {x} | " + " | ".join(f"{v:.3f}" for v in row) + " |")


if __name__ == "__main__":
    main()
