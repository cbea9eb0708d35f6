"""Run a scene: the one loop, recorder, checkpoint and plot writer of every coupled run
(``Scene.run()``, ``cosim run``).

The run stops at exact event times, ``k * every`` (counted, never accumulated): probe
samples (``world.sample_every``), particle snapshots (``snapshot_every``), checkpoints
(``checkpoint_every``) and particle plots (``plot_at``); the coupler lands on each
(``Coupler.run``). One output folder per run:

- ``scene.toml``: the scene as run, every field;
- ``run.h5`` + ``run.xmf`` (ParaView): ``/series/probes/GROUP`` (one column per
  ``ENTITY.QUANTITY``, :mod:`cosim.scene.probes`), ``/series/ledger/BODY`` (the loads of
  every coupling step), particle snapshots (``fluid.output``); each dataset's unit in its
  CF-style ``units`` attribute (a line's state: ``flag_values``, ``flag_meanings``);
- ``GROUP.csv`` per probe group (header ``t [s]`` then ``NAME [UNIT]``; a line's state
  names its codes, ``[0 resting|1 partly lifted|2 fully lifted|3 taut]``), ``ledger.csv``;
- ``GROUP.png`` per probe group, ``particles_tT.png`` at each ``plot_at`` time (:mod:`cosim.scene.plots`);
- ``sea_components.csv`` (the analytic fluid's incident sea, :mod:`fluid.waves`): its linear
  components (ω, amplitude, phase, k) and, for an irregular sea, the spectrum they stand for
  (the target S(ω), or a record's periodogram a² / 2Δω), plotted in ``sea_spectrum.png``;
- ``summary.json``: set-up, scheme, sizes, steps (``coupling``: by what set them), wall and CPU
  time, the cost estimate (``estimate``, :mod:`cosim.scene.cost`), each series' range, ``warnings``,
  ``line_breaks``, the catenary lines' ``line_events`` (:mod:`moorings.line_events`), ``near_field``
  (its box, why), ``sph_domain`` (a moving tank's, why), ``sea_variance_left_out`` (per body);
- ``checkpoint.h5``: the latest checkpoint, data only (:mod:`cosim.checkpoint`,
  ``docs/checkpoints.md``), replaced atomically: every ``world.checkpoint_wall`` of wall
  time (stretched so that writing takes at most :data:`CHECKPOINT_SHARE` of the run), at
  each ``world.checkpoint_every`` of simulated time and at the end; with both 0, none.

The folder must be new or empty: one that holds files is refused before any work, unless
``overwrite=True`` (``--overwrite``), which clears a folder an earlier run wrote (one that
holds one of :data:`RUN_FILES`) once the scene is built, or ``resume=True``.

``resume=True`` continues from ``checkpoint.h5`` in the folder, bit for bit, to the
scene's duration (which may be longer than the first run's; of the rest only
``world.checkpoint_wall`` may differ). It refuses, before anything is written, a
checkpoint of another scene, of other code (unless ``resume_any_version``), one that is
corrupt or truncated, and one holding values no run reaches (a NaN, an infinite time).
If the run raises, the outputs so far are written and left readable before the error
propagates; the build's temporary folder goes in every case.
"""

from __future__ import annotations

import hashlib
import json
import logging
import math
import os
import shutil
import tempfile
import time
from pathlib import Path

import numpy as np

from cosim import checkpoint
from cosim.checkpoint import CheckpointError
from cosim.errors import InputError
from cosim.scene.fields import SceneError

log = logging.getLogger(__name__)

CHECKPOINT = "checkpoint.h5"
#: what older versions wrote: a pickle, never loaded (loading one runs whatever it holds)
LEGACY_CHECKPOINT = "checkpoint.pkl"
#: the largest share of a run's wall time that writing checkpoints may take [-]
CHECKPOINT_SHARE = 0.02
#: the world's fields a resumed run may change (nothing it computes depends on them; a
#: plot time off the sampling grid cuts one step to land on, as the end does)
RESUMABLE = ("duration", "checkpoint_wall", "plot_at")
_TICK = 1e-12  # the coupler's clock resolution [s]
#: per-particle arrays of each snapshot (attributes of the fluid's particle set) and their units
SNAPSHOT_FIELDS = {"vel": "m/s", "rho": "kg/m^3", "p": "Pa", "kind": "1", "ids": "1"}


