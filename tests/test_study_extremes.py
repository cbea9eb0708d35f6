"""cosim study --extremes: each lever of a scene pushed towards its limits; every value
ends as ok, refused (before any work, the field named), unstable (a clear stop) or crash
(a bug of ours: none here)."""

import json

import pytest

from cosim.scene import SPH, Analytic, Box, Line, Moorings, Scene, Tank, World
from cosim.study.extremes import _outcome, levers, run_extremes, summary


def test_levers_follow_what_the_scene_has():
    box = Box("b", size=(1.0, 1.0), density=500.0, pos=(0.0, 0.0), fairleads={"f": (0.0, -0.5)})
    line = Line("b.f", anchor=(5.0, -3.0), length=6.0, weight=6.7, EA=1e6, mass_per_length=1.0, diameter=0.02)
    analytic = Scene(fluid=Analytic(), bodies=[box], moorings=Moorings(model="moordyn", lines=[line]))
    assert [lv for lv, _ in levers(analytic)] == ["bodies[0].density", "moorings.lines[*].EA", "moorings.segments",
                                                   "coupling.dt"]
    sph = Scene(fluid=SPH(dx=0.02), domain=Tank(length=1.0, height=0.5, depth=0.3))
    assert [lv for lv, _ in levers(sph)] == ["fluid.dx", "fluid.c0_factor", "fluid.cfl"]
    assert dict(levers(sph))["fluid.dx"][0] == ("4 x", ["fluid.dx=0.08"])


def test_outcomes():
    assert _outcome({"error": None}) == "ok"
    assert _outcome({"error": "InstabilityError: step 3 ...", "returncode": 2}) == "unstable"
    assert _outcome({"error": "fluid.dx: ...", "returncode": 2}) == "refused"
    assert _outcome({"error": "fluid.dx: ...", "returncode": 2, "steps": 0}) == "refused"
    assert _outcome({"error": "InputError: ...", "returncode": 2, "steps": 5}) == "unstable"
    assert _outcome({"error": "ZeroDivisionError: ...", "returncode": 1}) == "crash"


@pytest.mark.long
def test_extremes_of_a_floating_box(tmp_path):
    scene = Scene(world=World(dim=2, duration=0.2, sample_every=0.05), fluid=Analytic(level=0.0),
                  bodies=[Box("b", size=(1.0, 1.0), density=500.0, pos=(0.0,), place="floating")])
    rows = run_extremes(scene, tmp_path, serial=True)
    got = {(r["lever"], r["value"]): r["outcome"] for r in rows}
    assert got[("bodies[0].density", "2 x water")] == "refused"  # it cannot float: refused before any step
    assert got[("bodies[0].density", "0.5 x water")] == "ok"
    assert all(o != "crash" for o in got.values()), rows
    assert "bodies[0].density: runs at" in summary(rows)[0]
    assert len(json.loads((tmp_path / "extremes.json").read_text())) == len(rows) == 9
    assert (tmp_path / "extremes.md").read_text().startswith("# Extremes")


@pytest.mark.long
def test_a_body_denser_than_water_sinks_as_physics_says(tmp_path):
    """The analytic moored box at twice the water's density falls (net weight 20 kN/m on
    4.1 t/m) until its fairleads pass below its anchors' seabed, where the run stops: that
    is the physics, told apart from an unstable run; at half the density it floats."""
    from pathlib import Path

    import pytest

    from cosim.errors import InstabilityError
    from cosim.study.extremes import _sank

    box = Scene.from_toml(Path(__file__).resolve().parents[1] / "examples" / "moored_box.toml")
    heavy = box.with_values(["bodies[0].density=2050.0", "world.duration=4.0"])
    with pytest.raises(InstabilityError, match="below the seabed through its anchor"):
        heavy.run(tmp_path / "heavy" / "run", progress=False)
    why = _sank(heavy, "bodies[0].density", tmp_path / "heavy")
    assert why.startswith("denser than the water, body 'box' sank ") and why.endswith("as physics says")
    assert float(why.split("sank ")[1].split(" m")[0]) > 9.0  # from z = 0 to the anchors' 10 m down
    light = box.with_values(["bodies[0].density=512.5", "world.duration=1.0"])
    light.run(tmp_path / "light" / "run", progress=False)
    assert _sank(light, "bodies[0].density", tmp_path / "light") is None
    assert _sank(light, "moorings.lines[*].EA", tmp_path / "light") is None
