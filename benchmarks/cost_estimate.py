"""The cost estimate (cosim.scene.cost) against the measured cost of short runs of the
examples: each case runs as ``cosim run`` in its own process; the table gives, estimated
and measured, the particles, the coupling steps and the run's CPU time (summary.json's
``cpu_s``: the run, without Python's start) and the process's peak memory, and the ratio
estimated / measured. Prints the table; asserts nothing.

    python benchmarks/cost_estimate.py [--only NAME ...] [--fit]

``--fit``: also the factors on each term of the CPU model that would fit the runs best
(least squares of the relative error; 1 where the module's constants fit).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EX = ROOT / "examples"
DYN = [f"moorings.lines[{i}].{k}" for i in (0, 1) for k in ("EA=5e7", "mass_per_length=5.82", "diameter=0.03")]

#: (name, scene file, --set assignments)
CASES = [
    ("sloshing 2-D", EX / "sloshing_tank.toml", ["world.duration=0.5", "world.plot_at=[]"]),
    ("sloshing 2-D fine", EX / "sloshing_tank.toml", ["world.duration=0.2", "fluid.dx=0.0125", "world.plot_at=[]"]),
    ("earthquake 2-D", EX / "earthquake_tank.toml", ["world.duration=0.5", "world.plot_at=[]"]),
    ("moored box waves 2-D", EX / "moored_box_waves.toml", ["world.duration=0.5", "world.plot_at=[]"]),
    ("wind turbine 3-D SPH", EX / "wind_turbine_base.toml", ["fluid.model=sph", "fluid.dx=2.0", "world.duration=0.3",
                                                             "world.sample_every=0.05"]),
    ("sloshing 2-D, 1 thread", EX / "sloshing_tank.toml", ["world.duration=0.5", "world.plot_at=[]", "fluid.threads=1"]),
    ("sloshing 3-D, 1 thread", EX / "sloshing_tank.toml", ["world.dim=3", "domain.width=0.2",
                                                           "base_motion.direction=[1.0,0.0,0.0]", "probes.gauges=[]",
                                                           "probes.pressure=[]", "world.plot_at=[]", "fluid.dx=0.025",
                                                           "world.duration=0.1", "fluid.threads=1"]),
    ("wind turbine 3-D SPH, 1 thread", EX / "wind_turbine_base.toml", ["fluid.model=sph", "fluid.dx=2.0",
                                                                       "world.duration=0.3", "world.sample_every=0.05",
                                                                       "fluid.threads=1"]),
    ("wind turbine near field 3-D, 1 thread", ROOT / "cosim/validations/scenes/wind-turbine-sph.toml",
     ["fluid.dx=1.25", "world.duration=0.5", "fluid.threads=1"]),
    ("moored box (analytic)", EX / "moored_box.toml", []),
    ("wind turbine (analytic)", EX / "wind_turbine_base.toml", ["world.duration=20.0"]),
    ("moored box, MoorDyn", EX / "moored_box.toml", ["world.duration=5.0", "moorings.model=moordyn"]),
    ("moored box, SPH cable", EX / "moored_box.toml", ["world.duration=5.0", "moorings.model=sph-cable"]),
]


def run_case(path: Path, sets: list[str], out: Path) -> dict:
    """Run the scene as ``cosim run`` in a child process; its summary and peak memory."""
    cmd = [sys.executable, "-m", "cosim.cli", "run", str(path), "--out", str(out), "--quiet", "--yes"]
    for a in sets:
        cmd += ["--set", a]
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env, text=True)
    _, status, usage = os.wait4(proc.pid, 0)
    err = proc.stderr.read()
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError(f"{path.name} {sets}: {err[-2000:]}")
    s = json.loads((out / "summary.json").read_text())
    s["max_rss_bytes"] = usage.ru_maxrss * 1024.0
    s["process_wall_s"] = time.perf_counter() - t0
    return s


def main(argv=None) -> int:
    from cosim.scene.cost import estimate, human_bytes
    from cosim.scene.load import load

    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--only", nargs="*", help="case names (a part of the name is enough)")
    p.add_argument("--fit", action="store_true", help="fit the CPU model's constants to the runs")
    args = p.parse_args(argv)
    cases = [c for c in CASES if not args.only or any(o in c[0] for o in args.only)]
    rows = []
    print("| case | particles est. / built | steps est. / run | CPU est. [s] | CPU run [s] | ratio | memory est. "
          "| peak RSS |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="cost-estimate-") as tmp:
        for k, (name, path, sets) in enumerate(cases):
            scene = load(path).with_values(sets)
            est = estimate(scene)
            s = run_case(path, sets, Path(tmp) / str(k))
            rows.append((name, scene, est, s))
            parts = f"{est.particles} / {s.get('particles', 0)}"
            print(f"| {name} | {parts} | {est.steps:.4g} / {s['steps']} | {est.cpu_s:.3g} | {s['cpu_s']:.3g} | "
                  f"{est.cpu_s / s['cpu_s']:.2f} | {human_bytes(est.memory_bytes)} | "
                  f"{human_bytes(s['max_rss_bytes'])} |", flush=True)
    ratios = [est.cpu_s / s["cpu_s"] for _, _, est, s in rows]
    if ratios:
        import math

        gm = math.exp(sum(math.log(r) for r in ratios) / len(ratios))
        print(f"\nCPU estimate / measured: geometric mean {gm:.2f}, range {min(ratios):.2f} .. {max(ratios):.2f}")
    if args.fit:
        _fit(rows)
    return 0


def _fit(rows) -> None:
    """Least squares (relative) of the measured CPU on the model's terms, each at unit
    constant: the SPH term per dimension, the coupling and bodies terms, the lines'."""
    import numpy as np

    names = ["fluid 2-D", "fluid 3-D", "coupling", "bodies", "lines"]
    A, b = [], []
    for _, scene, est, s in rows:
        t = {x.name: x.cpu_s for x in est.terms}
        row = [t.get("fluid", 0.0) if scene.world.dim == 2 else 0.0, t.get("fluid", 0.0) if scene.world.dim == 3
               else 0.0, t.get("coupling", 0.0), t.get("bodies", 0.0), t.get("lines", 0.0)]
        A.append(row)
        b.append(s["cpu_s"])
    A, b = np.array(A), np.array(b)
    used = A.any(axis=0)
    k, *_ = np.linalg.lstsq(A[:, used] / b[:, None], np.ones(len(b)), rcond=None)
    print("factors that would fit the runs best (1: the module's constants):",
          ", ".join(f"{n} x {v:.2f}" for n, v in zip(np.array(names)[used], k)))


if __name__ == "__main__":
    sys.exit(main())
