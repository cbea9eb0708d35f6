"""Throughput of the SPH fluid: particle-steps per second (particles x steps / wall s) for
2-D and 3-D dam breaks at a few sizes, compilation reported apart, and memory per particle.
Not a test.

Reference case of issue 3 (2-D): water column 1 m wide, 2 m high in a tank 4 m x 3 m,
Wendland h = sqrt(2) dp, alpha = 0.02, Fourtakas delta = 0.1, c0 = 20 sqrt(2 g) m/s, CFL 0.2,
dp = 0.01 m (22 008 particles) and 0.005 m (82 008). 3-D: column 0.5 x 0.5 x 1 m in a tank
2 x 0.5 x 1.5 m, dp = 0.017 m: 107 012 particles (48 778 fluid), the size of DualSPHysics'
3-D dam break of issue 3. Verlet time stepping as in the reference case (one pair loop per
step); ``--integrator symplectic`` for the predictor-corrector (two pair loops per step):
compare ``pair_loops_per_s`` across the two.

The machine may be shared: ``cpu_s_per_wall_s`` below the thread count says so, and
``particle_steps_per_cpu_s`` (particles x steps / CPU seconds of this process) is then the
figure to compare between runs with ``--threads 1`` (alternate the runs being compared).
``--threads N`` sets NUMBA_NUM_THREADS, so that no idle worker thread spins on the CPU.

The current figures against DualSPHysics 5.4, the speed-up from 1 to 2 threads, bytes per
particle, where a step's time goes, and the optional terms' costs: docs/benchmarks/fluid_throughput_history.md.

    .venv/bin/python benchmarks/fluid_throughput.py                 # default sizes, warm numba cache
    .venv/bin/python benchmarks/fluid_throughput.py --cold          # compile from scratch (empty cache)
    .venv/bin/python benchmarks/fluid_throughput.py --case 2d --dp 0.01 --steps 200 --threads 2
    .venv/bin/python benchmarks/fluid_throughput.py --case 3d --steps 4 --speedup 16  # 1 -> 2 threads

GPU (``--device cuda``; fluid.cuda, numba-cuda, which lists what it covers): the same
cases stepped on an NVIDIA GPU; it prints the device (or that it is numba's CUDA simulator,
NUMBA_ENABLE_CUDASIM=1, whose timings are meaningless) and ``bytes_per_particle`` from the
arrays the device state allocated; benchmarks/gpu_session.sh measures them on a GPU machine.

    NUMBA_ENABLE_CUDASIM=1 python benchmarks/fluid_throughput.py --device cuda --case 2d --dp 0.05 --steps 2  # simulator
    python benchmarks/fluid_throughput.py --device cuda --case 3d --dp 0.017 --steps 200                   # a GPU
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import tempfile
import time

# run as a script, this file's folder comes first on sys.path and its name would shadow the
# ``fluid`` package: drop that folder
_here = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _here]
sys.path.insert(0, _here)
from machine import cpu_name, vector_extensions  # noqa: E402  (benchmarks/machine.py, beside this script)
sys.path.pop(0)


#: where the fluid steps (--device): FluidConfig.device
DEVICE = "cpu"


def device_line() -> str:
    """What runs ``--device cuda``: the GPU's name, compute capability and memory, or numba's
    CUDA simulator; exits with the reason where neither is there."""
    from fluid.cuda import availability, simulator

    why = availability()
    if why is not None:
        raise SystemExit(f"--device cuda: {why}")
    from numba import cuda
    if simulator():
        return ("device: numba's CUDA simulator (NUMBA_ENABLE_CUDASIM=1): every kernel runs in Python, the timings "
                "below are meaningless")
    d = cuda.get_current_device()
    free, total = cuda.current_context().get_memory_info()
    name = d.name.decode() if isinstance(d.name, bytes) else d.name
    return (f"device: {name}, compute capability {d.compute_capability[0]}.{d.compute_capability[1]}, "
            f"{total / 2**30:.1f} GiB ({free / 2**30:.1f} GiB free)")


def build(case: str, dp: float, integrator: str = "verlet", nu: float = 0.0, xsph_eps: float = 0.0,
          wall_model: str = "dbc", precision: str = "float64", wall_loads: bool = True):
    import numpy as np

    from fluid.geometry import assemble, block, set_hydrostatic, tank_walls
    from fluid.particles import Kind
    from fluid.solver import FluidConfig

    g = 9.81
    if case == "2d":
        inner_lo, inner_hi = np.zeros(2), np.array([4.0, 3.0])
        col = block([0.0, 0.0], [1.0, 2.0], dp)
        H = 2.0
    else:  # 3-D dam break: column 0.5 x 0.5 x 1 m in a tank 2 x 0.5 x 1.5 m
        inner_lo, inner_hi = np.zeros(3), np.array([2.0, 0.5, 1.5])
        col = block([0.0, 0.0, 0.0], [0.5, 0.5, 1.0], dp)
        H = 1.0
    walls = tank_walls(inner_lo, inner_hi, dp, layers=2)
    b = assemble(len(inner_lo), dp, 1000.0, col, [(walls, Kind.FIXED_WALL, 0)])
    cfg = FluidConfig(dim=len(inner_lo), dx=dp, device=DEVICE, c0=20 * math.sqrt(g * H), alpha=0.02, delta=0.1,
                      diffusion="fourtakas", cfl=0.2, integrator=integrator, nu=nu, xsph_eps=xsph_eps, walls=wall_model,
                      precision=precision, wall_loads=wall_loads,
                      domain_lo=tuple(inner_lo - 0.1), domain_hi=tuple(inner_hi + 0.5))
    set_hydrostatic(b.particles, H, 1000.0, cfg.speed_of_sound, cfg.gamma, g)
    return cfg, b.particles


def run(case: str, dp: float, steps: int, integrator: str = "verlet", nu: float = 0.0, xsph_eps: float = 0.0,
        walls: str = "dbc", precision: str = "float64", wall_loads: bool = True) -> dict:
    from fluid.particles import Kind
    from fluid.solver import Fluid

    cfg, ps = build(case, dp, integrator, nu, xsph_eps, walls, precision, wall_loads)
    t0 = time.perf_counter()
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    f.step(f.max_dt())  # the first step compiles (or loads from the cache) whatever is left
    t_first = time.perf_counter() - t0
    t1, c1 = time.perf_counter(), time.process_time()
    for _ in range(steps):
        f.step(f.max_dt())
    wall = time.perf_counter() - t1
    cpu = time.process_time() - c1
    n = f.ps.n
    per_step = wall / steps
    # every array the fluid keeps between steps: particles, the integrator's saved state,
    # the pair loop's workspace (packed table, rates) and the cell list
    if DEVICE == "cuda":  # every array of the device state (fluid.cuda.state), the cells' included
        mem = f.device_memory["total_bytes"]
    else:
        arrays = [getattr(f.ps, k) for k in f.ps.FIELDS] + list(f._aux.values()) \
            + list(f._work.arrays.values()) + [f._start]
        mem = sum(a.nbytes for a in arrays)
    return {
        "case": case, "dp_m": dp, "particles": n,
        "fluid": int((f.ps.kind == Kind.FLUID).sum()), "steps": steps,
        "dt_s": f.max_dt(), "limiter": f.limit.limiter,
        "first_step_s": round(t_first - per_step, 3),
        "ms_per_step": round(per_step * 1e3, 3),
        "particle_steps_per_s": round(n * steps / wall),
        "pair_loops_per_s": round((2 if integrator == "symplectic" else 1) * n * steps / wall),
        "integrator": integrator, "precision": precision, "nu": nu, "xsph_eps": xsph_eps, "walls": walls,
        "wall_loads": wall_loads,
        "particle_steps_per_cpu_s": round(n * steps / cpu),
        "cpu_s_per_wall_s": round(cpu / wall, 2),  # < threads: the machine is shared
        "bytes_per_particle": round(mem / n),
        "threads": __import__("numba").get_num_threads(),
    }


def profile(case: str, dp: float, steps: int, integrator: str = "verlet", precision: str = "float64") -> dict:
    """CPU seconds of each part of a step, summed over ``steps`` steps after a warm-up one,
    as shares of the whole: every part's function is wrapped with a CPU-time counter."""
    import fluid.equations as eq
    import fluid.neighbours as nb
    import fluid.solver as sv
    from fluid.particles import ParticleSet
    from fluid.solver import Fluid

    cost = {}

    def timed(name, fn):
        def wrapper(*args, **kw):
            c0 = time.process_time()
            try:
                return fn(*args, **kw)
            finally:
                cost[name] = cost.get(name, 0.0) + time.process_time() - c0
        return wrapper

    parts = [(nb, "bin_particles", "sort: binning"), (nb, "counting_sort", "sort: counting sort"),
             (nb, "order_cells_by_x", "sort: x-order in cells, sub-bin table"),
             (ParticleSet, "permute", "gather (reorder every array)"), (eq, "pack", "packing (EOS, table)"),
             (eq, "pack_f32", "packing (float32 table)"),
             (eq, "interact", "pair loop"), (sv, integrator if integrator == "verlet" else "predictor", "integrator"),
             (sv, "corrector", "integrator"), (sv, "stable_dt", "time step"),
             (sv, "first_non_finite", "NaN check"), (Fluid, "_group_sums", "group loads")]
    saved = [(m, a, getattr(m, a)) for m, a, _ in parts]
    cfg, ps = build(case, dp, integrator, precision=precision)
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    f.step(f.max_dt())
    try:
        for m, a, name in parts:
            setattr(m, a, timed(name, getattr(m, a)))
        c0 = time.process_time()
        for _ in range(steps):
            f.step(f.max_dt())
        total = time.process_time() - c0
    finally:
        for m, a, fn in saved:
            setattr(m, a, fn)
    cost["rest (Python, allocation)"] = total - sum(cost.values())
    return {"particles": f.ps.n, "steps": steps, "cpu_s_per_step": total / steps,
            "shares": {k: v / total for k, v in sorted(cost.items(), key=lambda kv: -kv[1])}}


