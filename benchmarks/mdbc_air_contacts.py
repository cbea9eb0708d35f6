"""Where mDBC's air rule fires on a body under an impact: elastic-table2's structure
(Yang & Li 2020, Table 2) struck by the dam-break flow.

Every ``--every`` s from just before the arrival, it prints how many of the structure's
particles have their ghost node in the air (``fluid.terms.mdbc_in_air``: rho0, the air's
pressure) and how many of those have a fluid particle within one spacing, by part (the
front and back halves below the top spacing, the top), with the fluid's x force on the
structure. Figures:
docs/validation/nearfield.md, "mDBC's ghost nodes in the air carry the air's pressure".

    python benchmarks/mdbc_air_contacts.py [--test 5] [--dx 0.005]
"""

from __future__ import annotations

import argparse

import numpy as np


def main(argv=None) -> None:
    from scipy.spatial import cKDTree

    from cosim.scene.build import build
    from cosim.validations import elastic_table2 as et
    from fluid.particles import Kind

    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--test", type=int, default=5, choices=sorted(et.TABLE2), help="Table 2's test")
    p.add_argument("--dx", type=float, default=0.005, help="particle spacing [m] (the quick variant's)")
    p.add_argument("--start", type=float, default=0.12, help="first time [s] (the flow arrives at 0.13-0.16 s)")
    p.add_argument("--end", type=float, default=0.24, help="last time [s]")
    p.add_argument("--every", type=float, default=0.004, help="sampling interval [s]")
    a = p.parse_args(argv)
    dx = a.dx
    b = build(et.scene_of(a.test, dx), "/tmp/mdbc_air_contacts")
    fl, mdbc = b.fluid.fluid, b.fluid._mdbc
    x0 = et.L_COL + et.TABLE2[a.test][1]  # the structure's left face [m]
    print(f"Test {a.test}, dx = {dx} m: t [s], the structure's particles, ghosts in the air, those with fluid "
          f"within dx (front / top / back), fluid x force [N/m]")
    for t in np.arange(a.start, a.end + 1e-9, a.every):
        b.coupler.run(t)
        ps = fl.ps
        near = (np.abs(ps.pos[:, 0] - x0 - 0.5 * et.B) < et.B) & (ps.pos[:, -1] < et.H_S + dx)
        body = (ps.kind != Kind.FLUID) & near
        air = body & (mdbc.low_order[:ps.n] == 2)
        pa = ps.pos[air]
        d = cKDTree(ps.pos[ps.kind == Kind.FLUID]).query(pa)[0] if len(pa) else np.zeros(0)
        wet = d < 1.01 * dx
        top = pa[:, -1] >= et.H_S - dx
        front = ~top & (pa[:, 0] < x0 + 0.5 * et.B)  # the struck half (the structure bends by millimetres)
        back = ~top & ~front
        print(f"{t:.3f}  {body.sum():4d}  {air.sum():4d}  {wet.sum():3d} ({(wet & front).sum()} / "
              f"{(wet & top).sum()} / {(wet & back).sum()})  {b.fluid.exchanged_wrenches()[0][0, 0]:8.1f}", flush=True)


if __name__ == "__main__":
    main()
