"""Checkpoints are data (cosim.checkpoint): every participant's state comes back exactly,
nothing in a file is run (a pickle that would write a file writes nothing), a damaged or
foreign file is refused with its cause, a write cut short leaves the previous checkpoint,
and a run interrupted between two checkpoints resumes to the uninterrupted run's outputs
bit for bit. Runs leave no temporary folder and no MuJoCo log behind."""

import dataclasses
import json
import logging
import math
import os
import pickle
import signal
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

import h5py
import numpy as np
import pytest

from cosim import checkpoint
from cosim.checkpoint import CheckpointError
from cosim.errors import ProtocolError
from cosim.scene import Analytic, Box, Line, Moorings, Scene, World

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "moored_box_waves.toml"


def assert_same(a, b, path="state"):
    """``b`` is ``a``: the same types, keys in the same order, arrays of the same dtype,
    shape and bits."""
    assert type(a) is type(b), f"{path}: {type(a).__name__} became {type(b).__name__}"
    if isinstance(a, dict):
        assert list(a) == list(b), f"{path}: keys {list(a)} became {list(b)}"
        for k in a:
            assert_same(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, (list, tuple)):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            assert_same(x, y, f"{path}[{i}]")
    elif dataclasses.is_dataclass(a):
        for f in dataclasses.fields(a):
            assert_same(getattr(a, f.name), getattr(b, f.name), f"{path}.{f.name}")
    elif isinstance(a, (np.ndarray, np.generic)):
        assert a.dtype == b.dtype and np.shape(a) == np.shape(b), path
        assert np.asarray(a).tobytes() == np.asarray(b).tobytes(), path
    elif isinstance(a, float):
        assert a.hex() == b.hex(), path
    else:
        assert a == b, path


# ------------------------------------------------------------------------ the format
def test_every_kind_of_value_comes_back_exactly(tmp_path):
    from cosim.line_step import LineStepLimit

    content = {
        "ints": [0, -1, 2 ** 62, True, False], "floats": (0.1, -0.0, 5e-324, math.inf, -math.inf),
        "texts": ["", "box.left", "a,b/c\n\u03a9 \U0001f600"], "bytes": b"\x00\x80\xff", "none": None,
        "arrays": [np.arange(5, dtype=np.int8), np.zeros((0, 3)), np.array(2.5), np.ones((2, 3), np.float32),
                   np.array([True, False]), np.arange(4, dtype=np.uint16).reshape(2, 2)],
        "scalars": [np.float64(0.1), np.int64(-3), np.bool_(True)],
        "keys": {7: "an int key", "..": "dots", "a/b": "a slash", "~0": "a tilde", "": "empty"},
        "record": LineStepLimit(0.01, "spring", "m", "l", "b", 3.0, math.inf),
    }
    checkpoint.write(tmp_path / "c.h5", content)
    assert_same(content, checkpoint.read(tmp_path / "c.h5"), "content")
    assert not (tmp_path / "c.h5.tmp").exists()


def _analytic_scene(model, **line):
    """The analytic fluid, a box on two lines of the given model (cheap to build and step)."""
    w = 50.0  # N/m: MoorDyn wants it to agree with the mass and the buoyancy of the diameter
    kw = dict(length=25.0, weight=w, EA=1e8, mass_per_length=w / 9.81 + 1000.0 * math.pi * 0.1 ** 2 / 4,
              diameter=0.1) | line
    return Scene(name="ck", world=World(dim=2, duration=0.05, sample_every=0.01),
                 fluid=Analytic(linear_damping={"box": [800.0, 0.0, 1500.0, 0.0, 1500.0, 0.0]}),
                 bodies=[Box("box", size=(2.0, 1.0), pos=(3.0, 0.0), density=500.0,
                             fairleads={"left": (-1.0, -0.5), "right": (1.0, -0.5)})],
                 moorings=Moorings(model=model, lines=[Line("box.left", anchor=(-20.0, -10.0), **kw),
                                                      Line("box.right", anchor=(20.0, -10.0), **kw)]))


@pytest.mark.parametrize("model, line", [("catenary", {}), ("catenary", {"break_load": 1000.0}), ("sph-cable", {}),
                                         ("moordyn", {}), ("fmu", {})],
                         ids=["catenary", "breaking", "sph-cable", "moordyn", "fmu"])
