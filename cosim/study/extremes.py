"""``cosim study SCENE --extremes``: each lever of a scene pushed towards its limits, one at
a time from the scene's own settings, and what happens at each value: the run finishes
(``ok``), the value is refused before any step with a message naming the field
(``refused``), the run stops with a clear error naming the step and the entity
(``unstable``: an InstabilityError, ConvergenceError or TautLineError, or any error of ours
after the first step), or it fails in a way that is a bug of ours (``crash``: any other
error; the table says so). A body denser than the water must sink: a run of such a density
that stops with the body gone down by more than half its height since the start (the
body's ``heave`` probe) ``sank``, as physics says, rather than being ``unstable`` (on the
analytic fluid the box sinks until its fairleads pass below its anchors' seabed, where the
catenary stops the run).

The levers, where the scene has them (values relative to the scene's own):

- ``fluid.dx`` x 4, 2, 1, 1/2 (the particle count);
- ``fluid.c0_factor`` 5, 10, 20, 40 (the speed of sound over the expected speed; < 10 refused);
- ``fluid.cfl`` 0.05, 0.1, 0.2, 0.4, 0.6 (> 0.4 refused);
- ``bodies[i].density`` 0.001, 0.01, 0.1, 0.5, 2 x the water's (light bodies: added mass; a
  body heavier than water cannot float: refused where it is placed floating, else it sinks);
- ``moorings.lines[*].EA`` x 1e-3, 1e-1, 1, 10, 1e3 (every line; line stiffness);
- ``moorings.segments`` 2, 5, 20, 80 (the dynamic lines' resolution);
- ``coupling.dt`` 1e-3, 1e-2, 0.1, 0.5 s (a fixed coupling step; without the SPH fluid,
  whose own step rules).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from cosim.errors import CosimError
from cosim.scene.registry import MOORINGS
from cosim.scene.shapes import RigidBody
from cosim.scene.spec import MJCF, SPH
from cosim.study import sweep

UNSTABLE = ("InstabilityError", "ConvergenceError", "TautLineError")
#: the water densities of the density lever [-]; above 1 a body sinks
DENSITY_RATIOS = (0.001, 0.01, 0.1, 0.5, 2.0)


def levers(scene) -> list[tuple[str, list[tuple[str, list[str]]]]]:
    """``[(lever, [(value label, assignments), ...]), ...]`` for the scene."""
    out = []
    f = scene.fluid
    if isinstance(f, SPH):
        out.append(("fluid.dx", [(f"{k:g} x", [f"fluid.dx={f.dx * k!r}"]) for k in (4, 2, 1, 0.5)]))
        out.append(("fluid.c0_factor", [(f"{v:g}", [f"fluid.c0_factor={v!r}"]) for v in (5.0, 10.0, 20.0, 40.0)]))
        out.append(("fluid.cfl", [(f"{v:g}", [f"fluid.cfl={v!r}"]) for v in (0.05, 0.1, 0.2, 0.4, 0.6)]))
    rho = f.rho0 if isinstance(f, SPH) else getattr(f, "rho", None)
    if rho is not None:
        for i, b in enumerate(scene.bodies):
            if not isinstance(b, MJCF) and b.density is not None:
                out.append((f"bodies[{i}].density", [(f"{r:g} x water", [f"bodies[{i}].density={r * rho!r}"])
                                                     for r in DENSITY_RATIOS]))
    m = scene.moorings
    if m is not None:
        if all(ln.EA is not None for ln in m.lines):
            out.append(("moorings.lines[*].EA", [(f"{k:g} x", [f"moorings.lines[{i}].EA={ln.EA * k!r}"
                                                               for i, ln in enumerate(m.lines)])
                                                 for k in (1e-3, 1e-1, 1.0, 10.0, 1e3)]))
        if MOORINGS[m.model].dynamic:
            out.append(("moorings.segments", [(str(n), [f"moorings.segments={n}"]) for n in (2, 5, 20, 80)]))
    if not isinstance(f, SPH) and scene.bodies:
        out.append(("coupling.dt", [(f"{v:g} s", [f"coupling.dt={v!r}"]) for v in (1e-3, 1e-2, 0.1, 0.5)]))
    return out


def _outcome(rec: dict) -> str:
    err = rec.get("error")
    if not err:
        return "ok"
    kind = err.split(":", 1)[0]
    if kind in UNSTABLE:
        return "unstable"
    if rec.get("returncode") == 2:  # a clear error of ours: before any step, or a stop during the run
        return "refused" if not rec.get("steps") else "unstable"
    return "crash"


def _height(body, dim: int) -> float | None:
    """A rigid builder body's upright height [m] (None for others)."""
    return 2.0 * float(body.half_size(dim)[-1]) if isinstance(body, RigidBody) else None


