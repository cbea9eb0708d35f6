"""Every numeric field of a scene, fed any number: finite, infinite, NaN, huge, tiny,
negative. The property: the scene is refused (``cosim.errors.InputError``, a
``SceneError`` naming the field, before any file is written: by its checks, by the cost
estimate, or by the solvers while it is built), or it builds and takes its first coupling
step with every probe finite. The fields are walked from the scene's own declarations
(``cosim.scene.fields``), so a field added later is fed too.

Two cheap base scenes: the analytic fluid with a moored box and a buoy (2-D; fast), and a
coarse 2-D SPH tank shaken under a floating box (marked slow: a step of the SPH fluid
and its start)."""

from __future__ import annotations

import copy
import math
import tempfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cosim.errors import InputError
from cosim.scene import Scene
from cosim.scene.fields import Gauges, Num, NumOrVec, Part, Parts, Table, Vec, Vecs, Whole, spec_fields
from cosim.scene.toml_io import from_dict, to_dict

ANALYTIC = """
[world]
dim = 2
duration = 2.0
sample_every = 0.05

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
  { fairlead = "box.left", anchor = [-20.0, -10.0], length = 25.0, weight = 50.0, EA = 5e7 },
  { fairlead = "box.right", anchor = [20.0, -10.0], length = 25.0, weight = 50.0 },
]
"""

SPH_TANK = """
[world]
dim = 2
duration = 0.2
sample_every = 0.05
snapshot_every = 0.0

[fluid]
model = "sph"
dx = 0.04

[domain]
kind = "tank"
length = 0.8
height = 0.4
depth = 0.2

[base_motion]
kind = "harmonic"
period = 1.0
amplitude = 0.01

[[bodies]]
shape = "box"
name = "box"
size = [0.2, 0.12]
pos = [0.4]
place = "floating"
density = 500.0

[probes]
gauges = [0.2]
energy = true
"""

#: numbers chosen to break things
NASTY = [0.0, -0.0, -1.0, 1.0, 1e-300, 5e-324, -5e-324, 1e-12, 1e12, 1e30, -1e30, 1e300, 1e308, -1e308,
         1.7976931348623157e308, math.inf, -math.inf, math.nan, 10 ** 20, -(10 ** 20), 10 ** 400]
VALUES = st.one_of(st.sampled_from(NASTY), st.floats(allow_nan=True, allow_infinity=True),
                   st.integers(-10 ** 6, 10 ** 6))


def numeric_paths(spec, prefix="") -> list[str]:
    """The key path of every number the scene ``spec`` declares (set or unset), vectors
    component by component, tables entry by entry; nested parts walked."""
    out = []
    for name, check, _ in spec_fields(type(spec)):
        key = f"{prefix}{name}"
        value = getattr(spec, name)
        if isinstance(check, (Num, Whole)) or (isinstance(check, NumOrVec) and not isinstance(value, tuple)):
            out.append(key)
        elif isinstance(check, NumOrVec):
            out += [f"{key}[{i}]" for i in range(len(value))]
        elif isinstance(check, Vec):
            out += [f"{key}[{i}]" for i in range(len(value) if value is not None else check.sizes[0])]
        elif isinstance(check, (Vecs, Gauges)):
            out += [f"{key}[{i}]" for i in range(len(value))]
        elif isinstance(check, Table):
            out += [f"{key}.{k}[{i}]" for k, v in value.items() for i in range(len(v))]
        elif isinstance(check, Part) and value is not None:
            out += numeric_paths(value, f"{key}.")
        elif isinstance(check, Parts):
            for i, part in enumerate(value):
                out += numeric_paths(part, f"{key}[{i}].")
    return out


def _set(data: dict, path: str, value) -> None:
    import re

    keys = []
    for piece in path.split("."):
        m = re.fullmatch(r"([\w-]+)((?:\[\d+\])*)", piece)
        keys.append(m.group(1))
        keys += [int(i) for i in re.findall(r"\[(\d+)\]", m.group(2))]
    node = data
    for k, nxt in zip(keys, keys[1:]):
        if isinstance(k, str) and k not in node:
            node[k] = [0.0] * (nxt + 1) if isinstance(nxt, int) else {}
        node = node[k]
        if isinstance(nxt, int) and nxt >= len(node):
            node.extend([0.0] * (nxt + 1 - len(node)))
    node[keys[-1]] = value


def refused_or_finite(scene_text: str, path: str, value) -> str:
    """The property for one change; returns "refused" or "ran" (for the statistics)."""
    import tomllib

    from cosim.scene import cost
    from cosim.scene.build import build
    from cosim.scene.probes import groups

    data = tomllib.loads(scene_text)
    data = to_dict(from_dict(data))
    _set(data, path, copy.deepcopy(value))
    with tempfile.TemporaryDirectory(prefix="scene-properties-") as tmp:
        out = Path(tmp) / "out"
        try:
            scene = from_dict(data)
            cost.check(cost.estimate(scene), out)
            built = build(scene, Path(tmp) / "build")
        except InputError:
            assert not out.exists()
            return "refused"
        try:
            probes = groups(scene, built)
            before = [np.asarray(g.sample(), float) for g in probes]
            built.coupler.step(scene.world.duration)
            after = [np.asarray(g.sample(), float) for g in probes]
        finally:
            close = getattr(built.mooring, "close", None)
            if callable(close):
                close()
        for g, a, b in zip(probes, before, after):
            assert np.all(np.isfinite(a)), f"{path} = {value!r}: {g.name} at the start: {dict(zip(g.columns, a))}"
            assert np.all(np.isfinite(b)), f"{path} = {value!r}: {g.name} after a step: {dict(zip(g.columns, b))}"
        assert not out.exists()
        return "ran"


ANALYTIC_PATHS = numeric_paths(from_dict(__import__("tomllib").loads(ANALYTIC)))
SPH_PATHS = numeric_paths(from_dict(__import__("tomllib").loads(SPH_TANK)))


def test_the_walk_reaches_every_kind_of_number():
    assert {"world.duration", "world.gravity", "fluid.rho", "fluid.linear_damping.box[2]", "bodies[0].size[1]",
            "bodies[0].euler[1]", "bodies[1].mass", "moorings.lines[0].EA", "moorings.lines[1].break_load",
            "moorings.segments", "coupling.dt", "coupling.body_timestep"} <= set(ANALYTIC_PATHS)
    assert {"fluid.dx", "fluid.c0", "fluid.settle", "domain.depth", "base_motion.amplitude", "bodies[0].pos[0]",
            "probes.gauges[0]"} <= set(SPH_PATHS)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(path=st.sampled_from(ANALYTIC_PATHS), value=VALUES)
def test_any_number_in_the_analytic_scene_is_refused_or_runs(path, value):
    refused_or_finite(ANALYTIC, path, value)


@pytest.mark.slow
@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(path=st.sampled_from(SPH_PATHS), value=VALUES)
def test_any_number_in_the_sph_scene_is_refused_or_runs(path, value):
    refused_or_finite(SPH_TANK, path, value)
