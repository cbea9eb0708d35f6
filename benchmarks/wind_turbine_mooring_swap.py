"""Every mooring model on the flagship scene, on each fluid: the wind-turbine base of the
`wind-turbine-sph` case (Barreiro et al. 2016, §5) in its SPH near field, and the same base,
lines and sea on the potential-flow and analytic fluids (the case's ``surface_scene``), with
``moorings.model`` swapped (catenary, sph-cable, moordyn, fmu). Prints, per run, the surge,
heave and pitch first harmonics at the wave's period and the mean fairlead tensions over the
window (the case's ``motion_figures``), the lines' states, and the cost; then a markdown
table. Each run is kept in ``OUT/MODEL/FLUID`` and resumed or read back when the script is
run again (the case's ``run_or_resume``), so a long sweep can span sessions.

    python benchmarks/wind_turbine_mooring_swap.py --out OUT [--dx 1.25] [--duration 40]
        [--window 20 40] [--models catenary sph-cable moordyn fmu] [--fluids sph potential analytic]

The defaults are the case's quick variant (dx = 1.25 m, 40 s, window 20-40 s).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

from cosim.validations import wind_turbine_sph as case


def scene_for(model: str, fluid: str, dx: float, duration: float):
    """The case's wave scene at ``dx`` and ``duration`` with the mooring ``model``, on ``fluid``."""
    scene = case.sph_scene(False).with_values([f"fluid.dx={dx}", f"world.duration={duration}",
                                               f"moorings.model={model}"])
    return scene if fluid == "sph" else case.surface_scene(scene, fluid)


def run_arguments(ap: argparse.ArgumentParser) -> None:
    """The options of a wave run kept under ``--out`` at ``--dx`` for ``--duration``, its
    first harmonics read over ``--window``: the case's quick variant by default (also
    benchmarks/wind_turbine_levers.py's)."""
    ap.add_argument("--out", type=Path, required=True, help="folder of the runs (kept, resumed, read back)")
    ap.add_argument("--dx", type=float, default=case.RUNS[True][0])
    ap.add_argument("--duration", type=float, default=case.RUNS[True][1])
    ap.add_argument("--window", type=float, nargs=2, default=case.RUNS[True][3])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    run_arguments(ap)
    ap.add_argument("--models", nargs="+", default=["catenary", "sph-cable", "moordyn", "fmu"])
    ap.add_argument("--fluids", nargs="+", default=["sph", "potential", "analytic"])
    a = ap.parse_args(argv)
    rows = []
    for model in a.models:
        for fluid in a.fluids:
            scene = scene_for(model, fluid, a.dx, a.duration)
            res, _ = case.run_or_resume(scene, a.out / model / fluid)
            f = case.motion_figures(res, tuple(a.window), 2.0 * math.pi / scene.waves.period)
            row = {"model": model, "fluid": fluid} | f
            print(json.dumps(row), flush=True)
            rows.append(row)
    print("| mooring | fluid | surge [m] | heave [m] | pitch [deg] | back / front tension [kN] | lines' states "
          "(back, front) | particles | steps | CPU [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        states = ", ".join(str(r["line_events"][n]["state"]) for n in ("back", "front_port"))
        print(f"| {r['model']} | {r['fluid']} | {r['surge_amp']:.3f} | {r['heave_amp']:.3f} | {r['pitch_amp']:.3f} | "
              f"{r['tension_back_N'] / 1e3:.1f} / {r['tension_front_N'] / 1e3:.1f} | {states} | "
              f"{r['particles'] or '-'} | {r['steps']} | {r['cpu_s']:.0f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
