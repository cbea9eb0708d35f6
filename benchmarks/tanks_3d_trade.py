"""Error and cost of Sunara et al. 2021's 3-D tanks at one resolution: the whole vertical-wall tank
(``cosim.validations.sloshing.run_westergaard`` with ``dim=3``), the inclined tank's
3-D slice (``cosim.validations.tanks.run_inclined`` with ``dim=3``) or the cylinder
(``cosim.validations.tanks.run_cylinder``), c0 = 1430 m/s, walls="adami", ``--skip``
periods skipped (1) and ``--fit`` fitted (1), 40 samples a period (the full variants'
settings; the cylinder's full variant skips 2 and fits 3).

    python benchmarks/tanks_3d_trade.py vertical --dx 0.05 --out /tmp/v005.json
    python benchmarks/tanks_3d_trade.py inclined --dx 0.05 --angle 45 --out /tmp/i45_005.json
    python benchmarks/tanks_3d_trade.py cylinder --dx 0.05 --skip 2 --fit 3 --out /tmp/c005.json

Writes the run's metrics, profile, particles, steps and CPU seconds (``time.process_time``,
all threads of this process) as JSON, and prints one line. Run with NUMBA_NUM_THREADS=1
on a shared machine: CPU seconds then compare between runs.

    python benchmarks/tanks_3d_trade.py plot DIR RUN.json [RUN.json ...]

draws the runs' profiles beside the references as the validation report does (the
cases' ``series``: Sunara et al. 2021, Fig. 5 for the vertical tank, Fig. 12 for the inclined one, the
inclined runs of one dx on one plot, Fig. 17 for the cylinder) into
DIR/tanks3d_<tank>_dx<dx>.png.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from machine import cpu_name


def plot(folder: str, files: list[str]) -> list[Path]:
    """The PNGs of the runs in ``files`` (JSON written by :func:`main`) into ``folder``."""
    from cosim.report import plot_series
    from cosim.validations.sloshing import westergaard_3d_series_plot
    from cosim.validations.tanks import cylinder_series_plot, inclined_3d_series_plot

    runs = [json.loads(Path(f).read_text()) for f in files]
    groups: dict[tuple, list] = {}
    for r in runs:
        groups.setdefault((r["args"]["tank"], r["args"]["dx"]), []).append(r)
    out = []
    Path(folder).mkdir(parents=True, exist_ok=True)
    for (tank, dx), rs in sorted(groups.items()):
        if tank == "vertical":
            series = westergaard_3d_series_plot(rs[-1]["profile"])
        elif tank == "cylinder":
            series = cylinder_series_plot(rs[-1]["profile"])
        else:
            series = inclined_3d_series_plot({r["args"]["angle"]: r["profile"] for r in rs})
        for _, name in plot_series(series, Path(folder), f"tanks3d_{tank}_dx{dx:g}"):
            out.append(Path(folder) / name)
    return out


def main(argv=None) -> None:
    import sys

    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] == "plot":
        for p in plot(argv[1], argv[2:]):
            print(p)
        return
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tank", choices=("vertical", "inclined", "cylinder"))
    ap.add_argument("--dx", type=float, required=True, help="particle spacing [m]")
    ap.add_argument("--angle", type=float, default=45.0, help="inclined side from the vertical [deg]")
    ap.add_argument("--skip", type=int, default=1, help="periods skipped before the fit")
    ap.add_argument("--fit", type=int, default=1, help="periods fitted after those skipped")
    ap.add_argument("--out", required=True, help="JSON file to write")
    a = ap.parse_args(argv)
    t0 = time.process_time()
    if a.tank == "vertical":
        from cosim.validations.sloshing import run_westergaard

        r = run_westergaard(a.dx, dim=3, width=1.0, periods_skip=a.skip, periods_fit=a.fit, walls="adami")
    elif a.tank == "inclined":
        from cosim.validations.tanks import run_inclined

        r = run_inclined(a.angle, a.dx, dim=3, periods_skip=a.skip, periods_fit=a.fit, walls="adami")
    else:
        from cosim.validations.tanks import run_cylinder

        r = run_cylinder(a.dx, periods_skip=a.skip, periods_fit=a.fit, walls="adami")
    r["cpu_s"] = time.process_time() - t0
    r["cpu"] = cpu_name()
    r["args"] = vars(a)
    with open(a.out, "w") as f:
        json.dump(r, f, indent=1, default=float)
    print(a.tank, a.dx, a.angle, r["particles"], r["steps"], f"{r['cpu_s']:.0f} CPU-s", flush=True)


if __name__ == "__main__":
    main()
