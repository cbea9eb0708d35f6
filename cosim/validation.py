"""Registry of validation cases, run by ``cosim validate NAME``.

A case is a function ``fn(quick: bool) -> dict`` registered with :func:`case` (from
:mod:`cosim.validations.registry`, which the case modules import), with the target it is
held to: ``target`` (the stated target, copied from the target column of its row of
``docs/VALIDATION.md``, or declared where it has no row) and ``quick_target`` (what its
coarse variant is judged against, declared). The function returns ``metrics`` (measured
errors and quantities) and ``tolerances`` (what ``passed`` is judged against, see
:func:`~cosim.validations.judging.judge`), and, where they apply, ``particles``, ``steps``,
``stated_tolerances`` (the stated target's tolerances where the judged ones differ: a
quick variant, a departed criterion), ``departure`` (``criterion`` and ``why``: the full
variant is judged on a criterion that departs from the stated target), ``series`` (curves
of ours against the reference, for the report's plots; not JSON: ``cosim validate``
leaves them out) and any further JSON-ready keys. It does not return ``passed``:
:func:`run` judges it from the metrics and the tolerances, the same way for a quick
variant and a full one, and adds ``name``, ``quick``, ``target`` (the text of what was
judged), ``stated_target``, ``stated`` (the stated target with its measured values, where
the judged tolerances differ from it), ``wall_s`` and ``case_cpu_s`` (the case's CPU
seconds: all its threads and the processes it ran and waited for; a case that reads back
runs made by earlier processes returns their recorded CPU as ``read_back_cpu_s``, which
:func:`cost` adds). ``quick=True`` is the
coarse variant that CI runs. Cases live in the modules of :mod:`cosim.validations`, imported
only when a case is listed or run (by name, :data:`CASE_MODULES`), so ``import cosim``
stays light; none of them imports this module.
"""

from __future__ import annotations

import importlib
import math
import os
import time
from collections.abc import Iterator
from pathlib import Path

from cosim.errors import InputError
from cosim.validations.folders import SCENES
from cosim.validations.judging import judge, lookup, measured, within  # noqa: F401 (this module's API)
from cosim.validations.registry import _CASES, LONG_QUICK_S, Case, case  # noqa: F401 (this module's API)

#: modules that register cases; a new family adds its module here
CASE_MODULES = ("cosim.validations.catenary", "cosim.validations.cable", "cosim.validations.fluid",
                "cosim.validations.sloshing", "cosim.validations.coupling", "cosim.validations.floating",
                "cosim.validations.waves", "cosim.validations.tanks", "cosim.validations.elastic",
                "cosim.validations.arch_rib", "cosim.validations.elastic_gate",
                "cosim.validations.dambreak_lobovsky", "cosim.validations.long_period",
                "cosim.validations.elastic_table2", "cosim.validations.wind_turbine", "cosim.validations.wind_turbine_sph",
                "cosim.validations.wave_propagation", "cosim.validations.potential",
                "cosim.validations.nearfield", "cosim.validations.radiation",
                "cosim.validations.shaken_cantilever")

#: where the stated targets are written
VALIDATION_DOC = "docs/VALIDATION.md"


def cases() -> dict[str, Case]:
    """All registered cases, by name."""
    for mod in CASE_MODULES:
        importlib.import_module(mod)
    return dict(sorted(_CASES.items()))


def case_scenes() -> dict[str, Path | None]:
    """Each case's scene file, ``cosim/validations/scenes/NAME.toml`` (None where the case has
    none yet: it builds its set-up in code). A case that is a scene runs, and is re-measured,
    by the same runner as a user's scene (``cosim run``, ``cosim study``)."""
    return {name: (SCENES / f"{name}.toml" if (SCENES / f"{name}.toml").exists() else None) for name in cases()}


def target_text(c: Case, quick: bool, departure: dict | None = None) -> str:
    """What a record of case ``c`` was judged against, in words."""
    if quick:
        return f"quick: {c.quick_target} (declared)"
    if c.row is None:
        stated = f"declared (no row in {VALIDATION_DOC}): {c.target}"
    else:
        stated = f"the stated target of {VALIDATION_DOC} (row {c.row})"
    if departure:
        return f"full: {departure['criterion']} (departs from {stated}: see departure)"
    return f"full: {stated}"


