"""Where on nearfield-radiation's cylinder the force's parts sit: the vertical fluid force on
the body's boundary particles split by ring of its section (from the rim inwards, every
layer; and, of the outer ring, the side's part above the bottom layer), each part's first
harmonic fitted as the case fits the whole (``cosim.validations.radiation.added_mass_damping``,
the annulus' hydrostatic restoring added back to its A33), against Capytaine's heave
pressure integrated over the annuli of the bottom that the rings stand for (each ring
samples the annulus a spacing wide round its radius; the side's panels carry no vertical
force). docs/validation/nearfield.md, "The reference's panels, and the full variant in rings".

    python benchmarks/radiation_force_by_ring.py --out OUT [--r-over-dx 4] [--periods 2] [--draft 1.5]
        [--amplitude 0.3] [--only forced|held]

The case's scene at ``--r-over-dx``, its cylinder drawing ``--draft`` [m] and forced through
``--amplitude`` [m] (``benchmarks/radiation_hull.py``'s), run for its ramp and ``--periods`` periods, the force
on every body particle read every twentieth of a period after the ramp
(``cosim.sph_fluid.SPHFluid.body_particle_forces``: on the half body the plane's particles
once, the others twice); ``--only held`` the case's tare (``held_scene``), whose parts are
subtracted. Each run's parts are saved in ``OUT/RUN.npz``; a call without ``--only`` runs
what is missing and prints the table; ``--only forced`` prints it untared (the tare moves
the whole body's B33 by about 8 % of Capytaine's at 0.3 m of heave, 4 % at 0.6 m).
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import numpy as np

from cosim.validations import case_scene
from cosim.validations.radiation import added_mass_damping, cylinder_hull, draft_of, radiation_scene
from radiation_hull import scene_for as hull_scene  # benchmarks/radiation_hull.py, beside this script

SAMPLES_A_PERIOD = 20


def scene_for(r_over_dx: float, periods: float, held: bool, draft: float = 1.5, amplitude: float = 0.3):
    """The case's quick scene at ``r_over_dx`` for its ramp and ``periods`` periods, its
    cylinder drawing ``draft`` [m] and heaving ``amplitude`` [m] (``held``: its tare)."""
    return hull_scene("cylinder", draft, r_over_dx, periods, held, amplitude)


def ring_forces(scene) -> dict:
    """``{"t": times, "parts": (n_times, n_rings + 1) vertical force [N], "radii": ring radii}``:
    the body's particles by ring from the rim inwards, every layer (the kernel reaches past the
    bottom layer), the last column the outer ring's particles above the bottom layer (a part
    of the first: the side's)."""
    b, m = scene.bodies[0], radiation_scene(True).bodies[0].motion  # the forced motion's times (held too)
    dx = scene.fluid.dx
    ramp_end = m.ramp * m.period
    times = ramp_end + np.arange(1, round((scene.world.duration - ramp_end) / m.period * SAMPLES_A_PERIOD) + 1) \
        * m.period / SAMPLES_A_PERIOD
    n_rings = int(math.ceil(b.radius / dx))
    rows, cpu = [], time.process_time()
    with case_scene.built(scene) as built:
        for t in times:
            built.coupler.run(float(t))
            pos, F, shares = built.fluid.body_particle_forces(0)
            x, y, z = pos[:, 0] - b.pos[0], pos[:, 1] - b.pos[1], pos[:, 2] - pos[:, 2].min()
            ring = np.clip(np.floor((b.radius - np.hypot(x, y)) / dx).astype(int), 0, n_rings - 1)
            fz = shares * F[:, 2]
            rim_above = (ring == 0) & (z > 0.5 * dx)
            rows.append(np.append(np.bincount(ring, weights=fz, minlength=n_rings), fz[rim_above].sum()))
    radii = b.radius - dx * (0.5 + np.arange(n_rings))
    return {"t": times, "parts": np.array(rows), "radii": radii, "cpu_s": time.process_time() - cpu}


