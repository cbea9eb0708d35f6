"""The cost estimate (cosim.scene.cost) against what the scene builds and runs: the SPH
particles of every kind of domain, the SPH fluid's first step, an elastic plate's stable
step, the dynamic lines' internal steps and the coupling steps of a run; the refusals by
memory and by CPU time (confirmed with yes, or interactively); ``summary.json`` keeps the
estimate; ``cosim run --dry-run`` writes nothing."""

import json
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import pytest

from cosim.scene import (SPH, Analytic, Beach, Block, Box, CylinderTank, ElasticPlate, Flume, InclinedTank, Line,
                         Moorings, NoFluid, Piston, PolygonTank, Scene, SceneError, Tank, World)
from cosim.scene import cost
from cosim.scene.build import build

ROOT = Path(__file__).resolve().parents[1]
W2, W3 = World(dim=2, duration=0.01, sample_every=0.005), World(dim=3, duration=0.01, sample_every=0.005)
BOX = Box("box", size=(0.2, 0.1), density=500.0, pos=(0.5,), place="floating")


@pytest.mark.parametrize("scene", [
    Scene(world=W2, fluid=SPH(dx=0.02), domain=Tank(length=1.0, height=0.6, depth=0.3)),
    Scene(world=W2, fluid=SPH(dx=0.02), domain=Tank(length=1.0, height=0.6, water=[Block((0.0, 0.0), (0.4, 0.3))])),
    Scene(world=W2, fluid=SPH(dx=0.02), domain=Flume(length=3.0, depth=0.3, height=0.45, beach=Beach(2.0, 0.3)),
          waves=Piston(height=0.04, period=1.0), bodies=[BOX]),
    Scene(world=W2, fluid=SPH(dx=0.02), domain=InclinedTank(angle=30.0, length=1.0, depth=0.3, height=0.5)),
    Scene(world=W2, fluid=SPH(dx=0.02), domain=PolygonTank(vertices=[(0.0, 0.0), (1.0, 0.0), (1.4, 0.6), (-0.4, 0.6)],
                                                           fill_level=0.3)),
    Scene(world=W3, fluid=SPH(dx=0.05), domain=Tank(length=1.0, width=0.5, height=0.6, depth=0.3)),
    Scene(world=W3, fluid=SPH(dx=0.05), domain=CylinderTank(diameter=1.0, depth=0.3, height=0.5)),
    pytest.param(Scene(world=W3, fluid=SPH(dx=0.05), domain=Flume(length=3.0, width=0.5, depth=0.3, height=0.45,
                                                                  beach=Beach(2.0, 0.3)),
                       waves=Piston(height=0.04, period=1.0)), marks=pytest.mark.long),  # a pair loop of its own
    Scene(world=W2, fluid=SPH(dx=0.005), domain=Tank(length=0.584, height=0.32, water=[Block((0.0, 0.0),
                                                                                             (0.146, 0.292))]),
          bodies=[ElasticPlate("plate", length=0.08, thickness=0.012, E=1e6, density=2500.0, base=(0.298, 0.0))]),
], ids=["tank", "blocks", "flume-beach-box", "inclined", "polygon", "tank-3d", "cylinder-3d", "flume-3d", "plate"])
def test_particles_and_step_are_what_the_scene_builds(scene, tmp_path):
    """The particles counted from the geometry are those built, to 6 % (the fluid's to
    3 %: a lattice's rows against the area); the SPH step at rest is the built fluid's
    first step to 5 % (the same limit from the same set-up, at the reference sound speed:
    the hydrostatic density raises it at depth)."""
    from fluid.particles import Kind

    water, walls, bodies = cost.sph_particles(scene)
    built = build(scene, tmp_path)
    sph = built.sph if built.sph is not None else built.fluid.fluid
    kind = sph.ps.kind
    assert water == pytest.approx(int((kind == Kind.FLUID).sum()), rel=0.03)
    assert water + walls + bodies == pytest.approx(sph.ps.n, rel=0.06)
    assert cost.sph_step(scene)[0] == pytest.approx(sph.max_dt(), rel=0.05)