class Results:
    """The probe series of a run: ``results["box.heave"]`` (an array at ``results.t``),
    ``results.units[name]``, ``results.summary`` (summary.json), ``results.out``."""

    def __init__(self, t, series: dict, units: dict, summary: dict, out: Path):
        self.t, self.series, self.units, self.summary, self.out = np.asarray(t), series, units, summary, Path(out)

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self.series:
            raise KeyError(f"no series {name!r}; series: {', '.join(self.series)}")
        return self.series[name]

    def __contains__(self, name) -> bool:
        return name in self.series

    @property
    def names(self) -> list[str]:
        return list(self.series)

    def __repr__(self) -> str:
        return f"Results({len(self.t)} samples of {len(self.series)} series in {self.out})"


def read(out, unfinished: bool = False) -> Results:
    """The :class:`Results` of a run that another process wrote into the folder ``out``
    (its ``run.h5`` and ``summary.json``), as ``Scene.run`` returned them: for judging a
    long run after it ended, or one resumed over several sessions. A series' unit is its
    ``units`` attribute ("1": a pure number); the series in the run's order.
    ``unfinished``: also a run still going, or killed, that has no ``summary.json`` yet:
    its ``run.h5`` as far as written (opened without HDF5's file lock, which the writing
    process holds), the samples every series has whole, an empty ``summary``."""
    import h5py

    out = Path(out)
    for f in ("run.h5",) if unfinished else ("run.h5", "summary.json"):
        if not (out / f).is_file():
            raise InputError(f"{out}: no {f}; the folder holds no " + ("run" if unfinished else
                             "finished run (cosim run writes both; read(out, unfinished=True) reads a run still "
                             "going or killed, as far as it wrote)"))
    series, units, t = {}, {}, None
    with h5py.File(out / "run.h5", "r", locking=not unfinished) as h5:
        for g in h5["series/probes"].values():
            n = min(d.shape[0] for d in g.values())  # a row half written by a run still going: left out
            tg = g["t"][:n]
            if t is None or len(tg) > len(t):
                t = tg
            for name, d in g.items():
                if name != "t":
                    series[name], units[name] = d[:n], str(d.attrs.get("units", ""))
    summary = json.loads((out / "summary.json").read_text()) if (out / "summary.json").is_file() else {}
    order = [k for k in summary.get("series", {}) if k in series]  # the run's order of its series
    series = {k: series[k] for k in order + sorted(set(series) - set(order))}
    return Results(t if t is not None else np.zeros(0), series, units, summary, out)


def _event_times(w, particles: bool = True) -> list[tuple[float, set]]:
    """(time, what is due) for every event of the run, in order: particle snapshots only
    where there are particles (``particles``), plots only within the run."""
    ev: dict[int, tuple[float, set]] = {}

    def add(t, what):
        k = round(t / _TICK)
        ev.setdefault(k, (t, set()))[1].add(what)

    for every, what in ((w.sample_every, "sample"), (w.snapshot_every if particles else 0.0, "snapshot"),
                        (w.checkpoint_every, "checkpoint")):
        if every > 0:
            n = math.floor(w.duration / every * (1 + 1e-12))
            for k in range(n + 1):
                add(k * every, what)
    for t in w.plot_at:
        if t <= w.duration:
            add(t, "plot")
    add(w.duration, "sample")
    if w.checkpoint_every > 0 or w.checkpoint_wall > 0:
        add(w.duration, "checkpoint")
    return [ev[k] for k in sorted(ev)]


def _cf_attrs(unit: str, categories=None) -> dict:
    """The CF-style attributes of a probe column of unit ``unit``: ``units`` ("1" for a
    pure number), and for a column of codes their values and names (``flag_values``,
    ``flag_meanings``)."""
    out = {"units": "1" if unit == "-" else unit}
    if categories:
        out |= {"flag_values": np.arange(len(categories), dtype=np.int8),
                "flag_meanings": " ".join(c.replace(" ", "_") for c in categories)}
    return out


def _header(unit: str, categories=None) -> str:
    """A CSV column's unit in brackets; for codes, what each one means."""
    return "|".join(f"{k} {c}" for k, c in enumerate(categories)) if categories else unit


