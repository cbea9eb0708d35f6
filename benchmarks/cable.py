"""Cost of the SPH cable (Dinçer & Demir 2020) -- a benchmark, not a test.

Prints
1. compile time of the compiled kernels (in a fresh process with an empty numba cache)
   and the cache-load time of a warm start;
2. microseconds per particle-step and wall time per simulated second at several particle
   counts, for a line in air (Dinçer & Demir 2020, Experiment 2) and for a 100-particle mooring line
   in water (Morison drag, added mass, seabed), next to the cost of one quasi-static
   catenary evaluation (moorings.catenary.solve) for the same line;
3. the speed/accuracy trade (error and wall time at several particle counts) of Dinçer & Demir 2020,
   Case 1 (displacement of L against the exact elastic catenary), Experiment 2 at rest
   (shape and reactions), the mooring line against the quasi-static catenary,
   Experiment 2 shaken (free period against the measured 0.42 s and against the finest
   run) and Experiment 1 released at one end (free-end position and dissipated energy
   against the finest run: no measured trajectory exists).

Run: ``.venv/bin/python benchmarks/cable.py`` (``--quick`` for fewer sizes).
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from moorings.line import MooringLine
from moorings.sph_cable import SPHCable, SPHCableMooring

_FIRST_CALL = """
import time
t = time.perf_counter()
from moorings.sph_cable import SPHCable
c = SPHCable(1.0, 11, 1e4, 0.1, (0, 0), (0.9, 0))
c.advance(0.0, 1e-3)
print(time.perf_counter() - t)
"""


def first_call_seconds(empty_cache: bool) -> float:
    env = dict(os.environ)
    with tempfile.TemporaryDirectory() as d:
        if empty_cache:
            env["NUMBA_CACHE_DIR"] = d
        out = subprocess.run([sys.executable, "-c", _FIRST_CALL], env=env, capture_output=True, text=True, check=True)
    return float(out.stdout.strip().splitlines()[-1])


def per_particle_step(c, seconds: float, chunk: float) -> tuple[float, float]:
    """(microseconds per particle-step, wall seconds per simulated second)."""
    c.advance(c.t, chunk)  # warm
    s0, t0, w0 = c.steps, c.t, time.perf_counter()
    while c.t < t0 + seconds - 1e-12:
        c.advance(c.t, chunk)
    wall = time.perf_counter() - w0
    return 1e6 * wall / ((c.steps - s0) * c.n), wall / (c.t - t0)


def main(quick: bool = False) -> None:
    print("compile (empty numba cache): %.2f s; warm start (cache load): %.2f s"
          % (first_call_seconds(True), first_call_seconds(False)))

    print("\nline in air, Dinçer & Demir 2020, Experiment 2 (EA = 21.4 kN, l = 1.272 m), cfl 0.4")
    print(f"{'particles':>10} {'stable dt [s]':>14} {'us/particle-step':>17} {'wall s per sim s':>17}")
    for n in ([25, 100, 400] if quick else [25, 100, 400, 1600]):
        c = SPHCable(1.272, n, 2.14e4, 0.02708, (0, 0), (1.2, -0.22), weight_per_length=0.2656)
        c.set_harmonic("a", (0.025, 0.0), 1.0)
        us, ws = per_particle_step(c, 0.02 if n >= 400 else 0.1, 0.01)
        print(f"{n:>10} {c.stable_dt():>14.3g} {us:>17.4f} {ws:>17.3g}")

    print("\n100-particle mooring line in water (l = 150 m, h = 50 m, EA = 1 GN, chain 107.7 kg/m, d = 0.15 m)")
    line = MooringLine(anchor=(0.0, -50.0), length=150.0, weight=918.75, EA=1e9, mass_per_length=107.7, diameter=0.15)
    m = SPHCableMooring([line], fairleads=[[130.0, 0.0]], n_particles=100)
    m.initialize(0.0)
    c = m.cables[0]
    us, ws = per_particle_step(c, 2.0, 0.1)
    print(f"SPH cable: {us:.4f} us per particle-step, {ws:.3g} s wall per simulated second "
          f"(stable dt {c.stable_dt():.3g} s)")
    from moorings.catenary import solve

    solve(130.0, 50.0, 150.0, 918.75, 1e9)
    k = 20000
    w0 = time.perf_counter()
    for i in range(k):
        solve(130.0 + 1e-4 * (i % 7), 50.0, 150.0, 918.75, 1e9)
    print(f"catenary law: {1e6 * (time.perf_counter() - w0) / k:.2f} us per evaluation (quasi-static: one per "
          "coupling step)")

    from cosim.validations.cable import (case1_scene, exp2_scene, exp2_static_metrics, run_case1, run_vs_catenary,
                                         vs_catenary_scene)

    print("\nDinçer & Demir 2020, Case 1 (35.586 kN at L): error of the displacement of L against the exact catenary")
    print(f"{'particles':>10} {'err dz':>10} {'err dx':>10} {'err dz vs Table 2':>18} {'wall [s]':>9}")
    for n in ([20, 40, 80] if quick else [20, 40, 80, 160, 313]):
        w0 = time.perf_counter()
        mm = run_case1(case1_scene(False, particles=n))[0]
        print(f"{n:>10} {mm['err_dz_vs_exact']:>10.2e} {mm['err_dx_vs_exact']:>10.2e} "
              f"{mm['err_dz_vs_table2']:>18.2e} {time.perf_counter() - w0:>9.2f}")

    print("\nDinçer & Demir 2020, Experiment 2 at rest: shape and reactions against the exact catenary")
    print(f"{'particles':>10} {'max shape err [m]':>18} {'err H vs exact':>15} {'err V at P0':>12} {'wall [s]':>9}")
    for n in ([16, 31, 61] if quick else [16, 31, 61, 121]):
        w0 = time.perf_counter()
        mm = exp2_static_metrics(exp2_scene("cable-exp2-static", False, particles=n))[0]
        print(f"{n:>10} {mm['shape_max_err_m']:>18.2e} {mm['err_H_vs_exact']:>15.2e} {mm['err_V_P0_vs_exact']:>12.2e} "
              f"{time.perf_counter() - w0:>9.2f}")

    print("\nmooring line with seabed, fairlead moved at 0.05 m/s: fairlead tension vs the quasi-static catenary")
    print(f"{'particles':>10} {'max |err T|':>12} {'wall [s]':>9}")
    for n in ([10, 20, 40] if quick else [10, 20, 40, 80]):
        w0 = time.perf_counter()
        mm = run_vs_catenary(vs_catenary_scene(False, particles=n))[0]
        print(f"{n:>10} {mm['max_abs_err_tension']:>12.2e} {time.perf_counter() - w0:>9.2f}")

    shake_convergence([16, 31, 61] if quick else [16, 31, 61, 121])
    free_fall_convergence([24, 48, 95] if quick else [24, 48, 95, 190, 380])


def shake_convergence(sizes: list[int]) -> None:
    """cable-exp2-shake (the case's geometry: the length fitted to the measured shape)."""
    from cosim.validations.cable import (EXP2_PERIOD, SHAKE_NFFT, fit_length_to_measured_shape, run_exp2_shake,
                                         shake_scene)

    L = fit_length_to_measured_shape()
    bin_ms = 1e3 * EXP2_PERIOD**2 / (SHAKE_NFFT * shake_scene(False).world.sample_every)
    print(f"\nDinçer & Demir 2020, Experiment 2 shaken (l = {L:.4f} m fitted to Table 5): free period vs the measured "
          f"{EXP2_PERIOD} s and vs the finest run\n(FFT peak: one spectral bin is {bin_ms:.1f} ms of period; "
          "wall = both types)")
    print(f"{'particles':>10} {'T1 [s]':>8} {'err T1':>9} {'dT1 [ms]':>9} {'T2 [s]':>8} {'err T2':>9} "
          f"{'dT2 [ms]':>9} {'wall [s]':>9}")
    rows = []
    for n in sizes:
        w0 = time.perf_counter()
        T1 = run_exp2_shake(shake_scene(False, 1.0, L, particles=n))[0]
        T2 = run_exp2_shake(shake_scene(False, 1.5, L, particles=n))[0]
        rows.append((n, T1, T2, time.perf_counter() - w0))
    f1, f2 = rows[-1][1:3]
    for n, T1, T2, wall in rows:
        print(f"{n:>10} {T1:>8.4f} {T1 / EXP2_PERIOD - 1:>+9.2%} {1e3 * (T1 - f1):>+9.2f} {T2:>8.4f} "
              f"{T2 / EXP2_PERIOD - 1:>+9.2%} {1e3 * (T2 - f2):>+9.2f} {wall:>9.2f}")


def free_fall_convergence(sizes: list[int], times=(0.3, 0.6, 0.9, 1.2)) -> None:
    """cable-free-fall: distance of the free end from the finest run's at fixed times and
    the dissipated energy (fraction of w L^2), against the finest run."""
    from cosim.validations.cable import free_fall_scene, run_free_fall

    runs = []
    for n in sizes:
        w0 = time.perf_counter()
        m, _ = run_free_fall(free_fall_scene(False, particles=n))
        traj = {round(t, 3): np.array([x, z]) for t, x, z in m["free_end_xz_every_0.1s"]}
        runs.append((n, traj, m["dissipated_fraction_of_w_L_L"], time.perf_counter() - w0))
    fine, dfine = runs[-1][1], runs[-1][2]
    print("\nDinçer & Demir 2020, Experiment 1 released at P5: free end |x - x_finest| [mm] at t [s] (max: over 0.1-1.2 s "
          "every 0.1 s)\nand energy dissipated by 1.2 s (fraction of w L^2) vs the finest run")
    head = "".join(f"{f't={t:g}':>8}" for t in times)
    print(f"{'particles':>10}{head}{'max':>8} {'dissipated':>11} {'d dissip':>9} {'wall [s]':>9}")
    for n, traj, diss, wall in runs:
        d = {t: 1e3 * float(np.linalg.norm(traj[t] - fine[t])) for t in fine}
        cols = "".join(f"{d[round(t, 3)]:>8.3f}" for t in times)
        print(f"{n:>10}{cols}{max(d.values()):>8.3f} {diss:>11.5f} {diss - dfine:>+9.1e} {wall:>9.2f}")


if __name__ == "__main__":
    main(quick="--quick" in sys.argv)
