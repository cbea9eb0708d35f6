"""Is the energy budget of `benchmarks/wave_energy_budget.py` complete? The closed tank of
`benchmarks/standing_wave_decay.py` (its standing wave, 2-D or a 3-D slice) with the
fluid's whole energy, ``E = sum_a m_a (|v_a|^2 / 2 + g z_a + e(rho_a))`` (``e`` the Tait
equation of state's internal energy, ``int p / rho^2 d rho``: Barreiro et al. 2016, Eq. 8
integrated), read every T/32 against the time integral of the four powers that do not
conserve it (density diffusion, artificial viscosity, the floor's and the side walls'
pressures; whole sums here, not the budget's covariances), taken every second rate
evaluation by the trapezoid rule. What is left (``residual_J``) is what the time
integration and anything unmeasured put in (docs/validation/wave-propagation_history.md,
"The wave's energy budget").

    python benchmarks/standing_wave_energy_audit.py --rows 10 --periods 4
    python benchmarks/standing_wave_energy_audit.py --rows 10 --periods 4 --width 5
"""

from __future__ import annotations

import argparse
import json
import math
import time

import numpy as np

from machine import cpu_name  # benchmarks/machine.py, beside this script
from standing_wave_decay import AMPLITUDE, started_tank, tank_mode  # beside this script
from wave_energy_budget import RHO_WATER, term_rates  # beside this script
from cosim.validations.wave_propagation import G, WP_DEPTH as DEPTH
from fluid import equations as eq
from fluid.particles import Kind

TERMS = ("diffusion", "viscosity", "floor", "side walls")


def internal_energy(c, rho) -> np.ndarray:
    """The Tait equation of state's internal energy per unit mass [J/kg] at densities ``rho``
    (``int p / rho^2 d rho`` from ``rho0``; ``c`` the fluid's config)."""
    B, g1 = eq.tait_B(c.rho0, c.speed_of_sound, c.gamma), c.gamma - 1.0
    return B * ((rho ** g1 - c.rho0 ** g1) / (g1 * c.rho0 ** c.gamma) + 1.0 / rho - 1.0 / c.rho0)


def energy(f) -> float:
    """The fluid particles' kinetic, gravitational and internal energy [J]."""
    c, ps = f.config, f.ps
    fl = ps.kind == Kind.FLUID
    m, rho = ps.mass[fl], ps.rho[fl]
    e = internal_energy(c, rho)
    return float((m * (0.5 * (ps.vel[fl] ** 2).sum(axis=1) + G * ps.pos[fl, -1] + e)).sum())


def run(rows: int, width_rows: int, periods: int) -> dict:
    f, _ = started_tank(rows, {}, width_rows)
    width = width_rows * DEPTH / rows
    length, _, omega = tank_mode(DEPTH / rows)
    period = 2.0 * math.pi / omega
    times, powers = [], []
    rates, calls = f._rates, [0]

    def sampled():
        rates()
        calls[0] += 1
        if calls[0] % 2:
            return
        ps = f.ps
        fl = ps.kind == Kind.FLUID
        m, v = ps.mass[fl], ps.vel[fl]
        D, dv, X = term_rates(f, width)
        times.append(f.t)
        powers.append([float((m * ps.p[fl] / ps.rho[fl] ** 2 * D[fl]).sum()),
                       float((m * (v * dv[fl]).sum(axis=1)).sum()),
                       float((m * (v * X["floor"][fl]).sum(axis=1)).sum()),
                       float((m * (v * X["side"][fl]).sum(axis=1)).sum())])

    f._rates = sampled
    cpu0, t, E0 = time.process_time(), 0.0, energy(f)
    out = {"rows": rows, "width_rows": width_rows,
           "wave_energy_J": 0.25 * RHO_WATER * G * AMPLITUDE ** 2 * length * (width if width_rows else 1.0),
           "periods": []}
    for p in range(periods):
        for _ in range(32):
            f.advance(t, period / 32.0)
            t += period / 32.0
        ts, P = np.asarray(times), np.asarray(powers)
        work = {name: float(np.trapezoid(P[:, i], ts)) for i, name in enumerate(TERMS)}
        dE = energy(f) - E0
        out["periods"].append({"t_s": round(t, 4), "energy_change_J": round(dE, 6),
                               "work_J": {k: round(v, 6) for k, v in work.items()},
                               "residual_J": round(dE - sum(work.values()), 6)})
    out["cpu_s"] = round(time.process_time() - cpu0, 1)
    return out


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rows", type=int, default=10, help="particle rows over the depth")
    ap.add_argument("--width", type=int, default=0, help="the slice's width in spacings (0: 2-D)")
    ap.add_argument("--periods", type=int, default=4)
    args = ap.parse_args(argv)
    print(f"# CPU: {cpu_name()}")
    r = run(args.rows, args.width, args.periods)
    print(json.dumps(r))
    print(f"\nthe wave's energy {r['wave_energy_J']:.4f} J")
    print("| t [s] | energy change [J] | " + " | ".join(f"{t} [J]" for t in TERMS) + " | residual [J] |")
    print("|---|---|" + "---|" * (len(TERMS) + 1))
    for p in r["periods"]:
        print(f"| {p['t_s']} | {p['energy_change_J']:.5f} | " + " | ".join(f"{p['work_J'][t]:.5f}" for t in TERMS)
              + f" | {p['residual_J']:.6f} |")


if __name__ == "__main__":
    main()
