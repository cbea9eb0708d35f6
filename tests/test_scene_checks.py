"""The scene's checks of where things start (``cosim.scene.checks``, ``cosim.scene.placement``)
refuse only what is wrong: the edge cases next to each refusal of docs/scene_errors.md are
accepted (bodies that touch, a fairlead at its anchor's height, a line exactly long enough
or elastic and stretched, water blocks that meet, a patch in a corner or on a beach), and
what the checks compute is what the builder builds (a turned body's fairlead, a floating
body's height)."""

import math

import numpy as np
import pytest

from cosim.scene import (SPH, Analytic, Beach, Block, Box, Cylinder, Flume, Line, Moorings, Patch, Probes, Scene,
                         Sphere, Tank, World)
from cosim.scene.checks import _rotation
from cosim.scene.placement import floating_height

W2, W3 = World(dim=2, duration=1.0), World(dim=3, duration=1.0)


@pytest.mark.parametrize("euler", [(30.0, 40.0, 50.0), (0.0, 90.0, 0.0), (-120.0, 10.0, 200.0)])
def test_a_turned_bodys_fairlead_is_where_mujoco_puts_it(euler):
    import mujoco

    from bodies import builders

    p, pos = (0.5, -0.2, 0.3), (1.0, 2.0, 3.0)
    xml = builders.scene(builders.box("b", (1.0, 0.4, 0.6), pos, density=500.0, euler=euler, sites={"f": p}))
    m = mujoco.MjModel.from_xml_string(xml)
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    r = np.array(_rotation(euler))
    np.testing.assert_allclose(np.add(pos, r @ p), d.site_xpos[0], atol=1e-12)


def _moored(anchor, length, EA=None, pos=(3.0, 0.0), euler=None, dim=2):
    size = (2.0, 1.0) if dim == 2 else (2.0, 1.0, 1.0)
    fair = (1.0, -0.5) if dim == 2 else (1.0, 0.0, -0.5)
    return Scene(world=W2 if dim == 2 else W3, fluid=Analytic(),
                 bodies=[Box("box", size=size, pos=pos, density=500.0, euler=euler, fairleads={"f": fair})],
                 moorings=Moorings(lines=[Line("box.f", anchor=anchor, length=length, weight=50.0, EA=EA)]))


def test_lines_at_the_edge_are_accepted():
    # the fairlead (4, -0.5) at its anchor's height, the line exactly as long as the distance
    _moored(anchor=(20.0, -0.5), length=16.0)
    # an elastic line may start stretched (a taut, pre-tensioned mooring), up to the limit:
    # 18.61 m from anchor to fairlead on 14.31 m of line is 30 %, on 14.30 m beyond it
    dist = math.hypot(16.0, 9.5)
    _moored(anchor=(20.0, -10.0), length=dist / 1.3 * (1 + 1e-9), EA=1e7)
    with pytest.raises(ValueError, match="would start stretched by 30 %, beyond 30 %"):
        _moored(anchor=(20.0, -10.0), length=dist / 1.3 * (1 - 1e-6), EA=1e7)
    # a 3-D body turned 180 deg about x: its fairlead (z -0.5 in its frame) is at z = +0.5
    _moored(anchor=(20.0, 0.0, 0.4), length=20.0, pos=(3.0, 0.0, 0.0), euler=(180.0, 0.0, 0.0), dim=3)
    with pytest.raises(ValueError, match="below this anchor's seabed"):
        _moored(anchor=(20.0, 0.0, 0.4), length=20.0, pos=(3.0, 0.0, 0.0), dim=3)
    with pytest.raises(ValueError, match="shorter than the straight distance 16 m"):
        _moored(anchor=(20.0, -0.5), length=15.999)


def test_bodies_that_touch_are_accepted():
    Scene(world=W2, fluid=Analytic(), bodies=[Box("a", size=(2.0, 1.0), pos=(0.0, 0.0), density=500.0),
                                              Box("b", size=(2.0, 1.0), pos=(2.0, 0.0), density=500.0),
                                              Cylinder("c", radius=0.5, pos=(3.5, 0.0), density=500.0)])
    Scene(world=W3, fluid=Analytic(), bodies=[Sphere("a", radius=0.5, pos=(0.0, 0.0, 0.0), density=500.0),
                                              Cylinder("b", radius=0.5, length=1.0, pos=(0.0, 0.0, 1.0),
                                                       density=500.0),
                                              Box("c", size=(1.0, 1.0, 1.0), pos=(1.0, 0.0, 1.0), density=500.0)])
    # a sphere beside a box's edge, clear of it though their bounding boxes overlap
    Scene(world=W3, fluid=Analytic(), bodies=[Box("a", size=(1.0, 1.0, 1.0), pos=(0.0, 0.0, 0.0), density=500.0),
                                              Sphere("b", radius=0.5, pos=(0.9, 0.9, 0.0), density=500.0)])
    with pytest.raises(ValueError, match="overlaps body 'a'"):
        Scene(world=W3, fluid=Analytic(), bodies=[Box("a", size=(1.0, 1.0, 1.0), pos=(0.0, 0.0, 0.0), density=500.0),
                                                  Sphere("b", radius=0.5, pos=(0.8, 0.8, 0.0), density=500.0)])


