"""Cost per coupling step of each mooring model on the same mooring system.

Three elastic 3-D lines (150 m, 900 N/m, EA = 2e8 N, 120 degrees apart) on a body
that surges slowly; one coupling step is ``set_fairlead_motion`` +
``advance(t, dt)`` + ``fairlead_forces`` at the coupling step ``--dt``:

- native: :class:`moorings.catenary_mooring.CatenaryMooring` (numba law)
- fmu:    the same law exported as an FMU (compiled C) through fmpy, :class:`FMUMooring`
- fmu-c:  the FMU's own C evaluation time, fmpy's ctypes calls excluded (GetReal after a SetReal)
- moordyn: :class:`MoorDynMooring` (lumped mass, 20 segments per line, its internal
  step sub-cycling each coupling step), when the ``moordyn`` package is installed

    python benchmarks/mooring_models.py [--steps 2000] [--dt 0.01] [--png tensions.png]

``--png`` also plots the fairlead tension of each line against time for every
model on one figure (the body surges 4 m over 20 s from rest).

Prints figures; asserts nothing. Set-up (export + compile, MoorDyn's initial
state) is reported apart from the per-step cost.
"""

from __future__ import annotations

import argparse
import ctypes
import math
import platform
import sys
import tempfile
import time
from pathlib import Path

# this file is named like the package it measures: keep its folder off the import path, and if a
# script in this folder imported it as "moorings", hand that import over to the real package
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != Path(__file__).resolve().parent]
if __name__ == "moorings":
    import importlib

    del sys.modules["moorings"]
    sys.modules["moorings"] = importlib.import_module("moorings")

import numpy as np  # noqa: E402

from moorings.catenary_mooring import CatenaryMooring  # noqa: E402
from moorings.fmu_export import catenary_fmu_variable_map, export_catenary_fmu  # noqa: E402
from moorings.fmu_mooring import FMUMooring  # noqa: E402
from moorings.line import MooringLine  # noqa: E402
from moorings.moordyn_mooring import MoorDynMooring, moordyn_available  # noqa: E402


def system():
    az = (0.0, 2 * math.pi / 3, 4 * math.pi / 3)
    lines = [MooringLine((120 * math.cos(a), 120 * math.sin(a), -60.0), 150.0, 900.0, EA=2e8,
                         mass_per_length=110.0, name=f"leg{i}") for i, a in enumerate(az)]
    fb = np.array([[8 * math.cos(a), 8 * math.sin(a), -5.0] for a in az])
    return lines, fb


def motion(t, fb):
    w = 2 * math.pi / 40.0
    return fb + np.array([4.0 * (1 - math.cos(w * t)), 0, 0]), np.tile([4.0 * w * math.sin(w * t), 0, 0], (3, 1))


def run(model, fb, steps, dt, record=None):
    """Seconds per coupling step, and the last forces; ``record`` collects (t, tensions)."""
    model.initialize(0.0)
    t0 = time.perf_counter()
    for k in range(steps):
        t = k * dt
        pos, vel = motion(t, fb)
        model.set_fairlead_motion(pos, vel)
        model.advance(t, dt)
        f = model.fairlead_forces()
        if record is not None:
            record.append((t + dt, np.linalg.norm(f, axis=1)))
    return (time.perf_counter() - t0) / steps, f