class _Recorder:
    def __init__(self, scene, built, out: Path):
        from cosim.scene.probes import groups

        self.scene, self.built, self.out = scene, built, out
        self.groups = groups(scene, built)
        self.rows: dict[str, list] = {g.name: [] for g in self.groups}
        self.times: list[float] = []
        self.h5 = None
        self.ledger_done = 0
        self.n_snap = 0

    def open(self, old_snapshots=()):
        from fluid.output import H5Output

        s = self.scene
        attrs = {"scene": s.name, "dim": s.world.dim, "duration_s": s.world.duration}
        self.h5 = H5Output(self.out / "run.h5", dim=s.world.dim, attrs={k: v for k, v in attrs.items() if k != "dim"})
        for f, unit in SNAPSHOT_FIELDS.items():
            self.h5.annotate("snapshots", f, units=unit)
        for g in self.groups:
            for c, u in zip(g.columns, g.units):
                self.h5.annotate(f"probes/{g.name}", c, **_cf_attrs(u, g.categories))
        for snap in old_snapshots:
            self.h5.snapshot(snap.pop("t"), snap.pop("pos"), **snap)
            self.n_snap += 1
        for k, t in enumerate(self.times):
            for g in self.groups:
                self.h5.series(f"probes/{g.name}", t, **dict(zip(g.columns, self.rows[g.name][k])))

    def sample(self, t: float):
        """One row of every group at ``t`` [s], recorded only when all of them could be
        taken (a probe that fails leaves the rows so far whole, for the outputs)."""
        values = []
        for g in self.groups:
            v = np.asarray(g.sample(), float)
            bad = ~np.isfinite(v)
            if bad.any():
                from cosim.errors import InstabilityError

                raise InstabilityError(f"t = {t:.9g} s: probe {g.columns[int(np.argmax(bad))]!r} is not finite "
                                       f"({v[bad][0]})")
            values.append(v)
        for g, v in zip(self.groups, values):
            self.rows[g.name].append(v)
        self.times.append(t)  # last: a row counts once every group has it (an interrupt may come between)
        for g, v in zip(self.groups, values):
            self.h5.series(f"probes/{g.name}", t, **dict(zip(g.columns, v)))

    def snapshot(self, t: float):
        sph = self.built.sph
        if sph is not None:
            ps = sph.simulated()  # a symmetry plane's mirror images are not written
            self.h5.snapshot(t, ps.pos, **{f: getattr(ps, f) for f in SNAPSHOT_FIELDS})
            self.n_snap += 1
        self.write_ledger()

    def write_ledger(self):
        led = self.built.coupler.ledger
        if led.body_names:
            self.ledger_done = led.write_h5(self.h5, start=self.ledger_done)

    def table(self, g) -> np.ndarray:
        """The samples of probe group ``g`` so far, (n_samples, n_columns)."""
        n = len(self.times)
        return np.array(self.rows[g.name][:n], float).reshape(n, len(g.columns))

    def series(self):
        out, units = {}, {}
        for g in self.groups:
            a = self.table(g)
            for j, (c, u) in enumerate(zip(g.columns, g.units)):
                out[c], units[c] = a[:, j], u
        return out, units

    def close(self):
        if self.h5 is not None and not self.h5.closed:
            try:
                self.write_ledger()
            finally:
                self.h5.close()


def _check_writable(out: Path) -> None:
    """Refuse an output folder that cannot be made or written, before any work."""
    probe = out
    while not probe.exists():
        probe = probe.parent
    if not probe.is_dir() or not os.access(probe, os.W_OK | os.X_OK):
        what = "is not a folder" if not probe.is_dir() else "cannot be written"
        raise InputError(f"output folder {str(out)!r}: {str(probe)!r} {what}; give another --out")


def _without_resumable(d: dict) -> dict:
    """The scene's fields ``d`` without those a resumed run may change (:data:`RESUMABLE`)."""
    return d | {"world": {k: v for k, v in d.get("world", {}).items() if k not in RESUMABLE}}


