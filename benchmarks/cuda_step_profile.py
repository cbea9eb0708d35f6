"""Where a step of the GPU path's time goes: each kernel of fluid.cuda.kernels timed on its
own (the device synchronised before and after every launch), and the rest of the step
(host Python, the launches, the small copies a step makes) as the difference from the
step's wall time without that synchronisation. Not a test; the case is
benchmarks/fluid_throughput.py's dam break::

    python benchmarks/cuda_step_profile.py --case 3d --dp 0.00505 --steps 20   # a GPU
    NUMBA_ENABLE_CUDASIM=1 python benchmarks/cuda_step_profile.py --case 2d --dp 0.1 --steps 1  # the simulator

Prints the plain step's wall time, then each kernel's milliseconds a step and share of
the synchronised step, largest first.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from collections import defaultdict

_here = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _here]
sys.path.insert(0, _here)
import fluid_throughput as tp  # noqa: E402  (benchmarks/fluid_throughput.py, beside this script)
sys.path.pop(0)


class Timed:
    """A kernel whose launches are timed: the device synchronised before and after each."""

    def __init__(self, name: str, kernel, times: dict, counts: dict):
        self.name, self.kernel, self.times, self.counts = name, kernel, times, counts

    def __getitem__(self, launch_config):
        from numba import cuda

        launcher = self.kernel[launch_config]

        def call(*args):
            cuda.synchronize()
            t = time.perf_counter()
            launcher(*args)
            cuda.synchronize()
            self.times[self.name] += time.perf_counter() - t
            self.counts[self.name] += 1
        return call


def time_kernels(times: dict, counts: dict) -> None:
    """Replace every kernel of fluid.cuda.kernels (and the pair and gradient loops its
    factories make) by a :class:`Timed` one."""
    from fluid.cuda import kernels as K

    for name in dir(K):
        if name.startswith("k_"):
            setattr(K, name, Timed(name, getattr(K, name), times, counts))
    for factory in ("make_pair_loop", "make_gradient_loop"):
        make = getattr(K, factory)

        def timed_make(*key, _make=make, _name=factory.removeprefix("make_")):
            return Timed(_name, _make(*key), times, counts)
        setattr(K, factory, timed_make)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--case", choices=["2d", "3d"], default="3d")
    ap.add_argument("--dp", type=float, default=0.00505, help="particle spacing [m]")
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--integrator", choices=["verlet", "symplectic"], default="verlet")
    a = ap.parse_args()
    tp.DEVICE = "cuda"
    print(tp.device_line())
    from numba import cuda

    from fluid.solver import Fluid

    cfg, ps = tp.build(a.case, a.dp, a.integrator)
    f = Fluid(cfg, ps)
    f.initialize(0.0)

    def seconds_a_step() -> float:
        f.step(f.max_dt())  # compiles (the first time), or the timed launchers' first calls
        times.clear()
        counts.clear()
        cuda.synchronize()
        t = time.perf_counter()
        for _ in range(a.steps):
            f.step(f.max_dt())
        cuda.synchronize()
        return (time.perf_counter() - t) / a.steps

    times, counts = defaultdict(float), defaultdict(int)
    plain = seconds_a_step()
    time_kernels(times, counts)
    synced = seconds_a_step()
    n = f.device_memory["particles"]
    print(f"case={a.case} dp={a.dp} particles={n} integrator={a.integrator} steps={a.steps} "
          f"ms_per_step={1e3 * plain:.3f} (synchronised per kernel: {1e3 * synced:.3f}) "
          f"particle_steps_per_s={n / plain:.4g}")
    rest = synced - sum(times.values()) / a.steps
    rows = sorted(((v / a.steps, k) for k, v in times.items()), reverse=True) + [(rest, "(host and copies)")]
    for v, k in rows:
        calls = counts.get(k, 0) / a.steps
        print(f"  {1e3 * v:9.3f} ms  {100 * v / synced:5.1f} %  {k}" + (f"  x{calls:g}" if calls else ""))


if __name__ == "__main__":
    main()