def speedup(case: str, dp: float, steps: int, blocks: int) -> dict:
    """Wall time per step on one thread and on all of numba's, in ``blocks`` pairs of
    ``steps`` steps alternating inside one process (``numba.set_num_threads``), so that both
    see the same particles and the same moment's machine; the speed-up of each pair."""
    import numba
    import numpy as np

    from fluid.solver import Fluid

    cfg, ps = build(case, dp)
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    most = numba.config.NUMBA_NUM_THREADS
    for t in (1, most):  # compile, and wake the threads
        numba.set_num_threads(t)
        f.step(f.max_dt())
    per = {1: [], most: []}
    for b in range(blocks):
        for t in ((1, most) if b % 2 == 0 else (most, 1)):
            numba.set_num_threads(t)
            t0 = time.perf_counter()
            for _ in range(steps):
                f.step(f.max_dt())
            per[t].append((time.perf_counter() - t0) / steps)
    ratio = np.array(per[1]) / np.array(per[most])
    return {"particles": f.ps.n, "threads": most, "ms_per_step_1": 1e3 * float(np.median(per[1])),
            "ms_per_step_n": 1e3 * float(np.median(per[most])), "speedup_median": float(np.median(ratio)),
            "speedup_quartiles": (float(np.percentile(ratio, 25)), float(np.percentile(ratio, 75))),
            "load_avg_1min": os.getloadavg()[0]}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--case", choices=["2d", "3d", "all"], default="all")
    ap.add_argument("--dp", type=float, action="append", help="particle spacing [m] (repeatable)")
    ap.add_argument("--steps", type=int, default=50, help="timed steps per size")
    ap.add_argument("--threads", type=int, default=None, help="numba threads (default: all)")
    ap.add_argument("--cold", action="store_true", help="compile from scratch in an empty numba cache")
    ap.add_argument("--integrator", choices=["verlet", "symplectic"], default="verlet")
    ap.add_argument("--nu", type=float, default=0.0, help="laminar viscosity [m^2/s] (0: off, as the reference case)")
    ap.add_argument("--xsph", type=float, default=0.0, help="XSPH epsilon [-] (0: off, as the reference case)")
    ap.add_argument("--walls", choices=["dbc", "adami"], default="dbc",
                    help="tank-wall densities (FluidConfig.walls; dbc: the reference case)")
    ap.add_argument("--wall-loads", choices=["on", "off"], default="on",
                    help="the fluid's load on the walls computed (FluidConfig.wall_loads; off: the walls get their "
                         "continuity rate and viscous step bound only, as DualSPHysics' fixed boundaries)")
    ap.add_argument("--precision", choices=["float64", "float32"], default="float64",
                    help="arithmetic of the pair terms (FluidConfig.precision)")
    ap.add_argument("--profile", action="store_true",
                    help="print each part's share of a step's CPU time (run it with --threads 1)")
    ap.add_argument("--speedup", type=int, default=0, metavar="BLOCKS",
                    help="the step's speed-up from 1 thread to all: BLOCKS pairs of --steps steps, alternating "
                         "in one process (needs a quiet machine)")
    ap.add_argument("--device", choices=["cpu", "cuda"], default="cpu",
                    help="where the fluid steps (FluidConfig.device; cuda: numba-cuda, or its simulator with "
                         "NUMBA_ENABLE_CUDASIM=1)")
    a = ap.parse_args(argv)
    if a.cold:
        os.environ["NUMBA_CACHE_DIR"] = tempfile.mkdtemp(prefix="numba_cold_")
    if a.threads:
        os.environ["NUMBA_NUM_THREADS"] = str(a.threads)
    import numba
    t0 = time.perf_counter()
    import fluid.solver  # noqa: F401  (imports numba modules; compilation is lazy)
    print(f"import: {time.perf_counter() - t0:.2f} s; numba cache {'cold' if a.cold else 'as found'}")
    print(f"cpu: {cpu_name()}; vector extensions: {' '.join(vector_extensions()) or 'none found'}; "
          f"{os.cpu_count()} cores; numba {numba.__version__}")
    global DEVICE
    DEVICE = a.device
    if a.device == "cuda":
        print(device_line())
    sizes = {"2d": a.dp or [0.01, 0.005], "3d": a.dp or [0.017]}
    cases = ["2d", "3d"] if a.case == "all" else [a.case]
    for c in cases:
        for dp in sizes[c]:
            if a.speedup:
                r = speedup(c, dp, a.steps, a.speedup)
                q = r["speedup_quartiles"]
                print(f"{c} dp={dp} particles={r['particles']} 1 thread {r['ms_per_step_1']:.1f} ms/step, "
                      f"{r['threads']} threads {r['ms_per_step_n']:.1f} ms/step: speed-up median "
                      f"{r['speedup_median']:.2f} (quartiles {q[0]:.2f}-{q[1]:.2f}) "
                      f"load_avg_1min={r['load_avg_1min']:.2f}")
                continue
            if a.profile:
                r = profile(c, dp, a.steps, a.integrator, a.precision)
                print(f"{c} dp={dp} particles={r['particles']} steps={r['steps']} "
                      f"cpu_ms_per_step={1e3 * r['cpu_s_per_step']:.1f} threads={numba.get_num_threads()} "
                      f"load_avg_1min={os.getloadavg()[0]:.2f}")
                for k, v in r["shares"].items():
                    print(f"  {100 * v:5.1f} %  {k}")
                continue
            r = run(c, dp, a.steps, a.integrator, a.nu, a.xsph, a.walls, a.precision, a.wall_loads == "on")
            r["load_avg_1min"] = round(os.getloadavg()[0], 2)  # other work on the machine
            r["device"] = DEVICE
            print(" ".join(f"{k}={v}" for k, v in r.items()))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
