"""cosim.recorder: a coupled run written to one HDF5 file agrees with the coupler's own
state and ledger, with SPH snapshots when the fluid has particles."""

import math

import h5py
import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.errors import InputError
from cosim.ledger import FIELDS
from cosim.recorder import RunRecorder, record_run
from cosim.sph_fluid import SPHFluid
from fluid.analytic import AnalyticFluid
from fluid.geometry import block, tank_walls
from fluid.output import H5Output, read_series, read_snapshot
from fluid.particles import Kind
from fluid.probes import Energy, WaveGauge
from fluid.solver import FluidConfig
from moorings import CatenaryMooring, MooringLine


def moored_box():
    sites = {"fl_left": (-1.0, 0.0, -0.5), "fl_right": (1.0, 0.0, -0.5)}
    box = builders.box("box", (2.0, 1.0), (1.0, 0.0, 0.0), density=500.0, planar=True, sites=sites)
    bodies = MujocoBodies(builders.scene(box, timestep=2e-3))
    fluid = AnalyticFluid(rho=1025.0, linear_damping={"box": [800.0, 0.0, 1500.0, 0.0, 1500.0, 0.0]})
    lines = [MooringLine((x, -10.0), length=25.0, weight=50.0, EA=5e7, name=n)
             for x, n in ((-20.0, "left"), (20.0, "right"))]
    mooring = CatenaryMooring(lines)
    return Coupler(bodies=bodies, fluid=fluid, moorings=[(mooring, list(sites))], dt=0.01), mooring


def test_moored_box_run_is_recorded(tmp_path):
    c, mooring = moored_box()
    path = tmp_path / "moored.h5"
    steps = record_run(c, 0.5, path, sample_every=0.1, attrs={"case": "moored box"})
    assert steps == 50
    b = read_series(path, "bodies/box")
    np.testing.assert_allclose(b["t"], 0.1 * np.arange(6), atol=1e-9)
    kin = c.bodies.kinematics()
    np.testing.assert_array_equal(b["com"][-1], kin.com[0])
    np.testing.assert_array_equal(b["rotation"][-1], kin.rotation[0].ravel())
    assert b["com"][0, 0] == pytest.approx(1.0) and b["com"][-1, 0] < 1.0  # pulled back towards 0
    m = read_series(path, "moorings/" + mooring.name)
    f = mooring.fairlead_forces()
    np.testing.assert_array_equal(m["fairlead_force"][-1], f.ravel())
    np.testing.assert_allclose(m["tension"][-1], np.linalg.norm(f, axis=1), rtol=1e-15)
    led = c.ledger.arrays()
    s = read_series(path, "ledger/box")
    np.testing.assert_array_equal(s["t"], led["t"])
    for k in FIELDS:
        np.testing.assert_array_equal(s[k], led[k][:, 0])
    with h5py.File(path) as h5:
        assert h5.attrs["case"] == "moored box"


def test_sph_run_writes_snapshots_probes_and_a_readable_file_on_error(tmp_path):
    dx, g = 0.02, 9.81
    cfg = FluidConfig(dim=2, dx=dx, u_max=math.sqrt(g * 0.2), c0_factor=20.0, threads=1)
    walls = [(tank_walls(np.zeros(2), np.array([0.4, 0.3]), dx, 3), Kind.FIXED_WALL, 0)]
    fluid = SPHFluid(cfg, block(np.zeros(2), np.array([0.4, 0.2]), dx), walls, z_surface=0.2)
    bodies = MujocoBodies(builders.scene(builders.box("b", (0.1, 0.06), (0.2, 0.0, 0.1), density=2000.0,
                                                      planar=True)))
    c = Coupler(bodies=bodies, fluid=fluid, scheme="fluid-first")
    path = tmp_path / "sph.h5"
    calls = []

    def stop(info):  # fail on the step after 0.02 s, as an unstable participant would
        calls.append(info.t)
        if info.t > 0.02:
            raise RuntimeError("stopped")

    with pytest.raises(RuntimeError, match="stopped"):
        record_run(c, 1.0, path, snapshot_every=0.01, probes=[WaveGauge([0.05]), Energy()], callback=stop)
    with h5py.File(path) as h5:
        times = h5["snapshot_times"][()]
    assert times[0] == 0.0 and len(times) == 3 and times[1] >= 0.01 and times[2] >= 0.02
    snap = read_snapshot(path, 1)
    assert snap["pos"].shape[1] == 2 and (snap["kind"] == Kind.BODY).any()
    eta = read_series(path, "gauges")
    assert eta["t"].size == len(calls) + 1 and np.abs(eta["eta"] - 0.2).max() < dx / 2
    assert read_series(path, "ledger/b")["t"].size == len(c.ledger)
    with pytest.raises(InputError, match="dim=2"):
        with H5Output(tmp_path / "x.h5", dim=3) as out:
            RunRecorder(c, out)
