"""Where does staggered SPH-body coupling break, per scheme and light-body remedy?

A 2-D box (0.10 x 0.06 m) is released at rest fully submerged (centre 0.1 m deep
in 0.2 m of water, tank 0.4 x 0.3 m, dx = 2 cm, c0 = 20 sqrt(g D) = 28 m/s) at
body/fluid density ratios from 0.001 to 1, and rises for 0.12 s (it stays under
water: at 0.2 s the lightest ones break the surface). Fully submerged is
the hard case: the added mass (about the displaced mass, or more) is largest
relative to the body's. Each run either ends ("ok") or is stopped by the coupler
(its instability watch or a solver) with its message. Also printed: the body's
largest speed, its largest acceleration in the last fifth of the run, and the
rms of the acceleration's step-to-step wiggle (a - mean of its neighbours) in the
first and last fifths: a run whose wiggle grows is going unstable.

    python benchmarks/density_ratio_sweep.py [--t-end 0.12] [--dx 0.02]
        [--ratios 0.001,0.003,0.01,0.05,0.1,0.2,1] [--cases explicit,fluid-first,fluid-first+subiterate]

What it found (explicit and predictor-corrector coupling hold down to a ratio of about
0.003, fluid-first to about 0.1, sub-iterated fluid-first to 0.001; the added-mass remedy
makes every scheme worse on the SPH fluid, so ``"auto"`` never picks it there), with the
measured table: docs/benchmarks/density_ratio_sweep.md.
"""

import argparse
import math
import time

import numpy as np

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.errors import CosimError
from cosim.sph_fluid import SPHFluid
from fluid.geometry import block, tank_walls
from fluid.particles import Kind
from fluid.solver import FluidConfig

G, L, H, D = 9.81, 0.4, 0.3, 0.2  # m/s^2, tank length, wall height, water depth [m]
BOX = (0.1, 0.06)  # body size (x, z) [m]


def submerged_box(ratio: float, dx: float, scheme: str, light_body: str, z: float = 0.1):
    """The coupler, bodies of the sweep's scene (box centre at height ``z`` [m])."""
    cfg = FluidConfig(dim=2, dx=dx, u_max=math.sqrt(G * D), c0_factor=20.0)
    walls = [(tank_walls(np.zeros(2), np.array([L, H]), dx, 3), Kind.FIXED_WALL, 0)]
    box = builders.box("box", BOX, (L / 2, 0.0, z), density=1000.0 * ratio, planar=True)
    bodies = MujocoBodies(builders.scene(box, timestep=1e-3, floor_z=0.0))
    fluid = SPHFluid(cfg, block(np.zeros(2), np.array([L, D]), dx), walls, z_surface=D)
    return Coupler(bodies=bodies, fluid=fluid, scheme=scheme, light_body=light_body), bodies


def run(ratio: float, case: str, dx: float, t_end: float):
    scheme, _, remedy = case.partition("+")
    coupler, bodies = submerged_box(ratio, dx, scheme, remedy or "none")
    acc, vmax, iters = [], [0.0], []
    prev = [bodies.dof_velocities()]

    def watch(info):
        v = bodies.dof_velocities()
        acc.append((v - prev[0]) / info.dt)
        prev[0] = v
        vmax[0] = max(vmax[0], float(np.linalg.norm(bodies.kinematics().velocity[0])))
        iters.append(coupler.subiterations)

    wall = time.perf_counter()
    try:
        coupler.run(t_end, callback=watch)
        status = "ok"
    except CosimError as exc:
        status = f"stopped: {exc}"
    wall = time.perf_counter() - wall
    a = np.array(acc)[:, 1] if acc else np.zeros(3)  # the heave dof (slide z)
    n = max(len(a) // 5, 1)
    wiggle = a[1:-1] - 0.5 * (a[:-2] + a[2:]) if len(a) > 2 else np.zeros(1)
    return {"status": status, "steps": coupler.steps, "vmax": vmax[0], "a_last": float(np.abs(a[-n:]).max()),
            "wiggle": (float(wiggle[:n].std()), float(wiggle[-n:].std())), "wall": wall,
            "iters": float(np.mean(iters)) if iters and iters[-1] else 0.0}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--t-end", type=float, default=0.12, help="simulated time [s]")
    parser.add_argument("--dx", type=float, default=0.02, help="particle spacing [m]")
    parser.add_argument("--ratios", default="0.001,0.003,0.01,0.05,0.1,0.2,1", help="body/fluid density ratios")
    parser.add_argument("--cases", default="explicit,predictor-corrector,fluid-first,fluid-first+subiterate",
                        help="schemes, each optionally +light_body remedy (none, added-mass, subiterate)")
    args = parser.parse_args()
    print(f"{'ratio':>6} {'case':<28} {'steps':>5} {'vmax':>7} {'|a| end':>8} {'wiggle first->last':>20} "
          f"{'iters':>5} {'wall':>6}  status")
    for r in (float(x) for x in args.ratios.split(",")):
        for case in args.cases.split(","):
            o = run(r, case, args.dx, args.t_end)
            print(f"{r:6.3f} {case:<28} {o['steps']:5d} {o['vmax']:7.3f} {o['a_last']:8.3g} "
                  f"{o['wiggle'][0]:9.3g} -> {o['wiggle'][1]:8.3g} {o['iters']:5.1f} {o['wall']:6.1f}  {o['status']}",
                  flush=True)


if __name__ == "__main__":
    main()