def capytaine_by_annulus(scene, edges) -> tuple[np.ndarray, np.ndarray]:
    """(A33, B33) [kg, kg/s] of the cylinder carried by the bottom's annuli between ``edges``
    [m] (radii, decreasing from R) and by the side: Capytaine's heave radiation pressure
    integrated over the panels there, scaled so that the parts sum to its own A33, B33."""
    import capytaine as cpt

    b, d = scene.bodies[0], scene.domain
    w = 2.0 * math.pi / b.motion.period
    hull = cylinder_hull(b.radius, draft_of(scene))
    mesh = cpt.Mesh(hull.vertices, hull.faces)
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs())
    pb = cpt.RadiationProblem(body=body, radiating_dof="Heave", omega=w, water_depth=d.depth, rho=scene.fluid.rho0,
                              g=scene.world.gravity)
    res = cpt.BEMSolver().solve(pb, keep_details=True)
    c, n, area = mesh.faces_centers, mesh.faces_normals, mesh.faces_areas
    fz = res.pressure * n[:, 2] * area  # the heave force's density, Capytaine's sign
    r = np.hypot(c[:, 0], c[:, 1])
    on_bottom = n[:, 2] < -0.5
    parts = [fz[on_bottom & (r <= hi) & (r > lo)].sum() for hi, lo in zip(edges[:-1], edges[1:])]
    parts.append(fz[~on_bottom].sum())
    parts = np.array(parts)
    total = parts.sum()
    a33, b33 = float(res.added_masses["Heave"]), float(res.radiation_dampings["Heave"])
    return a33 * parts.real / total.real, b33 * parts.imag / total.imag


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True, type=Path)
    ap.add_argument("--r-over-dx", type=float, default=4.0)
    ap.add_argument("--periods", type=float, default=2.0)
    ap.add_argument("--draft", type=float, default=1.5, help="the cylinder's draft [m] (the case's: 1.5)")
    ap.add_argument("--amplitude", type=float, default=0.3, help="the heave amplitude [m] (the case's: 0.3)")
    ap.add_argument("--only", choices=("forced", "held"))
    args = ap.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    for run in ([args.only] if args.only else ["forced", "held"]):
        path = args.out / f"{run}.npz"
        if not path.is_file():
            np.savez(path, **ring_forces(scene_for(args.r_over_dx, args.periods, run == "held", args.draft,
                                                   args.amplitude)))
    if args.only == "held":
        return
    scene = scene_for(args.r_over_dx, args.periods, False, args.draft, args.amplitude)
    b, m = scene.bodies[0], scene.bodies[0].motion
    w = 2.0 * math.pi / m.period
    forced = np.load(args.out / "forced.npz")
    tared = args.only is None
    held = np.load(args.out / "held.npz") if tared else {"parts": 0.0, "cpu_s": 0.0}
    parts = forced["parts"] - held["parts"]
    radii = forced["radii"]
    dx = scene.fluid.dx
    edges = np.concatenate([[b.radius], np.maximum(b.radius - dx * np.arange(1, len(radii) + 1), 0.0)])
    a_cap, b_cap = capytaine_by_annulus(scene, edges)
    print(f"draft {args.draft:g} m, amplitude {m.amplitude:g} m, R/dx = {args.r_over_dx:g}, {args.periods:g} periods "
          f"after the ramp, {'tared' if tared else 'untared'}; "
          f"CPU {float(forced['cpu_s']):.0f} + {float(held['cpu_s']):.0f} s")
    print("| part | SPH A33 [t] | Capytaine A33 [t] | SPH B33 [kN s/m] | Capytaine B33 [kN s/m] |")
    print("|---|---|---|---|---|")
    names = [f"ring at r = {r:.3g} m (annulus {hi:.3g}-{lo:.3g} m)" for r, hi, lo in zip(radii, edges[:-1], edges[1:])]
    names.append("of the outer ring: above the bottom layer (Capytaine: the side)")
    g, rho = scene.world.gravity, scene.fluid.rho0
    stiffness = np.append(rho * g * math.pi * (edges[:-1] ** 2 - edges[1:] ** 2), 0.0)  # each annulus' hydrostatics
    tot = np.zeros(2)
    for j, name in enumerate(names):
        a, bb = added_mass_damping(forced["t"], parts[:, j], m.amplitude, w, stiffness[j])
        tot += (a, bb) if j < len(radii) else 0.0
        print(f"| {name} | {a / 1e3:.2f} | {a_cap[j] / 1e3:.2f} | {bb / 1e3:.2f} | {b_cap[j] / 1e3:.2f} |")
    print(f"| sum of the rings | {tot[0] / 1e3:.2f} | {a_cap[:-1].sum() / 1e3:.2f} | {tot[1] / 1e3:.2f} | "
          f"{b_cap[:-1].sum() / 1e3:.2f} |")

if __name__ == "__main__":
    main()
