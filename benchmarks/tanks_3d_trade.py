"""Error and cost of seed 001's 3-D tanks at one resolution: the whole vertical-wall tank
(``cosim.validations.sloshing.run_westergaard`` with ``dim=3``) or the inclined tank's
3-D slice (``cosim.validations.tanks.run_inclined`` with ``dim=3``), c0 = 1430 m/s, walls="adami",
1 period skipped and 1 fitted (``--fit``), 40 samples a period (the full variants' settings).

    python benchmarks/tanks_3d_trade.py vertical --dx 0.05 --out /tmp/v005.json
    python benchmarks/tanks_3d_trade.py inclined --dx 0.05 --angle 45 --out /tmp/i45_005.json

Writes the run's metrics, profile, particles, steps and CPU seconds (``time.process_time``,
all threads of this process) as JSON, and prints one line. Run with NUMBA_NUM_THREADS=1
on a shared machine: CPU seconds then compare between runs.
"""

from __future__ import annotations

import argparse
import json
import time

from machine import cpu_name


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tank", choices=("vertical", "inclined"))
    ap.add_argument("--dx", type=float, required=True, help="particle spacing [m]")
    ap.add_argument("--angle", type=float, default=45.0, help="inclined side from the vertical [deg]")
    ap.add_argument("--fit", type=int, default=1, help="periods fitted after the one skipped")
    ap.add_argument("--out", required=True, help="JSON file to write")
    a = ap.parse_args(argv)
    t0 = time.process_time()
    if a.tank == "vertical":
        from cosim.validations.sloshing import run_westergaard

        r = run_westergaard(a.dx, dim=3, width=1.0, periods_skip=1, periods_fit=a.fit, walls="adami")
    else:
        from cosim.validations.tanks import run_inclined

        r = run_inclined(a.angle, a.dx, dim=3, periods_skip=1, periods_fit=a.fit, walls="adami")
    r["cpu_s"] = time.process_time() - t0
    r["cpu"] = cpu_name()
    r["args"] = vars(a)
    with open(a.out, "w") as f:
        json.dump(r, f, indent=1, default=float)
    print(a.tank, a.dx, a.angle, r["particles"], r["steps"], f"{r['cpu_s']:.0f} CPU-s", flush=True)


if __name__ == "__main__":
    main()
