"""The force on a body held at rest against Archimedes, as its flat bottom face moves
between the fluid lattice's planes: the water's standoff from the face (fluid.standoff).

A 2-D box 2 m wide, 1 m high, held with its bottom 0.6 m (6 rows) below the level of a
12 m x 3 m tank, dx = 0.1 m, its face ``delta`` dx below a lattice plane; set-up
"waves"; the water settled (velocities damped, ``Fluid.settle``) around it. Prints per
phase the fluid's force at t = 0 and settled, over rho g W draft, with the fit and
(``--no-fit``) without it. The figures: docs/validation/nearfield.md.

    python benchmarks/standoff_draft.py [--no-fit] [--settle 1.0] [--boundary mdbc|dbc]
"""

from __future__ import annotations

import argparse

import numpy as np

DX, LENGTH, DEPTH, WIDTH, DRAFT = 0.1, 12.0, 3.0, 2.0, 0.6


def held_box(delta: float, settle: float, boundary: str) -> tuple[float, float]:
    """(force at t = 0, force settled) over Archimedes, the face ``delta`` dx off."""
    from cosim.scene import SPH, Box, Scene, Tank, World
    from cosim.scene.build import build

    bottom = DEPTH - DRAFT - delta * DX
    s = Scene(name="held", world=World(dim=2, duration=1.0),
              fluid=SPH(dx=DX, rho0=1000.0, setup="waves", body_boundary=boundary),
              domain=Tank(length=LENGTH, height=DEPTH + 1.0, depth=DEPTH),
              bodies=[Box(name="b", size=[WIDTH, 1.0], pos=[0.5 * LENGTH, bottom + 0.5], density=500.0)])
    sph = build(s, "/tmp").fluid
    archimedes = 1000.0 * 9.81 * WIDTH * (DEPTH - bottom)
    start = sph.body_wrenches()[0][0][2] / archimedes
    sph.fluid.settle(settle, tau=0.2 * settle)
    return start, sph.body_wrenches()[0][0][2] / archimedes


def main(argv=None) -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--no-fit", action="store_true", help="the lattice as carved, no fit to the faces")
    p.add_argument("--settle", type=float, default=1.0, help="settling time [s]")
    p.add_argument("--boundary", default="mdbc", choices=("mdbc", "dbc"))
    p.add_argument("--deltas", default="0,0.25,0.5,0.75", help="the face's offsets below a lattice plane [dx]")
    a = p.parse_args(argv)
    if a.no_fit:
        import cosim.sph_fluid

        cosim.sph_fluid.fit_to_faces = lambda pts, geoms, dx: (pts, np.ones(len(pts)))
    print(f"fit: {not a.no_fit}, boundary {a.boundary}, settled {a.settle} s")
    for delta in (float(d) for d in a.deltas.split(",")):
        start, settled = held_box(delta, a.settle, a.boundary)
        print(f"delta {delta:.3f} dx: F/Archimedes at t = 0 {start:.4f}, settled {settled:.4f}", flush=True)


if __name__ == "__main__":
    main()
