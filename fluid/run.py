"""The SPH fluid on its own: advance by its stable step to ``t_end``, sample probes and
write snapshots at exact times, show a progress bar.

    from fluid.run import run
    from fluid.probes import PressureProbe, WaveGauge, Energy
    samples = run(fluid, 2.0, probes=[WaveGauge([0.1, 0.5]), Energy()], sample_every=0.01,
                  output="tank.h5", snapshot_every=0.1)
    samples["gauges"]["t"], samples["gauges"]["eta"]        # (n,), (n, 2)

Sample and snapshot times are ``t0 + k * every`` (counted, never accumulated), reached
exactly: the step before one is shortened, and the two steps before it are evened out
when the last would be tiny. Each probe (see :mod:`fluid.probes`) becomes the series
``/series/NAME`` of the output.

If the fluid raises (an ``InstabilityError``: a NaN, every particle gone), the output is
flushed and closed before the error propagates, so the file holds everything up to the
last good sample; the samples so far ride on the error as ``error.samples``.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from cosim.errors import InputError
from fluid.output import H5Output
from fluid.progress import Progress

#: per-particle arrays written in each snapshot by default (attributes of ``fluid.ps``)
SNAPSHOT_FIELDS = ("vel", "rho", "p", "kind", "ids")


class _Times:
    """The event times ``t0 + k every`` [s] up to ``t_end``, or none."""

    def __init__(self, t0: float, t_end: float, every, what: str):
        if every is not None and not (isinstance(every, (int, float)) and math.isfinite(every) and every > 0):
            raise InputError(f"run: {what}={every!r} s; give a positive interval in seconds or None")
        self.t0, self.t_end, self.every, self.k = t0, t_end, every, 0

    def next(self) -> float:
        if self.every is None:
            return math.inf
        t = self.t0 + self.k * self.every
        return t if t <= self.t_end * (1 + 1e-12) + 1e-12 else math.inf

    def due(self, t: float, tol: float) -> bool:
        return abs(self.next() - t) <= tol


def run(fluid, t_end: float, *, probes=(), sample_every: float | None = None, output=None,
        snapshot_every: float | None = None, snapshot_fields=SNAPSHOT_FIELDS, attrs: dict | None = None,
        progress=None) -> dict[str, dict[str, np.ndarray]]:
    """Advance ``fluid`` (a :class:`fluid.solver.Fluid`; initialised at t = 0 s if it is not
    yet) to ``t_end`` [s] by steps of its own ``max_dt()``.

    ``probes``: objects with ``name``, ``columns`` and ``sample(fluid) -> dict`` (see
    :mod:`fluid.probes`), sampled at the start and every ``sample_every`` [s] (None: at the
    start and at ``t_end`` only). ``output``: an :class:`~fluid.output.H5Output` (left open
    for the caller) or a path (a new file, closed at the end; ``attrs`` go in it); None
    writes nothing. ``snapshot_every`` [s]: particle snapshots of ``snapshot_fields`` at the
    start and at that interval (needs ``output``). ``progress``: None (a bar on stderr when
    it is a terminal), True, False, or a :class:`~fluid.progress.Progress`.

    Returns ``{probe.name: {"t": (n,), column: (n,) or (n, k)}}``.
    """
    if fluid.limit is None:
        fluid.initialize(0.0)
    t0 = float(fluid.t)
    if not (isinstance(t_end, (int, float)) and math.isfinite(t_end) and t_end > t0):
        raise InputError(f"run: t_end={t_end!r} s; give a finite end time after the fluid's time {t0} s")
    probes = list(probes)
    names = [getattr(p, "name", None) for p in probes]
    for p, name in zip(probes, names):
        if not (isinstance(name, str) and callable(getattr(p, "sample", None))):
            raise InputError(f"run: probe {p!r} needs a name and a sample(fluid) method (see fluid.probes)")
    if len(set(names)) != len(names):
        raise InputError(f"run: probe names {names} repeat; give each probe its own name=")
    for f in snapshot_fields:
        if not isinstance(getattr(fluid.ps, f, None), np.ndarray) or f == "pos":
            raise InputError(f"run: snapshot field {f!r} is not a particle array; choose from "
                             f"{[k for k in fluid.ps.FIELDS if k != 'pos']}")
    if snapshot_every is not None and output is None:
        raise InputError("run: snapshot_every needs an output (an H5Output or a path)")
    samples_at = _Times(t0, t_end, sample_every, "sample_every")
    snaps_at = _Times(t0, t_end, snapshot_every, "snapshot_every")
    own = output is not None and not isinstance(output, H5Output)
    if own:
        if not isinstance(output, (str, Path)):
            raise InputError(f"run: output={output!r}; give an H5Output, a path or None")
        output = H5Output(output, fluid.config.dim, attrs=attrs)
    elif attrs:
        raise InputError("run: attrs go into a file run() opens; write them with H5Output(..., attrs=)")
    if output is not None and output.dim != fluid.config.dim:
        raise InputError(f"run: the output is {output.dim}-D but the fluid is {fluid.config.dim}-D; "
                         f"open the H5Output with dim={fluid.config.dim}")
    bar = progress if isinstance(progress, Progress) else Progress(t0, t_end, enabled=progress)
    rows: dict[str, list] = {name: [] for name in names}
    tol = 1e-9 * max(1.0, abs(t_end))

    def record(t: float) -> None:
        if samples_at.due(t, tol) or (sample_every is None and t in (t0, t_end)):
            for p in probes:
                s = p.sample(fluid)
                rows[p.name].append((t, s))
                if output is not None:
                    output.series(p.name, t, **s)
            samples_at.k += samples_at.due(t, tol)
        if snaps_at.due(t, tol):
            ps = fluid.ps
            output.snapshot(t, ps.pos, **{f: getattr(ps, f) for f in snapshot_fields})
            snaps_at.k += 1

    try:
        try:
            t = t0
            record(t)
            while t_end - t > tol:
                target = min(samples_at.next(), snaps_at.next(), t_end)
                remaining = target - t
                dt = fluid.max_dt()
                if remaining <= dt * (1 + 1e-12):
                    dt, t_next = remaining, target  # land exactly on the event
                elif remaining < 2.0 * dt:
                    dt, t_next = 0.5 * remaining, None  # two even steps, no sliver
                else:
                    t_next = None
                fluid.advance(t, dt)
                t = t_next if t_next is not None else t + dt
                bar.update(t)
                if t_next is not None:
                    record(t)
        finally:
            bar.close(t)
            if output is not None and not output.closed:
                if own:
                    output.close()
                else:
                    output.flush()
    except Exception as e:
        e.samples = _arrays(rows)  # what was sampled before the failure
        raise
    return _arrays(rows)


def _arrays(rows: dict) -> dict[str, dict[str, np.ndarray]]:
    out = {}
    for name, rs in rows.items():
        d = {"t": np.array([t for t, _ in rs])}
        if rs:
            for k in rs[0][1]:
                d[k] = np.array([np.asarray(s[k], dtype=np.float64) for _, s in rs])
        out[name] = d
    return out