def _sank(scene, lever: str, folder) -> str | None:
    """Why the run of a density lever's value counts as sunk (module docstring), or None:
    the body (denser than the water) went down by more than half its height."""
    if not lever.startswith("bodies[") or not lever.endswith("].density"):
        return None
    body = scene.bodies[int(lever[len("bodies["):-len("].density")])]
    tall = _height(body, scene.world.dim)
    heave = sweep.series(folder).get(f"{body.name}.heave")
    if tall is None or heave is None or len(heave[1]) < 2:
        return None
    drop = float(heave[1][0] - np.min(heave[1]))
    if drop <= 0.5 * tall:
        return None
    return (f"denser than the water, body '{body.name}' sank {drop:.3g} m (its height: {tall:.3g} m) in "
            f"{float(heave[0][-1]):.3g} s, as physics says")


def run_extremes(scene, out, *, workers=None, threads=1, scheduler=None, serial=False, report=None) -> list[dict]:
    """Run every lever's values; write extremes.csv, .md, .json into ``out``; return the rows."""
    import os

    sweep.check_workers(workers, threads)
    out = Path(out)
    version = sweep.code_version()
    rows, cases = [], []
    for lever, values in levers(scene):
        for label, assignments in values:
            row = {"lever": lever, "value": label, "outcome": None, "message": "", "wall_s": None, "steps": None}
            rows.append(row)
            try:
                s = scene.with_values(assignments)
            except CosimError as e:  # refused by the scene's own checks
                row.update(outcome="refused", message=str(e))
                continue
            cases.append((row, sweep.case(len(cases), {lever: label}, s, out, version), s))
    out.mkdir(parents=True, exist_ok=True)
    workers = workers or max(1, (os.cpu_count() or 1) // max(threads, 1))
    records = sweep.execute([c for _, c, _ in cases], workers=workers, threads=threads, scheduler=scheduler,
                            serial=serial, version=version, report=report)
    for (row, c, s), rec in zip(cases, records):
        row.update(outcome=_outcome(rec), message=rec.get("error") or "", wall_s=rec.get("wall_s"),
                   steps=rec.get("steps"))
        why = _sank(s, row["lever"], c.folder) if row["outcome"] in ("unstable", "ok") else None
        if why is not None:
            row.update(outcome="sank" if row["outcome"] == "unstable" else "ok",
                       message=why + (f"; the run then stopped: {row['message']}" if row["message"] else ""))
    _write(out, rows)
    return rows


def summary(rows) -> list[str]:
    """Per lever: the values that ran, and where and how the others stopped."""
    lines = []
    for lever in dict.fromkeys(r["lever"] for r in rows):
        rs = [r for r in rows if r["lever"] == lever]
        ok = [r["value"] for r in rs if r["outcome"] == "ok"]
        bad = [f"{r['value']}: {'sank, as physics says' if r['outcome'] == 'sank' else r['outcome']}"
               for r in rs if r["outcome"] != "ok"]
        lines.append(f"{lever}: runs at {', '.join(ok) or 'no value'}" + (f"; {'; '.join(bad)}" if bad else ""))
    return lines


def _write(out: Path, rows):
    import csv

    keys = ["lever", "value", "outcome", "wall_s", "steps", "message"]
    with open(out / "extremes.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["lever", "value", "outcome", "wall [s]", "steps", "message"])
        w.writerows([[r[k] for k in keys] for r in rows])
    md = ["# Extremes", "", *[f"- {s}" for s in summary(rows)], "",
          "| lever | value | outcome | wall [s] | steps | message |", "|---|---|---|---|---|---|"]
    for r in rows:
        msg = r["message"].replace("|", "\\|").replace("\n", " ")
        msg = msg if len(msg) <= 240 else msg[:237] + "..."
        wall = f"{r['wall_s']:.3g}" if r["wall_s"] is not None else ""
        md.append(f"| {r['lever']} | {r['value']} | {r['outcome']} | {wall} | {r['steps'] or ''} | {msg} |")
    (out / "extremes.md").write_text("\n".join(md) + "\n")
    (out / "extremes.json").write_text(json.dumps(rows, indent=1))
