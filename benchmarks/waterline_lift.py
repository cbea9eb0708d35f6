"""Where the SPH fluid's lift over the waterline sits: a 2-D box held half in still water,
the fluid's vertical force on it against Archimedes', and the pressures by height along
its sides and in the far water.

A body that pierces the free surface is lifted by a force of the order of rho g h^2 per
metre of waterline (docs/benchmarks/wind_turbine_static.md, "The kernel's width"); it is
what keeps the wind-turbine base's draft short of hydrostatics. The box (B = 0.2 m wide, 0.2
m high, its centre on the still level of a tank 1.2 m long and 0.3 m deep, mDBC body, the
wave set-up) is held still for ``--duration`` s; the mean of its ``fluid_Fz`` over the
second half is set against rho g B (d + eta), eta the mean level at two gauges 0.45 m from
it. ``--oracle`` sets the body's mDBC densities of some particles to rho0 after each
correction (a probe, not a model): ``shepard``, those whose ghost node took the Shepard
fallback (too few fluid neighbours, above the water); ``above``, every body particle above
the still level. It prints the water's volume (sum m / rho above the box's bottom) missing
from the :data:`NEAR_COLUMNS` lattice columns beside each face against the far columns' (whether the lift is a
gap in the water), and per height band [dx] the side particles' mean pressure and the far
water's (:data:`FAR`), over rho g dx, from snapshots every 0.02 s over the run's
last third. Figures: docs/validation/nearfield.md, "The still draft's window, and where the
lift over the waterline sits".

    python benchmarks/waterline_lift.py [--dx 0.02] [--h-coef 2] [--oracle none|shepard|above]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

B, HEIGHT, DRAFT, DEPTH, LENGTH = 0.2, 0.2, 0.1, 0.3, 1.2
RHO, G = 1000.0, 9.81
#: the far water: |x - xc| within these [m] (clear of the box's kernel and of the tank's walls)
FAR = (0.3, 0.5)
#: lattice columns beside each face whose water is set against the far water's
NEAR_COLUMNS = 12


def _oracle(kind: str) -> None:
    """Patch the bodies' mDBC to zero the pressure of the particles ``kind`` names."""
    from fluid import boundary_correction as bc
    from fluid.particles import Kind

    orig = bc.MDBC.__call__

    def patched(self, ps, start, grid):
        orig(self, ps, start, grid)
        body = ps.kind != Kind.FLUID
        if kind == "shepard":
            ps.rho[body & self.low_order.astype(bool)] = self.rho0
        else:
            near = np.abs(ps.pos[:, 0] - 0.5 * LENGTH) < 0.5 * B
            ps.rho[body & near & (ps.pos[:, -1] > DEPTH)] = self.rho0

    bc.MDBC.__call__ = patched


