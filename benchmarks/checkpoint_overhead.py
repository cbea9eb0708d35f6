"""What checkpoints cost a run: ``cosim run`` of the README's main example
(``examples/moored_box_waves.toml``) with checkpoints off (``world.checkpoint_wall=0``),
by default (every 120 s of wall time and at the end) and often (every 1 s, stretched to
50 x the time one write takes), the settings alternated round by round so that a machine
whose load drifts weighs on each alike. Not a test; prints a table and one JSON object.

    python benchmarks/checkpoint_overhead.py [--duration 5.0] [--rounds 3] [--walls 0,120,1]

Per run: the loop's wall time (summary.json ``wall_s``), the checkpoints written and the
wall time spent writing them (``checkpoints.write_s``), the size of checkpoint.h5. The
overhead of a setting is its median wall time over the rounds against that of ``0``.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def one(duration: float, wall: float, out: Path) -> dict:
    cmd = [sys.executable, "-m", "cosim.cli", "run", str(ROOT / "examples" / "moored_box_waves.toml"), "--out",
           str(out), "--quiet", "--set", f"world.duration={duration}", "--set", f"world.checkpoint_wall={wall}"]
    if duration < 5.0:
        cmd += ["--set", "world.plot_at=[]"]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT)
    if r.returncode:
        raise SystemExit(r.stderr[-2000:])
    s = json.loads((out / "summary.json").read_text())
    ck = out / "checkpoint.h5"
    return {"checkpoint_wall_s": wall, "wall_s": s["wall_s"], "steps": s["steps"], **s["checkpoints"],
            "checkpoint_bytes": ck.stat().st_size if ck.exists() else 0}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--duration", type=float, default=5.0, help="world.duration [s] (the example's: 5)")
    ap.add_argument("--rounds", type=int, default=3, help="runs of each setting")
    ap.add_argument("--walls", default="0,120,1", help="world.checkpoint_wall values [s], the first the reference")
    a = ap.parse_args()
    walls = [float(x) for x in a.walls.split(",")]
    runs = []
    with tempfile.TemporaryDirectory(prefix="checkpoint-overhead-") as tmp:
        for k in range(a.rounds):
            for w in walls:
                runs.append(one(a.duration, w, Path(tmp) / f"r{k}_{w:g}") | {"round": k})
                print(json.dumps(runs[-1]), file=sys.stderr, flush=True)
    ref = statistics.median(r["wall_s"] for r in runs if r["checkpoint_wall_s"] == walls[0])
    table = []
    for w in walls:
        mine = [r for r in runs if r["checkpoint_wall_s"] == w]
        med = statistics.median(r["wall_s"] for r in mine)
        table.append({"checkpoint_wall_s": w, "median_wall_s": med, "overhead": med / ref - 1,
                      "written": statistics.median(r["written"] for r in mine),
                      "write_s": statistics.median(r["write_s"] for r in mine),
                      "checkpoint_bytes": mine[-1]["checkpoint_bytes"]})
        print(f"checkpoint_wall {w:6g} s: wall {med:8.2f} s ({100 * (med / ref - 1):+6.2f} %), "
              f"{table[-1]['written']:g} checkpoints, {table[-1]['write_s']:.3f} s writing, "
              f"{table[-1]['checkpoint_bytes'] / 1e6:.2f} MB")
    print(json.dumps({"duration_s": a.duration, "rounds": a.rounds, "load": os.getloadavg(), "table": table,
                      "runs": runs}))


if __name__ == "__main__":
    main()
