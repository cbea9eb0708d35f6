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

Measured (2026-11-26, AMD EPYC, 2 cores, loaded), per second over 6 s; the sub-iterated
exchange (the default, ``Coupler.LINES_TOL`` 1e-5) first, the lines' force held
(``--lines explicit``) after:

=========================  ============  ==============================  ========  ========  ======
model, nodes               step          max |omega| per second [rad/s]  verdict   advances  CPU-s
                                                                                  per step
=========================  ============  ==============================  ========  ========  ======
SPH cable 20, sub-iter.    auto 0.0061   1.1e-6 ... 1.6e-6               settled   1.74      5.0
SPH cable 20, sub-iter.    2x  0.0122    1.1e-6 ... 1.4e-6               settled   2.02      2.4
SPH cable 20, sub-iter.    3x  0.0183    0.021 0.027 ... 0.027           cycle     9.57      4.3
SPH cable 20, sub-iter.    4x  0.0245    3.6e-6 2.1e-5 ... 0.0071        grows     6.53      2.5
SPH cable 40, sub-iter.    auto 0.0061   8.2e-7 ... 1.9e-6               settled   2.26      6.3
SPH cable 40, sub-iter.    2x  0.0121    9.1e-7 ... 2.8e-6               settled   2.44      3.0
SPH cable 40, sub-iter.    3x / 4x       0.024 / 0.0063 (last)           cycle     8.8-9.4   4.1-5.4
MoorDyn 20, sub-iter.      auto 0.0050   1.3e-6 ... 1.9e-6               settled   1.59      6.1
MoorDyn 20, sub-iter.      2x / 3x / 4x  1.3e-6 ... 6.6e-6               settled   1.9-2.3   1.9-3.7
MoorDyn 40, sub-iter.      auto 0.0049   1.9e-5 2.8e-6 ... 2.6e-6        settled   2.24      9.1
MoorDyn 40, sub-iter.      2x / 3x / 4x  4.1e-6 ... 4.4e-5               settled   2.4-2.9   4.1-6.3
SPH cable 20, held         auto 0.0061   3.1e-6 3.5e-4 0.022 0.028 ...   cycle     1         3.5
MoorDyn 20, held (lead)    auto 0.0050   8.3e-7 ... 9.4e-7               settled   1         5.1
MoorDyn 20, held (lead)    2x  0.0100    0.072 0.13 ... 0.13             cycle     1         2.7
MoorDyn 20 / 40, held      3x, 4x        stopped by the coupler's watch  grows     1         <1
MoorDyn 40, held (lead)    auto 0.0049   2.6e-5 5.9e-7 ... 1.2e-6        settled   1         6.2
MoorDyn 40, held (lead)    2x  0.0099    0.066 ... 0.11, stopped at 4.3 s grows    1         2.5
=========================  ============  ==============================  ========  ========  ======

With the force held, the SPH cable holds a ~28 Hz limit cycle at the derived step (the
tensions swinging by some 100 kN; at 0.001 s it settles, 3e-5 rad/s); the bound takes the
line for a semi-infinite bar, whose radiation damps the base, but the wave the fairlead
sends comes back from the anchor within four steps. MoorDyn settles with the held force
only through its adapter's one-step lead (given the step's own start and end, 0.032-0.047
rad/s), and not at twice the derived step. Advanced with the base until their mean force
agrees (the default), both settle at the derived step and at twice it, MoorDyn up to four
times it; the SPH cable holds a limit cycle again at three times it.
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
