"""The runs of a study: every combination of the varied fields, each a ``cosim run`` in its
own process (a crash or an instability is that run's row, not the study's end; its cost is
measured on the process alone: wall and CPU time, peak memory), cached by a hash of the
scene and of the code, scheduled serially or on Dask.

Dask (``dask.distributed``): a local cluster by default, one single-threaded worker process
per run slot, each run's numba threads set by ``NUMBA_NUM_THREADS`` so that slots x threads
do not exceed the cores; or an existing cluster (``scheduler="tcp://host:8786"``): the same
study sweeps one workstation or many nodes (the workers need this package and a shared
output folder).
"""

from __future__ import annotations

import hashlib
import itertools
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from cosim.version import code_version  # noqa: F401 - the studies' cache key (sweep.code_version)


@dataclass
class Case:
    """One run of a study: the values it sets (``{"fluid.dx": 0.01}``), its scene as TOML,
    its cache key and folder."""

    index: int
    values: dict
    toml: str
    key: str
    folder: Path
    scene: object = None  #: the case's Scene (not sent to the workers: they get its TOML)
    notes: tuple = ()  #: what changing a part's kind dropped or carried over; --set values not applied


def combinations(vary: dict) -> list[dict]:
    """Every combination of the varied fields' values, the first field varying slowest."""
    keys = list(vary)
    return [dict(zip(keys, combo)) for combo in itertools.product(*(vary[k] for k in keys))]


def case(index: int, values: dict, scene, out: Path, version: str, notes=()) -> Case:
    """The case of ``scene`` (already changed by ``values``), keyed by its TOML and the code."""
    text = scene.to_toml()
    key = hashlib.sha256((text + version).encode()).hexdigest()[:16]
    return Case(index, values, text, key, out / "runs" / key, scene, tuple(notes))


def foreign(scene, assignment: str, values: dict | None = None) -> str | None:
    """The name of the kind of the part that ``assignment`` (``KEY.PATH=VALUE``) changes when
    that kind has no such field (``fluid.dx`` on the analytic fluid: ``"Analytic"``), else
    None (the field is the kind's, or the part has one kind only); the kind is the one
    ``values`` (``{"fluid.model": "sph"}``) choose, else the scene's."""
    from cosim.scene import spec
    from cosim.scene.fields import Spec, spec_fields

    head, _, rest = assignment.split("=", 1)[0].strip().partition(".")
    kind = type(getattr(scene, head, None))
    if not rest or getattr(kind, "TAG", None) is None:
        return None
    tag = kind.TAG[0]
    if values and f"{head}.{tag}" in values:
        chosen = [c for c in vars(spec).values() if isinstance(c, type) and issubclass(c, Spec)
                  and c.TAG == (tag, values[f"{head}.{tag}"])]
        kind = chosen[0] if len(chosen) == 1 else kind
    name = re.split(r"[.\[]", rest, maxsplit=1)[0]
    return None if name == tag or name in {n for n, _, _ in spec_fields(kind)} else kind.__name__


def cases(scene, vary: dict, out: Path, version: str, sets=()) -> list[Case]:
    """The study's cases; a value the scene refuses is refused here, before any run.

    ``sets``: ``KEY.PATH=VALUE`` for every run (``cosim study --set``). One that names a
    field the scene's part lacks but a varied kind has (``fluid.dx`` with ``--vary
    fluid.model=analytic,sph``) is applied, after the varied values, to the runs whose
    part has it and no other (each run's notes say so); one that no run's part has is
    refused, as are the runs of a kind that needs a field no one gave."""
    from cosim.errors import InputError
    from cosim.scene.fields import SceneError
    from cosim.scene.toml_io import toml_value, with_values

    later = [a for a in sets if foreign(scene, a) is not None]
    scene = with_values(scene, [a for a in sets if a not in later]) if len(later) < len(sets) else scene
    combos = combinations(vary)
    missing = [a for a in later if all(foreign(scene, a, values) is not None for values in combos)]
    if missing:
        with_values(scene, missing)  # no run's part has the field: the scene's own error names it
    out_cases = []
    for i, values in enumerate(combos):
        notes: list[str] = []
        try:
            own = [a for a in later if foreign(scene, a, values) is None]
            s = with_values(scene, [f"{k}={toml_value(v)}" for k, v in values.items()] + own, notes)
            notes += [f"--set {a} not applied ({foreign(s, a)} has no such field)" for a in later if a not in own]
        except SceneError as e:
            hint = (f" (a field of this kind alone: give it with --set {e.path}=VALUE, which the study applies to "
                    f"the runs whose {e.path.split('.')[0]} has it)") if e.problem.startswith("is required") else ""
            raise InputError(f"the run with {values}: {e}{hint}") from None
        out_cases.append(case(i, values, s, out, version, notes))
    return out_cases


def check_workers(workers, threads) -> None:
    """Refuse a number of runs at once (``workers``; None: the default) or of numba threads
    per run (``threads``) that is not a whole number >= 1, before any run: 0 or -1 would
    start no worker and the study would wait for ever."""
    from cosim.errors import InputError

    for flag, v, what in (("--workers", workers, "runs at once; leave it out for cores / --threads"),
                          ("--threads", threads, "numba threads per run; default 1")):
        if v is None and flag == "--workers":
            continue
        if isinstance(v, bool) or not isinstance(v, int) or v < 1:
            raise InputError(f"{flag} {v!r}: give a whole number >= 1 ({what})")


