"""``cosim study``: the speed/accuracy trade of any scene, measured.

    cosim study SCENE --vary fluid.dx=0.02,0.01,0.005 --vary moorings.model=catenary,sph-cable \\
                      --metric box.heave:amplitude [--reference finest|richardson|FILE] [--tol 5%]

runs every combination of the varied fields (:mod:`cosim.study.sweep`: each in its own
process, cached, on Dask or serially), reduces probe series to metrics
(:mod:`cosim.study.metrics`), measures each run's error against the reference and its cost,
and writes into one folder: ``study.csv`` and ``study.md`` (one row per run), ``study.json``
(the rows, the reference, the recommendation), ``pareto.png`` (error against cost, the
Pareto front marked) and the runs themselves under ``runs/``.

Each row holds the values as varied and what the run used: its mean coupling step and
range (``dt used``, ``summary.json``'s ``coupling``), the fluid's speed of sound and set-up
where the SPH fluid chose them. The reference: ``finest`` (default) the run with the
smallest value of the refined field (``fluid.dx`` if it is varied, else ``coupling.dt``,
taken as the step the run used, else the first varied number; the most expensive run if
none is); ``richardson`` each metric extrapolated to h -> 0 (h the refined
field) from the three smallest h of the runs that share the other values, m(h) = m* + C h^p,
with the observed order p reported (``rms`` metrics, which compare whole series, take the
finest run's series); or a file: JSON ``{"SERIES:STAT": value}`` or a CSV table whose first
column is the time [s] and whose other columns are reference series by name (their
statistics are the reference values; ``rms`` compares with them). The error of a metric is
|m - m_ref| / |m_ref| (``rms`` is a relative error by itself). The recommendation is the
cheapest run whose every metric is within ``tol``, or the statement that none is. Cost is
the run's CPU time (core-seconds: it does not depend on what else the machine ran beside
it, as the wall time of runs sharing cores in a sweep does; the table has both).
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from cosim.errors import InputError
from cosim.study import metrics as M
from cosim.study import sweep


@dataclass
class StudyResult:
    rows: list
    reference: dict
    recommendation: dict
    out: Path
    wall_s: float = 0.0
    orders: dict = field(default_factory=dict)


def _richardson(dx: list, m: list) -> tuple[float, float]:
    """(m*, p) of m(dx) = m* + C dx^p through three points, dx ascending."""
    (d1, d2, d3), (m1, m2, m3) = dx, m
    if m1 == m2 == m3:  # converged to the last digit: nothing to extrapolate, no order
        return m1, float("nan")
    if m2 == m1 or m3 == m2 or (m2 - m1) * (m3 - m2) < 0:
        raise InputError("the three finest runs do not converge monotonically; Richardson extrapolation needs "
                         "m(dx) monotonic (refine, or use --reference finest)")
    target = (m2 - m1) / (m3 - m2)
    f = lambda p: (d2**p - d1**p) / (d3**p - d2**p) - target
    lo, hi = 0.05, 12.0
    if f(lo) * f(hi) > 0:
        raise InputError(f"no convergence order in [{lo}, {hi}] fits the three finest runs")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(lo) * f(mid) > 0 else (lo, mid)
    p = 0.5 * (lo + hi)
    C = (m2 - m1) / (d2**p - d1**p)
    return m1 - C * d1**p, p


def _reference_file(path: Path, specs):
    if path.suffix == ".json":
        data = json.loads(path.read_text())
        return {"kind": "file", "values": {s: float(data[s]) for s in specs if s in data}, "series": {}}
    rows = np.genfromtxt(path, delimiter=",", names=True)
    names = rows.dtype.names
    t = rows[names[0]]
    ser = {n: (t, rows[n]) for n in names[1:]}
    vals = {}
    for s in specs:
        name, stat = M.parse(s)
        key = name.replace(".", "_") if name not in ser and name.replace(".", "_") in ser else name
        if key in ser and stat != "rms":
            vals[s] = M.value(stat, *ser[key])
        if key in ser:
            ser.setdefault(name, ser[key])
    return {"kind": "file", "values": vals, "series": ser}


def run_study(scene, vary: dict, specs: list[str], out, *, reference: str = "finest", tol: float | None = None,
              workers: int | None = None, threads: int = 1, scheduler: str | None = None, serial: bool = False,
              report=None, yes: bool = False, ask=None, sets=()) -> StudyResult:
    """Run the study; see the module docstring. ``vary``: ``{key path: [values]}``;
    ``specs``: ``["SERIES:STAT", ...]``; ``tol``: a relative error (0.05 for 5 %);
    ``sets``: ``KEY.PATH=VALUE`` for every run whose part has the field
    (:func:`cosim.study.sweep.cases`: ``fluid.dx`` for the SPH runs of a study that varies
    ``fluid.model``). Before
    the first run every run's cost is estimated (:mod:`cosim.scene.cost`): one beyond the
    machine's memory is refused, and runs whose CPU time passes a day together need ``yes``
    (or ``ask(question)`` to answer True)."""
    import time

    sweep.check_workers(workers, threads)
    if not vary:
        raise InputError("a study varies at least one field: --vary KEY.PATH=V1,V2,...")
    for k, vals in vary.items():
        twice = [v for i, v in enumerate(vals) if v in vals[:i]]
        if twice:
            raise InputError(f"--vary {k}: the value {twice[0]!r} is given twice; give each value once")
    if not specs:
        raise InputError("a study measures at least one metric: --metric SERIES:STAT")
    parsed = [M.parse(s) for s in specs]
    if tol is not None and not (math.isfinite(tol) and tol > 0):
        raise InputError(f"--tol {tol!r}: give a relative tolerance > 0, e.g. 5% or 0.05")
    if reference not in ("finest", "richardson") and not Path(reference).is_file():
        raise InputError(f"--reference {reference!r}: give finest, richardson or an existing file")
    refine = refined_field(vary)
    if reference == "richardson" and (refine is None or len(vary[refine]) < 3):
        raise InputError("--reference richardson needs at least three values of a refined field (--vary "
                         "fluid.dx=... or coupling.dt=...)")
    out = Path(out)
    version = sweep.code_version()
    cs = sweep.cases(scene, vary, out, version, sets)  # every combination checked before any run
    _check_metrics(cs, specs, parsed)
    if reference not in ("finest", "richardson"):
        _check_reference_file(Path(reference), specs, parsed)
    check_costs(cs, out, yes=yes, ask=ask)
    workers = workers or max(1, (os.cpu_count() or 1) // max(threads, 1))
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    records = sweep.execute(cs, workers=workers, threads=threads, scheduler=scheduler, serial=serial,
                            version=version, report=report)
    wall = time.perf_counter() - t0
    rows = []
    for c, rec in zip(cs, records):
        row = {"case": c.key, "values": c.values, **{k: rec.get(k) for k in (
            "wall_s", "cpu_s", "wall_s_per_simulated_s", "max_rss_mb", "particles", "steps", "error", "cached")},
               "used": {k: rec.get(k) for k in USED}, "notes": list(c.notes)}
        row["series"] = sweep.series(c.folder) if not rec.get("error") else {}
        row["metrics"] = {}
        for s, (name, stat) in zip(specs, parsed):
            if row["series"] and name not in row["series"]:
                raise InputError(f"--metric {s!r}: the runs have no series {name!r}; they have "
                                 f"{', '.join(sorted(row['series']))}")
            if row["series"] and stat != "rms":
                row["metrics"][s] = M.value(stat, *row["series"][name])
        rows.append(row)
    ok = [r for r in rows if not r["error"]]
    if not ok:
        raise InputError("every run of the study failed: " + "; ".join(f"{r['values']}: {r['error']}" for r in rows))
    ref, orders = _reference(reference, ok, specs, parsed, vary, refine)
    for r in rows:
        r["errors"] = {}
        if r["error"]:
            continue
        for s, (name, stat) in zip(specs, parsed):
            if stat == "rms":
                rs = ref["series"].get(name) if ref["kind"] == "file" else ref["series_of"](r)[name]
                r["metrics"][s] = r["errors"][s] = M.value("rms", *r["series"][name], ref=rs)
            else:
                m_ref = ref["value_of"](r, s)
                r["errors"][s] = abs(r["metrics"][s] - m_ref) / abs(m_ref) if m_ref != 0 else abs(r["metrics"][s])
    rec = _recommend(rows, tol)
    res = StudyResult(rows, {k: v for k, v in ref.items() if not callable(v) and k != "series"}, rec, out, wall,
                      orders)
    _write(res, specs, vary, tol)
    return res


#: what each run used, from its summary.json (sweep.run_case): the mean, smallest and largest
#: coupling step [s], the SPH fluid's speed of sound [m/s] and set-up
USED = ("dt_used_s", "dt_min_s", "dt_max_s", "c0_m_s", "setup")


def _check_metrics(cs, specs, parsed) -> None:
    """Every ``--metric`` names a series that each run records (known from its scene,
    :func:`cosim.scene.probes.series_names`), before the first run."""
    from cosim.scene.probes import series_names

    for c in cs:
        names = series_names(c.scene)
        for s, (name, _) in zip(specs, parsed):
            if name not in names:
                where = f" with {c.values}" if len(cs) > 1 else ""
                raise InputError(f"--metric {s!r}: the runs{where} record no series {name!r}; they record "
                                 f"{', '.join(names) or 'none'}")


def _check_reference_file(path: Path, specs, parsed) -> None:
    """A reference file holds a value (or, for ``rms``, a series) for every metric, before the first run."""
    try:
        ref = _reference_file(path, specs)
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise InputError(f"--reference {path}: cannot be read as a reference ({type(e).__name__}: {e}); give JSON "
                         f"{{\"SERIES:STAT\": value}} or a CSV table, the time [s] first") from None
    missing = [s for s, (name, stat) in zip(specs, parsed)
               if (stat == "rms" and name not in ref["series"]) or (stat != "rms" and s not in ref["values"])]
    if missing:
        raise InputError(f"--reference {path}: no reference value for {', '.join(missing)}")


def check_costs(cs, out, *, yes: bool = False, ask=None) -> None:
    """Each run's estimated cost (:func:`cosim.scene.cost.check`: its memory and disk) and
    all of them together (their CPU time against a day), before the first run; the runs
    themselves are then started with ``--yes``."""
    from cosim.scene import cost
    from cosim.scene.fields import SceneError

    ests = []
    for c in cs:
        est = cost.estimate(c.scene)
        try:
            cost.check(est, out, yes=True)
        except SceneError as e:
            raise InputError(f"the run with {c.values}: {e}") from None
        ests.append((est, c))
    total = sum(e.cpu_s for e, _ in ests)
    if total > cost.CONFIRM_CPU_S and not yes:
        worst, c = max(ests, key=lambda x: x[0].cpu_s)
        question = (f"the study's {len(cs)} runs would take about {cost.human_time(total)} of CPU (the costliest, "
                    f"{c.values}, {cost.human_time(worst.cpu_s)}, driven by {worst.driver.field})")
        if ask is not None and ask(question + ". Run them? [y/N] "):
            return
        raise InputError(f"{question}, more than {cost.human_time(cost.CONFIRM_CPU_S)}; vary over cheaper values, "
                         f"or confirm that they should run: cosim study --yes")


def refined_field(vary: dict) -> str | None:
    """The varied field that refines the runs: fluid.dx, else coupling.dt, else the first
    varied field whose values are all numbers."""
    for k in ("fluid.dx", "coupling.dt"):
        if k in vary:
            return k
    for k, vals in vary.items():
        if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in vals):
            return k
    return None


def _reference(reference, ok, specs, parsed, vary, refine):
    def dx(r):
        if refine == "coupling.dt" and r["used"].get("dt_used_s"):
            return r["used"]["dt_used_s"]  # the step the run took
        return r["values"].get(refine, math.inf) if refine else math.inf

    finest = min(ok, key=lambda r: (dx(r), -(r["wall_s"] or 0)))
    if reference == "finest":
        return {"kind": "finest", "case": finest["case"], "values": finest["values"],
                "value_of": lambda r, s: finest["metrics"][s], "series_of": lambda r: finest["series"]}, {}
    if reference == "richardson":
        others = [k for k in vary if k != refine]
        refs, orders = {}, {}
        for r in ok:
            g = tuple(r["values"][k] for k in others)
            if g in refs:
                continue
            group = sorted([q for q in ok if tuple(q["values"][k] for k in others) == g], key=dx)[:3]
            if len(group) < 3:
                raise InputError(f"richardson: fewer than three successful runs at {dict(zip(others, g))}")
            refs[g] = {"series": group[0]["series"]}
            for s, (_, stat) in zip(specs, parsed):
                if stat != "rms":
                    m_star, p = _richardson([dx(q) for q in group], [q["metrics"][s] for q in group])
                    refs[g][s] = m_star
                    orders[f"{s} at {dict(zip(others, g))}"] = {"extrapolated": m_star, "order": p}
        key = lambda r: tuple(r["values"][k] for k in others)
        return {"kind": "richardson", "value_of": lambda r, s: refs[key(r)][s],
                "series_of": lambda r: refs[key(r)]["series"]}, orders
    ref = _reference_file(Path(reference), specs)  # its values checked before the runs
    ref["value_of"] = lambda r, s: ref["values"][s]
    ref["file"] = str(reference)
    return ref, {}


def _recommend(rows, tol):
    ok = [r for r in rows if not r["error"]]
    worst = lambda r: max(r["errors"].values()) if r["errors"] else 0.0
    for r in rows:
        r["max_error"] = worst(r) if not r["error"] else None
    if tol is None:
        return {"tol": None, "text": "no tolerance given (--tol): no recommendation"}
    within = [r for r in ok if worst(r) <= tol]
    if not within:
        best = min(ok, key=worst)
        return {"tol": tol, "case": None, "text": f"no run is within {tol:.3g} of the reference; the closest, "
                f"{best['values']}, is {worst(best):.3g} away"}
    r = min(within, key=cost)
    return {"tol": tol, "case": r["case"], "values": r["values"], "wall_s": r["wall_s"], "cpu_s": r.get("cpu_s"),
            "max_error": worst(r),
            "text": f"cheapest within {tol:.3g}: {r['values']} ({cost(r):.3g} s of CPU, largest error "
                    f"{worst(r):.3g})"}


def cost(r) -> float:
    """A run's cost: its CPU time [s] (its wall time where that was not measured)."""
    return r["cpu_s"] if r.get("cpu_s") is not None else r["wall_s"]