def _cpu_s() -> float:
    """CPU seconds of this process and of the child processes it has waited for."""
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def run(name: str, quick: bool = False) -> dict:
    """Run one case and return its record: JSON-ready but for ``series`` (if any)."""
    known = cases()
    if name not in known:
        raise InputError(f"no validation case {name!r}; known cases: {', '.join(known)}")
    c = known[name]
    t0, c0 = time.perf_counter(), _cpu_s()
    out = c.fn(quick)
    wall, cpu = time.perf_counter() - t0, _cpu_s() - c0
    if "passed" in out:
        raise TypeError(f"validation case {name!r} returned 'passed': it is judged from its tolerances by run()")
    metrics, tolerances = out.pop("metrics", {}), out.pop("tolerances", {})
    passed, failed = judge(metrics, tolerances)
    departure = out.pop("departure", None)
    stated_tol = out.pop("stated_tolerances", None)
    series = out.pop("series", None)
    record = {"name": name, "quick": quick, "passed": passed, "target": target_text(c, quick, departure),
              "stated_target": c.target, "metrics": metrics, "tolerances": tolerances,
              "outside_tolerance": failed, "particles": 0, "steps": 0}
    if stated_tol is not None or departure:
        stated = {"target": c.target, "tolerances": stated_tol or {}}
        given = (departure or {}).get("stated_measured")
        if given is not None:  # the stated target's values come from elsewhere (a past run)
            stated["measured"] = given
            stated["met"] = departure.get("stated_met")
            stated["source"] = departure.get("source", "")
        else:
            stated["measured"] = measured(metrics, stated["tolerances"])
            known_all = all(v is not None for v in stated["measured"].values()) and stated["tolerances"]
            stated["met"] = judge(metrics, stated["tolerances"])[0] if known_all else None
            if not known_all:
                stated["source"] = (departure or {}).get("source", "not measured by this variant")
        record["stated"] = stated
    if departure:
        record["departure"] = {"criterion": departure["criterion"], "why": departure["why"]}
    record.update(out)
    record["wall_s"] = round(wall, 4)
    record["case_cpu_s"] = round(cpu, 4)
    if series:
        record["series"] = series
    return record


def cores() -> int:
    """The CPU cores this process may run on."""
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)


def _worker_threads(threads: int) -> None:
    """A worker's numba threads, set before its first case imports numba."""
    os.environ["NUMBA_NUM_THREADS"] = str(threads)


def _stop(pool) -> None:
    """Cancel what has not started and end the pool's own workers (the running cases)."""
    pool.shutdown(wait=False, cancel_futures=True)
    for proc in list((getattr(pool, "_processes", None) or {}).values()):
        proc.terminate()