def held_box(dx: float, h_coef: float, duration: float) -> dict:
    """The held box's vertical force over Archimedes', the water missing beside it and the
    pressure bands (module docstring)."""
    from cosim.scene import SPH, Box, Probes, Scene, Tank, World
    from cosim.scene.build import build
    from cosim.scene.spec import ForcedTable
    from fluid.particles import Kind
    from fluid.probes import surface_elevation

    xc = 0.5 * LENGTH
    s = Scene(name="held-box", world=World(dim=2, duration=duration, sample_every=0.01),
              fluid=SPH(dx=dx, rho0=RHO, setup="waves", h_coef=h_coef),
              domain=Tank(length=LENGTH, height=DEPTH + 0.2, depth=DEPTH),
              bodies=[Box(name="box", size=[B, HEIGHT], density=500.0, pos=[xc, DEPTH - DRAFT + 0.5 * HEIGHT],
                          motion=ForcedTable(points=[[0.0, 0.0], [duration, 0.0]], dof="heave"))],
              probes=Probes(motion=["box"]))
    cpu = time.process_time()
    b = build(s, "/tmp")
    fl = b.fluid.fluid
    c0 = fl.config.speed_of_sound
    edges = np.arange(-6, 5) * dx
    nb = len(edges) - 1
    side_p, far_p, side_n, far_n = np.zeros(nb), np.zeros(nb), np.zeros(nb), np.zeros(nb)
    gap = []  # the water missing beside the box [m^2], against the far water's columns
    fz, eta = [], []
    times = np.arange(0.5 * duration, duration + 1e-9, 0.01)
    b.coupler.run(times[0])
    for k, t in enumerate(times[1:]):
        b.coupler.run(t)
        fz.append(b.fluid.exchanged_wrenches()[0][0, -1])
        eta.append(float(np.mean(surface_elevation(fl, np.array([xc - 0.45, xc + 0.45])))) - DEPTH)
        if t < 2.0 * duration / 3.0 or k % 2:
            continue
        ps = fl.ps
        z, x = ps.pos[:, -1] - DEPTH, ps.pos[:, 0] - xc
        p = (ps.rho - RHO) * c0 ** 2 / (RHO * G * dx)
        side = (ps.kind != Kind.FLUID) & (np.abs(x) < 0.5 * B) & (np.abs(x) > 0.5 * B - 2.0 * h_coef * dx)
        far = (ps.kind == Kind.FLUID) & (np.abs(x) > FAR[0]) & (np.abs(x) < FAR[1])
        band = np.digitize(z, edges) - 1
        vol, above_bottom = ps.mass / ps.rho, z > -DRAFT
        near = (ps.kind == Kind.FLUID) & above_bottom & (np.abs(x) - 0.5 * B < NEAR_COLUMNS * dx)
        far_per_m = vol[far & above_bottom].sum() / (2.0 * (FAR[1] - FAR[0]))  # both sides
        gap.append(far_per_m * NEAR_COLUMNS * dx - 0.5 * vol[near].sum())
        for j in range(nb):
            s_sel, f_sel = side & (band == j), far & (band == j)
            side_p[j] += p[s_sel].sum()
            side_n[j] += s_sel.sum()
            far_p[j] += p[f_sel].sum()
            far_n[j] += f_sel.sum()
    level = float(np.mean(eta))
    return {"lift": float(np.mean(fz)) / (RHO * G * B * (DRAFT + level)), "eta_m": level, "edges": edges,
            "gap_dx2": float(np.mean(gap)) / dx ** 2, "side_p": side_p / np.maximum(side_n, 1),
            "far_p": far_p / np.maximum(far_n, 1), "steps": int(b.coupler.steps), "cpu_s": time.process_time() - cpu}


def main(argv=None) -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--dx", type=float, default=0.02, help="particle spacing [m] (the draft is 0.1 m)")
    p.add_argument("--h-coef", type=float, default=2.0, help="h / dx (the wave set-up's is 2)")
    p.add_argument("--oracle", choices=("none", "shepard", "above"), default="none",
                   help="body particles given rho0 after each mDBC pass (a probe): none; those whose ghost took "
                        "the Shepard fallback; those above the still level")
    p.add_argument("--duration", type=float, default=2.0, help="simulated time [s]")
    a = p.parse_args(argv)
    if a.oracle != "none":
        _oracle(a.oracle)
    r = held_box(a.dx, a.h_coef, a.duration)
    print(f"dx = {a.dx} m, h = {a.h_coef:g} dx, oracle {a.oracle}: Fz / (rho g B (d + eta)) = {r['lift']:.4f} "
          f"(eta {1e3 * r['eta_m']:+.2f} mm; {r['steps']} steps, {r['cpu_s']:.0f} CPU s)")
    print(f"the water beside each face ({NEAR_COLUMNS} columns) lacks {r['gap_dx2']:+.4f} dx^2 of the far "
          f"columns' volume (a gap carrying the lift would be about {0.1 * a.h_coef ** 2:.2f} dx^2)")
    print("| z above the still level [dx] | the body's side: p / (rho g dx) | the far water's |")
    print("|---|---|---|")
    e = r["edges"] / a.dx
    for j in range(len(e) - 1):
        print(f"| {e[j]:+.0f} .. {e[j + 1]:+.0f} | {r['side_p'][j]:+.3f} | {r['far_p'][j]:+.3f} |")


if __name__ == "__main__":
    main()
