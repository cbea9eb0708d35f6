"""nearfield-radiation at several spacings: does the heave damping B33 of the cylinder forced
in the SPH near field converge to the boundary-element reference as R/dx grows? The case's
scene (``cosim/validations/scenes/nearfield-radiation.toml``: the wind-turbine base's hull,
R = 3 m, forced 0.3 m at k R = 1) at each R/dx, read by the case's ``radiation_metrics``
(A33 and B33 from the force's first harmonic against Capytaine's, the radiated wave's
reflection and its amplitude against the one B33 carries). Each run is kept in
``OUT/R_over_dx_N`` and resumed from its checkpoint or read back when the script runs again
(``cosim.validations.case_scene.run_or_resume``): R/dx = 8 takes several CPU-hours (``cosim
run ... --dry-run`` estimates 2.2), and a run a stopped process leaves, the next one resumes.

    python benchmarks/radiation_convergence.py --out OUT [--r-over-dx 4 6 8] [--periods 3]

``--periods``: the periods run after the ramp (the case's 3); the fit takes the last two, so
a longer run shows whether B33 has settled or still swings with what the zones send back.

Prints one JSON line per run, then a markdown table.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from cosim.validations import case_scene
from cosim.validations.radiation import PERIODS_AFTER_RAMP, radiation_metrics, radiation_scene


def scene_at(r_over_dx: float, periods: float = PERIODS_AFTER_RAMP):
    """The case's full scene at ``R / dx = r_over_dx``, run ``periods`` periods after the ramp."""
    scene = radiation_scene(False)
    m = scene.bodies[0].motion
    return scene.with_values([f"fluid.dx={case_scene.number(scene.bodies[0].radius / r_over_dx)}",
                              f"world.duration={case_scene.number((m.ramp + periods) * m.period)}"])


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--out", type=Path, required=True, help="folder of the kept runs")
    p.add_argument("--r-over-dx", type=float, nargs="+", default=[4.0, 6.0, 8.0], help="radii per spacing")
    p.add_argument("--periods", type=float, default=PERIODS_AFTER_RAMP, help="periods run after the ramp")
    a = p.parse_args(argv)
    rows = []
    for r in a.r_over_dx:
        scene = scene_at(r, a.periods)
        tag = "" if a.periods == PERIODS_AFTER_RAMP else f"_{a.periods:g}periods"
        res, earlier = case_scene.run_or_resume(scene, a.out / f"R_over_dx_{r:g}{tag}")
        m = radiation_metrics(res, scene)
        keep = ("R_over_dx", "A33_kg", "A33_error", "B33_kg_s", "B33_error", "reflection", "particles", "steps",
                "cpu_s")
        row = {k: m.get(k) for k in keep} | {"cpu_s_earlier": earlier, "outgoing_over_B33": max(
            v["outgoing_over_theory"] for v in m["lines"].values())}
        print(json.dumps(row), flush=True)
        rows.append(row)
    print("\n| R/dx | A33 error | B33 error | reflection | outgoing / B33's | particles | steps | CPU s |")
    print("|---|---|---|---|---|---|---|---|")
    for w in rows:
        print(f"| {w['R_over_dx']:g} | {w['A33_error']:.1%} | {w['B33_error']:.1%} | {w['reflection']:.3f} | "
              f"{w['outgoing_over_B33']:.3f} | {w['particles']} | {w['steps']} | {w['cpu_s']:.0f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
