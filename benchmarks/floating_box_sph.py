"""A 2-D box floating in SPH water, coupled to MuJoCo: draft against Archimedes
and wall time, at two resolutions (the speed/accuracy trade of the coupling).

A 0.10 x 0.05 m box of 500 kg/m^3 (1 m thick) is released 1 cm above its
Archimedes equilibrium in a 0.4 m tank of 0.2 m water, explicit coupling. The
draft is averaged over the last second, across the weakly damped heave.

    python benchmarks/floating_box_sph.py [--t-end 2.0]

Prints figures; asserts nothing.
"""

import argparse
import math
import time

import numpy as np

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.sph_fluid import SPHFluid
from fluid.geometry import block, tank_walls
from fluid.particles import Kind
from fluid.solver import FluidConfig

G, L, H, D = 9.81, 0.4, 0.3, 0.2  # m/s^2, tank length, wall height, water depth [m]
BW, BH, RHO_B = 0.1, 0.05, 500.0  # box width, height [m], density [kg/m^3]


def run(dx: float, t_end: float):
    draft = RHO_B / 1000.0 * BH
    z_eq = D - draft + BH / 2
    cfg = FluidConfig(dim=2, dx=dx, u_max=math.sqrt(G * D), c0_factor=20.0)
    walls = [(tank_walls(np.zeros(2), np.array([L, H]), dx, 3), Kind.FIXED_WALL, 0)]
    box = builders.box("box", (BW, BH), (L / 2, 0.0, z_eq + 0.01), density=RHO_B, planar=True)
    bodies = MujocoBodies(builders.scene(box, timestep=1e-3))
    fluid = SPHFluid(cfg, block(np.zeros(2), np.array([L, D]), dx), walls, z_surface=D)
    coupler = Coupler(bodies=bodies, fluid=fluid, scheme="explicit")
    t, z = [], []
    wall = time.perf_counter()
    coupler.run(t_end, callback=lambda i: (t.append(i.t), z.append(bodies.kinematics().com[0, 2])))
    wall = time.perf_counter() - wall
    t, z = np.array(t), np.array(z)
    late = t > t_end - 1.0
    mean_draft = D - z[late].mean() + BH / 2
    return mean_draft, draft, coupler.steps, fluid.fluid.ps.n, wall


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--t-end", type=float, default=2.0, help="simulated time [s]")
    args = parser.parse_args()
    print(f"{'dx [m]':>8} {'particles':>9} {'steps':>7} {'draft [mm]':>10} {'Archimedes':>10} {'error':>8} "
          f"{'error/dx':>8} {'wall [s]':>8}")
    for dx in (0.01, 0.005):
        d, d0, steps, n, wall = run(dx, args.t_end)
        print(f"{dx:8.3f} {n:9d} {steps:7d} {1e3 * d:10.2f} {1e3 * d0:10.2f} {(d - d0) / d0:+8.1%} "
              f"{(d - d0) / dx:+8.2f} {wall:8.1f}")


if __name__ == "__main__":
    main()
