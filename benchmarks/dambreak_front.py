"""What moves the dam-break surge front (``dambreak-2d``, cosim/validations/fluid.py): error
and wall time at several resolutions, and at 20 particles across the column one change at a
time (the solver's levers, and a gate lifted at finite speed instead of the instantaneous
release).

    python benchmarks/dambreak_front.py [--what resolution|levers|gate|all] [--fine]

Columns: Z at T = 1, 2, 3 (T = t sqrt(2g/a), Z = x_front / a); the RMS relative error
against Martin & Moyce's Table 2 as measured (the experiment's clock taken as is); the
experiment's time-origin offset fitted over the points after its release phase and the RMS
error after it (the case's judged metric, 5 %); the back-wall residual height in the first
half of the collapse; wall time of this process (threads as FluidConfig decides; set
NUMBA_NUM_THREADS to fix them), after a warm-up run that compiles the kernels. ``--fine``
adds 80 particles across the column to the resolution table (about 10 minutes on one core).
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from cosim.validations.fluid import run_dambreak

LEVERS = [("defaults", {}), ("alpha=0.001", {"alpha": 0.001}), ("alpha=0.05", {"alpha": 0.05}),
          ("alpha=0.1", {"alpha": 0.1}), ("nu=1e-6 (water)", {"nu": 1e-6}), ("nu=1e-4", {"nu": 1e-4}),
          ("c0_factor=20", {"c0_factor": 20.0}), ("c0_factor=40", {"c0_factor": 40.0}),
          ("h_coef=1.2", {"h_coef": 1.2}), ("h_coef=2", {"h_coef": 2.0}),
          ("diffusion=none", {"diffusion": "none"}), ("integrator=verlet", {"integrator": "verlet"})]
GATES = [0.0, 0.25, 0.5, 1.0]


def _row(label: str, n_a: int, **kw) -> str:
    t0 = time.perf_counter()
    rec = run_dambreak(n_a, **kw)
    wall = time.perf_counter() - t0
    m = rec["metrics"]
    TZ = np.array(m["front_T_Z"])
    z = [np.interp(T, TZ[:, 0], TZ[:, 1]) for T in (1.0, 2.0, 3.0)]
    return (f"| {label} | {n_a} | {rec['particles']} | {rec['steps']} | {z[0]:.3f} | {z[1]:.3f} | {z[2]:.3f} | "
            f"{100 * m['front_rms_rel_err_mm1952_table2']:.1f} | {m['front_release_delay_T_mm1952']:.3f} | "
            f"{100 * m['front_rms_rel_err_mm1952_after_release']:.1f} | {100 * m['height_rms_rel_err_mm1952']:.1f} | "
            f"{m['front_detached_particles_max']} | {wall:.0f} |")


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--what", choices=("resolution", "levers", "gate", "all"), default="all")
    ap.add_argument("--fine", action="store_true", help="add n_a = 80 to the resolution table")
    a = ap.parse_args(argv)
    run_dambreak(8, T_end=0.5, gate_T_open=0.1)  # warm-up: compile or load every kernel
    print("| run | n_a | particles | steps | Z(T=1) | Z(T=2) | Z(T=3) | raw RMS % (Table 2) | fitted delay T | "
          "RMS % after release | height RMS % | detached | wall s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    if a.what in ("resolution", "all"):
        for n in (10, 20, 40) + ((80,) if a.fine else ()):
            print(_row("resolution", n), flush=True)
    if a.what in ("levers", "all"):
        for label, kw in LEVERS:
            print(_row(label, 20, **kw), flush=True)
    if a.what in ("gate", "all"):
        for T_open in GATES:
            print(_row(f"gate lifted over T = {T_open}", 20, gate_T_open=T_open), flush=True)


if __name__ == "__main__":
    main()
