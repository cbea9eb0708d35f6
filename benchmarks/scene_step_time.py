"""Wall time of a scene's coupled step and the pair loop's share of it, under the thread
count numba is given (``NUMBA_NUM_THREADS``): run it once per thread count, alternately,
to see how far a scene's step scales with threads (the pair loop does, the rest of the
step, written as one parallel loop per task over all particles, much less). The scene is
built as ``cosim run`` builds it, stepped ``--warm`` simulated seconds to compile and
settle, then ``--blocks`` blocks of ``--block`` simulated seconds each are timed, and the
fastest and the median block summed up (on a machine whose speed moves from block to block
the fastest is the code's, the median the machine's). Not a test.

    NUMBA_NUM_THREADS=1 python benchmarks/scene_step_time.py SCENE.toml [--set KEY=VALUE ...]
    NUMBA_NUM_THREADS=2 python benchmarks/scene_step_time.py SCENE.toml
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

import numba

import fluid.equations as eq
from cosim.scene.build import build
from cosim.scene.load import load
from machine import cpu_name  # benchmarks/machine.py, beside this script


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("scene", type=Path)
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    ap.add_argument("--warm", type=float, default=0.02, help="simulated seconds before timing [s]")
    ap.add_argument("--block", type=float, default=0.05, help="simulated seconds per timed block [s]")
    ap.add_argument("--blocks", type=int, default=3)
    a = ap.parse_args(argv)
    scene = load(a.scene)
    if a.set:
        scene = scene.with_values(a.set)
    spent = [0.0]
    pair_loop = eq.interact

    def timed(*args, **kw):  # the pair loop, as evaluate calls it
        t0 = time.perf_counter()
        try:
            return pair_loop(*args, **kw)
        finally:
            spent[0] += time.perf_counter() - t0

    eq.interact = timed
    print(cpu_name(), f"numba threads {numba.config.NUMBA_NUM_THREADS}", flush=True)
    with tempfile.TemporaryDirectory(prefix="cosim-step-time-") as work:
        c = build(scene, Path(work)).coupler
        c.run(c.t + a.warm)
        per_step = []
        for _ in range(a.blocks):
            spent[0] = 0.0
            s0, w0, p0 = c.steps, time.perf_counter(), time.process_time()
            c.run(c.t + a.block)
            wall, n = time.perf_counter() - w0, c.steps - s0
            per_step.append(wall / n * 1e3)
            print(f"{wall / n * 1e3:.1f} ms a step (CPU / wall {(time.process_time() - p0) / wall:.2f}), pair loops "
                  f"{spent[0] / n * 1e3:.1f} ms, the rest {(wall - spent[0]) / n * 1e3:.1f} ms ({n} steps)", flush=True)
    print(f"over {a.blocks} blocks: fastest {min(per_step):.3f}, median {statistics.median(per_step):.3f} ms a step")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
