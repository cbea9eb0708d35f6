"""A validation case's scene: its file ``scenes/CASE.toml`` (:data:`~cosim.validations.folders.SCENES`)
loaded with a variant's values set, and built into its participants as ``cosim run`` builds them.

A case is a scene plus a reference and a metric (docs/DESIGN.md, "Scenes"). Where the case's
metric needs more than the scene's probes record (every particle's pressure, a body's state
at every coupling step), the case builds the scene here and steps its coupler itself: the
set-up is the scene's, field for field, so that the case and a user's ``cosim run
cosim/validations/scenes/CASE.toml`` run the same water, walls, bodies and lines; what is
read differs, and where the steps fall (the runner lands a step on each sample time).

Under :func:`auto_setup` a case runs the fluid set-up that ``cosim.scene.setup`` chooses for
its scene (``fluid.setup = "auto"``, the set-up's own fields cleared) instead of the one set
by hand: a scene-built case through :func:`load`, a code-built one through :func:`fluid_setup`
(tests/test_setup_chooser.py: each case so meets its quick tolerance).
"""

from __future__ import annotations

import contextvars
import dataclasses
import logging
import os
import tempfile
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path

from cosim.validations.folders import SCENES

log = logging.getLogger(__name__)

#: whether the cases run the chooser's set-up (set by :func:`auto_setup`; a context variable, so
#: that a thread or task that did not enter it is not affected)
_auto = contextvars.ContextVar("auto_setup", default=False)


@contextmanager
def auto_setup() -> Iterator[None]:
    """Within it, the cases run the set-up the chooser picks for their scenes (module
    docstring)."""
    token = _auto.set(True)
    try:
        yield
    finally:
        _auto.reset(token)


def chosen(scene):
    """``scene`` with ``fluid.setup = "auto"`` and the settings a set-up chooses cleared
    (``cosim.scene.setup.chosen_settings``; the others a scene sets, dx, c0 or c0_factor,
    settle, are its own; a fluid without a set-up, the analytic one, as it is)."""
    from cosim.scene.setup import chosen_settings

    if not hasattr(scene.fluid, "setup"):
        return scene
    fluid = dataclasses.replace(scene.fluid, setup="auto", **{k: None for k in chosen_settings()})
    return dataclasses.replace(scene, fluid=fluid)


def fluid_setup(case: str, own: dict) -> dict:
    """The FluidConfig set-up of a case that builds its fluid in code: ``own``, the
    settings it sets by hand; under :func:`auto_setup`, the settings a set-up chooses
    (``cosim.scene.setup.chosen_settings``) as ``cosim.scene.setup.choose`` gives them to
    the case's scene file."""
    if not _auto.get():
        return dict(own)
    from cosim.scene.setup import choose, chosen_settings

    cfg = choose(load(case)).config
    return {k: cfg[k] for k in chosen_settings() if k in cfg}


def path(case: str) -> Path:
    """The scene file of ``case``: ``scenes/CASE.toml``."""
    return SCENES / f"{case}.toml"


def number(x: float) -> str:
    """A value for :func:`load`'s ``values``, to 12 decimals: the number a scene file writes
    (a wall ``0.1 + 0.05 + 3 * 0.0125`` m high is 0.1875, not its binary neighbour
    0.18750000000000003), so that a variant whose values the file holds is the file's scene,
    equal field for field."""
    return repr(round(float(x), 12))


def settings(part: str, values: dict) -> list[str]:
    """``values`` ({field: value}) as :func:`load`'s assignments to the fields of ``part``
    (e.g. ``"fluid"``): numbers as :func:`number` writes them, the rest as TOML writes them
    (:func:`cosim.scene.toml_io.toml_value`; ``{"alpha": 0.05, "diffusion": "none"}`` ->
    ``["fluid.alpha=0.05", 'fluid.diffusion="none"']``)."""
    from cosim.scene.toml_io import toml_value

    return [f"{part}.{k}={number(v) if isinstance(v, float) else toml_value(v)}" for k, v in values.items()]


def load(case: str, values: Sequence[str] = ()):
    """The scene of ``case`` with ``values`` set (``KEY=VALUE`` as ``cosim run --set`` takes
    them, e.g. ``"fluid.dx=0.01"``): a :class:`cosim.scene.Scene`, validated (under
    :func:`auto_setup`: with the chooser's set-up)."""
    from cosim.scene import Scene

    scene = Scene.from_toml(path(case))
    scene = scene.with_values(list(values)) if values else scene
    return chosen(scene) if _auto.get() else scene


