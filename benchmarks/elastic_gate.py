"""Resolution table of the elastic-gate case (Antoci et al. 2007; cosim/validations/elastic_gate.py):
the free end against the measured frames, and the cost, at each dx.

    python benchmarks/elastic_gate.py --dx 0.005,0.0025,0.00125 [--t-end 0.4] [--E 12e6] [--elements 16]
    python benchmarks/elastic_gate.py --dx 0.0025 --zeta 0,0.05,0.1,0.2   # rubber damping, a sensitivity

Prints per dx: particles, coupling steps, CPU seconds (``time.process_time``, all threads) and CPU s
per simulated s, the RMS difference over the frames relative to the measured peak (x, y; the
judged 15 %), the peaks and their lag behind the measured ones (judged: within 0.04 s). Compare
CPU times, not wall times, on a shared machine. ``--zeta``: the damping ratio of the gate's
first mode (stiffness-proportional, beta = 2 zeta / omega_1, omega_1 the clamped-free
Euler-Bernoulli mode of the dry gate, ``BeamModel.natural_frequencies``); the validation has none."""

from __future__ import annotations

import argparse
import math

from machine import cpu_name

from bodies.elastic import elastic_beam
from cosim.validations.elastic_gate import E_S, GATE_B, GATE_L, NU_S, RHO_S, compare, run_elastic_gate


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dx", default="0.005,0.0025,0.00125", help="particle spacings [m], comma separated")
    ap.add_argument("--t-end", type=float, default=0.4, help="simulated time [s]")
    ap.add_argument("--E", type=float, default=E_S, help="the gate's Young's modulus [Pa]")
    ap.add_argument("--elements", type=int, default=16, help="chain elements N")
    ap.add_argument("--zeta", default="0", help="first-mode damping ratios, comma separated (0: none)")
    a = ap.parse_args(argv)
    dry = elastic_beam("gate", GATE_L, GATE_B, E=a.E, rho=RHO_S, nu=NU_S)
    omega1 = 2.0 * math.pi * dry.natural_frequencies(1, "euler-bernoulli")[0]  # rad/s
    runs = [(float(dx), float(z)) for dx in a.dx.split(",") for z in a.zeta.split(",")]
    print(f"elastic-gate, E = {a.E:.4g} Pa, N = {a.elements}, {a.t_end} s; CPU: {cpu_name()}")
    print(f"{'dx [mm]':>8} {'zeta':>5} {'particles':>9} {'steps':>6} {'CPU s':>7} {'CPU s/sim s':>11} "
          f"{'rms x':>6} {'rms y':>6} "
          f"{'peak x [mm]':>11} {'at [s]':>6} {'peak y [mm]':>11} {'lag x [s]':>9} {'lag y [s]':>9}")
    for dx, zeta in runs:
        r = run_elastic_gate(dx, a.t_end, n_elements=a.elements, E=a.E, beta=2.0 * zeta / omega1)
        m = compare(r["t"], r["x"], r["y"], a.t_end)
        print(f"{1e3 * dx:8.3g} {zeta:5.2f} {r['particles']:9d} {r['steps']:6d} {r['cpu_s']:7.1f} "
              f"{r['cpu_s'] / a.t_end:11.1f} "
              f"{m['rms_rel_x']:6.3f} {m['rms_rel_y']:6.3f} {m['peak_mm_x']:11.1f} {m['peak_t_s_x']:6.3f} "
              f"{m['peak_mm_y']:11.1f} {m['peak_lag_s_x']:9.3f} {m['peak_lag_s_y']:9.3f}", flush=True)


if __name__ == "__main__":
    main()