def test_every_participants_state_comes_back_exactly(model, line, tmp_path):
    """The coupler's state (clock, bodies, fluid, each mooring model's lines, the watch,
    the step limits, breaks) through a file equals the state in memory."""
    if model == "moordyn":
        pytest.importorskip("moordyn")
    if model == "fmu":
        from conftest import HAVE_CC

        if not HAVE_CC:
            pytest.skip("no C compiler to build the FMU binary")
    from cosim.scene.build import build

    built = build(_analytic_scene(model, **line), tmp_path)
    try:
        c = built.coupler
        c.run(0.03)
        if line:
            assert built.mooring.events, "the lines did not break: the state holds no LineBreak"
        state = c.save_state()
        c.write_checkpoint(tmp_path / "c.h5")
        assert_same(state, checkpoint.read(tmp_path / "c.h5")["state"])
        c.run(0.05)
        after = c.save_state()
        c.read_checkpoint(tmp_path / "c.h5")
        c.run(0.05)
        assert_same(after, c.save_state())  # and the run goes on from it bit for bit
    finally:
        getattr(built.mooring, "close", lambda: None)()


def test_what_a_state_cannot_hold_is_refused_when_written(tmp_path):
    with pytest.raises(ProtocolError, match=r"checkpoint: /x/0 holds a .*Thing, which a checkpoint cannot hold"):
        checkpoint.write(tmp_path / "c.h5", {"x": [type("Thing", (), {})()]})
    with pytest.raises(ProtocolError, match="/a holds a numpy.ndarray of dtype object, which a checkpoint cannot"):
        checkpoint.write(tmp_path / "c.h5", {"a": np.array([object()])})
    assert not list(tmp_path.iterdir())  # nor a half-written file


class Pwn:
    """A pickle that, loaded, writes the file ``pwned`` (``open(path, "w")``)."""

    def __init__(self, path):
        self.path = str(path)

    def __reduce__(self):
        return (open, (self.path, "w"))


def test_a_pickle_is_never_loaded(tmp_path):
    """An attacker's pickle under the checkpoint's name, in the folder a user resumes:
    nothing runs and the refusal says why; the same under the old name checkpoint.pkl."""
    scene = _analytic_scene("catenary")
    for name in ("checkpoint.h5", "checkpoint.pkl"):
        out = tmp_path / name.replace(".", "_")
        out.mkdir()
        (out / name).write_bytes(pickle.dumps(Pwn(tmp_path / "pwned")))
        with pytest.raises(CheckpointError, match="pickle") as err:
            scene.run(out, resume=True, progress=False)
        assert "does not load" in str(err.value) and "runs whatever code it holds" in str(err.value)
        assert not (tmp_path / "pwned").exists()
        assert [p.name for p in out.iterdir()] == [name]  # nothing written
    with pytest.raises(CheckpointError, match="is a Python pickle, not a checkpoint"):
        checkpoint.read(tmp_path / "checkpoint_h5" / "checkpoint.h5")
    pickle.loads(pickle.dumps(Pwn(tmp_path / "pwned")))  # the pickle does what it says, when loaded
    assert (tmp_path / "pwned").exists()


def _flip(path, dataset):
    with h5py.File(path, "r") as f:
        at = f[dataset].id.get_offset()
    data = bytearray(path.read_bytes())
    data[at] ^= 1
    path.write_bytes(bytes(data))


