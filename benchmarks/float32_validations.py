"""float32 pair arithmetic (``FluidConfig(precision="float32")``) against the float64
reference on the validation cases: each case run twice, in its own process on one thread,
once as it is and once with every SPH fluid it builds switched to float32; the judged
metrics side by side, their relative change, the verdicts and the CPU seconds. Cases that
build no SPH fluid are listed as such (float32 does not reach them). Prints figures;
asserts nothing.

    python benchmarks/float32_validations.py [NAMES ...] [--full] [--out FILE.jsonl]

Quick variants by default (``--full``: the full ones). ``--out`` keeps the records. Scenes
that a case runs through a study in child processes (``elastic-table2``) get the scene's
``fluid.precision``.

Every verdict holds in float32 but momentum-exchange's (the pair terms, evaluated once from
each side in float32, are antisymmetric to float32's round-off only); the measured changes
per case: docs/benchmarks/float32_validations.md.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

#: run in the child (validation_child.run_child): the fluid's precision forced where asked
PATCH = r"""
import sys
precision, name, quick = sys.argv[1], sys.argv[2], sys.argv[3] == "1"
from fluid import solver
built = []
post = solver.FluidConfig.__post_init__
def forced(self):
    if precision == "float32" and self.device == "cpu":
        object.__setattr__(self, "precision", "float32")
    built.append(self.precision)
    post(self)
solver.FluidConfig.__post_init__ = forced
from cosim.study import sweep
case = sweep.case
def case_with(index, values, scene, *args):  # scenes a study runs in its own processes (elastic-table2)
    if getattr(scene.fluid, "model", None) == "sph":
        scene = scene.with_values([f"fluid.precision={precision}"])
        built.append(precision)
    return case(index, values, scene, *args)
sweep.case = case_with
"""


def run(name: str, precision: str, quick: bool) -> dict:
    from validation_child import run_child

    return run_child(PATCH, name, [precision, name, "1" if quick else "0"])


def _num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def compare(r64: dict, r32: dict) -> list[str]:
    """One line per judged metric: float64, float32 and their relative change."""
    from cosim.validation import lookup

    out = []
    for key in r64.get("tolerances", {}):
        try:
            a, b = lookup(r64["metrics"], key), lookup(r32["metrics"], key)
        except KeyError:
            continue
        if isinstance(a, list) and isinstance(b, list) and a and all(_num(x) for x in a + b):
            d = max(abs(y - x) / max(abs(x), 1e-300) for x, y in zip(a, b))
            out.append(f"    {key}: max rel. change over {len(a)} values {d:.2g}")
        elif _num(a) and _num(b):
            out.append(f"    {key}: {a:.6g} -> {b:.6g} ({(b - a) / max(abs(a), 1e-300):+.2g})")
        else:
            out.append(f"    {key}: {a} -> {b}")
    return out


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("names", nargs="*", help="validation cases (default: all)")
    ap.add_argument("--full", action="store_true", help="the full variants (default: quick)")
    ap.add_argument("--out", help="append the records here (JSON lines)")
    a = ap.parse_args(argv)
    from cosim import validation

    names = a.names or list(validation.cases())
    for name in names:
        t0 = time.perf_counter()
        r64 = run(name, "float64", not a.full)
        if "error" in r64:
            print(f"{name}: failed ({r64['error']})", flush=True)
            continue
        if not r64["_fluids"]:
            print(f"{name}: no SPH fluid ({r64['_cpu_s']:.1f} CPU-s)", flush=True)
            continue
        r32 = run(name, "float32", not a.full)
        if "error" in r32:
            print(f"{name}: float32 failed ({r32['error']})", flush=True)
            continue
        print(f"{name}: passed {r64['passed']} -> {r32['passed']}; CPU {r64['_cpu_s']:.1f} -> {r32['_cpu_s']:.1f} s "
              f"({time.perf_counter() - t0:.0f} s wall)", flush=True)
        print("\n".join(compare(r64, r32)), flush=True)
        if a.out:
            with open(a.out, "a") as f:
                f.write(json.dumps({"name": name, "quick": not a.full, "float64": r64, "float32": r32}) + "\n")


if __name__ == "__main__":
    main()
