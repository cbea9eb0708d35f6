"""Is a flume's decay per wavelength a steady figure? The wave-propagation case reads its
stations over one window, the last three periods of a run that ends four periods after the
ramp's front (at the group velocity) has passed the last station. This probe samples the
same gauges from ``--from`` [s] to ``--extra`` periods past that end and reads every
window of ``--window`` periods, a period apart: each station's first-harmonic height over
linear theory's (cosim.validations.wave_propagation.flume_figures, the front included) and
the decay per wavelength fitted over the stations the front has passed by four periods.
If the decay moves from window to window by more than it moves with dx, the case's one
window cannot tell whether the decay converges.

    python benchmarks/wave_decay_windows.py --rows 20
    python benchmarks/wave_decay_windows.py --rows 40 --save /tmp/flume40.npz

The wave, the flume and the set-up are the case's (d = 0.3 m, T = 1 s, H = 4 cm, 8 stations,
``fluid.solver.travelling_waves``); ``--set KEY=VALUE`` adds FluidConfig settings.
``--save``: the samples (times, gauges' elevations) to an .npz, read back by ``--load``
without running.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from machine import cpu_name  # benchmarks/machine.py, beside this script
from wave_propagation import setting_value  # benchmarks/wave_propagation.py
from cosim.validations import wave_propagation as wp
from fluid.solver import travelling_waves


def windows(ts, eta, wm, wavelengths: int, window: float, anchor: float) -> list[dict]:
    """Every ``window``-period window of the samples, a period apart and one of them from
    ``anchor`` [s] (the case's window): its start [s], the
    stations' H1 / linear theory's, and the decay per wavelength fitted over the stations
    settled in it (None with fewer than three)."""
    T = wm.T
    # when the case would start reading each station, as if it were the last
    settled_at = np.array([wp._duration(wm.H, T, wm.depth, j, fit_periods=0.0) for j in range(1, wavelengths + 1)])
    out = []
    t0 = anchor - math.floor((anchor - ts[0]) / T + 1e-9) * T
    while t0 + window * T <= ts[-1] + 1e-9:
        sel = (ts >= t0 - 1e-9) & (ts <= t0 + window * T + 1e-9)
        r = wp.flume_figures(ts[sel], eta[sel], wm, wavelengths)
        ok = settled_at <= t0 + 1e-9
        decay = None
        if ok.sum() >= 3:
            j = np.flatnonzero(ok) + 1
            decay = float(-math.expm1(np.polyfit(j, np.log(r["H1_over_H"][ok]), 1)[0]))
        out.append({"t0": float(t0), "H1": r["H1_over_H"], "settled": ok, "decay": decay,
                    "lag": r["phase_lag_periods"], "reflection": r["reflection"]})
        t0 += T
    return out


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rows", type=int, default=20, help="particle rows over the depth")
    ap.add_argument("--wavelengths", type=int, default=wp.WP_WAVELENGTHS)
    ap.add_argument("--height", type=float, default=wp.WP_HEIGHT, help="the wave's height [m]")
    ap.add_argument("--from", dest="t_from", type=float, default=5.0, help="first sample [s]")
    ap.add_argument("--extra", type=float, default=4.0, help="periods run past the case's end")
    ap.add_argument("--window", type=float, default=wp.FIT_PERIODS, help="periods per window")
    ap.add_argument("--set", nargs="*", default=[], metavar="KEY=VALUE", help="FluidConfig settings on top")
    ap.add_argument("--save", help="write the samples to this .npz")
    ap.add_argument("--load", help="read the samples from this .npz instead of running")
    args = ap.parse_args(argv)
    wm, L, _ = wp._wave(args.height, wp.WP_PERIOD, wp.WP_DEPTH)
    print(f"# CPU: {cpu_name()}")
    if args.load:
        d = np.load(args.load)
        ts, eta = d["ts"], d["eta"]
        print(f"# samples from {args.load}: {ts[0]:.2f} ... {ts[-1]:.2f} s")
    else:
        T = wp.WP_PERIOD
        t_end = wp._duration(args.height, T, wp.WP_DEPTH, args.wavelengths) + args.extra * T
        fit = (t_end - args.t_from) / T
        settle = wp.SETTLE_PERIODS + wp.FIT_PERIODS + args.extra - fit  # so that the run ends at t_end
        cfg = travelling_waves(args.rows) | {k: setting_value(v) for k, v in (s.split("=", 1) for s in args.set)}
        r = wp.propagate(wp.WP_DEPTH / args.rows, wp.WP_DEPTH, args.height, T, wavelengths=args.wavelengths,
                         settle_periods=settle, fit_periods=fit, series=True, **cfg)
        ts, eta = r["ts"], r["eta"]
        print(f"# rows {args.rows}, config {cfg}: {r['particles']} particles, {r['steps']} steps, "
              f"{r['cpu_s']:.0f} CPU-s; samples {ts[0]:.2f} ... {ts[-1]:.2f} s")
        if args.save:
            np.savez(args.save, ts=ts, eta=eta, rows=args.rows, height=args.height)
    case_start = wp._duration(args.height, wp.WP_PERIOD, wp.WP_DEPTH, args.wavelengths) - wp.FIT_PERIODS * wm.T
    rows = windows(np.asarray(ts), np.asarray(eta), wm, args.wavelengths, args.window, case_start)
    print(f"\nH1 / linear theory's at 1 ... {args.wavelengths} wavelengths over each {args.window:g}-period window "
          f"(* : not yet settled); the case reads the window from {case_start:.2f} s\n")
    print("| window from [s] | " + " | ".join(f"{j} L" for j in range(1, args.wavelengths + 1))
          + " | decay per L (settled) | lag at the last settled [periods] | reflection |")
    print("|---" * (args.wavelengths + 4) + "|")
    for w in rows:
        cells = " | ".join(f"{h:.3f}" + ("" if ok else "*") for h, ok in zip(w["H1"], w["settled"]))
        last = np.flatnonzero(w["settled"])
        lag = f"{w['lag'][last[-1]]:.3f}" if len(last) else "-"
        decay = "-" if w["decay"] is None else f"{100 * w['decay']:.2f} % ({int(w['settled'].sum())})"
        mark = " (the case's)" if abs(w["t0"] - case_start) < 1e-6 else ""
        print(f"| {w['t0']:.2f}{mark} | {cells} | {decay} | {lag} | {100 * w['reflection']:.2f} % |")
    full = [w["decay"] for w in rows if w["settled"].all()]
    if full:
        print(f"\ndecay over all {args.wavelengths} stations, windows after the last station settled: "
              f"{', '.join(f'{100 * d:.3f}' for d in full)} % (mean {100 * np.mean(full):.3f}, "
              f"spread {100 * (max(full) - min(full)):.3f})")


if __name__ == "__main__":
    main()
