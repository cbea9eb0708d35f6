"""A catalogue of bad scenes: each is refused before any work is done, from TOML (a dict
read by ``from_dict``, and the same change made by ``--set``, ``with_values``) and in
Python (the classes constructed directly), naming the exact key path and saying what would
be accepted. Four tables: the scene's fields (:data:`CASES`), the contents of the files a
scene names (:data:`FILE_CASES`, written into the working folder first), what is only known
once the scene is built (:data:`BUILD_CASES`: refused by ``run`` before it writes anything)
and the command line (:data:`CLI_CASES`: ``cosim run`` in a subprocess exits with status 2,
says what is wrong on stderr and makes no output folder).

Each case takes one of the valid base scenes below and changes it (``key = value``, or a
key left out); ``path`` is the key path the error must name, ``says`` a fragment of its
message. ``python`` is the path of the same error when the scene is built in Python: the
class that refuses it first (``Box.density``: a Box does not know where it will be put;
``Scene.bodies[0].pos``: the scene's own checks), ``TYPE`` where Python's call itself
refuses it (an unknown or missing keyword: ``TypeError``), None where there is no Python
counterpart (the TOML tag that picks a class; ``--set`` syntax).

``docs/scene_errors.md`` is this catalogue as a table, rendered by :func:`render`; regenerate
it with ``python tests/test_scene_errors.py > docs/scene_errors.md``.
"""

from __future__ import annotations

import atexit
import contextlib
import copy
import dataclasses
import functools
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import tomllib
from dataclasses import dataclass
from pathlib import Path

import pytest

from cosim.errors import InputError
from cosim.scene import Scene
from cosim.scene.fields import Part, Parts
from cosim.scene.toml_io import from_dict, with_values

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "scene_errors.md"

# ------------------------------------------------------------------------ base scenes
BASES = {
    "flume": """
# 2-D: SPH flume, piston waves, a floating box on two catenary lines, gauges, a wall patch
[world]
dim = 2
duration = 5.0
sample_every = 0.02
plot_at = [2.5]

[fluid]
model = "sph"
dx = 0.02

[domain]
kind = "flume"
length = 3.0
depth = 0.3
height = 0.45

[waves]
kind = "piston"
height = 0.04
period = 1.0

[[bodies]]
shape = "box"
name = "box"
size = [0.2, 0.1]
pos = [1.2]
place = "floating"
density = 500.0
fairleads = { left = [-0.1, -0.05], right = [0.1, -0.05] }

[moorings]
lines = [
  { fairlead = "box.left", anchor = [0.5, 0.0], length = 0.9, weight = 5.0 },
  { fairlead = "box.right", anchor = [1.9, 0.0], length = 0.9, weight = 5.0 },
]

[probes]
gauges = [0.6, 1.6]
pressure = [{ name = "wall", centre = [3.0, 0.1], normal = [-1.0, 0.0], size = 0.05 }]
""",
    "tank3d": """
# 3-D: SPH tank filled to a depth, shaken; a floating sphere; a gauge
[world]
dim = 3
duration = 2.0

[fluid]
model = "sph"
dx = 0.02

[domain]
kind = "tank"
length = 1.0
width = 0.5
height = 0.6
depth = 0.2

[base_motion]
kind = "harmonic"
period = 1.0
direction = [1.0, 0.0, 0.0]
amplitude = 0.01

[[bodies]]
shape = "sphere"
name = "ball"
radius = 0.05
pos = [0.5, 0.25]
place = "floating"
density = 500.0

[probes]
gauges = [[0.1, 0.25]]
""",
    "analytic": """
# 2-D: the analytic fluid, a moored box at a given pose and a buoy
[world]
dim = 2
duration = 10.0

[fluid]
model = "analytic"
linear_damping = { box = [800.0, 0.0, 1500.0, 0.0, 1500.0, 0.0] }

[[bodies]]
shape = "box"
name = "box"
size = [2.0, 1.0]
pos = [3.0, 0.0]
density = 500.0
fairleads = { left = [-1.0, -0.5], right = [1.0, -0.5] }

[[bodies]]
shape = "cylinder"
name = "buoy"
radius = 0.3
pos = [8.0, 0.0]
mass = 150.0

[moorings]
lines = [
  { fairlead = "box.left", anchor = [-20.0, -10.0], length = 25.0, weight = 50.0 },
  { fairlead = "box.right", anchor = [20.0, -10.0], length = 25.0, weight = 50.0 },
]
""",
    "potential": """
# 3-D: linear potential flow (Capytaine), a floating cylinder in linear waves, 20 m of water
[world]
dim = 3
duration = 10.0

[fluid]
model = "potential"
panel_size = 1.0
omega_max = 3.0
frequencies = 20

[waves]
kind = "linear"
height = 0.2
period = 6.0
depth = 20.0

[[bodies]]
shape = "cylinder"
name = "buoy"
radius = 3.0
length = 3.0
pos = [0.0, 0.0]
place = "floating"
density = 500.0
""",
    "tank2d": """
# 2-D: SPH tank shaken by a table of displacement (motion.txt)
[world]
dim = 2
duration = 2.0

[fluid]
model = "sph"
dx = 0.02

[domain]
kind = "tank"
length = 1.0
height = 0.6
depth = 0.3

[base_motion]
kind = "table"
file = "motion.txt"
""",
    "nearfield": """
# 2-D: an SPH near field in regular waves round a floating box
[world]
dim = 2
duration = 5.0

[fluid]
model = "sph"
dx = 0.02

[domain]
kind = "nearfield"
depth = 0.3

[waves]
kind = "regular"
height = 0.04
period = 1.0
depth = 0.3

[[bodies]]
shape = "box"
name = "box"
size = [0.2, 0.1]
pos = [1.2]
place = "floating"
density = 500.0
""",
    "nearfield3d": """
# 3-D: the base of Barreiro et al. 2016 on three lines in a near field, its half y >= 0 simulated
[world]
dim = 3
duration = 1.0

[fluid]
model = "sph"
dx = 1.5
rho0 = 1025.0

[domain]
kind = "nearfield"
depth = 20.0
symmetry = true

[waves]
kind = "regular"
height = 0.7
period = 20.0
depth = 20.0

[[bodies]]
shape = "cylinder"
name = "base"
radius = 3.0
length = 3.0
mass = 16000.0
pos = [70.0, 0.0]
place = "floating"
fairleads = { back = [3.0, 0.0, -1.5], port = [-1.5, 2.5981, -1.5], starboard = [-1.5, -2.5981, -1.5] }

[moorings]
lines = [
  { fairlead = "base.back", anchor = [107.0, 0.0, 0.0], length = 45.0, weight = 3769.85 },
  { fairlead = "base.port", anchor = [51.5, 32.0429, 0.0], length = 45.0, weight = 3769.85 },
  { fairlead = "base.starboard", anchor = [51.5, -32.0429, 0.0], length = 45.0, weight = 3769.85 },
]
""",
    "mjcf": """
# 3-D: the analytic fluid, the body "float" of an MJCF file (float.xml) on one line
[world]
dim = 3
duration = 2.0

[fluid]
model = "analytic"
linear_damping = { float = [100.0, 100.0, 200.0, 10.0, 10.0, 10.0] }

[[bodies]]
shape = "mjcf"
file = "float.xml"
bodies = ["float"]

[moorings]
lines = [{ fairlead = "float.top", anchor = [0.0, 0.0, -10.0], length = 12.0, weight = 5.0 }]

[probes]
motion = ["float"]
""",
    "plate": """
# 2-D: a dam break on an elastic plate (Yang & Li 2020, §3.3)
[world]
dim = 2
duration = 0.4

[fluid]
model = "sph"
dx = 0.005

[domain]
kind = "tank"
length = 0.584
height = 0.32
water = [{ lo = [0.0, 0.0], hi = [0.146, 0.292] }]

[[bodies]]
shape = "elastic-plate"
name = "plate"
length = 0.08
thickness = 0.012
E = 1e6
density = 2500.0
base = [0.298, 0.0]
""",
}

#: the files beside the base scenes (in the working folder): valid, as the scenes read them
BASE_FILES = {
    "motion.txt": "# t [s]  x [m]\n0.0  0.0\n0.25  0.005\n0.5  0.0\n0.75  -0.005\n1.0  0.0\n",
    "quake.AT2": ("PEER RECORD\nSYNTHETIC, 2024, STATION, 000\nACCELERATION TIME SERIES IN UNITS OF G\n"
                  "NPTS=   10, DT=   .0100 SEC\n0.0 0.01 0.02 0.01 0.0\n-0.01 -0.02 -0.01 0.0 0.0\n"),
    "paddle.txt": "t [s], x [m]\n0.0, 0.0\n0.5, 0.01\n1.0, 0.0\n1.5, -0.01\n2.0, 0.0\n",
    "roll.txt": ("# t [s]  angle [deg]  angle + 3 [deg]\n0.0  0.0  3.0\n0.5  2.0  5.0\n1.0  0.0  3.0\n"
                 "1.5  -2.0  1.0\n2.0  0.0  3.0\n"),
    "float.xml": """<mujoco>
  <worldbody>
    <body name="float"><freejoint/><geom type="box" size="0.5 0.5 0.25" density="500"/>
      <site name="top" pos="0 0 0.25"/></body>
    <body name="boat" pos="3 0 0"><freejoint/><geom type="box" size="0.5 0.3 0.2" density="400"/>
      <site name="bow" pos="0.5 0 0"/></body>
    <body name="post" pos="-3 0 0"><geom type="cylinder" size="0.1 1"/><site name="tip" pos="0 0 1"/></body>
  </worldbody>
</mujoco>
""",
}


@contextlib.contextmanager
def folder():
    """A fresh working folder holding the base files (the scenes' relative names are read
    from it)."""
    old = os.getcwd()
    with tempfile.TemporaryDirectory(prefix="scene-errors-") as tmp:
        for name, text in BASE_FILES.items():
            Path(tmp, name).write_text(text, encoding="utf-8")
        os.chdir(tmp)
        try:
            yield Path(tmp)
        finally:
            os.chdir(old)


@pytest.fixture(autouse=True)
def _in_folder():
    with folder():
        yield

OUT = object()  # an edit's value: leave the key out
TYPE = TypeError  # the Python route: the call's own TypeError (unknown or missing keyword)


@dataclass(frozen=True)
class Case:
    id: str
    base: str
    change: tuple | str  # ((key path, value or OUT), ...), or a raw --set assignment (TOML's route only)
    path: str  # the key path in the error (TOML, --set)
    says: str  # a fragment of the message
    python: str | tuple | type | None  # the path in Python (and a fragment where Python's message differs),
    #                                     TYPE, or None: no Python counterpart
    files: tuple = ()  # ((name, text), ...): files written into the working folder first

    @property
    def python_path(self):
        return self.python[0] if isinstance(self.python, tuple) else self.python

    def write_files(self):
        for name, text in self.files:
            Path(name).write_text(text, encoding="utf-8")


def case(id, base, change, path, says, python, files=None):
    if isinstance(change, tuple) and change and not isinstance(change[0], tuple):
        change = (change,)
    return Case(id, base, change, path, says, python, tuple((files or {}).items()))


OPEN = {"kind": "open", "lo": [-0.5, -0.5, -0.5], "hi": [1.5, 1.0, 1.0], "water": [{"lo": [0.0, 0.0, 0.0],
                                                                                 "hi": [1.0, 0.5, 0.2]}]}
INCLINED = {"kind": "inclined-tank", "angle": 95.0, "length": 1.0, "depth": 0.2, "height": 0.6, "width": 0.5}
LINE_DYN = {"EA": 1e5, "mass_per_length": 0.6, "diameter": 0.01}
LINEAR = {"kind": "linear", "height": 0.7, "period": 20.0, "depth": 20.0}  # Barreiro et al. 2016's waves
REGULAR = {"kind": "regular", "height": 0.7, "period": 20.0, "depth": 20.0}
JONSWAP = {"kind": "irregular", "depth": 20.0, "hs": 1.0, "tp": 8.0}
SERIES = {"kind": "irregular", "depth": 20.0, "spectrum": "series", "file": "eta.txt"}


def eta_rows(n=24, a=0.1, late=None):
    """A record of a 6 s wave of amplitude ``a`` [m], ``n`` samples 0.5 s apart (sample
    ``late`` 0.1 s late)."""
    return "t [s], eta [m]\n" + "".join(f"{0.5 * i + 0.1 * (i == late)}, {a * math.cos(math.pi * i / 6):.6f}\n"
                                         for i in range(n))


ETA_TXT = eta_rows()  # 12 s long: the analytic base scene runs 10 s

