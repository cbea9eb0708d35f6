"""Verlet's density-diffusion step limit at several safety margins (issue 20): how far below
the edge ``z_N h^2 / (5.8 nu_eff)`` that ``fluid.integrator``'s docstring derives the Verlet
``C`` of ``diffusion_coefficient`` must stay before the dam breaks grow density noise, and
what each margin gives per simulated second. Prints figures; asserts nothing (the margin is
patched in this process and its children only).

``--margin m`` sets the Verlet ``C`` to ``z_N / (5.8 m)``: 2.75 is Morris' factor (the
default until these figures), 1.5 the default now (``fluid.integrator.VERLET_MARGIN``), 1.0
the derived edge, ``inf`` no limit (as DualSPHysics). The predictor-corrector's C is left
alone.

``fluid``: the dam breaks of benchmarks/fluid_throughput.py (its ``build``: Verlet,
reset every 40 steps, alpha 0.02, Fourtakas delta 0.1, c0 = 20 sqrt(g H), CFL 0.2, DBC),
one thread, run to ``--t-end`` [s]. Per margin: the mean step, the limiters' shares,
particle-steps and simulated seconds per CPU-second of the steps alone, and at intervals
a density-noise measure: ``noise`` = RMS over fluid particles (by id) of
``(rho - mean of rho over the last 8 steps) / rho0`` (Verlet's odd/even mode and any
growing instability show in it; where stable it is the flow's own change over 8 steps, so
it scales with the step), its largest value in the interval, ``max |rho - rho0| / rho0``
and the largest fluid speed. ``--cfl`` raises the build's CFL factor 0.2, so that the
diffusion limit, not the CFL, sets the step at margins near 1.

``validations``: the quick validation cases, run with every SPH fluid forced to Verlet
(none of the validation scenes uses Verlet: ``grep -ri verlet cosim``), in a child process
per case and margin, one thread: their judged metrics side by side and CPU seconds.

One thread unless NUMBA_NUM_THREADS says otherwise::

    python benchmarks/verlet_diffusion_margin.py fluid --case 2d --t-end 0.3 --every 0.03
    python benchmarks/verlet_diffusion_margin.py fluid --case 3d --t-end 0.1 --every 0.01
    python benchmarks/verlet_diffusion_margin.py fluid --case 2d --cfl 0.4 --t-end 0.1 --margin 1 --margin 0.75
    python benchmarks/verlet_diffusion_margin.py validations --margin 2.75 --margin 1 --margin inf

The measured steps, noise and costs per margin, and the conclusion (margin 1.0 is the real
edge and not safe; 1.5, the default, is): docs/benchmarks/verlet_diffusion_margin.md.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from pathlib import Path

os.environ.setdefault("NUMBA_NUM_THREADS", "1")  # before numba is imported
ROOT = Path(__file__).resolve().parents[1]
_here = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _here]  # ``fluid`` not shadowed
sys.path.insert(0, _here)
from validation_child import run_child  # noqa: E402  (beside this script)
import fluid_throughput  # noqa: E402  (beside this script: the dam breaks' build)
sys.path.pop(0)



def set_margin(margin: float) -> None:
    """Scale Verlet's C of ``fluid.integrator.diffusion_coefficient`` to ``margin`` below the
    edge, wherever it is called by name (fluid.integrator, fluid.solver)."""
    import fluid.integrator as integ
    import fluid.solver as solver

    default = integ.VERLET_MARGIN  # the margin the unpatched C has

    original = getattr(integ, "_original_diffusion_coefficient", integ.diffusion_coefficient)
    integ._original_diffusion_coefficient = original

    def patched(integrator: str, verlet_reset: int) -> float:
        c = original(integrator, verlet_reset)
        if integrator != "verlet":
            return c
        return math.inf if math.isinf(margin) else c * default / margin

    integ.diffusion_coefficient = patched
    solver.diffusion_coefficient = patched


def run_fluid(case: str, dp: float, margin: float, t_end: float, every: float, cfl: float | None = None) -> dict:
    import dataclasses

    import numpy as np

    from fluid.particles import Kind
    from fluid.solver import Fluid

    set_margin(margin)
    cfg, ps = fluid_throughput.build(case, dp, "verlet")
    if cfl is not None:  # a larger CFL factor, so that the step can reach the diffusion edge
        cfg = dataclasses.replace(cfg, cfl=cfl)
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    f.step(f.max_dt())  # compile / load the cache
    rho0 = cfg.rho0
    fluid_ids = np.sort(f.ps.ids[f.ps.kind == Kind.FLUID])
    by_id = np.zeros(int(f.ps.ids.max()) + 1)
    ring = np.zeros((8, fluid_ids.size))
    limiters: dict[str, int] = {}
    steps, cpu, dts = 0, 0.0, 0.0
    next_print, noise_max, blew, noise = every, 0.0, None, math.nan
    print(f"{case} dp={dp} margin={margin} cfl={cfg.cfl} particles={f.ps.n} fluid={fluid_ids.size} c_diff="
          f"{f._diffusivity['c_diff']:.4g}", flush=True)
    t_start = f.t
    while f.t < t_end:
        dt = f.max_dt()
        c0 = time.process_time()
        try:
            f.step(dt)
        except Exception as e:  # non-finite state: the run blew up
            blew = f"{type(e).__name__} at t={f.t:.4f} s: {str(e)[:120]}"
            break
        cpu += time.process_time() - c0
        steps += 1
        dts += dt
        limiters[f.limit.limiter] = limiters.get(f.limit.limiter, 0) + 1
        fl = f.ps.kind == Kind.FLUID
        by_id[f.ps.ids[fl]] = f.ps.rho[fl]
        ring[steps % 8] = by_id[fluid_ids]
        if steps >= 8:
            noise = float(np.sqrt(np.mean((ring[steps % 8] - ring.mean(axis=0)) ** 2))) / rho0
            noise_max = max(noise_max, noise)
        if f.t >= next_print or f.t >= t_end:
            dev = float(np.max(np.abs(ring[steps % 8] - rho0))) / rho0
            print(f"  t={f.t:.4f} s steps={steps} dt={dt:.3e} ({f.limit.limiter}) noise={noise:.2e} "
                  f"noise_max_interval={noise_max:.2e} max|rho-rho0|/rho0={dev:.4f} "
                  f"max|v|={float(np.max(np.linalg.norm(f.ps.vel[fl], axis=1))):.3f} m/s", flush=True)
            next_print += every
            noise_max = 0.0
    n = f.ps.n
    return {"case": case, "margin": margin, "cfl": cfg.cfl, "particles": n, "steps": steps, "t_s": f.t - t_start,
            "mean_dt_s": dts / max(steps, 1), "limiters": limiters, "cpu_s": cpu,
            "particle_steps_per_cpu_s": n * steps / cpu if cpu else math.nan,
            "sim_s_per_cpu_s": dts / cpu if cpu else math.nan, "blew_up": blew,
            "load_avg_1min": os.getloadavg()[0]}


#: run in the child (validation_child.run_child): every SPH fluid forced to Verlet, the margin set
PATCH = r"""
import sys
sys.path.insert(0, sys.argv[4])
margin, name, quick = float(sys.argv[1]), sys.argv[2], sys.argv[3] == "1"
from verlet_diffusion_margin import set_margin
set_margin(margin)
from fluid import solver
built = []
post = solver.FluidConfig.__post_init__
def forced(self):
    if self.device == "cpu":
        object.__setattr__(self, "integrator", "verlet")
    built.append(self.integrator)
    post(self)
