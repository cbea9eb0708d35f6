"""Error and cost of the ``long-period`` validation's tanks (Sunara et al. 2021, §3.1-3.3 at
T_p = 1.0 s and 0.7 s) at several resolutions: :func:`cosim.validations.long_period.run_long_period`
with the case's settings, exactly as its full variant calls it (``shape, dx=, dim=, a0=``),
one run per dx, in turn.

    NUMBA_NUM_THREADS=1 python benchmarks/long_period_trade.py rectangular --dim 3 --dx 0.1 1/13 1/15 --out DIR
    NUMBA_NUM_THREADS=1 python benchmarks/long_period_trade.py cylinder --dx 0.1 0.075 0.06 --out DIR
    python benchmarks/long_period_trade.py table DIR/*.json

``--dx`` takes decimals or fractions (1/13 m: 13 rows over the rectangle's 1.0 m of
water; the case refuses a dx that does not divide the depth). ``--a0`` is in g (0.05, the
judged linear regime, by default; 0.5 the paper's). Each run writes
DIR/long_period_<shape>_<dim>d_dx<dx>_<a0>g.json (the run's metrics, record, particles,
steps, CPU seconds: ``time.process_time``, all threads of this process, numba's compile
included unless its cache is warm) and prints one line; ``table`` prints the runs as the
rows of the case's docstring table: particles, forced (the gauges' RMS while shaken / the
linear peak), w1 (the free first mode against linear theory), p (the wall pressure's RMS
/ rho g h), whole (the gauges over the whole record), the largest run-up at a wall while
shaken [m] (linear theory's beside it), CPU seconds. Run with NUMBA_NUM_THREADS=1 on a
shared machine: CPU seconds then compare between runs.
"""

from __future__ import annotations

import argparse
import json
import time
from fractions import Fraction
from pathlib import Path

from machine import cpu_name


def _length(text: str) -> float:
    """A length [m] given as a decimal or a fraction ("1/13")."""
    return float(Fraction(text))


def _row(r: dict) -> str:
    m, a = r["metrics"], r["args"]
    return (f"{a['shape']:<12} {a['dim']}-D  a0 {a['a0_g']:g} g  dx {a['dx']:.4f}  {r['particles']:>6}  "
            f"forced {m['gauge_rms_rel_forced']:.3f}  w1 {100 * m['omega1_free_rel_err']:+.2f} %  "
            f"p {m['wall_pressure_rms_rel']:.3f}  whole {m['gauge_rms_rel']:.2f}  "
            f"run-up {m['runup_peak_forced_m']:.3f} (lin. {m['runup_peak_forced_linear_m']:.3f}) m  "
            f"lost {m['particles_lost']}  steps {r['steps']}  {r['cpu_s']:.0f} CPU-s")


def main(argv=None) -> None:
    import sys

    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] == "table":
        runs = [json.loads(Path(f).read_text()) for f in argv[1:]]
        for r in sorted(runs, key=lambda r: (r["args"]["shape"], r["args"]["dim"], r["args"]["a0_g"], -r["args"]["dx"])):
            print(_row(r))
        return
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("shape", choices=("rectangular", "inclined", "cylinder"))
    ap.add_argument("--dim", type=int, default=3, choices=(2, 3))
    ap.add_argument("--dx", type=_length, nargs="+", required=True, help="particle spacings [m], run in turn")
    ap.add_argument("--a0", type=float, default=0.05, help="peak base acceleration [g]")
    ap.add_argument("--out", required=True, help="folder for the JSON files")
    a = ap.parse_args(argv)
    from cosim.validations.long_period import G, run_long_period

    Path(a.out).mkdir(parents=True, exist_ok=True)
    for dx in a.dx:
        t0 = time.process_time()
        r = run_long_period(a.shape, dx=dx, dim=a.dim, a0=a.a0 * G)
        r["cpu_s"] = time.process_time() - t0
        r["cpu"] = cpu_name()
        r["args"] = {"shape": a.shape, "dim": a.dim, "dx": dx, "a0_g": a.a0}
        path = Path(a.out) / f"long_period_{a.shape}_{a.dim}d_dx{dx:.4f}_{a.a0:g}g.json"
        path.write_text(json.dumps(r, indent=1, default=float))
        print(_row(r), flush=True)


if __name__ == "__main__":
    main()