CASES = [
    # -- keys: unknown, misspelt, missing
    case("unknown top-level key", "analytic", ("colour", "red"), "colour",
         "unknown key. Known keys here: world, fluid", TYPE),
    case("misspelt top-level key", "analytic", ("mooring", {"model": "catenary"}), "mooring",
         "did you mean 'moorings'?", TYPE),
    case("misspelt key deep down", "analytic", ("moorings.lines[1].lenght", 25.0), "moorings.lines[1].lenght",
         "unknown key; did you mean 'length'?", TYPE),
    case("missing required: fluid.dx", "flume", ("fluid.dx", OUT), "fluid.dx",
         "is required: a number [m] > 0 (particle spacing)", TYPE),
    case("missing required: domain.length", "flume", ("domain.length", OUT), "domain.length",
         "is required: a number [m] > 0", TYPE),
    case("missing required: a line's anchor", "analytic", ("moorings.lines[0].anchor", OUT),
         "moorings.lines[0].anchor", "is required: a list of 2 or 3 numbers [m]", TYPE),
    case("missing tag", "flume", ("fluid", {"dx": 0.02}), "fluid.model",
         "is required: one of 'none', 'analytic', 'potential', 'sph'", None),
    # -- types
    case("text for a number", "flume", ("fluid.dx", "0.01"), "fluid.dx",
         "'0.01' is not a finite number; give a number [m] > 0", "SPH.dx"),
    case("number for a text", "analytic", ("bodies[0].name", 5), "bodies[0].name",
         "5 is not accepted; give a name of letters, digits, '_' and '-'", "Box.name"),
    case("bool for a number", "analytic", ("bodies[0].density", True), "bodies[0].density",
         "True is not a finite number; give a number [kg/m^3] > 0", "Box.density"),
    case("float for a whole number", "analytic", ("moorings.segments", 2.5), "moorings.segments",
         "2.5 is not a whole number; give a whole number >= 2", "Moorings.segments"),
    case("number for true/false", "flume", ("probes.energy", 1), "probes.energy",
         "1 is not true or false", "Probes.energy"),
    case("list of the wrong length", "analytic", ("bodies[0].size", [0.2, 0.1, 0.3, 0.4]), "bodies[0].size",
         "is not accepted; give a list of 2 or 3 numbers [m]", "Box.size"),
    case("damping row of 5 values", "analytic", ("fluid.linear_damping.box", [1.0, 2.0, 3.0, 4.0, 5.0]),
         "fluid.linear_damping.box", "give a list of 6 numbers", "Analytic.linear_damping.box"),
    case("a number for a table", "flume", ("world", 3), "world", "3 is not a table",
         ("Scene.world", "int 3 is not accepted; give World")),
    case("a table for a list", "analytic", ("bodies", {"shape": "box"}), "bodies",
         "is not a list; give a list of Box or Cylinder or Sphere or MJCF", "Scene.bodies"),
    case("a tag that is not a text", "flume", ("domain.kind", [1]), "domain.kind",
         "[1] is not accepted. Give one of 'tank', 'flume'", None),
    case("a name with a dot", "analytic", ("bodies[1].name", "my.buoy"), "bodies[1].name",
         "'my.buoy' is not accepted; give a name of letters, digits, '_' and '-'", "Cylinder.name"),
    # -- not finite
    case("nan", "flume", ("world.duration", math.nan), "world.duration",
         "nan is not a finite number; give a number [s] > 0", "World.duration"),
    case("inf", "analytic", ("bodies[0].density", math.inf), "bodies[0].density",
         "inf is not a finite number", "Box.density"),
    case("-inf in a vector", "analytic", ("bodies[0].pos", [3.0, -math.inf]), "bodies[0].pos",
         "[3.0, -inf] is not accepted; give a list of 1, 2 or 3 numbers [m]", "Box.pos"),
    case("an integer beyond any float", "analytic", ("bodies[1].mass", 10 ** 400), "bodies[1].mass",
         "is not a finite number; give a number [kg] > 0", "Cylinder.mass"),
    # -- zero or negative where positive is required
    case("negative dx", "flume", ("fluid.dx", -0.01), "fluid.dx",
         "-0.01 [m] is out of range; give a number [m] > 0", "SPH.dx"),
    case("zero duration", "flume", ("world.duration", 0.0), "world.duration",
         "0.0 [s] is out of range; give a number [s] > 0", "World.duration"),
    case("negative density", "analytic", ("bodies[0].density", -500.0), "bodies[0].density",
         "is out of range; give a number [kg/m^3] > 0", "Box.density"),
    case("zero line length", "analytic", ("moorings.lines[0].length", 0.0), "moorings.lines[0].length",
         "0.0 [m] is out of range; give a number [m] > 0 (unstretched length)", "Line.length"),
    case("negative line weight", "analytic", ("moorings.lines[1].weight", -50.0), "moorings.lines[1].weight",
         "is out of range; give a number [N/m] > 0", "Line.weight"),
    case("zero EA", "analytic", ("moorings.lines[0].EA", 0.0), "moorings.lines[0].EA",
         "0.0 [N] is out of range; give a number [N] > 0 and <= 1e+11 (axial stiffness", "Line.EA"),
    case("zero break load", "analytic", ("moorings.lines[0].break_load", 0.0), "moorings.lines[0].break_load",
         "0.0 [N] is out of range; give a number [N] > 0 and <= 3e+08 (tension at which the line breaks", "Line.break_load"),
    case("negative break load", "analytic", ("moorings.lines[1].break_load", -1.4e6), "moorings.lines[1].break_load",
         "-1400000.0 [N] is out of range; give a number [N] > 0", "Line.break_load"),
    case("zero wave height", "analytic", ("waves", dict(LINEAR, height=0.0)), "waves.height",
         "0.0 [m] is out of range; give a number [m] > 0 (wave height H", "LinearWaves.height"),
    case("negative wave period", "analytic", ("waves", dict(LINEAR, period=-20.0)), "waves.period",
         "-20.0 [s] is out of range; give a number [s] > 0 (wave period T)", "LinearWaves.period"),
    # -- the potential-flow fluid
    case("potential flow in 2-D", "potential", (("world.dim", 2), ("bodies[0].pos", [0.0]), ("bodies[0].length", OUT)),
         "world.dim", "linear potential flow about a body is 3-D; set world.dim = 3", "Scene.world.dim"),
    case("potential flow: a depth other than the waves'", "potential", ("fluid.depth", 30.0), "fluid.depth",
         "30 m differs from the waves' depth (waves.depth), 20 m", "Scene.fluid.depth"),
    case("potential flow: a body fully submerged", "potential",
         (("bodies[0].place", "given"), ("bodies[0].pos", [0.0, 0.0, -2.0])), "bodies[0].pos",
         "body 'buoy' spans z = -3.5 .. -0.5 m: fully submerged, below the still water at 0 m", "Scene.bodies[0].pos"),
    case("potential flow: a dry body", "potential", (("bodies[0].place", "given"), ("bodies[0].pos", [0.0, 0.0, 2.0])),
         "bodies[0].pos", "body 'buoy' spans z = 0.5 .. 3.5 m: dry, above the still water", "Scene.bodies[0].pos"),
    case("potential flow: waves outside the trusted band", "potential", ("fluid.omega_max", 1.5), "fluid.omega_max",
         "the waves' 1.047 rad/s (period 6 s) lies outside the band the impulse response is trusted in, "
         "0.1047 .. 0.75 rad/s", "Scene.fluid.omega_max"),
    case("potential flow: a memory beyond what the frequencies resolve", "potential", ("fluid.memory", 30.0),
         "fluid.memory", "30 s is longer than the 20.94 s that 20 frequencies up to 3 rad/s resolve",
         "Scene.fluid.memory"),
    case("potential flow: drift without waves", "potential", (("fluid.drift", True), ("waves", OUT)), "fluid.drift",
         "the drift force needs waves: give waves", "Scene.fluid.drift"),
    case("potential flow: interaction with drift", "potential", (("fluid.drift", True), ("fluid.interaction", True)),
         "fluid.interaction", "which gives the group's total, not each body's", "Scene.fluid.interaction"),
    case("potential flow: drag for an unknown body", "potential", ("fluid.quadratic_drag.box", [1.0] * 6),
         "fluid.quadratic_drag.box", "no body named 'box'; bodies: ['buoy']", "Scene.fluid.quadratic_drag.box"),
    case("potential flow: a turned body above the water", "potential",
         (("bodies[0].place", "given"), ("bodies[0].pos", [0.0, 0.0, 3.5]), ("bodies[0].euler", [90.0, 0.0, 0.0])),
         "bodies[0].pos", "body 'buoy' spans z = 0.5 .. 6.5 m: dry, above the still water at 0 m",
         "Scene.bodies[0].pos"),
    case("potential flow: a body it cannot mesh", "mjcf", ("fluid", {"model": "potential"}), "bodies[0].shape",
         "the potential fluid meshes boxes, cylinders and spheres; a 'mjcf' body needs the analytic or SPH fluid",
         "Scene.bodies[0].shape"),
    case("potential flow: an irregular sea too steep", "potential", ("waves", dict(JONSWAP, hs=9.0)), "waves.hs",
         "Hs/Lp = 0.1014 is beyond 0.1 (Lp the linear wavelength at the peak period): its largest waves would break",
         "Scene.waves.hs"),
    case("potential flow: a peak period of zero", "potential", ("waves", dict(JONSWAP, tp=0.0)), "waves.tp",
         "0.0 [s] is out of range; give a number [s] > 0 (peak period Tp", "IrregularWaves.tp"),
    case("zero water depth of the waves", "analytic", ("waves", dict(LINEAR, depth=0.0)), "waves.depth",
         "0.0 [m] is out of range; give a number [m] > 0 (still-water depth over the seabed", "LinearWaves.depth"),
    case("waves' depth not the flume's", "flume", (("fluid", {"model": "analytic"}),
                                                    ("waves", {"kind": "linear", "height": 0.04, "period": 1.0,
                                                               "depth": 0.25})), "waves.depth",
         "0.25 m differs from the flume's still-water depth 0.3 m (domain.depth)", "Scene.waves.depth"),
    case("negative radius", "tank3d", ("bodies[0].radius", -0.05), "bodies[0].radius",
         "is out of range; give a number [m] > 0 (radius)", "Sphere.radius"),
    case("a zero edge", "analytic", ("bodies[0].size", [2.0, 0.0]), "bodies[0].size",
         "every edge length must be > 0 m", "Box.size"),
    case("too few segments", "analytic", ("moorings.segments", 1), "moorings.segments",
         "1 is out of range; give a whole number >= 2", "Moorings.segments"),
    # -- out of range
    case("dim 4", "flume", ("world.dim", 4), "world.dim", "4 is out of range; give a whole number from 2 to 3",
         "World.dim"),
    case("cfl 0.5", "flume", ("fluid.cfl", 0.5), "fluid.cfl", "0.5 is out of range; give a number > 0 and <= 0.4",
         "SPH.cfl"),
    case("h_coef 5", "flume", ("fluid.h_coef", 5), "fluid.h_coef", "give a number >= 1 and <= 3", "SPH.h_coef"),
    case("alpha 2", "flume", ("fluid.alpha", 2.0), "fluid.alpha", "give a number >= 0 and <= 1", "SPH.alpha"),
    case("c0_factor below 10", "flume", ("fluid.c0_factor", 5.0), "fluid.c0_factor", "give a number >= 10",
         "SPH.c0_factor"),
    case("inclination 95 deg", "tank3d", ("domain", INCLINED), "domain.angle",
         "95.0 [deg] is out of range; give a number [deg] >= 0 and < 90", "InclinedTank.angle"),
    case("negative gravity", "analytic", ("world.gravity", -9.81), "world.gravity",
         "-9.81 [m/s^2] is out of range; give a number [m/s^2] from 0", "World.gravity"),
    # -- choices
    case("fluid.model misspelt", "flume", ("fluid.model", "sphh"), "fluid.model",
         "'sphh' is not accepted; did you mean 'sph'? Give one of 'none', 'analytic', 'potential', 'sph'", None),
    case("domain.kind misspelt", "flume", ("domain.kind", "flumee"), "domain.kind",
         "'flumee' is not accepted; did you mean 'flume'?", None),
    case("an unknown shape", "analytic", ("bodies[1].shape", "torus"), "bodies[1].shape",
         "'torus' is not accepted. Give one of 'box', 'cylinder', 'sphere', 'mjcf'", None),
    case("moorings.model misspelt", "analytic", ("moorings.model", "moordin"), "moorings.model",
         "'moordin' is not accepted; did you mean 'moordyn'? Give one of 'catenary', 'sph-cable', 'moordyn', 'fmu'",
         "Moorings.model"),
    case("coupling.scheme misspelt", "analytic", ("coupling.scheme", "predictor_corrector"), "coupling.scheme",
         "did you mean 'predictor-corrector'?", "Coupling.scheme"),
    case("place misspelt", "flume", ("bodies[0].place", "float"), "bodies[0].place",
         "'float' is not accepted; did you mean 'floating'? Give one of 'given', 'floating'", "Box.place"),
    case("fluid.setup unknown", "flume", ("fluid.setup", "tsunami"), "fluid.setup",
         "'tsunami' is not accepted; give one of 'auto', 'still', 'waves'", "SPH.setup"),
    # -- one of two
    case("density and mass", "analytic", ("bodies[0].mass", 1000.0), "bodies[0].density",
         "give either density [kg/m^3] or mass [kg], one of the two", "Box.density"),
    case("neither density nor mass", "analytic", ("bodies[0].density", OUT), "bodies[0].density",
         "give either density [kg/m^3] or mass [kg], one of the two", "Box.density"),
    case("depth and water blocks", "tank3d", ("domain.water", [{"lo": [0.0, 0.0, 0.0], "hi": [0.3, 0.5, 0.4]}]),
         "domain.depth", "give either depth (a tank filled to it) or water blocks, one of the two", "Tank.depth"),
    case("neither depth nor water blocks", "tank3d", ("domain.depth", OUT), "domain.depth",
         "give either depth (a tank filled to it) or water blocks", "Tank.depth"),
    case("amplitude and acceleration", "tank3d", ("base_motion.acceleration", 2.0), "base_motion.amplitude",
         "give either amplitude [m] or acceleration [m/s^2], one of the two", "Shake.amplitude"),
    case("neither amplitude nor acceleration", "tank3d", ("base_motion.amplitude", OUT), "base_motion.amplitude",
         "give either amplitude [m] or acceleration [m/s^2]", "Shake.amplitude"),
    case("a shake's stop without a ramp to fade it out", "tank3d", ("base_motion.stop", 2.0), "base_motion.ramp",
         "is 0 s, but stop = 2 s fades the shaking out over ramp; give ramp > 0 (e.g. one period), or hold = true",
         "Shake.ramp"),
    case("a held shake without a stop", "tank3d", ("base_motion.hold", True), "base_motion.hold",
         "= true needs stop, the time [s] at which the tank stops and is held", "Shake.hold"),
    case("a held stop where the tank moves", "tank3d", (("base_motion.hold", True), ("base_motion.stop", 2.0)),
         "base_motion.stop", "= 2 s: the tank moves at 0.0628 m/s there (its peak 0.0628 m/s), and hold cuts the "
         "motion at stop, a jump to rest; give a stop where it is at rest, e.g. 1.75 s or 2.25 s", "Shake.stop"),
    case("a held stop before the fade-in ends", "tank3d",
         (("base_motion.hold", True), ("base_motion.ramp", 2.0), ("base_motion.stop", 1.75)), "base_motion.stop",
         "= 1.75 s comes before the fade-in over ramp = 2 s ends", "Shake.stop"),
    case("c0 and u_max", "flume", (("fluid.c0", 20.0), ("fluid.u_max", 2.0)), "fluid.c0",
         "give c0 or u_max, not both", "SPH.c0"),
    # -- dimensions
    case("a 3-D pos in a 2-D scene", "analytic", ("bodies[0].pos", [3.0, 0.0, 0.0]), "bodies[0].pos",
         "[3.0, 0.0, 0.0] has 3 coordinates; a 2-D scene gives a point as (x, z)", "Scene.bodies[0].pos"),
    case("a 2-D anchor in a 3-D scene", "mjcf", ("moorings.lines[0].anchor", [0.0, -10.0]),
         "moorings.lines[0].anchor", "a 3-D scene gives a point as (x, y, z)", "Scene.moorings.lines[0].anchor"),
    case("gauge pairs in 2-D", "flume", ("probes.gauges", [[0.6, 0.0]]), "probes.gauges[0]",
         "a 2-D scene gives a gauge as x [m]", "Scene.probes.gauges[0]"),
    case("a gauge number in 3-D", "tank3d", ("probes.gauges", [0.1]), "probes.gauges[0]",
         "a 3-D scene gives a gauge as (x, y) [m]", "Scene.probes.gauges[0]"),
    case("a 3-D flume without width", "flume", ("world.dim", 3), "domain.width",
         "a 3-D flume (a wave tank) needs its width along y", "Scene.domain.width"),
    case("a flume's width in 2-D", "flume", ("domain.width", 1.0), "domain.width",
         "a 2-D flume is the x-z plane; leave width out", "Scene.domain.width"),
    case("symmetry planes as a 2-D flume's sides", "flume", ("domain.sides", "symmetry"), "domain.sides",
         "a 2-D flume has no sides: leave sides out", "Scene.domain.sides"),
    case("a body in a flume between symmetry planes", "flume",
         (("world.dim", 3), ("domain.width", 0.2), ("domain.sides", "symmetry")), "domain.sides",
         "a flume between symmetry planes carries waves uniform across y and no bodies", "Scene.domain.sides"),
    case("the analytic fluid's level in a flume", "flume", (("fluid", {"model": "analytic", "level": 0.5}),
                                                         ("probes.pressure", [])),
         "fluid.level", "with a flume the still level is its depth", "Scene.fluid.level"),
    case("a paddle record on the analytic fluid", "flume",
         (("fluid", {"model": "analytic"}), ("probes.pressure", []),
          ("waves", {"kind": "record", "paddle": "piston", "file": "paddle.txt"})),
         "waves.kind", "the analytic fluid takes the waves themselves", "Scene.waves.kind"),
    case("open water shaken", "tank3d", ("domain", OPEN), "base_motion",
         "open water has no tank to move; leave base_motion out", "Scene.base_motion"),
    case("a floating body in open water", "tank3d", (("domain", OPEN), ("base_motion", OUT)), "bodies[0].place",
         "\"floating\" finds a waterline under a still level; open water has none", "Scene.bodies[0].place"),
    case("open water's block beyond its box", "tank3d",
         (("domain", OPEN | {"hi": [1.5, 1.0, 0.1]}), ("base_motion", OUT)), "domain.water[0]",
         "the block [0.0, 0.0, 0.0] .. [1.0, 0.5, 0.2] m reaches outside the fluid's box [-0.5, -0.5, -0.5] .. "
         "[1.5, 1.0, 0.1] m", "Scene.domain.water[0]"),
    case("open water without water", "tank3d", (("domain", OPEN | {"water": []}), ("base_motion", OUT)),
         "domain.water", "give at least one block of water", "OpenWater.water"),
    case("open water that nothing moves, without c0", "tank3d",
         (("domain", OPEN), ("base_motion", OUT), ("bodies", OUT), ("world.gravity", 0.0)), "fluid.c0",
         "nothing sets the open water's flow speed (no gravity, no body given a velocity)", "Scene.fluid.c0"),
    case("a body's velocity in the wrong dimension", "analytic", ("bodies[0].velocity", [1.0, 0.0, 0.0]),
         "bodies[0].velocity", "has 3 coordinates; a 2-D scene gives a velocity as (x, z)",
         "Scene.bodies[0].velocity"),
    case("a body thrown faster than any water entry", "analytic", ("bodies[0].velocity", [0.0, 656.0]),
         "bodies[0].velocity", "656 m/s is beyond 100 m/s, above the fastest water entries these models serve",
         "Box.velocity"),
    case("a driven body given a velocity", "analytic",
         (("bodies[0].velocity", [1.0, 0.0]), ("bodies[0].motion", {"kind": "harmonic", "amplitude": 0.1,
                                                                      "period": 2.0})),
         "bodies[0].velocity", "a body with a prescribed motion moves as its motion says; leave velocity out",
         "Box.velocity"),
    case("a cylinder-tank in 2-D", "flume", ("domain", {"kind": "cylinder-tank", "diameter": 1.0, "depth": 0.3,
                                                        "height": 0.5}),
         "domain.kind", "a cylinder-tank is 3-D; set world.dim = 3", "Scene.domain.kind"),
    case("a sphere in 2-D", "analytic", ("bodies[1]", {"shape": "sphere", "name": "buoy", "radius": 0.3,
                                                       "pos": [8.0, 0.0], "mass": 150.0}),
         "bodies[1].shape", "a sphere is 3-D; in 2-D use a cylinder", "Scene.bodies[1].shape"),
    case("width in 2-D", "flume", ("domain", {"kind": "tank", "length": 3.0, "width": 1.0, "height": 0.45,
                                              "depth": 0.3}),
         "domain.width", "a 2-D scene is the x-z plane; leave width out", "Scene.domain.width"),
    case("no width in 3-D", "tank3d", ("domain.width", OUT), "domain.width", "a 3-D tank needs its width along y",
         "Scene.domain.width"),
    case("a 3-D cylinder without length", "tank3d", ("bodies[0].shape", "cylinder"), "bodies[0].length",
         "a 3-D cylinder needs its length [m]", "Scene.bodies[0].length"),
    case("a roll axis in 2-D", "flume", (("waves", OUT), ("domain", {"kind": "tank", "length": 3.0, "height": 0.45,
                                                                     "depth": 0.3}),
                                         ("base_motion", {"kind": "roll", "amplitude": 4.0, "period": 1.5,
                                                          "point": [1.5, 0.0], "axis": [0.0, 1.0, 0.0]})),
         "base_motion.axis", "a 2-D roll is about +y; leave axis out", "Scene.base_motion.axis"),
    # -- waves and fluids
    case("linear waves on the SPH fluid", "flume", ("waves", LINEAR), "waves.kind",
         "linear waves act on the analytic or potential fluid's bodies (fluid.model = \"analytic\"); the 'sph' fluid "
         "has none: make waves with a piston or flap in a flume", "Scene.waves.kind"),
    case("a piston on the analytic fluid", "analytic", ("waves", {"kind": "piston", "height": 0.04, "period": 1.0}),
         "waves.kind", "the analytic fluid takes the waves themselves: kind = \"linear\"", "Scene.waves.kind"),
    case("linear waves across a 2-D scene", "analytic", ("waves", dict(LINEAR, direction=30.0)), "waves.direction",
         "30.0 deg: a 2-D scene's waves travel along +x (0) or -x (180)", "Scene.waves.direction"),
    case("linear waves beyond breaking", "analytic", ("waves", dict(LINEAR, height=1.0, period=2.0)), "waves.height",
         "H/λ = 0.160 is beyond the breaking limit 1/7 (Michell 1893); lower H or lengthen T", "Scene.waves.height"),
    case("a piston's wave beyond Miche's limit on the analytic fluid", "flume",
         (("fluid", {"model": "analytic"}), ("waves", {"kind": "piston", "height": 0.19, "period": 1.04})),
         "waves.height", "H/λ = 0.1307 is beyond the breaking limit 0.142 tanh(kd) = 0.1222 at kd = 1.3 (Miche 1944)",
         "Scene.waves.height"),
    case("regular waves on the SPH fluid", "flume",
         ("waves", {"kind": "regular", "height": 0.04, "period": 1.0, "depth": 0.3}), "waves.kind",
         "regular waves act on the analytic or potential fluid's bodies (fluid.model = \"analytic\"); the 'sph' fluid has none: "
         "make waves with a piston or flap in a flume, or take the sea through a near field (domain.kind = \"nearfield\")",
         "Scene.waves.kind"),
    case("an irregular sea on the SPH fluid", "flume",
         ("waves", {"kind": "irregular", "hs": 0.04, "tp": 1.0, "depth": 0.3}), "waves.kind",
         "irregular waves act on the analytic or potential fluid's bodies", "Scene.waves.kind"),
    case("regular waves beyond Miche's limit", "analytic", ("waves", dict(REGULAR, height=6.5, period=6.0, depth=10.0)),
         "waves.height", "H/λ = 0.1343 is beyond the breaking limit 0.142 tanh(kd) = 0.1223 at kd = 1.3 (Miche 1944); "
         "lower H or lengthen T", "Scene.waves.height"),
    case("Stokes-2 waves with a secondary crest", "analytic",
         ("waves", dict(REGULAR, height=1.2, period=7.6, depth=5.0, theory="stokes2")), "waves.height",
         "a secondary crest rises in the trough, outside Stokes second order's range (Sorensen 2006, Eq. 3.6: H/λ <= "
         "0.0203 at d/λ = 0.0998; here H/λ = 0.0239, Ursell number H λ²/d³ = 24.1); lower H, or use theory = "
         "'linear'", "Scene.waves.height"),
    case("an unknown wave theory", "analytic", ("waves", dict(REGULAR, theory="stokes5")), "waves.theory",
         "'stokes5' is not accepted; did you mean 'stokes2'? Give one of 'linear', 'stokes2'", "RegularWaves.theory"),
    case("an unknown spectrum", "analytic", ("waves", dict(JONSWAP, spectrum="bretschneider")), "waves.spectrum",
         "'bretschneider' is not accepted; give one of 'jonswap', 'pierson-moskowitz', 'series'",
         "IrregularWaves.spectrum"),
    case("a spectrum without Hs", "analytic", ("waves", {k: v for k, v in JONSWAP.items() if k != "hs"}), "waves.hs",
         "is required with spectrum = 'jonswap': give the significant wave height [m]", "IrregularWaves.hs"),
    case("a JONSWAP gamma below 1", "analytic", ("waves", dict(JONSWAP, gamma=0.5)), "waves.gamma",
         "0.5 is out of range; give a number >= 1 and <= 7 (JONSWAP peak enhancement factor", "IrregularWaves.gamma"),
    case("a gamma for Pierson-Moskowitz", "analytic",
         ("waves", dict(JONSWAP, spectrum="pierson-moskowitz", gamma=2.0)), "waves.gamma",
         "the Pierson-Moskowitz spectrum has no peak enhancement; leave gamma out", "IrregularWaves.gamma"),
    case("deep-water waves on the analytic fluid", "analytic",
         ("waves", {"kind": "linear", "height": 0.1, "period": 5.0, "depth": math.inf}), "waves.depth",
         "inf (deep water) is the potential fluid's; the 'analytic' fluid's wave kinematics decay to a seabed: give "
         "the depth [m]", "Scene.waves.depth"),
    case("a spectrum's band upside down", "analytic", ("waves", dict(JONSWAP, band=[1.5, 0.7])), "waves.band",
         "[1.5, 0.7]: give the lowest and highest component frequency in peak frequencies, 0 < lo < hi",
         "IrregularWaves.band"),
    case("a band for a recorded series", "analytic", ("waves", dict(SERIES, band=[0.5, 2.0])), "waves.band",
         "a series' sea is its record; leave band out", "IrregularWaves.band"),
    case("a sea too steep", "analytic", ("waves", dict(JONSWAP, hs=9.0)), "waves.hs",
         "is beyond 0.1 (Lp the linear wavelength at the peak period): its largest waves would break",
         "Scene.waves.hs"),
    case("too few components for the run", "analytic", (("waves", dict(JONSWAP, components=20)),
                                                        ("world.duration", 600.0)), "waves.components",
         "the sea repeats itself every 45.71 s (2π/Δω), less than the run's 600 s; give at least 263 components",
         "Scene.waves.components"),
    case("an irregular sea across a 2-D scene", "analytic", ("waves", dict(JONSWAP, direction=30.0)),
         "waves.direction", "30.0 deg: a 2-D scene's waves travel along +x (0) or -x (180)", "Scene.waves.direction"),
    case("a series' field with a spectrum", "analytic", ("waves", dict(JONSWAP, min_period=1.0)), "waves.min_period",
         "belongs to spectrum = \"series\"; leave it out with 'jonswap'", "IrregularWaves.min_period"),
    case("a series without its file", "analytic", ("waves", {k: v for k, v in SERIES.items() if k != "file"}),
         "waves.file",
         "is required with spectrum = \"series\": give the record's file", "IrregularWaves.file"),
    # -- the near field
    case("a near field without a sea", "nearfield", ("waves", OUT), "waves",
         "a near field sits in an incident sea: give waves of kind \"regular\" or \"irregular\"", "Scene.waves"),
    case("a near field with a wavemaker", "nearfield", ("waves", {"kind": "piston", "height": 0.04, "period": 1.0}),
         "waves", "a near field sits in an incident sea", "Scene.waves"),
    case("a near field's sea against -x", "nearfield", ("waves.direction", 180.0), "waves.direction",
         "180 deg: the near field's end walls stand across x; give the sea along +x (0)", "Scene.waves.direction"),
    case("a near field's depth not the sea's", "nearfield", ("waves.depth", 0.4), "waves.depth",
         "0.4 m differs from the nearfield's still-water depth 0.3 m", "Scene.waves.depth"),
    case("a near field on the GPU on a symmetry plane", "nearfield3d", ("fluid.device", "cuda"), "domain.symmetry",
         "the symmetry plane's mirror images are made on the CPU only: with fluid.device = \"cuda\" simulate the "
         "whole box", "Scene.domain.symmetry"),
    case("a 2-D near field with a width", "nearfield", ("domain.width", 1.0), "domain.width",
         "a 2-D near field is the x-z plane; leave width out", "Scene.domain.width"),
    case("symmetry planes as sides of a channel with side zones", "nearfield3d", ("domain.sides", "symmetry"),
         "domain.sides", "set side_zones = false, or leave sides out", "Scene.domain.sides"),
    case("a channel between symmetry planes without its width", "nearfield3d",
         (("domain.sides", "symmetry"), ("domain.side_zones", False)), "domain.width",
         "a channel between symmetry planes needs its width", "Scene.domain.width"),
    case("a body in a channel between symmetry planes", "nearfield3d",
         (("domain.sides", "symmetry"), ("domain.side_zones", False), ("domain.width", 30.0)), "domain.sides",
         "a channel between symmetry planes carries a sea uniform across y and no bodies", "Scene.domain.sides"),
    case("walls below the water", "nearfield", ("domain.height", 0.2), "domain.height",
         "0.2 m must exceed the depth 0.3 m", "NearField.height"),
    case("a body in a relaxation zone", "nearfield", ("domain.x0", 1.0), "bodies[0].pos",
         "between its relaxation zones, of which there is none: the zones overlap", "Scene.bodies[0].pos"),
    case("a box too short for the body's motion", "nearfield", (("domain.zone", 0.5), ("domain.x0", 0.6),
                                                                 ("domain.x1", 1.8)), "bodies[0].pos",
         "the body and its reach 0.0455 m (the sea's orbit, doubled) span", "Scene.bodies[0].pos"),
    case("a pressure patch on a near field's wall", "nearfield",
         ("probes", {"pressure": [{"name": "w", "centre": [0.5, 0.1], "normal": [1.0, 0.0], "size": 0.05}]}),
         "probes.pressure", "a near field's walls are not a structure", "Scene.probes.pressure"),
    case("a near field shaken", "nearfield",
         ("base_motion", {"kind": "harmonic", "amplitude": 0.01, "period": 1.0}), "base_motion",
         "a near field follows its sea and does not move as a whole", "Scene.base_motion"),
    case("a symmetry plane in 2-D", "nearfield", ("domain.symmetry", True), "domain.symmetry",
         "a 2-D near field is the x-z plane; leave symmetry out", "Scene.domain.symmetry"),
    case("a channel's side walls in 2-D", "nearfield", ("domain.side_zones", False), "domain.side_zones",
         "a 2-D near field is the x-z plane, with no side walls; leave side_zones out", "Scene.domain.side_zones"),
    case("a body off the symmetry plane", "nearfield3d", ("bodies[0].pos", [70.0, 4.0]), "bodies[0].pos",
         "y = 4 m: with domain.symmetry each body is centred on the symmetry plane y = 0", "Scene.bodies[0].pos"),
    case("a body turned out of its mirror image", "nearfield3d", (("bodies[0].place", "given"),
                                                                  ("bodies[0].pos", [70.0, 0.0, 19.0]),
                                                                  ("bodies[0].euler", [0.0, 0.0, 30.0])),
         "bodies[0].euler", "with domain.symmetry a body turns about y only", "Scene.bodies[0].euler"),
    case("a fairlead without its mirror image", "nearfield3d",
         ("bodies[0].fairleads.starboard", [-1.5, -2.0, -1.5]), "bodies[0].fairleads.port",
         "has no mirror image (-1.5, -2.598, -1.5) among the body's fairleads", "Scene.bodies[0].fairleads.port"),
    case("a mooring line without its mirror image", "nearfield3d", ("moorings.lines[1].anchor", [51.5, 30.0, 0.0]),
         "moorings.lines[1]", "has no mirror image about y = 0", "Scene.moorings.lines[1]"),
    # -- a body's prescribed motion (bodies[].motion)
    case("a forced body's points going back in time", "analytic",
         ("bodies[1].motion", {"kind": "table", "dof": "surge", "points": [[0.0, 0.0], [2.0, 0.1], [1.0, 0.2]]}),
         "bodies[1].motion.points[2]", "t = 1 s does not follow t = 2 s", "ForcedTable.points[2]"),
    case("a forced body's points not starting at its pos", "analytic",
         ("bodies[1].motion", {"kind": "table", "dof": "surge", "points": [[0.0, 0.1], [1.0, 0.2]]}),
         "bodies[1].motion.points[0]", "s = 0.1 m: the motion starts at the body's pos", "ForcedTable.points[0]"),
    case("a forced body's single point", "analytic",
         ("bodies[1].motion", {"kind": "table", "dof": "surge", "points": [[0.0, 0.0]]}),
         "bodies[1].motion.points", "has 1 entries", "ForcedTable.points"),
    case("a forced body heaving beyond its draft", "analytic",
         ("bodies[1].motion", {"kind": "harmonic", "amplitude": 0.4, "period": 2.0}), "bodies[1].motion.amplitude",
         "0.4 m is not below the body's draft 0.3 m", "Scene.bodies[1].motion.amplitude"),
    case("a forced body swaying in 2-D", "analytic",
         ("bodies[1].motion", {"kind": "harmonic", "amplitude": 0.1, "period": 2.0, "dof": "sway"}),
         "bodies[1].motion.dof", "a 2-D scene is the x-z plane; give surge or heave", "Scene.bodies[1].motion.dof"),
    case("a forced body placed floating", "nearfield",
         ("bodies[0].motion", {"kind": "harmonic", "amplitude": 0.01, "period": 1.0}), "bodies[0].place",
         "has a prescribed motion about the pos it is given", "Scene.bodies[0].place"),
    case("a forced body with no amplitude", "analytic",
         ("bodies[1].motion", {"kind": "harmonic", "amplitude": 0.0, "period": 2.0}), "bodies[1].motion.amplitude",
         "a number [m] > 0", "ForcedMotion.amplitude"),
    # -- names and references
    case("a fairlead on an unknown body", "analytic", ("moorings.lines[0].fairlead", "boat.left"),
         "moorings.lines[0].fairlead", "no body named 'boat'; bodies: ['box', 'buoy']",
         "Scene.moorings.lines[0].fairlead"),
    case("an unknown fairlead", "analytic", ("moorings.lines[1].fairlead", "box.top"), "moorings.lines[1].fairlead",
         "body 'box' has no fairlead 'top'; its fairleads: ['left', 'right']", "Scene.moorings.lines[1].fairlead"),
    case("a fairlead not as BODY.NAME", "analytic", ("moorings.lines[0].fairlead", "box"),
         "moorings.lines[0].fairlead", "give it as BODY.NAME", "Line.fairlead"),
    # -- names that become folders, files and columns
    case("a scene name that climbs out of its folder", "analytic", ("name", "../../../x"), "name",
         "'../../../x' is not accepted; give a name of letters, digits, '_' and '-' (the scene's name: the default "
         "output folder out/NAME, plot titles)", "Scene.name"),
    case("a scene name with a path separator", "analytic", ("name", "runs/box"), "name",
         "'runs/box' is not accepted; give a name of letters, digits, '_' and '-'", "Scene.name"),
    case("a line name with a comma", "analytic", ("moorings.lines[0].name", "left,1"), "moorings.lines[0].name",
         "'left,1' is not accepted; give a name of letters, digits, '_' and '-', or names joined by single '.' (as "
         "BODY.NAME)", "Line.name"),
    case("a line name with a control character", "analytic", ("moorings.lines[1].name", "right\t"),
         "moorings.lines[1].name", "'right\\t' is not accepted; give a name of letters, digits", "Line.name"),
    case("a line name with two dots in a row", "analytic", ("moorings.lines[1].name", "box..right"),
         "moorings.lines[1].name", "'box..right' is not accepted", "Line.name"),
    case("a patch name with a comma", "flume", ("probes.pressure[0].name", "wall,1"), "probes.pressure[0].name",
         "'wall,1' is not accepted; give a name of letters, digits, '_' and '-' (the probe's name)", "Patch.name"),
    case("a fairlead with a path separator", "analytic", ("moorings.lines[0].fairlead", "box/left.x"),
         "moorings.lines[0].fairlead", "'box/left.x': give it as BODY.NAME, two names of letters, digits, '_' and "
         "'-'", "Line.fairlead"),
    case("two lines on one fairlead", "analytic", ("moorings.lines[1].fairlead", "box.left"),
         "moorings.lines[1].fairlead", "'box.left' is also the fairlead of moorings.lines[0]",
         "Scene.moorings.lines[1].fairlead"),
    case("duplicate body names", "analytic", ("bodies[1].name", "box"), "bodies[1].name",
         "'box' is also the name of bodies[0]; names must be unique", "Scene.bodies[1].name"),
    case("a probe naming an unknown body", "analytic", ("probes.motion", ["box", "boat"]), "probes.motion[1]",
         "no body named 'boat'; bodies: ['box', 'buoy'] (or \"all\")", "Scene.probes.motion[1]"),
    case("damping for an unknown body", "analytic", ("fluid.quadratic_damping", {"boat": [1.0] * 6}),
         "fluid.quadratic_damping.boat", "no body named 'boat'", "Scene.fluid.quadratic_damping.boat"),
    case("duplicate patch names", "flume", ("probes.pressure", [
        {"name": "wall", "centre": [3.0, 0.1], "normal": [-1.0, 0.0], "size": 0.05},
        {"name": "wall", "centre": [3.0, 0.2], "normal": [-1.0, 0.0], "size": 0.05}]),
         "probes.pressure[1].name", "'wall' is used twice", "Scene.probes.pressure[1].name"),
    case("a zero normal", "flume", ("probes.pressure[0].normal", [0.0, 0.0]), "probes.pressure[0].normal",
         "is a zero vector", "Patch.normal"),
    # -- what fits together
    case("nothing that moves", "analytic", (("bodies", []), ("moorings", OUT), ("fluid.linear_damping", {})),
         "bodies", "the scene has nothing that moves: give bodies, or the SPH fluid in a domain", "Scene.bodies"),
    case("SPH without a domain", "flume", ("domain", OUT), "domain", "the SPH fluid needs a domain", "Scene.domain"),
    case("a domain with the analytic fluid", "analytic",
         ("domain", {"kind": "tank", "length": 10.0, "height": 2.0, "depth": 1.0}), "domain",
         "with fluid.model = 'analytic' leave it out", "Scene.domain"),
    case("waves without a flume", "tank3d", ("waves", {"kind": "piston", "height": 0.02, "period": 1.0}), "waves",
         "a wavemaker needs a flume (domain.kind = \"flume\")", "Scene.waves"),
    case("base_motion on a flume", "flume",
         (("waves", OUT), ("base_motion", {"kind": "harmonic", "period": 1.0, "amplitude": 0.01})),
         "base_motion", "a flume does not move as a whole; use a tank", "Scene.base_motion"),
    case("waves and base_motion", "flume", ("base_motion", {"kind": "harmonic", "period": 1.0, "amplitude": 0.01}),
         "base_motion", "give one of waves and base_motion", "Scene.base_motion"),
    case("base_motion without a tank or a plate", "analytic",
         ("base_motion", {"kind": "harmonic", "period": 1.0, "amplitude": 0.01}), "base_motion",
         "base motion moves the SPH fluid's tank and the clamps of elastic plates; give a domain and fluid.model = "
         "\"sph\", or (fluid.model = \"none\") an elastic plate to shake", "Scene.base_motion"),
    case("mooring lines in a shaken tank", "tank3d",
         ("moorings", {"lines": [{"fairlead": "ball.top", "anchor": [0.5, 0.25, 0.0], "length": 0.3,
                                  "weight": 1.0}]}), "moorings",
         "mooring lines in a moving tank: their anchors are fixed in space and would not move with the tank's floor",
         "Scene.moorings"),
    case("gauges without SPH", "analytic", ("probes.gauges", [1.0]), "probes.gauges",
         "need the SPH fluid (fluid.model = \"sph\")", "Scene.probes.gauges"),
    case("fluid-first without SPH", "analytic", ("coupling.scheme", "fluid-first"), "coupling.scheme",
         "'fluid-first' needs the SPH fluid", "Scene.coupling.scheme"),
    case("a dynamic mooring model without EA", "analytic", ("moorings.model", "moordyn"), "moorings.lines[0].EA",
         "the 'moordyn' model needs it for every line; give it, or use model = \"catenary\"", "Moorings.lines[0].EA"),
    case("MoorDyn without a diameter", "analytic",
         (("moorings.model", "moordyn"), ("moorings.lines[0].EA", 1e5), ("moorings.lines[0].mass_per_length", 0.6)),
         "moorings.lines[0].diameter", "the 'moordyn' model needs it for every line", "Moorings.lines[0].diameter"),
    case("catenary lines without a seabed", "analytic", ("moorings.seabed", False), "moorings.seabed",
         "the 'catenary' model does not take it; give model = \"sph-cable\"", "Moorings.seabed"),
    case("a damping rate for the catenary", "analytic", ("moorings.damping", 1.0), "moorings.damping",
         "the 'catenary' model does not take it", "Moorings.damping"),
    case("a point load on a catenary line", "analytic",
         ("moorings.lines[1].point_loads", [{"s": 1.0, "force": [0.0, -10.0]}]), "moorings.lines[1].point_loads",
         "the 'catenary' model does not take it", "Moorings.lines[1].point_loads"),
    case("a point load beyond the line's end", "analytic",
         (("moorings.model", "sph-cable"), ("moorings.lines[0].EA", 1e5), ("moorings.lines[0].mass_per_length", 0.6),
          ("moorings.lines[1].EA", 1e5), ("moorings.lines[1].mass_per_length", 0.6),
          ("moorings.lines[0].point_loads", [{"s": 99.0, "force": [0.0, -10.0]}])),
         "moorings.lines[0].point_loads[0].s", "99 m is not inside the line", "Line.point_loads[0].s"),
    case("a released catenary line", "analytic", ("moorings.lines[0].released", True), "moorings.lines[0].released",
         "the 'catenary' model does not take it", "Moorings.lines[0].released"),
    case("a recorded point off the line", "analytic",
         (("moorings.model", "sph-cable"), ("moorings.lines[0].EA", 1e5), ("moorings.lines[0].mass_per_length", 0.6),
          ("moorings.lines[1].EA", 1e5), ("moorings.lines[1].mass_per_length", 0.6),
          ("moorings.lines[0].points", [1.0, -2.0])),
         "moorings.lines[0].points[1]", "-2 m is not on the line", "Line.points[1]"),
    case("moorings without lines", "analytic", ("moorings.lines", []), "moorings.lines",
         "give at least one line (or leave moorings out)", "Moorings.lines"),
    case("a floating body without a fluid", "analytic",
         (("fluid", {"model": "none"}), ("bodies[1].place", "floating"), ("bodies[1].pos", [8.0])),
         "bodies[1].place", "a floating body needs a fluid to float on", "Scene.bodies[1].place"),
    # -- geometry
    case("dx too coarse for the depth", "flume", ("fluid.dx", 0.2), "fluid.dx",
         "leaves fewer than 2 particles over the water depth 0.3 m; refine dx to at most 0.075 m", "Scene.fluid.dx"),
    case("a body outside the tank", "tank3d", (("bodies[0].place", "given"), ("bodies[0].pos", [0.98, 0.25, 0.1])),
         "bodies[0].pos", "the body reaches 0.93 .. 1.03 m along x, outside the domain's 0 .. 1 m",
         "Scene.bodies[0].pos"),
    case("a floating body with a full pos", "flume", ("bodies[0].pos", [1.2, 0.3]), "bodies[0].pos",
         "a floating body's height is computed; give its horizontal position only, (x,)", "Scene.bodies[0].pos"),
    case("a floating body turned", "flume", ("bodies[0].euler", [0.0, 10.0, 0.0]), "bodies[0].euler",
         "a floating body is placed upright", "Box.euler"),
    case("water block outside the tank", "tank3d",
         ("domain", {"kind": "tank", "length": 1.0, "width": 0.5, "height": 0.6,
                     "water": [{"lo": [0.0, 0.0, 0.0], "hi": [0.3, 0.5, 0.8]}]}),
         "domain.water[0]", "reaches outside the tank 0 .. [1.0, 0.5, 0.6] m", "Scene.domain.water[0]"),
    case("a water block upside down", "tank3d",
         ("domain", {"kind": "tank", "length": 1.0, "width": 0.5, "height": 0.6,
                     "water": [{"lo": [0.0, 0.0, 0.4], "hi": [0.3, 0.5, 0.2]}]}),
         "domain.water[0].hi", "must exceed lo = (0.0, 0.0, 0.4) in every coordinate", "Block.hi"),
    case("depth above the walls", "flume", ("domain.depth", 0.5), "domain.depth",
         "0.5 m must be below the wall height 0.45 m", "Flume.depth"),
    case("a beach beyond the flume", "flume", ("domain.beach", {"toe": 4.0, "slope": 0.3}), "domain.beach.toe",
         "4.0 m must lie inside the flume (< length 3.0 m)", "Flume.beach.toe"),
    case("an absorber as long as the flume", "flume", ("domain.absorber", {"length": 3.0}), "domain.absorber.length",
         "3.0 m must be shorter than the flume (length 3.0 m)", "Flume.absorber.length"),
    case("an absorber without a rate or wavemaker", "flume", (("waves", OUT), ("domain.absorber", {"length": 1.0})),
         "domain.absorber.rate", "give the zone's relaxation rate [1/s]", "Scene.domain.absorber.rate"),
    case("a body in a flume's absorber", "flume", ("domain.absorber", {"length": 2.0}), "bodies[0].pos",
         "the body reaches x = 1.3 m, into the flume's absorbing zone (1 .. 3 m)", "Scene.bodies[0].pos"),
    case("an absorber on the analytic fluid", "flume", (("fluid", {"model": "analytic"}),
                                                       ("domain.absorber", {"length": 1.0})),
         "domain.absorber", "the analytic fluid takes the flume's end as absorbing already",
         "Scene.domain.absorber"),
    case("a polygon without area", "flume", (("waves", OUT), ("domain", {"kind": "polygon", "fill_level": 0.5,
                                                                        "vertices": [[0, 0], [1, 1], [2, 2]]})),
         "domain.vertices", "the polygon has no area", "PolygonTank.vertices"),
    case("a gauge outside the flume", "flume", ("probes.gauges", [0.6, 3.5]), "probes.gauges[1]",
         "x = 3.5 m lies outside the domain's 0 .. 3 m; put the gauge over the water", "Scene.probes.gauges[1]"),
    case("a 3-D gauge beside the tank", "tank3d", ("probes.gauges", [[0.1, 0.7]]), "probes.gauges[0]",
         "[0.1, 0.7]: y = 0.7 m lies outside the domain's 0 .. 0.5 m", "Scene.probes.gauges[0]"),
    case("a wavemaker beyond the breaking limit", "flume", ("waves.height", 0.5), "waves.height",
         "is beyond the breaking limit 1/7; lower H or lengthen T", "Scene.waves.height"),
    case("a wavemaker without gravity", "flume", ("world.gravity", 0.0), "world.gravity",
         "a wavemaker's waves need gravity > 0", "Scene.world.gravity"),
    # -- where things start: bodies in the water and apart, lines that reach, water that holds particles
    case("a body below the floor", "tank3d", (("bodies[0].place", "given"), ("bodies[0].pos", [0.5, 0.25, 0.02])),
         "bodies[0].pos", "the body reaches -0.03 .. 0.07 m along z, outside the domain's 0 .. 0.6 m",
         "Scene.bodies[0].pos"),
    case("a body in a flume's beach", "flume", (("domain.beach", {"toe": 2.0, "slope": 0.3}),
                                               ("bodies[0].place", "given"), ("bodies[0].pos", [2.6, 0.1])),
         "bodies[0].pos", "the body's corner (2.7, 0.05) m (in x-z) lies 0.153 m deep in the beach; move it",
         "Scene.bodies[0].pos"),
    case("a body in a cylinder tank's round wall", "tank3d",
         (("domain", {"kind": "cylinder-tank", "diameter": 1.0, "depth": 0.2, "height": 0.6}),
          ("bodies[0].pos", [0.4, 0.3])),
         "bodies[0].pos", "the body reaches 0.55 m from the tank's axis, beyond its radius 0.5 m, into the round wall",
         "Scene.bodies[0].pos"),
    case("two bodies overlapping", "analytic", ("bodies[1].pos", [4.0, 0.0]), "bodies[1].pos",
         "body 'buoy' (x 3.7 .. 4.3 m, z -0.3 .. 0.3 m) overlaps body 'box' (bodies[0], x 2 .. 4 m, z -0.5 .. 0.5 m) "
         "at the start", "Scene.bodies[1].pos"),
    case("two floating bodies on one footprint", "tank3d",
         ("bodies", [{"shape": "sphere", "name": "ball", "radius": 0.05, "pos": [0.5, 0.25], "place": "floating",
                      "density": 500.0},
                     {"shape": "sphere", "name": "ball2", "radius": 0.05, "pos": [0.55, 0.25], "place": "floating",
                      "density": 500.0}]),
         "bodies[1].pos", "both float, so their footprints must be apart", "Scene.bodies[1].pos"),
    case("a fairlead below its anchor's seabed", "analytic", ("moorings.lines[0].anchor", [-20.0, 0.0]),
         "moorings.lines[0].anchor", "the fairlead 'box.left' starts at z = -0.5 m, below this anchor's seabed "
         "z = 0 m", "Scene.moorings.lines[0].anchor"),
    case("a line too short to reach", "analytic", ("moorings.lines[1].length", 15.0), "moorings.lines[1].length",
         "15 m is shorter than the straight distance 18.61 m from the anchor (20, -10) m to the fairlead 'box.right' "
         "at (4, -0.5) m at the start", "Scene.moorings.lines[1].length"),
    case("two lines with one label", "analytic",
         (("moorings.lines[0].name", "chain"), ("moorings.lines[1].name", "chain")), "moorings.lines[1].name",
         "'chain' is also the label of moorings.lines[0]", "Scene.moorings.lines[1].name"),
    case("a water block thinner than dx", "tank3d",
         ("domain", {"kind": "tank", "length": 1.0, "width": 0.5, "height": 0.6,
                     "water": [{"lo": [0.0, 0.0, 0.0], "hi": [0.3, 0.5, 0.01]}]}),
         "domain.water[0]", "the block is 0.01 m thick along z, less than one particle spacing (fluid.dx = 0.02 m): "
         "it would hold no particle", "Scene.domain.water[0]"),
    case("two water blocks overlapping", "tank3d",
         ("domain", {"kind": "tank", "length": 1.0, "width": 0.5, "height": 0.6,
                     "water": [{"lo": [0.0, 0.0, 0.0], "hi": [0.3, 0.5, 0.3]},
                               {"lo": [0.2, 0.0, 0.0], "hi": [0.5, 0.5, 0.2]}]}),
         "domain.water[1]", "overlaps domain.water[0]", "Scene.domain.water[1]"),
    case("a polygon that crosses itself", "flume",
         (("waves", OUT), ("domain", {"kind": "polygon", "fill_level": 0.5,
                                      "vertices": [[0.0, 0.0], [3.0, 0.0], [0.0, 1.0], [1.0, 1.0]]})),
         "domain.vertices", "edge 1 ((3, 0) to (0, 1) m) and edge 3 ((1, 1) to (0, 0) m) cross",
         "Scene.domain.vertices"),
    case("an arch rib filled over its crown", "flume", (("waves", OUT), ("domain", {"kind": "arch-rib", "level": 24.5})),
         "domain.level", "24.5 m is at or above the crown's inner top 24.06 m (rise 23.333 m + inner_height / 2): the "
         "water would not fit", "ArchRib.level"),
    case("an arch rib filled below its springings", "flume",
         (("waves", OUT), ("domain", {"kind": "arch-rib", "level": -1.0})),
         "domain.level", "-1.0 m is at or below the springings (z = 0): the legs would hold no water", "ArchRib.level"),
    case("an arch rib taller inside than its rise", "flume",
         (("waves", OUT), ("domain", {"kind": "arch-rib", "rise": 2.0, "inner_height": 3.0, "level": 1.0})),
         "domain.inner_height", "3.0 m is not below the rise 2.0 m: the rib would have no legs to hold water",
         "ArchRib.inner_height"),
    case("an arch rib too narrow for dx", "flume",
         (("waves", OUT), ("domain", {"kind": "arch-rib"}), ("fluid.dx", 0.6)),
         "fluid.dx", "0.6 m leaves fewer than 3 particles across the rib's cavity (inner_height 1.458 m)",
         "Scene.fluid.dx"),
    case("a pressure patch outside the domain", "flume", ("probes.pressure[0].centre", [3.5, 0.1]),
         "probes.pressure[0].centre", "(3.5, 0.1) m lies outside the domain (x 0 .. 3 m, z 0 .. 0.45 m)",
         "Scene.probes.pressure[0].centre"),
    case("a pressure patch off the wall", "flume", ("probes.pressure[0].centre", [2.5, 0.1]),
         "probes.pressure[0].centre", "(2.5, 0.1) m lies in the water, 0.1 m from the nearest wall",
         "Scene.probes.pressure[0].centre"),
    case("a pressure patch facing out of the water", "flume", ("probes.pressure[0].normal", [1.0, 0.0]),
         "probes.pressure[0].normal", "[1.0, 0.0] does not point into the water from the wall at (3, 0.1) m, whose "
         "normal into the domain is (-1, 0); give that normal, e.g. [-1.0, 0.0]", "Scene.probes.pressure[0].normal"),
    case("a pressure patch smaller than dx", "flume", ("probes.pressure[0].size", 0.01), "probes.pressure[0].size",
         "0.01 m is less than one particle spacing (fluid.dx = 0.02 m)", "Scene.probes.pressure[0].size"),
    # -- elastic plates
    case("an elastic plate beyond the tank's end", "plate", ("bodies[0].base", [0.7, 0.0]), "bodies[0].base",
         "the body reaches 0.694 .. 0.706 m along x, outside the domain's 0 .. 0.584 m; move it inside the tank",
         "Scene.bodies[0].base"),
    case("an elastic plate taller than the tank", "plate", ("bodies[0].length", 0.4), "bodies[0].base",
         "the body reaches 0 .. 0.4 m along z, outside the domain's 0 .. 0.32 m", "Scene.bodies[0].base"),
    case("an elastic plate off the floor", "plate", ("bodies[0].base", [0.298, 0.05]), "bodies[0].base",
         "z = 0.05 m: the plate is clamped by its foot to the tank's floor at z = 0 m; give base z = 0",
         "Scene.bodies[0].base"),
    case("an elastic plate under two particle spacings thick", "plate", ("bodies[0].thickness", 0.006),
         "bodies[0].thickness", "0.006 m is 1.2 particle spacings (dx = 0.005 m): 1 boundary particle across, which "
         "lies on the mid-plane and holds neither side's fluid properly; refine fluid.dx to 0.003 m or less, or set "
         "thin_wall = true", "Scene.bodies[0].thickness"),
    case("an elastic plate with E = 0", "plate", ("bodies[0].E", 0.0), "bodies[0].E",
         "0.0 [Pa] is out of range; give a number [Pa] > 0 and <= 1.2e+12 (Young's modulus)", "ElasticPlate.E"),
    case("an elastic plate of negative density", "plate", ("bodies[0].density", -2500.0), "bodies[0].density",
         "-2500.0 [kg/m^3] is out of range; give a number [kg/m^3] > 0", "ElasticPlate.density"),
    case("a 2-D elastic plate with a width", "plate", ("bodies[0].width", 0.1), "bodies[0].width",
         "a 2-D plate is 1 m wide (the scene's depth); leave width out", "Scene.bodies[0].width"),
    case("too few elements for an elastic plate", "plate", ("bodies[0].elements", 3), "bodies[0].elements",
         "3 is out of range; give a whole number >= 4", "ElasticPlate.elements"),
    case("an elastic plate turned sideways", "plate", ("bodies[0].direction", "sideways"), "bodies[0].direction",
         "'sideways' is not accepted; give one of 'up', 'down'", "ElasticPlate.direction"),
    case("a turned elastic plate in the SPH fluid", "plate", ("bodies[0].angle", 90.0), "bodies[0].angle",
         "90 deg: the SPH fluid's boundary stands a plate on the tank's floor", "Scene.bodies[0].angle"),
    case("a hanging elastic plate turned", "plate", (("bodies[0].direction", "down"), ("bodies[0].angle", 30.0)),
         "bodies[0].angle", "30 deg: a hanging plate (direction = \"down\") hangs along -z", "ElasticPlate.angle"),
    case("an elastic plate turned beyond a half turn", "plate", ("bodies[0].angle", 270.0), "bodies[0].angle",
         "270.0 [deg] is out of range; give a number [deg] >= -180 and <= 180", "ElasticPlate.angle"),
    case("a hanging elastic plate through the floor", "plate", ("bodies[0].direction", "down"), "bodies[0].base",
         "z = 0 m: a hanging plate 0.08 m long clamped there reaches z = -0.08 m, below the tank's floor at z = 0 m; "
         "give base z >= 0.08 or a shorter length", "Scene.bodies[0].base"),
    # -- physics: what cannot happen (cosim.scene.plausible, cosim.scene.limits)
    case("fairleads given in world coordinates", "analytic",
         (("bodies[0].fairleads", {"left": [2.0, -0.5], "right": [4.0, -0.5]}), ("moorings.lines[0].EA", 1e7),
          ("moorings.lines[1].EA", 1e7)), "bodies[0].fairleads.left",
         "(2, -0.5) m is 2.062 m from the body's centre, beyond 1.677 m (1.5 times its bounding radius 1.118 m): a "
         "fairlead lies on or near the hull, in the body's frame (from its centre), not in the world's; if (2, -0.5) "
         "is where it is in the world, give (-1, -0.5)", "Scene.bodies[0].fairleads.left"),
    case("a turned body's corner below the floor", "tank3d",
         ("bodies", [{"shape": "box", "name": "box", "size": [0.2, 0.2, 0.1], "pos": [0.5, 0.25, 0.08],
                      "density": 500.0, "euler": [30.0, 30.0, 0.0]}]), "bodies[0].pos",
         "the body (turned by euler = (30, 30, 0) deg) reaches -0.0508013 .. 0.210801 m along z, outside the "
         "domain's 0 .. 0.6 m", "Scene.bodies[0].pos"),
    case("a 2-D body turned out of its plane", "analytic", ("bodies[0].euler", [10.0, 0.0, 0.0]), "bodies[0].euler",
         "[10.0, 0.0, 0.0]: a 2-D body turns in the x-z plane, about y only (its 1 m depth stays along y); give [0, "
         "angle, 0]", "Scene.bodies[0].euler"),
    case("a 2-D cylinder turned", "analytic", ("bodies[1].euler", [0.0, 30.0, 0.0]), "bodies[1].euler",
         "a 2-D cylinder is a circle in the x-z plane: turned, it is the same circle; leave euler out",
         "Scene.bodies[1].euler"),
    case("a body against a turned one", "analytic", (("bodies[0].euler", [0.0, 45.0, 0.0]), ("bodies[1].pos", [4.1, 0.0])),
         "bodies[1].pos", "body 'buoy' (x 3.8 .. 4.4 m, z -0.3 .. 0.3 m) overlaps body 'box' (turned by euler = (0, "
         "45, 0) deg) (bodies[0], x 1.939 .. 4.061 m, z -1.061 .. 1.061 m) at the start", "Scene.bodies[1].pos"),
    case("a floating body without gravity", "tank3d", ("world.gravity", 0.0), "world.gravity",
         "0 m/s^2: body 'ball' (bodies[0]) is placed floating, but without gravity there is no buoyancy (nor weight) "
         "to float it", "Scene.world.gravity"),
    case("gravity beyond 100 g", "analytic", ("world.gravity", 1e4), "world.gravity",
         "10000 [m/s^2] is beyond 980.665 [m/s^2], 100 g, the most a geotechnical centrifuge applies to a model",
         "World.gravity"),
    case("a 2-D gravity of 3 components", "analytic", ("world.gravity", [0.0, 0.0, -9.81]), "world.gravity",
         "has 3 components; a 2-D scene's gravity is (gx, gz) [m/s^2], or a number along -z", "World.gravity"),
    case("a tilted gravity on the analytic fluid", "analytic", ("world.gravity", [1.0, -9.81]), "world.gravity",
         "5.82 deg from -z: the analytic fluid's hydrostatics hold the free surface at a height",
         "Scene.world.gravity"),
    case("a tilted gravity under waves", "flume", ("world.gravity", [1.0, -9.81]), "world.gravity",
         "waves travel on a free surface under gravity along -z", "Scene.world.gravity"),
    case("a floating body under a tilted gravity", "tank3d", ("world.gravity", [0.0, 1.0, -9.81]),
         "bodies[0].place", "\"floating\" finds a waterline at a height, under gravity along -z",
         "Scene.bodies[0].place"),
    case("mooring lines under a tilted gravity", "analytic",
         (("fluid", {"model": "none"}), ("world.gravity", [1.0, -9.81])), "moorings.model",
         "'catenary': the mooring models take each line's weight along -z", "Scene.moorings.model"),
    case("a tank too low for its water under a tilted gravity", "tank2d", ("world.gravity", [6.0, -9.81]),
         "world.gravity", "the water at rest under it, its surface normal to gravity, stands 0.6058 m high at the "
         "tank's wall, over its height (0.6 m)", "Scene.world.gravity"),
    case("a body denser than osmium", "analytic", ("bodies[0].density", 1e308), "bodies[0].density",
         "1e+308 [kg/m^3] is beyond 22590 [kg/m^3], osmium's, the densest element", "Box.density"),
    case("a body's mass denser than osmium", "analytic", ("bodies[1].mass", 1e7), "bodies[1].mass",
         "1e+07 kg in 0.2827 m^3 per metre of depth is a mean density of 3.537e+07 kg/m^3, beyond 22590",
         "Scene.bodies[1].mass"),
    case("water denser than osmium", "analytic", ("fluid.rho", 1e5), "fluid.rho",
         "100000 [kg/m^3] is beyond 22590 [kg/m^3]", "Analytic.rho"),
    case("an elastic plate with E = 1e30", "plate", ("bodies[0].E", 1e30), "bodies[0].E",
         "1e+30 [Pa] is beyond 1.2e+12 [Pa], diamond's, the stiffest material", "ElasticPlate.E"),
    case("a line weight of 1e308", "analytic", ("moorings.lines[0].weight", 1e308), "moorings.lines[0].weight",
         "1e+308 [N/m] is beyond 100000 [N/m], ten times the heaviest offshore chain's", "Line.weight"),
    case("a line stiffer than any tendon", "analytic", ("moorings.lines[1].EA", 1e13), "moorings.lines[1].EA",
         "1e+13 [N] is beyond 1e+11 [N], four times a tension-leg platform's steel tendon", "Line.EA"),
    case("a line heavier in water than in air", "analytic", ("moorings.lines[0].mass_per_length", 1.0),
         "moorings.lines[0].weight", "50 N/m is more than the line weighs in air, mass_per_length x g = 1 x 9.81 = "
         "9.81 N/m", "Scene.moorings.lines[0].weight"),
    case("an elastic line's anchor in millimetres", "analytic",
         (("moorings.lines[0].anchor", [-20000.0, -10000.0]), ("moorings.lines[0].EA", 1e7)),
         "moorings.lines[0].length", "25 m is shorter than the straight distance 2.236e+04 m from the anchor (-2e+04, "
         "-1e+04) m to the fairlead 'box.left' at the start: the elastic line would start stretched by 8.93e+04 %",
         "Scene.moorings.lines[0].length"),
    case("an elastic line stretched beyond 30 %", "analytic",
         (("moorings.lines[1].length", 14.0), ("moorings.lines[1].EA", 1e7)), "moorings.lines[1].length",
         "14 m is shorter than the straight distance 18.61 m from the anchor (20, -10) m to the fairlead 'box.right' at "
         "the start: the elastic line would start stretched by 32.9 %, beyond 30 %", "Scene.moorings.lines[1].length"),
    case("an MJCF line too short to reach", "mjcf", ("moorings.lines[0].length", 5.0), "moorings.lines[0].length",
         "5 m is shorter than the straight distance 10.25 m from the anchor (0, 0, -10) m to the fairlead 'float.top' at "
         "the start: an inextensible line cannot reach", "Scene.moorings.lines[0].length"),
    case("a floating body's elastic line stretched beyond 30 %", "flume",
         (("moorings.lines[0].anchor", [0.2, 0.0]), ("moorings.lines[0].length", 0.5), ("moorings.lines[0].EA", 1e5)),
         "moorings.lines[0].length", "0.5 m is shorter than the straight distance 0.922 m from the anchor (0.2, 0) m "
         "to the fairlead 'box.left' at the nearest it comes, over every draft: the elastic line would start "
         "stretched by 84.4 %", "Scene.moorings.lines[0].length"),
    case("a shake beyond 5 g", "tank3d", ("base_motion.amplitude", 2.0), "base_motion.amplitude",
         "the shaking (2 m at 1 s: amplitude (2 pi / period)^2) peaks at 78.96 m/s^2 (8.05 g), beyond 49.03 m/s^2 (5 g)",
         "Scene.base_motion.amplitude"),
    case("a shake's acceleration beyond 5 g", "tank3d",
         ("base_motion", {"kind": "harmonic", "period": 1.0, "direction": [1.0, 0.0, 0.0], "acceleration": 100.0}),
         "base_motion.acceleration", "the shaking peaks at 100 m/s^2 (10.2 g), beyond 49.03 m/s^2 (5 g)",
         "Scene.base_motion.acceleration"),
    case("a roll beyond 5 g", "tank2d", ("base_motion", {"kind": "roll", "amplitude": 30.0, "period": 0.5,
                                                         "point": [0.5, 0.0]}), "base_motion.amplitude",
         "the roll (30 deg at 0.5 s, at the tank's corner 0.781 m from the axis) peaks at", "Scene.base_motion.amplitude"),
    case("a table of motion scaled beyond 5 g", "tank2d", ("base_motion.scale", 1000.0), "base_motion.scale",
         "the table's motion (times scale = 1000) peaks at", "Scene.base_motion.scale"),
    case("an earthquake scaled to 1e8 g", "tank2d", ("base_motion", {"kind": "earthquake", "file": "quake.AT2",
                                                                     "scale": 1e8}), "base_motion.scale",
         "the record times scale = 1e+08 peaks at 1.961e+07 m/s^2 (2e+06 g), beyond 49.03 m/s^2 (5 g), more than the "
         "strongest shaking tables and recorded earthquakes reach (about 3-4 g); give a scale up to 250", "Scene.base_motion.scale"),
    case("a ground motion scaled beyond 5 g", "tank2d",
         ("base_motion", {"kind": "ground_motion", "hold": True, "components": [
             {"file": "quake.AT2", "direction": [1.0, 0.0], "scale": 1000.0}]}), "base_motion.components[0].scale",
         "record 0 times its scales (1 x 1000) peaks at 196.1 m/s^2 (20 g)", "Scene.base_motion.components[0].scale"),
    case("two ground-motion records along one axis", "tank2d",
         ("base_motion", {"kind": "ground_motion", "hold": True, "components": [
             {"file": "quake.AT2", "direction": [1.0, 0.0]}, {"file": "quake.AT2", "direction": [2.0, 0.0]}]}),
         "base_motion.components[1].direction", "(2, 0) is along the same axis as base_motion.components[0].direction "
         "(1, 0) (the angle between them is 0 deg): each record is the ground's motion along its own axis",
         "Scene.base_motion.components[1].direction"),
    case("ground-motion records not perpendicular", "tank2d",
         ("base_motion", {"kind": "ground_motion", "hold": True, "components": [
             {"file": "quake.AT2", "direction": [1.0, 0.0]}, {"file": "quake.AT2", "direction": [1.0, 1.0]}]}),
         "base_motion.components[1].direction", "(1, 1) is not perpendicular to base_motion.components[0].direction "
         "(1, 0) (the angle between them is 45 deg)", "Scene.base_motion.components[1].direction"),
    case("a body beyond the Earth's radius", "analytic", ("bodies[1].pos", [1e30, 0.0]), "bodies[1].pos",
         "1e+30 m is beyond 6.371e+06 m, the Earth's radius: a scene lies on the Earth; check the units (m)",
         "Scene.bodies[1].pos"),
    case("a box 5e-324 m high", "analytic", ("bodies[0].size", [2.0, 5e-324]), "bodies[0].size",
         "4.94066e-324 m is below 1e-06 m, a micron: the water round it is no continuum for these models",
         "Scene.bodies[0].size"),
    case("a body lighter than air", "analytic", ("bodies[0].density", 1e-3), "bodies[0].density",
         "0.001 kg/m^3 is below 0.1 kg/m^3, a tenth of air's density: no body or liquid is that light",
         "Scene.bodies[0].density"),
    case("a body's mass lighter than air", "analytic", ("bodies[1].mass", 1e-5), "bodies[1].mass",
         "1e-05 kg in 0.2827 m^3 is a mean density of 3.537e-05 kg/m^3, below 0.1, a tenth of air's",
         "Scene.bodies[1].mass"),
    case("a speed of sound below the long-wave speed", "flume", ("fluid.c0", 0.1), "fluid.c0",
         "gives a speed of sound of 0.1 m/s, below the water's long-wave speed sqrt(g h) = 1.716 m/s",
         "Scene.fluid.c0"),
    case("a gauge on the wall", "flume", ("probes.gauges", [0.0, 1.6]), "probes.gauges[0]",
         "x = 0 m is on the domain's wall (within half a particle spacing, 0.01 m, of 0 .. 3 m), where no free surface "
         "is found", "Scene.probes.gauges[0]"),
    case("a coupling step longer than the run", "analytic", ("coupling.dt", 20.0), "coupling.dt",
         "20 s is longer than the run (10 s)", "Scene.coupling.dt"),
    case("fluid steps per exchange without an SPH fluid", "analytic", ("coupling.fluid_steps", 4),
         "coupling.fluid_steps", "this scene has no SPH fluid: leave coupling.fluid_steps out (1)",
         "Scene.coupling.fluid_steps"),
    case("fluid steps per exchange of none", "flume", ("coupling.fluid_steps", 0), "coupling.fluid_steps",
         "0 is out of range; give a whole number from 1 to 100", "Coupling.fluid_steps"),
    case("a paddle stroke beyond the flume", "flume", ("waves.period", 100.0), "waves.period",
         "waves of 0.04 m at 100 s in 0.3 m of water need a paddle stroke of 3.64 m (linear wavemaker theory): the "
         "paddle would sweep 1.82 m into the flume", "Scene.waves.period"),
    case("a body in the paddle's sweep", "flume", ("bodies[0].pos", [0.11]), "bodies[0].pos",
         "the body starts at x = 0.01 m, within the paddle's sweep", "Scene.bodies[0].pos"),
    # -- times and files
    case("plot_at before the run", "flume", ("world.plot_at", [2.5, -1.0]), "world.plot_at[1]",
         "-1.0 s lies before the run's start (0 s); give a time >= 0", "World.plot_at[1]"),
    case("a coupling step that does not divide the samples", "analytic",
         (("world.sample_every", 0.05), ("coupling.dt", 0.016)), "coupling.dt",
         "0.016 s does not divide world.sample_every = 0.05 s (3.125 steps): the run stops exactly at each output "
         "time, so the step before each would be cut short and 0.016 s would not be the step used; give a step that "
         "divides the output intervals, e.g. 0.0125 s or 0.0166667 s", "Scene.coupling.dt"),
    case("sample_every longer than the run", "flume", ("world.sample_every", 10.0), "world.sample_every",
         "10.0 s is longer than the run (5.0 s)", "World.sample_every"),
    case("the 2-D default direction in 3-D", "tank3d", ("base_motion.direction", OUT), "base_motion.direction",
         "a 3-D scene needs the direction as (x, y, z), e.g. [1, 0, 0]", "Scene.base_motion.direction"),
    case("a ground motion without records", "tank2d", ("base_motion", {"kind": "ground_motion", "components": []}),
         "base_motion.components", "is empty; give at least one record", "GroundMotion.components"),
    case("more ground-motion records than axes", "tank2d",
         ("base_motion", {"kind": "ground_motion", "hold": True,
                          "components": [{"file": "quake.AT2", "direction": d} for d in ([1.0, 0.0], [0.0, 1.0],
                                                                                         [1.0, 1.0])]}),
         "base_motion.components", "has 3 records; a 2-D scene moves along at most 2 axes (x, z): give one record "
         "per direction", "Scene.base_motion.components"),
    case("a ground-motion direction of the wrong size", "tank2d",
         ("base_motion", {"kind": "ground_motion", "hold": True,
                          "components": [{"file": "quake.AT2", "direction": [0.0, 0.0, 1.0]}]}),
         "base_motion.components[0].direction", "[0.0, 0.0, 1.0] has 3 coordinates; a 2-D scene gives a direction "
         "as (x, z)", "Scene.base_motion.components[0].direction"),
    case("a ground-motion stop after its records end", "tank2d",
         ("base_motion", {"kind": "ground_motion", "stop": 0.5, "fade": 0.02,
                          "components": [{"file": "quake.AT2", "direction": [1.0, 0.0]}]}),
         "base_motion.stop", "= 0.5 s lies after the end of base_motion.components[0]'s record (0.09 s); give at most "
         "0.09 s", "Scene.base_motion.stop"),
    case("a ground-motion stop inside its fade", "tank2d",
         ("base_motion", {"kind": "ground_motion", "stop": 0.05,
                          "components": [{"file": "quake.AT2", "direction": [1.0, 0.0]}]}),
         "base_motion.stop", "= 0.05 s leaves no room for the 0.5 s fade before it", "GroundMotion.stop"),
    case("a missing file", "tank3d",
         ("base_motion", {"kind": "table", "file": "nowhere.csv", "direction": [1.0, 0.0, 0.0]}), "base_motion.file",
         "no file 'nowhere.csv' (a relative path is read from the scene file's folder)", "Scene.base_motion.file"),
    case("a tank's inner wall outside the tank", "tank2d", ("domain.walls", [{"lo": [0.5, 0.0], "hi": [1.2, 0.3]}]),
         "domain.walls[0]", "the block [0.5, 0.0] .. [1.2, 0.3] m reaches outside the tank 0 .. [1.0, 0.6] m",
         "Scene.domain.walls[0]"),
    case("two inner walls overlapping", "tank2d",
         ("domain.walls", [{"lo": [0.2, 0.0], "hi": [0.3, 0.4]}, {"lo": [0.25, 0.0], "hi": [0.35, 0.4]}]),
         "domain.walls[1]", "overlaps domain.walls[0] ([0.2, 0.0] .. [0.3, 0.4] m)", "Scene.domain.walls[1]"),
    case("a water block overlapping an inner wall", "tank2d",
         (("domain.depth", OUT), ("domain.water", [{"lo": [0.0, 0.0], "hi": [0.3, 0.3]}]),
          ("domain.walls", [{"lo": [0.25, 0.0], "hi": [0.35, 0.4]}])),
         "domain.water[0]", "overlaps the solid domain.walls[0] ([0.25, 0.0] .. [0.35, 0.4] m); let the water end "
         "where the wall begins", "Scene.domain.water[0]"),
    case("a recorded roll that does not start level", "tank2d",
         ("base_motion", {"kind": "roll_table", "file": "roll.txt", "point": [0.5, 0.0], "column": 2}),
         "base_motion.file", "the record's first angle (3 deg at t = 0 s) turns the tank's farthest corner 0.04089 m "
         "from where the walls are built at t = 0", "Scene.base_motion.file"),
    case("a recorded roll scaled past any tank's acceleration", "tank2d",
         ("base_motion", {"kind": "roll_table", "file": "roll.txt", "point": [0.5, 0.0], "scale": 1e4}),
         "base_motion.scale", "the recorded roll (times scale = 10000, at the tank's corner 0.781 m from the axis)",
         "Scene.base_motion.scale"),
    case("a 2-D recorded roll given an axis", "tank2d",
         ("base_motion", {"kind": "roll_table", "file": "roll.txt", "point": [0.5, 0.0], "axis": [0.0, 1.0, 0.0]}),
         "base_motion.axis", "a 2-D roll is about +y; leave axis out", "Scene.base_motion.axis"),
    case("a missing MJCF file", "analytic", (("bodies", [{"shape": "mjcf", "file": "boat.xml"}]),
                                             ("fluid.linear_damping", {})),
         "bodies[0].file", "no file 'boat.xml'", "Scene.bodies[0].file"),
    # -- --set
    case("--set to a list index that does not exist", "analytic", "bodies[5].density=600", "bodies[5].density",
         "there is no entry 5 of bodies (the list has 2; the last is [1])", None),
    case("--set on a list without an index", "analytic", "bodies.density=600", "bodies.density",
         "bodies is a list of 2, not a table; give an entry, e.g. bodies[0].density", None),
    case("--set under a value", "analytic", "world.dim.x=1", "world.dim.x", "world.dim is 2, not a table", None),
    case("--set without a value", "analytic", "fluid.rho", "fluid.rho", "give --set as KEY.PATH=VALUE", None),
    case("--set with a bad key path", "analytic", "fluid..rho=1000", "fluid..rho", "is not a key path", None),
]


