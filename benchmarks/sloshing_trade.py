"""Cost against error of the sloshing / base-excitation validations, at several resolutions
(and speeds of sound for westergaard), printed as one table.

    NUMBA_NUM_THREADS=1 .venv/bin/python benchmarks/sloshing_trade.py            # all
    .venv/bin/python benchmarks/sloshing_trade.py --cases westergaard --levels 2

Columns: the case, its resolution dx [m] and c0 [m/s], particles, fluid steps, wall time
[s] (on whatever else the machine is doing: compare rows of one run), and, after the
fluid set-up in brackets (each case's own, then the solver's defaults in the last row),
the case's error metrics:

- westergaard: RMS of k_p on the wall against the exact incompressible series for the
  3 m tank, with the raw boundary-particle pressure, plain Sunara et al. 2021, Eq. 15, and Eq. 15 carried
  to the wall face; plus against the compressible series for the run's c0 (what a
  perfect weakly compressible model would give);
- sloshing-frequency: relative error of the first natural frequency (FFT of the wall
  pressure in free decay) against linear theory;
- sloshing-spheric10 (walls="adami" and the wall-patch sensor, the case's set-up; the
  last row reads the face probe instead): ratio of the first measured impact's peak, its
  lag [s], the ratios of its largest 20 ms mean and of its impulse, and the first swing's
  peak ratio and lag (run to 2.7 s: the first impact).
"""

from __future__ import annotations

import argparse
import time

from cosim.validations.sloshing import run_sloshing_frequency, run_spheric10, run_westergaard
from fluid.solver import SLOSHING_2D

#: the cases' own set-ups (westergaard: walls="adami"; sloshing-frequency: SLOSHING_2D), then
#: the solver's defaults at one resolution for comparison (the last row of each)
_ADAMI = {"walls": "adami"}
RUNS = {
    "westergaard": [dict(dx=0.1, **_ADAMI), dict(dx=0.05, **_ADAMI), dict(dx=0.05, c0=700.0, **_ADAMI),
                    dict(dx=0.05, c0=350.0, **_ADAMI), dict(dx=0.025, **_ADAMI), dict(dx=0.05)],
    "sloshing-frequency": [dict(dx=0.05, **SLOSHING_2D), dict(dx=0.025, **SLOSHING_2D), dict(dx=0.0125, **SLOSHING_2D),
                           dict(dx=0.025, setup="defaults")],
    "sloshing-spheric10": [dict(dx=0.0186, t_end=2.7), dict(dx=0.0093, t_end=2.7), dict(dx=0.0062, t_end=2.7),
                           dict(dx=0.00465, t_end=2.7), dict(dx=0.0062, t_end=2.7, sensor="face")],
}


def _row(case: str, kw: dict) -> dict:
    t0 = time.perf_counter()
    if case == "westergaard":
        r = run_westergaard(**kw)
        m = r["metrics"]
        err = (f"raw {m['rms_raw_vs_exact']:.4f}  Eq.15 {m['rms_avg_vs_exact']:.4f}  "
               f"face {m['rms_face_vs_exact']:.4f}  face-vs-compressible {m['rms_face_vs_compressible']:.4f}")
        c0 = m["c0_m_s"]
    elif case == "sloshing-frequency":
        r = run_sloshing_frequency(**kw)
        m = r["metrics"]
        err = f"f1 {m['f1_hz']:.4f} Hz vs {m['f1_linear_hz']:.4f}: {m['f1_signed_rel_err']:+.4f}"
        c0 = m["c0_m_s"]
    else:
        r = run_spheric10(**kw)
        m = r["metrics"]
        err = (f"impact1 peak {m.get('impact1_peak_ratio', float('nan')):.3f} lag "
               f"{m.get('impact1_lag_s', float('nan')):+.3f} s, 20 ms mean "
               f"{m.get('impact1_mean20ms_ratio', float('nan')):.3f}, impulse "
               f"{m.get('impact1_impulse_ratio', float('nan')):.3f}; swing1 peak {m['swing1_peak_ratio']:.3f} "
               f"lag {m['swing1_lag_s']:+.3f} s")
        c0 = m["c0_m_s"]
    setup = ",".join(f"{k}={v}" for k, v in kw.items() if k in ("walls", "h_coef", "sensor")) or "defaults"
    return {"case": case, "dx": kw["dx"], "c0": c0, "particles": r["particles"], "steps": r["steps"],
            "wall_s": time.perf_counter() - t0, "error": f"[{setup}] {err}"}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", nargs="*", default=list(RUNS), choices=list(RUNS))
    ap.add_argument("--levels", type=int, default=99, help="run only the first N settings of each case")
    a = ap.parse_args(argv)
    print(f"{'case':<20} {'dx [m]':>8} {'c0 [m/s]':>9} {'particles':>9} {'steps':>7} {'wall [s]':>9}  error")
    for case in a.cases:
        for kw in RUNS[case][:a.levels]:
            r = _row(case, kw)
            print(f"{r['case']:<20} {r['dx']:>8.4g} {r['c0']:>9.4g} {r['particles']:>9d} {r['steps']:>7d} "
                  f"{r['wall_s']:>9.1f}  {r['error']}", flush=True)


if __name__ == "__main__":
    main()