@pytest.mark.parametrize("elements, E", [(8, 1e6), (16, 1e8), (40, 2e11)])
def test_an_elastic_plates_step_bounds_its_chains(elements, E):
    """The plate's analytic stable step (its chain's highest bending and shear modes) lies
    within a factor 2 below MuJoCo's linearised chain's (bodies.elastic.BeamModel.stable_dt):
    never above it, where MuJoCo would go unstable."""
    from cosim.scene.build import plates

    plate = ElasticPlate("p", length=0.5, thickness=0.01, E=E, density=1000.0, base=(0.3, 0.0), elements=elements)
    scene = Scene(world=W2, fluid=NoFluid(), bodies=[plate])
    exact = plates(scene)["p"].stable_dt()
    assert 0.5 * exact <= cost.plate_step(plate, 2) <= exact


def _moored(model, segments=20):
    chain = dict(length=25.0, weight=50.0, EA=5.0e7, mass_per_length=5.82, diameter=0.03)
    return Scene(world=World(dim=2, duration=1.0, sample_every=0.05), fluid=Analytic(rho=1025.0),
                 bodies=[Box("box", size=(2.0, 1.0), density=500.0, pos=(3.0, 0.0),
                             fairleads={"left": (-1.0, -0.5), "right": (1.0, -0.5)})],
                 moorings=Moorings(model=model, segments=segments,
                                   lines=[Line("box.left", anchor=(-20.0, -10.0), **chain),
                                          Line("box.right", anchor=(20.0, -10.0), **chain)]))


@pytest.mark.parametrize("model", ["moordyn", "sph-cable"])
def test_the_lines_internal_steps_are_the_models(model, tmp_path):
    """MoorDyn's internal step is the adapter's own (the same bounds); the SPH cable's
    Courant step is its first stable step, to 6 % (the hanging cable is stretched)."""
    built = build(_moored(model), tmp_path)
    (_, n, dt, _), _ = cost.line_steps(_moored(model))
    assert n == 21
    inner = built.mooring.inner if hasattr(built.mooring, "inner") else built.mooring
    got = inner.dt_internal if model == "moordyn" else inner.stable_dt()
    assert dt == pytest.approx(got, rel=1e-9 if model == "moordyn" else 0.06)


@pytest.mark.long
def test_the_coupling_steps_and_the_estimate_in_the_summary(tmp_path):
    """The coupling steps estimated are those the run takes, to 15 % (the lines' bound on
    MoorDyn is taken from the catenary at rest), and summary.json keeps the estimate."""
    res = _moored("moordyn").run(tmp_path, progress=False)
    est = res.summary["estimate"]
    assert est["steps"] == pytest.approx(res.summary["steps"], rel=0.15)
    assert set(est["terms"]) == {"bodies", "lines", "coupling", "records"}
    assert est["cpu_s"] == pytest.approx(sum(t["cpu_s"] for t in est["terms"].values()), rel=1e-3)


def test_refused_by_memory_before_anything_is_written(tmp_path):
    """A flume at dx = 10 um: its 7e9 particles need terabytes; refused naming fluid.dx,
    in an instant (nothing is built), and no folder is made."""
    scene = Scene(world=World(dim=2, duration=1.0), fluid=SPH(dx=1e-5),
                  domain=Flume(length=3.0, depth=0.3, height=0.45))
    est = cost.estimate(scene)
    assert est.fluid_particles == pytest.approx(3.0 * 0.3 / 1e-10, rel=1e-6)
    with pytest.raises(SceneError) as e:
        scene.run(tmp_path / "out", progress=False)
    assert e.value.path == "fluid.dx" and "of memory" in e.value.problem and "a coarser fluid.dx" in e.value.problem
    assert not (tmp_path / "out").exists()