AT2_HEAD = "PEER RECORD\nSYNTHETIC, 2024, STATION, 000\nACCELERATION TIME SERIES IN UNITS OF G\n"
MOVING_XML = ('<mujoco><worldbody><body name="float"><freejoint/>\n'
              '<geom type="box" sizes="0.5 0.5 0.25"/></body></worldbody></mujoco>\n')

#: the contents of the files a scene names (written into the working folder first)
FILE_CASES = [
    # -- an elevation record
    case("Hs with a series", "analytic", ("waves", dict(SERIES, hs=1.0)), "waves.hs",
         "a series' sea is its record; leave hs out", "IrregularWaves.hs", files={"eta.txt": ETA_TXT}),
    case("a series that does not exist", "analytic", ("waves", dict(SERIES, file="none.txt")), "waves.file",
         "no file 'none.txt' (a relative path is read from the scene file's folder)", "Scene.waves.file"),
    case("a series shorter than the run", "analytic", ("waves", dict(SERIES, file="short.txt")), "waves.file",
         "the sea repeats itself every 8 s (2π/Δω), less than the run's 10 s; give a record at least as long as the "
         "run", "Scene.waves.file", files={"short.txt": eta_rows(16)}),
    case("a series sampled unevenly", "analytic", ("waves", dict(SERIES, file="uneven.txt")), "waves.file",
         "the samples must be evenly spaced and increasing (steps from 0.4 to 0.6 s); resample the record to one "
         "step", "Scene.waves.file", files={"uneven.txt": eta_rows(late=5)}),
    case("a series without the column", "analytic", ("waves", dict(SERIES, column=2)), "waves.column",
         "2 is beyond the last column of 'eta.txt' (2 column(s), 0 is the time); give one of 1 .. 1",
         "Scene.waves.column", files={"eta.txt": ETA_TXT}),
    case("a series measured at a 3-D point in 2-D", "analytic", ("waves", dict(SERIES, at=[1.0, 2.0])), "waves.at",
         "[1.0, 2.0]: a 2-D scene gives the record's point as x [m]", "Scene.waves.at", files={"eta.txt": ETA_TXT}),
    case("a series too steep", "analytic", ("waves", dict(SERIES, file="steep.txt")), "waves.file",
         "Hs/Lp = 0.1028 is beyond 0.1", "Scene.waves.file", files={"steep.txt": eta_rows(a=2.0)}),
    # -- an MJCF model
    case("an MJCF file that is not XML", "mjcf", ("bodies[0].file", "notes.xml"), "bodies[0].file",
         "'notes.xml' is not XML (syntax error: line 1, column 0); give an MJCF file", "Scene.bodies[0].file",
         files={"notes.xml": "float: a 1 m box of density 500\n"}),
    case("an MJCF file MuJoCo refuses", "mjcf", ("bodies[0].file", "typo.xml"), "bodies[0].file",
         "MuJoCo refuses 'typo.xml': XML Error: Schema violation: unrecognized attribute: 'sizes'; Element 'geom', "
         "line 2; correct the file there", "Scene.bodies[0].file", files={"typo.xml": MOVING_XML}),
    case("an MJCF body the file does not have", "mjcf", ("bodies[0].bodies", ["float", "raft"]),
         "bodies[0].bodies[1]", "'raft': the file has no body of that name; its bodies: ['float', 'boat', 'post']",
         "Scene.bodies[0].bodies[1]"),
    case("an MJCF body fixed to the world", "mjcf", ("bodies[0].bodies", ["post"]), "bodies[0].bodies[0]",
         "'post' is fixed to the world (neither it nor a body it hangs from has a joint): it cannot move",
         "Scene.bodies[0].bodies[0]"),
    case("an MJCF file with nothing that moves", "mjcf",
         (("bodies[0].file", "statue.xml"), ("bodies[0].bodies", [])), "bodies[0].file",
         "'statue.xml' has no body that can move (none has a joint)", "Scene.bodies[0].file",
         files={"statue.xml": '<mujoco><worldbody><body name="post"><geom type="sphere" size="1"/></body>'
                              '</worldbody></mujoco>\n'}),
    case("an MJCF body whose name is not a name", "mjcf", (("bodies[0].file", "odd.xml"), ("bodies[0].bodies", [])),
         "bodies[0].file", "body 'boat,2' of 'odd.xml' is coupled, and its name goes into the outputs: give it a "
         "name of letters, digits, '_' and '-' in the file", "Scene.bodies[0].file",
         files={"odd.xml": '<mujoco><worldbody><body name="float"><freejoint/><geom type="sphere" size="1"/>'
                           '<site name="top"/></body>\n<body name="boat,2" pos="3 0 0"><freejoint/>'
                           '<geom type="sphere" size="1"/></body></worldbody></mujoco>\n'}),
    case("a fairlead on a site the MJCF file lacks", "mjcf", ("moorings.lines[0].fairlead", "float.keel"),
         "moorings.lines[0].fairlead", "the MJCF file has no site 'keel'; the sites of body 'float': ['top']",
         "Scene.moorings.lines[0].fairlead"),
    case("a fairlead on an MJCF body not coupled", "mjcf", ("moorings.lines[0].fairlead", "boat.bow"),
         "moorings.lines[0].fairlead", "body 'boat' is not one of the coupled bodies ['float']",
         "Scene.moorings.lines[0].fairlead"),
    case("a probe on an MJCF body not coupled", "mjcf", ("probes.motion", ["float", "boat"]), "probes.motion[1]",
         "'boat' is not one of the bodies coupled from the MJCF file: ['float']", "Scene.probes.motion[1]"),
    # -- an accelerogram
    case("an .AT2 record shorter than its NPTS", "tank2d", ("base_motion", {"kind": "earthquake", "file": "short.AT2"}),
         "base_motion.file", "read_at2: short.AT2 declares NPTS=10 but holds 5 values; the record is cut short, has "
         "a gap or its NPTS is wrong", "Scene.base_motion.file",
         files={"short.AT2": AT2_HEAD + "NPTS=   10, DT=   .0100 SEC\n0.0 0.01 0.02 0.01 0.0\n"}),
    case("an .AT2 header without NPTS and DT", "tank2d", ("base_motion", {"kind": "earthquake", "file": "bare.AT2"}),
         "base_motion.file", "read_at2: line 4 of bare.AT2 should give NPTS and DT, e.g. 'NPTS=  4000, DT= .0050 "
         "SEC'; got 'DATA FOLLOW'", "Scene.base_motion.file",
         files={"bare.AT2": AT2_HEAD + "DATA FOLLOW\n0.0 0.01 0.02 0.01 0.0\n"}),
    case("a baseline degree the correction lacks", "tank2d",
         ("base_motion", {"kind": "earthquake", "file": "quake.AT2", "baseline_degree": 2}),
         "base_motion.baseline_degree", "2 is out of range; give a whole number from 3 to 12 (degree",
         "Earthquake.baseline_degree"),
    case("an .AT2 record with a gap", "tank2d", ("base_motion", {"kind": "earthquake", "file": "gap.AT2"}),
         "base_motion.file", "read_at2: line 6 of gap.AT2 holds 2 value(s) where the other data lines hold 5: a gap "
         "in the record", "Scene.base_motion.file",
         files={"gap.AT2": AT2_HEAD + "NPTS=   10, DT=   .0100 SEC\n0.0 0.01 0.02 0.01 0.0\n-0.01 -0.02\n"
                           "0.0 0.0 0.0\n"}),
    case("an .AT2 record with a non-finite value", "tank2d", ("base_motion", {"kind": "earthquake", "file": "nan.AT2"}),
         "base_motion.file", "read_at2: nan.AT2 holds a non-finite value (nan) at sample 7 (t = 7 DT)",
         "Scene.base_motion.file",
         files={"nan.AT2": AT2_HEAD + "NPTS=   10, DT=   .0100 SEC\n0.0 0.01 0.02 0.01 0.0\n"
                           "-0.01 -0.02 NaN 0.0 0.0\n"}),
    case("a velocity record given as an accelerogram", "tank2d",
         ("base_motion", {"kind": "earthquake", "file": "quake.VT2"}), "base_motion.file",
         "read_at2: line 3 of quake.VT2 is 'VELOCITY TIME SERIES IN UNITS OF CM/SEC': a velocity record (.VT2)",
         "Scene.base_motion.file",
         files={"quake.VT2": "PEER RECORD\nSYNTHETIC, 2024, STATION, 000\nVELOCITY TIME SERIES IN UNITS OF CM/SEC\n"
                             "NPTS=   10, DT=   .0100 SEC\n0.0 0.01 0.02 0.01 0.0\n-0.01 -0.02 -0.01 0.0 0.0\n"}),
    case("a ground-motion record shorter than the run", "tank2d",
         ("base_motion", {"kind": "ground_motion", "components": [{"file": "quake.AT2", "direction": [1.0, 0.0]}]}),
         "base_motion.components[0].file", "the record ends at 0.09 s, before world.duration = 2 s; shorten "
         "world.duration to at most 0.09 s, or set base_motion.hold = true", "Scene.base_motion.components[0].file"),
    case("a ground-motion record too coarse for the first sloshing mode", "tank2d",
         ("base_motion", {"kind": "ground_motion", "components": [{"file": "quake.AT2", "direction": [1.0, 0.0]},
                                                                  {"file": "coarse.AT2", "direction": [0.0, 1.0]}],
                          "hold": True}),
         "base_motion.components[1].file", "sampled every 0.5 s: too coarse for the water's first sloshing period "
         "of 1.32 s (linear theory), which needs at least 10 samples (DT <= 0.132 s)",
         "Scene.base_motion.components[1].file",
         files={"coarse.AT2": AT2_HEAD + "NPTS=   10, DT=   .5000 SEC\n0.0 0.01 0.02 0.01 0.0\n"
                              "-0.01 -0.02 -0.01 0.0 0.0\n"}),
    case("an earthquake record too coarse for the first sloshing mode", "tank2d",
         ("base_motion", {"kind": "earthquake", "file": "coarse.AT2"}), "base_motion.file",
         "sampled every 0.5 s: too coarse for the water's first sloshing period of 1.32 s (linear theory), which "
         "needs at least 10 samples (DT <= 0.132 s)", "Scene.base_motion.file",
         files={"coarse.AT2": AT2_HEAD + "NPTS=   10, DT=   .5000 SEC\n0.0 0.01 0.02 0.01 0.0\n"
                              "-0.01 -0.02 -0.01 0.0 0.0\n"}),
    # -- a table of motion
    case("a table that is not numbers", "tank2d", ("base_motion.file", "labelled.txt"), "base_motion.file",
         "line 1 of 'labelled.txt' is not a row of numbers: 'time displacement'; give rows of numbers separated by "
         "spaces or tabs", "Scene.base_motion.file",
         files={"labelled.txt": "time displacement\n0.0 0.0\n0.5 0.01\n1.0 0.0\n1.5 -0.01\n"}),
    case("a table without the column", "tank2d", ("base_motion.column", 2), "base_motion.column",
         "2 is beyond the last column of 'motion.txt' (2 column(s), 0 is the time): its value columns are 1 .. 1",
         "Scene.base_motion.column"),
    case("a table whose times go back", "tank2d", ("base_motion.file", "unsorted.txt"), "base_motion.file",
         "the times of 'unsorted.txt' must increase: row 4 (t = 0.5 s) follows t = 1 s; sort the rows",
         "Scene.base_motion.file", files={"unsorted.txt": "0.0 0.0\n0.25 0.005\n1.0 0.0\n0.5 -0.005\n"}),
    case("a table holding a NaN", "tank2d", ("base_motion.file", "nan.txt"), "base_motion.file",
         "row 3 of 'nan.txt' holds a value that is not finite (0.5, nan); give finite numbers",
         "Scene.base_motion.file", files={"nan.txt": "0.0 0.0\n0.25 0.005\n0.5 nan\n0.75 0.0\n"}),
    case("a table whose rows differ in width", "tank2d", ("base_motion.file", "ragged.txt"), "base_motion.file",
         "row 3 of 'ragged.txt' has 3 value(s), row 1 has 2; give every row the same columns",
         "Scene.base_motion.file", files={"ragged.txt": "0.0 0.0\n0.25 0.005\n0.5 0.0 1.0\n0.75 0.0\n"}),
    case("a table of three rows", "tank2d", ("base_motion.file", "three.txt"), "base_motion.file",
         "'three.txt' has 3 row(s); a record needs at least 4 samples", "Scene.base_motion.file",
         files={"three.txt": "0.0 0.0\n0.5 0.01\n1.0 0.0\n"}),
    case("a table that does not start at rest", "tank2d", ("base_motion.file", "offset.txt"), "base_motion.file",
         "the table moves the tank 0.05 m from where the walls are built at t = 0", "Scene.base_motion.file",
         files={"offset.txt": "0.0 0.05\n0.5 0.06\n1.0 0.05\n1.5 0.04\n"}),
    case("a paddle record without the column", "flume",
         ("waves", {"kind": "record", "paddle": "piston", "file": "paddle.txt", "column": 2}), "waves.column",
         "2 is beyond the last column of 'paddle.txt' (2 column(s), 0 is the time)", "Scene.waves.column"),
    case("a paddle record with a line of text", "flume",
         ("waves", {"kind": "record", "paddle": "piston", "file": "broken.txt"}), "waves.file",
         "line 4 of 'broken.txt' is not a row of numbers: '1.0 n/a'; give rows of numbers separated by spaces, tabs "
         "or commas (text lines before the first row are a header)", "Scene.waves.file",
         files={"broken.txt": "t x\n0.0 0.0\n0.5 0.01\n1.0 n/a\n1.5 -0.01\n2.0 0.0\n"}),
    case("a paddle record that does not start at rest", "flume",
         ("waves", {"kind": "record", "paddle": "flap", "file": "paddle.txt", "t_shift": -0.5}), "waves.file",
         "the record turns the flap by 0.01 rad, which puts its top 0.0045 m from where the walls are built at t = 0",
         "Scene.waves.file"),
]

