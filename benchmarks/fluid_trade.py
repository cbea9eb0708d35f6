"""Cost-vs-error trade tables of the SPH fluid (DESIGN.md, validation tier 4) for the
``hydrostatic`` (2-D tank at rest) and ``dambreak-2d`` cases: error and wall time at
several resolutions, and at one resolution for each lever: c0 (c0_factor 10/20/40),
kernel (wendland/cubic), density diffusion (fourtakas/molteni/none; Fourtakas with
delta = 0.03 instead of 0.1; the renormalised "antuono"; Fourtakas faded under the free
surface, diffusion_at_surface=False, the set-up of the 3-D hydrostatic case), MLS density
re-initialisation (off / every 30 steps,
Sunara et al. 2021, Eq. 9-12), the tank walls' density (plain dynamic boundaries /
walls="adami", fluid.wall_density), the artificial viscosity with the walls
(alpha_wall 1 / 0), the smoothing length (h = 2 dx) and the wave set-up
(fluid.solver.SLOSHING_2D: h = 2 dx with walls="adami"; the hydrostatic rows start from
the lattice, without Fluid.settle).

    python benchmarks/fluid_trade.py [--case hydrostatic|dambreak|all] [--quick] [--csv FILE]

Errors are the cases' own metrics (cosim/validations/fluid.py): hydrostatic, RMS of the
time-averaged pressure error over rho g H and the largest speed over sqrt(g H);
dam break, RMS relative error of the surge front against Martin & Moyce (1952) and
Koshizuka & Oka (1996), the back-wall residual height against Martin & Moyce, and the
particle-scale pressure noise. Wall time is this process's, on whatever the machine is
doing (threads as FluidConfig decides; set NUMBA_NUM_THREADS to fix them), after a
warm-up run that compiles the kernels.
"""

from __future__ import annotations

import argparse
import csv
import sys
import time

from cosim.validations.fluid import run_dambreak, run_hydrostatic
from fluid.solver import SLOSHING_2D

LEVERS = [{"c0_factor": 10.0}, {"c0_factor": 20.0}, {"c0_factor": 40.0}, {"kernel": "cubic"},
          {"diffusion": "molteni"}, {"diffusion": "none"}, {"diffusion": "antuono"}, {"delta": 0.03},
          {"diffusion_at_surface": False}, {"mls_every": 30}, {"walls": "adami"}, {"alpha_wall": 0.0},
          {"h_coef": 2.0}, dict(SLOSHING_2D)]
#: each case's own c0_factor (its "defaults" row): hydrostatic 20, dam break 10
C0_DEFAULT = {"hydrostatic": 20.0, "dambreak-2d": 10.0}


def _levers(case):
    return [kw for kw in LEVERS if kw.get("c0_factor") != C0_DEFAULT[case]]


def _hydro_rows(quick: bool):
    dxs = (0.04, 0.02, 0.01) if not quick else (0.04, 0.02)
    base = 0.02
    runs = [({"dx": dx}, {}) for dx in dxs]
    runs += [({"dx": base}, kw) for kw in _levers("hydrostatic")]
    for geo, kw in runs:
        t0 = time.perf_counter()
        rec = run_hydrostatic(2, dx=geo["dx"], t_end=2.0, **kw)
        wall = time.perf_counter() - t0
        m = rec["metrics"]
        yield {"case": "hydrostatic", "dx_m": geo["dx"], "lever": _name(kw), "particles": rec["particles"],
               "steps": rec["steps"], "wall_s": round(wall, 1),
               "err1": m["p_rms_err_time_avg"], "err1_name": "p_rms/rhogH",
               "err2": m["max_speed_over_sqrt_gH"], "err2_name": "vmax/sqrt(gH)",
               "err3": m["wall_p_rms_err_time_avg"], "err3_name": "wall_p_rms/rhogH"}


def _dam_rows(quick: bool):
    nas = (10, 20, 40) if not quick else (10, 20)
    base = 20
    runs = [(n, {}) for n in nas] + [(base, kw) for kw in _levers("dambreak-2d")]
    for n, kw in runs:
        t0 = time.perf_counter()
        rec = run_dambreak(n, **kw)
        wall = time.perf_counter() - t0
        m = rec["metrics"]
        yield {"case": "dambreak-2d", "dx_m": round(m["dx_m"], 5), "lever": _name(kw), "particles": rec["particles"],
               "steps": rec["steps"], "wall_s": round(wall, 1),
               "err1": m["front_rms_rel_err_mm1952"], "err1_name": "front_rms_MM",
               "err2": m["front_rms_rel_err_ko1996"], "err2_name": "front_rms_KO",
               "err3": m["height_rms_rel_err_mm1952"], "err3_name": "height_rms_MM",
               "err4": m["p_noise_rms"], "err4_name": "p_noise/rhog2a"}


def _warm_up():
    """Compile (or load from numba's cache) every kernel before anything is timed."""
    run_dambreak(8, T_end=1.0, mls_every=1)


def _name(kw):
    return ",".join(f"{k}={v}" for k, v in kw.items()) or "defaults"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", choices=("hydrostatic", "dambreak", "all"), default="all")
    ap.add_argument("--quick", action="store_true", help="fewer resolutions (no finest)")
    ap.add_argument("--csv", help="also write the rows to this CSV file")
    a = ap.parse_args(argv)
    gens = []
    if a.case in ("hydrostatic", "all"):
        gens.append(_hydro_rows(a.quick))
    if a.case in ("dambreak", "all"):
        gens.append(_dam_rows(a.quick))
    _warm_up()
    rows = []
    print(f"{'case':12s} {'dx [m]':>8s} {'lever':28s} {'N':>6s} {'steps':>6s} {'wall [s]':>8s}  errors")
    for g in gens:
        for r in g:
            rows.append(r)
            errs = "  ".join(f"{r[f'err{i}_name']}={r[f'err{i}']:.4g}" for i in range(1, 5) if f"err{i}" in r)
            print(f"{r['case']:12s} {r['dx_m']:8.4f} {r['lever']:28s} {r['particles']:6d} {r['steps']:6d} "
                  f"{r['wall_s']:8.1f}  {errs}", flush=True)
    if a.csv:
        keys = sorted({k for r in rows for k in r})
        with open(a.csv, "w", newline="") as fh:
            w = csv.DictWriter(fh, keys)
            w.writeheader()
            w.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
