"""Cost levers on the flagship scene: the `wind-turbine-sph` case's wave run (Barreiro et
al. 2016, §5: the base on its three lines in a 3-D SPH near field) with set-up values
changed (the speed of sound, the integrator, the pair loop's precision), each judged the way
the case judges it: surge and heave first harmonics against the potential-flow fluid's on the
same base, lines and sea, the mean fairlead tensions, and the gauges' height and phase
against the sea's; the phases of surge, pitch and the horizontal fluid force against the
heave (not judged by the case); with the particles, steps and CPU seconds of each run. Prints one JSON
line per variant, then a markdown table.

A variant is ``LABEL:KEY=VALUE[,KEY=VALUE...]`` (scene keys, as ``--set`` takes them); the
case's scene as written (its full variant's, c0 = 70 m/s) at ``--dx`` and ``--duration`` is
run as ``base`` unless ``--no-base``. Runs are kept in ``OUT/LABEL`` and read
back or resumed when the script runs again (the case's ``run_or_resume``).

    python benchmarks/wind_turbine_levers.py --out OUT [--dx 1.25] [--duration 40]
        [--window 20 40] [--no-base] [--variant c140:fluid.c0=140]
        [--variant v10:fluid.integrator=verlet,fluid.verlet_reset=10]

The defaults are the case's quick variant's spacing, duration and window (dx = 1.25 m, 40 s,
20-40 s; that variant also sets c0 = 140 m/s, ``case.QUICK_C0``: give it as a variant). CPU seconds
are this machine's, under whatever else runs on it: compare variants run side by side.
"""

from __future__ import annotations

import argparse
import json
import math

import numpy as np

from cosim.validations import wind_turbine_sph as case
from cosim.validations.wave_propagation import harmonics
from wind_turbine_mooring_swap import run_arguments  # benchmarks/, beside this script


def parse_variant(text: str) -> tuple[str, list[str]]:
    """``LABEL:KEY=VALUE,...`` -> (label, ["KEY=VALUE", ...])."""
    label, sep, sets = text.partition(":")
    if not sep or not label or not sets:
        raise SystemExit(f"--variant {text!r}: give LABEL:KEY=VALUE[,KEY=VALUE...], e.g. c70:fluid.c0=70")
    return label, [s for s in sets.split(",") if s]


def phases(res, window, omega: float) -> dict:
    """The phases [deg] of the surge, the pitch and the horizontal fluid force against the
    heave (respectively the vertical fluid force) at the wave's frequency over ``window``:
    the heave is in phase with the wave on every fluid, so these compare fluids without a
    reference elevation."""
    late = (res.t >= window[0] - 1e-9) & (res.t <= window[1] + 1e-9)
    ts = res.t[late]

    def h(name):
        return harmonics(ts, res[f"base.{name}"][late][:, None], omega)[0]

    deg = lambda z: float(np.degrees(np.angle(z)))
    return {"surge_minus_heave_deg": deg(h("surge") / h("heave")), "pitch_minus_heave_deg": deg(h("pitch") / h("heave")),
            "fluid_Fx_minus_Fz_deg": deg(h("fluid_Fx") / h("fluid_Fz"))}


def figures(res, scene, window, pot) -> dict:
    """The case's judged figures of one wave run against the potential fluid's ``pot``."""
    omega = 2.0 * math.pi / scene.waves.period
    m = case.motion_figures(res, window, omega) | phases(res, window, omega)
    g = case.gauge_figures(res, scene, window)
    return m | {"surge_error": m["surge_amp"] / pot["surge_amp"] - 1.0,
                "heave_error": m["heave_amp"] / pot["heave_amp"] - 1.0,
                "tension_back_error": m["tension_back_N"] / pot["tension_back_N"] - 1.0,
                "tension_front_error": m["tension_front_N"] / pot["tension_front_N"] - 1.0,
                "gauge_height_error": float(np.max(np.abs(np.asarray(g["H1_over_H"]) - 1.0))),
                "gauge_lag_periods": float(np.max(np.abs(g["lag_periods"])))}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    run_arguments(ap)
    ap.add_argument("--variant", action="append", default=[], type=parse_variant,
                    help="LABEL:KEY=VALUE[,KEY=VALUE...] (repeatable)")
    ap.add_argument("--no-base", action="store_true", help="leave out the scene as written")
    a = ap.parse_args(argv)
    window = tuple(a.window)
    scene0 = case.sph_scene(False).with_values([f"fluid.dx={a.dx}", f"world.duration={a.duration}"])
    pot_scene = case.surface_scene(scene0, "potential")
    omega = 2.0 * math.pi / scene0.waves.period
    pot_res, _ = case.run_or_resume(pot_scene, a.out / "potential")
    pot = case.motion_figures(pot_res, window, omega) | phases(pot_res, window, omega)
    variants = ([] if a.no_base else [("base", [])]) + a.variant
    rows = []
    for label, sets in variants:
        scene = scene0.with_values(sets) if sets else scene0
        res, _ = case.run_or_resume(scene, a.out / label)
        row = {"variant": label, "sets": sets} | figures(res, scene, window, pot)
        print(json.dumps(row), flush=True)
        rows.append(row)
    print(f"potential fluid: surge {pot['surge_amp']:.3f} m, heave {pot['heave_amp']:.3f} m, pitch "
          f"{pot['pitch_amp']:.3f} deg; surge - heave {pot['surge_minus_heave_deg']:+.0f} deg, pitch - heave "
          f"{pot['pitch_minus_heave_deg']:+.0f} deg, Fx - Fz {pot['fluid_Fx_minus_Fz_deg']:+.0f} deg")
    print("| variant | surge [m] (vs potential) | heave [m] (vs potential) | pitch [deg] | surge / pitch / Fx phase "
          "[deg] | tensions back / front vs potential | gauges' height / lag [periods] | particles | steps | CPU [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['variant']} | {r['surge_amp']:.3f} ({r['surge_error']:+.1%}) | {r['heave_amp']:.3f} "
              f"({r['heave_error']:+.1%}) | {r['pitch_amp']:.3f} | {r['surge_minus_heave_deg']:+.0f} / "
              f"{r['pitch_minus_heave_deg']:+.0f} / {r['fluid_Fx_minus_Fz_deg']:+.0f} | {r['tension_back_error']:+.1%} / "
              f"{r['tension_front_error']:+.1%} | {r['gauge_height_error']:.1%} / {r['gauge_lag_periods']:.3f} | "
              f"{r['particles']} | {r['steps']} | {r['cpu_s']:.0f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