#: what is only known once the scene is built (a floating body's height): refused by run()
#: before it writes anything; the scene itself constructs
BUILD_CASES = [
    case("a floating body's fairlead below its anchor's seabed", "flume", ("moorings.lines[0].anchor", [0.5, 0.28]),
         "moorings.lines[0].anchor", "body 'box' starts below this anchor's seabed z = 0.28 m (the horizontal plane "
         "through the anchor): it floats only at a draft beyond 0.02 m, where its fairlead 'box.left' is below it; "
         "put the anchor lower, below z = 0.25 m", None),
    case("a floating body's line too short to reach", "flume", ("moorings.lines[0].length", 0.5),
         "moorings.lines[0].length", "0.5 m is shorter than the straight distance 0.6325 m from its anchor to its "
         "fairlead 'box.left' with body 'box' fully submerged, the nearest it comes", None),
    case("potential flow: a frequency range too short for the impulse response", "potential",
         (("fluid.omega_max", 1.1), ("fluid.frequencies", 24), ("waves.period", 20.0)), "fluid.omega_max",
         "the impulse response rebuilds the", None),
    case("potential flow: frequencies too coarse for the impulse response to decay", "potential",
         ("fluid.frequencies", 6), "fluid.frequencies", "of its peak over the last 10 % of the 6.283 s "
         "that the frequency spacing resolves (π/Δω); give more frequencies", None),
    case("potential flow: an irregular sea beyond the frequencies' trusted band", "potential", ("waves", JONSWAP),
         "fluid.omega_max", "the sea's components outside the coefficients' trusted band 0.15-1.5 rad/s (the lowest "
         "frequency to 0.5 x the highest) carry 5.5% of its variance", None),
    case("a tank's inner wall thinner than its walls", "tank2d",
         ("domain.walls", [{"lo": [0.5, 0.0], "hi": [0.54, 0.6]}]),
         "domain.walls[0]", "is 0.04 m thick, fewer than the walls' 4 layers of fluid.dx = 0.02 m (the kernel's "
         "support 2h behind a wetted face)", None),
    case("a floating body that sinks", "flume", ("bodies[0].density", 1500.0), "bodies[0].place",
         "body 'box' (30 kg) sinks: fully submerged it displaces 20 kg of water", None),
    case("a coupling step above the analytic fluid's stable step", "analytic",
         (("world.sample_every", 0.1), ("coupling.dt", 0.05)), "coupling.dt",
         "coupling step dt = 0.05 s is above the stable step of participant 'fluid'", None),
]