def run_logged(cmd: list[str], log: Path, env: dict) -> tuple[int, object, str]:
    """Run ``cmd`` with its messages (stderr) written to the file ``log``; returns its exit
    code, its resource usage (``os.wait4``: CPU of the process alone) and the messages.
    A file, not a pipe: a pipe holds 64 KiB, and a run that writes more (a warning each
    time particles leave the domain) would wait on it while this process waits on the run."""
    with open(log, "w") as err:
        proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=err, env=env)
        _, status, usage = os.wait4(proc.pid, 0)
    return os.waitstatus_to_exitcode(status), usage, Path(log).read_text(errors="replace")


def run_case(toml: str, folder: str, threads: int, version: str) -> dict:
    """Run one case in its own process (``cosim run``) unless the same scene and code ran
    before into ``folder``; returns its record (``case.json``)."""
    folder = Path(folder)
    record = folder / "case.json"
    if record.is_file():
        rec = json.loads(record.read_text())
        if rec.get("version") == version and rec.get("complete"):
            rec["cached"] = True
            return rec
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "scene.toml").write_text(toml)
    env = dict(os.environ, NUMBA_NUM_THREADS=str(threads))
    t0 = time.perf_counter()
    # --yes: the study checked the runs' costs before the first (cosim.study.check_costs)
    returncode, usage, stderr = run_logged([sys.executable, "-m", "cosim.cli", "run", str(folder / "scene.toml"),
                                            "--out", str(folder / "run"), "--overwrite", "--quiet", "--yes"],
                                           folder / "stderr.log", env)
    rec = {"version": version, "complete": True, "wall_s": time.perf_counter() - t0,
           "cpu_s": usage.ru_utime + usage.ru_stime, "max_rss_mb": usage.ru_maxrss / 1024.0,
           "threads": threads, "returncode": returncode, "error": None}
    summary = folder / "run" / "summary.json"
    if summary.is_file():
        s = json.loads(summary.read_text())
        rec.update({k: s.get(k) for k in ("steps", "particles", "t_reached_s", "wall_s_per_simulated_s")})
        c = s.get("coupling") or {}  # what the run used where the scene left it to the run, or asked for it
        rec.update(dt_used_s=c.get("dt_mean_s"), dt_min_s=c.get("dt_min_s"), dt_max_s=c.get("dt_max_s"),
                   c0_m_s=s.get("speed_of_sound_m_s"), setup=(s.get("setup") or {}).get("name"))
        rec["run_wall_s"] = s.get("wall_s")
        rec["error"] = s.get("error")
    if returncode != 0:
        lines = [ln for ln in stderr.strip().splitlines() if ln.strip()]
        last = lines[-1].removeprefix("cosim run: error: ") if lines else f"exit status {returncode}"
        rec["error"] = rec["error"] or last
    record.write_text(json.dumps(rec, indent=1))
    rec["cached"] = False
    return rec


def series(folder: Path) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """The probe series of a case's run, ``{name: (t, x)}`` (what a run wrote before failing)."""
    import h5py

    path = Path(folder) / "run" / "run.h5"
    out = {}
    if not path.is_file():
        return out
    from fluid.output import read_series

    with h5py.File(path, "r") as f:
        groups = list(f["series/probes"]) if "series/probes" in f else []
    for g in groups:
        s = read_series(path, f"probes/{g}")
        for k, v in s.items():
            if k != "t":
                out[k] = (s["t"], v)
    return out


def execute(cs: list[Case], *, workers: int, threads: int, scheduler: str | None = None, serial: bool = False,
            version: str, report=None) -> list[dict]:
    """Run the cases (serially, on a local Dask cluster of ``workers`` processes, or on the
    cluster at ``scheduler``); ``report(case, record)`` after each. Returns the records in
    case order."""
    results: list[dict | None] = [None] * len(cs)
    if serial:
        for c in cs:
            results[c.index] = run_case(c.toml, str(c.folder), threads, version)
            if report:
                report(c, results[c.index])
        return results
    try:
        from dask.distributed import Client, LocalCluster, as_completed
    except ImportError:
        from cosim.errors import InputError

        raise InputError("a study on Dask needs dask.distributed: pip install 'cosim-sph[study]', or run it "
                         "with --serial") from None

    import dask

    # Dask's scratch space (locks, the workers' folders) in a folder of the study's own, gone at the end
    with tempfile.TemporaryDirectory(prefix="cosim-dask-", ignore_cleanup_errors=True) as scratch, \
            dask.config.set({"temporary-directory": scratch}):
        cluster = None
        if scheduler is None:
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
            client = Client(cluster)
        else:
            client = Client(scheduler)
        try:
            futures = {client.submit(run_case, c.toml, str(c.folder), threads, version, pure=False,
                                     key=f"case-{c.key}"): c for c in cs}
            for fut in as_completed(futures):
                c = futures[fut]
                try:
                    results[c.index] = fut.result()
                except Exception as e:  # the worker itself failed: the run's row says so
                    results[c.index] = {"version": version, "complete": False, "error": f"{type(e).__name__}: {e}",
                                        "cached": False}
                if report:
                    report(c, results[c.index])
        finally:
            client.close()
            if cluster is not None:
                cluster.close()
    return results
