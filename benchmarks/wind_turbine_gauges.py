"""The flagship's gauges against what linear potential flow puts there: the `wind-turbine-sph`
case judges each gauge's first harmonic against the incident sea's alone; this prints what
the base adds to the sea at the gauges in linear theory (the diffracted wave, and the waves
radiated by the base's surge, heave and pitch, Capytaine's free-surface elevation of each
problem solved at the wave's period), the total against the sea's, and each SPH run's
gauges beside it. So it tells whether a gauge's departure from the sea is the body's own
wave field or the SPH fluid's error.

    python benchmarks/wind_turbine_gauges.py --runs DIR [--sph waves abs ...] [--window 30 90]

``DIR``: a folder of runs of the case's scene (the case's ``COSIM_CASE_RUNS/wind-turbine-sph/full``,
or ``benchmarks/wind_turbine_levers.py``'s ``--out``): the motions driving the radiated
waves are those of ``DIR/potential`` (the potential-flow fluid's run), as complex
amplitudes at the wave's period against the sea's elevation at the base's centre.
Capytaine's convention is ``exp(-i omega t)``, the runs' ``exp(+i omega t)``: the
amplitudes are conjugated on the way in and out. The base: the scene's upright cylinder
at the draft of hydrostatics and the catenaries
(:func:`cosim.validations.wind_turbine_sph.equilibrium_draft`), its rotation centre at its
centre of mass, panels of ``--panel`` [m].
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

from cosim.scene.runner import read
from cosim.scene.toml_io import read_toml
from cosim.validations import wind_turbine_sph as case
from cosim.validations.wave_propagation import harmonics

DOFS = {"Surge": ("surge", 1.0), "Heave": ("heave", 1.0), "Pitch": ("pitch", math.pi / 180.0)}  # pitch in degrees


def base_problems(scene, omega: float, panel: float):
    """Capytaine's solved diffraction (heading along x) and radiation problems of the
    scene's base, centred at the origin: (solver, diffraction result, {dof: result})."""
    import capytaine as cpt

    from fluid.potential.hull import wetted_hull

    b = scene.bodies[0]
    draft = case.equilibrium_draft(scene)
    zc = 0.5 * b.length - draft  # the cylinder's centre (its centre of mass) above the still level
    hull = wetted_hull("cylinder", [b.radius, 0.5 * b.length], np.eye(3), [0.0, 0.0, zc], panel, name=b.name)
    mesh = cpt.Mesh(vertices=hull.vertices, faces=hull.faces, name=b.name)
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs(rotation_center=(0, 0, zc)), center_of_mass=(0, 0, zc))
    solver = cpt.BEMSolver()
    kw = dict(omega=omega, water_depth=scene.domain.depth, rho=scene.fluid.rho0, g=scene.world.gravity)
    diffraction = solver.solve(cpt.DiffractionProblem(body=body, wave_direction=0.0, **kw), keep_details=True)
    radiation = {d: solver.solve(cpt.RadiationProblem(body=body, radiating_dof=d, **kw), keep_details=True)
                 for d in DOFS}
    return solver, diffraction, radiation


def response(res, scene, window, omega: float) -> dict:
    """The base's motion amplitudes per metre of the sea's elevation at its centre (the
    runs' convention), {Capytaine dof: complex}."""
    late = (res.t >= window[0] - 1e-9) & (res.t <= window[1] + 1e-9)
    ts = res.t[late]
    x, y = scene.bodies[0].pos[:2]
    sea = scene.waves.sea(scene).elevation(np.full((1, 1), x), np.full((1, 1), y), ts[:, None])
    z_sea = harmonics(ts, sea, omega)[0]
    return {d: harmonics(ts, res[f"base.{name}"][late][:, None], omega)[0] * unit / z_sea
            for d, (name, unit) in DOFS.items()}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=Path, required=True)
    ap.add_argument("--sph", nargs="+", default=["waves"], help="SPH runs' folders under --runs")
    ap.add_argument("--window", type=float, nargs=2, default=(30.0, 90.0))
    ap.add_argument("--panel", type=float, default=0.4, help="panel size [m]")
    a = ap.parse_args(argv)
    import capytaine as cpt

    scene = read_toml(a.runs / a.sph[0] / "scene.toml")  # the base, the depth and the gauges
    omega = 2.0 * math.pi / scene.waves.period
    solver, diffraction, radiation = base_problems(scene, omega, a.panel)
    motion = response(read(a.runs / "potential"), scene, a.window, omega)
    pts = np.asarray(scene.probes.gauges, float)
    rel = pts - np.asarray(scene.bodies[0].pos[:2], float)
    incident = cpt.bem.airy_waves.airy_waves_free_surface_elevation(rel, diffraction.problem)
    parts = {"diffracted": solver.compute_free_surface_elevation(rel, diffraction)}
    for d, r in radiation.items():
        parts[f"{d.lower()} radiated"] = np.conj(motion[d]) * solver.compute_free_surface_elevation(rel, r)
    total = np.conj((incident + sum(parts.values())) / incident)  # back to exp(+i omega t)
    print("motions per metre of the sea at the base (potential fluid): "
          + ", ".join(f"{d} {abs(z):.4g} at {math.degrees(np.angle(z)):+.0f} deg" for d, z in motion.items()))
    runs = {}
    for label in a.sph:
        g = case.gauge_figures(read(a.runs / label), read_toml(a.runs / label / "scene.toml"), a.window)
        runs[label] = np.asarray(g["H1_over_H"])
    print("\n| gauge (x, y) [m] | " + " | ".join(parts) + " | potential flow total / sea | "
          + " | ".join(f"SPH {k} / sea" for k in runs) + " |")
    print("|---" * (2 + len(parts) + len(runs)) + "|")
    for i, p in enumerate(pts):
        cells = [f"{abs(v[i] / incident[i]):.4f}" for v in parts.values()]
        cells.append(f"{abs(total[i]):.4f} ({-np.angle(total[i]) / (2 * math.pi):+.4f} periods)")
        cells += [f"{h[i]:.3f}" for h in runs.values()]
        print(f"| ({p[0]:g}, {p[1]:g}) | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