@dataclass(frozen=True)
class CliCase:
    id: str
    args: tuple  # after `cosim COMMAND`; the output folder is the --out given (or out/)
    says: str  # a fragment of the message on stderr
    files: tuple = ()
    prepare: tuple = ()  # commands run first in the folder: ("cosim", ...) or ("python", ...)
    command: str = "run"  # the cosim command: run, or study

    @property
    def out(self) -> str:
        return self.args[self.args.index("--out") + 1]


def cli(id, args, says, files=None, prepare=(), command="run"):
    return CliCase(id, tuple(args), says, tuple((files or {}).items()), tuple(tuple(c) for c in prepare), command)


SCENE = {"scene.toml": BASES["analytic"]}
#: in the folder of every command-line case: what the cases that resume do to the checkpoint
#: of the run they make first
CLI_FILES = {"edit_checkpoint.py": '''"""Change out/checkpoint.h5 as the argument says."""
import pickle
import sys

from cosim import checkpoint

PATH = "out/checkpoint.h5"
what = sys.argv[1]
if what == "truncate":  # the second half lost (a full disk, a copy cut short)
    data = open(PATH, "rb").read()
    open(PATH, "wb").write(data[: len(data) // 2])
elif what == "flip":  # one bit flipped in the ledger's first time
    import h5py

    with h5py.File(PATH, "r") as f:
        at = f["ledger/t"].id.get_offset()
    data = bytearray(open(PATH, "rb").read())
    data[at] ^= 1
    open(PATH, "wb").write(data)
elif what == "pickle":  # a pickle that, loaded, would write the file pwned
    class Pwn:
        def __reduce__(self):
            return (open, ("pwned", "w"))

    open(PATH, "wb").write(pickle.dumps(Pwn()))
else:  # KEY=VALUE: one value of the checkpoint's meta changed, its checksum made anew
    key, value = what.split("=")
    content = checkpoint.read(PATH)
    content["meta"][key] = float(value) if key == "t" else value
    checkpoint.write(PATH, content)
'''}


