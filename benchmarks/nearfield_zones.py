"""How narrow may a near field's zones be? The moored box of ``nearfield-floating-box`` (its
full variant: dx = 0.01 m, 10 s, amplitudes over 5-10 s) in near fields whose zones and end
walls are given (``domain.zone``, ``domain.absorbing_walls``), against the flume: the
committed record's flume run (docs/validation/records.jsonl), or with ``--flume`` the flume
run here too, so that the cost ratio is measured in one session. Prints one JSON line per
variant: the surge and heave first-harmonic amplitudes per incident height against the
flume's (the case's departure criterion), the pitch's ratio, particles, steps, CPU seconds
and the CPU over the flume's. Table: docs/validation/nearfield.md, "Narrower zones need
absorbing end walls".

    python benchmarks/nearfield_zones.py "" "domain.zone=0.1716,domain.absorbing_walls=true"
        [--flume] [--gauge 0.9]

Each variant is a comma-separated list of scene assignments on the case's own near field
(its quarter-wavelength zones and absorbing end walls; "" for it as it is). ``--gauge``
[m]: the upstream gauge's x (the case's reads 0.8 m, which boxes with zones wider than a
quarter wavelength leave inside; narrower ones need one nearer the body).
"""

from __future__ import annotations

import argparse
import json
import math
import tempfile
from pathlib import Path

from cosim.validations import nearfield as nf
from cosim.validations.folders import HISTORY_DIR


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("variants", nargs="+", help='comma-separated scene assignments per variant ("" for none)')
    ap.add_argument("--flume", action="store_true", help="run the flume here (else the committed record's)")
    ap.add_argument("--gauge", type=float, default=None, help="the upstream gauge's x [m] in the near fields")
    a = ap.parse_args()

    flume = nf.floating_flume(False)
    near = flume.with_values(list(nf.FLOATING_NEAR_FIELD))
    _, duration, t0 = nf.FLOATING_RUNS[False]
    period = flume.waves.period
    with tempfile.TemporaryDirectory(prefix="nearfield_zones_") as tmp:
        if a.flume:
            ref = nf.floating_figures(flume.run(Path(tmp) / "flume", progress=False), t0, period,
                                      nf.upstream_gauge(flume))
            empty = nf._without_bodies(flume, flume.bodies[0].pos[0]).run(Path(tmp) / "empty", progress=False)
            late = empty.t >= t0
            incident = 2.0 * nf.first_harmonic(empty.t[late], empty[nf._gauge(empty)][late], 2.0 * math.pi / period)
        else:
            rec = next(r for r in map(json.loads, (HISTORY_DIR / "records.jsonl").read_text().splitlines())
                       if r["name"] == "nearfield-floating-box" and not r["quick"])
            ref, incident = rec["metrics"]["runs"]["flume"], rec["metrics"]["incident_H1_at_body_m"]["flume"]
        print(json.dumps({"flume": {k: ref[k] for k in ("surge_amp", "heave_amp", "pitch_amp", "cpu_s")},
                          "incident_H1_m": incident, "measured_here": a.flume}), flush=True)
        for i, spec in enumerate(a.variants):
            values = [v for v in spec.split(",") if v] + ([f"probes.gauges=[{a.gauge}]"] if a.gauge is not None else [])
            f = nf.floating_figures(near.with_values(values).run(Path(tmp) / f"near{i}", progress=False), t0, period)

            def per_wave(q):
                return (f[q] / near.waves.height) / (ref[q] / incident)

            print(json.dumps({"values": values, "surge_per_wave_error": round(per_wave("surge_amp") - 1.0, 4),
                              "heave_per_wave_error": round(per_wave("heave_amp") - 1.0, 4),
                              "pitch_per_wave_ratio": round(per_wave("pitch_amp"), 3), "particles": f["particles"],
                              "steps": f["steps"], "cpu_s": f["cpu_s"],
                              "cpu_fraction": round(f["cpu_s"] / ref["cpu_s"], 3)}), flush=True)


if __name__ == "__main__":
    main()
