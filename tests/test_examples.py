"""Every example runs at its default settings (users copy them): each scene file through
`cosim run`, each script as a script; a scene given as both a script and a TOML file is
the same scene. Every run but the two quickest (QUICK_EXAMPLE's scene, two_line_mooring.py)
is in the long tier."""

import json
import os
import runpy
import subprocess
import sys
from pathlib import Path

import pytest

from cosim.scene import Scene

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SCENES = sorted(EXAMPLES.glob("*.toml"))
#: the example whose run stays in the fast tier (seconds); the others run in the long one
QUICK_EXAMPLE = "moored_box"


def _run(args, cwd=None, timeout=1800):
    """Run in a child process that imports this checkout's packages (a script's own folder,
    not the checkout, starts its path)."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(EXAMPLES.parent), os.environ.get("PYTHONPATH", "")]))
    return subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True, timeout=timeout, cwd=cwd,
                          env=env)


@pytest.mark.parametrize("path", [p if p.stem == QUICK_EXAMPLE else pytest.param(p, marks=pytest.mark.long)
                                  for p in SCENES], ids=[p.stem for p in SCENES])
def test_scene_example_runs_at_default(path, tmp_path):
    out = _run(["-m", "cosim.cli", "run", path, "--out", tmp_path])
    assert out.returncode == 0, out.stderr[-3000:]
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["t_reached_s"] == Scene.from_toml(path).world.duration and "error" not in s
    assert list(tmp_path.glob("*.png")) and list(tmp_path.glob("*.csv"))
    if path.stem == "moored_box_waves":  # the main example moors its box: the lines lift and go slack
        import numpy as np

        states = np.loadtxt(tmp_path / "line_states.csv", delimiter=",", skiprows=1)[:, 1:]
        tension = np.loadtxt(tmp_path / "tensions.csv", delimiter=",", skiprows=1)[:, 1:3]
        for k in range(2):
            assert {0.0, 1.0} <= set(states[:, k]), k  # resting and partly lifted, each line
            assert tension[:, k].max() > 1.25 * tension[:, k].min(), k
        # the README's tension ranges, to the 0.1 N it gives them in
        import re

        readme = " ".join((EXAMPLES.parent / "README.md").read_text().split())
        said = re.search(r"tensions ([\d.]+)–([\d.]+) N and ([\d.]+)–([\d.]+) N", readme)
        assert said, "the README's tension ranges of the main example"
        measured = [tension[:, 0].min(), tension[:, 0].max(), tension[:, 1].min(), tension[:, 1].max()]
        np.testing.assert_allclose([float(g) for g in said.groups()], measured, atol=0.06)


def test_the_quick_example_is_an_example():
    """Else every example's run would be in the long tier, none in the fast one."""
    assert QUICK_EXAMPLE in [p.stem for p in SCENES]


def test_the_main_example_lines_are_just_lifted_at_rest():
    """The design of examples/moored_box_waves (its docstring), by the catenary: at the
    floating box's start each line is partly lifted with a small pull, and a surge of
    0.022-0.023 m towards its anchor lays it on the seabed (X = L - h)."""
    import pytest

    from cosim.scene.placement import floating_height
    from moorings.catenary import LineState, solve

    scene = Scene.from_toml(EXAMPLES / "moored_box_waves.toml")
    box, lines = scene.bodies[0], scene.moorings.lines
    h = floating_height(box, 2, 0.3, 1000.0, 9.81, lines) - 0.05  # the fairleads, 0.05 m below the centre
    for ln, x in zip(lines, (1.1, 1.3)):
        X = abs(x - ln.anchor[0])
        r = solve(X, h, ln.length, ln.weight, ln.EA)
        assert r.state == LineState.PARTLY_LIFTED and 0.0 < r.H < 0.1 * r.V
        assert 0.022 < X - (ln.length - h) < 0.023
        assert solve(X - 0.023, h, ln.length, ln.weight, ln.EA).state == LineState.RESTING
    assert h == pytest.approx(0.2474, abs=1e-3)


@pytest.mark.parametrize("path", SCENES, ids=[p.stem for p in SCENES])
def test_script_and_toml_are_one_scene(path):
    script = path.with_suffix(".py")
    if script.is_file():
        assert runpy.run_path(str(script), run_name="scene")["scene"] == Scene.from_toml(path)


@pytest.mark.long
def test_moored_box_compares_every_model(tmp_path):
    """The script over 5 s per model (its 20 s cost 76 CPU-s, most of it MoorDyn's and the
    SPH cable's; the catenary's 20 s run is the fast tier's, above)."""
    out = _run([EXAMPLES / "moored_box.py", "--duration", "5"], cwd=tmp_path)
    assert out.returncode == 0, out.stderr[-3000:]
    assert (tmp_path / "out" / "moored_box" / "models.png").stat().st_size > 0
    for model in ("catenary", "sph-cable", "fmu"):
        assert f"{model:10s}" in out.stdout
        summary = json.loads((tmp_path / "out" / "moored_box" / model / "summary.json").read_text())
        assert summary["t_reached_s"] == 5.0


@pytest.mark.long
def test_two_line_mooring(tmp_path):
    out = _run([EXAMPLES / "two_line_mooring.py", "--out", tmp_path])
    assert out.returncode == 0, out.stderr[-3000:]
    assert list(tmp_path.iterdir())


@pytest.mark.parametrize("mode, remedy", [("auto", "none"), ("subiterate", "subiterate"), ("none", "none")])
def test_light_body_setting_reaches_the_coupler(mode, remedy, tmp_path):
    """``coupling.light_body`` is the coupler's remedy (auto leaves this box of half the
    water's density uncorrected: ratio 0.5 > 0.3). Only built, not run."""
    from cosim.scene.build import build

    scene = Scene.from_toml(EXAMPLES / "moored_box_waves.toml").with_values(
        ["fluid.dx=0.05", f"coupling.light_body={mode}"])
    c = build(scene, tmp_path).coupler
    assert c.light_body == mode and c.remedies == {"box": remedy}
    assert c.added_mass.ratio[0] == pytest.approx(0.5, rel=0.02)