def study(id, args, says, vary="coupling.dt=0.01,0.005", metric="box.heave:max", files=None, scene="scene.toml"):
    """A case of ``cosim study`` on a base scene (the analytic one), run serially into out/."""
    return cli(id, [scene, "--vary", vary, "--metric", metric, "--serial", "--out", "out", *args], says,
               SCENE | (files or {}), command="study")


FLUME = {"flume.toml": BASES["flume"]}
#: the analytic base scene's lines as dynamic ones (50 N/m submerged in water of 1000 kg/m^3)
DYNAMIC = [x for i in (0, 1) for kv in (("EA", "5e7"), ("mass_per_length", "5.803665"), ("diameter", "0.03"))
           for x in ("--set", f"moorings.lines[{i}].{kv[0]}={kv[1]}")]


FIRST = ("cosim", "run", "scene.toml", "--out", "out", "--set", "world.duration=0.1", "--quiet")
RESUME = ["scene.toml", "--out", "out", "--resume", "--set", "world.duration=0.2"]
CLI_CASES = [
    cli("a scene file that does not exist", ["nothing.toml", "--out", "out"],
        "no scene file 'nothing.toml'; give a .toml file or a .py script that defines `scene`"),
    cli("a scene file neither .toml nor .py", ["scene.json", "--out", "out"],
        "scene.json: a scene is a .toml file or a .py script", {"scene.json": "{}\n"}),
    cli("a script that defines no `scene`", ["make.py", "--out", "out"],
        "make.py defines no Scene named `scene` (it has ['tank']); assign one: scene = Scene(...)",
        {"make.py": "from cosim.scene import SPH, Scene, Tank\n\n"
                    "tank = Scene(fluid=SPH(dx=0.05), domain=Tank(length=1.0, height=0.5, depth=0.2))\n"}),
    cli("a script that exits", ["make.py", "--out", "out"],
        "make.py called sys.exit(0) while it was loaded; a scene script defines `scene` and leaves running it to "
        "cosim", {"make.py": "import sys\n\nsys.exit(0)\n"}),
    cli("a script that raises", ["make.py", "--out", "out"],
        "make.py raised FileNotFoundError: [Errno 2] No such file or directory: 'hull.csv' (at make.py line 1)",
        {"make.py": "rows = open(\"hull.csv\").read().split()\n"}),
    cli("TOML that does not parse", ["bad.toml", "--out", "out"],
        "bad.toml is not valid TOML: Expected ']' at the end of a table declaration (at line 2, column 7)",
        {"bad.toml": "# a tank\n[world\ndim = 2\n"}),
    cli("--set without '='", ["scene.toml", "--set", "world.duration", "--out", "out"],
        "world.duration: give --set as KEY.PATH=VALUE, e.g. fluid.dx=0.01", SCENE),
    cli("--resume without a checkpoint", ["scene.toml", "--resume", "--out", "out"],
        "--resume: no checkpoint out/checkpoint.h5; run without --resume first", SCENE),
    cli("--resume-any-version without --resume", ["scene.toml", "--resume-any-version", "--out", "out"],
        "--resume-any-version goes with --resume", SCENE),
    cli("--resume from an older cosim's pickle", RESUME,
        "--resume: out/checkpoint.pkl is a checkpoint of an older cosim, a Python pickle, which cosim does not load "
        "(loading one runs whatever code it holds)", SCENE | {"out/checkpoint.pkl": "(a pickle)\n"}),
    cli("--resume from a pickle named checkpoint.h5", RESUME,
        "--resume: out/checkpoint.h5 is a Python pickle, not a checkpoint: cosim does not load pickles (loading one "
        "runs whatever code it holds)", SCENE, prepare=[FIRST, ("python", "edit_checkpoint.py", "pickle")]),
    cli("--resume from a file that is not HDF5", RESUME,
        "--resume: out/checkpoint.h5 is not a checkpoint (not an HDF5 file)",
        SCENE | {"out/checkpoint.h5": "t = 1.0\n"}),
    cli("--resume from a truncated checkpoint", RESUME,
        "--resume: out/checkpoint.h5 is truncated or corrupt, HDF5 cannot open it",
        SCENE, prepare=[FIRST, ("python", "edit_checkpoint.py", "truncate")]),
    cli("--resume from a checkpoint with one bit flipped", RESUME,
        "--resume: out/checkpoint.h5 is corrupt: its contents do not match their checksum (sha256)",
        SCENE, prepare=[FIRST, ("python", "edit_checkpoint.py", "flip")]),
    cli("--resume from a checkpoint whose time is NaN", RESUME,
        "--resume: out/checkpoint.h5 holds a state no run reaches (t = nan); it is corrupt or was not written by "
        "cosim", SCENE, prepare=[FIRST, ("python", "edit_checkpoint.py", "t=nan")]),
    cli("--resume from a checkpoint of other code", RESUME,
        "--resume: out/checkpoint.h5 was written by other code (cosim 0.1.0, sources 0123456789abcdef; this is "
        "cosim 0.1.0 with other sources), which may not continue the run bit for bit", SCENE, prepare=[FIRST, ("python", "edit_checkpoint.py", "code_version=0123456789abcdef")]),
    cli("--resume from a checkpoint of another scene", RESUME,
        "world.gravity: differs from the run being resumed; a resumed run may change world.duration, "
        "world.checkpoint_wall and world.plot_at only", SCENE, prepare=[FIRST + ("--set", "world.gravity=9.8")]),
    cli("--resume to a duration before the checkpoint", ["scene.toml", "--out", "out", "--resume", "--set",
                                                         "world.duration=0.05"],
        "world.duration: 0.05 s is before the checkpoint at 0.1 s", SCENE, prepare=[FIRST]),
    cli("an output folder that holds an earlier run", ["scene.toml", "--out", "out"],
        "output folder 'out' is not empty (checkpoint.h5, ledger.csv, line_states.csv, line_states.png and 10 more): "
        "a run would leave the earlier files beside its own; give --overwrite", SCENE, prepare=[FIRST]),
    cli("--overwrite of a folder no run wrote", ["scene.toml", "--out", "out", "--overwrite"],
        "--overwrite: output folder 'out' holds notes.txt, none of them a run's output (summary.json, scene.toml, "
        "run.h5, checkpoint.h5); it is not cleared: give a new or empty --out", SCENE | {"out/notes.txt": "mine\n"}),
    cli("--overwrite with --resume", ["scene.toml", "--out", "out", "--overwrite", "--resume"],
        "--overwrite clears the folder that --resume continues: give one", SCENE),
    cli("a coupling step above the fluid's stable step", ["scene.toml", "--out", "out", "--set",
                                                          "world.sample_every=0.1", "--set", "coupling.dt=0.05"],
        "coupling step dt = 0.05 s is above the stable step of participant 'fluid'", SCENE),
    cli("an output folder under a regular file", ["scene.toml", "--out", "notes.txt/out"],
        "output folder 'notes.txt/out': 'notes.txt' is not a folder; give another --out",
        SCENE | {"notes.txt": "not a folder\n"}),
    # -- cosim study: every spec checked before the first run
    study("a study with --workers -1", ["--workers", "-1"], "--workers -1: give a whole number >= 1 (runs at once"),
    study("a study with --workers 0", ["--workers", "0"], "--workers 0: give a whole number >= 1"),
    study("a study with --threads 0", ["--threads", "0"], "--threads 0: give a whole number >= 1 (numba threads"),
    study("a study's metric of a series the runs do not record", [], "--metric 'box.roll:max': the runs with "
          "{'coupling.dt': 0.01} record no series 'box.roll'; they record box.surge, box.heave, box.pitch",
          metric="box.roll:max"),
    study("a study's metric of an unknown statistic", [], "--metric 'box.heave:median': unknown statistic 'median'; "
          "choose from peak, max", metric="box.heave:median"),
    study("a study's metric without a statistic", [], "--metric 'box.heave': give SERIES:STAT", metric="box.heave"),
    study("a study's --vary without '='", [], "--vary 'coupling.dt': give KEY.PATH=V1,V2,...", vary="coupling.dt"),
    study("a study varying a field that does not exist", [], "coupling.dtt: unknown key; did you mean 'dt'?",
          vary="coupling.dtt=0.01,0.005"),
    study("a study varying a field to a value it refuses", [], "coupling.dt: -0.01 [s] is out of range; give a "
          "number [s] > 0", vary="coupling.dt=0.01,-0.01"),
    study("a study with a value given twice", [], "--vary coupling.dt: the value 0.01 is given twice",
          vary="coupling.dt=0.01,0.01"),
    study("a study varying one field twice", ["--vary", "coupling.dt=0.002"], "--vary coupling.dt: given twice; give "
          "all its values in one --vary"),
    study("a study with a negative tolerance", ["--tol=-5%"], "--tol -0.05: give a relative tolerance > 0"),
    study("a study whose reference file lacks a metric", ["--reference", "ref.json"], "--reference ref.json: no "
          "reference value for box.heave:max", files={"ref.json": '{"box.surge:min": -0.5}\n'}),
    study("a study over the fluids that gives SPH no spacing", [], "the run with {'fluid.model': 'sph'}: fluid.dx: "
          "is required: a number [m] > 0 (particle spacing) (a field of this kind alone: give it with --set "
          "fluid.dx=VALUE", vary="fluid.model=analytic,sph"),
    study("a study over the fluids of a 2-D scene", [], "the run with {'fluid.model': 'potential'}: world.dim: linear "
          "potential flow about a body is 3-D", vary="fluid.model=analytic,potential"),
    study("a study setting a field no varied fluid has", ["--set", "fluid.dxx=0.1"], "fluid.dxx: unknown key",
          vary="fluid.model=analytic,sph"),
    # a capytaine.py that fails to import, first on the path, stands in for a machine without the extra
    cli("the potential fluid without its extra", ["scene.toml", "--out", "out"], "fluid.model: \"potential\" needs "
        "Capytaine and h5netcdf (capytaine is not installed): pip install cosim-sph[potential]",
        {"scene.toml": BASES["potential"],
         "capytaine.py": "raise ImportError(\"No module named 'capytaine'\", name=\"capytaine\")\n"}),
    study("a study whose runs together pass a day of CPU", [], "the study's 2 runs would take about",
          vary="fluid.settle=1e7,2e7", metric="gauge1.eta:max", files=FLUME, scene="flume.toml"),
    # -- the cost estimated before any work (cosim.scene.cost): memory beyond the machine's, a day of CPU
    cli("a run of 1e300 s", ["scene.toml", "--set", "world.duration=1e300", "--out", "out"],
        "world.duration: the run would need about", SCENE),
    cli("a sample every 1e-12 s", ["scene.toml", "--set", "world.sample_every=1e-12", "--out", "out"],
        "world.sample_every: the run would need about", SCENE),
    cli("a coupling step of 1e-9 s", ["scene.toml", "--set", "coupling.dt=1e-9", "--out", "out"],
        "coupling.dt: the run would need about", SCENE),
    cli("a particle spacing of 10 um", ["flume.toml", "--set", "fluid.dx=1e-5", "--out", "out"],
        "fluid.dx: the run would need about", FLUME),
    cli("settling for 1e9 s", ["flume.toml", "--set", "fluid.settle=1e9", "--out", "out"],
        "fluid.settle: the run would take about", FLUME),
    cli("a dry run of a run that would be refused", ["flume.toml", "--dry-run", "--set", "fluid.settle=1e9", "--out",
                                                     "out"], "fluid.settle: the run would take about", FLUME),
    cli("MoorDyn lines of 1e5 segments", ["scene.toml", *DYNAMIC, "--set", "moorings.model=moordyn", "--set",
                                          "moorings.segments=100000", "--out", "out"],
        "moorings.segments: the run would take about", SCENE),
    cli("SPH cables of 1e5 particles", ["scene.toml", *DYNAMIC, "--set", "moorings.model=sph-cable", "--set",
                                        "moorings.segments=100000", "--out", "out"],
        "moorings.segments: the run would take about", SCENE),
    cli("an elastic plate of 1e6 elements", ["plate.toml", "--set", "bodies[0].elements=1000000", "--out", "out"],
        "bodies[0].elements: the run would need about", {"plate.toml": BASES["plate"]}),
]


