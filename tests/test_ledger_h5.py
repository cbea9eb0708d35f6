"""Ledger.write_h5: every booked load comes back from the HDF5 file, per body, also
when a long run is written in pieces."""

import numpy as np
import pytest

from cosim.errors import InputError
from cosim.ledger import FIELDS, Ledger
from fluid.output import H5Output, read_series


def _ledger(n_steps, rng):
    led = Ledger(["box", "buoy"])
    for k in range(n_steps):
        led.record(0.01 * k, *(rng.random((2, 3)) for _ in FIELDS))
    return led


def test_ledger_round_trips_through_h5_in_pieces(tmp_path):
    rng = np.random.default_rng(0)
    led = _ledger(5, rng)
    path = tmp_path / "run.h5"
    with H5Output(path, dim=3) as out:
        done = led.write_h5(out)
        for k in range(5, 8):
            led.record(0.01 * k, *(rng.random((2, 3)) for _ in FIELDS))
        assert led.write_h5(out, start=done) == 8
    a = led.arrays()
    for j, body in enumerate(led.body_names):
        s = read_series(path, f"ledger/{body}")
        np.testing.assert_array_equal(s["t"], a["t"])
        for f in FIELDS:
            np.testing.assert_array_equal(s[f], a[f][:, j])


def test_ledger_writes_its_own_file_from_a_path(tmp_path):
    led = _ledger(3, np.random.default_rng(1))
    assert led.write_h5(tmp_path / "ledger.h5", name="loads") == 3
    assert read_series(tmp_path / "ledger.h5", "loads/buoy")["gravity"].shape == (3, 3)
    with pytest.raises(InputError, match="start"):
        led.write_h5(tmp_path / "x.h5", start=4)
