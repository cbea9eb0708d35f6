"""fluid.run: probes sampled at exact times into the output and the returned arrays, a
progress bar only on request or on a terminal, a readable file after an instability."""

import io
import math

import h5py
import numpy as np
import pytest

from cosim.errors import InputError, InstabilityError
from fluid.geometry import set_hydrostatic, tank_with_water
from fluid.output import read_series, read_snapshot
from fluid.probes import Energy, PressureProbe, WaveGauge
from fluid.progress import Progress
from fluid.run import run
from fluid.solver import Fluid, FluidConfig

G, RHO0, H, DX = 9.81, 1000.0, 0.1, 0.02


def _tank():
    b = tank_with_water(2, DX, 0.2, H, 1.25 * H)
    cfg = FluidConfig(dim=2, dx=DX, u_max=math.sqrt(G * H), c0_factor=20.0, threads=1)
    set_hydrostatic(b.particles, H, RHO0, cfg.speed_of_sound, cfg.gamma, G)
    return Fluid(cfg, b.particles)


def _probes():
    return [PressureProbe([[0.0, H - 0.05]], name="wall"), WaveGauge([0.1]), Energy()]


def test_samples_at_exact_times_into_the_file_and_the_arrays(tmp_path, capsys):
    f = _tank()
    path = tmp_path / "tank.h5"
    out = run(f, 0.05, probes=_probes(), sample_every=0.01, output=path, snapshot_every=0.025,
              attrs={"dx": DX})
    t = 0.01 * np.arange(6)
    for name in ("wall", "gauges", "energy"):
        np.testing.assert_array_equal(out[name]["t"], t)
        np.testing.assert_array_equal(read_series(path, name)["t"], t)
    np.testing.assert_array_equal(read_series(path, "wall")["p"], out["wall"]["p"])
    assert out["wall"]["p"].shape == (6, 1) and out["gauges"]["eta"].shape == (6, 1)
    # the tank stays at rest: wall pressure rho g d (within the start's acoustic ringing,
    # 3 % at 5 layers), surface at H, kinetic energy tiny
    np.testing.assert_allclose(out["wall"]["p"][:, 0], RHO0 * G * 0.05, rtol=0.05)
    assert np.abs(out["gauges"]["eta"] - H).max() < DX / 2
    assert out["energy"]["kinetic"].max() < 1e-4 * out["energy"]["potential"][0]
    assert f.t == pytest.approx(0.05, abs=1e-12) and f.counters.steps > 50
    with h5py.File(path) as h5:
        np.testing.assert_array_equal(h5["snapshot_times"][()], [0.0, 0.025, 0.05])
        assert h5.attrs["dx"] == DX
    snap = read_snapshot(path, 2)
    assert set(snap) >= {"t", "pos", "vel", "rho", "p", "kind", "ids"} and snap["pos"].shape == f.ps.pos.shape
    assert capsys.readouterr().err == ""  # no terminal under pytest: quiet


def test_progress_bar_is_shown_when_asked(tmp_path):
    f = _tank()
    buf = io.StringIO()
    bar = Progress(0.0, 0.01, stream=buf, enabled=True, every_s=0.0)
    run(f, 0.01, progress=bar)
    text = buf.getvalue()
    assert "t = 0.01 / 0.01 s (100.0 %)" in text and "steps/s" in text and text.endswith("\n")
    assert bar.steps == f.counters.steps
    assert not Progress(0.0, 1.0, stream=io.StringIO()).enabled  # a StringIO is no terminal


class _Saboteur:
    """A probe that poisons one particle at its third sample (a blow-up, on cue)."""

    name, columns = "saboteur", ("n",)

    def __init__(self):
        self.n = 0

    def sample(self, fluid):
        self.n += 1
        if self.n == 3:
            fluid.ps.vel[0, 0] = np.nan
        return {"n": float(self.n)}


def test_instability_leaves_a_readable_file_with_the_data_so_far(tmp_path):
    f = _tank()
    path = tmp_path / "blowup.h5"
    with pytest.raises(InstabilityError, match="non-finite") as err:
        run(f, 0.05, probes=[Energy(), _Saboteur()], sample_every=0.005, output=path, snapshot_every=0.005)
    s = read_series(path, "saboteur")
    np.testing.assert_array_equal(s["t"], [0.0, 0.005, 0.01])
    np.testing.assert_array_equal(s["n"], [1.0, 2.0, 3.0])
    assert read_series(path, "energy")["t"].size == 3
    np.testing.assert_array_equal(err.value.samples["saboteur"]["t"], s["t"])
    assert read_snapshot(path, 2)["t"] == 0.01


def test_bad_run_input_is_refused(tmp_path):
    f = _tank()
    with pytest.raises(InputError, match="t_end"):
        run(f, -1.0)
    with pytest.raises(InputError, match="sample_every"):
        run(f, 0.1, sample_every=0.0)
    with pytest.raises(InputError, match="needs an output"):
        run(f, 0.1, snapshot_every=0.01)
    with pytest.raises(InputError, match="repeat"):
        run(f, 0.1, probes=[Energy(), Energy()])
    from fluid.output import H5Output

    with pytest.raises(InputError, match="dim=2"), H5Output(tmp_path / "y.h5", dim=3) as out:
        run(f, 0.1, output=out)
    with pytest.raises(InputError, match="snapshot field"):
        run(f, 0.1, output=tmp_path / "x.h5", snapshot_fields=("nope",))
