"""Resolution table of the dambreak-lobovsky case (Yang & Li 2020, Appendix A, Lobovsky et al. 2014,
H = 0.3 m; cosim/validations/dambreak_lobovsky.py): the water levels at H1-H4 against the
measured runs, and the cost, at each dx.

    python benchmarks/dambreak_lobovsky.py --dx 0.015,0.01,0.005 [--t-star 11]

Prints per dx: particles, steps, CPU seconds (``time.process_time``, all threads) and CPU s per
simulated s, the largest RMS difference of h/H over t* <= 5 (judged: 0.05), the largest arrival
error at H2-H4 in t* (judged: 0.25), and the RMS over the reflected bore (t* > 5) against each run;
then the wall pressure at P1-P4 (reported, PRESSURE_TARGET) read both ways: the first impact peak
and its time against the measured run's, the RMS over the record, the window means.
Compare CPU times, not wall times, on a shared machine."""

from __future__ import annotations

import argparse
import math

from machine import cpu_name

from cosim.validations.dambreak_lobovsky import H, compare, compare_pressure, run_lobovsky


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dx", default="0.015,0.01,0.005", help="particle spacings [m], comma separated")
    ap.add_argument("--t-star", type=float, default=11.0, help="simulated t* = t sqrt(g/H)")
    a = ap.parse_args(argv)
    sim_s = a.t_star / math.sqrt(9.81 / H)
    print(f"dambreak-lobovsky, H = {H} m, t* <= {a.t_star} ({sim_s:.3f} s); CPU: {cpu_name()}")
    for dx in (float(v) for v in a.dx.split(",")):
        r = run_lobovsky(dx, a.t_star)
        m = compare(r["t_star"], r["h"], a.t_star)
        late = ", ".join(f"{k} {v:.3f}" for k, v in m["rms_late"].items())
        early = ", ".join(f"{k} {v:.3f}" for k, v in m["rms_early"].items())
        arrive = ", ".join(f"{k} {v:+.3f}" for k, v in m["arrival_err_t_star"].items())
        print(f"dx {1e3 * dx:.3g} mm (H/{H / dx:.0f}): {r['particles']} particles, {r['steps']} steps, "
              f"{r['cpu_s']:.1f} CPU s, {r['cpu_s'] / sim_s:.1f} CPU s per simulated s; "
              f"rms t*<=5 max {m['rms_early_max']:.4f} ({early}); "
              f"arrival error max {m['arrival_err_abs_max']:.3f} ({arrive}); "
              f"rms t*>5: {late or '-'}", flush=True)
        for key in ("p", "p_point"):
            pm = compare_pressure(r["t_star_p"], r[key], a.t_star)
            peaks = ", ".join(f"{k} {v:.2f} ({pm['peak_rel_err'][k]:+.0%}) at t* {pm['peak_t_star'][k]:.3f} "
                              f"({pm['peak_t_err'][k]:+.3f})" for k, v in pm["peak"].items())
            rms = ", ".join(f"{k} {v:.3f}" for k, v in pm["rms"].items())
            means = ", ".join(f"{k} {v[0]:.2f}/{v[1]:.2f}" for k, v in pm["window_mean"].items())
            print(f"  wall pressure p/(rho g H), {'patch' if key == 'p' else 'Eq. 15 at the face'}: first peak "
                  f"{peaks}; rms {rms}; window means ours/measured {means}", flush=True)


if __name__ == "__main__":
    main()