# ------------------------------------------------------------------------ the routes
def base_dict(name: str) -> dict:
    return tomllib.loads(BASES[name])


def split(path: str) -> list:
    out = []
    for piece in path.split("."):
        m = re.fullmatch(r"(\w+)((?:\[\d+\])*)", piece)
        out.append(m.group(1))
        out.extend(int(i) for i in re.findall(r"\[(\d+)\]", m.group(2)))
    return out


def edited(c: Case) -> dict:
    """The base scene's dict with the case's edits made."""
    data = base_dict(c.base)
    for key, value in c.change:
        *parents, last = split(key)
        node = data
        for k, nxt in zip(parents, parents[1:] + [last]):
            node = node[k] if isinstance(k, int) else node.setdefault(k, [] if isinstance(nxt, int) else {})
        if value is OUT:
            del node[last]
        elif isinstance(last, int) and last == len(node):
            node.append(copy.deepcopy(value))
        else:
            node[last] = copy.deepcopy(value)
    return data


def toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float) and not math.isfinite(v):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return "{ " + ", ".join(f"{k} = {toml_value(x)}" for k, x in v.items()) + " }" if v else "{}"


def assignments(c: Case) -> list[str] | None:
    """The case as --set assignments (None where an edit leaves a key out)."""
    if isinstance(c.change, str):
        return [c.change]
    if any(v is OUT for _, v in c.change):
        return None
    return [f"{k}={toml_value(v)}" for k, v in c.change]


