"""nearfield-floating-box's quick variant with ``coupling.fluid_steps = K`` on both of its
compared runs (the flume and the near field; the flume without the body, which has nothing
to exchange, at 1): what sub-cycling the fluid saves and what it moves. Not a test; prints
the case's metrics as JSON (docs/validation/nearfield.md, "Sub-cycling the fluid")::

    NUMBA_NUM_THREADS=1 python benchmarks/floating_box_fluid_steps.py 4
"""

from __future__ import annotations

import json
import sys
import time

import cosim.validations.nearfield as nf


def main(k: int) -> dict:
    flume, without = nf.floating_flume, nf._without_bodies
    nf.floating_flume = lambda quick: flume(quick).with_values([f"coupling.fluid_steps={k}"])
    nf._without_bodies = lambda scene, x: without(scene.with_values(["coupling.fluid_steps=1"]), x)
    t0 = time.process_time()
    m = nf.nearfield_floating_box(True)["metrics"]
    return {"fluid_steps": k, "cpu_s_total": time.process_time() - t0} | {
        q: m[q] for q in ("cpu_fraction", "heave_error", "surge_error", "heave_per_wave_error",
                          "surge_per_wave_error")} | {"runs": m["runs"]}


if __name__ == "__main__":
    print(json.dumps(main(int(sys.argv[1]) if sys.argv[1:] else 4), indent=1, default=float))
