"""What writing outputs costs next to a fluid step: one H5Output series row, the probes
(pressure points, gauges, energy), one particle snapshot (time and bytes), for a 2-D tank
at rest. Not a test; prints one JSON object.

    NUMBA_NUM_THREADS=1 .venv/bin/python benchmarks/output_overhead.py [--dx 0.005] [--steps 50]
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import tempfile
import time

_here = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _here]  # no package shadowing


def main():
    import numpy as np

    from fluid.geometry import set_hydrostatic, tank_with_water
    from fluid.output import H5Output
    from fluid.probes import Energy, PressureProbe, WaveGauge
    from cosim.scene.runner import SNAPSHOT_FIELDS
    from fluid.solver import Fluid, FluidConfig

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dx", type=float, default=0.005, help="particle spacing [m]")
    ap.add_argument("--steps", type=int, default=50, help="fluid steps timed")
    ap.add_argument("--rows", type=int, default=20000, help="series rows timed")
    ap.add_argument("--snapshots", type=int, default=5, help="snapshots timed")
    a = ap.parse_args()

    g, H, L = 9.81, 0.5, 1.0
    b = tank_with_water(2, a.dx, L, H, 1.25 * H)
    cfg = FluidConfig(dim=2, dx=a.dx, u_max=math.sqrt(g * H), c0_factor=20.0)
    set_hydrostatic(b.particles, H, 1000.0, cfg.speed_of_sound, cfg.gamma, g)
    f = Fluid(cfg, b.particles)
    f.initialize(0.0)
    probes = [PressureProbe([[0.0, z] for z in np.linspace(0.05, 0.45, 8)]), WaveGauge([0.1, 0.5, 0.9]),
              Energy()]
    for p in probes:  # compile
        p.sample(f)
    f.advance(0.0, f.max_dt())

    t0 = time.perf_counter()
    for _ in range(a.steps):
        f.advance(f.t, f.max_dt())
    step_s = (time.perf_counter() - t0) / a.steps

    t0 = time.perf_counter()
    for _ in range(20):
        for p in probes:
            p.sample(f)
    probes_s = (time.perf_counter() - t0) / 20

    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "bench.h5")
        with H5Output(path, dim=2) as out:
            t0 = time.perf_counter()
            for k in range(a.rows):
                out.series("body", 1e-4 * k, x=0.1, z=0.2, theta=0.0, F=[1.0, 2.0])
            out.flush()
            row_s = (time.perf_counter() - t0) / a.rows
            ps = f.ps
            size0 = os.path.getsize(path)
            t0 = time.perf_counter()
            for k in range(a.snapshots):
                out.snapshot(0.1 * k, ps.pos, **{n: getattr(ps, n) for n in SNAPSHOT_FIELDS})
            snap_s = (time.perf_counter() - t0) / a.snapshots
        snap_bytes = (os.path.getsize(path) - size0) / a.snapshots
        xmf_bytes = os.path.getsize(os.path.join(tmp, "bench.xmf"))
    print(json.dumps({
        "particles": int(f.ps.n), "dx_m": a.dx, "numba_threads": int(os.environ.get("NUMBA_NUM_THREADS", 0)) or None,
        "fluid_step_ms": round(1e3 * step_s, 3),
        "series_row_us": round(1e6 * row_s, 2),
        "probes_ms": round(1e3 * probes_s, 3),
        "snapshot_ms": round(1e3 * snap_s, 2),
        "snapshot_bytes_per_particle": round(snap_bytes / f.ps.n, 1),
        "snapshot_MB": round(snap_bytes / 1e6, 3),
        "xmf_bytes_for_snapshots": xmf_bytes,
    }))


if __name__ == "__main__":
    main()
