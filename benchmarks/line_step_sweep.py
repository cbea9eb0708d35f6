"""The coupling step swept on the wind-turbine base (examples/wind_turbine_base.toml, waves
0.01 m high: the lines' own dynamics, not the sea): for each mooring model, line
resolution and step, the base's largest angular speed [rad/s] in each second, and whether
it grows; beside the step the coupler derives (cosim.line_step). Prints figures; asserts
nothing.

    python benchmarks/line_step_sweep.py --model sph-cable --segments 20,40 --dt auto,0.004,0.003,0.001 [--seconds 6]

Verdict on the last second's largest angular speed: "settled" below 1e-3 rad/s; else
"grows" when it is more than 3 times the second one's (the first holds the start's
transient) or the run stopped; else "limit cycle".

Measured (2026-11-26, AMD EPYC, 2 cores, loaded), per second over 6 s (4 s where shorter):

- MoorDyn, 20 segments, derived 0.0050 s: 8e-7 ... 9e-7 rad/s, settled (as at 0.001 s);
  40 segments: 2.6e-5 then 3e-7 ... 1.2e-6, settled. With the adapter's one-step lead taken
  out (MoorDyn given the step's start and end), 0.032-0.036 (20) and 0.039-0.047 (40): the
  same limit cycle as the SPH cable's; the lead is what settles it.
- SPH cable, 20 nodes, derived 0.0061 s: 0.030 0.036 0.025 0.030 0.026 0.031, a limit
  cycle (the tensions swing by some 100 kN at ~28 Hz); 0.0037 s: 0.016 sustained; 0.003 s:
  0.017 0.0081 0.0091 0.011; 0.002 s: 0.012 0.0028 0.0011 0.00048 (decaying); 0.001 s:
  0.0039 0.00043 9.9e-5 4.8e-5 2.5e-5 3.2e-5. With visc_alpha = 3 (its dashpot 3 times
  larger, derived step 0.0037 s): 0.0024 2.2e-5 1.2e-5 9.4e-6, settled.
- SPH cable, 40 nodes, derived 0.0061 s: 0.048 0.039 0.034 0.034 0.028 0.031; 0.001 s:
  0.0055 0.0039 0.0023 0.0015 0.0011 0.00076 (decaying).

The derived bound (``2 M / c``, the line a semi-infinite bar whose radiation damps the
base) does not hold for the SPH cable: the wave the fairlead sends comes back from the
anchor within four coupling steps. More axial damping settles it (above); MoorDyn has 0.8
of critical per segment, and its adapter leads the fairlead by one step.
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
        vals.append(f"coupling.dt={dt}")
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
