"""The wave flume builder."""

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.flume import PADDLE_GROUP, WALL_GROUP, flume
from fluid.particles import Kind


def test_flume_parts_and_beach():
    dx = 0.02
    f = flume(dx, 3.0, 0.3, 0.45, back=0.05, beach=(2.0, 0.3))
    (fixed, k0, g0), (paddle, k1, g1) = f.walls
    assert (k0, g0, k1, g1) == (Kind.FIXED_WALL, WALL_GROUP, Kind.MOVING_WALL, PADDLE_GROUP)
    assert paddle[:, 0].max() < 0 and paddle[:, 1].min() > 0  # the paddle columns, above the floor
    assert fixed[:, 0].min() < -0.05 - 3 * dx + dx  # floor behind the paddle
    # no water under the beach; the water's far end is where the beach meets the surface
    assert (f.fluid[:, 1] > 0.3 * (f.fluid[:, 0] - 2.0)).all()
    # (the top row at z = 0.29 m stays dx/2 clear of the ramp: x < 2 + 0.28 / 0.3)
    assert f.fluid[:, 0].max() == pytest.approx(2.0 + 0.28 / 0.3, abs=dx)


def test_bad_flume_input():
    with pytest.raises(InputError, match="below the wall height"):
        flume(0.02, 2.0, 0.5, 0.4)
    with pytest.raises(InputError, match="beach"):
        flume(0.02, 2.0, 0.3, 0.4, beach=(3.0, 0.2))