def plot(path, records):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.5, 4.2), dpi=120)
    styles = {"native": "-", "fmu": "--", "moordyn": ":"}
    for name, rec in records.items():
        t = np.array([r[0] for r in rec])
        T = np.array([r[1] for r in rec]) / 1e3
        for i in range(T.shape[1]):
            ax.plot(t, T[:, i], styles.get(name, "-"), color=f"C{i}", lw=1.4, label=f"{name}, leg{i}")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("fairlead tension [kN]")
    ax.set_title("Same mooring, three models: native catenary, its FMU (on top of it), MoorDyn", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=3)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=2000, help="coupling steps per model")
    ap.add_argument("--dt", type=float, default=0.01, help="coupling step [s]")
    ap.add_argument("--png", help="also plot the fairlead tensions of every model (a separate, recorded run)")
    args = ap.parse_args()
    lines, fb = system()
    print(f"# {platform.processor() or platform.machine()}, Python {platform.python_version()}; "
          f"3 lines, {args.steps} coupling steps of {args.dt} s")
    print(f"{'model':10s} {'us/step':>10s} {'setup s':>9s}  note")
    rows = []

    t0 = time.perf_counter()
    native = CatenaryMooring(lines, fairleads=fb)
    native.set_fairlead_motion(fb)  # compile / load the numba cache
    setup = time.perf_counter() - t0
    cost, f_native = run(native, fb, args.steps, args.dt)
    rows.append(("native", cost, setup, "numba quasi-static catenary"))

    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        path = export_catenary_fmu(lines, Path(tmp) / "bench.fmu", fairleads=fb)
        fmu = FMUMooring(path, lines, catenary_fmu_variable_map(lines), fairleads=fb)
        setup = time.perf_counter() - t0
        cost, f_fmu = run(fmu, fb, args.steps, args.dt)
        rel = float(np.max(np.abs(f_fmu - f_native)) / np.max(np.abs(f_native)))
        rows.append(("fmu", cost, setup, f"fmpy FMU2Slave calls; last forces vs native: {rel:.1e} relative"))
        # the C evaluation alone: one SetReal (invalidates) + GetReal of the forces, called directly
        lib, comp = fmu._fmu.dll, fmu._fmu.component
        vr_in = (ctypes.c_uint * 9)(*fmu._vr_pos)
        vr_out = (ctypes.c_uint * 9)(*fmu._vr_force)
        vals, out = (ctypes.c_double * 9)(*fb.ravel()), (ctypes.c_double * 9)()
        n = 20 * args.steps
        t0 = time.perf_counter()
        for _ in range(n):
            lib.fmi2SetReal(comp, vr_in, 9, vals)
            lib.fmi2GetReal(comp, vr_out, 9, out)
        rows.append(("fmu-c", (time.perf_counter() - t0) / n, 0.0, "fmi2SetReal + fmi2GetReal through bare ctypes"))
        fmu.close()

    if moordyn_available():
        t0 = time.perf_counter()
        md = MoorDynMooring(lines, fairleads=fb)
        md.initialize(0.0)
        setup = time.perf_counter() - t0
        cost, f_md = run(md, fb, args.steps, args.dt)
        cat = CatenaryMooring(lines, fairleads=motion(args.steps * args.dt, fb)[0]).fairlead_forces()
        rel = float(np.max(np.linalg.norm(f_md - cat, axis=1) / np.linalg.norm(cat, axis=1)))
        rows.append(("moordyn", cost, setup, f"dtM = {md.dt_internal:.2e} s ({math.ceil(args.dt / md.dt_internal)} "
                                             f"sub-steps); vs catenary {rel:.1%}"))
        md.close()
    else:
        print("moordyn    (not installed: pip install .[moordyn])")

    for name, cost, setup, note in rows:
        print(f"{name:10s} {cost * 1e6:10.1f} {setup:9.3f}  {note}")

    if args.png:  # recorded runs, apart from the timed ones
        steps = int(round(20.0 / args.dt))
        records = {}
        with tempfile.TemporaryDirectory() as tmp:
            models = {"native": CatenaryMooring(lines, fairleads=fb)}
            path = export_catenary_fmu(lines, Path(tmp) / "plot.fmu", fairleads=fb)
            models["fmu"] = FMUMooring(path, lines, catenary_fmu_variable_map(lines), fairleads=fb)
            if moordyn_available():
                models["moordyn"] = MoorDynMooring(lines, fairleads=fb)
            for name, model in models.items():
                records[name] = []
                run(model, fb, steps, args.dt, records[name])
            models["fmu"].close()
        plot(args.png, records)
        print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
