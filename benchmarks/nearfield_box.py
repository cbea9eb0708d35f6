"""Waves through a 2-D near-field box with no body (cosim.validations.nearfield.run_box):
heights and phases across the box against the sea's, the mean level's drift, the cost.

    python benchmarks/nearfield_box.py --dx 0.03 --periods 20 --zone 0.5 --length 1.8
    python benchmarks/nearfield_box.py --dx 0.03 --set mls_every=0

The sea: d = 0.3 m, T = 1.2 s, H = 6 cm (the nearfield-waves case's), or a JONSWAP sea of
Hs = 4 cm (``--sea jonswap``); zone and length in wavelengths; ``--set KEY=VALUE``:
FluidConfig settings on top of the near field's set-up (``fluid.solver.NEAR_FIELD``).
Prints one JSON object; the figures measured are in docs/validation/nearfield.md.
"""

from __future__ import annotations

import argparse
import json
import logging

import numpy as np

from cosim.validations import nearfield as nf


def main(argv=None) -> None:
    from fluid.solver import NEAR_FIELD
    from fluid.waves import RegularWave

    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--sea", choices=("linear", "stokes2", "jonswap"), default="linear")
    p.add_argument("--dx", type=float, default=0.03, help="particle spacing [m]")
    p.add_argument("--periods", type=float, default=20.0, help="run length in (peak) periods")
    p.add_argument("--settle", type=float, default=1.0, help="damped relaxation before the sea [s]")
    p.add_argument("--zone", type=float, default=0.5, help="zone width [wavelengths]")
    p.add_argument("--length", type=float, default=1.8, help="box length [wavelengths]")
    p.add_argument("--rate", type=float, default=2.0, help="relaxation rate at the walls [wave frequencies]")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="a FluidConfig setting")
    a = p.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(message)s")  # the run's progress
    cfg = dict(NEAR_FIELD)
    for kv in a.set:
        k, v = kv.split("=", 1)
        cfg[k] = int(v) if v.lstrip("-").isdigit() else float(v)
    T = nf.NF_PERIOD
    wl = RegularWave(nf.NF_HEIGHT, T, nf.NF_DEPTH, level=nf.NF_DEPTH, g=nf.G).wavelength
    r = nf.run_box(nf._sea(a.sea, a.periods * T), a.dx, a.length * wl, a.zone * wl, a.periods * T,
                   settle=a.settle, rate_per_omega=a.rate, progress=True, **cfg)
    per = int(round(len(r["t"]) / a.periods))
    whole = (len(r["t"]) // per) * per
    out = {"sea": a.sea, "dx_m": a.dx, "zone_wavelengths": a.zone, "length_wavelengths": a.length, "rate": a.rate,
           "settings": cfg, "drift_over_depth": nf.level_drift(r, T, 2 * T) / nf.NF_DEPTH,
           "settled_level_m": r["settled_level_m"],
           "level_per_period_mm": np.round(1e3 * r["box_level_m"][:whole].reshape(-1, per).mean(axis=1), 2).tolist(),
           "particles": r["particles"], "steps": r["steps"], "cpu_s": round(r["cpu_s"], 1), "lost": r["removed"]}
    m = nf.irregular_metrics(r, T, 2 * T) if a.sea == "jonswap" else nf.regular_metrics(r, T)
    out.update({k: np.round(v, 4).tolist() for k, v in m.items() if k not in ("f_Hz", "S_sph", "S_sea")})
    print(json.dumps(out))


if __name__ == "__main__":
    main()
