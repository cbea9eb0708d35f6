"""Kill safety: a run killed with SIGKILL leaves an HDF5 file that opens and holds whole
samples (a prefix of the uninterrupted run's), and ``cosim run --resume`` continues from
the last checkpoint to the uninterrupted run's results, bit for bit. Every run here loads
the kernels from numba's cache (the fixture fills it first): code numba has just compiled
and the same code loaded from its cache can part in the last bit (docs/checkpoints.md),
which is numba's, not the checkpoint's."""

import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from fluid.output import read_series

SCENE = """
name = "kill"
[world]
dim = 2
duration = 2.0
sample_every = 0.02
snapshot_every = 0.1
checkpoint_every = 0.2
[fluid]
model = "sph"
dx = 0.025
[domain]
kind = "tank"
length = 0.6
height = 0.5
depth = 0.3
[base_motion]
kind = "harmonic"
amplitude = 0.01
period = 0.8
[probes]
gauges = [0.05, 0.55]
energy = true
"""


def _cosim(*args, wait=True):
    cmd = [sys.executable, "-m", "cosim.cli", "run", *map(str, args), "--quiet"]
    if wait:
        return subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    return subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


@pytest.fixture(scope="module")
def whole(tmp_path_factory):
    d = tmp_path_factory.mktemp("kill")
    (d / "scene.toml").write_text(SCENE)
    (d / "warm.toml").write_text(SCENE.replace("duration = 2.0", "duration = 0.25"))
    out = _cosim(d / "warm.toml", "--out", d / "warm")  # fills numba's cache
    assert out.returncode == 0, out.stderr[-2000:]
    out = _cosim(d / "scene.toml", "--out", d / "whole")
    assert out.returncode == 0, out.stderr[-2000:]
    return d


@pytest.mark.long
@pytest.mark.parametrize("after_checkpoints, delay", [(1, 0.0), pytest.param(3, 0.13, marks=pytest.mark.long),
                                                      pytest.param(5, 0.29, marks=pytest.mark.long)])
def test_killed_run_reads_and_resumes_bit_for_bit(whole, after_checkpoints, delay, tmp_path):
    """Killed ``delay`` [s] of wall time after its n-th checkpoint: between two
    checkpoints, probably mid-step, possibly mid-write."""
    run = tmp_path / "run"
    p = _cosim(whole / "scene.toml", "--out", run, wait=False)
    ck = run / "checkpoint.h5"
    deadline = time.monotonic() + 300
    seen, last = 0, None
    while seen < after_checkpoints and p.poll() is None and time.monotonic() < deadline:
        if ck.exists() and ck.stat().st_mtime_ns != last:
            last, seen = ck.stat().st_mtime_ns, seen + 1
        time.sleep(0.005)
    time.sleep(delay)
    assert p.poll() is None, "the run ended before it could be killed; make it longer"
    p.send_signal(signal.SIGKILL)
    p.wait()
    ref = read_series(whole / "whole" / "run.h5", "probes/gauges")
    got = read_series(run / "run.h5", "probes/gauges")  # opens, whole rows only
    n = len(got["t"])
    assert n <= len(ref["t"])
    for k in got:
        np.testing.assert_array_equal(got[k], ref[k][:n], err_msg=k)  # a prefix of the uninterrupted run
    out = _cosim(whole / "scene.toml", "--out", run, "--resume")
    assert out.returncode == 0, out.stderr[-2000:]
    for name in ("probes/gauges", "probes/energy"):
        a, b = read_series(whole / "whole" / "run.h5", name), read_series(run / "run.h5", name)
        for k in a:
            np.testing.assert_array_equal(b[k], a[k], err_msg=f"{name}/{k}")
    for csv in ("gauges.csv", "energy.csv"):
        assert (run / csv).read_text() == (whole / "whole" / csv).read_text()
    import h5py

    with h5py.File(whole / "whole" / "run.h5") as f, h5py.File(run / "run.h5") as g:
        np.testing.assert_array_equal(f["snapshot_times"][:], g["snapshot_times"][:])
        last = f"snapshots/{len(f['snapshot_times']) - 1:04d}"
        np.testing.assert_array_equal(f[f"{last}/pos"][:], g[f"{last}/pos"][:])
    assert not (run / "run.h5.old").exists()