def test_water_blocks_that_meet_and_patches_in_corners_are_accepted():
    Scene(world=W2, fluid=SPH(dx=0.02), domain=Tank(length=1.0, height=0.6, water=[
        Block((0.0, 0.0), (0.3, 0.4)), Block((0.3, 0.0), (0.6, 0.2))]))
    flume = Flume(length=3.0, depth=0.3, height=0.45, beach=Beach(toe=2.0, slope=0.5))
    k = 1 / math.hypot(1.0, 0.5)
    Scene(world=W2, fluid=SPH(dx=0.02), domain=flume, probes=Probes(pressure=[
        Patch("corner", centre=(0.0, 0.0), normal=(1.0, 1.0), size=0.05),
        Patch("floor", centre=(0.0, 0.0), normal=(0.0, 1.0), size=0.05),
        Patch("beach", centre=(2.5, 0.25), normal=(-0.5 * k, k), size=0.05),
        Patch("near", centre=(2.5, 0.255), normal=(-0.5 * k, k), size=0.05)]))  # within half a spacing
    with pytest.raises(ValueError, match="lies in the water"):
        Scene(world=W2, fluid=SPH(dx=0.02), domain=flume,
              probes=Probes(pressure=[Patch("off", centre=(2.5, 0.27), normal=(-0.5 * k, k), size=0.05)]))
    with pytest.raises(ValueError, match=r"whose normal into the domain is \(-0.4472, 0.8944\)"):
        Scene(world=W2, fluid=SPH(dx=0.02), domain=flume,
              probes=Probes(pressure=[Patch("up", centre=(2.5, 0.25), normal=(-1.0, 0.0), size=0.05)]))


def test_a_floating_body_moored_just_below_its_fairlead_floats_above_the_anchor():
    """The anchor 1 mm below where the fairlead floats without lines: the body floats, its
    fairlead above the anchor's seabed; 1 mm above, refused naming the line's anchor."""
    box = Box("box", size=(0.2, 0.1), density=500.0, pos=(1.2,), place="floating", fairleads={"f": (-0.1, -0.05)})
    free = floating_height(box, 2, 0.3, 1000.0, 9.81)  # centre 0.3 m: the fairlead at 0.25 m
    for dz, ok in ((-1e-3, True), (1e-3, False)):
        line = Line("box.f", anchor=(0.5, free - 0.05 + dz), length=0.9, weight=5.0)
        if ok:
            z = floating_height(box, 2, 0.3, 1000.0, 9.81, [line])
            assert line.anchor[1] <= z - 0.05 < free - 0.05
        else:
            with pytest.raises(ValueError) as err:
                floating_height(box, 2, 0.3, 1000.0, 9.81, [line], keys=["moorings.lines[3]"])
            assert err.value.path == "moorings.lines[3].anchor"


def test_physical_limits_are_edges():
    """Each limit of cosim.scene.plausible accepts its edge and refuses just beyond it: a
    fairlead at 1.5 bounding radii, a shake peaking at 5 g, a turned box whose corner
    touches the floor."""
    from cosim.scene import Shake
    from cosim.scene.limits import FAIRLEAD_REACH, MAX_BASE_ACCELERATION

    reach = FAIRLEAD_REACH * math.hypot(1.0, 0.5)  # the 2 x 1 m box's bounding radius is 1.118 m
    for k, ok in ((1 - 1e-9, True), (1 + 1e-6, False)):
        box = Box("box", size=(2.0, 1.0), pos=(3.0, 0.0), density=500.0, fairleads={"f": (reach * k, 0.0)})
        if ok:
            Scene(world=W2, fluid=Analytic(), bodies=[box])
        else:
            with pytest.raises(ValueError, match=r"beyond 1.677 m \(1.5 times its bounding radius 1.118 m\)"):
                Scene(world=W2, fluid=Analytic(), bodies=[box])
    tank = Tank(length=1.0, height=0.6, depth=0.3)
    top = MAX_BASE_ACCELERATION / (2 * math.pi) ** 2  # the amplitude [m] that peaks at 5 g at a 1 s period
    Scene(world=W2, fluid=SPH(dx=0.02), domain=tank, base_motion=Shake(period=1.0, amplitude=top * (1 - 1e-12)))
    with pytest.raises(ValueError, match=r"peaks at 49.03 m/s\^2 \(5 g\), beyond 49.03 m/s\^2 \(5 g\)"):
        Scene(world=W2, fluid=SPH(dx=0.02), domain=tank, base_motion=Shake(period=1.0, amplitude=top * (1 + 1e-6)))
    z = 0.1 * math.cos(math.radians(45.0)) + 0.05 * math.sin(math.radians(45.0))  # the turned box's half height
    turned = dict(size=(0.2, 0.1), density=500.0, euler=(0.0, 45.0, 0.0))
    Scene(world=W2, fluid=SPH(dx=0.02), domain=tank, bodies=[Box("b", pos=(0.5, z + 1e-12), **turned)])
    with pytest.raises(ValueError, match=r"the body \(turned by euler = \(0, 45, 0\) deg\) reaches -1e-06"):
        Scene(world=W2, fluid=SPH(dx=0.02), domain=tank, bodies=[Box("b", pos=(0.5, z - 1e-6), **turned)])
