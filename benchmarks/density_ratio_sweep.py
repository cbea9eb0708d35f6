"""Where does explicit SPH-body coupling break? A 2-D box (0.10 x 0.05 m) in a
0.4 m tank of 0.2 m water at body/fluid density ratios 0.1 ... 10, fluid-first
coupling (momentum-exact), dx = 1 cm: stable or not, fastest body speed, wall time.

    python benchmarks/density_ratio_sweep.py [--t-end 0.5] [--ratios 0.1,0.2,0.5,2,10]

Prints figures; asserts nothing. Light bodies start near the surface, heavy ones
near the floor (which only the fluid holds them off: give the scene a MuJoCo floor,
``bodies.builders.scene(floor_z=...)``, for contact).
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

G, L, H, D, DX = 9.81, 0.4, 0.3, 0.2, 0.01  # m/s^2, tank length, wall height, depth, spacing [m]


def run(ratio: float, t_end: float):
    cfg = FluidConfig(dim=2, dx=DX, u_max=math.sqrt(G * D), c0_factor=20.0)
    walls = [(tank_walls(np.zeros(2), np.array([L, H]), DX, 3), Kind.FIXED_WALL, 0)]
    z = 0.18 if ratio < 1 else 0.06
    box = builders.box("box", (0.1, 0.05), (L / 2, 0.0, z), density=1000.0 * ratio, planar=True)
    bodies = MujocoBodies(builders.scene(box, timestep=1e-3))
    coupler = Coupler(bodies=bodies, fluid=SPHFluid(cfg, block(np.zeros(2), np.array([L, D]), DX), walls,
                                                  z_surface=D), scheme="fluid-first")
    vmax = [0.0]

    def watch(info):
        vmax[0] = max(vmax[0], float(np.abs(bodies.kinematics().velocity[0]).max()))
        if vmax[0] > 5.0:
            raise CosimError(f"runaway body speed {vmax[0]:.1f} m/s at t = {info.t:.4f} s")

    wall = time.perf_counter()
    try:
        coupler.run(t_end, callback=watch)
        status = "stable"
    except CosimError as exc:
        status = str(exc)
    return status, vmax[0], coupler.steps, time.perf_counter() - wall


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--t-end", type=float, default=0.5, help="simulated time [s]")
    parser.add_argument("--ratios", default="0.1,0.2,0.5,2,10", help="body/fluid density ratios")
    args = parser.parse_args()
    print(f"{'ratio':>6} {'steps':>6} {'max speed [m/s]':>15} {'wall [s]':>8}  status")
    for r in (float(x) for x in args.ratios.split(",")):
        status, v, steps, wall = run(r, args.t_end)
        print(f"{r:6.2f} {steps:6d} {v:15.3f} {wall:8.1f}  {status}")


if __name__ == "__main__":
    main()
