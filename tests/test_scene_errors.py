"""A catalogue of bad scenes: each is refused before any work is done, from TOML (a dict
read by ``from_dict``, and the same change made by ``--set``, ``with_values``) and in
Python (the classes constructed directly), naming the exact key path and saying what would
be accepted.

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

import copy
import dataclasses
import math
import re
import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path

import pytest

from cosim.errors import InputError
from cosim.scene import Scene
from cosim.scene.fields import Part, Parts
from cosim.scene.toml_io import from_dict, with_values

DOC = Path(__file__).resolve().parents[1] / "docs" / "scene_errors.md"

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
}

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

    @property
    def python_path(self):
        return self.python[0] if isinstance(self.python, tuple) else self.python


def case(id, base, change, path, says, python):
    if isinstance(change, tuple) and change and not isinstance(change[0], tuple):
        change = (change,)
    return Case(id, base, change, path, says, python)


INCLINED = {"kind": "inclined-tank", "angle": 95.0, "length": 1.0, "depth": 0.2, "height": 0.6, "width": 0.5}
LINE_DYN = {"EA": 1e5, "mass_per_length": 0.6, "diameter": 0.01}

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
         "is required: one of 'none', 'analytic', 'sph'", None),
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
         "0.0 [N] is out of range; give a number [N] > 0 (axial stiffness", "Line.EA"),
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
    case("negative gravity", "analytic", ("world.gravity", -9.81), "world.gravity", "give a number [m/s^2] >= 0",
         "World.gravity"),
    # -- choices
    case("fluid.model misspelt", "flume", ("fluid.model", "sphh"), "fluid.model",
         "'sphh' is not accepted; did you mean 'sph'? Give one of 'none', 'analytic', 'sph'", None),
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
    case("c0 and u_max", "flume", (("fluid.c0", 20.0), ("fluid.u_max", 2.0)), "fluid.c0",
         "give c0 or u_max, not both", "SPH.c0"),
    # -- dimensions
    case("a 3-D pos in a 2-D scene", "analytic", ("bodies[0].pos", [3.0, 0.0, 0.0]), "bodies[0].pos",
         "[3.0, 0.0, 0.0] has 3 coordinates; a 2-D scene gives a point as (x, z)", "Scene.bodies[0].pos"),
    case("a 2-D anchor in a 3-D scene", "tank3d",
         (("bodies[0].fairleads", {"top": [0.0, 0.0, 0.05]}),
          ("moorings", {"lines": [{"fairlead": "ball.top", "anchor": [0.5, 0.0], "length": 0.3, "weight": 1.0}]})),
         "moorings.lines[0].anchor", "a 3-D scene gives a point as (x, y, z)", "Scene.moorings.lines[0].anchor"),
    case("gauge pairs in 2-D", "flume", ("probes.gauges", [[0.6, 0.0]]), "probes.gauges[0]",
         "a 2-D scene gives a gauge as x [m]", "Scene.probes.gauges[0]"),
    case("a gauge number in 3-D", "tank3d", ("probes.gauges", [0.1]), "probes.gauges[0]",
         "a 3-D scene gives a gauge as (x, y) [m]", "Scene.probes.gauges[0]"),
    case("a flume in 3-D", "flume", ("world.dim", 3), "domain.kind", "a flume is 2-D; set world.dim = 2",
         "Scene.domain.kind"),
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
    # -- names and references
    case("a fairlead on an unknown body", "analytic", ("moorings.lines[0].fairlead", "boat.left"),
         "moorings.lines[0].fairlead", "no body named 'boat'; bodies: ['box', 'buoy']",
         "Scene.moorings.lines[0].fairlead"),
    case("an unknown fairlead", "analytic", ("moorings.lines[1].fairlead", "box.top"), "moorings.lines[1].fairlead",
         "body 'box' has no fairlead 'top'; its fairleads: ['left', 'right']", "Scene.moorings.lines[1].fairlead"),
    case("a fairlead not as BODY.NAME", "analytic", ("moorings.lines[0].fairlead", "box"),
         "moorings.lines[0].fairlead", "give it as BODY.NAME", "Line.fairlead"),
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
    case("gauges without SPH", "analytic", ("probes.gauges", [1.0]), "probes.gauges",
         "need the SPH fluid (fluid.model = \"sph\")", "Scene.probes.gauges"),
    case("fluid-first without SPH", "analytic", ("coupling.scheme", "fluid-first"), "coupling.scheme",
         "'fluid-first' needs the SPH fluid", "Scene.coupling.scheme"),
    case("a dynamic mooring model without EA", "analytic", ("moorings.model", "moordyn"), "moorings.lines[0].EA",
         "the 'moordyn' model needs it for every line; give it, or use model = \"catenary\"", "Moorings.lines[0].EA"),
    case("a dynamic model without a diameter", "analytic",
         (("moorings.model", "sph-cable"), ("moorings.lines[0].EA", 1e5), ("moorings.lines[0].mass_per_length", 0.6)),
         "moorings.lines[0].diameter", "the 'sph-cable' model needs it for every line", "Moorings.lines[0].diameter"),
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
    # -- times and files
    case("plot_at outside the run", "flume", ("world.plot_at", [2.5, 6.0]), "world.plot_at[1]",
         "6.0 s lies outside the run, 0 .. 5.0 s", "World.plot_at[1]"),
    case("sample_every longer than the run", "flume", ("world.sample_every", 10.0), "world.sample_every",
         "10.0 s is longer than the run (5.0 s)", "World.sample_every"),
    case("the 2-D default direction in 3-D", "tank3d", ("base_motion.direction", OUT), "base_motion.direction",
         "a 3-D scene needs the direction as (x, y, z), e.g. [1, 0, 0]", "Scene.base_motion.direction"),
    case("a missing file", "tank3d",
         ("base_motion", {"kind": "table", "file": "nowhere.csv", "direction": [1.0, 0.0, 0.0]}), "base_motion.file",
         "no file 'nowhere.csv' (a relative path is read from the scene file's folder)", "Scene.base_motion.file"),
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
    if isinstance(c.change, str):
        return refusal(lambda: with_values(from_dict(base_dict(c.base)), [c.change]))
    return refusal(lambda: from_dict(edited(c)))


# ------------------------------------------------------------------------ the tests
IDS = [c.id for c in CASES]


def test_catalogue_is_large_and_ids_are_unique():
    assert len(CASES) >= 35
    assert len(set(IDS)) == len(IDS)


@pytest.mark.parametrize("name", sorted(BASES))
def test_base_scenes_are_valid(name):
    scene = from_dict(base_dict(name))
    assert build_python(base_dict(name)) == scene
    assert with_values(scene, []) == scene


@pytest.mark.parametrize("c", CASES, ids=IDS)
def test_refused_from_toml(c):
    err = toml_error(c)
    assert isinstance(err, InputError), f"{type(err).__name__}: {err}"
    assert err.path == c.path, str(err)
    assert c.says in str(err)
    assert str(err) == f"{c.path}: {err.problem}"


@pytest.mark.parametrize("c", [c for c in CASES if not isinstance(c.change, str) and assignments(c)],
                         ids=[c.id for c in CASES if not isinstance(c.change, str) and assignments(c)])
def test_refused_by_set(c):
    """The same change made by --set on the valid base scene: the same error."""
    err = refusal(lambda: with_values(from_dict(base_dict(c.base)), assignments(c)))
    assert isinstance(err, InputError), f"{type(err).__name__}: {err}"
    assert (err.path, err.problem) == (c.path, toml_error(c).problem)


PY_CASES = [c for c in CASES if c.python is not None]


@pytest.mark.parametrize("c", PY_CASES, ids=[c.id for c in PY_CASES])
def test_refused_in_python(c):
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


# ------------------------------------------------------------------------ the table
def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


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


def render() -> str:
    """The catalogue as Markdown: docs/scene_errors.md."""
    lines = [
        "# Scene errors",
        "",
        "Generated from `tests/test_scene_errors.py` (the table is checked against the tests); "
        "regenerate it with `python tests/test_scene_errors.py > docs/scene_errors.md`.",
        "",
        f"Each of the {len(CASES)} inputs below is refused before any work is done, with the key path of the bad "
        "field and what would be accepted: from a TOML file, by `cosim run --set KEY.PATH=VALUE` (where the change "
        "can be written as assignments) and in Python. An input is a change to one of the valid base scenes at "
        "the end (`key = value`, or a key left out). The error (`cosim.errors.InputError`) reads `PATH: MESSAGE`. "
        "In Python a part does not know where it will be put: the error "
        "names its class (`Box.density`), or `Scene.` and the key path for the checks of the scene as a whole; "
        "an unknown or missing keyword is Python's own `TypeError`; \u2014 where there is no Python counterpart "
        "(the TOML field that picks a class, `--set` syntax).",
        "",
        "| # | case | base | input | key path | message | Python |",
        "|---|---|---|---|---|---|---|",
    ]
    for i, c in enumerate(CASES, 1):
        err = toml_error(c)
        py = "\u2014" if c.python is None else "`TypeError`" if c.python is TYPE else _code(c.python_path)
        lines.append(f"| {i} | {_cell(c.id)} | {c.base} | {_cell(describe(c))} | {_code(c.path)} | "
                     f"{_cell(err.problem)} | {py} |")
    lines += ["", "## Base scenes", ""]
    for name, text in BASES.items():
        lines += [f"### {name}", "", "```toml", text.strip(), "```", ""]
    return "\n".join(lines)


def test_docs_table_is_current():
    assert DOC.is_file(), "write it: python tests/test_scene_errors.py > docs/scene_errors.md"
    assert DOC.read_text() == render() + "\n", ("docs/scene_errors.md is out of date: "
                                                 "python tests/test_scene_errors.py > docs/scene_errors.md")


if __name__ == "__main__":
    sys.stdout.write(render() + "\n")