@contextmanager
def built(scene) -> Iterator:
    """The participants and coupler of ``scene`` (:class:`cosim.scene.build.Built`),
    initialised at t = 0 as :meth:`Scene.run` builds them; files a participant makes go
    into a temporary folder, removed on leaving, and a mooring holding a library (an FMU,
    MoorDyn) is closed."""
    from cosim.scene.build import build
    from cosim.scene.runner import close_participants

    with tempfile.TemporaryDirectory(prefix="cosim-case-") as work:
        b = build(scene, Path(work))
        try:
            yield b
        finally:
            close_participants(b)


def run_once(scene):
    """``scene`` run by ``cosim run``'s runner (no progress line) in a temporary folder,
    removed after: its results (:class:`cosim.scene.runner.RunResults`, held in memory)."""
    with tempfile.TemporaryDirectory(prefix="cosim-case-") as tmp:
        return scene.run(Path(tmp) / "run", progress=False)


def kept_runs(case: str, quick: bool) -> Path:
    """Where a case keeps the runs it resumes between sessions (:func:`run_or_resume`):
    ``$COSIM_CASE_RUNS/CASE/quick`` or ``/full`` (default ``out/case-runs``)."""
    root = Path(os.environ.get("COSIM_CASE_RUNS", "out/case-runs"))
    return root / case / ("quick" if quick else "full")


def runs_of_other_code(runs: dict) -> dict:
    """Of ``runs`` (name -> results of :func:`run_or_resume`), those read back that other code
    made, name -> that code's version: their figures are that code's, not these sources'."""
    return {k: r.summary["read_back_other_code"] for k, r in runs.items() if r.summary.get("read_back_other_code")}


def run_or_resume(scene, out: Path, progress=None):
    """``(results, earlier_cpu_s)`` of ``scene`` in the folder ``out``: read back if a run of
    it there has finished (a run of another scene there is refused), resumed from its
    checkpoint if one stopped (written by any version of the code: it may then not continue
    bit for bit, which its summary's ``resumed`` says), else run from the start, with the
    runner's ``progress`` line (None: redrawn on a terminal, else a whole line a minute).
    ``earlier_cpu_s`` [s]: the CPU the run recorded in earlier processes (all of it when read
    back, the earlier segments' when resumed), which the case's own CPU does not count. A
    run read back that other code made (its checkpoint's ``code_version``) is warned of and
    its ``summary["read_back_other_code"]`` names that code: its figures are that code's."""
    import json

    from cosim import checkpoint
    from cosim.checkpoint import CheckpointError
    from cosim.errors import InputError
    from cosim.scene.runner import CHECKPOINT, kept_scene_difference, read
    from cosim.version import code_version

    done = out / "summary.json"
    if done.is_file():
        other = kept_scene_difference(scene, out)
        if other is not None:
            raise InputError(f"{out} holds a run of another scene ({other} differs); move it away, or point "
                             f"COSIM_CASE_RUNS elsewhere")
        s = json.loads(done.read_text())
        if s.get("t_reached_s", 0.0) >= scene.world.duration - 1e-9 and not s.get("error"):
            res = read(out)
            try:
                made_by = checkpoint.read(out / CHECKPOINT)["meta"]["code_version"]
            except (OSError, KeyError, CheckpointError):
                made_by = None
            if made_by is not None and made_by != code_version():
                log.warning("%s: read back a finished run made by other code (sources %s, these %s); move the "
                            "folder away to measure this code", out, made_by, code_version())
                res.summary["read_back_other_code"] = made_by
            return res, float(res.summary.get("cpu_s") or 0.0)
    if (out / CHECKPOINT).is_file():
        res = scene.run(out, resume=True, resume_any_version=True, progress=progress, yes=True)
    else:
        res = scene.run(out, overwrite=True, progress=progress, yes=True)
    s = res.summary
    return res, float(s.get("cpu_s") or 0.0) - float(s.get("cpu_s_this_run") or 0.0)


def shaken_samples(scene) -> tuple[int, int]:
    """(samples a period, whole periods run) of a scene whose base is shaken harmonically:
    its ``world.sample_every`` and ``world.duration`` in periods of its ``base_motion``."""
    period = scene.base_motion.period
    return round(period / scene.world.sample_every), round(scene.world.duration / period)


def section(scene):
    """The 2-D section of a shaken 3-D tank ``scene`` (its domain's ``width`` along y): the
    same tank, shaking, fluid and run in the x-z plane, its pressure patches taken from
    their plane y = const to the section."""
    from cosim.scene.toml_io import from_dict, to_dict

    d = to_dict(scene)
    d["world"]["dim"] = 2
    del d["domain"]["width"]
    d["base_motion"]["direction"] = d["base_motion"]["direction"][::2]
    for p in d.get("probes", {}).get("pressure", []):
        p["centre"], p["normal"] = p["centre"][::2], p["normal"][::2]
    return from_dict(d)