def pareto_front(rows) -> list:
    """The runs no other run beats in both cost (:func:`cost`) and largest error."""
    ok = sorted([r for r in rows if not r["error"]], key=lambda r: (cost(r), r["max_error"]))
    front, best = [], math.inf
    for r in ok:
        if r["max_error"] < best:
            front.append(r)
            best = r["max_error"]
    return front


def _fmt(v):
    if isinstance(v, float):
        return f"{v:.6g}"
    return "" if v is None else str(v)


def _write(res: StudyResult, specs, vary, tol):
    out, rows = res.out, res.rows
    cost = ["wall_s", "cpu_s", "wall_s_per_simulated_s", "max_rss_mb", "particles", "steps"]
    cost_head = ["wall [s]", "CPU [s]", "wall per simulated s [-]", "peak memory [MB]", "particles", "steps"]
    used_head = {"dt": "dt used [s]", "c0_m_s": "c0 used [m/s]", "setup": "set-up used"}
    used = [k for k in used_head if any(r["used"].get("dt_used_s" if k == "dt" else k) for r in rows)]

    def used_cell(r, k):
        u = r["used"]
        if k != "dt":
            return _fmt(u.get(k))
        if u.get("dt_used_s") is None:
            return ""
        same = u.get("dt_min_s") is not None and math.isclose(u["dt_min_s"], u["dt_max_s"], rel_tol=1e-9)
        return _fmt(u["dt_used_s"]) + ("" if same else f" ({_fmt(u['dt_min_s'])}..{_fmt(u['dt_max_s'])})")

    head = (list(vary) + [used_head[k] for k in used] + [s for s in specs] + [f"error {s}" for s in specs]
            + cost_head + ["error"])
    table = []
    for r in rows:
        table.append([_fmt(r["values"][k]) for k in vary] + [used_cell(r, k) for k in used]
                     + [_fmt(r["metrics"].get(s)) for s in specs]
                     + [_fmt(r["errors"].get(s)) for s in specs] + [_fmt(r.get(k)) for k in cost]
                     + [_fmt(r["error"])])
    import csv

    with open(out / "study.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(head)
        w.writerows(table)
    front = {r["case"] for r in pareto_front(rows)}
    md = [f"# Study: {', '.join(specs)}", "", f"Reference: {res.reference.get('kind')} "
          f"{res.reference.get('values', res.reference.get('file', ''))}. {res.recommendation['text']}.", "",
          "| " + " | ".join(head + ["Pareto"]) + " |", "|" + "---|" * (len(head) + 1)]
    md += ["| " + " | ".join(t + ["*" if r["case"] in front else ""]) + " |" for t, r in zip(table, rows)]
    notes = [(r["values"], n) for r in rows for n in r.get("notes", ())]
    if notes:
        md += ["", "What each run's scene changed beyond the varied values:", ""]
        md += [f"- {v}: {n}" for v, n in notes]
    if res.orders:
        md += ["", "Richardson extrapolation (observed order p):", ""]
        md += [f"- {k}: {v['extrapolated']:.10g}, p = {v['order']:.3g}" for k, v in res.orders.items()]
    (out / "study.md").write_text("\n".join(md) + "\n")
    js = {"vary": vary, "metrics": specs, "tol": tol, "reference": res.reference, "recommendation": res.recommendation,
          "orders": res.orders, "wall_s": res.wall_s,
          "rows": [{k: v for k, v in r.items() if k != "series"} for r in rows]}
    (out / "study.json").write_text(json.dumps(js, indent=1, default=str))
    _plot(out, rows, front, tol, specs)


def _plot(out, rows, front, tol, specs):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ok = [r for r in rows if not r["error"]]
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=110)
    floor = min([r["max_error"] for r in ok if r["max_error"] > 0] or [1e-6]) / 10
    for r in ok:
        y = max(r["max_error"], floor)
        ax.scatter(cost(r), y, c="C3" if r["case"] in front else "C0", zorder=3)
        ax.annotate(", ".join(f"{k.split('.')[-1]}={v}" for k, v in r["values"].items()), (cost(r), y),
                    fontsize=7, xytext=(4, 3), textcoords="offset points")
    fr = sorted([r for r in ok if r["case"] in front], key=cost)
    ax.plot([cost(r) for r in fr], [max(r["max_error"], floor) for r in fr], "C3-", lw=1, label="Pareto front")
    if tol is not None:
        ax.axhline(tol, color="0.4", ls="--", lw=1, label=f"tolerance {tol:.3g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("cost: CPU time of the run [s]")
    ax.set_ylabel("largest relative error")
    ax.set_title(f"error against cost: {', '.join(specs)}", fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "pareto.png")
    plt.close(fig)
