"""A validation case run in a child process with the fluid patched (``-c`` code that sets
``name``, ``quick`` and a list ``built`` of what the patch touched), its record read back:
shared by the benchmarks that compare one fluid setting across the validation cases
(float32_validations.py, verlet_diffusion_margin.py). One thread per child."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: appended to the patch code: runs the case and prints its record, with the CPU seconds of
#: the child and its own children (a study's runs) and what the patch built, as one JSON line
RUN_AND_REPORT = r"""
import json, resource
from cosim import validation
r = validation.run(name, quick=quick)
r.pop("series", None)
u, c = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
r["_cpu_s"] = u.ru_utime + u.ru_stime + c.ru_utime + c.ru_stime
r["_fluids"] = sorted(set(built))
print("RECORD " + json.dumps(r, default=float))
"""


def run_child(patch: str, name: str, args: list[str]) -> dict:
    """The record of case ``name`` run by ``patch`` + :data:`RUN_AND_REPORT` with ``args``
    (``sys.argv[1:]`` there), or ``{"name", "error"}`` with the child's last error line."""
    env = dict(os.environ, NUMBA_NUM_THREADS="1", PYTHONPATH=str(ROOT))
    p = subprocess.run([sys.executable, "-c", patch + RUN_AND_REPORT, *args], env=env, capture_output=True,
                       text=True)
    for line in p.stdout.splitlines():
        if line.startswith("RECORD "):
            return json.loads(line[7:])
    return {"name": name, "error": (p.stderr.strip().splitlines() or ["no output"])[-1][:200]}
