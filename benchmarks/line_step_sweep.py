"""The coupling step swept on the wind-turbine base (examples/wind_turbine_base.toml, waves
0.01 m high: the lines' own dynamics, not the sea): for each mooring model, line
resolution, exchange (``coupling.lines``) and step, the base's largest angular speed
[rad/s] in each second, and whether it grows; beside the step the coupler derives
(cosim.line_step). Prints figures; asserts nothing.

    python benchmarks/line_step_sweep.py --model sph-cable --segments 20,40 --dt auto,2x,3x --lines subiterate,explicit

(``--dt``: steps [s], "auto" for the coupler's own, "2x" for twice it.) Verdict on the
last second's largest angular speed: "settled" below 1e-3 rad/s; else "grows" when it is
more than 3 times the second one's (the first holds the start's transient) or the run
stopped; else "limit cycle".

The measured sweep (SPH cable and MoorDyn, 20 and 40 nodes, sub-iterated and held, up to
four times the derived step) and what it shows: docs/benchmarks/line_step_sweep.md.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

SCENE = ROOT / "examples" / "wind_turbine_base.toml"


def sweep_one(model: str, segments: int, dt: str, seconds: float, lines: str = "auto") -> dict:
    """One run: the base's largest angular speed [rad/s] per second, the step taken. ``dt``:
    a step [s], "auto" (the coupler's own) or "Nx" (N times the coupler's own, the bound's
    check let through)."""
    import cosim.line_step as ls
    from cosim.scene import Scene
    from cosim.scene.build import build

    vals = [f"moorings.model={model}", f"moorings.segments={segments}", "waves.height=0.01", f"coupling.lines={lines}"]
    safety = dict(ls.SAFETY)
    if dt.endswith("x"):
        ls.SAFETY.update({k: v * float(dt[:-1]) for k, v in safety.items()})
    elif dt != "auto":
        vals += [f"coupling.dt={dt}", f"world.sample_every={dt}"]  # a step that lands on the samples
    try:
        built = build(Scene.from_toml(SCENE).with_values(vals), Path(tempfile.mkdtemp(prefix="line_step_")))
        lim = built.coupler.line_limit
        spin, ts, tries = [], [], []

        def watch(info):
            spin.append(float(np.abs(built.bodies.kinematics().omega).max()))
            ts.append(built.coupler.t)
            tries.append(built.coupler.line_iterations)

        c0 = time.process_time()
        try:
            built.coupler.run(seconds, watch)
            error = ""
        except Exception as exc:  # noqa: BLE001 - a run that stops is a result here
            error = f"{type(exc).__name__}: {str(exc)[:120]}"
    finally:
        ls.SAFETY.update(safety)
    spin, ts = np.array(spin), np.array(ts)
    per_s = [float(spin[(ts > k) & (ts <= k + 1)].max(initial=0.0)) for k in range(int(seconds))]
    if not error and per_s[-1] < 1e-3:
        verdict = "settled"
    elif error or (len(per_s) > 2 and per_s[-1] > 3 * per_s[1]):
        verdict = "grows"
    else:
        verdict = "limit cycle"
    return {"derived_dt": lim.dt if lim else float("nan"), "per_s": per_s, "verdict": verdict, "error": error,
            "cpu_s": time.process_time() - c0, "advances": float(np.mean(tries)) if tries else 0.0}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--model", default="sph-cable", help="moorings.model: sph-cable, moordyn")
    ap.add_argument("--segments", default="20", help="comma-separated moorings.segments")
    ap.add_argument("--dt", default="auto", help="comma-separated coupling steps [s] ('auto': the coupler's own, "
                                                     "'2x': twice it)")
    ap.add_argument("--lines", default="subiterate", help="comma-separated coupling.lines: subiterate, explicit")
    ap.add_argument("--seconds", type=float, default=6.0)
    a = ap.parse_args(argv)
    for lines in a.lines.split(","):
        for n in [int(s) for s in a.segments.split(",")]:
            for dt in a.dt.split(","):
                r = sweep_one(a.model, n, dt, a.seconds, lines)
                spins = " ".join(f"{v:.2g}" for v in r["per_s"])
                print(f"{a.model} {n} segments, lines {lines}, dt {dt} (derived {r['derived_dt']:.4g} s): max |omega| "
                      f"per second [rad/s] {spins} -> {r['verdict']} {r['error']} ({r['cpu_s']:.1f} CPU-s, "
                      f"{r['advances']:.2f} advances of the lines a step)", flush=True)


if __name__ == "__main__":
    main()