def _scene_identity(scene) -> tuple[dict, str]:
    """The scene as a checkpoint records it (without the fields a resumed run may change,
    :data:`RESUMABLE`) and the SHA-256 of its canonical JSON."""
    d = json.loads(json.dumps(_without_resumable(scene.to_dict()), default=_json))
    return d, hashlib.sha256(json.dumps(d, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


def _read_resume(scene, out: Path, any_version: bool) -> dict:
    """The checkpoint in ``out`` that ``scene`` may continue from, or a refusal naming
    the cause (see the module docstring); nothing in the file is run."""
    from cosim.clock import TICKS_PER_SECOND
    from cosim.version import __version__, code_version

    path = out / CHECKPOINT
    if not path.is_file():
        if (out / LEGACY_CHECKPOINT).is_file():
            raise CheckpointError(f"--resume: {out / LEGACY_CHECKPOINT} is a checkpoint of an older cosim, a Python "
                                  f"pickle, which cosim does not load (loading one runs whatever code it holds); run "
                                  f"the scene again without --resume")
        raise InputError(f"--resume: no checkpoint {path}; run without --resume first (a run writes one every "
                         f"world.checkpoint_wall s of wall time and at its end), or give the folder of that run")
    try:
        ck = checkpoint.read(path)
    except CheckpointError as e:
        raise CheckpointError(f"--resume: {e}") from None
    meta = ck.get("meta")
    if not isinstance(meta, dict) or meta.get("of") != "scene run" or not all(
            k in ck for k in ("scene", "state", "ledger", "probes")):
        raise CheckpointError(f"--resume: {path} is a checkpoint but not of a scene run (cosim run, Scene.run)")
    if meta.get("code_version") != code_version() and not any_version:
        raise CheckpointError(f"--resume: {path} was written by other code (cosim {meta.get('cosim_version')}, "
                              f"sources {meta.get('code_version')}; this is cosim {__version__} with other sources), "
                              f"which may not continue the run bit for bit; run the scene again without --resume, or "
                              f"continue anyway with --resume-any-version")
    mine, sha = _scene_identity(scene)
    if meta.get("scene_sha256") != sha:
        try:  # a checkpoint written before a field became resumable records it: compare without
            theirs = _without_resumable(json.loads(ck["scene"]))
        except (TypeError, ValueError, AttributeError):
            theirs = None
        if theirs != mine:
            raise SceneError(_first_difference(theirs, mine), "differs from the run being resumed; a resumed run "
                             "may change world.duration, world.checkpoint_wall and world.plot_at only")
    t, ticks = meta.get("t"), ck["state"].get("ticks") if isinstance(ck["state"], dict) else None
    where = checkpoint.first_not_finite({"t": t, "state": ck["state"], "ledger": ck["ledger"],
                                          "probes": ck["probes"]})
    if where is None and not (isinstance(t, float) and isinstance(ticks, int) and t >= 0
                              and abs(t - ticks / TICKS_PER_SECOND) <= 1e-9 * max(1.0, t)):
        where = f"t = {t!r} s against the clock's {ticks!r} ticks"
    if where is not None:
        raise CheckpointError(f"--resume: {path} holds a state no run reaches ({where}); it is corrupt or was not "
                              f"written by cosim; run the scene again without --resume")
    if scene.world.duration < t:
        raise SceneError("world.duration", f"{scene.world.duration} s is before the checkpoint at {t} s")
    return ck


def plot_checkpoint(out, png=None) -> Path:
    """Draw the particles of the run kept in the folder ``out`` as its checkpoint holds them
    (the latest state of a running, stopped or finished run: a run writes one every
    ``world.checkpoint_wall`` s of wall time and at its end), with the bodies, lines and
    gauges as the ``plot_at`` plots draw them, into ``png`` (default
    ``out/particles_checkpoint_tT.png``); returns the file. Reads the folder only: a run
    going on there is not disturbed (a checkpoint is replaced whole)."""
    from cosim.scene.spec import Scene
    from cosim.scene.build import build
    from cosim.scene.plots import plot_particles

    out = Path(out)
    for name in ("scene.toml", CHECKPOINT):
        if not (out / name).is_file():
            raise InputError(f"{out}: no {name}; give the folder of a run (cosim run --out) that has written its first "
                             f"checkpoint (every world.checkpoint_wall s of wall time, and at its end)")
    scene = Scene.from_toml(out / "scene.toml")
    if scene.fluid.model != "sph":
        raise InputError(f"{out}: the run's fluid is {scene.fluid.model!r}; only an SPH run has particles to draw")
    ck = _read_resume(scene, out, True)
    with tempfile.TemporaryDirectory(prefix="cosim-plot-") as work:
        built = build(scene, Path(work))
        try:
            _restore(ck, built, _Recorder(scene, built, out))
            t = float(ck["meta"]["t"])
            path = Path(png) if png is not None else out / f"particles_checkpoint_t{t:07.3f}.png"
            plot_particles(path, scene, built, t)
        finally:
            close_participants(built)
    return path


def kept_scene_difference(scene, out) -> str | None:
    """The first field (its key path) in which the run kept in the folder ``out`` (its
    ``scene.toml``) differs from ``scene``, the fields a resumed run may change
    (:data:`RESUMABLE`) not counted; None where they are one scene. A field added to the
    scenes since the run was kept counts at its default (the run had it so)."""
    import tomllib

    from cosim.scene.toml_io import from_dict, to_dict

    kept = tomllib.loads((Path(out) / "scene.toml").read_text(encoding="utf-8"))  # as the run wrote it: every field
    try:
        kept = to_dict(from_dict(kept))
    except Exception:  # a field since removed or renamed: compared as written
        pass
    kept = json.loads(json.dumps(_without_resumable(kept), default=_json))
    mine = _scene_identity(scene)[0]
    return None if kept == mine else _first_difference(kept, mine)


def _first_difference(a, b, prefix=""):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in list(a) + [k for k in b if k not in a]:
            if a.get(k) != b.get(k):
                return _first_difference(a.get(k), b.get(k), f"{prefix}.{k}" if prefix else k)
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            if x != y:
                return _first_difference(x, y, f"{prefix}[{i}]")
    return prefix


def _old_snapshots(path: Path, t_max: float):
    """The snapshots up to ``t_max`` [s] of the interrupted run's file, one at a time (a file
    the kill left unreadable gives none: the probe series come from the checkpoint)."""
    import h5py

    from fluid.output import read_snapshot

    try:
        with h5py.File(path, "r") as f:
            times = f["snapshot_times"][:]
    except (OSError, KeyError) as e:
        log.warning("resume: the snapshots of %s cannot be read (%s); the resumed file starts without them", path, e)
        return
    for k, t in enumerate(times):
        if t <= t_max + 1e-9:
            yield read_snapshot(path, k)


class _Checkpoints:
    """Writes the run's checkpoint (one file, replaced atomically): when the scene's
    events ask for one, and every ``world.checkpoint_wall`` s of wall time, that interval
    stretched to ``cost / CHECKPOINT_SHARE`` when a write takes longer."""

    def __init__(self, path: Path, scene, built, rec, wall_before: float, cpu_before: float, cpu0: float):
        from cosim.version import __version__, code_version

        self.path, self.built, self.rec = path, built, rec
        self.every = scene.world.checkpoint_wall
        self.wall_before, self.loop0, self.next = wall_before, time.perf_counter(), math.inf
        self.cpu_before, self.cpu0 = cpu_before, cpu0
        self.written, self.cost = 0, 0.0
        mine, sha = _scene_identity(scene)
        self.fixed = {"of": "scene run", "cosim_version": __version__, "code_version": code_version(),
                      "scene_sha256": sha}
        self.scene_json = json.dumps(mine, sort_keys=True)

    def start(self) -> float:
        """The run's loop starts now (returned): the first checkpoint by wall time is due
        ``world.checkpoint_wall`` from now."""
        self.loop0 = time.perf_counter()
        self.next = self.loop0 + self.every if self.every > 0 else math.inf
        return self.loop0

    def due(self) -> bool:
        return time.perf_counter() >= self.next

    def write(self) -> None:
        c, rec = self.built.coupler, self.rec
        t0 = time.perf_counter()
        rows = {g.name: rec.table(g) for g in rec.groups}
        checkpoint.write(self.path, {
            "meta": self.fixed | {"t": c.t, "steps": c.steps, "wall_s": self.wall_before + t0 - self.loop0,
                                  "cpu_s": self.cpu_before + time.process_time() - self.cpu0},
            "scene": self.scene_json, "state": c.save_state(), "ledger": c.ledger.arrays(),
            "probes": {"t": np.array(rec.times, float), "rows": rows}})
        done = time.perf_counter()
        self.written, self.cost = self.written + 1, self.cost + done - t0
        if self.every > 0:
            self.next = done + max(self.every, (done - t0) / CHECKPOINT_SHARE)


def _restore(ck: dict, built, rec) -> None:
    """The coupler, its ledger and the probe rows as the checkpoint holds them."""
    c = built.coupler
    rows = ck["probes"]["rows"]
    want = {g.name: len(g.columns) for g in rec.groups}
    have = {k: (v.shape[1] if getattr(v, "ndim", 0) == 2 else None) for k, v in rows.items()}
    times = np.asarray(ck["probes"]["t"], float)
    if have != want or any(len(v) != len(times) for v in rows.values()):
        raise CheckpointError(f"--resume: the checkpoint's probe groups {have} are not this run's {want}")
    try:
        c.load_state(ck["state"])
        c.ledger.restore(ck["ledger"])
    except (KeyError, IndexError, TypeError, ValueError) as e:  # only with --resume-any-version
        raise CheckpointError(f"--resume: the checkpoint's state does not fit this code's participants "
                              f"({type(e).__name__}: {e}); run the scene again without --resume") from None
    rec.times = times.tolist()
    rec.rows = {k: list(v) for k, v in rows.items()}


#: what a folder written by a run holds (one of them marks a folder that ``overwrite`` may clear)
RUN_FILES = ("summary.json", "scene.toml", "run.h5", CHECKPOINT)


def _check_empty(out: Path, overwrite: bool) -> None:
    """Refuse a folder that holds files unless the run may clear it (``overwrite``, and only
    a folder an earlier run wrote): a run's files beside another's would be taken for one."""
    if not out.is_dir():
        return
    held = sorted(p.name for p in out.iterdir())
    if not held:
        return
    some = ", ".join(held[:4]) + (f" and {len(held) - 4} more" if len(held) > 4 else "")
    if not overwrite:
        raise InputError(f"output folder {str(out)!r} is not empty ({some}): a run would leave the earlier files "
                         f"beside its own; give --overwrite (Scene.run(overwrite=True)) to clear it first, --resume "
                         f"to continue the run it holds, or another --out")
    if not any(name in held for name in RUN_FILES):
        raise InputError(f"--overwrite: output folder {str(out)!r} holds {some}, none of them a run's output "
                         f"({', '.join(RUN_FILES)}); it is not cleared: give a new or empty --out")


def _clear(out: Path) -> None:
    for p in out.iterdir():
        if p.is_dir() and not p.is_symlink():
            shutil.rmtree(p)
        else:
            p.unlink()


def run(scene, out, *, resume: bool = False, resume_any_version: bool = False, overwrite: bool = False,
        progress=None, yes: bool = False, ask=None) -> Results:
    """Run ``scene`` into the folder ``out``; see the module docstring. Before anything,
    its cost is estimated (:mod:`cosim.scene.cost`): a run beyond the machine's memory or
    disk is refused, one beyond a day of CPU unless ``yes`` or ``ask(question)`` says so."""
    from cosim.scene import cost
    from cosim.scene.build import build

    out = Path(out)
    _check_writable(out)
    if resume and overwrite:
        raise InputError("--resume continues the run in the output folder and --overwrite clears it: give one")
    if not resume:
        _check_empty(out, overwrite)
    ck = _read_resume(scene, out, resume_any_version) if resume else None
    est = cost.estimate(scene)
    cost.check(est, out, yes=yes, ask=ask)
    wall0, cpu0 = time.perf_counter(), time.process_time()
    with tempfile.TemporaryDirectory(prefix="cosim-build-") as work:
        # built before anything is written: a scene that the solvers refuse leaves no folder
        built = build(scene, Path(work))
        try:
            rec = _Recorder(scene, built, out)
            if ck is not None:
                _restore(ck, built, rec)
            if overwrite and out.is_dir():
                _clear(out)  # only now: a scene the solvers refuse leaves the earlier run whole
            out.mkdir(parents=True, exist_ok=True)
            for f in Path(work).iterdir():  # files the participants made (an exported FMU) go with the outputs
                shutil.copy2(f, out / f.name)
            return _run_built(scene, built, rec, out, ck, progress, wall0, cpu0, est)
        finally:
            close_participants(built)


def _run_built(scene, built, rec, out: Path, ck, progress, wall0: float, cpu0: float, est=None) -> Results:
    from cosim.progress import Progress

    build_s = time.perf_counter() - wall0
    c, sph = built.coupler, built.sph
    notices = []  # what the run left out of what the scene asked for (logged, and in summary.json's warnings)
    if scene.world.plot_at and sph is None:
        notices.append("world.plot_at: particle plots need the SPH fluid; this scene has none, so none are drawn")
    late = [t for t in scene.world.plot_at if t > scene.world.duration]
    if late and sph is not None:
        notices.append(f"world.plot_at: {', '.join(f'{t:g}' for t in late)} s lie beyond the run's end "
                       f"({scene.world.duration:g} s); not drawn")
    for n in notices:
        log.warning("%s", n)
    # the wall and CPU time of the segments before this one (a checkpoint of an older
    # version has no CPU time: 0)
    meta = ck["meta"] if ck is not None else {}
    t_start, wall_before, cpu_before = (meta.get("t", 0.0), float(meta.get("wall_s", 0.0)),
                                        float(meta.get("cpu_s", 0.0)))
    saver = _Checkpoints(out / CHECKPOINT, scene, built, rec, wall_before, cpu_before, cpu0)
    steps0, error, bar, loop0 = c.steps, None, None, None
    try:  # from the first file written on: whatever happens, the outputs so far are left whole
        if ck is not None:
            old = out / "run.h5.old"  # kept until the new file holds its snapshots (a kill here loses nothing)
            if not old.exists() and (out / "run.h5").exists():
                os.replace(out / "run.h5", old)
            rec.open(_old_snapshots(old, t_start) if old.exists() else ())
            old.unlink(missing_ok=True)
        else:
            for stale in (CHECKPOINT, CHECKPOINT + ".tmp", LEGACY_CHECKPOINT):  # an earlier run's, in this folder
                (out / stale).unlink(missing_ok=True)
            if sph is not None and scene.fluid.settle > 0:
                sph.settle(scene.fluid.settle)
            rec.open()
        scene.to_toml(out / "scene.toml")
        _write_sea(out, built)
        events = [(t, what) for t, what in _event_times(scene.world, sph is not None) if t > t_start + 0.5 * _TICK or
                  (ck is None and t == 0.0)]
        bar = Progress(t_start, scene.world.duration, enabled=progress)
        loop0 = saver.start()
        for t, what in events:
            if t > c.t:
                def between(info, t=t):  # a checkpoint between two events, never on one (its samples are due)
                    if saver.due() and c.clock.ticks_until(t) > 0:
                        saver.write()

                bar.update(t, c.run(t, between, progress=False))
            if "sample" in what:
                rec.sample(c.t)
            if "snapshot" in what:
                rec.snapshot(c.t)
            if "plot" in what and sph is not None:
                from cosim.scene.plots import plot_particles

                plot_particles(out / f"particles_t{c.t:07.3f}.png", scene, built, c.t)
            if "checkpoint" in what or saver.due():
                saver.write()
    except BaseException as e:
        error = e
        raise
    finally:
        if bar is not None:
            bar.close(c.t)
        rec.close()
        loop_s = 0.0 if loop0 is None else time.perf_counter() - loop0
        series, units = rec.series()
        summary = _summary(scene, built, series, units, c.steps - steps0, loop_s, build_s,
                           time.process_time() - cpu0, wall_before, cpu_before, ck is not None, error)
        summary["checkpoints"] = {"written": saver.written, "write_s": round(saver.cost, 3)}
        if est is not None:
            summary["estimate"] = est.as_dict()
        if notices:
            summary["warnings"] = summary.get("warnings", []) + notices
        _write_tables(out, rec, built)
        (out / "summary.json").write_text(json.dumps(summary, indent=1, default=_json))
        if series and rec.times:
            from cosim.scene.plots import plot_groups

            plot_groups(out, rec.times, rec.groups, {g.name: rec.table(g) for g in rec.groups}, scene)
    return Results(rec.times, series, units, summary, out)


def close_participants(built) -> None:
    """Release what the participants hold outside Python (an FMU's or MoorDyn's library)."""
    close = getattr(built.mooring, "close", None)
    if callable(close):
        try:
            close()
        except Exception as e:  # the run's own outcome matters more
            log.warning("closing mooring '%s' failed: %s", built.mooring.name, e)


def _json(o):
    if isinstance(o, np.generic):
        return o.item()
    if isinstance(o, (np.ndarray, tuple)):
        return list(o)
    return str(o)


def _summary(scene, built, series, units, steps, loop_s, build_s, cpu_s, wall_before, cpu_before, resumed, error):
    c = built.coupler
    s = {"scene": scene.name, "dim": scene.world.dim, "fluid": scene.fluid.model,
         "duration_s": scene.world.duration, "t_reached_s": c.t, "steps": c.steps, "steps_this_run": steps,
         "wall_s": round(loop_s + wall_before, 3), "build_s": round(build_s, 3),
         "cpu_s": round(cpu_s + cpu_before, 3), "cpu_s_this_run": round(cpu_s, 3), "resumed": resumed}
    if c.t > 0:
        s["wall_s_per_simulated_s"] = round((loop_s + wall_before) / c.t, 3)
    if hasattr(c, "scheme") and built.bodies is not None:
        s["scheme"], s["remedies"] = c.scheme, dict(c.remedies)
    s["coupling"] = c.step_summary()  # the steps taken and what set them (a participant, coupling.dt, an output time)
    if c.line_limit is not None:
        s["coupling"]["line_limit"] = {"dt_s": c.line_limit.dt, "why": c.line_limit.describe()}
    if built.setup is not None:
        s["setup"] = {"name": built.setup.name, "reason": built.setup.reason, "config": built.setup.config,
                      "overridden": list(built.setup.overridden)}
    if built.sph is not None:
        from fluid.particles import Kind

        ps = built.sph.simulated()
        s["particles"], s["fluid_particles"] = int(ps.n), int((ps.kind == Kind.FLUID).sum())
        s["speed_of_sound_m_s"] = built.sph.config.speed_of_sound
    if built.start_heights:
        s["floating_start_z_m"] = built.start_heights
    if built.warnings:
        s["warnings"] = list(built.warnings)
    if built.near_field is not None:  # the near field's box, as chosen, and why
        s["near_field"] = built.near_field.as_dict()
    if built.sph_domain is not None:  # a moving tank's SPH domain, and why
        s["sph_domain"] = built.sph_domain.as_dict()
    if built.wavemaker is not None:
        s["wavemaker"] = {"stroke_m": built.wavemaker.stroke, "wavelength_m": built.wavemaker.wavelength}
    sea = _incident_sea(built)
    if sea is not None:
        a = sea.components.amplitude
        s["sea"] = {"kind": type(sea).__name__, "peak_period_s": sea.peak_period, "wavelength_m": sea.wavelength,
                    "shortest_period_s": sea.shortest_period, "components": len(a)}
        if hasattr(sea, "repeat_period"):  # an irregular sea: its Hs (given) and its components' 4 sqrt(m0)
            s["sea"] |= {"hs_m": sea.hs, "hs_components_m": 4.0 * math.sqrt(float(np.sum(a * a)) / 2.0),
                         "repeat_period_s": sea.repeat_period}
        else:
            s["sea"]["height_m"] = sea.height
    left_out = getattr(built.fluid, "sea_left_out", None)
    if left_out:  # the potential fluid's: per body, the share of the sea's m0 outside its coefficients' trusted band
        s["sea_variance_left_out"] = dict(left_out)
    if built.mooring is not None:
        s["mooring"] = {"model": scene.moorings.model, "lines": built.line_names}
        if hasattr(built.mooring, "events"):  # lines with a break load (moorings.breaking)
            s["line_breaks"] = [e.as_dict() for e in built.mooring.events]
        log_ = getattr(built.mooring, "state_log", None)  # when lines go fully lifted, taut (moorings.line_events)
        if log_ is not None:
            s["line_events"] = dict(zip(built.line_names, log_.summary().values()))
    s["series"] = {k: {"unit": units[k], "min": float(v.min()), "max": float(v.max()), "mean": float(v.mean()),
                       "last": float(v[-1])} for k, v in series.items() if len(v)}
    if error is not None:
        s["error"] = f"{type(error).__name__}: {error}"
    return s


def _write_tables(out: Path, rec, built):
    t = np.asarray(rec.times)
    for g in rec.groups:
        a = rec.table(g)
        with open(out / f"{g.name}.csv", "w") as f:
            f.write("t [s]," + ",".join(f"{c} [{_header(u, g.categories)}]" for c, u in zip(g.columns, g.units)) + "\n")
            for k in range(len(t)):
                f.write(repr(float(t[k])) + "," + ",".join(repr(float(x)) for x in a[k]) + "\n")
    if built.coupler.ledger.body_names:
        built.coupler.ledger.write_csv(out / "ledger.csv")


def _incident_sea(built):
    """The incident sea (a ``fluid.waves.Sea``) of the analytic or potential fluid, or of
    the SPH fluid's near field; None."""
    from fluid.waves import Sea

    if built.sea is not None:
        return built.sea
    sea = getattr(built.fluid, "sea", None) if built.sph is None else None
    return sea if isinstance(sea, Sea) else None


def _write_sea(out: Path, built) -> None:
    """The incident sea's components and, for an irregular sea, its spectrum
    (``sea_components.csv``, ``sea_spectrum.png``)."""
    from fluid.waves import RecordedSea, SpectralSea

    sea = _incident_sea(built)
    if sea is None:
        return
    w, a, phase, k = sea.components
    cols = {"omega [rad/s]": w, "amplitude [m]": a, "phase [rad]": phase, "k [rad/m]": k}
    if isinstance(sea, SpectralSea):
        cols["S [m^2 s/rad]"] = sea.spectrum_at(w)
        cols["S_components [m^2 s/rad]"] = a * a / (2.0 * sea.d_omega)
    elif isinstance(sea, RecordedSea):
        cols["S_components [m^2 s/rad]"] = a * a / (2.0 * (2.0 * math.pi / sea.repeat_period))
    with open(out / "sea_components.csv", "w") as f:
        f.write(",".join(cols) + "\n")
        for row in zip(*cols.values()):
            f.write(",".join(repr(float(x)) for x in row) + "\n")
    if "S_components [m^2 s/rad]" not in cols:
        return
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 3.5), dpi=110)
    ax.plot(w, cols["S_components [m^2 s/rad]"], ".", ms=3, label="components, a² / 2Δω")
    if "S [m^2 s/rad]" in cols:
        fine = np.linspace(w[0], w[-1], 1000)
        ax.plot(fine, sea.spectrum_at(fine), "-", lw=1.2, label=f"target ({sea.spectrum})")
    ax.set_xlabel("ω [rad/s]")
    ax.set_ylabel("S [m² s/rad]")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "sea_spectrum.png")
    plt.close(fig)
