"""A moored floating box, one mooring model swapped for another in one line.

A 2-D box (2 m wide, 1 m tall, 500 kg/m^3, 1 m thick) floats on the analytic
fluid (buoyancy, damping) and is held by two 25 m chain-like lines. It is pushed
3 m sideways and released. The same run is made with each mooring model — the
quasi-static catenary, the SPH cable, the catenary exported as an FMU and run
through fmpy, and MoorDyn when installed — and their fairlead tensions and the
box's surge go on one plot. The only line that differs between the runs is the
one in :func:`make_mooring`.

    python examples/moored_box.py [--models catenary,sph-cable,fmu,moordyn] [--duration 20] [--out DIR]
"""

import argparse
import math
import tempfile
import time
from pathlib import Path

import numpy as np

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from fluid.analytic import AnalyticFluid
from moorings import MooringLine

ANCHOR_X, ANCHOR_Z, LENGTH = 20.0, -10.0, 25.0  # m
RHO, G = 1025.0, 9.81  # sea water [kg/m^3], [m/s^2]
WEIGHT, EA, DIAMETER = 50.0, 5.0e7, 0.03  # N/m submerged, N, m
MASS = WEIGHT / G + RHO * math.pi * DIAMETER**2 / 4  # kg/m in air, consistent with the submerged weight
MODELS = ("catenary", "sph-cable", "fmu", "moordyn")


def lines():
    common = dict(length=LENGTH, weight=WEIGHT, EA=EA, mass_per_length=MASS, diameter=DIAMETER)
    return [MooringLine((-ANCHOR_X, ANCHOR_Z), name="left", **common),
            MooringLine((ANCHOR_X, ANCHOR_Z), name="right", **common)]


def make_mooring(model: str, workdir: Path):
    """The one line a scenario changes to swap mooring models."""
    if model == "catenary":
        from moorings import CatenaryMooring
        return CatenaryMooring(lines())
    if model == "sph-cable":
        from moorings.sph_cable import SPHCableMooring
        return SPHCableMooring(lines(), n_particles=30)
    if model == "fmu":
        from moorings.fmu_export import catenary_fmu_variable_map, export_catenary_fmu
        from moorings.fmu_mooring import FMUMooring
        path = export_catenary_fmu(lines(), workdir / "mooring.fmu")
        return FMUMooring(path, lines(), catenary_fmu_variable_map(lines()))
    if model == "moordyn":
        from moorings.moordyn_mooring import MoorDynMooring
        return MoorDynMooring(lines(), segments=10)
    raise ValueError(f"unknown model {model!r}; choose from {MODELS}")


def run(model: str, duration: float, workdir: Path):
    sites = {"fl_left": (-1.0, 0.0, -0.5), "fl_right": (1.0, 0.0, -0.5)}
    box = builders.box("box", (2.0, 1.0), (3.0, 0.0, 0.0), density=500.0, planar=True, sites=sites)
    bodies = MujocoBodies(builders.scene(box, gravity=G, timestep=2e-3))
    fluid = AnalyticFluid(rho=RHO, g=G, linear_damping={"box": [800.0, 0.0, 1500.0, 0.0, 1500.0, 0.0]})
    mooring = make_mooring(model, workdir)
    coupler = Coupler(bodies=bodies, fluid=fluid, moorings=[(mooring, list(sites))])
    t, surge, tension = [], [], []

    def record(info):
        t.append(info.t)
        surge.append(bodies.kinematics().com[0, 0])
        tension.append(np.linalg.norm(mooring.fairlead_forces(), axis=1))

    wall = time.perf_counter()
    coupler.run(duration, callback=record)
    wall = time.perf_counter() - wall
    return np.array(t), np.array(surge), np.array(tension), wall, coupler


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--models", default=",".join(MODELS), help="comma-separated, from " + ", ".join(MODELS))
    parser.add_argument("--duration", type=float, default=20.0, help="simulated time [s]")
    parser.add_argument("--out", type=Path, default=Path("out/moored_box"), help="output folder")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for model in args.models.split(","):
            if model == "moordyn":
                from moorings.moordyn_mooring import moordyn_available
                if not moordyn_available():
                    print("moordyn: skipped (pip install 'cosim-sph[moordyn]' to include it)")
                    continue
            t, surge, tension, wall, coupler = run(model, args.duration, Path(tmp))
            coupler.ledger.write_csv(args.out / f"ledger_{model}.csv")
            results[model] = (t, surge, tension)
            print(f"{model:10s} {coupler.steps} steps in {wall:5.2f} s wall; surge at the end {surge[-1]:+.4f} m, "
                  f"fairlead tensions {tension[-1, 0]:.1f} / {tension[-1, 1]:.1f} N")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 6), dpi=120, sharex=True)
    for model, (t, surge, tension) in results.items():
        line, = ax1.plot(t, surge, label=model)
        ax2.plot(t, tension[:, 0], color=line.get_color(), label=f"{model}, left")
        ax2.plot(t, tension[:, 1], "--", color=line.get_color(), label=f"{model}, right")
    ax1.set_ylabel("surge [m]")
    ax2.set_ylabel("fairlead tension [N]")
    ax2.set_xlabel("t [s]")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(args.out / "moored_box.png")
    print(f"wrote {args.out / 'moored_box.png'} and the ledgers")


if __name__ == "__main__":
    main()
