"""A free 2-D circle of half the water's density floating at rest: its draft against
Archimedes' (the radius), at several spacings: how much the water's standoff from a
curved face (which ``fluid.standoff`` does not fit) lifts a body.

The circle (radius ``R``, 500 kg/m^3, 1 m long) starts centred on the still level of a
tank 8 R long and 3 R deep, under the floating-box-draft case's set-up ("defaults":
h = sqrt(2) dx, mDBC body, c0 = 20 sqrt(g d)); its draft is the far-field level (the
mean top of the water's columns farther than 1.5 R from it, plus half a spacing) less
its lowest point, averaged over the second half of the run. Prints per R/dx the draft
over R and the offset in spacings. The figures: docs/validation/nearfield.md, "The
static draft's offset".

    python benchmarks/circle_draft.py [--radius 0.05] [--r-over-dx 5 10 20] [--duration 2.0]
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def circle_draft(radius: float, dx: float, duration: float) -> dict:
    """The circle's mean draft [m] over the run's second half, and its spread, steps and CPU seconds."""
    from cosim.scene import SPH, Cylinder, Scene, Tank, World
    from cosim.scene.build import build
    from cosim.validations.floating import water_level

    length, depth = 8.0 * radius, 3.0 * radius
    s = Scene(name="circle", world=World(dim=2, duration=duration, sample_every=duration / 100),
              fluid=SPH(dx=dx, rho0=1000.0, setup="defaults", c0_factor=20.0),
              domain=Tank(length=length, height=depth + 2.0 * radius, depth=depth),
              bodies=[Cylinder(name="c", radius=radius, density=500.0, pos=[0.5 * length, depth])])
    cpu = time.process_time()
    b = build(s, "/tmp")
    ts, drafts = [], []

    def sample(info):
        ps = b.fluid.fluid.ps
        level = water_level(ps.pos, ps.kind, dx, 1.5 * radius, [0.5 * length])
        ts.append(info.t)
        drafts.append(level - (b.bodies.kinematics().com[0, -1] - radius))

    b.coupler.run(duration, callback=sample)
    t, d = np.array(ts), np.array(drafts)
    late = d[t > 0.5 * duration]
    return {"draft_m": float(late.mean()), "spread_m": float(late.std()), "steps": int(b.coupler.steps),
            "cpu_s": time.process_time() - cpu}


def main(argv=None) -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--radius", type=float, default=0.05, help="the circle's radius [m]")
    p.add_argument("--r-over-dx", type=float, nargs="+", default=[5.0, 10.0, 20.0])
    p.add_argument("--duration", type=float, default=2.0,
                   help="simulated time [s] (about 3.5 heave periods at R = 5 cm)")
    a = p.parse_args(argv)
    print("| R/dx | draft / R | offset [dx] | spread / R | steps | CPU s |")
    print("|---|---|---|---|---|---|")
    for r in a.r_over_dx:
        dx = a.radius / r
        m = circle_draft(a.radius, dx, a.duration)
        print(f"| {r:g} | {m['draft_m'] / a.radius:.4f} | {(m['draft_m'] - a.radius) / dx:+.3f} | "
              f"{m['spread_m'] / a.radius:.4f} | {m['steps']} | {m['cpu_s']:.0f} |", flush=True)


if __name__ == "__main__":
    main()