solver.FluidConfig.__post_init__ = forced
"""


def run_validation(name: str, margin: float, quick: bool) -> dict:
    return run_child(PATCH, name, [repr(margin), name, "1" if quick else "0", _here])


def _fmt(v) -> str:
    if isinstance(v, float):
        return f"{v:.5g}"
    if isinstance(v, list) and len(v) > 4:
        return f"[{len(v)} values, max {max(v, key=abs) if all(isinstance(x, (int, float)) for x in v) else '?'}]"
    return str(v)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("what", choices=["fluid", "validations"])
    ap.add_argument("names", nargs="*", help="validation cases (validations; default dambreak-2d dambreak-lobovsky)")
    ap.add_argument("--margin", type=float, action="append", help="factor below the edge (repeatable; inf: no limit)")
    ap.add_argument("--case", choices=["2d", "3d"], default="2d")
    ap.add_argument("--dp", type=float, default=None, help="spacing [m] (2d 0.01, 3d 0.017)")
    ap.add_argument("--t-end", type=float, default=0.3, help="simulated time [s]")
    ap.add_argument("--every", type=float, default=None, help="print interval [s] (t_end / 10)")
    ap.add_argument("--cfl", type=float, default=None, help="fluid: CFL factor (default the build's 0.2)")
    ap.add_argument("--full", action="store_true", help="validations: the full variants")
    a = ap.parse_args(argv)
    margins = a.margin or [2.75, 1.5, 1.0, math.inf]
    import numba
    print(f"{fluid_throughput.cpu_name()}; threads {numba.get_num_threads()}; load {os.getloadavg()[0]:.2f}",
          flush=True)
    if a.what == "fluid":
        dp = a.dp or (0.01 if a.case == "2d" else 0.017)
        for m in margins:
            r = run_fluid(a.case, dp, m, a.t_end, a.every or a.t_end / 10, a.cfl)
            print("RESULT " + " ".join(f"{k}={_fmt(v)}" for k, v in r.items()), flush=True)
        return
    from cosim.validation import lookup
    for name in a.names or ["dambreak-2d", "dambreak-lobovsky"]:
        recs = {m: run_validation(name, m, not a.full) for m in margins}
        for m, r in recs.items():
            if "error" in r:
                print(f"{name} margin {m}: failed ({r['error']})", flush=True)
                continue
            print(f"{name} margin {m}: passed {r['passed']} fluids {r['_fluids']} CPU {r['_cpu_s']:.1f} s", flush=True)
            for key in r.get("tolerances", {}):
                try:
                    print(f"    {key}: {_fmt(lookup(r['metrics'], key))}  (tolerance {r['tolerances'][key]})")
                except KeyError:
                    pass


if __name__ == "__main__":
    main()