def test_damaged_and_foreign_files_are_refused_with_their_cause(tmp_path):
    p = tmp_path / "c.h5"
    good = {"meta": {"t": 1.0}, "x": np.arange(10.0)}
    refusals = []

    def refused(match, make):
        checkpoint.write(p, good)
        make()
        with pytest.raises(CheckpointError, match=match) as err:
            checkpoint.read(p)
        refusals.append(str(err.value))

    refused("corrupt: its contents do not match their checksum", lambda: _flip(p, "x"))
    refused("truncated or corrupt", lambda: p.write_bytes(p.read_bytes()[:len(p.read_bytes()) // 2]))
    refused(r"not a checkpoint \(not an HDF5 file\)", lambda: p.write_text("t = 1.0\n"))

    def edit(fn):
        def make():
            with h5py.File(p, "r+") as f:
                fn(f)
        return make

    refused("an HDF5 file but not a cosim checkpoint", edit(lambda f: f.attrs.__setitem__("format", "other")))
    refused("format version 2; this cosim reads version 1", edit(lambda f: f.attrs.__setitem__("format_version", 2)))
    refused("/meta/t is of kind 'int' but stored as float64", edit(lambda f: f["meta/t"].attrs.__setitem__("kind", "int")))
    refused(r"/evil names the class 'os.system', which a checkpoint may not hold",
            edit(lambda f: f.create_group("evil").attrs.update({"kind": "object", "class": "os.system"})))
    refused(r"/x is stored with filters", edit(lambda f: (f.__delitem__("x"), f.create_dataset(
        "x", data=np.arange(10.0), compression="gzip").attrs.__setitem__("kind", "array"))))
    refused(r"/y is a link", edit(lambda f: f.__setitem__("y", h5py.ExternalLink("/etc/passwd", "/"))))
    refused(r"/x has the type", edit(lambda f: (f.__delitem__("x"), f.create_dataset(
        "x", data=np.array([b"ab"], dtype=object), dtype=h5py.string_dtype()).attrs.__setitem__("kind", "array"))))
    assert all(str(p) in r for r in refusals)


def test_a_write_cut_short_leaves_the_previous_checkpoint(tmp_path, monkeypatch):
    p = tmp_path / "c.h5"
    checkpoint.write(p, {"t": 1.0})

    def killed(*a):
        raise KeyboardInterrupt

    monkeypatch.setattr(checkpoint.os, "replace", killed)
    with pytest.raises(KeyboardInterrupt):
        checkpoint.write(p, {"t": 2.0})
    assert checkpoint.read(p) == {"t": 1.0}
    assert [x.name for x in tmp_path.iterdir()] == ["c.h5"]


def test_values_no_run_reaches_are_found():
    assert checkpoint.first_not_finite({"t": 0.5, "a": [np.ones(3), -math.inf], "b": {"t_off": math.inf}}) is None
    assert checkpoint.first_not_finite({"meta": {"t": math.inf}}) == "meta.t = inf"
    assert checkpoint.first_not_finite({"s": (1.0, math.nan)}) == "s[1] = nan"
    assert checkpoint.first_not_finite({"pos": np.array([[0.0, 1.0], [np.inf, 2.0]])}) == "pos[1, 0] = inf"


def test_a_coupler_checkpoint_of_other_code_or_with_a_nan_is_refused(tmp_path):
    from cosim.scene.build import build

    c = build(_analytic_scene("catenary"), tmp_path).coupler
    c.run(0.02)
    p = tmp_path / "c.h5"
    c.write_checkpoint(p)
    ck = checkpoint.read(p)
    ck["meta"]["code_version"] = "0" * 16
    checkpoint.write(p, ck)
    with pytest.raises(CheckpointError, match="was written by other code"):
        c.read_checkpoint(p)
    c.read_checkpoint(p, any_version=True)
    ck["state"]["participants"]["bodies"][3] = math.nan
    checkpoint.write(p, ck)
    with pytest.raises(CheckpointError, match=r"holds a state no run reaches \(state.participants.bodies\[3\] = nan\)"):
        c.read_checkpoint(p, any_version=True)


# ------------------------------------------------------------------------ runs
def _short(duration, *more):
    """The README's main example, shortened."""
    return Scene.from_toml(EXAMPLE).with_values([f"world.duration={duration}", "world.plot_at=[]", *more])


def _same_outputs(a: Path, b: Path):
    """Every CSV byte for byte, every dataset of run.h5 bit for bit."""
    names = sorted(p.name for p in a.glob("*.csv"))
    assert names and names == sorted(p.name for p in b.glob("*.csv"))
    for n in names:
        assert (a / n).read_bytes() == (b / n).read_bytes(), n
    with h5py.File(a / "run.h5", "r") as f, h5py.File(b / "run.h5", "r") as g:
        seen = []

        def same(name, obj):
            if isinstance(obj, h5py.Dataset):
                seen.append(name)
                assert g[name].dtype == obj.dtype and g[name][()].tobytes() == obj[()].tobytes(), name

        f.visititems(same)
        assert "snapshot_times" in seen and any(n.startswith("series/ledger") for n in seen)


@pytest.mark.long
@pytest.mark.parametrize("fluid_steps", [1, 4])
def test_a_run_interrupted_between_checkpoints_resumes_bit_for_bit(fluid_steps, tmp_path, monkeypatch):
    """The main example, interrupted mid-step far from any event with checkpoints written
    by wall time, resumes to the outputs of the run never interrupted (and never
    checkpointed) exactly, exchanging every step or every fourth fluid step
    (``coupling.fluid_steps``); by default a run writes its last state."""
    from cosim.coupler import Coupler

    whole = _short(0.1, "world.checkpoint_wall=0", f"coupling.fluid_steps={fluid_steps}").run(
        tmp_path / "whole", progress=False)
    assert whole.summary["checkpoints"]["written"] == 0 and not (tmp_path / "whole" / "checkpoint.h5").exists()
    from cosim.scene import runner

    share = runner.CHECKPOINT_SHARE
    monkeypatch.setattr(runner, "CHECKPOINT_SHARE", 1.0)  # writing may take all the time
    # a clock that ticks a second at every reading: a checkpoint is due at every step whatever
    # the machine's speed (by the real clock, which steps get one depended on it)
    ticks = iter(range(10 ** 9))
    monkeypatch.setattr(runner, "time", SimpleNamespace(perf_counter=lambda: float(next(ticks)),
                                                        process_time=time.process_time, time=time.time))
    scene = _short(0.1, "world.checkpoint_wall=1e-6", f"coupling.fluid_steps={fluid_steps}")
    step, n = Coupler.step, {"steps": 0}

    def interrupted(self, *a, **k):
        n["steps"] += 1
        if n["steps"] == 61 // fluid_steps:
            raise KeyboardInterrupt
        return step(self, *a, **k)

    monkeypatch.setattr(Coupler, "step", interrupted)
    with pytest.raises(KeyboardInterrupt):
        scene.run(tmp_path / "split", progress=False)
    monkeypatch.setattr(Coupler, "step", step)
    t = checkpoint.read(tmp_path / "split" / "checkpoint.h5")["meta"]["t"]
    assert 0 < t < 0.1 and round(t / 0.01) * 0.01 != pytest.approx(t, abs=1e-9)  # between two samples
    monkeypatch.setattr(runner, "CHECKPOINT_SHARE", share)  # the resumed part need not write at every step
    monkeypatch.setattr(runner, "time", time)
    resumed = scene.run(tmp_path / "split", resume=True, progress=False)
    assert resumed.summary["resumed"] and resumed.summary["steps"] == whole.summary["steps"]
    _same_outputs(tmp_path / "whole", tmp_path / "split")
    # on by default: the last state, from which a longer run continues
    default = _short(0.02).run(tmp_path / "default", progress=False)
    assert default.summary["checkpoints"]["written"] == 1
    assert checkpoint.read(tmp_path / "default" / "checkpoint.h5")["meta"]["t"] == 0.02


def _env(tmpdir: Path) -> dict:
    return dict(os.environ, TMPDIR=str(tmpdir),
                PYTHONPATH=os.pathsep.join([str(ROOT)] + [x for x in [os.environ.get("PYTHONPATH")] if x]))


@pytest.mark.long
@pytest.mark.parametrize("model", ["fmu", "moordyn"])
def test_runs_leave_no_temporary_folder(model, tmp_path):
    """A run stopped by SIGTERM mid-run and a run refused while it is built leave nothing
    in the temporary folder (the build's folder, an exported and unpacked FMU, MoorDyn's
    input files) and nothing but the output folder in the working folder."""
    if model == "moordyn":
        pytest.importorskip("moordyn")
    from conftest import HAVE_CC

    if model == "fmu" and not HAVE_CC:
        pytest.skip("no C compiler to build the FMU binary")
    tmp, cwd = tmp_path / "tmp", tmp_path / "cwd"
    tmp.mkdir()
    cwd.mkdir()
    (cwd / "scene.toml").write_text(_analytic_scene(model).replace(world=World(dim=2, duration=1e4)).to_toml())
    cmd = [sys.executable, "-m", "cosim.cli", "run", "scene.toml", "--out", "out", "--quiet"]
    p = subprocess.Popen(cmd, cwd=cwd, env=_env(tmp), stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while not (cwd / "out" / "run.h5").exists() and p.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    time.sleep(0.5)
    p.send_signal(signal.SIGTERM)
    err = p.communicate(timeout=120)[1]
    assert p.returncode == 128 + signal.SIGTERM, err
    assert err.strip().splitlines()[-1] == "cosim run: interrupted (SIGTERM)"
    assert (cwd / "out" / "summary.json").is_file(), (err, sorted(x.name for x in (cwd / "out").iterdir()))
    assert json.loads((cwd / "out" / "summary.json").read_text())["error"] == "Terminated: signal 15"
    refused = subprocess.run(cmd[:-3] + ["--out", "out2", "--set", "bodies[0].density=5000", "--set",
                                         "bodies[0].place=\"floating\"", "--set", "bodies[0].pos=[3.0]"],
                             cwd=cwd, env=_env(tmp), capture_output=True, text=True, timeout=120)
    assert refused.returncode == 2 and "sinks" in refused.stderr, refused.stderr  # refused while it is built
    assert not list(tmp.iterdir())
    assert sorted(x.name for x in cwd.iterdir()) == ["out", "scene.toml"]


def test_mujoco_warnings_go_to_the_log_not_to_a_file(tmp_path, monkeypatch, caplog):
    """An unstable body: MuJoCo's warning is logged, and no MUJOCO_LOG.TXT appears in the
    working folder."""
    import mujoco

    from bodies.mujoco_bodies import MujocoBodies

    monkeypatch.chdir(tmp_path)
    b = MujocoBodies("<mujoco><worldbody><body name='b'><freejoint/><geom size='0.1'/></body></worldbody></mujoco>")
    b.data.qvel[:] = math.nan
    with caplog.at_level(logging.WARNING, logger="bodies.mujoco_bodies"):
        mujoco.mj_step(b.model, b.data)
    assert any("MuJoCo: Nan, Inf or huge value in QVEL" in r.getMessage() for r in caplog.records)
    assert not list(tmp_path.iterdir())


def _cosim_run(*args, wait=True):
    cmd = [sys.executable, "-m", "cosim.cli", "run", str(EXAMPLE), "--set", "world.duration=0.4", "--set",
           "world.plot_at=[]", "--set", "world.checkpoint_wall=0.2", "--quiet", *map(str, args)]
    if wait:
        return subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    return subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


@pytest.fixture(scope="module")
def whole_example(tmp_path_factory):
    out = tmp_path_factory.mktemp("example") / "whole"
    r = _cosim_run("--out", out)
    assert r.returncode == 0, r.stderr[-2000:]
    return out


@pytest.mark.slow
@pytest.mark.parametrize("moment", ["just after the first checkpoint", "between the second and third",
                                    "while a checkpoint is written"])
def test_the_main_example_killed_by_sigkill_resumes_bit_for_bit(whole_example, moment, tmp_path):
    """``cosim run`` of the README's example (0.4 s, checkpoints by wall time only) killed
    with SIGKILL, then ``cosim run --resume``: the outputs of the uninterrupted run, bit
    for bit."""
    out = tmp_path / "run"
    p = _cosim_run("--out", out, wait=False)
    ck, tmp = out / "checkpoint.h5", out / "checkpoint.h5.tmp"
    seen, last, deadline = 0, None, time.monotonic() + 300
    while p.poll() is None and time.monotonic() < deadline:
        if ck.exists() and ck.stat().st_mtime_ns != last:
            last, seen = ck.stat().st_mtime_ns, seen + 1
        if (moment.startswith("just") and seen == 1) or (moment.startswith("between") and seen == 2) \
                or (moment.startswith("while") and seen >= 1 and tmp.exists()):
            break
        time.sleep(0.001)
    if moment.startswith("between"):
        time.sleep(0.3)
    assert p.poll() is None, "the run ended before it could be killed; make it longer"
    p.send_signal(signal.SIGKILL)
    p.wait()
    r = _cosim_run("--out", out, "--resume")
    assert r.returncode == 0, r.stderr[-2000:]
    assert json.loads((out / "summary.json").read_text())["resumed"]
    _same_outputs(whole_example, out)
    assert not tmp.exists() and not (out / "run.h5.old").exists()


def test_two_runs_of_a_scene_write_the_same_checkpoint(tmp_path):
    """Byte for byte but for the wall and CPU seconds: the SPH fluid's cell-list workspace
    (its sub-bin table, saved with the rates) starts zeroed, so that no byte of a
    checkpoint is whatever memory held."""
    scene = Scene.from_toml(Path(__file__).parents[1] / "examples" / "sloshing_tank.toml").with_values(
        ["world.duration=0.05", "world.checkpoint_every=0.05", "world.checkpoint_wall=0.0"])
    files = [scene.run(tmp_path / f"run{i}", progress=False).out / "checkpoint.h5" for i in (1, 2)]

    def datasets(path):
        out = {}
        with h5py.File(path) as f:
            f.visititems(lambda k, v: out.__setitem__(k, v[()]) if isinstance(v, h5py.Dataset) else None)
        return out

    a, b = (datasets(f) for f in files)
    assert a.keys() == b.keys() and any("rates" in k for k in a)
    differ = [k for k in a if not np.array_equal(a[k], b[k], equal_nan=np.asarray(a[k]).dtype.kind in "fc")]
    assert sorted(differ) == ["meta/cpu_s", "meta/wall_s"], differ
