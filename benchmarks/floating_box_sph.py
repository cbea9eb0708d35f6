"""A 2-D box floating in SPH water, coupled to MuJoCo: draft against Archimedes
and wall time, plain dynamic boundaries (DBC) against modified ones (mDBC), at
two resolutions.

A 0.10 x 0.05 m box of 500 kg/m^3 (1 m thick) is released at rest one particle
spacing above its Archimedes position in a 0.3 m tank of 0.1 m water (faces on
the particle lattice, see ``cosim.validations.floating``), fluid-first coupling.
The draft below the far-field water level is averaged over the last 0.5 s.

    python benchmarks/floating_box_sph.py [--t-end 1.5]

Prints figures; asserts nothing.
"""

import argparse
import time

from cosim.validations.floating import settle_draft

BH, RHO_B = 0.05, 500.0  # box height [m], density [kg/m^3]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--t-end", type=float, default=1.5, help="simulated time [s]")
    args = parser.parse_args()
    print(f"{'boundary':>8} {'dx [m]':>8} {'particles':>9} {'steps':>7} {'draft [mm]':>10} {'Archimedes':>10} "
          f"{'err/height':>10} {'err/dx':>7} {'wall [s]':>8}")
    for dx in (0.0125, 0.00625):
        for boundary in ("dbc", "mdbc"):
            wall = time.perf_counter()
            r = settle_draft(2, dx, RHO_B, args.t_end, 0.5, lift=dx, boundary=boundary)
            wall = time.perf_counter() - wall
            err = r["draft_m"] - r["archimedes_m"]
            print(f"{boundary:>8} {dx:8.5f} {r['particles']:9d} {r['steps']:7d} {1e3 * r['draft_m']:10.2f} "
                  f"{1e3 * r['archimedes_m']:10.2f} {err / BH:+10.2%} {err / dx:+7.2f} {wall:8.1f}", flush=True)


if __name__ == "__main__":
    main()