def build_python(data, classes=(Scene,)):
    """The scene of a TOML-like dict built by calling the classes themselves (no toml_io):
    a table becomes the class its tag names, its keys the keyword arguments."""
    if not isinstance(data, dict):
        return data
    if len(classes) == 1:
        cls = classes[0]
    else:
        tag = classes[0].TAG[0]
        cls = {c.TAG[1]: c for c in classes}[data[tag]]
    checks = {f.name: f.metadata.get("check") for f in dataclasses.fields(cls)}
    kwargs = {}
    for k, v in data.items():
        if cls.TAG and k == cls.TAG[0]:
            continue
        check = checks.get(k)
        if isinstance(check, Part):
            v = build_python(v, check.classes)
        elif isinstance(check, Parts) and isinstance(v, list):
            v = [build_python(x, check.part.classes) for x in v]
        kwargs[k] = v
    return cls(**kwargs)


def refusal(fn):
    with pytest.raises(Exception) as info:
        fn()
    return info.value


def toml_error(c: Case) -> InputError:
    """The error of the case's TOML route (from_dict of the edited dict, or --set alone)."""
    c.write_files()
    if isinstance(c.change, str):
        return refusal(lambda: with_values(from_dict(base_dict(c.base)), [c.change]))
    return refusal(lambda: from_dict(edited(c)))


def build_error(c: Case, out: Path) -> InputError:
    """The error of running the case's scene (which constructs) into ``out``."""
    c.write_files()
    scene = from_dict(edited(c))
    return refusal(lambda: scene.run(out, progress=False))


def _listing(folder: Path):
    """What a folder holds: (name, size, modification time) of each file, or None."""
    if not folder.is_dir():
        return None
    return sorted((str(p.relative_to(folder)), p.stat().st_size, p.stat().st_mtime_ns) for p in folder.rglob("*"))


def _cosim(args, cwd) -> subprocess.CompletedProcess:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT)] + [x for x in [os.environ.get("PYTHONPATH")] if x]))
    cmd = [sys.executable] + (["-m", "cosim.cli", *args[1:]] if args[0] == "cosim" else list(args[1:]))
    return subprocess.run(cmd, capture_output=True, text=True, cwd=cwd, env=env, timeout=300)


def _write_case_files(folder, files: tuple) -> None:
    for name, text in {**CLI_FILES, **dict(files)}.items():
        Path(folder, name).parent.mkdir(parents=True, exist_ok=True)
        Path(folder, name).write_text(text, encoding="utf-8")


@functools.lru_cache(maxsize=None)
def _made_by(args: tuple, files: tuple) -> Path:
    """The folder in which the command ``args`` (``cosim run ... --out OUT``) ran among
    ``files``: run once per test process, its OUT copied into each case that starts from it
    (a run costs seconds, and the cases that spoil its checkpoint start from the same one)."""
    tmp = tempfile.mkdtemp(prefix="scene-errors-made-")
    atexit.register(shutil.rmtree, tmp, True)
    _write_case_files(tmp, files)
    r = _cosim(args, tmp)
    assert r.returncode == 0, f"{' '.join(args)}: {r.stderr[-2000:]}"
    return Path(tmp)


@functools.lru_cache(maxsize=None)
def run_cli(c: CliCase) -> tuple[int, str, bool]:
    """(exit status, stderr, whether the output folder was left as it was: not made, or,
    where the case made it first, unchanged) of ``python -m cosim.cli run ARGS`` in a fresh
    folder holding the case's files, after the case's ``prepare`` commands (a ``cosim run``
    among them: its folder copied from :func:`_made_by`)."""
    with tempfile.TemporaryDirectory(prefix="scene-errors-cli-") as tmp:
        _write_case_files(tmp, c.files)
        for args in c.prepare:
            if args[:2] == ("cosim", "run"):
                out = args[args.index("--out") + 1]  # OUT as given (a path under the folder)
                shutil.copytree(_made_by(args, c.files) / out, Path(tmp, out), dirs_exist_ok=True)
                continue
            r = _cosim(args, tmp)
            assert r.returncode == 0, f"{' '.join(args)}: {r.stderr[-2000:]}"
        before = _listing(Path(tmp, c.out))
        r = _cosim(("cosim", c.command) + c.args, tmp)
        assert not Path(tmp, "pwned").exists(), "the checkpoint's pickle ran"
        return r.returncode, r.stderr, _listing(Path(tmp, c.out)) == before


def cli_message(c: CliCase) -> str:
    rc, err, _ = run_cli(c)
    lines = err.strip().splitlines()
    return lines[-1].removeprefix(f"cosim {c.command}: error: ") if lines else ""


def machine_free(message: str) -> str:
    """A message for the table, without what depends on the machine that rendered it (its
    available memory)."""
    return re.sub(r"this machine's available memory \([^)]*\)", "this machine's available memory (...)", message)


# ------------------------------------------------------------------------ the tests
SCENE_CASES = CASES + FILE_CASES
IDS = [c.id for c in SCENE_CASES]
ALL_IDS = IDS + [c.id for c in BUILD_CASES] + [c.id for c in CLI_CASES]


def test_catalogue_is_large_and_ids_are_unique():
    assert len(CASES) >= 35
    assert len(FILE_CASES) + len(BUILD_CASES) + len(CLI_CASES) >= 25
    assert len(set(ALL_IDS)) == len(ALL_IDS)


@pytest.mark.parametrize("name", sorted(BASES))
def test_base_scenes_are_valid(name):
    scene = from_dict(base_dict(name))
    assert build_python(base_dict(name)) == scene
    assert with_values(scene, []) == scene


@pytest.mark.parametrize("c", SCENE_CASES, ids=IDS)
def test_refused_from_toml(c):
    err = toml_error(c)
    assert isinstance(err, InputError), f"{type(err).__name__}: {err}"
    assert err.path == c.path, str(err)
    assert c.says in str(err)
    assert str(err) == f"{c.path}: {err.problem}"


SET_CASES = [c for c in SCENE_CASES if not isinstance(c.change, str) and assignments(c)]


@pytest.mark.parametrize("c", SET_CASES, ids=[c.id for c in SET_CASES])
def test_refused_by_set(c):
    """The same change made by --set on the valid base scene: the same error."""
    c.write_files()
    err = refusal(lambda: with_values(from_dict(base_dict(c.base)), assignments(c)))
    assert isinstance(err, InputError), f"{type(err).__name__}: {err}"
    assert (err.path, err.problem) == (c.path, toml_error(c).problem)


PY_CASES = [c for c in SCENE_CASES if c.python is not None]


@pytest.mark.parametrize("c", PY_CASES, ids=[c.id for c in PY_CASES])
def test_refused_in_python(c):
    c.write_files()
    err = refusal(lambda: build_python(edited(c)))
    if c.python is TYPE:  # the call's own refusal names the keyword
        assert isinstance(err, TypeError), f"{type(err).__name__}: {err}"
        assert split(c.path)[-1] in str(err) or (isinstance(split(c.path)[-1], int))
        return
    assert isinstance(err, InputError), f"{type(err).__name__}: {err}"
    assert err.path == c.python_path, str(err)
    if isinstance(c.python, tuple):  # a Python value, not a TOML one: Python's words
        assert c.python[1] in str(err)
    else:
        assert c.says in str(err)
        assert err.problem == toml_error(c).problem


@pytest.mark.parametrize("c", BUILD_CASES, ids=[c.id for c in BUILD_CASES])
def test_refused_when_built_before_anything_is_written(c, tmp_path):
    """The scene constructs (in Python too); running it is refused while it is built, before
    the output folder is made."""
    c.write_files()
    assert build_python(edited(c)) == from_dict(edited(c))
    err = build_error(c, tmp_path / "out")
    assert isinstance(err, InputError), f"{type(err).__name__}: {err}"
    assert err.path == c.path and c.says in str(err), str(err)
    assert str(err) == f"{c.path}: {err.problem}"
    assert not (tmp_path / "out").exists()


# a case that first runs a scene to make its checkpoint costs two runs of cosim: the long tier
@pytest.mark.parametrize("c", [pytest.param(c, marks=pytest.mark.long) if c.prepare else c for c in CLI_CASES],
                         ids=[c.id for c in CLI_CASES])
def test_refused_by_the_command_line(c):
    """``cosim run`` (``cosim study``) exits with status 2, the last line of stderr says what
    is wrong (no traceback), no output folder is made and none that was there is written into."""
    rc, err, untouched = run_cli(c)
    assert rc == 2, err
    assert "Traceback" not in err, err
    assert err.strip().splitlines()[-1] == f"cosim {c.command}: error: {cli_message(c)}"
    assert c.says in cli_message(c), err
    assert untouched
    # its row of docs/scene_errors.md, which test_docs_table_is_current checks but for these messages
    assert cli_row(cli_number(c), c, cli_message(c)) in DOC.read_text().splitlines(), (
        "docs/scene_errors.md is out of date: python tests/test_scene_errors.py > docs/scene_errors.md")


# ------------------------------------------------------------------------ the table
def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _text(text: str) -> str:
    """A message for a table cell: its tags (<freejoint/>) shown, not taken as HTML."""
    return _cell(text.replace("&", "&amp;").replace("<", "&lt;"))


def _code(text: str) -> str:
    return f"`{text}`" if "`" not in text else f"``{text}``"


def describe(c: Case) -> str:
    if isinstance(c.change, str):
        return _code(f"--set {c.change}")
    out = []
    for k, v in c.change:
        if v is OUT:
            out.append(_code(k) + " left out")
        elif isinstance(v, int) and abs(v) > 10 ** 20:  # a long integer: its digits in short
            out.append(_code(f"{k} = 1000...000") + f" ({len(str(v))} digits)")
        else:
            out.append(_code(f"{k} = {toml_value(v)}"))
    return "<br>".join(out)


def describe_files(c) -> str:
    """The case's files, line by line, for the table."""
    out = []
    for name, text in c.files:
        out.append(f"file {_code(name)}:<br>" + "<br>".join(_code(x) if x.strip() else "(blank)"
                                                            for x in text.rstrip("\n").split("\n")))
    return "<br>".join(out)


def cli_files(c: CliCase) -> str:
    out = []
    bases = {text: base for base, text in BASES.items()}
    for name, text in c.files:
        if text in bases:
            out.append(f"{_code(name)}: the base scene {bases[text]}")
        else:
            out.append(describe_files(dataclasses.replace(c, files=((name, text),))))
    if c.prepare:
        out.append("made first: " + ", then ".join(_code(" ".join(a)) for a in c.prepare))
    return "<br>".join(out)


def _python(c) -> str:
    return "\u2014" if c.python is None else "`TypeError`" if c.python is TYPE else _code(c.python_path)


def cli_row(k: int, c: CliCase, message: str) -> str:
    """The command-line table's row ``k`` (numbered over the whole catalogue) of case ``c``
    whose stderr's last line says ``message``."""
    return (f"| {k} | {_cell(c.id)} | {_code(f'cosim {c.command} ' + ' '.join(c.args))} | {_cell(cli_files(c))} | "
            f"{_text(machine_free(message))} |")


def cli_number(c: CliCase) -> int:
    """``c``'s row number in the document (the command-line table comes last)."""
    return len(ALL_IDS) - len(CLI_CASES) + CLI_CASES.index(c) + 1


def render(cli_text: str | None = None) -> str:
    """The catalogue as Markdown: docs/scene_errors.md. ``cli_text``: written in place of
    every command-line case's message instead of running the case (None: run)."""
    n = len(CASES) + len(FILE_CASES) + len(BUILD_CASES) + len(CLI_CASES)
    lines = [
        "# Scene errors",
        "",
        "Generated from `tests/test_scene_errors.py` (the tables are checked against the tests); "
        "regenerate it with `python tests/test_scene_errors.py > docs/scene_errors.md`.",
        "",
        f"Each of the {n} inputs below is refused before any step is taken and before anything is written, with "
        "the key path of the bad field, what is wrong and how to fix it. The error (`cosim.errors.InputError`) "
        "reads `PATH: MESSAGE`; `cosim run` prints it as `cosim run: error: PATH: MESSAGE` and exits with status 2.",
        "",
        "- [Scene fields](#scene-fields): refused when the scene is constructed, from a TOML file, by "
        "`cosim run --set KEY.PATH=VALUE` (where the change can be written as assignments) and in Python;",
        "- [File contents](#file-contents): the files a scene names (an MJCF model, an accelerogram, a table of "
        "motion), read when the scene is constructed, as the builder will read them;",
        "- [Known once built](#known-once-built): what depends on a floating body's computed height or on the "
        "built participants (their stable steps), refused by `run` while it builds the scene, before the output "
        "folder is made;",
        "- [The command line](#the-command-line): `cosim run` itself (with the runs whose estimated cost, "
        "`cosim.scene.cost`, passes the machine's memory or a day of CPU) and `cosim study`.",
        "",
        "An input is a change to one of the valid [base scenes](#base-scenes) (`key = value`, or a key left out), "
        "with the [files beside them](#base-files) and the case's own files in the working folder. "
        "In Python a part does not know where it will be put: the error "
        "names its class (`Box.density`), or `Scene.` and the key path for the checks of the scene as a whole; "
        "an unknown or missing keyword is Python's own `TypeError`; \u2014 where there is no Python counterpart "
        "(the TOML field that picks a class, `--set` syntax).",
        "",
        "## Scene fields",
        "",
        f"{len(CASES)} inputs.",
        "",
        "| # | case | base | input | key path | message | Python |",
        "|---|---|---|---|---|---|---|",
    ]
    k = 0
    for c in CASES:
        k += 1
        lines.append(f"| {k} | {_cell(c.id)} | {c.base} | {_cell(describe(c))} | {_code(c.path)} | "
                     f"{_text(toml_error(c).problem)} | {_python(c)} |")
    lines += ["", "## File contents", "", f"{len(FILE_CASES)} inputs: the scene's change and the files it names.", "",
              "| # | case | base | input | key path | message | Python |", "|---|---|---|---|---|---|---|"]
    for c in FILE_CASES:
        k += 1
        what = describe(c) + ("<br>" + describe_files(c) if c.files else "")
        lines.append(f"| {k} | {_cell(c.id)} | {c.base} | {_cell(what)} | {_code(c.path)} | "
                     f"{_text(toml_error(c).problem)} | {_python(c)} |")
    lines += ["", "## Known once built", "", f"{len(BUILD_CASES)} inputs: the scene constructs; `run` (and "
              "`cosim run`) refuses it while building, before anything is written. The same in Python.", "",
              "| # | case | base | input | key path | message |", "|---|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory(prefix="scene-errors-build-") as tmp:
        for c in BUILD_CASES:
            k += 1
            lines.append(f"| {k} | {_cell(c.id)} | {c.base} | {_cell(describe(c))} | {_code(c.path)} | "
                         f"{_text(build_error(c, Path(tmp) / c.id).problem)} |")
    lines += ["", "## The command line", "", f"{len(CLI_CASES)} inputs: `cosim run ARGS` (or `cosim study ARGS`) "
              "in a folder holding the "
              "files (and [edit_checkpoint.py](#edit_checkpointpy)), after the commands that make the case's "
              "checkpoint; it exits with status 2, prints the message on stderr, makes no output folder (the "
              "`--out` given) and writes nothing into one that is there. A checkpoint is never run: the pickle "
              "cases would write the file `pwned` if it were.", "",
              "| # | case | command | files | message |", "|---|---|---|---|---|"]
    for c in CLI_CASES:
        k += 1
        lines.append(cli_row(k, c, cli_message(c) if cli_text is None else cli_text))
    lines += ["", "## Base scenes", ""]
    for name, text in BASES.items():
        lines += [f"### {name}", "", "```toml", text.strip(), "```", ""]
    lines += ["## Base files", "", "In the working folder of every case."]
    for name, text in BASE_FILES.items():
        lines += ["", f"### {name}", "", "```", text.rstrip("\n"), "```"]
    lines += ["", "In the folder of every command-line case."]
    for name, text in CLI_FILES.items():
        lines += ["", f"### {name}", "", "```python", text.rstrip("\n"), "```"]
    return "\n".join(lines)


@pytest.mark.long  # it runs every case but the command line's (seconds)
def test_docs_table_is_current():
    """The document is what :func:`render` writes, each command-line message aside: those
    cases run in subprocesses (a minute in all), and each one's test checks its own row."""
    assert DOC.is_file(), "write it: python tests/test_scene_errors.py > docs/scene_errors.md"
    mark = "CLI-MESSAGE-CHECKED-BY-ITS-OWN-TEST"
    pattern = re.escape(render(cli_text=mark) + "\n").replace(re.escape(_text(mark)), "[^\n]*")
    assert re.fullmatch(pattern, DOC.read_text()), ("docs/scene_errors.md is out of date: "
                                                     "python tests/test_scene_errors.py > docs/scene_errors.md")


if __name__ == "__main__":
    with folder():
        sys.stdout.write(render() + "\n")
