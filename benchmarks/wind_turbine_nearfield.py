"""The wind-turbine base of Barreiro et al. 2016 (§5) in its 3-D SPH near field
(``benchmarks/wind_turbine_nearfield.toml``): what each lever on its cost gives,
variants run alternately in one process so that their CPU seconds compare.

    python benchmarks/wind_turbine_nearfield.py --dx 1.5 --duration 2 \\
        --variant whole:domain.symmetry=false --variant half:domain.symmetry=true
    python benchmarks/wind_turbine_nearfield.py --dx 1.5 --duration 5 --offset 0.3 \\
        --variant auto:coupling.light_body=auto --variant none:coupling.light_body=none

A variant is ``NAME:KEY=VALUE,KEY=VALUE`` (scene fields, as ``cosim run --set``).
``--offset``: the base starts that far [m] above its floating height (a free heave decay:
the hardest test of a coupling's stability with added mass), and the variants' heave is
compared against the first's. Prints, per run, the particles, the coupling steps, the CPU
seconds (every thread's, compilation included in the first run: ``--warm`` runs a short
one first), the CPU per simulated second and the 90 s run extrapolated from it, and the
base's heave; then one JSON line per run. The figures measured: docs/validation/nearfield.md.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

import numpy as np

from benchmarks.machine import cpu_name
from cosim.scene import Scene

SCENE = Path(__file__).with_name("wind_turbine_nearfield.toml")


def _scene(dx: float, duration: float, offset: float, changes: list[str]):
    from cosim.scene.build import water_level
    from cosim.scene.nearfield import box_for
    from cosim.scene.placement import floating_height

    s = Scene.from_toml(SCENE).with_values([f"fluid.dx={dx}", f"world.duration={duration}", *changes])
    if offset:  # the box the floating base gets (a body placed at a given height has no heave period to size it)
        c = box_for(s)
        b, mine = s.bodies[0], list(s.moorings.lines)
        z = floating_height(b, 3, water_level(s), s.fluid.rho0, s.world.gravity, mine)
        width = 2.0 * (c.y[1] - c.y[0]) if s.domain.symmetry else c.y[1] - c.y[0]
        s = s.with_values(["bodies[0].place=given", f"bodies[0].pos=[{b.pos[0]}, {b.pos[1]}, {z + offset}]",
                           f"domain.x0={c.x[0]}", f"domain.x1={c.x[1]}", f"domain.width={width}",
                           f"domain.zone={c.zone}", f"domain.height={c.height}"])
    return s


def run_variant(dx, duration, offset, name, changes, out_dir) -> dict:
    from errors import InstabilityError

    s = _scene(dx, duration, offset, changes)
    c0 = time.process_time()
    try:
        res = s.run(out=out_dir / name, yes=True)
    except InstabilityError as e:  # a result: the variant cannot run this scene
        return {"variant": name, "changes": changes, "dx_m": dx, "duration_s": duration, "offset_m": offset,
                "unstable": str(e), "cpu_s": round(time.process_time() - c0, 1)}
    cpu = time.process_time() - c0
    sm = res.summary
    heave = np.asarray(res["base.heave"])
    return {"variant": name, "changes": changes, "dx_m": dx, "duration_s": duration, "offset_m": offset,
            "particles": sm["particles"], "fluid_particles": sm["fluid_particles"],
            "coupling_steps": sm["coupling"]["steps"], "remedies": sm.get("remedies"), "cpu_s": round(cpu, 1),
            "cpu_s_per_s": round(cpu / duration, 2), "cpu_h_90s": round(cpu / duration * 90.0 / 3600.0, 2),
            "t": np.asarray(res.t).tolist(), "heave_m": heave.tolist()}


def main(argv=None) -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--dx", type=float, default=1.5, help="particle spacing [m]")
    p.add_argument("--duration", type=float, default=2.0, help="simulated time per run [s]")
    p.add_argument("--offset", type=float, default=0.0, help="start the base this far above floating [m]")
    p.add_argument("--variant", action="append", default=[], metavar="NAME:KEY=VALUE,...")
    p.add_argument("--repeat", type=int, default=1, help="rounds of the variants, alternated")
    p.add_argument("--warm", action="store_true", help="a short run first, so that no variant pays compilation")
    a = p.parse_args(argv)
    variants = [(v.split(":", 1)[0], [c for c in v.split(":", 1)[1].split(",") if c]) for v in a.variant]
    variants = variants or [("half", ["domain.symmetry=true"])]
    print(f"CPU: {cpu_name()}")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        if a.warm:
            run_variant(a.dx, 0.2, 0.0, "warm", variants[0][1], Path(tmp))
        for r in range(a.repeat):
            for name, changes in variants:
                row = run_variant(a.dx, a.duration, a.offset, f"{name}-{r}", changes, Path(tmp))
                rows.append(row)
                if "unstable" in row:
                    print(f"{row['variant']:>12}: stopped after {row['cpu_s']} CPU-s: {row['unstable']}", flush=True)
                    continue
                print(f"{row['variant']:>12}: {row['particles']} particles ({row['fluid_particles']} fluid), "
                      f"{row['coupling_steps']} steps, {row['cpu_s']} CPU-s, {row['cpu_s_per_s']} CPU-s per s, "
                      f"90 s: {row['cpu_h_90s']} CPU-h; heave {min(row['heave_m']):+.4f} .. {max(row['heave_m']):+.4f} m",
                      flush=True)
    ran = [row for row in rows if "unstable" not in row]
    ref = np.asarray(ran[0]["heave_m"]) if ran else np.zeros(0)
    for row in ran:
        h = np.asarray(row["heave_m"])
        n = min(len(h), len(ref))
        row["heave_vs_first_max_m"] = float(np.abs(h[:n] - ref[:n]).max())
    for row in rows:
        print(json.dumps({k: v for k, v in row.items() if k not in ("t", "heave_m")}))


if __name__ == "__main__":
    main()
