"""Determinism: the same scene run twice gives the same numbers bit for bit, and so does
the fluid on one or two threads (its pair loops gather: thread i writes only particle i, in
a fixed neighbour order; sums over particles, such as the fluid's energy, are reduced in
an order that depends on the thread count and agree to round-off)."""

import numpy as np
import pytest

from cosim.scene import SPH, Beach, Box, Flume, Line, Moorings, Piston, Probes, Scene, World

LINE = dict(length=0.9, weight=5.0, EA=1.0e5, mass_per_length=0.588, diameter=0.01)


def scene(threads):
    return Scene(world=World(dim=2, duration=0.2, sample_every=0.02, snapshot_every=0),
                 fluid=SPH(dx=0.04, threads=threads),
                 domain=Flume(length=2.0, depth=0.3, height=0.45, beach=Beach(toe=1.4, slope=0.3)),
                 waves=Piston(height=0.04, period=1.0, ramp=0.5),
                 bodies=[Box("box", size=(0.2, 0.12), density=500.0, pos=(1.0,), place="floating",
                             fairleads={"l": (-0.1, -0.06), "r": (0.1, -0.06)})],
                 moorings=Moorings(lines=[Line("box.l", anchor=(0.4, 0.0), **LINE),
                                          Line("box.r", anchor=(1.6, 0.0), **LINE)]),
                 probes=Probes(gauges=[0.5, 1.3], energy=True))


@pytest.mark.long
def test_same_scene_twice_and_on_two_threads(tmp_path):
    a = scene(1).run(tmp_path / "a", progress=False)
    b = scene(1).run(tmp_path / "b", progress=False)
    c = scene(2).run(tmp_path / "c", progress=False)
    assert a.summary["steps"] == b.summary["steps"] == c.summary["steps"]
    for name in a.names:
        np.testing.assert_array_equal(a[name], b[name], err_msg=name)
        if name.startswith("fluid."):  # a sum over particles: the reduction order follows the threads
            np.testing.assert_allclose(c[name], a[name], rtol=1e-12, atol=1e-12, err_msg=name)
        else:
            np.testing.assert_array_equal(c[name], a[name], err_msg=name)