def run_many(names: list[str], quick: bool = False, jobs: int = 1,
             costs: dict[str, float] | None = None) -> Iterator[dict]:
    """The records of :func:`run` for each case of ``names``, in that order. ``jobs`` > 1:
    that many cases at once, each in a worker process of its own (spawned, so that no
    numba threads are forked) with ``cores() // jobs`` numba threads (at least one). A
    case's fluid runs on one thread below its parallel threshold (``FluidConfig.
    parallel_min_particles``), which every quick variant is, so on N cores N cases run in
    about the time of one. They start costliest first by ``costs`` (case: seconds, from
    earlier records; a case without one counts as the costliest), the longest-processing-
    time rule (Graham 1969): the last case to finish then starts early. A case that raises
    stops the others and the error reaches the caller, as without workers. A script that
    calls it with ``jobs`` > 1 does so under ``if __name__ == "__main__":`` (the workers
    import the main module)."""
    known = cases()
    unknown = [n for n in names if n not in known]
    if unknown:
        raise InputError(f"no validation case {', '.join(map(repr, unknown))}; known cases: {', '.join(known)}")
    if jobs < 1:
        raise InputError(f"jobs={jobs!r}: give at least 1 (cases run at once)")
    if jobs == 1 or len(names) < 2:
        for name in names:
            yield run(name, quick)
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    first = sorted(names, key=lambda n: -(costs or {}).get(n, math.inf))
    pool = ProcessPoolExecutor(min(jobs, len(names)), mp_context=multiprocessing.get_context("spawn"),
                               initializer=_worker_threads, initargs=(max(1, cores() // jobs),))
    try:
        futures = {name: pool.submit(run, name, quick) for name in first}
        for name in names:
            yield futures[name].result()
    except BaseException:
        _stop(pool)
        raise
    pool.shutdown()


def quick_tier() -> tuple[list[str], list[str]]:
    """The cases ``cosim validate all --quick`` runs (their quick variants within
    :data:`LONG_QUICK_S` of CPU each), and the long ones it leaves out (:attr:`Case.long`)."""
    known = cases()
    return [n for n, c in known.items() if not c.long], [n for n, c in known.items() if c.long]


# ------------------------------------------------------------------------------- listing
#: where a checkout keeps the records of the last validation runs (``cosim validate --report``'s
#: records.jsonl), which ``cosim validate --list`` reads when it is there
COMMITTED_RECORDS = "docs/validation/records.jsonl"


def committed_records() -> Path:
    """The checkout's :data:`COMMITTED_RECORDS` (it may not exist: an installed package)."""
    return Path(__file__).resolve().parents[1] / COMMITTED_RECORDS


def status(rec: dict) -> str:
    """What a record says of its case: ``target met`` (judged on the stated target, or a
    quick variant on its declared one), ``departure met`` (a full variant judged on a
    criterion that departs from the stated target, which is then ``stated target met`` /
    ``not met`` / unmeasured), or ``not met``."""
    if not rec.get("passed"):
        return "not met"
    if rec.get("quick") or not rec.get("departure"):
        return "target met"
    met = (rec.get("stated") or {}).get("met")
    return "departure met (stated target " + {True: "met", False: "not met"}.get(met, "not measured") + ")"


def cost(rec: dict | None) -> float | None:
    """A record's cost [s]: its CPU seconds (``case_cpu_s``: on one core, what the machine's
    load changes least; with ``read_back_cpu_s``, those its runs read back from earlier
    processes recorded), or its wall time where it has none."""
    rec = rec or {}
    own = rec.get("case_cpu_s", rec.get("wall_s"))
    return own if own is None else own + rec.get("read_back_cpu_s", 0.0)


def _wall(costs: list[float], n: int) -> float:
    """The wall time [s] of cases costing ``costs`` [s] each, ``n`` at once: the total over
    the cores, or the costliest case if that is longer (0 for none)."""
    return max(sum(costs) / n, max(costs, default=0.0))


def _seconds(s: float | None) -> str:
    """Seconds, short ("-" for none)."""
    if s is None:
        return "-"
    return f"{s:.0f}" if s >= 100 else f"{s:.1f}" if s >= 1 else f"{s:.2f}" if s >= 0.01 else "<0.01"


def listing(records: list[dict] | None, source: str = "") -> list[str]:
    """``cosim validate --list``: each case with the cost (:func:`cost`) and status of its
    quick and full variant in ``records`` (records of :func:`run`, e.g. read from a report's
    records.jsonl), a record judged against another target than the case's present one
    marked as such, the long cases' quick variants marked ``(long)``, and the quick variants'
    total with the wall time ``all --quick`` (and ``--long``) take on this machine's cores;
    or, without records, the cases and their descriptions with a line that says that their
    costs and statuses are unknown and how to measure them."""
    known = cases()
    lines = []
    if not records:
        lines += [f"no validation records{f' in {source}' if source else ''}: cost and status unknown until the "
                  f"cases run (cosim validate all --quick --report DIR; then cosim validate --list --from "
                  f"DIR/records.jsonl)", ""]
        lines += [f"{'case':28s} description"]
        lines += [f"{c.name:28s} {c.description}" for c in known.values()]
        return lines
    by = {(r["name"], bool(r.get("quick"))): r for r in records}
    lines += [f"from {source}" if source else "from the records given", ""]
    head = f"{'case':28s} {'quick [s]':>9s} {'full [s]':>9s}  status"
    lines += [head, "-" * len(head)]
    stale = False
    for c in known.values():
        said = []
        for variant, quick in (("quick", True), ("full", False)):
            r = by.get((c.name, quick))
            label = f"{variant} (long)" if quick and c.long else variant
            said.append(f"{label}: {status(r)}" if r else f"{label}: no record")
            if r and r.get("target") != target_text(c, quick, r.get("departure")):
                said[-1] += " (*)"
                stale = True
        costs = [_seconds(cost(by.get((c.name, quick)))) for quick in (True, False)]
        lines.append(f"{c.name:28s} {costs[0]:>9s} {costs[1]:>9s}  {'; '.join(said)}")
    quick = {name: cost(r) or 0.0 for (name, q), r in by.items() if q and name in known}
    lines += [""]
    if quick:
        n = cores()
        tier = [v for k, v in quick.items() if not known[k].long]
        long = [v for k, v in quick.items() if known[k].long]
        lines += [f"quick variants: {len(quick)} of {len(known)} cases recorded, {sum(quick.values()):.0f} s in all;",
                  f"  cosim validate all --quick runs the {len(tier)} recorded of the quick tier ({sum(tier):.0f} s), "
                  f"{n} at once on this machine's {n} cores (--jobs): about {_wall(tier, n):.0f} s of wall time;"]
        if long:
            lines += [f"  --long adds the {len(long)} recorded long ones (quick variants beyond {LONG_QUICK_S:.0f} s "
                      f"each, {sum(long):.0f} s): about {_wall(tier + long, n):.0f} s of wall time in all"]
    if stale:
        lines += ["(*) the record was judged against another target than the case's present one: run it again"]
    lines += ["cost: the CPU seconds of the recorded run, on one core (its wall time where it has none)",
              f"target met: judged on the stated target of {VALIDATION_DOC} (a quick variant: on its declared one)",
              "departure met: judged on a criterion that departs from the stated target, named in the record"]
    return lines