def test_a_day_of_cpu_needs_a_yes():
    """fluid.settle = 1e9 s: years of relaxation. Refused without yes, naming the field;
    asked (and refused on no, let through on yes) where a terminal can answer."""
    scene = Scene(world=World(dim=2, duration=0.01, sample_every=0.005), fluid=SPH(dx=0.05, settle=1e9),
                  domain=Tank(length=1.0, height=0.6, depth=0.3))
    est = cost.estimate(scene)
    assert est.cpu_s > cost.CONFIRM_CPU_S and est.driver.field == "fluid.settle"
    with pytest.raises(SceneError, match="fluid.settle: the run would take about .* years of CPU, driven by "
                                         "fluid.settle") as e:
        cost.check(est)
    assert "cosim run --yes" in str(e.value)
    asked = []
    with pytest.raises(SceneError):
        cost.check(est, ask=lambda q: asked.append(q) or False)
    assert asked and asked[0].endswith("Run it? [y/N] ")
    cost.check(est, ask=lambda q: True)
    cost.check(est, yes=True)


@pytest.mark.parametrize("change, field", [
    ("world.duration=1e300", "world.duration"), ("world.sample_every=1e-12", "world.sample_every"),
    ("coupling.dt=1e-9", "coupling.dt"), ("moorings.segments=100000", "moorings.segments"),
    ("bodies[0].elements=100000", "bodies[0].elements")])
def test_each_unbounded_work_is_named_by_its_field(change, field):
    """Each of the issue's unbounded scenes is refused, by memory or by CPU time, naming
    the field that drives the cost."""
    scene = (Scene(world=World(dim=2, duration=1.0), fluid=NoFluid(),
                   bodies=[ElasticPlate("p", length=0.5, thickness=0.01, E=1e8, density=1000.0, base=(0.3, 0.0))])
             if change.startswith("bodies") else _moored("moordyn"))
    with pytest.raises(SceneError) as e:
        cost.check(cost.estimate(scene.with_values([change])))
    assert e.value.path == field, str(e.value)


@pytest.mark.long
def test_dry_run_prints_the_estimate_and_writes_nothing(tmp_path):
    """``cosim run --dry-run``: the estimate on stdout, exit 0, no folder; a run it would
    refuse: exit 2 and the refusal."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    scene = ROOT / "examples" / "sloshing_tank.toml"
    r = subprocess.run([sys.executable, "-m", "cosim.cli", "run", str(scene), "--dry-run", "--out", "out"],
                       capture_output=True, text=True, cwd=tmp_path, env=env, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "particles: 1,247 (799 fluid)" in r.stdout and "CPU time:" in r.stdout
    r = subprocess.run([sys.executable, "-m", "cosim.cli", "run", str(scene), "--dry-run", "--out", "out", "--set",
                        "fluid.settle=1e9"], capture_output=True, text=True, cwd=tmp_path, env=env, timeout=300)
    assert r.returncode == 2 and "fluid.settle: the run would take about" in r.stderr
    assert not list(tmp_path.iterdir())


def test_a_driven_body_sets_no_line_step_bound():
    """A body on its prescribed motion follows it whatever its lines pull (the drive takes
    their load): the SPH cable's stiff fairlead spring bounds the step of the same body
    left free, not of the driven rig (cable-vs-catenary's scene)."""
    from cosim.scene import Scene
    from cosim.scene.toml_io import from_dict, to_dict
    from cosim.validations.folders import SCENES

    rig = Scene.from_toml(SCENES / "cable-vs-catenary.toml")
    assert cost.line_coupling_step(rig) == (math.inf, "")
    d = to_dict(rig)
    del d["bodies"][0]["motion"]
    dt, key = cost.line_coupling_step(from_dict(d))
    assert 0.0 < dt < 1e-3 and key == "moorings.lines[0].EA"
